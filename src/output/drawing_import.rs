//! `dxf-import`: another drawing's entities and layers added to this one, with the block
//! definitions its INSERTs and DIMENSIONs name (nested ones too) and the text styles and line
//! types those use, so the result never refers to something it lacks. A named block the
//! drawing already has is used as it is (AutoCAD's INSERT of a drawing does the same); an
//! anonymous one (`*U2`, `*D1`...) that clashes is renamed. Every copied record gets a fresh
//! handle and its owner here, and its pointers follow the copies (`dxf_relocate`): the
//! entities keep their groups, reactors, extended data (their applications registered) and
//! the objects they own; the records of block definitions and tables leave their
//! application and extended data behind. An R12 file's records get the subclass markers of
//! a newer drawing (`dxf_upgrade`), a newer file's lose them in an R12 one.

use std::collections::HashMap;

use super::document::{DxfDocument, Section};
use super::drawing::{Drawing, EntityKind};
use super::record::TagList;

impl Drawing {
    /// Add `other`'s layers (those this drawing lacks), entities (with new handles) and the
    /// definitions they need; the handles of the added entities.
    pub fn import(&mut self, other: &Drawing) -> Vec<u64> {
        self.import_layers(other);
        let kept = |e: &super::Entity| matches!(e.kind, EntityKind::Unmodelled { .. });
        let mut copied = Copied::default();
        if let (true, Some(odoc)) = (self.document().is_some(), other.document()) {
            let roots: Vec<&TagList> = other
                .entities_with_sources()
                .filter(|(e, _)| kept(e))
                .filter_map(|(_, s)| s.map(|s| &s.tags))
                .collect();
            copied = import_definitions(self, odoc, &roots);
        }
        // Modelled entities keep their groups too (thickness, text alignment...), but an R12
        // drawing has no LWPOLYLINE or SPLINE: those are written from the model there.
        let keeps_groups = !self.document().is_some_and(DxfDocument::is_r12)
            || other.document().is_some_and(DxfDocument::is_r12);
        // Every record of a kept entity gets its handle before any is copied, so pointers
        // between them (a hatch and its boundary, reactors) follow.
        let mut fresh: Vec<Option<Vec<u64>>> = Vec::new();
        for (e, src) in other.entities_with_sources() {
            fresh.push(match src {
                Some(s) if (kept(e) || keeps_groups) && self.document().is_some() => {
                    Some(copied.allocate(self, &s.tags))
                }
                // A modelled entity is written from the model: one handle.
                _ if self.document().is_some() => {
                    let h = self.alloc_handle();
                    copied.map.entry(e.handle).or_insert(h);
                    Some(vec![h])
                }
                _ => None,
            });
        }
        let objects = match other.document() {
            Some(odoc) if self.document().is_some() => copied.owned_objects(self, odoc),
            _ => Vec::new(),
        };
        let mut added = Vec::new();
        for ((e, src), handles) in other.entities_with_sources().zip(fresh) {
            let mut e = e.clone();
            e.handle = 0;
            let src = match (src, handles, other.document()) {
                (Some(s), Some(handles), Some(odoc)) if kept(&e) || keeps_groups => {
                    let mut s = s.clone();
                    // Into this drawing's model space, whatever layout it came from.
                    s.block = None;
                    s.tags = copied.entity_tags(self, odoc, &s.tags, &handles);
                    e.handle = handles[0];
                    s.original.handle = handles[0];
                    Some(s)
                }
                (_, Some(handles), _) => {
                    e.handle = handles[0];
                    None
                }
                _ => None,
            };
            added.push(self.push_loaded(e, src));
        }
        if let (Some(odoc), false) = (other.document(), objects.is_empty()) {
            copied.copy_objects(self, odoc, &objects);
        }
        self.register_xdata_apps(&added);
        added
    }

    /// Registers the applications the extended data of `handles` names (AutoCAD refuses
    /// extended data of an application its APPID table lacks).
    fn register_xdata_apps(&mut self, handles: &[u64]) {
        if self.document().is_none() {
            return;
        }
        let mut apps: Vec<String> = Vec::new();
        for h in handles {
            if let Some(s) = self.source(*h) {
                for (c, v) in s.tags.iter() {
                    if c == 1001 && !apps.iter().any(|a| same(a, v)) {
                        apps.push(v.to_string());
                    }
                }
            }
        }
        for a in apps {
            self.add_appid(&a);
        }
    }

