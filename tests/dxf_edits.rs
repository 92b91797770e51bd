//! `entmod` on an opened drawing changes only what it is given: the groups lispcad does not
//! model (thickness, extrusion, line type scale, true colour, transparency, text alignment,
//! per-vertex widths, spline tangents, extended data) survive an edit of a modelled entity,
//! and any group of an entity kept as its groups (INSERT and its ATTRIBs, MTEXT, HATCH) can
//! be replaced. A TEXT style the script uses is added to the STYLE table. ezdxf reads the
//! original and the result, and computes the expected values itself
//! (`tests/validate/dxf_edits.py`).

mod dxf_support;

use std::process::Command;

use dxf_support::{lispcad, manifest, python, strs};

const EDIT: &str = r#"
(defun ent (layer / ss) (if (setq ss (ssget "X" (list (cons 8 layer)))) (ssname ss 0)))
(defun put (e code val) (entmod (subst (cons code val) (assoc code e) e)))
(defun moved (e code d) (subst (cons code (mapcar '+ (cdr (assoc code e)) d)) (assoc code e) e))
(if (setq x (ent "LN")) (entmod (moved (entget x) 10 '(1 2 3))))
(if (setq x (ent "TX")) (put (entget x) 1 "world"))
(if (setq x (ent "TJ")) (entmod (moved (entget x) 10 '(2 -1 0))))
(if (setq x (ent "CI")) (put (moved (entget x) 10 '(0 0 1)) 40 2.0))
(if (setq x (ent "LW")) (entmod (moved (entget x) 10 '(0.5 0))))
(if (setq x (ent "SP"))
  (progn
    (setq e (entget x)
          old (cadr (vl-remove-if-not '(lambda (g) (= (car g) 10)) e)))
    (entmod (subst (cons 10 (mapcar '+ (cdr old) '(0 1 0))) old e))))
(defun ctrl (e) (vl-remove-if-not '(lambda (g) (= (car g) 10)) e))
(if (setq x (ent "SQ"))
  (progn
    (setq e (entget x) old (cadr (ctrl e)))
    (entmod (subst (cons 10 (mapcar '+ (cdr old) '(0 0 1))) old e))))
(if (setq x (ent "SR"))
  (entmod (mapcar '(lambda (g) (if (= (car g) 10) (list 10 (cadr g) (caddr g) (cadr g)) g))
                  (entget x))))
(if (setq x (ent "IN"))
  (progn
    (put (subst '(10 41.0 42.0 0.0) (assoc 10 (entget x)) (entget x)) 41 3.0)
    (put (entget (entnext x)) 1 "second")))
(if (setq x (ent "MT")) (put (subst '(40 . 2.5) (assoc 40 (entget x)) (entget x)) 1 "new text"))
(if (setq x (ent "HA")) (put (subst '(62 . 6) (assoc 62 (entget x)) (entget x)) 41 0.75))
(entmake '((0 . "TEXT") (8 . "ZZ") (10 0.0 0.0 0.0) (40 . 1.0) (1 . "new") (7 . "Mono")))
"#;

/// Runs `tests/validate/dxf_edits.py MODE ARGS...` and gives its output.
fn edits_py(args: &[&std::path::Path], mode: &str) -> Vec<u8> {
    let o = Command::new(python())
        .arg(manifest().join("tests/validate/dxf_edits.py"))
        .arg(mode)
        .args(args)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    o.stdout
}

/// `(dxf-import "o.dxf")` into `t.dxf` opened, saved as `result`.
fn import_o_into_t(d: &std::path::Path, result: &std::path::Path) {
    std::fs::write(d.join("import.lsp"), "(dxf-import \"o.dxf\")").unwrap();
    let o = lispcad(
        d,
        &[
            "run",
            "import.lsp",
            "--open",
            "t.dxf",
            "-o",
            result.to_str().unwrap(),
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// A check's verdict: no differences, and ezdxf's audit found no error and fixed nothing.
fn assert_clean(r: &serde_json::Value, what: &str) {
    assert!(strs(&r["diffs"]).is_empty(), "{what}: {r:#}");
    assert!(strs(&r["audit_errors"]).is_empty(), "{what}: {r:#}");
    assert!(strs(&r["audit_fixes"]).is_empty(), "{what}: {r:#}");
}

fn edits(dir: &std::path::Path, version: &str) -> serde_json::Value {
    let script = manifest().join("tests/validate/dxf_edits.py");
    let orig = dir.join(format!("{version}.dxf"));
    let out = dir.join(format!("{version}-edited.dxf"));
    let o = Command::new(python())
        .arg(&script)
        .args(["make", orig.to_str().unwrap(), version])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = lispcad(
        dir,
        &[
            "run",
            "edit.lsp",
            "--open",
            orig.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ],
    );
    assert!(
        o.status.success(),
        "{version}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let o = Command::new(python())
        .arg(&script)
        .args(["check", orig.to_str().unwrap(), out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn entmod_changes_only_the_given_groups() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("edit.lsp"), EDIT).unwrap();
    for version in ["R12", "R2000", "R2018"] {
        let r = edits(dir.path(), version);
        assert_clean(&r, version);
        assert!(strs(&r["styles"]).contains(&"Mono".to_string()), "{r}");
    }
}

#[test]
fn dxf_import_brings_the_block_definitions_its_inserts_need() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (target, other, result) = (d.join("t.dxf"), d.join("o.dxf"), d.join("r.dxf"));
    edits_py(&[&target, &other], "import-make");
    import_o_into_t(d, &result);
    let r: serde_json::Value =
        serde_json::from_slice(&edits_py(&[&target, &other, &result], "import-check")).unwrap();
    assert_clean(&r, "");
}

/// Into a drawing made from scratch, an import of INSERTs with ATTRIBs, DIMENSIONs and the
/// blocks, styles and line types they name is written whole (the R2000 writer of new drawings
/// used to drop them); a drawing that already has entities of its own refuses instead.
#[test]
fn dxf_import_into_a_new_drawing_keeps_its_inserts() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let script = manifest().join("tests/validate/dxf_edits.py");
    let (target, other, result) = (d.join("t.dxf"), d.join("o.dxf"), d.join("r.dxf"));
    let o = Command::new(python())
        .arg(&script)
        .arg("import-make")
        .args([&target, &other])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::write(
        d.join("import.lsp"),
        "(dxf-import \"o.dxf\")\n(entmake '((0 . \"LINE\") (8 . \"NEW\") (10 1.0 2.0 0.0) (11 7.0 8.0 0.0)))",
    )
    .unwrap();
    let o = lispcad(d, &["run", "import.lsp", "-o", result.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = Command::new(python())
        .arg(&script)
        .arg("scratch-check")
        .args([&other, &result])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_clean(&r, "");
}

/// Into a drawing made from scratch that already has entities (a script holds their
/// enames), the import relocates every record of the file above the drawing's handles: the
/// drawing's own entities keep theirs and come back unchanged, the file's INSERTs, ATTRIBs,
/// DIMENSIONs, hatch associations, reactors, group, extension dictionary and xdata handle
/// point at the relocated records, and ezdxf's audit finds nothing.
#[test]
fn dxf_import_into_a_drawing_with_content_relocates_handles() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let script = manifest().join("tests/validate/dxf_edits.py");
    let py = |args: &[&str]| {
        let o = Command::new(python())
            .arg(&script)
            .args(args)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    let (t, o) = (d.join("t.dxf"), d.join("o.dxf"));
    py(&["import-make", t.to_str().unwrap(), o.to_str().unwrap()]);
    let own = r#"
(regapp "MINE")
(entmake '((0 . "LINE") (8 . "MINE") (10 1.0 2.0 0.0) (11 7.0 8.0 0.0)
           (-3 ("MINE" (1000 . "own")))))
(entmake '((0 . "CIRCLE") (8 . "0") (62 . 5) (10 3.0 3.0 0.0) (40 . 2.0)))
(entmake '((0 . "LAYER") (100 . "AcDbSymbolTableRecord") (100 . "AcDbLayerTableRecord")
           (2 . "DASHY") (70 . 0) (62 . 2) (6 . "MYDASH")))
(entmake '((0 . "LINE") (8 . "DASHY") (10 0.0 0.0 0.0) (11 1.0 0.0 0.0)))
(entmake '((0 . "LWPOLYLINE") (100 . "AcDbEntity") (8 . "MINE") (100 . "AcDbPolyline")
           (90 . 3) (70 . 1) (10 0.0 0.0) (42 . 0.5) (10 5.0 0.0) (10 5.0 5.0)))
(setq mine (entlast))
"#;
    std::fs::write(d.join("alone.lsp"), own).unwrap();
    std::fs::write(
        d.join("late.lsp"),
        format!(
            "{own}(dxf-import \"o.dxf\")\n\
             (if (not (equal (cdr (assoc 0 (entget mine))) \"LWPOLYLINE\")) (exit))"
        ),
    )
    .unwrap();
    for (lsp, out) in [("alone.lsp", "alone.dxf"), ("late.lsp", "late.dxf")] {
        let o = lispcad(d, &["run", lsp, "-o", out]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let paths = ["o.dxf", "alone.dxf", "late.dxf"].map(|f| d.join(f).display().to_string());
    let r: serde_json::Value =
        serde_json::from_slice(&py(&["late-check", &paths[0], &paths[1], &paths[2]])).unwrap();
    assert_clean(&r, "");
}

/// An R12 file's records imported into an R2018 drawing get the subclass markers ezdxf
/// itself writes for them (LINE to DIMENSION, POLYLINE's VERTEXes and face records,
/// INSERT's ATTRIBs, the BLOCK and ATTDEF of its block), and read back with the R12 values
/// (thickness and text alignment included).
#[test]
fn dxf_import_of_r12_into_r2018_adds_subclass_markers() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (target, other, result) = (d.join("t.dxf"), d.join("o.dxf"), d.join("r.dxf"));
    edits_py(&[&target, &d.join("unused.dxf")], "import-make");
    edits_py(&[&other], "r12-make");
    import_o_into_t(d, &result);
    let r: serde_json::Value =
        serde_json::from_slice(&edits_py(&[&target, &other, &result], "r12-check")).unwrap();
    assert_clean(&r, "");
}

/// A POLYLINE or INSERT whose only change is its layer takes its VERTEX and SEQEND records
/// along (and a 3D polyline moved too), as AutoCAD and ezdxf keep them; the ATTRIBs keep
/// their own layer, as AutoCAD's CHPROP leaves them.
#[test]
fn a_new_layer_takes_the_followers_along() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let script = manifest().join("tests/validate/dxf_edits.py");
    let lsp = r#"
(setq v (entnext (entnext (ssname (ssget "X" '((8 . "P3"))) 0))) e (entget v))
(entmod (subst '(10 7.0 0.0 1.0) (assoc 10 e) e))
(setq ss (ssget "X") i 0)
(repeat (sslength ss)
  (setq e (entget (ssname ss i)) i (1+ i))
  (entmod (subst '(8 . "MOVED") (assoc 8 e) e)))
"#;
    std::fs::write(d.join("move.lsp"), lsp).unwrap();
    for version in ["R12", "R2000"] {
        let (orig, out) = (
            d.join(format!("{version}.dxf")),
            d.join(format!("{version}-m.dxf")),
        );
        let o = Command::new(python())
            .arg(&script)
            .args(["followers-make", orig.to_str().unwrap(), version])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let o = lispcad(
            d,
            &[
                "run",
                "move.lsp",
                "--open",
                orig.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ],
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let o = Command::new(python())
            .arg(&script)
            .args([
                "followers-check",
                orig.to_str().unwrap(),
                out.to_str().unwrap(),
            ])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_clean(&r, version);
    }
}

/// A group of the wrong type is an error, more of a repeated code than the entity has gives
/// nil, and neither changes the entity.
#[test]
fn entmod_of_kept_groups_refuses_what_does_not_fit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let script = manifest().join("tests/validate/dxf_edits.py");
    let o = Command::new(python())
        .arg(&script)
        .args(["make", d.join("in.dxf").to_str().unwrap(), "R2018"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let lsp = r#"
(setq h (ssname (ssget "X" '((0 . "HATCH"))) 0) e (entget h) more e)
(princ (vl-catch-all-error-p (vl-catch-all-apply 'entmod (list (subst '(41 . "x") (assoc 41 e) e)))))
(repeat 50 (setq more (append more '((10 1.0 2.0)))))
(princ " ")
(princ (entmod more))
(princ " ")
(princ (equal (entget h) e))
"#;
    std::fs::write(d.join("bad.lsp"), lsp).unwrap();
    let o = lispcad(d, &["run", "bad.lsp", "--open", "in.dxf"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "T nil T");
}
