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

    /// The same curve as a degree-2 B-spline with simple interior knots: the control points are
    /// the segments' middle controls (plus the two ends), and the knot intervals are chosen so
    /// each joint divides its two neighbouring controls in the joint's own ratio
    /// (h_next / h_prev = |C_next − J| / |J − C_prev|). Half the control points of
    /// `to_bspline`, and readers that mishandle repeated knots (LibreCAD) stay well-behaved.
    /// `None` when a joint does not lie strictly between its controls (a degenerate leg), except
    /// a corner where both legs are zero.
    pub fn to_bspline_simple_knots(&self) -> Option<BSpline> {
        let n = self.segments.len();
        let mut h = Vec::with_capacity(n);
        h.push(1.0);
        for i in 0..n.saturating_sub(1) {
            let (c0, j, c1) = (
                self.segments[i][1],
                self.segments[i][2],
                self.segments[i + 1][1],
            );
            let (a, b) = (j.distance(c0), c1.distance(j));
            if a == 0.0 && b == 0.0 {
                // A corner (zero tangent on both sides, see quadspline_fit): any ratio gives
                // the joint; keep the knot spacing.
                h.push(h[i]);
                continue;
            }
            let collinear =
                (c1 - c0).length() > 0.0 && ((a + b) - c1.distance(c0)).abs() <= 1e-9 * (a + b);
            if !(a > 0.0 && b > 0.0 && collinear) {
                return None;
            }
            let next = h[i] * b / a;
            if !(next.is_finite() && next > 1e-12 && next < 1e12) {
                return None;
            }
            h.push(next);
        }
        let total: f64 = h.iter().sum();
        let mut knots = vec![0.0; 3];
        let mut acc = 0.0;
        for x in &h[..n - 1] {
            acc += x;
            knots.push(acc / total);
        }
        knots.extend([1.0; 3]);
        let mut ctrl = Vec::with_capacity(n + 2);
        ctrl.push(self.segments[0][0]);
        ctrl.extend(self.segments.iter().map(|s| s[1]));
        ctrl.push(self.segments[n - 1][2]);
        BSpline::new(2, ctrl, Some(knots), None).ok()
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn simple_knot_form_traces_the_same_curve() {
        // No right-angle corner (those get a zero tangent, a degenerate leg, by design).
        let pts: Vec<DVec3> = [
            (0.0, -2.0),
            (5.6, -2.5),
            (49.0, -2.1),
            (98.0, -1.75),
            (126.0, -3.5),
            (140.0, 0.0),
            (126.0, 3.5),
            (98.0, 1.75),
            (49.0, 2.1),
            (5.6, 2.5),
            (0.0, 2.0),
        ]
        .iter()
        .map(|(x, y)| DVec3::new(*x, *y, 0.0))
        .collect();
        for closed in [false, true] {
            let s = QuadSpline::interpolate(&pts, closed).unwrap();
            let b = s.to_bspline_simple_knots().expect("regular joints");
            assert_eq!(b.ctrl.len(), s.segments.len() + 2);
            // Each Bezier piece of the B-spline is the matching segment.
            let pieces = b.to_beziers();
            assert_eq!(pieces.len(), s.segments.len());
            for (seg, (ctrl, _)) in s.segments.iter().zip(&pieces) {
                for k in 0..3 {
                    assert!(
                        (seg[k] - ctrl[k]).length() < 1e-9,
                        "{:?} vs {:?}",
                        seg,
                        ctrl
                    );
                }
            }
        }
    }
}
