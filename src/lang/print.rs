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

/// A string as `prin1` writes it: quoted, with AutoLISP's escapes.
pub fn escape_into(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\x1b' => out.push_str("\\e"),
            c if (c as u32) < 32 => {
                let _ = write!(out, "\\{:03o}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

/// A real as AutoLISP prints it: C's `%g` with 6 significant digits, always with a decimal
/// point (1.0, 3.14159, 1.0e+06).
pub fn format_real(x: f64) -> String {
    if x.is_nan() {
        return "-1.#IND".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "1.#INF" } else { "-1.#INF" }.into();
    }
    let s = format_g(x, 6);
    // %g drops the point; AutoLISP keeps one so a real never reads back as an integer.
    match s.find('e') {
        Some(e) if !s[..e].contains('.') => format!("{}.0{}", &s[..e], &s[e..]),
        Some(_) => s,
        None if s.contains('.') => s,
        None => format!("{s}.0"),
    }
}

/// C's `%.{digits}g`.
pub fn format_g(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return if x.is_sign_negative() { "-0" } else { "0" }.into();
    }
    let p = digits.max(1);
    // The exponent after rounding to p significant digits decides the style.
    let sci = format!("{:.*e}", p - 1, x);
    let (mant, exp) = sci.split_once('e').expect("e in {:e}");
    let exp: i32 = exp.parse().expect("exponent");
    if exp < -4 || exp >= p as i32 {
        let mant = trim_zeros(mant);
        let sign = if exp < 0 { '-' } else { '+' };
        format!("{mant}e{sign}{:02}", exp.abs())
    } else {
        let decimals = (p as i32 - 1 - exp).max(0) as usize;
        trim_zeros(&format!("{x:.decimals$}")).to_string()
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_print_like_autolisp() {
        assert_eq!(format_real(1.0), "1.0");
        assert_eq!(format_real(3.5), "3.5");
        assert_eq!(format_real(1.23456789), "1.23457");
        assert_eq!(format_real(100000.0), "100000.0");
        assert_eq!(format_real(1e6), "1.0e+06");
        assert_eq!(format_real(1.5e-7), "1.5e-07");
        assert_eq!(format_real(123456789.0), "1.23457e+08");
        assert_eq!(format_real(0.1), "0.1");
        assert_eq!(format_real(-2.0), "-2.0");
        assert_eq!(format_real(0.0001), "0.0001");
        assert_eq!(format_real(0.00001), "1.0e-05");
    }
}
