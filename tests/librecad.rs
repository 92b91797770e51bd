//! LibreCAD, a real CAD program, must open what lispcad writes: the temple in both DXF
//! profiles and the AutoLISP example are printed to PDF headless (`librecad dxf2pdf`), which
//! fails or hangs on files it cannot read. (LibreCAD once hung on repeated-knot splines.)

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
