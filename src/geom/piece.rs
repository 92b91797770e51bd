//! The pieces every curve decomposes into — line segments, circular arcs and rational Bézier
//! spans — each with its range of the owning curve's public parameter. Algorithms that work on
//! any curve (length, nearest point, bounding box, flattening, area, intersection) are written
//! once against pieces.

use std::sync::OnceLock;

use glam::DVec3;

use super::arc::Arc;
use super::bezier::Bez;
use super::line::Line;
use super::traits::*;

/// One analytic or polynomial piece of a curve, over its own parameter s in [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub enum Piece {
    Line(Line),
    Arc(Arc),
    Bez(Bez),
}

/// A piece and the public parameter range [t0, t1] of the curve it belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Span {
    pub piece: Piece,
    pub t0: f64,
    pub t1: f64,
}

impl Span {
    /// The curve's public parameter at piece parameter `s`.
    #[inline]
    pub fn t_of(&self, s: f64) -> f64 {
        if s >= 1.0 {
            self.t1
        } else {
            self.t0 + (self.t1 - self.t0) * s
        }
    }
}

/// The public parameters where consecutive spans' derivatives (in that parameter) differ in
/// direction or size: a curve's creases ([`ParamCurve::creases`]).
pub(crate) fn span_creases(spans: &[Span]) -> Vec<f64> {
    let speed = |s: &Span, at: f64| s.piece.deriv(at) / (s.t1 - s.t0);
    spans
        .windows(2)
        .filter(|w| {
            let (a, b) = (speed(&w[0], 1.0), speed(&w[1], 0.0));
            // Smooth joins agree to rounding; 1e-9 of the speed is far above it.
            (a - b).length() > 1e-9 * a.length().max(b.length())
        })
        .map(|w| w[0].t1)
        .collect()
}

/// Gauss–Legendre nodes and weights on [0, 1] (16 points, computed once by Newton on P16).
pub(crate) fn gauss16() -> &'static [(f64, f64); 16] {
    static G: OnceLock<[(f64, f64); 16]> = OnceLock::new();
    G.get_or_init(|| {
        let n = 16;
        let mut out = [(0.0, 0.0); 16];
        for (i, slot) in out.iter_mut().enumerate() {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 0.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            *slot = (0.5 * (1.0 + x), 0.5 * w);
        }
        out
    })
}

fn gauss_speed(b: &Bez, a: f64, c: f64) -> f64 {
    let h = c - a;
    gauss16()
        .iter()
        .map(|(x, w)| w * b.deriv(a + h * x).length())
        .sum::<f64>()
        * h
}

/// Arc length of a Bézier piece between parameters a and c: exact for a polynomial quadratic
/// or line (`quad_length`), adaptive Gauss–Legendre otherwise.
pub(crate) fn bez_length(b: &Bez, a: f64, c: f64, accuracy: f64) -> f64 {
    if c <= a {
        return 0.0;
    }
    if !b.rational && b.h.len() <= 3 {
        let mut p = [DVec3::ZERO; 3];
        for (slot, q) in p.iter_mut().zip(b.points()) {
            *slot = q;
        }
        if b.h.len() == 2 {
            return (p[1] - p[0]).length() * (c - a);
        }
        if b.h.len() == 3 {
            return quad_length(p, a, c);
        }
    }
    adaptive_length(b, a, c, accuracy)
}

