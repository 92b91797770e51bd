//! CAD-profile DXF (R2000): every file is read back with ezdxf's strict reader, audited (0
//! errors, 0 fixes, no loader warnings), and its entities compared with what was drawn.

mod output_support;

use glam::{DVec2, DVec3};
use lispcad::geom::bspline::BSpline;
use lispcad::geom::frame::arbitrary_axis;
use lispcad::output::{
    render, save, Drawing, Entity, EntityKind, Format, Layer, OutputError, OutputOptions,
};
use output_support::*;
use serde_json::Value;

const TOL: f64 = 1e-9;

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn p3(v: &Value) -> DVec3 {
    DVec3::new(f(&v[0]), f(&v[1]), f(&v[2]))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= TOL * (1.0 + a.abs().max(b.abs()))
}

fn close3(a: DVec3, b: DVec3) -> bool {
    close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z)
}

fn deg(a: f64) -> f64 {
    a.to_degrees().rem_euclid(360.0)
}

fn same_angle_deg(a: f64, b: f64) -> bool {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d) <= 1e-9
}

/// Compare one read-back entity with the drawn one.
fn compare(drawn: &Entity, got: &Value) {
    let ctx = format!("entity {:X} {:?} vs {got}", drawn.handle, drawn.kind);
    assert_eq!(got["layer"], drawn.layer.as_str(), "{ctx}");
    match drawn.color {
        Some(c) => assert_eq!(got["color"], c as i64, "{ctx}"),
        None => assert!(got["color"].is_null() || got["color"] == 256, "{ctx}"),
    }
    match &drawn.kind {
        EntityKind::Line { p0, p1 } => {
            assert_eq!(got["type"], "LINE", "{ctx}");
            assert!(
                close3(p3(&got["start"]), *p0) && close3(p3(&got["end"]), *p1),
                "{ctx}"
            );
        }
        EntityKind::Circle {
            center,
            radius,
            normal,
        } => {
            assert_eq!(got["type"], "CIRCLE", "{ctx}");
            assert!(close3(p3(&got["center_wcs"]), *center), "{ctx}");
            assert!(close(f(&got["radius"]), *radius), "{ctx}");
            assert!(close3(p3(&got["extrusion"]), normal.normalize()), "{ctx}");
        }
        EntityKind::Arc {
            center,
            radius,
            start,
            end,
            normal,
        } => {
            assert_eq!(got["type"], "ARC", "{ctx}");
            assert!(close3(p3(&got["center_wcs"]), *center), "{ctx}");
            assert!(close(f(&got["radius"]), *radius), "{ctx}");
            assert!(close3(p3(&got["extrusion"]), normal.normalize()), "{ctx}");
            assert!(same_angle_deg(f(&got["start_angle"]), deg(*start)), "{ctx}");
            assert!(same_angle_deg(f(&got["end_angle"]), deg(*end)), "{ctx}");
        }
        EntityKind::Point { p } => {
            assert_eq!(got["type"], "POINT", "{ctx}");
            assert!(close3(p3(&got["location"]), *p), "{ctx}");
        }
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            elevation,
            normal,
        } => {
            assert_eq!(got["type"], "LWPOLYLINE", "{ctx}");
            assert_eq!(got["closed"], *closed, "{ctx}");
            assert!(close(f(&got["elevation"]), *elevation), "{ctx}");
            assert!(close3(p3(&got["extrusion"]), normal.normalize()), "{ctx}");
            let gp = got["points"].as_array().unwrap();
            assert_eq!(gp.len(), points.len(), "{ctx}");
            for (i, (p, g)) in points.iter().zip(gp).enumerate() {
                assert!(close(f(&g[0]), p.x) && close(f(&g[1]), p.y), "{ctx}");
                let b = bulges.get(i).copied().unwrap_or(0.0);
                assert!(close(f(&g[2]), b), "{ctx}");
            }
        }
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } => {
            assert_eq!(got["type"], "POLYLINE", "{ctx}");
            assert_eq!(got["closed"], *closed, "{ctx}");
            let flat = points.iter().all(|p| p.z == points[0].z);
            assert_eq!(got["is_3d"], !flat, "{ctx}");
            let gp = got["points"].as_array().unwrap();
            assert_eq!(gp.len(), points.len(), "{ctx}");
            for (i, (p, g)) in points.iter().zip(gp).enumerate() {
                assert!(close3(p3(g), *p), "{ctx}");
                if flat {
                    let b = bulges.get(i).copied().unwrap_or(0.0);
                    assert!(close(f(&g[3]), b), "{ctx}");
                }
            }
        }
        EntityKind::Spline { curve, .. } => {
            assert_eq!(got["type"], "SPLINE", "{ctx}");
            assert_eq!(got["degree"], curve.degree as i64, "{ctx}");
            let knots: Vec<f64> = got["knots"].as_array().unwrap().iter().map(f).collect();
            assert_eq!(knots.len(), curve.knots.len(), "{ctx}");
            assert!(
                knots.iter().zip(&curve.knots).all(|(a, b)| close(*a, *b)),
                "{ctx}"
            );
            let cps = got["control_points"].as_array().unwrap();
            assert_eq!(cps.len(), curve.ctrl.len(), "{ctx}");
            assert!(
                cps.iter().zip(&curve.ctrl).all(|(g, p)| close3(p3(g), *p)),
                "{ctx}"
            );
            let ws: Vec<f64> = got["weights"].as_array().unwrap().iter().map(f).collect();
            match &curve.weights {
                Some(w) => assert!(
                    ws.len() == w.len() && ws.iter().zip(w).all(|(a, b)| close(*a, *b)),
                    "{ctx}"
                ),
                None => assert!(ws.is_empty(), "{ctx}"),
            }
        }
        EntityKind::Face3d { corners } => {
            assert_eq!(got["type"], "3DFACE", "{ctx}");
            let gc = got["corners"].as_array().unwrap();
            assert!(
                gc.iter().zip(corners).all(|(g, c)| close3(p3(g), *c)),
                "{ctx}"
            );
        }
        EntityKind::Text {
            insert,
            height,
            value,
            rotation,
            ..
        } => {
            assert_eq!(got["type"], "TEXT", "{ctx}");
            assert!(close3(p3(&got["insert"]), *insert), "{ctx}");
            assert!(close(f(&got["height"]), *height), "{ctx}");
            assert_eq!(got["text"], value.as_str(), "{ctx}");
            assert!(same_angle_deg(f(&got["rotation"]), deg(*rotation)), "{ctx}");
        }
        EntityKind::Mesh { .. } => unreachable!("meshes are compared face by face"),
        EntityKind::Ellipse { .. } => assert_eq!(got["type"], "ELLIPSE", "{ctx}"),
        EntityKind::Unmodelled { .. } => unreachable!("drawings made here model every entity"),
    }
}

