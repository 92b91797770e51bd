//! The printer: `prin1` (readable: strings quoted and escaped) and `princ` (strings raw) forms
//! of values, as AutoLISP prints them.

use std::fmt::Write;

use super::eval::Interp;
use super::value::Value;

/// Nesting (through cars) beyond which the printer writes "..." instead of recursing.
const MAX_PRINT_DEPTH: usize = 1_000;

impl Interp {
    pub fn prin1_string(&self, v: &Value) -> String {
        let mut s = String::new();
        self.print_to(&mut s, v, true, 0);
        s
    }

    pub fn princ_string(&self, v: &Value) -> String {
        let mut s = String::new();
        self.print_to(&mut s, v, false, 0);
        s
    }

    fn print_to(&self, out: &mut String, v: &Value, readable: bool, depth: usize) {
        match v {
            Value::Nil => out.push_str("nil"),
            Value::Int(i) => {
                let _ = write!(out, "{i}");
            }
            Value::Real(r) => out.push_str(&format_real(*r)),
            Value::Str(s) => {
                if readable {
                    escape_into(out, s);
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
                let _ = o.print(out);
            }
        }
    }
}

pub use super::real::format_real;

/// A string as `prin1` writes it: quoted, with AutoLISP's escapes.
pub fn escape_into(out: &mut String, s: &str) {
    out.push_str(&super::escape::escape_for_prin1(s));
}
