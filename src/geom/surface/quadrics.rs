//! Closed-form intersections involving a cylinder: an oblique plane region (an ellipse, clipped
//! to the region and the height), another cylinder with a parallel axis (rulings, one where they
//! touch), two cylinders touching from outside (a point), and a sphere (circles when its centre
//! is on the axis, a point where it touches the cylinder from inside or outside).
//!
//! Every curve is parameterised by the angle θ about a cylinder's axis, in which the plane's
//! and the other surfaces' equations are trigonometric polynomials of degree one, so the
//! clipping angles are closed-form roots and every sample lies on both surfaces to roundoff.

use super::hits::{point_in_polygon, ArcData};
use super::kinds::{Cylinder, PlaneRegion, Sphere};
use crate::geom::mesh::Polyline3;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Roots θ of `a cos θ + b sin θ + c = 0` in [0, 2π) (one for a double root within `eps`).
pub(crate) fn trig_roots(a: f64, b: f64, c: f64, eps: f64) -> Vec<f64> {
    let r = a.hypot(b);
    if r == 0.0 {
        return Vec::new();
    }
    let phi = b.atan2(a);
    let cv = -c / r;
    if (cv.abs() - 1.0).abs() <= eps {
        return vec![(phi + if cv < 0.0 { PI } else { 0.0 }).rem_euclid(TAU)];
    }
    if cv.abs() > 1.0 {
        return Vec::new();
    }
    let d = cv.acos();
    vec![(phi + d).rem_euclid(TAU), (phi - d).rem_euclid(TAU)]
}

/// A closed curve `pt(θ)`, θ in [0, 2π), split at `cuts` into the pieces where `inside` holds at
/// their middle; each sampled at most `step` apart in θ. No cut: the whole loop or nothing.
fn pieces(
    cuts: Vec<f64>,
    step: f64,
    pt: impl Fn(f64) -> DVec3,
    inside: impl Fn(f64) -> bool,
) -> Vec<Polyline3> {
    let sample = |a: f64, b: f64, closed: bool| {
        let n = ((b - a) / step).ceil().max(1.0) as usize;
        let last = if closed { n } else { n + 1 };
        Polyline3 {
            points: (0..last)
                .map(|i| pt(a + (b - a) * i as f64 / n as f64))
                .collect(),
            closed,
        }
    };
    split_turn(cuts, inside, sample)
}

/// A full turn θ in [0, 2π) split at the angles `cuts` into the pieces where `inside` holds at
/// their middle, each made by `sample(from, to, closed)`; with no cut, the whole closed turn or
/// nothing. The one rule for every circle-like curve clipped to a region (quadrics, analytic
/// circles, conics), so they cannot differ on a cut through a corner.
pub(super) fn split_turn<T>(
    mut cuts: Vec<f64>,
    inside: impl Fn(f64) -> bool,
    sample: impl Fn(f64, f64, bool) -> T,
) -> Vec<T> {
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|a, b| (*a - *b).abs() <= 1e-15);
    if cuts.is_empty() {
        return if inside(0.0) {
            vec![sample(0.0, TAU, true)]
        } else {
            Vec::new()
        };
    }
    let mut out = Vec::new();
    for i in 0..cuts.len() {
        let a = cuts[i];
        let b = cuts.get(i + 1).copied().unwrap_or(cuts[0] + TAU);
        if b > a && inside(0.5 * (a + b)) {
            out.push(sample(a, b, false));
        }
    }
    out
}

/// The angular step for samples of an ellipse with semi-major axis at most `rho`'s circle
/// (`rho` bounds the radius of curvature) within `chord_tol`.
fn angle_step(rho: f64, chord_tol: f64) -> f64 {
    (2.0 * (1.0 - chord_tol / rho).clamp(-1.0, 1.0).acos()).clamp(1e-5, PI / 8.0)
}

