//! Biarc approximation of plane curves, for the CAM profile (arcs and lines only).
//!
//! Each span [t0, t1] of the curve is replaced by a biarc: two circular arcs meeting at a point
//! with a common tangent, starting at C(t0) along C'(t0) and ending at C(t1) along C'(t1).
//! The joint uses the equal-distance choice d1 = d2 (Bolton 1975; Meek & Walton 1992;
//! derivation as in R. Juckett, "Biarc Interpolation", 2010). When the sampled deviation of
//! the curve from the biarc exceeds the tolerance the span is halved, so joints between
//! biarcs keep the curve's own tangent: the result is tangent-continuous (G1) wherever the
//! curve is.

use glam::{DVec2, DVec3};

use crate::geom::bspline::BSpline;

/// A plane curve with a derivative, on a parameter interval of its choosing.
pub trait Curve2 {
    /// (point, derivative) at `t`.
    fn eval_d(&self, t: f64) -> (DVec2, DVec2);
}

/// One rational Bézier piece projected to XY (z dropped), evaluated in homogeneous
/// coordinates by de Casteljau with the quotient rule for the derivative.
pub struct Bezier2 {
    h: Vec<DVec3>,
}

impl Bezier2 {
    pub fn new(pts: &[DVec3], weights: &[f64]) -> Bezier2 {
        Bezier2 {
            h: pts
                .iter()
                .zip(weights)
                .map(|(p, w)| DVec3::new(p.x * w, p.y * w, *w))
                .collect(),
        }
    }
}

impl Curve2 for Bezier2 {
    fn eval_d(&self, t: f64) -> (DVec2, DVec2) {
        let n = self.h.len() - 1;
        let mut q = self.h.clone();
        for r in 1..n {
            for j in 0..=n - r {
                q[j] = q[j].lerp(q[j + 1], t);
            }
        }
        let (q0, q1) = (q[0], q[1]);
        let h = q0.lerp(q1, t);
        let dh = (q1 - q0) * n as f64;
        let p = h.truncate() / h.z;
        let d = (dh.truncate() * h.z - h.truncate() * dh.z) / (h.z * h.z);
        (p, d)
    }
}

/// Any parametric 3D curve projected to XY, derivative by central differences (used for arcs
/// in tilted planes, whose projections are ellipses).
pub struct Projected<F: Fn(f64) -> DVec3>(pub F);

impl<F: Fn(f64) -> DVec3> Curve2 for Projected<F> {
    fn eval_d(&self, t: f64) -> (DVec2, DVec2) {
        let h = 1e-6;
        let p = (self.0)(t).truncate();
        let d = ((self.0)(t + h) - (self.0)(t - h)).truncate() / (2.0 * h);
        (p, d)
    }
}

/// A chain of bulge segments: `points[i]` to `points[i+1]` with `bulges[i]` (tan of a quarter
/// of the signed included angle; 0 = straight).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BulgeChain {
    pub points: Vec<DVec2>,
    pub bulges: Vec<f64>,
}

impl BulgeChain {
    fn push_seg(&mut self, a: DVec2, b: DVec2, bulge: f64) {
        if self.points.is_empty() {
            self.points.push(a);
        }
        // Zero-length pieces (a degenerate biarc half) carry nothing.
        if (b - a).length() <= 1e-12 {
            return;
        }
        self.bulges.push(bulge);
        self.points.push(b);
    }
}

/// The tangent direction at t, falling back to a short chord where the derivative vanishes
/// (coincident control points).
fn unit_tangent(c: &dyn Curve2, t: f64, lo: f64, hi: f64) -> Option<DVec2> {
    let (p, d) = c.eval_d(t);
    if d.length() > 1e-12 {
        return Some(d.normalize());
    }
    let h = (hi - lo) * 1e-6;
    let (a, b) = if t + h <= hi {
        (p, c.eval_d(t + h).0)
    } else {
        (c.eval_d(t - h).0, p)
    };
    let v = b - a;
    (v.length() > 0.0).then(|| v.normalize())
}

/// The signed angle from u to v.
fn signed_angle(u: DVec2, v: DVec2) -> f64 {
    u.perp_dot(v).atan2(u.dot(v))
}

