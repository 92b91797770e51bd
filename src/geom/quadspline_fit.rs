//! Interpolation for [`QuadSpline`]: the C1 quadratic spline ("二次样条") through every
//! type-value point, open or closed.
//!
//! Method: quadratic B-spline interpolation with chord-length data parameters t_j and knots at
//! the midpoints between consecutive data parameters (the averaging technique of Piegl & Tiller,
//! The NURBS Book §9.2.1, for p = 2; periodic when closed). Each data parameter then lies inside
//! its own span, the collocation matrix is tridiagonal (cyclic when closed) and totally
//! nonnegative, so it is solved without pivoting (de Boor, A Practical Guide to Splines, ch. XIII).
//! Each span is then split (de Casteljau) at its data parameter so that every type-value point is
//! a segment end, and the result is laid out with exactly two Bézier segments between consecutive
//! type-value points: point j sits at public parameter j/(n−1) (open) or j/n (closed).

use glam::DVec3;

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

/// Split the quadratic Bézier [a, b, c] at u (de Casteljau): (left, right).
fn split(s: [DVec3; 3], u: f64) -> ([DVec3; 3], [DVec3; 3]) {
    let ab = s[0].lerp(s[1], u);
    let bc = s[1].lerp(s[2], u);
    let m = ab.lerp(bc, u);
    ([s[0], ab, m], [m, bc, s[2]])
}

/// Thomas algorithm for a tridiagonal system: sub a[i] (row i, column i−1), diagonal b, super c.
/// Stable without pivoting for the totally nonnegative collocation matrices used here.
fn solve_tridiagonal(a: &[f64], b: &[f64], c: &[f64], r: &[DVec3]) -> Vec<DVec3> {
    let n = b.len();
    let mut cp = vec![0.0; n];
    let mut x = vec![DVec3::ZERO; n];
    let mut denom = b[0];
    cp[0] = c[0] / denom;
    x[0] = r[0] / denom;
    for i in 1..n {
        denom = b[i] - a[i] * cp[i - 1];
        cp[i] = c[i] / denom;
        x[i] = (r[i] - x[i - 1] * a[i]) / denom;
    }
    for i in (0..n - 1).rev() {
        x[i] = x[i] - x[i + 1] * cp[i];
    }
    x
}

/// Cyclic tridiagonal solve (Sherman–Morrison, Numerical Recipes §2.7 `cyclic`, γ = −b₀):
/// a[0] is row 0's coefficient of x[n−1], c[n−1] row n−1's coefficient of x[0].
fn solve_cyclic(a: &[f64], b: &[f64], c: &[f64], r: &[DVec3]) -> Vec<DVec3> {
    let n = b.len();
    // NR's names: β the top-right corner (row 0, column n−1), α the bottom-left.
    let beta = a[0];
    let alpha = c[n - 1];
    let gamma = -b[0];
    let mut bb = b.to_vec();
    bb[0] = b[0] - gamma;
    bb[n - 1] = b[n - 1] - alpha * beta / gamma;
    let mut aa = a.to_vec();
    aa[0] = 0.0;
    let mut cc = c.to_vec();
    cc[n - 1] = 0.0;
    let x = solve_tridiagonal(&aa, &bb, &cc, r);
    // The correction vector u = (γ, 0, …, 0, α) is scalar; solve it once per component alike.
    let mut u = vec![DVec3::ZERO; n];
    u[0] = DVec3::splat(gamma);
    u[n - 1] = DVec3::splat(alpha);
    let z = solve_tridiagonal(&aa, &bb, &cc, &u);
    let z0 = z[0].x;
    let zn = z[n - 1].x;
    let fact = (x[0] + x[n - 1] * (beta / gamma)) / (1.0 + z0 + beta * zn / gamma);
    x.iter().zip(&z).map(|(xi, zi)| *xi - fact * zi.x).collect()
}

/// The collocation system of one interpolation problem, kept so a residual can be re-solved
/// (one step of iterative refinement when the first solve is not accurate enough).
struct System {
    a: Vec<f64>,
    b: Vec<f64>,
    c: Vec<f64>,
    cyclic: bool,
}

impl System {
    fn solve(&self, r: &[DVec3]) -> Vec<DVec3> {
        if self.cyclic {
            solve_cyclic(&self.a, &self.b, &self.c, r)
        } else {
            solve_tridiagonal(&self.a, &self.b, &self.c, r)
        }
    }

