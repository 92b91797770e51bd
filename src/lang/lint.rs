//! `lispcad check`: static checks on read (not evaluated) code — global leaks from `setq` inside
//! a `defun`, wrong argument counts to builtins, calls of functions defined nowhere.

use std::collections::{HashMap, HashSet};

use super::error::Span;
use super::reader::{Parsed, SpanMap};
use super::symbols::*;
use super::value::{Sym, Value};
use super::Interp;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
}

#[derive(Clone, Debug)]
pub struct Lint {
    pub severity: Severity,
    pub message: String,
    pub span: Option<Span>,
}

/// A function a form defines, in source order: `defun` with its parameter count, or `setq` of
/// a lambda (whose arity is not tracked: the name may be set to other lambdas).
#[derive(Clone, Debug)]
struct Def {
    name: Sym,
    params: Option<usize>,
}

/// A finding-to-be of one form, decided once the whole file's functions are known.
#[derive(Clone, Debug)]
enum Event {
    /// A call of `f` with `n` arguments; `in_scope` when `f` is a parameter or local there.
    Call {
        f: Sym,
        n: usize,
        in_scope: bool,
        span: Option<Span>,
    },
    /// A `setq` of `sym` inside `defun` that binds it nowhere.
    Leak {
        defun: Sym,
        sym: Sym,
        span: Option<Span>,
    },
}

/// What the lints need to know of one top-level form, read on its own: the functions it
/// defines, its calls and leaking `setq`s in walk order, the files it loads. The whole-file
/// lints (undefined functions, arities, one leak warning per symbol and function) are decided
/// by `resolve` from these, so an editor re-reads and re-walks only the forms an edit touched.
#[derive(Clone, Debug, Default)]
pub struct FormFacts {
    defs: Vec<Def>,
    events: Vec<Event>,
    /// Literal file names of `(load "name" ...)` forms in it.
    pub loads: Vec<String>,
}

/// Lints every form of a parsed source, against the builtins of `it`.
pub fn lint(it: &Interp, parsed: &Parsed) -> Vec<Lint> {
    lint_with(it, parsed, &HashSet::new())
}

/// The facts of each form of a parsed source, in order.
fn all_facts(it: &Interp, parsed: &Parsed) -> Vec<FormFacts> {
    parsed
        .forms
        .iter()
        .map(|(f, span)| form_facts(it, &parsed.spans, f, *span))
        .collect()
}

/// The functions a source defines (`defun`, `defun-q`, `setq` of a lambda), for linting the
/// files that use them.
pub fn defined_functions(parsed: &Parsed) -> HashSet<Sym> {
    let mut defs = Vec::new();
    for (f, _) in &parsed.forms {
        collect_defuns(f, &mut defs, 0);
    }
    defs.into_iter().map(|d| d.name).collect()
}

/// The literal file names of `(load "name" ...)` forms anywhere in a source.
pub fn loaded_files(parsed: &Parsed, syms: &super::symbols::SymbolTable) -> Vec<String> {
    let load = syms.lookup("LOAD");
    let mut out = Vec::new();
    for (f, _) in &parsed.forms {
        collect_loads(f, load, &mut out, 0);
    }
    out
}

fn collect_loads(v: &Value, load: Option<Sym>, out: &mut Vec<String>, depth: usize) {
    let Value::Cons(c) = v else { return };
    if depth > 200 {
        return;
    }
    if load.is_some() && c.car.as_sym() == load {
        if let Some(name) = c.cdr.car().as_str() {
            out.push(name.to_string());
        }
    }
    for x in v.iter() {
        collect_loads(x, load, out, depth + 1);
    }
}

/// Lints a source knowing that `known` functions are defined elsewhere (files checked together,
/// files it loads).
pub fn lint_with(it: &Interp, parsed: &Parsed, known: &HashSet<Sym>) -> Vec<Lint> {
    let facts = all_facts(it, parsed);
    let forms: Vec<(u32, &FormFacts)> = facts.iter().map(|f| (0, f)).collect();
    resolve(it, &forms, known)
}

/// The facts of one top-level form; `spans` holds the spans of its lists, `span` its own.
pub fn form_facts(it: &Interp, spans: &SpanMap, form: &Value, span: Span) -> FormFacts {
    let mut cx = Walk {
        it,
        spans,
        facts: FormFacts::default(),
    };
    collect_defuns(form, &mut cx.facts.defs, 0);
    collect_loads(form, it.syms.lookup("LOAD"), &mut cx.facts.loads, 0);
    cx.walk(form, &mut Vec::new(), None, Some(span), 0);
    cx.facts
}

