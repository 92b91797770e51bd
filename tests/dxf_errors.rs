//! Bad drawings: each damaged-file case is exit 1 with the line (or byte offset) named and no
//! output written; `--recover` reads what can be read and says so. Also `entity-curve` on
//! an opened polyline.

mod dxf_support;

use dxf_support::lispcad;

const GOOD: &str = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n5\n2A\n8\nOutline\n90\n4\n70\n1\n10\n0.0\n20\n0.0\n10\n10.0\n20\n0.0\n10\n10.0\n20\n10.0\n10\n0.0\n20\n10.0\n0\nENDSEC\n0\nEOF\n";

fn convert_fails(data: &[u8], want: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("in.dxf"), data).unwrap();
    let o = lispcad(dir.path(), &["convert", "in.dxf", "-o", "out.dxf"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    for w in want {
        assert!(err.contains(w), "missing {w:?} in: {err}");
    }
    assert!(
        !dir.path().join("out.dxf").exists(),
        "output written for a bad file"
    );
}

#[test]
fn empty_file() {
    convert_fails(b"", &["in.dxf", "empty"]);
}

#[test]
fn truncated_file() {
    let cut: String = GOOD.lines().take(30).map(|l| format!("{l}\n")).collect();
    convert_fails(
        cut.as_bytes(),
        &[
            "line 29",
            "ends inside the ENTITIES section begun at line 1",
            "truncated",
        ],
    );
}

#[test]
fn non_numeric_value() {
    let bad = GOOD.replace("10\n10.0\n20\n10.0", "10\nten\n20\n10.0");
    convert_fails(
        bad.as_bytes(),
        &["line 23", "group code 10 needs a number", "\"ten\""],
    );
}

#[test]
fn odd_number_of_lines() {
    let bad = GOOD.trim_end().strip_suffix("EOF").unwrap().to_string();
    convert_fails(bad.as_bytes(), &["line 33", "odd number of lines"]);
}

#[test]
fn binary_file_that_is_not_dxf() {
    convert_fails(
        b"\x7fELF\x02\x01\x01\0\0\0\0",
        &["byte 7", "not a DXF file"],
    );
}

#[test]
fn unknown_group_code_in_a_known_entity() {
    let bad = GOOD.replace("70\n1\n", "70\n1\n77\n5\n");
    convert_fails(
        bad.as_bytes(),
        &["line 15", "group code 77 is not valid in a LWPOLYLINE"],
    );
}

#[test]
fn recover_reads_damaged_files_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let bad = GOOD.replace("70\n1\n", "70\n1\n77\n5\n");
    std::fs::write(dir.path().join("in.dxf"), bad).unwrap();
    let o = lispcad(
        dir.path(),
        &["convert", "--recover", "in.dxf", "-o", "out.dxf"],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("--recover") && err.contains("1 bad group"),
        "{err}"
    );
    let out = std::fs::read_to_string(dir.path().join("out.dxf")).unwrap();
    assert!(
        out.contains("LWPOLYLINE") && !out.contains("\n 77\n"),
        "{out}"
    );
}

#[test]
fn entity_curve_of_an_opened_polyline() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("in.dxf"), GOOD).unwrap();
    std::fs::write(
        dir.path().join("c.lsp"),
        "(setq e (ssname (ssget \"X\" '((8 . \"Outline\"))) 0))\n\
         (princ (curve-length (entity-curve e)))",
    )
    .unwrap();
    let o = lispcad(dir.path(), &["run", "c.lsp", "--open", "in.dxf"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), "40.0");
}
