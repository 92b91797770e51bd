//! QuadSpline::interpolate and its queries: interpolation, C1 joints, the B-spline form,
//! no wild overshoot, errors, length, nearest point, bbox, polyline approximation.

use glam::DVec3;
use lispcad::geom::quadspline::{quad_bezier, QuadSpline};
use lispcad::geom::quadspline_fit::QuadSplineError;
use lispcad::geom::ParamCurve;
use proptest::prelude::*;

fn v(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, 0.0)
}

fn scale(pts: &[DVec3]) -> f64 {
    pts.iter().fold(1.0f64, |m, p| m.max(p.abs().max_element()))
}

/// Every type-value point is the curve's point at its parameter, within 1e-12 (relative).
fn assert_interpolates(s: &QuadSpline, pts: &[DVec3]) {
    let tol = 1e-12 * scale(pts);
    for (j, p) in pts.iter().enumerate() {
        let q = s.eval(s.point_param(j));
        assert!(q.distance(*p) <= tol, "point {j}: {q} vs {p}");
    }
}

/// C1 at every joint: the end tangent of each segment and the start tangent of the next are
/// parallel and point the same way (and across the seam when closed).
fn assert_c1(s: &QuadSpline) {
    let n = s.segments.len();
    let joints = if s.closed { n } else { n - 1 };
    for i in 0..joints {
        let a = s.segments[i];
        let b = s.segments[(i + 1) % n];
        assert_eq!(a[2], b[0], "segments {i} and next are not joined");
        if a[2] == a[1] && b[1] == b[0] {
            // A zero tangent on both sides (derivative 0, still C1): only at a type-value point
            // where every coordinate turns back, a corner by design (see quadspline_fit).
            assert!(i % 2 == 1, "zero tangent at a mid-interval joint {i}");
            continue;
        }
        let ta = (a[2] - a[1]).normalize();
        let tb = (b[1] - b[0]).normalize();
        assert!(ta.cross(tb).length() < 1e-9, "joint {i}: {ta} vs {tb}");
        assert!(ta.dot(tb) > 0.0, "joint {i} reverses: {ta} vs {tb}");
    }
}

fn assert_bspline_matches(s: &QuadSpline) {
    let b = s.to_bspline();
    for k in 0..=400 {
        let t = k as f64 / 400.0;
        let d = b.eval(t).distance(s.eval(t));
        assert!(d < 1e-9, "t = {t}: {d}");
    }
}

fn temple_outline() -> Vec<DVec3> {
    vec![
        v(0.0, 2.5),
        v(42.0, 1.9375),
        v(84.0, 1.75),
        v(114.8, 2.625),
        v(131.6, 3.5),
        v(140.0, 0.0),
        v(131.6, -3.5),
        v(114.8, -2.625),
        v(84.0, -1.75),
        v(42.0, -1.9375),
        v(0.0, -2.5),
    ]
}

#[test]
fn closed_temple_outline_interpolates_and_is_c1() {
    let pts = temple_outline();
    let s = QuadSpline::interpolate(&pts, true).unwrap();
    assert_eq!(s.segments.len(), 2 * pts.len());
    assert_eq!(s.eval(0.0), pts[0]);
    assert_eq!(s.eval(1.0), pts[0]);
    assert_interpolates(&s, &pts);
    assert_c1(&s);
    assert_bspline_matches(&s);
}

#[test]
fn open_layout_two_segments_per_interval() {
    for n in 2..8 {
        let pts: Vec<DVec3> = (0..n).map(|i| v(i as f64, ((i * i) % 5) as f64)).collect();
        let s = QuadSpline::interpolate(&pts, false).unwrap();
        assert_eq!(s.segments.len(), 2 * (n - 1), "n = {n}");
        assert_eq!(s.start(), pts[0]);
        assert_eq!(s.end(), pts[n - 1]);
        assert_interpolates(&s, &pts);
        assert_c1(&s);
        assert_bspline_matches(&s);
    }
}

#[test]
fn closing_point_repeated_is_dropped() {
    let mut pts = temple_outline();
    let s1 = QuadSpline::interpolate(&pts, true).unwrap();
    pts.push(pts[0]);
    let s2 = QuadSpline::interpolate(&pts, true).unwrap();
    assert_eq!(s1, s2);
}

