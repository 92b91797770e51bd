//! Boundary corners and surface extension (paper 003).
//!
//! Corners: walk each boundary loop; where the tangent turns by more than `angle` between the
//! incoming and outgoing boundary edges, the point is a corner (paper 003 splits the boundary
//! where the tangent is discontinuous and keeps the split points whose tangent angle exceeds
//! the threshold ε; on a discrete boundary every vertex is a candidate split point).
//!
//! Extension: each boundary run (corner to corner) is extruded outward in the surface's tangent
//! plane by `distance`: every boundary edge moves along `d × n` (its direction crossed with its
//! facet's normal, so away from the facet, in the facet's plane); inside a run the two
//! directions meeting at a vertex are mitred into one, so the strips of one run share their
//! outer vertices. At a convex corner the gap between the two runs' strips is filled by a fan
//! (a rounded corner, ≤ 15° per triangle); at a reflex corner the two strips share one mitred
//! vertex when it lies within both strips; otherwise (a short edge, a sharp notch) each side's
//! strip and corner fan are trimmed at the bisector plane, the two sides sharing their cut
//! vertices. The strips reuse the boundary vertices, so there are no cracks; whatever still
//! overlaps (strips of non-adjacent edges meeting) is an error.

use super::{Mesh, MeshError};
use glam::DVec3;
use std::collections::HashMap;

/// An oriented boundary loop: vertex ids (interior on the left), and the facet of each edge.
struct Loop {
    verts: Vec<u32>,
    facets: Vec<u32>,
}

/// Boundary loops walked along the facets' orientation (each boundary edge goes from corner i
/// to corner i + 1 of its facet, so the surface is on the left about the facet normal).
fn oriented_loops(mesh: &Mesh) -> Vec<Loop> {
    let adj = mesh.adjacency();
    let tris = mesh.triangles();
    let mut from: HashMap<u32, Vec<(u32, u32)>> = HashMap::new();
    for (t, i) in adj.boundary_edges() {
        let a = tris[t][i];
        let b = tris[t][(i + 1) % 3];
        from.entry(a).or_default().push((b, t as u32));
    }
    let mut starts: Vec<u32> = from.keys().copied().collect();
    starts.sort_unstable();
    let mut loops = Vec::new();
    for s in starts {
        while let Some((mut next, facet)) = from.get_mut(&s).and_then(|v| v.pop()) {
            let mut verts = vec![s];
            let mut facets = vec![facet];
            let mut closed = false;
            for _ in 0..tris.len() * 3 {
                if next == s {
                    closed = true;
                    break;
                }
                verts.push(next);
                match from.get_mut(&next).and_then(|v| v.pop()) {
                    Some((n, f)) => {
                        facets.push(f);
                        next = n;
                    }
                    None => break,
                }
            }
            if closed && verts.len() >= 3 {
                loops.push(Loop { verts, facets });
            }
        }
    }
    loops
}

fn turn_angle(a: DVec3, b: DVec3) -> f64 {
    let (la, lb) = (a.length(), b.length());
    if la == 0.0 || lb == 0.0 {
        return 0.0;
    }
    (a.dot(b) / (la * lb)).clamp(-1.0, 1.0).acos()
}

fn check_angle(angle: f64) -> Result<f64, MeshError> {
    if angle.is_finite() && (0.0..=std::f64::consts::PI).contains(&angle) {
        Ok(angle)
    } else {
        Err(MeshError::BadParameter {
            parameter: "angle",
            limit: "in [0, π]",
            value: angle,
        })
    }
}

fn corner_flags(mesh: &Mesh, l: &Loop, angle: f64) -> Vec<bool> {
    let v = mesh.vertices();
    let n = l.verts.len();
    (0..n)
        .map(|i| {
            let p = v[l.verts[i] as usize];
            let a = p - v[l.verts[(i + n - 1) % n] as usize];
            let b = v[l.verts[(i + 1) % n] as usize] - p;
            turn_angle(a, b) > angle
        })
        .collect()
}

/// The boundary points where the boundary's tangent turns by more than `angle` (radians),
/// loop by loop, each loop in the facets' orientation.
pub fn corners(mesh: &Mesh, angle: f64) -> Result<Vec<DVec3>, MeshError> {
    let angle = check_angle(angle)?;
    let mut out = Vec::new();
    for l in oriented_loops(mesh) {
        let flags = corner_flags(mesh, &l, angle);
        out.extend(
            l.verts
                .iter()
                .zip(&flags)
                .filter(|(_, &f)| f)
                .map(|(&v, _)| mesh.vertices()[v as usize]),
        );
    }
    Ok(out)
}

