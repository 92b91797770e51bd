//! Queries on a [`QuadSpline`]: derivative, arc length (adaptive Gauss–Legendre), nearest point
//! (exact roots of the cubic (B(u) − p)·B'(u) per segment), bounding box (per-coordinate
//! extrema of each Bézier) and an adaptive polyline approximation within a chord tolerance.
//!
//! All parameters are the public t in [0, 1] of [`QuadSpline`] (uniform over segments).

use glam::{DMat4, DVec3};
use smallvec::SmallVec;

use super::quadspline::{quad_bezier, QuadSpline};

/// The derivative of the quadratic Bézier [p0, p1, p2] with respect to its own parameter.
pub fn quad_bezier_deriv(s: &[DVec3; 3], u: f64) -> DVec3 {
    ((s[1] - s[0]) * (1.0 - u) + (s[2] - s[1]) * u) * 2.0
}

/// The nearest point of a curve to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nearest {
    /// Public parameter in [0, 1].
    pub t: f64,
    pub point: DVec3,
    pub distance: f64,
}

/// 8-point Gauss–Legendre nodes and weights on [−1, 1].
const GL_X: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
const GL_W: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

fn gauss8(s: &[DVec3; 3], a: f64, b: f64) -> f64 {
    let c = 0.5 * (a + b);
    let r = 0.5 * (b - a);
    let mut sum = 0.0;
    for (x, w) in GL_X.iter().zip(GL_W) {
        sum += w
            * (quad_bezier_deriv(s, c - r * x).length() + quad_bezier_deriv(s, c + r * x).length());
    }
    sum * r
}

/// Arc length of Bézier `s` over [a, b] by adaptive Gauss–Legendre: split until the 8-point
/// rule on the whole and on the two halves agree within `acc`.
fn seg_arclen(s: &[DVec3; 3], a: f64, b: f64, acc: f64, depth: u32) -> f64 {
    let whole = gauss8(s, a, b);
    let m = 0.5 * (a + b);
    let halves = gauss8(s, a, m) + gauss8(s, m, b);
    if (whole - halves).abs() <= acc || depth >= 24 {
        halves
    } else {
        seg_arclen(s, a, m, 0.5 * acc, depth + 1) + seg_arclen(s, m, b, 0.5 * acc, depth + 1)
    }
}

/// Every root in [0, 1] of the cubic c3 u³ + c2 u² + c1 u + c0, found by splitting [0, 1] at
/// the roots of its derivative into monotone pieces and bisecting each sign change (with
/// Newton steps when they stay in the bracket). Exact to machine precision, loses no root.
fn cubic_roots_unit(c3: f64, c2: f64, c1: f64, c0: f64, out: &mut SmallVec<[f64; 6]>) {
    let f = |u: f64| ((c3 * u + c2) * u + c1) * u + c0;
    let df = |u: f64| (3.0 * c3 * u + 2.0 * c2) * u + c1;
    let mut cuts: SmallVec<[f64; 4]> = SmallVec::new();
    cuts.push(0.0);
    // Critical points: 3c3 u² + 2c2 u + c1 = 0, solved without cancellation.
    let (qa, qb, qc) = (3.0 * c3, 2.0 * c2, c1);
    if qa != 0.0 {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc >= 0.0 {
            let q = -0.5 * (qb + qb.signum() * disc.sqrt());
            let rs = if q != 0.0 {
                let (r0, r1) = (q / qa, qc / q);
                [r0.min(r1), r0.max(r1)]
            } else {
                [0.0, 0.0]
            };
            for r in rs {
                if r > 0.0 && r < 1.0 {
                    cuts.push(r);
                }
            }
        }
    } else if qb != 0.0 {
        let r = -qc / qb;
        if r > 0.0 && r < 1.0 {
            cuts.push(r);
        }
    }
    cuts.push(1.0);
    for w in cuts.windows(2) {
        let (mut lo, mut hi) = (w[0], w[1]);
        let (flo, fhi) = (f(lo), f(hi));
        if flo == 0.0 {
            out.push(lo);
            continue;
        }
        if fhi == 0.0 {
            out.push(hi);
            continue;
        }
        if flo.signum() == fhi.signum() {
            continue;
        }
        let rising = fhi > 0.0;
        let mut u = 0.5 * (lo + hi);
        for _ in 0..100 {
            let fu = f(u);
            if fu == 0.0 {
                break;
            }
            if (fu > 0.0) == rising {
                hi = u;
            } else {
                lo = u;
            }
            let d = df(u);
            let newton = u - fu / d;
            if d != 0.0 && newton > lo && newton < hi {
                // Newton converges from one side and need not shrink the bracket: stop when
                // its step is at the rounding level.
                let step = (newton - u).abs();
                u = newton;
                if step <= 4.0 * f64::EPSILON {
                    break;
                }
            } else {
                u = 0.5 * (lo + hi);
            }
            if hi - lo <= 4.0 * f64::EPSILON {
                break;
            }
        }
        out.push(u);
    }
}

