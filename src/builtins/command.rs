//! `command`, `command-s` and `vl-cmdf`: AutoCAD's command line, headless.
//!
//! Arguments are fed one at a time to the pending command, as AutoCAD's prompts consume them,
//! so a command may be spread over several `(command ...)` calls. Point input takes point lists
//! and the command-line strings `"x,y[,z]"`, `"@dx,dy[,dz]"` (relative to the last point) and
//! `"d<a"` / `"@d<a"` (polar, a in degrees as typed at AutoCAD's prompt); `""` is Enter;
//! `(command)` cancels. Commands: LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT,
//! MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines, arcs, circles, polylines), CHPROP, CHANGE, UNDO (marks), UCS (World only), and the
//! display commands (ZOOM, REGEN...) that have nothing to do headless.

use glam::{DVec2, DVec3};

use crate::builtin;
use crate::builtins::entities::select::selected_handles;
use crate::builtins::entities::EntityState;
use crate::builtins::input::{parse_real, point_text};
use crate::builtins::system::SysVars;
use crate::lang::builtin::{Builtin, MANY};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::{Drawing, Entity, EntityKind};

#[path = "command/draw.rs"]
mod draw;
#[path = "command/edit.rs"]
mod edit;
#[path = "command/explode.rs"]
mod explode;
#[path = "command/fillet.rs"]
mod fillet;
#[path = "command/fillet_pline.rs"]
mod fillet_pline;
#[path = "command/insert.rs"]
mod insert;
#[path = "command/layer.rs"]
mod layer;
#[path = "command/modify.rs"]
mod modify;
#[path = "command/text.rs"]
mod text;

pub static BUILTINS: &[Builtin] = &[
    builtin!("command", "(command [arg...])", "Feeds arguments to AutoCAD commands (LINE CIRCLE ARC PLINE SPLINE LAYER ERASE POINT TEXT MOVE COPY ROTATE SCALE MIRROR INSERT OFFSET EXPLODE FILLET CHPROP CHANGE UNDO); \"\" is Enter, PAUSE takes the next --answers line, (command) cancels; a command may span several calls. Returns nil.", 0, MANY, command),
    builtin!("command-s", "(command-s [arg...])", "As command, but a command left unfinished at the end of the call is cancelled. Returns nil.", 0, MANY, command_s),
    builtin!("vl-cmdf", "(vl-cmdf [arg...])", "As command; returns T.", 0, MANY, vl_cmdf),
];

/// Binds PAUSE, AutoLISP's "wait for the user" token (a backslash string).
pub fn init(it: &mut Interp) {
    it.set_global("PAUSE", Value::str("\\"));
}

/// One argument as a prompt sees it.
#[derive(Clone, Debug)]
pub(crate) enum Input {
    /// `""`: Enter.
    Enter,
    Point(DVec3),
    Number(f64),
    /// Any other string: a keyword (compare upper-cased) or a name.
    Word(String),
    /// Entities given by a selection set, an entity name or an `(ename point)` list.
    Select(Vec<u64>),
}

impl Input {
    pub(crate) fn keyword(&self) -> Option<String> {
        match self {
            // "_S": the underscore asks for the English keyword, as in AutoCAD.
            Input::Word(w) => Some(w.trim().trim_start_matches('_').to_uppercase()),
            _ => None,
        }
    }

    /// The text of a name argument (a layer name may look like a number).
    pub(crate) fn name(&self, raw: &Value) -> Option<String> {
        match raw {
            Value::Str(s) => Some(s.to_string()),
            Value::Int(i) => Some(i.to_string()),
            _ => match self {
                Input::Word(w) => Some(w.clone()),
                _ => None,
            },
        }
    }

    fn describe(&self) -> String {
        match self {
            Input::Enter => "Enter (\"\")".to_string(),
            Input::Point(p) => format!("the point ({} {} {})", p.x, p.y, p.z),
            Input::Number(x) => format!("the number {x}"),
            Input::Word(w) => format!("\"{w}\""),
            Input::Select(_) => "a selection".to_string(),
        }
    }
}

