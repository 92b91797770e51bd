//! `lispcad check`: parse and lint files without running them.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use miette::{Diagnostic, LabeledSpan, NamedSource, SourceCode};

use super::{EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::lang::lint::{defined_functions, lint_with, loaded_files, Severity};
use crate::lang::reader::{read_source, Parsed, ReadError};
use crate::lang::value::Sym;
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

/// One file read and parsed for checking.
struct Source {
    name: String,
    text: String,
    parsed: Result<Parsed, ReadError>,
}

fn read_and_parse(it: &mut Interp, path: &Path) -> std::io::Result<Source> {
    let code_page = it.ext::<crate::lang::encoding::SourceCodePage>().0;
    let text = crate::lang::encoding::read_source_file(path, code_page)?;
    let name = path.display().to_string();
    let id = it.add_source(&name, &text);
    let parsed = read_source(&text, id, &mut it.syms);
    it.sync_cells();
    Ok(Source { name, text, parsed })
}

/// The functions defined by the files a source loads with a literal name, followed
/// transitively (`seen` stops cycles); unreadable or unparsable ones are skipped: they are not
/// what is being checked.
fn loaded_definitions(
    it: &mut Interp,
    dir: &Path,
    parsed: &Parsed,
    seen: &mut HashSet<PathBuf>,
    out: &mut HashSet<Sym>,
) {
    for name in loaded_files(parsed, &it.syms) {
        let mut p = dir.join(&name);
        if p.extension().is_none() {
            p.set_extension("lsp");
        }
        let Ok(canon) = p.canonicalize() else {
            continue;
        };
        if !seen.insert(canon.clone()) {
            continue;
        }
        let Ok(src) = read_and_parse(it, &canon) else {
            continue;
        };
        let Ok(parsed) = src.parsed else { continue };
        out.extend(defined_functions(&parsed));
        let sub = canon.parent().map(Path::to_path_buf).unwrap_or_default();
        loaded_definitions(it, &sub, &parsed, seen, out);
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
    // One interpreter for all files so their symbols are shared: functions defined in one
    // file checked together with another, or loaded by it, are not "undefined" there.
    let mut it = crate::builtins::new_interp();
    let mut sources = Vec::new();
    for file in files {
        match read_and_parse(&mut it, file) {
            Ok(src) => sources.push((file.clone(), src)),
            Err(e) => {
                eprintln!("error: cannot read {}: {e}", file.display());
                unreadable = true;
            }
        }
    }
    let own: Vec<HashSet<Sym>> = sources
        .iter()
        .map(|(_, s)| s.parsed.as_ref().map(defined_functions).unwrap_or_default())
        .collect();
    for (i, (file, src)) in sources.iter().enumerate() {
        let report = |message: String, severity, at| LintReport {
            message,
            severity,
            src: NamedSource::new(src.name.clone(), src.text.clone()),
            at,
        };
        let parsed = match &src.parsed {
            Ok(p) => p,
            Err(e) => {
                errors += 1;
                let r = report(
                    e.message.clone(),
                    miette::Severity::Error,
                    Some((e.start, e.end - e.start)),
                );
                eprintln!("{:?}", miette::Report::new(r));
                continue;
            }
        };
        let mut known: HashSet<Sym> = own
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .flat_map(|(_, d)| d.iter().copied())
            .collect();
        let dir = file
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_else(|| PathBuf::from("."));
        let mut seen = HashSet::new();
        if let Ok(c) = file.canonicalize() {
            seen.insert(c);
        }
        loaded_definitions(&mut it, &dir, parsed, &mut seen, &mut known);
        for l in lint_with(&it, parsed, &known) {
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
