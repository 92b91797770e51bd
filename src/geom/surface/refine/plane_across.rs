//! A plane section's point found across the curve where Newton crawls: beside a branch point
//! (a crossing running into a tangent contact) the signed distance to the plane has the
//! crossing's simple root next to the contact's double one, Newton's steps onto it stop
//! shrinking fourfold (taken for a contact's, see `newton::shrinks`), and the point stops
//! within the tolerance of the plane far off the curve (1e-5 seen at W = 3.7e-4). Along the
//! line across the curve the distance's simple root is still well conditioned as a 1-D root,
//! and bracketed it is found to its rounding — what `across::onto_crossing` does for two
//! surfaces.

use super::across::{flat, past_flat, Across};
use super::Patch;
use crate::geom::root::{from_newton_step, NewtonStep};
use glam::{DVec2, DVec3};

/// The crossing's point across the curve from `uv` (a point of `s` within `tol` of the plane
/// through `p0` with unit normal `n`, at `at` in space): the root of the signed distance on
/// the line through `uv` along which it grows fastest in space, bracketed from Newton's 1-D
/// step (or past it by twice the secant's estimate of what is left) and solved by the
/// Illinois method (Newton's step itself where it lands within the distance's rounding). None
/// where the point is already as near as the distance's rounding tells, its Newton step is
/// within 1e-3·`tol`, the step does not cut the distance eightfold (a contact's even root), no
/// sign change lies within `reach`, or the line leaves `s`: [`Across::Stands`] then, but
/// [`Across::Neither`] where the step cut it so and is longer than a contact's (see
/// `across::flat`) and no sign change lies within three steps (see `across::past_flat`).
pub(super) fn onto_plane_crossing(
    s: &Patch,
    (uv, at): (DVec2, DVec3),
    (p0, n): (DVec3, DVec3),
    tol: f64,
    reach: f64,
) -> Across<DVec2> {
    plane_crossing(s, (uv, at), (p0, n), tol, reach).unwrap_or(Across::Stands)
}

