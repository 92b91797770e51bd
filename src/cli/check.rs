//! `lispcad check`: parse and lint files without running them; human (miette) or JSON output.

use std::collections::HashSet;
use std::path::PathBuf;

use clap::Args;
use miette::{Diagnostic, LabeledSpan, NamedSource, SourceCode};

use super::analysis::{self, Finding};
use super::{EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::lang::error::line_col;
use crate::lang::lint::{defined_functions, Severity};
use crate::lang::value::Sym;

#[derive(Args, Debug)]
pub struct CheckArgs {
    pub files: Vec<PathBuf>,
    /// Output: human (miette diagnostics on stderr) or json (one object on stdout).
    #[arg(long, value_name = "human|json", default_value = "human")]
    pub format: Format,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Human,
    Json,
}

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

/// A file's findings, for printing.
struct Checked {
    name: String,
    text: String,
    findings: Vec<Finding>,
}

fn check_all(files: &[PathBuf], unreadable: &mut bool) -> Vec<Checked> {
    // One interpreter for all files so their symbols are shared: functions defined in one
    // file checked together with another are not "undefined" there.
    let mut it = crate::builtins::new_interp();
    let mut sources = Vec::new();
    for file in files {
        let code_page = it.ext::<crate::lang::encoding::SourceCodePage>().0;
        match crate::lang::encoding::read_source_file(file, code_page) {
            Ok(text) => {
                let parsed = analysis::parse(&mut it, &text);
                sources.push((file, text, parsed));
            }
            Err(e) => {
                eprintln!("error: cannot read {}: {e}", file.display());
                *unreadable = true;
            }
        }
    }
    let own: Vec<HashSet<Sym>> = sources
        .iter()
        .map(|(_, _, p)| p.as_ref().map(defined_functions).unwrap_or_default())
        .collect();
    let mut out = Vec::new();
    for (i, (file, text, parsed)) in sources.iter().enumerate() {
        let known: HashSet<Sym> = own
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .flat_map(|(_, d)| d.iter().copied())
            .collect();
        let dir = super::run::parent_dir(file);
        let findings = analysis::findings(&mut it, text, parsed, &dir, Some(file), &known);
        out.push(Checked {
            name: file.display().to_string(),
            text: text.clone(),
            findings,
        });
    }
    out
}

pub fn check(args: &CheckArgs) -> i32 {
    let files = &args.files;
    if files.is_empty() {
        eprintln!("error: check needs at least one file");
        return EXIT_USAGE;
    }
    super::diag::install_hook();
    let mut unreadable = false;
    let checked = check_all(files, &mut unreadable);
    let count = |sev| {
        checked
            .iter()
            .flat_map(|c| &c.findings)
            .filter(|f| f.severity == sev)
            .count()
    };
    let (errors, warnings) = (count(Severity::Error), count(Severity::Warning));
    match args.format {
        Format::Human => {
            for c in &checked {
                print_human(c);
            }
            eprintln!(
                "{} file(s) checked: {errors} error(s), {warnings} warning(s)",
                files.len()
            );
        }
        Format::Json => println!("{}", to_json(&checked, files.len(), errors, warnings)),
    }
    if unreadable {
        EXIT_USAGE
    } else if errors > 0 {
        EXIT_SCRIPT_ERROR
    } else {
        EXIT_OK
    }
}

fn print_human(c: &Checked) {
    for f in &c.findings {
        let severity = match f.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
        };
        let r = LintReport {
            message: f.message.clone(),
            severity,
            src: NamedSource::new(c.name.clone(), c.text.clone()),
            at: f.range.map(|(s, e)| (s, e - s)),
        };
        eprintln!("{:?}", miette::Report::new(r));
    }
}

/// `{"files", "errors", "warnings", "diagnostics": [{file, severity, message, line, column,
/// end_line, end_column}]}`; lines and columns 1-based, columns in characters, positions null
/// when a lint has no form to point at.
fn to_json(checked: &[Checked], files: usize, errors: usize, warnings: usize) -> String {
    let diags: Vec<serde_json::Value> = checked
        .iter()
        .flat_map(|c| c.findings.iter().map(move |f| finding_json(c, f)))
        .collect();
    serde_json::json!({
        "files": files,
        "errors": errors,
        "warnings": warnings,
        "diagnostics": diags,
    })
    .to_string()
}

fn finding_json(c: &Checked, f: &Finding) -> serde_json::Value {
    let pos = |o: usize| line_col(&c.text, o);
    let (start, end) = match f.range {
        Some((s, e)) => (Some(pos(s)), Some(pos(e))),
        None => (None, None),
    };
    serde_json::json!({
        "file": c.name,
        "severity": match f.severity { Severity::Error => "error", Severity::Warning => "warning" },
        "message": f.message,
        "line": start.map(|p| p.0),
        "column": start.map(|p| p.1),
        "end_line": end.map(|p| p.0),
        "end_column": end.map(|p| p.1),
    })
}
