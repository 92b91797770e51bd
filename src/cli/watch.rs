//! `lispcad watch`: re-run a script whenever it, or a file it loads, changes, and rewrite the
//! outputs. A failing run prints its error and keeps the last good outputs (writes are atomic
//! and happen only after a successful run).

use std::path::PathBuf;
use std::time::{Duration, SystemTime};

use clap::Args;

use super::{diag, Common, EXIT_USAGE};
use crate::lang::ErrorKind;

#[derive(Args, Debug)]
pub struct WatchArgs {
    pub file: PathBuf,
    /// Outputs rewritten after every successful run (.svg or .dxf).
    #[arg(short = 'o', long = "output", value_name = "OUT", required = true)]
    pub outputs: Vec<PathBuf>,
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub set: Vec<String>,
}

/// One run; returns the files the script read (itself and what it loaded).
fn run_once(args: &WatchArgs, common: &Common) -> Vec<PathBuf> {
    let mut watched = super::changes::inputs(&args.file, common.open.as_ref());
    let policy = super::run::fs_policy(common, Some(&args.file), &args.outputs, &watched[1..]);
    let mut it = match super::run::configured_interp(common, policy) {
        Ok(it) => it,
        Err(m) => {
            eprintln!("error: {m}");
            return watched;
        }
    };
    if let Err(m) = super::run::open_start_drawing(&mut it, common) {
        eprintln!("error: {m}");
        return watched;
    }
    if let Err(m) = super::run::apply_sets(&mut it, &args.set) {
        eprintln!("error: {m}");
        return watched;
    }
    let r = it.load_file(&args.file.display().to_string());
    it.flush_out();
    watched.extend(it.loaded_files.iter().cloned());
    match r {
        Err(e) if e.kind != ErrorKind::Exit => {
            diag::print_error(&it, &e);
            eprintln!("watch: run failed; the outputs keep the last good drawing");
        }
        _ => match crate::builtins::write_outputs(&mut it, &args.outputs, common) {
            Ok(()) => eprintln!(
                "watch: wrote {}",
                args.outputs
                    .iter()
                    .map(|o| o.display().to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            Err(m) => eprintln!("error: {m}"),
        },
    }
    watched
}

pub fn watch(args: &WatchArgs, common: &Common) -> i32 {
    if let Err(msg) =
        super::check_output_formats(&args.outputs).and(super::check_writer_options(common))
    {
        eprintln!("error: {msg}");
        return EXIT_USAGE;
    }
    if !args.file.is_file() {
        eprintln!("error: cannot read script {}", args.file.display());
        return EXIT_USAGE;
    }
    if let Err(m) = super::run::check_sets(&args.file, &args.set) {
        eprintln!("error: {m}");
        return EXIT_USAGE;
    }
    let mut changes = match super::changes::Changes::new() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: cannot watch files: {e}");
            return EXIT_USAGE;
        }
    };
    changes.watch(&super::changes::inputs(&args.file, common.open.as_ref()));
    loop {
        let started = SystemTime::now();
        let read = run_once(args, common);
        if !changes.wait(&read, started, Duration::from_millis(100)) {
            return 0;
        }
    }
}
