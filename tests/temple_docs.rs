//! The pictures in docs/ are made from scripts/temple.lsp by this test, so they cannot go
//! stale: docs/temple.svg must be byte-identical to what the script draws now, docs/temple.png
//! (150 dpi) must have the size the script's drawing has now, docs/temple.pdf and
//! docs/sheet.svg (the contact sheet of scripts/variants.csv) must exist. Regenerate all four
//! with `LISPCAD_UPDATE_DOCS=1 cargo test --test temple_docs`, then look at them.

#[path = "cli_support/mod.rs"]
mod cli;

use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn png_size(p: &Path) -> (u32, u32) {
    let r = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(p).unwrap()))
        .read_info()
        .unwrap();
    (r.info().width, r.info().height)
}

#[test]
fn docs_pictures_are_made_from_the_script() {
    let dir = tempfile::tempdir().unwrap();
    let script = root().join("scripts/temple.lsp");
    let s = script.to_str().unwrap();
    let o = cli::lispcad_in(
        dir.path(),
        &[
            "run",
            s,
            "-o",
            "temple.svg",
            "-o",
            "temple.png",
            "-o",
            "temple.pdf",
            "--dpi",
            "150",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let table = root().join("scripts/variants.csv");
    let o = cli::lispcad_in(
        dir.path(),
        &[
            "batch",
            s,
            "--vary",
            table.to_str().unwrap(),
            "-o",
            "out/{name}.svg",
            "--sheet",
            "sheet.svg",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let docs = root().join("docs");
    let files = ["temple.svg", "temple.png", "temple.pdf", "sheet.svg"];
    if std::env::var_os("LISPCAD_UPDATE_DOCS").is_some() {
        for f in files {
            std::fs::copy(dir.path().join(f), docs.join(f)).unwrap();
        }
    }
    let fresh = std::fs::read_to_string(dir.path().join("temple.svg")).unwrap();
    let kept = std::fs::read_to_string(docs.join("temple.svg")).unwrap();
    assert!(
        fresh == kept,
        "docs/temple.svg is stale: LISPCAD_UPDATE_DOCS=1 cargo test --test temple_docs"
    );
    assert_eq!(
        png_size(&docs.join("temple.png")),
        png_size(&dir.path().join("temple.png")),
        "docs/temple.png is stale"
    );
    let sheet = std::fs::read_to_string(docs.join("sheet.svg")).unwrap();
    let fresh_sheet = std::fs::read_to_string(dir.path().join("sheet.svg")).unwrap();
    assert!(sheet == fresh_sheet, "docs/sheet.svg is stale");
    assert!(std::fs::metadata(docs.join("temple.pdf")).unwrap().len() > 1000);
}
