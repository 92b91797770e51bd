//! Mesh/mesh intersection curves (paper 001's six steps, paper 002's plane-side pre-test).
//!
//! 1. Broad phase: simultaneous descent of both meshes' BVHs (each built once and cached),
//!    keeping triangle pairs whose exact boxes overlap (paper 001 step 2).
//! 2. Plane-side pre-test (paper 002): the corners of Q against P's plane, then P's corners
//!    against Q's plane, all on one side → no intersection. The signs are exact (Shewchuk's
//!    orient3d), with a consistent symbolic tie-break for exact zeros ([`side_perturbed`]).
//! 3. Exact triangle/triangle: the intersection segment's ends are where an edge of one
//!    triangle passes through the other (paper 001 step 3: a point is valid only inside the
//!    facet and on the other facet's edge). An edge `pq` crossing the plane of `rst` passes
//!    through the triangle iff the three signs `side(p, q, r, s)`, `side(p, q, s, t)`,
//!    `side(p, q, t, r)` agree. Every sign is a function of four vertices only, so the two
//!    triangles on either side of an edge agree on whether (and where) the edge is crossed.
//! 4. Each end is keyed by (edge, triangle); its point is computed from the key alone, so
//!    neighbouring pairs share it bit for bit and chaining is exact (paper 001 step 4). Touching
//!    through vertices or along edges and coplanar facets fall under the tie-break (step 5).
//!
//! The output is canonicalised by coordinates ([`chain_segments`]), so it does not depend on
//! triangle or vertex order or on which mesh comes first.

use super::chain::{chain_segments, Polyline3, Segment};
use super::predicates::side_perturbed;
use super::Mesh;
use glam::DVec3;
use rayon::prelude::*;

/// Counts from the phases of [`intersect_meshes_with_stats`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IntersectStats {
    /// Triangle pairs whose boxes overlap.
    pub box_pairs: usize,
    /// Pairs surviving the plane-side pre-test both ways.
    pub plane_pairs: usize,
    /// Pairs that truly intersect (each yields one segment).
    pub intersecting_pairs: usize,
    /// Pairs whose exact test found an odd number of ends (a degenerate touch); skipped.
    pub irregular_pairs: usize,
}

/// The intersection curves of two meshes, chained into polylines (closed where they close).
pub fn intersect_meshes(a: &Mesh, b: &Mesh) -> Vec<Polyline3> {
    intersect_meshes_with_stats(a, b).0
}

const B_FLAG: u64 = 1 << 40;

struct Side<'m> {
    mesh: &'m Mesh,
    /// Added to vertex indices to make global ids (0 for the first mesh, `B_FLAG` for the second).
    id_base: u64,
    /// Distinguishes the mesh in node keys.
    tag: u128,
}

impl Side<'_> {
    #[inline]
    fn tri(&self, t: u32) -> ([DVec3; 3], [u64; 3], [u32; 3]) {
        let v = self.mesh.triangles()[t as usize];
        (
            self.mesh.corners_of(t as usize),
            v.map(|i| i as u64 + self.id_base),
            v,
        )
    }
}

/// Like [`intersect_meshes`], also returning the phase counts.
pub fn intersect_meshes_with_stats(a: &Mesh, b: &Mesh) -> (Vec<Polyline3>, IntersectStats) {
    let (ba, bb) = rayon::join(|| a.bvh(), || b.bvh());
    let pairs = ba.overlapping_pairs(bb);
    let sa = Side {
        mesh: a,
        id_base: 0,
        tag: 0,
    };
    let sb = Side {
        mesh: b,
        id_base: B_FLAG,
        tag: 1,
    };
    #[derive(Default)]
    struct Acc {
        segs: Vec<Segment>,
        plane: usize,
        irregular: usize,
    }
    let acc = pairs
        .par_iter()
        .with_min_len(256)
        .fold(Acc::default, |mut acc, &(ta, tb)| {
            match pair_segment(&sa, ta, &sb, tb) {
                PairResult::Rejected => {}
                PairResult::Miss => acc.plane += 1,
                PairResult::Segment(s) => {
                    acc.plane += 1;
                    acc.segs.push(s)
                }
                PairResult::Irregular => {
                    acc.plane += 1;
                    acc.irregular += 1
                }
            }
            acc
        })
        .reduce(Acc::default, |mut x, mut y| {
            x.segs.append(&mut y.segs);
            x.plane += y.plane;
            x.irregular += y.irregular;
            x
        });
    let stats = IntersectStats {
        box_pairs: pairs.len(),
        plane_pairs: acc.plane,
        intersecting_pairs: acc.segs.len(),
        irregular_pairs: acc.irregular,
    };
    (chain_segments(acc.segs), stats)
}

