//! Writing a drawing that was opened from a DXF file: every section as it was read, the
//! entities from the drawing. An entity still equal to what was read is written from its
//! groups; one whose layer or colour changed has those groups patched; one whose geometry
//! changed, and every new one, is written from the model (keeping its handle, owner,
//! extended data and reactors). The layer table follows the drawing's layers. The file is
//! in the version and code page it was read in (a binary file comes back as ASCII).

use super::document::{DxfDocument, Section};
use super::drawing::{Drawing, Entity, EntityKind, SourceRecord};
use super::dxf::{write_entity, DxfWriter};
use super::record::TagList;
use crate::output::Layer;

/// The opened drawing as DXF bytes in its own version and encoding.
pub fn write_opened(d: &Drawing, doc: &DxfDocument) -> Vec<u8> {
    let mut next = d.next_handle();
    let mut alloc = || {
        let h = next;
        next += 1;
        h
    };
    let owner = doc.model_space_owner().unwrap_or(0);
    let mut ents = String::with_capacity(1 << 16);
    // Entities of the other layouts go back into their layout blocks.
    let mut in_blocks: Vec<(usize, String)> = Vec::new();
    for (e, src) in d.entities_with_sources() {
        match src.and_then(|s| s.block) {
            Some(b) => {
                let mut s = String::new();
                write_one(&mut s, e, src, doc, owner, &mut alloc);
                match in_blocks.iter_mut().find(|(i, _)| *i == b) {
                    Some((_, text)) => text.push_str(&s),
                    None => in_blocks.push((b, s)),
                }
            }
            None => match d.new_entity_xdata(e.handle).filter(|_| src.is_none()) {
                None if src.is_some() || d.props(e.handle).is_none() => {
                    write_one(&mut ents, e, src, doc, owner, &mut alloc)
                }
                x => {
                    let mut s = String::new();
                    write_one(&mut s, e, src, doc, owner, &mut alloc);
                    // CHPROP's line type, weight... of a new entity.
                    let s = d.with_props(e.handle, &e.kind, s);
                    match x {
                        Some(x) => ents.push_str(&super::objects::splice_xdata(&s, x, true)),
                        None => ents.push_str(&s),
                    }
                }
            },
        }
    }
    let layers = layer_records(d, doc, &mut alloc);
    let styles = new_style_records(d, doc, &mut alloc);
    let linetypes = new_linetype_records(d, doc, &mut alloc);
    let handseed = format!("{:X}", alloc());

    let mut out = String::with_capacity(ents.len() + (1 << 16));
    let begin = |out: &mut String, name: &str| {
        out.push_str("  0\nSECTION\n  2\n");
        out.push_str(name);
        out.push('\n');
    };
    for s in &doc.sections {
        match s {
            Section::Header(h) => {
                begin(&mut out, "HEADER");
                let mut after_seed = false;
                for (c, v) in h.iter() {
                    let v = if after_seed && c == 5 { &handseed } else { v };
                    after_seed = c == 9 && v == "$HANDSEED";
                    push_group(&mut out, c, v);
                }
            }
            Section::Tables(ts) => {
                begin(&mut out, "TABLES");
                for t in ts {
                    if t.name.eq_ignore_ascii_case("LAYER") {
                        if layers == t.records {
                            t.head.write_to(&mut out);
                        } else {
                            t.head
                                .with(70, &layers.len().to_string(), 2)
                                .write_to(&mut out);
                        }
                        for r in &layers {
                            r.write_to(&mut out);
                        }
                    } else if let Some(added) = [("STYLE", &styles), ("LTYPE", &linetypes)]
                        .into_iter()
                        .find(|(n, a)| t.name.eq_ignore_ascii_case(n) && !a.is_empty())
                        .map(|(_, a)| a)
                    {
                        let n = t.records.len() + added.len();
                        t.head.with(70, &n.to_string(), 2).write_to(&mut out);
                        for r in t.records.iter().chain(added) {
                            r.write_to(&mut out);
                        }
                    } else {
                        t.head.write_to(&mut out);
                        for r in &t.records {
                            r.write_to(&mut out);
                        }
                    }
                    t.end.write_to(&mut out);
                }
            }
            Section::Entities => {
                begin(&mut out, "ENTITIES");
                out.push_str(&ents);
            }
            Section::Other { name, records } => {
                begin(&mut out, name);
                let blocks = name == "BLOCKS";
                for (i, r) in records.iter().enumerate() {
                    r.write_to(&mut out);
                    if let Some((_, text)) = in_blocks.iter().find(|(b, _)| blocks && *b == i) {
                        out.push_str(text);
                    }
                }
            }
        }
        out.push_str("  0\nENDSEC\n");
    }
    out.push_str("  0\nEOF\n");
    encode(out, doc)
}

