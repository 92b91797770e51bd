//! Every surface kind is meshed within CHORDTOL of the true surface (issue 13, item 2): points
//! sampled over every triangle are measured against the surface by closed-form distances
//! (torus, cylinder, sphere, plane) or an upper bound of it (the vertical distance to a graph
//! surface), independent of the mesher.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Mesh;
use lispcad::geom::surface::{mesh_surface, CurveRef, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

fn c(x: Curve) -> CurveRef {
    Arc::new(x)
}

fn line(a: [f64; 3], b: [f64; 3]) -> CurveRef {
    c(Curve::line(DVec3::from_array(a), DVec3::from_array(b)).unwrap())
}

/// Points over every triangle: centroid, edge midpoints and a few fixed interior points.
fn samples(m: &Mesh) -> Vec<DVec3> {
    const W: [[f64; 3]; 7] = [
        [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
        [0.5, 0.5, 0.0],
        [0.0, 0.5, 0.5],
        [0.5, 0.0, 0.5],
        [0.7, 0.2, 0.1],
        [0.1, 0.7, 0.2],
        [0.2, 0.1, 0.7],
    ];
    (0..m.len())
        .flat_map(|t| {
            let [a, b, cc] = m.corners_of(t);
            W.map(|w| a * w[0] + b * w[1] + cc * w[2])
        })
        .collect()
}

fn check(name: &str, s: &Surface, dist: impl Fn(DVec3) -> f64) {
    for tol in [0.05, 0.005] {
        let m = mesh_surface(s, tol).unwrap();
        let worst = samples(&m).into_iter().map(&dist).fold(0.0, f64::max);
        assert!(
            worst <= tol,
            "{name} at CHORDTOL {tol}: {worst} ({} triangles)",
            m.len()
        );
    }
}

/// Distance to the torus about the z axis with radii `big`, `small`.
fn torus(p: DVec3, big: f64, small: f64) -> f64 {
    ((p.truncate().length() - big).hypot(p.z) - small).abs()
}

#[test]
fn twisted_ruled_surface_is_meshed_within_chordtol() {
    // z = 0.3 y − 0.06 x y over [0, 10]²: a hyperbolic paraboloid with straight iso-lines.
    let s = Surface::ruled(
        line([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]),
        line([0.0, 10.0, 3.0], [10.0, 10.0, -3.0]),
    );
    check("ruled", &s, |p| {
        (p.z - (0.3 * p.y - 0.06 * p.x * p.y)).abs()
    });
    assert!(mesh_surface(&s, 0.01).unwrap().len() > 8);
}

#[test]
fn coons_patches_are_meshed_within_chordtol() {
    // Four straight edges around a twisted quadrilateral: the bilinear patch, the same graph.
    let s = Surface::boundary([
        line([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]),
        line([10.0, 0.0, 0.0], [10.0, 10.0, -3.0]),
        line([10.0, 10.0, -3.0], [0.0, 10.0, 3.0]),
        line([0.0, 10.0, 3.0], [0.0, 0.0, 0.0]),
    ])
    .unwrap();
    check("coons bilinear", &s, |p| {
        (p.z - (0.3 * p.y - 0.06 * p.x * p.y)).abs()
    });
    // Two arcs of radius 5 at z = 0 and z = 4 joined by rulings: a quarter cylinder.
    let arc = |z: f64| c(Curve::arc(DVec3::new(0.0, 0.0, z), 5.0, 0.0, PI / 2.0, None).unwrap());
    let s = Surface::boundary([
        arc(0.0),
        line([0.0, 5.0, 0.0], [0.0, 5.0, 4.0]),
        arc(4.0),
        line([5.0, 0.0, 4.0], [5.0, 0.0, 0.0]),
    ])
    .unwrap();
    check("coons cylinder", &s, |p| {
        (p.truncate().length() - 5.0).abs()
    });
}

#[test]
fn revolved_and_swept_tubes_are_meshed_within_chordtol() {
    // A circle of radius 1 about (5, 0, 0) in the xz plane, turned about z: a torus.
    let profile = c(Curve::circle(DVec3::new(5.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap());
    let s = Surface::revolve(profile.clone(), DVec3::ZERO, DVec3::Z, TAU).unwrap();
    check("revolve", &s, |p| torus(p, 5.0, 1.0));
    let half = Surface::revolve(profile.clone(), DVec3::ZERO, DVec3::Z, PI).unwrap();
    check("half revolve", &half, |p| torus(p, 5.0, 1.0));
    // The same circle swept along a quarter of the circle of radius 5 about z: a torus piece.
    let guide = c(Curve::arc(DVec3::ZERO, 5.0, 0.0, PI / 2.0, None).unwrap());
    let s = Surface::sweep(profile, guide).unwrap();
    check("sweep", &s, |p| torus(p, 5.0, 1.0));
}

#[test]
fn analytic_kinds_are_meshed_within_chordtol() {
    let cyl = Surface::cylinder(DVec3::ZERO, DVec3::Z, 2.0, 3.0).unwrap();
    check("cylinder", &cyl, |p| (p.truncate().length() - 2.0).abs());
    let sph = Surface::sphere(DVec3::new(1.0, 2.0, 3.0), 2.0).unwrap();
    check("sphere", &sph, |p| {
        (p.distance(DVec3::new(1.0, 2.0, 3.0)) - 2.0).abs()
    });
    let pl = Surface::plane(vec![
        DVec3::ZERO,
        DVec3::new(4.0, 0.0, 0.0),
        DVec3::new(4.0, 3.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.0, 3.0, 0.0),
    ])
    .unwrap();
    check("plane", &pl, |p| p.z.abs());
}

#[test]
fn bad_tolerances_and_open_boundaries_are_errors() {
    let s = Surface::ruled(
        line([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]),
        line([0.0, 10.0, 3.0], [10.0, 10.0, -3.0]),
    );
    for bad in [0.0, -1.0, f64::NAN] {
        let e = mesh_surface(&s, bad).unwrap_err().to_string();
        assert!(e.contains("CHORDTOL"), "{e}");
    }
    // Past the triangle budget: an error naming CHORDTOL, not a coarser mesh.
    let e = mesh_surface(&s, 1e-9).unwrap_err().to_string();
    assert!(e.contains("CHORDTOL") && e.contains("triangles"), "{e}");
    let e = Surface::boundary([
        line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        line([1.0, 0.0, 0.0], [1.0, 1.0, 0.0]),
        line([1.0, 1.0, 0.0], [0.0, 1.0, 0.0]),
        line([0.0, 1.1, 0.0], [0.0, 0.0, 0.0]),
    ])
    .unwrap_err()
    .to_string();
    assert!(e.contains("does not meet"), "{e}");
}
