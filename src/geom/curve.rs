//! `Curve`: one value type over every curve kind (line, circle, arc, polyline, quadratic
//! spline, B-spline), with the queries and transforms the language binds to.
//!
//! Every query takes the public parameter t in [0, 1] (SPEC §4). Kind-specific algorithms
//! are in the kind's file; the rest work on the curve's pieces (`piece.rs`).

use std::f64::consts::PI;

use glam::{DMat3, DMat4, DVec3};

use super::arc::Arc;
use super::bezier::Bez;
use super::bspline::BSpline;
use super::circle::Circle;
use super::ellipse::Ellipse;
use super::error::{finite, finite3, invalid, GeomError, Result};
use super::line::Line;
use super::piece::{span_creases, Piece, Span};
use super::polyline::{Polyline, Segment};
use super::quadspline::QuadSpline;
use super::traits::*;

mod display;
pub use display::fmt_g;

/// Any curve lispcad knows.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    Line(Line),
    Circle(Circle),
    Arc(Arc),
    Polyline(Polyline),
    Spline(QuadSpline),
    BSpline(BSpline),
    Ellipse(Ellipse),
}

impl From<Line> for Curve {
    fn from(v: Line) -> Curve {
        Curve::Line(v)
    }
}
impl From<Circle> for Curve {
    fn from(v: Circle) -> Curve {
        Curve::Circle(v)
    }
}
impl From<Arc> for Curve {
    fn from(v: Arc) -> Curve {
        Curve::Arc(v)
    }
}
impl From<Polyline> for Curve {
    fn from(v: Polyline) -> Curve {
        Curve::Polyline(v)
    }
}
impl From<QuadSpline> for Curve {
    fn from(v: QuadSpline) -> Curve {
        Curve::Spline(v)
    }
}
impl From<Ellipse> for Curve {
    fn from(v: Ellipse) -> Curve {
        Curve::Ellipse(v)
    }
}
impl From<BSpline> for Curve {
    fn from(v: BSpline) -> Curve {
        Curve::BSpline(v)
    }
}

/// Relative accuracy used for arc lengths (exact for lines and arcs).
const LEN_ACC: f64 = 1e-13;

fn bspline_spans(s: &BSpline) -> Vec<Span> {
    if let Some(spans) = decompose_clamped(s) {
        return spans;
    }
    let (a, b) = s.domain();
    let mut breaks: Vec<f64> = s
        .knots
        .iter()
        .copied()
        .filter(|u| *u >= a && *u <= b)
        .collect();
    breaks.dedup();
    let pieces = s.to_beziers();
    breaks
        .windows(2)
        .filter(|w| w[1] > w[0])
        .zip(pieces)
        .map(|(w, (pts, ws))| Span {
            piece: Piece::Bez(Bez::from_weighted(&pts, &ws)),
            t0: (w[0] - a) / (b - a),
            t1: (w[1] - a) / (b - a),
        })
        .collect()
}

