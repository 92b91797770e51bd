//! A crossing's point found across it where Newton crawls: near a branch point the surfaces
//! part so slowly across the curve (their Jacobian near singular, its damped steps capped) that
//! Newton stops within the tolerance of both far off the curve. Along a line across the curve
//! the gap between the surfaces still has a simple root there, well conditioned as a 1-D root
//! (its slope, however small, is far above the gap's rounding), and bracketed it is found to
//! that rounding. A tangent contact's gap has an even root, with no sign change to bracket.

use super::{Node, Patch};
use crate::geom::root::{from_newton_step, illinois, At, NewtonStep, Stop};
use glam::{DVec2, DVec3};
use std::cell::Cell;

/// The point of the crossing through `m` (a point of both `a` and `b` within `tol`, the
/// midpoint of the chord `p0p1`, where the surfaces' derivatives are about `cols`) on the
/// line through it in `a` along which the gap grows fastest (b's normal projected onto a's
/// tangent plane: across the curve, whatever the chord's direction): Newton's 1-D step on the
/// signed gap from `a` to `b` (its slope from the normals), and where the gap changes sign
/// there or just beyond, the root bracketed by the Illinois method (or the step's point, where
/// its gap is at the rounding). None where the step does not cut the gap eightfold (a
/// contact's even root: it cuts it fourfold, and the gap keeps its sign), where the line leaves
/// either surface, or where the root would be farther than four times the chord's length and
/// the point's distance from it (another curve's root). Where the step cuts it so but is
/// longer than a contact's (see [`flat`]), [`Across::Neither`] unless a sign change lies within
/// three steps (see [`past_flat`]).
pub(super) fn onto_crossing(
    a: &Patch,
    b: &Patch,
    m: &Node,
    ((p0, p1), cols): ((DVec3, DVec3), [DVec3; 4]),
    tol: f64,
) -> Across<Node> {
    crossing_across(a, b, m, ((p0, p1), cols), tol).unwrap_or(Across::Stands)
}

/// What became of a point Newton may have left off the curve, taken across it.
pub(super) enum Across<P> {
    /// The crossing's point on the line across.
    Onto(P),
    /// The point stands as Newton left it: on a contact's double zero, or nothing better found.
    Stands,
    /// The point is neither a crossing's nor a contact's: not to be put in the curve.
    Neither,
}

/// [`onto_crossing`], None where Newton's point stands.
fn crossing_across(
    a: &Patch,
    b: &Patch,
    m: &Node,
    ((p0, p1), cols): ((DVec3, DVec3), [DVec3; 4]),
    tol: f64,
) -> Option<Across<Node>> {
    let chord = p1 - p0;
    // How far the root may lie: four times the chord's length and the point's distance from it
    // (Newton's point may be crawled off it by more than the chord is long, deep in densify).
    let reach = 4.0 * (chord.length() + (m.point - p0).cross(chord).length() / chord.length());
    let [su, sv, bu, bv] = cols;
    let nb = bu.cross(bv).try_normalize()?;
    let na = su.cross(sv).try_normalize()?;
    // Across the curve, not the chord: beside a branch point a chord's end can itself be off
    // the curve, and a line square to that chord then ran almost along the crossing (which
    // leaves the contact nearly square to it there), where the gap hardly changes; the probe
    // below took it for a contact's, and the point stayed 1.7e-5 off. Along a good chord the
    // two directions agree (the curve's tangent is a's normal × b's).
    let across = (nb - na * na.dot(nb)).try_normalize()?;
    // The parameter direction whose image is `across` (unit speed in space).
    let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
    let det = e * g - f * f;
    if !(det > 0.0 && det.is_finite()) {
        return None;
    }
    let (c0, c1) = (su.dot(across), sv.dot(across));
    let dir = DVec2::new(g * c0 - f * c1, e * c1 - f * c0) / det;
    let warm = Cell::new(m.uv[1]);
    let at = |s: f64| node_at(a, b, (m.uv[0] + dir * s, &warm), tol);
    let noise = rounding(a, b);
    let g0 = (a.eval(m.uv[0]) - b.eval(m.uv[1])).dot(nb);
    let step = -g0 / across.dot(nb);
    // A gap within a few roundings says nothing of where the root is (beside a branch point
    // the surfaces are that close over a stretch as wide as the step). `noise` bounds it from
    // the surfaces' sizes; where the gap is under that bound its own rounding is read.
    let in_noise = g0.abs() <= 8.0 * noise && g0.abs() <= 8.0 * gap_noise(a, b, m, (cols, nb), g0);
    if in_noise || !(step.is_finite() && step.abs() <= reach) {
        return None;
    }
    // Most points here are a contact's (Newton crawls onto its double zero too): told first by
    // a probe with b's foot moved one Gauss–Newton step, its error third order in the step.
    let probe = probe_at(a, b, m, (dir * step, [bu, bv], nb))?;
    if probe.signum() == g0.signum() && 8.0 * probe.abs() > g0.abs() {
        if !flat(step, tol, a.scale().min(b.scale())) {
            return None;
        }
        let found = past_flat(&at, (g0, 3.0 * step), (reach, noise), 1e-3 * tol, None);
        return Some(match found {
            Some(root) if root.payload.residual <= tol => Across::Onto(root.payload),
            _ => Across::Neither,
        });
    }
    // `dir` is of unit speed in space, so the reach and the width are the argument's own.
    let newton = NewtonStep {
        f0: g0,
        t: step,
        unit: 1.0,
        reach,
        width: 1e-3 * tol,
        rounding: noise,
    };
    // The start's gap is taken again for a bracket [0, step]: `g0` is to b's foot at `m`,
    // `at`'s to b's point projected, and the bracketed sign must be the node's.
    let root = from_newton_step(&at, newton, None)?;
    (root.payload.residual <= tol).then_some(Across::Onto(root.payload))
}

