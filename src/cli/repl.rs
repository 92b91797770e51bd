//! The REPL: rustyline with history, multi-line entry until the form is complete (the reader's
//! own scan, so strings and comments are understood), completion of builtins and user symbols,
//! matching-bracket highlight, `:help`/`:load`/`:save`, Ctrl-C interrupting an evaluation.
//!
//! When standard input is not a terminal the same loop runs without line editing, so the REPL
//! can be driven by a pipe (tests, editors).

use std::borrow::Cow;
use std::cell::RefCell;
use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;
use std::rc::Rc;

use rustyline::completion::Completer;
use rustyline::highlight::{CmdKind, Highlighter, MatchingBracketHighlighter};
use rustyline::hint::Hinter;
use rustyline::validate::{ValidationContext, ValidationResult, Validator};
use rustyline::{Context, Helper};

use super::{diag, Common, EXIT_OK};
use crate::lang::lint::{function_names, nearest};
use crate::lang::reader::{scan, Scan};
use crate::lang::{ErrorKind, Interp, Value};

const PROMPT: &str = "_$ ";

struct ReplHelper {
    names: Rc<RefCell<Vec<String>>>,
    brackets: MatchingBracketHighlighter,
}

impl Completer for ReplHelper {
    type Candidate = String;
    fn complete(
        &self,
        line: &str,
        pos: usize,
        _ctx: &Context<'_>,
    ) -> rustyline::Result<(usize, Vec<String>)> {
        let start = line[..pos]
            .rfind(|c: char| c.is_whitespace() || "()'\"".contains(c))
            .map_or(0, |i| i + 1);
        let prefix = line[start..pos].to_lowercase();
        if prefix.is_empty() {
            return Ok((start, Vec::new()));
        }
        let mut found: Vec<String> = self
            .names
            .borrow()
            .iter()
            .filter(|n| n.starts_with(&prefix))
            .cloned()
            .collect();
        found.sort();
        found.dedup();
        Ok((start, found))
    }
}

impl Hinter for ReplHelper {
    type Hint = String;
}

impl Highlighter for ReplHelper {
    fn highlight<'l>(&self, line: &'l str, pos: usize) -> Cow<'l, str> {
        self.brackets.highlight(line, pos)
    }
    fn highlight_char(&self, line: &str, pos: usize, kind: CmdKind) -> bool {
        self.brackets.highlight_char(line, pos, kind)
    }
}

/// Whether an entry is ready to evaluate: a `:command` line, or text whose forms are all closed
/// by the reader's own scan (so parens in strings and comments do not count). Malformed text
/// (a stray `)`) is "complete" too: evaluating it reports the error.
fn entry_complete(input: &str) -> bool {
    input.trim_start().starts_with(':') || !matches!(scan(input), Scan::Incomplete(_))
}

/// Entries are assembled by `read_entry`, line by line, so each line is accepted as typed.
impl Validator for ReplHelper {
    fn validate(&self, _ctx: &mut ValidationContext) -> rustyline::Result<ValidationResult> {
        Ok(ValidationResult::Valid(None))
    }
}

impl Helper for ReplHelper {}

fn history_path() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("LISPCAD_HISTORY") {
        return Some(PathBuf::from(p));
    }
    std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".lispcad_history"))
}

/// Every name completion offers: builtins and the symbols that have values.
fn completion_names(it: &Interp) -> Vec<String> {
    it.syms
        .all()
        .filter(|(s, n)| !n.is_empty() && it.values.get(s.idx()).is_some_and(Value::truthy))
        .map(|(_, n)| n.to_lowercase())
        .collect()
}

pub fn repl(files: &[PathBuf], common: &Common) -> i32 {
    // The first file is the script: its directory is the write root (without one, the
    // current directory); every file given is readable under --sandbox.
    let policy = super::run::fs_policy(common, files.first().map(PathBuf::as_path), &[], files);
    let mut it = match super::run::configured_interp(common, policy) {
        Ok(it) => it,
        Err(msg) => {
            eprintln!("error: {msg}");
            return super::EXIT_USAGE;
        }
    };
    it.ext::<ReplOptions>().0 = common.clone();
    if let Err(msg) = super::run::open_start_drawing(&mut it, common) {
        eprintln!("error: {msg}");
        return super::EXIT_SCRIPT_ERROR;
    }
    for f in files {
        if let Err(e) = it.load_file(&f.display().to_string()) {
            diag::print_error(&it, &e);
        }
    }
    let flag = it.interrupt.clone();
    // Ctrl-C while evaluating interrupts the evaluation; while editing, rustyline sees it.
    let _ = ctrlc::set_handler(move || flag.store(true, std::sync::atomic::Ordering::Relaxed));
    if std::io::stdin().is_terminal() {
        it.ext::<crate::builtins::input::InputState>().terminal = true;
        interactive(&mut it)
    } else {
        piped(&mut it)
    }
}

