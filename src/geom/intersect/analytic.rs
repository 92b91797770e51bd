//! Closed forms for lines, circles and arcs in 3D (ZMOLD paper, SEEDS.md 000, made stable).
//!
//! No quadratic is solved by the textbook formula: a line meets a circle at the foot F of the
//! perpendicular from the centre ± the half chord √((r − h)(r + h)), and two circles meet at
//! a ± h with h² from the factored (Heron) form
//! (r1+r2−d)(d−r1+r2)(d+r1−r2)(r1+r2+d)/(4d²) — both free of cancellation at tangency.
//! Non-coplanar circles: the first circle is cut with the second circle's plane (the line
//! plane1 ∩ plane2), each candidate then tested against the second circle.

use std::f64::consts::TAU;

use glam::DVec3;

use super::{LKind, Sink, TANGENT_SIN};
use crate::geom::arc::{norm_angle, Arc};
use crate::geom::line::Line;
use crate::geom::piece::Piece;
use crate::geom::traits::ParamCurve;

#[inline]
fn kind_by_tangents(t1: DVec3, t2: DVec3) -> LKind {
    let (a, b) = (t1.length_squared(), t2.length_squared());
    if t1.cross(t2).length_squared() <= TANGENT_SIN * TANGENT_SIN * a * b {
        LKind::Tangent
    } else {
        LKind::Cross
    }
}

/// The parameter of `p` on a segment of length `len()` if within `tol` of its range.
#[inline]
fn seg_param(s: f64, len: impl FnOnce() -> f64, tol: f64) -> Option<f64> {
    if (0.0..=1.0).contains(&s) {
        return Some(s);
    }
    // Only now the length and the slack (a root and a division): most candidates are
    // inside or far outside.
    let slack = tol / len();
    if (-slack..=1.0 + slack).contains(&s) {
        Some(s.clamp(0.0, 1.0))
    } else {
        None
    }
}

/// Segment / segment: the closest points of the two carriers; collinear pieces give an
/// overlap segment (or a touch point when they only share an end).
pub fn line_line<S: Sink>(a: &Line, b: &Line, tol: f64, out: &mut S) {
    let (da, db) = (a.dir(), b.dir());
    let (la, lb) = (da.length(), db.length());
    let w = b.p0 - a.p0;
    let cross = da.cross(db);
    let cc = cross.length_squared();
    // Collinear: parallel, and both ends of b within tol of a's carrier.
    if cc <= 1e-18 * (la * lb) * (la * lb) {
        let dist_to_a = |p: DVec3| (p - a.p0).cross(da).length() / la;
        if dist_to_a(b.p0) <= tol && dist_to_a(b.p1) <= tol {
            collinear(a, b, tol, out);
            return;
        }
        if cc == 0.0 {
            return;
        }
    }
    let s = w.cross(db).dot(cross) / cc;
    let u = w.cross(da).dot(cross) / cc;
    let (Some(s), Some(u)) = (seg_param(s, || la, tol), seg_param(u, || lb, tol)) else {
        return;
    };
    let (pa, pb) = (a.eval(s), b.eval(u));
    if (pa - pb).length_squared() <= tol * tol {
        out.put(s, u, (pa + pb) * 0.5, kind_by_tangents(da, db));
    }
}

fn collinear<S: Sink>(a: &Line, b: &Line, tol: f64, out: &mut S) {
    let la = a.dir().length();
    let (s0, s1) = (a.project(b.p0), a.project(b.p1));
    let lo = s0.min(s1).max(0.0);
    let hi = s0.max(s1).min(1.0);
    if (hi - lo) * la > tol {
        let piece = Line {
            p0: a.eval(lo),
            p1: a.eval(hi),
        };
        let (u0, u1) = (b.project(piece.p0), b.project(piece.p1));
        out.put(
            lo,
            u0.clamp(0.0, 1.0),
            piece.p0,
            LKind::Overlap(Box::new(Piece::Line(piece)), hi, u1.clamp(0.0, 1.0)),
        );
    } else if (lo - hi) * la <= tol {
        let s = (0.5 * (lo + hi)).clamp(0.0, 1.0);
        let p = a.eval(s);
        out.put(s, b.project(p).clamp(0.0, 1.0), p, LKind::Tangent);
    }
}

