//! The compiler: forms to closures. Special forms are recognised once, symbols become direct
//! indices into the value cells, and calls look their function up in the symbol's cell at run
//! time (AutoLISP is a Lisp-1 with redefinable functions), so evaluation never walks the list
//! structure or hashes a name.
//!
//! Malformed special forms compile to code that raises AutoLISP's error when (and only when)
//! it runs, as an interpreter would: a bad `setq` inside a function that is never called is
//! not an error.

use std::rc::Rc;

use super::call::call_computed;
pub(super) use super::call::call_symbol;
pub use super::call::Args;
pub use super::code::{Code, Operand};
use super::error::{err, Exn, Span};
use super::eval::Interp;
use super::reader::SpanMap;
use super::symbols::*;
use super::value::{Sym, Value};

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
            Value::Sym(S_T) => Code::new(|_| Ok(Value::T)),
            Value::Sym(s) => {
                let i = s.idx();
                Code::new(move |it| Ok(it.values[i].clone()))
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
                Code::new(move |_| Ok(v.clone()))
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
            0 => Code::new(|_| Ok(Value::Nil)),
            1 => codes.pop().expect("one form"),
            _ => {
                let codes = codes.into_boxed_slice();
                Code::new(move |it| {
                    let (last, init) = codes.split_last().expect("several forms");
                    for c in init {
                        c.run(it)?;
                    }
                    last.run(it)
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
                Code::new(move |_| Ok(v.clone()))
            }
            S_FUNCTION => {
                let v = arg(0);
                if matches!(&v, Value::Cons(c) if c.car.as_sym() == Some(S_LAMBDA)) {
                    self.compile(&v)
                } else {
                    Code::new(move |_| Ok(v.clone()))
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
                        return Code::new(move |it| {
                            if test(it)? {
                                then.eval(it)
                            } else {
                                els.eval(it)
                            }
                        })
                    }
                    Err(code) => code,
                };
                Code::new(move |it| {
                    let t = test.run(it)?;
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
                Code::new(move |it| {
                    for p in parts.iter() {
                        if p.run(it)?.truthy() == want {
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
                        return Code::new(move |it| {
                            let mut last = Value::Nil;
                            while test(it)? {
                                it.tick()?;
                                std::mem::replace(&mut last, body.run(it)?).release();
                            }
                            Ok(last)
                        })
                    }
                    Err(code) => code,
                };
                Code::new(move |it| {
                    let mut last = Value::Nil;
                    loop {
                        let t = test.run(it)?;
                        let go = t.truthy();
                        t.release();
                        if !go {
                            break;
                        }
                        it.tick()?;
                        std::mem::replace(&mut last, body.run(it)?).release();
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
                Code::new(move |it| {
                    let c = count.run(it)?;
                    let times = match c {
                        Value::Int(i) => i,
                        _ => return Err(it_bad_arg(it, "fixnump", &c, span)),
                    };
                    let mut last = Value::Nil;
                    for _ in 0..times.max(0) {
                        it.tick()?;
                        last = body.run(it)?;
                    }
                    Ok(last)
                })
            }
            S_FOREACH => self.compile_foreach(rest, n, span),
            S_DEFUN | S_DEFUN_Q => self.compile_defun(head, rest, span),
            S_LAMBDA => match self.lambda(None, rest) {
                Ok(l) => {
                    let f = Value::Func(Rc::new(l));
                    Code::new(move |_| Ok(f.clone()))
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
            return Code::new(|_| Ok(Value::Nil));
        }
        let mut pairs: Vec<(Sym, Operand)> = Vec::new();
        for chunk in items.chunks(2) {
            let target = match chunk[0] {
                Value::Sym(s) if *s != S_T => *s,
                other => {
                    let other = other.clone();
                    return Code::new(move |it| Err(it_bad_arg(it, "symbolp", &other, span)));
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
                Operand::Code(code) => Code::new(move |it| {
                    let v = code.run(it)?;
                    std::mem::replace(&mut it.values[i], v.clone()).release();
                    Ok(v)
                }),
                other => Code::new(move |it| {
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
        Code::new(move |it| {
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
                return Code::new(move |it| Err(it_bad_arg(it, "consp", &c, span)));
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
        Code::new(move |it| {
            for (test, body) in clauses.iter() {
                let t = test.run(it)?;
                if t.truthy() {
                    return match body {
                        Some(b) => b.run(it),
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
            other => return Code::new(move |it| Err(it_bad_arg(it, "symbolp", &other, span))),
        };
        let list = self.compile(&rest.cdr().car());
        let body = self.compile_body(&rest.cdr().cdr());
        Code::new(move |it| {
            let l = list.run(it)?;
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
                last = body.run(it);
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
            other => return Code::new(move |it| Err(it_bad_arg(it, "symbolp", &other, span))),
        };
        if !rest.cdr().is_list() || rest.cdr().is_nil() {
            return arity_error(true, span);
        }
        if head == S_DEFUN_Q {
            // defun-q keeps the definition as a list: ((params / locals) body...).
            let def = rest.cdr();
            return Code::new(move |it| {
                it.values[name.idx()] = def.clone();
                Ok(Value::Sym(name))
            });
        }
        match self.lambda(Some(name), &rest.cdr()) {
            Ok(l) => {
                let f = Value::Func(Rc::new(l));
                Code::new(move |it| {
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
pub(super) fn with_span(e: Exn, span: Option<Span>) -> Exn {
    match span {
        Some(s) => e.with_span(s),
        None => e,
    }
}

fn fail(e: Exn, span: Option<Span>) -> Code {
    Code::new(move |_| Err(with_span(e.clone(), span)))
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
