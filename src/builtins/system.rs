//! System variables (getvar/setvar), the symbol table (atoms-family), help and version.

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
        "A setting from the per-user settings file (setenv), else the process environment, or nil.",
        1,
        1,
        getenv
    ),
    builtin!(
        "setenv",
        "(setenv name value)",
        "Stores a setting in the per-user settings file ($LISPCAD_SETTINGS, default ~/.config/lispcad/settings); returns value.",
        2,
        2,
        setenv
    ),
    builtin!(
        "vl-registry-write",
        "(vl-registry-write key [name] value)",
        "Stores a value under a registry key in the per-user settings file; returns value.",
        2,
        3,
        registry_write
    ),
    builtin!(
        "vl-registry-read",
        "(vl-registry-read key [name])",
        "A value vl-registry-write stored, or nil.",
        1,
        2,
        registry_read
    ),
    builtin!(
        "vl-registry-delete",
        "(vl-registry-delete key [name])",
        "Removes a stored registry value; T if it was there.",
        1,
        2,
        registry_delete
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

pub use super::sysvars::SysVars;
use super::sysvars::{coerce, table};

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
    Ok(match name.as_str() {
        "CDATE" => Value::Real(date_now()),
        "DATE" => Value::Real(julian_now()),
        "MILLISECS" => Value::Int(millisecs()),
        "CLAYER" => {
            let layer = it.ext::<crate::output::Drawing>().current_layer();
            Value::str(layer)
        }
        "DWGPREFIX" => match it.ext::<SysVars>().get("DWGPREFIX") {
            Some(Value::Str(s)) if !s.is_empty() => Value::Str(s.clone()),
            _ => Value::str(&dir_with_separator(it.base_dir.clone())),
        },
        "EXTMIN" | "EXTMAX" => match it.ext::<crate::output::Drawing>().extents() {
            Some((lo, hi)) => {
                let p = if name == "EXTMIN" { lo } else { hi };
                Value::list(p.to_array().map(Value::Real))
            }
            None => it.ext::<SysVars>().get(&name).cloned().unwrap_or_default(),
        },
        "LOGINNAME" => Value::str(&std::env::var("USER").unwrap_or_default()),
        "TEMPPREFIX" => Value::str(&dir_with_separator(Some(std::env::temp_dir()))),
        _ => it
            .ext::<SysVars>()
            .get(&name)
            .cloned()
            .unwrap_or(Value::Nil),
    })
}

/// A directory as AutoCAD's *PREFIX variables give it: absolute, ending in a separator (the
/// current directory when none).
fn dir_with_separator(dir: Option<std::path::PathBuf>) -> String {
    let d = dir
        .or_else(|| std::env::current_dir().ok())
        .map(|d| std::path::absolute(&d).unwrap_or(d))
        .unwrap_or_default();
    let mut s = d.display().to_string();
    if !s.ends_with(std::path::MAIN_SEPARATOR) {
        s.push(std::path::MAIN_SEPARATOR);
    }
    s
}

/// DATE: the Julian day number and fraction of the current UTC time, as AutoCAD gives it.
fn julian_now() -> f64 {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0.0, |d| d.as_secs_f64());
    2_440_587.5 + secs / 86_400.0
}

/// MILLISECS: milliseconds since the process started (AutoCAD counts from system start; only
/// differences are meaningful), wrapping like a 32-bit counter.
fn millisecs() -> i32 {
    static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
    START
        .get_or_init(std::time::Instant::now)
        .elapsed()
        .as_millis() as u32 as i32
}

