//! Intersection of any two curves in 3D: every root found, each classified CROSS, TANGENT or
//! OVERLAP (ZMOLD paper, SEEDS.md 000, with root isolation before any Newton step).
//!
//! Curves are cut into pieces (`piece.rs`): lines, arcs and rational Bézier spans.
//! Line/arc pairs use closed forms (`analytic`); a Bézier against a line or an arc becomes a
//! scalar polynomial in Bernstein form whose roots are isolated by subdivision (`implicit`);
//! Bézier against Bézier is box subdivision down to flat pieces, then Gauss–Newton
//! (`subdivide`). Results from all piece pairs are merged (points closer than `tol` are one
//! point), points inside an overlap are dropped, and the list is sorted by t1.
//!
//! Argument-order independence is by construction: the pair is always computed in one
//! canonical order (by kind, then by data) and the parameters swapped back.

mod analytic;
mod implicit;
mod subdivide;

use std::cmp::Ordering;

use glam::DVec3;
use smallvec::SmallVec;

use super::arc::Arc;
use super::bezier::Bez;
use super::bspline::BSpline;
use super::circle::Circle;
use super::curve::Curve;
use super::line::Line;
use super::piece::Piece;
use super::traits::ParamCurve;

/// The default tolerance, SPEC's GEOMTOL.
pub const GEOMTOL: f64 = 1e-9;

/// |sin| of the angle between the two tangents below which a hit is TANGENT.
pub(crate) const TANGENT_SIN: f64 = 1e-8;

/// How two curves meet at a hit.
#[derive(Clone, Debug, PartialEq)]
pub enum HitKind {
    /// The curves cross (tangents not parallel).
    Cross,
    /// The curves touch (tangents parallel, or a double root within tolerance).
    Tangent,
    /// The curves share a piece; it is given, running the direction of the first curve.
    /// The hit's `point`, `t1`, `t2` are at the start of that piece. (Boxed so that the
    /// common point hits stay small; `Hit::overlap` borrows it.)
    Overlap(Box<Curve>),
}

/// One intersection: the point, the public parameters on both curves and the kind.
#[derive(Clone, Debug, PartialEq)]
pub struct Hit {
    pub point: DVec3,
    pub t1: f64,
    pub t2: f64,
    pub kind: HitKind,
}

impl Hit {
    /// The shared piece of an OVERLAP hit.
    pub fn overlap(&self) -> Option<&Curve> {
        match &self.kind {
            HitKind::Overlap(c) => Some(c),
            _ => None,
        }
    }

    /// `CROSS`, `TANGENT` or `OVERLAP`.
    pub fn kind_name(&self) -> &'static str {
        match self.kind {
            HitKind::Cross => "CROSS",
            HitKind::Tangent => "TANGENT",
            HitKind::Overlap(_) => "OVERLAP",
        }
    }
}

/// A hit between two pieces in piece parameters (s on the first, u on the second).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct LHit {
    pub s: f64,
    pub u: f64,
    pub p: DVec3,
    pub kind: LKind,
    /// Set on the two simple roots flanking one extremum: merged, they are one tangency.
    pub twin: Option<u32>,
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum LKind {
    Cross,
    Tangent,
    /// The shared piece and the parameters (on the first, second piece) at its end.
    Overlap(Box<Piece>, f64, f64),
}

impl LHit {
    #[inline]
    pub fn new(s: f64, u: f64, p: DVec3, kind: LKind) -> LHit {
        LHit {
            s,
            u,
            p,
            kind,
            twin: None,
        }
    }
}

pub(crate) type LHits = SmallVec<[LHit; 4]>;

/// Where the closed forms put their hits: the piece-hit list of the general path, or, for a
/// pair of simple curves, the public hit list itself (their piece parameters are the public
/// ones), which spares an intermediate copy per hit.
pub(crate) trait Sink {
    fn put(&mut self, s: f64, u: f64, p: DVec3, kind: LKind);

    /// True when the hits should come in the order of the second piece's parameter (the
    /// caller's first curve is that piece): the closed forms put their points in the
    /// caller's order, so no hit is moved after it is written.
    #[inline(always)]
    fn by_u(&self) -> bool {
        false
    }
}

impl Sink for LHits {
    #[inline]
    fn put(&mut self, s: f64, u: f64, p: DVec3, kind: LKind) {
        self.push(LHit::new(s, u, p, kind));
    }
}

