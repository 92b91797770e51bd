//! Where two meshes coincide over a region (exactly coplanar facets overlapping: two copies of a
//! mesh, two pieces of one planar region, two cylinder meshes sharing their facet strips), their
//! intersection is that region, not a curve; the symbolic tie-break of [`super::intersect`]
//! pushes such facets apart and sees nothing there. This returns the region's boundary loops.
//!
//! Every exactly coplanar pair (Shewchuk's orient3d zero for all three corners) gives its common
//! convex piece: corners of either triangle inside or on the other, and the proper crossings of
//! their edges. A crossing is computed from its two edges alone (endpoints in a fixed order,
//! projected along the edges' own plane normal), so every piece that meets it gets the same
//! bits. Pieces are wound as their triangle of `a`; an edge shared by two pieces appears once
//! each way and cancels, and the edges left are the region's boundary, chained into loops.

use super::chain::{chain_segments, cmp_point, Polyline3, Segment};
use super::intersect::Piece;
use super::Mesh;
use glam::{DVec2, DVec3};
use rayon::prelude::*;
use robust::{orient2d, orient3d, Coord, Coord3D};
use std::collections::HashMap;

fn c3(p: DVec3) -> Coord3D<f64> {
    Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    }
}

/// The 2D image dropping the coordinate `k` (exact: coordinates are copied, not combined).
fn drop_axis(p: DVec3, k: usize) -> Coord<f64> {
    match k {
        0 => Coord { x: p.y, y: p.z },
        1 => Coord { x: p.z, y: p.x },
        _ => Coord { x: p.x, y: p.y },
    }
}

fn dominant(n: DVec3) -> usize {
    let a = n.abs();
    if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    }
}

/// A point of a common piece and the edge of its facet of `a` it lies on (vertex indices; None
/// for a corner or an interior point).
type Corner = (DVec3, Option<(u32, u32)>);

/// The boundary of the coincident regions as directed edges, each with the facet of `a` it
/// crosses, from the exactly coplanar triangle pairs.
fn boundary_edges(a: &Mesh, b: &Mesh, pairs: &[(u32, u32)]) -> Vec<(u32, Corner, Corner)> {
    let pieces: Vec<(u32, Vec<Corner>)> = pairs
        .par_iter()
        .with_min_len(256)
        .filter_map(|&(ta, tb)| {
            let (pa, pb) = (a.corners_of(ta as usize), b.corners_of(tb as usize));
            let piece = common_piece(&pa, &pb, a.triangles()[ta as usize]);
            (piece.len() >= 3).then_some((ta, piece))
        })
        .collect();
    // Directed edges; one each way cancels.
    let key = |p: DVec3| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()];
    let mut count: HashMap<([u64; 3], [u64; 3]), i32> = HashMap::new();
    for (_, piece) in &pieces {
        for i in 0..piece.len() {
            let (p, q) = (piece[i].0, piece[(i + 1) % piece.len()].0);
            *count.entry((key(p), key(q))).or_default() += 1;
            *count.entry((key(q), key(p))).or_default() -= 1;
        }
    }
    let mut out = Vec::new();
    for (ta, piece) in &pieces {
        for i in 0..piece.len() {
            let (p, q) = (piece[i], piece[(i + 1) % piece.len()]);
            if count.get(&(key(p.0), key(q.0))).copied().unwrap_or(0) > 0 {
                out.push((*ta, p, q));
            }
        }
    }
    out
}

