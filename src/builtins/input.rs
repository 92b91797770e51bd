//! Interactive input: `getpoint getcorner getreal getint getstring getdist getangle getorient
//! getkword initget`.
//!
//! An answer comes from, in order: the scripted answer list (`--answers FILE`, one answer per
//! line, consumed in order), else the terminal when standard input is one (the REPL), else it
//! is an error naming `--answers`. AutoCAD re-prompts on an answer that `initget` forbids; a
//! batch run has no one to ask again, so there such an answer is an error.
//!
//! Answer syntax is AutoCAD's command line: a point `x,y` or `x,y,z` (`#` or `*` before it
//! marks absolute/world input), relative `@dx,dy[,dz]`
//! (to the base point when given, else LASTPOINT), polar `d<a` / `@d<a` (a in degrees); a
//! number as text; an empty line is Enter (nil).

use std::collections::VecDeque;
use std::io::{BufRead, IsTerminal, Write};

use glam::DVec3;

use super::system::SysVars;
use crate::builtin;
use crate::lang::builtin::{point_value, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("initget", "(initget [bits] [keywords])", "Restricts the next get* call: bits 1 no Enter, 2 no zero, 4 no negative, 64 2D distance, 128 arbitrary text; keywords like \"Yes No\".", 0, 2, initget),
    builtin!("getpoint", "(getpoint [base] [prompt])", "Asks for a point (x,y[,z], @dx,dy relative to base, d<a polar); a 3D point, a keyword, or nil on Enter.", 0, 2, getpoint),
    builtin!("getcorner", "(getcorner base [prompt])", "Asks for the opposite corner of a rectangle from base; a 3D point.", 1, 2, getcorner),
    builtin!("getreal", "(getreal [prompt])", "Asks for a number; a real, a keyword, or nil on Enter.", 0, 1, getreal),
    builtin!("getint", "(getint [prompt])", "Asks for an integer in -32768..32767; an integer, a keyword, or nil on Enter.", 0, 1, getint),
    builtin!("getstring", "(getstring [allow-spaces] [prompt])", "Asks for text; without allow-spaces the answer ends at its first space; \"\" on Enter.", 0, 2, getstring),
    builtin!("getdist", "(getdist [base] [prompt])", "Asks for a distance: a number in any linear format (2.5, 1'-6\", 1 1/2), or a point whose distance from base (or from a second point) is taken.", 0, 2, getdist),
    builtin!("getangle", "(getangle [base] [prompt])", "Asks for an angle in degrees (or a point: the angle from base); radians relative to ANGBASE.", 0, 2, getangle),
    builtin!("getorient", "(getorient [base] [prompt])", "Like getangle but absolute: radians from east, counter-clockwise, whatever ANGBASE/ANGDIR.", 0, 2, getorient),
    builtin!("getfiled", "(getfiled title default ext flags)", "Asks for a file name (the dialog's answer, headless from --answers or the terminal); nil on Enter (cancel); ext is added when the name has none.", 4, 4, getfiled),
    builtin!("getkword", "(getkword [prompt])", "Asks for one of the keywords given to initget; returns the keyword as initget spelt it.", 0, 1, getkword),
];

/// Where answers come from, and the pending `initget` restrictions.
#[derive(Default)]
pub struct InputState {
    /// The scripted answers not yet consumed (`--answers FILE`); None without a file.
    pub answers: Option<VecDeque<String>>,
    /// Ask on the terminal when there is no answer list (the interactive REPL).
    pub terminal: bool,
    /// Never ask the terminal, even when stdin is one (parallel batch rows).
    pub no_terminal: bool,
    pending: Option<Initget>,
    /// The rest of a console line `read-char` has started (with its newline).
    chars: VecDeque<char>,
}

impl InputState {
    /// Loads an answers file: one answer per line (a trailing newline does not add an answer).
    pub fn load_answers(&mut self, text: &str) {
        self.answers = Some(
            text.lines()
                .map(|l| l.strip_suffix('\r').unwrap_or(l).to_string())
                .collect(),
        );
    }
}

