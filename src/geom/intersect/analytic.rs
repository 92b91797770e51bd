//! Closed forms for lines, circles and arcs in 3D (ZMOLD paper, SEEDS.md 000, made stable).
//!
//! No quadratic is solved by the textbook formula: a line meets a circle at the foot F of the
//! perpendicular from the centre ± the half chord √((r − h)(r + h)), and two circles meet at
//! a ± h with h² from the factored (Heron) form ((r1+r2)² − d²)(d² − (r1−r2)²)/(4d²), free
//! of cancellation at tangency. Non-coplanar circles: the first circle is cut with the
//! second circle's plane (the line plane1 ∩ plane2), each candidate then tested against the
//! second circle.
//!
//! The work is done in the circles' own 2D frames (the world's for the common +Z normal),
//! and the parameters of both hits of a pair come out of one two-lane atan2 per curve
//! (`fastmath`, `Arc::params_of_atan2`). Points that cannot be on an arc are dropped before
//! any atan2 (`Arc::maybe_on`), and hits are put straight into the caller's list in its
//! order. This is the hot path of `intersect` (issue 3: ≥ 20M pairs/s).

use std::f64::consts::TAU;

use glam::DVec3;

use super::{LKind, Sink, TANGENT_SIN};
use crate::geom::arc::{norm_angle, Arc, Frame};
use crate::geom::fastmath::{atan2_lanes, atan2_lanes_regular};
use crate::geom::lanes::F2;
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
    let (la, lb) = (a.dir().length(), b.dir().length());
    if la.max(lb) < HUGE {
        line_line_fitting(a, b, (la, lb), tol, out);
    } else {
        let size = size_of(a.p0)
            .max(size_of(a.p1))
            .max(size_of(b.p0))
            .max(size_of(b.p1));
        rescaled(size, tol, out, |s, tol, out| {
            let (a, b) = (a.scaled(s), b.scaled(s));
            let lengths = (a.dir().length(), b.dir().length());
            line_line_fitting(&a, &b, lengths, tol, out)
        });
    }
}

/// `line_line` for segments (of lengths `la`, `lb`) shorter than `HUGE`.
#[inline(always)]
fn line_line_fitting<S: Sink>(a: &Line, b: &Line, (la, lb): (f64, f64), tol: f64, out: &mut S) {
    let (da, db) = (a.dir(), b.dir());
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

/// Radii and segment lengths up to which the closed forms run as they are: they multiply
/// two squared lengths (4d²h², the cross products of two segments), which must stay
/// finite. Larger pairs are solved scaled down by a power of two (`rescaled`). (Far-apart
/// pieces need no scaling: their overflows give NaN or infinity, and every test is written
/// so that these mean "no hit", which is the answer when a piece is that far.)
const HUGE: f64 = 1e75;

/// A pair solved scaled by 1/k: points and shared pieces are scaled back by k on the way
/// out (exactly: k is a power of two); parameters do not depend on scale.
struct Unscale<'a, S: Sink> {
    out: &'a mut S,
    k: f64,
}

impl<S: Sink> Sink for Unscale<'_, S> {
    fn put(&mut self, s: f64, u: f64, p: DVec3, kind: LKind) {
        let kind = match kind {
            LKind::Overlap(piece, se, ue) => {
                let piece = match *piece {
                    Piece::Line(l) => Piece::Line(l.scaled(self.k)),
                    Piece::Arc(a) => Piece::Arc(a.scaled(self.k)),
                    // The closed forms share only lines and arcs.
                    bez @ Piece::Bez(_) => bez,
                };
                LKind::Overlap(Box::new(piece), se, ue)
            }
            kind => kind,
        };
        self.out.put(s, u, p * self.k, kind);
    }

    fn by_u(&self) -> bool {
        self.out.by_u()
    }
}

/// Solve a pair too large for the closed forms at unit size: `solve` gets the factor 1/k,
/// with k the power of two at `size` (the pair's largest magnitude), the tolerance scaled
/// likewise, and a sink that scales the answers back.
#[cold]
#[inline(never)]
fn rescaled<S: Sink>(
    size: f64,
    tol: f64,
    out: &mut S,
    solve: impl FnOnce(f64, f64, &mut Unscale<S>),
) {
    // 2^⌊log2 size⌋ from the exponent bits (size is finite and past HUGE, so normal).
    let k = f64::from_bits(size.to_bits() & 0x7ff0_0000_0000_0000);
    if k.is_finite() && k > 0.0 {
        let s = 1.0 / k;
        solve(s, tol * s, &mut Unscale { out, k });
    }
}

