//! AutoLISP's entity interface on the drawing model: entity names (ENAME), selection sets
//! (PICKSET), `entmake`/`entget`/`entmod`/`entdel`/`entlast`/`entnext`/`handent`, `ssget "X"`
//! with filter lists, the `ss...` functions, and `tblsearch`/`tblnext`.
//!
//! An entity name is the entity's handle (`<Entity name: 1a2b>`), so names stay valid across
//! deletion and undeletion as in AutoCAD. A POLYLINE is one entity of the drawing; its VERTEX and
//! SEQEND sub-entities are named by the polyline's handle plus a sub-index, so the classic
//! `entnext` walk over vertices works.

use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt;

use crate::builtin;
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{Exn, LResult};
use crate::lang::value::Object;
use crate::lang::{Interp, Value};
use crate::output::{Drawing, EntityKind};

use crate::builtins::drawing::drawing;

pub mod block_make;
#[path = "entities/dxf_list.rs"]
pub mod dxf_list;
#[path = "entities/make.rs"]
pub mod make;
pub mod objects;
#[path = "entities/select.rs"]
pub mod select;
pub mod select_area;
#[path = "entities/tables.rs"]
pub mod tables;
pub mod tag_list;

pub static BUILTINS: &[Builtin] = &[
    builtin!("entmake", "(entmake [dxf-list])", "Adds an entity (or a LAYER or APPID record, or an ownerless XRECORD or DICTIONARY) from a DXF association list; a BLOCK list opens a block definition that holds the entities made until ENDBLK, whose entmake returns the block's name; with extended data from a (-3 (\"APP\" ...)) group; returns the list, or nil when a required group is missing, the data is invalid or an application is not registered.", 0, 1, make::entmake),
    builtin!("entget", "(entget ename [applist])", "The DXF association list of an entity, object or table record (nil if deleted); with applist, the extended data of the matching registered applications as a final (-3 (\"APP\" ...)) group.", 1, 2, entget),
    builtin!("entmod", "(entmod dxf-list)", "Modifies the entity (or XRECORD) named by the list's -1 group (groups absent from the list keep their values; a -3 group replaces the named applications' extended data); returns the list or nil.", 1, 1, make::entmod),
    builtin!("entupd", "(entupd ename)", "Accepted for compatibility (the drawing is always up to date); returns ename.", 1, 1, entupd),
    builtin!("entdel", "(entdel ename)", "Deletes an entity, or restores it when it is deleted; returns ename.", 1, 1, entdel),
    builtin!("entlast", "(entlast)", "The name of the last live entity, or nil.", 0, 0, entlast),
    builtin!("entnext", "(entnext [ename])", "The first entity, or the one after ename (walking a POLYLINE's VERTEX and SEQEND sub-entities); nil at the end.", 0, 1, entnext),
    builtin!("handent", "(handent handle)", "The entity name for a handle string, or nil.", 1, 1, handent),
    builtin!("ssget", "(ssget [mode] [pt1 [pt2]] [filter])", "A selection set: mode \"X\" (all, with an optional filter list), \"A\", \"L\" (last), \"P\" (previous), \"W\"/\"C\" pt1 pt2 (window: entirely inside; crossing: inside or crossing), \"WP\"/\"CP\"/\"F\" point-list (polygons, fence); nil when nothing matches. Interactive modes are an error in a headless run.", 0, 4, select::ssget),
    builtin!("sslength", "(sslength ss)", "The number of entities in a selection set.", 1, 1, select::sslength),
    builtin!("ssname", "(ssname ss index)", "The entity at index (from 0) in a selection set, or nil.", 2, 2, select::ssname),
    builtin!("ssadd", "(ssadd [ename [ss]])", "A new empty set, a new set with ename, or ss with ename added (returns ss).", 0, 2, select::ssadd),
    builtin!("ssdel", "(ssdel ename ss)", "Removes ename from ss; returns ss, or nil if it was not there.", 2, 2, select::ssdel),
    builtin!("ssmemb", "(ssmemb ename ss)", "ename if it is in ss, else nil.", 2, 2, select::ssmemb),
    builtin!("tblsearch", "(tblsearch table name [setnext])", "The record of a table entry (LAYER, LTYPE, STYLE, BLOCK; an opened drawing's every table) as a DXF list, or nil.", 2, 3, tables::tblsearch),
    builtin!("tblobjname", "(tblobjname table name)", "The entity name of a symbol-table record (LAYER, LTYPE, STYLE, APPID, BLOCK...), or nil.", 2, 2, objects::tblobjname),
    builtin!("regapp", "(regapp appname)", "Registers an application name for extended data (the APPID table); returns the name, or nil if it is already registered or invalid.", 1, 1, objects::regapp),
    builtin!("namedobjdict", "(namedobjdict)", "The entity name of the drawing's named-object dictionary (the root of its dictionaries).", 0, 0, objects::namedobjdict),
    builtin!("dictsearch", "(dictsearch ename key [setnext])", "The entget list of a dictionary's entry named key (case-insensitive), or nil; setnext makes dictnext continue after it.", 2, 3, objects::dictsearch),
    builtin!("dictnext", "(dictnext ename [rewind])", "The entget list of a dictionary's next entry (the first with rewind), or nil after the last.", 1, 2, objects::dictnext),
    builtin!("dictadd", "(dictadd ename key newobj)", "Adds an object (an XRECORD or DICTIONARY made by entmakex) to a dictionary under key, making the dictionary its owner; returns newobj, or nil if key is taken.", 3, 3, objects::dictadd),
    builtin!("dictremove", "(dictremove ename key)", "Removes an entry from a dictionary (the object stays, without an owner, and is not saved); returns its name, or nil.", 2, 2, objects::dictremove),
    builtin!("dictrename", "(dictrename ename oldkey newkey)", "Renames a dictionary entry; returns newkey, or nil if oldkey is missing or newkey taken.", 3, 3, objects::dictrename),
    builtin!("tblnext", "(tblnext table [rewind])", "The next record of a table (the first with rewind), or nil at the end.", 1, 2, tables::tblnext),
];

