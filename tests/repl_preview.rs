//! The REPL's `:preview OUT.svg` rewrites the SVG after every evaluation.

mod cli_support;
use cli_support::repl_output;

#[test]
fn preview_rewrites_the_svg_after_each_evaluation() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("live.svg");
    let input = format!(
        ":preview {}\n(draw (circle '(0 0) 5))\n(draw (line '(0 0) '(30 0)))\n",
        out.display()
    );
    let o = repl_output(dir.path(), &[], &input);
    assert!(o.status.success());
    let svg = std::fs::read_to_string(&out).unwrap();
    // Both entities drawn in separate evaluations are in the file: the circle as two arcs,
    // then the line.
    assert!(
        svg.contains(r#"<path d="M5 0 A5 5 0 0 1 -5 0 A5 5 0 0 1 5 0 Z"/>"#),
        "{svg}"
    );
    assert!(svg.contains(r#"<path d="M0 0 L30 0"/>"#), "{svg}");
}
