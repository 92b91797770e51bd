//! General B-spline / NURBS curve: degree p, control points P_i, a full knot vector of
//! n + p + 1 values, optional weights (rational when present).
//!
//! Natural parameter: u in [knots[p], knots[n]]; the public `ParamCurve` parameter t in [0, 1]
//! maps linearly onto it. Evaluation is de Boor's algorithm in homogeneous coordinates
//! (Piegl & Tiller, The NURBS Book, A4.1 with A2.1's span search).

use glam::{DVec3, DVec4};

use super::traits::ParamCurve;

/// A B-spline or NURBS curve in 3D.
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline {
    pub degree: usize,
    pub ctrl: Vec<DVec3>,
    /// The full knot vector: `ctrl.len() + degree + 1` non-decreasing values.
    pub knots: Vec<f64>,
    /// One positive weight per control point, or `None` for a non-rational spline.
    pub weights: Option<Vec<f64>>,
}

/// Why a set of B-spline data was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BSplineError {
    #[error("degree must be at least 1, got {0}")]
    Degree(usize),
    #[error("need at least degree + 1 = {need} control points, got {got}")]
    TooFewPoints { need: usize, got: usize },
    #[error("knot vector must have {need} values (control points + degree + 1), got {got}")]
    KnotCount { need: usize, got: usize },
    #[error("knots must be finite and non-decreasing")]
    KnotOrder,
    #[error("the knot vector's active range is empty")]
    EmptyDomain,
    #[error("need one weight per control point ({need}), got {got}")]
    WeightCount { need: usize, got: usize },
    #[error("weights must be finite and positive")]
    WeightValue,
    #[error("control points must be finite")]
    NonFinite,
}

impl BSpline {
    /// A checked B-spline. `knots: None` gives the clamped uniform knot vector.
    pub fn new(
        degree: usize,
        ctrl: Vec<DVec3>,
        knots: Option<Vec<f64>>,
        weights: Option<Vec<f64>>,
    ) -> Result<Self, BSplineError> {
        if degree < 1 {
            return Err(BSplineError::Degree(degree));
        }
        if ctrl.len() < degree + 1 {
            return Err(BSplineError::TooFewPoints {
                need: degree + 1,
                got: ctrl.len(),
            });
        }
        if ctrl.iter().any(|p| !p.is_finite()) {
            return Err(BSplineError::NonFinite);
        }
        let knots = match knots {
            Some(k) => k,
            None => clamped_uniform_knots(ctrl.len(), degree),
        };
        let need = ctrl.len() + degree + 1;
        if knots.len() != need {
            return Err(BSplineError::KnotCount {
                need,
                got: knots.len(),
            });
        }
        if knots.iter().any(|k| !k.is_finite()) || knots.windows(2).any(|w| w[1] < w[0]) {
            return Err(BSplineError::KnotOrder);
        }
        if knots[ctrl.len()] <= knots[degree] {
            return Err(BSplineError::EmptyDomain);
        }
        if let Some(w) = &weights {
            if w.len() != ctrl.len() {
                return Err(BSplineError::WeightCount {
                    need: ctrl.len(),
                    got: w.len(),
                });
            }
            if w.iter().any(|w| !(w.is_finite() && *w > 0.0)) {
                return Err(BSplineError::WeightValue);
            }
        }
        Ok(BSpline {
            degree,
            ctrl,
            knots,
            weights,
        })
    }

