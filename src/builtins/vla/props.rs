//! Properties of VLA objects: read from and written to the drawing each time. `Prop` is the
//! neutral form; `vla-get-*`/`vlax-get-property` hand points out as variants, `vlax-get` as
//! lists (AutoCAD's two conventions).

use glam::{DVec2, DVec3};

use crate::builtins::system::SysVars;
use crate::lang::error::{err, Exn};
use crate::lang::{Interp, Value};
use crate::output::entity::{Entity, EntityKind};
use crate::output::Drawing;

use super::curve::entity_curve;
use super::variant::{coord_points, doubles_variant, point_arg, to_lisp, vlax_bool};
use super::{entity_class, Vla};

/// A property value before it is given its Lisp form.
pub enum Prop {
    Real(f64),
    Int(i32),
    Str(String),
    Bool(bool),
    Point(DVec3),
    /// A flat coordinate list (LWPOLYLINE: x y pairs; others x y z triples).
    Coords(Vec<f64>),
    Obj(Vla),
}

/// ActiveX's "unknown name" error for a property or method an object lacks.
pub fn unknown_name(name: &str) -> Exn {
    err(format!(
        "ActiveX Server returned the error: unknown name: {name}"
    ))
}

/// The property as `vla-get-*` returns it (points as variants, booleans as :vlax-true).
pub fn prop_value(it: &mut Interp, p: Prop) -> Value {
    match p {
        Prop::Real(r) => Value::Real(r),
        Prop::Int(i) => Value::Int(i),
        Prop::Str(s) => Value::str(&s),
        Prop::Bool(b) => vlax_bool(it, b),
        Prop::Point(p) => doubles_variant(&p.to_array()),
        Prop::Coords(c) => doubles_variant(&c),
        Prop::Obj(o) => super::vla_value(it, o),
    }
}

/// The property as `vlax-get` returns it (points as lists, booleans as -1/0).
pub fn prop_lisp(it: &mut Interp, p: Prop) -> Value {
    match p {
        Prop::Bool(b) => Value::Int(if b { -1 } else { 0 }),
        Prop::Point(p) => crate::builtins::geometry::point3(p),
        Prop::Coords(c) => Value::list(c.into_iter().map(Value::Real).collect::<Vec<_>>()),
        other => prop_value(it, other),
    }
}

fn entity(it: &mut Interp, h: u64) -> Result<Entity, Exn> {
    let d = it.ext::<Drawing>();
    match d.get(h) {
        Some(e) if !d.is_deleted(h) => Ok(e.clone()),
        _ => Err(err("Automation Error. Object was erased")),
    }
}

