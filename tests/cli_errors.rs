//! Error paths of the binary: AutoLISP's message as the first line, the span at the right
//! form (line:col in miette's output), the Lisp call stack, exit codes, `--set`, `--max-steps`,
//! and the limits that must end in clean errors rather than aborts.

use std::process::Output;

mod cli_support;
use cli_support::lispcad_in;

struct Run {
    /// None when the process died of a signal (an abort): always a test failure.
    code: Option<i32>,
    out: String,
    err: String,
}

impl Run {
    /// The diagnostic's first line without miette's marker: AutoLISP's message.
    fn message(&self) -> String {
        let line = self
            .err
            .lines()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("");
        line.trim().trim_start_matches('×').trim().to_string()
    }
}

fn to_run(o: Output) -> Run {
    Run {
        code: o.status.code(),
        out: String::from_utf8_lossy(&o.stdout).into_owned(),
        err: String::from_utf8_lossy(&o.stderr).into_owned(),
    }
}

/// Runs a script file `s.lsp` with extra arguments.
fn run_script(script: &str, extra: &[&str]) -> Run {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), script).unwrap();
    let mut args = vec!["run", "s.lsp"];
    args.extend_from_slice(extra);
    to_run(lispcad_in(dir.path(), &args))
}

fn eval(expr: &str, extra: &[&str]) -> Run {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec!["eval", expr];
    args.extend_from_slice(extra);
    to_run(lispcad_in(dir.path(), &args))
}

#[test]
fn autolisp_messages_come_first() {
    let cases = [
        ("(+ 1 nil)", "bad argument type: numberp: nil"),
        ("(/ 1 0)", "divide by zero"),
        ("(foo 1)", "no function definition: FOO"),
        ("(progn (defun f (a b) a) (f 1))", "too few arguments"),
        ("(progn (defun f (a) a) (f 1 2))", "too many arguments"),
        ("(car 1 2)", "too many arguments"),
        ("(strcat \"a\" 1)", "bad argument type: stringp 1"),
        ("(distance '(0 0) 5)", "bad argument type: 2D/3D point: 5"),
    ];
    for (expr, msg) in cases {
        let r = eval(expr, &[]);
        assert_eq!(r.code, Some(1), "{expr}: {}", r.err);
        assert_eq!(r.message(), msg, "{expr}");
    }
}

#[test]
fn span_points_at_the_failing_form_and_stack_names_callers() {
    let script = "\
(defun inner (x)
  (+ x 1))
(defun outer (y)
  (inner y))
(setq ok 1)
(outer nil)
";
    let r = run_script(script, &[]);
    assert_eq!(r.code, Some(1));
    assert_eq!(r.message(), "bad argument type: numberp: nil");
    // The (+ x 1) form on line 2, column 3.
    assert!(r.err.contains("[s.lsp:2:3]"), "{}", r.err);
    assert!(r.err.contains("2 │   (+ x 1))"), "{}", r.err);
    // The underline sits under "(+ x 1)" (7 characters) on the snippet line.
    let snippet = r
        .err
        .lines()
        .skip_while(|l| !l.contains("(+ x 1))"))
        .nth(1)
        .unwrap();
    assert!(snippet.ends_with("   ───┬───"), "{snippet:?}");
    // Innermost call first, each with its call site.
    let inner = r
        .err
        .find("in (INNER) called at s.lsp:4:3")
        .expect("inner frame");
    let outer = r
        .err
        .find("in (OUTER) called at s.lsp:6:1")
        .expect("outer frame");
    assert!(inner < outer);
}

#[test]
fn span_of_a_builtin_error_inside_a_nested_expression() {
    let r = run_script("(setq a 1)\n(setq b (list 1 (car (cdr 5)) 3))\n", &[]);
    assert_eq!(r.message(), "bad argument type: consp 5");
    assert!(r.err.contains("[s.lsp:2:22]"), "{}", r.err);
}

