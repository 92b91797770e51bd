//! Parametric surfaces (paper 002) and their tessellation into meshes.
