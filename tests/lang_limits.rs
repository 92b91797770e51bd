//! Limits of the evaluator: hostile programs end in clean errors, never in a Rust stack
//! overflow. These run on the evaluation thread `with_eval_stack` gives the CLI, in debug and
//! release alike.

use std::sync::atomic::Ordering;

use lispcad::builtins::new_interp;
use lispcad::lang::eval::with_eval_stack;

/// Runs each source in one fresh interpreter (output discarded); the printed value or
/// "ERR: message" of each.
fn run_all(srcs: &'static [&'static str], max_steps: Option<u64>) -> Vec<String> {
    with_eval_stack(move || {
        let mut it = new_interp();
        it.out = Box::new(std::io::sink());
        it.set_max_steps(max_steps);
        srcs.iter()
            .map(|s| match it.eval_source("test", s) {
                Ok(v) => it.prin1_string(&v),
                Err(e) => format!("ERR: {}", e.message),
            })
            .collect()
    })
}

const DEF_F: &str = "(defun f (n) (if (= n 0) 0 (1+ (f (1- n)))))";

#[test]
fn hundred_thousand_nested_calls_work_and_deeper_ones_fail_cleanly() {
    let r = run_all(
        &[
            DEF_F,
            "(f 100000)",
            "(f 1000000)",
            "(f 100000000)",
            "(f 10)",
        ],
        None,
    );
    assert_eq!(r[1], "100000");
    // A million fits the evaluation stack in release builds, not in debug ones: either
    // outcome is fine, an abort is not. A hundred million exceeds it in both.
    assert!(
        r[2] == "1000000" || r[2].starts_with("ERR: stack overflow"),
        "{}",
        r[2]
    );
    assert!(r[3].starts_with("ERR: stack overflow"), "{}", r[3]);
    // The interpreter is usable after the overflow: bindings were unwound.
    assert_eq!(r[4], "10");
}

#[test]
fn recursion_through_builtins_fails_cleanly() {
    let r = run_all(
        &[
            "(defun g (n) (if (> n 0) (apply 'g (list (1- n))) 0))",
            "(g 100000000)",
            "(defun h (n) (if (> n 0) (eval (list 'h (1- n))) 0))",
            "(h 100000000)",
            "(defun m (n) (if (> n 0) (car (mapcar 'm (list (1- n)))) 0))",
            "(m 100000000)",
            "(defun k (n) (if (> n 0) ((lambda (x) (k x)) (1- n)) 0))",
            "(k 100000000)",
            "(m 1000)",
        ],
        None,
    );
    for i in [1, 3, 5, 7] {
        assert!(r[i].starts_with("ERR: stack overflow"), "{i}: {}", r[i]);
    }
    assert_eq!(r[8], "0");
}

#[test]
fn deeply_nested_data_prints_compares_and_drops() {
    let r = run_all(
        &[
            "(setq a nil b nil) (repeat 1000000 (setq a (list a) b (list b))) 'ok",
            "(equal a b)",
            "(equal a (list b))",
            "(strlen (vl-prin1-to-string a))",
            "(eval a)",
            "(setq a nil b nil)",
        ],
        None,
    );
    assert_eq!(r[0], "OK");
    assert_eq!(r[1], "T");
    assert_eq!(r[2], "nil");
    assert!(r[3].parse::<usize>().is_ok(), "{}", r[3]);
    assert!(r[4].starts_with("ERR:"), "{}", r[4]);
    assert_eq!(r[5], "nil");
}

#[test]
fn max_steps_stops_runaway_loops() {
    let r = run_all(
        &[
            "(while t nil)",
            "(repeat 100000000 nil)",
            "(defun r () (r)) (r)",
            "(foreach x '(1 2 3) x)",
        ],
        Some(10_000),
    );
    for (i, msg) in r.iter().take(3).enumerate() {
        assert!(
            msg.starts_with("ERR: evaluation budget exceeded"),
            "{i}: {msg}"
        );
    }
    // The budget counts from `set_max_steps`: once spent, it stays spent.
    assert!(
        r[3].starts_with("ERR: evaluation budget exceeded"),
        "{}",
        r[3]
    );
}

const DEF_FIB: &str = "(defun fib (n) (if (< n 2) n (+ (fib (- n 1)) (fib (- n 2)))))";

/// Steps taken by each source, evaluated in turn in one interpreter.
fn steps_of(srcs: &'static [&'static str]) -> Vec<u64> {
    with_eval_stack(move || {
        let mut it = new_interp();
        it.out = Box::new(std::io::sink());
        it.set_max_steps(Some(1 << 40));
        srcs.iter()
            .map(|s| {
                let before = it.steps();
                it.eval_source("test", s).unwrap();
                it.steps() - before
            })
            .collect()
    })
}

#[test]
fn every_call_path_counts_one_step_per_call() {
    let r = steps_of(&[
        DEF_FIB,
        // fib(15) makes 2 fib(16) - 1 = 1973 calls; the inlined `<`, `+`, `-` are no calls.
        "(fib 15)",
        // Five parameters take the general path, locals the save stack: 11 calls each.
        "(defun g5 (a b c d e) (if (> a 0) (g5 (1- a) b c d e) 0)) (g5 10 0 0 0 0)",
        "(defun g2 (a b / x) (if (> a 0) (g2 (1- a) b) 0)) (g2 10 0)",
        // `apply` and `mapcar` call through the slice path: 3 + 3 calls.
        "(defun one (x) x) (apply 'one '(1)) (mapcar 'one '(1 2))",
        // A redefined `<` is a user function: one more step per test (1973 calls of each).
        "(setq old< <) (defun < (a b) (old< a b)) (fib 15) (setq < old<)",
    ]);
    assert_eq!(r[1..], [1973, 11, 11, 3, 2 * 1973]);
}

#[test]
fn parameters_come_back_after_a_budget_or_stack_abort_deep_in_a_recursion() {
    let r = run_all(
        &[
            "(setq n 'outer a 'outer)",
            DEF_FIB,
            DEF_F,
            "(fib 25)",
            "n",
            "(defun h (a b / c) (h (1+ a) b))",
            "(h 0 'b)",
            "(list n a)",
        ],
        Some(200_000),
    );
    assert!(
        r[3].starts_with("ERR: evaluation budget exceeded"),
        "{}",
        r[3]
    );
    assert_eq!(r[4], "OUTER");
    assert!(
        r[6].starts_with("ERR: evaluation budget exceeded"),
        "{}",
        r[6]
    );
    assert_eq!(r[7], "(OUTER OUTER)");
    let r = run_all(&["(setq n 'outer)", DEF_F, "(f 100000000)", "n"], None);
    assert!(r[2].starts_with("ERR: stack overflow"), "{}", r[2]);
    assert_eq!(r[3], "OUTER");
}

#[test]
fn interrupt_flag_stops_a_loop() {
    let r = with_eval_stack(|| {
        let mut it = new_interp();
        it.interrupt.store(true, Ordering::Relaxed);
        match it.eval_source("test", "(while t nil)") {
            Ok(_) => "finished".to_string(),
            Err(e) => e.message,
        }
    });
    assert_eq!(r, "interrupted");
}

#[test]
fn reader_nesting_is_bounded() {
    let r = with_eval_stack(|| {
        let mut it = new_interp();
        let src = "(".repeat(100_000) + &")".repeat(100_000);
        match it.eval_source("test", &src) {
            Ok(_) => "finished".to_string(),
            Err(e) => e.message,
        }
    });
    assert!(r.contains("nested deeper"), "{r}");
}
