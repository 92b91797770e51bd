//! INSERT / -INSERT of a block the opened drawing defines: block name, insertion point, X
//! and Y scale (Enter: 1, and Y = X), rotation in degrees (Enter: 0), then one value per
//! ATTDEF of the block in its order (Enter: the ATTDEF's default), as AutoCAD prompts with
//! ATTREQ 1 and ATTDIA 0. The INSERT, its ATTRIBs and SEQEND are added as DXF groups (lispcad
//! keeps block references as read), so `entget`/`entnext` and the DXF writer see them as
//! those of a read file. A drawing made from scratch has no block definitions: an error.

use glam::{DVec2, DVec3};

use super::{cmd_err, unexpected, Input, Pending, Step};
use crate::lang::error::Exn;
use crate::lang::{Interp, Value};
use crate::output::drawing::SourceRecord;
use crate::output::dxf::push_float;
use crate::output::record::TagList;
use crate::output::{Drawing, Entity, EntityKind};

/// An ATTDEF of the block: tag, default value, position (block coordinates), height,
/// rotation (degrees), style, layer, flags.
struct AttDef {
    tag: String,
    default: String,
    at: DVec3,
    height: f64,
    rotation: f64,
    style: Option<String>,
    layer: String,
    flags: String,
}

pub(crate) struct InsertCmd {
    block: Option<(String, DVec3, Vec<AttDef>)>,
    point: Option<DVec3>,
    xscale: Option<f64>,
    yscale: Option<f64>,
    rotation: Option<f64>,
    values: Vec<String>,
}

fn num(v: Option<&str>) -> f64 {
    v.and_then(|s| s.trim().parse().ok()).unwrap_or(0.0)
}

/// The block's base point and ATTDEFs, from the opened drawing's BLOCKS section.
fn block_def(d: &Drawing, name: &str) -> Result<(String, DVec3, Vec<AttDef>), Exn> {
    if d.document().is_some_and(|doc| doc.is_r12()) {
        return Err(cmd_err(
            "INSERT",
            format!("block \"{name}\": lispcad inserts blocks into R2000 and later drawings only"),
        ));
    }
    let recs = d.block_section();
    let start = recs
        .iter()
        .position(|r| {
            r.type_name() == "BLOCK" && r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(name))
        })
        .ok_or_else(|| cmd_err("INSERT", format!("block \"{name}\" is not defined")))?;
    let b = &recs[start];
    let base = DVec3::new(num(b.get(10)), num(b.get(20)), num(b.get(30)));
    let mut defs = Vec::new();
    for r in recs[start + 1..]
        .iter()
        .take_while(|r| r.type_name() != "ENDBLK")
    {
        if r.type_name() != "ATTDEF" {
            continue;
        }
        defs.push(AttDef {
            tag: r.get(2).unwrap_or("").to_string(),
            default: r.get(1).unwrap_or("").to_string(),
            at: DVec3::new(num(r.get(10)), num(r.get(20)), num(r.get(30))),
            height: r.get(40).map_or(2.5, |h| num(Some(h))),
            rotation: num(r.get(50)),
            style: r.get(7).map(str::to_string),
            layer: r.get(8).unwrap_or("0").to_string(),
            flags: r.get(70).unwrap_or("0").trim().to_string(),
        });
    }
    Ok((b.get(2).unwrap_or(name).to_string(), base, defs))
}

impl InsertCmd {
    pub(crate) fn new() -> InsertCmd {
        InsertCmd {
            block: None,
            point: None,
            xscale: None,
            yscale: None,
            rotation: None,
            values: Vec::new(),
        }
    }

