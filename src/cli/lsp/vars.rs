//! Variables under the cursor: a parameter or declared local of the defun (or lambda) around
//! it, a `foreach` loop variable, or a global that `setq` sets somewhere in the document
//! (outside every function that binds the name).

use super::document::Document;
use super::lex;
use crate::lang::error::Span;
use crate::lang::reader::Parsed;
use crate::lang::symbols::{S_DEFUN, S_DEFUN_Q, S_FOREACH, S_LAMBDA, S_QUOTE, S_SETQ, S_SLASH};
use crate::lang::{Interp, Sym, Value};

/// How a name is bound where it is used.
#[derive(Debug, PartialEq)]
pub enum Binding {
    /// A parameter, or a local declared after `/`, of `owner` (a defun's name, or None for a
    /// lambda inside `within`). `at` is where the argument list names it.
    Param {
        owner: Option<String>,
        within: Option<String>,
        local: bool,
        /// The argument list as written, e.g. `(w h / total)`.
        arglist: String,
        at: (usize, usize),
    },
    /// The variable of a `foreach` (inside the defun `within`, if any).
    Loop {
        within: Option<String>,
        at: (usize, usize),
    },
    /// A global: where `setq` sets it, each in the defun it sits in (None at top level).
    Global {
        sets: Vec<((usize, usize), Option<String>)>,
    },
}

/// The binding of `name` for a use at `offset`: the innermost function or `foreach` around the
/// cursor that binds it, else the document's global `setq`s of it. None when it is neither.
pub fn binding(it: &Interp, doc: &Document, offset: usize, name: &str) -> Option<Binding> {
    let sym = it.syms.lookup(name)?;
    local(it, doc, offset, sym).or_else(|| {
        let sets = global_sets(it, doc, sym);
        (!sets.is_empty()).then_some(Binding::Global { sets })
    })
}

fn local(it: &Interp, doc: &Document, offset: usize, sym: Sym) -> Option<Binding> {
    let form = doc.form_at(offset)?;
    let Ok(p) = &form.read.parsed else {
        return None;
    };
    let mut w = Local {
        it,
        p,
        text: &doc.text()[form.start..form.end],
        at: offset - form.start,
        sym,
        found: None,
    };
    for (v, _) in &p.forms {
        w.visit(v, None, 0);
    }
    w.found.map(|b| shift(b, form.start))
}

fn shift(b: Binding, by: usize) -> Binding {
    let s = |(a, e): (usize, usize)| (a + by, e + by);
    match b {
        Binding::Param {
            owner,
            within,
            local,
            arglist,
            at,
        } => Binding::Param {
            owner,
            within,
            local,
            arglist,
            at: s(at),
        },
        Binding::Loop { within, at } => Binding::Loop { within, at: s(at) },
        g => g,
    }
}

/// The descent from a top-level form to the cursor, keeping the innermost binder of `sym`.
struct Local<'a> {
    it: &'a Interp,
    p: &'a Parsed,
    /// The form's text, and the cursor relative to it.
    text: &'a str,
    at: usize,
    sym: Sym,
    found: Option<Binding>,
}

impl Local<'_> {
    fn contains(&self, v: &Value) -> Option<Span> {
        self.p
            .spans
            .get(v)
            .filter(|s| s.start as usize <= self.at && self.at <= s.end as usize)
    }

    /// Where the `i`th item of the list `v` is written.
    fn item(&self, v: &Value, i: usize) -> Option<(usize, usize)> {
        let s = self.p.spans.get(v)?;
        lex::list_items(self.text, s.start as usize).get(i).copied()
    }

    fn visit(&mut self, v: &Value, defun: Option<Sym>, depth: usize) {
        let Value::Cons(c) = v else { return };
        if depth > 500 || self.contains(v).is_none() {
            return;
        }
        let name = |s: Option<Sym>| s.map(|s| self.it.syms.name(s).to_string());
        let mut inner = defun;
        match c.car.as_sym() {
            Some(S_QUOTE) => return,
            Some(h @ (S_DEFUN | S_DEFUN_Q | S_LAMBDA)) => {
                let (owner, arglist) = if h == S_LAMBDA {
                    (None, c.cdr.car())
                } else {
                    inner = c.cdr.car().as_sym();
                    (inner, c.cdr.cdr().car())
                };
                let names: Vec<Option<Sym>> = arglist.iter().map(Value::as_sym).collect();
                if let Some(i) = names.iter().position(|s| *s == Some(self.sym)) {
                    let slash = names.iter().position(|s| *s == Some(S_SLASH));
                    let at = self.item(&arglist, i).unwrap_or_default();
                    self.found = Some(Binding::Param {
                        owner: name(owner),
                        within: if h == S_LAMBDA { name(defun) } else { None },
                        local: slash.is_some_and(|s| s < i),
                        arglist: self
                            .p
                            .spans
                            .get(&arglist)
                            .map(|s| self.text[s.start as usize..s.end as usize].to_string())
                            .unwrap_or_default(),
                        at,
                    });
                }
            }
            Some(S_FOREACH) if c.cdr.car().as_sym() == Some(self.sym) => {
                self.found = Some(Binding::Loop {
                    within: name(defun),
                    at: self.item(v, 1).unwrap_or_default(),
                });
            }
            _ => {}
        }
        for x in v.iter() {
            self.visit(x, inner, depth + 1);
        }
    }
}

/// The `setq`s of `sym` in the document outside every function binding it: where the name is
/// written in each, and the defun around it.
fn global_sets(it: &Interp, doc: &Document, sym: Sym) -> Vec<((usize, usize), Option<String>)> {
    let mut out = Vec::new();
    for (start, p) in doc.read_forms() {
        let text = &doc.text()[start..];
        let mut found = Vec::new();
        for (v, _) in &p.forms {
            sets_in(v, sym, false, None, &mut found, 0);
        }
        for (setq, i, defun) in found {
            let Some(span) = p.spans.get(&setq) else {
                continue;
            };
            let Some(&(a, b)) = lex::list_items(text, span.start as usize).get(i + 1) else {
                continue;
            };
            out.push((
                (a + start, b + start),
                defun.map(|d| it.syms.name(d).to_string()),
            ));
        }
    }
    out
}

/// Collects (setq form, index of the argument naming `sym`, enclosing defun).
fn sets_in(
    v: &Value,
    sym: Sym,
    bound: bool,
    defun: Option<Sym>,
    out: &mut Vec<(Value, usize, Option<Sym>)>,
    depth: usize,
) {
    let Value::Cons(c) = v else { return };
    if depth > 500 {
        return;
    }
    let binds = |arglist: Value| arglist.iter().any(|a| a.as_sym() == Some(sym));
    let (mut bound, mut defun) = (bound, defun);
    match c.car.as_sym() {
        Some(S_QUOTE) => return,
        Some(S_DEFUN | S_DEFUN_Q) => {
            defun = c.cdr.car().as_sym();
            bound |= binds(c.cdr.cdr().car());
        }
        Some(S_LAMBDA) => bound |= binds(c.cdr.car()),
        Some(S_FOREACH) => bound |= c.cdr.car().as_sym() == Some(sym),
        Some(S_SETQ) if !bound => {
            for (i, a) in c.cdr.iter().enumerate() {
                if i % 2 == 0 && a.as_sym() == Some(sym) {
                    out.push((v.clone(), i, defun));
                }
            }
        }
        _ => {}
    }
    for x in v.iter() {
        sets_in(x, sym, bound, defun, out, depth + 1);
    }
}