/// The restrictions `initget` sets for the next get* call only.
#[derive(Clone, Default)]
struct Initget {
    bits: i32,
    /// (what the user may type in full, the shortest accepted abbreviation, what is returned)
    keywords: Vec<Keyword>,
}

#[derive(Clone)]
struct Keyword {
    full: String,
    abbrev: String,
    result: String,
}

const NO_NULL: i32 = 1;
const NO_ZERO: i32 = 2;
const NO_NEGATIVE: i32 = 4;
const FLAT_DIST: i32 = 64;
const ARBITRARY: i32 = 128;

/// Parses initget's keyword string: words separated by spaces; the capital letters of a word
/// are its abbreviation ("LType" accepts "LT"), or "FULL,ABBR"; a "_" separates the local
/// keywords from the global ones returned in their place.
fn parse_keywords(s: &str) -> Vec<Keyword> {
    let (local, global) = match s.split_once('_') {
        Some((l, g)) => (l, Some(g)),
        None => (s, None),
    };
    let globals: Vec<&str> = global
        .map(|g| g.split_whitespace().collect())
        .unwrap_or_default();
    local
        .split_whitespace()
        .enumerate()
        .map(|(i, w)| {
            let (full, abbrev) = match w.split_once(',') {
                Some((f, a)) => (f.to_string(), a.to_uppercase()),
                None => {
                    let caps: String = w.chars().filter(|c| c.is_uppercase()).collect();
                    let abbrev = if caps.is_empty() {
                        w.to_uppercase()
                    } else {
                        caps
                    };
                    (w.to_string(), abbrev)
                }
            };
            let result = globals.get(i).map_or(full.clone(), |g| g.to_string());
            Keyword {
                full,
                abbrev,
                result,
            }
        })
        .collect()
}

impl Initget {
    fn has(&self, bit: i32) -> bool {
        self.bits & bit != 0
    }

    /// The keyword an answer selects: it must start with the abbreviation and be a prefix of
    /// the full word, case-insensitively.
    fn keyword(&self, answer: &str) -> Option<String> {
        let a = answer.trim().to_uppercase();
        if a.is_empty() {
            return None;
        }
        let a = a.strip_prefix('_').unwrap_or(&a);
        self.keywords.iter().find_map(|k| {
            let full = k.full.to_uppercase();
            // Capitals that start the word allow any longer prefix ("LType": LT, LTY...);
            // capitals inside it ("eXit") are typed exactly.
            let by_abbrev = if full.starts_with(&k.abbrev) {
                full.starts_with(a) && a.starts_with(&k.abbrev)
            } else {
                a == k.abbrev
            };
            (by_abbrev || a == full || a == k.result.to_uppercase()).then(|| k.result.clone())
        })
    }
}

fn initget(it: &mut Interp, a: &[Value]) -> LResult {
    let mut ig = Initget::default();
    for v in a {
        match v {
            Value::Int(b) => ig.bits = *b,
            Value::Str(s) => ig.keywords = parse_keywords(s),
            Value::Nil => {}
            other => return Err(crate::lang::builtin::bad_arg(it, "stringp", other)),
        }
    }
    it.ext::<InputState>().pending = Some(ig);
    Ok(Value::Nil)
}

/// One raw answer: from the list, the terminal, or an error.
fn next_answer(it: &mut Interp, func: &str, prompt: Option<&str>) -> Result<String, Exn> {
    let st = it.ext::<InputState>();
    if let Some(list) = st.answers.as_mut() {
        return list
            .pop_front()
            .ok_or_else(|| err(format!("{func}: no answers left in the --answers file")));
    }
    if st.no_terminal || !st.terminal && !std::io::stdin().is_terminal() {
        return Err(err(format!(
            "{func}: no input available (use --answers FILE)"
        )));
    }
    it.write_out(prompt.unwrap_or(""));
    it.flush_out();
    let mut line = String::new();
    let _ = std::io::stdout().flush();
    match std::io::stdin().lock().read_line(&mut line) {
        Ok(0) => Err(err(format!("{func}: end of input"))),
        Ok(_) => Ok(line.trim_end_matches(['\n', '\r']).to_string()),
        Err(e) => Err(err(format!("{func}: cannot read the terminal: {e}"))),
    }
}

