//! Entities as DXF association lists, in the groups and order AutoCAD's `entget` gives
//! (AutoCAD DXF Reference, ENTITIES section), and the group access `entmake`/`entmod` parse with.

use glam::{DVec2, DVec3};

use super::{ename_value, name_value, Ename};
use crate::geom::frame::Ocs;
use crate::lang::error::{err, Exn};
use crate::lang::{Interp, Value};
use crate::output::{Drawing, Entity, EntityKind};

/// The handle of the model-space block record in the DXF writer: the owner (330) of every
/// entity.
pub const MODEL_SPACE_RECORD: u64 = 0xF;

pub fn pair(code: i32, v: Value) -> Value {
    Value::cons(Value::Int(code), v)
}

pub fn real(code: i32, x: f64) -> Value {
    pair(code, Value::Real(x))
}

pub fn int(code: i32, x: i32) -> Value {
    pair(code, Value::Int(x))
}

pub fn text(code: i32, s: &str) -> Value {
    pair(code, Value::str(s))
}

pub fn pt3(code: i32, p: DVec3) -> Value {
    pair(
        code,
        Value::list([Value::Real(p.x), Value::Real(p.y), Value::Real(p.z)]),
    )
}

pub fn pt2(code: i32, p: DVec2) -> Value {
    pair(code, Value::list([Value::Real(p.x), Value::Real(p.y)]))
}

/// Whether a POLYLINE's points leave one plane of constant Z (written as a 3D polyline).
pub fn is_3d(points: &[DVec3]) -> bool {
    points.first().is_some_and(|p0| {
        points
            .iter()
            .any(|p| (p.z - p0.z).abs() > 1e-12 * (1.0 + p0.z.abs()))
    })
}

/// The groups every entity starts with: name, type, owner, handle, space, layer, colour.
fn head(out: &mut Vec<Value>, name: Value, type_name: &str, owner: Value, handle: Option<u64>) {
    out.push(pair(-1, name));
    out.push(text(0, type_name));
    out.push(pair(330, owner));
    if let Some(h) = handle {
        out.push(text(5, &format!("{h:X}")));
    }
    out.push(text(100, "AcDbEntity"));
    out.push(int(67, 0));
    out.push(text(410, "Model"));
}

/// DXF makes an arc a subclass of a circle, so both lists start with the same group.
fn circle_part(out: &mut Vec<Value>, center: DVec3, radius: f64, normal: DVec3) {
    out.push(text(100, "AcDbCircle"));
    out.push(pt3(10, Ocs::new(normal).wcs_to_ocs(center)));
    out.push(real(40, radius));
    out.push(pt3(210, normal.normalize()));
}

/// CHPROP's line type (after the layer), weight and line-type scale (after the colour).
fn entity_props(out: &mut Vec<Value>, p: &crate::output::props::EntityProps) {
    // BYLAYER is what an entity without a 6 group has: entget leaves it out, as AutoCAD's.
    if let Some(lt) = p
        .linetype
        .as_ref()
        .filter(|l| !l.eq_ignore_ascii_case("ByLayer"))
    {
        let at =
            out.len() - usize::from(out.last().is_some_and(|g| g.car().as_f64() == Some(62.0)));
        out.insert(at, text(6, lt));
    }
    if let Some(w) = p.lineweight.filter(|w| *w != -1) {
        out.push(int(370, w as i32));
    }
    if let Some(s) = p.ltscale.filter(|s| *s != 1.0) {
        out.push(real(48, s));
    }
}

/// The thickness CHPROP set: replaces the list's 39 group, or follows its subclass marker.
fn with_thickness(out: &mut Vec<Value>, t: f64) {
    if let Some(g) = out.iter_mut().find(|g| g.car().as_f64() == Some(39.0)) {
        *g = real(39, t);
        return;
    }
    let marker = out
        .iter()
        .enumerate()
        .filter(|(_, g)| g.car().as_f64() == Some(100.0))
        .nth(1)
        .map(|(i, _)| i + 1);
    if let Some(i) = marker {
        out.insert(i, real(39, t));
    }
}

