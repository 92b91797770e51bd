//! Corners and extension (paper 003).
