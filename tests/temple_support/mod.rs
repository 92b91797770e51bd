//! Shared by the temple tests and the temple benchmark (benches/geom_temple.rs includes it with
//! `#[path]`): the outline of scripts/temple.lsp.
#![allow(
    dead_code,
    reason = "each crate including this module uses only one of the two functions"
)]

use glam::DVec3;

/// Outline of scripts/temple.lsp with the given widths (half widths derived as there): hinge
/// end at x = 0, slimmest at 0.7·L1, tip at 0.9·L1, apex at (L1, 0).
pub fn outline(l1: f64, hinge: f64, min: f64, tip: f64) -> Vec<DVec3> {
    let (h0, hm, ht) = (hinge / 2.0, min / 2.0, tip / 2.0);
    let hq = hm + 0.3 * (h0 - hm);
    [
        (0.0, -h0),
        (0.04 * l1, -h0),
        (0.35 * l1, -hq),
        (0.7 * l1, -hm),
        (0.9 * l1, -ht),
        (l1, 0.0),
        (0.9 * l1, ht),
        (0.7 * l1, hm),
        (0.35 * l1, hq),
        (0.04 * l1, h0),
        (0.0, h0),
    ]
    .iter()
    .map(|(x, y)| DVec3::new(*x, *y, 0.0))
    .collect()
}

/// The default outline of scripts/temple.lsp (hinge 5, slimmest 3.5, tip 7; half widths 2.5,
/// 1.75, 3.5), used across the tests and the benchmark.
pub fn default_outline(l1: f64) -> Vec<DVec3> {
    outline(l1, 5.0, 3.5, 7.0)
}