/// ∫ₐᶜ |B'(t)| dt for the polynomial quadratic Bézier with control points `p`.
///
/// B'(t) = u + t·v, so |B'(t)|² = |v|²((t − t*)² + k²) with t* = −u·v/|v|² and
/// k = |u × v|/|v|²: the speed is analytic except at the complex points t* ± ik. When those are
/// far from [a, c] (the Bernstein ellipse through them has ρ ≥ 4, i.e. the sum of their
/// distances to a and c is at least 2.125·(c − a)), one 16-point Gauss–Legendre rule is exact
/// to rounding (its error bound falls as ρ⁻³²), and the closed form below would cancel (t*
/// and k large: the nearly uniform, nearly straight piece). When they are near, the closed
/// form ½|v|[s·r(s) + k²·asinh(s/k)] over s = t − t* has every term of the size of the result
/// (|s|, k ≲ 2 there), so it keeps full precision, cusps (k → 0) and collinear controls
/// included, where Gauss–Legendre would need many subdivisions.
pub(crate) fn quad_length(p: [DVec3; 3], a: f64, c: f64) -> f64 {
    // From the differences of neighbouring points, which are exact when they are close, so a
    // small piece far from the origin keeps its digits.
    let (d0, d1) = (p[1] - p[0], p[2] - p[1]);
    let u = 2.0 * d0;
    let v = 2.0 * (d1 - d0);
    let vv = v.length_squared();
    let h = c - a;
    if vv == 0.0 {
        return u.length() * h;
    }
    let ts = -u.dot(v) / vv;
    let k = u.cross(v).length() / vv;
    let far = (ts - a).hypot(k) + (ts - c).hypot(k) >= 2.125 * h;
    if far || !ts.is_finite() || !k.is_finite() {
        return gauss16()
            .iter()
            .map(|(x, w)| w * (u + v * (a + h * x)).length())
            .sum::<f64>()
            * h;
    }
    let (s0, s1) = (a - ts, c - ts);
    let (r0, r1) = (s0.hypot(k), s1.hypot(k));
    let logs = if k > 0.0 {
        k * k * (asinh_ratio(s1, k) - asinh_ratio(s0, k))
    } else {
        0.0
    };
    0.5 * vv.sqrt() * (s1 * r1 - s0 * r0 + logs)
}

/// asinh(s/k) for k > 0, without overflow when k is tiny: ln((|s| + √(s² + k²))/k), signed.
fn asinh_ratio(s: f64, k: f64) -> f64 {
    let x = s / k;
    if x.abs() < 1e300 {
        x.asinh()
    } else {
        ((s.abs() + s.hypot(k)).ln() - k.ln()).copysign(s)
    }
}

/// Arc length of a Bézier piece between parameters a and c, adaptive Gauss–Legendre.
fn adaptive_length(b: &Bez, a: f64, c: f64, accuracy: f64) -> f64 {
    fn rec(b: &Bez, a: f64, c: f64, whole: f64, acc: f64, depth: u32) -> f64 {
        let m = 0.5 * (a + c);
        let l = gauss_speed(b, a, m);
        let r = gauss_speed(b, m, c);
        if depth > 20 || (l + r - whole).abs() <= acc {
            l + r
        } else {
            rec(b, a, m, l, acc * 0.5, depth + 1) + rec(b, m, c, r, acc * 0.5, depth + 1)
        }
    }
    let whole = gauss_speed(b, a, c);
    rec(b, a, c, whole, accuracy.max(1e-15), 0)
}

impl Piece {
    #[inline]
    pub fn eval(&self, s: f64) -> DVec3 {
        match self {
            Piece::Line(l) => l.eval(s),
            Piece::Arc(a) => a.eval(s),
            Piece::Bez(b) => b.eval(s),
        }
    }

    /// dP/ds.
    #[inline]
    pub fn deriv(&self, s: f64) -> DVec3 {
        match self {
            Piece::Line(l) => l.dir(),
            Piece::Arc(a) => a.deriv(s),
            Piece::Bez(b) => b.deriv(s),
        }
    }

    pub fn length(&self, accuracy: f64) -> f64 {
        match self {
            Piece::Line(l) => l.arclen(accuracy),
            Piece::Arc(a) => a.arclen(accuracy),
            Piece::Bez(b) => bez_length(b, 0.0, 1.0, accuracy),
        }
    }

