//! Extended data, registered applications, dictionaries, XRECORDs and table-record names as
//! AutoLISP sees them: `regapp`, the `(-3 ("APP" ...))` group of `entmake`/`entmod`/`entget`,
//! `tblobjname`, `namedobjdict`, `dictsearch`/`dictnext`/`dictadd`/`dictremove`/`dictrename`,
//! and `entmake(x)` of XRECORD and DICTIONARY objects (made without an owner, as AutoCAD's
//! `entmakex` makes them, until `dictadd` gives them one). The storage is the drawing's
//! (`output/objects.rs`), so all of it is written to DXF.

use std::collections::HashMap;

use super::dxf_list::{bad_group, entity_list, pair, point_of, Groups};
use super::{ename_arg, ename_value, Ename};
use crate::builtins::drawing::drawing;
use crate::builtins::text::wcmatch::WcPattern;
use crate::lang::error::{Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::dxf::push_float;
use crate::output::dxfin::tags::{value_type, ValueType};
use crate::output::objects::{owner_of, with_owner};
use crate::output::record::TagList;

/// `dictnext` positions per dictionary handle.
#[derive(Default)]
struct DictCursors(HashMap<u64, usize>);

/// One `(code . value)` pair as DXF groups: a point as its x, y and z groups (code,
/// code + 10, code + 20), an entity name as its handle, numbers as the code's type wants.
fn push_value(it: &Interp, t: &mut TagList, code: i32, v: &Value) -> Result<(), Exn> {
    let bad = || bad_group(it, &pair(code, v.clone()));
    let float = |t: &mut TagList, c: i32, x: f64| {
        let mut s = String::new();
        push_float(&mut s, x);
        t.push(c, &s);
    };
    let is_float = matches!(value_type(code), ValueType::Float);
    match v {
        Value::Cons(_) => {
            let p = point_of(it, code, v)?;
            for (k, x) in [p.x, p.y, p.z].into_iter().enumerate() {
                float(t, code + 10 * k as i32, x);
            }
        }
        Value::Str(s) => t.push(code, s),
        Value::Int(i) if is_float => float(t, code, *i as f64),
        Value::Int(i) => t.push(code, &i.to_string()),
        Value::Real(x) if x.is_finite() && is_float => float(t, code, *x),
        Value::Real(x) if x.is_finite() && x.fract() == 0.0 && x.abs() < 2.2e9 => {
            t.push(code, &(*x as i64).to_string())
        }
        _ => match v.as_obj::<Ename>() {
            Some(e) => t.push(code, &format!("{:X}", e.handle)),
            None => return Err(bad()),
        },
    }
    Ok(())
}

// ---- extended data ----

/// The extended data of a list's -3 group.
pub enum XdataIn {
    Absent,
    /// An application in it is not registered: `entmake`/`entmod` return nil.
    Unregistered,
    /// Per application: its name and its groups (from its 1001 on; just the 1001 for
    /// `("APP")`, which removes the application's data in `entmod`).
    Apps(Vec<(String, TagList)>),
}

/// Parses `(-3 ("APP" (1000 . "x") (1010 1 2 3) ...) ...)`.
pub fn parse_xdata(it: &mut Interp, g: &Groups) -> Result<XdataIn, Exn> {
    let Some(x) = g.get(-3).cloned() else {
        return Ok(XdataIn::Absent);
    };
    let registered = drawing(it).appids();
    let mut apps = Vec::new();
    for app in x.iter() {
        let Some(name) = app.car().as_str().map(str::to_string) else {
            return Err(bad_group(it, &pair(-3, x.clone())));
        };
        if !registered.iter().any(|a| a.eq_ignore_ascii_case(&name)) {
            return Ok(XdataIn::Unregistered);
        }
        let mut t = TagList::new();
        t.push(1001, &name);
        let groups = Groups::parse(it, &app.cdr())?;
        for (code, v) in &groups.0 {
            let ok = match code {
                1000 | 1003..=1005 => v.as_str().is_some() || v.as_obj::<Ename>().is_some(),
                1002 => matches!(v.as_str(), Some("{") | Some("}")),
                1010..=1013 => matches!(v, Value::Cons(_)),
                1040..=1042 => v.as_f64().is_some(),
                1070 => matches!(v, Value::Int(i) if (-32768..=32767).contains(i)),
                1071 => matches!(v, Value::Int(_)),
                _ => false,
            };
            if !ok {
                return Err(bad_group(it, &pair(*code, v.clone())));
            }
            push_value(it, &mut t, *code, v)?;
        }
        apps.push((name, t));
    }
    Ok(XdataIn::Apps(apps))
}

/// An entity's extended data split per application.
fn split_apps(x: &TagList) -> Vec<(String, TagList)> {
    let mut out: Vec<(String, TagList)> = Vec::new();
    for (c, v) in x.iter() {
        if c == 1001 {
            out.push((v.to_string(), TagList::new()));
        }
        if let Some((_, t)) = out.last_mut() {
            t.push(c, v);
        }
    }
    out
}

/// Sets the applications' data on an entity; an application given without groups loses
/// its data, the others keep theirs (AutoCAD's `entmod` rule).
pub fn apply_xdata(it: &mut Interp, handle: u64, apps: Vec<(String, TagList)>) {
    let d = drawing(it);
    let mut all = split_apps(&d.xdata(handle));
    for (name, t) in apps {
        let at = all.iter().position(|(n, _)| n.eq_ignore_ascii_case(&name));
        match (at, t.len() > 1) {
            (Some(i), true) => all[i].1 = t,
            (Some(i), false) => {
                all.remove(i);
            }
            (None, true) => all.push((name, t)),
            (None, false) => {}
        }
    }
    let mut joined = TagList::new();
    for (_, t) in &all {
        for (c, v) in t.iter() {
            joined.push(c, v);
        }
    }
    d.set_xdata(handle, joined);
}

/// The `(-3 ...)` group of the entity's applications matching the patterns, or None.
pub fn xdata_group(it: &mut Interp, handle: u64, apps: &[String]) -> Option<Value> {
    let pats: Vec<WcPattern> = apps
        .iter()
        .map(|a| WcPattern::new(&a.to_uppercase()))
        .collect();
    let x = drawing(it).xdata(handle);
    let groups: Vec<(i32, &str)> = x.iter().collect();
    let num = |v: &str| v.trim().parse::<f64>().unwrap_or(0.0);
    let mut out = Vec::new();
    let mut i = 0;
    while i < groups.len() {
        let (c, name) = groups[i];
        i += 1;
        if c != 1001 {
            continue;
        }
        let mut items = vec![Value::str(name)];
        while i < groups.len() && groups[i].0 != 1001 {
            let (c, v) = groups[i];
            i += 1;
            let value = match c {
                1010..=1019 => {
                    let mut p = vec![Value::Real(num(v))];
                    for k in [10, 20] {
                        if let Some((_, v2)) = groups.get(i).filter(|(c2, _)| *c2 == c + k) {
                            p.push(Value::Real(num(v2)));
                            i += 1;
                        }
                    }
                    Value::list(p)
                }
                1040..=1059 => Value::Real(num(v)),
                1060..=1071 => Value::Int(num(v) as i32),
                _ => Value::str(v),
            };
            items.push(pair(c, value));
        }
        if pats.iter().any(|p| p.matches(&name.to_uppercase())) {
            out.push(Value::list(items));
        }
    }
    (!out.is_empty()).then(|| pair(-3, Value::list(out)))
}

/// Whether an entity's `(-3 ...)` value has every application a filter's -3 value names
/// (wild-card names, as in `(ssget "X" '((-3 ("APP*"))))`).
pub fn xdata_filter_match(want: &Value, got: &Value) -> bool {
    want.iter().all(|w| {
        let Some(p) = w.car().as_str().map(|s| WcPattern::new(&s.to_uppercase())) else {
            return false;
        };
        got.iter().any(|g| {
            g.car()
                .as_str()
                .is_some_and(|n| p.matches(&n.to_uppercase()))
        })
    })
}

/// A valid symbol-table name (what `snvalid` accepts).
fn valid_name(name: &str) -> bool {
    let n = name.chars().count();
    n > 0
        && n <= 255
        && name
            .chars()
            .all(|c| !c.is_control() && !"<>/\\\":;?*|,=`".contains(c))
}

pub fn regapp(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    if !valid_name(&name) || !drawing(it).add_appid(&name) {
        return Ok(Value::Nil);
    }
    Ok(Value::str(&name))
}

/// `entmake` of an APPID record.
pub fn make_appid(it: &mut Interp, g: &Groups) -> Result<bool, Exn> {
    let Some(name) = g.string(it, 2)? else {
        return Ok(false);
    };
    Ok(valid_name(&name) && drawing(it).add_appid(&name))
}

// ---- objects ----

/// The data groups of an XRECORD list: those after `(100 . "AcDbXrecord")` (and its 280
/// flag) when it is there, else every group but the header ones.
fn xrecord_data(g: &Groups) -> &[(i32, Value)] {
    let marker =
        g.0.iter()
            .position(|(c, v)| *c == 100 && v.as_str() == Some("AcDbXrecord"));
    match marker {
        Some(i) => {
            let rest = &g.0[i + 1..];
            match rest.first() {
                Some((280, _)) => &rest[1..],
                _ => rest,
            }
        }
        None => &g.0,
    }
}

fn xrecord_tags(it: &Interp, h: u64, owner: u64, g: &Groups) -> Result<TagList, Exn> {
    let mut t = TagList::new();
    t.push(0, "XRECORD");
    t.push(5, &format!("{h:X}"));
    t.push(330, &format!("{owner:X}"));
    t.push(100, "AcDbXrecord");
    t.push(280, "1");
    let data = xrecord_data(g);
    // Without the subclass marker the header groups are mixed in: the owner is not data.
    let unmarked = data.len() == g.0.len();
    for (c, v) in data {
        if matches!(c, -1 | 0 | 5 | 100 | 102) || (*c == 330 && unmarked) {
            continue;
        }
        push_value(it, &mut t, *c, v)?;
    }
    Ok(t)
}

/// `entmake`/`entmakex` of an XRECORD or DICTIONARY: a new object without an owner.
pub fn make_object(it: &mut Interp, ty: &str, g: &Groups) -> Result<Option<u64>, Exn> {
    let h = drawing(it).alloc_handle();
    let t = if ty == "XRECORD" {
        xrecord_tags(it, h, 0, g)?
    } else {
        let mut t = TagList::new();
        t.push(0, "DICTIONARY");
        t.push(5, &format!("{h:X}"));
        t.push(330, "0");
        t.push(100, "AcDbDictionary");
        if let Some(f) = g.int(it, 280)? {
            t.push(280, &f.to_string());
        }
        t.push(281, &g.int(it, 281)?.unwrap_or(1).to_string());
        t
    };
    Ok(drawing(it).put_object(t).then_some(h))
}

/// `entmod` of an object: an XRECORD's data is replaced; other objects are not modified.
pub fn modify_object(it: &mut Interp, h: u64, g: &Groups) -> Result<bool, Exn> {
    let Some(old) = drawing(it).object(h) else {
        return Ok(false);
    };
    if old.type_name() != "XRECORD" {
        return Ok(false);
    }
    let owner = owner_of(&old).unwrap_or(0);
    let t = xrecord_tags(it, h, owner, g)?;
    Ok(drawing(it).put_object(t))
}

/// The `entget` list of a handle that names no entity: an object, or a table record.
pub fn record_list(it: &mut Interp, h: u64, me: Value) -> Option<Value> {
    if let Some(t) = drawing(it).object(h) {
        return Some(super::tag_list::object_list(it, &t, me));
    }
    let d = drawing(it);
    let opened = d
        .document()
        .and_then(|doc| {
            doc.sections.iter().find_map(|s| match s {
                crate::output::document::Section::Tables(ts) => ts
                    .iter()
                    .flat_map(|t| t.records.iter())
                    .find(|r| r.handle() == Some(h))
                    .cloned(),
                _ => None,
            })
        })
        .or_else(|| {
            // Block definitions: the opened file's and those entmake made.
            d.new_block_records()
                .iter()
                .chain(d.block_section())
                .find(|r| r.handle() == Some(h))
                .cloned()
        });
    if let Some(t) = opened {
        return Some(super::tag_list::object_list(it, &t, me));
    }
    let (table, name) = drawing(it)
        .table_record_of(h)
        .map(|(t, n)| (t.to_string(), n.to_string()))?;
    let list = super::tables::records(it, &table)
        .into_iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(&name))?
        .1;
    let mut out = vec![pair(-1, me)];
    for (i, g) in list.iter().enumerate() {
        out.push(g.clone());
        if i == 0 {
            out.push(pair(5, Value::str(&format!("{h:X}"))));
            out.push(pair(100, Value::str("AcDbSymbolTableRecord")));
        }
    }
    Some(Value::list(out))
}

