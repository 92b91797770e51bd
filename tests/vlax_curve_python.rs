//! vlax-curve-* against an independent computation (tests/validate/vlax_curve_ref.py: ezdxf's
//! B-spline basis and bulge geometry, numpy Gauss–Legendre lengths) on every curve type, with
//! AutoCAD's parameter per type: points, first and second derivatives, distances, parameters
//! at distances and areas agree to 1e-9. Needs `<repo>/.venv/bin/python` (`.ci/setup`).

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};

use lispcad::lang::Value;
use serde_json::{json, Value as Json};

const FRACTIONS: [f64; 7] = [0.0, 0.1, 0.25, 0.5, 0.61, 0.9, 1.0];

fn entities() -> Vec<(Json, String)> {
    let pt = |p: &[f64]| {
        format!(
            "({})",
            p.iter()
                .map(|x| format!("{x:?}"))
                .collect::<Vec<_>>()
                .join(" ")
        )
    };
    let mut out = Vec::new();
    out.push((
        json!({"kind": "LINE", "p0": [1.0, 2.0, 0.5], "p1": [7.0, -3.0, 2.0]}),
        format!(
            "((0 . \"LINE\") (10 . {}) (11 . {}))",
            pt(&[1.0, 2.0, 0.5]),
            pt(&[7.0, -3.0, 2.0])
        ),
    ));
    out.push((
        json!({"kind": "CIRCLE", "c": [2.0, -1.0, 0.0], "r": 3.5}),
        "((0 . \"CIRCLE\") (10 2.0 -1.0 0.0) (40 . 3.5))".into(),
    ));
    out.push((
        json!({"kind": "ARC", "c": [1.0, 1.0, 0.0], "r": 2.0, "a0": 5.5, "a1": 0.75}),
        "((0 . \"ARC\") (10 1.0 1.0 0.0) (40 . 2.0) (50 . 5.5) (51 . 0.75))".into(),
    ));
    let lw = [
        [0.0, 0.0],
        [10.0, 0.0],
        [12.0, 5.0],
        [4.0, 8.0],
        [-1.0, 4.0],
    ];
    let bulges = [0.0, 0.4, -0.3, 1.0, 0.0];
    let mut dxf = String::from(
        "((0 . \"LWPOLYLINE\") (100 . \"AcDbEntity\") (100 . \"AcDbPolyline\") (90 . 5) (70 . 1)",
    );
    for (p, b) in lw.iter().zip(bulges) {
        dxf += &format!(" (10 {:?} {:?}) (42 . {b:?})", p[0], p[1]);
    }
    dxf += ")";
    out.push((
        json!({"kind": "LWPOLYLINE", "pts": lw, "bulges": bulges, "closed": true}),
        dxf,
    ));
    let open = [[0.0, 0.0], [5.0, 1.0], [9.0, -2.0]];
    out.push((
        json!({"kind": "LWPOLYLINE", "pts": open, "bulges": [0.7, 0.0, 0.0], "closed": false}),
        "((0 . \"LWPOLYLINE\") (100 . \"AcDbEntity\") (100 . \"AcDbPolyline\") (90 . 3) (70 . 0) (10 0.0 0.0) (42 . 0.7) (10 5.0 1.0) (10 9.0 -2.0))".into(),
    ));
    let p3 = [
        [0.0, 0.0, 0.0],
        [3.0, 1.0, 2.0],
        [5.0, -2.0, 4.0],
        [9.0, 0.0, 1.0],
    ];
    out.push((
        json!({"kind": "POLYLINE", "pts": p3, "closed": false}),
        String::new(),
    ));
    // A CURVE value (the drawing gets ELLIPSE entities with the DXF reader).
    out.push((
        json!({"kind": "ELLIPSE", "c": [1.0, -2.0, 0.5], "major": [3.0, 1.0, 0.0], "normal": [0.0, 0.0, 1.0], "ratio": 0.4, "a0": 0.7, "a1": 5.9}),
        "(ellipse '(1.0 -2.0 0.5) '(3.0 1.0 0.0) 0.4 0.7 5.9)".into(),
    ));
    let ctrl = [
        [0.0, 0.0, 0.0],
        [1.0, 3.0, 0.0],
        [4.0, 4.0, 1.0],
        [6.0, 0.0, 0.0],
        [9.0, 2.0, -1.0],
        [11.0, 1.0, 0.0],
    ];
    let knots = [0.0, 0.0, 0.0, 0.0, 1.5, 4.0, 6.0, 6.0, 6.0, 6.0];
    for weights in [None, Some([1.0, 2.0, 0.5, 1.5, 1.0, 0.8])] {
        let mut dxf = format!(
            "((0 . \"SPLINE\") (100 . \"AcDbEntity\") (100 . \"AcDbSpline\") (70 . {}) (71 . 3) (72 . 10) (73 . 6)",
            if weights.is_some() { 12 } else { 8 }
        );
        for k in knots {
            dxf += &format!(" (40 . {k:?})");
        }
        for (i, c) in ctrl.iter().enumerate() {
            dxf += &format!(" (10 . {})", pt(c));
            if let Some(w) = weights {
                dxf += &format!(" (41 . {:?})", w[i]);
            }
        }
        dxf += ")";
        out.push((
            json!({"kind": "SPLINE", "degree": 3, "ctrl": ctrl, "knots": knots, "weights": weights}),
            dxf,
        ));
    }
    out
}

