//! Bézier against Bézier: recursive subdivision with hull bounding boxes (Lane–Riesenfeld
//! style) until each surviving pair of sub-pieces provably holds at most one intersection:
//! when the tangent cones of the two sub-pieces (spanned by their control polygons' edges,
//! which contain every derivative direction, rational pieces included) share no direction up
//! to sign, two intersections would need a common chord direction inside both cones
//! (Sederberg & Meyers' loop test, applied to a pair). Such a pair is solved by Gauss–Newton
//! on |A(s) − B(u)|² (the 3-D least-squares form of the paper's Newton step) from the chords'
//! closest points; if Newton does not land inside the pair, the pair is split further.
//! Pairs whose cones keep overlapping (tangencies) are followed down to tolerance size.

use glam::DVec3;

use super::{LHit, LHits, LKind, TANGENT_SIN};
use crate::geom::bezier::Bez;
use crate::geom::piece::Piece;

struct Ctx<'a> {
    a: &'a Bez,
    b: &'a Bez,
    tol: f64,
    flat: f64,
    /// Pieces below this size whose tangent cones still overlap are near-tangent.
    graze: f64,
    /// The common plane's normal when both pieces are coplanar.
    plane: Option<DVec3>,
}

pub fn bez_bez(a: &Bez, b: &Bez, tol: f64, out: &mut LHits) {
    if coincident(a, b, tol) {
        out.push(LHit::new(
            0.0,
            0.0,
            a.eval(0.0),
            LKind::Overlap(Box::new(Piece::Bez(a.clone())), 1.0, 1.0),
        ));
        return;
    }
    if coincident_reversed(a, b, tol) {
        out.push(LHit::new(
            0.0,
            1.0,
            a.eval(0.0),
            LKind::Overlap(Box::new(Piece::Bez(a.clone())), 1.0, 0.0),
        ));
        return;
    }
    let (lo_a, hi_a) = a.hull_bbox();
    let (lo_b, hi_b) = b.hull_bbox();
    let scale = (hi_a - lo_a)
        .max_element()
        .max((hi_b - lo_b).max_element())
        .max(tol);
    let ctx = Ctx {
        a,
        b,
        tol,
        flat: (1e-9 * scale).max(tol),
        graze: 1e-3 * scale,
        plane: common_plane(a, b, tol),
    };
    let start = out.len();
    recurse(&ctx, a, (0.0, 1.0), b, (0.0, 1.0), 0, out);
    merge_overlaps(a, out, start, tol);
    // Remove duplicates found from neighbouring box pairs.
    let mut i = start;
    while i < out.len() {
        let dup = (start..i).any(|j| (out[j].p - out[i].p).length() <= tol);
        if dup {
            out.remove(i);
        } else {
            i += 1;
        }
    }
}

/// Join the shared stretches found by neighbouring sub-pieces into maximal overlap pieces
/// (each the sub-curve of `a` over the joined range) and drop point hits inside them.
fn merge_overlaps(a: &Bez, out: &mut LHits, start: usize, tol: f64) {
    let mut ranges: smallvec::SmallVec<[(f64, f64, f64, f64); 4]> = smallvec::SmallVec::new();
    for h in &out[start..] {
        if let LKind::Overlap(_, se, ue) = &h.kind {
            ranges.push((h.s, *se, h.u, *ue));
        }
    }
    if ranges.is_empty() {
        return;
    }
    ranges.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut merged: smallvec::SmallVec<[(f64, f64, f64, f64); 4]> = smallvec::SmallVec::new();
    for r in ranges {
        match merged.last_mut() {
            Some(m) if r.0 <= m.1 + 1e-12 => {
                if r.1 > m.1 {
                    m.1 = r.1;
                    m.3 = r.3;
                }
            }
            _ => merged.push(r),
        }
    }
    let inside = |s: f64| merged.iter().any(|m| s >= m.0 - 1e-12 && s <= m.1 + 1e-12);
    let mut kept: LHits = out
        .drain(start..)
        .filter(|h| !matches!(h.kind, LKind::Overlap(..)) && !inside(h.s))
        .collect();
    for (s0, s1, u0, u1) in merged {
        if (a.eval(s1) - a.eval(s0)).length() <= tol {
            // A stretch shorter than tol is a touch point.
            kept.push(LHit::new(s0, u0, a.eval(s0), LKind::Tangent));
            continue;
        }
        let piece = Piece::Bez(a.subsegment(s0, s1));
        kept.push(LHit::new(
            s0,
            u0,
            a.eval(s0),
            LKind::Overlap(Box::new(piece), s1, u1),
        ));
    }
    kept.sort_by(|x, y| x.s.total_cmp(&y.s));
    out.extend(kept);
}

