//! A circular arc in 3D: centre, radius, unit normal, and the angle range swept counter-
//! clockwise about the normal. Angles are measured from the X axis of the normal's DXF
//! arbitrary-axis frame (`frame::arbitrary_axis`), exactly as a DXF ARC entity stores them.
//!
//! P(t) = C + r·(cos θ·X + sin θ·Y), θ = start + sweep·t, t in [0, 1].
//! A full circle is the same shape with sweep 2π (see `circle.rs`).

use std::f64::consts::TAU;

use glam::DVec3;

use super::error::{finite, finite3, invalid, Result};
use super::fastmath::{atan2, atan2_lanes};
use super::frame::arbitrary_axis;
use super::lanes::F2;
use super::traits::*;

/// A circular arc (or, with sweep 2π, the full circle used by `Circle`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arc {
    pub(crate) center: DVec3,
    pub(crate) radius: f64,
    pub(crate) normal: DVec3,
    pub(crate) x_axis: DVec3,
    pub(crate) y_axis: DVec3,
    /// Start angle in [0, 2π).
    pub(crate) start: f64,
    /// Swept angle in (0, 2π].
    pub(crate) sweep: f64,
}

/// An atan2 result (in [−π, π]) reduced to [0, 2π): `norm_angle`'s answer with one test in
/// the common case, for the hit parameters' hot path.
#[inline(always)]
fn norm_atan2(a: f64) -> f64 {
    // Written as selects, not branches: the sign of a hit's angle is a coin toss.
    let r = a + if a < 0.0 { TAU } else { 0.0 };
    // −ε + 2π rounds to 2π: that point is at the seam.
    if r >= TAU {
        0.0
    } else {
        r
    }
}

/// Angle reduced to [0, 2π).
#[inline]
pub(crate) fn norm_angle(a: f64) -> f64 {
    // Most inputs are within one turn of the range: avoid the division in rem_euclid.
    if (0.0..TAU).contains(&a) {
        return a;
    }
    if (-TAU..0.0).contains(&a) {
        let r = a + TAU;
        return if r >= TAU { 0.0 } else { r };
    }
    if (TAU..2.0 * TAU).contains(&a) {
        return a - TAU;
    }
    let r = a.rem_euclid(TAU);
    if r >= TAU {
        0.0
    } else {
        r
    }
}

pub(crate) fn check_normal(normal: DVec3) -> Result<DVec3> {
    finite3("normal", normal)?;
    let len = normal.length();
    if len.is_nan() || len <= 1e-300 {
        return Err(invalid("normal", "must not be the zero vector"));
    }
    Ok(normal / len)
}

pub(crate) fn check_radius(radius: f64) -> Result<f64> {
    finite("radius", radius)?;
    if radius <= 0.0 {
        return Err(invalid("radius", format!("must be > 0, got {radius}")));
    }
    Ok(radius)
}

impl Arc {
    /// The arc CCW about `normal` from `start` to `end` (radians, from the OCS X axis).
    /// The sweep is (end − start) reduced to (0, 2π]; equal angles are an error (use a circle).
    pub fn new(center: DVec3, radius: f64, start: f64, end: f64, normal: DVec3) -> Result<Arc> {
        finite3("center", center)?;
        check_radius(radius)?;
        finite("start angle", start)?;
        finite("end angle", end)?;
        let normal = check_normal(normal)?;
        let sweep = norm_angle(end - start);
        if sweep == 0.0 {
            return Err(invalid(
                "end angle",
                "equals the start angle (zero sweep); use a circle for a full turn",
            ));
        }
        Ok(Arc::from_parts(
            center,
            radius,
            normal,
            norm_angle(start),
            sweep,
        ))
    }

    /// Unchecked constructor from a unit normal, start in [0,2π) and sweep in (0, 2π].
    pub(crate) fn from_parts(
        center: DVec3,
        radius: f64,
        normal: DVec3,
        start: f64,
        sweep: f64,
    ) -> Arc {
        let (x_axis, y_axis) = arbitrary_axis(normal);
        Arc {
            center,
            radius,
            normal,
            x_axis,
            y_axis,
            start,
            sweep,
        }
    }

