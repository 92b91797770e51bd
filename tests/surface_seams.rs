//! Seams and boundary edges lose no hit, and a curve lying on a surface is an OVERLAP
//! (issue 13, item 3).

use lispcad::geom::curve::Curve;
use lispcad::geom::surface::{curve_on_surface, segment_surface_hits, surface_section, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

mod surface_support;
use surface_support::eval;

fn torus() -> Surface {
    // The profile circle starts at (4, 0, 0): its seam lies on the plane z = 0.
    let profile = Curve::circle(DVec3::new(5.0, 0.0, 0.0), 1.0, Some(DVec3::Y)).unwrap();
    assert!(profile.eval(0.0).distance(DVec3::new(4.0, 0.0, 0.0)) < 1e-12);
    Surface::revolve(Arc::new(profile), DVec3::ZERO, DVec3::Z, TAU).unwrap()
}

#[test]
fn torus_sectioned_through_its_profile_seam_gives_both_circles() {
    for n in [DVec3::Z, -DVec3::Z] {
        let cs = surface_section(&torus(), DVec3::ZERO, n, 1e-4).unwrap();
        let mut radii: Vec<f64> = cs
            .iter()
            .map(|c| {
                assert!(c.closed);
                let r = c.points[0].truncate().length();
                for p in &c.points {
                    assert!((p.truncate().length() - r).abs() < 1e-12 && p.z.abs() < 1e-12);
                }
                r
            })
            .collect();
        radii.sort_by(f64::total_cmp);
        assert_eq!(radii.len(), 2, "normal {n}");
        assert!((radii[0] - 4.0).abs() < 1e-12 && (radii[1] - 6.0).abs() < 1e-12);
    }
}

#[test]
fn a_line_through_both_end_edges_of_a_half_revolution_finds_both_points() {
    // The line x ∈ [−5, 5] at y = 0, z = 1 passes through the revolution's start edge (angle 0)
    // and its end edge (angle π, where the mesh's y is 1.2e-16 off).
    let half = Surface::revolve(
        Arc::new(Curve::line(DVec3::new(2.0, 0.0, 0.0), DVec3::new(2.0, 0.0, 3.0)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        PI,
    )
    .unwrap();
    let hits = segment_surface_hits(
        DVec3::new(-5.0, 0.0, 1.0),
        DVec3::new(5.0, 0.0, 1.0),
        &half,
        1e-9,
    )
    .unwrap();
    assert_eq!(hits.len(), 2, "{hits:?}");
    assert!(hits[0].1.distance(DVec3::new(-2.0, 0.0, 1.0)) <= 1e-9);
    assert!(hits[1].1.distance(DVec3::new(2.0, 0.0, 1.0)) <= 1e-9);
    assert!((hits[0].0 - 0.3).abs() <= 1e-9 && (hits[1].0 - 0.7).abs() <= 1e-9);
}

#[test]
fn curves_lying_on_surfaces_are_overlaps() {
    let cyl = Surface::cylinder(DVec3::ZERO, DVec3::Z, 2.0, 3.0).unwrap();
    let sph = Surface::sphere(DVec3::ZERO, 2.0).unwrap();
    let on_cyl = Curve::circle(DVec3::new(0.0, 0.0, 1.0), 2.0, None).unwrap();
    let equator = Curve::circle(DVec3::ZERO, 2.0, Some(DVec3::new(1.0, 1.0, 0.3))).unwrap();
    assert!(curve_on_surface(&on_cyl, &cyl, 1e-9).unwrap());
    assert!(curve_on_surface(&equator, &sph, 1e-9).unwrap());
    // A circle on the torus (its outer equator) and one just off it.
    let eq = Curve::circle(DVec3::ZERO, 6.0, None).unwrap();
    assert!(curve_on_surface(&eq, &torus(), 1e-9).unwrap());
    let off = Curve::circle(DVec3::ZERO, 6.0 + 1e-6, None).unwrap();
    assert!(!curve_on_surface(&off, &torus(), 1e-9).unwrap());
    let above = Curve::circle(DVec3::new(0.0, 0.0, 3.5), 2.0, None).unwrap();
    assert!(!curve_on_surface(&above, &cyl, 1e-9).unwrap());
}

#[test]
fn intersect_and_intersect_info_report_the_overlap() {
    let cyl = "(cylinder-surface '(0 0 0) '(0 0 1) 2 3)";
    assert_eq!(
        eval(&format!(
            "(mapcar 'type (intersect (circle '(0 0 1) 2) {cyl}))"
        )),
        "(CURVE)"
    );
    assert_eq!(
        eval(&format!(
            "(cdr (assoc 'kind (car (intersect-info (circle '(0 0 1) 2) {cyl}))))"
        )),
        "OVERLAP"
    );
    assert_eq!(
        eval("(mapcar 'type (intersect (circle '(0 0 0) 2 '(0 1 0)) (sphere-surface '(0 0 0) 2)))"),
        "(CURVE)"
    );
    // A crossing circle: two CROSS hits with the circle's parameter.
    assert_eq!(
        eval(&format!(
            "(mapcar '(lambda (h) (cdr (assoc 'kind h))) (intersect-info (circle '(2 0 1) 1 '(0 1 0)) {cyl}))"
        )),
        "(CROSS CROSS)"
    );
    // Tangent contacts come back as points in the result list.
    assert_eq!(
        eval("(surface-intersect (sphere-surface '(0 0 1) 1) (sphere-surface '(0 0 3) 1))"),
        "((0.0 0.0 2.0))"
    );
}