/// An oblique plane region cuts the cylinder in an ellipse: at angle θ the ruling's height is
/// `s(θ) = −(q + r(m cos θ + n sin θ)) / k`. Clipped where s leaves [0, h] and where the ellipse
/// crosses the region's edges (`(P(θ) − e0)·w = 0` for the edge's in-plane normal w).
pub(crate) fn cylinder_plane_oblique(
    c: &Cylinder,
    p: &PlaneRegion,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let nn = p.normal;
    let (x, y) = c.frame();
    let k = nn.dot(c.axis);
    let q = nn.dot(c.base - p.boundary[0]);
    let (m, n) = (nn.dot(x), nn.dot(y));
    let r = c.radius;
    let s = |t: f64| -(q + r * (m * t.cos() + n * t.sin())) / k;
    let pt = |t: f64| c.base + r * (t.cos() * x + t.sin() * y) + c.axis * s(t);
    let eps = 1e-12;
    let mut cuts = Vec::new();
    for h in [0.0, c.height] {
        cuts.extend(trig_roots(r * m, r * n, q + h * k, eps));
    }
    // P(θ) − e0 = (base − e0 − axis q/k) + r cos θ (x − axis m/k) + r sin θ (y − axis n/k).
    let (ex, ey) = (x - c.axis * (m / k), y - c.axis * (n / k));
    let nb = p.boundary.len();
    for i in 0..nb {
        let (e0, e1) = (p.boundary[i], p.boundary[(i + 1) % nb]);
        let w = nn.cross(e1 - e0);
        let c0 = (c.base - e0 - c.axis * (q / k)).dot(w);
        for t in trig_roots(r * ex.dot(w), r * ey.dot(w), c0, eps) {
            let f = (pt(t) - e0).dot(e1 - e0) / (e1 - e0).length_squared();
            if (-1e-12..=1.0 + 1e-12).contains(&f) {
                cuts.push(t);
            }
        }
    }
    let inside = |t: f64| {
        let h = s(t);
        (0.0..=c.height).contains(&h) && point_in_polygon(pt(t), &p.boundary, nn, tol).is_in()
    };
    // The ellipse's largest radius of curvature is a²/b = r/k².
    let step = angle_step(r / (k * k), chord_tol);
    let mut out = pieces(cuts, step, pt, inside);
    // A piece shorter than the tolerance (the ellipse grazing a corner) is a point.
    for c in out.iter_mut() {
        if !c.closed && c.length() <= tol {
            c.points.truncate(1);
        }
    }
    out
}

/// Rulings of a cylinder at the angles `thetas`, each clipped to the height range `[lo, hi]`
/// along the axis (measured from the base).
fn rulings(c: &Cylinder, thetas: &[f64], lo: f64, hi: f64, tol: f64) -> Vec<Polyline3> {
    let (x, y) = c.frame();
    let (lo, hi) = (lo.max(0.0), hi.min(c.height));
    if hi < lo - tol {
        return Vec::new();
    }
    thetas
        .iter()
        .map(|t| {
            let foot = c.base + c.radius * (t.cos() * x + t.sin() * y);
            let points = if hi - lo <= tol {
                vec![foot + c.axis * lo]
            } else {
                vec![foot + c.axis * lo, foot + c.axis * hi]
            };
            Polyline3 {
                points,
                closed: false,
            }
        })
        .collect()
}

