//! Surfaces and meshes as Lisp values (papers 001–003, SPEC §4): parametric surfaces
//! (`type` → SURFACE) kept parametric where the closed forms of paper 002 apply, and discrete
//! surfaces (`type` → MESH): indexed triangle meshes with shared vertices and adjacency.
//! Operations that work on the discrete surface tessellate a parametric argument first, within
//! the chord tolerance CHORDTOL.

use std::fmt;
use std::rc::Rc;
use std::sync::Arc;

use glam::{DMat4, DVec3};

use crate::builtin;
use crate::builtins::geometry::{curve, curve_value, geom_err, geomtol, point3, vec3};
use crate::builtins::system::SysVars;
use crate::geom::curve::Curve;
use crate::geom::mesh::{self, Mesh, Polyline3};
use crate::geom::surface::{self, ArcData, CurveRef, Surface};
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::value::Object;
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("ruled-surface", "(ruled-surface c1 c2)", "The ruled surface between two curves.", 2, 2, ruled_surface),
    builtin!("revolve-surface", "(revolve-surface profile axis-point axis-dir angle)", "The surface of revolution of a profile curve about an axis, through angle radians.", 4, 4, revolve_surface),
    builtin!("sweep-surface", "(sweep-surface profile path)", "A profile swept along a guide curve (rotation-minimising frame).", 2, 2, sweep_surface),
    builtin!("boundary-surface", "(boundary-surface c1 c2 c3 c4)", "The Coons patch bounded by four curves in order around it.", 4, 4, boundary_surface),
    builtin!("plane-surface", "(plane-surface closed-curve)", "The planar region inside a closed curve.", 1, 1, plane_surface),
    builtin!("cylinder-surface", "(cylinder-surface base-center axis-dir radius height)", "A cylinder.", 4, 4, cylinder_surface),
    builtin!("sphere-surface", "(sphere-surface center radius)", "A sphere.", 2, 2, sphere_surface),
    builtin!("mesh-surface", "(mesh-surface s [chord-tol])", "The discrete surface: an indexed triangle mesh within chord-tol (default CHORDTOL).", 1, 2, mesh_surface),
    builtin!("mesh-read", "(mesh-read \"file.stl\")", "Reads a triangle mesh from STL (ASCII or binary) or OBJ, welding shared vertices.", 1, 1, mesh_read),
    builtin!("mesh-write", "(mesh-write m \"file.obj\")", "Writes a surface or mesh as STL (binary) or OBJ, by extension; returns the file name.", 2, 2, mesh_write),
    builtin!("surface-section", "(surface-section s plane-point plane-normal)", "The plane section of a surface: a list of polylines (closed where the section closes), on the true surface within GEOMTOL; a plane touching it at a point gives that point (x y z); a region lying in the plane gives that region's boundary as closed loops.", 3, 3, surface_section),
    builtin!("surface-intersect", "(surface-intersect s1 s2)", "The intersection curves of two surfaces, chained into polylines on both true surfaces within GEOMTOL; a tangent contact as a point (x y z); where they coincide over a region (any kinds), that region's boundary as closed loops; where they coincide everywhere with no boundary (equal spheres), (s1) itself.", 2, 2, surface_intersect),
    builtin!("trim-surface", "(trim-surface s cutter keep-point)", "The part of s, cut along its intersection with cutter, that holds the point nearest keep-point.", 3, 3, trim_surface),
    builtin!("surface-corners", "(surface-corners s [angle])", "The boundary corners: where the boundary's tangent turns by more than angle (default 30 degrees, in radians).", 1, 2, surface_corners),
    builtin!("extend-surface", "(extend-surface s distance [angle] [holes])", "The surface extended outward by distance along its boundary, split at corners (angle as surface-corners); holes extended inward unless holes is nil; an error where the strips would overlap.", 2, 4, extend_surface),
    builtin!("surface-area", "(surface-area s)", "The area of a surface.", 1, 1, surface_area),
    builtin!("surface-boundary", "(surface-boundary s)", "The boundary loops of a surface as closed polylines.", 1, 1, surface_boundary),
];

/// A parametric surface: `type` → SURFACE.
pub struct SurfaceValue(pub Surface);

