//! Where a common region ends, to the tolerance of the surfaces rather than of the gap.
//!
//! Bisection on "the gap is within the tolerance" stops where the gap reaches the tolerance.
//! Where the surfaces part across a crease that is the edge itself, to within tol/slope; where
//! they part tangentially (a flat joining an arc of radius R, the gap growing like s²/2R) it is
//! √(2·tol·R) beyond the edge: 1e-4 for R = 10 and tol = 1e-9. Beyond the threshold the gap is
//! `c·(s − s0)^k` (k = 1 across a crease, 2 past a tangent join with a jump in curvature, 3 past
//! a curvature-continuous one, more where further derivatives are continuous), so `gap^(1/k)`
//! is linear in s: two samples well above the tolerance give s0 by extrapolation and a third
//! tells which of k = 1, 2, 3 holds, then takes out the bend of `gap^(1/k)` where the search
//! line, straight in parameters, is not straight across the edge in space; failing those, the
//! three give k too and a fourth checks it. Near a corner of the region, where the samples along the search line would leave the
//! domain or the other surface, they are taken along turned lines. When none fits (the gap is
//! the other surface's extent ending, or not a power law) the threshold point stays.

use super::{Patch, Target, Tracer};
use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, FRAC_PI_6};

/// How far above the tracer's tolerance the first sample's gap must be: large enough that its
/// roundoff (about 1e-15 of the scale) is small beside it, small enough that the power law's
/// next term is negligible.
const ABOVE: f64 = 64.0;

/// Nearest the first sample lies past the threshold, in parameters, in the fits tried: near,
/// so the power law's next term counts least; failing that, beyond where the projection onto
/// a target with a kink inside its patch (a fold's crease) blends the two sides' derivatives
/// (its central differences step 1e-6 in parameters), which bends a crease's straight gap by
/// some 1e-3 within a few of those steps.
const FIRST: [f64; 2] = [1e-7, 1e-5];

/// How far along the search line from a threshold point, in parameters, the target's extent
/// edge is looked for when no turned line finds the region's edge (a point near a corner
/// where the region's edge meets the extent's: the threshold's reach there, √(2·tol·R) for
/// R up to some 10 times the surface, is below it).
const NEAR: f64 = 1e-4;

/// Farthest the first sample goes past the threshold, in parameters (a grid cell is 1/32).
const REACH: f64 = 1.0 / 64.0;

/// Largest relative misfit of the third sample for a power law to be taken.
const FIT: f64 = 1e-3;

/// How far behind the threshold the zero may lie, in the first sample's distances from it:
/// for `c·s^k` the gap grows by ABOVE over that distance, so the zero lies within
/// 1/(ABOVE^(1/k) − 1) of it behind, 3.3 for k = 16.
const BEHIND: f64 = 4.0;

/// The turns of the search line tried, in radians, when the samples along it leave the domain
/// or the target's extent: a direction between the region's edge and a domain or extent edge
/// meeting it stays within both and still crosses the region's edge.
const TURNS: [f64; 6] = [
    FRAC_PI_6, -FRAC_PI_6, FRAC_PI_3, -FRAC_PI_3, FRAC_PI_2, -FRAC_PI_2,
];

/// The powers fitted when no whole one of 1 to 3 fits (some roundoff below 1).
const POWERS: std::ops::RangeInclusive<f64> = 0.9..=16.0;

impl Target<'_> {
    /// The distance from `p` to the target's carrier surface when `p` lies within the target's
    /// extent (None beyond it: past the region's edge there is no smooth gap to extrapolate).
    pub(super) fn gap(&self, p: DVec3, tol: f64) -> Option<f64> {
        match self {
            Target::Sphere(s) => Some((p.distance(s.center) - s.radius).abs()),
            Target::Cylinder(c) => {
                let h = (p - c.base).dot(c.axis);
                let radial = (p - c.base - c.axis * h).length();
                (h >= -tol && h <= c.height + tol).then_some((radial - c.radius).abs())
            }
            Target::Region(r) => {
                let inside = super::point_in_polygon(p, &r.boundary, r.normal, tol).is_in();
                inside.then(|| r.normal.dot(p - r.boundary[0]).abs())
            }
            Target::Plane(o, n) => Some(n.dot(p - *o).abs()),
            Target::Patch(patch, hint) => {
                let (uv, foot) = patch.project_warm(p, hint.get());
                (!patch.bounds_at(uv) || over_edge(patch, uv, p - foot, tol))
                    .then(|| foot.distance(p))
            }
        }
    }
}

