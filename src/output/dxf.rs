//! The project's own DXF writer. `DxfWriter` emits group-code/value pairs; `write_cad` writes
//! the CAD profile: AutoCAD R2000 (AC1015) with every section a strict reader expects (header,
//! classes, tables, blocks, entities, objects), unique handles, owner handles (330) and
//! subclass markers (100), after the DXF reference and what ezdxf's auditor checks.
//!
//! Structural objects (tables, block records, dictionaries, layouts) have fixed handles below
//! `FIRST_HANDLE`; entities keep their drawing handles; records the drawing does not number
//! (layers, vertices, extra mesh faces) get handles above the drawing's last one.

use std::sync::OnceLock;

use glam::{DVec2, DVec3};

use super::drawing::{Drawing, EntityKind};
pub use super::dxf_entities::{degrees, plane_normal};
pub(crate) use super::dxf_entities::{entity_head, kept_groups, write_entity};
pub use super::dxf_writer::{encode_cp1252, push_float, DxfWriter};
use super::record::TagList;

// Fixed structural handles.
const H_LAYER_TABLE: u64 = 0x1;
const H_LTYPE_TABLE: u64 = 0x2;
const H_APPID_TABLE: u64 = 0x3;
const H_DIMSTYLE_TABLE: u64 = 0x4;
const H_STYLE_TABLE: u64 = 0x5;
const H_UCS_TABLE: u64 = 0x6;
const H_VIEW_TABLE: u64 = 0x7;
const H_VPORT_TABLE: u64 = 0x8;
const H_BLOCK_RECORD_TABLE: u64 = 0x9;
const H_ROOT_DICT: u64 = 0xA;
const H_GROUP_DICT: u64 = 0xB;
const H_LAYOUT_DICT: u64 = 0xC;
const H_PLOTSTYLE_DICT: u64 = 0xD;
const H_PLOTSTYLE_NORMAL: u64 = 0xE;
const H_MODEL_RECORD: u64 = 0xF;
const H_PAPER_RECORD: u64 = 0x10;
const H_MODEL_BLOCK: u64 = 0x11;
const H_MODEL_ENDBLK: u64 = 0x12;
const H_PAPER_BLOCK: u64 = 0x13;
const H_PAPER_ENDBLK: u64 = 0x14;
const H_MODEL_LAYOUT: u64 = 0x15;
const H_PAPER_LAYOUT: u64 = 0x16;
const H_VPORT_ACTIVE: u64 = 0x17;
const H_LTYPE_BYBLOCK: u64 = 0x18;
const H_LTYPE_BYLAYER: u64 = 0x19;
const H_LTYPE_CONTINUOUS: u64 = 0x1A;
const H_APPID_ACAD: u64 = 0x1B;
const H_DIMSTYLE_STANDARD: u64 = 0x1C;
const H_STYLE_STANDARD: u64 = 0x1D;
const H_MLINESTYLE_DICT: u64 = 0x1E;
const H_MLINESTYLE_STANDARD: u64 = 0x1F;

/// Write the drawing as AutoCAD R2000 DXF (the CAD profile).
pub fn write_cad(d: &Drawing) -> String {
    write_cad_units(d, 4)
}

/// `write_cad` with the drawing unit (`$INSUNITS` code) in the header.
pub fn write_cad_units(d: &Drawing, insunits: i32) -> String {
    write_cad_prepared(&super::Prepared::new(d), insunits)
}