fn interactive(it: &mut Interp) -> i32 {
    let names = Rc::new(RefCell::new(completion_names(it)));
    // A double Tab lists every candidate, as bash does, instead of cycling through them.
    let config = rustyline::Config::builder()
        .auto_add_history(false)
        .completion_type(rustyline::CompletionType::List)
        .build();
    let mut ed = match rustyline::Editor::with_config(config) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("error: cannot start the line editor: {e}");
            return piped(it);
        }
    };
    ed.set_helper(Some(ReplHelper {
        names: names.clone(),
        brackets: MatchingBracketHighlighter::new(),
    }));
    let hist = history_path();
    if let Some(h) = &hist {
        let _ = ed.load_history(h);
    }
    println!(
        "lispcad {} — AutoLISP REPL. :help NAME, :load FILE, :save FILE, :quit; Ctrl-D exits.",
        env!("CARGO_PKG_VERSION")
    );
    while let Some(text) = read_entry(&mut ed) {
        if text.trim().is_empty() {
            continue;
        }
        let _ = ed.add_history_entry(text.as_str());
        if let Some(h) = &hist {
            let _ = ed.save_history(h);
        }
        if !entry(it, &text) {
            break;
        }
        *names.borrow_mut() = completion_names(it);
    }
    EXIT_OK
}

/// One entry: lines are read until the form is complete, each further line after AutoCAD's
/// continuation prompt (`(_> ` per open list, `"_> ` in a string). None at end of input;
/// Ctrl-C abandons the entry (an empty one).
fn read_entry(
    ed: &mut rustyline::Editor<ReplHelper, rustyline::history::DefaultHistory>,
) -> Option<String> {
    use rustyline::error::ReadlineError;
    let mut text = String::new();
    let mut prompt = PROMPT.to_string();
    loop {
        match ed.readline(&prompt) {
            Ok(line) => {
                if !text.is_empty() {
                    text.push('\n');
                }
                text.push_str(&line);
                if entry_complete(&text) {
                    return Some(text);
                }
                prompt = continuation_prompt(&text);
            }
            Err(ReadlineError::Interrupted) => return Some(String::new()),
            Err(_) => return None,
        }
    }
}

/// `((_> ` for an entry with two lists open, `"_> ` inside a string.
fn continuation_prompt(text: &str) -> String {
    match scan(text) {
        Scan::Incomplete(e) if e.message.contains("string") => "\"_> ".into(),
        Scan::Incomplete(e) if e.message.contains("comment") => ";|_> ".into(),
        _ => format!("{}_> ", "(".repeat(open_lists(text).max(1))),
    }
}

/// How many lists are open at the end of `text`, outside strings and comments.
fn open_lists(text: &str) -> usize {
    let mut depth: usize = 0;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            '"' => {
                while let Some(c) = chars.next() {
                    match c {
                        '\\' => {
                            chars.next();
                        }
                        '"' => break,
                        _ => {}
                    }
                }
            }
            ';' if chars.peek() == Some(&'|') => {
                let mut prev = ' ';
                for c in chars.by_ref() {
                    if prev == '|' && c == ';' {
                        break;
                    }
                    prev = c;
                }
            }
            ';' => {
                for c in chars.by_ref() {
                    if c == '\n' {
                        break;
                    }
                }
            }
            _ => {}
        }
    }
    depth
}

fn piped(it: &mut Interp) -> i32 {
    let stdin = std::io::stdin();
    let mut pending = String::new();
    for line in stdin.lock().lines() {
        let Ok(line) = line else { break };
        pending.push_str(&line);
        pending.push('\n');
        if !entry_complete(&pending) {
            continue;
        }
        let text = std::mem::take(&mut pending);
        if text.trim().is_empty() {
            continue;
        }
        if !entry(it, &text) {
            return EXIT_OK;
        }
    }
    if !pending.trim().is_empty() {
        entry(it, &pending);
    }
    EXIT_OK
}

