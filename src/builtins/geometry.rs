//! Curves as Lisp values: constructors, queries, transforms and intersection, binding
//! `geom::Curve` (which knows nothing of the language) to the forms of SPEC §4.

use std::fmt;

use glam::{DMat4, DVec3};

use crate::builtin;
use crate::builtins::system::SysVars;
use crate::geom::curve::{xform, Curve};
use crate::geom::intersect::{intersect, intersect_near, HitKind};
use crate::geom::quadspline::QuadSpline;
use crate::geom::GeomError;
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::value::Object;
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("line", "(line p1 p2)", "A line segment from p1 to p2.", 2, 2, line),
    builtin!("circle", "(circle center radius [normal])", "A full circle (normal default (0 0 1)).", 2, 3, circle),
    builtin!("arc", "(arc center radius start-angle end-angle [normal])", "An arc CCW from start to end about the normal; angles from the X axis of the normal's arbitrary-axis frame (as DXF).", 4, 5, arc),
    builtin!("arc3", "(arc3 p1 p2 p3)", "The arc from p1 through p2 to p3.", 3, 3, arc3),
    builtin!("pline", "(pline points [closed] [bulges])", "A polyline; bulges: one per vertex, for the segment starting there (as LWPOLYLINE).", 1, 3, pline),
    builtin!("spline", "(spline points [closed])", "The C1 quadratic spline interpolating the points (the temple paper's spline).", 1, 2, spline),
    builtin!("ellipse", "(ellipse center major-axis ratio [start end] [normal])", "An ellipse or elliptical arc as DXF's ELLIPSE: major-axis vector from the centre, minor/major ratio in (0, 1], eccentric-angle start and end (default the full ellipse), normal default (0 0 1).", 3, 6, ellipse),
    builtin!("bspline", "(bspline control-points degree [knots] [weights])", "A B-spline or NURBS curve; knots: the full vector (default clamped uniform).", 2, 4, bspline),
    builtin!("curve-length", "(curve-length c)", "The length of a curve.", 1, 1, curve_length),
    builtin!("point-at", "(point-at c t)", "The point at parameter t in [0, 1].", 2, 2, point_at),
    builtin!("point-at-length", "(point-at-length c s)", "The point at arc length s from the start.", 2, 2, point_at_length),
    builtin!("tangent-at", "(tangent-at c t)", "The unit tangent at parameter t in [0, 1].", 2, 2, tangent_at),
    builtin!("closest-point", "(closest-point c p)", "The point of the curve closest to p.", 2, 2, closest_point),
    builtin!("curve-param", "(curve-param c p)", "The parameter in [0, 1] of the curve point closest to p.", 2, 2, curve_param),
    builtin!("curve-points", "(curve-points c tol)", "Points of a polyline within tol of the curve.", 2, 2, curve_points),
    builtin!("curve-closed-p", "(curve-closed-p c)", "T if the curve is closed.", 1, 1, curve_closed_p),
    builtin!("bbox", "(bbox v)", "The bounding box of a curve (or surface/mesh) as (min-point max-point).", 1, 1, bbox),
    builtin!("area", "(area closed-curve)", "The area enclosed by a closed planar curve.", 1, 1, area),
    builtin!("move", "(move v delta)", "The value moved by the vector delta.", 2, 2, move_),
    builtin!("rotate", "(rotate v base angle [axis])", "The value rotated by angle (radians, CCW) about an axis through base (default Z).", 3, 4, rotate),
    builtin!("scale", "(scale v base factor)", "The value scaled uniformly about base.", 3, 3, scale),
    builtin!("mirror", "(mirror v p1 p2)", "The value mirrored in the line p1-p2 (the vertical plane through it).", 3, 3, mirror),
    builtin!("offset", "(offset c d)", "A planar curve offset by d (positive: to the left of its direction).", 2, 2, offset),
    builtin!("intersect", "(intersect a b [near])", "All intersection points of two curves sorted along a (overlaps as curves), or the one nearest to near; nil if none.", 2, 3, intersect_fn),
    builtin!("intersect-info", "(intersect-info a b)", "One association list per hit: ((point . P) (t1 . u) (t2 . v) (kind . CROSS|TANGENT|OVERLAP)); against a surface t2 is nil.", 2, 2, intersect_info),
];

