//! Interpolation for [`QuadSpline`]: the C1 quadratic spline ("二次样条") through every
//! type-value point, open or closed, that does not overshoot.
//!
//! Method: a local, shape-preserving quadratic Hermite spline. The parameter is chord length
//! (interval j has length h_j = |Q_{j+1} − Q_j|). The tangent at each point is chosen per
//! coordinate of the points' principal axes (PCA frame, so the curve turns with the points:
//! rotating the points rotates the spline): Bessel's three-point slope, set to zero where that
//! coordinate has a local extremum at the point and clamped to twice the smaller neighbouring
//! chord slope (the monotonicity filter of Hyman 1983 / Fritsch & Carlson 1980, with the bound
//! the quadratic pair needs). Each interval is then two
//! quadratic Bézier pieces [Q_j, Q_j + m_j·h_j/4, M], [M, Q_{j+1} − m_{j+1}·h_j/4, Q_{j+1}] with
//! the joint M midway between the two inner controls (C1 there), and C1 at every type-value
//! point in the chord-length parameter. With |m| ≤ 2·min(slopes) every control of an interval
//! lies, coordinate by coordinate, between the interval's two type-value points, so the curve
//! stays in the box of its two points (in the principal frame): no overshoot, however uneven
//! the spacing. Why not a global chord-length or centripetal spline: both still overshoot next to
//! a short chord between long ones (the README's temple tip bulged to ±13 between points at ±6
//! with chord length); the local rule cannot. A point where every coordinate has an extremum (a
//! right-angle turn between a chord along one axis and one along another, as at a temple's
//! hinge corners) gets a zero tangent: a corner, which is what such points describe. The layout
//! is two segments per interval: point j sits at public parameter j/(n−1) (open) or j/n
//! (closed).

use glam::{DMat3, DVec3};

use super::quadspline::QuadSpline;

/// Why a set of type-value points was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum QuadSplineError {
    #[error("a {} spline needs at least {need} points, got {got}", if *.closed { "closed" } else { "open" })]
    TooFewPoints {
        need: usize,
        got: usize,
        closed: bool,
    },
    #[error("point {index} is not finite: ({}, {}, {})", .point.x, .point.y, .point.z)]
    NonFinite { index: usize, point: DVec3 },
    #[error(
        "points {index} and {next} coincide (distance {distance:e}); consecutive type-value points must be distinct"
    )]
    Coincident {
        index: usize,
        next: usize,
        distance: f64,
    },
}

impl QuadSpline {
    /// The C1 quadratic interpolating spline through `points`, shape-preserving (see the module
    /// doc for the method). Open: at least 2 points (2 points give a straight segment). Closed: at least 3;
    /// periodic, C1 at the seam; a last point equal to the first is taken as the closing point
    /// and dropped. Errors name the offending point index.
    pub fn interpolate(points: &[DVec3], closed: bool) -> Result<QuadSpline, QuadSplineError> {
        for (index, p) in points.iter().enumerate() {
            if !p.is_finite() {
                return Err(QuadSplineError::NonFinite { index, point: *p });
            }
        }
        let scale = points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs().max_element()))
            .max(1.0);
        // Distances at or below this are coincident points: they would give a zero-length
        // parameter interval and a singular system.
        let coincident = 64.0 * f64::EPSILON * scale;
        let mut pts: Vec<DVec3> = points.to_vec();
        if closed && pts.len() > 3 && pts[0].distance(pts[pts.len() - 1]) <= coincident {
            pts.pop();
        }
        let n = pts.len();
        let need = if closed { 3 } else { 2 };
        if n < need {
            return Err(QuadSplineError::TooFewPoints {
                need,
                got: points.len(),
                closed,
            });
        }
        let intervals = if closed { n } else { n - 1 };
        let h: Vec<f64> = (0..intervals)
            .map(|j| pts[j].distance(pts[(j + 1) % n]))
            .collect();
        if let Some(j) = h.iter().position(|&d| d <= coincident) {
            return Err(QuadSplineError::Coincident {
                index: j,
                next: (j + 1) % n,
                distance: h[j],
            });
        }
        let tangents = shape_preserving_tangents(&pts, &h, closed);
        let segments = hermite_segments(&pts, &h, &tangents, closed);
        Ok(QuadSpline {
            points: pts,
            closed,
            segments,
        })
    }
}

/// The principal axes of the points (columns of the result), an orthonormal frame; the identity
/// when the spread is isotropic enough that no axis is preferred (then world axes are as good).
fn principal_axes(pts: &[DVec3]) -> DMat3 {
    let n = pts.len() as f64;
    let c = pts.iter().copied().sum::<DVec3>() / n;
    let mut a = [[0.0f64; 3]; 3];
    for p in pts {
        let d = (*p - c).to_array();
        for (i, row) in a.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v += d[i] * d[j];
            }
        }
    }
    let (vals, vecs) = jacobi_eigen(a);
    // Sort by decreasing spread; ties (within 1e-9 relative) keep world order for determinism.
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&i, &j| vals[j].total_cmp(&vals[i]).then(i.cmp(&j)));
    let top = vals[idx[0]].abs().max(1e-300);
    if (vals[idx[0]] - vals[idx[1]]).abs() <= 1e-9 * top {
        return DMat3::IDENTITY;
    }
    let col = |k: usize| DVec3::new(vecs[0][k], vecs[1][k], vecs[2][k]);
    let (mut e0, e1) = (col(idx[0]), col(idx[1]));
    // A deterministic sign: the axis points the way the points run (first to last).
    if (pts[pts.len() - 1] - pts[0]).dot(e0) < 0.0 {
        e0 = -e0;
    }
    let e2 = e0.cross(e1);
    DMat3::from_cols(e0, e2.cross(e0), e2)
}

