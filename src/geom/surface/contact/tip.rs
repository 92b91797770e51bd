//! The tips of a lens. Where a crossing leaves a tangent contact and another runs back into it
//! (z = y² + y·C(x) against z = 0, C a bump: the crossings y = 0 and y = −C bound a lens whose
//! tips narrow tangentially into the contact y = 0), the lens is thinner than any mesh cell
//! near its tips, and the seeding meshes' loop cuts across each tip. Refined, such a chord keeps
//! no midpoint (it refines onto one side or the other, beyond the chord's ends) and is left loose
//! (see `refine::assemble_loose`): a straight line across the lens, off both surfaces.
//!
//! Between the two sides the gap has an extremum across them, of the sign opposite to theirs
//! outside: a ridge, running to the tip, whose value there falls to zero. The ridge is walked
//! from the chord's middle to where its value comes within half the tolerance (bisected like a
//! contact's end), and at each of its nodes each side's crossing is found from it outwards, by
//! a bracket that cannot fall onto the other side. There the two sides are within the tolerance
//! of each other and of both surfaces, and the lens closes across its tip. Beyond the tip the
//! surfaces touch: the contact is traced from there (the seeds of the contact search that lie
//! beside a tip are taken for the crossings', which run in there nearly tangent).
//!
//! A tongue of a crossing leaves such a chord too: where one surface dips just through the
//! other at a small angle, the crossing can turn back in a loop narrower than the cells beyond
//! where the seed cuts across it. Its tip is an ordinary point of the crossing, where the
//! surfaces cross; the ridge there rises along its way (it does not flatten into a contact), and
//! its walk stalled short of the tip, which was closed by a chord 2.5e-5 short of the arc round
//! it and taken for a lens tip with a contact beyond. Tried first: the crossing marched on the
//! true surfaces from one end of the chord round to the other ([`around`]); the ridge is walked
//! where that march does not come back (along a lens's side it runs on into the contact).

use super::alongside::{between, march};
use super::branch::contact_curve_near;
use super::line::{clamp_bounded, delta, settle, speed_along, GapAt};
use super::{beside, near_any};
use crate::geom::mesh::Polyline3;
use crate::geom::surface::refine::{assemble, mid, Patch};
use glam::{DVec2, DVec3};

/// A parameter pair of `a` and the point there.
type Node = (DVec2, DVec3);

/// Most nodes one walk along a ridge makes.
const MAX_NODES: usize = 1 << 12;

/// `c` with its chords that were left loose (among `loose`) and are off the surfaces (`off`, the
/// distance to the farther, beyond `tol + chord_tol` at the chord's midpoint) carried round the
/// tongue of the crossing or across the tip of the lens each cuts, and the contacts traced from
/// the lenses' tips. A chord that does neither is left as it is: a seed curve that runs along a
/// contact and then off along a crossing leaving it has one too, and `regroup` takes such a
/// curve apart (cut there, it came back as a second copy of the crossing's end).
pub(crate) fn mend(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    off: &dyn Fn(DVec3) -> f64,
    c: Polyline3,
    loose: &[[DVec3; 2]],
    (tol, chord_tol): (f64, f64),
) -> (Polyline3, Vec<Polyline3>) {
    let pts = &c.points;
    let n = pts.len();
    let segs = if c.closed { n } else { n.saturating_sub(1) };
    let broken: Vec<usize> = (0..segs)
        .filter(|&k| {
            let (p, q) = (pts[k], pts[(k + 1) % n]);
            loose.contains(&[p, q]) && off(0.5 * (p + q)) > tol + chord_tol
        })
        .collect();
    if broken.is_empty() {
        return (c, Vec::new());
    }
    let mut points: Vec<DVec3> = Vec::with_capacity(n);
    let mut contacts: Vec<Polyline3> = Vec::new();
    let near = beside(a, tol, chord_tol);
    for k in 0..n {
        points.push(pts[k]);
        if !broken.contains(&k) {
            continue;
        }
        if let Some(fill) = around(a, gap, (pts, c.closed), k, (tol, chord_tol)) {
            points.extend(fill);
            continue;
        }
        let res = across_tip(a, gap, off, (pts, c.closed), k, (tol, chord_tol));
        let Some((fill, tip)) = res else {
            continue;
        };
        points.extend(fill);
        // The chord was about a seed cell long: the contact's step.
        let len = pts[k].distance(pts[(k + 1) % n]);
        if !near_any(gap(tip).point, &contacts, near) {
            contacts.extend(contact_curve_near(a, gap, tip, len, tol, chord_tol));
        }
    }
    let c = Polyline3 {
        points,
        closed: c.closed,
    };
    (c, contacts)
}

