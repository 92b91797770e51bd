//! CAM profile (R12): strict ezdxf read and clean audit, only LINE/ARC/CIRCLE/POLYLINE, biarcs
//! within tolerance of the spline (sampled densely both ways) and tangent-continuous at joints,
//! closed outlines as single closed polylines, no coincident or overlapping edges.

mod output_support;

use glam::{DVec2, DVec3};
use lispcad::geom::bspline::BSpline;
use lispcad::output::cam::r12_layer_name;
use lispcad::output::{save, Drawing, DxfProfile, Entity, EntityKind, OutputOptions};
use output_support::*;
use serde_json::Value;

fn cam(tol: f64) -> OutputOptions {
    OutputOptions {
        dxf_profile: DxfProfile::Cam,
        cam_tol: tol,
        ..OutputOptions::default()
    }
}

fn write_cam(d: &Drawing, tol: f64) -> Value {
    write_cam_many(&[(d, tol)]).remove(0)
}

/// Write each drawing in the CAM profile, validate them all in one Python run.
fn write_cam_many(jobs: &[(&Drawing, f64)]) -> Vec<Value> {
    let dir = tempfile::tempdir().unwrap();
    let paths: Vec<std::path::PathBuf> = (0..jobs.len())
        .map(|i| dir.path().join(format!("cam{i}.dxf")))
        .collect();
    for ((d, tol), p) in jobs.iter().zip(&paths) {
        save(d, p, &cam(*tol)).unwrap();
    }
    let refs: Vec<&std::path::Path> = paths.iter().map(|p| p.as_path()).collect();
    check_dxf_many(&refs, true)
        .into_iter()
        .map(check_cam)
        .collect()
}

fn check_cam(v: Value) -> Value {
    assert_eq!(v["version"], "AC1009");
    for e in v["entities"].as_array().unwrap() {
        let t = e["type"].as_str().unwrap();
        assert!(
            ["LINE", "ARC", "CIRCLE", "POLYLINE", "TEXT"].contains(&t),
            "CAM wrote {t}"
        );
    }
    assert_eq!(
        v["cam"]["overlaps"].as_array().unwrap().len(),
        0,
        "overlapping edges: {}",
        v["cam"]
    );
    assert_eq!(
        v["cam"]["congruent_edges"], 0,
        "ezdxf found coincident edges"
    );
    v
}

