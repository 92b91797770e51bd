//! System variables (getvar/setvar), the symbol table (atoms-family), help and version.

use std::collections::BTreeMap;

use crate::builtin;
use crate::lang::builtin::{Builtin, MANY};
use crate::lang::error::{err, LResult};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!(
        "getvar",
        "(getvar name)",
        "The value of a system variable (nil if unknown).",
        1,
        1,
        getvar
    ),
    builtin!(
        "setvar",
        "(setvar name value)",
        "Sets a system variable; returns the value.",
        2,
        2,
        setvar
    ),
    builtin!(
        "atoms-family",
        "(atoms-family format [names])",
        "The defined symbols (format 0: symbols, 1: strings); with names, each one's presence.",
        1,
        2,
        atoms_family
    ),
    builtin!(
        "help",
        "(help 'name)",
        "Prints the signature and description of a builtin.",
        0,
        1,
        help
    ),
    builtin!("ver", "(ver)", "The lispcad version string.", 0, 0, ver),
    builtin!(
        "vl-load-com",
        "(vl-load-com)",
        "Accepted for compatibility; does nothing.",
        0,
        0,
        noop
    ),
    builtin!(
        "gc",
        "(gc)",
        "Accepted for compatibility (memory is reference counted); returns nil.",
        0,
        0,
        noop
    ),
    builtin!(
        "getenv",
        "(getenv name)",
        "The value of an environment variable, or nil.",
        1,
        1,
        getenv
    ),
    builtin!(
        "setq-default",
        "(setq-default 'sym value ...)",
        "Sets each symbol only if it is still nil; returns the last value (for script parameters).",
        2,
        MANY,
        setq_default
    ),
    builtin!(
        "graphscr",
        "(graphscr)",
        "Accepted for compatibility (no screen headless); returns nil.",
        0,
        0,
        noop
    ),
    builtin!(
        "textscr",
        "(textscr)",
        "Accepted for compatibility (no screen headless); returns nil.",
        0,
        0,
        noop
    ),
    builtin!(
        "textpage",
        "(textpage)",
        "Accepted for compatibility (no screen headless); returns nil.",
        0,
        0,
        noop
    ),
    builtin!(
        "redraw",
        "(redraw [ename [mode]])",
        "Accepted for compatibility (no screen headless); returns nil.",
        0,
        2,
        noop
    ),
    builtin!(
        "setfunhelp",
        "(setfunhelp c:name [file topic command])",
        "Accepted for compatibility (no help files headless); returns nil.",
        1,
        4,
        noop
    ),
    builtin!(
        "vl-acad-defun",
        "(vl-acad-defun 'function)",
        "Accepted for compatibility (every function is visible); returns nil.",
        1,
        1,
        noop
    ),
    builtin!(
        "vl-acad-undefun",
        "(vl-acad-undefun 'function)",
        "Accepted for compatibility; returns nil.",
        1,
        1,
        noop
    ),
    builtin!(
        "acad-push-dbmod",
        "(acad-push-dbmod)",
        "Accepted for compatibility; returns nil.",
        0,
        0,
        noop
    ),
    builtin!(
        "acad-pop-dbmod",
        "(acad-pop-dbmod)",
        "Accepted for compatibility; returns nil.",
        0,
        0,
        noop
    ),
    builtin!(
        "trace",
        "(trace function...)",
        "Prints each call of the user functions and its result (\"Entering (F 1)\" / \"Result:  2\").",
        0,
        MANY,
        crate::builtins::trace::trace
    ),
    builtin!(
        "untrace",
        "(untrace function...)",
        "Stops tracing the functions; returns the last function name.",
        0,
        MANY,
        crate::builtins::trace::untrace
    ),
    builtin!(
        "vl-doc-set",
        "(vl-doc-set 'sym value)",
        "Sets a symbol in the document namespace (the one namespace headless); returns the value.",
        2,
        2,
        doc_set
    ),
    builtin!(
        "vl-doc-ref",
        "(vl-doc-ref 'sym)",
        "The value of a symbol in the document namespace (the one namespace headless).",
        1,
        1,
        doc_ref
    ),
    builtin!(
        "vl-propagate",
        "(vl-propagate 'sym)",
        "Copies a symbol's value to every document (there is one headless); returns nil.",
        1,
        1,
        noop
    ),
];

/// The system variable table of one interpreter.
pub struct SysVars {
    vars: BTreeMap<String, Value>,
}

