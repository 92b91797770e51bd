//! Errors of mesh construction, import/export and mesh operations.

use thiserror::Error;

/// What went wrong with a mesh or a mesh operation.
#[derive(Debug, Error)]
pub enum MeshError {
    #[error("triangle {triangle} refers to a vertex index beyond the {vertices} vertices")]
    IndexOutOfRange { triangle: usize, vertices: usize },
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinite { vertex: usize },
    #[error("mesh too large: {vertices} vertices (limit u32::MAX - 1)")]
    TooLarge { vertices: usize },
    #[error("cannot read {path}: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: {message}")]
    Parse { path: String, message: String },
    #[error("unknown mesh file extension of {path} (expected .stl or .obj)")]
    UnknownFormat { path: String },
    #[error("{parameter} must be {limit}, got {value}")]
    BadParameter {
        parameter: &'static str,
        limit: &'static str,
        value: f64,
    },
    #[error("{0}")]
    Invalid(String),
}
