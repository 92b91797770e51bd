//! Crossings running alongside a traced tangent contact. Where the surfaces touch along a curve
//! and also cross each other a short way off it (closer than the seeding meshes resolve), the
//! meshes see one change of side for the two, and their one seed curve refines onto either the
//! contact or the crossing, never both. Once the contact is traced, the signed gap is scanned
//! across it on both sides, outwards in geometric steps from near the contact to where the
//! surfaces are plainly apart: a change of sign between two samples that are beyond the
//! tolerance (so the crossing is told from the contact by more than the tolerance) is bisected
//! to a point of the crossing. Runs of such points along the contact are joined and densified
//! within the chord tolerance like every refined curve.

use super::super::refine::{assemble, mid, Patch};
use super::line::{delta, speed_along, GapAt, MAX_NODES};
use super::near_any;
use crate::geom::mesh::Polyline3;
use crate::geom::root::{illinois, At, Stop};
use glam::{DVec2, DVec3};

/// How far the scan looks across, and how densely along.
pub(crate) struct Scan {
    /// Spacing along the contact of the nodes scanned across (the seeding mesh's edge length:
    /// what the meshes hide lies within a cell of them).
    pub step: f64,
    /// The gap beyond which the scan stops: the meshes tell the surfaces apart there.
    pub apart: f64,
    /// A crossing point this close to a curve in `known` is that curve's.
    pub dup: f64,
}

/// The crossings alongside the traced `contact` (a curve of `a`, on which `gap` has a zero
/// extremum across) not already among `known`: every point within `tol` of both surfaces,
/// densified within `chord_tol`.
pub(crate) fn crossings_alongside(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    contact: &Polyline3,
    scan: &Scan,
    known: &[Polyline3],
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let pts = &contact.points;
    let n = pts.len();
    if n < 2 {
        return Vec::new();
    }
    let mut prev = None;
    let uvs: Vec<DVec2> = pts
        .iter()
        .map(|p| {
            let uv = a.project(*p, prev);
            prev = Some(uv);
            uv
        })
        .collect();
    let at = scanned(pts, contact.closed, scan.step);
    let mut out = Vec::new();
    for side in [1.0, -1.0] {
        let roots: Vec<Option<(DVec2, DVec3)>> = at
            .iter()
            .map(|&(i, t)| {
                let (b, f) = if t > 0.0 {
                    (i, i + 1)
                } else if contact.closed {
                    ((i + n - 1) % n, (i + 1) % n)
                } else {
                    (i.saturating_sub(1), (i + 1).min(n - 1))
                };
                let across = delta(a, uvs[b], uvs[f]).perp().normalize_or_zero();
                if across == DVec2::ZERO {
                    return None;
                }
                let from = if t > 0.0 {
                    a.project(pts[i].lerp(pts[i + 1], t), Some(uvs[i]))
                } else {
                    uvs[i]
                };
                let uv = first_crossing(a, gap, from, across * side, scan, tol)?;
                let p = gap(uv).point;
                (!near_any(p, known, scan.dup) && !near_any(p, &out, scan.dup)).then_some((uv, p))
            })
            .collect();
        let whole = contact.closed && roots.iter().all(Option::is_some);
        let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| between(a, gap, x, y, tol);
        for run in roots.split(Option::is_none) {
            let nodes: Vec<(DVec2, DVec3)> = run.iter().flatten().copied().collect();
            if nodes.len() >= 2 {
                out.push(assemble(&nodes, whole, |x| x.1, &mid_of, tol, chord_tol));
            }
        }
    }
    out
}

/// The point of the crossing between two of its points `x` and `y`: the root of the gap across
/// the chord from its midpoint in (u, v).
pub(super) fn between(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    x: &(DVec2, DVec3),
    y: &(DVec2, DVec3),
    tol: f64,
) -> Option<(DVec2, DVec3)> {
    let across = delta(a, x.0, y.0).perp().normalize_or_zero();
    let uv = root_along(a, gap, mid(a, x.0, y.0), across, tol)?;
    Some((uv, gap(uv).point))
}

