//! Surfaces that coincide over a region, found on the true surfaces whatever their kinds and
//! meshes: a ruled surface and a piece of itself, a Coons patch and a sub-patch, two sweeps of
//! overlapping profiles along one path, a revolved profile lying partly on a cylinder or a
//! sphere. Their intersection is that region, returned as its boundary loops, closed, as the
//! analytic pairs ([`super::coincide`]) and coplanar regions ([`super::overlap`]) give theirs.
//!
//! A quick look first: samples of each surface are projected onto the other (Newton, as in
//! [`super::refine`]); when none lies within the tolerance there is no common region. Otherwise
//! the region is traced in the parameter domain of the surface that lies more on the other:
//! its grid nodes are classified (on the other surface, with a neighbour on it too, so a node
//! where the surfaces merely cross or touch along a line is not a region), the domain's own
//! edges give the boundary pieces of that surface lying on the other, and marching squares give
//! the rest (the other surface's boundary, or where the two part). Every boundary point is
//! found by bisection of "lies on the other surface" along a grid edge, so it lies on both
//! surfaces within the tolerance, then carried back to where the gap beyond it extrapolates to
//! zero ([`edge`]: where the surfaces part tangentially the threshold lies √(2·tol·R) past the
//! edge); the loops are then densified within the chord tolerance.
//!
//! A region narrower than a quarter of a grid cell (1/128 of the parameter range) holds no
//! node; it is looked for ([`seed`]) and gets finer grid lines across it: from the samples
//! lying on the other surface when some did but no node lies in any region; from the gap's
//! minima over a 16 × 16 grid when no sample did, and beside the regions the nodes see (a
//! narrow flat beside a wide one, or one under a cell wide between the nodes); from the
//! section's curves in a plane section, where the surface meets the plane around a curve's
//! middle point. Still not seen: a region narrower than [`seed::W_MIN`] of the surface's size
//! either way, one whose gap minimum is not among that grid's twelve smallest or not reached
//! from them within a sixteenth of the range, one at least a quarter cell wide sharing a grid
//! cell with a node of a region the nodes see (taken for that region), and in a section one
//! no curve's middle point lies in or beside.

mod edge;
mod outline;
mod outside;
mod seed;
mod target;
mod threshold;
mod walk;

pub(crate) use outside::{flat_on_plane, outside_common, outside_plane_region};
use target::{on_samples, sample_count, Target};

use super::hits::point_in_polygon;
use super::kinds::Surface;
use super::refine::Patch;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};
use std::cell::Cell;
use std::collections::HashMap;

/// Where two surfaces coincide.
#[derive(Debug, Clone)]
pub(crate) enum Overlap {
    /// The common region's boundary loops, closed.
    Loops(Vec<Polyline3>),
    /// Everywhere, and the common region has no boundary (two equal spheres or tori).
    Everywhere,
}

/// Grid cells per parameter direction when tracing a region.
const N: usize = 32;
/// Samples per direction in the quick look.
const K: usize = 12;
/// How far to either side of a grid edge (in parameters, a 312th of a cell) its region edge is
/// looked for when a crossing may run along it: off the crossing by far more than the
/// tolerance allows, near enough that a curved region edge is straight across the two lines.
const OFF_LINE: f64 = 1e-4;
/// The rounding of a gap, relative to the surface's size and distance from the origin, kept
/// off the tolerance where the tracer tests it (a thousand times a double's).
const ROUNDING: f64 = 1e-13;
/// How far from a curve's middle point (as a fraction of the surface's size) the surfaces must
/// still coincide for the curve to lie in their common region: as [`super::beside`]'s probes.
const PROBE: f64 = 1e-4;

/// The region where `a` and `b` coincide: in closed form for the analytic pairs
/// ([`super::coincide`]), traced on the true surfaces when a free-form kind is involved.
pub(crate) fn overlap(a: &Surface, b: &Surface, tol: f64, chord_tol: f64) -> Option<Overlap> {
    super::coincide::coincident(a, b, tol, chord_tol)
        .or_else(|| common_region(a, b, tol, chord_tol))
}

