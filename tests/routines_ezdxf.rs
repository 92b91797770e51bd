//! The published-style routines under tests/routines/ on a drawing ezdxf made (opened with
//! `--open`): their printed results and the drawing they write compared with values computed
//! independently in Python (tests/validate/routines_ref.py: ezdxf's bulge and B-spline
//! geometry, numpy Gauss-Legendre lengths), to 1e-8.

mod output_support;

use std::process::Command;

use output_support::{manifest, python};
use serde_json::Value;

const TOL: f64 = 1e-8;

fn py(mode: &str, path: &std::path::Path) -> Value {
    let out = Command::new(python())
        .arg(manifest().join("tests/validate/routines_ref.py"))
        .arg(mode)
        .arg(path)
        .output()
        .expect("running routines_ref.py");
    assert!(
        out.status.success(),
        "routines_ref.py {mode}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON from routines_ref.py")
}

fn nums(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(nums).collect(),
        Value::Number(n) => vec![n.as_f64().unwrap()],
        other => panic!("not numbers: {other}"),
    }
}

fn assert_close(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: got {got:?}, want {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= TOL, "{what}: got {got:?}, want {want:?}");
    }
}

#[test]
fn routines_on_an_ezdxf_drawing_match_python() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.dxf");
    let want = py("make", &input);
    let routines = manifest().join("tests/routines");
    let script = format!(
        r#"
(foreach f '("total_length" "divide_curve" "reverse_pline" "list_intersections")
  (load (strcat "{}/" f ".lsp")))
(defun pr (lst) (foreach x lst (princ (rtos x 2 12)) (princ " ")) (princ "\n"))
(defun first-of (type) (ssname (ssget "X" (list (cons 0 type))) 0))
(setq total (c:tlen))
(princ "\n")
(pr (list total))
(pr (apply 'append (mapcar '(lambda (p) (list (car p) (cadr p))) (divpts (first-of "LWPOLYLINE") 5))))
(pr (apply 'append (mapcar '(lambda (p) (list (car p) (cadr p))) (divpts (first-of "SPLINE") 4))))
(setq lw (revpl (first-of "LWPOLYLINE")))
(pr (mapcar '(lambda (g) (if (listp (cdr g)) (car (cdr g)) (cdr g)))
  (vl-remove-if-not '(lambda (g) (member (car g) '(10 42))) (entget lw))))