/// The value of a property, or the unknown-name error.
pub fn get(it: &mut Interp, obj: &Vla, name: &str) -> Result<Prop, Exn> {
    let key = name.to_ascii_uppercase();
    let p = match obj {
        Vla::Application => match key.as_str() {
            "ACTIVEDOCUMENT" => Some(Prop::Obj(Vla::Document)),
            "NAME" => Some(Prop::Str("AutoCAD".into())),
            "VERSION" => Some(Prop::Str("24.3s (lispcad)".into())),
            _ => None,
        },
        Vla::Document => match key.as_str() {
            "MODELSPACE" => Some(Prop::Obj(Vla::ModelSpace)),
            "PAPERSPACE" => Some(Prop::Obj(Vla::PaperSpace)),
            "LAYERS" => Some(Prop::Obj(Vla::Layers)),
            "BLOCKS" => Some(Prop::Obj(Vla::Blocks)),
            "APPLICATION" => Some(Prop::Obj(Vla::Application)),
            "ACTIVELAYER" => {
                let l = it.ext::<Drawing>().current_layer().to_string();
                Some(Prop::Obj(Vla::Layer(l)))
            }
            "NAME" | "FULLNAME" | "PATH" => {
                let v = it.ext::<SysVars>();
                let name = v.get("DWGNAME").and_then(Value::as_str).unwrap_or("");
                let dir = v.get("DWGPREFIX").and_then(Value::as_str).unwrap_or("");
                Some(Prop::Str(match key.as_str() {
                    "NAME" => name.to_string(),
                    "PATH" => dir.trim_end_matches('/').to_string(),
                    _ => format!("{dir}{name}"),
                }))
            }
            _ => None,
        },
        Vla::ModelSpace | Vla::PaperSpace | Vla::Block(_) => match key.as_str() {
            "COUNT" => Some(Prop::Int(space_members(it, obj).len() as i32)),
            "NAME" => Some(Prop::Str(match obj {
                Vla::ModelSpace => "*Model_Space".into(),
                Vla::PaperSpace => "*Paper_Space".into(),
                Vla::Block(n) => n.clone(),
                _ => unreachable!("a space"),
            })),
            "ISLAYOUT" => Some(Prop::Bool(!matches!(obj, Vla::Block(_)))),
            _ => None,
        },
        Vla::Layers => match key.as_str() {
            "COUNT" => Some(Prop::Int(it.ext::<Drawing>().layers().len() as i32)),
            _ => None,
        },
        Vla::Blocks => match key.as_str() {
            "COUNT" => Some(Prop::Int(2)),
            _ => None,
        },
        Vla::Layer(n) => {
            let d = it.ext::<Drawing>();
            let l = d
                .layer(n)
                .ok_or_else(|| err("Automation Error. Object was erased"))?;
            match key.as_str() {
                "NAME" => Some(Prop::Str(l.name.clone())),
                "COLOR" => Some(Prop::Int(l.color.abs() as i32)),
                "LAYERON" => Some(Prop::Bool(!l.is_off())),
                "FREEZE" => Some(Prop::Bool(l.frozen)),
                "LOCK" => Some(Prop::Bool(l.locked)),
                "LINETYPE" => Some(Prop::Str(l.linetype.clone())),
                "OBJECTNAME" => Some(Prop::Str("AcDbLayerTableRecord".into())),
                _ => None,
            }
        }
        Vla::Entity(h, _) => {
            let e = entity(it, *h)?;
            entity_prop(&e, &key)?
        }
    };
    p.ok_or_else(|| unknown_name(name))
}

/// The handles an entity collection holds (model space holds every entity headless; paper
/// space and other blocks are empty).
pub fn space_members(it: &mut Interp, obj: &Vla) -> Vec<u64> {
    match obj {
        Vla::ModelSpace => it.ext::<Drawing>().entities().map(|e| e.handle).collect(),
        _ => Vec::new(),
    }
}

fn lw_coords(points: &[DVec2]) -> Vec<f64> {
    points.iter().flat_map(|p| [p.x, p.y]).collect()
}

