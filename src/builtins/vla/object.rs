//! The ActiveX object model's functions: the application and document objects, ename/object
//! conversion, generic property and method access (`vlax-get-property`, `vlax-invoke`...),
//! `vla-get-*`/`vla-put-*`/`vla-<Method>` for the common names, `vlax-for` over collections
//! and `vlax-dump-object`.

use crate::builtin;
use crate::builtins::entities::{ename_arg, ename_value};
use crate::lang::builtin::{bad_arg, Builtin, MANY};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::Drawing;

use super::methods::{entity_obj, invoke, Ret};
use super::props::{self, prop_lisp, prop_value, space_members};
use super::variant::{doubles_variant, objects_variant, to_lisp};
use super::{vla_value, Vla};

pub static BUILTINS: &[Builtin] = &[
    builtin!(
        "vlax-get-acad-object",
        "(vlax-get-acad-object)",
        "The application object (IAcadApplication).",
        0,
        0,
        acad_object
    ),
    builtin!(
        "vlax-ename->vla-object",
        "(vlax-ename->vla-object ename)",
        "The VLA object of an entity.",
        1,
        1,
        ename_to_vla
    ),
    builtin!(
        "vlax-vla-object->ename",
        "(vlax-vla-object->ename object)",
        "The entity name of a VLA entity object.",
        1,
        1,
        vla_to_ename
    ),
    builtin!(
        "vlax-get-property",
        "(vlax-get-property object property)",
        "A property (points as variants, booleans as :vlax-true/:vlax-false).",
        2,
        2,
        get_property
    ),
    builtin!(
        "vlax-put-property",
        "(vlax-put-property object property value)",
        "Sets a property; returns nil.",
        3,
        3,
        put_property
    ),
    builtin!(
        "vlax-get",
        "(vlax-get object property)",
        "A property with points as lists and booleans as -1/0.",
        2,
        2,
        vlax_get
    ),
    builtin!(
        "vlax-put",
        "(vlax-put object property value)",
        "Sets a property from a Lisp value (points as lists); returns nil.",
        3,
        3,
        put_property
    ),
    builtin!(
        "vlax-invoke-method",
        "(vlax-invoke-method object method arg...)",
        "Calls a method (results as variants and objects).",
        2,
        MANY,
        invoke_method
    ),
    builtin!(
        "vlax-invoke",
        "(vlax-invoke object method arg...)",
        "Calls a method (results as lists).",
        2,
        MANY,
        vlax_invoke
    ),
    builtin!(
        "vlax-property-available-p",
        "(vlax-property-available-p object property [check-modify])",
        "T if the object has the property (and, with check-modify, it can be set).",
        2,
        3,
        property_available
    ),
    builtin!(
        "vlax-method-applicable-p",
        "(vlax-method-applicable-p object method)",
        "T if the object has the method.",
        2,
        2,
        method_applicable
    ),
    builtin!(
        "vlax-dump-object",
        "(vlax-dump-object object [methods])",
        "Prints the object's properties (and methods); returns T.",
        1,
        2,
        dump_object
    ),
    builtin!(
        "vlax-for-items",
        "(vlax-for-items collection)",
        "The members of a collection as a list (what vlax-for iterates).",
        1,
        1,
        for_items
    ),
    builtin!(
        "vlax-erased-p",
        "(vlax-erased-p object)",
        "T if the object's entity was deleted.",
        1,
        1,
        erased_p
    ),
    builtin!(
        "vlax-release-object",
        "(vlax-release-object object)",
        "Accepted for compatibility (objects are reference counted); returns nil.",
        1,
        1,
        nil_fn
    ),
    builtin!(
        "vlax-object-released-p",
        "(vlax-object-released-p object)",
        "nil: objects stay valid while referenced.",
        1,
        1,
        nil_fn
    ),
    builtin!(
        "vlax-read-enabled-p",
        "(vlax-read-enabled-p object)",
        "T: every object can be read.",
        1,
        1,
        t_fn
    ),
    builtin!(
        "vlax-write-enabled-p",
        "(vlax-write-enabled-p object)",
        "T: every object can be modified.",
        1,
        1,
        t_fn
    ),
    builtin!(
        "vlax-typeinfo-available-p",
        "(vlax-typeinfo-available-p object)",
        "T: type information is available for every object.",
        1,
        1,
        t_fn
    ),
    builtin!(
        "vlax-get-object",
        "(vlax-get-object prog-id)",
        "nil: there are no other ActiveX applications headless.",
        1,
        1,
        nil_fn
    ),
    builtin!(
        "vlax-create-object",
        "(vlax-create-object prog-id)",
        "nil: there are no other ActiveX applications headless.",
        1,
        1,
        nil_fn
    ),
    builtin!(
        "vlax-get-or-create-object",
        "(vlax-get-or-create-object prog-id)",
        "nil: there are no other ActiveX applications headless.",
        1,
        1,
        nil_fn
    ),
];

