//! A cone — a straight profile revolved about an axis it is coplanar with — cut by a plane, in
//! closed form: the conic (circle, ellipse, parabola or hyperbola; rulings through the apex or
//! the apex alone when the plane passes through it), clipped to the cone's extent, its partial
//! revolution and a planar region's edges.
//!
//! The cone is `P(t, θ) = O + a·z(t) + s(t)·R(θ)r̂`, with z and s (signed distance from the
//! axis, so a profile crossing the axis gives both nappes) linear in the profile parameter t.
//! For each θ the plane meets the ruling at `t(θ) = −N(θ)/D(θ)`, both of the form
//! `p + q·(α cos θ + β sin θ)`; so every clipping angle (t = 0, t = 1, a ruling parallel to the
//! plane, a region edge — whose `s·c·u` terms cancel) is a root of a first-degree trigonometric
//! polynomial, and every sample lies on its ruling and on the plane to roundoff.

use super::analytic::line_in_region;
use super::hits::point_in_polygon;
use super::kinds::{PlaneRegion, Revolve};
use super::quadrics::trig_roots;
use crate::geom::mesh::Polyline3;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// A revolved straight profile in its meridian frame.
pub(crate) struct Cone {
    o: DVec3,
    a: DVec3,
    /// The profile's radial direction (at θ = 0).
    r: DVec3,
    /// `a × r` (θ = π/2).
    q: DVec3,
    z0: f64,
    dz: f64,
    s0: f64,
    ds: f64,
    angle: f64,
}

impl Cone {
    /// The revolution as a cone, when its profile is a straight segment coplanar with the axis,
    /// neither parallel nor perpendicular to it (those are cylinders and annuli).
    pub(crate) fn of(rev: &Revolve) -> Option<Cone> {
        let (o, a) = (rev.axis_point, rev.axis_dir);
        let (p0, p1) = (rev.profile.eval(0.0), rev.profile.eval(1.0));
        let d = p1 - p0;
        let len = d.length();
        if len.is_nan() || len <= 0.0 {
            return None;
        }
        let size = len + (p0 - o).length();
        // Straight and running one way: 65 points on the chord, in order.
        let mut last = 0.0;
        for i in 1..64 {
            let p = rev.profile.eval(i as f64 / 64.0) - p0;
            let f = p.dot(d) / (len * len);
            if (p - d * f).length() > 1e-12 * size || f < last {
                return None;
            }
            last = f;
        }
        let (w0, w1) = (p0 - o, p1 - o);
        let (z0, z1) = (w0.dot(a), w1.dot(a));
        let (m0, m1) = (w0 - a * z0, w1 - a * z1);
        let far = if m1.length() >= m0.length() { m1 } else { m0 };
        if far.length() <= 1e-12 * size {
            return None; // the profile lies on the axis
        }
        let r = far.normalize();
        // Coplanar with the axis: no component across the meridian plane.
        let q = a.cross(r);
        if m0.dot(q).abs() > 1e-12 * size || m1.dot(q).abs() > 1e-12 * size {
            return None;
        }
        let (s0, s1) = (m0.dot(r), m1.dot(r));
        if (s1 - s0).abs() <= 1e-12 * size || (z1 - z0).abs() <= 1e-12 * size {
            return None;
        }
        Some(Cone {
            o,
            a,
            r,
            q,
            z0,
            dz: z1 - z0,
            s0,
            ds: s1 - s0,
            angle: rev.angle,
        })
    }

    fn point(&self, t: f64, th: f64) -> DVec3 {
        let radial = self.r * th.cos() + self.q * th.sin();
        self.o + self.a * (self.z0 + t * self.dz) + radial * (self.s0 + t * self.ds)
    }

    fn in_span(&self, th: f64) -> bool {
        self.angle >= TAU || th <= self.angle + 1e-12
    }
}

