//! Small capability traits shared by every curve kind (after kurbo's `ParamCurve` family).
//!
//! The public parameter of every curve runs over [0, 1] (SPEC §4: `point-at` takes t in [0,1]),
//! whatever the curve's natural parameterization is.

use glam::DVec3;

/// A curve that can be evaluated at a parameter in [0, 1].
pub trait ParamCurve {
    /// The point at parameter `t` in [0, 1].
    fn eval(&self, t: f64) -> DVec3;

    /// The point at t = 0.
    fn start(&self) -> DVec3 {
        self.eval(0.0)
    }

    /// The point at t = 1.
    fn end(&self) -> DVec3 {
        self.eval(1.0)
    }

    /// The parameters inside (0, 1), ascending, where the first derivative jumps: joins that
    /// are only C0 in this parameter (a polyline's vertices, a B-spline's full-multiplicity
    /// knots). Difference quotients must not straddle them. Empty where the curve is smooth.
    fn creases(&self) -> Vec<f64> {
        Vec::new()
    }
}

/// The first derivative with respect to the public parameter t.
pub trait ParamCurveDeriv: ParamCurve {
    /// dP/dt at `t` in [0, 1].
    fn deriv(&self, t: f64) -> DVec3;

    /// The unit tangent at `t` (zero only where the curve is degenerate).
    fn unit_tangent(&self, t: f64) -> DVec3 {
        self.deriv(t).normalize_or_zero()
    }
}

/// Arc length, to a stated absolute accuracy (exact for lines and arcs).
pub trait ParamCurveArclen: ParamCurve {
    fn arclen(&self, accuracy: f64) -> f64;
}

/// The nearest point of the curve to a given point.
pub trait ParamCurveNearest: ParamCurve {
    /// `(t, point)` of the curve point closest to `p`, found to `accuracy` (distance units).
    fn nearest(&self, p: DVec3, accuracy: f64) -> (f64, DVec3);
}

/// An axis-aligned bounding box that is tight (touches the curve), not a hull bound.
pub trait ParamCurveBbox {
    /// `(min, max)` corners.
    fn bbox(&self) -> (DVec3, DVec3);
}

/// The piece of a curve between two parameters, as a curve of the same kind.
pub trait ParamCurveSubdivide: Sized {
    /// The part between `t0 < t1`, reparameterized over [0, 1].
    fn subsegment(&self, t0: f64, t1: f64) -> Self;
}
