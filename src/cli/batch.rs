//! `lispcad batch`: one run of a script per row of a CSV table or per point of a grid, rows in
//! parallel, each in a fresh interpreter, outputs named by a pattern and written atomically.
//!
//! The script is read and checked once; each worker thread parses it once and keeps the forms
//! (values are reference counted, so they cannot cross threads); every row then compiles and
//! runs those forms in a new interpreter whose symbol table starts as a copy of the parse's.

use std::cell::RefCell;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use clap::Args;
use rayon::prelude::*;

use super::{diag, Common, EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::builtins::io::FsPolicy;
use crate::lang::compile::Compiler;
use crate::lang::eval::{mark_eval_thread, read_error, EVAL_STACK_SIZE};
use crate::lang::reader::{parse_number, read_one, read_source, Parsed};
use crate::lang::symbols::SymbolTable;
use crate::lang::{ErrorKind, Interp, Value};

#[derive(Args, Debug)]
pub struct BatchArgs {
    /// The script to run for every row.
    pub file: PathBuf,
    /// A CSV table: a header of variable names, one run per row.
    #[arg(
        long,
        value_name = "TABLE.csv",
        conflicts_with = "grid",
        required_unless_present = "grid"
    )]
    pub vary: Option<PathBuf>,
    /// A cartesian grid, e.g. "L1=135:150:5,R=10,15,20" (start:stop:step ranges or value lists).
    #[arg(long, value_name = "SPEC")]
    pub grid: Option<String>,
    /// Output pattern(s), e.g. "out/{name}-{L1}.dxf": {column} is the row's value, {row} its number.
    #[arg(short = 'o', long = "output", value_name = "PATTERN", required = true)]
    pub outputs: Vec<String>,
    /// Parallel jobs (default: all cores).
    #[arg(short = 'j', long = "jobs", value_name = "N")]
    pub jobs: Option<usize>,
    /// Bind a global for every row: NAME=VALUE.
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub set: Vec<String>,
    /// Also write one contact sheet of every row's drawing, labelled (.pdf or .svg).
    #[arg(long, value_name = "FILE")]
    pub sheet: Option<PathBuf>,
}

/// One row: (variable name, value text as written) pairs.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub values: Vec<(String, Cell)>,
}

/// A table cell: quoted cells are strings; unquoted ones are numbers when they read as one.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    pub text: String,
    pub quoted: bool,
}

/// Parses CSV (RFC 4180: commas, double quotes, doubled quotes inside quotes).
pub fn parse_csv(text: &str) -> Result<Vec<Vec<Cell>>, String> {
    let mut rows = Vec::new();
    let mut row: Vec<Cell> = Vec::new();
    let mut cell = String::new();
    let mut quoted = false;
    let mut in_quotes = false;
    let mut chars = text.chars().peekable();
    let mut line = 1;
    let mut any = false;
    while let Some(c) = chars.next() {
        if in_quotes {
            match c {
                '"' if chars.peek() == Some(&'"') => {
                    chars.next();
                    cell.push('"');
                }
                '"' => in_quotes = false,
                '\n' => {
                    line += 1;
                    cell.push(c);
                }
                _ => cell.push(c),
            }
            continue;
        }
        match c {
            '"' if cell.trim().is_empty() => {
                cell.clear();
                in_quotes = true;
                quoted = true;
                any = true;
            }
            ',' => {
                row.push(finish_cell(&mut cell, &mut quoted));
                any = true;
            }
            '\r' => {}
            '\n' => {
                if any || !cell.trim().is_empty() {
                    row.push(finish_cell(&mut cell, &mut quoted));
                    rows.push(std::mem::take(&mut row));
                }
                any = false;
                line += 1;
            }
            _ => {
                if quoted && !c.is_whitespace() {
                    return Err(format!("line {line}: text after a closing quote"));
                }
                cell.push(c);
                any = true;
            }
        }
    }
    if in_quotes {
        return Err(format!("line {line}: unterminated quoted field"));
    }
    if any || !cell.trim().is_empty() {
        row.push(finish_cell(&mut cell, &mut quoted));
        rows.push(row);
    }
    Ok(rows)
}