impl Tracer<'_, '_> {
    /// The region's edge between `lo` (in the region) and `hi` (out of it).
    pub(super) fn edge(&self, lo: DVec2, hi: DVec2) -> DVec2 {
        let t = self.bisect(lo, hi);
        self.extrapolated(lo, t, hi).unwrap_or(t)
    }

    /// The gap at the parameters `uv` (None outside the domain or the target's extent).
    pub(super) fn gap_at(&self, uv: DVec2) -> Option<f64> {
        for k in 0..2 {
            if !self.periodic[k] && !(0.0..=1.0).contains(&uv[k]) {
                return None;
            }
        }
        self.target.gap(self.eval(uv), self.tol)
    }

    /// The edge near the threshold point `t` on the line from `lo` to `hi`: the zero of the
    /// gap's power law fitted beyond `t` along that line. Where the samples along it leave the
    /// domain or the target's extent (near a corner of the region, where the other surface's
    /// edge or the domain's cuts it), the edge is found along the line turned by [`TURNS`]
    /// instead, at two places either side where it can be, and the line taken to where it
    /// crosses the chord between them: on the edge (to the edge's curvature over a few
    /// thresholds' distance) and on the line, so that densifying does not step back and forth
    /// along the edge. With one place only, that place.
    fn extrapolated(&self, lo: DVec2, t: DVec2, hi: DVec2) -> Option<DVec2> {
        let span = hi.distance(lo);
        if span == 0.0 {
            return None;
        }
        let dir = (hi - lo) / span;
        if let Some(e) = self.zero_along(t, dir, t.distance(lo)) {
            return Some(e);
        }
        let parting = self.parting(t, dir);
        let on_extent = self.gap_at(t).is_none() || self.gap_at(t + dir * 1e-9).is_none();
        if on_extent && (parting || self.barely_parting(t, dir)) {
            if let Some(c) = self.corner(t, dir, 1e-6) {
                return Some(c);
            }
        }
        self.turned(t, dir)
            .or_else(|| parting.then(|| self.corner(t, dir, NEAR)).flatten())
    }

    /// Whether the surfaces part at the threshold point `t`: the gap there (or just inside
    /// it, back along `dir`, where `t` lies on the target's extent edge) stands above the
    /// region's own. Only then may the region's corner lie behind `t` along the extent edge.
    /// Where the region runs on to that edge, flat along it, `t` lies on the region's edge
    /// already (the extent's), and the slide along it would take thousands of projections to
    /// find no zero behind it (it did so for every such crossing, making the common-region
    /// tests 35–90 times slower). Not looked for: a corner that `t` lies beyond by less than
    /// the gap's rounding tells, √(2·R·rounding) where the surfaces part tangentially
    /// (9e-7 for the oblique band's R = 2 and rounding 2e-13).
    fn parting(&self, t: DVec2, dir: DVec2) -> bool {
        let g = self.gap_at(t).or_else(|| self.gap_at(t - dir * 1e-9));
        g.is_some_and(|g| g > self.flat)
    }

    /// Whether the surfaces part at a threshold point `t` on the target's extent edge by less
    /// than [`Self::parting`] tells but more than a double's rounding could make of the
    /// region's own gap: a hundredth of the tracer's rounding above the region's level. There
    /// the region's corner may lie behind `t` along the extent edge by up to √(2·R·rounding)
    /// (9e-7 for the oblique band), off the outline by more than GEOMTOL if not looked for.
    /// A region running flat onto the extent edge has its own gap there, to a double's
    /// rounding, so the costly slide is still not made for it. The gap is read 1e-8 back:
    /// the bisected `t` may lie some 2e-9 past the extent edge (the oblique band's did).
    fn barely_parting(&self, t: DVec2, dir: DVec2) -> bool {
        let g = self.gap_at(t).or_else(|| self.gap_at(t - dir * 1e-8));
        let level = self.flat - self.rounding;
        g.is_some_and(|g| g > level + 1e-2 * self.rounding)
    }

