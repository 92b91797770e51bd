//! Generating a bent temple outline within a tolerance of the exact bend.
//!
//! Paper 004 bends the type-value points and regenerates the quadratic spline through them
//! ("transform first, then generate"). Any such spline only approximates the exact image of the
//! original outline under the bend: the bend curves the outline between type-value points and
//! even puts a slight corner in it where the outline crosses s = L or s = L + Rθ off the
//! centerline (the map is C1 only along the centerline). So, after each generation, the exact
//! bent outline is sampled between consecutive type-value points (8 even samples per interval,
//! plus every kink — where the outline crosses s = L or s = L + Rθ — inside it) and each
//! sample's distance to the spline (exact nearest point on that interval's two segments, an
//! upper bound of the true distance) is measured. Every interval over tolerance gets new
//! type-value points, bent images of the original outline: at its middle parameter, or, when
//! it holds a kink, at kink ± δ with δ = (interval)·tol/(4·error), since the corner's error
//! shrinks in proportion to the piece that holds it. Repeated until within tolerance, then
//! verified with 32 samples per interval (intervals already under tol/4 excepted); the
//! verified figure is the deviation reported, and intervals it finds over tolerance are
//! refined further. Caps (48 rounds, 4000 added points) end the loop with the deviation
//! achieved, which is then above the tolerance.
//!
//! Two generators are offered:
//! - [`bend_spline`] (default): between consecutive bent type-value points, two quadratic pieces
//!   whose controls are the intersections of the exact bent outline's tangent lines at the two
//!   points and at the interval's middle (quadratic Hermite with a joint; C1 by construction,
//!   the joint is the exact bent middle point). Where the bend is rigid (before the bend, and
//!   beyond it) this reproduces the original outline's segments exactly, so points are only
//!   added in and next to the bend: typically tens, not thousands.
//! - [`bend_spline_interpolated`]: the literal reading, [`QuadSpline::interpolate`] through the
//!   bent type-value points each round. A spline interpolating a superset of the original's
//!   points never reproduces the original exactly, so at 1e-6 it adds ~1000 points all round the
//!   outline (hundreds of ms); kept for comparison and for callers who need
//!   `interpolate(result.points) == result`.

use glam::DVec3;

use super::quadspline::QuadSpline;
use super::quadspline_fit::QuadSplineError;
use super::temple::{bend_one, Bend, TempleError, TempleParams};
use super::traits::ParamCurve;

/// Samples of the exact bent outline measured inside each interval while refining…
const SAMPLES_PER_INTERVAL: usize = 8;
/// …and when verifying the final spline: the deviation reported comes from this denser pass.
const VERIFY_SAMPLES: usize = 32;
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

/// Bend a quadratic-spline outline (see the module doc): bend its type-value points, generate
/// the C1 quadratic spline through them with tangents and joints taken from the exact bend, and
/// add bent type-value points until the spline is within `tol` of the exact bend of `s`. The
/// result passes through the bent image of every original type-value point and keeps the
/// two-segments-per-interval layout (`point_param` holds). If the caps (48 rounds, 4000 added
/// points) are hit first, the result carries the deviation it achieved, then above `tol`.
pub fn bend_spline(
    s: &QuadSpline,
    params: &TempleParams,
    tol: f64,
) -> Result<BentSpline, TempleError> {
    refine(s, params, tol, Generator::Hermite)
}

/// As [`bend_spline`], but each round refits with [`QuadSpline::interpolate`] through the bent
/// type-value points (paper 004 read literally). Much slower to converge; see the module doc.
pub fn bend_spline_interpolated(
    s: &QuadSpline,
    params: &TempleParams,
    tol: f64,
) -> Result<BentSpline, TempleError> {
    refine(s, params, tol, Generator::Interpolate)
}

#[derive(Clone, Copy, PartialEq)]
enum Generator {
    Hermite,
    Interpolate,
}

