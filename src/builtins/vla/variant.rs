//! Variants and safearrays, as Visual LISP hands them to and from ActiveX: a variant is a
//! type code (`vlax-vbDouble`...) and a value; a safearray is a typed array with bounds per
//! dimension, mutable in place (`vlax-safearray-put-element`).

use std::cell::RefCell;
use std::fmt;

use glam::DVec3;

use crate::builtin;
use crate::lang::builtin::{bad_arg, Builtin, MANY};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::value::Object;
use crate::lang::{Interp, Value};

pub const VB_EMPTY: i32 = 0;
pub const VB_NULL: i32 = 1;
pub const VB_INTEGER: i32 = 2;
pub const VB_LONG: i32 = 3;
pub const VB_SINGLE: i32 = 4;
pub const VB_DOUBLE: i32 = 5;
pub const VB_STRING: i32 = 8;
pub const VB_OBJECT: i32 = 9;
pub const VB_BOOLEAN: i32 = 11;
pub const VB_VARIANT: i32 = 12;
pub const VB_ARRAY: i32 = 8192;

pub static BUILTINS: &[Builtin] = &[
    builtin!(
        "vlax-make-variant",
        "(vlax-make-variant [value [type]])",
        "A variant holding value, of the given type (default: from the value).",
        0,
        2,
        make_variant
    ),
    builtin!(
        "vlax-variant-type",
        "(vlax-variant-type variant)",
        "The type code of a variant (vlax-vbDouble, 8192 + element type for arrays...).",
        1,
        1,
        variant_type
    ),
    builtin!(
        "vlax-variant-value",
        "(vlax-variant-value variant)",
        "The value a variant holds (a safearray for arrays).",
        1,
        1,
        variant_value
    ),
    builtin!(
        "vlax-variant-change-type",
        "(vlax-variant-change-type variant type)",
        "A variant converted to another type, or nil when it cannot be.",
        2,
        2,
        variant_change_type
    ),
    builtin!(
        "vlax-make-safearray",
        "(vlax-make-safearray type '(lower . upper) ...)",
        "A safearray of the element type with one (lower . upper) bound per dimension.",
        2,
        MANY,
        make_safearray
    ),
    builtin!(
        "vlax-safearray-fill",
        "(vlax-safearray-fill array list)",
        "Stores the list's elements (lists of lists for 2 dimensions) in the array; returns it.",
        2,
        2,
        safearray_fill
    ),
    builtin!(
        "vlax-safearray-get-element",
        "(vlax-safearray-get-element array i [j])",
        "The element at the given indices.",
        2,
        3,
        safearray_get
    ),
    builtin!(
        "vlax-safearray-put-element",
        "(vlax-safearray-put-element array i [j] value)",
        "Stores an element; returns the value.",
        3,
        4,
        safearray_put
    ),
    builtin!(
        "vlax-safearray-get-u-bound",
        "(vlax-safearray-get-u-bound array dim)",
        "The upper bound of a dimension (from 1).",
        2,
        2,
        safearray_u_bound
    ),
    builtin!(
        "vlax-safearray-get-l-bound",
        "(vlax-safearray-get-l-bound array dim)",
        "The lower bound of a dimension (from 1).",
        2,
        2,
        safearray_l_bound
    ),
    builtin!(
        "vlax-safearray-get-dim",
        "(vlax-safearray-get-dim array)",
        "The number of dimensions of a safearray.",
        1,
        1,
        safearray_dim
    ),
    builtin!(
        "vlax-safearray-type",
        "(vlax-safearray-type array)",
        "The element type code of a safearray.",
        1,
        1,
        safearray_type
    ),
    builtin!(
        "vlax-safearray->list",
        "(vlax-safearray->list array)",
        "The elements as a list (a list of lists for 2 dimensions).",
        1,
        1,
        safearray_to_list
    ),
    builtin!(
        "vlax-3d-point",
        "(vlax-3d-point x y [z]) or (vlax-3d-point '(x y [z]))",
        "A variant holding a safearray of 3 doubles, the form ActiveX takes points in.",
        1,
        3,
        vlax_3d_point
    ),
];