/// Whether the kind is one the analytic code cannot decide coincidence for.
fn free_form(s: &Surface) -> bool {
    matches!(
        s,
        Surface::Ruled(_) | Surface::Revolve(_) | Surface::Sweep(_) | Surface::Coons(_)
    )
}

/// The region where `a` and `b` coincide, on the true surfaces; None when they share no region
/// (or neither is a free-form kind: the analytic pairs are decided in closed form).
pub(crate) fn common_region(a: &Surface, b: &Surface, tol: f64, chord_tol: f64) -> Option<Overlap> {
    if !(free_form(a) || free_form(b)) {
        return None;
    }
    let (ta, tb) = (Target::of(a), Target::of(b));
    let (hits_b, least_b, most_b) = on_samples(a, &tb, tol);
    let (hits_a, least_a, most_a) = on_samples(b, &ta, tol);
    let (on_a, on_b) = (hits_a.len(), hits_b.len());
    if on_a == 0 && on_b == 0 {
        // No sample lies on the other surface: a region, if any, is narrower than the samples'
        // spacing; it is looked for from where the gap vanishes, in each free-form domain.
        return [(a, &tb), (b, &ta)]
            .into_iter()
            .filter(|(s, _)| free_form(s))
            .find_map(|(s, t)| trace(s, t, tol, chord_tol, None, &[]));
    }
    // Trace in the domain of the one lying more on the other (a plane region has none).
    let a_first = !matches!(a, Surface::Plane(_))
        && (matches!(b, Surface::Plane(_)) || on_b * sample_count(b) >= on_a * sample_count(a));
    let (s, t) = if a_first { (a, &tb) } else { (b, &ta) };
    let levels = (least_a.min(least_b), most_a.max(most_b));
    // The samples lying on the other surface are points of the region, whatever its width.
    let hits: Vec<DVec3> = hits_a.into_iter().chain(hits_b).collect();
    trace(s, t, tol, chord_tol, Some(levels), &hits)
}

/// The part of `s` lying in the plane through `p` with unit normal `n`, as its boundary loops;
/// None when no region of it lies in the plane. Given `seeds` (points of `s` in the plane: a
/// mesh section's), the region is looked for from them alone.
pub(crate) fn in_plane(
    s: &Surface,
    (p, n): (DVec3, DVec3),
    seeds: &[DVec3],
    tol: f64,
    chord_tol: f64,
) -> Option<Vec<Polyline3>> {
    match s {
        Surface::Plane(r) => {
            let flat = r.normal.cross(n).length() <= 1e-12
                && r.boundary.iter().all(|q| n.dot(*q - p).abs() <= tol);
            flat.then(|| {
                vec![Polyline3 {
                    points: r.boundary.clone(),
                    closed: true,
                }]
            })
        }
        Surface::Sphere(_) | Surface::Cylinder(_) => None,
        _ => {
            let t = Target::Plane(p, n);
            // No sample in the plane: a region, if any, is narrower than their spacing.
            let level = match seeds {
                [] => {
                    let (hits, least, most) = on_samples(s, &t, tol);
                    (!hits.is_empty()).then_some((least, most))
                }
                _ => None,
            };
            match trace(s, &t, tol, chord_tol, level, seeds)? {
                Overlap::Loops(l) => Some(l),
                Overlap::Everywhere => None,
            }
        }
    }
}

/// A key of the marching grid: a node, or the crossing on a horizontal (u) or vertical (v)
/// grid edge starting at a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Node(usize, usize),
    H(usize, usize),
    V(usize, usize),
}

/// A grid edge along the domain's edge: its nodes in counter-clockwise order and its key.
type SideEdge = ((usize, usize), (usize, usize), Key);