fn nums(v: &Value) -> Vec<f64> {
    match v {
        Value::Int(_) | Value::Real(_) => vec![v.as_f64().unwrap()],
        _ => v.iter().map(|x| x.as_f64().expect("a number")).collect(),
    }
}

fn close(a: &[f64], b: &Json, what: &str) {
    let b: Vec<f64> = match b {
        Json::Array(xs) => xs.iter().map(|x| x.as_f64().unwrap()).collect(),
        x => vec![x.as_f64().unwrap()],
    };
    assert_eq!(a.len(), b.len(), "{what}: {a:?} vs {b:?}");
    for (x, y) in a.iter().zip(&b) {
        assert!(
            (x - y).abs() <= 1e-9 * (1.0 + y.abs()),
            "{what}: {a:?} vs {b:?}"
        );
    }
}

#[test]
fn vlax_curve_agrees_with_ezdxf_and_numpy() {
    let ents = entities();
    let mut input: Vec<Json> = ents.iter().map(|(j, _)| j.clone()).collect();
    for j in &mut input {
        j["fractions"] = json!(FRACTIONS);
    }
    let py = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(".venv/bin/python");
    assert!(py.exists(), "{} missing: run .ci/setup", py.display());
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/validate/vlax_curve_ref.py");
    let mut child = Command::new(py)
        .arg(script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(serde_json::to_string(&input).unwrap().as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let refs: Vec<Json> = serde_json::from_slice(&out.stdout).unwrap();

    let mut it = lispcad::builtins::new_interp();
    let mut eval = |code: &str| -> Value {
        it.eval_source("<test>", code)
            .unwrap_or_else(|e| panic!("{code}: {}", e.message))
    };
    for ((j, dxf), r) in ents.iter().zip(&refs) {
        let kind = j["kind"].as_str().unwrap();
        if dxf.is_empty() {
            // The 3D POLYLINE through entmake's POLYLINE/VERTEX/SEQEND sequence.
            eval("(entmake '((0 . \"POLYLINE\") (66 . 1) (70 . 8)))");
            for p in j["pts"].as_array().unwrap() {
                let c: Vec<f64> = p
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect();
                eval(&format!(
                    "(entmake '((0 . \"VERTEX\") (70 . 32) (10 {:?} {:?} {:?})))",
                    c[0], c[1], c[2]
                ));
            }
            eval("(entmake '((0 . \"SEQEND\")))");
        } else if kind == "ELLIPSE" {
            eval(&format!("(setq e {dxf})"));
        } else {
            eval(&format!("(entmake '{dxf})"));
        }
        if kind != "ELLIPSE" {
            eval("(setq e (entlast))");
        }
        close(
            &nums(&eval("(vlax-curve-getStartParam e)")),
            &r["start"],
            kind,
        );
        close(&nums(&eval("(vlax-curve-getEndParam e)")), &r["end"], kind);
        let total = nums(&eval(
            "(vlax-curve-getDistAtParam e (vlax-curve-getEndParam e))",
        ));
        close(&total, &r["length"], &format!("{kind} length"));
        if !r["area"].is_null() {
            close(
                &nums(&eval("(vlax-curve-getArea e)")),
                &r["area"],
                &format!("{kind} area"),
            );
        }
        for at in r["at"].as_array().unwrap() {
            let u = at["param"].as_f64().unwrap();
            let what = format!("{kind} at {u}");
            close(
                &nums(&eval(&format!("(vlax-curve-getPointAtParam e {u:?})"))),
                &at["point"],
                &what,
            );
            close(
                &nums(&eval(&format!("(vlax-curve-getDistAtParam e {u:?})"))),
                &at["dist"],
                &what,
            );
            // Derivatives are one-sided at polyline vertices: compare inside segments only.
            let at_vertex = kind.contains("POLYLINE") && u.fract() == 0.0;
            if !at_vertex {
                close(
                    &nums(&eval(&format!("(vlax-curve-getFirstDeriv e {u:?})"))),
                    &at["d1"],
                    &what,
                );
                close(
                    &nums(&eval(&format!("(vlax-curve-getSecondDeriv e {u:?})"))),
                    &at["d2"],
                    &what,
                );
            }
            let p = &at["point"];
            let back = nums(&eval(&format!(
                "(vlax-curve-getParamAtPoint e '({:?} {:?} {:?}))",
                p[0].as_f64().unwrap(),
                p[1].as_f64().unwrap(),
                p[2].as_f64().unwrap()
            )));
            // A closed curve's start and end are one point: either parameter is right.
            let wraps = (u - r["end"].as_f64().unwrap()).abs() < 1e-12
                && back[0] == r["start"].as_f64().unwrap();
            if !wraps {
                close(&back, &json!(u), &format!("{what} param at point"));
            }
        }
        for d in r["dist"].as_array().unwrap() {
            let s = d["dist"].as_f64().unwrap();
            let what = format!("{kind} at distance {s}");
            let pt = nums(&eval(&format!("(vlax-curve-getPointAtDist e {s:?})")));
            close(&pt, &d["point"], &what);
            let u = nums(&eval(&format!("(vlax-curve-getParamAtDist e {s:?})")));
            close(&u, &d["param"], &what);
        }
    }
}