fn layer_color(out: &mut Vec<Value>, e: &Entity) {
    out.push(text(8, &e.layer));
    if let Some(c) = e.color {
        out.push(int(62, c as i32));
    }
}

/// The `entget` list of the entity or sub-entity named `name`; `None` if it is not live.
pub fn entity_list(it: &mut Interp, name: Ename) -> Option<Value> {
    let me = name_value(it, name);
    let parent = ename_value(it, name.handle);
    let space = ename_value(it, MODEL_SPACE_RECORD);
    let d: &Drawing = it.ext::<Drawing>();
    let Some(e) = d.get(name.handle) else {
        if name.sub != 0 || d.is_deleted(name.handle) {
            return None;
        }
        return super::objects::record_list(it, name.handle, me);
    };
    if let EntityKind::Unmodelled { .. } = e.kind {
        let tags = d.source(name.handle)?.tags.clone();
        let (layer, color) = (e.layer.clone(), e.color);
        return super::tag_list::tags_entity_list(it, &tags, name.sub as usize, me, &layer, color);
    }
    let mut out = Vec::with_capacity(24);
    if name.sub != 0 {
        sub_entity_list(&mut out, e, name, me, parent)?;
        return Some(Value::list(out));
    }
    head(&mut out, me, e.kind.type_name(), space, Some(e.handle));
    layer_color(&mut out, e);
    let props = d.props(e.handle).cloned();
    if let Some(p) = &props {
        entity_props(&mut out, p);
    }
    match &e.kind {
        EntityKind::Line { p0, p1 } => {
            out.push(text(100, "AcDbLine"));
            out.push(pt3(10, *p0));
            out.push(pt3(11, *p1));
            out.push(pt3(210, DVec3::Z));
        }
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => circle_part(&mut out, *center, *radius, *normal),
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            circle_part(&mut out, *center, *radius, *normal);
            out.push(text(100, "AcDbArc"));
            out.push(real(50, *start));
            out.push(real(51, *end));
        }
        EntityKind::Point { p } => {
            out.push(text(100, "AcDbPoint"));
            out.push(pt3(10, *p));
            out.push(pt3(210, DVec3::Z));
            out.push(real(50, 0.0));
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            out.push(text(100, "AcDbPolyline"));
            out.push(int(90, points.len() as i32));
            out.push(int(70, i32::from(*closed)));
            out.push(real(43, 0.0));
            out.push(real(38, *elevation));
            out.push(real(39, 0.0));
            for (i, p) in points.iter().enumerate() {
                out.push(pt2(10, *p));
                out.push(real(40, 0.0));
                out.push(real(41, 0.0));
                out.push(real(42, bulges.get(i).copied().unwrap_or(0.0)));
                out.push(int(91, 0));
            }
            out.push(pt3(210, normal.normalize()));
        }
        EntityKind::Polyline { points, closed, .. } => {
            let three_d = is_3d(points);
            out.push(text(
                100,
                if three_d {
                    "AcDb3dPolyline"
                } else {
                    "AcDb2dPolyline"
                },
            ));
            out.push(int(66, 1));
            let z = if three_d { 0.0 } else { points[0].z };
            out.push(pt3(10, DVec3::new(0.0, 0.0, z)));
            out.push(int(70, i32::from(*closed) | if three_d { 8 } else { 0 }));
            out.push(real(40, 0.0));
            out.push(real(41, 0.0));
            out.push(pt3(210, DVec3::Z));
            for c in 71..=75 {
                out.push(int(c, 0));
            }
        }
        EntityKind::Spline {
            curve,
            fit_points,
            closed,
        } => {
            out.push(text(100, "AcDbSpline"));
            let planar = curve
                .ctrl
                .iter()
                .all(|p| (p.z - curve.ctrl[0].z).abs() < 1e-12);
            if planar {
                out.push(pt3(210, DVec3::Z));
            }
            let flags = i32::from(*closed)
                | if curve.is_rational() { 4 } else { 0 }
                | if planar { 8 } else { 0 };
            out.push(int(70, flags));
            out.push(int(71, curve.degree as i32));
            out.push(int(72, curve.knots.len() as i32));
            out.push(int(73, curve.ctrl.len() as i32));
            out.push(int(74, fit_points.len() as i32));
            out.push(real(42, 1e-10));
            out.push(real(43, 1e-10));
            if !fit_points.is_empty() {
                out.push(real(44, 1e-10));
            }
            for k in &curve.knots {
                out.push(real(40, *k));
            }
            for (i, p) in curve.ctrl.iter().enumerate() {
                out.push(pt3(10, *p));
                if let Some(w) = &curve.weights {
                    out.push(real(41, w[i]));
                }
            }
            for p in fit_points {
                out.push(pt3(11, *p));
            }
        }
        EntityKind::Face3d { corners } => {
            out.push(text(100, "AcDbFace"));
            for (i, c) in corners.iter().enumerate() {
                out.push(pt3(10 + i as i32, *c));
            }
            out.push(int(70, 0));
        }
        EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            style,
        } => {
            out.push(text(100, "AcDbText"));
            out.push(pt3(10, *insert));
            out.push(real(40, *height));
            out.push(text(1, value));
            out.push(real(50, *rotation));
            out.push(real(41, 1.0));
            out.push(real(51, 0.0));
            out.push(text(7, style));
            out.push(int(71, 0));
            out.push(int(72, 0));
            out.push(pt3(11, DVec3::ZERO));
            out.push(pt3(210, DVec3::Z));
            out.push(text(100, "AcDbText"));
            out.push(int(73, 0));
        }
        EntityKind::Ellipse {
            center,
            major,
            normal,
            ratio,
            start,
            end,
        } => {
            out.push(text(100, "AcDbEllipse"));
            out.push(pt3(10, *center));
            out.push(pt3(11, *major));
            out.push(pt3(210, normal.normalize()));
            out.push(real(40, *ratio));
            out.push(real(41, *start));
            out.push(real(42, *end));
        }
        EntityKind::Unmodelled { .. } => {}
        EntityKind::Mesh {
            vertices,
            triangles,
        } => {
            out.push(text(100, "AcDbSubDMesh"));
            out.push(int(71, 2));
            out.push(int(72, 0));
            out.push(int(91, 0));
            out.push(int(92, vertices.len() as i32));
            for v in vertices {
                out.push(pt3(10, *v));
            }
            out.push(int(93, (triangles.len() * 4) as i32));
            for t in triangles {
                out.push(int(90, 3));
                for &i in t {
                    out.push(int(90, i as i32));
                }
            }
        }
    }
    if let Some(t) = props
        .and_then(|p| p.thickness)
        .filter(|t| *t != 0.0 || out.iter().any(|g| g.car().as_f64() == Some(39.0)))
        .filter(|_| crate::output::props::has_thickness(&e.kind))
    {
        with_thickness(&mut out, t);
    }
    Some(Value::list(out))
}

