//! Curve kinds, queries and transforms as the language binds them (SPEC §4).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use lispcad::geom::bspline::BSpline;
use lispcad::geom::curve::xform;
use lispcad::geom::quadspline::QuadSpline;
use lispcad::geom::{Curve, DVec3, GeomError};

fn v(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, 0.0)
}
fn close(a: DVec3, b: DVec3, eps: f64) -> bool {
    (a - b).length() <= eps
}

#[test]
fn constructors_refuse_bad_input_naming_the_parameter() {
    let msg = |e: GeomError| e.to_string();
    assert!(msg(Curve::line(v(1.0, 1.0), v(1.0, 1.0)).unwrap_err()).contains("zero length"));
    assert!(msg(Curve::circle(v(0.0, 0.0), 0.0, None).unwrap_err()).starts_with("radius"));
    assert!(msg(Curve::circle(v(0.0, 0.0), -1.0, None).unwrap_err()).contains("> 0"));
    assert!(
        msg(Curve::circle(v(0.0, 0.0), 1.0, Some(DVec3::ZERO)).unwrap_err()).starts_with("normal")
    );
    assert!(msg(Curve::line(v(f64::NAN, 0.0), v(1.0, 0.0)).unwrap_err()).contains("finite"));
    assert!(
        msg(Curve::circle(v(0.0, 0.0), f64::INFINITY, None).unwrap_err()).starts_with("radius")
    );
    assert!(Curve::arc(v(0.0, 0.0), 1.0, 1.0, 1.0, None).is_err());
    assert!(
        msg(Curve::arc3(v(0.0, 0.0), v(1.0, 1.0), v(2.0, 2.0)).unwrap_err()).contains("collinear")
    );
    assert!(msg(
        Curve::pline(vec![v(0.0, 0.0), v(0.0, 0.0), v(1.0, 0.0)], false, None).unwrap_err()
    )
    .contains("coincide"));
    assert!(Curve::pline(vec![v(0.0, 0.0)], false, None).is_err());
    assert!(Curve::pline(vec![v(0.0, 0.0), v(1.0, 0.0)], false, Some(vec![0.0; 5])).is_err());
    assert!(Curve::bspline(vec![v(0.0, 0.0), v(1.0, 0.0)], 3, None, None).is_err());
}

#[test]
fn display_forms() {
    assert_eq!(
        Curve::line(v(0.0, 0.0), v(1.0, 1.0)).unwrap().to_string(),
        "#<LINE (0 0 0)-(1 1 0)>"
    );
    assert_eq!(
        Curve::circle(v(0.0, 0.0), 5.0, None).unwrap().to_string(),
        "#<CIRCLE (0 0 0) R5>"
    );
    assert_eq!(
        Curve::arc(v(0.5, 0.0), 2.5, 0.0, FRAC_PI_2, None)
            .unwrap()
            .to_string(),
        "#<ARC (0.5 0 0) R2.5 0 to 1.5708>"
    );
    let p = Curve::pline(
        vec![v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)],
        true,
        None,
    )
    .unwrap();
    assert_eq!(p.to_string(), "#<PLINE 4 closed>");
    let b = Curve::bspline(
        (0..5).map(|i| v(i as f64, (i % 2) as f64)).collect(),
        3,
        None,
        None,
    )
    .unwrap();
    assert_eq!(b.to_string(), "#<BSPLINE degree 3, 5 points>");
    assert_eq!(lispcad::geom::curve::fmt_g(1e-7), "1e-07");
    assert_eq!(lispcad::geom::curve::fmt_g(123456789.0), "1.23457e+08");
    assert_eq!(lispcad::geom::curve::fmt_g(-0.000123), "-0.000123");
}

#[test]
fn arc_angles_follow_the_dxf_ocs() {
    // Normal −Z: OCS X is −X world, so angle 0 is at (−r, 0).
    let a = Curve::arc(v(0.0, 0.0), 2.0, 0.0, FRAC_PI_2, Some(-DVec3::Z)).unwrap();
    assert!(close(a.eval(0.0), v(-2.0, 0.0), 1e-12));
    assert!(close(a.eval(1.0), v(0.0, 2.0), 1e-12));
    let c = Curve::circle(v(1.0, 1.0), 1.0, None).unwrap();
    assert!(close(c.eval(0.25), v(1.0, 2.0), 1e-12));
}

