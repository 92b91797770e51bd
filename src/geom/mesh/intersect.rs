//! Mesh/mesh intersection curves (paper 001's six steps, paper 002's plane-side pre-test).
//!
//! 1. Broad phase: simultaneous descent of both meshes' BVHs (each built once and cached),
//!    keeping triangle pairs whose exact boxes overlap (paper 001 step 2).
//! 2. Plane-side pre-test (paper 002): the corners of Q against P's plane, then P's corners
//!    against Q's plane, all on one side → no intersection. The signs are exact (Shewchuk's
//!    orient3d); exact zeros (touching, coplanar) are decided by a symbolic translation of one
//!    mesh ([`side_sos`]), so every decision agrees with one real perturbed configuration.
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
//! Where the meshes coincide (exactly coplanar facets overlapping: a region, not a curve) the
//! translation tie-break pushes them apart; the region's boundary loops are added by
//! [`super::coplanar`]. Known limit: where coincident facets have collinear shared edges the
//! tie-break cannot separate parallel edges and stray fragments may come with the loops.
//!
//! The output is canonicalised by coordinates ([`chain_segments`]), so it does not depend on
//! triangle or vertex order or on which mesh comes first.

use super::chain::{chain_keyed, chain_segments, cmp_point, Polyline3, Segment};
use super::predicates::side_sos;
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
    /// Whether this mesh is the symbolically translated one.
    moving: bool,
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
    let (pieces, stats, pairs) = pieces_and_pairs(a, b);
    let segs = pieces.into_iter().map(|p| p.seg).collect();
    // Crossings through a vertex or an edge/edge touch are found from several (edge, triangle)
    // keys with the same exact point; they are one node of the curve.
    let mut out = chain_segments(merge_keys_by_point(segs));
    // Where the meshes coincide: the region's boundary loops.
    out.extend(super::coplanar::coincident_loops(a, b, &pairs));
    (out, stats)
}

/// An intersection polyline with, for each point, the mesh edge it lies on: `(on_b, [v0, v1])`,
/// whether the edge is the second mesh's and its vertices (None where several keys meet at one
/// point, a touch through a vertex or edge). The vertices lie on the edge owner's surface on
/// opposite sides of the other mesh, so they bracket the true crossing.
pub type PairEdgedPolyline = (Polyline3, Vec<Option<(bool, [DVec3; 2])>>);

/// [`intersect_meshes`] with, for each point, the mesh edge it lies on.
pub fn intersect_meshes_edges(a: &Mesh, b: &Mesh) -> Vec<PairEdgedPolyline> {
    let (pieces, _, pairs) = pieces_and_pairs(a, b);
    let segs = pieces.into_iter().map(|p| p.seg).collect();
    let (segs, canon) = merge_keys_noting(segs);
    // A key standing for several (a touch through a vertex or an edge) names no one edge.
    let merged: std::collections::HashSet<u128> = canon.into_values().collect();
    let edge_of = |key: u128| {
        if !merged.is_empty() && merged.contains(&key) {
            return None;
        }
        let on_b = (key >> 96) == 1;
        let m = if on_b { b } else { a };
        let v = m.vertices();
        let (lo, hi) = ((key >> 64) as u32 as usize, (key >> 32) as u32 as usize);
        Some((on_b, [*v.get(lo)?, *v.get(hi)?]))
    };
    let mut out: Vec<PairEdgedPolyline> = chain_keyed(segs)
        .into_iter()
        .map(|(c, keys)| {
            let e = keys.into_iter().map(edge_of).collect();
            (c, e)
        })
        .collect();
    out.extend(
        super::coplanar::coincident_loops(a, b, &pairs)
            .into_iter()
            .map(|c| (c, Vec::new())),
    );
    out
}

/// One intersecting triangle pair's segment, with where its ends lie on `a`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Piece {
    pub ta: u32,
    pub seg: Segment,
    /// For each end: the edge of `a` (vertex indices) it lies on, or None inside triangle `ta`.
    pub a_edge: [Option<(u32, u32)>; 2],
}

