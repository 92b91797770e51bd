//! Calls: a compiled call of a symbol's function, binding a user function's parameters
//! (dynamic scope, shallow binding), and applying any function value at run time.

use std::rc::Rc;

use smallvec::SmallVec;

use super::code::{Code, Operand, Ret};
use super::compile::{with_span, Compiler, Lambda};
use super::error::{err, Exn, Frame, LResult, Span};
use super::eval::Interp;
use super::symbols::S_LAMBDA;
use super::value::{Sym, Value};

/// Argument vectors live on the Rust stack for the common arities.
pub type Args = SmallVec<[Value; 4]>;

#[cold]
fn arg_count_error(too_few: bool) -> Exn {
    err(if too_few {
        "too few arguments"
    } else {
        "too many arguments"
    })
}

/// Adds a call-stack frame as an error leaves a user function.
#[cold]
#[inline(never)]
/// Adds a call-stack frame as an error leaves a user function. Deep recursion keeps the 32
/// innermost frames and the 32 outermost (which name the caller that started it), counting
/// the ones dropped between them.
fn add_frame(it: &Interp, mut e: Exn, name: Option<Sym>, span: Option<Span>) -> Exn {
    const KEEP_EACH_END: usize = 32;
    if e.stack.len() == 2 * KEEP_EACH_END {
        e.stack.remove(KEEP_EACH_END);
        e.omitted_frames += 1;
    }
    e.stack.push(Frame {
        function: name.map_or_else(|| "LAMBDA".to_string(), |s| it.syms.name(s).to_string()),
        call_site: span,
    });
    e
}

fn eval_args(it: &mut Interp, args: &[Code]) -> Result<Args, Exn> {
    let mut v = Args::new();
    for a in args {
        v.push(a.run(it)?);
    }
    Ok(v)
}

/// `(f args...)` with `f` a symbol: the function is whatever the symbol's cell holds when the
/// call runs. Calls of up to four arguments keep them in a fixed array on the Rust stack, and
/// a user function takes them from there by move.
pub(super) fn call_symbol(fsym: Sym, args: Vec<Operand>, span: Option<Span>) -> Code {
    // The arguments are evaluated straight into an array (left to right, as AutoLISP does)
    // that the callee's parameters take by move: no argument vector on the heap, no
    // default-then-overwrite of each slot.
    macro_rules! fixed {
        ($n:literal, [$($i:literal),*]) => {{
            let args: Box<[Operand; $n]> = args
                .into_boxed_slice()
                .try_into()
                .ok()
                .expect("arity matches");
            Code::new(move |it: &mut Interp| {
                check_defined(it, fsym, span)?;
                let argv: [Value; $n] = [$(args[$i].eval(it)?),*];
                dispatch(it, fsym, argv, span)
            }) as Code
        }};
    }
    match args.len() {
        0 => Code::new(move |it: &mut Interp| {
            check_defined(it, fsym, span)?;
            dispatch(it, fsym, [], span)
        }),
        1 => {
            let [a]: [Operand; 1] = args.try_into().ok().expect("arity matches");
            Code::new_raw(move |it: &mut Interp| call1(it, fsym, &a, span))
        }
        2 => fixed!(2, [0, 1]),
        3 => fixed!(3, [0, 1, 2]),
        4 => fixed!(4, [0, 1, 2, 3]),
        _ => {
            let args = args.into_boxed_slice();
            Code::new(move |it| {
                check_defined(it, fsym, span)?;
                let mut argv = Args::new();
                for a in args.iter() {
                    argv.push(a.eval(it)?);
                }
                dispatch(it, fsym, argv, span)
            })
        }
    }
}

/// A call with one argument, the commonest shape of a recursion (`(fib (- n 1))`). A user
/// function of one parameter is entered here with the argument kept in registers on its way
/// into the parameter's cell and the body's result passed back still packed: moved through
/// the general path's argument array and result slot, both went through the stack and were
/// read back as 16 bytes written in pieces, which stalls on store forwarding. Everything
/// else (builtins, other arities: their errors) takes `dispatch`.
#[inline(always)]
fn call1(it: &mut Interp, fsym: Sym, a: &Operand, span: Option<Span>) -> Ret {
    if let Err(e) = check_defined(it, fsym, span) {
        return Ret::pack(Err(e));
    }
    // An integer argument (a counter, `(- n 1)`) is written into the parameter's cell as it is
    // made: as a general value it was assembled on the stack in pieces and copied out whole,
    // which stalls the reload (`int` has no side effects, so `eval` may run after it).
    if let Some(n) = a.int(it) {
        return match user1(it, fsym) {
            Some(l) => {
                let r = enter1(it, &l, |c| *c = Value::Int(n));
                leave1(it, r, fsym, span)
            }
            None => Ret::pack(dispatch(it, fsym, [Value::Int(n)], span)),
        };
    }
    let x = match a.eval(it) {
        Ok(x) => x,
        Err(e) => return Ret::pack(Err(e)),
    };
    match user1(it, fsym) {
        Some(l) => {
            let r = enter1(it, &l, move |c| *c = x);
            leave1(it, r, fsym, span)
        }
        None => Ret::pack(dispatch(it, fsym, [x], span)),
    }
}

