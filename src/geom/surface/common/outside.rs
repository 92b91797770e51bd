//! The curves found beside a common region (a closed form's, or a section's crossings and
//! contacts) that do not lie in it: the region's boundary loops already describe those.

use super::super::kinds::Surface;
use super::super::refine::Patch;
use super::seed::W_MIN;
use super::{free_form, Target, Tracer};
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

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

/// Whether `s` (as `patch`) may lie in the plane through `o` with unit normal `n` beside its
/// point `p` (a section curve's): the surface meets the plane within `tol` a quarter of the
/// narrowest region looked for ([`W_MIN`]) off `p` in one of four oblique directions, as it
/// does over a flat lying in the plane (from inside it, or from its edge towards it) and along
/// a tangent contact, and a crossing does not (it leaves the plane at its angle: 2.5e-6 of the
/// size times the angle's sine). A cheap test before the search for a region in the plane
/// ([`super::in_plane`]), which builds a tracer of its own: one projection and four points.
pub(crate) fn flat_on_plane(patch: &Patch, p: DVec3, (o, n): (DVec3, DVec3), tol: f64) -> bool {
    let uv = patch.project(p, None);
    let (du, dv) = patch.derivs(uv);
    let step = 0.25 * W_MIN * patch.scale();
    let d = |speed: f64| step / speed.max(1e-300);
    let d = DVec2::new(d(du.length()), d(dv.length()));
    // An irrational slope, as the tracer's probes: not along a grid line or a diagonal.
    let phi = 0.618_033_988_749_895;
    [(1.0, phi), (-phi, 1.0), (-1.0, -phi), (phi, -1.0)]
        .iter()
        .any(|&(x, y)| {
            let mut q = uv + DVec2::new(x, y) * d;
            patch.normalise(&mut q);
            n.dot(patch.eval(q) - o).abs() <= tol
        })
}

#[cfg(test)]
mod tests {
    use super::{flat_on_plane, Patch, Surface};
    use crate::geom::curve::Curve;
    use glam::DVec3;
    use std::sync::Arc;

    #[test]
    fn a_flat_in_the_plane_passes_and_a_crossing_does_not() {
        // A strip ruled from (-1, 1) down to a flat (0, 0)..(1, 0) and up to (2, 1) at 45°, at
        // z = 0 and 3. The plane y = 0 holds the flat: its middle and both its edges (creases,
        // the slope's side beyond) pass. The plane y = 0.5 crosses the slopes at 45°: no point
        // a probe away lies within the tolerance of it.
        let profile = |z: f64| {
            let pts = [(-1.0, 1.0), (0.0, 0.0), (1.0, 0.0), (2.0, 1.0)];
            let pts = pts.iter().map(|&(x, y)| DVec3::new(x, y, z)).collect();
            Arc::new(Curve::pline(pts, false, None).unwrap())
        };
        let s = Surface::ruled(profile(0.0), profile(3.0));
        let patch = Patch::new(&s);
        let tol = 1e-9;
        let flat = (DVec3::ZERO, DVec3::Y);
        for x in [0.0, 0.5, 1.0] {
            let p = DVec3::new(x, 0.0, 1.5);
            assert!(flat_on_plane(&patch, p, flat, tol), "flat at x = {x}");
        }
        let across = (DVec3::new(0.0, 0.5, 0.0), DVec3::Y);
        for x in [-0.5, 1.5] {
            let p = DVec3::new(x, 0.5, 1.5);
            assert!(
                !flat_on_plane(&patch, p, across, tol),
                "crossing at x = {x}"
            );
        }
    }
}