/// Eigen-decomposition of a symmetric 3×3 matrix by cyclic Jacobi rotations: (eigenvalues,
/// eigenvectors as columns).
fn jacobi_eigen(mut a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let diag = a[0][0].abs() + a[1][1].abs() + a[2][2].abs();
        if off <= 1e-300 || off <= 1e-15 * diag {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q].abs() <= 1e-300 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for row in a.iter_mut() {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (rp, rq) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * rp[k] - s * rq[k];
                a[q][k] = s * rp[k] + c * rq[k];
            }
            for row in v.iter_mut() {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

/// One coordinate's tangent at a point between chord slopes `a` (before, chord length `ha`) and
/// `b` (after, `hb`): Bessel's estimate (the slope at the point of the parabola through the three
/// points), zero where the coordinate turns back or flattens, and clamped to twice the smaller
/// slope so neither neighbouring interval can overshoot (the Hyman filter with the quadratic
/// pair's bound 2 in place of the cubic's 3).
fn limited_slope(a: f64, b: f64, ha: f64, hb: f64) -> f64 {
    if a * b <= 0.0 {
        return 0.0;
    }
    let bessel = (hb * a + ha * b) / (ha + hb);
    // Just under the bound: at exactly 2·min on both ends of an interval the two inner
    // controls would meet and the joint between them would have no tangent.
    let cap = 2.0 * (1.0 - 1e-6) * a.abs().min(b.abs());
    bessel.clamp(-cap, cap)
}

/// The tangent (derivative in the chord-length parameter) at every point, computed in the
/// points' principal frame and returned in world coordinates.
pub(crate) fn shape_preserving_tangents(pts: &[DVec3], h: &[f64], closed: bool) -> Vec<DVec3> {
    let n = pts.len();
    let frame = principal_axes(pts);
    let inv = frame.transpose();
    let slope = |j: usize| inv * ((pts[(j + 1) % n] - pts[j]) / h[j]);
    let intervals = h.len();
    (0..n)
        .map(|j| {
            let limited = |i: usize, k: usize| {
                let (a, b) = (slope(i), slope(k));
                let (ha, hb) = (h[i], h[k]);
                DVec3::new(
                    limited_slope(a.x, b.x, ha, hb),
                    limited_slope(a.y, b.y, ha, hb),
                    limited_slope(a.z, b.z, ha, hb),
                )
            };
            let local = if closed {
                limited((j + n - 1) % n, j)
            } else if j == 0 {
                slope(0)
            } else if j == intervals {
                slope(intervals - 1)
            } else {
                limited(j - 1, j)
            };
            frame * local
        })
        .collect()
}

/// Two quadratic pieces per interval from the points and their chord-length tangents (see the
/// module doc): C1 at the joints and, in the chord-length parameter, at the points.
pub(crate) fn hermite_segments(
    pts: &[DVec3],
    h: &[f64],
    tangents: &[DVec3],
    closed: bool,
) -> Vec<[DVec3; 3]> {
    let n = pts.len();
    let intervals = if closed { n } else { n - 1 };
    // A tangent so small that a leg is lost in rounding on one side would leave a leg without
    // a reliable direction: it is a corner, both legs zero.
    let leg_vanishes = |j: usize, h: f64| {
        let leg = (tangents[j] * (0.25 * h)).length();
        h > 0.0 && leg <= 1e-9 * h.max(pts[j].abs().max_element())
    };
    let tangents: Vec<DVec3> = (0..n)
        .map(|j| {
            let before = if j > 0 || closed {
                h[(j + n - 1) % n]
            } else {
                0.0
            };
            let after = if j < intervals { h[j] } else { 0.0 };
            if leg_vanishes(j, before) || leg_vanishes(j, after) {
                DVec3::ZERO
            } else {
                tangents[j]
            }
        })
        .collect();
    let mut segs = Vec::with_capacity(2 * intervals);
    for j in 0..intervals {
        let k = (j + 1) % n;
        let c0 = pts[j] + tangents[j] * (0.25 * h[j]);
        let c1 = pts[k] - tangents[k] * (0.25 * h[j]);
        let m = c0.lerp(c1, 0.5);
        segs.push([pts[j], c0, m]);
        segs.push([m, c1, pts[k]]);
    }
    segs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_of_diagonal_and_rotated() {
        let (vals, _) = jacobi_eigen([[3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 2.0]]);
        assert_eq!(vals, [3.0, 1.0, 2.0]);
        // [[2,1,0],[1,2,0],[0,0,0]]: eigenvalues 3, 1, 0.
        let (mut vals, _) = jacobi_eigen([[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 0.0]]);
        vals.sort_by(f64::total_cmp);
        for (v, w) in vals.iter().zip([0.0, 1.0, 3.0]) {
            assert!((v - w).abs() < 1e-12, "{vals:?}");
        }
    }

    #[test]
    fn slope_is_bounded_by_twice_the_smaller() {
        for (a, b) in [(1.0, 10.0), (0.1, 0.2), (-3.0, -0.5), (5.0, 5.0)] {
            let m = limited_slope(a, b, 1.0, 3.0);
            let lim = 2.0 * f64::min(a.abs(), b.abs());
            assert!(m.abs() <= lim + 1e-15 && m * a >= 0.0, "{a} {b} {m}");
        }
        assert_eq!(limited_slope(1.0, -1.0, 1.0, 1.0), 0.0);
        assert_eq!(limited_slope(0.0, 2.0, 1.0, 1.0), 0.0);
        assert_eq!(limited_slope(1.0, 2.0, 1.0, 1.0), 1.5);
    }
}
