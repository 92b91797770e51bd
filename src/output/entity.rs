//! Entities: AutoCAD's entity kinds with their checks, extents and the bulge arithmetic that
//! LWPOLYLINE/POLYLINE segments share with the writers.

use std::rc::Rc;

use glam::{DVec2, DVec3, DVec4};

use super::drawing::DrawingError;
use crate::geom::bspline::BSpline;
use crate::geom::frame::Ocs;

/// A spline's Bézier pieces (`BSpline::to_beziers`), shared.
pub type BezierPieces = Rc<Vec<(Vec<DVec3>, Vec<f64>)>>;
/// Where `extent_points_with` and the SVG writer get a spline's pieces from.
pub type BezierSource<'a> = dyn Fn(&BSpline) -> BezierPieces + 'a;

/// The [`BezierSource`] that decomposes the spline afresh on every call.
pub fn fresh_beziers(curve: &BSpline) -> BezierPieces {
    Rc::new(curve.to_beziers())
}

/// One drawn entity.
#[derive(Clone, Debug, PartialEq)]
pub struct Entity {
    /// Unique, never reused within a drawing. Assigned by `Drawing::add`.
    pub handle: u64,
    pub layer: String,
    /// ACI colour: `None` = BYLAYER, `Some(0)` = BYBLOCK, `Some(1..=255)`.
    pub color: Option<i16>,
    pub kind: EntityKind,
}

impl Entity {
    /// An entity on `layer`, colour BYLAYER (handle assigned when added).
    pub fn new(layer: &str, kind: EntityKind) -> Entity {
        Entity {
            handle: 0,
            layer: layer.to_string(),
            color: None,
            kind,
        }
    }

    pub fn with_color(mut self, color: i16) -> Entity {
        self.color = Some(color);
        self
    }
}

/// The geometry of an entity. Points are WCS unless said otherwise.
#[derive(Clone, Debug, PartialEq)]
pub enum EntityKind {
    Line {
        p0: DVec3,
        p1: DVec3,
    },
    /// `center` in WCS; the circle lies in the plane through it perpendicular to `normal`.
    Circle {
        center: DVec3,
        radius: f64,
        normal: DVec3,
    },
    /// Angles in radians, counter-clockwise from the OCS X axis of `arbitrary_axis(normal)`
    /// (DXF's convention); `center` in WCS.
    Arc {
        center: DVec3,
        radius: f64,
        start: f64,
        end: f64,
        normal: DVec3,
    },
    Point {
        p: DVec3,
    },
    /// DXF LWPOLYLINE: vertices in the OCS of `normal` at height `elevation`; `bulges[i]` is
    /// tan(included angle / 4) of the segment leaving vertex i (positive = CCW).
    LwPolyline {
        points: Vec<DVec2>,
        bulges: Vec<f64>,
        closed: bool,
        elevation: f64,
        normal: DVec3,
    },
    /// The R12-style POLYLINE with VERTEX entities: WCS points; bulges only meaningful when the
    /// points share one Z (written as a 2D polyline then, else as a 3D polyline).
    Polyline {
        points: Vec<DVec3>,
        bulges: Vec<f64>,
        closed: bool,
    },
    Spline {
        curve: BSpline,
        fit_points: Vec<DVec3>,
        closed: bool,
    },
    Face3d {
        corners: [DVec3; 4],
    },
    /// Single-line text; `rotation` in radians; `style` names a text style ("Standard").
    Text {
        insert: DVec3,
        height: f64,
        value: String,
        rotation: f64,
        style: String,
    },
    /// A triangle mesh (surfaces): 3DFACEs in DXF, projected wireframe in SVG.
    Mesh {
        vertices: Vec<DVec3>,
        triangles: Vec<[usize; 3]>,
    },
    /// DXF's ELLIPSE: `major` is the WCS vector from the centre to the end of the major axis,
    /// `ratio` minor/major in (0, 1], `start`/`end` the parameters (radians) of the arc.
    Ellipse {
        center: DVec3,
        major: DVec3,
        normal: DVec3,
        ratio: f64,
        start: f64,
        end: f64,
    },
    /// An entity read from a file that lispcad does not model (INSERT, MTEXT, HATCH,
    /// DIMENSION, polygon meshes...): its groups live in the drawing's source record.
    Unmodelled {
        dxf_type: String,
    },
}

impl EntityKind {
    /// The DXF entity type name (`(0 . "LINE")`); a mesh reports "MESH" but is written as
    /// 3DFACEs.
    pub fn type_name(&self) -> &str {
        match self {
            EntityKind::Line { .. } => "LINE",
            EntityKind::Circle { .. } => "CIRCLE",
            EntityKind::Arc { .. } => "ARC",
            EntityKind::Point { .. } => "POINT",
            EntityKind::LwPolyline { .. } => "LWPOLYLINE",
            EntityKind::Polyline { .. } => "POLYLINE",
            EntityKind::Spline { .. } => "SPLINE",
            EntityKind::Face3d { .. } => "3DFACE",
            EntityKind::Text { .. } => "TEXT",
            EntityKind::Mesh { .. } => "MESH",
            EntityKind::Ellipse { .. } => "ELLIPSE",
            EntityKind::Unmodelled { dxf_type } => dxf_type,
        }
    }

