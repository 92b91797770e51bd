//! Curves given as point lists, and adaptive sampling of any [`ParamCurve`].

use crate::geom::line::Line;
use crate::geom::traits::ParamCurveNearest;
use crate::geom::ParamCurve;
use glam::DVec3;

/// A polyline through `points`, parameterised by chord length over [0, 1].
#[derive(Debug, Clone)]
pub struct SampledCurve {
    points: Vec<DVec3>,
    /// Cumulative chord length at each point, normalised to end at 1.
    params: Vec<f64>,
}

impl SampledCurve {
    /// A polyline through at least two finite points; `closed` repeats the first at the end.
    pub fn new(mut points: Vec<DVec3>, closed: bool) -> Option<SampledCurve> {
        if points.len() < 2 || points.iter().any(|p| !p.is_finite()) {
            return None;
        }
        if closed && points[0] != points[points.len() - 1] {
            points.push(points[0]);
        }
        let mut params = Vec::with_capacity(points.len());
        let mut s = 0.0;
        params.push(0.0);
        for w in points.windows(2) {
            s += w[0].distance(w[1]);
            params.push(s);
        }
        if s <= 0.0 {
            // All points equal: spread the parameter uniformly.
            let n = (points.len() - 1) as f64;
            params = (0..points.len()).map(|i| i as f64 / n).collect();
        } else {
            params.iter_mut().for_each(|p| *p /= s);
        }
        Some(SampledCurve { points, params })
    }

    /// The points.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }
}

impl ParamCurve for SampledCurve {
    fn eval(&self, t: f64) -> DVec3 {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let i = self
            .params
            .partition_point(|&p| p <= t)
            .clamp(1, self.points.len() - 1);
        let (t0, t1) = (self.params[i - 1], self.params[i]);
        let f = if t1 > t0 { (t - t0) / (t1 - t0) } else { 0.0 };
        self.points[i - 1].lerp(self.points[i], f)
    }

    /// Every inner point where the polyline turns (by chord length the speed is the same on
    /// every segment, so only the direction can jump).
    fn creases(&self) -> Vec<f64> {
        let dir = |i: usize| (self.points[i + 1] - self.points[i]).normalize_or_zero();
        (1..self.points.len() - 1)
            .filter(|&i| dir(i - 1).distance(dir(i)) > 1e-9)
            .map(|i| self.params[i])
            .filter(|t| *t > 0.0 && *t < 1.0)
            .collect()
    }
}

/// Samples `c` adaptively: split a parameter interval while its midpoint lies farther than
/// `chord_tol` from the chord (starting from `min_segments` equal pieces so features smaller
/// than the initial spacing are still seen). Returns (parameters, points), ends included.
pub fn sample_curve(
    c: &dyn ParamCurve,
    chord_tol: f64,
    min_segments: usize,
) -> (Vec<f64>, Vec<DVec3>) {
    let n0 = min_segments.max(1);
    let mut ts = vec![0.0];
    let mut ps = vec![c.eval(0.0)];
    for i in 0..n0 {
        let a = i as f64 / n0 as f64;
        let b = (i + 1) as f64 / n0 as f64;
        refine(
            c,
            a,
            c.eval(a),
            b,
            c.eval(b),
            chord_tol,
            0,
            &mut ts,
            &mut ps,
        );
    }
    (ts, ps)
}

#[allow(clippy::too_many_arguments)]
fn refine(
    c: &dyn ParamCurve,
    a: f64,
    pa: DVec3,
    b: f64,
    pb: DVec3,
    tol: f64,
    depth: u32,
    ts: &mut Vec<f64>,
    ps: &mut Vec<DVec3>,
) {
    let m = 0.5 * (a + b);
    let pm = c.eval(m);
    // Also probe the quarter points: a symmetric wiggle can put the midpoint on the chord.
    let q1 = c.eval(0.5 * (a + m));
    let q3 = c.eval(0.5 * (m + b));
    let dev = dist_to_segment(pm, pa, pb)
        .max(dist_to_segment(q1, pa, pb))
        .max(dist_to_segment(q3, pa, pb));
    if depth < 20 && dev > tol {
        refine(c, a, pa, m, pm, tol, depth + 1, ts, ps);
        refine(c, m, pm, b, pb, tol, depth + 1, ts, ps);
    } else {
        ts.push(b);
        ps.push(pb);
    }
}

pub(crate) fn dist_to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    // Unchecked on purpose: a zero-length segment measures the distance to its point.
    p.distance(Line { p0: a, p1: b }.nearest(p, 0.0).1)
}