/// Nearest point of one quadratic Bézier to `p`: (local u, squared distance).
fn seg_nearest(s: &[DVec3; 3], p: DVec3) -> (f64, f64) {
    // B(u) = A u² + B u + C;  (B(u) − p)·B'(u) = 2AA u³ + 3AB u² + (BB + 2AD) u + DB, D = C − p.
    let a = s[0] - 2.0 * s[1] + s[2];
    let b = 2.0 * (s[1] - s[0]);
    let d = s[0] - p;
    let mut cands: SmallVec<[f64; 6]> = SmallVec::new();
    cands.extend([0.0, 1.0]);
    cubic_roots_unit(
        2.0 * a.dot(a),
        3.0 * a.dot(b),
        b.dot(b) + 2.0 * a.dot(d),
        d.dot(b),
        &mut cands,
    );
    cands
        .into_iter()
        .map(|u| (u, quad_bezier(s, u).distance_squared(p)))
        .min_by(|x, y| x.1.total_cmp(&y.1))
        .unwrap_or((0.0, d.length_squared()))
}

fn seg_hull_dist2(s: &[DVec3; 3], p: DVec3) -> f64 {
    let lo = s[0].min(s[1]).min(s[2]);
    let hi = s[0].max(s[1]).max(s[2]);
    let q = p.clamp(lo, hi);
    q.distance_squared(p)
}

impl QuadSpline {
    /// The public parameter of type-value point `j`: j/(n−1) open, j/n closed (interpolated
    /// splines put exactly two segments between consecutive type-value points).
    pub fn point_param(&self, j: usize) -> f64 {
        let n = self.points.len();
        let intervals = if self.closed { n } else { n.saturating_sub(1) };
        if intervals == 0 {
            0.0
        } else {
            j as f64 / intervals as f64
        }
    }

    /// The derivative with respect to the public parameter t.
    pub fn derivative(&self, t: f64) -> DVec3 {
        let (i, u) = self.locate(t);
        quad_bezier_deriv(&self.segments[i], u) * self.segments.len() as f64
    }

    /// The unit tangent at t, or None where the curve has zero speed.
    pub fn tangent(&self, t: f64) -> Option<DVec3> {
        self.derivative(t).try_normalize()
    }

    /// Arc length of segment i, within `accuracy`.
    pub fn segment_length(&self, i: usize, accuracy: f64) -> f64 {
        seg_arclen(&self.segments[i], 0.0, 1.0, accuracy.abs().max(1e-15), 0)
    }

    /// Total arc length within `accuracy` (adaptive Gauss–Legendre per segment).
    pub fn length(&self, accuracy: f64) -> f64 {
        let acc = accuracy.abs().max(1e-15) / self.segments.len() as f64;
        (0..self.segments.len())
            .map(|i| self.segment_length(i, acc))
            .sum()
    }

    /// Arc length from t = 0 to t, within `accuracy`.
    pub fn length_to(&self, t: f64, accuracy: f64) -> f64 {
        let (i, u) = self.locate(t);
        let acc = accuracy.abs().max(1e-15) / (i + 1) as f64;
        let whole: f64 = (0..i).map(|k| self.segment_length(k, acc)).sum();
        whole + seg_arclen(&self.segments[i], 0.0, u, acc, 0)
    }

    /// The public parameter at arc length `s` from the start (clamped to [0, length]), within
    /// `accuracy` in length: segment found by cumulative lengths, then safeguarded Newton on the
    /// arc-length function inside it.
    pub fn param_at_length(&self, s: f64, accuracy: f64) -> f64 {
        let n = self.segments.len();
        let acc = accuracy.abs().max(1e-15) / n as f64;
        if s.is_nan() || s <= 0.0 {
            return 0.0;
        }
        let mut before = 0.0;
        for i in 0..n {
            let seg = &self.segments[i];
            let li = seg_arclen(seg, 0.0, 1.0, acc, 0);
            if before + li >= s || i + 1 == n {
                let target = (s - before).min(li);
                let (mut lo, mut hi) = (0.0, 1.0);
                let mut u = if li > 0.0 { target / li } else { 0.0 };
                for _ in 0..60 {
                    let err = seg_arclen(seg, 0.0, u, acc, 0) - target;
                    if err.abs() <= acc {
                        break;
                    }
                    if err > 0.0 {
                        hi = u;
                    } else {
                        lo = u;
                    }
                    let speed = quad_bezier_deriv(seg, u).length();
                    let nu = if speed > 0.0 { u - err / speed } else { -1.0 };
                    u = if nu > lo && nu < hi {
                        nu
                    } else {
                        0.5 * (lo + hi)
                    };
                }
                return (i as f64 + u) / n as f64;
            }
            before += li;
        }
        1.0
    }

    /// The nearest point of the spline to `p` (global: every segment's cubic is solved exactly,
    /// segments whose control hull is farther than the best so far are skipped).
    pub fn closest_point(&self, p: DVec3) -> Nearest {
        self.closest_point_in(p, 0, self.segments.len())
    }

