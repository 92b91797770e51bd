//! Strings: formatting numbers and angles, parsing them back, matching and the vl-string
//! family. Thin argument-checking wrappers over the pure functions in `text`; the unit
//! settings come from the system variables (LUNITS, LUPREC, AUNITS, AUPREC, DIMZIN...).

use super::strings::build_string;
use crate::builtin;
use crate::builtins::system::SysVars;
use crate::builtins::text::{self, AngleSettings, FmtError};
use crate::lang::builtin::{Builtin, MANY};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("rtos", "(rtos number [mode [precision]])", "A number as a string: mode 1 scientific, 2 decimal, 3 engineering, 4 architectural, 5 fractional (defaults LUNITS, LUPREC).", 1, 3, rtos),
    builtin!("angtos", "(angtos angle [mode [precision]])", "An angle (radians) as a string: mode 0 degrees, 1 deg/min/sec, 2 grads, 3 radians, 4 surveyor's (defaults AUNITS, AUPREC).", 1, 3, angtos),
    builtin!("distof", "(distof string [mode])", "A distance read from a string in any rtos format, or nil.", 1, 2, distof),
    builtin!("angtof", "(angtof string [mode])", "An angle in radians read from a string in any angtos format, or nil.", 1, 2, angtof),
    builtin!("atoi", "(atoi string)", "The integer a string starts with (0 if none).", 1, 1, atoi),
    builtin!("atof", "(atof string)", "The real a string starts with (0.0 if none).", 1, 1, atof),
    builtin!("substr", "(substr string start [length])", "The part of a string from 1-based start, length characters long (or to the end).", 2, 3, substr),
    builtin!("strcase", "(strcase string [lower])", "The string in upper case, or in lower case when lower is non-nil.", 1, 2, strcase),
    builtin!("wcmatch", "(wcmatch string pattern)", "T if the string matches the wild-card pattern (# @ . * ? ~ [..] ` and , alternatives).", 2, 2, wcmatch),
    builtin!("vl-string-trim", "(vl-string-trim chars string)", "The string without the given characters at both ends.", 2, 2, trim),
    builtin!("vl-string-left-trim", "(vl-string-left-trim chars string)", "The string without the given characters at its start.", 2, 2, left_trim),
    builtin!("vl-string-right-trim", "(vl-string-right-trim chars string)", "The string without the given characters at its end.", 2, 2, right_trim),
    builtin!("vl-string-search", "(vl-string-search pattern string [start])", "The 0-based position of pattern in string, or nil.", 2, 3, search),
    builtin!("vl-string-position", "(vl-string-position code string [start [from-end]])", "The 0-based position of a character code, or nil.", 2, 4, position),
    builtin!("vl-string-subst", "(vl-string-subst new pattern string [start])", "The string with the first occurrence of pattern replaced by new.", 3, 4, subst),
    builtin!("vl-string-translate", "(vl-string-translate from to string)", "The string with each character of from replaced by the one at the same place in to.", 3, 3, translate),
    builtin!("vl-string-mismatch", "(vl-string-mismatch s1 s2 [pos1 pos2 ignore-case])", "The length of the common prefix of s1 and s2 from the given positions.", 2, 5, mismatch),
    builtin!("vl-string-elt", "(vl-string-elt string position)", "The character code at a 0-based position.", 2, 2, elt),
    builtin!("xstrcase", "(xstrcase string)", "The string in upper case.", 1, MANY, xstrcase),
];

fn fmt_err(e: FmtError) -> Exn {
    err(e.to_string())
}

fn opt_int(it: &Interp, a: &[Value], i: usize) -> Result<Option<i32>, Exn> {
    match a.get(i) {
        None | Some(Value::Nil) => Ok(None),
        Some(v) => it.int(v).map(Some),
    }
}

fn rtos(it: &mut Interp, a: &[Value]) -> LResult {
    let x = it.num(&a[0])?;
    let mode = opt_int(it, a, 1)?;
    let prec = opt_int(it, a, 2)?;
    // Each variable is a lookup by name: LUNITS and LUPREC only when the call leaves them out.
    let vars = it.ext::<SysVars>();
    let mode = mode.unwrap_or_else(|| vars.int("LUNITS"));
    let prec = prec.unwrap_or_else(|| vars.int("LUPREC"));
    let (dimzin, unitmode) = (vars.int("DIMZIN"), vars.int("UNITMODE"));
    text::rtos(x, mode, prec, dimzin, unitmode)
        .map(|s| Value::str(&s))
        .map_err(fmt_err)
}

fn angle_settings(it: &mut Interp) -> AngleSettings {
    let vars = it.ext::<SysVars>();
    AngleSettings {
        angbase: vars.real("ANGBASE"),
        angdir: vars.int("ANGDIR"),
        dimzin: vars.int("DIMZIN"),
        unitmode: vars.int("UNITMODE"),
    }
}

fn angtos(it: &mut Interp, a: &[Value]) -> LResult {
    let x = it.num(&a[0])?;
    let settings = angle_settings(it);
    let vars = it.ext::<SysVars>();
    let (aunits, auprec) = (vars.int("AUNITS"), vars.int("AUPREC"));
    let mode = opt_int(it, a, 1)?.unwrap_or(aunits);
    let prec = opt_int(it, a, 2)?.unwrap_or(auprec);
    text::angtos(x, mode, prec, &settings)
        .map(|s| Value::str(&s))
        .map_err(fmt_err)
}

