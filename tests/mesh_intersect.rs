//! Mesh/mesh intersection: two spheres meet in the expected circle; result independent of
//! argument order and of vertex/triangle order; touching and coplanar cases.

use lispcad::geom::mesh::{icosphere, intersect_meshes, intersect_meshes_with_stats, Mesh};
use lispcad::geom::{DMat4, DVec3};
use proptest::prelude::*;

mod mesh_support;
use mesh_support::{grid, triangles_cross};

#[test]
fn two_spheres_meet_in_the_expected_circle() {
    let a = icosphere(DVec3::ZERO, 1.0, 4);
    let b = icosphere(DVec3::new(1.0, 0.05, 0.02), 1.0, 4);
    let (r, stats) = intersect_meshes_with_stats(&a, &b);
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    assert_eq!(stats.irregular_pairs, 0);
    assert_eq!(r[0].points.len(), stats.intersecting_pairs);
    assert!(stats.plane_pairs < stats.box_pairs);
    // The exact circle: plane through the midpoint ⟂ the centre line, radius √(1 − d²/4).
    let c = DVec3::new(1.0, 0.05, 0.02);
    let d = c.length();
    let axis = c / d;
    let rad = (1.0 - d * d / 4.0).sqrt();
    for p in &r[0].points {
        let h = (*p - c * 0.5).dot(axis);
        let q = (*p - c * 0.5) - axis * h;
        // Level-4 sagitta is below 1.2e-3; the circle of the meshes lies inside both spheres.
        assert!(h.abs() < 3e-3, "{h}");
        assert!((q.length() - rad).abs() < 3e-3);
    }
}

#[test]
fn argument_order_does_not_matter() {
    let a = icosphere(DVec3::ZERO, 1.0, 3);
    let m = DMat4::from_translation(DVec3::new(0.5, 0.3, 0.2))
        * DMat4::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.3);
    let b = a.map_vertices(|p| m.transform_point3(p)).unwrap();
    let ab = intersect_meshes(&a, &b);
    let ba = intersect_meshes(&b, &a);
    assert_eq!(ab.len(), 1);
    assert!(ab[0].closed);
    assert_eq!(ab, ba);
}

#[test]
fn plane_through_sphere_vertices_and_edges() {
    // z = 0 contains icosphere vertices and edges: the touching case of paper 001 step 5.
    let a = icosphere(DVec3::ZERO, 1.0, 3);
    let g = grid(7, 1.5, 0.0);
    let r = intersect_meshes(&a, &g);
    assert_eq!(
        r.len(),
        1,
        "{:?}",
        r.iter().map(|p| p.points.len()).collect::<Vec<_>>()
    );
    assert!(r[0].closed);
    assert!(r[0].points.iter().all(|p| p.z.abs() < 1e-15));
    assert_eq!(r, intersect_meshes(&g, &a));
}

#[test]
fn crossing_planes_give_a_line() {
    let a = grid(4, 1.0, 0.0);
    // A vertical plane x = 0.3 made of a rotated grid.
    let m = DMat4::from_translation(DVec3::new(0.3, 0.0, 0.0))
        * DMat4::from_rotation_y(std::f64::consts::FRAC_PI_2);
    let b = grid(3, 0.5, 0.0)
        .map_vertices(|p| m.transform_point3(p))
        .unwrap();
    let r = intersect_meshes(&a, &b);
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    let pts = &r[0].points;
    assert!(pts
        .iter()
        .all(|p| (p.x - 0.3).abs() < 1e-15 && p.z.abs() < 1e-15));
    assert!((pts[0].y + 0.5).abs() < 1e-12 && (pts[pts.len() - 1].y - 0.5).abs() < 1e-12);
}

#[test]
fn coplanar_overlap_is_its_boundary_and_disjoint_meshes_give_no_curve() {
    let a = grid(3, 1.0, 0.0);
    let b = grid(5, 0.7, 0.0);
    let r = intersect_meshes(&a, &b);
    // Overlapping coplanar regions are a region, not a curve: its boundary loop, the square
    // |x|, |y| <= 0.7 (its sides split where the facets of a cross them).
    assert_eq!(r.len(), 1, "{r:?}");
    assert!(r[0].closed);
    assert!((r[0].length() - 5.6).abs() <= 1e-12, "{}", r[0].length());
    assert!(r[0]
        .points
        .iter()
        .all(|p| p.z == 0.0
            && ((p.x.abs() - 0.7).abs() <= 1e-15 || (p.y.abs() - 0.7).abs() <= 1e-15)));
    let c = grid(3, 1.0, 2.0);
    assert!(intersect_meshes(&a, &c).is_empty());
    let empty = Mesh::new(vec![], vec![]).unwrap();
    assert!(intersect_meshes(&a, &empty).is_empty());
}

