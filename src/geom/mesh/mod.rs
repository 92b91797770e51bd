//! The discrete surface of paper 001: an indexed triangle mesh with shared vertices.
//!
//! Paper 001 stores a discrete surface as three linked structures, Surface / Patch / Vertex,
//! with each vertex stored once however many patches meet there, and with the facet adjacency
//! recorded. [`Mesh`] is that structure: `vertices` (each stored once), `triangles` (patches as
//! three vertex indices, counter-clockwise about the outward side) and, built lazily on first use
//! and cached, the facet adjacency ([`Adjacency`]) and a bounding-volume hierarchy ([`Bvh`]).

mod adjacency;
mod bvh;
mod chain;
mod coplanar;
mod error;
mod extend;
mod intersect;
mod io;
pub mod predicates;
mod primitives;
mod section;
mod trim;

pub use adjacency::{Adjacency, NO_NEIGHBOUR};
pub use bvh::{Aabb, Bvh};
pub(crate) use chain::chain_directed;
pub use chain::{chain_segments, Polyline3, Segment};
pub use error::MeshError;
pub use extend::{corners, extend, extend_with};
pub use intersect::{
    intersect_meshes, intersect_meshes_edges, intersect_meshes_with_stats, IntersectStats,
    PairEdgedPolyline,
};
pub(crate) use io::weld_tolerance_grid;
pub use io::{
    parse_obj, parse_stl, read_mesh, read_obj, read_stl, write_mesh, write_obj, write_stl_ascii,
    write_stl_binary, StlRead,
};
pub use primitives::icosphere;
pub use section::{section, section_edges};
pub(crate) use trim::closest_on_triangle;
pub use trim::{trim, Trimmed};

use glam::DVec3;
use std::sync::OnceLock;

/// Keeps only the vertices the triangles use, renumbered in first-use order.
pub(crate) fn compact_vertices(
    verts: &[DVec3],
    mut tris: Vec<[u32; 3]>,
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut map = vec![u32::MAX; verts.len()];
    let mut out = Vec::new();
    // In place, in a plain loop: written with `array::map` and `collect`, the per-index closure
    // was inlined or not depending on how the crate's codegen units fell, which moved the
    // section benchmarks by 1.5 % between builds of unrelated code.
    for i in tris.iter_mut().flatten() {
        let k = *i as usize;
        if map[k] == u32::MAX {
            map[k] = out.len() as u32;
            out.push(verts[k]);
        }
        *i = map[k];
    }
    (out, tris)
}

/// An indexed triangle mesh (paper 001's discrete surface) with lazily cached adjacency and BVH.
#[derive(Debug, Default)]
pub struct Mesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    adjacency: OnceLock<Adjacency>,
    bvh: OnceLock<Bvh>,
}

impl Clone for Mesh {
    fn clone(&self) -> Self {
        // The caches are pure functions of the data; cloning them saves a rebuild.
        Mesh {
            vertices: self.vertices.clone(),
            triangles: self.triangles.clone(),
            adjacency: self.adjacency.clone(),
            bvh: self.bvh.clone(),
        }
    }
}