/// x ≤ lim, false for a NaN: the rejection tests use it so that a NaN from an overflow
/// (pieces too far apart for their distance to be a double) means "no hit".
#[inline(always)]
fn at_most(x: f64, lim: f64) -> bool {
    x <= lim
}

/// The largest coordinate magnitude of a point, for `rescaled`.
fn size_of(p: DVec3) -> f64 {
    p.abs().max_element()
}

/// Parameters of two candidate points on one curve, and a mask with bit i set when point i
/// lies on it (as `Arc::params_of_atan2` gives them).
type Params = (F2, u32);

/// The angles (raw `atan2`) of two points given in a circle's 2D frame, relative to its
/// centre.
#[inline(always)]
fn angles(q: [(f64, f64); 2]) -> F2 {
    atan2_lanes(F2::new(q[0].1, q[1].1), F2::new(q[0].0, q[1].0))
}

/// Put the candidates `p` that lie on both curves (among the first `count`), in the order
/// the sink wants (the caller's t1).
#[inline(always)]
fn put_hits<S: Sink>(
    out: &mut S,
    (s, on_s): Params,
    (u, on_u): Params,
    count: usize,
    p: [DVec3; 2],
    kind: impl Fn(usize) -> LKind,
) {
    let on = on_s & on_u & if count == 2 { 0b11 } else { 0b01 };
    let (s, u) = (s.get(), u.get());
    let key = if out.by_u() { u } else { s };
    let order = if on == 0b11 && key[1] < key[0] {
        [1, 0]
    } else {
        [0, 1]
    };
    for i in order {
        if on >> i & 1 == 1 {
            out.put(s[i], u[i], p[i], kind(i));
        }
    }
}

/// Segment / arc (or full circle).
pub fn line_arc<S: Sink>(l: &Line, a: &Arc, tol: f64, out: &mut S) {
    if a.radius < HUGE && l.dir().length_squared() < HUGE * HUGE {
        line_arc_fitting(l, a, tol, out);
    } else {
        let size = size_of(l.p0)
            .max(size_of(l.p1))
            .max(size_of(a.center))
            .max(a.radius);
        rescaled(size, tol, out, |s, tol, out| {
            line_arc_fitting(&l.scaled(s), &a.scaled(s), tol, out)
        });
    }
}

/// `line_arc` for a radius and a segment below `HUGE`.
#[inline(always)]
fn line_arc_fitting<S: Sink>(l: &Line, a: &Arc, tol: f64, out: &mut S) {
    let d = l.dir();
    let c = a.center;
    // Start and direction in the arc's frame.
    let frame = a.frame_view();
    let (u0, v0, h0) = frame.coords(l.p0 - c);
    let (du, dv, dn) = frame.coords(d);
    if h0.abs() <= tol && (h0 + dn).abs() <= tol {
        line_arc_flat(l, a, frame, (u0, v0), (du, dv), tol, out);
        return;
    }
    if dn == 0.0 {
        return;
    }
    // Pierces the plane once: on the circle there or nowhere.
    let s = -h0 / dn;
    let p = l.p0 + d * s;
    if !at_most(((p - c).length() - a.radius).abs(), tol) {
        return;
    }
    let Some(s) = seg_param(s, || d.length(), tol) else {
        return;
    };
    if let Some(u) = a.param_of_point(p, tol) {
        out.put(s, u, p, kind_by_tangents(d, a.tangent_at_point(p)));
    }
}

