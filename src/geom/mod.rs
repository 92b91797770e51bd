//! The geometry core: curves, intersection, splines, surfaces, meshes and the temple bend.
//!
//! Pure Rust over glam's f64 types. Nothing here knows about the language (`Value`):
//! the bindings in `src/builtins` convert.

pub mod bspline;
pub mod frame;
pub mod mesh;
pub mod quadspline;
pub mod surface;
pub mod traits;

pub use glam::{DMat4, DVec2, DVec3};
pub use traits::ParamCurve;