    /// Why this geometry cannot be drawn, or `Ok`.
    pub fn validate(&self) -> Result<(), DrawingError> {
        fn fin(name: &'static str, ok: bool) -> Result<(), DrawingError> {
            if ok {
                Ok(())
            } else {
                Err(DrawingError::NonFinite(name))
            }
        }
        fn normal_ok(n: &DVec3) -> Result<(), DrawingError> {
            if !n.is_finite() || n.length() < 1e-12 {
                return Err(DrawingError::BadNormal);
            }
            Ok(())
        }
        fn radius_ok(r: f64) -> Result<(), DrawingError> {
            if !(r.is_finite() && r > 0.0) {
                return Err(DrawingError::BadRadius(r));
            }
            Ok(())
        }
        match self {
            EntityKind::Line { p0, p1 } => fin("line end point", p0.is_finite() && p1.is_finite()),
            EntityKind::Circle {
                center,
                radius,
                normal,
            } => {
                fin("circle centre", center.is_finite())?;
                radius_ok(*radius)?;
                normal_ok(normal)
            }
            EntityKind::Arc {
                center,
                radius,
                start,
                end,
                normal,
            } => {
                fin("arc centre", center.is_finite())?;
                fin("arc angle", start.is_finite() && end.is_finite())?;
                radius_ok(*radius)?;
                normal_ok(normal)
            }
            EntityKind::Point { p } => fin("point", p.is_finite()),
            EntityKind::LwPolyline {
                points,
                bulges,
                elevation,
                normal,
                ..
            } => {
                if points.len() < 2 {
                    return Err(DrawingError::TooFewVertices(points.len()));
                }
                check_bulges(points.len(), bulges)?;
                fin("polyline vertex", points.iter().all(|p| p.is_finite()))?;
                fin("polyline elevation", elevation.is_finite())?;
                normal_ok(normal)
            }
            EntityKind::Polyline { points, bulges, .. } => {
                if points.len() < 2 {
                    return Err(DrawingError::TooFewVertices(points.len()));
                }
                check_bulges(points.len(), bulges)?;
                fin("polyline vertex", points.iter().all(|p| p.is_finite()))
            }
            EntityKind::Spline {
                curve, fit_points, ..
            } => {
                // Re-run BSpline's own checks: the struct's fields are public.
                BSpline::new(
                    curve.degree,
                    curve.ctrl.clone(),
                    Some(curve.knots.clone()),
                    curve.weights.clone(),
                )
                .map_err(|e| DrawingError::Spline(e.to_string()))?;
                fin("spline fit point", fit_points.iter().all(|p| p.is_finite()))
            }
            EntityKind::Face3d { corners } => {
                fin("3dface corner", corners.iter().all(|p| p.is_finite()))
            }
            EntityKind::Text {
                insert,
                height,
                rotation,
                ..
            } => {
                fin("text insertion point", insert.is_finite())?;
                fin("text rotation", rotation.is_finite())?;
                if !(height.is_finite() && *height > 0.0) {
                    return Err(DrawingError::BadTextHeight(*height));
                }
                Ok(())
            }
            EntityKind::Mesh {
                vertices,
                triangles,
            } => {
                fin("mesh vertex", vertices.iter().all(|p| p.is_finite()))?;
                let n = vertices.len();
                if let Some(t) = triangles.iter().find(|t| t.iter().any(|&i| i >= n)) {
                    return Err(DrawingError::MeshIndex {
                        index: *t.iter().max().unwrap_or(&0),
                        vertices: n,
                    });
                }
                Ok(())
            }
            EntityKind::Ellipse {
                center,
                major,
                normal,
                ratio,
                start,
                end,
            } => {
                fin("ellipse centre", center.is_finite())?;
                fin("ellipse parameter", start.is_finite() && end.is_finite())?;
                if !major.is_finite() || major.length() < 1e-12 {
                    return Err(DrawingError::NonFinite("ellipse major axis (non-zero)"));
                }
                if !(*ratio > 0.0 && *ratio <= 1.0) {
                    return Err(DrawingError::BadRadius(*ratio));
                }
                normal_ok(normal)
            }
            EntityKind::Unmodelled { .. } => Ok(()),
        }
    }

    /// Points that bound the entity (exact for lines, polylines without bulges, faces and
    /// meshes; arcs and curves are sampled densely, so the box may be short by a hair).
    pub fn extent_points(&self, out: &mut Vec<DVec3>) {
        self.extent_points_with(out, &fresh_beziers);
    }