/// Whether a Newton step of length `step` across a curve (in space) that cut the gap only as
/// a contact's double zero does is longer than a contact's: within the tolerance `tol` of both
/// surfaces Newton leaves a point of a contact whose gap curves on the surfaces' `scale` about
/// √(tol·scale)/10 off it, its step half that; beside a branch point, where the crossing runs
/// into the contact and the gap across flattens to a triple root, points are left up to ∛tol
/// off both curves (5e-4 on the sheet of surface_contact_crossing, `near` there 2.9e-4), and
/// their steps are as long as a quarter of √(tol·scale) (1.8e-5 there) and more. Only such
/// points pay for [`past_flat`]: the surfaces of the benches (a torus touching a plane) have
/// contacts that curve on their own scale, and their midpoints' steps are far shorter.
pub(super) fn flat(step: f64, tol: f64, scale: f64) -> bool {
    step.abs() > 0.25 * (tol * scale).sqrt()
}

/// The crossing's root between 0 and `far` (three Newton steps, on `f`'s argument) where the
/// gap `g0` at 0 fell under the first step only as at a contact's double zero: beside a branch
/// point the gap across is near a triple root and Newton cuts a crossing's gap so too (3.4 to
/// 4-fold), the root up to three steps on (a double zero's lies two on, and the gap three on is
/// a quarter of `g0`, its sign the same). Bracketed where the gap at `far` has the other sign
/// (beyond `noise`) and solved by the Illinois method to `width`; None where it keeps its sign,
/// `far` lies beyond `reach`, or `f` cannot be evaluated. `start` is `f`'s payload at 0 where
/// `g0` is `f`'s own value there (else `f` is evaluated at 0 for the bracket).
pub(super) fn past_flat<P>(
    mut f: impl FnMut(f64) -> Option<(f64, P)>,
    (g0, far): (f64, f64),
    (reach, noise): (f64, f64),
    width: f64,
    start: Option<P>,
) -> Option<At<P>> {
    if !(far.is_finite() && far.abs() <= reach) {
        return None;
    }
    let (g, payload) = f(far)?;
    if g.signum() == g0.signum() || g.abs() <= noise || !g.is_finite() {
        return None;
    }
    let zero = At::at_zero(g0, start, &mut f)?;
    let end = At {
        t: far,
        f: g,
        payload,
    };
    illinois(f, [zero, end], Stop::Width(width))
}

