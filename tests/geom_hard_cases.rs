//! Named hard cases for curve/curve intersection (issue 3): tangencies, near misses,
//! overlaps, seams, end points, many roots, close roots, non-coplanar circles.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use lispcad::geom::bspline::BSpline;
use lispcad::geom::quadspline::QuadSpline;
use lispcad::geom::{intersect, Curve, DVec3, Hit, HitKind};

const TOL: f64 = 1e-9;

fn v(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, 0.0)
}
fn v3(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}
fn line(a: DVec3, b: DVec3) -> Curve {
    Curve::line(a, b).unwrap()
}
fn circle(c: DVec3, r: f64) -> Curve {
    Curve::circle(c, r, None).unwrap()
}
fn arc(c: DVec3, r: f64, a0: f64, a1: f64) -> Curve {
    Curve::arc(c, r, a0, a1, None).unwrap()
}
fn close(a: DVec3, b: DVec3, eps: f64) -> bool {
    (a - b).length() <= eps
}
fn kinds(h: &[Hit]) -> Vec<&'static str> {
    h.iter().map(|h| h.kind_name()).collect()
}

/// Both orders give the same points with swapped parameters.
fn both(a: &Curve, b: &Curve) -> Vec<Hit> {
    let h1 = intersect(a, b, TOL);
    let mut h2 = intersect(b, a, TOL);
    assert_eq!(
        h1.len(),
        h2.len(),
        "order changes the count: {h1:?} vs {h2:?}"
    );
    h2.sort_by(|x, y| x.t2.total_cmp(&y.t2));
    for (x, y) in h1.iter().zip(&h2) {
        if let (HitKind::Overlap(c1), HitKind::Overlap(c2)) = (&x.kind, &y.kind) {
            // The shared piece runs along the first curve: same ends, maybe swapped.
            let (a0, a1, b0, b1) = (c1.eval(0.0), c1.eval(1.0), c2.eval(0.0), c2.eval(1.0));
            assert!(
                (close(a0, b0, 1e-9) && close(a1, b1, 1e-9))
                    || (close(a0, b1, 1e-9) && close(a1, b0, 1e-9)),
                "{x:?} vs {y:?}"
            );
            continue;
        }
        assert!(close(x.point, y.point, 1e-12), "{x:?} vs {y:?}");
        assert!((x.t1 - y.t2).abs() < 1e-12 && (x.t2 - y.t1).abs() < 1e-12);
        assert_eq!(x.kind_name(), y.kind_name());
    }
    for h in &h1 {
        if !matches!(h.kind, HitKind::Overlap(_)) {
            assert!(close(a.eval(h.t1), h.point, 1e-9), "{h:?} not on a");
            assert!(close(b.eval(h.t2), h.point, 1e-9), "{h:?} not on b");
        }
    }
    h1
}

#[test]
fn tangent_line_circle() {
    let h = both(&line(v(-2.0, 1.0), v(2.0, 1.0)), &circle(v(0.0, 0.0), 1.0));
    assert_eq!(kinds(&h), ["TANGENT"]);
    assert!(close(h[0].point, v(0.0, 1.0), 1e-12));
    assert!((h[0].t1 - 0.5).abs() < 1e-12 && (h[0].t2 - 0.25).abs() < 1e-12);
}

#[test]
fn line_near_miss_is_no_hit() {
    let h = both(
        &line(v(-2.0, 1.0 + 1e-8), v(2.0, 1.0 + 1e-8)),
        &circle(v(0.0, 0.0), 1.0),
    );
    assert!(h.is_empty(), "{h:?}");
}

#[test]
fn tangent_circles_outside_and_inside() {
    let h = both(&circle(v(0.0, 0.0), 1.0), &circle(v(2.0, 0.0), 1.0));
    assert_eq!(kinds(&h), ["TANGENT"]);
    assert!(close(h[0].point, v(1.0, 0.0), 1e-12));
    let h = both(&circle(v(0.0, 0.0), 2.0), &circle(v(1.0, 0.0), 1.0));
    assert_eq!(kinds(&h), ["TANGENT"]);
    assert!(close(h[0].point, v(2.0, 0.0), 1e-12));
}

