//! Bounding-volume hierarchy over a mesh's triangles (paper 001 step 2: reject facet pairs whose
//! coordinates cannot meet before intersecting them).
//!
//! A linear BVH: triangle centroids get 30-bit Morton codes, one radix sort orders them, and
//! the tree is cut top-down where the highest differing code bit changes (Lauterbach et al.,
//! "Fast BVH construction on GPUs", 2009), into flat arrays: nodes in depth-first order, the left
//! child right after its parent, leaves holding a run of `order` (their boxes are stored in
//! the same order, so traversal reads them sequentially). Boxes are stored in f32 rounded
//! outward, so box tests never reject a pair that truly touches.

use super::Mesh;
use glam::DVec3;

/// An axis-aligned box (closed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    pub min: DVec3,
    pub max: DVec3,
}

impl Aabb {
    /// The empty box (grows to the first point).
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    #[inline]
    pub fn grow(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    #[inline]
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    #[inline]
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.min.x <= o.max.x
            && o.min.x <= self.max.x
            && self.min.y <= o.max.y
            && o.min.y <= self.max.y
            && self.min.z <= o.max.z
            && o.min.z <= self.max.z
    }

    #[inline]
    pub fn of_points(pts: &[DVec3]) -> Aabb {
        let mut b = Aabb::EMPTY;
        for &p in pts {
            b.grow(p);
        }
        b
    }

    /// Squared distance from `p` to the box (0 inside).
    #[inline]
    pub fn distance_squared(&self, p: DVec3) -> f64 {
        let d = (self.min - p).max(p - self.max).max(DVec3::ZERO);
        d.length_squared()
    }

    /// Whether the box has corners on both (closed) sides of the plane `n·x = d`.
    #[inline]
    pub fn straddles_plane(&self, n: DVec3, d: f64) -> bool {
        let c = (self.min + self.max) * 0.5;
        let e = (self.max - self.min) * 0.5;
        let r = e.x * n.x.abs() + e.y * n.y.abs() + e.z * n.z.abs();
        let s = n.dot(c) - d;
        // Slack for the rounding of this floating test; exact tests follow on the triangles.
        let slack = 1e-12 * (r + s.abs() + d.abs() + 1.0);
        s.abs() <= r + slack
    }
}

/// A box stored in f32 with its bounds rounded outward: half the memory of [`Aabb`] (which
/// matters at millions of triangles) and still conservative, so no touching pair is lost.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Box32 {
    min: [f32; 3],
    max: [f32; 3],
}

#[inline]
fn round_down(x: f64) -> f32 {
    let r = x as f32;
    if r as f64 > x {
        r.next_down()
    } else {
        r
    }
}

#[inline]
fn round_up(x: f64) -> f32 {
    let r = x as f32;
    if (r as f64) < x {
        r.next_up()
    } else {
        r
    }
}

impl Box32 {
    const EMPTY: Box32 = Box32 {
        min: [f32::INFINITY; 3],
        max: [f32::NEG_INFINITY; 3],
    };

    #[inline]
    fn from_aabb(b: &Aabb) -> Box32 {
        Box32 {
            min: [
                round_down(b.min.x),
                round_down(b.min.y),
                round_down(b.min.z),
            ],
            max: [round_up(b.max.x), round_up(b.max.y), round_up(b.max.z)],
        }
    }

    #[inline]
    fn to_aabb(self) -> Aabb {
        Aabb {
            min: DVec3::new(self.min[0] as f64, self.min[1] as f64, self.min[2] as f64),
            max: DVec3::new(self.max[0] as f64, self.max[1] as f64, self.max[2] as f64),
        }
    }

    #[inline]
    fn union(&self, o: &Box32) -> Box32 {
        Box32 {
            min: std::array::from_fn(|i| self.min[i].min(o.min[i])),
            max: std::array::from_fn(|i| self.max[i].max(o.max[i])),
        }
    }

    #[inline]
    fn overlaps(&self, o: &Box32) -> bool {
        self.min[0] <= o.max[0]
            && o.min[0] <= self.max[0]
            && self.min[1] <= o.max[1]
            && o.min[1] <= self.max[1]
            && self.min[2] <= o.max[2]
            && o.min[2] <= self.max[2]
    }

    #[inline]
    fn size2(&self) -> f32 {
        (0..3).map(|i| (self.max[i] - self.min[i]).powi(2)).sum()
    }
}

