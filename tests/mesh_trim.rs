//! Trimming: the parts add up to the whole, share the cut exactly, and the keep point picks
//! the side.

use lispcad::geom::mesh::{icosphere, trim, Mesh};
use lispcad::geom::{DMat4, DVec3};

mod mesh_support;
use mesh_support::grid;

fn sorted_points(m: &Mesh) -> Vec<[u64; 3]> {
    let mut pts: Vec<[u64; 3]> = m
        .boundary()
        .iter()
        .flat_map(|l| l.points.clone())
        .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
        .collect();
    pts.sort_unstable();
    pts
}

fn check_split(whole: &Mesh, cutter: &Mesh, keep: DVec3) -> (Mesh, Mesh) {
    let r = trim(whole, cutter, keep).unwrap();
    assert!(r.split_facets > 0);
    let sum = r.kept.area() + r.removed.area();
    assert!(
        (sum - whole.area()).abs() <= 1e-12 * whole.area(),
        "{sum} vs {}",
        whole.area()
    );
    (r.kept, r.removed)
}

#[test]
fn sphere_cut_by_a_plane_gives_cap_and_rest_sharing_the_cut() {
    let s = icosphere(DVec3::ZERO, 1.0, 3);
    let cutter = grid(3, 2.0, 0.3);
    let (cap, rest) = check_split(&s, &cutter, DVec3::new(0.0, 0.0, 2.0));
    // The cap is the smaller part, above the plane.
    assert!(cap.area() < rest.area());
    assert!(cap.vertices().iter().all(|p| p.z >= 0.3 - 1e-12));
    assert!(rest.vertices().iter().all(|p| p.z <= 0.3 + 1e-12));
    let (cb, rb) = (cap.boundary(), rest.boundary());
    assert_eq!(cb.len(), 1);
    assert_eq!(rb.len(), 1);
    // The same cut vertices, bit for bit.
    assert_eq!(sorted_points(&cap), sorted_points(&rest));
    // The analytic cap area 2πrh with h = 0.7, within the tessellation error.
    let exact = 2.0 * std::f64::consts::PI * 0.7;
    assert!((cap.area() - exact).abs() < 0.02 * exact);
    // Keeping the other side swaps the parts.
    let r = trim(&s, &cutter, DVec3::new(0.0, 0.0, -2.0)).unwrap();
    assert!((r.kept.area() - rest.area()).abs() < 1e-12);
}

#[test]
fn plane_cut_by_a_sphere_gives_a_disc_with_a_hole_partner() {
    let g = grid(10, 2.0, 0.1);
    let m = DMat4::from_axis_angle(DVec3::new(0.3, 0.1, 1.0).normalize(), 0.2);
    let s = icosphere(DVec3::ZERO, 1.0, 3)
        .map_vertices(|p| m.transform_point3(p))
        .unwrap();
    let (disc, outer) = check_split(&g, &s, DVec3::new(0.0, 0.0, 0.1));
    assert_eq!(disc.boundary().len(), 1);
    assert_eq!(outer.boundary().len(), 2);
    let r2 = 1.0 - 0.01;
    assert!((disc.area() - std::f64::consts::PI * r2).abs() < 0.03);
}

#[test]
fn cut_through_mesh_vertices_and_along_edges() {
    // The plane z = 0 runs through icosphere vertices and along its edges.
    let s = icosphere(DVec3::ZERO, 1.0, 2);
    let cutter = grid(4, 2.0, 0.0);
    let r = trim(&s, &cutter, DVec3::new(0.0, 0.0, 3.0)).unwrap();
    let sum = r.kept.area() + r.removed.area();
    assert!((sum - s.area()).abs() <= 1e-12 * s.area());
    assert!(
        (r.kept.area() - r.removed.area()).abs() < 1e-9,
        "symmetric halves"
    );
    assert_eq!(r.kept.boundary().len(), 1);
    assert_eq!(sorted_points(&r.kept), sorted_points(&r.removed));
}

#[test]
fn a_cutter_that_misses_keeps_everything() {
    let s = icosphere(DVec3::ZERO, 1.0, 1);
    let r = trim(&s, &grid(2, 1.0, 5.0), DVec3::ZERO).unwrap();
    assert_eq!(r.kept.len(), s.len());
    assert!(r.removed.is_empty());
    assert!(trim(&s, &grid(2, 1.0, 5.0), DVec3::NAN).is_err());
}

use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn trimmed_parts_add_up_and_share_the_cut(z in -0.8f64..0.8, ax in -0.5f64..0.5, ay in -0.5f64..0.5) {
        let s = icosphere(DVec3::ZERO, 1.0, 2);
        let m = DMat4::from_translation(DVec3::new(0.0, 0.0, z)) * DMat4::from_rotation_x(ax) * DMat4::from_rotation_y(ay);
        let cutter = grid(3, 3.0, 0.0).map_vertices(|p| m.transform_point3(p)).unwrap();
        let r = trim(&s, &cutter, DVec3::new(0.0, 0.0, 5.0)).unwrap();
        let sum = r.kept.area() + r.removed.area();
        prop_assert!((sum - s.area()).abs() <= 1e-12 * s.area());
        prop_assert_eq!(r.kept.boundary().len(), 1);
        prop_assert_eq!(r.removed.boundary().len(), 1);
        prop_assert_eq!(sorted_points(&r.kept), sorted_points(&r.removed));
    }
}

#[test]
fn hole_inside_a_single_facet() {
    use lispcad::geom::surface::{mesh_surface, Surface};
    // Two big triangles; a thin cylinder pierces the middle of one: the cut is a loop that
    // touches no facet edge (the case paper 001 avoids by refining).
    let square = Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(2.0, 2.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap();
    let cyl = Surface::cylinder(DVec3::new(1.4, 0.5, -1.0), DVec3::Z, 0.2, 2.0).unwrap();
    let cutter = mesh_surface(&cyl, 1e-3).unwrap();
    let r = trim(&square, &cutter, DVec3::new(1.4, 0.5, 0.0)).unwrap();
    assert_eq!(r.split_facets, 1);
    let disc = std::f64::consts::PI * 0.04;
    assert!(
        r.kept.area() < disc && r.kept.area() > disc * 0.99,
        "{}",
        r.kept.area()
    );
    assert!((r.kept.area() + r.removed.area() - 4.0).abs() < 1e-12);
    assert_eq!(r.kept.boundary().len(), 1);
    assert_eq!(r.removed.boundary().len(), 2, "outer square and the hole");
    assert_eq!(sorted_points(&r.kept), {
        // The hole's points are the disc's boundary, bit for bit.
        let mut hole: Vec<[u64; 3]> = r
            .removed
            .boundary()
            .iter()
            .filter(|l| {
                l.points
                    .iter()
                    .all(|p| (p.x - 1.4).abs() < 0.3 && (p.y - 0.5).abs() < 0.3)
            })
            .flat_map(|l| l.points.clone())
            .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
            .collect();
        hole.sort_unstable();
        hole
    });
    // Keeping the outside gives the square with the hole.
    let o = trim(&square, &cutter, DVec3::new(0.1, 1.9, 0.0)).unwrap();
    assert!((o.kept.area() - r.removed.area()).abs() < 1e-12);
}
