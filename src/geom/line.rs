//! A line segment in 3D: P(t) = p0 + t·(p1 − p0), t in [0, 1].

use glam::DVec3;

use super::error::{finite3, invalid, Result};
use super::traits::*;

/// A straight segment from `p0` to `p1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line {
    pub p0: DVec3,
    pub p1: DVec3,
}

impl Line {
    /// The segment scaled by `k` about the origin.
    pub(crate) fn scaled(&self, k: f64) -> Line {
        Line {
            p0: self.p0 * k,
            p1: self.p1 * k,
        }
    }

    /// A checked segment: finite end points that are not the same point.
    pub fn new(p0: DVec3, p1: DVec3) -> Result<Line> {
        finite3("line start point", p0)?;
        finite3("line end point", p1)?;
        if p0 == p1 {
            return Err(invalid("line", "zero length: start and end point coincide"));
        }
        Ok(Line { p0, p1 })
    }

    /// p1 − p0.
    #[inline]
    pub fn dir(&self) -> DVec3 {
        self.p1 - self.p0
    }

    /// The parameter of the foot of the perpendicular from `p` on the infinite line.
    #[inline]
    pub fn project(&self, p: DVec3) -> f64 {
        let d = self.dir();
        let dd = d.length_squared();
        if dd == 0.0 {
            0.0
        } else {
            (p - self.p0).dot(d) / dd
        }
    }
}

impl ParamCurve for Line {
    #[inline]
    fn eval(&self, t: f64) -> DVec3 {
        self.p0 + (self.p1 - self.p0) * t
    }
    fn start(&self) -> DVec3 {
        self.p0
    }
    fn end(&self) -> DVec3 {
        self.p1
    }
}

impl ParamCurveDeriv for Line {
    fn deriv(&self, _t: f64) -> DVec3 {
        self.dir()
    }
}

impl ParamCurveArclen for Line {
    fn arclen(&self, _accuracy: f64) -> f64 {
        self.dir().length()
    }
}

impl ParamCurveNearest for Line {
    fn nearest(&self, p: DVec3, _accuracy: f64) -> (f64, DVec3) {
        let t = self.project(p).clamp(0.0, 1.0);
        (t, self.eval(t))
    }
}

impl ParamCurveBbox for Line {
    fn bbox(&self) -> (DVec3, DVec3) {
        (self.p0.min(self.p1), self.p0.max(self.p1))
    }
}

impl ParamCurveSubdivide for Line {
    fn subsegment(&self, t0: f64, t1: f64) -> Line {
        Line {
            p0: self.eval(t0),
            p1: self.eval(t1),
        }
    }
}