#[test]
fn arc3_passes_through_its_points() {
    let (p1, p2, p3) = (v(1.0, 0.0), v(0.0, 1.0), v(-1.0, 0.0));
    let a = Curve::arc3(p1, p2, p3).unwrap();
    assert!(close(a.eval(0.0), p1, 1e-12) && close(a.eval(1.0), p3, 1e-12));
    assert!((a.closest_point(p2).1 - p2).length() < 1e-12);
    // Clockwise order: the arc's normal flips, it still passes through p2.
    let b = Curve::arc3(p3, p2, p1).unwrap();
    assert!((b.closest_point(p2).1 - p2).length() < 1e-12);
    assert!((b.length() - PI).abs() < 1e-12);
    // In 3D.
    let c = Curve::arc3(
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.0),
    )
    .unwrap();
    assert!(close(c.eval(1.0), DVec3::new(0.0, 0.0, 1.0), 1e-12));
}

#[test]
fn lengths_and_points_at_length() {
    let c = Curve::circle(v(0.0, 0.0), 2.0, None).unwrap();
    assert!((c.length() - 4.0 * PI).abs() < 1e-12);
    assert!(close(c.point_at_length(PI).unwrap(), v(0.0, 2.0), 1e-12));
    assert!(c.point_at_length(-1.0).is_err() && c.point_at_length(100.0).is_err());
    // Polyline: square side 1 with one semicircular bulge (bulge 1) on the last side.
    let p = Curve::pline(
        vec![v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)],
        true,
        Some(vec![0.0, 0.0, 0.0, 1.0]),
    )
    .unwrap();
    assert!((p.length() - (3.0 + PI / 2.0)).abs() < 1e-12);
    // The bulged segment from (0,1) to (0,0) CCW: bulges out to the left (x < 0).
    assert!(
        close(p.eval(0.875), v(-0.5, 0.5), 1e-12),
        "{}",
        p.eval(0.875)
    );
    // Area: unit square plus half a disc of radius 1/2.
    assert!((p.area().unwrap() - (1.0 + PI / 8.0)).abs() < 1e-12);
    // Spline: a straight quadratic with uneven control gives exact length.
    let q = Curve::Spline(QuadSpline {
        points: vec![v(0.0, 0.0), v(4.0, 0.0)],
        closed: false,
        segments: vec![[v(0.0, 0.0), v(1.0, 0.0), v(4.0, 0.0)]],
    });
    assert!((q.length() - 4.0).abs() < 1e-12);
    let m = q.point_at_length(2.0).unwrap();
    assert!(close(m, v(2.0, 0.0), 1e-10), "{m}");
    // B-spline parabola y = x² on [0, 1]: length (2√5 + asinh 2)/4.
    let b = Curve::bspline(vec![v(0.0, 0.0), v(0.5, 0.0), v(1.0, 1.0)], 2, None, None).unwrap();
    let exact = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
    assert!((b.length() - exact).abs() < 1e-12, "{}", b.length() - exact);
}

#[test]
fn tangents_closest_points_and_boxes() {
    let a = Curve::arc(v(0.0, 0.0), 1.0, 0.0, PI, None).unwrap();
    assert!(close(a.tangent(0.5), v(-1.0, 0.0), 1e-12));
    let (t, p) = a.closest_point(v(0.0, 5.0));
    assert!((t - 0.5).abs() < 1e-12 && close(p, v(0.0, 1.0), 1e-12));
    let (t, p) = a.closest_point(v(0.5, -3.0));
    assert!(t == 0.0 && close(p, v(1.0, 0.0), 1e-12));
    let (lo, hi) = a.bbox();
    assert!(close(lo, v(-1.0, 0.0), 1e-12) && close(hi, v(1.0, 1.0), 1e-12));
    let b = Curve::bspline(vec![v(0.0, 0.0), v(1.0, 2.0), v(2.0, 0.0)], 2, None, None).unwrap();
    let (lo, hi) = b.bbox();
    assert!(
        close(lo, v(0.0, 0.0), 1e-12) && close(hi, v(2.0, 1.0), 1e-12),
        "{lo} {hi}"
    );
    let (t, p) = b.closest_point(v(1.0, 3.0));
    assert!((t - 0.5).abs() < 1e-9 && close(p, v(1.0, 1.0), 1e-9));
}

