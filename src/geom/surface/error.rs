//! Errors of surface construction and surface operations.

use crate::geom::mesh::MeshError;
use thiserror::Error;

/// What went wrong building or using a surface.
#[derive(Debug, Error)]
pub enum SurfaceError {
    #[error("{parameter} must be {limit}, got {value}")]
    BadParameter {
        parameter: &'static str,
        limit: &'static str,
        value: f64,
    },
    #[error("{0}")]
    Invalid(String),
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

pub(crate) fn check_positive(parameter: &'static str, value: f64) -> Result<f64, SurfaceError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(SurfaceError::BadParameter {
            parameter,
            limit: "finite and > 0",
            value,
        })
    }
}

pub(crate) fn check_unit(
    parameter: &'static str,
    v: glam::DVec3,
) -> Result<glam::DVec3, SurfaceError> {
    let l = v.length();
    if l > 0.0 && l.is_finite() {
        Ok(v / l)
    } else {
        Err(SurfaceError::BadParameter {
            parameter,
            limit: "a finite non-zero vector (its length)",
            value: l,
        })
    }
}

pub(crate) fn check_point(
    parameter: &'static str,
    p: glam::DVec3,
) -> Result<glam::DVec3, SurfaceError> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(SurfaceError::Invalid(format!(
            "{parameter} must have finite coordinates"
        )))
    }
}
