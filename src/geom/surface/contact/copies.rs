//! Copies among the crossing pieces found beside a contact. The seeding meshes, at a CHORDTOL
//! as coarse as the contact's band, see the contact and a crossing close beside it as one
//! sawtooth of curves: several seed curves refine onto the same stretch of the crossing, and
//! one can run out along it, onto the contact and back. Cut off the contact and carried on,
//! such stretches lie along one another; joined end to end they double back over the crossing
//! (a detour), and those that join nothing stay beside it as extra curves. A stretch lying along
//! another piece is that piece's, not a new curve.

use super::super::refine::Patch;
use super::alongside::densified;
use super::line::GapAt;
use super::near_any;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

/// The open `pieces` with their stretches that lie along a longer piece cut out: each piece,
/// longest first, loses every run of two or more of its points within `r` of the longer pieces
/// (whole: a stretch cut out of one is still where it runs, and a shorter piece lying along that
/// stretch is as much a copy), and a piece all of whose points are, whatever their number, goes
/// whole; the rest stay as pieces of two points or more in its place. A single point within `r`
/// is kept: where two pieces meet end to end, or cross, only a point or so comes so near, and
/// [`super::alongside::join_ends`] makes the joints. Whether any was cut; where none was, the
/// pieces come back unchanged, in their order.
pub(super) fn without_copies(pieces: Vec<Polyline3>, r: f64) -> (Vec<Polyline3>, bool) {
    let mut order: Vec<usize> = (0..pieces.len()).collect();
    // Longest first (stable: ties in their order), so of two copies the fuller one stays.
    order.sort_by(|&i, &j| pieces[j].length().total_cmp(&pieces[i].length()));
    let mut kept: Vec<Option<Vec<Polyline3>>> = vec![None; pieces.len()];
    let mut cut = false;
    for (k, &i) in order.iter().enumerate() {
        let c = &pieces[i];
        let longer: Vec<&Polyline3> = order[..k].iter().map(|&j| &pieces[j]).collect();
        let runs = match c.closed || longer.is_empty() {
            true => None,
            false => off_others(c, &longer, r),
        };
        cut |= runs.is_some();
        kept[i] = Some(runs.unwrap_or_else(|| vec![c.clone()]));
    }
    (kept.into_iter().flatten().flatten().collect(), cut)
}

/// The runs of `c` left when its runs of two or more points within `r` of `others` are cut
/// out (none when all of its points are within `r`); None where nothing is cut.
fn off_others(c: &Polyline3, others: &[&Polyline3], r: f64) -> Option<Vec<Polyline3>> {
    let near = |p: DVec3| {
        others
            .iter()
            .any(|o| near_any(p, std::slice::from_ref(*o), r))
    };
    let on: Vec<bool> = c.points.iter().map(|p| near(*p)).collect();
    if on.iter().all(|x| *x) {
        return Some(Vec::new());
    }
    // A lone point near another piece is no copy: kept as off.
    let n = on.len();
    let copied: Vec<bool> = (0..n)
        .map(|k| on[k] && ((k > 0 && on[k - 1]) || (k + 1 < n && on[k + 1])))
        .collect();
    if !copied.contains(&true) {
        return None;
    }
    let runs = copied
        .split(|x| *x)
        .scan(0, |at, run| {
            let start = *at;
            *at += run.len() + 1;
            Some(start..start + run.len())
        })
        .filter(|run| run.len() >= 2)
        .map(|run| Polyline3 {
            points: c.points[run].to_vec(),
            closed: false,
        })
        .collect();
    Some(runs)
}

