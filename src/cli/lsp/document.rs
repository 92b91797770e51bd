//! An open document as the server keeps it between edits: the text, its line starts, and its
//! top-level forms, each read on its own and linted on its own.
//!
//! An edit re-reads only the forms whose text it changed: the text is split into top-level
//! forms lexically (`lex::top_level`, linear and cheap), forms whose text is unchanged keep
//! their read values and lint facts, and only new texts go through the reader. The whole-file
//! lints are then resolved from every form's facts (`lint::resolve`). The answers are those of
//! a full read of the text (`tests::incremental_equals_full_read`).

use std::collections::HashMap;
use std::path::PathBuf;
use std::rc::Rc;

use lsp_types::{Position, Range, TextDocumentContentChangeEvent};

use super::lex;
use crate::cli::analysis::{self, Defun};
use crate::lang::lint::{form_facts, FormFacts};
use crate::lang::reader::{scan, Parsed, ReadError, Scan};
use crate::lang::Interp;

/// A top-level form read on its own: spans and facts are relative to its first byte.
pub struct FormRead {
    pub text: Box<str>,
    pub parsed: Result<Parsed, ReadError>,
    pub facts: Vec<FormFacts>,
}

/// A top-level form of the current text.
#[derive(Clone)]
pub struct Form {
    pub start: usize,
    pub end: usize,
    pub read: Rc<FormRead>,
}

pub struct Document {
    text: String,
    /// The file on disk, when the document has a `file:` URI: `load`s resolve beside it.
    pub path: Option<PathBuf>,
    lines: LineIndex,
    forms: Vec<Form>,
    /// Whether the brackets balance, so that `forms` are those of the text.
    balanced: bool,
    /// The error a full read of the text reports, if any.
    error: Option<ReadError>,
    /// Forms read by the last update (a measure of how incremental it was).
    pub reread: usize,
}

impl Document {
    pub fn new(it: &mut Interp, text: String, path: Option<PathBuf>) -> Document {
        let mut d = Document {
            lines: LineIndex::new(""),
            text: String::new(),
            path,
            forms: Vec::new(),
            balanced: true,
            error: None,
            reread: 0,
        };
        d.set_text(it, text);
        d
    }

    pub fn text(&self) -> &str {
        &self.text
    }

    /// Applies an editor's changes in order: a change with a range replaces that range, one
    /// without replaces the whole text.
    pub fn apply(&mut self, it: &mut Interp, changes: Vec<TextDocumentContentChangeEvent>) {
        let mut text = self.text.clone();
        let mut lines = None::<LineIndex>;
        for c in changes {
            match c.range {
                None => {
                    text = c.text;
                }
                Some(r) => {
                    // Each change's positions refer to the text after the previous one.
                    let idx = lines.get_or_insert_with(|| LineIndex::new(&text));
                    let a = idx.offset(&text, r.start);
                    let b = idx.offset(&text, r.end).max(a);
                    text.replace_range(a..b, &c.text);
                }
            }
            lines = None;
        }
        self.set_text(it, text);
    }

    /// Replaces the text, re-reading the forms whose text is new.
    pub fn set_text(&mut self, it: &mut Interp, text: String) {
        self.text = text;
        self.lines = LineIndex::new(&self.text);
        self.reread = 0;
        self.error = match scan(&self.text) {
            Scan::Complete => None,
            Scan::Incomplete(e) | Scan::Invalid(e) => Some(e),
        };
        // An unbalanced text (a `(` just typed) has no forms; the last ones are kept to be
        // reused once it balances again.
        self.balanced = self.error.is_none();
        if !self.balanced {
            return;
        }
        let old_forms = std::mem::take(&mut self.forms);
        let spans = lex::top_level(&self.text);
        let new_text = |i: usize| &self.text[spans[i].0..spans[i].1];
        let (n, m) = (spans.len(), old_forms.len());
        // The unchanged run at the front and at the back; in between, forms are looked up by
        // text (a form moved elsewhere is not re-read either).
        let mut front = 0;
        while front < n.min(m) && new_text(front) == &*old_forms[front].read.text {
            front += 1;
        }
        let mut back = 0;
        while back < (n - front).min(m - front)
            && new_text(n - 1 - back) == &*old_forms[m - 1 - back].read.text
        {
            back += 1;
        }
        let middle: HashMap<&str, &Rc<FormRead>> = old_forms[front..m - back]
            .iter()
            .map(|f| (&*f.read.text, &f.read))
            .collect();
        let mut forms = Vec::with_capacity(n);
        for (i, &(start, end)) in spans.iter().enumerate() {
            let read = if i < front {
                Rc::clone(&old_forms[i].read)
            } else if i >= n - back {
                Rc::clone(&old_forms[m - (n - i)].read)
            } else if let Some(r) = middle.get(new_text(i)) {
                Rc::clone(r)
            } else {
                self.reread += 1;
                Rc::new(read_form(it, new_text(i)))
            };
            forms.push(Form { start, end, read });
        }
        drop(middle);
        self.forms = forms;
        self.error = first_error(&self.forms);
    }

