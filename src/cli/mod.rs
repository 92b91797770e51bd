//! Command line: argument parsing and dispatch. Each subcommand is a module taking its options
//! and returning an exit status; exit codes live here (0 ok, 1 script error, 2 usage error).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

pub mod analysis;
pub mod batch;
mod changes;
pub mod check;
pub mod completions;
pub mod convert;
pub mod diag;
pub mod doc;
pub mod lsp;
pub mod params;
pub mod repl;
pub mod run;
pub mod serve;
mod stack;
pub mod watch;

pub const EXIT_OK: i32 = 0;
pub const EXIT_SCRIPT_ERROR: i32 = 1;
pub const EXIT_USAGE: i32 = 2;

#[derive(Parser, Debug)]
#[command(
    name = "lispcad",
    version,
    about = "An AutoLISP dialect over a 3D geometry core, writing SVG and DXF"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub common: Common,
}

/// Options every evaluating command shares.
#[derive(Args, Debug, Clone, Default)]
pub struct Common {
    /// Evaluation budget: stop with an error after N steps (calls and loop iterations).
    #[arg(long, global = true, value_name = "N")]
    pub max_steps: Option<u64>,
    /// DXF flavour: cad (R2000, full) or cam (R12, arcs and polylines only).
    #[arg(long, global = true, value_name = "cad|cam")]
    pub dxf_profile: Option<String>,
    /// Arc-fitting tolerance of the CAM profile, in drawing units (mm).
    #[arg(long, global = true, value_name = "MM")]
    pub cam_tol: Option<f64>,
    /// Shortest segment of the CAM profile, in drawing units (default 0.05).
    #[arg(long, global = true, value_name = "MM")]
    pub cam_min_seg: Option<f64>,
    /// Resolution of PNG output, in pixels per inch (default 300).
    #[arg(long, global = true, value_name = "N")]
    pub dpi: Option<f64>,
    /// Scripted answers for getpoint/getreal/... (one per line).
    #[arg(long, global = true, value_name = "FILE")]
    pub answers: Option<PathBuf>,
    /// Allow file writes anywhere (default: below the script's and the outputs' directories).
    #[arg(long, global = true)]
    pub allow_fs: bool,
    /// Start from this drawing (DXF, ASCII or binary, R12..R2018) instead of an empty one.
    #[arg(long, global = true, value_name = "IN.dxf")]
    pub open: Option<PathBuf>,
    /// Read damaged DXF files leniently (skip bad groups), saying when it was needed.
    #[arg(long, global = true)]
    pub recover: bool,
    // ---- confinement and limits (issue 14) ----
    /// Confine reads too (script and output directories, files named on the command line,
    /// --allow-read DIRs); getenv answers nil. For untrusted scripts.
    #[arg(long, global = true)]
    pub sandbox: bool,
    /// Under --sandbox, also allow reading below DIR (repeatable).
    #[arg(long, global = true, value_name = "DIR")]
    pub allow_read: Vec<PathBuf>,
    /// Memory budget, e.g. 512M or 2G (default: half the physical memory); exceeding it is
    /// an "out of memory" error. In a batch, every row has the whole budget.
    #[arg(long, global = true, value_name = "SIZE", value_parser = crate::lang::memory::parse_size)]
    pub max_memory: Option<usize>,
}

