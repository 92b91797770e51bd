//! The current drawing: `draw`, `layer`, `save`, `clear-drawing`, and writing the drawing at
//! the end of a run. Curves and meshes become AutoCAD entities here (`geom` stays unaware of
//! the drawing; `output` of the language).

use std::path::{Path, PathBuf};

use glam::{DVec2, DVec3};

use crate::builtin;
use crate::builtins::fs_policy::Confined;
use crate::builtins::geometry::CurveValue;
use crate::builtins::io::FsPolicy;
use crate::builtins::surfaces::mesh_of;
use crate::builtins::system::SysVars;
use crate::geom::curve::Curve;
use crate::geom::frame::arbitrary_axis;
use crate::lang::builtin::{bad_arg, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};
use crate::output::{Drawing, DxfProfile, Entity, EntityKind, OutputOptions};

pub static BUILTINS: &[Builtin] = &[
    builtin!("draw", "(draw v [layer])", "Adds a curve, a mesh, or a list of them to the drawing (on layer, else the current layer); returns v.", 1, 2, draw),
    builtin!("layer", "(layer name [color])", "Makes name the current layer (created if new; color an ACI number); returns the name.", 1, 2, layer),
    builtin!("save", "(save \"file.svg\"|\"file.dxf\")", "Writes the drawing (format from the extension, DXF profile from DXFPROFILE); returns the file name.", 1, 1, save),
    builtin!("clear-drawing", "(clear-drawing)", "Removes every entity and layer from the drawing; returns nil.", 0, 0, clear_drawing),
    builtin!("dxf-open", "(dxf-open \"file.dxf\")", "Replaces the drawing with a DXF file (ASCII or binary, R12..R2018); saving as DXF writes it back losslessly in its version. Returns the file name.", 1, 1, dxf_open),
    builtin!("entity-curve", "(entity-curve ename)", "The CURVE of a LINE, ARC, CIRCLE, LWPOLYLINE (with bulges), POLYLINE or SPLINE entity, or nil for other entities.", 1, 1, entity_curve),
    builtin!("dxf-import", "(dxf-import \"file.dxf\")", "Adds the entities and layers of a DXF file to the drawing (new handles); returns a selection set of the added entities, or nil.", 1, 1, dxf_import),
];

/// The drawing of an interpreter.
pub fn drawing(it: &mut Interp) -> &mut Drawing {
    it.ext::<Drawing>()
}

fn draw_err(e: impl std::fmt::Display) -> Exn {
    err(e.to_string())
}

/// The entity for a curve: LINE, CIRCLE, ARC, LWPOLYLINE (planar) or 3D POLYLINE, SPLINE.
pub fn curve_entity(c: &Curve) -> EntityKind {
    match c {
        Curve::Line(l) => EntityKind::Line { p0: l.p0, p1: l.p1 },
        Curve::Circle(c) => EntityKind::Circle {
            center: c.center(),
            radius: c.radius(),
            normal: c.normal(),
        },
        Curve::Arc(a) => EntityKind::Arc {
            center: a.center(),
            radius: a.radius(),
            start: a.start_angle(),
            end: a.end_angle(),
            normal: a.normal(),
        },
        Curve::Polyline(p) => polyline_entity(p),
        Curve::Spline(s) => EntityKind::Spline {
            curve: s
                .to_bspline_simple_knots()
                .unwrap_or_else(|| s.to_bspline()),
            fit_points: Vec::new(),
            closed: s.closed,
        },
        // Drawn as the exact degree-2 rational SPLINE until the drawing has ELLIPSE entities.
        Curve::Ellipse(e) => {
            let (ctrl, knots, weights) = e.nurbs();
            EntityKind::Spline {
                curve: crate::geom::bspline::BSpline::new(2, ctrl, Some(knots), Some(weights))
                    .expect("an ellipse's NURBS is valid"),
                fit_points: Vec::new(),
                closed: e.is_full(),
            }
        }
        Curve::BSpline(b) => EntityKind::Spline {
            curve: b.clone(),
            fit_points: Vec::new(),
            closed: false,
        },
    }
}

