//! Facet adjacency of a triangle mesh (paper 001 records it for the chaining and the flood fill).

use super::chain::{chain_segments, Polyline3, Segment};
use glam::DVec3;
use rayon::prelude::*;

/// Marker for "no neighbour across this edge" (a boundary or non-manifold edge).
pub const NO_NEIGHBOUR: u32 = u32::MAX;

/// For each triangle, the neighbour across each edge; edge `i` of triangle `[a, b, c]` runs from
/// corner `i` to corner `(i + 1) % 3`. An edge shared by exactly two triangles links them; an
/// edge with one triangle is boundary; an edge with three or more (non-manifold) links none.
#[derive(Debug, Clone)]
pub struct Adjacency {
    neighbours: Vec<[u32; 3]>,
}

#[inline]
pub(crate) fn edge_key(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    ((lo as u64) << 32) | hi as u64
}

impl Adjacency {
    /// Built by sorting the half-edges on their undirected vertex pair (O(n log n), parallel).
    pub fn build(triangles: &[[u32; 3]], _vertex_count: usize) -> Adjacency {
        let mut half: Vec<(u64, u32)> = triangles
            .par_iter()
            .enumerate()
            .flat_map_iter(|(t, tri)| {
                (0..3).map(move |i| (edge_key(tri[i], tri[(i + 1) % 3]), (t * 3 + i) as u32))
            })
            .collect();
        half.par_sort_unstable();
        let mut neighbours = vec![[NO_NEIGHBOUR; 3]; triangles.len()];
        let mut i = 0;
        while i < half.len() {
            let mut j = i + 1;
            while j < half.len() && half[j].0 == half[i].0 {
                j += 1;
            }
            if j - i == 2 {
                let (h0, h1) = (half[i].1 as usize, half[i + 1].1 as usize);
                neighbours[h0 / 3][h0 % 3] = (h1 / 3) as u32;
                neighbours[h1 / 3][h1 % 3] = (h0 / 3) as u32;
            }
            i = j;
        }
        Adjacency { neighbours }
    }

    /// The neighbours of triangle `t` across its edges 0, 1, 2 ([`NO_NEIGHBOUR`] where none).
    #[inline]
    pub fn neighbours(&self, t: usize) -> [u32; 3] {
        self.neighbours[t]
    }

    /// Edges with no neighbour, as (triangle, edge index).
    pub fn boundary_edges(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.neighbours.iter().enumerate().flat_map(|(t, n)| {
            (0..3)
                .filter(move |&i| n[i] == NO_NEIGHBOUR)
                .map(move |i| (t, i))
        })
    }

    /// The boundary edges chained into polylines (closed loops on a manifold mesh).
    pub fn boundary_loops(&self, triangles: &[[u32; 3]], vertices: &[DVec3]) -> Vec<Polyline3> {
        let segs: Vec<Segment> = self
            .boundary_edges()
            .map(|(t, i)| {
                let a = triangles[t][i];
                let b = triangles[t][(i + 1) % 3];
                Segment {
                    keys: [a as u128, b as u128],
                    points: [vertices[a as usize], vertices[b as usize]],
                }
            })
            .collect();
        chain_segments(segs)
    }
}
