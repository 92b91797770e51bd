//! Real drawings nobody on the team wrote, opened and saved, must be the same document to
//! ezdxf:
//! - every DXF part and hatch pattern LibreCAD ships (over a thousand, under
//!   /usr/share/librecad; GPL-2.0), written by LibreCAD's and QCAD's writers;
//! - OpenSCAD's test drawings (Debian's openscad-testing-data, under
//!   /usr/share/openscad/testdata; GPL-2+), written by QCAD's dxflib 2.2;
//! - drawings written by AutoCAD that ship in two npm packages, both under the MIT licence:
//!   three-dxf 1.3.1's `sample/data/demo.dxf` (AC1032, R2018) and dxf2json 1.0.3's
//!   `sample/*.dxf` (five AC1027/AC1021 drawings with Chinese and Korean code pages, and
//!   `234.dxf`, an R12 file from Global Mapper). AutoCAD wrote them as far as a file can
//!   tell: `$ACADMAINTVER` and `$REQUIREDVERSIONS` in AutoCAD's padded layout, a user name
//!   in `$LASTSAVEDBY`, CLASSES records of Autodesk applications (Architectural Desktop, Map,
//!   Express Tools); an ODA-based clone could write the same, so that is the evidence, not
//!   proof. `.ci/setup` fetches the two tarballs with `npm pack` into tests/dxf_samples.
//!
//! All are read from the installed packages (`.ci/setup`), not copied into the repository.
//! An unchanged sound file must come back with its own groups (same codes, same value text,
//! comments and line ends aside): then it is the same document to any reader, so only the
//! copies that differ (damaged files read with --recover) go through ezdxf (one Python process
//! over all of them), with a sample of the others to keep the comparison honest.

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

/// (code, value) pairs of an ASCII DXF, line ends (LF or CRLF) and comments aside.
fn groups(data: &[u8]) -> Option<Vec<(i32, &[u8])>> {
    let mut lines = data
        .split(|b| *b == b'\n')
        .map(|l| l.strip_suffix(b"\r").unwrap_or(l));
    let mut out = Vec::new();
    while let Some(c) = lines.next() {
        if c.is_empty() && out.last().is_some_and(|(c, v)| *c == 0 && *v == b"EOF") {
            break;
        }
        let code = std::str::from_utf8(c).ok()?.trim().parse().ok()?;
        let value = lines.next()?;
        // Comments (the writer's name) are not part of the document; readers skip them.
        if code != 999 {
            out.push((code, value));
        }
    }
    Some(out)
}

/// What opening and saving one file gave: whether the copy's groups are the original's and
/// whether it needed --recover; or the reader's error.
fn round_trip(f: &Path, copy: &Path) -> Result<(bool, bool), String> {
    let data = std::fs::read(f).unwrap();
    // A damaged file (OpenSCAD's has one with decimal commas) must be refused with a clear
    // error and read with --recover, as ezdxf's comparison then reads it with its recover.
    let (d, recovered) = match read_dxf(&data, false) {
        Ok(d) => (d, false),
        Err(strict) => (
            read_dxf(&data, true).map_err(|e| format!("{strict}; recover: {e}"))?,
            true,
        ),
    };
    let bytes = render(&d, Format::Dxf, &OutputOptions::default()).map_err(|e| e.to_string())?;
    std::fs::write(copy, &bytes).unwrap();
    let same = groups(&data).is_some_and(|g| Some(g) == groups(&bytes));
    Ok((same, recovered))
}

/// Round-trips every file; the problems found (a file that could not be read, a copy that is
/// not its original's document to ezdxf, a sound file whose copy has other groups), and how
/// many files needed --recover.
fn check(files: &[PathBuf]) -> (Vec<String>, usize) {
    check_every(files, 50)
}

/// `check` with every copy compared by ezdxf.
fn check_all(files: &[PathBuf]) -> (Vec<String>, usize) {
    check_every(files, 1)
}

