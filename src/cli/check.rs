//! `lispcad check`: parse and lint files without running them.

use std::path::PathBuf;

use miette::{Diagnostic, LabeledSpan, NamedSource, SourceCode};

use super::{EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::lang::lint::{lint, Severity};
use crate::lang::reader::read_source;
use crate::lang::Interp;

#[derive(Debug)]
struct LintReport {
    message: String,
    severity: miette::Severity,
    src: NamedSource<String>,
    at: Option<(usize, usize)>,
}

impl std::fmt::Display for LintReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}
impl std::error::Error for LintReport {}
impl Diagnostic for LintReport {
    fn severity(&self) -> Option<miette::Severity> {
        Some(self.severity)
    }
    fn source_code(&self) -> Option<&dyn SourceCode> {
        Some(&self.src)
    }
    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let (s, l) = self.at?;
        Some(Box::new(std::iter::once(LabeledSpan::new(None, s, l))))
    }
}

pub fn check(files: &[PathBuf]) -> i32 {
    if files.is_empty() {
        eprintln!("error: check needs at least one file");
        return EXIT_USAGE;
    }
    super::diag::install_hook();
    let mut errors = 0;
    let mut warnings = 0;
    let mut unreadable = false;
    for file in files {
        let text = match std::fs::read_to_string(file) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("error: cannot read {}: {e}", file.display());
                unreadable = true;
                continue;
            }
        };
        let name = file.display().to_string();
        let mut it = Interp::new();
        let id = it.add_source(&name, &text);
        let src = NamedSource::new(name.clone(), text.clone());
        let report = |message: String, severity, at| LintReport {
            message,
            severity,
            src: src.clone(),
            at,
        };
        let parsed = match read_source(&text, id, &mut it.syms) {
            Ok(p) => p,
            Err(e) => {
                errors += 1;
                let r = report(
                    e.message,
                    miette::Severity::Error,
                    Some((e.start, e.end - e.start)),
                );
                eprintln!("{:?}", miette::Report::new(r));
                continue;
            }
        };
        it.sync_cells();
        for l in lint(&it, &parsed) {
            let sev = match l.severity {
                Severity::Error => {
                    errors += 1;
                    miette::Severity::Error
                }
                Severity::Warning => {
                    warnings += 1;
                    miette::Severity::Warning
                }
            };
            let at = l
                .span
                .map(|s| (s.start as usize, (s.end - s.start) as usize));
            eprintln!("{:?}", miette::Report::new(report(l.message, sev, at)));
        }
    }
    eprintln!(
        "{} file(s) checked: {errors} error(s), {warnings} warning(s)",
        files.len()
    );
    if unreadable {
        EXIT_USAGE
    } else if errors > 0 {
        EXIT_SCRIPT_ERROR
    } else {
        EXIT_OK
    }
}