/// A command waiting for more input.
pub(crate) enum Pending {
    Draw(draw::DrawCmd),
    Layer(layer::LayerCmd),
    Erase(Vec<u64>),
    Text(text::TextCmd),
    Edit(edit::EditCmd),
    Chprop(modify::ChpropCmd),
    Explode,
    Offset(modify::OffsetCmd),
    Fillet(modify::FilletCmd),
    Insert(insert::InsertCmd),
    /// UNDO: BEgin/End marks keep UNDOCTL's bit 8; the other options do nothing headless.
    Undo,
    /// UCS: only the World UCS exists headless.
    Ucs,
    /// A display command with nothing to do headless: swallows the rest of the call.
    Ignore,
}

/// The command line's state between calls.
#[derive(Default)]
pub struct CommandState {
    pending: Option<Pending>,
    last_point: Option<DVec3>,
}

/// What feeding one input did.
pub(crate) enum Step {
    /// The command wants more input.
    More(Pending),
    /// The command is complete.
    Done,
    /// The command is complete and did not use this input: give it to the command line.
    DoneNotConsumed,
}

pub(crate) fn cmd_err(cmd: &str, msg: impl std::fmt::Display) -> Exn {
    err(format!("{cmd}: {msg}"))
}

pub(crate) fn unexpected(cmd: &str, want: &str, got: &Input) -> Exn {
    cmd_err(cmd, format!("expected {want}, got {}", got.describe()))
}

/// Adds an entity on the current layer, colour BYLAYER.
pub(crate) fn add(it: &mut Interp, cmd: &str, kind: EntityKind) -> Result<u64, Exn> {
    let layer = crate::builtins::entities::make::current_layer(it);
    it.ext::<Drawing>()
        .add(Entity::new(&layer, kind))
        .map_err(|e| cmd_err(cmd, e))
}

/// A command-line point string; `last` is what "@" is relative to.
pub(crate) fn parse_point_str(s: &str, last: DVec3) -> Option<DVec3> {
    point_text(s, || last)
}

fn classify(it: &Interp, v: &Value, last: DVec3) -> Result<Option<Input>, Exn> {
    Ok(Some(match v {
        Value::Nil => return Ok(None),
        Value::Str(s) if s.is_empty() => Input::Enter,
        Value::Str(s) => {
            if let Some(p) = parse_point_str(s, last) {
                Input::Point(p)
            } else if let Some(x) = parse_real(s) {
                Input::Number(x)
            } else {
                Input::Word(s.to_string())
            }
        }
        Value::Int(i) => Input::Number(*i as f64),
        Value::Real(r) => Input::Number(*r),
        Value::Cons(_) => match selected_handles(v) {
            Some(h) => Input::Select(h),
            None => Input::Point(DVec3::from_array(it.point(v)?)),
        },
        Value::Obj(_) => match selected_handles(v) {
            Some(h) => Input::Select(h),
            None => {
                return Err(err(format!(
                    "command: cannot use {} as command input",
                    it.prin1_string(v)
                )))
            }
        },
        _ => {
            return Err(err(format!(
                "command: cannot use {} as command input",
                it.prin1_string(v)
            )))
        }
    }))
}