/// A variant: an ActiveX type code and the value.
pub struct Variant {
    pub vt: i32,
    pub value: Value,
}

impl Object for Variant {
    fn type_name(&self) -> &'static str {
        "VARIANT"
    }
    /// `#<variant 5 2.5>`; arrays print as AutoCAD prints them, `#<variant 8197 ...>`.
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        if self.vt & VB_ARRAY != 0 {
            return write!(f, "#<variant {} ...>", self.vt);
        }
        match &self.value {
            Value::Str(s) => write!(f, "#<variant {} {}>", self.vt, s),
            Value::Real(r) => write!(
                f,
                "#<variant {} {}>",
                self.vt,
                crate::geom::curve::fmt_g(*r)
            ),
            Value::Int(i) => write!(f, "#<variant {} {}>", self.vt, i),
            Value::Nil => write!(f, "#<variant {} >", self.vt),
            Value::Sym(_) if self.vt == VB_BOOLEAN => write!(
                f,
                "#<variant 11 {}>",
                if is_true(&self.value) {
                    ":vlax-true"
                } else {
                    ":vlax-false"
                }
            ),
            Value::Obj(o) => {
                write!(f, "#<variant {} ", self.vt)?;
                o.print(f)?;
                write!(f, ">")
            }
            _ => write!(f, "#<variant {} ...>", self.vt),
        }
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

/// A safearray: element type, (lower, upper) bounds per dimension, elements in row order.
pub struct SafeArray {
    pub vt: i32,
    pub bounds: Vec<(i32, i32)>,
    pub data: RefCell<Vec<Value>>,
}

impl Object for SafeArray {
    fn type_name(&self) -> &'static str {
        "SAFEARRAY"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(f, "#<safearray...>")
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

impl SafeArray {
    fn len(&self, dim: usize) -> usize {
        let (lo, hi) = self.bounds[dim];
        (i64::from(hi) - i64::from(lo) + 1).max(0) as usize
    }

