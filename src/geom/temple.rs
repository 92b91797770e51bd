//! The eyeglass-temple bend of paper 004 (Zhou, Li, Xue 2007, "parametric modeling and curving
//! algorithm of eyeglasses' temple"), with the corrections of SEEDS.md.
//!
//! The straight temple's centerline starts at the base point P1 = (x, y) and runs along +X for
//! length L1. Bending by (L2, R, θ) replaces it with line P1–P2 (length L = L1 − L2 − R·tan(θ/2)),
//! arc P2–P3 (centre O1, radius R, turning through θ) and line P3–P4 (length Lp = L1 − L − R·θ),
//! so the centerline keeps length L1. θ > 0 bends toward −Y; θ < 0 is the mirror image (bends
//! toward +Y). A point at (s, d) — arc position s along the straight centerline, signed offset d
//! from it — goes to the point at the same s along the bent centerline and the same offset d
//! from it ("every point keeps its distance from the centerline"). Z is kept.
//!
//! The outline is bent "transform first, then generate": the type-value points are bent and the
//! quadratic spline refitted through them; [`bend_spline`] then adds type-value points where the
//! refit drifts from the exact bend of the original outline (see `temple_refine`).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::{DVec2, DVec3};

use super::quadspline_fit::QuadSplineError;

pub use super::temple_refine::{bend_spline, bend_spline_interpolated, BentSpline};

/// The bend parameters of paper 004.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TempleParams {
    /// Total length of the temple's centerline (mm).
    pub l1: f64,
    /// Distance from the temple's far end back to the vertex V where the two straight parts'
    /// extensions meet, measured on the straight temple.
    pub l2: f64,
    /// Bend radius (> 0).
    pub r: f64,
    /// Bend angle in radians, |θ| < π; positive bends toward −Y.
    pub theta: f64,
    /// The base point P1.
    pub base: DVec2,
}

/// Why a bend was refused. Messages name the parameter and the limit.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TempleError {
    #[error("temple parameter {name} must be finite, got {value}")]
    NonFinite { name: &'static str, value: f64 },
    #[error("temple length L1 must be > 0, got {l1}")]
    LengthNotPositive { l1: f64 },
    #[error("bend radius R must be > 0, got {r}")]
    RadiusNotPositive { r: f64 },
    #[error("bend angle theta must satisfy |theta| < pi, got {theta}")]
    AngleOutOfRange { theta: f64 },
    #[error(
        "the straight part before the bend L = L1 - L2 - R*tan(theta/2) = {l} must be >= 0 \
         (L1 = {l1}, L2 = {l2}, R = {r}, theta = {theta}); reduce L2 or R"
    )]
    StraightNegative {
        l: f64,
        l1: f64,
        l2: f64,
        r: f64,
        theta: f64,
    },
    #[error(
        "the straight part after the bend Lp = L1 - L - R*theta = L2 + R*(tan(theta/2) - theta) \
         = {lp} must be >= 0 (L2 = {l2}, R = {r}, theta = {theta}); the bend runs past the end, \
         increase L2"
    )]
    TailNegative {
        lp: f64,
        l2: f64,
        r: f64,
        theta: f64,
    },
    #[error("point {index} is not finite")]
    NonFinitePoint { index: usize },
    #[error(
        "point {index} lies {offset} inside the bend, not less than the bend radius R = {r}: \
         the outline would fold"
    )]
    Fold { index: usize, offset: f64, r: f64 },
    #[error(
        "the outline at parameter {t} lies {offset} inside the bend, not less than the bend \
         radius R = {r}: the outline would fold"
    )]
    OutlineFolds { t: f64, offset: f64, r: f64 },
    #[error("bend tolerance must be finite and > 0, got {tol}")]
    Tolerance { tol: f64 },
    #[error("refitting the bent outline: {0}")]
    Spline(#[from] QuadSplineError),
}

