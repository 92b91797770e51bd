//! The editing commands routines call most: MOVE, COPY, ROTATE, SCALE, MIRROR. Each takes
//! objects (selection sets, entity names, "L", "ALL", "P") ended by Enter, then its points
//! and values as AutoCAD prompts for them; the entities change through the same transforms
//! as the ActiveX methods (`vla/xform.rs`).

use glam::{DMat4, DVec3};

use super::{cmd_err, unexpected, Input, Pending, Step};
use crate::builtins::entities::EntityState;
use crate::builtins::vla::xform::transform_entity;
use crate::geom::curve::xform;
use crate::lang::error::Exn;
use crate::lang::Interp;
use crate::output::{Drawing, Entity};

/// Where an editing command is in its prompts.
pub(crate) struct EditCmd {
    name: &'static str,
    picked: Vec<u64>,
    /// Points given so far after the selection.
    points: Vec<DVec3>,
    selecting: bool,
}

impl EditCmd {
    pub(crate) fn new(name: &'static str) -> EditCmd {
        EditCmd {
            name,
            picked: Vec::new(),
            points: Vec::new(),
            selecting: true,
        }
    }

    pub(crate) fn feed(mut self, it: &mut Interp, input: &Input) -> Result<Step, Exn> {
        if self.selecting {
            return self.select(it, input);
        }
        let name = self.name;
        match (name, self.points.len(), input) {
            (_, 0, Input::Point(p)) => {
                self.points.push(*p);
                Ok(Step::More(Pending::Edit(self)))
            }
            ("MOVE" | "COPY", 1, Input::Point(p)) => {
                let m = xform::translate(*p - self.points[0]);
                apply(it, name, &self.picked, &m, name == "COPY")?;
                if name == "COPY" {
                    // COPY repeats (AutoCAD's Multiple mode) until Enter.
                    return Ok(Step::More(Pending::Edit(self)));
                }
                Ok(Step::Done)
            }
            ("MOVE", 1, Input::Enter) => {
                // Enter: the base point is the displacement.
                let m = xform::translate(self.points[0]);
                apply(it, name, &self.picked, &m, false)?;
                Ok(Step::Done)
            }
            ("COPY", 1, Input::Enter) => Ok(Step::Done),
            ("COPY", 1, Input::Word(_)) => Ok(Step::DoneNotConsumed),
            ("ROTATE", 1, Input::Number(deg)) => {
                let m = xform::rotate(self.points[0], deg.to_radians(), None)
                    .map_err(|e| cmd_err(name, e))?;
                apply(it, name, &self.picked, &m, false)?;
                Ok(Step::Done)
            }
            ("SCALE", 1, Input::Number(f)) => {
                let m = xform::scale(self.points[0], *f).map_err(|e| cmd_err(name, e))?;
                apply(it, name, &self.picked, &m, false)?;
                Ok(Step::Done)
            }
            ("MIRROR", 1, Input::Point(p)) => {
                self.points.push(*p);
                Ok(Step::More(Pending::Edit(self)))
            }
            ("MIRROR", 2, _) => {
                let erase = match input {
                    Input::Enter => false,
                    _ => match input.keyword().as_deref() {
                        Some("Y" | "YES") => true,
                        Some("N" | "NO") => false,
                        _ => return Err(unexpected(name, "Y, N or \"\"", input)),
                    },
                };
                let m =
                    xform::mirror(self.points[0], self.points[1]).map_err(|e| cmd_err(name, e))?;
                apply(it, name, &self.picked, &m, !erase)?;
                Ok(Step::Done)
            }
            _ => Err(unexpected(name, self.wanted(), input)),
        }
    }

    fn wanted(&self) -> &'static str {
        match (self.name, self.points.len()) {
            (_, 0) => "a base point",
            ("ROTATE", _) => "a rotation angle in degrees",
            ("SCALE", _) => "a scale factor",
            ("MIRROR", 1) => "the second point of the mirror line",
            ("MIRROR", _) => "Y, N or \"\" (erase source objects?)",
            _ => "a second point or \"\"",
        }
    }

    fn select(mut self, it: &mut Interp, input: &Input) -> Result<Step, Exn> {
        match input {
            Input::Select(h) => self.picked.extend(h),
            Input::Enter => {
                if self.picked.is_empty() {
                    return Err(cmd_err(self.name, "no objects selected"));
                }
                self.selecting = false;
            }
            Input::Word(_) => match input.keyword().as_deref() {
                Some("L" | "LAST") => self.picked.extend(it.ext::<Drawing>().last()),
                Some("ALL") => {
                    let all: Vec<u64> = it.ext::<Drawing>().entities().map(|e| e.handle).collect();
                    self.picked.extend(all);
                }
                Some("P" | "PREVIOUS") => {
                    let prev = it.ext::<EntityState>().previous.clone();
                    self.picked.extend(prev);
                }
                _ => return Err(unexpected(self.name, OBJECTS, input)),
            },
            _ => return Err(unexpected(self.name, OBJECTS, input)),
        }
        Ok(Step::More(Pending::Edit(self)))
    }
}

const OBJECTS: &str = "objects (a selection set, an entity name, \"L\", \"ALL\", \"P\") or \"\"";

/// Transforms the picked entities in place, or adds transformed copies.
fn apply(it: &mut Interp, cmd: &str, picked: &[u64], m: &DMat4, copy: bool) -> Result<(), Exn> {
    let d = it.ext::<Drawing>();
    for &h in picked {
        let Some(e) = d.get(h).filter(|_| !d.is_deleted(h)).cloned() else {
            continue;
        };
        let kind = transform_entity(&e.kind, m).map_err(|x| cmd_err(cmd, x))?;
        if copy {
            let mut n = Entity::new(&e.layer, kind);
            n.color = e.color;
            let made = d.add(n).map_err(|x| cmd_err(cmd, x))?;
            d.copy_props(h, made);
        } else {
            d.replace(h, Entity { kind, ..e })
                .map_err(|x| cmd_err(cmd, x))?;
        }
    }
    Ok(())
}