pub fn tblobjname(it: &mut Interp, a: &[Value]) -> LResult {
    let table = it.string(&a[0])?.to_uppercase();
    let name = it.string(&a[1])?.to_string();
    let d = drawing(it);
    // A block's name is its BLOCK_RECORD's, as AutoCAD gives it.
    let made_block = (table == "BLOCK" && d.document().is_none())
        .then(|| {
            d.new_block_records()
                .iter()
                .find(|r| r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(&name)))
                .and_then(TagList::handle)
        })
        .flatten();
    if let Some(h) = made_block {
        return Ok(ename_value(it, h));
    }
    let in_file = drawing(it).document().and_then(|doc| {
        let recs: &[TagList] = if table == "BLOCK" {
            doc.table_records("BLOCK_RECORD")
        } else if table == "LAYER" && drawing_lacks_layer_record(doc, &name) {
            &[]
        } else {
            doc.table_records(&table)
        };
        recs.iter()
            .find(|r| r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(&name)))
            .and_then(TagList::handle)
    });
    if let Some(h) = in_file {
        return Ok(ename_value(it, h));
    }
    let exact = super::tables::records(it, &table)
        .into_iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(&name))
        .map(|(n, _)| n);
    let Some(exact) = exact else {
        return Ok(Value::Nil);
    };
    let h = drawing(it).table_handle(&table, &exact);
    Ok(ename_value(it, h))
}

