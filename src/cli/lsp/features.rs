//! The language server's answers: pure functions from a document (its text, path and read
//! forms) to diagnostics, hover, completion, definition, symbols and folding ranges. The interpreter
//! passed in is only a symbol table and the builtin library; nothing is evaluated.

use std::collections::{BTreeSet, HashSet};
use std::path::{Path, PathBuf};

use lsp_types::{
    CompletionItem, CompletionItemKind, Diagnostic, DiagnosticSeverity, DocumentSymbol,
    FoldingRange, FoldingRangeKind, Hover, HoverContents, Location, MarkupContent, MarkupKind,
    Position, Range, SymbolKind, Uri,
};

use super::document::{Document, LineIndex};
use super::vars::{self, Binding};
use crate::cli::analysis::{self, Defun};
use crate::lang::lint::Severity;
use crate::lang::{Interp, Value};

/// Reader errors and `check` lints of the document: those of a full read of its text.
pub fn findings(it: &mut Interp, doc: &Document) -> Vec<analysis::Finding> {
    match doc.read_error() {
        Some(e) => vec![analysis::read_error_finding(doc.text(), e)],
        None => analysis::lint_findings(
            it,
            &doc.facts(),
            &doc.dir(),
            doc.path.as_deref(),
            &HashSet::new(),
        ),
    }
}

/// The findings as LSP diagnostics.
pub fn diagnostics(it: &mut Interp, doc: &Document) -> Vec<Diagnostic> {
    findings(it, doc)
        .into_iter()
        .map(|f| Diagnostic {
            range: f.range.map_or_else(Range::default, |r| doc.range(r)),
            severity: Some(match f.severity {
                Severity::Error => DiagnosticSeverity::ERROR,
                Severity::Warning => DiagnosticSeverity::WARNING,
            }),
            source: Some("lispcad".into()),
            message: f.message,
            ..Default::default()
        })
        .collect()
}

/// A defun and where it is written: this document (None) or a file it loads.
struct Found {
    defun: Defun,
    file: Option<PathBuf>,
    text: Option<String>,
}

/// The defun of `name` in the document, else in the files it loads (first definition wins,
/// as the file is read top to bottom).
fn find_defun(it: &mut Interp, doc: &Document, name: &str) -> Option<Found> {
    if let Some(d) = doc
        .defuns(it)
        .into_iter()
        .find(|d| d.name.eq_ignore_ascii_case(name))
    {
        return Some(Found {
            defun: d,
            file: None,
            text: None,
        });
    }
    let mut seen: HashSet<PathBuf> = doc
        .path
        .iter()
        .filter_map(|p| p.canonicalize().ok())
        .collect();
    let names: Vec<String> = doc
        .facts()
        .iter()
        .flat_map(|(_, f)| f.loads.iter().cloned())
        .collect();
    analysis::loaded_names(it, &doc.dir(), &names, &mut seen)
        .into_iter()
        .find_map(|l| {
            let d = l
                .defuns
                .into_iter()
                .find(|d| d.name.eq_ignore_ascii_case(name))?;
            Some(Found {
                defun: d,
                file: Some(l.path),
                text: Some(l.text),
            })
        })
}

/// A variable's binding (parameter, local, loop variable, global), a user defun's parameter
/// list and the comment above it, or a builtin's signature and doc.
pub fn hover(it: &mut Interp, doc: &Document, pos: Position) -> Option<Hover> {
    let offset = doc.offset(pos);
    let (start, end, word) = analysis::word_at(doc.text(), offset)?;
    let bound = vars::binding(it, doc, offset, word);
    let value = match bound {
        // A parameter or local shadows a function of the same name.
        Some(b @ (Binding::Param { .. } | Binding::Loop { .. })) => variable_hover(doc, word, b),
        // A user defun of a builtin's name replaces the builtin when the file runs.
        _ => {
            if let Some(f) = find_defun(it, doc, word) {
                defun_hover(&f)
            } else if let Some(b) = crate::builtins::find(word) {
                format!("```lisp\n{}\n```\n{}", b.sig, b.doc)
            } else {
                variable_hover(doc, word, bound?)
            }
        }
    };
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value,
        }),
        range: Some(doc.range((start, end))),
    })
}

fn defun_hover(f: &Found) -> String {
    let mut v = format!("```lisp\n{}\n```", f.defun.signature());
    if !f.defun.comment.is_empty() {
        v.push('\n');
        v.push_str(&f.defun.comment);
    }
    if let (Some(file), Some(text)) = (&f.file, &f.text) {
        let (line, _) = crate::lang::error::line_col(text, f.defun.form.0);
        v.push_str(&format!("\n\n*defined in {}:{line}*", file.display()));
    }
    v
}

