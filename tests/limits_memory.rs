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

/// Runs a script under an address-space limit; (exit code, stdout, stderr).
fn script_limited(address_space: &str, pre: &[&str], src: &str) -> (Option<i32>, String, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.lsp"), src).unwrap();
    let mut args: Vec<&str> = pre.to_vec();
    args.extend(["run", "s.lsp"]);
    let o = lispcad_limited(address_space, &args, dir.path());
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        err(&o),
    )
}

#[test]
fn a_budget_above_the_address_space_still_ends_in_out_of_memory() {
    // The user's budget is larger than the kernel allows: the strcat that the kernel refuses
    // is caught by its fallible reservation, not aborted.
    let (code, out, e) = script_limited(
        "1500000000",
        &["--max-memory", "64G"],
        &format!("{BOMB}\n(princ (strlen s))\n"),
    );
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("out of memory"), "{e}");
    assert!(out.is_empty(), "{out}");
}

/// A structure shared 60 levels deep: 60 conses, 2^60 leaves when printed as a tree.
const SHARED: &str = "(setq l (list 1)) (repeat 60 (setq l (list l l)))";

#[test]
fn printing_a_shared_structure_ends_in_out_of_memory() {
    for print in [
        "(princ l)",
        "(prin1 l)",
        "(print l)",
        "(setq x (vl-prin1-to-string l))",
        "(setq x (vl-princ-to-string l))",
    ] {
        let (code, out, e) = script_limited(
            "3000000000",
            &["--max-memory", "16M"],
            &format!(
                "{SHARED}\n(princ (vl-catch-all-error-message (vl-catch-all-apply '(lambda () {print}) nil)))\n(princ \"|after\")\n{print}\n"
            ),
        );
        assert_eq!(code, Some(1), "{print}: {e}");
        assert!(out.starts_with("out of memory: "), "{print}: {out}");
        assert!(out.ends_with("|after"), "{print}: {out}");
        assert!(e.contains("out of memory"), "{print}: {e}");
    }
}

#[test]
fn an_error_message_shows_a_huge_value_shortened() {
    let (code, _, e) = script_limited("3000000000", &[], &format!("{SHARED}\n(+ 1 l)\n"));
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("bad argument type: numberp: ((((("), "{e}");
    assert!(e.contains("..."), "{e}");
    assert!(e.len() < 20_000, "{} bytes of message", e.len());
}

#[test]
fn one_call_asking_for_gigabytes_is_refused_before_allocating() {
    // Each makes one huge allocation from small arguments (or from one big string).
    for (what, src) in [
        (
            "safearray",
            "(vlax-make-safearray vlax-vbDouble '(0 . 2000000000))".to_string(),
        ),
        (
            "safearray 2D",
            "(vlax-make-safearray vlax-vbDouble '(0 . 100000) '(0 . 100000))".to_string(),
        ),
        (
            "subst",
            "(setq s (strcat \"x\")) (repeat 23 (setq s (strcat s s))) (repeat 8 (setq s (vl-string-subst s \"x\" s)))"
                .to_string(),
        ),
        (
            "strcase",
            "(setq s \"x\") (repeat 23 (setq s (strcat s s))) (setq a (strcase s) b (strcase s) c (strcase s) d (strcase s) e (strcase s))".to_string(),
        ),
    ] {
        let (code, _, e) = script_limited("3000000000", &["--max-memory", "64M"], &src);
        assert_eq!(code, Some(1), "{what}: {e}");
        assert!(e.contains("out of memory"), "{what}: {e}");
    }
}

#[test]
fn a_file_of_one_endless_line_is_out_of_memory_not_an_abort() {
    let dir = tempfile::tempdir().unwrap();
    // 48 MB without a newline, read by read-line, load and dxf-open under a 16 MB budget.
    std::fs::write(dir.path().join("big.txt"), vec![b'a'; 48 << 20]).unwrap();
    for read in [
        "(read-line (open \"big.txt\" \"r\"))",
        "(load \"big.txt\")",
        "(dxf-open \"big.txt\")",
    ] {
        std::fs::write(dir.path().join("s.lsp"), read).unwrap();
        let o = lispcad_limited(
            "3000000000",
            &["--max-memory", "16M", "run", "s.lsp"],
            dir.path(),
        );
        assert_eq!(o.status.code(), Some(1), "{read}: {}", err(&o));
        assert!(err(&o).contains("out of memory"), "{read}: {}", err(&o));
    }
}

#[test]
fn batch_starts_its_workers_under_a_small_address_space_limit() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("t.lsp"),
        "(defun f (n) (if (= n 0) 0 (1+ (f (1- n)))))\n(f 5000)\n(draw (circle '(0 0) K))\n",
    )
    .unwrap();
    for kb in ["1000000", "2000000"] {
        let o = Command::new("sh")
            .arg("-c")
            .arg(format!("ulimit -v {kb} && exec \"$0\" \"$@\""))
            .arg(env!("CARGO_BIN_EXE_lispcad"))
            .args([
                "batch",
                "t.lsp",
                "--grid",
                "K=1:4:1",
                "-o",
                "out/c-{K}.svg",
                "-j",
                "2",
            ])
            .current_dir(dir.path())
            .output()
            .unwrap();
        let e = err(&o);
        assert_eq!(o.status.code(), Some(0), "ulimit -v {kb}: {e}");
        assert!(e.contains("batch: 4 done, 0 failed"), "ulimit -v {kb}: {e}");
        for k in 1..=4 {
            assert!(dir.path().join(format!("out/c-{k}.svg")).is_file());
        }
        std::fs::remove_dir_all(dir.path().join("out")).unwrap();
    }
}

#[test]
fn a_request_the_system_refused_is_not_left_counted() {
    // Each safearray asks for 800 MB at once, within the 8 GB budget but beyond the 600 MB
    // address space: the system refuses it. Were the refused requests left in the thread's
    // count, the twentieth message would name 16 GB and the list after it would be refused.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("r.lsp"),
        "(setq msgs nil)\n\
         (repeat 20 (setq msgs (cons (vl-catch-all-error-message (vl-catch-all-apply \
           'vlax-make-safearray (list vlax-vbDouble '(0 . 99999999)))) msgs)))\n\
         (princ (car msgs)) (princ \"|\") (princ (last msgs)) (princ \"|\")\n\
         (setq l nil) (repeat 100000 (setq l (cons 1 l))) (princ (length l))\n",
    )
    .unwrap();
    let o = lispcad_limited(
        "600000000",
        &["--max-memory", "8G", "run", "r.lsp"],
        dir.path(),
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{}{out}", err(&o));
    let parts: Vec<&str> = out.split('|').collect();
    assert!(parts[0].starts_with("out of memory: "), "{out}");
    assert_eq!(parts[0], parts[1], "{out}");
    assert_eq!(parts[2], "100000", "{out}");
}
