//! The drawing model: a layer table and entities in insertion order, each with a stable handle.
//!
//! Entities mirror AutoCAD's (so `entmake`/`entget` map one-to-one onto them). Deleted entities
//! stay in place as tombstones, because AutoLISP's `entdel` on a deleted entity restores it and
//! handles must never be reused.

use std::collections::HashMap;

use glam::DVec3;

use super::document::DxfDocument;
pub use super::entity::{bulge_arc, bulge_segments, ccw_sweep, is_flat, Entity, EntityKind};
use super::record::TagList;

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
    #[error("invalid line type name {0:?}: containing one of <>/\\\":;?*|,=`")]
    BadLinetype(String),
    #[error("no entity with handle {0:X}")]
    NoSuchEntity(u64),
    #[error("layer {0:?} cannot be deleted")]
    LayerInUse(String),
}

/// An entity as it was read from a file: its groups (with its VERTEX/ATTRIB/SEQEND
/// followers) and the entity as first built from them. The writer puts the groups back
/// unchanged while the entity still equals `original`.
#[derive(Clone, Debug, PartialEq)]
pub struct SourceRecord {
    pub tags: TagList,
    pub original: Entity,
    /// For an entity of a layout other than model space and the active paper space: the
    /// index of its layout's BLOCK record in the BLOCKS section, where it is written back.
    pub block: Option<usize>,
}

