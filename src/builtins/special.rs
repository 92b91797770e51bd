//! Special forms. The compiler evaluates them; these entries give them a value cell (so
//! `(type if)` is SUBR), help text and completion.

use crate::lang::builtin::{Builtin, MANY};
use crate::lang::error::{err, LResult};
use crate::lang::{Interp, Value};

fn not_applicable(_: &mut Interp, _: &[Value]) -> LResult {
    Err(err("bad function: special forms cannot be applied"))
}

macro_rules! special {
    ($name:expr, $sig:expr, $doc:expr) => {
        Builtin {
            name: $name,
            sig: $sig,
            doc: $doc,
            min: 0,
            max: MANY,
            f: not_applicable,
            special: true,
        }
    };
}

pub static BUILTINS: &[Builtin] = &[
    special!("quote", "(quote expr) or 'expr", "Returns expr unevaluated."),
    special!("function", "(function f)", "Like quote; marks a lambda for compilation."),
    special!("setq", "(setq sym expr [sym expr]...)", "Sets each symbol to its expression's value; returns the last value."),
    special!("if", "(if test then [else])", "Evaluates then when test is non-nil, else otherwise."),
    special!("cond", "(cond (test body...)...)", "Evaluates the body of the first clause whose test is non-nil; a clause without body returns its test."),
    special!("progn", "(progn expr...)", "Evaluates the expressions in order; returns the last."),
    special!("while", "(while test body...)", "Repeats body while test is non-nil; returns the last body value."),
    special!("repeat", "(repeat n body...)", "Evaluates body n times (n an integer); returns the last value."),
    special!("foreach", "(foreach var list body...)", "Evaluates body with var bound to each element; returns the last value."),
    special!("and", "(and expr...)", "T if every expression is non-nil (stops at the first nil), else nil."),
    special!("or", "(or expr...)", "T at the first non-nil expression, else nil."),
    special!("defun", "(defun name (args / locals) body...)", "Defines a function; locals start as nil; returns the name."),
    special!("defun-q", "(defun-q name (args / locals) body...)", "Defines a function kept as a list (see defun-q-list-ref)."),
    special!("defparam", "(defparam NAME default \"doc\" [min max])", "Declares a script parameter (NAME unevaluated): sets it to default unless --set or a batch table gave it a value; a number outside [min, max] is an error. Listed by `lispcad params`."),
    special!("lambda", "(lambda (args / locals) body...)", "An anonymous function (it does not capture variables: scope is dynamic)."),
];