fn coincident(a: &Bez, b: &Bez, tol: f64) -> bool {
    a.h.len() == b.h.len()
        && a.points()
            .zip(b.points())
            .all(|(p, q)| (p - q).length() <= tol)
        && a.h
            .iter()
            .zip(&b.h)
            .all(|(x, y)| (x.w / a.h[0].w - y.w / b.h[0].w).abs() <= 1e-12)
}

fn coincident_reversed(a: &Bez, b: &Bez, tol: f64) -> bool {
    let mut h = b.h.clone();
    h.reverse();
    coincident(
        a,
        &Bez {
            h,
            rational: b.rational,
        },
        tol,
    )
}

fn boxes_meet(a: &Bez, b: &Bez, tol: f64) -> bool {
    let (la, ha) = a.hull_bbox();
    let (lb, hb) = b.hull_bbox();
    !((la - tol).cmpgt(hb + tol).any() || (lb - tol).cmpgt(ha + tol).any())
}

/// The tangent cone of a piece: (unit axis, half-angle), or `None` when it is 90° or wider.
fn cone(x: &Bez) -> Option<(DVec3, f64)> {
    let mut prev: Option<DVec3> = None;
    let mut axis = DVec3::ZERO;
    let mut edges: smallvec::SmallVec<[DVec3; 8]> = smallvec::SmallVec::new();
    for p in x.points() {
        if let Some(q) = prev {
            if let Some(e) = (p - q).try_normalize() {
                axis += e;
                edges.push(e);
            }
        }
        prev = Some(p);
    }
    let axis = axis.try_normalize()?;
    let mut cos_half: f64 = 1.0;
    for e in &edges {
        cos_half = cos_half.min(axis.dot(*e));
    }
    if cos_half <= 0.0 {
        return None;
    }
    Some((axis, cos_half.min(1.0).acos()))
}

/// True when no tangent of `a` is parallel (either sense) to a tangent of `b`.
fn cones_disjoint(a: &Bez, b: &Bez) -> bool {
    let (Some((xa, ha)), Some((xb, hb))) = (cone(a), cone(b)) else {
        return false;
    };
    let between = xa.dot(xb).abs().min(1.0).acos();
    between > ha + hb + 1e-12
}

fn size(x: &Bez) -> f64 {
    let (l, h) = x.hull_bbox();
    (h - l).max_element()
}

fn recurse(
    ctx: &Ctx,
    a: &Bez,
    ra: (f64, f64),
    b: &Bez,
    rb: (f64, f64),
    depth: u32,
    out: &mut LHits,
) {
    if !boxes_meet(a, b, ctx.tol) {
        return;
    }
    let (sa, sb) = (size(a), size(b));
    let tiny = sa <= ctx.flat && sb <= ctx.flat;
    if let Some(n) = ctx.plane {
        if sa.max(sb) <= ctx.graze && !cones_disjoint(a, b) {
            graze(ctx, n, ra, rb, out);
            return;
        }
    }
    if tiny || depth >= 60 || cones_disjoint(a, b) {
        // At most one intersection here (or tolerance-sized pieces): Newton from the chords.
        let (a0, a1) = (a.eval(0.0), a.eval(1.0));
        let (b0, b1) = (b.eval(0.0), b.eval(1.0));
        let (s, u, _) = segment_closest(a0, a1, b0, b1);
        let s0 = ra.0 + (ra.1 - ra.0) * s;
        let u0 = rb.0 + (rb.1 - rb.0) * u;
        if let Some(h) = polish(ctx, s0, u0) {
            // Accept only a root inside this pair (a neighbour pair owns the others).
            let slack_a = 1e-9 * (ra.1 - ra.0);
            let slack_b = 1e-9 * (rb.1 - rb.0);
            if (ra.0 - slack_a..=ra.1 + slack_a).contains(&h.s)
                && (rb.0 - slack_b..=rb.1 + slack_b).contains(&h.u)
            {
                out.push(h);
                return;
            }
        }
        if tiny || depth >= 60 {
            return;
        }
    }
    if sa >= sb {
        let (l, r) = a.split(0.5);
        let m = 0.5 * (ra.0 + ra.1);
        recurse(ctx, &l, (ra.0, m), b, rb, depth + 1, out);
        recurse(ctx, &r, (m, ra.1), b, rb, depth + 1, out);
    } else {
        let (l, r) = b.split(0.5);
        let m = 0.5 * (rb.0 + rb.1);
        recurse(ctx, a, ra, &l, (rb.0, m), depth + 1, out);
        recurse(ctx, a, ra, &r, (m, rb.1), depth + 1, out);
    }
}

