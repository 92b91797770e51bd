//! Values: nil, integers (32-bit, wrapping like AutoLISP), reals, strings, interned symbols,
//! immutable cons cells, builtin and user functions, and opaque objects (geometry, entity names,
//! selection sets, files, caught errors) that other layers define.

use std::any::Any;
use std::cell::Cell;
use std::fmt;
use std::ptr::NonNull;
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
    Cons(ConsRef),
    Subr(&'static Builtin),
    Func(Rc<Lambda>),
    Obj(Rc<Box<dyn Object>>),
}

/// A cons cell. AutoLISP has no destructive list operations, so cells are immutable.
pub struct Cons {
    pub car: Value,
    pub cdr: Value,
}

/// A counted reference to a cons cell: `Rc<Cons>` without the weak count nobody uses, so a
/// cell takes 40 bytes instead of 48 (lists of a million elements are common in CAD data, and
/// their memory is what peers are compared on). Cells live in the thread's pool (`cells`).
pub struct ConsRef(NonNull<ConsBox>);

struct ConsBox {
    count: Cell<usize>,
    cell: Cons,
}

impl ConsRef {
    #[inline]
    pub fn new(cell: Cons) -> ConsRef {
        let p = super::cells::take().cast::<ConsBox>();
        // SAFETY: a fresh slot of a cell's size and alignment (checked below), ours alone.
        unsafe {
            p.as_ptr().write(ConsBox {
                count: Cell::new(1),
                cell,
            })
        };
        ConsRef(p)
    }

    #[inline(always)]
    fn header(&self) -> &ConsBox {
        // SAFETY: the box lives while any ConsRef to it does (the count is at least 1).
        unsafe { self.0.as_ref() }
    }

    pub fn ptr_eq(a: &ConsRef, b: &ConsRef) -> bool {
        a.0 == b.0
    }

    /// The cell's address: its identity for `eq` and for caches keyed by cell.
    /// The counted pointer as a word (`code::Ret`); `from_raw` takes the reference back.
    #[inline(always)]
    pub(crate) fn into_raw(self) -> *mut () {
        let p = self.0;
        std::mem::forget(self);
        p.as_ptr().cast()
    }

    /// # Safety
    /// `p` comes from `into_raw`, and each such pointer is taken back once.
    #[inline(always)]
    pub(crate) unsafe fn from_raw(p: *mut ()) -> ConsRef {
        // SAFETY: `into_raw` gave a non-null pointer.
        ConsRef(unsafe { NonNull::new_unchecked(p.cast()) })
    }

    pub fn as_ptr(&self) -> *const Cons {
        &self.header().cell
    }

    /// How many references the cell has.
    pub fn strong_count(&self) -> usize {
        self.header().count.get()
    }

    /// The cell itself when this is its only reference.
    pub fn try_unwrap(self) -> Result<Cons, ConsRef> {
        if self.strong_count() != 1 {
            return Err(self);
        }
        let p = self.0;
        std::mem::forget(self);
        // SAFETY: this was the only reference, and it is forgotten: the cell is ours, and
        // once read out its storage goes back to the pool.
        let b = unsafe { p.as_ptr().read() };
        unsafe { super::cells::give(p.cast()) };
        Ok(b.cell)
    }
}

// The pool's slots are sized for a cell.
const _: () = assert!(
    std::mem::size_of::<ConsBox>() == std::mem::size_of::<super::cells::Slot>()
        && std::mem::align_of::<ConsBox>() == std::mem::align_of::<super::cells::Slot>()
);

impl std::ops::Deref for ConsRef {
    type Target = Cons;
    #[inline(always)]
    fn deref(&self) -> &Cons {
        &self.header().cell
    }
}

impl Clone for ConsRef {
    #[inline(always)]
    fn clone(&self) -> ConsRef {
        let c = &self.header().count;
        // As `Rc`: a count that would wrap means leaked references beyond memory; abort.
        let n = c.get().wrapping_add(1);
        if n == 0 {
            std::process::abort();
        }
        c.set(n);
        ConsRef(self.0)
    }
}

impl Drop for ConsRef {
    #[inline]
    fn drop(&mut self) {
        let c = &self.header().count;
        let n = c.get() - 1;
        c.set(n);
        if n == 0 {
            // SAFETY: the last reference is going: nothing else can reach the cell.
            unsafe {
                std::ptr::drop_in_place(self.0.as_ptr());
                super::cells::give(self.0.cast());
            }
        }
    }
}

/// Builds a proper list front to back without an intermediate vector: each new cell is
/// linked to the previous last one, which only the builder can reach until `finish`.
#[derive(Default)]
pub struct ListBuilder {
    head: Value,
    tail: Option<NonNull<ConsBox>>,
}

impl ListBuilder {
    pub fn new() -> ListBuilder {
        ListBuilder::default()
    }

    #[inline]
    pub fn push(&mut self, v: Value) {
        let cell = ConsRef::new(Cons {
            car: v,
            cdr: Value::Nil,
        });
        let p = cell.0;
        match self.tail {
            // SAFETY: the tail cell is referenced only from the list under construction,
            // which nothing outside the builder has seen, and no `&Cons` to it is alive.
            Some(mut t) => unsafe { t.as_mut().cell.cdr = Value::Cons(cell) },
            None => self.head = Value::Cons(cell),
        }
        self.tail = Some(p);
    }

