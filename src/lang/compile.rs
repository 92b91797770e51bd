//! The compiler: forms to closures. Special forms are recognised once, symbols become direct
//! indices into the value cells, and calls look their function up in the symbol's cell at run
//! time (AutoLISP is a Lisp-1 with redefinable functions), so evaluation never walks the list
//! structure or hashes a name.
//!
//! Malformed special forms compile to code that raises AutoLISP's error when (and only when)
//! it runs, as an interpreter would: a bad `setq` inside a function that is never called is
//! not an error.

use std::rc::Rc;

use smallvec::SmallVec;

use super::error::{err, Exn, Frame, LResult, Span};
use super::eval::Interp;
use super::reader::SpanMap;
use super::symbols::*;
use super::value::{Sym, Value};

/// Compiled code: run it against the interpreter to get the form's value.
pub type Code = Box<dyn Fn(&mut Interp) -> LResult>;

/// Argument vectors live on the Rust stack for the common arities.
pub type Args = SmallVec<[Value; 4]>;

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
            Operand::Code(c) => c(it),
            Operand::Arith(a) => a.eval(it),
        }
    }

    /// Back to a closure, for the places that store plain code.
    pub fn into_code(self) -> Code {
        match self {
            Operand::Var(i) => Box::new(move |it| Ok(it.values[i].clone())),
            Operand::Const(v) => Box::new(move |_| Ok(v.clone())),
            Operand::Code(c) => c,
            Operand::Arith(a) => Box::new(move |it| a.eval(it)),
        }
    }
}

/// A user function (from `defun`, `lambda`, or a quoted lambda list applied at run time).
pub struct Lambda {
    pub name: Option<Sym>,
    pub params: Box<[Sym]>,
    pub locals: Box<[Sym]>,
    pub body: Code,
    /// `((params / locals) body...)`, for printing and `defun-q-list-ref`.
    pub source: Value,
}

/// Deepest form nesting the compiler follows (the reader already bounds source text; this
/// bounds lists built at run time and handed to `eval`).
const MAX_DEPTH: usize = 4_000;

pub struct Compiler<'a> {
    spans: Option<&'a SpanMap>,
    syms: &'a super::symbols::SymbolTable,
    depth: usize,
    /// Lowest stack address compilation may reach (0: only `MAX_DEPTH` applies). Set from the
    /// interpreter's stack budget so `eval` of deep data deep in a recursion fails cleanly.
    stack_floor: usize,
}

impl<'a> Compiler<'a> {
    pub(super) fn sym_name(&self, s: Sym) -> &str {
        self.syms.name(s)
    }

    pub fn new(spans: Option<&'a SpanMap>, syms: &'a super::symbols::SymbolTable) -> Self {
        Compiler {
            spans,
            syms,
            depth: 0,
            stack_floor: 0,
        }
    }

    pub fn with_stack_floor(mut self, floor: usize) -> Self {
        self.stack_floor = floor;
        self
    }

    fn span_of(&self, form: &Value) -> Option<Span> {
        self.spans.and_then(|m| m.get(form))
    }

    pub fn compile(&mut self, form: &Value) -> Code {
        self.depth += 1;
        let code = if self.depth > MAX_DEPTH || super::eval::stack_pointer() < self.stack_floor {
            fail(err("stack overflow: expression nested too deeply"), None)
        } else {
            self.compile_inner(form)
        };
        self.depth -= 1;
        code
    }

    /// A form as an operand: the same evaluation as `compile`, with variables and constants
    /// left unboxed.
    pub fn operand(&mut self, form: &Value) -> Operand {
        match form {
            Value::Sym(S_T) => Operand::Const(Value::T),
            Value::Sym(s) => Operand::Var(s.idx()),
            Value::Cons(c) => {
                // The same depth check as `compile`'s.
                if let Value::Sym(head) = c.car {
                    if self.depth < MAX_DEPTH && super::eval::stack_pointer() >= self.stack_floor {
                        let name = self.syms.name(head);
                        if let Some(a) =
                            super::fastpath::arith(head, name, &c.cdr, self.span_of(form))
                        {
                            return Operand::Arith(a);
                        }
                    }
                }
                Operand::Code(self.compile(form))
            }
            other => Operand::Const(other.clone()),
        }
    }