/// The command-line options the REPL was started with: each entry gets the `--max-steps`
/// budget afresh, and `:save`/`:preview` write with the given DXF profile and tolerances.
#[derive(Default)]
struct ReplOptions(Common);

fn options(it: &mut Interp) -> Common {
    it.ext::<ReplOptions>().0.clone()
}

/// The file `:preview` rewrites after every evaluation.
#[derive(Default)]
struct Preview(Option<PathBuf>);

fn refresh_preview(it: &mut Interp) {
    let Some(path) = it.ext::<Preview>().0.clone() else {
        return;
    };
    let common = options(it);
    if let Err(msg) = crate::builtins::write_outputs(it, std::slice::from_ref(&path), &common) {
        eprintln!("preview: {msg}");
    }
}

/// Handles one complete entry; false to leave the REPL.
fn entry(it: &mut Interp, text: &str) -> bool {
    let trimmed = text.trim();
    if let Some(cmd) = trimmed.strip_prefix(':') {
        return command(it, cmd);
    }
    it.interrupt
        .store(false, std::sync::atomic::Ordering::Relaxed);
    let budget = options(it).max_steps;
    it.set_max_steps(budget);
    let r = it.eval_source("<repl>", text);
    it.flush_out();
    match r {
        Ok(v) => {
            let shown = it.prin1_string(&v);
            if !shown.is_empty() {
                println!("{shown}");
            }
            if v.is_nil() {
                if let Some(h) = unbound_hint(it, text) {
                    eprintln!("{h}");
                }
            }
            publish(it, None);
        }
        Err(e) if e.kind == ErrorKind::Exit => return false,
        Err(e) => {
            eprintln!("{}", diag::render_error(it, &e));
            publish(it, Some(&e));
        }
    }
    refresh_preview(it);
    let _ = std::io::stdout().flush();
    true
}

fn command(it: &mut Interp, cmd: &str) -> bool {
    let (name, arg) = cmd.split_once(char::is_whitespace).unwrap_or((cmd, ""));
    let arg = arg.trim();
    match name {
        "q" | "quit" | "exit" => return false,
        "help" | "h" => {
            if arg.is_empty() {
                println!(":help NAME     signature and description of a builtin or your defun");
                println!(":apropos TEXT  the builtins and functions whose names contain TEXT");
                println!(":inspect EXPR  the properties of a value (curve, surface, mesh, entity)");
                println!(":load FILE     load and evaluate a .lsp file");
                println!(":save FILE     write the drawing (.svg or .dxf)");
                println!(
                    ":preview FILE  rewrite FILE (.svg) after every evaluation; :preview off stops"
                );
                println!(
                    ":serve [PORT]  show the drawing in a browser, updated after every evaluation"
                );
                println!(":quit          leave (or Ctrl-D)");
            } else {
                println!("{}", help_or_suggestion(it, arg));
            }
        }
        "apropos" | "a" => apropos(it, arg),
        "inspect" | "i" => inspect(it, arg),
        "serve" => serve(it, arg),
        "load" => match it.load_file(arg) {
            Ok(v) => println!("{}", it.prin1_string(&v)),
            Err(e) => eprintln!("{}", diag::render_error(it, &e)),
        },
        "save" => {
            let common = options(it);
            match crate::builtins::write_outputs(it, &[PathBuf::from(arg)], &common) {
                Ok(()) => println!("wrote {arg}"),
                Err(msg) => eprintln!("error: {msg}"),
            }
        }
        "preview" => {
            if arg.is_empty() || arg == "off" {
                it.ext::<Preview>().0 = None;
                println!("preview off");
            } else {
                it.ext::<Preview>().0 = Some(PathBuf::from(arg));
                refresh_preview(it);
                println!("previewing into {arg} after every evaluation");
            }
        }
        other => eprintln!("unknown command :{other} (try :help)"),
    }
    true
}

/// A builtin's help, a user defun's, or "no help" with the nearest name.
fn help_or_suggestion(it: &mut Interp, name: &str) -> String {
    if let Some(t) = crate::builtins::system::help_text(name) {
        return t;
    }
    if let Some(t) = crate::lang::lint::user_help(it, name) {
        return t;
    }
    match nearest(name, function_names(it)) {
        Some(n) => format!(
            "no help for {name}: not a builtin or a defun; did you mean {}?",
            n.to_lowercase()
        ),
        None => format!("no help for {name}: not a builtin or a defun"),
    }
}

