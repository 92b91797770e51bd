//! The drawing model and its writers (SVG, DXF).
