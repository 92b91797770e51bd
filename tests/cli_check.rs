//! `lispcad check`: lint without running. Global leaks and undefined calls are warnings
//! (exit 0), wrong builtin argument counts and parse errors are errors (exit 1).

mod cli_support;
use cli_support::lispcad_in;

/// Checks `script`; (exit code, stderr).
fn check(script: &str) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("c.lsp"), script).unwrap();
    let o = lispcad_in(dir.path(), &["check", "c.lsp"]);
    (
        o.status.code().expect("exit code"),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn global_leak_is_a_warning_at_the_setq() {
    let (code, err) = check("(defun area (w h / a)\n  (setq a (* w h))\n  (setq total (+ a 1)))\n");
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("⚠ setq of TOTAL in AREA: TOTAL is neither a parameter nor a declared local"),
        "{err}"
    );
    assert!(err.contains("[c.lsp:3:3]"), "{err}");
    assert!(!err.contains("setq of A "), "{err}");
    assert!(err.contains("0 error(s), 1 warning(s)"), "{err}");
}

#[test]
fn no_leak_for_params_locals_foreach_lambda_and_earmuffs() {
    let script = "\
(defun f (a / b)
  (setq a 1 b 2)
  (foreach x '(1 2) (setq b x))
  (mapcar '(lambda (q / r) (setq r q)) '(1 2))
  (setq *counter* 1))
(setq top 1)
";
    let (code, err) = check(script);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("0 error(s), 0 warning(s)"), "{err}");
}

#[test]
fn one_leak_warning_per_symbol_per_function() {
    let (_, err) = check(
        "(defun m () (setq lst (list 1)) (setq lst (cons 2 lst)))\n(defun n () (setq lst nil))\n",
    );
    assert_eq!(err.matches("setq of LST in M").count(), 1, "{err}");
    assert_eq!(err.matches("setq of LST in N").count(), 1, "{err}");
}

#[test]
fn wrong_builtin_argument_count_is_an_error() {
    let (code, err) = check("(defun f (l)\n  (car l l))\n(strcat)\n(nth 1)\n");
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("too many arguments: (car) takes at most 1, given 2; usage (car list)"),
        "{err}"
    );
    assert!(err.contains("[c.lsp:2:3]"), "{err}");
    assert!(
        err.contains("too few arguments: (nth) takes at least 2, given 1"),
        "{err}"
    );
    assert!(err.contains("2 error(s)"), "{err}");
}

#[test]
fn undefined_function_is_a_warning() {
    let (code, err) = check("(defun f () (helper 1))\n(undefined-thing)\n(defun helper (x) x)\n(setq g (lambda (x) x))\n(g 1)\n");
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("call of undefined function UNDEFINED-THING"),
        "{err}"
    );
    assert!(
        !err.contains("HELPER"),
        "a function defined later is defined: {err}"
    );
    assert!(
        !err.contains("function G"),
        "setq of a lambda defines it: {err}"
    );
    assert!(err.contains("0 error(s), 1 warning(s)"), "{err}");
}

#[test]
fn check_does_not_run_the_code() {
    let (code, err) = check("(princ \"ran\")\n(/ 1 0)\n(exit)\n");
    assert_eq!(code, 0, "{err}");
}

#[test]
fn parse_errors_fail_the_check() {
    let (code, err) = check("(setq a \"unterminated)\n");
    assert_eq!(code, 1, "{err}");
    let (code, err) = check("(setq a 1))\n");
    assert_eq!(code, 1, "{err}");
}

#[test]
fn wrong_argument_count_to_a_defun_of_the_file_is_a_warning() {
    let script = "(defun f (a b / c) (list a b))\n(f 1)\n(f 1 2)\n(f 1 2 3)\n\
                  (defun g (x) x)\n(defun g (x y) x)\n(g 1)\n(setq h (lambda (x) x))\n(h)\n";
    let (code, err) = check(script);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("too few arguments: (F) is defined with 2 parameter(s), called with 1"),
        "{err}"
    );
    assert!(err.contains("[c.lsp:2:1]"), "{err}");
    assert!(
        err.contains("too many arguments: (F) is defined with 2 parameter(s), called with 3"),
        "{err}"
    );
    // G has two definitions and H is a variable: no guess about their arity.
    assert!(err.contains("0 error(s), 2 warning(s)"), "{err}");
}