impl Object for SurfaceValue {
    fn type_name(&self) -> &'static str {
        "SURFACE"
    }
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        let kind = match &self.0 {
            Surface::Ruled(_) => "RULED",
            Surface::Revolve(_) => "REVOLVED",
            Surface::Sweep(_) => "SWEPT",
            Surface::Coons(_) => "BOUNDARY",
            Surface::Plane(_) => "PLANE",
            Surface::Cylinder(c) => {
                return write!(
                    f,
                    "#<SURFACE CYLINDER R{} H{}>",
                    crate::geom::curve::fmt_g(c.radius),
                    crate::geom::curve::fmt_g(c.height)
                )
            }
            Surface::Sphere(s) => {
                return write!(
                    f,
                    "#<SURFACE SPHERE R{}>",
                    crate::geom::curve::fmt_g(s.radius)
                )
            }
        };
        write!(f, "#<SURFACE {kind}>")
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

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

fn surface_value(s: Surface) -> Value {
    Value::obj(SurfaceValue(s))
}

fn mesh_err(e: impl fmt::Display) -> Exn {
    err(e.to_string())
}

/// The chord tolerance for tessellating parametric surfaces (CHORDTOL).
fn chord_tol(it: &mut Interp) -> f64 {
    it.ext::<SysVars>().real("CHORDTOL")
}

/// A surface or mesh argument.
enum Surf {
    Param(Surface),
    Discrete(Rc<Mesh>),
}

fn surf(it: &Interp, v: &Value) -> Result<Surf, Exn> {
    if let Some(s) = v.as_obj::<SurfaceValue>() {
        return Ok(Surf::Param(s.0.clone()));
    }
    if let Some(m) = v.as_obj::<MeshValue>() {
        return Ok(Surf::Discrete(m.0.clone()));
    }
    Err(bad_arg(it, "surfacep", v))
}

/// The discrete surface of a surface-like value (a parametric one tessellated).
fn discrete(it: &mut Interp, v: &Value) -> Result<Rc<Mesh>, Exn> {
    match surf(it, v)? {
        Surf::Discrete(m) => Ok(m),
        Surf::Param(s) => {
            let tol = chord_tol(it);
            Ok(Rc::new(surface::mesh_surface(&s, tol).map_err(mesh_err)?))
        }
    }
}

/// The mesh a surface-like value stands for (a parametric one tessellated within CHORDTOL);
/// None when `v` is not a surface, an error when it cannot be tessellated.
pub fn mesh_of(it: &mut Interp, v: &Value) -> Option<Result<Rc<Mesh>, Exn>> {
    is_surface(v).then(|| discrete(it, v))
}

pub fn is_surface(v: &Value) -> bool {
    v.as_obj::<MeshValue>().is_some() || v.as_obj::<SurfaceValue>().is_some()
}

pub fn bbox_of(it: &mut Interp, v: &Value) -> Option<Result<(DVec3, DVec3), Exn>> {
    let mesh = mesh_of(it, v)?;
    Some(mesh.and_then(|m| {
        m.bounds()
            .map(|b| (b.min, b.max))
            .ok_or_else(|| err("bbox: the surface is empty"))
    }))
}

/// A transformed copy of a surface-like value (a parametric surface becomes its mesh); None
/// when `v` is not one.
pub fn transform(it: &mut Interp, v: &Value, m: &DMat4) -> Option<LResult> {
    let mesh = mesh_of(it, v)?;
    Some(mesh.and_then(|mesh| mesh.transformed(m).map(mesh_value).map_err(mesh_err)))
}

fn curve_ref(it: &Interp, v: &Value) -> Result<CurveRef, Exn> {
    Ok(Arc::new(curve(it, v)?.clone()))
}