/// The command a name starts ("_.-LAYER" → LAYER), with AutoCAD's usual aliases.
fn start(name: &str) -> Result<Step, Exn> {
    let n = name
        .trim()
        .trim_start_matches(['_', '.', '-', '\''])
        .to_uppercase();
    const KNOWN: &[&str] = &[
        "LINE",
        "TEXT",
        "UCS",
        "CIRCLE",
        "ARC",
        "PLINE",
        "SPLINE",
        "POINT",
        "LAYER",
        "ERASE",
        "ZOOM",
        "PAN",
        "REGEN",
        "REGENALL",
        "REDRAW",
        "REDRAWALL",
        "UNDO",
        "MOVE",
        "COPY",
        "ROTATE",
        "SCALE",
        "MIRROR",
        "CHPROP",
        "CHANGE",
        "EXPLODE",
        "OFFSET",
        "FILLET",
        "INSERT",
        "OSNAP",
        "GRAPHSCR",
        "TEXTSCR",
    ];
    let alias = match n.as_str() {
        "L" => "LINE",
        "C" => "CIRCLE",
        "A" => "ARC",
        "PL" => "PLINE",
        "SPL" => "SPLINE",
        "LA" => "LAYER",
        "E" => "ERASE",
        "PO" => "POINT",
        "DT" | "DTEXT" => "TEXT",
        "Z" => "ZOOM",
        "P" => "PAN",
        "RE" => "REGEN",
        "R" => "REDRAW",
        "U" => "UNDO",
        "OS" => "OSNAP",
        "M" => "MOVE",
        "CO" | "CP" => "COPY",
        "RO" => "ROTATE",
        "SC" => "SCALE",
        "MI" => "MIRROR",
        "X" => "EXPLODE",
        "O" => "OFFSET",
        "F" => "FILLET",
        "I" => "INSERT",
        other => other,
    };
    let cmd = KNOWN.iter().copied().find(|k| *k == alias).unwrap_or("");
    Ok(match cmd {
        "LINE" | "CIRCLE" | "ARC" | "PLINE" | "SPLINE" | "POINT" => {
            Step::More(Pending::Draw(draw::DrawCmd::new(cmd)))
        }
        "LAYER" => Step::More(Pending::Layer(layer::LayerCmd::default())),
        "ERASE" => Step::More(Pending::Erase(Vec::new())),
        "TEXT" => Step::More(Pending::Text(text::TextCmd::default())),
        "UCS" => Step::More(Pending::Ucs),
        "MOVE" => Step::More(Pending::Edit(edit::EditCmd::new("MOVE"))),
        "COPY" => Step::More(Pending::Edit(edit::EditCmd::new("COPY"))),
        "ROTATE" => Step::More(Pending::Edit(edit::EditCmd::new("ROTATE"))),
        "SCALE" => Step::More(Pending::Edit(edit::EditCmd::new("SCALE"))),
        "MIRROR" => Step::More(Pending::Edit(edit::EditCmd::new("MIRROR"))),
        "UNDO" => Step::More(Pending::Undo),
        "CHPROP" => Step::More(Pending::Chprop(modify::ChpropCmd::new("CHPROP"))),
        "CHANGE" => Step::More(Pending::Chprop(modify::ChpropCmd::new("CHANGE"))),
        "EXPLODE" => Step::More(Pending::Explode),
        "OFFSET" => Step::More(Pending::Offset(modify::OffsetCmd::Distance)),
        "FILLET" => Step::More(Pending::Fillet(modify::FilletCmd::First)),
        "INSERT" => Step::More(Pending::Insert(insert::InsertCmd::new())),
        "ZOOM" | "PAN" | "REGEN" | "REGENALL" | "REDRAW" | "REDRAWALL" | "OSNAP" | "GRAPHSCR"
        | "TEXTSCR" => Step::More(Pending::Ignore),
        _ => {
            return Err(err(format!(
                "command: unknown command \"{name}\" (lispcad runs LINE, CIRCLE, ARC, PLINE, SPLINE, LAYER, ERASE, POINT, TEXT, MOVE, COPY, ROTATE, SCALE, MIRROR, INSERT, OFFSET, EXPLODE, FILLET (lines, arcs, circles, polylines), CHPROP, CHANGE, UNDO)"
            )));
        }
    })
}

fn erase(it: &mut Interp, mut picked: Vec<u64>, input: &Input) -> Result<Step, Exn> {
    match input {
        Input::Select(h) => picked.extend(h),
        Input::Enter => {
            let d = it.ext::<Drawing>();
            for h in picked {
                d.delete(h);
            }
            return Ok(Step::Done);
        }
        Input::Word(_) => match input.keyword().as_deref() {
            Some("L" | "LAST") => picked.extend(it.ext::<Drawing>().last()),
            Some("ALL") => {
                let all: Vec<u64> = it.ext::<Drawing>().entities().map(|e| e.handle).collect();
                picked.extend(all);
            }
            Some("P" | "PREVIOUS") => {
                let prev = it.ext::<EntityState>().previous.clone();
                picked.extend(prev);
            }
            _ => {
                return Err(unexpected(
                    "ERASE",
                    "objects (a selection set, an entity name, \"L\", \"ALL\", \"P\") or \"\"",
                    input,
                ))
            }
        },
        _ => {
            return Err(unexpected(
                "ERASE",
                "objects (a selection set, an entity name, \"L\", \"ALL\", \"P\") or \"\"",
                input,
            ))
        }
    }
    Ok(Step::More(Pending::Erase(picked)))
}