impl Sink for Vec<Hit> {
    #[inline]
    fn put(&mut self, s: f64, u: f64, p: DVec3, kind: LKind) {
        self.push(Hit {
            point: p,
            t1: s,
            t2: u,
            kind: hit_kind(kind),
        });
    }
}

/// The public list of a pair computed in swapped order: the second piece is the caller's
/// first curve. Overlap pieces still run along the piece computed first (`fix_overlaps`
/// turns them round).
struct Swapped<'a>(&'a mut Vec<Hit>);

impl Sink for Swapped<'_> {
    #[inline]
    fn put(&mut self, s: f64, u: f64, p: DVec3, kind: LKind) {
        self.0.put(u, s, p, kind);
    }

    #[inline(always)]
    fn by_u(&self) -> bool {
        true
    }
}

fn piece_to_curve(p: Piece) -> Curve {
    match p {
        Piece::Line(l) => Curve::Line(l),
        Piece::Arc(a) if a.is_full() => Curve::Circle(Circle { arc: a }),
        Piece::Arc(a) => Curve::Arc(a),
        Piece::Bez(b) => {
            let n = b.h.len();
            let deg = n - 1;
            let mut knots = vec![0.0; n];
            knots.extend(std::iter::repeat_n(1.0, n));
            Curve::BSpline(BSpline {
                degree: deg,
                ctrl: b.points().collect(),
                knots,
                weights: if b.rational {
                    Some(b.h.iter().map(|h| h.w).collect())
                } else {
                    None
                },
            })
        }
    }
}

/// Intersect two pieces, appending hits in piece parameters.
pub(crate) fn piece_pair(a: &Piece, b: &Piece, tol: f64, out: &mut LHits) {
    let start = out.len();
    match (a, b) {
        (Piece::Line(x), Piece::Line(y)) => analytic::line_line(x, y, tol, out),
        (Piece::Line(x), Piece::Arc(y)) => analytic::line_arc(x, y, tol, out),
        (Piece::Arc(x), Piece::Line(y)) => {
            analytic::line_arc(y, x, tol, out);
            swap_from(out, start);
        }
        (Piece::Arc(x), Piece::Arc(y)) => analytic::arc_arc(x, y, tol, out),
        (Piece::Bez(x), Piece::Line(y)) => implicit::bez_line(x, y, tol, out),
        (Piece::Bez(x), Piece::Arc(y)) => implicit::bez_arc(x, y, tol, out),
        (Piece::Line(_) | Piece::Arc(_), Piece::Bez(_)) => {
            piece_pair(b, a, tol, out);
            swap_from(out, start);
        }
        (Piece::Bez(x), Piece::Bez(y)) => subdivide::bez_bez(x, y, tol, out),
    }
}

/// Swap the roles of the two pieces for the hits from `start` on.
fn swap_from(out: &mut LHits, start: usize) {
    for h in &mut out[start..] {
        std::mem::swap(&mut h.s, &mut h.u);
        if let LKind::Overlap(piece, se, ue) = &mut h.kind {
            std::mem::swap(se, ue);
            // The shared piece runs along the first curve: reverse it if it ran along b.
            if *se < h.s {
                **piece = reverse_piece(piece);
                // Its start is now at the other end.
                let (s0, u0) = (h.s, h.u);
                h.s = *se;
                h.u = *ue;
                *se = s0;
                *ue = u0;
                h.p = piece.eval(0.0);
            }
        }
    }
}

fn reverse_piece(p: &Piece) -> Piece {
    match p {
        Piece::Line(l) => Piece::Line(Line { p0: l.p1, p1: l.p0 }),
        Piece::Arc(a) => {
            let end = a.eval(1.0);
            let r = Arc::from_parts(a.center, a.radius, -a.normal, 0.0, a.sweep);
            Piece::Arc(r.with_range(r.angle_of(end), a.sweep))
        }
        Piece::Bez(b) => {
            let mut h = b.h.clone();
            h.reverse();
            Piece::Bez(Bez {
                h,
                rational: b.rational,
            })
        }
    }
}

fn rank(c: &Curve) -> u8 {
    match c {
        Curve::Line(_) => 0,
        Curve::Circle(_) => 1,
        Curve::Arc(_) => 2,
        Curve::Polyline(_) => 3,
        Curve::Spline(_) => 4,
        Curve::BSpline(_) => 5,
        Curve::Ellipse(_) => 6,
    }
}

