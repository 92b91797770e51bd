//! Tangent contact along a curve (a cylinder lying on a plane, a torus under its top plane): the
//! surfaces touch at every point of a line or loop without crossing, so neither the meshes'
//! intersection nor the local minimum search sees more than scattered points of it.
//!
//! Seen from the parameters of surface `a`, the signed gap `h(u, v)` to the other surface has a
//! zero extremum at a contact; along a contact curve its Hessian is singular, the null direction
//! being the curve's tangent. From a contact point the curve is followed both ways: a step along
//! the tangent, then the extremum of `h` across it (Newton on the transverse derivative, exact
//! for the quadratic `h` of a tangency). A step is kept when the surfaces meet there within the
//! tolerance; it is halved where they part (bisecting for the contact's end to a hundredth of the
//! tolerance), held at the edge of a bounded parameter, and the loop closes when the walk returns
//! to its start. The nodes are then densified within the chord tolerance like every refined
//! curve.

use super::super::refine::{assemble, mid, Patch};
use super::near_any;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

/// The gap between the surfaces at a parameter pair of `a`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GapAt {
    /// Signed: smooth through a contact, where it has an extremum of value zero.
    pub signed: f64,
    /// The distance between the surfaces (it differs from |signed| off the other's extent).
    pub dist: f64,
    /// The point of contact (midway between the surfaces).
    pub point: DVec3,
}

/// Difference step in (u, v) for the derivatives of the gap.
const D: f64 = 1e-5;

/// The smaller principal curvature of `h` over the larger below which the contact is a curve:
/// along one the Hessian is zero but for difference noise (about 1e-7 of the other).
const FLAT: f64 = 1e-4;

/// Most nodes one walk makes before giving up (a curve thousands of steps long).
const MAX_NODES: usize = 1 << 15;

/// The Hessian of `h` at `uv` by central differences: `[h_uu, h_uv, h_vv]`.
fn hessian(h: &dyn Fn(DVec2) -> f64, uv: DVec2) -> [f64; 3] {
    let f = |du: f64, dv: f64| h(uv + DVec2::new(du, dv));
    let h0 = f(0.0, 0.0);
    let d2 = D * D;
    [
        (f(D, 0.0) - 2.0 * h0 + f(-D, 0.0)) / d2,
        (f(D, D) - f(D, -D) - f(-D, D) + f(-D, -D)) / (4.0 * d2),
        (f(0.0, D) - 2.0 * h0 + f(0.0, -D)) / d2,
    ]
}

/// The eigenpairs of the symmetric `[[a, b], [b, c]]`, the larger |λ| first.
fn eigen([a, b, c]: [f64; 3]) -> [(f64, DVec2); 2] {
    let (m, r) = (0.5 * (a + c), (0.25 * (a - c) * (a - c) + b * b).sqrt());
    let th = 0.5 * (2.0 * b).atan2(a - c);
    let (e1, e2) = (
        DVec2::new(th.cos(), th.sin()),
        DVec2::new(-th.sin(), th.cos()),
    );
    let (p1, p2) = ((m + r, e1), (m - r, e2));
    if p1.0.abs() >= p2.0.abs() {
        [p1, p2]
    } else {
        [p2, p1]
    }
}

/// The three-point derivative's bias over the second derivative (the shift it gives the
/// extremum, in parameters) up to which Newton runs on three-point differences less the bias
/// found at the start; a step of it this short has converged (the next is at the noise).
const QUICK: f64 = 1e-9;

/// The extremum of `h` on the line `uv + s·w` nearest `uv` (Newton on the derivative along `w`),
/// with bounded parameters held in their domain. The three-point derivative is off by D²·h‴/6,
/// which moves the extremum by that over h″ (1e-9 in parameters on a contact 1e-9 long, enough
/// for a scan across from its end on a bounded edge to leave the domain), unbounded where the
/// contact flattens to an inflection across (a crossing running into it): there Newton leapt
/// off, or onto the gap's other extremum, a maximum beside the contact. The five-point
/// derivative at the start measures the bias: below [`QUICK`], plain Newton on three-point
/// differences less that bias (h‴ barely changes over the search; two or three steps);
/// elsewhere [`settle_flat`].
pub(super) fn settle(a: &Patch, h: &dyn Fn(DVec2) -> f64, uv: DVec2, w: DVec2) -> DVec2 {
    let f = |x: f64| h(uv + w * x);
    let g5 = slope5(&f, 0.0);
    let (p, z, m) = (f(D), f(0.0), f(-D));
    let (g, c) = ((p - m) / (2.0 * D), (p - 2.0 * z + m) / (D * D));
    if !(c.abs() > 0.0 && c.is_finite() && g.is_finite() && g5.is_finite()) {
        return clamp_bounded(a, uv);
    }
    let bias = g - g5;
    if bias.abs() > QUICK * c.abs() {
        return clamp_bounded(a, uv + w * settle_flat(&f, g5, c));
    }
    let (mut s, mut step) = (0.0, (g5 / c).clamp(-0.05, 0.05));
    for _ in 0..10 {
        s -= step;
        if step.abs() <= QUICK {
            break;
        }
        let (m, z, p) = (f(s - D), f(s), f(s + D));
        let (g, c) = ((p - m) / (2.0 * D) - bias, (p - 2.0 * z + m) / (D * D));
        if !(c.abs() > 0.0 && c.is_finite() && g.is_finite()) {
            break;
        }
        step = (g / c).clamp(-0.05, 0.05);
    }
    clamp_bounded(a, uv + w * s)
}

