//! Real drawings nobody on the team wrote: every DXF part and hatch pattern LibreCAD ships
//! (over a thousand, under /usr/share/librecad) is opened and saved, and ezdxf must see the
//! same document (one Python process over all of them). LibreCAD's parts are GPL-2.0, read
//! from the installed package, not copied into the repository.

mod dxf_support;

use std::path::{Path, PathBuf};

use dxf_support::{compare, strs};
use lispcad::output::{read_dxf, render, Format, OutputOptions};

fn dxf_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for e in rd.flatten() {
        let p = e.path();
        if p.is_dir() {
            dxf_files(&p, out);
        } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("dxf")) {
            out.push(p);
        }
    }
}

#[test]
fn librecad_parts_round_trip() {
    let mut files = Vec::new();
    dxf_files(Path::new("/usr/share/librecad"), &mut files);
    files.sort();
    assert!(
        files.len() > 1000,
        "LibreCAD's parts missing ({} files): run `bash .ci/setup` first",
        files.len()
    );
    let dir = tempfile::tempdir().unwrap();
    let mut pairs = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let data = std::fs::read(f).unwrap();
        let d = read_dxf(&data, false).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let bytes = render(&d, Format::Dxf, &OutputOptions::default()).unwrap();
        let copy = dir.path().join(format!("{i}.dxf"));
        std::fs::write(&copy, &bytes).unwrap();
        pairs.push((f.clone(), copy));
    }
    let mut bad = Vec::new();
    for r in compare(&pairs) {
        let ok = r.get("load_error").is_none()
            && r["diffs"].as_array().is_some_and(|d| d.is_empty())
            && strs(&r["extra"]).is_empty()
            // Some parts need ezdxf's audit fixes already (bad owners): the copy may need
            // those, never more.
            && strs(&r["audit_errors"]).len() as u64 <= r["orig_audit_errors"].as_u64().unwrap()
            && strs(&r["audit_fixes"]).len() as u64 <= r["orig_audit_fixes"].as_u64().unwrap();
        if !ok {
            bad.push(r.to_string());
        }
    }
    assert!(
        bad.is_empty(),
        "{} files differ:\n{}",
        bad.len(),
        bad[..bad.len().min(5)].join("\n")
    );
}
