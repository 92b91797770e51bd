//! Inline arithmetic and comparison: calls of `+ - * / < > <= >= = /= 1+ 1- sin cos` with one
//! or two arguments compile to code that does the operation directly on integers and reals,
//! after one pointer comparison showing the symbol still holds the builtin (AutoLISP lets a
//! program redefine `+`; then the ordinary call path runs). Anything unusual — a non-number,
//! division by zero — also falls back to the builtin itself, so errors and results are the
//! library's own. `cons`, `car` and `cdr` get the same treatment.

use std::sync::OnceLock;

use super::builtin::Builtin;
use super::code::Ret;
use super::compile::{call_symbol, Code, Operand};
use super::error::{Exn, LResult, Span};
use super::eval::Interp;
use super::value::{Sym, Value};

#[derive(Clone, Copy)]
#[repr(u8)]
enum Bin {
    Add,
    Sub,
    Mul,
    Div,
    Lt,
    Gt,
    Le,
    Ge,
    Eq,
    Ne,
}

#[derive(Clone, Copy)]
#[repr(u8)]
enum Un {
    Inc,
    Dec,
    Neg,
    Sin,
    Cos,
}

/// The operator back from the const parameter the code closures carry it in: the closures
/// are monomorphised per operator, so this folds away and no `match` on the operator runs.
#[inline(always)]
const fn bin_of(op: u8) -> Bin {
    const ALL: [Bin; 10] = [
        Bin::Add,
        Bin::Sub,
        Bin::Mul,
        Bin::Div,
        Bin::Lt,
        Bin::Gt,
        Bin::Le,
        Bin::Ge,
        Bin::Eq,
        Bin::Ne,
    ];
    ALL[op as usize]
}

#[inline(always)]
const fn un_of(op: u8) -> Un {
    const ALL: [Un; 5] = [Un::Inc, Un::Dec, Un::Neg, Un::Sin, Un::Cos];
    ALL[op as usize]
}

/// Runs `$body` with `$o` a `const u8` naming the operator `$op`, for each possible operator.
macro_rules! with_op {
    ($op:expr, $ty:ident [$($v:ident),*], $o:ident => $body:expr) => {
        match $op {
            $($ty::$v => {
                const $o: u8 = $ty::$v as u8;
                $body
            })*
        }
    };
}

struct Known {
    bins: Vec<(&'static str, Bin, &'static Builtin)>,
    uns: Vec<(&'static str, Un, &'static Builtin)>,
    cons: &'static Builtin,
    car: &'static Builtin,
    cdr: &'static Builtin,
}

/// The library's descriptors of the inlined functions, once the host has installed the
/// library; before that (a bare interpreter) every call takes the ordinary path.
static KNOWN: OnceLock<Option<Known>> = OnceLock::new();

/// Tells the compiler which library functions it inlines: `find` gives the descriptor the
/// library registers for each name (`+`, `-`, ... `cons`, `car`, `cdr`). Called by the host as
/// it installs the library; the descriptors are static, so the first call settles it for the
/// process. A name `find` does not know disables the fast path rather than failing.
pub fn register_inlined(find: impl Fn(&str) -> Option<&'static Builtin>) {
    KNOWN.get_or_init(|| {
        let bins = [
            ("+", Bin::Add),
            ("-", Bin::Sub),
            ("*", Bin::Mul),
            ("/", Bin::Div),
            ("<", Bin::Lt),
            (">", Bin::Gt),
            ("<=", Bin::Le),
            (">=", Bin::Ge),
            ("=", Bin::Eq),
            ("/=", Bin::Ne),
        ];
        let uns = [
            ("1+", Un::Inc),
            ("1-", Un::Dec),
            ("-", Un::Neg),
            ("sin", Un::Sin),
            ("cos", Un::Cos),
        ];
        Some(Known {
            bins: bins
                .iter()
                .map(|(n, b)| Some((*n, *b, find(n)?)))
                .collect::<Option<_>>()?,
            uns: uns
                .iter()
                .map(|(n, u)| Some((*n, *u, find(n)?)))
                .collect::<Option<_>>()?,
            cons: find("cons")?,
            car: find("car")?,
            cdr: find("cdr")?,
        })
    });
}

