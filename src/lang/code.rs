//! Compiled code and its operands. A compiled form is a boxed closure; what it returns travels
//! in two registers rather than through memory (see `Ret`).

use std::rc::Rc;

use super::builtin::Builtin;
use super::compile::Lambda;
use super::error::{LResult, LispError};
use super::eval::Interp;
use super::value::{ConsRef, Object, Sym, Value};

/// An `LResult` as two machine words. Rust returns a 16-byte enum such as `LResult` through a
/// hidden pointer: the callee wrote the tag and the payload as separate stores and the caller
/// copied the value out as one 16-byte load, which cannot be forwarded from those stores and
/// stalls (about a third of fib's time in the call closure, by perf's samples). A pair of
/// words comes back in `rax:rdx`. The words are built field by field, not transmuted: a
/// transmute went through the stack and stalled the same way.
///
/// `w0` holds the variant (`9` for an error) in its low half and an `Int`'s or a `Sym`'s value
/// in its high half; `w1` holds a `Real`'s bits or the pointer of the others. A `Ret` owns the
/// references it holds: every one made is unpacked once.
pub struct Ret {
    w0: u64,
    w1: u64,
}

const TAG_ERR: u32 = 9;

impl Ret {
    #[inline(always)]
    pub fn pack(r: LResult) -> Ret {
        let (w0, w1) = match r {
            Ok(v) => match v {
                Value::Nil => (0, 0),
                Value::Int(i) => (1 | (i as u32 as u64) << 32, 0),
                Value::Real(x) => (2, x.to_bits()),
                Value::Str(s) => (3, Rc::into_raw(s) as u64),
                Value::Sym(s) => (4 | (s.0 as u64) << 32, 0),
                Value::Cons(c) => (5, c.into_raw() as u64),
                Value::Subr(b) => (6, b as *const Builtin as u64),
                Value::Func(l) => (7, Rc::into_raw(l) as u64),
                Value::Obj(o) => (8, Rc::into_raw(o) as u64),
            },
            Err(e) => (TAG_ERR as u64, Box::into_raw(e) as u64),
        };
        Ret { w0, w1 }
    }

    #[inline(always)]
    pub fn is_err(&self) -> bool {
        self.w0 as u32 == TAG_ERR
    }

    #[inline(always)]
    pub fn unpack(self) -> LResult {
        let Ret { w0, w1 } = self;
        let hi = (w0 >> 32) as u32;
        // SAFETY: the words were made by `pack` from a value of the variant `w0` names; each
        // pointer was taken out of its owner there and is given back once, here.
        unsafe {
            Ok(match w0 as u32 {
                0 => Value::Nil,
                1 => Value::Int(hi as i32),
                2 => Value::Real(f64::from_bits(w1)),
                3 => Value::Str(Rc::from_raw(w1 as *const String)),
                4 => Value::Sym(Sym(hi)),
                5 => Value::Cons(ConsRef::from_raw(w1 as *mut ())),
                6 => Value::Subr(&*(w1 as *const Builtin)),
                7 => Value::Func(Rc::from_raw(w1 as *const Lambda)),
                8 => Value::Obj(Rc::from_raw(w1 as *const Box<dyn Object>)),
                _ => return Err(Box::from_raw(w1 as *mut LispError)),
            })
        }
    }
}

/// Compiled code: run it against the interpreter to get the form's value.
pub struct Code(Box<dyn Fn(&mut Interp) -> Ret>);

impl Code {
    #[inline(always)]
    pub fn new(f: impl Fn(&mut Interp) -> LResult + 'static) -> Code {
        Code(Box::new(move |it| Ret::pack(f(it))))
    }

    /// Code that returns its result packed already (the call path passes a body's result
    /// through without unpacking it).
    #[inline(always)]
    pub fn new_raw(f: impl Fn(&mut Interp) -> Ret + 'static) -> Code {
        Code(Box::new(f))
    }

    #[inline(always)]
    pub fn run(&self, it: &mut Interp) -> LResult {
        (self.0)(it).unpack()
    }

    #[inline(always)]
    pub fn run_raw(&self, it: &mut Interp) -> Ret {
        (self.0)(it)
    }
}

/// An argument of a call, classified when compiled: variables and constants (most arguments
/// in practice) are read in place instead of through a boxed closure call.
pub enum Operand {
    /// A symbol's value cell.
    Var(usize),
    /// A self-evaluating atom (number, string, nil, T).
    Const(Value),
    Code(Code),
    /// `(+ v 1)`, `(1- v)` and the like (`fastpath::Arith`).
    Arith(super::fastpath::Arith),
}

impl Operand {
    #[inline(always)]
    pub fn eval(&self, it: &mut Interp) -> LResult {
        match self {
            // Numbers first: a copy without the generic clone's dispatch over every variant.
            Operand::Var(i) => Ok(match &it.values[*i] {
                Value::Int(n) => Value::Int(*n),
                Value::Real(r) => Value::Real(*r),
                v => v.clone(),
            }),
            Operand::Const(v) => Ok(v.clone()),
            Operand::Code(c) => c.run(it),
            Operand::Arith(a) => a.eval(it),
        }
    }

    /// The operand's value when it is an integer found without calling anything (a variable,
    /// a constant, `Arith`'s fast path); `None` leaves it to `eval`. No side effects.
    #[inline(always)]
    pub fn int(&self, it: &Interp) -> Option<i32> {
        match self {
            Operand::Var(i) => match it.values[*i] {
                Value::Int(n) => Some(n),
                _ => None,
            },
            Operand::Const(Value::Int(n)) => Some(*n),
            Operand::Arith(a) => a.fast(it),
            Operand::Const(_) | Operand::Code(_) => None,
        }
    }

    /// `eval` with the result packed: code's result passes through as it came.
    #[inline(always)]
    pub fn eval_raw(&self, it: &mut Interp) -> Ret {
        match self {
            Operand::Code(c) => c.run_raw(it),
            other => Ret::pack(other.eval(it)),
        }
    }

    /// Back to a closure, for the places that store plain code.
    pub fn into_code(self) -> Code {
        match self {
            Operand::Var(i) => Code::new(move |it| Ok(it.values[i].clone())),
            Operand::Const(v) => Code::new(move |_| Ok(v.clone())),
            Operand::Code(c) => c,
            Operand::Arith(a) => Code::new(move |it| a.eval(it)),
        }
    }
}