/// `(read-line)` without a file: the next console line (answers file or terminal); the rest of
/// a line `read-char` started comes first.
pub fn console_read_line(it: &mut Interp) -> LResult {
    let st = it.ext::<InputState>();
    if !st.chars.is_empty() {
        let rest: String = st.chars.drain(..).collect();
        return Ok(Value::str(rest.trim_end_matches('\n')));
    }
    Ok(Value::str(&next_answer(it, "read-line", None)?))
}

/// `(read-char)` without a file: the next character code of the console input, 10 at the end
/// of each line, as AutoLISP's keyboard buffer gives them.
pub fn console_read_char(it: &mut Interp) -> LResult {
    if it.ext::<InputState>().chars.is_empty() {
        let line = next_answer(it, "read-char", None)?;
        let st = it.ext::<InputState>();
        st.chars.extend(line.chars());
        st.chars.push_back('\n');
    }
    let c = it.ext::<InputState>().chars.pop_front().unwrap_or('\n');
    Ok(Value::Int(c as i32))
}

/// The optional (base point, prompt) arguments in either order, as AutoLISP accepts them.
fn base_and_prompt(it: &Interp, a: &[Value]) -> Result<(Option<DVec3>, Option<String>), Exn> {
    let mut base = None;
    let mut prompt = None;
    for v in a {
        match v {
            Value::Str(s) => prompt = Some(s.to_string()),
            Value::Nil => {}
            _ => {
                let p = it.point(v)?;
                base = Some(DVec3::from_array(p));
            }
        }
    }
    Ok((base, prompt))
}

fn prompt_arg(it: &Interp, a: &[Value]) -> Result<Option<String>, Exn> {
    match a.first() {
        None | Some(Value::Nil) => Ok(None),
        Some(v) => Ok(Some(it.string(v)?.to_string())),
    }
}

/// What an answer turned into, before the type-specific checks.
enum Answer {
    Enter,
    Keyword(String),
    Text(String),
}

/// Reads an answer and resolves Enter and keywords; consumes the pending initget.
fn ask(it: &mut Interp, func: &str, prompt: Option<&str>) -> Result<(Answer, Initget), Exn> {
    let ig = it.ext::<InputState>().pending.take().unwrap_or_default();
    let raw = next_answer(it, func, prompt)?;
    let ans = if raw.trim().is_empty() {
        if ig.has(NO_NULL) {
            return Err(rejected(func, &raw, "an answer is required (initget 1)"));
        }
        Answer::Enter
    } else if let Some(k) = ig.keyword(&raw) {
        Answer::Keyword(k)
    } else {
        Answer::Text(raw.trim().to_string())
    };
    Ok((ans, ig))
}

fn rejected(func: &str, raw: &str, why: &str) -> Exn {
    err(format!("{func}: answer \"{raw}\" rejected: {why}"))
}

/// The value for an answer that is not of the asked kind: the text itself under initget 128,
/// else an error (AutoCAD would re-prompt).
fn other_input(func: &str, ig: &Initget, text: &str, why: &str) -> LResult {
    if ig.has(ARBITRARY) {
        Ok(Value::str(text))
    } else {
        Err(rejected(func, text, why))
    }
}

fn check_sign(func: &str, ig: &Initget, text: &str, x: f64) -> Result<(), Exn> {
    if ig.has(NO_ZERO) && x == 0.0 {
        return Err(rejected(
            func,
            text,
            "the value must be nonzero (initget 2)",
        ));
    }
    if ig.has(NO_NEGATIVE) && x < 0.0 {
        return Err(rejected(
            func,
            text,
            "the value must be nonnegative (initget 4)",
        ));
    }
    Ok(())
}

pub(crate) fn parse_real(t: &str) -> Option<f64> {
    let t = t.trim();
    let ok = !t.is_empty()
        && t.chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'));
    ok.then(|| t.parse::<f64>().ok())
        .flatten()
        .filter(|x| x.is_finite())
}