/// A segment in the arc's plane (within tol at both ends), worked in the arc's 2D frame
/// (start and direction given there): the foot F of the perpendicular from the centre ± the half chord √(r² − |F|²).
#[inline(always)]
fn line_arc_flat<S: Sink>(
    l: &Line,
    a: &Arc,
    frame: Frame,
    (u0, v0): (f64, f64),
    (du, dv): (f64, f64),
    tol: f64,
    out: &mut S,
) {
    let d = l.dir();
    let r = a.radius;
    let dq2 = du * du + dv * dv;
    // Reciprocals first, off the dependency chain that leads to the angles.
    let (inv2, inv) = (1.0 / dq2, 1.0 / dq2.sqrt());
    let sf = -(u0 * du + v0 * dv) * inv2;
    let (fu, fv) = (u0 + du * sf, v0 + dv * sf);
    let hh = fu * fu + fv * fv;
    if !at_most(hh, (r + tol) * (r + tol)) {
        return;
    }
    let at = |s: f64| (u0 + du * s, v0 + dv * s);
    // half² = (r − h)(r + h).
    let half2 = (r * r - hh).max(0.0);
    if 4.0 * half2 <= tol * tol {
        // Touches: the foot, put on the circle.
        let h = hh.sqrt();
        let q = if h > 0.0 {
            (fu * (r / h), fv * (r / h))
        } else {
            (fu, fv)
        };
        let Some(s) = seg_param(sf, || d.length(), tol) else {
            return;
        };
        let (u, on) = a.params_of_atan2(angles([q; 2]), tol);
        if on & 1 == 1 {
            out.put(s, u.get()[0], frame.point(q), LKind::Tangent);
        }
        return;
    }
    let ds = half2.sqrt() * inv;
    let (s1, s2) = (sf - ds, sf + ds);
    let q = [at(s1), at(s2)];
    let (s1, s2) = (
        seg_param(s1, || d.length(), tol),
        seg_param(s2, || d.length(), tol),
    );
    let s = (
        F2::new(s1.unwrap_or(0.0), s2.unwrap_or(0.0)),
        s1.is_some() as u32 | (s2.is_some() as u32) << 1,
    );
    // No atan2 when neither point is on the segment and (maybe) on the arc.
    if s.1 & a.maybe_on(q, 1.0, tol) == 0 {
        return;
    }
    let u = a.params_of_atan2(angles(q), tol);
    // The circle's tangent is perpendicular to the radius, so the sine of its angle with
    // the line is the cosine of the radius's: half / r at both points.
    let kind = || {
        if half2 <= (TANGENT_SIN * r) * (TANGENT_SIN * r) {
            LKind::Tangent
        } else {
            LKind::Cross
        }
    };
    put_hits(out, s, u, 2, frame.points(q), |_| kind());
}

/// Arc / arc (either may be a full circle), coplanar or not.
pub fn arc_arc<S: Sink>(a: &Arc, b: &Arc, tol: f64, out: &mut S) {
    if a.radius.max(b.radius) < HUGE {
        arc_arc_fitting(a, b, tol, out);
    } else {
        let size = size_of(a.center)
            .max(size_of(b.center))
            .max(a.radius)
            .max(b.radius);
        rescaled(size, tol, out, |s, tol, out| {
            arc_arc_fitting(&a.scaled(s), &b.scaled(s), tol, out)
        });
    }
}

/// `arc_arc` for radii below `HUGE`.
#[inline(always)]
fn arc_arc_fitting<S: Sink>(a: &Arc, b: &Arc, tol: f64, out: &mut S) {
    let bits = |n: DVec3| n.to_array().map(f64::to_bits);
    if bits(a.normal) == bits(b.normal) {
        // One normal (bit for bit), so one OCS frame: circles drawn in one plane.
        arc_arc_flat(a, b, tol, out);
        return;
    }
    let v = b.center - a.center;
    // b's normal in a's frame: its in-plane part m has length sin(angle of the normals).
    let m = (b.normal.dot(a.x_axis), b.normal.dot(a.y_axis));
    let m2 = m.0 * m.0 + m.1 * m.1;
    let e = b.normal.dot(v);
    let off = v.dot(a.normal).abs().max(e.abs());
    let rmax = a.radius.max(b.radius);
    if off <= tol && rmax * rmax * m2 <= (tol - off) * (tol - off) {
        // Coplanar within tol: opposite normals, or nearly equal ones.
        arc_arc_coplanar(a, b, v, tol, out);
    } else if m2 > 1e-30 {
        arc_arc_3d(a, b, v, m, e, tol, out);
    }
    // else: parallel planes apart.
}

