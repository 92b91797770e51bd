//! The entity factory: the entity kinds lispcad models, built from their group lists; every
//! other type becomes `EntityKind::Unmodelled` (its groups stay in the source record).

use glam::{DVec2, DVec3};

use crate::geom::bspline::BSpline;
use crate::geom::frame::Ocs;
use crate::output::drawing::{Entity, EntityKind, Layer};
use crate::output::record::TagList;

/// Groups any entity may carry (AcDbEntity, handles, owners, colours, line styles...).
pub fn common_code(code: i32) -> bool {
    matches!(
        code,
        5 | 6
            | 8
            | 48
            | 60
            | 62
            | 67
            | 92
            | 100
            | 102
            | 160
            | 284
            | 310
            | 330
            | 347
            | 348
            | 360
            | 370
            | 380
            | 390
            | 410
            | 420
            | 430
            | 440
            | 999
    )
}

/// The groups a modelled entity type may have beyond the common ones; `None` for types the
/// reader keeps without checking.
pub fn allowed_codes(ty: &str) -> Option<fn(i32) -> bool> {
    fn ext(c: i32) -> bool {
        matches!(c, 39 | 210 | 220 | 230)
    }
    Some(match ty {
        "LINE" => |c| matches!(c, 10 | 20 | 30 | 11 | 21 | 31) || ext(c),
        "CIRCLE" => |c| matches!(c, 10 | 20 | 30 | 40) || ext(c),
        "ARC" => |c| matches!(c, 10 | 20 | 30 | 40 | 50 | 51) || ext(c),
        "POINT" => |c| matches!(c, 10 | 20 | 30 | 50) || ext(c),
        "LWPOLYLINE" => |c| matches!(c, 10 | 20 | 38 | 40 | 41 | 42 | 43 | 70 | 90 | 91) || ext(c),
        "POLYLINE" => |c| matches!(c, 10 | 20 | 30 | 40 | 41 | 66 | 70..=75) || ext(c),
        "VERTEX" => |c| matches!(c, 10 | 20 | 30 | 40 | 41 | 42 | 50 | 70..=74 | 91),
        "SEQEND" => |_| false,
        "SPLINE" => |c| matches!(c, 10..=13 | 20..=23 | 30..=33 | 40..=44 | 70..=74) || ext(c),
        "3DFACE" => |c| matches!(c, 10..=13 | 20..=23 | 30..=33 | 70),
        "TEXT" => |c| {
            matches!(
                c,
                1 | 7 | 10 | 20 | 30 | 11 | 21 | 31 | 40 | 41 | 50 | 51 | 71..=74
            ) || ext(c)
        },
        "ELLIPSE" => |c| matches!(c, 10 | 20 | 30 | 11 | 21 | 31 | 40..=42) || ext(c),
        _ => return None,
    })
}

/// A layer-table record as a layer.
pub fn layer(r: &TagList) -> Option<Layer> {
    let name = r.get(2)?.to_string();
    let flags = int(r, 70).unwrap_or(0);
    let color = int(r, 62).unwrap_or(7) as i16;
    Some(Layer {
        name,
        color: if color == 0 { 7 } else { color },
        linetype: r.get(6).unwrap_or("Continuous").to_string(),
        frozen: flags & 1 != 0,
        locked: flags & 4 != 0,
    })
}

fn int(r: &TagList, code: i32) -> Option<i64> {
    let v = r.get(code)?.trim();
    v.parse::<i64>()
        .ok()
        .or_else(|| v.parse::<f64>().ok().map(|x| x as i64))
}

/// The groups of the first record of a group list, with helpers to read typed values.
struct Fields<'a> {
    tags: Vec<(i32, &'a str)>,
}

