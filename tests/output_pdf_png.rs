//! PDF and PNG at true scale, and INSUNITS (issue 15 items 1 and 2): the CUT outline's extent
//! measured in pixels — the PDF rendered by poppler's pdftoppm, the PNG decoded directly —
//! matches its extent read from the DXF by ezdxf to 0.3 mm, for a drawing in millimetres and
//! one in inches; the DXF header and the SVG carry the unit; a bad output extension is a usage
//! error before the script runs; the PDF's layers are optional content groups that pypdf lists
//! by name and that poppler hides when they are switched off.

#[path = "cli_support/mod.rs"]
mod cli;
#[path = "output_support/mod.rs"]
mod support;

use std::path::Path;
use std::process::Command;

/// The CUT layer is drawn in ACI 1, pure red; the stroke (0.25 mm) adds half its width on
/// each side of the true outline.
const STROKE_MM: f64 = 0.25;

/// Width and height (mm) of the red pixels of an RGB(A) PNG at `dpi`.
fn red_extent_mm(png_path: &Path, dpi: f64) -> (f64, f64) {
    let dec = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(png_path).unwrap(),
    ));
    let mut r = dec.read_info().unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    let ch = info.color_type.samples();
    let (w, h) = (info.width as usize, info.height as usize);
    let (mut x0, mut x1, mut y0, mut y1) = (usize::MAX, 0, usize::MAX, 0);
    for y in 0..h {
        for x in 0..w {
            let p = &buf[(y * w + x) * ch..(y * w + x) * ch + 3];
            if p[0] > 128 && p[1] < 100 && p[2] < 100 {
                x0 = x0.min(x);
                x1 = x1.max(x);
                y0 = y0.min(y);
                y1 = y1.max(y);
            }
        }
    }
    assert!(x0 <= x1, "no red pixel in {}", png_path.display());
    let mm = 25.4 / dpi;
    (((x1 - x0 + 1) as f64) * mm, ((y1 - y0 + 1) as f64) * mm)
}

fn pdftoppm(pdf: &Path, dpi: u32, stem: &Path) -> std::path::PathBuf {
    let st = Command::new("pdftoppm")
        .args(["-r", &dpi.to_string(), "-png", "-singlefile"])
        .arg(pdf)
        .arg(stem)
        .status()
        .expect("pdftoppm missing: run .ci/setup");
    assert!(st.success());
    stem.with_extension("png")
}

