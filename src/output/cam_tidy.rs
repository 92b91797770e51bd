//! Making CAM chains laser-ready: no segment shorter than `cam_min_seg` where a neighbour can
//! take it over within tolerance, closed contours oriented (outer CCW, holes CW) and started
//! on a straight or gently curved stretch.
//!
//! Short segments come from biarc fitting (a knot or a span split close to another) and stall
//! controllers. Merging replaces two neighbouring segments by one arc through their outer ends
//! and their common point; it is accepted only when every sample of the segments it replaces
//! (the originally fitted ones, not earlier merges) lies within the merge tolerance of it, so
//! the error never accumulates. A short segment no neighbour can absorb — a real corner, or a
//! feature that small — stays and is counted.

use glam::DVec2;

use super::biarc::{bulge_point, dist_to_bulge_seg, BulgeChain};

/// Samples per original segment when checking a merge.
const CHECK_SAMPLES: usize = 8;

/// One segment of the chain being tidied, with the original segments it stands for.
#[derive(Clone)]
struct Span {
    a: DVec2,
    b: DVec2,
    bulge: f64,
    /// Original segment indices first..last (inclusive), in chain order.
    orig: (usize, usize),
}

/// The bulge of the arc from `a` through `m` to `b` (0 when the three are collinear).
fn bulge_through(a: DVec2, m: DVec2, b: DVec2) -> f64 {
    let (u, v) = (a - m, b - m);
    let cross = (b - a).perp_dot(m - a);
    if cross.abs() <= 1e-14 * (b - a).length_squared() {
        return 0.0;
    }
    // The inscribed angle at m is π − sweep/2: bulge = tan(sweep/4) = tan((π − angle)/2).
    let angle = u.angle_to(v).abs();
    let mag = ((std::f64::consts::PI - angle) / 2.0).tan();
    // m to the right of a→b: the arc bulges right, i.e. turns counter-clockwise.
    if cross < 0.0 {
        mag
    } else {
        -mag
    }
}

/// Merge segments shorter than `min_seg` into a neighbour where the merged arc stays within
/// `tol` of the chain as given. Returns how many short segments remain.
pub fn merge_short(ch: &mut BulgeChain, closed: bool, min_seg: f64, tol: f64) -> usize {
    let m = ch.bulges.len();
    if min_seg <= 0.0 || m < 2 {
        return 0;
    }
    let n = ch.points.len();
    let orig: Vec<(DVec2, DVec2, f64)> = (0..m)
        .map(|i| (ch.points[i], ch.points[(i + 1) % n], ch.bulges[i]))
        .collect();
    let mut spans: Vec<Span> = orig
        .iter()
        .enumerate()
        .map(|(i, &(a, b, bulge))| Span {
            a,
            b,
            bulge,
            orig: (i, i),
        })
        .collect();
    let mut stuck = vec![false; spans.len()];
    loop {
        let short = (0..spans.len())
            .filter(|&i| !stuck[i] && spans[i].a.distance(spans[i].b) < min_seg)
            .min_by(|&i, &j| {
                let li = spans[i].a.distance(spans[i].b);
                let lj = spans[j].a.distance(spans[j].b);
                li.total_cmp(&lj)
            });
        let Some(i) = short else { break };
        let k = spans.len();
        let prev = if i > 0 {
            Some(i - 1)
        } else if closed && k > 2 {
            Some(k - 1)
        } else {
            None
        };
        let next = if i + 1 < k {
            Some(i + 1)
        } else if closed && k > 2 {
            Some(0)
        } else {
            None
        };
        let try_merge = |x: usize, y: usize| -> Option<(Span, f64)> {
            let (s, t) = (&spans[x], &spans[y]);
            let bulge = bulge_through(s.a, s.b, t.b);
            let merged = Span {
                a: s.a,
                b: t.b,
                bulge,
                orig: (s.orig.0, t.orig.1),
            };
            let err = merge_error(&orig, &merged);
            (err <= tol).then_some((merged, err))
        };
        let a = prev.and_then(|p| try_merge(p, i).map(|m| (p, m)));
        let b = next.and_then(|q| try_merge(i, q).map(|m| (q, m)));
        let best = match (a, b) {
            (Some(x), Some(y)) => Some(if x.1 .1 <= y.1 .1 { x } else { y }),
            (x, y) => x.or(y),
        };
        match best {
            Some((other, (merged, _))) => {
                let first = if Some(other) == prev { other } else { i };
                let second = if first == other { i } else { other };
                spans[first] = merged;
                spans.remove(second);
                stuck.remove(second);
                stuck[if second < first { first - 1 } else { first }] = false;
            }
            None => stuck[i] = true,
        }
    }
    let left = spans.iter().filter(|s| s.a.distance(s.b) < min_seg).count();
    ch.points = spans.iter().map(|s| s.a).collect();
    if !closed {
        ch.points.push(spans[spans.len() - 1].b);
    }
    ch.bulges = spans.iter().map(|s| s.bulge).collect();
    left
}

/// Largest distance from the original segments `merged` replaces to it.
fn merge_error(orig: &[(DVec2, DVec2, f64)], merged: &Span) -> f64 {
    let m = orig.len();
    let (first, last) = merged.orig;
    let count = if last >= first {
        last - first + 1
    } else {
        m - first + last + 1
    };
    let mut err: f64 = 0.0;
    for k in 0..count {
        let (a, b, bulge) = orig[(first + k) % m];
        for s in 0..=CHECK_SAMPLES {
            let p = bulge_point(a, b, bulge, s as f64 / CHECK_SAMPLES as f64);
            err = err.max(dist_to_bulge_seg(p, merged.a, merged.b, merged.bulge));
        }
    }
    err
}