/// A POLYLINE's VERTEX (sub 1..=n) or SEQEND (sub n + 1).
fn sub_entity_list(
    out: &mut Vec<Value>,
    e: &Entity,
    name: Ename,
    me: Value,
    owner: Value,
) -> Option<()> {
    let EntityKind::Polyline { points, bulges, .. } = &e.kind else {
        return None;
    };
    let n = points.len() as u32;
    if name.sub <= n {
        let i = (name.sub - 1) as usize;
        let three_d = is_3d(points);
        head(out, me, "VERTEX", owner, None);
        layer_color(out, e);
        out.push(text(100, "AcDbVertex"));
        out.push(text(
            100,
            if three_d {
                "AcDb3dPolylineVertex"
            } else {
                "AcDb2dVertex"
            },
        ));
        out.push(pt3(10, points[i]));
        out.push(real(40, 0.0));
        out.push(real(41, 0.0));
        out.push(real(42, bulges.get(i).copied().unwrap_or(0.0)));
        out.push(int(70, if three_d { 32 } else { 0 }));
        out.push(real(50, 0.0));
        Some(())
    } else if name.sub == n + 1 {
        head(out, me, "SEQEND", owner.clone(), None);
        layer_color(out, e);
        out.push(pair(-2, owner));
        Some(())
    } else {
        None
    }
}