    fn operands(&mut self, args: &Value) -> Vec<Operand> {
        args.iter().map(|a| self.operand(a)).collect()
    }

    fn compile_inner(&mut self, form: &Value) -> Code {
        match form {
            Value::Sym(S_T) => Box::new(|_| Ok(Value::T)),
            Value::Sym(s) => {
                let i = s.idx();
                Box::new(move |it| Ok(it.values[i].clone()))
            }
            Value::Cons(c) => {
                let span = self.span_of(form);
                match &c.car {
                    Value::Sym(s) => self.compile_list(*s, &c.cdr, span),
                    head => {
                        let f = self.compile(head);
                        let args = self.compile_args(&c.cdr);
                        call_computed(f, args, span)
                    }
                }
            }
            other => {
                let v = other.clone();
                Box::new(move |_| Ok(v.clone()))
            }
        }
    }

    /// The head, operands and span of a two-argument comparison the fast path may inline
    /// (`fastpath::is_comparison`); `None` for any other form.
    fn comparison(&mut self, form: &Value) -> Option<(Sym, Vec<Operand>, Option<Span>)> {
        let Value::Cons(c) = form else { return None };
        let Value::Sym(head) = c.car else { return None };
        // What `compile` would do for this form, up to the inline comparison itself.
        if super::fastpath::is_comparison(self.syms.name(head))
            && c.cdr.iter().count() == 2
            && self.depth < MAX_DEPTH
            && super::eval::stack_pointer() >= self.stack_floor
        {
            self.depth += 1;
            let span = self.span_of(form);
            let args = self.operands(&c.cdr);
            self.depth -= 1;
            return Some((head, args, span));
        }
        None
    }

    /// A condition: the fused comparison when the form is an inlined one (`fastpath`),
    /// otherwise the form's ordinary code.
    fn test(&mut self, form: &Value) -> Result<super::fastpath::Test, Code> {
        match self.comparison(form) {
            Some((head, args, span)) => {
                let name = self.syms.name(head);
                super::fastpath::compile_test(head, name, args, span)
                    .map_err(|args| super::fastpath::compile(head, name, args, span))
            }
            None => Err(self.compile(form)),
        }
    }

    fn compile_args(&mut self, args: &Value) -> Box<[Code]> {
        args.iter().map(|a| self.compile(a)).collect()
    }

    fn compile_body(&mut self, body: &Value) -> Code {
        let mut codes: Vec<Code> = body.iter().map(|f| self.compile(f)).collect();
        match codes.len() {
            0 => Box::new(|_| Ok(Value::Nil)),
            1 => codes.pop().expect("one form"),
            _ => {
                let codes = codes.into_boxed_slice();
                Box::new(move |it| {
                    let (last, init) = codes.split_last().expect("several forms");
                    for c in init {
                        c(it)?;
                    }
                    last(it)
                })
            }
        }
    }

