//! The loader: tags → records → sections; entities through the factory, everything else
//! kept as its group list in the drawing's `DxfDocument`.

use super::factory;
use super::tags::{Pos, Tag, Tagger};
use super::DxfReadError;
use crate::output::document::{DxfDocument, Section, Table};
use crate::output::drawing::{Layer, SourceRecord};
use crate::output::record::TagList;
use crate::output::Drawing;

/// Read a whole DXF file (ASCII or binary, any version R12..R2018) into a drawing.
pub fn read_dxf(data: &[u8], recover: bool) -> Result<Drawing, DxfReadError> {
    let tagger = Tagger::new(data, recover)?;
    let enc = tagger.encoding();
    let binary = tagger.is_binary();
    let mut rs = Records {
        tags: tagger,
        peek: None,
        recover,
        recovered: 0,
        last_pos: Pos::Line(1),
    };
    let mut sections = Vec::new();
    let mut groups: Vec<(TagList, Option<usize>)> = Vec::new();
    let mut layout_groups: Vec<(TagList, Option<usize>)> = Vec::new();
    let mut seen_any = false;
    while let Some((rec, pos)) = rs.next(false)? {
        seen_any = true;
        match rec.type_name() {
            "SECTION" => {
                let name = rec.get(2).unwrap_or("").to_string();
                let section = match name.as_str() {
                    "HEADER" => {
                        let mut h = TagList::new();
                        for (c, v) in rec.iter().skip(2) {
                            h.push(c, v);
                        }
                        rs.header_rest(pos, &mut h)?;
                        Section::Header(h)
                    }
                    "TABLES" => Section::Tables(rs.tables(pos)?),
                    "ENTITIES" => {
                        rs.section_body(&name, pos, true, |r| {
                            group_entity(&mut groups, r, None);
                            Ok(())
                        })?;
                        Section::Entities
                    }
                    "BLOCKS" => {
                        let mut records: Vec<TagList> = Vec::new();
                        let mut layout: Option<usize> = None;
                        rs.section_body(&name, pos, true, |r| {
                            match r.type_name() {
                                "BLOCK" => {
                                    let is_layout = r.get(2).is_some_and(|n| {
                                        // `get`: byte 12 may fall inside a character.
                                        n.len() > 12
                                            && n.get(..12).is_some_and(|p| {
                                                p.eq_ignore_ascii_case("*Paper_Space")
                                            })
                                    });
                                    layout = is_layout.then_some(records.len());
                                    records.push(r);
                                }
                                "ENDBLK" => {
                                    layout = None;
                                    records.push(r);
                                }
                                // Layout entities are drawing entities (`ssget "X"` sees them).
                                _ => match layout {
                                    Some(b) => group_entity(&mut layout_groups, r, Some(b)),
                                    None => records.push(r),
                                },
                            }
                            Ok(())
                        })?;
                        Section::Other { name, records }
                    }
                    _ => {
                        // THUMBNAILIMAGE's data comes before any record: it arrives with the
                        // SECTION record, and is kept as a first record without a 0 group.
                        let mut lead = TagList::new();
                        for (c, v) in rec.iter().skip(2) {
                            lead.push(c, v);
                        }
                        let mut records = Vec::new();
                        if !lead.is_empty() {
                            records.push(lead);
                        }
                        rs.section_body(&name, pos, false, |r| {
                            records.push(r);
                            Ok(())
                        })?;
                        Section::Other { name, records }
                    }
                };
                sections.push(section);
            }
            "EOF" => break,
            // A stray ENDSEC (dxflib writes one after a header that goes on): ezdxf skips it.
            "ENDSEC" => {}
            other => rs.damaged(pos, format!("expected SECTION or EOF, found {other:?}"))?,
        }
    }
    if !seen_any {
        return Err(DxfReadError::at(None, "no DXF groups in the file"));
    }
    if !sections.iter().any(|s| matches!(s, Section::Entities)) {
        sections.push(Section::Entities);
    }
    let recovered = rs.recovered + rs.tags.recovered;
    let doc = DxfDocument {
        version: enc.version,
        encoding: enc.encoding,
        binary,
        sections,
        recovered,
    };
    groups.append(&mut layout_groups);
    Ok(build_drawing(doc, groups))
}