    /// A·x for the unknowns alone (fixed end points excluded).
    fn apply(&self, x: &[DVec3]) -> Vec<DVec3> {
        let n = x.len();
        (0..n)
            .map(|i| {
                let mut v = x[i] * self.b[i];
                if i > 0 {
                    v += x[i - 1] * self.a[i];
                } else if self.cyclic {
                    v += x[n - 1] * self.a[0];
                }
                if i + 1 < n {
                    v += x[i + 1] * self.c[i];
                } else if self.cyclic {
                    v += x[0] * self.c[n - 1];
                }
                v
            })
            .collect()
    }

    /// Solve, then refine once if the residual is above a few ulps of the data scale.
    fn solve_refined(&self, r: &[DVec3], scale: f64) -> Vec<DVec3> {
        let mut x = self.solve(r);
        let res: Vec<DVec3> = self
            .apply(&x)
            .iter()
            .zip(r)
            .map(|(ax, ri)| *ri - *ax)
            .collect();
        let worst = res.iter().map(|v| v.length()).fold(0.0, f64::max);
        if worst > 1e-14 * scale {
            let dx = self.solve(&res);
            for (xi, d) in x.iter_mut().zip(dx) {
                *xi += d;
            }
        }
        x
    }
}

impl QuadSpline {
    /// The C1 quadratic interpolating spline through `points` (see the module doc for the
    /// method). Open: at least 2 points (2 points give a straight segment). Closed: at least 3;
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
        let segments = if closed {
            closed_segments(&pts, &h, scale)
        } else if n == 2 {
            let m = pts[0].lerp(pts[1], 0.5);
            vec![
                [pts[0], pts[0].lerp(pts[1], 0.25), m],
                [m, pts[0].lerp(pts[1], 0.75), pts[1]],
            ]
        } else {
            open_segments(&pts, &h, scale)
        };
        Ok(QuadSpline {
            points: pts,
            closed,
            segments,
        })
    }
}

/// Coefficients of the row for the data point inside a span of length `d` at local parameter
/// `u`, given the neighbouring spans' lengths (None for a clamped end, whose joint is fixed).
/// Returns (coef of P_prev, coef of P_this, coef of P_next).
fn row(u: f64, d: f64, d_prev: Option<f64>, d_next: Option<f64>) -> (f64, f64, f64) {
    let w0 = (1.0 - u) * (1.0 - u);
    let w2 = u * u;
    let mut diag = 2.0 * u * (1.0 - u);
    let mut a = 0.0;
    let mut c = 0.0;
    if let Some(dp) = d_prev {
        a = w0 * d / (dp + d);
        diag += w0 * dp / (dp + d);
    }
    if let Some(dn) = d_next {
        c = w2 * d / (d + dn);
        diag += w2 * dn / (d + dn);
    }
    (a, diag, c)
}

/// The C1 joint at the knot between a span of length `d0` (control p0) and the next of length
/// `d1` (control p1).
fn joint(p0: DVec3, p1: DVec3, d0: f64, d1: f64) -> DVec3 {
    (p0 * d1 + p1 * d0) / (d0 + d1)
}

fn closed_segments(q: &[DVec3], h: &[f64], scale: f64) -> Vec<[DVec3; 3]> {
    let n = q.len();
    let prev = |j: usize| (j + n - 1) % n;
    // Span j = [m_{j-1}, m_j] holds t_j; its length and the local parameter of t_j in it.
    let d: Vec<f64> = (0..n).map(|j| 0.5 * (h[prev(j)] + h[j])).collect();
    let u: Vec<f64> = (0..n).map(|j| h[prev(j)] / (h[prev(j)] + h[j])).collect();
    let mut sys = System {
        a: vec![0.0; n],
        b: vec![0.0; n],
        c: vec![0.0; n],
        cyclic: true,
    };
    for j in 0..n {
        let (a, b, c) = row(u[j], d[j], Some(d[prev(j)]), Some(d[(j + 1) % n]));
        sys.a[j] = a;
        sys.b[j] = b;
        sys.c[j] = c;
    }
    let p = sys.solve_refined(q, scale);
    // J_j: the joint between span j and span j+1.
    let jn: Vec<DVec3> = (0..n)
        .map(|j| joint(p[j], p[(j + 1) % n], d[j], d[(j + 1) % n]))
        .collect();
    let halves: Vec<([DVec3; 3], [DVec3; 3])> = (0..n)
        .map(|j| {
            let (mut l, mut r) = split([jn[prev(j)], p[j], jn[j]], u[j]);
            l[2] = q[j];
            r[0] = q[j];
            (l, r)
        })
        .collect();
    let mut segs = Vec::with_capacity(2 * n);
    for j in 0..n {
        segs.push(halves[j].1);
        segs.push(halves[(j + 1) % n].0);
    }
    segs
}

