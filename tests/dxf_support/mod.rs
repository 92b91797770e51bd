//! Shared by the DXF reader tests: ezdxf-made samples, the ezdxf comparison, running lispcad.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

#[path = "../output_support/mod.rs"]
mod output_support;
pub use output_support::{manifest, python};

/// Writes the ezdxf sample drawings (every version, binary too) into `dir`; their paths.
pub fn samples(dir: &Path) -> Vec<PathBuf> {
    let o = Command::new(python())
        .arg(manifest().join("tests/validate/dxf_samples.py"))
        .arg(dir)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "dxf"))
        .collect();
    v.sort();
    v
}

/// `tests/validate/dxf_compare.py` over (original, copy) pairs, one Python process.
pub fn compare(pairs: &[(PathBuf, PathBuf)]) -> Vec<serde_json::Value> {
    let mut cmd = Command::new(python());
    cmd.arg(manifest().join("tests/validate/dxf_compare.py"));
    for (a, b) in pairs {
        cmd.arg(a).arg(b);
    }
    let o = cmd.output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice::<serde_json::Value>(&o.stdout)
        .unwrap()
        .as_array()
        .unwrap()
        .clone()
}

pub fn lispcad(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

pub fn strs(v: &serde_json::Value) -> Vec<String> {
    v.as_array()
        .map(|a| {
            a.iter()
                .map(|x| x.as_str().unwrap_or("").to_string())
                .collect()
        })
        .unwrap_or_default()
}
