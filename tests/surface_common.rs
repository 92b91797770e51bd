//! Free-form surfaces that coincide over a region (issue 13, items 1 and 3): the intersection is
//! the common region's boundary loops, closed, found on the true surfaces — a twisted ruled
//! surface and an overlapping piece of itself, a Coons patch and a sub-patch, two sweeps of
//! overlapping profiles along one path, a revolved profile lying partly on a cylinder. Surfaces
//! coinciding everywhere with no boundary (equal spheres, one torus with two seams) are told
//! apart from surfaces that do not meet. References are closed forms written out here: the
//! carriers' equations (hyperbolic paraboloid, cylinder, bilinear patch) and the loops' lengths.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{
    surface_intersect_tol, surface_meet, surface_section_tol, Meet, Surface,
};
use lispcad::geom::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

mod surface_support;
use surface_support::{check_loops, eval};

const CT: f64 = 1e-6;
const GT: f64 = 1e-9;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn line(a: DVec3, b: DVec3) -> Arc<Curve> {
    Arc::new(Curve::line(a, b).unwrap())
}

fn meet(a: &Surface, b: &Surface) -> Vec<Polyline3> {
    meet_ct(a, b, CT)
}

fn meet_ct(a: &Surface, b: &Surface, ct: f64) -> Vec<Polyline3> {
    surface_intersect_tol(a, b, ct, GT).unwrap()
}

/// Both orders give loops of the expected total length, every point accepted by `on`; three
/// runs give the same bits.
fn check(a: &Surface, b: &Surface, loops: usize, length: f64, on: impl Fn(DVec3) -> bool) {
    check_ct(a, b, CT, loops, length, on)
}

/// [`check`] with a chord tolerance: a polygon of sagitta s inscribed in radius R is s/3R
/// short, so s ≤ 3e-6·R keeps the length within 1e-6.
fn check_ct(
    a: &Surface,
    b: &Surface,
    ct: f64,
    loops: usize,
    length: f64,
    on: impl Fn(DVec3) -> bool,
) {
    check_loops(|x, y| meet_ct(x, y, ct), a, b, loops, length, on);
}

#[test]
fn a_twisted_ruled_surface_and_an_overlapping_piece_of_itself_share_a_band() {
    // Both on z = y(3 − 0.6x)/10: the first for x in [0, 6], the second for x in [4, 10].
    let a = Surface::ruled(
        line(v(0.0, 0.0, 0.0), v(6.0, 0.0, 0.0)),
        line(v(0.0, 10.0, 3.0), v(6.0, 10.0, -0.6)),
    );
    let b = Surface::ruled(
        line(v(4.0, 0.0, 0.0), v(10.0, 0.0, 0.0)),
        line(v(4.0, 10.0, 0.6), v(10.0, 10.0, -3.0)),
    );
    // The band x in [4, 6]: along c1, the rulings at x = 4 and 6, along c2.
    let length = 2.0 + (4.0f64 + 1.44).sqrt() + 2.0 * (100.0f64 + 0.36).sqrt();
    check(&a, &b, 1, length, |p| {
        (p.z - p.y * (3.0 - 0.6 * p.x) / 10.0).abs() <= GT
            && (4.0 - GT..=6.0 + GT).contains(&p.x)
            && (-GT..=10.0 + GT).contains(&p.y)
    });
    // Side by side (sharing the ruling at x = 6 only) they share no region.
    let c = Surface::ruled(
        line(v(6.0, 0.0, 0.0), v(10.0, 0.0, 0.0)),
        line(v(6.0, 10.0, -0.6), v(10.0, 10.0, -3.0)),
    );
    assert!(meet_ct(&a, &c, 1e-3).iter().all(|l| !l.closed));
}

