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

/// An end of an open curve: the curve, whether its last point, and the direction the curve
/// leaves that point in.
struct End {
    curve: usize,
    last: bool,
    point: DVec3,
    dir: DVec3,
}

/// Where the curves are cut and joined again: for each curve, the bends cut at (index, and
/// the slots of the pieces arriving there and leaving), and the slots of its start and end
/// if they are joined; which slot each slot is joined to.
struct Plan {
    cuts: Vec<Vec<(usize, usize, usize)>>,
    ends: Vec<[Option<usize>; 2]>,
    partner: Vec<usize>,
}

/// Every point where a curve turns by more than 15° and other curves turn or end too,
/// re-paired straightest first where that is straighter (see [`straighter`]): the curves are
/// cut there and the pieces joined again as re-paired. A turn at a point no other curve passes
/// or ends at is the curve's own (a coarse chord, a corner); an odd number of ways out there
/// (a lens's tip with a contact ending on it) is left as it is.
fn repair(curves: Vec<Polyline3>, tol: f64) -> Vec<Polyline3> {
    let bends = bends(&curves, tol);
    if bends.is_empty() {
        return curves;
    }
    let ends = ends(&curves, tol);
    let mut plan = Plan {
        cuts: vec![Vec::new(); curves.len()],
        ends: vec![[None; 2]; curves.len()],
        partner: Vec::new(),
    };
    let (mut bend_taken, mut end_taken) = (vec![false; bends.len()], vec![false; ends.len()]);
    for i in 0..bends.len() {
        if bend_taken[i] {
            continue;
        }
        let at = curves[bends[i].curve].points[bends[i].at];
        let here = |p: DVec3| p.distance(at) <= tol;
        let nb: Vec<usize> = (i..bends.len())
            .filter(|&j| !bend_taken[j] && here(curves[bends[j].curve].points[bends[j].at]))
            .collect();
        let ne: Vec<usize> = (0..ends.len())
            .filter(|&j| !end_taken[j] && here(ends[j].point))
            .collect();
        let dirs: Vec<DVec3> = (nb.iter().flat_map(|&j| bends[j].dirs))
            .chain(ne.iter().map(|&j| ends[j].dir))
            .collect();
        if dirs.len() < 4 || dirs.len() % 2 == 1 {
            continue;
        }
        let Some(pairs) = straighter(&dirs, nb.len()) else {
            continue;
        };
        let base = plan.partner.len();
        plan.partner.resize(base + dirs.len(), 0);
        for (x, y) in pairs {
            plan.partner[base + x] = base + y;
            plan.partner[base + y] = base + x;
        }
        for (g, &j) in nb.iter().enumerate() {
            bend_taken[j] = true;
            let b = &bends[j];
            plan.cuts[b.curve].push((b.at, base + 2 * g, base + 2 * g + 1));
        }
        for (g, &j) in ne.iter().enumerate() {
            end_taken[j] = true;
            plan.ends[ends[j].curve][usize::from(ends[j].last)] = Some(base + 2 * nb.len() + g);
        }
    }
    if plan.partner.is_empty() {
        return curves;
    }
    rejoin(curves, plan)
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

/// The ends of the open curves of `curves` (see [`End`]).
fn ends(curves: &[Polyline3], tol: f64) -> Vec<End> {
    let mut out = Vec::new();
    for (ci, c) in curves.iter().enumerate() {
        if c.closed || c.points.len() < 2 {
            continue;
        }
        for last in [false, true] {
            if let (point, Some(d)) = end(c, last, tol) {
                out.push(End {
                    curve: ci,
                    last,
                    point,
                    dir: -d,
                });
            }
        }
    }
    out
}

/// `idx` (indices into `dirs`) paired straightest first: the two most nearly opposite, then
/// the two most nearly opposite of the rest, …
fn greedy(dirs: &[DVec3], idx: &[usize]) -> Vec<(usize, usize)> {
    let straightness = |(x, y): (usize, usize)| -dirs[x].dot(dirs[y]);
    let mut all: Vec<(usize, usize)> = (0..idx.len())
        .flat_map(|x| (x + 1..idx.len()).map(move |y| (idx[x], idx[y])))
        .collect();
    all.sort_by(|&p, &q| straightness(q).total_cmp(&straightness(p)));
    let mut used = vec![false; dirs.len()];
    let mut pairs = Vec::with_capacity(idx.len() / 2);
    for (x, y) in all {
        if !used[x] && !used[y] {
            used[x] = true;
            used[y] = true;
            pairs.push((x, y));
        }
    }
    pairs
}

/// The directions leaving one point, the first 2·`passes` those of curves passing it (0 with
/// 1, 2 with 3, …), the rest those of curves ending there, paired straightest first if that
/// is straighter than as they are (the ends paired among themselves straightest first, as
/// [`join_through`] would): the joints' straightness, straightest first, compared in turn, by
/// more than rounding.
fn straighter(dirs: &[DVec3], passes: usize) -> Option<Vec<(usize, usize)>> {
    let straightness = |(x, y): (usize, usize)| -dirs[x].dot(dirs[y]);
    let all: Vec<usize> = (0..dirs.len()).collect();
    let pairs = greedy(dirs, &all);
    let mut now: Vec<f64> = (0..passes)
        .map(|g| (2 * g, 2 * g + 1))
        .chain(greedy(dirs, &all[2 * passes..]))
        .map(straightness)
        .collect();
    now.sort_by(|x, y| y.total_cmp(x));
    // Already straightest first.
    let new = pairs.iter().map(|&p| straightness(p));
    let first_apart = new.zip(now).find(|(n, o)| (n - o).abs() > 1e-9);
    first_apart.is_some_and(|(n, o)| n > o).then_some(pairs)
}

/// A closed curve's points end on its first point exactly, as closed curves do (its last point
/// was within the joining tolerance of it).
fn end_on_first(points: &mut [DVec3]) {
    if let (Some(&first), Some(last)) = (points.first(), points.len().checked_sub(1)) {
        points[last] = first;
    }
}

/// A piece of a curve cut at bends, with the slot (see [`Plan`]) at each end that is joined.
struct Piece {
    points: Vec<DVec3>,
    ends: [Option<usize>; 2],
}

/// The curves cut and joined again as `plan` says; the curves it leaves alone come first,
/// unchanged.
fn rejoin(curves: Vec<Polyline3>, plan: Plan) -> Vec<Polyline3> {
    let mut out = Vec::new();
    let mut pieces: Vec<Piece> = Vec::new();
    for ((c, mut ks), ends) in curves.into_iter().zip(plan.cuts).zip(plan.ends) {
        if ks.is_empty() && ends == [None, None] {
            out.push(c);
            continue;
        }
        ks.sort_unstable();
        pieces.extend(cut_at(c, &ks, ends));
    }
    // Where each slot is: the piece, and whether at its start.
    let mut slot_at = vec![(0, false); plan.partner.len()];
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
            let (next, at_start) = slot_at[plan.partner[s]];
            if seen[next] {
                break true;
            }
            (cur, fwd) = (next, at_start);
        };
        if closed {
            end_on_first(&mut pts);
        }
        out.push(Polyline3 {
            points: pts,
            closed,
        });
    }
    out
}

