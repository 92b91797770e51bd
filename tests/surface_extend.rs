//! Paper 003: boundary corners and extension strips without cracks.

use lispcad::geom::mesh::{corners, extend, Mesh};
use lispcad::geom::surface::{mesh_surface, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_6, PI};

mod mesh_support;
use mesh_support::l_outline;

fn square() -> Mesh {
    Mesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .unwrap()
}

fn l_shape() -> Mesh {
    let s = Surface::plane(l_outline()).unwrap();
    mesh_surface(&s, 1e-3).unwrap()
}

#[test]
fn square_has_four_corners() {
    let c = corners(&square(), FRAC_PI_6).unwrap();
    assert_eq!(c.len(), 4);
    for p in [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y] {
        assert!(c.contains(&p));
    }
    // Above 90° nothing is a corner.
    assert!(corners(&square(), 1.6).unwrap().is_empty());
    assert!(corners(&square(), -1.0).is_err());
}

#[test]
fn cylinder_rims_have_no_corners() {
    let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    assert!(corners(&m, FRAC_PI_6).unwrap().is_empty());
}

#[test]
fn extended_square_is_crack_free_with_rounded_corners() {
    let d = 0.5;
    let e = extend(&square(), d, FRAC_PI_6).unwrap();
    // One boundary loop: the strips and corner fans close up with the original boundary.
    let b = e.boundary();
    assert_eq!(b.len(), 1);
    // Sides 1 + 4·d, rounded corners: four fans of six 15° triangles.
    let fans = 4.0 * 6.0 * 0.5 * d * d * (15f64).to_radians().sin();
    assert!(
        (e.area() - (1.0 + 4.0 * d + fans)).abs() < 1e-12,
        "{}",
        e.area()
    );
    assert!(e.vertices().iter().all(|p| p.z == 0.0));
    // Every outer boundary point is exactly d from the square.
    for p in &b[0].points {
        let dx = (p.x - p.x.clamp(0.0, 1.0)).abs();
        let dy = (p.y - p.y.clamp(0.0, 1.0)).abs();
        assert!(((dx * dx + dy * dy).sqrt() - d).abs() < 1e-12);
    }
    // Consistent orientation: every triangle faces +z like the original.
    for t in 0..e.len() {
        let [a, b, c] = e.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
}

#[test]
fn reflex_corner_is_mitred() {
    let e = extend(&l_shape(), 0.25, FRAC_PI_6).unwrap();
    assert_eq!(e.boundary().len(), 1);
    // The inner corner (1,1) moves diagonally to (1.25, 1.25).
    assert!(e
        .vertices()
        .iter()
        .any(|p| (*p - DVec3::new(1.25, 1.25, 0.0)).length() < 1e-12));
    for t in 0..e.len() {
        let [a, b, c] = e.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
}

#[test]
fn cylinder_extends_along_its_axis() {
    let s = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    let e = extend(&m, 0.5, FRAC_PI_6).unwrap();
    let (lo, hi) = e
        .vertices()
        .iter()
        .fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p.z), h.max(p.z)));
    assert!(
        (lo + 0.5).abs() < 1e-9 && (hi - 2.5).abs() < 1e-9,
        "{lo} {hi}"
    );
    assert_eq!(e.boundary().len(), 2);
    let exact = 2.0 * PI * 3.0;
    assert!((e.area() - exact).abs() < 0.01 * exact);
    assert!(extend(&m, 0.0, FRAC_PI_6).is_err());
}
