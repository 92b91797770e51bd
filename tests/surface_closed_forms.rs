//! Closed-form surface/surface intersections (issue 13, items 2 and 3): an oblique plane region
//! through a cylinder (an ellipse, clipped), cylinders with parallel or touching axes, spheres
//! against cylinders, and coaxial surfaces of revolution (circles, tangent circles included).
//! References are closed forms or midpoint quadrature written out here, independent of lispcad.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{
    surface_intersect, surface_intersect_tol, surface_section_tol, CurveRef, Surface,
};
use lispcad::geom::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

mod surface_support;
use surface_support::cone;

fn c(x: Curve) -> CurveRef {
    Arc::new(x)
}

fn rho(p: DVec3) -> f64 {
    p.truncate().length()
}

/// ∫ f over [a, b] by the midpoint rule on 400 000 steps (smooth integrands: error ≪ 1e-9).
fn quad(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let n = 400_000;
    let h = (b - a) / n as f64;
    (0..n).map(|i| f(a + h * (i as f64 + 0.5))).sum::<f64>() * h
}

fn square(z: impl Fn(f64, f64) -> f64, x0: f64, x1: f64, y0: f64, y1: f64) -> Surface {
    Surface::plane(vec![
        DVec3::new(x0, y0, z(x0, y0)),
        DVec3::new(x1, y0, z(x1, y0)),
        DVec3::new(x1, y1, z(x1, y1)),
        DVec3::new(x0, y1, z(x0, y1)),
    ])
    .unwrap()
}

fn assert_rel(l: f64, exact: f64, rel: f64) {
    assert!(
        (l - exact).abs() <= rel * exact,
        "{l} vs {exact}: {:.3e}",
        (l - exact) / exact
    );
}

#[test]
fn oblique_plane_cuts_a_cylinder_in_a_whole_ellipse() {
    // z = 5 + 0.5 y through the cylinder ρ = 1: points (cos θ, sin θ, 5 + 0.5 sin θ).
    let cyl = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 10.0).unwrap();
    let plane = square(|_, y| 5.0 + 0.5 * y, -3.0, 3.0, -3.0, 3.0);
    let r = surface_intersect(&cyl, &plane, 1e-7).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!((rho(*p) - 1.0).abs() <= 1e-12, "{p}");
        assert!((p.z - 5.0 - 0.5 * p.y).abs() <= 1e-12, "{p}");
    }
    let exact = quad(0.0, TAU, |t| {
        (t.sin().powi(2) + 1.25 * t.cos().powi(2)).sqrt()
    });
    assert_rel(r[0].length(), exact, 1e-7);
    // The same with the arguments swapped.
    assert_eq!(surface_intersect(&plane, &cyl, 1e-7).unwrap(), r);
}

#[test]
fn oblique_plane_ellipse_is_clipped_by_the_region_and_the_height() {
    let cyl = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 10.0).unwrap();
    // The region stops at x = −0.5: the arc cos θ ≥ −0.5, θ in [−2π/3, 2π/3].
    let plane = square(|_, y| 5.0 + 0.5 * y, -0.5, 3.0, -3.0, 3.0);
    let r = surface_intersect(&cyl, &plane, 1e-7).unwrap();
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    let (a, b) = (r[0].points[0], *r[0].points.last().unwrap());
    assert!(
        (a.x + 0.5).abs() <= 1e-12 && (b.x + 0.5).abs() <= 1e-12,
        "{a} {b}"
    );
    assert!((a.y.abs() - 0.75f64.sqrt()).abs() <= 1e-12);
    for p in &r[0].points {
        assert!((rho(*p) - 1.0).abs() <= 1e-12 && (p.z - 5.0 - 0.5 * p.y).abs() <= 1e-12);
        assert!(p.x >= -0.5 - 1e-12);
    }
    let f = |t: f64| (t.sin().powi(2) + 1.25 * t.cos().powi(2)).sqrt();
    assert_rel(
        r[0].length(),
        quad(-2.0 * PI / 3.0, 2.0 * PI / 3.0, f),
        1e-7,
    );
    // A cylinder ending at z = 5.25 keeps the part with 0.5 sin θ ≤ 0.25: θ in [5π/6, 13π/6].
    let short = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 5.25).unwrap();
    let big = square(|_, y| 5.0 + 0.5 * y, -3.0, 3.0, -3.0, 3.0);
    let r = surface_intersect(&short, &big, 1e-7).unwrap();
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    for p in &r[0].points {
        assert!(p.z <= 5.25 + 1e-12 && (rho(*p) - 1.0).abs() <= 1e-12);
    }
    assert!((r[0].points[0].z - 5.25).abs() <= 1e-12);
    assert_rel(
        r[0].length(),
        quad(5.0 * PI / 6.0, 13.0 * PI / 6.0, f),
        1e-7,
    );
    // Both: θ in [5π/6, 13π/6] with cos θ ≥ −0.5 leaves θ in [4π/3, 13π/6].
    let r = surface_intersect(&short, &plane, 1e-7).unwrap();
    let total: f64 = r.iter().map(Polyline3::length).sum();
    let exact = quad(4.0 * PI / 3.0, 13.0 * PI / 6.0, f);
    assert_eq!(r.len(), 1);
    assert_rel(total, exact, 1e-7);
}