/// The curve `c` cut at the bends `ks` (index ascending, then the slots arriving and
/// leaving), its ends joined at the slots `ends` if open: each piece with its ends' slots.
fn cut_at(c: Polyline3, ks: &[(usize, usize, usize)], ends: [Option<usize>; 2]) -> Vec<Piece> {
    let p = c.points;
    let m = ks.len();
    let mut out = Vec::with_capacity(m + 1);
    if c.closed {
        // From each cut on to the next, the last round through the first point.
        for (i, &(k, _, on)) in ks.iter().enumerate() {
            let (k1, back1, _) = ks[(i + 1) % m];
            let points = if k1 > k {
                p[k..=k1].to_vec()
            } else {
                p[k..p.len() - 1].iter().chain(&p[..=k1]).copied().collect()
            };
            out.push(Piece {
                points,
                ends: [Some(on), Some(back1)],
            });
        }
        return out;
    }
    let mut from = (0, ends[0]);
    for &(k, back, on) in ks {
        out.push(Piece {
            points: p[from.0..=k].to_vec(),
            ends: [from.1, Some(back)],
        });
        from = (k, Some(on));
    }
    out.push(Piece {
        points: p[from.0..].to_vec(),
        ends: [from.1, ends[1]],
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

/// An end point of a curve and the direction the curve leaves it in there (none where the
/// curve does not leave it).
type CurveEnd = (DVec3, Option<DVec3>);

/// A curve's end (`last`) or start, and the direction it leaves the curve in there.
fn end(c: &Polyline3, last: bool, tol: f64) -> CurveEnd {
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
    // Each open curve's start and end, taken once: every pair of curves looks at them.
    let open: Vec<(usize, [CurveEnd; 2])> = (0..curves.len())
        .filter(|&i| !curves[i].closed && curves[i].points.len() >= 2)
        .map(|i| (i, [false, true].map(|last| end(&curves[i], last, tol))))
        .collect();
    let mut best: Option<(f64, Joint)> = None;
    for &(i, ends_i) in &open {
        for &(j, ends_j) in &open {
            for (ri, rj) in [(false, false), (false, true), (true, false), (true, true)] {
                if i == j && (ri || rj || curves[i].points.len() < 4) {
                    continue;
                }
                let ((pe, de), (ps, ds)) = (ends_i[usize::from(!ri)], ends_j[usize::from(rj)]);
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
        // Its own end on its start: closed.
        end_on_first(&mut curves[i].points);
        curves[i].closed = true;
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
        assert_the_two_circles(&got, up, down);
        assert!(got.iter().all(|cv| cv.points[0] == cv.points[24]));
    }

    /// `got` is the two closed circles of radius √2 about `up` and `down`, 24 chords each.
    fn assert_the_two_circles(got: &[Polyline3], up: DVec3, down: DVec3) {
        assert_eq!(got.len(), 2, "{got:?}");
        for c in [up, down] {
            let round = |cv: &Polyline3| {
                cv.closed
                    && cv.points.len() == 25
                    && cv
                        .points
                        .iter()
                        .all(|p| (p.distance(c) - 2f64.sqrt()).abs() < 1e-12)
            };
            assert!(got.iter().any(round), "the circle about {c}: {got:?}");
        }
    }

    #[test]
    fn one_open_curve_round_both_circles_becomes_the_two() {
        // From (−1, 0) round the circle about (0, 1), on there round the circle about
        // (0, −1) and back: it turns at (−1, 0), where it also begins and ends.
        let (up, down) = (v(0.0, 1.0), v(0.0, -1.0));
        let first = arc(up, 225.0, -135.0, 24);
        let second = arc(down, 135.0, 495.0, 24);
        let both = open(
            first
                .into_iter()
                .chain(second.into_iter().skip(1))
                .collect(),
        );
        let got = through_branches(vec![both], 1e-9);
        assert_the_two_circles(&got, up, down);
    }

    #[test]
    fn a_turn_no_other_curve_passes_is_the_curves_own() {
        let a = open(vec![v(-2.0, 0.0), v(0.0, 0.0), v(0.0, 2.0)]);
        let b = open(vec![v(5.0, 0.0), v(6.0, 0.0), v(6.0, 1.0)]);
        let r = through_branches(vec![a.clone(), b.clone()], 1e-9);
        assert_eq!(r, vec![a, b]);
    }
}