/// The drawing: layers ("0" always exists) and entities in insertion order.
#[derive(Clone, Debug)]
pub struct Drawing {
    layers: Vec<Layer>,
    /// In insertion (file) order. Sorted by handle for drawings made from scratch (handles
    /// only grow), so lookups are binary searches; an opened file's order may not be, and
    /// then `by_handle` indexes them.
    entities: Vec<Entity>,
    deleted: Vec<bool>,
    /// Parallel to `entities`: the groups an entity was read from, if it was.
    sources: Vec<Option<Box<SourceRecord>>>,
    by_handle: Option<HashMap<u64, usize>>,
    next_handle: u64,
    current_layer: String,
    /// The file the drawing was opened from, minus its entities.
    document: Option<Box<DxfDocument>>,
    /// Extended data, registered applications and objects (`objects.rs`).
    pub(super) extras: super::objects::Extras,
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
            sources: Vec::new(),
            by_handle: None,
            next_handle: FIRST_HANDLE,
            current_layer: "0".to_string(),
            document: None,
            extras: Default::default(),
        }
    }

    /// The file this drawing was opened from (its tables, blocks, objects...), if any.
    pub fn document(&self) -> Option<&DxfDocument> {
        self.document.as_deref()
    }

    /// The opened file's tables and blocks, to add records to (`dxf-import`, APPIDs).
    pub fn document_mut(&mut self) -> Option<&mut DxfDocument> {
        self.document.as_deref_mut()
    }

    /// A fresh handle for a record that is not an entity (dictionary, XRECORD, APPID...).
    pub fn alloc_handle(&mut self) -> u64 {
        let h = self.next_handle;
        self.next_handle += 1;
        h
    }

    pub fn set_document(&mut self, doc: DxfDocument) {
        self.document = Some(Box::new(doc));
    }

    /// The groups a live or deleted entity was read from, if it was read from a file.
    pub fn source(&self, handle: u64) -> Option<&SourceRecord> {
        self.sources[self.index(handle)?].as_deref()
    }

    pub fn source_mut(&mut self, handle: u64) -> Option<&mut SourceRecord> {
        let i = self.index(handle)?;
        self.sources[i].as_deref_mut()
    }

    /// Replace the groups an entity kept as read is written from (`entmod` of an INSERT,
    /// HATCH...); false when it has none.
    pub fn set_source_tags(&mut self, handle: u64, tags: TagList) -> bool {
        match self.source_mut(handle) {
            Some(s) => {
                s.tags = tags;
                true
            }
            None => false,
        }
    }

    /// Start new handles at `h` (an opened file's `$HANDSEED`), for a drawing with no
    /// entities yet; never below an existing entity's handle.
    pub fn set_handle_seed(&mut self, h: u64) {
        let used = self
            .entities
            .iter()
            .map(|e| e.handle + 1)
            .max()
            .unwrap_or(1);
        self.next_handle = h.max(used);
    }

    /// Replace the layer table with layers read from a file (their names are not re-checked:
    /// the file's own are kept as they are). "0" is added if the file lacks it.
    pub fn set_loaded_layers(&mut self, mut layers: Vec<Layer>) {
        if !layers.iter().any(|l| l.name == "0") {
            layers.insert(0, Layer::new("0"));
        }
        self.layers = layers;
    }

    /// Make an existing layer current.
    pub fn set_current_layer(&mut self, name: &str) -> Result<(), DrawingError> {
        let l = self
            .layer(name)
            .ok_or_else(|| DrawingError::BadLayerName(name.to_string()))?;
        self.current_layer = l.name.clone();
        Ok(())
    }

    /// Append an entity read from a file, keeping its handle when it has a free one (else a
    /// fresh one), and its layer as written (added to the table if missing). No checks: a
    /// file's entities are kept even when lispcad could not have made them.
    pub fn push_loaded(&mut self, mut e: Entity, source: Option<SourceRecord>) -> u64 {
        if e.handle == 0 || self.index(e.handle).is_some() {
            e.handle = self.next_handle;
        }
        self.next_handle = self.next_handle.max(e.handle + 1);
        if self.layer(&e.layer).is_none() {
            self.layers.push(Layer::new(&e.layer));
        }
        let h = e.handle;
        // A record the file gave no handle (old R12 files) keeps having none when written back.
        let source = source.map(|mut s| {
            if s.original.handle == 0 {
                s.original.handle = h;
            }
            s
        });
        let i = self.entities.len();
        let sorted = self.entities.last().is_none_or(|l| l.handle < h);
        if !sorted && self.by_handle.is_none() {
            self.by_handle = Some(
                self.entities
                    .iter()
                    .enumerate()
                    .map(|(i, e)| (e.handle, i))
                    .collect(),
            );
        }
        if let Some(m) = &mut self.by_handle {
            m.insert(h, i);
        }
        self.entities.push(e);
        self.deleted.push(false);
        self.sources.push(source.map(Box::new));
        h
    }

    /// Live entities with the groups they were read from (`None` for new ones).
    pub fn entities_with_sources(
        &self,
    ) -> impl Iterator<Item = (&Entity, Option<&SourceRecord>)> + '_ {
        self.entities
            .iter()
            .zip(&self.deleted)
            .zip(&self.sources)
            .filter(|((_, d), _)| !**d)
            .map(|((e, _), s)| (e, s.as_deref()))
    }

    /// Forget every entity and layer except "0" (restored to its defaults); handles keep
    /// growing so an old handle never names a new entity.
    pub fn clear(&mut self) {
        self.layers = vec![Layer::new("0")];
        self.entities.clear();
        self.deleted.clear();
        self.sources.clear();
        self.by_handle = None;
        self.document = None;
        self.extras = Default::default();
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
        if let Some(m) = &mut self.by_handle {
            m.insert(h, self.entities.len());
        }
        self.entities.push(e);
        self.deleted.push(false);
        self.sources.push(None);
        Ok(h)
    }

    /// Add geometry on the current layer, colour BYLAYER.
    pub fn add_kind(&mut self, kind: EntityKind) -> Result<u64, DrawingError> {
        let layer = self.current_layer.clone();
        self.add(Entity::new(&layer, kind))
    }

    fn index(&self, handle: u64) -> Option<usize> {
        match &self.by_handle {
            Some(m) => m.get(&handle).copied(),
            None => self
                .entities
                .binary_search_by_key(&handle, |e| e.handle)
                .ok(),
        }
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
        let start = match (&self.by_handle, self.index(handle)) {
            (_, Some(i)) => i + 1,
            (Some(_), None) => return None,
            (None, None) => self.entities.partition_point(|e| e.handle < handle),
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
    pub fn set_layer_record(&mut self, mut layer: Layer) -> Result<(), DrawingError> {
        check_layer_name(&layer.name)?;
        // A layer always names a line type the writers can define.
        if layer.linetype.trim().is_empty() {
            layer.linetype = "Continuous".to_string();
        } else if layer
            .linetype
            .chars()
            .any(|c| "<>/\\\":;?*|,=`".contains(c) || c.is_control())
        {
            return Err(DrawingError::BadLinetype(layer.linetype));
        }
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
        self.extents_with(&super::entity::fresh_beziers)
    }

    /// `extents` with splines decomposed by `beziers` (see `EntityKind::extent_points_with`).
    pub fn extents_with(&self, beziers: &super::entity::BezierSource) -> Option<(DVec3, DVec3)> {
        let mut pts = Vec::new();
        let mut bb: Option<(DVec3, DVec3)> = None;
        for e in self.entities() {
            pts.clear();
            e.kind.extent_points_with(&mut pts, beziers);
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
    use glam::DVec2;

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
