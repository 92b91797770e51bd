//! Plane section of a mesh, chained into polylines.
//!
//! Each vertex is classified once by the sign of `n·(v − p)`; a vertex exactly on the plane
//! counts as positive (a symbolic shift of the plane by an infinitesimal along −n). With that
//! single consistent rule every triangle has 0 or 2 sign-changing edges, so the section is a
//! clean 1-manifold on a manifold mesh: a plane through vertices gives the vertices (every edge
//! crossing that ends at an on-plane vertex is keyed as that vertex), a plane along an edge
//! gives that edge once (only from the triangle on the negative side), a triangle lying in the
//! plane gives nothing, and no piece is duplicated. Crossing points are computed from the edge's
//! vertices in coordinate order, so both triangles of an edge produce the same point bit for bit, and
//! chaining is by these keys (paper 001 step 5, the line through vertices or along edges).

use super::chain::{chain_keyed, cmp_point, Polyline3, Segment};
use super::{Mesh, MeshError};
use glam::DVec3;
use rayon::prelude::*;

#[inline]
fn vertex_key(v: u32) -> u128 {
    (((v as u64) << 32) | v as u64) as u128
}

/// The section of `mesh` by the plane through `point` with normal `normal` (need not be unit).
pub fn section(mesh: &Mesh, point: DVec3, normal: DVec3) -> Result<Vec<Polyline3>, MeshError> {
    Ok(section_edges(mesh, point, normal)?
        .into_iter()
        .map(|c| c.0)
        .collect())
}

/// A section polyline with, for each of its points, the mesh edge it lies on (see
/// [`section_edges`]).
pub type EdgedPolyline = (Polyline3, Vec<Option<[DVec3; 2]>>);

/// [`section`] with, for each point of each polyline, the two vertices of the mesh edge it lies
/// on (None for a vertex on the plane): their sides of the plane bracket the true crossing.
pub fn section_edges(
    mesh: &Mesh,
    point: DVec3,
    normal: DVec3,
) -> Result<Vec<EdgedPolyline>, MeshError> {
    let len = normal.length();
    if !(len > 0.0 && len.is_finite()) {
        return Err(MeshError::BadParameter {
            parameter: "plane normal length",
            limit: "finite and > 0",
            value: len,
        });
    }
    if !point.is_finite() {
        return Err(MeshError::Invalid("plane point must be finite".into()));
    }
    let n = normal / len;
    let verts = mesh.vertices();
    let dist = |v: u32| n.dot(verts[v as usize] - point);
    let tris = mesh.triangles();

    let seg_of = |t: u32| -> Option<Segment> {
        let tri = tris[t as usize];
        let d = [dist(tri[0]), dist(tri[1]), dist(tri[2])];
        let neg = [d[0] < 0.0, d[1] < 0.0, d[2] < 0.0];
        if neg[0] == neg[1] && neg[1] == neg[2] {
            return None;
        }
        let mut keys = [0u128; 2];
        let mut pts = [DVec3::ZERO; 2];
        let mut k = 0;
        for i in 0..3 {
            let j = (i + 1) % 3;
            if neg[i] != neg[j] {
                // Interpolate from the lexicographically smaller end so the point depends on
                // the edge's coordinates only (not on vertex numbering or triangle order).
                let first = cmp_point(verts[tri[i] as usize], verts[tri[j] as usize])
                    .then(tri[i].cmp(&tri[j]))
                    .is_lt();
                let (a, b, da, db) = if first {
                    (tri[i], tri[j], d[i], d[j])
                } else {
                    (tri[j], tri[i], d[j], d[i])
                };
                let (key, p) = if da == 0.0 {
                    (vertex_key(a), verts[a as usize])
                } else if db == 0.0 {
                    (vertex_key(b), verts[b as usize])
                } else {
                    let va = verts[a as usize];
                    let vb = verts[b as usize];
                    let s = da / (da - db);
                    ((((a as u64) << 32) | b as u64) as u128, va + (vb - va) * s)
                };
                keys[k] = key;
                pts[k] = p;
                k += 1;
            }
        }
        Some(Segment { keys, points: pts })
    };

    let segments: Vec<Segment> = if let Some(bvh) = mesh.bvh_if_built() {
        let mut out = Vec::new();
        bvh.query_plane(n, n.dot(point), |t| {
            if let Some(s) = seg_of(t) {
                out.push(s)
            }
        });
        out
    } else {
        // One pass classifying every vertex, then a scan of the triangles over those bits.
        let neg: Vec<bool> = verts
            .par_iter()
            .with_min_len(1 << 14)
            .map(|&v| n.dot(v - point) < 0.0)
            .collect();
        tris.par_iter()
            .enumerate()
            .with_min_len(1 << 14)
            .filter_map(|(t, tri)| {
                let a = neg[tri[0] as usize];
                if a == neg[tri[1] as usize] && a == neg[tri[2] as usize] {
                    None
                } else {
                    seg_of(t as u32)
                }
            })
            .collect()
    };
    let edge = |k: u128| {
        let (a, b) = ((k >> 32) as u32, k as u32);
        (a != b).then(|| [verts[a as usize], verts[b as usize]])
    };
    Ok(chain_keyed(segments)
        .into_iter()
        .map(|(c, keys)| (c, keys.into_iter().map(edge).collect()))
        .collect())
}