#[test]
fn collinear_points_give_a_straight_curve() {
    let pts = [
        v(0.0, 0.0),
        v(1.0, 1.0),
        v(1.5, 1.5),
        v(4.0, 4.0),
        v(4.1, 4.1),
    ];
    let s = QuadSpline::interpolate(&pts, false).unwrap();
    for seg in &s.segments {
        for p in seg {
            assert!((p.x - p.y).abs() < 1e-12, "{p} off the line");
        }
    }
    // Monotone along the line: no overshoot past the ends or back-tracking.
    let mut last = -1.0;
    for k in 0..=1000 {
        let x = s.eval(k as f64 / 1000.0).x;
        assert!(
            x >= last - 1e-12 && (-1e-12..=4.1 + 1e-12).contains(&x),
            "x = {x}"
        );
        last = x;
    }
}

#[test]
fn circle_points_stay_close_to_the_circle() {
    let n = 16;
    let pts: Vec<DVec3> = (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            v(10.0 * a.cos(), 10.0 * a.sin())
        })
        .collect();
    let s = QuadSpline::interpolate(&pts, true).unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..2000 {
        let p = s.eval(k as f64 / 2000.0);
        worst = worst.max((p.length() - 10.0).abs());
    }
    // Quadratic spline error on 16 points of r = 10 is O(r·(π/8)³) ≈ small; far below a chord's sag.
    let sag = 10.0 * (1.0 - (std::f64::consts::PI / n as f64).cos());
    assert!(worst < 0.1 * sag, "worst {worst}, sag {sag}");
    let len = s.length(1e-12);
    assert!(
        // The local, shape-preserving rule is less accurate than a global interpolant (0.03 %
        // short here, 0.1 % of the chord's sag in radius): the price of never overshooting.
        (len - std::f64::consts::TAU * 10.0).abs() < 2.5e-2,
        "length {len}"
    );
}

#[test]
fn uneven_spacing_does_not_overshoot_wildly() {
    // An L-shaped run with a long leg next to very short steps.
    let pts = [
        v(0.0, 0.0),
        v(100.0, 0.0),
        v(100.5, 0.0),
        v(100.5, 0.5),
        v(100.5, 100.0),
    ];
    let s = QuadSpline::interpolate(&pts, false).unwrap();
    assert_interpolates(&s, &pts);
    assert_c1(&s);
    let (lo, hi) = s.bbox();
    // The curve may round the corner but must stay near the polyline's box.
    assert!(lo.x > -2.0 && lo.y > -2.0, "{lo}");
    assert!(hi.x < 102.5 && hi.y < 102.0, "{hi}");
}

#[test]
fn errors_name_the_point() {
    assert_eq!(
        QuadSpline::interpolate(&[v(0.0, 0.0)], false),
        Err(QuadSplineError::TooFewPoints {
            need: 2,
            got: 1,
            closed: false
        })
    );
    assert!(matches!(
        QuadSpline::interpolate(&[v(0.0, 0.0), v(1.0, 0.0)], true),
        Err(QuadSplineError::TooFewPoints { need: 3, .. })
    ));
    let e = QuadSpline::interpolate(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 0.0), v(2.0, 1.0)], false)
        .unwrap_err();
    assert!(matches!(
        e,
        QuadSplineError::Coincident {
            index: 1,
            next: 2,
            ..
        }
    ));
    assert!(e.to_string().contains("points 1 and 2"), "{e}");
    let e =
        QuadSpline::interpolate(&[v(0.0, 0.0), v(1.0, f64::NAN), v(2.0, 0.0)], false).unwrap_err();
    assert!(matches!(e, QuadSplineError::NonFinite { index: 1, .. }));
    let e = QuadSpline::interpolate(&[v(0.0, 0.0), v(1.0, 0.0), v(f64::INFINITY, 0.0)], true)
        .unwrap_err();
    assert!(matches!(e, QuadSplineError::NonFinite { index: 2, .. }));
}

#[test]
fn length_of_a_line() {
    let s = QuadSpline::interpolate(&[v(0.0, 0.0), v(3.0, 4.0)], false).unwrap();
    assert!((s.length(1e-14) - 5.0).abs() < 1e-12);
    assert!((s.length_to(0.5, 1e-14) - 2.5).abs() < 1e-12);
    let t = s.param_at_length(1.0, 1e-13);
    assert!(s.eval(t).distance(v(0.6, 0.8)) < 1e-12);
}

