//! The surface kinds and their evaluation at (u, v) in [0, 1]².

use super::error::{check_point, check_positive, check_unit, SurfaceError};
use super::sweep::{rotation_minimizing_frames, Frame};
use super::{CurveRef, ParamSurface};
use crate::geom::frame::arbitrary_axis;
use glam::DVec3;
use std::f64::consts::TAU;

/// Ruled surface (直纹面): `P(u, v) = (1 − v)·c1(u) + v·c2(u)`.
#[derive(Clone)]
pub struct Ruled {
    pub c1: CurveRef,
    pub c2: CurveRef,
}

/// Surface of revolution (旋转面): the profile at `u` turned by `v·angle` about the axis
/// (right-hand rule about `axis_dir`).
#[derive(Clone)]
pub struct Revolve {
    pub profile: CurveRef,
    pub axis_point: DVec3,
    pub axis_dir: DVec3,
    pub angle: f64,
}

/// Swept surface (导动面): the profile carried along the guide by a rotation-minimising frame
/// (double reflection, Wang et al. 2008). The profile is placed as drawn relative to the
/// guide's start; `P(u, v) = g(v) + F(v)·F(0)⁻¹·(profile(u) − g(0))`.
#[derive(Clone)]
pub struct Sweep {
    pub profile: CurveRef,
    pub guide: CurveRef,
    frames: Vec<Frame>,
}

/// Boundary surface (边界面): the bilinearly blended Coons patch of four curves that run head to
/// tail around the patch (each is reversed if needed to meet the previous one's end).
#[derive(Clone)]
pub struct Coons {
    pub curves: [CurveRef; 4],
    reversed: [bool; 4],
    /// p00, p10, p11, p01: every point of the patch needs them.
    corners: [DVec3; 4],
}

impl Coons {
    /// Boundary curve i at t, in the patch's direction around it.
    pub(crate) fn edge(&self, i: usize, t: f64) -> DVec3 {
        let t = if self.reversed[i] { 1.0 - t } else { t };
        self.curves[i].eval(t)
    }

    pub(crate) fn corners(&self) -> [DVec3; 4] {
        self.corners
    }
}

impl Sweep {
    pub(crate) fn frames(&self) -> &[Frame] {
        &self.frames
    }
}

/// A planar region bounded by a closed polygon.
#[derive(Debug, Clone)]
pub struct PlaneRegion {
    /// Boundary points (no repeated closing point).
    pub boundary: Vec<DVec3>,
    /// Unit normal (Newell's method, so it follows the boundary's winding).
    pub normal: DVec3,
}

/// Right circular cylinder: base centre, unit axis, radius, height (along the axis from the base).
#[derive(Debug, Clone, Copy)]
pub struct Cylinder {
    pub base: DVec3,
    pub axis: DVec3,
    pub radius: f64,
    pub height: f64,
}

/// Sphere: centre and radius.
#[derive(Debug, Clone, Copy)]
pub struct Sphere {
    pub center: DVec3,
    pub radius: f64,
}

/// Every surface kind.
#[derive(Clone)]
pub enum Surface {
    Ruled(Ruled),
    Revolve(Revolve),
    Sweep(Sweep),
    Coons(Coons),
    Plane(PlaneRegion),
    Cylinder(Cylinder),
    Sphere(Sphere),
}

impl Surface {
    /// A ruled surface between two curves.
    pub fn ruled(c1: CurveRef, c2: CurveRef) -> Surface {
        Surface::Ruled(Ruled { c1, c2 })
    }

    /// A surface of revolution; `angle` in (0, 2π].
    pub fn revolve(
        profile: CurveRef,
        axis_point: DVec3,
        axis_dir: DVec3,
        angle: f64,
    ) -> Result<Surface, SurfaceError> {
        let axis_dir = check_unit("axis-dir", axis_dir)?;
        let axis_point = check_point("axis-point", axis_point)?;
        if !(angle > 0.0 && angle <= TAU + 1e-12) {
            return Err(SurfaceError::BadParameter {
                parameter: "angle",
                limit: "in (0, 2π]",
                value: angle,
            });
        }
        Ok(Surface::Revolve(Revolve {
            profile,
            axis_point,
            axis_dir,
            angle: angle.min(TAU),
        }))
    }