/// The biarc from p0 (tangent t0) to p1 (tangent t1), both tangents unit: two bulge segments
/// through the joint, or `None` where the equal-distance construction has no solution (the
/// caller subdivides).
pub fn biarc(p0: DVec2, t0: DVec2, p1: DVec2, t1: DVec2) -> Option<[(DVec2, DVec2, f64); 2]> {
    let v = p1 - p0;
    let vv = v.dot(v);
    if vv <= 1e-24 {
        return None;
    }
    let t = t0 + t1;
    let denom = 2.0 * (1.0 - t0.dot(t1));
    let d = if denom.abs() < 1e-12 {
        let vt1 = v.dot(t1);
        if vt1.abs() < 1e-12 {
            return None;
        }
        vv / (4.0 * vt1)
    } else {
        let vt = v.dot(t);
        (-vt + (vt * vt + denom * vv).sqrt()) / denom
    };
    if !(d.is_finite() && d > 0.0) {
        return None;
    }
    let pm = (p0 + p1 + (t0 - t1) * d) / 2.0;
    let b1 = (signed_angle(t0, pm - p0) / 2.0).tan();
    let b2 = (signed_angle(p1 - pm, t1) / 2.0).tan();
    if !(b1.is_finite() && b2.is_finite()) || b1.abs() > 1.0 || b2.abs() > 1.0 {
        // More than a half turn on one arc: the span is too coarse to trust.
        return None;
    }
    Some([(p0, pm, b1), (pm, p1, b2)])
}

/// Distance from q to the bulge segment a→b.
pub fn dist_to_bulge_seg(q: DVec2, a: DVec2, b: DVec2, bulge: f64) -> f64 {
    match super::drawing::bulge_arc(a, b, bulge) {
        None => dist_to_segment(q, a, b),
        Some((c, r, a0, a1)) => {
            let sweep = a1 - a0;
            let phi = (q - c).y.atan2((q - c).x);
            let tau = std::f64::consts::TAU;
            let rel = if sweep > 0.0 {
                (phi - a0).rem_euclid(tau)
            } else {
                (a0 - phi).rem_euclid(tau)
            };
            if rel <= sweep.abs() {
                ((q - c).length() - r).abs()
            } else {
                (q - a).length().min((q - b).length())
            }
        }
    }
}

pub fn dist_to_segment(q: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let l2 = ab.length_squared();
    if l2 == 0.0 {
        return (q - a).length();
    }
    let s = ((q - a).dot(ab) / l2).clamp(0.0, 1.0);
    (q - (a + ab * s)).length()
}

/// The point at parameter s in [0, 1] along a bulge segment (by angle on arcs).
pub fn bulge_point(a: DVec2, b: DVec2, bulge: f64, s: f64) -> DVec2 {
    match super::drawing::bulge_arc(a, b, bulge) {
        None => a.lerp(b, s),
        Some((c, r, a0, a1)) => {
            let t = a0 + (a1 - a0) * s;
            c + DVec2::new(t.cos(), t.sin()) * r
        }
    }
}

const SAMPLES: usize = 16;
const MAX_DEPTH: u32 = 40;

/// Append to `out` arcs approximating `c` on [t0, t1] within `tol` (sampled both ways:
/// curve samples to the arcs and arc samples to the curve's sample polyline).
pub fn fit_span(c: &dyn Curve2, t0: f64, t1: f64, tol: f64, out: &mut BulgeChain) {
    let p0 = c.eval_d(t0).0;
    let p1 = c.eval_d(t1).0;
    let d0 = unit_tangent(c, t0, t0, t1);
    let d1 = unit_tangent(c, t1, t0, t1);
    fit_rec(c, t0, t1, (p0, d0), (p1, d1), tol, 0, out);
}

type Anchor = (DVec2, Option<DVec2>);

