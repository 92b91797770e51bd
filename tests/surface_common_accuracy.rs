//! Accuracy of a common region's boundary where the surfaces part tangentially (issue 13): a
//! profile whose straight piece lies on a cylinder or a plane and then leaves it along a tangent
//! arc of radius R. The gap grows like s²/2R past the junction, so "gap ≤ GEOMTOL" holds some
//! √(2·GEOMTOL·R) beyond it; the region's edge is the junction itself, written here in closed
//! form (the arc starts at y = 2, at x = 2).

use lispcad::geom::curve::Curve;
use lispcad::geom::surface::Surface;
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_4, PI, TAU};
use std::sync::Arc;

mod surface_support;
use surface_support::check_loops_reaching as check;

const GT: f64 = 1e-9;
const R: f64 = 10.0;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// In the xy plane: x = 1 for y in [0, 2] (two pieces, so the junction is not at a grid node of
/// the profile's parameter), then an arc of radius R about (1 + R, 2) turning away from x = 1
/// through π/4.
fn fillet_profile() -> Arc<Curve> {
    let end = v(
        1.0 + R - R * FRAC_PI_4.cos(),
        2.0 + R * FRAC_PI_4.sin(),
        0.0,
    );
    let pts = vec![v(1.0, 0.0, 0.0), v(1.0, 1.5, 0.0), v(1.0, 2.0, 0.0), end];
    let bulges = vec![0.0, 0.0, -(FRAC_PI_4 / 4.0).tan()];
    Arc::new(Curve::pline(pts, false, Some(bulges)).unwrap())
}

#[test]
fn the_profile_is_the_closed_form_one() {
    let c = fillet_profile();
    for i in 0..=20 {
        let p = c.eval(2.0 / 3.0 + i as f64 / 60.0);
        assert!((p.distance(v(1.0 + R, 2.0, 0.0)) - R).abs() <= 1e-12, "{p}");
        assert!(p.y >= 2.0 - 1e-12 && p.x >= 1.0 - 1e-12);
    }
}

/// On the cylinder ρ = 1 about the y axis, on one of the two circles y = 0 and y = 2.
fn on_band_circles(p: DVec3) -> bool {
    let rho = (p.x * p.x + p.z * p.z).sqrt();
    (rho - 1.0).abs() <= GT && (p.y.abs() <= GT || (p.y - 2.0).abs() <= GT)
}

#[test]
fn a_filleted_profile_revolved_on_a_cylinder_ends_its_band_at_the_junction() {
    let rev = Surface::revolve(fillet_profile(), DVec3::ZERO, DVec3::Y, TAU).unwrap();
    let cyl = Surface::cylinder(v(0.0, -1.0, 0.0), DVec3::Y, 1.0, 12.0).unwrap();
    let top = |p: DVec3| (p.y - 2.0).abs() <= GT;
    check(&rev, &cyl, 2, 4.0 * PI, on_band_circles, &[&top]);
}

#[test]
fn a_filleted_profile_revolved_on_a_revolved_line_ends_its_band_at_the_junction() {
    // The cylinder as a surface of revolution: the other surface is a free-form one too.
    let rev = Surface::revolve(fillet_profile(), DVec3::ZERO, DVec3::Y, TAU).unwrap();
    let line = Arc::new(Curve::line(v(1.0, -1.0, 0.0), v(1.0, 6.0, 0.0)).unwrap());
    let cyl = Surface::revolve(line, DVec3::ZERO, DVec3::Y, TAU).unwrap();
    let top = |p: DVec3| (p.y - 2.0).abs() <= GT;
    check(&rev, &cyl, 2, 4.0 * PI, on_band_circles, &[&top]);
}

#[test]
fn a_filleted_strip_on_a_plane_ends_its_flat_at_the_junction() {
    // In the planes z = 0 and z = 3: y = 0 for x in [0, 2], then up along an arc of radius R
    // about (2, R). Ruled between them, it lies on the plane y = 0 over x in [0, 2], z in [0, 3].
    let prof = |z: f64| {
        let end = v(2.0 + R * FRAC_PI_4.sin(), R - R * FRAC_PI_4.cos(), z);
        let pts = vec![v(0.0, 0.0, z), v(1.5, 0.0, z), v(2.0, 0.0, z), end];
        let bulges = vec![0.0, 0.0, (FRAC_PI_4 / 4.0).tan()];
        Arc::new(Curve::pline(pts, false, Some(bulges)).unwrap())
    };
    let strip = Surface::ruled(prof(0.0), prof(3.0));
    let wall = Surface::plane(vec![
        v(-1.0, 0.0, -1.0),
        v(12.0, 0.0, -1.0),
        v(12.0, 0.0, 4.0),
        v(-1.0, 0.0, 4.0),
    ])
    .unwrap();
    let on_rect = |p: DVec3| {
        let side = p.x.abs() <= GT || (p.x - 2.0).abs() <= GT;
        let end = p.z.abs() <= GT || (p.z - 3.0).abs() <= GT;
        p.y.abs() <= GT
            && (side || end)
            && (-GT..=2.0 + GT).contains(&p.x)
            && (-GT..=3.0 + GT).contains(&p.z)
    };
    let edge = |p: DVec3| (p.x - 2.0).abs() <= GT && (p.z - 1.5).abs() <= 0.5;
    check(&strip, &wall, 1, 10.0, on_rect, &[&edge]);
}
