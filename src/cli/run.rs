//! `lispcad run` and `lispcad eval`: evaluate a script or an expression.

use std::path::{Path, PathBuf};

use clap::Args;

use super::{diag, Common, EXIT_OK, EXIT_SCRIPT_ERROR, EXIT_USAGE};
use crate::builtins::input::InputState;
use crate::builtins::io::FsPolicy;
use crate::lang::reader::read_one;
use crate::lang::{ErrorKind, Interp};

#[derive(Args, Debug)]
pub struct RunArgs {
    /// The script to evaluate.
    pub file: PathBuf,
    /// Write the drawing here after the script ends (.svg, .dxf, .pdf, .png); repeatable.
    #[arg(short = 'o', long = "output", value_name = "OUT")]
    pub outputs: Vec<PathBuf>,
    /// Bind a global before the script runs: NAME=VALUE (VALUE read as a lispcad literal).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub set: Vec<String>,
}

/// The file-system policy of a run, built once from the script's and the outputs' directories
/// (the write roots) and the options; `named` are the other files named on the command line
/// (readable under --sandbox).
pub fn fs_policy(
    common: &Common,
    script: Option<&Path>,
    outputs: &[PathBuf],
    named: &[PathBuf],
) -> FsPolicy {
    let mut p = FsPolicy::for_script(script, outputs);
    p.allow_all = common.allow_fs;
    p.sandbox = common.sandbox;
    p.read_roots = common.allow_read.clone();
    p.read_files = script
        .map(Path::to_path_buf)
        .into_iter()
        .chain(named.iter().cloned())
        .chain(common.answers.iter().cloned())
        .collect();
    p
}

/// An interpreter configured from the common options and a file-system policy; a usage error
/// message when the answers file cannot be read.
pub fn configured_interp(common: &Common, policy: FsPolicy) -> Result<Interp, String> {
    // The budget belongs to the thread that will run the script (each batch row's worker).
    crate::lang::memory::set_budget(Some(
        common
            .max_memory
            .unwrap_or_else(crate::lang::memory::default_budget),
    ));
    let mut it = crate::builtins::new_interp();
    it.set_max_steps(common.max_steps);
    *it.ext::<FsPolicy>() = policy;
    if let Some(path) = &common.answers {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("cannot read the answers file {}: {e}", path.display()))?;
        it.ext::<InputState>().load_answers(&text);
    }
    Ok(it)
}

/// Applies `--set NAME=VALUE` bindings; an error message on a malformed one.
pub fn apply_sets(it: &mut Interp, sets: &[String]) -> Result<(), String> {
    for s in sets {
        let (name, value) = s
            .split_once('=')
            .ok_or_else(|| format!("--set {s}: expected NAME=VALUE"))?;
        let name = name.trim();
        if name.is_empty() || crate::lang::reader::parse_number(name).is_some() {
            return Err(format!("--set {s}: `{name}` is not a symbol name"));
        }
        let v = match read_one(value, &mut it.syms) {
            Ok(Some((v, end))) if value[end..].trim().is_empty() => v,
            Ok(_) => return Err(format!("--set {s}: `{value}` is not one lispcad literal")),
            Err(e) => return Err(format!("--set {s}: {}", e.message)),
        };
        it.sync_cells();
        it.set_global(name, v);
    }
    Ok(())
}

/// Starts the interpreter's drawing from `--open IN.dxf`; an error message for a drawing
/// that cannot be read (exit 1: bad input, not bad usage).
pub fn open_start_drawing(it: &mut Interp, common: &Common) -> Result<(), String> {
    if let Some(path) = &common.open {
        let note = crate::builtins::drawing::open_into(it, path, common.recover)?;
        if let Some(n) = note {
            eprintln!("{n}");
        }
    }
    Ok(())
}

pub fn run(args: &RunArgs, common: &Common) -> i32 {
    if let Err(msg) =
        super::check_output_formats(&args.outputs).and(super::check_writer_options(common))
    {
        eprintln!("error: {msg}");
        return EXIT_USAGE;
    }
    let named: Vec<PathBuf> = common.open.iter().cloned().collect();
    let policy = fs_policy(common, Some(&args.file), &args.outputs, &named);
    let mut it = match configured_interp(common, policy) {
        Ok(it) => it,
        Err(msg) => {
            eprintln!("error: {msg}");
            return EXIT_USAGE;
        }
    };
    if let Err(msg) = open_start_drawing(&mut it, common) {
        eprintln!("error: {msg}");
        return EXIT_SCRIPT_ERROR;
    }
    if let Err(msg) =
        check_sets(&args.file, &args.set).and_then(|()| apply_sets(&mut it, &args.set))
    {
        eprintln!("error: {msg}");
        return EXIT_USAGE;
    }
    if !args.file.is_file() {
        eprintln!("error: cannot read script {}", args.file.display());
        return EXIT_USAGE;
    }
    let name = args.file.display().to_string();
    let r = it.load_file(&name);
    it.flush_out();
    match r {
        Ok(_) => {}
        Err(e) if e.kind == ErrorKind::Exit => {}
        Err(e) => {
            diag::print_error(&it, &e);
            return leave(it, EXIT_SCRIPT_ERROR);
        }
    }
    let status = match crate::builtins::write_outputs(&mut it, &args.outputs, common) {
        Ok(()) => EXIT_OK,
        Err(msg) => {
            eprintln!("error: {msg}");
            EXIT_SCRIPT_ERROR
        }
    };
    leave(it, status)
}

/// Ends a one-shot run: flushes what dropping would flush (open files, output) and lets the
/// process reclaim the heap at exit, instead of freeing a script's large data value by value.
fn leave(mut it: Interp, status: i32) -> i32 {
    crate::builtins::io::flush_open_files(&mut it);
    it.flush_out();
    std::mem::forget(it);
    status
}

/// `--set` names must be symbols the script uses and values within declared ranges.
pub fn check_sets(file: &Path, sets: &[String]) -> Result<(), String> {
    if sets.is_empty() {
        return Ok(());
    }
    super::params::script_names(file)?.check_sets(sets)
}

/// The directory a file is in ("." for a bare file name).
pub fn parent_dir(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

pub fn eval_expr(expr: &str, sets: &[String], common: &Common) -> i32 {
    let mut it = match configured_interp(common, fs_policy(common, None, &[], &[])) {
        Ok(it) => it,
        Err(msg) => {
            eprintln!("error: {msg}");
            return EXIT_USAGE;
        }
    };
    if let Err(msg) = apply_sets(&mut it, sets) {
        eprintln!("error: {msg}");
        return EXIT_USAGE;
    }
    let r = it.eval_source("<eval>", expr);
    it.flush_out();
    match r {
        Ok(v) => {
            let s = it.prin1_string(&v);
            println!("{s}");
            EXIT_OK
        }
        Err(e) if e.kind == ErrorKind::Exit => EXIT_OK,
        Err(e) => {
            diag::print_error(&it, &e);
            EXIT_SCRIPT_ERROR
        }
    }
}