fn refine(
    s: &QuadSpline,
    params: &TempleParams,
    tol: f64,
    generator: Generator,
) -> Result<BentSpline, TempleError> {
    if !(tol > 0.0 && tol.is_finite()) {
        return Err(TempleError::Tolerance { tol });
    }
    let bend = Bend::new(params)?;
    let closed = s.closed;
    let need = if closed { 3 } else { 2 };
    if s.points.len() < need || s.segments.is_empty() {
        // Only a hand-built spline can be this short; `interpolate` refuses it.
        return Err(QuadSplineError::TooFewPoints {
            need,
            got: s.points.len(),
            closed,
        }
        .into());
    }
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
    let kinks = kink_params(s, &bend);
    // Hermite state: the exact bend's unit tangent at each type-value point, and each
    // interval's pair of pieces once built (they depend on their own interval only).
    let mut tangents: Vec<DVec3> = Vec::with_capacity(n0);
    for i in 0..n0 {
        let next = if i + 1 < n0 {
            i + 1
        } else {
            i.saturating_sub(1)
        };
        let chord = (bent[next] - bent[i]) * if next > i { 1.0 } else { -1.0 };
        tangents.push(bent_tangent(s, &bend, ts[i], chord));
    }
    let mut pieces: Vec<Option<[[DVec3; 3]; 2]>> = vec![None; intervals];
    let mut added = 0;
    let mut round = 0;
    // Measured error per interval; None where it must be (re)measured. Hermite pieces depend
    // only on their own interval, so only new intervals are measured; interpolation is global.
    let mut known: Vec<Option<f64>> = vec![None; intervals];
    loop {
        round += 1;
        let fit = match generator {
            Generator::Interpolate => QuadSpline::interpolate(&bent, closed)?,
            Generator::Hermite => hermite_fit(s, &bend, &ts, &bent, &tangents, &mut pieces)?,
        };
        if generator == Generator::Interpolate {
            known.iter_mut().for_each(|e| *e = None);
        }
        let mut errs = interval_errors(
            s,
            &fit,
            &ts,
            &bend,
            &kinks,
            SAMPLES_PER_INTERVAL,
            &mut known,
        )?;
        let mut deviation = errs.iter().copied().fold(0.0, f64::max);
        let capped = round >= MAX_ROUNDS || added >= MAX_ADDED;
        if deviation <= tol || capped {
            // Verify with denser samples; report that. Intervals it finds over tolerance are
            // refined further (rare: the sparse pass missed a narrow peak). Intervals whose
            // sparse error is under tol/4 keep it: a smooth error curve sampled 8 times (kinks
            // sampled exactly) is not 4× higher between the samples.
            let mut fresh: Vec<Option<f64>> = errs
                .iter()
                .map(|&e| (e <= 0.25 * tol).then_some(e))
                .collect();
            errs = interval_errors(s, &fit, &ts, &bend, &kinks, VERIFY_SAMPLES, &mut fresh)?;
            deviation = errs.iter().copied().fold(0.0, f64::max);
            if deviation <= tol || capped {
                return Ok(BentSpline {
                    spline: fit,
                    deviation,
                    added_points: added,
                    rounds: round,
                });
            }
        }
        let n = ts.len();
        let mut new_ts = Vec::with_capacity(n + errs.len());
        let mut new_bent = Vec::with_capacity(n + errs.len());
        let mut new_known = Vec::with_capacity(n + errs.len());
        let mut new_tangents = Vec::with_capacity(n + errs.len());
        let mut new_pieces = Vec::with_capacity(n + errs.len());
        for i in 0..n {
            new_ts.push(ts[i]);
            new_bent.push(bent[i]);
            new_tangents.push(tangents[i]);
            if i >= errs.len() {
                continue;
            }
            let (ta, tb) = interval_span(&ts, i);
            if errs[i] > tol && added < MAX_ADDED && tb - ta > MIN_INTERVAL {
                let cuts = split_params(ta, tb, errs[i], tol, &kinks);
                let chord = bent[(i + 1) % n] - bent[i];
                for &tm in &cuts {
                    new_ts.push(tm);
                    new_bent.push(bend_sample(&bend, s.eval(tm), tm)?);
                    new_tangents.push(bent_tangent(s, &bend, tm, chord));
                    new_known.push(None);
                    new_pieces.push(None);
                    added += 1;
                }
                new_known.push(None);
                new_pieces.push(None);
            } else {
                new_known.push(Some(errs[i]));
                new_pieces.push(pieces[i]);
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
        known = new_known;
        tangents = new_tangents;
        pieces = new_pieces;
    }
}

/// Where to add type-value points in an interval whose error `err` exceeds `tol`: at the
/// middle, except around a kink inside the interval. There the error comes from the corner
/// and shrinks in proportion to the length of the piece holding it, so one step puts the
/// corner in a piece short enough for the tolerance (half-width δ = (tb − ta)·tol/(4·err)),
/// instead of halving toward it for a dozen rounds; the two long neighbours are smooth.
fn split_params(ta: f64, tb: f64, err: f64, tol: f64, kinks: &[f64]) -> Vec<f64> {
    let first = kinks.partition_point(|k| *k <= ta);
    let h = tb - ta;
    if let Some(&k) = kinks[first..].first().filter(|k| **k < tb) {
        let delta = h * (tol / (4.0 * err)).min(0.25);
        let margin = (h * 1e-3).max(MIN_INTERVAL);
        let cuts: Vec<f64> = [k - delta, k + delta]
            .into_iter()
            .filter(|t| *t > ta + margin && *t < tb - margin)
            .collect();
        if !cuts.is_empty() {
            return cuts;
        }
    }
    vec![0.5 * (ta + tb)]
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
/// exact bend of the original outline (sampled) to the spline's two segments of that interval
/// (the nearest point restricted to them: an upper bound of the true distance, so honest).
/// Intervals with a `known` value are not measured again. Besides the evenly spaced samples,
/// every kink parameter inside the interval is sampled: the error peaks there.
///
/// Only the largest distance counts. Where the first sample already strays well above the
/// rounding level (the intervals in and next to the bend), every other sample gets a cheap
/// upper bound (the distance to a point of its likely segment found by a few Newton steps,
/// see [`foot_bound`]); the one with the largest bound is measured exactly first, and any
/// whose bound is then below the maximum cannot raise it and is not measured. The result is
/// the same maximum, bit for bit, as measuring every sample. Rigid intervals, where every
/// distance is rounding noise that no bound can settle, are measured sample by sample.
fn interval_errors(
    orig: &QuadSpline,
    fit: &QuadSpline,
    ts: &[f64],
    bend: &Bend,
    kinks: &[f64],
    samples: usize,
    known: &mut [Option<f64>],
) -> Result<Vec<f64>, TempleError> {
    let mut errs = Vec::with_capacity(known.len());
    // (exact bent point, likeliest segment, its local parameter guess) per sample, and the
    // samples' upper bounds; reused across intervals.
    let mut todo: Vec<(DVec3, usize, f64)> = Vec::with_capacity(samples + 4);
    let mut bounds: Vec<f64> = Vec::with_capacity(samples + 4);
    for (i, slot) in known.iter_mut().enumerate() {
        if let Some(e) = *slot {
            errs.push(e);
            continue;
        }
        let (ta, tb) = interval_span(ts, i);
        let first = kinks.partition_point(|k| *k <= ta);
        let inside = kinks[first..].iter().take_while(|k| **k < tb).copied();
        let even = (1..=samples).map(|k| ta + (tb - ta) * k as f64 / (samples + 1) as f64);
        let mid = 0.5 * (ta + tb);
        todo.clear();
        // Bent in parameter order, so a fold reports the same (first) parameter as before.
        for t in even.chain(inside) {
            let exact = bend_sample(bend, orig.eval(t), t)?;
            todo.push(if t < mid {
                (exact, 2 * i, (t - ta) / (mid - ta))
            } else {
                (exact, 2 * i + 1, (t - mid) / (tb - mid))
            });
        }
        let measure = |&(exact, likely, _): &(DVec3, usize, f64)| {
            fit.closest_point_in_from(exact, 2 * i, 2 * i + 2, likely)
                .distance
        };
        let mut err: f64 = 0.0;
        if let Some((head, rest)) = todo.split_first() {
            err = err.max(measure(head));
            if err > 4096.0 * f64::EPSILON * head.0.abs().max_element() {
                bounds.clear();
                bounds.extend(rest.iter().map(|&(p, seg, u)| foot_bound(fit, seg, p, u)));
                let top = (0..bounds.len()).max_by(|&a, &b| bounds[a].total_cmp(&bounds[b]));
                if let Some(k) = top.filter(|&k| bounds[k] >= err) {
                    err = err.max(measure(&rest[k]));
                    bounds[k] = f64::NEG_INFINITY;
                }
                for (x, bound) in rest.iter().zip(&bounds) {
                    if *bound >= err {
                        err = err.max(measure(x));
                    }
                }
            } else {
                for x in rest {
                    err = err.max(measure(x));
                }
            }
        }
        *slot = Some(err);
        errs.push(err);
    }
    Ok(errs)
}

/// An upper bound of the distance `closest_point_in_from` reports for `p` on `fit`'s segment
/// `seg` (when present): the distance to the point of that segment reached by three Newton
/// steps on (B(u) − p)·B'(u) from `u` (clamped to [0, 1]), plus a margin far above the
/// rounding of either computation (1024 ulps of the coordinates' size), so that a sample whose
/// bound is below the maximum measured exactly truly cannot raise it. Infinite (measure the
/// sample) when the steps do not settle on a finite point.
fn foot_bound(fit: &QuadSpline, seg: usize, p: DVec3, u: f64) -> f64 {
    let Some(s) = fit.segments.get(seg) else {
        return f64::INFINITY;
    };
    let a = s[0] - 2.0 * s[1] + s[2];
    let b = 2.0 * (s[1] - s[0]);
    let d = s[0] - p;
    let mut u = u.clamp(0.0, 1.0);
    for _ in 0..3 {
        let q = (a * u + b) * u + d;
        let dq = 2.0 * a * u + b;
        let f = q.dot(dq);
        let df = dq.dot(dq) + 2.0 * q.dot(a);
        if df > 0.0 {
            u = (u - f / df).clamp(0.0, 1.0);
        }
    }
    let dist = ((a * u + b) * u + d).length();
    let size = s
        .iter()
        .chain([&p])
        .fold(0.0_f64, |m, c| m.max(c.abs().max_element()));
    let bound = dist + 1024.0 * f64::EPSILON * size;
    if bound.is_finite() {
        bound
    } else {
        f64::INFINITY
    }
}

/// The parameters where the original outline crosses s = L or s = L + Rθ, sorted: there the
/// exact bent outline has a slight corner (off the centerline the map is only C0 across those
/// lines), so the refit's error peaks there. Roots of x(u) = c per Bézier segment.
fn kink_params(orig: &QuadSpline, bend: &Bend) -> Vec<f64> {
    let mut out = Vec::new();
    if bend.th == 0.0 {
        return out;
    }
    let n = orig.segments.len() as f64;
    for c in [bend.l, bend.l + bend.r * bend.th] {
        let c = bend.base.x + c;
        for (i, sg) in orig.segments.iter().enumerate() {
            // x(u) = a u² + b u + x0 with a = x0 − 2x1 + x2, b = 2(x1 − x0).
            let (x0, x1, x2) = (sg[0].x - c, sg[1].x - c, sg[2].x - c);
            let (a, b) = (x0 - 2.0 * x1 + x2, 2.0 * (x1 - x0));
            let mut roots = [f64::NAN; 2];
            if a.abs() <= 1e-300 {
                if b != 0.0 {
                    roots[0] = -x0 / b;
                }
            } else {
                let disc = b * b - 4.0 * a * x0;
                if disc >= 0.0 {
                    let q = -0.5 * (b + b.signum() * disc.sqrt());
                    roots[0] = q / a;
                    if q != 0.0 {
                        roots[1] = x0 / q;
                    }
                }
            }
            for u in roots {
                if (0.0..=1.0).contains(&u) {
                    out.push((i as f64 + u) / n);
                }
            }
        }
    }
    out.sort_by(f64::total_cmp);
    out
}

/// The unit tangent of the exact bent outline at original parameter t: J(S(t))·S'(t), falling
/// back to `fallback` where the outline has zero speed.
fn bent_tangent(orig: &QuadSpline, bend: &Bend, t: f64, fallback: DVec3) -> DVec3 {
    let (jx, jy) = bend.jacobian(orig.eval(t));
    let d = orig.derivative(t);
    (jx * d.x + jy * d.y + DVec3::Z * d.z)
        .try_normalize()
        .or_else(|| fallback.try_normalize())
        .unwrap_or(DVec3::X)
}

/// The control point of a quadratic from `p` (unit tangent `tp`) to `q` (unit tangent `tq`):
/// the meeting point of the two tangent lines, X = p + α·tp = q − γ·tq with α, γ > 0. None when
/// the lines are parallel (unless the piece is straight), skew, or meet behind an end or
/// within 5% of the chord from one.
fn tangent_meet(p: DVec3, tp: DVec3, q: DVec3, tq: DVec3) -> Option<DVec3> {
    let d = q - p;
    let len = d.length();
    // α·tp + γ·tq = d, solved with cross products (n = tp × tq, |n|² = sin² of the angle
    // between the tangents): no 1 − cos² cancellation, so nearly parallel tangents (a nearly
    // straight piece) still give an accurate meeting point.
    let n = tp.cross(tq);
    let n2 = n.length_squared();
    if n2 < 1e-24 {
        // Parallel tangents: only a straight piece along them works (control at the middle).
        let straight = tp.dot(tq) > 0.0 && d.dot(tp) > 0.0 && d.cross(tp).length() <= 1e-12 * len;
        return straight.then(|| p.lerp(q, 0.5));
    }
    let alpha = d.cross(tq).dot(n) / n2;
    let gamma = tp.cross(d).dot(n) / n2;
    // Legs much shorter than the chord make a near-cusp (speed almost 0 at an end), which
    // CAM arc fitting and offsetting handle badly: refuse them as well.
    if !(alpha > 0.05 * len && gamma > 0.05 * len) {
        return None;
    }
    let x1 = p + tp * alpha;
    let x2 = q - tq * gamma;
    (x1.distance(x2) <= 1e-9 * len).then(|| x1.lerp(x2, 0.5))
}

/// Quadratic Hermite with a joint on every interval (see the module doc): two segments per
/// interval, C1 at every joint and at every type-value point.
fn hermite_fit(
    orig: &QuadSpline,
    bend: &Bend,
    ts: &[f64],
    bent: &[DVec3],
    tangents: &[DVec3],
    pieces: &mut [Option<[[DVec3; 3]; 2]>],
) -> Result<QuadSpline, TempleError> {
    let n = ts.len();
    let closed = orig.closed;
    for (i, slot) in pieces.iter_mut().enumerate() {
        if slot.is_none() {
            let j = (i + 1) % n;
            *slot = Some(hermite_pair(
                orig,
                bend,
                interval_span(ts, i),
                [bent[i], bent[j]],
                [tangents[i], tangents[j]],
            )?);
        }
    }
    Ok(QuadSpline {
        points: bent.to_vec(),
        closed,
        segments: pieces.iter().flat_map(|p| p.unwrap_or_default()).collect(),
    })
}

/// The two pieces of one interval from `ends[0]` to `ends[1]` (original parameters `span`).
fn hermite_pair(
    orig: &QuadSpline,
    bend: &Bend,
    span: (f64, f64),
    ends: [DVec3; 2],
    tans: [DVec3; 2],
) -> Result<[[DVec3; 3]; 2], TempleError> {
    if let Some(pair) = rigid_pair(orig, bend, span) {
        return Ok(pair);
    }
    let [a, b] = ends;
    let [ta, tb] = tans;
    let tm = 0.5 * (span.0 + span.1);
    let m = bend_sample(bend, orig.eval(tm), tm)?;
    let tmv = bent_tangent(orig, bend, tm, b - a);
    Ok(
        match (tangent_meet(a, ta, m, tmv), tangent_meet(m, tmv, b, tb)) {
            (Some(x1), Some(x2)) => [[a, x1, m], [m, x2, b]],
            _ => {
                // No tangent-meeting controls (inflection or a fold of the tangents): a C1 pair
                // with controls on the end tangents and the joint between them; the error
                // measurement will split the interval if this is not close enough.
                // Legs of a third of the chord: exact for a straight piece, and never a
                // near-cusp (halves would collapse both controls onto the joint).
                let h = a.distance(b) / 3.0;
                let x1 = a + ta * h;
                let x2 = b - tb * h;
                let mid = x1.lerp(x2, 0.5);
                [[a, x1, mid], [mid, x2, b]]
            }
        },
    )
}

/// The original's two segments of `span`, moved by the bend, when the whole span lies where
/// the bend is rigid (before the bend, or beyond it): the map is affine there, so the moved
/// controls give the exact image — corners (zero tangents) and straight runs included.
fn rigid_pair(orig: &QuadSpline, bend: &Bend, span: (f64, f64)) -> Option<[[DVec3; 3]; 2]> {
    let n = orig.segments.len() as f64;
    let (k0, k1) = (span.0 * n, span.1 * n);
    let first = k0.round();
    if (k0 - first).abs() > 1e-9 || (k1 - first - 2.0).abs() > 1e-9 || first < 0.0 {
        return None;
    }
    let i = first as usize;
    let segs = [*orig.segments.get(i)?, *orig.segments.get(i + 1)?];
    let end = bend.l + bend.r * bend.th;
    let ss = segs.iter().flatten().map(|p| bend.local(*p).0);
    let (lo, hi) = ss.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
        (lo.min(s), hi.max(s))
    });
    if !(hi <= bend.l || bend.th == 0.0 || lo >= end) {
        return None;
    }
    Some(segs.map(|sg| sg.map(|p| bend.map(p))))
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;

    /// `interval_errors` as first written: every sample measured exactly, in parameter order.
    fn errors_measuring_all(
        orig: &QuadSpline,
        fit: &QuadSpline,
        ts: &[f64],
        bend: &Bend,
        kinks: &[f64],
        samples: usize,
    ) -> Vec<f64> {
        (0..ts.len().min(fit.segments.len() / 2))
            .map(|i| {
                let (ta, tb) = interval_span(ts, i);
                let first = kinks.partition_point(|k| *k <= ta);
                let inside = kinks[first..].iter().take_while(|k| **k < tb).copied();
                let even = (1..=samples).map(|k| ta + (tb - ta) * k as f64 / (samples + 1) as f64);
                let mid = 0.5 * (ta + tb);
                even.chain(inside).fold(0.0_f64, |err, t| {
                    let exact = bend_sample(bend, orig.eval(t), t).unwrap();
                    let likely = if t < mid { 2 * i } else { 2 * i + 1 };
                    err.max(
                        fit.closest_point_in_from(exact, 2 * i, 2 * i + 2, likely)
                            .distance,
                    )
                })
            })
            .collect()
    }

    /// The outline of scripts/temple.lsp (hinge 5, slimmest 3.5, tip 7) for length `l1`.
    fn temple_outline(l1: f64) -> QuadSpline {
        let pts: Vec<DVec3> = [
            (0.0, -2.5),
            (0.04, -2.5),
            (0.35, -2.125),
            (0.7, -1.75),
            (0.9, -3.5),
            (1.0, 0.0),
            (0.9, 3.5),
            (0.7, 1.75),
            (0.35, 2.125),
            (0.04, 2.5),
            (0.0, 2.5),
        ]
        .iter()
        .map(|(x, y)| {
            DVec3::new(
                if *x == 1.0 { l1 } else { x * l1 },
                if *x == 1.0 { 0.0 } else { *y },
                0.0,
            )
        })
        .collect();
        QuadSpline::interpolate(&pts, true).unwrap()
    }

    /// The bound-and-skip measurement returns exactly (bit for bit) the maxima of measuring
    /// every sample, on the first fit of several bends and on a fit with every interval
    /// halved (more intervals, kinks inside some of them), for the refining and the verifying
    /// sample counts.
    #[test]
    fn bounded_errors_are_the_exhaustive_maxima() {
        let mut compared = 0;
        for (l1, l2, r, deg) in [
            (130.0, 30.0, 10.0, 25.0),
            (140.0, 35.0, 15.0, 40.0),
            (150.0, 25.0, 8.0, 60.0),
            (120.0, 40.0, 20.0, -35.0),
            (135.0, 30.0, 5.0, 80.0),
        ] {
            let params = TempleParams {
                l1,
                l2,
                r,
                theta: f64::to_radians(deg),
                base: DVec2::ZERO,
            };
            let s = temple_outline(l1);
            let bend = Bend::new(&params).unwrap();
            let kinks = kink_params(&s, &bend);
            assert!(!kinks.is_empty());
            let n0 = s.points.len();
            let first: Vec<f64> = (0..n0).map(|j| s.point_param(j)).collect();
            let halved: Vec<f64> = (0..2 * n0).map(|j| j as f64 / (2 * n0) as f64).collect();
            for ts in [first, halved] {
                let n = ts.len();
                let bent: Vec<DVec3> = ts
                    .iter()
                    .map(|&t| bend_sample(&bend, s.eval(t), t).unwrap())
                    .collect();
                let tangents: Vec<DVec3> = (0..n)
                    .map(|i| bent_tangent(&s, &bend, ts[i], bent[(i + 1) % n] - bent[i]))
                    .collect();
                let mut pieces = vec![None; n];
                let fit = hermite_fit(&s, &bend, &ts, &bent, &tangents, &mut pieces).unwrap();
                for samples in [SAMPLES_PER_INTERVAL, VERIFY_SAMPLES] {
                    let mut known = vec![None; n];
                    let got =
                        interval_errors(&s, &fit, &ts, &bend, &kinks, samples, &mut known).unwrap();
                    let want = errors_measuring_all(&s, &fit, &ts, &bend, &kinks, samples);
                    let bits = |v: &[f64]| v.iter().map(|e| e.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&got), bits(&want), "{l1} {l2} {r} {deg}° {samples}");
                    assert!(got.iter().any(|e| *e > 1e-6), "a bend that errs somewhere");
                    compared += got.len();
                }
            }
        }
        assert_eq!(compared, 5 * 2 * (11 + 22));
    }
}
