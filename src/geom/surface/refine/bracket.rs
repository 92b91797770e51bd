//! A plane-section seed point kept between the two vertices of the mesh edge it came from.
//!
//! The vertices lie on the true surface on opposite sides of the plane, so the gap changes sign
//! between them on the true surface too: the crossing this seed stands for lies there. Newton
//! from the seed goes to the nearer crossing, which is another where the mesh's section is off
//! the true one's middle: in a lens of crossings narrower than the mesh's cells (the arc dips
//! 1e-4 below the plane) both seed lines lay on one side of the lens's middle, and the crossing
//! on that side came back twice, the other not at all. A Newton point outside the edge's slab is
//! replaced by the root of the gap along the parameter segment between the vertices (Illinois,
//! which keeps the bracket).

use super::newton::Node;
use super::Patch;
use crate::geom::root::{illinois, At, Stop};
use glam::{DVec2, DVec3};

/// `(uv, r)`, Newton's refinement from `start` of a seed point on the mesh edge `[va, vb]`, or,
/// where Newton went the wrong way, the crossing between `va` and `vb` on `s` (when their gaps
/// to the plane bracket one and it is solved within `tol`). The wrong way: the crossing of the
/// bracket lies from the start toward the vertex whose gap has the other sign than the start's,
/// and Newton moved toward the other vertex (the start's slope differs in sign from the edge's:
/// beyond the lens's middle), AND its point left the edge's span across the seed curve
/// (`along`, the seed's direction there: the long cells' rulings make the edge's span along it
/// meaningless). Both, since near a branch point (a torus's figure eight) Newton's first step
/// may go against the edge's slope yet stay on the edge's branch.
pub(crate) fn within_edge(
    s: &Patch,
    (p0, n): (DVec3, DVec3),
    (start, along): (DVec2, DVec3),
    (uv, r): (DVec2, f64),
    e: [DVec3; 2],
    tol: f64,
) -> (DVec2, f64) {
    let gap = |x: DVec3| n.dot(x - p0);
    within_edge_of(s, (&gap, n), (start, along), (uv, r), e, tol)
}

/// [`within_edge`] against any other object whose signed gap is `gap` (a surface: the
/// distance along its normal), `n` its normal near the seed.
pub(crate) fn within_edge_of(
    s: &Patch,
    (gap_of, n): (&dyn Fn(DVec3) -> f64, DVec3),
    (start, along): (DVec2, DVec3),
    (uv, r): (DVec2, f64),
    [va, vb]: [DVec3; 2],
    tol: f64,
) -> (DVec2, f64) {
    // Inside the edge's span first: it settles nearly every seed point with one evaluation.
    let x = s.eval(uv);
    let across = n.cross(along).normalize_or_zero();
    let (ca, cb) = (va.dot(across), vb.dot(across));
    if r <= tol && (ca.min(cb)..=ca.max(cb)).contains(&x.dot(across)) {
        return (uv, r);
    }
    let s0 = s.eval(start);
    let g0 = gap_of(s0);
    // `e` runs from the vertex on the start's side to the other: the crossing lies along it.
    let e = if gap_of(vb) * g0 < 0.0 {
        vb - va
    } else {
        va - vb
    };
    if g0.abs() <= tol || (r <= tol && (x - s0).dot(e) >= 0.0) {
        return (uv, r);
    }
    let ua = s.project(va, Some(start));
    let ub = s.project(vb, Some(start));
    let mut d = ub - ua;
    for (k, periodic) in s.periodic().into_iter().enumerate() {
        if periodic {
            d[k] -= d[k].round();
        }
    }
    let at = |t: f64| {
        let mut q = ua + d * t;
        s.normalise(&mut q);
        q
    };
    let sample = |t: f64| {
        let q = at(t);
        (gap_of(s.eval(q)), q)
    };
    let ends = [0.0, 1.0].map(|t| {
        let (f, payload) = sample(t);
        At { t, f, payload }
    });
    match illinois(|t| Some(sample(t)), ends, Stop::Value(0.01 * tol)) {
        Some(root) if root.f.abs() <= tol => (root.payload, root.f.abs()),
        _ => (uv, r),
    }
}

/// [`within_edge`] for a seed point of two meshes' intersection lying on an edge of one of
/// them (`on_b`: of `b`'s): its vertices lie on that surface on opposite sides of the other, so
/// the crossing the seed stands for lies between them there, and two seed points of a lens
/// narrower than the cells, both on one side of its middle, go to its two crossings, not both
/// to one. The gap to the other surface is taken along its normal at the point's projection.
pub(crate) fn pair_within_edge(
    (a, b): (&Patch, &Patch),
    (on_b, e): (bool, [DVec3; 2]),
    (start, along): ([DVec2; 2], DVec3),
    n: Node,
    tol: f64,
) -> Node {
    // Inside the edge's own span across the seed curve first: it settles nearly every seed
    // point with no evaluation, where the other surface's normal costs four.
    if n.residual <= tol && within_span(n.point, along, e) {
        return n;
    }
    let k = on_b as usize;
    let (s, o) = if on_b { (b, a) } else { (a, b) };
    let hint = if n.residual <= tol {
        n.uv[1 - k]
    } else {
        start[1 - k]
    };
    let normal = |q: DVec2| {
        let (su, sv) = o.derivs(q);
        su.cross(sv).normalize_or_zero()
    };
    let gap = |x: DVec3| {
        let q = o.project(x, Some(hint));
        normal(q).dot(x - o.eval(q))
    };
    let r = (start[k], along);
    let (uv, res) = within_edge_of(s, (&gap, normal(hint)), r, (n.uv[k], n.residual), e, tol);
    if uv == n.uv[k] {
        return n;
    }
    let x = s.eval(uv);
    let q = o.project(x, Some(hint));
    let y = o.eval(q);
    let mut uvs = [uv, q];
    if on_b {
        uvs.swap(0, 1);
    }
    Node {
        uv: uvs,
        point: 0.5 * (x + y),
        residual: x.distance(y).max(res),
    }
}

/// Whether `x` lies within the span of the edge `[va, vb]` across the seed curve's direction
/// `along` (the edge's part square to it).
fn within_span(x: DVec3, along: DVec3, [va, vb]: [DVec3; 2]) -> bool {
    let t = along.normalize_or_zero();
    let d = vb - va;
    let across = d - t * d.dot(t);
    let (ca, cb) = (va.dot(across), vb.dot(across));
    (ca.min(cb)..=ca.max(cb)).contains(&x.dot(across))
}
