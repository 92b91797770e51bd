//! The C1 quadratic interpolating spline of the temple paper ("二次样条"): a chain of quadratic
//! Bézier segments passing through every type-value point, open or closed.
//!
//! Public parameter: t in [0, 1] spread uniformly over the segments (segment i covers
//! [i/n, (i+1)/n]). The interpolation itself (how segments are placed between the type-value
//! points) lives in `QuadSpline::interpolate`.

use glam::DVec3;

use super::bspline::BSpline;
use super::traits::ParamCurve;

/// A quadratic spline: its type-value (interpolated) points and its Bézier segments.
#[derive(Clone, Debug, PartialEq)]
pub struct QuadSpline {
    /// The type-value points the spline passes through, in order (not repeated when closed).
    pub points: Vec<DVec3>,
    pub closed: bool,
    /// Quadratic Bézier segments [start, control, end]; each end is the next one's start
    /// (and the last end is the first start when closed). C1 at every joint.
    pub segments: Vec<[DVec3; 3]>,
}

impl QuadSpline {
    /// The exact degree-2 B-spline of the same curve: control points are the segments' shared
    /// ends and controls, every interior knot doubled (C1 joints keep the curve exact whatever
    /// the joint ratio is).
    pub fn to_bspline(&self) -> BSpline {
        let n = self.segments.len();
        let mut ctrl = Vec::with_capacity(2 * n + 1);
        let mut knots = vec![0.0; 3];
        for (i, s) in self.segments.iter().enumerate() {
            if i == 0 {
                ctrl.push(s[0]);
            }
            ctrl.push(s[1]);
            ctrl.push(s[2]);
            if i + 1 < n {
                let u = (i + 1) as f64 / n as f64;
                knots.push(u);
                knots.push(u);
            }
        }
        knots.extend([1.0; 3]);
        BSpline {
            degree: 2,
            ctrl,
            knots,
            weights: None,
        }
    }

    /// Segment index and local parameter for a public parameter t in [0, 1].
    pub fn locate(&self, t: f64) -> (usize, f64) {
        let n = self.segments.len();
        let x = t.clamp(0.0, 1.0) * n as f64;
        let i = (x.floor() as usize).min(n - 1);
        (i, x - i as f64)
    }
}

/// The point at `t` on the quadratic Bézier [p0, p1, p2].
pub fn quad_bezier(s: &[DVec3; 3], t: f64) -> DVec3 {
    let u = 1.0 - t;
    s[0] * (u * u) + s[1] * (2.0 * u * t) + s[2] * (t * t)
}

impl ParamCurve for QuadSpline {
    fn eval(&self, t: f64) -> DVec3 {
        let (i, u) = self.locate(t);
        quad_bezier(&self.segments[i], u)
    }
}