fn xy(v: &Value) -> DVec2 {
    DVec2::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

/// Every read-back edge as a dense polyline.
fn edge_polylines(v: &Value) -> Vec<Vec<DVec2>> {
    let mut out = Vec::new();
    for e in v["entities"].as_array().unwrap() {
        match e["type"].as_str().unwrap() {
            "LINE" => out.push(vec![xy(&e["start"]), xy(&e["end"])]),
            "ARC" | "CIRCLE" => {
                let c = xy(&e["center_wcs"]);
                let r = e["radius"].as_f64().unwrap();
                let (a0, a1) = if e["type"] == "ARC" {
                    let s = e["start_angle"].as_f64().unwrap().to_radians();
                    let mut t = e["end_angle"].as_f64().unwrap().to_radians();
                    while t <= s {
                        t += std::f64::consts::TAU;
                    }
                    (s, t)
                } else {
                    (0.0, std::f64::consts::TAU)
                };
                let n = (((a1 - a0) * (r / 8e-7).sqrt()).ceil() as usize).clamp(4, 20000);
                out.push(dense(|s| c + DVec2::from_angle(a0 + (a1 - a0) * s) * r, n));
            }
            "POLYLINE" => {
                for (a, b, bu) in poly_segments(e) {
                    out.push(bulge_ref(a, b, bu));
                }
            }
            t => panic!("unexpected {t}"),
        }
    }
    out
}

fn poly_segments(e: &Value) -> Vec<(DVec2, DVec2, f64)> {
    let pts = e["points"].as_array().unwrap();
    let n = pts.len();
    let segs = if e["closed"] == true { n } else { n - 1 };
    (0..segs)
        .map(|i| {
            (
                xy(&pts[i]),
                xy(&pts[(i + 1) % n]),
                pts[i][3].as_f64().unwrap(),
            )
        })
        .collect()
}

/// Unit tangents at the start and end of a bulge segment: the chord turned by ∓θ/2.
fn seg_tangents(a: DVec2, b: DVec2, bulge: f64) -> (DVec2, DVec2) {
    let ch = (b - a).normalize();
    let half = 2.0 * bulge.atan();
    (
        DVec2::from_angle(-half).rotate(ch),
        DVec2::from_angle(half).rotate(ch),
    )
}

fn spline_drawing(s: &BSpline, closed: bool) -> Drawing {
    let mut d = Drawing::new();
    d.add_kind(EntityKind::Spline {
        curve: s.clone(),
        fit_points: vec![],
        closed,
    })
    .unwrap();
    d
}

/// A spline with a z wobble: CAM flattens onto XY.
fn wobbly_3d() -> BSpline {
    BSpline::new(
        3,
        (0..9)
            .map(|i| {
                let x = i as f64 * 8.0;
                DVec3::new(x, (x * 0.4).sin() * 15.0, (i % 3) as f64)
            })
            .collect(),
        None,
        None,
    )
    .unwrap()
}

#[test]
fn biarcs_stay_within_tolerance_and_are_tangent_continuous() {
    let cases: Vec<(&str, BSpline, bool)> = vec![
        ("cubic", cubic_s(), false),
        ("quad", quad_wave(), false),
        ("rational", rational_quarter(), false),
        ("closed quad", closed_quad_outline(), true),
        ("3d", wobbly_3d(), false),
    ];
    let tols = [0.1, 0.01, 0.001];
    let drawings: Vec<Drawing> = tols
        .iter()
        .flat_map(|_| {
            cases
                .iter()
                .map(|(_, s, closed)| spline_drawing(s, *closed))
        })
        .collect();
    let jobs: Vec<(&Drawing, f64)> = drawings
        .iter()
        .enumerate()
        .map(|(i, d)| (d, tols[i / cases.len()]))
        .collect();
    let mut results = write_cam_many(&jobs).into_iter();
    for tol in tols {
        for (name, s, closed) in &cases {
            let v = results.next().unwrap();
            let ents = v["entities"].as_array().unwrap();
            assert_eq!(ents.len(), 1, "{name}: one polyline per spline");
            let e = &ents[0];
            assert_eq!(e["type"], "POLYLINE", "{name}");
            assert_eq!(e["closed"], *closed, "{name}");
            // Both ways: spline samples near the arcs, arc samples near the spline.
            let edges = edge_polylines(&v);
            let edge_ix = SegIndex::new(&edges);
            let (a, b) = s.domain();
            let curve: Vec<DVec2> = dense(|t| s.eval_u(a + (b - a) * t).truncate(), 20000);
            let curve_ix = SegIndex::new(std::slice::from_ref(&curve));
            for q in &curve {
                let dist = edge_ix.dist(*q);
                assert!(
                    dist <= tol * (1.0 + 1e-9),
                    "{name} tol {tol}: spline point {q} is {dist} from the arcs"
                );
            }
            // Each edge's own vertices are exact points of the arcs; test a spread of them.
            for q in edges
                .iter()
                .flat_map(|e| e.iter().step_by((e.len() / 64).max(1)))
            {
                let dist = curve_ix.dist(*q);
                assert!(
                    dist <= tol + 1e-5,
                    "{name} tol {tol}: arc point {q} is {dist} from the spline"
                );
            }
            // G1 at every joint (and at the seam of the closed, C1 outline).
            let segs = poly_segments(e);
            let n = segs.len();
            let joints = if *closed { n } else { n - 1 };
            for i in 0..joints {
                let (_, t_in) = seg_tangents(segs[i].0, segs[i].1, segs[i].2);
                let j = (i + 1) % n;
                let (t_out, _) = seg_tangents(segs[j].0, segs[j].1, segs[j].2);
                let ang = t_in.perp_dot(t_out).atan2(t_in.dot(t_out)).abs();
                assert!(
                    ang < 1e-6,
                    "{name} tol {tol}: kink of {ang} rad at joint {i}"
                );
            }
            // Tighter tolerance never needs fewer arcs, and the count stays sane.
            assert!(n < 400, "{name} tol {tol}: {n} segments");
        }
    }
}

#[test]
fn mixed_drawing_is_clean_r12_with_single_closed_outlines() {
    let d = mixed_drawing();
    let v = write_cam(&d, 0.01);
    let ents = v["entities"].as_array().unwrap();
    let closed: Vec<&Value> = ents
        .iter()
        .filter(|e| e["type"] == "POLYLINE" && e["closed"] == true)
        .collect();
    // The closed LWPOLYLINE, the closed 2D POLYLINE and the closed spline: one each.
    assert_eq!(closed.len(), 3);
    let lw = closed
        .iter()
        .find(|e| e["points"].as_array().unwrap().len() == 4)
        .expect("the closed lwpolyline keeps its 4 vertices");
    let want = [
        (0.0, -20.0, 0.0),
        (30.0, -20.0, 0.5),
        (30.0, -10.0, 0.0),
        (0.0, -10.0, -0.3),
    ];
    for (g, w) in lw["points"].as_array().unwrap().iter().zip(want) {
        assert_eq!(
            (
                g[0].as_f64().unwrap(),
                g[1].as_f64().unwrap(),
                g[3].as_f64().unwrap()
            ),
            w
        );
    }
    assert!(ents.iter().any(|e| e["type"] == "CIRCLE"));
    // Mirrored arc (extrusion -Z) comes out as a plain counter-clockwise ARC in XY covering the
    // same points: start (36, 30), end (40, 34).
    let arcs: Vec<&Value> = ents.iter().filter(|e| e["type"] == "ARC").collect();
    let mirrored = arcs
        .iter()
        .find(|e| (xy(&e["center_wcs"]) - DVec2::new(40.0, 30.0)).length() < 1e-12)
        .unwrap();
    assert_eq!(mirrored["extrusion"][2], 1.0);
    let s = mirrored["start_angle"].as_f64().unwrap();
    let t = mirrored["end_angle"].as_f64().unwrap();
    assert!(
        (s - 90.0).abs() < 1e-9 && (t - 180.0).abs() < 1e-9,
        "{s} {t}"
    );
    // Layers are R12 names; text only on a layer of its own (0_TEXT: layer 0 also cuts).
    for e in ents {
        let l = e["layer"].as_str().unwrap();
        if e["type"] == "TEXT" {
            assert_eq!(l, "0_TEXT");
        } else {
            assert!(["0", "OUTLINE", "CONSTRUCTION"].contains(&l), "{l}");
        }
    }
    assert_eq!(r12_layer_name("Outline"), "OUTLINE");
}

#[test]
fn duplicates_and_overlaps_are_removed() {
    let mut d = Drawing::new();
    let line = |a: (f64, f64), b: (f64, f64)| EntityKind::Line {
        p0: DVec3::new(a.0, a.1, 0.0),
        p1: DVec3::new(b.0, b.1, 0.0),
    };
    d.add_kind(line((0.0, 0.0), (10.0, 0.0))).unwrap();
    d.add_kind(line((0.0, 0.0), (10.0, 0.0))).unwrap(); // same line twice
    d.add_kind(line((10.0, 0.0), (0.0, 0.0))).unwrap(); // reversed duplicate
    d.add_kind(line((2.0, 0.0), (7.0, 0.0))).unwrap(); // covered
    d.add_kind(line((5.0, 0.0), (20.0, 0.0))).unwrap(); // overlapping: 10..20 survives
    let arc = |s: f64, e: f64| EntityKind::Arc {
        center: DVec3::new(50.0, 0.0, 0.0),
        radius: 5.0,
        start: s,
        end: e,
        normal: DVec3::Z,
    };
    d.add_kind(arc(0.0, 2.0)).unwrap();
    d.add_kind(arc(0.0, 2.0)).unwrap(); // duplicate arc
    d.add_kind(arc(1.0, 3.0)).unwrap(); // overlapping arc: 2..3 survives
    let circle = EntityKind::Circle {
        center: DVec3::new(80.0, 0.0, 0.0),
        radius: 4.0,
        normal: DVec3::Z,
    };
    d.add_kind(circle.clone()).unwrap();
    d.add_kind(circle).unwrap(); // duplicate circle
    d.add_kind(EntityKind::Arc {
        center: DVec3::new(80.0, 0.0, 0.0),
        radius: 4.0,
        start: 1.0,
        end: 2.0,
        normal: DVec3::Z,
    })
    .unwrap(); // arc on the circle
    let square = |rev: bool| {
        let mut p = vec![
            DVec2::new(100.0, 0.0),
            DVec2::new(110.0, 0.0),
            DVec2::new(110.0, 10.0),
            DVec2::new(100.0, 10.0),
        ];
        if rev {
            p.reverse();
        }
        EntityKind::LwPolyline {
            points: p,
            bulges: vec![],
            closed: true,
            elevation: 0.0,
            normal: DVec3::Z,
        }
    };
    d.add_kind(square(false)).unwrap();
    d.add_kind(square(true)).unwrap(); // the same outline traced backwards
    d.add_kind(line((110.0, 2.0), (110.0, 8.0))).unwrap(); // on the outline's edge
    d.add(Entity::new("0", line((200.0, 0.0), (210.0, 0.0))).with_color(1))
        .unwrap();

    let v = write_cam(&d, 0.01);
    let ents = v["entities"].as_array().unwrap();
    let count = |t: &str| ents.iter().filter(|e| e["type"] == t).count();
    assert_eq!(count("CIRCLE"), 1);
    assert_eq!(count("POLYLINE"), 1);
    assert_eq!(count("ARC"), 2, "{ents:?}");
    assert_eq!(count("LINE"), 3, "{ents:?}");
    let lines: Vec<(DVec2, DVec2)> = ents
        .iter()
        .filter(|e| e["type"] == "LINE")
        .map(|e| (xy(&e["start"]), xy(&e["end"])))
        .collect();
    assert_eq!(lines[0], (DVec2::new(0.0, 0.0), DVec2::new(10.0, 0.0)));
    assert_eq!(lines[1], (DVec2::new(10.0, 0.0), DVec2::new(20.0, 0.0)));
    // Open paths are cut before closed outlines: the coloured line is the last open one.
    let coloured = ents
        .iter()
        .find(|e| e["type"] == "LINE" && xy(&e["start"]) == DVec2::new(200.0, 0.0))
        .unwrap();
    assert_eq!(coloured["color"], 1, "colour kept");
    let arcs: Vec<(f64, f64)> = ents
        .iter()
        .filter(|e| e["type"] == "ARC")
        .map(|e| {
            (
                e["start_angle"].as_f64().unwrap(),
                e["end_angle"].as_f64().unwrap(),
            )
        })
        .collect();
    assert!((arcs[0].0 - 0.0).abs() < 1e-9 && (arcs[0].1 - 2f64.to_degrees()).abs() < 1e-9);
    assert!(
        (arcs[1].0 - 2f64.to_degrees()).abs() < 1e-9
            && (arcs[1].1 - 3f64.to_degrees()).abs() < 1e-9
    );
}

#[test]
fn tilted_circle_becomes_one_closed_outline_within_tolerance() {
    let mut d = Drawing::new();
    let n = DVec3::new(0.4, 0.1, 1.0);
    let (c, r) = (DVec3::new(10.0, 5.0, 2.0), 6.0);
    d.add_kind(EntityKind::Circle {
        center: c,
        radius: r,
        normal: n,
    })
    .unwrap();
    let tol = 0.005;
    let v = write_cam(&d, tol);
    let ents = v["entities"].as_array().unwrap();
    assert_eq!(ents.len(), 1);
    assert_eq!(ents[0]["closed"], true);
    let (ax, ay) = lispcad::geom::frame::arbitrary_axis(n);
    let ellipse = dense(
        |t| {
            let a = t * std::f64::consts::TAU;
            (c + (ax * a.cos() + ay * a.sin()) * r).truncate()
        },
        20000,
    );
    let edges = edge_polylines(&v);
    let ix = SegIndex::new(&edges);
    for q in &ellipse {
        assert!(ix.dist(*q) <= tol * (1.0 + 1e-9));
    }
}

#[test]
fn bad_tolerance_is_refused() {
    let d = mixed_drawing();
    let dir = tempfile::tempdir().unwrap();
    for t in [0.0, -1.0, f64::NAN] {
        let r = save(&d, &dir.path().join("a.dxf"), &cam(t));
        assert!(r.unwrap_err().to_string().contains("cam_tol"));
    }
}