fn entity_prop(e: &Entity, key: &str) -> Result<Option<Prop>, Exn> {
    let (_, object_name) = entity_class(&e.kind);
    let common = match key {
        "OBJECTNAME" => Some(Prop::Str(object_name.into())),
        "HANDLE" => Some(Prop::Str(format!("{:X}", e.handle))),
        "LAYER" => Some(Prop::Str(e.layer.clone())),
        "COLOR" => Some(Prop::Int(e.color.map_or(256, i32::from))),
        "LINETYPE" => Some(Prop::Str("ByLayer".into())),
        "LINETYPESCALE" => Some(Prop::Real(1.0)),
        "LINEWEIGHT" => Some(Prop::Int(-1)),
        "VISIBLE" => Some(Prop::Bool(true)),
        "OWNERID" | "OBJECTID" => Some(Prop::Int(e.handle as i32)),
        "ENTITYTYPE" => Some(Prop::Int(0)),
        "DOCUMENT" => Some(Prop::Obj(Vla::Document)),
        _ => None,
    };
    if common.is_some() {
        return Ok(common);
    }
    let curve = entity_curve(&e.kind).and_then(Result::ok);
    let measure = |c: &crate::geom::Curve| match key {
        "LENGTH" if !matches!(e.kind, EntityKind::Arc { .. } | EntityKind::Circle { .. }) => {
            Some(Prop::Real(c.length()))
        }
        "AREA" => Some(Prop::Real(curve_area(c))),
        "CLOSED" => Some(Prop::Bool(c.is_closed())),
        _ => None,
    };
    Ok(match (&e.kind, key) {
        (EntityKind::Line { p0, .. }, "STARTPOINT") => Some(Prop::Point(*p0)),
        (EntityKind::Line { p1, .. }, "ENDPOINT") => Some(Prop::Point(*p1)),
        (EntityKind::Line { p0, p1 }, "DELTA") => Some(Prop::Point(*p1 - *p0)),
        (EntityKind::Line { p0, p1 }, "ANGLE") => Some(Prop::Real(crate::geom::arc::norm_angle(
            (p1.y - p0.y).atan2(p1.x - p0.x),
        ))),
        (EntityKind::Line { .. }, "THICKNESS") => Some(Prop::Real(0.0)),
        (EntityKind::Line { .. }, "NORMAL") => Some(Prop::Point(DVec3::Z)),
        (EntityKind::Line { .. }, "LENGTH") => curve.as_ref().and_then(measure),
        (EntityKind::Circle { center, .. } | EntityKind::Arc { center, .. }, "CENTER") => {
            Some(Prop::Point(*center))
        }
        (EntityKind::Circle { radius, .. } | EntityKind::Arc { radius, .. }, "RADIUS") => {
            Some(Prop::Real(*radius))
        }
        (EntityKind::Circle { normal, .. } | EntityKind::Arc { normal, .. }, "NORMAL") => {
            Some(Prop::Point(*normal))
        }
        (EntityKind::Circle { radius, .. }, "DIAMETER") => Some(Prop::Real(2.0 * radius)),
        (EntityKind::Circle { radius, .. }, "CIRCUMFERENCE") => {
            Some(Prop::Real(std::f64::consts::TAU * radius))
        }
        (EntityKind::Circle { radius, .. }, "AREA") => {
            Some(Prop::Real(std::f64::consts::PI * radius * radius))
        }
        (EntityKind::Arc { start, .. }, "STARTANGLE") => Some(Prop::Real(*start)),
        (EntityKind::Arc { end, .. }, "ENDANGLE") => Some(Prop::Real(*end)),
        (EntityKind::Arc { start, end, .. }, "TOTALANGLE") => {
            Some(Prop::Real(crate::output::entity::ccw_sweep(*start, *end)))
        }
        (EntityKind::Arc { .. }, "STARTPOINT") => curve.map(|c| Prop::Point(c.eval(0.0))),
        (EntityKind::Arc { .. }, "ENDPOINT") => curve.map(|c| Prop::Point(c.eval(1.0))),
        (EntityKind::Arc { .. }, "ARCLENGTH") => curve.map(|c| Prop::Real(c.length())),
        (EntityKind::Arc { .. }, "AREA") => curve.as_ref().and_then(measure),
        (EntityKind::LwPolyline { points, .. }, "COORDINATES") => {
            Some(Prop::Coords(lw_coords(points)))
        }
        (EntityKind::LwPolyline { elevation, .. }, "ELEVATION") => Some(Prop::Real(*elevation)),
        (EntityKind::LwPolyline { normal, .. }, "NORMAL") => Some(Prop::Point(*normal)),
        (EntityKind::LwPolyline { .. }, "CONSTANTWIDTH") => Some(Prop::Real(0.0)),
        (EntityKind::Polyline { points, .. }, "COORDINATES") => Some(Prop::Coords(
            points.iter().flat_map(|p| p.to_array()).collect(),
        )),
        (EntityKind::LwPolyline { .. } | EntityKind::Polyline { .. }, _) => {
            curve.as_ref().and_then(measure)
        }
        (EntityKind::Spline { curve: b, .. }, "DEGREE") => Some(Prop::Int(b.degree as i32)),
        (EntityKind::Spline { curve: b, .. }, "NUMBEROFCONTROLPOINTS") => {
            Some(Prop::Int(b.ctrl.len() as i32))
        }
        (EntityKind::Spline { fit_points, .. }, "NUMBEROFFITPOINTS") => {
            Some(Prop::Int(fit_points.len() as i32))
        }
        (EntityKind::Spline { curve: b, .. }, "CONTROLPOINTS") => Some(Prop::Coords(
            b.ctrl.iter().flat_map(|p| p.to_array()).collect(),
        )),
        (EntityKind::Spline { fit_points, .. }, "FITPOINTS") => Some(Prop::Coords(
            fit_points.iter().flat_map(|p| p.to_array()).collect(),
        )),
        (EntityKind::Spline { curve: b, .. }, "KNOTS") => Some(Prop::Coords(b.knots.clone())),
        (EntityKind::Spline { curve: b, .. }, "WEIGHTS") => Some(Prop::Coords(
            b.weights.clone().unwrap_or_else(|| vec![1.0; b.ctrl.len()]),
        )),
        (EntityKind::Spline { curve: b, .. }, "ISRATIONAL") => {
            Some(Prop::Bool(b.weights.is_some()))
        }
        (EntityKind::Spline { .. }, _) => curve.as_ref().and_then(measure),
        (EntityKind::Point { p }, "COORDINATES") => Some(Prop::Point(*p)),
        (EntityKind::Text { insert, .. }, "INSERTIONPOINT") => Some(Prop::Point(*insert)),
        (EntityKind::Text { value, .. }, "TEXTSTRING") => Some(Prop::Str(value.clone())),
        (EntityKind::Text { height, .. }, "HEIGHT") => Some(Prop::Real(*height)),
        (EntityKind::Text { rotation, .. }, "ROTATION") => Some(Prop::Real(*rotation)),
        (EntityKind::Text { style, .. }, "STYLENAME") => Some(Prop::Str(style.clone())),
        _ => None,
    })
}

