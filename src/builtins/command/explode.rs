//! EXPLODE of a block reference: the block's entities, moved by the reference's transform
//! (scale, rotation about Z, then the insertion point), replace it with their own layers and
//! colours, as AutoCAD does; its ATTRIBs (their values) and SEQEND go with it. One level
//! only: a nested block reference becomes a block reference (with its attributes) whose
//! insertion point, scale and rotation compose both transforms; an ATTDEF becomes an ATTDEF
//! again, showing its tag. A non-uniform scale maps every entity exactly: circles become
//! ellipses, arcs (and a polyline's arc segments) elliptical arcs, lines, points and straight
//! polylines their transformed points. A nested reference that would be skewed, an entity
//! lispcad does not model, an array or a tilted reference is a clear error and changes
//! nothing.

use glam::{DMat3, DMat4, DVec2, DVec3};

use super::cmd_err;
use crate::builtins::vla::xform::transform_entity;
use crate::geom::frame::Ocs;
use crate::lang::error::Exn;
use crate::lang::Interp;
use crate::output::drawing::{bulge_arc, bulge_segments, SourceRecord};
use crate::output::dxf_writer::push_float;
use crate::output::record::TagList;
use crate::output::{Drawing, Entity, EntityKind};

fn num(v: Option<&str>) -> f64 {
    v.and_then(|s| s.trim().parse().ok()).unwrap_or(0.0)
}

fn real(x: f64) -> String {
    let mut s = String::new();
    push_float(&mut s, x);
    s
}

/// What the explosion adds: a modelled entity, or groups kept as read (INSERT, ATTDEF).
enum Piece {
    Model(Entity),
    Kept(String, Entity, TagList),
}

/// The records of a block between BLOCK and ENDBLK, each entity with its followers.
fn block_entities(d: &Drawing, name: &str) -> Option<(DVec3, Vec<TagList>)> {
    let recs = d.block_section();
    let start = recs.iter().position(|r| {
        r.type_name() == "BLOCK" && r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(name))
    })?;
    let b = &recs[start];
    let base = DVec3::new(num(b.get(10)), num(b.get(20)), num(b.get(30)));
    let mut out: Vec<TagList> = Vec::new();
    for r in recs[start + 1..]
        .iter()
        .take_while(|r| r.type_name() != "ENDBLK")
    {
        let follower = matches!(r.type_name(), "VERTEX" | "ATTRIB" | "SEQEND");
        match out.last_mut() {
            Some(last) if follower => {
                for (c, v) in r.iter() {
                    last.push(c, v);
                }
            }
            _ => out.push(r.clone()),
        }
    }
    Some((base, out))
}

/// The principal axes of the ellipse c + a cos t + b sin t (conjugate semi-diameters a, b):
/// (major, ratio, t0) with the point at parameter p of the result being the one at t = p + t0.
fn principal(a: DVec3, b: DVec3) -> (DVec3, f64, f64) {
    let t0 = 0.5 * (2.0 * a.dot(b)).atan2(a.dot(a) - b.dot(b));
    let at = |t: f64| a * t.cos() + b * t.sin();
    let (m0, m1) = (at(t0), at(t0 + std::f64::consts::FRAC_PI_2));
    if m0.length() >= m1.length() {
        (m0, (m1.length() / m0.length()).min(1.0), t0)
    } else {
        let t1 = t0 + std::f64::consts::FRAC_PI_2;
        (m1, (m0.length() / m1.length()).min(1.0), t1)
    }
}

/// The image of c + a cos t + b sin t (t from `s` to `e`) under `m`, as an ELLIPSE.
fn ellipse_image(m: &DMat4, c: DVec3, a: DVec3, b: DVec3, s: f64, e: f64) -> EntityKind {
    let lin = DMat3::from_mat4(*m);
    let (la, lb) = (lin * a, lin * b);
    let (major, ratio, t0) = principal(la, lb);
    let tau = std::f64::consts::TAU;
    let full = (e - s - tau).abs() < 1e-12;
    EntityKind::Ellipse {
        center: m.transform_point3(c),
        major,
        normal: la.cross(lb).normalize(),
        ratio,
        start: if full { 0.0 } else { (s - t0).rem_euclid(tau) },
        end: if full { tau } else { (e - t0).rem_euclid(tau) },
    }
}

/// A circular arc (centre, radius, normal, CCW from `s` to `e`) under `m`.
fn arc_image(m: &DMat4, c: DVec3, r: f64, n: DVec3, s: f64, e: f64) -> EntityKind {
    let ocs = Ocs::new(n);
    ellipse_image(m, c, ocs.x * r, ocs.y * r, s, e)
}