    /// The turned lines' zeros of [`Self::extrapolated`], taken to the line along `dir`.
    fn turned(&self, t: DVec2, dir: DVec2) -> Option<DVec2> {
        let turned = |a: f64| {
            let (sin, cos) = f64::sin_cos(a);
            DVec2::new(cos * dir.x - sin * dir.y, sin * dir.x + cos * dir.y)
        };
        let mut found = TURNS
            .iter()
            .filter_map(|&a| self.zero_along(t, turned(a), 0.0));
        let e1 = found.next()?;
        let Some(e2) = found.next() else {
            return Some(e1);
        };
        let f = e2 - e1;
        let across = dir.perp_dot(f);
        if across.abs() <= 1e-3 * f.length() {
            return Some(e1);
        }
        let s = (e1 - t).perp_dot(f) / across;
        let reach = 2.0 * e1.distance(t).max(e2.distance(t));
        let e = t + dir * s;
        (s <= 0.0 && s >= -reach && self.on(e))
            .then_some(e)
            .or(Some(e1))
    }

    /// The corner where the region's edge meets the target's extent edge, for a threshold
    /// point `t` lying on that extent edge or within `reach` of it along `dir` (in parameters):
    /// near such a corner the samples along any line from `t` leave the extent, but along the
    /// extent edge itself the gap follows the same power law, the corner being its zero. The
    /// extent edge is found by bisection along `dir` on lines offset across it, and the zero
    /// fitted in the offset, either way (the other way runs along the region, where the gap
    /// does not rise, or past its far corner, a zero ahead: no fit).
    fn corner(&self, t: DVec2, dir: DVec2, reach: f64) -> Option<DVec2> {
        self.slide(t, dir, reach, false)
    }

    /// The corner of [`Self::corner`] ahead of a point `t` on the extent edge, inside the
    /// region (where the region narrows to an acute corner between grid lines, whose points
    /// densifying converges on but never reaches): the zero lies between `t` and the samples.
    pub(super) fn corner_ahead(&self, t: DVec2, dir: DVec2) -> Option<DVec2> {
        self.slide(t, dir, 1e-6, true)
    }

    /// The zero of the gap along the extent edge from near `t`, behind or `ahead`.
    fn slide(&self, t: DVec2, dir: DVec2, reach: f64, ahead: bool) -> Option<DVec2> {
        let base = self.extent_cross(t, dir, reach)?;
        let across = dir.perp();
        [across, -across].into_iter().find_map(|w| {
            // The extent edge may cross the line at a shallow angle (1 in 10.5 for the tilted
            // square seen from the strip's domain), far along `dir` for a small step across.
            let at = |s: f64| self.extent_cross(base + w * s, dir, reach + 16.0 * s.abs());
            FIRST
                .iter()
                .find_map(|&first| self.zero_on(&at, 0.0, first, ahead))
        })
    }

    /// Where the line along `dir` through `b` leaves the target's extent (or the domain),
    /// within `reach` either side of `b`: the last point inside, to a double's precision.
    fn extent_cross(&self, b: DVec2, dir: DVec2, reach: f64) -> Option<DVec2> {
        let (mut lo, mut hi) = (b - dir * reach, b + dir * reach);
        if self.gap_at(lo).is_none() || self.gap_at(hi).is_some() {
            return None;
        }
        for _ in 0..64 {
            let m = 0.5 * (lo + hi);
            if m == lo || m == hi {
                break;
            }
            if self.gap_at(m).is_some() {
                lo = m;
            } else {
                hi = m;
            }
        }
        Some(lo)
    }

    /// The zero of the gap's power law fitted beyond `t` along the unit direction `w`, when
    /// one fits. It lies behind `t`, within a few samples' spacing or `back`: maybe behind the
    /// region's point the search started from too, which lies on the target only within the
    /// tolerance (a threshold point taken as the inside end when densifying along an edge).
    fn zero_along(&self, t: DVec2, w: DVec2, back: f64) -> Option<DVec2> {
        FIRST
            .iter()
            .find_map(|&first| self.zero_from(t, w, back, first))
    }

    /// [`Self::zero_along`] with the first sample no nearer `t` than `first`.
    fn zero_from(&self, t: DVec2, w: DVec2, back: f64, first: f64) -> Option<DVec2> {
        self.zero_on(&|s: f64| Some(t + w * s), back, first, false)
    }

