//! Coplanar planar regions overlap in a region, not a curve: their intersection is returned as
//! that region's boundary loops (as OCCT's section of coplanar faces gives the common part's
//! edges), each closed and counter-clockwise about the first region's normal.
//!
//! Each region's edges are split where they cross the other's (one computed point, shared by
//! both edges, so the pieces chain exactly); a piece of one boundary lies on the overlap's
//! boundary when its middle is inside the other region. Where the boundaries run together, the
//! piece is kept once (from the first region) when both regions lie on the same side of it, and
//! dropped when they lie on opposite sides (they only touch there).

use super::hits::{point_in_polygon, FacetLocation};
use super::kinds::PlaneRegion;
use crate::geom::frame::arbitrary_axis;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

/// The overlap of two regions when they are coplanar (within `tol`), None otherwise.
pub(crate) fn coplanar_overlap(
    p: &PlaneRegion,
    q: &PlaneRegion,
    tol: f64,
) -> Option<Vec<Polyline3>> {
    let n = p.normal;
    if n.cross(q.normal).length() > 1e-12
        || q.boundary
            .iter()
            .any(|b| n.dot(*b - p.boundary[0]).abs() > tol)
    {
        return None;
    }
    let a = p.boundary.clone();
    let mut b = q.boundary.clone();
    if q.normal.dot(n) < 0.0 {
        b.reverse();
    }
    let (x, y) = arbitrary_axis(n);
    let o = a[0];
    let to2 = |v: DVec3| DVec2::new((v - o).dot(x), (v - o).dot(y));
    let (a2, b2): (Vec<DVec2>, Vec<DVec2>) = (
        a.iter().map(|v| to2(*v)).collect(),
        b.iter().map(|v| to2(*v)).collect(),
    );
    let (mut split_a, mut split_b) = split_points(&a, &b, &a2, &b2, tol);
    let nb = b.len();
    let mut edges: Vec<(DVec3, DVec3)> = Vec::new();
    let pieces = |poly: &[DVec3], splits: &mut [Vec<(f64, DVec3)>]| {
        let m = poly.len();
        let mut out = Vec::new();
        for (i, s) in splits.iter_mut().enumerate() {
            s.sort_by(|u, v| u.0.total_cmp(&v.0));
            let mut pts = vec![poly[i]];
            pts.extend(s.iter().map(|v| v.1));
            pts.push(poly[(i + 1) % m]);
            pts.dedup();
            for w in pts.windows(2) {
                out.push((w[0], w[1]));
            }
        }
        out
    };
    for (u, v) in pieces(&a, &mut split_a) {
        match point_in_polygon(u.lerp(v, 0.5), &b, n, tol) {
            FacetLocation::Inside => edges.push((u, v)),
            FacetLocation::OnEdge(j) | FacetLocation::OnVertex(j) => {
                // Running along b's boundary: kept when b's edge goes the same way.
                let e = b[(j + 1) % nb] - b[j];
                if e.dot(v - u) > 0.0 {
                    edges.push((u, v));
                }
            }
            FacetLocation::Outside => {}
        }
    }
    for (u, v) in pieces(&b, &mut split_b) {
        if point_in_polygon(u.lerp(v, 0.5), &a, n, tol) == FacetLocation::Inside {
            edges.push((u, v));
        }
    }
    Some(chain_loops(edges))
}

/// Per edge: its split points, (fraction along the edge, point).
type Splits = Vec<Vec<(f64, DVec3)>>;

/// The split points of every edge of both polygons (3D, with their 2D images in the plane):
/// crossings computed once for both edges, and corners of one lying on an edge of the other.
fn split_points(
    a: &[DVec3],
    b: &[DVec3],
    a2: &[DVec2],
    b2: &[DVec2],
    tol: f64,
) -> (Splits, Splits) {
    let mut split_a: Splits = vec![Vec::new(); a.len()];
    let mut split_b: Splits = vec![Vec::new(); b.len()];
    let (na, nb) = (a.len(), b.len());
    for i in 0..na {
        let (p0, p1) = (a2[i], a2[(i + 1) % na]);
        for j in 0..nb {
            let (q0, q1) = (b2[j], b2[(j + 1) % nb]);
            let (dp, dq) = (p1 - p0, q1 - q0);
            let den = dp.perp_dot(dq);
            let scale = dp.length() * dq.length();
            if den.abs() > 1e-12 * scale {
                let w = q0 - p0;
                let s = w.perp_dot(dq) / den;
                let t = w.perp_dot(dp) / den;
                if s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0 {
                    let pt = a[i].lerp(a[(i + 1) % na], s);
                    split_a[i].push((s, pt));
                    split_b[j].push((t, pt));
                }
            }
            // Corners of one lying on an edge of the other (touching or running together).
            let on = |v: DVec2, e0: DVec2, e1: DVec2| {
                let d = e1 - e0;
                let f = (v - e0).dot(d) / d.length_squared();
                let off = (v - e0).perp_dot(d).abs() / d.length();
                (f > 0.0 && f < 1.0 && off <= tol).then_some(f)
            };
            if let Some(f) = on(q0, p0, p1) {
                split_a[i].push((f, b[j]));
            }
            if let Some(f) = on(p0, q0, q1) {
                split_b[j].push((f, a[i]));
            }
        }
    }
    (split_a, split_b)
}

/// Chains directed edges that meet end to start (exactly) into closed loops.
fn chain_loops(edges: Vec<(DVec3, DVec3)>) -> Vec<Polyline3> {
    // Points as their coordinates' bits, with -0 read as +0 so that equal points are one key.
    let key = |p: DVec3| (p + DVec3::ZERO).to_array().map(f64::to_bits);
    let keys: Vec<_> = edges.iter().map(|&(a, b)| (key(a), key(b))).collect();
    crate::geom::mesh::chain_directed(&keys)
        .into_iter()
        .map(|(run, closed)| Polyline3 {
            points: run
                .into_iter()
                .map(|k| DVec3::from_array(k.map(f64::from_bits)))
                .collect(),
            closed,
        })
        .collect()
}