    /// The flat index of the given indices, or AutoCAD's bounds error.
    fn index(&self, idx: &[i32]) -> Result<usize, Exn> {
        if idx.len() != self.bounds.len() {
            return Err(err(
                "ActiveX Server returned an error: Invalid number of dimensions",
            ));
        }
        let mut flat = 0usize;
        for (d, &i) in idx.iter().enumerate() {
            let (lo, hi) = self.bounds[d];
            if i < lo || i > hi {
                return Err(err("ActiveX Server returned an error: Invalid index"));
            }
            flat = flat * self.len(d) + (i64::from(i) - i64::from(lo)) as usize;
        }
        Ok(flat)
    }
}

/// The `:vlax-true`/`:vlax-false` symbol values.
pub fn vlax_bool(it: &mut Interp, b: bool) -> Value {
    Value::Sym(it.intern(if b { ":VLAX-TRUE" } else { ":VLAX-FALSE" }))
}

fn is_true(v: &Value) -> bool {
    v.truthy() && !matches!(v, Value::Int(0))
}

/// A value converted to its element type (AutoCAD's coercion of safearray elements).
fn coerce(it: &mut Interp, vt: i32, v: &Value) -> Result<Value, Exn> {
    let v = to_lisp(it, v);
    Ok(match vt {
        VB_INTEGER | VB_LONG => match v {
            Value::Int(_) => v,
            Value::Real(r) => Value::Int(r.round() as i32),
            _ => return Err(bad_arg(it, "numberp", &v)),
        },
        VB_SINGLE | VB_DOUBLE => Value::Real(it.num(&v)?),
        VB_STRING => match v {
            Value::Str(_) => v,
            other => Value::str(&it.princ_string(&other)),
        },
        VB_BOOLEAN => vlax_bool(it, is_true(&v)),
        _ => v,
    })
}

/// An ActiveX value as a plain Lisp value: variants unwrap, safearrays become lists,
/// `:vlax-true`/`:vlax-false` stay symbols.
pub fn to_lisp(it: &Interp, v: &Value) -> Value {
    if let Some(var) = v.as_obj::<Variant>() {
        return to_lisp(it, &var.value);
    }
    if let Some(sa) = v.as_obj::<SafeArray>() {
        return array_list(it, sa);
    }
    v.clone()
}

fn array_list(it: &Interp, sa: &SafeArray) -> Value {
    let data = sa.data.borrow();
    let conv: Vec<Value> = data.iter().map(|x| to_lisp(it, x)).collect();
    if sa.bounds.len() == 2 {
        let cols = sa.len(1).max(1);
        Value::list(
            conv.chunks(cols)
                .map(|c| Value::list(c.to_vec()))
                .collect::<Vec<_>>(),
        )
    } else {
        Value::list(conv)
    }
}

/// A variant holding a 1-dimensional safearray of doubles (points, coordinate lists).
pub fn doubles_variant(xs: &[f64]) -> Value {
    let sa = SafeArray {
        vt: VB_DOUBLE,
        bounds: vec![(0, xs.len() as i32 - 1)],
        data: RefCell::new(xs.iter().map(|x| Value::Real(*x)).collect()),
    };
    Value::obj(Variant {
        vt: VB_ARRAY | VB_DOUBLE,
        value: Value::obj(sa),
    })
}

/// A variant holding a safearray of objects (the results of Offset, Explode...).
pub fn objects_variant(objs: Vec<Value>) -> Value {
    let sa = SafeArray {
        vt: VB_OBJECT,
        bounds: vec![(0, objs.len() as i32 - 1)],
        data: RefCell::new(objs),
    };
    Value::obj(Variant {
        vt: VB_ARRAY | VB_OBJECT,
        value: Value::obj(sa),
    })
}

/// A point argument in any of the forms ActiveX methods take: a list, a variant or a
/// safearray of 2 or 3 numbers.
pub fn point_arg(it: &Interp, v: &Value) -> Result<DVec3, Exn> {
    let l = to_lisp(it, v);
    it.point(&l).map(DVec3::from_array)
}

/// Flat coordinates (a list, variant or safearray of numbers) as points of `dim` (2 or 3)
/// values each (z = 0 for 2), at least two points; AutoCAD's "Invalid input" otherwise.
pub fn coord_points(it: &Interp, v: &Value, dim: usize) -> Result<Vec<DVec3>, Exn> {
    let xs: Vec<f64> = to_lisp(it, v)
        .iter()
        .map(|x| it.num(x))
        .collect::<Result<_, _>>()?;
    if !xs.len().is_multiple_of(dim) || xs.len() < 2 * dim {
        return Err(err("ActiveX Server returned an error: Invalid input"));
    }
    Ok(xs
        .chunks(dim)
        .map(|c| DVec3::new(c[0], c[1], if dim == 3 { c[2] } else { 0.0 }))
        .collect())
}

fn default_type(it: &mut Interp, v: &Value) -> i32 {
    match v {
        Value::Nil => VB_EMPTY,
        Value::Int(_) => VB_LONG,
        Value::Real(_) => VB_DOUBLE,
        Value::Str(_) => VB_STRING,
        Value::Sym(s) => match it.syms.name(*s) {
            ":VLAX-TRUE" | ":VLAX-FALSE" => VB_BOOLEAN,
            ":VLAX-NULL" => VB_NULL,
            _ => VB_VARIANT,
        },
        Value::Obj(o) => {
            if let Some(var) = o.as_any().downcast_ref::<Variant>() {
                var.vt
            } else if let Some(sa) = o.as_any().downcast_ref::<SafeArray>() {
                VB_ARRAY | sa.vt
            } else {
                VB_OBJECT
            }
        }
        _ => VB_VARIANT,
    }
}

fn make_variant(it: &mut Interp, a: &[Value]) -> LResult {
    let v = a.first().cloned().unwrap_or(Value::Nil);
    if let Some(var) = v.as_obj::<Variant>() {
        if a.get(1).is_none() {
            return Ok(Value::obj(Variant {
                vt: var.vt,
                value: var.value.clone(),
            }));
        }
    }
    let vt = match a.get(1) {
        Some(t) if t.truthy() => it.int(t)?,
        _ => default_type(it, &v),
    };
    let value = if vt & VB_ARRAY != 0 || vt == VB_OBJECT || vt == VB_VARIANT {
        v
    } else {
        coerce(it, vt, &v)?
    };
    Ok(Value::obj(Variant { vt, value }))
}

fn variant_arg<'a>(it: &Interp, v: &'a Value) -> Result<&'a Variant, Exn> {
    v.as_obj::<Variant>()
        .ok_or_else(|| bad_arg(it, "variantp", v))
}

