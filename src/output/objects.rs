//! What a drawing holds besides entities and layers for AutoLISP's extended data, APPID
//! table, dictionaries and XRECORDs.
//!
//! A drawing opened from a file keeps them where the file had them (an entity's own groups,
//! the document's APPID table and OBJECTS section) and they are changed there, so the writer
//! puts them back with no special case. A drawing made from scratch keeps them in `Extras`,
//! and the CAD writer emits them. An object without an owner (made by `entmakex`, or taken
//! out of its dictionary by `dictremove`) lives in `Extras` either way and is not written:
//! AutoCAD does not save an object nothing reaches, and a reader's audit would flag it.

use std::collections::HashMap;

use super::document::Section;
use super::drawing::Drawing;
use super::dxf_writer::DxfWriter;
use super::record::TagList;

/// The fixed handle of the named-object dictionary of a drawing made from scratch.
pub const ROOT_DICT: u64 = 0xA;
/// The fixed handle of its ACAD_GROUP dictionary.
pub const GROUP_DICT: u64 = 0xB;

/// Session state of a drawing's non-graphical data (see the module documentation).
#[derive(Clone, Debug, Default)]
pub struct Extras {
    /// Extended data of entities that were not read from a file: their 1001... groups.
    xdata: HashMap<u64, TagList>,
    /// Applications registered in a drawing made from scratch, besides ACAD.
    appids: Vec<String>,
    /// Objects of a drawing made from scratch, and ownerless objects of any drawing.
    objects: Vec<TagList>,
    /// Handles given to table records of a drawing made from scratch (`tblobjname`):
    /// (table, name, handle).
    table_handles: Vec<(String, String, u64)>,
    /// Block definitions of a drawing made from scratch (`blocks.rs`): their BLOCKS
    /// section records and their BLOCK_RECORD table records.
    pub(super) blocks: Vec<TagList>,
    pub(super) block_records: Vec<TagList>,
    /// Line types, weights, thicknesses and scales CHPROP set (`props.rs`).
    pub(super) props: super::props::PropsMap,
}

impl Extras {
    pub fn is_empty(&self) -> bool {
        self.xdata.is_empty()
            && self.appids.is_empty()
            && self.objects.is_empty()
            && self.table_handles.is_empty()
            && self.blocks.is_empty()
            && self.props.is_empty()
    }

    /// Whether a drawing with these extras can take an opened file's document: the
    /// extended data and applications move into it; its own objects and table handles
    /// cannot yet.
    pub fn is_adoptable(&self) -> bool {
        self.objects.is_empty() && self.table_handles.is_empty()
    }

    /// The registered applications, moved out (into a document's APPID table).
    pub fn take_appids(&mut self) -> Vec<String> {
        std::mem::take(&mut self.appids)
    }
}

/// The extended data of an entity's group list: its first record's groups from the first
/// 1001 on.
pub fn xdata_of(tags: &TagList) -> TagList {
    let end = tags.first_record_end();
    let mut out = TagList::new();
    let mut on = false;
    for i in 0..end {
        let (c, v) = tags.at(i);
        on |= c == 1001;
        if on {
            out.push(c, v);
        }
    }
    out
}

/// The group list with its first record's extended data replaced by `xdata`.
fn with_xdata(tags: &TagList, xdata: &TagList) -> TagList {
    let end = tags.first_record_end();
    let mut out = TagList::new();
    let mut on = false;
    for (i, (c, v)) in tags.iter().enumerate() {
        if i == end {
            for (c, v) in xdata.iter() {
                out.push(c, v);
            }
        }
        on = i < end && (on || c == 1001);
        if !on {
            out.push(c, v);
        }
    }
    if end >= tags.len() {
        for (c, v) in xdata.iter() {
            out.push(c, v);
        }
    }
    out
}