impl<'a> Fields<'a> {
    fn of(t: &'a TagList, range: std::ops::Range<usize>) -> Fields<'a> {
        Fields {
            // Stop at extended data: its 1010 points are not the entity's.
            tags: range
                .map(|i| t.at(i))
                .take_while(|(c, _)| *c < 1000)
                .collect(),
        }
    }

    fn f(&self, code: i32) -> Option<f64> {
        let v = self.tags.iter().find(|(c, _)| *c == code)?.1;
        v.trim().parse().ok()
    }

    fn fd(&self, code: i32, d: f64) -> f64 {
        self.f(code).unwrap_or(d)
    }

    fn i(&self, code: i32) -> i64 {
        self.f(code).map_or(0, |x| x as i64)
    }

    fn s(&self, code: i32) -> Option<&'a str> {
        self.tags.iter().find(|(c, _)| *c == code).map(|(_, v)| *v)
    }

    fn p(&self, code: i32) -> DVec3 {
        DVec3::new(
            self.fd(code, 0.0),
            self.fd(code + 10, 0.0),
            self.fd(code + 20, 0.0),
        )
    }

    fn normal(&self) -> DVec3 {
        let n = DVec3::new(self.fd(210, 0.0), self.fd(220, 0.0), self.fd(230, 1.0));
        if n.is_finite() && n.length() > 1e-12 {
            n.normalize()
        } else {
            DVec3::Z
        }
    }

    /// Every point of a code in order (LWPOLYLINE vertices, SPLINE control points...), with
    /// the groups that follow each one until the next (bulges).
    fn points(&self, code: i32) -> Vec<DVec3> {
        let mut out: Vec<DVec3> = Vec::new();
        for (c, v) in &self.tags {
            let x: f64 = v.trim().parse().unwrap_or(0.0);
            if *c == code {
                out.push(DVec3::new(x, 0.0, 0.0));
            } else if *c == code + 10 {
                if let Some(p) = out.last_mut() {
                    p.y = x;
                }
            } else if *c == code + 20 {
                if let Some(p) = out.last_mut() {
                    p.z = x;
                }
            }
        }
        out
    }

    fn all(&self, code: i32) -> Vec<f64> {
        self.tags
            .iter()
            .filter(|(c, _)| *c == code)
            .map(|(_, v)| v.trim().parse().unwrap_or(0.0))
            .collect()
    }
}

/// The record ranges of a group list: the entity and its VERTEX/ATTRIB/SEQEND followers.
pub fn record_ranges(t: &TagList) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..t.len() {
        if t.at(i).0 == 0 {
            out.push(start..i);
            start = i;
        }
    }
    out.push(start..t.len());
    out
}

/// The entity of a group list: modelled kinds parsed, the rest `Unmodelled`. Geometry that
/// does not pass the model's checks is kept unmodelled too, so it is still written back.
pub fn entity(t: &TagList) -> Entity {
    let ranges = record_ranges(t);
    let f = Fields::of(t, ranges[0].clone());
    let ty = t.type_name();
    let layer = f.s(8).unwrap_or("0");
    let color = f
        .s(62)
        .and_then(|v| v.trim().parse::<i16>().ok())
        .filter(|c| (0..256).contains(c));
    let kind = kind(ty, &f, t, &ranges)
        .filter(|k| k.validate().is_ok())
        .unwrap_or_else(|| EntityKind::Unmodelled {
            dxf_type: ty.to_string(),
        });
    let mut e = Entity::new(layer, kind);
    e.color = color;
    e.handle = t.handle().unwrap_or(0);
    e
}

