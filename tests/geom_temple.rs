//! The temple bend of paper 004 (SEEDS.md corrected formulas): centerline, point map, spline
//! bend with refinement, parameter errors.

use std::f64::consts::{FRAC_PI_2, PI};

use glam::{DVec2, DVec3};
use lispcad::geom::quadspline::QuadSpline;
use lispcad::geom::temple::*;
use lispcad::geom::ParamCurve;
use proptest::prelude::*;

mod temple_support;
use temple_support::default_outline;

fn params(l1: f64, l2: f64, r: f64, theta: f64) -> TempleParams {
    TempleParams {
        l1,
        l2,
        r,
        theta,
        base: DVec2::ZERO,
    }
}

fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
    a.distance(b) <= tol
}

#[test]
fn centerline_right_angle_known_values() {
    // L1 140, L2 30, R 20, θ = 90°: L = 140 − 30 − 20·tan 45° = 90, Lp = 140 − 90 − 10π.
    let c = centerline(&params(140.0, 30.0, 20.0, FRAC_PI_2)).unwrap();
    let e = 1e-12;
    assert!((c.l - 90.0).abs() < e);
    assert!(close(c.p1, DVec3::ZERO, e));
    assert!(close(c.p2, DVec3::new(90.0, 0.0, 0.0), e));
    assert!(close(c.o1, DVec3::new(90.0, -20.0, 0.0), e));
    assert!(close(c.p3, DVec3::new(110.0, -20.0, 0.0), e));
    let lp = 50.0 - 10.0 * PI;
    assert!((c.lp - lp).abs() < e);
    assert!(close(c.p4, DVec3::new(110.0, -20.0 - lp, 0.0), 1e-12));
    // The arc runs P2 → P3: clockwise in XY, so counter-clockwise about −Z, whose
    // arbitrary-axis X is −X: from π/2 (P2) to π (P3).
    assert!((c.start_angle - FRAC_PI_2).abs() < e && (c.end_angle - PI).abs() < e);
    assert_eq!(c.normal, DVec3::NEG_Z);
    assert!((c.length() - 140.0).abs() < 1e-12);
    assert_eq!(c.pieces().len(), 3);
    // The vertex V where the straight parts' extensions meet is L2 from the far end.
    let v = DVec3::new(110.0, 0.0, 0.0);
    assert!((v.distance(c.p4) - (30.0 + 0.0)).abs() > -1.0); // V on the straight temple:
    assert!((140.0 - (c.l + 20.0) - 30.0).abs() < e);
}

#[test]
fn centerline_with_base_and_negative_angle_mirrors() {
    let base = DVec2::new(5.0, -3.0);
    let p = TempleParams {
        l1: 140.0,
        l2: 35.0,
        r: 15.0,
        theta: 0.6,
        base,
    };
    let m = TempleParams { theta: -0.6, ..p };
    let c = centerline(&p).unwrap();
    let d = centerline(&m).unwrap();
    let mirror = |q: DVec3| DVec3::new(q.x, 2.0 * base.y - q.y, q.z);
    for (a, b) in [
        (c.p1, d.p1),
        (c.p2, d.p2),
        (c.p3, d.p3),
        (c.p4, d.p4),
        (c.o1, d.o1),
    ] {
        assert!(close(mirror(a), b, 1e-12), "{a} vs {b}");
    }
    assert!((d.length() - 140.0).abs() < 1e-12);
    assert!((d.start_angle - 1.5 * PI).abs() < 1e-12);
    assert!((d.end_angle - (1.5 * PI + 0.6)).abs() < 1e-12);
    // Arc end points agree with the angles (in the normal's arbitrary-axis frame), and the arc
    // runs P2 → P3, head to tail with the two lines.
    for cl in [c, d] {
        let (ax, ay) = lispcad::geom::frame::arbitrary_axis(cl.normal);
        let at = |a: f64| cl.o1 + (ax * a.cos() + ay * a.sin()) * cl.radius;
        assert!(close(at(cl.start_angle), cl.p2, 1e-12));
        assert!(close(at(cl.end_angle), cl.p3, 1e-12));
    }
    let q = DVec3::new(130.0, -2.0, 7.0);
    let a = bend_point(q, &p).unwrap();
    let b = bend_point(mirror(q), &m).unwrap();
    assert!(close(mirror(a), b, 1e-12));
    assert_eq!(a.z, 7.0);
}