#[test]
fn parallel_cylinders_meet_along_rulings_and_touch_along_one() {
    let a = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 4.0).unwrap();
    // Crossing: rulings at x = 1/2, y = ±√3/2, over the common height z in [1, 4].
    let b = Surface::cylinder(DVec3::new(1.0, 0.0, 1.0), DVec3::Z, 1.0, 4.0).unwrap();
    let r = surface_intersect(&a, &b, 0.01).unwrap();
    assert_eq!(r.len(), 2);
    for l in &r {
        assert_eq!(l.points.len(), 2);
        for p in &l.points {
            assert!((p.x - 0.5).abs() <= 1e-12 && (p.y.abs() - 0.75f64.sqrt()).abs() <= 1e-12);
        }
        assert!((l.length() - 3.0).abs() <= 1e-12);
    }
    // Touching from outside (axis 2 apart), its axis reversed: the ruling x = 1, y = 0.
    let b = Surface::cylinder(DVec3::new(2.0, 0.0, 3.0), -DVec3::Z, 1.0, 4.0).unwrap();
    let r = surface_intersect(&a, &b, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    let l = &r[0];
    assert!(l
        .points
        .iter()
        .all(|p| p.distance(DVec3::new(1.0, 0.0, p.z)) <= 1e-12));
    assert!((l.length() - 3.0).abs() <= 1e-12);
    // Touching from inside: a thin cylinder in a fat one.
    let thin = Surface::cylinder(DVec3::new(0.0, 0.5, 0.0), DVec3::Z, 0.5, 4.0).unwrap();
    let r = surface_intersect(&thin, &a, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0]
        .points
        .iter()
        .all(|p| p.distance(DVec3::new(0.0, 1.0, p.z)) <= 1e-12));
    // And the other way round.
    let r2 = surface_intersect(&a, &thin, 0.01).unwrap();
    assert_eq!(r2.len(), 1);
    assert!(r2[0]
        .points
        .iter()
        .all(|p| p.distance(DVec3::new(0.0, 1.0, p.z)) <= 1e-12));
}

#[test]
fn crossing_cylinders_touching_from_outside_meet_in_a_point() {
    let a = Surface::cylinder(DVec3::new(0.0, 0.0, -3.0), DVec3::Z, 1.0, 6.0).unwrap();
    let b = Surface::cylinder(DVec3::new(-3.0, 2.0, 0.0), DVec3::X, 1.0, 6.0).unwrap();
    let r = surface_intersect(&a, &b, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].points.len(), 1);
    assert!(r[0].points[0].distance(DVec3::new(0.0, 1.0, 0.0)) <= 1e-12);
    // Moved off the end of b: nothing.
    let b = Surface::cylinder(DVec3::new(2.0, 2.0, 0.0), DVec3::X, 1.0, 6.0).unwrap();
    assert!(surface_intersect(&a, &b, 0.01).unwrap().is_empty());
}

