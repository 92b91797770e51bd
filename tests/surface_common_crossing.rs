//! Crossings beside a common region (issue 13) for pairs with no closed form, which go through
//! the meshes: two surfaces that coincide over a region and also cross elsewhere give the
//! region's boundary loop AND the crossing; a crossing that runs into the region ends on its
//! loop; a pair that only shares a region gives its loop and nothing else (no fragment of the
//! region's interior, where the two meshes cross all over).
//!
//! Every pair is run in both orders and three times (bit-identical). The references are closed
//! forms written out here: the carriers' implicit equations (the cylinder x² + y² = 1, the
//! planes z = 0 and 3x − 4y + 4 = 0, the hyperbolic paraboloids 6z = (y − 4)(0.7x − 3) and
//! 6z = (y − 4)(0.7x − 3.5)), the crossings' end points and the loops' and crossings' exact
//! lengths.

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_seeded, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_8, PI};
use std::sync::Arc;

const CT: f64 = 1e-6;
const GT: f64 = 1e-9;
/// The seeding meshes' tolerance: coarse meshes seed curves refined to GEOMTOL and densified
/// within CT (a twisted patch meshed within 1e-6 has tens of thousands of triangles).
const ST: f64 = 1e-3;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn line(a: DVec3, b: DVec3) -> Arc<Curve> {
    Arc::new(Curve::line(a, b).unwrap())
}

fn pline(points: Vec<DVec3>, bulges: Option<Vec<f64>>) -> Arc<Curve> {
    Arc::new(Curve::pline(points, false, bulges).unwrap())
}

/// What one pair must give: the loops (closed) and the crossings (open), by count and total
/// length; every point accepted by `on`; each crossing end at one of `ends`.
struct Expect<'a> {
    loops: usize,
    loop_length: f64,
    crossings: usize,
    crossing_length: f64,
    on: &'a dyn Fn(DVec3) -> bool,
    ends: &'a [DVec3],
    /// Crossing ends that must lie on a loop (a crossing running into the region).
    on_loop: &'a [DVec3],
}

fn seg_dist(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
    p.distance(a + d * t)
}

fn dist_to(p: DVec3, c: &Polyline3) -> f64 {
    let n = c.points.len();
    if n == 1 {
        return p.distance(c.points[0]);
    }
    let segs = if c.closed { n } else { n - 1 };
    (0..segs)
        .map(|k| seg_dist(p, c.points[k], c.points[(k + 1) % n]))
        .fold(f64::INFINITY, f64::min)
}

fn check(a: &Surface, b: &Surface, e: &Expect) {
    for (x, y) in [(a, b), (b, a)] {
        let r = surface_intersect_seeded(x, y, ST, CT, GT).unwrap();
        let (loops, crossings): (Vec<&Polyline3>, Vec<&Polyline3>) =
            r.iter().partition(|c| c.closed);
        let total = |cs: &[&Polyline3]| cs.iter().map(|c| c.length()).sum::<f64>();
        assert_eq!(loops.len(), e.loops, "loops: {r:?}");
        assert_eq!(
            crossings.len(),
            e.crossings,
            "crossings: {:?}",
            crossings
                .iter()
                .map(|c| (c.points.len(), c.points[0], c.points[c.points.len() - 1]))
                .collect::<Vec<_>>()
        );
        let (ll, cl) = (total(&loops), total(&crossings));
        assert!(
            (ll - e.loop_length).abs() <= 1e-6 * e.loop_length,
            "loop length {ll} vs {}",
            e.loop_length
        );
        assert!(
            (cl - e.crossing_length).abs() <= 1e-6 * e.crossing_length.max(1.0),
            "crossing length {cl} vs {}",
            e.crossing_length
        );
        for p in r.iter().flat_map(|c| &c.points) {
            assert!((e.on)(*p), "off the true surfaces: {p}");
        }
        for c in &crossings {
            for end in [c.points[0], c.points[c.points.len() - 1]] {
                let nearest = e
                    .ends
                    .iter()
                    .map(|q| q.distance(end))
                    .fold(f64::INFINITY, f64::min);
                // An end on a loop is where the loop is: where the fold leaves the plane at a
                // vanishing angle, the loop's side is only located to where the two are
                // GEOMTOL apart (about 1e-7 here).
                let into = e.on_loop.iter().any(|q| q.distance(end) <= 1e-6);
                let within = if into { 1e-6 } else { 1e-9 };
                assert!(
                    nearest <= within,
                    "crossing end {end}, {nearest} from the exact ends"
                );
                if into {
                    let d = loops
                        .iter()
                        .map(|l| dist_to(end, l))
                        .fold(f64::INFINITY, f64::min);
                    assert!(d <= 1e-9, "crossing end {end} is {d} from the loop");
                }
            }
        }
        for _ in 0..2 {
            let again = surface_intersect_seeded(x, y, ST, CT, GT).unwrap();
            assert_eq!(again.len(), r.len());
            assert!(again
                .iter()
                .zip(&r)
                .all(|(c, d)| c.points == d.points && c.closed == d.closed));
        }
    }
}