#[test]
fn near_tangent_circles_meet_twice() {
    let d = 2.0 - 1e-9;
    let h = both(&circle(v(0.0, 0.0), 1.0), &circle(v(d, 0.0), 1.0));
    assert_eq!(kinds(&h), ["CROSS", "CROSS"]);
    let gap = (h[0].point - h[1].point).length();
    assert!((gap - 6.3245e-5).abs() < 1e-8, "gap {gap}");
    for p in [h[0].point, h[1].point] {
        assert!((p.length() - 1.0).abs() < 1e-15);
        assert!(((p - v(d, 0.0)).length() - 1.0).abs() < 1e-15);
    }
    // 1e-8 apart: no hit.
    assert!(both(&circle(v(0.0, 0.0), 1.0), &circle(v(2.0 + 1e-8, 0.0), 1.0)).is_empty());
}

#[test]
fn coincident_and_overlapping_arcs() {
    let a = arc(v(0.0, 0.0), 1.0, 0.0, FRAC_PI_2);
    let h = both(&a, &a.clone());
    assert_eq!(kinds(&h), ["OVERLAP"]);
    let b = arc(v(0.0, 0.0), 1.0, FRAC_PI_4, PI);
    let h = both(&a, &b);
    assert_eq!(kinds(&h), ["OVERLAP"]);
    let Some(Curve::Arc(o)) = h[0].overlap() else {
        panic!("{h:?}")
    };
    assert!((o.start_angle() - FRAC_PI_4).abs() < 1e-12 && (o.sweep() - FRAC_PI_4).abs() < 1e-12);
    assert!((h[0].t1 - 0.5).abs() < 1e-12 && h[0].t2.abs() < 1e-12);
    // Same arc reversed (normal −Z) still overlaps.
    let r = Curve::arc(v(0.0, 0.0), 1.0, FRAC_PI_2, PI, Some(-DVec3::Z)).unwrap();
    // Under −Z the OCS X axis is −X: the arc runs CW in plan from (0,1) to (1,0).
    assert!(close(r.eval(0.0), v(0.0, 1.0), 1e-12), "{}", r.eval(0.0));
    assert!(close(r.eval(1.0), v(1.0, 0.0), 1e-12), "{}", r.eval(1.0));
    let h = both(&a, &r);
    assert_eq!(kinds(&h), ["OVERLAP"]);
    assert!(
        h[0].t1.abs() < 1e-12 && (h[0].t2 - 1.0).abs() < 1e-12,
        "{h:?}"
    );
    // π..3π/2 about −Z is world 0..−π/2: touches a at (1, 0) only.
    let w = Curve::arc(v(0.0, 0.0), 1.0, PI, 3.0 * FRAC_PI_2, Some(-DVec3::Z)).unwrap();
    let h = both(&a, &w);
    assert_eq!(kinds(&h), ["TANGENT"]);
    assert!(close(h[0].point, v(1.0, 0.0), 1e-12));
    // Arcs on one circle touching end to end.
    let c = arc(v(0.0, 0.0), 1.0, FRAC_PI_2, PI);
    let h = both(&a, &c);
    assert_eq!(kinds(&h), ["TANGENT"]);
    assert!(close(h[0].point, v(0.0, 1.0), 1e-12));
}