/// Lexicographic order of two runs of numbers (`total_cmp`, so NaN and -0 are ordered).
fn lex(a: &[f64], b: &[f64]) -> Ordering {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.total_cmp(y))
        .find(|o| o.is_ne())
        .unwrap_or_else(|| a.len().cmp(&b.len()))
}

/// A total order on curves: by kind, then by their defining numbers (for lines, circles and
/// arcs read in place: this runs for every pair, so it must cost next to nothing).
fn canonical_cmp(a: &Curve, b: &Curve) -> Ordering {
    let by_kind = rank(a).cmp(&rank(b));
    if by_kind != Ordering::Equal {
        return by_kind;
    }
    match (a, b) {
        (Curve::Line(x), Curve::Line(y)) => lex(&x.p0.to_array(), &y.p0.to_array())
            .then_with(|| lex(&x.p1.to_array(), &y.p1.to_array())),
        (Curve::Circle(x), Curve::Circle(y)) => arc_cmp(&x.arc, &y.arc),
        (Curve::Arc(x), Curve::Arc(y)) => arc_cmp(x, y),
        _ => {
            let mut fa: SmallVec<[f64; 16]> = SmallVec::new();
            let mut fb: SmallVec<[f64; 16]> = SmallVec::new();
            fingerprint(a, &mut fa);
            fingerprint(b, &mut fb);
            lex(&fa, &fb)
        }
    }
}

/// Arcs (and circles) by their defining numbers: centre, normal, radius, start, sweep. The
/// first number nearly always decides, so the rest is kept out of line.
#[inline(always)]
fn arc_cmp(x: &Arc, y: &Arc) -> Ordering {
    #[inline(never)]
    fn rest(x: &Arc, y: &Arc) -> Ordering {
        lex(&x.center.to_array()[1..], &y.center.to_array()[1..])
            .then_with(|| lex(&x.normal.to_array(), &y.normal.to_array()))
            .then_with(|| lex(&[x.radius, x.start, x.sweep], &[y.radius, y.start, y.sweep]))
    }
    x.center.x.total_cmp(&y.center.x).then_with(|| rest(x, y))
}

fn fingerprint(c: &Curve, out: &mut SmallVec<[f64; 16]>) {
    fn pt3(out: &mut SmallVec<[f64; 16]>, p: DVec3) {
        out.extend([p.x, p.y, p.z]);
    }
    match c {
        Curve::Line(l) => {
            pt3(out, l.p0);
            pt3(out, l.p1);
        }
        Curve::Circle(ci) => {
            pt3(out, ci.arc.center);
            pt3(out, ci.arc.normal);
            out.push(ci.arc.radius);
        }
        Curve::Arc(a) => {
            pt3(out, a.center);
            pt3(out, a.normal);
            out.extend([a.radius, a.start, a.sweep]);
        }
        Curve::Polyline(p) => {
            for v in &p.vertices {
                pt3(out, *v);
            }
            out.extend(p.bulges.iter().copied());
            out.push(p.closed as u8 as f64);
        }
        Curve::Spline(q) => {
            for s in &q.segments {
                pt3(out, s[0]);
                pt3(out, s[1]);
            }
            out.push(q.closed as u8 as f64);
        }
        Curve::BSpline(b) => {
            out.push(b.degree as f64);
            for v in &b.ctrl {
                pt3(out, *v);
            }
            out.extend(b.knots.iter().copied());
            if let Some(w) = &b.weights {
                out.extend(w.iter().copied());
            }
        }
        Curve::Ellipse(e) => {
            pt3(out, e.center);
            pt3(out, e.major);
            pt3(out, e.normal);
            out.extend([e.ratio, e.start, e.sweep]);
        }
    }
}

/// `(intersect a b)` / `(intersect-info a b)`: every hit of `a` and `b`, sorted by t1.
/// `tol` (GEOMTOL, default 1e-9): points closer than it are one point, curves farther apart
/// than it do not meet; a non-finite or non-positive `tol` means GEOMTOL. Parameters are the
/// curves' public t in [0, 1]; a hit at a closed curve's seam has t = 0. Swapping `a` and `b`
/// gives the same points with t1 and t2 swapped (overlap pieces then run along the new `a`).
pub fn intersect(a: &Curve, b: &Curve, tol: f64) -> Vec<Hit> {
    let mut out = Vec::new();
    intersect_into(a, b, tol, &mut out);
    out
}

