//! The seeds of the contact search on a mesh: its vertices (and edge midpoints) nearest the
//! other surface, less those that belong to a curve already found.

use super::{seed_gap, PARALLEL};
use crate::geom::mesh::{Mesh, Polyline3};
use glam::{DVec2, DVec3};
use std::cell::Cell;

/// The sine of the angle between the surfaces at a point, projected onto them from a start
/// (the parameters on each of a point near it, or the search grid), with those parameters.
pub(super) type Sine<'a> = dyn Fn(DVec3, Option<(DVec2, DVec2)>) -> (f64, (DVec2, DVec2)) + 'a;

/// The seeds of the contact search on a mesh: its vertices (and edge midpoints) nearest the
/// other surface, away from the curves already found.
pub(super) struct Lows<'a> {
    /// Each vertex's distance to the other surface (its mesh, or the plane).
    dist: &'a [f64],
    /// The meshes are within this of their surfaces; seeds are within 8 times it.
    seed_tol: f64,
    /// The sine of the angle between the surfaces at a point (about zero on a contact).
    sine: &'a Sine<'a>,
    /// Whether the triangles round each vertex meet both sides: the other surface crosses them.
    crossed: Vec<bool>,
    /// The triangles with a vertex within the gap (a section of a large mesh has few).
    near: Vec<[usize; 3]>,
    /// The points of the curves found, with `sine` there and the parameters it projected
    /// them to (asked once).
    found: Vec<(DVec3, Cell<Option<Angle>>)>,
}

/// A sine and the parameters on both surfaces it was taken at.
type Angle = (f64, (DVec2, DVec2));