impl TempleParams {
    /// Check the parameters: finite, L1 > 0, R > 0, |θ| < π, L ≥ 0 and Lp ≥ 0.
    pub fn validate(&self) -> Result<(), TempleError> {
        Bend::new(self).map(|_| ())
    }

    /// L = L1 − L2 − R·tan(|θ|/2), the first straight part (not validated).
    pub fn straight_length(&self) -> f64 {
        self.l1 - self.l2 - self.r * (0.5 * self.theta.abs()).tan()
    }
}

/// The validated bend, with the quantities every mapped point needs.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Bend {
    pub(crate) base: DVec2,
    pub(crate) l: f64,
    pub(crate) lp: f64,
    pub(crate) r: f64,
    /// |θ|.
    pub(crate) th: f64,
    /// +1 bends toward −Y (θ ≥ 0), −1 toward +Y.
    pub(crate) sign: f64,
    sin: f64,
    cos: f64,
}

impl Bend {
    pub(crate) fn new(p: &TempleParams) -> Result<Bend, TempleError> {
        for (name, value) in [
            ("L1", p.l1),
            ("L2", p.l2),
            ("R", p.r),
            ("theta", p.theta),
            ("base x", p.base.x),
            ("base y", p.base.y),
        ] {
            if !value.is_finite() {
                return Err(TempleError::NonFinite { name, value });
            }
        }
        if p.l1 <= 0.0 {
            return Err(TempleError::LengthNotPositive { l1: p.l1 });
        }
        if p.r <= 0.0 {
            return Err(TempleError::RadiusNotPositive { r: p.r });
        }
        let th = p.theta.abs();
        if th >= PI {
            return Err(TempleError::AngleOutOfRange { theta: p.theta });
        }
        let l = p.straight_length();
        if l < 0.0 {
            return Err(TempleError::StraightNegative {
                l,
                l1: p.l1,
                l2: p.l2,
                r: p.r,
                theta: p.theta,
            });
        }
        let lp = p.l1 - l - p.r * th;
        if lp < 0.0 {
            return Err(TempleError::TailNegative {
                lp,
                l2: p.l2,
                r: p.r,
                theta: p.theta,
            });
        }
        Ok(Bend {
            base: p.base,
            l,
            lp,
            r: p.r,
            th,
            sign: if p.theta < 0.0 { -1.0 } else { 1.0 },
            sin: th.sin(),
            cos: th.cos(),
        })
    }

    /// (s, d'): position along the straight centerline and offset, d' > 0 away from the centre
    /// of the bend.
    pub(crate) fn local(&self, p: DVec3) -> (f64, f64) {
        (p.x - self.base.x, self.sign * (p.y - self.base.y))
    }

    fn world(&self, x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(self.base.x + x, self.base.y + self.sign * y, z)
    }

    /// How far inside the bend a point lies (−d'), when it is moved by the bend (s > L).
    pub(crate) fn inner_offset(&self, p: DVec3) -> Option<f64> {
        let (s, d) = self.local(p);
        (s > self.l && self.th > 0.0).then_some(-d)
    }

    /// The bend of paper 004 (corrected): unchanged for s ≤ L, around O1 for L < s ≤ L + Rθ,
    /// rigidly moved with the last line beyond. Assumes the fold check passed.
    pub(crate) fn map(&self, p: DVec3) -> DVec3 {
        let (s, d) = self.local(p);
        if s <= self.l || self.th == 0.0 {
            return p;
        }
        let arc = self.r * self.th;
        if s <= self.l + arc {
            let a = (s - self.l) / self.r;
            let rr = self.r + d;
            self.world(self.l + rr * a.sin(), -self.r + rr * a.cos(), p.z)
        } else {
            let t = s - self.l - arc;
            let p3 = DVec2::new(self.l + self.r * self.sin, -self.r + self.r * self.cos);
            self.world(
                p3.x + t * self.cos + d * self.sin,
                p3.y - t * self.sin + d * self.cos,
                p.z,
            )
        }
    }

