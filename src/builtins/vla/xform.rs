//! Entities under the similarity transforms of Move, Copy, Rotate, ScaleEntity and Mirror
//! (the ActiveX methods and the MOVE/ROTATE/SCALE/MIRROR commands): point-defined kinds map
//! their points, circles, arcs and LWPOLYLINEs go through the geometry core's curve transform
//! (which keeps them exact and flips their orientation under a mirror).

use glam::{DMat3, DMat4, DVec2, DVec3};

use crate::builtins::drawing::curve_entity;
use crate::geom::frame::Ocs;
use crate::output::entity::EntityKind;

use super::curve::entity_curve;

/// The entity kind moved by `m` (a similarity), or why it cannot be.
pub fn transform_entity(k: &EntityKind, m: &DMat4) -> Result<EntityKind, String> {
    let pt = |p: &DVec3| m.transform_point3(*p);
    let lin = DMat3::from_mat4(*m);
    Ok(match k {
        EntityKind::Line { p0, p1 } => EntityKind::Line {
            p0: pt(p0),
            p1: pt(p1),
        },
        EntityKind::Point { p } => EntityKind::Point { p: pt(p) },
        EntityKind::Face3d { corners } => EntityKind::Face3d {
            corners: corners.map(|c| pt(&c)),
        },
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            let flip = if lin.determinant() < 0.0 { -1.0 } else { 1.0 };
            EntityKind::Polyline {
                points: points.iter().map(pt).collect(),
                bulges: bulges.iter().map(|b| b * flip).collect(),
                closed: *closed,
            }
        }
        EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            style,
        } => {
            let x = lin * DVec3::new(rotation.cos(), rotation.sin(), 0.0);
            EntityKind::Text {
                insert: pt(insert),
                height: height * x.length(),
                value: value.clone(),
                rotation: crate::geom::arc::norm_angle(x.y.atan2(x.x)),
                style: style.clone(),
            }
        }
        EntityKind::Mesh {
            vertices,
            triangles,
        } => EntityKind::Mesh {
            vertices: vertices.iter().map(pt).collect(),
            triangles: triangles.clone(),
        },
        EntityKind::Spline {
            curve,
            fit_points,
            closed,
        } => {
            let mut c = curve.clone();
            c.ctrl = c.ctrl.iter().map(pt).collect();
            EntityKind::Spline {
                curve: c,
                fit_points: fit_points.iter().map(pt).collect(),
                closed: *closed,
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
            // The normal maps by the cofactor (det · M⁻ᵀ): then minor = normal × major maps
            // onto itself and the parameters stay, mirror included.
            let n = (lin.inverse().transpose() * *normal) * lin.determinant();
            EntityKind::Ellipse {
                center: pt(center),
                major: lin * *major,
                normal: n.normalize(),
                ratio: *ratio,
                start: *start,
                end: *end,
            }
        }
        EntityKind::Unmodelled { dxf_type } => {
            return Err(format!("cannot transform a {dxf_type} entity yet"))
        }
        EntityKind::Circle { .. } | EntityKind::Arc { .. } | EntityKind::LwPolyline { .. } => {
            let c = entity_curve(k)
                .ok_or("not a curve")?
                .map_err(|e| e.to_string())?;
            let n0 = match k {
                EntityKind::Circle { normal, .. }
                | EntityKind::Arc { normal, .. }
                | EntityKind::LwPolyline { normal, .. } => *normal,
                _ => DVec3::Z,
            };
            keep_normal(
                curve_entity(&c.transform(m).map_err(|e| e.to_string())?),
                n0,
            )
        }
    })
}

/// A mirror turns a planar entity's normal over; AutoCAD's MIRROR keeps the normal and
/// describes the same points from the original side (angles swapped, bulges negated).
fn keep_normal(k: EntityKind, n0: DVec3) -> EntityKind {
    let ocs = Ocs::new(n0);
    let angle = |center: DVec3, p: DVec3| {
        let v = p - center;
        crate::geom::arc::norm_angle(v.dot(ocs.y).atan2(v.dot(ocs.x)))
    };
    match k {
        EntityKind::Circle {
            center,
            radius,
            normal,
        } if normal.dot(n0) < 0.0 => EntityKind::Circle {
            center,
            radius,
            normal: n0,
        },
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } if normal.dot(n0) < 0.0 => {
            let flipped = Ocs::new(normal);
            let (p0, p1) = (
                flipped.on_circle(center, radius, start),
                flipped.on_circle(center, radius, end),
            );
            EntityKind::Arc {
                center,
                radius,
                start: angle(center, p1),
                end: angle(center, p0),
                normal: n0,
            }
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } if normal.dot(n0) < 0.0 => {
            let flipped = Ocs::new(normal);
            let wcs: Vec<DVec3> = points
                .iter()
                .map(|p| flipped.to_wcs(*p, elevation))
                .collect();
            EntityKind::LwPolyline {
                points: wcs
                    .iter()
                    .map(|p| DVec2::new(p.dot(ocs.x), p.dot(ocs.y)))
                    .collect(),
                bulges: bulges.iter().map(|b| -b).collect(),
                closed,
                elevation: wcs.first().map_or(0.0, |p| p.dot(ocs.n)),
                normal: n0,
            }
        }
        other => other,
    }
}
