//! Selection sets: `ssget` with the non-interactive modes and AutoCAD's filter lists, and the
//! `ss...` functions.
//!
//! A filter is tested against each entity's `entget` list: strings match as `wcmatch`
//! patterns (case-insensitive, as AutoCAD compares names), numbers by value (with a preceding
//! `(-4 . "<")`-style relational operator when given), points coordinate-wise
//! (`(-4 . "<,>,*")`), and `(-4 . "<AND")` ... `(-4 . "AND>")`, `<OR`, `<XOR`, `<NOT` group
//! the tests. A colour filter (62 . 256) matches BYLAYER entities, which have no 62 group.

use glam::DVec2;

use super::dxf_list::{entity_list, point_of, Groups};
use super::select_area::{select_area, AreaMode};
use super::{ename_arg, ename_value, pickset_arg, pickset_value, Ename, EntityState};
use crate::builtins::drawing::drawing;
use crate::builtins::text::wcmatch::WcPattern;
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};

/// One parsed filter node.
enum Filter {
    /// A group test, with the relational operator that preceded it (`=` when none).
    Test {
        code: i32,
        op: String,
        value: Value,
        /// The upper-cased wild-card pattern of a string test, compiled once.
        pattern: Option<WcPattern>,
    },
    And(Vec<Filter>),
    Or(Vec<Filter>),
    Xor(Vec<Filter>),
    Not(Box<Filter>),
}

fn filter_err(msg: &str) -> Exn {
    err(format!("ssget: bad filter list: {msg}"))
}

/// Parses a filter list into an implicit AND of its nodes.
fn parse_filter(it: &Interp, list: &Value) -> Result<Filter, Exn> {
    let g = Groups::parse(it, list)?;
    let mut pos = 0;
    let nodes = parse_seq(&g.0, &mut pos, None)?;
    Ok(Filter::And(nodes))
}

/// Nodes until the closing `(-4 . "NAME>")` (or the end of the list at top level).
fn parse_seq(g: &[(i32, Value)], pos: &mut usize, close: Option<&str>) -> Result<Vec<Filter>, Exn> {
    let mut out = Vec::new();
    let mut op = "=".to_string();
    while *pos < g.len() {
        let (code, v) = &g[*pos];
        *pos += 1;
        if *code == -4 {
            let s = v
                .as_str()
                .ok_or_else(|| filter_err("a -4 group needs a string operator"))?
                .to_uppercase();
            match s.as_str() {
                "<AND" | "<OR" | "<XOR" | "<NOT" => {
                    let name = &s[1..];
                    let inner = parse_seq(g, pos, Some(name))?;
                    out.push(match name {
                        "AND" => Filter::And(inner),
                        "OR" => Filter::Or(inner),
                        "XOR" => {
                            if inner.len() != 2 {
                                return Err(filter_err("<XOR needs exactly two operands"));
                            }
                            Filter::Xor(inner)
                        }
                        _ => {
                            let mut inner = inner;
                            if inner.len() != 1 {
                                return Err(filter_err("<NOT needs exactly one operand"));
                            }
                            Filter::Not(Box::new(inner.remove(0)))
                        }
                    });
                }
                "AND>" | "OR>" | "XOR>" | "NOT>" => {
                    return if close == Some(&s[..s.len() - 1]) {
                        Ok(out)
                    } else {
                        Err(filter_err(&format!("unexpected {s}")))
                    };
                }
                _ => op = s,
            }
            continue;
        }
        out.push(Filter::Test {
            code: *code,
            op: std::mem::replace(&mut op, "=".to_string()),
            value: v.clone(),
            pattern: v.as_str().map(|p| WcPattern::new(&p.to_uppercase())),
        });
    }
    match close {
        Some(c) => Err(filter_err(&format!("<{c} is not closed by {c}>"))),
        None => Ok(out),
    }
}