/// One entity's groups as written (`text`, with any followers) with `xdata` after its
/// first record.
pub fn splice_xdata(text: &str, xdata: &TagList, raw_text: bool) -> String {
    let mut w = DxfWriter::new();
    w.raw_text = raw_text;
    for (c, v) in xdata.iter() {
        w.str(c as u16, v);
    }
    let mut at = text.len();
    let mut off = 0;
    let mut lines = text.split_inclusive('\n');
    let mut first = true;
    while let Some(code) = lines.next() {
        if !first && code.trim() == "0" {
            at = off;
            break;
        }
        first = false;
        let Some(v) = lines.next() else { break };
        off += code.len() + v.len();
    }
    format!("{}{}{}", &text[..at], w.out, &text[at..])
}

/// The record's owner: its first 330 group outside application data ({ACAD_REACTORS ...}).
pub fn owner_of(t: &TagList) -> Option<u64> {
    let mut in_app = false;
    for (c, v) in t.iter().take(t.first_record_end()) {
        match c {
            102 => in_app = v.starts_with('{'),
            330 if !in_app => return u64::from_str_radix(v.trim(), 16).ok(),
            _ => {}
        }
    }
    None
}

/// The record with its owner set (the group added after the handle when missing).
pub fn with_owner(t: &TagList, owner: u64) -> TagList {
    let owner = format!("{owner:X}");
    let mut out = TagList::new();
    let mut in_app = false;
    let mut done = false;
    for (i, (c, v)) in t.iter().enumerate() {
        match c {
            102 => in_app = v.starts_with('{'),
            330 if !in_app && !done => {
                out.push(330, &owner);
                done = true;
                continue;
            }
            _ => {}
        }
        out.push(c, v);
        if i == 1 && c == 5 && !t.iter().any(|(c, _)| c == 330) {
            out.push(330, &owner);
            done = true;
        }
    }
    out
}

/// The handles the CAD writer gives the table records of every new drawing (`dxf.rs`).
fn fixed_record_handle(table: &str, name: &str) -> Option<u64> {
    let fixed: [(&str, &str, u64); 7] = [
        ("VPORT", "*Active", 0x17),
        ("LTYPE", "ByBlock", 0x18),
        ("LTYPE", "ByLayer", 0x19),
        ("LTYPE", "Continuous", 0x1A),
        ("APPID", "ACAD", 0x1B),
        ("DIMSTYLE", "Standard", 0x1C),
        ("STYLE", "Standard", 0x1D),
    ];
    fixed
        .iter()
        .find(|(t, n, _)| *t == table && n.eq_ignore_ascii_case(name))
        .map(|(_, _, h)| *h)
}

fn default_object(h: u64) -> Option<TagList> {
    let mut t = TagList::new();
    t.push(0, "DICTIONARY");
    t.push(5, &format!("{h:X}"));
    match h {
        ROOT_DICT => {
            t.push(330, "0");
            t.push(100, "AcDbDictionary");
            t.push(281, "1");
            for (k, v) in [
                ("ACAD_GROUP", "B"),
                ("ACAD_LAYOUT", "C"),
                ("ACAD_MLINESTYLE", "1E"),
                ("ACAD_PLOTSTYLENAME", "D"),
            ] {
                t.push(3, k);
                t.push(350, v);
            }
        }
        GROUP_DICT => {
            t.push(330, "A");
            t.push(100, "AcDbDictionary");
            t.push(281, "1");
        }
        _ => return None,
    }
    Some(t)
}

fn objects_section(sections: &mut [Section]) -> Option<&mut Vec<TagList>> {
    sections.iter_mut().find_map(|s| match s {
        Section::Other { name, records } if name.eq_ignore_ascii_case("OBJECTS") => Some(records),
        _ => None,
    })
}

impl Drawing {
    /// The extended data of an entity (its 1001... groups; empty when it has none).
    pub fn xdata(&self, handle: u64) -> TagList {
        if let Some(x) = self.extras.xdata.get(&handle) {
            return x.clone();
        }
        self.source(handle)
            .map_or_else(TagList::new, |s| xdata_of(&s.tags))
    }

    /// Replace an entity's extended data: in the groups it was read from, or kept aside
    /// for a new entity.
    pub fn set_xdata(&mut self, handle: u64, xdata: TagList) {
        if let Some(s) = self.source_mut(handle) {
            s.tags = with_xdata(&s.tags, &xdata);
            return;
        }
        if xdata.is_empty() {
            self.extras.xdata.remove(&handle);
        } else {
            self.extras.xdata.insert(handle, xdata);
        }
    }