fn kind(
    ty: &str,
    f: &Fields,
    t: &TagList,
    ranges: &[std::ops::Range<usize>],
) -> Option<EntityKind> {
    let ocs_point = |p: DVec3, n: DVec3| {
        if n == DVec3::Z {
            p
        } else {
            Ocs::new(n).to_wcs(p.truncate(), p.z)
        }
    };
    Some(match ty {
        "LINE" => EntityKind::Line {
            p0: f.p(10),
            p1: f.p(11),
        },
        "CIRCLE" => {
            let n = f.normal();
            EntityKind::Circle {
                center: ocs_point(f.p(10), n),
                radius: f.f(40)?,
                normal: n,
            }
        }
        "ARC" => {
            let n = f.normal();
            EntityKind::Arc {
                center: ocs_point(f.p(10), n),
                radius: f.f(40)?,
                start: f.fd(50, 0.0).to_radians(),
                end: f.fd(51, 0.0).to_radians(),
                normal: n,
            }
        }
        "POINT" => EntityKind::Point { p: f.p(10) },
        "LWPOLYLINE" => {
            let mut points = Vec::new();
            let mut bulges = Vec::new();
            for (c, v) in &f.tags {
                let x: f64 = v.trim().parse().unwrap_or(0.0);
                match c {
                    10 => {
                        points.push(DVec2::new(x, 0.0));
                        bulges.push(0.0);
                    }
                    20 => {
                        if let Some(p) = points.last_mut() {
                            p.y = x;
                        }
                    }
                    42 => {
                        if let Some(b) = bulges.last_mut() {
                            *b = x;
                        }
                    }
                    _ => {}
                }
            }
            if bulges.iter().all(|b| *b == 0.0) {
                bulges.clear();
            }
            EntityKind::LwPolyline {
                points,
                bulges,
                closed: f.i(70) & 1 != 0,
                elevation: f.fd(38, 0.0),
                normal: f.normal(),
            }
        }
        "POLYLINE" => {
            let flags = f.i(70);
            // Polygon meshes (16) and polyface meshes (64) stay unmodelled.
            if flags & (16 | 64) != 0 {
                return None;
            }
            let is3d = flags & 8 != 0;
            let n = f.normal();
            let elevation = f.p(10).z;
            let mut points = Vec::new();
            let mut bulges = Vec::new();
            for r in &ranges[1..] {
                if t.at(r.start).1 != "VERTEX" {
                    continue;
                }
                let v = Fields::of(t, r.clone());
                let p = v.p(10);
                points.push(if is3d {
                    p
                } else {
                    ocs_point(DVec3::new(p.x, p.y, elevation), n)
                });
                bulges.push(if is3d { 0.0 } else { v.fd(42, 0.0) });
            }
            if bulges.iter().all(|b| *b == 0.0) {
                bulges.clear();
            }
            // The model's POLYLINE is WCS; a tilted 2D one keeps its bulges only when flat.
            if !is3d && n != DVec3::Z && !bulges.is_empty() {
                return None;
            }
            EntityKind::Polyline {
                points,
                bulges,
                closed: flags & 1 != 0,
            }
        }
        "SPLINE" => {
            let degree = f.i(71);
            if !(1..=32).contains(&degree) {
                return None;
            }
            let degree = degree as usize;
            let ctrl = f.points(10);
            let knots = f.all(40);
            let weights = f.all(41);
            let weights = (weights.len() == ctrl.len() && weights.iter().any(|w| *w != 1.0))
                .then_some(weights);
            let curve = BSpline::new(degree, ctrl, Some(knots), weights).ok()?;
            EntityKind::Spline {
                curve,
                fit_points: f.points(11),
                closed: f.i(70) & 1 != 0,
            }
        }
        "3DFACE" => EntityKind::Face3d {
            corners: [f.p(10), f.p(11), f.p(12), f.p(13)],
        },
        "TEXT" => EntityKind::Text {
            insert: f.p(10),
            height: f.f(40)?,
            value: f.s(1).unwrap_or("").to_string(),
            rotation: f.fd(50, 0.0).to_radians(),
            style: f.s(7).unwrap_or("Standard").to_string(),
        },
        "ELLIPSE" => EntityKind::Ellipse {
            center: f.p(10),
            major: f.p(11),
            normal: f.normal(),
            ratio: f.f(40)?,
            start: f.fd(41, 0.0),
            end: f.fd(42, std::f64::consts::TAU),
        },
        _ => return None,
    })
}
