//! Measures up to a parameter and second derivatives: what AutoCAD's `vlax-curve-*` family
//! needs beyond `Curve`'s queries (distance from the start to a parameter, d²P/dt²), and the
//! exact derivatives of a NURBS curve at its natural parameter u (The NURBS Book, A2.3 for the
//! basis function derivatives, eq. 4.8 for the rational quotient).

use glam::{DVec3, DVec4};

use super::bspline::BSpline;
use super::curve::Curve;
use super::piece::{bez_length, Piece, Span};
use super::traits::ParamCurve;

/// Relative accuracy of partial arc lengths (as `Curve::length`).
const LEN_ACC: f64 = 1e-13;

impl Curve {
    /// The arc length from the start to public parameter `t` (clamped to [0, 1]).
    pub fn length_to(&self, t: f64) -> f64 {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        match self {
            Curve::Line(_) | Curve::Circle(_) | Curve::Arc(_) => self.length() * t,
            _ => {
                let acc = LEN_ACC * self.scale();
                let mut total = 0.0;
                for sp in self.spans() {
                    if sp.t1 <= t {
                        total += sp.piece.length(acc);
                        continue;
                    }
                    if sp.t0 < t {
                        total += piece_length_to(&sp, t, acc);
                    }
                    break;
                }
                total
            }
        }
    }

    /// d²P/dt² at public parameter `t` (clamped to [0, 1]).
    pub fn second_deriv(&self, t: f64) -> DVec3 {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        match self {
            Curve::Line(_) => DVec3::ZERO,
            Curve::Circle(c) => {
                let a = c.as_arc();
                -(a.sweep * a.sweep) * (a.eval(t) - a.center)
            }
            Curve::Arc(a) => -(a.sweep * a.sweep) * (a.eval(t) - a.center),
            Curve::BSpline(b) => {
                let (lo, hi) = b.domain();
                derivs_u(b, lo + (hi - lo) * t)[2] * (hi - lo) * (hi - lo)
            }
            _ => {
                let spans = self.spans();
                let i = spans.partition_point(|s| s.t1 <= t).min(spans.len() - 1);
                let sp = &spans[i];
                let w = sp.t1 - sp.t0;
                let s = ((t - sp.t0) / w).clamp(0.0, 1.0);
                let d2 = match &sp.piece {
                    Piece::Line(_) => DVec3::ZERO,
                    Piece::Arc(a) => -(a.sweep * a.sweep) * (a.eval(s) - a.center),
                    Piece::Bez(b) => {
                        // Rational quadratic/cubic spans of splines: differentiate the
                        // homogeneous form exactly.
                        let pts: Vec<DVec4> = b.h.to_vec();
                        bez_second_deriv(&pts, s)
                    }
                };
                d2 / (w * w)
            }
        }
    }
}

/// A curve's spans with their cumulative lengths, for many length queries on one curve (the
/// vlax-curve loops of published routines): a query measures one span, not the whole curve.
pub struct Measured {
    spans: Vec<Span>,
    /// `cum[i]`: the length before span i; the last entry is the total.
    cum: Vec<f64>,
    acc: f64,
}

impl Measured {
    pub fn new(c: &Curve) -> Measured {
        let acc = LEN_ACC * c.scale();
        let spans = c.spans();
        let mut cum = Vec::with_capacity(spans.len() + 1);
        let mut total = 0.0;
        cum.push(0.0);
        for sp in &spans {
            total += sp.piece.length(acc);
            cum.push(total);
        }
        Measured { spans, cum, acc }
    }

    pub fn total(&self) -> f64 {
        self.cum[self.cum.len() - 1]
    }

    /// As `Curve::length_to`.
    pub fn length_to(&self, t: f64) -> f64 {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let i = self
            .spans
            .partition_point(|s| s.t1 <= t)
            .min(self.spans.len() - 1);
        self.cum[i] + piece_length_to(&self.spans[i], t, self.acc)
    }

    /// As `Curve::param_at_length`, None outside [0, total] (beyond a relative 1e-12 slack).
    pub fn param_at_length(&self, s: f64) -> Option<f64> {
        let total = self.total();
        let slack = 1e-12 * total.max(1.0);
        if !s.is_finite() || s < -slack || s > total + slack {
            return None;
        }
        let s = s.clamp(0.0, total);
        let i = (self.cum.partition_point(|c| *c <= s).max(1) - 1).min(self.spans.len() - 1);
        let sp = &self.spans[i];
        Some(sp.t_of(sp.piece.param_at_length(s - self.cum[i], self.acc)))
    }
}

/// The length of a span's piece from its start to public parameter t inside it.
fn piece_length_to(sp: &Span, t: f64, acc: f64) -> f64 {
    let s = ((t - sp.t0) / (sp.t1 - sp.t0)).clamp(0.0, 1.0);
    match &sp.piece {
        Piece::Line(_) | Piece::Arc(_) => sp.piece.length(acc) * s,
        Piece::Bez(b) => bez_length(b, 0.0, s, acc),
    }
}