/// `write_cad_units` of a prepared drawing.
pub fn write_cad_prepared(p: &super::Prepared, insunits: i32) -> String {
    let d = p.drawing;
    let mut next = d.next_handle();
    let mut alloc = || {
        let h = next;
        next += 1;
        h
    };
    let (linetypes, styles) = table_names(d);
    let layer_names = d.layers().iter().map(|l| l.name.as_str());
    let layer_handles = record_handles(d, "LAYER", layer_names, &mut alloc);
    let ltype_handles = record_handles(d, "LTYPE", linetypes.iter(), &mut alloc);
    let style_handles = record_handles(d, "STYLE", styles.iter(), &mut alloc);
    // Entities first into their own buffer: they allocate handles the header's $HANDSEED
    // must exceed.
    let ents = entities(d, &mut alloc);
    let appids = d.appids();
    let appid_handles = record_handles(d, "APPID", appids.iter().skip(1), &mut alloc);
    let handseed = alloc();
    let tables = Tables {
        linetypes,
        ltype_handles,
        layer_handles,
        styles,
        style_handles,
        appids,
        appid_handles,
    };

    let mut w = DxfWriter::new();
    let extents = p.extents();
    write_header(&mut w, d, extents, handseed, insunits);
    w.out.push_str(prepared(&CLASSES, write_classes));
    w.str(0, "SECTION");
    w.str(2, "TABLES");
    write_vport(&mut w, extents);
    write_tables(&mut w, d, &tables);
    w.out.push_str(prepared(&TABLES_TAIL, write_tables_tail));
    write_blocks(&mut w, d);
    w.out.push_str(&ents.out);
    w.str(0, "ENDSEC");
    write_drawing_objects(&mut w, d);
    w.out.push_str(prepared(&OBJECTS, write_objects));
    w.out
}

/// The table records a drawing needs beyond the fixed ones, with their handles.
struct Tables {
    linetypes: Vec<String>,
    ltype_handles: Vec<u64>,
    layer_handles: Vec<u64>,
    styles: Vec<String>,
    style_handles: Vec<u64>,
    appids: Vec<String>,
    appid_handles: Vec<u64>,
}

/// Names the tables must define: line types and text styles used by layers and entities.
fn table_names(d: &Drawing) -> (Vec<String>, Vec<String>) {
    let mut linetypes: Vec<String> = Vec::new();
    let layer_types = d.layers().iter().map(|l| l.linetype.clone());
    for lt in layer_types.chain(d.entity_linetypes()) {
        let lt = &lt;
        let builtin = ["BYBLOCK", "BYLAYER", "CONTINUOUS"]
            .iter()
            .any(|b| lt.eq_ignore_ascii_case(b));
        if !builtin && !linetypes.iter().any(|x| x.eq_ignore_ascii_case(lt)) {
            linetypes.push(lt.clone());
        }
    }
    let mut styles: Vec<String> = Vec::new();
    for e in d.entities() {
        if let EntityKind::Text { style, .. } = &e.kind {
            if !style.eq_ignore_ascii_case("STANDARD")
                && !style.is_empty()
                && !styles.iter().any(|x| x.eq_ignore_ascii_case(style))
            {
                styles.push(style.clone());
            }
        }
    }
    (linetypes, styles)
}

/// The ENTITIES section's records, each with its properties and xdata.
fn entities(d: &Drawing, alloc: &mut impl FnMut() -> u64) -> DxfWriter {
    let mut ents = DxfWriter::new();
    for (e, src) in d.entities_with_sources() {
        if let (EntityKind::Unmodelled { .. }, Some(s)) = (&e.kind, src) {
            // An INSERT (with its ATTRIBs) or ATTDEF a script made: kept as its groups.
            kept_groups(&mut ents, e, s);
            continue;
        }
        let xdata = d.new_entity_xdata(e.handle);
        if xdata.is_none() && d.props(e.handle).is_none() {
            write_entity(&mut ents, e, H_MODEL_RECORD, alloc);
            continue;
        }
        let mut one = DxfWriter::new();
        write_entity(&mut one, e, H_MODEL_RECORD, alloc);
        let text = d.with_props(e.handle, &e.kind, one.out);
        match xdata {
            None => ents.out.push_str(&text),
            Some(x) => ents
                .out
                .push_str(&super::objects::splice_xdata(&text, x, false)),
        }
    }
    ents
}

