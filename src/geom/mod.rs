//! The geometry core: curves, intersection, splines, surfaces, meshes and the temple bend.
//!
//! Pure Rust over glam's f64 types. Nothing here knows about the language (`Value`):
//! the bindings in `src/builtins` convert.
//!
//! Curves: `line`, `circle`, `arc`, `polyline` (bulges), `quadspline` (the temple paper's
//! spline), `bspline` (NURBS); the `Curve` enum (`curve.rs`) unites them with the queries and
//! transforms SPEC §4 names; `offset.rs` offsets planar curves; `intersect/` intersects any
//! two. Shared machinery: `piece.rs` (lines, arcs and Bézier spans every curve decomposes
//! into), `bezier.rs`, `bernstein.rs` (root isolation), `traits.rs` (capabilities).

pub mod arc;
pub mod bernstein;
pub mod bezier;
pub mod bspline;
pub mod circle;
pub mod curve;
pub mod curve_measure;
pub mod ellipse;
pub mod error;
pub(crate) mod fastmath;
pub mod frame;
pub mod intersect;
pub(crate) mod lanes;
pub mod line;
pub mod mesh;
pub mod minimize;
pub mod offset;
pub mod piece;
pub mod polyline;
pub mod quadspline;
pub mod quadspline_fit;
pub mod quadspline_query;
pub mod root;
pub mod surface;
pub mod temple;
pub mod temple_refine;
#[cfg(test)]
pub(crate) mod test_rng;
pub mod traits;

pub use curve::Curve;
pub use error::GeomError;
pub use glam::{DMat4, DVec2, DVec3};
pub use intersect::{intersect, intersect_near, Hit, HitKind, GEOMTOL};
pub use traits::ParamCurve;