/// `:apropos TEXT`: every builtin and user function whose name contains TEXT, with its help's
/// first line.
fn apropos(it: &mut Interp, text: &str) {
    if text.is_empty() {
        eprintln!("usage: :apropos TEXT (the functions whose names contain TEXT)");
        return;
    }
    let want = text.to_lowercase();
    let mut names: Vec<String> = function_names(it)
        .map(str::to_lowercase)
        .filter(|n| n.contains(&want))
        .collect();
    names.sort();
    names.dedup();
    if names.is_empty() {
        println!("nothing matches {text}");
    }
    for n in names {
        let help = help_or_suggestion(it, &n);
        let mut lines = help.lines();
        let sig = lines.next().unwrap_or("");
        let doc = lines.next().unwrap_or("").trim();
        // A long signature keeps the descriptions in one column: its own line.
        if sig.chars().count() < 40 {
            println!("{sig:<40} {doc}");
        } else {
            println!("{sig}\n{:41}{doc}", "");
        }
    }
}

/// `:inspect EXPR`: the value, its type, and every property query that applies to it; an
/// entity's data one group per line, and its curve properties when it is a curve.
fn inspect(it: &mut Interp, expr: &str) {
    if expr.trim().is_empty() {
        eprintln!(
            "usage: :inspect EXPR (the properties of a curve, surface, mesh, entity or list)"
        );
        return;
    }
    let v = match it.eval_source("<inspect>", expr) {
        Ok(v) => v,
        Err(e) => {
            eprintln!("{}", diag::render_error(it, &e));
            return;
        }
    };
    it.flush_out();
    println!("{}", it.prin1_string(&v));
    let slot = "LISPCAD-INSPECTED";
    it.set_global(slot, v);
    const PROPERTIES: [(&str, &str); 10] = [
        ("type", "(type ~)"),
        ("length", "(curve-length ~)"),
        ("closed", "(curve-closed-p ~)"),
        ("start", "(point-at ~ 0.0)"),
        ("end", "(point-at ~ 1.0)"),
        ("area", "(area ~)"),
        ("surface area", "(surface-area ~)"),
        ("bounding box", "(bbox ~)"),
        ("boundary loops", "(length (surface-boundary ~))"),
        ("length (list)", "(if (listp ~) (length ~) (exit))"),
    ];
    // An entity's curve, through the ActiveX curve functions that take entity names.
    const ENTITY_CURVE: [(&str, &str); 5] = [
        (
            "length",
            "(vlax-curve-getDistAtParam ~ (vlax-curve-getEndParam ~))",
        ),
        ("closed", "(vlax-curve-isClosed ~)"),
        ("start", "(vlax-curve-getStartPoint ~)"),
        ("end", "(vlax-curve-getEndPoint ~)"),
        (
            "area",
            "(if (vlax-curve-isClosed ~) (vlax-curve-getArea ~) (exit))",
        ),
    ];
    let budget = options(it).max_steps;
    // Queries that do not apply fail; they are skipped quietly.
    let query = |it: &mut Interp, q: &str| {
        it.set_max_steps(budget.or(Some(10_000_000)));
        it.eval_source("<inspect>", &q.replace('~', slot)).ok()
    };
    for (label, q) in PROPERTIES {
        if let Some(r) = query(it, q) {
            println!("  {label:<15} {}", it.prin1_string(&r));
        }
    }
    if let Some(data) = query(it, "(entget ~)") {
        println!("  entity");
        for group in data.iter() {
            println!("    {}", it.prin1_string(group));
        }
        for (label, q) in ENTITY_CURVE {
            if let Some(r) = query(it, q) {
                println!("  {label:<15} {}", it.prin1_string(&r));
            }
        }
    }
    it.set_global(slot, Value::Nil);
    it.set_max_steps(budget);
}

/// The preview server started by `:serve`; every evaluation publishes into it.
#[derive(Default)]
struct Serving(Option<std::sync::Arc<super::serve::Shared>>);

fn serve(it: &mut Interp, arg: &str) {
    if let Some(_s) = &it.ext::<Serving>().0 {
        println!("already serving (one preview per session)");
        return;
    }
    let port = if arg.is_empty() {
        7878
    } else {
        match arg.parse::<u16>() {
            Ok(p) => p,
            Err(_) => {
                eprintln!("error: :serve PORT: `{arg}` is not a port number");
                return;
            }
        }
    };
    let shared = std::sync::Arc::new(super::serve::Shared::default());
    match super::serve::start(port, shared.clone()) {
        Ok(addr) => {
            shared.publish(super::serve::snapshot(it));
            it.ext::<Serving>().0 = Some(shared);
            println!("serving http://{addr}/ (updated after every evaluation)");
        }
        Err(e) => eprintln!("error: cannot listen on 127.0.0.1:{port}: {e}"),
    }
}