#[test]
fn overlapping_segments() {
    let h = both(
        &line(v(0.0, 0.0), v(2.0, 0.0)),
        &line(v(1.0, 0.0), v(3.0, 0.0)),
    );
    assert_eq!(kinds(&h), ["OVERLAP"]);
    let Some(Curve::Line(l)) = h[0].overlap() else {
        panic!()
    };
    assert!(close(l.p0, v(1.0, 0.0), 1e-15) && close(l.p1, v(2.0, 0.0), 1e-15));
    assert!((h[0].t1 - 0.5).abs() < 1e-15 && h[0].t2.abs() < 1e-15);
    // Opposite direction: piece still runs along the first curve.
    let h = both(
        &line(v(0.0, 0.0), v(2.0, 0.0)),
        &line(v(3.0, 0.0), v(1.0, 0.0)),
    );
    let Some(Curve::Line(l)) = h[0].overlap() else {
        panic!()
    };
    assert!(close(l.p0, v(1.0, 0.0), 1e-15) && close(l.p1, v(2.0, 0.0), 1e-15));
    // Collinear, touching end to end.
    let h = both(
        &line(v(0.0, 0.0), v(1.0, 0.0)),
        &line(v(1.0, 0.0), v(2.0, 0.0)),
    );
    assert_eq!(kinds(&h), ["TANGENT"]);
    // Collinear, apart.
    assert!(both(
        &line(v(0.0, 0.0), v(1.0, 0.0)),
        &line(v(1.5, 0.0), v(2.0, 0.0))
    )
    .is_empty());
}

#[test]
fn near_parallel_lines() {
    let h = both(
        &line(v(0.0, 0.0), v(1.0, 0.0)),
        &line(v(0.0, -1e-7), v(1.0, 1e-7)),
    );
    assert_eq!(kinds(&h), ["CROSS"]);
    assert!(close(h[0].point, v(0.5, 0.0), 1e-12));
    assert!((h[0].t1 - 0.5).abs() < 1e-9);
    // Parallel 1e-8 apart: nothing.
    assert!(both(
        &line(v(0.0, 0.0), v(1.0, 0.0)),
        &line(v(0.0, 1e-8), v(1.0, 1e-8))
    )
    .is_empty());
}

#[test]
fn arcs_across_the_seam() {
    let a = arc(v(0.0, 0.0), 1.0, 350f64.to_radians(), 10f64.to_radians());
    let h = both(&line(v(0.5, 0.0), v(2.0, 0.0)), &a);
    assert_eq!(kinds(&h), ["CROSS"]);
    assert!(close(h[0].point, v(1.0, 0.0), 1e-12));
    assert!((h[0].t2 - 0.5).abs() < 1e-12);
    let b = arc(v(0.0, 0.0), 1.0, 0.0, 20f64.to_radians());
    let h = both(&a, &b);
    assert_eq!(kinds(&h), ["OVERLAP"]);
    let Some(Curve::Arc(o)) = h[0].overlap() else {
        panic!()
    };
    assert!(o.start_angle().abs() < 1e-12 && (o.sweep() - 10f64.to_radians()).abs() < 1e-12);
    // An arc across the seam against a circle: the arc itself is the overlap.
    let h = both(&a, &circle(v(0.0, 0.0), 1.0));
    assert_eq!(kinds(&h), ["OVERLAP"]);
}

#[test]
fn segments_meeting_at_end_points() {
    let h = both(
        &line(v(0.0, 0.0), v(1.0, 0.0)),
        &line(v(1.0, 0.0), v(1.0, 1.0)),
    );
    assert_eq!(kinds(&h), ["CROSS"]);
    assert!((h[0].t1 - 1.0).abs() < 1e-15 && h[0].t2.abs() < 1e-15);
    // A polyline through the vertex of another: one point, not two.
    let p = Curve::pline(vec![v(0.0, -1.0), v(1.0, 0.0), v(0.0, 1.0)], false, None).unwrap();
    let h = both(&p, &line(v(0.0, 0.0), v(2.0, 0.0)));
    assert_eq!(kinds(&h), ["CROSS"]);
    assert!(close(h[0].point, v(1.0, 0.0), 1e-12) && (h[0].t1 - 0.5).abs() < 1e-12);
}

/// Bernstein coefficients of the cubic with power coefficients a0..a3.
fn bern3(a: [f64; 4]) -> [f64; 4] {
    let c = |k: usize, i: usize| -> f64 {
        let f = |n: usize| (1..=n).product::<usize>() as f64;
        f(k) / (f(i) * f(k - i))
    };
    let mut b = [0.0; 4];
    for (k, bk) in b.iter_mut().enumerate() {
        for (i, ai) in a.iter().enumerate().take(k + 1) {
            *bk += c(k, i) / c(3, i) * ai;
        }
    }
    b
}

