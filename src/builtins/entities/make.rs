//! `entmake` and `entmod`: DXF association lists → entities, with AutoLISP's rules: the type
//! group first (after an optional -1), defaults for optional groups (layer CLAYER, colour
//! BYLAYER, extrusion (0 0 1), text height TEXTSIZE, style "Standard"), nil when a required
//! group is missing or the geometry is invalid, and a POLYLINE collected over several calls
//! until its SEQEND.

use glam::{DVec2, DVec3};

use super::dxf_list::{entity_list, Groups};
use super::{ename_arg, EntityState};
use crate::builtins::drawing::drawing;
use crate::builtins::system::SysVars;
use crate::geom::bspline::BSpline;
use crate::geom::frame::Ocs;
use crate::geom::quadspline::QuadSpline;
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::props::EntityProps;
use crate::output::record::TagList;
use crate::output::{Entity, EntityKind};

/// A POLYLINE whose VERTEX entities are still arriving.
pub struct PendingPolyline {
    layer: String,
    color: Option<i16>,
    closed: bool,
    three_d: bool,
    elevation: f64,
    normal: DVec3,
    points: Vec<DVec3>,
    bulges: Vec<f64>,
    /// The header's extended data, given to the polyline when its SEQEND makes it.
    xdata: Option<Vec<(String, TagList)>>,
}

/// AutoCAD entity types lispcad does not model: `entmake` says so instead of returning a
/// silent nil (which AutoCAD gives for unknown types).
const UNSUPPORTED: &[&str] = &[
    "MTEXT",
    "HATCH",
    "DIMENSION",
    "SOLID",
    "TRACE",
    "RAY",
    "XLINE",
    "REGION",
    "LEADER",
    "MLEADER",
    "3DSOLID",
    "MLINE",
    "IMAGE",
    "VIEWPORT",
    "WIPEOUT",
    "TOLERANCE",
    "SHAPE",
    "BODY",
    "SURFACE",
    "TABLE",
    "MESH",
    "STYLE",
    "LTYPE",
    "DIMSTYLE",
    "UCS",
    "VIEW",
    "VPORT",
    "BLOCK_RECORD",
];

/// The layer new entities go on (entmake without an 8 group, command): the drawing's current
/// layer, which is what CLAYER reads and sets.
pub fn current_layer(it: &mut Interp) -> String {
    drawing(it).current_layer().to_string()
}

/// The entity type of a list: the first group, or the second after a -1.
fn type_of(g: &Groups) -> Option<String> {
    let first = match g.0.first() {
        Some((-1, _)) => g.0.get(1),
        other => other,
    }?;
    match first {
        (0, Value::Str(s)) => Some(s.to_uppercase()),
        _ => None,
    }
}

/// Colour group 62: None = BYLAYER (absent or 256), Some(0) BYBLOCK, Some(1..=255);
/// Err(()) for anything else (entmake then returns nil).
fn color_of(it: &Interp, g: &Groups) -> Result<Result<Option<i16>, ()>, Exn> {
    Ok(match g.int(it, 62)? {
        None | Some(256) => Ok(None),
        Some(c) if (0..=255).contains(&c) => Ok(Some(c as i16)),
        Some(_) => Err(()),
    })
}

fn normal_of(it: &Interp, g: &Groups) -> Result<Option<DVec3>, Exn> {
    let n = g.point(it, 210)?.unwrap_or(DVec3::Z);
    Ok((n.length() > 1e-12).then(|| n.normalize()))
}

