//! Curve/surface hits in closed form — paper 002's three basic functions (line/plane,
//! circle-or-arc/plane, line/cylinder) with their early rejections and the point-in-facet test
//! that handles vertices and edges — and any sampled curve against a mesh through its BVH.

use super::kinds::{Cylinder, PlaneRegion};
use super::sampled::sample_curve;
use crate::geom::frame::arbitrary_axis;
use crate::geom::mesh::{Aabb, Mesh, Polyline3};
use crate::geom::ParamCurve;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Where a point lies relative to a facet or polygon.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FacetLocation {
    Inside,
    /// On edge `i` (from vertex `i` to vertex `i + 1`), between its ends.
    OnEdge(usize),
    /// On vertex `i`.
    OnVertex(usize),
    Outside,
}

impl FacetLocation {
    /// Inside or on the boundary.
    pub fn is_in(self) -> bool {
        self != FacetLocation::Outside
    }
}

/// Paper 002's point-in-convex-facet test: with `v_i = p_i − p`, `p` is inside iff every
/// `(v_i × v_{i+1})·n` has the same sign. The degenerate cases are decided explicitly (within
/// `tol`, a distance): `|v_i| ≤ tol` → on vertex i; a zero cross product means `p` is on the line
/// of edge i — on the edge when it lies between the ends (`v_i·v_{i+1} ≤ 0`), else on the edge's
/// extension, which is outside.
pub fn point_in_convex_facet(p: DVec3, facet: &[DVec3], normal: DVec3, tol: f64) -> FacetLocation {
    let n = facet.len();
    if n < 3 {
        return FacetLocation::Outside;
    }
    let nn = normal.normalize_or_zero();
    for (i, q) in facet.iter().enumerate() {
        if q.distance(p) <= tol {
            return FacetLocation::OnVertex(i);
        }
    }
    let mut sign = 0.0f64;
    let mut on_edge = None;
    for i in 0..n {
        let a = facet[i] - p;
        let b = facet[(i + 1) % n] - p;
        let len = (facet[(i + 1) % n] - facet[i]).length();
        let c = a.cross(b).dot(nn);
        // |a × b| / |edge| is the distance from p to the edge's line.
        if len > 0.0 && c.abs() / len <= tol {
            if a.dot(b) <= 0.0 {
                on_edge = Some(i);
                continue;
            }
            return FacetLocation::Outside;
        }
        if sign == 0.0 {
            sign = c.signum();
        } else if c.signum() != sign {
            return FacetLocation::Outside;
        }
    }
    match on_edge {
        Some(i) => FacetLocation::OnEdge(i),
        None => FacetLocation::Inside,
    }
}

/// Point in a simple (possibly non-convex) planar polygon: vertices and edges first (within
/// `tol`), then the even-odd crossing rule in the plane's arbitrary-axis frame.
pub fn point_in_polygon(p: DVec3, polygon: &[DVec3], normal: DVec3, tol: f64) -> FacetLocation {
    let n = polygon.len();
    if n < 3 {
        return FacetLocation::Outside;
    }
    for (i, q) in polygon.iter().enumerate() {
        if q.distance(p) <= tol {
            return FacetLocation::OnVertex(i);
        }
    }
    for i in 0..n {
        if super::sampled::dist_to_segment(p, polygon[i], polygon[(i + 1) % n]) <= tol {
            return FacetLocation::OnEdge(i);
        }
    }
    let (x, y) = arbitrary_axis(normal);
    let (px, py) = (p.dot(x), p.dot(y));
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        let (ax, ay, bx, by) = (a.dot(x), a.dot(y), b.dot(x), b.dot(y));
        // Half-open rule on y so a ray through a vertex counts it once.
        if (ay > py) != (by > py) {
            let xi = ax + (py - ay) * (bx - ax) / (by - ay);
            if px < xi {
                inside = !inside;
            }
        }
    }
    if inside {
        FacetLocation::Inside
    } else {
        FacetLocation::Outside
    }
}