    fn import_layers(&mut self, other: &Drawing) {
        for l in other.layers() {
            if self.layer(&l.name).is_none() {
                // A name the model refuses cannot be merged; its entities land on it anyway.
                let _ = self.set_layer_record(l.clone());
            }
        }
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

/// What `import_definitions` copied: old handle → new handle of every record brought over,
/// the renamed anonymous blocks, and how the target names the source's table records.
#[derive(Default)]
struct Copied {
    map: HashMap<u64, u64>,
    renames: HashMap<String, String>,
}

impl Copied {
    /// Fresh handles for each record of an entity's group list (the entity, then its
    /// followers), remembered against the old ones.
    fn allocate(&mut self, target: &mut Drawing, t: &TagList) -> Vec<u64> {
        super::dxfin::factory::record_ranges(t)
            .into_iter()
            .map(|r| {
                let h = target.alloc_handle();
                if let Some(old) = record_handle(t, r) {
                    self.map.entry(old).or_insert(h);
                }
                h
            })
            .collect()
    }

    /// The objects of `odoc` that what was copied owns, directly or through one another (an
    /// entity's extension dictionary and its XRECORDs), with their handles allocated.
    fn owned_objects<'a>(
        &mut self,
        target: &mut Drawing,
        odoc: &'a DxfDocument,
    ) -> Vec<&'a TagList> {
        let objects = odoc.section_records("OBJECTS");
        let mut out: Vec<&TagList> = Vec::new();
        loop {
            let before = out.len();
            for o in objects {
                let (Some(h), Some(owner)) = (o.handle(), super::objects::owner_of(o)) else {
                    continue;
                };
                if !self.map.contains_key(&h) && self.map.contains_key(&owner) {
                    let new = target.alloc_handle();
                    self.map.insert(h, new);
                    out.push(o);
                }
            }
            if out.len() == before {
                return out;
            }
        }
    }

    /// Appends the relocated `objects` to the target's OBJECTS section.
    fn copy_objects(&self, target: &mut Drawing, odoc: &DxfDocument, objects: &[&TagList]) {
        let Some(tdoc) = target.document() else {
            return;
        };
        let copies: Vec<TagList> = objects
            .iter()
            .map(|o| super::dxf_relocate::relocate(o, &|h| self.resolve(tdoc, odoc, h)))
            .collect();
        let section = target.document_mut().and_then(|d| {
            d.sections.iter_mut().find_map(|s| match s {
                Section::Other { name, records } if same(name, "OBJECTS") => Some(records),
                _ => None,
            })
        });
        if let Some(records) = section {
            records.extend(copies);
        }
    }

    /// The target's handle for a source handle: the copy's, else the record of the same
    /// table and name the target has (layer, style, line type, model space...).
    fn resolve(&self, target: &DxfDocument, odoc: &DxfDocument, h: u64) -> Option<u64> {
        if let Some(n) = self.map.get(&h) {
            return Some(*n);
        }
        let tables = |d: &DxfDocument| -> Vec<(String, TagList)> {
            d.sections
                .iter()
                .filter_map(|s| match s {
                    Section::Tables(ts) => Some(ts),
                    _ => None,
                })
                .flatten()
                .flat_map(|t| t.records.iter().map(move |r| (t.name.clone(), r.clone())))
                .collect()
        };
        let (table, name) = tables(odoc)
            .into_iter()
            .find(|(_, r)| r.handle() == Some(h))
            .and_then(|(t, r)| r.get(2).map(|n| (t, n.to_string())))?;
        tables(target)
            .into_iter()
            .find(|(t, r)| same(t, &table) && r.get(2).is_some_and(|n| same(n, &name)))
            .and_then(|(_, r)| r.handle())
    }

