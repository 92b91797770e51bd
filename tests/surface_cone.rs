//! Plane sections of a cone in closed form (issue 13): a straight profile revolved about the
//! axis it meets, cut by planes giving an ellipse, a parabola, both branches of a hyperbola,
//! rulings through the apex, or the apex alone; clipped to the cone's extent, its partial
//! revolution and a region's edges. References are written out here from the cone's equation
//! `z = 2ρ` and the plane `z = m x + h` (on the ruling at angle θ, `s = h / (2 − m cos θ)`),
//! with lengths by midpoint quadrature, independent of lispcad.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_tol, surface_section_tol, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// The cone z = 2ρ between heights `z0` and `z1` (z0 < 0: both nappes), revolved by `angle`.
fn cone(z0: f64, z1: f64, angle: f64) -> Surface {
    let p = Curve::line(DVec3::new(z0 / 2.0, 0.0, z0), DVec3::new(z1 / 2.0, 0.0, z1)).unwrap();
    Surface::revolve(Arc::new(p), DVec3::ZERO, DVec3::Z, angle).unwrap()
}

/// The region of the plane z = m x + h over the box [x0, x1] × [y0, y1].
fn slope(m: f64, h: f64, x0: f64, x1: f64, y0: f64, y1: f64) -> Surface {
    let z = |x: f64| m * x + h;
    Surface::plane(vec![
        DVec3::new(x0, y0, z(x0)),
        DVec3::new(x1, y0, z(x1)),
        DVec3::new(x1, y1, z(x1)),
        DVec3::new(x0, y1, z(x0)),
    ])
    .unwrap()
}

/// The surface's curves with a plane region, at CT and GEOMTOL 1e-9.
fn cut(k: &Surface, plane: Surface) -> Vec<Polyline3> {
    surface_intersect_tol(k, &plane, CT, 1e-9).unwrap()
}

fn quad(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let n = 400_000;
    let w = (b - a) / n as f64;
    (0..n).map(|i| f(a + w * (i as f64 + 0.5))).sum::<f64>() * w
}

/// Length of the conic arc θ in [a, b] on z = m x + h: P = s(cos θ, sin θ, 2) with
/// s = h / (2 − m cos θ), so |P'|² = 5 s'² + s².
fn conic_length(m: f64, h: f64, a: f64, b: f64) -> f64 {
    quad(a, b, |t| {
        let d = 2.0 - m * t.cos();
        let s = h / d;
        let ds = -h * m * t.sin() / (d * d);
        (5.0 * ds * ds + s * s).sqrt()
    })
}

fn on_both(curves: &[Polyline3], m: f64, h: f64) {
    for c in curves {
        for p in &c.points {
            let rho = p.truncate().length();
            // Distance to the cone |z| = 2ρ (its generator has slope 2: divide by √5).
            assert!(
                (p.z.abs() - 2.0 * rho).abs() / 5f64.sqrt() <= 1e-9,
                "off the cone: {p}"
            );
            let off = (p.z - m * p.x - h).abs() / (1.0 + m * m).sqrt();
            assert!(off <= 1e-9, "off the plane: {p}");
        }
    }
}

fn total(curves: &[Polyline3]) -> f64 {
    curves.iter().map(Polyline3::length).sum()
}

fn assert_rel(l: f64, exact: f64, rel: f64) {
    assert!(
        (l - exact).abs() <= rel * exact,
        "{l} vs {exact}: {:.3e}",
        (l - exact) / exact
    );
}

const CT: f64 = 1e-7;

#[test]
fn an_oblique_plane_cuts_a_whole_ellipse() {
    let (m, h) = (0.3, 2.0);
    let r = cut(&cone(0.0, 4.0, TAU), slope(m, h, -9., 9., -9., 9.));
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    on_both(&r, m, h);
    assert_rel(r[0].length(), conic_length(m, h, 0.0, TAU), 1e-6);
    // The infinite plane through surface-section gives the same ellipse.
    let n = DVec3::new(-m, 0.0, 1.0);
    let s =
        surface_section_tol(&cone(0.0, 4.0, TAU), DVec3::new(0.0, 0.0, h), n, CT, 1e-9).unwrap();
    assert_eq!(s.len(), 1);
    assert!(s[0].closed);
    on_both(&s, m, h);
    assert_rel(s[0].length(), conic_length(m, h, 0.0, TAU), 1e-6);
}

#[test]
fn the_ellipse_is_clipped_by_the_region_and_the_partial_revolution() {
    let (m, h) = (0.3, 2.0);
    // Region x ≤ 1: s cos θ = 1 at cos θ = 2 / 2.3.
    let r = cut(&cone(0.0, 4.0, TAU), slope(m, h, -9., 1., -9., 9.));
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    on_both(&r, m, h);
    let c = (2.0f64 / 2.3).acos();
    assert_rel(r[0].length(), conic_length(m, h, c, TAU - c), 1e-6);
    for end in [r[0].points[0], *r[0].points.last().unwrap()] {
        assert!((end.x - 1.0).abs() <= 1e-9, "{end}");
    }
    // Half a revolution (θ in [0, π]): half the ellipse.
    let r = cut(&cone(0.0, 4.0, PI), slope(m, h, -9., 9., -9., 9.));
    assert_eq!(r.len(), 1);
    on_both(&r, m, h);
    assert!(r[0].points.iter().all(|p| p.y >= -1e-12));
    assert_rel(r[0].length(), conic_length(m, h, 0.0, PI), 1e-6);
}

