//! Trimming a discrete surface by another (paper 001, "split at once").
//!
//! 1. The intersection of the surface with the cutter gives, per crossed facet, the cut
//!    segments; their ends lie on the facet's edges or inside it (exact keys, shared points).
//! 2. Each crossed facet is split at once: its boundary (corners plus the cut points on its
//!    edges, in order) and the cut segments form a planar graph whose faces (traced by the
//!    half-edge rule "turn as far clockwise as possible", in the facet's plane) are the new
//!    facets, each ear-clipped into triangles. A facet crossed several times simply has more
//!    faces, which replaces the paper's successive halving. Dangling cut ends are pruned.
//! 3. Auto search: flood fill over the facet adjacency from the facet nearest the keep point,
//!    never across a cut edge (paper 001: walk adjacent facets of the same class, then the
//!    untouched facets). The facets reached form the kept part; the rest the other part.
//!
//! Where the cutter coincides with the surface over a region (exactly coplanar overlapping
//! facets), the cut runs along that region's boundary ([`super::coplanar`]), so the region
//! comes off whole; stretches of that boundary lying along edges of the surface make those
//! edges cut edges ([`along`]).
//!
//! Cut points are vertices shared by the facets on both sides, so the two parts share the
//! discrete cut edge exactly (same coordinates bit for bit).

mod along;
mod nodes;
mod split;

use super::adjacency::edge_key;
use super::intersect::{merge_keys_by_point, pieces_and_pairs};
use super::{Mesh, MeshError};
use glam::DVec3;
use nodes::CutNodes;
use std::collections::{BTreeSet, HashMap, HashSet};

/// Twice a triangle's area over its longest edge squared below which it is a roundoff sliver.
const SLIVER: f64 = 1e-12;

/// Relative distance (to a facet's size) within which a cut point is taken to be on a vertex or
/// an edge of the facet.
const SNAP: f64 = 1e-12;

/// The two parts of a trimmed surface.
#[derive(Debug, Clone)]
pub struct Trimmed {
    /// The part containing the facet nearest the keep point.
    pub kept: Mesh,
    /// Everything else (empty when the cut does not separate the surface).
    pub removed: Mesh,
    /// The number of facets that were split.
    pub split_facets: usize,
}

/// Trims `mesh` by `cutter`, keeping the side of the cut that contains the facet nearest
/// `keep_point`.
pub fn trim(mesh: &Mesh, cutter: &Mesh, keep_point: DVec3) -> Result<Trimmed, MeshError> {
    if !keep_point.is_finite() {
        return Err(MeshError::Invalid(
            "keep-point must have finite coordinates".into(),
        ));
    }
    if mesh.is_empty() {
        return Err(MeshError::Invalid("cannot trim an empty mesh".into()));
    }
    let (mut pieces, _, pairs) = pieces_and_pairs(mesh, cutter);
    // Where the cutter coincides with the surface, the cut runs along the region's boundary,
    // stretches lying on the surface's edges included.
    pieces.extend(super::coplanar::coincident_pieces(mesh, cutter, &pairs));
    if !pairs.is_empty() {
        let loops = super::coplanar::coincident_loops(mesh, cutter, &pairs);
        pieces.extend(along::along_edge_pieces(mesh, &loops));
    }
    {
        let segs: Vec<_> = pieces.iter().map(|p| p.seg).collect();
        let merged = merge_keys_by_point(segs);
        for (p, s) in pieces.iter_mut().zip(merged) {
            p.seg = s;
        }
    }
    let cut = CutNodes::build(mesh, &pieces);
    let (out, cut_edges, split_facets) = split_crossed(mesh, cut);
    let keep = flood_fill(&out, &cut_edges, keep_point);
    Ok(Trimmed {
        kept: part(&out, &keep, true),
        removed: part(&out, &keep, false),
        split_facets,
    })
}