    /// A profile swept along a guide.
    pub fn sweep(profile: CurveRef, guide: CurveRef) -> Result<Surface, SurfaceError> {
        let frames = rotation_minimizing_frames(guide.as_ref(), 512)?;
        Ok(Surface::Sweep(Sweep {
            profile,
            guide,
            frames,
        }))
    }

    /// A Coons patch from four boundary curves given in order around the patch.
    pub fn boundary(curves: [CurveRef; 4]) -> Result<Surface, SurfaceError> {
        let mut reversed = [false; 4];
        let mut end = curves[0].end();
        for i in 1..4 {
            let (s, e) = (curves[i].start(), curves[i].end());
            reversed[i] = e.distance(end) < s.distance(end);
            end = if reversed[i] { s } else { e };
        }
        // The first curve may itself be backwards relative to the second.
        let (s0, e0) = (curves[0].start(), curves[0].end());
        let c1s = if reversed[1] {
            curves[1].end()
        } else {
            curves[1].start()
        };
        if s0.distance(c1s) < e0.distance(c1s) {
            reversed[0] = true;
            let mut end = s0;
            for i in 1..4 {
                let (s, e) = (curves[i].start(), curves[i].end());
                reversed[i] = e.distance(end) < s.distance(end);
                end = if reversed[i] { s } else { e };
            }
        }
        // Each curve must end where the next begins (head to tail around the patch).
        let ends: Vec<(DVec3, DVec3)> = (0..4)
            .map(|i| {
                let (s, e) = (curves[i].start(), curves[i].end());
                if reversed[i] {
                    (e, s)
                } else {
                    (s, e)
                }
            })
            .collect();
        let size = ends
            .iter()
            .map(|(s, e)| s.length().max(e.length()).max(s.distance(*e)))
            .fold(1.0, f64::max);
        for i in 0..4 {
            let gap = ends[i].1.distance(ends[(i + 1) % 4].0);
            if gap.is_nan() || gap > 1e-9 * size {
                return Err(SurfaceError::Invalid(format!(
                    "boundary-surface: curve {} does not meet curve {} at their corner \
                     (gap {gap:.3e}); the four curves must run head to tail around the patch",
                    i + 1,
                    (i + 1) % 4 + 1
                )));
            }
        }
        let mut c = Coons {
            curves,
            reversed,
            corners: [DVec3::ZERO; 4],
        };
        c.corners = [
            c.edge(0, 0.0),
            c.edge(0, 1.0),
            c.edge(2, 0.0),
            c.edge(2, 1.0),
        ];
        Ok(Surface::Coons(c))
    }

    /// A planar region bounded by the closed polygon `boundary` (closing point optional).
    pub fn plane(boundary: Vec<DVec3>) -> Result<Surface, SurfaceError> {
        let mut b = boundary;
        if b.len() > 1 && b[0] == b[b.len() - 1] {
            b.pop();
        }
        if b.len() < 3 {
            return Err(SurfaceError::BadParameter {
                parameter: "boundary point count",
                limit: "at least 3",
                value: b.len() as f64,
            });
        }
        if b.iter().any(|p| !p.is_finite()) {
            return Err(SurfaceError::Invalid(
                "boundary points must be finite".into(),
            ));
        }
        let normal = super::planar::newell_normal(&b);
        let normal = check_unit("boundary's area (Newell normal)", normal)?;
        Ok(Surface::Plane(PlaneRegion {
            boundary: b,
            normal,
        }))
    }

    /// A cylinder.
    pub fn cylinder(
        base: DVec3,
        axis: DVec3,
        radius: f64,
        height: f64,
    ) -> Result<Surface, SurfaceError> {
        Ok(Surface::Cylinder(Cylinder {
            base: check_point("base-center", base)?,
            axis: check_unit("axis-dir", axis)?,
            radius: check_positive("radius", radius)?,
            height: check_positive("height", height)?,
        }))
    }