/// The mesh extended outward by `distance` along all its boundary loops (holes inward), the
/// boundary split into runs at corners (tangent turn above `angle`). See [`extend_with`].
pub fn extend(mesh: &Mesh, distance: f64, angle: f64) -> Result<Mesh, MeshError> {
    extend_with(mesh, distance, angle, true)
}

/// Whether a loop is a hole: walked with the surface on its left, its total signed turn about
/// the facets' normals is about −2π (an outer boundary turns +2π, a cylinder's rim 0).
fn is_hole(mesh: &Mesh, l: &Loop) -> bool {
    let v = mesh.vertices();
    let n = l.verts.len();
    let total: f64 = (0..n)
        .map(|i| {
            let p = v[l.verts[i] as usize];
            let a = p - v[l.verts[(i + n - 1) % n] as usize];
            let b = v[l.verts[(i + 1) % n] as usize] - p;
            let [x, y, z] = mesh.corners_of(l.facets[i] as usize);
            let nrm = (y - x).cross(z - x).normalize_or_zero();
            a.cross(b).dot(nrm).atan2(a.dot(b))
        })
        .sum();
    total < -std::f64::consts::PI
}

/// [`extend`], with `holes` false leaving the holes' boundaries as they are. The strips are
/// mitred exactly at concave vertices (trimmed at the bisector where the mitre would fall past
/// the adjacent edges) and fanned at convex corners; an extension whose strips would still
/// overlap themselves or the surface (a slot or a hole too small for `distance`) is an error
/// naming the place, never a folded result.
pub fn extend_with(mesh: &Mesh, distance: f64, angle: f64, holes: bool) -> Result<Mesh, MeshError> {
    let angle = check_angle(angle)?;
    if !(distance.is_finite() && distance > 0.0) {
        return Err(MeshError::BadParameter {
            parameter: "distance",
            limit: "finite and > 0",
            value: distance,
        });
    }
    let mut verts = mesh.vertices().to_vec();
    let mut tris = mesh.triangles().to_vec();
    for l in oriented_loops(mesh) {
        if !holes && is_hole(mesh, &l) {
            continue;
        }
        extend_loop(mesh, &l, distance, angle, &mut verts, &mut tris)?;
    }
    if verts.iter().any(|v| !v.is_finite()) {
        return Err(MeshError::Invalid(
            "extension produced a non-finite point".into(),
        ));
    }
    let out = Mesh::new(verts, tris)?;
    if let Some(p) = first_overlap(&out, mesh.len()) {
        return Err(overlap_error(distance, holes, p));
    }
    Ok(out)
}

