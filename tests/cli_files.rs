//! Files through the binary: open/write-line/princ/print/read-line/read-char/close, load,
//! findfile, the write policy (below the script's and outputs' directories unless --allow-fs),
//! console read-line/read-char from --answers, and the refused shell escape.

use std::path::Path;

mod cli_support;
use cli_support::lispcad_in;

fn run(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let o = lispcad_in(dir, args);
    (
        o.status.code().expect("exit code"),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn write_then_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let script = r#"
(setq f (open "out.txt" "w"))
(write-line "line one" f)
(write-char 65 f)
(princ "x" f)
(prin1 "q" f)
(print 12 f)
(close f)
(setq f (open "out.txt" "a")) (write-line "more" f) (close f)
(setq f (open "out.txt" "r"))
(setq got (list (read-line f) (read-char f) (read-line f) (read-line f) (read-line f)))
(close f)
(prin1 got)
(prin1 (list (type f) (open "missing.txt" "r") (findfile "nope.txt")
             (= (findfile "out.txt") nil)))
"#;
    std::fs::write(dir.path().join("s.lsp"), script).unwrap();
    let (code, out, err) = run(dir.path(), &["run", "s.lsp"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        out,
        r#"("line one" 65 "x\"q\"" "12 more" nil)(FILE nil nil nil)"#
    );
    // print writes a newline before and a space after, as AutoLISP does.
    let text = std::fs::read_to_string(dir.path().join("out.txt")).unwrap();
    assert_eq!(text, "line one\nAx\"q\"\n12 more\n");
}

#[test]
fn bad_file_modes_and_closed_files() {
    let dir = tempfile::tempdir().unwrap();
    let (code, _, err) = run(dir.path(), &["eval", r#"(open "o.txt" "x")"#]);
    assert_eq!(code, 1);
    assert!(err.contains("bad argument value: file mode \"x\""), "{err}");
    let (code, _, err) = run(
        dir.path(),
        &[
            "eval",
            r#"(progn (setq f (open "o.txt" "w")) (close f) (write-line "a" f))"#,
        ],
    );
    assert_eq!(code, 1, "writing to a closed file is an error");
    assert!(!err.is_empty());
}

#[test]
fn load_finds_files_beside_the_script() {
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("lib");
    std::fs::create_dir(&sub).unwrap();
    std::fs::write(
        sub.join("util.lsp"),
        "(defun twice (x) (* 2 x))\n\"loaded\"\n",
    )
    .unwrap();
    std::fs::write(sub.join("bad.lsp"), "(car 1)\n").unwrap();
    std::fs::write(
        sub.join("main.lsp"),
        r#"(prin1 (load "util"))
(prin1 (twice 21))
(prin1 (load "missing" 'fallback))
(prin1 (vl-catch-all-error-message (vl-catch-all-apply 'load '("missing.lsp"))))
(prin1 (vl-catch-all-error-message (vl-catch-all-apply 'load '("bad.lsp"))))
"#,
    )
    .unwrap();
    // Run from the parent directory: load resolves against the script's own directory.
    let (code, out, err) = run(dir.path(), &["run", "lib/main.lsp"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        out,
        r#""loaded"42FALLBACK"LOAD failed: \"missing.lsp\"""bad argument type: consp 1""#
    );
}

#[test]
fn writes_outside_the_script_directory_need_allow_fs() {
    let dir = tempfile::tempdir().unwrap();
    let other = tempfile::tempdir().unwrap();
    let target = other.path().join("x.txt");
    let script = format!(
        "(setq f (open {:?} \"w\")) (write-line \"hi\" f) (close f)",
        target.display().to_string()
    );
    std::fs::write(dir.path().join("s.lsp"), &script).unwrap();
    let (code, _, err) = run(dir.path(), &["run", "s.lsp"]);
    assert_eq!(code, 1);
    assert!(err.contains("file access refused"), "{err}");
    assert!(err.contains("--allow-fs"), "{err}");
    assert!(!target.exists());
    let (code, _, err) = run(dir.path(), &["run", "s.lsp", "--allow-fs"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "hi\n");
    // The output's directory is permitted too.
    let (code, _, err) = run(
        dir.path(),
        &[
            "run",
            "s.lsp",
            "-o",
            &other.path().join("d.svg").display().to_string(),
        ],
    );
    assert_eq!(code, 0, "{err}");
}

#[test]
fn console_read_line_and_read_char_use_the_answers() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.txt"), "ab\nline two\nthree\n").unwrap();
    let (code, out, err) = run(
        dir.path(),
        &[
            "eval",
            "(list (read-char) (read-line) (read-line) (read-char) (read-char) (read-line))",
            "--answers",
            "a.txt",
        ],
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.trim(), r#"(97 "b" "line two" 116 104 "ree")"#);
    let (code, _, err) = run(dir.path(), &["eval", "(read-line)"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("read-line: no input available (use --answers FILE)"),
        "{err}"
    );
}

#[test]
fn there_is_no_shell_escape() {
    let dir = tempfile::tempdir().unwrap();
    let (code, _, err) = run(dir.path(), &["eval", r#"(startapp "touch" "pwned")"#]);
    assert_eq!(code, 1);
    assert!(err.contains("startapp is refused"), "{err}");
    assert!(!dir.path().join("pwned").exists());
}

#[test]
fn vl_file_functions_respect_the_write_policy() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path();
    std::fs::write(p.join("f1.txt"), "hello\n").unwrap();
    std::fs::write(p.join("b.lsp"), "").unwrap();
    let script = r#"
(prin1 (list (vl-file-size "f1.txt") (vl-file-size ".") (vl-file-size "nope")))
(prin1 (vl-directory-files "." "*.TXT" 1))
(prin1 (list (vl-file-copy "f1.txt" "f2.txt") (vl-file-copy "f1.txt" "f2.txt")
             (vl-file-copy "f1.txt" "f2.txt" T) (vl-file-size "f2.txt")))
(prin1 (list (vl-file-rename "f2.txt" "f3.txt") (vl-file-rename "f2.txt" "f4.txt")
             (vl-file-delete "f3.txt") (vl-file-delete "f3.txt")))
(prin1 (list (vl-mkdir "d") (vl-file-directory-p "d") (vl-mkdir "d") (vl-file-directory-p "f1.txt")))
(prin1 (vl-directory-files "." nil -1))
(prin1 (findtrustedfile "b.lsp"))
"#;
    std::fs::write(p.join("s.lsp"), script).unwrap();
    let (code, out, err) = run(p, &["run", "s.lsp"]);
    assert_eq!(code, 0, "{err}");
    let want_trusted = format!(
        "{:?}",
        p.canonicalize()
            .unwrap()
            .join("b.lsp")
            .display()
            .to_string()
    );
    assert_eq!(
        out,
        format!(
            r#"(6 0 nil)("f1.txt")(6 nil 6 12)(T nil T nil)(T T nil nil)("." ".." "d"){want_trusted}"#
        )
    );
    // Outside the script's directory: refused, and nothing is deleted.
    let other = tempfile::tempdir().unwrap();
    let victim = other.path().join("keep.txt");
    std::fs::write(&victim, "x").unwrap();
    let del = format!("(vl-file-delete {:?})", victim.display().to_string());
    std::fs::write(p.join("d.lsp"), &del).unwrap();
    let (code, _, err) = run(p, &["run", "d.lsp"]);
    assert_eq!(code, 1);
    assert!(err.contains("file access refused"), "{err}");
    assert!(victim.exists());
}