/// Up to two candidate hits, then how to classify them: `Some(tangent)` when known for all,
/// `None` to compare the tangents at each point.
type Candidates<T> = ([T; 2], usize, Option<bool>);

/// Segment / arc (or full circle).
pub fn line_arc<S: Sink>(l: &Line, a: &Arc, tol: f64, out: &mut S) {
    let Some((cand, count, tangent)) = line_arc_candidates(l, a, tol) else {
        return;
    };
    let d = l.dir();
    // The segment test first (cheap), then the angles of the points that pass it, side by
    // side when there are two.
    let mut on = [(0.0, DVec3::ZERO); 2];
    let mut k = 0;
    for &(s, p) in &cand[..count] {
        if let Some(s) = seg_param(s, || d.length(), tol) {
            on[k] = (s, p);
            k += 1;
        }
    }
    let u = match k {
        0 => return,
        1 => [a.param_of_point(on[0].1, tol), None],
        _ => a.params_of2([on[0].1, on[1].1], tol),
    };
    for (&(s, p), u) in on.iter().zip(u).take(k) {
        let Some(u) = u else {
            continue;
        };
        let kind = match tangent {
            Some(true) => LKind::Tangent,
            Some(false) => LKind::Cross,
            None => kind_by_tangents(d, a.tangent_at_point(p)),
        };
        out.put(s, u, p, kind);
    }
}

/// The points (with their segment parameters) where the segment's carrier meets the circle.
#[inline(always)]
fn line_arc_candidates(l: &Line, a: &Arc, tol: f64) -> Option<Candidates<(f64, DVec3)>> {
    let d = l.dir();
    let n = a.normal;
    let c = a.center;
    let r = a.radius;
    let h0 = (l.p0 - c).dot(n);
    let dn = d.dot(n);
    let h1 = h0 + dn;
    if h0.abs() <= tol && h1.abs() <= tol {
        // In the circle's plane: project the segment into it.
        let q0 = l.p0 - n * h0;
        let dq = d - n * dn;
        let dq2 = dq.length_squared();
        let sf = -(q0 - c).dot(dq) / dq2;
        let foot = q0 + dq * sf;
        let h = (foot - c).length();
        if h > r + tol {
            return None;
        }
        let half = ((r - h) * (r + h)).max(0.0).sqrt();
        if 2.0 * half <= tol {
            let p = if h > 0.0 {
                c + (foot - c) * (r / h)
            } else {
                foot
            };
            return Some(([(sf, p); 2], 1, Some(true)));
        }
        let ds = half / dq2.sqrt();
        let (s1, s2) = (sf - ds, sf + ds);
        // The circle's tangent is perpendicular to the radius, so the sine of its angle with
        // the line is the cosine of the radius's: half / r at both points.
        let tangent = half <= TANGENT_SIN * r;
        return Some(([(s1, q0 + dq * s1), (s2, q0 + dq * s2)], 2, Some(tangent)));
    }
    if dn == 0.0 {
        return None;
    }
    // Pierces the plane once: on the circle there or nowhere.
    let s = -h0 / dn;
    let p = l.p0 + d * s;
    let rho = (p - c).length();
    ((rho - r).abs() <= tol).then_some(([(s, p); 2], 1, None))
}

/// Arc / arc (either may be a full circle), coplanar or not.
pub fn arc_arc<S: Sink>(a: &Arc, b: &Arc, tol: f64, out: &mut S) {
    let Some((p, count, tangent)) = arc_arc_candidates(a, b, tol, out) else {
        return;
    };
    // The angles are computed two at a time: both points on a, then, if either is on a,
    // both on b.
    let s = a.params_of2(p, tol);
    if s[..count].iter().all(Option::is_none) {
        return;
    }
    let u = b.params_of2(p, tol);
    for i in 0..count {
        let (Some(s), Some(u)) = (s[i], u[i]) else {
            continue;
        };
        let kind = match tangent {
            Some(true) => LKind::Tangent,
            Some(false) => LKind::Cross,
            None => kind_by_tangents(a.tangent_at_point(p[i]), b.tangent_at_point(p[i])),
        };
        out.put(s, u, p[i], kind);
    }
}