/// The VLA object argument, or "bad argument type: VLA-OBJECT".
pub fn obj_arg(it: &Interp, v: &Value) -> Result<Vla, Exn> {
    v.as_obj::<Vla>()
        .cloned()
        .ok_or_else(|| bad_arg(it, "VLA-OBJECT", v))
}

/// A property or method name: a symbol or a string.
fn name_arg(it: &Interp, v: &Value) -> Result<String, Exn> {
    match v {
        Value::Sym(s) => Ok(it.syms.name(*s).to_string()),
        Value::Str(s) => Ok(s.to_string()),
        other => Err(bad_arg(it, "symbolp", other)),
    }
}

fn acad_object(it: &mut Interp, _: &[Value]) -> LResult {
    Ok(vla_value(it, Vla::Application))
}

fn ename_to_vla(it: &mut Interp, a: &[Value]) -> LResult {
    let e = ename_arg(it, &a[0])?;
    if it.ext::<Drawing>().get(e.handle).is_none() {
        return Err(err("bad argument type: lentityp: unknown entity"));
    }
    let o = entity_obj(it, e.handle);
    Ok(vla_value(it, o))
}

fn vla_to_ename(it: &mut Interp, a: &[Value]) -> LResult {
    match obj_arg(it, &a[0])? {
        Vla::Entity(h, _) => Ok(ename_value(it, h)),
        _ => Err(err("ActiveX Server returned an error: not an entity")),
    }
}

pub fn get_prop(it: &mut Interp, a: &[Value], name: &str) -> LResult {
    let o = obj_arg(it, &a[0])?;
    let p = props::get(it, &o, name)?;
    Ok(prop_value(it, p))
}

pub fn put_prop(it: &mut Interp, a: &[Value], name: &str) -> LResult {
    let o = obj_arg(it, &a[0])?;
    props::put(it, &o, name, &a[1])?;
    Ok(Value::Nil)
}

fn get_property(it: &mut Interp, a: &[Value]) -> LResult {
    let name = name_arg(it, &a[1])?;
    get_prop(it, &a[..1], &name)
}

fn put_property(it: &mut Interp, a: &[Value]) -> LResult {
    let name = name_arg(it, &a[1])?;
    put_prop(it, &[a[0].clone(), a[2].clone()], &name)
}

fn vlax_get(it: &mut Interp, a: &[Value]) -> LResult {
    let o = obj_arg(it, &a[0])?;
    let name = name_arg(it, &a[1])?;
    let p = props::get(it, &o, &name)?;
    Ok(prop_lisp(it, p))
}

/// Calls a method; `lists` picks `vlax-invoke`'s form of the result.
pub fn call(it: &mut Interp, a: &[Value], name: &str, lists: bool) -> LResult {
    let o = obj_arg(it, &a[0])?;
    let r = invoke(it, &o, name, &a[1..])?;
    Ok(match r {
        Ret::Nil => Value::Nil,
        Ret::Value(v) => v,
        Ret::Obj(o) => vla_value(it, o),
        Ret::Coords(c) if lists => Value::list(c.into_iter().map(Value::Real).collect::<Vec<_>>()),
        Ret::Coords(c) => doubles_variant(&c),
        Ret::Objects(os) => {
            let vals: Vec<Value> = os.into_iter().map(|o| vla_value(it, o)).collect();
            if lists {
                Value::list(vals)
            } else {
                objects_variant(vals)
            }
        }
    })
}

fn invoke_method(it: &mut Interp, a: &[Value]) -> LResult {
    let name = name_arg(it, &a[1])?;
    let mut args = vec![a[0].clone()];
    args.extend_from_slice(&a[2..]);
    call(it, &args, &name, false)
}

fn vlax_invoke(it: &mut Interp, a: &[Value]) -> LResult {
    let name = name_arg(it, &a[1])?;
    let mut args = vec![a[0].clone()];
    args.extend_from_slice(&a[2..]);
    call(it, &args, &name, true)
}

/// Properties that exist but cannot be set (computed ones).
const READ_ONLY: &[&str] = &[
    "OBJECTNAME",
    "HANDLE",
    "LENGTH",
    "AREA",
    "DELTA",
    "ANGLE",
    "TOTALANGLE",
    "ARCLENGTH",
    "CIRCUMFERENCE",
    "COUNT",
    "DEGREE",
    "NUMBEROFCONTROLPOINTS",
    "NUMBEROFFITPOINTS",
    "APPLICATION",
    "DOCUMENT",
    "MODELSPACE",
    "PAPERSPACE",
    "LAYERS",
    "BLOCKS",
    "VERSION",
    "FULLNAME",
    "PATH",
    "ISRATIONAL",
];