/// A curve value: `type` → CURVE.
pub struct CurveValue(pub Curve);

impl Object for CurveValue {
    fn type_name(&self) -> &'static str {
        "CURVE"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(f, "{}", self.0)
    }
    fn equal(&self, other: &dyn Object) -> bool {
        other
            .as_any()
            .downcast_ref::<CurveValue>()
            .is_some_and(|o| o.0 == self.0)
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

pub fn curve_value(c: Curve) -> Value {
    Value::obj(CurveValue(c))
}

pub fn geom_err(e: GeomError) -> Exn {
    err(e.to_string())
}

/// The drawing tolerance (GEOMTOL).
pub fn geomtol(it: &mut Interp) -> f64 {
    it.ext::<SysVars>().real("GEOMTOL")
}

pub fn vec3(it: &Interp, v: &Value) -> Result<DVec3, Exn> {
    it.point(v).map(DVec3::from_array)
}

/// A point as a 3D Lisp list.
pub fn point3(p: DVec3) -> Value {
    Value::list([Value::Real(p.x), Value::Real(p.y), Value::Real(p.z)])
}

pub fn points(it: &Interp, v: &Value) -> Result<Vec<DVec3>, Exn> {
    it.list_arg(v)?.iter().map(|p| vec3(it, p)).collect()
}

pub fn curve<'a>(it: &Interp, v: &'a Value) -> Result<&'a Curve, Exn> {
    v.as_obj::<CurveValue>()
        .map(|c| &c.0)
        .ok_or_else(|| bad_arg(it, "curvep", v))
}

fn numbers(it: &Interp, v: &Value) -> Result<Vec<f64>, Exn> {
    it.list_arg(v)?.iter().map(|x| it.num(x)).collect()
}

fn opt_normal(it: &Interp, a: &[Value], i: usize) -> Result<Option<DVec3>, Exn> {
    match a.get(i) {
        None | Some(Value::Nil) => Ok(None),
        Some(v) => vec3(it, v).map(Some),
    }
}

fn line(it: &mut Interp, a: &[Value]) -> LResult {
    let c = Curve::line(vec3(it, &a[0])?, vec3(it, &a[1])?).map_err(geom_err)?;
    Ok(curve_value(c))
}

fn circle(it: &mut Interp, a: &[Value]) -> LResult {
    let n = opt_normal(it, a, 2)?;
    let c = Curve::circle(vec3(it, &a[0])?, it.num(&a[1])?, n).map_err(geom_err)?;
    Ok(curve_value(c))
}

fn arc(it: &mut Interp, a: &[Value]) -> LResult {
    let n = opt_normal(it, a, 4)?;
    let c = Curve::arc(
        vec3(it, &a[0])?,
        it.num(&a[1])?,
        it.num(&a[2])?,
        it.num(&a[3])?,
        n,
    )
    .map_err(geom_err)?;
    Ok(curve_value(c))
}

fn ellipse(it: &mut Interp, a: &[Value]) -> LResult {
    let (start, end) = match (a.get(3), a.get(4)) {
        (Some(s), Some(e)) if s.truthy() || e.truthy() => (it.num(s)?, it.num(e)?),
        _ => (0.0, std::f64::consts::TAU),
    };
    let n = opt_normal(it, a, 5)?;
    let e = crate::geom::ellipse::Ellipse::new(
        vec3(it, &a[0])?,
        vec3(it, &a[1])?,
        it.num(&a[2])?,
        start,
        end,
        n.unwrap_or(DVec3::Z),
    )
    .map_err(geom_err)?;
    Ok(curve_value(Curve::Ellipse(e)))
}

