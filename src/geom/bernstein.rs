//! Polynomials in Bernstein form on [0, 1] and a root isolator that never loses a root.
//!
//! Root isolation follows the classical Bernstein subdivision scheme (Lane & Riesenfeld 1981;
//! Mørken & Reimers): the convex-hull property bounds the polynomial on an interval by its
//! coefficients, and the variation-diminishing property (Descartes' rule of signs in Bernstein
//! form) bounds the number of roots by the sign changes of the coefficients. An interval with
//! one sign change and opposite end values holds exactly one root, found by Newton's method
//! kept inside the shrinking bracket (bisecting where it leaves it). Where the derivative has
//! exactly one root the polynomial has one extremum, so both monotone halves are solved
//! separately: two roots however close stay two, and an extremum within the tolerance of zero
//! with no sign change is a tangency.

use std::ops::{Add, Mul};

use smallvec::SmallVec;

pub type Coeffs = SmallVec<[f64; 16]>;

/// Value at `t` by de Casteljau.
pub fn eval(c: &[f64], t: f64) -> f64 {
    eval_deriv(c, t).0
}

/// Value and first derivative at `t` from one de Casteljau pass (the derivative is
/// n·(b1 − b0) of the last-but-one level).
pub fn eval_deriv(c: &[f64], t: f64) -> (f64, f64) {
    let n = c.len();
    if n == 1 {
        return (c[0], 0.0);
    }
    let mut buf = [0.0f64; 24];
    let mut heap;
    let b: &mut [f64] = if n <= buf.len() {
        buf[..n].copy_from_slice(c);
        &mut buf[..n]
    } else {
        heap = c.to_vec();
        &mut heap
    };
    let u = 1.0 - t;
    for r in 1..n - 1 {
        for j in 0..n - r {
            b[j] = b[j] * u + b[j + 1] * t;
        }
    }
    (b[0] * u + b[1] * t, (n - 1) as f64 * (b[1] - b[0]))
}

/// The coefficients of the two halves split at `t`.
pub fn split(c: &[f64], t: f64) -> (Coeffs, Coeffs) {
    split_points(c, t)
}

/// De Casteljau subdivision at `t` of any control points that combine affinely: scalar
/// coefficients here, homogeneous points in `Bez::split`.
pub(crate) fn split_points<A>(c: &[A::Item], t: f64) -> (SmallVec<A>, SmallVec<A>)
where
    A: smallvec::Array,
    A::Item: Copy + Add<Output = A::Item> + Mul<f64, Output = A::Item>,
{
    let n = c.len();
    // Level r rewrites only b[..n - r], so b[n - 1 - r] keeps level r's last point: the
    // working array ends up holding the right half and needs no copy.
    let mut b: SmallVec<A> = SmallVec::from_slice(c);
    let mut left = SmallVec::with_capacity(n);
    let u = 1.0 - t;
    left.push(b[0]);
    for r in 1..n {
        for j in 0..n - r {
            b[j] = b[j] * u + b[j + 1] * t;
        }
        left.push(b[0]);
    }
    (left, b)
}

/// The derivative's coefficients: n·(c[i+1] − c[i]).
pub fn deriv(c: &[f64]) -> Coeffs {
    let n = (c.len() - 1) as f64;
    c.windows(2).map(|w| n * (w[1] - w[0])).collect()
}

fn binom(n: usize, k: usize) -> f64 {
    let mut r = 1.0;
    for i in 0..k.min(n - k) {
        r = r * (n - i) as f64 / (i + 1) as f64;
    }
    r
}

/// The product of two polynomials in Bernstein form (degree m + n).
pub fn mul(a: &[f64], b: &[f64]) -> Coeffs {
    let (m, n) = (a.len() - 1, b.len() - 1);
    let mut out: Coeffs = SmallVec::from_elem(0.0, m + n + 1);
    for (i, ai) in a.iter().enumerate() {
        let ci = binom(m, i);
        for (j, bj) in b.iter().enumerate() {
            out[i + j] += ci * binom(n, j) * ai * bj;
        }
    }
    for (k, o) in out.iter_mut().enumerate() {
        *o /= binom(m + n, k);
    }
    out
}