    fn compile_list(&mut self, head: Sym, rest: &Value, span: Option<Span>) -> Code {
        let n = rest.iter().count();
        let arg = |i: usize| rest.iter().nth(i).cloned().unwrap_or(Value::Nil);
        match head {
            S_QUOTE | S_FUNCTION if n != 1 => arity_error(n < 1, span),
            S_QUOTE => {
                let v = arg(0);
                Box::new(move |_| Ok(v.clone()))
            }
            S_FUNCTION => {
                let v = arg(0);
                if matches!(&v, Value::Cons(c) if c.car.as_sym() == Some(S_LAMBDA)) {
                    self.compile(&v)
                } else {
                    Box::new(move |_| Ok(v.clone()))
                }
            }
            S_SETQ => self.compile_setq(rest, span),
            S_IF => {
                if !(2..=3).contains(&n) {
                    return arity_error(n < 2, span);
                }
                let cond = self.comparison(&arg(0));
                // Branches are often a variable or a constant (a recursion's base case).
                let mut then = self.operand(&arg(1));
                let mut els = if n == 3 {
                    self.operand(&arg(2))
                } else {
                    Operand::Const(Value::Nil)
                };
                let test = match cond {
                    Some((head, args, tspan)) => {
                        let name = self.syms.name(head);
                        match super::fastpath::compile_if(head, name, args, tspan, then, els) {
                            Ok(code) => return code,
                            Err((args, t, e)) => {
                                (then, els) = (t, e);
                                Err(super::fastpath::compile(head, name, args, tspan))
                            }
                        }
                    }
                    None => self.test(&arg(0)),
                };
                let test = match test {
                    Ok(test) => {
                        return Box::new(move |it| {
                            if test(it)? {
                                then.eval(it)
                            } else {
                                els.eval(it)
                            }
                        })
                    }
                    Err(code) => code,
                };
                Box::new(move |it| {
                    let t = test(it)?;
                    let go = t.truthy();
                    t.release();
                    if go {
                        then.eval(it)
                    } else {
                        els.eval(it)
                    }
                })
            }
            S_COND => self.compile_cond(rest, span),
            S_PROGN => self.compile_body(rest),
            S_AND | S_OR => {
                let parts = self.compile_args(rest);
                let want = head == S_OR;
                Box::new(move |it| {
                    for p in parts.iter() {
                        if p(it)?.truthy() == want {
                            return Ok(Value::bool(want));
                        }
                    }
                    Ok(Value::bool(!want))
                })
            }
            S_WHILE => {
                if n < 1 {
                    return arity_error(true, span);
                }
                let test = self.test(&arg(0));
                let body = self.compile_body(&rest.cdr());
                let test = match test {
                    Ok(test) => {
                        return Box::new(move |it| {
                            let mut last = Value::Nil;
                            while test(it)? {
                                it.tick()?;
                                std::mem::replace(&mut last, body(it)?).release();
                            }
                            Ok(last)
                        })
                    }
                    Err(code) => code,
                };
                Box::new(move |it| {
                    let mut last = Value::Nil;
                    loop {
                        let t = test(it)?;
                        let go = t.truthy();
                        t.release();
                        if !go {
                            break;
                        }
                        it.tick()?;
                        std::mem::replace(&mut last, body(it)?).release();
                    }
                    Ok(last)
                })
            }
            S_REPEAT => {
                if n < 1 {
                    return arity_error(true, span);
                }
                let count = self.compile(&arg(0));
                let body = self.compile_body(&rest.cdr());
                Box::new(move |it| {
                    let c = count(it)?;
                    let times = match c {
                        Value::Int(i) => i,
                        _ => return Err(it_bad_arg(it, "fixnump", &c, span)),
                    };
                    let mut last = Value::Nil;
                    for _ in 0..times.max(0) {
                        it.tick()?;
                        last = body(it)?;
                    }
                    Ok(last)
                })
            }
            S_FOREACH => self.compile_foreach(rest, n, span),
            S_DEFUN | S_DEFUN_Q => self.compile_defun(head, rest, span),
            S_LAMBDA => match self.lambda(None, rest) {
                Ok(l) => {
                    let f = Value::Func(Rc::new(l));
                    Box::new(move |_| Ok(f.clone()))
                }
                Err(e) => fail(e, span),
            },
            _ if self.syms.name(head) == "DEFPARAM" => super::defparam::compile(self, rest, span),
            // `(vlax-for var collection body...)` is `foreach` over the collection's items
            // (the library's `vlax-for-items` lists them: the language knows no collections).
            _ if self.syms.name(head).eq_ignore_ascii_case("VLAX-FOR") && n >= 2 => {
                match self.syms.lookup("VLAX-FOR-ITEMS") {
                    Some(items) => {
                        let coll = Value::list([Value::Sym(items), arg(1)]);
                        let rest = Value::cons(arg(0), Value::cons(coll, rest.cdr().cdr()));
                        self.compile_foreach(&rest, n, span)
                    }
                    None => arity_error(false, span),
                }
            }
            _ => {
                let args = self.operands(rest);
                super::fastpath::compile(head, self.syms.name(head), args, span)
            }
        }
    }