/// An entity name: a handle, plus a sub-index for a POLYLINE's VERTEX (1..=n) and SEQEND
/// (n + 1) sub-entities (0 = the entity itself).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Ename {
    pub handle: u64,
    pub sub: u32,
}

impl Object for Ename {
    fn type_name(&self) -> &'static str {
        "ENAME"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        if self.sub == 0 {
            write!(f, "<Entity name: {:x}>", self.handle)
        } else {
            write!(f, "<Entity name: {:x}.{}>", self.handle, self.sub)
        }
    }
    fn equal(&self, other: &dyn Object) -> bool {
        other.as_any().downcast_ref::<Ename>() == Some(self)
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

/// A selection set: entity handles in selection order. Shared and mutable, as AutoLISP's
/// `ssadd`/`ssdel` change the set they are given.
pub struct PickSet {
    pub id: u32,
    pub members: RefCell<Vec<u64>>,
}

impl Object for PickSet {
    fn type_name(&self) -> &'static str {
        "PICKSET"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(f, "<Selection set: {}>", self.id)
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

/// Per-interpreter state of the entity interface.
#[derive(Default)]
pub struct EntityState {
    /// Selection sets made so far (numbers them as AutoCAD does, from 1).
    pub sets_made: u32,
    /// The last set `ssget` returned (`ssget "P"`).
    pub previous: Vec<u64>,
    /// A POLYLINE being built by `entmake` until its SEQEND.
    pub pending_polyline: Option<make::PendingPolyline>,
    /// A block definition being built by `entmake` until its ENDBLK.
    pub pending_block: Option<block_make::PendingBlock>,
    /// An INSERT with attributes being built by `entmake` until its SEQEND.
    pub pending_insert: Option<block_make::PendingInsert>,
    /// `tblnext` positions per table name.
    pub table_cursor: Vec<(String, usize)>,
}

/// One value per entity name, so `eq` is true for two names of the same entity as in
/// AutoLISP (`(eq e (entlast))`).
#[derive(Default)]
pub struct EnameCache(HashMap<Ename, Value>);

/// The value naming an entity or sub-entity.
pub fn name_value(it: &mut Interp, name: Ename) -> Value {
    it.ext::<EnameCache>()
        .0
        .entry(name)
        .or_insert_with(|| Value::obj(name))
        .clone()
}

/// The value naming the entity with `handle`.
pub fn ename_value(it: &mut Interp, handle: u64) -> Value {
    name_value(it, Ename { handle, sub: 0 })
}

/// A new selection set value holding `members`.
pub fn pickset_value(it: &mut Interp, members: Vec<u64>) -> Value {
    let st = it.ext::<EntityState>();
    st.sets_made += 1;
    let id = st.sets_made;
    Value::obj(PickSet {
        id,
        members: RefCell::new(members),
    })
}

/// The entity-name argument, or AutoLISP's "bad argument type: lentityp ...".
pub fn ename_arg(it: &Interp, v: &Value) -> Result<Ename, Exn> {
    v.as_obj::<Ename>()
        .copied()
        .ok_or_else(|| bad_arg(it, "lentityp", v))
}

/// The selection-set argument, or "bad argument type: lselsetp ...".
pub fn pickset_arg<'a>(it: &Interp, v: &'a Value) -> Result<&'a PickSet, Exn> {
    v.as_obj::<PickSet>()
        .ok_or_else(|| bad_arg(it, "lselsetp", v))
}