/// Write `d`, read it back, and compare every entity and layer.
fn round_trip(d: &Drawing, name: &str) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    save(d, &path, &OutputOptions::default()).unwrap();
    let v = check_dxf(&path, false);
    assert_eq!(v["version"], "AC1015");
    assert_eq!(v["insunits"], 4);
    let got = v["entities"].as_array().unwrap();
    let mut k = 0;
    for e in d.entities() {
        if let EntityKind::Mesh {
            vertices,
            triangles,
        } = &e.kind
        {
            for (i, t) in triangles.iter().enumerate() {
                let g = &got[k];
                assert_eq!(g["type"], "3DFACE");
                assert_eq!(g["layer"], e.layer.as_str());
                if i == 0 {
                    assert_eq!(g["handle"], format!("{:X}", e.handle));
                }
                let gc = g["corners"].as_array().unwrap();
                for (j, vi) in [t[0], t[1], t[2], t[2]].iter().enumerate() {
                    assert!(close3(p3(&gc[j]), vertices[*vi]));
                }
                k += 1;
            }
            continue;
        }
        assert_eq!(got[k]["handle"], format!("{:X}", e.handle));
        compare(e, &got[k]);
        k += 1;
    }
    assert_eq!(k, got.len(), "extra entities read back");
    // Layers: every drawn layer with its colour and line type (ezdxf adds Defpoints).
    let layers = v["layers"].as_array().unwrap();
    for l in d.layers() {
        let g = layers
            .iter()
            .find(|g| g["name"] == l.name.as_str())
            .unwrap_or_else(|| panic!("layer {} missing", l.name));
        assert_eq!(g["color"], l.color as i64);
        assert!(g["linetype"]
            .as_str()
            .unwrap()
            .eq_ignore_ascii_case(&l.linetype));
    }
    v
}

