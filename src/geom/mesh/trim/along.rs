//! The stretches of a coincident region's boundary that run along edges of the trimmed mesh.
//!
//! [`super::super::coplanar::coincident_pieces`] gives the boundary where it crosses facets; a
//! stretch lying on an edge crosses none, so it is not there — and a cutter that is a piece of
//! the surface itself (a sub-grid of a grid, a sector of a cylinder's strips) has its whole
//! boundary on edges: nothing was cut and the trim kept everything, or, with the boundary
//! partly on edges, the cut had gaps and the flood fill leaked round them. These stretches are
//! cut too: each becomes a piece on a facet holding that edge, its ends the edge's vertices or
//! nodes on it, so the edge (or its part) is a cut edge and the facets on both sides are split
//! at the nodes like any other.

use super::super::adjacency::edge_key;
use super::super::chain::{Polyline3, Segment};
use super::super::intersect::Piece;
use super::super::{Aabb, Mesh};
use super::SNAP;
use glam::DVec3;
use std::collections::HashMap;

/// Where a boundary point lies on `mesh`: a vertex, or inside an edge.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Spot {
    Vertex(u32),
    Edge(u32, u32),
}

/// The place of `p` on `mesh` among the facets near it: a vertex (same bits, or within roundoff
/// of one), else an edge it lies on to roundoff (the crossing of a cutter edge with this edge,
/// computed from both); None inside a facet or off the mesh.
fn spot(mesh: &Mesh, p: DVec3) -> Option<Spot> {
    let r = SNAP * (1.0 + p.abs().max_element());
    let b = Aabb {
        min: p - DVec3::splat(r),
        max: p + DVec3::splat(r),
    };
    let mut facets: Vec<u32> = Vec::new();
    mesh.bvh().query_box(&b, |t| facets.push(t));
    facets.sort_unstable();
    let v = mesh.vertices();
    let mut on_edge: Option<Spot> = None;
    for &t in &facets {
        let tri = mesh.triangles()[t as usize];
        for k in 0..3 {
            let (i, j) = (tri[k], tri[(k + 1) % 3]);
            let (a, c) = (v[i as usize], v[j as usize]);
            let len = a.distance(c);
            if a == p || a.distance(p) <= SNAP * len {
                return Some(Spot::Vertex(i));
            }
            if on_edge.is_none() {
                let d = c - a;
                let f = (p - a).dot(d) / d.length_squared();
                if f > 0.0 && f < 1.0 && p.distance(a + d * f) <= SNAP * len {
                    on_edge = Some(Spot::Edge(i.min(j), i.max(j)));
                }
            }
        }
    }
    on_edge
}

/// A facet holding the inner edge of `mesh` both spots lie on.
fn common_edge(mesh: &Mesh, p: Spot, q: Spot, by_edge: &HashMap<u64, u32>) -> Option<u32> {
    let edge = |u: u32, w: u32| by_edge.get(&edge_key(u, w)).copied();
    match (p, q) {
        (Spot::Vertex(u), Spot::Vertex(w)) => edge(u, w),
        (Spot::Vertex(u), Spot::Edge(i, j)) | (Spot::Edge(i, j), Spot::Vertex(u)) => {
            (u == i || u == j).then(|| edge(i, j)).flatten()
        }
        (Spot::Edge(i, j), Spot::Edge(k, l)) => ((i, j) == (k, l)).then(|| edge(i, j)).flatten(),
    }
    .filter(|&t| (t as usize) < mesh.len())
}

/// Cut pieces for the boundary stretches of `loops` that lie along edges of `mesh`, keyed by
/// point in a key space of their own (merged with the others by point afterwards).
pub(super) fn along_edge_pieces(mesh: &Mesh, loops: &[Polyline3]) -> Vec<Piece> {
    // Edges inside the surface, each with one facet holding it (a stretch along the surface's
    // own boundary separates nothing and is left alone).
    let mut count: HashMap<u64, (u32, u32)> = HashMap::new();
    for (t, tri) in mesh.triangles().iter().enumerate() {
        for k in 0..3 {
            count
                .entry(edge_key(tri[k], tri[(k + 1) % 3]))
                .or_insert((t as u32, 0))
                .1 += 1;
        }
    }
    let by_edge: HashMap<u64, u32> = count
        .into_iter()
        .filter(|(_, (_, n))| *n >= 2)
        .map(|(e, (t, _))| (e, t))
        .collect();
    let mut ids: HashMap<[u64; 3], u128> = HashMap::new();
    let mut key = |p: DVec3| {
        let n = ids.len() as u128;
        (1u128 << 126) | *ids.entry(p.to_array().map(f64::to_bits)).or_insert(n)
    };
    let mut out = Vec::new();
    for l in loops {
        let n = l.points.len();
        let spots: Vec<Option<Spot>> = l.points.iter().map(|&p| spot(mesh, p)).collect();
        let segs = if l.closed { n } else { n.saturating_sub(1) };
        for i in 0..segs {
            let j = (i + 1) % n;
            let (Some(sp), Some(sq)) = (spots[i], spots[j]) else {
                continue;
            };
            let Some(ta) = common_edge(mesh, sp, sq, &by_edge) else {
                continue;
            };
            let on = |s: Spot| match s {
                Spot::Vertex(_) => None,
                Spot::Edge(u, w) => Some((u, w)),
            };
            let (p, q) = (l.points[i], l.points[j]);
            out.push(Piece {
                ta,
                seg: Segment {
                    keys: [key(p), key(q)],
                    points: [p, q],
                },
                a_edge: [on(sp), on(sq)],
            });
        }
    }
    out
}
