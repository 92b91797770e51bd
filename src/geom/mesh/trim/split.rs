//! Splitting one crossed facet at once: its boundary (corners plus the cut points on its edges)
//! and the cut segments form a planar graph whose faces, traced by the half-edge rule "turn as
//! far clockwise as possible" in the facet's plane, are ear-clipped into the new triangles.

use crate::geom::frame::arbitrary_axis;
use glam::{DVec2, DVec3};
use std::collections::{BTreeMap, BTreeSet};

/// Splits triangle `tri` by the cut segments `segs` (global vertex ids), with the cut points on
/// its edges in `on_edge`, appending the new triangles.
pub(super) fn split_facet(
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
    let edges = facet_edges(verts, tri, &mut on_edge, segs);
    let mut nbrs: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for &(u, v) in &edges {
        nbrs.entry(u).or_default().push(v);
        nbrs.entry(v).or_default().push(u);
    }
    prune_dangling(&mut nbrs);
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
    trace_faces(&nbrs, &pos, 4 * edges.len() + 8, out);
}

/// The edges of the facet's planar graph: the boundary cycle (corners with the cut points of
/// each edge ordered along it) and the cut segments, each once as (low id, high id).
fn facet_edges(
    verts: &[DVec3],
    tri: [u32; 3],
    on_edge: &mut [Vec<u32>; 3],
    segs: &[[u32; 2]],
) -> BTreeSet<(u32, u32)> {
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
    let mut add = |u: u32, v: u32| {
        if u != v {
            edges.insert((u.min(v), u.max(v)));
        }
    };
    for i in 0..cycle.len() {
        add(cycle[i], cycle[(i + 1) % cycle.len()]);
    }
    for s in segs {
        add(s[0], s[1]);
    }
    edges
}

/// Removes dangling cut ends (degree 1) repeatedly.
fn prune_dangling(nbrs: &mut BTreeMap<u32, Vec<u32>>) {
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
}

/// Traces the faces of the graph (neighbours sorted by angle): at v, arriving from u, leave by
/// the edge just clockwise of v→u. Each counter-clockwise face (the outer one is clockwise) is
/// ear-clipped into `out`; `guard` bounds a walk.
fn trace_faces(
    nbrs: &BTreeMap<u32, Vec<u32>>,
    pos: &BTreeMap<u32, DVec2>,
    guard_limit: usize,
    out: &mut Vec<[u32; 3]>,
) {
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
            while visited.insert((u, v)) && guard < guard_limit {
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
