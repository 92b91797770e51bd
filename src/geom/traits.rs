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
}