/// Two cylinders: parallel axes meet along rulings (the base circles' crossings in a common
/// cross-section, one ruling where they touch); crossing axes at distance r1 + r2 touch at one
/// point. Other pairs: None (through the meshes). Coaxial cylinders of one radius are the same
/// surface (a region, not a curve): none.
pub(crate) fn cylinder_cylinder(a: &Cylinder, b: &Cylinder, tol: f64) -> Option<Vec<Polyline3>> {
    let cross = a.axis.cross(b.axis);
    if cross.length() <= 1e-12 {
        // b's axis in a's frame: its offset from a's axis and its height range along a's axis.
        let d = b.base - a.base;
        let off = d - a.axis * d.dot(a.axis);
        let dist = off.length();
        let sign = a.axis.dot(b.axis).signum();
        let (h0, h1) = (d.dot(a.axis), d.dot(a.axis) + sign * b.height);
        let (lo, hi) = (h0.min(h1), h0.max(h1));
        if dist <= tol {
            return Some(Vec::new());
        }
        let (ra, rb) = (a.radius, b.radius);
        if dist > ra + rb + tol || dist < (ra - rb).abs() - tol {
            return Some(Vec::new());
        }
        let (x, y) = a.frame();
        let phi = off.dot(y).atan2(off.dot(x));
        // The angle at a's axis between the offset and the crossing: law of cosines.
        let touch = (dist - (ra + rb)).abs() <= tol || (dist - (ra - rb).abs()).abs() <= tol;
        let thetas = if touch {
            // Inside touching with the larger cylinder being b: the contact is away from b.
            let away = rb > ra && (dist - (rb - ra)).abs() <= tol;
            vec![if away { phi + PI } else { phi }]
        } else {
            let cg = ((ra * ra + dist * dist - rb * rb) / (2.0 * ra * dist)).clamp(-1.0, 1.0);
            let g = cg.acos();
            vec![phi - g, phi + g]
        };
        return Some(rulings(a, &thetas, lo, hi, tol));
    }
    // Crossing axes: the common perpendicular between the axis lines.
    let u = cross.normalize();
    let w = b.base - a.base;
    let dist = w.dot(u);
    if (dist.abs() - (a.radius + b.radius)).abs() > tol {
        return None;
    }
    // Feet of the common perpendicular: a.base + s·a.axis and b.base + t·b.axis.
    let (d1, d2) = (a.axis, b.axis);
    let (e, f, g) = (d1.dot(d2), d1.dot(w), d2.dot(w));
    let den = 1.0 - e * e;
    let sa = (f - e * g) / den;
    let tb = (e * f - g) / den;
    let inside_a = (-tol..=a.height + tol).contains(&sa);
    let inside_b = (-tol..=b.height + tol).contains(&tb);
    if !(inside_a && inside_b) {
        // The touching point is off one of the finite cylinders; nothing else meets.
        return Some(Vec::new());
    }
    let p = a.base + d1 * sa + u * (a.radius * dist.signum());
    Some(vec![Polyline3 {
        points: vec![p],
        closed: false,
    }])
}

/// A sphere and a cylinder: with the centre on the axis, circles at heights `±√(R² − r²)` from
/// it (one circle where the sphere touches the cylinder all round); with the centre off the
/// axis at distance d, a point where `d = r + R` (outside) or `d + R = r` (inside). Other
/// pairs: None (through the meshes).
pub(crate) fn sphere_cylinder(
    s: &Sphere,
    c: &Cylinder,
    tol: f64,
    chord_tol: f64,
) -> Option<Vec<Polyline3>> {
    let w = s.center - c.base;
    let hc = w.dot(c.axis);
    let off = w - c.axis * hc;
    let d = off.length();
    let (r, rs) = (c.radius, s.radius);
    let point = |p: DVec3, h: f64| {
        if (-tol..=c.height + tol).contains(&h) {
            vec![Polyline3 {
                points: vec![p],
                closed: false,
            }]
        } else {
            Vec::new()
        }
    };
    if d <= tol * 1e-3 {
        let circle = |h: f64, out: &mut Vec<Polyline3>| {
            if (-tol..=c.height + tol).contains(&h) {
                let h = h.clamp(0.0, c.height);
                let arc = ArcData::circle(c.base + c.axis * h, r, c.axis);
                let step = angle_step(r, chord_tol);
                let n = (TAU / step).ceil() as usize;
                out.push(Polyline3 {
                    points: (0..n)
                        .map(|i| arc.point(TAU * i as f64 / n as f64))
                        .collect(),
                    closed: true,
                });
            }
        };
        let mut out = Vec::new();
        if (rs - r).abs() <= tol {
            circle(hc, &mut out);
        } else if rs > r {
            let dz = (rs * rs - r * r).sqrt();
            circle(hc - dz, &mut out);
            circle(hc + dz, &mut out);
        }
        return Some(out);
    }
    let dir = off / d;
    if (d - (r + rs)).abs() <= tol || (d + rs - r).abs() <= tol {
        return Some(point(c.base + c.axis * hc + dir * r, hc));
    }
    if d > r + rs || d + rs < r {
        return Some(Vec::new());
    }
    None
}
