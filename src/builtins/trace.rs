//! `trace` / `untrace`: a traced user function is replaced by a wrapper with the same
//! parameters that prints the call and its result the way AutoCAD does, indented by depth:
//!
//! ```text
//! Entering (FACT 2)
//!   Entering (FACT 1)
//!   Result:  1
//! Result:  2
//! ```
//!
//! The evaluator is untouched: the wrapper is an ordinary lambda calling a hidden builtin.

use std::collections::HashMap;

use crate::builtin;
use crate::lang::builtin::Builtin;
use crate::lang::error::LResult;
use crate::lang::value::Sym;
use crate::lang::{Interp, Value};

/// Not in the library's tables (no doc, no completion): only the wrappers call it, through
/// the global below.
static TRACE_CALL: Builtin = builtin!(
    "lispcad-trace-call",
    "(lispcad-trace-call 'name args)",
    "Calls a traced function's original definition, printing the call and its result.",
    2,
    2,
    trace_call
);
const CALLER: &str = "*LISPCAD-TRACE-CALL*";

#[derive(Default)]
struct Traced {
    originals: HashMap<Sym, Value>,
    depth: usize,
}

/// The symbol a `trace`/`untrace` argument names: `(trace fact)` passes the function itself
/// (its name is in it), `(trace 'fact)` the symbol.
fn named(it: &Interp, v: &Value) -> Option<Sym> {
    match v {
        Value::Sym(s) => Some(*s),
        Value::Func(l) => l.name,
        _ => None,
    }
    .filter(|s| it.values.get(s.idx()).is_some())
}

/// `(trace f...)`: wraps each user function; already traced or not user functions are left.
/// Returns the last function's name, as AutoCAD does.
pub fn trace(it: &mut Interp, a: &[Value]) -> LResult {
    it.set_global(CALLER, Value::Subr(&TRACE_CALL));
    let mut last = Value::Nil;
    for v in a {
        let Some(s) = named(it, v) else { continue };
        last = Value::Sym(s);
        let Some(Value::Func(l)) = it.values.get(s.idx()).cloned() else {
            continue;
        };
        if it.ext::<Traced>().originals.contains_key(&s) {
            continue;
        }
        let params: Vec<&str> = l.params.iter().map(|p| it.syms.name(*p)).collect();
        let src = format!(
            "(lambda ({ps}) ({CALLER} '{name} (list {ps})))",
            ps = params.join(" "),
            name = it.syms.name(s)
        );
        let wrapper = it.eval_source("<trace>", &src)?;
        it.ext::<Traced>().originals.insert(s, Value::Func(l));
        it.values[s.idx()] = wrapper;
    }
    Ok(last)
}

/// `(untrace f...)`: puts the original definitions back.
pub fn untrace(it: &mut Interp, a: &[Value]) -> LResult {
    let mut last = Value::Nil;
    for v in a {
        // A traced function evaluates to its wrapper, which has no name: find it by value.
        let s = named(it, v).or_else(|| {
            let t = it.ext::<Traced>();
            let keys: Vec<Sym> = t.originals.keys().copied().collect();
            keys.into_iter().find(|k| it.values[k.idx()].is_eq(v))
        });
        let Some(s) = s else { continue };
        last = Value::Sym(s);
        if let Some(orig) = it.ext::<Traced>().originals.remove(&s) {
            it.values[s.idx()] = orig;
        }
    }
    Ok(last)
}

fn trace_call(it: &mut Interp, a: &[Value]) -> LResult {
    let Value::Sym(s) = &a[0] else {
        return Ok(Value::Nil);
    };
    let Some(f) = it.ext::<Traced>().originals.get(s).cloned() else {
        return Ok(Value::Nil);
    };
    let args: Vec<Value> = a[1].iter().cloned().collect();
    let depth = it.ext::<Traced>().depth;
    let pad = "  ".repeat(depth);
    let mut call = format!("({}", it.syms.name(*s));
    for x in &args {
        call.push(' ');
        call.push_str(&it.prin1_string(x));
    }
    call.push(')');
    it.write_out(&format!("{pad}Entering {call}\n"));
    it.ext::<Traced>().depth = depth + 1;
    let r = it.apply(&f, &args);
    it.ext::<Traced>().depth = depth;
    let r = r?;
    let shown = it.prin1_string(&r);
    it.write_out(&format!("{pad}Result:  {shown}\n"));
    Ok(r)
}
