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

use super::adjacency::{edge_key, Adjacency, NO_NEIGHBOUR};
use super::chain::cmp_point;
use super::intersect::{intersection_pieces, merge_keys_by_point};
use super::{Mesh, MeshError};
use crate::geom::frame::arbitrary_axis;
use glam::{DVec2, DVec3};
use std::collections::{HashMap, HashSet};

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

    // Global vertex ids of the cut points: an end equal to an end of its edge is that vertex.
    let mut vertices: Vec<DVec3> = mesh.vertices().to_vec();
    let mut node_id: HashMap<u128, u32> = HashMap::new();
    let mut ids_of = Vec::with_capacity(pieces.len());
    for p in &pieces {
        let ids: [u32; 2] = std::array::from_fn(|e| {
            let key = p.seg.keys[e];
            let pt = p.seg.points[e];
            let snapped = p.a_edge[e].and_then(|(u, v)| {
                [u, v]
                    .into_iter()
                    .find(|&w| cmp_point(vertices[w as usize], pt).is_eq())
            });
            match snapped {
                Some(w) => w,
                None => *node_id.entry(key).or_insert_with(|| {
                    vertices.push(pt);
                    (vertices.len() - 1) as u32
                }),
            }
        });
        ids_of.push(ids);
    }

    // Group the cut segments by facet.
    let mut by_facet: HashMap<u32, Vec<usize>> = HashMap::new();
    for (i, p) in pieces.iter().enumerate() {
        if ids_of[i][0] != ids_of[i][1] {
            by_facet.entry(p.ta).or_default().push(i);
        }
    }
    let mut facets: Vec<u32> = by_facet.keys().copied().collect();
    facets.sort_unstable();

    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(mesh.len() + facets.len() * 4);
    let split: HashSet<u32> = facets.iter().copied().collect();
    for (t, tri) in mesh.triangles().iter().enumerate() {
        if !split.contains(&(t as u32)) {
            triangles.push(*tri);
        }
    }
    let mut cut_edges: HashSet<u64> = HashSet::new();
    for &t in &facets {
        let segs: Vec<[u32; 2]> = by_facet[&t].iter().map(|&i| ids_of[i]).collect();
        for s in &segs {
            cut_edges.insert(edge_key(s[0], s[1]));
        }
        // Which cut vertices sit on which edge of this facet.
        let tri = mesh.triangles()[t as usize];
        let mut on_edge: [Vec<u32>; 3] = Default::default();
        for &i in &by_facet[&t] {
            for (e, &id) in ids_of[i].iter().enumerate() {
                if let Some((u, v)) = pieces[i].a_edge[e] {
                    if tri.contains(&id) {
                        continue;
                    }
                    for k in 0..3 {
                        let (a, b) = (tri[k], tri[(k + 1) % 3]);
                        if edge_key(a, b) == edge_key(u, v) && !on_edge[k].contains(&id) {
                            on_edge[k].push(id);
                        }
                    }
                }
            }
        }
        split_facet(&vertices, tri, on_edge, &segs, &mut triangles);
    }

    let out = Mesh::new_unchecked(vertices, triangles);
    let adj = Adjacency::build(out.triangles(), out.vertices().len());
    let seed = out
        .bvh()
        .nearest(keep_point, |t| {
            let [a, b, c] = out.corners_of(t as usize);
            closest_on_triangle(keep_point, a, b, c).distance_squared(keep_point)
        })
        .map(|(t, _)| t as usize)
        .unwrap_or(0);
    let mut keep = vec![false; out.len()];
    let mut stack = vec![seed];
    keep[seed] = true;
    while let Some(t) = stack.pop() {
        let tri = out.triangles()[t];
        let nb = adj.neighbours(t);
        for i in 0..3 {
            let n = nb[i];
            if n == NO_NEIGHBOUR || keep[n as usize] {
                continue;
            }
            if cut_edges.contains(&edge_key(tri[i], tri[(i + 1) % 3])) {
                continue;
            }
            keep[n as usize] = true;
            stack.push(n as usize);
        }
    }
    let part = |want: bool| {
        let tris: Vec<[u32; 3]> = out
            .triangles()
            .iter()
            .zip(&keep)
            .filter(|(_, &k)| k == want)
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
        });
        cycle.push(tri[k]);
        cycle.extend_from_slice(&on_edge[k]);
    }
    let mut edges: HashSet<(u32, u32)> = HashSet::new();
    let add = |u: u32, v: u32, edges: &mut HashSet<(u32, u32)>| {
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
    let mut nbrs: HashMap<u32, Vec<u32>> = HashMap::new();
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
    let pos: HashMap<u32, DVec2> = nbrs.keys().map(|&k| (k, to2(verts[k as usize]))).collect();
    bridge_inner_loops(&mut nbrs, &pos, &tri);
    for (k, n) in nbrs.iter_mut() {
        let o = pos[k];
        n.sort_by(|&u, &v| {
            let du = pos[&u] - o;
            let dv = pos[&v] - o;
            du.y.atan2(du.x).total_cmp(&dv.y.atan2(dv.x))
        });
    }
    // Trace faces: at v, arriving from u, leave by the edge just clockwise of v→u.
    let mut visited: HashSet<(u32, u32)> = HashSet::new();
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
            let pts: Vec<DVec3> = face.iter().map(|&i| verts[i as usize]).collect();
            for t in crate::geom::surface::triangulate_polygon(&pts, normal) {
                out.push(t.map(|i| face[i as usize]));
            }
        }
    }
}

/// Connects every part of the facet's graph that does not reach its boundary (a cut loop lying
/// wholly inside the facet — paper 001 avoids it by refining the mesh) to the rest by a bridge
/// edge that crosses nothing, nearest pairs first. The face tracer then walks the bridge twice
/// (a keyhole polygon, as in ear clipping of polygons with holes), and the bridge is not a cut
/// edge, so the flood fill crosses it.
fn bridge_inner_loops(
    nbrs: &mut HashMap<u32, Vec<u32>>,
    pos: &HashMap<u32, DVec2>,
    tri: &[u32; 3],
) {
    let mut reached: HashSet<u32> = HashSet::new();
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
        let mut seen: HashSet<u32> = HashSet::new();
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
