//! Entities as DXF group lists, the form AutoLISP's `entget` returns and `entmake`/`entmod`
//! take, without any Lisp value type: the bindings convert `(code . value)` pairs to and from
//! `(i16, Group)`.
//!
//! Conventions follow AutoLISP: points of CIRCLE, ARC and LWPOLYLINE are in the entity's OCS
//! (extrusion 210), angles (50, 51) are radians, colour 62 is absent for BYLAYER. `from_groups`
//! applies entmake's rules: the entity type (0) comes first, optional groups take their
//! defaults, a missing required group is an error (the binding returns nil).

use glam::{DVec2, DVec3};

use super::drawing::{Entity, EntityKind, Layer};
use crate::geom::bspline::BSpline;
use crate::geom::frame::arbitrary_axis;

/// A group value.
#[derive(Clone, Debug, PartialEq)]
pub enum Group {
    Int(i64),
    Real(f64),
    Str(String),
    Point(DVec3),
    /// A 2D point (AutoLISP's `(10 x y)` of LWPOLYLINE vertices).
    Point2(DVec2),
}

/// Why a group list does not make an entity.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum GroupError {
    #[error("the first group must be (0 . \"TYPE\")")]
    NoType,
    #[error("entmake cannot make a {0:?}")]
    Unsupported(String),
    #[error("required group {code} missing for {kind}")]
    Missing { kind: String, code: i16 },
    #[error("group {code} has the wrong kind of value")]
    BadValue { code: i16 },
    #[error("{0}")]
    Invalid(String),
}

/// What one `entmake` call produced. POLYLINE is made by a header, VERTEX calls and a SEQEND,
/// so the binding collects those three into one `EntityKind::Polyline`.
#[derive(Clone, Debug, PartialEq)]
pub enum Made {
    Entity(Entity),
    Layer(Layer),
    PolylineStart {
        layer: String,
        color: Option<i16>,
        closed: bool,
    },
    Vertex {
        p: DVec3,
        bulge: f64,
    },
    SeqEnd,
}

fn pt(v: DVec3) -> Group {
    Group::Point(v)
}

/// The `entget` list of an entity, without the (-1 . ename) pair the binding adds. A mesh is
/// not an AutoCAD entity: it lists only its type, handle, layer and vertex count (90).
pub fn to_groups(e: &Entity) -> Vec<(i16, Group)> {
    let mut g: Vec<(i16, Group)> = vec![
        (0, Group::Str(e.kind.type_name().to_string())),
        (5, Group::Str(format!("{:X}", e.handle))),
        (100, Group::Str("AcDbEntity".into())),
        (8, Group::Str(e.layer.clone())),
    ];
    if let Some(c) = e.color {
        g.push((62, Group::Int(c as i64)));
    }
    let ocs = |p: DVec3, n: DVec3| {
        let (ax, ay) = arbitrary_axis(n);
        DVec3::new(p.dot(ax), p.dot(ay), p.dot(n.normalize()))
    };
    match &e.kind {
        EntityKind::Line { p0, p1 } => {
            g.push((100, Group::Str("AcDbLine".into())));
            g.push((10, pt(*p0)));
            g.push((11, pt(*p1)));
            g.push((210, pt(DVec3::Z)));
        }
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => {
            g.push((100, Group::Str("AcDbCircle".into())));
            g.push((10, pt(ocs(*center, *normal))));
            g.push((40, Group::Real(*radius)));
            g.push((210, pt(normal.normalize())));
        }
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            g.push((100, Group::Str("AcDbCircle".into())));
            g.push((10, pt(ocs(*center, *normal))));
            g.push((40, Group::Real(*radius)));
            g.push((210, pt(normal.normalize())));
            g.push((100, Group::Str("AcDbArc".into())));
            let tau = std::f64::consts::TAU;
            g.push((50, Group::Real(start.rem_euclid(tau))));
            g.push((51, Group::Real(end.rem_euclid(tau))));
        }
        EntityKind::Point { p } => {
            g.push((100, Group::Str("AcDbPoint".into())));
            g.push((10, pt(*p)));
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            g.push((100, Group::Str("AcDbPolyline".into())));
            g.push((90, Group::Int(points.len() as i64)));
            g.push((70, Group::Int(*closed as i64)));
            g.push((43, Group::Real(0.0)));
            g.push((38, Group::Real(*elevation)));
            for (i, p) in points.iter().enumerate() {
                // AutoLISP lists LWPOLYLINE vertices as 2D points.
                g.push((10, Group::Point2(*p)));
                g.push((40, Group::Real(0.0)));
                g.push((41, Group::Real(0.0)));
                g.push((42, Group::Real(bulges.get(i).copied().unwrap_or(0.0))));
                g.push((91, Group::Int(0)));
            }
            g.push((210, pt(normal.normalize())));
        }
        EntityKind::Polyline { closed, .. } => {
            // The header only: the vertices are separate VERTEX entities in AutoCAD.
            g.push((100, Group::Str("AcDb3dPolyline".into())));
            g.push((66, Group::Int(1)));
            g.push((10, pt(DVec3::ZERO)));
            g.push((70, Group::Int(8 | *closed as i64)));
        }
        EntityKind::Spline {
            curve,
            fit_points,
            closed,
        } => {
            g.push((100, Group::Str("AcDbSpline".into())));
            let mut flags = 0;
            if *closed {
                flags |= 1;
            }
            if curve.weights.is_some() {
                flags |= 4;
            }
            g.push((70, Group::Int(flags)));
            g.push((71, Group::Int(curve.degree as i64)));
            g.push((72, Group::Int(curve.knots.len() as i64)));
            g.push((73, Group::Int(curve.ctrl.len() as i64)));
            g.push((74, Group::Int(fit_points.len() as i64)));
            for k in &curve.knots {
                g.push((40, Group::Real(*k)));
            }
            if let Some(w) = &curve.weights {
                for x in w {
                    g.push((41, Group::Real(*x)));
                }
            }
            for p in &curve.ctrl {
                g.push((10, pt(*p)));
            }
            for p in fit_points {
                g.push((11, pt(*p)));
            }
        }
        EntityKind::Face3d { corners } => {
            g.push((100, Group::Str("AcDbFace".into())));
            for (i, c) in corners.iter().enumerate() {
                g.push((10 + i as i16, pt(*c)));
            }
            g.push((70, Group::Int(0)));
        }
        EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            style,
        } => {
            g.push((100, Group::Str("AcDbText".into())));
            g.push((10, pt(*insert)));
            g.push((40, Group::Real(*height)));
            g.push((1, Group::Str(value.clone())));
            g.push((50, Group::Real(*rotation)));
            g.push((7, Group::Str(style.clone())));
            g.push((210, pt(DVec3::Z)));
        }
        EntityKind::Mesh { vertices, .. } => {
            g.push((90, Group::Int(vertices.len() as i64)));
        }
    }
    g
}

