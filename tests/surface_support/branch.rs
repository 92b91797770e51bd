//! The surface of the branch-point tests (issue 13; `surface_contact_branch` and
//! `surface_contact_branch_grid`): the Coons patch over the quarter annulus whose intersection
//! with the plane z = 0 (or, sloped, with a cone) is a curved contact and a crossing through it
//! at a branch point (see `surface_contact_branch`'s module doc), the plate, and the check of
//! both curves against their closed forms.
#![allow(dead_code)] // each test file uses its own part of this module

use crate::surface_support::{assert_chords_on, assert_meet_at, assert_same_bits, summary};
use lispcad::geom::curve::Curve;
use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::Surface;
use lispcad::geom::DVec3;
use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::Arc;

/// The product of two polynomials (coefficients from the constant term up).
pub fn times(p: &[f64], q: &[f64]) -> Vec<f64> {
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
pub fn profile(d: f64, th: f64, k: f64) -> Curve {
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
pub fn patch(d0: f64, d1: f64) -> Surface {
    sloped_patch(d0, d1, 0.0)
}

/// [`patch`] with k·w added to its height: it then touches and crosses the cone z = k·w (the
/// line from (1, 0, −k) to (3, 0, k) revolved about z) where the flat patch meets z = 0.
pub fn sloped_patch(d0: f64, d1: f64, k: f64) -> Surface {
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

/// The cone z = k·w (w = r − 2): the line from (1, 0, −k) to (3, 0, k) revolved about z, which
/// [`sloped_patch`] touches along r = 2 and crosses.
pub fn cone(k: f64) -> Surface {
    let line = Curve::line(DVec3::new(1.0, 0.0, -k), DVec3::new(3.0, 0.0, k)).unwrap();
    Surface::revolve(Arc::new(line), DVec3::ZERO, DVec3::Z, 2.0 * PI).unwrap()
}

/// The crossing's w for `d`.
pub fn root(d: f64) -> f64 {
    2.0 * d / (1.0 + (1.0 + 4.0 * d * d).sqrt())
}

/// The length of the crossing r = 2 + W(d(θ)), z = k·W over [0, π/2]: ∫ √(r² + (1 + k²)·r′²) dθ
/// by composite Simpson on 4096 panels (the integrand is smooth; error far under 1e-9).
pub fn crossing_length(d0: f64, d1: f64, k: f64) -> f64 {
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
pub fn check(name: &str, r: &[Polyline3], (d0, d1): (f64, f64), meet: f64) {
    check_sloped(name, r, (d0, d1), 0.0, meet);
}

/// How near the branch point both curves come (and how far from the closed form either may be
/// there): it is solved where the gap's Hessian vanishes (inside the patch: 8.9e-10 the most
/// seen, patch ∩ cone), or, on the patch's edge θ = 0 or π/2, where the gap's second derivative
/// along that edge does (4.5e-11 seen from the patch's parameters; 6.0e-13 from the plate's,
/// the gap then taken along the patch's edge from the patch to the plate).
pub const MEET: f64 = 2e-9;

/// How far a crossing point may be from the closed form (its distance in space to the curve,
/// [`off_curve`]) where the crossing is W from the contact: 1e-9 (GEOMTOL) where W ≥ 1e-3, nearer the branch point the rounding of the gap
/// (about 4e-16 here) over its slope across the crossing (W², the gap across being
/// w²(d(1 − w²) − w)) with a margin of 5: where the surfaces part more slowly than that no
/// computation tells the crossing's point, nor ever farther than W/4 (the contact's side).
/// Seen: up to 1.3e-6 at W = 1.8e-5 (0.14e-3 from the branch point), 1.3e-7 at W = 5.7e-5;
/// on c948918, 3.3e-5 at W = 5.3e-4 and 5e-8 where W > 3e-2 (points whose gap came within
/// 0.01·tol were taken for the crossing's, however flat the gap across it).
pub fn on_crossing(w: f64) -> f64 {
    (2e-15 / (w * w)).min(0.25 * w.abs()).max(1e-9)
}

/// How far a contact point may be from r = 2: 2e-8 (seen: 1.83e-8 at the contact's ends on the
/// patch's edges, traced from the plate's parameters; 5.5e-9 elsewhere away from the branch
/// point), nearer the branch point 2e-11/W (the gap across the contact, d·w², flattens with d,
/// about W: seen 8.1e-8 at W = 9.8e-5, patch ∩ cone), never farther than W/4.
pub fn on_contact(w: f64) -> f64 {
    (2e-11 / w.abs()).min(0.25 * w.abs()).max(2e-8)
}

/// [`check`] for [`sloped_patch`] against the cone z = k·w (the plane z = 0 for k = 0): the
/// distance to the cone is |z − k·w|·cos(atan k) (the cone is straight along its generators, and
/// a point's nearest on it lies in its meridian plane).
pub fn check_sloped(name: &str, r: &[Polyline3], d: (f64, f64), k: f64, meet: f64) {
    check_sloped_within(name, r, d, k, meet, 1e-6);
}

/// [`check_sloped`] for curves densified within `chord`: chords within `chord` + 1e-9 of both
/// surfaces, and lengths to 1e-6 over the closed form's but, where `chord` is above 1e-6, up
/// to its length·`chord`/3 under it (a chord whose middle is h from a curve of curvature κ
/// is shorter than its arc by about κ·h/3 of it, and κ ≤ 1 here: the contact's 1/2, the
/// crossing's near it).
pub fn check_sloped_within(
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
pub fn off_curve(p: &DVec3, (d0, d1): (f64, f64), kr: f64, kc: f64) -> f64 {
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
pub fn on_line(c: &Polyline3, (d0, d1): (f64, f64), kr: f64, kc: f64, meet: f64) -> bool {
    c.points.iter().all(|p| {
        let (r, th) = (p.x.hypot(p.y), p.y.atan2(p.x));
        let w = root(d0 + (d1 - d0) * th / FRAC_PI_2);
        (r - 2.0 - kr * w).abs() <= 0.25 * w.abs() || off_curve(p, (d0, d1), kr, kc) <= meet
    })
}

/// How far `p` is from the plane or cone z = k·w and from the patch (its height difference
/// times the cosine of its slope), w = r − 2.
pub fn off_both(p: &DVec3, (d0, d1): (f64, f64), k: f64) -> [f64; 2] {
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

/// The plate z = 0, a square wider than the patch.
pub fn plate() -> Surface {
    Surface::plane(vec![
        DVec3::new(-4.0, -4.0, 0.0),
        DVec3::new(4.0, -4.0, 0.0),
        DVec3::new(4.0, 4.0, 0.0),
        DVec3::new(-4.0, 4.0, 0.0),
    ])
    .unwrap()
}

/// One run of a sweep: `run` twice, the first result checked by `check` and the second the same
/// bits; a failure (any panic) is listed in `failed` by `name`, so a sweep reports all of its.
pub fn list_if_failing(
    failed: &mut Vec<String>,
    name: String,
    run: impl Fn() -> Vec<Polyline3>,
    check: impl Fn(&str, &[Polyline3]),
) {
    let once = || {
        let r = run();
        check(&name, &r);
        assert_same_bits(&name, &run(), &r);
    };
    if std::panic::catch_unwind(std::panic::AssertUnwindSafe(once)).is_err() {
        failed.push(name);
    }
}
