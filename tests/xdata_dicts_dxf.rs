//! Extended data, registered applications, dictionaries and XRECORDs written to DXF and read
//! back by ezdxf (tests/validate/xdata_dicts.py): on a drawing made from scratch, and on a
//! drawing ezdxf made, opened with `--open`, read by the script and changed. The files load
//! with ezdxf's strict reader and audit with 0 errors and 0 fixes.

mod output_support;

use std::path::Path;

use serde_json::{json, Value};

fn ezdxf(mode: &str, path: &Path) -> Value {
    output_support::validator_json("xdata_dicts.py", mode, path)
}

fn lispcad(dir: &Path, script: &str, args: &[&str]) -> String {
    output_support::run_script(dir, script, args)
}

/// The xdata of the one model-space entity of `ty` matching `pick`.
fn apps_of<'a>(doc: &'a Value, ty: &str, pick: impl Fn(&Value) -> bool) -> &'a Value {
    let ents = doc["entities"].as_object().unwrap();
    let found: Vec<&Value> = ents
        .values()
        .filter(|e| e["type"] == ty && pick(&e["apps"]))
        .collect();
    assert_eq!(found.len(), 1, "one {ty} wanted in {}", doc["entities"]);
    &found[0]["apps"]
}

#[test]
fn new_drawing_xdata_and_dictionaries_read_back_by_ezdxf() {
    let dir = tempfile::tempdir().unwrap();
    let script = r#"
(regapp "LCAPP")
(setq e (entmakex '((0 . "LINE") (10 0 0 0) (11 4 0 0)
  (-3 ("LCAPP" (1000 . "Größe") (1070 . 12) (1040 . 0.125) (1010 1.5 2.5 0.0) (1071 . 70000))))))