/// The segments of every truly intersecting triangle pair (before chaining), and the exactly
/// coplanar triangle pairs.
#[allow(clippy::type_complexity)]
pub(crate) fn pieces_and_pairs(
    a: &Mesh,
    b: &Mesh,
) -> (Vec<Piece>, IntersectStats, Vec<(u32, u32)>) {
    let (ba, bb) = rayon::join(|| a.bvh(), || b.bvh());
    let pairs = ba.overlapping_pairs(bb);
    // A surface coincides with itself everywhere: a region (its boundary, found by the
    // coincident pass), not a curve.
    if a.vertices() == b.vertices() && a.triangles() == b.triangles() {
        let flat = pairs
            .into_iter()
            .filter(|&(ta, tb)| super::coplanar::coplanar_pair(a, ta, b, tb))
            .collect();
        return (Vec::new(), IntersectStats::default(), flat);
    }
    // Which mesh the tie-break translates is chosen from the meshes' contents, not from the
    // argument order, so swapping the arguments cannot change a degenerate decision.
    let a_moves = moving_first(a, b);
    let sa = Side {
        mesh: a,
        id_base: 0,
        tag: 0,
        moving: a_moves,
    };
    let sb = Side {
        mesh: b,
        id_base: B_FLAG,
        tag: 1,
        moving: !a_moves,
    };
    #[derive(Default)]
    struct Acc {
        segs: Vec<Piece>,
        plane: usize,
        irregular: usize,
        /// Exactly coplanar pairs (the tie-break rejects them): for the coincident pass.
        flat: Vec<(u32, u32)>,
    }
    let acc = pairs
        .par_iter()
        .with_min_len(256)
        .fold(Acc::default, |mut acc, &(ta, tb)| {
            match pair_segment(&sa, ta, &sb, tb) {
                PairResult::Rejected => {
                    // Checked here, while the corners are in cache.
                    if super::coplanar::coplanar_pair(a, ta, b, tb) {
                        acc.flat.push((ta, tb));
                    }
                }
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
            x.flat.append(&mut y.flat);
            x
        });
    let stats = IntersectStats {
        box_pairs: pairs.len(),
        plane_pairs: acc.plane,
        intersecting_pairs: acc.segs.len(),
        irregular_pairs: acc.irregular,
    };
    let mut segs = acc.segs;
    // Deterministic order whatever the thread scheduling.
    segs.sort_unstable_by_key(|p| (p.ta, p.seg.keys));
    let mut flat = acc.flat;
    flat.sort_unstable();
    (segs, stats, flat)
}

enum PairResult {
    Rejected,
    Miss,
    Segment(Piece),
    Irregular,
}

/// Whether `a` (rather than `b`) is the mesh the tie-break translates: the one whose smallest
/// vertex is larger (then more vertices, then more triangles).
fn moving_first(a: &Mesh, b: &Mesh) -> bool {
    let min = |m: &Mesh| {
        m.vertices()
            .iter()
            .copied()
            .min_by(|p, q| cmp_point(*p, *q))
    };
    let o = match (min(a), min(b)) {
        (Some(x), Some(y)) => cmp_point(x, y),
        _ => std::cmp::Ordering::Equal,
    };
    o.then(a.vertices().len().cmp(&b.vertices().len()))
        .then(a.len().cmp(&b.len()))
        .is_gt()
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
    let (ma, mb) = (sa.moving, sb.moving);
    let sign_b: [i8; 3] = std::array::from_fn(|j| {
        side_sos(
            [pa[0], pa[1], pa[2], pb[j]],
            [ma, ma, ma, mb],
            [ia[0], ia[1], ia[2], ib[j]],
        )
    });
    if sign_b[0] == sign_b[1] && sign_b[1] == sign_b[2] {
        return PairResult::Rejected;
    }
    let sign_a: [i8; 3] = std::array::from_fn(|i| {
        side_sos(
            [pb[0], pb[1], pb[2], pa[i]],
            [mb, mb, mb, ma],
            [ib[0], ib[1], ib[2], ia[i]],
        )
    });
    if sign_a[0] == sign_a[1] && sign_a[1] == sign_a[2] {
        return PairResult::Rejected;
    }
    let mut keys = [0u128; 2];
    let mut pts = [DVec3::ZERO; 2];
    let mut a_edge = [None; 2];
    let mut k = 0usize;
    let mut push = |key: u128, p: DVec3, e: Option<(u32, u32)>, k: &mut usize| {
        if *k < 2 {
            keys[*k] = key;
            pts[*k] = p;
            a_edge[*k] = e;
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
            // Put the edge in coordinate order so the point is the same from both triangles
            // that share it, whatever the vertex numbering.
            let (p, q, ip, iq) = if cmp_point(pe[i], pe[j]).then(ie[i].cmp(&ie[j])).is_lt() {
                (pe[i], pe[j], ie[i], ie[j])
            } else {
                (pe[j], pe[i], ie[j], ie[i])
            };
            let (me, mt) = (edge_side.moving, tri_side.moving);
            let mv = [me, me, mt, mt];
            let s0 = side_sos([p, q, pt[0], pt[1]], mv, [ip, iq, it[0], it[1]]);
            let s1 = side_sos([p, q, pt[1], pt[2]], mv, [ip, iq, it[1], it[2]]);
            let s2 = side_sos([p, q, pt[2], pt[0]], mv, [ip, iq, it[2], it[0]]);
            if s0 == s1 && s1 == s2 {
                let key = node_key(edge_side.tag, ve[i], ve[j], tt);
                let e = (edge_side.tag == 0).then_some((ve[i], ve[j]));
                push(key, edge_plane_point(p, q, pt), e, &mut k);
            }
        }
    }
    match k {
        0 => PairResult::Miss,
        2 => PairResult::Segment(Piece {
            ta,
            seg: Segment { keys, points: pts },
            a_edge,
        }),
        _ => PairResult::Irregular,
    }
}

/// Where the edge `p q` (in coordinate order) meets the plane of triangle `t`; computed from
/// these arguments only, so every pair that finds this crossing gets the same bits.
#[inline]
fn edge_plane_point(p: DVec3, q: DVec3, t: &[DVec3; 3]) -> DVec3 {
    // Start the triangle at its smallest corner (a rotation keeps the orientation) so the
    // plane is computed the same whatever the stored corner order.
    let k = if cmp_point(t[0], t[1]).is_le() {
        if cmp_point(t[0], t[2]).is_le() {
            0
        } else {
            2
        }
    } else if cmp_point(t[1], t[2]).is_le() {
        1
    } else {
        2
    };
    let t = [t[k], t[(k + 1) % 3], t[(k + 2) % 3]];
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

/// Re-keys segment ends so that ends with bit-identical points share one key.
pub(crate) fn merge_keys_by_point(segs: Vec<Segment>) -> Vec<Segment> {
    merge_keys_noting(segs).0
}

/// [`merge_keys_by_point`] with the keys it replaced, each mapped to the one it now shares.
fn merge_keys_noting(
    mut segs: Vec<Segment>,
) -> (Vec<Segment>, std::collections::HashMap<u128, u128>) {
    let mut ends: Vec<(DVec3, u128)> = segs
        .iter()
        .flat_map(|s| [(s.points[0], s.keys[0]), (s.points[1], s.keys[1])])
        .collect();
    ends.sort_unstable_by(|a, b| cmp_point(a.0, b.0).then(a.1.cmp(&b.1)));
    let mut canon: std::collections::HashMap<u128, u128> = std::collections::HashMap::new();
    let mut i = 0;
    while i < ends.len() {
        let mut j = i + 1;
        while j < ends.len() && cmp_point(ends[j].0, ends[i].0).is_eq() {
            j += 1;
        }
        if ends[j - 1].1 != ends[i].1 {
            for e in &ends[i..j] {
                canon.insert(e.1, ends[i].1);
            }
        }
        i = j;
    }
    if !canon.is_empty() {
        for s in segs.iter_mut() {
            for k in s.keys.iter_mut() {
                if let Some(&c) = canon.get(k) {
                    *k = c;
                }
            }
        }
    }
    (segs, canon)
}