/// Shared by the integer and real arms. The plain operators (not `partial_cmp`) keep the IEEE
/// answers for NaN: every ordering and `=` false, `/=` true.
#[inline(always)]
fn compare<T: PartialOrd>(op: Bin, a: T, b: T) -> Value {
    Value::bool(match op {
        Bin::Lt => a < b,
        Bin::Gt => a > b,
        Bin::Le => a <= b,
        Bin::Ge => a >= b,
        Bin::Eq => a == b,
        Bin::Ne => a != b,
        // Callers route only the comparisons here; once inlined this arm is dead code.
        Bin::Add | Bin::Sub | Bin::Mul | Bin::Div => unreachable!("not a comparison"),
    })
}

#[inline(always)]
fn bin_numbers(op: Bin, x: &Value, y: &Value) -> Option<Value> {
    match (x, y) {
        (Value::Int(a), Value::Int(b)) => {
            let (a, b) = (*a, *b);
            Some(match op {
                Bin::Add => Value::Int(a.wrapping_add(b)),
                Bin::Sub => Value::Int(a.wrapping_sub(b)),
                Bin::Mul => Value::Int(a.wrapping_mul(b)),
                Bin::Div => {
                    if b == 0 || (a == i32::MIN && b == -1) {
                        return None;
                    }
                    Value::Int(a / b)
                }
                Bin::Lt | Bin::Gt | Bin::Le | Bin::Ge | Bin::Eq | Bin::Ne => compare(op, a, b),
            })
        }
        _ => {
            let a = x.as_f64()?;
            let b = y.as_f64()?;
            Some(match op {
                Bin::Add => Value::Real(a + b),
                Bin::Sub => Value::Real(a - b),
                Bin::Mul => Value::Real(a * b),
                Bin::Div => {
                    if b == 0.0 {
                        return None;
                    }
                    Value::Real(a / b)
                }
                Bin::Lt | Bin::Gt | Bin::Le | Bin::Ge | Bin::Eq | Bin::Ne => compare(op, a, b),
            })
        }
    }
}

#[inline(always)]
fn un_number(op: Un, x: &Value) -> Option<Value> {
    Some(match (op, x) {
        (Un::Inc, Value::Int(a)) => Value::Int(a.wrapping_add(1)),
        (Un::Dec, Value::Int(a)) => Value::Int(a.wrapping_sub(1)),
        (Un::Neg, Value::Int(a)) => Value::Int(a.wrapping_neg()),
        (Un::Inc, Value::Real(a)) => Value::Real(a + 1.0),
        (Un::Dec, Value::Real(a)) => Value::Real(a - 1.0),
        (Un::Neg, Value::Real(a)) => Value::Real(-a),
        (Un::Sin, v) => Value::Real(v.as_f64()?.sin()),
        (Un::Cos, v) => Value::Real(v.as_f64()?.cos()),
        _ => return None,
    })
}

/// The slow path: whatever the symbol holds now, called the ordinary way.
#[cold]
fn fallback(it: &mut Interp, fsym: Sym, args: &[Value], span: Option<Span>) -> LResult {
    let f = it.values[fsym.idx()].clone();
    let with_span = |e: Exn| match span {
        Some(s) => e.with_span(s),
        None => e,
    };
    if f.is_nil() {
        return Err(with_span(super::error::err(format!(
            "no function definition: {}",
            it.syms.name(fsym)
        ))));
    }
    it.apply(&f, args).map_err(with_span)
}

/// `fallback` with the two arguments by value: the hot path then builds no argument array
/// for it (the compiler stored both values in one on every call, in case).
#[cold]
#[inline(never)]
fn fallback2(it: &mut Interp, fsym: Sym, x: Value, y: Value, span: Option<Span>) -> LResult {
    fallback(it, fsym, &[x, y], span)
}

/// An operand whose evaluation is known when compiling, so the closures below are
/// monomorphised per operand shape and a variable or constant costs no indirect call.
trait Opnd: 'static {
    fn get(&self, it: &mut Interp) -> LResult;
}

struct OVar(usize);
/// An integer constant (`(- n 1)`, `(< i 10)`): its type known when compiling, so the
/// arithmetic's type dispatch on it folds away.
struct OInt(i32);
struct OConst(Value);
struct OCode(Code);

