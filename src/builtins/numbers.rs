//! Numbers: AutoLISP arithmetic (32-bit integers that wrap, reals, integer division),
//! comparison, transcendental functions and bit operations.

use crate::builtin;
use crate::lang::builtin::{bad_arg, Builtin, MANY};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("+", "(+ [number...])", "The sum; integer if every argument is an integer (32-bit, wrapping), else real.", 0, MANY, add),
    builtin!("-", "(- [number [number...]])", "The first number minus the rest; with one argument, its negation.", 0, MANY, sub),
    builtin!("*", "(* [number...])", "The product; integer if every argument is an integer.", 0, MANY, mul),
    builtin!("/", "(/ [number [number...]])", "The first number divided by the rest; integer division (truncating) when all are integers.", 0, MANY, div),
    builtin!("rem", "(rem [number number...])", "The remainder of dividing the first number by the rest (sign of the dividend); 0 without arguments.", 0, MANY, rem),
    builtin!("1+", "(1+ number)", "The number plus 1.", 1, 1, one_plus),
    builtin!("1-", "(1- number)", "The number minus 1.", 1, 1, one_minus),
    builtin!("abs", "(abs number)", "The absolute value.", 1, 1, abs),
    builtin!("fix", "(fix number)", "The number truncated toward zero to an integer.", 1, 1, fix),
    builtin!("float", "(float number)", "The number as a real.", 1, 1, float),
    builtin!("max", "(max [number...])", "The largest number (real if any argument is real); 0 without arguments.", 0, MANY, max),
    builtin!("min", "(min [number...])", "The smallest number (real if any argument is real); 0 without arguments.", 0, MANY, min),
    builtin!("gcd", "(gcd int int)", "The greatest common divisor of two integers.", 2, 2, gcd),
    builtin!("lcm", "(lcm int int...)", "The least common multiple of integers.", 1, MANY, lcm),
    builtin!("sqrt", "(sqrt number)", "The square root, as a real.", 1, 1, sqrt),
    builtin!("expt", "(expt base power)", "base raised to power; an integer when both are integers.", 2, 2, expt),
    builtin!("exp", "(exp number)", "e raised to the number.", 1, 1, exp),
    builtin!("log", "(log number)", "The natural logarithm of a positive number.", 1, 1, log),
    builtin!("sin", "(sin angle)", "The sine of an angle in radians.", 1, 1, sin),
    builtin!("cos", "(cos angle)", "The cosine of an angle in radians.", 1, 1, cos),
    builtin!("atan", "(atan y [x])", "The arctangent of y (or of y/x, in the right quadrant), in radians.", 1, 2, atan),
    builtin!("~", "(~ int)", "The bitwise NOT of an integer.", 1, 1, bitnot),
    builtin!("logand", "(logand int...)", "The bitwise AND of integers.", 0, MANY, logand),
    builtin!("logior", "(logior int...)", "The bitwise OR of integers.", 0, MANY, logior),
    builtin!("lsh", "(lsh int bits)", "int shifted left by bits (right when negative).", 1, 2, lsh),
    builtin!("boole", "(boole op int int...)", "A general bitwise function: op's bits 8/4/2/1 select the result for 00/01/10/11 bit pairs.", 3, MANY, boole),
    builtin!("=", "(= x y...)", "T if all arguments are numerically equal (or equal strings).", 1, MANY, num_eq),
    builtin!("/=", "(/= x y...)", "T if each argument differs from the one after it.", 1, MANY, num_ne),
    builtin!("<", "(< x y...)", "T if each argument is less than the next (numbers or strings).", 1, MANY, lt),
    builtin!("<=", "(<= x y...)", "T if each argument is less than or equal to the next.", 1, MANY, le),
    builtin!(">", "(> x y...)", "T if each argument is greater than the next.", 1, MANY, gt),
    builtin!(">=", "(>= x y...)", "T if each argument is greater than or equal to the next.", 1, MANY, ge),
    builtin!("zerop", "(zerop number)", "T if the number is zero.", 1, 1, zerop),
    builtin!("minusp", "(minusp number)", "T if the number is negative.", 1, 1, minusp),
    builtin!("numberp", "(numberp x)", "T if x is an integer or a real.", 1, 1, numberp),
    builtin!("cvunit", "(cvunit value from to)", "Converts a number (or a list of numbers) between units of length, angle, area or volume, e.g. \"inch\" \"mm\"; nil if unknown or incompatible.", 3, 3, cvunit),
];