#[test]
fn unclosed_paren_is_reported_at_the_paren() {
    let script = "(setq a 1)\n(defun f (x)\n  (* x 2)\n\n(setq b 2)\n";
    let r = run_script(script, &[]);
    assert_eq!(r.code, Some(1));
    assert_eq!(
        r.message(),
        "malformed list on input: this ( is never closed"
    );
    assert!(r.err.contains("[s.lsp:2:1]"), "{}", r.err);
    // check reports it too, at the same place, as an error.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), script).unwrap();
    let c = to_run(lispcad_in(dir.path(), &["check", "s.lsp"]));
    assert_eq!(c.code, Some(1));
    assert!(c.err.contains("[s.lsp:2:1]"), "{}", c.err);
}

#[test]
fn exit_codes() {
    assert_eq!(eval("(+ 1 2)", &[]).code, Some(0));
    assert_eq!(eval("(car 1)", &[]).code, Some(1));
    // (exit) ends the script normally.
    let r = run_script("(princ \"a\")\n(exit)\n(princ \"b\")\n", &[]);
    assert_eq!((r.code, r.out.as_str()), (Some(0), "a"));
    // Usage errors: a missing script, a malformed --set, an unknown option.
    let dir = tempfile::tempdir().unwrap();
    let missing = to_run(lispcad_in(dir.path(), &["run", "nope.lsp"]));
    assert_eq!(missing.code, Some(2));
    assert!(
        missing.err.contains("cannot read script nope.lsp"),
        "{}",
        missing.err
    );
    for bad in ["L1", "=3", "L1=", "L1=(1 2", "L1=1 2", "12=3"] {
        let r = eval("1", &["--set", bad]);
        assert_eq!(r.code, Some(2), "--set {bad}: {}", r.err);
        assert!(r.err.contains("--set"), "{}", r.err);
    }
    assert_eq!(eval("1", &["--no-such-option"]).code, Some(2));
    assert_eq!(
        to_run(lispcad_in(dir.path(), &["check", "nope.lsp"])).code,
        Some(2)
    );
}

#[test]
fn set_binds_globals_read_as_literals() {
    let r = eval(
        "(list L1 name n lst (type L1) (type n))",
        &[
            "--set",
            "L1=140.0",
            "--set",
            "name=\"big\"",
            "--set",
            "n=7",
            "--set",
            "lst=(1 \"a\" b)",
        ],
    );
    assert_eq!(r.code, Some(0), "{}", r.err);
    assert_eq!(r.out.trim(), "(140.0 \"big\" 7 (1 \"a\" B) REAL INT)");
    // In a script, before the first form runs.
    let r = run_script("(princ (* L1 2))", &["--set", "L1=140.0"]);
    assert_eq!((r.code, r.out.as_str()), (Some(0), "280.0"));
}

#[test]
fn max_steps_stops_runaway_loops() {
    let r = eval("(while t 1)", &["--max-steps", "10000"]);
    assert_eq!(r.code, Some(1));
    assert!(r.message().contains("--max-steps"), "{}", r.err);
    let r = eval(
        "(progn (setq i 0) (repeat 100 (setq i (1+ i))) i)",
        &["--max-steps", "100000"],
    );
    assert_eq!((r.code, r.out.trim()), (Some(0), "100"));
    // The budget cannot be caught by vl-catch-all-apply.
    let r = eval(
        "(vl-catch-all-apply '(lambda () (while t 1)) nil)",
        &["--max-steps", "5000"],
    );
    assert_eq!(r.code, Some(1), "{}", r.out);
    assert_eq!(eval("1", &["--max-steps", "lots"]).code, Some(2));
}

#[test]
fn a_million_cell_list_builds_and_drops() {
    let r = eval(
        "(progn (setq l nil) (repeat 1000000 (setq l (cons 1 l))) \
         (setq n (length l) l nil) \
         (setq m (list (list (list 1)))) (repeat 1000000 (setq m (list m))) (setq m nil) n)",
        &[],
    );
    assert_eq!((r.code, r.out.trim()), (Some(0), "1000000"), "{}", r.err);
}

#[test]
fn a_hundred_thousand_nested_user_calls_work() {
    let r = eval(
        "(progn (defun d (n) (if (= n 0) 0 (1+ (d (1- n))))) (d 100000))",
        &[],
    );
    assert_eq!((r.code, r.out.trim()), (Some(0), "100000"), "{}", r.err);
}

