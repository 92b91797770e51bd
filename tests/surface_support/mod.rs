//! What the surface-intersection tests share: the cylinders built through the mesh-path kinds,
//! a one-line summary of a result for assertion messages, `lispcad eval` of one expression, and
//! the check that two surfaces'
//! common region comes back as the expected closed loops, the same bits on every run, and the
//! narrow-flat profile of the common-region tests, with the distance to a strip ruled on one.
#![allow(dead_code)] // each test file uses its own part of this module

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{
    surface_intersect_seeded, surface_intersect_tol, surface_meet, surface_section_seeded,
    surface_section_tol, Meet, Surface,
};
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_3, PI, TAU};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::process::Command;
use std::sync::Arc;

/// Three cylinders of radius 1 about the x axis through (0, 0, 1), from x = 0 to 4, built
/// through the mesh-path kinds: ruled between two circles, a circle swept along a line, a line
/// revolved about the axis.
pub fn cylinders() -> Vec<(&'static str, Surface)> {
    let c = DVec3::new(0.0, 0.0, 1.0);
    let c0 = Curve::circle(c, 1.0, Some(DVec3::X)).unwrap();
    let c1 = Curve::circle(c + DVec3::X * 4.0, 1.0, Some(DVec3::X)).unwrap();
    let guide = Curve::line(c, c + DVec3::X * 4.0).unwrap();
    let prof = Curve::line(DVec3::new(0.0, 1.0, 1.0), DVec3::new(4.0, 1.0, 1.0)).unwrap();
    vec![
        ("ruled", Surface::ruled(Arc::new(c0.clone()), Arc::new(c1))),
        (
            "sweep",
            Surface::sweep(Arc::new(c0), Arc::new(guide)).unwrap(),
        ),
        (
            "revolve",
            Surface::revolve(Arc::new(prof), c, DVec3::X, 2.0 * PI).unwrap(),
        ),
    ]
}

