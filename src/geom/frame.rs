//! DXF's arbitrary-axis algorithm: the object coordinate system (OCS) of a plane normal.
//!
//! Arcs and circles measure their angles from the X axis of this frame, as DXF does, so an
//! arc made by `(arc ...)` and the ARC entity written to DXF agree without conversion.

use glam::{DVec2, DVec3};

/// The OCS X and Y axes for the (unit or not) extrusion `normal`, per the DXF reference's
/// "Arbitrary Axis Algorithm": if the normal is close to the world Z axis (|Nx| and |Ny| both
/// below 1/64) then Ax = Wy × N, else Ax = Wz × N; Ay = N × Ax.
pub fn arbitrary_axis(normal: DVec3) -> (DVec3, DVec3) {
    let n = normal.normalize();
    let ax = if n.x.abs() < 1.0 / 64.0 && n.y.abs() < 1.0 / 64.0 {
        DVec3::Y.cross(n)
    } else {
        DVec3::Z.cross(n)
    }
    .normalize();
    let ay = n.cross(ax).normalize();
    (ax, ay)
}

/// The OCS of one plane normal, for the two mappings every writer needs: OCS points at an
/// elevation, and points at an OCS angle on a circle in the plane.
#[derive(Clone, Copy, Debug)]
pub struct Ocs {
    pub x: DVec3,
    pub y: DVec3,
    /// The unit normal.
    pub n: DVec3,
}

impl Ocs {
    pub fn new(normal: DVec3) -> Ocs {
        let (x, y) = arbitrary_axis(normal);
        Ocs {
            x,
            y,
            n: normal.normalize(),
        }
    }

    /// The WCS point of the OCS point `p` at `elevation` along the normal.
    pub fn to_wcs(&self, p: DVec2, elevation: f64) -> DVec3 {
        self.x * p.x + self.y * p.y + self.n * elevation
    }

    /// The OCS coordinates of the WCS point `p`: (x, y, elevation).
    pub fn wcs_to_ocs(&self, p: DVec3) -> DVec3 {
        DVec3::new(p.dot(self.x), p.dot(self.y), p.dot(self.n))
    }

    /// The point at OCS angle `t` on the circle (`center`, `radius`) in this plane.
    pub fn on_circle(&self, center: DVec3, radius: f64, t: f64) -> DVec3 {
        center + (self.x * t.cos() + self.y * t.sin()) * radius
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn world_z_gives_world_axes() {
        let (x, y) = arbitrary_axis(DVec3::Z);
        assert!((x - DVec3::X).length() < 1e-15);
        assert!((y - DVec3::Y).length() < 1e-15);
    }

    #[test]
    fn negative_z_flips_x() {
        // The classic mirrored-arc case: extrusion (0 0 -1) has OCS X = -WX.
        let (x, y) = arbitrary_axis(-DVec3::Z);
        assert!((x + DVec3::X).length() < 1e-15);
        assert!((y - DVec3::Y).length() < 1e-15);
    }
}
