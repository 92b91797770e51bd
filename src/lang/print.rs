//! The printer: `prin1` (readable: strings quoted and escaped) and `princ` (strings raw) forms
//! of values, as AutoLISP prints them.

use std::fmt::Write;

use super::eval::Interp;
use super::value::Value;

/// Nesting (through cars) beyond which the printer writes "..." instead of recursing.
const MAX_PRINT_DEPTH: usize = 1_000;

/// The longest text a printer makes: AutoLISP's string limit (`strlen` counts in 32 bits).
pub const MAX_PRINTED: usize = i32::MAX as usize;

/// Text being printed, bounded: each growth of the buffer is asked of the memory budget first
/// and made fallibly, and the text stops at `limit` bytes. A shared structure printed as a
/// tree (`(repeat 60 (setq l (list l l)))`) is exponentially long; once stopped, the walk
/// ends at once instead of visiting the rest.
struct Out {
    text: String,
    limit: usize,
    stopped: Option<super::error::Exn>,
}

impl Out {
    fn new(limit: usize) -> Out {
        Out {
            text: String::new(),
            limit,
            stopped: None,
        }
    }

    fn push_str(&mut self, s: &str) {
        if self.stopped.is_some() {
            return;
        }
        let len = self.text.len();
        if len.saturating_add(s.len()) > self.limit {
            // Whole characters only, so the partial text stays valid.
            let mut cut = self.limit.saturating_sub(len).min(s.len());
            while !s.is_char_boundary(cut) {
                cut -= 1;
            }
            self.text.push_str(&s[..cut]);
            self.stopped = Some(super::error::err(format!(
                "string too long: the printed text exceeds {} bytes",
                self.limit
            )));
            return;
        }
        if len + s.len() > self.text.capacity() {
            let more = s.len().max(self.text.capacity()).max(64);
            if let Err(e) = super::memory::reserve(more) {
                self.stopped = Some(e);
                return;
            }
            if self.text.try_reserve(more).is_err() {
                self.stopped = Some(super::memory::system_refused(more));
                return;
            }
        }
        self.text.push_str(s);
    }

    fn push(&mut self, c: char) {
        self.push_str(c.encode_utf8(&mut [0; 4]));
    }
}

impl Write for Out {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.push_str(s);
        Ok(())
    }
}

impl Interp {
    /// `prin1`'s text of `v`, as much as fits in memory and the string limit (then "...").
    pub fn prin1_string(&self, v: &Value) -> String {
        self.printed(v, true, MAX_PRINTED)
    }

    /// `princ`'s text of `v`, as much as fits (then "...").
    pub fn princ_string(&self, v: &Value) -> String {
        self.printed(v, false, MAX_PRINTED)
    }

    /// At most about `limit` bytes of `prin1`'s text (then "..."): for messages.
    pub fn prin1_short(&self, v: &Value, limit: usize) -> String {
        self.printed(v, true, limit)
    }

    /// The whole text, or the error that stopped it ("out of memory", "string too long").
    pub fn try_print_string(&self, v: &Value, readable: bool) -> Result<String, super::error::Exn> {
        let mut out = Out::new(MAX_PRINTED);
        self.print_to(&mut out, v, readable, 0);
        match out.stopped {
            Some(e) => Err(e),
            None => Ok(out.text),
        }
    }

    fn printed(&self, v: &Value, readable: bool, limit: usize) -> String {
        let mut out = Out::new(limit);
        self.print_to(&mut out, v, readable, 0);
        let mut text = out.text;
        if out.stopped.is_some() {
            text.push_str("...");
        }
        text
    }

    fn print_to(&self, out: &mut Out, v: &Value, readable: bool, depth: usize) {
        match v {
            Value::Nil => out.push_str("nil"),
            Value::Int(i) => {
                let _ = write!(out, "{i}");
            }
            Value::Real(r) => out.push_str(&format_real(*r)),
            Value::Str(s) => {
                if readable {
                    // The escaped copy is made whole: ask for it first.
                    if let Err(e) = super::memory::reserve(s.len().saturating_mul(2)) {
                        out.stopped.get_or_insert(e);
                        return;
                    }
                    out.push_str(&super::escape::escape_for_prin1(s));
                } else {
                    out.push_str(s);
                }
            }
            Value::Sym(s) => out.push_str(self.syms.name(*s)),
            Value::Cons(_) => {
                if depth >= MAX_PRINT_DEPTH {
                    out.push_str("(...)");
                    return;
                }
                out.push('(');
                let mut cur = v;
                let mut first = true;
                while let Value::Cons(c) = cur {
                    if out.stopped.is_some() {
                        return;
                    }
                    if !first {
                        out.push(' ');
                    }
                    first = false;
                    self.print_to(out, &c.car, readable, depth + 1);
                    cur = &c.cdr;
                }
                if !cur.is_nil() {
                    out.push_str(" . ");
                    self.print_to(out, cur, readable, depth + 1);
                }
                out.push(')');
            }
            Value::Subr(b) => {
                let _ = write!(out, "#<SUBR @{}>", b.name.to_uppercase());
            }
            Value::Func(l) => match l.name {
                Some(n) => {
                    let _ = write!(out, "#<USUBR @{}>", self.syms.name(n));
                }
                None => out.push_str("#<USUBR @LAMBDA>"),
            },
            Value::Obj(o) => {
                let mut s = String::new();
                let _ = o.print(&mut s);
                out.push_str(&s);
            }
        }
    }
}

pub use super::real::format_real;

/// A string as `prin1` writes it: quoted, with AutoLISP's escapes.
pub fn escape_into(out: &mut String, s: &str) {
    out.push_str(&super::escape::escape_for_prin1(s));
}