fn push_group(out: &mut String, code: i32, value: &str) {
    use std::fmt::Write as _;
    let _ = writeln!(out, "{code:>3}");
    out.push_str(value);
    out.push('\n');
}

/// The text in the document's encoding: UTF-8 from R2007, else its code page with
/// AutoCAD's `\U+XXXX` escapes for characters the code page lacks.
pub fn encode(s: String, doc: &DxfDocument) -> Vec<u8> {
    if s.is_ascii() || doc.encoding == encoding_rs::UTF_8 {
        return s.into_bytes();
    }
    let mut enc = doc.encoding.new_encoder();
    let mut out = Vec::with_capacity(s.len() + 16);
    let mut src = s.as_str();
    loop {
        let need = enc
            .max_buffer_length_from_utf8_without_replacement(src.len())
            .unwrap_or(src.len() * 4 + 16);
        let start = out.len();
        out.resize(start + need, 0);
        let (res, read, written) =
            enc.encode_from_utf8_without_replacement(src, &mut out[start..], true);
        out.truncate(start + written);
        src = &src[read..];
        match res {
            encoding_rs::EncoderResult::InputEmpty => break,
            encoding_rs::EncoderResult::Unmappable(c) => {
                let cp = c as u32;
                if cp <= 0xFFFF {
                    out.extend_from_slice(format!("\\U+{cp:04X}").as_bytes());
                } else {
                    out.push(b'?');
                }
            }
            encoding_rs::EncoderResult::OutputFull => {}
        }
    }
    out
}

/// Whether the entity still is what was read (handle included: an imported entity gets a
/// new one).
fn same_geometry(e: &Entity, s: &SourceRecord) -> bool {
    e.kind == s.original.kind && e.handle == s.original.handle
}

fn write_one(
    out: &mut String,
    e: &Entity,
    src: Option<&SourceRecord>,
    doc: &DxfDocument,
    model: u64,
    alloc: &mut impl FnMut() -> u64,
) {
    if let Some(s) = src {
        let unmodelled = matches!(e.kind, EntityKind::Unmodelled { .. });
        if same_geometry(e, s) || unmodelled {
            if e.layer == s.original.layer && e.color == s.original.color && same_geometry(e, s) {
                s.tags.write_to(out);
                return;
            }
            let mut t = s.tags.clone();
            if e.layer != s.original.layer {
                t = followers_on_layer(&t.with(8, &e.layer, 100), &e.layer);
            }
            if e.color != s.original.color {
                t = match e.color {
                    Some(c) => t.with(62, &c.to_string(), 8),
                    None => t.with(62, "256", 8),
                };
            }
            if e.handle != s.original.handle {
                t = t.with(5, &format!("{:X}", e.handle), 0);
                if !doc.is_r12() {
                    t = t.with(330, &format!("{model:X}"), 5);
                }
                t = renumber_followers(&t, e.handle, alloc);
            }
            t.write_to(out);
            return;
        }
    }
    let owner = src
        .and_then(|s| s.tags.get(330))
        .filter(|_| src.is_some_and(|s| s.original.handle == e.handle))
        .and_then(|v| u64::from_str_radix(v.trim(), 16).ok())
        .unwrap_or(model);
    let r12_kind;
    let e = if doc.is_r12() {
        r12_kind = r12_entity(e);
        &r12_kind
    } else {
        e
    };
    let mut w = DxfWriter::new();
    w.raw_text = true;
    write_entity(&mut w, e, owner, alloc);
    if src.is_none() && !doc.is_r12() {
        out.push_str(&w.out);
        return;
    }
    let mut t = TagList::from_dxf_text(&w.out);
    if let Some(s) = src {
        t = match super::dxf_merge::merge_changed(&s.tags, &t, e, &s.original) {
            Some(m) => followers_on_layer(&m, &e.layer),
            None => keep_from_original(&t, &s.tags),
        };
    }
    if doc.is_r12() {
        t = r12_groups(&t);
    }
    t.write_to(out);
}

