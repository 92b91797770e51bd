//! `entmake` of block definitions and block references, with AutoCAD's protocol:
//! a BLOCK list opens a definition, the entities made after it are held in it, and ENDBLK
//! defines the block and returns its name (an anonymous block, 70 bit 1, gets the next
//! free `*U<n>`). An INSERT with (66 . 1) is held until its ATTRIBs and SEQEND have come.
//! A list out of sequence (ENDBLK without BLOCK, a BLOCK inside a definition, anything but
//! ATTRIB or SEQEND after an INSERT with attributes) gives nil and drops what was pending,
//! as `entmake` does for an unfinished POLYLINE. INSERT, ATTDEF and ATTRIB are kept as the
//! DXF groups a file would hold (lispcad does not model them), so `entget`, `entmod`, the
//! INSERT and EXPLODE commands and the DXF writers treat them as those of an opened file.

use glam::DVec3;

use super::dxf_list::Groups;
use super::EntityState;
use crate::builtins::drawing::drawing;
use crate::builtins::system::SysVars;
use crate::lang::error::Exn;
use crate::lang::{Interp, Value};
use crate::output::blocks::BlockDef;
use crate::output::drawing::SourceRecord;
use crate::output::dxf::{write_entity, DxfWriter};
use crate::output::dxf_writer::push_float;
use crate::output::record::TagList;
use crate::output::{Entity, EntityKind};

/// A block definition between its BLOCK and ENDBLK.
pub struct PendingBlock {
    /// The handle of its BLOCK_RECORD: the owner of its entities.
    record: u64,
    name: String,
    flags: i32,
    base: DVec3,
    layer: String,
    body: Vec<TagList>,
}

/// An INSERT with (66 . 1) waiting for its ATTRIBs and SEQEND.
pub struct PendingInsert {
    handle: u64,
    layer: String,
    color: Option<i16>,
    tags: TagList,
    attribs: usize,
}

fn real(x: f64) -> String {
    let mut s = String::new();
    push_float(&mut s, x);
    s
}

fn hex(h: u64) -> String {
    format!("{h:X}")
}

/// Whether a block definition is open (entities go into it).
pub fn in_block(it: &mut Interp) -> bool {
    it.ext::<EntityState>().pending_block.is_some()
}

/// Drop whatever is pending: `(entmake)` with no list, or a list out of sequence.
pub fn cancel(it: &mut Interp) {
    let st = it.ext::<EntityState>();
    st.pending_block = None;
    st.pending_insert = None;
}

fn valid_block_name(name: &str) -> bool {
    !name.is_empty()
        && !name
            .chars()
            .any(|c| "<>/\\\":;?*|,=`".contains(c) || c.is_control())
}

/// BLOCK: 2 name, 10 base point (required), 70 flags, 8 layer (default "0").
pub fn block(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    if in_block(it) {
        cancel(it);
        return Ok(false);
    }
    let (Some(name), Some(base)) = (g.string(it, 2)?, g.point(it, 10)?) else {
        return Ok(false);
    };
    let mut flags = g.int(it, 70)?.unwrap_or(0);
    let anonymous = flags & 1 != 0 || name.starts_with('*');
    if anonymous {
        flags |= 1;
    } else if !valid_block_name(&name) || name.len() > 255 {
        return Ok(false);
    }
    let layer = g.string(it, 8)?.unwrap_or_else(|| "0".to_string());
    let d = drawing(it);
    if d.ensure_layer(&layer).is_err() {
        return Ok(false);
    }
    let record = match d.block_record_handle(&name).filter(|_| !anonymous) {
        Some(h) => h,
        None => d.alloc_handle(),
    };
    it.ext::<EntityState>().pending_block = Some(PendingBlock {
        record,
        name,
        flags,
        base,
        layer,
        body: Vec::new(),
    });
    Ok(true)
}

/// ENDBLK: defines the pending block; its name, or nil when none is pending.
pub fn endblk(it: &mut Interp) -> Result<Value, Exn> {
    let Some(mut b) = it.ext::<EntityState>().pending_block.take() else {
        cancel(it);
        return Ok(Value::Nil);
    };
    if it.ext::<EntityState>().pending_insert.take().is_some() {
        return Ok(Value::Nil);
    }
    let d = drawing(it);
    if b.flags & 1 != 0 {
        let n = (1..).find(|n| !d.has_block(&format!("*U{n}"))).unwrap_or(1);
        b.name = format!("*U{n}");
    }
    // Bit 2: the block has attributes that are not constant (70 bit 2 of their ATTDEF).
    let variable_attdefs = b.body.iter().any(|t| {
        t.type_name() == "ATTDEF"
            && t.get(70)
                .and_then(|v| v.trim().parse::<i32>().ok())
                .is_none_or(|f| f & 2 == 0)
    });
    if variable_attdefs {
        b.flags |= 2;
    }
    let name = b.name.clone();
    let def = BlockDef {
        record: b.record,
        name: b.name,
        flags: b.flags,
        base: b.base,
        layer: b.layer,
        body: b.body,
    };
    match d.define_block(def) {
        Ok(()) => Ok(Value::str(&name)),
        Err(m) => Err(crate::lang::error::err(format!("entmake: {m}"))),
    }
}