fn cubic_power(k: f64, r: [f64; 3]) -> [f64; 4] {
    // 0.5 + k (x − r0)(x − r1)(x − r2)
    let (a, b, c) = (r[0], r[1], r[2]);
    [
        0.5 - k * a * b * c,
        k * (a * b + b * c + a * c),
        -k * (a + b + c),
        k,
    ]
}

#[test]
fn cubic_pair_with_nine_crossings() {
    let p = cubic_power(18.0, [0.1, 0.45, 0.9]);
    let q = cubic_power(29.0, [0.12, 0.55, 0.88]);
    let (bp, bq) = (bern3(p), bern3(q));
    let pa: Vec<DVec3> = (0..4).map(|i| v(i as f64 / 3.0, bp[i])).collect();
    let pb: Vec<DVec3> = (0..4).map(|i| v(bq[i], i as f64 / 3.0)).collect();
    let a = Curve::BSpline(BSpline::new(3, pa, None, None).unwrap());
    let b = Curve::BSpline(BSpline::new(3, pb, None, None).unwrap());
    let h = both(&a, &b);
    assert_eq!(h.len(), 9, "{h:?}");
    let poly = |c: [f64; 4], x: f64| c[0] + x * (c[1] + x * (c[2] + x * c[3]));
    let expect_x = [
        0.03470673262228954,
        0.13563990965397413,
        0.2119437141949558,
        0.2764098035890559,
        0.425388843381012,
        0.5847865063140416,
        0.8328980131149866,
        0.8928549721355195,
        0.9553715049941652,
    ];
    for (hit, x) in h.iter().zip(expect_x) {
        assert_eq!(hit.kind, HitKind::Cross);
        assert!((hit.point.x - x).abs() < 1e-9, "{hit:?} vs x = {x}");
        assert!((poly(p, hit.point.x) - hit.point.y).abs() < 1e-9);
        assert!((poly(q, hit.point.y) - hit.point.x).abs() < 1e-9);
    }
}

fn quad(segs: Vec<[DVec3; 3]>) -> Curve {
    let mut points = vec![segs[0][0]];
    points.extend(segs.iter().map(|s| s[2]));
    Curve::Spline(QuadSpline {
        points,
        closed: false,
        segments: segs,
    })
}

#[test]
fn spline_grazing_a_line_two_roots_7e6_apart() {
    // y = (x − 0.5)² − (3.5e-6)² on x in [0, 1]: roots at 0.5 ± 3.5e-6.
    let c = 3.5e-6f64 * 3.5e-6;
    let s = quad(vec![[
        v(0.0, 0.25 - c),
        v(0.5, -0.25 - c),
        v(1.0, 0.25 - c),
    ]]);
    let h = both(&s, &line(v(-1.0, 0.0), v(2.0, 0.0)));
    assert_eq!(kinds(&h), ["CROSS", "CROSS"], "{h:?}");
    assert!((h[0].point.x - (0.5 - 3.5e-6)).abs() < 1e-11, "{h:?}");
    assert!((h[1].point.x - (0.5 + 3.5e-6)).abs() < 1e-11, "{h:?}");
    // Touching exactly: one tangent point.
    let s = quad(vec![[v(0.0, 0.25), v(0.5, -0.25), v(1.0, 0.25)]]);
    let h = both(&s, &line(v(-1.0, 0.0), v(2.0, 0.0)));
    assert_eq!(kinds(&h), ["TANGENT"], "{h:?}");
    assert!(close(h[0].point, v(0.5, 0.0), 1e-9));
    // Missing by 1e-8: nothing.
    let s = quad(vec![[
        v(0.0, 0.25 + 1e-8),
        v(0.5, -0.25 + 1e-8),
        v(1.0, 0.25 + 1e-8),
    ]]);
    assert!(both(&s, &line(v(-1.0, 0.0), v(2.0, 0.0))).is_empty());
}

