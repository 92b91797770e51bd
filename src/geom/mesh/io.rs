//! Mesh import and export: STL (binary and ASCII) and Wavefront OBJ.
//!
//! STL stores every facet with its own three corners; reading welds corners with the same
//! coordinates into one shared vertex (paper 001's "a vertex shared by several patches is stored
//! once"): exactly, by bit pattern (with -0 equal to +0), through an open-addressing hash table,
//! then optionally within a distance tolerance through a uniform grid. Facets whose corners weld
//! together (a repeated vertex index) are dropped; facets of zero area with three distinct
//! vertices are kept.

use super::{Mesh, MeshError};
use glam::DVec3;
use std::io::Write;
use std::path::Path;

/// What a read produced besides the mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StlRead {
    /// Facets in the file.
    pub facets: usize,
    /// Facets dropped because two corners welded into one vertex.
    pub dropped: usize,
    /// Whether the file was binary.
    pub binary: bool,
}

fn io_err(path: &Path, source: std::io::Error) -> MeshError {
    MeshError::Io {
        path: path.display().to_string(),
        source,
    }
}

fn parse_err(path: &str, message: impl Into<String>) -> MeshError {
    MeshError::Parse {
        path: path.to_string(),
        message: message.into(),
    }
}

/// Reads an STL or OBJ file, chosen by extension (case-insensitive), welding exactly.
pub fn read_mesh(path: impl AsRef<Path>) -> Result<Mesh, MeshError> {
    let path = path.as_ref();
    match extension(path).as_deref() {
        Some("stl") => read_stl(path, 0.0).map(|(m, _)| m),
        Some("obj") => read_obj(path),
        _ => Err(MeshError::UnknownFormat {
            path: path.display().to_string(),
        }),
    }
}

/// Writes `.stl` (binary) or `.obj` by extension, atomically (temporary file, then rename).
pub fn write_mesh(mesh: &Mesh, path: impl AsRef<Path>) -> Result<(), MeshError> {
    let path = path.as_ref();
    match extension(path).as_deref() {
        Some("stl") => write_stl_binary(mesh, path),
        Some("obj") => write_obj(mesh, path),
        _ => Err(MeshError::UnknownFormat {
            path: path.display().to_string(),
        }),
    }
}

fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase())
}

/// Reads a binary or ASCII STL file. `weld_tolerance` ≥ 0: corners closer than it merge
/// (0 = exact bit-pattern welding only).
pub fn read_stl(path: impl AsRef<Path>, weld_tolerance: f64) -> Result<(Mesh, StlRead), MeshError> {
    use std::io::Read;
    let path = path.as_ref();
    let name = path.display().to_string();
    let mut file = std::fs::File::open(path).map_err(|e| io_err(path, e))?;
    let len = file.metadata().map_err(|e| io_err(path, e))?.len();
    let mut header = [0u8; 84];
    if len >= 84 {
        file.read_exact(&mut header).map_err(|e| io_err(path, e))?;
        let n = u32::from_le_bytes([header[80], header[81], header[82], header[83]]) as u64;
        if len == 84 + 50 * n {
            check_weld_tolerance(weld_tolerance)?;
            // Binary: stream the facets through the welder in chunks (no copy of the file).
            let n = n as usize;
            let mut welder = Welder::new(n * 3);
            const CHUNK: usize = 8192;
            let mut buf = vec![0u8; 50 * CHUNK];
            let mut done = 0;
            while done < n {
                let k = CHUNK.min(n - done);
                file.read_exact(&mut buf[..50 * k])
                    .map_err(|e| io_err(path, e))?;
                for rec in buf[..50 * k].chunks_exact(50) {
                    for c in 0..3 {
                        welder.push(binary_corner(rec, c));
                    }
                }
                done += k;
            }
            let (v, idx) = welder.finish();
            return finish_stl(n, v, idx, weld_tolerance, &name, true);
        }
    }
    let mut bytes = header[..len.min(84) as usize].to_vec();
    file.read_to_end(&mut bytes).map_err(|e| io_err(path, e))?;
    parse_stl(&bytes, weld_tolerance, &name)
}

fn check_weld_tolerance(weld_tolerance: f64) -> Result<(), MeshError> {
    if weld_tolerance >= 0.0 && weld_tolerance.is_finite() {
        Ok(())
    } else {
        Err(MeshError::BadParameter {
            parameter: "weld tolerance",
            limit: "finite and >= 0",
            value: weld_tolerance,
        })
    }
}

/// Corner `c` (0..3) of a 50-byte binary STL facet record.
#[inline]
fn binary_corner(rec: &[u8], c: usize) -> DVec3 {
    let s = 12 + 12 * c;
    let f = |j: usize| {
        let o = s + 4 * j;
        f32::from_le_bytes([rec[o], rec[o + 1], rec[o + 2], rec[o + 3]]) as f64
    };
    DVec3::new(f(0), f(1), f(2))
}

