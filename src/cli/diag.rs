//! Printing diagnostics: a Lisp error rendered by miette with its source snippet and call stack.

use std::sync::Once;

use crate::lang::error::Report;
use crate::lang::{Interp, LispError};

/// miette's handler without line wrapping: the first line must stay AutoLISP's whole message
/// (scripts and tests match on it), whatever the terminal width.
pub fn install_hook() {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        let _ = miette::set_hook(Box::new(|_| {
            Box::new(miette::MietteHandlerOpts::new().wrap_lines(false).build())
        }));
    });
}

/// Prints an error to stderr as a miette diagnostic.
pub fn print_error(it: &Interp, e: &LispError) {
    eprintln!("{}", render_error(it, e));
}

/// Renders an error to a string (for the REPL, which prints to its own output).
pub fn render_error(it: &Interp, e: &LispError) -> String {
    install_hook();
    let report = miette::Report::new(Report::new(e, &it.sources));
    format!("{report:?}")
}