    /// The extended data the writers add to an entity not read from a file.
    pub fn new_entity_xdata(&self, handle: u64) -> Option<&TagList> {
        self.extras.xdata.get(&handle)
    }

    /// The registered application names (the APPID table), ACAD first in a new drawing.
    pub fn appids(&self) -> Vec<String> {
        match self.document() {
            Some(doc) => doc
                .table_records("APPID")
                .iter()
                .filter_map(|r| r.get(2).map(str::to_string))
                .collect(),
            None => std::iter::once("ACAD".to_string())
                .chain(self.extras.appids.iter().cloned())
                .collect(),
        }
    }

    /// Register an application; false when it already is (or the opened file has no APPID
    /// table to hold it).
    pub fn add_appid(&mut self, name: &str) -> bool {
        if self.appids().iter().any(|a| a.eq_ignore_ascii_case(name)) {
            return false;
        }
        if self.document().is_none() {
            self.extras.appids.push(name.to_string());
            return true;
        }
        let h = self.alloc_handle();
        let Some(doc) = self.document_mut() else {
            return false;
        };
        let r12 = doc.is_r12();
        let table = doc.sections.iter_mut().find_map(|s| match s {
            Section::Tables(ts) => ts.iter_mut().find(|t| t.name.eq_ignore_ascii_case("APPID")),
            _ => None,
        });
        let Some(table) = table else {
            return false;
        };
        let mut r = TagList::new();
        r.push(0, "APPID");
        if !r12 {
            r.push(5, &format!("{h:X}"));
            if let Some(th) = table.head.handle() {
                r.push(330, &format!("{th:X}"));
            }
            r.push(100, "AcDbSymbolTableRecord");
            r.push(100, "AcDbRegAppTableRecord");
        }
        r.push(2, name);
        r.push(70, "0");
        table.records.push(r);
        table.head = table.head.with(70, &table.records.len().to_string(), 2);
        true
    }

    /// The handle of the named-object dictionary (None for a file without OBJECTS, R12).
    pub fn root_dict(&self) -> Option<u64> {
        match self.document() {
            None => Some(ROOT_DICT),
            Some(doc) => doc
                .section_records("OBJECTS")
                .iter()
                .find(|r| r.type_name() == "DICTIONARY")
                .and_then(TagList::handle),
        }
    }

    /// A non-graphical object (DICTIONARY, XRECORD...) by handle.
    pub fn object(&self, h: u64) -> Option<TagList> {
        if let Some(t) = self.extras.objects.iter().find(|t| t.handle() == Some(h)) {
            return Some(t.clone());
        }
        match self.document() {
            Some(doc) => doc
                .section_records("OBJECTS")
                .iter()
                .find(|r| r.handle() == Some(h))
                .cloned(),
            None => default_object(h),
        }
    }

    /// Add or replace an object (by its handle); false when an opened file has no OBJECTS
    /// section for an owned object.
    pub fn put_object(&mut self, t: TagList) -> bool {
        let Some(h) = t.handle() else {
            return false;
        };
        let in_doc = self.document().is_some() && self.reachable(&t);
        if in_doc {
            let Some(recs) = self
                .document_mut()
                .and_then(|d| objects_section(&mut d.sections))
            else {
                return false;
            };
            match recs.iter_mut().find(|r| r.handle() == Some(h)) {
                Some(r) => *r = t,
                None => recs.push(t),
            }
            self.extras.objects.retain(|r| r.handle() != Some(h));
            self.settle();
            return true;
        }
        if let Some(recs) = self
            .document_mut()
            .and_then(|d| objects_section(&mut d.sections))
        {
            recs.retain(|r| r.handle() != Some(h));
        }
        match self
            .extras
            .objects
            .iter_mut()
            .find(|r| r.handle() == Some(h))
        {
            Some(r) => *r = t,
            None => self.extras.objects.push(t),
        }
        true
    }

