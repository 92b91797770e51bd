//! Lists: car/cdr and their compositions, construction, search, sorting.

use crate::builtin;
use crate::lang::builtin::{bad_arg, Builtin, MANY};
use crate::lang::compile::Args;
use crate::lang::error::{err, Exn, LResult};
use crate::lang::value::{ConsRef, ListBuilder};
use crate::lang::{Interp, Value};

/// car/cdr compositions: the letters between c and r, applied right to left.
fn cxr(it: &Interp, v: &Value, path: &[u8]) -> LResult {
    let mut cur = v.clone();
    for op in path.iter().rev() {
        cur = match &cur {
            Value::Cons(c) => {
                if *op == b'a' {
                    c.car.clone()
                } else {
                    c.cdr.clone()
                }
            }
            Value::Nil => Value::Nil,
            other => return Err(bad_arg(it, "consp", other)),
        };
    }
    Ok(cur)
}

macro_rules! cxr_fns {
    ($($f:ident $path:literal),* $(,)?) => {
        $(fn $f(it: &mut Interp, a: &[Value]) -> LResult { cxr(it, &a[0], $path) })*
    };
}

cxr_fns!(car b"a", cdr b"d", caar b"aa", cadr b"ad", cdar b"da", cddr b"dd",
    caaar b"aaa", caadr b"aad", cadar b"ada", caddr b"add", cdaar b"daa", cdadr b"dad",
    cddar b"dda", cdddr b"ddd", caaaar b"aaaa", caaadr b"aaad", caadar b"aada", caaddr b"aadd",
    cadaar b"adaa", cadadr b"adad", caddar b"adda", cadddr b"addd", cdaaar b"daaa",
    cdaadr b"daad", cdadar b"dada", cdaddr b"dadd", cddaar b"ddaa", cddadr b"ddad",
    cdddar b"ddda", cddddr b"dddd");

macro_rules! cxr_table {
    ($($name:literal $f:ident),* $(,)?) => {
        &[$(builtin!($name, concat!("(", $name, " list)"), "A car/cdr composition: the letters between c and r applied right to left (nil on nil).", 1, 1, $f)),*]
    };
}

pub static CXR: &[Builtin] = cxr_table!(
    "caar" caar, "cadr" cadr, "cdar" cdar, "cddr" cddr,
    "caaar" caaar, "caadr" caadr, "cadar" cadar, "caddr" caddr, "cdaar" cdaar, "cdadr" cdadr,
    "cddar" cddar, "cdddr" cdddr, "caaaar" caaaar, "caaadr" caaadr, "caadar" caadar,
    "caaddr" caaddr, "cadaar" cadaar, "cadadr" cadadr, "caddar" caddar, "cadddr" cadddr,
    "cdaaar" cdaaar, "cdaadr" cdaadr, "cdadar" cdadar, "cdaddr" cdaddr, "cddaar" cddaar,
    "cddadr" cddadr, "cdddar" cdddar, "cddddr" cddddr,
);

