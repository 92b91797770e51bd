//! A script may write only below its own and its outputs' directories, whatever it does with
//! symlinks, hard links, `..` or races (SPEC §8); `--sandbox` confines reads and hides the
//! environment. Each attack runs in a temporary tree whose victim lies outside the script's
//! directory, and the test asserts the victim is untouched and nothing new appeared there.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

struct Tree {
    _dir: tempfile::TempDir,
    inside: PathBuf,
    outside: PathBuf,
}

fn tree() -> Tree {
    let dir = tempfile::tempdir().unwrap();
    let inside = dir.path().join("in");
    let outside = dir.path().join("outside");
    std::fs::create_dir_all(&inside).unwrap();
    std::fs::create_dir_all(&outside).unwrap();
    std::fs::write(outside.join("victim"), "secret\n").unwrap();
    Tree {
        _dir: dir,
        inside,
        outside,
    }
}

fn outside_is_untouched(t: &Tree) {
    let mut names: Vec<String> = std::fs::read_dir(&t.outside)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["victim"], "something was written outside");
    assert_eq!(
        std::fs::read_to_string(t.outside.join("victim")).unwrap(),
        "secret\n"
    );
}

fn run(t: &Tree, src: &str, pre: &[&str], post: &[&str]) -> Output {
    let script = t.inside.join("s.lsp");
    std::fs::write(&script, src).unwrap();
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(pre)
        .arg("run")
        .arg(&script)
        .args(post)
        .output()
        .unwrap()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Every way a script writes, aimed at `name`; prints one result per attempt.
fn attempts(name: &str) -> String {
    format!(
        r#"(defun try (f a) (princ (if (vl-catch-all-error-p (setq r (vl-catch-all-apply f a))) "refused" (if r "written" "nil"))) (princ " "))
(try 'open (list "{name}" "a"))
(try 'open (list "{name}" "w"))
(try 'vl-file-copy (list "s.lsp" "{name}" T))
(try 'vl-file-copy (list "s.lsp" "{name}"))
(try 'save (list "{name}.dxf"))
(try 'vl-mkdir (list "{name}.d"))
"#
    )
}

fn symlink(target: &Path, link: &Path) {
    std::os::unix::fs::symlink(target, link).unwrap();
}

#[test]
fn a_symlink_to_a_file_outside_is_not_written_through() {
    let t = tree();
    symlink(&t.outside.join("victim"), &t.inside.join("link"));
    symlink(&t.outside.join("victim"), &t.inside.join("link.dxf"));
    let o = run(&t, &attempts("link"), &[], &[]);
    // The in-place writes fail; `save` replaces the link itself (inside), never its target.
    let out = stdout(&o);
    assert!(
        !out.starts_with("written") && !out.contains("written written written"),
        "{out}"
    );
    assert!(!t.inside.join("link.dxf").is_symlink());
    outside_is_untouched(&t);
}

#[test]
fn a_dangling_symlink_creates_nothing_outside() {
    let t = tree();
    symlink(&t.outside.join("new"), &t.inside.join("dangle"));
    symlink(&t.outside.join("new.dxf"), &t.inside.join("dangle.dxf"));
    let o = run(&t, &attempts("dangle"), &[], &[]);
    let out = stdout(&o);
    assert!(out.starts_with("nil nil nil nil"), "{out}");
    outside_is_untouched(&t);
}

#[test]
fn a_symlinked_directory_and_dotdot_lead_nowhere() {
    let t = tree();
    symlink(&t.outside, &t.inside.join("dir"));
    for name in ["dir/x", "../outside/x", "sub/../../outside/x"] {
        let o = run(&t, &attempts(name), &[], &[]);
        assert_eq!(
            stdout(&o).trim(),
            "refused refused refused refused refused refused",
            "{name}"
        );
    }
    let abs = t.outside.join("x").display().to_string();
    let o = run(&t, &attempts(&abs), &[], &[]);
    assert!(!stdout(&o).contains("written"), "{}", stdout(&o));
    outside_is_untouched(&t);
}

#[test]
fn a_hard_link_to_a_file_outside_is_not_written_without_allow_fs() {
    let t = tree();
    std::fs::hard_link(t.outside.join("victim"), t.inside.join("hard")).unwrap();
    let o = run(&t, &attempts("hard"), &[], &[]);
    let out = stdout(&o);
    assert!(out.starts_with("refused refused refused"), "{out}");
    outside_is_untouched(&t);
    // With --allow-fs the user vouches for the tree.
    let o = run(
        &t,
        "(setq f (open \"hard\" \"a\")) (write-line \"x\" f) (close f)",
        &["--allow-fs"],
        &[],
    );
    assert!(o.status.success());
    assert_eq!(
        std::fs::read_to_string(t.outside.join("victim")).unwrap(),
        "secret\nx\n"
    );
}

#[test]
fn writes_inside_work_and_every_file_is_0644() {
    use std::os::unix::fs::PermissionsExt;
    let t = tree();
    let src = "(setq f (open \"a.txt\" \"w\")) (write-line \"hi\" f) (close f)\n\
               (vl-mkdir \"sub\") (setq f (open \"sub/b.txt\" \"w\")) (close f)\n\
               (command \"circle\" '(0 0) 5) (save \"d.dxf\")\n\
               (mesh-write (mesh-surface (sphere-surface '(0 0 0) 5.0) 0.5) \"m.stl\")\n";
    let out = t.inside.join("o.svg");
    std::fs::write(t.inside.join("s.lsp"), src).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("run")
        .arg(t.inside.join("s.lsp"))
        .arg("-o")
        .arg(&out)
        .current_dir(&t.outside)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["a.txt", "sub/b.txt", "d.dxf", "m.stl", "o.svg"] {
        let mode = std::fs::metadata(t.inside.join(f))
            .unwrap()
            .permissions()
            .mode()
            & 0o777;
        assert_eq!(mode, 0o644, "{f}");
    }
    outside_is_untouched(&t);
}

#[test]
fn a_failing_run_leaves_no_output() {
    let t = tree();
    let out = t.inside.join("o.svg");
    let o = run(
        &t,
        "(command \"circle\" '(0 0) 5) (car 1)",
        &[],
        &["-o", out.to_str().unwrap()],
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(!out.exists());
}

#[test]
fn watch_and_repl_take_the_scripts_directory_not_the_current_one() {
    let t = tree();
    // From the outside directory (as from $HOME), a script given to repl may not write there.
    let script = t.inside.join("r.lsp");
    std::fs::write(&script, "(princ (vl-catch-all-error-p (vl-catch-all-apply 'open (list \"../outside/victim\" \"a\"))))\n(setq f (open \"own.txt\" \"w\")) (close f)\n").unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("repl")
        .arg(&script)
        .current_dir(&t.outside)
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    assert!(
        stdout(&o).contains('T'),
        "{}{}",
        stdout(&o),
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        t.inside.join("own.txt").exists(),
        "refused its own directory"
    );
    outside_is_untouched(&t);
}

#[test]
fn a_directory_flipped_to_a_symlink_never_lets_a_write_escape() {
    let t = tree();
    let d = t.inside.join("d");
    let real = t.inside.join("d.real");
    std::fs::create_dir(&real).unwrap();
    symlink(&real, &d);
    // The script writes d/f.txt over and over while d flips between a directory inside and a
    // symlink to the outside directory.
    let script = t.inside.join("s.lsp");
    std::fs::write(
        &script,
        "(repeat 20000 (if (not (vl-catch-all-error-p (setq f (vl-catch-all-apply 'open (list \"d/f.txt\" \"w\"))))) (if f (close f))))\n",
    )
    .unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("run")
        .arg(&script)
        .spawn()
        .unwrap();
    let tmp = t.inside.join("d.tmp");
    let mut flips = 0u64;
    while child.try_wait().unwrap().is_none() && flips < 200_000 {
        // Atomically replace d: a link to the outside, then back to the real directory.
        let target = if flips.is_multiple_of(2) {
            &t.outside
        } else {
            &real
        };
        let _ = std::fs::remove_file(&tmp);
        symlink(target, &tmp);
        std::fs::rename(&tmp, &d).unwrap();
        flips += 1;
    }
    let _ = child.kill();
    let _ = child.wait();
    assert!(flips > 100, "the race did not run ({flips} flips)");
    outside_is_untouched(&t);
}

#[test]
fn the_sandbox_confines_reads_and_hides_the_environment() {
    let t = tree();
    let extra = t._dir.path().join("lib");
    std::fs::create_dir(&extra).unwrap();
    std::fs::write(extra.join("data.txt"), "ok\n").unwrap();
    let victim = t.outside.join("victim").display().to_string();
    let data = extra.join("data.txt").display().to_string();
    let src = format!(
        "(defun r (n) (princ (if (vl-catch-all-error-p (setq f (vl-catch-all-apply 'open (list n \"r\")))) \"refused\" (read-line f))) (princ \" \"))\n\
         (r \"{victim}\") (r \"{data}\") (princ (getenv \"HOME\"))"
    );
    let o = run(&t, &src, &[], &[]);
    assert_eq!(
        stdout(&o),
        format!("secret ok {}", std::env::var("HOME").unwrap())
    );
    let o = run(&t, &src, &["--sandbox"], &[]);
    assert_eq!(stdout(&o), "refused refused nil");
    // A symlink inside pointing at the victim is not followed either: a refusal.
    symlink(&t.outside.join("victim"), &t.inside.join("peek"));
    let o = run(
        &t,
        "(princ (vl-catch-all-error-message (vl-catch-all-apply 'open (list \"peek\" \"r\"))))",
        &["--sandbox"],
        &[],
    );
    assert!(
        stdout(&o).starts_with("file access refused"),
        "{}",
        stdout(&o)
    );
    let o = run(
        &t,
        &src,
        &["--sandbox", "--allow-read", extra.to_str().unwrap()],
        &[],
    );
    assert_eq!(stdout(&o), "refused ok nil");
    outside_is_untouched(&t);
}

/// Every way a script reads, aimed at `name`: "refused" for a policy refusal, the result
/// otherwise (never the victim's text, which would be a leak).
fn read_attempts(name: &str) -> String {
    format!(
        r#"(defun try (f a) (setq r (vl-catch-all-apply f a))
  (princ (cond ((and (vl-catch-all-error-p r) (wcmatch (vl-catch-all-error-message r) "file access refused*")) "refused")
               ((vl-catch-all-error-p r) (strcat "error:" (vl-catch-all-error-message r)))
               (r (vl-princ-to-string r)) (T "nil"))) (princ " "))
(try '(lambda (n) (read-line (open n "r"))) (list "{name}"))
(try 'load (list "{name}"))
(try 'vl-file-copy (list "{name}" "copy.txt"))
(try 'vl-file-size (list "{name}"))
(try 'vl-file-directory-p (list "{name}"))
(try 'findfile (list "{name}"))
(try 'dxf-open (list "{name}"))
(try 'dxf-import (list "{name}"))
"#
    )
}

#[test]
fn sandboxed_reads_follow_no_symlink_or_dotdot_out_of_a_root() {
    let t = tree();
    symlink(&t.outside.join("victim"), &t.inside.join("peek"));
    symlink(&t.outside, &t.inside.join("dir"));
    std::fs::create_dir(t.inside.join("sub")).unwrap();
    for name in [
        "peek",
        "dir/victim",
        "../outside/victim",
        "sub/../../outside/victim",
    ] {
        let o = run(&t, &read_attempts(name), &["--sandbox"], &[]);
        assert_eq!(
            stdout(&o).trim(),
            "refused refused refused refused refused nil refused refused",
            "{name}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    // A directory reached through a symlink out is neither listed nor examined.
    let o = run(
        &t,
        "(princ (vl-catch-all-error-p (vl-catch-all-apply 'vl-directory-files (list \"dir\"))))\
         (princ (vl-catch-all-error-p (vl-catch-all-apply 'vl-file-directory-p (list \"dir\"))))",
        &["--sandbox"],
        &[],
    );
    assert_eq!(stdout(&o), "TT");
    // A mesh file linked from outside is not read either.
    symlink(&t.outside.join("victim"), &t.inside.join("peek.stl"));
    let o = run(
        &t,
        "(princ (vl-catch-all-error-message (vl-catch-all-apply 'mesh-read (list \"peek.stl\"))))",
        &["--sandbox"],
        &[],
    );
    assert!(
        stdout(&o).starts_with("file access refused"),
        "{}",
        stdout(&o)
    );
    assert!(!t.inside.join("copy.txt").exists());
    outside_is_untouched(&t);
}

#[test]
fn sandboxed_reads_follow_symlinks_that_stay_inside() {
    let t = tree();
    std::fs::create_dir(t.inside.join("lib")).unwrap();
    std::fs::write(t.inside.join("lib/data.txt"), "ok\n").unwrap();
    std::fs::write(t.inside.join("lib/code.lsp"), "(setq loaded 42)\n").unwrap();
    symlink(Path::new("lib/data.txt"), &t.inside.join("alias.txt"));
    symlink(Path::new("lib"), &t.inside.join("libs"));
    let o = run(
        &t,
        "(princ (read-line (open \"alias.txt\" \"r\"))) (princ \" \")\
         (princ (read-line (open \"libs/data.txt\" \"r\"))) (princ \" \")\
         (load \"libs/code\") (princ loaded) (princ \" \")\
         (princ (vl-file-size \"alias.txt\")) (princ \" \")\
         (princ (vl-directory-files \"libs\" \"*.txt\" 1))",
        &["--sandbox"],
        &[],
    );
    assert_eq!(
        stdout(&o),
        "ok ok 42 3 (data.txt)",
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn a_directory_flipped_to_a_symlink_never_lets_a_sandboxed_read_escape() {
    let t = tree();
    let d = t.inside.join("d");
    let real = t.inside.join("d.real");
    std::fs::create_dir(&real).unwrap();
    std::fs::write(real.join("victim"), "inside\n").unwrap();
    // Relative links: an absolute one leaves the root by definition and is always refused.
    let (to_real, to_outside) = (Path::new("d.real"), Path::new("../outside"));
    symlink(to_real, &d);
    // The script reads d/victim over and over while d flips between the directory inside and
    // a symlink to the outside one (whose victim says "secret"); it counts what it saw.
    let script = t.inside.join("s.lsp");
    std::fs::write(
        &script,
        "(setq inside 0 secret 0 refused 0)\n\
         (repeat 20000\n\
           (setq f (vl-catch-all-apply 'open (list \"d/victim\" \"r\")))\n\
           (cond ((vl-catch-all-error-p f) (setq refused (1+ refused)))\n\
                 (f (setq l (read-line f)) (close f)\n\
                    (if (= l \"secret\") (setq secret (1+ secret)) (setq inside (1+ inside))))))\n\
         (princ (list inside secret refused))\n",
    )
    .unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .arg("--sandbox")
        .arg("run")
        .arg(&script)
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let tmp = t.inside.join("d.tmp");
    let mut flips = 0u64;
    while child.try_wait().unwrap().is_none() && flips < 2_000_000 {
        let target = if flips.is_multiple_of(2) {
            to_outside
        } else {
            to_real
        };
        let _ = std::fs::remove_file(&tmp);
        symlink(target, &tmp);
        std::fs::rename(&tmp, &d).unwrap();
        flips += 1;
    }
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success(), "the script did not finish");
    assert!(flips > 100, "the race did not run ({flips} flips)");
    let out = stdout(&o);
    let counts: Vec<u64> = out
        .trim_matches(['(', ')'])
        .split(' ')
        .map(|n| n.parse().unwrap())
        .collect();
    let [inside, secret, refused] = counts[..] else {
        panic!("{out}")
    };
    assert_eq!(secret, 0, "{out}: a read escaped");
    assert_eq!(inside + refused, 20000, "{out}");
    // Both states were met (otherwise the race proved nothing).
    assert!(inside > 0 && refused > 0, "{out} after {flips} flips");
    outside_is_untouched(&t);
}