#[test]
fn spline_line_hit_at_the_spline_end_point() {
    let s = quad(vec![
        [v(0.0, 0.0), v(0.5, 1.0), v(1.0, 0.5)],
        [v(1.0, 0.5), v(1.5, 0.0), v(2.0, 0.0)],
    ]);
    let h = both(&s, &line(v(2.0, -1.0), v(2.0, 1.0)));
    assert_eq!(h.len(), 1, "{h:?}");
    assert!(close(h[0].point, v(2.0, 0.0), 1e-12));
    assert!((h[0].t1 - 1.0).abs() < 1e-12 && (h[0].t2 - 0.5).abs() < 1e-12);
    // And at the joint between the two segments: one point.
    let h = both(&s, &line(v(1.0, -1.0), v(1.0, 2.0)));
    assert_eq!(h.len(), 1, "{h:?}");
    assert!(close(h[0].point, v(1.0, 0.5), 1e-12));
}

#[test]
fn non_coplanar_circles_meet_at_two_and_one_points() {
    let a = circle(v(0.0, 0.0), 1.0);
    let b = Curve::circle(v3(0.0, 0.0, 0.0), 1.0, Some(DVec3::X)).unwrap();
    let h = both(&a, &b);
    assert_eq!(h.len(), 2, "{h:?}");
    assert!(close(h[0].point, v(0.0, 1.0), 1e-12) && close(h[1].point, v(0.0, -1.0), 1e-12));
    let c = Curve::circle(v3(0.0, 1.0, 1.0), 1.0, Some(DVec3::X)).unwrap();
    let h = both(&a, &c);
    assert_eq!(kinds(&h), ["CROSS"], "{h:?}");
    assert!(close(h[0].point, v(0.0, 1.0), 1e-12));
    // Lifted by 1e-8: no hit.
    let c = Curve::circle(v3(0.0, 1.0, 1.0 + 1e-8), 1.0, Some(DVec3::X)).unwrap();
    assert!(both(&a, &c).is_empty());
    // Tilted arcs in 3D.
    // OCS of (1,0,1): X = (0,1,0), so angle 0 is (0,1,0) and π/2 is (−1,0,1)/√2.
    let d = Curve::arc(
        v3(0.0, 0.0, 0.0),
        1.0,
        0.0,
        FRAC_PI_2,
        Some(v3(1.0, 0.0, 1.0)),
    )
    .unwrap();
    let h = both(&a, &d);
    assert_eq!(h.len(), 1, "{h:?}");
}

#[test]
fn line_piercing_circle_plane_on_the_circle() {
    let h = both(
        &line(v3(1.0, 0.0, -1.0), v3(1.0, 0.0, 1.0)),
        &circle(v(0.0, 0.0), 1.0),
    );
    assert_eq!(kinds(&h), ["CROSS"]);
    assert!(close(h[0].point, v(1.0, 0.0), 1e-15));
    assert!((h[0].t1 - 0.5).abs() < 1e-15 && h[0].t2.abs() < 1e-15);
    let h = both(
        &line(v3(1.0 + 1e-8, 0.0, -1.0), v3(1.0 + 1e-8, 0.0, 1.0)),
        &circle(v(0.0, 0.0), 1.0),
    );
    assert!(h.is_empty());
}

#[test]
fn spline_against_circle_and_spline() {
    let s = quad(vec![[v(-2.0, 0.0), v(0.0, 2.0), v(2.0, 0.0)]]);
    // y = 1 − x²/4 on [−2, 2] meets the unit circle at (0,1) tangentially? (curvature differs)
    let c = circle(v(0.0, 0.0), 1.0);
    let h = both(&s, &c);
    assert_eq!(kinds(&h), ["TANGENT"], "{h:?}");
    assert!(close(h[0].point, v(0.0, 1.0), 1e-9));
    let s2 = quad(vec![[v(-2.0, 1.5), v(0.0, -0.5), v(2.0, 1.5)]]);
    let h = both(&s, &s2);
    assert_eq!(kinds(&h), ["CROSS", "CROSS"], "{h:?}");
    // Same spline: one overlap.
    let h = both(&s, &s.clone());
    assert_eq!(kinds(&h), ["OVERLAP"]);
}