/// A polyline lying in a plane perpendicular to its normal becomes an LWPOLYLINE in that
/// normal's OCS; one that leaves its plane is a 3D POLYLINE.
fn polyline_entity(p: &crate::geom::polyline::Polyline) -> EntityKind {
    let n = p.normal();
    let v = p.vertices();
    let elevation = v[0].dot(n);
    let planar = v
        .iter()
        .all(|q| (q.dot(n) - elevation).abs() <= 1e-9 * (1.0 + q.length()));
    if planar {
        let (ax, ay) = arbitrary_axis(n);
        EntityKind::LwPolyline {
            points: v.iter().map(|q| DVec2::new(q.dot(ax), q.dot(ay))).collect(),
            bulges: p.bulges().to_vec(),
            closed: p.is_closed(),
            elevation,
            normal: n,
        }
    } else {
        EntityKind::Polyline {
            points: v.to_vec(),
            bulges: p.bulges().to_vec(),
            closed: p.is_closed(),
        }
    }
}

/// Adds a drawable value (curve, mesh, or a list of them) on `layer`.
fn add_value(it: &mut Interp, v: &Value, layer: &str) -> Result<(), Exn> {
    if let Some(c) = v.as_obj::<CurveValue>() {
        let kind = curve_entity(&c.0);
        drawing(it)
            .add(Entity::new(layer, kind))
            .map_err(draw_err)?;
        return Ok(());
    }
    if let Some(m) = mesh_of(it, v) {
        let m = m?;
        let kind = EntityKind::Mesh {
            vertices: m.vertices().to_vec(),
            triangles: m
                .triangles()
                .iter()
                .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
                .collect(),
        };
        drawing(it)
            .add(Entity::new(layer, kind))
            .map_err(draw_err)?;
        return Ok(());
    }
    if let Value::Cons(_) = v {
        if let Ok(p) = it.point(v) {
            let kind = EntityKind::Point {
                p: DVec3::from_array(p),
            };
            drawing(it)
                .add(Entity::new(layer, kind))
                .map_err(draw_err)?;
            return Ok(());
        }
        for x in v.iter().cloned().collect::<Vec<_>>() {
            add_value(it, &x, layer)?;
        }
        return Ok(());
    }
    Err(bad_arg(it, "drawablep", v))
}

fn draw(it: &mut Interp, a: &[Value]) -> LResult {
    let layer = match a.get(1) {
        Some(Value::Nil) | None => drawing(it).current_layer().to_string(),
        Some(l) => {
            let name = it.string(l)?.to_string();
            drawing(it).ensure_layer(&name).map_err(draw_err)?
        }
    };
    add_value(it, &a[0], &layer)?;
    Ok(a[0].clone())
}

fn layer(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let color = match a.get(1) {
        None | Some(Value::Nil) => None,
        Some(c) => {
            let c = it.int(c)?;
            if !(1..=255).contains(&c) {
                return Err(err(format!(
                    "layer: color must be an ACI number 1..255, got {c}"
                )));
            }
            Some(c as i16)
        }
    };
    drawing(it).use_layer(&name, color).map_err(draw_err)?;
    Ok(a[0].clone())
}

/// Writer options given on the command line (`--dxf-profile`, `--cam-tol`, `--cam-min-seg`,
/// `--dpi`): they win over the system variables. The host fills it in; the library never
/// reads CLI structs.
#[derive(Clone, Debug, Default)]
pub struct OutputOverrides {
    pub dxf_profile: Option<String>,
    pub cam_tol: Option<f64>,
    pub cam_min_seg: Option<f64>,
    pub dpi: Option<f64>,
}

/// The writer options from the system variables, overridden by the command line.
pub fn output_options(
    it: &mut Interp,
    common: Option<&OutputOverrides>,
) -> Result<OutputOptions, Exn> {
    let vars = it.ext::<SysVars>();
    let mut o = OutputOptions::default();
    if let Some(Value::Str(p)) = vars.get("DXFPROFILE") {
        o.dxf_profile = p.parse::<DxfProfile>().map_err(draw_err)?;
    }
    o.cam_tol = vars.real("CAMTOL");
    o.insunits = vars.int("INSUNITS");
    if let Some(v) = vars.get("VIEWDIR").cloned() {
        o.view_dir = DVec3::from_array(it.point(&v)?);
    }
    if let Some(c) = common {
        if let Some(p) = &c.dxf_profile {
            o.dxf_profile = p.parse::<DxfProfile>().map_err(draw_err)?;
        }
        if let Some(t) = c.cam_tol {
            o.cam_tol = t;
        }
        if let Some(t) = c.cam_min_seg {
            o.cam_min_seg = t;
        }
        if let Some(t) = c.dpi {
            o.dpi = t;
        }
    }
    o.validate().map_err(draw_err)?;
    Ok(o)
}

