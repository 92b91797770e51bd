//! Plane sections that touch without crossing (issue 13, item 3): a plane tangent to a sphere
//! gives the point of contact, tangent to a cylinder along a ruling the ruling, the top plane of
//! a torus its top circle, and a plane lifted 1e-3 off gives nothing. For the kinds sectioned
//! through their mesh (a torus cut by a plane parallel to its axis), the contact the mesh misses
//! is found on the true surface. References are the closed forms written out here.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_section_seeded, surface_section_tol, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::PI;
use std::sync::Arc;

fn section(s: &Surface, p: DVec3, n: DVec3) -> Vec<Polyline3> {
    surface_section_tol(s, p, n, 1e-7, 1e-9).unwrap()
}

/// That the midpoint of every chord of `r` is within CHORDTOL + GEOMTOL (1e-7 + 1e-9 here) of
/// both the plane through `p0` with unit normal `n` and the surface (`off_surface`, a closed
/// form).
fn assert_chords_on(
    name: &str,
    r: &[Polyline3],
    (p0, n): (DVec3, DVec3),
    off_surface: impl Fn(DVec3) -> f64,
) {
    for c in r {
        let k = c.points.len();
        let segs = if c.closed { k } else { k.saturating_sub(1) };
        for i in 0..segs {
            let m = 0.5 * (c.points[i] + c.points[(i + 1) % k]);
            let d = n.dot(m - p0).abs().max(off_surface(m));
            assert!(
                d <= 1e-7 + 1e-9,
                "{name}: chord {i}'s midpoint {m} {d:e} off"
            );
        }
    }
}

/// The distance from `p` to the torus [`torus`].
fn off_torus(p: DVec3) -> f64 {
    let rho = p.truncate().length();
    (((rho - 3.0).powi(2) + p.z * p.z).sqrt() - 1.0).abs()
}

fn one_point(r: &[Polyline3]) -> DVec3 {
    assert_eq!(r.len(), 1, "{r:?}");
    assert_eq!(r[0].points.len(), 1, "{r:?}");
    r[0].points[0]
}

/// The torus of tube radius 1 about the circle ρ = 3 in z = 0.
fn torus() -> Surface {
    let tube = Curve::circle(DVec3::new(3.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap();
    Surface::revolve(Arc::new(tube), DVec3::ZERO, DVec3::Z, 2.0 * PI).unwrap()
}

#[test]
fn a_plane_tangent_to_a_sphere_gives_the_point() {
    let c = DVec3::new(1.0, 2.0, 3.0);
    let s = Surface::sphere(c, 2.0).unwrap();
    let p = one_point(&section(&s, DVec3::new(0.0, 0.0, 5.0), DVec3::Z));
    assert!(p.distance(DVec3::new(1.0, 2.0, 5.0)) <= 1e-12, "{p}");
    // An oblique tangent plane touches at c + 2 n.
    let n = DVec3::new(1.0, -2.0, 2.0) / 3.0;
    let p = one_point(&section(&s, c + n * 2.0, n));
    assert!(p.distance(c + n * 2.0) <= 1e-12, "{p}");
    // Within GEOMTOL outside still touches; 1e-3 off does not.
    let p = one_point(&section(&s, c + n * (2.0 + 5e-10), n));
    assert!(p.distance(c + n * 2.0) <= 1e-9, "{p}");
    assert!(section(&s, c + n * 2.001, n).is_empty());
}

#[test]
fn a_plane_tangent_to_a_cylinder_gives_the_ruling() {
    let axis = DVec3::new(0.0, 1.0, 1.0).normalize();
    let s = Surface::cylinder(DVec3::ZERO, axis, 1.0, 5.0).unwrap();
    let r = section(&s, DVec3::X, DVec3::X);
    assert_eq!(r.len(), 1, "{r:?}");
    assert!(!r[0].closed);
    let (a, b) = (r[0].points[0], *r[0].points.last().unwrap());
    let (e0, e1) = (DVec3::X, DVec3::X + axis * 5.0);
    let ends_ok = (a.distance(e0) <= 1e-12 && b.distance(e1) <= 1e-12)
        || (a.distance(e1) <= 1e-12 && b.distance(e0) <= 1e-12);
    assert!(ends_ok, "{a} {b}");
    let off = |p: DVec3| (p - axis * p.dot(axis)).length() - 1.0;
    assert_chords_on("ruling", &r, (DVec3::X, DVec3::X), |p| off(p).abs());
    assert!(section(&s, DVec3::X * 1.001, DVec3::X).is_empty());
}

#[test]
fn the_top_plane_of_a_torus_gives_its_top_circle() {
    let t = torus();
    for z in [1.0, -1.0] {
        let r = section(&t, DVec3::new(0.0, 0.0, z), DVec3::Z);
        assert_eq!(r.len(), 1, "{r:?}");
        assert!(r[0].closed);
        for p in &r[0].points {
            assert!((p.truncate().length() - 3.0).abs() <= 1e-9, "{p}");
            assert!((p.z - z).abs() <= 1e-12, "{p}");
        }
        let l = r[0].length();
        assert!((l - 6.0 * PI).abs() <= 1e-6 * 6.0 * PI, "{l}");
        assert_chords_on("top circle", &r, (DVec3::Z * z, DVec3::Z), off_torus);
    }
    assert!(section(&t, DVec3::new(0.0, 0.0, 1.001), DVec3::Z).is_empty());
}

#[test]
fn a_plane_touching_a_torus_beside_its_axis_gives_the_point_the_mesh_misses() {
    // x = 4 touches the outer equator at (4, 0, 0) only (the surface curves away both ways).
    let t = torus();
    let (c, s) = (0.5f64.cos(), 0.5f64.sin());
    let tilted = DVec3::new(c, 0.0, s);
    for (p0, n) in [
        (DVec3::new(4.0, 0.0, 0.0), DVec3::X),
        (DVec3::new(0.0, -4.0, 0.0), -DVec3::Y),
        // Tangent at tube angle 0.5 on the outer side, where the torus curves away both ways.
        (DVec3::new(3.0 + c, 0.0, s), tilted),
    ] {
        // A coarse seeding mesh, refined on the true surface.
        let seeded = |p0: DVec3| surface_section_seeded(&t, p0, n, 1e-2, 1e-7, 1e-9).unwrap();
        let p = one_point(&seeded(p0));
        assert!(n.dot(p - p0).abs() <= 1e-9, "{p}");
        // On the torus: (ρ − 3)² + z² = 1.
        let rho = p.truncate().length();
        assert!(
            (((rho - 3.0).powi(2) + p.z * p.z).sqrt() - 1.0).abs() <= 1e-12,
            "{p}"
        );
        assert!(p.distance(p0) <= 1e-6, "{p} vs {p0}");
        assert!(seeded(p0 + n * 1e-3).is_empty());
        // Pushed 1e-3 into the tube it crosses: one small closed curve, no point.
        let r = seeded(p0 - n * 1e-3);
        assert_eq!(r.len(), 1, "{r:?}");
        assert!(r[0].closed && r[0].points.len() > 3, "{r:?}");
        for q in &r[0].points {
            assert!(n.dot(*q - p0 + n * 1e-3).abs() <= 1e-9, "{q}");
            let rho = q.truncate().length();
            assert!((((rho - 3.0).powi(2) + q.z * q.z).sqrt() - 1.0).abs() <= 1e-12);
        }
        assert_chords_on("small loop", &r, (p0 - n * 1e-3, n), off_torus);
    }
}
