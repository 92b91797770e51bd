//! Block definitions made with `entmake` (BLOCK … ENDBLK), block references made with
//! `entmake` and the INSERT command, and table-record handles, written to DXF and read back
//! by ezdxf (tests/validate/blocks_dump.py): on a drawing made from scratch and on one ezdxf
//! made, opened with `--open`. Every file loads with ezdxf's strict reader and audits with
//! 0 errors and 0 fixes.

mod output_support;

use std::path::Path;
use std::process::Command;

use output_support::{manifest, python};
use serde_json::Value;

fn ezdxf(mode: &str, path: &Path) -> Value {
    output_support::validator_json("blocks_dump.py", mode, path)
}

fn lispcad(dir: &Path, script: &str, args: &[&str]) -> String {
    output_support::run_script(dir, script, args)
}

fn close(a: &Value, b: &[f64]) {
    let a: Vec<f64> = a
        .as_array()
        .unwrap_or_else(|| panic!("not a list: {a}"))
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(a.len(), b.len(), "{a:?} vs {b:?}");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() < 1e-9, "{a:?} vs {b:?}");
    }
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The model-space entities of a type.
fn of_type<'a>(doc: &'a Value, ty: &str) -> Vec<&'a Value> {
    doc["modelspace"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["type"] == ty)
        .collect()
}