    pub(crate) fn feed(mut self, it: &mut Interp, input: &Input, raw: &Value) -> Result<Step, Exn> {
        let enter = matches!(input, Input::Enter);
        let number = |input: &Input| match input {
            Input::Number(x) => Some(*x),
            _ => None,
        };
        if self.block.is_none() {
            let name = input
                .name(raw)
                .map(|s| s.trim().to_string())
                .filter(|s| !s.is_empty())
                .ok_or_else(|| unexpected("INSERT", "a block name", input))?;
            if name.contains(['/', '\\', '.']) {
                return Err(cmd_err(
                    "INSERT",
                    format!("inserting a drawing file (\"{name}\") is not supported; name a block of the opened drawing"),
                ));
            }
            self.block = Some(block_def(it.ext::<Drawing>(), &name)?);
        } else if self.point.is_none() {
            match input {
                Input::Point(p) => self.point = Some(*p),
                _ => return Err(unexpected("INSERT", "an insertion point", input)),
            }
        } else if self.xscale.is_none() {
            self.xscale = Some(if enter {
                1.0
            } else {
                number(input)
                    .filter(|x| *x != 0.0)
                    .ok_or_else(|| unexpected("INSERT", "an X scale factor or \"\"", input))?
            });
        } else if self.yscale.is_none() {
            self.yscale = Some(if enter {
                self.xscale.unwrap_or(1.0)
            } else {
                number(input)
                    .filter(|x| *x != 0.0)
                    .ok_or_else(|| unexpected("INSERT", "a Y scale factor or \"\"", input))?
            });
        } else if self.rotation.is_none() {
            self.rotation = Some(if enter {
                0.0
            } else {
                number(input)
                    .ok_or_else(|| unexpected("INSERT", "a rotation angle or \"\"", input))?
            });
        } else {
            let value = if enter {
                None
            } else {
                Some(
                    input
                        .name(raw)
                        .or_else(|| number(input).map(|x| x.to_string()))
                        .ok_or_else(|| unexpected("INSERT", "an attribute value", input))?,
                )
            };
            let i = self.values.len();
            let default = self
                .block
                .as_ref()
                .map_or(String::new(), |b| b.2[i].default.clone());
            self.values.push(value.unwrap_or(default));
        }
        let wanted = self.block.as_ref().map_or(0, |b| b.2.len());
        if self.rotation.is_some() && self.values.len() == wanted {
            self.add(it)?;
            return Ok(Step::Done);
        }
        Ok(Step::More(Pending::Insert(self)))
    }

    /// Adds the INSERT with its ATTRIBs and SEQEND.
    fn add(self, it: &mut Interp) -> Result<(), Exn> {
        let (Some((name, base, defs)), Some(p), Some(sx), Some(sy), Some(rot)) = (
            self.block,
            self.point,
            self.xscale,
            self.yscale,
            self.rotation,
        ) else {
            return Ok(());
        };
        let d = it.ext::<Drawing>();
        let owner = d.model_space_record();
        let layer = d.current_layer().to_string();
        let h = d.next_handle();
        let hex = |h: u64| format!("{h:X}");
        let f = |x: f64| {
            let mut s = String::new();
            push_float(&mut s, x);
            s
        };
        let mut t = TagList::new();
        let head = |t: &mut TagList, ty: &str, me: u64, own: u64, layer: &str| {
            t.push(0, ty);
            t.push(5, &hex(me));
            t.push(330, &hex(own));
            t.push(100, "AcDbEntity");
            t.push(8, layer);
        };
        head(&mut t, "INSERT", h, owner, &layer);
        t.push(100, "AcDbBlockReference");
        if !defs.is_empty() {
            t.push(66, "1");
        }
        t.push(2, &name);
        for (c, x) in [
            (10, p.x),
            (20, p.y),
            (30, p.z),
            (41, sx),
            (42, sy),
            (43, sx),
        ] {
            t.push(c, &f(x));
        }
        t.push(50, &f(rot));
        let turn = DVec2::from_angle(rot.to_radians());
        for (i, (a, value)) in defs.iter().zip(&self.values).enumerate() {
            let local = (a.at - base).truncate() * DVec2::new(sx, sy);
            let at = p.truncate() + turn.rotate(local);
            let att_layer = if a.layer == "0" { &layer } else { &a.layer };
            head(&mut t, "ATTRIB", h + 1 + i as u64, h, att_layer);
            t.push(100, "AcDbText");
            for (c, x) in [(10, at.x), (20, at.y), (30, p.z + a.at.z - base.z)] {
                t.push(c, &f(x));
            }
            t.push(40, &f(a.height * sy.abs()));
            t.push(1, value);
            t.push(50, &f(a.rotation + rot));
            if let Some(s) = &a.style {
                t.push(7, s);
            }
            t.push(100, "AcDbAttribute");
            t.push(2, &a.tag);
            t.push(70, &a.flags);
        }
        if !defs.is_empty() {
            head(&mut t, "SEQEND", h + 1 + defs.len() as u64, h, &layer);
        }
        let e = Entity {
            handle: h,
            layer,
            color: None,
            kind: EntityKind::Unmodelled {
                dxf_type: "INSERT".to_string(),
            },
        };
        let source = SourceRecord {
            tags: t,
            original: e.clone(),
            block: None,
        };
        d.push_loaded(e, Some(source));
        // The followers' handles.
        for _ in 0..defs.len() + usize::from(!defs.is_empty()) {
            d.alloc_handle();
        }
        Ok(())
    }
}