/// The entity kinds `k` becomes under the affine map `m` (one, or a polyline's segments
/// when it has arc segments and `m` is not a similarity).
fn affine_image(k: &EntityKind, m: &DMat4) -> Result<Vec<EntityKind>, String> {
    let lin = DMat3::from_mat4(*m);
    let (x, y, z) = (
        lin.x_axis.length(),
        lin.y_axis.length(),
        lin.z_axis.length(),
    );
    let orthogonal = lin.x_axis.dot(lin.y_axis).abs() < 1e-12 * x * y
        && lin.x_axis.dot(lin.z_axis).abs() < 1e-12 * x * z
        && lin.y_axis.dot(lin.z_axis).abs() < 1e-12 * y * z;
    let similar = orthogonal && (x - y).abs() <= 1e-12 * x && (x - z).abs() <= 1e-12 * x;
    if similar {
        return transform_entity(k, m).map(|k| vec![k]);
    }
    let tau = std::f64::consts::TAU;
    Ok(match k {
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => vec![arc_image(m, *center, *radius, *normal, 0.0, tau)],
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            let sweep = crate::output::drawing::ccw_sweep(*start, *end);
            vec![arc_image(
                m,
                *center,
                *radius,
                *normal,
                *start,
                *start + sweep,
            )]
        }
        EntityKind::Ellipse {
            center,
            major,
            normal,
            ratio,
            start,
            end,
        } => {
            let minor = normal.normalize().cross(*major) * *ratio;
            let sweep = crate::output::drawing::ccw_sweep(*start, *end);
            vec![ellipse_image(
                m,
                *center,
                *major,
                minor,
                *start,
                *start + sweep,
            )]
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } if bulges.iter().any(|b| *b != 0.0) => {
            let ocs = Ocs::new(*normal);
            segments(
                points,
                bulges,
                *closed,
                |p| ocs.to_wcs(p, *elevation),
                m,
                *normal,
            )
        }
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } if bulges.iter().any(|b| *b != 0.0) && crate::output::drawing::is_flat(points) => {
            let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
            let z = points[0].z;
            segments(&flat, bulges, *closed, |p| p.extend(z), m, DVec3::Z)
        }
        EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            style,
        } => {
            let dir = lin * DVec3::new(rotation.cos(), rotation.sin(), 0.0);
            let up = lin * DVec3::new(-rotation.sin(), rotation.cos(), 0.0);
            vec![EntityKind::Text {
                insert: m.transform_point3(*insert),
                height: height * up.length(),
                value: value.clone(),
                rotation: crate::geom::arc::norm_angle(dir.y.atan2(dir.x)),
                style: style.clone(),
            }]
        }
        // Point-defined kinds (lines, points, faces, meshes, splines, 3D polylines) map
        // their points, which is exact under any affine map.
        other => vec![transform_entity(other, m)?],
    })
}

/// A 2D polyline with arc segments as its lines and elliptical arcs under `m`.
fn segments(
    points: &[DVec2],
    bulges: &[f64],
    closed: bool,
    to_wcs: impl Fn(DVec2) -> DVec3,
    m: &DMat4,
    normal: DVec3,
) -> Vec<EntityKind> {
    let mut out = Vec::new();
    for (a, b, bulge) in bulge_segments(points, bulges, closed) {
        match bulge_arc(a, b, bulge) {
            Some((c, r, a0, a1)) => {
                let (s, e) = if a0 <= a1 { (a0, a1) } else { (a1, a0) };
                let centre = to_wcs(c);
                out.push(arc_image(m, centre, r, normal, s, e));
            }
            None => out.push(EntityKind::Line {
                p0: m.transform_point3(to_wcs(a)),
                p1: m.transform_point3(to_wcs(b)),
            }),
        }
    }
    out
}