/// Bézier decomposition of a B-spline with a clamped knot vector (end knots of multiplicity
/// p + 1) in one sweep, without re-allocating per inserted knot: Piegl & Tiller, The NURBS
/// Book, algorithm A5.6 (DecomposeCurve), in homogeneous coordinates.
fn decompose_clamped(s: &BSpline) -> Option<Vec<Span>> {
    use glam::DVec4;
    use smallvec::SmallVec;
    let p = s.degree;
    let u = &s.knots;
    let n = s.ctrl.len() - 1;
    let m = n + p + 1;
    if p > 8 || u[..=p].iter().any(|k| *k != u[0]) || u[m - p..].iter().any(|k| *k != u[m]) {
        return None;
    }
    let w = |i: usize| s.weights.as_ref().map_or(1.0, |w| w[i]);
    let pw = |i: usize| (s.ctrl[i] * w(i)).extend(w(i));
    let (lo, hi) = (u[p], u[m - p]);
    let span_t = |x: f64| (x - lo) / (hi - lo);
    let rational = s.weights.is_some();
    let mut out = Vec::new();
    let mut q: SmallVec<[DVec4; 9]> = (0..=p).map(pw).collect();
    let mut next: SmallVec<[DVec4; 9]> = SmallVec::from_elem(DVec4::ZERO, p + 1);
    let mut alphas = [0.0f64; 9];
    let (mut a, mut b) = (p, p + 1);
    while b < m {
        let i = b;
        while b < m && u[b + 1] == u[b] {
            b += 1;
        }
        let mult = b - i + 1;
        if mult < p {
            let numer = u[b] - u[a];
            for j in ((mult + 1)..=p).rev() {
                alphas[j - mult - 1] = numer / (u[a + j] - u[a]);
            }
            let r = p - mult;
            for j in 1..=r {
                let save = r - j;
                let st = mult + j;
                for k in (st..=p).rev() {
                    let al = alphas[k - st];
                    q[k] = q[k] * al + q[k - 1] * (1.0 - al);
                }
                if b < m {
                    next[save] = q[p];
                }
            }
        }
        out.push(Span {
            piece: Piece::Bez(Bez {
                h: q.iter().copied().collect(),
                rational,
            }),
            t0: span_t(u[a]),
            t1: span_t(u[b]),
        });
        if b < m {
            for k in (p - mult.min(p))..=p {
                next[k] = pw(b - p + k);
            }
            std::mem::swap(&mut q, &mut next);
            a = b;
            b += 1;
        }
    }
    Some(out)
}

impl Curve {
    /// `(line p1 p2)`.
    pub fn line(p1: DVec3, p2: DVec3) -> Result<Curve> {
        Line::new(p1, p2).map(Curve::Line)
    }
    /// `(circle center radius [normal])`.
    pub fn circle(center: DVec3, radius: f64, normal: Option<DVec3>) -> Result<Curve> {
        Circle::new(center, radius, normal.unwrap_or(DVec3::Z)).map(Curve::Circle)
    }
    /// `(arc center radius start end [normal])`: CCW about the normal, angles from the OCS X
    /// axis of the normal's arbitrary-axis frame.
    pub fn arc(
        center: DVec3,
        radius: f64,
        start: f64,
        end: f64,
        normal: Option<DVec3>,
    ) -> Result<Curve> {
        Arc::new(center, radius, start, end, normal.unwrap_or(DVec3::Z)).map(Curve::Arc)
    }
    /// `(arc3 p1 p2 p3)`: the arc from p1 through p2 to p3.
    pub fn arc3(p1: DVec3, p2: DVec3, p3: DVec3) -> Result<Curve> {
        Arc::through(p1, p2, p3).map(Curve::Arc)
    }
    /// `(pline points [closed] [bulges])`.
    pub fn pline(points: Vec<DVec3>, closed: bool, bulges: Option<Vec<f64>>) -> Result<Curve> {
        Polyline::new(points, bulges, closed, None).map(Curve::Polyline)
    }
    /// `(bspline control-points degree [knots] [weights])`.
    pub fn bspline(
        ctrl: Vec<DVec3>,
        degree: usize,
        knots: Option<Vec<f64>>,
        weights: Option<Vec<f64>>,
    ) -> Result<Curve> {
        Ok(Curve::BSpline(BSpline::new(degree, ctrl, knots, weights)?))
    }