fn real_or_nil(v: Option<f64>) -> Value {
    v.map_or(Value::Nil, Value::Real)
}

fn distof(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?.to_string();
    let mode = opt_int(it, a, 1)?;
    Ok(real_or_nil(text::distof(&s, mode)))
}

fn angtof(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?.to_string();
    let mode = opt_int(it, a, 1)?;
    let settings = angle_settings(it);
    Ok(real_or_nil(text::angtof(&s, mode, &settings)))
}

fn atoi(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Int(text::atoi(it.string(&a[0])?)))
}

fn atof(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(text::atof(it.string(&a[0])?)))
}

fn substr(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?;
    let start = it.int(&a[1])? as i64;
    let len = match a.get(2) {
        Some(v) => Some(it.int(v)? as i64),
        None => None,
    };
    // The copy is asked of the memory budget first (a substring of a huge string is huge).
    super::strings::check_string_room(s.len().min(len.map_or(usize::MAX, |l| l.max(0) as usize)))?;
    text::substr(s, start, len)
        .map(|r| Value::str(&r))
        .map_err(fmt_err)
}

fn strcase(it: &mut Interp, a: &[Value]) -> LResult {
    let lower = a.get(1).is_some_and(Value::truthy);
    let s = it.string(&a[0])?;
    // Case mapping may lengthen a character: twice the bytes is room for any text.
    build_string(s.len().saturating_mul(2), |out| {
        out.push_str(&text::strcase(s, lower))
    })
}

fn xstrcase(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?;
    build_string(s.len().saturating_mul(2), |out| {
        out.push_str(&text::strcase(s, false))
    })
}

fn wcmatch(it: &mut Interp, a: &[Value]) -> LResult {
    let (s, p) = two_strings(it, a)?;
    // Linear-time matching (see text::wcmatch); charged by the size of the job.
    let work = (s.len() as u64).saturating_mul(p.matches('*').count() as u64 + 1) + p.len() as u64;
    let hit = text::wcmatch(s, p);
    it.charge(work)?;
    Ok(Value::bool(hit))
}

fn two_strings<'a>(it: &Interp, a: &'a [Value]) -> Result<(&'a str, &'a str), Exn> {
    Ok((it.string(&a[0])?, it.string(&a[1])?))
}

fn trim(it: &mut Interp, a: &[Value]) -> LResult {
    let (set, s) = two_strings(it, a)?;
    build_string(s.len(), |out| out.push_str(&text::vl_string_trim(set, s)))
}

fn left_trim(it: &mut Interp, a: &[Value]) -> LResult {
    let (set, s) = two_strings(it, a)?;
    build_string(s.len(), |out| {
        out.push_str(&text::vl_string_left_trim(set, s))
    })
}

fn right_trim(it: &mut Interp, a: &[Value]) -> LResult {
    let (set, s) = two_strings(it, a)?;
    build_string(s.len(), |out| {
        out.push_str(&text::vl_string_right_trim(set, s))
    })
}

fn index_or_nil(i: Option<usize>) -> Value {
    i.map_or(Value::Nil, |i| Value::Int(i as i32))
}

fn opt_start(it: &Interp, a: &[Value], i: usize) -> Result<i64, Exn> {
    Ok(opt_int(it, a, i)?.unwrap_or(0) as i64)
}

fn search(it: &mut Interp, a: &[Value]) -> LResult {
    let (pat, s) = two_strings(it, a)?;
    let start = opt_start(it, a, 2)?;
    Ok(index_or_nil(text::vl_string_search(pat, s, start)))
}

fn position(it: &mut Interp, a: &[Value]) -> LResult {
    let code = it.int(&a[0])?;
    let s = it.string(&a[1])?;
    let start = opt_start(it, a, 2)?;
    let from_end = a.get(3).is_some_and(Value::truthy);
    Ok(index_or_nil(text::vl_string_position(
        code.max(0) as u32,
        s,
        start,
        from_end,
    )))
}

fn subst(it: &mut Interp, a: &[Value]) -> LResult {
    let (new, pat) = two_strings(it, a)?;
    let s = it.string(&a[2])?;
    let start = opt_start(it, a, 3)?;
    build_string(s.len().saturating_add(new.len()), |out| {
        out.push_str(&text::vl_string_subst(new, pat, s, start))
    })
}

fn translate(it: &mut Interp, a: &[Value]) -> LResult {
    let (from, to) = two_strings(it, a)?;
    let s = it.string(&a[2])?;
    // A one-byte character may become a four-byte one.
    let widest = to.chars().map(char::len_utf8).max().unwrap_or(1);
    build_string(s.len().saturating_mul(widest), |out| {
        out.push_str(&text::vl_string_translate(from, to, s))
    })
}

fn mismatch(it: &mut Interp, a: &[Value]) -> LResult {
    let (s1, s2) = two_strings(it, a)?;
    let p1 = opt_start(it, a, 2)?;
    let p2 = opt_start(it, a, 3)?;
    let ic = a.get(4).is_some_and(Value::truthy);
    Ok(Value::Int(
        text::vl_string_mismatch(s1, s2, p1, p2, ic) as i32
    ))
}

fn elt(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?;
    let pos = it.int(&a[1])? as i64;
    text::vl_string_elt(s, pos)
        .map(|c| Value::Int(c as i32))
        .ok_or_else(|| {
            err(format!(
                "bad argument value: string position out of range {pos}"
            ))
        })
}