struct Tracer<'a, 'b> {
    patch: Patch<'a>,
    periodic: [bool; 2],
    target: &'b Target<'b>,
    tol: f64,
    /// The region's gap and its rounding: a gap no higher is the region's own (see
    /// [`edge`]: only above it do the surfaces part).
    flat: f64,
    /// The part of `flat` that is rounding (above the region's level).
    rounding: f64,
    chord_tol: f64,
    /// The grid's lines in u and in v, from 0 to 1: N cells each, with finer lines added
    /// around a narrow region ([`seed`]).
    lines: [Vec<f64>; 2],
    nodes: Vec<bool>,
    cross: HashMap<Key, DVec2>,
    /// The lines spread across oblique or narrowing bands, per direction, sorted, and where
    /// those bands pass ([`walk`]): where two spread lines cross far from every band, the node
    /// is not classified (out of the region).
    spread: [Vec<f64>; 2],
    corridors: Vec<walk::Corridor>,
    /// Where the nodes saw regions before bands beside them spread lines ([`walk::Seen`]).
    seen: Option<walk::Seen>,
    /// How far past its threshold the last power-law fit's first sample stood ([`edge`]):
    /// the next fit's search for its first sample starts there.
    rise: Cell<Option<f64>>,
}

/// Traces the region of `s` lying on `t`, whose gap over the region is `level` (None: not
/// known, the region narrower than the quick look's samples, looked for by [`seed`], from
/// `seeds` when given, points of `s` on `t`). Where the samples met `t` (`seeds`) but no grid
/// node lies in the region, the region is narrower than the grid's cells: looked for from them.
/// Where nodes do lie in a region, narrower ones beside it are looked for from the gap's minima
/// ([`Tracer::refine_beside`]), and the grid classified again when one is found.
///
/// The region's edge is taken where the gap rises half the tolerance above its level: as
/// far inside the tolerance as the level allows, so that where the surfaces part across a
/// crease the edge found lies within half the tolerance over the slope of the true edge, while
/// surfaces held 0.9 of the tolerance apart still coincide (SPEC §4: farther apart than it
/// they do not meet). At most the whole tolerance less a margin for rounding, so the boundary
/// points found by bisection lie within it.
///
/// `level` is the least and the most gap where the surfaces were seen to meet. When the most
/// lies above the edge threshold, a region may sit at a higher level than the least (two
/// flats, one on a plane and one 0.9 of the tolerance off it): the grid is classified again
/// at the whole tolerance, and each part of the region so found that holds no node of the
/// first is traced at that threshold, the first's loops kept as they were.
fn trace(
    s: &Surface,
    t: &Target,
    tol: f64,
    chord_tol: f64,
    level: Option<(f64, f64)>,
    seeds: &[DVec3],
) -> Option<Overlap> {
    let mut tr = Tracer::new(s, t, tol, chord_tol);
    let size = tr.patch.scale() + tr.eval(DVec2::splat(0.5)).length();
    let within = (tol - ROUNDING * size).max(0.5 * tol);
    tr.tol = within;
    tr.flat = ROUNDING * size;
    tr.rounding = ROUNDING * size;
    let (mut least, mut most) = match level {
        Some(l) => l,
        None => tr.refine_narrow(seeds)?,
    };
    // The edge lies where the gap rises half the tolerance above the region's level.
    let edge_at = |least: f64| (least + 0.5 * tol).min(within);
    tr.tol = edge_at(least);
    tr.flat = least + ROUNDING * size;
    tr.classify();
    if level.is_some() {
        // Regions narrower than the grid's cells: beside those its nodes see, or from the
        // samples that met `t` when the nodes see none (none there: no region).
        tr.tol = within;
        let narrow = if tr.nodes.contains(&true) {
            tr.refine_beside()
        } else if seeds.is_empty() {
            None
        } else {
            Some(tr.refine_narrow(seeds)?)
        };
        if let Some((l, m)) = narrow {
            (least, most) = (least.min(l), most.max(m));
        }
        tr.tol = edge_at(least);
        tr.flat = least + ROUNDING * size;
        if narrow.is_some() {
            tr.classify();
        }
    }
    let segs = tr.segments();
    let first = tr.nodes.clone();
    let mut loops = tr.loops(&segs);
    if most > tr.tol && tr.tol < within {
        tr.tol = within;
        tr.cross.clear();
        tr.classify();
        tr.nodes = tr.new_parts(&first);
        let segs = tr.segments();
        loops.extend(tr.loops(&segs));
        tr.nodes = first;
    }
    if !loops.is_empty() {
        return Some(Overlap::Loops(loops));
    }
    let all = segs.is_empty() && tr.nodes.iter().all(|&x| x);
    (all && tr.boundaryless()).then_some(Overlap::Everywhere)
}

