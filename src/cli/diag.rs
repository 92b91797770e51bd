//! Printing diagnostics: a Lisp error rendered by miette with its source snippet and call stack.

use std::fmt;
use std::sync::Once;

use miette::{Diagnostic, LabeledSpan, SourceCode};

use crate::lang::error::Report;
use crate::lang::lint::{function_names, nearest};
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
    let report = miette::Report::new(Hinted {
        report: Report::new(e, &it.sources),
        hint: hint(it, &e.message),
    });
    format!("{report:?}")
}

/// "did you mean DTR?" for a call of an undefined function. It goes in the diagnostic's help,
/// never in the message: `*error*` handlers see AutoLISP's message unchanged.
pub fn hint(it: &Interp, message: &str) -> Option<String> {
    let name = message.strip_prefix("no function definition: ")?;
    nearest(name, function_names(it)).map(|n| format!("did you mean {}?", n.to_uppercase()))
}

/// A lang Report with a hint line before its call stack.
#[derive(Debug)]
struct Hinted {
    report: Report,
    hint: Option<String>,
}

impl fmt::Display for Hinted {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.report.fmt(f)
    }
}

impl std::error::Error for Hinted {}

impl Diagnostic for Hinted {
    fn source_code(&self) -> Option<&dyn SourceCode> {
        self.report.source_code()
    }
    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        self.report.labels()
    }
    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        let stack = self.report.help().map(|h| h.to_string());
        match (&self.hint, stack) {
            (None, None) => None,
            (Some(h), None) => Some(Box::new(h.clone())),
            (None, Some(s)) => Some(Box::new(s)),
            (Some(h), Some(s)) => Some(Box::new(format!("{h}\n{s}"))),
        }
    }
}
