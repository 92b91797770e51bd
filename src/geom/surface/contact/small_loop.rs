//! A loop of a plane section smaller than the seeding mesh, seeded about the extremum of the
//! height over the plane that the contact search levelled to (see [`super::plane_contacts`]).

use super::super::refine::Patch;
use crate::geom::mesh::Polyline3;
use glam::DVec2;

/// A closed seed polyline about the extremum `top` of `h`: on 16 rays in (u, v), the point where
/// h changes sign, searched out to 4·r (r: the distance to a known zero) and bisected.
pub(super) fn small_loop(
    a: &Patch,
    top: DVec2,
    r: f64,
    h: &dyn Fn(DVec2) -> f64,
) -> Option<Polyline3> {
    let sign = h(top).signum();
    let mut points = Vec::with_capacity(16);
    for k in 0..16 {
        let ang = std::f64::consts::TAU * k as f64 / 16.0;
        let dir = DVec2::new(ang.cos(), ang.sin());
        let step = 0.25 * r;
        let mut lo = 0.0;
        let hi = (1..=16).map(|j| j as f64 * step).find(|&t| {
            let inside = h(top + dir * t).signum() == sign;
            if inside {
                lo = t;
            }
            !inside
        })?;
        let (mut lo, mut hi) = (lo, hi);
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if h(top + dir * m).signum() == sign {
                lo = m;
            } else {
                hi = m;
            }
        }
        let mut uv = top + dir * (0.5 * (lo + hi));
        a.normalise(&mut uv);
        points.push(a.eval(uv));
    }
    Some(Polyline3 {
        points,
        closed: true,
    })
}
