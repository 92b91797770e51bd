//! Opening and saving DXF files: ezdxf-made drawings of every version (R12..R2018, binary,
//! code pages and UTF-8) come back as the same document to ezdxf; an edit changes only the
//! edited entity; opened entities answer entget/ssget as AutoCAD's do.

mod dxf_support;

use std::path::PathBuf;

use dxf_support::{compare, lispcad, samples, strs};

#[test]
fn every_version_round_trips_unchanged() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("src");
    let files = samples(&src);
    assert!(files.len() >= 13, "{files:?}");
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let mut args = vec!["convert".to_string()];
    args.extend(files.iter().map(|f| f.display().to_string()));
    args.extend(["-o".into(), format!("{}/{{stem}}.dxf", out.display())]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = lispcad(dir.path(), &args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let pairs: Vec<(PathBuf, PathBuf)> = files
        .iter()
        .map(|f| (f.clone(), out.join(f.file_name().unwrap())))
        .collect();
    for (f, c) in &pairs {
        let name = f.file_name().unwrap().to_string_lossy();
        if !name.contains("bin") {
            // Nothing changed: an ASCII file comes back byte for byte.
            assert_eq!(
                std::fs::read(f).unwrap(),
                std::fs::read(c).unwrap(),
                "{name}"
            );
        }
    }
    for r in compare(&pairs) {
        let name = r["orig"].as_str().unwrap();
        assert!(r.get("load_error").is_none(), "{name}: {r}");
        assert!(r["diffs"].as_array().unwrap().is_empty(), "{name}: {r}");
        assert!(strs(&r["audit_errors"]).is_empty(), "{name}: {r}");
        assert!(strs(&r["audit_fixes"]).is_empty(), "{name}: {r}");
        assert!(strs(&r["extra"]).is_empty(), "{name}: {r}");
        assert!(r["objects"].as_u64().unwrap() >= 30, "{name}: {r}");
    }
}

/// A script that moves one circle to another layer, moves one line's end and adds a line.
const EDIT: &str = r#"
(setq ss (ssget "X" '((0 . "CIRCLE") (62 . 2))))
(setq c (ssname ss 0))
(entmod (subst '(8 . "Outline") (assoc 8 (entget c)) (entget c)))
(setq l (ssname (ssget "X" '((0 . "LINE") (8 . "Outline"))) 0))
(entmod (subst '(11 99.0 98.0 0.0) (assoc 11 (entget l)) (entget l)))
(entmake '((0 . "LINE") (8 . "New") (10 0.0 0.0 0.0) (11 1.0 1.0 0.0)))
(princ (strcat (cdr (assoc 5 (entget c))) " " (cdr (assoc 5 (entget l))) " "
               (cdr (assoc 5 (entget (entlast))))))
"#;

#[test]
fn an_edit_changes_only_the_edited_entities() {
    let dir = tempfile::tempdir().unwrap();
    let files = samples(&dir.path().join("src"));
    std::fs::write(dir.path().join("edit.lsp"), EDIT).unwrap();
    let mut pairs = Vec::new();
    let mut handles = Vec::new();
    for v in ["R12", "R2000", "R2018", "R2018_bin"] {
        let input = files
            .iter()
            .find(|f| f.file_stem().unwrap() == v)
            .unwrap()
            .clone();
        let out = dir.path().join(format!("{v}-edited.dxf"));
        let o = lispcad(
            dir.path(),
            &[
                "run",
                "edit.lsp",
                "--open",
                input.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ],
        );
        assert!(
            o.status.success(),
            "{v}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let printed = String::from_utf8_lossy(&o.stdout).trim().to_string();
        let h: Vec<String> = printed.split(' ').map(str::to_string).collect();
        assert_eq!(h.len(), 3, "{printed}");
        handles.push(h);
        pairs.push((input, out));
    }
    for (r, h) in compare(&pairs).iter().zip(&handles) {
        let name = r["orig"].as_str().unwrap();
        assert!(r.get("load_error").is_none(), "{name}: {r}");
        assert!(strs(&r["audit_errors"]).is_empty(), "{name}: {r}");
        assert!(strs(&r["audit_fixes"]).is_empty(), "{name}: {r}");
        let diffs = strs(&r["diffs"]);
        let circle: Vec<&String> = diffs
            .iter()
            .filter(|d| d.starts_with(&format!("{} ", h[0])))
            .collect();
        assert_eq!(circle.len(), 1, "{name}: {diffs:?}");
        assert!(
            circle[0].contains("layer: '0' -> 'Outline'"),
            "{name}: {diffs:?}"
        );
        let line: Vec<&String> = diffs
            .iter()
            .filter(|d| d.starts_with(&format!("{} ", h[1])))
            .collect();
        assert_eq!(line.len(), 1, "{name}: {diffs:?}");
        assert!(line[0].contains("end"), "{name}: {diffs:?}");
        // Nothing else differs: the layer table gained "New" and the drawing one LINE.
        assert_eq!(diffs.len(), 2, "{name}: {diffs:?}");
        let extra = strs(&r["extra"]);
        assert!(
            extra.contains(&format!("{} LINE", h[2])),
            "{name}: {extra:?}"
        );
        assert!(
            extra
                .iter()
                .all(|e| e.ends_with(" LINE") || e.ends_with(" LAYER")),
            "{name}: {extra:?}"
        );
    }
}

/// entget, ssget and the sub-entity walk over an opened drawing, as AutoCAD answers them.
const QUERY: &str = r#"
(defun show (x) (prin1 x) (terpri))
(show (sslength (ssget "X")))
(show (sslength (ssget "X" '((0 . "INSERT")))))
(setq ins (ssname (ssget "X" '((0 . "INSERT"))) 0))
(show (cdr (assoc 2 (entget ins))))
(setq att (entnext ins))
(show (cdr (assoc 0 (entget att))))
(show (cdr (assoc 1 (entget att))))
(setq el (ssname (ssget "X" '((0 . "ELLIPSE"))) 0))
(show (cdr (assoc 40 (entget el))))
(setq lw (entget (ssname (ssget "X" '((0 . "LWPOLYLINE"))) 0)))
(show (cdr (assoc 90 lw)))
(show (mapcar 'cdr (vl-remove-if-not '(lambda (g) (= (car g) 42)) lw)))
(setq tx (entget (ssname (ssget "X" '((0 . "TEXT"))) 0)))
(show (cdr (assoc 1 tx)))
(show (cdr (assoc 62 (tblsearch "LAYER" "Outline"))))
(show (cdr (assoc 70 (tblsearch "LAYER" "Frozen"))))
(show (sslength (ssget "X" '((8 . "Outline")))))
(show (cdr (assoc 0 (entget (handent (cdr (assoc 5 (entget ins))))))))
(show (cdr (assoc 2 (tblsearch "BLOCK" "TAG"))))
(show (cdr (assoc 2 (tblnext "APPID" T))))
(show (cdr (assoc 3 (tblsearch "STYLE" "Standard"))))
"#;

#[test]
fn opened_entities_answer_entget_and_ssget() {
    let dir = tempfile::tempdir().unwrap();
    let files = samples(&dir.path().join("src"));
    std::fs::write(dir.path().join("q.lsp"), QUERY).unwrap();
    let input = files
        .iter()
        .find(|f| f.file_stem().unwrap() == "R2000")
        .unwrap();
    let o = lispcad(
        dir.path(),
        &["run", "q.lsp", "--open", input.to_str().unwrap()],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines,
        vec![
            // Model space (22), the active layout (1) and the other layout, Sheet2 (1).
            "24",
            "1",
            "\"TAG\"",
            "\"ATTRIB\"",
            "\"value Größe café €\"",
            "0.4",
            "4",
            "(0.5 0.0 -1.0 0.0)",
            "\"Größe café €\"",
            "1",
            "1",
            "2",
            "\"INSERT\"",
            "\"TAG\"",
            "\"ACAD\"",
            "\"txt\"",
        ],
        "{out}"
    );
}

/// `command` ERASE and LAYER on an opened drawing: the erased entities are gone, the layer's
/// flags and colour change in its own record, nothing else differs.
const COMMANDS: &str = r#"
(command "_.ERASE" (ssget "X" '((0 . "ARC"))) "")
(command "_.LAYER" "_Color" "4" "Outline" "_LOck" "Frozen" "")
"#;

#[test]
fn erase_and_layer_commands_edit_the_opened_drawing() {
    let dir = tempfile::tempdir().unwrap();
    let files = samples(&dir.path().join("src"));
    std::fs::write(dir.path().join("c.lsp"), COMMANDS).unwrap();
    let input = files
        .iter()
        .find(|f| f.file_stem().unwrap() == "R2013")
        .unwrap();
    let out = dir.path().join("out.dxf");
    let o = lispcad(
        dir.path(),
        &[
            "run",
            "c.lsp",
            "--open",
            input.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = &compare(&[(input.clone(), out)])[0];
    assert!(strs(&r["audit_errors"]).is_empty(), "{r}");
    assert!(strs(&r["audit_fixes"]).is_empty(), "{r}");
    let mut diffs = strs(&r["diffs"]);
    diffs.sort();
    assert_eq!(diffs.len(), 3, "{diffs:?}");
    assert!(
        diffs.iter().any(|d| d.ends_with("ARC missing")),
        "{diffs:?}"
    );
    assert!(
        diffs.iter().any(|d| d.contains("LAYER color: 1 -> 4")),
        "{diffs:?}"
    );
    assert!(
        diffs.iter().any(|d| d.contains("LAYER flags: 1 -> 5")),
        "{diffs:?}"
    );
}
