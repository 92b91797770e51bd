//! Symbol tables as AutoLISP sees them: `tblsearch`/`tblnext` over LAYER (the drawing's
//! layers), and, for an opened drawing, every table of the file and its BLOCK definitions;
//! for a drawing made from scratch LTYPE (Continuous and the line types layers name) and
//! STYLE (Standard and the styles text uses). `entmake` of LAYER records.

use super::dxf_list::{int, real, text, Groups};
use super::EntityState;
use crate::builtins::drawing::drawing;
use crate::lang::error::{Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::record::TagList;
use crate::output::{Drawing, EntityKind, Layer};

/// The records of an opened drawing's table, as read, or the BLOCK definitions of any
/// drawing; `None` for another table of a drawing made from scratch or for LAYER, which
/// follows the drawing's layers.
fn opened_records(it: &mut Interp, table: &str) -> Option<Vec<(String, Value)>> {
    if table == "BLOCK" {
        return Some(block_records(it));
    }
    let doc = drawing(it).document()?;
    let recs: Vec<TagList> = match table {
        "LAYER" => return None,
        _ => doc.table(table)?.records.clone(),
    };
    Some(
        recs.iter()
            .map(|r| {
                let name = r.get(2).unwrap_or("").to_string();
                (name, super::tag_list::table_record_list(it, r))
            })
            .collect(),
    )
}

/// The BLOCK table as `tblsearch` gives it (the opened file's blocks and those `entmake`
/// defined): name, flags, base point, and -2 the first entity of the definition.
fn block_records(it: &mut Interp) -> Vec<(String, Value)> {
    let recs = drawing(it).block_section().to_vec();
    let mut out = Vec::new();
    for (i, r) in recs.iter().enumerate() {
        // Model and paper space are layouts, not blocks, to tblnext.
        let layout = r.get(2).is_some_and(|n| {
            n.starts_with("*Model_Space") || n.to_ascii_uppercase().starts_with("*PAPER_SPACE")
        });
        if r.type_name() != "BLOCK" || layout {
            continue;
        }
        let name = r.get(2).unwrap_or("").to_string();
        let list = super::tag_list::table_record_list(it, r);
        let mut items: Vec<Value> = list
            .iter()
            .filter(|g| {
                let code = match g.car() {
                    Value::Int(c) => c,
                    _ => 0,
                };
                let empty_path = code == 1 && g.cdr().as_str() == Some("");
                !matches!(code, 3 | 8) && !empty_path
            })
            .cloned()
            .collect();
        let first = recs.get(i + 1).filter(|f| f.type_name() != "ENDBLK");
        if let Some(h) = first.and_then(TagList::handle) {
            items.push(Value::cons(Value::Int(-2), super::ename_value(it, h)));
        }
        out.push((name, Value::list(items)));
    }
    out
}

/// The records of a table, each as (name, DXF list), in table order.
pub(super) fn records(it: &mut Interp, table: &str) -> Vec<(String, Value)> {
    if let Some(r) = opened_records(it, table) {
        return r;
    }
    let d: &Drawing = drawing(it);
    match table {
        "LAYER" => d
            .layers()
            .iter()
            .map(|l| {
                let flags = i32::from(l.frozen) | if l.locked { 4 } else { 0 };
                let list = Value::list([
                    text(0, "LAYER"),
                    text(2, &l.name),
                    int(70, flags),
                    int(62, l.color as i32),
                    text(6, &l.linetype),
                ]);
                (l.name.clone(), list)
            })
            .collect(),
        "LTYPE" => {
            let mut names: Vec<String> = vec!["Continuous".to_string()];
            let layer_types = d.layers().iter().map(|l| l.linetype.clone());
            // And those CHPROP gave entities (written solid, as layers' are).
            for lt in layer_types.chain(d.entity_linetypes()) {
                if !names.iter().any(|n| n.eq_ignore_ascii_case(&lt)) {
                    names.push(lt);
                }
            }
            names
                .into_iter()
                .map(|n| {
                    let descr = if n.eq_ignore_ascii_case("Continuous") {
                        "Solid line"
                    } else {
                        ""
                    };
                    let list = Value::list([
                        text(0, "LTYPE"),
                        text(2, &n),
                        int(70, 0),
                        text(3, descr),
                        int(72, 65),
                        int(73, 0),
                        real(40, 0.0),
                    ]);
                    (n, list)
                })
                .collect()
        }
        "STYLE" => {
            let mut names: Vec<String> = vec!["Standard".to_string()];
            for e in d.entities() {
                if let EntityKind::Text { style, .. } = &e.kind {
                    if !names.iter().any(|n| n.eq_ignore_ascii_case(style)) {
                        names.push(style.clone());
                    }
                }
            }
            names
                .into_iter()
                .map(|n| {
                    let list = Value::list([
                        text(0, "STYLE"),
                        text(2, &n),
                        int(70, 0),
                        real(40, 0.0),
                        real(41, 1.0),
                        real(50, 0.0),
                        int(71, 0),
                        real(42, 2.5),
                        text(3, "txt"),
                        text(4, ""),
                    ]);
                    (n, list)
                })
                .collect()
        }
        "APPID" => d
            .appids()
            .into_iter()
            .map(|n| {
                let list = Value::list([text(0, "APPID"), text(2, &n), int(70, 0)]);
                (n, list)
            })
            .collect(),
        _ => Vec::new(),
    }
}

fn set_cursor(it: &mut Interp, table: &str, pos: usize) {
    let st = it.ext::<EntityState>();
    match st.table_cursor.iter_mut().find(|(t, _)| t == table) {
        Some(c) => c.1 = pos,
        None => st.table_cursor.push((table.to_string(), pos)),
    }
}

pub fn tblsearch(it: &mut Interp, a: &[Value]) -> LResult {
    let table = it.string(&a[0])?.to_uppercase();
    let name = it.string(&a[1])?.to_string();
    let recs = records(it, &table);
    let Some(i) = recs.iter().position(|(n, _)| n.eq_ignore_ascii_case(&name)) else {
        return Ok(Value::Nil);
    };
    if a.get(2).is_some_and(Value::truthy) {
        set_cursor(it, &table, i + 1);
    }
    Ok(recs[i].1.clone())
}

pub fn tblnext(it: &mut Interp, a: &[Value]) -> LResult {
    let table = it.string(&a[0])?.to_uppercase();
    let rewind = a.get(1).is_some_and(Value::truthy);
    let pos = if rewind {
        0
    } else {
        it.ext::<EntityState>()
            .table_cursor
            .iter()
            .find(|(t, _)| *t == table)
            .map_or(0, |c| c.1)
    };
    let recs = records(it, &table);
    let Some((_, rec)) = recs.into_iter().nth(pos) else {
        set_cursor(it, &table, pos);
        return Ok(Value::Nil);
    };
    set_cursor(it, &table, pos + 1);
    Ok(rec)
}

/// `entmake` of a LAYER record: 2 name (required), 70 flags (1 frozen, 4 locked), 62 colour
/// (negative = off; default 7), 6 line type (default Continuous). A name already in the table
/// gives nil, as in AutoCAD.
pub fn make_layer(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    let Some(name) = g.string(it, 2)? else {
        return Ok(false);
    };
    let flags = g.int(it, 70)?.unwrap_or(0);
    let color = g.int(it, 62)?.unwrap_or(7);
    let linetype = g.string(it, 6)?.unwrap_or_else(|| "Continuous".to_string());
    if !(-255..=255).contains(&color) || color == 0 {
        return Ok(false);
    }
    let d = drawing(it);
    if d.layer(&name).is_some() {
        return Ok(false);
    }
    let layer = Layer {
        name,
        color: color as i16,
        linetype,
        frozen: flags & 1 != 0,
        locked: flags & 4 != 0,
    };
    Ok(d.set_layer_record(layer).is_ok())
}