/// Appends the strips (and corner fans) of one boundary loop to `verts` and `tris`.
fn extend_loop(
    mesh: &Mesh,
    l: &Loop,
    distance: f64,
    angle: f64,
    verts: &mut Vec<DVec3>,
    tris: &mut Vec<[u32; 3]>,
) -> Result<(), MeshError> {
    let n = l.verts.len();
    let mv = mesh.vertices();
    let p = |i: usize| mv[l.verts[i % n] as usize];
    let flags = corner_flags(mesh, l, angle);
    // Outward direction of each boundary edge, in its facet's plane.
    let outward: Vec<DVec3> = (0..n)
        .map(|e| {
            let d = p(e + 1) - p(e);
            let [a, b, c] = mesh.corners_of(l.facets[e] as usize);
            let nrm = (b - a).cross(c - a);
            d.cross(nrm).normalize_or_zero()
        })
        .collect();
    // For each boundary vertex: the offset vertex its incoming edge uses, and its outgoing.
    let mut q_in = vec![0u32; n];
    let mut q_out = vec![0u32; n];
    let first_tri = tris.len();
    // What made each new triangle: the strip of an edge or the fan at a vertex.
    let mut tags: Vec<Piece> = Vec::new();
    let mut trims: Vec<Trim> = Vec::new();
    for i in 0..n {
        let o_in = outward[(i + n - 1) % n];
        let o_out = outward[i];
        let b = p(i);
        let a_dir = b - p(i + n - 1);
        let b_dir = p(i + 1) - b;
        let [x, y, z] = mesh.corners_of(l.facets[i] as usize);
        let nrm = (y - x).cross(z - x);
        let convex = a_dir.cross(b_dir).dot(nrm) > 0.0;
        if flags[i] && convex {
            let first = verts.len() as u32;
            let dirs = fan_dirs(o_in, o_out, nrm);
            let k = dirs.len() - 1;
            verts.extend(dirs.iter().map(|&dir| b + dir * distance));
            for s in 0..k as u32 {
                tris.push([l.verts[i], first + s, first + s + 1]);
                tags.push(Piece::Fan(i));
            }
            q_in[i] = first;
            q_out[i] = first + k as u32;
        } else {
            // The exact mitre when it lies within both strips; otherwise each strip is cut
            // at the bisector after the fact.
            let mitre = mitre_within(o_in, o_out, a_dir, b_dir, distance);
            if let Some(mitre) = mitre {
                verts.push(b + mitre);
                q_in[i] = (verts.len() - 1) as u32;
                q_out[i] = q_in[i];
            } else if convex {
                // A smooth-run vertex turning nearly back on itself (angle near π).
                return Err(MeshError::Invalid(format!(
                    "extend-surface: the boundary folds back at ({}, {}, {}): no clean \
                     extension there",
                    b.x, b.y, b.z
                )));
            } else {
                verts.push(b + o_in * distance);
                verts.push(b + o_out * distance);
                q_in[i] = (verts.len() - 2) as u32;
                q_out[i] = (verts.len() - 1) as u32;
                trims.push(Trim {
                    at: i,
                    apex: l.verts[i],
                    normal: (o_out - o_in).normalize_or_zero(),
                    cuts_from: 0,
                });
            }
        }
    }
    for e in 0..n {
        let (v, w) = (l.verts[e], l.verts[(e + 1) % n]);
        let (qv, qw) = (q_out[e], q_in[(e + 1) % n]);
        tris.push([w, v, qv]);
        tris.push([w, qv, qw]);
        tags.extend([Piece::Strip(e), Piece::Strip(e)]);
    }
    if !trims.is_empty() {
        let new_tris = tris.split_off(first_tri);
        tris.extend(trim_corners(verts, new_tris, tags, &mut trims, n));
    }
    Ok(())
}

/// Directions from `o_in` to `o_out` (both included) in equal steps of at most 15° about the
/// normal `nrm`: a convex corner's rounded fan.
fn fan_dirs(o_in: DVec3, o_out: DVec3, nrm: DVec3) -> Vec<DVec3> {
    let turn = turn_angle(o_in, o_out);
    let k = ((turn / (15f64).to_radians()).ceil() as usize).max(1);
    let axis = o_in.cross(o_out).normalize_or(nrm.normalize_or(DVec3::Z));
    (0..=k)
        .map(|s| {
            if s == k {
                o_out
            } else {
                glam::DQuat::from_axis_angle(axis, s as f64 / k as f64 * turn) * o_in
            }
        })
        .collect()
}

/// The mitre offset at a concave vertex (where the two edges' offset lines meet), when it lies
/// within both strips: not past the far end of the incoming edge `a_dir` or outgoing `b_dir`.
fn mitre_within(o_in: DVec3, o_out: DVec3, a_dir: DVec3, b_dir: DVec3, d: f64) -> Option<DVec3> {
    let m = (o_in + o_out).normalize_or(o_out);
    let c = m.dot(o_out);
    let mitre = m * (d / c.max(1e-300));
    let fits = c >= 0.05
        && mitre.dot(-a_dir) <= a_dir.length_squared()
        && mitre.dot(b_dir) <= b_dir.length_squared();
    (fits || o_in.dot(o_out) > 1.0 - 1e-12).then_some(mitre)
}

fn overlap_error(distance: f64, holes: bool, p: DVec3) -> MeshError {
    MeshError::Invalid(format!(
        "extend-surface: extending by {distance} folds the strips over each other or the \
         surface near ({:.6}, {:.6}, {:.6}) (a concave boundary or a hole too small for \
         that distance){}",
        p.x,
        p.y,
        p.z,
        if holes {
            "; pass nil as the fourth argument to leave holes alone"
        } else {
            ""
        }
    ))
}

#[derive(Clone, Copy)]
enum Piece {
    Strip(usize),
    Fan(usize),
}

/// A concave boundary vertex whose mitre would fall outside its strips: the strips on either
/// side are cut by the plane through the vertex with this normal (from o_in towards o_out).
struct Trim {
    at: usize,
    apex: u32,
    normal: DVec3,
    /// Vertices from here on are cut points, which the two sides share.
    cuts_from: usize,
}