#[test]
fn a_coons_patch_and_a_sub_patch_give_the_sub_patch_boundary() {
    // The Coons patch of four segments is the bilinear patch of its corners; so is any
    // sub-rectangle of it, and the sub-patch's sides are straight iso-lines.
    let c = [
        v(0.0, 0.0, 0.0),
        v(10.0, 0.0, 0.0),
        v(10.0, 10.0, 3.0),
        v(0.0, 10.0, -2.0),
    ];
    let bil = |u: f64, w: f64| {
        (1.0 - u) * (1.0 - w) * c[0] + u * (1.0 - w) * c[1] + u * w * c[2] + (1.0 - u) * w * c[3]
    };
    let quad = |q: [DVec3; 4]| {
        Surface::boundary([
            line(q[0], q[1]),
            line(q[1], q[2]),
            line(q[2], q[3]),
            line(q[3], q[0]),
        ])
        .unwrap()
    };
    let big = quad(c);
    let sub = [bil(0.2, 0.1), bil(0.7, 0.1), bil(0.7, 0.6), bil(0.2, 0.6)];
    let small = quad(sub);
    let length: f64 = (0..4).map(|i| sub[i].distance(sub[(i + 1) % 4])).sum();
    // Every point on one of the sub-patch's four sides.
    let on_side = |p: DVec3| {
        (0..4).any(|i| {
            let (a, b) = (sub[i], sub[(i + 1) % 4]);
            let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            p.distance(a.lerp(b, t)) <= GT
        })
    };
    check(&big, &small, 1, length, on_side);
    // Its corners are in the loop exactly (the sub-patch's own corners).
    let r = meet(&big, &small);
    for q in sub {
        assert!(r[0].points.iter().any(|p| p.distance(q) <= 1e-12), "{q}");
    }
}

#[test]
fn a_curved_coons_patch_and_a_band_of_it_share_the_band() {
    // Bottom arc through (0,0,0), (5,2,0), (10,0,0) (centre (5, −5.25), radius 7.25) lifted
    // along z: a translational patch on the cylinder over that circle.
    let arc =
        |z: f64| Arc::new(Curve::arc3(v(0.0, 0.0, z), v(5.0, 2.0, z), v(10.0, 0.0, z)).unwrap());
    let patch = |z0: f64, z1: f64| {
        Surface::boundary([
            arc(z0),
            line(v(10.0, 0.0, z0), v(10.0, 0.0, z1)),
            arc(z1),
            line(v(0.0, 0.0, z1), v(0.0, 0.0, z0)),
        ])
        .unwrap()
    };
    let (a, b) = (patch(0.0, 5.0), patch(1.0, 3.0));
    let r: f64 = 7.25;
    let arc_len = 2.0 * r * (5.0 / r).asin();
    check_ct(&a, &b, 1e-5, 1, 2.0 * arc_len + 4.0, |p| {
        (v(p.x - 5.0, p.y + 5.25, 0.0).length() - r).abs() <= GT
            && (1.0 - GT..=3.0 + GT).contains(&p.z)
            && p.y >= -GT
    });
}

#[test]
fn two_sweeps_of_overlapping_profiles_along_one_path_share_a_band() {
    // A quarter circle of radius 10 in z = 0; vertical profiles z in [0, 2] and [1, 3] swept
    // along it lie on the cylinder ρ = 10 and share the band z in [1, 2].
    let h = 10.0 / 2f64.sqrt();
    let guide =
        || Arc::new(Curve::arc3(v(10.0, 0.0, 0.0), v(h, h, 0.0), v(0.0, 10.0, 0.0)).unwrap());
    let a = Surface::sweep(line(v(10.0, 0.0, 0.0), v(10.0, 0.0, 2.0)), guide()).unwrap();
    let b = Surface::sweep(line(v(10.0, 0.0, 1.0), v(10.0, 0.0, 3.0)), guide()).unwrap();
    check_ct(&a, &b, 1e-5, 1, 10.0 * PI + 2.0, |p| {
        (p.truncate().length() - 10.0).abs() <= GT
            && (1.0 - GT..=2.0 + GT).contains(&p.z)
            && p.x >= -GT
            && p.y >= -GT
    });
}

