//! Why a curve could not be built or a query could not be answered.
//!
//! Every message names the offending parameter and the limit it broke, so the language layer
//! can show it to the user unchanged.

use super::bspline::BSplineError;

/// A refused geometric input or an unsupported query.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum GeomError {
    /// A coordinate, length or angle was NaN or infinite.
    #[error("{param} must be finite, got {value}")]
    NonFinite { param: &'static str, value: String },
    /// A parameter broke a limit (e.g. radius <= 0, zero-length line).
    #[error("{param}: {limit}")]
    Invalid { param: &'static str, limit: String },
    /// The query needs a closed curve.
    #[error("{0}: the curve is not closed")]
    NotClosed(&'static str),
    /// The query needs a planar curve.
    #[error("{0}: the curve is not planar")]
    NotPlanar(&'static str),
    /// The operation is not available for this curve kind.
    #[error("{0}")]
    Unsupported(String),
    /// Bad B-spline data.
    #[error("bspline: {0}")]
    BSpline(#[from] BSplineError),
}

pub type Result<T> = std::result::Result<T, GeomError>;

/// `Ok(v)` when `v` is finite, else a `NonFinite` error naming `param`.
pub(crate) fn finite(param: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(GeomError::NonFinite {
            param,
            value: format!("{v}"),
        })
    }
}

/// `Ok(p)` when every coordinate of `p` is finite.
pub(crate) fn finite3(param: &'static str, p: glam::DVec3) -> Result<glam::DVec3> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(GeomError::NonFinite {
            param,
            value: format!("({} {} {})", p.x, p.y, p.z),
        })
    }
}

pub(crate) fn invalid(param: &'static str, limit: impl Into<String>) -> GeomError {
    GeomError::Invalid {
        param,
        limit: limit.into(),
    }
}