/// The signed gap from `a` at `m`'s parameters moved by `du` to `b` along `nb` (b's unit normal
/// at `m`, its derivatives there `[bu, bv]`), b's foot moved from `m`'s by one Gauss–Newton
/// step: None where `a`'s point leaves its domain.
fn probe_at(
    a: &Patch,
    b: &Patch,
    m: &Node,
    (du, [bu, bv], nb): (DVec2, [DVec3; 2], DVec3),
) -> Option<f64> {
    let mut ua = m.uv[0] + du;
    if a.normalise(&mut ua) != [false; 2] {
        return None;
    }
    let pa = a.eval(ua);
    let d = pa - b.eval(m.uv[1]);
    let (e, f, g) = (bu.dot(bu), bu.dot(bv), bv.dot(bv));
    let det = e * g - f * f;
    let (d0, d1) = (bu.dot(d), bv.dot(d));
    let mut ub = m.uv[1] + DVec2::new(g * d0 - f * d1, e * d1 - f * d0) / det;
    b.normalise(&mut ub);
    let gap = (pa - b.eval(ub)).dot(nb);
    gap.is_finite().then_some(gap)
}

/// The rounding of a gap between points of `a` and `b`: a few ulps of their coordinates' size.
/// A residual within it is as near both as any computation gets, and a sign within it says
/// nothing.
pub(super) fn rounding(a: &Patch, b: &Patch) -> f64 {
    4.0 * f64::EPSILON * a.scale().max(b.scale())
}

/// The rounding of the gap `g0` from `a` to `b` along `nb` at `m` (the surfaces' derivatives
/// there `cols`), read from the gap itself: each parameter nudged by 1, 2 and 3 ulps each way in
/// turn, the gap's change beyond what the derivative predicts is rounding, and its largest,
/// doubled, bounds it. One nudge can land where the rounding happens to cancel (beside a tilted
/// 200-wide plate, at +2 ulps of both its parameters, to 1/257 of the scatter); six per
/// parameter did not all land so. [`rounding`] takes it from the surfaces' sizes, which beside
/// a small point of a large surface (a crossing at r = 2 on an 8×8 plate: 1e-14, where the
/// gap's own is 4e-16) hides a gap that still tells where its root is.
fn gap_noise(a: &Patch, b: &Patch, m: &Node, (cols, nb): ([DVec3; 4], DVec3), g0: f64) -> f64 {
    let [su, sv, bu, bv] = cols;
    let mut spread = 0.0_f64;
    for (k, col) in [su, sv, -bu, -bv].into_iter().enumerate() {
        for up in [false, true] {
            let mut uv = m.uv;
            let before = uv[k / 2][k % 2];
            for _ in 0..3 {
                let x = &mut uv[k / 2][k % 2];
                *x = if up { x.next_up() } else { x.next_down() };
                let h = *x - before;
                let off = ((a.eval(uv[0]) - b.eval(uv[1])).dot(nb) - g0 - h * col.dot(nb)).abs();
                // Not a number (a point past a domain's end): the sizes' bound stands.
                if !off.is_finite() {
                    return f64::INFINITY;
                }
                spread = spread.max(off);
            }
        }
    }
    2.0 * spread.max(f64::EPSILON * g0.abs())
}

