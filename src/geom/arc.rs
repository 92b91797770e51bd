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
    /// Start angle in [0, 2π).
    pub(crate) start: f64,
    /// Swept angle in (0, 2π].
    pub(crate) sweep: f64,
    /// The unit vector (in the frame) at the middle of the arc, and cos(sweep / 2): a point
    /// q of the circle (about the centre) is on the arc when q·mid ≥ r·cos_half. Cached for
    /// the closed forms, which reject points far off the arc before any atan2. Derived from
    /// start and sweep: set those only through `from_parts` or `with_range`.
    pub(crate) cos_half: f64,
    pub(crate) mid: (f64, f64),
    pub(crate) x_axis: DVec3,
    pub(crate) y_axis: DVec3,
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
            start: 0.0,
            sweep: 0.0,
            mid: (1.0, 0.0),
            cos_half: 1.0,
        }
        .with_range(start, sweep)
    }

    /// The arc scaled by `k` about the origin (same angles and frame).
    pub(crate) fn scaled(&self, k: f64) -> Arc {
        Arc {
            center: self.center * k,
            radius: self.radius * k,
            ..*self
        }
    }

    /// The same circle with another angle range (start in [0, 2π), sweep in (0, 2π]).
    pub(crate) fn with_range(&self, start: f64, sweep: f64) -> Arc {
        let (sin, cos) = (start + 0.5 * sweep).sin_cos();
        Arc {
            start,
            sweep,
            mid: (cos, sin),
            cos_half: (0.5 * sweep).cos(),
            ..*self
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

    /// A mask of the two points of the circle (given in the frame about the centre, times
    /// `scale` > 0) that may be on the arc: no atan2, and it never drops a point that
    /// `params_of_atan2` keeps. A point δ ≤ tol/r beyond an end has q·mid ≥
    /// r·cos_half − tol − tol²/2r; the bound allows 2·tol + 1e-9·r, which also covers the
    /// rounding of q.
    #[inline(always)]
    pub(crate) fn maybe_on(&self, q: [(f64, f64); 2], scale: f64, tol: f64) -> u32 {
        let r = self.radius;
        if self.is_full() || r <= tol {
            return 0b11;
        }
        let lim = scale * (r * self.cos_half - (2.0 * tol + 1e-9 * r));
        let on = |(x, y): (f64, f64)| (x * self.mid.0 + y * self.mid.1 >= lim) as u32;
        on(q[0]) | on(q[1]) << 1
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
        let turn = k(TAU);
        let rel = if self.start == 0.0 {
            // ang in [−2π, 2π]: one turn at most (circles start at 0).
            ang + ang.lt(k(0.0)).keep(turn)
        } else {
            // ang − start in (−4π, 2π]: up to two turns to add, or one to take away.
            let d = ang - k(self.start);
            d + d.lt(k(0.0)).keep(turn) + d.lt(-turn).keep(turn) - d.ge(turn).keep(turn)
        };
        // Just below a turn rounds up to 2π: that point is at the start.
        let rel = rel.ge(turn).drop(rel);
        if self.is_full() {
            // Every point is on it; t rounds up to 1 only at the seam, which is t = 0. (The
            // mask is false only for a NaN angle: no NaN reaches a result.)
            let t = rel * k(1.0 / TAU);
            return (t.ge(k(1.0)).drop(t), rel.ge(k(0.0)).bits());
        }
        let sweep = k(self.sweep);
        let on = rel.le(sweep);
        let t = (rel * k(1.0 / self.sweep)).min(k(1.0));
        // Beyond the end or before the start by at most tol (tol / r radians).
        let r = k(self.radius);
        let past_end = ((rel - sweep) * r).le(k(tol));
        let before_start = ((turn - rel) * r).le(k(tol));
        let t = on.select(t, past_end.keep(k(1.0)));
        (t, on.or(past_end).or(before_start).bits())
    }

    /// The arc's 2D frame, for the closed forms (`Frame`).
    #[inline(always)]
    pub(crate) fn frame_view(&self) -> Frame<'_> {
        // The normal exactly +Z, compared as bits: integer tests, and a −0 component just
        // takes the general path.
        let world = (self.normal.x.to_bits() | self.normal.y.to_bits()) == 0
            && self.normal.z.to_bits() == 1f64.to_bits();
        Frame { arc: self, world }
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

/// An arc's frame (X, Y, normal) for the closed forms, with one test done up front: when
/// the normal is +Z (most drawings) the frame is the world's, and coordinates in it are
/// the components themselves, the same numbers as the dot products, sooner.
#[derive(Clone, Copy)]
pub(crate) struct Frame<'a> {
    arc: &'a Arc,
    world: bool,
}

impl Frame<'_> {
    /// The coordinates of the vector `w`: along X, along Y, along the normal.
    #[inline(always)]
    pub(crate) fn coords(&self, w: DVec3) -> (f64, f64, f64) {
        let a = self.arc;
        if self.world {
            (w.x, w.y, w.z)
        } else {
            (w.dot(a.x_axis), w.dot(a.y_axis), w.dot(a.normal))
        }
    }

    /// The point at frame coordinates (u, v) from the centre, in the arc's plane.
    #[inline(always)]
    pub(crate) fn point(&self, (u, v): (f64, f64)) -> DVec3 {
        let a = self.arc;
        if self.world {
            DVec3::new(a.center.x + u, a.center.y + v, a.center.z)
        } else {
            a.center + a.x_axis * u + a.y_axis * v
        }
    }

    /// `point` of two points (not `map`: that is not always inlined).
    #[inline(always)]
    pub(crate) fn points(&self, q: [(f64, f64); 2]) -> [DVec3; 2] {
        [self.point(q[0]), self.point(q[1])]
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
        self.with_range(
            norm_angle(self.start + self.sweep * t0),
            self.sweep * (t1 - t0),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::geom::test_rng::Rng;

    /// The quick rejection never drops a point the exact parameter test keeps: points at
    /// random angles, and points just inside and just beyond both ends (within and past
    /// the end slack), on arcs of every sweep and radii from 1e-6 to 1e6.
    #[test]
    fn maybe_on_keeps_every_point_params_keep() {
        let mut r = Rng(0x2545F4914F6CDD1D);
        let tol = 1e-9;
        let mut kept = 0;
        for i in 0..200_000 {
            let radius = 10f64.powf(r.f() * 12.0 - 6.0);
            let start = r.f() * TAU;
            let sweep = if i % 50 == 0 { TAU } else { r.f() * TAU };
            let Ok(a) = Arc::new(DVec3::ZERO, radius, start, start + sweep, DVec3::Z) else {
                continue;
            };
            let slack = tol / radius;
            let ang = match i % 5 {
                0 => r.f() * TAU,
                1 => a.start - slack * r.f() * 2.0,
                2 => a.start + a.sweep + slack * r.f() * 2.0,
                3 => a.start + a.sweep - slack * r.f(),
                _ => a.start + slack * r.f(),
            };
            // The point in the frame, relative to the centre, times a scale.
            let scale = 10f64.powf(r.f() * 4.0 - 2.0);
            let q = (radius * ang.cos() * scale, radius * ang.sin() * scale);
            let (_, on) = a.params_of_atan2(
                crate::geom::fastmath::atan2_lanes(F2::splat(q.1), F2::splat(q.0)),
                tol,
            );
            if on & 1 == 1 {
                kept += 1;
                assert_eq!(a.maybe_on([q; 2], scale, tol), 0b11, "{a:?} at angle {ang}");
            }
        }
        assert!(kept > 50_000, "only {kept} points on their arcs");
    }

    /// A NaN angle is never a point of the curve, full circle or arc.
    #[test]
    fn nan_angles_are_off_every_arc() {
        let circle = Arc::from_parts(DVec3::ZERO, 1.0, DVec3::Z, 0.0, TAU);
        let turned = circle.with_range(1.0, TAU);
        let arc = Arc::new(DVec3::ZERO, 1.0, 1.0, 2.0, DVec3::Z).unwrap();
        for a in [circle, turned, arc] {
            let (_, on) = a.params_of_atan2(F2::new(f64::NAN, 0.5), 1e-9);
            assert_eq!(on & 1, 0, "{a:?}");
        }
    }

    /// The cached middle direction and cos(sweep/2) follow every change of range.
    #[test]
    fn with_range_recomputes_the_cache() {
        let a = Arc::new(DVec3::new(1.0, 2.0, 3.0), 2.0, 0.5, 2.0, DVec3::Y).unwrap();
        let b = a.with_range(4.0, 3.0);
        let c = Arc::from_parts(a.center, a.radius, a.normal, 4.0, 3.0);
        assert_eq!(b, c);
        let s = a.subsegment(0.25, 0.75);
        assert_eq!(s, a.with_range(s.start, s.sweep));
        assert!((s.mid.0 - (s.start + 0.5 * s.sweep).cos()).abs() < 1e-15);
    }
}