/// The lints of a file from the facts of its forms, in order, each with the byte offset to add
/// to its spans (where that form was read from); `known` as in `lint_with`.
pub fn resolve(it: &Interp, forms: &[(u32, &FormFacts)], known: &HashSet<Sym>) -> Vec<Lint> {
    let mut defined = known.clone();
    let mut arity: HashMap<Sym, Option<usize>> = HashMap::new();
    for d in forms.iter().flat_map(|(_, f)| &f.defs) {
        defined.insert(d.name);
        match d.params {
            Some(p) => {
                let e = arity.entry(d.name).or_insert(Some(p));
                if *e != Some(p) {
                    *e = None;
                }
            }
            None => {
                arity.insert(d.name, None);
            }
        }
    }
    // A function also defined in another file may have another parameter list there.
    for s in known {
        if arity.contains_key(s) {
            arity.insert(*s, None);
        }
    }
    let mut cx = Resolve {
        it,
        defined,
        arity,
        leaked: HashSet::new(),
        out: Vec::new(),
    };
    for (shift, f) in forms {
        let at = |span: &Option<Span>| {
            span.map(|s| Span {
                src: s.src,
                start: s.start + shift,
                end: s.end + shift,
            })
        };
        for e in &f.events {
            match e {
                Event::Call {
                    f,
                    n,
                    in_scope,
                    span,
                } => cx.check_call(*f, *n, *in_scope, at(span)),
                Event::Leak { defun, sym, span } => cx.leak(*defun, *sym, at(span)),
            }
        }
    }
    cx.out
}

fn collect_defuns(f: &Value, out: &mut Vec<Def>, depth: usize) {
    if depth > 200 {
        return;
    }
    if let Value::Cons(c) = f {
        if matches!(c.car.as_sym(), Some(S_DEFUN | S_DEFUN_Q)) {
            if let Some(n) = c.cdr.car().as_sym() {
                let params = c
                    .cdr
                    .cdr()
                    .car()
                    .iter()
                    .take_while(|p| p.as_sym() != Some(S_SLASH))
                    .count();
                out.push(Def {
                    name: n,
                    params: Some(params),
                });
            }
        }
        // (setq name (lambda ...)) or (setq name (function (lambda ...))) defines name too.
        if c.car.as_sym() == Some(S_SETQ) {
            let args: Vec<Value> = c.cdr.iter().cloned().collect();
            for pair in args.chunks(2) {
                if let [Value::Sym(n), v] = pair {
                    let head = v.car().as_sym();
                    let is_fn = head == Some(S_LAMBDA)
                        || head == Some(S_FUNCTION)
                            && v.cdr().car().car().as_sym() == Some(S_LAMBDA);
                    if is_fn {
                        out.push(Def {
                            name: *n,
                            params: None,
                        });
                    }
                }
            }
        }
        if c.car.as_sym() == Some(S_QUOTE) {
            return;
        }
        for x in f.iter() {
            collect_defuns(x, out, depth + 1);
        }
    }
}

/// `*name*` marks a global on purpose (the common AutoLISP convention): no leak warning.
fn is_earmuffed(name: &str) -> bool {
    name.len() > 2 && name.starts_with('*') && name.ends_with('*')
}

/// Parameters and locals of `(args / locals)`.
fn arglist_syms(v: &Value) -> Vec<Sym> {
    v.iter()
        .filter_map(Value::as_sym)
        .filter(|s| *s != S_SLASH)
        .collect()
}

/// The walk of one form, recording its events.
struct Walk<'a> {
    it: &'a Interp,
    spans: &'a SpanMap,
    facts: FormFacts,
}

