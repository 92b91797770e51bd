//! Coaxial surfaces of revolution meet in circles: a surface of revolution against a cylinder
//! or another surface of revolution about the same axis line, or a sphere centred on it.
//!
//! In the meridian half-plane (ρ, z) — distance from the axis, height along it — each surface
//! is a curve (a profile, the line ρ = r, the circle ρ² + (z − zc)² = R²); every point where the
//! meridian curves meet turns into a circle about the axis (an arc where a revolution is
//! partial, a point on the axis). Crossings are bracketed on the sampled profile and solved to
//! roundoff (bisection on a sign change; a minimum of the distance within the tolerance is a
//! tangent circle), so the circles lie on both true surfaces.

use super::hits::ArcData;
use super::kinds::{Cylinder, Revolve, Sphere, Surface};
use crate::geom::frame::arbitrary_axis;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// The axis line and its frame.
pub(super) struct Axis {
    pub(super) o: DVec3,
    pub(super) a: DVec3,
    x: DVec3,
    y: DVec3,
}

impl Axis {
    pub(super) fn new(o: DVec3, a: DVec3) -> Axis {
        let (x, y) = arbitrary_axis(a);
        Axis { o, a, x, y }
    }

    /// (ρ, z) of a point.
    pub(super) fn meridian(&self, p: DVec3) -> DVec2 {
        let d = p - self.o;
        let z = d.dot(self.a);
        DVec2::new((d - self.a * z).length(), z)
    }

    /// The angle of a point about the axis, in [0, 2π).
    pub(super) fn angle(&self, p: DVec3) -> f64 {
        let d = p - self.o;
        d.dot(self.y).atan2(d.dot(self.x)).rem_euclid(TAU)
    }

    /// Whether the line through `p` along `dir` is this axis line.
    pub(super) fn same_line(&self, p: DVec3, dir: DVec3, tol: f64) -> bool {
        let d = p - self.o;
        self.a.cross(dir).length() <= 1e-12 && (d - self.a * d.dot(self.a)).length() <= tol
    }

    /// A cylinder about this axis line as (radius, z at its base, z at its top), z measured
    /// along the axis; None when its axis is another line.
    pub(super) fn cylinder(&self, c: &Cylinder, tol: f64) -> Option<(f64, f64, f64)> {
        if !self.same_line(c.base, c.axis, tol) {
            return None;
        }
        let z0 = (c.base - self.o).dot(self.a);
        Some((c.radius, z0, z0 + c.height * c.axis.dot(self.a).signum()))
    }
}

/// The angular span a surface covers about the axis at a meridian crossing: (start, sweep).
pub(super) type Span = (f64, f64);

/// What the other surface looks like in the meridian plane.
enum Meridian<'a> {
    /// ρ = r for z in [lo, hi].
    Line { r: f64, lo: f64, hi: f64 },
    /// ρ² + (z − zc)² = R².
    Circle { zc: f64, r: f64 },
    /// Another profile revolved about the same axis.
    Profile(&'a Revolve),
    /// z = const: a plane perpendicular to the axis.
    Height(f64),
}

/// The intersection when the pair is coaxial (None otherwise).
pub(crate) fn coaxial_intersect(
    a: &Surface,
    b: &Surface,
    tol: f64,
    chord_tol: f64,
) -> Option<Vec<Polyline3>> {
    let (rev, other) = match (a, b) {
        (Surface::Revolve(r), o) | (o, Surface::Revolve(r)) => (r, o),
        _ => return None,
    };
    let ax = Axis::new(rev.axis_point, rev.axis_dir);
    let mer = match other {
        Surface::Cylinder(c) => {
            let (radius, z0, z1) = ax.cylinder(c, tol)?;
            Meridian::Line {
                r: radius,
                lo: z0.min(z1),
                hi: z0.max(z1),
            }
        }
        Surface::Sphere(Sphere { center, radius }) => {
            let m = ax.meridian(*center);
            if m.x > tol {
                return None;
            }
            Meridian::Circle {
                zc: m.y,
                r: *radius,
            }
        }
        Surface::Revolve(r2) if !std::ptr::eq(r2, rev) => {
            if !ax.same_line(r2.axis_point, r2.axis_dir, tol) {
                return None;
            }
            Meridian::Profile(r2)
        }
        _ => return None,
    };
    let crossings = match &mer {
        Meridian::Profile(r2) => profile_profile(&ax, rev, r2, tol),
        _ => profile_implicit(&ax, rev, &mer, tol),
    };
    let mut out = Vec::new();
    for (m, span_a, span_b) in crossings {
        let spans = match span_b {
            Some(sb) => overlap(span_a, sb),
            None => vec![span_a],
        };
        for (start, sweep) in spans {
            out.push(circle(&ax, m, start, sweep, tol, chord_tol));
        }
    }
    Some(out)
}