#[test]
fn bulged_polyline_against_circle_and_near_point() {
    // Slot: (0,0)→(4,0), semicircle to (4,2), (4,2)→(0,2), semicircle back to (0,0).
    let slot = Curve::pline(
        vec![v(0.0, 0.0), v(4.0, 0.0), v(4.0, 2.0), v(0.0, 2.0)],
        true,
        Some(vec![0.0, 1.0, 0.0, 1.0]),
    )
    .unwrap();
    // The slot's right end cap is the circle (4,1) R1: overlap of half of it.
    let cap = circle(v(4.0, 1.0), 1.0);
    let h = both(&slot, &cap);
    assert_eq!(kinds(&h), ["OVERLAP"], "{h:?}");
    // A vertical line through x = 2 crosses twice; the near point picks the upper one.
    let l = line(v(2.0, -1.0), v(2.0, 3.0));
    let h = both(&slot, &l);
    assert_eq!(kinds(&h), ["CROSS", "CROSS"]);
    let near = lispcad::geom::intersect_near(&h, v(2.0, 2.5)).unwrap();
    assert!(close(near, v(2.0, 2.0), 1e-12));
    // A horizontal line y = 1 crosses both caps at their outermost points.
    let h = both(&slot, &line(v(-2.0, 1.0), v(6.0, 1.0)));
    assert_eq!(h.len(), 2);
    assert!(close(h[0].point, v(5.0, 1.0), 1e-12) || close(h[0].point, v(-1.0, 1.0), 1e-12));
    assert!(lispcad::geom::intersect_near(&[], v(0.0, 0.0)).is_none());
}

#[test]
fn closed_spline_hit_at_its_seam_is_reported_once_at_t_zero() {
    // A closed quadratic spline: four segments around the unit square's midpoints.
    let pts = [v(1.0, 0.0), v(0.0, 1.0), v(-1.0, 0.0), v(0.0, -1.0)];
    let ctrl = [v(1.0, 1.0), v(-1.0, 1.0), v(-1.0, -1.0), v(1.0, -1.0)];
    let segs: Vec<[DVec3; 3]> = (0..4)
        .map(|i| [pts[i], ctrl[i], pts[(i + 1) % 4]])
        .collect();
    let s = Curve::Spline(QuadSpline {
        points: pts.to_vec(),
        closed: true,
        segments: segs,
    });
    let h = both(&s, &line(v(0.0, 0.0), v(3.0, 0.0)));
    assert_eq!(h.len(), 1, "{h:?}");
    assert!(h[0].t1 == 0.0 && close(h[0].point, v(1.0, 0.0), 1e-12));
}

#[test]
fn nurbs_circle_overlaps_the_circle_and_a_spline_pierces_a_circle_plane() {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let ctrl = vec![
        v(1.0, 0.0),
        v(1.0, 1.0),
        v(0.0, 1.0),
        v(-1.0, 1.0),
        v(-1.0, 0.0),
    ];
    let knots = vec![0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0];
    let half = Curve::bspline(ctrl, 2, Some(knots), Some(vec![1.0, w, 1.0, w, 1.0])).unwrap();
    let h = both(&half, &circle(v(0.0, 0.0), 1.0));
    assert!(
        !h.is_empty() && h.iter().all(|x| x.kind_name() == "OVERLAP"),
        "{h:?}"
    );
    // A space spline crossing the XY plane exactly on the unit circle at (0, 1, 0).
    let s = Curve::bspline(
        vec![
            v3(0.0, 1.0, -1.0),
            v3(0.5, 1.0, -0.5),
            v3(-0.5, 1.0, 0.5),
            v3(0.0, 1.0, 1.0),
        ],
        3,
        None,
        None,
    )
    .unwrap();
    let h = both(&s, &circle(v(0.0, 0.0), 1.0));
    assert_eq!(h.len(), 1, "{h:?}");
    assert!(close(h[0].point, v(0.0, 1.0), 1e-12));
}

