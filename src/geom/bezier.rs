//! Rational Bézier pieces in homogeneous form (w·P, w): the common currency of spline
//! algorithms. A QuadSpline segment is a degree-2 piece with unit weights; a B-spline span is
//! one piece of `BSpline::to_beziers`. De Casteljau in homogeneous coordinates evaluates and
//! splits both (Farin, Curves and Surfaces for CAGD, ch. 13).

use glam::{DVec3, DVec4};
use smallvec::SmallVec;

use super::bernstein::{self, Coeffs};

/// A (possibly rational) Bézier curve over [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct Bez {
    /// Homogeneous control points (w·P, w), all w > 0.
    pub h: SmallVec<[DVec4; 4]>,
    pub rational: bool,
}

impl Bez {
    pub fn from_points(pts: &[DVec3]) -> Bez {
        Bez {
            h: pts.iter().map(|p| p.extend(1.0)).collect(),
            rational: false,
        }
    }

    pub fn from_weighted(pts: &[DVec3], w: &[f64]) -> Bez {
        let rational = w.iter().any(|x| *x != w[0]);
        Bez {
            h: pts
                .iter()
                .zip(w)
                .map(|(p, w)| (*p * *w).extend(*w))
                .collect(),
            rational,
        }
    }

    pub fn degree(&self) -> usize {
        self.h.len() - 1
    }

    /// The Cartesian control points.
    pub fn points(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.h.iter().map(|h| h.truncate() / h.w)
    }

    fn casteljau(&self, t: f64) -> (DVec4, DVec4, DVec4) {
        // Returns the point and the two points of the last level (for the derivative).
        let mut b: SmallVec<[DVec4; 8]> = SmallVec::from_slice(&self.h);
        let n = b.len();
        let u = 1.0 - t;
        if n == 1 {
            return (b[0], b[0], b[0]);
        }
        for r in 1..n - 1 {
            for j in 0..n - r {
                b[j] = b[j] * u + b[j + 1] * t;
            }
        }
        (b[0] * u + b[1] * t, b[0], b[1])
    }

    #[inline]
    pub fn eval(&self, t: f64) -> DVec3 {
        let (p, _, _) = self.casteljau(t);
        p.truncate() / p.w
    }

    /// dP/dt by the quotient rule on the homogeneous curve.
    pub fn deriv(&self, t: f64) -> DVec3 {
        let (p, a, b) = self.casteljau(t);
        let dh = (b - a) * self.degree() as f64;
        (dh.truncate() * p.w - p.truncate() * dh.w) / (p.w * p.w)
    }

    /// The point and derivative at `t`.
    pub fn eval_deriv(&self, t: f64) -> (DVec3, DVec3) {
        let (p, a, b) = self.casteljau(t);
        let dh = (b - a) * self.degree() as f64;
        let pt = p.truncate() / p.w;
        (pt, (dh.truncate() - pt * dh.w) / p.w)
    }

    /// The two halves at `t`.
    pub fn split(&self, t: f64) -> (Bez, Bez) {
        let (left, right) = bernstein::split_points(&self.h, t);
        (
            Bez {
                h: left,
                rational: self.rational,
            },
            Bez {
                h: right,
                rational: self.rational,
            },
        )
    }

    /// The piece between t0 and t1 (t0 < t1).
    pub fn subsegment(&self, t0: f64, t1: f64) -> Bez {
        let (_, right) = self.split(t0);
        if t0 >= 1.0 {
            return right;
        }
        let (mid, _) = right.split(((t1 - t0) / (1.0 - t0)).clamp(0.0, 1.0));
        mid
    }

    /// The control hull's bounding box (contains the curve since all weights are positive).
    pub fn hull_bbox(&self) -> (DVec3, DVec3) {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for p in self.points() {
            lo = lo.min(p);
            hi = hi.max(p);
        }
        (lo, hi)
    }

    /// The largest distance of a control point from the chord (a flatness bound).
    pub fn flatness(&self) -> f64 {
        let a = self.h[0].truncate() / self.h[0].w;
        let l = self.h.len() - 1;
        let b = self.h[l].truncate() / self.h[l].w;
        let d = b - a;
        let dd = d.length_squared();
        let mut m: f64 = 0.0;
        for p in self.points() {
            let v = p - a;
            let dist2 = if dd > 0.0 {
                let t = (v.dot(d) / dd).clamp(0.0, 1.0);
                (v - d * t).length_squared()
            } else {
                v.length_squared()
            };
            m = m.max(dist2);
        }
        m.sqrt()
    }

    /// Bernstein coefficients of the scalar w(t)·(n·(P(t) − o)) : the signed distance to the
    /// plane through `o` with unit normal `n`, times the weight (same sign, same roots).
    pub fn plane_fn(&self, o: DVec3, n: DVec3) -> Coeffs {
        self.h
            .iter()
            .map(|h| n.dot(h.truncate()) - h.w * n.dot(o))
            .collect()
    }

    /// Bernstein coefficients of w(t)²·(|P(t) − c|² − r²): zero on the sphere.
    pub fn sphere_fn(&self, c: DVec3, r: f64) -> Coeffs {
        let mut acc: Option<Coeffs> = None;
        for i in 0..3 {
            let x: Coeffs = self.h.iter().map(|h| h[i] - h.w * c[i]).collect();
            let sq = bernstein::mul(&x, &x);
            acc = Some(match acc {
                None => sq,
                Some(a) => a.iter().zip(&sq).map(|(a, b)| a + b).collect(),
            });
        }
        let w: Coeffs = self.h.iter().map(|h| h.w).collect();
        let ww = bernstein::mul(&w, &w);
        acc.unwrap()
            .iter()
            .zip(&ww)
            .map(|(a, b)| a - r * r * b)
            .collect()
    }

    /// The weights' range (1, 1) for a non-rational piece.
    pub fn weight_range(&self) -> (f64, f64) {
        let mut lo = f64::INFINITY;
        let mut hi: f64 = 0.0;
        for h in &self.h {
            lo = lo.min(h.w);
            hi = hi.max(h.w);
        }
        (lo, hi)
    }

    /// Parameters where coordinate `axis` has a critical point (for a tight bounding box).
    pub fn critical_params(&self, axis: usize, out: &mut Vec<f64>) {
        let x: Coeffs = self.h.iter().map(|h| h[axis]).collect();
        let num: Coeffs = if self.rational {
            let w: Coeffs = self.h.iter().map(|h| h.w).collect();
            let a = bernstein::mul(&bernstein::deriv(&x), &w);
            let b = bernstein::mul(&x, &bernstein::deriv(&w));
            a.iter().zip(&b).map(|(a, b)| a - b).collect()
        } else {
            bernstein::deriv(&x)
        };
        if num.len() < 2 {
            return;
        }
        let mut roots = SmallVec::new();
        bernstein::roots(&num, 0.0, &mut roots);
        out.extend(roots.iter().map(|r| r.t));
    }
}
