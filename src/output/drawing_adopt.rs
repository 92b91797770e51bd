//! `dxf-import` into a drawing made from scratch that already has content, of a file with
//! entities lispcad keeps only as read (INSERT, HATCH, MTEXT, DIMENSION...). Only an opened
//! document can write those, so the drawing takes the file's document whole, as an untouched
//! one would; but its own entities keep their handles (a script may hold them), so every
//! record of the file is relocated above them: a fresh handle from the drawing's `$HANDSEED`
//! on, in file order, and every pointer to it follows (`dxf_relocate`). The drawing's own
//! entities, layers and applications are then written into that document like the new
//! entities of an opened drawing.

use std::collections::HashMap;

use super::document::{DxfDocument, Section};
use super::drawing::Drawing;
use super::dxf_relocate::relocate;
use super::record::TagList;

/// Why a drawing cannot take a file's document.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "the drawing has dictionaries, XRECORDs or table handles of its own, which an imported \
     document cannot hold yet"
)]
pub struct CannotAdopt;

impl Drawing {
    /// Add every entity, layer, block, table record and object of `other` (an opened file)
    /// to this drawing made from scratch, relocated above its handles; the handles of the
    /// added entities.
    pub fn import_relocated(&mut self, other: &Drawing) -> Result<Vec<u64>, CannotAdopt> {
        let Some(odoc) = other.document() else {
            return Ok(self.import(other));
        };
        if self.document().is_some() || !self.extras.is_adoptable() {
            return Err(CannotAdopt);
        }
        let mut map: HashMap<u64, u64> = HashMap::new();
        let mut note = |d: &mut Drawing, t: &TagList| {
            for old in super::dxf_relocate::own_handles(t) {
                if let std::collections::hash_map::Entry::Vacant(v) = map.entry(old) {
                    v.insert(d.alloc_handle());
                }
            }
        };
        for s in &odoc.sections {
            match s {
                Section::Tables(ts) => {
                    for t in ts {
                        note(self, &t.head);
                        for r in &t.records {
                            note(self, r);
                        }
                    }
                }
                Section::Other { records, .. } => {
                    for r in records {
                        note(self, r);
                    }
                }
                Section::Header(_) | Section::Entities => {}
            }
        }
        for (_, src) in other.entities_with_sources() {
            if let Some(s) = src {
                note(self, &s.tags);
            }
        }
        let resolve = |h: u64| map.get(&h).copied();
        let doc = relocated_document(odoc, &resolve);
        self.set_document(doc);
        for name in self.extras.take_appids() {
            self.add_appid(&name);
        }
        for l in other.layers() {
            if self.layer(&l.name).is_none() {
                let _ = self.set_layer_record(l.clone());
            }
        }
        let mut added = Vec::new();
        for (e, src) in other.entities_with_sources() {
            let mut e = e.clone();
            let src = src.cloned().map(|mut s| {
                let old = super::dxf_relocate::own_handles(&s.tags).first().copied();
                e.handle = old.and_then(resolve).unwrap_or_else(|| self.alloc_handle());
                s.tags = relocate(&s.tags, &resolve);
                s.original.handle = e.handle;
                s
            });
            if src.is_none() {
                e.handle = 0;
            }
            added.push(self.push_loaded(e, src));
        }
        Ok(added)
    }
}

fn relocated_document(odoc: &DxfDocument, resolve: &dyn Fn(u64) -> Option<u64>) -> DxfDocument {
    let mut doc = odoc.clone();
    for s in &mut doc.sections {
        match s {
            Section::Header(h) => *h = relocate(h, resolve),
            Section::Tables(ts) => {
                for t in ts {
                    t.head = relocate(&t.head, resolve);
                    for r in &mut t.records {
                        *r = relocate(r, resolve);
                    }
                    t.end = relocate(&t.end, resolve);
                }
            }
            Section::Other { records, .. } => {
                for r in records {
                    *r = relocate(r, resolve);
                }
            }
            Section::Entities => {}
        }
    }
    doc
}