fn check_every(files: &[PathBuf], sample: usize) -> (Vec<String>, usize) {
    let dir = tempfile::tempdir().unwrap();
    let copies: Vec<PathBuf> = (0..files.len())
        .map(|i| dir.path().join(format!("{i}.dxf")))
        .collect();
    // Opening and saving in parallel: the debug build is slow, the files independent.
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let chunk = files.len().div_ceil(threads).max(1);
    let results: Vec<Result<(bool, bool), String>> = std::thread::scope(|s| {
        let handles: Vec<_> = files
            .chunks(chunk)
            .zip(copies.chunks(chunk))
            .map(|(fs, cs)| {
                s.spawn(move || {
                    fs.iter()
                        .zip(cs)
                        .map(|(f, c)| round_trip(f, c))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    let mut bad = Vec::new();
    let mut pairs = Vec::new();
    let mut recovered = 0;
    for (i, (r, (f, c))) in results.iter().zip(files.iter().zip(&copies)).enumerate() {
        match r {
            Err(e) => bad.push(format!("{}: {e}", f.display())),
            Ok((same, rec)) => {
                recovered += usize::from(*rec);
                // Lossless: an unchanged sound file comes back with its own groups.
                if !same && !rec {
                    bad.push(format!("{}: the copy's groups differ", f.display()));
                }
                if !same || i % sample == 0 {
                    pairs.push((f.clone(), c.clone()));
                }
            }
        }
    }
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
    (bad, recovered)
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
    let (bad, recovered) = check(&files);
    assert!(
        bad.is_empty(),
        "{} files differ:\n{}",
        bad.len(),
        bad[..bad.len().min(5)].join("\n")
    );
    assert_eq!(recovered, 0);
}

#[test]
fn openscad_test_drawings_round_trip() {
    let mut files = Vec::new();
    dxf_files(Path::new("/usr/share/openscad/testdata"), &mut files);
    files.sort();
    assert!(
        files.len() >= 30,
        "OpenSCAD's test drawings missing ({} files): run `bash .ci/setup` first",
        files.len()
    );
    let (bad, recovered) = check(&files);
    // nothing-decimal-comma-separated.dxf, which ezdxf too reads only with its recover.
    assert_eq!(recovered, 1);
    assert!(
        bad.is_empty(),
        "{} files differ:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

/// The AutoCAD drawings of three-dxf and dxf2json (see the module documentation); every one
/// is compared by ezdxf too, as there are few.
#[test]
fn autocad_drawings_from_npm_packages_round_trip() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/dxf_samples");
    let mut files = Vec::new();
    dxf_files(&root, &mut files);
    files.sort();
    let names: Vec<String> = files
        .iter()
        .filter_map(|f| f.file_name()?.to_str().map(str::to_string))
        .collect();
    assert_eq!(
        files.len(),
        7,
        "the npm packages' drawings are missing or changed ({names:?}): run `bash .ci/setup`"
    );
    // Who wrote them, as their headers say (an update of the packages must not silently
    // swap in other producers' files).
    let mut versions: Vec<String> = files
        .iter()
        .map(|f| {
            let d = read_dxf(&std::fs::read(f).unwrap(), false).unwrap();
            let doc = d.document().unwrap();
            let by = doc.header_var("$LASTSAVEDBY").is_some()
                && doc.header_var("$ACADMAINTVER").is_some();
            format!("{}{}", doc.version, if by { " AutoCAD" } else { "" })
        })
        .collect();
    versions.sort();
    assert_eq!(
        versions,
        [
            "AC1009",
            "AC1021 AutoCAD",
            "AC1027 AutoCAD",
            "AC1027 AutoCAD",
            "AC1027 AutoCAD",
            "AC1027 AutoCAD",
            "AC1032 AutoCAD"
        ]
    );
    let (bad, recovered) = check_all(&files);
    assert_eq!(recovered, 0);
    assert!(
        bad.is_empty(),
        "{} files differ:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
