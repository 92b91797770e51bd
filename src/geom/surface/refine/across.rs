//! A crossing's point found across it where Newton crawls: near a branch point the surfaces
//! part so slowly across the curve (their Jacobian near singular, its damped steps capped) that
//! Newton stops within the tolerance of both far off the curve. Along a line across the curve
//! the gap between the surfaces still has a simple root there, well conditioned as a 1-D root
//! (its slope, however small, is far above the gap's rounding), and bracketed it is found to
//! that rounding. A tangent contact's gap has an even root, with no sign change to bracket.

use super::{Node, Patch};
use crate::geom::root::{illinois, At, Stop};
use glam::{DVec2, DVec3};
use std::cell::Cell;

/// The point of the crossing through `m` (a point of both `a` and `b` within `tol`, the
/// midpoint of the chord `p0p1`, where the surfaces' derivatives are about `cols`) on the
/// line through it in `a` along which the gap grows fastest (b's normal projected onto a's
/// tangent plane: across the curve, whatever the chord's direction): Newton's 1-D step on the
/// signed gap from `a` to `b` (its slope from the normals), and where the gap changes sign
/// there or just beyond, the root bracketed by the Illinois method (or the step's point, where
/// its gap is at the rounding). None where the step does not cut the gap eightfold (a
/// contact's even root: it cuts it fourfold, and the gap keeps its sign), where the line leaves
/// either surface, or where the root would be farther than four times the chord's length and
/// the point's distance from it (another curve's root).
pub(super) fn onto_crossing(
    a: &Patch,
    b: &Patch,
    m: &Node,
    ((p0, p1), cols): ((DVec3, DVec3), [DVec3; 4]),
    tol: f64,
) -> Option<Node> {
    let chord = p1 - p0;
    // How far the root may lie: four times the chord's length and the point's distance from it
    // (Newton's point may be crawled off it by more than the chord is long, deep in densify).
    let reach = 4.0 * (chord.length() + (m.point - p0).cross(chord).length() / chord.length());
    let [su, sv, bu, bv] = cols;
    let nb = bu.cross(bv).try_normalize()?;
    let na = su.cross(sv).try_normalize()?;
    // Across the curve, not the chord: beside a branch point a chord's end can itself be off
    // the curve, and a line square to that chord then ran almost along the crossing (which
    // leaves the contact nearly square to it there), where the gap hardly changes; the probe
    // below took it for a contact's, and the point stayed 1.7e-5 off. Along a good chord the
    // two directions agree (the curve's tangent is a's normal × b's).
    let across = (nb - na * na.dot(nb)).try_normalize()?;
    // The parameter direction whose image is `across` (unit speed in space).
    let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
    let det = e * g - f * f;
    if !(det > 0.0 && det.is_finite()) {
        return None;
    }
    let (c0, c1) = (su.dot(across), sv.dot(across));
    let dir = DVec2::new(g * c0 - f * c1, e * c1 - f * c0) / det;
    let warm = Cell::new(m.uv[1]);
    let at = |s: f64| node_at(a, b, (m.uv[0] + dir * s, &warm), tol);
    let noise = rounding(a, b);
    let g0 = (a.eval(m.uv[0]) - b.eval(m.uv[1])).dot(nb);
    let step = -g0 / across.dot(nb);
    // A gap within a few roundings says nothing of where the root is (beside a branch point
    // the surfaces are that close over a stretch as wide as the step). `noise` bounds it from
    // the surfaces' sizes; where the gap is under that bound its own rounding is read.
    let in_noise = g0.abs() <= 8.0 * noise && g0.abs() <= 8.0 * gap_noise(a, b, m, (cols, nb), g0);
    if in_noise || !(step.is_finite() && step.abs() <= reach) {
        return None;
    }
    // Most points here are a contact's (Newton crawls onto its double zero too): told first by
    // a probe with b's foot moved one Gauss–Newton step, its error third order in the step.
    let probe = probe_at(a, b, m, (dir * step, [bu, bv], nb))?;
    if probe.signum() == g0.signum() && 8.0 * probe.abs() > g0.abs() {
        return None;
    }
    let one = at(step)?;
    let (lo, hi) = if one.0.abs() <= noise {
        // At the gap's rounding: as near the root as it can be told.
        return (one.1.residual <= tol).then_some(one.1);
    } else if one.0.signum() != g0.signum() {
        ((0.0, at(0.0)?), (step, one))
    } else if 8.0 * one.0.abs() > g0.abs() {
        return None;
    } else {
        // Short of the root: past it by twice the secant's estimate of what is left.
        let beyond = step + 2.0 * step * one.0 / (g0 - one.0);
        let two = at(beyond)?;
        if two.0.signum() == one.0.signum() || beyond.abs() > reach {
            return None;
        }
        ((step, one), (beyond, two))
    };
    if lo.1 .0.signum() == hi.1 .0.signum() {
        return None;
    }
    let end = |(t, (f, payload)): (f64, (f64, Node))| At { t, f, payload };
    let root = illinois(&at, [end(lo), end(hi)], Stop::Width(1e-3 * tol))?;
    (root.payload.residual <= tol).then_some(root.payload)
}