/// The five-point derivative of `f` at `x`.
fn slope5(f: &dyn Fn(f64) -> f64, x: f64) -> f64 {
    (8.0 * (f(x + D) - f(x - D)) - (f(x + 2.0 * D) - f(x - 2.0 * D))) / (12.0 * D)
}

/// The extremum of `f` nearest 0 (where its five-point derivative is `g` and its second
/// derivative `c`) by Newton on the five-point derivative, where the three-point one is off: a
/// step that does not lessen the derivative is halved, and the search stops where none does
/// (the derivative at its noise).
fn settle_flat(f: &dyn Fn(f64) -> f64, mut g: f64, mut c: f64) -> f64 {
    let mut s = 0.0;
    for it in 0..20 {
        if it > 0 {
            c = (f(s + D) - 2.0 * f(s) + f(s - D)) / (D * D);
        }
        if !(c.abs() > 0.0 && c.is_finite() && g.is_finite()) {
            break;
        }
        let mut step = (g / c).clamp(-0.05, 0.05);
        let mut next = None;
        for _ in 0..8 {
            let gn = slope5(f, s - step);
            if gn.abs() < g.abs() {
                next = Some(gn);
                break;
            }
            step *= 0.5;
        }
        let Some(gn) = next else { break };
        s -= step;
        g = gn;
        if step.abs() <= 1e-13 {
            break;
        }
    }
    s
}

pub(super) fn clamp_bounded(a: &Patch, mut uv: DVec2) -> DVec2 {
    for k in 0..2 {
        if !a.periodic()[k] {
            uv[k] = uv[k].clamp(0.0, 1.0);
        }
    }
    uv
}

/// `y − x` the short way round in periodic directions.
pub(super) fn delta(a: &Patch, x: DVec2, y: DVec2) -> DVec2 {
    let mut d = y - x;
    for k in 0..2 {
        if a.periodic()[k] {
            d[k] -= d[k].round();
        }
    }
    d
}