/// How far (in lengths of the chord) the march round a tongue goes from the chord before giving
/// up: a tongue thinner than the seeding cells all along its length is not followed farther.
const REACH: f64 = 16.0;

/// The points that replace the chord from `pts[k]` (P) to the next (Q) where it cuts across a
/// tongue of the crossing thinner than the seeding cells (the crossing turns back beyond the
/// chord, as a crossing at a small angle does where one surface dips just through the other):
/// the crossing marched on the true surfaces from P, the way the curve runs into it, round to
/// where it comes back to Q, densified within `chord_tol`. None where the march does not come
/// back to Q (a lens, whose sides run into a contact at its tip: see [`across_tip`]), or where
/// P or Q ends the curve (no way in, or out, to follow).
fn around(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    (pts, closed): (&[DVec3], bool),
    k: usize,
    (tol, chord_tol): (f64, f64),
) -> Option<Vec<DVec3>> {
    let n = pts.len();
    if !closed && (k == 0 || k + 2 >= n) {
        return None;
    }
    let (p, q) = (pts[k], pts[(k + 1) % n]);
    let (prev, next) = (pts[(k + n - 1) % n], pts[(k + 2) % n]);
    let up = a.project(p, None);
    let into = delta(a, a.project(prev, Some(up)), up);
    let (chord, away) = (p.distance(q), next - q);
    // A node past Q (beyond the plane across the curve there) is refused near it, so the march
    // ends on that plane, at Q; and one too far from the chord anywhere.
    let stop = |_: DVec2, _: DVec2, x: DVec3| {
        ((x - q).dot(away) > 0.0 && x.distance(q) <= 0.5 * chord) || x.distance(p) > REACH * chord
    };
    // Along the crossing's tangent at P, not the way the curve came in: a seed curve that ran
    // along a contact comes onto the crossing across it. The way in first; then the other.
    let t = crossing_tangent(gap, up)?;
    let t = if t.dot(into) < 0.0 { -t } else { t };
    let mut nodes = [t, -t].into_iter().find_map(|t| {
        let mut nodes = vec![(up, p)];
        nodes.extend(march(a, gap, (up, t), 0.25 * chord, tol, &stop));
        (nodes.len() >= 2 && nodes[nodes.len() - 1].1.distance(q) <= tol).then_some(nodes)
    })?;
    let last = nodes.len() - 1;
    nodes[last] = (a.project(q, Some(nodes[last].0)), q);
    let mid_of = |x: &Node, y: &Node| between(a, gap, x, y, tol);
    let fill = assemble(&nodes, false, |x| x.1, &mid_of, tol, chord_tol).points;
    let inner = fill.len().saturating_sub(1);
    Some(fill[1.min(inner)..inner].to_vec())
}

/// The unit tangent (in parameters) at `uv` of the zero set of the gap: across its gradient.
fn crossing_tangent(gap: &dyn Fn(DVec2) -> GapAt, uv: DVec2) -> Option<DVec2> {
    const D: f64 = 1e-7;
    let h = |d: DVec2| gap(uv + d).signed;
    let g = DVec2::new(
        h(DVec2::X * D) - h(-DVec2::X * D),
        h(DVec2::Y * D) - h(-DVec2::Y * D),
    );
    g.perp().try_normalize()
}