    /// [`Self::zero_from`] along the path `at` (the point at distance s from where it starts,
    /// None where there is none); the zero may lie `ahead` of the start, short of the samples.
    fn zero_on(
        &self,
        at: &dyn Fn(f64) -> Option<DVec2>,
        back: f64,
        first: f64,
        ahead: bool,
    ) -> Option<DVec2> {
        let gap_at = |s: f64| at(s).and_then(|p| self.gap_at(p));
        let (d, g1) = self.first_sample(&gap_at, first)?;
        let s = [d, 2.0 * d, 4.0 * d];
        let g = [g1, gap_at(s[1])?, gap_at(s[2])?];
        let s0 = match fit_zero(s, g) {
            Some(z) => z,
            None => fit_power(s, g, (3.0 * d, gap_at(3.0 * d)?))?,
        };
        if ahead {
            if !(s0 >= -1e-3 * d && s0 <= d) {
                return None;
            }
        } else if !(s0 <= 1e-3 * d && s0 >= -back.max(BEHIND * d)) {
            return None;
        }
        let e = at(if ahead { s0.max(0.0) } else { s0.min(0.0) })?;
        self.on(e).then_some(e)
    }
}

impl Tracer<'_, '_> {
    /// The first sample of a fit along the path whose gap is `gap_at`: the nearest of
    /// `first`·2^m (up to [`REACH`]) where the gap stands [`ABOVE`] the tolerance, so that its
    /// roundoff is small beside it (the samples may lie past the region's edge search's far
    /// end: a densifying search brackets the edge closely); None where there is none, or
    /// where the path leaves the domain or the target's extent first.
    ///
    /// The gap rises steadily out from the threshold, so the doublings are not walked from
    /// `first` (13 projections for a tangent parting) but from where the last fit's first
    /// sample stood, down while the one before also stands above, or up until one does (2 or
    /// 3 projections where the edge's shape changes little from one boundary point to the
    /// next). Where the gap does rise steadily, the sample is the one walking from `first`
    /// finds.
    fn first_sample(&self, gap_at: &dyn Fn(f64) -> Option<f64>, first: f64) -> Option<(f64, f64)> {
        let mut top = 0;
        while first * 2f64.powi(top + 1) <= REACH {
            top += 1;
        }
        let d = |m: i32| first * 2f64.powi(m);
        // Whether the m-th doubling's gap stands above the tolerance, or is unknown.
        let rises = |m: i32| {
            let g = gap_at(d(m));
            (g.is_none_or(|g| g >= ABOVE * self.tol), g)
        };
        let start = self
            .rise
            .get()
            .map_or(0, |r| (r / first).log2().round() as i32);
        let mut m = start.clamp(0, top);
        let (up, mut g) = rises(m);
        if up {
            while m > 0 {
                let (below, gb) = rises(m - 1);
                if !below {
                    break;
                }
                (m, g) = (m - 1, gb);
            }
        } else {
            loop {
                m += 1;
                if m > top {
                    return None;
                }
                let (above, ga) = rises(m);
                if above {
                    g = ga;
                    break;
                }
            }
        }
        let g = g?;
        self.rise.set(Some(d(m)));
        Some((d(m), g))
    }
}

/// Whether `r`, the offset of a point from its foot `uv` on the patch's boundary, has no part
/// along a parameter held at the domain's edge there (to a thousandth of `tol`): the point
/// lies over the boundary, not beyond it (on the line of a ruled square's edge, off the square
/// by its gap), and its distance is the gap.
fn over_edge(patch: &Patch, uv: DVec2, r: DVec3, tol: f64) -> bool {
    let periodic = patch.periodic();
    let (du, dv) = patch.derivs(uv);
    [du, dv].iter().enumerate().all(|(k, d)| {
        periodic[k] || (uv[k] != 0.0 && uv[k] != 1.0) || r.dot(*d).abs() <= 1e-3 * tol * d.length()
    })
}