#[test]
fn mixed_drawing_reads_back_exactly() {
    round_trip(&mixed_drawing(), "mixed.dxf");
}

#[test]
fn empty_drawing_is_valid() {
    let v = round_trip(&Drawing::new(), "empty.dxf");
    assert_eq!(v["entities"].as_array().unwrap().len(), 0);
}

/// A small deterministic generator (no external RNG needed for a fixed corpus).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn coord(&mut self) -> f64 {
        // Mix of magnitudes: tiny, ordinary, large, and values with long decimal expansions.
        match (self.next() * 4.0) as u32 {
            0 => (self.next() - 0.5) * 1e-7,
            1 => (self.next() - 0.5) * 1e6,
            2 => (self.next() * 1000.0).round() / 10.0,
            _ => (self.next() - 0.5) * 300.0,
        }
    }
    fn p(&mut self) -> DVec3 {
        DVec3::new(self.coord(), self.coord(), self.coord())
    }
    fn normal(&mut self) -> DVec3 {
        match (self.next() * 3.0) as u32 {
            0 => DVec3::Z,
            1 => -DVec3::Z,
            _ => DVec3::new(
                self.next() - 0.5,
                self.next() - 0.5,
                self.next() - 0.5 + 0.1,
            ),
        }
    }
}

#[test]
fn random_entities_round_trip_to_full_precision() {
    let mut r = Lcg(42);
    let mut d = Drawing::new();
    for i in 0..40 {
        d.use_layer(&format!("L{i}"), Some(1 + (i % 255) as i16))
            .unwrap();
    }
    for i in 0..600 {
        let layer = format!("L{}", i % 40);
        let kind = match i % 8 {
            0 => EntityKind::Line {
                p0: r.p(),
                p1: r.p(),
            },
            1 => EntityKind::Circle {
                center: r.p(),
                radius: 0.001 + r.next() * 100.0,
                normal: r.normal(),
            },
            2 => EntityKind::Arc {
                center: r.p(),
                radius: 0.001 + r.next() * 100.0,
                start: r.next() * 7.0 - 0.5,
                end: r.next() * 7.0,
                normal: r.normal(),
            },
            3 => EntityKind::LwPolyline {
                points: (0..5).map(|_| DVec2::new(r.coord(), r.coord())).collect(),
                bulges: (0..5).map(|_| r.next() * 2.0 - 1.0).collect(),
                closed: r.next() < 0.5,
                elevation: r.coord(),
                normal: r.normal(),
            },
            4 => EntityKind::Point { p: r.p() },
            5 => {
                let n = 4 + (r.next() * 4.0) as usize;
                let ctrl: Vec<DVec3> = (0..n).map(|_| r.p()).collect();
                let weights = (r.next() < 0.3).then(|| (0..n).map(|_| 0.2 + r.next()).collect());
                EntityKind::Spline {
                    curve: BSpline::new(1 + (i / 8) % 3, ctrl, None, weights).unwrap(),
                    fit_points: vec![],
                    closed: false,
                }
            }
            6 => EntityKind::Polyline {
                points: (0..4).map(|_| r.p()).collect(),
                bulges: vec![],
                closed: r.next() < 0.5,
            },
            _ => EntityKind::Text {
                insert: r.p(),
                height: 0.1 + r.next() * 10.0,
                value: format!("t{i} <&> \"q\""),
                rotation: r.next() * 6.0,
                style: "Standard".into(),
            },
        };
        let mut e = Entity::new(&layer, kind);
        if i % 5 == 0 {
            e.color = Some(1 + (i % 250) as i16);
        }
        d.add(e).unwrap();
    }
    round_trip(&d, "random.dxf");
}

