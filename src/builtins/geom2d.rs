//! AutoLISP's point functions: `inters`, `polar`, `angle`, `distance`, `trans`.
//!
//! They follow AutoCAD's documented behaviour point for point: a 2D point stays 2D where AutoCAD
//! keeps it 2D (`polar`, `inters` unless all four points are 3D), `distance` measures in the
//! plane when either point is 2D, `angle` is measured in the XY plane and lies in [0, 2π).
//! Headless there is no UCS or view, so WCS, UCS and DCS are the same frame; `trans` still does
//! real work for OCS extrusion vectors (DXF's arbitrary-axis algorithm, `geom::frame`).

use std::f64::consts::TAU;

use glam::DVec3;

use crate::builtin;
use crate::geom::frame::arbitrary_axis;
use crate::lang::builtin::{bad_arg, point_value, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("inters", "(inters p1 p2 p3 p4 [onseg])", "The intersection of lines p1-p2 and p3-p4; onseg omitted or non-nil: on both segments; nil: infinite lines; 3D when all four points are 3D.", 4, 5, inters),
    builtin!("polar", "(polar point angle distance)", "The point at angle (radians, in the XY plane) and distance from point; keeps the point's dimension and Z.", 3, 3, polar),
    builtin!("angle", "(angle p1 p2)", "The angle of the line p1->p2 in the XY plane, radians in [0, 2pi).", 2, 2, angle),
    builtin!("distance", "(distance p1 p2)", "The distance between two points; in the XY plane when either point is 2D.", 2, 2, distance),
    builtin!("trans", "(trans point from to [disp])", "The point (or displacement when disp is non-nil) translated between coordinate systems: 0 WCS, 1 UCS, 2 DCS, 3 PSDCS, an extrusion vector or an entity name (OCS); always 3D.", 3, 4, trans),
];

/// A point argument and whether it was given in 3D.
fn pt(it: &Interp, v: &Value) -> Result<(DVec3, bool), Exn> {
    let p = it.point(v)?;
    Ok((DVec3::from_array(p), Interp::point_dim(v) == 3))
}

/// Relative tolerance of the intersection tests: AutoCAD's fuzz is of this order for drawing
/// coordinates, and it keeps exact-looking inputs (0.1 + 0.2 style rounding) from missing.
const REL_TOL: f64 = 1e-10;

/// Solves p1 + s·(p2-p1) = p3 + t·(p4-p3) in the XY plane; None when parallel (or degenerate).
fn solve_2d(p1: DVec3, p2: DVec3, p3: DVec3, p4: DVec3) -> Option<(f64, f64)> {
    let d1 = (p2 - p1).truncate();
    let d2 = (p4 - p3).truncate();
    let w = (p3 - p1).truncate();
    let den = d1.perp_dot(d2);
    let scale = d1.length() * d2.length();
    if scale == 0.0 || den.abs() <= REL_TOL * scale {
        return None;
    }
    Some((w.perp_dot(d2) / den, w.perp_dot(d1) / den))
}

/// The same in 3D: the lines must meet (closest points within tolerance), not merely cross
/// in projection.
fn solve_3d(p1: DVec3, p2: DVec3, p3: DVec3, p4: DVec3) -> Option<(f64, f64)> {
    let d1 = p2 - p1;
    let d2 = p4 - p3;
    let n = d1.cross(d2);
    let scale = d1.length() * d2.length();
    if scale == 0.0 || n.length() <= REL_TOL * scale {
        return None;
    }
    let w = p3 - p1;
    let nn = n.length_squared();
    let s = w.cross(d2).dot(n) / nn;
    let t = w.cross(d1).dot(n) / nn;
    let gap = (p1 + d1 * s - (p3 + d2 * t)).length();
    let size = p1
        .abs()
        .max(p2.abs())
        .max(p3.abs())
        .max(p4.abs())
        .max_element()
        .max(d1.length())
        .max(d2.length());
    if gap > 10.0 * REL_TOL * size.max(1.0) {
        return None;
    }
    Some((s, t))
}

fn inters(it: &mut Interp, a: &[Value]) -> LResult {
    let (p1, z1) = pt(it, &a[0])?;
    let (p2, z2) = pt(it, &a[1])?;
    let (p3, z3) = pt(it, &a[2])?;
    let (p4, z4) = pt(it, &a[3])?;
    let onseg = a.get(4).is_none_or(Value::truthy);
    let three_d = z1 && z2 && z3 && z4;
    let st = if three_d {
        solve_3d(p1, p2, p3, p4)
    } else {
        solve_2d(p1, p2, p3, p4)
    };
    let Some((s, t)) = st else {
        return Ok(Value::Nil);
    };
    let within = |u: f64| (-REL_TOL..=1.0 + REL_TOL).contains(&u);
    if onseg && !(within(s) && within(t)) {
        return Ok(Value::Nil);
    }
    let p = p1 + (p2 - p1) * s;
    Ok(point_value(p.to_array(), if three_d { 3 } else { 2 }))
}