#[test]
fn spline_pair_grazing_with_close_roots_and_touching() {
    // y = (x − ½)² against y = c − (x − ½)²: roots at ½ ± √(c/2).
    let c = 2.0 * 3.5e-6f64 * 3.5e-6;
    let a = quad(vec![[v(0.0, 0.25), v(0.5, -0.25), v(1.0, 0.25)]]);
    let b = Curve::bspline(
        vec![v(0.0, c - 0.25), v(0.5, c + 0.25), v(1.0, c - 0.25)],
        2,
        None,
        None,
    )
    .unwrap();
    let h = both(&a, &b);
    assert_eq!(h.len(), 2, "{h:?}");
    assert!(
        (h[0].point.x - (0.5 - 3.5e-6)).abs() < 1e-9
            && (h[1].point.x - (0.5 + 3.5e-6)).abs() < 1e-9,
        "{h:?}"
    );
    let b = Curve::bspline(
        vec![v(0.0, -0.25), v(0.5, 0.25), v(1.0, -0.25)],
        2,
        None,
        None,
    )
    .unwrap();
    let h = both(&a, &b);
    assert_eq!(kinds(&h), ["TANGENT"], "{h:?}");
    assert!(close(h[0].point, v(0.5, 0.0), 1e-9));
}

#[test]
fn spline_and_a_piece_of_itself_overlap() {
    let ctrl = vec![v(0.0, 0.0), v(1.0, 2.0), v(2.0, -1.0), v(3.0, 1.0)];
    let a = Curve::bspline(ctrl.clone(), 3, None, None).unwrap();
    // The same cubic restricted to [0.25, 0.75] (de Casteljau by hand via the curve).
    let Curve::BSpline(bs) = &a else {
        unreachable!()
    };
    let piece = {
        let spans = a.spans();
        let lispcad::geom::piece::Piece::Bez(b) = &spans[0].piece else {
            unreachable!()
        };
        b.subsegment(0.25, 0.75)
    };
    let _ = bs;
    let b = Curve::bspline(piece.points().collect(), 3, None, None).unwrap();
    let h = both(&a, &b);
    assert_eq!(kinds(&h), ["OVERLAP"], "{h:?}");
    let o = h[0].overlap().unwrap();
    assert!(
        close(o.eval(0.0), a.eval(0.25), 1e-9) && close(o.eval(1.0), a.eval(0.75), 1e-9),
        "{h:?}"
    );
    assert!((h[0].t1 - 0.25).abs() < 1e-9 && h[0].t2.abs() < 1e-9);
}