/// Runs `script` to DXF, PDF, PNG and SVG; checks the three pictures against the DXF.
fn check_true_scale(dir: &Path, script: &str, unit_mm: f64, insunits: i64) {
    std::fs::write(dir.join("s.lsp"), script).unwrap();
    let o = cli::lispcad_in(
        dir,
        &[
            "run", "s.lsp", "-o", "s.dxf", "-o", "s.pdf", "-o", "s.png", "-o", "s.svg", "--dpi",
            "200",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let ([x0, y0, x1, y1], units, measurement) = support::ezdxf_cut_extent(&dir.join("s.dxf"));
    let (w, h) = (x1 - x0, y1 - y0);
    assert_eq!(units, insunits);
    assert_eq!(measurement, if insunits == 1 { 0 } else { 1 });
    let (w_mm, h_mm) = (w * unit_mm + STROKE_MM, h * unit_mm + STROKE_MM);
    let rendered = pdftoppm(&dir.join("s.pdf"), 300, &dir.join("from-pdf"));
    for (png, dpi) in [(rendered, 300.0), (dir.join("s.png"), 200.0)] {
        let (pw, ph) = red_extent_mm(&png, dpi);
        assert!(
            (pw - w_mm).abs() <= 0.3 && (ph - h_mm).abs() <= 0.3,
            "{}: {pw} x {ph} mm, DXF says {w_mm} x {h_mm}",
            png.display()
        );
    }
    let svg = std::fs::read_to_string(dir.join("s.svg")).unwrap();
    let width = svg
        .split("width=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap();
    let unit = if insunits == 1 { "in" } else { "mm" };
    let value: f64 = width.strip_suffix(unit).expect(width).parse().unwrap();
    let expect_mm = w_mm - STROKE_MM + 2.0 * 5.0; // CUT is the widest layer here
    let got_mm = value * if insunits == 1 { 25.4 } else { 1.0 };
    assert!(
        got_mm >= expect_mm - 0.3,
        "SVG width {width}, CUT alone needs {expect_mm} mm"
    );
}

#[test]
fn the_temple_in_millimetres_prints_at_true_scale() {
    let dir = tempfile::tempdir().unwrap();
    let script = std::fs::read_to_string(support::manifest().join("scripts/temple.lsp")).unwrap();
    check_true_scale(dir.path(), &script, 1.0, 4);
}

#[test]
fn an_inch_drawing_prints_at_true_scale() {
    let dir = tempfile::tempdir().unwrap();
    // A closed outline 4 × 1.5 inches, a spline on its way round.
    let script = "(setvar \"INSUNITS\" 1)\n(layer \"CUT\" 1)\n\
                  (draw (spline '((0 0) (2 -0.25) (4 0) (4 1.5) (2 1.75) (0 1.5)) T))\n\
                  (layer \"NOTES\" 7)\n(draw (line '(0 -1) '(4 -1)))\n";
    check_true_scale(dir.path(), script, 25.4, 1);
}

#[test]
fn pdf_page_is_the_extents_plus_margin() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("r.lsp"),
        "(layer \"CUT\" 1)\n(draw (pline '((0 0) (100 0) (100 50) (0 50)) T))\n",
    )
    .unwrap();
    let o = cli::lispcad_in(dir.path(), &["run", "r.lsp", "-o", "r.pdf"]);
    assert!(o.status.success());
    let info = Command::new("pdfinfo")
        .arg(dir.path().join("r.pdf"))
        .output();
    if let Ok(info) = info {
        let text = String::from_utf8_lossy(&info.stdout);
        let line = text.lines().find(|l| l.starts_with("Page size")).unwrap();
        // 110 × 60 mm (5 mm margin) in points.
        let nums: Vec<f64> = line
            .split_whitespace()
            .filter_map(|w| w.parse().ok())
            .collect();
        let pt = 72.0 / 25.4;
        assert!((nums[0] - 110.0 * pt).abs() < 0.05, "{line}");
        assert!((nums[1] - 60.0 * pt).abs() < 0.05, "{line}");
    }
}

#[test]
fn unknown_output_extension_is_a_usage_error_before_the_run() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("w.lsp"),
        "(setq f (open \"ran.txt\" \"w\")) (close f)",
    )
    .unwrap();
    let o = cli::lispcad_in(dir.path(), &["run", "w.lsp", "-o", "x.jpg"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("x.jpg"));
    assert!(!dir.path().join("ran.txt").exists(), "the script ran");
    let o = cli::lispcad_in(dir.path(), &["run", "w.lsp", "--dpi", "0", "-o", "x.png"]);
    assert_eq!(o.status.code(), Some(2), "a bad --dpi is a usage error");
    assert!(!dir.path().join("ran.txt").exists(), "the script ran");
    let o = cli::lispcad_in(
        dir.path(),
        &["run", "w.lsp", "--cam-min-seg", "-1", "-o", "x.dxf"],
    );
    assert_eq!(
        o.status.code(),
        Some(2),
        "a bad --cam-min-seg is a usage error"
    );
}

#[test]
fn png_records_its_resolution() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("c.lsp"), "(draw (circle '(0 0) 10))").unwrap();
    let o = cli::lispcad_in(dir.path(), &["run", "c.lsp", "-o", "c.png", "--dpi", "254"]);
    assert!(o.status.success());
    let dec = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.path().join("c.png")).unwrap(),
    ));
    let r = dec.read_info().unwrap();
    let info = r.info();
    let phys = info.pixel_dims.unwrap();
    assert_eq!(phys.xppu, 10_000); // 254 dpi = 10 px/mm
                                   // 20 mm circle + 2 × 5 mm margin = 30 mm = 300 px.
    assert_eq!((info.width, info.height), (300, 300));
}

