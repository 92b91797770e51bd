//! Static analysis of a source text, shared by `check`, the language server and the REPL's help:
//! reader errors and lints as findings with byte ranges, the defuns a file makes (name,
//! parameters, the comment above), the files it loads, the symbol at a position.
//!
//! Everything here reads; nothing evaluates the code being analysed.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use crate::lang::lint::{
    defined_functions, form_facts, loaded_files, resolve, FormFacts, Severity,
};
use crate::lang::reader::{read_source, Parsed, ReadError};
use crate::lang::symbols::{S_DEFUN, S_DEFUN_Q};
use crate::lang::value::Sym;
use crate::lang::{Interp, Value};

/// One problem found in a text: byte range, severity, message.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    pub severity: Severity,
    pub message: String,
    /// Byte range in the text; None when the lint could not attribute it to a form.
    pub range: Option<(usize, usize)>,
}

/// A function a source defines with `defun` / `defun-q`.
#[derive(Clone, Debug, PartialEq)]
pub struct Defun {
    /// As AutoLISP prints it (upper case).
    pub name: String,
    pub params: Vec<String>,
    pub locals: Vec<String>,
    /// Byte range of the whole `(defun ...)` form.
    pub form: (usize, usize),
    /// Byte range of the name inside the form.
    pub name_range: (usize, usize),
    /// The `;` comment lines right above the form, without their semicolons.
    pub comment: String,
}

impl Defun {
    /// `(NAME a b / c)` as help shows it.
    pub fn signature(&self) -> String {
        let mut s = format!("({}", self.name);
        for p in &self.params {
            s.push(' ');
            s.push_str(p);
        }
        if !self.locals.is_empty() {
            s.push_str(" /");
            for l in &self.locals {
                s.push(' ');
                s.push_str(l);
            }
        }
        s.push(')');
        s
    }

    /// Signature, then the comment (or "a user function") indented, like a builtin's help.
    pub fn help(&self) -> String {
        let doc = if self.comment.is_empty() {
            "a user function".to_string()
        } else {
            self.comment.replace('\n', "\n  ")
        };
        format!("{}\n  {doc}", self.signature())
    }
}

/// Reads a text with `it`'s symbol table. The source id is 0: spans are only used as byte
/// ranges into this text, so nothing is registered with the interpreter (an editor sends a
/// new text on every keystroke).
pub fn parse(it: &mut Interp, text: &str) -> Result<Parsed, ReadError> {
    let p = read_source(text, 0, &mut it.syms);
    it.sync_cells();
    p
}

/// The defuns of a parsed text, in source order, at any depth (outside quoted data).
pub fn defuns(it: &Interp, text: &str, parsed: &Parsed) -> Vec<Defun> {
    fn walk(it: &Interp, text: &str, p: &Parsed, v: &Value, out: &mut Vec<Defun>, depth: usize) {
        let Value::Cons(c) = v else { return };
        if depth > 200 || c.car.as_sym() == Some(crate::lang::symbols::S_QUOTE) {
            return;
        }
        if matches!(c.car.as_sym(), Some(S_DEFUN | S_DEFUN_Q)) {
            if let (Some(name), Some(span)) = (c.cdr.car().as_sym(), p.spans.get(v)) {
                out.push(defun_at(it, text, name, &c.cdr.cdr().car(), span));
            }
        }
        for x in v.iter() {
            walk(it, text, p, x, out, depth + 1);
        }
    }
    let mut out = Vec::new();
    for (f, _) in &parsed.forms {
        walk(it, text, parsed, f, &mut out, 0);
    }
    out
}

fn defun_at(
    it: &Interp,
    text: &str,
    name: Sym,
    arglist: &Value,
    span: crate::lang::error::Span,
) -> Defun {
    let form = (span.start as usize, span.end as usize);
    let shown = it.syms.name(name).to_string();
    let mut params = Vec::new();
    let mut locals = Vec::new();
    let mut after_slash = false;
    for a in arglist.iter().filter_map(Value::as_sym) {
        let n = it.syms.name(a).to_string();
        if n == "/" {
            after_slash = true;
        } else if after_slash {
            locals.push(n);
        } else {
            params.push(n);
        }
    }
    Defun {
        name_range: name_range(text, form, &shown),
        name: shown,
        params,
        locals,
        form,
        comment: comment_above(text, form.0),
    }
}

/// Where the name is written inside `(defun NAME ...)`: the first token after the head.
fn name_range(text: &str, form: (usize, usize), name: &str) -> (usize, usize) {
    let body = &text[form.0..form.1.min(text.len())];
    let lower = body.to_ascii_lowercase();
    let want = name.to_ascii_lowercase();
    let mut from = 0;
    while let Some(i) = lower[from..].find(&want) {
        let at = from + i;
        let before_ok = body[..at].ends_with(|c: char| c.is_whitespace());
        let end = at + want.len();
        let after_ok = body[end..].starts_with(|c: char| !is_symbol_char(c));
        if before_ok && after_ok {
            return (form.0 + at, form.0 + end);
        }
        from = end;
    }
    (form.0, form.0)
}

