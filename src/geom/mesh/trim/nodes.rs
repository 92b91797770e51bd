//! The cut nodes of a trim: every end of a cut segment becomes a vertex id — a corner of its
//! facet when it lies there (within roundoff), else a new vertex shared by all the pieces that
//! reach it — together with the edges of the mesh each node lies on.

use super::super::adjacency::edge_key;
use super::super::chain::cmp_point;
use super::super::intersect::Piece;
use super::super::Mesh;
use super::SNAP;
use crate::geom::frame::arbitrary_axis;
use glam::DVec3;
use std::collections::{BTreeMap, HashMap};

/// The cut graph over the mesh's vertices (the originals first, then the new cut nodes).
pub(super) struct CutNodes {
    pub vertices: Vec<DVec3>,
    /// The vertex ids of each piece's two ends.
    pub ids_of: Vec<[u32; 2]>,
    /// The pieces (of non-zero length) crossing each facet.
    pub by_facet: BTreeMap<u32, Vec<usize>>,
    /// The cut nodes lying on each edge of the mesh (by edge key), sorted.
    pub edge_nodes: BTreeMap<u64, Vec<u32>>,
}

/// The largest side of a triangle.
fn facet_size(c: [DVec3; 3]) -> f64 {
    c[0].distance(c[1])
        .max(c[1].distance(c[2]))
        .max(c[2].distance(c[0]))
}

impl CutNodes {
    pub fn build(mesh: &Mesh, pieces: &[Piece]) -> CutNodes {
        let mut vertices: Vec<DVec3> = mesh.vertices().to_vec();
        let key_vertex = corner_keys(mesh, pieces);
        let mut node_id: HashMap<u128, u32> = HashMap::new();
        let mut ids_of: Vec<[u32; 2]> = pieces
            .iter()
            .map(|p| {
                std::array::from_fn(|e| {
                    let key = p.seg.keys[e];
                    match key_vertex.get(&key) {
                        Some(&w) => w,
                        None => *node_id.entry(key).or_insert_with(|| {
                            vertices.push(p.seg.points[e]);
                            (vertices.len() - 1) as u32
                        }),
                    }
                })
            })
            .collect();
        merge_short(mesh, pieces, &vertices, &mut ids_of);
        // The edges of `mesh` each cut node lies on (in the perturbed configuration), gathered
        // from every piece that reaches it: a node found as interior to one facet can be the
        // crossing of that facet's edge seen from its neighbour.
        let mut node_edges: HashMap<u32, Vec<u64>> = HashMap::new();
        let mut add = |id: u32, ek: u64| {
            let l = node_edges.entry(id).or_default();
            if !l.contains(&ek) {
                l.push(ek);
            }
        };
        for (p, ids) in pieces.iter().zip(&ids_of) {
            for (&id, edge) in ids.iter().zip(&p.a_edge) {
                if let Some((u, v)) = *edge {
                    add(id, edge_key(u, v));
                }
            }
        }
        // Group the cut segments by facet (zero-length ones, whose ends merged, drop out).
        let mut by_facet: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
        for (i, p) in pieces.iter().enumerate() {
            if ids_of[i][0] != ids_of[i][1] {
                by_facet.entry(p.ta).or_default().push(i);
            }
        }
        // A node interior to its facet in the perturbed configuration may lie on (or, rounded,
        // just beyond) one of its edges in real coordinates: it is put on that edge, for every
        // facet sharing it, so no face of the split is a zero-area sliver and no T-junction is
        // left.
        for (&t, list) in &by_facet {
            let tri = mesh.triangles()[t as usize];
            for &i in list {
                for id in ids_of[i] {
                    if tri.contains(&id) {
                        continue;
                    }
                    if let Some(k) = edge_holding(&vertices, tri, vertices[id as usize]) {
                        add(id, edge_key(tri[k], tri[(k + 1) % 3]));
                    }
                }
            }
        }
        let mut edge_nodes: BTreeMap<u64, Vec<u32>> = BTreeMap::new();
        for (&id, es) in &node_edges {
            for &e in es {
                edge_nodes.entry(e).or_default().push(id);
            }
        }
        for l in edge_nodes.values_mut() {
            l.sort_unstable();
            l.dedup();
        }
        CutNodes {
            vertices,
            ids_of,
            by_facet,
            edge_nodes,
        }
    }
}

/// The keys of the piece ends that are corners of their facet. An end whose point is a corner —
/// or within roundoff of it (SNAP times the facet's size: a cut meant to pass through the
/// vertex, like a cylinder's vertex at angle π, 1.2e-16 off the plane y = 0) — is that vertex;
/// every end with the same key (after merging equal points) gets the same id.
fn corner_keys(mesh: &Mesh, pieces: &[Piece]) -> HashMap<u128, u32> {
    let vertices = mesh.vertices();
    let mut key_vertex: HashMap<u128, u32> = HashMap::new();
    for p in pieces {
        let tri = mesh.triangles()[p.ta as usize];
        let size = facet_size(tri.map(|w| vertices[w as usize]));
        for e in 0..2 {
            let pt = p.seg.points[e];
            if let Some(&w) = tri.iter().find(|&&w| {
                let v = vertices[w as usize];
                cmp_point(v, pt).is_eq() || v.distance(pt) <= SNAP * size
            }) {
                key_vertex.entry(p.seg.keys[e]).or_insert(w);
            }
        }
    }
    key_vertex
}