fn variant_type(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Int(variant_arg(it, &a[0])?.vt))
}

fn variant_value(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(variant_arg(it, &a[0])?.value.clone())
}

fn variant_change_type(it: &mut Interp, a: &[Value]) -> LResult {
    let var = variant_arg(it, &a[0])?;
    let (value, vt) = (var.value.clone(), it.int(&a[1])?);
    Ok(match coerce(it, vt, &value) {
        Ok(value) => Value::obj(Variant { vt, value }),
        Err(_) => Value::Nil,
    })
}

fn empty_element(vt: i32) -> Value {
    match vt {
        VB_INTEGER | VB_LONG => Value::Int(0),
        VB_SINGLE | VB_DOUBLE => Value::Real(0.0),
        VB_STRING => Value::str(""),
        _ => Value::Nil,
    }
}

fn make_safearray(it: &mut Interp, a: &[Value]) -> LResult {
    let vt = it.int(&a[0])?;
    let mut bounds = Vec::new();
    for b in &a[1..] {
        let (lo, hi) = match b {
            Value::Cons(c) => (it.int(&c.car)?, it.int(&c.cdr)?),
            other => return Err(bad_arg(it, "consp", other)),
        };
        if i64::from(hi) < i64::from(lo) - 1 {
            return Err(err("ActiveX Server returned an error: Invalid bounds"));
        }
        bounds.push((lo, hi));
    }
    if bounds.len() > 2 {
        return Err(err(
            "vlax-make-safearray: lispcad supports 1 and 2 dimensions",
        ));
    }
    let n: usize = bounds
        .iter()
        .map(|&(lo, hi)| (i64::from(hi) - i64::from(lo) + 1).max(0) as usize)
        .fold(1usize, usize::saturating_mul);
    // Bounds of a few numbers can ask for gigabytes: the memory budget answers first.
    let bytes = n.saturating_mul(std::mem::size_of::<Value>());
    crate::lang::memory::reserve(bytes)?;
    let mut data = Vec::new();
    data.try_reserve_exact(n)
        .map_err(|_| crate::lang::memory::system_refused(bytes))?;
    data.resize(n, empty_element(vt));
    Ok(Value::obj(SafeArray {
        vt,
        bounds,
        data: RefCell::new(data),
    }))
}

fn array_arg<'a>(it: &Interp, v: &'a Value) -> Result<&'a SafeArray, Exn> {
    v.as_obj::<SafeArray>()
        .ok_or_else(|| bad_arg(it, "safearrayp", v))
}

fn safearray_fill(it: &mut Interp, a: &[Value]) -> LResult {
    let sa = array_arg(it, &a[0])?;
    let items: Vec<Value> = if sa.bounds.len() == 2 {
        a[1].iter()
            .flat_map(|row| row.iter().cloned().collect::<Vec<_>>())
            .collect()
    } else {
        a[1].iter().cloned().collect()
    };
    let n = sa.data.borrow().len();
    if items.len() > n {
        return Err(err("ActiveX Server returned an error: Invalid index"));
    }
    let vt = sa.vt;
    let mut conv = Vec::with_capacity(items.len());
    for x in &items {
        conv.push(coerce(it, vt, x)?);
    }
    let sa = array_arg(it, &a[0])?;
    for (slot, x) in sa.data.borrow_mut().iter_mut().zip(conv) {
        *slot = x;
    }
    Ok(a[0].clone())
}

fn indices(it: &Interp, a: &[Value]) -> Result<Vec<i32>, Exn> {
    a.iter().map(|v| it.int(v)).collect()
}

fn safearray_get(it: &mut Interp, a: &[Value]) -> LResult {
    let sa = array_arg(it, &a[0])?;
    let i = sa.index(&indices(it, &a[1..])?)?;
    Ok(sa.data.borrow()[i].clone())
}