    /// The Jacobian of the map in the XY plane: (∂W'/∂X, ∂W'/∂Y) as world vectors.
    pub(crate) fn jacobian(&self, p: DVec3) -> (DVec3, DVec3) {
        let (s, d) = self.local(p);
        if s <= self.l || self.th == 0.0 {
            return (DVec3::X, DVec3::Y);
        }
        let arc = self.r * self.th;
        // Local derivatives (d/ds, d/dd'), then back to world: y flips with sign, and d' = sign·Y.
        let (ds, dd) = if s <= self.l + arc {
            let a = (s - self.l) / self.r;
            let k = (self.r + d) / self.r;
            (
                DVec2::new(k * a.cos(), -k * a.sin()),
                DVec2::new(a.sin(), a.cos()),
            )
        } else {
            (
                DVec2::new(self.cos, -self.sin),
                DVec2::new(self.sin, self.cos),
            )
        };
        let g = self.sign;
        (
            DVec3::new(ds.x, g * ds.y, 0.0),
            DVec3::new(g * dd.x, dd.y, 0.0),
        )
    }
}

/// One piece of the bent centerline, as plain data for the curve constructors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CenterPiece {
    Line {
        start: DVec3,
        end: DVec3,
    },
    /// An arc CCW about `normal` from `start_angle` to `end_angle` (radians from +X, in
    /// [0, 2π)), as DXF's ARC with extrusion (0, 0, 1).
    Arc {
        center: DVec3,
        radius: f64,
        start_angle: f64,
        end_angle: f64,
        normal: DVec3,
    },
}

/// The bent centerline: key points P1..P4 and O1 (z = 0) and the arc's data.
///
/// The arc runs P2 → P3, so the three pieces join head to tail. Its angles are measured CCW
/// about its normal from the X axis of that normal's arbitrary-axis frame (as DXF). For θ > 0 the
/// bend turns clockwise in XY, which is counter-clockwise about the normal (0, 0, −1), whose
/// frame's X axis is −X: from P2 (start_angle = π/2) to P3 (end_angle = π/2 + θ). For θ < 0 the
/// normal is (0, 0, 1), from P2 (3π/2) to P3 (3π/2 + |θ|).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TempleCenterline {
    pub p1: DVec3,
    pub p2: DVec3,
    pub p3: DVec3,
    pub p4: DVec3,
    pub o1: DVec3,
    /// Length of line P1–P2 (L).
    pub l: f64,
    /// Length of line P3–P4 (Lp).
    pub lp: f64,
    pub radius: f64,
    pub start_angle: f64,
    pub end_angle: f64,
    pub normal: DVec3,
}

impl TempleCenterline {
    /// The three pieces in order along the centerline, leaving out degenerate ones (a line of
    /// length 0 when L = 0 or Lp = 0; the arc when θ = 0).
    pub fn pieces(&self) -> Vec<CenterPiece> {
        let mut out = Vec::with_capacity(3);
        if self.l > 0.0 {
            out.push(CenterPiece::Line {
                start: self.p1,
                end: self.p2,
            });
        }
        if self.start_angle != self.end_angle {
            out.push(CenterPiece::Arc {
                center: self.o1,
                radius: self.radius,
                start_angle: self.start_angle,
                end_angle: self.end_angle,
                normal: self.normal,
            });
        }
        if self.lp > 0.0 {
            out.push(CenterPiece::Line {
                start: self.p3,
                end: self.p4,
            });
        }
        out
    }

    /// The arc's sweep |θ| (radians).
    pub fn sweep(&self) -> f64 {
        (self.end_angle - self.start_angle).rem_euclid(TAU)
    }

    /// Total length L + R·|θ| + Lp (= L1).
    pub fn length(&self) -> f64 {
        self.l + self.radius * self.sweep() + self.lp
    }

