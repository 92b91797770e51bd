//! `entget` lists of entities lispcad keeps as their file groups (INSERT, ATTRIB, MTEXT,
//! HATCH, DIMENSION...): the groups as read, typed as AutoCAD's `entget` types them (points
//! joined, reals, integers, handles as entity names, angles in radians).

use super::dxf_list::pair;
use super::ename_value;
use crate::lang::error::Exn;
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

/// `entmod` of a record kept as its groups (record `index`: 0 the entity, else an ATTRIB or
/// VERTEX follower): each group of the list replaces the record's group with its code, the
/// i-th of a repeated code the i-th (as AutoCAD matches them); a code the record lacks is
/// added at the end of its data. Handles, owners, subclass markers, application data and
/// extended data are kept; at index 0 the layer and colour are the drawing's (set by the
/// caller). A group equal to the `old` list's (the record's `entget`) is left as it was
/// read. `None` when the list has more of a code than the record can take.
pub fn modify_tags(
    it: &Interp,
    t: &TagList,
    index: usize,
    groups: &super::dxf_list::Groups,
    old: &super::dxf_list::Groups,
) -> Result<Option<TagList>, Exn> {
    let Some(range) = records(t).get(index).cloned() else {
        return Ok(None);
    };
    let ty = t.at(range.start).1.to_string();
    let mut rec: Vec<(i32, String)> = range
        .clone()
        .map(|i| (t.at(i).0, t.at(i).1.to_string()))
        .collect();
    let kept = |c: i32| {
        matches!(c, -5..=0 | 5 | 105 | 100 | 102 | 330 | 360)
            || c >= 1000
            || (index == 0 && matches!(c, 8 | 62))
    };
    // Where each code occurs in the record's own data (not in application or extended data).
    let data_end = rec
        .iter()
        .position(|(c, _)| *c >= 1000)
        .unwrap_or(rec.len());
    let mut in_app = false;
    let mut slots: Vec<(i32, usize)> = Vec::new();
    for (k, (c, v)) in rec[..data_end].iter().enumerate() {
        if *c == 102 {
            in_app = v.starts_with('{');
        } else if !in_app && k > 0 {
            slots.push((*c, k));
        }
    }
    let mut seen: Vec<(i32, usize)> = Vec::new();
    let mut added: Vec<(i32, String)> = Vec::new();
    for (c, v) in &groups.0 {
        let c = *c;
        if kept(c) {
            continue;
        }
        let n = match seen.iter_mut().find(|(x, _)| *x == c) {
            Some((_, n)) => {
                *n += 1;
                *n - 1
            }
            None => {
                seen.push((c, 1));
                0
            }
        };
        // A group given back as `entget` gave it keeps its text exactly.
        let unchanged = old
            .0
            .iter()
            .filter(|(x, _)| *x == c)
            .nth(n)
            .is_some_and(|(_, ov)| ov.equal(v, 0.0));
        if unchanged {
            continue;
        }
        let texts = group_texts(it, c, v, &ty)?;
        match slots.iter().filter(|(x, _)| *x == c).nth(n) {
            Some(&(_, k)) => {
                // A point's coordinates follow its x group.
                for (j, (code, text)) in texts.into_iter().enumerate() {
                    match rec.get_mut(k + j) {
                        Some(g) if g.0 == code => g.1 = text,
                        _ => {}
                    }
                }
            }
            None if n == 0 => added.extend(texts),
            None => return Ok(None),
        }
    }
    let at = data_end;
    rec.splice(at..at, added);
    let mut out = TagList::new();
    for i in 0..range.start {
        let (c, v) = t.at(i);
        out.push(c, v);
    }
    for (c, v) in &rec {
        out.push(*c, v);
    }
    for i in range.end..t.len() {
        let (c, v) = t.at(i);
        out.push(c, v);
    }
    Ok(Some(out))
}

/// A list value as the group(s) of a file: a point as its x, y (and z) groups, an angle in
/// degrees, an entity name as its handle, numbers as DXF writes them.
pub(crate) fn group_texts(
    it: &Interp,
    c: i32,
    v: &Value,
    ty: &str,
) -> Result<Vec<(i32, String)>, Exn> {
    let bad = || super::dxf_list::bad_group(it, &pair(c, v.clone()));
    let real = |x: f64| {
        let mut s = String::new();
        crate::output::dxf_writer::push_float(&mut s, x);
        s
    };
    if matches!(c, 10..=18 | 110..=112 | 210) && matches!(v, Value::Cons(_)) {
        let p: Vec<f64> = v
            .iter()
            .map(|x| x.as_f64().filter(|x| x.is_finite()))
            .collect::<Option<_>>()
            .ok_or_else(bad)?;
        if !(2..=3).contains(&p.len()) {
            return Err(bad());
        }
        return Ok(p
            .iter()
            .enumerate()
            .map(|(i, x)| (c + 10 * i as i32, real(*x)))
            .collect());
    }
    let text = match (value_type(c), v) {
        (_, Value::Obj(_)) if matches!(c, 320..=369 | 390..=399 | 480 | 481) => {
            let e = super::ename_arg(it, v)?;
            format!("{:X}", e.handle)
        }
        (ValueType::Float, _) => {
            let x = v.as_f64().filter(|x| x.is_finite()).ok_or_else(bad)?;
            real(if matches!(c, 50..=58) && ty != "MTEXT" {
                x.to_degrees()
            } else {
                x
            })
        }
        (
            ValueType::Int16 | ValueType::Int32 | ValueType::Int64 | ValueType::Bool,
            Value::Int(i),
        ) => i.to_string(),
        (ValueType::Str | ValueType::Binary, Value::Str(s)) => s.to_string(),
        _ => return Err(bad()),
    };
    Ok(vec![(c, text)])
}