    /// An imported entity's groups for the target: its handles and its followers' the fresh
    /// ones, owned by model space (the followers by it), pointers relocated, block names
    /// renamed, and in the target's era (subclass markers added or taken away).
    fn entity_tags(
        &self,
        target: &Drawing,
        odoc: &DxfDocument,
        t: &TagList,
        handles: &[u64],
    ) -> TagList {
        let Some(tdoc) = target.document() else {
            return t.clone();
        };
        let r12 = tdoc.is_r12();
        let t = super::dxf_relocate::relocate(t, &|h| self.resolve(tdoc, odoc, h));
        let t = rename_refs(&t, &self.renames);
        let model = tdoc.model_space_owner().unwrap_or(0);
        let mut out = TagList::new();
        for (k, r) in super::dxfin::factory::record_ranges(&t)
            .into_iter()
            .enumerate()
        {
            let mut rec = TagList::new();
            for i in r {
                let (c, v) = t.at(i);
                rec.push(c, v);
            }
            let owner = if k == 0 { model } else { handles[0] };
            let rec =
                with_handle_and_owner(&in_model_space(&rec), handles[k], (!r12).then_some(owner));
            let rec = match (r12, odoc.is_r12()) {
                (true, false) => strip_r2000_groups(&rec),
                (false, true) => super::dxf_upgrade::with_subclass_markers(&rec),
                _ => rec,
            };
            for (c, v) in rec.iter() {
                out.push(c, v);
            }
        }
        out
    }
}

/// A record of another layout moved to model space: no paper-space flag (67), layout name
/// (410) "Model".
fn in_model_space(rec: &TagList) -> TagList {
    let end = rec.iter().position(|(c, _)| c >= 1000).unwrap_or(rec.len());
    let mut out = TagList::new();
    for (i, (c, v)) in rec.iter().enumerate() {
        match c {
            67 if i < end => {}
            410 if i < end => out.push(410, "Model"),
            _ => out.push(c, v),
        }
    }
    out
}

/// The own handle of the record at `r` in `t`.
fn record_handle(t: &TagList, r: std::ops::Range<usize>) -> Option<u64> {
    r.take(3)
        .map(|i| t.at(i))
        .find(|(c, _)| *c == 5 || *c == 105)
        .and_then(|(_, v)| super::dxf_relocate::parse_handle(v))
}

