//! Exact orientation signs (Shewchuk's adaptive orient3d via the `robust` crate).

use glam::DVec3;
use robust::{orient3d, Coord3D};

#[inline]
fn c(p: DVec3) -> Coord3D<f64> {
    Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    }
}

/// Exact sign of `((b - a) × (c - a)) · (d - a)`: +1 when `d` is on the side the normal of the
/// counter-clockwise triangle `a b c` points to, -1 on the other side, 0 when coplanar.
#[inline]
pub fn side(a: DVec3, b: DVec3, cc: DVec3, d: DVec3) -> i8 {
    // Shewchuk's orient3d is positive when d lies *below* the plane (the opposite convention).
    let o = orient3d(c(a), c(b), c(cc), c(d));
    if o < 0.0 {
        1
    } else if o > 0.0 {
        -1
    } else {
        0
    }
}

/// [`side`] made never zero by a consistent symbolic tie-break: the four points are put in a
/// canonical order (lexicographic by coordinates, then by the global ids `ids`), tracking the
/// permutation's parity, and an exactly coplanar configuration counts as positive in that
/// canonical order. Ordering by coordinates first keeps the tie-break independent of vertex
/// numbering and of which mesh is given first. Every evaluation of the same four
/// points therefore agrees, whichever triangle asks, which is what chaining needs.
#[inline]
pub fn side_perturbed(p: [DVec3; 4], ids: [u64; 4]) -> i8 {
    let s = side(p[0], p[1], p[2], p[3]);
    if s != 0 {
        return s;
    }
    let mut idx = [0usize, 1, 2, 3];
    let mut parity = 1i8;
    // Insertion sort on four items, counting swaps.
    for i in 1..4 {
        let mut j = i;
        while j > 0
            && crate::geom::mesh::chain::cmp_point(p[idx[j - 1]], p[idx[j]])
                .then(ids[idx[j - 1]].cmp(&ids[idx[j]]))
                .is_gt()
        {
            idx.swap(j - 1, j);
            parity = -parity;
            j -= 1;
        }
    }
    parity
}
