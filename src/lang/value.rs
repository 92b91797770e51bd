//! Values: nil, integers (32-bit, wrapping like AutoLISP), reals, strings, interned symbols,
//! immutable cons cells, builtin and user functions, and opaque objects (geometry, entity names,
//! selection sets, files, caught errors) that other layers define.

use std::any::Any;
use std::fmt;
use std::rc::Rc;

use super::builtin::Builtin;
use super::compile::Lambda;

/// An interned symbol: an index into the symbol table and into the value cells.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, PartialOrd, Ord)]
pub struct Sym(pub u32);

impl Sym {
    #[inline]
    pub fn idx(self) -> usize {
        self.0 as usize
    }
}

/// A Lisp value. 16 bytes: numbers never allocate.
#[derive(Clone, Default)]
pub enum Value {
    /// nil, the empty list and false: one object, as in AutoLISP.
    #[default]
    Nil,
    Int(i32),
    Real(f64),
    /// Strings are immutable; `Rc<String>` keeps the pointer thin so a value stays 16 bytes.
    Str(Rc<String>),
    Sym(Sym),
    Cons(Rc<Cons>),
    Subr(&'static Builtin),
    Func(Rc<Lambda>),
    Obj(Rc<Box<dyn Object>>),
}

/// A cons cell. AutoLISP has no destructive list operations, so cells are immutable.
pub struct Cons {
    pub car: Value,
    pub cdr: Value,
}

/// A value defined outside the language core (a curve, an entity name, a file...).
pub trait Object: Any {
    /// What `type` returns, e.g. "CURVE", "ENAME", "FILE".
    fn type_name(&self) -> &'static str;
    /// The printed form, e.g. `#<LINE (0 0 0)-(1 1 0)>`.
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result;
    /// `equal` between two objects of possibly different kinds; identity by default.
    fn equal(&self, _other: &dyn Object) -> bool {
        false
    }
    fn as_any(&self) -> &dyn Any;
}

impl Drop for Cons {
    /// Frees long and deeply nested lists without recursion: a 1M-cell list must not overflow
    /// the stack when dropped. The work list only allocates when nested cells are freed.
    fn drop(&mut self) {
        let mut work: Vec<Value> = Vec::new();
        let take = |v: &mut Value, work: &mut Vec<Value>| {
            if let Value::Cons(rc) = v {
                if Rc::strong_count(rc) == 1 {
                    work.push(std::mem::take(v));
                }
            }
        };
        take(&mut self.car, &mut work);
        take(&mut self.cdr, &mut work);
        while let Some(v) = work.pop() {
            if let Value::Cons(rc) = v {
                if let Ok(mut cell) = Rc::try_unwrap(rc) {
                    take(&mut cell.car, &mut work);
                    take(&mut cell.cdr, &mut work);
                    // `cell` drops here with nil car and cdr: no recursion.
                }
            }
        }
    }
}

impl Value {
    pub const T: Value = Value::Sym(super::symbols::S_T);

    #[inline]
    pub fn is_nil(&self) -> bool {
        matches!(self, Value::Nil)
    }

    #[inline]
    pub fn truthy(&self) -> bool {
        !self.is_nil()
    }

    #[inline]
    pub fn bool(b: bool) -> Value {
        if b {
            Value::T
        } else {
            Value::Nil
        }
    }

    pub fn str(s: &str) -> Value {
        Value::Str(Rc::new(s.to_string()))
    }

    /// Wraps an opaque object.
    pub fn obj(o: impl Object) -> Value {
        Value::Obj(Rc::new(Box::new(o)))
    }

    pub fn cons(car: Value, cdr: Value) -> Value {
        Value::Cons(Rc::new(Cons { car, cdr }))
    }

    /// A proper list from the items, in order.
    pub fn list<I>(items: I) -> Value
    where
        I: IntoIterator<Item = Value>,
        I::IntoIter: DoubleEndedIterator,
    {
        Self::list_with_tail(items, Value::Nil)
    }

    /// A list from the items ending in `tail` (a dotted list when `tail` is an atom).
    pub fn list_with_tail<I>(items: I, tail: Value) -> Value
    where
        I: IntoIterator<Item = Value>,
        I::IntoIter: DoubleEndedIterator,
    {
        items
            .into_iter()
            .rev()
            .fold(tail, |acc, v| Value::cons(v, acc))
    }

    pub fn is_list(&self) -> bool {
        matches!(self, Value::Nil | Value::Cons(_))
    }

    pub fn as_cons(&self) -> Option<&Cons> {
        match self {
            Value::Cons(c) => Some(c),
            _ => None,
        }
    }

    pub fn car(&self) -> Value {
        match self {
            Value::Cons(c) => c.car.clone(),
            _ => Value::Nil,
        }
    }

    pub fn cdr(&self) -> Value {
        match self {
            Value::Cons(c) => c.cdr.clone(),
            _ => Value::Nil,
        }
    }

    /// Iterates the cars of a list; stops at the first non-cons tail.
    pub fn iter(&self) -> ListIter<'_> {
        ListIter { cur: self }
    }