/// Two arcs with the same normal, in their shared 2D frame. With d = |c1c2|, the chord's
/// foot is at x = (d² + r1² − r2²) / 2d from c1, and the half chord h comes from Heron's
/// factored form 4d²h² = ((r1+r2)² − d²)(d² − (r1−r2)²), free of cancellation at tangency.
/// Both are taken as fractions of d (x/d, h/d), so no root of d² is needed.
#[inline(always)]
fn arc_arc_flat<S: Sink>(a: &Arc, b: &Arc, tol: f64, out: &mut S) {
    let frame = a.frame_view();
    let (vx, vy, vz) = frame.coords(b.center - a.center);
    if !at_most(vz.abs(), tol) {
        return; // parallel planes apart
    }
    let dd = vx * vx + vy * vy;
    let (r1, r2) = (a.radius, b.radius);
    if dd <= tol * tol {
        if (r1 - r2).abs() <= tol {
            cocircular(a, b, tol, out);
        }
        return;
    }
    let (sum, dif) = (r1 + r2, r1 - r2);
    let gap = dif.abs() - tol;
    if !at_most(dd, (sum + tol) * (sum + tol)) || (gap > 0.0 && dd < gap * gap) {
        return;
    }
    let n = (sum * sum - dd).max(0.0) * (dd - dif * dif).max(0.0);
    // x, x − d (formed directly: no cancellation) and h, all times 2d.
    let (x2, xd2) = (dd + dif * sum, dif * sum - dd);
    // A zero half chord (2h <= tol) is one touch point.
    let (h2, count, tangent) = if n <= tol * tol * dd {
        (0.0, 1, true)
    } else {
        // The tangents are perpendicular to the radii, so the sine of their angle is that
        // of the radii: twice the area of the triangle c1 c2 p over r1 r2, i.e. d·h / r1r2.
        let t = TANGENT_SIN * r1 * r2;
        (n.sqrt(), 2, 0.25 * n <= t * t)
    };
    // x/d, (x − d)/d and h/d.
    let inv = 0.5 / dd;
    let (k1, m1, k2) = (x2 * inv, xd2 * inv, h2 * inv);
    // The two points (the first at base − (n × ex)·h, as the 3D forms order them), from c1
    // and from c2.
    let pa = [
        (vx * k1 + vy * k2, vy * k1 - vx * k2),
        (vx * k1 - vy * k2, vy * k1 + vx * k2),
    ];
    if !(a.is_full() && b.is_full()) {
        // Arcs: no atan2 when neither point may be on both.
        let pb = [
            (vx * m1 + vy * k2, vy * m1 - vx * k2),
            (vx * m1 - vy * k2, vy * m1 + vx * k2),
        ];
        let first = if count == 2 { 0b11 } else { 0b01 };
        if first & a.maybe_on(pa, 1.0, tol) & b.maybe_on(pb, 1.0, tol) == 0 {
            return;
        }
    }
    // Their angles about c1 are θ ∓ φa, about c2 θ ∓ φb: θ the direction of c1c2, φa the
    // triangle's angle at c1 (atan2(h, x)), φb the outer angle at c2 (atan2(h, x − d)). So
    // three atan2 instead of four, and θ's is ready before the root of the half chord.
    // (vx, vy: below 2·HUGE, and not both zero as d > tol.)
    let theta = atan2_lanes_regular(F2::splat(vy), F2::splat(vx));
    let phi = atan2_lanes(F2::splat(h2), F2::new(x2, xd2)).get();
    let s = a.params_of_atan2(theta + F2::new(-phi[0], phi[0]), tol);
    let u = b.params_of_atan2(theta + F2::new(-phi[1], phi[1]), tol);
    let kind = |_| {
        if tangent {
            LKind::Tangent
        } else {
            LKind::Cross
        }
    };
    let p = frame.points(pa);
    put_hits(out, s, u, count, p, kind);
}

/// Two arcs in one plane with different normals (opposite, or equal within tol): as
/// `arc_arc_flat`, in 3D.
#[cold]
fn arc_arc_coplanar<S: Sink>(a: &Arc, b: &Arc, v: DVec3, tol: f64, out: &mut S) {
    let (n1, c1, r1, r2) = (a.normal, a.center, a.radius, b.radius);
    let vp = v - n1 * v.dot(n1);
    let d = vp.length();
    if d <= tol {
        if (r1 - r2).abs() <= tol {
            cocircular(a, b, tol, out);
        }
        return;
    }
    if !at_most(d, r1 + r2 + tol) || d < (r1 - r2).abs() - tol {
        return;
    }
    let h2 =
        (r1 + r2 - d).max(0.0) * (d - r1 + r2).max(0.0) * (d + r1 - r2).max(0.0) * (r1 + r2 + d)
            / (4.0 * d * d);
    let h = h2.sqrt();
    let ex = vp / d;
    let ey = n1.cross(ex);
    let base = c1 + ex * ((d * d + (r1 - r2) * (r1 + r2)) / (2.0 * d));
    let (p, count, kind) = if 2.0 * h <= tol {
        ([base; 2], 1, LKind::Tangent)
    } else if d * h <= TANGENT_SIN * r1 * r2 {
        ([base - ey * h, base + ey * h], 2, LKind::Tangent)
    } else {
        ([base - ey * h, base + ey * h], 2, LKind::Cross)
    };
    let (s, u) = (a.params_of2(p, tol), b.params_of2(p, tol));
    put_hits(out, s, u, count, p, |_| kind.clone());
}

