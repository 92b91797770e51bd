//! An ellipse or elliptical arc with DXF ELLIPSE's conventions: centre C, major-axis vector M
//! (centre to the end of the major axis), unit normal n, ratio r = minor / major in (0, 1], and
//! the eccentric-anomaly parameters `start`, `end` in radians. The point at angle θ is
//!
//!   E(θ) = C + M cos θ + m sin θ,   m = r · (n × M),
//!
//! running counter-clockwise about n from `start` to `end` (end ≤ start wraps by 2π; equal
//! values, or 0 and 2π, give the full ellipse). AutoCAD's parameter of an ELLIPSE is this θ.
//!
//! The geometry core sees the ellipse as exact rational quadratic Bézier spans (the affine
//! image of the circular-arc conic), at most a quarter turn each. The public parameter t runs
//! over [0, 1] with span i covering [i/k, (i+1)/k] and the span's own Bézier parameter linear
//! inside it, so every span-based algorithm is consistent; `angle_at` and `t_at_angle` convert
//! exactly between t and θ (inside a span of angle Δ centred on θc, θ = θc + 2·atan((2s − 1)·
//! tan(Δ/4))).

use std::f64::consts::{FRAC_PI_2, TAU};

use glam::{DVec3, DVec4};
use smallvec::smallvec;

use super::arc::{check_normal, norm_angle};
use super::bezier::Bez;
use super::error::{finite, finite3, invalid, Result};
use super::piece::{Piece, Span};

/// An ellipse or elliptical arc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipse {
    pub(crate) center: DVec3,
    /// Centre to the end of the major axis.
    pub(crate) major: DVec3,
    /// Centre to the end of the minor axis: ratio · (n × major).
    pub(crate) minor: DVec3,
    pub(crate) normal: DVec3,
    pub(crate) ratio: f64,
    /// Start angle in [0, 2π).
    pub(crate) start: f64,
    /// Swept angle in (0, 2π].
    pub(crate) sweep: f64,
}

impl Ellipse {
    /// A checked ellipse: `major` non-zero and perpendicular to `normal` (relative 1e-9),
    /// 0 < ratio ≤ 1, finite angles.
    pub fn new(
        center: DVec3,
        major: DVec3,
        ratio: f64,
        start: f64,
        end: f64,
        normal: DVec3,
    ) -> Result<Ellipse> {
        finite3("center", center)?;
        finite3("major axis", major)?;
        finite("ratio", ratio)?;
        finite("start", start)?;
        finite("end", end)?;
        let normal = check_normal(normal)?;
        let len = major.length();
        if len <= 1e-300 {
            return Err(invalid("major axis", "must not be the zero vector"));
        }
        if major.dot(normal).abs() > 1e-9 * len {
            return Err(invalid("major axis", "must be perpendicular to the normal"));
        }
        if !(ratio > 0.0 && ratio <= 1.0) {
            return Err(invalid("ratio", format!("must be in (0, 1], got {ratio}")));
        }
        // Remove the tiny normal component so the frame is exactly orthogonal.
        let major = major - normal * major.dot(normal);
        let s = norm_angle(start);
        let mut sweep = norm_angle(end) - s;
        if sweep <= 0.0 || (end - start).abs() >= TAU {
            sweep += TAU;
        }
        Ok(Ellipse {
            center,
            major,
            minor: normal.cross(major) * ratio,
            normal,
            ratio,
            start: s,
            sweep,
        })
    }

    pub fn center(&self) -> DVec3 {
        self.center
    }
    pub fn major_axis(&self) -> DVec3 {
        self.major
    }
    pub fn normal(&self) -> DVec3 {
        self.normal
    }
    pub fn ratio(&self) -> f64 {
        self.ratio
    }
    /// The start angle θ0 in [0, 2π).
    pub fn start_angle(&self) -> f64 {
        self.start
    }
    /// The end angle θ0 + sweep (may exceed 2π).
    pub fn end_angle(&self) -> f64 {
        self.start + self.sweep
    }
    pub fn sweep(&self) -> f64 {
        self.sweep
    }
    pub fn is_full(&self) -> bool {
        self.sweep >= TAU
    }

    /// E(θ).
    pub fn point_at_angle(&self, a: f64) -> DVec3 {
        let (s, c) = a.sin_cos();
        self.center + self.major * c + self.minor * s
    }

    /// dE/dθ.
    pub fn deriv_at_angle(&self, a: f64) -> DVec3 {
        let (s, c) = a.sin_cos();
        self.minor * c - self.major * s
    }

    /// d²E/dθ².
    pub fn second_deriv_at_angle(&self, a: f64) -> DVec3 {
        let (s, c) = a.sin_cos();
        -(self.major * c + self.minor * s)
    }

    /// The eccentric angle of a point (projected into the ellipse's plane), in [0, 2π).
    pub fn angle_of(&self, p: DVec3) -> f64 {
        let v = p - self.center;
        let x = v.dot(self.major) / self.major.length_squared();
        let y = v.dot(self.minor) / self.minor.length_squared();
        norm_angle(y.atan2(x))
    }

    /// The number of spans: quarter turns at most.
    fn span_count(&self) -> usize {
        ((self.sweep / FRAC_PI_2 - 1e-9).ceil() as usize).max(1)
    }