/// The area as AutoCAD's Area property gives it: closed curves enclose, open ones count as
/// closed by their chord.
pub fn curve_area(c: &crate::geom::Curve) -> f64 {
    if let crate::geom::Curve::Line(_) = c {
        return 0.0;
    }
    if c.is_closed() {
        return c.area().unwrap_or(0.0);
    }
    let va: DVec3 = c.spans().iter().map(|s| s.piece.vector_area()).sum();
    (va + 0.5 * c.eval(1.0).cross(c.eval(0.0))).length()
}

fn real(it: &Interp, v: &Value) -> Result<f64, Exn> {
    it.num(v)
}

fn flag(it: &Interp, v: &Value) -> bool {
    match v {
        Value::Int(i) => *i != 0,
        Value::Sym(s) => it.syms.name(*s) != ":VLAX-FALSE",
        other => other.truthy(),
    }
}

/// Sets a property, or the unknown-name / rejected-value error.
pub fn put(it: &mut Interp, obj: &Vla, name: &str, v: &Value) -> Result<(), Exn> {
    let key = name.to_ascii_uppercase();
    let v = to_lisp(it, v);
    match obj {
        Vla::Layer(n) => return put_layer(it, n, &key, &v, name),
        Vla::Entity(h, _) => {
            let mut e = entity(it, *h)?;
            put_entity(it, &mut e, &key, &v, name)?;
            return it
                .ext::<Drawing>()
                .replace(*h, e)
                .map_err(|e| err(format!("ActiveX Server returned an error: {e}")));
        }
        Vla::Document if key == "ACTIVELAYER" => {
            if let Some(Vla::Layer(l)) = v.as_obj::<Vla>() {
                let l = l.clone();
                return it
                    .ext::<Drawing>()
                    .use_layer(&l, None)
                    .map_err(|e| err(e.to_string()));
            }
            return Err(crate::lang::builtin::bad_arg(it, "VLA-OBJECT", &v));
        }
        _ => {}
    }
    Err(unknown_name(name))
}