/// [`onto_plane_crossing`], None where the point stands.
fn plane_crossing(
    s: &Patch,
    (uv, at): (DVec2, DVec3),
    (p0, n): (DVec3, DVec3),
    tol: f64,
    reach: f64,
) -> Option<Across<DVec2>> {
    let g0 = n.dot(at - p0);
    // The distance's rounding: a few ulps of the coordinates' size.
    let noise = 8.0 * f64::EPSILON * (at.abs().max_element() + p0.abs().max_element());
    if g0.abs() <= 8.0 * noise {
        return None;
    }
    let (su, sv) = s.derivs(uv);
    let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
    let det = e * g - f * f;
    let grad = DVec2::new(n.dot(su), n.dot(sv));
    // The parameter direction of steepest growth in space (the metric's inverse on the
    // gradient), and the distance's slope along it.
    let dir = DVec2::new(g * grad.x - f * grad.y, e * grad.y - f * grad.x) / det;
    let slope = grad.dot(dir);
    if !(det > 0.0 && slope > 0.0 && slope.is_finite()) {
        return None;
    }
    // t = 1 is Newton's step; its length in space |g0|/√slope.
    let len = g0.abs() / slope.sqrt();
    if len <= 1e-3 * tol || len > reach {
        return None;
    }
    let step = dir * (g0 / slope);
    let dist = |t: f64| {
        let mut q = uv - step * t;
        if s.normalise(&mut q) != [false; 2] {
            return None;
        }
        let d = n.dot(s.eval(q) - p0);
        d.is_finite().then_some((d, q))
    };
    // A step longer than a contact's that cuts the distance as a contact's double zero does
    // (beside a branch point): the crossing looked for within three steps, the point given up
    // where none is (its step's distance is taken again by `from_newton_step` otherwise: only
    // such long steps pay for it).
    if flat(len, tol, s.scale()) {
        let (f1, _) = dist(1.0)?;
        if f1.abs() > 8.0 * noise && f1.signum() == g0.signum() && 8.0 * f1.abs() > g0.abs() {
            let found = past_flat(
                dist,
                (g0, 3.0),
                (reach / len, 8.0 * noise),
                1e-3 * tol / len,
                Some(uv),
            );
            return Some(match found {
                Some(root) if root.f.abs() <= tol => Across::Onto(root.payload),
                _ => Across::Neither,
            });
        }
    }
    // Newton's step lands within the distance's rounding where the point was off only by
    // Newton's crawl (3.8e-8 seen at W = −4.5e-3): kept, with nothing left to bracket and no
    // sign change past it. Its distance is then within `tol` (the start's is, and the
    // rounding is under it), so the check below keeps it.
    let newton = NewtonStep {
        f0: g0,
        t: 1.0,
        unit: len,
        reach,
        width: 1e-3 * tol,
        rounding: 8.0 * noise,
    };
    let root = from_newton_step(dist, newton, Some(uv))?;
    (root.f.abs() <= tol).then_some(Across::Onto(root.payload))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::surface::Surface;

    /// `onto_plane_crossing` from the points of `s` `delta` off the plane through `p0` square
    /// to `n`, across the section from its points `on` (by its closed form, each with the
    /// direction across it in space): each result's distance from the plane in ulps of the
    /// coordinates, or None.
    fn from_beside(
        s: &Patch,
        (p0, n): (DVec3, DVec3),
        on: &[(DVec3, DVec3)],
        deltas: &[f64],
    ) -> Vec<Option<f64>> {
        let tol = 1e-6;
        let mut out = Vec::new();
        for &(q, across) in on {
            for &delta in deltas {
                let uv = s.project(q + delta * across, None);
                let at = s.eval(uv);
                let g0 = n.dot(at - p0);
                // Within the tolerance, and far over the distance's rounding.
                assert!(g0.abs() <= tol && g0.abs() >= 1e-9, "{q} {delta}: {g0:e}");
                let x = match onto_plane_crossing(s, (uv, at), (p0, n), tol, 1.0) {
                    Across::Onto(x) => Some(x),
                    Across::Stands | Across::Neither => None,
                };
                // Within the distance's rounding as `onto_plane_crossing` bounds it (a few
                // ulps of the coordinates), the kept step's promise.
                out.push(x.map(|x| {
                    let p = s.eval(x);
                    let ulps = f64::EPSILON * (p.abs().max_element() + p0.abs().max_element());
                    n.dot(p - p0) / ulps
                }));
            }
        }
        out
    }

    /// Beside a plate and a sphere (no branch point, no crawl) Newton's 1-D step lands on
    /// the plane to the distance's rounding, of either sign or exactly on it. Where it kept the
    /// start's sign, a bracket past it found no sign change (the distance's rounding hides
    /// one so near) and the point was given up (80bd438 keeps it): with the step not kept, 30
    /// of these 240 points came back None.
    #[test]
    fn a_newton_step_onto_the_plane_to_its_rounding_is_kept() {
        let deltas = [3e-9, -2e-8, 1e-7, -4e-7];
        let c = DVec3::new(0.1, 0.2, 0.3);
        // A plate z = 0 cut by the plane through c square to (0.6, 0.8, 0): the line through
        // (0.1, 0.2, 0) along (−0.8, 0.6, 0); the distance to the plane grows along n.
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        let plate = Surface::plane(corners.map(|(x, y)| DVec3::new(x, y, 0.0)).to_vec());
        let plate = plate.unwrap();
        let n = DVec3::new(0.6, 0.8, 0.0);
        let line: Vec<_> = (0..30)
            .map(|i| {
                let t = -0.9 + 0.06 * f64::from(i);
                let q = DVec3::new(c.x, c.y, 0.0) + t * DVec3::new(-0.8, 0.6, 0.0);
                (q, n)
            })
            .collect();
        let mut got = from_beside(&Patch::new(&plate), (c, n), &line, &deltas);
        // A sphere of radius 2 about c cut by the plane 0.5 from c square to (1, 2, 3): a
        // circle of radius √3.75; across it on the sphere, n less its part along the radius.
        let sphere = Surface::sphere(c, 2.0).unwrap();
        let n = DVec3::new(1.0, 2.0, 3.0).normalize();
        let e1 = n.cross(DVec3::X).normalize();
        let e2 = n.cross(e1);
        let circle: Vec<_> = (0..30)
            .map(|i| {
                let phi = f64::from(i) * std::f64::consts::TAU / 30.0;
                let q = c + 0.5 * n + 3.75f64.sqrt() * (phi.cos() * e1 + phi.sin() * e2);
                let r = (q - c) / 2.0;
                (q, n - r * n.dot(r))
            })
            .collect();
        let p0 = c + 0.5 * n;
        got.extend(from_beside(&Patch::new(&sphere), (p0, n), &circle, &deltas));
        let missed = got.iter().filter(|d| d.is_none()).count();
        assert_eq!(missed, 0, "{missed} of {} given up", got.len());
        for d in got.into_iter().flatten() {
            assert!(d.abs() <= 64.0, "{d} ulps off");
        }
    }
}