fn arc3(it: &mut Interp, a: &[Value]) -> LResult {
    let c = Curve::arc3(vec3(it, &a[0])?, vec3(it, &a[1])?, vec3(it, &a[2])?).map_err(geom_err)?;
    Ok(curve_value(c))
}

fn pline(it: &mut Interp, a: &[Value]) -> LResult {
    let pts = points(it, &a[0])?;
    let closed = a.get(1).is_some_and(Value::truthy);
    let bulges = match a.get(2) {
        None | Some(Value::Nil) => None,
        Some(b) => Some(numbers(it, b)?),
    };
    Ok(curve_value(
        Curve::pline(pts, closed, bulges).map_err(geom_err)?,
    ))
}

fn spline(it: &mut Interp, a: &[Value]) -> LResult {
    let pts = points(it, &a[0])?;
    let closed = a.get(1).is_some_and(Value::truthy);
    let s = QuadSpline::interpolate(&pts, closed).map_err(|e| err(e.to_string()))?;
    Ok(curve_value(Curve::Spline(s)))
}

fn bspline(it: &mut Interp, a: &[Value]) -> LResult {
    let ctrl = points(it, &a[0])?;
    let degree = it.int(&a[1])?;
    if degree < 1 {
        return Err(err(format!(
            "bspline: degree must be at least 1, got {degree}"
        )));
    }
    let knots = match a.get(2) {
        None | Some(Value::Nil) => None,
        Some(k) => Some(numbers(it, k)?),
    };
    let weights = match a.get(3) {
        None | Some(Value::Nil) => None,
        Some(w) => Some(numbers(it, w)?),
    };
    let c = Curve::bspline(ctrl, degree as usize, knots, weights).map_err(geom_err)?;
    Ok(curve_value(c))
}

fn param(it: &Interp, v: &Value) -> Result<f64, Exn> {
    let t = it.num(v)?;
    if !(0.0..=1.0).contains(&t) {
        return Err(err(format!("curve parameter must be in [0, 1], got {t}")));
    }
    Ok(t)
}

fn curve_length(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(curve(it, &a[0])?.length()))
}

fn point_at(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    Ok(point3(c.eval(param(it, &a[1])?)))
}

fn point_at_length(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    let s = it.num(&a[1])?;
    Ok(point3(c.point_at_length(s).map_err(geom_err)?))
}

fn tangent_at(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    Ok(point3(c.tangent(param(it, &a[1])?)))
}

fn closest_point(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    Ok(point3(c.closest_point(vec3(it, &a[1])?).1))
}

fn curve_param(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    Ok(Value::Real(c.closest_point(vec3(it, &a[1])?).0))
}

fn curve_points(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    let tol = it.num(&a[1])?;
    if !(tol > 0.0 && tol.is_finite()) {
        return Err(err(format!(
            "curve-points: tolerance must be > 0, got {tol}"
        )));
    }
    let pts = c.points(tol).map_err(geom_err)?;
    Ok(Value::list(pts.into_iter().map(point3).collect::<Vec<_>>()))
}

fn curve_closed_p(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(curve(it, &a[0])?.is_closed()))
}

fn bbox(it: &mut Interp, a: &[Value]) -> LResult {
    if let Some(b) = crate::builtins::surfaces::bbox_of(it, &a[0]) {
        let (lo, hi) = b?;
        return Ok(Value::list([point3(lo), point3(hi)]));
    }
    let (lo, hi) = curve(it, &a[0])?.bbox();
    Ok(Value::list([point3(lo), point3(hi)]))
}

fn area(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(curve(it, &a[0])?.area().map_err(geom_err)?))
}

