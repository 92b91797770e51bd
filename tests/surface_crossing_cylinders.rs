//! Crossing cylinders at the user's CHORDTOL (issue 13): the seeding meshes are made within
//! CHORDTOL, so every value must give the same curves. Unequal radii on tilted, offset axes
//! (two loops, no branch point), and equal radii on axes crossing at 60° (two ellipses of
//! different sizes through two branch points, where each must run straight on). Every point
//! within 1e-9 of both cylinders by closed-form distances, each curve on its own loop, lengths
//! against independent quadratures (midpoint rule on smooth periodic integrands: spectral).

use lispcad::geom::mesh::Polyline3;
use lispcad::geom::surface::{surface_intersect_seeded, surface_intersect_tol, Surface};
use lispcad::geom::DVec3;
use std::f64::consts::TAU;

mod surface_support;
use surface_support::ellipse_perimeter;

/// The user's CHORDTOLs tried, coarse to fine.
const CHORDTOLS: [f64; 10] = [
    0.03, 0.02, 0.015, 0.01, 0.007, 0.005, 0.003, 0.002, 0.001, 0.0007,
];

/// A cylinder by its axis through `c` (unit `axis`) and radius, reaching `half` each way.
struct Cyl {
    c: DVec3,
    axis: DVec3,
    r: f64,
    half: f64,
}

impl Cyl {
    fn surface(&self) -> Surface {
        Surface::cylinder(
            self.c - self.axis * self.half,
            self.axis,
            self.r,
            2.0 * self.half,
        )
        .unwrap()
    }

    fn off(&self, p: DVec3) -> f64 {
        let d = p - self.c;
        ((d - self.axis * d.dot(self.axis)).length() - self.r).abs()
    }
}

/// Two unit vectors square to `e` and to each other.
fn frame(e: DVec3) -> (DVec3, DVec3) {
    let u = e.any_orthonormal_vector();
    (u, e.cross(u))
}

/// Least radius of curvature of the closed curve through `pts` (evenly and finely sampled):
/// the least circumradius of three consecutive points.
fn least_radius(pts: &[DVec3]) -> f64 {
    let n = pts.len();
    (0..n)
        .map(|i| {
            let (a, b, c) = (pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]);
            let (x, y) = (a - b, c - b);
            (x.length() * y.length() * (x - y).length()) / (2.0 * x.cross(y).length())
        })
        .fold(f64::INFINITY, f64::min)
}

/// Whether the polyline is short of a loop of length `exact` and least radius of curvature
/// `rho` by no more than chords within `t` of it allow: a chord whose refined midpoint is
/// within t of it (taken a quarter to three quarters along) leaves the arc within 4t/3, and an
/// arc of sag δ is longer than its chord by δ/(3ρ) of it.
fn short_within(l: f64, exact: f64, rho: f64, t: f64) -> bool {
    l <= exact + 1e-9 && exact - l <= 4.0 * t / (9.0 * rho) * exact
}

/// Cylinder A (radius 1.5, axis z) pierced by cylinder B (radius 0.8) on an axis tilted out
/// of the xy plane and off A's axis: B goes in and out of A in two separate loops, one each
/// side of B's middle (t = (p − c)·e of one sign).
fn tilted() -> (Cyl, Cyl) {
    let a = Cyl {
        c: DVec3::ZERO,
        axis: DVec3::Z,
        r: 1.5,
        half: 3.0,
    };
    let b = Cyl {
        c: DVec3::new(0.0, 0.3, 0.2),
        axis: DVec3::new(1.0, 0.2, 0.35).normalize(),
        r: 0.8,
        half: 4.0,
    };
    (a, b)
}