/// The normal of the plane holding both pieces' control points (within `tol`), if any.
fn common_plane(a: &Bez, b: &Bez, tol: f64) -> Option<DVec3> {
    let pts: smallvec::SmallVec<[DVec3; 16]> = a.points().chain(b.points()).collect();
    let o = pts[0];
    // The widest pair of spanning directions from o gives a robust normal.
    let far = pts.iter().copied().max_by(|p, q| {
        (*p - o)
            .length_squared()
            .total_cmp(&(*q - o).length_squared())
    })?;
    let d1 = far - o;
    let n = pts
        .iter()
        .map(|p| d1.cross(*p - o))
        .max_by(|x, y| x.length_squared().total_cmp(&y.length_squared()))?
        .try_normalize()?;
    pts.iter()
        .all(|p| (*p - o).dot(n).abs() <= tol)
        .then_some(n)
}

/// Near-tangent coplanar sub-pieces: the signed gap g(s) from A(s) to B (along B's in-plane
/// normal at the nearest point) is a smooth function of one variable. Sampled, its sign
/// changes are crossings (bisection); a sampled local minimum of |g| is searched for its
/// extremum (golden section), which either dips through zero — two crossings however close —
/// or stays within `tol` of it — a tangency. This keeps a 7e-6 pair of roots apart where box
/// subdivision alone would only see "within tolerance" everywhere.
fn graze(ctx: &Ctx, n: DVec3, ra: (f64, f64), rb: (f64, f64), out: &mut LHits) {
    let gap = |s: f64, u0: f64| -> (f64, f64) {
        let p = ctx.a.eval(s);
        let mut u = u0;
        for _ in 0..30 {
            let (q, d) = ctx.b.eval_deriv(u);
            let dd = d.length_squared();
            if dd == 0.0 {
                break;
            }
            let step = (p - q).dot(d) / dd;
            let nu = (u + step).clamp(0.0, 1.0);
            if (nu - u).abs() < 1e-16 {
                u = nu;
                break;
            }
            u = nu;
        }
        let (q, d) = ctx.b.eval_deriv(u);
        let side = n.cross(d).normalize_or_zero();
        ((p - q).dot(side), u)
    };
    const K: usize = 16;
    let mut ss = [0.0; K + 1];
    let mut gs = [0.0; K + 1];
    let mut us = [0.0; K + 1];
    let mut u = 0.5 * (rb.0 + rb.1);
    for i in 0..=K {
        ss[i] = ra.0 + (ra.1 - ra.0) * i as f64 / K as f64;
        let (g, nu) = gap(ss[i], u);
        gs[i] = g;
        us[i] = nu;
        u = nu;
    }
    // The whole sub-piece within tol of B: a shared stretch (merged with its neighbours by
    // `merge_overlaps`).
    if gs.iter().all(|g| g.abs() <= ctx.tol) {
        let p0 = ctx.a.eval(ra.0);
        let p1 = ctx.a.eval(ra.1);
        let (q0, q1) = (ctx.b.eval(us[0]), ctx.b.eval(us[K]));
        if (p0 - q0).length() <= ctx.tol && (p1 - q1).length() <= ctx.tol {
            out.push(LHit::new(
                ra.0,
                us[0],
                p0,
                LKind::Overlap(Box::new(Piece::Bez(ctx.a.clone())), ra.1, us[K]),
            ));
            return;
        }
    }
    let push = |s: f64, u0: f64, tangent: bool, out: &mut LHits| {
        let (_, u) = gap(s, u0);
        let slack = 1e-9 * (rb.1 - rb.0);
        if !(rb.0 - slack..=rb.1 + slack).contains(&u) {
            return;
        }
        let (pa, pb) = (ctx.a.eval(s), ctx.b.eval(u));
        if (pa - pb).length() > ctx.tol {
            return;
        }
        let (ta, tb) = (ctx.a.deriv(s), ctx.b.deriv(u));
        let parallel = ta.cross(tb).length() <= TANGENT_SIN * ta.length() * tb.length();
        let kind = if tangent || parallel {
            LKind::Tangent
        } else {
            LKind::Cross
        };
        out.push(LHit::new(s, u, (pa + pb) * 0.5, kind));
    };
    let root = |mut lo: f64, mut hi: f64, glo: f64, u0: f64| -> f64 {
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            let (gm, _) = gap(m, u0);
            if (gm > 0.0) == (glo > 0.0) {
                lo = m;
            } else {
                hi = m;
            }
            if hi - lo <= 1e-16 {
                break;
            }
        }
        0.5 * (lo + hi)
    };
    for i in 0..=K {
        if gs[i] == 0.0 {
            // A sampled exact zero: a crossing if the gap changes sign across it.
            let l = if i > 0 { gs[i - 1] } else { 0.0 };
            let r = if i < K { gs[i + 1] } else { 0.0 };
            push(ss[i], us[i], l * r >= 0.0, out);
        } else if i < K && gs[i] * gs[i + 1] < 0.0 {
            push(root(ss[i], ss[i + 1], gs[i], us[i]), us[i], false, out);
        }
    }
    // Local minima of |g| without a sign change around them: look for the extremum.
    for i in 0..=K {
        let left = if i > 0 { gs[i - 1] } else { f64::INFINITY };
        let right = if i < K { gs[i + 1] } else { f64::INFINITY };
        let gi = gs[i];
        if gi == 0.0 || !(gi.abs() <= left.abs() && gi.abs() <= right.abs()) {
            continue;
        }
        if (i > 0 && left * gi < 0.0) || (i < K && right * gi < 0.0) {
            continue;
        }
        let sgn = gi.signum();
        let f = |s: f64| sgn * gap(s, us[i]).0;
        let (lo, hi) = (ss[i.saturating_sub(1)], ss[(i + 1).min(K)]);
        let se = crate::geom::minimize::golden_section_min(f, lo, hi, 100, 1e-16);
        let ge = f(se);
        if ge < 0.0 {
            // The gap dips through zero: a root on each side of the extremum.
            push(root(lo, se, gi, us[i]), us[i], false, out);
            push(root(se, hi, -gi, us[i]), us[i], false, out);
        } else if ge <= ctx.tol {
            push(se, us[i], true, out);
        }
    }
}