    /// A sphere.
    pub fn sphere(center: DVec3, radius: f64) -> Result<Surface, SurfaceError> {
        Ok(Surface::Sphere(Sphere {
            center: check_point("center", center)?,
            radius: check_positive("radius", radius)?,
        }))
    }

    /// The parameters inside (0, 1) of each direction (u, v) where the surface has a crease,
    /// from its defining curves' (a polyline profile's vertices): ascending, each once.
    pub fn creases(&self) -> [Vec<f64>; 2] {
        // A curve run at parameter 1 − t (a Coons side taken backwards) has its creases mirrored.
        let of = |c: &CurveRef, backwards: bool| -> Vec<f64> {
            let t = c.creases();
            if backwards {
                t.into_iter().map(|x| 1.0 - x).collect()
            } else {
                t
            }
        };
        let mut out = match self {
            Surface::Ruled(r) => [[of(&r.c1, false), of(&r.c2, false)].concat(), Vec::new()],
            Surface::Revolve(r) => [of(&r.profile, false), Vec::new()],
            Surface::Sweep(s) => [of(&s.profile, false), of(&s.guide, false)],
            Surface::Coons(c) => {
                // Bottom runs with u, top against it; right with v, left against it.
                let side = |i: usize, against: bool| of(&c.curves[i], c.reversed[i] != against);
                [
                    [side(0, false), side(2, true)].concat(),
                    [side(1, false), side(3, true)].concat(),
                ]
            }
            Surface::Plane(_) | Surface::Cylinder(_) | Surface::Sphere(_) => {
                [Vec::new(), Vec::new()]
            }
        };
        for t in &mut out {
            t.retain(|x| *x > 0.0 && *x < 1.0);
            t.sort_by(f64::total_cmp);
            t.dedup();
        }
        out
    }

    /// The kind's name, as the language shows it.
    pub fn name(&self) -> &'static str {
        match self {
            Surface::Ruled(_) => "ruled",
            Surface::Revolve(_) => "revolve",
            Surface::Sweep(_) => "sweep",
            Surface::Coons(_) => "boundary",
            Surface::Plane(_) => "plane",
            Surface::Cylinder(_) => "cylinder",
            Surface::Sphere(_) => "sphere",
        }
    }
}

impl std::fmt::Debug for Surface {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Surface::{}", self.name())
    }
}

impl Cylinder {
    /// The OCS axes of the base circle (DXF arbitrary-axis frame of the axis).
    pub fn frame(&self) -> (DVec3, DVec3) {
        arbitrary_axis(self.axis)
    }
}

impl ParamSurface for Surface {
    fn eval(&self, u: f64, v: f64) -> DVec3 {
        match self {
            Surface::Plane(_) | Surface::Sphere(_) => self.eval_whole(u, v),
            _ => self.combine(&self.u_part(u), &self.v_part(v)),
        }
    }
}

impl Surface {
    /// The point at (u, v) of the kinds whose parameters do not separate.
    pub(crate) fn eval_whole(&self, u: f64, v: f64) -> DVec3 {
        match self {
            Surface::Plane(p) => {
                // Not parametric over the unit square; map (u, v) into the boundary's box.
                let (x, y) = arbitrary_axis(p.normal);
                let o = p.boundary[0];
                let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
                for q in &p.boundary {
                    let d = *q - o;
                    x0 = x0.min(d.dot(x));
                    x1 = x1.max(d.dot(x));
                    y0 = y0.min(d.dot(y));
                    y1 = y1.max(d.dot(y));
                }
                o + x * (x0 + u * (x1 - x0)) + y * (y0 + v * (y1 - y0))
            }
            Surface::Sphere(s) => {
                let lon = TAU * u;
                let lat = std::f64::consts::PI * (v - 0.5);
                s.center
                    + s.radius * DVec3::new(lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin())
            }
            _ => self.eval(u, v),
        }
    }
}