impl Mesh {
    /// A mesh from shared vertices and triangles of vertex indices.
    ///
    /// Errors when an index is out of range, a coordinate is not finite, or there are more
    /// than `u32::MAX` vertices.
    pub fn new(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<Mesh, MeshError> {
        if vertices.len() >= u32::MAX as usize {
            return Err(MeshError::TooLarge {
                vertices: vertices.len(),
            });
        }
        if let Some(i) = vertices.iter().position(|v| !v.is_finite()) {
            return Err(MeshError::NonFinite { vertex: i });
        }
        let n = vertices.len() as u32;
        if let Some(t) = triangles.iter().position(|t| t.iter().any(|&i| i >= n)) {
            return Err(MeshError::IndexOutOfRange {
                triangle: t,
                vertices: vertices.len(),
            });
        }
        Ok(Mesh::new_unchecked(vertices, triangles))
    }

    /// A mesh from data already known to be valid (indices in range, finite coordinates).
    pub(crate) fn new_unchecked(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Mesh {
        Mesh {
            vertices,
            triangles,
            adjacency: OnceLock::new(),
            bvh: OnceLock::new(),
        }
    }

    /// The shared vertices.
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The triangles, as indices into [`Mesh::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// True when the mesh has no triangles.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The three corner points of triangle `t`.
    #[inline]
    pub fn corners_of(&self, t: usize) -> [DVec3; 3] {
        let [a, b, c] = self.triangles[t];
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// The facet adjacency, built on first use and cached.
    pub fn adjacency(&self) -> &Adjacency {
        self.adjacency
            .get_or_init(|| Adjacency::build(&self.triangles, self.vertices.len()))
    }

    /// The bounding-volume hierarchy over the triangles, built on first use and cached.
    pub fn bvh(&self) -> &Bvh {
        self.bvh.get_or_init(|| Bvh::build(self))
    }

    /// The BVH if it has already been built.
    pub fn bvh_if_built(&self) -> Option<&Bvh> {
        self.bvh.get()
    }

    /// Total area: the sum of the triangles' areas (half the cross-product lengths).
    pub fn area(&self) -> f64 {
        (0..self.triangles.len())
            .map(|t| {
                let [a, b, c] = self.corners_of(t);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum()
    }

    /// The axis-aligned bounding box of the vertices used by triangles (None when empty).
    pub fn bounds(&self) -> Option<Aabb> {
        if self.triangles.is_empty() {
            return None;
        }
        let mut b = Aabb::EMPTY;
        for t in &self.triangles {
            for &i in t {
                b.grow(self.vertices[i as usize]);
            }
        }
        Some(b)
    }

    /// The boundary as closed polylines: the loops of edges that have a single adjacent facet.
    pub fn boundary(&self) -> Vec<Polyline3> {
        self.adjacency()
            .boundary_loops(&self.triangles, &self.vertices)
    }

    /// The same mesh with every vertex mapped by `f` (caches dropped).
    pub fn map_vertices(&self, f: impl Fn(DVec3) -> DVec3) -> Result<Mesh, MeshError> {
        Mesh::new(
            self.vertices.iter().map(|&v| f(v)).collect(),
            self.triangles.clone(),
        )
    }

    /// The mesh under an affine map (move, rotate, scale, mirror). A map that reverses
    /// orientation (negative determinant, e.g. a mirror) also reverses every triangle's winding,
    /// so normals keep pointing to the same side of the surface.
    pub fn transformed(&self, m: &glam::DMat4) -> Result<Mesh, MeshError> {
        let vertices = self
            .vertices
            .iter()
            .map(|&v| m.transform_point3(v))
            .collect();
        let triangles = if m.determinant() < 0.0 {
            self.triangles.iter().map(|t| [t[0], t[2], t[1]]).collect()
        } else {
            self.triangles.clone()
        };
        Mesh::new(vertices, triangles)
    }

    /// Each undirected edge once, as vertex index pairs (lower index first), sorted — for
    /// wireframe output.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        let mut e: Vec<[u32; 2]> = self
            .triangles
            .iter()
            .flat_map(|t| {
                (0..3).map(move |i| {
                    let (a, b) = (t[i], t[(i + 1) % 3]);
                    [a.min(b), a.max(b)]
                })
            })
            .collect();
        e.sort_unstable();
        e.dedup();
        e
    }

    /// Mesh with the triangles of `other` appended (vertices not merged).
    pub fn append(&self, other: &Mesh) -> Mesh {
        let off = self.vertices.len() as u32;
        let mut vertices = self.vertices.clone();
        vertices.extend_from_slice(&other.vertices);
        let mut triangles = self.triangles.clone();
        triangles.extend(other.triangles.iter().map(|t| t.map(|i| i + off)));
        Mesh::new_unchecked(vertices, triangles)
    }
}
