//! Tessellation of a parametric surface into the discrete surface of paper 001.

use super::error::{check_positive, SurfaceError};
use super::kinds::Surface;
use super::planar::triangulate_polygon;
use super::sampled::sample_curve;
use super::ParamSurface;
use crate::geom::mesh::{icosphere, Mesh};
use crate::geom::ParamCurve;
use glam::DVec3;

/// Most grid lines in one parameter direction (keeps a tiny tolerance from exhausting memory).
const MAX_LINES: usize = 4096;

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
    if ts.len() > MAX_LINES {
        let n = MAX_LINES - 1;
        ts = (0..=n).map(|i| i as f64 / n as f64).collect();
    }
    ts
}

/// The discrete surface of `s`: an indexed triangle mesh with shared vertices whose iso-lines
/// are within `chord_tol` of the surface (sphere: an icosphere refined until its triangles'
/// centroids are within `chord_tol`; plane: the boundary polygon ear-clipped). Seams and poles where
/// grid points coincide are welded (within 1e-9 of the size) and collapsed triangles dropped.
pub fn mesh_surface(s: &Surface, chord_tol: f64) -> Result<Mesh, SurfaceError> {
    let tol = check_positive("chord-tol", chord_tol)?;
    match s {
        Surface::Plane(p) => {
            let tris = triangulate_polygon(&p.boundary, p.normal);
            return Ok(Mesh::new(p.boundary.clone(), tris)?);
        }
        Surface::Sphere(sp) => {
            // Refine until every triangle's centroid (its deepest point, near enough) is within
            // tol of the sphere; level 9 (5.2M triangles) is the cap.
            let mut n = 0;
            loop {
                let m = icosphere(sp.center, sp.radius, n);
                let dev = (0..m.len())
                    .map(|t| {
                        let [a, b, c] = m.corners_of(t);
                        sp.radius - ((a + b + c) / 3.0).distance(sp.center)
                    })
                    .fold(0.0, f64::max);
                if dev <= tol || n >= 9 {
                    return Ok(m);
                }
                n += 1;
            }
        }
        _ => {}
    }
    let us = grid_params(s, tol, true, 4);
    let vs = grid_params(s, tol, false, 1);
    let (nu, nv) = (us.len(), vs.len());
    let mut verts = Vec::with_capacity(nu * nv);
    for &v in &vs {
        for &u in &us {
            verts.push(s.eval(u, v));
        }
    }
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
            if verts[a as usize].distance_squared(verts[d as usize])
                <= verts[b as usize].distance_squared(verts[c as usize])
            {
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
