//! The language server's answers: pure functions from a document snapshot (its text and path)
//! to diagnostics, hover, completion, definition, symbols and folding ranges. The interpreter
//! passed in is only a symbol table and the builtin library; nothing is evaluated.

use std::collections::{BTreeSet, HashSet};
use std::path::{Path, PathBuf};

use lsp_types::{
    CompletionItem, CompletionItemKind, Diagnostic, DiagnosticSeverity, DocumentSymbol,
    FoldingRange, FoldingRangeKind, Hover, HoverContents, Location, MarkupContent, MarkupKind,
    Position, Range, SymbolKind, Uri,
};

use crate::cli::analysis::{self, Defun};
use crate::lang::lint::Severity;
use crate::lang::{Interp, Value};

/// A document as the editor last sent it.
pub struct Snapshot {
    pub text: String,
    /// The file on disk, when the document has a `file:` URI: `load`s resolve beside it.
    pub path: Option<PathBuf>,
    lines: LineIndex,
}

impl Snapshot {
    pub fn new(text: String, path: Option<PathBuf>) -> Snapshot {
        let lines = LineIndex::new(&text);
        Snapshot { text, path, lines }
    }

    pub fn position(&self, offset: usize) -> Position {
        self.lines.position(&self.text, offset)
    }

    pub fn offset(&self, p: Position) -> usize {
        self.lines.offset(&self.text, p)
    }

    pub fn range(&self, (start, end): (usize, usize)) -> Range {
        Range::new(self.position(start), self.position(end))
    }

    fn dir(&self) -> PathBuf {
        self.path
            .as_deref()
            .map(crate::cli::run::parent_dir)
            .unwrap_or_else(|| PathBuf::from("."))
    }
}

/// Line starts of a text, to convert byte offsets to LSP positions (UTF-16 columns, the
/// protocol's default encoding) and back.
struct LineIndex(Vec<usize>);

impl LineIndex {
    fn new(text: &str) -> LineIndex {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        LineIndex(starts)
    }

    fn position(&self, text: &str, offset: usize) -> Position {
        let offset = offset.min(text.len());
        let line = self.0.partition_point(|&s| s <= offset) - 1;
        let start = self.0[line];
        let col: usize = text[start..offset].chars().map(char::len_utf16).sum();
        Position::new(line as u32, col as u32)
    }

    fn offset(&self, text: &str, p: Position) -> usize {
        let Some(&start) = self.0.get(p.line as usize) else {
            return text.len();
        };
        let mut units = 0;
        for (i, c) in text[start..].char_indices() {
            if units >= p.character as usize || c == '\n' {
                return start + i;
            }
            units += c.len_utf16();
        }
        text.len()
    }
}

/// Reader errors and `check` lints of the snapshot.
pub fn diagnostics(it: &mut Interp, snap: &Snapshot) -> Vec<Diagnostic> {
    let parsed = analysis::parse(it, &snap.text);
    let found = analysis::findings(
        it,
        &snap.text,
        &parsed,
        &snap.dir(),
        snap.path.as_deref(),
        &HashSet::new(),
    );
    found
        .into_iter()
        .map(|f| Diagnostic {
            range: f.range.map_or_else(Range::default, |r| snap.range(r)),
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

/// The defun of `name` in the snapshot, else in the files it loads (first definition wins,
/// as the file is read top to bottom).
fn find_defun(it: &mut Interp, snap: &Snapshot, name: &str) -> Option<Found> {
    let parsed = analysis::parse(it, &snap.text).ok()?;
    if let Some(d) = analysis::defuns(it, &snap.text, &parsed)
        .into_iter()
        .find(|d| d.name.eq_ignore_ascii_case(name))
    {
        return Some(Found {
            defun: d,
            file: None,
            text: None,
        });
    }
    let mut seen: HashSet<PathBuf> = snap
        .path
        .iter()
        .filter_map(|p| p.canonicalize().ok())
        .collect();
    analysis::loaded(it, &snap.dir(), &parsed, &mut seen)
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

/// A builtin's signature and doc, or a user defun's parameter list and the comment above it.
pub fn hover(it: &mut Interp, snap: &Snapshot, pos: Position) -> Option<Hover> {
    let (start, end, word) = analysis::word_at(&snap.text, snap.offset(pos))?;
    let value = if let Some(b) = crate::builtins::find(word) {
        format!("```lisp\n{}\n```\n{}", b.sig, b.doc)
    } else {
        let f = find_defun(it, snap, word)?;
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
    };
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value,
        }),
        range: Some(snap.range((start, end))),
    })
}

/// Where a function is defined: this document or a file it loads.
pub fn definition(it: &mut Interp, snap: &Snapshot, uri: &Uri, pos: Position) -> Option<Location> {
    let (_, _, word) = analysis::word_at(&snap.text, snap.offset(pos))?;
    let f = find_defun(it, snap, word)?;
    match (f.file, f.text) {
        (Some(file), Some(text)) => {
            let other = Snapshot::new(text, None);
            Some(Location::new(
                path_to_uri(&file)?,
                other.range(f.defun.name_range),
            ))
        }
        _ => Some(Location::new(uri.clone(), snap.range(f.defun.name_range))),
    }
}