    /// The arc through three points, from `p1` via `p2` to `p3` (circumcircle; the normal is
    /// (p2 − p1) × (p3 − p1), so the arc runs CCW about it). Collinear points are an error.
    pub fn through(p1: DVec3, p2: DVec3, p3: DVec3) -> Result<Arc> {
        finite3("first point", p1)?;
        finite3("second point", p2)?;
        finite3("third point", p3)?;
        let a = p2 - p1;
        let b = p3 - p1;
        let n = a.cross(b);
        let nn = n.length_squared();
        if nn <= (1e-12 * a.length_squared() * b.length_squared()).max(1e-300) {
            return Err(invalid(
                "arc3 points",
                "the three points are collinear or coincide; no arc passes through them",
            ));
        }
        // Circumcentre: p1 + (|a|² (b × n) + |b|² (n × a)) / (2|n|²).
        let center =
            p1 + (b.cross(n) * a.length_squared() + n.cross(a) * b.length_squared()) / (2.0 * nn);
        let normal = n / nn.sqrt();
        let radius = (p1 - center).length();
        let (x, y) = arbitrary_axis(normal);
        let ang = |p: DVec3| {
            let v = p - center;
            norm_angle(v.dot(y).atan2(v.dot(x)))
        };
        let start = ang(p1);
        let sweep = norm_angle(ang(p3) - start);
        let sweep = if sweep == 0.0 { TAU } else { sweep };
        Ok(Arc::from_parts(center, radius, normal, start, sweep))
    }

    pub fn center(&self) -> DVec3 {
        self.center
    }
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// The unit normal; the arc runs CCW about it.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }
    /// Start angle in [0, 2π) from the OCS X axis.
    pub fn start_angle(&self) -> f64 {
        self.start
    }
    /// End angle, reduced to [0, 2π).
    pub fn end_angle(&self) -> f64 {
        norm_angle(self.start + self.sweep)
    }
    /// The angle swept, in (0, 2π].
    pub fn sweep(&self) -> f64 {
        self.sweep
    }
    /// The OCS axes (X, Y) of the normal.
    pub fn frame(&self) -> (DVec3, DVec3) {
        (self.x_axis, self.y_axis)
    }
    pub(crate) fn is_full(&self) -> bool {
        self.sweep >= TAU
    }

    #[inline]
    pub fn point_at_angle(&self, a: f64) -> DVec3 {
        let (s, c) = a.sin_cos();
        self.center + (self.x_axis * c + self.y_axis * s) * self.radius
    }

    /// The angle of `p` projected into the arc's plane, in [0, 2π) (the fast atan2 of
    /// `fastmath`: within 2 ulps of std's, same sign, so seam points stay at 0).
    #[inline(always)]
    pub fn angle_of(&self, p: DVec3) -> f64 {
        let v = p - self.center;
        norm_atan2(atan2(v.dot(self.y_axis), v.dot(self.x_axis)))
    }

    /// The public parameter of the point at angle `a` if it lies on the arc, allowing `slack`
    /// radians beyond either end (clamped to [0, 1]).
    pub(crate) fn param_of_angle(&self, a: f64, slack: f64) -> Option<f64> {
        let rel = norm_angle(a - self.start);
        if rel <= self.sweep {
            Some(rel / self.sweep)
        } else if rel <= self.sweep + slack {
            Some(1.0)
        } else if rel >= TAU - slack {
            Some(0.0)
        } else {
            None
        }
    }

    /// The public parameter of a point `p` of the circle, `None` when it is more than `tol`
    /// beyond the arc's ends (`params_of_atan2` of its angle).
    #[inline(always)]
    pub(crate) fn param_of_point(&self, p: DVec3, tol: f64) -> Option<f64> {
        let v = p - self.center;
        let (y, x) = (F2::splat(v.dot(self.y_axis)), F2::splat(v.dot(self.x_axis)));
        let (t, on) = self.params_of_atan2(atan2_lanes(y, x), tol);
        (on & 1 == 1).then_some(t.get()[0])
    }

    /// `param_of_point` of two points, their angles computed side by side (the two hits of a
    /// pair), as `params_of_atan2` gives them.
    #[inline(always)]
    pub(crate) fn params_of2(&self, p: [DVec3; 2], tol: f64) -> (F2, u32) {
        let (v0, v1) = (p[0] - self.center, p[1] - self.center);
        let y = F2::new(v0.dot(self.y_axis), v1.dot(self.y_axis));
        let x = F2::new(v0.dot(self.x_axis), v1.dot(self.x_axis));
        self.params_of_atan2(atan2_lanes(y, x), tol)
    }