/// Closest points of two segments: (s, u, distance).
fn segment_closest(a0: DVec3, a1: DVec3, b0: DVec3, b1: DVec3) -> (f64, f64, f64) {
    let (d1, d2, r) = (a1 - a0, b1 - b0, a0 - b0);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let (s, u);
    if a <= 1e-300 && e <= 1e-300 {
        s = 0.0;
        u = 0.0;
    } else if a <= 1e-300 {
        s = 0.0;
        u = (f / e).clamp(0.0, 1.0);
    } else {
        let c = d1.dot(r);
        if e <= 1e-300 {
            u = 0.0;
            s = (-c / a).clamp(0.0, 1.0);
        } else {
            let bb = d1.dot(d2);
            let denom = a * e - bb * bb;
            let mut s1 = if denom > 0.0 {
                ((bb * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut u1 = (bb * s1 + f) / e;
            if u1 < 0.0 {
                u1 = 0.0;
                s1 = (-c / a).clamp(0.0, 1.0);
            } else if u1 > 1.0 {
                u1 = 1.0;
                s1 = ((bb - c) / a).clamp(0.0, 1.0);
            }
            s = s1;
            u = u1;
        }
    }
    let dist = ((a0 + d1 * s) - (b0 + d2 * u)).length();
    (s, u, dist)
}

/// Gauss–Newton on r(s, u) = A(s) − B(u): solve the 2×2 normal equations
/// [A'·A'  −A'·B'; −A'·B'  B'·B'] δ = [−A'·r; B'·r], parameters clamped to [0, 1].
fn polish(ctx: &Ctx, mut s: f64, mut u: f64) -> Option<LHit> {
    let mut last = f64::INFINITY;
    for _ in 0..60 {
        let (pa, da) = ctx.a.eval_deriv(s);
        let (pb, db) = ctx.b.eval_deriv(u);
        let r = pa - pb;
        let (a11, a12, a22) = (da.dot(da), -da.dot(db), db.dot(db));
        let (b1, b2) = (-da.dot(r), db.dot(r));
        let det = a11 * a22 - a12 * a12;
        let (ds, du) = if det.abs() > 1e-30 * a11 * a22 {
            ((b1 * a22 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det)
        } else {
            // Parallel tangents: move along the steepest descent of each separately.
            (
                if a11 > 0.0 { b1 / a11 } else { 0.0 },
                if a22 > 0.0 { b2 / a22 } else { 0.0 },
            )
        };
        s = (s + ds).clamp(0.0, 1.0);
        u = (u + du).clamp(0.0, 1.0);
        let step = ds.abs() + du.abs();
        if step < 1e-16 || (step >= last && step < 1e-12) {
            break;
        }
        last = step;
    }
    let (pa, ta) = ctx.a.eval_deriv(s);
    let (pb, tb) = ctx.b.eval_deriv(u);
    if (pa - pb).length() > ctx.tol {
        return None;
    }
    let kind = if ta.cross(tb).length() <= TANGENT_SIN * ta.length() * tb.length() {
        LKind::Tangent
    } else {
        LKind::Cross
    };
    Some(LHit::new(s, u, (pa + pb) * 0.5, kind))
}
