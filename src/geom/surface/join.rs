//! Refined curves put together where they meet at a point: re-paired straight on through the
//! points where two of them cross (branch points), then joined end to end where one ends on
//! the point another begins and runs straight on.
//!
//! At a branch point two crossings meet at an angle, so each true curve runs straight on
//! through it while a curve turning there has gone over onto the other one. The seeds do not
//! know this: two equal cylinders at some seed tolerances gave four half-ellipses ending at
//! the branch points, at others two closed curves each made of halves of both ellipses.

use super::refine::leaving;
use crate::geom::mesh::Polyline3;
use glam::DVec3;

/// How straight on a curve must run through a joint to be joined there: within 15°. A
/// smaller turn is also not taken for a curve that went over onto another one.
const STRAIGHT: f64 = 0.966;

/// The curves re-paired through the branch points they turn at ([`repair`]), then joined end
/// to end through the points where they meet ([`join_through`]).
pub(crate) fn through_branches(curves: Vec<Polyline3>, tol: f64) -> Vec<Polyline3> {
    join_through(repair(curves, tol), tol)
}

/// A point a curve passes through (not an end of an open curve), turning there by more than
/// 15°: the curve, the point's index, and the directions the curve leaves it backwards and on.
struct Bend {
    curve: usize,
    at: usize,
    dirs: [DVec3; 2],
}

/// Every point where one curve turns by more than 15° and another (or the same one, elsewhere
/// along it) turns too, re-paired straightest first (see [`straightest`]) where that is
/// straighter: the curves are cut there and the pieces joined again as re-paired. A turn at
/// a point no other curve passes is the curve's own (a coarse chord, a corner), and a curve
/// running straight through a point where another turns cannot be made straighter.
fn repair(curves: Vec<Polyline3>, tol: f64) -> Vec<Polyline3> {
    let bends = bends(&curves, tol);
    if bends.len() < 2 {
        return curves;
    }
    // The bends cut at, and for each of the two directions of each (2·g backwards, 2·g + 1
    // on), the direction it is joined to.
    let mut cut: Vec<&Bend> = Vec::new();
    let mut partner: Vec<usize> = Vec::new();
    let mut taken = vec![false; bends.len()];
    for i in 0..bends.len() {
        if taken[i] {
            continue;
        }
        let at = curves[bends[i].curve].points[bends[i].at];
        let node: Vec<usize> = (i..bends.len())
            .filter(|&j| {
                !taken[j] && curves[bends[j].curve].points[bends[j].at].distance(at) <= tol
            })
            .collect();
        if node.len() < 2 {
            continue;
        }
        let dirs: Vec<DVec3> = node.iter().flat_map(|&j| bends[j].dirs).collect();
        let Some(pairs) = straighter(&dirs) else {
            continue;
        };
        let base = 2 * cut.len();
        partner.resize(base + dirs.len(), 0);
        for (x, y) in pairs {
            partner[base + x] = base + y;
            partner[base + y] = base + x;
        }
        for &j in &node {
            taken[j] = true;
            cut.push(&bends[j]);
        }
    }
    if cut.is_empty() {
        return curves;
    }
    rejoin(curves, &cut, &partner)
}

/// The bends of `curves` (see [`Bend`]). The turn is read from the neighbouring points, and
/// where that shows one, from the first points farther than `tol` each way; a point within
/// `tol` of the one before it is that one.
fn bends(curves: &[Polyline3], tol: f64) -> Vec<Bend> {
    let mut out = Vec::new();
    for (ci, c) in curves.iter().enumerate() {
        let p = &c.points;
        let n = p.len();
        if n < 3 || (c.closed && n < 4) {
            continue;
        }
        // A closed curve passes its first point too (its last repeats it).
        let (from, to) = if c.closed { (0, n - 1) } else { (1, n - 1) };
        for k in from..to {
            let prev = if k == 0 { p[n - 2] } else { p[k - 1] };
            let (u, v) = (prev - p[k], p[k + 1] - p[k]);
            let (uu, vv) = (u.length_squared(), v.length_squared());
            if uu <= tol * tol || (vv > tol * tol && -u.dot(v) >= STRAIGHT * (uu * vv).sqrt()) {
                continue;
            }
            let (back, on) = if c.closed {
                let ring = &p[..n - 1];
                (
                    leaving(
                        p[k],
                        ring[..k].iter().rev().chain(ring[k + 1..].iter().rev()),
                        tol,
                    ),
                    leaving(p[k], ring[k + 1..].iter().chain(&ring[..k]), tol),
                )
            } else {
                (
                    leaving(p[k], p[..k].iter().rev(), tol),
                    leaving(p[k], p[k + 1..].iter(), tol),
                )
            };
            // `leaving` gives the way out at an end, opposite to the way along the curve.
            if let (Some(back), Some(on)) = (back, on) {
                if -back.dot(on) < STRAIGHT {
                    out.push(Bend {
                        curve: ci,
                        at: k,
                        dirs: [-back, -on],
                    });
                }
            }
        }
    }
    out
}

