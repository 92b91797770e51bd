//! Writing back an opened entity whose geometry a script changed: its original groups are
//! kept, and only the groups the model owns for its type (points, radius, angles, flags bits
//! the model decides...) are replaced by the values the writer gives them. Everything the
//! model does not hold (thickness, line type scale, true colour, transparency, text
//! alignment, per-vertex widths, tolerances, application and extended data) survives the
//! edit, as in AutoCAD, where `entmod` changes only the groups it is given.

use glam::DVec3;

use super::drawing::{Entity, EntityKind};
use super::dxfin::factory::record_ranges;
use super::record::TagList;

/// How the model owns a type's groups.
struct Owned {
    /// Groups the model decides, one value each (replaced, added or dropped to match).
    fixed: fn(i32) -> bool,
    /// Groups of a variable-length run (vertices, knots, control points), replaced as a
    /// block where the original's run started.
    run: fn(i32) -> bool,
    /// For flags group 70: the bits the model decides (the others stay as read).
    flag_bits: i64,
}

fn owned(ty: &str) -> Option<Owned> {
    fn none(_: i32) -> bool {
        false
    }
    let fixed: fn(i32) -> bool = match ty {
        "LINE" => |c| matches!(c, 8 | 62 | 10 | 20 | 30 | 11 | 21 | 31),
        "POINT" => |c| matches!(c, 8 | 62 | 10 | 20 | 30),
        "CIRCLE" => |c| matches!(c, 8 | 62 | 10 | 20 | 30 | 40 | 210 | 220 | 230),
        "ARC" => |c| matches!(c, 8 | 62 | 10 | 20 | 30 | 40 | 50 | 51 | 210 | 220 | 230),
        "ELLIPSE" => |c| matches!(c, 8 | 62 | 10 | 20 | 30 | 11 | 21 | 31 | 40..=42 | 210..=230),
        "3DFACE" => |c| matches!(c, 8 | 62 | 10..=13 | 20..=23 | 30..=33),
        "TEXT" => |c| matches!(c, 8 | 62 | 1 | 7 | 10 | 20 | 30 | 40 | 50),
        "LWPOLYLINE" => |c| matches!(c, 8 | 62 | 70 | 90 | 38 | 210 | 220 | 230),
        "SPLINE" => |c| matches!(c, 8 | 62 | 70..=74 | 210 | 220 | 230),
        "POLYLINE" => |c| matches!(c, 8 | 62 | 10 | 20 | 30 | 70),
        "VERTEX" => |c| matches!(c, 8 | 10 | 20 | 30 | 42),
        _ => return None,
    };
    let (run, flag_bits): (fn(i32) -> bool, i64) = match ty {
        "LWPOLYLINE" => (|c| matches!(c, 10 | 20 | 42), 1),
        // The planar bit (8) follows the edited control points, with the normal (210),
        // as AutoCAD recomputes both on an edit (the linear bit is settled in
        // `merge_changed`).
        "SPLINE" => (
            |c| matches!(c, 10 | 20 | 30 | 11 | 21 | 31 | 40 | 41),
            1 | 4 | 8,
        ),
        "POLYLINE" => (none, 1 | 8),
        _ => (none, 0),
    };
    Some(Owned {
        fixed,
        run,
        flag_bits,
    })
}

/// The entity's groups: `orig` (as read) with the model's groups from `new` (as the writer
/// wrote the changed entity) merged in. `None` when the two cannot be merged group by group
/// (another type, a 2D polyline turned 3D...); the caller then writes the model's groups.
pub fn merge_changed(orig: &TagList, new: &TagList, e: &Entity, was: &Entity) -> Option<TagList> {
    let ty = orig.type_name();
    if ty != new.type_name() {
        return None;
    }
    let or = record_ranges(orig);
    let nr = record_ranges(new);
    let own = owned(ty)?;
    let mut out = TagList::new();
    let o0: Vec<(i32, &str)> = or[0].clone().map(|i| orig.at(i)).collect();
    let n0: Vec<(i32, &str)> = nr[0].clone().map(|i| new.at(i)).collect();
    if ty == "POLYLINE" {
        let flags = |g: &[(i32, &str)]| int_of(g, 70) & 8;
        if flags(&o0) != flags(&n0) {
            return None;
        }
    }
    let mut first = merge_record(&o0, &n0, &own, ty == "LWPOLYLINE");
    if ty == "TEXT" {
        shift_alignment_point(&mut first, e, was);
    }
    if let EntityKind::Spline { curve, .. } = &e.kind {
        settle_linear_bit(&mut first, &curve.ctrl);
    }
    for (c, v) in &first {
        out.push(*c, v);
    }
    if ty == "POLYLINE" {
        let vertex = owned("VERTEX")?;
        let overt: Vec<_> = or[1..].iter().filter(|r| is(orig, r, "VERTEX")).collect();
        let nvert: Vec<_> = nr[1..].iter().filter(|r| is(new, r, "VERTEX")).collect();
        for (i, nv) in nvert.iter().enumerate() {
            let ng: Vec<(i32, &str)> = (*nv).clone().map(|k| new.at(k)).collect();
            match overt.get(i) {
                Some(ov) => {
                    let og: Vec<(i32, &str)> = (*ov).clone().map(|k| orig.at(k)).collect();
                    for (c, v) in merge_record(&og, &ng, &vertex, false) {
                        out.push(c, &v);
                    }
                }
                // A vertex the script added: the writer's record (its handle is fresh).
                None => ng.iter().for_each(|(c, v)| out.push(*c, v)),
            }
        }
        // The SEQEND (and anything else after the vertices) as read.
        for r in or[1..].iter().filter(|r| !is(orig, r, "VERTEX")) {
            r.clone().for_each(|k| {
                let (c, v) = orig.at(k);
                out.push(c, v)
            });
        }
    } else {
        for r in &or[1..] {
            r.clone().for_each(|k| {
                let (c, v) = orig.at(k);
                out.push(c, v)
            });
        }
    }
    Some(out)
}