/// The number of vertices of a POLYLINE entity (None for other kinds).
fn vertex_count(d: &Drawing, handle: u64) -> Option<u32> {
    match &d.get(handle)?.kind {
        EntityKind::Polyline { points, .. } => Some(points.len() as u32),
        // INSERT's ATTRIBs, a polygon mesh's vertices: the followers read with it.
        EntityKind::Unmodelled { .. } => tag_list::follower_count(&d.source(handle)?.tags),
        _ => None,
    }
}

fn entget(it: &mut Interp, a: &[Value]) -> LResult {
    let e = ename_arg(it, &a[0])?;
    let Some(list) = dxf_list::entity_list(it, e) else {
        return Ok(Value::Nil);
    };
    let apps: Vec<String> = match a.get(1).filter(|v| v.truthy()) {
        Some(l) => it
            .list_arg(l)?
            .iter()
            .map(|v| it.string(v).map(str::to_string))
            .collect::<Result<_, _>>()?,
        None => return Ok(list),
    };
    if e.sub != 0 {
        return Ok(list);
    }
    match objects::xdata_group(it, e.handle, &apps) {
        Some(x) => {
            let mut items: Vec<Value> = list.iter().cloned().collect();
            items.push(x);
            Ok(Value::list(items))
        }
        None => Ok(list),
    }
}

fn entupd(it: &mut Interp, a: &[Value]) -> LResult {
    ename_arg(it, &a[0])?;
    Ok(a[0].clone())
}

fn entdel(it: &mut Interp, a: &[Value]) -> LResult {
    let e = ename_arg(it, &a[0])?;
    if e.sub != 0 {
        // AutoCAD refuses to delete a sub-entity on its own.
        return Ok(Value::Nil);
    }
    let d = drawing(it);
    if d.delete(e.handle) || d.undelete(e.handle) {
        Ok(a[0].clone())
    } else {
        Ok(Value::Nil)
    }
}

fn entlast(it: &mut Interp, _: &[Value]) -> LResult {
    let last = drawing(it).last();
    Ok(last.map_or(Value::Nil, |h| ename_value(it, h)))
}

fn entnext(it: &mut Interp, a: &[Value]) -> LResult {
    let Some(v) = a.first().filter(|v| v.truthy()) else {
        let first = drawing(it).first();
        return Ok(first.map_or(Value::Nil, |h| ename_value(it, h)));
    };
    let e = ename_arg(it, v)?;
    let d = drawing(it);
    // Into and through a POLYLINE's vertices, then its SEQEND.
    if let Some(n) = vertex_count(d, e.handle) {
        if e.sub <= n {
            return Ok(name_value(
                it,
                Ename {
                    handle: e.handle,
                    sub: e.sub + 1,
                },
            ));
        }
    }
    let next = d.next_after(e.handle);
    Ok(next.map_or(Value::Nil, |h| ename_value(it, h)))
}

fn handent(it: &mut Interp, a: &[Value]) -> LResult {
    let s = it.string(&a[0])?;
    let Ok(h) = u64::from_str_radix(s.trim(), 16) else {
        return Ok(Value::Nil);
    };
    let d = drawing(it);
    // A deleted entity keeps its name for the session, as in AutoCAD.
    if d.get(h).is_some() || d.is_deleted(h) || d.object(h).is_some() {
        Ok(ename_value(it, h))
    } else {
        Ok(Value::Nil)
    }
}