    /// θ at public parameter t ∈ [0, 1].
    pub fn angle_at(&self, t: f64) -> f64 {
        let k = self.span_count();
        let d = self.sweep / k as f64;
        let x = t.clamp(0.0, 1.0) * k as f64;
        let i = (x.floor() as usize).min(k - 1);
        let s = x - i as f64;
        let mid = self.start + d * (i as f64 + 0.5);
        mid + 2.0 * ((2.0 * s - 1.0) * (d / 4.0).tan()).atan()
    }

    /// The public parameter of angle θ (reduced into the arc; angles outside it clamp to the
    /// nearer end).
    pub fn t_at_angle(&self, a: f64) -> f64 {
        let mut rel = norm_angle(a - self.start);
        if rel > self.sweep {
            // Outside the arc: the nearer end.
            rel = if rel - self.sweep < TAU - rel {
                self.sweep
            } else {
                0.0
            };
        }
        let k = self.span_count();
        let d = self.sweep / k as f64;
        let i = ((rel / d).floor() as usize).min(k - 1);
        let phi = rel - d * (i as f64 + 0.5);
        let s = 0.5 * ((phi / 2.0).tan() / (d / 4.0).tan() + 1.0);
        ((i as f64 + s.clamp(0.0, 1.0)) / k as f64).clamp(0.0, 1.0)
    }

    /// The exact rational quadratic spans.
    pub fn spans(&self) -> Vec<Span> {
        let k = self.span_count();
        let d = self.sweep / k as f64;
        let w = (d / 2.0).cos();
        (0..k)
            .map(|i| {
                let a0 = self.start + d * i as f64;
                let (p0, p2) = (self.point_at_angle(a0), self.point_at_angle(a0 + d));
                let mid = a0 + d / 2.0;
                let p1 = self.center + (self.major * mid.cos() + self.minor * mid.sin()) / w;
                Span {
                    piece: Piece::Bez(Bez {
                        h: smallvec![p0.extend(1.0), (p1 * w).extend(w), p2.extend(1.0)],
                        rational: true,
                    }),
                    t0: i as f64 / k as f64,
                    t1: (i + 1) as f64 / k as f64,
                }
            })
            .collect()
    }

    /// The homogeneous control points of the whole ellipse as one degree-2 NURBS (the spans
    /// joined with double interior knots): for writing it as a SPLINE.
    pub fn nurbs(&self) -> (Vec<DVec3>, Vec<f64>, Vec<f64>) {
        let spans = self.spans();
        let k = spans.len();
        let mut ctrl = Vec::with_capacity(2 * k + 1);
        let mut weights = Vec::with_capacity(2 * k + 1);
        for (i, sp) in spans.iter().enumerate() {
            let Piece::Bez(b) = &sp.piece else {
                unreachable!("ellipse spans are Béziers")
            };
            let take = if i == 0 { 0 } else { 1 };
            for h in &b.h[take..] {
                let h: DVec4 = *h;
                ctrl.push(h.truncate() / h.w);
                weights.push(h.w);
            }
        }
        let mut knots = vec![0.0; 3];
        for i in 1..k {
            let u = i as f64 / k as f64;
            knots.push(u);
            knots.push(u);
        }
        knots.extend([1.0; 3]);
        (ctrl, knots, weights)
    }

    /// The area of the full ellipse, π a b.
    pub fn full_area(&self) -> f64 {
        std::f64::consts::PI * self.major.length() * self.minor.length()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::traits::ParamCurve;

    fn sample() -> Ellipse {
        Ellipse::new(
            DVec3::new(1.0, 2.0, 0.5),
            DVec3::new(3.0, 1.0, 0.0),
            0.4,
            0.3,
            5.0,
            DVec3::new(0.0, 0.0, 1.0),
        )
        .unwrap()
    }

    #[test]
    fn spans_trace_the_ellipse_with_the_angle_map() {
        let e = sample();
        let spans = e.spans();
        for sp in &spans {
            for j in 0..=16 {
                let s = j as f64 / 16.0;
                let t = sp.t_of(s);
                let p = sp.piece.eval(s);
                let a = e.angle_at(t);
                assert!((p - e.point_at_angle(a)).length() < 1e-12, "t {t}");
                assert!((e.t_at_angle(a) - t).abs() < 1e-12, "t {t}");
            }
        }
    }

    #[test]
    fn full_ellipse_and_refusals() {
        let e = Ellipse::new(DVec3::ZERO, DVec3::X * 2.0, 0.5, 0.0, TAU, DVec3::Z).unwrap();
        assert!(e.is_full());
        assert_eq!(e.spans().len(), 4);
        assert!((e.point_at_angle(FRAC_PI_2) - DVec3::Y).length() < 1e-15);
        assert!(Ellipse::new(DVec3::ZERO, DVec3::Z, 0.5, 0.0, 1.0, DVec3::Z).is_err());
        assert!(Ellipse::new(DVec3::ZERO, DVec3::X, 1.5, 0.0, 1.0, DVec3::Z).is_err());
        let b = crate::geom::bspline::BSpline::new(
            2,
            e.nurbs().0,
            Some(e.nurbs().1),
            Some(e.nurbs().2),
        )
        .unwrap();
        for j in 0..=40 {
            let p = b.eval(j as f64 / 40.0);
            let a = e.angle_of(p);
            assert!((p - e.point_at_angle(a)).length() < 1e-12);
        }
    }
}