/// A SPLINE read as linear (bit 16, with the planar bit) stays so while its control points
/// are on one line; one bent off it is neither linear nor, by that bit, planar.
fn settle_linear_bit(first: &mut [(i32, String)], ctrl: &[DVec3]) {
    let Some((_, v)) = first.iter_mut().find(|(c, _)| *c == 70) else {
        return;
    };
    let flags: i64 = v.trim().parse().unwrap_or(0);
    if flags & 16 == 0 {
        return;
    }
    let flags = if collinear(ctrl) {
        flags | 8
    } else {
        flags & !16
    };
    *v = flags.to_string();
}

fn collinear(pts: &[DVec3]) -> bool {
    let Some(&o) = pts.first() else {
        return true;
    };
    let far = pts
        .iter()
        .copied()
        .max_by(|a, b| (*a - o).length().total_cmp(&(*b - o).length()))
        .unwrap_or(o);
    let span = far - o;
    let len = span.length();
    if len == 0.0 {
        return true;
    }
    let dir = span / len;
    pts.iter()
        .all(|p| (*p - o).cross(dir).length() <= 1e-9 * len)
}

fn is(t: &TagList, r: &std::ops::Range<usize>, ty: &str) -> bool {
    t.at(r.start).1 == ty
}

fn int_of(g: &[(i32, &str)], code: i32) -> i64 {
    g.iter()
        .find(|(c, _)| *c == code)
        .and_then(|(_, v)| v.trim().parse::<f64>().ok())
        .map_or(0, |x| x as i64)
}

/// One record: the original's groups in their order, owned ones replaced by the new
/// record's (in occurrence order), the run replaced as a block, owned groups the original
/// lacks inserted after their predecessor in the new record. Application data (102 braces)
/// and extended data (1000+) are never owned.
fn merge_record(
    o: &[(i32, &str)],
    n: &[(i32, &str)],
    own: &Owned,
    lw_vertices: bool,
) -> Vec<(i32, String)> {
    let owned_fixed = |c: i32| (own.fixed)(c);
    let mut placed: Vec<Option<usize>> = vec![None; n.len()];
    let mut out: Vec<(i32, String)> = Vec::with_capacity(o.len() + 4);
    let mut used = vec![false; n.len()];
    let mut run_done = false;
    let mut in_app = false;
    let body_end = o.iter().position(|(c, _)| *c >= 1000).unwrap_or(o.len());
    for (k, &(c, v)) in o.iter().enumerate() {
        if c == 102 {
            in_app = v.starts_with('{');
            out.push((c, v.to_string()));
            continue;
        }
        if in_app || k >= body_end || k == 0 {
            out.push((c, v.to_string()));
            continue;
        }
        if (own.run)(c) || (lw_vertices && matches!(c, 40 | 41 | 91) && run_started(o, k)) {
            if !run_done {
                run_done = true;
                emit_run(o, n, own, lw_vertices, &mut out, &mut placed, &mut used);
            }
            continue;
        }
        if owned_fixed(c) {
            if let Some(j) = (0..n.len()).find(|&j| !used[j] && n[j].0 == c) {
                used[j] = true;
                let value = if c == 70 && own.flag_bits != 0 {
                    let old: i64 = v.trim().parse().unwrap_or(0);
                    let new: i64 = n[j].1.trim().parse().unwrap_or(0);
                    ((old & !own.flag_bits) | (new & own.flag_bits)).to_string()
                } else {
                    n[j].1.to_string()
                };
                placed[j] = Some(out.len());
                out.push((c, value));
            }
            // An owned group the new record lacks: the model says it is absent (default).
            continue;
        }
        out.push((c, v.to_string()));
    }
    // Owned groups the original lacks: after their predecessor in the new record, else
    // before the extended data. One the writer gives its default value stays absent, as it
    // was (the writer always names a TEXT's style, a reader assumes "Standard").
    let mut tail_at = out
        .iter()
        .position(|(c, _)| *c >= 1000)
        .unwrap_or(out.len());
    // An extrusion is left out only when the whole vector is the default (0, 0, 1).
    let default_extrusion = [210, 220, 230].iter().all(|&c| {
        n.iter()
            .find(|g| g.0 == c)
            .is_none_or(|g| is_default(c, g.1))
    });
    for j in 1..n.len() {
        let c = n[j].0;
        let default = if matches!(c, 210 | 220 | 230) {
            default_extrusion
        } else {
            is_default(c, n[j].1)
        };
        if used[j] || !(owned_fixed(c) || (own.run)(c)) || default {
            continue;
        }
        // After the nearest earlier group of the new record that is placed: an owned one,
        // or its subclass marker (so a normal lands in its subclass, not AcDbEntity's).
        let at = (0..j)
            .rev()
            .find_map(|i| {
                placed[i].or_else(|| {
                    (n[i].0 == 100)
                        .then(|| out.iter().position(|(c, v)| *c == 100 && v == n[i].1))
                        .flatten()
                })
            })
            .map_or(tail_at, |p| p + 1);
        out.insert(at, (c, n[j].1.to_string()));
        for p in placed.iter_mut().flatten() {
            if *p >= at {
                *p += 1;
            }
        }
        if at <= tail_at {
            tail_at += 1;
        }
        placed[j] = Some(at);
        used[j] = true;
    }
    out
}