/// The zero of `c·(s − s0)^k` through the samples `(s[i], g[i])` for the k ∈ {1, 2, 3} that
/// predicts the third sample from the first two best (None when none predicts it within
/// [`FIT`]): the common partings, fitted from two samples so the power law's next term (an
/// arc's gap is not quite a parabola) moves the zero least; then taken through the third too
/// ([`quadratic_zero`]).
fn fit_zero(s: [f64; 3], g: [f64; 3]) -> Option<f64> {
    let mut best: Option<(f64, f64, [f64; 3])> = None;
    for k in 1..=3 {
        let f = g.map(|x| x.powf(1.0 / k as f64));
        let slope = (f[1] - f[0]) / (s[1] - s[0]);
        if !(slope > 0.0 && slope.is_finite()) {
            continue;
        }
        let predicted = f[1] + slope * (s[2] - s[1]);
        let misfit = (predicted - f[2]).abs() / f[2];
        if misfit <= FIT && best.is_none_or(|(m, ..)| misfit < m) {
            best = Some((misfit, s[0] - f[0] / slope, f));
        }
    }
    let (_, linear, f) = best?;
    Some(quadratic_zero(s, f, linear))
}

/// The zero near `linear` of the parabola through the samples `(s[i], f[i])` of the gap's
/// k-th root, which the power law makes linear in the distance from the region's edge: the
/// search line is straight in the traced surface's parameters, and where that surface's map
/// is not linear along it (a ruled square whose bottom edge is tilted: its points are
/// bilinear in u and v) the distance from the edge is not linear in s either. The line
/// through the first two samples then puts the zero off by the curvature times the samples'
/// spacing squared (3.3e-8 for the tilted square's lines oblique to u and v); the parabola
/// takes the curvature out, to its change over the samples. Where the parabola has no zero
/// near the line's (farther than the samples' spacing, or falling there), the line's.
fn quadratic_zero(s: [f64; 3], f: [f64; 3], linear: f64) -> f64 {
    let f01 = (f[1] - f[0]) / (s[1] - s[0]);
    let f12 = (f[2] - f[1]) / (s[2] - s[1]);
    let f012 = (f12 - f01) / (s[2] - s[0]);
    let q = |x: f64| f[0] + (x - s[0]) * (f01 + f012 * (x - s[1]));
    let dq = |x: f64| f01 + f012 * (2.0 * x - s[0] - s[1]);
    let mut z = linear;
    for _ in 0..8 {
        let slope = dq(z);
        if slope.is_nan() || slope <= 0.0 {
            return linear;
        }
        let step = q(z) / slope;
        z -= step;
        if step.abs() <= 1e-15 * s[2] {
            break;
        }
    }
    if z.is_finite() && (z - linear).abs() <= s[1] - s[0] && dq(z) > 0.0 {
        z
    } else {
        linear
    }
}

