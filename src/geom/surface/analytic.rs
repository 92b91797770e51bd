//! Closed-form intersections of the analytic pairs: sphere/sphere and sphere/plane give a circle
//! (or a tangent point), plane/plane a line, each clipped to the planar regions involved; the
//! pairs with a cylinder are in [`super::quadrics`], coaxial surfaces of revolution in
//! [`super::coaxial`].
//! Curves are sampled within the chord tolerance; their points lie on both surfaces to
//! roundoff.

use super::hits::{point_in_polygon, ArcData};
use super::kinds::{Cylinder, PlaneRegion, Sphere, Surface};
use crate::geom::frame::arbitrary_axis;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// The intersection in closed form when the pair has one (None: use the meshes).
pub(crate) fn analytic_intersect(
    a: &Surface,
    b: &Surface,
    tol: f64,
    chord_tol: f64,
) -> Option<Vec<Polyline3>> {
    match (a, b) {
        (Surface::Sphere(s1), Surface::Sphere(s2)) => Some(sphere_sphere(s1, s2, tol, chord_tol)),
        (Surface::Sphere(s), Surface::Plane(p)) | (Surface::Plane(p), Surface::Sphere(s)) => {
            Some(sphere_plane(s, p, tol, chord_tol))
        }
        (Surface::Plane(p), Surface::Plane(q)) => Some(plane_plane(p, q, tol)),
        (Surface::Cylinder(c), Surface::Plane(p)) | (Surface::Plane(p), Surface::Cylinder(c)) => {
            Some(
                cylinder_plane_parallel(c, p, tol).unwrap_or_else(|| {
                    super::quadrics::cylinder_plane_oblique(c, p, tol, chord_tol)
                }),
            )
        }
        (Surface::Cylinder(c), Surface::Cylinder(d)) => {
            super::quadrics::cylinder_cylinder(c, d, tol)
        }
        (Surface::Sphere(s), Surface::Cylinder(c)) | (Surface::Cylinder(c), Surface::Sphere(s)) => {
            super::quadrics::sphere_cylinder(s, c, tol, chord_tol)
        }
        (Surface::Revolve(r), Surface::Plane(p)) | (Surface::Plane(p), Surface::Revolve(r)) => {
            match super::cone::Cone::of(r) {
                Some(k) => Some(super::cone::cone_plane(
                    &k,
                    p.boundary[0],
                    p.normal,
                    Some(p),
                    tol,
                    chord_tol,
                )),
                None => super::coaxial::coaxial_intersect(a, b, tol, chord_tol),
            }
        }
        _ => super::coaxial::coaxial_intersect(a, b, tol, chord_tol),
    }
}

/// A circle (center, radius, normal) clipped to `region` (None: the whole circle), sampled.
fn circle_pieces(
    c: DVec3,
    r: f64,
    n: DVec3,
    region: Option<&PlaneRegion>,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let arc = ArcData::circle(c, r, n);
    if r <= tol {
        let inside = region.is_none_or(|p| point_in_polygon(c, &p.boundary, p.normal, tol).is_in());
        return if inside {
            vec![Polyline3 {
                points: vec![c],
                closed: false,
            }]
        } else {
            Vec::new()
        };
    }
    // Angles where the circle crosses the region's edges split it into pieces wholly in or out.
    let (x, y) = arbitrary_axis(n);
    let mut cuts: Vec<f64> = Vec::new();
    if let Some(p) = region {
        let m = p.boundary.len();
        for i in 0..m {
            let (e0, e1) = (p.boundary[i] - c, p.boundary[(i + 1) % m] - c);
            let (a, b) = (
                DVec2::new(e0.dot(x), e0.dot(y)),
                DVec2::new(e1.dot(x), e1.dot(y)),
            );
            let d = b - a;
            let (qa, qb, qc) = (d.dot(d), a.dot(d), a.dot(a) - r * r);
            let disc = qb * qb - qa * qc;
            if qa == 0.0 || disc < 0.0 {
                continue;
            }
            for t in [(-qb - disc.sqrt()) / qa, (-qb + disc.sqrt()) / qa] {
                if (0.0..=1.0).contains(&t) {
                    let q = a + d * t;
                    cuts.push(q.y.atan2(q.x).rem_euclid(TAU));
                }
            }
        }
    }
    let step = (2.0 * (1.0 - chord_tol / r).clamp(-1.0, 1.0).acos()).clamp(1e-4, TAU / 16.0);
    let sample = |t0: f64, t1: f64, closed: bool| {
        let k = ((t1 - t0) / step).ceil().max(1.0) as usize;
        let last = if closed { k } else { k + 1 };
        Polyline3 {
            points: (0..last)
                .map(|i| arc.point(t0 + (t1 - t0) * i as f64 / k as f64))
                .collect(),
            closed,
        }
    };
    let inside = |t: f64| {
        region.is_none_or(|p| point_in_polygon(arc.point(t), &p.boundary, p.normal, tol).is_in())
    };
    super::quadrics::split_turn(cuts, inside, sample)
}

