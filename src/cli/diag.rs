//! Printing diagnostics: a Lisp error rendered by miette with its source snippet and call stack.

use crate::lang::error::Report;
use crate::lang::{Interp, LispError};

/// Prints an error to stderr as a miette diagnostic.
pub fn print_error(it: &Interp, e: &LispError) {
    let report = miette::Report::new(Report::new(e, &it.sources));
    eprintln!("{report:?}");
}

/// Renders an error to a string (for the REPL, which prints to its own output).
pub fn render_error(it: &Interp, e: &LispError) -> String {
    let report = miette::Report::new(Report::new(e, &it.sources));
    format!("{report:?}")
}
