//! Tessellation of a parametric surface into the discrete surface of paper 001.

use super::error::{check_positive, SurfaceError};
use super::kinds::Surface;
use super::planar::triangulate_polygon;
use super::sampled::sample_curve;
use super::ParamSurface;
use crate::geom::mesh::{icosphere, Mesh};
use crate::geom::ParamCurve;
use glam::DVec3;

/// The triangle budget: a tolerance that needs more ends in an error naming CHORDTOL instead
/// of exhausting memory or silently giving a coarser mesh.
pub const MAX_TRIANGLES: usize = 6_000_000;

fn over_budget(tol: f64, needed: usize) -> SurfaceError {
    SurfaceError::Invalid(format!(
        "meshing within CHORDTOL = {tol} needs more than {MAX_TRIANGLES} triangles \
         (at least {needed}); raise CHORDTOL"
    ))
}

struct Iso<'a> {
    s: &'a Surface,
    fixed: f64,
    along_u: bool,
}

impl ParamCurve for Iso<'_> {
    fn eval(&self, t: f64) -> DVec3 {
        if self.along_u {
            self.s.eval(t, self.fixed)
        } else {
            self.s.eval(self.fixed, t)
        }
    }
}

/// Grid parameters in one direction: the union of the adaptive samples (chord error within
/// `tol`) of nine iso-curves across the other direction.
fn grid_params(s: &Surface, tol: f64, along_u: bool, min_segments: usize) -> Vec<f64> {
    let mut ts: Vec<f64> = Vec::new();
    for k in 0..=8 {
        let iso = Iso {
            s,
            fixed: k as f64 / 8.0,
            along_u,
        };
        ts.extend(sample_curve(&iso, tol, min_segments).0);
    }
    ts.sort_by(f64::total_cmp);
    ts.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    ts
}