/// Saves through the write policy: the file is replaced atomically in the confined directory.
fn save_to(it: &mut Interp, path: &Path, opts: &OutputOptions) -> Result<(), Exn> {
    let policy = std::mem::take(it.ext::<FsPolicy>());
    let r = save_prepared(
        &policy,
        &crate::output::Prepared::new(drawing(it)),
        path,
        opts,
    );
    *it.ext::<FsPolicy>() = policy;
    r
}

/// Saves `path` (confined by `policy`, through the output directory handles it holds).
fn save_prepared(
    policy: &FsPolicy,
    p: &crate::output::Prepared,
    path: &Path,
    opts: &OutputOptions,
) -> Result<(), Exn> {
    let c = policy.confine_output(path).map_err(err)?;
    match write_confined(p, &c, path, opts) {
        // The directory held was removed since it was opened: open it again by its path (it
        // may have been re-created), or say that it is gone.
        Err(crate::output::OutputError::Io { source, .. })
            if c.was_cached() && source.kind() == std::io::ErrorKind::NotFound =>
        {
            policy.dirs.clear();
            let c = policy.confine_output(path).map_err(|m| {
                err(format!(
                    "save {}: its directory was removed during the run ({m})",
                    path.display()
                ))
            })?;
            write_confined(p, &c, path, opts).map_err(|e| save_error(&c, path, e))
        }
        r => r.map_err(|e| save_error(&c, path, e)),
    }
}

fn write_confined(
    p: &crate::output::Prepared,
    c: &Confined,
    path: &Path,
    opts: &OutputOptions,
) -> Result<(), crate::output::OutputError> {
    match c.dir_and_name() {
        Some((dir, name)) => crate::output::save_prepared_at(p, dir, name, path, opts),
        None => crate::output::save_prepared(p, &c.path, opts),
    }
}

fn save_error(c: &Confined, path: &Path, e: crate::output::OutputError) -> Exn {
    let msg = e
        .to_string()
        .replace(&c.path.display().to_string(), &path.display().to_string());
    err(format!("save {}: {msg}", path.display()))
}

fn save(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let path = match &it.base_dir {
        Some(b) if Path::new(&name).is_relative() => b.join(&name),
        _ => PathBuf::from(&name),
    };
    let opts = output_options(it, None)?;
    save_to(it, &path, &opts)?;
    Ok(a[0].clone())
}

fn clear_drawing(it: &mut Interp, _: &[Value]) -> LResult {
    drawing(it).clear();
    forget_pending(it);
    Ok(Value::Nil)
}

/// A half-made POLYLINE or a command waiting for input belonged to the old drawing.
fn forget_pending(it: &mut Interp) {
    it.ext::<crate::builtins::entities::EntityState>()
        .pending_polyline = None;
    *it.ext::<crate::builtins::command::CommandState>() = Default::default();
}

/// Make the DXF file at `path` the interpreter's drawing (`--open`, `dxf-open`). Returns the
/// `--recover` note to show when damaged groups were skipped.
pub fn open_into(it: &mut Interp, path: &Path, recover: bool) -> Result<Option<String>, String> {
    let d = crate::output::open_drawing(path, recover).map_err(|e| e.to_string())?;
    let note = crate::output::dxfin::recover_note(path, &d);
    *drawing(it) = d;
    forget_pending(it);
    // DWGNAME/DWGPREFIX name the opened drawing, as in AutoCAD.
    it.ext::<SysVars>().set_drawing_path(path);
    Ok(note)
}

fn script_path(it: &Interp, name: &str) -> PathBuf {
    match &it.base_dir {
        Some(b) if Path::new(name).is_relative() => b.join(name),
        _ => PathBuf::from(name),
    }
}