/// The points where the two circles meet. Two arcs of one circle are put as overlaps (or
/// touch points) straight away, and give no candidates.
#[inline(always)]
fn arc_arc_candidates<S: Sink>(
    a: &Arc,
    b: &Arc,
    tol: f64,
    out: &mut S,
) -> Option<Candidates<DVec3>> {
    let (n1, n2) = (a.normal, b.normal);
    let (c1, c2) = (a.center, b.center);
    let (r1, r2) = (a.radius, b.radius);
    let v = c2 - c1;
    // Equal normals (circles drawn in one plane, the common case) give a zero cross product
    // exactly: skip computing it.
    let (cross, sin) = if n1 == n2 {
        (DVec3::ZERO, 0.0)
    } else {
        let cross = n1.cross(n2);
        (cross, cross.length())
    };
    let off_plane = v.dot(n1).abs().max(v.dot(n2).abs()) + r1.max(r2) * sin;
    if off_plane <= tol {
        let vp = v - n1 * v.dot(n1);
        let d = vp.length();
        if d <= tol {
            if (r1 - r2).abs() <= tol {
                cocircular(a, b, tol, out);
            }
            return None;
        }
        if d > r1 + r2 + tol || d < (r1 - r2).abs() - tol {
            return None;
        }
        let h2 = (r1 + r2 - d).max(0.0)
            * (d - r1 + r2).max(0.0)
            * (d + r1 - r2).max(0.0)
            * (r1 + r2 + d)
            / (4.0 * d * d);
        let h = h2.sqrt();
        let ex = vp / d;
        let ey = n1.cross(ex);
        let x = (d * d + (r1 - r2) * (r1 + r2)) / (2.0 * d);
        let base = c1 + ex * x;
        if 2.0 * h <= tol {
            return Some(([base; 2], 1, Some(true)));
        }
        // The tangents are perpendicular to the radii, so the sine of their angle is that of
        // the radii: twice the area of the triangle c1 c2 p over r1 r2.
        let tangent = d * h <= TANGENT_SIN * r1 * r2;
        return Some(([base - ey * h, base + ey * h], 2, Some(tangent)));
    }
    if sin <= 1e-15 {
        return None; // parallel planes apart
    }
    // The line plane1 ∩ plane2 through x0 (the foot of c1 on it), direction n1 × n2.
    let k = n1.dot(n2);
    let d2 = n2.dot(v);
    let x0 = c1 + (n2 - n1 * k) * (d2 / (sin * sin));
    let dir = cross / sin;
    let hvec = x0 - c1;
    let h = hvec.length();
    if h > r1 + tol {
        return None;
    }
    let half = ((r1 - h) * (r1 + h)).max(0.0).sqrt();
    let on_b = |p: DVec3| {
        let w = p - c2;
        let z = w.dot(n2);
        let rho = (w - n2 * z).length();
        (z * z + (rho - r2) * (rho - r2)) <= tol * tol
    };
    let on_a_circle = |p: DVec3| {
        // Project to circle 1 exactly (keeps the point on the first curve).
        let w = p - c1;
        let wp = w - n1 * w.dot(n1);
        let l = wp.length();
        if l > 0.0 {
            c1 + wp * (r1 / l)
        } else {
            p
        }
    };
    if 2.0 * half <= tol {
        let p = on_a_circle(x0);
        return on_b(p).then_some(([p; 2], 1, None));
    }
    let p = [-1.0, 1.0].map(|sgn| on_a_circle(x0 + dir * (sgn * half)));
    match (on_b(p[0]), on_b(p[1])) {
        (true, true) => Some((p, 2, None)),
        (true, false) => Some((p, 1, None)),
        (false, true) => Some(([p[1], p[0]], 1, None)),
        (false, false) => None,
    }
}