fn finish_cell(cell: &mut String, quoted: &mut bool) -> Cell {
    let c = Cell {
        text: if *quoted {
            std::mem::take(cell)
        } else {
            std::mem::take(cell).trim().to_string()
        },
        quoted: *quoted,
    };
    *quoted = false;
    c
}

/// The rows of a CSV table with a header of variable names.
pub fn table_rows(text: &str) -> Result<Vec<Row>, String> {
    let mut rows = parse_csv(text)?;
    if rows.is_empty() {
        return Err("the table is empty (it needs a header of variable names)".into());
    }
    let header: Vec<String> = rows.remove(0).into_iter().map(|c| c.text).collect();
    for h in &header {
        if h.is_empty() || parse_number(h).is_some() || h.contains(char::is_whitespace) {
            return Err(format!("header: `{h}` is not a variable name"));
        }
    }
    rows.into_iter()
        .enumerate()
        .map(|(i, r)| {
            if r.len() != header.len() {
                return Err(format!(
                    "row {}: {} fields, the header has {}",
                    i + 1,
                    r.len(),
                    header.len()
                ));
            }
            Ok(Row {
                values: header.iter().cloned().zip(r).collect(),
            })
        })
        .collect()
}

/// The points of a grid spec: "L1=135:150:5,R=10,15,20" → every combination, the first
/// variable varying slowest.
pub fn grid_rows(spec: &str) -> Result<Vec<Row>, String> {
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
    for (name, vals) in vars {
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
        axes.push((name, expanded));
    }
    let mut rows = vec![Row { values: Vec::new() }];
    for (name, vals) in &axes {
        let mut next = Vec::with_capacity(rows.len() * vals.len());
        for r in &rows {
            for v in vals {
                let mut r = r.clone();
                r.values.push((
                    name.clone(),
                    Cell {
                        text: v.clone(),
                        quoted: false,
                    },
                ));
                next.push(r);
            }
        }
        rows = next;
    }
    Ok(rows)
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
    let n = ((b - a) / step + 1e-9).floor() as usize;
    if n > 100_000 {
        return Err(format!("grid: {name}: more than 100000 values"));
    }
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

/// The value a cell binds: numbers as numbers, quoted or other text as a string.
fn cell_value(it: &mut Interp, c: &Cell) -> Value {
    if !c.quoted {
        if let Some(v) = parse_number(&c.text) {
            return v;
        }
        if let Ok(Some((v, end))) = read_one(&c.text, &mut it.syms) {
            if c.text[end..].trim().is_empty() && !matches!(v, Value::Sym(_)) {
                it.sync_cells();
                return v;
            }
        }
    }
    Value::str(&c.text)
}

/// Expands {column} and {row} in an output pattern.
pub fn expand_pattern(pattern: &str, row: &Row, number: usize) -> Result<String, String> {
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
            out.push_str(&number.to_string());
        } else {
            let v = row
                .values
                .iter()
                .find(|(k, _)| k.eq_ignore_ascii_case(key))
                .ok_or_else(|| format!("pattern `{pattern}`: no column named {key}"))?;
            out.push_str(&sanitize(&v.1.text));
        }
        rest = &after[j + 1..];
    }
    out.push_str(rest);
    Ok(out)
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

thread_local! {
    /// This worker's parse of the script: the symbol table after reading, and the forms.
    static PARSED: RefCell<Option<(SymbolTable, Parsed)>> = const { RefCell::new(None) };
}

/// What one row did (with its drawing as SVG when a contact sheet is wanted).
enum Outcome {
    Ok(Option<String>),
    Failed(String),
}

struct Job<'a> {
    name: &'a str,
    text: &'a str,
    script_path: &'a Path,
    script_dir: PathBuf,
    common: &'a Common,
    sets: &'a [String],
    stop: &'a AtomicBool,
    interrupts: &'a Mutex<Vec<Arc<AtomicBool>>>,
    sheet: bool,
}