/// Folds integer-or-real arithmetic: stays integer (wrapping) until a real appears.
#[inline]
fn arith(
    it: &Interp,
    a: &[Value],
    int_op: fn(i32, i32) -> Option<i32>,
    real_op: fn(f64, f64) -> f64,
) -> LResult {
    let mut acc = match &a[0] {
        Value::Int(i) => Value::Int(*i),
        Value::Real(r) => Value::Real(*r),
        other => return Err(bad_arg(it, "numberp", other)),
    };
    for x in &a[1..] {
        acc = match (&acc, x) {
            (Value::Int(p), Value::Int(q)) => match int_op(*p, *q) {
                Some(v) => Value::Int(v),
                None => return Err(err("divide by zero")),
            },
            (_, Value::Int(_) | Value::Real(_)) => {
                let (p, q) = (acc.as_f64().expect("number"), x.as_f64().expect("number"));
                Value::Real(real_op(p, q))
            }
            _ => return Err(bad_arg(it, "numberp", x)),
        };
    }
    Ok(acc)
}

fn add(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return Ok(Value::Int(0));
    }
    arith(it, a, |p, q| Some(p.wrapping_add(q)), |p, q| p + q)
}

fn sub(it: &mut Interp, a: &[Value]) -> LResult {
    match a.len() {
        0 => Ok(Value::Int(0)),
        1 => match &a[0] {
            Value::Int(i) => Ok(Value::Int(i.wrapping_neg())),
            Value::Real(r) => Ok(Value::Real(-r)),
            other => Err(bad_arg(it, "numberp", other)),
        },
        _ => arith(it, a, |p, q| Some(p.wrapping_sub(q)), |p, q| p - q),
    }
}

fn mul(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return Ok(Value::Int(1));
    }
    arith(it, a, |p, q| Some(p.wrapping_mul(q)), |p, q| p * q)
}

fn div(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return Ok(Value::Int(0));
    }
    for x in &a[1..] {
        if x.as_f64() == Some(0.0) {
            return Err(err("divide by zero"));
        }
    }
    arith(
        it,
        a,
        |p, q| p.checked_div(q).or(Some(p.wrapping_div(q))),
        |p, q| p / q,
    )
}

fn rem(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return Ok(Value::Int(0));
    }
    if a.len() == 1 {
        it.num(&a[0])?;
        return Ok(a[0].clone());
    }
    for x in &a[1..] {
        if x.as_f64() == Some(0.0) {
            return Err(err("divide by zero"));
        }
    }
    arith(it, a, |p, q| Some(p.wrapping_rem(q)), |p, q| p % q)
}

fn one_plus(it: &mut Interp, a: &[Value]) -> LResult {
    match &a[0] {
        Value::Int(i) => Ok(Value::Int(i.wrapping_add(1))),
        Value::Real(r) => Ok(Value::Real(r + 1.0)),
        other => Err(bad_arg(it, "numberp", other)),
    }
}

fn one_minus(it: &mut Interp, a: &[Value]) -> LResult {
    match &a[0] {
        Value::Int(i) => Ok(Value::Int(i.wrapping_sub(1))),
        Value::Real(r) => Ok(Value::Real(r - 1.0)),
        other => Err(bad_arg(it, "numberp", other)),
    }
}

fn abs(it: &mut Interp, a: &[Value]) -> LResult {
    match &a[0] {
        Value::Int(i) => Ok(Value::Int(i.wrapping_abs())),
        Value::Real(r) => Ok(Value::Real(r.abs())),
        other => Err(bad_arg(it, "numberp", other)),
    }
}