/// A point typed at the command line, relative forms resolved against `base` (or LASTPOINT).
fn parse_point(it: &mut Interp, t: &str, base: Option<DVec3>) -> Option<DVec3> {
    // "#x,y" (absolute under dynamic input) and "*x,y" (world coordinates) are absolute
    // points; headless, the UCS is the world, so both prefixes just mark absolute input.
    let t = t.trim();
    let t = t.strip_prefix(['#', '*']).unwrap_or(t);
    point_text(t, || base.unwrap_or_else(|| last_point(it)))
}

/// The point syntax `get*` and `command` share: "x,y[,z]", "@dx,dy[,dz]", "d<a", "@d<a"
/// (a in degrees), "@" alone; `last` (asked only for relative input) is what "@" is from.
pub(crate) fn point_text(t: &str, last: impl FnOnce() -> DVec3) -> Option<DVec3> {
    let t = t.trim();
    let (rel, body) = match t.strip_prefix('@') {
        Some(b) => (true, b.trim()),
        None => (false, t),
    };
    let origin = if rel { last() } else { DVec3::ZERO };
    if rel && body.is_empty() {
        return Some(origin);
    }
    if let Some((d, a)) = body.split_once('<') {
        let d = parse_real(d)?;
        let a = parse_real(a)?.to_radians();
        // "d<a" without @ is measured from the origin, as in AutoCAD.
        return Some(origin + DVec3::new(d * a.cos(), d * a.sin(), 0.0));
    }
    let parts: Vec<&str> = body.split(',').collect();
    if !(2..=3).contains(&parts.len()) {
        return None;
    }
    let mut c = [0.0; 3];
    for (i, p) in parts.iter().enumerate() {
        c[i] = parse_real(p)?;
    }
    // An absolute 2D answer takes the elevation 0 (AutoCAD's ELEVATION default).
    Some(origin + DVec3::from_array(c))
}

fn last_point(it: &mut Interp) -> DVec3 {
    let v = it.ext::<SysVars>().get("LASTPOINT").cloned();
    v.and_then(|v| it.point(&v).ok())
        .map(DVec3::from_array)
        .unwrap_or(DVec3::ZERO)
}

fn set_last_point(it: &mut Interp, p: DVec3) {
    it.ext::<SysVars>()
        .put("LASTPOINT", point_value(p.to_array(), 3));
}

/// A point answer, a keyword, arbitrary text, or nil.
fn point_answer(it: &mut Interp, func: &str, a: &[Value], corner: bool) -> LResult {
    let (base, prompt) = base_and_prompt(it, a)?;
    if corner && base.is_none() {
        return Err(err("too few arguments"));
    }
    let (ans, ig) = ask(it, func, prompt.as_deref())?;
    match ans {
        Answer::Enter => Ok(Value::Nil),
        Answer::Keyword(k) => Ok(Value::str(&k)),
        Answer::Text(t) => match parse_point(it, &t, base) {
            Some(p) => {
                set_last_point(it, p);
                Ok(point_value(p.to_array(), 3))
            }
            None => other_input(func, &ig, &t, "not a point (x,y or x,y,z, @dx,dy, d<a)"),
        },
    }
}

fn getpoint(it: &mut Interp, a: &[Value]) -> LResult {
    point_answer(it, "getpoint", a, false)
}

fn getcorner(it: &mut Interp, a: &[Value]) -> LResult {
    point_answer(it, "getcorner", a, true)
}

fn getreal(it: &mut Interp, a: &[Value]) -> LResult {
    let prompt = prompt_arg(it, a)?;
    let (ans, ig) = ask(it, "getreal", prompt.as_deref())?;
    match ans {
        Answer::Enter => Ok(Value::Nil),
        Answer::Keyword(k) => Ok(Value::str(&k)),
        Answer::Text(t) => match parse_real(&t) {
            Some(x) => {
                check_sign("getreal", &ig, &t, x)?;
                Ok(Value::Real(x))
            }
            None => other_input("getreal", &ig, &t, "requires a numeric value"),
        },
    }
}