/// Parses STL bytes (`name` is used in error messages).
pub fn parse_stl(
    bytes: &[u8],
    weld_tolerance: f64,
    name: &str,
) -> Result<(Mesh, StlRead), MeshError> {
    check_weld_tolerance(weld_tolerance)?;
    let binary = bytes.len() >= 84 && {
        let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        bytes.len() as u64 == 84 + 50 * n as u64
    };
    let (facets, vertices, idx) = if binary {
        let n = (bytes.len() - 84) / 50;
        let mut welder = Welder::new(n * 3);
        for rec in bytes[84..].chunks_exact(50) {
            for c in 0..3 {
                welder.push(binary_corner(rec, c));
            }
        }
        let (v, idx) = welder.finish();
        (n, v, idx)
    } else {
        let corners = parse_ascii_stl(bytes, name)?;
        let mut welder = Welder::new(corners.len());
        for &c in &corners {
            welder.push(c);
        }
        let (v, idx) = welder.finish();
        (corners.len() / 3, v, idx)
    };
    finish_stl(facets, vertices, idx, weld_tolerance, name, binary)
}

fn finish_stl(
    facets: usize,
    vertices: Vec<DVec3>,
    idx: Vec<u32>,
    weld_tolerance: f64,
    name: &str,
    binary: bool,
) -> Result<(Mesh, StlRead), MeshError> {
    if let Some(i) = vertices.iter().position(|c| !c.is_finite()) {
        return Err(parse_err(
            name,
            format!("vertex {i} has a non-finite coordinate"),
        ));
    }
    let (vertices, idx) = if weld_tolerance > 0.0 {
        weld_tolerance_grid(vertices, idx, weld_tolerance)
    } else {
        (vertices, idx)
    };
    let triangles: Vec<[u32; 3]> = idx
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    let dropped = facets - triangles.len();
    Ok((
        Mesh::new(vertices, triangles)?,
        StlRead {
            facets,
            dropped,
            binary,
        },
    ))
}

fn parse_ascii_stl(bytes: &[u8], name: &str) -> Result<Vec<DVec3>, MeshError> {
    let text = std::str::from_utf8(bytes)
        .map_err(|_| parse_err(name, "neither binary STL nor UTF-8 text"))?;
    let mut tokens = text.split_ascii_whitespace();
    match tokens.next() {
        Some(t) if t.eq_ignore_ascii_case("solid") => {}
        _ => {
            return Err(parse_err(
                name,
                "not an STL file (no 'solid' header, size not binary)",
            ))
        }
    }
    let mut corners = Vec::new();
    while let Some(t) = tokens.next() {
        if t.eq_ignore_ascii_case("vertex") {
            let mut v = [0.0; 3];
            for (k, slot) in v.iter_mut().enumerate() {
                let s = tokens
                    .next()
                    .ok_or_else(|| parse_err(name, "file ends inside a vertex"))?;
                *slot = s.parse().map_err(|_| {
                    parse_err(
                        name,
                        format!(
                            "vertex {} coordinate {k}: '{s}' is not a number",
                            corners.len()
                        ),
                    )
                })?;
            }
            corners.push(DVec3::from_array(v));
        }
    }
    if corners.len() % 3 != 0 {
        return Err(parse_err(
            name,
            format!("{} vertices is not a whole number of facets", corners.len()),
        ));
    }
    Ok(corners)
}

#[inline]
fn hash_point(p: DVec3) -> u64 {
    let mut h = p.x.to_bits().wrapping_mul(0x9E37_79B9_7F4A_7C15);
    h = (h.rotate_left(23) ^ p.y.to_bits()).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    h = (h.rotate_left(29) ^ p.z.to_bits()).wrapping_mul(0x1656_67B1_9E37_79F9);
    h ^ (h >> 32)
}

#[inline]
fn same_bits(a: DVec3, b: DVec3) -> bool {
    a.x.to_bits() == b.x.to_bits()
        && a.y.to_bits() == b.y.to_bits()
        && a.z.to_bits() == b.z.to_bits()
}

/// Exact welding by the coordinates' bit patterns (after `+ 0.0`, which turns -0 into +0 so
/// the two zeros weld): an open-addressing table, grown at half load, fed one corner at a time.
struct Welder {
    cap: usize,
    table: Vec<u32>,
    vertices: Vec<DVec3>,
    idx: Vec<u32>,
}

impl Welder {
    fn new(corners: usize) -> Welder {
        // Closed meshes have about one vertex per six corners.
        let cap = (corners / 3).next_power_of_two().max(16);
        Welder {
            cap,
            table: vec![u32::MAX; cap],
            vertices: Vec::with_capacity(corners / 5 + 16),
            idx: Vec::with_capacity(corners),
        }
    }