enum PairResult {
    Rejected,
    Miss,
    Segment(Segment),
    Irregular,
}

/// Node key: which mesh owns the edge, the edge (global ids, ordered), the other's triangle.
#[inline]
fn node_key(edge_owner: u128, e0: u32, e1: u32, tri: u32) -> u128 {
    let (lo, hi) = if e0 < e1 { (e0, e1) } else { (e1, e0) };
    (edge_owner << 96) | ((lo as u128) << 64) | ((hi as u128) << 32) | tri as u128
}

fn pair_segment(sa: &Side, ta: u32, sb: &Side, tb: u32) -> PairResult {
    let (pa, ia, va) = sa.tri(ta);
    let (pb, ib, vb) = sb.tri(tb);
    // Paper 002's pre-test, both ways, with exact signs.
    let sign_b: [i8; 3] = std::array::from_fn(|j| {
        side_perturbed([pa[0], pa[1], pa[2], pb[j]], [ia[0], ia[1], ia[2], ib[j]])
    });
    if sign_b[0] == sign_b[1] && sign_b[1] == sign_b[2] {
        return PairResult::Rejected;
    }
    let sign_a: [i8; 3] = std::array::from_fn(|i| {
        side_perturbed([pb[0], pb[1], pb[2], pa[i]], [ib[0], ib[1], ib[2], ia[i]])
    });
    if sign_a[0] == sign_a[1] && sign_a[1] == sign_a[2] {
        return PairResult::Rejected;
    }
    let mut keys = [0u128; 2];
    let mut pts = [DVec3::ZERO; 2];
    let mut k = 0usize;
    let mut push = |key: u128, p: DVec3, k: &mut usize| {
        if *k < 2 {
            keys[*k] = key;
            pts[*k] = p;
        }
        *k += 1;
    };
    for (edge_side, pe, ie, ve, se, tri_side, pt, it, tt) in [
        (sa, &pa, &ia, &va, &sign_a, sb, &pb, &ib, tb),
        (sb, &pb, &ib, &vb, &sign_b, sa, &pa, &ia, ta),
    ] {
        for i in 0..3 {
            let j = (i + 1) % 3;
            if se[i] == se[j] {
                continue;
            }
            // Put the edge in canonical (global id) order so the test is the same from both
            // triangles that share it.
            let (p, q, ip, iq) = if ie[i] < ie[j] {
                (pe[i], pe[j], ie[i], ie[j])
            } else {
                (pe[j], pe[i], ie[j], ie[i])
            };
            let s0 = side_perturbed([p, q, pt[0], pt[1]], [ip, iq, it[0], it[1]]);
            let s1 = side_perturbed([p, q, pt[1], pt[2]], [ip, iq, it[1], it[2]]);
            let s2 = side_perturbed([p, q, pt[2], pt[0]], [ip, iq, it[2], it[0]]);
            if s0 == s1 && s1 == s2 {
                let key = node_key(edge_side.tag, ve[i], ve[j], tt);
                let _ = tri_side;
                push(key, edge_plane_point(p, q, pt), &mut k);
            }
        }
    }
    match k {
        0 => PairResult::Miss,
        2 => PairResult::Segment(Segment { keys, points: pts }),
        _ => PairResult::Irregular,
    }
}

/// Where the edge `p q` (in canonical order) meets the plane of triangle `t`; computed from
/// these arguments only, so every pair that finds this crossing gets the same bits.
#[inline]
fn edge_plane_point(p: DVec3, q: DVec3, t: &[DVec3; 3]) -> DVec3 {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let dp = n.dot(p - t[0]);
    let dq = n.dot(q - t[0]);
    let den = dp - dq;
    let s = if den != 0.0 {
        (dp / den).clamp(0.0, 1.0)
    } else {
        0.5
    };
    let x = p + (q - p) * s;
    if x.is_finite() {
        x
    } else {
        (p + q) * 0.5
    }
}
