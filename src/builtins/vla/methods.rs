//! Methods of VLA objects: the Add* family of model space, the entity edits (Move, Copy,
//! Rotate, ScaleEntity, Mirror, Offset, Delete), IntersectWith with the acExtend* options,
//! collection Item/Add, and the document's undo marks.

use glam::{DVec2, DVec3};

use crate::builtins::drawing::curve_entity;
use crate::builtins::system::SysVars;
use crate::geom::curve::{xform, Curve};
use crate::geom::intersect::{intersect, HitKind};
use crate::lang::error::{err, Exn};
use crate::lang::{Interp, Value};
use crate::output::entity::{Entity, EntityKind};
use crate::output::Drawing;

use super::curve::entity_curve;
use super::props::{space_members, unknown_name};
use super::variant::{coord_points, point_arg, to_lisp};
use super::xform::transform_entity;
use super::{entity_class, Vla};

/// What a method returns, before it takes `vlax-invoke-method`'s form (variants) or
/// `vlax-invoke`'s (lists).
pub enum Ret {
    Nil,
    Value(Value),
    Obj(Vla),
    Coords(Vec<f64>),
    Objects(Vec<Vla>),
}

/// The object for an entity handle.
pub fn entity_obj(it: &mut Interp, h: u64) -> Vla {
    let class = it
        .ext::<Drawing>()
        .get(h)
        .map_or("IAcadEntity", |e| entity_class(&e.kind).0);
    Vla::Entity(h, class)
}

fn ax_err(e: impl std::fmt::Display) -> Exn {
    err(format!("ActiveX Server returned an error: {e}"))
}

fn add(it: &mut Interp, kind: EntityKind) -> Result<Ret, Exn> {
    kind.validate().map_err(ax_err)?;
    let h = it.ext::<Drawing>().add_kind(kind).map_err(ax_err)?;
    Ok(Ret::Obj(entity_obj(it, h)))
}

fn need(args: &[Value], n: usize, name: &str) -> Result<(), Exn> {
    if args.len() < n {
        return Err(err(format!(
            "too few arguments: {name} needs {n}, got {}",
            args.len()
        )));
    }
    Ok(())
}

/// Invokes a method by name (case-insensitive).
pub fn invoke(it: &mut Interp, obj: &Vla, name: &str, args: &[Value]) -> Result<Ret, Exn> {
    let key = name.to_ascii_uppercase();
    match obj {
        Vla::ModelSpace | Vla::PaperSpace | Vla::Block(_) => space_method(it, obj, &key, args),
        Vla::Layers => match key.as_str() {
            "ADD" => {
                need(args, 1, name)?;
                let n = it.string(&to_lisp(it, &args[0]))?.to_string();
                let d = it.ext::<Drawing>();
                let n = d.ensure_layer(&n).map_err(ax_err)?;
                Ok(Ret::Obj(Vla::Layer(n)))
            }
            "ITEM" => {
                need(args, 1, name)?;
                let key = to_lisp(it, &args[0]);
                let d = it.ext::<Drawing>();
                let found = match &key {
                    Value::Int(i) => d.layers().get(*i as usize).map(|l| l.name.clone()),
                    Value::Str(s) => d.layer(s).map(|l| l.name.clone()),
                    _ => None,
                };
                found
                    .map(|n| Ret::Obj(Vla::Layer(n)))
                    .ok_or_else(|| ax_err("Key not found"))
            }
            _ => Err(unknown_name(name)),
        },
        Vla::Blocks if key == "ITEM" => {
            need(args, 1, name)?;
            match to_lisp(it, &args[0]) {
                Value::Int(0) => Ok(Ret::Obj(Vla::ModelSpace)),
                Value::Int(1) => Ok(Ret::Obj(Vla::PaperSpace)),
                Value::Str(s) if s.eq_ignore_ascii_case("*Model_Space") => {
                    Ok(Ret::Obj(Vla::ModelSpace))
                }
                Value::Str(s) if s.eq_ignore_ascii_case("*Paper_Space") => {
                    Ok(Ret::Obj(Vla::PaperSpace))
                }
                _ => Err(ax_err("Key not found")),
            }
        }
        Vla::Document => match key.as_str() {
            "STARTUNDOMARK" | "ENDUNDOMARK" => {
                // UNDOCTL bit 8: a group is open (AutoCAD's undo mark state).
                let sv = it.ext::<SysVars>();
                let ctl = sv.int("UNDOCTL");
                let ctl = if key == "STARTUNDOMARK" {
                    ctl | 8
                } else {
                    ctl & !8
                };
                sv.put("UNDOCTL", Value::Int(ctl));
                Ok(Ret::Nil)
            }
            "REGEN" | "SAVE" | "AUDITINFO" | "PURGEALL" => Ok(Ret::Nil),
            _ => Err(unknown_name(name)),
        },
        Vla::Entity(h, _) => entity_method(it, *h, &key, name, args),
        Vla::Layer(n) if key == "DELETE" => {
            let n = n.clone();
            it.ext::<Drawing>().remove_layer(&n).map_err(ax_err)?;
            Ok(Ret::Nil)
        }
        _ => Err(unknown_name(name)),
    }
}

