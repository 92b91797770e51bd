//! `vlax-curve-*`: AutoCAD's curve queries on entity names, VLA objects and CURVE values, with
//! AutoCAD's parameter per kind (SPEC §3): LINE distance from the start, ARC/CIRCLE angle
//! from the OCS X axis, (LW)POLYLINE vertex index plus fraction, SPLINE knot value. Every
//! one of these is linear in the geometry core's public parameter t ∈ [0, 1], so a curve is
//! the core's `Curve` plus the parameter range [lo, hi] that t maps onto.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::builtin;
use crate::builtins::entities::ename_arg;
use crate::builtins::geometry::{curve_value, geom_err, geomtol, vec3, CurveValue};
use crate::geom::curve::Curve;
use crate::geom::curve_measure::Measured;
use crate::geom::frame::Ocs;
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::entity::EntityKind;
use crate::output::Drawing;
use std::rc::Rc;

use super::Vla;

pub static BUILTINS: &[Builtin] = &[
    builtin!("vlax-curve-getStartParam", "(vlax-curve-getStartParam curve)", "The parameter at the start of a curve (entity name, VLA object or CURVE).", 1, 1, start_param),
    builtin!("vlax-curve-getEndParam", "(vlax-curve-getEndParam curve)", "The parameter at the end of a curve (LINE: its length; ARC: end angle; polyline: segment count; SPLINE: last knot).", 1, 1, end_param),
    builtin!("vlax-curve-getStartPoint", "(vlax-curve-getStartPoint curve)", "The start point of a curve.", 1, 1, start_point),
    builtin!("vlax-curve-getEndPoint", "(vlax-curve-getEndPoint curve)", "The end point of a curve.", 1, 1, end_point),
    builtin!("vlax-curve-getPointAtParam", "(vlax-curve-getPointAtParam curve param)", "The point at a parameter, or nil outside the curve's range.", 2, 2, point_at_param),
    builtin!("vlax-curve-getParamAtPoint", "(vlax-curve-getParamAtPoint curve point)", "The parameter of a point on the curve, or nil when the point is not on it.", 2, 2, param_at_point),
    builtin!("vlax-curve-getDistAtParam", "(vlax-curve-getDistAtParam curve param)", "The length along the curve from its start to a parameter, or nil outside the range.", 2, 2, dist_at_param),
    builtin!("vlax-curve-getParamAtDist", "(vlax-curve-getParamAtDist curve dist)", "The parameter at a length along the curve, or nil outside [0, length].", 2, 2, param_at_dist),
    builtin!("vlax-curve-getDistAtPoint", "(vlax-curve-getDistAtPoint curve point)", "The length along the curve from its start to a point on it, or nil when the point is not on it.", 2, 2, dist_at_point),
    builtin!("vlax-curve-getPointAtDist", "(vlax-curve-getPointAtDist curve dist)", "The point at a length along the curve, or nil outside [0, length].", 2, 2, point_at_dist),
    builtin!("vlax-curve-getClosestPointTo", "(vlax-curve-getClosestPointTo curve point [extend])", "The point of the curve nearest to a point; with extend, lines and arcs are extended.", 2, 3, closest_point_to),
    builtin!("vlax-curve-getClosestPointToProjection", "(vlax-curve-getClosestPointToProjection curve point normal [extend])", "The point of the curve nearest to a point when both are projected along normal.", 3, 4, closest_point_to_projection),
    builtin!("vlax-curve-getFirstDeriv", "(vlax-curve-getFirstDeriv curve param)", "The first derivative (a vector) with respect to the curve's parameter.", 2, 2, first_deriv),
    builtin!("vlax-curve-getSecondDeriv", "(vlax-curve-getSecondDeriv curve param)", "The second derivative (a vector) with respect to the curve's parameter.", 2, 2, second_deriv),
    builtin!("vlax-curve-getArea", "(vlax-curve-getArea curve)", "The area enclosed by the curve (an open curve as if closed by a straight segment).", 1, 1, get_area),
    builtin!("vlax-curve-isClosed", "(vlax-curve-isClosed curve)", "T if the curve is closed.", 1, 1, is_closed),
    builtin!("vlax-curve-isPeriodic", "(vlax-curve-isPeriodic curve)", "T if the curve is periodic (circles, closed ellipses and closed splines).", 1, 1, is_periodic),
    builtin!("vlax-curve-isPlanar", "(vlax-curve-isPlanar curve)", "T if the curve lies in a plane.", 1, 1, is_planar),
];