/// Geometry far beyond drawing sizes: the closed forms square lengths (and multiply two
/// squares), so pairs this large are scaled down before solving. The answers are those of
/// the same pair at unit size, scaled; pieces too far apart for their distance to be a
/// double meet nowhere, without a NaN on the way.
#[test]
fn huge_circles_and_lines_meet_as_at_unit_size() {
    for s in [1e80, 1e160, 1e300] {
        let rel = |p: DVec3, q: DVec3| (p - q).length() <= 1e-12 * s;
        // Two circles through (s/2, ±s·√3/2).
        let h = intersect(&circle(v(0.0, 0.0), s), &circle(v(s, 0.0), s), TOL);
        assert_eq!(kinds(&h), ["CROSS", "CROSS"], "scale {s:e}: {h:?}");
        let y = s * 3f64.sqrt() / 2.0;
        assert!(rel(h[0].point, v(s / 2.0, y)) && rel(h[1].point, v(s / 2.0, -y)));
        assert!((h[0].t1 - 1.0 / 6.0).abs() < 1e-12 && (h[1].t1 - 5.0 / 6.0).abs() < 1e-12);
        // A line across a circle.
        let h = intersect(
            &line(v(-s, 0.0), v(s, 0.0)),
            &circle(v(0.0, 0.0), s / 2.0),
            TOL,
        );
        assert_eq!(kinds(&h), ["CROSS", "CROSS"], "scale {s:e}: {h:?}");
        assert!(rel(h[0].point, v(-s / 2.0, 0.0)) && rel(h[1].point, v(s / 2.0, 0.0)));
        assert!((h[0].t1 - 0.25).abs() < 1e-12 && (h[0].t2 - 0.5).abs() < 1e-12);
        // Circles in the XY and XZ planes through (±s, 0, 0).
        let xz = Curve::circle(v(0.0, 0.0), s, Some(DVec3::Y)).unwrap();
        let h = intersect(&circle(v(0.0, 0.0), s), &xz, TOL);
        assert_eq!(kinds(&h), ["CROSS", "CROSS"], "scale {s:e}: {h:?}");
        assert!(rel(h[0].point, v(s, 0.0)) && rel(h[1].point, v(-s, 0.0)));
        for h in &h {
            assert!(h.t1.is_finite() && h.t2.is_finite());
        }
        // Huge segments crossing each other.
        let h = intersect(&line(v(-s, -s), v(s, s)), &line(v(-s, s), v(s, -s)), TOL);
        assert_eq!(kinds(&h), ["CROSS"], "scale {s:e}: {h:?}");
        assert!(h[0].point.length() <= 1e-12 * s && (h[0].t1 - 0.5).abs() < 1e-12);
    }
    // Mixed scales past double precision (a unit circle against a 1e300 segment or circle:
    // the unit is below the large piece's ulp): finite answers, no NaN.
    let mixed = [
        (
            line(v(-1e300, 3.0), v(1e300, -1.0)),
            circle(v(0.0, 0.0), 1.0),
        ),
        (circle(v(0.0, 0.0), 1e300), circle(v(1e300, 0.0), 1.0)),
    ];
    for (a, b) in &mixed {
        for h in intersect(a, b, TOL) {
            assert!(
                h.point.is_finite() && h.t1.is_finite() && h.t2.is_finite(),
                "{h:?}"
            );
        }
    }
    // Pieces whose separation overflows: no hit, and nothing NaN on the way.
    let far = [
        (
            line(v(-1.7e308, 0.0), v(-1.6e308, 1.0)),
            circle(v(1.7e308, 0.0), 1.0),
        ),
        (circle(v(-1.7e308, 0.0), 1.0), circle(v(1.7e308, 0.0), 1.0)),
        (
            circle(v3(-1.7e308, 0.0, 1.0), 1.0),
            Curve::circle(v(1.7e308, 1.0), 1.0, Some(DVec3::X)).unwrap(),
        ),
        (
            line(v(-1.7e308, 0.0), v(-1.6e308, 1.0)),
            line(v(1.7e308, 0.0), v(1.6e308, 1.0)),
        ),
    ];
    for (a, b) in &far {
        assert!(intersect(a, b, TOL).is_empty() && intersect(b, a, TOL).is_empty());
    }
}

/// Two circles in planes 30° apart, both tangent to the planes' common line at one point:
/// one TANGENT hit, also when the second is a short arc around that point (its quick
/// rejection must see the point at the scale it was computed at).
#[test]
fn tilted_circles_touching_on_their_common_line() {
    let a = circle(v(0.0, 0.0), 1.0);
    let touch = v(0.0, 1.0);
    let alpha = 30f64.to_radians();
    let n = v3(0.0, -alpha.sin(), alpha.cos());
    let c = touch + v3(0.0, alpha.cos(), alpha.sin());
    let (x, y) = lispcad::geom::frame::arbitrary_axis(n);
    let at = (touch - c).dot(y).atan2((touch - c).dot(x));
    for b in [
        Curve::circle(c, 1.0, Some(n)).unwrap(),
        Curve::arc(c, 1.0, at - 0.1, at + 0.1, Some(n)).unwrap(),
    ] {
        let h = both(&a, &b);
        assert_eq!(kinds(&h), ["TANGENT"], "{b:?}: {h:?}");
        assert!(close(h[0].point, touch, 1e-9), "{h:?}");
    }
}
