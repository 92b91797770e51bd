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