#[test]
fn a_profile_partly_on_a_cylinder_gives_the_coincident_band() {
    // ρ = 1 for z in [0, 2], then out along 45° to (2, 3): the band z in [0, 2] lies on the
    // cylinder; it ends where the profile leaves it.
    let profile = || {
        Arc::new(
            Curve::pline(
                vec![v(1.0, 0.0, 0.0), v(1.0, 0.0, 2.0), v(2.0, 0.0, 3.0)],
                false,
                None,
            )
            .unwrap(),
        )
    };
    let cyl = Surface::cylinder(v(0.0, 0.0, -1.0), DVec3::Z, 1.0, 6.0).unwrap();
    let on_band = |p: DVec3, z0: f64, z1: f64| {
        (p.truncate().length() - 1.0).abs() <= GT
            && ((p.z - z0).abs() <= 2.0 * GT || (p.z - z1).abs() <= 2.0 * GT)
    };
    let full = Surface::revolve(profile(), DVec3::ZERO, DVec3::Z, TAU).unwrap();
    check(&full, &cyl, 2, 4.0 * PI, |p| on_band(p, 0.0, 2.0));
    // A quarter turn: one loop, two profile pieces and two quarter circles.
    let quarter = Surface::revolve(profile(), DVec3::ZERO, DVec3::Z, PI / 2.0).unwrap();
    check(&quarter, &cyl, 1, 4.0 + PI, |p| {
        (p.truncate().length() - 1.0).abs() <= GT
            && (-GT..=2.0 + 2.0 * GT).contains(&p.z)
            && p.x >= -GT
            && p.y >= -GT
    });
    // A shorter cylinder, z in [0.5, 1.5]: the band is bounded by the cylinder's own ends.
    let short = Surface::cylinder(v(0.0, 0.0, 0.5), DVec3::Z, 1.0, 1.0).unwrap();
    check(&full, &short, 2, 4.0 * PI, |p| on_band(p, 0.5, 1.5));
}

#[test]
fn a_profile_on_a_cylinder_then_crossing_it_gives_the_band_and_the_crossing_circle() {
    // ρ = 1 for z in [0, 2], out to (2, 3), back in through ρ = 1 at z = 11/3 to (0.5, 4).
    let prof = Curve::pline(
        vec![
            v(1.0, 0.0, 0.0),
            v(1.0, 0.0, 2.0),
            v(2.0, 0.0, 3.0),
            v(0.5, 0.0, 4.0),
        ],
        false,
        None,
    )
    .unwrap();
    let rev = Surface::revolve(Arc::new(prof), DVec3::ZERO, DVec3::Z, TAU).unwrap();
    let cyl = Surface::cylinder(v(0.0, 0.0, -1.0), DVec3::Z, 1.0, 6.0).unwrap();
    check(&rev, &cyl, 3, 6.0 * PI, |p| {
        (p.truncate().length() - 1.0).abs() <= GT
            && [0.0, 2.0, 11.0 / 3.0]
                .iter()
                .any(|z| (p.z - z).abs() <= 2.0 * GT)
    });
}

fn torus(tube_centre: DVec3, normal: DVec3) -> Surface {
    let tube = Curve::circle(tube_centre, 1.0, Some(normal)).unwrap();
    Surface::revolve(Arc::new(tube), DVec3::ZERO, DVec3::Z, TAU).unwrap()
}

#[test]
fn surfaces_coinciding_everywhere_are_told_apart_from_surfaces_that_do_not_meet() {
    let everywhere =
        |a: &Surface, b: &Surface| matches!(surface_meet(a, b, CT, GT).unwrap(), Meet::Everywhere);
    let s = Surface::sphere(v(1.0, 2.0, 3.0), 2.0).unwrap();
    assert!(everywhere(&s, &s.clone()));
    // One torus, its profile drawn at another azimuth (another seam, another mesh).
    let (t1, t2) = (
        torus(v(3.0, 0.0, 0.0), DVec3::Y),
        torus(v(0.0, 3.0, 0.0), DVec3::X),
    );
    assert!(everywhere(&t1, &t2));
    // A half meridian from pole to pole turned all round is its sphere.
    let c = v(0.0, 0.0, 1.0);
    let merid = Curve::arc3(c + 2.0 * DVec3::Z, c + 2.0 * DVec3::X, c - 2.0 * DVec3::Z).unwrap();
    let rev = Surface::revolve(Arc::new(merid), c, DVec3::Z, TAU).unwrap();
    assert!(everywhere(&rev, &Surface::sphere(c, 2.0).unwrap()));
    // Not everywhere: a larger sphere about the same centre, a torus of another tube.
    for (a, b) in [
        (s.clone(), Surface::sphere(v(1.0, 2.0, 3.0), 2.5).unwrap()),
        (t1.clone(), torus(v(6.0, 0.0, 0.0), DVec3::Y)),
    ] {
        match surface_meet(&a, &b, CT, GT).unwrap() {
            Meet::Curves(c) => assert!(c.is_empty(), "{} curves", c.len()),
            Meet::Everywhere => panic!("not the same surface"),
        }
    }
}