/// The user function of one parameter `fsym` holds, if it holds one. The clone keeps the
/// function alive if its body redefines its own name.
#[inline(always)]
fn user1(it: &Interp, fsym: Sym) -> Option<Rc<Lambda>> {
    match &it.values[fsym.idx()] {
        Value::Func(l) if l.params.len() == 1 => Some(l.clone()),
        _ => None,
    }
}

#[inline(always)]
fn leave1(it: &Interp, r: Ret, fsym: Sym, span: Option<Span>) -> Ret {
    if r.is_err() {
        frame_raw(it, r, fsym, span)
    } else {
        r
    }
}

/// `bind_array`'s `enter` for one parameter, whose cell `set` fills, with the result packed.
#[inline(always)]
fn enter1(it: &mut Interp, l: &Lambda, set: impl FnOnce(&mut Value)) -> Ret {
    if let Err(e) = it.tick().and_then(|()| it.check_stack()) {
        return Ret::pack(Err(e));
    }
    let p = l.params[0].idx();
    let cell = &mut it.values[p];
    let outer = std::mem::take(cell);
    set(cell);
    let base = it.saves_len();
    for s in l.locals.iter() {
        it.bind(*s, Value::Nil);
    }
    let mut r = l.body.run_raw(it);
    if r.is_err() {
        r = Ret::pack(it.offer_error(r.unpack()));
    }
    it.unwind_to(base);
    std::mem::replace(&mut it.values[p], outer).release();
    r
}

/// The error leaving `call1`'s function, with its frame added.
#[cold]
#[inline(never)]
fn frame_raw(it: &Interp, r: Ret, fsym: Sym, span: Option<Span>) -> Ret {
    Ret::pack(
        r.unpack()
            .map_err(|e| add_frame(it, with_span(e, span), Some(fsym), span)),
    )
}

#[inline(always)]
fn check_defined(it: &Interp, fsym: Sym, span: Option<Span>) -> Result<(), Exn> {
    if it.values[fsym.idx()].is_nil() {
        return Err(undefined(it, fsym, span));
    }
    Ok(())
}

#[cold]
fn undefined(it: &Interp, fsym: Sym, span: Option<Span>) -> Exn {
    with_span(
        err(format!("no function definition: {}", it.syms.name(fsym))),
        span,
    )
}

/// Calls whatever `fsym`'s cell holds with evaluated arguments: a builtin gets them as a
/// slice, a user function binds them by move.
#[inline(always)]
fn dispatch<A>(it: &mut Interp, fsym: Sym, argv: A, span: Option<Span>) -> LResult
where
    A: AsRef<[Value]> + IntoIterator<Item = Value> + BindArgs,
{
    match &it.values[fsym.idx()] {
        Value::Func(l) => {
            // The clone keeps the function alive if its body redefines its own name.
            let l = l.clone();
            match argv.enter(it, &l) {
                Ok(v) => Ok(v),
                Err(e) => Err(add_frame(it, with_span(e, span), Some(fsym), span)),
            }
        }
        Value::Subr(b) => {
            let b = *b;
            let argv = argv.as_ref();
            match b.check_arity(argv.len()) {
                Ok(()) => (b.f)(it, argv).map_err(|e| with_span(e, span)),
                Err(e) => Err(with_span(e, span)),
            }
        }
        other => {
            let f = other.clone();
            it.apply_args(&f, argv.into_iter().collect())
                .map_err(|e| add_frame(it, with_span(e, span), Some(fsym), span))
        }
    }
}

/// Arguments a call hands to a user function, bound to its parameters by move. Compiled calls'
/// fixed arrays are taken apart element by element: moved through an array iterator, each
/// value was copied through the stack, and reloading 16 bytes written a field at a time
/// stalled on store forwarding (a third of fib's call path, by perf's samples).
pub(crate) trait BindArgs: Sized {
    fn count(&self) -> usize;
    /// Binds the arguments to `params`, which has `count()` symbols.
    fn bind_to(self, it: &mut Interp, params: &[Sym]);
    /// Calls `l` with these arguments.
    #[inline(always)]
    fn enter(self, it: &mut Interp, l: &Lambda) -> LResult {
        it.enter_lambda_with(l, self)
    }
}