/// The open crossing `pieces` joined where one ends within `reach` of where another begins
/// (either way round) and both run on across the joint: a crossing found in parts, by the scan
/// where it runs beside a contact and by the meshes where it leaves it. The joint is densified
/// on the true surfaces, and made only where its midpoint is on the crossing.
pub(crate) fn join_ends(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    mut pieces: Vec<Polyline3>,
    reach: f64,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let node = |p: DVec3| (a.project(p, None), p);
    // A joint's midpoint lies about its chord (within its length of the chord's middle): the
    // root across the chord can run far off (beside a branch point, along the contact's double
    // zero onto the crossing's far stretch: a 7-long seam across a joint 9e-4 long).
    let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| {
        between(a, gap, x, y, tol).filter(|m| m.1.distance(x.1.midpoint(y.1)) <= x.1.distance(y.1))
    };
    'joining: loop {
        for i in 0..pieces.len() {
            for j in 0..pieces.len() {
                let (pi, pj) = (&pieces[i].points, &pieces[j].points);
                if i == j || pieces[i].closed || pieces[j].closed || pi.len() < 2 || pj.len() < 2 {
                    continue;
                }
                // The end of i (its first point when reversed) to the start of j (its last).
                for (ri, rj) in [(false, false), (false, true), (true, false)] {
                    let (ni, nj) = (pi.len(), pj.len());
                    let (e, before) = if ri {
                        (pi[0], pi[1])
                    } else {
                        (pi[ni - 1], pi[ni - 2])
                    };
                    let (s, after) = if rj {
                        (pj[nj - 1], pj[nj - 2])
                    } else {
                        (pj[0], pj[1])
                    };
                    let joint = s - e;
                    let runs_on = joint.dot(e - before) > 0.0 && joint.dot(after - s) > 0.0;
                    if joint.length() > reach || !runs_on {
                        continue;
                    }
                    let (x, y) = (node(e), node(s));
                    if mid_of(&x, &y).is_none() {
                        continue;
                    }
                    let seam = assemble(&[x, y], false, |n| n.1, &mid_of, tol, chord_tol);
                    let (mut head, mut tail) = (pi.clone(), pj.clone());
                    if ri {
                        head.reverse();
                    }
                    if rj {
                        tail.reverse();
                    }
                    let inner = seam.points.len().saturating_sub(1);
                    head.extend_from_slice(&seam.points[1.min(inner)..inner]);
                    head.extend(tail);
                    let (lo, hi) = (i.min(j), i.max(j));
                    pieces.remove(hi);
                    pieces[lo] = Polyline3 {
                        points: head,
                        closed: false,
                    };
                    continue 'joining;
                }
            }
        }
        return pieces;
    }
}

/// Where the contact is scanned across: both ends (of an open curve) and points about `step`
/// apart between, as (i, t): the point a fraction t of the way from point i to the next. A
/// segment longer than the step (a straight contact keeps only its ends) is split evenly.
fn scanned(pts: &[DVec3], closed: bool, step: f64) -> Vec<(usize, f64)> {
    let n = pts.len();
    let mut at = vec![(0, 0.0)];
    let mut run = 0.0;
    for i in 1..n {
        let len = pts[i].distance(pts[i - 1]);
        let k = (len / step).ceil();
        if k > 1.0 && k.is_finite() {
            at.extend((1..k as usize).map(|j| (i - 1, j as f64 / k)));
        }
        run += len;
        // A segment a roundoff shorter than the step still counts as a step.
        if run >= step * (1.0 - 1e-12) || (i == n - 1 && !closed) {
            at.push((i, 0.0));
            run = 0.0;
        }
    }
    at
}

/// Smallest distance scanned from the contact, as a fraction of the step. The samples grow
/// fourfold from there while the gap is within the tolerance, so a crossing is found when the
/// stretch of gap beyond the tolerance between it and the contact spans a ratio of four in
/// distance (for a quadratic contact, when the gap there rises to about twice the tolerance):
/// one closer is within the tolerance of the contact all the way.
const FIRST: f64 = 1e-7;

/// How far past a bounded parameter's edge roundoff carries a point (parameters are in [0, 1]).
const EDGE_ROUNDOFF: f64 = 1e-12;

