//! Narrow common regions that do not run along a parameter line of the traced surface, or
//! whose width changes along their length (issue 13). One surface is the unit square y = 0,
//! 0 ≤ x, z ≤ 1, built as a ruled surface between two lines (u = x, v = z); the other is a
//! ruled surface between two copies of the narrow-flat profile drawn in planes z = const (the
//! arcs rise towards +y), whose flat lies on the square over a band written here in closed
//! form: diagonal in (u, v), or narrowing from 0.08 to 0.02 across the square. The bands avoid
//! the quick look's samples and the tracer's grid nodes, so only the seed search finds them.
//!
//! Both orders are checked to the same closed forms. In the order (square, other) the tracer
//! works in the square's domain, where the band is oblique or narrowing; in the other, in the
//! profile surface's own domain, where the band runs along a parameter line at a steady width.
//! Where the square's edge cuts the band (in the order (other, square), the target's extent
//! ending across the tracer's domain), the corners are found along that extent edge, so both
//! orders are checked to GEOMTOL (before: points up to √(2·(tol/2)·R) = 4.5e-5 off near the
//! corners, and with a first fix the loop 1.9e-3 short, cutting the acute corner).

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_tol, surface_section_tol, Surface};
use lispcad::geom::DVec3;
use std::sync::Arc;

mod surface_support;
use surface_support::{summary, u_profile, unit_square, R};

const GT: f64 = 1e-9;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The distance from `p` to the segment from `a` to `b`.
fn to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
    p.distance(a + d * t)
}

/// The distance from `p` to the closed polygon `q`.
fn to_polygon(p: DVec3, q: &[DVec3]) -> f64 {
    (0..q.len())
        .map(|i| to_segment(p, q[i], q[(i + 1) % q.len()]))
        .fold(f64::INFINITY, f64::min)
}

fn perimeter(q: &[DVec3]) -> f64 {
    (0..q.len())
        .map(|i| q[i].distance(q[(i + 1) % q.len()]))
        .sum()
}

/// A band of the square where the profile surface's flat lies on it: its outline
/// (counter-clockwise from (x0(0), 0)) and where the flat runs at each z (from `x0(z)` to
/// `x1(z)`; the arcs rise beyond, R − √(R² − s²) at s past the flat's edge).
struct Band {
    outline: [DVec3; 4],
    flat: fn(f64) -> (f64, f64),
}

impl Band {
    /// The height of the profile surface over the point (x, 0, z) near the band: the gap
    /// along y, at least the distance between the surfaces there.
    fn lift(&self, p: DVec3) -> f64 {
        let (x0, x1) = (self.flat)(p.z);
        let s = (x0 - p.x).max(p.x - x1).max(0.0);
        R - (R * R - s * s).sqrt()
    }
}

/// Both orders of the intersection of the square and `other`: [`check_loop`] of each.
fn check_both(other: &Surface, band: &Band) {
    check_both_with(&unit_square(), other, band);
}

/// [`check_both`] with the square `sq` in the plane y = 0.
fn check_both_with(sq: &Surface, other: &Surface, band: &Band) {
    let meet = |x: &Surface, y: &Surface| surface_intersect_tol(x, y, 1e-6, 1e-9).unwrap();
    for (order, (x, y)) in [(sq, other), (other, sq)].into_iter().enumerate() {
        let name = if order == 0 {
            "square, other"
        } else {
            "other, square"
        };
        check_loop(name, &|| meet(x, y), band, 0.05);
    }
}

/// The section of `other` by the plane y = 0: the whole of its flat, `band` (in the profile
/// surface's own domain, a band along a parameter line at a steady width or one narrowing
/// evenly), checked as [`check_loop`] to GEOMTOL. Its straight sides, up to 4 long, have
/// points only where they cross the grid's lines (an eighth of the length apart along z).
fn check_section(other: &Surface, band: &Band) {
    let cut = || surface_section_tol(other, DVec3::ZERO, DVec3::Y, 1e-6, 1e-9).unwrap();
    check_loop("section", &cut, band, 0.2);
}

