//! `--max-steps` bounds expensive builtins by their work, not only loops: directory globbing
//! (linear-time, charged per comparison), sorting (n log n), wcmatch and file reads.

use std::process::{Command, Output};

fn run(dir: &std::path::Path, src: &str, steps: &str) -> Output {
    let script = dir.join("s.lsp");
    std::fs::write(&script, src).unwrap();
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(["--max-steps", steps, "run"])
        .arg(&script)
        .output()
        .unwrap()
}

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn a_pattern_of_many_stars_is_fast_and_exact() {
    let dir = tempfile::tempdir().unwrap();
    for i in 0..20 {
        std::fs::write(dir.path().join(format!("{}{i}.txt", "a".repeat(60))), "").unwrap();
    }
    std::fs::write(dir.path().join(format!("{}b", "a".repeat(60))), "").unwrap();
    // Ten stars: exponential backtracking took minutes on these names.
    let o = run(
        dir.path(),
        "(princ (vl-directory-files nil \"*a*a*a*a*a*a*a*a*a*b\" 1))",
        "100000000",
    );
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        format!("({}b)", "a".repeat(60))
    );
}

#[test]
fn builtins_are_charged_by_their_work() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("big.txt"), "x".repeat(4_000_000)).unwrap();
    let cases = [
        // One call each, far more work than the budget.
        ("(setq l nil) (setq i 0) (repeat 3000 (setq l (cons (setq i (1+ i)) l))) (setq l (append l l l l l l l l l l l l l l l l))", "(vl-sort l '<)"),
        ("(setq s (strcat \"x\" \"xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx\")) (repeat 10 (setq s (strcat s s)))", "(wcmatch s \"*a*a*a*a*a*a*a*a*b\")"),
        ("(setq f (open \"big.txt\" \"r\"))", "(read-line f)"),
    ];
    for (setup, call) in cases {
        // Everything but the last call fits easily in the budget.
        let o = run(dir.path(), setup, "20000");
        assert_eq!(o.status.code(), Some(0), "{setup}: {}", err(&o));
        let src = format!("{setup} {call}");
        let o = run(dir.path(), &src, "20000");
        assert_eq!(o.status.code(), Some(1), "{src}: {}", err(&o));
        assert!(
            err(&o).contains("evaluation budget exceeded"),
            "{src}: {}",
            err(&o)
        );
    }
}
