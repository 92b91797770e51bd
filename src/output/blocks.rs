//! Block definitions a script makes (`entmake` of BLOCK … ENDBLK), kept as the group lists
//! a file would hold: the BLOCK_RECORD table record, and the BLOCK record, the entities and
//! the ENDBLK record of the BLOCKS section. An opened drawing gets them in its own table and
//! section (so its writer puts them back with no special case); a drawing made from scratch
//! keeps them in `Extras`, and the CAD writer emits them after model and paper space.
//! Either way `block_section` reads them as INSERT, EXPLODE and `tblsearch` want them.

use glam::DVec3;

use super::document::Section;
use super::drawing::Drawing;
use super::dxf_writer::push_float;
use super::record::TagList;

/// The fixed handle of the model-space block record of a drawing made from scratch.
pub const MODEL_RECORD: u64 = 0xF;
/// The fixed handle of its BLOCK_RECORD table.
pub const BLOCK_RECORD_TABLE: u64 = 0x9;

/// A block definition to add: its record's handle (the owner of `body`'s entities), name,
/// flags (70), base point, layer, and entities as groups (each with its followers).
pub struct BlockDef {
    pub record: u64,
    pub name: String,
    pub flags: i32,
    pub base: DVec3,
    pub layer: String,
    pub body: Vec<TagList>,
}

fn real(x: f64) -> String {
    let mut s = String::new();
    push_float(&mut s, x);
    s
}

/// Split group lists holding followers (POLYLINE + VERTEX... + SEQEND) into one list per
/// record, as the BLOCKS section holds them.
fn split_records(t: &TagList) -> Vec<TagList> {
    let mut out: Vec<TagList> = Vec::new();
    for (c, v) in t.iter() {
        if c == 0 || out.is_empty() {
            out.push(TagList::new());
        }
        if let Some(last) = out.last_mut() {
            last.push(c, v);
        }
    }
    out
}

fn is_named(r: &TagList, ty: &str, name: &str) -> bool {
    r.type_name() == ty && r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(name))
}

impl Drawing {
    /// The records of the BLOCKS section: BLOCK, its entities (one record each, followers
    /// apart), ENDBLK, for every block the drawing defines.
    pub fn block_section(&self) -> &[TagList] {
        match self.document() {
            Some(doc) => doc.section_records("BLOCKS"),
            None => &self.extras.blocks,
        }
    }

    /// The BLOCK_RECORD records of blocks a script defined in a drawing made from scratch
    /// (an opened drawing's are in its table).
    pub fn new_block_records(&self) -> &[TagList] {
        &self.extras.block_records
    }

    /// The block record that owns model-space entities.
    pub fn model_space_record(&self) -> u64 {
        match self.document() {
            Some(doc) => doc.model_space_owner().unwrap_or(0),
            None => MODEL_RECORD,
        }
    }

    /// The handle of a defined block's record (for a redefinition to keep it), if any.
    pub fn block_record_handle(&self, name: &str) -> Option<u64> {
        let recs: &[TagList] = match self.document() {
            Some(doc) => doc.table_records("BLOCK_RECORD"),
            None => &self.extras.block_records,
        };
        recs.iter()
            .find(|r| is_named(r, "BLOCK_RECORD", name))
            .and_then(TagList::handle)
    }

    /// Whether a block of this name is defined (layouts included).
    pub fn has_block(&self, name: &str) -> bool {
        self.block_section()
            .iter()
            .any(|r| is_named(r, "BLOCK", name))
    }

    /// Add a block definition, or replace the one with the same name (keeping its record).
    /// Err when an opened drawing cannot hold one (R12, or no BLOCKS section).
    pub fn define_block(&mut self, def: BlockDef) -> Result<(), String> {
        let r12 = self.document().is_some_and(|d| d.is_r12());
        if r12 {
            return Err("lispcad defines blocks in R2000 and later drawings only".into());
        }
        let hex = |h: u64| format!("{h:X}");
        let (blk, end) = (self.alloc_handle(), self.alloc_handle());
        let mut recs = Vec::with_capacity(def.body.len() + 2);
        let mut b = TagList::new();
        b.push(0, "BLOCK");
        b.push(5, &hex(blk));
        b.push(330, &hex(def.record));
        b.push(100, "AcDbEntity");
        b.push(8, &def.layer);
        b.push(100, "AcDbBlockBegin");
        b.push(2, &def.name);
        b.push(70, &def.flags.to_string());
        b.push(10, &real(def.base.x));
        b.push(20, &real(def.base.y));
        b.push(30, &real(def.base.z));
        b.push(3, &def.name);
        b.push(1, "");
        recs.push(b);
        for t in &def.body {
            recs.extend(split_records(t));
        }
        let mut e = TagList::new();
        e.push(0, "ENDBLK");
        e.push(5, &hex(end));
        e.push(330, &hex(def.record));
        e.push(100, "AcDbEntity");
        e.push(8, &def.layer);
        e.push(100, "AcDbBlockEnd");
        recs.push(e);

        let existing = self.block_record_handle(&def.name).is_some();
        let mut rec = TagList::new();
        rec.push(0, "BLOCK_RECORD");
        rec.push(5, &hex(def.record));
        rec.push(330, &hex(BLOCK_RECORD_TABLE));
        rec.push(100, "AcDbSymbolTableRecord");
        rec.push(100, "AcDbBlockTableRecord");
        rec.push(2, &def.name);
        rec.push(340, "0");
        if self.document().is_none() {
            if !existing {
                self.extras.block_records.push(rec);
            }
            replace_block(&mut self.extras.blocks, &def.name, recs);
            return Ok(());
        }
        let shift = self.replace_in_document(&def.name, recs, rec, existing)?;
        if let Some((at, delta)) = shift {
            self.shift_layout_indices(at, delta);
        }
        Ok(())
    }