fn space_method(it: &mut Interp, obj: &Vla, key: &str, args: &[Value]) -> Result<Ret, Exn> {
    if !matches!(obj, Vla::ModelSpace) && key.starts_with("ADD") {
        return Err(err(
            "lispcad draws in model space only: paper space and blocks cannot be added to",
        ));
    }
    match key {
        "ADDLINE" => {
            need(args, 2, "AddLine")?;
            add(
                it,
                EntityKind::Line {
                    p0: point_arg(it, &args[0])?,
                    p1: point_arg(it, &args[1])?,
                },
            )
        }
        "ADDCIRCLE" => {
            need(args, 2, "AddCircle")?;
            add(
                it,
                EntityKind::Circle {
                    center: point_arg(it, &args[0])?,
                    radius: it.num(&to_lisp(it, &args[1]))?,
                    normal: DVec3::Z,
                },
            )
        }
        "ADDARC" => {
            need(args, 4, "AddArc")?;
            let n = |i: usize| it.num(&to_lisp(it, &args[i]));
            add(
                it,
                EntityKind::Arc {
                    center: point_arg(it, &args[0])?,
                    radius: n(1)?,
                    start: n(2)?,
                    end: n(3)?,
                    normal: DVec3::Z,
                },
            )
        }
        "ADDPOINT" => {
            need(args, 1, "AddPoint")?;
            add(
                it,
                EntityKind::Point {
                    p: point_arg(it, &args[0])?,
                },
            )
        }
        "ADDLIGHTWEIGHTPOLYLINE" => {
            need(args, 1, "AddLightWeightPolyline")?;
            let points: Vec<DVec2> = coord_points(it, &args[0], 2)?
                .iter()
                .map(|p| p.truncate())
                .collect();
            add(
                it,
                EntityKind::LwPolyline {
                    bulges: vec![0.0; points.len()],
                    points,
                    closed: false,
                    elevation: 0.0,
                    normal: DVec3::Z,
                },
            )
        }
        "ADDPOLYLINE" | "ADD3DPOLY" => {
            need(args, 1, "AddPolyline")?;
            let points = coord_points(it, &args[0], 3)?;
            add(
                it,
                EntityKind::Polyline {
                    bulges: vec![0.0; points.len()],
                    points,
                    closed: false,
                },
            )
        }
        "ADDTEXT" => {
            need(args, 3, "AddText")?;
            let value = it.string(&to_lisp(it, &args[0]))?.to_string();
            add(
                it,
                EntityKind::Text {
                    insert: point_arg(it, &args[1])?,
                    height: it.num(&to_lisp(it, &args[2]))?,
                    value,
                    rotation: 0.0,
                    style: "Standard".into(),
                },
            )
        }
        "ADDSPLINE" => {
            need(args, 1, "AddSpline")?;
            let pts = coord_points(it, &args[0], 3)?;
            let curve = crate::geom::quadspline::QuadSpline::interpolate(&pts, false)
                .map(Curve::Spline)
                .map_err(ax_err)?;
            let kind = match curve_entity(&curve) {
                EntityKind::Spline { curve, closed, .. } => EntityKind::Spline {
                    curve,
                    fit_points: pts,
                    closed,
                },
                other => other,
            };
            add(it, kind)
        }
        "ITEM" => {
            need(args, 1, "Item")?;
            let i = it.int(&to_lisp(it, &args[0]))?;
            let members = space_members(it, obj);
            let h = usize::try_from(i)
                .ok()
                .and_then(|i| members.get(i).copied())
                .ok_or_else(|| ax_err("Invalid index"))?;
            Ok(Ret::Obj(entity_obj(it, h)))
        }
        _ => Err(unknown_name(key)),
    }
}