/// POLYLINE's VERTEX records, INSERT's ATTRIBs and their SEQEND travel with their owner.
fn group_entity(groups: &mut Vec<(TagList, Option<usize>)>, r: TagList, block: Option<usize>) {
    let follower = matches!(r.type_name(), "VERTEX" | "ATTRIB" | "SEQEND");
    match groups.last_mut() {
        Some((g, _)) if follower => {
            for (c, v) in r.iter() {
                g.push(c, v);
            }
        }
        _ => groups.push((r, block)),
    }
}

fn build_drawing(doc: DxfDocument, groups: Vec<(TagList, Option<usize>)>) -> Drawing {
    let mut d = Drawing::new();
    let layers: Vec<Layer> = doc
        .table_records("LAYER")
        .iter()
        .filter_map(factory::layer)
        .collect();
    if !layers.is_empty() {
        d.set_loaded_layers(layers);
    }
    let mut max_handle = 0u64;
    for s in &doc.sections {
        let recs: Box<dyn Iterator<Item = &TagList>> = match s {
            Section::Tables(ts) => Box::new(
                ts.iter()
                    .flat_map(|t| std::iter::once(&t.head).chain(&t.records)),
            ),
            Section::Other { records, .. } => Box::new(records.iter()),
            _ => Box::new(std::iter::empty()),
        };
        for r in recs {
            max_handle = max_handle.max(all_handles_max(r));
        }
    }
    for (g, _) in &groups {
        max_handle = max_handle.max(all_handles_max(g));
    }
    let seed = doc
        .header_var("$HANDSEED")
        .and_then(|h| u64::from_str_radix(h.trim(), 16).ok())
        .unwrap_or(0);
    d.set_handle_seed(seed.max(max_handle + 1));
    let clayer = doc.header_var("$CLAYER").map(str::to_string);
    for (g, block) in groups {
        let e = factory::entity(&g);
        let original = e.clone();
        d.push_loaded(
            e,
            Some(SourceRecord {
                tags: g,
                original,
                block,
            }),
        );
    }
    if let Some(l) = clayer {
        let _ = d.set_current_layer(&l);
    }
    d.set_document(doc);
    d
}

/// The largest handle (group 5 or 105) anywhere in a record group.
fn all_handles_max(r: &TagList) -> u64 {
    r.iter()
        .filter(|(c, _)| *c == 5 || *c == 105)
        .filter_map(|(_, v)| u64::from_str_radix(v.trim(), 16).ok())
        .max()
        .unwrap_or(0)
}

/// Records (a 0 group and the groups up to the next 0) over the tag stream.
struct Records<'a> {
    tags: Tagger<'a>,
    peek: Option<Tag<'a>>,
    recover: bool,
    recovered: usize,
    last_pos: Pos,
}