/// How a variable is bound, in the words of the hover.
fn variable_hover(doc: &Document, word: &str, b: Binding) -> String {
    let name = word.to_uppercase();
    let within = |w: Option<String>| w.map(|w| format!(" in {w}")).unwrap_or_default();
    match b {
        Binding::Param {
            owner,
            within: lambda_in,
            local,
            arglist,
            ..
        } => {
            let what = if local {
                "a local variable"
            } else {
                "a parameter"
            };
            let of = match owner {
                Some(f) => format!("`{f}`"),
                None => format!("a lambda{}", within(lambda_in)),
            };
            let declared = if local { ", declared after `/`" } else { "" };
            format!("`{name}`: {what} of {of}{declared}\n\n```lisp\n{arglist}\n```")
        }
        Binding::Loop { within: w, .. } => {
            format!("`{name}`: the variable of a `foreach`{}", within(w))
        }
        Binding::Global { sets } => {
            const SHOWN: usize = 8;
            let mut v = format!("`{name}`: a global variable, set by `setq`");
            for (at, defun) in sets.iter().take(SHOWN) {
                let line = doc.position(at.0).line + 1;
                let place = defun
                    .as_ref()
                    .map_or_else(|| " (top level)".to_string(), |d| format!(" in `{d}`"));
                v.push_str(&format!("\n- line {line}{place}"));
            }
            if sets.len() > SHOWN {
                v.push_str(&format!("\n- and {} more", sets.len() - SHOWN));
            }
            v
        }
    }
}

/// Where a name is bound or defined: the argument list or `foreach` binding it, its defun in
/// this document or a file it loads, or the first `setq` of a global.
pub fn definition(it: &mut Interp, doc: &Document, uri: &Uri, pos: Position) -> Option<Location> {
    let offset = doc.offset(pos);
    let (_, _, word) = analysis::word_at(doc.text(), offset)?;
    let here = |r| Some(Location::new(uri.clone(), doc.range(r)));
    let bound = vars::binding(it, doc, offset, word);
    if let Some(Binding::Param { at, .. } | Binding::Loop { at, .. }) = bound {
        return here(at);
    }
    let Some(f) = find_defun(it, doc, word) else {
        let Some(Binding::Global { sets }) = bound else {
            return None;
        };
        return here(sets.first()?.0);
    };
    match (f.file, f.text) {
        (Some(file), Some(text)) => Some(Location::new(
            path_to_uri(&file)?,
            LineIndex::new(&text).range(&text, f.defun.name_range),
        )),
        _ => here(f.defun.name_range),
    }
}

/// Builtins and the document's own symbols (defuns, variables) starting with the word being
/// typed; lower case, as AutoLISP code is usually written.
pub fn completion(it: &mut Interp, doc: &Document, pos: Position) -> Vec<CompletionItem> {
    let offset = doc.offset(pos);
    let text = doc.text();
    let prefix = analysis::word_at(text, offset)
        .filter(|(s, _, _)| *s < offset)
        .map(|(s, _, _)| text[s..offset].to_lowercase())
        .unwrap_or_default();
    let mut items = Vec::new();
    let mut seen = HashSet::new();
    let defuns = doc.defuns(it);
    for d in &defuns {
        let label = d.name.to_lowercase();
        if label.starts_with(&prefix) && seen.insert(label.clone()) {
            items.push(CompletionItem {
                label,
                kind: Some(CompletionItemKind::FUNCTION),
                detail: Some(d.signature()),
                ..Default::default()
            });
        }
    }
    for (_, table) in crate::builtins::tables() {
        for b in table.iter() {
            if b.name.starts_with(&prefix) && seen.insert(b.name.to_string()) {
                items.push(CompletionItem {
                    label: b.name.to_string(),
                    kind: Some(if b.special {
                        CompletionItemKind::KEYWORD
                    } else {
                        CompletionItemKind::FUNCTION
                    }),
                    detail: Some(b.sig.to_string()),
                    ..Default::default()
                });
            }
        }
    }
    let word_here = analysis::word_at(text, offset).map(|(s, e, _)| (s, e));
    for (s, e) in symbol_tokens(text) {
        if Some((s, e)) == word_here {
            continue;
        }
        let label = text[s..e].to_lowercase();
        if label.starts_with(&prefix) && seen.insert(label.clone()) {
            items.push(CompletionItem {
                label,
                kind: Some(CompletionItemKind::VARIABLE),
                ..Default::default()
            });
        }
    }
    items
}

