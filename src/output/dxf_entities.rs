//! Entities in the CAD profile's R2000 form: each kind's groups, the OCS for planar kinds off
//! the XY plane, and the groups an opened file's entity keeps.

use glam::DVec3;

use super::drawing::{is_flat, Entity, EntityKind};
use super::dxf_writer::DxfWriter;
use crate::geom::frame::Ocs;

pub(crate) fn entity_head(w: &mut DxfWriter, kind: &str, handle: u64, owner: u64, e: &Entity) {
    w.str(0, kind);
    w.handle(5, handle);
    w.handle(330, owner);
    w.str(100, "AcDbEntity");
    w.str(8, &e.layer);
    if let Some(c) = e.color {
        w.int(62, c as i64);
    }
}

/// The unit normal, and whether it differs from +Z (then 210 is written and points are OCS).
fn unit_normal(n: DVec3) -> (DVec3, bool) {
    let n = n.normalize();
    (n, n != DVec3::Z)
}

/// Angle in degrees in [0, 360).
pub fn degrees(a: f64) -> f64 {
    let d = a.to_degrees().rem_euclid(360.0);
    if d >= 360.0 {
        0.0
    } else {
        d
    }
}

/// An entity's groups (R2000 form) owned by the block record `owner`. Unmodelled entities
/// are skipped: their groups only make sense inside the document they were read from.
pub(crate) fn write_entity(
    w: &mut DxfWriter,
    e: &Entity,
    owner: u64,
    alloc: &mut impl FnMut() -> u64,
) {
    match &e.kind {
        EntityKind::Line { p0, p1 } => {
            entity_head(w, "LINE", e.handle, owner, e);
            w.str(100, "AcDbLine");
            w.point(10, *p0);
            w.point(11, *p1);
        }
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => {
            entity_head(w, "CIRCLE", e.handle, owner, e);
            circle_groups(w, *center, *radius, *normal);
        }
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            entity_head(w, "ARC", e.handle, owner, e);
            circle_groups(w, *center, *radius, *normal);
            w.str(100, "AcDbArc");
            w.float(50, degrees(*start));
            w.float(51, degrees(*end));
        }
        EntityKind::Point { p } => {
            entity_head(w, "POINT", e.handle, owner, e);
            w.str(100, "AcDbPoint");
            w.point(10, *p);
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            let (n, ocs) = unit_normal(*normal);
            entity_head(w, "LWPOLYLINE", e.handle, owner, e);
            w.str(100, "AcDbPolyline");
            w.int(90, points.len() as i64);
            w.int(70, *closed as i64);
            w.float(43, 0.0);
            if *elevation != 0.0 {
                w.float(38, *elevation);
            }
            for (i, p) in points.iter().enumerate() {
                w.point2(10, *p);
                let b = bulges.get(i).copied().unwrap_or(0.0);
                if b != 0.0 {
                    w.float(42, b);
                }
            }
            if ocs {
                w.point(210, n);
            }
        }
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            let z = points[0].z;
            let flat = is_flat(points);
            entity_head(w, "POLYLINE", e.handle, owner, e);
            let owner = e.handle;
            if flat {
                w.str(100, "AcDb2dPolyline");
                w.int(66, 1);
                w.point(10, DVec3::new(0.0, 0.0, z));
                w.int(70, *closed as i64);
            } else {
                w.str(100, "AcDb3dPolyline");
                w.int(66, 1);
                w.point(10, DVec3::ZERO);
                w.int(70, 8 | *closed as i64);
            }
            for (i, p) in points.iter().enumerate() {
                w.str(0, "VERTEX");
                w.handle(5, alloc());
                w.handle(330, owner);
                w.str(100, "AcDbEntity");
                w.str(8, &e.layer);
                w.str(100, "AcDbVertex");
                if flat {
                    w.str(100, "AcDb2dVertex");
                    w.point(10, *p);
                    let b = bulges.get(i).copied().unwrap_or(0.0);
                    if b != 0.0 {
                        w.float(42, b);
                    }
                    w.int(70, 0);
                } else {
                    w.str(100, "AcDb3dPolylineVertex");
                    w.point(10, *p);
                    w.int(70, 32);
                }
            }
            w.str(0, "SEQEND");
            w.handle(5, alloc());
            w.handle(330, owner);
            w.str(100, "AcDbEntity");
            w.str(8, &e.layer);
        }
        EntityKind::Spline {
            curve,
            fit_points,
            closed,
        } => super::dxf_spline::write_spline(w, e, owner, alloc, curve, fit_points, *closed),
        EntityKind::Face3d { corners } => {
            write_face(w, e.handle, owner, e, corners);
        }
        EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            style,
        } => {
            entity_head(w, "TEXT", e.handle, owner, e);
            w.str(100, "AcDbText");
            w.point(10, *insert);
            w.float(40, *height);
            w.str(1, value);
            if *rotation != 0.0 {
                w.float(50, degrees(*rotation));
            }
            w.str(7, if style.is_empty() { "Standard" } else { style });
            w.str(100, "AcDbText");
        }
        EntityKind::Mesh {
            vertices,
            triangles,
        } => {
            for (i, t) in triangles.iter().enumerate() {
                let h = if i == 0 { e.handle } else { alloc() };
                let c = [
                    vertices[t[0]],
                    vertices[t[1]],
                    vertices[t[2]],
                    vertices[t[2]],
                ];
                write_face(w, h, owner, e, &c);
            }
        }
        EntityKind::Ellipse {
            center,
            major,
            normal,
            ratio,
            start,
            end,
        } => {
            entity_head(w, "ELLIPSE", e.handle, owner, e);
            w.str(100, "AcDbEllipse");
            w.point(10, *center);
            w.point(11, *major);
            let n = normal.normalize();
            if n != DVec3::Z {
                w.point(210, n);
            }
            w.float(40, *ratio);
            w.float(41, *start);
            w.float(42, *end);
        }
        EntityKind::Unmodelled { .. } => {}
    }
}