impl Walk<'_> {
    fn walk(
        &mut self,
        form: &Value,
        scope: &mut Vec<Sym>,
        defun: Option<Sym>,
        outer: Option<Span>,
        depth: usize,
    ) {
        let Value::Cons(c) = form else { return };
        if depth > 500 {
            return;
        }
        let span = self.spans.get(form).or(outer);
        let args: Vec<&Value> = c.cdr.iter().collect();
        let Some(head) = c.car.as_sym() else {
            for x in form.iter() {
                self.walk(x, scope, defun, span, depth + 1);
            }
            return;
        };
        match head {
            S_QUOTE => {}
            S_DEFUN | S_DEFUN_Q | S_LAMBDA => {
                let (name, def) = if head == S_LAMBDA {
                    (defun, c.cdr.clone())
                } else {
                    (c.cdr.car().as_sym(), c.cdr.cdr())
                };
                let mark = scope.len();
                scope.extend(arglist_syms(&def.car()));
                for x in def.cdr().iter() {
                    self.walk(x, scope, name, span, depth + 1);
                }
                scope.truncate(mark);
            }
            S_SETQ => {
                for (i, x) in args.iter().enumerate() {
                    if i % 2 == 0 {
                        if let (Some(s), Some(f)) = (x.as_sym(), defun) {
                            if !scope.contains(&s) && !is_earmuffed(self.it.syms.name(s)) {
                                self.facts.events.push(Event::Leak {
                                    defun: f,
                                    sym: s,
                                    span,
                                });
                            }
                        }
                    } else {
                        self.walk(x, scope, defun, span, depth + 1);
                    }
                }
            }
            S_FOREACH => {
                let mark = scope.len();
                if let Some(v) = args.first().and_then(|v| v.as_sym()) {
                    scope.push(v);
                }
                for x in args.iter().skip(1) {
                    self.walk(x, scope, defun, span, depth + 1);
                }
                scope.truncate(mark);
            }
            S_COND => {
                for clause in &args {
                    for x in clause.iter() {
                        self.walk(x, scope, defun, span, depth + 1);
                    }
                }
            }
            S_IF | S_PROGN | S_WHILE | S_REPEAT | S_AND | S_OR | S_FUNCTION => {
                for x in &args {
                    self.walk(x, scope, defun, span, depth + 1);
                }
            }
            _ => {
                self.facts.events.push(Event::Call {
                    f: head,
                    n: args.len(),
                    in_scope: scope.contains(&head),
                    span,
                });
                for x in &args {
                    self.walk(x, scope, defun, span, depth + 1);
                }
            }
        }
    }
}

/// The whole-file state the events are decided against.
struct Resolve<'a> {
    it: &'a Interp,
    defined: HashSet<Sym>,
    /// Parameter counts of the file's defuns; None when a name is defined with two counts.
    arity: HashMap<Sym, Option<usize>>,
    /// (function, symbol) leaks already reported: one warning per symbol per defun.
    leaked: HashSet<(Sym, Sym)>,
    out: Vec<Lint>,
}

impl Resolve<'_> {
    /// The function name nearest to a misspelt one: the file's defuns and the builtins.
    fn suggest(&self, name: &str) -> Option<String> {
        let own = self.defined.iter().map(|s| self.it.syms.name(*s));
        nearest(name, own.chain(function_names(self.it))).map(str::to_uppercase)
    }

    fn push(&mut self, severity: Severity, message: String, span: Option<Span>) {
        self.out.push(Lint {
            severity,
            message,
            span,
        });
    }

    fn leak(&mut self, f: Sym, s: Sym, span: Option<Span>) {
        if self.leaked.insert((f, s)) {
            let (sn, fname) = (self.it.syms.name(s), self.it.syms.name(f));
            self.push(
                Severity::Warning,
                format!("setq of {sn} in {fname}: {sn} is neither a parameter nor a declared local, so it leaks into the global scope (add it after / in the argument list)"),
                span,
            );
        }
    }

    fn check_call(&mut self, f: Sym, n: usize, in_scope: bool, span: Option<Span>) {
        let name = self.it.syms.name(f).to_string();
        match &self.it.values.get(f.idx()) {
            Some(Value::Subr(b)) if !self.defined.contains(&f) => {
                if n < b.min as usize {
                    self.push(
                        Severity::Error,
                        format!(
                            "too few arguments: ({}) takes at least {}, given {n}; usage {}",
                            b.name, b.min, b.sig
                        ),
                        span,
                    );
                } else if n > b.max as usize {
                    self.push(
                        Severity::Error,
                        format!(
                            "too many arguments: ({}) takes at most {}, given {n}; usage {}",
                            b.name, b.max, b.sig
                        ),
                        span,
                    );
                }
            }
            Some(Value::Subr(_)) => {}
            _ if self.defined.contains(&f) => {
                if let Some(Some(params)) = self.arity.get(&f) {
                    if n != *params {
                        let few = if n < *params { "few" } else { "many" };
                        self.push(
                            Severity::Warning,
                            format!("too {few} arguments: ({name}) is defined with {params} parameter(s), called with {n}"),
                            span,
                        );
                    }
                }
            }
            _ => {
                if !in_scope {
                    let hint = self
                        .suggest(&name)
                        .map(|s| format!("; did you mean {s}?"))
                        .unwrap_or_default();
                    self.push(
                        Severity::Warning,
                        format!("call of undefined function {name}: no defun for it in this file and no builtin of that name{hint}"),
                        span,
                    );
                }
            }
        }
    }
}