/// A compiled call's fixed arguments. Besides `bind_to`, `enter` runs the whole call with the
/// parameters' outer values kept in the Rust frame instead of the save stack: a push and a pop
/// of the two save-stack vectors per parameter, with their capacity and length updates, were
/// a fifth of fib's call path. The bindings are the same dynamic ones (the new values are in
/// the symbols' cells while the body runs); only where the outer values wait differs. Errors
/// leave through this frame too, so the outer values come back on every exit, after
/// `*error*` has seen the bindings in place.
macro_rules! bind_array {
    ($n:literal, [$($i:literal $a:ident),*], [$($ri:literal $r:ident),*]) => {
        impl BindArgs for [Value; $n] {
            #[inline(always)]
            fn count(&self) -> usize {
                $n
            }
            #[inline(always)]
            #[allow(unused_variables)]
            fn bind_to(self, it: &mut Interp, params: &[Sym]) {
                let [$($a),*] = self;
                $(it.bind(params[$i], $a);)*
            }
            #[inline(always)]
            #[allow(unused_variables)]
            fn enter(self, it: &mut Interp, l: &Lambda) -> LResult {
                let params: &[Sym; $n] = match (*l.params).try_into() {
                    Ok(p) => p,
                    Err(_) => return Err(arg_count_error($n < l.params.len())),
                };
                it.tick()?;
                it.check_stack()?;
                let [$($a),*] = self;
                // Each parameter's cell takes its argument; the name now holds the outer value.
                $(let $a = std::mem::replace(&mut it.values[params[$i].idx()], $a);)*
                let base = it.saves_len();
                for p in l.locals.iter() {
                    it.bind(*p, Value::Nil);
                }
                let mut r = l.body.run(it);
                if r.is_err() {
                    r = it.offer_error(r);
                }
                it.unwind_to(base);
                // Outer values back in reverse order: a parameter repeated (bound to NIL's cell
                // twice) ends with its first outer value, as with the save stack.
                $(std::mem::replace(&mut it.values[params[$ri].idx()], $r).release();)*
                r
            }
        }
    };
}

bind_array!(0, [], []);
bind_array!(1, [0 a], [0 a]);
bind_array!(2, [0 a, 1 b], [1 b, 0 a]);
bind_array!(3, [0 a, 1 b, 2 c], [2 c, 1 b, 0 a]);
bind_array!(4, [0 a, 1 b, 2 c, 3 d], [3 d, 2 c, 1 b, 0 a]);

impl BindArgs for Args {
    fn count(&self) -> usize {
        self.len()
    }
    fn bind_to(self, it: &mut Interp, params: &[Sym]) {
        for (p, a) in params.iter().zip(self) {
            it.bind(*p, a);
        }
    }
}

/// A slice's values, taken (left nil).
struct Taken<'a>(&'a mut [Value]);

impl BindArgs for Taken<'_> {
    fn count(&self) -> usize {
        self.0.len()
    }
    fn bind_to(self, it: &mut Interp, params: &[Sym]) {
        for (p, a) in params.iter().zip(self.0.iter_mut()) {
            it.bind(*p, std::mem::take(a));
        }
    }
}

/// `((lambda ...) args...)` and other computed heads.
pub(super) fn call_computed(f: Code, args: Box<[Code]>, span: Option<Span>) -> Code {
    Code::new(move |it| {
        let fv = f.run(it)?;
        let argv = eval_args(it, &args)?;
        it.apply_args(&fv, argv).map_err(|e| with_span(e, span))
    })
}

impl Interp {
    /// Compile a form read at run time (`eval`, quoted lambdas): no source spans.
    pub fn compile_value(&mut self, form: &Value) -> Code {
        self.sync_cells();
        Compiler::new(None, &self.syms)
            .with_stack_floor(self.stack_floor())
            .compile(form)
    }

    /// Calls a user function with dynamic (shallow) binding: parameters and locals get their
    /// new values in the symbols' own cells, the old values go on the save stack and come back
    /// on return, error or not. Before unwinding on an error, `*error*` is offered the error
    /// while every binding is still in place, as AutoLISP does.
    pub fn call_lambda(&mut self, l: &Lambda, mut args: Args) -> LResult {
        self.enter_lambda(l, &mut args)
    }

    /// `call_lambda` taking the arguments by move out of `args` (left nil).
    pub fn enter_lambda(&mut self, l: &Lambda, args: &mut [Value]) -> LResult {
        self.enter_lambda_with(l, Taken(args))
    }