/// As `intersect`, writing into `out` (cleared first) so a caller can reuse its allocation.
pub fn intersect_into(a: &Curve, b: &Curve, tol: f64, out: &mut Vec<Hit>) {
    // Only an overlap hit owns memory. (`clear` alone is a drop loop the compiler keeps out
    // of line: a call per pair.)
    if out.iter().any(|h| matches!(h.kind, HitKind::Overlap(_))) {
        out.clear();
    } else {
        // SAFETY: shortening is always sound; the point hits dropped here own nothing.
        unsafe { out.set_len(0) };
    }
    // One range test on the bits (a positive finite tol is 1..=MAX as an integer); the two
    // float tests became a long classification sequence.
    let tol = if tol.to_bits().wrapping_sub(1) < f64::MAX.to_bits() {
        tol
    } else {
        GEOMTOL
    };
    if canonical_cmp(a, b) != Ordering::Greater {
        if !simple_pair(a, b, tol, out) {
            by_pieces(a, b, tol, out);
        }
    } else if simple_pair(b, a, tol, &mut Swapped(out)) {
        fix_overlaps(a, b, out);
    } else {
        by_pieces(b, a, tol, out);
        for h in out.iter_mut() {
            std::mem::swap(&mut h.t1, &mut h.t2);
        }
        fix_overlaps(a, b, out);
    }
    // The closed forms put their points in order of t1, with a double root once and no
    // point inside an overlap. Several overlaps (arcs of one circle), a turned overlap
    // piece, or the swapped parameters of the general path need a sort.
    if out.len() > 2 || (out.len() == 2 && out[1].t1 < out[0].t1) {
        out.sort_by(|x, y| x.t1.total_cmp(&y.t1));
    }
}

/// Hits of (a, b) computed as (b, a), parameters already swapped: give each overlap piece
/// the direction of `a` (the caller then restores the order of t1).
fn fix_overlaps(a: &Curve, b: &Curve, out: &mut [Hit]) {
    for h in out.iter_mut() {
        if let HitKind::Overlap(c) = &mut h.kind {
            if let Some(rev) = reversed_if_against(c, a) {
                **c = rev;
                h.point = c.eval(0.0);
                h.t1 = a.closest_point(h.point).0;
                h.t2 = b.closest_point(h.point).0;
            }
        }
    }
}

/// The overlap piece `c` reversed when it runs against curve `a`.
fn reversed_if_against(c: &Curve, a: &Curve) -> Option<Curve> {
    let piece = match c {
        Curve::Line(l) => Piece::Line(*l),
        Curve::Arc(x) => Piece::Arc(*x),
        Curve::BSpline(bs) => {
            let s = &bs.ctrl;
            Piece::Bez(Bez::from_weighted(
                s,
                bs.weights.as_deref().unwrap_or(&vec![1.0; s.len()]),
            ))
        }
        _ => return None,
    };
    // Compare a's direction with the piece's at its middle.
    let (t, _) = a.closest_point(piece.eval(0.5));
    if a.deriv(t).dot(piece.deriv(0.5)) >= 0.0 {
        return None;
    }
    Some(piece_to_curve(reverse_piece(&piece)))
}

/// A hit with the key of the root pair it belongs to (two simple roots around one extremum).
type Keyed = (Hit, Option<u64>);

/// The arc (or full-circle arc) of a circle or an arc.
fn as_arc(c: &Curve) -> Option<&Arc> {
    match c {
        Curve::Circle(ci) => Some(&ci.arc),
        Curve::Arc(a) => Some(a),
        _ => None,
    }
}

/// Closed forms for two lines, circles or arcs, straight into `out` (their piece parameters
/// are the public ones). False when the pair is not of that kind. (In canonical order a
/// line always comes first.)
#[inline(always)]
fn simple_pair<S: Sink>(a: &Curve, b: &Curve, tol: f64, out: &mut S) -> bool {
    match (a, b) {
        (Curve::Line(x), Curve::Line(y)) => analytic::line_line(x, y, tol, out),
        (Curve::Line(x), _) if as_arc(b).is_some() => {
            analytic::line_arc(x, as_arc(b).unwrap(), tol, out)
        }
        _ => match (as_arc(a), as_arc(b)) {
            (Some(x), Some(y)) => analytic::arc_arc(x, y, tol, out),
            _ => return false,
        },
    }
    true
}