/// The directions leaving one point, paired straightest first (most nearly opposite), if
/// that pairing is straighter than the one they came in (0 with 1, 2 with 3, …): its joints'
/// straightness, straightest first, compared in turn, by more than rounding.
fn straighter(dirs: &[DVec3]) -> Option<Vec<(usize, usize)>> {
    let straightness = |(x, y): (usize, usize)| -dirs[x].dot(dirs[y]);
    let mut all: Vec<(usize, usize)> = (0..dirs.len())
        .flat_map(|x| (x + 1..dirs.len()).map(move |y| (x, y)))
        .collect();
    all.sort_by(|&p, &q| straightness(q).total_cmp(&straightness(p)));
    let mut used = vec![false; dirs.len()];
    let mut pairs = Vec::with_capacity(dirs.len() / 2);
    for (x, y) in all {
        if !used[x] && !used[y] {
            used[x] = true;
            used[y] = true;
            pairs.push((x, y));
        }
    }
    // Already straightest first.
    let new = pairs.iter().map(|&p| straightness(p));
    let mut now: Vec<f64> = (0..dirs.len() / 2)
        .map(|g| straightness((2 * g, 2 * g + 1)))
        .collect();
    now.sort_by(|x, y| y.total_cmp(x));
    let first_apart = new.zip(now).find(|(n, o)| (n - o).abs() > 1e-9);
    first_apart.is_some_and(|(n, o)| n > o).then_some(pairs)
}

/// A piece of a curve cut at bends, with the direction slot (see [`repair`]) at each end that
/// is a cut.
struct Piece {
    points: Vec<DVec3>,
    ends: [Option<usize>; 2],
}

/// The curves cut at the bends `cut` (bend g's directions are slots 2·g and 2·g + 1) and the
/// pieces joined again slot to `partner` slot; the curves not cut come first, unchanged.
fn rejoin(curves: Vec<Polyline3>, cut: &[&Bend], partner: &[usize]) -> Vec<Polyline3> {
    let mut at: Vec<Vec<(usize, usize)>> = vec![Vec::new(); curves.len()];
    for (g, b) in cut.iter().enumerate() {
        at[b.curve].push((b.at, g));
    }
    let mut out = Vec::new();
    let mut pieces: Vec<Piece> = Vec::new();
    for (c, mut ks) in curves.into_iter().zip(at) {
        if ks.is_empty() {
            out.push(c);
            continue;
        }
        ks.sort_unstable();
        pieces.extend(cut_at(c, &ks));
    }
    // Where each slot is: the piece, and whether at its start.
    let mut slot_at = vec![(0, false); partner.len()];
    for (i, pc) in pieces.iter().enumerate() {
        for (e, s) in pc.ends.iter().enumerate() {
            if let Some(s) = s {
                slot_at[*s] = (i, e == 0);
            }
        }
    }
    let mut seen = vec![false; pieces.len()];
    // Chains from the free ends first; what is left are loops.
    let starts: Vec<(usize, bool)> = (0..pieces.len())
        .flat_map(|i| [(i, true), (i, false)])
        .filter(|&(i, start)| pieces[i].ends[usize::from(!start)].is_none())
        .chain((0..pieces.len()).map(|i| (i, true)))
        .collect();
    for (i, forward) in starts {
        if seen[i] {
            continue;
        }
        let (mut cur, mut fwd) = (i, forward);
        let mut pts: Vec<DVec3> = Vec::new();
        let closed = loop {
            seen[cur] = true;
            let skip = usize::from(!pts.is_empty());
            if fwd {
                pts.extend(pieces[cur].points.iter().skip(skip));
            } else {
                pts.extend(pieces[cur].points.iter().rev().skip(skip));
            }
            let Some(s) = pieces[cur].ends[usize::from(fwd)] else {
                break false;
            };
            let (next, at_start) = slot_at[partner[s]];
            if seen[next] {
                break true;
            }
            (cur, fwd) = (next, at_start);
        };
        if closed {
            // Ending on its first point, as closed curves do.
            let first = pts[0];
            if let Some(l) = pts.last_mut() {
                *l = first;
            }
        }
        out.push(Polyline3 {
            points: pts,
            closed,
        });
    }
    out
}