fn sphere_sphere(a: &Sphere, b: &Sphere, tol: f64, chord_tol: f64) -> Vec<Polyline3> {
    let d = b.center - a.center;
    let dist = d.length();
    if dist <= tol {
        return Vec::new(); // concentric: the same sphere or none (a region, not a curve)
    }
    let n = d / dist;
    // Distance from a's centre to the radical plane.
    let h = (dist * dist + a.radius * a.radius - b.radius * b.radius) / (2.0 * dist);
    let r2 = a.radius * a.radius - h * h;
    let touching = (dist - (a.radius + b.radius)).abs() <= tol
        || (dist - (a.radius - b.radius).abs()).abs() <= tol;
    if touching {
        return vec![Polyline3 {
            points: vec![a.center + n * (a.radius * h.signum())],
            closed: false,
        }];
    }
    if r2 < 0.0 {
        return Vec::new();
    }
    circle_pieces(a.center + n * h, r2.sqrt(), n, None, tol, chord_tol)
}

fn sphere_plane(s: &Sphere, p: &PlaneRegion, tol: f64, chord_tol: f64) -> Vec<Polyline3> {
    let n = p.normal;
    let h = n.dot(s.center - p.boundary[0]);
    let c = s.center - n * h;
    if (h.abs() - s.radius).abs() <= tol {
        return circle_pieces(c, 0.0, n, Some(p), tol, chord_tol);
    }
    let r2 = s.radius * s.radius - h * h;
    if r2 < 0.0 {
        return Vec::new();
    }
    circle_pieces(c, r2.sqrt(), n, Some(p), tol, chord_tol)
}

/// The parameter intervals of the line `o + t·d` inside a planar region (the line lies in its
/// plane).
pub(crate) fn line_in_region(o: DVec3, d: DVec3, p: &PlaneRegion, tol: f64) -> Vec<(f64, f64)> {
    let (x, y) = arbitrary_axis(p.normal);
    let to2 = |q: DVec3| DVec2::new(q.dot(x), q.dot(y));
    let (o2, d2) = (to2(o), DVec2::new(d.dot(x), d.dot(y)));
    let m = p.boundary.len();
    let mut ts = Vec::new();
    for i in 0..m {
        let (a, b) = (to2(p.boundary[i]), to2(p.boundary[(i + 1) % m]));
        let e = b - a;
        let den = d2.perp_dot(e);
        if den == 0.0 {
            continue;
        }
        let t = (a - o2).perp_dot(e) / den;
        let s = (a - o2).perp_dot(d2) / den;
        if (0.0..=1.0).contains(&s) {
            ts.push(t);
        }
    }
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    let mut out: Vec<(f64, f64)> = Vec::new();
    for w in ts.windows(2) {
        let mid = o + d * (0.5 * (w[0] + w[1]));
        if point_in_polygon(mid, &p.boundary, p.normal, tol).is_in() {
            match out.last_mut() {
                Some(last) if last.1 == w[0] => last.1 = w[1],
                _ => out.push((w[0], w[1])),
            }
        }
    }
    out
}

fn plane_plane(p: &PlaneRegion, q: &PlaneRegion, tol: f64) -> Vec<Polyline3> {
    let d = p.normal.cross(q.normal);
    if d.length() <= 1e-12 {
        // Parallel: apart (none), or coplanar: their common region's boundary.
        return super::overlap::coplanar_overlap(p, q, tol).unwrap_or_default();
    }
    // A point on both planes: the one nearest p's first vertex.
    let (hp, hq) = (p.normal.dot(p.boundary[0]), q.normal.dot(q.boundary[0]));
    let o = (d.cross(q.normal) * hp + p.normal.cross(d) * hq) / d.length_squared();
    let (ia, ib) = (line_in_region(o, d, p, tol), line_in_region(o, d, q, tol));
    let mut out = Vec::new();
    for &(a0, a1) in &ia {
        for &(b0, b1) in &ib {
            let (t0, t1) = (a0.max(b0), a1.min(b1));
            if t1 >= t0 {
                let points = if (t1 - t0) * d.length() <= tol {
                    vec![o + d * t0]
                } else {
                    vec![o + d * t0, o + d * t1]
                };
                out.push(Polyline3 {
                    points,
                    closed: false,
                });
            }
        }
    }
    out
}

/// A plane parallel to a cylinder's axis cuts it along rulings (one where it touches): each
/// clipped to the region. Other planes: None (an ellipse, [`super::quadrics`]).
fn cylinder_plane_parallel(c: &Cylinder, p: &PlaneRegion, tol: f64) -> Option<Vec<Polyline3>> {
    let n = p.normal;
    if n.dot(c.axis).abs() > 1e-12 {
        return None;
    }
    let base = ArcData::circle(c.base, c.radius, c.axis);
    let mut out = Vec::new();
    for q in super::hits::circle_plane(&base, p.boundary[0], n, tol) {
        // The ruling through q lies in the plane: clip it to the region and to the height.
        for (t0, t1) in line_in_region(q, c.axis, p, tol) {
            let (t0, t1) = (t0.max(0.0), t1.min(c.height));
            if t1 > t0 + tol {
                out.push(Polyline3 {
                    points: vec![q + c.axis * t0, q + c.axis * t1],
                    closed: false,
                });
            } else if t1 >= t0 {
                out.push(Polyline3 {
                    points: vec![q + c.axis * t0],
                    closed: false,
                });
            }
        }
    }
    Some(out)
}
