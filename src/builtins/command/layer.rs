//! The LAYER command (AutoCAD's -LAYER prompts): Make, Set, New, Color, LType, ON/OFF,
//! Freeze/Thaw, LOck/Unlock; name lists are comma-separated and may use wild-cards for
//! existing layers; `""` ends the command.

use super::{cmd_err, unexpected, Input, Pending, Step};
use crate::builtins::text::wcmatch::WcPattern;
use crate::lang::error::Exn;
use crate::lang::{Interp, Value};
use crate::output::Drawing;

#[derive(Default)]
pub(crate) enum LayerCmd {
    /// Waiting for an option.
    #[default]
    Option,
    Make,
    Set,
    New,
    Color,
    /// The layers to give colour `.0` (Enter = the current layer).
    ColorNames(i16),
    LtypeName,
    LtypeNames(String),
    /// Names for ON, OFF, FREEZE, THAW, LOCK, UNLOCK.
    Names(&'static str),
}

/// The colour numbers AutoCAD's prompts accept by name (ACI 1 to 7).
pub(super) fn named_color(name: &str) -> Option<i64> {
    let c = match name.trim().to_uppercase().as_str() {
        "RED" => 1,
        "YELLOW" => 2,
        "GREEN" => 3,
        "CYAN" => 4,
        "BLUE" => 5,
        "MAGENTA" => 6,
        "WHITE" => 7,
        _ => return None,
    };
    Some(c)
}

fn color_number(input: &Input, raw: &Value) -> Option<i16> {
    let c = match input {
        Input::Number(x) if x.fract() == 0.0 => *x as i64,
        _ => named_color(&input.name(raw)?)?,
    };
    (1..=255).contains(&c).then_some(c as i16)
}

fn set_current(it: &mut Interp, name: &str) -> Result<(), Exn> {
    it.ext::<Drawing>()
        .use_layer(name, None)
        .map_err(|e| cmd_err("LAYER", e))?;
    Ok(())
}

/// The existing layers a comma-separated name list names (wild-cards allowed); Enter means the
/// current layer.
fn matching_layers(it: &mut Interp, list: Option<&str>) -> Vec<String> {
    let d = it.ext::<Drawing>();
    let Some(list) = list else {
        return vec![d.current_layer().to_string()];
    };
    let pat = WcPattern::new(&list.to_uppercase());
    d.layers()
        .iter()
        .filter(|l| pat.matches(&l.name.to_uppercase()))
        .map(|l| l.name.clone())
        .collect()
}

impl LayerCmd {
    pub(crate) fn feed(self, it: &mut Interp, input: &Input, raw: &Value) -> Result<Step, Exn> {
        let name = input.name(raw);
        let enter = matches!(input, Input::Enter);
        let next = match self {
            LayerCmd::Option => {
                if enter {
                    return Ok(Step::Done);
                }
                match input.keyword().as_deref() {
                    Some("M" | "MAKE") => LayerCmd::Make,
                    Some("S" | "SET") => LayerCmd::Set,
                    Some("N" | "NEW") => LayerCmd::New,
                    Some("C" | "COLOR" | "COLOUR") => LayerCmd::Color,
                    Some("L" | "LT" | "LTYPE") => LayerCmd::LtypeName,
                    Some("ON") => LayerCmd::Names("ON"),
                    Some("OFF") => LayerCmd::Names("OFF"),
                    Some("F" | "FREEZE") => LayerCmd::Names("FREEZE"),
                    Some("T" | "THAW") => LayerCmd::Names("THAW"),
                    Some("LO" | "LOCK") => LayerCmd::Names("LOCK"),
                    Some("U" | "UNLOCK") => LayerCmd::Names("UNLOCK"),
                    _ => {
                        return Err(unexpected(
                            "LAYER",
                            "an option (M, S, N, C, L, ON, OFF, F, T, LO, U) or \"\"",
                            input,
                        ))
                    }
                }
            }
            LayerCmd::Make | LayerCmd::Set | LayerCmd::New if enter => LayerCmd::Option,
            LayerCmd::Make => {
                let n = name.ok_or_else(|| unexpected("LAYER", "a layer name", input))?;
                set_current(it, n.trim())?;
                LayerCmd::Option
            }
            LayerCmd::Set => {
                let n = name.ok_or_else(|| unexpected("LAYER", "a layer name", input))?;
                if it.ext::<Drawing>().layer(n.trim()).is_none() {
                    return Err(cmd_err(
                        "LAYER",
                        format!("cannot find layer \"{}\"", n.trim()),
                    ));
                }
                set_current(it, n.trim())?;
                LayerCmd::Option
            }
            LayerCmd::New => {
                let n = name.ok_or_else(|| unexpected("LAYER", "layer names", input))?;
                for part in n.split(',').map(str::trim).filter(|s| !s.is_empty()) {
                    it.ext::<Drawing>()
                        .ensure_layer(part)
                        .map_err(|e| cmd_err("LAYER", e))?;
                }
                LayerCmd::Option
            }
            LayerCmd::Color => {
                let c = color_number(input, raw).ok_or_else(|| {
                    unexpected("LAYER", "a colour (1..255 or a colour name)", input)
                })?;
                LayerCmd::ColorNames(c)
            }
            LayerCmd::ColorNames(c) => {
                for l in matching_layers(it, if enter { None } else { name.as_deref() }) {
                    if let Some(layer) = it.ext::<Drawing>().layer_mut(&l) {
                        // Keep an off layer off (negative colour).
                        layer.color = if layer.color < 0 { -c } else { c };
                    }
                }
                LayerCmd::Option
            }
            LayerCmd::LtypeName => {
                let n = name.ok_or_else(|| unexpected("LAYER", "a line type name", input))?;
                LayerCmd::LtypeNames(n.trim().to_string())
            }
            LayerCmd::LtypeNames(lt) => {
                for l in matching_layers(it, if enter { None } else { name.as_deref() }) {
                    if let Some(layer) = it.ext::<Drawing>().layer_mut(&l) {
                        layer.linetype = lt.clone();
                    }
                }
                LayerCmd::Option
            }
            LayerCmd::Names(op) => {
                for l in matching_layers(it, if enter { None } else { name.as_deref() }) {
                    if let Some(layer) = it.ext::<Drawing>().layer_mut(&l) {
                        match op {
                            "ON" => layer.color = layer.color.abs(),
                            "OFF" => layer.color = -layer.color.abs(),
                            "FREEZE" => layer.frozen = true,
                            "THAW" => layer.frozen = false,
                            "LOCK" => layer.locked = true,
                            _ => layer.locked = false,
                        }
                    }
                }
                LayerCmd::Option
            }
        };
        Ok(Step::More(Pending::Layer(next)))
    }
}