/// The geometry of a graphical entity from its groups; Ok(None) when a required group is
/// missing or a value is out of range.
pub fn kind_of(it: &mut Interp, ty: &str, g: &Groups) -> Result<Option<EntityKind>, Exn> {
    let Some(normal) = normal_of(it, g)? else {
        return Ok(None);
    };
    let kind = match ty {
        "LINE" => {
            let (Some(p0), Some(p1)) = (g.point(it, 10)?, g.point(it, 11)?) else {
                return Ok(None);
            };
            EntityKind::Line { p0, p1 }
        }
        "CIRCLE" => {
            let (Some(c), Some(r)) = (g.point(it, 10)?, g.real(it, 40)?) else {
                return Ok(None);
            };
            EntityKind::Circle {
                center: Ocs::new(normal).to_wcs(c.truncate(), c.z),
                radius: r,
                normal,
            }
        }
        "ARC" => {
            let (Some(c), Some(r), Some(a0), Some(a1)) = (
                g.point(it, 10)?,
                g.real(it, 40)?,
                g.real(it, 50)?,
                g.real(it, 51)?,
            ) else {
                return Ok(None);
            };
            let tau = std::f64::consts::TAU;
            EntityKind::Arc {
                center: Ocs::new(normal).to_wcs(c.truncate(), c.z),
                radius: r,
                start: a0.rem_euclid(tau),
                end: a1.rem_euclid(tau),
                normal,
            }
        }
        "POINT" => {
            let Some(p) = g.point(it, 10)? else {
                return Ok(None);
            };
            EntityKind::Point { p }
        }
        "LWPOLYLINE" => return lwpolyline(it, g, normal),
        "SPLINE" => return spline(it, g),
        "3DFACE" => {
            let (Some(a), Some(b), Some(c)) =
                (g.point(it, 10)?, g.point(it, 11)?, g.point(it, 12)?)
            else {
                return Ok(None);
            };
            let d = g.point(it, 13)?.unwrap_or(c);
            EntityKind::Face3d {
                corners: [a, b, c, d],
            }
        }
        "TEXT" => {
            let (Some(p), Some(s)) = (g.point(it, 10)?, g.string(it, 1)?) else {
                return Ok(None);
            };
            let height = match g.real(it, 40)? {
                Some(h) => h,
                None => it.ext::<SysVars>().real("TEXTSIZE"),
            };
            // Justification (72/73, with the alignment point 11) is accepted; the text is
            // placed at its insertion point.
            g.int(it, 72)?;
            g.int(it, 73)?;
            EntityKind::Text {
                insert: p,
                height,
                value: s,
                rotation: g.real(it, 50)?.unwrap_or(0.0),
                style: g.string(it, 7)?.unwrap_or_else(|| "Standard".to_string()),
            }
        }
        "ELLIPSE" => {
            let (Some(center), Some(major), Some(ratio)) =
                (g.point(it, 10)?, g.point(it, 11)?, g.real(it, 40)?)
            else {
                return Ok(None);
            };
            EntityKind::Ellipse {
                center,
                major,
                normal,
                ratio,
                start: g.real(it, 41)?.unwrap_or(0.0),
                end: g.real(it, 42)?.unwrap_or(std::f64::consts::TAU),
            }
        }
        _ => return Ok(None),
    };
    Ok(Some(kind))
}

/// LWPOLYLINE: vertices from the 10 groups in order, each followed by its optional 42 bulge;
/// 90 (if given) the vertex count, 70 bit 1 closed, 38 elevation; points in the OCS.
fn lwpolyline(it: &Interp, g: &Groups, normal: DVec3) -> Result<Option<EntityKind>, Exn> {
    let mut points: Vec<DVec2> = Vec::new();
    let mut bulges: Vec<f64> = Vec::new();
    for (code, v) in &g.0 {
        match code {
            10 => {
                let p = super::dxf_list::point_of(it, 10, v)?;
                points.push(p.truncate());
                bulges.push(0.0);
            }
            42 => {
                let b = v.as_f64().filter(|b| b.is_finite()).ok_or_else(|| {
                    super::dxf_list::bad_group(it, &Value::cons(Value::Int(42), v.clone()))
                })?;
                if let Some(last) = bulges.last_mut() {
                    *last = b;
                }
            }
            _ => {}
        }
    }
    if let Some(n) = g.int(it, 90)? {
        if n < 0 || n as usize > points.len() {
            return Ok(None);
        }
        points.truncate(n as usize);
        bulges.truncate(n as usize);
    }
    let flags = g.int(it, 70)?.unwrap_or(0);
    Ok(Some(EntityKind::LwPolyline {
        points,
        bulges,
        closed: flags & 1 != 0,
        elevation: g.real(it, 38)?.unwrap_or(0.0),
        normal,
    }))
}