impl<'a, 'b> Tracer<'a, 'b> {
    fn new(s: &'a Surface, target: &'b Target<'b>, tol: f64, chord_tol: f64) -> Self {
        let patch = Patch::new(s);
        let periodic = patch.periodic();
        let uniform: Vec<f64> = (0..=N).map(|i| i as f64 / N as f64).collect();
        Tracer {
            patch,
            periodic,
            target,
            tol,
            flat: 0.0,
            rounding: 0.0,
            chord_tol,
            lines: [uniform.clone(), uniform],
            nodes: Vec::new(),
            cross: HashMap::new(),
            spread: [Vec::new(), Vec::new()],
            corridors: Vec::new(),
            seen: None,
            rise: Cell::new(None),
        }
    }
}

impl Tracer<'_, '_> {
    /// Cells in each direction.
    fn cells(&self) -> [usize; 2] {
        [self.lines[0].len() - 1, self.lines[1].len() - 1]
    }

    fn uv_of(&self, i: usize, j: usize) -> DVec2 {
        DVec2::new(self.lines[0][i], self.lines[1][j])
    }

    /// The smaller of the two cells either side of line `i` in direction `k` (one at a domain
    /// edge, the wrapped one across a seam).
    fn cell_near(&self, k: usize, i: usize) -> f64 {
        let l = &self.lines[k];
        let n = l.len() - 1;
        let after = (i < n).then(|| l[i + 1] - l[i]);
        let before = if i > 0 {
            Some(l[i] - l[i - 1])
        } else {
            self.periodic[k].then(|| l[n] - l[n - 1])
        };
        let after = after.or_else(|| self.periodic[k].then(|| l[1] - l[0]));
        after.into_iter().chain(before).fold(f64::MAX, f64::min)
    }

    fn eval(&self, uv: DVec2) -> DVec3 {
        let mut q = uv;
        self.patch.normalise(&mut q);
        self.patch.eval(q)
    }

    /// Whether the point at `uv` lies on the target (off outside the domain).
    fn on(&self, uv: DVec2) -> bool {
        self.apart(uv) <= self.tol
    }

    /// The parameter steps of a probe [`PROBE`] of the surface's size long along u and v at
    /// `uv` (at most a quarter cell): a region narrower than a cell still holds the probes
    /// around a point inside it, and off a crossing they leave the other surface.
    fn probe(&self, uv: DVec2) -> DVec2 {
        let (du, dv) = self.patch.derivs(uv);
        let step = PROBE * self.patch.scale();
        let quarter = 0.25 / N as f64;
        let d = |speed: f64| (step / speed.max(1e-300)).min(quarter);
        DVec2::new(d(du.length()), d(dv.length()))
    }

    /// A point belongs to the region when it lies on the target and so does a point `d` away
    /// (per direction; a quarter of the grid's local cell for a node) in one of four oblique
    /// directions (an irrational slope, so a crossing curve along a grid line or a diagonal
    /// does not count).
    fn in_region_by(&self, uv: DVec2, d: DVec2) -> bool {
        if !self.on(uv) {
            return false;
        }
        let phi = 0.618_033_988_749_895;
        [(1.0, phi), (-phi, 1.0), (-1.0, -phi), (phi, -1.0)]
            .iter()
            .any(|&(x, y)| self.on(uv + DVec2::new(x, y) * d))
    }

    /// Line `i` of direction `k`, the last one taken back to the first across a seam.
    fn wrap(&self, k: usize, i: usize) -> usize {
        if self.periodic[k] {
            i % (self.lines[k].len() - 1)
        } else {
            i
        }
    }

    fn idx(&self, i: usize, j: usize) -> usize {
        self.wrap(1, j) * self.lines[0].len() + self.wrap(0, i)
    }

    fn node(&self, i: usize, j: usize) -> bool {
        self.nodes[self.idx(i, j)]
    }

