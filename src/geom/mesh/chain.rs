//! Chaining segments into polylines (paper 001 step 4: "sort the segments found in each facet
//! and chain them into the intersection line").
//!
//! Segments carry symbolic end keys (a mesh vertex, or an edge/facet pair) so chaining is
//! topological and exact: two segments join exactly when they share a key, never by a distance
//! tolerance. The output is put in a canonical form (start point and direction chosen from the
//! coordinates) so it does not depend on the order of the input triangles.

use glam::DVec3;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::hash::Hash;

/// A polyline in space. A closed polyline does not repeat its first point at the end.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline3 {
    pub points: Vec<DVec3>,
    pub closed: bool,
}

impl Polyline3 {
    /// Its segments as point pairs (with the closing one of a closed polyline); none for fewer
    /// than two points.
    pub fn segments(&self) -> impl Iterator<Item = (DVec3, DVec3)> + '_ {
        let m = self.points.len();
        let segs = match m {
            0 | 1 => 0,
            _ if self.closed => m,
            _ => m - 1,
        };
        (0..segs).map(move |i| (self.points[i], self.points[(i + 1) % m]))
    }

    /// Total length (including the closing segment of a closed polyline).
    pub fn length(&self) -> f64 {
        let mut l: f64 = self.points.windows(2).map(|w| w[0].distance(w[1])).sum();
        if self.closed && self.points.len() > 1 {
            l += self.points[self.points.len() - 1].distance(self.points[0]);
        }
        l
    }
}

/// One segment with the symbolic keys of its two ends.
#[derive(Debug, Clone, Copy)]
pub struct Segment {
    pub keys: [u128; 2],
    pub points: [DVec3; 2],
}

pub(crate) fn cmp_point(a: DVec3, b: DVec3) -> Ordering {
    a.x.total_cmp(&b.x)
        .then(a.y.total_cmp(&b.y))
        .then(a.z.total_cmp(&b.z))
}

/// Chains segments that share end keys into polylines.
///
/// Duplicate segments (same two keys) count once and zero-length ones (equal keys) are
/// dropped. Walks start at the keys whose degree is not two (open ends, branch points), then
/// the remaining segments form closed loops. Each loop starts at its lexicographically smallest
/// point and runs toward the smaller of its two neighbours; each open polyline starts at its
/// smaller end; the list is sorted by first point.
pub fn chain_segments(segments: Vec<Segment>) -> Vec<Polyline3> {
    chain_keyed(segments).into_iter().map(|c| c.0).collect()
}

/// [`chain_segments`] with each polyline's point keys, in the order of its points: a plane
/// section's seed point can then be kept between the two vertices of the edge it lies on.
pub(crate) fn chain_keyed(mut segments: Vec<Segment>) -> Vec<(Polyline3, Vec<u128>)> {
    segments.retain(|s| s.keys[0] != s.keys[1]);
    for s in segments.iter_mut() {
        if s.keys[0] > s.keys[1] {
            s.keys.swap(0, 1);
            s.points.swap(0, 1);
        }
    }
    segments.sort_unstable_by_key(|s| s.keys);
    segments.dedup_by_key(|s| s.keys);

    let mut incident: HashMap<u128, Vec<u32>> = HashMap::with_capacity(segments.len() * 2);
    for (i, s) in segments.iter().enumerate() {
        for k in s.keys {
            incident.entry(k).or_default().push(i as u32);
        }
    }
    let mut used = vec![false; segments.len()];
    let mut out = Vec::new();

    let walk = |start_seg: usize, start_key: u128, used: &mut Vec<bool>| {
        let mut pts = Vec::new();
        let mut keys = Vec::new();
        let mut seg = start_seg;
        let mut key = start_key;
        loop {
            used[seg] = true;
            let s = &segments[seg];
            let (from, to, pto) = if s.keys[0] == key {
                (0, s.keys[1], s.points[1])
            } else {
                (1, s.keys[0], s.points[0])
            };
            if pts.is_empty() {
                pts.push(s.points[from]);
                keys.push(key);
            }
            pts.push(pto);
            keys.push(to);
            key = to;
            let inc = &incident[&key];
            if inc.len() != 2 {
                break;
            }
            match inc.iter().find(|&&j| !used[j as usize]) {
                Some(&j) => seg = j as usize,
                None => break,
            }
        }
        (pts, keys, key)
    };

    // Open chains first, from every key whose degree is not two, in key order for determinism.
    let mut ends: Vec<u128> = incident
        .iter()
        .filter(|(_, v)| v.len() != 2)
        .map(|(&k, _)| k)
        .collect();
    ends.sort_unstable();
    for k in ends {
        let inc = incident[&k].clone();
        for j in inc {
            if !used[j as usize] {
                let (pts, keys, _) = walk(j as usize, k, &mut used);
                out.push(canonical(pts, keys, false));
            }
        }
    }
    for i in 0..segments.len() {
        if !used[i] {
            let k = segments[i].keys[0];
            let (mut pts, mut keys, end) = walk(i, k, &mut used);
            let closed = end == k;
            if closed {
                pts.pop();
                keys.pop();
            }
            out.push(canonical(pts, keys, closed));
        }
    }
    out.sort_by(|(a, _), (b, _)| {
        cmp_point(a.points[0], b.points[0]).then(a.points.len().cmp(&b.points.len()))
    });
    out
}

