//! Deep recursion keeps both ends of the call stack in the diagnostic: the innermost frames
//! and the outermost, which name the caller that started the recursion.

#[test]
fn the_outer_callers_of_a_deep_recursion_are_shown() {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .env("NO_COLOR", "1")
        .arg("eval")
        .arg("(progn (defun d (n) (if (= n 0) (car 1) (d (1- n)))) (defun e () (d 100)) (e))")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1));
    assert!(err.contains("bad argument type: consp 1"), "{err}");
    assert!(err.contains("in (E) called at <eval>:1:75"), "{err}");
    assert!(err.contains("more frames"), "{err}");
}

/// Runs `lispcad ARGS` under `ulimit -v KB` (address space), as a small container or a
/// cautious admin sets it.
fn lispcad_under_ulimit(kb: u32, args: &[&str]) -> std::process::Output {
    std::process::Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kb} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

#[test]
fn every_command_starts_under_a_small_address_space_limit() {
    for kb in [1_000_000, 2_000_000] {
        let o = lispcad_under_ulimit(kb, &["eval", "(+ 1 2)"]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "ulimit -v {kb}: {err}");
        assert_eq!(
            String::from_utf8_lossy(&o.stdout).trim(),
            "3",
            "ulimit -v {kb}"
        );
        // Recursion still works, with a smaller limit that ends in the clean error.
        let o = lispcad_under_ulimit(
            kb,
            &[
                "eval",
                "(defun f (n) (if (= n 0) 0 (1+ (f (1- n))))) (princ (f 10000)) (f 100000000)",
            ],
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "ulimit -v {kb}: {err}");
        assert_eq!(
            String::from_utf8_lossy(&o.stdout),
            "10000",
            "ulimit -v {kb}"
        );
        assert!(err.contains("stack overflow"), "ulimit -v {kb}: {err}");
        assert!(!err.contains("panicked"), "ulimit -v {kb}: {err}");
    }
}
