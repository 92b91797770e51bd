//! Offset curves of planar curves: positive distance offsets to the right of the direction of
//! travel seen from the plane normal, i.e. outward for a CCW closed curve and r + d for
//! circles and arcs.
//!
//! Polylines are offset segment by segment (lines shift, arcs change radius) and re-joined at
//! the intersection of neighbouring offset carriers nearest the original vertex (a miter for
//! two lines), or with a connecting segment where the carriers do not meet.

use glam::DVec3;

use super::arc::{norm_angle, Arc};
use super::circle::Circle;
use super::curve::Curve;
use super::error::{finite, invalid, GeomError, Result};
use super::line::Line;
use super::polyline::{arc_bulge, Polyline, Segment};
use super::traits::ParamCurve;

impl Curve {
    /// `(offset c d)`: the curve offset by `d` in its plane (see the module doc for the side).
    /// Lines offset in the XY plane (normal +Z). Splines are not offset exactly: use
    /// `offset_approx`. Errors name the distance when it would collapse a circle or an arc.
    pub fn offset(&self, d: f64) -> Result<Curve> {
        finite("distance", d)?;
        match self {
            Curve::Line(l) => {
                let dir = l.dir();
                let side = dir.cross(DVec3::Z);
                if side.length_squared() <= 1e-24 * dir.length_squared() {
                    return Err(invalid(
                        "line",
                        "a line along Z has no offset plane (offset works in the XY plane)",
                    ));
                }
                let v = side.normalize() * d;
                Line::new(l.p0 + v, l.p1 + v).map(Curve::Line)
            }
            Curve::Circle(c) => {
                let r = c.radius() + d;
                if r <= 0.0 {
                    return Err(collapse(d, c.radius()));
                }
                Circle::new(c.center(), r, c.normal()).map(Curve::Circle)
            }
            Curve::Arc(a) => {
                let r = a.radius + d;
                if r <= 0.0 {
                    return Err(collapse(d, a.radius));
                }
                Ok(Curve::Arc(Arc { radius: r, ..*a }))
            }
            Curve::Polyline(p) => offset_polyline(p, d).map(Curve::Polyline),
            Curve::Spline(_) | Curve::BSpline(_) | Curve::Ellipse(_) => Err(GeomError::Unsupported(
                "offset: splines and ellipses have no exact offset; use offset_approx (a polyline within \
                 a tolerance) or offset (curve-points c tol)"
                    .into(),
            )),
        }
    }

    /// The offset of any planar curve, splines included, as a polyline within about `tol` of
    /// the exact offset: the curve is flattened within `tol` and that polyline offset.
    pub fn offset_approx(&self, d: f64, tol: f64) -> Result<Curve> {
        match self {
            Curve::Spline(_) | Curve::BSpline(_) | Curve::Ellipse(_) => {
                let normal = self.plane_normal().ok_or(GeomError::NotPlanar("offset"))?;
                let mut pts = self.points(tol)?;
                let closed = self.is_closed();
                if closed {
                    pts.pop();
                }
                let p = Polyline::new(pts, None, closed, Some(normal))?;
                offset_polyline(&p, d).map(Curve::Polyline)
            }
            _ => self.offset(d),
        }
    }
}

fn collapse(d: f64, r: f64) -> GeomError {
    invalid(
        "distance",
        format!("offset {d} collapses a radius of {r} (need radius + distance > 0)"),
    )
}

/// One offset segment: a line, or an arc with its CCW-ness about the polyline normal.
#[derive(Clone, Copy)]
enum Off {
    Line(DVec3, DVec3),
    Arc(Arc, DVec3, DVec3),
}

impl Off {
    fn start(&self) -> DVec3 {
        match self {
            Off::Line(a, _) | Off::Arc(_, a, _) => *a,
        }
    }
    fn end(&self) -> DVec3 {
        match self {
            Off::Line(_, b) | Off::Arc(_, _, b) => *b,
        }
    }
}