fn write_header(
    w: &mut DxfWriter,
    d: &Drawing,
    extents: Option<(DVec3, DVec3)>,
    handseed: u64,
    insunits: i32,
) {
    // ---- HEADER ----: the variables no drawing changes come prepared, in three runs.
    w.out.push_str(prepared(&HEADER_HEAD, |w| {
        w.str(0, "SECTION");
        w.str(2, "HEADER");
        var(w, "$ACADVER");
        w.str(1, "AC1015");
        var(w, "$ACADMAINTVER");
        w.int(70, 6);
        var(w, "$DWGCODEPAGE");
        w.str(3, "ANSI_1252");
        var(w, "$INSBASE");
        w.point(10, DVec3::ZERO);
        var(w, "$EXTMIN");
    }));
    let (lo, hi) = extents.unwrap_or((DVec3::splat(1e20), DVec3::splat(-1e20)));
    w.point(10, lo);
    var(w, "$EXTMAX");
    w.point(10, hi);
    w.out.push_str(prepared(&HEADER_LIMITS, |w| {
        var(w, "$LIMMIN");
        w.point2(10, DVec2::ZERO);
        var(w, "$LIMMAX");
        w.point2(10, DVec2::new(420.0, 297.0));
        var(w, "$LTSCALE");
        w.float(40, 1.0);
        var(w, "$TEXTSTYLE");
        w.str(7, "Standard");
        var(w, "$CLAYER");
    }));
    w.str(8, d.current_layer());
    w.out.push_str(prepared(&HEADER_UNITS, |w| {
        var(w, "$CELTYPE");
        w.str(6, "ByLayer");
        var(w, "$CECOLOR");
        w.int(62, 256);
        var(w, "$DIMSTYLE");
        w.str(2, "Standard");
        var(w, "$LUNITS");
        w.int(70, 2);
        var(w, "$AUNITS");
        w.int(70, 0);
        var(w, "$HANDSEED");
    }));
    w.handle(5, handseed);
    var(w, "$MEASUREMENT");
    w.int(70, super::measurement(insunits) as i64);
    var(w, "$INSUNITS");
    w.int(70, insunits as i64);
    w.str(0, "ENDSEC");
}

/// A header variable's name group.
fn var(w: &mut DxfWriter, name: &str) {
    w.str(9, name);
}

/// The active viewport, framing the drawing's extents.
fn write_vport(w: &mut DxfWriter, extents: Option<(DVec3, DVec3)>) {
    table(w, "VPORT", H_VPORT_TABLE, 1);
    record(
        w,
        "VPORT",
        H_VPORT_ACTIVE,
        H_VPORT_TABLE,
        "AcDbViewportTableRecord",
    );
    w.str(2, "*Active");
    w.int(70, 0);
    w.point2(10, DVec2::ZERO);
    w.point2(11, DVec2::ONE);
    let (center, height) = match extents {
        Some((lo, hi)) => (
            ((lo + hi) / 2.0).truncate(),
            ((hi - lo).y.max((hi - lo).x / 1.5)).max(1.0) * 1.1,
        ),
        None => (DVec2::new(210.0, 148.5), 297.0),
    };
    w.point2(12, center);
    w.point2(13, DVec2::ZERO);
    w.point2(14, DVec2::splat(10.0));
    w.point2(15, DVec2::splat(10.0));
    w.point(16, DVec3::Z);
    w.point(17, DVec3::ZERO);
    w.float(40, height);
    w.float(41, 1.5);
    w.float(42, 50.0);
    w.float(43, 0.0);
    w.float(44, 0.0);
    w.float(50, 0.0);
    w.float(51, 0.0);
    w.int(71, 0);
    w.int(72, 1000);
    w.int(73, 1);
    w.int(74, 3);
    w.int(75, 0);
    w.int(76, 0);
    w.int(77, 0);
    w.int(78, 0);
    w.str(0, "ENDTAB");
}

