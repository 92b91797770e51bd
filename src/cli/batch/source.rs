//! Where a batch's rows come from: a CSV table (read whole: tables are small and their
//! outputs are checked for clashes before anything runs) or a grid (streamed: a grid of
//! 10^10 points costs no more memory than one of ten).
//!
//! A new source (e.g. `--open 'GLOB'`, one row per drawing with a `{stem}` pattern field) is
//! a new `Source` variant: it yields `Row`s whose `values` are bound as globals, whose
//! `fields` only name outputs, and whose `open` is the drawing the row starts from.

use std::path::PathBuf;

use crate::lang::reader::parse_number;

/// A table cell: quoted cells are strings; unquoted ones are numbers when they read as one.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    pub text: String,
    pub quoted: bool,
}

impl Cell {
    pub fn bare(text: impl Into<String>) -> Cell {
        Cell {
            text: text.into(),
            quoted: false,
        }
    }
}

/// One row: its number (from 1), the globals it binds, and pattern-only fields.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Row {
    pub number: u64,
    /// (variable name, value as written): bound as globals and usable in patterns.
    pub values: Vec<(String, Cell)>,
    /// Pattern fields that bind nothing (a drawing source's `{stem}`).
    pub fields: Vec<(String, String)>,
    /// The drawing the row starts from (a drawings source; nothing reads it yet).
    pub open: Option<PathBuf>,
}

impl Row {
    /// The text of a pattern field (case-insensitive), if the row has it.
    pub fn field(&self, key: &str) -> Option<&str> {
        self.values
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(key))
            .map(|(_, c)| c.text.as_str())
            .or_else(|| {
                self.fields
                    .iter()
                    .find(|(k, _)| k.eq_ignore_ascii_case(key))
                    .map(|(_, v)| v.as_str())
            })
    }

    pub fn describe(&self) -> String {
        if self.values.is_empty() {
            if let Some(p) = &self.open {
                return p.display().to_string();
            }
        }
        self.values
            .iter()
            .map(|(k, v)| format!("{k}={}", v.text))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The rows of a batch.
pub enum Source {
    /// A CSV table, in memory.
    Table {
        columns: Vec<String>,
        rows: Vec<Row>,
    },
    /// A cartesian grid, enumerated on demand.
    Grid(Grid),
}

impl Source {
    /// The names every row binds (checked against the script's symbols).
    pub fn columns(&self) -> Vec<String> {
        match self {
            Source::Table { columns, .. } => columns.clone(),
            Source::Grid(g) => g.axes.iter().map(|(n, _)| n.clone()).collect(),
        }
    }

    /// The number of rows.
    pub fn len(&self) -> u64 {
        match self {
            Source::Table { rows, .. } => rows.len() as u64,
            Source::Grid(g) => g.len,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The rows in order, each built when asked for.
    pub fn rows(&self) -> Box<dyn Iterator<Item = Row> + Send + '_> {
        match self {
            Source::Table { rows, .. } => Box::new(rows.iter().cloned()),
            Source::Grid(g) => Box::new((0..g.len).map(|i| g.row(i))),
        }
    }

    /// The rows when they are all in memory (so clashes can be checked before running).
    pub fn in_memory(&self) -> Option<&[Row]> {
        match self {
            Source::Table { rows, .. } => Some(rows),
            Source::Grid(_) => None,
        }
    }
}

/// A grid: axes of values, the first varying slowest.
#[derive(Debug)]
pub struct Grid {
    pub axes: Vec<(String, Vec<String>)>,
    pub len: u64,
}

impl Grid {
    /// Row `i` (from 0): the mixed-radix digits of `i` pick one value per axis.
    pub fn row(&self, i: u64) -> Row {
        let mut values = Vec::with_capacity(self.axes.len());
        let mut rest = i;
        for (name, vals) in self.axes.iter().rev() {
            let n = vals.len() as u64;
            values.push((name.clone(), Cell::bare(vals[(rest % n) as usize].clone())));
            rest /= n;
        }
        values.reverse();
        Row {
            number: i + 1,
            values,
            ..Row::default()
        }
    }
}

/// `--open 'GLOB'`: one row per matching drawing, in name order, with the pattern fields
/// `{stem}` and `{file}`; the row binds nothing and starts from its drawing. Only the file
/// name may hold wildcards (`*`, `?`), as a shell would expand them in one directory.
pub fn drawings_source(glob: &std::path::Path) -> Result<Source, String> {
    let name = glob
        .file_name()
        .and_then(|n| n.to_str())
        .ok_or_else(|| format!("--open {}: not a file pattern", glob.display()))?;
    let dir = match glob.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if dir.to_string_lossy().contains(['*', '?']) {
        return Err(format!(
            "--open {}: only the file name may contain wildcards",
            glob.display()
        ));
    }
    let pat: Vec<char> = name.chars().collect();
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map_err(|e| {
            format!(
                "--open {}: cannot list {}: {e}",
                glob.display(),
                dir.display()
            )
        })?
        .filter_map(|e| e.ok())
        .filter(|e| e.file_type().is_ok_and(|t| !t.is_dir()))
        .filter(|e| {
            let n: Vec<char> = e.file_name().to_string_lossy().chars().collect();
            crate::builtins::io::glob(&pat, &n).0
        })
        .map(|e| e.path())
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(format!("--open {}: no drawing matches", glob.display()));
    }
    let rows = files
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let stem = p
                .file_stem()
                .map_or(String::new(), |s| s.to_string_lossy().into());
            let file = p
                .file_name()
                .map_or(String::new(), |s| s.to_string_lossy().into());
            Row {
                number: i as u64 + 1,
                values: Vec::new(),
                fields: vec![("stem".into(), stem), ("file".into(), file)],
                open: Some(p),
            }
        })
        .collect();
    Ok(Source::Table {
        columns: Vec::new(),
        rows,
    })
}