    /// The call itself, taking the arguments from an array on the caller's stack (compiled
    /// calls) or a slice.
    #[inline(always)]
    pub(crate) fn enter_lambda_with<A: BindArgs>(&mut self, l: &Lambda, args: A) -> LResult {
        let n = args.count();
        if n != l.params.len() {
            return Err(arg_count_error(n < l.params.len()));
        }
        self.tick()?;
        self.check_stack()?;
        let base = self.saves_len();
        args.bind_to(self, &l.params);
        for p in l.locals.iter() {
            self.bind(*p, Value::Nil);
        }
        let r = l.body.run(self);
        if r.is_err() {
            return self.leave_lambda_with_error(r, base);
        }
        self.unwind_to(base);
        r
    }

    /// An error leaving a user function, offered to `*error*` while the function's bindings
    /// are still in place.
    #[cold]
    #[inline(never)]
    pub(super) fn offer_error(&mut self, r: LResult) -> LResult {
        r.map_err(|e| self.offer_to_error_handler(e))
    }

    #[cold]
    #[inline(never)]
    fn leave_lambda_with_error(&mut self, r: LResult, base: usize) -> LResult {
        let r = r.map_err(|e| self.offer_to_error_handler(e));
        self.unwind_to(base);
        r
    }

    /// Applies any function value: builtin, user function, a symbol naming one, or a list
    /// `(lambda ...)` / defun-q definition.
    pub fn apply_args(&mut self, f: &Value, args: Args) -> LResult {
        match f {
            Value::Subr(b) => {
                if b.special {
                    return Err(err(format!("bad function: {}", b.name.to_uppercase())));
                }
                b.check_arity(args.len())?;
                (b.f)(self, &args)
            }
            Value::Func(l) => {
                let l = l.clone();
                self.call_lambda(&l, args)
                    .map_err(|e| add_frame(self, e, l.name, None))
            }
            Value::Sym(s) => {
                let v = self.values[s.idx()].clone();
                match v {
                    Value::Nil => Err(err(format!(
                        "no function definition: {}",
                        self.syms.name(*s)
                    ))),
                    Value::Sym(_) => Err(err(format!("bad function: {}", self.prin1_string(&v)))),
                    other => self.apply_args(&other, args),
                }
            }
            Value::Cons(_) => {
                let l = self.lambda_of_list(f)?;
                self.call_lambda(&l, args)
                    .map_err(|e| add_frame(self, e, l.name, None))
            }
            other => Err(err(format!("bad function: {}", self.prin1_string(other)))),
        }
    }

    /// The function a value designates, resolved once for repeated application (mapcar and
    /// friends): a symbol's function, a lambda list compiled.
    pub fn callable(&mut self, f: &Value) -> LResult {
        match f {
            Value::Subr(_) | Value::Func(_) => Ok(f.clone()),
            Value::Sym(s) => match self.values[s.idx()].clone() {
                v @ (Value::Subr(_) | Value::Func(_)) => Ok(v),
                Value::Cons(_) => Ok(f.clone()),
                Value::Nil => Err(err(format!(
                    "no function definition: {}",
                    self.syms.name(*s)
                ))),
                other => Err(err(format!("bad function: {}", self.prin1_string(&other)))),
            },
            Value::Cons(_) => Ok(Value::Func(self.lambda_of_list(f)?)),
            other => Err(err(format!("bad function: {}", self.prin1_string(other)))),
        }
    }

    pub fn apply(&mut self, f: &Value, args: &[Value]) -> LResult {
        self.apply_args(f, args.iter().cloned().collect())
    }

    /// The compiled lambda of a `(lambda params body...)` or `(params body...)` list, cached
    /// by identity so `(mapcar '(lambda ...) big-list)` compiles once.
    fn lambda_of_list(&mut self, f: &Value) -> Result<Rc<Lambda>, Exn> {
        let key = match f {
            Value::Cons(c) => c.as_ptr(),
            _ => unreachable!(),
        };
        if let Some((_, l)) = self.lambda_cache.get(&key) {
            return Ok(l.clone());
        }
        let def = if f.car().as_sym() == Some(S_LAMBDA) {
            f.cdr()
        } else {
            f.clone()
        };
        if !def.car().is_list() {
            return Err(err(format!("bad function: {}", self.prin1_string(f))));
        }
        self.sync_cells();
        let l = Rc::new(
            Compiler::new(None, &self.syms)
                .with_stack_floor(self.stack_floor())
                .lambda(None, &def)?,
        );
        if self.lambda_cache.len() > 4096 {
            self.lambda_cache.clear();
        }
        // The key's cell is kept alive by the cached value, so the address cannot be reused.
        self.lambda_cache.insert(key, (f.clone(), l.clone()));
        Ok(l)
    }
}