#[test]
fn touching_spheres_do_not_produce_garbage() {
    // Two spheres mirrored about the tangent plane at the top vertex: they touch at that
    // vertex and share the vertical plane x = 0 with collinear edges.
    let a = icosphere(DVec3::ZERO, 1.0, 2);
    let top = a
        .vertices()
        .iter()
        .copied()
        .max_by(|p, q| p.z.total_cmp(&q.z))
        .unwrap();
    let b = a
        .map_vertices(|p| DVec3::new(p.x, p.y, 2.0 * top.z - p.z))
        .unwrap();
    let (r, stats) = intersect_meshes_with_stats(&a, &b);
    // Translated apart by the tie-break, the surfaces only touch: no curve at all.
    assert!(r.is_empty(), "{r:?}");
    assert_eq!(stats.irregular_pairs, 0);
    assert_eq!(r, intersect_meshes(&b, &a));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn invariant_under_triangle_order(seed in any::<u64>(), dx in 0.2f64..1.5, dy in -0.3f64..0.3) {
        let a = icosphere(DVec3::ZERO, 1.0, 2);
        let b = icosphere(DVec3::new(dx, dy, 0.1), 0.8, 2);
        let mut s = seed | 1;
        let mut next = || { s ^= s << 13; s ^= s >> 7; s ^= s << 17; s };
        let mut tris = b.triangles().to_vec();
        for i in (1..tris.len()).rev() { let j = (next() % (i as u64 + 1)) as usize; tris.swap(i, j); }
        for t in tris.iter_mut() { t.rotate_left((next() % 3) as usize); }
        let b2 = Mesh::new(b.vertices().to_vec(), tris).unwrap();
        let r1 = intersect_meshes(&a, &b);
        let r2 = intersect_meshes(&b2, &a);
        prop_assert_eq!(r1.len(), 1);
        prop_assert!(r1[0].closed);
        prop_assert_eq!(r1, r2);
    }
}

#[test]
fn exactly_the_truly_intersecting_pairs() {
    let a = icosphere(DVec3::ZERO, 1.0, 3);
    let m = DMat4::from_translation(DVec3::new(0.5, 0.3, 0.2))
        * DMat4::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.3);
    let b = a.map_vertices(|p| m.transform_point3(p)).unwrap();
    let mut truth = 0;
    for ta in 0..a.len() {
        let pa = a.corners_of(ta);
        for tb in 0..b.len() {
            let pb = b.corners_of(tb);
            truth += triangles_cross(pa, pb) as usize;
        }
    }
    let (r, stats) = intersect_meshes_with_stats(&a, &b);
    assert_eq!(stats.intersecting_pairs, truth);
    assert!(stats.box_pairs > truth);
    assert_eq!(r.len(), 1);
    assert_eq!(
        r[0].points.len(),
        truth,
        "one curve point per intersecting pair on a closed loop"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn swapping_the_arguments_gives_the_same_curves(
        ax in -1.0f64..1.0, ay in -1.0f64..1.0, angle in 0.0f64..3.0,
        tx in -1.5f64..1.5, ty in -1.0f64..1.0, tz in -1.0f64..1.0,
    ) {
        let a = icosphere(DVec3::ZERO, 1.0, 2);
        let m = DMat4::from_translation(DVec3::new(tx, ty, tz))
            * DMat4::from_axis_angle(DVec3::new(ax, ay, 1.0).normalize(), angle);
        let b = a.map_vertices(|p| m.transform_point3(p)).unwrap();
        let ab = intersect_meshes(&a, &b);
        let ba = intersect_meshes(&b, &a);
        prop_assert_eq!(&ab, &ba);
        // Closed meshes meet in closed curves.
        prop_assert!(ab.iter().all(|p| p.closed));
    }
}

#[test]
fn a_mesh_against_itself_has_no_curve() {
    let a = icosphere(DVec3::ZERO, 1.0, 2);
    assert!(intersect_meshes(&a, &a.clone()).is_empty());
}