    #[inline]
    fn push(&mut self, p: DVec3) {
        let p = p + DVec3::ZERO;
        let mask = self.cap - 1;
        let mut slot = hash_point(p) as usize & mask;
        loop {
            let e = self.table[slot];
            if e == u32::MAX {
                self.table[slot] = self.vertices.len() as u32;
                self.idx.push(self.vertices.len() as u32);
                self.vertices.push(p);
                break;
            }
            if same_bits(self.vertices[e as usize], p) {
                self.idx.push(e);
                break;
            }
            slot = (slot + 1) & mask;
        }
        if self.vertices.len() * 2 > self.cap {
            self.cap *= 2;
            let mask = self.cap - 1;
            self.table = vec![u32::MAX; self.cap];
            for (k, &v) in self.vertices.iter().enumerate() {
                let mut slot = hash_point(v) as usize & mask;
                while self.table[slot] != u32::MAX {
                    slot = (slot + 1) & mask;
                }
                self.table[slot] = k as u32;
            }
        }
    }

    fn finish(self) -> (Vec<DVec3>, Vec<u32>) {
        (self.vertices, self.idx)
    }
}

/// Tolerance welding: each vertex, in order, joins the first earlier kept vertex within `tol`
/// (searched in the 27 neighbouring cells of a grid of cell size `tol`).
pub(crate) fn weld_tolerance_grid(
    vertices: Vec<DVec3>,
    idx: Vec<u32>,
    tol: f64,
) -> (Vec<DVec3>, Vec<u32>) {
    // The grid is only looked up, never iterated, so the hasher cannot change the result; the
    // default SipHash was a third of a refined surface intersection's welding time.
    use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
    const NONE: u32 = u32::MAX;
    let cell = |p: DVec3| -> [i64; 3] {
        let q = (p / tol).floor();
        [q.x as i64, q.y as i64, q.z as i64]
    };
    // Blocks of 16³ cells that hold a kept vertex: a vertex whose neighbouring cells lie in
    // empty blocks (nearly all, as a mesh's spacing is far above `tol`) skips the 27 lookups.
    // Integer cells, so the filter decides exactly what the lookups would.
    let block = |c: [i64; 3]| c.map(|x| x >> 4);
    let mut blocks: HashSet<[i64; 3]> = HashSet::default();
    // A cell's kept vertices as a chain in the order they were kept (first, last, `next`): the
    // search meets them in that order, with no list allocated per cell.
    let mut grid: HashMap<[i64; 3], (u32, u32)> = HashMap::default();
    let mut next: Vec<u32> = Vec::new();
    let mut kept: Vec<DVec3> = Vec::new();
    let mut remap = vec![0u32; vertices.len()];
    let tol2 = tol * tol;
    for (i, &p) in vertices.iter().enumerate() {
        let c = cell(p);
        let (lo, hi) = (
            block(c.map(|x| x.wrapping_sub(1))),
            block(c.map(|x| x.wrapping_add(1))),
        );
        let near = (lo[0]..=hi[0])
            .any(|x| (lo[1]..=hi[1]).any(|y| (lo[2]..=hi[2]).any(|z| blocks.contains(&[x, y, z]))));
        let mut found = None;
        'search: for dx in -1..=1 {
            if !near {
                break;
            }
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(&(first, _)) = grid.get(&[
                        c[0].wrapping_add(dx),
                        c[1].wrapping_add(dy),
                        c[2].wrapping_add(dz),
                    ]) else {
                        continue;
                    };
                    let mut k = first;
                    while k != NONE {
                        if kept[k as usize].distance_squared(p) <= tol2 {
                            found = Some(k);
                            break 'search;
                        }
                        k = next[k as usize];
                    }
                }
            }
        }
        remap[i] = match found {
            Some(k) => k,
            None => {
                let k = kept.len() as u32;
                kept.push(p);
                next.push(NONE);
                blocks.insert(block(c));
                let chain = grid.entry(c).or_insert((k, k));
                if chain.1 != k {
                    next[chain.1 as usize] = k;
                    chain.1 = k;
                }
                k
            }
        };
    }
    (kept, idx.into_iter().map(|i| remap[i as usize]).collect())
}

fn unit_normal(m: &Mesh, t: usize) -> DVec3 {
    let [a, b, c] = m.corners_of(t);
    let n = (b - a).cross(c - a);
    let l = n.length();
    if l > 0.0 && l.is_finite() {
        n / l
    } else {
        DVec3::ZERO
    }
}

fn write_atomic(
    path: &Path,
    f: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), MeshError> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    let mut tmp = tempfile::NamedTempFile::new_in(&dir).map_err(|e| io_err(path, e))?;
    {
        let mut w = std::io::BufWriter::new(tmp.as_file_mut());
        f(&mut w).map_err(|e| io_err(path, e))?;
        w.flush().map_err(|e| io_err(path, e))?;
    }
    tmp.persist(path).map_err(|e| io_err(path, e.error))?;
    Ok(())
}