impl Records<'_> {
    /// A damaged-file error, or in recover mode a count and `Ok`.
    fn damaged(&mut self, pos: Pos, msg: String) -> Result<(), DxfReadError> {
        if self.recover {
            self.recovered += 1;
            Ok(())
        } else {
            Err(DxfReadError::at(Some(pos), msg))
        }
    }

    fn next_tag(&mut self) -> Result<Option<Tag<'_>>, DxfReadError> {
        Ok(match self.peek.take() {
            Some(t) => Some(t),
            None => match self.tags.next() {
                Some(t) => {
                    let t = t?;
                    self.last_pos = t.pos;
                    Some(t)
                }
                None => None,
            },
        })
    }

    /// The next record; with `check`, groups a modelled entity never has are refused.
    fn next(&mut self, check: bool) -> Result<Option<(TagList, Pos)>, DxfReadError> {
        let first = loop {
            let Some(t) = self.next_tag()? else {
                return Ok(None);
            };
            if t.code == 0 {
                break (t.value.into_owned(), t.pos);
            }
            if t.code == 999 {
                // A comment (LibreCAD starts its files with one); ezdxf drops them too.
                continue;
            }
            let (code, pos) = (t.code, t.pos);
            self.damaged(
                pos,
                format!("group code {code} outside any record (expected a 0 group)"),
            )?;
        };
        let (ty, pos) = first;
        let mut list = TagList::new();
        list.push(0, &ty);
        let allowed = if check {
            factory::allowed_codes(&ty)
        } else {
            None
        };
        let (mut xdata, mut appdata) = (false, false);
        loop {
            let t = match self.tags.next() {
                None => break,
                Some(t) => t?,
            };
            self.last_pos = t.pos;
            if t.code == 0 {
                self.peek = Some(t);
                break;
            }
            if let Some(ok) = allowed {
                xdata |= t.code >= 1000;
                if t.code == 102 {
                    appdata = t.value.starts_with('{');
                } else if !xdata && !appdata && !factory::common_code(t.code) && !ok(t.code) {
                    let (code, tpos) = (t.code, t.pos);
                    self.damaged(tpos, format!("group code {code} is not valid in a {ty}"))?;
                    continue;
                }
            }
            list.push(t.code, &t.value);
        }
        Ok(Some((list, pos)))
    }

    /// The rest of a HEADER section. dxflib (LibreCAD) writes an ENDSEC in the middle of its
    /// header and goes on with variables: such an ENDSEC and what follows it stay part of
    /// the header, so the file is written back as it was.
    fn header_rest(&mut self, start: Pos, h: &mut TagList) -> Result<(), DxfReadError> {
        let mut other = Vec::new();
        self.section_body("HEADER", start, false, |r| {
            other.push(r);
            Ok(())
        })?;
        for r in other {
            for (c, v) in r.iter() {
                h.push(c, v);
            }
        }
        Ok(())
    }

    /// The records of a section up to its ENDSEC, handed to `each`.
    fn section_body(
        &mut self,
        name: &str,
        start: Pos,
        check: bool,
        mut each: impl FnMut(TagList) -> Result<(), DxfReadError>,
    ) -> Result<(), DxfReadError> {
        loop {
            let Some((rec, pos)) = self.next(check)? else {
                let at = self.last_pos;
                self.damaged(
                    at,
                    format!("the file ends inside the {name} section begun at {start} (truncated file?)"),
                )?;
                return Ok(());
            };
            match rec.type_name() {
                "ENDSEC" if name == "HEADER" && rec.len() > 1 => each(rec)?,
                "ENDSEC" => return Ok(()),
                "SECTION" | "EOF" => {
                    self.damaged(
                        pos,
                        format!("the {name} section begun at {start} has no ENDSEC"),
                    )?;
                    if rec.type_name() == "EOF" {
                        return Ok(());
                    }
                    each(rec)?;
                }
                _ => each(rec)?,
            }
        }
    }

    fn tables(&mut self, start: Pos) -> Result<Vec<Table>, DxfReadError> {
        let mut tables: Vec<Table> = Vec::new();
        let mut open = false;
        let mut bad: Option<(Pos, String)> = None;
        self.section_body("TABLES", start, false, |r| {
            match r.type_name() {
                "TABLE" => {
                    tables.push(Table {
                        name: r.get(2).unwrap_or("").to_string(),
                        head: r,
                        records: Vec::new(),
                        end: TagList::new(),
                    });
                    open = true;
                }
                "ENDTAB" if open => {
                    if let Some(t) = tables.last_mut() {
                        t.end = r;
                    }
                    open = false;
                }
                _ if open => {
                    if let Some(t) = tables.last_mut() {
                        t.records.push(r);
                    }
                }
                other => {
                    bad.get_or_insert((start, format!("{other} record outside a TABLE")));
                }
            }
            Ok(())
        })?;
        if let Some((pos, msg)) = bad {
            self.damaged(pos, msg)?;
        }
        for t in &mut tables {
            if t.end.is_empty() {
                t.end.push(0, "ENDTAB");
            }
        }
        Ok(tables)
    }
}