/// `piece` (a crossing's stretch of a refined seed curve) with the stretches where it turns back
/// over itself cut out: refined seed points can slide along the crossing past the next ones
/// (beyond what [`super::alongside::unfold_overshoots`] puts back, several points out of order:
/// θ 0.0248, 0.0218, 0.0238, 0.0251, 0.0069 on the patch ∩ cone crossing at CHORDTOL 1e-3), and
/// joined so the crossing doubles back on itself, 0.0127 too long. A point more than `tol`
/// behind the way the piece runs (its last step longer than `tol`: the points are placed only
/// to within that) starts a retrace, which ends at the first point past where it began; the
/// points between go, and the chord across is densified within `chord_tol` on the true surfaces.
/// A retrace that never ends (the piece running back from its start on) is left as it is.
pub(super) fn without_retraces(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    piece: Polyline3,
    tol: f64,
    chord_tol: f64,
) -> Polyline3 {
    let p = &piece.points;
    let mut kept: Vec<usize> = Vec::with_capacity(p.len());
    let mut across: Vec<usize> = Vec::new();
    let mut way: Option<DVec3> = None;
    let mut i = 0;
    while i < p.len() {
        let last = kept.last().map(|&k| p[k]);
        let ahead = |q: DVec3| match (last, way) {
            (Some(l), Some(w)) => (q - l).dot(w),
            _ => f64::INFINITY,
        };
        if ahead(p[i]) < -tol {
            if let Some(j) = (i + 1..p.len()).find(|&j| ahead(p[j]) > tol) {
                across.push(kept.len());
                i = j;
                continue;
            }
        }
        if let Some(l) = last {
            way = (p[i] - l)
                .try_normalize()
                .filter(|_| p[i].distance(l) > tol)
                .or(way);
        }
        kept.push(i);
        i += 1;
    }
    if across.is_empty() {
        return piece;
    }
    let mut points = Vec::with_capacity(p.len());
    for (n, &k) in kept.iter().enumerate() {
        if across.contains(&n) {
            let x = points.last().copied().unwrap_or(p[k]);
            let chord = densified(a, gap, &[x, p[k]], tol, chord_tol);
            points.extend_from_slice(&chord[1..chord.len() - 1]);
        }
        points.push(p[k]);
    }
    Polyline3 {
        points,
        closed: piece.closed,
    }
}

#[cfg(test)]
mod tests {
    use super::without_copies;
    use crate::geom::mesh::Polyline3;
    use glam::DVec3;

    fn line(xs: &[f64], y: f64) -> Polyline3 {
        Polyline3 {
            points: xs.iter().map(|&x| DVec3::new(x, y, 0.0)).collect(),
            closed: false,
        }
    }

    #[test]
    fn a_stretch_along_a_longer_piece_is_cut_out() {
        let r = 1e-3;
        // A copy inside the long piece (5e-4 beside it) goes; one overlapping its end keeps only
        // what runs on past it; one crossing it (a point near it) stays whole.
        let long = line(&[0.0, 0.1, 0.2, 0.3, 0.4, 0.5], 0.0);
        let inside = line(&[0.12, 0.15, 0.18], 5e-4);
        let over_end = line(&[0.35, 0.42, 0.48, 0.6, 0.7, 0.8], 2e-4);
        let across = Polyline3 {
            points: vec![
                DVec3::new(0.25, -0.1, 0.0),
                DVec3::new(0.25, 0.0, 0.0),
                DVec3::new(0.25, 0.1, 0.0),
            ],
            closed: false,
        };
        let pieces = vec![inside, long.clone(), over_end, across.clone()];
        let (out, cut) = without_copies(pieces, r);
        assert!(cut);
        assert_eq!(out.len(), 3, "{out:?}");
        assert_eq!(out[0], long);
        assert_eq!(out[1], line(&[0.6, 0.7, 0.8], 2e-4));
        assert_eq!(out[2], across);
    }

    #[test]
    fn pieces_apart_come_back_unchanged() {
        let pieces = vec![line(&[0.0, 0.1, 0.2], 0.0), line(&[0.2005, 0.3, 0.4], 0.0)];
        assert_eq!(without_copies(pieces.clone(), 1e-3), (pieces, false));
    }
}