/// A curve with AutoCAD's parameter: the core curve's t ∈ [0, 1] maps linearly onto
/// [lo, hi]. `periodic` marks the curves whose parameter wraps (circles).
pub struct AcCurve {
    pub curve: Curve,
    pub lo: f64,
    pub hi: f64,
    pub periodic: bool,
    /// Span lengths, measured on the first length query.
    measured: std::cell::OnceCell<Measured>,
}

impl AcCurve {
    fn new(curve: Curve) -> AcCurve {
        let (lo, hi) = natural_range(&curve);
        let periodic = match &curve {
            Curve::Circle(_) => true,
            Curve::Ellipse(e) => e.is_full(),
            _ => false,
        };
        AcCurve {
            curve,
            lo,
            hi,
            periodic,
            measured: std::cell::OnceCell::new(),
        }
    }

    fn measured(&self) -> &Measured {
        self.measured.get_or_init(|| Measured::new(&self.curve))
    }

    /// The core parameter of an AutoCAD parameter, None outside the range (beyond a relative
    /// 1e-10 slack, as AutoCAD's own tolerance).
    pub fn t_of(&self, param: f64) -> Option<f64> {
        let span = self.hi - self.lo;
        let slack = 1e-10 * span.abs().max(1.0);
        if !param.is_finite() || param < self.lo - slack || param > self.hi + slack {
            return None;
        }
        if let Curve::Ellipse(e) = &self.curve {
            // The ellipse's angle is not linear in the core's t: convert exactly.
            return Some(if param >= self.hi {
                1.0
            } else if param <= self.lo {
                0.0
            } else {
                e.t_at_angle(param)
            });
        }
        Some(((param - self.lo) / span).clamp(0.0, 1.0))
    }

    pub fn param_of(&self, t: f64) -> f64 {
        if let Curve::Ellipse(e) = &self.curve {
            return if t >= 1.0 { self.hi } else { e.angle_at(t) };
        }
        self.lo + (self.hi - self.lo) * t
    }

    /// dparam/dt.
    fn scale(&self) -> f64 {
        self.hi - self.lo
    }
}

/// AutoCAD's parameter range of a core curve.
fn natural_range(c: &Curve) -> (f64, f64) {
    match c {
        Curve::Line(_) => (0.0, c.length()),
        Curve::Circle(_) => (0.0, TAU),
        Curve::Arc(a) => (a.start_angle(), a.start_angle() + a.sweep()),
        Curve::Polyline(p) => (0.0, p.segment_count() as f64),
        // The lispcad spline through fit points: its quadratic segment index plus fraction.
        Curve::Spline(q) => (0.0, q.segments.len() as f64),
        Curve::BSpline(b) => b.domain(),
        Curve::Ellipse(e) => (e.start_angle(), e.end_angle()),
    }
}

/// The core curve of an entity, None for kinds that are not curves (POINT, TEXT...).
pub fn entity_curve(k: &EntityKind) -> Option<Result<Curve, crate::geom::GeomError>> {
    Some(match k {
        EntityKind::Line { p0, p1 } => Curve::line(*p0, *p1),
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => Curve::circle(*center, *radius, Some(*normal)),
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => Curve::arc(*center, *radius, *start, *end, Some(*normal)),
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            let ocs = Ocs::new(*normal);
            let pts = points
                .iter()
                .map(|p: &DVec2| ocs.to_wcs(*p, *elevation))
                .collect();
            let b = (!bulges.is_empty()).then(|| bulges.clone());
            crate::geom::polyline::Polyline::new(pts, b, *closed, Some(*normal))
                .map(Curve::Polyline)
        }
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => Curve::pline(
            points.clone(),
            *closed,
            (!bulges.is_empty()).then(|| bulges.clone()),
        ),
        EntityKind::Spline { curve, .. } => Ok(Curve::BSpline(curve.clone())),
        EntityKind::Ellipse {
            center,
            major,
            normal,
            ratio,
            start,
            end,
        } => crate::geom::ellipse::Ellipse::new(*center, *major, *ratio, *start, *end, *normal)
            .map(Curve::Ellipse),
        _ => return None,
    })
}

/// The curves of the entities queried last, with their measures: routines call vlax-curve
/// many times on one entity. An entry is used only while the entity is unchanged.
#[derive(Default)]
struct CurveCache(Vec<(u64, EntityKind, Rc<AcCurve>)>);