    fn classify(&mut self) {
        let [nu, nv] = self.cells();
        let mut nodes = vec![false; (nu + 1) * (nv + 1)];
        for j in 0..=nv {
            for i in 0..=nu {
                let wrapped = (self.periodic[0] && i == nu) || (self.periodic[1] && j == nv);
                if !wrapped && self.needed(i, j) {
                    let d = 0.25 * DVec2::new(self.cell_near(0, i), self.cell_near(1, j));
                    nodes[j * (nu + 1) + i] = self.in_region_by(self.uv_of(i, j), d);
                }
            }
        }
        // Nodes on the far side of a seam are the ones on the near side.
        for j in 0..=nv {
            for i in 0..=nu {
                nodes[j * (nu + 1) + i] = nodes[self.idx(i, j)];
            }
        }
        self.nodes = nodes;
    }

    /// Whether the surface has no boundary of its own: every domain edge is a seam or collapses
    /// to a point (a pole).
    fn boundaryless(&self) -> bool {
        (0..2).all(|k| {
            self.periodic[k]
                || [0.0, 1.0].iter().all(|&c| {
                    let at = |t: f64| {
                        let mut uv = DVec2::splat(t);
                        uv[k] = c;
                        self.eval(uv)
                    };
                    let p0 = at(0.0);
                    (1..=8).all(|i| at(i as f64 / 8.0).distance(p0) <= self.tol)
                })
        })
    }

    fn norm_key(&self, k: Key) -> Key {
        let (w0, w1) = (|i| self.wrap(0, i), |j| self.wrap(1, j));
        match k {
            Key::Node(i, j) => Key::Node(w0(i), w1(j)),
            Key::H(i, j) => Key::H(i, w1(j)),
            Key::V(i, j) => Key::V(w0(i), j),
        }
    }

    /// The directed boundary segments: marching squares in every cell (the region on the
    /// left), and the domain's own edges where its nodes are in the region.
    fn segments(&mut self) -> Vec<(Key, Key)> {
        let mut segs = Vec::new();
        let [nu, nv] = self.cells();
        for j in 0..nv {
            for i in 0..nu {
                self.cell(i, j, &mut segs);
            }
        }
        // Domain edges, counter-clockwise: bottom, right, top, left.
        let sides: [(bool, Vec<SideEdge>); 4] = [
            (
                !self.periodic[1],
                (0..nu)
                    .map(|i| ((i, 0), (i + 1, 0), Key::H(i, 0)))
                    .collect(),
            ),
            (
                !self.periodic[0],
                (0..nv)
                    .map(|j| ((nu, j), (nu, j + 1), Key::V(nu, j)))
                    .collect(),
            ),
            (
                !self.periodic[1],
                (0..nu)
                    .rev()
                    .map(|i| ((i + 1, nv), (i, nv), Key::H(i, nv)))
                    .collect(),
            ),
            (
                !self.periodic[0],
                (0..nv)
                    .rev()
                    .map(|j| ((0, j + 1), (0, j), Key::V(0, j)))
                    .collect(),
            ),
        ];
        for (real, edges) in sides {
            if !real {
                continue;
            }
            for ((ai, aj), (bi, bj), e) in edges {
                let (va, vb) = (self.node(ai, aj), self.node(bi, bj));
                let (na, nb) = (
                    self.norm_key(Key::Node(ai, aj)),
                    self.norm_key(Key::Node(bi, bj)),
                );
                match (va, vb) {
                    (true, true) => segs.push((na, nb)),
                    (true, false) => {
                        self.crossing(e);
                        segs.push((na, self.norm_key(e)));
                    }
                    (false, true) => {
                        self.crossing(e);
                        segs.push((self.norm_key(e), nb));
                    }
                    (false, false) => {}
                }
            }
        }
        segs
    }