fn drawing_lacks_layer_record(doc: &crate::output::document::DxfDocument, name: &str) -> bool {
    !doc.table_records("LAYER")
        .iter()
        .any(|r| r.get(2).is_some_and(|n| n.eq_ignore_ascii_case(name)))
}

// ---- dictionaries ----

/// A dictionary's entries: (key, handle of the object) from its 3 and 350/360 groups.
fn entries(t: &TagList) -> Vec<(String, u64)> {
    let mut out = Vec::new();
    let mut key: Option<&str> = None;
    for (c, v) in t.iter().take(t.first_record_end()) {
        match c {
            3 => key = Some(v),
            350 | 360 => {
                if let (Some(k), Ok(h)) = (key.take(), u64::from_str_radix(v.trim(), 16)) {
                    out.push((k.to_string(), h));
                }
            }
            _ => {}
        }
    }
    out
}

/// The dictionary an argument names: (handle, groups), or None when it names no
/// dictionary.
fn dict_arg(it: &mut Interp, v: &Value) -> Result<Option<(u64, TagList)>, Exn> {
    let e = ename_arg(it, v)?;
    Ok(drawing(it)
        .object(e.handle)
        .filter(|t| t.type_name() == "DICTIONARY" || t.type_name() == "ACDBDICTIONARYWDFLT")
        .map(|t| (e.handle, t)))
}

