//! `dxf-import`: another drawing's entities and layers added to this one, with the block
//! definitions its INSERTs and DIMENSIONs name (nested ones too) and the text styles and line
//! types those use, so the result never refers to something it lacks. A named block the
//! drawing already has is used as it is (AutoCAD's INSERT of a drawing does the same); an
//! anonymous one (`*U2`, `*D1`...) that clashes is renamed. Copied records get fresh handles
//! and owners; their application data (reactors, extension dictionaries) stays behind.

use std::collections::HashMap;

use super::document::{DxfDocument, Section};
use super::drawing::{Drawing, EntityKind};
use super::record::TagList;

impl Drawing {
    /// Add `other`'s layers (those this drawing lacks), entities (with new handles) and the
    /// definitions they need; the handles of the added entities.
    pub fn import(&mut self, other: &Drawing) -> Vec<u64> {
        for l in other.layers() {
            if self.layer(&l.name).is_none() {
                // A name the model refuses cannot be merged; its entities land on it anyway.
                let _ = self.set_layer_record(l.clone());
            }
        }
        let kept = |e: &super::Entity| matches!(e.kind, EntityKind::Unmodelled { .. });
        let mut renames = HashMap::new();
        if let (true, Some(odoc)) = (self.document().is_some(), other.document()) {
            let roots: Vec<&TagList> = other
                .entities_with_sources()
                .filter(|(e, _)| kept(e))
                .filter_map(|(_, s)| s.map(|s| &s.tags))
                .collect();
            renames = import_definitions(self, odoc, &roots);
        }
        let mut added = Vec::new();
        for (e, src) in other.entities_with_sources() {
            let mut e = e.clone();
            e.handle = 0;
            // Modelled entities are re-written from the model in their new drawing; only the
            // kept ones need their groups.
            let src = if kept(&e) {
                src.cloned().map(|mut s| {
                    // Into this drawing's model space, whatever layout it came from.
                    s.block = None;
                    s.tags = rename_refs(&s.tags, &renames);
                    s
                })
            } else {
                None
            };
            added.push(self.push_loaded(e, src));
        }
        added
    }

    /// Whether some live entity is kept only as the groups it was read from (INSERT, HATCH,
    /// MTEXT, DIMENSION...): only a drawing with a document can write those.
    pub fn has_kept_entities(&self) -> bool {
        self.entities_with_sources()
            .any(|(e, s)| s.is_some() && matches!(e.kind, EntityKind::Unmodelled { .. }))
    }

    /// A drawing made from scratch that nothing has been done to yet: no handle given out
    /// (so no script holds an ename it could confuse with a file's), no layer but a default
    /// "0", no extended data, application or object.
    pub fn is_untouched(&self) -> bool {
        self.document().is_none()
            && self.next_handle() == super::drawing::FIRST_HANDLE
            && self.layers() == [super::drawing::Layer::new("0")]
            && self.current_layer() == "0"
            && self.extras.is_empty()
    }
}

/// The block a record refers to by name, if it is an INSERT or a DIMENSION.
fn block_ref(r: &TagList) -> Option<&str> {
    matches!(r.type_name(), "INSERT" | "DIMENSION")
        .then(|| r.get(2))
        .flatten()
}

/// Every record of a group list (an entity and its followers) with the block names it refers
/// to renamed.
fn rename_refs(t: &TagList, renames: &HashMap<String, String>) -> TagList {
    let Some(new) = block_ref(t).and_then(|n| renames.get(&n.to_ascii_uppercase())) else {
        return t.clone();
    };
    t.with(2, new, 0)
}

fn same(a: &str, b: &str) -> bool {
    a.eq_ignore_ascii_case(b)
}

/// The BLOCK..ENDBLK records of a block in a BLOCKS section.
fn definition<'a>(blocks: &'a [TagList], name: &str) -> Option<&'a [TagList]> {
    let start = blocks
        .iter()
        .position(|r| r.type_name() == "BLOCK" && r.get(2).is_some_and(|n| same(n, name)))?;
    let len = blocks[start..]
        .iter()
        .position(|r| r.type_name() == "ENDBLK")?;
    Some(&blocks[start..=start + len])
}

fn block_names(doc: &DxfDocument) -> Vec<String> {
    doc.section_records("BLOCKS")
        .iter()
        .filter(|r| r.type_name() == "BLOCK")
        .filter_map(|r| r.get(2).map(str::to_string))
        .collect()
}