#[test]
fn spheres_and_cylinders_meet_in_circles_or_touch_in_points() {
    let cyl = Surface::cylinder(DVec3::new(0.0, 0.0, -5.0), DVec3::Z, 2.0, 10.0).unwrap();
    // A ball inside touching the wall.
    let ball = Surface::sphere(DVec3::new(1.0, 0.0, 0.5), 1.0).unwrap();
    let r = surface_intersect(&ball, &cyl, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].points, vec![DVec3::new(2.0, 0.0, 0.5)]);
    // Outside touching.
    let out = Surface::sphere(DVec3::new(0.0, -3.0, 1.0), 1.0).unwrap();
    let r = surface_intersect(&cyl, &out, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].points[0].distance(DVec3::new(0.0, -2.0, 1.0)) <= 1e-15);
    // Centred on the axis with the cylinder's radius: touching all round, one circle.
    let snug = Surface::sphere(DVec3::new(0.0, 0.0, 1.0), 2.0).unwrap();
    let r = surface_intersect(&snug, &cyl, 1e-6).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!((rho(*p) - 2.0).abs() <= 1e-12 && (p.z - 1.0).abs() <= 1e-15);
    }
    assert_rel(r[0].length(), 4.0 * PI, 1e-6);
    // Larger: two circles at z = 1 ± √5.
    let big = Surface::sphere(DVec3::new(0.0, 0.0, 1.0), 3.0).unwrap();
    let r = surface_intersect(&big, &cyl, 1e-6).unwrap();
    assert_eq!(r.len(), 2);
    let mut zs: Vec<f64> = r.iter().map(|l| l.points[0].z).collect();
    zs.sort_by(f64::total_cmp);
    assert!((zs[0] - (1.0 - 5f64.sqrt())).abs() <= 1e-12);
    assert!((zs[1] - (1.0 + 5f64.sqrt())).abs() <= 1e-12);
    for p in r.iter().flat_map(|l| l.points.iter()) {
        assert!((rho(*p) - 2.0).abs() <= 1e-12);
        assert!((p.distance(DVec3::new(0.0, 0.0, 1.0)) - 3.0).abs() <= 1e-12);
    }
}

#[test]
fn coaxial_cone_cylinder_and_sphere_meet_in_circles() {
    let cyl = Surface::cylinder(DVec3::new(0.0, 0.0, -1.0), DVec3::Z, 1.0, 6.0).unwrap();
    let r = surface_intersect_tol(&cone(), &cyl, 1e-6, 1e-9).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!(
            (rho(*p) - 1.0).abs() <= 1e-12 && (p.z - 2.0).abs() <= 1e-12,
            "{p}"
        );
    }
    assert_rel(r[0].length(), TAU, 1e-6);
    // A sphere about (0, 0, 5) of radius 3: ρ² + (2ρ − 5)² = 9, so ρ = 2 − √0.8 (the other
    // root, 2 + √0.8, is past the cone's rim).
    let s = Surface::sphere(DVec3::new(0.0, 0.0, 5.0), 3.0).unwrap();
    let r = surface_intersect_tol(&s, &cone(), 1e-6, 1e-9).unwrap();
    assert_eq!(r.len(), 1);
    let rr = 2.0 - 0.8f64.sqrt();
    for p in &r[0].points {
        assert!(
            (rho(*p) - rr).abs() <= 1e-12 && (p.z - 2.0 * rr).abs() <= 1e-12,
            "{p}"
        );
    }
    assert_rel(r[0].length(), TAU * rr, 1e-6);
}

