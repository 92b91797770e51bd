//! Surface-level operations: closed forms where available, meshes otherwise.

use lispcad::geom::surface::{
    arc_surface_hits, segment_surface_hits, surface_intersect, surface_section, ArcData, Surface,
};
use lispcad::geom::DVec3;

#[test]
fn segment_against_sphere_plane_and_cylinder() {
    let s = Surface::sphere(DVec3::ZERO, 2.0).unwrap();
    let h = segment_surface_hits(
        DVec3::new(-4.0, 0.0, 0.0),
        DVec3::new(4.0, 0.0, 0.0),
        &s,
        1e-12,
    )
    .unwrap();
    assert_eq!(
        h,
        vec![
            (0.25, DVec3::new(-2.0, 0.0, 0.0)),
            (0.75, DVec3::new(2.0, 0.0, 0.0))
        ]
    );
    // Tangent.
    let h = segment_surface_hits(
        DVec3::new(-4.0, 2.0, 0.0),
        DVec3::new(4.0, 2.0, 0.0),
        &s,
        1e-12,
    )
    .unwrap();
    assert_eq!(h.len(), 1);
    let p = Surface::plane(vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::Y,
    ])
    .unwrap();
    assert_eq!(
        segment_surface_hits(
            DVec3::new(0.5, 0.5, 1.0),
            DVec3::new(0.5, 0.5, -1.0),
            &p,
            1e-12
        )
        .unwrap()
        .len(),
        1
    );
    let c = Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 1.0).unwrap();
    assert_eq!(
        segment_surface_hits(
            DVec3::new(-2.0, 0.0, 0.5),
            DVec3::new(2.0, 0.0, 0.5),
            &c,
            1e-12
        )
        .unwrap()
        .len(),
        2
    );
    // A ruled surface through its mesh.
    let r = Surface::ruled(
        std::sync::Arc::new(
            lispcad::geom::surface::SampledCurve::new(vec![DVec3::ZERO, DVec3::X], false).unwrap(),
        ),
        std::sync::Arc::new(
            lispcad::geom::surface::SampledCurve::new(
                vec![DVec3::Y, DVec3::new(1.0, 1.0, 0.0)],
                false,
            )
            .unwrap(),
        ),
    );
    let h = segment_surface_hits(
        DVec3::new(0.3, 0.4, 1.0),
        DVec3::new(0.3, 0.4, -1.0),
        &r,
        1e-6,
    )
    .unwrap();
    assert_eq!(h.len(), 1);
    assert!((h[0].1 - DVec3::new(0.3, 0.4, 0.0)).length() < 1e-12);
}

#[test]
fn arc_against_a_plane_region() {
    let p = Surface::plane(vec![
        DVec3::ZERO,
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(2.0, 2.0, 0.0),
        DVec3::new(0.0, 2.0, 0.0),
    ])
    .unwrap();
    // A vertical circle of radius 1 centred at (1, 1, 0) in the plane y = 1: meets z = 0 at x = 0 and 2 (edges).
    let c = ArcData::circle(DVec3::new(1.0, 1.0, 0.0), 1.0, DVec3::Y);
    let h = arc_surface_hits(&c, &p, 1e-9).unwrap();
    assert_eq!(h.len(), 2);
    // Shifted so one hit falls outside the region.
    let c = ArcData::circle(DVec3::new(2.5, 1.0, 0.0), 1.0, DVec3::Y);
    let h = arc_surface_hits(&c, &p, 1e-9).unwrap();
    assert_eq!(h.len(), 1);
    assert!((h[0] - DVec3::new(1.5, 1.0, 0.0)).length() < 1e-12);
}

#[test]
fn two_sphere_surfaces_meet_in_a_circle() {
    let a = Surface::sphere(DVec3::ZERO, 1.0).unwrap();
    let b = Surface::sphere(DVec3::new(1.2, 0.0, 0.0), 1.0).unwrap();
    let r = surface_intersect(&a, &b, 1e-3).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    let rad = (1.0f64 - 0.36).sqrt();
    for p in &r[0].points {
        assert!((p.x - 0.6).abs() < 5e-3);
        assert!(((p.y * p.y + p.z * p.z).sqrt() - rad).abs() < 5e-3);
    }
}