fn getint(it: &mut Interp, a: &[Value]) -> LResult {
    let prompt = prompt_arg(it, a)?;
    let (ans, ig) = ask(it, "getint", prompt.as_deref())?;
    match ans {
        Answer::Enter => Ok(Value::Nil),
        Answer::Keyword(k) => Ok(Value::str(&k)),
        Answer::Text(t) => match t.parse::<i32>() {
            Ok(n) if (-32768..=32767).contains(&n) => {
                check_sign("getint", &ig, &t, n as f64)?;
                Ok(Value::Int(n))
            }
            Ok(_) => other_input(
                "getint",
                &ig,
                &t,
                "requires an integer between -32768 and 32767",
            ),
            Err(_) => other_input("getint", &ig, &t, "requires an integer value"),
        },
    }
}

fn getstring(it: &mut Interp, a: &[Value]) -> LResult {
    let (spaces, prompt) = match a {
        [] => (false, None),
        [Value::Str(p)] => (false, Some(p.to_string())),
        [cr] => (cr.truthy(), None),
        [cr, p, ..] => (cr.truthy(), prompt_arg(it, std::slice::from_ref(p))?),
    };
    // getstring ignores initget, but a pending one is still used up.
    it.ext::<InputState>().pending = None;
    let raw = next_answer(it, "getstring", prompt.as_deref())?;
    let text = if spaces {
        raw.as_str()
    } else {
        // Without allow-spaces, a space acts as Enter.
        raw.trim_start().split(' ').next().unwrap_or("")
    };
    Ok(Value::str(text))
}

fn getdist(it: &mut Interp, a: &[Value]) -> LResult {
    let (base, prompt) = base_and_prompt(it, a)?;
    let (ans, ig) = ask(it, "getdist", prompt.as_deref())?;
    let t = match ans {
        Answer::Enter => return Ok(Value::Nil),
        Answer::Keyword(k) => return Ok(Value::str(&k)),
        Answer::Text(t) => t,
    };
    let d = if let Some(x) = parse_real(&t).or_else(|| unit_distance(it, &t)) {
        x
    } else if let Some(p) = parse_point(it, &t, base) {
        // A point: the distance from the base, or from this point to a second one.
        let (from, to) = match base {
            Some(b) => (b, p),
            None => {
                let raw = next_answer(it, "getdist", Some("Second point: "))?;
                let q = parse_point(it, &raw, Some(p))
                    .ok_or_else(|| rejected("getdist", &raw, "not a point"))?;
                (p, q)
            }
        };
        set_last_point(it, to);
        if ig.has(FLAT_DIST) {
            from.truncate().distance(to.truncate())
        } else {
            from.distance(to)
        }
    } else {
        return other_input("getdist", &ig, &t, "requires a distance or a point");
    };
    check_sign("getdist", &ig, &t, d)?;
    Ok(Value::Real(d))
}

/// A distance typed in any of AutoCAD's linear formats (1'-6", 1 1/2, 3/4), as `distof` reads
/// them.
fn unit_distance(it: &mut Interp, text: &str) -> Option<f64> {
    let distof = super::find("distof")?;
    (distof.f)(it, &[Value::str(text)])
        .ok()?
        .as_f64()
        .filter(|x| x.is_finite())
}

/// getangle and getorient: typed degrees or a point giving the direction from the base.
fn angle_answer(it: &mut Interp, func: &str, a: &[Value], relative: bool) -> LResult {
    let (base, prompt) = base_and_prompt(it, a)?;
    let (ans, ig) = ask(it, func, prompt.as_deref())?;
    let t = match ans {
        Answer::Enter => return Ok(Value::Nil),
        Answer::Keyword(k) => return Ok(Value::str(&k)),
        Answer::Text(t) => t,
    };
    let (angbase, clockwise) = {
        let sv = it.ext::<SysVars>();
        (sv.real("ANGBASE"), sv.int("ANGDIR") == 1)
    };
    // The direction the user meant, absolute (east = 0, counter-clockwise).
    let absolute = if let Some(deg) = parse_real(&t) {
        let x = deg.to_radians();
        // Typed angles are in the user's convention: from ANGBASE, in ANGDIR.
        angbase + if clockwise { -x } else { x }
    } else if let Some(p) = parse_point(it, &t, base) {
        let from = match base {
            Some(b) => b,
            None => {
                let raw = next_answer(it, func, Some("Second point: "))?;
                let q = parse_point(it, &raw, Some(p))
                    .ok_or_else(|| rejected(func, &raw, "not a point"))?;
                let r = super::geom2d::xy_angle(p, q);
                return finish_angle(func, &ig, &t, r, relative, angbase, clockwise);
            }
        };
        super::geom2d::xy_angle(from, p)
    } else {
        return other_input(func, &ig, &t, "requires an angle or a point");
    };
    finish_angle(func, &ig, &t, absolute, relative, angbase, clockwise)
}

