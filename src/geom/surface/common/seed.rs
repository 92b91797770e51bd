//! Common regions narrower than the tracer's grid: a band of a profile's short flat lying on a
//! plane or a cylinder, 1/161 of the profile's parameter range, has no grid node with a
//! neighbour a quarter cell away on it, and no sample of the quick look on it.
//!
//! Such a region is found from where the gap vanishes: the local minima of the gap over a
//! coarse grid are followed downhill (golden-section searches along u and v in turn) to a point
//! lying on the other surface. Crossings and tangent contacts reach such points too; they are
//! told from a region by the region's width along u and along v, each measured from the point
//! to the edges found as the tracer finds them ([`super::edge`]: where the surfaces part
//! tangentially, extrapolated to the edge itself, so a contact line's "band" of gap below the
//! tolerance has no width). A region at least [`W_MIN`] of the surface's size wide both ways
//! gets grid lines at an eighth of its width across it in each direction where it is narrower
//! than two cells; the tracer then classifies and traces it as any other region.
//!
//! A region oblique to the parameter lines, or whose width changes along its length, is
//! followed from the seed and gets lines wherever it passes ([`super::walk`]).

use super::walk::{Seen, Station};
use super::{Tracer, N};
use glam::{DVec2, DVec3};

/// Cells per direction of the grid whose gap minima are followed.
const S: usize = 16;
/// A seed cell's width, in parameters.
pub(super) const SEED_CELL: f64 = 1.0 / S as f64;
/// Most minima (one per plateau) followed, smallest gap first.
const CANDIDATES: usize = 12;
/// The narrowest region looked for, as a fraction of the surface's size (its bounding box's
/// diagonal).
pub(super) const W_MIN: f64 = 1e-5;
/// The largest rise of the gap across a region's band, as a fraction of the tolerance
/// ([`Tracer::flat_between`]).
const FLAT: f64 = 1e-2;
/// Golden-section steps per search (0.618^48 ≈ 1e-10 of the cell searched).
const GOLDEN: usize = 48;

/// A region found around a seed: per direction, its extent when narrow enough to need finer
/// lines (None: at least two cells, or as wide as the search went).
type Band = [Option<(f64, f64)>; 2];

impl Tracer<'_, '_> {
    /// Looks for a region from the gap's minima (from `seeds` instead, points of the surface
    /// on the target, when given) and adds finer grid lines across each narrow one found,
    /// followed along its length ([`super::walk`]); the least and most levels of the regions
    /// found, None when none is found.
    pub(super) fn refine_narrow(&mut self, seeds: &[DVec3]) -> Option<(f64, f64)> {
        let starts = match seeds {
            [] => self.candidates(),
            _ => seeds.iter().map(|p| self.patch.project(*p, None)).collect(),
        };
        self.refine_from(starts, false)
    }

    /// [`Self::refine_narrow`] from the gap's minima, once the grid's nodes have seen a region
    /// (as classified now): a region narrower than a cell beside it (or anywhere else) may
    /// hold no node. Points lying in a region a quarter cell wide with a node of their cell in
    /// a region are passed over (the grid sees that one; a band 0.64 cells wide between two
    /// lines of nodes was passed over when the first test alone decided). Where bands found
    /// spread lines, the nodes on them are classified in the bands' corridors and round the
    /// nodes the regions seen hold ([`Seen`]).
    pub(super) fn refine_beside(&mut self) -> Option<(f64, f64)> {
        let starts = self.candidates();
        self.refine_from(starts, true)
    }