    /// The active parameter range [u_min, u_max].
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.ctrl.len()])
    }

    pub fn is_rational(&self) -> bool {
        self.weights.is_some()
    }

    fn weight(&self, i: usize) -> f64 {
        self.weights.as_ref().map_or(1.0, |w| w[i])
    }

    /// The knot span index k with knots[k] <= u < knots[k+1] (the last non-empty span at u_max).
    pub fn find_span(&self, u: f64) -> usize {
        let p = self.degree;
        let n = self.ctrl.len() - 1;
        if u >= self.knots[n + 1] {
            // Last span with positive length.
            let mut k = n;
            while k > p && self.knots[k] >= self.knots[k + 1] {
                k -= 1;
            }
            return k;
        }
        if u <= self.knots[p] {
            let mut k = p;
            while k < n && self.knots[k + 1] <= self.knots[p] {
                k += 1;
            }
            return k;
        }
        // Binary search in [p, n+1).
        let (mut lo, mut hi) = (p, n + 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if u < self.knots[mid] {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        lo
    }

    /// The point at the natural parameter `u` (clamped to the domain), by de Boor.
    pub fn eval_u(&self, u: f64) -> DVec3 {
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let p = self.degree;
        let k = self.find_span(u);
        // De Boor's triangle lives on the stack for the usual degrees (this is called per sample
        // by extents and flattening, so a heap allocation here dominated their cost).
        let mut stack = [DVec4::ZERO; 8];
        let mut heap = Vec::new();
        let d: &mut [DVec4] = if p < stack.len() {
            &mut stack[..=p]
        } else {
            heap.resize(p + 1, DVec4::ZERO);
            &mut heap
        };
        for (j, slot) in d.iter_mut().enumerate() {
            let i = k - p + j;
            let w = self.weight(i);
            *slot = (self.ctrl[i] * w).extend(w);
        }
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = k - p + j;
                let denom = self.knots[i + p + 1 - r] - self.knots[i];
                let alpha = if denom > 0.0 {
                    (u - self.knots[i]) / denom
                } else {
                    0.0
                };
                d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
            }
        }
        let h = d[p];
        h.truncate() / h.w
    }

    /// Decompose into Bézier pieces by knot insertion (Boehm), each piece as its p+1 control
    /// points and weights. Exact: the pieces together trace the same curve. Used by SVG (`Q`/`C`)
    /// and by the intersection code's subdivision.
    pub fn to_beziers(&self) -> Vec<(Vec<DVec3>, Vec<f64>)> {
        let p = self.degree;
        let (a, b) = self.domain();
        // Raise every distinct interior knot (and the domain ends) to multiplicity p.
        let mut breaks: Vec<f64> = self
            .knots
            .iter()
            .copied()
            .filter(|u| *u >= a && *u <= b)
            .collect();
        breaks.dedup();
        // Homogeneous control points and the knot vector, refined in place, with room for
        // every insertion (at most p + 1 a break) made once instead of regrown as they come.
        let room = breaks.len() * (p + 1);
        let mut pw: Vec<DVec4> = Vec::with_capacity(self.ctrl.len() + room);
        pw.extend(
            self.ctrl
                .iter()
                .enumerate()
                .map(|(i, c)| (*c * self.weight(i)).extend(self.weight(i))),
        );
        let mut knots = Vec::with_capacity(self.knots.len() + room);
        knots.extend_from_slice(&self.knots);
        // Knots in order (as `new` checks; insertion keeps them so) let the searches below be
        // binary ones, with the same answers as the scans they replace; a batch row
        // decomposes its outline five times, and the scans made it quadratic.
        let sorted = knots.is_sorted();
        for &u in &breaks {
            let mult = if sorted {
                knots.partition_point(|k| *k <= u) - knots.partition_point(|k| *k < u)
            } else {
                knots.iter().filter(|k| **k == u).count()
            };
            let need = if u == a || u == b { p + 1 } else { p };
            for _ in mult..need {
                insert_knot(&mut knots, &mut pw, p, u, sorted);
            }
        }
        // Now every span [breaks[i], breaks[i+1]] has its own p+1 control points.
        let mut out = Vec::with_capacity(breaks.len());
        for w in breaks.windows(2) {
            if w[1] <= w[0] {
                continue;
            }
            // First control point of the piece: the index of the first knot equal to w[0]
            // counted so that knots[s..s+p+1] == w[0] region precedes it.
            let last_a = if sorted {
                let end = knots.partition_point(|k| *k <= w[0]);
                if end > 0 && knots[end - 1] == w[0] {
                    end - 1
                } else {
                    p
                }
            } else {
                knots.iter().rposition(|k| *k == w[0]).unwrap_or(p)
            };
            let start = last_a - p;
            let piece = &pw[start..start + p + 1];
            out.push((
                piece.iter().map(|h| h.truncate() / h.w).collect(),
                piece.iter().map(|h| h.w).collect(),
            ));
        }
        out
    }
}

/// Insert knot `u` once into (knots, homogeneous control points) of degree p (Boehm's algorithm).
/// `sorted`: the knots are in order, so the span is found by a binary search.
fn insert_knot(knots: &mut Vec<f64>, pw: &mut Vec<DVec4>, p: usize, u: f64, sorted: bool) {
    // Span k: knots[k] <= u < knots[k+1], taking the last such k for repeated knots.
    let n = pw.len();
    let k = if sorted {
        match knots[p..n].partition_point(|k| *k <= u) {
            0 => p,
            c => p + c - 1,
        }
    } else {
        (p..n).rfind(|&i| knots[i] <= u).unwrap_or(p)
    };
    // The new points: old[i] for i <= k - p, old[i - 1] for i > k, and between them blends
    // of old[i - 1] and old[i]. Made in place rather than as a new vector per inserted knot:
    // old[k] is duplicated into slot k, then the blends are written from the top down, so
    // each still reads old values (the same operations as before, so the same bits).
    pw.insert(k, pw[k]);
    for i in (k + 1 - p..=k).rev() {
        let denom = knots[i + p] - knots[i];
        let alpha = if denom > 0.0 {
            (u - knots[i]) / denom
        } else {
            0.0
        };
        pw[i] = pw[i - 1] * (1.0 - alpha) + pw[i] * alpha;
    }
    knots.insert(k + 1, u);
}

