//! From the traced boundary to loops on the surface: the marching grid's directed segments
//! chained into loops, crossings that step back along them dropped, and each loop evaluated on
//! the surface and densified within the chord tolerance (boundary points found across each
//! chord, or along a domain edge, or at a corner ahead on the target's extent edge).

use super::{Key, Tracer};
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

/// A traced boundary point: its parameters, which of them sit on a domain edge, and whether
/// it is a crossing lying off its grid edge ([`Tracer::untangle`]).
#[derive(Debug, Clone, Copy)]
struct Pt {
    uv: DVec2,
    pinned: [bool; 2],
    off: bool,
}

impl Tracer<'_, '_> {
    /// The boundary loops of the directed segments `segs`.
    pub(super) fn loops(&mut self, segs: &[(Key, Key)]) -> Vec<Polyline3> {
        self.chain(segs)
            .into_iter()
            .filter_map(|(pts, closed)| self.polyline(&pts, closed))
            .collect()
    }

    fn pt(&self, k: Key) -> Pt {
        let (uv, pinned_i, pinned_j) = match k {
            Key::Node(i, j) => (self.uv_of(i, j), Some(i), Some(j)),
            Key::H(_, j) => (self.cross[&k], None, Some(j)),
            Key::V(i, _) => (self.cross[&k], Some(i), None),
        };
        let n = self.cells();
        let edge = |x: Option<usize>, k: usize| {
            !self.periodic[k] && x.is_some_and(|x| x == 0 || x == n[k])
        };
        // A crossing's grid edge: the line it lies on and the span along the other direction.
        let off = match k {
            Key::Node(..) => false,
            Key::H(i, j) => self.off_edge(uv, 1, j, 0, i),
            Key::V(i, j) => self.off_edge(uv, 0, i, 1, j),
        };
        Pt {
            uv,
            pinned: [edge(pinned_i, 0), edge(pinned_j, 1)],
            off,
        }
    }

    /// Whether `uv` lies off the grid edge on line `i` of direction `k` from line `j` of
    /// direction `m` to the next.
    fn off_edge(&self, uv: DVec2, k: usize, i: usize, m: usize, j: usize) -> bool {
        let l = &self.lines;
        let x = self.wrap(k, i);
        let (a, b) = (l[m][j], l[m][(j + 1).min(l[m].len() - 1)]);
        uv[k] != l[k][x] && uv[k] != l[k][i] || uv[m] < a.min(b) || uv[m] > a.max(b)
    }

    /// The loop's points without crossings that step back along it. A node lying beyond the
    /// region's edge within the tolerance's reach (where the surfaces part tangentially, the
    /// gap stays under it for a while) is classified in the region, and the edge found from
    /// it along its grid edges lies behind it, off those edges: exact, but in the cell's
    /// order rather than the edge's, so the loop would run back and forth along the edge by
    /// that reach. Such a crossing is dropped where the loop turns back at it, and
    /// densifying fills the chord left from the points on either side.
    fn untangle(&self, pts: Vec<Pt>, closed: bool) -> Vec<Pt> {
        if pts.len() < 4 || !pts.iter().any(|p| p.off) {
            return pts;
        }
        let m = pts.len();
        let mut keep: Vec<Pt> = Vec::with_capacity(m);
        for i in 0..m {
            let b = pts[i];
            let prev = keep.last().copied().or(closed.then(|| pts[m - 1]));
            let first = keep.first().copied().unwrap_or(pts[0]);
            let next = (i + 1 < m).then(|| pts[i + 1]).or(closed.then_some(first));
            if let (true, Some(a), Some(c)) = (b.off, prev, next) {
                if self.delta(a.uv, b.uv).dot(self.delta(b.uv, c.uv)) < 0.0 {
                    continue;
                }
            }
            keep.push(b);
        }
        if keep.len() >= 3 {
            keep
        } else {
            pts
        }
    }

    /// Directed segments joined head to tail into loops (open chains where a loop does not
    /// close, which a consistent classification never leaves).
    fn chain(&self, segs: &[(Key, Key)]) -> Vec<(Vec<Pt>, bool)> {
        crate::geom::mesh::chain_directed(segs)
            .into_iter()
            .map(|(keys, closed)| {
                let pts = keys.into_iter().map(|k| self.pt(k)).collect();
                (self.untangle(pts, closed), closed)
            })
            .collect()
    }