fn setvar(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_uppercase();
    let shown = format!("\"{}\" {}", name, it.prin1_string(&a[1]));
    let rejected = || err(format!("AutoCAD variable setting rejected: {shown}"));
    let Some(def) = table().get(name.as_str()) else {
        return Err(rejected());
    };
    if def.read_only {
        return Err(rejected());
    }
    let v = coerce(def, &a[1]).ok_or_else(rejected)?;
    match name.as_str() {
        "CLAYER" => {
            // The current layer is the drawing's: it must exist, as in AutoCAD.
            let layer = it.string(&a[1])?.to_string();
            let d = it.ext::<crate::output::Drawing>();
            if d.layer(&layer).is_none() {
                return Err(rejected());
            }
            d.use_layer(&layer, None).map_err(|e| err(e.to_string()))?;
            return Ok(a[1].clone());
        }
        "DXFPROFILE" => {
            let p = v.as_str().unwrap_or("").to_uppercase();
            if !matches!(p.as_str(), "CAD" | "CAM") {
                return Err(rejected());
            }
            it.ext::<SysVars>().put(&name, Value::str(&p));
            return Ok(a[1].clone());
        }
        "DWGCODEPAGE" => {
            // Writable here (AutoCAD sets it from the drawing): it picks the code page of the
            // ANSI source files loaded after it.
            let cp = v.as_str().unwrap_or("").to_uppercase();
            let enc = crate::lang::encoding::code_page(&cp).ok_or_else(rejected)?;
            it.ext::<crate::lang::encoding::SourceCodePage>().0 = enc;
            it.ext::<SysVars>().put(&name, Value::str(&cp));
            return Ok(a[1].clone());
        }
        "CECOLOR" => {
            let c = v.as_str().unwrap_or("").to_uppercase();
            if !valid_color_name(&c) {
                return Err(rejected());
            }
            it.ext::<SysVars>().put(&name, Value::str(&c));
            return Ok(a[1].clone());
        }
        _ => {}
    }
    it.ext::<SysVars>().put(&name, v);
    Ok(a[1].clone())
}

/// CECOLOR's forms: BYLAYER, BYBLOCK, an ACI number 1..255 or RGB:r,g,b.
fn valid_color_name(c: &str) -> bool {
    if c == "BYLAYER" || c == "BYBLOCK" {
        return true;
    }
    if let Some(rgb) = c.strip_prefix("RGB:") {
        let parts: Vec<_> = rgb.split(',').map(|x| x.trim().parse::<u8>()).collect();
        return parts.len() == 3 && parts.iter().all(Result::is_ok);
    }
    c.parse::<u16>().is_ok_and(|n| (1..=255).contains(&n))
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
    // A sandboxed script learns nothing of the environment (tokens, home, paths).
    if it.ext::<crate::builtins::io::FsPolicy>().sandbox {
        it.string(&a[0])?;
        return Ok(Value::Nil);
    }
    let name = it.string(&a[0])?;
    if let Some(v) = super::settings::read(&format!("env\t{name}")) {
        return Ok(Value::str(&v));
    }
    Ok(std::env::var(name).map_or(Value::Nil, |v| Value::str(&v)))
}

fn setenv(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let value = it.string(&a[1])?.to_string();
    super::settings::write(&format!("env\t{name}"), Some(&value)).map_err(err)?;
    Ok(a[1].clone())
}

/// The settings key of a registry value: `reg<TAB>KEY\NAME` (case-insensitive, as the
/// Windows registry).
fn registry_key(it: &Interp, a: &[Value], with_name: bool) -> Result<String, crate::lang::Exn> {
    let key = it.string(&a[0])?.to_uppercase();
    let name = if with_name {
        it.string(&a[1])?.to_uppercase()
    } else {
        String::new()
    };
    Ok(format!("reg\t{key}\\{name}"))
}

fn registry_write(it: &mut Interp, a: &[Value]) -> LResult {
    let k = registry_key(it, a, a.len() == 3)?;
    let v = a.last().cloned().unwrap_or_default();
    let text = match &v {
        Value::Str(s) => s.to_string(),
        Value::Int(i) => i.to_string(),
        other => return Err(crate::lang::builtin::bad_arg(it, "stringp", other)),
    };
    super::settings::write(&k, Some(&text)).map_err(err)?;
    Ok(v)
}

fn registry_read(it: &mut Interp, a: &[Value]) -> LResult {
    let k = registry_key(it, a, a.len() == 2)?;
    Ok(super::settings::read(&k).map_or(Value::Nil, |v| Value::str(&v)))
}

fn registry_delete(it: &mut Interp, a: &[Value]) -> LResult {
    let k = registry_key(it, a, a.len() == 2)?;
    let was = super::settings::read(&k).is_some();
    super::settings::write(&k, None).map_err(err)?;
    Ok(Value::bool(was))
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