/// R12 has no LWPOLYLINE: a flat one becomes a 2D POLYLINE.
fn r12_entity(e: &Entity) -> Entity {
    let mut e = e.clone();
    if let EntityKind::LwPolyline {
        points,
        bulges,
        closed,
        elevation,
        normal,
    } = &e.kind
    {
        let ocs = crate::geom::frame::Ocs::new(*normal);
        e.kind = EntityKind::Polyline {
            points: points.iter().map(|p| ocs.to_wcs(*p, *elevation)).collect(),
            bulges: bulges.clone(),
            closed: *closed,
        };
    }
    e
}

/// Groups R12 does not know: subclass markers, owners, application data.
fn r12_groups(t: &TagList) -> TagList {
    let mut out = TagList::new();
    let mut in_app = false;
    for (c, v) in t.iter() {
        if c == 102 {
            in_app = v.starts_with('{');
            continue;
        }
        if in_app || c == 100 || c == 330 || c == 360 {
            continue;
        }
        out.push(c, v);
    }
    out
}

/// A re-written entity keeps what the model does not hold from its original groups:
/// application data (reactors, extension dictionary) after the handle, the AcDbEntity
/// groups lispcad does not write (paper space, line type, weight...) after the layer, and
/// the extended data at the end.
fn keep_from_original(new: &TagList, orig: &TagList) -> TagList {
    const ENTITY_GROUPS: [i32; 10] = [67, 410, 6, 48, 60, 370, 420, 430, 440, 284];
    let first = orig.first_record_end();
    let head: Vec<(i32, &str)> = (0..first).map(|i| orig.at(i)).collect();
    let mut app = Vec::new();
    let mut in_app = false;
    for (c, v) in &head {
        if *c == 102 {
            in_app = v.starts_with('{');
            app.push((*c, *v));
        } else if in_app {
            app.push((*c, *v));
        }
    }
    let xdata_at = head
        .iter()
        .position(|(c, _)| *c >= 1000)
        .unwrap_or(head.len());
    let entity_groups: Vec<(i32, &str)> = head[..xdata_at]
        .iter()
        .filter(|(c, _)| ENTITY_GROUPS.contains(c))
        .copied()
        .collect();
    let new_first = new.first_record_end();
    let mut out = TagList::new();
    for i in 0..new.len() {
        let (c, v) = new.at(i);
        out.push(c, v);
        if i == 1 && c == 5 {
            for (c, v) in &app {
                out.push(*c, v);
            }
        }
        if c == 8 && i < new_first {
            for (c, v) in &entity_groups {
                out.push(*c, v);
            }
        }
        if i + 1 == new_first {
            for (c, v) in &head[xdata_at..] {
                out.push(*c, v);
            }
        }
    }
    out
}

/// The LAYER table's records for the drawing's layers: a layer read from the file keeps its
/// record (colour, line type and flags patched if changed); a new one is a copy of layer
/// "0"'s record (so it names the same plot style) with its own name, handle and values.
fn layer_records(d: &Drawing, doc: &DxfDocument, alloc: &mut impl FnMut() -> u64) -> Vec<TagList> {
    let old = doc.table_records("LAYER");
    let find = |name: &str| {
        old.iter()
            .find(|r| r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(name)))
    };
    let template = find("0").or(old.first());
    d.layers()
        .iter()
        // Layer "0" exists in every drawing: a file without its record stays without it.
        .filter(|l| find(&l.name).is_some() || l.name != "0" || **l != Layer::new("0"))
        .map(|l| match find(&l.name) {
            Some(r) => patch_layer(r, l),
            None => {
                let mut r = match template {
                    Some(t) => t.clone(),
                    None => {
                        let mut t = TagList::new();
                        t.push(0, "LAYER");
                        t.push(2, "0");
                        t.push(70, "0");
                        t.push(62, "7");
                        t.push(6, "Continuous");
                        t
                    }
                };
                if r.get(5).is_some() {
                    r = r.with(5, &format!("{:X}", alloc()), 0);
                }
                r = r.with(2, &l.name, 100);
                patch_layer(&r, l)
            }
        })
        .collect()
}

fn patch_layer(r: &TagList, l: &Layer) -> TagList {
    let old = super::dxfin::factory::layer(r);
    if old.as_ref() == Some(l) {
        return r.clone();
    }
    let flags: i64 = r.get(70).and_then(|v| v.trim().parse().ok()).unwrap_or(0);
    let flags = (flags & !5) | l.frozen as i64 | ((l.locked as i64) << 2);
    r.with(70, &flags.to_string(), 2)
        .with(62, &l.color.to_string(), 70)
        .with(6, &l.linetype, 62)
}