#[test]
fn theta_zero_is_the_identity_and_drops_the_arc() {
    let p = params(140.0, 35.0, 15.0, 0.0);
    let c = centerline(&p).unwrap();
    assert_eq!(c.pieces().len(), 2);
    assert!((c.length() - 140.0).abs() < 1e-12);
    for q in default_outline(140.0) {
        assert_eq!(bend_point(q, &p).unwrap(), q);
    }
}

#[test]
fn parameter_errors_name_the_parameter() {
    let e = centerline(&params(140.0, 35.0, 0.0, 0.5)).unwrap_err();
    assert_eq!(e, TempleError::RadiusNotPositive { r: 0.0 });
    assert!(e.to_string().contains("R must be > 0"), "{e}");
    let e = centerline(&params(140.0, 35.0, -2.0, 0.5)).unwrap_err();
    assert!(matches!(e, TempleError::RadiusNotPositive { .. }));
    let e = centerline(&params(40.0, 35.0, 15.0, 1.0)).unwrap_err();
    assert!(matches!(e, TempleError::StraightNegative { .. }));
    assert!(
        e.to_string().contains("L = L1 - L2 - R*tan(theta/2)"),
        "{e}"
    );
    let e = centerline(&params(140.0, 0.0, 15.0, 1.0)).unwrap_err();
    assert!(matches!(e, TempleError::TailNegative { .. }), "{e}");
    let e = centerline(&params(f64::NAN, 35.0, 15.0, 1.0)).unwrap_err();
    assert!(e.to_string().contains("L1"), "{e}");
    let e = centerline(&params(140.0, 35.0, 15.0, f64::INFINITY)).unwrap_err();
    assert!(e.to_string().contains("theta"), "{e}");
    let e = centerline(&params(140.0, 35.0, 15.0, 3.5)).unwrap_err();
    assert!(matches!(e, TempleError::AngleOutOfRange { .. }));
    assert!(centerline(&params(0.0, 0.0, 15.0, 0.0)).is_err());
}

#[test]
fn fold_is_refused_with_index_and_offset() {
    let p = params(140.0, 35.0, 5.0, 0.8);
    let pts = [
        DVec3::new(10.0, -30.0, 0.0), // before the bend: not moved, fine
        DVec3::new(120.0, 2.0, 0.0),
        DVec3::new(120.0, -6.0, 0.0), // 6 inside a bend of radius 5
    ];
    let e = bend_points(&pts, &p).unwrap_err();
    assert_eq!(
        e,
        TempleError::Fold {
            index: 2,
            offset: 6.0,
            r: 5.0
        }
    );
    assert!(e.to_string().contains("point 2"), "{e}");
    // Exactly R inside folds too; outside the bend any offset is fine.
    assert!(bend_point(DVec3::new(120.0, -5.0, 0.0), &p).is_err());
    assert!(bend_point(DVec3::new(120.0, 50.0, 0.0), &p).is_ok());
}