    pub fn finish(self) -> Value {
        self.head
    }
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
        let unique = |v: &Value| matches!(v, Value::Cons(rc) if rc.strong_count() == 1);
        // The common case, and every cell freed by the loop below: nothing to free beneath.
        if !unique(&self.car) && !unique(&self.cdr) {
            return;
        }
        let mut work: Vec<Value> = Vec::new();
        let take = |v: &mut Value, work: &mut Vec<Value>| {
            if let Value::Cons(rc) = v {
                if rc.strong_count() == 1 {
                    work.push(std::mem::take(v));
                }
            }
        };
        take(&mut self.car, &mut work);
        take(&mut self.cdr, &mut work);
        while let Some(v) = work.pop() {
            if let Value::Cons(rc) = v {
                if let Ok(mut cell) = rc.try_unwrap() {
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

    /// Drops a value, skipping the out-of-line drop glue for the variants that own nothing
    /// (numbers, symbols, nil): the hot paths drop such values millions of times.
    #[inline(always)]
    pub fn release(self) {
        if matches!(
            self,
            Value::Nil | Value::Int(_) | Value::Real(_) | Value::Sym(_) | Value::Subr(_)
        ) {
            std::mem::forget(self);
        } else {
            drop(self);
        }
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
        Value::Cons(ConsRef::new(Cons { car, cdr }))
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
            (Value::Cons(a), Value::Cons(b)) => ConsRef::ptr_eq(a, b),
            (Value::Subr(a), Value::Subr(b)) => std::ptr::eq(*a, *b),
            (Value::Func(a), Value::Func(b)) => Rc::ptr_eq(a, b),
            (Value::Obj(a), Value::Obj(b)) => Rc::ptr_eq(a, b),
            _ => false,
        }
    }

    /// `equal` with a numeric fuzz: structural, numbers compared within `fuzz`
    /// (an integer and a real compare by value). Iterative along cdrs and, with an explicit
    /// work list, through cars too: a list nested a million levels deep compares without
    /// recursion. The work list only allocates when a car is itself a cons.
    pub fn equal(&self, other: &Value, fuzz: f64) -> bool {
        let mut pending: Vec<(&Value, &Value)> = Vec::new();
        let (mut a, mut b) = (self, other);
        loop {
            let same = match (a, b) {
                (Value::Cons(x), Value::Cons(y)) => {
                    if ConsRef::ptr_eq(x, y) {
                        true
                    } else if matches!(x.car, Value::Cons(_)) && matches!(y.car, Value::Cons(_)) {
                        pending.push((&x.cdr, &y.cdr));
                        a = &x.car;
                        b = &y.car;
                        continue;
                    } else if !x.car.atom_equal(&y.car, fuzz) {
                        false
                    } else {
                        a = &x.cdr;
                        b = &y.cdr;
                        continue;
                    }
                }
                _ => a.atom_equal(b, fuzz),
            };
            if !same {
                return false;
            }
            match pending.pop() {
                Some((x, y)) => (a, b) = (x, y),
                None => return true,
            }
        }
    }

    /// `equal` when at most one side is a cons (then they differ).
    fn atom_equal(&self, other: &Value, fuzz: f64) -> bool {
        match (self, other) {
            // The common keys of association lists, without the conversion to reals.
            (Value::Int(x), Value::Int(y)) if fuzz == 0.0 => x == y,
            (Value::Sym(x), Value::Sym(y)) => x == y,
            (Value::Str(x), Value::Str(y)) => x == y,
            (Value::Obj(x), Value::Obj(y)) => Rc::ptr_eq(x, y) || x.equal(y.as_ref().as_ref()),
            _ => {
                if let (Some(x), Some(y)) = (self.as_f64(), other.as_f64()) {
                    if fuzz > 0.0 {
                        (x - y).abs() <= fuzz
                    } else {
                        x == y
                    }
                } else {
                    self.is_eq(other)
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

/// Nesting (through cars) beyond which `Debug` writes "(...)" instead of recursing.
const MAX_DEBUG_DEPTH: usize = 200;

impl fmt::Debug for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        debug_to(self, f, 0)
    }
}

fn debug_to(v: &Value, f: &mut fmt::Formatter<'_>, depth: usize) -> fmt::Result {
    match v {
        Value::Nil => write!(f, "nil"),
        Value::Int(i) => write!(f, "{i}"),
        Value::Real(r) => write!(f, "{r:?}"),
        Value::Str(s) => write!(f, "{s:?}"),
        Value::Sym(s) => write!(f, "#sym{}", s.0),
        Value::Cons(_) if depth >= MAX_DEBUG_DEPTH => write!(f, "(...)"),
        Value::Cons(_) => {
            write!(f, "(")?;
            let mut first = true;
            let mut cur = v;
            while let Value::Cons(c) = cur {
                if !first {
                    write!(f, " ")?;
                }
                first = false;
                debug_to(&c.car, f, depth + 1)?;
                cur = &c.cdr;
            }
            if !cur.is_nil() {
                write!(f, " . ")?;
                debug_to(cur, f, depth + 1)?;
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_is_16_bytes() {
        assert_eq!(std::mem::size_of::<Value>(), 16);
    }

    #[test]
    fn a_cons_cell_takes_40_bytes() {
        assert_eq!(std::mem::size_of::<ConsBox>(), 40);
    }

    #[test]
    fn cells_are_counted_while_live_and_reused_once_freed() {
        use crate::lang::memory::thread_bytes;
        let build = || {
            let mut l = Value::Nil;
            for i in 0..100_000 {
                l = Value::cons(Value::Int(i), l);
            }
            l
        };
        let l = build();
        let built = thread_bytes();
        drop(l);
        // Every cell gives its 40 bytes back to the thread's budget.
        assert_eq!(built - thread_bytes(), 100_000 * 40);
        // The same list again takes the freed cells: no new chunk, the same count.
        let l = build();
        assert_eq!(thread_bytes(), built);
        assert_eq!(l.iter().count(), 100_000);
        assert!(matches!(l.iter().next(), Some(Value::Int(99_999))));
    }

    #[test]
    fn cons_references_count_and_free() {
        let shared = Value::str("s");
        let a = Value::cons(shared.clone(), Value::Nil);
        let b = a.clone();
        let (Value::Cons(ca), Value::Cons(cb)) = (&a, &b) else {
            panic!("conses")
        };
        assert!(ConsRef::ptr_eq(ca, cb));
        assert_eq!(ca.strong_count(), 2);
        drop(b);
        let Value::Cons(ca) = a else { panic!("cons") };
        assert_eq!(ca.strong_count(), 1);
        let cell = ca.try_unwrap().ok().expect("the only reference");
        assert!(cell.car.is_eq(&shared));
        drop(cell);
        // The string's other owner is all that is left: the cell released its reference.
        let Value::Str(rc) = &shared else {
            panic!("string")
        };
        assert_eq!(Rc::strong_count(rc), 1);
    }

    #[test]
    fn list_builder_builds_front_to_back() {
        let mut b = ListBuilder::new();
        assert!(ListBuilder::new().finish().is_nil());
        for i in 0..5 {
            b.push(Value::Int(i));
        }
        let l = b.finish();
        assert!(l.equal(&Value::list((0..5).map(Value::Int)), 0.0));
        let mut big = ListBuilder::new();
        for i in 0..1_000_000 {
            big.push(Value::Int(i));
        }
        let big = big.finish();
        assert_eq!(big.iter().count(), 1_000_000);
        assert!(matches!(big.iter().last(), Some(Value::Int(999_999))));
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

    /// `(((...)))` a million levels deep through the car, ending in `x`.
    fn nested(depth: usize, x: Value) -> Value {
        let mut n = Value::list([x]);
        for _ in 0..depth {
            n = Value::cons(n, Value::Nil);
        }
        n
    }

    #[test]
    fn equal_on_deep_nesting_does_not_recurse() {
        let a = nested(1_000_000, Value::Int(1));
        let b = nested(1_000_000, Value::Real(1.0));
        let c = nested(1_000_000, Value::Int(2));
        assert!(a.equal(&b, 0.0));
        assert!(!a.equal(&c, 0.0));
        assert!(!a.equal(&nested(999_999, Value::Int(1)), 0.0));
        let s = format!("{a:?}");
        assert!(s.starts_with("((((") && s.contains("(...)"), "{}", &s[..50]);
    }

    #[test]
    fn equal_compares_cars_and_tails() {
        let l = |v: Vec<Value>| Value::list(v);
        let a = l(vec![l(vec![Value::Int(1), Value::str("a")]), Value::Int(3)]);
        let b = l(vec![l(vec![Value::Int(1), Value::str("a")]), Value::Int(3)]);
        let c = l(vec![l(vec![Value::Int(1), Value::str("b")]), Value::Int(3)]);
        let d = l(vec![l(vec![Value::Int(1), Value::str("a")]), Value::Int(4)]);
        let e = l(vec![Value::Int(1), Value::Int(3)]);
        assert!(a.equal(&b, 0.0));
        assert!(!a.equal(&c, 0.0));
        assert!(!a.equal(&d, 0.0));
        assert!(!a.equal(&e, 0.0));
        assert!(!e.equal(&a, 0.0));
        let dotted = Value::cons(Value::Int(1), Value::Int(2));
        assert!(dotted.equal(&Value::cons(Value::Int(1), Value::Real(2.0)), 0.0));
        assert!(!dotted.equal(&Value::list([Value::Int(1), Value::Int(2)]), 0.0));
    }

    #[test]
    fn equal_with_fuzz() {
        let a = Value::list([Value::Real(1.0), Value::Int(2)]);
        let b = Value::list([Value::Real(1.0 + 1e-9), Value::Real(2.0)]);
        assert!(a.equal(&b, 1e-6));
        assert!(!a.equal(&b, 0.0));
    }
}
