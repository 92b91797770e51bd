//! SPLINE entities of the CAD profile, and why a spline with corners is written as a chain.
//!
//! A degree-2 spline can turn a corner where the curve passes through a control point: the
//! temple outline's hinge corners are doubled control points under simple knots (both legs
//! zero), `QuadSpline::to_bspline`'s form has a double knot at every joint. ezdxf and AutoCAD
//! draw such a corner sharp. LibreCAD 2.2 does not: it ignores the knot vector (it evaluates
//! every spline on uniform knots) and draws the curve as a smooth path through samples about
//! a centimetre of paper apart, so a corner inside one entity comes out as a round of that
//! size (probed with hand-made files: a doubled control point, a tripled one and a double
//! knot are all rounded; a corner where two entities meet is exact). So such a spline is
//! written as open SPLINE entities split at its corners, each ending exactly on the corner,
//! in the curve's order and direction: a chain that closes where the curve closes. The pieces
//! are cut out of the control points and knots without recomputing either, so each traces
//! its part of the curve exactly. Splines without a corner are written as one entity.

use glam::DVec3;

use super::drawing::Entity;
use super::dxf::{entity_head, plane_normal, DxfWriter};
use crate::geom::bspline::BSpline;
use crate::geom::quadspline::QuadSpline;

/// Write the spline `curve` of entity `e` (handle `e.handle`; extra pieces get handles from
/// `alloc`).
pub(crate) fn write_spline(
    w: &mut DxfWriter,
    e: &Entity,
    owner: u64,
    alloc: &mut impl FnMut() -> u64,
    curve: &BSpline,
    fit_points: &[DVec3],
    closed: bool,
) {
    let pieces = if fit_points.is_empty() {
        corner_pieces(curve)
    } else {
        // Fit points describe the whole curve: keep them with it.
        None
    };
    let Some(pieces) = pieces else {
        spline_groups(w, e.handle, owner, e, curve, fit_points, closed);
        return;
    };
    let mut first = true;
    for piece in pieces.iter().flat_map(straight_ends) {
        let h = if first { e.handle } else { alloc() };
        first = false;
        match piece {
            Piece::Line(a, b) => {
                entity_head(w, "LINE", h, owner, e);
                w.str(100, "AcDbLine");
                w.point(10, a);
                w.point(11, b);
            }
            Piece::Spline(c) => spline_groups(w, h, owner, e, &c, &[], false),
        }
    }
}

/// One entity of a spline written as a chain.
#[derive(Clone, Debug, PartialEq)]
pub enum Piece {
    Line(DVec3, DVec3),
    Spline(BSpline),
}

/// A corner piece as its straight runs at either end (LINEs) and the spline between them.
/// LibreCAD 2.2 leaves straight spans at the end of a degree-2 spline undrawn (the temple's
/// edges run straight into the hinge corners, and its butt is straight), and a piece ending
/// on a corner ends on a zero leg, which is a straight span too. Interior spans are kept.
pub fn straight_ends(piece: &BSpline) -> Vec<Piece> {
    let segments: Vec<[DVec3; 3]> = piece
        .to_beziers()
        .into_iter()
        .map(|(c, _)| [c[0], c[1], c[2]])
        .collect();
    let n = segments.len();
    let head = segments.iter().take_while(|s| straight(s)).count();
    if head == n {
        return vec![Piece::Line(segments[0][0], segments[n - 1][2])];
    }
    let tail = segments.iter().rev().take_while(|s| straight(s)).count();
    let mut out = Vec::with_capacity(3);
    if head > 0 {
        out.push(Piece::Line(segments[0][0], segments[head - 1][2]));
    }
    let middle = &segments[head..n - tail];
    let q = QuadSpline {
        points: middle.iter().map(|s| s[0]).collect(),
        closed: false,
        segments: middle.to_vec(),
    };
    out.push(Piece::Spline(
        q.to_bspline_simple_knots()
            .unwrap_or_else(|| q.to_bspline()),
    ));
    if tail > 0 {
        out.push(Piece::Line(segments[n - tail][0], segments[n - 1][2]));
    }
    out
}

/// Whether a quadratic Bézier is the straight line between its ends: its control on that
/// line and not beyond either end (a control outside would make the curve overshoot).
fn straight(s: &[DVec3; 3]) -> bool {
    let d = s[2] - s[0];
    let len2 = d.length_squared();
    if len2 == 0.0 {
        return false;
    }
    let t = (s[1] - s[0]).dot(d) / len2;
    let off = (s[1] - s[0]).cross(d).length() / len2.sqrt();
    (0.0..=1.0).contains(&t) && off <= 1e-9 * len2.sqrt()
}