    /// The nearest point to `p` among segments `first..last` (indices clamped to the spline).
    pub fn closest_point_in(&self, p: DVec3, first: usize, last: usize) -> Nearest {
        self.closest_point_in_from(p, first, last, first)
    }

    /// As [`closest_point_in`](Self::closest_point_in), scanning from segment `start` (the
    /// likeliest one) so the others are mostly skipped by their hull distance.
    pub fn closest_point_in_from(
        &self,
        p: DVec3,
        first: usize,
        last: usize,
        start: usize,
    ) -> Nearest {
        let n = self.segments.len();
        let last = last.min(n);
        let first = first.min(last.saturating_sub(1));
        let start = start.clamp(first, last.saturating_sub(1));
        let mut best = (first, 0.0, f64::INFINITY);
        for i in (start..last).chain(first..start) {
            let s = &self.segments[i];
            if seg_hull_dist2(s, p) >= best.2 {
                continue;
            }
            let (u, d2) = seg_nearest(s, p);
            if d2 < best.2 {
                best = (i, u, d2);
            }
        }
        let (i, u, d2) = best;
        Nearest {
            t: (i as f64 + u) / n as f64,
            point: quad_bezier(&self.segments[i], u),
            distance: d2.sqrt(),
        }
    }

    /// The spline under an affine map (move, rotate, scale, mirror): exact, since an affine
    /// image of a quadratic Bézier is the Bézier of the mapped control points. Type-value
    /// points are mapped alike, so `point_param` still holds.
    pub fn transformed(&self, m: &DMat4) -> QuadSpline {
        QuadSpline {
            points: self.points.iter().map(|p| m.transform_point3(*p)).collect(),
            closed: self.closed,
            segments: self
                .segments
                .iter()
                .map(|s| s.map(|p| m.transform_point3(p)))
                .collect(),
        }
    }

    /// The same curve traversed the other way (type-value points reversed).
    pub fn reversed(&self) -> QuadSpline {
        let mut points = self.points.clone();
        let segments: Vec<[DVec3; 3]> = self
            .segments
            .iter()
            .rev()
            .map(|s| [s[2], s[1], s[0]])
            .collect();
        if self.closed && !points.is_empty() {
            // The reversed segments already start at point 0; the points keep it first too.
            points[1..].reverse();
        } else {
            points.reverse();
        }
        QuadSpline {
            points,
            closed: self.closed,
            segments,
        }
    }

    /// The exact axis-aligned bounding box (min, max): segment ends and the interior extremum
    /// of each coordinate, u* = (p0 − p1)/(p0 − 2p1 + p2).
    pub fn bbox(&self) -> (DVec3, DVec3) {
        let mut lo = DVec3::splat(f64::INFINITY);
        let mut hi = DVec3::splat(f64::NEG_INFINITY);
        for s in &self.segments {
            lo = lo.min(s[0]).min(s[2]);
            hi = hi.max(s[0]).max(s[2]);
            let num = s[0] - s[1];
            let den = s[0] - 2.0 * s[1] + s[2];
            for k in 0..3 {
                if den[k] != 0.0 {
                    let u = num[k] / den[k];
                    if u > 0.0 && u < 1.0 {
                        let q = quad_bezier(s, u);
                        lo = lo.min(q);
                        hi = hi.max(q);
                    }
                }
            }
        }
        (lo, hi)
    }

    /// A polyline within `tol` of the spline: each segment cut into k equal parameter steps with
    /// k = ⌈√(|p0 − 2p1 + p2| / (4·tol))⌉ (the chord error of a quadratic with constant second
    /// derivative 2(p0 − 2p1 + p2) over a step 1/k is |p0 − 2p1 + p2|/(4k²)). Starts at the
    /// spline's start and ends at its end (for a closed spline the first point is repeated).
    /// A non-positive or non-finite `tol` is treated as the smallest step count cap (1024 per
    /// segment).
    pub fn points(&self, tol: f64) -> Vec<DVec3> {
        let mut out = vec![self.segments[0][0]];
        for s in &self.segments {
            let a = (s[0] - 2.0 * s[1] + s[2]).length();
            let k = if tol > 0.0 && tol.is_finite() {
                ((a / (4.0 * tol)).sqrt().ceil() as usize).clamp(1, 1024)
            } else {
                1024
            };
            for j in 1..=k {
                let u = j as f64 / k as f64;
                out.push(if j == k { s[2] } else { quad_bezier(s, u) });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_roots_found() {
        // (u − 0.2)(u − 0.5)(u − 0.9)
        let mut r = SmallVec::new();
        cubic_roots_unit(1.0, -1.6, 0.73, -0.09, &mut r);
        r.sort_by(f64::total_cmp);
        assert_eq!(r.len(), 3);
        for (x, y) in r.iter().zip([0.2, 0.5, 0.9]) {
            assert!((x - y).abs() < 1e-14, "{x} vs {y}");
        }
    }
}