/// A root of a polynomial on [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Root {
    pub t: f64,
    /// A double root (the polynomial touches zero within tolerance at an extremum).
    pub tangent: bool,
    /// For a pair of simple roots flanking one extremum: that extremum, so the caller can
    /// merge the pair into one tangency when the two points are closer than its tolerance.
    pub extremum: Option<f64>,
}

impl Root {
    fn simple(t: f64) -> Root {
        Root {
            t,
            tangent: false,
            extremum: None,
        }
    }

    fn touch(t: f64) -> Root {
        Root {
            t,
            tangent: true,
            extremum: None,
        }
    }
}

fn sign_changes(c: &[f64]) -> usize {
    let mut n = 0;
    let mut last = 0.0;
    for &x in c {
        if x != 0.0 {
            if last != 0.0 && (x > 0.0) != (last > 0.0) {
                n += 1;
            }
            last = x;
        }
    }
    n
}

/// The single root of `c` in [0, 1] when c(0) and c(1) have opposite signs and c has one
/// sign change there: Newton's method kept inside a shrinking bracket, falling back to a
/// bisection step whenever Newton leaves the bracket or stops contracting.
fn solve_bracketed(c: &[f64]) -> f64 {
    let (mut a, mut b) = (0.0f64, 1.0f64);
    let neg_at_a = c[0] < 0.0;
    let (f0, f1) = (c[0], c[c.len() - 1]);
    let mut t = f0 / (f0 - f1);
    if !(t > 0.0 && t < 1.0) {
        t = 0.5;
    }
    let mut last_step = f64::INFINITY;
    for _ in 0..200 {
        let (ft, dt) = eval_deriv(c, t);
        if ft == 0.0 {
            return t;
        }
        if (ft < 0.0) == neg_at_a {
            a = t;
        } else {
            b = t;
        }
        if b - a <= 2.0 * f64::EPSILON * b.max(1e-300) {
            return t;
        }
        let nt = t - ft / dt;
        let step = (nt - t).abs();
        let next = if dt != 0.0 && nt > a && nt < b && step < 0.5 * last_step {
            last_step = step;
            nt
        } else {
            last_step = f64::INFINITY;
            0.5 * (a + b)
        };
        if (next - t).abs() <= f64::EPSILON * t.abs().max(1e-300) {
            return next;
        }
        t = next;
    }
    t
}

/// Every root of the polynomial `c` on [0, 1]: sign changes (simple roots, however close) and
/// touches within `tol` of zero (tangent roots). `tol` is in the units of the coefficients.
/// The end points count as roots when |c| <= tol there. Roots come out in increasing order.
pub fn roots(c: &[f64], tol: f64, out: &mut SmallVec<[Root; 8]>) {
    if c.len() < 2 {
        return;
    }
    let n = c.len() - 1;
    if c[0].abs() <= tol {
        out.push(Root::simple(0.0));
    }
    // Below this an extremum's value is rounding noise: a double root, not two roots.
    let noise = 64.0 * f64::EPSILON * c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    isolate(c, 0.0, 1.0, tol, noise, 0, out);
    if c[n].abs() <= tol && out.last().is_none_or(|r| r.t < 1.0) {
        out.push(Root::simple(1.0));
    }
}

fn push_interior(out: &mut SmallVec<[Root; 8]>, r: Root) {
    if r.t > 0.0 && r.t < 1.0 {
        out.push(r);
    }
}