/// Line segment / plane (paper 002): both ends strictly on one side → none (the early
/// rejection); else `t = −(A·xs + B·ys + C·zs + D) / (A·vx + B·vy + C·vz)`. A segment lying in
/// the plane or parallel to it gives none. Returns `(t, point)` with t in [0, 1].
pub fn segment_plane(
    p0: DVec3,
    p1: DVec3,
    plane_point: DVec3,
    plane_normal: DVec3,
) -> Option<(f64, DVec3)> {
    let d0 = plane_normal.dot(p0 - plane_point);
    let d1 = plane_normal.dot(p1 - plane_point);
    if (d0 > 0.0 && d1 > 0.0) || (d0 < 0.0 && d1 < 0.0) {
        return None;
    }
    let den = d0 - d1;
    if den == 0.0 {
        return None;
    }
    let t = (d0 / den).clamp(0.0, 1.0);
    let p = if t == 0.0 {
        p0
    } else if t == 1.0 {
        p1
    } else {
        p0 + (p1 - p0) * t
    };
    Some((t, p))
}

impl PlaneRegion {
    /// Segment / bounded planar region: [`segment_plane`] then [`point_in_polygon`].
    pub fn segment_hit(&self, p0: DVec3, p1: DVec3, tol: f64) -> Option<(f64, DVec3)> {
        let (t, p) = segment_plane(p0, p1, self.boundary[0], self.normal)?;
        point_in_polygon(p, &self.boundary, self.normal, tol)
            .is_in()
            .then_some((t, p))
    }
}

/// A circle or arc as plain data: centre, radius, normal, and the angles (radians, CCW about
/// the normal from the X axis of `frame::arbitrary_axis(normal)`, as DXF). `end_angle −
/// start_angle ≥ 2π` (or a full circle's 0..2π) means the whole circle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcData {
    pub center: DVec3,
    pub radius: f64,
    pub normal: DVec3,
    pub start_angle: f64,
    pub end_angle: f64,
}

impl ArcData {
    /// A full circle.
    pub fn circle(center: DVec3, radius: f64, normal: DVec3) -> ArcData {
        ArcData {
            center,
            radius,
            normal,
            start_angle: 0.0,
            end_angle: TAU,
        }
    }

    /// The angle swept, in [0, 2π]: end − start reduced to a turn (an arc may run across
    /// angle 0), 2π for a whole circle.
    pub(crate) fn sweep(&self) -> f64 {
        let s = self.end_angle - self.start_angle;
        if s >= TAU {
            TAU
        } else {
            s.rem_euclid(TAU)
        }
    }

    /// The point at angle `theta`.
    pub fn point(&self, theta: f64) -> DVec3 {
        let (x, y) = arbitrary_axis(self.normal);
        self.center + self.radius * (theta.cos() * x + theta.sin() * y)
    }

    /// Whether `theta` is inside the arc's span (within `eps` radians).
    pub fn contains_angle(&self, theta: f64, eps: f64) -> bool {
        let sw = self.sweep();
        if sw >= TAU {
            return true;
        }
        let d = (theta - self.start_angle).rem_euclid(TAU);
        d <= sw + eps || d >= TAU - eps
    }
}