    /// The error a full read reports, else None.
    pub fn read_error(&self) -> Option<&ReadError> {
        self.error.as_ref()
    }

    /// The top-level forms (none when the brackets do not balance).
    pub fn forms(&self) -> &[Form] {
        if self.balanced {
            &self.forms
        } else {
            &[]
        }
    }

    /// The forms that were read without error, with their start offsets.
    pub fn read_forms(&self) -> impl Iterator<Item = (usize, &Parsed)> {
        self.forms()
            .iter()
            .filter_map(|f| f.read.parsed.as_ref().ok().map(|p| (f.start, p)))
    }

    /// The form whose text contains `offset` (its end included: the cursor may sit there).
    pub fn form_at(&self, offset: usize) -> Option<&Form> {
        let forms = self.forms();
        let i = forms.partition_point(|f| f.end < offset);
        forms
            .get(i)
            .filter(|f| f.start <= offset && offset <= f.end)
    }

    /// The document's defuns in source order, ranges in this text.
    pub fn defuns(&self, it: &Interp) -> Vec<Defun> {
        let mut out = Vec::new();
        for f in self.forms() {
            let Ok(p) = &f.read.parsed else { continue };
            for mut d in analysis::defuns(it, &self.text[f.start..f.end], p) {
                d.form = (d.form.0 + f.start, d.form.1 + f.start);
                d.name_range = (d.name_range.0 + f.start, d.name_range.1 + f.start);
                d.comment = analysis::comment_above(&self.text, d.form.0);
                out.push(d);
            }
        }
        out
    }

    /// Every form's lint facts, with the offset of the form.
    pub fn facts(&self) -> Vec<(u32, &FormFacts)> {
        self.forms()
            .iter()
            .flat_map(|f| f.read.facts.iter().map(|x| (f.start as u32, x)))
            .collect()
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

    pub fn dir(&self) -> PathBuf {
        self.path
            .as_deref()
            .map(crate::cli::run::parent_dir)
            .unwrap_or_else(|| PathBuf::from("."))
    }
}

fn read_form(it: &mut Interp, text: &str) -> FormRead {
    let parsed = analysis::parse(it, text);
    let facts = match &parsed {
        Ok(p) => p
            .forms
            .iter()
            .map(|(v, span)| form_facts(it, &p.spans, v, *span))
            .collect(),
        Err(_) => Vec::new(),
    };
    FormRead {
        text: text.into(),
        parsed,
        facts,
    }
}

/// The error a full read of the text would report: the reader matches the whole grammar before
/// building any value, so the first grammar error wins over an earlier error found while
/// building (a bad dotted pair, a bad escape).
fn first_error(forms: &[Form]) -> Option<ReadError> {
    let shifted = |f: &Form| {
        f.read.parsed.as_ref().err().map(|e| ReadError {
            message: e.message.clone(),
            start: e.start + f.start,
            end: e.end + f.start,
        })
    };
    let grammar = forms.iter().find(|f| {
        f.read
            .parsed
            .as_ref()
            .is_err_and(|e| e.message == crate::lang::reader::GRAMMAR_ERROR)
    });
    grammar
        .or_else(|| forms.iter().find(|f| f.read.parsed.is_err()))
        .and_then(shifted)
}

/// Line starts of a text, to convert byte offsets to LSP positions (UTF-16 columns, the
/// protocol's default encoding) and back.
pub struct LineIndex(Vec<usize>);

impl LineIndex {
    pub fn new(text: &str) -> LineIndex {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        LineIndex(starts)
    }

    pub fn position(&self, text: &str, offset: usize) -> Position {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.0.partition_point(|&s| s <= offset) - 1;
        let start = self.0[line];
        let col: usize = text[start..offset].chars().map(char::len_utf16).sum();
        Position::new(line as u32, col as u32)
    }