/// One record with its handle set (added after the type when missing) and, when given, its
/// owner: the first group after the handle and the application data that follows it.
fn with_handle_and_owner(rec: &TagList, handle: u64, owner: Option<u64>) -> TagList {
    let code = if rec.type_name() == "DIMSTYLE" {
        105
    } else {
        5
    };
    let r = rec.with(code, &format!("{handle:X}"), 0);
    let Some(owner) = owner else {
        return r;
    };
    let start = r.iter().position(|(c, _)| c == code).map_or(1, |i| i + 1);
    let mut in_app = false;
    let mut at = r.len();
    for (i, (c, v)) in r.iter().enumerate().skip(start) {
        if c == 102 {
            in_app = v.starts_with('{');
        } else if !in_app {
            at = i;
            break;
        }
    }
    let owner = format!("{owner:X}");
    let mut out = TagList::new();
    for (i, (c, v)) in r.iter().enumerate() {
        if i == at {
            out.push(330, &owner);
            if c == 330 {
                continue;
            }
        }
        out.push(c, v);
    }
    if at >= r.len() {
        out.push(330, &owner);
    }
    out
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
fn import_definitions(target: &mut Drawing, odoc: &DxfDocument, roots: &[&TagList]) -> Copied {
    let oblocks = odoc.section_records("BLOCKS");
    let Some(tdoc) = target.document() else {
        return Copied::default();
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
    let mut copied = Copied {
        renames,
        ..Copied::default()
    };
    for s in &styles {
        copy_table_record(target, odoc, "STYLE", s, &mut copied);
    }
    for l in &linetypes {
        copy_table_record(target, odoc, "LTYPE", l, &mut copied);
    }
    // Handles first, for pointers from one block into another (or forward in one).
    let plans: Vec<BlockPlan> = copy
        .into_iter()
        .map(|(def, name)| plan_block(target, odoc, def, name, &mut copied))
        .collect();
    for plan in plans {
        copy_block(target, odoc, plan, &copied);
    }
    copied
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
fn copied_record(r: &TagList, handle: Option<u64>) -> TagList {
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
fn copy_table_record(
    target: &mut Drawing,
    odoc: &DxfDocument,
    table: &str,
    name: &str,
    copied: &mut Copied,
) {
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
    if let Some(old) = src.handle() {
        copied.map.insert(old, h);
    }
    let Some(t) = target.document_mut().and_then(|d| table_mut(d, table)) else {
        return;
    };
    let mut r = copied_record(src, src.get(5).map(|_| h));
    if let Some(owner) = t.head.handle() {
        if r.get(330).is_some() {
            r = r.with(330, &format!("{owner:X}"), 5);
        }
    }
    t.records.push(r);
    t.head = t.head.with(70, &t.records.len().to_string(), 2);
}

/// A block definition to copy, with the handles its records get.
struct BlockPlan<'a> {
    def: &'a [TagList],
    name: String,
    /// The BLOCK_RECORD's new handle (R2000 on).
    record: Option<u64>,
    /// One per record of `def` (none in an R12 target when the source had none).
    handles: Vec<Option<u64>>,
}

fn plan_block<'a>(
    target: &mut Drawing,
    odoc: &DxfDocument,
    def: &'a [TagList],
    name: String,
    copied: &mut Copied,
) -> BlockPlan<'a> {
    let old_name = def[0].get(2).unwrap_or(&name).to_string();
    let r12 = target.document().is_none_or(DxfDocument::is_r12);
    let has_br = !r12
        && target
            .document()
            .is_some_and(|d| d.table("BLOCK_RECORD").is_some());
    let record = has_br.then(|| {
        let h = target.alloc_handle();
        let src = odoc
            .table_records("BLOCK_RECORD")
            .iter()
            .find(|r| r.get(2).is_some_and(|n| same(n, &old_name)));
        if let Some(old) = src.and_then(TagList::handle) {
            copied.map.insert(old, h);
        }
        h
    });
    let handles = def
        .iter()
        .map(|r| {
            let old = r.handle();
            (old.is_some() || !r12).then(|| {
                let h = target.alloc_handle();
                if let Some(old) = old {
                    copied.map.entry(old).or_insert(h);
                }
                h
            })
        })
        .collect();
    BlockPlan {
        def,
        name,
        record,
        handles,
    }
}

/// Copies one block definition (BLOCK, its entities, ENDBLK; and its BLOCK_RECORD from R2000
/// on) under its new name, with its planned handles, owners and pointers relocated.
fn copy_block(target: &mut Drawing, odoc: &DxfDocument, plan: BlockPlan, copied: &Copied) {
    let BlockPlan {
        def,
        name,
        record: br,
        handles,
    } = plan;
    let name = name.as_str();
    let old_name = def[0].get(2).unwrap_or(name).to_string();
    let Some(tdoc) = target.document() else {
        return;
    };
    let r12 = tdoc.is_r12();
    let resolve = |h: u64| copied.resolve(tdoc, odoc, h);
    let relocate = |t: &TagList| super::dxf_relocate::relocate(t, &resolve);
    let br_record = br.map(|h| block_record(odoc, &old_name, name, h, &relocate));
    let mut out = Vec::with_capacity(def.len());
    let mut parent = br.unwrap_or(0);
    for (r, h) in def.iter().zip(&handles) {
        let mut c = relocate(&copied_record(r, None));
        if matches!(r.type_name(), "BLOCK") {
            c = c.with(2, name, 8);
            if c.get(3).is_some() {
                c = c.with(3, name, 2);
            }
        }
        c = rename_refs(&c, &copied.renames);
        let follower = matches!(r.type_name(), "ATTRIB" | "VERTEX" | "SEQEND");
        let owner = if follower { parent } else { br.unwrap_or(0) };
        if let Some(h) = h {
            c = with_handle_and_owner(&c, *h, (!r12).then_some(owner));
            if !follower {
                parent = *h;
            }
        }
        c = match (r12, odoc.is_r12()) {
            (true, _) => strip_r2000_groups(&c),
            (false, true) => super::dxf_upgrade::with_subclass_markers(&c),
            _ => c,
        };
        out.push(c);
    }
    if let (Some(mut r), Some(t)) = (
        br_record,
        target
            .document_mut()
            .and_then(|d| table_mut(d, "BLOCK_RECORD")),
    ) {
        if let Some(owner) = t.head.handle() {
            r = with_handle_and_owner(&r, br.unwrap_or(0), Some(owner));
        }
        t.records.push(r);
        t.head = t.head.with(70, &t.records.len().to_string(), 2);
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

/// The BLOCK_RECORD of a copied block: the source's (relocated) or a new one, named `name`,
/// with handle `h` and no layout.
fn block_record(
    odoc: &DxfDocument,
    old_name: &str,
    name: &str,
    h: u64,
    relocate: &dyn Fn(&TagList) -> TagList,
) -> TagList {
    let src = odoc
        .table_records("BLOCK_RECORD")
        .iter()
        .find(|r| r.get(2).is_some_and(|n| same(n, old_name)));
    let mut r = match src {
        Some(s) => relocate(&copied_record(s, None)).with(5, &format!("{h:X}"), 0),
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
    r
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