#[test]
fn coaxial_torus_and_cylinders_meet_in_circles_or_touch_all_round() {
    // Torus: the circle of radius 1 about (5, 0, 0) in the plane y = 0, turned about Z.
    let torus = Surface::revolve(
        c(Curve::circle(DVec3::new(5.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        TAU,
    )
    .unwrap();
    let cyl = |r: f64| Surface::cylinder(DVec3::new(0.0, 0.0, -2.0), DVec3::Z, r, 4.0).unwrap();
    // ρ = 5.5: (ρ − 5)² + z² = 1 at z = ±√0.75.
    let r = surface_intersect_tol(&torus, &cyl(5.5), 1e-6, 1e-9).unwrap();
    assert_eq!(r.len(), 2);
    for p in r.iter().flat_map(|l| l.points.iter()) {
        assert!((rho(*p) - 5.5).abs() <= 1e-12 && (p.z.abs() - 0.75f64.sqrt()).abs() <= 1e-9);
    }
    // A fatter coaxial torus (tube about ρ = 5.5): meridian circles cross at ρ = 5.25,
    // z = ±√(1 − 0.25²).
    let t2 = Surface::revolve(
        c(Curve::circle(DVec3::new(0.0, 5.5, 0.0), 1.0, Some(DVec3::X)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        TAU,
    )
    .unwrap();
    let r = surface_intersect_tol(&torus, &t2, 1e-6, 1e-9).unwrap();
    assert_eq!(r.len(), 2);
    for p in r.iter().flat_map(|l| l.points.iter()) {
        assert!((rho(*p) - 5.25).abs() <= 1e-12, "{p}");
        assert!((p.z.abs() - (1.0f64 - 0.0625).sqrt()).abs() <= 1e-12, "{p}");
    }
    // The outer and inner equators: tangent circles, each once.
    for (rad, exact) in [(6.0, 6.0), (4.0, 4.0)] {
        let r = surface_intersect_tol(&torus, &cyl(rad), 1e-6, 1e-9).unwrap();
        assert_eq!(r.len(), 1, "radius {rad}");
        assert!(r[0].closed);
        for p in &r[0].points {
            assert!((rho(*p) - exact).abs() <= 1e-12 && p.z.abs() <= 1e-6, "{p}");
            let on_torus = ((rho(*p) - 5.0).hypot(p.z) - 1.0).abs();
            assert!(on_torus <= 1e-9);
        }
        assert_rel(r[0].length(), TAU * exact, 1e-6);
    }
}

#[test]
fn coaxial_partial_revolutions_meet_in_arcs() {
    // Half a cone (y ≥ 0) against the full cone z = 3 − ρ: the half circle ρ = 1, z = 2.
    let half = Surface::revolve(
        c(Curve::line(DVec3::ZERO, DVec3::new(2.0, 0.0, 4.0)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        PI,
    )
    .unwrap();
    let other = Surface::revolve(
        c(Curve::line(DVec3::new(0.0, 0.0, 3.0), DVec3::new(3.0, 0.0, 0.0)).unwrap()),
        DVec3::new(0.0, 0.0, 7.0),
        DVec3::Z,
        TAU,
    )
    .unwrap();
    let r = surface_intersect_tol(&half, &other, 1e-7, 1e-9).unwrap();
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    for p in &r[0].points {
        assert!(
            (rho(*p) - 1.0).abs() <= 1e-12 && (p.z - 2.0).abs() <= 1e-12,
            "{p}"
        );
        assert!(p.y >= -1e-12);
    }
    assert!(r[0].points[0].distance(DVec3::new(1.0, 0.0, 2.0)) <= 1e-12);
    assert!(
        r[0].points
            .last()
            .unwrap()
            .distance(DVec3::new(-1.0, 0.0, 2.0))
            <= 1e-12
    );
    assert_rel(r[0].length(), PI, 1e-6);
    // Two quarter turns overlapping by 30°: the other turned about −Z from angle 120°.
    let q = Surface::revolve(
        c(Curve::line(
            DVec3::new(0.0, 0.0, 3.0),
            DVec3::new(
                3.0 * (2.0 * PI / 3.0).cos(),
                3.0 * (2.0 * PI / 3.0).sin(),
                0.0,
            ),
        )
        .unwrap()),
        DVec3::ZERO,
        -DVec3::Z,
        PI / 2.0,
    )
    .unwrap();
    // q covers angles [30°, 120°]; half covers [0°, 180°]: the arc over [30°, 120°].
    let r = surface_intersect_tol(&half, &q, 1e-7, 1e-9).unwrap();
    assert_eq!(r.len(), 1);
    assert_rel(r[0].length(), PI / 2.0, 1e-6);
    let a0 = r[0].points[0].y.atan2(r[0].points[0].x);
    assert!((a0 - PI / 6.0).abs() <= 1e-12, "{a0}");
}

#[test]
fn planes_across_a_torus_axis_cut_circles_on_the_true_profile() {
    let torus = Surface::revolve(
        c(Curve::circle(DVec3::new(5.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        TAU,
    )
    .unwrap();
    // The tangent plane z = 1 on top: the circle ρ = 5, once (not once per side of the top).
    let r = surface_section_tol(&torus, DVec3::new(0.0, 0.0, 1.0), DVec3::Z, 1e-6, 1e-9).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!(
            (rho(*p) - 5.0).abs() <= 1e-7 && (p.z - 1.0).abs() <= 1e-15,
            "{p}"
        );
    }
    // z = 0.6: circles ρ = 5 ± 0.8 on the true profile (not on its sampled chords).
    let r = surface_section_tol(&torus, DVec3::new(0.0, 0.0, 0.6), DVec3::Z, 1e-3, 1e-9).unwrap();
    assert_eq!(r.len(), 2);
    let mut radii: Vec<f64> = r.iter().map(|l| rho(l.points[0])).collect();
    radii.sort_by(f64::total_cmp);
    assert!(
        (radii[0] - 4.2).abs() <= 1e-12 && (radii[1] - 5.8).abs() <= 1e-12,
        "{radii:?}"
    );
    for p in r.iter().flat_map(|l| l.points.iter()) {
        assert!((p.z - 0.6).abs() <= 1e-15);
    }
}

fn region(pts: &[(f64, f64)], z: f64) -> Surface {
    Surface::plane(pts.iter().map(|&(x, y)| DVec3::new(x, y, z)).collect()).unwrap()
}

/// Shoelace area of a closed loop in the XY plane.
fn loop_area(l: &Polyline3) -> f64 {
    let p = &l.points;
    0.5 * (0..p.len())
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            a.x * b.y - b.x * a.y
        })
        .sum::<f64>()
}

#[test]
fn coplanar_regions_overlap_in_their_common_region() {
    let sq = |x0: f64, y0: f64, s: f64| {
        region(
            &[(x0, y0), (x0 + s, y0), (x0 + s, y0 + s), (x0, y0 + s)],
            1.0,
        )
    };
    // [0, 2]² and [1, 3]²: the unit square [1, 2]², as one closed loop.
    let r = surface_intersect(&sq(0.0, 0.0, 2.0), &sq(1.0, 1.0, 2.0), 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    let mut pts: Vec<(f64, f64)> = r[0].points.iter().map(|p| (p.x, p.y)).collect();
    pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(pts, vec![(1.0, 1.0), (1.0, 2.0), (2.0, 1.0), (2.0, 2.0)]);
    assert!(r[0].points.iter().all(|p| p.z == 1.0));
    assert_eq!(loop_area(&r[0]), 1.0);
    // The same region twice: all of it.
    let r = surface_intersect(&sq(0.0, 0.0, 2.0), &sq(0.0, 0.0, 2.0), 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert_eq!(loop_area(&r[0]), 4.0);
    // An L (area 3) against [1, 3]² wound the other way: the overlap is the L's arm
    // [1, 2] × [1, 2] plus nothing else, area 1, counter-clockwise about the L's normal.
    let l = region(
        &[
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 2.0),
            (1.0, 2.0),
            (1.0, 1.0),
            (0.0, 1.0),
        ],
        1.0,
    );
    let cw = region(&[(1.0, 1.0), (1.0, 3.0), (3.0, 3.0), (3.0, 1.0)], 1.0);
    let r = surface_intersect(&l, &cw, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert_eq!(loop_area(&r[0]), 1.0);
    // An L against a square over both arms: [0.5, 2] × [0.5, 1] and [1, 2]², area 1.75.
    let big = region(&[(0.5, 0.5), (2.5, 0.5), (2.5, 2.5), (0.5, 2.5)], 1.0);
    let r = surface_intersect(&l, &big, 0.01).unwrap();
    assert_eq!(r.len(), 1);
    assert!((loop_area(&r[0]) - 1.75).abs() <= 1e-15);
    assert_eq!(r[0].points.len(), 6);
    // Coplanar but apart, and parallel planes: nothing.
    assert!(
        surface_intersect(&sq(0.0, 0.0, 1.0), &sq(5.0, 5.0, 1.0), 0.01)
            .unwrap()
            .is_empty()
    );
    let low = region(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)], 0.0);
    assert!(surface_intersect(&low, &sq(0.0, 0.0, 2.0), 0.01)
        .unwrap()
        .is_empty());
}