fn entry_list(it: &mut Interp, h: u64) -> Value {
    entity_list(it, Ename { handle: h, sub: 0 }).unwrap_or(Value::Nil)
}

pub fn namedobjdict(it: &mut Interp, _: &[Value]) -> LResult {
    Ok(match drawing(it).root_dict() {
        Some(h) => ename_value(it, h),
        None => Value::Nil,
    })
}

pub fn dictsearch(it: &mut Interp, a: &[Value]) -> LResult {
    let key = it.string(&a[1])?.to_string();
    let Some((dh, t)) = dict_arg(it, &a[0])? else {
        return Ok(Value::Nil);
    };
    let es = entries(&t);
    let Some(i) = es.iter().position(|(k, _)| k.eq_ignore_ascii_case(&key)) else {
        return Ok(Value::Nil);
    };
    if a.get(2).is_some_and(Value::truthy) {
        it.ext::<DictCursors>().0.insert(dh, i + 1);
    }
    Ok(entry_list(it, es[i].1))
}

pub fn dictnext(it: &mut Interp, a: &[Value]) -> LResult {
    let rewind = a.get(1).is_some_and(Value::truthy);
    let Some((dh, t)) = dict_arg(it, &a[0])? else {
        return Ok(Value::Nil);
    };
    let cursors = &mut it.ext::<DictCursors>().0;
    let pos = if rewind {
        0
    } else {
        cursors.get(&dh).copied().unwrap_or(0)
    };
    let es = entries(&t);
    let Some((_, h)) = es.get(pos) else {
        cursors.insert(dh, pos);
        return Ok(Value::Nil);
    };
    cursors.insert(dh, pos + 1);
    Ok(entry_list(it, *h))
}

