//! Parametric surfaces of paper 002, kept parametric, and their tessellation into meshes.
//!
//! Paper 002 builds surfaces four ways — swept (a profile along a guide), revolved, ruled and
//! boundary (from four edges) — plus planes; lispcad adds cylinders and spheres. Each is stored
//! by its defining data and evaluated at (u, v) in [0, 1]²; [`mesh_surface`] turns any of them
//! into the discrete surface of paper 001 within a chord tolerance. Curves come in as
//! [`CurveRef`] (any [`ParamCurve`]); [`SampledCurve`] wraps a point list.

mod analytic;
mod beside;
mod coaxial;
mod coincide;
mod common;
mod cone;
mod contact;
mod error;
mod hits;
mod join;
mod kinds;
mod loose;
mod ops;
mod overlap;
mod planar;
mod quadrics;
mod refine;
mod sampled;
mod separable;
mod sweep;
mod tessellate;

pub use error::SurfaceError;
pub use hits::{
    circle_plane, curve_mesh_hits, cylinder_section, point_in_convex_facet, point_in_polygon,
    polyline_mesh_hits, segment_cylinder, segment_plane, ArcData, CylinderHit, FacetLocation,
    MeshHit,
};
pub use kinds::{Coons, Cylinder, PlaneRegion, Revolve, Ruled, Sphere, Surface, Sweep};
pub use ops::{
    arc_surface_hits, curve_on_surface, curve_surface_hits, curve_surface_hits_refined,
    segment_surface_hits, surface_area, surface_boundary, surface_intersect,
    surface_intersect_seeded, surface_intersect_tol, surface_meet, surface_section,
    surface_section_seeded, surface_section_tol, Meet,
};
#[doc(hidden)]
pub use ops::{surface_intersect_without_contacts, surface_section_without_contacts};
pub use planar::triangulate_polygon;
pub use sampled::{sample_curve, SampledCurve};
pub use sweep::{rotation_minimizing_frames, Frame};
pub use tessellate::mesh_surface;

use crate::geom::ParamCurve;
use std::sync::Arc;

/// A shared curve: whatever implements [`ParamCurve`] (public parameter in [0, 1]).
pub type CurveRef = Arc<dyn ParamCurve + Send + Sync>;

/// A surface evaluated at (u, v) in [0, 1]².
pub trait ParamSurface {
    /// The point at (u, v).
    fn eval(&self, u: f64, v: f64) -> glam::DVec3;
}