    pub fn offset(&self, text: &str, p: Position) -> usize {
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

    pub fn range(&self, text: &str, (start, end): (usize, usize)) -> Range {
        Range::new(self.position(text, start), self.position(text, end))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::analysis::Finding;
    use std::collections::HashSet;
    use std::path::Path;

    /// The findings of a document, as the server publishes them (before ranges become
    /// positions).
    fn incremental(it: &mut Interp, d: &Document) -> Vec<Finding> {
        crate::cli::lsp::features::findings(it, d)
    }

    fn full(it: &mut Interp, text: &str) -> Vec<Finding> {
        let parsed = analysis::parse(it, text);
        analysis::findings(it, text, &parsed, Path::new("."), None, &HashSet::new())
    }

    fn change(d: &Document, (a, b): (usize, usize), text: &str) -> TextDocumentContentChangeEvent {
        TextDocumentContentChangeEvent {
            range: Some(d.range((a, b))),
            range_length: None,
            text: text.into(),
        }
    }

    const BASE: &[&str] = &[
        ";; Adds.\n(defun add (a b / c)\n  (setq c (+ a b))\n  (setq total c))\n",
        "(add 1 2)\n",
        "(add 1)\n",
        "'sym ",
        "\"a \\\"str\\\" ( \" ",
        ";| block ( |;\n",
        "(setq sq (lambda (x) (* x x)))\n",
        "(foreach p '(1 2) (princ p))\n",
        "(dtrr 90)\n",
        "(car)\n",
        "(setq *g* 1 n 2)\n",
        "(defun add (x) x)\n",
        "(if t (progn (setq k 1)) (cond ((= 1 2) (undefined-fn))))\n",
    ];
    const SNIPPETS: &[&str] = &[
        "(",
        ")",
        "\"",
        "'",
        ";",
        "\n",
        " ",
        "x",
        "(g 1)",
        " . ",
        "\\",
        ";|",
        "|;",
        "defun ",
        "(setq q 1)",
        "\u{FEFF}",
        "é",
        "(add 3 4)",
        "",
        "'(",
        "1+",
        "nil",
        "(defun g (y) y)",
    ];

    /// A deterministic stream of pseudo-random numbers (xorshift).
    struct Rng(u64);
    impl Rng {
        fn below(&mut self, n: usize) -> usize {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 % n.max(1) as u64) as usize
        }
    }

    fn boundary(text: &str, mut i: usize) -> usize {
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    }

    #[test]
    fn incremental_equals_full_read() {
        let mut it = crate::builtins::new_interp();
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let mut errors = 0;
        for round in 0..20 {
            let mut text: String = (0..12).map(|_| BASE[rng.below(BASE.len())]).collect();
            let mut d = Document::new(&mut it, text.clone(), None);
            assert_eq!(
                incremental(&mut it, &d),
                full(&mut it, &text),
                "open {text:?}"
            );
            // Edits are undone (last first) as often as made, so that texts keep reading.
            let mut undo: Vec<(usize, usize, String)> = Vec::new();
            for step in 0..40 {
                let (a, b, ins) = match undo.pop() {
                    Some((a, n, removed)) if rng.below(2) == 0 => (a, a + n, removed),
                    top => {
                        undo.extend(top);
                        let a = boundary(&text, rng.below(text.len() + 1));
                        let len = [0, 0, 1, 3, 12][rng.below(5)];
                        let b = boundary(&text, (a + len).min(text.len()));
                        let ins = SNIPPETS[rng.below(SNIPPETS.len())].to_string();
                        undo.push((a, ins.len(), text[a..b].to_string()));
                        (a, b, ins)
                    }
                };
                let c = change(&d, (a, b), &ins);
                text.replace_range(a..b, &ins);
                d.apply(&mut it, vec![c]);
                assert_eq!(d.text(), text);
                let (inc, all) = (incremental(&mut it, &d), full(&mut it, &text));
                assert_eq!(inc, all, "round {round} step {step}: {text:?}");
                errors += usize::from(d.read_error().is_some());
                if let Ok(p) = analysis::parse(&mut it, &text) {
                    assert_eq!(d.defuns(&it), analysis::defuns(&it, &text, &p), "{text:?}");
                }
            }
        }
        // The edits exercise both sides: texts that read and texts that do not.
        assert!(errors > 100 && errors < 700, "{errors} of 800 with errors");
    }

    #[test]
    fn an_edit_inside_one_form_rereads_that_form_only() {
        let mut it = crate::builtins::new_interp();
        let text: String = (0..500)
            .map(|i| {
                format!(";; f{i}\n(defun f{i} (a / b)\n  (setq b (+ a {i}))\n  (setq g{i} b))\n")
            })
            .collect();
        let mut d = Document::new(&mut it, text.clone(), None);
        assert_eq!(d.reread, 500);
        let at = text.find("(+ a 250)").unwrap() + 5;
        d.apply(&mut it, vec![change(&d, (at, at), "7")]);
        assert_eq!(d.reread, 1);
        assert_eq!(incremental(&mut it, &d), full(&mut it, d.text()));
        // Unbalanced for a moment, then closed again: still one form re-read.
        let at = d.text().find("(defun f300").unwrap();
        d.apply(&mut it, vec![change(&d, (at, at), "(")]);
        assert_eq!(d.forms().len(), 0);
        assert!(d.read_error().unwrap().message.contains("never closed"));
        d.apply(&mut it, vec![change(&d, (at, at + 1), "")]);
        assert_eq!((d.forms().len(), d.reread), (500, 0));
        // Several changes in one notification apply in order.
        let (a, b) = (
            d.text().find("f10 ").unwrap(),
            d.text().find("f20 ").unwrap(),
        );
        let first = change(&d, (b, b + 3), "h20");
        let mut after = d.text().to_string();
        after.replace_range(b..b + 3, "h20");
        let second = TextDocumentContentChangeEvent {
            range: Some(LineIndex::new(&after).range(&after, (a, a + 3))),
            range_length: None,
            text: "h10".into(),
        };
        d.apply(&mut it, vec![first, second]);
        assert_eq!(d.reread, 2);
        assert!(d.text().contains("(defun h10 (a / b)") && d.text().contains("(defun h20 "));
        assert_eq!(incremental(&mut it, &d), full(&mut it, d.text()));
    }
}