fn compare(op: &str, a: f64, b: f64) -> bool {
    match op {
        "*" => true,
        "=" => a == b,
        "!=" | "/=" | "<>" => a != b,
        "<" => a < b,
        "<=" => a <= b,
        ">" => a > b,
        ">=" => a >= b,
        _ => false,
    }
}

/// One group of the entity against one test value.
fn test_value(
    it: &Interp,
    code: i32,
    op: &str,
    want: &Value,
    pattern: Option<&WcPattern>,
    got: &Value,
) -> bool {
    match (want, got) {
        (Value::Str(_), Value::Str(g)) => {
            // Names compare case-insensitively: match upper against upper.
            pattern.is_some_and(|p| p.matches(&g.to_uppercase()))
        }
        (Value::Cons(_), Value::Cons(_)) => {
            let (Ok(w), Ok(g)) = (point_of(it, code, want), point_of(it, code, got)) else {
                return false;
            };
            let ops: Vec<&str> = if op.contains(',') {
                op.split(',').map(str::trim).collect()
            } else {
                vec![op; 3]
            };
            (0..3).all(|i| compare(ops.get(i).copied().unwrap_or("*"), g[i], w[i]))
        }
        (Value::Obj(_), Value::Obj(_)) => want.equal(got, 0.0),
        _ => match (want.as_f64(), got.as_f64()) {
            (Some(w), Some(g)) => compare(op, g, w),
            _ => false,
        },
    }
}

fn eval(it: &Interp, f: &Filter, groups: &Groups) -> bool {
    match f {
        Filter::Test {
            code,
            op,
            value,
            pattern,
        } if *code == -3 => groups
            .all(-3)
            .any(|g| super::objects::xdata_filter_match(value, g)),
        Filter::Test {
            code,
            op,
            value,
            pattern,
        } => {
            let mut any = false;
            for v in groups.all(*code) {
                any = true;
                if test_value(it, *code, op, value, pattern.as_ref(), v) {
                    return true;
                }
            }
            // BYLAYER entities have no 62 group; (62 . 256) selects them.
            !any && *code == 62 && test_value(it, 62, op, value, None, &Value::Int(256))
        }
        Filter::And(v) => v.iter().all(|f| eval(it, f, groups)),
        Filter::Or(v) => v.iter().any(|f| eval(it, f, groups)),
        Filter::Xor(v) => eval(it, &v[0], groups) != eval(it, &v[1], groups),
        Filter::Not(f) => !eval(it, f, groups),
    }
}

/// Whether every test of the filter is on the type, layer or colour.
fn only_common_groups(f: &Filter) -> bool {
    match f {
        Filter::Test { code, .. } => matches!(code, 0 | 8 | 62),
        Filter::And(v) | Filter::Or(v) | Filter::Xor(v) => v.iter().all(only_common_groups),
        Filter::Not(f) => only_common_groups(f),
    }
}

fn has_xdata_test(f: &Filter) -> bool {
    match f {
        Filter::Test { code, .. } => *code == -3,
        Filter::And(v) | Filter::Or(v) | Filter::Xor(v) => v.iter().any(has_xdata_test),
        Filter::Not(f) => has_xdata_test(f),
    }
}

/// The live entities matching `filter` (all of them without one), in drawing order.
fn select(it: &mut Interp, filter: Option<&Filter>) -> Result<Vec<u64>, Exn> {
    let handles: Vec<u64> = drawing(it).entities().map(|e| e.handle).collect();
    let Some(f) = filter else {
        return Ok(handles);
    };
    let mut out = Vec::new();
    if only_common_groups(f) {
        // The usual filters (type, layer, colour) need no full entget list per entity.
        let rows: Vec<(u64, String, String, Option<i16>)> = drawing(it)
            .entities()
            .map(|e| {
                let ty = e.kind.type_name().to_string();
                (e.handle, ty, e.layer.clone(), e.color)
            })
            .collect();
        for (handle, ty, layer, color) in rows {
            let mut g = vec![(0, Value::str(&ty)), (8, Value::Str(layer.into()))];
            if let Some(c) = color {
                g.push((62, Value::Int(c as i32)));
            }
            if eval(it, f, &Groups(g)) {
                out.push(handle);
            }
        }
        return Ok(out);
    }
    let all_apps = ["*".to_string()];
    for h in handles {
        let list = entity_list(it, Ename { handle: h, sub: 0 }).unwrap_or(Value::Nil);
        let mut g = Groups::parse(it, &list)?;
        // Extended data is looked at only when the filter has a -3 test (it is costly).
        if has_xdata_test(f) {
            if let Some(x) = super::objects::xdata_group(it, h, &all_apps) {
                g.0.push((-3, x.cdr()));
            }
        }
        if eval(it, f, &g) {
            out.push(h);
        }
    }
    Ok(out)
}