/// One closed loop from `run`, every point on the plane y = 0 and on the profile surface
/// within GEOMTOL, within GEOMTOL of the band's outline, every side reached (within `reach`)
/// at both ends and in the middle, the length the outline's to 1e-6, and two more runs giving
/// the same bits.
fn check_loop(name: &str, run: &dyn Fn() -> Vec<Polyline3>, band: &Band, reach: f64) {
    let q = &band.outline;
    let r = run();
    assert_eq!(r.len(), 1, "{name}: {}", summary(&r));
    assert!(r[0].closed, "{name}: {}", summary(&r));
    for p in &r[0].points {
        assert!(p.y.abs() <= GT, "{name}: {p} off the square");
        assert!(
            (p.y - band.lift(*p)).abs() <= GT,
            "{name}: {p} off the other"
        );
        assert!(
            to_polygon(*p, q) <= GT,
            "{name}: {p} off the band's outline"
        );
    }
    for i in 0..4 {
        let (a, b) = (q[i], q[(i + 1) % 4]);
        for f in [0.02, 0.5, 0.98] {
            let x = a.lerp(b, f);
            let near = |p: &&DVec3| p.distance(x) <= reach && to_segment(**p, a, b) <= GT;
            assert!(
                r[0].points.iter().any(|p| near(&p)),
                "{name}: side {i} at {f}"
            );
        }
    }
    let (length, want) = (r[0].length(), perimeter(q));
    assert!(
        (length - want).abs() <= 1e-6 * want,
        "{name}: length {length} vs {want}"
    );
    for _ in 0..2 {
        assert_eq!(run()[0].points, r[0].points, "{name}: another run");
    }
}

#[test]
fn a_narrow_flat_running_diagonally_across_the_unit_square() {
    // The flat, 0.02 wide along x, runs along (1, 0, 1) over the band c0 ≤ x − z ≤ c1: no grid
    // node (x − z a multiple of 1/32 or 1/16) and no sample (a multiple of 1/12) lies on it.
    // (On main before the walk: 7 short loops, one around each seed.)
    const C0: f64 = 0.035;
    const C1: f64 = 0.055;
    let prof = |z: f64| u_profile(C1 - C0, move |s, t| v(C0 + z + s, t, z), true);
    let strip = Surface::ruled(prof(-1.5), prof(2.5));
    let band = Band {
        outline: [
            v(C0, 0.0, 0.0),
            v(C1, 0.0, 0.0),
            v(1.0, 0.0, 1.0 - C1),
            v(1.0, 0.0, 1.0 - C0),
        ],
        flat: |z| (C0 + z, C1 + z),
    };
    check_both(&strip, &band);
    // The section by y = 0: the whole flat, from z = -1.5 to 2.5.
    let whole = Band {
        outline: [
            v(C0 - 1.5, 0.0, -1.5),
            v(C1 - 1.5, 0.0, -1.5),
            v(C1 + 2.5, 0.0, 2.5),
            v(C0 + 2.5, 0.0, 2.5),
        ],
        flat: band.flat,
    };
    check_section(&strip, &whole);
}

#[test]
fn a_narrow_flat_narrowing_across_the_unit_square() {
    // The flat runs along z over c0 ≤ x ≤ c0 + w(z), w falling linearly from 0.08 at z = 0 to
    // 0.02 at z = 1 (the ruled surface runs from z = −0.2 to 1.2). Its narrow end lies between
    // grid lines, its wide end between samples.
    const C0: f64 = 0.128;
    fn w(z: f64) -> f64 {
        0.08 - 0.06 * z
    }
    let prof = |z: f64| u_profile(w(z), move |s, t| v(C0 + s, t, z), true);
    let wedge = Surface::ruled(prof(-0.2), prof(1.2));
    let band = Band {
        outline: [
            v(C0, 0.0, 0.0),
            v(C0 + w(0.0), 0.0, 0.0),
            v(C0 + w(1.0), 0.0, 1.0),
            v(C0, 0.0, 1.0),
        ],
        flat: |z| (C0, C0 + w(z)),
    };
    check_both(&wedge, &band);
    // The section by y = 0: the whole flat, from z = -0.2 to 1.2.
    let whole = Band {
        outline: [
            v(C0, 0.0, -0.2),
            v(C0 + w(-0.2), 0.0, -0.2),
            v(C0 + w(1.2), 0.0, 1.2),
            v(C0, 0.0, 1.2),
        ],
        flat: band.flat,
    };
    check_section(&wedge, &whole);
}