    /// Distance from `p` to the bent centerline (the nearest of its three pieces).
    pub fn distance(&self, p: DVec3) -> f64 {
        let seg = |a: DVec3, b: DVec3| {
            let ab = b - a;
            let len2 = ab.length_squared();
            let t = if len2 > 0.0 {
                ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            p.distance(a + ab * t)
        };
        let mut best = seg(self.p1, self.p2).min(seg(self.p3, self.p4));
        let v = p - self.o1;
        // The angle in the arc's own frame (the normal may be −Z).
        let (ax, ay) = crate::geom::frame::arbitrary_axis(self.normal);
        let ang = v.dot(ay).atan2(v.dot(ax)).rem_euclid(TAU);
        let rel = (ang - self.start_angle).rem_euclid(TAU);
        if rel <= self.sweep() {
            best = best.min(
                (DVec2::new(v.x, v.y).length() - self.radius)
                    .abs()
                    .hypot(v.z),
            );
        }
        let ends = p.distance(self.p2).min(p.distance(self.p3));
        best.min(ends)
    }
}

/// The bent centerline of paper 004 (corrected formulas, SEEDS.md): P2 = (x + L, y),
/// O1 = (x + L, y − R), P3 = O1 + R·(sin θ, cos θ), P4 = P3 + Lp·(cos θ, −sin θ), mirrored in
/// the centerline for θ < 0.
pub fn centerline(p: &TempleParams) -> Result<TempleCenterline, TempleError> {
    let b = Bend::new(p)?;
    let g = b.sign;
    let p1 = b.world(0.0, 0.0, 0.0);
    let p2 = b.world(b.l, 0.0, 0.0);
    let o1 = b.world(b.l, -b.r, 0.0);
    let p3 = b.world(b.l + b.r * b.sin, -b.r + b.r * b.cos, 0.0);
    let p4 = p3 + DVec3::new(b.lp * b.cos, -g * b.lp * b.sin, 0.0);
    let (start_angle, end_angle, normal) = if g > 0.0 {
        (FRAC_PI_2, FRAC_PI_2 + b.th, DVec3::NEG_Z)
    } else {
        (
            3.0 * FRAC_PI_2,
            (3.0 * FRAC_PI_2 + b.th).rem_euclid(TAU),
            DVec3::Z,
        )
    };
    Ok(TempleCenterline {
        p1,
        p2,
        p3,
        p4,
        o1,
        l: b.l,
        lp: b.lp,
        radius: b.r,
        start_angle,
        end_angle,
        normal,
    })
}

/// One point bent (z kept). Refuses a point that the bend moves (s > L) lying at least R inside
/// the bend (its image would fold over the centre of the bend); the error's index is 0.
pub fn bend_point(p: DVec3, params: &TempleParams) -> Result<DVec3, TempleError> {
    let b = Bend::new(params)?;
    bend_one(&b, p, 0)
}

pub(crate) fn bend_one(b: &Bend, p: DVec3, index: usize) -> Result<DVec3, TempleError> {
    if !p.is_finite() {
        return Err(TempleError::NonFinitePoint { index });
    }
    if let Some(offset) = b.inner_offset(p) {
        if offset >= b.r {
            return Err(TempleError::Fold {
                index,
                offset,
                r: b.r,
            });
        }
    }
    Ok(b.map(p))
}

/// Every point bent; an error names the first offending point's index.
pub fn bend_points(points: &[DVec3], params: &TempleParams) -> Result<Vec<DVec3>, TempleError> {
    let b = Bend::new(params)?;
    points
        .iter()
        .enumerate()
        .map(|(i, p)| bend_one(&b, *p, i))
        .collect()
}

/// The Jacobian of the bend at `p` in the XY plane: the images of the unit X and Y directions.
/// Continuous along the centerline (d = 0) at s = L and s = L + Rθ, which is the map's C1
/// property there; off the centerline the X image scales by (R + d)/R inside the arc.
pub fn bend_jacobian(p: DVec3, params: &TempleParams) -> Result<(DVec3, DVec3), TempleError> {
    let b = Bend::new(params)?;
    Ok(b.jacobian(p))
}
