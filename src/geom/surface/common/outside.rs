//! The curves found beside a common region (a closed form's, or a section's crossings and
//! contacts) that do not lie in it: the region's boundary loops already describe those.

use super::super::kinds::Surface;
use super::{free_form, Target, Tracer};
use crate::geom::mesh::Polyline3;
use glam::DVec3;

/// The curves (of a closed form, found beside a common region) that do not lie in the common
/// region of `a` and `b`: a curve whose middle point lies on both surfaces with the surfaces
/// coinciding around it belongs to the region, whose boundary loops already describe it.
pub(crate) fn outside_common(
    a: &Surface,
    b: &Surface,
    curves: Vec<Polyline3>,
    tol: f64,
) -> Vec<Polyline3> {
    let (s, other) = if free_form(a) { (a, b) } else { (b, a) };
    outside(s, &Target::of(other), curves, tol)
}

/// [`outside_common`] for a section: the curves not lying in the region of `s` in the plane
/// through `p` with unit normal `n`.
pub(crate) fn outside_plane_region(
    s: &Surface,
    (p, n): (DVec3, DVec3),
    curves: Vec<Polyline3>,
    tol: f64,
) -> Vec<Polyline3> {
    outside(s, &Target::Plane(p, n), curves, tol)
}

fn outside(s: &Surface, t: &Target, curves: Vec<Polyline3>, tol: f64) -> Vec<Polyline3> {
    let tr = Tracer::new(s, t, tol, tol);
    curves
        .into_iter()
        .filter(|c| {
            let Some(&p) = c.points.get(c.points.len() / 2) else {
                return false;
            };
            let uv = tr.patch.project(p, None);
            !(tr.patch.eval(uv).distance(p) <= tol && tr.in_region_by(uv, tr.probe(uv)))
        })
        .collect()
}