/// d²/ds² of a rational Bézier given by homogeneous control points at `s`.
fn bez_second_deriv(h: &[DVec4], s: f64) -> DVec3 {
    let n = h.len() - 1;
    // Homogeneous derivatives by de Casteljau on the difference polygons.
    let eval = |pts: &[DVec4]| -> DVec4 {
        let mut v = pts.to_vec();
        for r in 1..v.len() {
            for j in 0..v.len() - r {
                v[j] = v[j] * (1.0 - s) + v[j + 1] * s;
            }
        }
        v.first().copied().unwrap_or(DVec4::ZERO)
    };
    let d1: Vec<DVec4> = h.windows(2).map(|w| (w[1] - w[0]) * n as f64).collect();
    let d2: Vec<DVec4> = if n >= 2 {
        d1.windows(2)
            .map(|w| (w[1] - w[0]) * (n - 1) as f64)
            .collect()
    } else {
        vec![DVec4::ZERO]
    };
    rational_second(eval(h), eval(&d1), eval(&d2))
}

/// C'' of C = A/w from the homogeneous value and derivatives (A, w), (A', w'), (A'', w'').
fn rational_second(p: DVec4, d1: DVec4, d2: DVec4) -> DVec3 {
    let w = p.w;
    let c = p.truncate() / w;
    let c1 = (d1.truncate() - c * d1.w) / w;
    (d2.truncate() - c1 * (2.0 * d1.w) - c * d2.w) / w
}

/// Point, first and second derivative of a B-spline at its natural parameter `u` (clamped to
/// the domain), exact (rational splines by the quotient rule).
pub fn derivs_u(b: &BSpline, u: f64) -> [DVec3; 3] {
    let (lo, hi) = b.domain();
    let u = u.clamp(lo, hi);
    let p = b.degree;
    let k = b.find_span(u);
    let ders = ders_basis(k, u, p, &b.knots);
    let mut h = [DVec4::ZERO; 3];
    for (order, hk) in h.iter_mut().enumerate() {
        if order > p {
            break;
        }
        for (j, n) in ders[order].iter().enumerate() {
            let i = k - p + j;
            let w = b.weights.as_ref().map_or(1.0, |w| w[i]);
            *hk += (b.ctrl[i] * w).extend(w) * *n;
        }
    }
    let w = h[0].w;
    let c = h[0].truncate() / w;
    let c1 = (h[1].truncate() - c * h[1].w) / w;
    [c, c1, rational_second(h[0], h[1], h[2])]
}

/// Basis functions N_{k-p..k, p} and their first two derivatives at u (A2.3, n = 2).
fn ders_basis(k: usize, u: f64, p: usize, knots: &[f64]) -> [Vec<f64>; 3] {
    let mut ndu = vec![vec![0.0; p + 1]; p + 1];
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[k + 1 - j];
        right[j] = knots[k + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = [vec![0.0; p + 1], vec![0.0; p + 1], vec![0.0; p + 1]];
    for j in 0..=p {
        ders[0][j] = ndu[j][p];
    }
    let n = 2.min(p);
    let mut a = [vec![0.0; p + 1], vec![0.0; p + 1]];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for kk in 1..=n {
            let mut d = 0.0;
            let rk = r as isize - kk as isize;
            let pk = p - kk;
            if r >= kk {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk as usize];
                d = a[s2][0] * ndu[rk as usize][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r as isize - 1 <= pk as isize {
                kk - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][idx];
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][kk] = -a[s1][kk - 1] / ndu[pk + 1][r];
                d += a[s2][kk] * ndu[r][pk];
            }
            ders[kk][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut f = p as f64;
    for (kk, row) in ders.iter_mut().enumerate().skip(1).take(n) {
        for v in row.iter_mut() {
            *v *= f;
        }
        f *= (p - kk) as f64;
    }
    ders
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spline_derivatives_match_differences() {
        let ctrl: Vec<DVec3> = (0..7)
            .map(|i| DVec3::new(i as f64, ((i * 5) % 3) as f64, ((i * 7) % 4) as f64 * 0.5))
            .collect();
        for p in 1..=4 {
            for w in [None, Some(vec![1.0, 2.0, 0.5, 1.0, 1.5, 0.7, 1.2])] {
                let b = BSpline::new(p, ctrl.clone(), None, w).unwrap();
                let (lo, hi) = b.domain();
                for i in 1..20 {
                    let u = lo + (hi - lo) * i as f64 / 20.0 + 1e-3;
                    let [c, d1, d2] = derivs_u(&b, u);
                    assert!((c - b.eval_u(u)).length() < 1e-12);
                    let h = 1e-5;
                    let fd1 = (b.eval_u(u + h) - b.eval_u(u - h)) / (2.0 * h);
                    let fd2 = (derivs_u(&b, u + h)[1] - derivs_u(&b, u - h)[1]) / (2.0 * h);
                    assert!((d1 - fd1).length() < 1e-6 * (1.0 + d1.length()), "p{p} {u}");
                    if p >= 2 {
                        assert!((d2 - fd2).length() < 1e-5 * (1.0 + d2.length()), "p{p} {u}");
                    }
                }
            }
        }
    }

    #[test]
    fn partial_lengths_add_up() {
        let c = Curve::pline(
            vec![
                DVec3::ZERO,
                DVec3::new(3.0, 0.0, 0.0),
                DVec3::new(3.0, 4.0, 0.0),
            ],
            false,
            Some(vec![0.0, 1.0, 0.0]),
        )
        .unwrap();
        assert!((c.length_to(0.5) - 3.0).abs() < 1e-12);
        assert!((c.length_to(1.0) - c.length()).abs() < 1e-12);
        // Half of the semicircle of diameter 4.
        assert!((c.length_to(0.75) - 3.0 - std::f64::consts::PI).abs() < 1e-12);
    }
}