pub fn ssget(it: &mut Interp, a: &[Value]) -> LResult {
    let mode = match a.first() {
        Some(Value::Str(s)) => Some(s.trim_start_matches(['_', '+', '.']).to_uppercase()),
        _ => None,
    };
    let Some(mode) = mode else {
        return Err(err(
            "ssget: interactive selection needs a user; in a headless run use (ssget \"X\" [filter]), \"A\", \"L\" or \"P\"",
        ));
    };
    // The filter list follows the mode's points; for the other modes it is the last
    // argument when that is a list of pairs.
    let filter_arg = match mode.as_str() {
        "W" | "C" => a.get(3),
        "WP" | "CP" | "F" => a.get(2),
        _ => a.last().filter(|_| a.len() >= 2),
    };
    let filter = match filter_arg {
        Some(v @ Value::Cons(c)) if matches!(c.car, Value::Cons(_)) => Some(parse_filter(it, v)?),
        _ => None,
    };
    let mut found = match mode.as_str() {
        "X" | "A" => select(it, filter.as_ref())?,
        "L" => {
            let last = drawing(it).last();
            let mut v: Vec<u64> = last.into_iter().collect();
            if let Some(f) = &filter {
                let all = select(it, Some(f))?;
                v.retain(|h| all.contains(h));
            }
            v
        }
        "P" => {
            let prev = it.ext::<EntityState>().previous.clone();
            let d = drawing(it);
            let mut v: Vec<u64> = prev.into_iter().filter(|h| d.get(*h).is_some()).collect();
            if let Some(f) = &filter {
                let all = select(it, Some(f))?;
                v.retain(|h| all.contains(h));
            }
            v
        }
        "W" | "C" => {
            let (p1, p2) = (point2(it, a.get(1))?, point2(it, a.get(2))?);
            let (lo, hi) = (p1.min(p2), p1.max(p2));
            let rect = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
            let how = if mode == "W" {
                AreaMode::Window
            } else {
                AreaMode::Crossing
            };
            by_area(it, &rect, how, filter.as_ref())?
        }
        "WP" | "CP" | "F" => {
            let list = a.get(1).cloned().unwrap_or(Value::Nil);
            let pts: Vec<DVec2> = list
                .iter()
                .map(|p| point2(it, Some(p)))
                .collect::<Result<_, _>>()?;
            let (how, need) = match mode.as_str() {
                "WP" => (AreaMode::Window, 3),
                "CP" => (AreaMode::Crossing, 3),
                _ => (AreaMode::Fence, 2),
            };
            if pts.len() < need {
                return Err(err(format!(
                    "ssget: mode \"{mode}\" needs a list of at least {need} points"
                )));
            }
            by_area(it, &pts, how, filter.as_ref())?
        }
        m => {
            return Err(err(format!(
                "ssget: selection mode \"{m}\" needs a user; in a headless run use \"X\" [filter], \"A\", \"L\", \"P\", \"W\"/\"C\" with two points, or \"WP\"/\"CP\"/\"F\" with a point list"
            )))
        }
    };
    found.dedup();
    if found.is_empty() {
        return Ok(Value::Nil);
    }
    it.ext::<EntityState>().previous = found.clone();
    Ok(pickset_value(it, found))
}