    /// `extent_points` with a spline's Bézier pieces taken from `beziers` (a writer that
    /// needs them again for the same file shares one decomposition).
    pub fn extent_points_with(&self, out: &mut Vec<DVec3>, beziers: &BezierSource) {
        match self {
            EntityKind::Line { p0, p1 } => out.extend([*p0, *p1]),
            EntityKind::Circle {
                center,
                radius,
                normal,
            } => arc_extent(*center, *radius, 0.0, std::f64::consts::TAU, *normal, out),
            EntityKind::Arc {
                center,
                radius,
                start,
                end,
                normal,
            } => {
                let sweep = ccw_sweep(*start, *end);
                arc_extent(*center, *radius, *start, *start + sweep, *normal, out)
            }
            EntityKind::Point { p } => out.push(*p),
            EntityKind::LwPolyline {
                points,
                bulges,
                closed,
                elevation,
                normal,
            } => {
                let ocs = Ocs::new(*normal);
                out.extend(points.iter().map(|p| ocs.to_wcs(*p, *elevation)));
                for (a, b, bulge) in bulge_segments(points, bulges, *closed) {
                    if bulge != 0.0 {
                        if let Some((c, r, a0, a1)) = bulge_arc(a, b, bulge) {
                            arc_extent(ocs.to_wcs(c, *elevation), r, a0, a1, ocs.n, out);
                        }
                    }
                }
            }
            EntityKind::Polyline {
                points,
                bulges,
                closed,
            } => {
                out.extend(points.iter().copied());
                let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
                let z = points.first().map_or(0.0, |p| p.z);
                for (a, b, bulge) in bulge_segments(&flat, bulges, *closed) {
                    if bulge != 0.0 {
                        if let Some((c, r, a0, a1)) = bulge_arc(a, b, bulge) {
                            arc_extent(c.extend(z), r, a0, a1, DVec3::Z, out);
                        }
                    }
                }
            }
            EntityKind::Spline { curve, .. } => {
                let mut buf: Vec<DVec4> = Vec::with_capacity(curve.degree + 1);
                let mut eval = |pts: &[DVec3], w: &[f64], t: f64| {
                    buf.clear();
                    buf.extend(pts.iter().zip(w).map(|(p, w)| (*p * *w).extend(*w)));
                    for r in 1..buf.len() {
                        for j in 0..buf.len() - r {
                            buf[j] = buf[j].lerp(buf[j + 1], t);
                        }
                    }
                    buf[0].truncate() / buf[0].w
                };
                for (pts, w) in beziers(curve).iter() {
                    out.push(pts[0]);
                    out.push(pts[pts.len() - 1]);
                    if curve.weights.is_none() && curve.degree <= 3 {
                        // Exact: the coordinate extremes are the roots of the hodograph.
                        for t in hodograph_roots(pts) {
                            out.push(eval(pts, w, t));
                        }
                    } else {
                        for k in 1..32 {
                            out.push(eval(pts, w, k as f64 / 32.0));
                        }
                    }
                }
            }
            EntityKind::Face3d { corners } => out.extend(corners.iter().copied()),
            EntityKind::Text { insert, .. } => out.push(*insert),
            EntityKind::Mesh { vertices, .. } => out.extend(vertices.iter().copied()),
            EntityKind::Ellipse { .. } => out.extend(self.ellipse_points(64)),
            EntityKind::Unmodelled { .. } => {}
        }
    }

    /// Points along an ELLIPSE from its start to its end parameter (`n` segments), or none
    /// for other kinds.
    pub fn ellipse_points(&self, n: usize) -> Vec<DVec3> {
        let EntityKind::Ellipse {
            center,
            major,
            normal,
            ratio,
            start,
            end,
        } = self
        else {
            return Vec::new();
        };
        let minor = normal.normalize().cross(*major) * *ratio;
        let sweep = ccw_sweep(*start, *end);
        (0..=n)
            .map(|i| {
                let t = start + sweep * i as f64 / n as f64;
                *center + *major * t.cos() + minor * t.sin()
            })
            .collect()
    }
}