/// The hits of a curve on a surface or mesh: `(curve parameter, point, kind)`, or the curve
/// itself when it lies on the surface (an OVERLAP). Closed forms for lines against cylinders,
/// planes and spheres and circles/arcs against planes (paper 002); other curves and surfaces
/// through the mesh, refined on the true curve and surface to GEOMTOL; any curve against a mesh
/// through its hierarchy.
fn curve_surface_hits(it: &mut Interp, a: &[Value]) -> Result<CurveSurfaceHits, Exn> {
    let c = curve(it, &a[0])?.clone();
    let s = surf(it, &a[1])?;
    let tol = geomtol(it);
    let ctol = chord_tol(it);
    if let Surf::Param(s) = &s {
        if surface::curve_on_surface(&c, s, tol).map_err(mesh_err)? {
            return Ok(CurveSurfaceHits::Overlap(c));
        }
    }
    let with_t = |pts: Vec<DVec3>| -> Vec<(f64, DVec3)> {
        pts.into_iter().map(|p| (c.closest_point(p).0, p)).collect()
    };
    let hits: Vec<(f64, DVec3)> = match (&c, &s) {
        (
            Curve::Line(l),
            Surf::Param(s @ (Surface::Cylinder(_) | Surface::Plane(_) | Surface::Sphere(_))),
        ) => surface::segment_surface_hits(l.p0, l.p1, s, tol).map_err(mesh_err)?,
        (Curve::Circle(ci), Surf::Param(s @ Surface::Plane(_))) => {
            let arc = ArcData::circle(ci.center(), ci.radius(), ci.normal());
            with_t(surface::arc_surface_hits(&arc, s, tol).map_err(mesh_err)?)
        }
        (Curve::Arc(ar), Surf::Param(s @ Surface::Plane(_))) => {
            let arc = ArcData {
                center: ar.center(),
                radius: ar.radius(),
                normal: ar.normal(),
                start_angle: ar.start_angle(),
                end_angle: ar.end_angle(),
            };
            with_t(surface::arc_surface_hits(&arc, s, tol).map_err(mesh_err)?)
        }
        (_, Surf::Param(s)) => {
            surface::curve_surface_hits_refined(&c, s, ctol, tol).map_err(mesh_err)?
        }
        (Curve::Line(l), Surf::Discrete(m)) => surface::polyline_mesh_hits(&[l.p0, l.p1], m)
            .into_iter()
            .map(|h| (h.t, h.point))
            .collect(),
        (_, Surf::Discrete(m)) => surface::curve_mesh_hits(&c, m, ctol.min(1e-3))
            .into_iter()
            .map(|h| (h.t, h.point))
            .collect(),
    };
    Ok(CurveSurfaceHits::Points(hits))
}

enum CurveSurfaceHits {
    Points(Vec<(f64, DVec3)>),
    Overlap(Curve),
}

/// `(intersect curve surface [near])`: the points, sorted along the curve, or the curve itself
/// in the list when it lies on the surface.
pub fn intersect_curve_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let mut pts: Vec<DVec3> = match curve_surface_hits(it, a)? {
        CurveSurfaceHits::Overlap(c) => {
            if a.get(2).is_some_and(|v| v.truthy()) {
                let near = vec3(it, &a[2])?;
                return Ok(point3(c.closest_point(near).1));
            }
            return Ok(Value::list(vec![curve_value(c)]));
        }
        CurveSurfaceHits::Points(h) => h.into_iter().map(|(_, p)| p).collect(),
    };
    if let Some(near) = a.get(2).filter(|v| v.truthy()) {
        let near = vec3(it, near)?;
        pts.sort_by(|p, q| p.distance(near).total_cmp(&q.distance(near)));
        return Ok(pts.first().map_or(Value::Nil, |p| point3(*p)));
    }
    Ok(Value::list(pts.into_iter().map(point3).collect::<Vec<_>>()))
}

/// `(intersect-info curve surface)`: one association list per hit, t1 the curve's parameter, t2
/// nil (a surface has two parameters); kind CROSS, or OVERLAP (with `(curve . c)`) when the curve
/// lies on the surface.
pub fn intersect_info_curve_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let field = |it: &mut Interp, k: &str, v: Value| Value::cons(Value::Sym(it.intern(k)), v);
    let kind = |it: &mut Interp, k: &str| {
        let v = Value::Sym(it.intern(k));
        field(it, "KIND", v)
    };
    let hits = curve_surface_hits(it, a)?;
    let mut out = Vec::new();
    match hits {
        CurveSurfaceHits::Overlap(c) => {
            let fields = vec![
                field(it, "POINT", point3(c.eval(0.0))),
                field(it, "T1", Value::Real(0.0)),
                field(it, "T2", Value::Nil),
                kind(it, "OVERLAP"),
                field(it, "CURVE", curve_value(c)),
            ];
            out.push(Value::list(fields));
        }
        CurveSurfaceHits::Points(h) => {
            for (t, p) in h {
                let fields = vec![
                    field(it, "POINT", point3(p)),
                    field(it, "T1", Value::Real(t)),
                    field(it, "T2", Value::Nil),
                    kind(it, "CROSS"),
                ];
                out.push(Value::list(fields));
            }
        }
    }
    Ok(Value::list(out))
}