/// The clamped uniform knot vector for `n` control points of degree `p`:
/// p+1 zeros, uniform interior knots, p+1 ones.
pub fn clamped_uniform_knots(n: usize, p: usize) -> Vec<f64> {
    let spans = n - p;
    let mut k = vec![0.0; p + 1];
    for i in 1..spans {
        k.push(i as f64 / spans as f64);
    }
    k.extend(std::iter::repeat_n(1.0, p + 1));
    k
}

impl ParamCurve for BSpline {
    fn eval(&self, t: f64) -> DVec3 {
        let (a, b) = self.domain();
        self.eval_u(a + (b - a) * t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bezier_eval(pts: &[DVec3], w: &[f64], t: f64) -> DVec3 {
        let mut h: Vec<DVec4> = pts
            .iter()
            .zip(w)
            .map(|(p, w)| (*p * *w).extend(*w))
            .collect();
        let n = h.len();
        for r in 1..n {
            for j in 0..n - r {
                h[j] = h[j] * (1.0 - t) + h[j + 1] * t;
            }
        }
        h[0].truncate() / h[0].w
    }

    #[test]
    fn clamped_cubic_ends_at_end_points() {
        let ctrl = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(3.0, 2.0, 1.0),
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(6.0, 1.0, 0.0),
        ];
        let s = BSpline::new(3, ctrl.clone(), None, None).unwrap();
        assert_eq!(s.eval(0.0), ctrl[0]);
        assert_eq!(s.eval(1.0), ctrl[4]);
    }

    #[test]
    fn bezier_decomposition_traces_the_same_curve() {
        let ctrl = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(3.0, 2.0, 1.0),
            DVec3::new(4.0, 0.0, 0.0),
            DVec3::new(6.0, 1.0, 0.0),
            DVec3::new(7.0, 3.0, 2.0),
        ];
        for p in 1..=4 {
            let s = BSpline::new(
                p,
                ctrl.clone(),
                None,
                Some(vec![1.0, 2.0, 0.5, 1.0, 1.5, 1.0]),
            )
            .unwrap();
            let pieces = s.to_beziers();
            assert_eq!(pieces.len(), ctrl.len() - p);
            let (a, b) = s.domain();
            let spans = pieces.len() as f64;
            for (i, (pts, w)) in pieces.iter().enumerate() {
                for j in 0..=10 {
                    let t = j as f64 / 10.0;
                    let u = a + (b - a) * (i as f64 + t) / spans;
                    let d = (bezier_eval(pts, w, t) - s.eval_u(u)).length();
                    assert!(d < 1e-12, "degree {p} piece {i} t {t}: {d}");
                }
            }
        }
    }

    /// The knot insertion as first written (a new vector per knot): the in-place one must
    /// give the same bits, since written drawings are compared byte for byte.
    fn insert_knot_by_copy(knots: &mut Vec<f64>, pw: &mut Vec<DVec4>, p: usize, u: f64) {
        let n = pw.len();
        let k = (p..n).rfind(|&i| knots[i] <= u).unwrap_or(p);
        let mut new_pts = Vec::with_capacity(n + 1);
        for i in 0..=n {
            if i + p <= k {
                new_pts.push(pw[i]);
            } else if i > k {
                new_pts.push(pw[i - 1]);
            } else {
                let denom = knots[i + p] - knots[i];
                let alpha = if denom > 0.0 {
                    (u - knots[i]) / denom
                } else {
                    0.0
                };
                new_pts.push(pw[i - 1] * (1.0 - alpha) + pw[i] * alpha);
            }
        }
        knots.insert(k + 1, u);
        *pw = new_pts;
    }

    /// `to_beziers` as first written (linear scans, a new vector per knot).
    fn to_beziers_by_scans(s: &BSpline) -> Vec<(Vec<DVec3>, Vec<f64>)> {
        let p = s.degree;
        let (a, b) = s.domain();
        let mut pw: Vec<DVec4> = s
            .ctrl
            .iter()
            .enumerate()
            .map(|(i, c)| (*c * s.weight(i)).extend(s.weight(i)))
            .collect();
        let mut knots = s.knots.clone();
        let mut breaks: Vec<f64> = knots
            .iter()
            .copied()
            .filter(|u| *u >= a && *u <= b)
            .collect();
        breaks.dedup();
        for &u in &breaks {
            let mult = knots.iter().filter(|k| **k == u).count();
            let need = if u == a || u == b { p + 1 } else { p };
            for _ in mult..need {
                insert_knot_by_copy(&mut knots, &mut pw, p, u);
            }
        }
        let mut out = Vec::new();
        for w in breaks.windows(2) {
            if w[1] <= w[0] {
                continue;
            }
            let last_a = knots.iter().rposition(|k| *k == w[0]).unwrap_or(p);
            let piece = &pw[last_a - p..last_a + 1];
            out.push((
                piece.iter().map(|h| h.truncate() / h.w).collect(),
                piece.iter().map(|h| h.w).collect(),
            ));
        }
        out
    }