    /// The piece parameter at arc length `len` from its start (clamped).
    pub fn param_at_length(&self, len: f64, accuracy: f64) -> f64 {
        match self {
            Piece::Line(l) => (len / l.dir().length()).clamp(0.0, 1.0),
            Piece::Arc(a) => (len / (a.radius * a.sweep)).clamp(0.0, 1.0),
            Piece::Bez(b) => {
                // Newton on L(s) − len with a bisection bracket.
                let (mut lo, mut hi) = (0.0, 1.0);
                let total = bez_length(b, 0.0, 1.0, accuracy);
                let mut s = (len / total).clamp(0.0, 1.0);
                for _ in 0..60 {
                    let f = bez_length(b, 0.0, s, accuracy) - len;
                    if f.abs() <= accuracy {
                        break;
                    }
                    if f > 0.0 {
                        hi = s;
                    } else {
                        lo = s;
                    }
                    let sp = b.deriv(s).length();
                    let next = s - f / sp;
                    s = if sp > 0.0 && next > lo && next < hi {
                        next
                    } else {
                        0.5 * (lo + hi)
                    };
                }
                s
            }
        }
    }

    /// (s, point) nearest to `p`.
    pub fn nearest(&self, p: DVec3) -> (f64, DVec3) {
        match self {
            Piece::Line(l) => l.nearest(p, 0.0),
            Piece::Arc(a) => a.nearest(p, 0.0),
            Piece::Bez(b) => bez_nearest(b, p),
        }
    }

    /// A tight axis-aligned box.
    pub fn bbox(&self) -> (DVec3, DVec3) {
        match self {
            Piece::Line(l) => l.bbox(),
            Piece::Arc(a) => a.bbox(),
            Piece::Bez(b) => {
                let (p, q) = (b.eval(0.0), b.eval(1.0));
                let (mut lo, mut hi) = (p.min(q), p.max(q));
                let mut ts = Vec::new();
                for axis in 0..3 {
                    ts.clear();
                    b.critical_params(axis, &mut ts);
                    for &t in &ts {
                        let v = b.eval(t)[axis];
                        lo[axis] = lo[axis].min(v);
                        hi[axis] = hi[axis].max(v);
                    }
                }
                (lo, hi)
            }
        }
    }

    /// A cheap box that contains the piece (hull box for Béziers).
    pub fn hull_bbox(&self) -> (DVec3, DVec3) {
        match self {
            Piece::Bez(b) => b.hull_bbox(),
            _ => self.bbox(),
        }
    }

    /// Append the points of a polyline within `tol` of the piece, excluding its start point.
    pub fn flatten(&self, tol: f64, out: &mut Vec<DVec3>) {
        match self {
            Piece::Line(l) => out.push(l.p1),
            Piece::Arc(a) => {
                let ratio = (1.0 - tol / a.radius).max(-1.0);
                let step = 2.0 * ratio.acos();
                let n = ((a.sweep / step).ceil() as usize).clamp(1, 1 << 20);
                for i in 1..=n {
                    out.push(a.eval(i as f64 / n as f64));
                }
            }
            Piece::Bez(b) => flatten_bez(b, tol, 0, out),
        }
    }

    /// ½∫ P × dP over the piece: summed over a closed planar curve it is area × unit normal
    /// (the vector form of Green's theorem).
    pub fn vector_area(&self) -> DVec3 {
        match self {
            Piece::Line(l) => 0.5 * l.p0.cross(l.p1),
            Piece::Arc(a) => {
                let (x, y) = (a.x_axis, a.y_axis);
                let e = |t: f64| x * t.cos() + y * t.sin();
                let (t0, t1) = (a.start, a.start + a.sweep);
                0.5 * (a.center.cross(e(t1) - e(t0)) * a.radius
                    + a.normal * (a.radius * a.radius * a.sweep))
            }
            Piece::Bez(b) => {
                // P × P' is a polynomial of degree 2n − 1: 16 Gauss points are exact up to
                // n = 16; rational pieces are split to keep the quadrature error negligible.
                let parts = if b.rational { 8 } else { 1 };
                let mut acc = DVec3::ZERO;
                for k in 0..parts {
                    let (a0, a1) = (k as f64 / parts as f64, (k + 1) as f64 / parts as f64);
                    for (x, w) in gauss16() {
                        let s = a0 + (a1 - a0) * x;
                        let (p, d) = b.eval_deriv(s);
                        acc += p.cross(d) * (w * (a1 - a0));
                    }
                }
                0.5 * acc
            }
        }
    }
}

