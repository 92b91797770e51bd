//! Folds of refined seed curves. The meshes see a contact as a lens of two section lines closer
//! than a cell; where that lens lies beside a crossing (a branch point), both its sides refine
//! onto the contact inside the crossing's seed curve, which runs out along the contact and back
//! (at s = 2e-2 in `surface_contact_branch`'s near-edge family, θ from 0.01 to 0.28 and back)
//! with none of its first, middle and last points touching. `regroup` probes such a curve where
//! it folds back.

use super::near_any;
use crate::geom::mesh::Polyline3;
use crate::geom::surface::refine::Patch;
use glam::{DVec2, DVec3};

/// A seed curve touching at some of its probes: which, and, for one probed at its folds only
/// (see [`fold_probes`]), the points where it folds.
pub(super) struct Probed {
    pub c: Polyline3,
    pub probes: Vec<DVec2>,
    pub on: Vec<bool>,
    pub folds: Vec<DVec3>,
}

/// Whether the contact `t` runs through `q` (within `near`), on past it both ways: `q` farther
/// than `10·near` from an open contact's ends. A contact traced from a true lens's tip ends
/// there (`surface_contact_lens`: its two sides retrace within `near` for about 6e-3 beyond
/// the tip); a mesh lens along a contact lies inside it.
fn runs_through(t: &Polyline3, q: DVec3, near: f64) -> bool {
    let (Some(first), Some(last)) = (t.points.first(), t.points.last()) else {
        return false;
    };
    let inside = t.closed || (q.distance(*first) > 10.0 * near && q.distance(*last) > 10.0 * near);
    inside && near_any(q, std::slice::from_ref(t), near)
}

/// Whether the contact `t` runs through any of `folds` (see [`runs_through`]).
pub(super) fn runs_through_any(t: &Polyline3, folds: &[DVec3], near: f64) -> bool {
    folds.iter().any(|q| runs_through(t, *q, near))
}

/// Most folds of one seed curve probed (see [`fold_probes`]).
const MAX_FOLDS: usize = 4;

/// The touching probes at the folds of a refined seed curve `c` none of whose first, middle and
/// last points touches (with, for each, that it touches), or None. The meshes see a contact as
/// a lens of two section lines closer than a cell: where such a lens lies beside a crossing
/// (a branch point), its two sides refine onto the contact, out along it and back, inside the
/// crossing's seed curve, and turn back where the lens closes. That turn, a segment reversing
/// the one before it, with the curve coming back along itself (see [`retraces`]), is where no
/// crossing takes a densified curve. Points crawled beside a branch point zigzag too, in runs
/// of folds (137 of them in one curve), which trace no contact: the loneliest folds (farthest in
/// points from any other) are probed first.
pub(super) fn fold_probes(
    a: &Patch,
    tangent: &dyn Fn(DVec2) -> bool,
    c: &Polyline3,
    near: f64,
) -> Option<(Vec<DVec2>, Vec<bool>, Vec<DVec3>)> {
    let p = &c.points;
    let folds: Vec<usize> = (1..p.len().saturating_sub(1))
        .filter(|&i| (p[i] - p[i - 1]).dot(p[i + 1] - p[i]) < 0.0)
        .collect();
    let alone = |k: usize| {
        let before = k.checked_sub(1).map_or(usize::MAX, |j| folds[k] - folds[j]);
        let after = folds.get(k + 1).map_or(usize::MAX, |f| f - folds[k]);
        before.min(after)
    };
    let mut order: Vec<usize> = (0..folds.len())
        .filter(|&k| retraces(p, folds[k], near))
        .collect();
    if order.is_empty() {
        return None;
    }
    // Stable: equally lonely folds go in the curve's order.
    order.sort_by_key(|&k| std::cmp::Reverse(alone(k)));
    let at: Vec<DVec3> = order.iter().take(MAX_FOLDS).map(|&k| p[folds[k]]).collect();
    let probes: Vec<DVec2> = at.iter().map(|&q| a.project(q, None)).collect();
    let on: Vec<bool> = probes.iter().map(|&uv| tangent(uv)).collect();
    on.contains(&true).then_some((probes, on, at))
}

/// Most points walked either way from a fold by [`retraces`].
const RETRACE_POINTS: usize = 64;

/// Whether the curve through `p` comes back along itself after its fold at `i`: the point
/// `10·near` back along it before the fold lies within `near` of its stretch after the fold.
/// Both sides of a mesh lens along a contact refine onto that contact, a cell long; a point
/// kinked out of line on a curve that goes on does not come back. A true lens of two crossings
/// closing tangentially at a tip into a contact can come back so too (2√tol wide at its tip,
/// its sides part slowly): [`runs_through`] tells it.
fn retraces(p: &[DVec3], i: usize, near: f64) -> bool {
    let reach = 10.0 * near;
    let (mut j, mut run) = (i, 0.0);
    while run < reach {
        if j == 0 || i - j >= RETRACE_POINTS {
            return false;
        }
        run += p[j].distance(p[j - 1]);
        j -= 1;
    }
    let end = (i + RETRACE_POINTS).min(p.len() - 1);
    let after = Polyline3 {
        points: p[i..=end].to_vec(),
        closed: false,
    };
    near_any(p[j], std::slice::from_ref(&after), near)
}

/// The points of `c` a run `len` along it from each of its touching probes (its first, middle
/// and last points; `on` tells which touch): inward from its ends, both ways from its middle.
/// Where a probe lies on a branch point, the seed curve beside it runs along the contact.
pub(super) fn step_in(c: &Polyline3, on: &[bool], len: f64) -> Vec<DVec3> {
    let p = &c.points;
    let n = p.len();
    let walk = |from: usize, ahead: bool| {
        let (mut i, mut run) = (from, 0.0);
        while run < len {
            let next = if ahead { i + 1 } else { i.checked_sub(1)? };
            run += p.get(next)?.distance(p[i]);
            i = next;
        }
        Some(p[i])
    };
    let ways = [
        (0, true),
        (n / 2, false),
        (n / 2, true),
        (n.wrapping_sub(1), false),
    ];
    let probe = [0, 1, 1, 2];
    ways.iter()
        .zip(probe)
        .filter(|(_, k)| on.get(*k) == Some(&true))
        .filter_map(|(&(from, ahead), _)| walk(from, ahead))
        .collect()
}
