//! Predicates and `type`.

use crate::builtin;
use crate::lang::builtin::Builtin;
use crate::lang::error::LResult;
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("atom", "(atom x)", "T if x is not a list cell (nil is an atom).", 1, 1, atom),
    builtin!("listp", "(listp x)", "T if x is a list (nil or a list cell).", 1, 1, listp),
    builtin!("vl-consp", "(vl-consp x)", "T if x is a non-empty list.", 1, 1, consp),
    builtin!("null", "(null x)", "T if x is nil.", 1, 1, null),
    builtin!("not", "(not x)", "T if x is nil.", 1, 1, null),
    builtin!("eq", "(eq a b)", "T if a and b are the same object (same atom value, or the same list cell).", 2, 2, eq),
    builtin!("equal", "(equal a b [fuzz])", "T if a and b have the same structure and values (numbers within fuzz).", 2, 3, equal),
    builtin!("boundp", "(boundp 'sym)", "T if the symbol has a non-nil value.", 1, 1, boundp),
    builtin!("vl-symbolp", "(vl-symbolp x)", "T if x is a symbol.", 1, 1, symbolp),
    builtin!("type", "(type x)", "The type of x as a symbol: INT REAL STR SYM LIST SUBR USUBR FILE ENAME PICKSET CURVE SURFACE MESH...; nil for nil.", 1, 1, type_of),
];

fn atom(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(!matches!(a[0], Value::Cons(_))))
}

fn listp(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(a[0].is_list()))
}

fn consp(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(matches!(a[0], Value::Cons(_))))
}

fn null(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(a[0].is_nil()))
}

fn eq(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(a[0].is_eq(&a[1])))
}

fn equal(it: &mut Interp, a: &[Value]) -> LResult {
    let fuzz = if a.len() == 3 { it.num(&a[2])? } else { 0.0 };
    Ok(Value::bool(a[0].equal(&a[1], fuzz)))
}

fn boundp(it: &mut Interp, a: &[Value]) -> LResult {
    // (boundp 'nil) is nil, not an error: nil reads as the empty list, not a symbol.
    if a[0].is_nil() {
        return Ok(Value::Nil);
    }
    let s = it.symbol(&a[0])?;
    Ok(Value::bool(it.values[s.idx()].truthy()))
}

fn symbolp(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(matches!(a[0], Value::Sym(_))))
}

fn type_of(it: &mut Interp, a: &[Value]) -> LResult {
    let name = match &a[0] {
        Value::Nil => return Ok(Value::Nil),
        Value::Int(_) => "INT",
        Value::Real(_) => "REAL",
        Value::Str(_) => "STR",
        Value::Sym(_) => "SYM",
        Value::Cons(_) => "LIST",
        Value::Subr(_) => "SUBR",
        Value::Func(_) => "USUBR",
        Value::Obj(o) => o.type_name(),
    };
    Ok(Value::Sym(it.intern(name)))
}