/// Each curve's point count, closure, length and ends, for assertion messages.
pub fn summary(r: &[Polyline3]) -> String {
    r.iter()
        .map(|c| {
            format!(
                "[{} pts{} len {:.12} {:?}..{:?}]",
                c.points.len(),
                if c.closed { " closed" } else { "" },
                c.length(),
                c.points.first(),
                c.points.last()
            )
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Both orders of `meet`: `loops` closed loops of total length `length` (to 1e-6 relative),
/// every point accepted by `on`, and two more runs giving the same bits. Returns each order's
/// result for further checks.
pub fn check_loops(
    meet: impl Fn(&Surface, &Surface) -> Vec<Polyline3>,
    a: &Surface,
    b: &Surface,
    loops: usize,
    length: f64,
    on: impl Fn(DVec3) -> bool,
) -> Vec<Vec<Polyline3>> {
    [(a, b), (b, a)]
        .into_iter()
        .map(|(x, y)| check_order(&meet, x, y, loops, length, &on))
        .collect()
}

/// [`check_loops`] of `meet(x, y)` in that order only.
pub fn check_order(
    meet: impl Fn(&Surface, &Surface) -> Vec<Polyline3>,
    x: &Surface,
    y: &Surface,
    loops: usize,
    length: f64,
    on: impl Fn(DVec3) -> bool,
) -> Vec<Polyline3> {
    let r = meet(x, y);
    assert_eq!(r.len(), loops, "{}", summary(&r));
    assert!(r.iter().all(|c| c.closed), "{}", summary(&r));
    let total: f64 = r.iter().map(Polyline3::length).sum();
    assert!(
        (total - length).abs() <= 1e-6 * length,
        "length {total} vs {length}"
    );
    for p in r.iter().flat_map(|c| &c.points) {
        assert!(on(*p), "{p}");
    }
    for _ in 0..2 {
        let again = meet(x, y);
        assert!(again.len() == r.len());
        assert!(again.iter().zip(&r).all(|(c, d)| c.points == d.points));
    }
    r
}

/// The intersection at CHORDTOL 1e-6 and GEOMTOL 1e-9.
fn meet_fine(x: &Surface, y: &Surface) -> Vec<Polyline3> {
    surface_intersect_tol(x, y, 1e-6, 1e-9).unwrap()
}

/// Whether each edge in `reach` is met by some point of `r`.
fn reaches(r: &[Polyline3], reach: &[&dyn Fn(DVec3) -> bool]) {
    for (k, e) in reach.iter().enumerate() {
        assert!(r.iter().flat_map(|c| &c.points).any(|p| e(*p)), "edge {k}");
    }
}

/// `check_loops` of `surface_intersect_tol` at CHORDTOL 1e-6 and GEOMTOL 1e-9, and each edge in
/// `reach` met by some point of each order's result.
pub fn check_loops_reaching(
    a: &Surface,
    b: &Surface,
    loops: usize,
    length: f64,
    on: impl Fn(DVec3) -> bool,
    reach: &[&dyn Fn(DVec3) -> bool],
) {
    for r in check_loops(meet_fine, a, b, loops, length, on) {
        reaches(&r, reach);
    }
}

/// [`check_loops_reaching`] in the order (a, b) only.
pub fn check_order_reaching(
    a: &Surface,
    b: &Surface,
    loops: usize,
    length: f64,
    on: impl Fn(DVec3) -> bool,
    reach: &[&dyn Fn(DVec3) -> bool],
) {
    reaches(&check_order(meet_fine, a, b, loops, length, on), reach);
}

/// What `lispcad eval EXPR` prints, trimmed; the command must succeed.
pub fn eval(expr: &str) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_lispcad"))
        .args(["eval", expr])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap().trim().to_string()
}

/// The arcs' radius.
pub const R: f64 = 2.0;
/// Arc segments before and after the flat (161 segments in all: the flat is 1/161 of the
/// parameter range).
pub const M1: usize = 70;
pub const M2: usize = 90;

/// A profile in local coordinates (s along the flat, t away from it): an arc of radius R
/// through π/3 in `M1` segments down to (0, 0), the flat to (w, 0), an arc through π/3 in `M2`
/// segments up again; both arcs are tangent to the flat and bend towards +t. `place` maps
/// (s, t) to space; `ccw` says whether that map keeps the arcs counter-clockwise.
pub fn u_profile(w: f64, place: impl Fn(f64, f64) -> DVec3, ccw: bool) -> Arc<Curve> {
    let (d1, d2) = (FRAC_PI_3 / M1 as f64, FRAC_PI_3 / M2 as f64);
    let mut pts = Vec::new();
    for k in (0..=M1).rev() {
        let f = k as f64 * d1;
        pts.push(place(-R * f.sin(), R - R * f.cos()));
    }
    for k in 0..=M2 {
        let f = k as f64 * d2;
        pts.push(place(w + R * f.sin(), R - R * f.cos()));
    }
    let sign = if ccw { 1.0 } else { -1.0 };
    let mut bulges = vec![sign * (d1 / 4.0).tan(); M1];
    bulges.push(0.0);
    bulges.extend(vec![sign * (d2 / 4.0).tan(); M2]);
    Arc::new(Curve::pline(pts, false, Some(bulges)).unwrap())
}

/// The unit square y = 0, 0 ≤ x, z ≤ 1, as a ruled surface (u = x, v = z).
pub fn unit_square() -> Surface {
    let line = |a: DVec3, b: DVec3| Arc::new(Curve::line(a, b).unwrap());
    let v = DVec3::new;
    Surface::ruled(
        line(v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0)),
        line(v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0)),
    )
}

/// One way of asking for the intersection.
pub type Run<'a> = Box<dyn Fn() -> Vec<Polyline3> + 'a>;

