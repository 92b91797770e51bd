//! Programs compiled once and run many times against a fresh global environment: what a batch
//! worker needs to run one script per table row without re-reading, re-compiling or
//! re-creating the interpreter. As a Lua host loads a chunk once (`luaL_loadbuffer`) and calls
//! it per job, resetting the globals from a snapshot rather than opening a new state.

use super::compile::{Code, Compiler};
use super::error::{Exn, LResult};
use super::eval::{read_error, Interp};
use super::reader::read_source;
use super::value::Value;

/// A source's top-level forms, compiled for the interpreter that compiled them (compiled code
/// holds that interpreter's symbol indices: run it there only).
pub struct Program {
    /// The source id spans point into (`Interp::sources`).
    pub source: u32,
    forms: Vec<Code>,
}

impl Program {
    pub fn len(&self) -> usize {
        self.forms.len()
    }

    pub fn is_empty(&self) -> bool {
        self.forms.is_empty()
    }
}

/// The global environment at one moment: every value cell, and how many symbols existed.
pub struct Globals {
    values: Vec<Value>,
    symbols: usize,
}

impl Interp {
    /// Reads and compiles every form of a source, running none; a reader error as a Lisp error
    /// with its span.
    pub fn compile_program(&mut self, name: &str, text: &str) -> Result<Program, Exn> {
        let source = self.add_source(name, text);
        let parsed =
            read_source(text, source, &mut self.syms).map_err(|e| read_error(e, source))?;
        self.sync_cells();
        let floor = self.stack_floor();
        let forms = parsed
            .forms
            .iter()
            .map(|(form, _)| {
                Compiler::new(Some(&parsed.spans), &self.syms)
                    .with_stack_floor(floor)
                    .compile(form)
            })
            .collect();
        Ok(Program { source, forms })
    }

    /// Runs a compiled program's forms in order, as `eval_source` would: the value of the
    /// last, or the first error. `(exit)` ends the program with its error (kind `Exit`), as it
    /// ends a script.
    pub fn run_program(&mut self, p: &Program) -> LResult {
        self.run_program_until(p, || false)
    }

    /// Like `run_program`, checking `stop` before each form (a batch's Ctrl-C).
    pub fn run_program_until(&mut self, p: &Program, stop: impl Fn() -> bool) -> LResult {
        let mut last = Value::Nil;
        for code in &p.forms {
            if stop() {
                return Err(super::error::abort("interrupted"));
            }
            last = self.run_toplevel(code)?;
        }
        Ok(last)
    }

    /// A snapshot of the global environment, to `restore_globals` before each run. Values are
    /// shared, not copied: taking one costs a reference count per bound symbol.
    pub fn save_globals(&self) -> Globals {
        Globals {
            values: self.values.clone(),
            symbols: self.syms.len(),
        }
    }

    /// Puts the global environment back as it was at `save_globals`: every cell, the symbol
    /// table (symbols interned since are forgotten), and the library areas' state (the
    /// drawing, system variables, selection sets...), which is dropped and created afresh on
    /// first use, as in a new interpreter. The host's own settings kept in that state (file
    /// policy, scripted answers) must be set again after this. Output, sources, limits and
    /// the interrupt flag are the host's and stay; the step count starts again.
    pub fn restore_globals(&mut self, g: &Globals) {
        // Bindings left by an error deep in a run are dropped with the old values.
        self.unwind_to(0);
        self.syms.truncate(g.symbols);
        self.values.clear();
        self.values.extend(g.values.iter().cloned());
        self.sync_cells();
        self.exts.clear();
        self.lambda_cache.clear();
        self.catch_depth = 0;
        self.in_error_handler = false;
        self.restart_steps();
    }
}
