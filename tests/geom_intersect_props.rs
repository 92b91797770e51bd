//! Property tests for `intersect`: reported points lie on both curves, curves built through
//! chosen points find exactly those points, and argument order does not matter.

use lispcad::geom::bspline::BSpline;
use lispcad::geom::ellipse::Ellipse;
use lispcad::geom::quadspline::QuadSpline;
use lispcad::geom::{intersect, Curve, DVec3, Hit, HitKind};
use proptest::prelude::*;

const TOL: f64 = 1e-9;

fn pt() -> impl Strategy<Value = DVec3> {
    (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}
fn pt2() -> impl Strategy<Value = DVec3> {
    (-10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y)| DVec3::new(x, y, 0.0))
}
fn unit() -> impl Strategy<Value = DVec3> {
    pt().prop_filter_map("non-zero", |p| p.try_normalize())
}

fn any_curve() -> impl Strategy<Value = Curve> {
    prop_oneof![
        (pt2(), pt2()).prop_filter_map("line", |(a, b)| Curve::line(a, b).ok()),
        (pt(), pt()).prop_filter_map("3d line", |(a, b)| Curve::line(a, b).ok()),
        (pt(), 0.5..8.0f64, unit(), 0.0..6.0f64, 0.1..6.2f64).prop_filter_map(
            "3d arc",
            |(c, r, n, a, s)| Curve::arc(c, r, a, a + s, Some(n)).ok()
        ),
        (prop::collection::vec(pt(), 4..7), 2usize..4).prop_filter_map("3d bspline", |(p, d)| {
            BSpline::new(d, p, None, None).ok().map(Curve::BSpline)
        }),
        (
            prop::collection::vec(pt2(), 3..6),
            prop::collection::vec(0.2..3.0f64, 6)
        )
            .prop_filter_map("nurbs", |(p, w)| {
                let n = p.len();
                BSpline::new(2, p, None, Some(w[..n].to_vec()))
                    .ok()
                    .map(Curve::BSpline)
            }),
        (pt2(), 0.5..8.0f64).prop_filter_map("circle", |(c, r)| Curve::circle(c, r, None).ok()),
        (pt(), 0.5..8.0f64, unit()).prop_filter_map("3d circle", |(c, r, n)| Curve::circle(
            c,
            r,
            Some(n)
        )
        .ok()),
        (pt2(), 0.5..8.0f64, 0.0..6.0f64, 0.1..6.2f64)
            .prop_filter_map("arc", |(c, r, a, s)| Curve::arc(c, r, a, a + s, None).ok()),
        (
            prop::collection::vec(pt2(), 3..6),
            prop::collection::vec(-1.0..1.0f64, 6),
            any::<bool>()
        )
            .prop_filter_map("pline", |(p, b, closed)| {
                let n = p.len();
                Curve::pline(p, closed, Some(b[..n].to_vec())).ok()
            }),
        prop::collection::vec(pt2(), 4..7).prop_map(|p| {
            // A C1 quadratic spline built from its control polygon (midpoints as joints).
            let mut segs = Vec::new();
            let n = p.len();
            let mut start = p[0];
            for i in 1..n - 1 {
                let end = if i == n - 2 {
                    p[n - 1]
                } else {
                    (p[i] + p[i + 1]) * 0.5
                };
                segs.push([start, p[i], end]);
                start = end;
            }
            let mut points = vec![segs[0][0]];
            points.extend(segs.iter().map(|s| s[2]));
            Curve::Spline(QuadSpline {
                points,
                closed: false,
                segments: segs,
            })
        }),
        (prop::collection::vec(pt2(), 4..7), 2usize..4).prop_filter_map("bspline", |(p, d)| {
            BSpline::new(d, p, None, None).ok().map(Curve::BSpline)
        }),
        (
            pt(),
            unit(),
            0.5..8.0f64,
            0.1..1.0f64,
            0.0..6.3f64,
            0.1..6.3f64,
            unit()
        )
            .prop_filter_map("elliptical arc", |(c, dir, len, r, a, s, n)| {
                let major = (dir - n * dir.dot(n)).try_normalize()? * len;
                Ellipse::new(c, major, r, a, a + s, n)
                    .ok()
                    .map(Curve::Ellipse)
            }),
        (pt2(), 0.5..8.0f64, 0.0..3.2f64, 0.1..1.0f64).prop_filter_map(
            "ellipse",
            |(c, len, rot, r)| {
                let major = DVec3::new(rot.cos(), rot.sin(), 0.0) * len;
                Ellipse::new(c, major, r, 0.0, std::f64::consts::TAU, DVec3::Z)
                    .ok()
                    .map(Curve::Ellipse)
            }
        ),
    ]
}