#[test]
fn a_million_nested_calls_end_cleanly_not_in_an_abort() {
    let r = eval(
        "(progn (defun d (n) (if (= n 0) 0 (1+ (d (1- n))))) (d 1000000))",
        &[],
    );
    // Either the evaluator manages it, or it reports a clean error: never a signal.
    match r.code {
        Some(0) => assert_eq!(r.out.trim(), "1000000"),
        Some(1) => {
            assert!(r.message().starts_with("stack overflow"), "{}", r.err);
            assert!(r.err.contains("in (D) called at <eval>:1:39"), "{}", r.err);
        }
        other => panic!("ended with {other:?} (a signal?): {}", r.err),
    }
    // Mutual recursion through mapcar and apply goes through builtins on the way down.
    let r = eval(
        "(progn (defun g (n) (if (= n 0) 0 (car (mapcar '(lambda (x) (1+ (g x))) (list (1- n)))))) \
         (g 1000000))",
        &[],
    );
    assert!(
        matches!(r.code, Some(0) | Some(1)),
        "{:?} {}",
        r.code,
        r.err
    );
    if r.code == Some(1) {
        assert!(r.message().starts_with("stack overflow"), "{}", r.err);
    }
}

#[test]
fn deep_reader_nesting_is_an_error_not_a_crash() {
    let deep = format!("{}1{}", "(".repeat(200_000), ")".repeat(200_000));
    let r = run_script(&format!("(setq x '{deep})"), &[]);
    assert!(
        matches!(r.code, Some(0) | Some(1)),
        "{:?} {}",
        r.code,
        r.err
    );
    let r = run_script(&format!("(setq x (read \"{deep}\"))"), &[]);
    assert!(
        matches!(r.code, Some(0) | Some(1)),
        "{:?} {}",
        r.code,
        r.err
    );
    // Printing or comparing a deeply nested list must not crash either.
    let nest = "(setq m 1) (repeat 200000 (setq m (list m)))";
    for tail in [
        "(princ m)",
        "(equal m m)",
        "(vl-prin1-to-string m)",
        "(length (vl-sort (list m m) '<))",
    ] {
        let r = run_script(&format!("{nest} {tail}"), &[]);
        assert!(
            matches!(r.code, Some(0) | Some(1)),
            "{tail}: {:?} {}",
            r.code,
            r.err
        );
    }
}

#[test]
fn error_handler_sees_autolisp_message() {
    let r = run_script(
        "(defun *error* (msg) (princ (strcat \"caught: \" msg)) (princ))\n(/ 1 0)\n",
        &[],
    );
    assert!(r.out.starts_with("caught: divide by zero"), "{}", r.out);
    assert_eq!(r.code, Some(1));
}

#[test]
fn eval_accepts_expressions_starting_with_a_minus() {
    let r = eval("-.5", &[]);
    assert_eq!((r.code, r.out.trim()), (Some(0), "-0.5"));
}

#[test]
fn repeated_frames_are_collapsed_with_a_count() {
    let r = run_script(
        "(defun d (n)\n  (if (= n 0) (car 1) (d (1- n))))\n(defun e () (d 3))\n(e)\n",
        &[],
    );
    assert_eq!(r.message(), "bad argument type: consp 1");
    let d_frames = "in (D) called at s.lsp:2:23 [3 times]";
    let first = "in (D) called at s.lsp:3:13";
    let e = "in (E) called at s.lsp:4:1";
    let (a, b, c) = (r.err.find(d_frames), r.err.find(first), r.err.find(e));
    assert!(a.is_some() && b.is_some() && c.is_some(), "{}", r.err);
    assert!(a < b && b < c, "{}", r.err);
}

#[test]
fn errors_in_loaded_files_point_into_that_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("lf.lsp"), "(defun libf (x)\n  (/ x 0))\n").unwrap();
    std::fs::write(dir.path().join("s.lsp"), "(load \"lf\")\n\n(libf 3)\n").unwrap();
    let r = to_run(lispcad_in(dir.path(), &["run", "s.lsp"]));
    assert_eq!(r.code, Some(1));
    assert_eq!(r.message(), "divide by zero");
    assert!(r.err.contains("lf.lsp:2:3]"), "{}", r.err);
    assert!(r.err.contains("in (LIBF) called at s.lsp:3:1"), "{}", r.err);
}
