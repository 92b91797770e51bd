//! Programs compiled once and run per row against restored globals (`Interp::compile_program`,
//! `save_globals`, `restore_globals`): each run sees what a fresh interpreter would.

use lispcad::builtins::new_interp;
use lispcad::lang::eval::with_eval_stack;
use lispcad::lang::Interp;

/// Runs `src` `rows` times on one interpreter, restoring the globals before each run, with the
/// row number bound to ROW; the printed value (or "ERR: message") of each run.
fn rows(src: &'static str, rows: i32) -> Vec<String> {
    with_eval_stack(move || {
        let mut it = new_interp();
        it.out = Box::new(std::io::sink());
        let program = it.compile_program("rows.lsp", src).expect("compiles");
        let fresh = it.save_globals();
        (0..rows)
            .map(|row| {
                it.restore_globals(&fresh);
                it.set_global("ROW", lispcad::lang::Value::Int(row));
                match it.run_program(&program) {
                    Ok(v) => it.prin1_string(&v),
                    Err(e) => format!("ERR: {}", e.message),
                }
            })
            .collect()
    })
}

#[test]
fn globals_set_by_one_run_are_gone_in_the_next() {
    let r = rows(
        "(setq seen (if counter 'dirty 'clean)) (setq counter (1+ (if counter counter 0))) (list seen counter row)",
        3,
    );
    assert_eq!(r, ["(CLEAN 1 0)", "(CLEAN 1 1)", "(CLEAN 1 2)"]);
}

#[test]
fn redefined_builtins_and_error_handlers_are_restored() {
    let r = rows(
        "(setq before (car '(1 2))) (defun car (x) 42) (defun *error* (m) (princ m)) (list before (car '(1 2)))",
        2,
    );
    assert_eq!(r, ["(1 42)", "(1 42)"]);
}

#[test]
fn the_drawing_and_system_variables_start_empty_each_run() {
    let r = rows(
        "(setq n (if (ssget \"X\") (sslength (ssget \"X\")) 0) old (getvar \"OSMODE\"))
         (setvar \"OSMODE\" (+ old 1))
         (entmake '((0 . \"LINE\") (10 0.0 0.0 0.0) (11 1.0 1.0 0.0)))
         (list n (= old (- (getvar \"OSMODE\") 1)) old)",
        2,
    );
    assert_eq!(r[0], r[1]);
    assert!(r[0].starts_with("(0 T "), "{}", r[0]);
}

#[test]
fn symbols_interned_by_a_run_are_forgotten_and_errors_leave_no_bindings() {
    with_eval_stack(|| {
        let mut it: Interp = new_interp();
        it.out = Box::new(std::io::sink());
        let program = it
            .compile_program(
                "rows.lsp",
                "(defun f (x / y) (setq y (read \"made-up-at-run-time\")) (set y x) (car x)) (f 5)",
            )
            .unwrap();
        let fresh = it.save_globals();
        let n = it.syms.len();
        for _ in 0..2 {
            it.restore_globals(&fresh);
            let e = it.run_program(&program).unwrap_err();
            assert!(e.message.contains("bad argument type"), "{}", e.message);
            assert!(it.syms.len() > n);
        }
        it.restore_globals(&fresh);
        assert_eq!(it.syms.len(), n);
        assert!(it.syms.lookup("MADE-UP-AT-RUN-TIME").is_none());
        // X was bound by F when the error struck: the binding is gone.
        assert!(it.global("X").is_nil());
    });
}

#[test]
fn a_reader_error_is_reported_when_compiling() {
    with_eval_stack(|| {
        let mut it = new_interp();
        let e = it
            .compile_program("bad.lsp", "(setq a 1) (oops")
            .err()
            .unwrap();
        assert!(e.span.is_some());
    });
}