/// The zero of `c·(s − s0)^k` through three samples with the power k fitted too (surfaces
/// parting with higher-order contact: a flat joining a curve whose curvature and its
/// derivatives are continuous), when k lies in [`POWERS`] and the law predicts a fourth
/// sample `check` within [`FIT`]. The three equations reduce to one in y = s[0] − s0: the
/// ratio of the logarithmic steps ln(g1/g0) / ln(g2/g1), which falls steadily from ∞ (y → 0)
/// to (s1 − s0) / (s2 − s1) (y → ∞), solved by bisection of log y.
fn fit_power(s: [f64; 3], g: [f64; 3], check: (f64, f64)) -> Option<f64> {
    if !(g[0] > 0.0 && g[1] > g[0] && g[2] > g[1] && check.1 > 0.0) {
        return None;
    }
    let rho = (g[1] / g[0]).ln() / (g[2] / g[1]).ln();
    let (a1, a2) = (s[1] - s[0], s[2] - s[0]);
    let ratio = |y: f64| ((a1 + y) / y).ln() / ((a2 + y) / (a1 + y)).ln();
    let (mut lo, mut hi) = ((1e-12 * a2).ln(), (1e6 * a2).ln());
    if !(ratio(lo.exp()) >= rho && ratio(hi.exp()) <= rho) {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if ratio(mid.exp()) > rho {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let y = (0.5 * (lo + hi)).exp();
    let k = (g[1] / g[0]).ln() / ((a1 + y) / y).ln();
    if !POWERS.contains(&k) {
        return None;
    }
    // The fourth sample's distance from the zero, as the law predicts it from the first.
    let predicted = y * (check.1 / g[0]).powf(1.0 / k);
    let actual = check.0 - s[0] + y;
    ((predicted - actual).abs() <= FIT * actual).then_some(s[0] - y)
}

#[cfg(test)]
mod tests {
    use super::{fit_power, fit_zero};

    #[test]
    fn the_fit_finds_the_zero_and_the_power() {
        for (k, s0) in [(1, -0.3), (2, -1e-4), (3, -0.02)] {
            let s = [0.01, 0.02, 0.04];
            let g = s.map(|x: f64| 0.7 * (x - s0).powi(k));
            let z = fit_zero(s, g).unwrap();
            assert!((z - s0).abs() <= 1e-12, "k {k}: {z} vs {s0}");
        }
        // An arc's gap R(1 − cos(x/R)): the quadratic, to the next term's error.
        let (r, s0) = (10.0f64, -1e-4);
        let s = [1e-3, 2e-3, 4e-3];
        let g = s.map(|x: f64| r * (1.0 - ((x - s0) / r).cos()));
        assert!((fit_zero(s, g).unwrap() - s0).abs() <= 1e-10);
        // No power law: none.
        assert!(fit_zero(s, [1.0, 5.0, 2.0]).is_none());
    }

    #[test]
    fn the_zero_is_found_where_the_distance_from_the_edge_bends_along_the_line() {
        // The distance from the edge quadratic in s, φ(s) = s + b·s² (a ruled square whose
        // points are bilinear in its parameters, along a line oblique to both), the gap
        // c·(φ(s) − φ(s0))^k: the line through the first two samples' k-th roots puts the
        // zero off by about b·s[0]·s[1] (computed here, to show the case bites); the fit not.
        let (b, s) = (0.05, [0.01, 0.02, 0.04]);
        for (k, s0) in [(1, -3e-3), (2, -1e-4), (3, -2e-3)] {
            let phi = |x: f64| x + b * x * x;
            let g = s.map(|x: f64| 0.7 * (phi(x) - phi(s0)).powi(k));
            let f = g.map(|x| x.powf(1.0 / k as f64));
            let line = s[0] - f[0] * (s[1] - s[0]) / (f[1] - f[0]);
            assert!((line - s0).abs() >= 5e-6, "k {k}: the line's {line}");
            let z = fit_zero(s, g).unwrap();
            assert!((z - s0).abs() <= 1e-14, "k {k}: {z} vs {s0}");
        }
    }

    #[test]
    fn the_power_is_fitted_where_no_whole_one_to_three_fits() {
        let s = [0.01, 0.02, 0.04];
        for (k, s0) in [
            (4.0, -0.004),
            (5.0, -0.01),
            (2.5, -1e-4),
            (8.0, -0.02),
            (1.0, -0.3),
        ] {
            let g = s.map(|x: f64| 0.7 * (x - s0).powf(k));
            if k > 3.0 {
                assert!(fit_zero(s, g).is_none(), "k {k}");
            }
            let check = (0.03, 0.7 * (0.03 - s0).powf(k));
            let z = fit_power(s, g, check).unwrap();
            assert!((z - s0).abs() <= 1e-12 * s[2], "k {k}: {z} vs {s0}");
        }
        // A gap of s⁴ + s⁵/10 near its zero: the fourth-order law to the next term's error.
        let gap = |x: f64| (x + 1e-3).powi(4) * (1.0 + (x + 1e-3) / 10.0);
        let check = (3e-3, gap(3e-3));
        let z = fit_power([1e-3, 2e-3, 4e-3], [gap(1e-3), gap(2e-3), gap(4e-3)], check);
        assert!((z.unwrap() + 1e-3).abs() <= 1e-6, "{z:?}");
        // Three samples fit some power; a fourth off the law is refused.
        let g = s.map(|x: f64| (x + 0.004).powi(4));
        assert!(fit_power(s, g, (0.03, 2.0 * (0.034f64).powi(4))).is_none());
        // Not rising, or rising faster than any power whose zero lies behind the first sample
        // (its logarithmic steps in the ratio 0.39, below the 1/2 of a zero far behind): none.
        assert!(fit_power(s, [1.0, 1.0, 2.0], (0.03, 1.5)).is_none());
        assert!(fit_power(s, [1.0, 1.1, 1.4], (0.03, 1.2)).is_none());
    }
}