/// Gives one input to the pending command (or starts one).
fn feed(it: &mut Interp, st: &mut CommandState, raw: &Value) -> Result<(), Exn> {
    let last = st.last_point.unwrap_or(DVec3::ZERO);
    // PAUSE takes the next scripted answer (--answers), as the user's input at the prompt.
    let answered;
    let raw = if matches!(raw, Value::Str(s) if s.as_str() == "\\") {
        answered = crate::builtins::input::console_read_line(it).map_err(|_| {
            err("command: PAUSE waits for the user: give the answer with --answers in a headless run")
        })?;
        &answered
    } else {
        raw
    };
    let Some(input) = classify(it, raw, last)? else {
        return Ok(());
    };
    let mut input = Some(input);
    // At most twice: a finished command may hand its input back to the command line.
    while let Some(inp) = input.take() {
        if let Input::Point(p) = inp {
            st.last_point = Some(p);
            it.ext::<SysVars>()
                .put("LASTPOINT", crate::builtins::geometry::point3(p));
        }
        let step = match st.pending.take() {
            None => match &inp {
                Input::Enter => Step::Done,
                Input::Word(w) => start(w)?,
                other => {
                    return Err(err(format!(
                        "command: expected a command name, got {}",
                        other.describe()
                    )))
                }
            },
            Some(Pending::Ignore) => Step::More(Pending::Ignore),
            Some(Pending::Erase(picked)) => erase(it, picked, &inp)?,
            Some(Pending::Layer(l)) => l.feed(it, &inp, raw)?,
            Some(Pending::Draw(d)) => d.feed(it, &inp)?,
            Some(Pending::Text(t)) => t.feed(it, &inp, raw)?,
            Some(Pending::Edit(e)) => e.feed(it, &inp)?,
            Some(Pending::Chprop(c)) => c.feed(it, &inp, raw)?,
            Some(Pending::Explode) => modify::explode(it, &inp)?,
            Some(Pending::Offset(o)) => o.feed(it, &inp)?,
            Some(Pending::Fillet(f)) => f.feed(it, &inp, raw)?,
            Some(Pending::Insert(c)) => c.feed(it, &inp, raw)?,
            Some(Pending::Undo) => {
                let sv = it.ext::<SysVars>();
                let ctl = sv.int("UNDOCTL");
                match inp.keyword().as_deref() {
                    Some("BE" | "BEGIN") => sv.put("UNDOCTL", Value::Int(ctl | 8)),
                    Some("E" | "END") => sv.put("UNDOCTL", Value::Int(ctl & !8)),
                    _ => {}
                }
                Step::Done
            }
            Some(Pending::Ucs) => match inp.keyword().as_deref() {
                Some("W" | "WORLD") => Step::Done,
                _ if matches!(inp, Input::Enter) => Step::Done,
                _ => {
                    return Err(cmd_err(
                        "UCS",
                        format!(
                            "only the World UCS exists in lispcad (\"W\"), got {}",
                            inp.describe()
                        ),
                    ))
                }
            },
        };
        match step {
            Step::More(p) => st.pending = Some(p),
            Step::Done => {}
            Step::DoneNotConsumed => input = Some(inp),
        }
    }
    Ok(())
}

/// Cancels the pending command; what AutoCAD keeps on Esc (a PLINE's segments) is kept.
fn cancel(it: &mut Interp, st: &mut CommandState) -> Result<(), Exn> {
    if let Some(Pending::Draw(d)) = st.pending.take() {
        d.cancel(it)?;
    }
    Ok(())
}

fn run(it: &mut Interp, a: &[Value], finish: bool) -> Result<(), Exn> {
    let mut st = std::mem::take(it.ext::<CommandState>());
    let mut r = Ok(());
    if a.is_empty() {
        r = cancel(it, &mut st);
    }
    for v in a {
        r = feed(it, &mut st, v);
        if r.is_err() {
            // A failed command is cancelled, as AutoCAD's *Cancel* on an error.
            st.pending = None;
            break;
        }
    }
    if matches!(st.pending, Some(Pending::Ignore)) {
        st.pending = None;
    }
    if finish && r.is_ok() {
        r = cancel(it, &mut st);
    }
    *it.ext::<CommandState>() = st;
    r
}

fn command(it: &mut Interp, a: &[Value]) -> LResult {
    run(it, a, false)?;
    Ok(Value::Nil)
}

fn command_s(it: &mut Interp, a: &[Value]) -> LResult {
    run(it, a, true)?;
    Ok(Value::Nil)
}

fn vl_cmdf(it: &mut Interp, a: &[Value]) -> LResult {
    run(it, a, false)?;
    Ok(Value::T)
}

/// The 2D direction angle of a vector.
pub(crate) fn angle2(v: DVec2) -> f64 {
    v.y.atan2(v.x)
}