fn on_curve(c: &Curve, p: DVec3, t: f64, scale: f64) -> bool {
    (c.eval(t) - p).length() <= 1e-9 * scale
}

/// Some hit of `h` is at `p` (within 1e-8), or some overlap of `h` passes through it.
fn has_hit_at(h: &[Hit], p: DVec3) -> bool {
    h.iter().any(|q| match &q.kind {
        HitKind::Overlap(o) => (o.closest_point(p).1 - p).length() < 1e-8,
        _ => (q.point - p).length() < 1e-8,
    })
}

fn check_pair(a: &Curve, b: &Curve) -> Result<Vec<Hit>, TestCaseError> {
    let h1 = intersect(a, b, TOL);
    let mut h2 = intersect(b, a, TOL);
    prop_assert_eq!(h1.len(), h2.len(), "{:?}\n{:?}", h1, h2);
    h2.sort_by(|x, y| x.t2.total_cmp(&y.t2));
    let scale = 20.0;
    for (x, y) in h1.iter().zip(&h2) {
        prop_assert_eq!(x.kind_name(), y.kind_name());
        if matches!(x.kind, HitKind::Overlap(_)) {
            continue;
        }
        prop_assert!(
            (x.point - y.point).length() <= 1e-12 * scale,
            "{:?} {:?}",
            x,
            y
        );
        prop_assert!((x.t1 - y.t2).abs() <= 1e-12 && (x.t2 - y.t1).abs() <= 1e-12);
        prop_assert!(on_curve(a, x.point, x.t1, scale), "{:?} off a {}", x, a);
        prop_assert!(on_curve(b, x.point, x.t2, scale), "{:?} off b {}", x, b);
    }
    for w in h1.windows(2) {
        prop_assert!(w[0].t1 <= w[1].t1);
    }
    Ok(h1)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn every_hit_is_on_both_curves_in_either_order(a in any_curve(), b in any_curve()) {
        check_pair(&a, &b)?;
    }

    #[test]
    fn lines_through_a_chosen_point(p in pt(), d1 in unit(), d2 in unit(), s in 0.05..0.95f64, u in 0.05..0.95f64, l1 in 0.5..10.0f64, l2 in 0.5..10.0f64) {
        prop_assume!(d1.cross(d2).length() > 1e-3);
        let a = Curve::line(p - d1 * (s * l1), p + d1 * ((1.0 - s) * l1)).unwrap();
        let b = Curve::line(p - d2 * (u * l2), p + d2 * ((1.0 - u) * l2)).unwrap();
        let h = check_pair(&a, &b)?;
        prop_assert_eq!(h.len(), 1);
        prop_assert!((h[0].point - p).length() < 1e-9 * 20.0);
        prop_assert!((h[0].t1 - s).abs() < 1e-9 && (h[0].t2 - u).abs() < 1e-9);
    }

    #[test]
    fn circles_through_two_chosen_points(a in pt(), b in pt(), n in unit(), k1 in -5.0..5.0f64, k2 in -5.0..5.0f64) {
        let ab = b - a;
        prop_assume!(ab.length() > 0.1);
        let n = (n - ab * (n.dot(ab) / ab.length_squared())).try_normalize();
        prop_assume!(n.is_some());
        let n = n.unwrap();
        // Centres on the bisector line in the plane (n) through a and b.
        let m = (a + b) * 0.5;
        let w = n.cross(ab).normalize();
        prop_assume!((k1 - k2).abs() > 0.05);
        let (c1, c2) = (m + w * k1, m + w * k2);
        let x = Curve::circle(c1, (a - c1).length(), Some(n)).unwrap();
        let y = Curve::circle(c2, (a - c2).length(), Some(n)).unwrap();
        let h = check_pair(&x, &y)?;
        prop_assert_eq!(h.len(), 2, "{:?}", h);
        for p in [a, b] {
            prop_assert!(h.iter().any(|q| (q.point - p).length() < 1e-8), "{:?} missing {}", h, p);
        }
    }

    #[test]
    fn non_coplanar_circles_through_chosen_points(a in pt(), b in pt(), n1 in unit(), n2 in unit(), k1 in -5.0..5.0f64, k2 in -5.0..5.0f64) {
        // Two circles in different planes that both contain the chord a–b.
        let ab = b - a;
        prop_assume!(ab.length() > 0.1);
        let perp = |n: DVec3| (n - ab * (n.dot(ab) / ab.length_squared())).try_normalize();
        let (Some(n1), Some(n2)) = (perp(n1), perp(n2)) else { return Ok(()); };
        prop_assume!(n1.cross(n2).length() > 1e-2);
        let m = (a + b) * 0.5;
        let c1 = m + n1.cross(ab).normalize() * k1;
        let c2 = m + n2.cross(ab).normalize() * k2;
        let x = Curve::circle(c1, (a - c1).length(), Some(n1)).unwrap();
        let y = Curve::circle(c2, (a - c2).length(), Some(n2)).unwrap();
        let h = check_pair(&x, &y)?;
        prop_assert_eq!(h.len(), 2, "{:?}", h);
        for p in [a, b] {
            prop_assert!(h.iter().any(|q| (q.point - p).length() < 1e-8), "{:?} missing {}", h, p);
        }
    }

    #[test]
    fn line_through_a_point_of_any_curve(c in any_curve(), t in 0.02..0.98f64, d in unit(), l in 1.0..5.0f64) {
        let p = c.eval(t);
        let line = Curve::line(p - d * l, p + d * (l * 0.7)).unwrap();
        let h = check_pair(&c, &line)?;
        prop_assert!(
            has_hit_at(&h, p),
            "{} at t={}: {:?}", c, t, h
        );
    }

    #[test]
    fn arc_through_a_point_of_any_curve(c in any_curve(), t in 0.02..0.98f64, q1 in pt2(), q3 in pt2()) {
        let p = c.eval(t);
        let Ok(arc) = Curve::arc3(q1, p, q3) else { return Ok(()); };
        prop_assume!(arc.length() < 200.0);
        let h = check_pair(&c, &arc)?;
        prop_assert!(
            has_hit_at(&h, p),
            "{} at t={}: {:?}", c, t, h
        );
    }

    #[test]
    fn spline_through_a_point_of_any_curve(c in any_curve(), t in 0.02..0.98f64, q1 in pt2(), k in pt2(), q3 in pt2(), cubic in any::<bool>()) {
        let p = c.eval(t);
        let k2 = p + (p - k);
        let spline = if cubic {
            Curve::BSpline(BSpline::new(3, vec![q1, k, p, k2, q3], Some(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]), None).unwrap())
        } else {
            Curve::Spline(QuadSpline { points: vec![q1, p, q3], closed: false, segments: vec![[q1, k, p], [p, k2, q3]] })
        };
        if cubic {
            // The cubic passes through p only at its knot if the polygon is symmetric there;
            // use its actual point at the knot instead.
            let p = spline.eval(0.5);
            let d = DVec3::new(0.6, 0.8, 0.0);
            let line = Curve::line(p - d, p + d * 0.5).unwrap();
            let h = check_pair(&spline, &line)?;
            prop_assert!(h.iter().any(|q| (q.point - p).length() < 1e-8), "{:?}", h);
            return Ok(());
        }
        let h = check_pair(&c, &spline)?;
        prop_assert!(
            has_hit_at(&h, p),
            "{} at t={}: {:?}", c, t, h
        );
    }
}