impl Opnd for OInt {
    #[inline(always)]
    fn get(&self, _: &mut Interp) -> LResult {
        Ok(Value::Int(self.0))
    }
}

impl Opnd for OVar {
    #[inline(always)]
    fn get(&self, it: &mut Interp) -> LResult {
        // Numbers first: a copy without the generic clone's dispatch over every variant.
        Ok(match &it.values[self.0] {
            Value::Int(i) => Value::Int(*i),
            Value::Real(r) => Value::Real(*r),
            v => v.clone(),
        })
    }
}

impl Opnd for OConst {
    #[inline(always)]
    fn get(&self, _: &mut Interp) -> LResult {
        Ok(self.0.clone())
    }
}

impl Opnd for OCode {
    #[inline(always)]
    fn get(&self, it: &mut Interp) -> LResult {
        self.0.run(it)
    }
}

/// `(+ v k)`, `(- v k)`, `(1+ v)`, `(1- v)` with `v` a variable and `k` an integer constant, as
/// an operand: a call's argument (`(fib (- n 1))`), a branch, a `setq` value. Evaluated in the
/// caller's own code, without a closure call and the result passed through memory (two of
/// them per fib call were a fifth of its instructions). The general path is `bin_code`'s and
/// `un_code`'s: redefined operators, reals and non-numbers go there.
pub struct Arith {
    var: usize,
    /// What the operation adds to an integer (`-k` for `-`; the sums wrap alike).
    delta: i32,
    op: ArithOp,
    head: Sym,
    b: &'static Builtin,
    span: Option<Span>,
}

enum ArithOp {
    Bin(Bin, i32),
    Un(Un),
}

impl Arith {
    #[inline(always)]
    pub fn eval(&self, it: &mut Interp) -> LResult {
        match self.fast(it) {
            Some(n) => Ok(Value::Int(n)),
            None => self.general(it),
        }
    }

    /// The integer result when the variable holds an integer and the operator its builtin.
    #[inline(always)]
    pub fn fast(&self, it: &Interp) -> Option<i32> {
        if let Value::Int(a) = it.values[self.var] {
            if holds(it, self.head.idx(), self.b) {
                return Some(a.wrapping_add(self.delta));
            }
        }
        None
    }

    #[cold]
    #[inline(never)]
    fn general(&self, it: &mut Interp) -> LResult {
        let xv = it.values[self.var].clone();
        let fi = self.head.idx();
        match self.op {
            ArithOp::Bin(op, k) => {
                let yv = Value::Int(k);
                match bin_numbers(op, &xv, &yv) {
                    Some(v) if holds(it, fi, self.b) => Ok(v),
                    _ => fallback2(it, self.head, xv, yv, self.span),
                }
            }
            ArithOp::Un(op) => match un_number(op, &xv) {
                Some(v) if holds(it, fi, self.b) => Ok(v),
                _ => fallback(it, self.head, &[xv], self.span),
            },
        }
    }
}

/// The `Arith` operand of `(head args...)`, when it is one of its shapes.
pub fn arith(head: Sym, name: &str, args: &Value, span: Option<Span>) -> Option<Arith> {
    let k = KNOWN.get().and_then(Option::as_ref)?;
    let var = |v: &Value| match v {
        Value::Sym(s) if *s != super::symbols::S_T => Some(s.idx()),
        _ => None,
    };
    let a: Vec<&Value> = args.iter().collect();
    let lname = name.to_ascii_lowercase();
    let (op, delta, b) = match (lname.as_str(), a.as_slice()) {
        ("+" | "-", [x, Value::Int(c)]) => {
            let (_, op, b) = k.bins.iter().find(|(n, _, _)| *n == lname)?;
            let delta = if lname == "+" { *c } else { c.wrapping_neg() };
            var(x)?;
            (ArithOp::Bin(*op, *c), delta, *b)
        }
        ("1+" | "1-", [x]) => {
            let (_, op, b) = k.uns.iter().find(|(n, _, _)| *n == lname)?;
            var(x)?;
            (ArithOp::Un(*op), if lname == "1+" { 1 } else { -1 }, *b)
        }
        _ => return None,
    };
    Some(Arith {
        var: var(a[0])?,
        delta,
        op,
        head,
        b,
        span,
    })
}