pub static BUILTINS: &[Builtin] = &[
    builtin!(
        "car",
        "(car list)",
        "The first element of a list (nil for nil).",
        1,
        1,
        car
    ),
    builtin!(
        "cdr",
        "(cdr list)",
        "The list without its first element (nil for nil).",
        1,
        1,
        cdr
    ),
    builtin!(
        "cons",
        "(cons first rest)",
        "A new list cell: first added in front of rest (a dotted pair when rest is an atom).",
        2,
        2,
        cons
    ),
    builtin!(
        "list",
        "(list expr...)",
        "A list of the arguments.",
        0,
        MANY,
        list
    ),
    builtin!(
        "append",
        "(append list...)",
        "The lists joined into one.",
        0,
        MANY,
        append
    ),
    builtin!(
        "reverse",
        "(reverse list)",
        "The list in reverse order.",
        1,
        1,
        reverse
    ),
    builtin!(
        "nth",
        "(nth n list)",
        "The element at zero-based index n, or nil.",
        2,
        2,
        nth
    ),
    builtin!(
        "length",
        "(length list)",
        "The number of elements of a list.",
        1,
        1,
        length
    ),
    builtin!(
        "last",
        "(last list)",
        "The last element of a list.",
        1,
        1,
        last
    ),
    builtin!(
        "assoc",
        "(assoc key alist)",
        "The first element of alist whose car is equal to key, or nil.",
        2,
        2,
        assoc
    ),
    builtin!(
        "member",
        "(member x list)",
        "The tail of list starting at the first element equal to x, or nil.",
        2,
        2,
        member
    ),
    builtin!(
        "subst",
        "(subst new old list)",
        "A copy of list with every top-level element equal to old replaced by new.",
        3,
        3,
        subst
    ),
    builtin!(
        "vl-remove",
        "(vl-remove x list)",
        "The list without the elements equal to x.",
        2,
        2,
        vl_remove
    ),
    builtin!(
        "vl-remove-if",
        "(vl-remove-if pred list)",
        "The list without the elements pred accepts.",
        2,
        2,
        vl_remove_if
    ),
    builtin!(
        "vl-remove-if-not",
        "(vl-remove-if-not pred list)",
        "The elements pred accepts.",
        2,
        2,
        vl_remove_if_not
    ),
    builtin!(
        "vl-position",
        "(vl-position x list)",
        "The zero-based index of the first element equal to x, or nil.",
        2,
        2,
        vl_position
    ),
    builtin!(
        "vl-member-if",
        "(vl-member-if pred list)",
        "The tail of list starting at the first element pred accepts.",
        2,
        2,
        vl_member_if
    ),
    builtin!(
        "vl-member-if-not",
        "(vl-member-if-not pred list)",
        "The tail of list starting at the first element pred rejects.",
        2,
        2,
        vl_member_if_not
    ),
    builtin!(
        "vl-some",
        "(vl-some pred list...)",
        "The first non-nil value of pred on the lists' elements in parallel, or nil.",
        2,
        MANY,
        vl_some
    ),
    builtin!(
        "vl-every",
        "(vl-every pred list...)",
        "T if pred is non-nil on every element (in parallel over the lists).",
        2,
        MANY,
        vl_every
    ),
    builtin!(
        "vl-list*",
        "(vl-list* x... tail)",
        "Like list, but the last argument becomes the tail.",
        1,
        MANY,
        vl_list_star
    ),
    builtin!(
        "vl-list-length",
        "(vl-list-length list)",
        "The length of a proper list; nil for a dotted list.",
        1,
        1,
        vl_list_length
    ),
    builtin!(
        "vl-sort",
        "(vl-sort list less)",
        "The list sorted by the predicate less (duplicate integers are dropped, as in AutoCAD).",
        2,
        2,
        vl_sort
    ),
    builtin!(
        "vl-sort-i",
        "(vl-sort-i list less)",
        "The indices of the list's elements in sorted order.",
        2,
        2,
        vl_sort_i
    ),
    builtin!(
        "acad_strlsort",
        "(acad_strlsort strings)",
        "A list of strings sorted alphabetically.",
        1,
        1,
        acad_strlsort
    ),
];

fn cons(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::cons(a[0].clone(), a[1].clone()))
}

fn list(_: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::list(a.iter().cloned()))
}

/// The elements of a proper list, or AutoLISP's error for anything else.
/// What one cons cell costs the allocator (the cell behind its reference count).
pub const CONS_BYTES: usize = std::mem::size_of::<crate::lang::value::Cons>() + 16;

pub fn elements(it: &Interp, v: &Value) -> Result<Vec<Value>, Exn> {
    let mut out = Vec::new();
    let mut cur = v;
    loop {
        match cur {
            // Callers build a new list of about this length: reserve its cells up front.
            Value::Nil => {
                crate::lang::memory::reserve(out.len().saturating_mul(CONS_BYTES))?;
                return Ok(out);
            }
            Value::Cons(c) => {
                if out.len() % (1 << 16) == (1 << 16) - 1 {
                    crate::lang::memory::check()?;
                }
                out.push(c.car.clone());
                cur = &c.cdr;
            }
            other => {
                return Err(if out.is_empty() {
                    bad_arg(it, "listp", other)
                } else {
                    err("bad list")
                })
            }
        }
    }
}

fn append(it: &mut Interp, a: &[Value]) -> LResult {
    let Some((last, init)) = a.split_last() else {
        return Ok(Value::Nil);
    };
    it.list_arg(last)?;
    let mut items = Vec::new();
    for l in init {
        items.extend(elements(it, l)?);
    }
    Ok(Value::list_with_tail(items, last.clone()))
}

fn reverse(it: &mut Interp, a: &[Value]) -> LResult {
    let mut out = Value::Nil;
    for x in elements(it, &a[0])? {
        out = Value::cons(x, out);
    }
    Ok(out)
}

fn nth(it: &mut Interp, a: &[Value]) -> LResult {
    let n = it.int(&a[0])?;
    it.list_arg(&a[1])?;
    if n < 0 {
        return Ok(Value::Nil);
    }
    Ok(a[1].iter().nth(n as usize).cloned().unwrap_or(Value::Nil))
}

fn length(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Int(elements(it, &a[0])?.len() as i32))
}