/// The first point from `uv0` along `dir` (in (u, v)) where the gap changes sign between two
/// samples beyond `tol`, bisected to within a hundredth of it.
fn first_crossing(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv0: DVec2,
    dir: DVec2,
    scan: &Scan,
    tol: f64,
) -> Option<DVec2> {
    let mut w = uv0;
    a.normalise(&mut w);
    // From a point on a bounded edge (the end of a contact that runs to it), along the edge
    // rather than out of the domain by the roundoff in `dir`. On it to within the roundoff, too:
    // the sheet's contact ending at v = 2e-29 was scanned with dir.v = -2e-11, which carried
    // the scan 1.2e-12 past the edge 0.05 along and stopped it short of the crossing.
    let mut dir = dir;
    for k in 0..2 {
        let out = (w[k] <= EDGE_ROUNDOFF && dir[k] < 0.0)
            || (w[k] >= 1.0 - EDGE_ROUNDOFF && dir[k] > 0.0);
        if !a.periodic()[k] && out {
            dir[k] = 0.0;
        }
    }
    let dir = dir.try_normalize()?;
    let uv0 = w;
    let (su, sv) = a.derivs(w);
    let speed = (su * dir.x + sv * dir.y).length();
    if !(speed > 0.0 && speed.is_finite()) {
        return None;
    }
    // Space distance s along the scan, to first order. From a point a roundoff short of a
    // bounded edge, the roundoff in `dir` along it would carry the scan out: held at the edge.
    let uv_at = |s: f64| {
        let mut uv = uv0 + dir * (s / speed);
        for k in 0..2 {
            if !a.periodic()[k] && (uv[k] - uv[k].clamp(0.0, 1.0)).abs() <= EDGE_ROUNDOFF {
                uv[k] = uv[k].clamp(0.0, 1.0);
            }
        }
        uv
    };
    let inside = |uv: DVec2| (0..2).all(|k| a.periodic()[k] || (0.0..=1.0).contains(&uv[k]));
    let mut last: Option<(f64, f64)> = None;
    let mut s = FIRST * scan.step;
    while s <= 4.0 * scan.step {
        let uv = uv_at(s);
        if !inside(uv) {
            return None;
        }
        let v = gap(uv).signed;
        if !v.is_finite() {
            return None;
        }
        if v.abs() > tol {
            if let Some((s0, sign)) = last.filter(|l| l.1 != v.signum()) {
                let (mut lo, mut hi) = (s0, s);
                let mut m = 0.5 * (lo + hi);
                for _ in 0..80 {
                    m = 0.5 * (lo + hi);
                    let g = gap(uv_at(m)).signed;
                    // Bracketed, so on to the root itself: near a branch point the gap across
                    // the crossing flattens, and a value within 0.01·tol leaves it far off.
                    if g == 0.0 || hi - lo <= FINE {
                        break;
                    }
                    if g.signum() == sign {
                        lo = m;
                    } else {
                        hi = m;
                    }
                }
                let mut uv = uv_at(m);
                a.normalise(&mut uv);
                return (gap(uv).dist <= tol).then_some(uv);
            }
            last = Some((s, v.signum()));
            if v.abs() > scan.apart {
                return None;
            }
        }
        // Fast through the tolerance band about the contact (its samples tell nothing), then
        // doubling: a sign change is seen between any two samples beyond the tolerance.
        s *= if last.is_none() { 4.0 } else { 2.0 };
    }
    None
}