/// STYLE records for the text styles the drawing's TEXT entities name and the file lacks:
/// copies of its "Standard" record (same font and settings) under the new name, so no TEXT
/// names a style that does not exist.
fn new_style_records(
    d: &Drawing,
    doc: &DxfDocument,
    alloc: &mut impl FnMut() -> u64,
) -> Vec<TagList> {
    let old = doc.table_records("STYLE");
    let Some(template) = old
        .iter()
        .find(|r| r.get(2).is_some_and(|n| n.eq_ignore_ascii_case("Standard")))
        .or(old.first())
    else {
        return Vec::new();
    };
    let mut names: Vec<&str> = Vec::new();
    for e in d.entities() {
        if let EntityKind::Text { style, .. } = &e.kind {
            let known = |n: &str| n.eq_ignore_ascii_case(style);
            if !style.is_empty()
                && !old.iter().any(|r| r.get(2).is_some_and(known))
                && !names.iter().any(|n| known(n))
            {
                names.push(style);
            }
        }
    }
    names
        .into_iter()
        .map(|name| {
            let mut r = without_app_data(template).with(2, name, 100);
            if r.get(5).is_some() {
                r = r.with(5, &format!("{:X}", alloc()), 0);
            }
            r
        })
        .collect()
}

/// LTYPE records for the line types the drawing's layers name and the file lacks (a layer
/// made by a script): solid ones, copies of the file's "Continuous" record under the new
/// name, as the writer of new drawings defines them.
fn new_linetype_records(
    d: &Drawing,
    doc: &DxfDocument,
    alloc: &mut impl FnMut() -> u64,
) -> Vec<TagList> {
    let old = doc.table_records("LTYPE");
    let Some(template) = old.iter().find(|r| {
        r.get(2)
            .is_some_and(|n| n.eq_ignore_ascii_case("Continuous"))
    }) else {
        return Vec::new();
    };
    let mut names: Vec<&str> = Vec::new();
    for l in d.layers() {
        let known = |n: &str| n.eq_ignore_ascii_case(&l.linetype);
        let builtin = ["ByLayer", "ByBlock", "Continuous"].into_iter().any(known);
        if !builtin
            && !old.iter().any(|r| r.get(2).is_some_and(known))
            && !names.iter().any(|n| known(n))
        {
            names.push(&l.linetype);
        }
    }
    names
        .into_iter()
        .map(|name| {
            let mut r = without_app_data(template).with(2, name, 100);
            if r.get(5).is_some() {
                r = r.with(5, &format!("{:X}", alloc()), 0);
            }
            r
        })
        .collect()
}

/// A record minus its application data (reactors, extension dictionary) and extended data,
/// which belong to the record it was copied from.
fn without_app_data(r: &TagList) -> TagList {
    let mut out = TagList::new();
    let mut in_app = false;
    for (c, v) in r.iter() {
        if c == 102 {
            in_app = v.starts_with('{');
            continue;
        }
        if !in_app && c < 1000 {
            out.push(c, v);
        }
    }
    out
}

/// An imported entity's ATTRIB/VERTEX/SEQEND followers: fresh handles, owned by their
/// entity's new handle (their old ones belong to the file they came from).
fn renumber_followers(t: &TagList, parent: u64, alloc: &mut impl FnMut() -> u64) -> TagList {
    let first = t.first_record_end();
    let mut out = TagList::new();
    let mut in_app = false;
    let mut record_start = 0;
    for (i, (c, v)) in t.iter().enumerate() {
        if c == 0 {
            record_start = i;
            in_app = false;
        }
        if i < first {
            out.push(c, v);
            continue;
        }
        if c == 102 {
            in_app = v.starts_with('{');
        }
        match c {
            5 if i == record_start + 1 => out.push(5, &format!("{:X}", alloc())),
            330 if !in_app => out.push(330, &format!("{parent:X}")),
            _ => out.push(c, v),
        }
    }
    out
}

/// A POLYLINE's VERTEX and SEQEND records, and an INSERT's SEQEND, on their entity's layer
/// (AutoCAD keeps them there, and ezdxf's audit moves them back); an INSERT's ATTRIBs keep
/// their own, as AutoCAD's CHPROP leaves them.
fn followers_on_layer(t: &TagList, layer: &str) -> TagList {
    let first = t.first_record_end();
    let mut out = TagList::new();
    let mut follows = false;
    for (i, (c, v)) in t.iter().enumerate() {
        if c == 0 {
            follows = i >= first && matches!(v, "VERTEX" | "SEQEND");
        }
        if follows && c == 8 {
            out.push(8, layer);
        } else {
            out.push(c, v);
        }
    }
    out
}