#[test]
fn the_builtin_returns_the_surface_itself_for_an_everywhere_overlap() {
    assert_eq!(
        eval("(surface-intersect (sphere-surface '(0 0 0) 2) (sphere-surface '(0 0 0) 2))"),
        "(#<SURFACE SPHERE R2>)"
    );
    assert_eq!(
        eval("(surface-intersect (sphere-surface '(0 0 0) 2) (sphere-surface '(0 0 9) 2))"),
        "nil"
    );
    // A region: its loop, a curve.
    assert_eq!(
        eval(
            "(mapcar 'type (surface-intersect \
               (ruled-surface (line '(0 0 0) '(6 0 0)) (line '(0 10 3) '(6 10 -0.6))) \
               (ruled-surface (line '(4 0 0) '(10 0 0)) (line '(4 10 0.6) '(10 10 -3)))))"
        ),
        "(CURVE)"
    );
}

#[test]
fn a_surface_lying_in_the_section_plane_gives_its_region_boundary() {
    // A flat ruled patch in z = 1: its four sides.
    let flat = Surface::ruled(
        line(v(0.0, 0.0, 1.0), v(4.0, 0.0, 1.0)),
        line(v(0.0, 3.0, 1.0), v(5.0, 3.0, 1.0)),
    );
    let r = surface_section_tol(&flat, v(0.0, 0.0, 1.0), DVec3::Z, CT, GT).unwrap();
    assert_eq!(r.len(), 1, "{} curves", r.len());
    assert!(r[0].closed);
    let exact = 4.0 + 10f64.sqrt() + 5.0 + 3.0;
    assert!((r[0].length() - exact).abs() <= 1e-9, "{}", r[0].length());
    assert!(r[0].points.iter().all(|p| (p.z - 1.0).abs() <= GT));
    // An annulus ρ in [1, 2] at z = 0 with a wall ρ = 2 up to z = 1: the plane z = 0 gives the
    // annulus's two circles; z = 0.5 crosses the wall in one circle, as before.
    let prof = Curve::pline(
        vec![v(1.0, 0.0, 0.0), v(2.0, 0.0, 0.0), v(2.0, 0.0, 1.0)],
        false,
        None,
    )
    .unwrap();
    let s = Surface::revolve(Arc::new(prof), DVec3::ZERO, DVec3::Z, TAU).unwrap();
    let r = surface_section_tol(&s, DVec3::ZERO, DVec3::Z, CT, GT).unwrap();
    assert_eq!(r.len(), 2, "{} curves", r.len());
    let total: f64 = r.iter().map(Polyline3::length).sum();
    assert!((total - 6.0 * PI).abs() <= 1e-6 * 6.0 * PI, "{total}");
    for p in r.iter().flat_map(|c| &c.points) {
        let rho = p.truncate().length();
        assert!(p.z.abs() <= GT && ((rho - 1.0).abs() <= GT || (rho - 2.0).abs() <= GT));
    }
    let r = surface_section_tol(&s, v(0.0, 0.0, 0.5), DVec3::Z, CT, GT).unwrap();
    assert_eq!(r.len(), 1, "{} curves", r.len());
    assert!((r[0].length() - 4.0 * PI).abs() <= 1e-6 * 4.0 * PI);
}
