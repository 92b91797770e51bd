//! Visual LISP: the `vlax-curve-*` family (`curve.rs`), the ActiveX object model over the
//! drawing (`object.rs`, `props.rs`, `methods.rs`) and variants and safearrays (`variant.rs`).
//! A VLA object is an opaque value (`Vla`) naming the application, the document, a collection,
//! a table record or an entity by handle; its properties are read from the drawing each time,
//! so an object never goes stale after `entmod` or `command`.

use std::collections::HashMap;
use std::fmt;

use crate::lang::builtin::Builtin;
use crate::lang::value::Object;
use crate::lang::{Interp, Value};
use crate::output::entity::EntityKind;

pub mod compat;
pub mod curve;
pub mod methods;
pub mod object;
pub mod props;
pub mod variant;
pub mod xform;

/// Every Visual LISP builtin, for `builtins::tables` (a constant: the symbol table is built
/// from it at compile time).
pub const TABLES: &[(&str, &[Builtin])] = &[
    ("Visual LISP: curves (vlax-curve-*)", curve::BUILTINS),
    ("Visual LISP: ActiveX objects", object::BUILTINS),
    (
        "Visual LISP: properties (vla-get-*, vla-put-*)",
        object::PROPS,
    ),
    ("Visual LISP: methods (vla-*)", object::METHODS),
    ("Visual LISP: variants and safearrays", variant::BUILTINS),
    ("AutoCAD compatibility", compat::BUILTINS),
];

/// The ActiveX constants (vlax-vb*, :vlax-true, acExtend*...).
pub fn init(it: &mut Interp) {
    variant::init(it);
}

/// What a VLA object stands for.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Vla {
    Application,
    Document,
    ModelSpace,
    PaperSpace,
    Layers,
    Blocks,
    Layer(String),
    /// A block definition (the model and paper space blocks are the only ones headless).
    Block(String),
    /// An entity by handle, with its interface name (an entity never changes kind).
    Entity(u64, &'static str),
}

impl Object for Vla {
    fn type_name(&self) -> &'static str {
        "VLA-OBJECT"
    }
    /// `#<VLA-OBJECT IAcadLine>`: AutoCAD's form without the address, for deterministic output.
    fn print(&self, f: &mut dyn fmt::Write) -> fmt::Result {
        write!(f, "#<VLA-OBJECT {}>", self.interface_static())
    }
    fn equal(&self, other: &dyn Object) -> bool {
        other.as_any().downcast_ref::<Vla>() == Some(self)
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

impl Vla {
    /// The ActiveX interface name (`IAcadLine`, `IAcadModelSpace`...).
    pub fn interface_static(&self) -> &'static str {
        match self {
            Vla::Application => "IAcadApplication",
            Vla::Document => "IAcadDocument",
            Vla::ModelSpace => "IAcadModelSpace",
            Vla::PaperSpace => "IAcadPaperSpace",
            Vla::Layers => "IAcadLayers",
            Vla::Blocks => "IAcadBlocks",
            Vla::Layer(_) => "IAcadLayer",
            Vla::Block(_) => "IAcadBlock",
            Vla::Entity(_, class) => class,
        }
    }
}

/// The ActiveX interface and the ObjectName of an entity kind.
pub fn entity_class(k: &EntityKind) -> (&'static str, &'static str) {
    match k {
        EntityKind::Line { .. } => ("IAcadLine", "AcDbLine"),
        EntityKind::Circle { .. } => ("IAcadCircle", "AcDbCircle"),
        EntityKind::Arc { .. } => ("IAcadArc", "AcDbArc"),
        EntityKind::Point { .. } => ("IAcadPoint", "AcDbPoint"),
        EntityKind::LwPolyline { .. } => ("IAcadLWPolyline", "AcDbPolyline"),
        EntityKind::Polyline { points, .. } => {
            if points.iter().all(|p| p.z == points[0].z) {
                ("IAcadPolyline", "AcDb2dPolyline")
            } else {
                ("IAcad3DPolyline", "AcDb3dPolyline")
            }
        }
        EntityKind::Spline { .. } => ("IAcadSpline", "AcDbSpline"),
        EntityKind::Face3d { .. } => ("IAcad3DFace", "AcDbFace"),
        EntityKind::Text { .. } => ("IAcadText", "AcDbText"),
        EntityKind::Mesh { .. } => ("IAcadPolyfaceMesh", "AcDbPolyFaceMesh"),
        EntityKind::Ellipse { .. } => ("IAcadEllipse", "AcDbEllipse"),
        EntityKind::Unmodelled { dxf_type } => match dxf_type.as_str() {
            "INSERT" => ("IAcadBlockReference", "AcDbBlockReference"),
            "MTEXT" => ("IAcadMText", "AcDbMText"),
            "HATCH" => ("IAcadHatch", "AcDbHatch"),
            "DIMENSION" => ("IAcadDimension", "AcDbDimension"),
            "SOLID" => ("IAcadSolid", "AcDbTrace"),
            "VIEWPORT" => ("IAcadPViewport", "AcDbViewport"),
            "ATTDEF" => ("IAcadAttribute", "AcDbAttributeDefinition"),
            "LEADER" => ("IAcadLeader", "AcDbLeader"),
            "XLINE" => ("IAcadXline", "AcDbXline"),
            "RAY" => ("IAcadRay", "AcDbRay"),
            _ => ("IAcadEntity", "AcDbEntity"),
        },
    }
}

/// One value per VLA object, so `eq` holds between two conversions of the same entity.
#[derive(Default)]
pub struct VlaCache(HashMap<Vla, Value>);

/// The value of a VLA object.
pub fn vla_value(it: &mut Interp, v: Vla) -> Value {
    it.ext::<VlaCache>()
        .0
        .entry(v.clone())
        .or_insert_with(|| Value::obj(v))
        .clone()
}