    /// An opened drawing's part of `define_block`: (index, change in length) of the BLOCKS
    /// section when a definition was replaced in place.
    fn replace_in_document(
        &mut self,
        name: &str,
        recs: Vec<TagList>,
        mut rec: TagList,
        existing: bool,
    ) -> Result<Option<(usize, isize)>, String> {
        let doc = self
            .document_mut()
            .ok_or_else(|| "no document".to_string())?;
        let mut shift = None;
        let blocks = doc.sections.iter_mut().find_map(|s| match s {
            Section::Other { name, records } if name == "BLOCKS" => Some(records),
            _ => None,
        });
        let Some(blocks) = blocks else {
            return Err("the opened drawing has no BLOCKS section".into());
        };
        let before = blocks.len();
        if let Some(at) = replace_block(blocks, name, recs) {
            shift = Some((at, blocks.len() as isize - before as isize));
        }
        if existing {
            return Ok(shift);
        }
        let table = doc.sections.iter_mut().find_map(|s| match s {
            Section::Tables(ts) => ts
                .iter_mut()
                .find(|t| t.name.eq_ignore_ascii_case("BLOCK_RECORD")),
            _ => None,
        });
        let Some(table) = table else {
            return Err("the opened drawing has no BLOCK_RECORD table".into());
        };
        if let Some(th) = table.head.handle() {
            rec = rec.with(330, &format!("{th:X}"), 5);
        }
        table.records.push(rec);
        table.head = table.head.with(70, &table.records.len().to_string(), 2);
        Ok(shift)
    }

    /// Entities of layouts written after BLOCKS record `at` move with it.
    fn shift_layout_indices(&mut self, at: usize, delta: isize) {
        if delta == 0 {
            return;
        }
        let moved: Vec<u64> = self
            .entities_with_sources()
            .filter(|(_, s)| s.and_then(|s| s.block).is_some_and(|b| b > at))
            .map(|(e, _)| e.handle)
            .collect();
        for h in moved {
            if let Some(s) = self.source_mut(h) {
                s.block = s.block.map(|b| (b as isize + delta) as usize);
            }
        }
    }
}

/// Replace the records of block `name` (BLOCK to ENDBLK) with `recs`, or append them; the
/// index of the replaced BLOCK record.
fn replace_block(blocks: &mut Vec<TagList>, name: &str, recs: Vec<TagList>) -> Option<usize> {
    let Some(start) = blocks.iter().position(|r| is_named(r, "BLOCK", name)) else {
        // Before a trailing record without a 0 group, if any (none in practice).
        blocks.extend(recs);
        return None;
    };
    let end = blocks[start..]
        .iter()
        .position(|r| r.type_name() == "ENDBLK")
        .map_or(blocks.len(), |i| start + i + 1);
    blocks.splice(start..end, recs);
    Some(start)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_block_is_defined_then_redefined_in_place() {
        let mut d = Drawing::new();
        let rec = d.alloc_handle();
        let line = TagList::from_dxf_text("  0\nLINE\n  5\n200\n  8\n0\n");
        let def = |body: Vec<TagList>| BlockDef {
            record: rec,
            name: "Box".into(),
            flags: 0,
            base: DVec3::ZERO,
            layer: "0".into(),
            body,
        };
        d.define_block(def(vec![line.clone()])).unwrap();
        assert!(d.has_block("BOX"));
        assert_eq!(d.block_record_handle("box"), Some(rec));
        assert_eq!(d.block_section().len(), 3);
        d.define_block(def(vec![line.clone(), line])).unwrap();
        assert_eq!(d.block_section().len(), 4);
        assert_eq!(d.new_block_records().len(), 1);
    }
}
