//! mimalloc started by the binary on first use (src/main.rs, `mimalloc_start`), seen through
//! its own MIMALLOC_VERBOSE report ("process init" when it starts, "process done" at exit):
//! an empty script never starts it; a script that allocates past the start-up buffer does,
//! once, and its exit report still prints; a batch's worker threads find it started.
#![cfg(lazy_mimalloc)]

use std::process::{Command, Output};

fn lispcad_verbose(dir: &std::path::Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .current_dir(dir)
        .env("MIMALLOC_VERBOSE", "1")
        .output()
        .expect("run lispcad")
}

fn count(o: &Output, what: &str) -> usize {
    String::from_utf8_lossy(&o.stderr).matches(what).count()
}

#[test]
fn an_empty_script_never_starts_mimalloc() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("empty.lsp"), "").unwrap();
    let o = lispcad_verbose(dir.path(), &["run", "empty.lsp"]);
    assert!(o.status.success(), "{o:?}");
    assert_eq!(count(&o, "mimalloc: process init"), 0, "{o:?}");
    assert_eq!(count(&o, "mimalloc: process done"), 0, "{o:?}");
}

#[test]
fn a_script_past_the_start_up_buffer_starts_it_once_and_its_exit_report_prints() {
    let dir = tempfile::tempdir().unwrap();
    // 100,000 cons cells: megabytes, far past the 128 KiB buffer.
    std::fs::write(
        dir.path().join("list.lsp"),
        "(setq l nil) (repeat 100000 (setq l (cons 1 l))) (princ (length l))",
    )
    .unwrap();
    let o = lispcad_verbose(dir.path(), &["run", "list.lsp"]);
    assert!(o.status.success(), "{o:?}");
    assert_eq!(String::from_utf8_lossy(&o.stdout), "100000");
    assert_eq!(count(&o, "mimalloc: process init"), 1, "{o:?}");
    assert_eq!(count(&o, "mimalloc: process done"), 1, "{o:?}");
}

#[test]
fn a_batch_of_small_rows_on_worker_threads_starts_it_once() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("row.lsp"), "(princ \"\")").unwrap();
    let o = lispcad_verbose(
        dir.path(),
        &[
            "batch",
            "row.lsp",
            "--grid",
            "N=1:8:1",
            "-o",
            "out/r-{N}.svg",
            "-j",
            "2",
        ],
    );
    assert!(o.status.success(), "{o:?}");
    assert_eq!(count(&o, "mimalloc: process init"), 1, "{o:?}");
    for n in 1..=8 {
        assert!(
            dir.path().join(format!("out/r-{n}.svg")).is_file(),
            "row {n}"
        );
    }
}