/// Builtins and the document's own symbols (defuns, variables) starting with the word being
/// typed; lower case, as AutoLISP code is usually written.
pub fn completion(it: &mut Interp, snap: &Snapshot, pos: Position) -> Vec<CompletionItem> {
    let offset = snap.offset(pos);
    let prefix = analysis::word_at(&snap.text, offset)
        .filter(|(s, _, _)| *s < offset)
        .map(|(s, _, _)| snap.text[s..offset].to_lowercase())
        .unwrap_or_default();
    let mut items = Vec::new();
    let mut seen = HashSet::new();
    let defuns = analysis::parse(it, &snap.text)
        .map(|p| analysis::defuns(it, &snap.text, &p))
        .unwrap_or_default();
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
    let word_here = analysis::word_at(&snap.text, offset).map(|(s, e, _)| (s, e));
    for (s, e) in symbol_tokens(&snap.text) {
        if Some((s, e)) == word_here {
            continue;
        }
        let label = snap.text[s..e].to_lowercase();
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
pub fn document_symbols(it: &mut Interp, snap: &Snapshot) -> Vec<DocumentSymbol> {
    let Ok(parsed) = analysis::parse(it, &snap.text) else {
        return Vec::new();
    };
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
    let mut out: Vec<(usize, DocumentSymbol)> = analysis::defuns(it, &snap.text, &parsed)
        .into_iter()
        .map(|d| {
            let s = symbol(
                d.name.clone(),
                Some(d.signature()),
                SymbolKind::FUNCTION,
                snap.range(d.form),
                snap.range(d.name_range),
            );
            (d.form.0, s)
        })
        .collect();
    let setq = it.syms.lookup("SETQ");
    for (f, span) in &parsed.forms {
        if setq.is_none() || f.car().as_sym() != setq {
            continue;
        }
        let range = snap.range((span.start as usize, span.end as usize));
        for (i, v) in f.cdr().iter().enumerate() {
            if let (0, Value::Sym(s)) = (i % 2, v) {
                let name = it.syms.name(*s).to_string();
                out.push((
                    span.start as usize,
                    symbol(name, None, SymbolKind::VARIABLE, range, range),
                ));
            }
        }
    }
    out.sort_by_key(|(at, _)| *at);
    out.into_iter().map(|(_, s)| s).collect()
}

/// Every list spanning several lines folds, and so does a run of comment lines.
pub fn folding_ranges(it: &mut Interp, snap: &Snapshot) -> Vec<FoldingRange> {
    let mut lines: BTreeSet<(u32, u32)> = BTreeSet::new();
    if let Ok(parsed) = analysis::parse(it, &snap.text) {
        let mut stack: Vec<&Value> = parsed.forms.iter().map(|(f, _)| f).collect();
        while let Some(v) = stack.pop() {
            if let Some(s) = parsed.spans.get(v) {
                let (a, b) = (
                    snap.position(s.start as usize).line,
                    snap.position(s.end as usize).line,
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
    for (n, l) in snap.text.lines().chain(std::iter::once("")).enumerate() {
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

    fn snap(text: &str) -> Snapshot {
        Snapshot::new(text.to_string(), None)
    }

    #[test]
    fn positions_count_utf16_units() {
        let s = snap("(a)\n(\"é𝄞\" b)\n");
        let b = s.text.find(" b").unwrap() + 1;
        // ( " é 𝄞 " space: 1 + 1 + 1 + 2 (a surrogate pair) + 1 + 1 units.
        assert_eq!(s.position(b), Position::new(1, 7));
        assert_eq!(s.offset(Position::new(1, 7)), b);
        assert_eq!(s.offset(Position::new(9, 0)), s.text.len());
    }

    #[test]
    fn hover_shows_builtin_doc_and_user_defun_comment() {
        let mut it = crate::builtins::new_interp();
        let s = snap(";; Degrees to radians.\n(defun dtr (a) (* pi (/ a 180.0)))\n(dtr 90)\n(polar '(0 0) 0 1)\n");
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
        let s = snap("(defun draw-hole (r) r)\n(setq hole-count 3)\n(dr)");
        let items = completion(&mut it, &s, Position::new(2, 3));
        let labels: Vec<&str> = items.iter().map(|i| i.label.as_str()).collect();
        assert_eq!(labels[0], "draw-hole");
        assert!(labels.contains(&"draw"), "{labels:?}");
        assert!(
            !labels.contains(&"dr"),
            "the word being typed is no candidate: {labels:?}"
        );
        let s = snap("(setq hole-count 3)\n(princ ho)");
        let items = completion(&mut it, &s, Position::new(1, 9));
        let labels: Vec<&str> = items.iter().map(|i| i.label.as_str()).collect();
        assert_eq!(labels, ["hole-count"]);
        assert_eq!(items[0].kind, Some(CompletionItemKind::VARIABLE));
    }

    #[test]
    fn symbols_and_folding() {
        let mut it = crate::builtins::new_interp();
        let s = snap(";; a\n;; b\n(defun f (x)\n  (* x 2))\n(setq y 1 z 2)\n");
        let syms = document_symbols(&mut it, &s);
        let names: Vec<&str> = syms.iter().map(|d| d.name.as_str()).collect();
        assert_eq!(names, ["F", "Y", "Z"]);
        assert_eq!(
            syms[0].selection_range,
            Range::new(Position::new(2, 7), Position::new(2, 8))
        );
        let folds = folding_ranges(&mut it, &s);
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