struct Lookup<'a> {
    kind: &'a str,
    g: &'a [(i16, Group)],
}

impl Lookup<'_> {
    fn all(&self, code: i16) -> impl Iterator<Item = &Group> + '_ {
        self.g
            .iter()
            .filter(move |(c, _)| *c == code)
            .map(|(_, v)| v)
    }
    fn opt(&self, code: i16) -> Option<&Group> {
        self.all(code).next()
    }
    fn missing(&self, code: i16) -> GroupError {
        GroupError::Missing {
            kind: self.kind.to_string(),
            code,
        }
    }
    fn point(&self, code: i16) -> Result<DVec3, GroupError> {
        self.opt_point(code)?.ok_or_else(|| self.missing(code))
    }
    fn opt_point(&self, code: i16) -> Result<Option<DVec3>, GroupError> {
        match self.opt(code) {
            None => Ok(None),
            Some(v) => as_point(v, code).map(Some),
        }
    }
    fn real(&self, code: i16) -> Result<f64, GroupError> {
        self.opt_real(code)?.ok_or_else(|| self.missing(code))
    }
    fn opt_real(&self, code: i16) -> Result<Option<f64>, GroupError> {
        match self.opt(code) {
            None => Ok(None),
            Some(v) => as_real(v, code).map(Some),
        }
    }
    fn opt_int(&self, code: i16) -> Result<Option<i64>, GroupError> {
        match self.opt(code) {
            None => Ok(None),
            Some(Group::Int(i)) => Ok(Some(*i)),
            Some(Group::Real(r)) if r.fract() == 0.0 => Ok(Some(*r as i64)),
            Some(_) => Err(GroupError::BadValue { code }),
        }
    }
    fn opt_str(&self, code: i16) -> Result<Option<&str>, GroupError> {
        match self.opt(code) {
            None => Ok(None),
            Some(Group::Str(s)) => Ok(Some(s)),
            Some(_) => Err(GroupError::BadValue { code }),
        }
    }
}

/// A point group; a 2D point reads z = 0. Non-finite coordinates are refused.
fn as_point(v: &Group, code: i16) -> Result<DVec3, GroupError> {
    let p = match v {
        Group::Point(p) => *p,
        Group::Point2(p) => p.extend(0.0),
        _ => return Err(GroupError::BadValue { code }),
    };
    if p.is_finite() {
        Ok(p)
    } else {
        Err(GroupError::BadValue { code })
    }
}

