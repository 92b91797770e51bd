//! `lispcad batch`: one run of a script per row of a source (a CSV table, a grid), rows in
//! parallel, each in a fresh interpreter, each row's drawing handed to the sinks (the `-o`
//! output files, written atomically).
//!
//! `source` yields the rows, `runner` runs one, `sink` takes its drawing; this module reads
//! the script, checks the names, and drives the rows with a progress bar and a summary.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use clap::Args;
use rayon::prelude::*;

use super::{diag, Common, EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::lang::eval::{mark_eval_thread, read_error, EVAL_STACK_SIZE};
use crate::lang::reader::read_source;

pub mod csv;
pub mod runner;
pub mod sink;
pub mod source;

use runner::{Outcome, Runner};
use sink::{OutputFiles, Sink};
use source::Source;

#[derive(Args, Debug)]
pub struct BatchArgs {
    /// The script to run for every row.
    pub file: PathBuf,
    /// A CSV table: a header of variable names, one run per row.
    #[arg(long, value_name = "TABLE.csv", conflicts_with = "grid")]
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

/// The rows of the batch: `--vary TABLE`, `--grid SPEC`, or `--open 'GLOB'` (a row per
/// drawing; with a table or grid, `--open` names the one drawing every row starts from).
fn open_source(args: &BatchArgs, common: &Common) -> Result<Source, String> {
    match (&args.vary, &args.grid, &common.open) {
        (None, None, Some(glob)) => return source::drawings_source(glob),
        (_, _, Some(p)) if p.to_string_lossy().contains(['*', '?']) => return Err(
            "--open GLOB makes one row per drawing: it cannot be combined with --vary or --grid"
                .into(),
        ),
        _ => {}
    }
    match (&args.vary, &args.grid) {
        (Some(t), _) => std::fs::read_to_string(t)
            .map_err(|e| format!("cannot read {}: {e}", t.display()))
            .and_then(|s| source::table_source(&s).map_err(|m| format!("{}: {m}", t.display()))),
        (None, Some(g)) => source::grid_source(g),
        (None, None) => Err("batch needs --vary TABLE, --grid SPEC or --open 'GLOB'".into()),
    }
}

/// Usage checks before any row runs: pattern fields exist, outputs do not clash.
fn check_plan(src: &Source, files: &OutputFiles) -> Result<(), String> {
    // The format comes from the pattern's extension, which no field changes.
    super::check_output_formats(&files.patterns)?;
    match src.in_memory() {
        Some(rows) => files.check_clashes(rows),
        None => {
            let cols = src.columns();
            for p in &files.patterns {
                for f in sink::pattern_fields(p) {
                    if !cols.iter().any(|c| c.eq_ignore_ascii_case(&f)) {
                        return Err(format!("pattern `{p}`: no column named {f}"));
                    }
                }
            }
            // A streamed source cannot be checked as a whole: a pattern that leaves out a
            // varying axis surely clashes; anything subtler fails the row that clashes.
            if let Source::Grid(g) = src {
                for p in &files.patterns {
                    let fields = sink::pattern_fields(p);
                    let covers = |n: &str| fields.iter().any(|f| f.eq_ignore_ascii_case(n));
                    if !p.contains("{row}") && g.axes.iter().any(|(n, v)| v.len() > 1 && !covers(n))
                    {
                        let r = g.row(0);
                        return Err(format!(
                            "two rows would write {}: add {{row}} or a column to the pattern",
                            sink::expand_pattern(p, &r)?
                        ));
                    }
                }
            }
            Ok(())
        }
    }
}

/// `--set` names and the source's columns must be symbols the script uses (a column may also
/// be a pattern field); values of declared parameters must be within their ranges.
fn check_names(text: &str, args: &BatchArgs, src: &Source) -> Result<(), String> {
    let names = super::params::scan_with_loads(text, &super::run::parent_dir(&args.file))?;
    names.check_sets(&args.set)?;
    let fields: Vec<String> = args
        .outputs
        .iter()
        .flat_map(|p| sink::pattern_fields(p))
        .collect();
    for c in src.columns() {
        names.check_name("column", &c, &fields)?;
    }
    match src {
        Source::Table { rows, .. } => {
            for r in rows {
                for (k, c) in &r.values {
                    names.check_value(&format!("row {}: column", r.number), k, &c.text)?;
                }
            }
        }
        Source::Grid(g) => {
            for (k, vals) in &g.axes {
                for v in vals {
                    names.check_value("--grid", k, v)?;
                }
            }
        }
    }
    Ok(())
}

/// Reads the script and checks its syntax once: a syntax error fails the whole batch.
fn load_script(args: &BatchArgs) -> Result<(String, String), i32> {
    let text = match crate::lang::encoding::read_source_file(
        &args.file,
        crate::lang::encoding::SourceCodePage::default().0,
    ) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: cannot read script {}: {e}", args.file.display());
            return Err(EXIT_USAGE);
        }
    };
    let name = args.file.display().to_string();
    let mut it = crate::builtins::new_interp();
    let id = it.add_source(&name, &text);
    if let Err(e) = read_source(&text, id, &mut it.syms) {
        diag::print_error(&it, &read_error(e, id));
        return Err(EXIT_SCRIPT_ERROR);
    }
    Ok((name, text))
}