/// Any other pair: cut both curves into pieces, intersect the pieces whose boxes meet, and
/// merge the results.
#[inline(never)]
fn by_pieces(a: &Curve, b: &Curve, tol: f64, out: &mut Vec<Hit>) {
    let mut hits = LHits::new();
    let sa = a.spans();
    let sb = b.spans();
    let boxes_b: Vec<(DVec3, DVec3)> = sb.iter().map(|s| s.piece.hull_bbox()).collect();
    let mut keyed: Vec<Keyed> = Vec::new();
    let (a_closed, b_closed) = (a.is_closed(), b.is_closed());
    for (i, x) in sa.iter().enumerate() {
        let (alo, ahi) = x.piece.hull_bbox();
        for (j, (y, (blo, bhi))) in sb.iter().zip(&boxes_b).enumerate() {
            if (alo - tol).cmpgt(*bhi + tol).any() || (blo - tol).cmpgt(ahi + tol).any() {
                continue;
            }
            hits.clear();
            piece_pair(&x.piece, &y.piece, tol, &mut hits);
            let pair = ((i as u64) << 42) | ((j as u64) << 20);
            for h in hits.drain(..) {
                let twin = h.twin.map(|k| pair | k as u64);
                let mut hit = to_hit(h, x.t0, x.t1, y.t0, y.t1);
                // Hits at a closed curve's seam: t = 0 rather than 1.
                if hit.t1 >= 1.0 && a_closed {
                    hit.t1 = 0.0;
                }
                if hit.t2 >= 1.0 && b_closed {
                    hit.t2 = 0.0;
                }
                keyed.push((hit, twin));
            }
        }
    }
    keyed.sort_by(|x, y| x.0.t1.total_cmp(&y.0.t1));
    finish(&mut keyed, tol, out);
}

fn to_hit(h: LHit, a0: f64, a1: f64, b0: f64, b1: f64) -> Hit {
    let map = |t: f64, lo: f64, hi: f64| if t >= 1.0 { hi } else { lo + (hi - lo) * t };
    Hit {
        point: h.p,
        t1: map(h.s, a0, a1),
        t2: map(h.u, b0, b1),
        kind: hit_kind(h.kind),
    }
}

#[inline(always)]
fn hit_kind(k: LKind) -> HitKind {
    match k {
        LKind::Cross => HitKind::Cross,
        LKind::Tangent => HitKind::Tangent,
        LKind::Overlap(p, _, _) => overlap_kind(*p),
    }
}

/// Kept out of line: point hits are the hot path.
#[cold]
fn overlap_kind(p: Piece) -> HitKind {
    HitKind::Overlap(Box::new(piece_to_curve(p)))
}

/// Merge hits closer than `tol` (a merged pair of roots around one extremum is a tangency),
/// drop point hits lying on an overlap piece; `hits` is sorted by t1 and so is `out`.
fn finish(hits: &mut Vec<Keyed>, tol: f64, out: &mut Vec<Hit>) {
    let overlaps: Vec<Curve> = hits
        .iter()
        .filter_map(|(h, _)| match &h.kind {
            HitKind::Overlap(c) => Some((**c).clone()),
            _ => None,
        })
        .collect();
    let mut kept: Vec<Keyed> = Vec::with_capacity(hits.len());
    for (h, key) in hits.drain(..) {
        let is_point = !matches!(h.kind, HitKind::Overlap(_));
        if is_point
            && overlaps
                .iter()
                .any(|c| (c.closest_point(h.point).1 - h.point).length() <= tol)
        {
            continue;
        }
        if is_point {
            if let Some(k) = kept.iter_mut().find(|(k, _)| {
                !matches!(k.kind, HitKind::Overlap(_)) && (k.point - h.point).length() <= tol
            }) {
                let same_pair = key.is_some() && k.1 == key;
                if same_pair || h.kind == HitKind::Tangent {
                    k.0.kind = HitKind::Tangent;
                }
                continue;
            }
        }
        kept.push((h, key));
    }
    out.clear();
    out.extend(kept.into_iter().map(|(h, _)| h));
}

