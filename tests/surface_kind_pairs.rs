//! Intersections through the mesh path between the parametric kinds (issue 13, "Checked by"):
//! ruled/plane, ruled/cylinder, sweep/ruled, sweep/plane, Coons/plane and revolve/cylinder
//! pairs give points within 1e-9 of both true surfaces and curve lengths within 1e-6 of a
//! quadrature reference, and a proptest moves the plane at random, half the time onto heights
//! where the seeding mesh has vertices. The true surfaces are written out implicitly here: the
//! twisted ruled surface
//! z = 0.3·y − 0.06·x·y, the cylinder (x − 5)² + (y − 5)² = r², the torus, the plane.

use lispcad::geom::curve::Curve;
use lispcad::geom::line::Line;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_seeded, CurveRef, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::PI;
use std::sync::Arc;

mod surface_support;

fn c(x: Curve) -> CurveRef {
    Arc::new(x)
}

/// The twisted ruled surface between (0,0,0)–(10,0,0) and (0,10,3)–(10,10,−3):
/// S(u, v) = (10u, 10v, v(3 − 6u)), i.e. z = 0.3·y − 0.06·x·y over [0, 10]².
fn twisted() -> Surface {
    let l = |a: [f64; 3], b: [f64; 3]| {
        Arc::new(Line {
            p0: DVec3::from_array(a),
            p1: DVec3::from_array(b),
        })
    };
    Surface::ruled(
        l([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]),
        l([0.0, 10.0, 3.0], [10.0, 10.0, -3.0]),
    )
}

/// Distance from p to the twisted surface, to first order (|F| / |∇F|; exact to roundoff at
/// the 1e-9 level this is used at).
fn off_twisted(p: DVec3) -> f64 {
    let f = p.z - 0.3 * p.y + 0.06 * p.x * p.y;
    let g = DVec3::new(0.06 * p.y, -0.3 + 0.06 * p.x, 1.0);
    f.abs() / g.length()
}

/// The horizontal square region z = h over [-1, 11]².
fn level(h: f64) -> Surface {
    Surface::plane(vec![
        DVec3::new(-1.0, -1.0, h),
        DVec3::new(11.0, -1.0, h),
        DVec3::new(11.0, 11.0, h),
        DVec3::new(-1.0, 11.0, h),
    ])
    .unwrap()
}

