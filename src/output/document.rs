//! What an opened DXF file holds besides its entities: the header, classes, tables, blocks,
//! objects and any unknown section, each kept as the group lists it was read as. The drawing
//! owns it (`Drawing::document`), and the DXF writer puts it back around the entities.

use encoding_rs::Encoding;

use super::record::TagList;

/// One section of the file, in file order.
#[derive(Clone, Debug)]
pub enum Section {
    /// The header variables: every group after `2 HEADER` up to ENDSEC.
    Header(TagList),
    Tables(Vec<Table>),
    /// Placeholder: the entities live in the drawing and are written from it.
    Entities,
    /// CLASSES, BLOCKS, OBJECTS, THUMBNAILIMAGE, ACDSDATA, unknown sections: records verbatim.
    Other {
        name: String,
        records: Vec<TagList>,
    },
}

/// A symbol table: its TABLE record, its entries, and the ENDTAB record.
#[derive(Clone, Debug)]
pub struct Table {
    pub name: String,
    pub head: TagList,
    pub records: Vec<TagList>,
    pub end: TagList,
}

/// An opened DXF file minus its entities.
#[derive(Clone, Debug)]
pub struct DxfDocument {
    /// `$ACADVER` as read (e.g. "AC1015"); the version `-o x.dxf` writes.
    pub version: &'static str,
    /// The code page strings are written in (UTF-8 from R2007 on).
    pub encoding: &'static Encoding,
    /// Whether the file was binary (it is written back as ASCII).
    pub binary: bool,
    pub sections: Vec<Section>,
    /// How many damaged groups `--recover` skipped (0 for a sound file).
    pub recovered: usize,
}

impl DxfDocument {
    /// Whether this is R12 (or older): no subclass markers, owners, LWPOLYLINE or SPLINE.
    pub fn is_r12(&self) -> bool {
        self.version <= "AC1009"
    }

    pub fn table(&self, name: &str) -> Option<&Table> {
        self.sections.iter().find_map(|s| match s {
            Section::Tables(ts) => ts.iter().find(|t| t.name.eq_ignore_ascii_case(name)),
            _ => None,
        })
    }

    /// The records of a table (empty when the file has none).
    pub fn table_records(&self, name: &str) -> &[TagList] {
        self.table(name).map_or(&[], |t| &t.records)
    }

    /// The records of a non-table section such as BLOCKS or OBJECTS.
    pub fn section_records(&self, name: &str) -> &[TagList] {
        self.sections
            .iter()
            .find_map(|s| match s {
                Section::Other { name: n, records } if n.eq_ignore_ascii_case(name) => {
                    Some(records.as_slice())
                }
                _ => None,
            })
            .unwrap_or(&[])
    }

    /// A header variable's first value (`$HANDSEED` → "2F1").
    pub fn header_var(&self, name: &str) -> Option<&str> {
        let Section::Header(h) = self
            .sections
            .iter()
            .find(|s| matches!(s, Section::Header(_)))?
        else {
            return None;
        };
        let mut it = h.iter();
        while let Some((c, v)) = it.next() {
            if c == 9 && v == name {
                return it.next().map(|(_, v)| v);
            }
        }
        None
    }

    /// The handle of the model-space block record: the owner of new entities.
    pub fn model_space_owner(&self) -> Option<u64> {
        self.table_records("BLOCK_RECORD")
            .iter()
            .find(|r| {
                r.get(2)
                    .is_some_and(|n| n.eq_ignore_ascii_case("*Model_Space"))
            })
            .and_then(|r| r.handle())
    }
}
