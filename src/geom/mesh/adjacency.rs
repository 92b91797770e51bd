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
    /// Built from the vertex → incident-triangle lists (compressed rows): the neighbour across
    /// edge (a, b) of t is the one other triangle in a's list that also uses b. Linear in the
    /// mesh size (times the vertex valence), parallel over triangles.
    pub fn build(triangles: &[[u32; 3]], vertex_count: usize) -> Adjacency {
        let mut start = vec![0u32; vertex_count + 1];
        for t in triangles {
            for &v in t {
                start[v as usize + 1] += 1;
            }
        }
        for i in 0..vertex_count {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut incident = vec![0u32; triangles.len() * 3];
        for (t, tri) in triangles.iter().enumerate() {
            for &v in tri {
                incident[fill[v as usize] as usize] = t as u32;
                fill[v as usize] += 1;
            }
        }
        let neighbours = triangles
            .par_iter()
            .enumerate()
            .map(|(t, tri)| {
                std::array::from_fn(|i| {
                    let (a, b) = (tri[i], tri[(i + 1) % 3]);
                    let list =
                        &incident[start[a as usize] as usize..start[a as usize + 1] as usize];
                    let mut found = NO_NEIGHBOUR;
                    let mut count = 0;
                    for &u in list {
                        if u as usize != t && triangles[u as usize].contains(&b) {
                            count += 1;
                            found = u;
                        }
                    }
                    if count == 1 {
                        found
                    } else {
                        NO_NEIGHBOUR
                    }
                })
            })
            .collect();
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
