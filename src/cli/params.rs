//! `lispcad params FILE` and the checks of `--set` names, table columns and values against
//! what a script declares and uses.
//!
//! Parameters are found statically: the script is read (not run) and every
//! `(defparam NAME default "doc" [min max])` form in it, at any depth, is listed with its
//! default and range as written. Nothing the script does (file writes, prompts) happens.

use std::path::Path;

use super::{EXIT_OK, EXIT_USAGE};
use crate::lang::reader::{parse_number, read_source};
use crate::lang::{Interp, Value};

/// One declared parameter, as written in the script.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    pub name: String,
    pub default: String,
    pub doc: String,
    pub range: Option<(f64, f64)>,
}

/// What a script declares and which symbols it mentions (upper case).
#[derive(Debug, Default)]
pub struct ScriptNames {
    pub params: Vec<Param>,
    pub symbols: Vec<String>,
    /// The literal file names of its `(load "...")` forms, as written.
    pub loads: Vec<String>,
}

/// Reads the script's forms (without running them) and collects its names.
pub fn scan(text: &str) -> Result<ScriptNames, String> {
    // An interpreter only for its symbol table and printer: nothing is evaluated.
    let mut it = crate::builtins::new_interp();
    let parsed = read_source(text, 0, &mut it.syms).map_err(|e| e.message)?;
    it.sync_cells();
    let mut out = ScriptNames::default();
    let mut seen = std::collections::HashSet::new();
    for (form, _) in &parsed.forms {
        walk(form, &it, &mut out, &mut seen);
    }
    Ok(out)
}

fn walk(
    v: &Value,
    it: &Interp,
    out: &mut ScriptNames,
    seen: &mut std::collections::HashSet<String>,
) {
    match v {
        Value::Sym(s) => {
            let n = it.syms.name(*s).to_string();
            if seen.insert(n.clone()) {
                out.symbols.push(n);
            }
        }
        Value::Cons(_) => {
            if let Some(name) = as_load(v, it) {
                out.loads.push(name);
            }
            if let Some(p) = as_defparam(v, it) {
                out.params.retain(|q| q.name != p.name);
                out.params.push(p);
            }
            // Dotted tails included: walk car and cdr by hand.
            let mut cur = v.clone();
            while let Value::Cons(c) = &cur {
                walk(&c.car, it, out, seen);
                let next = c.cdr.clone();
                cur = next;
            }
            if !matches!(cur, Value::Nil) {
                walk(&cur, it, out, seen);
            }
        }
        _ => {}
    }
}

/// The file of a `(load "NAME" ...)` form with a literal name.
fn as_load(v: &Value, it: &Interp) -> Option<String> {
    let Value::Cons(c) = v else { return None };
    if it.syms.name(c.car.as_sym()?) != "LOAD" {
        return None;
    }
    match &c.cdr {
        Value::Cons(a) => match &a.car {
            Value::Str(s) => Some(s.to_string()),
            _ => None,
        },
        _ => None,
    }
}

/// Where `load` would find `name` from a file in `dir`: there, then the current directory,
/// with ".lsp" added to a name without extension (as `Interp::resolve_path`).
fn resolve_load(name: &str, dir: &Path) -> Option<std::path::PathBuf> {
    let p = Path::new(name);
    let mut candidates = vec![p.to_path_buf()];
    if p.extension().is_none() {
        candidates.push(p.with_extension("lsp"));
    }
    candidates.into_iter().find_map(|c| {
        let places = if c.is_absolute() {
            vec![c]
        } else {
            vec![dir.join(&c), c]
        };
        places.into_iter().find(|q| q.is_file())
    })
}

/// `scan` of a script in `dir`, together with the files it loads by literal name (followed
/// from each loaded file's own directory, as `load` resolves them; each file once): a `--set`
/// or column may name a symbol only a loaded routine uses. A loaded file that cannot be read
/// or parsed is skipped here; the run reports it.
pub fn scan_with_loads(text: &str, dir: &Path) -> Result<ScriptNames, String> {
    /// Loaded files followed at most (a guard against a tree of thousands).
    const MAX_FILES: usize = 256;
    let mut out = scan(text)?;
    let mut known: std::collections::HashSet<String> = out.symbols.iter().cloned().collect();
    let mut seen = std::collections::HashSet::new();
    let mut queue: Vec<(String, std::path::PathBuf)> = std::mem::take(&mut out.loads)
        .into_iter()
        .map(|l| (l, dir.to_path_buf()))
        .collect();
    while let Some((name, base)) = queue.pop() {
        let Some(path) = resolve_load(&name, &base) else {
            continue;
        };
        let key = path.canonicalize().unwrap_or_else(|_| path.clone());
        if seen.len() >= MAX_FILES || !seen.insert(key) {
            continue;
        }
        let Ok(bytes) = std::fs::read(&path) else {
            continue;
        };
        let text = crate::lang::encoding::decode(
            &bytes,
            crate::lang::encoding::SourceCodePage::default().0,
        );
        let Ok(more) = scan(&text) else { continue };
        for s in more.symbols {
            if known.insert(s.clone()) {
                out.symbols.push(s);
            }
        }
        for p in more.params {
            out.params.retain(|q| q.name != p.name);
            out.params.push(p);
        }
        let here = path
            .parent()
            .map_or_else(|| base.clone(), Path::to_path_buf);
        queue.extend(more.loads.into_iter().map(|l| (l, here.clone())));
    }
    Ok(out)
}