/// Applies a transform to a curve, a surface or mesh, or a point.
fn transform(it: &mut Interp, v: &Value, m: DMat4) -> LResult {
    if let Some(c) = v.as_obj::<CurveValue>() {
        return Ok(curve_value(c.0.transform(&m).map_err(geom_err)?));
    }
    if let Some(r) = crate::builtins::surfaces::transform(it, v, &m) {
        return r;
    }
    if matches!(v, Value::Cons(_)) && it.point(v).is_ok() {
        let dim = Interp::point_dim(v);
        let p = m.transform_point3(vec3(it, v)?);
        return Ok(crate::lang::builtin::point_value(p.to_array(), dim));
    }
    if v.is_list() {
        let items: Vec<Value> = v.iter().cloned().collect();
        let mut out = Vec::with_capacity(items.len());
        for x in &items {
            out.push(transform(it, x, m)?);
        }
        return Ok(Value::list(out));
    }
    Err(bad_arg(it, "curvep", v))
}

fn move_(it: &mut Interp, a: &[Value]) -> LResult {
    let m = xform::translate(vec3(it, &a[1])?);
    transform(it, &a[0], m)
}

fn rotate(it: &mut Interp, a: &[Value]) -> LResult {
    let axis = opt_normal(it, a, 3)?;
    let m = xform::rotate(vec3(it, &a[1])?, it.num(&a[2])?, axis).map_err(geom_err)?;
    transform(it, &a[0], m)
}

fn scale(it: &mut Interp, a: &[Value]) -> LResult {
    let m = xform::scale(vec3(it, &a[1])?, it.num(&a[2])?).map_err(geom_err)?;
    transform(it, &a[0], m)
}

fn mirror(it: &mut Interp, a: &[Value]) -> LResult {
    let m = xform::mirror(vec3(it, &a[1])?, vec3(it, &a[2])?).map_err(geom_err)?;
    transform(it, &a[0], m)
}

fn offset(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    let d = it.num(&a[1])?;
    Ok(curve_value(c.offset(d).map_err(geom_err)?))
}

fn intersect_fn(it: &mut Interp, a: &[Value]) -> LResult {
    if crate::builtins::surfaces::is_surface(&a[1]) {
        return crate::builtins::surfaces::intersect_curve_surface(it, a);
    }
    let tol = geomtol(it);
    let (c1, c2) = (curve(it, &a[0])?, curve(it, &a[1])?);
    let hits = intersect(c1, c2, tol);
    if let Some(near) = a.get(2).filter(|v| v.truthy()) {
        let near = vec3(it, near)?;
        return Ok(intersect_near(&hits, near).map_or(Value::Nil, point3));
    }
    Ok(Value::list(
        hits.into_iter()
            .map(|h| match h.kind {
                HitKind::Overlap(c) => curve_value(*c),
                _ => point3(h.point),
            })
            .collect::<Vec<_>>(),
    ))
}

fn intersect_info(it: &mut Interp, a: &[Value]) -> LResult {
    if crate::builtins::surfaces::is_surface(&a[1]) {
        return crate::builtins::surfaces::intersect_info_curve_surface(it, a);
    }
    let tol = geomtol(it);
    let (c1, c2) = (curve(it, &a[0])?, curve(it, &a[1])?);
    let hits = intersect(c1, c2, tol);
    let mut out = Vec::with_capacity(hits.len());
    for h in hits {
        let kind = h.kind_name();
        let mut fields = vec![
            Value::cons(Value::Sym(it.intern("POINT")), point3(h.point)),
            Value::cons(Value::Sym(it.intern("T1")), Value::Real(h.t1)),
            Value::cons(Value::Sym(it.intern("T2")), Value::Real(h.t2)),
            Value::cons(Value::Sym(it.intern("KIND")), Value::Sym(it.intern(kind))),
        ];
        if let HitKind::Overlap(c) = h.kind {
            fields.push(Value::cons(Value::Sym(it.intern("CURVE")), curve_value(*c)));
        }
        out.push(Value::list(fields));
    }
    Ok(Value::list(out))
}
