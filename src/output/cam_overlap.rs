//! Overlap removal for the CAM profile: a cutter burns an edge twice when two entities share
//! it, so later open edges lose the parts that fixed outlines or earlier open edges cover.

use glam::DVec2;

use super::biarc::BulgeChain;
use super::drawing::bulge_arc;

/// Edges closer than this (drawing units) count as coincident.
pub(super) const EPS: f64 = 1e-6;

/// A line or circular arc, parameterized by s in [0, 1] from its start to its end.
#[derive(Clone, Copy, Debug)]
pub(super) enum Seg {
    Line {
        a: DVec2,
        b: DVec2,
    },
    /// Angle a0 + s·sweep (sweep signed: negative = clockwise).
    Arc {
        c: DVec2,
        r: f64,
        a0: f64,
        sweep: f64,
    },
}

impl Seg {
    pub(super) fn from_bulge(a: DVec2, b: DVec2, bulge: f64) -> Seg {
        match bulge_arc(a, b, bulge) {
            Some((c, r, a0, a1)) => Seg::Arc {
                c,
                r,
                a0,
                sweep: a1 - a0,
            },
            None => Seg::Line { a, b },
        }
    }

    pub(super) fn circle(c: DVec2, r: f64) -> Seg {
        Seg::Arc {
            c,
            r,
            a0: 0.0,
            sweep: std::f64::consts::TAU,
        }
    }

    fn at(&self, s: f64) -> DVec2 {
        match *self {
            Seg::Line { a, b } => a.lerp(b, s),
            Seg::Arc { c, r, a0, sweep } => {
                let t = a0 + sweep * s;
                c + DVec2::new(t.cos(), t.sin()) * r
            }
        }
    }

    fn length(&self) -> f64 {
        match *self {
            Seg::Line { a, b } => (b - a).length(),
            Seg::Arc { r, sweep, .. } => r * sweep.abs(),
        }
    }

    fn bbox(&self) -> (DVec2, DVec2) {
        match *self {
            Seg::Line { a, b } => (a.min(b), a.max(b)),
            // The arc's own box: its ends and the quarter-turn points inside its sweep (a
            // whole-circle box would make the nearly straight arcs of biarc chains, whose radii
            // are huge, overlap everything).
            Seg::Arc { c, r, a0, sweep } => {
                let (s0, e0) = (self.at(0.0), self.at(1.0));
                let (mut lo, mut hi) = (s0.min(e0), s0.max(e0));
                let (from, to) = if sweep > 0.0 {
                    (a0, a0 + sweep)
                } else {
                    (a0 + sweep, a0)
                };
                let quarter = std::f64::consts::FRAC_PI_2;
                let mut k = (from / quarter).ceil();
                while k * quarter < to {
                    let p = c + DVec2::from_angle(k * quarter) * r;
                    lo = lo.min(p);
                    hi = hi.max(p);
                    k += 1.0;
                }
                (lo, hi)
            }
        }
    }

    /// The bulge segment of the part s0..s1.
    pub(super) fn piece(&self, s0: f64, s1: f64) -> (DVec2, DVec2, f64) {
        let (a, b) = (self.at(s0), self.at(s1));
        match *self {
            Seg::Line { .. } => (a, b, 0.0),
            Seg::Arc { sweep, .. } => (a, b, (sweep * (s1 - s0) / 4.0).tan()),
        }
    }

    /// The parameter intervals of `self` that `other` covers (within EPS).
    fn covered_by(&self, other: &Seg) -> Vec<(f64, f64)> {
        match (*self, *other) {
            (Seg::Line { a, b }, Seg::Line { a: oa, b: ob }) => {
                let d = b - a;
                let len = d.length();
                if len == 0.0 {
                    return vec![];
                }
                let u = d / len;
                let off = |p: DVec2| (p - a).perp_dot(u).abs();
                if off(oa) > EPS || off(ob) > EPS {
                    return vec![];
                }
                let ta = (oa - a).dot(u) / len;
                let tb = (ob - a).dot(u) / len;
                // Exact ends (no widening): the uncovered rest must start where the cover ends.
                vec![(ta.min(tb), ta.max(tb))]
            }
            (
                Seg::Arc { c, r, a0, sweep },
                Seg::Arc {
                    c: oc,
                    r: or,
                    a0: oa0,
                    sweep: osweep,
                },
            ) => {
                if (c - oc).length() > EPS || (r - or).abs() > EPS {
                    return vec![];
                }
                let tau = std::f64::consts::TAU;
                let span = sweep.abs();
                // Both as CCW angular intervals [lo, lo + span].
                let lo = if sweep > 0.0 { a0 } else { a0 + sweep };
                let olo = if osweep > 0.0 { oa0 } else { oa0 + osweep };
                let ospan = osweep.abs();
                let start = (olo - lo).rem_euclid(tau);
                let mut out = Vec::new();
                for shift in [-tau, 0.0, tau] {
                    let (u0, u1) = (start + shift, start + shift + ospan);
                    if u1 >= 0.0 && u0 <= span {
                        let (s0, s1) = (u0 / span, u1 / span);
                        out.push(if sweep > 0.0 {
                            (s0, s1)
                        } else {
                            (1.0 - s1, 1.0 - s0)
                        });
                    }
                }
                out
            }
            _ => vec![],
        }
    }
}