/// Reads a CSV table: a header of variable names, one row per record.
pub fn table_source(text: &str) -> Result<Source, String> {
    let (columns, rows) = super::csv::table(text)?;
    Ok(Source::Table { columns, rows })
}

/// Parses a grid spec: "L1=135:150:5,R=10,15,20" → every combination, the first variable
/// varying slowest. Only the axes are built; rows are enumerated on demand.
pub fn grid_source(spec: &str) -> Result<Source, String> {
    let mut vars: Vec<(String, Vec<String>)> = Vec::new();
    for tok in spec.split(',') {
        let tok = tok.trim();
        if let Some((name, first)) = tok.split_once('=') {
            let name = name.trim();
            if name.is_empty() || parse_number(name).is_some() {
                return Err(format!("grid: `{name}` is not a variable name"));
            }
            vars.push((name.to_string(), vec![first.trim().to_string()]));
        } else {
            match vars.last_mut() {
                Some((_, vals)) => vals.push(tok.to_string()),
                None => return Err(format!("grid: `{tok}` has no NAME= before it")),
            }
        }
    }
    if vars.is_empty() {
        return Err("grid: empty specification".into());
    }
    let mut axes: Vec<(String, Vec<String>)> = Vec::new();
    let mut len: u64 = 1;
    for (name, vals) in vars {
        if axes.iter().any(|(n, _)| n.eq_ignore_ascii_case(&name)) {
            return Err(format!("grid: {name} is given twice"));
        }
        let mut expanded = Vec::new();
        for v in vals {
            if v.contains(':') {
                expanded.extend(range_values(&name, &v)?);
            } else if v.is_empty() {
                return Err(format!("grid: empty value for {name}"));
            } else {
                expanded.push(v);
            }
        }
        len = len
            .checked_mul(expanded.len() as u64)
            .ok_or_else(|| "grid: more than 2^64 rows".to_string())?;
        axes.push((name, expanded));
    }
    Ok(Source::Grid(Grid { axes, len }))
}

/// start:stop:step, inclusive of stop (within a rounding tolerance).
fn range_values(name: &str, spec: &str) -> Result<Vec<String>, String> {
    let parts: Vec<&str> = spec.split(':').collect();
    let num = |s: &str| -> Result<f64, String> {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("grid: {name}: `{s}` is not a number"))
    };
    if parts.len() != 3 {
        return Err(format!(
            "grid: {name}: a range is start:stop:step, got `{spec}`"
        ));
    }
    let (a, b, step) = (num(parts[0])?, num(parts[1])?, num(parts[2])?);
    if step <= 0.0 || b < a {
        return Err(format!(
            "grid: {name}: need start <= stop and step > 0, got `{spec}`"
        ));
    }
    let n = ((b - a) / step + 1e-9).floor();
    if n > 100_000.0 {
        return Err(format!("grid: {name}: more than 100000 values"));
    }
    let n = n as usize;
    let all_int = [parts[0], parts[1], parts[2]]
        .iter()
        .all(|p| p.trim().parse::<i64>().is_ok());
    Ok((0..=n)
        .map(|i| {
            let v = a + step * i as f64;
            if all_int {
                format!("{}", v.round() as i64)
            } else {
                // Shortest text that reads back as the value, without float noise.
                let s = format!("{:.10}", v);
                s.trim_end_matches('0').trim_end_matches('.').to_string()
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(s: &Source) -> Vec<Vec<String>> {
        s.rows()
            .map(|r| r.values.into_iter().map(|(_, c)| c.text).collect())
            .collect()
    }

    #[test]
    fn grid_is_cartesian_first_axis_slowest() {
        let g = grid_source("L1=135:150:5,R=10,15,20").unwrap();
        assert_eq!(g.len(), 12);
        let t = texts(&g);
        assert_eq!(t[0], ["135", "10"]);
        assert_eq!(t[1], ["135", "15"]);
        assert_eq!(t[3], ["140", "10"]);
        assert_eq!(t[11], ["150", "20"]);
        let r = grid_source("t=0.1:0.3:0.1").unwrap();
        assert_eq!(texts(&r), [["0.1"], ["0.2"], ["0.3"]]);
    }

    #[test]
    fn a_huge_grid_is_counted_not_built() {
        let g = grid_source("L1=0:99999:1,R=0:99999:1").unwrap();
        assert_eq!(g.len(), 100_000 * 100_000);
        let last = match &g {
            Source::Grid(g) => g.row(g.len - 1),
            _ => unreachable!(),
        };
        assert_eq!(last.number, 10_000_000_000);
        assert_eq!(last.field("l1"), Some("99999"));
        assert_eq!(last.field("R"), Some("99999"));
    }

    #[test]
    fn grid_errors() {
        for bad in [
            "",
            "=1",
            "5",
            "L1=1:2",
            "L1=2:1:1",
            "L1=0:1e9:1",
            "a=1,A=2",
            "x=1:y:1",
        ] {
            assert!(grid_source(bad).is_err(), "{bad}");
        }
    }
}