/// The zero of the gap on the line `uv + t·w` nearest `uv` (Newton with a difference
/// derivative), when the surfaces meet there within `tol`. A value within 0.01·`tol` is not
/// the end: near a branch point the gap across the crossing flattens (its slope about the
/// square of the distance to the point), and a value that small leaves the root up to ∛tol off
/// there (a value already that small where it starts, too: a chord's midpoint, a step along the
/// tangent). Where the next step would be longer than [`FINE`], the root is bracketed by a change
/// of sign (see [`onto_sign_change`]); the contact's double zero beside it has none, and where
/// none is found (Newton falling onto the contact) the point where the value came within
/// 0.01·`tol` is kept.
fn root_along(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv: DVec2,
    w: DVec2,
    tol: f64,
) -> Option<DVec2> {
    const D: f64 = 1e-7;
    let h = |t: f64| gap(uv + w * t).signed;
    let slope_at = |t: f64| (h(t + D) - h(t - D)) / (2.0 * D);
    let mut t = 0.0;
    // The last Newton step's slope.
    let mut slope_last: Option<f64> = None;
    for _ in 0..30 {
        let v = h(t);
        let slope = slope_last.filter(|_| v.abs() <= 0.01 * tol);
        let slope = slope.unwrap_or_else(|| slope_at(t));
        if !(slope.abs() > 0.0 && slope.is_finite()) {
            if v.abs() <= 0.01 * tol {
                break;
            }
            return None;
        }
        if v.abs() <= 0.01 * tol {
            if (v / slope).abs() > FINE {
                t = onto_sign_change(&h, (t, v), -v / slope);
            }
            break;
        }
        t -= (v / slope).clamp(-0.05, 0.05);
        slope_last = Some(slope);
    }
    let mut m = uv + w * t;
    a.normalise(&mut m);
    (gap(m).dist <= tol).then_some(m)
}

/// From `t0` (where `h` is `v0`, within the tolerance), the root a Newton step `step` points
/// at, bracketed: the step doubled (up to 64 times its length) until `h` changes sign, then
/// regula falsi ([`illinois`]) to a bracket within [`FINE`]. A crossing is a simple root, where
/// the gap changes sign; a contact a double one, where it does not: a step falling onto the
/// contact finds no bracket, and the crossing is looked for the other way (beside a branch point
/// `t0` can lie between the two); where neither way has one, `t0` is kept.
fn onto_sign_change(h: &dyn Fn(f64) -> f64, (t0, v0): (f64, f64), step: f64) -> f64 {
    let mut far = None;
    'sides: for side in [1.0, -1.0] {
        let mut s = side * step;
        for _ in 0..7 {
            let v = h(t0 + s);
            if v == 0.0 {
                return t0 + s;
            }
            if v.signum() != v0.signum() && v.is_finite() {
                far = Some((t0 + s, v));
                break 'sides;
            }
            s *= 2.0;
        }
    }
    let Some((t1, v1)) = far else {
        return t0;
    };
    let ends = [(t0, v0), (t1, v1)].map(|(t, f)| At { t, f, payload: () });
    // A NaN on the way (none is known to happen) keeps `t0`, as where no bracket is found.
    illinois(|t| Some((h(t), ())), ends, Stop::Width(FINE)).map_or(t0, |root| root.t)
}

/// How far (in parameters) [`root_along`]'s Newton is taken past a value within 0.01·tol: about
/// 1e-11 in space on the test surfaces, under the 1e-9 promised.
const FINE: f64 = 1e-11;