    fn compile_setq(&mut self, rest: &Value, span: Option<Span>) -> Code {
        let items: Vec<&Value> = rest.iter().collect();
        if items.is_empty() {
            // AutoLISP: (setq) is nil, not an error.
            return Box::new(|_| Ok(Value::Nil));
        }
        let mut pairs: Vec<(Sym, Operand)> = Vec::new();
        for chunk in items.chunks(2) {
            let target = match chunk[0] {
                Value::Sym(s) if *s != S_T => *s,
                other => {
                    let other = other.clone();
                    return Box::new(move |it| Err(it_bad_arg(it, "symbolp", &other, span)));
                }
            };
            if chunk.len() < 2 {
                return arity_error(true, span);
            }
            pairs.push((target, self.operand(chunk[1])));
        }
        if pairs.len() == 1 {
            let (s, code) = pairs.pop().expect("one pair");
            let i = s.idx();
            return match code {
                Operand::Code(code) => Box::new(move |it| {
                    let v = code(it)?;
                    std::mem::replace(&mut it.values[i], v.clone()).release();
                    Ok(v)
                }),
                other => Box::new(move |it| {
                    let v = other.eval(it)?;
                    std::mem::replace(&mut it.values[i], v.clone()).release();
                    Ok(v)
                }),
            };
        }
        // Every value but the last goes straight into its cell; the last is also the result.
        let (last_sym, last_code) = pairs.pop().expect("several pairs");
        let pairs: Box<[(usize, Operand)]> = pairs.into_iter().map(|(s, c)| (s.idx(), c)).collect();
        let li = last_sym.idx();
        Box::new(move |it| {
            for (i, code) in pairs.iter() {
                let v = code.eval(it)?;
                std::mem::replace(&mut it.values[*i], v).release();
            }
            let v = last_code.eval(it)?;
            std::mem::replace(&mut it.values[li], v.clone()).release();
            Ok(v)
        })
    }

    fn compile_cond(&mut self, rest: &Value, span: Option<Span>) -> Code {
        let mut clauses: Vec<(Code, Option<Code>)> = Vec::new();
        for clause in rest.iter() {
            if !matches!(clause, Value::Cons(_)) {
                let c = clause.clone();
                return Box::new(move |it| Err(it_bad_arg(it, "consp", &c, span)));
            }
            let test = self.compile(&clause.car());
            let body = clause.cdr();
            let body = if body.is_nil() {
                None
            } else {
                Some(self.compile_body(&body))
            };
            clauses.push((test, body));
        }
        let clauses = clauses.into_boxed_slice();
        Box::new(move |it| {
            for (test, body) in clauses.iter() {
                let t = test(it)?;
                if t.truthy() {
                    return match body {
                        Some(b) => b(it),
                        None => Ok(t),
                    };
                }
            }
            Ok(Value::Nil)
        })
    }

    fn compile_foreach(&mut self, rest: &Value, n: usize, span: Option<Span>) -> Code {
        if n < 2 {
            return arity_error(true, span);
        }
        let var = match rest.car() {
            Value::Sym(s) if s != S_T => s,
            other => return Box::new(move |it| Err(it_bad_arg(it, "symbolp", &other, span))),
        };
        let list = self.compile(&rest.cdr().car());
        let body = self.compile_body(&rest.cdr().cdr());
        Box::new(move |it| {
            let l = list(it)?;
            if !l.is_list() {
                return Err(it_bad_arg(it, "listp", &l, span));
            }
            let base = it.bind(var, Value::Nil);
            let mut last = Ok(Value::Nil);
            for x in l.iter() {
                if let Err(e) = it.tick() {
                    last = Err(e);
                    break;
                }
                it.values[var.idx()] = x.clone();
                last = body(it);
                if last.is_err() {
                    break;
                }
            }
            it.unwind_to(base);
            last
        })
    }

