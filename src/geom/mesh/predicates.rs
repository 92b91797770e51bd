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

#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let bv = x - a;
    let av = x - bv;
    (x, (a - av) + (b - bv))
}

#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let x = a * b;
    (x, a.mul_add(b, -x))
}

/// Shewchuk's Grow-Expansion with zero elimination: adds `b` exactly to the nonoverlapping
/// expansion `e` (components in increasing magnitude).
fn grow(e: &mut Vec<f64>, b: f64) {
    let mut q = b;
    let mut out = Vec::with_capacity(e.len() + 1);
    for &c in e.iter() {
        let (x, h) = two_sum(q, c);
        if h != 0.0 {
            out.push(h);
        }
        q = x;
    }
    if q != 0.0 {
        out.push(q);
    }
    *e = out;
}

/// Adds `sign · ((x − z)_i (y − z)_j − (x − z)_j (y − z)_i)` exactly to `e`: a component of
/// the cross product `(x − z) × (y − z)`.
fn add_cross(e: &mut Vec<f64>, x: DVec3, y: DVec3, z: DVec3, i: usize, j: usize, sign: f64) {
    let a_i = two_sum(x[i], -z[i]);
    let a_j = two_sum(x[j], -z[j]);
    let b_i = two_sum(y[i], -z[i]);
    let b_j = two_sum(y[j], -z[j]);
    for (u, w, s) in [(a_i, b_j, sign), (a_j, b_i, -sign)] {
        for p in [u.0, u.1] {
            for q in [w.0, w.1] {
                let (h, l) = two_prod(p, q);
                grow(e, s * h);
                grow(e, s * l);
            }
        }
    }
}

/// [`side`] with the second mesh symbolically translated by `ε·v`, `v = e_z + δ·e_y + δ²·e_x`
/// (0 < δ, ε infinitesimal): a real perturbation of the configuration, so every decision made
/// with it is consistent with one actual (perturbed) geometry — the idea of Edelsbrunner and
/// Mücke's Simulation of Simplicity, restricted to a translation. An exact zero is decided by
/// the sign of the first-order term `Σ_moving ∇_j side · v`, evaluated exactly (error-free
/// products and Shewchuk expansion sums). `moving[j]` marks the points of the translated mesh.
/// Configurations a translation cannot resolve (a degenerate triangle, all points in one mesh)
/// fall back to [`side_perturbed`].
pub fn side_sos(p: [DVec3; 4], moving: [bool; 4], ids: [u64; 4]) -> i8 {
    let s = side(p[0], p[1], p[2], p[3]);
    if s != 0 {
        return s;
    }
    let k = moving.iter().filter(|&&m| m).count();
    if k != 0 && k != 4 {
        for (i, j) in [(0usize, 1usize), (2, 0), (1, 2)] {
            let mut e: Vec<f64> = Vec::new();
            // ∂side/∂p3 = (p1−p0)×(p2−p0), ∂/∂p2 = (p3−p0)×(p1−p0), ∂/∂p1 = (p2−p0)×(p3−p0),
            // ∂/∂p0 = −(p2−p1)×(p3−p1).
            if moving[3] {
                add_cross(&mut e, p[1], p[2], p[0], i, j, 1.0);
            }
            if moving[2] {
                add_cross(&mut e, p[3], p[1], p[0], i, j, 1.0);
            }
            if moving[1] {
                add_cross(&mut e, p[2], p[3], p[0], i, j, 1.0);
            }
            if moving[0] {
                add_cross(&mut e, p[2], p[3], p[1], i, j, -1.0);
            }
            if let Some(&top) = e.last() {
                if top > 0.0 {
                    return 1;
                } else if top < 0.0 {
                    return -1;
                }
            }
        }
    }
    side_perturbed(p, ids)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sos_resolves_coplanar_point_by_translation() {
        // Triangle in z = 0 (normal +z), moving point on it: lifted by +ε in z → positive.
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
        let d = DVec3::new(0.2, 0.2, 0.0);
        assert_eq!(side(a, b, c, d), 0);
        assert_eq!(
            side_sos([a, b, c, d], [false, false, false, true], [0, 1, 2, 3]),
            1
        );
        // Moving the triangle instead lifts the plane: the point falls below.
        assert_eq!(
            side_sos([a, b, c, d], [true, true, true, false], [0, 1, 2, 3]),
            -1
        );
        // Vertical triangle (normal −y... in the xz plane): decided by the y component.
        let (a, b, c) = (DVec3::ZERO, DVec3::Z, DVec3::X);
        let d = DVec3::new(0.3, 0.0, 0.3);
        let s = side_sos([a, b, c, d], [false, false, false, true], [0, 1, 2, 3]);
        // n = Z × X = +Y, v has +δ·y: positive.
        assert_eq!(s, 1);
    }

    #[test]
    fn sos_two_moving_points() {
        // Two crossing coplanar segments in z = 0: p0 p1 fixed along x, p2 p3 moving along y.
        let p = [
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, -1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        let s = side_sos(p, [false, false, true, true], [0, 1, 2, 3]);
        // Derivative: v·((p1−p0)×(p2−p3)) = e_z·((2,0,0)×(0,−2,0)) = −4.
        assert_eq!(s, -1);
        assert_eq!(side_sos(p, [true, true, false, false], [0, 1, 2, 3]), 1);
    }
}