fn offset_polyline(p: &Polyline, d: f64) -> Result<Polyline> {
    let n = p.normal;
    let mut offs: Vec<Off> = Vec::new();
    for (i, seg) in p.segments().enumerate() {
        match seg {
            Segment::Line(l) => {
                let side = l.dir().cross(n).normalize() * d;
                offs.push(Off::Line(l.p0 + side, l.p1 + side));
            }
            Segment::Arc(a) => {
                let sign = if a.normal.dot(n) > 0.0 { 1.0 } else { -1.0 };
                let r = a.radius + sign * d;
                if r <= 1e-12 * a.radius {
                    return Err(invalid(
                        "distance",
                        format!(
                            "offset {d} collapses the arc segment {i} of radius {}",
                            a.radius
                        ),
                    ));
                }
                let na = Arc { radius: r, ..a };
                offs.push(Off::Arc(na, na.eval(0.0), na.eval(1.0)));
            }
        }
    }
    let m = offs.len();
    let joints = if p.closed { m } else { m - 1 };
    let scale = p
        .vertices
        .iter()
        .fold(1.0f64, |s, v| s.max(v.abs().max_element()));
    // Joint k is between segment k and k+1 at original vertex k+1.
    let mut extra: Vec<Option<DVec3>> = vec![None; m];
    for k in 0..joints {
        let (i, j) = (k, (k + 1) % m);
        let (e, s) = (offs[i].end(), offs[j].start());
        if (e - s).length() <= 1e-12 * scale {
            continue;
        }
        let v = p.vertices[(k + 1) % p.vertices.len()];
        match join(&offs[i], &offs[j], v, n, 4.0 * d.abs() + scale) {
            Some(q) => {
                set_end(&mut offs[i], q);
                set_start(&mut offs[j], q);
            }
            None => extra[i] = Some(s),
        }
    }
    let mut verts = Vec::new();
    let mut bulges = Vec::new();
    for (i, o) in offs.iter().enumerate() {
        verts.push(o.start());
        bulges.push(match o {
            Off::Line(..) => 0.0,
            Off::Arc(a, s, e) => {
                let sweep = norm_angle(a.angle_of(*e) - a.angle_of(*s));
                let sweep = if sweep == 0.0 { a.sweep } else { sweep };
                arc_bulge(&a.with_range(a.start, sweep), n)
            }
        });
        if extra[i].is_some() {
            verts.push(o.end());
            bulges.push(0.0);
        }
    }
    if !p.closed {
        verts.push(offs[m - 1].end());
        bulges.push(0.0);
    }
    Polyline::new(verts, Some(bulges), p.closed, Some(n))
}

fn set_end(o: &mut Off, q: DVec3) {
    match o {
        Off::Line(_, b) | Off::Arc(_, _, b) => *b = q,
    }
}
fn set_start(o: &mut Off, q: DVec3) {
    match o {
        Off::Line(a, _) | Off::Arc(_, a, _) => *a = q,
    }
}

/// The intersection of the two offset carriers (infinite line / full circle) nearest `v`.
/// Two lines meet in closed form (a miter); otherwise lines are extended by `ext` and the
/// curve intersection is used.
fn join(a: &Off, b: &Off, v: DVec3, n: DVec3, ext: f64) -> Option<DVec3> {
    if let (Off::Line(p, p1), Off::Line(q, q1)) = (a, b) {
        let (d1, d2) = (*p1 - *p, *q1 - *q);
        let den = d1.cross(d2).dot(n);
        if den.abs() <= 1e-12 * d1.length() * d2.length() {
            return None;
        }
        let s = (*q - *p).cross(d2).dot(n) / den;
        return Some(*p + d1 * s);
    }
    let carrier = |o: &Off| -> Curve {
        match o {
            Off::Line(p, q) => {
                let d = (*q - *p).normalize() * ext;
                Curve::Line(Line {
                    p0: *p - d,
                    p1: *q + d,
                })
            }
            Off::Arc(a, ..) => Curve::Circle(Circle {
                arc: a.with_range(0.0, std::f64::consts::TAU),
            }),
        }
    };
    let (ca, cb) = (carrier(a), carrier(b));
    let hits = super::intersect::intersect(&ca, &cb, 1e-9 * ext.max(1.0));
    super::intersect::intersect_near(&hits, v)
}