#[test]
fn curve_points_stay_within_tolerance() {
    let c = Curve::circle(v(0.0, 0.0), 10.0, None).unwrap();
    let pts = c.points(0.01).unwrap();
    assert!(close(pts[0], *pts.last().unwrap(), 1e-9));
    for w in pts.windows(2) {
        let m = (w[0] + w[1]) * 0.5;
        assert!(10.0 - m.length() <= 0.01 + 1e-12);
    }
    let b = Curve::bspline(
        vec![v(0.0, 0.0), v(1.0, 3.0), v(3.0, -2.0), v(4.0, 1.0)],
        3,
        None,
        None,
    )
    .unwrap();
    let pts = b.points(1e-4).unwrap();
    for w in pts.windows(2) {
        let m = (w[0] + w[1]) * 0.5;
        assert!((b.closest_point(m).1 - m).length() <= 1e-4 + 1e-12);
    }
    assert!(b.points(0.0).is_err());
}

#[test]
fn areas() {
    assert!(
        (Curve::circle(v(3.0, 3.0), 2.0, None)
            .unwrap()
            .area()
            .unwrap()
            - 4.0 * PI)
            .abs()
            < 1e-12
    );
    let sq = Curve::pline(
        vec![v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)],
        true,
        None,
    )
    .unwrap();
    assert!((sq.area().unwrap() - 4.0).abs() < 1e-12);
    assert!(Curve::line(v(0.0, 0.0), v(1.0, 0.0))
        .unwrap()
        .area()
        .is_err());
    // A rational quadratic B-spline circle (9 points): area π r².
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let ctrl = vec![
        v(1.0, 0.0),
        v(1.0, 1.0),
        v(0.0, 1.0),
        v(-1.0, 1.0),
        v(-1.0, 0.0),
        v(-1.0, -1.0),
        v(0.0, -1.0),
        v(1.0, -1.0),
        v(1.0, 0.0),
    ];
    let knots = vec![
        0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
    ];
    let c = Curve::bspline(
        ctrl,
        2,
        Some(knots),
        Some(vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0]),
    )
    .unwrap();
    assert!(c.is_closed());
    assert!(
        (c.area().unwrap() - PI).abs() < 1e-9,
        "{}",
        c.area().unwrap()
    );
    assert!((c.length() - TAU).abs() < 1e-9);
    // Non-planar closed polyline.
    let np = Curve::pline(
        vec![
            v(0.0, 0.0),
            v(1.0, 0.0),
            DVec3::new(1.0, 1.0, 1.0),
            v(0.0, 1.0),
        ],
        true,
        None,
    )
    .unwrap();
    assert!(matches!(np.area(), Err(GeomError::NotPlanar(_))));
}

#[test]
fn transforms() {
    let a = Curve::arc(v(1.0, 0.0), 1.0, 0.0, FRAC_PI_2, None).unwrap();
    let m = xform::mirror(v(0.0, 0.0), v(0.0, 1.0)).unwrap();
    let b = a.transform(&m).unwrap();
    // Mirrored in the Y axis: start (2,0) → (−2,0), end (1,1) → (−1,1); normal flips.
    assert!(close(b.eval(0.0), v(-2.0, 0.0), 1e-12) && close(b.eval(1.0), v(-1.0, 1.0), 1e-12));
    let Curve::Arc(ab) = &b else { panic!() };
    assert!(close(ab.normal(), -DVec3::Z, 1e-12));
    let r = a
        .transform(&xform::rotate(v(0.0, 0.0), FRAC_PI_2, None).unwrap())
        .unwrap();
    assert!(close(r.eval(0.0), v(0.0, 2.0), 1e-12));
    let s = a
        .transform(&xform::scale(v(0.0, 0.0), 2.0).unwrap())
        .unwrap();
    assert!((s.length() - PI).abs() < 1e-12);
    let mv = a
        .transform(&xform::translate(DVec3::new(0.0, 0.0, 5.0)))
        .unwrap();
    assert!(close(mv.eval(1.0), DVec3::new(1.0, 1.0, 5.0), 1e-12));
    // Non-uniform scale of an arc is refused; of a line it is fine.
    let ns = glam::DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
    assert!(a.transform(&ns).is_err());
    assert!(Curve::line(v(0.0, 0.0), v(1.0, 1.0))
        .unwrap()
        .transform(&ns)
        .is_ok());
    // Mirrored bulged polyline keeps its shape.
    let p = Curve::pline(vec![v(0.0, 0.0), v(2.0, 0.0)], false, Some(vec![1.0, 0.0])).unwrap();
    let pm = p.transform(&m).unwrap();
    for i in 0..=8 {
        let t = i as f64 / 8.0;
        let q = p.eval(t);
        assert!(close(pm.eval(t), v(-q.x, q.y), 1e-12), "{t}");
    }
}

