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
use super::line::{delta, GapAt};
use super::near_any;
use crate::geom::mesh::Polyline3;
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
            .map(|&i| {
                let (b, f) = if contact.closed {
                    ((i + n - 1) % n, (i + 1) % n)
                } else {
                    (i.saturating_sub(1), (i + 1).min(n - 1))
                };
                let across = delta(a, uvs[b], uvs[f]).perp().normalize_or_zero();
                if across == DVec2::ZERO {
                    return None;
                }
                let uv = first_crossing(a, gap, uvs[i], across * side, scan, tol)?;
                let p = gap(uv).point;
                (!near_any(p, known, scan.dup) && !near_any(p, &out, scan.dup)).then_some((uv, p))
            })
            .collect();
        let whole = contact.closed && roots.iter().all(Option::is_some);
        let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| {
            let across = delta(a, x.0, y.0).perp().normalize_or_zero();
            let uv = root_along(a, gap, mid(a, x.0, y.0), across, tol)?;
            Some((uv, gap(uv).point))
        };
        for run in roots.split(Option::is_none) {
            let nodes: Vec<(DVec2, DVec3)> = run.iter().flatten().copied().collect();
            if nodes.len() >= 2 {
                out.push(assemble(&nodes, whole, |x| x.1, &mid_of, tol, chord_tol));
            }
        }
    }
    out
}

/// The indices of the contact's points scanned across: both ends (of an open curve) and points
/// about `step` apart between.
fn scanned(pts: &[DVec3], closed: bool, step: f64) -> Vec<usize> {
    let n = pts.len();
    let mut at = vec![0];
    let mut run = 0.0;
    for i in 1..n {
        run += pts[i].distance(pts[i - 1]);
        if run >= step || (i == n - 1 && !closed) {
            at.push(i);
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
    // Space distance s along the scan, to first order.
    let uv_at = |s: f64| uv0 + dir * (s / speed);
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
                    if g.abs() <= 0.01 * tol {
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
/// derivative), when the surfaces meet there within `tol`.
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
    for _ in 0..30 {
        let v = h(t);
        if v.abs() <= 0.01 * tol {
            break;
        }
        let slope = (h(t + D) - h(t - D)) / (2.0 * D);
        if !(slope.abs() > 0.0 && slope.is_finite()) {
            return None;
        }
        t -= (v / slope).clamp(-0.05, 0.05);
    }
    let mut m = uv + w * t;
    a.normalise(&mut m);
    (gap(m).dist <= tol).then_some(m)
}
