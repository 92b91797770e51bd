//! Paper 002's closed-form curve/surface hits against their closed forms, including tangent
//! and grazing cases; the point-in-facet test on vertices and edges; curve/mesh hits.

use lispcad::geom::mesh::icosphere;
use lispcad::geom::surface::{
    circle_plane, curve_mesh_hits, cylinder_section, point_in_convex_facet, point_in_polygon,
    polyline_mesh_hits, segment_cylinder, segment_plane, ArcData, Cylinder, FacetLocation,
    SampledCurve, Surface,
};
use lispcad::geom::DVec3;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

mod mesh_support;
use mesh_support::l_outline;

fn cyl() -> Cylinder {
    match Surface::cylinder(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap() {
        Surface::Cylinder(c) => c,
        _ => unreachable!(),
    }
}

#[test]
fn line_through_cylinder_hits_twice() {
    let h = segment_cylinder(
        DVec3::new(-3.0, 0.0, 1.0),
        DVec3::new(3.0, 0.0, 1.0),
        &cyl(),
        1e-12,
    );
    assert_eq!(h.len(), 2);
    assert!((h[0].point - DVec3::new(-1.0, 0.0, 1.0)).length() < 1e-15);
    assert!((h[1].point - DVec3::new(1.0, 0.0, 1.0)).length() < 1e-15);
    assert!((h[0].t - 1.0 / 3.0).abs() < 1e-15 && (h[1].t - 2.0 / 3.0).abs() < 1e-15);
    assert!(!h[0].tangent);
}

#[test]
fn tangent_line_touches_once() {
    let h = segment_cylinder(
        DVec3::new(-3.0, 1.0, 1.0),
        DVec3::new(3.0, 1.0, 1.0),
        &cyl(),
        1e-9,
    );
    assert_eq!(h.len(), 1);
    assert!(h[0].tangent);
    assert!((h[0].point - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-12);
    // Just outside: nothing.
    assert!(segment_cylinder(
        DVec3::new(-3.0, 1.001, 1.0),
        DVec3::new(3.0, 1.001, 1.0),
        &cyl(),
        1e-9
    )
    .is_empty());
}

#[test]
fn height_range_and_early_rejections() {
    let c = cyl();
    // Above the top cap: rejected before the quadratic.
    assert!(segment_cylinder(
        DVec3::new(-3.0, 0.0, 2.5),
        DVec3::new(3.0, 0.0, 2.6),
        &c,
        1e-12
    )
    .is_empty());
    // Grazing the rim: a line at exactly the top height hits on the rim circle.
    let h = segment_cylinder(
        DVec3::new(-3.0, 0.0, 2.0),
        DVec3::new(3.0, 0.0, 2.0),
        &c,
        1e-12,
    );
    assert_eq!(h.len(), 2);
    // Oblique line entering through the side, leaving through the top: one side hit.
    let h = segment_cylinder(
        DVec3::new(-2.0, 0.0, 0.0),
        DVec3::new(0.0, 0.0, 4.0),
        &c,
        1e-12,
    );
    assert_eq!(h.len(), 1);
    assert!((h[0].point - DVec3::new(-1.0, 0.0, 2.0)).length() < 1e-12);
    // A segment along the surface: its part within the height range.
    let h = segment_cylinder(
        DVec3::new(1.0, 0.0, -1.0),
        DVec3::new(1.0, 0.0, 1.0),
        &c,
        1e-12,
    );
    assert_eq!(h.len(), 2);
    assert_eq!(h[0].point, DVec3::new(1.0, 0.0, 0.0));
    // A segment that stops short of the surface.
    assert!(segment_cylinder(
        DVec3::new(-0.5, 0.0, 1.0),
        DVec3::new(0.5, 0.0, 1.0),
        &c,
        1e-12
    )
    .is_empty());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn cylinder_hits_lie_on_the_cylinder(
        ax in -3.0f64..3.0, ay in -3.0f64..3.0, az in -1.0f64..3.0,
        bx in -3.0f64..3.0, by in -3.0f64..3.0, bz in -1.0f64..3.0,
    ) {
        let c = cyl();
        let (a, b) = (DVec3::new(ax, ay, az), DVec3::new(bx, by, bz));
        for h in segment_cylinder(a, b, &c, 1e-9) {
            let r = (h.point.x * h.point.x + h.point.y * h.point.y).sqrt();
            prop_assert!((r - 1.0).abs() < 1e-6);
            prop_assert!(h.point.z >= -1e-9 && h.point.z <= 2.0 + 1e-9);
            prop_assert!((a + (b - a) * h.t - h.point).length() < 1e-12);
        }
    }
}

#[test]
fn circle_and_arc_against_plane() {
    let c = ArcData::circle(DVec3::ZERO, 1.0, DVec3::Z);
    let p = circle_plane(&c, DVec3::new(0.5, 0.0, 0.0), DVec3::X, 1e-12);
    assert_eq!(p.len(), 2);
    let s = 0.75f64.sqrt();
    assert!((p[0] - DVec3::new(0.5, s, 0.0)).length() < 1e-15);
    assert!((p[1] - DVec3::new(0.5, -s, 0.0)).length() < 1e-15);
    // The quarter arc 0..π/2 keeps only the upper point.
    let arc = ArcData {
        start_angle: 0.0,
        end_angle: FRAC_PI_2,
        ..c
    };
    assert_eq!(
        circle_plane(&arc, DVec3::new(0.5, 0.0, 0.0), DVec3::X, 1e-12).len(),
        1
    );
    // Tangent plane x = 1: one point.
    let t = circle_plane(&c, DVec3::X, DVec3::X, 1e-12);
    assert_eq!(t.len(), 1);
    assert!((t[0] - DVec3::X).length() < 1e-15);
    // Beyond: none; parallel: none; oblique plane through the centre: two opposite points.
    assert!(circle_plane(&c, DVec3::new(1.01, 0.0, 0.0), DVec3::X, 1e-12).is_empty());
    assert!(circle_plane(&c, DVec3::new(0.0, 0.0, 0.0), DVec3::Z, 1e-12).is_empty());
    let o = circle_plane(&c, DVec3::ZERO, DVec3::new(1.0, 1.0, 1.0), 1e-12);
    assert_eq!(o.len(), 2);
    assert!((o[0] + o[1]).length() < 1e-15);
    // A tilted circle (normal X): the plane z = 0.5 meets it at angles where sinθ... closed form.
    let tc = ArcData::circle(DVec3::new(2.0, 0.0, 0.0), 2.0, DVec3::X);
    for q in circle_plane(&tc, DVec3::new(0.0, 0.0, 0.5), DVec3::Z, 1e-12) {
        assert!((q.z - 0.5).abs() < 1e-14);
        assert!(((q - tc.center).length() - 2.0).abs() < 1e-14);
        assert!((q.x - 2.0).abs() < 1e-14);
    }
    // An arc crossing angle 0 (from 3π/2 to π/2 the long way round: 270°..450°).
    let wrap = ArcData {
        start_angle: 1.5 * PI,
        end_angle: 2.5 * PI,
        ..c
    };
    assert_eq!(
        circle_plane(&wrap, DVec3::new(0.5, 0.0, 0.0), DVec3::X, 1e-12).len(),
        2
    );
    assert!(circle_plane(&wrap, DVec3::new(-0.5, 0.0, 0.0), DVec3::X, 1e-12).is_empty());
}

#[test]
fn segment_plane_rejects_one_side_and_handles_ends() {
    assert!(segment_plane(
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(1.0, 0.0, 2.0),
        DVec3::ZERO,
        DVec3::Z
    )
    .is_none());
    let (t, p) = segment_plane(
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::new(0.0, 0.0, 3.0),
        DVec3::ZERO,
        DVec3::Z,
    )
    .unwrap();
    assert_eq!((t, p), (0.25, DVec3::ZERO));
    // An end on the plane is that end, exactly.
    let e = DVec3::new(0.1, 0.7, 0.0);
    assert_eq!(
        segment_plane(e, DVec3::new(1.0, 1.0, 1.0), DVec3::ZERO, DVec3::Z)
            .unwrap()
            .1,
        e
    );
    // In the plane: none.
    assert!(segment_plane(DVec3::ZERO, DVec3::X, DVec3::ZERO, DVec3::Z).is_none());
}

#[test]
fn point_in_facet_on_vertices_edges_and_extensions() {
    let f = [DVec3::ZERO, DVec3::X, DVec3::Y];
    let n = DVec3::Z;
    assert_eq!(
        point_in_convex_facet(DVec3::new(0.2, 0.2, 0.0), &f, n, 1e-12),
        FacetLocation::Inside
    );
    assert_eq!(
        point_in_convex_facet(DVec3::X, &f, n, 1e-12),
        FacetLocation::OnVertex(1)
    );
    assert_eq!(
        point_in_convex_facet(DVec3::new(0.5, 0.0, 0.0), &f, n, 1e-12),
        FacetLocation::OnEdge(0)
    );
    assert_eq!(
        point_in_convex_facet(DVec3::new(0.5, 0.5, 0.0), &f, n, 1e-12),
        FacetLocation::OnEdge(1)
    );
    // On edge 0's extension: outside, not "on the edge".
    assert_eq!(
        point_in_convex_facet(DVec3::new(1.5, 0.0, 0.0), &f, n, 1e-12),
        FacetLocation::Outside
    );
    assert_eq!(
        point_in_convex_facet(DVec3::new(0.6, 0.6, 0.0), &f, n, 1e-12),
        FacetLocation::Outside
    );
    // Reversed winding works the same.
    let r = [DVec3::ZERO, DVec3::Y, DVec3::X];
    assert_eq!(
        point_in_convex_facet(DVec3::new(0.2, 0.2, 0.0), &r, n, 1e-12),
        FacetLocation::Inside
    );
    // Non-convex polygon (an L): the notch is outside.
    let l = l_outline();
    assert_eq!(
        point_in_polygon(DVec3::new(1.5, 1.5, 0.0), &l, n, 1e-12),
        FacetLocation::Outside
    );
    assert_eq!(
        point_in_polygon(DVec3::new(0.5, 1.5, 0.0), &l, n, 1e-12),
        FacetLocation::Inside
    );
    // A ray through the vertex (1, 1) counts it once.
    assert_eq!(
        point_in_polygon(DVec3::new(0.5, 1.0, 0.0), &l, n, 1e-12),
        FacetLocation::Inside
    );
    assert_eq!(
        point_in_polygon(DVec3::new(1.0, 1.5, 0.0), &l, n, 1e-12),
        FacetLocation::OnEdge(3)
    );
}

#[test]
fn plane_region_segment_hit_uses_the_polygon() {
    let s = Surface::plane(vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::Y,
    ])
    .unwrap();
    let Surface::Plane(p) = s else { unreachable!() };
    assert!(p
        .segment_hit(DVec3::new(0.5, 0.5, -1.0), DVec3::new(0.5, 0.5, 1.0), 1e-12)
        .is_some());
    assert!(p
        .segment_hit(DVec3::new(1.0, 0.5, -1.0), DVec3::new(1.0, 0.5, 1.0), 1e-12)
        .is_some());
    assert!(p
        .segment_hit(DVec3::new(1.5, 0.5, -1.0), DVec3::new(1.5, 0.5, 1.0), 1e-12)
        .is_none());
}

#[test]
fn curves_against_a_sphere_mesh() {
    let m = icosphere(DVec3::ZERO, 1.0, 3);
    // Through two opposite mesh vertices (the icosahedron's (0, ±1, ±t)/|.|): each crossing
    // is reported once, not once per triangle of the fan.
    let v = m.vertices()[0];
    let h = polyline_mesh_hits(&[v * 2.0, -v * 2.0], &m);
    assert_eq!(h.len(), 2, "{h:?}");
    assert!((h[0].point - v).length() < 1e-15);
    // A polyline whose vertex lies on the mesh: one hit, not one per segment.
    let h = polyline_mesh_hits(&[DVec3::new(0.0, 0.0, 0.0), v, v * 2.0], &m);
    assert_eq!(h.len(), 1);
    // A sampled curve: the x axis as a two-point curve.
    let c = SampledCurve::new(
        vec![DVec3::new(-2.0, 0.01, 0.02), DVec3::new(2.0, 0.01, 0.02)],
        false,
    )
    .unwrap();
    let h = curve_mesh_hits(&c, &m, 1e-6);
    assert_eq!(h.len(), 2);
    assert!(h[0].t < 0.5 && h[1].t > 0.5);
    assert!((h[0].point.x + 1.0).abs() < 2e-3);
}

#[test]
fn exact_cylinder_sections() {
    let c = cyl();
    // ⟂ axis: a circle.
    let r = cylinder_section(&c, DVec3::new(0.0, 0.0, 1.0), DVec3::Z, 1e-4);
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!(((p.x * p.x + p.y * p.y).sqrt() - 1.0).abs() < 1e-14 && (p.z - 1.0).abs() < 1e-14);
    }
    // Oblique within the height: a whole ellipse.
    let n = DVec3::new(0.5, 0.0, 1.0);
    let r = cylinder_section(&c, DVec3::new(0.0, 0.0, 1.0), n, 1e-4);
    assert_eq!(r.len(), 1);
    assert!(r[0].closed);
    for p in &r[0].points {
        assert!(((p.x * p.x + p.y * p.y).sqrt() - 1.0).abs() < 1e-14);
        assert!(n.dot(*p - DVec3::Z).abs() < 1e-14);
    }
    // Steep: clipped by both caps into two arcs.
    let r = cylinder_section(
        &c,
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(3.0, 0.0, 1.0),
        1e-4,
    );
    assert_eq!(r.len(), 2);
    assert!(r.iter().all(|p| !p.closed));
    // Parallel to the axis: two rulings.
    let r = cylinder_section(&c, DVec3::new(0.5, 0.0, 0.0), DVec3::X, 1e-4);
    assert_eq!(r.len(), 2);
    assert!(r
        .iter()
        .all(|p| (p.points[0].x - 0.5).abs() < 1e-14 && p.points[1].z == 2.0));
    // Missing the cylinder.
    assert!(cylinder_section(&c, DVec3::new(0.0, 0.0, 5.0), DVec3::Z, 1e-4).is_empty());
}