    /// The loop on the surface, densified within the chord tolerance; None when it collapses
    /// (a domain edge that is a pole).
    fn polyline(&self, pts: &[Pt], closed: bool) -> Option<Polyline3> {
        let m = pts.len();
        let segs = if closed { m } else { m - 1 };
        let mut out: Vec<DVec3> = Vec::with_capacity(2 * m);
        for i in 0..m {
            out.push(self.eval(pts[i].uv));
            if i < segs {
                self.densify(pts[i], pts[(i + 1) % m], 0, &mut out);
            }
        }
        out.dedup_by(|x, y| x.distance(*y) <= self.tol);
        while out.len() > 1 && out[0].distance(out[out.len() - 1]) <= self.tol {
            out.pop();
        }
        (out.len() >= 3 || (!closed && out.len() >= 2)).then_some(Polyline3 {
            points: out,
            closed,
        })
    }

    /// The parameter step from `a` to `b`, the short way round a periodic direction.
    fn delta(&self, a: DVec2, b: DVec2) -> DVec2 {
        let mut d = b - a;
        for k in 0..2 {
            if self.periodic[k] {
                d[k] -= d[k].round();
            }
        }
        d
    }

    fn densify(&self, a: Pt, b: Pt, depth: u32, out: &mut Vec<DVec3>) {
        let (pa, pb) = (self.eval(a.uv), self.eval(b.uv));
        if depth >= 40 || pa.distance(pb) <= 2.0 * self.tol {
            return;
        }
        let d = self.delta(a.uv, b.uv);
        let mid = a.uv + 0.5 * d;
        let pinned = [a.pinned[0] && b.pinned[0], a.pinned[1] && b.pinned[1]];
        let m = if pinned[0] || pinned[1] {
            // Along a domain edge: the edge's own point, when it lies on the target.
            let mut q = mid;
            for k in 0..2 {
                if pinned[k] {
                    q[k] = a.uv[k];
                }
            }
            self.on(q).then_some(q)
        } else {
            self.across(mid, d)
        };
        let Some(m) = m.or_else(|| self.corner_between(a.uv, b.uv)) else {
            return;
        };
        let pm = self.eval(m);
        let chord = pb - pa;
        let off = (pm - pa).cross(chord).length() / chord.length();
        if off > self.chord_tol {
            let mp = Pt {
                uv: m,
                pinned,
                off: false,
            };
            self.densify(a, mp, depth + 1, out);
            out.push(pm);
            self.densify(mp, b, depth + 1, out);
        }
    }

    /// Where the chord from `a` to `b` found no boundary point across it, the corner ahead of
    /// an end lying on the target's extent edge, when there is one (an acute corner of the
    /// region at that edge, between grid lines: the loop's points on the region's other edge
    /// close in on it but the chords from the extent edge's last crossing never reach it).
    fn corner_between(&self, a: DVec2, b: DVec2) -> Option<DVec2> {
        let d = self.delta(a, b);
        let len = d.length();
        if len == 0.0 {
            return None;
        }
        let dir = d / len;
        let c = self
            .corner_ahead(a, -dir)
            .or_else(|| self.corner_ahead(b, dir))?;
        // Legs of a corner of 30° and more, seen from the chord.
        (self.delta(a, c).length() + self.delta(c, b).length() <= 4.0 * len).then_some(c)
    }

    /// The boundary point across the chord `mid ± d⊥`: the region lies left of the chord's
    /// direction `d`; searched outward up to the chord's length, then bisected.
    fn across(&self, mid: DVec2, d: DVec2) -> Option<DVec2> {
        let len = d.length();
        if len == 0.0 {
            return None;
        }
        let right = DVec2::new(d.y, -d.x) / len;
        let inside = self.on(mid);
        let dir = if inside { right } else { -right };
        let mut s = len / 16.0;
        while s <= len {
            let q = mid + dir * s;
            if self.on(q) != inside {
                let (lo, hi) = if inside { (mid, q) } else { (q, mid) };
                let mut p = self.edge(lo, hi);
                self.patch.normalise(&mut p);
                return Some(p);
            }
            s *= 2.0;
        }
        None
    }
}