fn entity_method(
    it: &mut Interp,
    h: u64,
    key: &str,
    name: &str,
    args: &[Value],
) -> Result<Ret, Exn> {
    let e = {
        let d = it.ext::<Drawing>();
        match d.get(h) {
            Some(e) if !d.is_deleted(h) => e.clone(),
            _ => return Err(err("Automation Error. Object was erased")),
        }
    };
    let transform = |it: &mut Interp, m: glam::DMat4, copy: bool| -> Result<Ret, Exn> {
        let kind = transform_entity(&e.kind, &m).map_err(ax_err)?;
        let d = it.ext::<Drawing>();
        if copy {
            let mut n = Entity::new(&e.layer, kind);
            n.color = e.color;
            let nh = d.add(n).map_err(ax_err)?;
            return Ok(Ret::Obj(entity_obj(it, nh)));
        }
        let mut n = e.clone();
        n.kind = kind;
        d.replace(h, n).map_err(ax_err)?;
        Ok(Ret::Nil)
    };
    match key {
        "DELETE" | "ERASE" => {
            it.ext::<Drawing>().delete(h);
            Ok(Ret::Nil)
        }
        "UPDATE" | "HIGHLIGHT" => Ok(Ret::Nil),
        "COPY" => transform(it, glam::DMat4::IDENTITY, true),
        "MOVE" => {
            need(args, 2, name)?;
            let (a, b) = (point_arg(it, &args[0])?, point_arg(it, &args[1])?);
            transform(it, xform::translate(b - a), false)
        }
        "ROTATE" => {
            need(args, 2, name)?;
            let base = point_arg(it, &args[0])?;
            let ang = it.num(&to_lisp(it, &args[1]))?;
            let m = xform::rotate(base, ang, None).map_err(ax_err)?;
            transform(it, m, false)
        }
        "SCALEENTITY" => {
            need(args, 2, name)?;
            let base = point_arg(it, &args[0])?;
            let f = it.num(&to_lisp(it, &args[1]))?;
            let m = xform::scale(base, f).map_err(ax_err)?;
            transform(it, m, false)
        }
        "MIRROR" => {
            need(args, 2, name)?;
            let (a, b) = (point_arg(it, &args[0])?, point_arg(it, &args[1])?);
            let m = xform::mirror(a, b).map_err(ax_err)?;
            transform(it, m, true)
        }
        "OFFSET" => {
            need(args, 1, name)?;
            let d = it.num(&to_lisp(it, &args[0]))?;
            let c = entity_curve(&e.kind)
                .ok_or_else(|| unknown_name(name))?
                .map_err(ax_err)?;
            let o = c.offset(d).map_err(ax_err)?;
            let mut n = Entity::new(&e.layer, curve_entity(&o));
            n.color = e.color;
            let nh = it.ext::<Drawing>().add(n).map_err(ax_err)?;
            Ok(Ret::Objects(vec![entity_obj(it, nh)]))
        }
        "INTERSECTWITH" => {
            need(args, 2, name)?;
            let other = match to_lisp(it, &args[0]).as_obj::<Vla>() {
                Some(Vla::Entity(o, _)) => *o,
                _ => return Err(crate::lang::builtin::bad_arg(it, "VLA-OBJECT", &args[0])),
            };
            let ext = it.int(&to_lisp(it, &args[1]))?;
            let pts = intersect_with(it, &e.kind, other, ext)?;
            Ok(Ret::Coords(pts.iter().flat_map(|p| p.to_array()).collect()))
        }
        "GETBOUNDINGBOX" => {
            need(args, 2, name)?;
            let mut pts = Vec::new();
            e.kind.extent_points(&mut pts);
            let lo = pts
                .iter()
                .copied()
                .fold(DVec3::splat(f64::INFINITY), DVec3::min);
            let hi = pts
                .iter()
                .copied()
                .fold(DVec3::splat(f64::NEG_INFINITY), DVec3::max);
            for (sym, p) in args.iter().zip([lo, hi]) {
                let s = it.symbol(sym)?;
                it.values[s.idx()] = super::variant::doubles_variant(&p.to_array());
            }
            Ok(Ret::Nil)
        }
        _ => Err(unknown_name(name)),
    }
}

