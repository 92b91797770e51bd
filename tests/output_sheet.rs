//! `batch --sheet` (issue 15 item 6): one contact sheet of every row's drawing, one labelled
//! group per row, at one common scale; the SVG renders (rsvg-convert) and the PDF renders
//! (pdftoppm).

#[path = "cli_support/mod.rs"]
mod cli;
#[path = "output_support/mod.rs"]
mod support;

use std::process::Command;

#[test]
fn the_sheet_of_variants_has_one_labelled_group_per_row_and_renders() {
    let dir = tempfile::tempdir().unwrap();
    let root = support::manifest();
    let script = root.join("scripts/temple.lsp");
    let table = root.join("scripts/variants.csv");
    let names: Vec<String> = std::fs::read_to_string(&table)
        .unwrap()
        .lines()
        .skip(1)
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').next().unwrap().trim_matches('"').to_string())
        .collect();
    for sheet in ["sheet.svg", "sheet.pdf"] {
        let o = cli::lispcad_in(
            dir.path(),
            &[
                "batch",
                script.to_str().unwrap(),
                "--vary",
                table.to_str().unwrap(),
                "-o",
                "out/{name}.dxf",
                "--sheet",
                sheet,
                "-j",
                "2",
            ],
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let svg = std::fs::read_to_string(dir.path().join("sheet.svg")).unwrap();
    assert_eq!(svg.matches("class=\"sheet-row\"").count(), names.len());
    for (i, name) in names.iter().enumerate() {
        let start = svg.find(&format!("<g id=\"row-{}\"", i + 1)).unwrap();
        let group = &svg[start..start + svg[start..].find("</g>\n</svg>\n</g>").unwrap_or(2000)];
        assert!(
            group.contains(&format!(">{}: {name}</text>", i + 1)),
            "row {} is not labelled {name}",
            i + 1
        );
    }
    assert!(svg.contains("scale 1:1"));
    support::render_svg(&dir.path().join("sheet.svg"), &dir.path().join("sheet.png"));
    let st = Command::new("pdftoppm")
        .args(["-r", "30", "-png", "-singlefile"])
        .arg(dir.path().join("sheet.pdf"))
        .arg(dir.path().join("sheet-pdf"))
        .status()
        .unwrap();
    assert!(st.success());
    assert!(
        std::fs::metadata(dir.path().join("sheet-pdf.png"))
            .unwrap()
            .len()
            > 10_000
    );
}

#[test]
fn a_sheet_of_another_format_is_a_usage_error() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), "(draw (circle '(0 0) 1))").unwrap();
    let o = cli::lispcad_in(
        dir.path(),
        &[
            "batch",
            "s.lsp",
            "--grid",
            "R=1,2",
            "-o",
            "o{row}.svg",
            "--sheet",
            "s.png",
        ],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(!dir.path().join("o1.svg").exists());
}