fn property_available(it: &mut Interp, a: &[Value]) -> LResult {
    let o = obj_arg(it, &a[0])?;
    let name = name_arg(it, &a[1])?;
    let key = name.to_ascii_uppercase();
    let exists = props::get(it, &o, &name).is_ok();
    let computed = matches!(o, Vla::Entity(_, "IAcadArc")) && key.ends_with("POINT");
    let writable = !(READ_ONLY.contains(&key.as_str()) || computed);
    let check_modify = a.get(2).is_some_and(Value::truthy);
    Ok(Value::bool(exists && (!check_modify || writable)))
}

/// The methods each kind of object answers to.
fn methods_of(o: &Vla) -> &'static [&'static str] {
    const ENTITY: &[&str] = &[
        "Copy",
        "Delete",
        "GetBoundingBox",
        "Highlight",
        "IntersectWith",
        "Mirror",
        "Move",
        "Rotate",
        "ScaleEntity",
        "Update",
    ];
    const CURVE: &[&str] = &[
        "Copy",
        "Delete",
        "GetBoundingBox",
        "Highlight",
        "IntersectWith",
        "Mirror",
        "Move",
        "Offset",
        "Rotate",
        "ScaleEntity",
        "Update",
    ];
    match o {
        Vla::ModelSpace => &[
            "Add3DPoly",
            "AddArc",
            "AddCircle",
            "AddLightWeightPolyline",
            "AddLine",
            "AddPoint",
            "AddPolyline",
            "AddSpline",
            "AddText",
            "Item",
        ],
        Vla::PaperSpace | Vla::Block(_) => &["Item"],
        Vla::Layers => &["Add", "Item"],
        Vla::Blocks => &["Item"],
        Vla::Layer(_) => &["Delete"],
        Vla::Document => &["EndUndoMark", "Regen", "StartUndoMark"],
        Vla::Application => &[],
        Vla::Entity(_, c) => match *c {
            "IAcadLine" | "IAcadCircle" | "IAcadArc" | "IAcadLWPolyline" | "IAcadPolyline"
            | "IAcad3DPolyline" => CURVE,
            _ => ENTITY,
        },
    }
}

fn method_applicable(it: &mut Interp, a: &[Value]) -> LResult {
    let o = obj_arg(it, &a[0])?;
    let name = name_arg(it, &a[1])?;
    Ok(Value::bool(
        methods_of(&o).iter().any(|m| m.eq_ignore_ascii_case(&name)),
    ))
}

/// The properties `vlax-dump-object` lists, per kind of object.
fn dump_names(o: &Vla) -> &'static [&'static str] {
    match o {
        Vla::Application => &["ActiveDocument", "Name", "Version"],
        Vla::Document => &[
            "ActiveLayer",
            "Blocks",
            "FullName",
            "Layers",
            "ModelSpace",
            "Name",
            "PaperSpace",
            "Path",
        ],
        Vla::ModelSpace | Vla::PaperSpace | Vla::Block(_) => &["Count", "IsLayout", "Name"],
        Vla::Layers | Vla::Blocks => &["Count"],
        Vla::Layer(_) => &[
            "Color",
            "Freeze",
            "LayerOn",
            "Linetype",
            "Lock",
            "Name",
            "ObjectName",
        ],
        Vla::Entity(..) => &[
            "Angle",
            "ArcLength",
            "Area",
            "Center",
            "Circumference",
            "Closed",
            "Color",
            "ControlPoints",
            "Coordinates",
            "Degree",
            "Delta",
            "Diameter",
            "Elevation",
            "EndAngle",
            "EndPoint",
            "FitPoints",
            "Handle",
            "Height",
            "InsertionPoint",
            "Knots",
            "Layer",
            "Length",
            "Linetype",
            "Normal",
            "NumberOfControlPoints",
            "NumberOfFitPoints",
            "ObjectName",
            "Radius",
            "Rotation",
            "StartAngle",
            "StartPoint",
            "StyleName",
            "TextString",
            "TotalAngle",
            "Visible",
        ],
    }
}

fn dump_object(it: &mut Interp, a: &[Value]) -> LResult {
    let o = obj_arg(it, &a[0])?;
    let mut out = format!(
        "; {}: AutoCAD object\n; Property values:\n",
        o.interface_static()
    );
    for name in dump_names(&o) {
        let Ok(p) = props::get(it, &o, name) else {
            continue;
        };
        let key = name.to_ascii_uppercase();
        let ro = if READ_ONLY.contains(&key.as_str()) {
            " (RO)"
        } else {
            ""
        };
        let shown = match &p {
            props::Prop::Point(q) => format!("({} {} {})", fmt(q.x), fmt(q.y), fmt(q.z)),
            props::Prop::Coords(c) => format!("({} ...)", c.len()),
            _ => {
                let v = prop_value(it, p);
                it.prin1_string(&v)
            }
        };
        out.push_str(&format!(";   {name}{ro} = {shown}\n"));
    }
    if a.get(1).is_some_and(Value::truthy) {
        out.push_str("; Methods supported:\n");
        for m in methods_of(&o) {
            out.push_str(&format!(";   {m}\n"));
        }
    }
    it.write_out(&out);
    Ok(Value::T)
}

