//! The per-user settings file behind `setenv`/`getenv` and `vl-registry-*` (SPEC §3): one
//! `KEY<TAB>VALUE` line per setting (keys are `env<TAB>NAME` or `reg<TAB>KEY\NAME`), at
//! `$LISPCAD_SETTINGS`, else `$XDG_CONFIG_HOME/lispcad/settings`, else
//! `~/.config/lispcad/settings`. Written through a temporary file and a rename, so a crash
//! never leaves it half written.

use std::path::PathBuf;

fn path() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("LISPCAD_SETTINGS") {
        return Some(PathBuf::from(p));
    }
    let base = std::env::var_os("XDG_CONFIG_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".config")))?;
    Some(base.join("lispcad").join("settings"))
}

fn escape(s: &str) -> String {
    s.replace('\\', "\\\\")
        .replace('\n', "\\n")
        .replace('\t', "\\t")
}

fn unescape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            match chars.next() {
                Some('n') => out.push('\n'),
                Some('t') => out.push('\t'),
                Some(other) => out.push(other),
                None => out.push('\\'),
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// (key, value) lines of the file; empty when it does not exist.
fn entries() -> Vec<(String, String)> {
    let Some(p) = path() else { return Vec::new() };
    let Ok(text) = std::fs::read_to_string(p) else {
        return Vec::new();
    };
    text.lines()
        .filter_map(|l| {
            let (k, v) = l.split_once('\t')?;
            Some((unescape(k), unescape(v)))
        })
        .collect()
}

/// The stored value of `key` (case-insensitive).
pub fn read(key: &str) -> Option<String> {
    entries()
        .into_iter()
        .find(|(k, _)| k.eq_ignore_ascii_case(key))
        .map(|(_, v)| v)
}

/// Stores (`Some`) or removes (`None`) a setting.
pub fn write(key: &str, value: Option<&str>) -> Result<(), String> {
    let p = path().ok_or("no settings file: neither LISPCAD_SETTINGS nor HOME is set")?;
    let mut all: Vec<(String, String)> = entries()
        .into_iter()
        .filter(|(k, _)| !k.eq_ignore_ascii_case(key))
        .collect();
    if let Some(v) = value {
        all.push((key.to_string(), v.to_string()));
    }
    let text: String = all
        .iter()
        .map(|(k, v)| format!("{}\t{}\n", escape(k), escape(v)))
        .collect();
    let fail = |e: std::io::Error| format!("cannot write the settings file {}: {e}", p.display());
    if let Some(dir) = p.parent() {
        std::fs::create_dir_all(dir).map_err(fail)?;
    }
    let tmp = p.with_extension("tmp");
    std::fs::write(&tmp, text).map_err(fail)?;
    std::fs::rename(&tmp, &p).map_err(fail)
}