/// Circle or arc / plane (paper 002). In the circle's frame the plane equation becomes
/// `m·r·cosθ + n·r·sinθ + q = 0` (m = N·X, n = N·Y, q = N·(c − p)). Parallel planes (m = n = 0)
/// give none (also when the circle lies in the plane); the centre farther than r from the plane
/// gives none (the early rejection); else `cos(θ − φ) = −q / (r·√(m² + n²))`, φ = atan2(n, m),
/// one root when tangent (within `tol` as a distance), two otherwise; kept when inside the
/// arc's span. Returned in increasing angle from the arc's start.
pub fn circle_plane(
    arc: &ArcData,
    plane_point: DVec3,
    plane_normal: DVec3,
    tol: f64,
) -> Vec<DVec3> {
    let nn = plane_normal.normalize_or_zero();
    if nn == DVec3::ZERO || arc.radius.is_nan() || arc.radius <= 0.0 {
        return Vec::new();
    }
    let (x, y) = arbitrary_axis(arc.normal);
    let (m, n) = (nn.dot(x), nn.dot(y));
    let q = nn.dot(arc.center - plane_point);
    let rr = (m * m + n * n).sqrt();
    if rr * arc.radius <= tol {
        return Vec::new();
    }
    // Distance from the centre to the plane's trace line in the circle's plane: |q| / R.
    let dist = q.abs() / rr;
    if dist > arc.radius + tol / rr {
        return Vec::new();
    }
    let phi = n.atan2(m);
    let mut thetas = Vec::new();
    if (dist - arc.radius).abs() * rr <= tol {
        thetas.push(if q > 0.0 { phi + PI } else { phi });
    } else {
        let a = (-q / (arc.radius * rr)).clamp(-1.0, 1.0).acos();
        thetas.push(phi + a);
        thetas.push(phi - a);
    }
    let eps = tol / arc.radius;
    let mut out: Vec<(f64, DVec3)> = thetas
        .into_iter()
        .filter(|&t| arc.contains_angle(t, eps))
        .map(|t| ((t - arc.start_angle).rem_euclid(TAU), arc.point(t)))
        .collect();
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out.into_iter().map(|(_, p)| p).collect()
}

/// A line/cylinder hit: segment parameter and point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderHit {
    pub t: f64,
    pub point: DVec3,
    /// True for a tangent (grazing) hit.
    pub tangent: bool,
}

/// Line segment `p0 → p1` / finite cylinder (paper 002, corrected):
/// `|p − c|² − (n·(p − c))² − r² = 0`, `0 ≤ n·(p − c) ≤ h`; with `p = s + v·t`,
/// `a t² + 2 b t + c = 0`, `a = v·v − (n·v)²`, `b = v·(s − c) − (n·v)(n·(s − c))`,
/// `c = |s − c|² − (n·(s − c))² − r²`. Early rejections: both ends beyond the same end cap;
/// the line's distance from the axis above r. Tangency: that distance within `tol` of r → one
/// root. A segment along the surface (parallel to the axis at distance r) gives the ends of
/// the part inside the height range. Sorted by t.
pub fn segment_cylinder(p0: DVec3, p1: DVec3, cyl: &Cylinder, tol: f64) -> Vec<CylinderHit> {
    let n = cyl.axis;
    let h0 = n.dot(p0 - cyl.base);
    let h1 = n.dot(p1 - cyl.base);
    if (h0 < -tol && h1 < -tol) || (h0 > cyl.height + tol && h1 > cyl.height + tol) {
        return Vec::new();
    }
    let v = p1 - p0;
    let w = p0 - cyl.base;
    let nv = n.dot(v);
    let nw = n.dot(w);
    let a = v.dot(v) - nv * nv;
    let b = v.dot(w) - nv * nw;
    let c = w.dot(w) - nw * nw - cyl.radius * cyl.radius;
    let in_height = |t: f64| {
        let h = h0 + (h1 - h0) * t;
        h >= -tol && h <= cyl.height + tol
    };
    let at = |t: f64, tangent: bool| CylinderHit {
        t,
        point: p0 + v * t,
        tangent,
    };
    let vv = v.dot(v);
    if a <= 1e-24 * vv.max(1e-300) {
        // Parallel to the axis: on the surface or not at all.
        let d = (w.dot(w) - nw * nw).max(0.0).sqrt();
        if (d - cyl.radius).abs() > tol || nv == 0.0 {
            return Vec::new();
        }
        let t_of = |h: f64| (h - h0) / (h1 - h0);
        let (mut ta, mut tb) = (t_of(0.0), t_of(cyl.height));
        if ta > tb {
            std::mem::swap(&mut ta, &mut tb);
        }
        let (lo, hi) = (ta.max(0.0), tb.min(1.0));
        if lo > hi {
            return Vec::new();
        }
        let mut out = vec![at(lo, false)];
        if hi > lo {
            out.push(at(hi, false));
        }
        return out;
    }
    // Distance from the line to the axis: d² = r² + c − b²/a.
    let d2 = cyl.radius * cyl.radius + c - b * b / a;
    let d = d2.max(0.0).sqrt();
    if d > cyl.radius + tol {
        return Vec::new();
    }
    let roots: Vec<(f64, bool)> = if (d - cyl.radius).abs() <= tol {
        vec![(-b / a, true)]
    } else {
        let disc = (b * b - a * c).max(0.0).sqrt();
        // Numerically stable pair of roots.
        let qq = -(b + b.signum() * disc);
        let (r1, r2) = if qq != 0.0 {
            (qq / a, c / qq)
        } else {
            (-b / a, -b / a)
        };
        vec![(r1.min(r2), false), (r1.max(r2), false)]
    };
    let ttol = tol / vv.sqrt();
    roots
        .into_iter()
        .filter(|&(t, _)| t >= -ttol && t <= 1.0 + ttol)
        .map(|(t, g)| (t.clamp(0.0, 1.0), g))
        .filter(|&(t, _)| in_height(t))
        .map(|(t, g)| at(t, g))
        .collect()
}

