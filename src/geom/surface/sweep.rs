//! Rotation-minimising frames along a guide curve by the double reflection method
//! (W. Wang, B. Jüttler, D. Zheng, Y. Liu, "Computation of rotation minimizing frames",
//! ACM TOG 27(1), 2008, Algorithm "double reflection").

use super::error::SurfaceError;
use crate::geom::frame::arbitrary_axis;
use crate::geom::ParamCurve;
use glam::DVec3;

/// An orthonormal frame: tangent `t`, reference `r`, `s = t × r`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub t: DVec3,
    pub r: DVec3,
    pub s: DVec3,
}

fn tangent(c: &dyn ParamCurve, u: f64, h: f64) -> DVec3 {
    let a = (u - h).max(0.0);
    let b = (u + h).min(1.0);
    (c.eval(b) - c.eval(a)).normalize_or_zero()
}

/// Frames at `n + 1` equally spaced parameters along `guide`. The first reference vector is the
/// DXF arbitrary-axis X of the start tangent. Each step reflects the previous frame in the
/// bisector plane of the chord x_{i+1} − x_i, then in the plane that takes the reflected tangent
/// to the true tangent: `r_{i+1} = R2 R1 r_i`.
pub fn rotation_minimizing_frames(
    guide: &dyn ParamCurve,
    n: usize,
) -> Result<Vec<Frame>, SurfaceError> {
    let n = n.max(1);
    let h = 0.25 / n as f64;
    let xs: Vec<DVec3> = (0..=n).map(|i| guide.eval(i as f64 / n as f64)).collect();
    let ts: Vec<DVec3> = (0..=n)
        .map(|i| tangent(guide, i as f64 / n as f64, h))
        .collect();
    if xs.iter().any(|p| !p.is_finite()) || ts[0] == DVec3::ZERO {
        return Err(SurfaceError::Invalid(
            "guide curve must be finite and have a non-zero tangent at its start".into(),
        ));
    }
    let (r0, _) = arbitrary_axis(ts[0]);
    let mut frames = Vec::with_capacity(n + 1);
    frames.push(Frame {
        t: ts[0],
        r: r0,
        s: ts[0].cross(r0),
    });
    for i in 0..n {
        let prev = frames[i];
        let v1 = xs[i + 1] - xs[i];
        let c1 = v1.dot(v1);
        let t_next = if ts[i + 1] == DVec3::ZERO {
            prev.t
        } else {
            ts[i + 1]
        };
        if c1 == 0.0 {
            frames.push(Frame {
                t: t_next,
                r: prev.r,
                s: t_next.cross(prev.r),
            });
            continue;
        }
        let r_l = prev.r - (2.0 / c1) * v1.dot(prev.r) * v1;
        let t_l = prev.t - (2.0 / c1) * v1.dot(prev.t) * v1;
        let v2 = t_next - t_l;
        let c2 = v2.dot(v2);
        let r = if c2 == 0.0 {
            r_l
        } else {
            r_l - (2.0 / c2) * v2.dot(r_l) * v2
        };
        // Re-orthogonalise against rounding drift.
        let r = (r - t_next * r.dot(t_next)).normalize_or(prev.r);
        frames.push(Frame {
            t: t_next,
            r,
            s: t_next.cross(r),
        });
    }
    Ok(frames)
}

/// The frame at parameter `v` in [0, 1], interpolated between the computed ones.
pub(crate) fn frame_at(frames: &[Frame], v: f64) -> Frame {
    let n = frames.len() - 1;
    if n == 0 {
        return frames[0];
    }
    let x = v.clamp(0.0, 1.0) * n as f64;
    let i = (x.floor() as usize).min(n - 1);
    let f = x - i as f64;
    let (a, b) = (frames[i], frames[i + 1]);
    let t = a.t.lerp(b.t, f).normalize_or(a.t);
    let r = a.r.lerp(b.r, f);
    let r = (r - t * r.dot(t)).normalize_or(a.r);
    Frame {
        t,
        r,
        s: t.cross(r),
    }
}
