//! Isolated tangent contacts of two parametric surfaces: where they touch without crossing, the
//! meshes (both inscribed in their surfaces) miss each other by about the chord tolerance and
//! their intersection says nothing. Such a contact is a local minimum, zero, of the distance
//! between the surfaces: the mesh vertices of one surface nearest the other (local minima of
//! that distance over their neighbours, away from every curve already found) seed a minimisation
//! of the distance from `S_a(u, v)` to surface b on the true surfaces (Nelder–Mead in (u, v);
//! the distance is smooth and quadratic about a contact), and a minimum within the tolerance is
//! a contact point.

use super::refine::Patch;
use crate::geom::mesh::{closest_on_triangle, Aabb, Mesh, Polyline3};
use glam::{DVec2, DVec3};
use std::cell::Cell;

/// The contact points of `a` and `b` (meshed as `ma`, `mb` within `seed_tol`) not on `curves`,
/// each within `tol` of both surfaces.
pub(crate) fn tangent_contacts(
    a: &Patch,
    b: &Patch,
    ma: &Mesh,
    mb: &Mesh,
    curves: &[Polyline3],
    seed_tol: f64,
    tol: f64,
) -> Vec<DVec3> {
    let (va, ta) = (ma.vertices(), ma.triangles());
    if va.is_empty() || mb.is_empty() {
        return Vec::new();
    }
    // Two inscribed meshes of touching surfaces are apart by a few chord tolerances at most.
    let gap = 8.0 * seed_tol;
    let bvh = mb.bvh();
    // Distance to mb, only within the gap (a box query rejects the far vertices quickly).
    let dist: Vec<f64> = va
        .iter()
        .map(|&p| {
            let mut best = f64::INFINITY;
            let b = Aabb {
                min: p - DVec3::splat(gap),
                max: p + DVec3::splat(gap),
            };
            bvh.query_box(&b, |t| {
                let [x, y, z] = mb.corners_of(t as usize);
                best = best.min(closest_on_triangle(p, x, y, z).distance(p));
            });
            best
        })
        .collect();
    // Each vertex's neighbours and the longest edge at it.
    let mut nbrs: Vec<Vec<u32>> = vec![Vec::new(); va.len()];
    let mut reach = vec![0.0f64; va.len()];
    for t in ta {
        for k in 0..3 {
            let (i, j) = (t[k], t[(k + 1) % 3]);
            nbrs[i as usize].push(j);
            nbrs[j as usize].push(i);
            let l = va[i as usize].distance(va[j as usize]);
            reach[i as usize] = reach[i as usize].max(l);
            reach[j as usize] = reach[j as usize].max(l);
        }
    }
    let mut out: Vec<DVec3> = Vec::new();
    for i in 0..va.len() {
        let d = dist[i];
        if d > gap || nbrs[i].is_empty() {
            continue;
        }
        let lowest = nbrs[i].iter().all(|&j| {
            let dj = dist[j as usize];
            d < dj || (d == dj && i < j as usize)
        });
        if !lowest {
            continue;
        }
        let near_curve = curves
            .iter()
            .flat_map(|c| c.points.iter())
            .any(|q| q.distance(va[i]) <= 4.0 * reach[i]);
        if near_curve {
            continue;
        }
        if let Some(p) = touch(a, b, va[i], tol) {
            if !out.iter().any(|q| q.distance(p) <= 4.0 * reach[i]) {
                out.push(p);
            }
        }
    }
    out
}

/// Minimises the distance from `a(u, v)` to `b` from the point of `a` nearest `p`; the contact
/// point (midway between the surfaces) when the minimum is within `tol`.
fn touch(a: &Patch, b: &Patch, p: DVec3, tol: f64) -> Option<DVec3> {
    let warm: Cell<Option<DVec2>> = Cell::new(None);
    let eval = |uv: DVec2| {
        let mut uv = uv;
        a.normalise(&mut uv);
        let pa = a.eval(uv);
        let ub = b.project(pa, warm.get());
        warm.set(Some(ub));
        let pb = b.eval(ub);
        (pa.distance(pb), pa, pb)
    };
    let start = a.project(p, None);
    let uv = nelder_mead(&|uv| eval(uv).0, start, 1e-3);
    let (d, pa, pb) = eval(uv);
    (d <= tol).then(|| 0.5 * (pa + pb))
}

/// Nelder–Mead minimisation in the plane from `x0` with an initial simplex of size `h`.
fn nelder_mead(f: &dyn Fn(DVec2) -> f64, x0: DVec2, h: f64) -> DVec2 {
    let mut s = [
        (x0, f(x0)),
        (x0 + DVec2::X * h, f(x0 + DVec2::X * h)),
        (x0 + DVec2::Y * h, f(x0 + DVec2::Y * h)),
    ];
    for _ in 0..600 {
        s.sort_by(|p, q| p.1.total_cmp(&q.1));
        let size = s[1].0.distance(s[0].0).max(s[2].0.distance(s[0].0));
        if size <= 1e-15 || s[0].1 == 0.0 {
            break;
        }
        let c = 0.5 * (s[0].0 + s[1].0);
        let xr = c + (c - s[2].0);
        let fr = f(xr);
        if fr < s[0].1 {
            let xe = c + 2.0 * (c - s[2].0);
            let fe = f(xe);
            s[2] = if fe < fr { (xe, fe) } else { (xr, fr) };
        } else if fr < s[1].1 {
            s[2] = (xr, fr);
        } else {
            let xc = c + 0.5 * (s[2].0 - c);
            let fc = f(xc);
            if fc < s[2].1 {
                s[2] = (xc, fc);
            } else {
                for k in 1..3 {
                    let x = s[0].0 + 0.5 * (s[k].0 - s[0].0);
                    s[k] = (x, f(x));
                }
            }
        }
    }
    s.sort_by(|p, q| p.1.total_cmp(&q.1));
    s[0].0
}