/// Parameters in (0, 1) where a non-rational Bézier of degree ≤ 3 has a zero derivative in
/// some coordinate (its hodograph, of degree ≤ 2, solved per axis).
fn hodograph_roots(pts: &[DVec3]) -> Vec<f64> {
    let mut ts = Vec::new();
    for axis in 0..3 {
        let d: Vec<f64> = pts.windows(2).map(|w| w[1][axis] - w[0][axis]).collect();
        match d.len() {
            2 => {
                let den = d[0] - d[1];
                if den != 0.0 {
                    ts.push(d[0] / den);
                }
            }
            3 => {
                // d0 (1-t)^2 + 2 d1 t (1-t) + d2 t^2 = a t^2 + b t + c
                let (a, b, c) = (d[0] - 2.0 * d[1] + d[2], 2.0 * (d[1] - d[0]), d[0]);
                if a.abs() < 1e-300 {
                    if b != 0.0 {
                        ts.push(-c / b);
                    }
                } else {
                    let disc = b * b - 4.0 * a * c;
                    if disc >= 0.0 {
                        let q = -0.5 * (b + b.signum() * disc.sqrt());
                        ts.push(q / a);
                        if q != 0.0 {
                            ts.push(c / q);
                        }
                    }
                }
            }
            _ => {}
        }
    }
    ts.retain(|t| t.is_finite() && *t > 0.0 && *t < 1.0);
    ts
}

fn check_bulges(n: usize, bulges: &[f64]) -> Result<(), DrawingError> {
    if !bulges.is_empty() && bulges.len() != n {
        return Err(DrawingError::BulgeCount {
            need: n,
            got: bulges.len(),
        });
    }
    if bulges.iter().any(|b| !b.is_finite()) {
        return Err(DrawingError::NonFinite("bulge"));
    }
    Ok(())
}

/// The CCW sweep from `start` to `end` in (0, 2π] (an arc with equal angles is a full turn,
/// as AutoCAD draws it).
pub fn ccw_sweep(start: f64, end: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let s = (end - start).rem_euclid(tau);
    if s <= 1e-15 {
        tau
    } else {
        s
    }
}

/// Whether every point has the first one's Z (they lie in one plane parallel to XY). A flat
/// POLYLINE is 2D and its bulges apply; any other is 3D, straight segments only. Exact
/// equality, so every writer makes the same choice for the same points.
pub fn is_flat(points: &[DVec3]) -> bool {
    points.iter().all(|p| p.z == points[0].z)
}

/// The segments (start, end, bulge) of a 2D polyline with optional bulges.
pub fn bulge_segments<'a>(
    points: &'a [DVec2],
    bulges: &'a [f64],
    closed: bool,
) -> impl Iterator<Item = (DVec2, DVec2, f64)> + 'a {
    let n = points.len();
    let segs = if closed { n } else { n.saturating_sub(1) };
    (0..segs).map(move |i| {
        (
            points[i],
            points[(i + 1) % n],
            bulges.get(i).copied().unwrap_or(0.0),
        )
    })
}

/// The arc of a bulge segment as (centre, radius, start angle, end angle) with
/// start < end for a CCW (positive) bulge and start > end for a CW one; `None` when the chord
/// is degenerate. Bulge b = tan(θ/4) with θ the signed included angle.
pub fn bulge_arc(a: DVec2, b: DVec2, bulge: f64) -> Option<(DVec2, f64, f64, f64)> {
    let chord = b - a;
    let d = chord.length();
    if d < 1e-300 || bulge == 0.0 {
        return None;
    }
    let theta = 4.0 * bulge.atan();
    let r = d / (2.0 * (theta / 2.0).sin().abs());
    // Centre: from the chord midpoint along the left normal by the signed sagitta complement.
    let h = d / 2.0 / (theta / 2.0).tan();
    let left = DVec2::new(-chord.y, chord.x) / d;
    let c = (a + b) / 2.0 + left * h;
    let a0 = (a - c).y.atan2((a - c).x);
    Some((c, r, a0, a0 + theta))
}

/// Points bounding the arc from angle a0 to a1 (either direction): the ends, the axis extremes
/// for plane normals along Z, and a dense sample otherwise.
fn arc_extent(c: DVec3, r: f64, a0: f64, a1: f64, normal: DVec3, out: &mut Vec<DVec3>) {
    let ocs = Ocs::new(normal);
    let at = |t: f64| ocs.on_circle(c, r, t);
    let (lo, hi) = if a0 <= a1 { (a0, a1) } else { (a1, a0) };
    out.push(at(lo));
    out.push(at(hi));
    let step = std::f64::consts::FRAC_PI_2 / 16.0;
    // Multiples of the step include the quarter turns, where planar arcs reach their extremes.
    let mut k = (lo / step).ceil();
    while k * step < hi {
        out.push(at(k * step));
        k += 1.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spline_extents_are_exact_at_hodograph_roots() {
        let curve = BSpline::new(
            2,
            vec![
                DVec3::ZERO,
                DVec3::new(1.0, 2.0, 0.0),
                DVec3::new(2.0, 0.0, 0.0),
            ],
            None,
            None,
        )
        .unwrap();
        let mut pts = Vec::new();
        EntityKind::Spline {
            curve,
            fit_points: vec![],
            closed: false,
        }
        .extent_points(&mut pts);
        let ymax = pts.iter().map(|p| p.y).fold(f64::MIN, f64::max);
        assert_eq!(ymax, 1.0);
    }
}