/// Composite Simpson on [a, b] with 2·10⁵ intervals (smooth integrands: error far below 1e-9).
fn quad(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let n = 200_000;
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for i in 1..n {
        s += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

fn total(r: &[Polyline3]) -> f64 {
    r.iter().map(Polyline3::length).sum()
}

fn assert_len(name: &str, got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-6 * want,
        "{name}: length {got} vs {want} (rel {:.2e})",
        (got - want).abs() / want
    );
}

fn intersect(a: &Surface, b: &Surface) -> Vec<Polyline3> {
    surface_intersect_seeded(a, b, 1e-2, 1e-7, 1e-9).unwrap()
}

/// The twisted surface at height h (0 < h < 3): y = h / (0.3 − 0.06 x) from x = 0 up to
/// where y reaches 10; its length by quadrature.
fn level_curve_length(h: f64) -> f64 {
    let x1 = ((0.3 - h / 10.0) / 0.06).min(10.0);
    quad(0.0, x1, |x| {
        let d = 0.3 - 0.06 * x;
        let dy = h * 0.06 / (d * d);
        (1.0 + dy * dy).sqrt()
    })
}

#[test]
fn a_twisted_ruled_surface_meets_a_plane_on_both() {
    let r = intersect(&twisted(), &level(0.5));
    assert_eq!(r.len(), 1, "{r:?}");
    for p in &r[0].points {
        assert!((p.z - 0.5).abs() <= 1e-9 && off_twisted(*p) <= 1e-9, "{p}");
    }
    assert_len("ruled ∩ plane", total(&r), level_curve_length(0.5));
}

/// The closed curve where the cylinder of radius `rad` about x = y = 5 meets the twisted
/// surface: (5 + rad·cos t, 5 + rad·sin t, 0.3·y − 0.06·x·y); its length by quadrature.
fn cylinder_curve_length(rad: f64) -> f64 {
    quad(0.0, 2.0 * PI, |t| {
        let (x, y) = (5.0 + rad * t.cos(), 5.0 + rad * t.sin());
        let (dx, dy) = (-rad * t.sin(), rad * t.cos());
        let dz = 0.3 * dy - 0.06 * (dx * y + x * dy);
        (dx * dx + dy * dy + dz * dz).sqrt()
    })
}

fn on_cylinder(p: DVec3, rad: f64) -> f64 {
    ((p.x - 5.0).hypot(p.y - 5.0) - rad).abs()
}

#[test]
fn a_twisted_ruled_surface_meets_a_cylinder_and_a_swept_tube_on_both() {
    let cyl = Surface::cylinder(DVec3::new(5.0, 5.0, -5.0), DVec3::Z, 2.0, 10.0).unwrap();
    // A circle of radius 1.5 swept along the vertical line x = y = 5: a cylinder whose frames
    // are exact (a straight guide).
    let ring = Curve::circle(DVec3::new(5.0, 5.0, -5.0), 1.5, Some(DVec3::Z)).unwrap();
    let axis = Curve::line(DVec3::new(5.0, 5.0, -5.0), DVec3::new(5.0, 5.0, 5.0)).unwrap();
    let tube = Surface::sweep(c(ring), c(axis)).unwrap();
    for (name, s, rad) in [("cylinder", &cyl, 2.0), ("sweep", &tube, 1.5)] {
        let r = intersect(&twisted(), s);
        assert_eq!(r.len(), 1, "{name}: {r:?}");
        assert!(r[0].closed, "{name}");
        for p in &r[0].points {
            assert!(on_cylinder(*p, rad) <= 1e-9, "{name}: {p}");
            assert!(off_twisted(*p) <= 1e-9, "{name}: {p}");
        }
        assert_len(name, total(&r), cylinder_curve_length(rad));
    }
}

#[test]
fn a_swept_tube_and_a_coons_patch_meet_an_oblique_plane_on_both() {
    // The plane z = 0.2·x (a region over [-1, 11]²).
    let pl = Surface::plane(vec![
        DVec3::new(-1.0, -1.0, -0.2),
        DVec3::new(11.0, -1.0, 2.2),
        DVec3::new(11.0, 11.0, 2.2),
        DVec3::new(-1.0, 11.0, -0.2),
    ])
    .unwrap();
    let on_plane = |p: DVec3| (p.z - 0.2 * p.x).abs() / 1.04f64.sqrt();
    // The tube of radius 1.5 about x = y = 5: an ellipse, x = 5 + 1.5 cos t.
    let ring = Curve::circle(DVec3::new(5.0, 5.0, -5.0), 1.5, Some(DVec3::Z)).unwrap();
    let axis = Curve::line(DVec3::new(5.0, 5.0, -5.0), DVec3::new(5.0, 5.0, 5.0)).unwrap();
    let tube = Surface::sweep(c(ring), c(axis)).unwrap();
    let r = intersect(&tube, &pl);
    assert_eq!(r.len(), 1, "{r:?}");
    for p in &r[0].points {
        assert!(on_plane(*p) <= 1e-9 && on_cylinder(*p, 1.5) <= 1e-9, "{p}");
    }
    let ellipse = quad(0.0, 2.0 * PI, |t| {
        let (dx, dy) = (-1.5 * t.sin(), 1.5 * t.cos());
        (dx * dx + dy * dy + (0.2 * dx) * (0.2 * dx)).sqrt()
    });
    assert_len("sweep ∩ plane", total(&r), ellipse);
    // The quarter cylinder ρ = 5, x, y ≥ 0, |z| ≤ 2 as a Coons patch: the arc
    // (5 cos θ, 5 sin θ, cos θ), θ in [0, π/2].
    let coons = surface_support::quarter_cylinder_patch();
    let r = intersect(&coons, &pl);
    assert_eq!(r.len(), 1, "{r:?}");
    for p in &r[0].points {
        let rho = p.x.hypot(p.y);
        assert!(on_plane(*p) <= 1e-9 && (rho - 5.0).abs() <= 1e-9, "{p}");
    }
    let want = quad(0.0, PI / 2.0, |t| (25.0 + t.sin() * t.sin()).sqrt());
    assert_len("Coons ∩ plane", total(&r), want);
}

#[test]
fn a_torus_meets_an_off_axis_cylinder_on_both() {
    // The torus (ρ − 3)² + z² = 1 as a surface of revolution, and the vertical cylinder of
    // radius 0.5 about (3, 0): two closed curves z = ±√(1 − (ρ − 3)²) over the circle
    // x = 3 + 0.5 cos t, y = 0.5 sin t.
    let tube = Curve::circle(DVec3::new(3.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap();
    let torus = Surface::revolve(c(tube), DVec3::ZERO, DVec3::Z, 2.0 * PI).unwrap();
    let cyl = Surface::cylinder(DVec3::new(3.0, 0.0, -2.0), DVec3::Z, 0.5, 4.0).unwrap();
    let r = intersect(&torus, &cyl);
    assert_eq!(r.len(), 2, "{r:?}");
    for p in r.iter().flat_map(|c| c.points.iter()) {
        let on_torus = ((p.x.hypot(p.y) - 3.0).hypot(p.z) - 1.0).abs();
        let on_cyl = ((p.x - 3.0).hypot(p.y) - 0.5).abs();
        assert!(on_torus <= 1e-9 && on_cyl <= 1e-9, "{p}");
    }
    let one = quad(0.0, 2.0 * PI, |t| {
        let (x, y) = (3.0 + 0.5 * t.cos(), 0.5 * t.sin());
        let (dx, dy) = (-0.5 * t.sin(), 0.5 * t.cos());
        let rho = x.hypot(y);
        let drho = (x * dx + y * dy) / rho;
        let z = (1.0 - (rho - 3.0) * (rho - 3.0)).sqrt();
        let dz = -(rho - 3.0) * drho / z;
        (dx * dx + dy * dy + dz * dz).sqrt()
    });
    assert!(r.iter().all(|c| c.closed));
    for cv in &r {
        assert_len("torus ∩ cylinder", cv.length(), one);
    }
}

use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    /// The twisted surface cut by z = h at random, or at h = 0.3·k for small k: there the
    /// section runs through the edge x = 0 at y = k, a round value where the seeding mesh's
    /// rows of vertices fall. Every point on both surfaces, the length against quadrature.
    #[test]
    fn a_twisted_ruled_surface_cut_at_random_and_snapped_heights(
        hf in 0.05f64..2.5, k in 1u32..8, snap in any::<bool>(),
    ) {
        let h = if snap { 0.3 * k as f64 } else { hf };
        let r = intersect(&twisted(), &level(h));
        prop_assert!(!r.is_empty());
        for p in r.iter().flat_map(|c| c.points.iter()) {
            prop_assert!((p.z - h).abs() <= 1e-9 && off_twisted(*p) <= 1e-9, "{} at {}", p, h);
        }
        let (got, want) = (total(&r), level_curve_length(h));
        prop_assert!((got - want).abs() <= 1e-6 * want, "{} vs {} at {}", got, want, h);
    }
}