/// Runs `$body` with `$x` bound to the operand as its concrete `Opnd` type.
macro_rules! with_opnd {
    ($o:expr, $x:ident => $body:expr) => {
        match $o {
            Operand::Var(i) => {
                let $x = OVar(i);
                $body
            }
            Operand::Const(Value::Int(k)) => {
                let $x = OInt(k);
                $body
            }
            Operand::Const(v) => {
                let $x = OConst(v);
                $body
            }
            Operand::Code(c) => {
                let $x = OCode(c);
                $body
            }
            a @ Operand::Arith(_) => {
                let $x = OCode(a.into_code());
                $body
            }
        }
    };
}

#[inline(always)]
fn holds(it: &Interp, fi: usize, b: &'static Builtin) -> bool {
    matches!(&it.values[fi], Value::Subr(f) if std::ptr::eq(*f, b))
}

fn bin_code<const OP: u8, X: Opnd, Y: Opnd>(
    head: Sym,
    b: &'static Builtin,
    x: X,
    y: Y,
    span: Option<Span>,
) -> Code {
    let fi = head.idx();
    Code::new(move |it| {
        let xv = x.get(it)?;
        let yv = y.get(it)?;
        // The cell first, then the arithmetic: with the result computed before the check, it
        // went to the stack field by field and was copied out as 16 bytes, a store-forwarding
        // stall that made the float loop a third slower on fewer instructions.
        if holds(it, fi, b) {
            if let Some(v) = bin_numbers(bin_of(OP), &xv, &yv) {
                // Both are numbers: nothing to drop.
                std::mem::forget(xv);
                std::mem::forget(yv);
                return Ok(v);
            }
        }
        fallback2(it, head, xv, yv, span)
    })
}

fn un_code<const OP: u8, X: Opnd>(
    head: Sym,
    b: &'static Builtin,
    x: X,
    span: Option<Span>,
) -> Code {
    let fi = head.idx();
    Code::new(move |it| {
        let xv = x.get(it)?;
        if holds(it, fi, b) {
            if let Some(v) = un_number(un_of(OP), &xv) {
                std::mem::forget(xv);
                return Ok(v);
            }
        }
        fallback(it, head, &[xv], span)
    })
}

/// `(cons a b)` builds the cell from the evaluated arguments without copying them again.
fn cons_code<X: Opnd, Y: Opnd>(
    head: Sym,
    b: &'static Builtin,
    x: X,
    y: Y,
    span: Option<Span>,
) -> Code {
    let fi = head.idx();
    Code::new(move |it| {
        let xv = x.get(it)?;
        let yv = y.get(it)?;
        if holds(it, fi, b) {
            return Ok(Value::cons(xv, yv));
        }
        fallback(it, head, &[xv, yv], span)
    })
}

/// `(car l)` / `(cdr l)` on a list; anything else goes to the builtin for its error.
fn carcdr_code<X: Opnd>(
    head: Sym,
    cdr: bool,
    b: &'static Builtin,
    x: X,
    span: Option<Span>,
) -> Code {
    let fi = head.idx();
    Code::new(move |it| {
        let xv = x.get(it)?;
        if holds(it, fi, b) {
            match &xv {
                Value::Nil => return Ok(Value::Nil),
                Value::Cons(c) => return Ok(if cdr { c.cdr.clone() } else { c.car.clone() }),
                _ => {}
            }
        }
        fallback(it, head, &[xv], span)
    })
}

/// Whether `name` (a symbol's name) is one of the comparisons `compile_test` fuses.
pub fn is_comparison(name: &str) -> bool {
    matches!(name, "<" | ">" | "<=" | ">=" | "=" | "/=")
}

/// A condition's code: whether the test form's value is true, without making the value.
pub type Test = Box<dyn Fn(&mut Interp) -> Result<bool, Exn>>;

