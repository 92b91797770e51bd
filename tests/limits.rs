//! Hostile scripts through the real binary, in a child process: they must end in a result or
//! a clean error with exit status 1 — never a signal (a Rust stack overflow aborts with
//! SIGSEGV/SIGABRT).

use std::process::Command;

fn run_script(name: &str, src: &str, extra: &[&str]) -> (Option<i32>, String, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, src).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(extra)
        .arg("run")
        .arg(&path)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_million_nested_calls_end_in_a_result_or_the_clean_error() {
    let (code, out, err) = run_script(
        "deep.lsp",
        "(defun f (n) (if (= n 0) 0 (1+ (f (1- n)))))\n(princ (f 100000))\n(princ \" \")\n(princ (f 1000000))\n",
        &[],
    );
    assert!(out.starts_with("100000 "), "stdout: {out}\nstderr: {err}");
    match code {
        Some(0) => assert!(out.ends_with("1000000"), "{out}"),
        Some(1) => assert!(err.contains("stack overflow"), "{err}"),
        other => panic!("killed or odd exit {other:?}; stderr: {err}"),
    }
}

#[test]
fn unbounded_recursion_is_a_clean_error() {
    let (code, _, err) = run_script("inf.lsp", "(defun r (n) (+ 1 (r n))) (r 0)\n", &[]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("stack overflow"), "{err}");
}

#[test]
fn max_steps_stops_an_endless_loop() {
    let (code, _, err) = run_script(
        "loop.lsp",
        "(while t (setq x 1))\n",
        &["--max-steps", "100000"],
    );
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("evaluation budget exceeded"), "{err}");
}

#[test]
fn million_deep_data_is_built_compared_printed_and_dropped() {
    let (code, out, err) = run_script(
        "data.lsp",
        "(setq a nil b nil)\n(repeat 1000000 (setq a (list a) b (list b)))\n\
         (princ (equal a b))\n(princ (strlen (vl-prin1-to-string a)))\n(setq a nil b nil)\n(princ \"done\")\n",
        &[],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with('T') && out.ends_with("done"), "{out}");
}