/// An entity kept as groups (INSERT with ATTRIBs, ATTDEF), with the drawing's layer and
/// colour when a script changed them.
pub(crate) fn kept_groups(w: &mut DxfWriter, e: &Entity, s: &super::drawing::SourceRecord) {
    let mut t = s.tags.clone();
    if e.layer != s.original.layer {
        t = t.with(8, &e.layer, 100);
    }
    if e.color != s.original.color {
        t = t.with(62, &e.color.unwrap_or(256).to_string(), 8);
    }
    for (c, v) in t.iter() {
        w.str(c as u16, v);
    }
}

/// The AcDbCircle subclass an ARC shares with a CIRCLE: the centre in the OCS of a normal off
/// +Z, which is then written as the extrusion.
fn circle_groups(w: &mut DxfWriter, center: DVec3, radius: f64, normal: DVec3) {
    let (n, ocs) = unit_normal(normal);
    w.str(100, "AcDbCircle");
    w.point(
        10,
        if ocs {
            Ocs::new(n).wcs_to_ocs(center)
        } else {
            center
        },
    );
    w.float(40, radius);
    if ocs {
        w.point(210, n);
    }
}

fn write_face(w: &mut DxfWriter, h: u64, owner: u64, e: &Entity, c: &[DVec3; 4]) {
    entity_head(w, "3DFACE", h, owner, e);
    w.str(100, "AcDbFace");
    w.point(10, c[0]);
    w.point(11, c[1]);
    w.point(12, c[2]);
    w.point(13, c[3]);
    w.int(70, 0);
}

/// The unit normal of the plane holding every point (the largest cross product of spans from
/// the first point, then a flatness check), or `None` when they are not coplanar or are collinear.
pub fn plane_normal(pts: &[DVec3]) -> Option<DVec3> {
    if is_flat(pts) {
        return Some(DVec3::Z);
    }
    let o = pts[0];
    // The largest cross product of spans from the first point gives a robust normal.
    let mut best = DVec3::ZERO;
    for i in 1..pts.len() {
        for j in i + 1..pts.len() {
            let c = (pts[i] - o).cross(pts[j] - o);
            if c.length_squared() > best.length_squared() {
                best = c;
            }
        }
    }
    let len = best.length();
    let scale = pts
        .iter()
        .map(|p| (*p - o).length())
        .fold(0.0_f64, f64::max);
    if len <= 1e-12 * scale * scale || scale == 0.0 {
        return None;
    }
    let n = best / len;
    let flat = pts.iter().all(|p| (*p - o).dot(n).abs() <= 1e-9 * scale);
    flat.then_some(n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::frame::arbitrary_axis;

    #[test]
    fn plane_normal_of_tilted_and_skew_points() {
        let n = DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let (ax, ay) = arbitrary_axis(n);
        let pts: Vec<DVec3> = [(0.0, 0.0), (1.0, 0.0), (1.0, 2.0), (-3.0, 1.0)]
            .iter()
            .map(|(x, y)| ax * *x + ay * *y + n * 5.0)
            .collect();
        let got = plane_normal(&pts).unwrap();
        assert!(got.cross(n).length() < 1e-12);
        assert_eq!(
            plane_normal(&[DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z]),
            None
        );
        assert_eq!(plane_normal(&[DVec3::ZERO, DVec3::X * 2.0]), Some(DVec3::Z));
    }
}
