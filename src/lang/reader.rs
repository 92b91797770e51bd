//! The reader: source text to values, with the span of every list kept on the side so the
//! compiler can point diagnostics at the user's source.
//!
//! Parsing is the pest grammar in `grammar/lispcad.pest`. Before it runs, a small structural
//! scan (`scan`) checks bracket balance, strings and nesting depth: it reports an unclosed `(`
//! at the `(` itself (pest alone would report the end of file), bounds the nesting so hostile
//! input cannot exhaust the stack, and tells the REPL whether an entry is complete.

use pest::iterators::Pair;
use pest::Parser;

use super::error::Span;
use super::symbols::{SymbolTable, S_QUOTE};
use super::value::{Cons, Value};

#[derive(pest_derive::Parser)]
#[grammar = "../grammar/lispcad.pest"]
struct LispParser;

/// The deepest list nesting the reader accepts.
pub const MAX_NESTING: usize = 2_000;

/// Where each list read from source starts and ends, by cons-cell identity. Keyed by address
/// and never iterated, so FxHash: std's RandomState asked the kernel for keys (a system call
/// per run) and SipHashed each list read.
#[derive(Default)]
pub struct SpanMap {
    map: rustc_hash::FxHashMap<*const Cons, Span>,
}

impl SpanMap {
    pub fn get(&self, v: &Value) -> Option<Span> {
        match v {
            Value::Cons(c) => self.map.get(&c.as_ptr()).copied(),
            _ => None,
        }
    }
}

/// The forms of a source, each with its span, and the spans of every list inside them.
/// Holding the forms keeps the cons cells (the span map's keys) alive.
pub struct Parsed {
    pub forms: Vec<(Value, Span)>,
    pub spans: SpanMap,
}

#[derive(Debug, Clone, PartialEq)]
pub struct ReadError {
    pub message: String,
    pub start: usize,
    pub end: usize,
}

/// The result of the structural scan.
#[derive(Debug, Clone, PartialEq)]
pub enum Scan {
    Complete,
    /// More input is needed (an open list or string); the REPL keeps reading.
    Incomplete(ReadError),
    Invalid(ReadError),
}

/// Checks brackets, strings and nesting without building anything.
pub fn scan(text: &str) -> Scan {
    let b = text.as_bytes();
    let mut open: Vec<usize> = Vec::new();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b';' => {
                if b.get(i + 1) == Some(&b'|') {
                    match text[i + 2..].find("|;") {
                        Some(k) => i += 2 + k + 2,
                        None => {
                            return Scan::Incomplete(ReadError {
                                message: "unterminated block comment".into(),
                                start: i,
                                end: i + 2,
                            })
                        }
                    }
                    continue;
                }
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'"' => {
                let start = i;
                i += 1;
                loop {
                    match b.get(i) {
                        None => {
                            return Scan::Incomplete(ReadError {
                                message: "unterminated string".into(),
                                start,
                                end: start + 1,
                            })
                        }
                        Some(b'\\') => i += 2,
                        Some(b'"') => break,
                        Some(_) => i += 1,
                    }
                }
                i += 1;
            }
            b'(' => {
                open.push(i);
                if open.len() > MAX_NESTING {
                    return Scan::Invalid(ReadError {
                        message: format!("lists nested deeper than {MAX_NESTING} levels"),
                        start: i,
                        end: i + 1,
                    });
                }
                i += 1;
            }
            b')' => {
                if open.pop().is_none() {
                    return Scan::Invalid(ReadError {
                        message: "extra right paren on input".into(),
                        start: i,
                        end: i + 1,
                    });
                }
                i += 1;
            }
            _ => i += 1,
        }
    }
    match open.last() {
        Some(&p) => Scan::Incomplete(ReadError {
            message: "malformed list on input: this ( is never closed".into(),
            start: p,
            end: p + 1,
        }),
        None => Scan::Complete,
    }
}

/// Reads every form of a source.
pub fn read_source(text: &str, src: u32, syms: &mut SymbolTable) -> Result<Parsed, ReadError> {
    match scan(text) {
        Scan::Complete => {}
        Scan::Incomplete(e) | Scan::Invalid(e) => return Err(e),
    }
    let program = LispParser::parse(Rule::program, text)
        .map_err(pest_error)?
        .next()
        .expect("program rule");
    let mut b = Builder {
        syms,
        spans: SpanMap::default(),
        src,
    };
    let mut forms = Vec::new();
    for p in program.into_inner() {
        if p.as_rule() == Rule::EOI {
            break;
        }
        let span = b.span(&p);
        forms.push((b.datum(p)?, span));
    }
    Ok(Parsed {
        forms,
        spans: b.spans,
    })
}

/// Reads the first form of a string (AutoLISP's `read`); `Ok(None)` when it holds none.
/// Returns the form and the byte offset just past it.
pub fn read_one(text: &str, syms: &mut SymbolTable) -> Result<Option<(Value, usize)>, ReadError> {
    // Only the structure up to the first datum matters, but an unbalanced rest would make
    // pest fail, so scan the whole text for depth only when it is balanced.
    if let Scan::Invalid(e) = scan(text) {
        if e.message.starts_with("lists nested") {
            return Err(e);
        }
    }
    let single = LispParser::parse(Rule::single, text)
        .map_err(pest_error)?
        .next()
        .expect("single rule");
    let mut b = Builder {
        syms,
        spans: SpanMap::default(),
        src: 0,
    };
    match single.into_inner().next() {
        Some(p) => {
            let end = p.as_span().end();
            Ok(Some((b.datum(p)?, end)))
        }
        None => Ok(None),
    }
}