/// Where the next entity goes: the owner handle (the open block's record, or model space).
fn owner(it: &mut Interp) -> u64 {
    match &it.ext::<EntityState>().pending_block {
        Some(b) => b.record,
        None => drawing(it).model_space_record(),
    }
}

/// A modelled entity made while a block is open: its groups go into the block. Its handle.
pub fn add_to_block(it: &mut Interp, e: Entity, xdata: Option<TagList>) -> Option<u64> {
    e.kind.validate().ok()?;
    let rec = owner(it);
    let d = drawing(it);
    let mut e = e;
    e.layer = d.ensure_layer(&e.layer).ok()?;
    e.handle = d.alloc_handle();
    let h = e.handle;
    let mut w = DxfWriter::new();
    w.raw_text = true;
    write_entity(&mut w, &e, rec, &mut || d.alloc_handle());
    let text = match &xdata {
        Some(x) => crate::output::objects::splice_xdata(&w.out, x, true),
        None => w.out,
    };
    let tags = TagList::from_dxf_text(&text);
    it.ext::<EntityState>()
        .pending_block
        .as_mut()?
        .body
        .push(tags);
    Some(h)
}

/// The groups of an INSERT, ATTDEF or ATTRIB list as a file holds them (subclass markers,
/// angles in degrees, points as x/y/z groups); None when a required group is missing.
fn kept_tags(
    it: &mut Interp,
    ty: &str,
    g: &Groups,
    handle: u64,
    owner: u64,
    layer: &str,
    color: Option<i16>,
) -> Result<Option<TagList>, Exn> {
    const TEXT: &[i32] = &[39, 10, 40, 1, 50, 41, 51, 7, 71, 72, 11, 210];
    let (spec, required): (&[(&str, &[i32])], &[i32]) = match ty {
        "INSERT" => (
            &[(
                "AcDbBlockReference",
                &[66, 2, 10, 41, 42, 43, 50, 70, 71, 44, 45, 210],
            )],
            &[2, 10],
        ),
        "ATTDEF" => (
            &[
                ("AcDbText", TEXT),
                ("AcDbAttributeDefinition", &[3, 2, 70, 73, 74]),
            ],
            &[1, 2, 3, 10],
        ),
        _ => (
            &[("AcDbText", TEXT), ("AcDbAttribute", &[2, 70, 73, 74])],
            &[1, 2, 10],
        ),
    };
    if required.iter().any(|c| !g.has(*c)) {
        return Ok(None);
    }
    let mut t = TagList::new();
    t.push(0, ty);
    t.push(5, &hex(handle));
    t.push(330, &hex(owner));
    t.push(100, "AcDbEntity");
    t.push(8, layer);
    if let Some(c) = color {
        t.push(62, &c.to_string());
    }
    for (marker, codes) in spec {
        t.push(100, marker);
        for &c in *codes {
            if matches!(c, 10 | 11 | 210) {
                if let Some(p) = g.point(it, c)? {
                    t.push(c, &real(p.x));
                    t.push(c + 10, &real(p.y));
                    t.push(c + 20, &real(p.z));
                }
                continue;
            }
            let v = match g.get(c) {
                Some(v) => v.clone(),
                // Text height defaults to TEXTSIZE, as for TEXT.
                None if c == 40 && ty != "INSERT" => {
                    Value::Real(it.ext::<SysVars>().real("TEXTSIZE"))
                }
                None => continue,
            };
            for (code, text) in super::tag_list::group_texts(it, c, &v, ty)? {
                t.push(code, &text);
            }
        }
    }
    Ok(Some(t))
}

/// The layer (default CLAYER, created if missing) and colour of a kept entity; None when
/// either is invalid.
fn layer_color(it: &mut Interp, g: &Groups) -> Result<Option<(String, Option<i16>)>, Exn> {
    let color = match g.int(it, 62)? {
        None | Some(256) => None,
        Some(c) if (0..=255).contains(&c) => Some(c as i16),
        Some(_) => return Ok(None),
    };
    let layer = match g.string(it, 8)? {
        Some(l) => l,
        None => super::make::current_layer(it),
    };
    Ok(drawing(it).ensure_layer(&layer).ok().map(|l| (l, color)))
}

