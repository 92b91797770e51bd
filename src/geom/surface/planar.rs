//! Planar regions: Newell's normal and ear-clipping triangulation.

use crate::geom::frame::arbitrary_axis;
use glam::{DVec2, DVec3};
use robust::{orient2d, Coord};

/// Newell's method: the area-weighted normal of a (possibly non-planar) polygon; its length is
/// twice the projected area.
pub(crate) fn newell_normal(p: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for i in 0..p.len() {
        let a = p[i];
        let b = p[(i + 1) % p.len()];
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n
}

#[inline]
fn o2(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    orient2d(
        Coord { x: a.x, y: a.y },
        Coord { x: b.x, y: b.y },
        Coord { x: c.x, y: c.y },
    )
}

/// Triangulates a simple polygon lying (about) in the plane with normal `normal` by ear
/// clipping (Meisters' two-ears theorem; O(n²)), with exact orientation tests. Triangles are
/// counter-clockwise about `normal`. A polygon with no clean ear left (self-touching or
/// degenerate) is finished by clipping its flattest convex corner, so it always terminates.
pub fn triangulate_polygon(points: &[DVec3], normal: DVec3) -> Vec<[u32; 3]> {
    let n = points.len();
    if n < 3 {
        return Vec::new();
    }
    let (x, y) = arbitrary_axis(normal);
    let p2: Vec<DVec2> = points
        .iter()
        .map(|p| DVec2::new(p.dot(x), p.dot(y)))
        .collect();
    let area2: f64 = (0..n)
        .map(|i| {
            let (a, b) = (p2[i], p2[(i + 1) % n]);
            a.x * b.y - b.x * a.y
        })
        .sum();
    let mut idx: Vec<u32> = (0..n as u32).collect();
    let flip = area2 < 0.0;
    if flip {
        idx.reverse();
    }
    let mut tris = Vec::with_capacity(n - 2);
    while idx.len() > 3 {
        let m = idx.len();
        let mut clipped = false;
        for i in 0..m {
            let (ia, ib, ic) = (idx[(i + m - 1) % m], idx[i], idx[(i + 1) % m]);
            let (a, b, c) = (p2[ia as usize], p2[ib as usize], p2[ic as usize]);
            if o2(a, b, c) <= 0.0 {
                continue;
            }
            let blocked = idx.iter().any(|&j| {
                if j == ia || j == ib || j == ic {
                    return false;
                }
                let p = p2[j as usize];
                // A repeated corner (the two sides of a keyhole bridge) does not block.
                if p == a || p == b || p == c {
                    return false;
                }
                // Closed triangle test: a vertex on the ear's boundary blocks it too.
                o2(a, b, p) >= 0.0 && o2(b, c, p) >= 0.0 && o2(c, a, p) >= 0.0
            });
            if !blocked {
                tris.push([ia, ib, ic]);
                idx.remove(i);
                clipped = true;
                break;
            }
        }
        if !clipped {
            // Degenerate remainder: clip the corner with the largest (least negative) turn.
            let m = idx.len();
            let best = (0..m)
                .max_by(|&i, &j| {
                    let t = |k: usize| {
                        let (a, b, c) = (
                            p2[idx[(k + m - 1) % m] as usize],
                            p2[idx[k] as usize],
                            p2[idx[(k + 1) % m] as usize],
                        );
                        o2(a, b, c)
                    };
                    t(i).total_cmp(&t(j))
                })
                .unwrap_or(0);
            tris.push([idx[(best + m - 1) % m], idx[best], idx[(best + 1) % m]]);
            idx.remove(best);
        }
    }
    tris.push([idx[0], idx[1], idx[2]]);
    tris
}
