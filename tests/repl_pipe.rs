//! The REPL driven through a pipe (stdin not a terminal): the same entry loop without line
//! editing. Multi-line entries complete only when balanced, errors do not end the session.

use std::io::Write;
use std::process::Command;

mod cli_support;
use cli_support::{repl_output, spawn_piped};

/// Feeds `input` to `lispcad repl [args]`; (exit code, stdout, stderr).
fn repl_in(dir: &std::path::Path, args: &[&str], input: &str) -> (i32, String, String) {
    let o = repl_output(dir, args, input);
    (
        o.status.code().expect("exit code"),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn repl(input: &str) -> (i32, String, String) {
    let dir = tempfile::tempdir().unwrap();
    repl_in(dir.path(), &[], input)
}

fn lines(s: &str) -> Vec<&str> {
    s.lines().collect()
}

#[test]
fn multi_line_entries_wait_for_balance() {
    let (code, out, err) = repl("(setq s \"(((\" ; comment (((\n  n 5)\n(strcat s \")\")\n(+ 1\n  2\n)\n;| block ( |; (* 2 2)\n");
    assert_eq!(code, 0, "{err}");
    assert_eq!(lines(&out), ["5", "\"((()\"", "3", "4"]);
}

#[test]
fn an_error_does_not_end_the_session() {
    let (code, out, err) = repl("(car 1)\n(undefined-fn)\n(setq a 2)\n(* a 3)\n");
    assert_eq!(code, 0);
    assert_eq!(lines(&out), ["2", "6"]);
    assert!(err.contains("bad argument type: consp 1"), "{err}");
    assert!(
        err.contains("no function definition: UNDEFINED-FN"),
        "{err}"
    );
}

#[test]
fn princ_without_arguments_prints_nothing() {
    let (_, out, _) = repl("(princ)\n(progn (princ \"x\") (princ))\n(setq z 1)\n");
    assert_eq!(out, "x1\n");
}

#[test]
fn help_command_and_function() {
    let (_, out, _) = repl(":help car\n(help 'mapcar)\n:help no-such-thing\n");
    let l = lines(&out);
    assert_eq!(l[0], "(car list)");
    assert!(l[1].trim().starts_with("The first element"), "{out}");
    assert!(l.iter().any(|x| x.starts_with("(mapcar f list")), "{out}");
    assert!(out.contains("no help for no-such-thing"), "{out}");
}

#[test]
fn load_command_and_files_given_on_the_command_line() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("lib.lsp"), "(defun sq (x) (* x x))\n").unwrap();
    std::fs::write(dir.path().join("pre.lsp"), "(setq pre 41)\n").unwrap();
    let (code, out, err) = repl_in(
        dir.path(),
        &["pre.lsp"],
        ":load lib.lsp\n(sq 4)\n(1+ pre)\n:load missing.lsp\n(sq 5)\n",
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(lines(&out), ["SQ", "16", "42", "25"]);
    assert!(!err.is_empty());
}

#[test]
fn quit_and_exit_leave_the_session() {
    let (code, out, _) = repl("(setq a 1)\n:quit\n(setq a 2)\n");
    assert_eq!((code, out.as_str()), (0, "1\n"));
    let (code, out, _) = repl("(setq a 1)\n(exit)\n(setq a 2)\n");
    assert_eq!((code, out.as_str()), (0, "1\n"));
}

#[test]
fn an_unfinished_entry_at_end_of_input_is_reported() {
    let (code, out, err) = repl("(setq a 1)\n(setq b\n");
    assert_eq!(code, 0);
    assert_eq!(out, "1\n");
    assert!(err.contains("never closed"), "{err}");
}

#[test]
fn no_subcommand_starts_the_repl() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = spawn_piped(dir.path(), &[]);
    child.stdin.take().unwrap().write_all(b"(* 6 7)\n").unwrap();
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&o.stdout), "42\n");
}

#[test]
fn answers_feed_get_functions_in_the_repl() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.txt"), "3,4\n").unwrap();
    let (code, out, err) = repl_in(
        dir.path(),
        &["--answers", "a.txt"],
        "(distance '(0 0) (getpoint \"P: \"))\n(getreal)\n(+ 1 1)\n",
    );
    assert_eq!(code, 0);
    assert_eq!(lines(&out), ["5.0", "2"]);
    assert!(err.contains("getreal: no answers left"), "{err}");
}

/// SIGINT (Ctrl-C) during an evaluation interrupts it and the session goes on.
#[cfg(unix)]
#[test]
fn interrupt_stops_a_running_evaluation_not_the_session() {
    use std::io::{BufRead, BufReader};
    let dir = tempfile::tempdir().unwrap();
    let mut child = spawn_piped(dir.path(), &["repl"]);
    let mut stdin = child.stdin.take().unwrap();
    let mut out = BufReader::new(child.stdout.take().unwrap());
    // A first answer proves the REPL (and its interrupt handler) is up.
    stdin.write_all(b"(+ 40 2)\n").unwrap();
    let mut line = String::new();
    out.read_line(&mut line).unwrap();
    assert_eq!(line, "42\n");
    stdin.write_all(b"(while t 1)\n").unwrap();
    std::thread::sleep(std::time::Duration::from_millis(300));
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    stdin.write_all(b"(+ 1 2)\n").unwrap();
    drop(stdin);
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut out, &mut rest).unwrap();
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0), "ended by a signal?");
    assert_eq!(rest, "3\n");
    assert!(String::from_utf8_lossy(&o.stderr).contains("interrupted"));
}

#[test]
fn max_steps_applies_to_each_entry() {
    let dir = tempfile::tempdir().unwrap();
    let (code, out, err) = repl_in(
        dir.path(),
        &["--max-steps", "5000"],
        "(while t 1)\n(repeat 100 1)\n(progn (setq i 0) (repeat 3000 (setq i (1+ i))) i)\n",
    );
    assert_eq!(code, 0);
    assert!(err.contains("--max-steps"), "{err}");
    assert_eq!(lines(&out), ["1", "3000"]);
}

#[test]
fn save_writes_the_drawing() {
    let dir = tempfile::tempdir().unwrap();
    let (code, out, err) = repl_in(
        dir.path(),
        &["--dxf-profile", "cam"],
        "(draw (line '(0 0) '(10 5)))\n:save o.svg\n:save o.dxf\n:save o.txt\n",
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("wrote o.svg") && out.contains("wrote o.dxf"),
        "{out}"
    );
    assert!(err.contains("o.txt"), "{err}");
    let svg = std::fs::read_to_string(dir.path().join("o.svg")).unwrap();
    assert!(svg.contains("<svg"), "{svg}");
    let dxf = std::fs::read_to_string(dir.path().join("o.dxf")).unwrap();
    // The CAM profile given on the command line is R12 (AC1009).
    assert!(dxf.contains("AC1009"), "{dxf}");
}