pub use crate::lang::lint::comment_above;

/// Characters a symbol token is made of (everything but the reader's delimiters).
pub fn is_symbol_char(c: char) -> bool {
    !c.is_whitespace() && !"()'\";".contains(c)
}

/// The symbol token around a byte offset (the cursor may sit just after it), with its range.
pub fn word_at(text: &str, offset: usize) -> Option<(usize, usize, &str)> {
    let offset = offset.min(text.len());
    let start = text[..offset]
        .char_indices()
        .rev()
        .take_while(|(_, c)| is_symbol_char(*c))
        .last()
        .map_or(offset, |(i, _)| i);
    let end = text[offset..]
        .char_indices()
        .find(|(_, c)| !is_symbol_char(*c))
        .map_or(text.len(), |(i, _)| offset + i);
    (start < end).then(|| (start, end, &text[start..end]))
}

/// A file a source loads, read and parsed, with the defuns it makes.
pub struct Loaded {
    pub path: PathBuf,
    pub text: String,
    pub defuns: Vec<Defun>,
    pub functions: HashSet<Sym>,
}

/// The files a source loads with a literal name (`(load "lib/util")`, `.lsp` implied), followed
/// transitively; `seen` stops cycles. Unreadable or unparsable files are skipped: they are not
/// what is being analysed.
pub fn loaded(
    it: &mut Interp,
    dir: &Path,
    parsed: &Parsed,
    seen: &mut HashSet<PathBuf>,
) -> Vec<Loaded> {
    let names = loaded_files(parsed, &it.syms);
    loaded_names(it, dir, &names, seen)
}

/// As `loaded`, from the file names a source's `load` forms give.
pub fn loaded_names(
    it: &mut Interp,
    dir: &Path,
    names: &[String],
    seen: &mut HashSet<PathBuf>,
) -> Vec<Loaded> {
    let mut out = Vec::new();
    for name in names {
        let mut p = dir.join(name);
        if p.extension().is_none() {
            p.set_extension("lsp");
        }
        let Ok(canon) = p.canonicalize() else {
            continue;
        };
        if !seen.insert(canon.clone()) {
            continue;
        }
        let Ok(text) = std::fs::read_to_string(&canon) else {
            continue;
        };
        let Ok(sub) = parse(it, &text) else { continue };
        let sub_dir = canon.parent().map(Path::to_path_buf).unwrap_or_default();
        let defs = defuns(it, &text, &sub);
        let functions = defined_functions(&sub);
        let deeper = loaded(it, &sub_dir, &sub, seen);
        out.push(Loaded {
            path: canon,
            text,
            defuns: defs,
            functions,
        });
        out.extend(deeper);
    }
    out
}

/// Reader error or lints of one text. `dir` resolves its `load`s; `known` are functions
/// defined elsewhere (files checked together).
pub fn findings(
    it: &mut Interp,
    text: &str,
    parsed: &Result<Parsed, ReadError>,
    dir: &Path,
    self_path: Option<&Path>,
    known: &HashSet<Sym>,
) -> Vec<Finding> {
    let parsed = match parsed {
        Ok(p) => p,
        Err(e) => return vec![read_error_finding(text, e)],
    };
    let facts: Vec<FormFacts> = parsed
        .forms
        .iter()
        .map(|(f, span)| form_facts(it, &parsed.spans, f, *span))
        .collect();
    let forms: Vec<(u32, &FormFacts)> = facts.iter().map(|f| (0, f)).collect();
    lint_findings(it, &forms, dir, self_path, known)
}

/// A reader error as a finding, its range clamped to the text.
pub fn read_error_finding(text: &str, e: &ReadError) -> Finding {
    Finding {
        severity: Severity::Error,
        message: e.message.clone(),
        range: Some((e.start, e.end.max(e.start).min(text.len()))),
    }
}

/// The lints of a text from the facts of its top-level forms (each with the byte offset it was
/// read at), the files they load resolved from `dir`; `known` as in `findings`.
pub fn lint_findings(
    it: &mut Interp,
    forms: &[(u32, &FormFacts)],
    dir: &Path,
    self_path: Option<&Path>,
    known: &HashSet<Sym>,
) -> Vec<Finding> {
    let mut seen = HashSet::new();
    if let Some(c) = self_path.and_then(|p| p.canonicalize().ok()) {
        seen.insert(c);
    }
    let names: Vec<String> = forms
        .iter()
        .flat_map(|(_, f)| f.loads.iter().cloned())
        .collect();
    let mut known = known.clone();
    for l in loaded_names(it, dir, &names, &mut seen) {
        known.extend(l.functions);
    }
    resolve(it, forms, &known)
        .into_iter()
        .map(|l| Finding {
            severity: l.severity,
            message: l.message,
            range: l.span.map(|s| (s.start as usize, s.end as usize)),
        })
        .collect()
}