/// The LTYPE, LAYER, STYLE, VIEW/UCS and APPID tables.
fn write_tables(w: &mut DxfWriter, d: &Drawing, t: &Tables) {
    table(w, "LTYPE", H_LTYPE_TABLE, 3 + t.linetypes.len());
    fn continuous_like(w: &mut DxfWriter, h: u64, name: &str, desc: &str) {
        record(w, "LTYPE", h, H_LTYPE_TABLE, "AcDbLinetypeTableRecord");
        w.solid_linetype_fields(name, desc);
    }
    w.out.push_str(prepared(&LTYPE_FIXED, |w| {
        continuous_like(w, H_LTYPE_BYBLOCK, "ByBlock", "");
        continuous_like(w, H_LTYPE_BYLAYER, "ByLayer", "");
        continuous_like(w, H_LTYPE_CONTINUOUS, "Continuous", "Solid line");
    }));
    // Line types the drawing names but does not define are written solid, so a reader never
    // meets an undefined name.
    for (lt, h) in t.linetypes.iter().zip(&t.ltype_handles) {
        continuous_like(w, *h, lt, "");
    }
    w.str(0, "ENDTAB");

    table(w, "LAYER", H_LAYER_TABLE, d.layers().len());
    for (l, h) in d.layers().iter().zip(&t.layer_handles) {
        record(w, "LAYER", *h, H_LAYER_TABLE, "AcDbLayerTableRecord");
        w.str(2, &l.name);
        w.int(70, (l.frozen as i64) | ((l.locked as i64) << 2));
        w.int(62, l.color as i64);
        w.str(6, &l.linetype);
        w.int(370, -3);
        w.handle(390, H_PLOTSTYLE_NORMAL);
    }
    w.str(0, "ENDTAB");

    table(w, "STYLE", H_STYLE_TABLE, 1 + t.styles.len());
    fn style(w: &mut DxfWriter, h: u64, name: &str) {
        record(w, "STYLE", h, H_STYLE_TABLE, "AcDbTextStyleTableRecord");
        w.str(2, name);
        w.text_style_fields();
    }
    w.out.push_str(prepared(&STYLE_STANDARD, |w| {
        style(w, H_STYLE_STANDARD, "Standard");
    }));
    for (name, h) in t.styles.iter().zip(&t.style_handles) {
        style(w, *h, name);
    }
    w.str(0, "ENDTAB");

    w.out.push_str(prepared(&VIEW_UCS, write_view_ucs));
    // Scripts register applications (regapp), so APPID is the drawing's own.
    table(w, "APPID", H_APPID_TABLE, t.appids.len());
    for (name, h) in t
        .appids
        .iter()
        .zip(std::iter::once(H_APPID_ACAD).chain(t.appid_handles.iter().copied()))
    {
        record(w, "APPID", h, H_APPID_TABLE, "AcDbRegAppTableRecord");
        w.str(2, name);
        w.int(70, 0);
    }
    w.str(0, "ENDTAB");
}

/// The OBJECTS section's opening, then the dictionaries and objects scripts added.
fn write_drawing_objects(w: &mut DxfWriter, d: &Drawing) {
    // ---- OBJECTS ----
    w.str(0, "SECTION");
    w.str(2, "OBJECTS");
    // The root and group dictionaries are the ones scripts can add to (dictadd).
    for h in [H_ROOT_DICT, H_GROUP_DICT] {
        if let Some(t) = d.object(h) {
            for (c, v) in t.iter() {
                w.str(c as u16, v);
            }
        }
    }
    for t in d.owned_new_objects() {
        if t.handle()
            .is_some_and(|h| h != H_ROOT_DICT && h != H_GROUP_DICT)
        {
            for (c, v) in t.iter() {
                w.str(c as u16, v);
            }
        }
    }
}

