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

/// The boundary loops of the regions where `a` and `b` coincide, from their box-overlapping
/// triangle pairs.
pub(crate) fn coincident_loops(a: &Mesh, b: &Mesh, pairs: &[(u32, u32)]) -> Vec<Polyline3> {
    let pieces: Vec<Vec<DVec3>> = pairs
        .par_iter()
        .with_min_len(256)
        .filter_map(|&(ta, tb)| {
            let (pa, pb) = (a.corners_of(ta as usize), b.corners_of(tb as usize));
            coplanar(&pa, &pb).then(|| common_piece(&pa, &pb))
        })
        .filter(|p| p.len() >= 3)
        .collect();
    if pieces.is_empty() {
        return Vec::new();
    }
    // Directed edges; one each way cancels.
    let key = |p: DVec3| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()];
    let mut count: HashMap<([u64; 3], [u64; 3]), i32> = HashMap::new();
    for piece in &pieces {
        for i in 0..piece.len() {
            let (p, q) = (piece[i], piece[(i + 1) % piece.len()]);
            *count.entry((key(p), key(q))).or_default() += 1;
            *count.entry((key(q), key(p))).or_default() -= 1;
        }
    }
    let mut ids: HashMap<[u64; 3], u128> = HashMap::new();
    let mut segs = Vec::new();
    for piece in &pieces {
        for i in 0..piece.len() {
            let (p, q) = (piece[i], piece[(i + 1) % piece.len()]);
            if count.get(&(key(p), key(q))).copied().unwrap_or(0) > 0 {
                let n = ids.len() as u128;
                let kp = *ids.entry(key(p)).or_insert(n);
                let n = ids.len() as u128;
                let kq = *ids.entry(key(q)).or_insert(n);
                segs.push(Segment {
                    keys: [kp, kq],
                    points: [p, q],
                });
            }
        }
    }
    chain_segments(segs)
}

/// Whether the triangles lie in one plane exactly (and are not degenerate).
fn coplanar(pa: &[DVec3; 3], pb: &[DVec3; 3]) -> bool {
    // A cheap float screen first: most pairs are far from coplanar.
    let n = (pa[1] - pa[0]).cross(pa[2] - pa[0]);
    let scale = n.length() * (pa[1] - pa[0]).length().max((pa[2] - pa[0]).length());
    if scale == 0.0 || pb.iter().any(|q| n.dot(*q - pa[0]).abs() > 1e-9 * scale) {
        return false;
    }
    let (a, b, c) = (c3(pa[0]), c3(pa[1]), c3(pa[2]));
    pb.iter().all(|q| orient3d(a, b, c, c3(*q)) == 0.0)
}

/// The common piece of two coplanar triangles, wound as `pa`.
fn common_piece(pa: &[DVec3; 3], pb: &[DVec3; 3]) -> Vec<DVec3> {
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
    let mut pts: Vec<DVec3> = Vec::new();
    pts.extend(pa.iter().copied().filter(|p| inside(pb, sb, *p)));
    pts.extend(pb.iter().copied().filter(|p| inside(pa, sa, *p)));
    for i in 0..3 {
        for j in 0..3 {
            if let Some(x) = crossing((pa[i], pa[(i + 1) % 3]), (pb[j], pb[(j + 1) % 3])) {
                pts.push(x);
            }
        }
    }
    pts.sort_by(|p, q| cmp_point(*p, *q));
    pts.dedup();
    if pts.len() < 3 {
        return Vec::new();
    }
    // A convex piece: its corners in angular order about the centroid, in the projection.
    let to2 = |p: DVec3| {
        let c = drop_axis(p, k);
        DVec2::new(c.x, c.y)
    };
    let g = pts.iter().map(|p| to2(*p)).fold(DVec2::ZERO, |s, p| s + p) / pts.len() as f64;
    let ang = |p: &DVec3| {
        let d = to2(*p) - g;
        d.y.atan2(d.x) * sa
    };
    pts.sort_by(|p, q| ang(p).total_cmp(&ang(q)));
    // No area (touching along an edge or at a corner): nothing in common.
    let area: f64 = (0..pts.len())
        .map(|i| to2(pts[i] - pts[0]).perp_dot(to2(pts[(i + 1) % pts.len()] - pts[0])))
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