/// Whether a group's value is what a reader assumes when the group is missing.
fn is_default(code: i32, v: &str) -> bool {
    let num = |d: f64| v.trim().parse::<f64>().is_ok_and(|x| x == d);
    match code {
        7 => v.eq_ignore_ascii_case("Standard"),
        38 | 39 | 50 | 210 | 220 => num(0.0),
        230 => num(1.0),
        62 => num(256.0),
        _ => false,
    }
}

/// Whether an LWPOLYLINE group at `k` comes after its first vertex (40/41 before the first
/// 10 are the default widths, not per-vertex ones).
fn run_started(o: &[(i32, &str)], k: usize) -> bool {
    o[..k].iter().any(|(c, _)| *c == 10)
}

/// The new run; an LWPOLYLINE's vertices keep their original widths and ids (40, 41, 91)
/// by index.
fn emit_run(
    o: &[(i32, &str)],
    n: &[(i32, &str)],
    own: &Owned,
    lw_vertices: bool,
    out: &mut Vec<(i32, String)>,
    placed: &mut [Option<usize>],
    used: &mut [bool],
) {
    let mut extras: Vec<Vec<(i32, &str)>> = Vec::new();
    if lw_vertices {
        for &(c, v) in o {
            match c {
                10 => extras.push(Vec::new()),
                40 | 41 | 91 => {
                    if let Some(x) = extras.last_mut() {
                        x.push((c, v));
                    }
                }
                _ => {}
            }
        }
    }
    let mut vertex = 0usize;
    for j in 0..n.len() {
        let c = n[j].0;
        if !(own.run)(c) {
            continue;
        }
        used[j] = true;
        placed[j] = Some(out.len());
        out.push((c, n[j].1.to_string()));
        if lw_vertices && c == 20 {
            if let Some(x) = extras.get(vertex) {
                out.extend(x.iter().map(|(c, v)| (*c, v.to_string())));
            }
            vertex += 1;
        }
    }
}

/// A justified TEXT is placed by its alignment point (11): when the script moved the
/// insertion point, the alignment point moves with it.
fn shift_alignment_point(g: &mut [(i32, String)], e: &Entity, was: &Entity) {
    let (EntityKind::Text { insert: a, .. }, EntityKind::Text { insert: b, .. }) =
        (&was.kind, &e.kind)
    else {
        return;
    };
    let d: DVec3 = *b - *a;
    if d == DVec3::ZERO {
        return;
    }
    let justified = g
        .iter()
        .any(|(c, v)| matches!(c, 72 | 73) && v.trim().parse::<f64>().is_ok_and(|x| x != 0.0));
    if !justified {
        return;
    }
    for (c, v) in g.iter_mut() {
        let off = match c {
            11 => d.x,
            21 => d.y,
            31 => d.z,
            _ => continue,
        };
        if let Ok(x) = v.trim().parse::<f64>() {
            v.clear();
            super::dxf_writer::push_float(v, x + off);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flags_after(flags: &str, ctrl: &[DVec3]) -> String {
        let mut first = vec![(0, "SPLINE".to_string()), (70, flags.to_string())];
        settle_linear_bit(&mut first, ctrl);
        first[1].1.clone()
    }

    #[test]
    fn a_linear_spline_stays_linear_only_on_its_line() {
        let line = [
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(3.0, 3.0, 3.0),
        ];
        let bent = [
            DVec3::ZERO,
            DVec3::new(1.0, 1.2, 1.0),
            DVec3::new(3.0, 3.0, 3.0),
        ];
        assert_eq!(flags_after("24", &line), "24");
        assert_eq!(flags_after("16", &line), "24");
        assert_eq!(flags_after("24", &bent), "8");
        assert_eq!(flags_after("9", &bent), "9");
    }
}
