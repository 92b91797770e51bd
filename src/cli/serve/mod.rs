//! `lispcad serve SCRIPT` and the REPL's `:serve`: a live preview in the browser.
//!
//! Same shape as the language server: the run loop (the thread owning the interpreter)
//! publishes each result into a `Shared` slot; the HTTP handlers, on their own threads, only
//! read the latest one. `/events` streams one Server-Sent Event per publication.

mod http;

use std::path::PathBuf;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

use clap::Args;

use super::{diag, Common, EXIT_OK, EXIT_USAGE};
use crate::lang::error::line_col;
use crate::lang::{ErrorKind, Interp, LispError};
use crate::output::{Drawing, OutputOptions};

pub use http::start;

#[derive(Args, Debug)]
pub struct ServeArgs {
    /// The script to run, and re-run whenever it or a file it loads is saved.
    pub file: PathBuf,
    /// Port on 127.0.0.1 (0 picks a free one; the address is printed).
    #[arg(long, default_value_t = 7878)]
    pub port: u16,
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub set: Vec<String>,
}

/// A failed run as the page shows it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Failure {
    pub message: String,
    pub file: String,
    pub line: usize,
    pub column: usize,
    /// The source line, and a caret line under the error's start.
    pub snippet: String,
}

impl Failure {
    /// "message (file:line:col)", the `/status` error string.
    pub fn summary(&self) -> String {
        if self.line == 0 {
            self.message.clone()
        } else {
            format!(
                "{} ({}:{}:{})",
                self.message, self.file, self.line, self.column
            )
        }
    }

    pub fn from_error(it: &Interp, e: &LispError) -> Failure {
        let mut f = Failure {
            message: e.message.clone(),
            ..Default::default()
        };
        if let Some(hint) = diag::hint(it, &e.message) {
            f.message = format!("{}; {hint}", e.message);
        }
        let Some(span) = e.span else { return f };
        let Some(src) = it.sources.get(span.src as usize) else {
            return f;
        };
        let (line, column) = line_col(&src.text, span.start as usize);
        let text = src.text.lines().nth(line - 1).unwrap_or("");
        f.file = src.name.clone();
        f.line = line;
        f.column = column;
        f.snippet = format!("{text}\n{}^", " ".repeat(column - 1));
        f
    }
}

/// What the handlers serve: the last good drawing, and the outcome of the last run.
#[derive(Clone, Default)]
pub struct Published {
    pub drawing: Arc<Drawing>,
    pub options: OutputOptions,
    pub runs: u64,
    pub error: Option<Failure>,
}

/// The slot the run loop writes and the handlers read; the condvar wakes `/events` streams.
#[derive(Default)]
pub struct Shared {
    state: Mutex<Published>,
    changed: Condvar,
}

impl Shared {
    pub fn latest(&self) -> Published {
        self.state.lock().unwrap_or_else(|p| p.into_inner()).clone()
    }

    /// Records a run: a new drawing on success; on failure the error, keeping the last good
    /// drawing.
    pub fn publish(&self, result: Result<(Drawing, OutputOptions), Failure>) {
        let mut s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        s.runs += 1;
        match result {
            Ok((d, o)) => {
                s.drawing = Arc::new(d);
                s.options = o;
                s.error = None;
            }
            Err(f) => s.error = Some(f),
        }
        self.changed.notify_all();
    }

    /// Blocks until a run after `seen` is published (its state), or `timeout` passes (None).
    pub fn wait_after(&self, seen: u64, timeout: std::time::Duration) -> Option<Published> {
        let s = self.state.lock().unwrap_or_else(|p| p.into_inner());
        let (s, _) = self
            .changed
            .wait_timeout_while(s, timeout, |s| s.runs <= seen)
            .unwrap_or_else(|p| p.into_inner());
        (s.runs > seen).then(|| s.clone())
    }
}

/// The interpreter's drawing and SVG options after an evaluation.
pub fn snapshot(it: &mut Interp) -> Result<(Drawing, OutputOptions), Failure> {
    let options = crate::builtins::drawing::output_options(it, None).map_err(|e| Failure {
        message: e.message.clone(),
        ..Default::default()
    })?;
    Ok((crate::builtins::drawing::drawing(it).clone(), options))
}

/// One run of the script in a fresh interpreter; the files it read (itself and its loads).
fn run_once(args: &ServeArgs, common: &Common, shared: &Shared) -> Vec<PathBuf> {
    let mut read = super::changes::inputs(&args.file, common.open.as_ref());
    let named: Vec<PathBuf> = common.open.iter().cloned().collect();
    let policy = super::run::fs_policy(common, Some(&args.file), &[], &named);
    let mut it = match super::run::configured_interp(common, policy) {
        Ok(it) => it,
        Err(m) => {
            shared.publish(Err(Failure {
                message: m,
                ..Default::default()
            }));
            return read;
        }
    };
    if let Err(m) = super::run::open_start_drawing(&mut it, common)
        .and_then(|()| super::run::apply_sets(&mut it, &args.set))
    {
        shared.publish(Err(Failure {
            message: m,
            ..Default::default()
        }));
        return read;
    }
    let r = it.load_file(&args.file.display().to_string());
    it.flush_out();
    read.extend(it.loaded_files.iter().cloned());
    match r {
        Err(e) if e.kind != ErrorKind::Exit => {
            diag::print_error(&it, &e);
            shared.publish(Err(Failure::from_error(&it, &e)));
        }
        _ => shared.publish(snapshot(&mut it)),
    }
    read
}

pub fn serve(args: &ServeArgs, common: &Common) -> i32 {
    if !args.file.is_file() {
        eprintln!("error: cannot read script {}", args.file.display());
        return EXIT_USAGE;
    }
    if let Some(p) = common.open.as_ref().filter(|p| !p.is_file()) {
        eprintln!("error: cannot read drawing {}", p.display());
        return EXIT_USAGE;
    }
    let shared = Arc::new(Shared::default());
    let addr = match start(args.port, shared.clone()) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("error: cannot listen on 127.0.0.1:{}: {e}", args.port);
            return EXIT_USAGE;
        }
    };
    let mut watch = match super::changes::Changes::new() {
        Ok(w) => w,
        Err(e) => {
            eprintln!("error: cannot watch files: {e}");
            return EXIT_USAGE;
        }
    };
    watch.watch(&super::changes::inputs(&args.file, common.open.as_ref()));
    // Announced after the first run: whoever reads the address finds a drawing (or error).
    let mut started = std::time::SystemTime::now();
    let mut read = run_once(args, common, &shared);
    eprintln!("serving http://{addr}/ (Ctrl-C stops)");
    // A short settle: the page's latency budget is 100 ms from save to update.
    while watch.wait(&read, started, Duration::from_millis(20)) {
        started = std::time::SystemTime::now();
        read = run_once(args, common, &shared);
    }
    EXIT_OK
}
