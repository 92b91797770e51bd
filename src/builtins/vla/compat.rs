//! The rest of what published routines lean on: `entmakex`, `ssnamex`, `snvalid`, `textbox`,
//! and the dialog functions, which refuse clearly (there is no DCL headless).

use crate::builtin;
use crate::builtins::entities::{ename_value, pickset_arg};
use crate::lang::builtin::{Builtin, MANY};
use crate::lang::error::{err, LResult};
use crate::lang::{Interp, Value};
use crate::output::Drawing;

pub static BUILTINS: &[Builtin] = &[
    builtin!("entmakex", "(entmakex dxf-list)", "As entmake, returning the new entity's name (nil on failure); an XRECORD or DICTIONARY is made without an owner, for dictadd.", 1, 1, entmakex),
    builtin!("ssnamex", "(ssnamex ss [index])", "How the entities of a selection set were selected: a list of (0 ename) (selection method 0: non-interactive).", 1, 2, ssnamex),
    builtin!("snvalid", "(snvalid name [flag])", "T if name is a valid symbol table name (flag 1 allows | inside it).", 1, 2, snvalid),
    builtin!("textbox", "(textbox dxf-list)", "The box of a TEXT entity's string relative to its insertion point, ((0 0 0) (w h 0)); an estimate (character advance 2/3 of the height), as there are no font metrics headless.", 1, 1, textbox),
    builtin!("load_dialog", "(load_dialog file)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("new_dialog", "(new_dialog name id)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("start_dialog", "(start_dialog)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("done_dialog", "(done_dialog [status])", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("unload_dialog", "(unload_dialog id)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("action_tile", "(action_tile key action)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("set_tile", "(set_tile key value)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("get_tile", "(get_tile key)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("mode_tile", "(mode_tile key mode)", "Refused: DCL dialogs are not available headless.", 0, MANY, no_dialog),
    builtin!("acad_colordlg", "(acad_colordlg color [flag])", "Refused: dialogs are not available headless (set the colour in the script).", 0, MANY, no_dialog),
    builtin!("acad_truecolordlg", "(acad_truecolordlg color [flag])", "Refused: dialogs are not available headless (set the colour in the script).", 0, MANY, no_dialog),
];

fn entmakex(it: &mut Interp, a: &[Value]) -> LResult {
    let g = crate::builtins::entities::dxf_list::Groups::parse(it, &a[0])?;
    let ty = g.string(it, 0)?.unwrap_or_default().to_uppercase();
    if ty == "XRECORD" || ty == "DICTIONARY" {
        // An object without an owner, for dictadd.
        let h = crate::builtins::entities::objects::make_object(it, &ty, &g)?;
        return Ok(h.map_or(Value::Nil, |h| ename_value(it, h)));
    }
    let before = it.ext::<Drawing>().next_handle();
    let r = crate::builtins::entities::make::entmake(it, a)?;
    if r.is_nil() {
        return Ok(Value::Nil);
    }
    // A POLYLINE's header is made with its first call: entlast names the new entity.
    let d = it.ext::<Drawing>();
    match d.last() {
        Some(h) if h >= before => Ok(ename_value(it, h)),
        _ => Ok(Value::Nil),
    }
}

fn ssnamex(it: &mut Interp, a: &[Value]) -> LResult {
    let members = pickset_arg(it, &a[0])?.members.borrow().clone();
    let pick = match a.get(1) {
        Some(i) => {
            let i = it.int(i)?;
            match usize::try_from(i).ok().and_then(|i| members.get(i)) {
                Some(h) => vec![*h],
                None => return Ok(Value::Nil),
            }
        }
        None => members,
    };
    let mut out = Vec::with_capacity(pick.len());
    for h in pick {
        let e = ename_value(it, h);
        out.push(Value::list([Value::Int(0), e]));
    }
    Ok(Value::list(out))
}

fn snvalid(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let pipe_ok = match a.get(1) {
        Some(f) => it.int(f)? == 1,
        None => false,
    };
    let n = name.chars().count();
    let ok = n > 0
        && n <= 255
        && name.chars().enumerate().all(|(i, c)| {
            if c == '|' {
                return pipe_ok && i > 0 && i + 1 < n;
            }
            !c.is_control() && !"<>/\\\":;?*,=`".contains(c)
        });
    Ok(Value::bool(ok))
}

fn textbox(it: &mut Interp, a: &[Value]) -> LResult {
    let mut text = String::new();
    let mut height = it
        .ext::<crate::builtins::system::SysVars>()
        .real("TEXTSIZE");
    for g in a[0].iter() {
        match (g.car(), g.cdr()) {
            (Value::Int(1), Value::Str(s)) => text = s.to_string(),
            (Value::Int(40), h) => height = it.num(&h)?,
            _ => {}
        }
    }
    let w = text.chars().count() as f64 * height * 2.0 / 3.0;
    let pt = |x: f64, y: f64| Value::list([Value::Real(x), Value::Real(y), Value::Real(0.0)]);
    Ok(Value::list([pt(0.0, 0.0), pt(w, height)]))
}

fn no_dialog(_: &mut Interp, _: &[Value]) -> LResult {
    Err(err(
        "dialogs are not available headless: lispcad has no DCL or dialog boxes (take the value from the script, --set or --answers)",
    ))
}