    /// The public parameters of two points of the circle from their angles in the arc's
    /// frame (in [−2π, 2π]: an `atan2`, or a sum of two), and a mask with bit i set when point i is
    /// on the arc: within `tol` of it (a point beyond an end by at most `tol` gets that
    /// end). The closed forms' hot path: both points at once, no branch on the sign of an
    /// angle or on which side of the arc it falls, one division (none for a full circle),
    /// and the end slack tol / r tested as a product.
    #[inline(always)]
    pub(crate) fn params_of_atan2(&self, ang: F2, tol: f64) -> (F2, u32) {
        let k = F2::splat;
        let full = self.is_full();
        let inv = if full { 1.0 / TAU } else { 1.0 / self.sweep };
        let (sweep, turn) = (k(self.sweep), k(TAU));
        // ang in [−2π, 2π], start in [0, 2π): up to two turns to add, or one to take away.
        let d = ang - k(self.start);
        let rel = d + d.lt(k(0.0)).keep(turn) + d.lt(-turn).keep(turn) - d.ge(turn).keep(turn);
        // Just below a turn rounds up to 2π: that point is at the start.
        let rel = rel.ge(turn).drop(rel);
        let on = rel.le(sweep);
        // t rounds up to 1 only at the end: a full circle's seam is t = 0.
        let t = rel * k(inv);
        let t = t.ge(k(1.0)).select(k(if full { 0.0 } else { 1.0 }), t);
        // Beyond the end or before the start by at most tol (tol / r radians).
        let r = k(self.radius);
        let past_end = ((rel - sweep) * r).le(k(tol));
        let before_start = ((turn - rel) * r).le(k(tol));
        let t = on.select(t, past_end.keep(k(1.0)));
        (t, on.or(past_end).or(before_start).bits())
    }

    /// The coordinates of the vector `w` in the arc's frame: along X, along Y, along the
    /// normal. With the normal +Z (most drawings) the frame is the world's, and these are
    /// w's components: the same numbers as the three dot products, sooner.
    #[inline(always)]
    pub(crate) fn in_frame(&self, w: DVec3) -> (f64, f64, f64) {
        if self.normal == DVec3::Z {
            (w.x, w.y, w.z)
        } else {
            (w.dot(self.x_axis), w.dot(self.y_axis), w.dot(self.normal))
        }
    }

    /// The point at frame coordinates (u, v) from the centre, in the arc's plane.
    #[inline(always)]
    pub(crate) fn point_in_frame(&self, u: f64, v: f64) -> DVec3 {
        if self.normal == DVec3::Z {
            DVec3::new(self.center.x + u, self.center.y + v, self.center.z)
        } else {
            self.center + self.x_axis * u + self.y_axis * v
        }
    }

    /// The tangent direction (increasing angle) at a point `p` of the circle, length r.
    #[inline]
    pub(crate) fn tangent_at_point(&self, p: DVec3) -> DVec3 {
        self.normal.cross(p - self.center)
    }

    /// The unit tangent (direction of increasing angle) at angle `a`.
    pub(crate) fn tangent_at_angle(&self, a: f64) -> DVec3 {
        let (s, c) = a.sin_cos();
        self.y_axis * c - self.x_axis * s
    }
}

impl ParamCurve for Arc {
    #[inline]
    fn eval(&self, t: f64) -> DVec3 {
        self.point_at_angle(self.start + self.sweep * t)
    }
}

impl ParamCurveDeriv for Arc {
    fn deriv(&self, t: f64) -> DVec3 {
        self.tangent_at_angle(self.start + self.sweep * t) * (self.radius * self.sweep)
    }
}

impl ParamCurveArclen for Arc {
    fn arclen(&self, _accuracy: f64) -> f64 {
        self.radius * self.sweep
    }
}

impl ParamCurveNearest for Arc {
    fn nearest(&self, p: DVec3, _accuracy: f64) -> (f64, DVec3) {
        let v = p - self.center;
        let inplane = v - self.normal * v.dot(self.normal);
        if inplane.length_squared() > 0.0 {
            if let Some(t) = self.param_of_angle(self.angle_of(p), 0.0) {
                return (t, self.eval(t));
            }
        }
        let (a, b) = (self.eval(0.0), self.eval(1.0));
        if (p - a).length_squared() <= (p - b).length_squared() {
            (0.0, a)
        } else {
            (1.0, b)
        }
    }
}

impl ParamCurveBbox for Arc {
    fn bbox(&self) -> (DVec3, DVec3) {
        let (a, b) = (self.eval(0.0), self.eval(1.0));
        let mut lo = a.min(b);
        let mut hi = a.max(b);
        for i in 0..3 {
            // coordinate i is c_i + r·(cos θ x_i + sin θ y_i): extreme at atan2(y_i, x_i) (+π).
            let (xi, yi) = (self.x_axis[i], self.y_axis[i]);
            let amp = self.radius * xi.hypot(yi);
            if amp == 0.0 {
                continue;
            }
            let phi = yi.atan2(xi);
            if self.param_of_angle(phi, 0.0).is_some() {
                hi[i] = hi[i].max(self.center[i] + amp);
            }
            if self
                .param_of_angle(phi + std::f64::consts::PI, 0.0)
                .is_some()
            {
                lo[i] = lo[i].min(self.center[i] - amp);
            }
        }
        (lo, hi)
    }
}

impl ParamCurveSubdivide for Arc {
    fn subsegment(&self, t0: f64, t1: f64) -> Arc {
        Arc {
            start: norm_angle(self.start + self.sweep * t0),
            sweep: self.sweep * (t1 - t0),
            ..*self
        }
    }
}