    fn compile_defun(&mut self, head: Sym, rest: &Value, span: Option<Span>) -> Code {
        let name = match rest.car() {
            Value::Sym(s) if s != S_T => s,
            other => return Box::new(move |it| Err(it_bad_arg(it, "symbolp", &other, span))),
        };
        if !rest.cdr().is_list() || rest.cdr().is_nil() {
            return arity_error(true, span);
        }
        if head == S_DEFUN_Q {
            // defun-q keeps the definition as a list: ((params / locals) body...).
            let def = rest.cdr();
            return Box::new(move |it| {
                it.values[name.idx()] = def.clone();
                Ok(Value::Sym(name))
            });
        }
        match self.lambda(Some(name), &rest.cdr()) {
            Ok(l) => {
                let f = Value::Func(Rc::new(l));
                Box::new(move |it| {
                    it.values[name.idx()] = f.clone();
                    Ok(Value::Sym(name))
                })
            }
            Err(e) => fail(e, span),
        }
    }

    /// A lambda from `((params / locals) body...)`.
    pub fn lambda(&mut self, name: Option<Sym>, def: &Value) -> Result<Lambda, Exn> {
        let arglist = def.car();
        if !arglist.is_list() {
            return Err(err(format!(
                "bad argument list: {}",
                if arglist.is_nil() {
                    "nil"
                } else {
                    "not a list"
                }
            )));
        }
        let mut params = Vec::new();
        let mut locals = Vec::new();
        let mut after_slash = false;
        for a in arglist.iter() {
            match a {
                Value::Sym(S_SLASH) if !after_slash => after_slash = true,
                Value::Sym(s) if *s != S_T => {
                    if after_slash {
                        // The first occurrence wins (Autodesk): a local repeating a parameter
                        // must not reset the argument to nil.
                        if !params.contains(s) && !locals.contains(s) {
                            locals.push(*s)
                        }
                    } else if params.contains(s) {
                        // The first occurrence wins here too: a repeated parameter's
                        // argument goes to NIL's value cell, which no code reads (the
                        // reader makes `nil` the value nil, never this symbol).
                        params.push(S_NIL)
                    } else {
                        params.push(*s)
                    }
                }
                _ => return Err(err("bad argument list: parameters must be symbols")),
            }
        }
        let body = self.compile_body(&def.cdr());
        Ok(Lambda {
            name,
            params: params.into(),
            locals: locals.into(),
            body,
            source: def.clone(),
        })
    }
}

fn it_bad_arg(it: &Interp, pred: &str, v: &Value, span: Option<Span>) -> Exn {
    with_span(super::builtin::bad_arg(it, pred, v), span)
}

#[inline]
fn with_span(e: Exn, span: Option<Span>) -> Exn {
    match span {
        Some(s) => e.with_span(s),
        None => e,
    }
}

fn fail(e: Exn, span: Option<Span>) -> Code {
    Box::new(move |_| Err(with_span(e.clone(), span)))
}

#[cold]
fn arg_count_error(too_few: bool) -> Exn {
    err(if too_few {
        "too few arguments"
    } else {
        "too many arguments"
    })
}

fn arity_error(too_few: bool, span: Option<Span>) -> Code {
    fail(
        err(if too_few {
            "too few arguments"
        } else {
            "too many arguments"
        }),
        span,
    )
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
        v.push(a(it)?);
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
            Box::new(move |it: &mut Interp| {
                check_defined(it, fsym, span)?;
                let argv: [Value; $n] = [$(args[$i].eval(it)?),*];
                dispatch(it, fsym, argv, span)
            }) as Code
        }};
    }
    match args.len() {
        0 => Box::new(move |it: &mut Interp| {
            check_defined(it, fsym, span)?;
            dispatch(it, fsym, [], span)
        }),
        1 => fixed!(1, [0]),
        2 => fixed!(2, [0, 1]),
        3 => fixed!(3, [0, 1, 2]),
        4 => fixed!(4, [0, 1, 2, 3]),
        _ => {
            let args = args.into_boxed_slice();
            Box::new(move |it| {
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
                let mut r = (l.body)(it);
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
fn call_computed(f: Code, args: Box<[Code]>, span: Option<Span>) -> Code {
    Box::new(move |it| {
        let fv = f(it)?;
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
        let r = (l.body)(self);
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
    fn offer_error(&mut self, r: LResult) -> LResult {
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
