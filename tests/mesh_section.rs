//! Plane sections of meshes: loops close, no stray pieces through vertices and along edges,
//! invariance under vertex/triangle permutation.

use lispcad::geom::mesh::{icosphere, section, section_edges, Mesh, Polyline3};
use lispcad::geom::surface::{mesh_surface, Surface};
use lispcad::geom::DVec3;
use proptest::prelude::*;

fn no_repeated_points(p: &Polyline3) -> bool {
    let n = p.points.len();
    let mut pts = p.points.clone();
    pts.sort_by(|a, b| {
        a.x.total_cmp(&b.x)
            .then(a.y.total_cmp(&b.y))
            .then(a.z.total_cmp(&b.z))
    });
    pts.dedup();
    pts.len() == n
}

#[test]
fn sphere_section_is_one_closed_circle() {
    let m = icosphere(DVec3::ZERO, 1.0, 4);
    let r = section(&m, DVec3::new(0.0, 0.0, 0.3), DVec3::Z).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    assert!(no_repeated_points(&r[0]));
    let expected = (1.0f64 - 0.09).sqrt();
    for p in &r[0].points {
        assert!((p.z - 0.3).abs() < 1e-12);
        let rad = (p.x * p.x + p.y * p.y).sqrt();
        // Edges of a level-4 icosphere subtend < 0.07 rad: sagitta < 1e-3.
        assert!(rad <= expected + 1e-12 && rad > expected - 2e-3, "{rad}");
    }
}

#[test]
fn each_section_point_comes_with_the_edge_it_lies_on() {
    // The section is the same as `section`'s, and each point lies on the segment between its
    // edge's two vertices, which lie on opposite sides of the plane (a vertex on the plane
    // itself has no edge): what a refinement keeps the true crossing between.
    let m = icosphere(DVec3::ZERO, 1.0, 3);
    for (p0, n) in [
        (DVec3::new(0.0, 0.0, 0.3), DVec3::Z),
        (DVec3::ZERO, DVec3::X),
        (DVec3::new(0.1, -0.2, 0.05), DVec3::new(1.0, 2.0, -0.5)),
    ] {
        let plain = section(&m, p0, n).unwrap();
        let edged = section_edges(&m, p0, n).unwrap();
        assert_eq!(plain.len(), edged.len());
        let n = n.normalize();
        for (c, (e, edges)) in plain.iter().zip(&edged) {
            assert_eq!(c.points, e.points);
            assert_eq!(c.points.len(), edges.len());
            for (p, edge) in c.points.iter().zip(edges) {
                let Some([a, b]) = edge else {
                    assert!(m.vertices().contains(p), "{p} has no edge but is no vertex");
                    continue;
                };
                let (da, db) = (n.dot(*a - p0), n.dot(*b - p0));
                assert!(da * db < 0.0, "{p}: {a} and {b} on one side");
                let t = (*p - *a).dot(*b - *a) / (*b - *a).length_squared();
                assert!((0.0..=1.0).contains(&t), "{p} beyond its edge");
                assert!(
                    (*a + (*b - *a) * t).distance(*p) <= 1e-12,
                    "{p} off its edge"
                );
            }
        }
    }
}

#[test]
fn plane_through_vertices_gives_one_loop_without_duplicates() {
    // The icosahedron has vertices (and, subdivided, edges) on z = 0, x = 0 and y = 0.
    let m = icosphere(DVec3::ZERO, 1.0, 3);
    for n in [DVec3::X, DVec3::Y, DVec3::Z, -DVec3::Z] {
        let r = section(&m, DVec3::ZERO, n).unwrap();
        assert_eq!(r.len(), 1, "normal {n}");
        assert!(r[0].closed);
        assert!(no_repeated_points(&r[0]));
        let on_plane = m.vertices().iter().filter(|v| v.dot(n) == 0.0).count();
        assert!(on_plane > 0);
    }
}

/// A roof: grid over [-2,2]×[0,3] with z = |x|; the ridge x = 0 runs along mesh edges.
fn roof() -> Mesh {
    let mut v = Vec::new();
    for j in 0..=3 {
        for i in 0..=4 {
            let x = i as f64 - 2.0;
            v.push(DVec3::new(x, j as f64, x.abs()));
        }
    }
    let mut t = Vec::new();
    for j in 0..3u32 {
        for i in 0..4u32 {
            let a = j * 5 + i;
            t.push([a, a + 1, a + 6]);
            t.push([a, a + 6, a + 5]);
        }
    }
    Mesh::new(v, t).unwrap()
}