/// Two arcs in different planes: the line L = plane1 ∩ plane2 cuts circle a, and each point
/// is tested against circle b. In a's 2D frame L is m·q = e (m the in-plane part of n2,
/// |m| = sin of the planes' angle, e = n2·(c2 − c1)), so the points are
/// (m e ± m⊥ w) / |m|² with w = √(r1²|m|² − e²); in b's frame L is m'·q = e' likewise
/// (m' the in-plane part of n1, e' = n1·(c1 − c2)). Along L, with lengths times |m|, a's
/// points lie at o = g ± w from the foot of c2 (g = (c2 − c1)·(n1 × n2)), so in b's plane
/// their distance ρ from c2 has |m|²(ρ² − r2²) = o² − (r2²|m|² − e'²): the test against b
/// and b's coordinates need neither a root nor 3D points.
#[inline(always)]
fn arc_arc_3d<S: Sink>(a: &Arc, b: &Arc, v: DVec3, m: (f64, f64), e: f64, tol: f64, out: &mut S) {
    let (r1, r2) = (a.radius, b.radius);
    let m2 = m.0 * m.0 + m.1 * m.1;
    // L's distance from c1 is |e| / |m|.
    if !at_most(e * e, (r1 + tol) * (r1 + tol) * m2) {
        return;
    }
    // |m|² times a's half chord squared.
    let w2 = (r1 * r1 * m2 - e * e).max(0.0);
    // Ready while the root is computed: b's side of the construction.
    let mb = (a.normal.dot(b.x_axis), a.normal.dot(b.y_axis));
    let eb = -a.normal.dot(v);
    let g = v.dot(a.normal.cross(b.normal));
    let wb2 = r2 * r2 * m2 - eb * eb;
    // ρ within tol of r2: |m|²(ρ² − r2²) between these.
    let lo = if r2 > tol {
        tol * (tol - 2.0 * r2)
    } else {
        -r2 * r2
    } * m2;
    let hi = tol * (tol + 2.0 * r2) * m2;
    // The points in a's frame (times `scale`) and their offsets along L.
    let (q, o, count, scale) = if 4.0 * w2 <= tol * tol * m2 {
        // Touches circle a: the foot, put on the circle.
        let inv = 1.0 / m2;
        let f = (m.0 * e * inv, m.1 * e * inv);
        let l = f.0.hypot(f.1);
        let q = if l > 0.0 {
            (f.0 * (r1 / l), f.1 * (r1 / l))
        } else {
            f
        };
        ([q; 2], [g; 2], 1, 1.0)
    } else {
        // Times |m|²: no division before the angles (atan2 does not mind the scale).
        let w = w2.sqrt();
        (
            [
                (m.0 * e + m.1 * w, m.1 * e - m.0 * w),
                (m.0 * e - m.1 * w, m.1 * e + m.0 * w),
            ],
            [g + w, g - w],
            2,
            m2,
        )
    };
    // In b's frame, times |m|² whatever `scale` is: m'e' + o·m'⊥ (L runs along −m'⊥ there).
    let at_b = |o: f64| (mb.0 * eb - mb.1 * o, mb.1 * eb + mb.0 * o);
    let on_b = |o: f64| (lo..=hi).contains(&(o * o - wb2));
    let on_b = on_b(o[0]) as u32 | (on_b(o[1]) as u32) << 1;
    // No atan2 when no point is on circle b and (maybe) on both arcs.
    let qb = [at_b(o[0]), at_b(o[1])];
    if on_b & a.maybe_on(q, scale, tol) & b.maybe_on(qb, m2, tol) == 0 {
        return;
    }
    let s = a.params_of_atan2(angles(q), tol);
    let s = (s.0, s.1 & on_b);
    let u = b.params_of_atan2(angles(qb), tol);
    let inv = 1.0 / scale;
    // Two points w/|m| apart from the foot: the sine of the tangents' angle is at least
    // (half chord / r1)·|m| = w / r1, so above TANGENT_SIN they cross.
    let surely_cross = count == 2 && w2 > (TANGENT_SIN * r1) * (TANGENT_SIN * r1);
    let p = a
        .frame_view()
        .points(q.map(|(qx, qy)| (qx * inv, qy * inv)));
    put_hits(out, s, u, count, p, |i| {
        if surely_cross {
            LKind::Cross
        } else {
            kind_by_tangents(a.tangent_at_point(p[i]), b.tangent_at_point(p[i]))
        }
    });
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
                a.with_range(0.0, TAU)
            } else {
                a.with_range(norm_angle(a.start + lo), hi - lo)
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
        let piece = a.with_range(norm_angle(a.start + lo), hi - lo);
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