/// Both numbers: the comparison's truth; `None` sends the call to the builtin.
#[inline(always)]
fn cmp_numbers(op: Bin, x: &Value, y: &Value) -> Option<bool> {
    #[inline(always)]
    fn cmp<T: PartialOrd>(op: Bin, a: T, b: T) -> bool {
        match op {
            Bin::Lt => a < b,
            Bin::Gt => a > b,
            Bin::Le => a <= b,
            Bin::Ge => a >= b,
            Bin::Eq => a == b,
            Bin::Ne => a != b,
            Bin::Add | Bin::Sub | Bin::Mul | Bin::Div => unreachable!("not a comparison"),
        }
    }
    match (x, y) {
        (Value::Int(a), Value::Int(b)) => Some(cmp(op, *a, *b)),
        _ => Some(cmp(op, x.as_f64()?, y.as_f64()?)),
    }
}

fn test_code<const OP: u8, X: Opnd, Y: Opnd>(
    head: Sym,
    b: &'static Builtin,
    x: X,
    y: Y,
    span: Option<Span>,
) -> Test {
    let fi = head.idx();
    Box::new(move |it| {
        let xv = x.get(it)?;
        let yv = y.get(it)?;
        if let Some(t) = cmp_numbers(bin_of(OP), &xv, &yv) {
            if holds(it, fi, b) {
                std::mem::forget(xv);
                std::mem::forget(yv);
                return Ok(t);
            }
        }
        test_fallback(it, head, xv, yv, span)
    })
}

/// A comparison's truth from the builtin now in `head`'s cell (redefined, or not numbers).
#[cold]
#[inline(never)]
fn test_fallback(
    it: &mut Interp,
    head: Sym,
    xv: Value,
    yv: Value,
    span: Option<Span>,
) -> Result<bool, Exn> {
    let v = fallback(it, head, &[xv, yv], span)?;
    let t = v.truthy();
    v.release();
    Ok(t)
}

fn if_code<const OP: u8, X: Opnd, Y: Opnd>(
    head: Sym,
    b: &'static Builtin,
    (x, y): (X, Y),
    then: Operand,
    els: Operand,
    span: Option<Span>,
) -> Code {
    // The branch's result goes back packed as it came (a recursion's result passes through
    // every level's `if`).
    Code::new_raw(
        move |it| match if_test::<OP, X, Y>(it, head, b, (&x, &y), span) {
            Ok(true) => then.eval_raw(it),
            Ok(false) => els.eval_raw(it),
            Err(e) => Ret::pack(Err(e)),
        },
    )
}

#[inline(always)]
fn if_test<const OP: u8, X: Opnd, Y: Opnd>(
    it: &mut Interp,
    head: Sym,
    b: &'static Builtin,
    (x, y): (&X, &Y),
    span: Option<Span>,
) -> Result<bool, Exn> {
    let xv = x.get(it)?;
    let yv = y.get(it)?;
    match cmp_numbers(bin_of(OP), &xv, &yv) {
        Some(t) if holds(it, head.idx(), b) => {
            std::mem::forget(xv);
            std::mem::forget(yv);
            Ok(t)
        }
        _ => test_fallback(it, head, xv, yv, span),
    }
}

/// The comparison's operator and builtin, when `name` is an inlined comparison.
fn comparison_op(name: &str) -> Option<(Bin, &'static Builtin)> {
    let k = KNOWN.get().and_then(Option::as_ref)?;
    let lname = name.to_ascii_lowercase();
    let (_, op, b) = k.bins.iter().find(|(n, _, _)| *n == lname)?;
    match op {
        Bin::Add | Bin::Sub | Bin::Mul | Bin::Div => None,
        _ => Some((*op, *b)),
    }
}

/// `(if (< a b) then else)`: the comparison, the choice and the branches in one closure (the
/// test's own closure call and its boolean result were a fifth of fib's time). `Err` gives the
/// pieces back when `head` is not an inlined comparison with two arguments.
#[allow(clippy::type_complexity)]
pub fn compile_if(
    head: Sym,
    name: &str,
    mut args: Vec<Operand>,
    span: Option<Span>,
    then: Operand,
    els: Operand,
) -> Result<Code, (Vec<Operand>, Operand, Operand)> {
    let Some((op, b)) = comparison_op(name).filter(|_| args.len() == 2) else {
        return Err((args, then, els));
    };
    let y = args.pop().expect("two args");
    let x = args.pop().expect("two args");
    macro_rules! if_op {
        ($($v:ident),*) => {
            match op {
                $(Bin::$v => {
                    const O: u8 = Bin::$v as u8;
                    with_opnd!(x, x => with_opnd!(y, y =>
                        if_code::<O, _, _>(head, b, (x, y), then, els, span)))
                })*
                Bin::Add | Bin::Sub | Bin::Mul | Bin::Div => unreachable!("a comparison"),
            }
        };
    }
    Ok(if_op!(Lt, Gt, Le, Ge, Eq, Ne))
}