    fn cell(&mut self, i: usize, j: usize, segs: &mut Vec<(Key, Key)>) {
        let c = [
            self.node(i, j),
            self.node(i + 1, j),
            self.node(i + 1, j + 1),
            self.node(i, j + 1),
        ];
        let edges = [
            Key::H(i, j),
            Key::V(i + 1, j),
            Key::H(i, j + 1),
            Key::V(i, j),
        ];
        let exit: Vec<usize> = (0..4).filter(|&k| c[k] && !c[(k + 1) % 4]).collect();
        if exit.is_empty() {
            return;
        }
        let entry = |k: usize| !c[k] && c[(k + 1) % 4];
        // A saddle is joined through the middle when the cell's centre is in the region.
        let centre = 0.5 * (self.uv_of(i, j) + self.uv_of(i + 1, j + 1));
        let through = exit.len() == 2 && self.on(centre);
        for &x in &exit {
            let e = if through {
                (1..4).map(|d| (x + d) % 4).find(|&m| entry(m))
            } else {
                (1..4).map(|d| (x + 4 - d) % 4).find(|&m| entry(m))
            };
            let Some(e) = e else { continue };
            self.crossing(edges[x]);
            self.crossing(edges[e]);
            segs.push((self.norm_key(edges[x]), self.norm_key(edges[e])));
        }
    }

    /// The crossing on a grid edge: bisection between its node in the region and the other,
    /// keeping the end that lies on the target.
    fn crossing(&mut self, e: Key) {
        let e = self.norm_key(e);
        if self.cross.contains_key(&e) {
            return;
        }
        let (a, b) = match e {
            Key::H(i, j) => ((i, j), (i + 1, j)),
            Key::V(i, j) => ((i, j), (i, j + 1)),
            Key::Node(..) => unreachable!("crossings lie on edges"),
        };
        let (ua, ub) = (self.uv_of(a.0, a.1), self.uv_of(b.0, b.1));
        let (lo, hi) = if self.node(a.0, a.1) {
            (ua, ub)
        } else {
            (ub, ua)
        };
        let p = if self.on(hi) {
            self.edge_beside(lo, hi)
        } else {
            self.edge(lo, hi)
        };
        self.cross.insert(e, p);
    }

    /// [`Self::edge`] where the node out of the region still lies on the target: a crossing
    /// runs through it, maybe along this grid edge, whose points then all lie on the target and
    /// bisection would end at that node (a spike out along the crossing). The edge is found on
    /// the parallel lines a little to either side, off the crossing, and the mean of where they
    /// meet it taken (which cancels their offset's slant across an oblique edge). Where only
    /// one side's line does (the other lies outside the domain: the grid edge runs along the
    /// domain's edge), the slant is taken out by a second line twice as far off on that side,
    /// the edge's place extrapolated back from the two. Where neither line starts in the
    /// region, the node in it is the region's corner; where they do but neither meets the
    /// edge, as before.
    fn edge_beside(&self, lo: DVec2, hi: DVec2) -> DVec2 {
        let d = hi - lo;
        let len = d.length();
        let side = DVec2::new(-d.y, d.x) * (OFF_LINE / len);
        // Where the line offset by `s` meets the edge, as a fraction of the grid edge.
        let along = |s: DVec2| {
            let (l, h) = (lo + s, hi + s);
            (self.on(l) && !self.on(h)).then(|| (self.edge(l, h) - l).dot(d) / (len * len))
        };
        let one_sided = |a: f64, s: DVec2| along(2.0 * s).map_or(a, |a2| 2.0 * a - a2);
        let t = match (along(side), along(-side)) {
            (Some(a), Some(b)) => 0.5 * (a + b),
            (Some(a), None) => one_sided(a, side),
            (None, Some(b)) => one_sided(b, -side),
            (None, None) if !self.on(lo + side) && !self.on(lo - side) => return lo,
            (None, None) => return self.edge(lo, hi),
        };
        lo + d * t.clamp(0.0, 1.0)
    }
}

/// Whether a point lies on `s` within `tol` (inside its extent), tested as the tracing tests it:
/// for the crossings kept beside a common region ([`super::beside`]).
pub(super) fn on_surface(s: &Surface, tol: f64) -> impl Fn(DVec3) -> bool + '_ {
    let t = Target::of(s);
    move |p| t.on(p, tol)
}