/// SPLINE: from control points (10, with knots 40 and weights 41 when given) or, without
/// them, through the fit points (11) as lispcad's C1 quadratic interpolating spline.
fn spline(it: &Interp, g: &Groups) -> Result<Option<EntityKind>, Exn> {
    let flags = g.int(it, 70)?.unwrap_or(0);
    let closed = flags & 3 != 0;
    let degree = g.int(it, 71)?.unwrap_or(3);
    let ctrl = g.all_points(it, 10)?;
    let knots = g.all_reals(it, 40)?;
    let weights = g.all_reals(it, 41)?;
    let fit = g.all_points(it, 11)?;
    if degree < 1 {
        return Ok(None);
    }
    if !ctrl.is_empty() {
        let weights = if weights.is_empty() {
            None
        } else {
            Some(weights)
        };
        let knots = if knots.is_empty() { None } else { Some(knots) };
        return Ok(BSpline::new(degree as usize, ctrl, knots, weights)
            .ok()
            .map(|curve| EntityKind::Spline {
                curve,
                fit_points: fit,
                closed,
            }));
    }
    Ok(QuadSpline::interpolate(&fit, closed)
        .ok()
        .map(|s| EntityKind::Spline {
            curve: s.to_bspline(),
            fit_points: fit,
            closed,
        }))
}

/// Adds an entity from a parsed list; Ok(None) when entmake must return nil.
fn make_entity(it: &mut Interp, ty: &str, g: &Groups) -> Result<Option<u64>, Exn> {
    let Ok(color) = color_of(it, g)? else {
        return Ok(None);
    };
    let layer = match g.string(it, 8)? {
        Some(l) => l,
        None => current_layer(it),
    };
    let Some(kind) = kind_of(it, ty, g)? else {
        return Ok(None);
    };
    let Ok(props) = props_of(it, g)? else {
        return Ok(None);
    };
    let e = Entity {
        handle: 0,
        layer,
        color,
        kind,
    };
    let Ok(h) = drawing(it).add(e) else {
        return Ok(None);
    };
    if props != EntityProps::default() {
        drawing(it).set_props(h, props);
    }
    Ok(Some(h))
}

/// Line type (6), line-type scale (48), line weight (370) and thickness (39) of a list, as
/// CHPROP sets them (a group at its default leaves the property unset); Err(()) for a value
/// out of range (entmake and entmod then return nil).
fn props_of(it: &Interp, g: &Groups) -> Result<Result<EntityProps, ()>, Exn> {
    let mut p = EntityProps::default();
    if let Some(lt) = g.string(it, 6)? {
        if lt.is_empty() || lt.chars().any(|c| "<>/\\\":;?*|,=`".contains(c)) {
            return Ok(Err(()));
        }
        if !lt.eq_ignore_ascii_case("ByLayer") {
            p.linetype = Some(lt);
        }
    }
    if let Some(s) = g.real(it, 48)? {
        if !(s.is_finite() && s > 0.0) {
            return Ok(Err(()));
        }
        p.ltscale = (s != 1.0).then_some(s);
    }
    if let Some(w) = g.int(it, 370)? {
        if !(-3..=211).contains(&w) {
            return Ok(Err(()));
        }
        p.lineweight = (w != -1).then_some(w as i16);
    }
    if let Some(t) = g.real(it, 39)? {
        if !t.is_finite() {
            return Ok(Err(()));
        }
        p.thickness = (t != 0.0).then_some(t);
    }
    Ok(Ok(p))
}

/// An entity made while a block definition is open: it goes into the block.
fn make_in_block(
    it: &mut Interp,
    ty: &str,
    g: &Groups,
    xdata: Option<TagList>,
) -> Result<bool, Exn> {
    let Ok(color) = color_of(it, g)? else {
        return Ok(false);
    };
    let layer = match g.string(it, 8)? {
        Some(l) => l,
        None => current_layer(it),
    };
    let Some(kind) = kind_of(it, ty, g)? else {
        return Ok(false);
    };
    let e = Entity {
        handle: 0,
        layer,
        color,
        kind,
    };
    Ok(super::block_make::add_to_block(it, e, xdata).is_some())
}

