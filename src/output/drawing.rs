//! The drawing model: a layer table and entities in insertion order, each with a stable handle.
//!
//! Entities mirror AutoCAD's (so `entmake`/`entget` map one-to-one onto them). Deleted entities
//! stay in place as tombstones, because AutoLISP's `entdel` on a deleted entity restores it and
//! handles must never be reused.

use glam::{DVec2, DVec3};

use crate::geom::bspline::BSpline;
use crate::geom::frame::arbitrary_axis;

/// A layer-table record.
#[derive(Clone, Debug, PartialEq)]
pub struct Layer {
    pub name: String,
    /// AutoCAD Color Index 1..=255; negative means the layer is off (AutoCAD's convention).
    pub color: i16,
    pub linetype: String,
    pub frozen: bool,
    pub locked: bool,
}

impl Layer {
    /// A layer with colour 7 (white/black) and the CONTINUOUS line type.
    pub fn new(name: &str) -> Layer {
        Layer {
            name: name.to_string(),
            color: 7,
            linetype: "Continuous".to_string(),
            frozen: false,
            locked: false,
        }
    }

    pub fn is_off(&self) -> bool {
        self.color < 0
    }
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
}

impl EntityKind {
    /// The DXF entity type name (`(0 . "LINE")`); a mesh reports "MESH" but is written as
    /// 3DFACEs.
    pub fn type_name(&self) -> &'static str {
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
        }
    }

    /// Points that bound the entity (exact for lines, polylines without bulges, faces and
    /// meshes; arcs and curves are sampled densely, so the box may be short by a hair).
    pub fn extent_points(&self, out: &mut Vec<DVec3>) {
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
                let (ax, ay) = arbitrary_axis(*normal);
                let n = normal.normalize();
                let to_wcs = |p: DVec2| ax * p.x + ay * p.y + n * *elevation;
                for p in points {
                    out.push(to_wcs(*p));
                }
                for (a, b, bulge) in bulge_segments(points, bulges, *closed) {
                    if bulge != 0.0 {
                        if let Some((c, r, a0, a1)) = bulge_arc(a, b, bulge) {
                            let c3 = ax * c.x + ay * c.y + n * *elevation;
                            arc_extent(c3, r, a0, a1, n, out);
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
            EntityKind::Spline { curve, .. } => spline_extent_points(curve, out),
            EntityKind::Face3d { corners } => out.extend(corners.iter().copied()),
            EntityKind::Text { insert, .. } => out.push(*insert),
            EntityKind::Mesh { vertices, .. } => out.extend(vertices.iter().copied()),
        }
    }
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

/// Points whose bounding box is the spline's: per Bézier piece its ends plus, for non-rational
/// quadratics and cubics, the exact axis extrema (roots of the derivative); other pieces are
/// sampled densely.
fn spline_extent_points(curve: &BSpline, out: &mut Vec<DVec3>) {
    for (pts, w) in curve.to_beziers() {
        let rational = w.iter().any(|x| *x != w[0]);
        out.push(pts[0]);
        out.push(pts[pts.len() - 1]);
        let mut at = |t: f64| {
            if t > 0.0 && t < 1.0 {
                out.push(bezier_point(&pts, &w, t));
            }
        };
        match (pts.len(), rational) {
            (3, false) => {
                let den = pts[0] - 2.0 * pts[1] + pts[2];
                for axis in 0..3 {
                    if den[axis] != 0.0 {
                        at((pts[0][axis] - pts[1][axis]) / den[axis]);
                    }
                }
            }
            (4, false) => {
                // B'(t)/3 = (a - 2b + c) t² + 2 (b - a) t + a, with a, b, c the control deltas.
                let (a, b, c) = (pts[1] - pts[0], pts[2] - pts[1], pts[3] - pts[2]);
                for axis in 0..3 {
                    let (qa, qb, qc) = (
                        a[axis] - 2.0 * b[axis] + c[axis],
                        2.0 * (b[axis] - a[axis]),
                        a[axis],
                    );
                    if qa.abs() < 1e-300 {
                        if qb != 0.0 {
                            at(-qc / qb);
                        }
                        continue;
                    }
                    let disc = qb * qb - 4.0 * qa * qc;
                    if disc >= 0.0 {
                        let q = -0.5 * (qb + qb.signum() * disc.sqrt());
                        if q != 0.0 {
                            at(qc / q);
                        }
                        at(q / qa);
                    }
                }
            }
            _ => {
                for i in 1..64 {
                    at(i as f64 / 64.0);
                }
            }
        }
    }
}

/// A rational Bézier point by de Casteljau in homogeneous coordinates.
fn bezier_point(pts: &[DVec3], w: &[f64], t: f64) -> DVec3 {
    let mut h: Vec<glam::DVec4> = pts
        .iter()
        .zip(w)
        .map(|(p, w)| (*p * *w).extend(*w))
        .collect();
    for r in 1..h.len() {
        for j in 0..h.len() - r {
            h[j] = h[j] * (1.0 - t) + h[j + 1] * t;
        }
    }
    h[0].truncate() / h[0].w
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
    let (ax, ay) = arbitrary_axis(normal);
    let at = |t: f64| c + (ax * t.cos() + ay * t.sin()) * r;
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

/// Why an entity or layer was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DrawingError {
    #[error("{0} must be finite")]
    NonFinite(&'static str),
    #[error("radius must be positive and finite, got {0}")]
    BadRadius(f64),
    #[error("normal (extrusion direction) must be a finite non-zero vector")]
    BadNormal,
    #[error("a polyline needs at least 2 vertices, got {0}")]
    TooFewVertices(usize),
    #[error("need one bulge per vertex ({need}) or none, got {got}")]
    BulgeCount { need: usize, got: usize },
    #[error("text height must be positive and finite, got {0}")]
    BadTextHeight(f64),
    #[error("mesh triangle index {index} out of range (the mesh has {vertices} vertices)")]
    MeshIndex { index: usize, vertices: usize },
    #[error("bad spline: {0}")]
    Spline(String),
    #[error("colour must be an ACI number 0..=256 (layers 1..=255, negative = off), got {0}")]
    BadColor(i16),
    #[error("invalid layer name {0:?}: empty or containing one of <>/\\\":;?*|,=`")]
    BadLayerName(String),
    #[error("no entity with handle {0:X}")]
    NoSuchEntity(u64),
    #[error("layer {0:?} cannot be deleted")]
    LayerInUse(String),
}

/// The drawing: layers ("0" always exists) and entities in insertion order.
#[derive(Clone, Debug)]
pub struct Drawing {
    layers: Vec<Layer>,
    /// Sorted by handle (handles only grow), so lookups are binary searches.
    entities: Vec<Entity>,
    deleted: Vec<bool>,
    next_handle: u64,
    current_layer: String,
}

impl Default for Drawing {
    fn default() -> Self {
        Drawing::new()
    }
}

/// The first entity handle of a new drawing; lower values are left to the DXF writer's tables.
pub const FIRST_HANDLE: u64 = 0x100;

impl Drawing {
    pub fn new() -> Drawing {
        Drawing {
            layers: vec![Layer::new("0")],
            entities: Vec::new(),
            deleted: Vec::new(),
            next_handle: FIRST_HANDLE,
            current_layer: "0".to_string(),
        }
    }

    /// Forget every entity and layer except "0" (restored to its defaults); handles keep
    /// growing so an old handle never names a new entity.
    pub fn clear(&mut self) {
        self.layers = vec![Layer::new("0")];
        self.entities.clear();
        self.deleted.clear();
        self.current_layer = "0".to_string();
    }

    /// The handle the next added entity will get.
    pub fn next_handle(&self) -> u64 {
        self.next_handle
    }

    /// Add an entity (its `handle` field is overwritten), creating its layer if missing
    /// (as `entmake` does). An empty layer name means the current layer.
    pub fn add(&mut self, mut e: Entity) -> Result<u64, DrawingError> {
        e.kind.validate()?;
        check_entity_color(e.color)?;
        if e.layer.is_empty() {
            e.layer = self.current_layer.clone();
        }
        let layer_name = self.ensure_layer(&e.layer)?;
        e.layer = layer_name;
        let h = self.next_handle;
        self.next_handle += 1;
        e.handle = h;
        self.entities.push(e);
        self.deleted.push(false);
        Ok(h)
    }

    /// Add geometry on the current layer, colour BYLAYER.
    pub fn add_kind(&mut self, kind: EntityKind) -> Result<u64, DrawingError> {
        let layer = self.current_layer.clone();
        self.add(Entity::new(&layer, kind))
    }

    fn index(&self, handle: u64) -> Option<usize> {
        self.entities
            .binary_search_by_key(&handle, |e| e.handle)
            .ok()
    }

    /// The live entity with this handle.
    pub fn get(&self, handle: u64) -> Option<&Entity> {
        let i = self.index(handle)?;
        (!self.deleted[i]).then(|| &self.entities[i])
    }

    /// Mutable access to a live entity. The caller keeps it valid (prefer `replace`, which
    /// checks); the writers re-validate and refuse bad geometry with an error.
    pub fn get_mut(&mut self, handle: u64) -> Option<&mut Entity> {
        let i = self.index(handle)?;
        if self.deleted[i] {
            return None;
        }
        Some(&mut self.entities[i])
    }

    /// Replace a live entity's layer, colour and geometry (`entmod`); the handle is kept.
    pub fn replace(&mut self, handle: u64, mut e: Entity) -> Result<(), DrawingError> {
        e.kind.validate()?;
        check_entity_color(e.color)?;
        let i = self
            .index(handle)
            .filter(|&i| !self.deleted[i])
            .ok_or(DrawingError::NoSuchEntity(handle))?;
        if e.layer.is_empty() {
            e.layer = self.entities[i].layer.clone();
        }
        e.layer = self.ensure_layer(&e.layer)?;
        e.handle = handle;
        self.entities[i] = e;
        Ok(())
    }

    /// Delete a live entity; returns false when there is none with this handle.
    pub fn delete(&mut self, handle: u64) -> bool {
        match self.index(handle) {
            Some(i) if !self.deleted[i] => {
                self.deleted[i] = true;
                true
            }
            _ => false,
        }
    }

    /// Restore a deleted entity (AutoLISP's second `entdel`); false if it is not deleted.
    pub fn undelete(&mut self, handle: u64) -> bool {
        match self.index(handle) {
            Some(i) if self.deleted[i] => {
                self.deleted[i] = false;
                true
            }
            _ => false,
        }
    }

    pub fn is_deleted(&self, handle: u64) -> bool {
        self.index(handle).is_some_and(|i| self.deleted[i])
    }

    /// Live entities in insertion order.
    pub fn entities(&self) -> impl Iterator<Item = &Entity> + '_ {
        self.entities
            .iter()
            .zip(&self.deleted)
            .filter(|(_, d)| !**d)
            .map(|(e, _)| e)
    }

    pub fn len(&self) -> usize {
        self.deleted.iter().filter(|d| !**d).count()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The first live entity (`(entnext)`).
    pub fn first(&self) -> Option<u64> {
        self.entities().next().map(|e| e.handle)
    }

    /// The last live entity (`(entlast)`).
    pub fn last(&self) -> Option<u64> {
        self.entities
            .iter()
            .zip(&self.deleted)
            .rev()
            .find(|(_, d)| !**d)
            .map(|(e, _)| e.handle)
    }

    /// The live entity after `handle` in insertion order (`(entnext e)`); works from a
    /// deleted handle too.
    pub fn next_after(&self, handle: u64) -> Option<u64> {
        let start = match self.entities.binary_search_by_key(&handle, |e| e.handle) {
            Ok(i) => i + 1,
            Err(i) => i,
        };
        (start..self.entities.len())
            .find(|&i| !self.deleted[i])
            .map(|i| self.entities[i].handle)
    }

    // ---- layer table ----

    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// The layer named `name` (case-insensitive, as AutoCAD's tables are).
    pub fn layer(&self, name: &str) -> Option<&Layer> {
        self.layers
            .iter()
            .find(|l| l.name.eq_ignore_ascii_case(name))
    }

    pub fn layer_mut(&mut self, name: &str) -> Option<&mut Layer> {
        self.layers
            .iter_mut()
            .find(|l| l.name.eq_ignore_ascii_case(name))
    }

    /// Add a layer record, or replace the one with the same name (keeping its position).
    pub fn set_layer_record(&mut self, layer: Layer) -> Result<(), DrawingError> {
        check_layer_name(&layer.name)?;
        if layer.color == 0 || !(-255..=255).contains(&layer.color) {
            return Err(DrawingError::BadColor(layer.color));
        }
        match self.layer_mut(&layer.name) {
            Some(l) => *l = layer,
            None => self.layers.push(layer),
        }
        Ok(())
    }

    /// `(layer name [color])`: create the layer if missing, set its colour if given, and make
    /// it current.
    pub fn use_layer(&mut self, name: &str, color: Option<i16>) -> Result<(), DrawingError> {
        let name = self.ensure_layer(name)?;
        if let Some(c) = color {
            if c == 0 || !(-255..=255).contains(&c) {
                return Err(DrawingError::BadColor(c));
            }
            if let Some(l) = self.layer_mut(&name) {
                l.color = c;
            }
        }
        self.current_layer = name;
        Ok(())
    }

    /// The existing layer's exact name, creating a default layer if there is none.
    pub fn ensure_layer(&mut self, name: &str) -> Result<String, DrawingError> {
        if let Some(l) = self.layer(name) {
            return Ok(l.name.clone());
        }
        check_layer_name(name)?;
        self.layers.push(Layer::new(name));
        Ok(name.to_string())
    }

    pub fn current_layer(&self) -> &str {
        &self.current_layer
    }

    /// Remove a layer that no live entity uses (never "0" nor the current layer).
    pub fn remove_layer(&mut self, name: &str) -> Result<(), DrawingError> {
        let in_use = name == "0"
            || self.current_layer.eq_ignore_ascii_case(name)
            || self.entities().any(|e| e.layer.eq_ignore_ascii_case(name));
        if in_use {
            return Err(DrawingError::LayerInUse(name.to_string()));
        }
        self.layers.retain(|l| !l.name.eq_ignore_ascii_case(name));
        Ok(())
    }

    /// The effective ACI colour of an entity (BYLAYER/BYBLOCK resolved to the layer's).
    pub fn effective_color(&self, e: &Entity) -> i16 {
        match e.color {
            Some(c) if (1..=255).contains(&c) => c,
            _ => self.layer(&e.layer).map_or(7, |l| l.color.abs()),
        }
    }

    /// The bounding box (min, max) of every live entity, or `None` for an empty drawing.
    pub fn extents(&self) -> Option<(DVec3, DVec3)> {
        let mut pts = Vec::new();
        let mut bb: Option<(DVec3, DVec3)> = None;
        for e in self.entities() {
            pts.clear();
            e.kind.extent_points(&mut pts);
            for p in &pts {
                bb = Some(match bb {
                    None => (*p, *p),
                    Some((lo, hi)) => (lo.min(*p), hi.max(*p)),
                });
            }
        }
        bb
    }
}

fn check_entity_color(c: Option<i16>) -> Result<(), DrawingError> {
    match c {
        Some(c) if !(0..=256).contains(&c) => Err(DrawingError::BadColor(c)),
        _ => Ok(()),
    }
}

fn check_layer_name(name: &str) -> Result<(), DrawingError> {
    let bad = name.is_empty()
        || name.len() > 255
        || name
            .chars()
            .any(|c| "<>/\\\":;?*|,=`".contains(c) || c.is_control());
    if bad {
        Err(DrawingError::BadLayerName(name.to_string()))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(x: f64) -> EntityKind {
        EntityKind::Line {
            p0: DVec3::ZERO,
            p1: DVec3::new(x, 1.0, 0.0),
        }
    }

    #[test]
    fn handles_are_unique_ordered_and_survive_deletion() {
        let mut d = Drawing::new();
        let a = d.add_kind(line(1.0)).unwrap();
        let b = d.add_kind(line(2.0)).unwrap();
        let c = d.add_kind(line(3.0)).unwrap();
        assert!(a < b && b < c);
        assert_eq!(d.first(), Some(a));
        assert_eq!(d.next_after(a), Some(b));
        assert!(d.delete(b));
        assert!(!d.delete(b));
        assert_eq!(d.next_after(a), Some(c));
        assert_eq!(d.next_after(b), Some(c));
        assert!(d.get(b).is_none());
        assert!(d.undelete(b));
        assert_eq!(d.get(b).unwrap().handle, b);
        assert_eq!(d.last(), Some(c));
        d.clear();
        let e = d.add_kind(line(4.0)).unwrap();
        assert!(e > c, "handles are never reused");
        assert_eq!(d.len(), 1);
    }

    #[test]
    fn layers_are_created_and_case_insensitive() {
        let mut d = Drawing::new();
        d.use_layer("Outline", Some(1)).unwrap();
        let h = d.add_kind(line(1.0)).unwrap();
        assert_eq!(d.get(h).unwrap().layer, "Outline");
        d.use_layer("OUTLINE", None).unwrap();
        assert_eq!(d.current_layer(), "Outline");
        assert_eq!(d.layers().len(), 2);
        assert_eq!(d.effective_color(d.get(h).unwrap()), 1);
        assert!(d.use_layer("bad/name", None).is_err());
        assert!(d.use_layer("x", Some(300)).is_err());
        assert!(d.remove_layer("Outline").is_err());
    }

    #[test]
    fn bad_geometry_is_refused() {
        let mut d = Drawing::new();
        let r = d.add_kind(EntityKind::Circle {
            center: DVec3::ZERO,
            radius: -1.0,
            normal: DVec3::Z,
        });
        assert_eq!(r, Err(DrawingError::BadRadius(-1.0)));
        let r = d.add_kind(EntityKind::Line {
            p0: DVec3::new(f64::NAN, 0.0, 0.0),
            p1: DVec3::ZERO,
        });
        assert!(r.is_err());
        assert!(d.is_empty());
    }

    #[test]
    fn bulge_arc_is_a_semicircle_for_bulge_one() {
        let (c, r, a0, a1) = bulge_arc(DVec2::ZERO, DVec2::new(2.0, 0.0), 1.0).unwrap();
        assert!((c - DVec2::new(1.0, 0.0)).length() < 1e-15);
        assert!((r - 1.0).abs() < 1e-15);
        assert!((a1 - a0 - std::f64::consts::PI).abs() < 1e-15);
        // Positive bulge = counter-clockwise from a to b: the arc passes below the chord.
        let mid = c + DVec2::from_angle((a0 + a1) / 2.0) * r;
        assert!((mid - DVec2::new(1.0, -1.0)).length() < 1e-15);
    }

    #[test]
    fn extents_include_arc_extremes() {
        let mut d = Drawing::new();
        d.add_kind(EntityKind::Arc {
            center: DVec3::ZERO,
            radius: 2.0,
            start: 0.0,
            end: std::f64::consts::PI,
            normal: DVec3::Z,
        })
        .unwrap();
        let (lo, hi) = d.extents().unwrap();
        assert!((lo - DVec3::new(-2.0, 0.0, 0.0)).length() < 1e-12);
        assert!((hi - DVec3::new(2.0, 2.0, 0.0)).length() < 1e-12);
    }
}