fn safearray_put(it: &mut Interp, a: &[Value]) -> LResult {
    let (idx, v) = a[1..].split_at(a.len() - 2);
    let vt = array_arg(it, &a[0])?.vt;
    let value = coerce(it, vt, &v[0])?;
    let sa = array_arg(it, &a[0])?;
    let i = sa.index(&indices(it, idx)?)?;
    sa.data.borrow_mut()[i] = value;
    Ok(v[0].clone())
}

fn dim_arg(it: &Interp, sa: &SafeArray, v: &Value) -> Result<usize, Exn> {
    let d = it.int(v)?;
    if d < 1 || d as usize > sa.bounds.len() {
        return Err(err("ActiveX Server returned an error: Invalid dimension"));
    }
    Ok(d as usize - 1)
}

fn safearray_u_bound(it: &mut Interp, a: &[Value]) -> LResult {
    let sa = array_arg(it, &a[0])?;
    Ok(Value::Int(sa.bounds[dim_arg(it, sa, &a[1])?].1))
}

fn safearray_l_bound(it: &mut Interp, a: &[Value]) -> LResult {
    let sa = array_arg(it, &a[0])?;
    Ok(Value::Int(sa.bounds[dim_arg(it, sa, &a[1])?].0))
}

fn safearray_dim(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Int(array_arg(it, &a[0])?.bounds.len() as i32))
}

fn safearray_type(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Int(array_arg(it, &a[0])?.vt))
}

fn safearray_to_list(it: &mut Interp, a: &[Value]) -> LResult {
    let sa = array_arg(it, &a[0])?;
    if sa.data.borrow().is_empty() {
        // AutoCAD refuses an empty array here; routines test the u-bound first.
        return Err(err("ActiveX Server returned an error: Invalid index"));
    }
    Ok(array_list(it, sa))
}

fn vlax_3d_point(it: &mut Interp, a: &[Value]) -> LResult {
    let p = if a.len() == 1 {
        it.point(&a[0])?
    } else {
        [
            it.num(&a[0])?,
            it.num(&a[1])?,
            a.get(2).map_or(Ok(0.0), |z| it.num(z))?,
        ]
    };
    Ok(doubles_variant(&p))
}

/// The constants of the ActiveX interface: type codes, `:vlax-true`/`:vlax-false`/
/// `:vlax-null` (symbols that evaluate to themselves) and the acExtend* options.
pub fn init(it: &mut Interp) {
    for (name, v) in [
        ("vlax-vbEmpty", VB_EMPTY),
        ("vlax-vbNull", VB_NULL),
        ("vlax-vbInteger", VB_INTEGER),
        ("vlax-vbLong", VB_LONG),
        ("vlax-vbSingle", VB_SINGLE),
        ("vlax-vbDouble", VB_DOUBLE),
        ("vlax-vbCurrency", 6),
        ("vlax-vbDate", 7),
        ("vlax-vbString", VB_STRING),
        ("vlax-vbObject", VB_OBJECT),
        ("vlax-vbError", 10),
        ("vlax-vbBoolean", VB_BOOLEAN),
        ("vlax-vbVariant", VB_VARIANT),
        ("vlax-vbDecimal", 14),
        ("vlax-vbByte", 17),
        ("vlax-vbArray", VB_ARRAY),
        ("acExtendNone", 0),
        ("acExtendThisEntity", 1),
        ("acExtendOtherEntity", 2),
        ("acExtendBoth", 3),
        ("acByBlock", 0),
        ("acRed", 1),
        ("acYellow", 2),
        ("acGreen", 3),
        ("acCyan", 4),
        ("acBlue", 5),
        ("acMagenta", 6),
        ("acWhite", 7),
        ("acByLayer", 256),
    ] {
        // Interning upper-cases an ASCII name itself: no copy needed here.
        it.set_global(name, Value::Int(v));
    }
    for name in [":VLAX-TRUE", ":VLAX-FALSE", ":VLAX-NULL"] {
        let s = it.intern(name);
        it.set_global(name, Value::Sym(s));
    }
}