/// Follows a crossing from its point `uv` (parameters of `a`) along `dir` in steps of about
/// `len` in space: each node the zero of the gap across the step's end (along a bounded edge
/// where the step reaches one, so the crossing ends exactly on it). A node where `stop` holds
/// (beside a contact, whose double zero the search can fall on) or that is not ahead is refused
/// and the step halved, so the walk ends within a hundredth of the tolerance of an edge or of
/// where the crossing runs into the contact. `stop` is given the node's parameters, the march's
/// direction there (in parameters) and its point.
pub(super) fn march(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    (uv, dir): (DVec2, DVec2),
    len: f64,
    tol: f64,
    stop: &dyn Fn(DVec2, DVec2, DVec3) -> bool,
) -> Vec<(DVec2, DVec3)> {
    let (mut uv, mut t) = (uv, dir.normalize_or_zero());
    // The node the way was last taken from (see below).
    let mut anchor = uv;
    let mut nodes = Vec::new();
    let mut frac = 1.0;
    while nodes.len() < MAX_NODES && t != DVec2::ZERO {
        let Some(speed) = speed_along(a, uv, t) else {
            break;
        };
        let mut step = frac * len / speed;
        let mut edge = None;
        for k in 0..2 {
            if a.periodic()[k] || t[k] == 0.0 {
                continue;
            }
            let room = ((if t[k] > 0.0 { 1.0 } else { 0.0 }) - uv[k]) / t[k];
            if room <= 1e-12 {
                return nodes;
            }
            if room <= step {
                step = room;
                edge = Some(k);
            }
        }
        let mut ahead = uv + t * step;
        let across = match edge {
            Some(k) => {
                ahead[k] = if t[k] > 0.0 { 1.0 } else { 0.0 };
                if k == 0 {
                    DVec2::Y
                } else {
                    DVec2::X
                }
            }
            None => t.perp(),
        };
        let found = root_along(a, gap, ahead, across, tol).map(|c| (c, gap(c).point));
        let good = found.filter(|(c, p)| {
            let moved = delta(a, uv, *c);
            moved.dot(t) > 0.0 && moved.length() <= 2.0 * step && !stop(*c, t, *p)
        });
        match good {
            Some((c, p)) => {
                // A node is placed only to within the tolerance, near a branch point (where
                // the march is refused and its step halved down to 0.01·tol) only to within the
                // gap's rounding over its slope across, several tolerances: the chord of a step
                // not much longer than that says nothing of the way the crossing runs, and
                // taking it for the way on turned marches back along the crossing they came up
                // (s = 1.5e-2: a stub traced there and back, 0.154 long, from steps under the
                // tolerance; cone ∩ patch d = −0.05..0.5 seed 1e-2: the crossing there and back,
                // 6.42 long, from steps of 1e-9 to 1e-8 placed 4e-9 apart across). The way is
                // taken from the chord back to the node it was last taken at, once that is a
                // thousandth of the full step: at full steps, from the last node, as before.
                let moved = delta(a, anchor, c);
                if moved.length() * speed > tol.max(1e-3 * len) {
                    t = moved.normalize();
                    anchor = c;
                }
                uv = c;
                nodes.push((c, p));
                if edge.is_some() {
                    break;
                }
                frac = (4.0 * frac).min(1.0);
            }
            None => {
                frac *= 0.5;
                if frac * len < 0.01 * tol {
                    break;
                }
            }
        }
    }
    nodes
}

/// The crossing `piece` carried on past its ends along the crossing on the true surfaces, to a
/// bounded edge or to where `stop` holds (beside a contact or another piece); in steps of about
/// `len`, densified within `chord_tol`. The ends marked in `cut` are where the seed curve it
/// came from ran onto a contact: the seed's points there can fold back, and are dropped up to
/// the last fold.
pub(crate) fn extend_crossing(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    (piece, cut): (&Polyline3, [bool; 2]),
    stop: &dyn Fn(DVec2, DVec2, DVec3) -> bool,
    len: f64,
    (tol, chord_tol): (f64, f64),
) -> Polyline3 {
    let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| between(a, gap, x, y, tol);
    let mut points = piece.points.clone();
    for (k, cut) in cut.into_iter().enumerate() {
        if k == 0 {
            points.reverse();
        }
        if cut {
            unfold_end(&mut points);
        }
        if points.len() < 2 {
            break;
        }
        let n = points.len();
        let end = a.project(points[n - 1], None);
        let before = a.project(points[n - 2], Some(end));
        let mut nodes = vec![(end, points[n - 1])];
        nodes.extend(march(a, gap, (end, delta(a, before, end)), len, tol, stop));
        if nodes.len() >= 2 {
            let more = assemble(&nodes, false, |x| x.1, &mid_of, tol, chord_tol);
            points.extend_from_slice(&more.points[1..]);
        }
        if k == 0 {
            points.reverse();
        }
    }
    Polyline3 {
        points,
        closed: false,
    }
}