/// A plane perpendicular to the axis of a surface of revolution (through `p`) cuts it in
/// circles — arcs for a partial revolution, points on the axis — through the profile's
/// crossings of the plane, solved on the true profile; a profile touching the plane gives its
/// circle once.
pub(crate) fn revolve_plane_perpendicular(
    r: &Revolve,
    p: DVec3,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let ax = Axis::new(r.axis_point, r.axis_dir);
    let mer = Meridian::Height((p - ax.o).dot(ax.a));
    profile_implicit(&ax, r, &mer, tol)
        .into_iter()
        .map(|(m, (start, sweep), _)| circle(&ax, m, start, sweep, tol, chord_tol))
        .collect()
}

/// The span of a revolution at the profile point `q`: from q's own angle, `angle` about the
/// revolution's axis (reversed when that axis points against `ax`).
pub(super) fn span_of(ax: &Axis, r: &Revolve, q: DVec3) -> Span {
    let t = ax.angle(q);
    if r.angle >= TAU {
        (0.0, TAU)
    } else if r.axis_dir.dot(ax.a) > 0.0 {
        (t, r.angle)
    } else {
        ((t - r.angle).rem_euclid(TAU), r.angle)
    }
}

/// The common part of two angular spans (up to two pieces).
pub(super) fn overlap(a: Span, b: Span) -> Vec<Span> {
    if a.1 >= TAU {
        return vec![b];
    }
    if b.1 >= TAU {
        return vec![a];
    }
    let d = (b.0 - a.0).rem_euclid(TAU);
    let mut out = Vec::new();
    for s in [d, d - TAU] {
        let (lo, hi) = (s.max(0.0), (s + b.1).min(a.1));
        if hi >= lo {
            out.push((a.0 + lo, hi - lo));
        }
    }
    out
}

/// The circle (or arc, or point on the axis) through the meridian point `m`.
pub(super) fn circle(
    ax: &Axis,
    m: DVec2,
    start: f64,
    sweep: f64,
    tol: f64,
    chord_tol: f64,
) -> Polyline3 {
    let c = ax.o + ax.a * m.y;
    if m.x <= tol {
        return Polyline3 {
            points: vec![c],
            closed: false,
        };
    }
    let arc = ArcData::circle(c, m.x, ax.a);
    let full = sweep >= TAU;
    let step = (2.0 * (1.0 - chord_tol / m.x).clamp(-1.0, 1.0).acos()).clamp(1e-5, TAU / 16.0);
    let n = (sweep / step).ceil().max(1.0) as usize;
    let last = if full { n } else { n + 1 };
    let points = if sweep * m.x <= tol {
        vec![arc.point(start)]
    } else {
        (0..last)
            .map(|i| arc.point(start + sweep * i as f64 / n as f64))
            .collect()
    };
    Polyline3 {
        points,
        closed: full,
    }
}

/// A crossing: the meridian point and the spans of the two surfaces there (None: all round).
type Crossing = (DVec2, Span, Option<Span>);

/// The profile's parameters and meridian points, sampled finely enough to bracket crossings.
fn sample_meridian(ax: &Axis, r: &Revolve, tol: f64) -> (Vec<f64>, Vec<DVec2>) {
    let (ts, pts) = super::sampled::sample_curve(r.profile.as_ref(), tol, 512);
    (ts, pts.into_iter().map(|p| ax.meridian(p)).collect())
}

/// Profile against a line or circle in the meridian plane: the signed distance f along the
/// profile, roots by bisection, touching minima of |f| by golden section.
fn profile_implicit(ax: &Axis, r: &Revolve, mer: &Meridian, tol: f64) -> Vec<Crossing> {
    let f = |m: DVec2| match *mer {
        Meridian::Line { r, .. } => m.x - r,
        Meridian::Circle { zc, r } => m.x.hypot(m.y - zc) - r,
        Meridian::Height(z) => m.y - z,
        Meridian::Profile(_) => f64::NAN,
    };
    let at = |t: f64| ax.meridian(r.profile.eval(t));
    let g = |t: f64| f(at(t));
    let (ts, ms) = sample_meridian(ax, r, tol.max(1e-7));
    let fs: Vec<f64> = ms.iter().map(|m| f(*m)).collect();
    if fs.iter().all(|f| f.abs() <= tol) {
        return Vec::new(); // the same surface: a region, not curves
    }
    let mut roots: Vec<f64> = Vec::new();
    // Samples in a run lying on the other surface belong to a common band (traced by
    // `super::common` as a region), not to crossings.
    let on = |i: usize| fs[i].abs() <= tol;
    let band = |i: usize| on(i) && ((i > 0 && on(i - 1)) || (i + 1 < fs.len() && on(i + 1)));
    for i in 0..ts.len() {
        if band(i) {
            continue;
        }
        if fs[i] == 0.0 {
            roots.push(ts[i]);
        }
        if i + 1 < ts.len() && fs[i] * fs[i + 1] < 0.0 {
            roots.push(bisect(&g, ts[i], ts[i + 1], fs[i]));
        }
        // A local minimum of |f| without a sign change (the profile's ends count, bracketed on
        // one side): a touch when it reaches the tolerance.
        let (lo, hi) = (i.saturating_sub(1), (i + 1).min(ts.len() - 1));
        let same = fs[lo] * fs[i] > 0.0 && fs[i] * fs[hi] > 0.0;
        if same && fs[i].abs() <= fs[lo].abs() && fs[i].abs() <= fs[hi].abs() {
            let (a, b) = (ts[lo], ts[hi]);
            // Down to the last representable step of the bracket.
            let tol = 1e-16 * (1.0 + a.abs().max(b.abs()));
            let t = crate::geom::minimize::golden_section_min(|t| g(t).abs(), a, b, 200, tol);
            if g(t).abs() <= tol {
                roots.push(t);
            } else if fs[i].abs() <= tol {
                roots.push(ts[i]);
            }
        }
    }
    let in_range = |m: DVec2| match *mer {
        Meridian::Line { lo, hi, .. } => m.y >= lo - tol && m.y <= hi + tol,
        _ => true,
    };
    let mut out: Vec<Crossing> = Vec::new();
    for t in roots {
        let q = r.profile.eval(t);
        let m = ax.meridian(q);
        if in_range(m) && !out.iter().any(|c| c.0.distance(m) <= tol) {
            out.push((m, span_of(ax, r, q), None));
        }
    }
    out
}