#[derive(Debug, Clone, Copy)]
struct Node {
    bounds: Box32,
    /// Leaf: first index into `order`; inner: index of the right child.
    start_or_right: u32,
    /// Leaf: number of triangles (> 0); inner: 0.
    count: u32,
}

/// The hierarchy: flat nodes and the triangle order the leaves index into.
#[derive(Debug, Clone)]
pub struct Bvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
    /// The triangles' boxes (outward-rounded f32), in `order`'s order.
    tri_bounds: Vec<Box32>,
}

const LEAF_SIZE: usize = 4;

impl Bvh {
    /// Builds the hierarchy over all triangles of `mesh`.
    pub fn build(mesh: &Mesh) -> Bvh {
        use rayon::prelude::*;
        if mesh.is_empty() {
            return Bvh {
                nodes: Vec::new(),
                order: Vec::new(),
                tri_bounds: Vec::new(),
            };
        }
        let centroid = |t: usize| {
            let [a, b, c] = mesh.corners_of(t);
            (a + b + c) * (1.0 / 3.0)
        };
        let cb = (0..mesh.len())
            .into_par_iter()
            .with_min_len(1 << 14)
            .fold(
                || Aabb::EMPTY,
                |mut acc, t| {
                    acc.grow(centroid(t));
                    acc
                },
            )
            .reduce(|| Aabb::EMPTY, |x, y| x.union(&y));
        let ext = (cb.max - cb.min).max(DVec3::splat(f64::MIN_POSITIVE));
        let scale = DVec3::splat(((1u64 << MORTON_BITS) - 1) as f64) / ext;
        // Key = 30-bit Morton code << 32 | triangle: one u64 radix-sorted on the code bits.
        let keyed: Vec<u64> = (0..mesh.len())
            .into_par_iter()
            .with_min_len(1 << 14)
            .map(|t| {
                let q = ((centroid(t) - cb.min) * scale).max(DVec3::ZERO);
                (morton3(q.x as u64, q.y as u64, q.z as u64) << 32) | t as u64
            })
            .collect();
        let keyed = radix_sort_high32(keyed);
        let order: Vec<u32> = keyed.iter().map(|&k| k as u32).collect();
        // Boxes in leaf order, so the build and every traversal read them sequentially.
        let tri_bounds: Vec<Box32> = order
            .par_iter()
            .with_min_len(1 << 14)
            .map(|&t| Box32::from_aabb(&Aabb::of_points(&mesh.corners_of(t as usize))))
            .collect();
        let mut nodes = Vec::with_capacity(2 * keyed.len() / LEAF_SIZE + 1);
        build_into(&keyed, 0, &tri_bounds, &mut nodes);
        Bvh {
            nodes,
            order,
            tri_bounds,
        }
    }

    /// The box of everything (None for an empty mesh).
    pub fn bounds(&self) -> Option<Aabb> {
        self.nodes.first().map(|n| n.bounds.to_aabb())
    }

    /// Calls `f` with every triangle whose box overlaps `b`.
    pub fn query_box(&self, b: &Aabb, mut f: impl FnMut(u32)) {
        self.visit(
            |nb| nb.overlaps(b),
            |t, tb| {
                if tb.overlaps(b) {
                    f(t)
                }
            },
        );
    }

    /// Calls `f` with every triangle whose box straddles the plane `n·x = d`.
    pub fn query_plane(&self, n: DVec3, d: f64, mut f: impl FnMut(u32)) {
        self.visit(
            |nb| nb.straddles_plane(n, d),
            |t, tb| {
                if tb.straddles_plane(n, d) {
                    f(t)
                }
            },
        );
    }