/// Puts a finished INSERT (with its followers) or ATTDEF in the open block or the drawing.
fn place(
    it: &mut Interp,
    ty: &str,
    handle: u64,
    layer: String,
    color: Option<i16>,
    tags: TagList,
) -> bool {
    if let Some(b) = it.ext::<EntityState>().pending_block.as_mut() {
        b.body.push(tags);
        return true;
    }
    let e = Entity {
        handle,
        layer,
        color,
        kind: EntityKind::Unmodelled {
            dxf_type: ty.to_string(),
        },
    };
    let source = SourceRecord {
        tags,
        original: e.clone(),
        block: None,
    };
    drawing(it).push_loaded(e, Some(source));
    true
}

/// INSERT: 2 block name (defined, and not the one being defined), 10 insertion point,
/// 41–43 scale (non-zero), 50 rotation; with (66 . 1) it waits for ATTRIBs and SEQEND.
pub fn insert(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    let Some(name) = g.string(it, 2)? else {
        return Ok(false);
    };
    let inside_itself = it
        .ext::<EntityState>()
        .pending_block
        .as_ref()
        .is_some_and(|b| b.name.eq_ignore_ascii_case(&name));
    let layout = name.to_ascii_uppercase();
    if inside_itself
        || !drawing(it).has_block(&name)
        || layout.starts_with("*MODEL_SPACE")
        || layout.starts_with("*PAPER_SPACE")
    {
        return Ok(false);
    }
    for c in [41, 42, 43] {
        if g.real(it, c)? == Some(0.0) {
            return Ok(false);
        }
    }
    let Some((layer, color)) = layer_color(it, g)? else {
        return Ok(false);
    };
    let own = owner(it);
    let handle = drawing(it).alloc_handle();
    let Some(tags) = kept_tags(it, "INSERT", g, handle, own, &layer, color)? else {
        return Ok(false);
    };
    if g.int(it, 66)? == Some(1) {
        it.ext::<EntityState>().pending_insert = Some(PendingInsert {
            handle,
            layer,
            color,
            tags,
            attribs: 0,
        });
        return Ok(true);
    }
    Ok(place(it, "INSERT", handle, layer, color, tags))
}

/// ATTDEF: in a block definition (or model space): 1 default, 2 tag, 3 prompt, 10 point.
pub fn attdef(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    let Some((layer, color)) = layer_color(it, g)? else {
        return Ok(false);
    };
    let own = owner(it);
    let handle = drawing(it).alloc_handle();
    let Some(tags) = kept_tags(it, "ATTDEF", g, handle, own, &layer, color)? else {
        return Ok(false);
    };
    Ok(place(it, "ATTDEF", handle, layer, color, tags))
}

/// ATTRIB after an INSERT with (66 . 1): 1 value, 2 tag, 10 point.
pub fn attrib(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    let Some(parent) = it
        .ext::<EntityState>()
        .pending_insert
        .as_ref()
        .map(|p| p.handle)
    else {
        return Ok(false);
    };
    let Some((layer, color)) = layer_color(it, g)? else {
        return Ok(false);
    };
    let handle = drawing(it).alloc_handle();
    let Some(tags) = kept_tags(it, "ATTRIB", g, handle, parent, &layer, color)? else {
        return Ok(false);
    };
    if let Some(p) = it.ext::<EntityState>().pending_insert.as_mut() {
        for (c, v) in tags.iter() {
            p.tags.push(c, v);
        }
        p.attribs += 1;
    }
    Ok(true)
}

/// SEQEND after an INSERT's ATTRIBs: the INSERT is made.
pub fn seqend(it: &mut Interp) -> Result<bool, Exn> {
    let Some(mut p) = it.ext::<EntityState>().pending_insert.take() else {
        return Ok(false);
    };
    let h = drawing(it).alloc_handle();
    p.tags.push(0, "SEQEND");
    p.tags.push(5, &hex(h));
    p.tags.push(330, &hex(p.handle));
    p.tags.push(100, "AcDbEntity");
    p.tags.push(8, &p.layer);
    // An INSERT flagged as followed by attributes that has none is written without the flag.
    if p.attribs == 0 {
        let mut t = TagList::new();
        for (c, v) in p.tags.iter().take(p.tags.first_record_end()) {
            if c != 66 {
                t.push(c, v);
            }
        }
        p.tags = t;
    }
    Ok(place(it, "INSERT", p.handle, p.layer, p.color, p.tags))
}