/// The signed gap from `a` at `m`'s parameters moved by `du` to `b` along `nb` (b's unit normal
/// at `m`, its derivatives there `[bu, bv]`), b's foot moved from `m`'s by one Gauss–Newton
/// step: None where `a`'s point leaves its domain.
fn probe_at(
    a: &Patch,
    b: &Patch,
    m: &Node,
    (du, [bu, bv], nb): (DVec2, [DVec3; 2], DVec3),
) -> Option<f64> {
    let mut ua = m.uv[0] + du;
    if a.normalise(&mut ua) != [false; 2] {
        return None;
    }
    let pa = a.eval(ua);
    let d = pa - b.eval(m.uv[1]);
    let (e, f, g) = (bu.dot(bu), bu.dot(bv), bv.dot(bv));
    let det = e * g - f * f;
    let (d0, d1) = (bu.dot(d), bv.dot(d));
    let mut ub = m.uv[1] + DVec2::new(g * d0 - f * d1, e * d1 - f * d0) / det;
    b.normalise(&mut ub);
    let gap = (pa - b.eval(ub)).dot(nb);
    gap.is_finite().then_some(gap)
}

/// The rounding of a gap between points of `a` and `b`: a few ulps of their coordinates' size.
/// A residual within it is as near both as any computation gets, and a sign within it says
/// nothing.
pub(super) fn rounding(a: &Patch, b: &Patch) -> f64 {
    4.0 * f64::EPSILON * a.scale().max(b.scale())
}

/// The rounding of the gap `g0` from `a` to `b` along `nb` at `m` (the surfaces' derivatives
/// there `cols`), read from the gap itself: each parameter nudged by two ulps in turn, the gap's
/// change beyond what the derivative predicts is rounding, and its largest, doubled, bounds it.
/// [`rounding`] takes it from the surfaces' sizes, which beside a small point of a large surface
/// (a crossing at r = 2 on an 8×8 plate: 1e-14, where the gap's own is 4e-16) hides a gap
/// that still tells where its root is.
fn gap_noise(a: &Patch, b: &Patch, m: &Node, (cols, nb): ([DVec3; 4], DVec3), g0: f64) -> f64 {
    let [su, sv, bu, bv] = cols;
    let mut spread = 0.0_f64;
    for (k, col) in [su, sv, -bu, -bv].into_iter().enumerate() {
        let mut uv = m.uv;
        let x = &mut uv[k / 2][k % 2];
        let before = *x;
        *x = x.next_up().next_up();
        let h = *x - before;
        let off = ((a.eval(uv[0]) - b.eval(uv[1])).dot(nb) - g0 - h * col.dot(nb)).abs();
        // Not a number (a point past a domain's end): the sizes' bound stands.
        if !off.is_finite() {
            return f64::INFINITY;
        }
        spread = spread.max(off);
    }
    2.0 * spread.max(f64::EPSILON * g0.abs())
}

/// The signed gap from `a` at `ua` to `b` (its nearest point searched from `warm`, which it
/// updates) along b's normal there, and the node midway: None where `ua` leaves a's domain or
/// a's point lies past b's edge (the distance then exceeds the signed gap by more than `tol`).
fn node_at(
    a: &Patch,
    b: &Patch,
    (ua, warm): (DVec2, &Cell<DVec2>),
    tol: f64,
) -> Option<(f64, Node)> {
    let mut ua = ua;
    if a.normalise(&mut ua) != [false; 2] {
        return None;
    }
    let pa = a.eval(ua);
    let ub = b.project(pa, Some(warm.get()));
    warm.set(ub);
    let pb = b.eval(ub);
    let (bu, bv) = b.derivs(ub);
    let n = bu.cross(bv).try_normalize()?;
    let (signed, dist) = ((pa - pb).dot(n), pa.distance(pb));
    let node = Node {
        uv: [ua, ub],
        point: 0.5 * (pa + pb),
        residual: dist,
    };
    (dist - signed.abs() <= tol && signed.is_finite()).then_some((signed, node))
}