impl From<&Common> for crate::builtins::drawing::OutputOverrides {
    fn from(c: &Common) -> Self {
        crate::builtins::drawing::OutputOverrides {
            dxf_profile: c.dxf_profile.clone(),
            cam_tol: c.cam_tol,
            cam_min_seg: c.cam_min_seg,
            dpi: c.dpi,
        }
    }
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Interactive REPL (files are loaded first).
    Repl { files: Vec<PathBuf> },
    /// Evaluate a script and write the drawing to each output.
    Run(run::RunArgs),
    /// Evaluate one expression and print its value.
    Eval {
        /// The expression (may start with `-`, e.g. `-.5`).
        #[arg(allow_hyphen_values = true)]
        expr: String,
        /// Bind a global before evaluating: NAME=VALUE (VALUE read as a literal).
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
    },
    /// One run per row of a CSV table or per point of a grid, in parallel.
    Batch(batch::BatchArgs),
    /// Re-run a script whenever it (or a file it loads) changes, rewriting the outputs.
    Watch(watch::WatchArgs),
    /// Parse and lint without running; non-zero exit on errors.
    Check(check::CheckArgs),
    /// Open drawings (DXF) and write them as .svg or .dxf.
    Convert(convert::ConvertArgs),
    /// List the parameters a script declares with defparam (read, not run).
    Params { file: PathBuf },
    /// Print the reference of every builtin (or of one).
    Doc {
        /// A builtin's name: print only its signature and description.
        name: Option<String>,
    },
    // Editor and shell support (issue 16).
    /// Print a shell completion script: `lispcad completions bash > /etc/bash_completion.d/lispcad`.
    Completions {
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// Language server over stdio (LSP 3.17): diagnostics, hover, completion, definition.
    Lsp,
    /// Live preview in a browser on 127.0.0.1, re-running the script on every save.
    Serve(serve::ServeArgs),
}

/// A usage error message when an output's extension names no format lispcad writes, so the
/// mistake is reported before anything runs.
pub fn check_output_formats<P: AsRef<std::path::Path>>(outputs: &[P]) -> Result<(), String> {
    for o in outputs {
        crate::output::Format::from_path(o.as_ref()).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// A usage error when a writer option given on the command line (`--dpi`, `--cam-min-seg`,
/// `--cam-tol`) is out of range, reported before anything runs.
pub fn check_writer_options(common: &Common) -> Result<(), String> {
    let d = crate::output::OutputOptions::default();
    let o = crate::output::OutputOptions {
        dpi: common.dpi.unwrap_or(d.dpi),
        cam_min_seg: common.cam_min_seg.unwrap_or(d.cam_min_seg),
        cam_tol: common.cam_tol.unwrap_or(d.cam_tol),
        ..d
    };
    o.validate().map_err(|e| e.to_string())
}

/// Entry point; returns the process exit status.
pub fn main() -> i32 {
    let cli = match run_file_only(std::env::args_os()) {
        Some(c) => c,
        None => match parse_args() {
            Ok(c) => c,
            Err(code) => return code,
        },
    };
    // Everything that evaluates Lisp runs on a large stack of its own (see `stack`).
    stack::on_eval_stack(move || dispatch(cli))
}

/// `lispcad run FILE` with nothing else, recognised without clap: building clap's command tree
/// was a sixth of an empty script's start-up. Any other shape (options, `--`, a name starting
/// with `-`, an empty name) goes to clap, so every message and every default stays clap's;
/// the parse is the one clap gives for these arguments (checked by a test).
fn run_file_only(mut args: impl Iterator<Item = std::ffi::OsString>) -> Option<Cli> {
    let _program = args.next()?;
    let sub = args.next()?;
    let file = args.next()?;
    if args.next().is_some() || sub != "run" || file.is_empty() {
        return None;
    }
    if file.as_encoded_bytes().starts_with(b"-") {
        return None;
    }
    Some(Cli {
        command: Some(Command::Run(run::RunArgs {
            file: PathBuf::from(file),
            outputs: Vec::new(),
            set: Vec::new(),
        })),
        common: Common::default(),
    })
}

/// Clap's parse; the exit status when it printed help, a version or a usage error instead.
fn parse_args() -> Result<Cli, i32> {
    match Cli::try_parse() {
        Ok(c) => Ok(c),
        Err(e) => {
            let code = if e.use_stderr() { EXIT_USAGE } else { EXIT_OK };
            let _ = e.print();
            Err(code)
        }
    }
}

fn dispatch(cli: Cli) -> i32 {
    let common = cli.common;
    match cli.command {
        None => repl::repl(&[], &common),
        Some(Command::Repl { files }) => repl::repl(&files, &common),
        Some(Command::Run(args)) => run::run(&args, &common),
        Some(Command::Eval { expr, set }) => run::eval_expr(&expr, &set, &common),
        Some(Command::Check(args)) => check::check(&args),
        Some(Command::Convert(args)) => convert::convert(&args, &common),
        Some(Command::Batch(args)) => batch::batch(&args, &common),
        Some(Command::Watch(args)) => watch::watch(&args, &common),
        Some(Command::Params { file }) => params::params(&file),
        Some(Command::Doc { name: None }) => {
            print!("{}", doc::reference());
            EXIT_OK
        }
        Some(Command::Doc { name: Some(n) }) => doc::one(&n),
        Some(Command::Completions { shell }) => completions::print(shell),
        Some(Command::Lsp) => lsp::lsp(),
        Some(Command::Serve(args)) => serve::serve(&args, &common),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsString;

    fn args(a: &[&str]) -> Vec<OsString> {
        a.iter().map(OsString::from).collect()
    }

    #[test]
    fn run_file_fast_path_parses_as_clap_does() {
        for a in [
            &["lispcad", "run", "a.lsp"][..],
            &["lispcad", "run", "dir/with space/x"],
            &["lispcad", "run", "help"],
            &["lispcad", "run", "run"],
        ] {
            let fast = run_file_only(args(a).into_iter()).expect("the fast path takes it");
            let clap = Cli::try_parse_from(args(a)).expect("clap parses it");
            assert_eq!(format!("{fast:?}"), format!("{clap:?}"), "{a:?}");
        }
    }

    #[test]
    fn anything_else_goes_to_clap() {
        for a in [
            &["lispcad"][..],
            &["lispcad", "run"],
            &["lispcad", "run", ""],
            &["lispcad", "run", "-"],
            &["lispcad", "run", "--help"],
            &["lispcad", "run", "-o"],
            &["lispcad", "run", "--", "a.lsp"],
            &["lispcad", "run", "a.lsp", "-o", "x.svg"],
            &["lispcad", "--max-steps", "5"],
            &["lispcad", "eval", "x"],
            &["lispcad", "RUN", "a.lsp"],
        ] {
            assert!(run_file_only(args(a).into_iter()).is_none(), "{a:?}");
        }
    }
}
