//! The ellipse curve (geom/ellipse.rs): points satisfy the implicit equation, the exact
//! t ↔ angle maps invert each other, lengths and closest points round-trip, and
//! intersections with lines through the centre and with concentric circles are where the
//! closed forms put them. (Values against numpy: tests/vlax_curve_python.rs.)

use std::f64::consts::TAU;

use lispcad::geom::ellipse::Ellipse;
use lispcad::geom::{intersect, Curve, DVec3};
use proptest::prelude::*;

fn ellipse() -> impl Strategy<Value = Ellipse> {
    (
        (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64),
        (-1.0..1.0f64, -1.0..1.0f64, 0.2..1.0f64),
        (0.0..TAU, 0.5..8.0f64, 0.1..1.0f64),
        (0.0..TAU, 0.1..TAU),
    )
        .prop_filter_map(
            "ellipse",
            |((x, y, z), (nx, ny, nz), (rot, len, r), (a, s))| {
                let n = DVec3::new(nx, ny, nz).normalize();
                let (u, v) = lispcad::geom::frame::arbitrary_axis(n);
                let major = (u * rot.cos() + v * rot.sin()) * len;
                Ellipse::new(DVec3::new(x, y, z), major, r, a, a + s, n).ok()
            },
        )
}

/// (x/a)² + (y/b)² − 1 in the ellipse's frame, and the distance from its plane.
fn implicit(e: &Ellipse, p: DVec3) -> (f64, f64) {
    let v = p - e.center();
    let m = e.major_axis();
    let n = e.normal();
    let minor = n.cross(m) * e.ratio();
    let x = v.dot(m) / m.length_squared();
    let y = v.dot(minor) / minor.length_squared();
    (x * x + y * y - 1.0, v.dot(n))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn points_parameters_lengths_round_trip(e in ellipse(), t in 0.0..1.0f64) {
        let c = Curve::Ellipse(e);
        let p = c.eval(t);
        let (f, h) = implicit(&e, p);
        prop_assert!(f.abs() < 1e-12 && h.abs() < 1e-11, "{f} {h}");
        let a = e.angle_at(t);
        prop_assert!((e.point_at_angle(a) - p).length() < 1e-12);
        prop_assert!((e.t_at_angle(a) - t).abs() < 1e-11);
        let s = c.length_to(t);
        let back = c.param_at_length(s).unwrap();
        prop_assert!((c.eval(back) - p).length() < 1e-9, "{t} {back}");
        let (tc, q) = c.closest_point(p);
        prop_assert!((q - p).length() < 1e-9 && (c.eval(tc) - p).length() < 1e-9);
        // The derivative along t is dE/dθ · dθ/dt, so parallel to the angle derivative.
        let d = c.deriv(t).normalize();
        prop_assert!(d.cross(e.deriv_at_angle(a).normalize()).length() < 1e-9);
    }

    #[test]
    fn line_through_centre_meets_a_full_ellipse_at_the_closed_form(
        e in ellipse(), phi in 0.0..TAU
    ) {
        let full = Ellipse::new(e.center(), e.major_axis(), e.ratio(), 0.0, TAU, e.normal()).unwrap();
        // The points at angles phi and phi + π are opposite ends of a diameter.
        let (p, q) = (full.point_at_angle(phi), full.point_at_angle(phi + std::f64::consts::PI));
        let d = q - p;
        let l = Curve::line(p - d * 0.5, q + d * 0.5).unwrap();
        let hits = intersect(&l, &Curve::Ellipse(full), 1e-9);
        prop_assert_eq!(hits.len(), 2, "{:?}", hits);
        prop_assert!((hits[0].point - p).length() < 1e-8 && (hits[1].point - q).length() < 1e-8);
    }

    #[test]
    fn concentric_circle_meets_at_four_symmetric_points(
        e in ellipse(), k in 0.05..0.95f64
    ) {
        let full = Ellipse::new(e.center(), e.major_axis(), e.ratio(), 0.0, TAU, e.normal()).unwrap();
        prop_assume!(e.ratio() < 0.95);
        let (a, b) = (e.major_axis().length(), e.major_axis().length() * e.ratio());
        let r = b + (a - b) * k;
        let circle = Curve::circle(e.center(), r, Some(e.normal())).unwrap();
        let hits = intersect(&Curve::Ellipse(full), &circle, 1e-9);
        prop_assert_eq!(hits.len(), 4, "{:?}", hits);
        // cos²θ = (r² − b²) / (a² − b²) at each hit.
        let c2 = (r * r - b * b) / (a * a - b * b);
        for h in &hits {
            let th = full.angle_of(h.point);
            prop_assert!((th.cos().powi(2) - c2).abs() < 1e-8, "{th} {c2}");
            prop_assert!(((h.point - e.center()).length() - r).abs() < 1e-9);
        }
    }
}

#[test]
fn dxf_conventions_and_refusals() {
    let e = Ellipse::new(
        DVec3::ZERO,
        DVec3::new(0.0, 2.0, 0.0),
        0.5,
        0.0,
        0.0,
        DVec3::Z,
    )
    .unwrap();
    assert!(
        e.is_full(),
        "equal start and end make the full ellipse, as DXF"
    );
    // Angle 0 is the end of the major axis, π/2 the minor axis (n × M direction).
    assert!((e.point_at_angle(0.0) - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-15);
    assert!((e.point_at_angle(TAU / 4.0) - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-15);
    let c = Curve::Ellipse(e);
    assert!((c.area().unwrap() - std::f64::consts::PI * 2.0).abs() < 1e-12);
    assert!(Ellipse::new(DVec3::ZERO, DVec3::X, 0.0, 0.0, 1.0, DVec3::Z).is_err());
    assert!(Ellipse::new(DVec3::ZERO, DVec3::X, 0.5, 0.0, 1.0, DVec3::X).is_err());
    assert!(c.offset(1.0).is_err());
    // A mirror keeps it an ellipse through the mirrored points.
    let m =
        lispcad::geom::curve::xform::mirror(DVec3::new(3.0, 0.0, 0.0), DVec3::new(3.0, 1.0, 0.0))
            .unwrap();
    let mirrored = c.transform(&m).unwrap();
    for i in 0..8 {
        let p = m.transform_point3(c.eval(i as f64 / 8.0));
        assert!((mirrored.closest_point(p).1 - p).length() < 1e-12);
    }
}
