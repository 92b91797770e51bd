//! Surfaces and meshes as Lisp values: `type` → MESH for the discrete surfaces of papers
//! 001–003. Binds `geom::mesh` (reading, section, intersection, boundary, area).

use std::fmt;
use std::rc::Rc;

use glam::{DMat4, DVec3};

use crate::builtin;
use crate::builtins::geometry::{curve_value, vec3};
use crate::geom::curve::Curve;
use crate::geom::mesh::Mesh;
use crate::geom::mesh::Polyline3;
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::value::Object;
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!(
        "mesh-read",
        "(mesh-read \"file.stl\")",
        "Reads a triangle mesh from STL (ASCII or binary) or OBJ, welding shared vertices.",
        1,
        1,
        mesh_read
    ),
    builtin!(
        "mesh-write",
        "(mesh-write m \"file.obj\")",
        "Writes a mesh as STL (binary) or OBJ, by extension; returns the file name.",
        2,
        2,
        mesh_write
    ),
    builtin!(
        "surface-section",
        "(surface-section s plane-point plane-normal)",
        "The plane section of a surface: a list of polylines (closed where the section closes).",
        3,
        3,
        surface_section
    ),
    builtin!(
        "surface-intersect",
        "(surface-intersect s1 s2)",
        "The intersection curves of two surfaces, chained into polylines.",
        2,
        2,
        surface_intersect
    ),
    builtin!(
        "surface-area",
        "(surface-area s)",
        "The area of a surface.",
        1,
        1,
        surface_area
    ),
    builtin!(
        "surface-boundary",
        "(surface-boundary s)",
        "The boundary loops of a surface as closed polylines.",
        1,
        1,
        surface_boundary
    ),
];

/// A discrete surface (indexed triangle mesh): `type` → MESH.
pub struct MeshValue(pub Rc<Mesh>);

impl Object for MeshValue {
    fn type_name(&self) -> &'static str {
        "MESH"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(
            f,
            "#<MESH {} vertices, {} triangles>",
            self.0.vertices().len(),
            self.0.len()
        )
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

pub fn mesh_value(m: Mesh) -> Value {
    Value::obj(MeshValue(Rc::new(m)))
}

/// The mesh a surface-like value stands for.
pub fn mesh_of(v: &Value) -> Option<Rc<Mesh>> {
    v.as_obj::<MeshValue>().map(|m| m.0.clone())
}

pub fn is_surface(v: &Value) -> bool {
    mesh_of(v).is_some()
}

fn mesh_arg(it: &Interp, v: &Value) -> Result<Rc<Mesh>, Exn> {
    mesh_of(v).ok_or_else(|| bad_arg(it, "surfacep", v))
}

pub fn bbox_of(v: &Value) -> Option<(DVec3, DVec3)> {
    let m = mesh_of(v)?;
    let b = m.bounds()?;
    Some((b.min, b.max))
}

/// A transformed copy of a surface value; None when `v` is not one.
pub fn transform(v: &Value, m: &DMat4) -> Option<LResult> {
    let mesh = mesh_of(v)?;
    Some(
        mesh.map_vertices(|p| m.transform_point3(p))
            .map(mesh_value)
            .map_err(|e| err(e.to_string())),
    )
}

/// `(intersect curve surface)`: wired to the discrete-surface hit search (issue 6).
pub fn intersect_curve_surface(it: &mut Interp, a: &[Value]) -> LResult {
    crate::builtins::geometry::curve(it, &a[0])?;
    mesh_arg(it, &a[1])?;
    Err(err(
        "intersect: curve/surface intersection is not available in this build yet",
    ))
}

fn polylines(pls: Vec<Polyline3>) -> Result<Value, Exn> {
    let mut out = Vec::with_capacity(pls.len());
    for p in pls {
        let mut pts = p.points;
        if p.closed && pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        if pts.len() < 2 {
            continue;
        }
        let c = Curve::pline(pts, p.closed, None).map_err(crate::builtins::geometry::geom_err)?;
        out.push(curve_value(c));
    }
    Ok(Value::list(out))
}

fn mesh_read(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let path = it
        .resolve_path(&name)
        .ok_or_else(|| err(format!("mesh-read: cannot find \"{name}\"")))?;
    let m = crate::geom::mesh::read_mesh(&path).map_err(|e| err(e.to_string()))?;
    Ok(mesh_value(m))
}

fn mesh_write(it: &mut Interp, a: &[Value]) -> LResult {
    let mesh = mesh_arg(it, &a[0])?;
    let name = it.string(&a[1])?.to_string();
    let path = std::path::PathBuf::from(&name);
    if !it.ext::<crate::builtins::io::FsPolicy>().may_write(&path) {
        return Err(err(format!(
            "file access refused: {name} is outside the script and output directories (use --allow-fs)"
        )));
    }
    crate::geom::mesh::write_mesh(&mesh, &path).map_err(|e| err(e.to_string()))?;
    Ok(a[1].clone())
}

fn surface_section(it: &mut Interp, a: &[Value]) -> LResult {
    let mesh = mesh_arg(it, &a[0])?;
    let p = vec3(it, &a[1])?;
    let n = vec3(it, &a[2])?;
    let pls = crate::geom::mesh::section(&mesh, p, n).map_err(|e| err(e.to_string()))?;
    polylines(pls)
}

fn surface_intersect(it: &mut Interp, a: &[Value]) -> LResult {
    let m1 = mesh_arg(it, &a[0])?;
    let m2 = mesh_arg(it, &a[1])?;
    polylines(crate::geom::mesh::intersect_meshes(&m1, &m2))
}

fn surface_area(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(Value::Real(mesh_arg(it, &a[0])?.area()))
}

fn surface_boundary(it: &mut Interp, a: &[Value]) -> LResult {
    polylines(mesh_arg(it, &a[0])?.boundary())
}