/// `(if (< a b) ...)`, `(while (< i n) ...)`: a two-argument comparison as a condition gives
/// its truth straight to the branch, instead of a T or nil value to test and drop (fib's
/// base-case test, every counting loop). `None` when `head` is not an inlined comparison
/// or the arity differs; the code falls back to the builtin exactly as the inline call does.
pub fn compile_test(
    head: Sym,
    name: &str,
    mut args: Vec<Operand>,
    span: Option<Span>,
) -> Result<Test, Vec<Operand>> {
    let Some(k) = KNOWN.get().and_then(Option::as_ref) else {
        return Err(args);
    };
    if args.len() != 2 {
        return Err(args);
    }
    let lname = name.to_ascii_lowercase();
    let Some((_, op, b)) = k.bins.iter().find(|(n, _, _)| *n == lname) else {
        return Err(args);
    };
    let (op, b) = (*op, *b);
    if matches!(op, Bin::Add | Bin::Sub | Bin::Mul | Bin::Div) {
        return Err(args);
    }
    let y = args.pop().expect("two args");
    let x = args.pop().expect("two args");
    macro_rules! cmp_op {
        ($($v:ident),*) => {
            match op {
                $(Bin::$v => {
                    const O: u8 = Bin::$v as u8;
                    with_opnd!(x, x => with_opnd!(y, y => test_code::<O, _, _>(head, b, x, y, span)))
                })*
                Bin::Add | Bin::Sub | Bin::Mul | Bin::Div => unreachable!("checked above"),
            }
        };
    }
    Ok(cmp_op!(Lt, Gt, Le, Ge, Eq, Ne))
}

/// Inline code for `(head args...)` when head names a fast-path builtin and the arity fits;
/// otherwise the ordinary call.
pub fn compile(head: Sym, name: &str, mut args: Vec<Operand>, span: Option<Span>) -> Code {
    let Some(k) = KNOWN.get().and_then(Option::as_ref) else {
        return call_symbol(head, args, span);
    };
    let lname = name.to_ascii_lowercase();
    if args.len() == 2 {
        if let Some((_, op, b)) = k.bins.iter().find(|(n, _, _)| *n == lname) {
            let (op, b) = (*op, *b);
            let y = args.pop().expect("two args");
            let x = args.pop().expect("two args");
            return with_op!(op, Bin [Add, Sub, Mul, Div, Lt, Gt, Le, Ge, Eq, Ne], O =>
                with_opnd!(x, x => with_opnd!(y, y => bin_code::<O, _, _>(head, b, x, y, span))));
        }
        if lname == "cons" {
            let y = args.pop().expect("two args");
            let x = args.pop().expect("two args");
            let b = k.cons;
            return with_opnd!(x, x => with_opnd!(y, y => cons_code(head, b, x, y, span)));
        }
    }
    if args.len() == 1 {
        if let Some((_, op, b)) = k.uns.iter().find(|(n, _, _)| *n == lname) {
            let (op, b) = (*op, *b);
            let x = args.pop().expect("one arg");
            return with_op!(op, Un [Inc, Dec, Neg, Sin, Cos], O =>
                with_opnd!(x, x => un_code::<O, _>(head, b, x, span)));
        }
        if lname == "car" || lname == "cdr" {
            let x = args.pop().expect("one arg");
            let (cdr, b) = if lname == "cdr" {
                (true, k.cdr)
            } else {
                (false, k.car)
            };
            return with_opnd!(x, x => carcdr_code(head, cdr, b, x, span));
        }
    }
    call_symbol(head, args, span)
}