/// The three ways of asking for where `s` meets the plate z = 0: the section of `s` by the
/// plane z = 0, `s` ∩ `plate` and `plate` ∩ `s`, named with `s`'s `name`; the seeding meshes
/// made within `seed`, the curves densified within `chord`, at GEOMTOL.
pub fn section_and_both_orders<'a>(
    name: &str,
    s: &'a Surface,
    plate: &'a Surface,
    seed: f64,
    chord: f64,
) -> [(String, Run<'a>); 3] {
    [
        (
            "section".to_string(),
            Box::new(move || {
                surface_section_seeded(s, DVec3::ZERO, DVec3::Z, seed, chord, 1e-9).unwrap()
            }),
        ),
        (
            format!("{name} ∩ plate"),
            Box::new(move || surface_intersect_seeded(s, plate, seed, chord, 1e-9).unwrap()),
        ),
        (
            format!("plate ∩ {name}"),
            Box::new(move || surface_intersect_seeded(plate, s, seed, chord, 1e-9).unwrap()),
        ),
    ]
}

/// Every run of [`section_and_both_orders`] against the plate −1 ≤ x ≤ 5, −2 ≤ y ≤ 2 at z = 0,
/// seeds 1e-2 and 1e-3, curves densified within 1e-6: each result handed to `check` with its
/// run's name, then run again and required to be the same bits.
pub fn each_run_against_the_plate(name: &str, s: &Surface, check: impl Fn(&str, &[Polyline3])) {
    let plate = Surface::plane(vec![
        DVec3::new(-1.0, -2.0, 0.0),
        DVec3::new(5.0, -2.0, 0.0),
        DVec3::new(5.0, 2.0, 0.0),
        DVec3::new(-1.0, 2.0, 0.0),
    ])
    .unwrap();
    for seed in [1e-2, 1e-3] {
        for (run_name, run) in section_and_both_orders(name, s, &plate, seed, 1e-6) {
            let run_name = format!("{run_name} seed {seed}");
            let r = run();
            check(&run_name, &r);
            assert_same_bits(&run_name, &run(), &r);
        }
    }
}

/// That a second run of an intersection gave the same curves, bit for bit.
pub fn assert_same_bits(name: &str, again: &[Polyline3], first: &[Polyline3]) {
    assert_eq!(again.len(), first.len(), "{name}: {}", summary(again));
    assert!(
        again
            .iter()
            .zip(first)
            .all(|(c, e)| c.points == e.points && c.closed == e.closed),
        "{name}: a second run differs"
    );
}

/// The distance from `p` to the strip ruled between `profile` (in x and y) at z = 0 and z = 3:
/// in plan to the polyline, infinite beyond those heights by more than GEOMTOL.
pub fn off_strip(p: DVec3, profile: &[DVec3]) -> f64 {
    if !(-1e-9..=3.0 + 1e-9).contains(&p.z) {
        return f64::INFINITY;
    }
    profile
        .windows(2)
        .map(|s| {
            let (a, b) = (s[0], s[1]);
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let t = (((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
            (p.x - a.x - t * dx).hypot(p.y - a.y - t * dy)
        })
        .fold(f64::INFINITY, f64::min)
}

/// That the midpoint of every chord of `curves` (closing chords included) is within `within` of
/// both surfaces, `off` giving its distance to the farther: a polyline densified within CHORDTOL
/// of a curve on both surfaces is, and a chord cut across something the seeds missed is not.
pub fn assert_chords_on(name: &str, curves: &[Polyline3], off: impl Fn(DVec3) -> f64, within: f64) {
    for (i, c) in curves.iter().enumerate() {
        let n = c.points.len();
        let segs = if c.closed { n } else { n.saturating_sub(1) };
        for k in 0..segs {
            let (p, q) = (c.points[k], c.points[(k + 1) % n]);
            let d = off(0.5 * (p + q));
            assert!(
                d <= within,
                "{name}: curve {i} chord {k} {p}..{q}: midpoint {d:e} off"
            );
        }
    }
}

/// That each of `curves` has a point within `within` of `at`: where a crossing meets a contact,
/// both pass through the branch point, not merely near their chords.
pub fn assert_meet_at(name: &str, curves: &[&Polyline3], at: DVec3, within: f64) {
    for c in curves {
        let off = c
            .points
            .iter()
            .map(|p| p.distance(at))
            .fold(f64::INFINITY, f64::min);
        assert!(off <= within, "{name}: {off:e} from the branch point {at}");
    }
}

/// CHORDTOLs a user may set, coarse to fine (the default is 0.01), spaced unevenly so that the
/// seeding meshes' vertices fall differently on the curves: at the user level the seeding
/// tolerance IS CHORDTOL, so every closed-form case must hold at each of them.
pub const CHORDTOLS: [f64; 16] = [
    0.05, 0.03, 0.02, 0.015, 0.012, 0.01, 0.008, 0.007, 0.005, 0.004, 0.003, 0.002, 0.0015, 0.001,
    7e-4, 5e-4,
];

/// One way a user asks where surfaces meet, as the builtins do it.
pub enum Ask<'a> {
    /// `(surface-intersect a b)`: [`surface_meet`]; coinciding everywhere is a failure here.
    Meet(&'a Surface, &'a Surface),
    /// `(surface-section s point normal)`: [`surface_section_tol`].
    Section(&'a Surface, DVec3, DVec3),
}

impl Ask<'_> {
    /// The curves at CHORDTOL `chordtol` and GEOMTOL 1e-9.
    pub fn at(&self, chordtol: f64) -> Vec<Polyline3> {
        match *self {
            Ask::Meet(a, b) => match surface_meet(a, b, chordtol, 1e-9).unwrap() {
                Meet::Curves(c) => c,
                Meet::Everywhere => panic!("the surfaces coincide everywhere"),
            },
            Ask::Section(s, p, n) => surface_section_tol(s, p, n, chordtol, 1e-9).unwrap(),
        }
    }
}

/// Both orders of `(surface-intersect a b)`, named "`a`, `b`" and "`b`, `a`".
pub fn both_orders<'a>(
    (na, a): (&str, &'a Surface),
    (nb, b): (&str, &'a Surface),
) -> Vec<(String, Ask<'a>)> {
    vec![
        (format!("{na}, {nb}"), Ask::Meet(a, b)),
        (format!("{nb}, {na}"), Ask::Meet(b, a)),
    ]
}

/// Every ask at every CHORDTOL of `tols`, each result handed to `check(name, chordtol, curves)`
/// (which asserts). All cases are run; the test then fails listing every (ask, CHORDTOL) that
/// failed and why, so that one run shows the whole pattern of a defect.
pub fn at_chordtols(asks: &[(String, Ask)], tols: &[f64], check: impl Fn(&str, f64, &[Polyline3])) {
    let failed = failures(asks, tols, check);
    assert!(
        failed.is_empty(),
        "{} of {} failed:\n{}",
        failed.len(),
        asks.len() * tols.len(),
        failed.join("\n")
    );
}

/// What [`at_chordtols`] asserts: why each (ask, CHORDTOL) whose check panicked failed.
pub fn failures(
    asks: &[(String, Ask)],
    tols: &[f64],
    check: impl Fn(&str, f64, &[Polyline3]),
) -> Vec<String> {
    let mut failed = Vec::new();
    for &t in tols {
        for (name, ask) in asks {
            let name = format!("{name} at CHORDTOL {t}");
            let run = catch_unwind(AssertUnwindSafe(|| check(&name, t, &ask.at(t))));
            if let Err(e) = run {
                let why = e
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                failed.push(why);
            }
        }
    }
    failed
}

/// That `curves` cover the true curve sampled as `samples`: each sample within `within` of
/// some chord (a polyline densified within CHORDTOL of the curve lies within CHORDTOL of it
/// everywhere; a piece missing or cut short leaves samples far from every chord).
pub fn assert_covers(name: &str, curves: &[Polyline3], samples: &[DVec3], within: f64) {
    for s in samples {
        let d = curves
            .iter()
            .map(|c| distance_to_polyline(*s, c))
            .fold(f64::INFINITY, f64::min);
        assert!(d <= within, "{name}: {s} is {d:e} from every curve");
    }
}

/// The distance from `p` to the chords of `c` (closing chord included), or to its one point.
pub fn distance_to_polyline(p: DVec3, c: &Polyline3) -> f64 {
    let n = c.points.len();
    if n == 1 {
        return p.distance(c.points[0]);
    }
    let segs = if c.closed { n } else { n - 1 };
    (0..segs)
        .map(|k| {
            let (a, b) = (c.points[k], c.points[(k + 1) % n]);
            let ab = b - a;
            let t = if ab.length_squared() > 0.0 {
                ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            p.distance(a + ab * t)
        })
        .fold(f64::INFINITY, f64::min)
}

/// `n + 1` points of the curve `f` at evenly spaced parameters from `t0` to `t1`.
pub fn samples(f: impl Fn(f64) -> DVec3, (t0, t1): (f64, f64), n: usize) -> Vec<DVec3> {
    (0..=n)
        .map(|i| f(t0 + (t1 - t0) * i as f64 / n as f64))
        .collect()
}

/// The length of the curve `f` from `t0` to `t1`: chord sums on 100 000 and 200 000 steps
/// extrapolated (Richardson; their error is O(h²), so the result's is O(h⁴), far below 1e-9 on
/// a smooth curve).
pub fn curve_length(f: impl Fn(f64) -> DVec3, span: (f64, f64)) -> f64 {
    let chords = |n: usize| -> f64 {
        samples(&f, span, n)
            .windows(2)
            .map(|w| w[0].distance(w[1]))
            .sum()
    };
    let (coarse, fine) = (chords(100_000), chords(200_000));
    fine + (fine - coarse) / 3.0
}

/// That a polyline inscribed in a curve of length `exact` whose curvature is at most `kappa`,
/// its chords within CHORDTOL `t` of the curve, has the length `l`: not longer (but for its
/// points lying up to GEOMTOL off the curve), and short by at most what the chords' sag allows
/// (a chord of sag s on a curvature κ is short by about s·κ/3 of its length; half again for
/// the curvature varying along a chord).
pub fn assert_inscribed_length(name: &str, l: f64, exact: f64, (t, kappa): (f64, f64)) {
    assert!(
        l <= exact + 1e-8 && exact - l <= 0.5 * t * kappa * exact + 1e-8,
        "{name}: length {l} vs {exact}"
    );
}

/// Perimeter of the ellipse with semi-axes a, b by the midpoint rule on 200 000 steps (its error,
/// O(h²) on a smooth periodic integrand — in fact spectral — is far below 1e-9).
pub fn ellipse_perimeter(a: f64, b: f64) -> f64 {
    let n = 200_000;
    (0..n)
        .map(|i| {
            let t = TAU * (i as f64 + 0.5) / n as f64;
            (a * a * t.sin().powi(2) + b * b * t.cos().powi(2)).sqrt()
        })
        .sum::<f64>()
        * TAU
        / n as f64
}

/// The cone z = 2ρ with its apex at the origin, up to z = 4 (ρ in [0, 2]).
pub fn cone() -> Surface {
    Surface::revolve(
        Arc::new(Curve::line(DVec3::ZERO, DVec3::new(2.0, 0.0, 4.0)).unwrap()),
        DVec3::ZERO,
        DVec3::Z,
        TAU,
    )
    .unwrap()
}

/// The quarter cylinder ρ = 5, x, y ≥ 0, |z| ≤ 2 as a Coons patch of two arcs and two lines.
pub fn quarter_cylinder_patch() -> Surface {
    let arc = |z: f64| {
        Arc::new(Curve::arc(DVec3::new(0.0, 0.0, z), 5.0, 0.0, PI / 2.0, None).unwrap())
            as lispcad::geom::surface::CurveRef
    };
    let line = |a: [f64; 3], b: [f64; 3]| {
        Arc::new(Curve::line(DVec3::from_array(a), DVec3::from_array(b)).unwrap())
            as lispcad::geom::surface::CurveRef
    };
    Surface::boundary([
        arc(-2.0),
        line([0.0, 5.0, -2.0], [0.0, 5.0, 2.0]),
        arc(2.0),
        line([5.0, 0.0, 2.0], [5.0, 0.0, -2.0]),
    ])
    .unwrap()
}

/// The square of side 40 about the origin in the plane through it with normal `n`.
pub fn square_across(n: DVec3) -> Surface {
    let (x, y) = n.normalize().any_orthonormal_pair();
    Surface::plane(vec![
        (-x - y) * 20.0,
        (x - y) * 20.0,
        (x + y) * 20.0,
        (y - x) * 20.0,
    ])
    .unwrap()
}
