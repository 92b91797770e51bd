//! Where a common region ends, to the tolerance of the surfaces rather than of the gap.
//!
//! Bisection on "the gap is within the tolerance" stops where the gap reaches the tolerance.
//! Where the surfaces part across a crease that is the edge itself, to within tol/slope; where
//! they part tangentially (a flat joining an arc of radius R, the gap growing like s²/2R) it is
//! √(2·tol·R) beyond the edge: 1e-4 for R = 10 and tol = 1e-9. Beyond the threshold the gap is
//! `c·(s − s0)^k` (k = 1 across a crease, 2 past a tangent join with a jump in curvature, 3 past
//! a curvature-continuous one), so `gap^(1/k)` is linear in s: two samples well above the
//! tolerance give s0 by extrapolation and a third tells which k holds. When none fits (the gap
//! is the other surface's extent ending, or not a power law) the threshold point stays.

use super::{Target, Tracer};
use glam::{DVec2, DVec3};

/// How far above the tracer's tolerance the first sample's gap must be: large enough that its
/// roundoff (about 1e-15 of the scale) is small beside it, small enough that the power law's
/// next term is negligible.
const ABOVE: f64 = 64.0;

/// Farthest the first sample goes past the threshold, in parameters (a grid cell is 1/32).
const REACH: f64 = 1.0 / 64.0;

/// Largest relative misfit of the third sample for a power law to be taken.
const FIT: f64 = 1e-3;

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
                let uv = patch.project(p, hint.get());
                let periodic = patch.periodic();
                let at_edge = (0..2).any(|k| !periodic[k] && (uv[k] == 0.0 || uv[k] == 1.0));
                (!at_edge).then(|| patch.eval(uv).distance(p))
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

    /// The zero of the gap's power law fitted beyond the threshold point `t` on the line from
    /// `lo` to `hi`, when one fits and lies between `lo` and `t`.
    fn extrapolated(&self, lo: DVec2, t: DVec2, hi: DVec2) -> Option<DVec2> {
        let span = hi.distance(lo);
        if span == 0.0 {
            return None;
        }
        let dir = (hi - lo) / span;
        let at = |s: f64| t + dir * s;
        // Out from the threshold in doubling steps until the gap stands well above it (the
        // samples may lie past `hi`: a densifying search brackets the edge closely).
        let mut d = 1e-7;
        let g1 = loop {
            let g = self.gap_at(at(d))?;
            if g >= ABOVE * self.tol {
                break g;
            }
            d *= 2.0;
            if d > REACH {
                return None;
            }
        };
        let (g2, g3) = (self.gap_at(at(2.0 * d))?, self.gap_at(at(4.0 * d))?);
        let s0 = fit_zero([d, 2.0 * d, 4.0 * d], [g1, g2, g3])?;
        // The edge lies between the region's point and the threshold (a little slack for the
        // fit's own error either side: the region's point may be on the edge itself).
        let back = t.distance(lo);
        let slack = 1e-3 * back;
        if !(s0 <= slack && s0 >= -back - slack) {
            return None;
        }
        let e = at(s0.clamp(-back, 0.0));
        self.on(e).then_some(e)
    }
}

/// The zero of `c·(s − s0)^k` through the samples `(s[i], g[i])` for the k ∈ {1, 2, 3} that
/// predicts the third sample from the first two best (None when none predicts it within
/// [`FIT`]).
fn fit_zero(s: [f64; 3], g: [f64; 3]) -> Option<f64> {
    let mut best: Option<(f64, f64)> = None;
    for k in 1..=3 {
        let f = g.map(|x| x.powf(1.0 / k as f64));
        let slope = (f[1] - f[0]) / (s[1] - s[0]);
        if !(slope > 0.0 && slope.is_finite()) {
            continue;
        }
        let predicted = f[1] + slope * (s[2] - s[1]);
        let misfit = (predicted - f[2]).abs() / f[2];
        if misfit <= FIT && best.is_none_or(|(m, _)| misfit < m) {
            best = Some((misfit, s[0] - f[0] / slope));
        }
    }
    best.map(|(_, s0)| s0)
}

#[cfg(test)]
mod tests {
    use super::fit_zero;

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
}
