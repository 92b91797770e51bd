//! One row: a fresh interpreter, the script's forms, the row's bindings, then the sinks.
//!
//! Each worker thread parses the script once and keeps the forms (values are reference
//! counted, so they cannot cross threads); every row then compiles and runs those forms in a
//! new interpreter whose symbol table starts as a copy of the parse's.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use super::sink::Sink;
use super::source::{Cell, Row};
use crate::cli::{diag, Common};
use crate::lang::compile::Compiler;
use crate::lang::reader::{parse_number, read_one, read_source, Parsed};
use crate::lang::symbols::SymbolTable;
use crate::lang::{ErrorKind, Interp, Value};

thread_local! {
    /// This worker's parse of the script: the symbol table after reading, and the forms.
    static PARSED: RefCell<Option<(SymbolTable, Parsed)>> = const { RefCell::new(None) };
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
        PARSED.with(|cell| {
            let mut slot = cell.borrow_mut();
            if slot.is_none() {
                let mut tmpl = crate::builtins::new_interp();
                match read_source(self.text, 0, &mut tmpl.syms) {
                    Ok(p) => *slot = Some((tmpl.syms.clone(), p)),
                    Err(e) => return Outcome::Failed(e.message),
                }
            }
            let (syms, parsed) = slot.as_ref().expect("parsed above");
            let mut it = match self.interp(syms, row, &paths) {
                Ok(it) => it,
                Err(m) => return Outcome::Failed(m),
            };
            let flag = it.interrupt.clone();
            self.interrupts.lock().expect("lock").push(flag.clone());
            let r = self.run_forms(&mut it, parsed).and_then(|()| {
                for (s, p) in self.sinks.iter().zip(&per_sink) {
                    s.row_done(&mut it, row, p, self.common)?;
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

    /// A fresh interpreter for `row`: options, write roots, `--set` and the row's bindings.
    fn interp(&self, syms: &SymbolTable, row: &Row, paths: &[PathBuf]) -> Result<Interp, String> {
        // A drawings source names each row's drawing; otherwise `--open` is every row's.
        let open = row.open.as_ref().or(self.common.open.as_ref());
        let named: Vec<PathBuf> = open.into_iter().cloned().collect();
        let policy = crate::cli::run::fs_policy(self.common, Some(self.script_path), paths, &named);
        let mut it = crate::cli::run::configured_interp(self.common, policy)?;
        if let Some(p) = open {
            if let Some(note) =
                crate::builtins::drawing::open_into(&mut it, p, self.common.recover)?
            {
                eprintln!("{}: {note}", p.display());
            }
        }
        // Rows run in parallel: none of them may wait on the terminal.
        it.ext::<crate::builtins::input::InputState>().no_terminal = true;
        it.syms = syms.clone();
        it.sync_cells();
        it.add_source(self.name, self.text);
        it.base_dir = Some(self.script_dir.clone());
        it.out = Box::new(std::io::sink());
        crate::cli::run::apply_sets(&mut it, self.sets)?;
        for (k, c) in &row.values {
            let v = cell_value(&mut it, c);
            it.set_global(k, v);
        }
        Ok(it)
    }

    fn run_forms(&self, it: &mut Interp, parsed: &Parsed) -> Result<(), String> {
        for (form, _) in &parsed.forms {
            if self.stop.load(Ordering::Relaxed) {
                return Err("interrupted".into());
            }
            let code = Compiler::new(Some(&parsed.spans), &it.syms).compile(form);
            match it.run_toplevel(&code) {
                Ok(_) => {}
                Err(e) if e.kind == ErrorKind::Exit => break,
                Err(e) => return Err(diag::render_error(it, &e)),
            }
        }
        if self.stop.load(Ordering::Relaxed) {
            return Err("interrupted".into());
        }
        Ok(())
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