/// The curve an argument names: an entity name, a VLA entity or a CURVE value.
pub fn ac_curve(it: &mut Interp, v: &Value) -> Result<Rc<AcCurve>, Exn> {
    if let Some(c) = v.as_obj::<CurveValue>() {
        return Ok(Rc::new(AcCurve::new(c.0.clone())));
    }
    let handle = match v.as_obj::<Vla>() {
        Some(Vla::Entity(h, _)) => *h,
        Some(_) => return Err(bad_arg(it, "curvep", v)),
        None => ename_arg(it, v)?.handle,
    };
    let mut cache = std::mem::take(&mut it.ext::<CurveCache>().0);
    let d = it.ext::<Drawing>();
    let kind = match d.get(handle) {
        Some(e) if !d.is_deleted(handle) => &e.kind,
        _ => return Err(crate::lang::error::err("bad argument type: deleted entity")),
    };
    let hit = cache
        .iter()
        .find(|(h, k, _)| *h == handle && k == kind)
        .map(|(_, _, c)| c.clone());
    if let Some(c) = hit {
        it.ext::<CurveCache>().0 = cache;
        return Ok(c);
    }
    let kind = match it.ext::<Drawing>().get(handle) {
        Some(e) => e.kind.clone(),
        None => return Err(crate::lang::error::err("bad argument type: deleted entity")),
    };
    let c = entity_curve(&kind)
        .ok_or_else(|| bad_arg(it, "curvep", v))?
        .map_err(geom_err)?;
    let c = Rc::new(AcCurve::new(c));
    if cache.len() >= 4 {
        cache.remove(0);
    }
    cache.push((handle, kind, c.clone()));
    it.ext::<CurveCache>().0 = cache;
    Ok(c)
}

/// A point or vector as a list, without negative zeros (AutoCAD prints 0.0).
pub fn point3(p: DVec3) -> Value {
    crate::builtins::geometry::point3(p + DVec3::ZERO)
}

fn start_param(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(ac_curve(it, &a[0])?.lo))
}

fn end_param(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(ac_curve(it, &a[0])?.hi))
}

fn start_point(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(point3(ac_curve(it, &a[0])?.curve.eval(0.0)))
}

fn end_point(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(point3(ac_curve(it, &a[0])?.curve.eval(1.0)))
}

fn point_at_param(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let param = it.num(&a[1])?;
    Ok(c.t_of(param)
        .map_or(Value::Nil, |t| point3(c.curve.eval(t))))
}

/// The core parameter of a point on the curve, None when it is farther than the drawing
/// tolerance (GEOMTOL, relative to the curve's size) from it.
fn t_at_point(it: &mut Interp, c: &AcCurve, p: DVec3) -> Option<f64> {
    let (t, q) = c.curve.closest_point(p);
    let tol = geomtol(it) * p.abs().max_element().max(1.0) * 10.0;
    ((q - p).length() <= tol).then_some(t)
}

fn param_at_point(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let p = vec3(it, &a[1])?;
    Ok(t_at_point(it, &c, p).map_or(Value::Nil, |t| Value::Real(c.param_of(t))))
}

fn dist_at_param(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let param = it.num(&a[1])?;
    Ok(c.t_of(param)
        .map_or(Value::Nil, |t| Value::Real(c.measured().length_to(t))))
}

/// The core parameter at a length along the curve, None outside [0, length].
fn t_at_dist(c: &AcCurve, s: f64) -> Option<f64> {
    c.measured().param_at_length(s)
}

fn param_at_dist(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let s = it.num(&a[1])?;
    Ok(t_at_dist(&c, s).map_or(Value::Nil, |t| Value::Real(c.param_of(t))))
}

fn dist_at_point(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let p = vec3(it, &a[1])?;
    Ok(t_at_point(it, &c, p).map_or(Value::Nil, |t| Value::Real(c.measured().length_to(t))))
}

fn point_at_dist(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let s = it.num(&a[1])?;
    Ok(t_at_dist(&c, s).map_or(Value::Nil, |t| point3(c.curve.eval(t))))
}

/// The nearest point of the curve, or of its extension when `extend` (lines become infinite,
/// arcs full circles; other kinds are not extended).
fn nearest(c: &AcCurve, p: DVec3, extend: bool) -> DVec3 {
    if extend {
        match &c.curve {
            Curve::Line(l) => {
                let d = l.p1 - l.p0;
                return l.p0 + d * ((p - l.p0).dot(d) / d.length_squared());
            }
            Curve::Arc(a) => {
                if let Ok(full) = Curve::circle(a.center(), a.radius(), Some(a.normal())) {
                    return full.closest_point(p).1;
                }
            }
            _ => {}
        }
    }
    c.curve.closest_point(p).1
}