/// After an evaluation: the drawing, or the error over the last good drawing, to the page.
fn publish(it: &mut Interp, error: Option<&crate::lang::LispError>) {
    let Some(shared) = it.ext::<Serving>().0.clone() else {
        return;
    };
    match error {
        Some(e) => shared.publish(Err(super::serve::Failure::from_error(it, e))),
        None => shared.publish(super::serve::snapshot(it)),
    }
}

/// For an entry that is a bare symbol with no value: its nearest bound name, if any.
fn unbound_hint(it: &Interp, text: &str) -> Option<String> {
    let name = text.trim();
    if name.is_empty() || !name.chars().all(crate::cli::analysis::is_symbol_char) {
        return None;
    }
    if crate::lang::reader::parse_number(name).is_some() {
        return None;
    }
    if let Some(s) = it.syms.lookup(name) {
        if it.values.get(s.idx()).is_some_and(Value::truthy) {
            return None;
        }
    }
    let bound = it
        .syms
        .all()
        .filter(|(s, n)| !n.is_empty() && it.values.get(s.idx()).is_some_and(Value::truthy))
        .map(|(_, n)| n);
    nearest(name, bound).map(|n| {
        format!(
            "; {} has no value; did you mean {}?",
            name.to_uppercase(),
            n.to_uppercase()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rustyline::history::DefaultHistory;

    #[test]
    fn validator_understands_strings_and_comments() {
        assert!(entry_complete("(+ 1 2)"));
        assert!(!entry_complete("(+ 1\n"));
        assert!(!entry_complete("(strcat \")\""));
        assert!(entry_complete("(strcat \"((\" \")\")"));
        assert!(!entry_complete("(setq a 1 ; )\n"));
        assert!(entry_complete("(setq a 1 ; (\n)"));
        assert!(entry_complete("(setq a ;| ( |; 1)"));
        assert!(!entry_complete("(setq a ;| ) |; 1"));
        assert!(entry_complete("(princ \"\\\"\")"));
        assert!(entry_complete(":load (unbalanced"));
        assert!(entry_complete("a"));
        assert!(entry_complete(""));
    }

    fn helper(names: &[&str]) -> ReplHelper {
        ReplHelper {
            names: Rc::new(RefCell::new(names.iter().map(|s| s.to_string()).collect())),
            brackets: MatchingBracketHighlighter::new(),
        }
    }

    #[test]
    fn completer_offers_builtins_and_user_symbols() {
        let it = crate::builtins::new_interp();
        let mut names = completion_names(&it);
        names.push("my-func".into());
        let h = ReplHelper {
            names: Rc::new(RefCell::new(names)),
            brackets: MatchingBracketHighlighter::new(),
        };
        let hist = DefaultHistory::new();
        let ctx = Context::new(&hist);
        let (start, found) = h.complete("(mapc", 5, &ctx).unwrap();
        assert_eq!((start, found), (1, vec!["mapcar".to_string()]));
        let (start, found) = h.complete("(list (MY-", 10, &ctx).unwrap();
        assert_eq!((start, found), (7, vec!["my-func".to_string()]));
        let (_, found) = h.complete("(vl-string-tr", 13, &ctx).unwrap();
        assert!(found.contains(&"vl-string-trim".to_string()), "{found:?}");
        let (_, found) = h.complete("(", 1, &ctx).unwrap();
        assert!(found.is_empty());
    }

    #[test]
    fn completion_stops_at_quote_and_string_delimiters() {
        let h = helper(&["alpha", "alphabet", "beta"]);
        let hist = DefaultHistory::new();
        let ctx = Context::new(&hist);
        let (start, found) = h.complete("(f 'alp", 7, &ctx).unwrap();
        assert_eq!(start, 4);
        assert_eq!(found, ["alpha", "alphabet"]);
    }

    #[test]
    fn brackets_are_highlighted() {
        let h = helper(&[]);
        // The cursor after the closing paren highlights its partner.
        assert!(h.highlight_char("(+ 1 2)", 7, CmdKind::MoveCursor));
        let shown = h.highlight("(+ 1 2)", 7);
        assert_ne!(shown, "(+ 1 2)");
        assert!(shown.contains("\x1b["), "{shown:?}");
    }
}