/// Remove (lo, hi) from a sorted list of disjoint kept intervals.
fn subtract(keep: &mut Vec<(f64, f64)>, lo: f64, hi: f64) {
    let mut out = Vec::with_capacity(keep.len() + 1);
    for &(a, b) in keep.iter() {
        if hi <= a || lo >= b {
            out.push((a, b));
            continue;
        }
        if lo > a {
            out.push((a, lo));
        }
        if hi < b {
            out.push((hi, b));
        }
    }
    *keep = out;
}

/// An edge taking part in overlap removal.
pub(super) struct Edge {
    pub(super) seg: Seg,
    /// Open edges can be trimmed; fixed ones (closed outlines, circles) cannot.
    pub(super) open: bool,
    /// Position in drawing order: an open edge yields to every fixed edge and to earlier
    /// open edges.
    pub(super) order: usize,
    pub(super) keep: Vec<(f64, f64)>,
}

/// Sweep over x to find overlapping boxes, trimming open edges by what covers them.
pub(super) fn remove_overlaps(edges: &mut [Edge]) {
    let boxes: Vec<(DVec2, DVec2)> = edges.iter().map(|e| e.seg.bbox()).collect();
    let mut idx: Vec<usize> = (0..edges.len()).collect();
    idx.sort_by(|&i, &j| boxes[i].0.x.total_cmp(&boxes[j].0.x).then(i.cmp(&j)));
    let mut active: Vec<usize> = Vec::new();
    let mut cuts: Vec<(usize, f64, f64)> = Vec::new();
    for &i in &idx {
        let (lo, hi) = boxes[i];
        active.retain(|&j| boxes[j].1.x >= lo.x - EPS);
        for &j in &active {
            let (jlo, jhi) = boxes[j];
            if jlo.y > hi.y + EPS || jhi.y < lo.y - EPS {
                continue;
            }
            for (victim, cover) in [(i, j), (j, i)] {
                let (v, c) = (&edges[victim], &edges[cover]);
                let yields = v.open && (!c.open || c.order < v.order);
                if yields {
                    for (s0, s1) in v.seg.covered_by(&c.seg) {
                        cuts.push((victim, s0, s1));
                    }
                }
            }
        }
        active.push(i);
    }
    for (v, s0, s1) in cuts {
        subtract(&mut edges[v].keep, s0, s1);
    }
    for e in edges.iter_mut() {
        let len = e.seg.length();
        e.keep.retain(|(a, b)| (b - a) * len > EPS);
    }
}

pub(super) fn same_closed(a: &BulgeChain, b: &BulgeChain) -> bool {
    let n = a.points.len();
    if n != b.points.len() {
        return false;
    }
    let close = |p: DVec2, q: DVec2| (p - q).length() <= EPS;
    let bul = |i: usize, v: &BulgeChain| v.bulges.get(i).copied().unwrap_or(0.0);
    (0..n).any(|k| {
        let fwd = (0..n).all(|i| {
            close(a.points[i], b.points[(i + k) % n])
                && (bul(i, a) - bul((i + k) % n, b)).abs() <= 1e-9
        });
        // Reversed traversal: vertex i of a is vertex (k - i) of b, and segment i of a is
        // segment (k - i - 1) of b with the opposite bulge.
        let rev = (0..n).all(|i| {
            let j = (k + n - i) % n;
            let sj = (k + 2 * n - i - 1) % n;
            close(a.points[i], b.points[j]) && (bul(i, a) + bul(sj, b)).abs() <= 1e-9
        });
        fwd || rev
    })
}