/// The cone cut by the plane through `p` with unit normal `n`, clipped to `region` when given.
pub(crate) fn cone_plane(
    k: &Cone,
    p: DVec3,
    n: DVec3,
    region: Option<&PlaneRegion>,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let (ka, al, be) = (n.dot(k.a), n.dot(k.r), n.dot(k.q));
    let e = n.dot(k.o - p) + ka * k.z0;
    let kd = ka * k.dz;
    let c = |th: f64| al * th.cos() + be * th.sin();
    // t(θ) = −(e + s0 c) / (kd + ds c).
    let t_of = |th: f64| -(e + k.s0 * c(th)) / (kd + k.ds * c(th));
    let in_region =
        |x: DVec3| region.is_none_or(|g| point_in_polygon(x, &g.boundary, g.normal, tol).is_in());
    let ta = -k.s0 / k.ds;
    let apex = k.o + k.a * (k.z0 + ta * k.dz);
    if n.dot(apex - p).abs() <= tol {
        return through_apex(k, (ta, apex), ka, al, be, region, tol, &in_region);
    }
    let eps = 1e-12;
    let mut cuts = trig_roots(k.s0 * al, k.s0 * be, e, eps);
    let s1 = k.s0 + k.ds;
    cuts.extend(trig_roots(s1 * al, s1 * be, e + kd, eps));
    cuts.extend(trig_roots(k.ds * al, k.ds * be, kd, eps));
    if k.angle < TAU {
        cuts.extend([0.0, k.angle]);
    }
    if let Some(g) = region {
        let m = g.boundary.len();
        for i in 0..m {
            let (e0, e1) = (g.boundary[i], g.boundary[(i + 1) % m]);
            let w = g.normal.cross(e1 - e0);
            let gg = (k.o + k.a * k.z0 - e0).dot(w);
            let aw = k.a.dot(w);
            let (gm, dm) = (k.r.dot(w), k.q.dot(w));
            let lu = kd * k.s0 - e * k.ds;
            let lc = k.ds * gg - k.s0 * k.dz * aw;
            let c0 = kd * gg - e * k.dz * aw;
            for th in trig_roots(lu * gm + lc * al, lu * dm + lc * be, c0, eps) {
                let x = k.point(t_of(th), th);
                let f = (x - e0).dot(e1 - e0) / (e1 - e0).length_squared();
                if (-1e-12..=1.0 + 1e-12).contains(&f) {
                    cuts.push(th);
                }
            }
        }
    }
    let inside = |th: f64| {
        let t = t_of(th);
        k.in_span(th) && (0.0..=1.0).contains(&t) && in_region(k.point(t, th))
    };
    let pt = |th: f64| k.point(t_of(th).clamp(0.0, 1.0), th);
    let mut out = adaptive_pieces(cuts, &pt, &inside, chord_tol);
    for c in out.iter_mut() {
        if !c.closed && c.length() <= tol {
            c.points.truncate(1);
        }
    }
    out
}

/// A plane through the apex: the rulings lying in it (where the ruling is parallel to the
/// plane), clipped to the extent and the region, or the apex alone.
#[allow(clippy::too_many_arguments)]
fn through_apex(
    k: &Cone,
    (ta, apex): (f64, DVec3),
    ka: f64,
    al: f64,
    be: f64,
    region: Option<&PlaneRegion>,
    tol: f64,
    in_region: &dyn Fn(DVec3) -> bool,
) -> Vec<Polyline3> {
    let mut out = Vec::new();
    for th in trig_roots(k.ds * al, k.ds * be, ka * k.dz, 1e-12) {
        if !k.in_span(th) {
            continue;
        }
        let (q0, q1) = (k.point(0.0, th), k.point(1.0, th));
        let spans = match region {
            Some(g) => line_in_region(q0, q1 - q0, g, tol),
            None => vec![(0.0, 1.0)],
        };
        for (t0, t1) in spans {
            let (t0, t1) = (t0.max(0.0), t1.min(1.0));
            if t1 < t0 {
                continue;
            }
            let (x0, x1) = (k.point(t0, th), k.point(t1, th));
            out.push(Polyline3 {
                points: if x0.distance(x1) <= tol {
                    vec![x0]
                } else {
                    vec![x0, x1]
                },
                closed: false,
            });
        }
    }
    let eps = 1e-12;
    if out.is_empty() && (-eps..=1.0 + eps).contains(&ta) && in_region(apex) {
        out.push(Polyline3 {
            points: vec![apex],
            closed: false,
        });
    }
    out
}

/// The closed curve `pt(θ)` split at `cuts` into the pieces where `inside` holds at their
/// middle, each sampled by bisection until every chord is within `chord_tol` of the curve at its
/// middle (a conic's speed in θ varies too much for one step).
fn adaptive_pieces(
    mut cuts: Vec<f64>,
    pt: &dyn Fn(f64) -> DVec3,
    inside: &dyn Fn(f64) -> bool,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let sample = |a: f64, b: f64, closed: bool| {
        let n = ((b - a) / (PI / 16.0)).ceil().max(4.0) as usize;
        let mut pts = vec![pt(a)];
        for i in 0..n {
            let (t0, t1) = (
                a + (b - a) * i as f64 / n as f64,
                a + (b - a) * (i + 1) as f64 / n as f64,
            );
            refine(pt, (t0, pt(t0)), (t1, pt(t1)), chord_tol, 40, &mut pts);
        }
        if closed {
            pts.pop();
        }
        Polyline3 {
            points: pts,
            closed,
        }
    };
    for c in cuts.iter_mut() {
        *c = c.rem_euclid(TAU);
    }
    super::quadrics::split_turn(cuts, |t: f64| inside(t.rem_euclid(TAU)), sample)
}

/// Appends the points after `a` up to `b`, bisecting where the chord strays from the curve.
fn refine(
    pt: &dyn Fn(f64) -> DVec3,
    a: (f64, DVec3),
    b: (f64, DVec3),
    tol: f64,
    depth: u32,
    out: &mut Vec<DVec3>,
) {
    let tm = 0.5 * (a.0 + b.0);
    let m = pt(tm);
    let chord = b.1 - a.1;
    let l2 = chord.length_squared();
    let off = if l2 > 0.0 {
        let w = m - a.1;
        (w - chord * (w.dot(chord) / l2)).length()
    } else {
        m.distance(a.1)
    };
    if off > tol && depth > 0 {
        refine(pt, a, (tm, m), tol, depth - 1, out);
        refine(pt, (tm, m), b, tol, depth - 1, out);
    } else {
        out.push(b.1);
    }
}