/// The mesh with every crossed facet (and every facet with a cut node on one of its edges)
/// split along the cut, the cut edges, and the number of facets split.
fn split_crossed(mesh: &Mesh, cut: CutNodes) -> (Mesh, HashSet<u64>, usize) {
    let CutNodes {
        vertices,
        ids_of,
        by_facet,
        edge_nodes,
    } = cut;
    let mut to_split: BTreeSet<u32> = by_facet.keys().copied().collect();
    for (t, tri) in mesh.triangles().iter().enumerate() {
        if (0..3).any(|k| edge_nodes.contains_key(&edge_key(tri[k], tri[(k + 1) % 3]))) {
            to_split.insert(t as u32);
        }
    }
    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(mesh.len() + to_split.len() * 4);
    for (t, tri) in mesh.triangles().iter().enumerate() {
        if !to_split.contains(&(t as u32)) {
            triangles.push(*tri);
        }
    }
    let mut cut_edges: HashSet<u64> = HashSet::new();
    for &t in &to_split {
        let segs: Vec<[u32; 2]> = by_facet
            .get(&t)
            .map(|l| l.iter().map(|&i| ids_of[i]).collect())
            .unwrap_or_default();
        // Which cut vertices sit on which edge of this facet.
        let tri = mesh.triangles()[t as usize];
        let on_edge: [Vec<u32>; 3] = std::array::from_fn(|k| {
            let mut l = edge_nodes
                .get(&edge_key(tri[k], tri[(k + 1) % 3]))
                .cloned()
                .unwrap_or_default();
            l.retain(|id| !tri.contains(id));
            l
        });
        let segs = nodes::dissolve_straight(&vertices, tri, &on_edge, segs);
        for s in &segs {
            cut_edges.insert(edge_key(s[0], s[1]));
        }
        split::split_facet(&vertices, tri, on_edge, &segs, &mut triangles);
    }
    let n = to_split.len();
    (Mesh::new_unchecked(vertices, triangles), cut_edges, n)
}

/// Which facets are reached from the one nearest `keep_point` without crossing a cut edge.
/// Every edge that is not a cut edge is crossed, non-manifold ones included (all the facets
/// sharing an edge are reached through it), so a part joined to the rest only along such an
/// edge stays with the side it is joined to.
fn flood_fill(out: &Mesh, cut_edges: &HashSet<u64>, keep_point: DVec3) -> Vec<bool> {
    let seed = out
        .bvh()
        .nearest(keep_point, |t| {
            let [a, b, c] = out.corners_of(t as usize);
            closest_on_triangle(keep_point, a, b, c).distance_squared(keep_point)
        })
        .map(|(t, _)| t as usize)
        .unwrap_or(0);
    let mut by_edge: HashMap<u64, Vec<u32>> = HashMap::new();
    for (t, tri) in out.triangles().iter().enumerate() {
        for i in 0..3 {
            by_edge
                .entry(edge_key(tri[i], tri[(i + 1) % 3]))
                .or_default()
                .push(t as u32);
        }
    }
    let mut keep = vec![false; out.len()];
    if out.is_empty() {
        return keep;
    }
    let mut stack = vec![seed];
    keep[seed] = true;
    while let Some(t) = stack.pop() {
        let tri = out.triangles()[t];
        for i in 0..3 {
            let ek = edge_key(tri[i], tri[(i + 1) % 3]);
            if cut_edges.contains(&ek) {
                continue;
            }
            for &n in &by_edge[&ek] {
                if !keep[n as usize] {
                    keep[n as usize] = true;
                    stack.push(n as usize);
                }
            }
        }
    }
    keep
}

/// The facets on one side of the fill (`want`), compacted. Roundoff slivers (three cut points
/// collinear but for the last bits) carry no area and no connectivity the fill still needs:
/// they go.
fn part(out: &Mesh, keep: &[bool], want: bool) -> Mesh {
    let sound = |t: &[u32; 3]| {
        let [a, b, c] = t.map(|i| out.vertices()[i as usize]);
        let longest = (b - a)
            .length_squared()
            .max((c - b).length_squared())
            .max((a - c).length_squared());
        (b - a).cross(c - a).length() > SLIVER * longest
    };
    let tris: Vec<[u32; 3]> = out
        .triangles()
        .iter()
        .zip(keep)
        .filter(|(t, &k)| k == want && sound(t))
        .map(|(t, _)| *t)
        .collect();
    let (v, t) = super::compact_vertices(out.vertices(), tris);
    Mesh::new_unchecked(v, t)
}

/// The point of triangle `abc` closest to `p` (Ericson, Real-Time Collision Detection §5.1.5).
pub(crate) fn closest_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let ab = b - a;
    let ac = c - a;
    let ap = p - a;
    let d1 = ab.dot(ap);
    let d2 = ac.dot(ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let d3 = ab.dot(bp);
    let d4 = ac.dot(bp);
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let d5 = ab.dot(cp);
    let d6 = ac.dot(cp);
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let den = va + vb + vc;
    if den == 0.0 {
        return a;
    }
    a + ab * (vb / den) + ac * (vc / den)
}