fn closest_point_to(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let p = vec3(it, &a[1])?;
    let extend = a.get(2).is_some_and(Value::truthy);
    Ok(point3(nearest(&c, p, extend)))
}

/// Nearest in the projection along `n`: for a planar curve seen along its normal, the
/// nearest point to the point dropped into its plane (exact); otherwise the distance
/// perpendicular to `n` is minimised over a dense sampling refined by golden sections.
fn closest_point_to_projection(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let p = vec3(it, &a[1])?;
    let n = vec3(it, &a[2])?
        .try_normalize()
        .ok_or_else(|| bad_arg(it, "non-zero vector", &a[2]))?;
    let extend = a.get(3).is_some_and(Value::truthy);
    let plane = c.curve.plane_normal();
    if let Some(pn) = plane.filter(|pn| pn.cross(n).length() < 1e-12) {
        let o = c.curve.eval(0.0);
        let dropped = p - pn * (p - o).dot(pn);
        return Ok(point3(nearest(&c, dropped, extend)));
    }
    if let (true, Curve::Line(l)) = (extend, &c.curve) {
        // Infinite line: minimise |⊥n (p0 + s d − p)| in closed form.
        let perp = |v: DVec3| v - n * v.dot(n);
        let (d, w) = (perp(l.p1 - l.p0), perp(p - l.p0));
        if d.length_squared() > 0.0 {
            return Ok(point3(
                l.p0 + (l.p1 - l.p0) * (w.dot(d) / d.length_squared()),
            ));
        }
    }
    let dist = |t: f64| {
        let v = c.curve.eval(t) - p;
        (v - n * v.dot(n)).length_squared()
    };
    const N: usize = 2048;
    let best = (0..=N)
        .map(|i| i as f64 / N as f64)
        .min_by(|x, y| dist(*x).total_cmp(&dist(*y)))
        .unwrap_or(0.0);
    let (mut lo, mut hi) = (
        (best - 1.0 / N as f64).max(0.0),
        (best + 1.0 / N as f64).min(1.0),
    );
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if dist(x1) < dist(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    Ok(point3(c.curve.eval(0.5 * (lo + hi))))
}

fn first_deriv(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let param = it.num(&a[1])?;
    let Some(t) = c.t_of(param) else {
        return Ok(Value::Nil);
    };
    let d = match &c.curve {
        Curve::BSpline(b) => {
            let (lo, hi) = b.domain();
            crate::geom::curve_measure::derivs_u(b, lo + (hi - lo) * t)[1]
        }
        Curve::Ellipse(e) => e.deriv_at_angle(param),
        _ => c.curve.deriv(t) / c.scale(),
    };
    Ok(point3(d))
}

fn second_deriv(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let param = it.num(&a[1])?;
    let Some(t) = c.t_of(param) else {
        return Ok(Value::Nil);
    };
    if let Curve::Ellipse(e) = &c.curve {
        return Ok(point3(e.second_deriv_at_angle(param)));
    }
    Ok(point3(c.curve.second_deriv(t) / (c.scale() * c.scale())))
}

/// The enclosed area; an open curve counts as closed by the chord from its end to its start
/// (AutoCAD's Area of an open polyline, spline or arc).
fn get_area(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    if let Curve::Line(_) = c.curve {
        return Ok(Value::Real(0.0));
    }
    if c.curve.is_closed() {
        return c.curve.area().map(Value::Real).map_err(geom_err);
    }
    let mut va: DVec3 = c.curve.spans().iter().map(|s| s.piece.vector_area()).sum();
    let (p0, p1) = (c.curve.eval(0.0), c.curve.eval(1.0));
    va += 0.5 * p1.cross(p0);
    Ok(Value::Real(va.length()))
}

fn is_closed(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(ac_curve(it, &a[0])?.curve.is_closed()))
}

fn is_periodic(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    let periodic = c.periodic
        || match &c.curve {
            Curve::Spline(q) => q.closed,
            Curve::BSpline(_) => c.curve.is_closed(),
            _ => false,
        };
    Ok(Value::bool(periodic))
}

fn is_planar(it: &mut Interp, a: &[Value]) -> LResult {
    let c = ac_curve(it, &a[0])?;
    Ok(Value::bool(
        matches!(c.curve, Curve::Line(_)) || c.curve.plane_normal().is_some(),
    ))
}

/// A CURVE value of an entity (for the object model's methods).
pub fn entity_curve_value(k: &EntityKind) -> Option<Value> {
    entity_curve(k).and_then(Result::ok).map(curve_value)
}