/// The boundary loops of the regions where `a` and `b` coincide, from their exactly coplanar
/// triangle pairs.
pub(crate) fn coincident_loops(a: &Mesh, b: &Mesh, pairs: &[(u32, u32)]) -> Vec<Polyline3> {
    let mut ids: HashMap<[u64; 3], u128> = HashMap::new();
    let mut id = |p: DVec3| {
        let n = ids.len() as u128;
        *ids.entry([p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
            .or_insert(n)
    };
    let segs = boundary_edges(a, b, pairs)
        .into_iter()
        .map(|(_, p, q)| Segment {
            keys: [id(p.0), id(q.0)],
            points: [p.0, q.0],
        })
        .collect();
    chain_segments(segs)
}

/// The boundary of the coincident regions as cut pieces for a trim of `a`: keyed by point (in
/// a key space of their own), with the edges of `a` their ends lie on. Boundary edges running
/// along an edge of `a` are left out (the facets there are not crossed).
pub(crate) fn coincident_pieces(a: &Mesh, b: &Mesh, pairs: &[(u32, u32)]) -> Vec<Piece> {
    let mut ids: HashMap<[u64; 3], u128> = HashMap::new();
    let mut id = |p: DVec3| {
        let n = ids.len() as u128;
        (1u128 << 127)
            | *ids
                .entry([p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                .or_insert(n)
    };
    let mut out = Vec::new();
    for (ta, p, q) in boundary_edges(a, b, pairs) {
        let tri = a.triangles()[ta as usize];
        let on = |c: &Corner, e: (u32, u32)| {
            c.1.is_some_and(|f| f == e)
                || tri
                    .iter()
                    .any(|&w| (w == e.0 || w == e.1) && a.vertices()[w as usize] == c.0)
        };
        let along = (0..3).any(|k| {
            let e = (tri[k], tri[(k + 1) % 3]);
            on(&p, e) && on(&q, e)
        });
        if along {
            continue;
        }
        out.push(Piece {
            ta,
            seg: Segment {
                keys: [id(p.0), id(q.0)],
                points: [p.0, q.0],
            },
            a_edge: [p.1, q.1],
        });
    }
    out
}

/// Whether triangle `ta` of `a` and `tb` of `b` lie in one plane exactly (and are not
/// degenerate).
pub(crate) fn coplanar_pair(a: &Mesh, ta: u32, b: &Mesh, tb: u32) -> bool {
    let (pa, pb) = (a.corners_of(ta as usize), b.corners_of(tb as usize));
    // A cheap float screen first (no square roots): most pairs are far from coplanar.
    let n = (pa[1] - pa[0]).cross(pa[2] - pa[0]);
    let l2 = (pa[1] - pa[0])
        .length_squared()
        .max((pa[2] - pa[0]).length_squared());
    let bound = 1e-18 * n.length_squared() * l2;
    if bound == 0.0 || pb.iter().any(|q| n.dot(*q - pa[0]).powi(2) > bound) {
        return false;
    }
    let (a, b, c) = (c3(pa[0]), c3(pa[1]), c3(pa[2]));
    pb.iter().all(|q| orient3d(a, b, c, c3(*q)) == 0.0)
}

/// The common piece of two coplanar triangles, wound as `pa` (`ia`: its vertex indices), each
/// corner with the edge of `pa` it lies on.
fn common_piece(pa: &[DVec3; 3], pb: &[DVec3; 3], ia: [u32; 3]) -> Vec<Corner> {
    let n = (pa[1] - pa[0]).cross(pa[2] - pa[0]);
    let k = dominant(n);
    let o =
        |u: DVec3, v: DVec3, w: DVec3| orient2d(drop_axis(u, k), drop_axis(v, k), drop_axis(w, k));
    // Orientation of each triangle in the projection (+1 counter-clockwise).
    let (sa, sb) = (
        o(pa[0], pa[1], pa[2]).signum(),
        o(pb[0], pb[1], pb[2]).signum(),
    );
    if sa == 0.0 || sb == 0.0 {
        return Vec::new();
    }
    let inside =
        |t: &[DVec3; 3], s: f64, p: DVec3| (0..3).all(|i| o(t[i], t[(i + 1) % 3], p) * s >= 0.0);
    let edge_of_a = |p: DVec3| {
        (0..3)
            .find(|&i| o(pa[i], pa[(i + 1) % 3], p) == 0.0)
            .map(|i| (ia[i], ia[(i + 1) % 3]))
    };
    let mut pts: Vec<Corner> = Vec::new();
    pts.extend(
        pa.iter()
            .copied()
            .filter(|p| inside(pb, sb, *p))
            .map(|p| (p, None)),
    );
    pts.extend(
        pb.iter()
            .copied()
            .filter(|p| inside(pa, sa, *p))
            .map(|p| (p, edge_of_a(p))),
    );
    for i in 0..3 {
        for j in 0..3 {
            if let Some(x) = crossing((pa[i], pa[(i + 1) % 3]), (pb[j], pb[(j + 1) % 3])) {
                pts.push((x, Some((ia[i], ia[(i + 1) % 3]))));
            }
        }
    }
    pts.sort_by(|p, q| cmp_point(p.0, q.0));
    pts.dedup_by(|p, q| p.0 == q.0);
    if pts.len() < 3 {
        return Vec::new();
    }
    // A convex piece: its corners in angular order about the centroid, in the projection.
    let to2 = |p: DVec3| {
        let c = drop_axis(p, k);
        DVec2::new(c.x, c.y)
    };
    let g = pts.iter().map(|p| to2(p.0)).fold(DVec2::ZERO, |s, p| s + p) / pts.len() as f64;
    let ang = |p: &Corner| {
        let d = to2(p.0) - g;
        d.y.atan2(d.x) * sa
    };
    pts.sort_by(|p, q| ang(p).total_cmp(&ang(q)));
    // No area (touching along an edge or at a corner): nothing in common.
    let m = pts.len();
    let area: f64 = (0..m)
        .map(|i| to2(pts[i].0 - pts[0].0).perp_dot(to2(pts[(i + 1) % m].0 - pts[0].0)))
        .sum();
    if area == 0.0 {
        return Vec::new();
    }
    pts
}

/// The proper crossing of two coplanar segments (strictly inside both), computed from the two
/// segments alone: endpoints in lexicographic order, projected along their own plane's normal.
fn crossing(e: (DVec3, DVec3), f: (DVec3, DVec3)) -> Option<DVec3> {
    let order = |(p, q): (DVec3, DVec3)| {
        if cmp_point(p, q).is_le() {
            (p, q)
        } else {
            (q, p)
        }
    };
    let ((p, q), (u, v)) = (order(e), order(f));
    let k = dominant((q - p).cross(v - u));
    let (p2, q2, u2, v2) = (
        drop_axis(p, k),
        drop_axis(q, k),
        drop_axis(u, k),
        drop_axis(v, k),
    );
    let (op, oq) = (orient2d(u2, v2, p2), orient2d(u2, v2, q2));
    let (ou, ov) = (orient2d(p2, q2, u2), orient2d(p2, q2, v2));
    if op * oq >= 0.0 || ou * ov >= 0.0 {
        return None;
    }
    let s = op / (op - oq);
    Some(p + (q - p) * s)
}
