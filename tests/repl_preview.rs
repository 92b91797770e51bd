//! The REPL's `:preview OUT.svg` rewrites the SVG after every evaluation.

use std::io::Write;
use std::process::{Command, Stdio};

#[test]
fn preview_rewrites_the_svg_after_each_evaluation() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("live.svg");
    let mut child = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("repl")
        .current_dir(dir.path())
        .env("LISPCAD_HISTORY", dir.path().join("hist"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let input = format!(
        ":preview {}\n(draw (circle '(0 0) 5))\n(draw (line '(0 0) '(30 0)))\n",
        out.display()
    );
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success());
    let svg = std::fs::read_to_string(&out).unwrap();
    // Both entities drawn in separate evaluations are in the file.
    assert!(svg.contains("<circle") || svg.contains(" A"), "{svg}");
    assert!(
        svg.matches("<path").count() + svg.matches("<line").count() >= 1,
        "{svg}"
    );
    assert!(
        svg.contains("30"),
        "the line's end point is in the preview: {svg}"
    );
}
