//! DXF's arbitrary-axis algorithm: the object coordinate system (OCS) of a plane normal.
//!
//! Arcs and circles measure their angles from the X axis of this frame, as DXF does, so an
//! arc made by `(arc ...)` and the ARC entity written to DXF agree without conversion.

use glam::DVec3;

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