/// The run of `;` comment lines ending on the line above `offset`, semicolons and one space
/// stripped (`;;; Draws a hole` reads "Draws a hole"): a defun's documentation by convention.
pub fn comment_above(text: &str, offset: usize) -> String {
    let offset = offset.min(text.len());
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let mut lines: Vec<&str> = Vec::new();
    for l in text[..line_start].lines().rev() {
        match l.trim().strip_prefix(';') {
            Some(rest) if !rest.starts_with('|') => lines.push(rest.trim_start_matches(';').trim()),
            _ => break,
        }
    }
    lines.reverse();
    lines.join("\n").trim().to_string()
}

/// Help for a user function: `(NAME params / locals)` and the comment above its latest `defun`
/// among the sources read (files, REPL entries), else "a user function". None when `name` is
/// not bound to a user function.
pub fn user_help(it: &mut Interp, name: &str) -> Option<String> {
    let sym = it.syms.lookup(name)?;
    let Some(Value::Func(l)) = it.values.get(sym.idx()) else {
        return None;
    };
    let args = it.prin1_string(&l.source.car());
    let shown = it.syms.name(sym).to_string();
    let sig = if args == "nil" {
        format!("({shown})")
    } else {
        format!(
            "({shown} {})",
            args.trim_start_matches('(').trim_end_matches(')')
        )
    };
    let want = name.to_ascii_lowercase();
    let texts: Vec<std::sync::Arc<str>> = it.sources.iter().map(|s| s.text.clone()).collect();
    let mut doc = None;
    for (i, text) in texts.iter().enumerate().rev() {
        if !text.to_ascii_lowercase().contains(&want) {
            continue;
        }
        let Ok(parsed) = super::reader::read_source(text, 0, &mut it.syms) else {
            continue;
        };
        let found = parsed.forms.iter().rev().find(|(f, _)| {
            matches!(f.car().as_sym(), Some(S_DEFUN)) && f.cdr().car().as_sym() == Some(sym)
        });
        if let Some((_, span)) = found {
            let start = span.start as usize;
            let mut d = comment_above(text, start);
            // At a REPL, the comment is typically its own entry just before the defun's.
            if d.is_empty() && text[..start].trim().is_empty() && i > 0 {
                let prev = format!("{}\n", texts[i - 1].trim_end());
                if prev
                    .lines()
                    .all(|l| l.trim().is_empty() || l.trim_start().starts_with(';'))
                {
                    d = comment_above(&prev, prev.len());
                }
            }
            doc = Some(d);
            break;
        }
    }
    it.sync_cells();
    let doc = doc
        .filter(|d| !d.is_empty())
        .unwrap_or_else(|| "a user function".into());
    Some(format!("{sig}\n  {}", doc.replace('\n', "\n  ")))
}

/// The names bound to functions in an interpreter: builtins and loaded defuns.
pub fn function_names(it: &Interp) -> impl Iterator<Item = &str> {
    it.syms.all().filter_map(|(s, n)| {
        matches!(
            it.values.get(s.idx()),
            Some(Value::Subr(_) | Value::Func(_))
        )
        .then_some(n)
    })
}

/// The candidate closest to `name` by edit distance (case-insensitive), if close enough to be
/// a likely typo: at most one edit for short names, a third of the length for longer ones.
/// Ties go to the alphabetically first, so the answer does not depend on table order.
pub fn nearest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let want = name.to_lowercase();
    let limit = (want.chars().count() / 3).max(1);
    let mut best: Option<(usize, String, &'a str)> = None;
    for c in candidates {
        let lc = c.to_lowercase();
        if lc == want || lc.is_empty() {
            continue;
        }
        let d = strsim::damerau_levenshtein(&want, &lc);
        if d > limit {
            continue;
        }
        let better = match &best {
            None => true,
            Some((bd, bl, _)) => d < *bd || (d == *bd && lc < *bl),
        };
        if better {
            best = Some((d, lc, c));
        }
    }
    best.map(|(_, _, c)| c)
}

#[cfg(test)]
mod tests {
    use super::nearest;

    #[test]
    fn nearest_finds_typos_and_ignores_strangers() {
        let names = ["dtr", "rtd", "distance", "strcat", "setq"];
        assert_eq!(nearest("DTRR", names.iter().copied()), Some("dtr"));
        assert_eq!(nearest("distnace", names.iter().copied()), Some("distance"));
        assert_eq!(nearest("strcta", names.iter().copied()), Some("strcat"));
        assert_eq!(nearest("frobnicate", names.iter().copied()), None);
        // Equally near: the alphabetically first wins.
        assert_eq!(nearest("xtr", names.iter().copied()), Some("dtr"));
    }
}