/// Handles for table records: the one `tblobjname` gave a record, else a fresh one.
fn record_handles<S: AsRef<str>>(
    d: &Drawing,
    table: &str,
    names: impl Iterator<Item = S>,
    alloc: &mut impl FnMut() -> u64,
) -> Vec<u64> {
    names
        .map(|n| {
            d.given_table_handle(table, n.as_ref())
                .unwrap_or_else(&mut *alloc)
        })
        .collect()
}

fn table(w: &mut DxfWriter, name: &str, h: u64, count: usize) {
    w.str(0, "TABLE");
    w.str(2, name);
    w.handle(5, h);
    w.handle(330, 0);
    w.str(100, "AcDbSymbolTable");
    w.int(70, count as i64);
}

fn record(w: &mut DxfWriter, kind: &str, h: u64, owner: u64, subclass: &str) {
    w.str(0, kind);
    w.handle(5, h);
    w.handle(330, owner);
    w.str(100, "AcDbSymbolTableRecord");
    w.str(100, subclass);
}

/// The parts of the file no drawing changes, written once per process and copied into every
/// file after (a batch writes thousands of files with the same boilerplate). Each is written by
/// the same group calls as the rest, so the bytes are the same as writing it in place.
static CLASSES: OnceLock<String> = OnceLock::new();
static VIEW_UCS: OnceLock<String> = OnceLock::new();
static TABLES_TAIL: OnceLock<String> = OnceLock::new();
static OBJECTS: OnceLock<String> = OnceLock::new();
static HEADER_HEAD: OnceLock<String> = OnceLock::new();
static HEADER_LIMITS: OnceLock<String> = OnceLock::new();
static HEADER_UNITS: OnceLock<String> = OnceLock::new();
static LTYPE_FIXED: OnceLock<String> = OnceLock::new();
static STYLE_STANDARD: OnceLock<String> = OnceLock::new();
static BLOCK_RECORDS_FIXED: OnceLock<String> = OnceLock::new();
static SPACE_BLOCKS: OnceLock<String> = OnceLock::new();