#[test]
fn polyline_approximation_within_tolerance() {
    let s = QuadSpline::interpolate(&temple_outline(), true).unwrap();
    for tol in [1e-1, 1e-3, 1e-5] {
        let poly = s.points(tol);
        assert_eq!(poly[0], *poly.last().unwrap());
        for w in poly.windows(2) {
            for k in 1..8 {
                let m = w[0].lerp(w[1], k as f64 / 8.0);
                let d = s.closest_point(m).distance;
                assert!(d <= tol * (1.0 + 1e-9), "tol {tol}: chord off by {d}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn interpolates_any_distinct_points(
        raw in prop::collection::vec((-100.0f64..100.0, -100.0f64..100.0, -10.0f64..10.0), 2..24),
        closed in any::<bool>(),
    ) {
        let pts: Vec<DVec3> = raw.iter().map(|(x, y, z)| DVec3::new(*x, *y, *z)).collect();
        let n = pts.len();
        let distinct = (0..n).all(|i| {
            let j = (i + 1) % n;
            (j == 0 && !closed) || pts[i].distance(pts[j]) > 1e-3
        });
        prop_assume!(distinct && (!closed || n >= 3));
        let s = QuadSpline::interpolate(&pts, closed).unwrap();
        assert_interpolates(&s, &pts);
        assert_c1(&s);
        assert_bspline_matches(&s);
        prop_assert!(s.segments.iter().flatten().all(|p| p.is_finite()));
    }

    #[test]
    fn nearest_point_beats_dense_sampling(
        px in -20.0f64..160.0, py in -20.0f64..20.0,
    ) {
        let s = QuadSpline::interpolate(&temple_outline(), true).unwrap();
        let p = v(px, py);
        let near = s.closest_point(p);
        prop_assert!(near.point.distance(s.eval(near.t)) < 1e-9);
        prop_assert!((near.point.distance(p) - near.distance).abs() < 1e-12);
        for k in 0..=4000 {
            let q = s.eval(k as f64 / 4000.0);
            prop_assert!(near.distance <= q.distance(p) + 1e-12);
        }
    }

    #[test]
    fn bbox_is_tight(raw in prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0), 3..10)) {
        let pts: Vec<DVec3> = raw.iter().map(|(x, y)| v(*x, *y)).collect();
        let n = pts.len();
        prop_assume!((0..n).all(|i| pts[i].distance(pts[(i + 1) % n]) > 1e-3));
        let s = QuadSpline::interpolate(&pts, true).unwrap();
        let (lo, hi) = s.bbox();
        let (mut slo, mut shi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for seg in &s.segments {
            for k in 0..=200 {
                let q = quad_bezier(seg, k as f64 / 200.0);
                prop_assert!(q.cmpge(lo - 1e-12).all() && q.cmple(hi + 1e-12).all());
                slo = slo.min(q);
                shi = shi.max(q);
            }
        }
        // Tight: the sampled extremes come within a sampling step of the box.
        prop_assert!((slo - lo).length() < 1e-2 && (shi - hi).length() < 1e-2);
    }

    #[test]
    fn derivative_matches_finite_differences(t in 0.01f64..0.99) {
        let s = QuadSpline::interpolate(&temple_outline(), true).unwrap();
        let h = 1e-6;
        let fd = (s.eval(t + h) - s.eval(t - h)) / (2.0 * h);
        let (i0, _) = s.locate(t - h);
        let (i1, _) = s.locate(t + h);
        prop_assume!(i0 == i1);
        prop_assert!((fd - s.derivative(t)).length() < 1e-4 * (1.0 + fd.length()));
    }
}

#[test]
fn reversed_and_transformed_keep_the_layout() {
    use glam::DMat4;
    for closed in [false, true] {
        let pts = temple_outline();
        let s = QuadSpline::interpolate(&pts, closed).unwrap();
        let r = s.reversed();
        let n = r.points.len();
        for j in 0..n {
            let q = r.eval(r.point_param(j));
            assert!(q.distance(r.points[j]) < 1e-12);
        }
        for k in 0..=100 {
            let t = k as f64 / 100.0;
            assert!(r.eval(t).distance(s.eval(1.0 - t)) < 1e-9);
        }
        let m = DMat4::from_rotation_z(0.7) * DMat4::from_translation(DVec3::new(3.0, -2.0, 1.0));
        let moved = s.transformed(&m);
        for k in 0..=100 {
            let t = k as f64 / 100.0;
            assert!(moved.eval(t).distance(m.transform_point3(s.eval(t))) < 1e-12);
        }
    }
}