const BLOCK_SCRIPT: &str = r#"
(entmake '((0 . "BLOCK") (2 . "BOX") (70 . 0) (10 1.0 1.0 0.0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 4 0 0)))
(entmake '((0 . "CIRCLE") (10 2 2 0) (40 . 1.5) (8 . "Parts")))
(entmake '((0 . "ATTDEF") (10 0 3 0) (40 . 0.5) (1 . "def") (2 . "TAG1") (3 . "Give tag") (70 . 0)))
(entmake '((0 . "POLYLINE") (66 . 1) (70 . 1)))
(entmake '((0 . "VERTEX") (10 0 0 0)))
(entmake '((0 . "VERTEX") (10 1 0 0) (42 . 0.5)))
(entmake '((0 . "VERTEX") (10 1 1 0)))
(entmake '((0 . "SEQEND")))
(princ (entmake '((0 . "ENDBLK"))))
(entmake (list '(0 . "INSERT") '(2 . "BOX") '(66 . 1) '(10 10 10 0) '(41 . 2.0) '(42 . 2.0) '(43 . 2.0) (cons 50 (/ pi 6))))
(entmake '((0 . "ATTRIB") (10 9 16 0) (40 . 1.0) (1 . "hello") (2 . "TAG1") (70 . 0)))
(entmake '((0 . "SEQEND")))
(command "_.-INSERT" "BOX" '(30 0) "" "" 0 "typed")
(entmake '((0 . "BLOCK") (2 . "*U") (70 . 1) (10 0 0 0)))
(entmake '((0 . "INSERT") (2 . "BOX") (10 1 1 0)))
(princ (entmake '((0 . "ENDBLK"))))
(entmake '((0 . "INSERT") (2 . "*U1") (10 50 0 0)))
"#;

#[test]
fn entmake_blocks_in_a_new_drawing_read_back_by_ezdxf() {
    let dir = tempfile::tempdir().unwrap();
    let printed = lispcad(dir.path(), BLOCK_SCRIPT, &["-o", "out.dxf"]);
    assert!(printed.contains("BOX*U1"), "{printed}");
    let doc = ezdxf("check", &dir.path().join("out.dxf"));
    let b = &doc["blocks"]["BOX"];
    assert_eq!(b["flags"], 2, "non-constant ATTDEF: flag 2");
    close(&b["base"], &[1.0, 1.0, 0.0]);
    let types: Vec<&str> = b["entities"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["type"].as_str().unwrap())
        .collect();
    assert_eq!(types, ["LINE", "CIRCLE", "ATTDEF", "POLYLINE"]);
    let ents = b["entities"].as_array().unwrap();
    for e in ents {
        assert_eq!(e["owner"], b["record"], "owned by the block record");
    }
    close(&ents[0]["end"], &[4.0, 0.0, 0.0]);
    assert_eq!(ents[1]["layer"], "Parts");
    assert_eq!(ents[1]["radius"], 1.5);
    assert_eq!(ents[2]["tag"], "TAG1");
    assert_eq!(ents[2]["text"], "def");
    assert_eq!(ents[3]["bulges"][1], 0.5);
    assert_eq!(ents[3]["closed"], true);
    let anon = &doc["blocks"]["*U1"];
    assert_eq!(anon["flags"], 1);
    assert_eq!(anon["entities"][0]["name"], "BOX");

    let inserts = of_type(&doc, "INSERT");
    assert_eq!(inserts.len(), 3);
    let first = inserts[0];
    assert_eq!(first["name"], "BOX");
    close(&first["insert"], &[10.0, 10.0, 0.0]);
    close(&first["scale"], &[2.0, 2.0, 2.0]);
    assert!((num(&first["rotation"]) - 30.0).abs() < 1e-9);
    assert_eq!(first["attribs"][0]["text"], "hello");
    assert_eq!(first["attribs"][0]["tag"], "TAG1");
    // The command places the attribute at the ATTDEF's point relative to the base point.
    let typed = inserts[1];
    close(&typed["insert"], &[30.0, 0.0, 0.0]);
    assert_eq!(typed["attribs"][0]["text"], "typed");
    close(&typed["attribs"][0]["insert"], &[29.0, 2.0, 0.0]);
    assert_eq!(inserts[2]["name"], "*U1");
}

#[test]
fn entmake_blocks_in_an_opened_drawing_read_back_by_ezdxf() {
    let dir = tempfile::tempdir().unwrap();
    ezdxf("make", &dir.path().join("in.dxf"));
    let script = r#"
(entmake '((0 . "BLOCK") (2 . "NEW") (10 0 0 0)))
(entmake '((0 . "ARC") (10 0 0 0) (40 . 2.0) (50 . 0.0) (51 . 1.5707963267948966)))
(entmake '((0 . "INSERT") (2 . "PY") (10 5 0 0)))
(entmake '((0 . "ENDBLK")))
(entmake '((0 . "INSERT") (2 . "NEW") (10 7 7 0)))
(command "_.INSERT" "PY" '(2 2) 2 "" 90 "Ada")
;; A redefinition replaces the block's entities and keeps its record.
(setq rec (tblobjname "BLOCK" "NEW"))
(entmake '((0 . "BLOCK") (2 . "NEW") (10 0 0 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 0 9 0)))
(entmake '((0 . "ENDBLK")))
(princ (eq rec (tblobjname "BLOCK" "NEW")))
"#;
    let printed = lispcad(dir.path(), script, &["--open", "in.dxf", "-o", "out.dxf"]);
    assert_eq!(printed.trim(), "T");
    let doc = ezdxf("check", &dir.path().join("out.dxf"));
    let new = &doc["blocks"]["NEW"]["entities"];
    assert_eq!(new.as_array().unwrap().len(), 1);
    close(&new[0]["end"], &[0.0, 9.0, 0.0]);
    assert_eq!(doc["blocks"]["PY"]["entities"].as_array().unwrap().len(), 2);
    let inserts = of_type(&doc, "INSERT");
    assert_eq!(inserts.len(), 2);
    assert_eq!(inserts[0]["name"], "NEW");
    let py = inserts[1];
    assert_eq!(py["name"], "PY");
    close(&py["scale"], &[2.0, 2.0, 2.0]);
    assert_eq!(py["attribs"][0]["text"], "Ada");
    // ATTDEF at (0 1), base (1 0): (-1 1) scaled by 2, turned 90° about (2 2).
    close(&py["attribs"][0]["insert"], &[0.0, 0.0, 0.0]);
}

#[test]
fn tblobjname_handles_are_the_ones_written() {
    let dir = tempfile::tempdir().unwrap();
    let script = r#"
(entmake '((0 . "LAYER") (2 . "Parts") (62 . 3) (6 . "DASHED")))
(regapp "LCAPP")
(entmake '((0 . "TEXT") (10 0 0 0) (40 . 1.0) (1 . "x") (7 . "Mine")))
(entmake '((0 . "BLOCK") (2 . "BOX") (10 0 0 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0)))
(entmake '((0 . "ENDBLK")))
(foreach r '(("LAYER" "0") ("LAYER" "Parts") ("LTYPE" "Continuous") ("LTYPE" "DASHED")
             ("STYLE" "Standard") ("STYLE" "Mine") ("APPID" "ACAD") ("APPID" "LCAPP")
             ("BLOCK" "BOX"))
  (princ (strcat (car r) " " (cadr r) " " (cdr (assoc 5 (entget (apply 'tblobjname r)))) "\n")))
;; A layer made after the query gets a handle of its own.
(entmake '((0 . "LAYER") (2 . "Late")))
(entmake '((0 . "LINE") (10 0 0 0) (11 1 0 0) (8 . "Late")))
"#;
    let printed = lispcad(dir.path(), script, &["-o", "out.dxf"]);
    let doc = ezdxf("check", &dir.path().join("out.dxf"));
    let mut seen = Vec::new();
    for line in printed.lines() {
        let parts: Vec<&str> = line.split(' ').collect();
        let (table, name, handle) = (parts[0], parts[1], parts[2]);
        let table = if table == "BLOCK" {
            "BLOCK_RECORD"
        } else {
            table
        };
        assert_eq!(
            doc["tables"][table][name], handle,
            "{table} {name}: tblobjname gave {handle}, the file has {}",
            doc["tables"][table]
        );
        seen.push(handle.to_string());
    }
    assert_eq!(seen.len(), 9);
    // Fixed records keep their fixed handles; the others differ from one another.
    assert_eq!(seen[2], "1A");
    assert_eq!(seen[6], "1B");
    assert_eq!(seen[4], "1D");
    let late = doc["tables"]["LAYER"]["Late"].as_str().unwrap();
    assert!(!seen.iter().any(|h| h == late));
}

/// The model space after ezdxf explodes the block references of `path`.
fn ezdxf_explode(path: &Path) -> Value {
    let out = Command::new(python())
        .arg(manifest().join("tests/validate/blocks_dump.py"))
        .arg("explode")
        .arg(path)
        .output()
        .expect("running blocks_dump.py");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn explode_with_non_uniform_scale_matches_ezdxf_explode() {
    let dir = tempfile::tempdir().unwrap();
    let blocks = r#"
(entmake '((0 . "BLOCK") (2 . "STRETCH") (10 1 0 0)))
(entmake '((0 . "LINE") (10 0 0 0) (11 3 1 0)))
(entmake '((0 . "CIRCLE") (10 1 0 0) (40 . 1.0)))
(entmake (list '(0 . "ARC") '(10 3 1 0) '(40 . 1.5) '(50 . 0.5) (cons 51 2.5)))
(entmake '((0 . "POINT") (10 2 2 0)))
(entmake '((0 . "ENDBLK")))
(entmake (list '(0 . "INSERT") '(2 . "STRETCH") '(10 10 10 0) '(41 . 2.0) '(42 . 0.5) '(43 . 1.0) (cons 50 (/ pi 5))))
"#;
    lispcad(dir.path(), blocks, &["-o", "ref.dxf"]);
    let exploded = format!("{blocks}(command \"_.EXPLODE\" (entlast) \"\")\n");
    lispcad(dir.path(), &exploded, &["-o", "out.dxf"]);
    let want = ezdxf_explode(&dir.path().join("ref.dxf"));
    let got = &ezdxf("check", &dir.path().join("out.dxf"))["modelspace"];
    let (want, got) = (want.as_array().unwrap(), got.as_array().unwrap());
    let types = |v: &[Value]| -> Vec<String> {
        v.iter()
            .map(|e| e["type"].as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(types(got), types(want));
    assert_eq!(types(got), ["LINE", "ELLIPSE", "ELLIPSE", "POINT"]);
    for (g, w) in got.iter().zip(want) {
        for key in [
            "start",
            "end",
            "location",
            "center",
            "start_point",
            "end_point",
            "axes",
        ] {
            if let Some(wv) = w.get(key) {
                let wv: Vec<f64> = wv.as_array().unwrap().iter().map(num).collect();
                close(&g[key], &wv);
            }
        }
    }
    // The full circle stays a full ellipse.
    let full = got[1]["end_param"].as_f64().unwrap() - got[1]["start_param"].as_f64().unwrap();
    assert!((full - std::f64::consts::TAU).abs() < 1e-9);
}

/// The entity of `ty` in the model space (exactly one).
fn one<'a>(doc: &'a Value, ty: &str) -> &'a Value {
    let all = of_type(doc, ty);
    assert_eq!(all.len(), 1, "one {ty} in {}", doc["modelspace"]);
    all[0]
}

#[test]
fn chprop_line_type_weight_thickness_and_scale_read_back_by_ezdxf() {
    let dir = tempfile::tempdir().unwrap();
    let script = r#"
(entmake '((0 . "LINE") (10 0 0 0) (11 10 0 0) (62 . 1)))
(command "_.CHPROP" (entlast) "" "_LT" "DASHED" "_LW" 0.3 "_T" 2.5 "_S" 0.5 "")
(entmake '((0 . "CIRCLE") (10 0 0 0) (40 . 2.0)))
(command "_.CHANGE" (entlast) "" "_P" "_T" -1 "_LW" "_ByBlock" "")
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (100 . "AcDbPolyline") (90 . 2) (70 . 0) (10 0.0 0.0) (10 4.0 0.0)))
(command "_.CHPROP" (entlast) "" "_T" 3 "_LT" "Continuous" "")
"#;
    lispcad(dir.path(), script, &["-o", "out.dxf"]);
    let doc = ezdxf("check", &dir.path().join("out.dxf"));
    let line = one(&doc, "LINE");
    assert_eq!(line["linetype"], "DASHED");
    assert_eq!(line["lineweight"], 30);
    assert_eq!(line["ltscale"], 0.5);
    assert_eq!(line["thickness"], 2.5);
    assert_eq!(line["color"], 1);
    assert!(doc["tables"]["LTYPE"].get("DASHED").is_some());
    let circle = one(&doc, "CIRCLE");
    assert_eq!(circle["thickness"], -1.0);
    assert_eq!(circle["lineweight"], -2);
    let pl = one(&doc, "LWPOLYLINE");
    assert_eq!(pl["thickness"], 3.0);
    assert_eq!(pl["linetype"], "Continuous");

    // An opened drawing: the file's CIRCLE and a new LINE; a line type the file lacks is
    // refused there.
    ezdxf("make", &dir.path().join("in.dxf"));
    let script = r#"
(setq c (ssname (ssget "X" '((0 . "CIRCLE"))) 0))
(command "_.CHPROP" c "" "_LT" "Continuous" "_LW" 0.5 "_T" 4 "_S" 3 "")
(entmake '((0 . "LINE") (10 0 0 0) (11 10 0 0)))
(command "_.CHPROP" (entlast) "" "_LW" 0.13 "_T" 1 "")
(princ (vl-catch-all-error-message (vl-catch-all-apply 'command (list "_.CHPROP" c "" "_LT" "DASHDOT" ""))))
"#;
    let printed = lispcad(dir.path(), script, &["--open", "in.dxf", "-o", "out2.dxf"]);
    assert_eq!(
        printed.trim(),
        "CHPROP: line type \"DASHDOT\" is not loaded in the drawing"
    );
    let doc = ezdxf("check", &dir.path().join("out2.dxf"));
    let circle = one(&doc, "CIRCLE");
    assert_eq!(circle["linetype"], "Continuous");
    assert_eq!(circle["lineweight"], 50);
    assert_eq!(circle["thickness"], 4.0);
    assert_eq!(circle["ltscale"], 3.0);
    let line = one(&doc, "LINE");
    assert_eq!(line["lineweight"], 13);
    assert_eq!(line["thickness"], 1.0);
}
