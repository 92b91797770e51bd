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
    };
    let start = out.len();
    recurse(&ctx, a, (0.0, 1.0), b, (0.0, 1.0), 0, out);
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
