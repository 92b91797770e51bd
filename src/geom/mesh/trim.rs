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
//! Cut points are vertices shared by the facets on both sides, so the two parts share the
//! discrete cut edge exactly (same coordinates bit for bit).

use super::adjacency::edge_key;
use super::chain::cmp_point;
use super::intersect::{intersection_pieces, merge_keys_by_point};
use super::{Mesh, MeshError};
use crate::geom::frame::arbitrary_axis;
use glam::{DVec2, DVec3};
use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};

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
    let (mut pieces, _) = intersection_pieces(mesh, cutter);
    {
        let segs: Vec<_> = pieces.iter().map(|p| p.seg).collect();
        let merged = merge_keys_by_point(segs);
        for (p, s) in pieces.iter_mut().zip(merged) {
            p.seg = s;
        }
    }

    // Global vertex ids of the cut points. An end whose point is a corner of its facet — or
    // within roundoff of it (SNAP times the facet's size: a cut meant to pass through the vertex,
    // like a cylinder's vertex at angle π, 1.2e-16 off the plane y = 0) — is that vertex;
    // every end with the same key (after merging equal points) gets the same id.
    let mut vertices: Vec<DVec3> = mesh.vertices().to_vec();
    let mut key_vertex: HashMap<u128, u32> = HashMap::new();
    for p in &pieces {
        let tri = mesh.triangles()[p.ta as usize];
        for e in 0..2 {
            let pt = p.seg.points[e];
            let c = tri.map(|w| vertices[w as usize]);
            let size = c[0]
                .distance(c[1])
                .max(c[1].distance(c[2]))
                .max(c[2].distance(c[0]));
            if let Some(&w) = tri.iter().find(|&&w| {
                let v = vertices[w as usize];
                cmp_point(v, pt).is_eq() || v.distance(pt) <= SNAP * size
            }) {
                key_vertex.entry(p.seg.keys[e]).or_insert(w);
            }
        }
    }
    let mut node_id: HashMap<u128, u32> = HashMap::new();
    // The edges of `mesh` each cut node lies on (in the perturbed configuration), gathered from
    // every piece that reaches it: a node found as interior to one facet can be the crossing of
    // that facet's edge seen from its neighbour.
    let mut node_edges: HashMap<u32, Vec<u64>> = HashMap::new();
    let mut ids_of: Vec<[u32; 2]> = Vec::with_capacity(pieces.len());
    for p in &pieces {
        ids_of.push(std::array::from_fn(|e| {
            let key = p.seg.keys[e];
            match key_vertex.get(&key) {
                Some(&w) => w,
                None => *node_id.entry(key).or_insert_with(|| {
                    vertices.push(p.seg.points[e]);
                    (vertices.len() - 1) as u32
                }),
            }
        }));
    }
    // A segment shorter than roundoff (two crossings the perturbation tells apart, like a
    // cutter edge meeting a facet edge) is one node: its ends are merged, a mesh vertex
    // winning, else the smaller id.
    let mut rep: HashMap<u32, u32> = HashMap::new();
    fn find(rep: &HashMap<u32, u32>, mut x: u32) -> u32 {
        while let Some(&y) = rep.get(&x) {
            x = y;
        }
        x
    }
    for (p, ids) in pieces.iter().zip(&ids_of) {
        let c = mesh.corners_of(p.ta as usize);
        let size = c[0]
            .distance(c[1])
            .max(c[1].distance(c[2]))
            .max(c[2].distance(c[0]));
        let (a, b) = (find(&rep, ids[0]), find(&rep, ids[1]));
        if a != b && vertices[a as usize].distance(vertices[b as usize]) <= SNAP * size {
            rep.insert(a.max(b), a.min(b));
        }
    }
    for ids in ids_of.iter_mut() {
        *ids = ids.map(|i| find(&rep, i));
    }
    for (p, ids) in pieces.iter().zip(&ids_of) {
        for (&id, edge) in ids.iter().zip(&p.a_edge) {
            if let Some((u, v)) = *edge {
                let l = node_edges.entry(id).or_default();
                if !l.contains(&edge_key(u, v)) {
                    l.push(edge_key(u, v));
                }
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
    // facet sharing it, so no face of the split is a zero-area sliver and no T-junction is left.
    for (&t, list) in &by_facet {
        let tri = mesh.triangles()[t as usize];
        for &i in list {
            for id in ids_of[i] {
                if tri.contains(&id) {
                    continue;
                }
                if let Some(k) = edge_holding(&vertices, tri, vertices[id as usize]) {
                    let ek = edge_key(tri[k], tri[(k + 1) % 3]);
                    let l = node_edges.entry(id).or_default();
                    if !l.contains(&ek) {
                        l.push(ek);
                    }
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
    // Facets to split: those crossed, and those with a cut node on one of their edges.
    let mut to_split: BTreeSet<u32> = by_facet.keys().copied().collect();
    for (t, tri) in mesh.triangles().iter().enumerate() {
        if (0..3).any(|k| edge_nodes.contains_key(&edge_key(tri[k], tri[(k + 1) % 3]))) {
            to_split.insert(t as u32);
        }
    }
    let facets: Vec<u32> = to_split.iter().copied().collect();

    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(mesh.len() + facets.len() * 4);
    for (t, tri) in mesh.triangles().iter().enumerate() {
        if !to_split.contains(&(t as u32)) {
            triangles.push(*tri);
        }
    }
    let mut cut_edges: HashSet<u64> = HashSet::new();
    let no_segs = Vec::new();
    for &t in &facets {
        let segs: Vec<[u32; 2]> = by_facet
            .get(&t)
            .unwrap_or(&no_segs)
            .iter()
            .map(|&i| ids_of[i])
            .collect();
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
        let segs = dissolve_straight(&vertices, tri, &on_edge, segs);
        for s in &segs {
            cut_edges.insert(edge_key(s[0], s[1]));
        }
        split_facet(&vertices, tri, on_edge, &segs, &mut triangles);
    }

    let out = Mesh::new_unchecked(vertices, triangles);
    let seed = out
        .bvh()
        .nearest(keep_point, |t| {
            let [a, b, c] = out.corners_of(t as usize);
            closest_on_triangle(keep_point, a, b, c).distance_squared(keep_point)
        })
        .map(|(t, _)| t as usize)
        .unwrap_or(0);
    // Flood fill across every edge that is not a cut edge, non-manifold ones included (all the
    // facets sharing an edge are reached through it), so a part joined to the rest only along
    // such an edge stays with the side it is joined to.
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
    // Roundoff slivers (three cut points collinear but for the last bits) carry no area and
    // no connectivity the fill still needs: they go.
    let sound = |t: &[u32; 3]| {
        let [a, b, c] = t.map(|i| out.vertices()[i as usize]);
        let longest = (b - a)
            .length_squared()
            .max((c - b).length_squared())
            .max((a - c).length_squared());
        (b - a).cross(c - a).length() > SLIVER * longest
    };
    let part = |want: bool| {
        let tris: Vec<[u32; 3]> = out
            .triangles()
            .iter()
            .zip(&keep)
            .filter(|(t, &k)| k == want && sound(t))
            .map(|(t, _)| *t)
            .collect();
        compact(out.vertices(), tris)
    };
    Ok(Trimmed {
        kept: part(true),
        removed: part(false),
        split_facets: facets.len(),
    })
}

fn compact(verts: &[DVec3], tris: Vec<[u32; 3]>) -> Mesh {
    let (v, t) = super::compact_vertices(verts, tris);
    Mesh::new_unchecked(v, t)
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
fn dissolve_straight(
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

/// Splits triangle `tri` by the cut segments `segs` (global vertex ids), with the cut points on
/// its edges in `on_edge`, appending the new triangles.
fn split_facet(
    verts: &[DVec3],
    tri: [u32; 3],
    mut on_edge: [Vec<u32>; 3],
    segs: &[[u32; 2]],
    out: &mut Vec<[u32; 3]>,
) {
    let [a, b, c] = tri.map(|i| verts[i as usize]);
    let normal = (b - a).cross(c - a);
    if normal.length_squared() == 0.0 {
        out.push(tri);
        return;
    }
    let (x, y) = arbitrary_axis(normal);
    let to2 = |p: DVec3| DVec2::new((p - a).dot(x), (p - a).dot(y));
    // The boundary cycle: corners with the cut points of each edge ordered along it.
    let mut cycle = Vec::new();
    for k in 0..3 {
        let (p, q) = (verts[tri[k] as usize], verts[tri[(k + 1) % 3] as usize]);
        let d = q - p;
        on_edge[k].sort_by(|&u, &v| {
            (verts[u as usize] - p)
                .dot(d)
                .total_cmp(&(verts[v as usize] - p).dot(d))
                .then(u.cmp(&v))
        });
        cycle.push(tri[k]);
        cycle.extend_from_slice(&on_edge[k]);
    }
    let mut edges: BTreeSet<(u32, u32)> = BTreeSet::new();
    let add = |u: u32, v: u32, edges: &mut BTreeSet<(u32, u32)>| {
        if u != v {
            edges.insert((u.min(v), u.max(v)));
        }
    };
    for i in 0..cycle.len() {
        add(cycle[i], cycle[(i + 1) % cycle.len()], &mut edges);
    }
    for s in segs {
        add(s[0], s[1], &mut edges);
    }
    // Adjacency, pruning dangling cut ends (degree 1) repeatedly.
    let mut nbrs: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for &(u, v) in &edges {
        nbrs.entry(u).or_default().push(v);
        nbrs.entry(v).or_default().push(u);
    }
    loop {
        let dangling: Vec<u32> = nbrs
            .iter()
            .filter(|(_, n)| n.len() <= 1)
            .map(|(&k, _)| k)
            .collect();
        if dangling.is_empty() {
            break;
        }
        for d in dangling {
            if let Some(n) = nbrs.remove(&d) {
                for m in n {
                    if let Some(l) = nbrs.get_mut(&m) {
                        l.retain(|&z| z != d);
                    }
                }
            }
        }
    }
    let pos: BTreeMap<u32, DVec2> = nbrs.keys().map(|&k| (k, to2(verts[k as usize]))).collect();
    bridge_inner_loops(&mut nbrs, &pos, &tri);
    for (k, n) in nbrs.iter_mut() {
        let o = pos[k];
        n.sort_by(|&u, &v| {
            let du = pos[&u] - o;
            let dv = pos[&v] - o;
            du.y.atan2(du.x)
                .total_cmp(&dv.y.atan2(dv.x))
                .then(u.cmp(&v))
        });
    }
    // Trace faces: at v, arriving from u, leave by the edge just clockwise of v→u.
    let mut visited: BTreeSet<(u32, u32)> = BTreeSet::new();
    let mut keys: Vec<u32> = nbrs.keys().copied().collect();
    keys.sort_unstable();
    for &u0 in &keys {
        for &v0 in &nbrs[&u0] {
            if visited.contains(&(u0, v0)) {
                continue;
            }
            let mut face = Vec::new();
            let (mut u, mut v) = (u0, v0);
            let mut guard = 0;
            while visited.insert((u, v)) && guard < 4 * edges.len() + 8 {
                guard += 1;
                face.push(u);
                let n = &nbrs[&v];
                let i = n.iter().position(|&w| w == u).unwrap_or(0);
                let w = n[(i + n.len() - 1) % n.len()];
                u = v;
                v = w;
            }
            if face.len() < 3 {
                continue;
            }
            let area: f64 = (0..face.len())
                .map(|i| {
                    let p = pos[&face[i]];
                    let q = pos[&face[(i + 1) % face.len()]];
                    p.x * q.y - q.x * p.y
                })
                .sum();
            if area <= 0.0 {
                continue; // the outer face
            }
            let pts: Vec<DVec2> = face.iter().map(|&i| pos[&i]).collect();
            for t in triangulate_face(&pts) {
                out.push(t.map(|i| face[i as usize]));
            }
        }
    }
}

/// Ear clipping that takes the best-shaped ear each time (largest area over the sum of its
/// squared sides), so the cut points lying on a facet's edges — collinear but for roundoff —
/// never become a sliver while a sound ear exists. Faces are small; a large one (a very fine
/// cutter across one facet) falls back to the first clean ear.
fn triangulate_face(p: &[DVec2]) -> Vec<[u32; 3]> {
    use robust::{orient2d, Coord};
    let n = p.len();
    if n > 200 {
        let pts: Vec<DVec3> = p.iter().map(|q| q.extend(0.0)).collect();
        return crate::geom::surface::triangulate_polygon(&pts, DVec3::Z);
    }
    let o = |a: DVec2, b: DVec2, c: DVec2| {
        orient2d(
            Coord { x: a.x, y: a.y },
            Coord { x: b.x, y: b.y },
            Coord { x: c.x, y: c.y },
        )
    };
    let mut idx: Vec<u32> = (0..n as u32).collect();
    let mut tris = Vec::with_capacity(n.saturating_sub(2));
    while idx.len() > 3 {
        let m = idx.len();
        let mut best: Option<(f64, usize)> = None;
        for i in 0..m {
            let (ia, ib, ic) = (idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]);
            let (a, b, c) = (p[ia as usize], p[ib as usize], p[ic as usize]);
            let turn = o(a, b, c);
            if turn <= 0.0 {
                continue;
            }
            let blocked = idx.iter().any(|&j| {
                let q = p[j as usize];
                if j == ia || j == ib || j == ic || q == a || q == b || q == c {
                    return false;
                }
                o(a, b, q) >= 0.0 && o(b, c, q) >= 0.0 && o(c, a, q) >= 0.0
            });
            if blocked {
                continue;
            }
            let quality = turn
                / ((b - a).length_squared() + (c - b).length_squared() + (a - c).length_squared());
            if best.is_none_or(|(q, _)| quality > q) {
                best = Some((quality, i));
            }
        }
        let i = match best {
            Some((_, i)) => i,
            // Degenerate remainder: clip the corner with the largest turn.
            None => (0..m)
                .max_by(|&i, &j| {
                    let t = |k: usize| {
                        o(
                            p[idx[(k + m - 1) % m] as usize],
                            p[idx[k] as usize],
                            p[idx[(k + 1) % m] as usize],
                        )
                    };
                    t(i).total_cmp(&t(j))
                })
                .unwrap_or(0),
        };
        tris.push([idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]]);
        idx.remove(i);
    }
    if idx.len() == 3 {
        tris.push([idx[0], idx[1], idx[2]]);
    }
    tris
}

/// Connects every part of the facet's graph that does not reach its boundary (a cut loop lying
/// wholly inside the facet — paper 001 avoids it by refining the mesh) to the rest by a bridge
/// edge that crosses nothing, nearest pairs first. The face tracer then walks the bridge twice
/// (a keyhole polygon, as in ear clipping of polygons with holes), and the bridge is not a cut
/// edge, so the flood fill crosses it.
fn bridge_inner_loops(
    nbrs: &mut BTreeMap<u32, Vec<u32>>,
    pos: &BTreeMap<u32, DVec2>,
    tri: &[u32; 3],
) {
    let mut reached: BTreeSet<u32> = BTreeSet::new();
    let mut stack: Vec<u32> = tri
        .iter()
        .copied()
        .filter(|v| nbrs.contains_key(v))
        .collect();
    while let Some(v) = stack.pop() {
        if reached.insert(v) {
            stack.extend(nbrs[&v].iter().copied().filter(|w| !reached.contains(w)));
        }
    }
    let mut keys: Vec<u32> = nbrs.keys().copied().collect();
    keys.sort_unstable();
    for start in keys {
        if reached.contains(&start) {
            continue;
        }
        // This component.
        let mut comp = Vec::new();
        let mut seen: BTreeSet<u32> = BTreeSet::new();
        let mut stack = vec![start];
        while let Some(v) = stack.pop() {
            if seen.insert(v) {
                comp.push(v);
                stack.extend(nbrs[&v].iter().copied().filter(|w| !seen.contains(w)));
            }
        }
        let mut pairs: Vec<(f64, u32, u32)> = Vec::new();
        for &v in &comp {
            for &w in &reached {
                pairs.push((pos[&v].distance_squared(pos[&w]), v, w));
            }
        }
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
        let edges: Vec<(u32, u32)> = nbrs
            .iter()
            .flat_map(|(&u, n)| n.iter().filter(move |&&w| u < w).map(move |&w| (u, w)))
            .collect();
        let bridge = pairs.into_iter().find(|&(_, v, w)| {
            edges.iter().all(|&(a, b)| {
                a == v
                    || a == w
                    || b == v
                    || b == w
                    || !segments_cross(pos[&v], pos[&w], pos[&a], pos[&b])
            })
        });
        if let Some((_, v, w)) = bridge {
            if let Some(n) = nbrs.get_mut(&v) {
                n.push(w);
            }
            if let Some(n) = nbrs.get_mut(&w) {
                n.push(v);
            }
        }
        reached.extend(comp);
    }
}

/// Whether the closed segments `ab` and `cd` share a point (exact orientation signs).
fn segments_cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    use robust::{orient2d, Coord};
    let o = |p: DVec2, q: DVec2, r: DVec2| {
        orient2d(
            Coord { x: p.x, y: p.y },
            Coord { x: q.x, y: q.y },
            Coord { x: r.x, y: r.y },
        )
    };
    let (d1, d2, d3, d4) = (o(a, b, c), o(a, b, d), o(c, d, a), o(c, d, b));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let on = |p: DVec2, q: DVec2, r: DVec2| {
        r.x >= p.x.min(q.x) && r.x <= p.x.max(q.x) && r.y >= p.y.min(q.y) && r.y <= p.y.max(q.y)
    };
    (d1 == 0.0 && on(a, b, c))
        || (d2 == 0.0 && on(a, b, d))
        || (d3 == 0.0 && on(c, d, a))
        || (d4 == 0.0 && on(c, d, b))
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
