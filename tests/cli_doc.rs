//! `lispcad doc` and the REPL's `:help`: every builtin has a one-line signature and
//! description, names are unique across the library's tables, and help finds each one.

use std::collections::HashSet;
use std::process::Command;

mod cli_support;
use cli_support::repl_output;

/// (name, signature, description) of every builtin as `lispcad doc` lists them.
fn reference() -> Vec<(String, String, String)> {
    let o = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("doc")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8(o.stdout).unwrap();
    text.lines()
        .filter_map(|l| l.strip_prefix("- `"))
        .map(|l| {
            let (sig, doc) = l.split_once("` — ").expect("`sig` — doc");
            let name = sig
                .trim_start_matches('(')
                .split([' ', ')'])
                .next()
                .unwrap()
                .to_string();
            (name, sig.to_string(), doc.to_string())
        })
        .collect()
}

#[test]
fn every_builtin_is_documented_once() {
    let refs = reference();
    assert!(refs.len() > 200, "only {} builtins", refs.len());
    let mut seen = HashSet::new();
    for (name, sig, doc) in &refs {
        assert!(
            seen.insert(name.to_lowercase()),
            "{name} is registered twice"
        );
        assert!(
            sig.starts_with(&format!("({name}")),
            "{name}: signature {sig:?}"
        );
        assert!(!doc.trim().is_empty(), "{name}: no description");
        assert!(!doc.contains('\n'), "{name}: description is not one line");
    }
    for needed in [
        "inters",
        "polar",
        "angle",
        "distance",
        "trans",
        "getpoint",
        "getreal",
        "getint",
        "getstring",
        "getdist",
        "getangle",
        "getorient",
        "getkword",
        "getcorner",
        "initget",
        "vl-sort",
        "vl-catch-all-apply",
        "mapcar",
        "rtos",
        "wcmatch",
    ] {
        assert!(seen.contains(needed), "{needed} missing from the reference");
    }
}

#[test]
fn help_finds_every_builtin_in_the_repl() {
    let refs = reference();
    let mut input = String::new();
    for (name, _, _) in &refs {
        input.push_str(&format!(":help {name}\n"));
    }
    let dir = tempfile::tempdir().unwrap();
    let o = repl_output(dir.path(), &[], &input);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(!out.contains("no help for"), "{out}");
    let lines: Vec<&str> = out.lines().collect();
    // Two lines per builtin: the signature, then the indented description.
    assert_eq!(lines.len(), 2 * refs.len(), "{out}");
    for (i, (name, sig, doc)) in refs.iter().enumerate() {
        assert_eq!(lines[2 * i], sig, "{name}");
        assert_eq!(lines[2 * i + 1].trim(), doc, "{name}");
    }
}

#[test]
fn doc_name_prints_one_builtin_and_suggests_on_a_typo() {
    let dir = tempfile::tempdir().unwrap();
    let o = cli_support::lispcad_in(dir.path(), &["doc", "LINE"]);
    assert_eq!(o.status.code(), Some(0));
    let refs = reference();
    let (_, sig, doc) = refs.iter().find(|(n, _, _)| n == "line").unwrap();
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        format!("{sig}\n  {doc}\n")
    );
    let o = cli_support::lispcad_in(dir.path(), &["doc", "lien"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    assert_eq!(
        String::from_utf8_lossy(&o.stderr),
        "error: no builtin named lien; did you mean line?\n"
    );
}

#[test]
fn completions_for_each_shell_name_the_subcommands() {
    let dir = tempfile::tempdir().unwrap();
    for shell in ["bash", "zsh", "fish"] {
        let o = cli_support::lispcad_in(dir.path(), &["completions", shell]);
        assert_eq!(o.status.code(), Some(0), "{shell}");
        let text = String::from_utf8_lossy(&o.stdout);
        for sub in ["run", "check", "watch", "batch", "completions"] {
            assert!(text.contains(sub), "{shell} lacks {sub}");
        }
        assert!(text.contains("max-steps"), "{shell}");
    }
    let o = cli_support::lispcad_in(dir.path(), &["completions", "tcsh"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn bash_completion_script_is_valid_bash() {
    let dir = tempfile::tempdir().unwrap();
    let o = cli_support::lispcad_in(dir.path(), &["completions", "bash"]);
    let script = dir.path().join("lispcad.bash");
    std::fs::write(&script, &o.stdout).unwrap();
    // Sourcing defines the function; `complete -p` shows it registered for lispcad.
    let out = Command::new("bash")
        .arg("-c")
        .arg(format!(
            "source {} && complete -p lispcad",
            script.display()
        ))
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stdout).contains("_lispcad"));
}