fn spline_groups(
    w: &mut DxfWriter,
    handle: u64,
    owner: u64,
    e: &Entity,
    curve: &BSpline,
    fit_points: &[DVec3],
    closed: bool,
) {
    entity_head(w, "SPLINE", handle, owner, e);
    w.str(100, "AcDbSpline");
    let plane = plane_normal(&curve.ctrl);
    if let Some(n) = plane {
        w.point(210, n);
    }
    let mut flags = closed as i64;
    if plane.is_some() {
        flags |= 8;
    }
    if curve.weights.is_some() {
        flags |= 4;
    }
    w.int(70, flags);
    w.int(71, curve.degree as i64);
    w.int(72, curve.knots.len() as i64);
    w.int(73, curve.ctrl.len() as i64);
    w.int(74, fit_points.len() as i64);
    w.float(42, 1e-10);
    w.float(43, 1e-10);
    if !fit_points.is_empty() {
        w.float(44, 1e-10);
    }
    for k in &curve.knots {
        w.float(40, *k);
    }
    if let Some(ws) = &curve.weights {
        for x in ws {
            w.float(41, *x);
        }
    }
    for p in &curve.ctrl {
        w.point(10, *p);
    }
    for p in fit_points {
        w.point(11, *p);
    }
}

/// The pieces of a non-rational degree-2 spline split at its corners, or `None` when it has
/// none (or is of another kind: only degree 2 puts corners on control points this way).
pub fn corner_pieces(curve: &BSpline) -> Option<Vec<BSpline>> {
    if curve.degree != 2 || curve.weights.is_some() {
        return None;
    }
    let (ctrl, knots) = (&curve.ctrl, &curve.knots);
    let n = ctrl.len();
    let (lo, hi) = (knots[2], knots[n]);
    let interior = |u: f64| u > lo && u < hi;
    // Cheap test first: most splines have neither a repeated control point nor a double knot.
    let doubled = (1..n - 1).any(|c| ctrl[c] == ctrl[c + 1]);
    let double_knot = (3..n).any(|a| knots[a] == knots[a + 1] && interior(knots[a]));
    if !doubled && !double_knot {
        return None;
    }

    // A doubled control point under a simple knot is the same corner as a double knot with
    // the point once more (inserting that knot adds a copy of the point and changes nothing
    // else), so make every candidate a double knot.
    let (mut ctrl, mut knots) = (ctrl.clone(), knots.clone());
    let mut c = 1;
    while c + 2 < ctrl.len() {
        let u = knots[c + 2];
        let simple = knots[c + 1] < u && u < knots[c + 3];
        if ctrl[c] == ctrl[c + 1] && simple && interior(u) {
            ctrl.insert(c + 1, ctrl[c]);
            knots.insert(c + 2, u);
            c += 2;
        } else {
            c += 1;
        }
    }

    // At a double knot knots[a] = knots[a + 1] the curve passes through ctrl[a - 1]; it is a
    // corner when the tangents on either side point different ways.
    let n = ctrl.len();
    let mut splits = Vec::new();
    for a in 3..n {
        let u = knots[a];
        let double = knots[a + 1] == u && knots[a - 1] < u && knots[a + 2] > u;
        if double && interior(u) && turns(&ctrl, a - 1) {
            splits.push(a);
        }
    }
    if splits.is_empty() {
        return None;
    }
    let mut pieces = Vec::with_capacity(splits.len() + 1);
    // Each piece: the control points from one corner to the next, and the knots between
    // them with the corner's knot raised to multiplicity 3 (clamped) at a cut end.
    let mut start: Option<usize> = None;
    for end in splits.iter().copied().map(Some).chain([None]) {
        let (c0, k0) = start.map_or((0, 0), |a| (a - 1, a));
        let (c1, k1) = end.map_or((n - 1, knots.len() - 1), |a| (a - 1, a + 1));
        let mut kv = Vec::with_capacity(k1 - k0 + 3);
        if let Some(a) = start {
            kv.push(knots[a]);
        }
        kv.extend_from_slice(&knots[k0..=k1]);
        if let Some(a) = end {
            kv.push(knots[a]);
        }
        pieces.push(BSpline::new(2, ctrl[c0..=c1].to_vec(), Some(kv), None).ok()?);
        start = end;
    }
    Some(pieces)
}