fn put_layer(it: &mut Interp, n: &str, key: &str, v: &Value, name: &str) -> Result<(), Exn> {
    let on = flag(it, v);
    let color = if key == "COLOR" {
        Some(it.int(v)?)
    } else {
        None
    };
    let d = it.ext::<Drawing>();
    let l = d
        .layer_mut(n)
        .ok_or_else(|| err("Automation Error. Object was erased"))?;
    match key {
        "COLOR" => {
            let c = color.unwrap_or(7);
            if !(1..=255).contains(&c) {
                return Err(err("ActiveX Server returned an error: Invalid input"));
            }
            l.color = if l.color < 0 { -(c as i16) } else { c as i16 };
        }
        "LAYERON" => l.color = if on { l.color.abs() } else { -l.color.abs() },
        "FREEZE" => l.frozen = on,
        "LOCK" => l.locked = on,
        _ => return Err(unknown_name(name)),
    }
    Ok(())
}

fn put_entity(
    it: &mut Interp,
    e: &mut Entity,
    key: &str,
    v: &Value,
    name: &str,
) -> Result<(), Exn> {
    match key {
        "LAYER" => {
            let l = it.string(v)?.to_string();
            if it.ext::<Drawing>().layer(&l).is_none() {
                return Err(err("ActiveX Server returned an error: Key not found"));
            }
            e.layer = l;
            return Ok(());
        }
        "COLOR" => {
            let c = it.int(v)?;
            e.color = match c {
                256 => None,
                0..=255 => Some(c as i16),
                _ => return Err(err("ActiveX Server returned an error: Invalid input")),
            };
            return Ok(());
        }
        _ => {}
    }
    match (&mut e.kind, key) {
        (EntityKind::Line { p0, .. }, "STARTPOINT") => *p0 = point_arg(it, v)?,
        (EntityKind::Line { p1, .. }, "ENDPOINT") => *p1 = point_arg(it, v)?,
        (EntityKind::Circle { center, .. } | EntityKind::Arc { center, .. }, "CENTER") => {
            *center = point_arg(it, v)?
        }
        (EntityKind::Circle { radius, .. } | EntityKind::Arc { radius, .. }, "RADIUS") => {
            *radius = real(it, v)?
        }
        (EntityKind::Circle { radius, .. }, "DIAMETER") => *radius = real(it, v)? / 2.0,
        (EntityKind::Arc { start, .. }, "STARTANGLE") => *start = real(it, v)?,
        (EntityKind::Arc { end, .. }, "ENDANGLE") => *end = real(it, v)?,
        (EntityKind::LwPolyline { points, bulges, .. }, "COORDINATES") => {
            *points = coord_points(it, v, 2)?
                .iter()
                .map(|p| p.truncate())
                .collect();
            bulges.resize(points.len(), 0.0);
        }
        (EntityKind::Polyline { points, bulges, .. }, "COORDINATES") => {
            *points = coord_points(it, v, 3)?;
            bulges.resize(points.len(), 0.0);
        }
        (
            EntityKind::LwPolyline { closed, .. }
            | EntityKind::Polyline { closed, .. }
            | EntityKind::Spline { closed, .. },
            "CLOSED",
        ) => *closed = flag(it, v),
        (EntityKind::LwPolyline { elevation, .. }, "ELEVATION") => *elevation = real(it, v)?,
        (EntityKind::Point { p }, "COORDINATES") => *p = point_arg(it, v)?,
        (EntityKind::Text { insert, .. }, "INSERTIONPOINT") => *insert = point_arg(it, v)?,
        (EntityKind::Text { value, .. }, "TEXTSTRING") => *value = it.string(v)?.to_string(),
        (EntityKind::Text { height, .. }, "HEIGHT") => *height = real(it, v)?,
        (EntityKind::Text { rotation, .. }, "ROTATION") => *rotation = real(it, v)?,
        (EntityKind::Text { style, .. }, "STYLENAME") => *style = it.string(v)?.to_string(),
        _ => return Err(unknown_name(name)),
    }
    e.kind
        .validate()
        .map_err(|e| err(format!("ActiveX Server returned an error: {e}")))
}