#[test]
fn plane_along_edges_gives_each_edge_once() {
    let m = roof();
    // Along the ridge (every segment is a mesh edge).
    let r = section(&m, DVec3::ZERO, DVec3::X).unwrap();
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    assert_eq!(
        r[0].points,
        (0..=3)
            .map(|j| DVec3::new(0.0, j as f64, 0.0))
            .collect::<Vec<_>>()
    );
    // Across a row of vertices (y = 1): edges of the grid row.
    let r = section(&m, DVec3::new(0.0, 1.0, 0.0), DVec3::Y).unwrap();
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].points.len(), 5);
    assert!(no_repeated_points(&r[0]));
    // A horizontal plane through the vertices at height 1: two lines x = ±1.
    let r = section(&m, DVec3::new(0.0, 0.0, 1.0), DVec3::Z).unwrap();
    assert_eq!(r.len(), 2);
    for p in &r {
        assert_eq!(p.points.len(), 4);
        assert!(p.points.iter().all(|q| q.z == 1.0 && q.x.abs() == 1.0));
    }
}

#[test]
fn plane_missing_or_containing_a_flat_mesh() {
    let m = Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::new(1.0, 1.0, 0.0)],
        vec![[0, 1, 3], [0, 3, 2]],
    )
    .unwrap();
    assert!(section(&m, DVec3::new(0.0, 0.0, 5.0), DVec3::Z)
        .unwrap()
        .is_empty());
    // The plane containing the mesh: nothing (a region is not a section curve).
    assert!(section(&m, DVec3::ZERO, DVec3::Z).unwrap().is_empty());
    assert!(section(&m, DVec3::ZERO, DVec3::ZERO).is_err());
}

#[test]
fn degenerate_triangles_do_not_break_the_chain() {
    // A zero-area sliver (collinear vertices) inserted into a strip.
    let v = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(2.0, 1.0, 0.0),
    ];
    let m = Mesh::new(v, vec![[0, 1, 3], [1, 4, 3], [1, 2, 4], [0, 1, 2]]).unwrap();
    let r = section(&m, DVec3::new(0.5, 0.0, 0.0), DVec3::X).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].points.iter().all(|p| p.x == 0.5));
}

#[test]
fn cylinder_mesh_sections_are_circle_and_ellipse_within_chord_tol() {
    let tol = 1e-3;
    let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 2.0, 5.0).unwrap();
    let m = mesh_surface(&s, tol).unwrap();
    let r = section(&m, DVec3::new(0.0, 0.0, 2.5), DVec3::Z).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        let rad = (p.x * p.x + p.y * p.y).sqrt();
        assert!((rad - 2.0).abs() <= tol + 1e-9, "{rad}");
    }
    // Oblique: the ellipse (x, y on the circle, z on the plane).
    let n = DVec3::new(0.3, 0.0, 1.0);
    let r = section(&m, DVec3::new(0.0, 0.0, 2.5), n).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        let rad = (p.x * p.x + p.y * p.y).sqrt();
        assert!((rad - 2.0).abs() <= tol + 1e-9);
        assert!(n.dot(*p - DVec3::new(0.0, 0.0, 2.5)).abs() < 1e-9);
    }
}

fn permuted(m: &Mesh, vperm: &[usize], tperm: &[usize], rot: &[usize]) -> Mesh {
    let mut inv = vec![0u32; vperm.len()];
    let mut verts = vec![DVec3::ZERO; vperm.len()];
    for (new, &old) in vperm.iter().enumerate() {
        inv[old] = new as u32;
        verts[new] = m.vertices()[old];
    }
    let tris = tperm
        .iter()
        .zip(rot)
        .map(|(&t, &r)| {
            let mut x = m.triangles()[t].map(|i| inv[i as usize]);
            x.rotate_left(r % 3);
            x
        })
        .collect();
    Mesh::new(verts, tris).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn section_is_invariant_under_permutation(
        seed in any::<u64>(),
        z in -0.95f64..0.95,
        nx in -1.0f64..1.0,
        ny in -1.0f64..1.0,
    ) {
        let m = icosphere(DVec3::ZERO, 1.0, 2);
        let nv = m.vertices().len();
        let nt = m.len();
        // A cheap deterministic shuffle from the seed.
        let mut s = seed | 1;
        let mut next = || { s ^= s << 13; s ^= s >> 7; s ^= s << 17; s };
        let mut vperm: Vec<usize> = (0..nv).collect();
        for i in (1..nv).rev() { let j = (next() % (i as u64 + 1)) as usize; vperm.swap(i, j); }
        let mut tperm: Vec<usize> = (0..nt).collect();
        for i in (1..nt).rev() { let j = (next() % (i as u64 + 1)) as usize; tperm.swap(i, j); }
        let rot: Vec<usize> = (0..nt).map(|_| (next() % 3) as usize).collect();
        let p = permuted(&m, &vperm, &tperm, &rot);
        let n = DVec3::new(nx, ny, 1.0);
        let a = section(&m, DVec3::new(0.0, 0.0, z), n).unwrap();
        let b = section(&p, DVec3::new(0.0, 0.0, z), n).unwrap();
        prop_assert_eq!(a.len(), 1);
        prop_assert_eq!(a, b);
    }
}
