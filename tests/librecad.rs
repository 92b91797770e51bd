//! LibreCAD, a real CAD program, must open what lispcad writes: the temple in both DXF
//! profiles and the AutoLISP example are printed to PDF headless (`librecad dxf2pdf`), which
//! fails or hangs on files it cannot read. (LibreCAD once hung on repeated-knot splines.)
//! The temple's hinge corners must come out sharp in LibreCAD's drawing, as they are in the
//! file (LibreCAD rounds a corner inside a spline entity: see `output::dxf_spline`).

#[path = "output_support/mod.rs"]
mod support;

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

fn librecad_prints(dxf: &Path, outdir: &Path) {
    assert!(
        Command::new("librecad").arg("--help").output().is_ok(),
        "librecad missing: run `bash .ci/setup` first"
    );
    let mut child = Command::new("librecad")
        .env("QT_QPA_PLATFORM", "offscreen")
        .arg("dxf2pdf")
        .arg("-a")
        .arg("-t")
        .arg(outdir)
        .arg(dxf)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            assert!(status.success(), "librecad failed on {}", dxf.display());
            break;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("librecad hung on {}", dxf.display());
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let pdf = outdir.join(dxf.with_extension("pdf").file_name().unwrap());
    let len = std::fs::metadata(&pdf).map(|m| m.len()).unwrap_or(0);
    assert!(len > 1000, "{} printed an empty PDF", dxf.display());
}

fn lispcad(args: &[&str], dir: &Path) {
    let o = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn librecad_opens_the_temple_and_the_example_routine() {
    let dir = tempfile::tempdir().unwrap();
    let root = env!("CARGO_MANIFEST_DIR");
    let temple = format!("{root}/scripts/temple.lsp");
    let routine = format!("{root}/scripts/autolisp-routine.lsp");
    lispcad(&["run", &temple, "-o", "temple.dxf"], dir.path());
    lispcad(
        &[
            "run",
            &temple,
            "--dxf-profile",
            "cam",
            "-o",
            "temple-cam.dxf",
        ],
        dir.path(),
    );
    lispcad(
        &[
            "run",
            &temple,
            "--set",
            "BENDANG=25.0",
            "--set",
            "L1=150.0",
            "-o",
            "variant.dxf",
        ],
        dir.path(),
    );
    lispcad(&["run", &routine, "-o", "flange.dxf"], dir.path());
    for f in ["temple.dxf", "temple-cam.dxf", "variant.dxf", "flange.dxf"] {
        librecad_prints(&dir.path().join(f), dir.path());
    }
}

/// The red (CUT, ACI 1) pixels of a PNG as (x, y), with the image's width.
fn red_pixels(png_path: &Path) -> Vec<(f64, f64)> {
    let dec = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(png_path).unwrap(),
    ));
    let mut r = dec.read_info().unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    let ch = info.color_type.samples();
    let (w, h) = (info.width as usize, info.height as usize);
    let mut red = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let p = &buf[(y * w + x) * ch..(y * w + x) * ch + 3];
            if p[0] > 128 && p[1] < 100 && p[2] < 100 {
                red.push((x as f64, y as f64));
            }
        }
    }
    red
}

/// The temple's two hinge corners, (0, ±HINGEW/2) = (0, ±2.5) mm, as LibreCAD draws them:
/// the file printed by `librecad dxf2pdf` (fitted to the page), rasterised by pdftoppm at
/// 300 dpi; the page scale comes from the red pixels' extent against the CUT layer's extent
/// read by ezdxf. A sharp corner has a red pixel at the corner itself; a corner rounded with
/// radius r passes r(√2 − 1) inside it, so the 0.15 mm allowed here (two pixels at this
/// scale, the hairline's own blur) fails any round above 0.36 mm. LibreCAD drew the corner
/// as a single closed spline with a doubled control point rounded by several millimetres.
#[test]
fn librecad_draws_the_hinge_corners_sharp() {
    let dir = tempfile::tempdir().unwrap();
    let temple = format!("{}/scripts/temple.lsp", env!("CARGO_MANIFEST_DIR"));
    lispcad(&["run", &temple, "-o", "temple.dxf"], dir.path());
    let dxf = dir.path().join("temple.dxf");
    librecad_prints(&dxf, dir.path());
    let st = Command::new("pdftoppm")
        .args(["-r", "300", "-png", "-singlefile"])
        .arg(dir.path().join("temple.pdf"))
        .arg(dir.path().join("page"))
        .status()
        .expect("pdftoppm missing: run .ci/setup");
    assert!(st.success());
    let red = red_pixels(&dir.path().join("page.png"));
    assert!(!red.is_empty(), "no CUT pixels");
    let [x0, y0, x1, y1] = support::ezdxf_cut_extent(&dxf).0;
    let lo_x = red.iter().map(|p| p.0).fold(f64::MAX, f64::min);
    let hi_x = red.iter().map(|p| p.0).fold(f64::MIN, f64::max);
    let lo_y = red.iter().map(|p| p.1).fold(f64::MAX, f64::min);
    let hi_y = red.iter().map(|p| p.1).fold(f64::MIN, f64::max);
    // Pixel centres span the extent less one pixel; the page keeps the aspect ratio.
    let s = (hi_x - lo_x) / (x1 - x0);
    let sy = (hi_y - lo_y) / (y1 - y0);
    assert!((s - sy).abs() < 0.02 * s, "scales {s} and {sy} px/mm");
    assert!(s > 8.0, "the temple is drawn too small to judge: {s} px/mm");
    for y in [-2.5, 2.5] {
        let (cx, cy) = (lo_x + (0.0 - x0) * s, lo_y + (y1 - y) * s);
        let d = red
            .iter()
            .map(|p| (p.0 - cx).hypot(p.1 - cy))
            .fold(f64::MAX, f64::min);
        assert!(
            d / s <= 0.15,
            "hinge corner (0, {y}): nearest drawn point {:.2} mm away ({d:.1} px at \
             {s:.2} px/mm): rounded",
            d / s
        );
    }
}