/// Polylines as PLINE curves (closed ones closed); a one-point polyline (an isolated tangent
/// contact) as the point `(x y z)`.
fn polylines(pls: Vec<Polyline3>) -> LResult {
    let mut out = Vec::with_capacity(pls.len());
    for p in pls {
        let mut pts = p.points;
        if pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        // Chaining can leave points closer than a polyline segment may be: drop repeats.
        pts.dedup_by(|a, b| a.distance(*b) <= 1e-12 * (1.0 + a.length()));
        let closed = p.closed && pts.len() >= 3;
        if pts.len() == 1 {
            out.push(point3(pts[0]));
            continue;
        }
        if pts.len() < 2 {
            continue;
        }
        out.push(curve_value(
            Curve::pline(pts, closed, None).map_err(geom_err)?,
        ));
    }
    Ok(Value::list(out))
}

fn ruled_surface(it: &mut Interp, a: &[Value]) -> LResult {
    Ok(surface_value(Surface::ruled(
        curve_ref(it, &a[0])?,
        curve_ref(it, &a[1])?,
    )))
}

fn revolve_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let s = Surface::revolve(
        curve_ref(it, &a[0])?,
        vec3(it, &a[1])?,
        vec3(it, &a[2])?,
        it.num(&a[3])?,
    )
    .map_err(mesh_err)?;
    Ok(surface_value(s))
}

fn sweep_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let s = Surface::sweep(curve_ref(it, &a[0])?, curve_ref(it, &a[1])?).map_err(mesh_err)?;
    Ok(surface_value(s))
}

fn boundary_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let cs = [
        curve_ref(it, &a[0])?,
        curve_ref(it, &a[1])?,
        curve_ref(it, &a[2])?,
        curve_ref(it, &a[3])?,
    ];
    Ok(surface_value(Surface::boundary(cs).map_err(mesh_err)?))
}

fn plane_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let c = curve(it, &a[0])?;
    if !c.is_closed() {
        return Err(err("plane-surface: the boundary curve must be closed"));
    }
    let mut pts = c.points(geomtol(it).max(1e-6)).map_err(geom_err)?;
    if pts.len() > 1
        && pts
            .first()
            .zip(pts.last())
            .is_some_and(|(p, q)| p.distance(*q) < 1e-12)
    {
        pts.pop();
    }
    Ok(surface_value(Surface::plane(pts).map_err(mesh_err)?))
}

fn cylinder_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let s = Surface::cylinder(
        vec3(it, &a[0])?,
        vec3(it, &a[1])?,
        it.num(&a[2])?,
        it.num(&a[3])?,
    )
    .map_err(mesh_err)?;
    Ok(surface_value(s))
}

fn sphere_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let s = Surface::sphere(vec3(it, &a[0])?, it.num(&a[1])?).map_err(mesh_err)?;
    Ok(surface_value(s))
}

fn mesh_surface(it: &mut Interp, a: &[Value]) -> LResult {
    match surf(it, &a[0])? {
        Surf::Discrete(_) => Ok(a[0].clone()),
        Surf::Param(s) => {
            let tol = match a.get(1) {
                None | Some(Value::Nil) => chord_tol(it),
                Some(t) => it.num(t)?,
            };
            let m = surface::mesh_surface(&s, tol).map_err(mesh_err)?;
            charge_mesh(it, &m, tol)?;
            Ok(mesh_value(m))
        }
    }
}

/// A mesh's cost: its triangles are charged to the step budget and its memory to the memory
/// budget, with the tolerance to raise named when either runs out. (The geometry core bounds
/// the triangles a tolerance can ask for; this keeps a script's many meshes within budget.)
fn charge_mesh(it: &mut Interp, m: &Mesh, tol: f64) -> Result<(), Exn> {
    let tris = m.len() as u64;
    let hint = |e: Exn| {
        err(format!(
            "mesh-surface: {tris} triangles at chord tolerance {tol} ({}): raise CHORDTOL or the chord-tol argument",
            e.message
        ))
    };
    it.charge(tris.saturating_mul(16)).map_err(hint)?;
    crate::lang::memory::check().map_err(hint)
}

fn mesh_read(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let path = it
        .resolve_path(&name)
        .ok_or_else(|| err(format!("mesh-read: cannot find \"{name}\"")))?;
    // Read through the policy (confined under --sandbox) and within the memory budget, then
    // parsed from memory; the mesh takes about as much again.
    let bytes = it
        .ext::<crate::builtins::io::FsPolicy>()
        .read_bytes(&path)?;
    it.charge(bytes.len() as u64)?;
    crate::lang::memory::reserve(bytes.len())?;
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let m = match ext.as_deref() {
        Some("stl") => mesh::parse_stl(&bytes, 0.0, &shown).map(|(m, _)| m),
        Some("obj") => match std::str::from_utf8(&bytes) {
            Ok(text) => mesh::parse_obj(text, &shown),
            Err(_) => return Err(err(format!("mesh-read: {shown} is not UTF-8 text"))),
        },
        _ => mesh::read_mesh(&path),
    };
    Ok(mesh_value(m.map_err(mesh_err)?))
}