/// A drawing the script names, read through the file policy (confined under --sandbox) and
/// within the memory budget.
fn read_drawing(it: &mut Interp, path: &Path) -> Result<crate::output::Drawing, Exn> {
    let data = it.ext::<FsPolicy>().read_bytes(path)?;
    // The model takes a few times the file's size.
    crate::lang::memory::reserve(data.len().saturating_mul(4))?;
    crate::output::read_dxf(&data, false).map_err(|e| err(e.with_path(path).to_string()))
}

fn dxf_open(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let path = script_path(it, &name);
    let d = read_drawing(it, &path)?;
    *drawing(it) = d;
    forget_pending(it);
    it.ext::<SysVars>().set_drawing_path(&path);
    Ok(a[0].clone())
}

/// The curve of an entity's geometry (the inverse of `curve_entity`), if it is a curve.
pub fn entity_to_curve(kind: &EntityKind) -> Option<Curve> {
    crate::builtins::vla::curve::entity_curve(kind)?.ok()
}

fn entity_curve(it: &mut Interp, a: &[Value]) -> LResult {
    let e = crate::builtins::entities::ename_arg(it, &a[0])?;
    let kind = drawing(it).get(e.handle).map(|x| x.kind.clone());
    Ok(match kind.as_ref().and_then(entity_to_curve) {
        Some(c) if e.sub == 0 => crate::builtins::geometry::curve_value(c),
        _ => Value::Nil,
    })
}

fn dxf_import(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let path = script_path(it, &name);
    let other = read_drawing(it, &path)?;
    let d = drawing(it);
    // Entities kept as their groups (INSERT, HATCH...) can only be written with the document
    // they came from: the R2000 writer of new drawings would drop them. An untouched drawing
    // takes the file whole (with its handles, which nothing yet refers to); any other
    // drawing made from scratch takes it with every record relocated above its own handles.
    let added = if d.document().is_some() || !other.has_kept_entities() {
        d.import(&other)
    } else if d.is_untouched() && other.document().is_some() {
        *d = other;
        d.entities().map(|e| e.handle).collect()
    } else {
        d.import_relocated(&other).map_err(|e| {
            err(format!(
                "dxf-import: {} has entities lispcad keeps only as read (INSERT, HATCH, MTEXT, \
                 DIMENSION...) and {e}",
                path.display()
            ))
        })?
    };
    if added.is_empty() {
        return Ok(Value::Nil);
    }
    Ok(crate::builtins::entities::pickset_value(it, added))
}

/// The drawing as SVG with the run's writer options (a row of a contact sheet).
pub fn drawing_svg(
    it: &mut Interp,
    overrides: impl Into<OutputOverrides>,
) -> Result<String, String> {
    let overrides = overrides.into();
    let opts = output_options(it, Some(&overrides)).map_err(|e| e.message.clone())?;
    Ok(crate::output::svg::write_svg(drawing(it), &opts))
}

/// Writes the drawing to each output path after a run (`-o`); nothing is written for a run
/// that failed, and each file appears whole or not at all.
pub fn write_outputs(
    it: &mut Interp,
    outputs: &[PathBuf],
    overrides: impl Into<OutputOverrides>,
) -> Result<(), String> {
    if outputs.is_empty() {
        return Ok(());
    }
    let overrides = overrides.into();
    let opts = output_options(it, Some(&overrides)).map_err(|e| e.message.clone())?;
    for o in outputs {
        crate::output::Format::from_path(o).map_err(|e| e.to_string())?;
    }
    // The policy is taken out for the loop (the drawing is borrowed meanwhile) and put back.
    let mut policy = std::mem::take(it.ext::<FsPolicy>());
    // The files of one call share their directories' handles even where the policy keeps
    // none across calls (`run -o a.dxf -o a.svg` opens their directory once).
    let own = !policy.dirs.is_on();
    if own {
        policy.dirs = crate::builtins::fs_policy::DirCache::new();
    }
    let prepared = crate::output::Prepared::new(drawing(it));
    let r = outputs
        .iter()
        .try_for_each(|o| save_prepared(&policy, &prepared, o, &opts))
        .map_err(|e| e.message);
    if own {
        policy.dirs = Default::default();
    }
    *it.ext::<FsPolicy>() = policy;
    r
}
