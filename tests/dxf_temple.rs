//! A designer's temple outline drawn elsewhere (scripts/temple-outline.dxf: a closed
//! LWPOLYLINE on layer OUTLINE, written by ezdxf) is opened, bent by
//! scripts/temple-from-dxf.lsp and saved: the designer's file comes back unchanged with the
//! bent outline added, ezdxf audits it clean, LibreCAD prints it, and a batch over the
//! variants table regenerates every row.

mod dxf_support;

use std::process::Command;
use std::time::{Duration, Instant};

use dxf_support::{compare, lispcad, manifest, strs};

#[test]
fn the_outline_is_bent_and_the_file_kept() {
    let dir = tempfile::tempdir().unwrap();
    let script = manifest().join("scripts/temple-from-dxf.lsp");
    let outline = manifest().join("scripts/temple-outline.dxf");
    let o = lispcad(
        dir.path(),
        &[
            "run",
            script.to_str().unwrap(),
            "--open",
            outline.to_str().unwrap(),
            "-o",
            "bent.dxf",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.starts_with("bent 11-point outline, L1 140.0"), "{out}");
    let bent = dir.path().join("bent.dxf");
    let r = &compare(&[(outline.clone(), bent.clone())])[0];
    assert!(r.get("load_error").is_none(), "{r}");
    assert!(strs(&r["diffs"]).is_empty(), "{r}");
    assert!(strs(&r["audit_errors"]).is_empty(), "{r}");
    assert!(strs(&r["audit_fixes"]).is_empty(), "{r}");
    let extra = strs(&r["extra"]);
    assert!(extra.iter().any(|e| e.ends_with(" SPLINE")), "{extra:?}");
    assert!(extra.iter().any(|e| e.ends_with(" LAYER")), "{extra:?}");

    // LibreCAD reads the round-tripped, edited file.
    let mut child = Command::new("librecad")
        .env("QT_QPA_PLATFORM", "offscreen")
        .args(["dxf2pdf", "-a", "-t"])
        .arg(dir.path())
        .arg(&bent)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("librecad missing: run `bash .ci/setup` first");
    let start = Instant::now();
    loop {
        if let Some(s) = child.try_wait().unwrap() {
            assert!(s.success(), "librecad failed");
            break;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("librecad hung");
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let pdf = std::fs::metadata(dir.path().join("bent.pdf")).map_or(0, |m| m.len());
    assert!(pdf > 1000, "LibreCAD printed an empty PDF");
}

#[test]
fn a_batch_bends_every_variant() {
    let dir = tempfile::tempdir().unwrap();
    let script = manifest().join("scripts/temple-from-dxf.lsp");
    let outline = manifest().join("scripts/temple-outline.dxf");
    // The variants table's bend columns: its width columns name nothing this script uses, and
    // a column the script never reads is a usage error (SPEC §2).
    let full = std::fs::read_to_string(manifest().join("scripts/variants.csv")).unwrap();
    let bend: String = full
        .lines()
        .map(|l| l.split(',').take(5).collect::<Vec<_>>().join(",") + "\n")
        .collect();
    let table = dir.path().join("bend.csv");
    std::fs::write(&table, bend).unwrap();
    let pattern = format!("{}/bent-{{name}}.dxf", dir.path().display());
    let o = lispcad(
        dir.path(),
        &[
            "batch",
            script.to_str().unwrap(),
            "--vary",
            table.to_str().unwrap(),
            "--open",
            outline.to_str().unwrap(),
            "-o",
            &pattern,
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = std::fs::read_to_string(&table).unwrap().lines().count() - 1;
    let written = std::fs::read_dir(dir.path())
        .unwrap()
        .filter(|e| {
            let n = e.as_ref().unwrap().file_name();
            n.to_string_lossy().starts_with("bent-")
        })
        .count();
    assert_eq!(written, rows);
}