/// The diagonal band of the first test on a square whose bottom edge is tilted (falling 0.1
/// along x) to cross z = 0, a grid line of the profile surface's domain (v = 12/32), at
/// x* = C0 − `behind`, just outside the band: the band's corner on that edge then lies about
/// 0.9·`behind` from that crossing, along the square's edge.
///
/// Open defects (issue 13, item 5 of the closing note of 2026-11-27; the same figures on
/// `c948918` and after the threshold change):
/// - behind = 1e-6, order (other, square): the crossing's gap is 2.5e-13, under the rounding
///   the tracer in the profile surface's domain tells from the region's own gap (1e-13 of its
///   size, 9.5e-13), so `edge::parting` says the surfaces do not part there and the corner is
///   not looked for: the loop has the crossing (0.0349990, 0, 0), 9.19e-7 from the corner,
///   and not the corner (its nearest point 9.19e-7 away); 1.5e-6 long. Fixed (second
///   round): `t` lay 2.1e-9 past the extent edge, so `parting` read no gap; and `slide`'s
///   reach along the extent edge was too short for its shallow crossing (1 in 10.5).
/// - behind = 3e-6, order (other, square): the gap there (2.25e-12) passes the rounding and
///   the corner is slid for, but a point came back 3.2e-5 off the outline and the loop was
///   4.6e-5 long. Fixed with the first (the slide's reach).
/// - Both, order (square, other), where the tilted square's parameter lines run oblique to
///   its sides: a point (0.99902, 0, 0.94402) 3.3e-8 outside the band's side x − z = C1,
///   1e-3 from the square's right edge (1.1e-9 with behind = 1e-3, where the other order
///   is right to GEOMTOL). Fixed (third round): the tilted square's points are bilinear in
///   (u, v), so along a straight search line in its parameters the distance from the band's
///   side is quadratic, not linear; the power law's zero, taken on the line through two
///   samples of √gap, was off by the bend (up to 4.3e-8 on lines turned away from the right
///   edge, 1.8e-8 across a densified chord). The zero is now taken on the parabola through
///   the three samples: 1.8e-10 off at most.
#[test]
fn a_region_corner_just_behind_where_a_grid_line_leaves_the_square_traced_in_the_strip() {
    corner_behind(false);
}

/// [`a_region_corner_just_behind_where_a_grid_line_leaves_the_square_traced_in_the_strip`]
/// in both orders (the order (square, other): see the doc comment above).
#[test]
fn a_region_corner_just_behind_where_a_grid_line_leaves_the_square() {
    corner_behind(true);
}

/// The band of the tests above on the tilted square, in the order (other, square) only, or
/// in `both` orders.
fn corner_behind(both: bool) {
    const C0: f64 = 0.035;
    const C1: f64 = 0.055;
    const M: f64 = -0.1;
    let prof = |z: f64| u_profile(C1 - C0, move |s, t| v(C0 + z + s, t, z), true);
    let strip = Surface::ruled(prof(-1.5), prof(2.5));
    let line = |a: DVec3, b: DVec3| Arc::new(Curve::line(a, b).unwrap());
    for behind in [1e-6, 3e-6] {
        let x_star = C0 - behind;
        let bottom = |x: f64| M * (x - x_star);
        let sq = Surface::ruled(
            line(v(0.0, 0.0, bottom(0.0)), v(1.0, 0.0, bottom(1.0))),
            line(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0)),
        );
        // Where the bottom edge z = M(x − x*) meets the band's side x − z = c.
        let corner = |c: f64| {
            let x = (c - M * x_star) / (1.0 - M);
            v(x, 0.0, x - c)
        };
        let band = Band {
            outline: [
                corner(C0),
                corner(C1),
                v(1.0, 0.0, 1.0 - C1),
                v(1.0, 0.0, 1.0 - C0),
            ],
            flat: |z| (C0 + z, C1 + z),
        };
        if both {
            check_both_with(&sq, &strip, &band);
        } else {
            let meet = || surface_intersect_tol(&strip, &sq, 1e-6, 1e-9).unwrap();
            check_loop("other, square", &meet, &band, 0.05);
        }
    }
}