/// A nested block reference (with its ATTRIBs) under the outer transform `m` with rotation
/// `rot` (degrees) and scale `s`: the same block, its point, scale and rotation composed.
fn nested_insert(t: &TagList, m: &DMat4, rot: f64, s: DVec3) -> Result<TagList, String> {
    let get = |c| t.get(c).map_or(1.0, |v| num(Some(v)));
    let inner_rot = num(t.get(50)).to_radians();
    let inner = DMat3::from_rotation_z(inner_rot)
        * DMat3::from_diagonal(DVec3::new(get(41), get(42), get(43)));
    let outer = DMat3::from_rotation_z(rot.to_radians()) * DMat3::from_diagonal(s);
    let l = outer * inner;
    let (c0, c1) = (l.x_axis.truncate(), l.y_axis.truncate());
    if c0.dot(c1).abs() > 1e-9 * c0.length() * c1.length() {
        return Err(format!(
            "the nested reference to block \"{}\" would be skewed by the non-uniform scale",
            t.get(2).unwrap_or("")
        ));
    }
    let theta = c0.y.atan2(c0.x);
    let sx = c0.length();
    let sy = c1.length() * c0.perp_dot(c1).signum();
    let at = m.transform_point3(DVec3::new(num(t.get(10)), num(t.get(20)), num(t.get(30))));
    let deg = crate::output::dxf::degrees(theta);
    let mut out = TagList::new();
    let first = t.first_record_end();
    let mut head = TagList::new();
    for (c, v) in t.iter().take(first) {
        head.push(c, v);
    }
    head = head
        .with(10, &real(at.x), 2)
        .with(20, &real(at.y), 10)
        .with(30, &real(at.z), 20)
        .with(41, &real(sx), 30)
        .with(42, &real(sy), 41)
        .with(43, &real(l.z_axis.z), 42)
        .with(50, &real(deg), 43);
    for (c, v) in head.iter() {
        out.push(c, v);
    }
    // The ATTRIBs follow their reference: points moved, heights and angles as the text's.
    let rest: Vec<(i32, &str)> = t.iter().skip(first).collect();
    let mut i = 0;
    while i < rest.len() {
        let start = i;
        i += 1;
        while i < rest.len() && rest[i].0 != 0 {
            i += 1;
        }
        let mut rec = TagList::new();
        for (c, v) in &rest[start..i] {
            rec.push(*c, v);
        }
        if rec.type_name() == "ATTRIB" {
            rec = moved_text(&rec, m)?;
        }
        for (c, v) in rec.iter() {
            out.push(c, v);
        }
    }
    Ok(out)
}

/// An ATTDEF or ATTRIB record moved by `m`: its insertion and
/// alignment points, height (along its up direction) and rotation.
fn moved_text(t: &TagList, m: &DMat4) -> Result<TagList, String> {
    let lin = DMat3::from_mat4(*m);
    let r = num(t.get(50)).to_radians();
    let up = lin * DVec3::new(-r.sin(), r.cos(), 0.0);
    let dir = lin * DVec3::new(r.cos(), r.sin(), 0.0);
    let mut out = t.clone();
    for c in [10, 11] {
        if t.get(c).is_some() {
            let p = m.transform_point3(DVec3::new(
                num(t.get(c)),
                num(t.get(c + 10)),
                num(t.get(c + 20)),
            ));
            out = out
                .with(c, &real(p.x), 100)
                .with(c + 10, &real(p.y), c)
                .with(c + 20, &real(p.z), c + 10);
        }
    }
    let height = t.get(40).map_or(2.5, |v| num(Some(v))) * up.length();
    let width = t.get(41).map_or(1.0, |v| num(Some(v))) * dir.length() / up.length();
    out = out.with(40, &real(height), 30).with(
        50,
        &real(crate::output::dxf::degrees(dir.y.atan2(dir.x))),
        40,
    );
    if (width - 1.0).abs() > 1e-12 {
        out = out.with(41, &real(width), 50);
    }
    Ok(out)
}

/// The pieces block `name` becomes under `m`.
fn pieces(d: &Drawing, name: &str, at: DVec3, rot: f64, s: DVec3) -> Result<Vec<Piece>, String> {
    let (base, ents) =
        block_entities(d, name).ok_or_else(|| format!("block \"{name}\" is not defined"))?;
    let m = DMat4::from_translation(at)
        * DMat4::from_rotation_z(rot.to_radians())
        * DMat4::from_scale(s)
        * DMat4::from_translation(-base);
    let mut out = Vec::new();
    for t in ents {
        let e = crate::output::dxfin::factory::entity(&t);
        match t.type_name() {
            "INSERT" => {
                let tags = nested_insert(&t, &m, rot, s)?;
                out.push(Piece::Kept("INSERT".into(), e, tags));
            }
            "ATTDEF" => {
                let tags = moved_text(&t, &m)?;
                out.push(Piece::Kept("ATTDEF".into(), e, tags));
            }
            ty => {
                if let EntityKind::Unmodelled { .. } = e.kind {
                    return Err(format!(
                        "block \"{name}\" holds a {ty}, which lispcad does not model"
                    ));
                }
                for kind in affine_image(&e.kind, &m)? {
                    out.push(Piece::Model(Entity { kind, ..e.clone() }));
                }
            }
        }
    }
    Ok(out)
}