/// Layer names, then the names initially off, from the PDF's /OCProperties (read by pypdf); and
/// a copy of the PDF with the group `switch_off` also off, as a viewer's layer toggle leaves it.
fn pdf_layers(pdf: &Path, copy: &Path, switch_off: &str) -> (Vec<String>, Vec<String>) {
    let code = format!(
        "from pypdf import PdfReader, PdfWriter\n\
         from pypdf.generic import NameObject, ArrayObject\n\
         r = PdfReader(r'{}')\n\
         oc = r.trailer['/Root']['/OCProperties']\n\
         print('|'.join(g.get_object()['/Name'] for g in oc['/OCGs']))\n\
         print('|'.join(g.get_object()['/Name'] for g in oc['/D'].get('/OFF', [])))\n\
         w = PdfWriter(clone_from=r)\n\
         oc = w.root_object['/OCProperties']\n\
         hit = [g for g in oc['/OCGs'] if g.get_object()['/Name'] == '{switch_off}']\n\
         oc['/D'][NameObject('/OFF')] = ArrayObject(list(oc['/D'].get('/OFF', [])) + hit)\n\
         w.write(r'{}')\n",
        pdf.display(),
        copy.display()
    );
    let out = Command::new(support::python())
        .args(["-c", &code])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let s = String::from_utf8(out.stdout).unwrap();
    let mut lines = s.lines().map(|l| {
        l.split('|')
            .filter(|x| !x.is_empty())
            .map(String::from)
            .collect::<Vec<_>>()
    });
    (lines.next().unwrap(), lines.next().unwrap())
}

/// Whether any pixel of the PNG is close to `rgb`.
fn has_colour(png_path: &Path, rgb: [u8; 3]) -> bool {
    let dec = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(png_path).unwrap(),
    ));
    let mut r = dec.read_info().unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    let ch = info.color_type.samples();
    buf[..info.buffer_size()].chunks_exact(ch).any(|p| {
        p[..3]
            .iter()
            .zip(rgb)
            .all(|(&a, b)| (a as i32 - b as i32).abs() < 60)
    })
}

#[test]
fn pdf_layers_are_optional_content_groups() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(
        d.join("l.lsp"),
        "(layer \"CUT\" 1)\n(draw (pline '((0 0) (100 0) (100 50) (0 50)) T))\n\
         (layer \"HOLES\" 3)\n(draw (circle '(50 25) 10))\n\
         (layer \"NOTES\" 7)\n\
         (entmake '((0 . \"TEXT\") (8 . \"NOTES\") (10 10.0 -10.0 0.0) (40 . 5.0) (1 . \"Temple\")))\n\
         (layer \"GUIDE\" 5)\n(draw (line '(0 0) '(100 50)))\n\
         (command \"-LAYER\" \"OFF\" \"GUIDE\" \"\")\n",
    )
    .unwrap();
    let o = cli::lispcad_in(d, &["run", "l.lsp", "-o", "l.pdf"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (names, off) = pdf_layers(&d.join("l.pdf"), &d.join("no-cut.pdf"), "CUT");
    // Layer "0" has no entities and gets no group; the layer that is off starts off.
    assert_eq!(names, ["CUT", "HOLES", "NOTES", "GUIDE"]);
    assert_eq!(off, ["GUIDE"]);
    let (red, green, blue) = ([255, 0, 0], [0, 255, 0], [0, 0, 255]);
    let all = pdftoppm(&d.join("l.pdf"), 100, &d.join("all"));
    assert!(has_colour(&all, red) && has_colour(&all, green));
    assert!(!has_colour(&all, blue), "GUIDE is off but drawn");
    let no_cut = pdftoppm(&d.join("no-cut.pdf"), 100, &d.join("no-cut"));
    assert!(has_colour(&no_cut, green));
    assert!(!has_colour(&no_cut, red), "CUT switched off but drawn");
}