#[test]
fn offsets() {
    let c = Curve::circle(v(0.0, 0.0), 2.0, None).unwrap();
    let Curve::Circle(o) = c.offset(1.0).unwrap() else {
        panic!()
    };
    assert_eq!(o.radius(), 3.0);
    assert!(c.offset(-2.0).is_err());
    let l = Curve::line(v(0.0, 0.0), v(1.0, 0.0))
        .unwrap()
        .offset(1.0)
        .unwrap();
    assert!(close(l.eval(0.0), v(0.0, -1.0), 1e-15));
    // CCW square offset outward by 1: miter corners.
    let sq = Curve::pline(
        vec![v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)],
        true,
        None,
    )
    .unwrap();
    let Curve::Polyline(o) = sq.offset(1.0).unwrap() else {
        panic!()
    };
    let expect = [v(-1.0, -1.0), v(3.0, -1.0), v(3.0, 3.0), v(-1.0, 3.0)];
    assert_eq!(o.vertices().len(), 4);
    for p in expect {
        assert!(
            o.vertices().iter().any(|q| close(*q, p, 1e-12)),
            "{:?}",
            o.vertices()
        );
    }
    // Rounded slot: two lines and two semicircles; offset keeps tangency, area grows.
    let slot = Curve::pline(
        vec![v(0.0, 0.0), v(4.0, 0.0), v(4.0, 2.0), v(0.0, 2.0)],
        true,
        Some(vec![0.0, 1.0, 0.0, 1.0]),
    )
    .unwrap();
    let big = slot.offset(0.5).unwrap();
    let exact = 4.0 * 3.0 + PI * 1.5 * 1.5;
    assert!(
        (big.area().unwrap() - exact).abs() < 1e-9,
        "{}",
        big.area().unwrap()
    );
    let spline =
        Curve::bspline(vec![v(0.0, 0.0), v(1.0, 1.0), v(2.0, 0.0)], 2, None, None).unwrap();
    assert!(matches!(spline.offset(1.0), Err(GeomError::Unsupported(_))));
    let approx = spline.offset_approx(0.1, 1e-4).unwrap();
    // Every point of the approximate offset is 0.1 from the spline (within the tolerance).
    for pt in approx.points(1e-3).unwrap() {
        let d = (spline.closest_point(pt).1 - pt).length();
        assert!((d - 0.1).abs() < 2e-4, "{d}");
    }
}

#[test]
fn bspline_and_quadspline_parameters_agree_with_their_types() {
    let bs = BSpline::new(
        3,
        (0..6).map(|i| v(i as f64, ((i * 7) % 3) as f64)).collect(),
        None,
        None,
    )
    .unwrap();
    let c = Curve::BSpline(bs.clone());
    use lispcad::geom::ParamCurve;
    for i in 0..=20 {
        let t = i as f64 / 20.0;
        assert!(close(c.eval(t), bs.eval(t), 1e-12));
        let h = 1e-6;
        let (t0, t1) = ((t - h).max(0.0), (t + h).min(1.0));
        let fd = (bs.eval(t1) - bs.eval(t0)) / (t1 - t0);
        assert!(
            (c.deriv(t) - fd).length() < 1e-4 * fd.length().max(1.0),
            "{t}"
        );
    }
}