/// A root of `g` in `[a, b]` where `g(a)` has the sign of `ga`, to the last bit of t.
fn bisect(g: &impl Fn(f64) -> f64, mut a: f64, mut b: f64, ga: f64) -> f64 {
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let gm = g(m);
        if gm == 0.0 {
            return m;
        }
        if (gm < 0.0) == (ga < 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    if g(a).abs() <= g(b).abs() {
        a
    } else {
        b
    }
}

/// Two profiles about one axis: crossings of their sampled meridian curves, refined by Newton
/// on `m1(t) = m2(u)`.
fn profile_profile(ax: &Axis, r1: &Revolve, r2: &Revolve, tol: f64) -> Vec<Crossing> {
    // Coarser samples: they only bracket the crossings (every pair of segments is tried).
    let (t1, m1) = sample_meridian(ax, r1, tol.max(1e-5));
    let (t2, m2) = sample_meridian(ax, r2, tol.max(1e-5));
    if m1 == m2 {
        return Vec::new(); // the same surface: a region, not curves
    }
    let at1 = |t: f64| ax.meridian(r1.profile.eval(t));
    let at2 = |u: f64| ax.meridian(r2.profile.eval(u));
    let mut out: Vec<Crossing> = Vec::new();
    for i in 0..t1.len().saturating_sub(1) {
        let (a0, a1) = (m1[i], m1[i + 1]);
        for j in 0..t2.len().saturating_sub(1) {
            let (b0, b1) = (m2[j], m2[j + 1]);
            let Some((s, v)) = seg_cross(a0, a1, b0, b1) else {
                continue;
            };
            let mut t = t1[i] + (t1[i + 1] - t1[i]) * s;
            let mut u = t2[j] + (t2[j + 1] - t2[j]) * v;
            for _ in 0..50 {
                let r = at1(t) - at2(u);
                if r.length() <= 1e-15 * (1.0 + at1(t).length()) {
                    break;
                }
                const H: f64 = 1e-7;
                let d1 = (at1((t + H).min(1.0)) - at1((t - H).max(0.0)))
                    / ((t + H).min(1.0) - (t - H).max(0.0));
                let d2 = (at2((u + H).min(1.0)) - at2((u - H).max(0.0)))
                    / ((u + H).min(1.0) - (u - H).max(0.0));
                let det = d1.perp_dot(-d2);
                if det.abs() <= 1e-300 {
                    break;
                }
                // Solve [d1 −d2]·(dt, du) = −r by Cramer's rule.
                let dt = (-r).perp_dot(-d2) / det;
                let du = d1.perp_dot(-r) / det;
                t = (t + dt).clamp(0.0, 1.0);
                u = (u + du).clamp(0.0, 1.0);
            }
            let (p, q) = (r1.profile.eval(t), r2.profile.eval(u));
            let m = ax.meridian(p);
            if m.distance(ax.meridian(q)) > tol || out.iter().any(|c| c.0.distance(m) <= tol) {
                continue;
            }
            out.push((m, span_of(ax, r1, p), Some(span_of(ax, r2, q))));
        }
    }
    out
}

/// Where segments `a0a1` and `b0b1` cross: the fractions along each (ends included).
fn seg_cross(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> Option<(f64, f64)> {
    let (da, db, w) = (a1 - a0, b1 - b0, b0 - a0);
    let den = da.perp_dot(db);
    if den == 0.0 {
        return None;
    }
    let s = w.perp_dot(db) / den;
    let v = w.perp_dot(da) / den;
    ((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&v)).then_some((s, v))
}
