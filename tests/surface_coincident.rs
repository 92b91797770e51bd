//! Analytic surfaces coinciding over a region (issue 13, item 1): their intersection is the
//! region's boundary loops, closed, as coplanar regions give theirs. Two pieces of one
//! cylinder, a sphere cap against its sphere, two cones on one meridian line, a revolved
//! cylinder piece against the cylinder. References are the closed forms written out here.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_tol, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::PI;
use std::sync::Arc;

const CT: f64 = 1e-7;

fn rev(p0: DVec3, p1: DVec3, angle: f64) -> Surface {
    let c = Curve::line(p0, p1).unwrap();
    Surface::revolve(Arc::new(c), DVec3::ZERO, DVec3::Z, angle).unwrap()
}

fn circle_at(c: &Polyline3, rho: f64, z: f64) -> bool {
    c.closed
        && c.points
            .iter()
            .all(|p| (p.truncate().length() - rho).abs() <= 1e-12 && (p.z - z).abs() <= 1e-12)
        && (c.length() - 2.0 * PI * rho).abs() <= 1e-6 * 2.0 * PI * rho
}

#[test]
fn two_pieces_of_one_cylinder_overlap_in_a_band_bounded_by_two_circles() {
    let a = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 5.0).unwrap();
    // The same band [3, 5] whichever way the second one points.
    for b in [
        Surface::cylinder(DVec3::new(0.0, 0.0, 3.0), DVec3::Z, 1.0, 5.0).unwrap(),
        Surface::cylinder(DVec3::new(0.0, 0.0, 8.0), -DVec3::Z, 1.0, 5.0).unwrap(),
    ] {
        for r in [
            surface_intersect_tol(&a, &b, CT, 1e-9).unwrap(),
            surface_intersect_tol(&b, &a, CT, 1e-9).unwrap(),
        ] {
            assert_eq!(r.len(), 2, "{r:?}");
            assert!(r.iter().any(|c| circle_at(c, 1.0, 3.0)));
            assert!(r.iter().any(|c| circle_at(c, 1.0, 5.0)));
        }
    }
    // End to end they share one circle; apart, nothing.
    let b = Surface::cylinder(DVec3::new(0.0, 0.0, 5.0), DVec3::Z, 1.0, 2.0).unwrap();
    let r = surface_intersect_tol(&a, &b, CT, 1e-9).unwrap();
    assert_eq!(r.len(), 1);
    assert!(circle_at(&r[0], 1.0, 5.0));
    let b = Surface::cylinder(DVec3::new(0.0, 0.0, 6.0), DVec3::Z, 1.0, 2.0).unwrap();
    assert!(surface_intersect_tol(&a, &b, CT, 1e-9).unwrap().is_empty());
    // A revolved segment ρ = 1, z in [1, 2] is a piece of the same cylinder.
    let piece = rev(
        DVec3::new(1.0, 0.0, 1.0),
        DVec3::new(1.0, 0.0, 2.0),
        2.0 * PI,
    );
    let r = surface_intersect_tol(&piece, &a, CT, 1e-9).unwrap();
    assert_eq!(r.len(), 2, "{r:?}");
    assert!(r.iter().any(|c| circle_at(c, 1.0, 1.0)));
    assert!(r.iter().any(|c| circle_at(c, 1.0, 2.0)));
}

#[test]
fn a_sphere_cap_against_its_sphere_gives_the_cap_boundary() {
    // The cap of the sphere |p − (0,0,1)| = 2 from its pole to polar angle 0.6.
    let c = DVec3::new(0.0, 0.0, 1.0);
    let at = |t: f64| c + 2.0 * DVec3::new(t.sin(), 0.0, t.cos());
    let arc = Curve::arc3(at(0.0), at(0.3), at(0.6)).unwrap();
    let sphere = Surface::sphere(c, 2.0).unwrap();
    let (rho, z) = (2.0 * 0.6f64.sin(), 1.0 + 2.0 * 0.6f64.cos());
    let cap = Surface::revolve(Arc::new(arc.clone()), c, DVec3::Z, 2.0 * PI).unwrap();
    for r in [
        surface_intersect_tol(&cap, &sphere, CT, 1e-9).unwrap(),
        surface_intersect_tol(&sphere, &cap, CT, 1e-9).unwrap(),
    ] {
        assert_eq!(r.len(), 1, "{r:?}");
        assert!(circle_at(&r[0], rho, z));
    }
    // Half the cap: profile, rim half circle, profile back (the pole's arc is a point).
    let half = Surface::revolve(Arc::new(arc), c, DVec3::Z, PI).unwrap();
    let r = surface_intersect_tol(&half, &sphere, CT, 1e-9).unwrap();
    assert_eq!(r.len(), 1, "{r:?}");
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!((p.distance(c) - 2.0).abs() <= 1e-12, "{p}");
        assert!(p.y >= -1e-12 && p.z >= z - 1e-12, "{p}");
    }
    let exact = 2.0 * 1.2 + PI * rho;
    assert!(
        (r[0].length() - exact).abs() <= 1e-6 * exact,
        "{}",
        r[0].length()
    );
    // A sphere of another radius about the same centre: the cap is not on it.
    let other = Surface::sphere(c, 2.5).unwrap();
    assert!(surface_intersect_tol(&cap, &other, CT, 1e-9)
        .unwrap()
        .is_empty());
}

#[test]
fn two_cones_on_one_meridian_line_overlap_in_a_band() {
    // z = 2ρ: the first for z in [0, 4] all round, the second for z in [2, 6] over a quarter.
    let a = rev(DVec3::ZERO, DVec3::new(2.0, 0.0, 4.0), 2.0 * PI);
    let b = rev(
        DVec3::new(1.0, 0.0, 2.0),
        DVec3::new(3.0, 0.0, 6.0),
        PI / 2.0,
    );
    let r = surface_intersect_tol(&a, &b, CT, 1e-9).unwrap();
    assert_eq!(r.len(), 1, "{r:?}");
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!((p.z - 2.0 * p.truncate().length()).abs() <= 1e-12, "{p}");
        assert!(p.x >= -1e-12 && p.y >= -1e-12, "{p}");
        assert!((2.0 - 1e-12..=4.0 + 1e-12).contains(&p.z), "{p}");
    }
    // Two rulings √5 long, quarter circles of radius 2 and 1.
    let exact = 2.0 * 5f64.sqrt() + 1.5 * PI;
    assert!(
        (r[0].length() - exact).abs() <= 1e-6 * exact,
        "{}",
        r[0].length()
    );
    // Full against full: the circles at z = 2 and z = 4.
    let b = rev(
        DVec3::new(1.0, 0.0, 2.0),
        DVec3::new(3.0, 0.0, 6.0),
        2.0 * PI,
    );
    let r = surface_intersect_tol(&a, &b, CT, 1e-9).unwrap();
    assert_eq!(r.len(), 2, "{r:?}");
    assert!(r.iter().any(|c| circle_at(c, 1.0, 2.0)));
    assert!(r.iter().any(|c| circle_at(c, 2.0, 4.0)));
}