/// Exact plane section of a cylinder: a plane perpendicular to the axis gives a circle, an
/// oblique plane an ellipse (clipped to the height range, so possibly arcs of it), a plane
/// parallel to the axis gives its rulings (the circle/plane roots of the base circle). Curves
/// are sampled with chord error within `chord_tol`.
pub fn cylinder_section(
    cyl: &Cylinder,
    plane_point: DVec3,
    plane_normal: DVec3,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let nn = plane_normal.normalize_or_zero();
    if nn == DVec3::ZERO || chord_tol.is_nan() || chord_tol <= 0.0 {
        return Vec::new();
    }
    let (x, y) = cyl.frame();
    let k = nn.dot(cyl.axis);
    let q = nn.dot(cyl.base - plane_point);
    let (m, n) = (nn.dot(x), nn.dot(y));
    let r = cyl.radius;
    if k.abs() <= 1e-12 {
        let base = ArcData::circle(cyl.base, r, cyl.axis);
        return circle_plane(&base, plane_point, nn, chord_tol * 1e-3)
            .into_iter()
            .map(|p| Polyline3 {
                points: vec![p, p + cyl.axis * cyl.height],
                closed: false,
            })
            .collect();
    }
    // Height on the ruling at angle θ: s(θ) = −(q + r(m cosθ + n sinθ)) / k.
    let s = |t: f64| -(q + r * (m * t.cos() + n * t.sin())) / k;
    let pt = |t: f64, h: f64| cyl.base + r * (t.cos() * x + t.sin() * y) + cyl.axis * h;
    // The ellipse's largest radius of curvature bounds the angular step for the chord error.
    let rho = r / (k * k);
    let step = (2.0 * (1.0 - chord_tol / rho).clamp(-1.0, 1.0).acos()).clamp(1e-4, PI / 8.0);
    // Angles where s crosses 0 or h split the circle into pieces wholly in or out of range.
    let rr = (m * m + n * n).sqrt();
    let phi = n.atan2(m);
    let mut cuts = Vec::new();
    if rr > 0.0 {
        for h in [0.0, cyl.height] {
            let cv = (-q - h * k) / (r * rr);
            if cv.abs() < 1.0 {
                let a = cv.acos();
                cuts.push((phi + a).rem_euclid(TAU));
                cuts.push((phi - a).rem_euclid(TAU));
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let sample = |a: f64, b: f64| -> Vec<DVec3> {
        let nseg = ((b - a) / step).ceil().max(1.0) as usize;
        (0..=nseg)
            .map(|i| {
                let t = a + (b - a) * i as f64 / nseg as f64;
                pt(t, s(t).clamp(0.0, cyl.height))
            })
            .collect()
    };
    let valid = |t: f64| {
        let h = s(t);
        (0.0..=cyl.height).contains(&h)
    };
    if cuts.is_empty() {
        if !valid(0.0) {
            return Vec::new();
        }
        let mut pts = sample(0.0, TAU);
        pts.pop();
        return vec![Polyline3 {
            points: pts,
            closed: true,
        }];
    }
    let mut out = Vec::new();
    for i in 0..cuts.len() {
        let a = cuts[i];
        let b = if i + 1 < cuts.len() {
            cuts[i + 1]
        } else {
            cuts[0] + TAU
        };
        if b - a > 0.0 && valid(0.5 * (a + b)) {
            out.push(Polyline3 {
                points: sample(a, b),
                closed: false,
            });
        }
    }
    out
}

/// A hit of a curve on a mesh: the curve parameter, the point and the triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshHit {
    pub t: f64,
    pub point: DVec3,
    pub triangle: u32,
}

/// A polyline against a mesh through the mesh's BVH; `t` is the polyline parameter
/// `i + f` (segment i, fraction f). Each segment/triangle decision uses exact orient3d signs
/// with the consistent tie-break, so a hit through a mesh edge or vertex is reported by exactly
/// one triangle, and a hit at a polyline vertex by one segment.
pub fn polyline_mesh_hits(points: &[DVec3], mesh: &Mesh) -> Vec<MeshHit> {
    use crate::geom::mesh::predicates::side_sos;
    let bvh = mesh.bvh();
    let mut out = Vec::new();
    const SEG_BASE: u64 = 1 << 62;
    for i in 0..points.len().saturating_sub(1) {
        let (p, q) = (points[i], points[i + 1]);
        let (ip, iq) = (SEG_BASE + i as u64, SEG_BASE + i as u64 + 1);
        let b = Aabb::of_points(&[p, q]);
        bvh.query_box(&b, |t| {
            let tri = mesh.triangles()[t as usize];
            let c = mesh.corners_of(t as usize);
            let id = tri.map(|v| v as u64);
            // The polyline is the symbolically translated side.
            let sp = |pts: [DVec3; 4], ids: [u64; 4], mv: [bool; 4]| side_sos(pts, mv, ids);
            let (f, m) = (false, true);
            let s_p = sp(
                [c[0], c[1], c[2], p],
                [id[0], id[1], id[2], ip],
                [f, f, f, m],
            );
            let s_q = sp(
                [c[0], c[1], c[2], q],
                [id[0], id[1], id[2], iq],
                [f, f, f, m],
            );
            if s_p == s_q {
                return;
            }
            let mv = [m, m, f, f];
            let e0 = sp([p, q, c[0], c[1]], [ip, iq, id[0], id[1]], mv);
            let e1 = sp([p, q, c[1], c[2]], [ip, iq, id[1], id[2]], mv);
            let e2 = sp([p, q, c[2], c[0]], [ip, iq, id[2], id[0]], mv);
            if e0 == e1 && e1 == e2 {
                let nrm = (c[1] - c[0]).cross(c[2] - c[0]);
                let dp = nrm.dot(p - c[0]);
                let dq = nrm.dot(q - c[0]);
                let f = if dp != dq {
                    (dp / (dp - dq)).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                out.push(MeshHit {
                    t: i as f64 + f,
                    point: p + (q - p) * f,
                    triangle: t,
                });
            }
        });
    }
    out.sort_by(|a, b| a.t.total_cmp(&b.t).then(a.triangle.cmp(&b.triangle)));
    out
}

/// Any curve against a mesh: the curve is sampled within `chord_tol` ([`sample_curve`]) and
/// the polyline hit through the BVH; `t` is mapped back to the curve's parameter.
pub fn curve_mesh_hits(curve: &dyn ParamCurve, mesh: &Mesh, chord_tol: f64) -> Vec<MeshHit> {
    let (ts, pts) = sample_curve(curve, chord_tol, 16);
    polyline_mesh_hits(&pts, mesh)
        .into_iter()
        .map(|mut h| {
            let i = (h.t.floor() as usize).min(ts.len() - 2);
            let f = h.t - i as f64;
            h.t = ts[i] + (ts[i + 1] - ts[i]) * f;
            h
        })
        .collect()
}
