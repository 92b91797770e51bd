//! The builtin-function descriptor and the argument checks every library module shares,
//! with AutoLISP's error texts ("bad argument type: numberp: nil", "too few arguments").

use super::error::{err, Exn, LResult};
use super::eval::Interp;
use super::value::Value;

pub type BuiltinFn = fn(&mut Interp, &[Value]) -> LResult;

/// A function of the library. Each library module has a `static` table of these: the name
/// and doc sit beside the function they describe.
pub struct Builtin {
    /// The Lisp name, lower case as documented (symbols are case-insensitive).
    pub name: &'static str,
    /// The argument signature shown by help, e.g. "(nth n list)".
    pub sig: &'static str,
    /// One line: what it does.
    pub doc: &'static str,
    pub min: u16,
    /// `u16::MAX` for any number.
    pub max: u16,
    pub f: BuiltinFn,
    /// A special form: evaluated by the compiler, listed here for help and completion only.
    pub special: bool,
}

pub const MANY: u16 = u16::MAX;

impl Builtin {
    #[inline]
    pub fn check_arity(&self, n: usize) -> Result<(), Exn> {
        if n < self.min as usize {
            Err(err("too few arguments"))
        } else if n > self.max as usize {
            Err(err("too many arguments"))
        } else {
            Ok(())
        }
    }
}

/// Shorthand for registration tables.
#[macro_export]
macro_rules! builtin {
    ($name:expr, $sig:expr, $doc:expr, $min:expr, $max:expr, $f:expr) => {
        $crate::lang::builtin::Builtin {
            name: $name,
            sig: $sig,
            doc: $doc,
            min: $min,
            max: $max,
            f: $f,
            special: false,
        }
    };
}

/// "bad argument type: PRED: VALUE" as AutoLISP prints it. AutoLISP puts a colon after the
/// numeric predicates (numberp:, fixnump:) and none after the others (stringp nil).
pub fn bad_arg(it: &Interp, pred: &str, v: &Value) -> Exn {
    // Bounded: the value may be a huge (or exponentially shared) structure.
    let shown = it.prin1_short(v, 4096);
    if matches!(pred, "numberp" | "fixnump" | "2D/3D point" | "2D point") {
        err(format!("bad argument type: {pred}: {shown}"))
    } else {
        err(format!("bad argument type: {pred} {shown}"))
    }
}

impl Interp {
    #[inline]
    pub fn num(&self, v: &Value) -> Result<f64, Exn> {
        v.as_f64().ok_or_else(|| bad_arg(self, "numberp", v))
    }

    #[inline]
    pub fn int(&self, v: &Value) -> Result<i32, Exn> {
        match v {
            Value::Int(i) => Ok(*i),
            _ => Err(bad_arg(self, "fixnump", v)),
        }
    }

    pub fn string<'a>(&self, v: &'a Value) -> Result<&'a str, Exn> {
        v.as_str().ok_or_else(|| bad_arg(self, "stringp", v))
    }

    pub fn symbol(&self, v: &Value) -> Result<super::value::Sym, Exn> {
        v.as_sym().ok_or_else(|| bad_arg(self, "symbolp", v))
    }

    /// A list (nil or a cons).
    pub fn list_arg<'a>(&self, v: &'a Value) -> Result<&'a Value, Exn> {
        if v.is_list() {
            Ok(v)
        } else {
            Err(bad_arg(self, "listp", v))
        }
    }

    /// A 2D or 3D point list of numbers; 2D points get z = 0.
    pub fn point(&self, v: &Value) -> Result<[f64; 3], Exn> {
        let mut out = [0.0; 3];
        let mut n = 0;
        for x in v.iter() {
            if n == 3 {
                return Err(bad_arg(self, "2D/3D point", v));
            }
            out[n] = x.as_f64().ok_or_else(|| bad_arg(self, "2D/3D point", v))?;
            n += 1;
        }
        if n < 2 || !matches!(v, Value::Cons(_)) {
            return Err(bad_arg(self, "2D/3D point", v));
        }
        Ok(out)
    }

    /// Whether a point list has a z coordinate.
    pub fn point_dim(v: &Value) -> usize {
        v.iter().count()
    }
}

/// A point as a Lisp list of reals, 2D or 3D.
pub fn point_value(p: [f64; 3], dim: usize) -> Value {
    if dim == 2 {
        Value::list([Value::Real(p[0]), Value::Real(p[1])])
    } else {
        Value::list([Value::Real(p[0]), Value::Real(p[1]), Value::Real(p[2])])
    }
}