fn isolate(
    c: &[f64],
    a: f64,
    b: f64,
    tol: f64,
    noise: f64,
    depth: u32,
    out: &mut SmallVec<[Root; 8]>,
) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &x in c {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if lo > tol || hi < -tol {
        return;
    }
    let n = c.len() - 1;
    // End values at rounding-noise level are zeros: no spurious sign change at a split point.
    let snap = |x: f64| if x.abs() <= noise.min(tol) { 0.0 } else { x };
    let (f0, f1) = (snap(c[0]), snap(c[n]));
    let w = b - a;
    if depth > 60 || w < 1e-15 {
        let fm = eval(c, 0.5);
        if fm.abs() <= tol {
            push_interior(out, Root::touch(a + 0.5 * w));
        }
        return;
    }
    let d = deriv(c);
    let vd = sign_changes(&d);
    if vd == 0 {
        // Monotone: at most one root, strictly inside only on a sign change; an exact zero at
        // the right end belongs to this interval (the next one starts with it).
        if f0 * f1 < 0.0 {
            push_interior(out, Root::simple(a + w * solve_bracketed(c)));
        } else if f1 == 0.0 && f0 != 0.0 {
            push_interior(out, Root::simple(b));
        }
        return;
    }
    if vd == 1 && d[0] * d[d.len() - 1] < 0.0 {
        // One extremum at te: solve each monotone side.
        let te = solve_bracketed(&d);
        let (l, r) = split(c, te);
        let fe = l[n];
        let tg = a + w * te;
        if fe.abs() <= noise.min(tol) {
            push_interior(out, Root::touch(tg));
            return;
        }
        let left = if f0 * fe < 0.0 {
            Some(a + w * te * solve_bracketed(&l))
        } else {
            None
        };
        let right = if fe * f1 < 0.0 {
            Some(tg + w * (1.0 - te) * solve_bracketed(&r))
        } else {
            None
        };
        match (left, right) {
            (Some(x), Some(y)) => {
                for t in [x, y] {
                    push_interior(
                        out,
                        Root {
                            t,
                            tangent: false,
                            extremum: Some(tg),
                        },
                    );
                }
            }
            (Some(x), None) | (None, Some(x)) => push_interior(out, Root::simple(x)),
            (None, None) => {
                if fe.abs() <= tol {
                    push_interior(out, Root::touch(tg));
                }
            }
        }
        if f1 == 0.0 {
            push_interior(out, Root::simple(b));
        }
        return;
    }
    let (l, r) = split(c, 0.5);
    let m = a + 0.5 * w;
    isolate(&l, a, m, tol, noise, depth + 1, out);
    isolate(&r, m, b, tol, noise, depth + 1, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bernstein coefficients of the monic polynomial with the given roots (product of
    /// linear factors (t − r) = (−r)·B0 + (1 − r)·B1).
    fn from_roots(rs: &[f64]) -> Coeffs {
        let mut c: Coeffs = SmallVec::from_slice(&[1.0]);
        for &r in rs {
            c = mul(&c, &[-r, 1.0 - r]);
        }
        c
    }

    fn all_roots(c: &[f64], tol: f64) -> Vec<f64> {
        let mut out = SmallVec::new();
        roots(c, tol, &mut out);
        out.iter().map(|r| r.t).collect()
    }

    #[test]
    fn finds_close_simple_roots() {
        let c = from_roots(&[0.3, 0.3 + 7e-6, 0.8]);
        let r = all_roots(&c, 1e-15);
        assert_eq!(r.len(), 3, "{r:?}");
        assert!((r[0] - 0.3).abs() < 1e-12 && (r[1] - 0.300007).abs() < 1e-12);
    }

    #[test]
    fn nine_roots() {
        let rs: Vec<f64> = (1..=9).map(|i| i as f64 / 10.0).collect();
        let c = from_roots(&rs);
        let r = all_roots(&c, 1e-18);
        assert_eq!(r.len(), 9);
        for (a, b) in r.iter().zip(&rs) {
            assert!((a - b).abs() < 1e-10);
        }
    }

    #[test]
    fn double_root_is_tangent() {
        let c = from_roots(&[0.4, 0.4]);
        let mut out = SmallVec::new();
        roots(&c, 1e-12, &mut out);
        assert_eq!(out.len(), 1);
        assert!(out[0].tangent && (out[0].t - 0.4).abs() < 1e-9);
    }

    #[test]
    fn product_evaluates_as_product() {
        let a = [1.0, -2.0, 0.5];
        let b = [0.3, 4.0];
        let p = mul(&a, &b);
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            assert!((eval(&p, t) - eval(&a, t) * eval(&b, t)).abs() < 1e-14);
        }
    }
}
