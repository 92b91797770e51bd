//! The memory budget through the real binary, in a child process under an address-space
//! limit: the bombs end in an "out of memory" error (exit 1) that `*error*` and
//! `vl-catch-all-apply` see, never a signal; in a batch only the bomb row fails.
#![cfg(target_os = "linux")]

use std::process::{Command, Output};

const BOMB: &str = "(setq s \"x\") (repeat 31 (setq s (strcat s s)))";

fn lispcad_limited(address_space: &str, args: &[&str], dir: &std::path::Path) -> Output {
    Command::new("prlimit")
        .arg(format!("--as={address_space}"))
        .arg(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("prlimit (util-linux) runs")
}

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn the_strcat_bomb_is_an_out_of_memory_error_under_an_address_space_limit() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bomb.lsp"),
        format!("{BOMB}\n(princ (strlen s))\n"),
    )
    .unwrap();
    // The default budget follows the limit (a third of it): no --max-memory given.
    let o = lispcad_limited("3000000000", &["run", "bomb.lsp"], dir.path());
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    assert!(err(&o).contains("out of memory"), "{}", err(&o));
    assert!(o.stdout.is_empty());
}

#[test]
fn error_handlers_and_catch_all_see_out_of_memory() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("h.lsp"),
        format!(
            "(defun *error* (m) (princ (strcat \"handler: \" m)))\n\
             (princ (vl-catch-all-error-message (vl-catch-all-apply '(lambda () {BOMB}) nil)))\n\
             (setq s nil) (princ \"|\")\n\
             (setq l nil) (repeat 10000000 (setq l (cons 1 l)))\n"
        ),
    )
    .unwrap();
    let o = lispcad_limited(
        "3000000000",
        &["--max-memory", "64M", "run", "h.lsp"],
        dir.path(),
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{}", err(&o));
    let (caught, handled) = out.split_once('|').expect("both parts ran");
    assert!(caught.starts_with("out of memory: "), "{out}");
    assert!(
        caught.ends_with("budget of 64.0 MB (--max-memory)"),
        "{out}"
    );
    assert!(handled.starts_with("handler: out of memory"), "{out}");
}

#[test]
fn a_batch_with_one_bomb_row_finishes_every_other_row() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("t.lsp"),
        format!("(if (= K 3) (progn {BOMB}))\n(draw (circle '(0 0) K))\n"),
    )
    .unwrap();
    let o = lispcad_limited(
        "6000000000",
        &[
            "batch",
            "t.lsp",
            "--grid",
            "K=1:6:1",
            "-o",
            "out/c-{K}.svg",
            "-j",
            "2",
            "--max-memory",
            "256M",
        ],
        dir.path(),
    );
    let e = err(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(e.contains("row 3/6 FAILED"), "{e}");
    assert!(e.contains("out of memory"), "{e}");
    assert!(e.contains("batch: 5 done, 1 failed, 0 not run"), "{e}");
    let mut names: Vec<String> = std::fs::read_dir(dir.path().join("out"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        ["c-1.svg", "c-2.svg", "c-4.svg", "c-5.svg", "c-6.svg"]
    );
}

#[test]
fn a_bad_size_is_a_usage_error() {
    let o = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(["--max-memory", "lots", "eval", "1"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(err(&o).contains("not a size"), "{}", err(&o));
}