/// Cuts the new triangles of one loop (`n` boundary vertices, `tags` saying what made each) at
/// each trimmed corner's bisector plane.
fn trim_corners(
    verts: &mut Vec<DVec3>,
    mut new_tris: Vec<[u32; 3]>,
    mut tags: Vec<Piece>,
    trims: &mut [Trim],
    n: usize,
) -> Vec<[u32; 3]> {
    let cuts_from = verts.len();
    for t in trims.iter_mut() {
        t.cuts_from = cuts_from;
    }
    for t in trims.iter() {
        let (mut kept, mut kept_tags) = (Vec::new(), Vec::new());
        for (tri, tag) in new_tris.iter().zip(&tags) {
            // The strip and fan before the corner keep the side along the incoming edge,
            // those after it the other side; the bisector is where they meet.
            let sign = match *tag {
                Piece::Strip(e) | Piece::Fan(e) if e == (t.at + n - 1) % n => 1.0,
                Piece::Strip(e) if e == t.at => -1.0,
                Piece::Fan(e) if e == (t.at + 1) % n => -1.0,
                _ => 0.0,
            };
            let before = kept.len();
            if sign == 0.0 {
                kept.push(*tri);
            } else {
                clip(verts, *tri, t, sign, &mut kept);
            }
            kept_tags.extend(std::iter::repeat_n(*tag, kept.len() - before));
        }
        (new_tris, tags) = split_on_seam(verts, kept, kept_tags, t);
    }
    new_tris
}

/// Keeps the part of `tri` where `sign · normal · (p − apex) ≥ 0`, in the same orientation.
fn clip(verts: &mut Vec<DVec3>, tri: [u32; 3], t: &Trim, sign: f64, out: &mut Vec<[u32; 3]>) {
    let apex = verts[t.apex as usize];
    let scale = tri
        .iter()
        .map(|&v| (verts[v as usize] - apex).length())
        .fold(0.0, f64::max);
    let eps = 1e-12 * scale.max(1e-300);
    let dist = tri.map(|v| sign * t.normal.dot(verts[v as usize] - apex));
    if dist.iter().all(|&d| d >= -eps) {
        out.push(tri);
        return;
    }
    if dist.iter().all(|&d| d <= eps) {
        return;
    }
    let mut poly = Vec::with_capacity(4);
    for k in 0..3 {
        let (a, b) = (tri[k], tri[(k + 1) % 3]);
        let (da, db) = (dist[k], dist[(k + 1) % 3]);
        if da >= -eps {
            poly.push(a);
        }
        if (da > eps && db < -eps) || (da < -eps && db > eps) {
            let (pa, pb) = (verts[a as usize], verts[b as usize]);
            let x = pa + (pb - pa) * (da / (da - db));
            // Both triangles sharing this edge cut it at one shared vertex.
            let id = verts[t.cuts_from..]
                .iter()
                .position(|q| (*q - x).length() <= eps)
                .map(|j| (t.cuts_from + j) as u32)
                .unwrap_or_else(|| {
                    verts.push(x);
                    (verts.len() - 1) as u32
                });
            poly.push(id);
        }
    }
    for k in 1..poly.len().saturating_sub(1) {
        let tri = [poly[0], poly[k], poly[k + 1]];
        let [a, b, c] = tri.map(|v| verts[v as usize]);
        if (b - a).cross(c - a).length() > eps * eps {
            out.push(tri);
        }
    }
}

/// Splits the triangles whose edges run along the cut plane at the cut vertices of the other
/// side lying inside those edges, so the two sides meet vertex to vertex (no T-junctions).
fn split_on_seam(
    verts: &[DVec3],
    tris: Vec<[u32; 3]>,
    tags: Vec<Piece>,
    t: &Trim,
) -> (Vec<[u32; 3]>, Vec<Piece>) {
    let apex = verts[t.apex as usize];
    let on = |v: u32| {
        let p = verts[v as usize];
        t.normal.dot(p - apex).abs() <= 1e-9 * (p - apex).length().max(1e-300)
    };
    let mut seam: Vec<u32> = tris.iter().flatten().copied().filter(|&v| on(v)).collect();
    seam.sort_unstable();
    seam.dedup();
    let mut out = Vec::with_capacity(tris.len());
    let mut out_tags = Vec::with_capacity(tris.len());
    for (tri, tag) in tris.into_iter().zip(tags) {
        let mut done = false;
        for k in 0..3 {
            let (u, v, w) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
            if !(on(u) && on(v)) {
                continue;
            }
            let (pu, pv) = (verts[u as usize], verts[v as usize]);
            let len2 = (pv - pu).length_squared();
            let mut inner: Vec<(f64, u32)> = seam
                .iter()
                .filter(|&&s| s != u && s != v)
                .filter_map(|&s| {
                    let f = (verts[s as usize] - pu).dot(pv - pu) / len2;
                    let off = (pu + (pv - pu) * f - verts[s as usize]).length();
                    (f > 1e-12 && f < 1.0 - 1e-12 && off <= 1e-9 * len2.sqrt()).then_some((f, s))
                })
                .collect();
            if inner.is_empty() {
                continue;
            }
            inner.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut prev = u;
            for (_, s) in inner {
                out.push([prev, s, w]);
                out_tags.push(tag);
                prev = s;
            }
            out.push([prev, v, w]);
            out_tags.push(tag);
            done = true;
            break;
        }
        if !done {
            out.push(tri);
            out_tags.push(tag);
        }
    }
    (out, out_tags)
}