impl Default for SysVars {
    fn default() -> Self {
        let mut vars = BTreeMap::new();
        let mut put = |k: &str, v: Value| {
            vars.insert(k.to_string(), v);
        };
        put("LUNITS", Value::Int(2));
        put("LUPREC", Value::Int(4));
        put("AUNITS", Value::Int(0));
        put("AUPREC", Value::Int(0));
        put("DIMZIN", Value::Int(0));
        put("UNITMODE", Value::Int(0));
        put("ANGBASE", Value::Real(0.0));
        put("ANGDIR", Value::Int(0));
        put("CMDECHO", Value::Int(1));
        put("OSMODE", Value::Int(0));
        put("PDMODE", Value::Int(0));
        put("INSUNITS", Value::Int(4));
        put("MEASUREMENT", Value::Int(1));
        put("GEOMTOL", Value::Real(1e-9));
        put("BENDDEV", Value::Real(0.0));
        put("DXFPROFILE", Value::str("CAD"));
        put("CAMTOL", Value::Real(0.01));
        put("CHORDTOL", Value::Real(0.01));
        put("TEXTSIZE", Value::Real(2.5));
        put(
            "VIEWDIR",
            Value::list([Value::Real(0.0), Value::Real(0.0), Value::Real(1.0)]),
        );
        put(
            "ACADVER",
            Value::str(concat!("lispcad ", env!("CARGO_PKG_VERSION"))),
        );
        put("PLATFORM", Value::str(std::env::consts::OS));
        put("DWGNAME", Value::str("Drawing1.dwg"));
        put(
            "LASTPOINT",
            Value::list([Value::Real(0.0), Value::Real(0.0), Value::Real(0.0)]),
        );
        SysVars { vars }
    }
}

/// Variables `setvar` may not change.
const READ_ONLY: &[&str] = &["ACADVER", "PLATFORM", "DWGNAME", "CDATE", "DATE"];

impl SysVars {
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.vars.get(&name.to_uppercase())
    }

    pub fn real(&self, name: &str) -> f64 {
        self.get(name).and_then(Value::as_f64).unwrap_or(0.0)
    }

    pub fn int(&self, name: &str) -> i32 {
        match self.get(name) {
            Some(Value::Int(i)) => *i,
            _ => 0,
        }
    }

    /// Sets a variable from Rust (no type check): for the library's own results (BENDDEV).
    pub fn put(&mut self, name: &str, v: Value) {
        self.vars.insert(name.to_uppercase(), v);
    }
}

pub fn init(it: &mut Interp) {
    it.set_global("PI", Value::Real(std::f64::consts::PI));
}

fn date_now() -> f64 {
    // CDATE as AutoCAD gives it: YYYYMMDD.HHMMSS, in UTC here.
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let days = secs.div_euclid(86_400);
    let rem = secs.rem_euclid(86_400);
    // Civil-from-days (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    let ymd = (y * 10_000 + m * 100 + d) as f64;
    let hms = (rem / 3600 * 10_000 + rem % 3600 / 60 * 100 + rem % 60) as f64;
    ymd + hms / 1e6
}

fn getvar(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_uppercase();
    if name == "CDATE" {
        return Ok(Value::Real(date_now()));
    }
    if name == "CLAYER" {
        let layer = it
            .ext::<crate::output::Drawing>()
            .current_layer()
            .to_string();
        return Ok(Value::str(&layer));
    }
    Ok(it
        .ext::<SysVars>()
        .get(&name)
        .cloned()
        .unwrap_or(Value::Nil))
}