#[allow(clippy::too_many_arguments)]
fn fit_rec(
    c: &dyn Curve2,
    t0: f64,
    t1: f64,
    a0: Anchor,
    a1: Anchor,
    tol: f64,
    depth: u32,
    out: &mut BulgeChain,
) {
    let (p0, d0) = a0;
    let (p1, d1) = a1;
    let samples: Vec<DVec2> = (0..=SAMPLES)
        .map(|i| c.eval_d(t0 + (t1 - t0) * i as f64 / SAMPLES as f64).0)
        .collect();
    let candidate = match (d0, d1) {
        (Some(d0), Some(d1)) => biarc(p0, d0, p1, d1),
        _ => None,
    };
    let line_ok = || samples.iter().all(|q| dist_to_segment(*q, p0, p1) <= tol);
    if let Some(arcs) = candidate {
        if within(&samples, &arcs, tol) {
            for (a, b, bu) in arcs {
                out.push_seg(a, b, bu);
            }
            return;
        }
    } else if (p1 - p0).length() <= tol && line_ok() {
        // A span too short for a biarc (or with a vanishing tangent) that a chord covers.
        out.push_seg(p0, p1, 0.0);
        return;
    }
    if depth >= MAX_DEPTH || t1 - t0 <= 1e-12 * (1.0 + t0.abs()) {
        out.push_seg(p0, p1, 0.0);
        return;
    }
    let tm = 0.5 * (t0 + t1);
    let pm = c.eval_d(tm).0;
    let dm = unit_tangent(c, tm, t0, t1);
    fit_rec(c, t0, tm, a0, (pm, dm), tol, depth + 1, out);
    fit_rec(c, tm, t1, (pm, dm), a1, tol, depth + 1, out);
}

fn within(samples: &[DVec2], arcs: &[(DVec2, DVec2, f64); 2], tol: f64) -> bool {
    let curve_to_arcs = samples.iter().all(|q| {
        arcs.iter()
            .map(|(a, b, bu)| dist_to_bulge_seg(*q, *a, *b, *bu))
            .fold(f64::INFINITY, f64::min)
            <= tol
    });
    if !curve_to_arcs {
        return false;
    }
    // The other way: points along each arc must lie near the curve (its sample polyline).
    arcs.iter().all(|(a, b, bu)| {
        (1..8).all(|k| {
            let q = bulge_point(*a, *b, *bu, k as f64 / 8.0);
            samples
                .windows(2)
                .map(|w| dist_to_segment(q, w[0], w[1]))
                .fold(f64::INFINITY, f64::min)
                <= tol
        })
    })
}

/// Biarcs for a whole B-spline, projected to XY: each Bézier piece is fitted on its own, so
/// kinks at C0 knots stay kinks and smooth joints stay smooth.
pub fn fit_bspline(s: &BSpline, tol: f64) -> BulgeChain {
    let mut out = BulgeChain::default();
    for (pts, w) in s.to_beziers() {
        let piece = Bezier2::new(&pts, &w);
        fit_span(&piece, 0.0, 1.0, tol, &mut out);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn biarc_of_a_circle_quarter_is_the_circle() {
        // Quarter circle from (1,0) to (0,1): tangents (0,1) and (-1,0).
        let arcs = biarc(
            DVec2::new(1.0, 0.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(-1.0, 0.0),
        )
        .unwrap();
        for (a, b, bu) in arcs {
            for k in 0..=10 {
                let q = bulge_point(a, b, bu, k as f64 / 10.0);
                assert!((q.length() - 1.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn cubic_fit_is_within_tolerance() {
        let s = BSpline::new(
            3,
            vec![
                DVec3::new(0.0, 0.0, 0.0),
                DVec3::new(10.0, 20.0, 0.0),
                DVec3::new(30.0, -20.0, 0.0),
                DVec3::new(40.0, 0.0, 0.0),
            ],
            None,
            None,
        )
        .unwrap();
        let chain = fit_bspline(&s, 0.01);
        assert!(chain.bulges.len() >= 2);
        for i in 0..=2000 {
            let p = s.eval_u(i as f64 / 2000.0).truncate();
            let d = chain
                .points
                .windows(2)
                .zip(&chain.bulges)
                .map(|(w, b)| dist_to_bulge_seg(p, w[0], w[1], *b))
                .fold(f64::INFINITY, f64::min);
            assert!(d <= 0.01, "sample {i}: {d}");
        }
    }
}