pub fn entmake(it: &mut Interp, a: &[Value]) -> LResult {
    let Some(list) = a.first().filter(|v| v.truthy()) else {
        // (entmake) cancels a POLYLINE, INSERT or block definition in progress.
        it.ext::<EntityState>().pending_polyline = None;
        super::block_make::cancel(it);
        return Ok(Value::Nil);
    };
    let g = Groups::parse(it, list)?;
    let Some(ty) = type_of(&g) else {
        return Ok(Value::Nil);
    };
    let pending = it.ext::<EntityState>().pending_polyline.is_some();
    let xdata = match super::objects::parse_xdata(it, &g)? {
        super::objects::XdataIn::Unregistered => return Ok(Value::Nil),
        x => x,
    };
    let pending_insert = it.ext::<EntityState>().pending_insert.is_some();
    let made = match ty.as_str() {
        "VERTEX" if pending => vertex(it, &g)?,
        "SEQEND" if pending => seqend(it)?,
        "ATTRIB" if pending_insert => super::block_make::attrib(it, &g)?,
        "SEQEND" if pending_insert => super::block_make::seqend(it)?,
        "VERTEX" | "SEQEND" | "ATTRIB" => false,
        _ if pending || pending_insert => {
            // Any other entity abandons the unfinished polyline or INSERT, as AutoCAD does.
            it.ext::<EntityState>().pending_polyline = None;
            it.ext::<EntityState>().pending_insert = None;
            false
        }
        "BLOCK" => super::block_make::block(it, &g)?,
        "ENDBLK" => return super::block_make::endblk(it),
        "INSERT" => super::block_make::insert(it, &g)?,
        "ATTDEF" => super::block_make::attdef(it, &g)?,
        "POLYLINE" => {
            let apps = match xdata {
                super::objects::XdataIn::Apps(apps) => Some(apps),
                _ => None,
            };
            polyline_header(it, &g, apps)?
        }
        "LAYER" => super::tables::make_layer(it, &g)?,
        "APPID" => super::objects::make_appid(it, &g)?,
        "XRECORD" | "DICTIONARY" => super::objects::make_object(it, &ty, &g)?.is_some(),
        t if UNSUPPORTED.contains(&t) => {
            return Err(err(format!(
                "entmake: entity type {t} is not supported by lispcad (LINE, CIRCLE, ARC, POINT, LWPOLYLINE, POLYLINE, SPLINE, ELLIPSE, 3DFACE, TEXT, BLOCK...ENDBLK, INSERT, ATTDEF, ATTRIB, LAYER, APPID, XRECORD and DICTIONARY are)"
            )))
        }
        t if super::block_make::in_block(it) => {
            let xdata = match xdata {
                super::objects::XdataIn::Apps(apps) => {
                    let mut x = TagList::new();
                    for (c, v) in apps.iter().flat_map(|(_, t)| t.iter()) {
                        x.push(c, v);
                    }
                    Some(x)
                }
                _ => None,
            };
            make_in_block(it, t, &g, xdata)?
        }
        t => match make_entity(it, t, &g)? {
            Some(h) => {
                if let super::objects::XdataIn::Apps(apps) = xdata {
                    super::objects::apply_xdata(it, h, apps);
                }
                true
            }
            None => false,
        },
    };
    Ok(if made { list.clone() } else { Value::Nil })
}