/// Writes binary STL (coordinates rounded to f32, as the format stores them).
pub fn write_stl_binary(mesh: &Mesh, path: impl AsRef<Path>) -> Result<(), MeshError> {
    let path = path.as_ref();
    let mut buf = Vec::with_capacity(84 + 50 * mesh.len());
    let mut header = [0u8; 80];
    let h = b"binary STL written by lispcad";
    header[..h.len()].copy_from_slice(h);
    buf.extend_from_slice(&header);
    buf.extend_from_slice(&(mesh.len() as u32).to_le_bytes());
    for t in 0..mesh.len() {
        let n = unit_normal(mesh, t);
        for p in std::iter::once(n).chain(mesh.corners_of(t)) {
            for c in [p.x, p.y, p.z] {
                buf.extend_from_slice(&(c as f32).to_le_bytes());
            }
        }
        buf.extend_from_slice(&[0, 0]);
    }
    write_atomic(path, |w| w.write_all(&buf))
}

/// Writes ASCII STL with full f64 precision (shortest round-trip decimal form).
pub fn write_stl_ascii(mesh: &Mesh, path: impl AsRef<Path>) -> Result<(), MeshError> {
    write_atomic(path.as_ref(), |w| {
        writeln!(w, "solid lispcad")?;
        for t in 0..mesh.len() {
            let n = unit_normal(mesh, t);
            writeln!(w, "  facet normal {:e} {:e} {:e}", n.x, n.y, n.z)?;
            writeln!(w, "    outer loop")?;
            for p in mesh.corners_of(t) {
                writeln!(w, "      vertex {:e} {:e} {:e}", p.x, p.y, p.z)?;
            }
            writeln!(w, "    endloop")?;
            writeln!(w, "  endfacet")?;
        }
        writeln!(w, "endsolid lispcad")
    })
}

/// Writes Wavefront OBJ (shared vertices, 1-based faces, full f64 precision).
pub fn write_obj(mesh: &Mesh, path: impl AsRef<Path>) -> Result<(), MeshError> {
    write_atomic(path.as_ref(), |w| {
        writeln!(w, "# written by lispcad")?;
        for v in mesh.vertices() {
            writeln!(w, "v {} {} {}", v.x, v.y, v.z)?;
        }
        for t in mesh.triangles() {
            writeln!(w, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1)?;
        }
        Ok(())
    })
}

/// Reads Wavefront OBJ: `v` lines and `f` lines (`i`, `i/t`, `i//n`, `i/t/n`, negative indices
/// relative to the end); polygons are split into a fan of triangles. Other lines are ignored.
pub fn read_obj(path: impl AsRef<Path>) -> Result<Mesh, MeshError> {
    let path = path.as_ref();
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| io_err(path, e))?;
    parse_obj(&text, &name)
}

/// Parses OBJ text (`name` is used in error messages).
pub fn parse_obj(text: &str, name: &str) -> Result<Mesh, MeshError> {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for (ln, line) in text.lines().enumerate() {
        let mut it = line.split_ascii_whitespace();
        match it.next() {
            Some("v") => {
                let mut v = [0.0; 3];
                for (k, slot) in v.iter_mut().enumerate() {
                    let s = it.next().ok_or_else(|| {
                        parse_err(name, format!("line {}: vertex needs 3 coordinates", ln + 1))
                    })?;
                    *slot = s.parse().map_err(|_| {
                        parse_err(
                            name,
                            format!("line {}: coordinate {k} '{s}' is not a number", ln + 1),
                        )
                    })?;
                }
                vertices.push(DVec3::from_array(v));
            }
            Some("f") => {
                let mut poly = Vec::new();
                for s in it {
                    let first = s.split('/').next().unwrap_or("");
                    let i: i64 = first.parse().map_err(|_| {
                        parse_err(name, format!("line {}: bad face index '{s}'", ln + 1))
                    })?;
                    let n = vertices.len() as i64;
                    let j = if i > 0 { i - 1 } else { n + i };
                    if i == 0 || j < 0 || j >= n {
                        return Err(parse_err(
                            name,
                            format!(
                                "line {}: face index {i} outside the {n} vertices so far",
                                ln + 1
                            ),
                        ));
                    }
                    poly.push(j as u32);
                }
                if poly.len() < 3 {
                    return Err(parse_err(
                        name,
                        format!("line {}: a face needs 3 vertices", ln + 1),
                    ));
                }
                for k in 1..poly.len() - 1 {
                    let t = [poly[0], poly[k], poly[k + 1]];
                    if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
                        triangles.push(t);
                    }
                }
            }
            _ => {}
        }
    }
    Mesh::new(vertices, triangles)
}