fn last(it: &mut Interp, a: &[Value]) -> LResult {
    it.list_arg(&a[0])?;
    let mut cur = &a[0];
    while let Value::Cons(c) = cur {
        match &c.cdr {
            Value::Cons(_) => cur = &c.cdr,
            Value::Nil => return Ok(c.car.clone()),
            // A dotted list's last element is its tail, as in AutoLISP.
            tail => return Ok(tail.clone()),
        }
    }
    Ok(Value::Nil)
}

/// `equal` without fuzz, deciding first the cases association-list code meets on every
/// element — the same cell (`subst` of the pair `assoc` found), two pairs whose keys are
/// different integers or symbols, two integers — and leaving the rest to `Value::equal`, whose
/// answer these are: it compares two conses' atomic cars first and stops at the first
/// difference.
#[inline]
fn equal0(x: &Value, y: &Value) -> bool {
    match (x, y) {
        (Value::Int(p), Value::Int(q)) => p == q,
        (Value::Cons(a), Value::Cons(b)) => {
            if ConsRef::ptr_eq(a, b) {
                return true;
            }
            match (&a.car, &b.car) {
                (Value::Int(p), Value::Int(q)) if p != q => false,
                (Value::Sym(p), Value::Sym(q)) if p != q => false,
                _ => x.equal(y, 0.0),
            }
        }
        _ => x.equal(y, 0.0),
    }
}

fn assoc(it: &mut Interp, a: &[Value]) -> LResult {
    it.list_arg(&a[1])?;
    for e in a[1].iter() {
        if let Value::Cons(c) = e {
            if equal0(&c.car, &a[0]) {
                return Ok(e.clone());
            }
        }
    }
    Ok(Value::Nil)
}

fn member(it: &mut Interp, a: &[Value]) -> LResult {
    it.list_arg(&a[1])?;
    let mut cur = &a[1];
    while let Value::Cons(c) = cur {
        if equal0(&c.car, &a[0]) {
            return Ok(cur.clone());
        }
        cur = &c.cdr;
    }
    Ok(Value::Nil)
}

fn subst(it: &mut Interp, a: &[Value]) -> LResult {
    // Straight into the new list: entity-list updates call this in tight loops.
    let mut out = ListBuilder::new();
    let mut cur = &a[2];
    loop {
        match cur {
            Value::Nil => return Ok(out.finish()),
            Value::Cons(c) => {
                let x = &c.car;
                out.push(if equal0(x, &a[1]) {
                    a[0].clone()
                } else {
                    x.clone()
                });
                cur = &c.cdr;
            }
            other if cur.is_eq(&a[2]) => return Err(bad_arg(it, "listp", other)),
            _ => return Err(err("bad list")),
        }
    }
}

fn vl_remove(it: &mut Interp, a: &[Value]) -> LResult {
    let items = elements(it, &a[1])?;
    Ok(Value::list(
        items
            .into_iter()
            .filter(|x| !x.equal(&a[0], 0.0))
            .collect::<Vec<_>>(),
    ))
}

fn call1(it: &mut Interp, f: &Value, x: &Value) -> LResult {
    let mut args = Args::new();
    args.push(x.clone());
    it.apply_args(f, args)
}

fn filter(it: &mut Interp, a: &[Value], keep_when: bool) -> LResult {
    let items = elements(it, &a[1])?;
    let f = it.callable(&a[0])?;
    let mut out = Vec::new();
    for x in items {
        if call1(it, &f, &x)?.truthy() == keep_when {
            out.push(x);
        }
    }
    Ok(Value::list(out))
}

fn vl_remove_if(it: &mut Interp, a: &[Value]) -> LResult {
    filter(it, a, false)
}

fn vl_remove_if_not(it: &mut Interp, a: &[Value]) -> LResult {
    filter(it, a, true)
}

fn vl_position(it: &mut Interp, a: &[Value]) -> LResult {
    it.list_arg(&a[1])?;
    Ok(a[1]
        .iter()
        .position(|x| x.equal(&a[0], 0.0))
        .map_or(Value::Nil, |i| Value::Int(i as i32)))
}

fn member_if(it: &mut Interp, a: &[Value], want: bool) -> LResult {
    it.list_arg(&a[1])?;
    let mut cur = a[1].clone();
    while let Value::Cons(c) = &cur {
        if call1(it, &a[0], &c.car)?.truthy() == want {
            return Ok(cur);
        }
        let next = c.cdr.clone();
        cur = next;
    }
    Ok(Value::Nil)
}

fn vl_member_if(it: &mut Interp, a: &[Value]) -> LResult {
    member_if(it, a, true)
}

fn vl_member_if_not(it: &mut Interp, a: &[Value]) -> LResult {
    member_if(it, a, false)
}

