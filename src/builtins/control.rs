//! Evaluation and control: eval, apply, mapcar, set, errors and their catching, exit, load.

use std::fmt;

use crate::builtin;
use crate::lang::builtin::{Builtin, MANY};
use crate::lang::compile::Args;
use crate::lang::error::{err, ErrorKind, LResult, LispError};
use crate::lang::value::{ListBuilder, Object};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("eval", "(eval expr)", "Evaluates expr as a form.", 1, 1, eval),
    builtin!("apply", "(apply f list)", "Calls f with the elements of list as arguments.", 2, 2, apply),
    builtin!("mapcar", "(mapcar f list...)", "Calls f on the elements of the lists in parallel; a list of the results (stops at the shortest).", 2, MANY, mapcar),
    builtin!("set", "(set 'sym value)", "Sets the value of the symbol sym evaluates to.", 2, 2, set),
    builtin!("exit", "(exit)", "Ends the program (calls *error* with \"quit / exit abort\").", 0, 0, exit),
    builtin!("quit", "(quit)", "Same as exit.", 0, 0, exit),
    builtin!("vl-exit-with-error", "(vl-exit-with-error msg)", "Ends the program with an error carrying msg.", 1, 1, exit_with_error),
    builtin!("vl-exit-with-value", "(vl-exit-with-value value)", "Returns value from the nearest vl-catch-all-apply; outside one, ends the program.", 1, 1, exit_value),
    builtin!("vl-catch-all-apply", "(vl-catch-all-apply f list)", "Applies f to list; an error becomes an error object instead of stopping the program.", 2, 2, catch_all_apply),
    builtin!("vl-catch-all-error-p", "(vl-catch-all-error-p x)", "T if x is an error object from vl-catch-all-apply.", 1, 1, catch_all_error_p),
    builtin!("vl-catch-all-error-message", "(vl-catch-all-error-message err)", "The message of an error object.", 1, 1, catch_all_error_message),
    builtin!("load", "(load file [on-failure])", "Loads and evaluates a .lsp file; on failure returns on-failure if given, else errors.", 1, 2, load),
    builtin!("defun-q-list-ref", "(defun-q-list-ref 'name)", "The list a defun-q function is kept as.", 1, 1, defun_q_list_ref),
    builtin!("defun-q-list-set", "(defun-q-list-set 'name list)", "Defines name from a ((args / locals) body...) list.", 2, 2, defun_q_list_set),
    builtin!("vl-symbol-name", "(vl-symbol-name sym)", "The name of a symbol, as a string.", 1, 1, symbol_name),
    builtin!("vl-symbol-value", "(vl-symbol-value sym)", "The value of a symbol.", 1, 1, symbol_value),
    builtin!("vl-bb-ref", "(vl-bb-ref 'sym)", "The value of sym on the blackboard (one namespace here: the global value).", 1, 1, symbol_value),
    builtin!("vl-bb-set", "(vl-bb-set 'sym value)", "Sets sym on the blackboard (the global value here).", 2, 2, set),
    builtin!("startapp", "(startapp app [file])", "Refused: lispcad has no shell escape.", 1, 2, startapp),
];

fn eval(it: &mut Interp, a: &[Value]) -> LResult {
    it.eval_value(&a[0])
}

fn apply(it: &mut Interp, a: &[Value]) -> LResult {
    let args: Args = it.list_arg(&a[1])?.iter().cloned().collect();
    it.apply_args(&a[0], args)
}

fn mapcar(it: &mut Interp, a: &[Value]) -> LResult {
    let f = &it.callable(&a[0])?;
    let mut lists: Vec<Value> = Vec::with_capacity(a.len() - 1);
    for l in &a[1..] {
        lists.push(it.list_arg(l)?.clone());
    }
    // Results go straight into the list, front to back: no vector of a million values beside it.
    let mut out = ListBuilder::new();
    loop {
        let mut args = Args::new();
        for l in lists.iter_mut() {
            match l {
                Value::Cons(c) => {
                    args.push(c.car.clone());
                    let next = c.cdr.clone();
                    *l = next;
                }
                _ => return Ok(out.finish()),
            }
        }
        out.push(it.apply_args(f, args)?);
    }
}

fn set(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    if s == crate::lang::symbols::S_T {
        return Err(err("attempt to set a constant: T"));
    }
    it.values[s.idx()] = a[1].clone();
    Ok(a[1].clone())
}

fn exit(_: &mut Interp, _: &[Value]) -> LResult {
    Err(LispError::new(ErrorKind::Exit, "quit / exit abort"))
}