/// The curve `c` cut at the indices `ks` (ascending), bend g at `(k, g)`: each piece with the
/// slot of the bend at each end that is a cut.
fn cut_at(c: Polyline3, ks: &[(usize, usize)]) -> Vec<Piece> {
    let p = c.points;
    let m = ks.len();
    let mut out = Vec::with_capacity(m + 1);
    if c.closed {
        // From each cut on to the next, the last round through the first point.
        for (i, &(k, g)) in ks.iter().enumerate() {
            let (k1, g1) = ks[(i + 1) % m];
            let points = if k1 > k {
                p[k..=k1].to_vec()
            } else {
                p[k..p.len() - 1].iter().chain(&p[..=k1]).copied().collect()
            };
            out.push(Piece {
                points,
                ends: [Some(2 * g + 1), Some(2 * g1)],
            });
        }
        return out;
    }
    let mut from = (0, None);
    for &(k, g) in ks {
        out.push(Piece {
            points: p[from.0..=k].to_vec(),
            ends: [from.1, Some(2 * g)],
        });
        from = (k, Some(2 * g + 1));
    }
    out.push(Piece {
        points: p[from.0..].to_vec(),
        ends: [from.1, None],
    });
    out
}

/// A joint of two open curves (or of one with itself): `i`'s end (its start if `ri`) on
/// `j`'s start (its end if `rj`).
struct Joint {
    i: usize,
    ri: bool,
    j: usize,
    rj: bool,
}

/// Open curves joined where one ends on the point another begins (within `tol`, either way
/// round) and runs straight on through it, the most nearly straight joint first; a curve then
/// closed where its own ends meet so. The seeds split a crossing at a branch point, where
/// the other crossing passes (two equal cylinders: four half-ellipses from the meshes at most
/// seed tolerances), and each piece is carried onto the point; nothing joined them, so the
/// same surfaces gave two curves or four by the user's CHORDTOL. Within 15° only: the
/// crossings through a branch point meet at an angle.
fn join_through(mut curves: Vec<Polyline3>, tol: f64) -> Vec<Polyline3> {
    while let Some(joint) = straightest_joint(&curves, tol) {
        join(&mut curves, joint);
    }
    curves
}

/// A curve's end (`last`) or start, and the direction it leaves the curve in there.
fn end(c: &Polyline3, last: bool, tol: f64) -> (DVec3, Option<DVec3>) {
    let p = &c.points;
    if last {
        let e = p[p.len() - 1];
        (e, leaving(e, p.iter().rev().skip(1), tol))
    } else {
        (p[0], leaving(p[0], p.iter().skip(1), tol))
    }
}

/// The straightest joint of two open curves' ends meeting within `tol` (see [`join_through`]).
fn straightest_joint(curves: &[Polyline3], tol: f64) -> Option<Joint> {
    let open: Vec<usize> = (0..curves.len())
        .filter(|&i| !curves[i].closed && curves[i].points.len() >= 2)
        .collect();
    let mut best: Option<(f64, Joint)> = None;
    for &i in &open {
        for &j in &open {
            for (ri, rj) in [(false, false), (false, true), (true, false), (true, true)] {
                if i == j && (ri || rj || curves[i].points.len() < 4) {
                    continue;
                }
                let ((pe, de), (ps, ds)) = (end(&curves[i], !ri, tol), end(&curves[j], rj, tol));
                if pe.distance(ps) > tol {
                    continue;
                }
                // Each leaves the curve outwards: straight on where they oppose.
                let (Some(de), Some(ds)) = (de, ds) else {
                    continue;
                };
                let k = -de.dot(ds);
                if k >= STRAIGHT && best.as_ref().is_none_or(|b| k > b.0) {
                    best = Some((k, Joint { i, ri, j, rj }));
                }
            }
        }
    }
    best.map(|b| b.1)
}

