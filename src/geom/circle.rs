//! A full circle in 3D: centre, radius and unit normal. P(t) = C + r·(cos 2πt·X + sin 2πt·Y)
//! with (X, Y) the DXF arbitrary-axis frame of the normal, so t = 0 is on the OCS X axis and
//! the circle runs CCW about its normal.

use std::f64::consts::TAU;

use glam::DVec3;

use super::arc::{check_normal, check_radius, Arc};
use super::error::{finite3, Result};
use super::traits::*;

/// A full circle; internally the arc of sweep 2π starting at angle 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    pub(crate) arc: Arc,
}

impl Circle {
    /// A checked circle: finite centre, radius > 0, non-zero normal (normalized here).
    pub fn new(center: DVec3, radius: f64, normal: DVec3) -> Result<Circle> {
        finite3("center", center)?;
        check_radius(radius)?;
        let normal = check_normal(normal)?;
        Ok(Circle {
            arc: Arc::from_parts(center, radius, normal, 0.0, TAU),
        })
    }

    pub fn center(&self) -> DVec3 {
        self.arc.center
    }
    pub fn radius(&self) -> f64 {
        self.arc.radius
    }
    /// The unit normal; the circle runs CCW about it.
    pub fn normal(&self) -> DVec3 {
        self.arc.normal
    }
    /// The circle as a 2π arc starting at angle 0 (same parameterization).
    pub fn as_arc(&self) -> &Arc {
        &self.arc
    }
}

impl ParamCurve for Circle {
    #[inline]
    fn eval(&self, t: f64) -> DVec3 {
        self.arc.eval(t)
    }
}
impl ParamCurveDeriv for Circle {
    fn deriv(&self, t: f64) -> DVec3 {
        self.arc.deriv(t)
    }
}
impl ParamCurveArclen for Circle {
    fn arclen(&self, _accuracy: f64) -> f64 {
        TAU * self.arc.radius
    }
}
impl ParamCurveNearest for Circle {
    fn nearest(&self, p: DVec3, accuracy: f64) -> (f64, DVec3) {
        self.arc.nearest(p, accuracy)
    }
}
impl ParamCurveBbox for Circle {
    fn bbox(&self) -> (DVec3, DVec3) {
        self.arc.bbox()
    }
}