/// A half cylinder x² + y² = 1, y ≥ 0, z in [0, 3], as a ruled surface between two arcs.
fn half_cylinder() -> Surface {
    let arc =
        |z: f64| Arc::new(Curve::arc3(v(1.0, 0.0, z), v(0.0, 1.0, z), v(-1.0, 0.0, z)).unwrap());
    Surface::ruled(arc(0.0), arc(3.0))
}

/// Vertical rulings z in [0, 2] over a quarter circle of x² + y² = 1 from (1, 0) to (0, 1),
/// then, when `crossing`, over the segment (0, 1) → (−2, −0.5), which runs into the circle and
/// leaves it again at (−0.96, 0.28) (on the line 3x − 4y + 4 = 0).
fn bent_wall(crossing: bool) -> Surface {
    let base = |z: f64| {
        if crossing {
            pline(
                vec![v(1.0, 0.0, z), v(0.0, 1.0, z), v(-2.0, -0.5, z)],
                Some(vec![FRAC_PI_8.tan(), 0.0, 0.0]),
            )
        } else {
            pline(
                vec![v(1.0, 0.0, z), v(0.0, 1.0, z)],
                Some(vec![FRAC_PI_8.tan(), 0.0]),
            )
        }
    };
    Surface::ruled(base(0.0), base(2.0))
}

/// A point of the cylinder band or of the wall's flat part, within GEOMTOL of both surfaces of
/// the wall pairs: on x² + y² = 1, and on the quarter band's outline or the crossing ruling.
fn on_wall_pair(p: DVec3) -> bool {
    let on_cyl = ((p.x * p.x + p.y * p.y).sqrt() - 1.0).abs() <= GT;
    let z_ok = (-GT..=2.0 + GT).contains(&p.z);
    // The loop: the arcs at z = 0 and z = 2 (x, y ≥ 0), the rulings at (1, 0) and (0, 1).
    let on_loop = ((p.z.abs() <= GT || (p.z - 2.0).abs() <= GT) && p.x >= -GT && p.y >= -GT)
        || v(p.x, p.y, 0.0).distance(v(1.0, 0.0, 0.0)) <= GT
        || v(p.x, p.y, 0.0).distance(v(0.0, 1.0, 0.0)) <= GT;
    // The crossing: on the wall's plane too, at (−0.96, 0.28).
    let on_crossing = (3.0 * p.x - 4.0 * p.y + 4.0).abs() / 5.0 <= GT
        && v(p.x, p.y, 0.0).distance(v(-0.96, 0.28, 0.0)) <= 2.0 * GT;
    on_cyl && z_ok && (on_loop || on_crossing)
}

#[test]
fn two_ruled_walls_sharing_a_quarter_band_and_crossing_elsewhere_give_both() {
    // The band θ in [0, π/2], z in [0, 2]: two quarter arcs and two rulings. The crossing:
    // the ruling over (−0.96, 0.28), z in [0, 2].
    let ends = [v(-0.96, 0.28, 0.0), v(-0.96, 0.28, 2.0)];
    check(
        &half_cylinder(),
        &bent_wall(true),
        &Expect {
            loops: 1,
            loop_length: PI + 4.0,
            crossings: 1,
            crossing_length: 2.0,
            on: &on_wall_pair,
            ends: &ends,
            on_loop: &[],
        },
    );
}

#[test]
fn a_ruled_wall_against_a_true_cylinder_gives_the_band_and_the_crossing() {
    // The whole cylinder x² + y² = 1, z in [−1, 3]: the wall's line enters it at (0, 1), on
    // the band's ruling, and leaves it at (−0.96, 0.28).
    let cyl = Surface::cylinder(v(0.0, 0.0, -1.0), DVec3::Z, 1.0, 4.0).unwrap();
    let ends = [v(-0.96, 0.28, 0.0), v(-0.96, 0.28, 2.0)];
    check(
        &cyl,
        &bent_wall(true),
        &Expect {
            loops: 1,
            loop_length: PI + 4.0,
            crossings: 1,
            crossing_length: 2.0,
            on: &on_wall_pair,
            ends: &ends,
            on_loop: &[],
        },
    );
}

/// A fold of the square [0, 10]²: the plane z = 0 for y ≤ 4, and beyond y = 4 the ruled surface
/// (rulings along x between two folded lines) whose far edge y = 10 runs from height `h0` at
/// x = 0 to `h1` at x = 10: the hyperbolic paraboloid 6z = (y − 4)(h0 + (h1 − h0)x/10). Unless
/// h0 = h1 it crosses z = 0 along the line x = −10·h0/(h1 − h0), which runs into the flat part
/// at y = 4.
struct Fold {
    h0: f64,
    h1: f64,
}

/// The fold crossing z = 0 along x = 30/7.
const CROSSING: Fold = Fold { h0: -3.0, h1: 4.0 };

impl Fold {
    fn surface(&self) -> Surface {
        Surface::ruled(
            pline(
                vec![v(0.0, 0.0, 0.0), v(0.0, 4.0, 0.0), v(0.0, 10.0, self.h0)],
                None,
            ),
            pline(
                vec![v(10.0, 0.0, 0.0), v(10.0, 4.0, 0.0), v(10.0, 10.0, self.h1)],
                None,
            ),
        )
    }

