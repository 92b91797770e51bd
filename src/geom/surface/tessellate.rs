//! Tessellation of a parametric surface into the discrete surface of paper 001.

use super::error::{check_positive, SurfaceError};
use super::kinds::Surface;
use super::planar::triangulate_polygon;
use super::sampled::sample_curve;
use super::separable::{UPart, VPart};
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

/// Grid parameters in u and v, and the grid points (row by row in v).
type Grid = (Vec<f64>, Vec<f64>, Vec<DVec3>);

/// Centroid parameters of a cell's triangles along u (corners' (u0, u1) as (a, b) in the
/// triangles' corner order, see `refine_grid`) and along v.
const U_CENTROIDS: [[usize; 3]; 3] = [[0, 1, 1], [0, 1, 0], [1, 1, 0]];
const V_CENTROIDS: [[usize; 3]; 2] = [[0, 0, 1], [0, 1, 1]];

/// The parts a cell's checks evaluate at along one direction, per interval [a, b]: at the
/// midpoint, and at each centroid coordinate computed as the barycentric sum over the
/// triangle's corners in their order (w = 1/3), so the same bits. A point is evaluated once
/// however many cells or triangles share it.
fn interval_parts<P>(ts: &[f64], centroids: &[[usize; 3]], part: impl Fn(f64) -> P) -> Vec<Vec<P>> {
    let t = 1.0 / 3.0;
    let mut out: Vec<Vec<P>> = (0..=centroids.len()).map(|_| Vec::new()).collect();
    for w in ts.windows(2) {
        out[0].push(part(0.5 * w[0] + 0.5 * w[1]));
        for (k, c) in centroids.iter().enumerate() {
            out[k + 1].push(part(t * w[c[0]] + t * w[c[1]] + t * w[c[2]]));
        }
    }
    out
}

/// Refines the grid until every triangle is within `tol` of the surface at its centroid and
/// edge midpoints (the mesh point against the surface point of the same parameters, an upper
/// bound of the distance to the surface): iso-curves alone miss the twist of a ruled or Coons
/// patch, whose iso-lines are straight. A failing sample splits the parameter intervals it
/// depends on: an edge's midpoint the interval the edge spans, a centroid or diagonal both.
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
        let (gu, gv): (Vec<UPart>, Vec<VPart>) = (
            us.iter().map(|&u| s.u_part(u)).collect(),
            vs.iter().map(|&v| s.v_part(v)).collect(),
        );
        let verts: Vec<DVec3> = (0..nv)
            .flat_map(|j| (0..nu).map(move |i| (i, j)))
            .map(|(i, j)| s.combine(&gu[i], &gv[j]))
            .collect();
        // Before any check: a midpoint between finite corners would hide it.
        if let Some(i) = verts.iter().position(|p| !p.is_finite()) {
            return Err(SurfaceError::Invalid(format!(
                "surface evaluates to a non-finite point at grid vertex {i}"
            )));
        }
        let pu = interval_parts(&us, &U_CENTROIDS, |u| s.u_part(u));
        let pv = interval_parts(&vs, &V_CENTROIDS, |v| s.v_part(v));
        let at = |i: usize, j: usize| verts[j * nu + i];
        let mut max_err: f64 = 0.0;
        let mut split_u = vec![false; nu - 1];
        let mut split_v = vec![false; nv - 1];
        let mut check = |a: &UPart, b: &VPart, m: DVec3| {
            let e = s.combine(a, b).distance(m);
            max_err = max_err.max(e);
            e > tol
        };
        // Edge midpoints: an edge along u at every row, along v at every column.
        for (j, row) in gv.iter().enumerate() {
            for i in 0..nu - 1 {
                let m = 0.5 * at(i, j) + 0.5 * at(i + 1, j);
                split_u[i] |= check(&pu[0][i], row, m);
            }
        }
        for j in 0..nv - 1 {
            for (i, column) in gu.iter().enumerate() {
                let m = 0.5 * at(i, j) + 0.5 * at(i, j + 1);
                split_v[j] |= check(column, &pv[0][j], m);
            }
        }
        // Each cell's diagonal and its triangles' centroids (corners 0..3: bit 0 the u side,
        // bit 1 the v side; the centroid's parameters as `interval_parts` orders them).
        let t = 1.0 / 3.0;
        for j in 0..nv - 1 {
            for i in 0..nu - 1 {
                let c = [at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)];
                let centroid = |k: [usize; 3]| t * c[k[0]] + t * c[k[1]] + t * c[k[2]];
                let (diagonal, first, second) = if main_diagonal(c[0], c[1], c[2], c[3]) {
                    (
                        0.5 * c[0] + 0.5 * c[3],
                        (&pu[1][i], &pv[1][j], centroid([0, 1, 3])),
                        (&pu[2][i], &pv[2][j], centroid([0, 3, 2])),
                    )
                } else {
                    (
                        0.5 * c[1] + 0.5 * c[2],
                        (&pu[2][i], &pv[1][j], centroid([0, 1, 2])),
                        (&pu[3][i], &pv[2][j], centroid([1, 3, 2])),
                    )
                };
                let mut bad = check(&pu[0][i], &pv[0][j], diagonal);
                bad |= check(first.0, first.1, first.2);
                bad |= check(second.0, second.1, second.2);
                split_u[i] |= bad;
                split_v[j] |= bad;
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