    fn refine_from(&mut self, starts: Vec<DVec2>, beside: bool) -> Option<(f64, f64)> {
        let mut bands: Vec<(Band, [Vec<Station>; 2])> = Vec::new();
        let (mut level, mut most) = (f64::INFINITY, f64::NEG_INFINITY);
        let seen = |t: &Self, bands: &[(Band, [Vec<Station>; 2])], uv: DVec2| {
            bands
                .iter()
                .any(|(b, w)| t.covers(b, uv) || (0..2).any(|k| t.walked(k, &w[k], uv)))
        };
        let quarter = DVec2::splat(0.25 / N as f64);
        for uv in starts {
            if seen(self, &bands, uv) {
                continue;
            }
            let Some(q) = self.descend(uv) else { continue };
            if seen(self, &bands, q) || beside && self.in_region_by(q, quarter) && self.cell_seen(q)
            {
                continue;
            }
            if let Some((b, l)) = self.band(q) {
                (level, most) = (level.min(l), most.max(l));
                let wide = b.iter().all(Option::is_none);
                bands.push((b, [self.walk(q, 0), self.walk(q, 1)]));
                if wide {
                    break;
                }
            }
        }
        // Nodes off the bands' corridors are left out only when every band is oblique (lines
        // spread across it both ways): a band along a parameter line, or a wide region, has no
        // corridor, and may lie where another band's spread lines cross. The regions the nodes
        // saw (beside) keep the cells round their nodes as theirs.
        let saw = beside.then(|| Seen::of(self));
        let mut oblique = true;
        for (b, walks) in &bands {
            for (k, e) in b.iter().enumerate() {
                oblique &= match *e {
                    Some((lo, hi)) if self.steady(&walks[k], lo, hi) => {
                        self.add_lines(k, lo, hi);
                        false
                    }
                    _ => self.spread_lines(k, &walks[k]),
                };
            }
        }
        if !oblique {
            self.spread = [Vec::new(), Vec::new()];
            self.corridors.clear();
        } else {
            self.seen = saw;
        }
        (!bands.is_empty()).then_some((level, most))
    }

    /// The nodes of an S × S grid where the gap is no larger than at any neighbour, smallest
    /// gap first (ties in grid order), one per plateau: neighbouring minima have equal gaps (a
    /// band along a ruling lies at one gap all along it), and taken one by one they would fill
    /// the list from one band and hide the next (a second flat at another level).
    fn candidates(&self) -> Vec<DVec2> {
        let at = |i: usize, j: usize| DVec2::new(i as f64 / S as f64, j as f64 / S as f64);
        let wrap = |k: usize, i: usize| if self.periodic[k] { i % S } else { i };
        let id = |i: usize, j: usize| j * (S + 1) + i;
        let mut gap = vec![f64::INFINITY; (S + 1) * (S + 1)];
        for j in 0..=S {
            for i in 0..=S {
                if wrap(0, i) == i && wrap(1, j) == j {
                    gap[id(i, j)] = self.gap_at(at(i, j)).unwrap_or(f64::INFINITY);
                }
            }
        }
        let step = |k: usize, i: usize, d: i64| -> Option<usize> {
            let x = i as i64 + d;
            if self.periodic[k] {
                Some(x.rem_euclid(S as i64) as usize)
            } else {
                (0..=S as i64).contains(&x).then_some(x as usize)
            }
        };
        // The up to eight neighbours of a node, wrapped across seams.
        let around = |i: usize, j: usize| {
            (-1..=1i64)
                .flat_map(move |dj| (-1..=1i64).map(move |di| (di, dj)))
                .filter(|&d| d != (0, 0))
                .filter_map(move |(di, dj)| Some((step(0, i, di)?, step(1, j, dj)?)))
        };
        let mut lowest = vec![false; gap.len()];
        for j in 0..=S {
            for i in 0..=S {
                let here = gap[id(i, j)];
                lowest[id(i, j)] = here.is_finite()
                    && wrap(0, i) == i
                    && wrap(1, j) == j
                    && around(i, j).all(|(a, b)| here <= gap[id(a, b)]);
            }
        }
        let mut order: Vec<(f64, usize, usize)> = (0..=S)
            .flat_map(|j| (0..=S).map(move |i| (i, j)))
            .filter(|&(i, j)| lowest[id(i, j)])
            .map(|(i, j)| (gap[id(i, j)], j, i))
            .collect();
        order.sort_by(|a, b| a.0.total_cmp(&b.0).then((a.1, a.2).cmp(&(b.1, b.2))));
        let mut taken = vec![false; gap.len()];
        let mut out = Vec::new();
        for (_, j, i) in order {
            if taken[id(i, j)] {
                continue;
            }
            out.push(at(i, j));
            if out.len() == CANDIDATES {
                break;
            }
            // The rest of its plateau is passed over.
            let mut stack = vec![(i, j)];
            taken[id(i, j)] = true;
            while let Some((a, b)) = stack.pop() {
                for (c, d) in around(a, b) {
                    if lowest[id(c, d)] && !taken[id(c, d)] {
                        taken[id(c, d)] = true;
                        stack.push((c, d));
                    }
                }
            }
        }
        out
    }