/// Copies into `target`'s document the definitions `roots` need that it lacks; the renamed
/// anonymous blocks (upper-cased old name → new name).
fn import_definitions(
    target: &mut Drawing,
    odoc: &DxfDocument,
    roots: &[&TagList],
) -> HashMap<String, String> {
    let oblocks = odoc.section_records("BLOCKS");
    let Some(tdoc) = target.document() else {
        return HashMap::new();
    };
    let mut taken = block_names(tdoc);
    // Which definitions to copy, and under which names.
    let mut queue: Vec<String> = roots
        .iter()
        .filter_map(|t| block_ref(t).map(str::to_string))
        .collect();
    let mut copy: Vec<(&[TagList], String)> = Vec::new();
    let mut renames: HashMap<String, String> = HashMap::new();
    let mut seen: Vec<String> = Vec::new();
    while let Some(name) = queue.pop() {
        if seen.iter().any(|n| same(n, &name)) {
            continue;
        }
        seen.push(name.clone());
        let Some(def) = definition(oblocks, &name) else {
            continue;
        };
        let exists = taken.iter().any(|n| same(n, &name));
        let anonymous = name.starts_with('*');
        if exists && !anonymous {
            continue;
        }
        let new_name = if exists {
            fresh_anonymous(&name, &taken)
        } else {
            name.clone()
        };
        if new_name != name {
            renames.insert(name.to_ascii_uppercase(), new_name.clone());
        }
        taken.push(new_name.clone());
        queue.extend(def.iter().filter_map(|r| block_ref(r).map(str::to_string)));
        copy.push((def, new_name));
    }
    let mut styles: Vec<String> = Vec::new();
    let mut linetypes: Vec<String> = Vec::new();
    let records = roots.iter().flat_map(|t| {
        super::dxfin::factory::record_ranges(t)
            .into_iter()
            .map(move |r| (*t, r))
    });
    let mut note = |t: &TagList, r: std::ops::Range<usize>| {
        for i in r {
            match t.at(i) {
                (7, v) if !styles.iter().any(|s| same(s, v)) => styles.push(v.to_string()),
                (6, v) if !linetypes.iter().any(|s| same(s, v)) => linetypes.push(v.to_string()),
                _ => {}
            }
        }
    };
    for (t, r) in records {
        note(t, r);
    }
    for (def, _) in &copy {
        for r in def.iter() {
            note(r, 0..r.len());
        }
    }
    for s in &styles {
        copy_table_record(target, odoc, "STYLE", s);
    }
    for l in &linetypes {
        copy_table_record(target, odoc, "LTYPE", l);
    }
    for (def, name) in copy {
        copy_block(target, odoc, def, &name, &renames);
    }
    renames
}

/// `*U7` → the first `*U<n>` the drawing does not have.
fn fresh_anonymous(name: &str, taken: &[String]) -> String {
    let prefix: String = name.chars().take_while(|c| !c.is_ascii_digit()).collect();
    (1..)
        .map(|n| format!("{prefix}{n}"))
        .find(|n| !taken.iter().any(|t| same(t, n)))
        .unwrap_or_default()
}

/// A copied record: no application data or extended data (they belong to the original's
/// document), a fresh handle when it had one.
fn copied(r: &TagList, handle: Option<u64>) -> TagList {
    let mut out = TagList::new();
    let mut in_app = false;
    for (c, v) in r.iter() {
        if c == 102 {
            in_app = v.starts_with('{');
            continue;
        }
        if in_app || c >= 1000 {
            continue;
        }
        match (c, handle) {
            (5, Some(h)) => out.push(5, &format!("{h:X}")),
            _ => out.push(c, v),
        }
    }
    out
}

fn table_mut<'a>(doc: &'a mut DxfDocument, name: &str) -> Option<&'a mut super::document::Table> {
    doc.sections.iter_mut().find_map(|s| match s {
        Section::Tables(ts) => ts.iter_mut().find(|t| same(&t.name, name)),
        _ => None,
    })
}

