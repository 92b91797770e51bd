//! Parametric surfaces and their tessellation: shape, chord tolerance, seams, areas.

use lispcad::geom::mesh::section;
use lispcad::geom::surface::{mesh_surface, CurveRef, ParamSurface, SampledCurve, Surface};
use lispcad::geom::{DVec3, ParamCurve};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

mod mesh_support;
use mesh_support::l_outline;

struct Line(DVec3, DVec3);
impl ParamCurve for Line {
    fn eval(&self, t: f64) -> DVec3 {
        self.0.lerp(self.1, t)
    }
}

struct Circle {
    c: DVec3,
    r: f64,
}
impl ParamCurve for Circle {
    fn eval(&self, t: f64) -> DVec3 {
        let a = TAU * t;
        self.c + self.r * DVec3::new(a.cos(), a.sin(), 0.0)
    }
}

fn line(a: DVec3, b: DVec3) -> CurveRef {
    Arc::new(Line(a, b))
}

#[test]
fn cylinder_mesh_is_within_tolerance_and_has_two_rims() {
    let tol = 1e-3;
    let s = Surface::cylinder(
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::new(0.0, 1.0, 1.0),
        2.0,
        4.0,
    )
    .unwrap();
    let m = mesh_surface(&s, tol).unwrap();
    let exact = TAU * 2.0 * 4.0;
    assert!(m.area() < exact && m.area() > exact * (1.0 - 2.0 * tol / 2.0) - 1e-9);
    let b = m.boundary();
    assert_eq!(b.len(), 2, "seam welded: only the two rims are boundary");
    assert!(b.iter().all(|l| l.closed));
    let Surface::Cylinder(c) = s else {
        unreachable!()
    };
    for v in m.vertices() {
        let d = *v - c.base;
        let h = d.dot(c.axis);
        assert!(((d - c.axis * h).length() - 2.0).abs() < 1e-12);
    }
}

#[test]
fn sphere_mesh_is_closed_and_near_4pi() {
    let s = Surface::sphere(DVec3::new(0.0, 0.0, 1.0), 1.5).unwrap();
    let tol = 1e-3;
    let m = mesh_surface(&s, tol).unwrap();
    assert!(m.boundary().is_empty());
    let exact = 4.0 * PI * 1.5 * 1.5;
    assert!(m.area() < exact && m.area() > exact * 0.99);
    // Triangle centroids are within the chord tolerance of the sphere.
    for t in 0..m.len() {
        let [a, b, c] = m.corners_of(t);
        let g = (a + b + c) / 3.0;
        assert!(1.5 - (g - DVec3::Z).length() <= tol * 1.5);
    }
}

#[test]
fn revolved_segment_is_a_cylinder_and_its_section_matches_the_profile() {
    let prof = line(DVec3::new(1.0, 0.0, 0.0), DVec3::new(1.0, 0.0, 2.0));
    let s = Surface::revolve(prof, DVec3::ZERO, DVec3::Z, TAU).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    assert_eq!(m.boundary().len(), 2);
    // The section by a plane through the axis gives back the profile (and its mirror).
    let r = section(&m, DVec3::ZERO, DVec3::Y).unwrap();
    assert_eq!(r.len(), 2);
    for p in &r {
        assert!(p
            .points
            .iter()
            .all(|q| (q.x.abs() - 1.0).abs() < 1e-12 && q.y.abs() < 1e-12));
    }
    // A half revolution keeps its two open ends.
    let s = Surface::revolve(
        line(DVec3::X, DVec3::new(2.0, 0.0, 1.0)),
        DVec3::ZERO,
        DVec3::Z,
        PI,
    )
    .unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    assert_eq!(m.boundary().len(), 1);
    assert!(Surface::revolve(line(DVec3::X, DVec3::Y), DVec3::ZERO, DVec3::Z, 7.0).is_err());
    assert!(Surface::revolve(line(DVec3::X, DVec3::Y), DVec3::ZERO, DVec3::ZERO, 1.0).is_err());
}