/// The two loops of [`tilted`], sampled at `n` angles θ about B's axis: the point of B's
/// circle at θ carried along B's axis by the root t of |xy|² = 1.5² (the larger root, or the
/// smaller), and the length of each by the midpoint rule on |dQ/dθ|.
fn tilted_loops(n: usize) -> [(Vec<DVec3>, f64); 2] {
    let (a, b) = tilted();
    let (u, w) = frame(b.axis);
    let e = b.axis;
    let (ex, ey) = (e.x, e.y);
    let qa = ex * ex + ey * ey;
    [1.0, -1.0].map(|sign| {
        let mut pts = Vec::with_capacity(n);
        let mut len = 0.0;
        for i in 0..n {
            let th = TAU * (i as f64 + 0.5) / n as f64;
            let p = b.c + b.r * (th.cos() * u + th.sin() * w);
            let dp = b.r * (-th.sin() * u + th.cos() * w);
            let qb = p.x * ex + p.y * ey;
            let qc = p.x * p.x + p.y * p.y - a.r * a.r;
            let t = (-qb + sign * (qb * qb - qa * qc).sqrt()) / qa;
            let q = p + t * e;
            // d/dθ of |q_xy|² = R²: 2 q_xy·(dp_xy + t' e_xy) = 0.
            let dt = -(q.x * dp.x + q.y * dp.y) / (q.x * ex + q.y * ey);
            len += (dp + dt * e).length();
            pts.push(q);
        }
        (pts, len * TAU / n as f64)
    })
}

/// Which loop of [`tilted`] `p` is on: the sign of (p − c)·e along B's axis.
fn side(p: DVec3) -> f64 {
    let (_, b) = tilted();
    (p - b.c).dot(b.axis).signum()
}

#[test]
fn unequal_cylinders_on_tilted_offset_axes_give_two_loops_at_any_chordtol() {
    let (a, b) = tilted();
    let (sa, sb) = (a.surface(), b.surface());
    let loops = tilted_loops(200_000);
    let exact = [loops[0].1, loops[1].1];
    let rho = loops
        .iter()
        .map(|(pts, _)| least_radius(&pts[..]))
        .fold(f64::INFINITY, f64::min);
    let mut bad = Vec::new();
    for t in CHORDTOLS {
        let curves = surface_intersect_tol(&sa, &sb, t, 1e-9).unwrap();
        let one_side = |cv: &Polyline3| {
            let s = side(cv.points[0]);
            cv.points.iter().all(|p| side(*p) == s)
        };
        if curves.len() != 2
            || !curves.iter().all(|c| c.closed && one_side(c))
            || side(curves[0].points[0]) == side(curves[1].points[0])
        {
            bad.push((t, curves.len(), curves.iter().filter(|c| c.closed).count()));
            continue;
        }
        for cv in &curves {
            for p in &cv.points {
                assert!(a.off(*p) <= 1e-9 && b.off(*p) <= 1e-9, "{t}: {p}");
            }
            let want = exact[usize::from(side(cv.points[0]) < 0.0)];
            let l = cv.length();
            assert!(short_within(l, want, rho, t), "{t}: {l} vs {want}");
        }
    }
    assert!(bad.is_empty(), "(CHORDTOL, pieces, closed): {bad:?}");
}

#[test]
fn unequal_cylinders_on_tilted_offset_axes_have_their_lengths_to_1e_6() {
    let (a, b) = tilted();
    let (sa, sb) = (a.surface(), b.surface());
    let loops = tilted_loops(200_000);
    for seed in [0.02, 0.005] {
        let curves = surface_intersect_seeded(&sa, &sb, seed, 1e-6, 1e-9).unwrap();
        assert_eq!(curves.len(), 2, "{seed}");
        for cv in &curves {
            assert!(cv.closed, "{seed}");
            let want = loops[usize::from(side(cv.points[0]) < 0.0)].1;
            let l = cv.length();
            assert!(
                l <= want + 1e-9 && want - l < 1e-6 * want,
                "{seed}: {l} vs {want}"
            );
        }
    }
}