fn setvar(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_uppercase();
    let shown = format!("\"{}\" {}", name, it.prin1_string(&a[1]));
    let rejected = || err(format!("AutoCAD variable setting rejected: {shown}"));
    if READ_ONLY.contains(&name.as_str()) {
        return Err(rejected());
    }
    if name == "CLAYER" {
        // The current layer is the drawing's: it must exist, as in AutoCAD.
        let layer = it.string(&a[1])?.to_string();
        let d = it.ext::<crate::output::Drawing>();
        if d.layer(&layer).is_none() {
            return Err(rejected());
        }
        d.use_layer(&layer, None).map_err(|e| err(e.to_string()))?;
        return Ok(a[1].clone());
    }
    let vars = it.ext::<SysVars>();
    let Some(old) = vars.get(&name) else {
        return Err(rejected());
    };
    // The new value must have the variable's kind; an integer may stand for a real.
    let v = match (old, &a[1]) {
        (Value::Int(_), Value::Int(_)) => a[1].clone(),
        (Value::Real(_), Value::Int(i)) => Value::Real(*i as f64),
        (Value::Real(_), Value::Real(_)) => a[1].clone(),
        (Value::Str(_), Value::Str(s)) => Value::str(&s.to_uppercase()),
        (Value::Cons(_), Value::Cons(_)) => a[1].clone(),
        _ => return Err(rejected()),
    };
    if name == "DXFPROFILE" && !matches!(v.as_str(), Some("CAD" | "CAM")) {
        return Err(rejected());
    }
    if name == "GEOMTOL" && v.as_f64().is_none_or(|t| t.is_nan() || t <= 0.0) {
        return Err(rejected());
    }
    it.ext::<SysVars>().put(&name, v.clone());
    Ok(a[1].clone())
}

fn atoms_family(it: &mut Interp, a: &[Value]) -> LResult {
    let as_strings = it.int(&a[0])? == 1;
    let make = |it: &mut Interp, name: &str| {
        if as_strings {
            Value::str(name)
        } else {
            Value::Sym(it.intern(name))
        }
    };
    if let Some(names) = a.get(1) {
        let mut out = Vec::new();
        for n in it.list_arg(names)?.iter().cloned().collect::<Vec<_>>() {
            let name = it.string(&n)?.to_uppercase();
            let bound = it
                .syms
                .lookup(&name)
                .is_some_and(|s| it.values[s.idx()].truthy());
            out.push(if bound { make(it, &name) } else { Value::Nil });
        }
        return Ok(Value::list(out));
    }
    let names: Vec<String> = it
        .syms
        .all()
        .filter(|(s, n)| !n.is_empty() && it.values[s.idx()].truthy())
        .map(|(_, n)| n.to_string())
        .collect();
    let mut out = Vec::with_capacity(names.len());
    for n in names {
        out.push(make(it, &n));
    }
    Ok(Value::list(out))
}

/// "(sig)\n  doc" for a builtin name, or None.
pub fn help_text(name: &str) -> Option<String> {
    crate::builtins::find(name).map(|b| format!("{}\n  {}", b.sig, b.doc))
}

fn help(it: &mut Interp, a: &[Value]) -> LResult {
    let name = match a.first() {
        None => {
            it.write_out("(help 'name) describes a builtin; `lispcad doc` lists them all.\n");
            return Ok(Value::Sym(it.intern("")));
        }
        Some(Value::Sym(s)) => it.syms.name(*s).to_string(),
        Some(Value::Str(s)) => s.to_string(),
        Some(Value::Subr(b)) => b.name.to_string(),
        Some(other) => return Err(crate::lang::builtin::bad_arg(it, "symbolp", other)),
    };
    let text = help_text(&name)
        .or_else(|| crate::lang::lint::user_help(it, &name))
        .unwrap_or_else(|| format!("no help for {name}: not a builtin"));
    it.write_out(&format!("{text}\n"));
    Ok(Value::Sym(it.intern("")))
}

fn ver(_: &mut Interp, _: &[Value]) -> LResult {
    Ok(Value::str(concat!(
        "lispcad ",
        env!("CARGO_PKG_VERSION"),
        " (AutoLISP dialect)"
    )))
}

fn noop(_: &mut Interp, _: &[Value]) -> LResult {
    Ok(Value::Nil)
}

fn doc_set(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    let name = it.syms.name(s).to_string();
    it.set_global(&name, a[1].clone());
    Ok(a[1].clone())
}

fn doc_ref(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.symbol(&a[0])?;
    let name = it.syms.name(s).to_string();
    Ok(it.global(&name))
}

fn getenv(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?;
    Ok(std::env::var(name).map_or(Value::Nil, |v| Value::str(&v)))
}

fn setq_default(it: &mut Interp, a: &[Value]) -> LResult {
    if !a.len().is_multiple_of(2) {
        return Err(err("too few arguments"));
    }
    let mut last = Value::Nil;
    for pair in a.chunks(2) {
        let s = it.symbol(&pair[0])?;
        if it.values[s.idx()].is_nil() {
            it.values[s.idx()] = pair[1].clone();
        }
        last = it.values[s.idx()].clone();
    }
    Ok(last)
}