/// Ctrl-C or a termination signal: stop starting rows, interrupt running ones; atomic writes
/// leave no partial file behind.
fn on_interrupt(stop: &Arc<AtomicBool>, interrupts: &Arc<Mutex<Vec<Arc<AtomicBool>>>>) {
    let (stop, interrupts) = (stop.clone(), interrupts.clone());
    let _ = ctrlc::set_handler(move || {
        stop.store(true, Ordering::Relaxed);
        for f in interrupts.lock().map(|v| v.clone()).unwrap_or_default() {
            f.store(true, Ordering::Relaxed);
        }
    });
}

fn progress_bar(total: u64) -> Option<indicatif::ProgressBar> {
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let b = indicatif::ProgressBar::new(total);
    b.set_style(
        indicatif::ProgressStyle::with_template(
            "{bar:40} {pos}/{len} rows  {elapsed_precise}  {msg}",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    Some(b)
}

pub fn batch(args: &BatchArgs, common: &Common) -> i32 {
    let (name, text) = match load_script(args) {
        Ok(s) => s,
        Err(code) => return code,
    };
    let files = OutputFiles::new(args.outputs.clone());
    let sheet = args.sheet.clone().map(sink::ContactSheet::new);
    let src = match open_source(args, common)
        .and_then(|s| check_plan(&s, &files).map(|()| s))
        .and_then(|s| {
            sheet
                .as_ref()
                .map_or(Ok(()), |c| sink::ContactSheet::check(&c.path))?;
            super::check_writer_options(common).map(|()| s)
        })
        .and_then(|s| check_names(&text, args, &s).map(|()| s))
    {
        Ok(s) => s,
        Err(m) => {
            eprintln!("error: {m}");
            return EXIT_USAGE;
        }
    };
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let pool = match worker_pool(jobs) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: cannot start {jobs} workers: {e}");
            return EXIT_USAGE;
        }
    };
    let stop = Arc::new(AtomicBool::new(false));
    let interrupts: Arc<Mutex<Vec<Arc<AtomicBool>>>> = Arc::new(Mutex::new(Vec::new()));
    on_interrupt(&stop, &interrupts);
    let mut sinks: Vec<&dyn Sink> = vec![&files];
    if let Some(c) = &sheet {
        sinks.push(c);
    }
    let runner = Runner {
        name: &name,
        text: &text,
        script_path: &args.file,
        script_dir: super::run::parent_dir(&args.file),
        common,
        sets: &args.set,
        sinks: &sinks,
        stop: &stop,
        interrupts: &interrupts,
        budget: common
            .max_memory
            .unwrap_or_else(crate::lang::memory::default_budget),
    };
    let total = src.len();
    eprintln!("batch: {total} row{}", if total == 1 { "" } else { "s" });
    let start = Instant::now();
    let (ran, failed) = run_rows(&pool, &src, &runner, total);
    let mut finished = true;
    for s in &sinks {
        if let Err(m) = s.finish() {
            eprintln!("error: {m}");
            finished = false;
        }
    }
    let status = summary(ran, failed, total, start, jobs);
    if finished {
        status
    } else {
        EXIT_SCRIPT_ERROR
    }
}