/// `(intersect a b near)`: the hit point closest to `near` (for an overlap, its closest
/// point to `near`), or `None` when there are no hits.
pub fn intersect_near(hits: &[Hit], near: DVec3) -> Option<DVec3> {
    hits.iter()
        .map(|h| match &h.kind {
            HitKind::Overlap(c) => c.closest_point(near).1,
            _ => h.point,
        })
        .min_by(|p, q| {
            (*p - near)
                .length_squared()
                .total_cmp(&(*q - near).length_squared())
        })
}

#[cfg(test)]
mod fast_param_tests {
    //! The hit parameters on circles and arcs use `fastmath::atan2`: check them against the
    //! straightforward reference (std atan2 of the hit point in the curve's frame).
    use super::*;
    use crate::geom::arc::norm_angle;

    use crate::geom::test_rng::Rng;

    /// The public parameter of the hit point `p` on `c` by the reference formula.
    fn reference_t(c: &Curve, p: DVec3, tol: f64) -> Option<f64> {
        let a = as_arc(c)?;
        let v = p - a.center;
        let ang = norm_angle(v.dot(a.y_axis).atan2(v.dot(a.x_axis)));
        a.param_of_angle(ang, tol / a.radius)
    }

    fn random_pair(r: &mut Rng, i: usize) -> Option<(Curve, Curve)> {
        let flat = |p: DVec3| DVec3::new(p.x, p.y, 0.0);
        let pair = match i % 4 {
            0 => {
                let (c, a) = (flat(r.pt(10.0)), flat(r.pt(10.0)));
                (
                    Curve::line(a, c + (c - a) * 0.3),
                    Curve::arc(c, 1.0 + r.f() * 3.0, r.f() * 7.0, r.f() * 7.0, None),
                )
            }
            1 => {
                let c = flat(r.pt(10.0));
                (
                    Curve::circle(c, 2.0 + r.f(), None),
                    Curve::circle(c + flat(r.pt(3.0)), 1.0 + r.f() * 2.0, None),
                )
            }
            2 => {
                let c = flat(r.pt(10.0));
                let n = if r.f() < 0.5 { DVec3::Z } else { -DVec3::Z };
                (
                    Curve::arc(c, 2.0 + r.f(), r.f() * 7.0, r.f() * 7.0, Some(n)),
                    Curve::arc(
                        c + flat(r.pt(3.0)),
                        1.0 + r.f() * 2.0,
                        r.f() * 7.0,
                        1.0,
                        None,
                    ),
                )
            }
            _ => {
                let (a, b) = (r.pt(10.0), r.pt(10.0));
                let ab = b - a;
                let m = (a + b) * 0.5;
                let perp = |n: DVec3| (n - ab * (n.dot(ab) / ab.length_squared())).normalize();
                let (n1, n2) = (perp(r.pt(1.0) - 0.5), perp(r.pt(1.0) - 0.5));
                let c1 = m + n1.cross(ab).normalize() * (r.f() * 4.0 - 2.0);
                let c2 = m + n2.cross(ab).normalize() * (r.f() * 4.0 - 2.0);
                (
                    Curve::arc(c1, (a - c1).length(), r.f() * 6.0, r.f() * 6.0, Some(n1)),
                    Curve::circle(c2, (a - c2).length(), Some(n2)),
                )
            }
        };
        match pair {
            (Ok(a), Ok(b)) => Some((a, b)),
            _ => None,
        }
    }

    #[test]
    fn hit_parameters_match_std_atan2_reference() {
        let mut r = Rng(0x9E3779B97F4A7C15);
        let tol = GEOMTOL;
        let mut checked = 0;
        for i in 0..20_000 {
            let Some((a, b)) = random_pair(&mut r, i) else {
                continue;
            };
            for (x, y) in [(&a, &b), (&b, &a)] {
                for h in intersect(x, y, tol) {
                    if matches!(h.kind, HitKind::Overlap(_)) {
                        continue;
                    }
                    for (c, t) in [(x, h.t1), (y, h.t2)] {
                        if let Some(rt) = reference_t(c, h.point, tol) {
                            assert!(
                                (t - rt).abs() <= 1e-12,
                                "{c:?} at {:?}: {t} vs {rt}",
                                h.point
                            );
                            checked += 1;
                        } else if as_arc(c).is_some() {
                            panic!("hit {h:?} not on {c:?} by the reference");
                        }
                    }
                }
            }
        }
        assert!(checked > 10_000, "only {checked} parameters checked");
    }
}