    /// The kind's name as printed (`LINE`, `CIRCLE`, `ARC`, `PLINE`, `SPLINE`, `BSPLINE`).
    pub fn kind_name(&self) -> &'static str {
        match self {
            Curve::Line(_) => "LINE",
            Curve::Circle(_) => "CIRCLE",
            Curve::Arc(_) => "ARC",
            Curve::Polyline(_) => "PLINE",
            Curve::Spline(_) => "SPLINE",
            Curve::BSpline(_) => "BSPLINE",
            Curve::Ellipse(_) => "ELLIPSE",
        }
    }

    /// The curve as pieces with their public parameter ranges.
    pub fn spans(&self) -> Vec<Span> {
        let one = |piece| {
            vec![Span {
                piece,
                t0: 0.0,
                t1: 1.0,
            }]
        };
        match self {
            Curve::Line(l) => one(Piece::Line(*l)),
            Curve::Circle(c) => one(Piece::Arc(c.arc)),
            Curve::Arc(a) => one(Piece::Arc(*a)),
            Curve::Polyline(p) => {
                let n = p.segment_count();
                p.built_segments()
                    .iter()
                    .enumerate()
                    .map(|(i, s)| Span {
                        piece: match *s {
                            Segment::Line(l) => Piece::Line(l),
                            Segment::Arc(a) => Piece::Arc(a),
                        },
                        t0: i as f64 / n as f64,
                        t1: (i + 1) as f64 / n as f64,
                    })
                    .collect()
            }
            Curve::Spline(q) => {
                let n = q.segments.len();
                q.segments
                    .iter()
                    .enumerate()
                    .map(|(i, s)| Span {
                        piece: Piece::Bez(Bez::from_points(s)),
                        t0: i as f64 / n as f64,
                        t1: (i + 1) as f64 / n as f64,
                    })
                    .collect()
            }
            Curve::BSpline(b) => bspline_spans(b),
            Curve::Ellipse(e) => e.spans(),
        }
    }

    /// The span holding public parameter t, and the piece parameter there.
    fn locate(spans: &[Span], t: f64) -> (usize, f64) {
        let t = t.clamp(0.0, 1.0);
        let i = spans.partition_point(|s| s.t1 <= t).min(spans.len() - 1);
        let s = &spans[i];
        (i, ((t - s.t0) / (s.t1 - s.t0)).clamp(0.0, 1.0))
    }

    /// The span holding public parameter t and the piece parameter there (a polyline's are
    /// found without the spans: [`Polyline::segment_at`]).
    fn span_at(&self, t: f64) -> (Span, f64) {
        let mut spans = self.spans();
        let (i, s) = Curve::locate(&spans, t);
        (spans.swap_remove(i), s)
    }

    /// `(point-at c t)`: the point at public parameter t in [0, 1] (clamped; NaN reads as 0).
    pub fn eval(&self, t: f64) -> DVec3 {
        let t = if t.is_nan() { 0.0 } else { t };
        match self {
            Curve::Line(l) => l.eval(t.clamp(0.0, 1.0)),
            Curve::Circle(c) => c.eval(t.clamp(0.0, 1.0)),
            Curve::Arc(a) => a.eval(t.clamp(0.0, 1.0)),
            Curve::Spline(q) => q.eval(t),
            Curve::BSpline(b) => b.eval(t.clamp(0.0, 1.0)),
            Curve::Ellipse(e) => e.point_at_angle(e.angle_at(t)),
            Curve::Polyline(p) => match p.segment_at(t) {
                (Segment::Line(l), s, ..) => l.eval(s),
                (Segment::Arc(a), s, ..) => a.eval(s),
            },
        }
    }

    /// dP/dt at public parameter t (clamped to [0, 1]; NaN reads as 0).
    pub fn deriv(&self, t: f64) -> DVec3 {
        let t = if t.is_nan() { 0.0 } else { t };
        match self {
            Curve::Line(l) => l.dir(),
            Curve::Circle(c) => c.deriv(t.clamp(0.0, 1.0)),
            Curve::Arc(a) => a.deriv(t.clamp(0.0, 1.0)),
            Curve::Polyline(p) => match p.segment_at(t) {
                (Segment::Line(l), _, t0, t1) => l.dir() / (t1 - t0),
                (Segment::Arc(a), s, t0, t1) => a.deriv(s) / (t1 - t0),
            },
            _ => {
                let (span, s) = self.span_at(t);
                span.piece.deriv(s) / (span.t1 - span.t0)
            }
        }
    }

    /// `(tangent-at c t)`: the unit tangent at t (the zero vector only at a degenerate point
    /// such as a spline with coincident control points).
    pub fn tangent(&self, t: f64) -> DVec3 {
        self.deriv(t).normalize_or_zero()
    }

    /// `(curve-length c)`.
    pub fn length(&self) -> f64 {
        match self {
            Curve::Line(l) => l.arclen(0.0),
            Curve::Circle(c) => c.arclen(0.0),
            Curve::Arc(a) => a.arclen(0.0),
            _ => {
                let scale = self.scale();
                self.spans()
                    .iter()
                    .map(|s| s.piece.length(LEN_ACC * scale))
                    .sum()
            }
        }
    }

    /// `(point-at-length c s)`: the point at arc length `s` from the start. Errors when s is
    /// not finite or outside [0, length] (beyond a relative 1e-12 slack).
    pub fn point_at_length(&self, s: f64) -> Result<DVec3> {
        Ok(self.eval(self.param_at_length(s)?))
    }

    /// The public parameter at arc length `s` from the start.
    pub fn param_at_length(&self, s: f64) -> Result<f64> {
        finite("length", s)?;
        let total = self.length();
        let slack = 1e-12 * total.max(1.0);
        if s < -slack || s > total + slack {
            return Err(invalid(
                "length",
                format!("must be within [0, {total}] (the curve's length), got {s}"),
            ));
        }
        let acc = LEN_ACC * self.scale();
        let mut left = s.clamp(0.0, total);
        let spans = self.spans();
        for (i, sp) in spans.iter().enumerate() {
            let l = sp.piece.length(acc);
            if left <= l || i + 1 == spans.len() {
                return Ok(sp.t_of(sp.piece.param_at_length(left, acc)));
            }
            left -= l;
        }
        Ok(1.0)
    }

    /// `(closest-point c p)`: `(t, point)` of the curve point nearest to `p`. A non-finite
    /// `p` has no nearest point: the start `(0, start)` is returned (bindings should refuse it).
    pub fn closest_point(&self, p: DVec3) -> (f64, DVec3) {
        if !p.is_finite() {
            return (0.0, self.eval(0.0));
        }
        let mut best = (f64::INFINITY, 0.0, DVec3::ZERO);
        for sp in self.spans() {
            let (s, q) = sp.piece.nearest(p);
            let d = (q - p).length_squared();
            if d < best.0 {
                best = (d, sp.t_of(s), q);
            }
        }
        (best.1, best.2)
    }

    /// `(curve-points c tol)`: a polyline within `tol` of the curve, from its start to its end
    /// (a closed curve's last point repeats its first). Errors unless tol is finite and > 0.
    pub fn points(&self, tol: f64) -> Result<Vec<DVec3>> {
        finite("tolerance", tol)?;
        if tol <= 0.0 {
            return Err(invalid("tolerance", format!("must be > 0, got {tol}")));
        }
        let spans = self.spans();
        let mut out = vec![spans[0].piece.eval(0.0)];
        for sp in &spans {
            sp.piece.flatten(tol, &mut out);
        }
        Ok(out)
    }

    /// `(bbox c)`: the tight axis-aligned box `(min, max)`.
    pub fn bbox(&self) -> (DVec3, DVec3) {
        match self {
            Curve::Line(l) => l.bbox(),
            Curve::Circle(c) => c.bbox(),
            Curve::Arc(a) => a.bbox(),
            _ => self.spans().iter().map(|s| s.piece.bbox()).fold(
                (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
                |(a, b), (c, d)| (a.min(c), b.max(d)),
            ),
        }
    }

    /// A size for relative tolerances: the largest of the box's extent and 1.
    pub(crate) fn scale(&self) -> f64 {
        let (lo, hi) = match self {
            Curve::Line(l) => l.bbox(),
            Curve::Circle(c) => c.bbox(),
            Curve::Arc(a) => a.bbox(),
            _ => self.spans().iter().map(|s| s.piece.hull_bbox()).fold(
                (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
                |(a, b), (c, d)| (a.min(c), b.max(d)),
            ),
        };
        lo.abs().max(hi.abs()).max_element().max(1.0)
    }

    /// True for circles, closed polylines and splines, and B-splines whose ends coincide.
    pub fn is_closed(&self) -> bool {
        match self {
            Curve::Line(_) | Curve::Arc(_) => false,
            Curve::Circle(_) => true,
            Curve::Polyline(p) => p.closed,
            Curve::Spline(q) => q.closed,
            Curve::BSpline(b) => (b.eval(0.0) - b.eval(1.0)).length() <= 1e-12 * self.scale(),
            Curve::Ellipse(e) => e.is_full(),
        }
    }

    /// The points whose convex hull contains the curve (for planarity tests).
    fn hull_points(&self) -> Vec<DVec3> {
        match self {
            Curve::Polyline(p) => {
                let mut v = p.vertices.clone();
                for s in p.segments() {
                    if let Segment::Arc(a) = s {
                        let (lo, hi) = a.bbox();
                        v.push(lo);
                        v.push(hi);
                    }
                }
                v
            }
            Curve::Spline(q) => q.segments.iter().flat_map(|s| s.iter().copied()).collect(),
            Curve::BSpline(b) => b.ctrl.clone(),
            Curve::Line(l) => vec![l.p0, l.p1],
            Curve::Circle(c) => vec![c.center()],
            Curve::Arc(a) => vec![a.center()],
            Curve::Ellipse(e) => {
                let (c, m, n) = (e.center, e.major, e.minor);
                vec![c + m, c + n, c - m, c - n]
            }
        }
    }

    /// `(area closed-curve)`: the enclosed area (positive), by the vector form of Green's
    /// theorem A·n = ½∮ P × dP (exact for lines and arcs, Gauss–Legendre for splines).
    /// Errors when the curve is not closed or not planar (relative 1e-9).
    pub fn area(&self) -> Result<f64> {
        if !self.is_closed() {
            return Err(GeomError::NotClosed("area"));
        }
        if let Curve::Circle(c) = self {
            return Ok(PI * c.radius() * c.radius());
        }
        if let Curve::Ellipse(e) = self {
            return Ok(e.full_area());
        }
        let spans = self.spans();
        let va: DVec3 = spans.iter().map(|s| s.piece.vector_area()).sum();
        let a = va.length();
        let scale = self.scale();
        if a <= 1e-300 {
            return Ok(0.0);
        }
        let n = va / a;
        let pts = self.hull_points();
        let o = pts[0];
        if pts.iter().any(|p| (*p - o).dot(n).abs() > 1e-9 * scale) {
            return Err(GeomError::NotPlanar("area"));
        }
        Ok(a)
    }

    /// The plane normal of a planar curve (arc/circle normal, polyline normal, or the normal
    /// of a planar spline), `None` for a line or a non-planar curve.
    pub fn plane_normal(&self) -> Option<DVec3> {
        match self {
            Curve::Line(_) => None,
            Curve::Circle(c) => Some(c.normal()),
            Curve::Arc(a) => Some(a.normal()),
            Curve::Ellipse(e) => Some(e.normal()),
            Curve::Polyline(p) => {
                let pts = &p.vertices;
                let o = pts[0];
                let scale = self.scale();
                if pts
                    .iter()
                    .all(|q| (*q - o).dot(p.normal).abs() <= 1e-9 * scale)
                {
                    Some(p.normal)
                } else {
                    None
                }
            }
            _ => {
                let pts = self.hull_points();
                // Newell-style normal from the hull points' fan, then a flatness check.
                let o = pts[0];
                let mut n = DVec3::ZERO;
                for w in pts.windows(2) {
                    n += (w[0] - o).cross(w[1] - o);
                }
                let n = n.try_normalize()?;
                let scale = self.scale();
                if pts.iter().all(|q| (*q - o).dot(n).abs() <= 1e-9 * scale) {
                    Some(n)
                } else {
                    None
                }
            }
        }
    }

    /// `move`/`rotate`/`scale`/`mirror`: the curve under the affine map `m`. Lines, straight
    /// polylines and splines take any affine map (splines are affine invariant). Circles,
    /// arcs and bulged polylines need a similarity (uniform scale, rotation, mirror): a
    /// mirror flips their normal, so the image runs the right way round.
    pub fn transform(&self, m: &DMat4) -> Result<Curve> {
        if !m.is_finite() {
            return Err(invalid("transform", "matrix must be finite"));
        }
        let lin = DMat3::from_mat4(*m);
        let pt = |p: DVec3| m.transform_point3(p);
        match self {
            Curve::Line(l) => Line::new(pt(l.p0), pt(l.p1)).map(Curve::Line),
            Curve::Circle(c) => {
                let a = transform_arc(&c.arc, m, lin)?;
                Circle::new(a.center, a.radius, a.normal).map(Curve::Circle)
            }
            Curve::Arc(a) => transform_arc(a, m, lin).map(Curve::Arc),
            Curve::Polyline(p) => {
                let (u, v) = super::frame::arbitrary_axis(p.normal);
                let (lu, lv) = (lin * u, lin * v);
                if p.bulges.iter().any(|b| *b != 0.0) {
                    similarity_scale(lin, u, v, p.normal)?;
                }
                let normal = lu.cross(lv);
                let normal = if normal.length_squared() > 0.0 {
                    normal
                } else {
                    p.normal
                };
                Polyline::new(
                    p.vertices.iter().map(|q| pt(*q)).collect(),
                    Some(p.bulges.clone()),
                    p.closed,
                    Some(normal),
                )
                .map(Curve::Polyline)
            }
            Curve::Spline(q) => Ok(Curve::Spline(QuadSpline {
                points: q.points.iter().map(|p| pt(*p)).collect(),
                closed: q.closed,
                segments: q
                    .segments
                    .iter()
                    .map(|s| [pt(s[0]), pt(s[1]), pt(s[2])])
                    .collect(),
            })),
            Curve::BSpline(b) => Ok(Curve::BSpline(BSpline {
                ctrl: b.ctrl.iter().map(|p| pt(*p)).collect(),
                ..b.clone()
            })),
            Curve::Ellipse(e) => {
                let (u, v) = (e.major.normalize(), e.minor.normalize());
                similarity_scale(lin, u, v, e.normal)?;
                let (m, n) = (lin * e.major, lin * e.minor);
                Ellipse::new(
                    pt(e.center),
                    m,
                    e.ratio,
                    e.start,
                    e.start + e.sweep,
                    m.cross(n),
                )
                .map(Curve::Ellipse)
            }
        }
    }
}

impl ParamCurve for Curve {
    fn eval(&self, t: f64) -> DVec3 {
        Curve::eval(self, t)
    }

    /// Only polylines and B-splines can join spans at a kink; a quadratic spline is C1 by
    /// construction, the other kinds are one piece.
    fn creases(&self) -> Vec<f64> {
        match self {
            Curve::Polyline(_) | Curve::BSpline(_) => span_creases(&self.spans()),
            _ => Vec::new(),
        }
    }
}
impl ParamCurveDeriv for Curve {
    fn deriv(&self, t: f64) -> DVec3 {
        Curve::deriv(self, t)
    }
}
impl ParamCurveArclen for Curve {
    /// Lines and arcs are exact; spline pieces use adaptive Gauss–Legendre to 1e-13·scale.
    fn arclen(&self, _accuracy: f64) -> f64 {
        self.length()
    }
}
impl ParamCurveNearest for Curve {
    fn nearest(&self, p: DVec3, _accuracy: f64) -> (f64, DVec3) {
        self.closest_point(p)
    }
}
impl ParamCurveBbox for Curve {
    fn bbox(&self) -> (DVec3, DVec3) {
        Curve::bbox(self)
    }
}

/// The scale factor of `lin` on the plane (u, v) with normal n, or an error when `lin` is not
/// a similarity there.
fn similarity_scale(lin: DMat3, u: DVec3, v: DVec3, n: DVec3) -> Result<f64> {
    let (lu, lv, ln) = (lin * u, lin * v, lin * n);
    let s = lu.length();
    let ok = s > 0.0
        && (lv.length() - s).abs() <= 1e-9 * s
        && (ln.length() - s).abs() <= 1e-9 * s
        && lu.dot(lv).abs() <= 1e-9 * s * s;
    if ok {
        Ok(s)
    } else {
        Err(GeomError::Unsupported(
            "transform: circles, arcs and bulged polylines need a uniform scale (a similarity); \
             non-uniform scaling would make an ellipse"
                .into(),
        ))
    }
}

fn transform_arc(a: &Arc, m: &DMat4, lin: DMat3) -> Result<Arc> {
    let s = similarity_scale(lin, a.x_axis, a.y_axis, a.normal)?;
    let normal = (lin * a.x_axis).cross(lin * a.y_axis).normalize();
    let center = m.transform_point3(a.center);
    finite3("center", center)?;
    let out = Arc::from_parts(center, a.radius * s, normal, 0.0, a.sweep);
    Ok(out.with_range(out.angle_of(m.transform_point3(a.eval(0.0))), a.sweep))
}

/// The affine maps behind `move`, `rotate`, `scale` and `mirror`.
pub mod xform {
    use super::*;

    /// `(move v delta)`.
    pub fn translate(delta: DVec3) -> DMat4 {
        DMat4::from_translation(delta)
    }
    /// `(rotate v base angle [axis])`: CCW by `angle` about `axis` (default +Z) through `base`.
    pub fn rotate(base: DVec3, angle: f64, axis: Option<DVec3>) -> Result<DMat4> {
        let axis = axis.unwrap_or(DVec3::Z);
        finite("angle", angle)?;
        let axis = axis
            .try_normalize()
            .ok_or_else(|| invalid("axis", "must not be the zero vector"))?;
        Ok(DMat4::from_translation(base)
            * DMat4::from_axis_angle(axis, angle)
            * DMat4::from_translation(-base))
    }
    /// `(scale v base factor)`: uniform scale about `base`; factor must be non-zero.
    pub fn scale(base: DVec3, factor: f64) -> Result<DMat4> {
        finite("factor", factor)?;
        if factor == 0.0 {
            return Err(invalid("factor", "must not be 0"));
        }
        Ok(DMat4::from_translation(base)
            * DMat4::from_scale(DVec3::splat(factor))
            * DMat4::from_translation(-base))
    }
    /// `(mirror v p1 p2)`: reflection in the plane through p1 and p2 that contains the Z
    /// direction (the mirror line p1–p2 seen in plan, as AutoCAD's MIRROR).
    pub fn mirror(p1: DVec3, p2: DVec3) -> Result<DMat4> {
        let d = p2 - p1;
        let n = d.cross(DVec3::Z);
        let n = if n.length_squared() > 1e-24 * d.length_squared().max(1e-300) {
            n.normalize()
        } else {
            return Err(invalid(
                "mirror line",
                "p1 and p2 must differ in plan (X/Y)",
            ));
        };
        // Householder reflection I − 2nnᵀ about the plane through p1.
        let h = DMat3::from_cols(
            DVec3::X - n * (2.0 * n.x),
            DVec3::Y - n * (2.0 * n.y),
            DVec3::Z - n * (2.0 * n.z),
        );
        Ok(DMat4::from_translation(p1) * DMat4::from_mat3(h) * DMat4::from_translation(-p1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sweep_decomposition_matches_knot_insertion() {
        let ctrl: Vec<DVec3> = (0..8)
            .map(|i| DVec3::new(i as f64, ((i * 5) % 3) as f64, ((i * 7) % 4) as f64 * 0.5))
            .collect();
        let weights = vec![1.0, 2.0, 0.5, 1.0, 1.5, 1.0, 0.7, 1.2];
        for p in 1..=4 {
            for knots in [
                None,
                Some({
                    // A repeated interior knot.
                    let mut k = vec![0.0; p + 1];
                    let inner = 8 - p - 1;
                    for i in 0..inner {
                        k.push(if i == 1 {
                            0.25
                        } else {
                            (i as f64 + 1.0) / (inner + 1) as f64
                        });
                    }
                    k.sort_by(f64::total_cmp);
                    k.extend(std::iter::repeat_n(1.0, p + 1));
                    k
                }),
            ] {
                for w in [None, Some(weights.clone())] {
                    let s = BSpline::new(p, ctrl.clone(), knots.clone(), w).unwrap();
                    let fast = decompose_clamped(&s).unwrap();
                    for sp in &fast {
                        for j in 0..=8 {
                            let x = j as f64 / 8.0;
                            let t = sp.t0 + (sp.t1 - sp.t0) * x;
                            let d = (sp.piece.eval(x) - s.eval(t)).length();
                            assert!(d < 1e-12, "p {p} span {}..{} x {x}: {d}", sp.t0, sp.t1);
                        }
                    }
                    let (a, b) = (fast[0].t0, fast.last().unwrap().t1);
                    assert!(a == 0.0 && b == 1.0);
                }
            }
        }
    }
}
