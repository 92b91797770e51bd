//! Where a row's drawing goes once its script has run. Today: the output files named by the
//! `-o` patterns. A contact sheet is another `Sink`: it names no per-row files, takes each
//! row's drawing in `row_done`, and writes itself in `finish`.

use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::Mutex;

use super::source::Row;
use crate::cli::Common;
use crate::lang::Interp;

pub trait Sink: Sync {
    /// The files this sink writes for `row` (they also widen the row's write roots).
    fn paths(&self, row: &Row) -> Result<Vec<PathBuf>, String>;
    /// After the row's script ran without error: take its drawing.
    fn row_done(
        &self,
        it: &mut Interp,
        row: &Row,
        paths: &[PathBuf],
        common: &Common,
    ) -> Result<(), String>;
    /// After every row.
    fn finish(&self) -> Result<(), String> {
        Ok(())
    }
}

/// The `-o PATTERN` outputs: each row's drawing written (atomically) to every expanded name.
pub struct OutputFiles {
    pub patterns: Vec<String>,
    /// Names already written, so two streamed rows cannot silently overwrite each other
    /// (a table is checked as a whole before running: `check_clashes`).
    written: Mutex<HashSet<PathBuf>>,
    /// Directories already made (or found): most batches write every row into the same one
    /// or two, and asking for each again cost two system calls per file.
    made_dirs: Mutex<HashSet<PathBuf>>,
}

impl OutputFiles {
    pub fn new(patterns: Vec<String>) -> Self {
        OutputFiles {
            patterns,
            written: Mutex::new(HashSet::new()),
            made_dirs: Mutex::new(HashSet::new()),
        }
    }

    /// Every row's outputs, up front: a usage error when a pattern names a missing field or
    /// two rows would write the same file.
    pub fn check_clashes(&self, rows: &[Row]) -> Result<(), String> {
        let mut seen = HashSet::new();
        for r in rows {
            for o in self.paths(r)? {
                if !seen.insert(o.clone()) {
                    return Err(clash(&o));
                }
            }
        }
        Ok(())
    }
}

fn clash(o: &std::path::Path) -> String {
    format!(
        "two rows would write {}: add {{row}} or a column to the pattern",
        o.display()
    )
}

impl Sink for OutputFiles {
    fn paths(&self, row: &Row) -> Result<Vec<PathBuf>, String> {
        self.patterns
            .iter()
            .map(|p| expand_pattern(p, row).map(PathBuf::from))
            .collect()
    }

    fn row_done(
        &self,
        it: &mut Interp,
        _row: &Row,
        paths: &[PathBuf],
        common: &Common,
    ) -> Result<(), String> {
        {
            let mut w = self
                .written
                .lock()
                .map_err(|_| "lock poisoned".to_string())?;
            for o in paths {
                if !w.insert(o.clone()) {
                    return Err(clash(o));
                }
            }
        }
        for o in paths {
            if let Some(d) = o.parent().filter(|d| !d.as_os_str().is_empty()) {
                let mut made = self
                    .made_dirs
                    .lock()
                    .map_err(|_| "lock poisoned".to_string())?;
                if !made.contains(d) {
                    std::fs::create_dir_all(d)
                        .map_err(|e| format!("cannot create {}: {e}", d.display()))?;
                    made.insert(d.to_path_buf());
                }
            }
        }
        crate::builtins::write_outputs(it, paths, common)
    }
}

/// Expands {field} and {row} in an output pattern.
pub fn expand_pattern(pattern: &str, row: &Row) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = pattern;
    while let Some(i) = rest.find('{') {
        out.push_str(&rest[..i]);
        let after = &rest[i + 1..];
        let j = after
            .find('}')
            .ok_or_else(|| format!("pattern `{pattern}`: unclosed {{"))?;
        let key = &after[..j];
        if key == "row" {
            out.push_str(&row.number.to_string());
        } else {
            let v = row
                .field(key)
                .ok_or_else(|| format!("pattern `{pattern}`: no column named {key}"))?;
            out.push_str(&sanitize(v));
        }
        rest = &after[j + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

/// The `{field}` names of a pattern (without `row`).
pub fn pattern_fields(pattern: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = pattern;
    while let Some(i) = rest.find('{') {
        let after = &rest[i + 1..];
        let Some(j) = after.find('}') else { break };
        if &after[..j] != "row" {
            out.push(after[..j].to_string());
        }
        rest = &after[j + 1..];
    }
    out
}

/// A value as part of a file name: path separators and control characters replaced.
fn sanitize(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c == '/' || c == '\\' || c.is_control() {
                '_'
            } else {
                c
            }
        })
        .collect()
}

/// `--sheet FILE.pdf|FILE.svg`: every successful row's drawing, labelled, on one contact
/// sheet at a common scale, written once all rows have run.
pub struct ContactSheet {
    pub path: PathBuf,
    rows: Mutex<Vec<(u64, String, String)>>,
}

impl ContactSheet {
    pub fn new(path: PathBuf) -> Self {
        ContactSheet {
            path,
            rows: Mutex::new(Vec::new()),
        }
    }

    /// A usage error unless the sheet is .svg or .pdf.
    pub fn check(path: &std::path::Path) -> Result<(), String> {
        use crate::output::Format;
        match Format::from_path(path) {
            Ok(Format::Svg | Format::Pdf) => Ok(()),
            _ => Err("--sheet: the contact sheet must be a .svg or .pdf file".into()),
        }
    }
}

impl Sink for ContactSheet {
    fn paths(&self, _row: &Row) -> Result<Vec<PathBuf>, String> {
        Ok(Vec::new())
    }

    fn row_done(
        &self,
        it: &mut Interp,
        row: &Row,
        _paths: &[PathBuf],
        common: &Common,
    ) -> Result<(), String> {
        let svg = crate::builtins::drawing_svg(it, common)?;
        let label = match row.field("name").or_else(|| row.field("stem")) {
            Some(n) => format!("{}: {n}", row.number),
            None => format!("{}: {}", row.number, row.describe()),
        };
        self.rows
            .lock()
            .map_err(|_| "lock poisoned".to_string())?
            .push((row.number, label, svg));
        Ok(())
    }

    fn finish(&self) -> Result<(), String> {
        let mut rows = std::mem::take(&mut *self.rows.lock().map_err(|_| "lock poisoned")?);
        rows.sort_by_key(|r| r.0);
        let rows: Vec<_> = rows
            .into_iter()
            .map(|(_, label, svg)| crate::output::sheet::SheetRow { label, svg })
            .collect();
        let format = crate::output::Format::from_path(&self.path).map_err(|e| e.to_string())?;
        let bytes = crate::output::sheet::compose(&rows, format).map_err(|e| e.to_string())?;
        crate::output::atomic::write_atomic(&self.path, &bytes)
            .map_err(|e| format!("cannot write {}: {e}", self.path.display()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::batch::source::Cell;

    #[test]
    fn patterns() {
        let row = Row {
            number: 3,
            values: vec![
                ("name".into(), Cell::bare("big/../x")),
                ("L1".into(), Cell::bare("140")),
            ],
            fields: vec![("stem".into(), "part".into())],
            open: None,
        };
        assert_eq!(
            expand_pattern("out/{name}-{l1}-{row}-{stem}.dxf", &row).unwrap(),
            "out/big_.._x-140-3-part.dxf"
        );
        assert!(expand_pattern("{nope}.dxf", &row).is_err());
        assert!(expand_pattern("{L1.dxf", &row).is_err());
        assert_eq!(pattern_fields("o/{a}-{row}-{B}.svg"), ["a", "B"]);
    }
}