(pr (mapcar '(lambda (g) (cadr (cdr g)))
  (vl-remove-if-not '(lambda (g) (= (car g) 10)) (entget lw))))
(pr (apply 'append (mapcar '(lambda (p) (list (car p) (cadr p)))
  (vl-sort (list-intersections) '(lambda (a b) (< (car a) (car b)))))))
"#,
        routines.display()
    );
    std::fs::write(dir.path().join("r.lsp"), script).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .current_dir(dir.path())
        .args(["run", "r.lsp", "--open", "in.dxf", "-o", "out.dxf"])
        .output()
        .expect("running lispcad");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "lispcad: {stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<Vec<f64>> = stdout
        .lines()
        .skip_while(|l| !l.starts_with("Total length of 6 objects: "))
        .skip(1)
        .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(lines.len(), 6, "printed: {stdout}");
    assert_close(&lines[0], &nums(&want["total"]), "total length (TLEN)");
    assert_close(
        &lines[1],
        &nums(&want["div_lw"]),
        "polyline divided in 5 (DIVPTS)",
    );
    assert_close(
        &lines[2],
        &nums(&want["div_spline"]),
        "spline divided in 4 (DIVPTS)",
    );
    // REVPL: x and bulge per vertex, then y per vertex.
    let rev: Vec<Vec<f64>> = want["rev_lw"]
        .as_array()
        .unwrap()
        .iter()
        .map(nums)
        .collect();
    let xb: Vec<f64> = rev.iter().flat_map(|v| [v[0], v[2]]).collect();
    let ys: Vec<f64> = rev.iter().map(|v| v[1]).collect();
    assert_close(&lines[3], &xb, "reversed polyline x and bulges (REVPL)");
    assert_close(&lines[4], &ys, "reversed polyline y (REVPL)");
    assert_close(&lines[5], &nums(&want["inters"]), "intersections (INTERS)");

    // The drawing written: the POINTs DIVPTS made and the reversed polyline, as ezdxf reads
    // them (audit 0 errors, 0 fixes).
    let doc = py("check", &dir.path().join("out.dxf"));
    assert_eq!(doc["audit_errors"], 0);
    assert_eq!(doc["audit_fixes"], 0);
    let mut want_pts = nums(&want["div_lw"]);
    want_pts.extend(nums(&want["div_spline"]));
    assert_close(
        &nums(&doc["points"]),
        &want_pts,
        "POINTs in the written DXF",
    );
    assert_close(
        &nums(&doc["lw"]),
        &nums(&want["rev_lw"]),
        "LWPOLYLINE in the written DXF",
    );
}

/// INSERT/-INSERT of a block an ezdxf drawing defines, with its attributes: the ATTRIBs sit
/// where ezdxf's own block transform puts the ATTDEFs, with the values given (Enter: the
/// default), and the file audits clean.
#[test]
fn insert_with_attributes_into_an_ezdxf_drawing() {
    let dir = tempfile::tempdir().unwrap();
    py_plain("block", &dir.path().join("in.dxf"));
    let script = r#"
(command "_.-insert" "DOOR" '(10 5 0) 2 "" 90 "1200" "")
(setq ins (entlast))
(setq a (entget (entnext ins)))
(prin1 (list (cdr (assoc 0 a)) (cdr (assoc 2 a)) (cdr (assoc 1 a)))) (terpri)
(command "_.insert" "door" '(1 1 0) "" "" "" "" "left")
(setq b (entget (entnext (entnext (entlast)))))
(prin1 (list (cdr (assoc 2 b)) (cdr (assoc 1 b)))) (terpri)
(prin1 (cdr (assoc 0 (entget (entnext (entnext (entnext (entlast)))))))) (terpri)
"#;
    std::fs::write(dir.path().join("i.lsp"), script).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .current_dir(dir.path())
        .args(["run", "i.lsp", "--open", "in.dxf", "-o", "out.dxf"])
        .output()
        .expect("running lispcad");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "lispcad: {stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        stdout.lines().collect::<Vec<_>>(),
        [
            r#"("ATTRIB" "WIDTH" "1200")"#,
            r#"("NOTE" "left")"#,
            r#""SEQEND""#
        ]
    );
    let doc = py("inserts", &dir.path().join("out.dxf"));
    assert_eq!(doc["audit_errors"], 0);
    assert_eq!(doc["audit_fixes"], 0);
    let ins = doc["inserts"].as_array().unwrap();
    assert_eq!(ins.len(), 2);
    assert_eq!(ins[0]["name"], "DOOR");
    assert_close(
        &nums(&ins[0]["insert"]),
        &[10.0, 5.0, 0.0],
        "insertion point",
    );
    assert_close(&nums(&ins[0]["scale"]), &[2.0, 2.0], "scale");
    assert_close(&nums(&ins[0]["rotation"]), &[90.0], "rotation");
    let texts: Vec<(String, String)> = ins
        .iter()
        .flat_map(|i| i["attribs"].as_array().unwrap().clone())
        .map(|a| {
            (
                a["tag"].as_str().unwrap().into(),
                a["text"].as_str().unwrap().into(),
            )
        })
        .collect();
    let want: Vec<(String, String)> = [
        ("WIDTH", "1200"),
        ("NOTE", "none"),
        ("WIDTH", "900"),
        ("NOTE", "left"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    assert_eq!(texts, want);
    for i in ins {
        for a in i["attribs"].as_array().unwrap() {
            assert_close(&nums(&a["at"]), &nums(&a["want_at"]), "ATTRIB position");
        }
    }
    assert_close(
        &nums(&ins[0]["attribs"][0]["height"]),
        &[0.5],
        "scaled height",
    );
}

/// EXPLODE of a block reference: the block's LINE (0,0)-(1,0), inserted at (10,5) with
/// scale 2 and rotation 90 degrees, becomes the line (10,5)-(10,7) (worked by hand); the
/// INSERT and its ATTRIBs are gone, its ATTDEFs come back as ATTDEFs (AutoCAD's EXPLODE:
/// the last, NOTE at (0,-0.5), at (10,5) + 2 rot90(0,-0.5) = (11,5)), and ezdxf reads the
/// file with a clean audit.
#[test]
fn explode_of_an_inserted_block() {
    let dir = tempfile::tempdir().unwrap();
    py_plain("block", &dir.path().join("in.dxf"));
    let script = r#"
(command "_.-insert" "DOOR" '(10 5 0) 2 "" 90 "1200" "")
(setq ins (entlast))
(setq att (entnext ins))
(command "_.explode" ins "")
(prin1 (list (entget ins) (entget att) (cdr (assoc 0 (entget (entlast)))) (entnext (entlast))
  (cdr (assoc 2 (entget (entlast)))) (cdr (assoc 10 (entget (entlast))))))
"#;
    std::fs::write(dir.path().join("x.lsp"), script).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .current_dir(dir.path())
        .args(["run", "x.lsp", "--open", "in.dxf", "-o", "out.dxf"])
        .output()
        .expect("running lispcad");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "lispcad: {stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        stdout.trim(),
        r#"(nil nil "ATTDEF" nil "NOTE" (11.0 5.0 0.0))"#
    );
    let doc = py("inserts", &dir.path().join("out.dxf"));
    assert_eq!(doc["audit_errors"], 0);
    assert_eq!(doc["audit_fixes"], 0);
    assert_eq!(doc["inserts"].as_array().unwrap().len(), 0);
    let lines = doc["lines"].as_array().unwrap();
    assert_eq!(lines.len(), 1);
    assert_close(
        &nums(&lines[0]),
        &[10.0, 5.0, 0.0, 10.0, 7.0, 0.0],
        "exploded line",
    );
}

fn py_plain(mode: &str, path: &std::path::Path) {
    let out = Command::new(python())
        .arg(manifest().join("tests/validate/routines_ref.py"))
        .arg(mode)
        .arg(path)
        .output()
        .expect("running routines_ref.py");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
