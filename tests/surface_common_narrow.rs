//! Common regions narrower than the region tracer's grid (issue 13): a profile of many arc
//! segments with one short flat among them, so the flat spans well under 1/128 of the
//! profile's parameter range, no sample of the quick look lies on it and no grid node has a
//! neighbour a quarter cell away on it. The flat lies on a plane (ruled strip) or a cylinder
//! (revolved profile); the region and its boundary are written here in closed form. The arcs
//! leave the flat tangentially, so the edges are also the tangential-parting case.

use lispcad::geom::curve::Curve;
use lispcad::geom::surface::{surface_intersect_tol, surface_section_tol, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

mod surface_support;
use surface_support::{
    check_loops, check_loops_reaching as check, check_order, off_strip as off_profile, summary,
    u_profile, M1, M2, R,
};

const GT: f64 = 1e-9;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

#[test]
fn the_profile_is_the_closed_form_one() {
    let w = 0.05;
    let c = u_profile(w, |s, t| v(s, t, 0.0), true);
    let n = (M1 + M2 + 1) as f64;
    for i in 0..=200 {
        let p = c.eval(i as f64 / 200.0);
        let centre = if p.x < 0.0 {
            v(0.0, R, 0.0)
        } else {
            v(w, R, 0.0)
        };
        if p.x < 0.0 || p.x > w {
            assert!((p.distance(centre) - R).abs() <= 1e-12, "{p}");
        } else {
            assert!(p.y.abs() <= 1e-12, "{p}");
        }
    }
    // The flat is the one segment between the arcs: 1/161 of the parameter range.
    let (a, b) = (c.eval(M1 as f64 / n), c.eval((M1 + 1) as f64 / n));
    assert!(a.distance(v(0.0, 0.0, 0.0)) <= 1e-12 && b.distance(v(w, 0.0, 0.0)) <= 1e-12);
}

#[test]
fn a_ruled_strip_with_a_narrow_flat_on_a_plane() {
    // Ruled between the profile at z = 0 and at z = 3: it lies on the plane y = 0 over
    // x ∈ [0, w], z ∈ [0, 3] and nowhere else (y > 0 off the flat).
    let w = 0.05;
    let prof = |z: f64| u_profile(w, move |s, t| v(s, t, z), true);
    let strip = Surface::ruled(prof(0.0), prof(3.0));
    let wall = Surface::plane(vec![
        v(-1.0, 0.0, -1.0),
        v(1.0, 0.0, -1.0),
        v(1.0, 0.0, 4.0),
        v(-1.0, 0.0, 4.0),
    ])
    .unwrap();
    let on_rect = |p: DVec3| {
        let side = p.x.abs() <= GT || (p.x - w).abs() <= GT;
        let end = p.z.abs() <= GT || (p.z - 3.0).abs() <= GT;
        p.y.abs() <= GT
            && (side || end)
            && (-GT..=w + GT).contains(&p.x)
            && (-GT..=3.0 + GT).contains(&p.z)
    };
    let left = |p: DVec3| p.x.abs() <= GT && (p.z - 1.5).abs() <= 1.0;
    let right = |p: DVec3| (p.x - w).abs() <= GT && (p.z - 1.5).abs() <= 1.0;
    check(&strip, &wall, 1, 2.0 * (w + 3.0), on_rect, &[&left, &right]);
    // The section by the plane y = 0: the same region.
    let section =
        |x: &Surface, _: &Surface| surface_section_tol(x, DVec3::ZERO, DVec3::Y, 1e-6, GT).unwrap();
    let r = check_order(section, &strip, &wall, 1, 2.0 * (w + 3.0), on_rect);
    assert!(r[0].points.iter().any(|p| left(*p)) && r[0].points.iter().any(|p| right(*p)));
}

/// The band y ∈ [2, 2 + w] on the cylinder ρ = 1 about the y axis, revolved from a profile
/// whose flat is x = 1 there (x > 1 elsewhere).
fn narrow_band(w: f64) -> Surface {
    let prof = u_profile(w, |s, t| v(1.0 + t, 2.0 + s, 0.0), false);
    Surface::revolve(prof, DVec3::ZERO, DVec3::Y, TAU).unwrap()
}

fn on_band_circles(w: f64) -> impl Fn(DVec3) -> bool {
    move |p: DVec3| {
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        (rho - 1.0).abs() <= GT && ((p.y - 2.0).abs() <= GT || (p.y - 2.0 - w).abs() <= GT)
    }
}

/// The band's two edge circles, both orders, against a cylinder ρ = 1 about the y axis.
fn check_band_on(w: f64, cyl: &Surface) {
    let low = |p: DVec3| (p.y - 2.0).abs() <= GT;
    let high = |p: DVec3| (p.y - 2.0 - w).abs() <= GT;
    let reach: [&dyn Fn(DVec3) -> bool; 2] = [&low, &high];
    check(
        &narrow_band(w),
        cyl,
        2,
        4.0 * PI,
        on_band_circles(w),
        &reach,
    );
}

#[test]
fn a_revolved_profile_with_a_narrow_flat_on_a_cylinder() {
    let w = 0.04;
    let cyl = Surface::cylinder(v(0.0, -1.0, 0.0), DVec3::Y, 1.0, 12.0).unwrap();
    check_band_on(w, &cyl);
}

#[test]
fn a_revolved_profile_with_a_narrow_flat_on_a_revolved_line() {
    // The cylinder as a surface of revolution: both surfaces are free-form.
    let w = 0.04;
    let line = Arc::new(Curve::line(v(1.0, -1.0, 0.0), v(1.0, 6.0, 0.0)).unwrap());
    let cyl = Surface::revolve(line, DVec3::ZERO, DVec3::Y, TAU).unwrap();
    check_band_on(w, &cyl);
}

/// A profile in the plane z with a wide flat on y = 0 (x from 0 to 1, `m` segments) and,
/// beyond a ridge, a narrow one `lift` above it (x from 3 to 3 + `wn`, one segment), between
/// 45° slopes of `m` segments rising to y = 1: 5m + 1 segments, the narrow flat 1/(5m + 1) of
/// the parameter range (between the tracer's grid lines 25/32 and 26/32 for m = 80).
fn wide_and_narrow(wn: f64, lift: f64, m: usize, z: f64) -> Vec<DVec3> {
    let corners = [
        v(-1.0, 1.0, z),
        v(0.0, 0.0, z),
        v(1.0, 0.0, z),
        v(2.0, 1.0, z),
        v(3.0, lift, z),
        v(3.0 + wn, lift, z),
        v(4.0 + wn, 1.0, z),
    ];
    let mut pts = Vec::new();
    for (i, pair) in corners.windows(2).enumerate() {
        let n = if i == 4 { 1 } else { m };
        pts.extend((0..n).map(|k| pair[0].lerp(pair[1], k as f64 / n as f64)));
    }
    pts.push(corners[6]);
    pts
}

#[test]
fn a_narrow_flat_beside_a_wide_one_on_a_plane_is_found_too() {
    // The narrow flat on the plane, and 0.9 × GEOMTOL off it (as the levels' tests).
    assert_wide_and_narrow(0.0);
    assert_wide_and_narrow(0.9 * GT);
}

/// The quick look's samples and the tracer's grid nodes lie on the wide flat, none on the
/// narrow one `lift` off the plane y = 0: both regions come back, each as the rectangle
/// x ∈ [x0, x0 + w], z ∈ [0, 3] (the slopes leave the flats at 45°, so the edges lie within
/// (lift + GEOMTOL)·√2 of x = x0 and x0 + w), in both orders and as the section by y = 0.
fn assert_wide_and_narrow(lift: f64) {
    let (wn, m) = (0.02, 80);
    let profile = wide_and_narrow(wn, lift, m, 0.0);
    let curve = |z: f64| {
        let pts = wide_and_narrow(wn, lift, m, z);
        Arc::new(Curve::pline(pts, false, None).unwrap())
    };
    let strip = Surface::ruled(curve(0.0), curve(3.0));
    let wall = Surface::plane(vec![
        v(-2.0, 0.0, -1.0),
        v(6.0, 0.0, -1.0),
        v(6.0, 0.0, 4.0),
        v(-2.0, 0.0, 4.0),
    ])
    .unwrap();
    let slack = (lift + GT) * 2f64.sqrt();
    let flats = [(0.0, 1.0), (3.0, wn)];
    let on = |p: DVec3| {
        let in_flat = |&(x0, w): &(f64, f64)| {
            let x = p.x - x0;
            let side = x.abs() <= slack || (x - w).abs() <= slack;
            let end = p.z.abs() <= GT || (p.z - 3.0).abs() <= GT;
            (side || end) && (-slack..=w + slack).contains(&x)
        };
        p.y.abs() <= GT && off_profile(p, &profile) <= GT && flats.iter().any(in_flat)
    };
    let length = 2.0 * (1.0 + 3.0) + 2.0 * (wn + 3.0);
    let section =
        |x: &Surface, _: &Surface| surface_section_tol(x, DVec3::ZERO, DVec3::Y, 1e-6, GT).unwrap();
    let meet = |x: &Surface, y: &Surface| surface_intersect_tol(x, y, 1e-6, GT).unwrap();
    let mut all = check_loops(meet, &strip, &wall, 2, length, on);
    all.push(check_order(section, &strip, &wall, 2, length, on));
    for r in &all {
        // One loop round each flat, reaching both its sides.
        for &(x0, w) in &flats {
            let mine: Vec<_> = r
                .iter()
                .filter(|c| c.points.iter().all(|p| (p.x - x0 - 0.5 * w).abs() <= 0.6))
                .collect();
            assert_eq!(mine.len(), 1, "flat at {x0}: {}", summary(r));
            for x in [x0, x0 + w] {
                let reached = mine[0].points.iter().any(|p| (p.x - x).abs() <= slack);
                assert!(reached, "flat at {x0}: side x = {x} not reached");
            }
        }
    }
}

/// A profile in the plane z with two flats on y = 0, x − z·`shear` from 0.1 to 0.35 (wide)
/// and from 0.535 to 0.555 (narrow), between 45° slopes: a ridge between them, slopes rising
/// to y = 1 beyond.
fn two_bands(z: f64, shear: f64) -> Arc<Curve> {
    let at = |x: f64, y: f64| v(x + z * shear, y, z);
    let ridge = 0.5 * (0.35 + 0.535);
    let pts = vec![
        at(-0.9, 1.0),
        at(0.1, 0.0),
        at(0.35, 0.0),
        at(ridge, ridge - 0.35),
        at(0.535, 0.0),
        at(0.555, 0.0),
        at(1.555, 1.0),
    ];
    Arc::new(Curve::pline(pts, false, None).unwrap())
}

#[test]
fn a_band_under_a_cell_wide_between_the_nodes_beside_a_wide_one_is_found_too() {
    // Traced in the unit square's domain the narrow band is 0.64 of a cell wide (0.02), between
    // the grid's node lines x − z·shear = 17/32 and 18/32 and the samples' (a twelfth apart):
    // beside the wide band, which the nodes see, it was passed over as a region a quarter cell
    // wide that the nodes see (one loop). Along z (shear 0) and diagonal (shear 1), each band
    // comes back as its outline on the square: the band's edges (the slopes leave the plane at
    // 45°, so within GEOMTOL·√2) and the square's.
    let sq = surface_support::unit_square();
    for shear in [0.0, 1.0] {
        let other = Surface::ruled(two_bands(-1.5, shear), two_bands(2.5, shear));
        // The bands' outlines on the square: x − z·shear from c0 to c1 cut by 0 ≤ x, z ≤ 1.
        let outline = |c0: f64, c1: f64| {
            let top = |c: f64| {
                if shear > 0.0 {
                    ((1.0 - c) / shear).min(1.0)
                } else {
                    1.0
                }
            };
            let (z0, z1) = (top(c0), top(c1));
            vec![
                v(c0, 0.0, 0.0),
                v(c1, 0.0, 0.0),
                v(c1 + z1 * shear, 0.0, z1),
                v((c0 + z0 * shear).min(1.0), 0.0, z0),
            ]
        };
        let bands = [outline(0.1, 0.35), outline(0.535, 0.555)];
        let perimeter = |q: &[DVec3]| (0..4).map(|i| q[i].distance(q[(i + 1) % 4])).sum::<f64>();
        let slack = 2.0 * GT * 2f64.sqrt();
        let meet = |x: &Surface, y: &Surface| surface_intersect_tol(x, y, 1e-6, GT).unwrap();
        for (order, (x, y)) in [
            ("square, other", (&sq, &other)),
            ("other, square", (&other, &sq)),
        ] {
            let name = format!("shear {shear}, {order}");
            let r = meet(x, y);
            assert_eq!(r.len(), 2, "{name}: {}", summary(&r));
            surface_support::assert_same_bits(&name, &meet(x, y), &r);
            for q in &bands {
                let mine: Vec<_> = r
                    .iter()
                    .filter(|c| c.points.iter().all(|p| to_outline(*p, q) <= slack))
                    .collect();
                assert_eq!(
                    mine.len(),
                    1,
                    "{name}: band from x = {}: {}",
                    q[0].x,
                    summary(&r)
                );
                let c = mine[0];
                assert!(c.closed, "{name}: {}", summary(&r));
                assert!(
                    c.points.iter().all(|p| p.y.abs() <= GT),
                    "{name}: off the square"
                );
                let (length, want) = (c.length(), perimeter(q));
                assert!(
                    (length - want).abs() <= 1e-6,
                    "{name}: length {length} for {want}"
                );
            }
        }
    }
}

/// The distance from `p` to the closed polygon `q`.
fn to_outline(p: DVec3, q: &[DVec3]) -> f64 {
    (0..q.len())
        .map(|i| {
            let (a, b) = (q[i], q[(i + 1) % q.len()]);
            let d = b - a;
            let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
            p.distance(a + d * t)
        })
        .fold(f64::INFINITY, f64::min)
}
