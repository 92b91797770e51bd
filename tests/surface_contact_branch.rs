//! Branch points on a curved tangent contact (issue 13): a crossing running into and through a
//! contact that is a circle's arc, where the surface_contact_crossing sheet's contact is a line.
//!
//! The surface is a Coons patch over the quarter annulus 1 ≤ r ≤ 3, 0 ≤ θ ≤ π/2, bounded by
//! two radial profiles and two arcs: z = w²(d(θ)(1 − w²) − w) with w = r − 2 and d linear in θ.
//! Each radial profile is that quartic in w for its d, one Bézier span of degree 4 with control
//! points evenly spaced in r (so r is linear in the parameter and z is exactly the quartic); the
//! arcs lie at z = 1 (r = 1) and z = −1 (r = 3) whatever d, and the patch's blend of the four is
//! then exactly r = 1 + 2u, θ = (π/2)·v, z as above (the z of the radial profiles is linear in d).
//! Against the plane z = 0: a contact along the arc r = 2 (w = 0 a double root, the patch
//! parallel to the plane there) of length π, and a crossing along w = W(d) = 2d/(1 + √(1 + 4d²)),
//! the root of d(1 − w²) = w, passing through the contact where d = 0: a branch point, the gap
//! across a triple root (−w³).

use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_seeded, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::Arc;

mod surface_support;
use surface_support::{
    assert_chords_on, assert_meet_at, assert_same_bits, section_and_both_orders, summary,
};

/// The product of two polynomials (coefficients from the constant term up).
fn times(p: &[f64], q: &[f64]) -> Vec<f64> {
    let mut r = vec![0.0; p.len() + q.len() - 1];
    for (i, a) in p.iter().enumerate() {
        for (j, b) in q.iter().enumerate() {
            r[i + j] += a * b;
        }
    }
    r
}

/// The radial profile at angle `th` for `d`: z(w) = k·w + d·w² − d·w⁴ − w³ with w = 2u − 1, from
/// its power coefficients in u to Bernstein ones, b_i = Σ_{j ≤ i} C(i, j)/C(4, j)·a_j.
fn profile(d: f64, th: f64, k: f64) -> Curve {
    let w = [-1.0, 2.0];
    let w2 = times(&w, &w);
    let w3 = times(&w2, &w);
    let w4 = times(&w3, &w);
    let a: Vec<f64> = (0..5)
        .map(|j| {
            k * w.get(j).unwrap_or(&0.0) + d * w2.get(j).unwrap_or(&0.0)
                - d * w4[j]
                - w3.get(j).unwrap_or(&0.0)
        })
        .collect();
    let choose = |n: usize, k: usize| (0..k).fold(1.0, |c, m| c * (n - m) as f64 / (m + 1) as f64);
    let ctrl: Vec<DVec3> = (0..5)
        .map(|i| {
            let b: f64 = (0..=i).map(|j| choose(i, j) / choose(4, j) * a[j]).sum();
            let r = 1.0 + 2.0 * i as f64 / 4.0;
            DVec3::new(r * th.cos(), r * th.sin(), b)
        })
        .collect();
    Curve::bspline(ctrl, 4, None, None).unwrap()
}

/// The patch for d running from `d0` at θ = 0 to `d1` at θ = π/2.
fn patch(d0: f64, d1: f64) -> Surface {
    sloped_patch(d0, d1, 0.0)
}

/// [`patch`] with k·w added to its height: it then touches and crosses the cone z = k·w (the
/// line from (1, 0, −k) to (3, 0, k) revolved about z) where the flat patch meets z = 0.
fn sloped_patch(d0: f64, d1: f64, k: f64) -> Surface {
    let arc = |r: f64, z: f64| {
        Arc::new(Curve::arc(DVec3::new(0.0, 0.0, z), r, 0.0, FRAC_PI_2, Some(DVec3::Z)).unwrap())
    };
    Surface::boundary([
        Arc::new(profile(d0, 0.0, k)),
        arc(3.0, k - 1.0),
        Arc::new(profile(d1, FRAC_PI_2, k)),
        arc(1.0, 1.0 - k),
    ])
    .unwrap()
}

/// The crossing's w for `d`.
fn root(d: f64) -> f64 {
    2.0 * d / (1.0 + (1.0 + 4.0 * d * d).sqrt())
}