/// The signed gap from `a` at `ua` to `b` (its nearest point searched from `warm`, which it
/// updates) along b's normal there, and the node midway: None where `ua` leaves a's domain or
/// a's point lies past b's edge (the distance then exceeds the signed gap by more than `tol`).
fn node_at(
    a: &Patch,
    b: &Patch,
    (ua, warm): (DVec2, &Cell<DVec2>),
    tol: f64,
) -> Option<(f64, Node)> {
    let mut ua = ua;
    if a.normalise(&mut ua) != [false; 2] {
        return None;
    }
    let pa = a.eval(ua);
    let ub = b.project(pa, Some(warm.get()));
    warm.set(ub);
    let pb = b.eval(ub);
    let (bu, bv) = b.derivs(ub);
    let n = bu.cross(bv).try_normalize()?;
    let (signed, dist) = ((pa - pb).dot(n), pa.distance(pb));
    let node = Node {
        uv: [ua, ub],
        point: 0.5 * (pa + pb),
        residual: dist,
    };
    (dist - signed.abs() <= tol && signed.is_finite()).then_some((signed, node))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::surface::Surface;
    use std::f64::consts::{PI, TAU};

    const R: f64 = 2.0;

    /// A ball of radius 2 about `c` and a square plate of half-width `w` through `c`, square
    /// to `n` (its boundary wound about `n`, so its normal is `n`).
    fn ball_and_plate(c: DVec3, n: DVec3, w: f64) -> (Surface, Surface) {
        let e1 = n.cross(DVec3::X).normalize();
        let e2 = n.cross(e1);
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        let plate = Surface::plane(corners.map(|(s, t)| c + w * (s * e1 + t * e2)).to_vec());
        (Surface::sphere(c, R).unwrap(), plate.unwrap())
    }

    /// What `onto_crossing` hands `gap_noise` at the ball's point at height `z` over the plate
    /// (the gap's true value, but for the parameters' rounding) and angle `t` about `n`: the
    /// node (the plate's foot projected), the columns, the plate's normal (from difference
    /// quotients: 1e-12 off `n` beside a 200-wide plate) and the gap computed as there.
    fn at(a: &Patch, b: &Patch, n: DVec3, (t, z): (f64, f64)) -> Sample {
        let e1 = n.cross(DVec3::X).normalize();
        let e2 = n.cross(e1);
        let d = (R * R - z * z).sqrt() * (t.cos() * e1 + t.sin() * e2) + z * n;
        let lon = d.y.atan2(d.x).rem_euclid(TAU) / TAU;
        let ua = DVec2::new(lon, (d.z / R).asin() / PI + 0.5);
        let pa = a.eval(ua);
        let ub = b.project(pa, None);
        let pb = b.eval(ub);
        let ((su, sv), (bu, bv)) = (a.derivs(ua), b.derivs(ub));
        let nb = bu.cross(bv).normalize();
        assert!(nb.distance(n) <= 1e-9, "{nb} vs {n}");
        let m = Node {
            uv: [ua, ub],
            point: 0.5 * (pa + pb),
            residual: pa.distance(pb),
        };
        let g0 = (pa - pb).dot(nb);
        Sample {
            m,
            cols: [su, sv, bu, bv],
            nb,
            g0,
        }
    }

    struct Sample {
        m: Node,
        cols: [DVec3; 4],
        nb: DVec3,
        g0: f64,
    }

    impl Sample {
        fn noise(&self, a: &Patch, b: &Patch) -> f64 {
            gap_noise(a, b, &self.m, (self.cols, self.nb), self.g0)
        }

        /// The gap's rounding seen independently: each parameter moved by up to 16 ulps each
        /// way, the gap's change less the closed form's (the ball's derivatives along the
        /// plate's normal; the plate's own are square to it), at its largest.
        fn scatter(&self, a: &Patch, b: &Patch) -> f64 {
            let [ua, _] = self.m.uv;
            let (lon, lat) = (TAU * ua.x, PI * (ua.y - 0.5));
            let du = TAU * R * lat.cos() * DVec3::new(-lon.sin(), lon.cos(), 0.0);
            let dv = PI * R * DVec3::new(-lat.sin() * lon.cos(), -lat.sin() * lon.sin(), lat.cos());
            let slopes = [du.dot(self.nb), dv.dot(self.nb), 0.0, 0.0];
            let mut most = 0.0_f64;
            for (k, slope) in slopes.into_iter().enumerate() {
                for j in -16_i32..=16 {
                    let mut uv = self.m.uv;
                    let x = &mut uv[k / 2][k % 2];
                    let before = *x;
                    for _ in 0..j.abs() {
                        *x = if j > 0 { x.next_up() } else { x.next_down() };
                    }
                    let h = *x - before;
                    let g = (a.eval(uv[0]) - b.eval(uv[1])).dot(self.nb);
                    most = most.max((g - self.g0 - h * slope).abs());
                }
            }
            most
        }
    }

    #[test]
    fn beside_a_plate_square_to_an_axis_the_noise_is_the_balls_rounding_not_the_plates_size() {
        // The plate's z is exact (0.3 in every point); the gap's rounding is the ball's, a
        // fraction of an ulp of its coordinates (about 5e-17), where the sizes' bound of a
        // 200-wide plate is 2.5e-13.
        let (c, n) = (DVec3::new(0.1, 0.2, 0.3), DVec3::Z);
        let (ball, plate) = ball_and_plate(c, n, 100.0);
        let (a, b) = (Patch::new(&ball), Patch::new(&plate));
        for t in [0.1, 0.9, 2.0, 3.3, 5.5] {
            for z in [0.0, 1e-12, -3e-13] {
                let s = at(&a, &b, n, (t, z));
                let noise = s.noise(&a, &b);
                let ulp = f64::EPSILON * s.m.point.abs().max_element();
                // Within eight times the bound (onto_crossing's test) lie the gap's error
                // from its true value at the parameters taken (not quite `z`: the ball's
                // v is rounded, by up to 3.5e-16 in the gap) and its scatter over 16 ulps of
                // each parameter.
                let exact = R * (PI * (s.m.uv[0].y - 0.5)).sin();
                assert!(
                    (s.g0 - exact).abs() <= 8.0 * noise,
                    "{t} {z}: {} {noise:e}",
                    s.g0
                );
                assert!(s.scatter(&a, &b) <= 8.0 * noise, "{t} {z}: {noise:e}");
                // Yet it is the gap's rounding: under an ulp of the point's coordinates.
                assert!(noise > 0.0 && noise <= ulp, "{t} {z}: {noise:e} vs {ulp:e}");
                assert!(noise <= 1e-3 * rounding(&a, &b), "{t} {z}: {noise:e}");
            }
        }
    }

    #[test]
    fn a_true_gap_of_1e_12_beside_a_large_plate_is_not_taken_for_noise() {
        // 1e-12 is within eight times the sizes' bound of a 200-wide plate (2.5e-13), which
        // alone said nothing of where the root is; the gap's own rounding tells it.
        let (c, n) = (DVec3::new(0.1, 0.2, 0.3), DVec3::Z);
        let (ball, plate) = ball_and_plate(c, n, 100.0);
        let (a, b) = (Patch::new(&ball), Patch::new(&plate));
        for t in [0.1, 0.9, 2.0, 3.3, 5.5] {
            let s = at(&a, &b, n, (t, 1e-12));
            assert!((s.g0 - 1e-12).abs() <= 1e-15, "{t}: {:e}", s.g0);
            assert!(s.g0.abs() <= 8.0 * rounding(&a, &b));
            let noise = s.noise(&a, &b);
            assert!(s.g0.abs() > 8.0 * noise, "{t}: {:e} {noise:e}", s.g0);
        }
    }

    /// One nudge of two ulps per parameter (gap_noise before) can land where the gap's
    /// rounding happens to cancel (the plate's comes in steps of 9.5e-16 here, and is 0 at +2
    /// ulps of both its parameters at t = 2): at 45 of these 400 points of the crossing
    /// 8·gap_noise was under the gap's scatter over 16 ulps, by up to 257-fold, and where the
    /// computed gap (truly 0 but for the parameters' rounding) exceeded 8·gap_noise,
    /// `onto_crossing` took rounding for a gap and stepped on it. Nudges of 1, 2 and 3 ulps
    /// each way under-read at none.
    #[test]
    fn beside_a_tilted_plate_the_plates_own_rounding_is_read() {
        // A plate square to (1, 2, 3) has its points summed from coordinates of 100: the gap
        // at a point of the crossing is computed to a few times 1e-15, over 4 ulps of the
        // point's coordinates, and moves by as much from one ulp of the plate's parameters to
        // the next. That must be taken for noise, not for a gap.
        let (c, n) = (
            DVec3::new(0.1, 0.2, 0.3),
            DVec3::new(1.0, 2.0, 3.0).normalize(),
        );
        let (ball, plate) = ball_and_plate(c, n, 100.0);
        let (a, b) = (Patch::new(&ball), Patch::new(&plate));
        let (mut most, mut under, mut worst) = (0.0_f64, Vec::new(), 0.0_f64);
        for i in 0..400 {
            let t = f64::from(i) * TAU / 400.0;
            let s = at(&a, &b, n, (t, 0.0));
            let (noise, scatter) = (s.noise(&a, &b), s.scatter(&a, &b));
            most = most.max(scatter / (f64::EPSILON * s.m.point.abs().max_element()));
            assert!(noise <= rounding(&a, &b), "{t}: {noise:e}");
            worst = worst.max(scatter / noise);
            if scatter > 8.0 * noise {
                under.push(format!("t {t:.4}: scatter {scatter:.2e} noise {noise:.2e}"));
            }
        }
        assert!(
            most > 4.0,
            "the plate's rounding is not over the point's: {most}"
        );
        let list = under.join("\n");
        assert!(
            under.is_empty(),
            "{} of 400, to {worst:.0}-fold:\n{list}",
            under.len()
        );
    }
}
