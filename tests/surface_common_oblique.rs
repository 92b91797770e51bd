//! Narrow common regions that do not run along a parameter line of the traced surface, or
//! whose width changes along their length (issue 13). The traced surface is the unit square
//! y = 0, 0 ≤ x, z ≤ 1, built as a ruled surface between two lines (u = x, v = z); the other
//! is a ruled surface between two copies of the narrow-flat profile drawn in planes z = const
//! (the arcs rise towards +y), whose flat lies on the square over a band written here in
//! closed form: diagonal in (u, v), or narrowing from 0.08 to 0.02 across the square. The bands
//! avoid the quick look's samples and the tracer's grid nodes, so only the seed search finds
//! them.
//!
//! Only the order (square, other) is checked: it traces in the square's domain, where the band
//! is oblique or narrowing. The other order traces in the profile surface's own domain, where
//! the band runs along a parameter line at a steady width; it comes back as one loop of the
//! right shape, but with boundary points up to √(2·(tol/2)·R) = 4.5e-5 off the true edge near
//! the corners where the square's edge cuts the band. The diagonal band, traced in the square's
//! domain, has such points too, spread along its long edges from those corners (densifying
//! from a point beyond the edge keeps finding points beyond it), so it is checked to that
//! threshold rather than to 1e-9: a defect of the edge extrapolation near corners, not of the
//! seed search, left open.

use lispcad::geom::curve::Curve;
use lispcad::geom::surface::{surface_intersect_tol, Surface};
use lispcad::geom::DVec3;
use std::sync::Arc;

mod surface_support;
use surface_support::{check_order_reaching as check, summary, u_profile};

const GT: f64 = 1e-9;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn square() -> Surface {
    let line = |a: DVec3, b: DVec3| Arc::new(Curve::line(a, b).unwrap());
    Surface::ruled(
        line(v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0)),
        line(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0)),
    )
}

/// Whether `p` lies on the segment from `a` to `b` (within GT).
fn on_segment(p: DVec3, a: DVec3, b: DVec3) -> bool {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    p.distance(a + d * t) <= GT
}

/// Whether `p` lies on the closed polygon `q`.
fn on_polygon(q: &[DVec3]) -> impl Fn(DVec3) -> bool + '_ {
    move |p| (0..q.len()).any(|i| on_segment(p, q[i], q[(i + 1) % q.len()]))
}

fn perimeter(q: &[DVec3]) -> f64 {
    (0..q.len())
        .map(|i| q[i].distance(q[(i + 1) % q.len()]))
        .sum()
}

/// How far off the band's true edge the diagonal band's boundary points may lie: the tracer's
/// threshold, where the gap of surfaces parting tangentially reaches its tolerance,
/// √(2·(tol/2)·R) = 4.5e-5 for tol = 1e-9 and R = 2 (see the module's note).
const THRESHOLD: f64 = 5e-5;

#[test]
fn a_narrow_flat_running_diagonally_across_the_square() {
    // The flat, 0.02 wide along x, runs along (1, 0, 1) over the band c0 ≤ x − z ≤ c1: no grid
    // node (x − z a multiple of 1/32 or 1/16) and no sample (a multiple of 1/12) lies on it.
    let (c0, c1) = (0.035, 0.055);
    let prof = |z: f64| u_profile(c1 - c0, move |s, t| v(c0 + z + s, t, z), true);
    let strip = Surface::ruled(prof(-1.5), prof(2.5));
    let band = [
        v(c0, 0.0, 0.0),
        v(c1, 0.0, 0.0),
        v(1.0, 0.0, 1.0 - c1),
        v(1.0, 0.0, 1.0 - c0),
    ];
    let meet = |x: &Surface, y: &Surface| surface_intersect_tol(x, y, 1e-6, 1e-9).unwrap();
    let r = meet(&square(), &strip);
    // One loop round the whole band (on main: 7 short loops, one around each seed).
    assert_eq!(r.len(), 1, "{}", summary(&r));
    assert!(r[0].closed);
    let near = |p: DVec3, a: DVec3, b: DVec3| {
        let d = b - a;
        let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
        p.distance(a + d * t) <= THRESHOLD
    };
    for p in &r[0].points {
        assert!(p.y.abs() <= GT, "{p}");
        assert!((0..4).any(|i| near(*p, band[i], band[(i + 1) % 4])), "{p}");
    }
    // Every side of the band is reached, each long side at both ends and in the middle.
    for (a, b) in [(0, 1), (1, 2), (2, 3), (3, 0)] {
        for f in [0.02, 0.5, 0.98] {
            let x = band[a].lerp(band[b], f);
            assert!(
                r[0].points.iter().any(|p| p.distance(x) <= 0.05),
                "side {a}{b} at {f}"
            );
        }
    }
    let length = r[0].length();
    assert!(
        (length - perimeter(&band)).abs() <= 1e-3 * length,
        "{length}"
    );
    for _ in 0..2 {
        assert_eq!(meet(&square(), &strip)[0].points, r[0].points);
    }
}

#[test]
fn a_narrow_flat_narrowing_across_the_square() {
    // The flat runs along z over c0 ≤ x ≤ c0 + w(z), w falling linearly from 0.08 at z = 0 to
    // 0.02 at z = 1 (the ruled surface runs from z = −0.2 to 1.2). Its narrow end lies between
    // grid lines, its wide end between samples.
    let c0 = 0.128;
    let w = |z: f64| 0.08 - 0.06 * z;
    let prof = |z: f64| u_profile(w(z), move |s, t| v(c0 + s, t, z), true);
    let wedge = Surface::ruled(prof(-0.2), prof(1.2));
    let band = [
        v(c0, 0.0, 0.0),
        v(c0 + w(0.0), 0.0, 0.0),
        v(c0 + w(1.0), 0.0, 1.0),
        v(c0, 0.0, 1.0),
    ];
    let near = |a: DVec3, b: DVec3| move |p: DVec3| on_segment(p, a, b) && p.z > 0.4 && p.z < 0.9;
    let (left, right) = (near(band[3], band[0]), near(band[1], band[2]));
    let top = |p: DVec3| (p.z - 1.0).abs() <= GT;
    let bottom = |p: DVec3| p.z.abs() <= GT;
    let reach: [&dyn Fn(DVec3) -> bool; 4] = [&left, &right, &top, &bottom];
    check(
        &square(),
        &wedge,
        1,
        perimeter(&band),
        on_polygon(&band),
        &reach,
    );
}