    /// Generic traversal: descend where `enter(node box)`, call `leaf(triangle, box)` in leaves.
    pub fn visit(&self, mut enter: impl FnMut(&Aabb) -> bool, mut leaf: impl FnMut(u32, &Aabb)) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack: Vec<u32> = Vec::with_capacity(64);
        stack.push(0);
        while let Some(i) = stack.pop() {
            let n = &self.nodes[i as usize];
            if !enter(&n.bounds.to_aabb()) {
                continue;
            }
            if n.count > 0 {
                for k in n.start_or_right as usize..(n.start_or_right + n.count) as usize {
                    leaf(self.order[k], &self.tri_bounds[k].to_aabb());
                }
            } else {
                stack.push(n.start_or_right);
                stack.push(i + 1);
            }
        }
    }

    /// The triangle nearest to `p` by `dist2(triangle) -> squared distance`, branch and bound.
    pub fn nearest(&self, p: DVec3, mut dist2: impl FnMut(u32) -> f64) -> Option<(u32, f64)> {
        if self.nodes.is_empty() {
            return None;
        }
        let mut best: Option<(u32, f64)> = None;
        let mut stack: Vec<(u32, f64)> =
            vec![(0, self.nodes[0].bounds.to_aabb().distance_squared(p))];
        while let Some((i, d)) = stack.pop() {
            if best.is_some_and(|(_, bd)| d > bd) {
                continue;
            }
            let n = &self.nodes[i as usize];
            if n.count > 0 {
                for &t in
                    &self.order[n.start_or_right as usize..(n.start_or_right + n.count) as usize]
                {
                    let dt = dist2(t);
                    if best.is_none_or(|(bt, bd)| dt < bd || (dt == bd && t < bt)) {
                        best = Some((t, dt));
                    }
                }
            } else {
                let (l, r) = (i + 1, n.start_or_right);
                let dl = self.nodes[l as usize].bounds.to_aabb().distance_squared(p);
                let dr = self.nodes[r as usize].bounds.to_aabb().distance_squared(p);
                // Push the farther first so the nearer is explored first.
                if dl < dr {
                    stack.push((r, dr));
                    stack.push((l, dl));
                } else {
                    stack.push((l, dl));
                    stack.push((r, dr));
                }
            }
        }
        best
    }

    /// All pairs (triangle of `self`, triangle of `other`) whose boxes overlap, by simultaneous
    /// descent of both hierarchies; the top of the descent is split across rayon's threads.
    pub fn overlapping_pairs(&self, other: &Bvh) -> Vec<(u32, u32)> {
        use rayon::prelude::*;
        if self.nodes.is_empty() || other.nodes.is_empty() {
            return Vec::new();
        }
        // Expand the pair frontier breadth-first until there is enough parallel work.
        let mut frontier: Vec<(u32, u32)> = vec![(0, 0)];
        let mut leafpairs: Vec<(u32, u32)> = Vec::new();
        while !frontier.is_empty() && frontier.len() < 256 {
            let mut next = Vec::with_capacity(frontier.len() * 4);
            for &(a, b) in &frontier {
                self.expand_pair(other, a, b, &mut next, &mut leafpairs);
            }
            frontier = next;
        }
        let mut out: Vec<(u32, u32)> = frontier
            .par_iter()
            .chain(leafpairs.par_iter())
            .fold(Vec::new, |mut acc, &(a, b)| {
                self.descend(other, a, b, &mut acc);
                acc
            })
            .reduce(Vec::new, |mut x, mut y| {
                x.append(&mut y);
                x
            });
        out.sort_unstable();
        out
    }

    fn expand_pair(
        &self,
        other: &Bvh,
        a: u32,
        b: u32,
        next: &mut Vec<(u32, u32)>,
        leafpairs: &mut Vec<(u32, u32)>,
    ) {
        let na = &self.nodes[a as usize];
        let nb = &other.nodes[b as usize];
        if !na.bounds.overlaps(&nb.bounds) {
            return;
        }
        match (na.count > 0, nb.count > 0) {
            (true, true) => leafpairs.push((a, b)),
            (false, true) => {
                next.push((a + 1, b));
                next.push((na.start_or_right, b));
            }
            (true, false) => {
                next.push((a, b + 1));
                next.push((a, nb.start_or_right));
            }
            (false, false) => {
                for ca in [a + 1, na.start_or_right] {
                    for cb in [b + 1, nb.start_or_right] {
                        next.push((ca, cb));
                    }
                }
            }
        }
    }

    fn descend(&self, other: &Bvh, a: u32, b: u32, out: &mut Vec<(u32, u32)>) {
        let mut stack = vec![(a, b)];
        while let Some((a, b)) = stack.pop() {
            let na = &self.nodes[a as usize];
            let nb = &other.nodes[b as usize];
            if !na.bounds.overlaps(&nb.bounds) {
                continue;
            }
            match (na.count > 0, nb.count > 0) {
                (true, true) => {
                    let ra = na.start_or_right as usize..(na.start_or_right + na.count) as usize;
                    let rb = nb.start_or_right as usize..(nb.start_or_right + nb.count) as usize;
                    for ka in ra {
                        let ba = &self.tri_bounds[ka];
                        if !ba.overlaps(&nb.bounds) {
                            continue;
                        }
                        for kb in rb.clone() {
                            if ba.overlaps(&other.tri_bounds[kb]) {
                                out.push((self.order[ka], other.order[kb]));
                            }
                        }
                    }
                }
                (false, true) => {
                    stack.push((a + 1, b));
                    stack.push((na.start_or_right, b));
                }
                (true, false) => {
                    stack.push((a, b + 1));
                    stack.push((a, nb.start_or_right));
                }
                (false, false) => {
                    // Split the larger box to keep the pair boxes comparable.
                    let sa = na.bounds.size2();
                    let sb = nb.bounds.size2();
                    if sa >= sb {
                        stack.push((a + 1, b));
                        stack.push((na.start_or_right, b));
                    } else {
                        stack.push((a, b + 1));
                        stack.push((a, nb.start_or_right));
                    }
                }
            }
        }
    }
}