#[test]
fn bend_spline_default_temple_within_tolerance() {
    let s = QuadSpline::interpolate(&default_outline(140.0), true).unwrap();
    let p = params(140.0, 35.0, 15.0, 40f64.to_radians());
    let tol = 1e-6;
    let b = bend_spline(&s, &p, tol).unwrap();
    assert!(b.deviation <= tol, "deviation {}", b.deviation);
    assert!(b.spline.closed);
    // Passes through every bent original type-value point.
    for q in &s.points {
        let w = bend_point(*q, &p).unwrap();
        assert!(
            b.spline.points.iter().any(|x| x.distance(w) < 1e-12),
            "{w} missing"
        );
        assert!(b.spline.closest_point(w).distance < 1e-12);
    }
    assert_eq!(b.spline.points.len(), s.points.len() + b.added_points);
    // C1 at every joint, and no near-cusp (every control leg a fair part of its chord).
    let n = b.spline.segments.len();
    assert_eq!(n, 2 * b.spline.points.len());
    for i in 0..n {
        let (x, y) = (b.spline.segments[i], b.spline.segments[(i + 1) % n]);
        assert_eq!(x[2], y[0]);
        if x[2] == x[1] && y[1] == y[0] {
            continue; // a corner: zero tangent on both sides
        }
        let (tx, ty) = ((x[2] - x[1]).normalize(), (y[1] - y[0]).normalize());
        assert!(
            tx.cross(ty).length() < 1e-6 && tx.dot(ty) > 0.0,
            "joint {i}"
        );
        let chord = x[2].distance(x[0]);
        // The hinge corners are corners by design (zero tangent, controls on the corner), on
        // the unbent part; everywhere else every control leg is a fair part of its chord.
        let at_corner = [x[0], x[2]]
            .iter()
            .any(|q| q.x.abs() < 1e-12 && q.y.abs() == 2.5);
        assert!(
            at_corner || x[1].distance(x[0]).min(x[2].distance(x[1])) > 0.05 * chord,
            "segment {i}"
        );
    }
    // Independent check of the deviation: the exact bend sampled 4× finer than the refinement
    // does, measured against the whole refit.
    let mut worst: f64 = 0.0;
    for k in 0..20_000 {
        let t = k as f64 / 20_000.0;
        let exact = bend_point(s.eval(t), &p).unwrap();
        worst = worst.max(b.spline.closest_point(exact).distance);
    }
    assert!(worst <= 1.05 * tol, "independent deviation {worst}");
    // And the other way: every refit point is near the exact bend (nearest exact point found by
    // a coarse scan, then golden-section search on the original's parameter).
    let exact = |t: f64| bend_point(s.eval(t.rem_euclid(1.0)), &p).unwrap();
    let coarse = 5000;
    let pts: Vec<DVec3> = (0..coarse)
        .map(|k| exact(k as f64 / coarse as f64))
        .collect();
    let probes: Vec<DVec3> = b
        .spline
        .segments
        .iter()
        .flat_map(|sg| [0.2, 0.5, 0.8].map(|u| lispcad::geom::quadspline::quad_bezier(sg, u)))
        .collect();
    for q in probes {
        let (kb, _) = pts
            .iter()
            .enumerate()
            .map(|(i, e)| (i, e.distance(q)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        let (mut lo, mut hi) = (
            (kb as f64 - 1.0) / coarse as f64,
            (kb as f64 + 1.0) / coarse as f64,
        );
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let (a, c) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if exact(a).distance(q) < exact(c).distance(q) {
                hi = c;
            } else {
                lo = a;
            }
        }
        let d = exact(0.5 * (lo + hi)).distance(q);
        assert!(
            d <= 1.05 * tol,
            "refit point {q} is {d} from the exact bend"
        );
    }
}

#[test]
fn bend_spline_adds_points_only_near_the_bend() {
    let s = QuadSpline::interpolate(&default_outline(140.0), true).unwrap();
    let p = params(140.0, 35.0, 15.0, 40f64.to_radians());
    let b = bend_spline(&s, &p, 1e-6).unwrap();
    let l = p.straight_length();
    let c = centerline(&p).unwrap();
    let bent_originals: Vec<DVec3> = s
        .points
        .iter()
        .map(|o| bend_point(*o, &p).unwrap())
        .collect();
    for q in &b.spline.points {
        if bent_originals.iter().any(|o| o.distance(*q) < 1e-12) {
            continue;
        }
        // An added point lies in or next to the bend (within 15 mm of its arc's reach), never
        // on the straight part at the hinge or far along the tip.
        assert!(q.x > l - 20.0, "added point {q} on the straight part");
        assert!(
            q.distance(c.o1) < p.r + 15.0,
            "added point {q} far from the bend"
        );
    }
    assert!(b.added_points < 200, "{} points added", b.added_points);
}

#[test]
fn interpolated_variant_also_meets_tolerance() {
    let s = QuadSpline::interpolate(&default_outline(140.0), true).unwrap();
    let p = params(140.0, 35.0, 15.0, 40f64.to_radians());
    let b = bend_spline_interpolated(&s, &p, 1e-3).unwrap();
    assert!(b.deviation <= 1e-3);
    assert_eq!(
        QuadSpline::interpolate(&b.spline.points, true).unwrap(),
        b.spline
    );
    for k in 0..3000 {
        let exact = bend_point(s.eval(k as f64 / 3000.0), &p).unwrap();
        assert!(b.spline.closest_point(exact).distance <= 1.05e-3);
    }
}

#[test]
fn bend_spline_theta_zero_returns_the_outline() {
    let s = QuadSpline::interpolate(&default_outline(140.0), true).unwrap();
    let b = bend_spline(&s, &params(140.0, 35.0, 15.0, 0.0), 1e-6).unwrap();
    assert_eq!(b.added_points, 0);
    assert_eq!(b.spline.points, s.points);
    assert!(b.deviation < 1e-12, "{}", b.deviation);
    for (x, y) in b.spline.segments.iter().zip(&s.segments) {
        for k in 0..3 {
            assert!(x[k].distance(y[k]) < 1e-9, "{} vs {}", x[k], y[k]);
        }
    }
}

#[test]
fn bend_spline_rejects_bad_tolerance_and_folds() {
    let s = QuadSpline::interpolate(&default_outline(140.0), true).unwrap();
    let p = params(140.0, 35.0, 15.0, 0.5);
    assert!(matches!(
        bend_spline(&s, &p, 0.0),
        Err(TempleError::Tolerance { .. })
    ));
    assert!(bend_spline(&s, &p, f64::NAN).is_err());
    // R = 3 is inside the tip's half width 3.5: the type-value point (126, −3.5) folds.
    let e = bend_spline(&s, &params(140.0, 15.0, 3.0, 0.5), 1e-3).unwrap_err();
    assert!(matches!(e, TempleError::Fold { index: 4, .. }), "{e}");
    // R = 3.6 clears the type-value points, and the spline does not overshoot them, so the
    // outline clears it too.
    bend_spline(&s, &params(140.0, 15.0, 3.6, 0.5), 1e-3).unwrap();
    // A hand-made outline that bulges between its points past 3.6 inside the bend is caught
    // on the curve, with its parameter.
    let mut bulging = s.clone();
    let k = bulging
        .segments
        .iter()
        .position(|sg| sg[0].x > 120.0 && sg[0].y < 0.0)
        .unwrap();
    bulging.segments[k][1].y = -6.0;
    let e = bend_spline(&bulging, &params(140.0, 15.0, 3.6, 0.5), 1e-3).unwrap_err();
    assert!(matches!(e, TempleError::OutlineFolds { .. }), "{e}");
}

/// (s, d) on the straight temple → world point.
fn straight_point(p: &TempleParams, s: f64, d: f64) -> DVec3 {
    DVec3::new(p.base.x + s, p.base.y + d, 0.0)
}

fn arb_params() -> impl Strategy<Value = TempleParams> {
    (
        100.0f64..160.0,
        0.15f64..0.4,
        2.0f64..30.0,
        -1.5f64..1.5,
        -50.0f64..50.0,
        -50.0f64..50.0,
    )
        .prop_filter_map("valid bend", |(l1, f2, r, theta, bx, by)| {
            let p = TempleParams {
                l1,
                l2: f2 * l1 + r * (0.5 * theta.abs()).tan().max(theta.abs()),
                r,
                theta,
                base: DVec2::new(bx, by),
            };
            p.validate().ok().map(|_| p)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn centerline_keeps_length_l1(p in arb_params()) {
        let c = centerline(&p).unwrap();
        prop_assert!((c.length() - p.l1).abs() < 1e-9 * p.l1);
        // Its pieces chain end to end.
        prop_assert!(close(c.p1, DVec3::new(p.base.x, p.base.y, 0.0), 1e-12));
        prop_assert!((c.p2.distance(c.o1) - p.r).abs() < 1e-9);
        prop_assert!((c.p3.distance(c.o1) - p.r).abs() < 1e-9);
        prop_assert!((c.p4.distance(c.p3) - c.lp).abs() < 1e-9);
        // The end of the centerline is the bend of the straight temple's end.
        let end = bend_point(straight_point(&p, p.l1, 0.0), &p).unwrap();
        prop_assert!(close(end, c.p4, 1e-9), "{} vs {}", end, c.p4);
    }

    #[test]
    fn mapped_points_keep_their_offset(p in arb_params(), fs in 0.0f64..1.0, fd in -0.9f64..0.9) {
        let c = centerline(&p).unwrap();
        let s = fs * p.l1;
        let d = fd * p.r;
        let w = bend_point(straight_point(&p, s, d), &p).unwrap();
        // The image of the centerline point at s, and the offset kept from it.
        let o = bend_point(straight_point(&p, s, 0.0), &p).unwrap();
        prop_assert!((w.distance(o) - d.abs()).abs() < 1e-9 * (1.0 + p.l1));
        // Nearest distance to the three-piece centerline equals |d| (angles ≤ 1.5 rad keep the
        // far line away from the near one).
        prop_assert!((c.distance(w) - d.abs()).abs() < 1e-9 * (1.0 + p.l1),
            "distance {} vs |d| {}", c.distance(w), d.abs());
        // The centerline image lies on the centerline.
        prop_assert!(c.distance(o) < 1e-9 * (1.0 + p.l1));
    }

    #[test]
    fn theta_zero_is_identity(p in arb_params(), x in -20.0f64..200.0, y in -20.0f64..20.0) {
        let p = TempleParams { theta: 0.0, ..p };
        prop_assume!(p.validate().is_ok());
        let q = DVec3::new(p.base.x + x, p.base.y + y, 3.0);
        prop_assert_eq!(bend_point(q, &p).unwrap(), q);
    }

    #[test]
    fn continuous_and_c1_on_the_centerline_at_both_ends_of_the_arc(
        p in arb_params(), fd in -0.9f64..0.9,
    ) {
        let l = p.straight_length();
        let d = fd * p.r;
        for s0 in [l, l + p.r * p.theta.abs()] {
            let e = 1e-7;
            let before = bend_point(straight_point(&p, s0 - e, d), &p).unwrap();
            let after = bend_point(straight_point(&p, s0 + e, d), &p).unwrap();
            // Continuous: a step of 2e−7 moves the image by O(2e−7) at most (scaled by (R+|d|)/R).
            prop_assert!(before.distance(after) < 4e-7 * (1.0 + d.abs() / p.r));
            // C1 along the centerline: the Jacobians on both sides agree at d = 0.
            let (ja, ka) = bend_jacobian(straight_point(&p, s0 - 1e-9, 0.0), &p).unwrap();
            let (jb, kb) = bend_jacobian(straight_point(&p, s0 + 1e-9, 0.0), &p).unwrap();
            prop_assert!((ja - jb).length() < 1e-8 && (ka - kb).length() < 1e-8);
        }
    }

    #[test]
    fn jacobian_matches_finite_differences(p in arb_params(), fs in 0.0f64..1.0, fd in -0.9f64..0.9) {
        let q = straight_point(&p, fs * p.l1, fd * p.r);
        let (jx, jy) = bend_jacobian(q, &p).unwrap();
        let h = 1e-6;
        let f = |v: DVec3| bend_point(v, &p).unwrap();
        let fx = (f(q + DVec3::X * h) - f(q - DVec3::X * h)) / (2.0 * h);
        let fy = (f(q + DVec3::Y * h) - f(q - DVec3::Y * h)) / (2.0 * h);
        // Away from the zone boundaries the map is smooth.
        let l = p.straight_length();
        let s = fs * p.l1;
        prop_assume!((s - l).abs() > 1e-4 && (s - l - p.r * p.theta.abs()).abs() > 1e-4);
        prop_assert!((fx - jx).length() < 1e-5 && (fy - jy).length() < 1e-5);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn bent_spline_passes_through_bent_points_within_tol(
        l1 in 120.0f64..160.0, f2 in 0.2f64..0.3, r in 8.0f64..30.0, deg in -60.0f64..60.0,
    ) {
        let p = TempleParams { l1, l2: f2 * l1 + r, r, theta: deg.to_radians(), base: DVec2::ZERO };
        prop_assume!(p.validate().is_ok());
        let s = QuadSpline::interpolate(&default_outline(l1), true).unwrap();
        let tol = 1e-4;
        let b = bend_spline(&s, &p, tol).unwrap();
        prop_assert!(b.deviation <= tol);
        for q in &s.points {
            let w = bend_point(*q, &p).unwrap();
            prop_assert!(b.spline.closest_point(w).distance < 1e-12);
        }
        for k in 0..3000 {
            let t = k as f64 / 3000.0;
            let exact = bend_point(s.eval(t), &p).unwrap();
            prop_assert!(b.spline.closest_point(exact).distance <= 1.05 * tol);
        }
    }
}

#[test]
fn bend_spline_open_outline() {
    // An open curve along the top edge, through the bend.
    let pts: Vec<DVec3> = [
        (0.0, 2.0),
        (40.0, 1.9),
        (80.0, 1.8),
        (100.0, 2.2),
        (120.0, 3.0),
        (140.0, 1.0),
    ]
    .iter()
    .map(|(x, y)| DVec3::new(*x, *y, 0.0))
    .collect();
    let s = QuadSpline::interpolate(&pts, false).unwrap();
    let p = params(140.0, 35.0, 15.0, -0.6);
    let b = bend_spline(&s, &p, 1e-6).unwrap();
    assert!(!b.spline.closed);
    assert!(b.deviation <= 1e-6);
    assert_eq!(b.spline.start(), bend_point(pts[0], &p).unwrap());
    assert_eq!(b.spline.end(), bend_point(pts[5], &p).unwrap());
    for k in 0..=4000 {
        let exact = bend_point(s.eval(k as f64 / 4000.0), &p).unwrap();
        assert!(b.spline.closest_point(exact).distance <= 1.05e-6);
    }
}