/// The workers, each with the evaluator's deep stack; under an address-space limit
/// (`ulimit -v`) that cannot hold `jobs` of them, smaller stacks (a proportionally smaller
/// recursion limit, as for a single run) rather than no batch at all.
fn worker_pool(jobs: usize) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    // Stacks are address space: leave most of a limit to the rows' data (and spare the
    // failed attempts, whose threads are released asynchronously).
    let room = address_space_limit().map_or(usize::MAX, |l| l / 2 / jobs.max(1));
    let mut last = None;
    for shift in [0, 2, 4, 6] {
        let size = EVAL_STACK_SIZE >> shift;
        if size > room && shift < 6 {
            continue;
        }
        match rayon::ThreadPoolBuilder::new()
            .num_threads(jobs)
            .stack_size(size)
            .start_handler(move |_| mark_eval_thread(size))
            .build()
        {
            Ok(p) => return Ok(p),
            Err(e) => last = Some(e),
        }
    }
    Err(last.expect("at least one size was tried"))
}

/// The address-space limit (`ulimit -v`), if any.
fn address_space_limit() -> Option<usize> {
    let mut r = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: r is a valid rlimit for getrlimit to fill.
    let ok = unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut r) } == 0;
    (ok && r.rlim_cur != libc::RLIM_INFINITY)
        .then(|| usize::try_from(r.rlim_cur).unwrap_or(usize::MAX))
}

/// Runs every row (stopping early on an interrupt); the rows run and the failed row numbers.
fn run_rows(
    pool: &rayon::ThreadPool,
    src: &Source,
    runner: &Runner,
    total: u64,
) -> (u64, Vec<u64>) {
    let bar = progress_bar(total);
    let done = AtomicU64::new(0);
    let failed = Mutex::new(Vec::<u64>::new());
    let stop = runner.stop;
    pool.install(|| {
        // Rows are made as the workers ask for them: a grid is never held in memory, and an
        // interrupt stops the enumeration itself.
        src.rows()
            .take_while(|_| !stop.load(Ordering::Relaxed))
            .par_bridge()
            .for_each(|row| {
                if stop.load(Ordering::Relaxed) {
                    return;
                }
                let outcome = runner.run_row(&row);
                let k = done.fetch_add(1, Ordering::Relaxed) + 1;
                let n = row.number;
                let line = match &outcome {
                    Outcome::Ok(outs) => format!(
                        "row {n}/{total} ok: {}",
                        outs.iter()
                            .map(|o| o.display().to_string())
                            .collect::<Vec<_>>()
                            .join(" ")
                    ),
                    Outcome::Failed(m) => {
                        failed.lock().expect("lock").push(n);
                        format!("row {n}/{total} FAILED ({}):\n{m}", row.describe())
                    }
                };
                match &bar {
                    Some(b) => {
                        if matches!(outcome, Outcome::Failed(_)) {
                            b.println(line);
                        }
                        b.set_position(k);
                    }
                    // One write per line (`eprintln!` made two: the text, then the newline).
                    None => {
                        use std::io::Write;
                        let _ = std::io::stderr().write_all(format!("{line}\n").as_bytes());
                    }
                }
            });
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    (
        done.load(Ordering::Relaxed),
        failed.into_inner().unwrap_or_default(),
    )
}

fn summary(ran: u64, mut failed: Vec<u64>, total: u64, start: Instant, jobs: usize) -> i32 {
    failed.sort_unstable();
    let row_failures = failed.len() as u64;
    let secs = start.elapsed().as_secs_f64();
    eprintln!(
        "batch: {} done, {} failed, {} not run, {:.2} s ({} job{})",
        ran - row_failures,
        row_failures,
        total - ran,
        secs,
        jobs,
        if jobs == 1 { "" } else { "s" }
    );
    if row_failures > 0 {
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
