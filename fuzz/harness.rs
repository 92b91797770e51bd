//! One fuzz input through the reader and the evaluator, as `lispcad run` would take a script:
//! bytes as lossy UTF-8, a fresh interpreter on the evaluation thread, a small step budget,
//! output to a sink, no file writes. Anything but a clean `Ok`/`Err` — a panic, an abort, a
//! Rust stack overflow — is a bug. Shared by the cargo-fuzz target and the stable driver
//! `examples/fuzz_eval.rs`.

use std::path::PathBuf;

use lispcad::builtins::io::FsPolicy;
use lispcad::lang::eval::with_eval_stack;

/// Steps per input: enough for real work, small enough for thousands of runs a second.
pub const MAX_STEPS: u64 = 20_000;

pub fn run(data: &[u8]) {
    let text = String::from_utf8_lossy(data).into_owned();
    with_eval_stack(move || {
        let mut it = lispcad::builtins::new_interp();
        it.out = Box::new(std::io::sink());
        it.set_max_steps(Some(MAX_STEPS));
        // A root that does not exist: every file write is refused.
        it.ext::<FsPolicy>().roots = vec![PathBuf::from("/nonexistent/lispcad-fuzz")];
        let _ = it.eval_source("fuzz", &text);
    });
}