/// getangle returns the angle measured from ANGBASE counter-clockwise (ignoring ANGDIR, as
/// AutoCAD documents); getorient returns the absolute angle. Both lie in [0, 2π).
fn finish_angle(
    func: &str,
    ig: &Initget,
    text: &str,
    absolute: f64,
    relative: bool,
    angbase: f64,
    _clockwise: bool,
) -> LResult {
    let mut r = if relative {
        absolute - angbase
    } else {
        absolute
    };
    r = r.rem_euclid(std::f64::consts::TAU);
    if r >= std::f64::consts::TAU {
        r = 0.0;
    }
    check_sign(func, ig, text, r)?;
    Ok(Value::Real(r))
}

fn getangle(it: &mut Interp, a: &[Value]) -> LResult {
    angle_answer(it, "getangle", a, true)
}

fn getorient(it: &mut Interp, a: &[Value]) -> LResult {
    angle_answer(it, "getorient", a, false)
}

fn getkword(it: &mut Interp, a: &[Value]) -> LResult {
    let prompt = prompt_arg(it, a)?;
    let (ans, ig) = ask(it, "getkword", prompt.as_deref())?;
    match ans {
        Answer::Enter => Ok(Value::Nil),
        Answer::Keyword(k) => Ok(Value::str(&k)),
        Answer::Text(t) => other_input("getkword", &ig, &t, "invalid option keyword"),
    }
}

fn getfiled(it: &mut Interp, a: &[Value]) -> LResult {
    let title = it.string(&a[0])?.to_string();
    let default = match &a[1] {
        Value::Nil => String::new(),
        v => it.string(v)?.to_string(),
    };
    let ext = match &a[2] {
        Value::Nil => String::new(),
        v => it.string(v)?.to_string(),
    };
    it.int(&a[3])?;
    it.ext::<InputState>().pending = None;
    let raw = next_answer(it, "getfiled", Some(&format!("{title}: ")))?;
    let name = raw.trim();
    let name = if name.is_empty() {
        // Enter accepts the default when there is one, like OK in the dialog; else cancel.
        if default.is_empty() {
            return Ok(Value::Nil);
        }
        default.as_str()
    } else {
        name
    };
    // The dialog appends the filter's extension to a bare name ("" or "*" filter none).
    let ext = ext.trim_start_matches('.');
    let has_ext = std::path::Path::new(name).extension().is_some();
    if !has_ext && !ext.is_empty() && ext != "*" && !ext.contains(';') {
        Ok(Value::str(&format!("{name}.{ext}")))
    } else {
        Ok(Value::str(name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keyword_abbreviations() {
        let ig = Initget {
            bits: 0,
            keywords: parse_keywords("Width Height LType,LT eXit"),
        };
        assert_eq!(ig.keyword("w").as_deref(), Some("Width"));
        assert_eq!(ig.keyword("WID").as_deref(), Some("Width"));
        assert_eq!(ig.keyword("widthx"), None);
        assert_eq!(ig.keyword("lt").as_deref(), Some("LType"));
        assert_eq!(ig.keyword("l"), None);
        assert_eq!(ig.keyword("x").as_deref(), Some("eXit"));
        assert_eq!(ig.keyword("exit").as_deref(), Some("eXit"));
        assert_eq!(ig.keyword("e"), None);
    }

    #[test]
    fn global_keywords_are_returned() {
        let ig = Initget {
            bits: 0,
            keywords: parse_keywords("Ja Nein _ Yes No"),
        };
        assert_eq!(ig.keyword("j").as_deref(), Some("Yes"));
        assert_eq!(ig.keyword("_No").as_deref(), Some("No"));
    }
}