pub fn dictadd(it: &mut Interp, a: &[Value]) -> LResult {
    let key = it.string(&a[1])?.to_string();
    let obj = ename_arg(it, &a[2])?;
    let Some((dh, t)) = dict_arg(it, &a[0])? else {
        return Ok(Value::Nil);
    };
    if !valid_name(&key)
        || entries(&t)
            .iter()
            .any(|(k, _)| k.eq_ignore_ascii_case(&key))
    {
        return Ok(Value::Nil);
    }
    // Only objects go into dictionaries (entities belong to their space).
    let Some(o) = drawing(it).object(obj.handle) else {
        return Ok(Value::Nil);
    };
    let hard = t.get(280) == Some("1");
    let mut nt = TagList::new();
    for (c, v) in t.iter() {
        nt.push(c, v);
    }
    nt.push(3, &key);
    nt.push(if hard { 360 } else { 350 }, &format!("{:X}", obj.handle));
    let d = drawing(it);
    if !d.put_object(nt) {
        return Ok(Value::Nil);
    }
    d.put_object(with_owner(&o, dh));
    Ok(a[2].clone())
}

/// The dictionary's groups without the entry `key`.
fn without_entry(t: &TagList, key: &str) -> TagList {
    let mut out = TagList::new();
    let mut skip = false;
    for (c, v) in t.iter() {
        if c == 3 && v.eq_ignore_ascii_case(key) {
            skip = true;
            continue;
        }
        if skip && (c == 350 || c == 360) {
            skip = false;
            continue;
        }
        out.push(c, v);
    }
    out
}

pub fn dictremove(it: &mut Interp, a: &[Value]) -> LResult {
    let key = it.string(&a[1])?.to_string();
    let Some((_, t)) = dict_arg(it, &a[0])? else {
        return Ok(Value::Nil);
    };
    let Some((k, h)) = entries(&t)
        .into_iter()
        .find(|(k, _)| k.eq_ignore_ascii_case(&key))
    else {
        return Ok(Value::Nil);
    };
    let d = drawing(it);
    d.put_object(without_entry(&t, &k));
    // The object stays in the drawing, without an owner (AutoCAD's rule).
    if let Some(o) = d.object(h) {
        d.put_object(with_owner(&o, 0));
    }
    Ok(ename_value(it, h))
}

pub fn dictrename(it: &mut Interp, a: &[Value]) -> LResult {
    let old = it.string(&a[1])?.to_string();
    let new = it.string(&a[2])?.to_string();
    let Some((_, t)) = dict_arg(it, &a[0])? else {
        return Ok(Value::Nil);
    };
    let es = entries(&t);
    if !valid_name(&new)
        || !es.iter().any(|(k, _)| k.eq_ignore_ascii_case(&old))
        || es.iter().any(|(k, _)| k.eq_ignore_ascii_case(&new))
    {
        return Ok(Value::Nil);
    }
    let mut nt = TagList::new();
    for (c, v) in t.iter() {
        if c == 3 && v.eq_ignore_ascii_case(&old) {
            nt.push(3, &new);
        } else {
            nt.push(c, v);
        }
    }
    drawing(it).put_object(nt);
    Ok(Value::str(&new))
}