/// The points that replace the chord from `pts[k]` (P) to the next (Q) across the tip of the
/// lens it cuts: P's side on to the tip, then Q's side back to Q, each densified within
/// `chord_tol`, and the tip (the ridge's last node); None when the chord crosses no lens (its
/// ends not on either side of the gap's extremum along it) or the sides do not come within the
/// tolerance of each other.
fn across_tip(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    off: &dyn Fn(DVec3) -> f64,
    (pts, closed): (&[DVec3], bool),
    k: usize,
    (tol, chord_tol): (f64, f64),
) -> Option<(Vec<DVec3>, DVec2)> {
    let n = pts.len();
    let (p, q) = (pts[k], pts[(k + 1) % n]);
    let h = |uv: DVec2| gap(uv).signed;
    let up = a.project(p, None);
    let uq = a.project(q, Some(up));
    let w0 = delta(a, up, uq).try_normalize()?;
    let e0 = settle(a, &h, mid(a, up, uq), w0);
    let sign = h(e0).signum();
    let (to_p, to_q) = (delta(a, e0, up), delta(a, e0, uq));
    if !(h(e0).abs() > 0.5 * tol && to_p.dot(w0) < 0.0 && to_q.dot(w0) > 0.0) {
        return None;
    }
    // The tip lies the way the curve runs into P (or, backwards, out of Q).
    let into = if k > 0 || closed {
        delta(a, a.project(pts[(k + n - 1) % n], Some(up)), up)
    } else if k + 2 < n {
        delta(a, a.project(pts[k + 2], Some(uq)), uq)
    } else {
        return None;
    };
    let mut t = w0.perp();
    if t.dot(into) < 0.0 {
        t = -t;
    }
    let ridge = Ridge { a, gap, sign, tol };
    let side = if to_p.dot(t.perp()) > 0.0 { 1.0 } else { -1.0 };
    let (nodes, tip) = ridge.walk((e0, t), side, 0.5 * p.distance(q), [to_p, to_q]);
    let [np, nq] = nodes.last()?;
    if off(0.5 * (np.1 + nq.1)) > tol + chord_tol {
        return None;
    }
    let mid_of = |x: &Node, y: &Node| ridge.side_mid(x, y);
    let ps: Vec<Node> = std::iter::once((up, p))
        .chain(nodes.iter().map(|x| x[0]))
        .collect();
    let qs: Vec<Node> = nodes
        .iter()
        .rev()
        .map(|x| x[1])
        .chain(std::iter::once((uq, q)))
        .collect();
    let ps = assemble(&ps, false, |x| x.1, &mid_of, tol, chord_tol).points;
    let qs = assemble(&qs, false, |x| x.1, &mid_of, tol, chord_tol).points;
    let inner = qs.len().saturating_sub(1);
    let fill = ps.into_iter().skip(1).chain(qs.into_iter().take(inner));
    Some((fill.collect(), tip))
}

/// The gap's extremum between the two sides of a lens, of `sign`.
struct Ridge<'r> {
    a: &'r Patch<'r>,
    gap: &'r dyn Fn(DVec2) -> GapAt,
    sign: f64,
    tol: f64,
}