fn flatten_bez(b: &Bez, tol: f64, depth: u32, out: &mut Vec<DVec3>) {
    if depth >= 24 || b.flatness() <= tol {
        out.push(b.eval(1.0));
        return;
    }
    let (l, r) = b.split(0.5);
    flatten_bez(&l, tol, depth + 1, out);
    flatten_bez(&r, tol, depth + 1, out);
}

/// Nearest point on a Bézier: dense sampling, then golden-section search on the squared
/// distance around the best samples (the distance is unimodal between adjacent samples once
/// the sampling resolves the curve's turning).
fn bez_nearest(b: &Bez, p: DVec3) -> (f64, DVec3) {
    let n = 8 * (b.degree() + 1);
    let d2 = |t: f64| (b.eval(t) - p).length_squared();
    let mut samples: Vec<(f64, f64)> = (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            (d2(t), t)
        })
        .collect();
    samples.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best = samples[0];
    let h = 1.0 / n as f64;
    for &(_, t0) in samples.iter().take(3) {
        let (a, c) = ((t0 - h).max(0.0), (t0 + h).min(1.0));
        let t = crate::geom::minimize::golden_section_min(d2, a, c, 80, 1e-15);
        let f = d2(t);
        if f < best.0 {
            best = (f, t);
        }
    }
    (best.1, b.eval(best.1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// An independent reference, with a fixed amount of work: the speed |B'| from the
    /// hodograph's control points 2(p1 − p0) and 2(p2 − p1) (differences of nearby points are
    /// exact, so a tiny piece far from the origin keeps its digits), integrated by 16-point
    /// Gauss–Legendre on intervals that halve towards the speed's minimum on each side of it
    /// (found by golden section on |B'|², a convex quadratic). Every interval is at least its
    /// own length away from the minimum, and so from the speed's kink or complex near-kink,
    /// which puts the rule's error near rounding; 60 halvings leave an uncovered sliver of
    /// 2⁻⁶⁰ of the range, beyond what a 1e-12 check can see.
    fn reference(p: [DVec3; 3], a: f64, c: f64) -> f64 {
        let (d0, d1) = (2.0 * (p[1] - p[0]), 2.0 * (p[2] - p[1]));
        let speed = |t: f64| (d0 * (1.0 - t) + d1 * t).length();
        let gauss = |lo: f64, hi: f64| {
            gauss16()
                .iter()
                .map(|(x, w)| w * speed(lo + (hi - lo) * x))
                .sum::<f64>()
                * (hi - lo)
        };
        let tm = crate::geom::minimize::golden_section_min(|t| speed(t).powi(2), a, c, 200, 1e-16);
        let towards = |from: f64| {
            let mut sum = 0.0;
            let mut far = from;
            for j in 1..=60 {
                let near = tm + (from - tm) * 0.5f64.powi(j);
                sum += gauss(far.min(near), far.max(near));
                far = near;
            }
            sum
        };
        towards(a) + towards(c)
    }

    fn check(p: [DVec3; 3], a: f64, c: f64) -> Result<(), TestCaseError> {
        check_with(p, a, c, false)
    }

    /// `before`: also compare with the adaptive rule used until now, which is only as good at
    /// 1e-12 away from cusps (at one, the halves can agree with the whole by accident: off by
    /// 2e-11 on a collinear out-and-back piece the exact value settles).
    fn check_with(p: [DVec3; 3], a: f64, c: f64, before: bool) -> Result<(), TestCaseError> {
        let b = Bez::from_points(&p);
        let got = bez_length(&b, a, c, 1e-13);
        let want = reference(p, a, c);
        let scale = want.max(1e-300);
        prop_assert!(
            (got - want).abs() <= 1e-12 * scale,
            "{p:?} on [{a}, {c}]: {got} against {want} (rel {:e})",
            (got - want) / scale
        );
        if before {
            let size = p.iter().map(|q| q.abs().max_element()).fold(1.0, f64::max);
            let old = adaptive_length(&b, a, c, 1e-13 * size);
            prop_assert!(
                (got - old).abs() <= 1e-12 * scale,
                "{got} against {old} before"
            );
        }
        Ok(())
    }

    fn pt() -> impl Strategy<Value = DVec3> {
        (-100.0..100.0f64, -100.0..100.0f64, -1.0..1.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
    }

    fn range() -> impl Strategy<Value = (f64, f64)> {
        prop_oneof![
            Just((0.0, 1.0)),
            (0.0..1.0f64, 0.0..1.0f64).prop_map(|(a, c)| (a.min(c), a.max(c) + 1e-9)),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        #[test]
        fn quadratic_length_matches_reference(p0 in pt(), p1 in pt(), p2 in pt(), r in range()) {
            check_with([p0, p1, p2], r.0, r.1, true)?;
        }

        /// Collinear controls with the middle one beyond an end: the piece runs out and back,
        /// its speed zero at an interior cusp; perturbed by `eps` across the line: a near-cusp.
        #[test]
        fn cusps_and_near_cusps(p0 in pt(), d in pt(), lam in -3.0..4.0f64,
                                eps in prop_oneof![Just(0.0), (-12.0..-6.0f64).prop_map(|e| 10f64.powf(e))], r in range()) {
            let p2 = p0 + d;
            let across = DVec3::new(-d.y, d.x, 0.0).normalize_or_zero();
            let p1 = p0 + d * lam + across * eps;
            check([p0, p1, p2], r.0, r.1)?;
        }

        /// Nearly uniform, nearly straight pieces (the closed form would cancel there), a
        /// control point on an end (zero speed at the end), and points all equal.
        #[test]
        fn nearly_degenerate(p0 in pt(), d in pt(), off in pt(),
                             eps in prop_oneof![Just(0.0), (-12.0..-3.0f64).prop_map(|e| 10f64.powf(e))], r in range()) {
            let p2 = p0 + d;
            check([p0, p0 + 0.5 * d + off * eps, p2], r.0, r.1)?;
            check([p0, p0 + off * eps, p2], r.0, r.1)?;
            check([p0, p2 + off * eps, p2], r.0, r.1)?;
            check([p0, p0 + off * eps, p0 + off * (eps * 0.5)], r.0, r.1)?;
        }
    }

    #[test]
    fn exact_values() {
        let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        // Out and back along x: two straight runs of 1/2 each way.
        let b = Bez::from_points(&[p(0.0, 0.0), p(1.0, 0.0), p(0.0, 0.0)]);
        assert!((bez_length(&b, 0.0, 1.0, 1e-13) - 1.0).abs() < 1e-15);
        // A straight, uniformly parameterised piece and a zero-length one.
        let b = Bez::from_points(&[p(0.0, 0.0), p(1.5, 2.0), p(3.0, 4.0)]);
        assert!((bez_length(&b, 0.25, 0.75, 1e-13) - 2.5).abs() < 1e-15);
        let b = Bez::from_points(&[p(2.0, 3.0), p(2.0, 3.0), p(2.0, 3.0)]);
        assert_eq!(bez_length(&b, 0.0, 1.0, 1e-13), 0.0);
        // y = x² for x in [0, 1]: (2√5 + asinh 2)/4.
        let b = Bez::from_points(&[p(0.0, 0.0), p(0.5, 0.0), p(1.0, 1.0)]);
        let want = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
        assert!((bez_length(&b, 0.0, 1.0, 1e-13) - want).abs() < 4e-16 * want);
    }
}
