//! Refitting a bent temple outline within a tolerance of the exact bend.
//!
//! Paper 004 bends the type-value points and refits the quadratic spline through them
//! ("transform first, then generate"). The refit only approximates the exact image of the
//! original outline under the bend — the bend curves the outline between type-value points and
//! even puts a slight corner in it where the outline crosses s = L or s = L + Rθ off the
//! centerline (the map is C1 only along the centerline). So, after each refit, the exact bent
//! outline is sampled densely between consecutive type-value points and each sample's distance
//! to the refit (exact nearest point on the nearby segments) is measured; every interval whose
//! error exceeds the tolerance gets a new type-value point: the bent image of the original
//! outline at the interval's middle parameter (bisection, so the spacing halves where the
//! error lives — in and next to the bend). Repeated until within tolerance or a cap is hit; the
//! achieved deviation is returned either way.

use glam::DVec3;

use super::quadspline::QuadSpline;
use super::temple::{bend_one, Bend, TempleError, TempleParams};
use super::traits::ParamCurve;

/// Samples of the exact bent outline measured inside each interval between type-value points.
const SAMPLES_PER_INTERVAL: usize = 16;
/// Refinement rounds before giving up (each round can halve every bad interval).
const MAX_ROUNDS: usize = 48;
/// Added type-value points before giving up.
const MAX_ADDED: usize = 4000;
/// Intervals shorter than this (in the original's public parameter) are not split further.
const MIN_INTERVAL: f64 = 1e-12;

/// A bent outline: the refitted spline, its measured deviation from the exact bend of the
/// original outline, and how many type-value points were added to reach it.
#[derive(Clone, Debug, PartialEq)]
pub struct BentSpline {
    pub spline: QuadSpline,
    /// Largest distance found from the exact bent outline (sampled densely) to `spline`.
    pub deviation: f64,
    pub added_points: usize,
    /// Refit rounds performed (1 when the first refit was already within tolerance).
    pub rounds: usize,
}

/// Bend a quadratic-spline outline: bend its type-value points, refit with
/// [`QuadSpline::interpolate`], and add bent type-value points where the refit is farther than
/// `tol` from the exact bend of `s` (see the module doc). The result passes through the bent
/// image of every original type-value point. If the caps (48 rounds, 4000 added points) are hit
/// first, the result is returned with the deviation it achieved, which is then above `tol`.
pub fn bend_spline(
    s: &QuadSpline,
    params: &TempleParams,
    tol: f64,
) -> Result<BentSpline, TempleError> {
    if !(tol > 0.0 && tol.is_finite()) {
        return Err(TempleError::Tolerance { tol });
    }
    let bend = Bend::new(params)?;
    let closed = s.closed;
    let n0 = s.points.len();
    let intervals = if closed { n0 } else { n0.saturating_sub(1) };
    // Public parameter of each original type-value point on `s` (exact for interpolated
    // splines, whose layout is two segments per interval).
    let mut ts: Vec<f64> = if s.segments.len() == 2 * intervals {
        (0..n0).map(|j| s.point_param(j)).collect()
    } else {
        s.points.iter().map(|p| s.closest_point(*p).t).collect()
    };
    let mut bent = s
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| bend_one(&bend, *p, i))
        .collect::<Result<Vec<_>, _>>()?;
    let mut added = 0;
    let mut round = 0;
    loop {
        round += 1;
        let fit = QuadSpline::interpolate(&bent, closed)?;
        let errs = interval_errors(s, &fit, &ts, &bend)?;
        let deviation = errs.iter().copied().fold(0.0, f64::max);
        if deviation <= tol || round >= MAX_ROUNDS || added >= MAX_ADDED {
            return Ok(BentSpline {
                spline: fit,
                deviation,
                added_points: added,
                rounds: round,
            });
        }
        let n = ts.len();
        let mut new_ts = Vec::with_capacity(n + errs.len());
        let mut new_bent = Vec::with_capacity(n + errs.len());
        for i in 0..n {
            new_ts.push(ts[i]);
            new_bent.push(bent[i]);
            if i < errs.len() && errs[i] > tol && added < MAX_ADDED {
                let (ta, tb) = interval_span(&ts, i);
                if tb - ta > MIN_INTERVAL {
                    let tm = 0.5 * (ta + tb);
                    new_ts.push(tm);
                    new_bent.push(bend_sample(&bend, s.eval(tm), tm)?);
                    added += 1;
                }
            }
        }
        if new_ts.len() == n {
            // Nothing could be split further: report what we have.
            return Ok(BentSpline {
                spline: fit,
                deviation,
                added_points: added,
                rounds: round,
            });
        }
        ts = new_ts;
        bent = new_bent;
    }
}

/// The parameter range of interval i (from point i to the next; the closing interval of a
/// closed outline ends at t = 1).
fn interval_span(ts: &[f64], i: usize) -> (f64, f64) {
    let tb = if i + 1 < ts.len() { ts[i + 1] } else { 1.0 };
    (ts[i], tb)
}

fn bend_sample(bend: &Bend, p: DVec3, t: f64) -> Result<DVec3, TempleError> {
    bend_one(bend, p, 0).map_err(|e| match e {
        TempleError::Fold { offset, r, .. } => TempleError::OutlineFolds { t, offset, r },
        other => other,
    })
}

/// For each interval between consecutive type-value points, the largest distance from the
/// exact bend of the original outline (sampled) to the refit's segments near that interval.
fn interval_errors(
    orig: &QuadSpline,
    fit: &QuadSpline,
    ts: &[f64],
    bend: &Bend,
) -> Result<Vec<f64>, TempleError> {
    let n = ts.len();
    let count = if orig.closed { n } else { n - 1 };
    let mut errs = vec![0.0; count];
    for (i, err) in errs.iter_mut().enumerate() {
        let (ta, tb) = interval_span(ts, i);
        for k in 1..=SAMPLES_PER_INTERVAL {
            let t = ta + (tb - ta) * k as f64 / (SAMPLES_PER_INTERVAL + 1) as f64;
            let exact = bend_sample(bend, orig.eval(t), t)?;
            *err = f64::max(*err, near_distance(fit, i, count, exact));
        }
    }
    Ok(errs)
}

/// Distance from `p` to the refit's segments of intervals i−1, i, i+1 (two segments each,
/// wrapping around for a closed spline).
fn near_distance(fit: &QuadSpline, i: usize, count: usize, p: DVec3) -> f64 {
    let near: [Option<usize>; 3] = if fit.closed {
        [
            Some((i + count - 1) % count),
            Some(i),
            Some((i + 1) % count),
        ]
    } else {
        [i.checked_sub(1), Some(i), (i + 1 < count).then_some(i + 1)]
    };
    near.into_iter()
        .flatten()
        .map(|j| fit.closest_point_in(p, 2 * j, 2 * j + 2).distance)
        .fold(f64::INFINITY, f64::min)
}