fn as_real(v: &Group, code: i16) -> Result<f64, GroupError> {
    match v {
        Group::Real(r) => Ok(*r),
        Group::Int(i) => Ok(*i as f64),
        _ => Err(GroupError::BadValue { code }),
    }
}

/// Make an entity (or layer, or a piece of a POLYLINE) from an `entmake` list. `current_layer`
/// is used when group 8 is absent. The handle of a made entity is 0 (the drawing assigns it).
pub fn from_groups(groups: &[(i16, Group)], current_layer: &str) -> Result<Made, GroupError> {
    let kind = match groups.first() {
        Some((0, Group::Str(s))) => s.to_ascii_uppercase(),
        _ => return Err(GroupError::NoType),
    };
    let l = Lookup {
        kind: &kind,
        g: groups,
    };
    let layer = l.opt_str(8)?.unwrap_or(current_layer).to_string();
    let color = match l.opt_int(62)? {
        None | Some(256) => None,
        Some(c) => Some(c as i16),
    };
    let normal = l.opt_point(210)?.unwrap_or(DVec3::Z);
    if !normal.is_finite() || normal.length() < 1e-12 {
        return Err(GroupError::Invalid(
            "extrusion (210) must be non-zero".into(),
        ));
    }
    let from_ocs = |p: DVec3| {
        let (ax, ay) = arbitrary_axis(normal);
        ax * p.x + ay * p.y + normal.normalize() * p.z
    };
    let ek = match kind.as_str() {
        "LINE" => EntityKind::Line {
            p0: l.point(10)?,
            p1: l.point(11)?,
        },
        "CIRCLE" => EntityKind::Circle {
            center: from_ocs(l.point(10)?),
            radius: l.real(40)?,
            normal: normal.normalize(),
        },
        "ARC" => EntityKind::Arc {
            center: from_ocs(l.point(10)?),
            radius: l.real(40)?,
            start: l.real(50)?,
            end: l.real(51)?,
            normal: normal.normalize(),
        },
        "POINT" => EntityKind::Point { p: l.point(10)? },
        "LWPOLYLINE" => {
            // Each 10 starts a vertex; a 42 belongs to the vertex before it.
            let mut points = Vec::new();
            let mut bulges = Vec::new();
            for (c, v) in groups {
                match c {
                    10 => {
                        points.push(as_point(v, 10)?.truncate());
                        bulges.push(0.0);
                    }
                    42 => {
                        if let Some(b) = bulges.last_mut() {
                            *b = as_real(v, 42)?;
                        }
                    }
                    _ => {}
                }
            }
            if points.is_empty() {
                return Err(l.missing(10));
            }
            EntityKind::LwPolyline {
                points,
                bulges,
                closed: l.opt_int(70)?.unwrap_or(0) & 1 == 1,
                elevation: l.opt_real(38)?.unwrap_or(0.0),
                normal: normal.normalize(),
            }
        }
        "SPLINE" => {
            let degree = l.opt_int(71)?.unwrap_or(3);
            let ctrl: Vec<DVec3> = l
                .all(10)
                .map(|v| as_point(v, 10))
                .collect::<Result<_, _>>()?;
            if ctrl.is_empty() {
                return Err(l.missing(10));
            }
            let knots: Vec<f64> = l
                .all(40)
                .map(|v| as_real(v, 40))
                .collect::<Result<_, _>>()?;
            let weights: Vec<f64> = l
                .all(41)
                .map(|v| as_real(v, 41))
                .collect::<Result<_, _>>()?;
            let fit_points: Vec<DVec3> = l
                .all(11)
                .map(|v| as_point(v, 11))
                .collect::<Result<_, _>>()?;
            let curve = BSpline::new(
                degree.max(0) as usize,
                ctrl,
                (!knots.is_empty()).then_some(knots),
                (!weights.is_empty()).then_some(weights),
            )
            .map_err(|e| GroupError::Invalid(e.to_string()))?;
            EntityKind::Spline {
                curve,
                fit_points,
                closed: l.opt_int(70)?.unwrap_or(0) & 1 == 1,
            }
        }
        "3DFACE" => {
            let c2 = l.point(12)?;
            EntityKind::Face3d {
                corners: [
                    l.point(10)?,
                    l.point(11)?,
                    c2,
                    l.opt_point(13)?.unwrap_or(c2),
                ],
            }
        }
        "TEXT" => EntityKind::Text {
            insert: l.point(10)?,
            height: l.real(40)?,
            value: l.opt_str(1)?.ok_or_else(|| l.missing(1))?.to_string(),
            rotation: l.opt_real(50)?.unwrap_or(0.0),
            style: l.opt_str(7)?.unwrap_or("Standard").to_string(),
        },
        "LAYER" => {
            let name = l.opt_str(2)?.ok_or_else(|| l.missing(2))?;
            let flags = l.opt_int(70)?.unwrap_or(0);
            return Ok(Made::Layer(Layer {
                name: name.to_string(),
                color: l.opt_int(62)?.unwrap_or(7) as i16,
                linetype: l.opt_str(6)?.unwrap_or("Continuous").to_string(),
                frozen: flags & 1 == 1,
                locked: flags & 4 == 4,
            }));
        }
        "POLYLINE" => {
            return Ok(Made::PolylineStart {
                layer,
                color,
                closed: l.opt_int(70)?.unwrap_or(0) & 1 == 1,
            })
        }
        "VERTEX" => {
            return Ok(Made::Vertex {
                p: l.point(10)?,
                bulge: l.opt_real(42)?.unwrap_or(0.0),
            })
        }
        "SEQEND" => return Ok(Made::SeqEnd),
        other => return Err(GroupError::Unsupported(other.to_string())),
    };
    ek.validate()
        .map_err(|e| GroupError::Invalid(e.to_string()))?;
    Ok(Made::Entity(Entity {
        handle: 0,
        layer,
        color,
        kind: ek,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::Drawing;

    fn s(x: &str) -> Group {
        Group::Str(x.into())
    }

    #[test]
    fn entmake_line_uses_defaults_and_requires_points() {
        let made = from_groups(
            &[(0, s("LINE")), (10, pt(DVec3::ZERO)), (11, pt(DVec3::X))],
            "CUR",
        )
        .unwrap();
        let Made::Entity(e) = made else { panic!() };
        assert_eq!(e.layer, "CUR");
        assert_eq!(e.color, None);
        let err = from_groups(&[(0, s("LINE")), (10, pt(DVec3::ZERO))], "0").unwrap_err();
        assert_eq!(
            err,
            GroupError::Missing {
                kind: "LINE".into(),
                code: 11
            }
        );
        assert_eq!(
            from_groups(&[(8, s("x"))], "0").unwrap_err(),
            GroupError::NoType
        );
    }

    #[test]
    fn every_kind_round_trips_through_groups() {
        let d = {
            // The output tests' mixed drawing is not reachable here; a compact one instead.
            let mut d = Drawing::new();
            let n = DVec3::new(0.2, -0.3, 1.0).normalize();
            for k in [
                EntityKind::Line {
                    p0: DVec3::ZERO,
                    p1: DVec3::new(1.0, 2.0, 3.0),
                },
                EntityKind::Circle {
                    center: DVec3::new(1.0, 2.0, 3.0),
                    radius: 2.0,
                    normal: n,
                },
                EntityKind::Arc {
                    center: DVec3::new(1.0, 2.0, 3.0),
                    radius: 2.0,
                    start: 0.5,
                    end: 2.0,
                    normal: n,
                },
                EntityKind::Point { p: DVec3::ONE },
                EntityKind::LwPolyline {
                    points: vec![DVec2::ZERO, DVec2::X, DVec2::ONE],
                    bulges: vec![0.0, 0.5, 0.0],
                    closed: true,
                    elevation: 2.0,
                    normal: DVec3::Z,
                },
                EntityKind::Spline {
                    curve: BSpline::new(
                        2,
                        vec![DVec3::ZERO, DVec3::X, DVec3::ONE],
                        None,
                        Some(vec![1.0, 0.5, 1.0]),
                    )
                    .unwrap(),
                    fit_points: vec![],
                    closed: false,
                },
                EntityKind::Face3d {
                    corners: [DVec3::ZERO, DVec3::X, DVec3::ONE, DVec3::Y],
                },
                EntityKind::Text {
                    insert: DVec3::ONE,
                    height: 2.5,
                    value: "hi".into(),
                    rotation: 0.25,
                    style: "Standard".into(),
                },
            ] {
                d.add(Entity::new("L", k).with_color(3)).unwrap();
            }
            d
        };
        for e in d.entities() {
            let g = to_groups(e);
            let Made::Entity(back) = from_groups(&g, "0").unwrap() else {
                panic!()
            };
            match (&e.kind, &back.kind) {
                (EntityKind::Circle { center: a, .. }, EntityKind::Circle { center: b, .. })
                | (EntityKind::Arc { center: a, .. }, EntityKind::Arc { center: b, .. }) => {
                    assert!((*a - *b).length() < 1e-12)
                }
                (a, b) => assert_eq!(a, b),
            }
            assert_eq!((back.layer.as_str(), back.color), ("L", Some(3)));
        }
    }
}