/// The polyline started and run as [`chain_segments`] says, its keys permuted with its points.
fn canonical(mut pts: Vec<DVec3>, mut keys: Vec<u128>, closed: bool) -> (Polyline3, Vec<u128>) {
    if closed {
        if pts.len() >= 2 {
            let m = (0..pts.len())
                .min_by(|&a, &b| cmp_point(pts[a], pts[b]))
                .unwrap_or(0);
            pts.rotate_left(m);
            keys.rotate_left(m);
            let n = pts.len();
            if n > 2 && cmp_point(pts[n - 1], pts[1]) == Ordering::Less {
                pts[1..].reverse();
                keys[1..].reverse();
            }
        }
    } else if pts.len() >= 2 && cmp_point(pts[pts.len() - 1], pts[0]) == Ordering::Less {
        pts.reverse();
        keys.reverse();
    }
    let c = Polyline3 {
        points: pts,
        closed,
    };
    (c, keys)
}

/// Chains directed segments that meet end to start into runs of keys, each flagged closed when
/// it comes back to its first key; a run that cannot be continued stays open with its last key
/// appended. For boundaries whose orientation matters (traced common regions over grid keys,
/// coplanar overlaps over exact points): unlike `chain_segments`, nothing is deduplicated or
/// re-oriented. Where several unused segments leave one key, the earliest given is taken, so
/// the result does not depend on hashing order.
pub(crate) fn chain_directed<K: Copy + Eq + Hash>(segs: &[(K, K)]) -> Vec<(Vec<K>, bool)> {
    let mut from: HashMap<K, Vec<usize>> = HashMap::new();
    for (n, s) in segs.iter().enumerate() {
        from.entry(s.0).or_default().push(n);
    }
    let mut used = vec![false; segs.len()];
    let mut out = Vec::new();
    for s in 0..segs.len() {
        if used[s] {
            continue;
        }
        used[s] = true;
        let start = segs[s].0;
        let mut keys = vec![start];
        let mut end = segs[s].1;
        while end != start {
            let next = from
                .get(&end)
                .and_then(|v| v.iter().copied().find(|&n| !used[n]));
            let Some(n) = next else { break };
            used[n] = true;
            keys.push(end);
            end = segs[n].1;
        }
        let closed = end == start;
        if !closed {
            keys.push(end);
        }
        out.push((keys, closed));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(a: u128, b: u128) -> Segment {
        Segment {
            keys: [a, b],
            points: [
                DVec3::new(a as f64, 0.0, 0.0),
                DVec3::new(b as f64, 1.0, 0.0),
            ],
        }
    }

    #[test]
    fn square_loop_closes() {
        let mut pts = Vec::new();
        for i in 0..4u128 {
            let p = |k: u128| DVec3::new((k % 4) as f64, ((k % 4) / 2) as f64, 0.0);
            pts.push(Segment {
                keys: [i, (i + 1) % 4],
                points: [p(i), p((i + 1) % 4)],
            });
        }
        let r = chain_segments(pts);
        assert_eq!(r.len(), 1);
        assert!(r[0].closed);
        assert_eq!(r[0].points.len(), 4);
    }

    #[test]
    fn open_chain_and_duplicates() {
        let r = chain_segments(vec![seg(1, 2), seg(2, 3), seg(3, 2), seg(5, 5)]);
        assert_eq!(r.len(), 1);
        assert!(!r[0].closed);
        assert_eq!(r[0].points.len(), 3);
    }

    #[test]
    fn loops_and_open_runs() {
        // A triangle given out of order, and an open run 7 → 8 → 9.
        let segs = [(2, 0), (7, 8), (0, 1), (1, 2), (8, 9)];
        assert_eq!(
            chain_directed(&segs),
            vec![(vec![2, 0, 1], true), (vec![7, 8, 9], false)]
        );
    }

    #[test]
    fn a_key_leaving_twice_takes_the_earliest_segment() {
        // Two loops through key 0 (a figure eight): the first loop follows 0 → 1 as given first.
        let segs = [(0, 1), (1, 0), (0, 2), (2, 0)];
        assert_eq!(
            chain_directed(&segs),
            vec![(vec![0, 1], true), (vec![0, 2], true)]
        );
    }
}