const MORTON_BITS: u32 = 10;

/// LSD radix sort on the upper 32 bits (four stable 8-bit passes).
fn radix_sort_high32(mut a: Vec<u64>) -> Vec<u64> {
    let mut b = vec![0u64; a.len()];
    for pass in 0..4 {
        let shift = 32 + 8 * pass;
        let mut count = [0usize; 257];
        for &k in &a {
            count[((k >> shift) & 0xff) as usize + 1] += 1;
        }
        for i in 0..256 {
            count[i + 1] += count[i];
        }
        for &k in &a {
            let d = ((k >> shift) & 0xff) as usize;
            b[count[d]] = k;
            count[d] += 1;
        }
        std::mem::swap(&mut a, &mut b);
    }
    a
}

/// Spreads the low 21 bits of `v` to every third bit.
#[inline]
fn spread3(v: u64) -> u64 {
    let mut x = v & 0x1f_ffff;
    x = (x | (x << 32)) & 0x1f_0000_0000_ffff;
    x = (x | (x << 16)) & 0x1f_0000_ff00_00ff;
    x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
    x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
    x = (x | (x << 2)) & 0x1249_2492_4924_9249;
    x
}

#[inline]
fn morton3(x: u64, y: u64, z: u64) -> u64 {
    spread3(x) | (spread3(y) << 1) | (spread3(z) << 2)
}

/// The split of a Morton-sorted run: where its highest differing bit turns on (the linear BVH
/// of Lauterbach et al. 2009), or the middle when all codes are equal or the split is lopsided.
fn split_point(codes: &[u64]) -> usize {
    let n = codes.len();
    let (first, last) = (codes[0] >> 32, codes[n - 1] >> 32);
    if first != last {
        let bit = 63 - (first ^ last).leading_zeros();
        let mask = !0u64 << bit;
        let prefix = first & mask;
        // First index whose code has the bit set.
        let s = codes.partition_point(|&c| (c >> 32) & mask == prefix);
        if s > n / 8 && s < n - n / 8 {
            return s;
        }
    }
    n / 2
}

/// `codes` holds the sorted keys (Morton code in the high 32 bits); `tri_bounds` is in leaf
/// order; the run covers `offset..offset + codes.len()`.
fn build_into(codes: &[u64], offset: usize, tri_bounds: &[Box32], nodes: &mut Vec<Node>) -> Box32 {
    if codes.len() <= LEAF_SIZE {
        let mut b = Box32::EMPTY;
        for tb in &tri_bounds[offset..offset + codes.len()] {
            b = b.union(tb);
        }
        nodes.push(Node {
            bounds: b,
            start_or_right: offset as u32,
            count: codes.len() as u32,
        });
        return b;
    }
    let mid = split_point(codes);
    let me = nodes.len();
    nodes.push(Node {
        bounds: Box32::EMPTY,
        start_or_right: 0,
        count: 0,
    });
    let (lc, rc) = codes.split_at(mid);
    let bl = build_into(lc, offset, tri_bounds, nodes);
    nodes[me].start_or_right = nodes.len() as u32;
    let br = build_into(rc, offset + mid, tri_bounds, nodes);
    let b = bl.union(&br);
    nodes[me].bounds = b;
    b
}