/// Byte ranges of the symbol tokens of a text, outside strings and comments; numbers are not
/// symbols. A lexical scan, so it works on text that does not parse yet.
fn symbol_tokens(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'"' => {
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            b';' if b.get(i + 1) == Some(&b'|') => {
                i = text[i..].find("|;").map_or(b.len(), |j| i + j + 2);
            }
            b';' => i = text[i..].find('\n').map_or(b.len(), |j| i + j),
            _ if analysis::is_symbol_char(text[i..].chars().next().unwrap_or(' ')) => {
                let end = text[i..]
                    .char_indices()
                    .find(|(_, c)| !analysis::is_symbol_char(*c))
                    .map_or(text.len(), |(j, _)| i + j);
                if crate::lang::reader::parse_number(&text[i..end]).is_none() {
                    out.push((i, end));
                }
                i = end;
            }
            _ => i += text[i..].chars().next().map_or(1, char::len_utf8),
        }
    }
    out
}

/// The document's defuns, and its top-level `setq`s as variables.
#[allow(
    deprecated,
    reason = "DocumentSymbol's `deprecated` field must still be given"
)]
pub fn document_symbols(it: &mut Interp, doc: &Document) -> Vec<DocumentSymbol> {
    let symbol = |name: String, detail, kind, range, sel| DocumentSymbol {
        name,
        detail,
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range: sel,
        children: None,
    };
    let mut out: Vec<(usize, DocumentSymbol)> = doc
        .defuns(it)
        .into_iter()
        .map(|d| {
            let s = symbol(
                d.name.clone(),
                Some(d.signature()),
                SymbolKind::FUNCTION,
                doc.range(d.form),
                doc.range(d.name_range),
            );
            (d.form.0, s)
        })
        .collect();
    let setq = it.syms.lookup("SETQ");
    for (at, parsed) in doc.read_forms() {
        for (f, span) in &parsed.forms {
            if setq.is_none() || f.car().as_sym() != setq {
                continue;
            }
            let start = at + span.start as usize;
            let range = doc.range((start, at + span.end as usize));
            for (i, v) in f.cdr().iter().enumerate() {
                if let (0, Value::Sym(s)) = (i % 2, v) {
                    let name = it.syms.name(*s).to_string();
                    out.push((
                        start,
                        symbol(name, None, SymbolKind::VARIABLE, range, range),
                    ));
                }
            }
        }
    }
    out.sort_by_key(|(at, _)| *at);
    out.into_iter().map(|(_, s)| s).collect()
}

/// Every list spanning several lines folds, and so does a run of comment lines.
pub fn folding_ranges(doc: &Document) -> Vec<FoldingRange> {
    let mut lines: BTreeSet<(u32, u32)> = BTreeSet::new();
    for (at, parsed) in doc.read_forms() {
        let mut stack: Vec<&Value> = parsed.forms.iter().map(|(f, _)| f).collect();
        while let Some(v) = stack.pop() {
            if let Some(s) = parsed.spans.get(v) {
                let (a, b) = (
                    doc.position(at + s.start as usize).line,
                    doc.position(at + s.end as usize).line,
                );
                if b > a {
                    lines.insert((a, b));
                }
            }
            if matches!(v, Value::Cons(_)) {
                stack.extend(v.iter().filter(|x| matches!(x, Value::Cons(_))));
            }
        }
    }
    let mut out: Vec<FoldingRange> = lines
        .into_iter()
        .map(|(a, b)| FoldingRange {
            start_line: a,
            end_line: b,
            kind: Some(FoldingRangeKind::Region),
            ..Default::default()
        })
        .collect();
    let mut run: Option<(u32, u32)> = None;
    for (n, l) in doc.text().lines().chain(std::iter::once("")).enumerate() {
        let n = n as u32;
        if l.trim_start().starts_with(';') {
            run = Some(run.map_or((n, n), |(a, _)| (a, n)));
        } else if let Some((a, b)) = run.take() {
            if b > a {
                out.push(FoldingRange {
                    start_line: a,
                    end_line: b,
                    kind: Some(FoldingRangeKind::Comment),
                    ..Default::default()
                });
            }
        }
    }
    out
}

/// The path of a `file:` URI (percent-decoded).
pub fn uri_to_path(uri: &Uri) -> Option<PathBuf> {
    let s = uri.as_str().strip_prefix("file://")?;
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' && i + 2 < bytes.len() {
            if let Ok(b) = u8::from_str_radix(&s[i + 1..i + 3], 16) {
                out.push(b);
                i += 3;
                continue;
            }
        }
        out.push(bytes[i]);
        i += 1;
    }
    String::from_utf8(out).ok().map(PathBuf::from)
}