fn as_defparam(v: &Value, it: &Interp) -> Option<Param> {
    let syms = &it.syms;
    let items: Vec<&Value> = v.iter().collect();
    let head = items.first()?.as_sym()?;
    if syms.name(head) != "DEFPARAM" || !(4..=6).contains(&items.len()) {
        return None;
    }
    let name = syms.name(items[1].as_sym()?).to_string();
    let doc = match items[3] {
        Value::Str(s) => s.to_string(),
        other => it.prin1_string(other),
    };
    let range = if items.len() == 6 {
        Some((items[4].as_f64()?, items[5].as_f64()?))
    } else {
        None
    };
    Some(Param {
        name,
        default: it.prin1_string(items[2]),
        doc,
        range,
    })
}

/// `lispcad params FILE`.
pub fn params(file: &Path) -> i32 {
    let text = match std::fs::read_to_string(file) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: cannot read script {}: {e}", file.display());
            return EXIT_USAGE;
        }
    };
    let names = match scan_with_loads(&text, &super::run::parent_dir(file)) {
        Ok(n) => n,
        Err(m) => {
            eprintln!("error: {}: {m}", file.display());
            return super::EXIT_SCRIPT_ERROR;
        }
    };
    print!("{}", table(&names.params));
    EXIT_OK
}