fn mesh_write(it: &mut Interp, a: &[Value]) -> LResult {
    let m = discrete(it, &a[0])?;
    let name = it.string(&a[1])?.to_string();
    let path = match &it.base_dir {
        Some(b) if std::path::Path::new(&name).is_relative() => b.join(&name),
        _ => std::path::PathBuf::from(&name),
    };
    // Written through the confined directory; the file is created 0644 like every output.
    let c = it
        .ext::<crate::builtins::io::FsPolicy>()
        .confine(&path, crate::builtins::io::Access::Write)
        .map_err(err)?;
    mesh::write_mesh(&m, &c.path).map_err(mesh_err)?;
    crate::builtins::io::make_public(&c.path);
    Ok(a[1].clone())
}

fn surface_section(it: &mut Interp, a: &[Value]) -> LResult {
    let p = vec3(it, &a[1])?;
    let n = vec3(it, &a[2])?;
    match surf(it, &a[0])? {
        Surf::Param(s) => {
            let (tol, gtol) = (chord_tol(it), geomtol(it));
            polylines(surface::surface_section_tol(&s, p, n, tol, gtol).map_err(mesh_err)?)
        }
        Surf::Discrete(m) => polylines(mesh::section(&m, p, n).map_err(mesh_err)?),
    }
}

fn surface_intersect(it: &mut Interp, a: &[Value]) -> LResult {
    if let (Surf::Param(s1), Surf::Param(s2)) = (surf(it, &a[0])?, surf(it, &a[1])?) {
        let (tol, gtol) = (chord_tol(it), geomtol(it));
        return match surface::surface_meet(&s1, &s2, tol, gtol).map_err(mesh_err)? {
            surface::Meet::Curves(c) => polylines(c),
            // Coincident everywhere, no boundary: the common surface itself (an OVERLAP).
            surface::Meet::Everywhere => Ok(Value::list(vec![a[0].clone()])),
        };
    }
    let (m1, m2) = (discrete(it, &a[0])?, discrete(it, &a[1])?);
    polylines(mesh::intersect_meshes(&m1, &m2))
}

fn trim_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let m = discrete(it, &a[0])?;
    let cutter = discrete(it, &a[1])?;
    let keep = vec3(it, &a[2])?;
    let t = mesh::trim(&m, &cutter, keep).map_err(mesh_err)?;
    Ok(mesh_value(t.kept))
}

fn corner_angle(it: &Interp, a: &[Value], i: usize) -> Result<f64, Exn> {
    match a.get(i) {
        None | Some(Value::Nil) => Ok(30f64.to_radians()),
        Some(v) => it.num(v),
    }
}

fn surface_corners(it: &mut Interp, a: &[Value]) -> LResult {
    let m = discrete(it, &a[0])?;
    let angle = corner_angle(it, a, 1)?;
    let cs = mesh::corners(&m, angle).map_err(mesh_err)?;
    Ok(Value::list(cs.into_iter().map(point3).collect::<Vec<_>>()))
}

fn extend_surface(it: &mut Interp, a: &[Value]) -> LResult {
    let m = discrete(it, &a[0])?;
    let d = it.num(&a[1])?;
    let angle = corner_angle(it, a, 2)?;
    let holes = a.get(3).is_none_or(|v| v.truthy());
    Ok(mesh_value(
        mesh::extend_with(&m, d, angle, holes).map_err(mesh_err)?,
    ))
}

fn surface_area(it: &mut Interp, a: &[Value]) -> LResult {
    match surf(it, &a[0])? {
        Surf::Param(s) => {
            let tol = chord_tol(it);
            Ok(Value::Real(
                surface::surface_area(&s, tol).map_err(mesh_err)?,
            ))
        }
        Surf::Discrete(m) => Ok(Value::Real(m.area())),
    }
}

fn surface_boundary(it: &mut Interp, a: &[Value]) -> LResult {
    match surf(it, &a[0])? {
        Surf::Param(s) => {
            let tol = chord_tol(it);
            polylines(surface::surface_boundary(&s, tol).map_err(mesh_err)?)
        }
        Surf::Discrete(m) => polylines(m.boundary()),
    }
}
