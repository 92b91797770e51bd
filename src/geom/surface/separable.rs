//! A surface's point at (u, v) from a part that depends on u alone and a part that depends on
//! v alone. Meshing evaluates a grid: with the parts, n × m points cost n + m curve evaluations
//! (and sines) instead of n·m. `Surface::eval` is defined by these same parts, so a point put
//! together from cached parts is the point `eval` gives, bit for bit.

use super::kinds::Surface;
use super::sweep::Frame;
use glam::{DQuat, DVec3};
use std::f64::consts::TAU;

/// What the point takes from u.
#[derive(Clone, Copy, Debug)]
pub(crate) enum UPart {
    /// Both rails at u.
    Ruled(DVec3, DVec3),
    /// The profile point relative to the axis point.
    Revolve(DVec3),
    /// The profile point in the first frame's coordinates.
    Sweep(DVec3),
    /// The bottom and top curves at u, and u.
    Coons(DVec3, DVec3, f64),
    /// The radial offset.
    Cylinder(DVec3),
    /// Kinds whose parameters do not separate: u itself.
    Whole(f64),
}

/// What the point takes from v.
#[derive(Clone, Copy, Debug)]
pub(crate) enum VPart {
    Ruled(f64),
    /// The rotation by v·angle.
    Revolve(DQuat),
    /// The guide point and the frame at v.
    Sweep(DVec3, Frame),
    /// The left and right curves at v, and v.
    Coons(DVec3, DVec3, f64),
    /// The offset along the axis.
    Cylinder(DVec3),
    Whole(f64),
}

impl Surface {
    pub(crate) fn u_part(&self, u: f64) -> UPart {
        match self {
            Surface::Ruled(r) => UPart::Ruled(r.c1.eval(u), r.c2.eval(u)),
            Surface::Revolve(r) => UPart::Revolve(r.profile.eval(u) - r.axis_point),
            Surface::Sweep(s) => {
                let f0 = &s.frames()[0];
                let d = s.profile.eval(u) - s.guide.eval(0.0);
                UPart::Sweep(DVec3::new(d.dot(f0.t), d.dot(f0.r), d.dot(f0.s)))
            }
            // Bottom c0(u); top c2 runs backwards in u.
            Surface::Coons(c) => UPart::Coons(c.edge(0, u), c.edge(2, 1.0 - u), u),
            Surface::Cylinder(c) => {
                let (x, y) = c.frame();
                let a = TAU * u;
                UPart::Cylinder(c.radius * (a.cos() * x + a.sin() * y))
            }
            Surface::Plane(_) | Surface::Sphere(_) => UPart::Whole(u),
        }
    }

    pub(crate) fn v_part(&self, v: f64) -> VPart {
        match self {
            Surface::Ruled(_) => VPart::Ruled(v),
            Surface::Revolve(r) => VPart::Revolve(DQuat::from_axis_angle(r.axis_dir, v * r.angle)),
            Surface::Sweep(s) => {
                VPart::Sweep(s.guide.eval(v), super::sweep::frame_at(s.frames(), v))
            }
            // Right c1(v); left c3 runs backwards in v.
            Surface::Coons(c) => VPart::Coons(c.edge(3, 1.0 - v), c.edge(1, v), v),
            Surface::Cylinder(c) => VPart::Cylinder(c.axis * (v * c.height)),
            Surface::Plane(_) | Surface::Sphere(_) => VPart::Whole(v),
        }
    }

    /// The point from the parts of this surface at u and at v.
    pub(crate) fn combine(&self, a: &UPart, b: &VPart) -> DVec3 {
        match (self, *a, *b) {
            (_, UPart::Ruled(p, q), VPart::Ruled(v)) => p.lerp(q, v),
            (Surface::Revolve(r), UPart::Revolve(p), VPart::Revolve(q)) => r.axis_point + q * p,
            (_, UPart::Sweep(local), VPart::Sweep(g, f)) => {
                g + f.t * local.x + f.r * local.y + f.s * local.z
            }
            (Surface::Coons(c), UPart::Coons(bottom, top, u), VPart::Coons(left, right, v)) => {
                let [p00, p10, p11, p01] = c.corners();
                (1.0 - v) * bottom + v * top + (1.0 - u) * left + u * right
                    - ((1.0 - u) * (1.0 - v) * p00
                        + u * (1.0 - v) * p10
                        + (1.0 - u) * v * p01
                        + u * v * p11)
            }
            (Surface::Cylinder(c), UPart::Cylinder(radial), VPart::Cylinder(along)) => {
                c.base + radial + along
            }
            (_, UPart::Whole(u), VPart::Whole(v)) => self.eval_whole(u, v),
            // Parts of another kind of surface: a caller's mistake, answered without them.
            _ => {
                debug_assert!(false, "parts of another kind of surface");
                DVec3::NAN
            }
        }
    }
}