impl Job<'_> {
    fn run_row(&self, row: &Row, outputs: &[PathBuf]) -> Outcome {
        PARSED.with(|cell| {
            let mut slot = cell.borrow_mut();
            if slot.is_none() {
                let mut tmpl = Interp::new();
                match read_source(self.text, 0, &mut tmpl.syms) {
                    Ok(p) => *slot = Some((tmpl.syms.clone(), p)),
                    Err(e) => return Outcome::Failed(e.message),
                }
            }
            let (syms, parsed) = slot.as_ref().expect("parsed above");
            let mut it = match super::run::configured_interp(self.common) {
                Ok(it) => it,
                Err(m) => return Outcome::Failed(m),
            };
            // Rows run in parallel: none of them may wait on the terminal.
            it.ext::<crate::builtins::input::InputState>().no_terminal = true;
            it.syms = syms.clone();
            it.sync_cells();
            it.add_source(self.name, self.text);
            it.base_dir = Some(self.script_dir.clone());
            it.out = Box::new(std::io::sink());
            it.ext::<FsPolicy>().roots = super::run::script_roots(self.script_path, outputs);
            self.interrupts
                .lock()
                .expect("lock")
                .push(it.interrupt.clone());
            if let Err(m) = super::run::apply_sets(&mut it, self.sets) {
                return Outcome::Failed(m);
            }
            for (k, c) in &row.values {
                let v = cell_value(&mut it, c);
                it.set_global(k, v);
            }
            for (form, _) in &parsed.forms {
                if self.stop.load(Ordering::Relaxed) {
                    return Outcome::Failed("interrupted".into());
                }
                let code = Compiler::new(Some(&parsed.spans), &it.syms).compile(form);
                match it.run_toplevel(&code) {
                    Ok(_) => {}
                    Err(e) if e.kind == ErrorKind::Exit => break,
                    Err(e) => return Outcome::Failed(diag::render_error(&it, &e)),
                }
            }
            if self.stop.load(Ordering::Relaxed) {
                return Outcome::Failed("interrupted".into());
            }
            for o in outputs {
                if let Some(d) = o.parent().filter(|d| !d.as_os_str().is_empty()) {
                    if let Err(e) = std::fs::create_dir_all(d) {
                        return Outcome::Failed(format!("cannot create {}: {e}", d.display()));
                    }
                }
            }
            if let Err(m) = crate::builtins::write_outputs(&mut it, outputs, self.common) {
                return Outcome::Failed(m);
            }
            match self.sheet {
                true => match crate::builtins::drawing_svg(&mut it, self.common) {
                    Ok(svg) => Outcome::Ok(Some(svg)),
                    Err(m) => Outcome::Failed(m),
                },
                false => Outcome::Ok(None),
            }
        })
    }
}