    /// The number as f64 if this is a number.
    #[inline]
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            Value::Int(i) => Some(i as f64),
            Value::Real(r) => Some(r),
            _ => None,
        }
    }

    pub fn as_sym(&self) -> Option<Sym> {
        match self {
            Value::Sym(s) => Some(*s),
            _ => None,
        }
    }

    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) => Some(s),
            _ => None,
        }
    }

    /// Downcast an opaque object.
    pub fn as_obj<T: Object>(&self) -> Option<&T> {
        match self {
            Value::Obj(o) => o.as_any().downcast_ref::<T>(),
            _ => None,
        }
    }

    pub fn is_function(&self) -> bool {
        matches!(self, Value::Subr(_) | Value::Func(_))
    }

    /// `eq`: identity for conses, strings and objects; value for atoms.
    pub fn is_eq(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Nil, Value::Nil) => true,
            (Value::Int(a), Value::Int(b)) => a == b,
            (Value::Real(a), Value::Real(b)) => a == b,
            (Value::Sym(a), Value::Sym(b)) => a == b,
            (Value::Str(a), Value::Str(b)) => Rc::ptr_eq(a, b),
            (Value::Cons(a), Value::Cons(b)) => Rc::ptr_eq(a, b),
            (Value::Subr(a), Value::Subr(b)) => std::ptr::eq(*a, *b),
            (Value::Func(a), Value::Func(b)) => Rc::ptr_eq(a, b),
            (Value::Obj(a), Value::Obj(b)) => Rc::ptr_eq(a, b),
            _ => false,
        }
    }

    /// `equal` with a numeric fuzz: structural, numbers compared within `fuzz`
    /// (an integer and a real compare by value). Iterative along cdrs.
    pub fn equal(&self, other: &Value, fuzz: f64) -> bool {
        let (mut a, mut b) = (self, other);
        loop {
            match (a, b) {
                (Value::Cons(x), Value::Cons(y)) => {
                    if Rc::ptr_eq(x, y) {
                        return true;
                    }
                    if !x.car.equal(&y.car, fuzz) {
                        return false;
                    }
                    a = &x.cdr;
                    b = &y.cdr;
                }
                (Value::Str(x), Value::Str(y)) => return x == y,
                (Value::Obj(x), Value::Obj(y)) => {
                    return Rc::ptr_eq(x, y) || x.equal(y.as_ref().as_ref());
                }
                _ => {
                    if let (Some(x), Some(y)) = (a.as_f64(), b.as_f64()) {
                        return if fuzz > 0.0 {
                            (x - y).abs() <= fuzz
                        } else {
                            x == y
                        };
                    }
                    return a.is_eq(b);
                }
            }
        }
    }
}

pub struct ListIter<'a> {
    cur: &'a Value,
}

impl<'a> Iterator for ListIter<'a> {
    type Item = &'a Value;
    #[inline]
    fn next(&mut self) -> Option<&'a Value> {
        match self.cur {
            Value::Cons(c) => {
                self.cur = &c.cdr;
                Some(&c.car)
            }
            _ => None,
        }
    }
}

impl fmt::Debug for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Nil => write!(f, "nil"),
            Value::Int(i) => write!(f, "{i}"),
            Value::Real(r) => write!(f, "{r:?}"),
            Value::Str(s) => write!(f, "{s:?}"),
            Value::Sym(s) => write!(f, "#sym{}", s.0),
            Value::Cons(_) => {
                write!(f, "(")?;
                let mut first = true;
                let mut cur = self;
                while let Value::Cons(c) = cur {
                    if !first {
                        write!(f, " ")?;
                    }
                    first = false;
                    write!(f, "{:?}", c.car)?;
                    cur = &c.cdr;
                }
                if !cur.is_nil() {
                    write!(f, " . {cur:?}")?;
                }
                write!(f, ")")
            }
            Value::Subr(b) => write!(f, "#<SUBR {}>", b.name),
            Value::Func(_) => write!(f, "#<USUBR>"),
            Value::Obj(o) => {
                let mut s = String::new();
                o.print(&mut s)?;
                f.write_str(&s)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_is_16_bytes() {
        assert_eq!(std::mem::size_of::<Value>(), 16);
    }

    #[test]
    fn dropping_a_million_cell_list_does_not_recurse() {
        let mut l = Value::Nil;
        for i in 0..1_000_000 {
            l = Value::cons(Value::Int(i), l);
        }
        drop(l);
        // Deep nesting through the car as well.
        let mut n = Value::Nil;
        for _ in 0..1_000_000 {
            n = Value::cons(n, Value::Nil);
        }
        drop(n);
    }

    #[test]
    fn equal_with_fuzz() {
        let a = Value::list([Value::Real(1.0), Value::Int(2)]);
        let b = Value::list([Value::Real(1.0 + 1e-9), Value::Real(2.0)]);
        assert!(a.equal(&b, 1e-6));
        assert!(!a.equal(&b, 0.0));
    }
}