/// The distance from `p` to the segment `ab`, and where along it (0 at a, 1 at b) it is nearest.
fn to_segment(p: DVec3, a: DVec3, b: DVec3) -> (f64, f64) {
    let d = b - a;
    let f = ((p - a).dot(d) / d.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
    (p.distance(a + d * f), f)
}

/// A step along a contact this short (in space) is within about the tolerance of it when taken
/// straight along its tangent: the contact's curvature (about 1/size at most) times its square.
fn short_step(a: &Patch, tol: f64) -> f64 {
    (tol * a.scale()).sqrt()
}

/// Follows the contact from `start` along `dir` (in (u, v)) in steps of about `len` in space.
/// Returns the nodes after `start` and whether the walk came back round to it.
fn walk(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    start: DVec2,
    dir: DVec2,
    len: f64,
    tol: f64,
) -> (Vec<DVec2>, bool) {
    let h = |uv: DVec2| gap(uv).signed;
    let g_start = gap(start);
    let p_start = g_start.point;
    // Where the surfaces part: half way from the contact's own gap to the tolerance (half the
    // tolerance for surfaces that touch), so the end is found within it, and a contact held a
    // fraction of the tolerance apart (0.6 of it: they still meet) is followed all the same.
    let level = if g_start.dist >= 0.0 {
        g_start.dist.min(tol)
    } else {
        0.0
    };
    let parted = 0.5 * (tol + level);
    let (mut uv, mut t) = (start, dir.normalize());
    let mut p_prev = p_start;
    let mut nodes: Vec<DVec2> = Vec::new();
    let mut frac = 1.0;
    let short = short_step(a, tol);
    while nodes.len() < MAX_NODES {
        let Some(speed) = speed_along(a, uv, t) else {
            break;
        };
        let mut step = frac * len / speed;
        // A bounded parameter reaching its edge: the step ends there, and so does the walk.
        let mut at_edge = false;
        for k in 0..2 {
            if a.periodic()[k] || t[k] == 0.0 {
                continue;
            }
            let room = ((if t[k] > 0.0 { 1.0 } else { 0.0 }) - uv[k]) / t[k];
            if room <= 1e-12 {
                return (nodes, false);
            }
            if room <= step {
                step = room;
                at_edge = true;
            }
        }
        let ahead = uv + t * step;
        let on = |g: &GapAt, moved: DVec2| {
            g.dist <= parted && moved.dot(t) > 0.0 && moved.length() <= 2.0 * step
        };
        // Once a bisection for the end has made the step shorter than `short`, the step straight
        // along the tangent is on the contact to its curvature times the step squared (about
        // the tolerance), and is taken where the surfaces meet there: near a branch point (a
        // crossing running into the contact, here where it ends at the other surface's edge)
        // the section across flattens to an inflection, and the extremum `settle` finds is off
        // the contact by the derivative's noise over a vanishing curvature (1e-6 within 1e-5
        // of it), or missing. Where the surfaces part (the contact's true end) it fails.
        let straight = clamp_bounded(a, ahead);
        let gs = (frac * len <= short).then(|| gap(straight));
        let (cand, g) = match gs {
            Some(gs) if on(&gs, straight - uv) => (straight, gs),
            _ => {
                let c = settle(a, &h, ahead, t.perp());
                (c, gap(c))
            }
        };
        let moved = cand - uv;
        if on(&g, moved) {
            // Back round to the start (this step reaches or passes it): the loop closes there.
            let (d, f) = to_segment(p_start, p_prev, g.point);
            if nodes.len() >= 2 && d <= 0.1 * len && f > 0.0 {
                return (nodes, true);
            }
            nodes.push(cand);
            t = moved.normalize();
            uv = cand;
            p_prev = g.point;
            if at_edge {
                return (nodes, false);
            }
            // Back up to full steps gradually: near an end the next full step fails again,
            // and growing fourfold keeps the search for the end a bisection.
            frac = (4.0 * frac).min(1.0);
        } else {
            // The surfaces part (or the step left the curve): shorter steps find the end, to
            // well within the tolerance.
            frac *= 0.5;
            if frac * len < 0.01 * tol {
                break;
            }
        }
    }
    (nodes, false)
}

/// The contact curve through the contact at `uv0` (parameters of `a`, `gap` within `tol` there)
/// when the contact is a curve, densified within `chord_tol`; None when it is isolated (the gap
/// curves up both ways). `len` is the step length in space (the seeding mesh's edge length).
pub(crate) fn contact_curve(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv0: DVec2,
    len: f64,
    tol: f64,
    chord_tol: f64,
) -> Option<Polyline3> {
    let h = |uv: DVec2| gap(uv).signed;
    let [(big, across), (small, along)] = eigen(hessian(&h, uv0));
    // Curved both ways (or NaN): an isolated contact.
    let flat = small.abs() <= FLAT * big.abs();
    if !flat {
        return None;
    }
    // The seed lies on the contact to about √tol across it: settle it there first.
    let uv0 = settle(a, &h, uv0, across);
    if gap(uv0).dist > tol {
        return None;
    }
    let (fwd, mut closed) = walk(a, gap, uv0, along, len, tol);
    let mut nodes: Vec<DVec2> = Vec::new();
    if !closed {
        let (back, _) = walk(a, gap, uv0, -along, len, tol);
        nodes.extend(back.into_iter().rev());
    }
    nodes.push(uv0);
    nodes.extend(fwd);
    if nodes.len() < 2 {
        return None;
    }
    // Both ways ending on parameter edges that the surface joins (a sweep round a closed guide
    // whose frames do not close to roundoff): one loop.
    if !closed && nodes.len() >= 3 {
        let (p, q) = (gap(nodes[0]).point, gap(nodes[nodes.len() - 1]).point);
        if p.distance(q) <= 4.0 * tol {
            nodes.pop();
            closed = true;
        }
    }
    let nodes: Vec<(DVec2, DVec3)> = nodes
        .into_iter()
        .map(|mut uv| {
            a.normalise(&mut uv);
            (uv, gap(uv).point)
        })
        .collect();
    let short = short_step(a, tol);
    let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| {
        let across = delta(a, x.0, y.0).perp().normalize_or_zero();
        // Between nodes a short step apart (the walk's last, near an end) the midpoint is on
        // the contact to about the tolerance: settled, near a branch point, it would be off by
        // the noise over a vanishing curvature across (see `walk`) and be inserted as a zigzag.
        let m = mid(a, x.0, y.0);
        let m = if x.1.distance(y.1) <= short {
            m
        } else {
            settle(a, &h, m, across)
        };
        let g = gap(m);
        (g.dist <= tol).then_some((m, g.point))
    };
    Some(assemble(&nodes, closed, |x| x.1, &mid_of, tol, chord_tol))
}

// Crossings running alongside a traced tangent contact. Where the surfaces touch along a curve
// and also cross each other a short way off it (closer than the seeding meshes resolve), the
// meshes see one change of side for the two, and their one seed curve refines onto either the
// contact or the crossing, never both. Once the contact is traced, the signed gap is scanned
// across it on both sides, outwards in geometric steps from near the contact to where the
// surfaces are plainly apart: a change of sign between two samples that are beyond the
// tolerance (so the crossing is told from the contact by more than the tolerance) is bisected
// to a point of the crossing. Runs of such points along the contact are joined and densified
// within the chord tolerance like every refined curve.

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
    let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| between(a, gap, x, y, tol);
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
    // rather than out of the domain by the roundoff in `dir`.
    let mut dir = dir;
    for k in 0..2 {
        let out = (w[k] <= 0.0 && dir[k] < 0.0) || (w[k] >= 1.0 && dir[k] > 0.0);
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
/// derivative), when the surfaces meet there within `tol`. Newton goes on past a value within
/// 0.01·`tol` while its next step would be longer than [`FINE`]: near a branch point the gap
/// across the crossing flattens (its slope about the square of the distance to the point), and
/// a value that small leaves the root up to ∛tol off there. It goes on only while its steps
/// shrink fourfold or faster, as they do onto a simple root; halving, they are falling onto the
/// contact's double zero beside it, and the point where the value first came within 0.01·`tol`
/// is kept.
fn root_along(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv: DVec2,
    w: DVec2,
    tol: f64,
) -> Option<DVec2> {
    const D: f64 = 1e-7;
    let h = |t: f64| gap(uv + w * t).signed;
    let mut t = 0.0;
    // The last Newton step's slope, and, once the value is within 0.01·tol, where it came in
    // and the last step past it.
    let mut slope_last: Option<f64> = None;
    let mut band: Option<(f64, f64)> = None;
    let mut done = false;
    for _ in 0..30 {
        let v = h(t);
        if v.abs() <= 0.01 * tol {
            let Some(s) = slope_last else {
                done = true;
                break;
            };
            let next = (v / s).abs();
            // Within FINE, or at the gap's noise.
            if next <= FINE || v.abs() <= 1e-14 {
                done = true;
                break;
            }
            match band {
                Some((t0, prev)) if next > 0.25 * prev => {
                    t = t0;
                    done = true;
                    break;
                }
                Some((t0, _)) => band = Some((t0, next)),
                None => band = Some((t, next)),
            }
        }
        let slope = (h(t + D) - h(t - D)) / (2.0 * D);
        if !(slope.abs() > 0.0 && slope.is_finite()) {
            match band {
                Some((t0, _)) => {
                    t = t0;
                    done = true;
                    break;
                }
                None => return None,
            }
        }
        t -= (v / slope).clamp(-0.05, 0.05);
        slope_last = Some(slope);
    }
    if let (false, Some((t0, _))) = (done, band) {
        t = t0;
    }
    let mut m = uv + w * t;
    a.normalise(&mut m);
    (gap(m).dist <= tol).then_some(m)
}

/// How far (in parameters) [`root_along`]'s Newton is taken past a value within 0.01·tol: about
/// 1e-11 in space on the test surfaces, under the 1e-9 promised.
const FINE: f64 = 1e-11;

/// Follows a crossing from its point `uv` (parameters of `a`) along `dir` in steps of about
/// `len` in space: each node the zero of the gap across the step's end (along a bounded edge
/// where the step reaches one, so the crossing ends exactly on it). A node where `stop` holds
/// (beside a contact, whose double zero the search can fall on) or that is not ahead is refused
/// and the step halved, so the walk ends within a hundredth of the tolerance of an edge or of
/// where the crossing runs into the contact.
fn march(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    (uv, dir): (DVec2, DVec2),
    len: f64,
    tol: f64,
    stop: &dyn Fn(DVec3) -> bool,
) -> Vec<(DVec2, DVec3)> {
    let (mut uv, mut t) = (uv, dir.normalize_or_zero());
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
            moved.dot(t) > 0.0 && moved.length() <= 2.0 * step && !stop(*p)
        });
        match good {
            Some((c, p)) => {
                t = delta(a, uv, c).normalize();
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
    stop: &dyn Fn(DVec3) -> bool,
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

/// How fast the surface moves in space along the parameter direction `t` at `uv`; None at a
/// degenerate point of the parameterisation (zero, infinite or NaN), where there is no way on.
pub(super) fn speed_along(a: &Patch, uv: DVec2, t: DVec2) -> Option<f64> {
    let mut w = uv;
    a.normalise(&mut w);
    let (su, sv) = a.derivs(w);
    let speed = (su * t.x + sv * t.y).length();
    (speed > 0.0 && speed.is_finite()).then_some(speed)
}