/// Adds a record of `odoc`'s table named `name` to the target's table when it lacks one.
fn copy_table_record(target: &mut Drawing, odoc: &DxfDocument, table: &str, name: &str) {
    let builtin = ["BYBLOCK", "BYLAYER", "CONTINUOUS"];
    if table == "LTYPE" && builtin.iter().any(|b| same(b, name)) {
        return;
    }
    let Some(src) = odoc
        .table_records(table)
        .iter()
        .find(|r| r.get(2).is_some_and(|n| same(n, name)))
    else {
        return;
    };
    let has = |d: &Drawing| {
        d.document().is_none_or(|doc| {
            doc.table(table).is_none()
                || doc
                    .table_records(table)
                    .iter()
                    .any(|r| r.get(2).is_some_and(|n| same(n, name)))
        })
    };
    if has(target) {
        return;
    }
    let h = target.alloc_handle();
    let Some(t) = target.document_mut().and_then(|d| table_mut(d, table)) else {
        return;
    };
    let mut r = copied(src, src.get(5).map(|_| h));
    if let Some(owner) = t.head.handle() {
        if r.get(330).is_some() {
            r = r.with(330, &format!("{owner:X}"), 5);
        }
    }
    t.records.push(r);
    t.head = t.head.with(70, &t.records.len().to_string(), 2);
}

/// Copies one block definition (BLOCK, its entities, ENDBLK; and its BLOCK_RECORD from R2000
/// on) under `name`, with fresh handles and owners.
fn copy_block(
    target: &mut Drawing,
    odoc: &DxfDocument,
    def: &[TagList],
    name: &str,
    renames: &HashMap<String, String>,
) {
    let old_name = def[0].get(2).unwrap_or(name).to_string();
    let Some(tdoc) = target.document() else {
        return;
    };
    let r12 = tdoc.is_r12();
    let has_br = !r12 && tdoc.table("BLOCK_RECORD").is_some();
    let mut map: HashMap<u64, u64> = HashMap::new();
    let br = if has_br {
        let h = target.alloc_handle();
        let src = odoc
            .table_records("BLOCK_RECORD")
            .iter()
            .find(|r| r.get(2).is_some_and(|n| same(n, &old_name)));
        if let Some(old) = src.and_then(TagList::handle) {
            map.insert(old, h);
        }
        let mut r = match src {
            Some(s) => copied(s, Some(h)),
            None => {
                let mut r = TagList::new();
                for (c, v) in [
                    (0, "BLOCK_RECORD"),
                    (5, ""),
                    (330, "0"),
                    (100, "AcDbSymbolTableRecord"),
                    (100, "AcDbBlockTableRecord"),
                    (2, name),
                ] {
                    r.push(c, v);
                }
                r.with(5, &format!("{h:X}"), 0)
            }
        };
        r = r.with(2, name, 100);
        if r.get(340).is_some() {
            // The layout pointer: a block that is not a layout has none.
            r = r.with(340, "0", 2);
        }
        let t = target
            .document_mut()
            .and_then(|d| table_mut(d, "BLOCK_RECORD"));
        if let Some(t) = t {
            if let Some(owner) = t.head.handle() {
                r = r.with(330, &format!("{owner:X}"), 5);
            }
            t.records.push(r);
            t.head = t.head.with(70, &t.records.len().to_string(), 2);
        }
        Some(h)
    } else {
        None
    };
    let mut out = Vec::with_capacity(def.len());
    for r in def {
        let h = r.handle().map(|old| {
            let h = target.alloc_handle();
            map.insert(old, h);
            h
        });
        let mut c = copied(r, h);
        if matches!(r.type_name(), "BLOCK") {
            c = c.with(2, name, 8);
            if c.get(3).is_some() {
                c = c.with(3, name, 2);
            }
        }
        c = rename_refs(&c, renames);
        if let Some(owner) = r.get(330) {
            let old = u64::from_str_radix(owner.trim(), 16).unwrap_or(0);
            let new = map.get(&old).copied().or(br).unwrap_or(0);
            c = c.with(330, &format!("{new:X}"), 5);
        }
        if r12 {
            c = strip_r2000_groups(&c);
        }
        out.push(c);
    }
    let Some(doc) = target.document_mut() else {
        return;
    };
    let blocks = doc.sections.iter_mut().find_map(|s| match s {
        Section::Other { name, records } if same(name, "BLOCKS") => Some(records),
        _ => None,
    });
    match blocks {
        Some(records) => records.extend(out),
        None => {
            let at = doc
                .sections
                .iter()
                .position(|s| matches!(s, Section::Entities))
                .unwrap_or(doc.sections.len());
            doc.sections.insert(
                at,
                Section::Other {
                    name: "BLOCKS".into(),
                    records: out,
                },
            );
        }
    }
}

/// R12 has no subclass markers or owners.
fn strip_r2000_groups(t: &TagList) -> TagList {
    let mut out = TagList::new();
    for (c, v) in t.iter() {
        if !matches!(c, 100 | 330 | 360) {
            out.push(c, v);
        }
    }
    out
}