/// `piece` (a crossing's stretch of a refined seed curve) with each point that overshot the next
/// put back after it: where the crossing meets the other surface at a small angle, a seed point
/// refined onto it can slide along it past the next one, and the curve folds back on itself
/// (x = 1.989, 2.645, 2.462, 2.890 on a sheet at 0.06 rad). Only where the next point lies on
/// the chord to the overshooting one (within `chord_tol` of it, strictly between its ends), as
/// it does on the same stretch of curve (a tongue's tip, where the curve turns back, leaves the
/// point across the tongue); the three chords changed are densified again on the true surfaces.
pub(crate) fn unfold_overshoots(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    piece: Polyline3,
    tol: f64,
    chord_tol: f64,
) -> Polyline3 {
    let mut p = piece.points;
    let mut k = 1;
    while k + 1 < p.len() {
        let (before, at, next) = (p[k - 1], p[k], p[k + 1]);
        let chord = at - before;
        let along = (next - before).dot(chord) / chord.length_squared().max(f64::MIN_POSITIVE);
        let off = (next - before).cross(chord).length() / chord.length().max(f64::MIN_POSITIVE);
        let folds = (next - at).dot(chord) < 0.0;
        if !(folds && along > 0.0 && along < 1.0 && off <= chord_tol) {
            k += 1;
            continue;
        }
        p.swap(k, k + 1);
        let hi = (k + 2).min(p.len() - 1);
        let dense = densified(a, gap, &p[k - 1..=hi], tol, chord_tol);
        let added = dense.len() - (hi + 2 - k);
        p.splice(k - 1..=hi, dense);
        // On past the point put back, which may itself have overshot the one after.
        k += 1 + added;
    }
    Polyline3 {
        points: p,
        closed: piece.closed,
    }
}

/// `points` of a crossing, taken onto `a` in turn, with each chord densified within `chord_tol`
/// on the true surfaces (its midpoints the gap's roots across it, see [`between`]).
pub(super) fn densified(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    points: &[DVec3],
    tol: f64,
    chord_tol: f64,
) -> Vec<DVec3> {
    let mut prev = None;
    let nodes: Vec<(DVec2, DVec3)> = points
        .iter()
        .map(|&q| {
            let uv = a.project(q, prev);
            prev = Some(uv);
            (uv, q)
        })
        .collect();
    let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| between(a, gap, x, y, tol);
    assemble(&nodes, false, |x| x.1, &mid_of, tol, chord_tol).points
}

/// Drops the points of the last half of `points` from its first fold (a point where the polyline
/// turns back on itself), leaving the end running on from the rest.
fn unfold_end(points: &mut Vec<DVec3>) {
    let n = points.len();
    let fold = (n / 2..n.saturating_sub(1))
        .find(|&k| k >= 1 && (points[k + 1] - points[k]).dot(points[k] - points[k - 1]) < 0.0);
    if let Some(k) = fold {
        points.truncate(k);
    }
}

/// Whether the gap changes sign across `uv` (a point of a crossing marched along `t`, in
/// parameters): a simple root, a crossing's, where a contact's double zero keeps its sign on
/// both sides. The two samples, at equal distances either way across `t`, go out from a few
/// tolerances in space, doubling, until both are beyond `tol` (up to `reach`): the sign is told
/// there and nowhere nearer. A contact point is told so while the samples stay short of the
/// nearest crossing (its gap, κ·s², is beyond `tol` at √(tol/κ), κ about that crossing's
/// distance d, so for d above about ∛tol); a crossing point whatever lies beyond on either side
/// but another crossing (passing the contact's double zero keeps the sign). From a point on a
/// bounded edge of `a` the samples go along the edge. Where one would lie off a bounded edge of
/// `a` or past the edge of the surface the gap is measured to (where the distance exceeds the
/// signed gap: the march runs to that edge, at any angle), the pair is taken as far back along
/// `t` as it reaches across, where the crossing runs the same way; where that fails too, false.
pub(super) fn changes_sign(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv: DVec2,
    t: DVec2,
    reach: f64,
    tol: f64,
) -> bool {
    let mut w = t.perp();
    for k in 0..2 {
        if !a.periodic()[k] && (uv[k] <= EDGE_ROUNDOFF || uv[k] >= 1.0 - EDGE_ROUNDOFF) {
            w[k] = 0.0;
        }
    }
    let (Some(w), Some(t)) = (w.try_normalize(), t.try_normalize()) else {
        return false;
    };
    let (Some(across), Some(along)) = (speed_along(a, uv, w), speed_along(a, uv, t)) else {
        return false;
    };
    let inside = |q: DVec2| (0..2).all(|k| a.periodic()[k] || (0.0..=1.0).contains(&q[k]));
    let at = |q: DVec2| {
        if !inside(q) {
            return None;
        }
        let g = gap(q);
        (g.signed.is_finite() && g.dist - g.signed.abs() <= tol).then_some(g.signed)
    };
    let pair = |s: f64, back: f64| {
        let o = uv - t * (back * s / along);
        Some((at(o - w * (s / across))?, at(o + w * (s / across))?))
    };
    let mut s = 4.0 * tol;
    let mut back = 0.0;
    while s <= reach {
        let found = pair(s, back).or_else(|| {
            back = 1.0;
            pair(s, back)
        });
        let Some((lo, hi)) = found else {
            return false;
        };
        if lo.abs() > tol && hi.abs() > tol {
            return lo.signum() != hi.signum();
        }
        s *= 2.0;
    }
    false
}