/// The message of a text the grammar does not match. `read_source` matches the whole text
/// before building values, so this error wins over any found while building.
pub const GRAMMAR_ERROR: &str = "malformed input";

fn pest_error(e: pest::error::Error<Rule>) -> ReadError {
    let (start, end) = match e.location {
        pest::error::InputLocation::Pos(p) => (p, p + 1),
        pest::error::InputLocation::Span((a, b)) => (a, b.max(a + 1)),
    };
    ReadError {
        message: GRAMMAR_ERROR.into(),
        start,
        end,
    }
}

struct Builder<'a> {
    syms: &'a mut SymbolTable,
    spans: SpanMap,
    src: u32,
}

impl Builder<'_> {
    fn span(&self, p: &Pair<Rule>) -> Span {
        let s = p.as_span();
        Span {
            src: self.src,
            start: s.start() as u32,
            end: s.end() as u32,
        }
    }

    fn record(&mut self, v: &Value, span: Span) {
        if let Value::Cons(c) = v {
            self.spans.map.insert(c.as_ptr(), span);
        }
    }

    fn datum(&mut self, p: Pair<Rule>) -> Result<Value, ReadError> {
        let span = self.span(&p);
        match p.as_rule() {
            Rule::list => {
                let mut items = Vec::new();
                let mut dot_at: Option<(usize, Span)> = None;
                for q in p.into_inner() {
                    if q.as_rule() == Rule::token && q.as_str() == "." {
                        if dot_at.is_some() || items.is_empty() {
                            return Err(bad_dot(self.span(&q)));
                        }
                        dot_at = Some((items.len(), self.span(&q)));
                        continue;
                    }
                    items.push(self.datum(q)?);
                }
                let v = match dot_at {
                    Some((at, dspan)) => {
                        if at + 1 != items.len() {
                            return Err(bad_dot(dspan));
                        }
                        let tail = items.pop().expect("dotted tail");
                        Value::list_with_tail(items, tail)
                    }
                    None => Value::list(items),
                };
                self.record(&v, span);
                Ok(v)
            }
            Rule::quoted => {
                let inner = p.into_inner().next().expect("quoted datum");
                let d = self.datum(inner)?;
                let v = Value::list([Value::Sym(S_QUOTE), d]);
                self.record(&v, span);
                Ok(v)
            }
            Rule::string => {
                let raw = p.into_inner().next().map_or("", |c| c.as_str());
                let text = super::escape::unescape(raw).map_err(|e| ReadError {
                    message: e.to_string(),
                    start: span.start as usize,
                    end: span.end as usize,
                })?;
                Ok(Value::str(&text))
            }
            Rule::token => {
                let t = p.as_str();
                if t == "." {
                    return Err(bad_dot(span));
                }
                Ok(parse_atom(t, self.syms))
            }
            _ => unreachable!("grammar yields only data here"),
        }
    }
}

fn bad_dot(span: Span) -> ReadError {
    ReadError {
        message: "invalid dotted pair".into(),
        start: span.start as usize,
        end: span.end as usize,
    }
}

/// A token: an integer (32-bit; larger ones read as reals, as AutoLISP does), a real, nil, or
/// a symbol.
pub fn parse_atom(t: &str, syms: &mut SymbolTable) -> Value {
    if let Some(n) = parse_number(t) {
        return n;
    }
    if t.eq_ignore_ascii_case("nil") {
        return Value::Nil;
    }
    Value::Sym(syms.intern(t))
}

/// AutoLISP number syntax: optional sign, digits with an optional point, optional exponent.
/// Rust's float parser alone would also accept "inf" and "nan".
pub fn parse_number(t: &str) -> Option<Value> {
    let b = t.as_bytes();
    let body = match b.first()? {
        b'+' | b'-' => &b[1..],
        _ => b,
    };
    if body.is_empty() || !body.iter().any(u8::is_ascii_digit) {
        return None;
    }
    if !body
        .iter()
        .all(|c| c.is_ascii_digit() || matches!(c, b'.' | b'e' | b'E' | b'+' | b'-'))
    {
        return None;
    }
    if !(body[0].is_ascii_digit() || body[0] == b'.') {
        return None;
    }
    if body.iter().all(u8::is_ascii_digit) {
        return Some(match t.parse::<i32>() {
            Ok(i) => Value::Int(i),
            Err(_) => Value::Real(t.parse::<f64>().ok()?),
        });
    }
    t.parse::<f64>().ok().map(Value::Real)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers() {
        assert!(matches!(parse_number("42"), Some(Value::Int(42))));
        assert!(matches!(parse_number("-7"), Some(Value::Int(-7))));
        assert!(matches!(parse_number("1."), Some(Value::Real(r)) if r == 1.0));
        assert!(matches!(parse_number(".5"), Some(Value::Real(r)) if r == 0.5));
        assert!(matches!(parse_number("-1e-3"), Some(Value::Real(r)) if r == -1e-3));
        assert!(matches!(parse_number("3000000000"), Some(Value::Real(r)) if r == 3e9));
        assert!(parse_number("1+").is_none());
        assert!(parse_number("inf").is_none());
        assert!(parse_number("nan").is_none());
        assert!(parse_number("-").is_none());
        assert!(parse_number("e5").is_none());
    }

    #[test]
    fn unclosed_paren_is_reported_at_the_paren() {
        let text = "(defun f ()\n  (+ 1 2)\n";
        match scan(text) {
            Scan::Incomplete(e) => assert_eq!(e.start, 0),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn strings_and_comments_do_not_count_brackets() {
        assert_eq!(scan("(princ \")(\") ; )\n;| ( |;"), Scan::Complete);
    }
}