fn fmt(x: f64) -> String {
    crate::geom::curve::fmt_g(x)
}

fn for_items(it: &mut Interp, a: &[Value]) -> LResult {
    let v = to_lisp(it, &a[0]);
    let o = obj_arg(it, &v)?;
    let items: Vec<Vla> = match &o {
        Vla::ModelSpace | Vla::PaperSpace | Vla::Block(_) => space_members(it, &o)
            .into_iter()
            .map(|h| entity_obj(it, h))
            .collect(),
        Vla::Layers => it
            .ext::<Drawing>()
            .layers()
            .iter()
            .map(|l| Vla::Layer(l.name.clone()))
            .collect(),
        Vla::Blocks => vec![Vla::ModelSpace, Vla::PaperSpace],
        _ => return Err(err("vlax-for: not a collection")),
    };
    let vals: Vec<Value> = items.into_iter().map(|o| vla_value(it, o)).collect();
    Ok(Value::list(vals))
}

fn erased_p(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(match obj_arg(it, &a[0])? {
        Vla::Entity(h, _) => it.ext::<Drawing>().is_deleted(h),
        _ => false,
    }))
}

fn nil_fn(_: &mut Interp, _: &[Value]) -> LResult {
    Ok(Value::Nil)
}

fn t_fn(_: &mut Interp, _: &[Value]) -> LResult {
    Ok(Value::T)
}

/// `vla-get-NAME` and `vla-put-NAME` for each property name, as one module per name so the
/// functions need no hand-written pairs.
macro_rules! vla_props {
    ($($p:ident)*) => {
        #[allow(non_snake_case)]
        mod prop_fns {
            use super::*;
            $(pub mod $p {
                use super::*;
                pub fn get(it: &mut Interp, a: &[Value]) -> LResult {
                    get_prop(it, a, stringify!($p))
                }
                pub fn put(it: &mut Interp, a: &[Value]) -> LResult {
                    put_prop(it, a, stringify!($p))
                }
            })*
        }
        pub static PROPS: &[Builtin] = &[
            $(
                builtin!(concat!("vla-get-", stringify!($p)), concat!("(vla-get-", stringify!($p), " object)"), concat!("The ", stringify!($p), " property of a VLA object (points as variants)."), 1, 1, prop_fns::$p::get),
                builtin!(concat!("vla-put-", stringify!($p)), concat!("(vla-put-", stringify!($p), " object value)"), concat!("Sets the ", stringify!($p), " property of a VLA object; returns nil."), 2, 2, prop_fns::$p::put),
            )*
        ];
    };
}

/// `vla-NAME` for each method name.
macro_rules! vla_methods {
    ($($m:ident)*) => {
        #[allow(non_snake_case)]
        mod method_fns {
            use super::*;
            $(pub fn $m(it: &mut Interp, a: &[Value]) -> LResult {
                call(it, a, stringify!($m), false)
            })*
        }
        pub static METHODS: &[Builtin] = &[
            $(builtin!(concat!("vla-", stringify!($m)), concat!("(vla-", stringify!($m), " object arg...)"), concat!("Calls the ", stringify!($m), " method of a VLA object."), 1, MANY, method_fns::$m),)*
        ];
    };
}

vla_props!(
    ActiveDocument Application ModelSpace PaperSpace Layers Blocks ActiveLayer Document
    ObjectName Handle Layer Color Linetype LinetypeScale Lineweight Visible
    StartPoint EndPoint Center Radius Diameter Circumference Length Area Closed Coordinates
    InsertionPoint TextString Height Rotation Name StartAngle EndAngle TotalAngle ArcLength
    Angle Delta Normal Elevation Thickness Count Degree NumberOfControlPoints
    NumberOfFitPoints ControlPoints FitPoints Knots Weights StyleName LayerOn Freeze Lock
    FullName Path Version
);

vla_methods!(
    AddLine AddCircle AddArc AddPoint AddLightWeightPolyline AddPolyline Add3DPoly AddText
    AddSpline Add Item Move Copy Rotate ScaleEntity Mirror Offset Delete IntersectWith
    GetBoundingBox Update Highlight StartUndoMark EndUndoMark Regen
);