impl<'a> Lows<'a> {
    pub(super) fn new(
        m: &Mesh,
        (dist, side): (&'a [f64], &[f64]),
        seed_tol: f64,
        curves: &[Polyline3],
        sine: &'a Sine<'a>,
    ) -> Self {
        let gap = seed_gap(seed_tol);
        let mut sides = vec![(false, false); m.vertices().len()];
        let mut near = Vec::new();
        for t in m.triangles() {
            let t = t.map(|i| i as usize);
            if !t.iter().any(|&i| dist[i] <= gap) {
                continue;
            }
            near.push(t);
            let s = t.map(|i| side[i]);
            let met = (s.iter().any(|x| *x > 0.0), s.iter().any(|x| *x < 0.0));
            for i in t {
                sides[i] = (sides[i].0 || met.0, sides[i].1 || met.1);
            }
        }
        Lows {
            dist,
            seed_tol,
            sine,
            crossed: sides.into_iter().map(|(p, n)| p && n).collect(),
            near,
            found: curves
                .iter()
                .flat_map(|c| c.points.iter())
                .map(|p| (*p, Cell::new(None)))
                .collect(),
        }
    }

    /// Whether a seed at `p` (of a mesh cell `reach` across, `dist` from the other surface)
    /// belongs to a curve found: one lies within four cells, and the other surface crosses the
    /// seed's cells (`crossed`: the seed is that crossing's), or the nearest curve point is on a
    /// contact, or the crossing there accounts for `dist` (the surfaces part at its angle). A
    /// seed nearer the other surface than the crossing beside it accounts for, by more than
    /// the meshes' error, is left in: a contact running a few cells from a crossing. So is one
    /// that only the meshes' error lets the crossing account for, where the surface is much
    /// flatter to the other at the seed than at the crossing: a contact beside a crossing at a
    /// coarse CHORDTOL, both on the other surface (the sheet's vertices on the contact and on
    /// the crossing both lie on the plane, dist 0, and 2·seed_tol exceeds half the height the
    /// crossing's slope gives over the distance between them).
    fn claimed(&self, p: DVec3, reach: f64, dist: f64, crossed: bool) -> bool {
        let nearest = self
            .found
            .iter()
            .map(|(q, t)| (q.distance(p), q, t))
            .filter(|x| x.0 <= 4.0 * reach)
            .min_by(|x, y| x.0.total_cmp(&y.0));
        nearest.is_some_and(|(r, q, t)| {
            if crossed {
                return true;
            }
            let (sine, uv) = t.get().unwrap_or_else(|| {
                let s = (self.sine)(*q, None);
                t.set(Some(s));
                s
            });
            if sine.is_nan() || sine <= PARALLEL {
                return true;
            }
            // Half the first-order gap, against curving back towards the other surface; the
            // seed (a vertex, or the midpoint of an edge) and the other mesh are each within
            // the seed tolerance of their surfaces.
            let explained = 0.5 * r * sine;
            if dist < explained - 2.0 * self.seed_tol {
                return false;
            }
            // Projected from the crossing's parameters: the seed is within four cells of it.
            dist >= explained || (self.sine)(p, Some(uv)).0 >= 0.5 * sine
        })
    }

    /// The vertices of `m` whose `dist` is within the gap and lowest among their neighbours
    /// (ties to the lower index), not claimed by `curves`: with the longest edge at each.
    pub(super) fn vertices(&self, m: &Mesh) -> Vec<(usize, f64)> {
        let va = m.vertices();
        let (dist, gap) = (self.dist, seed_gap(self.seed_tol));
        // Distances this close are the same on the meshes' scale.
        let tie = 1e-9 * self.seed_tol;
        // One pass over the edges near the other surface, with no neighbour lists: a vertex
        // stays a candidate while every neighbour is farther.
        let mut low: Vec<bool> = dist.iter().map(|d| *d <= gap).collect();
        let mut has_edge = vec![false; va.len()];
        let mut reach = vec![0.0f64; va.len()];
        for t in &self.near {
            for k in 0..3 {
                let (i, j) = (t[k], t[(k + 1) % 3]);
                if !(dist[i] <= gap || dist[j] <= gap) {
                    continue;
                }
                let l = va[i].distance(va[j]);
                for (x, y) in [(i, j), (j, i)] {
                    has_edge[x] = true;
                    reach[x] = reach[x].max(l);
                    // A vertex level with a crossed neighbour, uncrossed itself, stays a
                    // candidate: a contact a coarse cell from a crossing, both on the other
                    // surface (at CHORDTOL 0.05 the sheet's vertices on the contact and on the
                    // crossing both lie on the plane, their heights 1.4e-17 apart by rounding).
                    if low[x]
                        && !(dist[x] < dist[y] || (dist[x] == dist[y] && x < y))
                        && !(dist[x] - dist[y] <= tie && self.crossed[y] && !self.crossed[x])
                    {
                        low[x] = false;
                    }
                }
            }
        }
        (0..va.len())
            .filter(|&i| low[i] && has_edge[i])
            .filter(|&i| !self.claimed(va[i], reach[i], dist[i], self.crossed[i]))
            .map(|i| (i, reach[i]))
            .collect()
    }

    /// The midpoints of edges of `m` that come nearer the other surface (`to_b`, within the
    /// gap) than both their ends, not claimed by `curves`, with the edge's length: a long edge
    /// over a narrow surface (the rulings of a ruled cylinder over a plate narrower than they
    /// are long) has no vertex near the contact.
    pub(super) fn edges(&self, m: &Mesh, to_b: &dyn Fn(DVec3) -> f64) -> Vec<(DVec3, f64)> {
        let va = m.vertices();
        let dist = self.dist;
        let mut out: Vec<(DVec3, f64)> = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for t in m.triangles() {
            for k in 0..3 {
                let (i, j) = (t[k] as usize, t[(k + 1) % 3] as usize);
                if !seen.insert((i.min(j), i.max(j))) {
                    continue;
                }
                let l = va[i].distance(va[j]);
                let q = 0.5 * (va[i] + va[j]);
                let d = to_b(q);
                let crossed = self.crossed[i] || self.crossed[j];
                let near_b = d <= seed_gap(self.seed_tol) && d < dist[i].min(dist[j]);
                if near_b && !self.claimed(q, l, d, crossed) {
                    out.push((q, l));
                }
            }
        }
        out
    }
}