fn open_segments(q: &[DVec3], h: &[f64], scale: f64) -> Vec<[DVec3; 3]> {
    let n = q.len();
    // Data parameters (chord length) and span boundaries: m_0 = t_0, m_j = (t_j + t_{j+1})/2
    // for 1 ≤ j ≤ n−3, m_{n−2} = t_{n−1}. Span j (1 ≤ j ≤ n−2) holds t_j and has control P_j.
    let mut t = vec![0.0; n];
    for j in 0..n - 1 {
        t[j + 1] = t[j] + h[j];
    }
    let mut m = vec![0.0; n - 1];
    m[0] = t[0];
    for j in 1..n - 2 {
        m[j] = 0.5 * (t[j] + t[j + 1]);
    }
    m[n - 2] = t[n - 1];
    let k = n - 2; // unknowns P_1..P_{n-2}, stored at index j-1
    let d: Vec<f64> = (1..=k).map(|j| m[j] - m[j - 1]).collect();
    let u: Vec<f64> = (1..=k).map(|j| (t[j] - m[j - 1]) / d[j - 1]).collect();
    let mut sys = System {
        a: vec![0.0; k],
        b: vec![0.0; k],
        c: vec![0.0; k],
        cyclic: false,
    };
    let mut rhs: Vec<DVec3> = q[1..=k].to_vec();
    for i in 0..k {
        let dp = (i > 0).then(|| d[i - 1]);
        let dn = (i + 1 < k).then(|| d[i + 1]);
        let (a, b, c) = row(u[i], d[i], dp, dn);
        sys.a[i] = a;
        sys.b[i] = b;
        sys.c[i] = c;
        // The clamped ends' joints are the fixed end points themselves.
        if i == 0 {
            rhs[i] -= q[0] * ((1.0 - u[i]) * (1.0 - u[i]));
        }
        if i + 1 == k {
            rhs[i] -= q[n - 1] * (u[i] * u[i]);
        }
    }
    let p = sys.solve_refined(&rhs, scale);
    // Joints: jn[0] = Q_0, jn[i] between span i and i+1 (1-based spans), jn[k] = Q_{n-1}.
    let mut jn = vec![q[0]; k + 1];
    for i in 1..k {
        jn[i] = joint(p[i - 1], p[i], d[i - 1], d[i]);
    }
    jn[k] = q[n - 1];
    let mut segs = Vec::with_capacity(2 * (n - 1));
    for i in 0..k {
        let (mut l, mut r) = split([jn[i], p[i], jn[i + 1]], u[i]);
        l[2] = q[i + 1];
        r[0] = q[i + 1];
        if i == 0 {
            // The first interval [Q_0, Q_1] is a single piece: halve it so every interval has two.
            let (a, b) = split(l, 0.5);
            segs.push(a);
            segs.push(b);
        } else {
            segs.push(l);
        }
        if i + 1 == k {
            let (a, b) = split(r, 0.5);
            segs.push(a);
            segs.push(b);
        } else {
            segs.push(r);
        }
    }
    segs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cyclic_solver_matches_dense() {
        let a = [0.2, 0.1, 0.3, 0.25];
        let b = [0.6, 0.7, 0.5, 0.6];
        let c = [0.2, 0.2, 0.2, 0.15];
        let x_true = [
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(-1.0, 0.5, 0.0),
            DVec3::new(4.0, -2.0, 1.0),
            DVec3::new(0.0, 1.0, -1.0),
        ];
        let sys = System {
            a: a.to_vec(),
            b: b.to_vec(),
            c: c.to_vec(),
            cyclic: true,
        };
        let r = sys.apply(&x_true);
        let x = sys.solve(&r);
        for (p, q) in x.iter().zip(&x_true) {
            assert!((*p - *q).length() < 1e-13, "{p} vs {q}");
        }
    }
}
