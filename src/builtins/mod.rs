//! The library, one module per area; each registers its builtins with a one-line doc.

pub mod text;