/// Whether the cell's diagonal runs from corner (0, 0) to (1, 1) (else (1, 0) to (0, 1)): the
/// shorter one.
#[inline]
fn main_diagonal(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> bool {
    a.distance_squared(d) <= b.distance_squared(c)
}

/// Refines the grid until every triangle is within `tol` of the surface at its centroid and
/// edge midpoints (the mesh point against the surface point of the same parameters, an upper
/// bound of the distance to the surface): iso-curves alone miss the twist of a ruled or Coons
/// patch, whose iso-lines are straight. A failing sample splits the parameter intervals it
/// depends on.
/// Grid parameters in u and v, and the grid points (row by row in v).
type Grid = (Vec<f64>, Vec<f64>, Vec<DVec3>);

fn refine_grid(
    s: &Surface,
    mut us: Vec<f64>,
    mut vs: Vec<f64>,
    tol: f64,
) -> Result<Grid, SurfaceError> {
    loop {
        let (nu, nv) = (us.len(), vs.len());
        let needed = 2 * (nu - 1) * (nv - 1);
        if needed > MAX_TRIANGLES {
            return Err(over_budget(tol, needed));
        }
        let mut verts = Vec::with_capacity(nu * nv);
        for &v in &vs {
            for &u in &us {
                verts.push(s.eval(u, v));
            }
        }
        let mut max_err: f64 = 0.0;
        let mut split_u = vec![false; nu - 1];
        let mut split_v = vec![false; nv - 1];
        for j in 0..nv - 1 {
            for i in 0..nu - 1 {
                let (u0, u1, v0, v1) = (us[i], us[i + 1], vs[j], vs[j + 1]);
                let p = |di: usize, dj: usize| verts[(j + dj) * nu + i + di];
                let corner = [p(0, 0), p(1, 0), p(0, 1), p(1, 1)];
                let param = |k: usize| {
                    (
                        if k & 1 == 0 { u0 } else { u1 },
                        if k & 2 == 0 { v0 } else { v1 },
                    )
                };
                // The two triangles as corner indices (bit 0: u side, bit 1: v side).
                let tris: [[usize; 3]; 2] =
                    if main_diagonal(corner[0], corner[1], corner[2], corner[3]) {
                        [[0, 1, 3], [0, 3, 2]]
                    } else {
                        [[0, 1, 2], [1, 3, 2]]
                    };
                let mut bad = (false, false);
                let mut worst: f64 = 0.0;
                for t in tris {
                    // Centroid, then the three edge midpoints.
                    let samples: [([f64; 3], bool, bool); 4] = [
                        ([1.0 / 3.0; 3], true, true),
                        ([0.5, 0.5, 0.0], true, true),
                        ([0.0, 0.5, 0.5], true, true),
                        ([0.5, 0.0, 0.5], true, true),
                    ];
                    for (k, (w, mut su, mut sv)) in samples.into_iter().enumerate() {
                        if k > 0 {
                            // An edge midpoint depends on the directions the edge spans.
                            let (e0, e1) = match k {
                                1 => (t[0], t[1]),
                                2 => (t[1], t[2]),
                                _ => (t[2], t[0]),
                            };
                            su = (e0 ^ e1) & 1 != 0;
                            sv = (e0 ^ e1) & 2 != 0;
                        }
                        let (mut u, mut v, mut m) = (0.0, 0.0, DVec3::ZERO);
                        for (c, &wk) in t.iter().zip(&w) {
                            let (cu, cv) = param(*c);
                            u += wk * cu;
                            v += wk * cv;
                            m += wk * corner[*c];
                        }
                        let e = s.eval(u, v).distance(m);
                        worst = worst.max(e);
                        if e > tol {
                            bad.0 |= su;
                            bad.1 |= sv;
                        }
                    }
                }
                split_u[i] |= bad.0;
                split_v[j] |= bad.1;
                max_err = max_err.max(worst);
            }
        }
        // The error falls at best like the square of the spacing, so the triangles needed grow
        // at least like √(error / tol): past the budget already, stop without refining further.
        if max_err > tol && (needed as f64) * (max_err / tol).sqrt() > MAX_TRIANGLES as f64 {
            return Err(over_budget(
                tol,
                ((needed as f64) * (max_err / tol).sqrt()) as usize,
            ));
        }
        let (nsu, nsv) = (
            split_u.iter().filter(|&&b| b).count(),
            split_v.iter().filter(|&&b| b).count(),
        );
        if nsu + nsv == 0 {
            return Ok((us, vs, verts));
        }
        let needed = 2 * (nu - 1 + nsu) * (nv - 1 + nsv);
        if needed > MAX_TRIANGLES {
            return Err(over_budget(tol, needed));
        }
        let split = |ts: &[f64], marks: &[bool]| {
            let mut out = Vec::with_capacity(ts.len() * 2);
            for (k, w) in ts.windows(2).enumerate() {
                out.push(w[0]);
                if marks[k] {
                    out.push(0.5 * (w[0] + w[1]));
                }
            }
            out.push(ts[ts.len() - 1]);
            out
        };
        us = split(&us, &split_u);
        vs = split(&vs, &split_v);
    }
}

/// The discrete surface of `s`: an indexed triangle mesh with shared vertices whose iso-lines
/// are within `chord_tol` of the surface (sphere: an icosphere refined until its triangles'
/// centroids are within `chord_tol`; plane: the boundary polygon ear-clipped). Seams and poles where
/// grid points coincide are welded (within 1e-9 of the size) and collapsed triangles dropped.
pub fn mesh_surface(s: &Surface, chord_tol: f64) -> Result<Mesh, SurfaceError> {
    let tol = check_positive("CHORDTOL (chord-tol)", chord_tol)?;
    match s {
        Surface::Plane(p) => {
            let tris = triangulate_polygon(&p.boundary, p.normal);
            return Ok(Mesh::new(p.boundary.clone(), tris)?);
        }
        Surface::Sphere(sp) => {
            // Refine until every triangle's centroid (its deepest point, near enough) is within
            // tol of the sphere, within the triangle budget.
            let mut n = 0;
            loop {
                let m = icosphere(sp.center, sp.radius, n);
                let dev = (0..m.len())
                    .map(|t| {
                        let [a, b, c] = m.corners_of(t);
                        sp.radius - ((a + b + c) / 3.0).distance(sp.center)
                    })
                    .fold(0.0, f64::max);
                if dev <= tol {
                    return Ok(m);
                }
                if 4 * m.len() > MAX_TRIANGLES {
                    return Err(over_budget(tol, 4 * m.len()));
                }
                n += 1;
            }
        }
        _ => {}
    }
    let us = grid_params(s, tol, true, 4);
    let vs = grid_params(s, tol, false, 1);
    if 2 * us.len() * vs.len() > MAX_TRIANGLES {
        return Err(over_budget(tol, 2 * us.len() * vs.len()));
    }
    let (us, vs, verts) = refine_grid(s, us, vs, tol)?;
    let (nu, nv) = (us.len(), vs.len());
    if let Some(i) = verts.iter().position(|p| !p.is_finite()) {
        return Err(SurfaceError::Invalid(format!(
            "surface evaluates to a non-finite point at grid vertex {i}"
        )));
    }
    let mut idx = Vec::with_capacity((nu - 1) * (nv - 1) * 6);
    for j in 0..nv - 1 {
        for i in 0..nu - 1 {
            let a = (j * nu + i) as u32;
            let b = a + 1;
            let c = a + nu as u32;
            let d = c + 1;
            // Split each cell along its shorter diagonal.
            if main_diagonal(
                verts[a as usize],
                verts[b as usize],
                verts[c as usize],
                verts[d as usize],
            ) {
                idx.extend_from_slice(&[a, b, d, a, d, c]);
            } else {
                idx.extend_from_slice(&[a, b, c, b, d, c]);
            }
        }
    }
    let mut lo = verts[0];
    let mut hi = verts[0];
    for &p in &verts {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let weld = (hi - lo).length().max(1e-300) * 1e-9;
    let (verts, idx) = crate::geom::mesh::weld_tolerance_grid(verts, idx, weld);
    let tris: Vec<[u32; 3]> = idx
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    Ok(compact(verts, tris)?)
}

/// Drops vertices no triangle uses.
fn compact(verts: Vec<DVec3>, tris: Vec<[u32; 3]>) -> Result<Mesh, crate::geom::mesh::MeshError> {
    let (v, t) = crate::geom::mesh::compact_vertices(&verts, tris);
    Mesh::new(v, t)
}