#[test]
fn ruled_and_coons_of_a_unit_square_are_flat() {
    let (a, b, c, d) = (DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y);
    let r = Surface::ruled(line(a, b), line(d, c));
    let m = mesh_surface(&r, 1e-3).unwrap();
    assert!((m.area() - 1.0).abs() < 1e-12);
    // Coons from four edges, some given backwards.
    let s = Surface::boundary([line(a, b), line(c, b), line(c, d), line(a, d)]).unwrap();
    for (u, v) in [(0.0, 0.0), (0.3, 0.7), (1.0, 1.0), (0.5, 0.0)] {
        let p = s.eval(u, v);
        assert!((p - DVec3::new(u, v, 0.0)).length() < 1e-15, "{u} {v} {p}");
    }
    let m = mesh_surface(&s, 1e-3).unwrap();
    assert!((m.area() - 1.0).abs() < 1e-12);
}

#[test]
fn coons_interpolates_curved_boundaries() {
    // Bottom edge bulges in z; the patch must reproduce all four boundary curves.
    struct Bulge;
    impl ParamCurve for Bulge {
        fn eval(&self, t: f64) -> DVec3 {
            DVec3::new(t, 0.0, (PI * t).sin())
        }
    }
    let (b, c, d) = (DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y);
    let s = Surface::boundary([
        Arc::new(Bulge),
        line(b, c),
        line(c, d),
        line(d, DVec3::ZERO),
    ])
    .unwrap();
    for i in 0..=10 {
        let t = i as f64 / 10.0;
        assert!((s.eval(t, 0.0) - Bulge.eval(t)).length() < 1e-15);
        assert!((s.eval(1.0, t) - b.lerp(c, t)).length() < 1e-15);
        assert!((s.eval(0.0, t) - DVec3::new(0.0, t, 0.0)).length() < 1e-15);
    }
}

#[test]
fn sweep_of_a_circle_along_a_line_is_a_tube() {
    let prof: CurveRef = Arc::new(Circle {
        c: DVec3::ZERO,
        r: 0.5,
    });
    let guide = line(DVec3::ZERO, DVec3::new(0.0, 0.0, 3.0));
    let s = Surface::sweep(prof, guide).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    for v in m.vertices() {
        assert!(((v.x * v.x + v.y * v.y).sqrt() - 0.5).abs() < 1e-12);
    }
    // Along a helix the rotation-minimising frame keeps the profile's distance to the guide.
    struct Helix;
    impl ParamCurve for Helix {
        fn eval(&self, t: f64) -> DVec3 {
            let a = 2.0 * TAU * t;
            DVec3::new(3.0 * a.cos(), 3.0 * a.sin(), 2.0 * t)
        }
    }
    let prof: CurveRef = Arc::new(
        SampledCurve::new(
            vec![DVec3::new(3.0, -0.2, -0.1), DVec3::new(3.0, 0.2, 0.1)],
            false,
        )
        .unwrap(),
    );
    let s = Surface::sweep(prof, Arc::new(Helix)).unwrap();
    for k in 0..=20 {
        let v = k as f64 / 20.0;
        let d0 = s.eval(0.0, v).distance(Helix.eval(v));
        let d1 = s.eval(1.0, v).distance(Helix.eval(v));
        let exp = (0.04f64 + 0.01).sqrt();
        assert!(
            (d0 - exp).abs() < 1e-9 && (d1 - exp).abs() < 1e-9,
            "{d0} {d1}"
        );
    }
}

#[test]
fn plane_surface_triangulates_non_convex_regions() {
    // Closed by repeating the first point, which `plane` accepts.
    let mut l = l_outline();
    l.push(l[0]);
    let s = Surface::plane(l).unwrap();
    let m = mesh_surface(&s, 1e-3).unwrap();
    assert_eq!(m.len(), 4);
    assert!((m.area() - 3.0).abs() < 1e-15);
    assert_eq!(m.boundary().len(), 1);
    // Triangles face along the polygon's (counter-clockwise → +z) normal.
    for t in 0..m.len() {
        let [a, b, c] = m.corners_of(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
    assert!(Surface::plane(vec![DVec3::ZERO, DVec3::X]).is_err());
    assert!(Surface::plane(vec![DVec3::ZERO, DVec3::X, DVec3::new(2.0, 0.0, 0.0)]).is_err());
}

#[test]
fn bad_parameters_are_errors() {
    assert!(Surface::cylinder(DVec3::ZERO, DVec3::Z, -1.0, 1.0).is_err());
    assert!(Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, f64::NAN).is_err());
    assert!(Surface::sphere(DVec3::ZERO, 0.0).is_err());
    let s = Surface::sphere(DVec3::ZERO, 1.0).unwrap();
    assert!(mesh_surface(&s, 0.0).is_err());
    assert!(mesh_surface(&s, f64::NAN).is_err());
}