#[cfg(test)]
mod tests {
    use super::{changes_sign, unfold_overshoots};
    use crate::geom::mesh::Polyline3;
    use crate::geom::surface::refine::Patch;
    use crate::geom::surface::Surface;
    use glam::{DVec2, DVec3};

    const TOL: f64 = 1e-9;

    /// The cylinder x² + y² = 1 from z = 0 to 4, and the unit parameter direction along its axis.
    fn cylinder() -> (Surface, DVec2) {
        let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 4.0).unwrap();
        let p = Patch::new(&s);
        let o = p.eval(DVec2::splat(0.5));
        let along_v = (p.eval(DVec2::new(0.5, 0.6)) - o).truncate().length() < 1e-12;
        (s, if along_v { DVec2::Y } else { DVec2::X })
    }

    #[test]
    fn the_gap_changes_sign_across_a_crossing_not_across_a_contact() {
        // The plane x = c cuts the cylinder along the lines cos θ = c (the gap cos θ − c, a
        // simple root) and touches it along θ = 0 for c = 1 (1 − cos θ ≥ 0: a double zero).
        let (s, t) = cylinder();
        let a = Patch::new(&s);
        for (c, crosses) in [(0.6, true), (1.0, false)] {
            let gap = |uv: DVec2| super::super::plane_gap(&a, (DVec3::X * c, DVec3::X), uv);
            let p = DVec3::new(c, (1.0 - c * c).sqrt(), 2.0);
            let uv = a.project(p, None);
            assert_eq!(changes_sign(&a, &gap, uv, t, 0.1, TOL), crosses, "x = {c}");
        }
    }

    #[test]
    fn a_point_refined_past_the_next_is_put_back_after_it() {
        let (s, _) = cylinder();
        let a = Patch::new(&s);
        let gap = |uv: DVec2| super::super::plane_gap(&a, (DVec3::X * 0.6, DVec3::X), uv);
        let on = |y: f64, z: f64| DVec3::new(0.6, y, z);
        let piece = |zs: &[(f64, f64)]| Polyline3 {
            points: zs.iter().map(|&(y, z)| on(y, z)).collect(),
            closed: false,
        };
        // Along the line (0.6, 0.8, z): the point at 1.2 overshot the one at 1.0.
        let out = unfold_overshoots(
            &a,
            &gap,
            piece(&[(0.8, 0.0), (0.8, 0.5), (0.8, 1.2), (0.8, 1.0), (0.8, 1.5)]),
            TOL,
            1e-3,
        );
        let zs: Vec<f64> = out.points.iter().map(|p| p.z).collect();
        assert_eq!(zs, [0.0, 0.5, 1.0, 1.2, 1.5]);
        // Turning back onto the other line (0.6, −0.8, z), 1.6 across: a tongue's tip, kept.
        let hairpin = piece(&[(0.8, 0.0), (0.8, 0.5), (0.8, 1.0), (-0.8, 0.7), (-0.8, 0.2)]);
        let out = unfold_overshoots(&a, &gap, hairpin.clone(), TOL, 1e-3);
        assert_eq!(out.points, hairpin.points);
    }
}