/// A parsed DXF list: `(code . value)` pairs in order.
pub struct Groups(pub Vec<(i32, Value)>);

/// "bad DXF group: (40 . \"x\")" as AutoLISP reports a malformed group.
pub fn bad_group(it: &Interp, g: &Value) -> Exn {
    err(format!("bad DXF group: {}", it.prin1_string(g)))
}

impl Groups {
    /// Every element must be a pair whose car is an integer group code.
    pub fn parse(it: &Interp, list: &Value) -> Result<Groups, Exn> {
        let list = it.list_arg(list)?;
        let mut out = Vec::new();
        for g in list.iter() {
            match g {
                Value::Cons(c) => match c.car {
                    Value::Int(code) => out.push((code, c.cdr.clone())),
                    _ => return Err(bad_group(it, g)),
                },
                _ => return Err(bad_group(it, g)),
            }
        }
        Ok(Groups(out))
    }

    pub fn get(&self, code: i32) -> Option<&Value> {
        self.0.iter().find(|(c, _)| *c == code).map(|(_, v)| v)
    }

    pub fn has(&self, code: i32) -> bool {
        self.get(code).is_some()
    }

    fn bad(&self, it: &Interp, code: i32, v: &Value) -> Exn {
        bad_group(it, &pair(code, v.clone()))
    }

    pub fn real(&self, it: &Interp, code: i32) -> Result<Option<f64>, Exn> {
        match self.get(code) {
            None => Ok(None),
            Some(v) => match v.as_f64() {
                Some(x) if x.is_finite() => Ok(Some(x)),
                _ => Err(self.bad(it, code, v)),
            },
        }
    }

    pub fn int(&self, it: &Interp, code: i32) -> Result<Option<i32>, Exn> {
        match self.get(code) {
            None => Ok(None),
            Some(Value::Int(i)) => Ok(Some(*i)),
            Some(v) => Err(self.bad(it, code, v)),
        }
    }

    pub fn string(&self, it: &Interp, code: i32) -> Result<Option<String>, Exn> {
        match self.get(code) {
            None => Ok(None),
            Some(Value::Str(s)) => Ok(Some(s.to_string())),
            Some(v) => Err(self.bad(it, code, v)),
        }
    }

    pub fn point(&self, it: &Interp, code: i32) -> Result<Option<DVec3>, Exn> {
        match self.get(code) {
            None => Ok(None),
            Some(v) => point_of(it, code, v).map(Some),
        }
    }

    /// Every value of a repeated group, in order (knots, control points...).
    pub fn all(&self, code: i32) -> impl Iterator<Item = &Value> + '_ {
        self.0
            .iter()
            .filter(move |(c, _)| *c == code)
            .map(|(_, v)| v)
    }

    pub fn all_points(&self, it: &Interp, code: i32) -> Result<Vec<DVec3>, Exn> {
        self.all(code).map(|v| point_of(it, code, v)).collect()
    }

    pub fn all_reals(&self, it: &Interp, code: i32) -> Result<Vec<f64>, Exn> {
        self.all(code)
            .map(|v| match v.as_f64() {
                Some(x) if x.is_finite() => Ok(x),
                _ => Err(self.bad(it, code, v)),
            })
            .collect()
    }
}

/// The value of a point group: 2 or 3 finite numbers (z = 0 for 2).
pub fn point_of(it: &Interp, code: i32, v: &Value) -> Result<DVec3, Exn> {
    let mut p = [0.0; 3];
    let mut n = 0;
    for x in v.iter() {
        match x.as_f64() {
            Some(x) if n < 3 && x.is_finite() => p[n] = x,
            _ => return Err(bad_group(it, &pair(code, v.clone()))),
        }
        n += 1;
    }
    if n < 2 || !matches!(v, Value::Cons(_)) {
        return Err(bad_group(it, &pair(code, v.clone())));
    }
    Ok(DVec3::from_array(p))
}
