//! The eyeglass temple (paper 004, SPEC §5): the bent centerline, bending points and bending
//! whole outlines, bound to `geom::temple`.

use glam::{DVec2, DVec3};

use crate::builtin;
use crate::builtins::geometry::{curve, curve_value, geomtol, point3, vec3, CurveValue};
use crate::builtins::system::SysVars;
use crate::geom::curve::Curve;
use crate::geom::temple::{self, CenterPiece, TempleParams};
use crate::lang::builtin::{bad_arg, point_value, Builtin};
use crate::lang::error::{err, Exn, LResult};
use crate::lang::{Interp, Value};

pub static BUILTINS: &[Builtin] = &[
    builtin!("temple-centerline", "(temple-centerline L1 L2 R theta [base])", "The bent centerline: line P1-P2, arc of radius R turning through theta (positive toward -Y), line P3-P4; total length L1.", 4, 5, temple_centerline),
    builtin!("bend-point", "(bend-point p L1 L2 R theta [base])", "One point bent with the temple (its distance from the centerline kept).", 5, 6, bend_point),
    builtin!("bend-temple", "(bend-temple profile L1 L2 R theta [base] [smooth-tol])", "A temple outline bent: a list of type-value points, or a spline refitted within GEOMTOL*1000 of the exact bend (deviation in BENDDEV); with smooth-tol, refitted only within that tolerance, which rounds off the exact bend's slight corners where the outline enters and leaves the arc.", 5, 7, bend_temple),
];

/// The bend parameters from `L1 L2 R theta [base]` starting at `a[0]`.
fn params(it: &Interp, a: &[Value]) -> Result<TempleParams, Exn> {
    let base = match a.get(4) {
        None | Some(Value::Nil) => DVec2::ZERO,
        Some(b) => vec3(it, b)?.truncate(),
    };
    let p = TempleParams {
        l1: it.num(&a[0])?,
        l2: it.num(&a[1])?,
        r: it.num(&a[2])?,
        theta: it.num(&a[3])?,
        base,
    };
    p.validate().map_err(|e| err(e.to_string()))?;
    Ok(p)
}

fn temple_err(e: temple::TempleError) -> Exn {
    err(e.to_string())
}

fn temple_centerline(it: &mut Interp, a: &[Value]) -> LResult {
    let p = params(it, a)?;
    let cl = temple::centerline(&p).map_err(temple_err)?;
    let mut out = Vec::new();
    for piece in cl.pieces() {
        let c = match piece {
            CenterPiece::Line { start, end } => Curve::line(start, end),
            CenterPiece::Arc {
                center,
                radius,
                start_angle,
                end_angle,
                normal,
            } => Curve::arc(center, radius, start_angle, end_angle, Some(normal)),
        }
        .map_err(crate::builtins::geometry::geom_err)?;
        out.push(curve_value(c));
    }
    Ok(Value::list(out))
}

fn bend_point(it: &mut Interp, a: &[Value]) -> LResult {
    let p = params(it, &a[1..])?;
    let dim = Interp::point_dim(&a[0]);
    let q = temple::bend_point(vec3(it, &a[0])?, &p).map_err(temple_err)?;
    Ok(point_value(q.to_array(), dim))
}

fn bend_temple(it: &mut Interp, a: &[Value]) -> LResult {
    let p = params(it, &a[1..])?;
    if a[0].as_obj::<CurveValue>().is_some() {
        let Curve::Spline(s) = curve(it, &a[0])? else {
            return Err(bad_arg(it, "splinep", &a[0]));
        };
        // The exact bend has a slight corner wherever the outline crosses the start or end of
        // the arc off the centerline; refitting within a coarser tolerance spreads it over
        // about 8·tol/corner-angle of outline instead of reproducing it.
        let tol = match a.get(6) {
            None | Some(Value::Nil) => geomtol(it) * 1000.0,
            Some(v) => it.num(v)?,
        };
        let bent = temple::bend_spline(s, &p, tol).map_err(temple_err)?;
        it.ext::<SysVars>()
            .put("BENDDEV", Value::Real(bent.deviation));
        return Ok(curve_value(Curve::Spline(bent.spline)));
    }
    let pts: Vec<DVec3> = crate::builtins::geometry::points(it, &a[0])?;
    if pts.is_empty() {
        return Err(bad_arg(it, "2D/3D point", &a[0]));
    }
    let dims: Vec<usize> = a[0].iter().map(Interp::point_dim).collect();
    let bent = temple::bend_points(&pts, &p).map_err(temple_err)?;
    it.ext::<SysVars>().put("BENDDEV", Value::Real(0.0));
    Ok(Value::list(
        bent.into_iter()
            .zip(dims)
            .map(|(q, d)| {
                if d == 2 {
                    point_value(q.to_array(), 2)
                } else {
                    point3(q)
                }
            })
            .collect::<Vec<_>>(),
    ))
}
