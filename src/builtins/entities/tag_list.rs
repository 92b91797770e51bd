//! `entget` lists of entities lispcad keeps as their file groups (INSERT, ATTRIB, MTEXT,
//! HATCH, DIMENSION...): the groups as read, typed as AutoCAD's `entget` types them (points
//! joined, reals, integers, handles as entity names, angles in radians).

use super::dxf_list::pair;
use super::ename_value;
use crate::lang::{Interp, Value};
use crate::output::dxfin::tags::{value_type, ValueType};
use crate::output::record::TagList;

use crate::output::dxfin::factory::record_ranges as records;

/// The number of followers before a closing SEQEND (ATTRIBs of an INSERT, VERTEXes of a
/// POLYLINE), when the group list has a SEQEND.
pub fn follower_count(t: &TagList) -> Option<u32> {
    let r = records(t);
    let last = r.last()?;
    (r.len() >= 2 && t.at(last.start).1 == "SEQEND").then(|| (r.len() - 2) as u32)
}

/// A table record's groups as `tblsearch` gives them: no handles, owners, subclass markers
/// or application data (AutoCAD leaves them out too).
pub fn table_record_list(it: &mut Interp, t: &TagList) -> Value {
    let groups: Vec<(i32, &str)> = t
        .iter()
        .take(t.first_record_end())
        .filter(|(c, _)| !matches!(c, 5 | 105 | 100 | 330 | 340 | 348 | 360 | 390))
        .collect();
    let mut out = vec![pair(0, Value::str(groups[0].1))];
    typed_groups_with(it, &groups, &mut out, None);
    Value::list(out)
}

/// The `entget` list of a non-graphical record (DICTIONARY, XRECORD, table record) named
/// `me`: its groups with handles as entity names, application data left out.
pub fn object_list(it: &mut Interp, t: &TagList, me: Value) -> Value {
    let groups: Vec<(i32, &str)> = t.iter().take(t.first_record_end()).collect();
    let mut out = vec![pair(-1, me), pair(0, Value::str(groups[0].1))];
    typed_groups_with(it, &groups, &mut out, None);
    Value::list(out)
}

/// The `entget` list of record `index` (0 = the entity) of a group list, named `me`, on
/// `layer` with `color` (the drawing's values: a script may have changed them).
pub fn tags_entity_list(
    it: &mut Interp,
    t: &TagList,
    index: usize,
    me: Value,
    layer: &str,
    color: Option<i16>,
) -> Option<Value> {
    let r = records(t).get(index)?.clone();
    let groups: Vec<(i32, &str)> = r.map(|i| t.at(i)).collect();
    let ty = groups[0].1;
    let mut out = vec![pair(-1, me), pair(0, Value::str(ty))];
    let layer_color = (layer, color);
    typed_groups_with(it, &groups, &mut out, Some(layer_color));
    Some(Value::list(out))
}

/// Groups after the leading 0 group as typed `entget` pairs; with `lc`, the layer (8) and
/// colour (62) are the drawing's.
fn typed_groups_with(
    it: &mut Interp,
    groups: &[(i32, &str)],
    out: &mut Vec<Value>,
    lc: Option<(&str, Option<i16>)>,
) {
    let ty = groups[0].1;
    let mut i = 1;
    let mut in_app = false;
    let mut color_done = false;
    while i < groups.len() {
        let (c, v) = groups[i];
        i += 1;
        if c == 102 {
            in_app = v.starts_with('{');
            continue;
        }
        if in_app || c >= 1000 {
            // Application data and extended data are not part of a plain entget list.
            continue;
        }
        let value = match (c, lc) {
            (8, Some((layer, _))) => Value::str(layer),
            (62, Some((_, color))) => {
                color_done = true;
                match color {
                    Some(c) => Value::Int(c as i32),
                    None => Value::Int(256),
                }
            }
            _ => typed_value(it, groups, &mut i, c, v, ty),
        };
        out.push(pair(c, value));
        if let (8, Some((_, Some(col))), false) = (c, lc, color_done) {
            if !groups.iter().any(|(c, _)| *c == 62) {
                out.push(pair(62, Value::Int(col as i32)));
                color_done = true;
            }
        }
    }
}

/// One group's value; a point consumes its y and z groups (advancing `i`).
fn typed_value(
    it: &mut Interp,
    groups: &[(i32, &str)],
    i: &mut usize,
    c: i32,
    v: &str,
    ty: &str,
) -> Value {
    match c {
        5 | 105 => Value::str(v),
        320..=369 | 390..=399 | 480 | 481 => match u64::from_str_radix(v.trim(), 16) {
            Ok(h) => ename_value(it, h),
            Err(_) => Value::str(v),
        },
        10..=18 | 110..=112 | 210 => {
            // A point: x, and y/z when they follow.
            let mut p = vec![Value::Real(num(v))];
            for k in [10, 20] {
                match groups.get(*i) {
                    Some((c2, v2)) if *c2 == c + k => {
                        p.push(Value::Real(num(v2)));
                        *i += 1;
                    }
                    _ => break,
                }
            }
            Value::list(p)
        }
        // An XRECORD keeps its data as given (no degrees in the file).
        50..=58 if ty != "MTEXT" && ty != "XRECORD" => Value::Real(num(v).to_radians()),
        _ => match value_type(c) {
            ValueType::Float => Value::Real(num(v)),
            ValueType::Int16 | ValueType::Int32 | ValueType::Int64 | ValueType::Bool => {
                Value::Int(num(v) as i32)
            }
            _ => Value::str(v),
        },
    }
}

fn num(v: &str) -> f64 {
    v.trim().parse().unwrap_or(0.0)
}