/// A segment shorter than roundoff (two crossings the perturbation tells apart, like a cutter
/// edge meeting a facet edge) is one node: its ends are merged, a mesh vertex winning, else the
/// smaller id.
fn merge_short(mesh: &Mesh, pieces: &[Piece], vertices: &[DVec3], ids_of: &mut [[u32; 2]]) {
    let mut rep: HashMap<u32, u32> = HashMap::new();
    fn find(rep: &HashMap<u32, u32>, mut x: u32) -> u32 {
        while let Some(&y) = rep.get(&x) {
            x = y;
        }
        x
    }
    for (p, ids) in pieces.iter().zip(ids_of.iter()) {
        let size = facet_size(mesh.corners_of(p.ta as usize));
        let (a, b) = (find(&rep, ids[0]), find(&rep, ids[1]));
        if a != b && vertices[a as usize].distance(vertices[b as usize]) <= SNAP * size {
            rep.insert(a.max(b), a.min(b));
        }
    }
    for ids in ids_of.iter_mut() {
        *ids = ids.map(|i| find(&rep, i));
    }
}

/// The edge `k` (from corner k to k + 1) of `tri` on which, or beyond which, `p` lies in the
/// facet's plane (exact 2D orientation in the facet's frame), when `p` projects between the
/// edge's ends; None when `p` is strictly inside.
fn edge_holding(verts: &[DVec3], tri: [u32; 3], p: DVec3) -> Option<usize> {
    use robust::{orient2d, Coord};
    let c = tri.map(|i| verts[i as usize]);
    let normal = (c[1] - c[0]).cross(c[2] - c[0]);
    if normal.length_squared() == 0.0 {
        return None;
    }
    let (x, y) = arbitrary_axis(normal);
    let to2 = |q: DVec3| Coord {
        x: (q - c[0]).dot(x),
        y: (q - c[0]).dot(y),
    };
    let (c2, q) = (c.map(to2), to2(p));
    let whole = orient2d(c2[0], c2[1], c2[2]);
    let mut best: Option<(f64, usize)> = None;
    for k in 0..3 {
        let (a, b) = (c[k], c[(k + 1) % 3]);
        let f = (p - a).dot(b - a) / (b - a).length_squared();
        if !(f > 0.0 && f < 1.0) {
            continue;
        }
        // Signed so that inside is positive; within SNAP of the edge's length counts as on it.
        let o = orient2d(c2[k], c2[(k + 1) % 3], q) * whole.signum();
        if o <= SNAP * (b - a).length_squared() && best.is_none_or(|(v, _)| o < v) {
            best = Some((o, k));
        }
    }
    best.map(|(_, k)| k)
}

/// Removes the cut nodes inside the facet (on none of its edges, not a corner) where the cut
/// runs straight to within roundoff — a planar cutter's edges crossing the facet — joining
/// their two segments: such a node would leave a zero-area face or force a sliver ear.
pub(super) fn dissolve_straight(
    verts: &[DVec3],
    tri: [u32; 3],
    on_edge: &[Vec<u32>; 3],
    mut segs: Vec<[u32; 2]>,
) -> Vec<[u32; 2]> {
    let c = tri.map(|i| verts[i as usize]);
    let size = c[0]
        .distance(c[1])
        .max(c[1].distance(c[2]))
        .max(c[2].distance(c[0]));
    loop {
        let mut deg: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
        for (i, s) in segs.iter().enumerate() {
            for &v in s {
                deg.entry(v).or_default().push(i);
            }
        }
        let found = deg.iter().find_map(|(&b, l)| {
            if l.len() != 2 || tri.contains(&b) || on_edge.iter().any(|e| e.contains(&b)) {
                return None;
            }
            let other = |s: [u32; 2]| if s[0] == b { s[1] } else { s[0] };
            let (a, cc) = (other(segs[l[0]]), other(segs[l[1]]));
            if a == cc {
                return None;
            }
            let (pa, pb, pc) = (verts[a as usize], verts[b as usize], verts[cc as usize]);
            let off = (pc - pa).cross(pb - pa).length() / pc.distance(pa).max(f64::MIN_POSITIVE);
            // Only between its neighbours (a straight run, not a fold back).
            let between = (pb - pa).dot(pc - pa) > 0.0 && (pb - pc).dot(pa - pc) > 0.0;
            (between && off <= SNAP * size).then_some((l[0], l[1], a, cc))
        });
        let Some((i, j, a, cc)) = found else {
            return segs;
        };
        segs[i] = [a, cc];
        segs.remove(j);
    }
}