    #[test]
    fn decomposition_gives_the_same_bits_as_the_scans() {
        let ctrl: Vec<DVec3> = (0..9)
            .map(|i| {
                let t = i as f64 * 0.7;
                DVec3::new(t.cos() * 3.1 + t, t.sin() * 1.7, (t * 0.3).sin())
            })
            .collect();
        let w: Vec<f64> = (0..9).map(|i| 0.6 + 0.11 * i as f64).collect();
        for p in 1..=4 {
            // Uniform, repeated interior knots, unclamped ends.
            let n = ctrl.len();
            let mut knots_sets = vec![None];
            let mut rep: Vec<f64> = (0..n + p + 1).map(|i| (i / 2) as f64 * 0.37).collect();
            rep.sort_by(f64::total_cmp);
            knots_sets.push(Some(rep));
            knots_sets.push(Some((0..n + p + 1).map(|i| i as f64 * 0.5 - 1.0).collect()));
            for knots in knots_sets {
                for weights in [None, Some(w.clone())] {
                    let Ok(s) = BSpline::new(p, ctrl.clone(), knots.clone(), weights) else {
                        continue;
                    };
                    let bits = |v: &[(Vec<DVec3>, Vec<f64>)]| -> Vec<u64> {
                        v.iter()
                            .flat_map(|(pts, ws)| {
                                pts.iter()
                                    .flat_map(|q| q.to_array())
                                    .chain(ws.iter().copied())
                                    .map(f64::to_bits)
                                    .collect::<Vec<_>>()
                            })
                            .collect()
                    };
                    let got = s.to_beziers();
                    assert!(!got.is_empty(), "degree {p}");
                    assert_eq!(bits(&got), bits(&to_beziers_by_scans(&s)), "degree {p}");
                }
            }
        }
    }

    #[test]
    fn knot_insertion_in_place_gives_the_same_bits() {
        // Irregular knots (repeated ones too), irrational-looking points and weights.
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut rnd = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for p in 1..=4 {
            let n = 9;
            let mut knots = vec![0.0; p + 1];
            let mut t = 0.0;
            for i in 0..n - p - 1 {
                if i != 3 {
                    t += 0.1 + rnd();
                }
                knots.push(t);
            }
            knots.extend(std::iter::repeat_n(t + 1.0, p + 1));
            let pw: Vec<DVec4> = (0..n)
                .map(|_| DVec4::new(rnd() * 7.0, rnd() * 3.0, rnd(), 0.5 + rnd()))
                .collect();
            let (mut k1, mut p1) = (knots.clone(), pw.clone());
            let (mut k2, mut p2) = (knots.clone(), pw);
            for j in 0..12 {
                let u = knots[p] + (knots[n] - knots[p]) * (j as f64 / 12.0 + 0.03 * rnd());
                // The binary search and the scan find the same span.
                insert_knot(&mut k1, &mut p1, p, u, j % 2 == 0);
                insert_knot_by_copy(&mut k2, &mut p2, p, u);
                // Existing knots raised too.
                let v = k1[p + 1 + j % 3];
                insert_knot(&mut k1, &mut p1, p, v, j % 2 == 1);
                insert_knot_by_copy(&mut k2, &mut p2, p, v);
            }
            assert_eq!(k1, k2, "degree {p}");
            let bits = |v: &[DVec4]| -> Vec<[u64; 4]> {
                v.iter().map(|q| q.to_array().map(f64::to_bits)).collect()
            };
            assert_eq!(bits(&p1), bits(&p2), "degree {p}");
        }
    }

    #[test]
    fn rejects_bad_data() {
        let c = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
        assert!(BSpline::new(0, c.clone(), None, None).is_err());
        assert!(BSpline::new(3, c.clone(), None, None).is_err());
        assert!(BSpline::new(2, c.clone(), Some(vec![0.0; 5]), None).is_err());
        assert!(
            BSpline::new(2, c.clone(), Some(vec![0.0, 0.0, 0.0, 1.0, 0.5, 1.0]), None).is_err()
        );
        assert!(BSpline::new(2, c, None, Some(vec![1.0, -1.0, 1.0])).is_err());
    }
}