impl Ridge<'_> {
    fn h(&self, uv: DVec2) -> f64 {
        (self.gap)(uv).signed
    }

    /// Walks the ridge from `e0` along `t0` in steps of about `len` in space, to where its value
    /// comes within half the tolerance (the tip; the step is halved where it does, down to a
    /// hundredth of the tolerance): at each node the crossings on either side, P's (`to[0]` from
    /// `e0`) on the `side` of the walk's left, Q's (`to[1]`) on the other; and the last node.
    fn walk(
        &self,
        (e0, t0): (DVec2, DVec2),
        side: f64,
        len: f64,
        to: [DVec2; 2],
    ) -> (Vec<[Node; 2]>, DVec2) {
        let a = self.a;
        let (mut uv, mut t) = (e0, t0);
        let short = (self.tol * a.scale()).sqrt();
        let mut reach = to.map(|d| d.length());
        let mut nodes = Vec::new();
        let mut frac = 1.0;
        while nodes.len() < MAX_NODES {
            let Some(speed) = speed_along(a, uv, t) else {
                break;
            };
            let step = frac * len / speed;
            let ahead = uv + t * step;
            let cand = settle(a, &|x| self.h(x), ahead, t.perp());
            let moved = delta(a, uv, cand);
            let ok = clamp_bounded(a, ahead) == ahead
                && self.h(cand) * self.sign > 0.5 * self.tol
                && moved.dot(t) > 0.0
                && moved.length() <= 2.0 * step;
            // The ridge is found to about 1e-9 across: a step much shorter than √(tol·size)
            // would turn the direction along, and with it the search for the sides across (a
            // zigzag of 1e-5 where the lens is 4.5e-5 thick).
            let along = if moved.length() * speed >= short {
                moved.normalize_or_zero()
            } else {
                t
            };
            let across = along.perp() * side;
            let sides = ok
                .then(|| {
                    let p = self.crossing(cand, across, reach[0])?;
                    let q = self.crossing(cand, -across, reach[1])?;
                    Some([p, q])
                })
                .flatten();
            match sides {
                Some(s) => {
                    reach = s.map(|x| delta(a, cand, x.0).length());
                    nodes.push(s);
                    t = along;
                    uv = cand;
                    frac = (4.0 * frac).min(1.0);
                }
                None => {
                    frac *= 0.5;
                    if frac * len < 0.01 * self.tol {
                        break;
                    }
                }
            }
        }
        (nodes, uv)
    }

    /// The first zero of the gap from `uv` (on the ridge) along `dir`: samples from half `r`
    /// (in parameters) outwards, doubling, to the first of the other sign, then bisection; the
    /// bracket keeps it on this side of the ridge.
    fn crossing(&self, uv: DVec2, dir: DVec2, r: f64) -> Option<Node> {
        let a = self.a;
        let at = |s: f64| uv + dir * s;
        if r.is_nan() || r <= 0.0 {
            return None;
        }
        let (mut lo, mut hi) = (0.0, 0.5 * r);
        for _ in 0..64 {
            if hi > 1.0 || clamp_bounded(a, at(hi)) != at(hi) {
                return None;
            }
            let v = self.h(at(hi));
            if !v.is_finite() {
                return None;
            }
            if v * self.sign <= 0.0 {
                break;
            }
            (lo, hi) = (hi, 2.0 * hi);
        }
        // To the bracket's roundoff, not to a fraction of the tolerance: near the tip the gap
        // rises across a side as slowly as the lens is thin (|gap| ≤ tol/100 over 2e-7 across
        // where it is 4.5e-5 thick), and points anywhere in that band would zigzag.
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                break;
            }
            let v = self.h(at(m));
            if v == 0.0 {
                (lo, hi) = (m, m);
                break;
            }
            if v * self.sign > 0.0 {
                lo = m;
            } else {
                hi = m;
            }
        }
        let mut uv = at(0.5 * (lo + hi));
        a.normalise(&mut uv);
        let g = (self.gap)(uv);
        (g.dist <= self.tol).then_some((uv, g.point))
    }

    /// The point of a side between two of its points `x` and `y`: from the ridge across the
    /// chord's middle, outwards to that side.
    fn side_mid(&self, x: &Node, y: &Node) -> Option<Node> {
        let a = self.a;
        let across = delta(a, x.0, y.0).perp().try_normalize()?;
        let e = settle(a, &|x| self.h(x), mid(a, x.0, y.0), across);
        if self.h(e) * self.sign <= 0.0 {
            return None;
        }
        let to = delta(a, e, x.0);
        let dir = if to.dot(across) > 0.0 {
            across
        } else {
            -across
        };
        self.crossing(e, dir, to.dot(dir).abs())
    }
}