/// A `file:` URI for an absolute path, reserved characters percent-encoded.
pub fn path_to_uri(path: &Path) -> Option<Uri> {
    let mut s = String::from("file://");
    for b in path.to_str()?.bytes() {
        if b.is_ascii_alphanumeric() || b"/-._~".contains(&b) {
            s.push(b as char);
        } else {
            s.push_str(&format!("%{b:02X}"));
        }
    }
    s.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn snap(it: &mut Interp, text: &str) -> Document {
        Document::new(it, text.to_string(), None)
    }

    #[test]
    fn positions_count_utf16_units() {
        let mut it = crate::builtins::new_interp();
        let s = snap(&mut it, "(a)\n(\"é𝄞\" b)\n");
        let b = s.text().find(" b").unwrap() + 1;
        // ( " é 𝄞 " space: 1 + 1 + 1 + 2 (a surrogate pair) + 1 + 1 units.
        assert_eq!(s.position(b), Position::new(1, 7));
        assert_eq!(s.offset(Position::new(1, 7)), b);
        assert_eq!(s.offset(Position::new(9, 0)), s.text().len());
    }

    #[test]
    fn hover_shows_builtin_doc_and_user_defun_comment() {
        let mut it = crate::builtins::new_interp();
        let s = snap(&mut it, ";; Degrees to radians.\n(defun dtr (a) (* pi (/ a 180.0)))\n(dtr 90)\n(polar '(0 0) 0 1)\n");
        let h = hover(&mut it, &s, Position::new(2, 2)).unwrap();
        let HoverContents::Markup(m) = h.contents else {
            panic!()
        };
        assert_eq!(m.value, "```lisp\n(DTR A)\n```\nDegrees to radians.");
        assert_eq!(
            h.range,
            Some(Range::new(Position::new(2, 1), Position::new(2, 4)))
        );
        let h = hover(&mut it, &s, Position::new(3, 3)).unwrap();
        let HoverContents::Markup(m) = h.contents else {
            panic!()
        };
        assert!(m.value.starts_with("```lisp\n(polar "), "{}", m.value);
        assert!(hover(&mut it, &s, Position::new(2, 6)).is_none());
    }

    #[test]
    fn completion_offers_builtins_defuns_and_variables() {
        let mut it = crate::builtins::new_interp();
        let s = snap(
            &mut it,
            "(defun draw-hole (r) r)\n(setq hole-count 3)\n(dr)",
        );
        let items = completion(&mut it, &s, Position::new(2, 3));
        let labels: Vec<&str> = items.iter().map(|i| i.label.as_str()).collect();
        assert_eq!(labels[0], "draw-hole");
        assert!(labels.contains(&"draw"), "{labels:?}");
        assert!(
            !labels.contains(&"dr"),
            "the word being typed is no candidate: {labels:?}"
        );
        let s = snap(&mut it, "(setq hole-count 3)\n(princ ho)");
        let items = completion(&mut it, &s, Position::new(1, 9));
        let labels: Vec<&str> = items.iter().map(|i| i.label.as_str()).collect();
        assert_eq!(labels, ["hole-count"]);
        assert_eq!(items[0].kind, Some(CompletionItemKind::VARIABLE));
    }

    #[test]
    fn symbols_and_folding() {
        let mut it = crate::builtins::new_interp();
        let s = snap(
            &mut it,
            ";; a\n;; b\n(defun f (x)\n  (* x 2))\n(setq y 1 z 2)\n",
        );
        let syms = document_symbols(&mut it, &s);
        let names: Vec<&str> = syms.iter().map(|d| d.name.as_str()).collect();
        assert_eq!(names, ["F", "Y", "Z"]);
        assert_eq!(
            syms[0].selection_range,
            Range::new(Position::new(2, 7), Position::new(2, 8))
        );
        let folds = folding_ranges(&s);
        let spans: Vec<(u32, u32)> = folds.iter().map(|f| (f.start_line, f.end_line)).collect();
        assert_eq!(spans, [(2, 3), (0, 1)]);
    }

    #[test]
    fn uris_round_trip() {
        let p = Path::new("/tmp/a dir/ü.lsp");
        let u = path_to_uri(p).unwrap();
        assert_eq!(u.as_str(), "file:///tmp/a%20dir/%C3%BC.lsp");
        assert_eq!(uri_to_path(&u).unwrap(), p);
    }
}
