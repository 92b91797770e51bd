//! The geometry core: curves, intersection, splines, surfaces, meshes and the temple bend.
//!
//! Pure Rust over glam's f64 types. Nothing here knows about the language (`Value`):
//! the bindings in `src/builtins` convert.

pub mod bspline;
pub mod frame;
pub mod quadspline;
pub mod quadspline_fit;
pub mod quadspline_query;
pub mod temple;
pub mod temple_refine;
pub mod traits;

pub use glam::{DMat4, DVec2, DVec3};
pub use traits::ParamCurve;
pub mod arc;
pub mod bernstein;
pub mod bezier;
pub mod circle;
pub mod curve;
pub mod error;
pub mod intersect;
pub mod line;
pub mod offset;
pub mod piece;
pub mod polyline;

pub use curve::Curve;
pub use error::GeomError;
pub use intersect::{intersect, intersect_near, Hit, HitKind};