(setq c (entmakex '((0 . "CIRCLE") (10 1 1 0) (40 . 2.0))))
(entmod (list (cons -1 c) '(-3 ("LCAPP" (1000 . "circle")))))
(setq d (entmakex '((0 . "DICTIONARY") (100 . "AcDbDictionary"))))
(dictadd (namedobjdict) "LC_DICT" d)
(setq x (entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "hello") (40 . 2.5) (70 . 3) (10 1.0 2.0 3.0))))
(dictadd d "REC1" x)
;; Never placed, and placed then removed: neither is written.
(entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "nobody")))
(setq gone (entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "removed"))))
(dictadd d "GONE" gone)
(dictremove d "GONE")
;; Filled before the dictionary itself is placed.
(setq d2 (entmakex '((0 . "DICTIONARY") (100 . "AcDbDictionary"))))
(setq x2 (entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "late"))))
(dictadd d2 "LATE" x2)
(dictadd d "SUB" d2)
;; A POLYLINE's extended data is given on its header.
(entmake '((0 . "POLYLINE") (66 . 1) (70 . 1) (-3 ("LCAPP" (1000 . "header") (1070 . 3)))))
(entmake '((0 . "VERTEX") (10 0 0 0)))
(entmake '((0 . "VERTEX") (10 4 0 0) (42 . 1.0)))
(entmake '((0 . "VERTEX") (10 4 4 0)))
(entmake '((0 . "SEQEND")))
"#;
    lispcad(dir.path(), script, &["-o", "out.dxf"]);
    let doc = ezdxf("check", &dir.path().join("out.dxf"));
    assert!(doc["appids"].as_array().unwrap().contains(&json!("LCAPP")));
    let line = apps_of(&doc, "LINE", |_| true);
    assert_eq!(
        line["LCAPP"],
        json!([
            [1000, "Größe"],
            [1070, 12],
            [1040, 0.125],
            [1010, [1.5, 2.5, 0.0]],
            [1071, 70000]
        ])
    );
    let pl = apps_of(&doc, "POLYLINE", |_| true);
    assert_eq!(pl["LCAPP"], json!([[1000, "header"], [1070, 3]]));
    let circle = apps_of(&doc, "CIRCLE", |_| true);
    assert_eq!(circle["LCAPP"], json!([[1000, "circle"]]));
    let lc = &doc["root"]["LC_DICT"];
    assert_eq!(lc["type"], "DICTIONARY");
    let entries = lc["entries"].as_object().unwrap();
    let mut keys: Vec<&String> = entries.keys().collect();
    keys.sort();
    assert_eq!(keys, ["REC1", "SUB"]);
    assert_eq!(
        entries["REC1"]["tags"],
        json!([[1, "hello"], [40, 2.5], [70, 3], [10, [1.0, 2.0, 3.0]]])
    );
    assert_eq!(
        entries["SUB"]["entries"]["LATE"]["tags"],
        json!([[1, "late"]])
    );
    // The root dictionary keeps the entries every drawing has.
    assert_eq!(doc["root"]["ACAD_GROUP"]["type"], "DICTIONARY");
    assert_eq!(doc["root"]["ACAD_LAYOUT"]["type"], "DICTIONARY");
}

#[test]
fn opened_ezdxf_drawing_xdata_and_dictionaries_are_read_and_changed() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("py.dxf");
    ezdxf("make", &input);
    let script = r#"
(setq l (ssname (ssget "X" '((0 . "LINE"))) 0))
(prin1 (assoc -3 (entget l '("PYAPP")))) (terpri)
(prin1 (sslength (ssget "X" '((-3 ("PY*")))))) (terpri)
(setq pyd (cdr (assoc -1 (dictsearch (namedobjdict) "PY_DICT"))))
(setq rec (dictsearch pyd "REC"))
(prin1 (mapcar '(lambda (c) (cdr (assoc c rec))) '(0 1 40 70))) (terpri)
(regapp "LCAPP")
(entmod (list (cons -1 l) '(-3 ("LCAPP" (1000 . "added")))))
(setq c (ssname (ssget "X" '((0 . "CIRCLE"))) 0))
(entmod (list (cons -1 c) '(-3 ("PYAPP" (1070 . 7)))))
(entmakex '((0 . "LINE") (10 0 5 0) (11 5 5 0) (-3 ("LCAPP" (1000 . "new line")))))
(setq x (entmakex '((0 . "XRECORD") (100 . "AcDbXrecord") (1 . "lispcad") (40 . 0.5))))
(dictadd pyd "LC_REC" x)
(setq xl (entget (cdr (assoc -1 rec))))
(entmod (subst '(1 . "changed") (assoc 1 xl) xl))
(prin1 (assoc -3 (entget l '("*")))) (terpri)
"#;
    let out = lispcad(dir.path(), script, &["--open", "py.dxf", "-o", "out.dxf"]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines,
        [
            r#"(-3 ("PYAPP" (1000 . "from python") (1070 . 42) (1010 1.0 2.0 3.0) (1040 . 1.5)))"#,
            "1",
            r#"("XRECORD" "py text" 2.25 9)"#,
            r#"(-3 ("PYAPP" (1000 . "from python") (1070 . 42) (1010 1.0 2.0 3.0) (1040 . 1.5)) ("LCAPP" (1000 . "added")))"#,
        ]
    );
    let doc = ezdxf("check", &dir.path().join("out.dxf"));
    assert!(doc["appids"].as_array().unwrap().contains(&json!("LCAPP")));
    let old_line = apps_of(&doc, "LINE", |a| a.get("PYAPP").is_some());
    assert_eq!(
        old_line["PYAPP"],
        json!([
            [1000, "from python"],
            [1070, 42],
            [1010, [1.0, 2.0, 3.0]],
            [1040, 1.5]
        ])
    );
    assert_eq!(old_line["LCAPP"], json!([[1000, "added"]]));
    let new_line = apps_of(&doc, "LINE", |a| a.get("PYAPP").is_none());
    assert_eq!(new_line["LCAPP"], json!([[1000, "new line"]]));
    assert_eq!(
        apps_of(&doc, "CIRCLE", |_| true)["PYAPP"],
        json!([[1070, 7]])
    );
    let py = &doc["root"]["PY_DICT"]["entries"];
    assert_eq!(
        py["REC"]["tags"],
        json!([[1, "changed"], [40, 2.25], [70, 9]])
    );
    assert_eq!(py["LC_REC"]["tags"], json!([[1, "lispcad"], [40, 0.5]]));
}