fn fix(it: &mut Interp, a: &[Value]) -> LResult {
    match &a[0] {
        Value::Int(i) => Ok(Value::Int(*i)),
        Value::Real(r) => {
            let t = r.trunc();
            if t.is_finite() && t >= i32::MIN as f64 && t <= i32::MAX as f64 {
                Ok(Value::Int(t as i32))
            } else {
                // AutoLISP cannot represent it as an integer: keep the truncated real.
                Ok(Value::Real(t))
            }
        }
        other => Err(bad_arg(it, "numberp", other)),
    }
}

fn float(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(it.num(&a[0])?))
}

fn extremum(it: &Interp, a: &[Value], pick_first: fn(f64, f64) -> bool) -> LResult {
    let mut any_real = false;
    let mut best = &a[0];
    let mut best_v = it.num(best)?;
    for x in a {
        let v = it.num(x)?;
        any_real |= matches!(x, Value::Real(_));
        if pick_first(v, best_v) {
            best = x;
            best_v = v;
        }
    }
    Ok(if any_real {
        Value::Real(best_v)
    } else {
        best.clone()
    })
}

// AutoCAD's reference: "If no argument is supplied, max returns 0" (min likewise).
fn max(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return Ok(Value::Int(0));
    }
    extremum(it, a, |v, b| v > b)
}

fn min(it: &mut Interp, a: &[Value]) -> LResult {
    if a.is_empty() {
        return Ok(Value::Int(0));
    }
    extremum(it, a, |v, b| v < b)
}

fn gcd_i(mut a: i64, mut b: i64) -> i64 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

fn gcd(it: &mut Interp, a: &[Value]) -> LResult {
    let (p, q) = (it.int(&a[0])?, it.int(&a[1])?);
    if p <= 0 || q <= 0 {
        return Err(err("bad argument value: positive integers expected"));
    }
    Ok(Value::Int(gcd_i(p as i64, q as i64) as i32))
}

fn lcm(it: &mut Interp, a: &[Value]) -> LResult {
    let mut acc: i64 = it.int(&a[0])? as i64;
    for x in &a[1..] {
        let v = it.int(x)? as i64;
        let g = gcd_i(acc, v);
        acc = if g == 0 { 0 } else { (acc / g * v).abs() };
    }
    Ok(Value::Int(acc as i32))
}

/// AutoLISP's domain error text.
fn undefined_for(it: &Interp, v: &Value) -> Exn {
    err(format!(
        "function undefined for argument: {}",
        it.prin1_string(v)
    ))
}

fn sqrt(it: &mut Interp, a: &[Value]) -> LResult {
    let x = it.num(&a[0])?;
    if x < 0.0 {
        return Err(undefined_for(it, &a[0]));
    }
    Ok(Value::Real(x.sqrt()))
}

fn expt(it: &mut Interp, a: &[Value]) -> LResult {
    if let (Value::Int(b), Value::Int(p)) = (&a[0], &a[1]) {
        return Ok(Value::Int(if *p >= 0 {
            b.wrapping_pow(*p as u32)
        } else {
            match b {
                1 => 1,
                -1 if p % 2 == 0 => 1,
                -1 => -1,
                0 => return Err(err("divide by zero")),
                _ => 0,
            }
        }));
    }
    let (b, p) = (it.num(&a[0])?, it.num(&a[1])?);
    let r = b.powf(p);
    if r.is_nan() {
        return Err(undefined_for(it, &a[0]));
    }
    Ok(Value::Real(r))
}

fn exp(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(it.num(&a[0])?.exp()))
}

fn log(it: &mut Interp, a: &[Value]) -> LResult {
    let x = it.num(&a[0])?;
    if x <= 0.0 {
        return Err(undefined_for(it, &a[0]));
    }
    Ok(Value::Real(x.ln()))
}

fn sin(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(it.num(&a[0])?.sin()))
}

fn cos(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(it.num(&a[0])?.cos()))
}