/// The curve of an entity, extended as acExtend* asks: a line to cover `reach` (the other
/// curve's box), an arc to its full circle.
fn extended(c: Curve, reach: (DVec3, DVec3)) -> Curve {
    match &c {
        Curve::Line(l) => {
            let d = (l.p1 - l.p0).normalize();
            let (lo, hi) = reach;
            let corners = (0..8).map(|i| {
                DVec3::new(
                    if i & 1 == 0 { lo.x } else { hi.x },
                    if i & 2 == 0 { lo.y } else { hi.y },
                    if i & 4 == 0 { lo.z } else { hi.z },
                )
            });
            let (mut s0, mut s1) = (0.0f64, (l.p1 - l.p0).length());
            for q in corners {
                let s = (q - l.p0).dot(d);
                s0 = s0.min(s - 1.0);
                s1 = s1.max(s + 1.0);
            }
            Curve::line(l.p0 + d * s0, l.p0 + d * s1).unwrap_or(c)
        }
        Curve::Arc(a) => Curve::circle(a.center(), a.radius(), Some(a.normal())).unwrap_or(c),
        _ => c,
    }
}

fn intersect_with(
    it: &mut Interp,
    kind: &EntityKind,
    other: u64,
    ext: i32,
) -> Result<Vec<DVec3>, Exn> {
    let ok = {
        let d = it.ext::<Drawing>();
        d.get(other)
            .filter(|_| !d.is_deleted(other))
            .map(|e| e.kind.clone())
    };
    let okind = ok.ok_or_else(|| err("Automation Error. Object was erased"))?;
    let (Some(Ok(a)), Some(Ok(b))) = (entity_curve(kind), entity_curve(&okind)) else {
        return Ok(Vec::new());
    };
    let (ba, bb) = (a.bbox(), b.bbox());
    let both = (ba.0.min(bb.0), ba.1.max(bb.1));
    let a = if ext & 1 != 0 { extended(a, both) } else { a };
    let b = if ext & 2 != 0 { extended(b, both) } else { b };
    let tol = crate::builtins::geometry::geomtol(it);
    let mut out = Vec::new();
    for h in intersect(&a, &b, tol) {
        match h.kind {
            HitKind::Overlap(c) => {
                out.push(c.eval(0.0));
                out.push(c.eval(1.0));
            }
            _ => out.push(h.point),
        }
    }
    Ok(out)
}