pub fn batch(args: &BatchArgs, common: &Common) -> i32 {
    let text = match std::fs::read_to_string(&args.file) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: cannot read script {}: {e}", args.file.display());
            return EXIT_USAGE;
        }
    };
    let name = args.file.display().to_string();
    // Check the script once, up front: a syntax error fails the whole batch at once.
    {
        let mut it = Interp::new();
        let id = it.add_source(&name, &text);
        if let Err(e) = read_source(&text, id, &mut it.syms) {
            diag::print_error(&it, &read_error(e, id));
            return EXIT_SCRIPT_ERROR;
        }
    }
    let rows = match (&args.vary, &args.grid) {
        (Some(t), _) => std::fs::read_to_string(t)
            .map_err(|e| format!("cannot read {}: {e}", t.display()))
            .and_then(|s| table_rows(&s)),
        (None, Some(g)) => grid_rows(g),
        (None, None) => Err("batch needs --vary TABLE or --grid SPEC".into()),
    };
    let rows = match rows {
        Ok(r) => r,
        Err(m) => {
            eprintln!("error: {m}");
            return EXIT_USAGE;
        }
    };
    let mut planned: Vec<Vec<PathBuf>> = Vec::with_capacity(rows.len());
    for (i, r) in rows.iter().enumerate() {
        let mut outs = Vec::new();
        for p in &args.outputs {
            match expand_pattern(p, r, i + 1) {
                Ok(s) => outs.push(PathBuf::from(s)),
                Err(m) => {
                    eprintln!("error: {m}");
                    return EXIT_USAGE;
                }
            }
        }
        if let Err(m) = super::check_output_formats(&outs)
            .and(check_sheet(&args.sheet))
            .and(super::check_writer_options(common))
        {
            eprintln!("error: {m}");
            return EXIT_USAGE;
        }
        planned.push(outs);
    }
    let mut seen = std::collections::HashSet::new();
    for outs in &planned {
        for o in outs {
            if !seen.insert(o.clone()) {
                eprintln!(
                    "error: two rows would write {}: add {{row}} or a column to the pattern",
                    o.display()
                );
                return EXIT_USAGE;
            }
        }
    }
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let pool = match rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .stack_size(EVAL_STACK_SIZE)
        .start_handler(|_| mark_eval_thread(EVAL_STACK_SIZE))
        .build()
    {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: cannot start {jobs} workers: {e}");
            return EXIT_USAGE;
        }
    };
    let stop = Arc::new(AtomicBool::new(false));
    let interrupts: Arc<Mutex<Vec<Arc<AtomicBool>>>> = Arc::new(Mutex::new(Vec::new()));
    {
        let (stop, interrupts) = (stop.clone(), interrupts.clone());
        // Ctrl-C or a termination signal: stop starting rows, interrupt running ones; atomic
        // writes leave no partial file behind.
        let _ = ctrlc::set_handler(move || {
            stop.store(true, Ordering::Relaxed);
            for f in interrupts.lock().map(|v| v.clone()).unwrap_or_default() {
                f.store(true, Ordering::Relaxed);
            }
        });
    }
    let script_dir = super::run::parent_dir(&args.file);
    let job = Job {
        name: &name,
        text: &text,
        script_path: &args.file,
        script_dir,
        common,
        sets: &args.set,
        stop: &stop,
        interrupts: &interrupts,
        sheet: args.sheet.is_some(),
    };
    let total = rows.len();
    let tty = std::io::stderr().is_terminal();
    let bar = if tty {
        let b = indicatif::ProgressBar::new(total as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} rows  {elapsed_precise}  {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        Some(b)
    } else {
        None
    };
    let done = AtomicUsize::new(0);
    let failed = Mutex::new(Vec::<usize>::new());
    let sheet_rows = Mutex::new(Vec::new());
    let start = Instant::now();
    pool.install(|| {
        rows.par_iter()
            .zip(planned.par_iter())
            .enumerate()
            .for_each(|(i, (row, outs))| {
                if stop.load(Ordering::Relaxed) {
                    return;
                }
                let n = i + 1;
                let outcome = job.run_row(row, outs);
                let k = done.fetch_add(1, Ordering::Relaxed) + 1;
                if let Outcome::Ok(Some(svg)) = &outcome {
                    let name = row
                        .values
                        .iter()
                        .find(|(k, _)| k.eq_ignore_ascii_case("name"));
                    let label = match name {
                        Some((_, c)) => format!("{n}: {}", c.text),
                        None => format!("{n}: {}", describe(row)),
                    };
                    sheet_rows
                        .lock()
                        .expect("lock")
                        .push((n, label, svg.clone()));
                }
                let line = match &outcome {
                    Outcome::Ok(_) => format!(
                        "row {n}/{total} ok: {}",
                        outs.iter()
                            .map(|o| o.display().to_string())
                            .collect::<Vec<_>>()
                            .join(" ")
                    ),
                    Outcome::Failed(m) => {
                        failed.lock().expect("lock").push(n);
                        format!("row {n}/{total} FAILED ({}):\n{m}", describe(row))
                    }
                };
                match &bar {
                    Some(b) => {
                        if matches!(outcome, Outcome::Failed(_)) {
                            b.println(line);
                        }
                        b.set_position(k as u64);
                    }
                    None => eprintln!("{line}"),
                }
            });
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    if let Some(path) = &args.sheet {
        if let Err(m) = write_sheet(path, sheet_rows.into_inner().unwrap_or_default()) {
            eprintln!("error: {m}");
            return EXIT_SCRIPT_ERROR;
        }
    }
    let mut failed = failed.into_inner().unwrap_or_default();
    failed.sort_unstable();
    let ran = done.load(Ordering::Relaxed);
    let secs = start.elapsed().as_secs_f64();
    eprintln!(
        "batch: {} done, {} failed, {} not run, {:.2} s ({} job{})",
        ran - failed.len(),
        failed.len(),
        total - ran,
        secs,
        jobs,
        if jobs == 1 { "" } else { "s" }
    );
    if !failed.is_empty() {
        eprintln!(
            "failed rows: {}",
            failed
                .iter()
                .map(|n| n.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    if failed.is_empty() && ran == total {
        EXIT_OK
    } else {
        EXIT_SCRIPT_ERROR
    }
}

/// A usage error unless the sheet (if any) is .svg or .pdf.
fn check_sheet(sheet: &Option<PathBuf>) -> Result<(), String> {
    use crate::output::Format;
    match sheet.as_deref().map(Format::from_path) {
        None | Some(Ok(Format::Svg | Format::Pdf)) => Ok(()),
        Some(_) => Err("--sheet: the contact sheet must be a .svg or .pdf file".into()),
    }
}

/// The contact sheet of the rows that ran, in row order.
fn write_sheet(path: &Path, mut rows: Vec<(usize, String, String)>) -> Result<(), String> {
    rows.sort_by_key(|r| r.0);
    let rows: Vec<_> = rows
        .into_iter()
        .map(|(_, label, svg)| crate::output::sheet::SheetRow { label, svg })
        .collect();
    let format = crate::output::Format::from_path(path).map_err(|e| e.to_string())?;
    let bytes = crate::output::sheet::compose(&rows, format).map_err(|e| e.to_string())?;
    crate::output::atomic::write_atomic(path, &bytes)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn describe(row: &Row) -> String {
    row.values
        .iter()
        .map(|(k, v)| format!("{k}={}", v.text))
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_with_quotes() {
        let rows = parse_csv("name,L1\n\"big, wide\",140\n\"say \"\"hi\"\"\",135.5\n").unwrap();
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[1][0].text, "big, wide");
        assert!(rows[1][0].quoted);
        assert_eq!(rows[2][0].text, "say \"hi\"");
        assert_eq!(rows[2][1].text, "135.5");
    }

    #[test]
    fn grid_is_cartesian() {
        let rows = grid_rows("L1=135:150:5,R=10,15,20").unwrap();
        assert_eq!(rows.len(), 12);
        assert_eq!(rows[0].values[0].1.text, "135");
        assert_eq!(rows[0].values[1].1.text, "10");
        assert_eq!(rows[11].values[0].1.text, "150");
        assert_eq!(rows[11].values[1].1.text, "20");
        let r = grid_rows("t=0.1:0.3:0.1").unwrap();
        let vals: Vec<_> = r.iter().map(|r| r.values[0].1.text.clone()).collect();
        assert_eq!(vals, ["0.1", "0.2", "0.3"]);
    }

    #[test]
    fn patterns() {
        let row = table_rows("name,L1\nbig,140\n").unwrap().remove(0);
        assert_eq!(
            expand_pattern("out/{name}-{L1}-{row}.dxf", &row, 3).unwrap(),
            "out/big-140-3.dxf"
        );
        assert!(expand_pattern("{nope}.dxf", &row, 1).is_err());
    }
}
