//! The current drawing: `draw`, `layer`, `save`, `clear-drawing`, and writing the drawing at
//! the end of a run. Curves and meshes become AutoCAD entities here (`geom` stays unaware of
//! the drawing; `output` of the language).

use std::path::{Path, PathBuf};

use glam::{DVec2, DVec3};

use crate::builtin;
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

/// The writer options from the system variables, overridden by the command line.
pub fn output_options(
    it: &mut Interp,
    common: Option<&crate::cli::Common>,
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

fn save_to(it: &mut Interp, path: &Path, opts: &OutputOptions) -> Result<(), Exn> {
    let d = drawing(it);
    crate::output::save(d, path, opts).map_err(|e| err(format!("save {}: {e}", path.display())))
}

fn save(it: &mut Interp, a: &[Value]) -> LResult {
    let name = it.string(&a[0])?.to_string();
    let path = match &it.base_dir {
        Some(b) if Path::new(&name).is_relative() => b.join(&name),
        _ => PathBuf::from(&name),
    };
    if !it.ext::<FsPolicy>().may_write(&path) {
        return Err(err(format!(
            "file access refused: {} is outside the script and output directories (use --allow-fs)",
            path.display()
        )));
    }
    let opts = output_options(it, None)?;
    save_to(it, &path, &opts)?;
    Ok(a[0].clone())
}

fn clear_drawing(it: &mut Interp, _: &[Value]) -> LResult {
    drawing(it).clear();
    // A half-made POLYLINE or a command waiting for input belonged to the old drawing.
    it.ext::<crate::builtins::entities::EntityState>()
        .pending_polyline = None;
    *it.ext::<crate::builtins::command::CommandState>() = Default::default();
    Ok(Value::Nil)
}

/// The drawing as SVG with the run's writer options (a row of a contact sheet).
pub fn drawing_svg(it: &mut Interp, common: &crate::cli::Common) -> Result<String, String> {
    let opts = output_options(it, Some(common)).map_err(|e| e.message.clone())?;
    Ok(crate::output::svg::write_svg(drawing(it), &opts))
}

/// Writes the drawing to each output path after a run (`-o`); nothing is written for a run
/// that failed, and each file appears whole or not at all.
pub fn write_outputs(
    it: &mut Interp,
    outputs: &[PathBuf],
    common: &crate::cli::Common,
) -> Result<(), String> {
    if outputs.is_empty() {
        return Ok(());
    }
    let opts = output_options(it, Some(common)).map_err(|e| e.message.clone())?;
    for o in outputs {
        crate::output::Format::from_path(o).map_err(|e| e.to_string())?;
    }
    for o in outputs {
        save_to(it, o, &opts).map_err(|e| e.message.clone())?;
    }
    Ok(())
}