fn prepared(cell: &'static OnceLock<String>, write: fn(&mut DxfWriter)) -> &'static str {
    cell.get_or_init(|| {
        let mut w = DxfWriter::new();
        write(&mut w);
        w.out
    })
}

fn write_classes(w: &mut DxfWriter) {
    // ---- CLASSES: the class-defined objects used in OBJECTS ----
    w.str(0, "SECTION");
    w.str(2, "CLASSES");
    for (dxf_name, cpp_name) in [
        ("ACDBDICTIONARYWDFLT", "AcDbDictionaryWithDefault"),
        ("ACDBPLACEHOLDER", "AcDbPlaceHolder"),
        ("LAYOUT", "AcDbLayout"),
    ] {
        w.str(0, "CLASS");
        w.str(1, dxf_name);
        w.str(2, cpp_name);
        w.str(3, "ObjectDBX Classes");
        w.int(90, 0);
        w.int(280, 0);
        w.int(281, 0);
    }
    w.str(0, "ENDSEC");
}

/// The empty VIEW and UCS tables, between STYLE and APPID.
fn write_view_ucs(w: &mut DxfWriter) {
    table(w, "VIEW", H_VIEW_TABLE, 0);
    w.str(0, "ENDTAB");
    table(w, "UCS", H_UCS_TABLE, 0);
    w.str(0, "ENDTAB");
}

/// The DIMSTYLE table, after APPID (it does not depend on the drawing).
fn write_tables_tail(w: &mut DxfWriter) {
    table(w, "DIMSTYLE", H_DIMSTYLE_TABLE, 1);
    w.str(100, "AcDbDimStyleTable");
    w.str(0, "DIMSTYLE");
    w.handle(105, H_DIMSTYLE_STANDARD);
    w.handle(330, H_DIMSTYLE_TABLE);
    w.str(100, "AcDbSymbolTableRecord");
    w.str(100, "AcDbDimStyleTableRecord");
    w.str(2, "Standard");
    w.int(70, 0);
    w.float(40, 1.0);
    w.float(41, 2.5);
    w.float(42, 0.625);
    w.float(43, 3.75);
    w.float(44, 1.25);
    w.float(140, 2.5);
    w.float(141, 2.5);
    w.float(147, 0.625);
    w.int(77, 1);
    w.int(78, 8);
    w.int(271, 2);
    w.int(272, 2);
    w.handle(340, H_STYLE_STANDARD);
    w.str(0, "ENDTAB");
}

/// The BLOCK_RECORD table, the BLOCKS section (model and paper space, then the blocks a
/// script defined) and the head of the ENTITIES section.
fn write_blocks(w: &mut DxfWriter, d: &Drawing) {
    let groups = |w: &mut DxfWriter, t: &TagList| {
        for (c, v) in t.iter() {
            w.str(c as u16, v);
        }
    };
    let user = d.new_block_records();
    table(w, "BLOCK_RECORD", H_BLOCK_RECORD_TABLE, 2 + user.len());
    w.out
        .push_str(prepared(&BLOCK_RECORDS_FIXED, write_space_records));
    for r in user {
        groups(w, r);
    }
    w.out.push_str(prepared(&SPACE_BLOCKS, write_space_blocks));
    for r in d.block_section() {
        groups(w, r);
    }
    w.str(0, "ENDSEC");

    // ---- ENTITIES ----
    w.str(0, "SECTION");
    w.str(2, "ENTITIES");
}

/// The model and paper space records of the BLOCK_RECORD table.
fn write_space_records(w: &mut DxfWriter) {
    for (h, name, layout) in [
        (H_MODEL_RECORD, "*Model_Space", H_MODEL_LAYOUT),
        (H_PAPER_RECORD, "*Paper_Space", H_PAPER_LAYOUT),
    ] {
        record(
            w,
            "BLOCK_RECORD",
            h,
            H_BLOCK_RECORD_TABLE,
            "AcDbBlockTableRecord",
        );
        w.str(2, name);
        w.handle(340, layout);
    }
}

/// The end of the TABLES section, and the BLOCKS section's model and paper space blocks.
fn write_space_blocks(w: &mut DxfWriter) {
    w.str(0, "ENDTAB");
    w.str(0, "ENDSEC");

    // ---- BLOCKS ----
    w.str(0, "SECTION");
    w.str(2, "BLOCKS");
    for (rec, blk, end, name) in [
        (
            H_MODEL_RECORD,
            H_MODEL_BLOCK,
            H_MODEL_ENDBLK,
            "*Model_Space",
        ),
        (
            H_PAPER_RECORD,
            H_PAPER_BLOCK,
            H_PAPER_ENDBLK,
            "*Paper_Space",
        ),
    ] {
        w.str(0, "BLOCK");
        w.handle(5, blk);
        w.handle(330, rec);
        w.str(100, "AcDbEntity");
        if rec == H_PAPER_RECORD {
            w.int(67, 1);
        }
        w.str(8, "0");
        w.str(100, "AcDbBlockBegin");
        w.str(2, name);
        w.int(70, 0);
        w.point(10, DVec3::ZERO);
        w.str(3, name);
        w.str(1, "");
        w.str(0, "ENDBLK");
        w.handle(5, end);
        w.handle(330, rec);
        w.str(100, "AcDbEntity");
        if rec == H_PAPER_RECORD {
            w.int(67, 1);
        }
        w.str(8, "0");
        w.str(100, "AcDbBlockEnd");
    }
}

/// The OBJECTS section after the dictionaries scripts can change, and EOF.
fn write_objects(w: &mut DxfWriter) {
    let dict = |w: &mut DxfWriter, h: u64, owner: u64, entries: &[(&str, u64)]| {
        w.str(0, "DICTIONARY");
        w.handle(5, h);
        w.handle(330, owner);
        w.str(100, "AcDbDictionary");
        w.int(281, 1);
        for (k, v) in entries {
            w.str(3, k);
            w.handle(350, *v);
        }
    };
    dict(
        w,
        H_LAYOUT_DICT,
        H_ROOT_DICT,
        &[("Layout1", H_PAPER_LAYOUT), ("Model", H_MODEL_LAYOUT)],
    );
    dict(
        w,
        H_MLINESTYLE_DICT,
        H_ROOT_DICT,
        &[("Standard", H_MLINESTYLE_STANDARD)],
    );
    w.str(0, "ACDBDICTIONARYWDFLT");
    w.handle(5, H_PLOTSTYLE_DICT);
    w.handle(330, H_ROOT_DICT);
    w.str(100, "AcDbDictionary");
    w.int(281, 1);
    w.str(3, "Normal");
    w.handle(350, H_PLOTSTYLE_NORMAL);
    w.str(100, "AcDbDictionaryWithDefault");
    w.handle(340, H_PLOTSTYLE_NORMAL);
    w.str(0, "ACDBPLACEHOLDER");
    w.handle(5, H_PLOTSTYLE_NORMAL);
    w.handle(330, H_PLOTSTYLE_DICT);
    w.str(0, "MLINESTYLE");
    w.handle(5, H_MLINESTYLE_STANDARD);
    w.handle(330, H_MLINESTYLE_DICT);
    w.str(100, "AcDbMlineStyle");
    w.str(2, "Standard");
    w.int(70, 0);
    w.str(3, "");
    w.int(62, 256);
    w.float(51, 90.0);
    w.float(52, 90.0);
    w.int(71, 2);
    w.float(49, 0.5);
    w.int(62, 256);
    w.str(6, "BYLAYER");
    w.float(49, -0.5);
    w.int(62, 256);
    w.str(6, "BYLAYER");
    for (h, name, flag, order, rec) in [
        (H_MODEL_LAYOUT, "Model", 1024, 0, H_MODEL_RECORD),
        (H_PAPER_LAYOUT, "Layout1", 0, 1, H_PAPER_RECORD),
    ] {
        write_layout(w, h, name, flag, order, rec);
    }
    w.str(0, "ENDSEC");
    w.str(0, "EOF");
}

fn write_layout(w: &mut DxfWriter, h: u64, name: &str, plot_flags: i64, order: i64, rec: u64) {
    w.str(0, "LAYOUT");
    w.handle(5, h);
    w.handle(330, H_LAYOUT_DICT);
    w.str(100, "AcDbPlotSettings");
    w.str(1, "");
    w.str(4, "A3");
    w.str(6, "");
    for (c, v) in [
        (40, 7.5),
        (41, 20.0),
        (42, 7.5),
        (43, 20.0),
        (44, 420.0),
        (45, 297.0),
        (46, 0.0),
        (47, 0.0),
        (48, 0.0),
        (49, 0.0),
        (140, 0.0),
        (141, 0.0),
        (142, 1.0),
        (143, 1.0),
    ] {
        w.float(c, v);
    }
    w.int(70, plot_flags);
    w.int(72, 1);
    w.int(73, 0);
    w.int(74, 5);
    w.str(7, "");
    w.int(75, 16);
    w.float(147, 1.0);
    w.float(148, 0.0);
    w.float(149, 0.0);
    w.str(100, "AcDbLayout");
    w.str(1, name);
    w.int(70, 1);
    w.int(71, order);
    w.point2(10, DVec2::ZERO);
    w.point2(11, DVec2::new(420.0, 297.0));
    w.point(12, DVec3::ZERO);
    w.point(14, DVec3::splat(1e20));
    w.point(15, DVec3::splat(-1e20));
    w.float(146, 0.0);
    w.point(13, DVec3::ZERO);
    w.point(16, DVec3::X);
    w.point(17, DVec3::Y);
    w.int(76, 1);
    w.handle(330, rec);
}