/// Calls pred over the lists in parallel until `stop` says so; returns that value or None.
fn parallel(
    it: &mut Interp,
    a: &[Value],
    stop: impl Fn(&Value) -> bool,
) -> Result<Option<Value>, Exn> {
    let mut lists = Vec::new();
    for l in &a[1..] {
        lists.push(elements(it, l)?);
    }
    let n = lists.iter().map(Vec::len).min().unwrap_or(0);
    for i in 0..n {
        let args: Args = lists.iter().map(|l| l[i].clone()).collect();
        let r = it.apply_args(&a[0], args)?;
        if stop(&r) {
            return Ok(Some(r));
        }
    }
    Ok(None)
}

fn vl_some(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(parallel(it, a, Value::truthy)?.unwrap_or(Value::Nil))
}

fn vl_every(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::bool(parallel(it, a, Value::is_nil)?.is_none()))
}

fn vl_list_star(_: &mut Interp, a: &[Value]) -> LResult {
    let (last, init) = a.split_last().expect("arity checked");
    Ok(Value::list_with_tail(init.iter().cloned(), last.clone()))
}

fn vl_list_length(it: &mut Interp, a: &[Value]) -> LResult {
    it.list_arg(&a[0])?;
    let mut n = 0;
    let mut cur = &a[0];
    while let Value::Cons(c) = cur {
        n += 1;
        cur = &c.cdr;
    }
    Ok(if cur.is_nil() {
        Value::Int(n)
    } else {
        Value::Nil
    })
}

/// A stable merge sort by a Lisp predicate; errors from the predicate stop the sort.
/// n·log2(n) comparisons, charged to the step budget before sorting.
fn charge_sort(it: &mut Interp, n: usize) -> Result<(), Exn> {
    let n = n as u64;
    it.charge(n.saturating_mul(64 - n.leading_zeros() as u64))
}

fn sort_indices(it: &mut Interp, items: &[Value], less: &Value) -> Result<Vec<usize>, Exn> {
    charge_sort(it, items.len())?;
    let mut idx: Vec<usize> = (0..items.len()).collect();
    let mut buf = idx.clone();
    let mut width = 1;
    while width < idx.len() {
        let mut start = 0;
        while start < idx.len() {
            let mid = (start + width).min(idx.len());
            let end = (start + 2 * width).min(idx.len());
            let (mut i, mut j, mut k) = (start, mid, start);
            while i < mid && j < end {
                let mut args = Args::new();
                args.push(items[idx[j]].clone());
                args.push(items[idx[i]].clone());
                // Take from the right run only when it is strictly less: stability.
                if it.apply_args(less, args)?.truthy() {
                    buf[k] = idx[j];
                    j += 1;
                } else {
                    buf[k] = idx[i];
                    i += 1;
                }
                k += 1;
            }
            buf[k..k + mid - i].copy_from_slice(&idx[i..mid]);
            k += mid - i;
            buf[k..k + end - j].copy_from_slice(&idx[j..end]);
            start = end;
        }
        std::mem::swap(&mut idx, &mut buf);
        width *= 2;
    }
    Ok(idx)
}

fn vl_sort(it: &mut Interp, a: &[Value]) -> LResult {
    let items = elements(it, &a[0])?;
    let less = it.callable(&a[1])?;
    let order = sort_indices(it, &items, &less)?;
    let mut out: Vec<Value> = Vec::with_capacity(items.len());
    for i in order {
        let x = &items[i];
        // AutoCAD's vl-sort drops duplicate integers (but keeps equal reals and lists).
        if let (Value::Int(v), Some(Value::Int(p))) = (x, out.last()) {
            if v == p {
                continue;
            }
        }
        out.push(x.clone());
    }
    Ok(Value::list(out))
}

fn vl_sort_i(it: &mut Interp, a: &[Value]) -> LResult {
    let mut items = elements(it, &a[0])?;
    let less = it.callable(&a[1])?;
    // AutoCAD lists equal elements last-first: its reference gives
    // (vl-sort-i '(3 2 1 3) '<) => (2 1 3 0). A stable sort of the reversed list does that.
    items.reverse();
    let n = items.len();
    let order = sort_indices(it, &items, &less)?;
    Ok(Value::list(
        order.into_iter().map(|i| Value::Int((n - 1 - i) as i32)),
    ))
}

fn acad_strlsort(it: &mut Interp, a: &[Value]) -> LResult {
    let items = elements(it, &a[0])?;
    charge_sort(it, items.len())?;
    let mut strs = Vec::with_capacity(items.len());
    for x in &items {
        strs.push(it.string(x)?.to_string());
    }
    // Alphabetical as AutoCAD's collation: case only breaks ties.
    strs.sort_by(|x, y| {
        x.to_lowercase()
            .cmp(&y.to_lowercase())
            .then_with(|| x.cmp(y))
    });
    Ok(Value::list(strs.iter().map(|s| Value::str(s))))
}