/// Whether the curve turns a corner at control point `j` (a point it passes through): the
/// incoming direction is the last non-zero leg before it, the outgoing the first after it.
fn turns(ctrl: &[DVec3], j: usize) -> bool {
    let back = ctrl[..j]
        .iter()
        .rev()
        .map(|p| ctrl[j] - *p)
        .find(|d| *d != DVec3::ZERO);
    let ahead = ctrl[j + 1..]
        .iter()
        .map(|p| *p - ctrl[j])
        .find(|d| *d != DVec3::ZERO);
    let (Some(a), Some(b)) = (back, ahead) else {
        return false;
    };
    let scale = a.length() * b.length();
    a.dot(b) <= 0.0 || a.cross(b).length() > 1e-9 * scale
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::traits::ParamCurve;

    fn p(x: f64, y: f64) -> DVec3 {
        DVec3::new(x, y, 0.0)
    }

    fn ends(piece: &Piece) -> (DVec3, DVec3) {
        match piece {
            Piece::Line(a, b) => (*a, *b),
            Piece::Spline(c) => (c.ctrl[0], *c.ctrl.last().unwrap()),
        }
    }

    fn samples(piece: &Piece) -> Vec<DVec3> {
        (0..=400)
            .map(|i| {
                let t = i as f64 / 400.0;
                match piece {
                    Piece::Line(a, b) => a.lerp(*b, t),
                    Piece::Spline(c) => c.eval(t),
                }
            })
            .collect()
    }

    /// The chain's pieces lie on the curve and cover it, end to start in order.
    fn traces_the_same(curve: &BSpline, chain: &[Piece]) {
        // Sampled densely and at every knot, so the polyline keeps the corners.
        let (lo, hi) = curve.domain();
        let mut ts: Vec<f64> = (0..=20000).map(|i| i as f64 / 20000.0).collect();
        ts.extend(
            curve
                .knots
                .iter()
                .map(|u| ((u - lo) / (hi - lo)).clamp(0.0, 1.0)),
        );
        ts.sort_by(f64::total_cmp);
        let dense: Vec<DVec3> = ts.iter().map(|t| curve.eval(*t)).collect();
        // Distance to the polyline through the samples (they are not evenly spaced).
        let near = |q: DVec3, set: &[DVec3]| {
            set.windows(2)
                .map(|w| {
                    let d = w[1] - w[0];
                    let t = if d == DVec3::ZERO {
                        0.0
                    } else {
                        ((q - w[0]).dot(d) / d.length_squared()).clamp(0.0, 1.0)
                    };
                    q.distance(w[0] + d * t)
                })
                .fold(f64::MAX, f64::min)
        };
        let mut all = Vec::new();
        for piece in chain {
            for q in samples(piece) {
                assert!(near(q, &dense) < 1e-4, "{q} off the curve");
                all.push(q);
            }
        }
        for i in 0..=400 {
            let q = curve.eval(i as f64 / 400.0);
            assert!(near(q, &all) < 0.05, "{q} not covered");
        }
        for w in chain.windows(2) {
            assert_eq!(ends(&w[0]).1, ends(&w[1]).0, "chain broken");
        }
        assert_eq!(ends(&chain[0]).0, curve.ctrl[0]);
        assert_eq!(ends(chain.last().unwrap()).1, *curve.ctrl.last().unwrap());
    }

    fn chain(curve: &BSpline) -> Vec<Piece> {
        corner_pieces(curve)
            .unwrap()
            .iter()
            .flat_map(straight_ends)
            .collect()
    }

    #[test]
    fn doubled_control_point_corner_is_split_there() {
        // Simple knots; (10, 0) doubled: a right-angle corner.
        let ctrl = vec![
            p(0.0, 0.0),
            p(10.0, 0.0),
            p(10.0, 0.0),
            p(10.0, 10.0),
            p(0.0, 10.0),
        ];
        let knots = vec![0.0, 0.0, 0.0, 0.2, 0.7, 1.0, 1.0, 1.0];
        let curve = BSpline::new(2, ctrl, Some(knots), None).unwrap();
        let pieces = corner_pieces(&curve).unwrap();
        // The curve's own control points and knots, the corner's knot raised to a clamped end.
        assert_eq!(pieces.len(), 2);
        assert_eq!(
            pieces[0].ctrl,
            vec![p(0.0, 0.0), p(10.0, 0.0), p(10.0, 0.0)]
        );
        assert_eq!(pieces[0].knots, vec![0.0, 0.0, 0.0, 0.2, 0.2, 0.2]);
        assert_eq!(pieces[1].ctrl[..2], [p(10.0, 0.0), p(10.0, 0.0)]);
        assert_eq!(pieces[1].knots, vec![0.2, 0.2, 0.2, 0.7, 1.0, 1.0, 1.0]);
        // The zero legs at the corner are straight spans: lines up to and away from it.
        let c = chain(&curve);
        assert_eq!(c[0], Piece::Line(p(0.0, 0.0), p(10.0, 0.0)));
        assert!(matches!(c[1], Piece::Line(a, _) if a == p(10.0, 0.0)));
        assert!(matches!(&c[2], Piece::Spline(s) if s.ctrl.windows(2).all(|w| w[0] != w[1])));
        assert_eq!(c.len(), 3);
        traces_the_same(&curve, &c);
    }

    #[test]
    fn double_knot_corner_is_split_and_smooth_double_knots_are_not() {
        // QuadSpline::to_bspline's form: every joint a double knot; only (10, 0) turns.
        let ctrl = vec![
            p(0.0, 0.0),
            p(5.0, 0.0),
            p(10.0, 0.0),
            p(10.0, 5.0),
            p(10.0, 10.0),
            p(10.0, 15.0),
            p(5.0, 20.0),
        ];
        let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0];
        let curve = BSpline::new(2, ctrl, Some(knots), None).unwrap();
        let pieces = corner_pieces(&curve).unwrap();
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].ctrl, vec![p(0.0, 0.0), p(5.0, 0.0), p(10.0, 0.0)]);
        assert_eq!(pieces[0].knots, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
        assert_eq!(pieces[1].ctrl[0], p(10.0, 0.0));
        let c = chain(&curve);
        // Straight up to (10, 10), where the curve bends away: a line, then the spline.
        assert_eq!(c[0], Piece::Line(p(0.0, 0.0), p(10.0, 0.0)));
        assert_eq!(c[1], Piece::Line(p(10.0, 0.0), p(10.0, 10.0)));
        assert_eq!(c.len(), 3);
        traces_the_same(&curve, &c);
    }

    #[test]
    fn smooth_splines_and_other_kinds_stay_whole() {
        let smooth = BSpline::new(
            2,
            vec![
                p(0.0, 0.0),
                p(5.0, 0.0),
                p(10.0, 0.0),
                p(15.0, 0.0),
                p(20.0, 5.0),
            ],
            Some(vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]),
            None,
        )
        .unwrap();
        assert_eq!(corner_pieces(&smooth), None);
        // A doubled point on a straight run is no corner.
        let straight = BSpline::new(
            2,
            vec![
                p(0.0, 0.0),
                p(5.0, 0.0),
                p(5.0, 0.0),
                p(10.0, 0.0),
                p(10.0, 5.0),
            ],
            None,
            None,
        )
        .unwrap();
        assert_eq!(corner_pieces(&straight), None);
        let cubic = BSpline::new(
            3,
            vec![p(0.0, 0.0), p(10.0, 0.0), p(10.0, 0.0), p(10.0, 10.0)],
            None,
            None,
        )
        .unwrap();
        assert_eq!(corner_pieces(&cubic), None);
    }

    #[test]
    fn closed_outline_with_corners_becomes_a_closed_chain() {
        // A closed simple-knot outline starting on one corner with another inside, as the
        // temple's hinge butt: edge lines, the curved part, the butt as one line.
        let ctrl = vec![
            p(0.0, -2.0),
            p(0.0, -2.0),
            p(50.0, -2.0),
            p(100.0, 0.0),
            p(50.0, 2.0),
            p(0.0, 2.0),
            p(0.0, 2.0),
            p(0.0, -2.0),
            p(0.0, -2.0),
        ];
        let curve = BSpline::new(2, ctrl, None, None).unwrap();
        assert_eq!(corner_pieces(&curve).unwrap().len(), 2);
        let c = chain(&curve);
        assert_eq!(c.last(), Some(&Piece::Line(p(0.0, 2.0), p(0.0, -2.0))));
        assert_eq!(
            c.iter().filter(|x| matches!(x, Piece::Spline(_))).count(),
            1
        );
        traces_the_same(&curve, &c);
    }
}