fn polar(it: &mut Interp, a: &[Value]) -> LResult {
    let p = it.point(&a[0])?;
    let ang = it.num(&a[1])?;
    let d = it.num(&a[2])?;
    let q = [p[0] + d * ang.cos(), p[1] + d * ang.sin(), p[2]];
    Ok(point_value(q, Interp::point_dim(&a[0])))
}

/// The direction of p1->p2 in the XY plane, normalised to [0, 2π).
pub fn xy_angle(p1: DVec3, p2: DVec3) -> f64 {
    let mut r = (p2.y - p1.y).atan2(p2.x - p1.x);
    if r < 0.0 {
        r += TAU;
    }
    // -tiny + 2π rounds to 2π itself, which is outside the half-open range.
    if r >= TAU {
        r = 0.0;
    }
    r
}

fn angle(it: &mut Interp, a: &[Value]) -> LResult {
    let (p1, _) = pt(it, &a[0])?;
    let (p2, _) = pt(it, &a[1])?;
    Ok(Value::Real(xy_angle(p1, p2)))
}

fn distance(it: &mut Interp, a: &[Value]) -> LResult {
    let (p1, z1) = pt(it, &a[0])?;
    let (p2, z2) = pt(it, &a[1])?;
    let d = if z1 && z2 {
        p1.distance(p2)
    } else {
        p1.truncate().distance(p2.truncate())
    };
    Ok(Value::Real(d))
}

/// A coordinate system argument of `trans`.
enum Cs {
    /// WCS, UCS, DCS and PSDCS: all the world frame when there is no drawing view.
    World,
    /// An object coordinate system given by its extrusion vector.
    Ocs(DVec3, DVec3, DVec3),
}

fn coord_system(it: &mut Interp, v: &Value) -> Result<Cs, Exn> {
    match v {
        Value::Int(0..=3) => Ok(Cs::World),
        Value::Cons(_) => {
            let n = DVec3::from_array(it.point(v)?);
            if n.length_squared() == 0.0 {
                return Err(err(format!(
                    "bad argument value: extrusion vector {} is zero",
                    it.prin1_string(v)
                )));
            }
            let (ax, ay) = arbitrary_axis(n);
            Ok(Cs::Ocs(ax, ay, n.normalize()))
        }
        // An entity's coordinate system is its OCS: the extrusion (group 210, default +Z).
        Value::Obj(o) if o.type_name() == "ENAME" => {
            let entget = super::find("entget").ok_or_else(|| err("trans: no entity support"))?;
            let data = (entget.f)(it, std::slice::from_ref(v))?;
            if data.is_nil() {
                return Err(err(format!(
                    "bad argument value: no entity {}",
                    it.prin1_string(v)
                )));
            }
            let n = data
                .iter()
                .find(|g| matches!(g.car(), Value::Int(210)))
                .and_then(|g| {
                    let xyz: Vec<f64> = g.cdr().iter().filter_map(|x| x.as_f64()).collect();
                    (xyz.len() == 3).then(|| DVec3::new(xyz[0], xyz[1], xyz[2]))
                })
                .filter(|n| n.length_squared() > 0.0)
                .unwrap_or(DVec3::Z);
            let (ax, ay) = arbitrary_axis(n);
            Ok(Cs::Ocs(ax, ay, n.normalize()))
        }
        Value::Int(_) => Err(err(format!(
            "bad argument value: coordinate system code {} (0 WCS, 1 UCS, 2 DCS, 3 PSDCS)",
            it.prin1_string(v)
        ))),
        _ => Err(bad_arg(it, "coordinate system", v)),
    }
}

fn trans(it: &mut Interp, a: &[Value]) -> LResult {
    let p = DVec3::from_array(it.point(&a[0])?);
    let from = coord_system(it, &a[1])?;
    let to = coord_system(it, &a[2])?;
    // Every frame shares the world origin, so a displacement (disp non-nil) transforms like a
    // point; the flag is accepted for AutoLISP compatibility.
    let world = match from {
        Cs::World => p,
        Cs::Ocs(ax, ay, az) => ax * p.x + ay * p.y + az * p.z,
    };
    let out = match to {
        Cs::World => world,
        Cs::Ocs(ax, ay, az) => DVec3::new(world.dot(ax), world.dot(ay), world.dot(az)),
    };
    Ok(point_value(out.to_array(), 3))
}
