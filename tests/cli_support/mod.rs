//! Shared by the CLI and REPL tests: run the lispcad binary.
#![allow(
    dead_code,
    reason = "each test crate includes this module and uses only some of the helpers"
)]

use std::io::Write;
use std::path::Path;
use std::process::{Child, Command, Output, Stdio};

/// Runs `lispcad ARGS` in `dir` with no colour, 100 columns and no stdin.
pub fn lispcad_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .env("COLUMNS", "100")
        .stdin(Stdio::null())
        .output()
        .expect("run lispcad")
}

/// Starts `lispcad ARGS` in `dir` with no colour, history in `dir/history` (never the user's)
/// and all three streams piped.
pub fn spawn_piped(dir: &Path, args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .env("LISPCAD_HISTORY", dir.join("history"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start lispcad")
}

/// Feeds `input` through a pipe to `lispcad repl ARGS` in `dir` (see `spawn_piped`) and waits
/// for it to end.
pub fn repl_output(dir: &Path, args: &[&str], input: &str) -> Output {
    let mut child = spawn_piped(dir, &[&["repl"], args].concat());
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    child.wait_with_output().unwrap()
}