/// A point argument's X and Y.
fn point2(it: &Interp, v: Option<&Value>) -> Result<DVec2, Exn> {
    let v = v.ok_or_else(|| err("ssget: this selection mode needs points"))?;
    let xs: Option<Vec<f64>> = v.iter().map(Value::as_f64).collect();
    match xs {
        Some(xs) if matches!(v, Value::Cons(_)) && (2..=3).contains(&xs.len()) => {
            Ok(DVec2::new(xs[0], xs[1]))
        }
        _ => Err(err(format!("ssget: bad point: {}", it.prin1_string(v)))),
    }
}

/// The entities a boundary selects that also pass the filter.
fn by_area(
    it: &mut Interp,
    pts: &[DVec2],
    how: AreaMode,
    filter: Option<&Filter>,
) -> Result<Vec<u64>, Exn> {
    let mut v = select_area(drawing(it), pts, how);
    if let Some(f) = filter {
        let all = select(it, Some(f))?;
        v.retain(|h| all.contains(h));
    }
    Ok(v)
}

pub fn sslength(it: &mut Interp, a: &[Value]) -> LResult {
    let ss = pickset_arg(it, &a[0])?;
    Ok(Value::Int(ss.members.borrow().len() as i32))
}

pub fn ssname(it: &mut Interp, a: &[Value]) -> LResult {
    let ss = pickset_arg(it, &a[0])?;
    let i = match &a[1] {
        Value::Int(i) => *i as f64,
        Value::Real(r) => r.trunc(),
        v => return Err(crate::lang::builtin::bad_arg(it, "fixnump", v)),
    };
    let h = {
        let m = ss.members.borrow();
        if i < 0.0 || i >= m.len() as f64 {
            return Ok(Value::Nil);
        }
        m[i as usize]
    };
    Ok(ename_value(it, h))
}

pub fn ssadd(it: &mut Interp, a: &[Value]) -> LResult {
    let e = match a.first() {
        Some(v) if v.truthy() => Some(ename_arg(it, v)?),
        _ => None,
    };
    if let Some(e) = e {
        if drawing(it).get(e.handle).is_none() || e.sub != 0 {
            return Ok(Value::Nil);
        }
    }
    match a.get(1).filter(|v| v.truthy()) {
        Some(v) => {
            let ss = pickset_arg(it, v)?;
            if let Some(e) = e {
                let mut m = ss.members.borrow_mut();
                if !m.contains(&e.handle) {
                    m.push(e.handle);
                }
            }
            Ok(v.clone())
        }
        None => {
            let members = e.map(|e| vec![e.handle]).unwrap_or_default();
            Ok(pickset_value(it, members))
        }
    }
}

pub fn ssdel(it: &mut Interp, a: &[Value]) -> LResult {
    let e = ename_arg(it, &a[0])?;
    let ss = pickset_arg(it, &a[1])?;
    let mut m = ss.members.borrow_mut();
    match m.iter().position(|h| *h == e.handle) {
        Some(i) => {
            m.remove(i);
            Ok(a[1].clone())
        }
        None => Ok(Value::Nil),
    }
}

pub fn ssmemb(it: &mut Interp, a: &[Value]) -> LResult {
    let e = ename_arg(it, &a[0])?;
    let ss = pickset_arg(it, &a[1])?;
    let found = ss.members.borrow().contains(&e.handle);
    Ok(if found { a[0].clone() } else { Value::Nil })
}

/// The live handles a selection value names: a PICKSET, an ENAME, or an `entsel`-style list
/// `(ename point)`. For commands such as ERASE.
pub fn selected_handles(v: &Value) -> Option<Vec<u64>> {
    if let Some(ss) = v.as_obj::<super::PickSet>() {
        let m = ss.members.borrow().clone();
        return Some(m);
    }
    if let Some(e) = v.as_obj::<Ename>() {
        return Some(vec![e.handle]);
    }
    if let Value::Cons(c) = v {
        if let Some(e) = c.car.as_obj::<Ename>() {
            return Some(vec![e.handle]);
        }
    }
    None
}
