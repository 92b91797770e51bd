//! One row: the worker's interpreter reset to its state after compiling the script, the row's
//! bindings, the compiled forms run, then the sinks.
//!
//! Each worker thread reads and compiles the script once, into an interpreter it keeps (values
//! are reference counted, so neither the interpreter nor the compiled code can cross threads),
//! and snapshots the global environment there. Every row restores that snapshot — a copy of
//! the value cells and a truncation of the symbol table, which also drops the previous row's
//! drawing and library state — instead of building a new interpreter and compiling again, as a
//! Lua host loads a chunk once and runs it per job.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use super::sink::Sink;
use super::source::{Cell, Row};
use crate::builtins::input::InputState;
use crate::cli::{diag, Common};
use crate::lang::program::{Globals, Program};
use crate::lang::reader::{parse_number, read_one};
use crate::lang::{ErrorKind, Interp, Value};

/// A worker's interpreter with the script compiled in it, and what a row resets it to.
struct Worker {
    it: Interp,
    program: Program,
    globals: Globals,
    /// Sources registered at the snapshot (the script's); later ones came from a row's `load`.
    sources: usize,
    /// The `--answers` file's text, read once per worker (each row consumes it afresh).
    answers: Result<Option<String>, String>,
    /// The output directories' handles, kept open from row to row (see
    /// `fs_policy::DirCache`: each row's policy shares them).
    dirs: crate::builtins::fs_policy::DirCache,
}

thread_local! {
    static WORKER: RefCell<Option<Worker>> = const { RefCell::new(None) };
}

/// What one row did.
pub enum Outcome {
    /// The files written.
    Ok(Vec<PathBuf>),
    Failed(String),
}

pub struct Runner<'a> {
    pub name: &'a str,
    pub text: &'a str,
    pub script_path: &'a Path,
    pub script_dir: PathBuf,
    pub common: &'a Common,
    pub sets: &'a [String],
    pub sinks: &'a [&'a dyn Sink],
    pub stop: &'a AtomicBool,
    /// The interrupt flags of the rows running now (Ctrl-C sets them all).
    pub interrupts: &'a Mutex<Vec<Arc<AtomicBool>>>,
    /// Every row's memory budget: `--max-memory`, or the default worked out once per batch
    /// (it asks the kernel for the physical memory and two limits: three calls per row).
    pub budget: usize,
}

impl Runner<'_> {
    pub fn run_row(&self, row: &Row) -> Outcome {
        let mut paths = Vec::new();
        let mut per_sink = Vec::with_capacity(self.sinks.len());
        for s in self.sinks {
            match s.paths(row) {
                Ok(p) => {
                    paths.extend(p.iter().cloned());
                    per_sink.push(p);
                }
                Err(m) => return Outcome::Failed(m),
            }
        }
        WORKER.with(|cell| {
            let mut slot = cell.borrow_mut();
            if slot.is_none() {
                match self.worker() {
                    Ok(w) => *slot = Some(w),
                    Err(m) => return Outcome::Failed(m),
                }
            }
            let w = slot.as_mut().expect("made above");
            if let Err(m) = self.reset(w, row, &paths) {
                return Outcome::Failed(m);
            }
            let it = &mut w.it;
            let flag = it.interrupt.clone();
            self.interrupts.lock().expect("lock").push(flag.clone());
            let r = self.run_program(it, &w.program).and_then(|()| {
                for (s, p) in self.sinks.iter().zip(&per_sink) {
                    s.row_done(it, row, p, self.common)?;
                }
                Ok(())
            });
            self.interrupts
                .lock()
                .expect("lock")
                .retain(|f| !Arc::ptr_eq(f, &flag));
            match r {
                Ok(()) => Outcome::Ok(paths),
                Err(m) => Outcome::Failed(m),
            }
        })
    }

    /// This worker's interpreter: the library installed, the script read and compiled.
    fn worker(&self) -> Result<Worker, String> {
        let mut it = crate::builtins::new_interp();
        let program = it
            .compile_program(self.name, self.text)
            .map_err(|e| diag::render_error(&it, &e))?;
        // Rows run in parallel and print nothing: none of them may wait on the terminal.
        it.out = Box::new(std::io::sink());
        let answers = match &self.common.answers {
            None => Ok(None),
            Some(path) => std::fs::read_to_string(path)
                .map(Some)
                .map_err(|e| format!("cannot read the answers file {}: {e}", path.display())),
        };
        Ok(Worker {
            globals: it.save_globals(),
            sources: it.sources.len(),
            it,
            program,
            answers,
            dirs: crate::builtins::fs_policy::DirCache::new(),
        })
    }

    /// The worker's interpreter as a fresh one for `row`: the globals as after compiling, the
    /// options, write roots, `--set` and the row's bindings.
    fn reset(&self, w: &mut Worker, row: &Row, paths: &[PathBuf]) -> Result<(), String> {
        let it = &mut w.it;
        // Frees the previous row's drawing and values before this row's budget is set.
        it.restore_globals(&w.globals);
        it.sources.truncate(w.sources);
        it.loaded_files.clear();
        it.base_dir = Some(self.script_dir.clone());
        it.interrupt.store(false, Ordering::Relaxed);
        crate::lang::memory::set_budget(Some(self.budget));
        it.set_max_steps(self.common.max_steps);
        // A drawings source names each row's drawing; otherwise `--open` is every row's.
        let open = row.open.as_ref().or(self.common.open.as_ref());
        let named: Vec<PathBuf> = open.into_iter().cloned().collect();
        let mut policy =
            crate::cli::run::fs_policy(self.common, Some(self.script_path), paths, &named);
        policy.dirs = w.dirs.clone();
        *it.ext::<crate::builtins::io::FsPolicy>() = policy;
        if let Some(text) = w.answers.clone()? {
            it.ext::<InputState>().load_answers(&text);
        }
        if let Some(p) = open {
            if let Some(note) = crate::builtins::drawing::open_into(it, p, self.common.recover)? {
                eprintln!("{}: {note}", p.display());
            }
        }
        it.ext::<InputState>().no_terminal = true;
        crate::cli::run::apply_sets(it, self.sets)?;
        for (k, c) in &row.values {
            let v = cell_value(it, c);
            it.set_global(k, v);
        }
        Ok(())
    }

    fn run_program(&self, it: &mut Interp, program: &Program) -> Result<(), String> {
        let r = it.run_program_until(program, || self.stop.load(Ordering::Relaxed));
        if self.stop.load(Ordering::Relaxed) {
            return Err("interrupted".into());
        }
        match r {
            Ok(_) => Ok(()),
            Err(e) if e.kind == ErrorKind::Exit => Ok(()),
            Err(e) => Err(diag::render_error(it, &e)),
        }
    }
}

/// The value a cell binds: numbers as numbers, quoted or other text as a string.
pub fn cell_value(it: &mut Interp, c: &Cell) -> Value {
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