    /// Down the gap from `uv` to a point on the target, by golden-section searches within a
    /// seed cell along u and v in turn; None when the gap stops falling first.
    fn descend(&self, mut uv: DVec2) -> Option<DVec2> {
        let mut g = self.gap_at(uv)?;
        for _ in 0..4 {
            let before = g;
            for k in 0..2 {
                if self.on(uv) {
                    return Some(uv);
                }
                (uv, g) = self.golden(uv, k, g);
            }
            if g.is_nan() || g >= 0.5 * before {
                break;
            }
        }
        self.on(uv).then_some(uv)
    }

    /// The least gap found along direction `k` within a seed cell of `uv` (whose gap is `g`).
    pub(super) fn golden(&self, uv: DVec2, k: usize, g: f64) -> (DVec2, f64) {
        let h = 1.0 / S as f64;
        let (mut a, mut b) = (uv[k] - h, uv[k] + h);
        if !self.periodic[k] {
            (a, b) = (a.max(0.0), b.min(1.0));
        }
        let put = |x: f64| {
            let mut p = uv;
            p[k] = x;
            p
        };
        let f = |x: f64| self.gap_at(put(x)).unwrap_or(f64::INFINITY);
        let r = 0.618_033_988_749_895;
        let mut best = (uv, g);
        let (mut x1, mut x2) = (b - r * (b - a), a + r * (b - a));
        let (mut f1, mut f2) = (f(x1), f(x2));
        for _ in 0..GOLDEN {
            for (x, fx) in [(x1, f1), (x2, f2)] {
                if fx < best.1 {
                    best = (put(x), fx);
                }
            }
            if best.1 <= self.tol {
                break;
            }
            if f1 <= f2 {
                (b, x2, f2) = (x2, x1, f1);
                x1 = b - r * (b - a);
                f1 = f(x1);
            } else {
                (a, x1, f1) = (x1, x2, f2);
                x2 = a + r * (b - a);
                f2 = f(x2);
            }
        }
        best
    }

    /// The region around `q` (on the target), measured along u and v, and its level (the gap
    /// across it); None when it is narrower than [`W_MIN`] either way or its gap not flat (a
    /// crossing or a tangent contact, not a region).
    fn band(&self, q: DVec2) -> Option<(Band, f64)> {
        let (du, dv) = self.patch.derivs(q);
        let speed = [du.length(), dv.length()];
        let w_min = W_MIN * self.patch.scale();
        let mut out: Band = [None, None];
        let mut level = self.gap_at(q)?;
        for k in 0..2 {
            if speed[k].is_nan() || speed[k] <= 0.0 {
                return None;
            }
            let mut e = DVec2::ZERO;
            e[k] = 1.0;
            // A region w_min wide around q reaches w_min/2 at least one way: quick refusal of
            // most crossings before their edges are located.
            let d = 0.5 * w_min / speed[k];
            if !self.on(q + e * d) && !self.on(q - e * d) {
                return None;
            }
            let (hi, lo) = (self.reach(q, e), self.reach(q, -e));
            let (Some(hi), Some(lo)) = (hi, lo) else {
                level = level.min(self.least_beyond(q, e, [hi.is_none(), lo.is_none()]));
                continue;
            };
            if (hi - lo) * speed[k] < w_min {
                return None;
            }
            level = level.min(self.flat_between(q, k, lo, hi)?);
            if hi - lo < 2.0 / N as f64 {
                out[k] = Some((lo, hi));
            }
        }
        Some((out, level))
    }