/// A point where a strip triangle (index ≥ `first_new`) overlaps another triangle with positive
/// area (coplanar) or crosses it (not sharing a vertex); None when the extension is clean.
fn first_overlap(m: &Mesh, first_new: usize) -> Option<DVec3> {
    let b = m.bounds()?;
    let eps = 1e-9 * (b.max - b.min).length().max(1e-300);
    let bvh = m.bvh();
    let mut pairs = bvh.overlapping_pairs(bvh);
    pairs.retain(|&(s, t)| s < t && t as usize >= first_new);
    pairs.sort_unstable();
    pairs.into_iter().find_map(|(s, t)| {
        let (ta, tb) = (m.triangles()[s as usize], m.triangles()[t as usize]);
        let (a, bb) = (m.corners_of(s as usize), m.corners_of(t as usize));
        let shared = ta.iter().filter(|v| tb.contains(v)).count();
        overlap(a, bb, shared, eps).then(|| (a[0] + a[1] + a[2] + bb[0] + bb[1] + bb[2]) / 6.0)
    })
}

/// Whether two triangles overlap: coplanar ones with an overlap wider than `eps` across every
/// separating direction (2D separating axes), others when an edge of one passes through the
/// inside of the other (only for triangles sharing no vertex).
fn overlap(a: [DVec3; 3], b: [DVec3; 3], shared: usize, eps: f64) -> bool {
    let na = (a[1] - a[0]).cross(a[2] - a[0]);
    let nb = (b[1] - b[0]).cross(b[2] - b[0]);
    let (la, lb) = (na.length(), nb.length());
    if la == 0.0 || lb == 0.0 {
        return false;
    }
    let (ua, ub) = (na / la, nb / lb);
    let coplanar =
        ua.cross(ub).length() <= 1e-9 && b.iter().all(|p| ua.dot(*p - a[0]).abs() <= eps);
    if coplanar {
        let (x, y) = crate::geom::frame::arbitrary_axis(ua);
        let to2 = |p: DVec3| glam::DVec2::new(p.dot(x), p.dot(y));
        let (a2, b2) = (a.map(to2), b.map(to2));
        for tri in [&a2, &b2] {
            for k in 0..3 {
                let e = tri[(k + 1) % 3] - tri[k];
                let axis = glam::DVec2::new(-e.y, e.x).normalize_or_zero();
                let span = |t: &[glam::DVec2; 3]| {
                    let d = t.map(|p| p.dot(axis));
                    (d[0].min(d[1]).min(d[2]), d[0].max(d[1]).max(d[2]))
                };
                let ((a0, a1), (b0, b1)) = (span(&a2), span(&b2));
                if a1.min(b1) - a0.max(b0) <= eps {
                    return false;
                }
            }
        }
        return true;
    }
    if shared > 0 {
        return false;
    }
    let crosses = |p: &[DVec3; 3], t: &[DVec3; 3], n: DVec3| {
        (0..3).any(|k| {
            let (s, e) = (p[k], p[(k + 1) % 3]);
            let (ds, de) = (n.dot(s - t[0]), n.dot(e - t[0]));
            if !((ds > eps && de < -eps) || (ds < -eps && de > eps)) {
                return false;
            }
            let x = s + (e - s) * (ds / (ds - de));
            (0..3).all(|j| (t[(j + 1) % 3] - t[j]).cross(x - t[j]).dot(n) > eps * eps)
        })
    };
    crosses(&a, &b, ua) || crosses(&b, &a, ub)
}