#[test]
fn ocs_arcs_land_where_they_were_drawn() {
    // The arc's start point in WCS read back through ezdxf's OCS must equal ours.
    let mut d = Drawing::new();
    let n = DVec3::new(0.3, -0.5, 0.8);
    d.add_kind(EntityKind::Arc {
        center: DVec3::new(10.0, 20.0, 30.0),
        radius: 4.0,
        start: 0.25,
        end: 1.5,
        normal: n,
    })
    .unwrap();
    let v = round_trip(&d, "ocs.dxf");
    let g = &v["entities"][0];
    let c_ocs = p3(&g["center_ocs"]);
    let (ax, ay) = arbitrary_axis(n);
    let nz = n.normalize();
    let c_wcs = ax * c_ocs.x + ay * c_ocs.y + nz * c_ocs.z;
    assert!(close3(c_wcs, DVec3::new(10.0, 20.0, 30.0)));
}

#[test]
fn unicode_and_odd_names_survive() {
    let mut d = Drawing::new();
    d.set_layer_record(Layer {
        color: 30,
        linetype: "DASHED".into(),
        ..Layer::new("Ébauche 1")
    })
    .unwrap();
    d.add(Entity::new(
        "Ébauche 1",
        EntityKind::Text {
            insert: DVec3::ZERO,
            height: 2.5,
            value: "Ø 5 — ok, α ≤ β".into(),
            rotation: 0.5,
            style: "Standard".into(),
        },
    ))
    .unwrap();
    round_trip(&d, "unicode.dxf");
}

#[test]
fn output_is_deterministic() {
    let d = mixed_drawing();
    let o = OutputOptions::default();
    assert_eq!(
        render(&d, Format::Dxf, &o).unwrap(),
        render(&d, Format::Dxf, &o).unwrap()
    );
}

#[test]
fn handles_are_unique_and_below_handseed() {
    let d = mixed_drawing();
    let s = String::from_utf8(render(&d, Format::Dxf, &OutputOptions::default()).unwrap()).unwrap();
    let lines: Vec<&str> = s.lines().collect();
    let mut handles = Vec::new();
    let mut seed = 0;
    let body = lines.iter().position(|l| *l == "ENDSEC").unwrap() + 1;
    for w in lines[body..].chunks(2) {
        let (code, val) = (w[0].trim(), w[1]);
        if code == "5" || code == "105" {
            handles.push(u64::from_str_radix(val, 16).unwrap());
        }
    }
    for (i, l) in lines.iter().enumerate() {
        if *l == "$HANDSEED" {
            seed = u64::from_str_radix(lines[i + 2], 16).unwrap();
        }
    }
    let n = handles.len();
    handles.sort();
    handles.dedup();
    assert_eq!(handles.len(), n, "duplicate handles");
    assert!(handles.iter().all(|h| *h > 0 && *h < seed));
}

#[test]
fn save_errors_are_clear_and_leave_nothing() {
    let d = mixed_drawing();
    let dir = tempfile::tempdir().unwrap();
    let bad = save(&d, &dir.path().join("a.jpg"), &OutputOptions::default());
    assert!(matches!(bad, Err(OutputError::UnknownFormat(_))));
    assert!(bad
        .unwrap_err()
        .to_string()
        .contains(".svg, .dxf, .pdf or .png"));
    let missing = save(
        &d,
        &dir.path().join("no/such/a.dxf"),
        &OutputOptions::default(),
    );
    assert!(matches!(missing, Err(OutputError::Io { .. })));
    let tol = save(
        &d,
        &dir.path().join("a.dxf"),
        &OutputOptions {
            cam_tol: 0.0,
            ..OutputOptions::default()
        },
    );
    assert!(matches!(tol, Err(OutputError::BadTolerance(_))));
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn a_corrupted_entity_is_an_error_not_a_file() {
    let mut d = mixed_drawing();
    let h = d.first().unwrap();
    if let EntityKind::Line { p0, .. } = &mut d.get_mut(h).unwrap().kind {
        p0.x = f64::NAN;
    }
    let dir = tempfile::tempdir().unwrap();
    let r = save(&d, &dir.path().join("a.dxf"), &OutputOptions::default());
    assert!(matches!(r, Err(OutputError::BadEntity { .. })));
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}