fn atan(it: &mut Interp, a: &[Value]) -> LResult {
    let y = it.num(&a[0])?;
    if a.len() == 2 {
        let x = it.num(&a[1])?;
        return Ok(Value::Real(y.atan2(x)));
    }
    Ok(Value::Real(y.atan()))
}

fn bitnot(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Int(!it.int(&a[0])?))
}

fn logand(it: &mut Interp, a: &[Value]) -> LResult {
    let mut acc = -1i32;
    for x in a {
        acc &= it.int(x)?;
    }
    Ok(Value::Int(if a.is_empty() { 0 } else { acc }))
}

fn logior(it: &mut Interp, a: &[Value]) -> LResult {
    let mut acc = 0i32;
    for x in a {
        acc |= it.int(x)?;
    }
    Ok(Value::Int(acc))
}

fn lsh(it: &mut Interp, a: &[Value]) -> LResult {
    let v = it.int(&a[0])?;
    let n = if a.len() > 1 { it.int(&a[1])? } else { 0 };
    Ok(Value::Int(if n >= 32 || n <= -32 {
        0
    } else if n >= 0 {
        ((v as u32) << n) as i32
    } else {
        ((v as u32) >> (-n)) as i32
    }))
}

fn boole(it: &mut Interp, a: &[Value]) -> LResult {
    let op = it.int(&a[0])?;
    let mut acc = it.int(&a[1])?;
    for x in &a[2..] {
        let b = it.int(x)?;
        let mut r = 0;
        if op & 8 != 0 {
            r |= !acc & !b;
        }
        if op & 4 != 0 {
            r |= !acc & b;
        }
        if op & 2 != 0 {
            r |= acc & !b;
        }
        if op & 1 != 0 {
            r |= acc & b;
        }
        acc = r;
    }
    Ok(Value::Int(acc))
}

/// Compares two numbers or two strings; None when they are not comparable.
/// The order of two numbers or two strings; `None` when a NaN is involved (unordered).
fn compare(it: &Interp, x: &Value, y: &Value) -> Result<Option<std::cmp::Ordering>, Exn> {
    match (x, y) {
        (Value::Int(p), Value::Int(q)) => Ok(Some(p.cmp(q))),
        (Value::Str(p), Value::Str(q)) => Ok(Some(p.as_bytes().cmp(q.as_bytes()))),
        _ => {
            let p = x.as_f64().ok_or_else(|| bad_arg(it, "numberp", x))?;
            let q = y.as_f64().ok_or_else(|| bad_arg(it, "numberp", y))?;
            Ok(p.partial_cmp(&q))
        }
    }
}

/// An unordered pair (a NaN) fails every test, as the compiled fast path's IEEE compares do.
fn chain(it: &Interp, a: &[Value], ok: fn(std::cmp::Ordering) -> bool) -> LResult {
    if a.len() == 1 {
        compare(it, &a[0], &a[0])?;
    }
    for w in a.windows(2) {
        if !compare(it, &w[0], &w[1])?.is_some_and(ok) {
            return Ok(Value::Nil);
        }
    }
    Ok(Value::T)
}

fn num_eq(_: &mut Interp, a: &[Value]) -> LResult {
    // Numbers compare by value, strings by content; anything else as `eq` does, as in
    // AutoCAD: (= 1 "1") and (= '(1) '(1)) are nil, (= 'a 'a) is T, none is an error.
    for w in a.windows(2) {
        let same = match (&w[0], &w[1]) {
            (Value::Str(p), Value::Str(q)) => p == q,
            (p, q) => match (p.as_f64(), q.as_f64()) {
                (Some(x), Some(y)) => x == y,
                _ => p.is_eq(q),
            },
        };
        if !same {
            return Ok(Value::Nil);
        }
    }
    Ok(Value::T)
}

fn num_ne(it: &mut Interp, a: &[Value]) -> LResult {
    for w in a.windows(2) {
        if num_eq(it, w)?.truthy() {
            return Ok(Value::Nil);
        }
    }
    Ok(Value::T)
}

fn lt(it: &mut Interp, a: &[Value]) -> LResult {
    chain(it, a, |o| o.is_lt())
}