fn polyline_header(
    it: &mut Interp,
    g: &Groups,
    xdata: Option<Vec<(String, TagList)>>,
) -> Result<bool, Exn> {
    let flags = g.int(it, 70)?.unwrap_or(0);
    if flags & (16 | 64) != 0 {
        return Err(err(
            "entmake: polygon and polyface meshes (POLYLINE flags 16, 64) are not supported",
        ));
    }
    let Ok(color) = color_of(it, g)? else {
        return Ok(false);
    };
    let Some(normal) = normal_of(it, g)? else {
        return Ok(false);
    };
    let layer = match g.string(it, 8)? {
        Some(l) => l,
        None => current_layer(it),
    };
    let elevation = g.point(it, 10)?.map_or(0.0, |p| p.z);
    it.ext::<EntityState>().pending_polyline = Some(PendingPolyline {
        layer,
        color,
        closed: flags & 1 != 0,
        three_d: flags & 8 != 0,
        elevation,
        normal,
        points: Vec::new(),
        bulges: Vec::new(),
        xdata,
    });
    Ok(true)
}

fn vertex(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    let Some(p) = g.point(it, 10)? else {
        return Ok(false);
    };
    let bulge = g.real(it, 42)?.unwrap_or(0.0);
    let st = it.ext::<EntityState>();
    let Some(pl) = st.pending_polyline.as_mut() else {
        return Ok(false);
    };
    // 2D polyline vertices are OCS points at the header's elevation.
    let p = if pl.three_d {
        p
    } else {
        Ocs::new(pl.normal).to_wcs(p.truncate(), pl.elevation)
    };
    pl.points.push(p);
    pl.bulges.push(bulge);
    Ok(true)
}

fn seqend(it: &mut Interp) -> Result<bool, Exn> {
    let Some(pl) = it.ext::<EntityState>().pending_polyline.take() else {
        return Ok(false);
    };
    let bulges = if pl.bulges.iter().all(|b| *b == 0.0) {
        Vec::new()
    } else {
        pl.bulges
    };
    let e = Entity {
        handle: 0,
        layer: pl.layer,
        color: pl.color,
        kind: EntityKind::Polyline {
            points: pl.points,
            bulges,
            closed: pl.closed,
        },
    };
    if super::block_make::in_block(it) {
        let x = pl.xdata.map(|apps| {
            let mut x = TagList::new();
            for (c, v) in apps.iter().flat_map(|(_, t)| t.iter()) {
                x.push(c, v);
            }
            x
        });
        return Ok(super::block_make::add_to_block(it, e, x).is_some());
    }
    let Ok(h) = drawing(it).add(e) else {
        return Ok(false);
    };
    if let Some(apps) = pl.xdata {
        super::objects::apply_xdata(it, h, apps);
    }
    Ok(true)
}