fn exit_with_error(it: &mut Interp, a: &[Value]) -> LResult {
    Err(err(it.string(&a[0])?.to_string()))
}

/// The value of a pending `vl-exit-with-value`: the nearest `vl-catch-all-apply` returns it
/// (an early return, as routines use it); with none, the program ends as with `exit`.
#[derive(Default)]
struct ExitValue(Option<Value>);

fn exit_value(it: &mut Interp, a: &[Value]) -> LResult {
    it.ext::<ExitValue>().0 = Some(a[0].clone());
    Err(LispError::new(ErrorKind::Exit, "quit / exit abort"))
}

/// The error object `vl-catch-all-apply` returns.
pub struct CaughtError {
    pub message: String,
}

impl Object for CaughtError {
    fn type_name(&self) -> &'static str {
        "VL-CATCH-ALL-APPLY-ERROR"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(f, "#<%catch-all-apply-error%>")
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

fn catch_all_apply(it: &mut Interp, a: &[Value]) -> LResult {
    let args: Args = it.list_arg(&a[1])?.iter().cloned().collect();
    it.catch_depth += 1;
    let r = it.apply_args(&a[0], args);
    it.catch_depth -= 1;
    match r {
        Ok(v) => Ok(v),
        Err(e) if e.kind == ErrorKind::Exit && it.ext::<ExitValue>().0.is_some() => {
            Ok(it.ext::<ExitValue>().0.take().unwrap_or_default())
        }
        Err(e) if e.kind == ErrorKind::Abort => Err(e),
        Err(e) => Ok(Value::obj(CaughtError { message: e.message })),
    }
}

fn catch_all_error_p(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(a[0].as_obj::<CaughtError>().is_some()))
}

fn catch_all_error_message(it: &mut Interp, a: &[Value]) -> LResult {
    match a[0].as_obj::<CaughtError>() {
        Some(e) => Ok(Value::str(&e.message)),
        None => Err(crate::lang::builtin::bad_arg(
            it,
            "vl-catch-all-apply-error-p",
            &a[0],
        )),
    }
}

fn load(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    match load_confined(it, &name) {
        Ok(v) => Ok(v),
        Err(e)
            if a.len() > 1
                && e.kind == ErrorKind::Error
                && e.message.starts_with("LOAD failed") =>
        {
            // AutoLISP evaluates a symbol/function on-failure argument; a plain value is returned.
            Ok(a[1].clone())
        }
        Err(e) => Err(e),
    }
}

/// `Interp::load_file`, with the file read through the policy (under --sandbox through the
/// root's directory handle, so no symlink swapped in meanwhile leads out) and within the
/// memory budget.
fn load_confined(it: &mut Interp, name: &str) -> LResult {
    use crate::builtins::fs_policy::ReadError;
    let failed = |m: String| err(format!("LOAD failed: \"{name}\": {m}"));
    let path = it
        .resolve_path(name)
        .ok_or_else(|| err(format!("LOAD failed: \"{name}\"")))?;
    let bytes = match it.ext::<crate::builtins::io::FsPolicy>().read_bytes(&path) {
        Ok(b) => b,
        Err(ReadError::Open(m)) if m.starts_with("file access refused") => return Err(err(m)),
        Err(ReadError::Open(m)) => return Err(failed(m)),
        Err(ReadError::Memory(e)) => return Err(e),
    };
    let code_page = it.ext::<crate::lang::encoding::SourceCodePage>().0;
    let text = crate::lang::encoding::decode(&bytes, code_page);
    drop(bytes);
    if !it.loaded_files.contains(&path) {
        it.loaded_files.push(path.clone());
    }
    let saved = it.base_dir.replace(
        path.parent()
            .map(std::path::Path::to_path_buf)
            .unwrap_or_default(),
    );
    let r = it.eval_source(&path.display().to_string(), &text);
    it.base_dir = saved;
    r
}

fn defun_q_list_ref(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    let v = it.values[s.idx()].clone();
    Ok(if v.is_list() { v } else { Value::Nil })
}

fn defun_q_list_set(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    it.list_arg(&a[1])?;
    it.values[s.idx()] = a[1].clone();
    Ok(a[0].clone())
}

fn symbol_name(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    Ok(Value::str(it.syms.name(s)))
}

fn symbol_value(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    Ok(it.values[s.idx()].clone())
}

fn startapp(_: &mut Interp, _: &[Value]) -> LResult {
    Err(err("startapp is refused: lispcad has no shell escape"))
}
