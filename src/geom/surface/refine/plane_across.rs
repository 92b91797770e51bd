//! A plane section's point found across the curve where Newton crawls: beside a branch point
//! (a crossing running into a tangent contact) the signed distance to the plane has the
//! crossing's simple root next to the contact's double one, Newton's steps onto it stop
//! shrinking fourfold (taken for a contact's, see `newton::shrinks`), and the point stops
//! within the tolerance of the plane far off the curve (1e-5 seen at W = 3.7e-4). Along the
//! line across the curve the distance's simple root is still well conditioned as a 1-D root,
//! and bracketed it is found to its rounding — what `across::onto_crossing` does for two
//! surfaces.

use super::Patch;
use crate::geom::root::{illinois, At, Stop};
use glam::{DVec2, DVec3};

/// The crossing's point across the curve from `uv` (a point of `s` within `tol` of the plane
/// through `p0` with unit normal `n`, at `at` in space): the root of the signed distance on
/// the line through `uv` along which it grows fastest in space, bracketed from Newton's 1-D
/// step (or past it by twice the secant's estimate of what is left) and solved by the
/// Illinois method (Newton's step itself where it lands within the distance's rounding). None
/// where the point is already as near as the distance's rounding tells,
/// its Newton step is within 1e-3·`tol`, the step does not cut the distance eightfold (a
/// contact's even root), no sign change lies within `reach`, or the line leaves `s`.
pub(super) fn onto_plane_crossing(
    s: &Patch,
    (uv, at): (DVec2, DVec3),
    (p0, n): (DVec3, DVec3),
    tol: f64,
    reach: f64,
) -> Option<DVec2> {
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
    let (h1, q1) = dist(1.0)?;
    // Newton's step landed on the root to the distance's rounding (the point was off only by
    // Newton's crawl, 3.8e-8 seen at W = −4.5e-3): nothing left to bracket, and no sign change
    // to find past it.
    if h1.abs() <= 8.0 * noise {
        return Some(q1);
    }
    let (lo, hi) = if h1.signum() != g0.signum() {
        (
            At {
                t: 0.0,
                f: g0,
                payload: uv,
            },
            At {
                t: 1.0,
                f: h1,
                payload: q1,
            },
        )
    } else if 8.0 * h1.abs() > g0.abs() {
        return None;
    } else {
        let beyond = 1.0 + 2.0 * h1 / (g0 - h1);
        if beyond.is_nan() || beyond * len > reach {
            return None;
        }
        let (h2, q2) = dist(beyond)?;
        if h2.signum() == h1.signum() {
            return None;
        }
        (
            At {
                t: 1.0,
                f: h1,
                payload: q1,
            },
            At {
                t: beyond,
                f: h2,
                payload: q2,
            },
        )
    };
    let root = illinois(dist, [lo, hi], Stop::Width(1e-3 * tol / len))?;
    (root.f.abs() <= tol).then_some(root.payload)
}