    /// Whether an object's owners lead to the named-object dictionary (or, in an opened
    /// file, to a record that is not an object here, such as an entity owning an extension
    /// dictionary).
    fn reachable(&self, t: &TagList) -> bool {
        if t.handle().is_some() && t.handle() == self.root_dict() {
            return true;
        }
        let mut owner = owner_of(t).unwrap_or(0);
        for _ in 0..64 {
            if owner == 0 {
                return false;
            }
            if Some(owner) == self.root_dict() {
                return true;
            }
            match self.object(owner) {
                Some(o) => owner = owner_of(&o).unwrap_or(0),
                None => return self.document().is_some(),
            }
        }
        false
    }

    /// Moves the objects of an opened drawing that became reachable (their dictionary was
    /// just added) into its OBJECTS section.
    fn settle(&mut self) {
        while let Some(i) =
            (0..self.extras.objects.len()).find(|&i| self.reachable(&self.extras.objects[i]))
        {
            let t = self.extras.objects.remove(i);
            if let Some(recs) = self
                .document_mut()
                .and_then(|d| objects_section(&mut d.sections))
            {
                recs.push(t);
            }
        }
    }

    /// The objects a drawing made from scratch writes after its fixed ones (those its
    /// named-object dictionary reaches): the root and group dictionaries when changed are
    /// among them (the writer puts those first).
    pub fn owned_new_objects(&self) -> impl Iterator<Item = &TagList> + '_ {
        self.extras.objects.iter().filter(|t| self.reachable(t))
    }

    /// A table record's handle given by `tblobjname` in a drawing made from scratch: the
    /// writer's fixed one for the records every drawing has, else a fresh one, which the
    /// writer then gives the record (`given_table_handle`).
    pub fn table_handle(&mut self, table: &str, name: &str) -> u64 {
        if let Some(h) = self.given_table_handle(table, name) {
            return h;
        }
        let h = fixed_record_handle(table, name).unwrap_or_else(|| self.alloc_handle());
        self.extras
            .table_handles
            .push((table.to_string(), name.to_string(), h));
        h
    }

    /// The handle `tblobjname` gave a record of a drawing made from scratch, if it did.
    pub fn given_table_handle(&self, table: &str, name: &str) -> Option<u64> {
        self.extras
            .table_handles
            .iter()
            .find(|(t, n, _)| t == table && n.eq_ignore_ascii_case(name))
            .map(|(_, _, h)| *h)
    }

    /// The (table, name) of a record handle given by `table_handle`.
    pub fn table_record_of(&self, h: u64) -> Option<(&str, &str)> {
        self.extras
            .table_handles
            .iter()
            .find(|(_, _, x)| *x == h)
            .map(|(t, n, _)| (t.as_str(), n.as_str()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xdata_is_replaced_in_the_first_record_only() {
        let t = TagList::from_dxf_text(
            "  0\nPOLYLINE\n  5\n2A\n  8\n0\n1001\nOLD\n1000\nx\n  0\nVERTEX\n  8\n0\n",
        );
        assert_eq!(xdata_of(&t).get(1000), Some("x"));
        let mut x = TagList::new();
        x.push(1001, "NEW");
        x.push(1070, "3");
        let u = with_xdata(&t, &x);
        let groups: Vec<(i32, &str)> = u.iter().collect();
        assert_eq!(
            groups,
            vec![
                (0, "POLYLINE"),
                (5, "2A"),
                (8, "0"),
                (1001, "NEW"),
                (1070, "3"),
                (0, "VERTEX"),
                (8, "0")
            ]
        );
        let s = splice_xdata("  0\nLINE\n  8\n0\n  0\nSEQEND\n", &x, true);
        assert_eq!(s, "  0\nLINE\n  8\n0\n1001\nNEW\n1070\n3\n  0\nSEQEND\n");
    }

    #[test]
    fn owner_skips_reactors() {
        let t = TagList::from_dxf_text(
            "  0\nXRECORD\n  5\n2B\n102\n{ACAD_REACTORS\n330\nC\n102\n}\n330\nD\n100\nAcDbXrecord\n",
        );
        assert_eq!(owner_of(&t), Some(0xD));
        let u = with_owner(&t, 0x1F);
        assert_eq!(owner_of(&u), Some(0x1F));
        assert_eq!(u.len(), t.len());
    }
}
