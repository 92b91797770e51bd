//! A Bézier piece against a line or an arc: substitute the piece into the other curve's
//! implicit equations (planes through the line; the circle's plane and sphere), giving
//! polynomials in Bernstein form whose roots `bernstein::roots` isolates without loss.
//! Each root is then checked in 3D against the other curve within `tol`.

use glam::DVec3;
use smallvec::SmallVec;

use super::{LHit, LHits, LKind, TANGENT_SIN};
use crate::geom::arc::Arc;
use crate::geom::bernstein::{self, Root};
use crate::geom::bezier::Bez;
use crate::geom::line::Line;
use crate::geom::traits::ParamCurve;

fn max_abs(c: &[f64]) -> f64 {
    c.iter().fold(0.0, |m, x| m.max(x.abs()))
}

fn classify(root: &Root, tb: DVec3, to: DVec3) -> LKind {
    if root.tangent || tb.cross(to).length() <= TANGENT_SIN * tb.length() * to.length() {
        LKind::Tangent
    } else {
        LKind::Cross
    }
}

/// Roots of `f1` (or of `f2` when the piece lies in f1's zero set within `tol`).
fn roots_of_pair(
    f1: &[f64],
    f2: &[f64],
    tol1: f64,
    tol2: f64,
    in_plane: bool,
) -> SmallVec<[Root; 8]> {
    let mut roots = SmallVec::new();
    if in_plane {
        bernstein::roots(f2, tol2, &mut roots);
    } else {
        bernstein::roots(f1, tol1, &mut roots);
    }
    roots
}

/// Bézier piece (s) against a segment (u).
pub fn bez_line(b: &Bez, l: &Line, tol: f64, out: &mut LHits) {
    let d = l.dir();
    let len = d.length();
    let dir = d / len;
    // n2: the direction (normal to the line) in which the piece spreads most; n1 = dir × n2.
    // A piece lying in a plane through the line has f1 ≡ 0 there.
    let mut best = DVec3::ZERO;
    for p in b.points() {
        let q = p - l.p0;
        let q = q - dir * q.dot(dir);
        if q.length_squared() > best.length_squared() {
            best = q;
        }
    }
    let (wlo, whi) = b.weight_range();
    if best.length() <= tol {
        // The whole piece lies on the line's carrier: a straight piece.
        straight_on_line(b, l, tol, out);
        return;
    }
    let n2 = best.normalize();
    let n1 = dir.cross(n2);
    let f1 = b.plane_fn(l.p0, n1);
    let f2 = b.plane_fn(l.p0, n2);
    let in_plane = max_abs(&f1) <= tol * wlo;
    let roots = roots_of_pair(&f1, &f2, tol * whi, tol * whi, in_plane);
    for r in &roots {
        let p = b.eval(r.t);
        let u = l.project(p);
        let slack = tol / len;
        if !(-slack..=1.0 + slack).contains(&u) {
            continue;
        }
        let u = u.clamp(0.0, 1.0);
        let q = l.eval(u);
        if (p - q).length_squared() > tol * tol {
            continue;
        }
        let mut h = LHit::new(r.t, u, p, classify(r, b.deriv(r.t), d));
        h.twin = twin_key(r);
        out.push(h);
    }
}

/// The two simple roots flanking one extremum share its parameter: key them by it.
fn twin_key(r: &Root) -> Option<u32> {
    r.extremum.map(|e| {
        let bits = e.to_bits();
        ((bits ^ (bits >> 20) ^ (bits >> 40)) & 0xF_FFFF) as u32
    })
}

/// A piece whose control points all lie on the line: intersect its chord as a segment and
/// map parameters back by projection.
fn straight_on_line(b: &Bez, l: &Line, tol: f64, out: &mut LHits) {
    let chord = Line {
        p0: b.eval(0.0),
        p1: b.eval(1.0),
    };
    if (chord.p1 - chord.p0).length() <= tol {
        return;
    }
    let start = out.len();
    super::analytic::line_line(&chord, l, tol, out);
    // chord parameter → Bézier parameter (monotone straight piece assumed)
    remap_to_bez(b, out, start, |t| chord.eval(t));
}

/// Map the first-piece parameters of the hits from `start` on (made against a stand-in for
/// `b`: its chord or its arc) back to `b`, through the stand-in's point at each.
fn remap_to_bez(b: &Bez, out: &mut LHits, start: usize, stand_in: impl Fn(f64) -> DVec3) {
    for h in &mut out[start..] {
        h.s = param_on_bez(b, stand_in(h.s));
        if let LKind::Overlap(_, se, _) = &mut h.kind {
            *se = param_on_bez(b, stand_in(*se));
        }
    }
}

fn param_on_bez(b: &Bez, p: DVec3) -> f64 {
    crate::geom::piece::Piece::Bez(b.clone()).nearest(p).0
}

/// Bézier piece (s) against an arc or circle (u).
pub fn bez_arc(b: &Bez, a: &Arc, tol: f64, out: &mut LHits) {
    let (wlo, whi) = b.weight_range();
    let g1 = b.plane_fn(a.center, a.normal);
    let in_plane = max_abs(&g1) <= tol * wlo;
    let roots = if in_plane {
        let g2 = b.sphere_fn(a.center, a.radius);
        if max_abs(&g2) <= tol * (2.0 * a.radius + tol) * wlo * wlo {
            on_circle(b, a, tol, out);
            return;
        }
        let mut r = SmallVec::new();
        bernstein::roots(&g2, tol * (2.0 * a.radius + tol) * whi * whi, &mut r);
        r
    } else {
        let mut r = SmallVec::new();
        bernstein::roots(&g1, tol * whi, &mut r);
        r
    };
    for r in &roots {
        let p = b.eval(r.t);
        let w = p - a.center;
        let z = w.dot(a.normal);
        let rho = (w - a.normal * z).length();
        if z * z + (rho - a.radius) * (rho - a.radius) > tol * tol {
            continue;
        }
        let ang = a.angle_of(p);
        let Some(u) = a.param_of_angle(ang, tol / a.radius) else {
            continue;
        };
        let mut h = LHit::new(
            r.t,
            u,
            p,
            classify(r, b.deriv(r.t), a.tangent_at_angle(ang)),
        );
        h.twin = twin_key(r);
        out.push(h);
    }
}

/// A piece lying on the circle: it is an arc of it; overlap with `a` via the arc/arc code.
fn on_circle(b: &Bez, a: &Arc, tol: f64, out: &mut LHits) {
    let (p0, pm, p1) = (b.eval(0.0), b.eval(0.5), b.eval(1.0));
    let Ok(arc) = Arc::through(p0, pm, p1) else {
        return;
    };
    let start = out.len();
    super::analytic::arc_arc(&arc, a, tol, out);
    remap_to_bez(b, out, start, |t| arc.eval(t));
}