/// `curves` with the `joint` made: one curve closed, or two made one.
fn join(curves: &mut Vec<Polyline3>, Joint { i, ri, j, rj }: Joint) {
    if i == j {
        // Its own end on its start: closed, ending on its first point as closed curves do.
        let c = &mut curves[i];
        let s = c.points[0];
        if let Some(l) = c.points.last_mut() {
            *l = s;
        }
        c.closed = true;
        return;
    }
    let mut head = std::mem::take(&mut curves[i].points);
    let mut tail = std::mem::take(&mut curves[j].points);
    if ri {
        head.reverse();
    }
    if rj {
        tail.reverse();
    }
    head.extend(tail.into_iter().skip(1));
    curves[i].points = head;
    curves.remove(j);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec3 {
        DVec3::new(x, y, 0.0)
    }

    fn open(points: Vec<DVec3>) -> Polyline3 {
        Polyline3 {
            points,
            closed: false,
        }
    }

    /// Whether `c` runs through exactly the points `want`, one way or the other.
    fn runs(c: &Polyline3, want: &[DVec3]) -> bool {
        let rev: Vec<DVec3> = want.iter().rev().copied().collect();
        c.points == want || c.points == rev
    }

    #[test]
    fn two_curves_turning_where_they_cross_are_re_paired_straight_on() {
        // The x axis and the y axis, each taken half by one curve and half by the other.
        let a = open(vec![
            v(-2.0, 0.0),
            v(-1.0, 0.0),
            v(0.0, 0.0),
            v(0.0, 1.0),
            v(0.0, 2.0),
        ]);
        let b = open(vec![
            v(0.0, -2.0),
            v(0.0, -1.0),
            v(0.0, 1e-12),
            v(1.0, 0.0),
            v(2.0, 0.0),
        ]);
        let r = through_branches(vec![a, b], 1e-9);
        assert_eq!(r.len(), 2);
        let x = [
            v(-2.0, 0.0),
            v(-1.0, 0.0),
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(2.0, 0.0),
        ];
        let y = [
            v(0.0, -2.0),
            v(0.0, -1.0),
            v(0.0, 1e-12),
            v(0.0, 1.0),
            v(0.0, 2.0),
        ];
        let y0 = [
            v(0.0, -2.0),
            v(0.0, -1.0),
            v(0.0, 0.0),
            v(0.0, 1.0),
            v(0.0, 2.0),
        ];
        assert!(r.iter().any(|c| runs(c, &x)), "{r:?}");
        assert!(r.iter().any(|c| runs(c, &y) || runs(c, &y0)), "{r:?}");
        assert!(r.iter().all(|c| !c.closed));
    }

    /// `k` chords of the circle about `c` of radius √2 from angle `from` to `to` (degrees).
    fn arc(c: DVec3, from: f64, to: f64, k: usize) -> Vec<DVec3> {
        (0..=k)
            .map(|i| {
                let t = (from + (to - from) * i as f64 / k as f64).to_radians();
                c + 2f64.sqrt() * v(t.cos(), t.sin())
            })
            .collect()
    }

    #[test]
    fn two_closed_curves_of_mixed_halves_become_the_two_circles() {
        // The circles about (0, ±1) through (±1, 0), crossing there at right angles; each
        // curve given takes the half of one above y = 0 and the other's half below (the outer
        // and the inner outline of their union's lens).
        let (up, down) = (v(0.0, 1.0), v(0.0, -1.0));
        let mixed = |top: Vec<DVec3>, bottom: Vec<DVec3>| Polyline3 {
            points: top.into_iter().chain(bottom.into_iter().skip(1)).collect(),
            closed: true,
        };
        let outer = mixed(arc(up, 225.0, -45.0, 12), arc(down, 45.0, -225.0, 12));
        let inner = mixed(arc(down, 135.0, 45.0, 12), arc(up, 315.0, 225.0, 12));
        let got = through_branches(vec![outer, inner], 1e-9);
        assert_eq!(got.len(), 2, "{got:?}");
        for c in [up, down] {
            let round = |cv: &Polyline3| {
                cv.closed
                    && cv.points.len() == 25
                    && cv.points[0] == cv.points[24]
                    && cv
                        .points
                        .iter()
                        .all(|p| (p.distance(c) - 2f64.sqrt()).abs() < 1e-12)
            };
            assert!(got.iter().any(round), "the circle about {c}: {got:?}");
        }
    }

    #[test]
    fn a_turn_no_other_curve_passes_is_the_curves_own() {
        let a = open(vec![v(-2.0, 0.0), v(0.0, 0.0), v(0.0, 2.0)]);
        let b = open(vec![v(5.0, 0.0), v(6.0, 0.0), v(6.0, 1.0)]);
        let r = through_branches(vec![a.clone(), b.clone()], 1e-9);
        assert_eq!(r, vec![a, b]);
    }
}
