//! Shared by the mesh tests (and examples/mesh_bench.rs, which includes it with `#[path]`):
//! simple meshes to cut and intersect with, and an independent triangle/triangle check; the
//! surface tests use it for their shared outline.
#![allow(
    dead_code,
    reason = "each crate including this module uses only some of the helpers"
)]

use lispcad::geom::mesh::Mesh;
use lispcad::geom::DVec3;

/// A flat square grid in the plane at height `z`: x and y in [-size, size], n×n cells of two
/// triangles each.
pub fn grid(n: usize, size: f64, z: f64) -> Mesh {
    let mut v = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            v.push(DVec3::new(
                -size + 2.0 * size * i as f64 / n as f64,
                -size + 2.0 * size * j as f64 / n as f64,
                z,
            ));
        }
    }
    let mut t = Vec::new();
    let w = (n + 1) as u32;
    for j in 0..n as u32 {
        for i in 0..n as u32 {
            let a = j * w + i;
            t.push([a, a + 1, a + w + 1]);
            t.push([a, a + w + 1, a + w]);
        }
    }
    Mesh::new(v, t).unwrap()
}

/// The L-shaped outline [0, 2]² minus [1, 2]² in z = 0, counter-clockwise, not closed: a
/// non-convex region of area 3 with one notch corner at (1, 1).
pub fn l_outline() -> Vec<DVec3> {
    vec![
        DVec3::ZERO,
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(2.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(1.0, 2.0, 0.0),
        DVec3::new(0.0, 2.0, 0.0),
    ]
}

/// Möller–Trumbore segment/triangle test in plain f64, independent of the library's predicates.
pub fn segment_hits_triangle(p: DVec3, q: DVec3, t: [DVec3; 3]) -> bool {
    let d = q - p;
    let e1 = t[1] - t[0];
    let e2 = t[2] - t[0];
    let h = d.cross(e2);
    let a = e1.dot(h);
    if a.abs() < 1e-300 {
        return false;
    }
    let f = 1.0 / a;
    let s = p - t[0];
    let u = f * s.dot(h);
    if !(0.0..=1.0).contains(&u) {
        return false;
    }
    let qq = s.cross(e1);
    let v = f * d.dot(qq);
    if v < 0.0 || u + v > 1.0 {
        return false;
    }
    let w = f * e2.dot(qq);
    (0.0..=1.0).contains(&w)
}

/// Two triangles cross: an edge of one hits the other (plain f64, via `segment_hits_triangle`).
pub fn triangles_cross(a: [DVec3; 3], b: [DVec3; 3]) -> bool {
    (0..3).any(|i| segment_hits_triangle(a[i], a[(i + 1) % 3], b))
        || (0..3).any(|i| segment_hits_triangle(b[i], b[(i + 1) % 3], a))
}