#[test]
fn cylinder_surface_section_is_exact() {
    let c = Surface::cylinder(DVec3::ZERO, DVec3::Z, 3.0, 2.0).unwrap();
    let r = surface_section(&c, DVec3::new(0.0, 0.0, 1.0), DVec3::Z, 1e-3).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0]
        .points
        .iter()
        .all(|p| ((p.x * p.x + p.y * p.y).sqrt() - 3.0).abs() < 1e-14));
    let s = Surface::sphere(DVec3::ZERO, 1.0).unwrap();
    let r = surface_section(&s, DVec3::ZERO, DVec3::new(1.0, 1.0, 0.0), 1e-3).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    assert!(r[0]
        .points
        .iter()
        .all(|p| (p.length() - 1.0).abs() < 1e-15 && (p.x + p.y).abs() < 1e-15));
    let r = surface_section(&s, DVec3::new(0.0, 0.0, 0.6), DVec3::Z, 1e-3).unwrap();
    assert!(r[0]
        .points
        .iter()
        .all(|p| ((p.x * p.x + p.y * p.y).sqrt() - 0.8).abs() < 1e-15 && p.z == 0.6));
    assert!(
        surface_section(&s, DVec3::new(0.0, 0.0, 1.5), DVec3::Z, 1e-3)
            .unwrap()
            .is_empty()
    );
    assert!(surface_section(&s, DVec3::ZERO, DVec3::ZERO, 1e-3).is_err());
}

#[test]
fn areas_and_boundaries() {
    use lispcad::geom::surface::{surface_area, surface_boundary};
    use std::f64::consts::PI;
    let c = Surface::cylinder(DVec3::ZERO, DVec3::Z, 2.0, 3.0).unwrap();
    assert_eq!(surface_area(&c, 1e-3).unwrap(), 12.0 * PI);
    assert_eq!(surface_boundary(&c, 1e-3).unwrap().len(), 2);
    let p = Surface::plane(vec![
        DVec3::ZERO,
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(2.0, 3.0, 0.0),
    ])
    .unwrap();
    assert_eq!(surface_area(&p, 1e-3).unwrap(), 3.0);
    assert_eq!(surface_boundary(&p, 1e-3).unwrap()[0].points.len(), 3);
    let s = Surface::sphere(DVec3::ZERO, 1.0).unwrap();
    assert!(surface_boundary(&s, 1e-3).unwrap().is_empty());
}

#[test]
fn revolved_profile_sections_are_exact() {
    use lispcad::geom::surface::SampledCurve;
    use std::sync::Arc;
    // A cone-like profile from (1,0,0) to (2,0,2), revolved fully about Z.
    let prof = Arc::new(
        SampledCurve::new(
            vec![DVec3::new(1.0, 0.0, 0.0), DVec3::new(2.0, 0.0, 2.0)],
            false,
        )
        .unwrap(),
    );
    let s = Surface::revolve(prof, DVec3::ZERO, DVec3::Z, std::f64::consts::TAU).unwrap();
    // ⟂ axis at z = 1: the circle of radius 1.5.
    let r = surface_section(&s, DVec3::new(0.0, 0.0, 1.0), DVec3::Z, 1e-4).unwrap();
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!(((p.x * p.x + p.y * p.y).sqrt() - 1.5).abs() < 1e-14 && (p.z - 1.0).abs() < 1e-15);
    }
    // Through the axis (plane x = 0): the profile and its mirror, exactly.
    let r = surface_section(&s, DVec3::ZERO, DVec3::X, 1e-4).unwrap();
    assert_eq!(r.len(), 2);
    for c in &r {
        assert!(c.points.iter().all(|p| p.x.abs() < 1e-15));
        let last = c.points[c.points.len() - 1];
        assert!((c.points[0].y.abs() - 1.0).abs() < 1e-15 && (last.y.abs() - 2.0).abs() < 1e-15);
        assert!((last.z - 2.0).abs() < 1e-15);
    }
}

#[test]
fn arc_across_angle_zero_against_a_sphere() {
    // The circle x = −2 + cos θ, y = sin θ meets the sphere |p| = 2 where cos θ = 1/4
    // (θ = ±75.5°); the arc from 300° to 90° runs across 0° and holds only θ = +75.5°.
    let s = Surface::sphere(DVec3::ZERO, 2.0).unwrap();
    let arc = ArcData {
        center: DVec3::new(-2.0, 0.0, 0.0),
        radius: 1.0,
        normal: DVec3::Z,
        start_angle: 300f64.to_radians(),
        end_angle: 90f64.to_radians(),
    };
    let h = arc_surface_hits(&arc, &s, 1e-4).unwrap();
    assert_eq!(h.len(), 1, "{h:?}");
    let want = DVec3::new(-1.75, (1.0f64 - 1.0 / 16.0).sqrt(), 0.0);
    assert!((h[0] - want).length() < 1e-2, "{h:?}");
}