#[test]
fn functions_from_loaded_files_and_files_checked_together_are_defined() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path();
    std::fs::create_dir(p.join("lib")).unwrap();
    std::fs::write(
        p.join("lib/util.lsp"),
        "(defun util-a (x) x)\n(load \"deeper\")\n",
    )
    .unwrap();
    std::fs::write(
        p.join("lib/deeper.lsp"),
        "(defun util-b () 1)\n(load \"util\")\n",
    )
    .unwrap();
    std::fs::write(p.join("other.lsp"), "(defun other-c () 2)\n").unwrap();
    std::fs::write(
        p.join("main.lsp"),
        "(load \"lib/util\")\n(util-a (util-b))\n(other-c)\n(nowhere-d)\n",
    )
    .unwrap();
    let run = |files: &[&str]| {
        let o = lispcad_in(p, &[&["check"], files].concat());
        (
            o.status.code().unwrap(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let (code, err) = run(&["main.lsp"]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("UTIL-A") && !err.contains("UTIL-B"), "{err}");
    assert!(err.contains("undefined function OTHER-C"), "{err}");
    assert!(err.contains("undefined function NOWHERE-D"), "{err}");
    let (code, err) = run(&["main.lsp", "other.lsp"]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("OTHER-C"), "{err}");
    assert!(
        err.contains("2 file(s) checked: 0 error(s), 1 warning(s)"),
        "{err}"
    );
}

#[test]
fn undefined_function_suggests_the_nearest_name() {
    let (code, err) =
        check("(defun dtr (a) (* pi (/ a 180.0)))\n(dtrr 90)\n(strcta \"a\")\n(zzqqxx)\n");
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("undefined function DTRR: no defun for it in this file and no builtin of that name; did you mean DTR?"), "{err}");
    assert!(err.contains("undefined function STRCTA: no defun for it in this file and no builtin of that name; did you mean STRCAT?"), "{err}");
    assert!(
        err.contains(
            "undefined function ZZQQXX: no defun for it in this file and no builtin of that name\n"
        ),
        "{err}"
    );
}

#[test]
fn json_format_lists_every_finding_with_positions() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("c.lsp"),
        "(defun f (x)\n  (setq g 1)\n  (car x x))\n",
    )
    .unwrap();
    std::fs::write(dir.path().join("bad.lsp"), "(setq a 1))\n").unwrap();
    let o = lispcad_in(
        dir.path(),
        &["check", "--format", "json", "c.lsp", "bad.lsp"],
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["files"], 2);
    assert_eq!(v["errors"], 2);
    assert_eq!(v["warnings"], 1);
    let d = v["diagnostics"].as_array().unwrap();
    assert_eq!(d.len(), 3, "{v}");
    assert_eq!(d[0]["file"], "c.lsp");
    assert_eq!(d[0]["severity"], "warning");
    assert!(d[0]["message"]
        .as_str()
        .unwrap()
        .starts_with("setq of G in F"));
    assert_eq!(
        (d[0]["line"].clone(), d[0]["column"].clone()),
        (2.into(), 3.into())
    );
    assert_eq!(
        (d[0]["end_line"].clone(), d[0]["end_column"].clone()),
        (2.into(), 13.into())
    );
    assert_eq!(d[1]["severity"], "error");
    assert_eq!(
        (d[1]["line"].clone(), d[1]["column"].clone()),
        (3.into(), 3.into())
    );
    assert_eq!(d[2]["file"], "bad.lsp");
    assert_eq!(d[2]["severity"], "error");
    assert_eq!(d[2]["line"], 1);
    // A clean file: an empty list, exit 0.
    std::fs::write(dir.path().join("ok.lsp"), "(setq a 1)\n").unwrap();
    let o = lispcad_in(dir.path(), &["check", "--format=json", "ok.lsp"]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["diagnostics"], serde_json::json!([]));
}

#[test]
fn runtime_undefined_function_hint_is_in_the_diagnostic_not_the_message() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("r.lsp"),
        "(defun dtr (a) (* pi (/ a 180.0)))\n\
         (defun *error* (msg) (princ (strcat \"[\" msg \"]\")))\n\
         (dtrr 90)\n",
    )
    .unwrap();
    let o = lispcad_in(dir.path(), &["run", "r.lsp"]);
    assert_eq!(o.status.code(), Some(1));
    let out = String::from_utf8_lossy(&o.stdout);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(out.contains("[no function definition: DTRR]"), "{out}");
    assert!(err.contains("× no function definition: DTRR\n"), "{err}");
    assert!(err.contains("help: did you mean DTR?"), "{err}");
}