    /// The least gap on the target at a half, one and two grid cells from `q` along `e`
    /// (`ways`: forward, backward) where the region goes on that far: the seed may lie where
    /// the gap rises to the region's edge, above the region's level.
    fn least_beyond(&self, q: DVec2, e: DVec2, ways: [bool; 2]) -> f64 {
        let mut least = f64::INFINITY;
        for (way, s) in ways.into_iter().zip([1.0, -1.0]) {
            for f in [0.5, 1.0, 2.0] {
                let p = q + e * (s * f / N as f64);
                if way && self.on(p) {
                    least = least.min(self.gap_at(p).unwrap_or(f64::INFINITY));
                }
            }
        }
        least
    }

    /// Whether the gap is flat across the middle of `lo..hi` (along direction `k` through `q`):
    /// it rises by at most [`FLAT`] of the tolerance between the points an eighth, a quarter
    /// and half of the way across. Two surfaces coinciding over a region keep one gap there,
    /// to rounding, at whatever level within the tolerance (0 when they coincide exactly, 0.3
    /// of the tolerance when held that far apart). Along a tangent contact the gap stays under
    /// the tolerance over a band too, but rises from its least as a power of the distance from
    /// the contact line: across the band of a square law it spans 0.56 of the tolerance
    /// between those points, of a sixth power 0.18, of a sixteenth 0.01.
    /// The least of those gaps (the region's level) when flat, None otherwise.
    pub(super) fn flat_between(&self, q: DVec2, k: usize, lo: f64, hi: f64) -> Option<f64> {
        let mut least = f64::INFINITY;
        let mut most = f64::NEG_INFINITY;
        for f in [0.125, 0.25, 0.5, 0.75, 0.875] {
            let mut p = q;
            p[k] = lo + f * (hi - lo);
            let g = self.gap_at(p)?;
            (least, most) = (least.min(g), most.max(g));
        }
        (most - least <= FLAT * self.tol).then_some(least)
    }

    /// Where the region ends from `q` in the unit direction `e` (its coordinate along `e`),
    /// or None when it goes on for two grid cells.
    fn reach(&self, q: DVec2, e: DVec2) -> Option<f64> {
        let k = if e.x != 0.0 { 0 } else { 1 };
        let mut inside = q;
        let mut d = 1e-9;
        while d <= 2.0 / N as f64 {
            let p = q + e * d;
            if !self.on(p) {
                return Some(self.edge(inside, p)[k]);
            }
            inside = p;
            d *= 2.0;
        }
        None
    }

    /// Whether a corner of the grid cell holding `uv` is a node in the region (as classified).
    fn cell_seen(&self, mut uv: DVec2) -> bool {
        self.patch.normalise(&mut uv);
        let [nu, nv] = self.cells();
        let at = |k: usize, n: usize| {
            let i = self.lines[k].partition_point(|x| *x <= uv[k]);
            i.saturating_sub(1).min(n - 1)
        };
        let (i, j) = (at(0, nu), at(1, nv));
        [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)]
            .iter()
            .any(|&(a, b)| self.node(a, b))
    }

    /// Whether `uv` lies within a seed cell of the band's narrow extents.
    fn covers(&self, b: &Band, uv: DVec2) -> bool {
        b.iter().enumerate().all(|(k, e)| {
            e.is_none_or(|(lo, hi)| {
                let mut d = uv[k] - 0.5 * (lo + hi);
                if self.periodic[k] {
                    d -= d.round();
                }
                d.abs() <= 0.5 * (hi - lo) + 1.0 / S as f64
            })
        })
    }

    /// Grid lines at an eighth of the extent `lo..hi` across it in direction `k`, reaching
    /// almost its width beyond either edge.
    fn add_lines(&mut self, k: usize, lo: f64, hi: f64) {
        let (c, e) = (0.5 * (lo + hi), hi - lo);
        let lines = &mut self.lines[k];
        for i in -8..8 {
            add_line(lines, self.periodic[k], c + e * (i as f64 + 0.5) / 8.0);
        }
        lines.sort_by(f64::total_cmp);
    }
}