    /// Where the fold crosses z = 0 (when it does).
    fn x0(&self) -> f64 {
        -10.0 * self.h0 / (self.h1 - self.h0)
    }

    /// A point within GEOMTOL of both z = 0 and the fold, on the rectangle's outline or on the
    /// crossing. Where the fold leaves the plane at a small angle, its loop side and the
    /// crossing's end are only defined to where the two are GEOMTOL apart, hence the looser
    /// place checks.
    fn on_pair(&self, p: DVec3) -> bool {
        let k = (self.h1 - self.h0) / 10.0;
        // The paraboloid f = 6z − (y − 4)(h0 + kx) = 0: distance |f| / |∇f|.
        let f = 6.0 * p.z - (p.y - 4.0) * (self.h0 + k * p.x);
        let grad = v(-k * (p.y - 4.0), -(self.h0 + k * p.x), 6.0).length();
        let on_fold = if p.y <= 4.0 {
            p.z.abs()
        } else {
            f.abs() / grad
        } <= GT;
        let on_both = p.z.abs() <= GT && on_fold;
        let in_square = (-GT..=10.0 + GT).contains(&p.x) && (-GT..=10.0 + GT).contains(&p.y);
        let on_rect = p.y <= 4.0 + 1e-6
            && (p.x.abs() <= GT
                || (p.x - 10.0).abs() <= GT
                || p.y.abs() <= GT
                || (p.y - 4.0).abs() <= 1e-6);
        let crosses = self.h0 != self.h1;
        let on_crossing = crosses && (p.x - self.x0()).abs() <= 1e-6 && p.y >= 4.0 - GT;
        on_both && in_square && (on_rect || on_crossing)
    }
}

fn flat_square() -> Surface {
    Surface::ruled(
        line(v(0.0, 0.0, 0.0), v(10.0, 0.0, 0.0)),
        line(v(0.0, 10.0, 0.0), v(10.0, 10.0, 0.0)),
    )
}

fn flat_plane() -> Surface {
    Surface::plane(vec![
        v(0.0, 0.0, 0.0),
        v(10.0, 0.0, 0.0),
        v(10.0, 10.0, 0.0),
        v(0.0, 10.0, 0.0),
    ])
    .unwrap()
}

/// The fold against the flat square (ruled) and against the plane region: the rectangle
/// [0, 10] × [0, 4] (length 28) and the crossing from the square's far edge y = 10 to the
/// rectangle's side y = 4 (length 6), which ends on the loop.
fn check_fold_crossing(fold: &Fold) {
    let x0 = fold.x0();
    let ends = [v(x0, 4.0, 0.0), v(x0, 10.0, 0.0)];
    let on = |p: DVec3| fold.on_pair(p);
    let e = Expect {
        loops: 1,
        loop_length: 28.0,
        crossings: 1,
        crossing_length: 6.0,
        on: &on,
        ends: &ends,
        on_loop: &[v(x0, 4.0, 0.0)],
    };
    check(&flat_square(), &fold.surface(), &e);
    // Against a planar region: no closed form for a ruled surface and a plane.
    check(&flat_plane(), &fold.surface(), &e);
}

#[test]
fn a_crossing_running_into_the_common_region_ends_on_its_loop() {
    check_fold_crossing(&CROSSING);
}

#[test]
fn a_crossing_along_a_grid_line_of_the_region_trace_leaves_the_loop_without_a_spike() {
    // The crossing x = 5 runs along the middle grid line of both ruled squares' domains (x is
    // 10 times a parameter of each, traced on a 32-cell grid), so grid nodes beyond the region
    // lie on both surfaces: a bisection along that line from inside the region must not take
    // them for the region (a spike out to the next node, 0.375 long, then back).
    let fold = Fold { h0: -3.5, h1: 3.5 };
    assert_eq!(fold.x0(), 5.0);
    check_fold_crossing(&fold);
}

#[test]
fn pairs_sharing_only_a_region_give_its_loop_and_nothing_else() {
    // The quarter band alone against the half cylinder, and against the true cylinder.
    let e = Expect {
        loops: 1,
        loop_length: PI + 4.0,
        crossings: 0,
        crossing_length: 0.0,
        on: &on_wall_pair,
        ends: &[],
        on_loop: &[],
    };
    check(&half_cylinder(), &bent_wall(false), &e);
    let cyl = Surface::cylinder(v(0.0, 0.0, -1.0), DVec3::Z, 1.0, 4.0).unwrap();
    check(&cyl, &bent_wall(false), &e);
    // The square folded upward beyond y = 4 leaves the plane along the fold and never comes
    // back: the rectangle alone.
    let fold = Fold { h0: 3.0, h1: 3.0 };
    let on = |p: DVec3| fold.on_pair(p);
    let e = Expect {
        loops: 1,
        loop_length: 28.0,
        crossings: 0,
        crossing_length: 0.0,
        on: &on,
        ends: &[],
        on_loop: &[],
    };
    check(&flat_square(), &fold.surface(), &e);
}