/// The parameters as an aligned text table: name, default, range, doc.
pub fn table(params: &[Param]) -> String {
    let rows: Vec<[String; 4]> = params
        .iter()
        .map(|p| {
            [
                p.name.clone(),
                p.default.clone(),
                p.range
                    .map_or_else(String::new, |(lo, hi)| format!("{lo}..{hi}")),
                p.doc.clone(),
            ]
        })
        .collect();
    let head = ["NAME", "DEFAULT", "RANGE", "DOC"].map(String::from);
    let mut w = [0usize; 3];
    for r in std::iter::once(&head).chain(&rows) {
        for i in 0..3 {
            w[i] = w[i].max(r[i].chars().count());
        }
    }
    let mut out = String::new();
    for r in std::iter::once(&head).chain(&rows) {
        let line = format!(
            "{:w0$}  {:w1$}  {:w2$}  {}",
            r[0],
            r[1],
            r[2],
            r[3],
            w0 = w[0],
            w1 = w[1],
            w2 = w[2]
        );
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

impl ScriptNames {
    /// A usage error unless `name` is a symbol the script uses (or one of `extra`, e.g. an
    /// output pattern's fields); it names the nearest known name, declared parameters first.
    pub fn check_name(&self, what: &str, name: &str, extra: &[String]) -> Result<(), String> {
        let up = name.to_uppercase();
        if self.symbols.contains(&up) || extra.iter().any(|e| e.eq_ignore_ascii_case(name)) {
            return Ok(());
        }
        let near = |cands: &mut dyn Iterator<Item = &str>| -> Option<String> {
            cands
                .map(|c| (strsim::damerau_levenshtein(&up, &c.to_uppercase()), c))
                .filter(|(d, c)| *d <= (c.len().max(up.len()) / 2).max(1))
                .min_by_key(|(d, _)| *d)
                .map(|(_, c)| c.to_string())
        };
        let hint = near(&mut self.params.iter().map(|p| p.name.as_str()))
            .or_else(|| {
                near(
                    &mut self
                        .symbols
                        .iter()
                        .map(String::as_str)
                        .chain(extra.iter().map(String::as_str)),
                )
            })
            .map_or_else(String::new, |n| format!(" (did you mean {n}?)"));
        Err(format!("{what} {name}: the script does not use {up}{hint}"))
    }

    /// A usage error when a value given for a declared parameter is outside its range.
    pub fn check_value(&self, what: &str, name: &str, text: &str) -> Result<(), String> {
        let Some(p) = self
            .params
            .iter()
            .find(|p| p.name.eq_ignore_ascii_case(name))
        else {
            return Ok(());
        };
        let Some((lo, hi)) = p.range else {
            return Ok(());
        };
        match parse_number(text.trim()).and_then(|v| v.as_f64()) {
            Some(x) if (lo..=hi).contains(&x) => Ok(()),
            _ => Err(format!(
                "{what} {}={}: parameter {} must be a number in [{lo}, {hi}]",
                name,
                text.trim(),
                p.name
            )),
        }
    }

    /// Checks `--set NAME=VALUE` options: name used, value in range.
    pub fn check_sets(&self, sets: &[String]) -> Result<(), String> {
        for s in sets {
            let Some((name, value)) = s.split_once('=') else {
                continue; // apply_sets reports the malformed option
            };
            self.check_name("--set", name.trim(), &[])?;
            self.check_value("--set", name.trim(), value)?;
        }
        Ok(())
    }
}

/// The script's names, or a usage error message when it cannot be read (a syntax error is
/// reported by the run itself, with its span).
pub fn script_names(file: &Path) -> Result<ScriptNames, String> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| format!("cannot read script {}: {e}", file.display()))?;
    Ok(scan_with_loads(&text, &super::run::parent_dir(file)).unwrap_or_default())
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCRIPT: &str = "(defparam L1 140.0 \"total length\" 100 200)\n\
        (defparam NAME \"t\" \"label\")\n(defun f (/ x) (setq x (* L1 BENDANG)))\n\
        (progn (defparam BENDANG 40.0 \"bend angle\" 0 90))\n";

    #[test]
    fn finds_every_defparam_without_running() {
        let n = scan(SCRIPT).unwrap();
        let names: Vec<_> = n.params.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["L1", "NAME", "BENDANG"]);
        assert_eq!(n.params[0].default, "140.0");
        assert_eq!(n.params[0].range, Some((100.0, 200.0)));
        assert_eq!(n.params[1].default, "\"t\"");
        assert_eq!(n.params[1].range, None);
        let t = table(&n.params);
        assert_eq!(t.lines().next().unwrap(), "NAME     DEFAULT  RANGE     DOC");
        assert_eq!(
            t.lines().nth(1).unwrap(),
            "L1       140.0    100..200  total length"
        );
    }

    #[test]
    fn names_and_values_are_checked() {
        let n = scan(SCRIPT).unwrap();
        assert!(n.check_name("--set", "l1", &[]).is_ok());
        assert!(n.check_name("--set", "x", &[]).is_ok());
        assert_eq!(
            n.check_name("--set", "BEND", &[]).unwrap_err(),
            "--set BEND: the script does not use BEND (did you mean BENDANG?)"
        );
        assert!(n
            .check_name("column", "name2", &[])
            .unwrap_err()
            .contains("did you mean NAME?"));
        assert!(n.check_name("column", "stem", &["stem".into()]).is_ok());
        assert!(n.check_sets(&["L1=150".into()]).is_ok());
        assert_eq!(
            n.check_sets(&["L1=250".into()]).unwrap_err(),
            "--set L1=250: parameter L1 must be a number in [100, 200]"
        );
        assert!(n.check_value("column", "L1", "\"big\"").is_err());
    }

    #[test]
    fn names_used_by_loaded_files_count() {
        let dir = tempfile::tempdir().unwrap();
        let lib = dir.path().join("lib");
        std::fs::create_dir(&lib).unwrap();
        // main loads lib/bend (".lsp" added), which loads its neighbour util.lsp, which
        // loads bend again (followed once).
        std::fs::write(
            lib.join("bend.lsp"),
            "(defparam BENDANG 40.0 \"bend\" 0 90) (load \"util.lsp\")",
        )
        .unwrap();
        std::fs::write(lib.join("util.lsp"), "(setq TIPR 2.0) (load \"bend\")").unwrap();
        let main = "(load \"lib/bend\") (load (strcat \"dyn\" \"amic\")) (princ L1)";
        let n = scan_with_loads(main, dir.path()).unwrap();
        assert!(n.check_name("--set", "bendang", &[]).is_ok());
        assert!(n.check_name("--set", "TIPR", &[]).is_ok());
        assert!(n.check_name("--set", "L1", &[]).is_ok());
        assert_eq!(n.params.len(), 1);
        assert_eq!(
            n.check_sets(&["BENDANG=95".into()]).unwrap_err(),
            "--set BENDANG=95: parameter BENDANG must be a number in [0, 90]"
        );
        assert!(n
            .check_name("--set", "BEND", &[])
            .unwrap_err()
            .contains("did you mean BENDANG?"));
        // The file alone knows none of them.
        assert!(scan(main)
            .unwrap()
            .check_name("--set", "TIPR", &[])
            .is_err());
    }
}