/// Adds the grid line `x` (wrapped into the domain where periodic, dropped outside it where
/// not) unless one lies within rounding of it; the caller sorts the lines after.
/// The line added, if any.
pub(super) fn add_line(lines: &mut Vec<f64>, periodic: bool, mut x: f64) -> Option<f64> {
    if periodic {
        x = x.rem_euclid(1.0);
    } else if !(x > 0.0 && x < 1.0) {
        return None;
    }
    let new = lines.iter().all(|l| (l - x).abs() > 1e-12);
    if new {
        lines.push(x);
    }
    new.then_some(x)
}

/// The second pass at a higher level (see `trace`) traces only the parts of the region the
/// first pass did not reach.
impl Tracer<'_, '_> {
    /// The nodes in the region (as now classified) whose connected part (across grid lines and
    /// seams) holds no node of `first`.
    pub(super) fn new_parts(&self, first: &[bool]) -> Vec<bool> {
        let [nu, nv] = self.cells();
        let n = self.nodes.len();
        let mut parent: Vec<usize> = (0..n).collect();
        fn root(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        let join = |p: &mut Vec<usize>, a: usize, b: usize| {
            let (ra, rb) = (root(p, a), root(p, b));
            p[ra] = rb;
        };
        for j in 0..=nv {
            for i in 0..=nu {
                let at = j * (nu + 1) + i;
                if !self.nodes[at] {
                    continue;
                }
                for b in [self.idx(i, j), at + 1, at + nu + 1] {
                    let beside = b == at + 1 && i == nu || b == at + nu + 1 && j == nv;
                    if !beside && b != at && self.nodes[b] {
                        join(&mut parent, at, b);
                    }
                }
            }
        }
        let mut old = vec![false; n];
        // The same grid in both passes: `first` has a flag per node.
        for x in (0..n).filter(|&x| first[x] && self.nodes[x]) {
            let r = root(&mut parent, x);
            old[r] = true;
        }
        (0..n)
            .map(|x| self.nodes[x] && !old[root(&mut parent, x)])
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Surface, Target, Tracer};
    use crate::geom::curve::Curve;
    use glam::{DVec2, DVec3};
    use std::sync::Arc;

    #[test]
    fn a_wide_region_seen_from_its_rising_edge_takes_its_least_gap_as_its_level() {
        // A strip ruled from (-1, 1) down to a flat (0, 0)..(1, 0) and up to (2, 1), at z = 0
        // and 3, on the plane y = 0: the flat is a third of u wide, the strip's v all of it.
        // A seed on the left slope where the gap is 0.9 x tol (the point (-1 + t, 1 - t),
        // t = 1 - 0.9 tol, at u = t/3) sees the region run on for two cells both ways.
        let tol = 1e-9;
        let profile = |z: f64| {
            let pts = [(-1.0, 1.0), (0.0, 0.0), (1.0, 0.0), (2.0, 1.0)];
            let pts = pts.iter().map(|&(x, y)| DVec3::new(x, y, z)).collect();
            Arc::new(Curve::pline(pts, false, None).unwrap())
        };
        let s = Surface::ruled(profile(0.0), profile(3.0));
        let t = Target::Plane(DVec3::ZERO, DVec3::Y);
        let tr = Tracer::new(&s, &t, tol, 1e-6);
        let q = DVec2::new((1.0 - 0.9 * tol) / 3.0, 0.5);
        let g = tr.gap_at(q).unwrap();
        assert!((g - 0.9 * tol).abs() <= 1e-15, "seed's gap {g}");
        let (band, level) = tr.band(q).expect("a region");
        assert_eq!(band, [None, None], "wide both ways");
        assert_eq!(level, 0.0, "the flat's level");
    }
}