#[test]
fn a_plane_parallel_to_a_ruling_cuts_a_parabola_up_to_the_rim() {
    // z = 2x + 1: s = 1 / (2 − 2 cos θ), up to the rim s = 2 where cos θ = 3/4.
    let (m, h) = (2.0, 1.0);
    let r = cut(&cone(0.0, 4.0, TAU), slope(m, h, -9., 9., -9., 9.));
    assert_eq!(r.len(), 1);
    assert!(!r[0].closed);
    on_both(&r, m, h);
    let c = 0.75f64.acos();
    assert_rel(r[0].length(), conic_length(m, h, c, TAU - c), 1e-6);
    for end in [r[0].points[0], *r[0].points.last().unwrap()] {
        assert!((end.z - 4.0).abs() <= 1e-9, "{end}");
    }
}

#[test]
fn a_steep_plane_cuts_both_branches_of_a_hyperbola_on_a_double_cone() {
    // z = 3x + 1 on the double cone z in [−4, 4]: upper branch s = 1/(2 − 3 cos θ) > 0 up to
    // s = 2 (cos θ ≤ 1/2); lower branch s < 0 down to s = −2 (cos θ ≥ 5/6).
    let (m, h) = (3.0, 1.0);
    let r = cut(&cone(-4.0, 4.0, TAU), slope(m, h, -9., 9., -9., 9.));
    assert_eq!(r.len(), 2, "{r:?}");
    on_both(&r, m, h);
    let (c1, c2) = ((0.5f64).acos(), (5.0f64 / 6.0).acos());
    let upper = conic_length(m, h, c1, TAU - c1);
    let lower = conic_length(m, h, -c2, c2);
    let mut l: Vec<f64> = r.iter().map(Polyline3::length).collect();
    l.sort_by(f64::total_cmp);
    let mut e = [upper, lower];
    e.sort_by(f64::total_cmp);
    assert_rel(l[0], e[0], 1e-6);
    assert_rel(l[1], e[1], 1e-6);
    // On the single nappe z ≥ 0 only the upper branch.
    let r = cut(&cone(0.0, 4.0, TAU), slope(m, h, -9., 9., -9., 9.));
    assert_eq!(r.len(), 1);
    assert_rel(total(&r), upper, 1e-6);
}

#[test]
fn planes_through_the_apex_give_rulings_or_the_apex() {
    let k = cone(0.0, 4.0, TAU);
    // z = 3x: rulings at cos θ = 2/3, from the apex to the rim, √20 long each.
    let r = cut(&k, slope(3.0, 0.0, -9., 9., -9., 9.));
    assert_eq!(r.len(), 2);
    on_both(&r, 3.0, 0.0);
    for c in &r {
        assert_eq!(c.points.len(), 2);
        assert_rel(c.length(), 20f64.sqrt(), 1e-12);
        assert!(c.points.iter().any(|p| p.length() <= 1e-12));
        let rim = c.points.iter().find(|p| p.z > 1.0).unwrap();
        assert!((rim.x - 4.0 / 3.0).abs() <= 1e-12, "{rim}");
    }
    // z = 2x touches the cone along the ruling θ = 0: the line (0,0,0)–(2,0,4).
    let r = cut(&k, slope(2.0, 0.0, -9., 9., -9., 9.));
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].points.len(), 2);
    let far = r[0].points.iter().find(|p| p.z > 1.0).unwrap();
    assert!(far.distance(DVec3::new(2.0, 0.0, 4.0)) <= 1e-12, "{far}");
    // z = 1.5x meets the cone only at the apex.
    let r = cut(&k, slope(1.5, 0.0, -9., 9., -9., 9.));
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].points.len(), 1);
    assert!(r[0].points[0].length() <= 1e-12);
    // The same plane through surface-section.
    let n = DVec3::new(-1.5, 0.0, 1.0);
    let s = surface_section_tol(&k, DVec3::ZERO, n, CT, 1e-9).unwrap();
    assert_eq!(s, r);
    // Lifted by 1e-3 it misses (the cone is only above the apex there).
    let r = cut(&k, slope(1.5, -1e-3, -9., 9., -9., 9.));
    assert!(r.is_empty(), "{r:?}");
    // The region's edge x ≤ 1 clips the rulings of z = 3x at z = 3.
    let r = cut(&k, slope(3.0, 0.0, -9., 1., -9., 9.));
    assert_eq!(r.len(), 2);
    for c in &r {
        assert!(c.points.iter().all(|p| p.z <= 3.0 + 1e-12));
        assert_rel(c.length(), 0.75 * 20f64.sqrt(), 1e-12);
    }
}
