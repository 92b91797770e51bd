//! What a traced surface's points are tested against (the other surface, or a section's
//! plane), and the quick look's samples that tell whether and at what level they coincide.

use super::super::hits::point_in_polygon;
use super::super::kinds::{Cylinder, PlaneRegion, Sphere, Surface};
use super::super::refine::Patch;
use super::K;
use glam::{DVec2, DVec3};
use std::cell::Cell;

/// What a point is tested against: a surface, or the plane of a section.
pub(super) enum Target<'a> {
    Sphere(Sphere),
    Cylinder(Cylinder),
    Region(&'a PlaneRegion),
    Plane(DVec3, DVec3),
    Patch(Patch<'a>, Cell<Option<DVec2>>),
}

impl<'a> Target<'a> {
    pub(super) fn of(s: &'a Surface) -> Target<'a> {
        match s {
            Surface::Sphere(sp) => Target::Sphere(*sp),
            Surface::Cylinder(c) => Target::Cylinder(*c),
            Surface::Plane(p) => Target::Region(p),
            _ => Target::Patch(Patch::new(s), Cell::new(None)),
        }
    }

    /// Whether `p` lies on the target within `tol` (inside its extent).
    pub(super) fn on(&self, p: DVec3, tol: f64) -> bool {
        self.apart(p, tol) <= tol
    }

    /// How far `p` lies from the target: within `tol` exactly where it lies on the target
    /// ([`Self::on`]); infinite outside the target's extent (by `tol`), where no distance
    /// grows smoothly to the threshold ([`super::threshold`] then bisects).
    pub(super) fn apart(&self, p: DVec3, tol: f64) -> f64 {
        match self {
            Target::Sphere(s) => (p.distance(s.center) - s.radius).abs(),
            Target::Cylinder(c) => {
                let h = (p - c.base).dot(c.axis);
                let radial = (p - c.base - c.axis * h).length();
                let inside = h >= -tol && h <= c.height + tol;
                if inside {
                    (radial - c.radius).abs()
                } else {
                    f64::INFINITY
                }
            }
            Target::Region(r) => {
                let d = r.normal.dot(p - r.boundary[0]).abs();
                // Off the plane already: the polygon test is not needed.
                if d > tol || point_in_polygon(p, &r.boundary, r.normal, tol).is_in() {
                    d
                } else {
                    f64::INFINITY
                }
            }
            Target::Plane(o, n) => n.dot(p - *o).abs(),
            Target::Patch(patch, hint) => {
                let (uv, foot) = patch.project_warm(p, hint.get());
                let d = foot.distance(p);
                if d <= tol {
                    hint.set(Some(uv));
                }
                d
            }
        }
    }
}

/// The quick look's sample points of a surface (inside the polygon for a planar region).
pub(super) fn samples(s: &Surface) -> Vec<DVec3> {
    use super::super::ParamSurface;
    let mut out = Vec::with_capacity(K * K);
    for j in 0..K {
        for i in 0..K {
            let (u, v) = ((i as f64 + 0.5) / K as f64, (j as f64 + 0.5) / K as f64);
            let p = s.eval(u, v);
            if let Surface::Plane(r) = s {
                if !point_in_polygon(p, &r.boundary, r.normal, 0.0).is_in() {
                    continue;
                }
            }
            out.push(p);
        }
    }
    out
}

pub(super) fn sample_count(s: &Surface) -> usize {
    samples(s).len().max(1)
}

/// Those of `s`'s samples that lie on `t`, and the least and most gaps among them (the least
/// is the common region's level: 0 where the surfaces coincide, 0.3 of the tolerance where
/// held that far apart; a region may sit at a higher level, up to the most; infinite when none
/// lies on `t`).
pub(super) fn on_samples(s: &Surface, t: &Target, tol: f64) -> (Vec<DVec3>, f64, f64) {
    let (mut least, mut most) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut hits = Vec::new();
    for p in samples(s) {
        if t.on(p, tol) {
            hits.push(p);
            // From where `on` left the projection; at most the tolerance, as `on` found.
            let g = t.gap(p, tol).unwrap_or(tol).min(tol);
            (least, most) = (least.min(g), most.max(g));
        }
    }
    (hits, least, most)
}
