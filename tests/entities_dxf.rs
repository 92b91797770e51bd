//! AutoLISP-style scripts (entmake, command) run through the `lispcad` binary with `-o x.dxf`;
//! the file is read back by ezdxf's strict reader and audited (0 errors, 0 fixes), and the
//! entities' types, layers, coordinates (1e-9) and closedness compared with what the script
//! asked for.

mod output_support;

use std::path::Path;
use std::process::Command;

use output_support::*;
use serde_json::Value;

const TOL: f64 = 1e-9;

fn run_script(dir: &Path, name: &str, script: &str) -> Value {
    let lsp = dir.join(format!("{name}.lsp"));
    let dxf = dir.join(format!("{name}.dxf"));
    std::fs::write(&lsp, script).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("run")
        .arg(&lsp)
        .arg("-o")
        .arg(&dxf)
        .output()
        .expect("running lispcad");
    assert!(
        out.status.success(),
        "lispcad run {name} failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    check_dxf(&dxf, false)
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn near(a: &Value, b: &[f64]) -> bool {
    let a = a.as_array().unwrap_or_else(|| panic!("not an array: {a}"));
    a.len() >= b.len() && b.iter().zip(a).all(|(x, y)| (x - f(y)).abs() <= TOL)
}

fn assert_pt(got: &Value, want: &[f64], ctx: &str) {
    assert!(near(got, want), "{ctx}: got {got}, want {want:?}");
}

fn ents(doc: &Value) -> &Vec<Value> {
    doc["entities"].as_array().unwrap()
}

fn layer_color(doc: &Value, name: &str) -> i64 {
    doc["layers"]
        .as_array()
        .unwrap()
        .iter()
        .find(|l| l["name"] == name)
        .unwrap_or_else(|| panic!("no layer {name} in {}", doc["layers"]))["color"]
        .as_i64()
        .unwrap()
}

#[test]
fn entmake_entities_read_back_through_ezdxf() {
    let dir = tempfile::tempdir().unwrap();
    let doc = run_script(
        dir.path(),
        "entmake",
        r#"
(entmake '((0 . "LAYER") (2 . "Outline") (70 . 0) (62 . 1) (6 . "Continuous")))
(entmake '((0 . "LINE") (8 . "Outline") (10 0.5 0.25 0) (11 10.125 5 1)))
(entmake '((0 . "CIRCLE") (8 . "Holes") (62 . 3) (10 5 5 0) (40 . 2.5)))
(entmake '((0 . "ARC") (10 1 2 0) (40 . 3.0) (50 . 0.5) (51 . 2.0)))
(entmake '((0 . "POINT") (10 1 2 3)))
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 4) (70 . 1)
           (10 0 0) (42 . 0.5) (10 10 0) (10 10 10) (42 . -0.25) (10 0 10)))
(entmake '((0 . "POLYLINE") (8 . "Outline") (66 . 1) (70 . 1)))
(entmake '((0 . "VERTEX") (10 20 0 0)))
(entmake '((0 . "VERTEX") (10 25 0 0) (42 . 1.0)))
(entmake '((0 . "VERTEX") (10 25 5 0)))
(entmake '((0 . "SEQEND")))
(entmake '((0 . "SPLINE") (70 . 8) (71 . 3) (72 . 8) (73 . 4) (74 . 0)
           (40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 0.0) (40 . 1.0) (40 . 1.0) (40 . 1.0) (40 . 1.0)
           (10 0 0 0) (10 1 2 0) (10 3 2 0) (10 4 0 0)))
(entmake '((0 . "3DFACE") (10 0 0 0) (11 1 0 0) (12 1 1 1) (13 0 1 1)))
(entmake '((0 . "TEXT") (8 . "Notes") (10 1 1 0) (40 . 3.5) (1 . "M6 x 4") (50 . 0.25)))
; Deleted entities are not written; a deleted then restored one is.
(entmake '((0 . "LINE") (10 0 0 0) (11 1 1 0)))
(entdel (entlast))
(entmake '((0 . "CIRCLE") (10 50 50 0) (40 . 1.0) (210 0 0 -1)))
(setq e (entlast))
(entdel e)
(entdel e)
"#,
    );
    let e = ents(&doc);
    let types: Vec<&str> = e.iter().map(|x| x["type"].as_str().unwrap()).collect();
    assert_eq!(
        types,
        [
            "LINE",
            "CIRCLE",
            "ARC",
            "POINT",
            "LWPOLYLINE",
            "POLYLINE",
            "SPLINE",
            "3DFACE",
            "TEXT",
            "CIRCLE"
        ]
    );
    assert_eq!(layer_color(&doc, "Outline"), 1);
    assert_eq!(layer_color(&doc, "Holes"), 7);
    assert_eq!(e[0]["layer"], "Outline");
    assert_pt(&e[0]["start"], &[0.5, 0.25, 0.0], "line start");
    assert_pt(&e[0]["end"], &[10.125, 5.0, 1.0], "line end");
    assert_eq!(e[1]["layer"], "Holes");
    assert_eq!(e[1]["color"], 3);
    assert_pt(&e[1]["center_wcs"], &[5.0, 5.0, 0.0], "circle");
    assert!((f(&e[1]["radius"]) - 2.5).abs() <= TOL);
    assert_eq!(e[2]["layer"], "0");
    assert!((f(&e[2]["start_angle"]) - 0.5f64.to_degrees()).abs() <= 1e-9);
    assert!((f(&e[2]["end_angle"]) - 2.0f64.to_degrees()).abs() <= 1e-9);
    assert_pt(&e[3]["location"], &[1.0, 2.0, 3.0], "point");
    assert_eq!(e[4]["closed"], true);
    let pts = e[4]["points"].as_array().unwrap();
    assert_eq!(pts.len(), 4);
    for (got, want) in pts.iter().zip([
        [0.0, 0.0, 0.5],
        [10.0, 0.0, 0.0],
        [10.0, 10.0, -0.25],
        [0.0, 10.0, 0.0],
    ]) {
        assert_pt(got, &want, "lwpolyline vertex (x y bulge)");
    }
    assert_eq!(e[5]["layer"], "Outline");
    assert_eq!(e[5]["closed"], true);
    let pv = e[5]["points"].as_array().unwrap();
    assert_eq!(pv.len(), 3);
    assert_pt(&pv[1], &[25.0, 0.0, 0.0, 1.0], "polyline vertex with bulge");
    assert_eq!(e[6]["degree"], 3);
    assert_pt(
        &e[6]["control_points"][1],
        &[1.0, 2.0, 0.0],
        "spline control point",
    );
    assert_pt(&e[7]["corners"][3], &[0.0, 1.0, 1.0], "3dface corner");
    assert_eq!(e[8]["text"], "M6 x 4");
    assert_eq!(e[8]["layer"], "Notes");
    assert!((f(&e[8]["height"]) - 3.5).abs() <= TOL);
    assert!((f(&e[8]["rotation"]) - 0.25f64.to_degrees()).abs() <= 1e-9);
    // The OCS circle: group 10 (50 50 0) about (0 0 -1) is WCS (-50 50 0).
    assert_pt(&e[9]["center_ocs"], &[50.0, 50.0, 0.0], "ocs circle");
    assert_pt(
        &e[9]["center_wcs"],
        &[-50.0, 50.0, 0.0],
        "ocs circle in wcs",
    );
    assert_pt(&e[9]["extrusion"], &[0.0, 0.0, -1.0], "extrusion");
}

#[test]
fn command_entities_read_back_through_ezdxf() {
    let dir = tempfile::tempdir().unwrap();
    let doc = run_script(
        dir.path(),
        "command",
        r#"
(setvar "CMDECHO" 0)
(command "-LAYER" "M" "Outline" "C" "1" "" "")
(command "LINE" '(0 0) "10,0" "@0,5" "")
(command "_.CIRCLE" "5,2.5" 1.25)
(command "ARC" '(1 0) '(0 1) '(-1 0))
(command "PLINE" '(0 0) '(20 0) "A" '(20 10) "L" '(0 10) "C")
(command "LAYER" "M" "Curves" "")
(command "SPLINE" '(0 0) '(5 5) '(10 0) '(15 -5) "" "" "")
(command "PLINE" "30,0")
(command "@10,0" "@10<90")
(command "")
(command "LINE" '(100 100) '(200 200) "")
(command "ERASE" (entlast) "")
"#,
    );
    let e = ents(&doc);
    let types: Vec<&str> = e.iter().map(|x| x["type"].as_str().unwrap()).collect();
    assert_eq!(
        types,
        [
            "LINE",
            "LINE",
            "CIRCLE",
            "ARC",
            "LWPOLYLINE",
            "SPLINE",
            "LWPOLYLINE"
        ]
    );
    assert_eq!(layer_color(&doc, "Outline"), 1);
    for x in &e[..5] {
        assert_eq!(x["layer"], "Outline", "{x}");
    }
    assert_pt(&e[1]["start"], &[10.0, 0.0, 0.0], "second line");
    assert_pt(&e[1]["end"], &[10.0, 5.0, 0.0], "relative point");
    assert_pt(&e[2]["center_wcs"], &[5.0, 2.5, 0.0], "circle");
    assert!((f(&e[2]["radius"]) - 1.25).abs() <= TOL);
    assert_pt(&e[3]["center_wcs"], &[0.0, 0.0, 0.0], "3-point arc");
    assert!((f(&e[3]["start_angle"]) - 0.0).abs() <= 1e-9);
    assert!((f(&e[3]["end_angle"]) - 180.0).abs() <= 1e-9);
    // PLINE: a tangent semicircle from (20 0) to (20 10) has bulge 1; closed.
    assert_eq!(e[4]["closed"], true);
    let pts = e[4]["points"].as_array().unwrap();
    for (got, want) in pts.iter().zip([
        [0.0, 0.0, 0.0],
        [20.0, 0.0, 1.0],
        [20.0, 10.0, 0.0],
        [0.0, 10.0, 0.0],
    ]) {
        assert_pt(got, &want, "pline vertex (x y bulge)");
    }
    assert_eq!(e[5]["layer"], "Curves");
    let fit = e[5]["fit_points"].as_array().unwrap();
    assert_eq!(fit.len(), 4);
    assert_pt(&fit[3], &[15.0, -5.0, 0.0], "spline fit point");
    assert_pt(&e[5]["control_points"][0], &[0.0, 0.0, 0.0], "spline start");
    // A PLINE spread over three calls with relative and polar points.
    assert_eq!(e[6]["closed"], false);
    let pts = e[6]["points"].as_array().unwrap();
    assert_eq!(pts.len(), 3);
    assert_pt(&pts[2], &[40.0, 10.0, 0.0], "polar point");
}

#[test]
fn example_flange_script_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let dxf = dir.path().join("flange.dxf");
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("run")
        .arg(manifest().join("scripts/autolisp-routine.lsp"))
        .arg("-o")
        .arg(&dxf)
        .output()
        .expect("running lispcad");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc = check_dxf(&dxf, false);
    let e = ents(&doc);
    let count = |t: &str, layer: &str| {
        e.iter()
            .filter(|x| x["type"] == t && x["layer"] == layer)
            .count()
    };
    // The plate outline: one closed polyline with four rounded corners (bulges).
    let outline: Vec<&Value> = e
        .iter()
        .filter(|x| x["type"] == "LWPOLYLINE" && x["layer"] == "FLANGE-OUTLINE")
        .collect();
    assert_eq!(outline.len(), 1);
    assert_eq!(outline[0]["closed"], true);
    let bulged = outline[0]["points"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| f(&p[2]).abs() > 1e-12)
        .count();
    assert_eq!(bulged, 4);
    // Bolt holes on the pitch circle, the bore, and centre marks.
    assert_eq!(count("CIRCLE", "FLANGE-HOLES"), 6);
    assert_eq!(count("CIRCLE", "FLANGE-CENTER"), 1);
    assert_eq!(count("CIRCLE", "FLANGE-OUTLINE"), 1);
    assert!(count("LINE", "FLANGE-CENTER") >= 2);
    assert_eq!(count("TEXT", "FLANGE-NOTES"), 1);
    for x in e.iter().filter(|x| x["layer"] == "FLANGE-HOLES") {
        let c = &x["center_wcs"];
        let r = (f(&c[0]).powi(2) + f(&c[1]).powi(2)).sqrt();
        if (f(&x["radius"]) - 5.5).abs() < 1e-9 {
            assert!(
                (r - 45.0).abs() <= TOL,
                "bolt hole off the pitch circle: {x}"
            );
        }
    }
}
