//! The TEXT command (AutoCAD's -TEXT prompts): start point (after the optional "J"ustify and
//! "S"tyle options), height, rotation in degrees, then one line of text.

use glam::DVec3;

use super::{add, unexpected, Input, Pending, Step};
use crate::lang::error::Exn;
use crate::lang::{Interp, Value};
use crate::output::EntityKind;

#[derive(Clone, Copy, PartialEq)]
enum Expect {
    Start,
    /// The justification keyword after "J" (accepted; the text is placed at its point).
    Justify,
    Style,
    Height,
    Rotation,
    Text,
}

pub(crate) struct TextCmd {
    expect: Expect,
    insert: DVec3,
    height: f64,
    rotation: f64,
    style: String,
}

impl Default for TextCmd {
    fn default() -> Self {
        TextCmd {
            expect: Expect::Start,
            insert: DVec3::ZERO,
            height: 2.5,
            rotation: 0.0,
            style: "Standard".to_string(),
        }
    }
}

impl TextCmd {
    pub(crate) fn feed(mut self, it: &mut Interp, input: &Input, raw: &Value) -> Result<Step, Exn> {
        match (self.expect, input) {
            (Expect::Start, Input::Point(p)) => {
                self.insert = *p;
                self.height = crate::builtins::system::SysVars::real(
                    it.ext::<crate::builtins::system::SysVars>(),
                    "TEXTSIZE",
                );
                self.expect = Expect::Height;
            }
            (Expect::Start, Input::Word(_)) => match input.keyword().as_deref() {
                Some("J" | "JUSTIFY") => self.expect = Expect::Justify,
                Some("S" | "STYLE") => self.expect = Expect::Style,
                _ => return Err(unexpected("TEXT", "a start point, \"J\" or \"S\"", input)),
            },
            (Expect::Justify, Input::Word(_)) => self.expect = Expect::Start,
            (Expect::Style, _) => {
                if let Some(s) = input.name(raw) {
                    self.style = s;
                }
                self.expect = Expect::Start;
            }
            (Expect::Height, Input::Number(h)) => {
                self.height = *h;
                self.expect = Expect::Rotation;
            }
            (Expect::Height, Input::Enter) => self.expect = Expect::Rotation,
            (Expect::Rotation, Input::Number(deg)) => {
                self.rotation = deg.to_radians();
                self.expect = Expect::Text;
            }
            (Expect::Rotation, Input::Enter) => self.expect = Expect::Text,
            (Expect::Text, Input::Enter) => return Ok(Step::Done),
            (Expect::Text, _) => {
                // The text is taken as typed, even when it looks like a number or a point.
                let value = match raw {
                    Value::Str(s) => s.to_string(),
                    Value::Int(i) => i.to_string(),
                    Value::Real(r) => crate::builtins::text::format_real(*r),
                    _ => return Err(unexpected("TEXT", "the text string", input)),
                };
                add(
                    it,
                    "TEXT",
                    EntityKind::Text {
                        insert: self.insert,
                        height: self.height,
                        value,
                        rotation: self.rotation,
                        style: std::mem::take(&mut self.style),
                    },
                )?;
                return Ok(Step::Done);
            }
            (Expect::Height, _) => return Err(unexpected("TEXT", "a height", input)),
            (Expect::Rotation, _) => {
                return Err(unexpected("TEXT", "a rotation angle in degrees", input))
            }
            _ => return Err(unexpected("TEXT", "a start point", input)),
        }
        Ok(Step::More(Pending::Text(self)))
    }
}