/// Signed area of a closed bulge chain (positive counter-clockwise), arcs included.
pub fn signed_area(ch: &BulgeChain) -> f64 {
    let n = ch.points.len();
    let mut area = 0.0;
    for i in 0..n {
        let (a, b) = (ch.points[i], ch.points[(i + 1) % n]);
        area += 0.5 * a.perp_dot(b);
        let bu = ch.bulges.get(i).copied().unwrap_or(0.0);
        if bu != 0.0 {
            let theta = 4.0 * bu.abs().atan();
            let c = a.distance(b);
            let r = c / (2.0 * (theta / 2.0).sin());
            area += bu.signum() * 0.5 * r * r * (theta - theta.sin());
        }
    }
    area
}

/// Reverse a closed chain's direction.
pub fn reverse_closed(ch: &mut BulgeChain) {
    let n = ch.points.len();
    let pts: Vec<DVec2> = (0..n).map(|k| ch.points[(n - k) % n]).collect();
    let bul: Vec<f64> = (0..n)
        .map(|k| -ch.bulges.get(n - k - 1).copied().unwrap_or(0.0))
        .collect();
    ch.points = pts;
    ch.bulges = bul;
}

/// Whether `p` lies inside the closed chain (its vertices as a polygon, arcs by their
/// midpoints: ample for deciding which contour holds which).
pub fn contains(ch: &BulgeChain, p: DVec2) -> bool {
    let n = ch.points.len();
    let mut poly = Vec::with_capacity(2 * n);
    for i in 0..n {
        let (a, b) = (ch.points[i], ch.points[(i + 1) % n]);
        poly.push(a);
        let bu = ch.bulges.get(i).copied().unwrap_or(0.0);
        if bu != 0.0 {
            poly.push(bulge_point(a, b, bu, 0.5));
        }
    }
    let mut inside = false;
    let k = poly.len();
    for i in 0..k {
        let (a, b) = (poly[i], poly[(i + 1) % k]);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Start the closed chain at the vertex where cutting begins best: tangent continuous there
/// (turn under 2°), then the gentlest curvature on both sides, then the longest neighbours.
pub fn choose_start(ch: &mut BulgeChain) {
    let n = ch.points.len();
    if n < 2 {
        return;
    }
    let seg = |i: usize| {
        let (a, b) = (ch.points[i % n], ch.points[(i + 1) % n]);
        let bu = ch.bulges.get(i % n).copied().unwrap_or(0.0);
        let d = b - a;
        let half = 2.0 * bu.atan();
        let c = d.length().max(1e-300);
        let curvature = 2.0 * half.sin().abs() / c;
        let dir = d.normalize_or_zero();
        let start = DVec2::from_angle(-half).rotate(dir);
        let end = DVec2::from_angle(half).rotate(dir);
        (start, end, curvature, c)
    };
    let mut best: Option<(usize, f64, f64)> = None;
    for k in 0..n {
        let (_, end_in, k_in, l_in) = seg(k + n - 1);
        let (start_out, _, k_out, l_out) = seg(k);
        let turn = end_in.angle_to(start_out).abs();
        if turn > 2f64.to_radians() {
            continue;
        }
        let curv = k_in.max(k_out);
        let len = l_in.min(l_out);
        let better = match best {
            None => true,
            Some((_, c, l)) => curv < c * 0.999 || (curv <= c * 1.001 && len > l),
        };
        if better {
            best = Some((k, curv, len));
        }
    }
    if let Some((k, _, _)) = best {
        ch.points.rotate_left(k);
        ch.bulges.rotate_left(k);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chain(points: &[(f64, f64)], bulges: &[f64]) -> BulgeChain {
        BulgeChain {
            points: points.iter().map(|&(x, y)| DVec2::new(x, y)).collect(),
            bulges: bulges.to_vec(),
        }
    }

    #[test]
    fn a_short_collinear_segment_is_absorbed() {
        let mut c = chain(
            &[(0.0, 0.0), (10.0, 0.0), (10.01, 0.0), (20.0, 0.0)],
            &[0.0; 3],
        );
        let left = merge_short(&mut c, false, 0.05, 1e-6);
        assert_eq!(left, 0);
        assert_eq!(c.bulges.len(), 2);
    }

    #[test]
    fn a_short_segment_at_a_corner_stays() {
        let mut c = chain(
            &[(0.0, 0.0), (10.0, 0.0), (10.0, 0.01), (0.0, 0.01)],
            &[0.0; 3],
        );
        assert_eq!(merge_short(&mut c, false, 0.05, 1e-3), 1);
        assert_eq!(c.bulges.len(), 3);
    }

    #[test]
    fn area_orientation_and_reversal() {
        // The unit square with its top edge a half circle bulging up (counter-clockwise).
        let mut c = chain(
            &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
            &[0.0, 0.0, 1.0, 0.0],
        );
        let a = signed_area(&c);
        assert!(
            (a - (1.0 + std::f64::consts::PI / 8.0)).abs() < 1e-12,
            "{a}"
        );
        reverse_closed(&mut c);
        assert!((signed_area(&c) + a).abs() < 1e-12);
        assert!(contains(&c, DVec2::new(0.5, 1.3)));
        assert!(!contains(&c, DVec2::new(0.5, 1.6)));
    }
}