/// The length of the crossing r = 2 + W(d(θ)), z = k·W over [0, π/2]: ∫ √(r² + (1 + k²)·r′²) dθ
/// by composite Simpson on 4096 panels (the integrand is smooth; error far under 1e-9).
fn crossing_length(d0: f64, d1: f64, k: f64) -> f64 {
    let dd = (d1 - d0) / FRAC_PI_2;
    let f = |th: f64| {
        let d = d0 + dd * th;
        let w = root(d);
        // From d(1 − w²) = w: w′(d) = (1 − w²)/(1 + 2dw).
        let dr = (1.0 - w * w) / (1.0 + 2.0 * d * w) * dd;
        let r = 2.0 + w;
        (r * r + (1.0 + k * k) * dr * dr).sqrt()
    };
    let n = 4096;
    let h = FRAC_PI_2 / n as f64;
    let mut s = f(0.0) + f(FRAC_PI_2);
    for k in 1..n {
        s += f(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

/// The contact and the crossing of [`patch`]`(d0, d1)` with z = 0: two open curves from θ = 0 to
/// θ = π/2 (to 1e-9), the contact on r = 2 and the crossing on r = 2 + W(d(θ)) (to
/// [`on_contact`] and [`on_crossing`]), both with a point within `meet` of the branch point r = 2, d(θ) = 0 where
/// they meet (a point within 1e-9 of both surfaces near it could be ∛1e-9 off either; it is
/// solved there), lengths π and the quadrature's to 1e-6, every point within 1e-9 of the plane
/// and of the patch (its height difference times the cosine of the patch's slope).
fn check(name: &str, r: &[Polyline3], (d0, d1): (f64, f64), meet: f64) {
    check_sloped(name, r, (d0, d1), 0.0, meet);
}

/// How near the branch point both curves come (and how far from the closed form either may be
/// there): it is solved where the gap's Hessian vanishes (inside the patch: 8.9e-10 the most
/// seen, patch ∩ cone), or, on the patch's edge θ = 0 or π/2, where the gap's second derivative
/// along that edge does (4.5e-11 seen from the patch's parameters; 6.0e-13 from the plate's,
/// the gap then taken along the patch's edge from the patch to the plate).
const MEET: f64 = 2e-9;

/// How far a crossing point may be from the closed form (its distance in space to the curve,
/// [`off_curve`]) where the crossing is W from the contact: 1e-9 (GEOMTOL) where W ≥ 1e-3, nearer the branch point the rounding of the gap
/// (about 4e-16 here) over its slope across the crossing (W², the gap across being
/// w²(d(1 − w²) − w)) with a margin of 5: where the surfaces part more slowly than that no
/// computation tells the crossing's point, nor ever farther than W/4 (the contact's side).
/// Seen: up to 1.3e-6 at W = 1.8e-5 (0.14e-3 from the branch point), 1.3e-7 at W = 5.7e-5;
/// on c948918, 3.3e-5 at W = 5.3e-4 and 5e-8 where W > 3e-2 (points whose gap came within
/// 0.01·tol were taken for the crossing's, however flat the gap across it).
fn on_crossing(w: f64) -> f64 {
    (2e-15 / (w * w)).min(0.25 * w.abs()).max(1e-9)
}

/// How far a contact point may be from r = 2: 2e-8 (seen: 1.83e-8 at the contact's ends on the
/// patch's edges, traced from the plate's parameters; 5.5e-9 elsewhere away from the branch
/// point), nearer the branch point 2e-11/W (the gap across the contact, d·w², flattens with d,
/// about W: seen 8.1e-8 at W = 9.8e-5, patch ∩ cone), never farther than W/4.
fn on_contact(w: f64) -> f64 {
    (2e-11 / w.abs()).min(0.25 * w.abs()).max(2e-8)
}

/// [`check`] for [`sloped_patch`] against the cone z = k·w (the plane z = 0 for k = 0): the
/// distance to the cone is |z − k·w|·cos(atan k) (the cone is straight along its generators, and
/// a point's nearest on it lies in its meridian plane).
fn check_sloped(name: &str, r: &[Polyline3], d: (f64, f64), k: f64, meet: f64) {
    check_sloped_within(name, r, d, k, meet, 1e-6);
}

/// [`check_sloped`] for curves densified within `chord`: chords within `chord` + 1e-9 of both
/// surfaces, and lengths to 1e-6 over the closed form's but, where `chord` is above 1e-6, up
/// to its length·`chord`/3 under it (a chord whose middle is h from a curve of curvature κ
/// is shorter than its arc by about κ·h/3 of it, and κ ≤ 1 here: the contact's 1/2, the
/// crossing's near it).
fn check_sloped_within(
    name: &str,
    r: &[Polyline3],
    (d0, d1): (f64, f64),
    k: f64,
    meet: f64,
    chord: f64,
) {
    assert_eq!(r.len(), 2, "{name}: {}", summary(r));
    let d = |th: f64| d0 + (d1 - d0) * th / FRAC_PI_2;
    let polar = |p: &DVec3| (p.x.hypot(p.y), p.y.atan2(p.x));
    let contact = r.iter().find(|c| on_line(c, (d0, d1), 0.0, k, meet));
    let crossing = r.iter().find(|c| on_line(c, (d0, d1), 1.0, k, meet));
    let (Some(contact), Some(crossing)) = (contact, crossing) else {
        panic!("{name}: {}", summary(r));
    };
    assert!(!std::ptr::eq(contact, crossing), "{name}: {}", summary(r));
    // On the curves themselves, not only within the tolerance of both surfaces (which, where
    // they meet at a small angle, leaves a point far off the curve): see ON_CROSSING, ON_CONTACT.
    for (c, kr, allow) in [
        (crossing, 1.0, on_crossing as fn(f64) -> f64),
        (contact, 0.0, on_contact),
    ] {
        for p in &c.points {
            let w = root(d(polar(p).1));
            let off = off_curve(p, (d0, d1), kr, k);
            assert!(
                off <= allow(w).max(meet),
                "{name}: {p} {off:e} off (W = {w:e})"
            );
        }
    }
    let th = -d0 / (d1 - d0) * FRAC_PI_2;
    let branch = DVec3::new(2.0 * th.cos(), 2.0 * th.sin(), 0.0);
    assert_meet_at(name, &[contact, crossing], branch, meet);
    for (c, len) in [(contact, PI), (crossing, crossing_length(d0, d1, k))] {
        assert!(!c.closed, "{name}: {}", summary(r));
        for p in &c.points {
            let (r, th) = polar(p);
            let [off, off_patch] = off_both(p, (d0, d1), k);
            assert!(off <= 1e-9, "{name}: {p} off the plane or cone");
            assert!(off_patch <= 1e-9, "{name}: {p} off the patch");
            assert!((1.0..=3.0).contains(&r), "{name}: {p}");
            assert!((-1e-9..=FRAC_PI_2 + 1e-9).contains(&th), "{name}: {p}");
        }
        let ends = [c.points[0], c.points[c.points.len() - 1]].map(|p| polar(&p).1);
        let (a, b) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
        assert!(
            a.abs() <= 1e-9 && (b - FRAC_PI_2).abs() <= 1e-9,
            "{name}: {}",
            summary(r)
        );
        let short = if chord > 1e-6 { len * chord / 3.0 } else { 0.0 };
        let l = c.length();
        assert!(
            l <= len + 1e-6 && l >= len - 1e-6 - short,
            "{name}: {} vs {len}",
            summary(r)
        );
    }
    // Densified within `chord` of curves on both surfaces: no chord cuts across anything.
    let off = |p: DVec3| off_both(&p, (d0, d1), k).into_iter().fold(0.0, f64::max);
    assert_chords_on(name, r, off, chord + 1e-9);
}

/// How far `p` is, in space, from the closed-form curve r = 2 + kr·W(d(θ)), z = kc·kr·W over
/// 0 ≤ θ ≤ π/2 (kr = 0 the contact r = 2, kr = 1 the crossing; kc the cone's slope), and on
/// its closed form's extension a hair past the patch's edges, as `off_both` measures the
/// surfaces (an end 4.6e-10 outside the edge θ = 0, on the steep crossing's extension, is
/// 4.8e-9 from its end at θ = 0 but 4.6e-10 from the curve; the ends' θ are checked apart):
/// its nearest point found by Newton on the curve's parameter from the point's own θ.
fn off_curve(p: &DVec3, (d0, d1): (f64, f64), kr: f64, kc: f64) -> f64 {
    let dd = (d1 - d0) / FRAC_PI_2;
    let at = |t: f64| {
        let d = d0 + dd * t;
        let w = root(d);
        let dw = (1.0 - w * w) / (1.0 + 2.0 * d * w) * dd;
        let (r, dr) = (2.0 + kr * w, kr * dw);
        let c = DVec3::new(r * t.cos(), r * t.sin(), kc * kr * w);
        let dc = DVec3::new(
            dr * t.cos() - r * t.sin(),
            dr * t.sin() + r * t.cos(),
            kc * dr,
        );
        (c, dc)
    };
    let span = |t: f64| t.clamp(-1e-6, FRAC_PI_2 + 1e-6);
    let mut t = span(p.y.atan2(p.x));
    for _ in 0..8 {
        let (c, dc) = at(t);
        t = span(t + (*p - c).dot(dc) / dc.length_squared());
    }
    p.distance(at(t).0)
}

/// Whether every point of `c` is on the curve r = 2 + kr·W(d(θ)) (kr = 0 the contact, 1 the
/// crossing) on the cone of slope `kc`: within W/4 in r (which tells the crossing from the
/// contact away from the branch point), or within `meet` of the curve in space. Beside the
/// branch point that is the distance to the curve, not the difference in r: where the crossing
/// is steep (d 0..16: r′/r about 5 at θ = 0) the branch point's solved end, 4.7e-10 from the
/// crossing and 1.4e-9 from the branch point, is 2.4e-9 from it in r, and no curve was taken
/// for the crossing.
fn on_line(c: &Polyline3, (d0, d1): (f64, f64), kr: f64, kc: f64, meet: f64) -> bool {
    c.points.iter().all(|p| {
        let (r, th) = (p.x.hypot(p.y), p.y.atan2(p.x));
        let w = root(d0 + (d1 - d0) * th / FRAC_PI_2);
        (r - 2.0 - kr * w).abs() <= 0.25 * w.abs() || off_curve(p, (d0, d1), kr, kc) <= meet
    })
}

/// How far `p` is from the plane or cone z = k·w and from the patch (its height difference
/// times the cosine of its slope), w = r − 2.
fn off_both(p: &DVec3, (d0, d1): (f64, f64), k: f64) -> [f64; 2] {
    let (r, th) = (p.x.hypot(p.y), p.y.atan2(p.x));
    let (w, dt) = (r - 2.0, d0 + (d1 - d0) * th / FRAC_PI_2);
    let z = k * w + w * w * (dt * (1.0 - w * w) - w);
    let dz_dr = k + 2.0 * dt * w - 4.0 * dt * w.powi(3) - 3.0 * w * w;
    let dz_dth = w * w * (1.0 - w * w) * (d1 - d0) / FRAC_PI_2 / r;
    let cos = 1.0 / (1.0 + dz_dr * dz_dr + dz_dth * dz_dth).sqrt();
    [
        (p.z - k * w).abs() / (1.0 + k * k).sqrt(),
        (p.z - z).abs() * cos,
    ]
}

/// [`check`] in section and patch ∩ plate (or, `plate_first`, in plate ∩ patch only) with the
/// plate z = 0 (a square wider than the patch), the seeding meshes made within `seed` and the
/// curves densified within 1e-6; each run twice for the same bits (three times took 280 s in a
/// debug build).
fn both_curves_come_back((d0, d1): (f64, f64), seed: f64, plate_first: bool) {
    let s = patch(d0, d1);
    let plate = plate();
    let chord = 1e-6;
    let runs = section_and_both_orders("patch", &s, &plate, seed, chord);
    for (name, run) in runs
        .iter()
        .filter(|r| (r.0 == "plate ∩ patch") == plate_first)
    {
        let r = run();
        let name = format!("{name} d = {d0}..{d1} seed {seed}");
        check(&name, &r, (d0, d1), MEET);
        let again = run();
        assert_same_bits(&name, &again, &r);
    }
}

/// The plate z = 0, a square wider than the patch.
fn plate() -> Surface {
    Surface::plane(vec![
        DVec3::new(-4.0, -4.0, 0.0),
        DVec3::new(4.0, -4.0, 0.0),
        DVec3::new(4.0, 4.0, 0.0),
        DVec3::new(-4.0, 4.0, 0.0),
    ])
    .unwrap()
}

/// [`check`] on each run of [`section_and_both_orders`] of `patch(d0, d1)` against [`plate`] at
/// `seed` (curves densified within 1e-6, each run twice for the same bits), the name of each
/// failing run pushed to `failed` (the check's message goes to stderr from the panic).
fn list_failing_runs(failed: &mut Vec<String>, tag: &str, (d0, d1): (f64, f64), seed: f64) {
    let s = patch(d0, d1);
    let plate = plate();
    for (name, run) in section_and_both_orders("patch", &s, &plate, seed, 1e-6) {
        let name = format!("{tag} seed {seed} {name}");
        let once = || {
            let r = run();
            check(&name, &r, (d0, d1), MEET);
            assert_same_bits(&name, &run(), &r);
        };
        if std::panic::catch_unwind(std::panic::AssertUnwindSafe(once)).is_err() {
            failed.push(name);
        }
    }
}

/// The reference itself: the patch's points (flat, and sloped for the cone) are where the closed
/// form puts them (so the checks above test the intersection, not the construction).
#[test]
fn the_patch_is_the_closed_form() {
    use lispcad::geom::surface::ParamSurface;
    let (d0, d1) = (-0.1, 0.3);
    for k in [0.0, 0.5] {
        let s = sloped_patch(d0, d1, k);
        for i in 0..=8 {
            for j in 0..=8 {
                let (u, v) = (i as f64 / 8.0, j as f64 / 8.0);
                let p = s.eval(u, v);
                let (r, th) = (1.0 + 2.0 * u, FRAC_PI_2 * v);
                let (w, d) = (r - 2.0, d0 + (d1 - d0) * v);
                let z = k * w + w * w * (d * (1.0 - w * w) - w);
                let q = DVec3::new(r * th.cos(), r * th.sin(), z);
                assert!(p.distance(q) <= 1e-12, "k {k} {u} {v}: {p} vs {q}");
            }
        }
    }
}

/// The check's measure beside the branch point, against the closed form: [`off_curve`] is the
/// distance in space to the curve (a crossing point moved δ across it, in the plate or off it,
/// is δ off), and [`on_line`] takes the shared end the d 0..16 run solved (2.4e-9 from the
/// crossing in r, 4.7e-10 across it) for both curves, but not the branch point moved 2.5e-9
/// across the crossing.
#[test]
fn the_check_measures_the_distance_to_the_curve() {
    let dd = (0.0, 16.0);
    let line = |p: DVec3, kr: f64| {
        let c = Polyline3 {
            points: vec![p],
            closed: false,
        };
        on_line(&c, dd, kr, 0.0, MEET)
    };
    // The crossing at θ: its point and unit normal in the plate (W′(0) = 1 at d = 0).
    let across = |th: f64| {
        let (d, dd_th) = (16.0 * th / FRAC_PI_2, 16.0 / FRAC_PI_2);
        let w = root(d);
        let (r, dr) = (2.0 + w, (1.0 - w * w) / (1.0 + 2.0 * d * w) * dd_th);
        let tangent = DVec3::new(
            dr * th.cos() - r * th.sin(),
            dr * th.sin() + r * th.cos(),
            0.0,
        );
        let at = DVec3::new(r * th.cos(), r * th.sin(), 0.0);
        (at, DVec3::Z.cross(tangent).normalize())
    };
    for th in [0.0, 1e-6, 1e-3, 0.5] {
        let (at, n) = across(th);
        for (dir, delta) in [(n, 2.5e-9), (DVec3::Z, 2.5e-9), (n, 1e-6)] {
            let off = off_curve(&(at + dir * delta), dd, 1.0, 0.0);
            // Rounding: a few ulps of coordinates about 2.
            assert!(
                (off - delta).abs() <= 2e-15 + 1e-9 * delta,
                "{th} {dir}: {off:e}"
            );
        }
    }
    let end = DVec3::new(
        2.000000001209422,
        7.120517524256676e-10,
        1.3705958819939735e-19,
    );
    let w = root(16.0 * end.y.atan2(end.x) / FRAC_PI_2);
    assert!(
        (end.x.hypot(end.y) - 2.0 - w).abs() > MEET,
        "the old measure, in r"
    );
    assert!(line(end, 1.0) && line(end, 0.0));
    let (branch, n) = across(0.0);
    assert!(!line(branch + n * 2.5e-9, 1.0) && line(branch + n * 1.5e-9, 1.0));
}

/// A crossing through a curved contact at an inner branch point (d = 0 at θ = π/8), in section
/// and both orders. Seen from the plate at seed 1e-2 it came back in two pieces ending about
/// 0.0034 either side of the branch point, run into the contact at points 2.3e-4 apart (the
/// branch point's spread) once their tangents were carried up to 4·near/sin rather than one
/// march step, and 1.7e-6 too long when joined through those points rather than end to end.
/// On 4cf8fa9 the branch point was solved in 1 of these 6 runs: elsewhere the crossing passed it
/// up to 4.9e-6 off, its nearest point up to 4.2e-3 away, and the contact's points beside it
/// were up to 8.4e-7 off r = 2; both now have it as a point (within [`MEET`]).
#[test]
fn a_crossing_through_a_curved_contact_comes_back_whole_with_it() {
    for seed in [1e-2, 1e-3] {
        both_curves_come_back((-0.1, 0.3), seed, false);
        both_curves_come_back((-0.1, 0.3), seed, true);
    }
}

/// A crossing running into a curved contact at a branch point on the patch's edge θ = 0 (or
/// π/2). On 0fb4b3e their shared end was 5.7e-7 to 8.3e-7 off the branch point (where the gap
/// across, a triple root, came within the tolerance); it is now solved along the edge.
#[test]
fn a_crossing_running_into_a_curved_contact_at_an_edge_comes_back_with_it() {
    for (d0, d1, seed) in [(0.0, 0.3, 1e-2), (0.3, 0.0, 1e-3)] {
        both_curves_come_back((d0, d1), seed, false);
    }
}

/// The same seen from the plate (the gap measured from the plate's parameters to the patch):
/// open. At seed 1e-2 a third curve, 29297 points and 18.03 long, came back: a second walk of the
/// contact, from a seed touching on it, that wandered about the branch point (the gap's maximum
/// beside the contact is within tol there). With that seed passed over, the contact (from the
/// plate's parameters, where the patch's edge is no parameter edge) stopped 1.2e-7 rad short of
/// θ = 0, and the crossing with it: the cross-section flattens to an inflection there. Stepping
/// straight on near the end, the contact came within 1e-9 of θ = 0 but 6e-6 too long (seed 1e-2;
/// 4.4e-5 at seed 1e-3), zigzagging up to 1.6e-6 off r = 2 within 1e-5 of the branch point, and
/// the crossing (seed 1e-2) stopped 4.1e-3 short of it, its tangent passing the contact's end.
/// Until the branch point was solved along the patch's edge (the gap taken from the patch to
/// the plate), their shared end was up to 4.9e-8 off it.
#[test]
fn a_crossing_into_a_curved_contact_at_an_edge_seen_from_the_plane() {
    for (d0, d1, seed) in [(0.0, 0.3, 1e-2), (0.3, 0.0, 1e-3)] {
        both_curves_come_back((d0, d1), seed, true);
    }
}

/// A branch point between two curved surfaces: the sloped patch (k = 0.5) against the cone
/// z = k·w, revolved whole about z, in both orders, seed 1e-2. The contact is the arc r = 2,
/// z = 0 (the cone's height and slope there are the patch's), and the crossing r = 2 + W(d),
/// z = k·W, through it where d = 0 (θ = π/8).
#[test]
fn a_crossing_through_a_contact_between_a_patch_and_a_cone() {
    let k = 0.5;
    let (d0, d1) = (-0.1, 0.3);
    let s = sloped_patch(d0, d1, k);
    let line = Curve::line(DVec3::new(1.0, 0.0, -k), DVec3::new(3.0, 0.0, k)).unwrap();
    let cone = Surface::revolve(Arc::new(line), DVec3::ZERO, DVec3::Z, 2.0 * PI).unwrap();
    for (name, x, y) in [("patch ∩ cone", &s, &cone), ("cone ∩ patch", &cone, &s)] {
        let run = || surface_intersect_seeded(x, y, 1e-2, 1e-6, 1e-9).unwrap();
        let r = run();
        check_sloped(name, &r, (d0, d1), k, MEET);
        assert_same_bits(name, &run(), &r);
    }
}

/// The test above past its one seed (i13a-s19): the patch ∩ cone branch point for the d ranges
/// of the plate's grids (d = −0.1..0.3 inside, 0..0.3 and 0.3..0 on an edge, −0.05..0.5 near
/// it, −0.3..0.1 far from it) at seeds 2e-2, 1e-2, 5e-3, 2e-3 and 1e-3, in both orders: 50
/// runs. Open (12 fail; the branch point at θ = −d0/(d1 − d0)·π/2):
/// - every run at seed 1e-3 (10): the contact whole (π to 1e-6), the crossing in pieces, some
///   overlapping (copies of stretches 0.15 to 0.31 long, some out from the edge θ = 0 and
///   back; in patch ∩ cone d = −0.3..0.1 a 1263-point piece 1.688 long with both ends beside
///   the branch point), and lone points or short pieces (1 to 17 points) within 1.6e-2 of the
///   branch point, 2.4e-4 to 4.2e-4 off r = 2; worst, cone ∩ patch d = 0.3..0: 40 lone points
///   along the contact every π/128 and the crossing in 20 pieces (one of 16015 points).
///   Traced (i13d-s19b, d = −0.1..0.3, both orders alike up to `regroup_pair`): it starts in
///   the seed. At 1e-3 both seeding meshes have a vertex on the contact every π/128, but the
///   meshes' curve (591 points, 5.324 long: the crossing from θ = π/2 to 21π/128, then the
///   contact's side) does not run along the contact between them: it is a sawtooth through
///   those vertices out to |r − 2| ≈ 0.03 (where the surfaces part by about d·w², under the
///   meshes' 1e-3), with 41 near-empty loops at the vertices and 3 loops 0.15 to 0.19 long in
///   the wedge by θ = 0. At 2e-3 (all 10 runs pass) 212 of its 401 points, θ = 0.12..1.03,
///   are within 1e-6 of r = 2. `refine_pair_curve` takes each sawtooth point onto both surfaces, but into
///   the band beside the contact where they are within GEOMTOL (the gap w²(d(1 − w²) − w) at
///   most 4.0e-10 there): 44077 points, 6.856 long (1825 and 5.232 at 2e-3), 42734 of them
///   more than 1e-6 off both the contact and the crossing, 31099 densified between θ = 0.3436
///   and the branch point π/8 alone, up to 5.9e-4 off r = 2 within 1.6e-2 of it; it runs on
///   and off the crossing (θ = 0.246..0.252 three times). `regroup_pair` traces the contact
///   whole from it but keeps the rest: the overlapping crossing stretches, and the band's
///   points as the lone points and stubs. The user's-CHORDTOL test below seeds at 1e-3 from
///   the same meshes (seed tolerance = CHORDTOL), so from this sawtooth; past the seed it was
///   not traced here;
/// - patch ∩ cone d = 0.3..0 seed 2e-2: eight curves, six of them pieces of 1 to 151 points
///   about the branch point on the edge θ = π/2;
/// - cone ∩ patch d = −0.05..0.5 seed 1e-2: a 2147-point curve from θ = π/2 back to it, 6.4236
///   long (about twice the crossing's 3.214 from there to the branch point), and the crossing's
///   stub from θ = 0 to the branch point apart.
#[test]
#[ignore = "open: 12 of 50 runs fail (see doc)"]
fn a_crossing_through_a_contact_between_a_patch_and_a_cone_at_every_seed() {
    let k = 0.5;
    let line = Curve::line(DVec3::new(1.0, 0.0, -k), DVec3::new(3.0, 0.0, k)).unwrap();
    let cone = Surface::revolve(Arc::new(line), DVec3::ZERO, DVec3::Z, 2.0 * PI).unwrap();
    let mut failed = Vec::new();
    for seed in [2e-2, 1e-2, 5e-3, 2e-3, 1e-3] {
        for (d0, d1) in [
            (-0.1, 0.3),
            (0.0, 0.3),
            (0.3, 0.0),
            (-0.05, 0.5),
            (-0.3, 0.1),
        ] {
            let s = sloped_patch(d0, d1, k);
            for (name, x, y) in [("patch ∩ cone", &s, &cone), ("cone ∩ patch", &cone, &s)] {
                let name = format!("{name} d = {d0}..{d1} seed {seed}");
                let once = || {
                    let run = || surface_intersect_seeded(x, y, seed, 1e-6, 1e-9).unwrap();
                    let r = run();
                    check_sloped(&name, &r, (d0, d1), k, MEET);
                    assert_same_bits(&name, &run(), &r);
                };
                if std::panic::catch_unwind(std::panic::AssertUnwindSafe(once)).is_err() {
                    failed.push(name);
                }
            }
        }
    }
    let n = failed.len();
    assert!(n == 0, "failing runs ({n}): {failed:?}");
}

/// The same at the user's CHORDTOL (`surface-intersect`: seeding meshes and chords both
/// within CHORDTOL, 2e-2 to 1e-3), checked by [`check_sloped_within`]: 50 runs (i13a-s19).
/// Open, not traced: all 10 runs at CHORDTOL 1e-3 fail, both orders, every d range, on the
/// number of curves (e.g. d = −0.1..0.3: the crossing 3.3314 long and a 5-point piece beside
/// it, 0.048 long; d = 0..0.3 and 0.3..0: lone points on the contact); 2e-3 and up pass.
#[test]
#[ignore = "open: 10 of 50 runs fail, all at CHORDTOL 1e-3 (see doc)"]
fn a_crossing_through_a_contact_between_a_patch_and_a_cone_at_the_users_chordtol() {
    let k = 0.5;
    let line = Curve::line(DVec3::new(1.0, 0.0, -k), DVec3::new(3.0, 0.0, k)).unwrap();
    let cone = Surface::revolve(Arc::new(line), DVec3::ZERO, DVec3::Z, 2.0 * PI).unwrap();
    let mut failed = Vec::new();
    for tol in [2e-2, 1e-2, 5e-3, 2e-3, 1e-3] {
        for d in [
            (-0.1, 0.3),
            (0.0, 0.3),
            (0.3, 0.0),
            (-0.05, 0.5),
            (-0.3, 0.1),
        ] {
            let s = sloped_patch(d.0, d.1, k);
            for (name, x, y) in [("patch ∩ cone", &s, &cone), ("cone ∩ patch", &cone, &s)] {
                let name = format!("{name} d = {}..{} CHORDTOL {tol}", d.0, d.1);
                let once = || {
                    let run = || surface_intersect_seeded(x, y, tol, tol, 1e-9).unwrap();
                    let r = run();
                    check_sloped_within(&name, &r, d, k, MEET, tol);
                    assert_same_bits(&name, &run(), &r);
                };
                if std::panic::catch_unwind(std::panic::AssertUnwindSafe(once)).is_err() {
                    failed.push(name);
                }
            }
        }
    }
    let n = failed.len();
    assert!(n == 0, "failing runs ({n}): {failed:?}");
}

/// A crossing through a curved contact at a branch point near the patch's edge θ = 0 but not
/// on it: 5e-3 and 1.5e-2 along the contact from the edge, d running steeply (by 16 over the
/// quarter turn) so that the crossing's stub between the edge and the branch point parts from
/// the contact by far more than the tolerance (its gap to the plane there reaches 4|d0|³/27,
/// 2.5e-6 for the nearer). Neither way of solving the branch point reached it on c948918: the
/// Hessian's stencils need about 2e-2 of room (`branch_point`), and the edge's own (`edge_meeting`)
/// only serves a branch point on the edge.
///
/// Open: with the stencils narrowed to fit (`branch_point`), the branch point is solved (a point
/// of both curves within 1e-12 of it) in the section and in patch ∩ plate, but not in plate ∩
/// patch (1.9e-7 away); and in patch ∩ plate and plate ∩ patch the crossing has points
/// 3.5e-4..5e-4 from the branch point up to 5.8e-5 off it in r (about 1.1e-5 across), within
/// 1e-9 of both surfaces. The section passes at both seeds.
///
/// The first such point (patch ∩ plate, s = 5e-3, seed 1e-2: r = 2.000331818, 1.7e-5 off at
/// W = 4.25e-4, gap 9.9e-12) is made before regroup: it is in the curve `refine_pair_curve`
/// returns, unchanged by every later stage (contact tracing, cut, extend, alongside, join_ends,
/// run_into, through_branch_points, the loose pass). It is a chord's midpoint from `densify`
/// (`pair_mid` → `newton_pair`): Newton crawled there for 27 iterations (its last step 6.7e-7,
/// the residual 1.03e-11 → 9.9e-12), between the crossing and the contact where the surfaces
/// part as a near triple root, and stopped on the first residual within 0.01·tol, as `goes_on`
/// wants a sixteenfold fall. Relaxing `goes_on`/`shrinks` (5-fold, 0.4) did not move that
/// point and broke `a_crossing_into_a_curved_contact_at_an_edge_seen_from_the_plane`. Why the
/// branch point is not solved in plate ∩ patch was not traced. The test also failed on c948918
/// (the branch point reached by neither solver there, as above).
///
/// Traced further (i13d-s15, not fixed): the crawl is `min_norm`'s Levenberg damping. λ is
/// 1e-12 of JJᵀ's largest entry (about 68 here, the plate's columns), so a step along the
/// direction where the surfaces part (singular value about 1e-7 of J, 1e-14 of JJᵀ, far under
/// λ) is capped at about the residual over √λ in space: 1e-11/8e-6, the 6.7e-7 seen; the point
/// is 9e-5 from the crossing. Two more ways points come out off it: a midpoint whose start is
/// already within 0.01·tol (6.4e-8 off at W = 3.9e-4) is taken with no step, and the chord's
/// own ends were made the same way. Tried: in `pair_mid` only, at least one step, and where
/// the residual falls less than twofold, undamped steps (the minimum-norm solution by QR of Jᵀ,
/// not JJᵀ, whose inverse is noise at condition 1e16), judged by the next step's length, not
/// the residual (a 2.9e-5 step put the gap right but raised the residual 2.3e-11 → 2.2e-10
/// along the surfaces, which the next step, 2.5e-7, takes out), halved where it overshoots.
/// That made patch ∩ plate pass at both seeds (plate ∩ patch still fails: the branch point),
/// but broke `a_crossing_into_a_curved_contact_at_an_edge_seen_from_the_plane` (plate ∩ patch,
/// d = 0..0.3, seed 1e-2: the crossing in pieces about (2.001, 0.012), cause not traced).
/// Lightening λ a thousandfold a step instead (JJᵀ kept) left the point 1.3e-8 off (allowed
/// 1.29e-8) with the residual bouncing, for the same reason.
///
/// Second round (i13d-s15): the plate-first branch point was missed because `branch_point`'s
/// stencils, taken from the plate's parameters, reached past the patch's edge θ = 0 (5e-3 and
/// 1.5e-2 away, the stencils 2.4e-2), where the gap is taken to that edge; they are now narrowed
/// to fit inside the other surface too. Not committed (patch
/// /tmp/i13d-wip-crawl-refusal-and-branch-narrowing.patch): `pair_mid` refusing a crawled
/// midpoint (Newton's last step longer than 0.01·tol lowering the residual less than twofold,
/// or a start taken with no step whose first step would) where it is more than `chord_tol`
/// off its chord. With the narrowing alone, 2 of the 8 runs here pass (s = 1.5e-2, seed 1e-3),
/// the other 6 failing, in both orders, on crawled crossing points 1.2e-7..1.7e-5 off (the
/// branch point itself now solved). With both, all eight pass; but the contact midpoints of
/// `a_crossing_into_a_curved_contact_at_an_edge_seen_from_the_plane` crawl the same way
/// (residual falling 1.03..1.7-fold a step, as the crossing's 1.16..1.7: no local test told
/// them apart), and refused there the contact's end on the patch's edge θ = π/2 comes out
/// 2.66e-8 off r = 2 (allowed 2e-8).
///
/// Third round (i13d-s16): `pair_mid` no longer refuses; where Newton's midpoint may lie off
/// the curve (its residual over the sine of the surfaces' angle above the tolerance, the
/// residual above the rounding, Newton not converging fourfold onto a contact's double zero),
/// `refine/across.rs` takes it across the chord onto the gap's simple root, bracketed (a
/// contact's even root has no sign change, and its point stays; a cheap probe, b's foot moved
/// one Gauss–Newton step, tells most contact midpoints first). 7 of the 8 runs pass (were
/// 2), `a_crossing_into_a_curved_contact_at_an_edge_seen_from_the_plane` too. Still failing:
/// s = 5e-3, seed 1e-2, patch ∩ plate: three curves, the contact split about θ = 0.00275 (just
/// past the branch point at θ = 0.0025) into a 26-point piece from θ = 0 and the rest; not
/// traced. (A first version, the gap's slope by differences on a hundredth of the chord and a
/// bracket at half and one and a half Newton steps, passed all 8, but cost five projections
/// per contact midpoint.)
///
/// Fourth round (i13d-s17): that run's third curve was no split contact (the contact came back
/// whole, π − 3e-7 long) but a 27-point stray from θ = 0 to 0.00275. The seed curve ran along
/// the contact and off along the crossing, one chord spanning the branch point; densifying it
/// left crossing points beside the branch point crawled off the crossing (1.7e-5 off at
/// W = 4.25e-4, which the check above also refuses) and out of order, and regroup cut two of
/// them off as a piece of crossing that `run_into` led back along the contact. They were
/// crawled because `onto_crossing` looked along the line square to the chord, and that chord's
/// far end was itself a crawled point: the line ran nearly along the crossing, the gap hardly
/// changed along it, and the probe took it for a contact's. It now looks along b's normal
/// projected onto a's tangent plane (across the curve whatever the chord), and that run passes.
/// This test stopped at its first failing run, which hid the others: on stage-s17 (26d853a)
/// the four runs at seed 1e-3 fail too, before and after that change: s = 5e-3, both orders, a
/// crossing point 3.9e-9 off at W = 1.39e-3 (allowed 1.03e-9; its gap, 4e-14, is within the
/// 8·`rounding` that `onto_crossing` takes for noise, where the plate's size sets the
/// rounding at 1e-14 and the gap's own is about 4e-16); s = 1.5e-2, both orders, a point of
/// the crossing's stub 1.55e-6 off at W = −8.9e-4 (not traced). Each run is now tried and the
/// failing ones listed together. The same listing on 6a88d76 (the main before this round)
/// fails 5 of the 8 (these four and the one fixed above): the third round's "7 of 8 pass" had
/// counted from a test that stopped at its first failure. After this round's merges (29b4dac)
/// it failed 5 again: the four at seed 1e-3 and s = 1.5e-2, seed 1e-2, the section (a stray
/// closed 50-point curve, 0.154 long, at (1.924, 0, 0) on the patch's edge θ = 0; not traced).
///
/// Fifth round (lead, from the helpers' patches): `newton_pair_mid` no longer skips the
/// cross-chord fix for a residual falling three- to sixfold (a contact's double zero): near the
/// branch point's triple root a crossing point falls so too (3.85-fold), and `onto_crossing`'s
/// probe tells contacts. And a gap within 8·`rounding` (from the surfaces' sizes: 1e-14 on the
/// 8×8 plate) is taken for noise only if it is also within 8 times its own rounding, read by
/// nudging each parameter two ulps (`across::gap_noise`; about 4e-16 at r = 2): the s = 5e-3
/// crossing point 3.9e-9 off had a gap of 4e-14. Now 2 of 8 fail: s = 1.5e-2, seed 1e-2, the
/// section's stray loop above; and s = 1.5e-2, seed 1e-3, plate ∩ patch (not traced).
///
/// Sixth round (i13d-s18): the section's stray (s = 1.5e-2, seed 1e-2) was the crossing's stub
/// traced there and back. Regroup cut the stub (θ = 0 to 3.7e-4 short of the branch point) off
/// a seed curve that ran along the contact, and `extend_crossing` marched it on towards the
/// branch point; every node within about 3.3e-4 of it was refused (beside the contact, no sign
/// change within reach), the step halved down to 1e-11, and the march took each accepted
/// node's chord for its way on: nodes placed by the gap's rounding turned it in five steps
/// (0.99, 0.12) → (0.81, 0.58) → (0.29, 0.96) → (−0.52, 0.85) → (−0.97, −0.25), and it marched
/// back down the stub to θ = 0. It now keeps its way over a step shorter than the tolerance.
/// That moved the stub's end by 5.7e-10 in the inner branch point's test above (section, seed
/// 1e-2, d = −0.1..0.3), whose joint across the branch point had passed by luck: its first
/// midpoint fell on the branch point; now it fell 7.6e-6 off, and densifying towards it drew
/// points nearer and nearer the branch point, each placed by the gap's rounding (3.2e-6 off the
/// crossing at 8.6e-6 from the point). `branch::splice_at` replaces the points within `near` of
/// the solved branch point; the chords to it no longer than `near` are now left undensified.
///
/// Sixth round (i13c-s18): that plate ∩ patch run gave a third curve, 6 points of the
/// crossing's stub from the branch point out to θ = 0.0068 (a second copy of it). A seed curve
/// ran along the contact to θ = 0 and back out along the crossing; the midpoint of its contact
/// chord from θ = 0.0123 to 0 (spanning the branch point) converged 2.2e-6 off r = 2, and
/// `onto_crossing` stepped 1.7e-2 across from it onto the stub (r = 1.989), which densify then
/// filled in as a spike that regroup cut off as a piece. The step came from the derivatives at
/// Newton's last start, the chord's parameter midpoint on the contact itself, where the
/// surfaces' angle (2·d·w) is nil: 4e-12 against 6.2e-8 at the point. `newton_pair_mid` now
/// takes them again where Newton stopped for a point it is not sure of; the step is then
/// 1.1e-6, the probe's gap falls fourfold (a contact's) and the point stays. See
/// [`a_crossing_near_an_edge_seen_from_the_plate_at_seed_1e_3`].
///
/// With both sixth-round changes merged (stage-s18) all 8 runs pass, and the test is no longer
/// ignored; the wider grid below holds the family's open runs.
#[test]
fn a_crossing_through_a_curved_contact_near_an_edge_comes_back_whole_with_it() {
    let mut failed = Vec::new();
    for s in [5e-3, 1.5e-2] {
        let d0 = -16.0 * (0.5 * s) / FRAC_PI_2;
        for seed in [1e-2, 1e-3] {
            for plate_first in [false, true] {
                let run = || both_curves_come_back((d0, d0 + 16.0), seed, plate_first);
                if std::panic::catch_unwind(run).is_err() {
                    failed.push(format!("s {s} seed {seed} plate first {plate_first}"));
                }
            }
        }
    }
    assert!(failed.is_empty(), "failing runs: {failed:?}");
}

/// The near-edge family's run that gave a second copy of the crossing's stub (s = 1.5e-2 from
/// the patch's edge, seed 1e-3, plate ∩ patch; see the sixth round above): a contact's midpoint
/// taken across onto the stub by a step from stale derivatives. Failed on c7e144c (three curves).
#[test]
fn a_crossing_near_an_edge_seen_from_the_plate_at_seed_1e_3() {
    let s = 1.5e-2;
    let d0 = -16.0 * (0.5 * s) / FRAC_PI_2;
    both_curves_come_back((d0, d0 + 16.0), 1e-3, true);
}

/// A crossing through a curved contact 2e-2 along it from the patch's edge θ = 0 (the near-edge
/// family below), where the meshes' section holds a lens along the contact beside the branch
/// point: the crossing's seed curve runs out along the contact to θ ≈ 0.28 and back, none of its
/// first, middle and last points touching. On c7e144c these four runs failed: at seed 1e-2 the
/// section came back as one curve (the crossing 6.18 long, 1.09 of it the contact out and
/// back; the rest of the contact lost), both orders with the crossing so and the contact;
/// at seed 5e-3, plate ∩ patch, the same.
#[test]
fn a_crossing_whose_seed_runs_along_the_contact_and_back_comes_back_whole_with_it() {
    let d0 = -16.0 * (0.5 * 2e-2) / FRAC_PI_2;
    for (seed, plate_first) in [(1e-2, false), (1e-2, true), (5e-3, true)] {
        both_curves_come_back((d0, d0 + 16.0), seed, plate_first);
    }
}

/// A crossing through a curved contact 2.5e-3 along it from the patch's edge θ = 0, at seed
/// 1e-3: a seed curve runs along the contact from θ = π/2 and on along the crossing's stub to
/// the edge, and the stub parts from the plane so slowly (at a sine under 1e-3) that all three
/// of its probes touch. On c7e144c `regroup` kept it whole beside the contact traced from it,
/// in the section and both orders: three curves, the contact twice (once with the stub on).
#[test]
fn a_seed_along_the_contact_and_on_along_a_tangent_stub_is_cut_off_the_contact() {
    let d0 = -16.0 * (0.5 * 2.5e-3) / FRAC_PI_2;
    both_curves_come_back((d0, d0 + 16.0), 1e-3, false);
    both_curves_come_back((d0, d0 + 16.0), 1e-3, true);
}

/// A crossing through a curved contact 5e-2 along it from the patch's edge θ = 0, plate ∩ patch
/// at seed 5e-3: the crossing comes in two pieces cut off its seed curves beside the branch
/// point, their ends 9e-4 apart, and `join_ends` joins them. On 208b8a0 the root across the
/// joint's chord from one of its midpoints ran off along the contact and the far stretch of the
/// crossing: a 7.05-long seam, the crossing 12.26 long (5.19).
#[test]
fn a_crossing_joined_across_the_branch_point_keeps_its_joint_short() {
    let d0 = -16.0 * (0.5 * 5e-2) / FRAC_PI_2;
    both_curves_come_back((d0, d0 + 16.0), 5e-3, true);
}

/// An inner branch point near the edge θ = 0 (d = −0.05..0.5: θ = π/22), seen from the plate
/// at seeds 1e-2 and 2e-3 (two runs of the second grid below). On f9f728b the contact came back
/// 3.1438 (1e-2) or 3.1423 (2e-3) long, its ends in place: a spur out to 3.2e-4 beside the
/// branch point and back, its points at r − 2 ≈ 2W/3, on the gap's other extremum between the
/// contact and the crossing (the gap across, d·w² − w³ near the branch point, has a maximum of
/// 4d³/27 there, within the tolerance for |d| up to 1.5e-3). The contact walk (`contact/line.rs`)
/// settled there: at 1e-2 a step 0.25 long from θ = 0.27 (its tangent running off the
/// contact's convex side, onto the crossing's) landed on that extremum at θ = 0.1441, and
/// densifying followed it out and back; at 2e-3 the midpoint of a chord 0.064 long spanning the
/// branch point did. A settled point whose gap is larger, not smaller, than beside it (h·h″ < 0,
/// h above its rounding) is now searched past, 2a/b = √(6|h/h″|) either way, and the contact
/// found there (the surfaces touching) taken instead (`line::settle_on_contact`).
#[test]
fn a_contact_past_an_inner_branch_point_near_an_edge_has_no_spur() {
    for seed in [1e-2, 2e-3] {
        both_curves_come_back((-0.05, 0.5), seed, true);
    }
}

/// A crossing from a branch point on the patch's edge θ = 0 with d = 0..1 (steeper than 0..0.3,
/// shallower than 0..16), plate ∩ patch at seeds 2e-2, 1e-2, 5e-3 and 2e-3. The meshes' section
/// runs along the crossing from θ = π/2 to θ ≈ 0.42 (0.20, 0.10 at 5e-3, 2e-3), across a cell onto
/// the contact and along it to the branch point (at 2e-2 out to θ ≈ 0.49 and back first; at 5e-3
/// and 2e-3 out and back too): the crossing's stretch on to the branch point, where the patch lies
/// within the seed tolerance of the plate, is no part of it. On f9f728b these four runs came back
/// as three curves: the crossing to θ ≈ 0.42, that seed curve's stretch along the contact (looking
/// like a second piece of the crossing; cut off it by the chord across the cell) and the contact,
/// traced apart; the crossing's last stretch was lost. `regroup`'s only touching probe of the seed
/// curve was its end on the branch point, from which no contact traced (nor from the steps off it,
/// a seed step long); it now tries the curve's points a step in from its touching probes. The
/// contact traced from there ran, at 2e-2, 5e-3 and 2e-3, onto the gap's other extremum beside the
/// branch point (w = 2d/3, within the tolerance of both surfaces out to 6e-3 from it) and came
/// back with a spur (3.14181, 3.14172, 3.14299 long): at 2e-2 a first full step from θ ≈ 0.13
/// straight along the circle's tangent landed 1.6e-2 off it, past the crossing, and settled there.
/// `line::settle_on_contact` (i13d, see the test above) searches past that extremum onto the
/// contact; i13c's own mend for it, a walk step shortened where it settles on the gap curving the
/// other way, was not merged: it left the midpoint case of the test above (seed 2e-3) open.
#[test]
fn a_crossing_from_a_branch_point_on_an_edge_at_d_0_to_1_comes_back_whole() {
    for seed in [2e-2, 1e-2, 5e-3, 2e-3] {
        both_curves_come_back((0.0, 1.0), seed, true);
    }
}

/// How wide the near-edge family is: the test above over a wider grid, s ∈ {2.5e-3, 5e-3,
/// 1e-2, 1.5e-2, 2e-2, 3e-2, 5e-2} along the contact from the edge θ = 0 (d running by 16 over
/// the quarter turn), the branch point on the edge (d = 0..0.3, 0.3..0, 0..16, 16..0) and the
/// inner one (−0.1..0.3), each at seeds 1e-2, 5e-3 and 1e-3 in the section and both orders:
/// 108 runs (about 20 s in a release build).
///
/// On c7e144c 22 fail. Nine were every run at s = 2e-2: a seed curve of the crossing held a
/// lens of the contact (two sides of the meshes' section closer than a cell, from the branch
/// point out to θ ≈ 0.28 and back) refined onto the contact out and back, and `regroup` kept it
/// whole, none of its first, middle and last points touching: the crossing came back 1.09
/// too long (the contact lost from the section at seed 1e-2), or with a closed 1.145-long
/// loop cut from it by `join` (seed 1e-3). `regroup` now probes such a curve where it folds
/// back (`fold_probes`), and all nine are mended; three runs at s = 2e-2 then fail on what the
/// spur had hidden (below). Three more were s = 2.5e-3 at seed 1e-3, all three runs: a seed
/// curve along the contact and on along the stub, all three probes touching (the stub parts
/// from the plane at a sine under 1e-3), kept whole beside the traced contact (three curves,
/// the contact twice); `regroup` now cuts such a curve off the contact.
///
/// On 208b8a0, 12 of 108 failed (13 before fb7e2b6, which mended the stray stub at s = 1.5e-2
/// seed 1e-2 in the section). Mended since: four section runs (s = 1.5e-2, 2e-2, 3e-2 at seed
/// 5e-3: 6.5e-6, 9.0e-6, 1.0e-5 off at |W| ≈ 3.5e-4; s = 2e-2 seed 1e-3, 2.8e-8 at W = 4.6e-3),
/// section midpoints where Newton crawled onto the crossing beside the contact's double zero
/// and stopped within 0.01·tol of the plane, now taken across the curve onto the distance's
/// root (`refine::plane_across`); s = 1.5e-2 seed 1e-3 plate ∩ patch (a 6-point copy of the
/// stub's end, a contact midpoint stepped across by stale derivatives, i13c); s = 5e-2 seed
/// 5e-3 plate ∩ patch (the crossing 12.26 long, a seam of `join_ends` run off along the
/// contact, i13d); d = 0..16 seed 1e-3 plate ∩ patch (a 15-point piece of the crossing, 0.056
/// long; mended by these merges, not traced which).
///
/// Mended on stage-s18 after that: two section runs, s = 1e-2 and 3e-2 at seed 1e-2 (a
/// crossing point 3.8e-8 off at W = −4.5e-3, 5.2e-8 at W = −5.5e-3): section midpoints whose
/// Newton stopped 4e-12 and 8e-12 off the plane, where `plane_across`'s own Newton step landed
/// on the root to rounding (1e-17) and, finding no sign change past it, was dropped (it now
/// keeps it, i13a). Two plate ∩ patch runs, s = 3e-2 seed 1e-2 and s = 2e-2 seed 1e-3: the
/// contact's end on the far edge θ = π/2 2.09e-8 and 2.81e-8 off r = 2 (allowed 2e-8). Traced
/// from the plate's parameters (`regroup`'s contact walk), the last 1.6e-4 to the patch's edge
/// were straight steps (the bisection for the end, shorter than √(tol·size)) along the last
/// settled chord's line, which leans off the circle by half its turn; they now follow the arc
/// the walk turns by (ends 8e-13 and 4e-12 off, i13d). And d = 0..16 seed 5e-3, plate ∩ patch,
/// mended in the check (i13c): no curve was taken for the crossing, because their shared end,
/// the branch point solved 1.4e-9 from (2, 0, 0), 4.7e-10 from the crossing in space, 1.2e-9
/// from the contact and 1.4e-19 off both surfaces (all in closed form), is 2.4e-9 off the
/// crossing in r, and `on_line` measured `MEET` in r across a crossing steep there (r′/r about
/// 5); it now measures the distance to the curve (`off_curve`), and the run passes whole.
///
/// All 108 runs pass on stage-s18, and the test is no longer ignored; a second grid, below,
/// holds the open runs found past this one.
///
/// The grid runs as six tests, one per seed and family (s, or the branch points' d), sharing
/// [`runs_of_the_family_pass`]: in one test it took 496 s of CI's debug build on one core.
const WIDER_S: [f64; 7] = [2.5e-3, 5e-3, 1e-2, 1.5e-2, 2e-2, 3e-2, 5e-2];

/// The branch points of the wider grid (see [`WIDER_S`]): on the edge, and the inner one.
const WIDER_D: [(f64, f64); 5] = [
    (0.0, 0.3),
    (0.3, 0.0),
    (0.0, 16.0),
    (16.0, 0.0),
    (-0.1, 0.3),
];

/// [`list_failing_runs`] at `seed` for each distance `s` along the contact from the edge θ = 0
/// (d running by 16 over the quarter turn from −16·(s/2)/(π/2)), then for each d range of `d`;
/// fails listing every failing run.
fn runs_of_the_family_pass(seed: f64, s: &[f64], d: &[(f64, f64)]) {
    let mut failed = Vec::new();
    for &s in s {
        let d0 = -16.0 * (0.5 * s) / FRAC_PI_2;
        list_failing_runs(&mut failed, &format!("s {s}"), (d0, d0 + 16.0), seed);
    }
    for &d in d {
        list_failing_runs(&mut failed, &format!("d {}..{}", d.0, d.1), d, seed);
    }
    assert!(
        failed.is_empty(),
        "failing runs ({}): {failed:?}",
        failed.len()
    );
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_2_over_s() {
    runs_of_the_family_pass(1e-2, &WIDER_S, &[]);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_2_over_d() {
    runs_of_the_family_pass(1e-2, &[], &WIDER_D);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_5e_3_over_s() {
    runs_of_the_family_pass(5e-3, &WIDER_S, &[]);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_5e_3_over_d() {
    runs_of_the_family_pass(5e-3, &[], &WIDER_D);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_3_over_s() {
    runs_of_the_family_pass(1e-3, &WIDER_S, &[]);
}

#[test]
fn the_near_edge_family_over_a_wider_grid_comes_back_whole_seed_1e_3_over_d() {
    runs_of_the_family_pass(1e-3, &[], &WIDER_D);
}

/// A second grid, past the first (lead, stage-s18, once the first passed whole): s ∈ {4e-3,
/// 7.5e-3, 1.2e-2, 2.5e-2, 4e-2, 7e-2} along the contact from the edge θ = 0, the branch
/// point on the edge with d = 0..1, and inner branch points near the edge (d = −0.05..0.5,
/// θ = π/22) and far from it (d = −0.3..0.1, θ = 3π/8), at seeds 2e-2, 1e-2, 5e-3,
/// 2e-3 and 1e-3, in the section and both orders: 135 runs. All 90 runs of the s family pass,
/// and every section and patch ∩ plate run. On f9f728b 6 of 135 failed, all plate ∩ patch (the
/// gap taken from the plate's parameters), all mended on stage-s19 and now passing:
/// - d = 0..1 at seeds 2e-2, 1e-2, 5e-3, 2e-3: three curves; not the crossing in two pieces,
///   but the crossing short of the branch point and a seed curve along the contact kept whole,
///   no contact traced from it in `regroup` (i13c); see
///   [`a_crossing_from_a_branch_point_on_an_edge_at_d_0_to_1_comes_back_whole`];
/// - d = −0.05..0.5 at seeds 1e-2 and 2e-3: the contact 3.1438 (1e-2) or 3.1423 (2e-3) long
///   against π, ends in place, a spur beside the branch point on the gap's other extremum
///   (i13d); see [`a_contact_past_an_inner_branch_point_near_an_edge_has_no_spur`].
///
/// The grid runs as five tests, one per seed, sharing [`runs_of_the_family_pass`], so that
/// libtest runs them side by side.
const SECOND_S: [f64; 6] = [4e-3, 7.5e-3, 1.2e-2, 2.5e-2, 4e-2, 7e-2];

/// The branch points of the second grid (see [`SECOND_S`]): on the edge, near it, far from it.
const SECOND_D: [(f64, f64); 3] = [(0.0, 1.0), (-0.05, 0.5), (-0.3, 0.1)];

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_2e_2() {
    runs_of_the_family_pass(2e-2, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_1e_2() {
    runs_of_the_family_pass(1e-2, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_5e_3() {
    runs_of_the_family_pass(5e-3, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_2e_3() {
    runs_of_the_family_pass(2e-3, &SECOND_S, &SECOND_D);
}

#[test]
fn a_second_grid_past_the_first_comes_back_whole_seed_1e_3() {
    runs_of_the_family_pass(1e-3, &SECOND_S, &SECOND_D);
}