/// Two cylinders of radius 1 whose axes z and (0, sin 60°, cos 60°) cross at the origin: a
/// point on both is as far from each axis, so (p·a1)² = (p·a2)², and the crossing is the two
/// ellipses in the planes p·(a1 ∓ a2) = 0. They meet at the branch points ±x̂ (on both planes,
/// square to both axes), where the cylinders touch. The plane square to a1 − a2 makes half the
/// axes' angle ψ with it: semi-axes 1 and 1/sin(ψ/2) = 2; the other 1 and 1/cos(ψ/2).
fn at_sixty() -> (Cyl, Cyl, [DVec3; 2]) {
    let a1 = DVec3::Z;
    let psi = 60f64.to_radians();
    let a2 = DVec3::new(0.0, psi.sin(), psi.cos());
    let cyl = |axis| Cyl {
        c: DVec3::ZERO,
        axis,
        r: 1.0,
        half: 3.0,
    };
    (
        cyl(a1),
        cyl(a2),
        [(a1 - a2).normalize(), (a1 + a2).normalize()],
    )
}

/// The plane of [`at_sixty`] every point of `cv` is within 1e-9 of (0 or 1), if one is.
fn plane_of(cv: &Polyline3, normals: &[DVec3; 2]) -> Option<usize> {
    (0..2).find(|&k| cv.points.iter().all(|p| p.dot(normals[k]).abs() <= 1e-9))
}

#[test]
fn equal_cylinders_crossing_at_sixty_degrees_give_two_ellipses_at_any_chordtol() {
    let (a, b, normals) = at_sixty();
    let (sa, sb) = (a.surface(), b.surface());
    let half = 30f64.to_radians();
    let major = [1.0 / half.sin(), 1.0 / half.cos()];
    let exact = major.map(|m| ellipse_perimeter(m, 1.0));
    // Least radius of curvature of an ellipse: b²/a.
    let rho = major.map(|m| 1.0 / m);
    let mut bad = Vec::new();
    for t in CHORDTOLS {
        let curves = surface_intersect_tol(&sa, &sb, t, 1e-9).unwrap();
        let planes: Vec<Option<usize>> = curves.iter().map(|c| plane_of(c, &normals)).collect();
        if curves.len() != 2
            || !curves.iter().all(|c| c.closed)
            || !(planes.contains(&Some(0)) && planes.contains(&Some(1)))
        {
            bad.push((t, curves.len(), planes));
            continue;
        }
        for (cv, k) in curves.iter().zip(planes) {
            for p in &cv.points {
                assert!(a.off(*p) <= 1e-9 && b.off(*p) <= 1e-9, "{t}: {p}");
            }
            let k = k.unwrap();
            let l = cv.length();
            assert!(
                short_within(l, exact[k], rho[k], t),
                "{t}: {l} vs {}",
                exact[k]
            );
        }
    }
    assert!(bad.is_empty(), "(CHORDTOL, pieces, planes): {bad:?}");
}

#[test]
fn equal_cylinders_crossing_at_sixty_degrees_have_their_lengths_to_1e_6() {
    let (a, b, normals) = at_sixty();
    let (sa, sb) = (a.surface(), b.surface());
    let half = 30f64.to_radians();
    let exact = [1.0 / half.sin(), 1.0 / half.cos()].map(|m| ellipse_perimeter(m, 1.0));
    for seed in [0.02, 0.01, 0.005] {
        let curves = surface_intersect_seeded(&sa, &sb, seed, 1e-6, 1e-9).unwrap();
        assert_eq!(curves.len(), 2, "{seed}");
        for cv in &curves {
            assert!(cv.closed, "{seed}");
            let k = plane_of(cv, &normals).expect("on one plane");
            let l = cv.length();
            assert!(
                l <= exact[k] + 1e-9 && exact[k] - l < 1e-6 * exact[k],
                "{seed}: {l} vs {}",
                exact[k]
            );
        }
    }
}