/// Two arcs on the same circle: the shared angular ranges as overlap arcs, or touch points.
fn cocircular<S: Sink>(a: &Arc, b: &Arc, tol: f64, out: &mut S) {
    let slack = tol / a.radius;
    let same_dir = a.normal.dot(b.normal) > 0.0;
    let b_piece = |lo: f64, hi: f64| -> (f64, f64) {
        // b's parameters at a's relative angles lo and hi (a-frame, relative to a.start).
        let pl = a.point_at_angle(a.start + lo);
        let ph = a.point_at_angle(a.start + hi);
        let ul = b.param_of_angle(b.angle_of(pl), slack).unwrap_or(0.0);
        let uh = b.param_of_angle(b.angle_of(ph), slack).unwrap_or(1.0);
        (ul, uh)
    };
    let emit = |lo: f64, hi: f64, out: &mut S| {
        let (ul, uh) = b_piece(lo, hi);
        if (hi - lo) * a.radius > tol {
            let piece = if hi - lo >= TAU - 1e-15 {
                Arc {
                    start: 0.0,
                    sweep: TAU,
                    ..*a
                }
            } else {
                Arc {
                    start: norm_angle(a.start + lo),
                    sweep: hi - lo,
                    ..*a
                }
            };
            let s0 = lo / a.sweep;
            out.put(
                s0,
                ul,
                a.point_at_angle(a.start + lo),
                LKind::Overlap(Box::new(Piece::Arc(piece)), (hi / a.sweep).min(1.0), uh),
            );
        } else {
            let m = 0.5 * (lo + hi);
            let p = a.point_at_angle(a.start + m);
            out.put((m / a.sweep).clamp(0.0, 1.0), ul, p, LKind::Tangent);
        }
    };
    if a.is_full() && b.is_full() {
        emit(0.0, TAU, out);
        return;
    }
    // b's range in a's frame, relative to a.start, CCW about a's normal.
    let b_first = if same_dir { b.eval(0.0) } else { b.eval(1.0) };
    let alpha = norm_angle(a.angle_of(b_first) - a.start);
    let (sw1, sw2) = (a.sweep, b.sweep);
    if b.is_full() {
        emit(0.0, sw1, out);
        return;
    }
    let mut ranges: smallvec::SmallVec<[(f64, f64); 3]> = smallvec::SmallVec::new();
    for shift in [-TAU, 0.0, TAU] {
        let (lo, hi) = ((alpha + shift).max(0.0), (alpha + shift + sw2).min(sw1));
        if hi >= lo - slack {
            ranges.push((lo.min(hi), hi.max(lo)));
        }
    }
    ranges.sort_by(|x, y| x.0.total_cmp(&y.0));
    // Merge touching ranges (a full circle a covering b across its seam).
    let mut merged: smallvec::SmallVec<[(f64, f64); 3]> = smallvec::SmallVec::new();
    for r in ranges {
        if let Some(last) = merged.last_mut() {
            if r.0 <= last.1 + slack {
                last.1 = last.1.max(r.1);
                continue;
            }
        }
        merged.push(r);
    }
    if a.is_full() && merged.len() == 2 && merged[0].0 <= slack && merged[1].1 >= sw1 - slack {
        // b crosses a's seam: report it as one piece starting at b's start.
        let (lo, hi) = (merged[1].0, merged[0].1 + TAU);
        let (ul, uh) = b_piece(lo, hi);
        let piece = Arc {
            start: norm_angle(a.start + lo),
            sweep: hi - lo,
            ..*a
        };
        out.put(
            lo / sw1,
            ul,
            a.point_at_angle(a.start + lo),
            LKind::Overlap(Box::new(Piece::Arc(piece)), (hi - TAU) / sw1, uh),
        );
        return;
    }
    for (lo, hi) in merged {
        emit(lo, hi, out);
    }
}