fn le(it: &mut Interp, a: &[Value]) -> LResult {
    chain(it, a, |o| o.is_le())
}

fn gt(it: &mut Interp, a: &[Value]) -> LResult {
    chain(it, a, |o| o.is_gt())
}

fn ge(it: &mut Interp, a: &[Value]) -> LResult {
    chain(it, a, |o| o.is_ge())
}

fn zerop(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(it.num(&a[0])? == 0.0))
}

fn minusp(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(it.num(&a[0])? < 0.0))
}

fn numberp(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(a[0].as_f64().is_some()))
}

/// The units `cvunit` knows (a subset of AutoCAD's acad.unt): (names, dimension, factor to the
/// base unit). Length in metres, angle in radians; area and volume are length² and length³.
const UNITS: &[(&[&str], u8, f64)] = &[
    (
        &[
            "millimeter",
            "millimeters",
            "millimetre",
            "millimetres",
            "mm",
        ],
        1,
        1e-3,
    ),
    (
        &[
            "centimeter",
            "centimeters",
            "centimetre",
            "centimetres",
            "cm",
        ],
        1,
        1e-2,
    ),
    (
        &["decimeter", "decimeters", "decimetre", "decimetres", "dm"],
        1,
        0.1,
    ),
    (&["meter", "meters", "metre", "metres", "m"], 1, 1.0),
    (
        &["kilometer", "kilometers", "kilometre", "kilometres", "km"],
        1,
        1e3,
    ),
    (
        &["micron", "microns", "micrometer", "micrometers", "um"],
        1,
        1e-6,
    ),
    (&["inch", "inches", "in"], 1, 0.0254),
    (&["foot", "feet", "ft"], 1, 0.3048),
    (&["yard", "yards", "yd"], 1, 0.9144),
    (&["mile", "miles", "mi"], 1, 1609.344),
    (&["mil", "mils"], 1, 0.0000254),
    (&["point", "points", "pt"], 1, 0.0254 / 72.0),
    (&["radian", "radians", "rad"], 2, 1.0),
    (
        &["degree", "degrees", "deg"],
        2,
        std::f64::consts::PI / 180.0,
    ),
    (
        &["grad", "grads", "gradian", "gradians", "grd"],
        2,
        std::f64::consts::PI / 200.0,
    ),
    (
        &["circle", "circles", "revolution", "revolutions", "rev"],
        2,
        std::f64::consts::TAU,
    ),
];

/// (dimension, factor) of a unit name: "inch", "sq inch", "cu mm"; case-insensitive.
fn unit(name: &str) -> Option<(u8, f64)> {
    let n = name.trim().to_lowercase();
    let (power, base) = if let Some(b) = n.strip_prefix("sq ").or(n.strip_prefix("square ")) {
        (2, b.trim())
    } else if let Some(b) = n.strip_prefix("cu ").or(n.strip_prefix("cubic ")) {
        (3, b.trim())
    } else {
        (1, n.as_str())
    };
    let &(_, dim, f) = UNITS.iter().find(|(names, _, _)| names.contains(&base))?;
    if power > 1 && dim != 1 {
        return None;
    }
    // Area and volume are separate dimensions of length.
    Some((
        if power == 1 { dim } else { 10 + power },
        f.powi(power as i32),
    ))
}

fn cvunit(it: &mut Interp, a: &[Value]) -> LResult {
    let from = it.string(&a[1])?.to_string();
    let to = it.string(&a[2])?.to_string();
    let (Some((d1, f1)), Some((d2, f2))) = (unit(&from), unit(&to)) else {
        return Ok(Value::Nil);
    };
    if d1 != d2 {
        return Ok(Value::Nil);
    }
    let k = f1 / f2;
    match &a[0] {
        Value::Cons(_) => {
            let mut out = Vec::new();
            for x in a[0].iter() {
                out.push(Value::Real(it.num(x)? * k));
            }
            Ok(Value::list(out))
        }
        v => Ok(Value::Real(it.num(v)? * k)),
    }
}