/// Kept groups renumbered for the drawing: new handles, owned by model space (followers by
/// their entity).
fn renumbered(t: &TagList, d: &mut Drawing) -> (u64, TagList) {
    let model = d.model_space_record();
    let mut out = TagList::new();
    let mut parent = 0;
    let mut record = 0;
    let mut in_app = false;
    let mut owner_done = false;
    for (i, (c, v)) in t.iter().enumerate() {
        if c == 0 {
            record += 1;
            in_app = false;
            owner_done = false;
        }
        if c == 102 {
            in_app = v.starts_with('{');
        }
        match c {
            5 if i > 0 && t.at(i - 1).0 == 0 => {
                let h = d.alloc_handle();
                if record == 1 {
                    parent = h;
                }
                out.push(5, &format!("{h:X}"));
            }
            330 if !in_app && !owner_done => {
                owner_done = true;
                let o = if record == 1 { model } else { parent };
                out.push(330, &format!("{o:X}"));
            }
            _ => out.push(c, v),
        }
    }
    (parent, out)
}

/// EXPLODE of the block reference `h` (see the module documentation).
pub(crate) fn explode_insert(it: &mut Interp, h: u64) -> Result<(), Exn> {
    let fail = |m: String| cmd_err("EXPLODE", m);
    let d = it.ext::<Drawing>();
    let t = d
        .source(h)
        .map(|s| s.tags.clone())
        .ok_or_else(|| fail("the block reference has no groups".into()))?;
    let name = t.get(2).unwrap_or("").to_string();
    let at = DVec3::new(num(t.get(10)), num(t.get(20)), num(t.get(30)));
    let scale = |c| t.get(c).map_or(1.0, |v| num(Some(v)));
    let s = DVec3::new(scale(41), scale(42), scale(43));
    if s.x * s.y * s.z == 0.0 {
        return Err(fail(format!("the block reference has a zero scale {s}")));
    }
    let normal = DVec3::new(
        num(t.get(210)),
        num(t.get(220)),
        t.get(230).map_or(1.0, |v| num(Some(v))),
    );
    let count = |c| t.get(c).map_or(1.0, |v| num(Some(v)));
    if (normal - DVec3::Z).length() > 1e-12 || count(70) > 1.0 || count(71) > 1.0 {
        return Err(fail(
            "lispcad explodes block references in the XY plane, not arrays or tilted ones".into(),
        ));
    }
    let made = pieces(d, &name, at, num(t.get(50)), s).map_err(fail)?;
    // The reference's ATTRIBs and SEQEND follow it.
    let mut next = d.next_after(h);
    d.delete(h);
    while let Some(n) = next {
        let follower = matches!(d.get(n).map(|e| &e.kind),
            Some(EntityKind::Unmodelled { dxf_type }) if dxf_type == "ATTRIB" || dxf_type == "SEQEND");
        if !follower {
            break;
        }
        next = d.next_after(n);
        d.delete(n);
    }
    for p in made {
        match p {
            Piece::Model(e) => {
                d.add(e).map_err(|x| fail(x.to_string()))?;
            }
            Piece::Kept(ty, e, tags) => {
                let (handle, tags) = renumbered(&tags, d);
                let e = Entity {
                    handle,
                    kind: EntityKind::Unmodelled { dxf_type: ty },
                    ..e
                };
                d.ensure_layer(&e.layer).map_err(|x| fail(x.to_string()))?;
                let source = SourceRecord {
                    tags,
                    original: e.clone(),
                    block: None,
                };
                d.push_loaded(e, Some(source));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_under_a_non_uniform_scale_is_an_ellipse() {
        let m = DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let k = EntityKind::Circle {
            center: DVec3::new(1.0, 1.0, 0.0),
            radius: 3.0,
            normal: DVec3::Z,
        };
        let out = affine_image(&k, &m).unwrap();
        let EntityKind::Ellipse {
            center,
            major,
            ratio,
            start,
            end,
            ..
        } = out[0]
        else {
            panic!("{out:?}")
        };
        assert_eq!(center, DVec3::new(2.0, 1.0, 0.0));
        assert!((major - DVec3::new(6.0, 0.0, 0.0)).length() < 1e-12);
        assert!((ratio - 0.5).abs() < 1e-12);
        assert_eq!((start, end), (0.0, std::f64::consts::TAU));
    }

    #[test]
    fn principal_axes_of_conjugate_diameters() {
        // a = (2,0), b = (1,1): the ellipse x = 2cos t + sin t, y = sin t.
        let (major, ratio, t0) = principal(DVec3::new(2.0, 0.0, 0.0), DVec3::new(1.0, 1.0, 0.0));
        let p = |t: f64| DVec3::new(2.0 * t.cos() + t.sin(), t.sin(), 0.0);
        assert!((p(t0) - major).length() < 1e-12);
        // Semi-axes: the square roots of the eigenvalues of [[5,1],[1,1]]... via the area:
        // |a x b| = major * minor.
        assert!((major.length() * major.length() * ratio - 2.0).abs() < 1e-12);
    }
}