/// `entmod`: the groups of the list override the entity's current ones; the type cannot change.
pub fn entmod(it: &mut Interp, a: &[Value]) -> LResult {
    let new = Groups::parse(it, &a[0])?;
    let Some(name) = new.get(-1).cloned() else {
        return Ok(Value::Nil);
    };
    let name = ename_arg(it, &name)?;
    if name.sub == 0 && drawing(it).get(name.handle).is_none() {
        // An object (XRECORD) rather than an entity.
        let ok = super::objects::modify_object(it, name.handle, &new)?;
        return Ok(if ok { a[0].clone() } else { Value::Nil });
    }
    let xdata = match super::objects::parse_xdata(it, &new)? {
        super::objects::XdataIn::Unregistered => return Ok(Value::Nil),
        x => x,
    };
    let Some(old_list) = entity_list(it, name) else {
        return Ok(Value::Nil);
    };
    let old = Groups::parse(it, &old_list)?;
    let ty = type_of(&old).unwrap_or_default();
    if let Some(t) = type_of(&new) {
        if t != ty {
            return Ok(Value::Nil);
        }
    }
    if !modify_kept_groups(it, name, &new, &old)? {
        return Ok(Value::Nil);
    }
    if name.sub != 0 {
        if drawing(it)
            .source(name.handle)
            .is_some_and(|s| unmodelled(&s.original))
        {
            return Ok(a[0].clone());
        }
        return Ok(if modify_vertex(it, name, &new)? {
            a[0].clone()
        } else {
            Value::Nil
        });
    }
    let mut merged: Vec<(i32, Value)> = new.0.clone();
    merged.extend(old.0.into_iter().filter(|(c, _)| !new.has(*c)));
    let g = Groups(merged);
    let Ok(color) = color_of(it, &g)? else {
        return Ok(Value::Nil);
    };
    let layer = g.string(it, 8)?.unwrap_or_default();
    let unmodelled = drawing(it)
        .get(name.handle)
        .filter(|e| matches!(e.kind, EntityKind::Unmodelled { .. }))
        .map(|e| e.kind.clone());
    let kind = if let Some(k) = unmodelled {
        // Kept as read (INSERT, MTEXT, HATCH...): layer and colour change, the geometry stays.
        k
    } else if ty == "POLYLINE" {
        // The header carries no geometry; flags 70 bit 1 may open or close it.
        let Some(e) = drawing(it).get(name.handle) else {
            return Ok(Value::Nil);
        };
        let mut kind = e.kind.clone();
        if let EntityKind::Polyline { closed, .. } = &mut kind {
            *closed = g.int(it, 70)?.unwrap_or(0) & 1 != 0;
        }
        kind
    } else {
        match kind_of(it, &ty, &g)? {
            Some(k) => k,
            None => return Ok(Value::Nil),
        }
    };
    let e = Entity {
        handle: name.handle,
        layer,
        color,
        kind,
    };
    let Ok(props) = props_of(it, &g)? else {
        return Ok(Value::Nil);
    };
    if drawing(it).replace(name.handle, e).is_err() {
        return Ok(Value::Nil);
    }
    let d = drawing(it);
    if props != EntityProps::default() || d.props(name.handle).is_some() {
        // Unset ones go back to their defaults, as a list without them means.
        let full = EntityProps {
            linetype: props.linetype.or_else(|| Some("ByLayer".to_string())),
            lineweight: props.lineweight.or(Some(-1)),
            thickness: props.thickness.or(Some(0.0)),
            ltscale: props.ltscale.or(Some(1.0)),
        };
        d.set_props(name.handle, full);
    }
    if let super::objects::XdataIn::Apps(apps) = xdata {
        super::objects::apply_xdata(it, name.handle, apps);
    }
    Ok(a[0].clone())
}

fn unmodelled(e: &Entity) -> bool {
    matches!(e.kind, EntityKind::Unmodelled { .. })
}

/// `entmod` of an entity kept as its groups (INSERT, MTEXT, HATCH, DIMENSION... and their
/// ATTRIB followers): the list's groups replace the kept ones. False when they do not fit.
fn modify_kept_groups(
    it: &mut Interp,
    name: super::Ename,
    g: &Groups,
    old: &Groups,
) -> Result<bool, Exn> {
    let d = drawing(it);
    let Some(tags) = d
        .source(name.handle)
        .filter(|s| unmodelled(&s.original) && d.get(name.handle).is_some())
        .map(|s| s.tags.clone())
    else {
        return Ok(true);
    };
    match super::tag_list::modify_tags(it, &tags, name.sub as usize, g, old)? {
        Some(t) => {
            drawing(it).set_source_tags(name.handle, t);
            Ok(true)
        }
        None => Ok(false),
    }
}

/// `entmod` of a VERTEX: its location (10) and bulge (42).
fn modify_vertex(it: &mut Interp, name: super::Ename, g: &Groups) -> Result<bool, Exn> {
    let p = g.point(it, 10)?;
    let b = g.real(it, 42)?;
    let Some(e) = drawing(it).get(name.handle).cloned() else {
        return Ok(false);
    };
    let mut e = e;
    let EntityKind::Polyline { points, bulges, .. } = &mut e.kind else {
        return Ok(false);
    };
    let i = (name.sub - 1) as usize;
    if i >= points.len() {
        return Ok(false);
    }
    if let Some(p) = p {
        points[i] = p;
    }
    if let Some(b) = b {
        if bulges.is_empty() {
            bulges.resize(points.len(), 0.0);
        }
        bulges[i] = b;
    }
    Ok(drawing(it).replace(name.handle, e).is_ok())
}
