//! `ssget` by area, on the drawing's geometry seen in plan (X and Y): window "W" and
//! window polygon "WP" take the entities entirely inside, crossing "C" and crossing polygon
//! "CP" also those crossing the boundary, fence "F" those the open polyline crosses
//! (AutoCAD's selection modes). An entity is inside when every point of its tight extents
//! (ends, arc and spline extremes) is; it crosses when the geometry core's intersection
//! finds a hit between its curve and a boundary edge, drawn at the entity's elevation.

use glam::{DVec2, DVec3};

use crate::builtins::vla::curve::entity_curve;
use crate::geom::{intersect, Curve, GEOMTOL};
use crate::output::{Drawing, Entity};

/// How the boundary selects.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum AreaMode {
    Window,
    Crossing,
    Fence,
}

/// Whether `p` is inside the closed polygon (boundary included).
fn inside(poly: &[DVec2], p: DVec2) -> bool {
    let n = poly.len();
    let mut wind = false;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        // On an edge counts as inside.
        let ab = b - a;
        let t = (p - a).dot(ab) / ab.length_squared().max(f64::MIN_POSITIVE);
        if (0.0..=1.0).contains(&t) && (a + ab * t - p).length() <= GEOMTOL {
            return true;
        }
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            wind = !wind;
        }
    }
    wind
}

/// Whether the entity's curve meets one of the boundary's edges.
fn crosses(e: &Entity, edges: &[(DVec2, DVec2)], z: f64) -> bool {
    let Some(Ok(curve)) = entity_curve(&e.kind) else {
        return false;
    };
    edges.iter().any(|(a, b)| {
        Curve::line(a.extend(z), b.extend(z))
            .map(|edge| !intersect(&curve, &edge, GEOMTOL).is_empty())
            .unwrap_or(false)
    })
}

/// The live entities the boundary `pts` selects, in drawing order: a window/crossing
/// polygon (closed), or a fence (open).
pub fn select_area(d: &Drawing, pts: &[DVec2], mode: AreaMode) -> Vec<u64> {
    let n = pts.len();
    let edges: Vec<(DVec2, DVec2)> = match mode {
        AreaMode::Fence => pts.windows(2).map(|w| (w[0], w[1])).collect(),
        _ => (0..n).map(|i| (pts[i], pts[(i + 1) % n])).collect(),
    };
    let mut ext: Vec<DVec3> = Vec::new();
    let mut out = Vec::new();
    for e in d.entities() {
        ext.clear();
        e.kind.extent_points(&mut ext);
        if ext.is_empty() {
            continue;
        }
        let z = ext[0].z;
        let picked = match mode {
            AreaMode::Fence => crosses(e, &edges, z),
            AreaMode::Window => {
                ext.iter().all(|p| inside(pts, p.truncate())) && !cuts(e, &edges, z, pts)
            }
            AreaMode::Crossing => {
                ext.iter().any(|p| inside(pts, p.truncate())) || crosses(e, &edges, z)
            }
        };
        if picked {
            out.push(e.handle);
        }
    }
    out
}

/// Whether an entity whose extents are inside a window polygon still leaves it: only a
/// concave polygon lets a curve out between its extent points, and then the curve meets
/// the boundary (touching it counts as not entirely inside).
fn cuts(e: &Entity, edges: &[(DVec2, DVec2)], z: f64, poly: &[DVec2]) -> bool {
    !is_convex(poly) && crosses(e, edges, z)
}

fn is_convex(poly: &[DVec2]) -> bool {
    let n = poly.len();
    let mut sign = 0.0;
    for i in 0..n {
        let (a, b, c) = (poly[i], poly[(i + 1) % n], poly[(i + 2) % n]);
        let cross = (b - a).perp_dot(c - b);
        if cross.abs() > 1e-15 {
            if sign != 0.0 && cross.signum() != sign {
                return false;
            }
            sign = cross.signum();
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_in_polygon_includes_the_boundary() {
        let sq = [
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ];
        assert!(inside(&sq, DVec2::new(1.0, 1.0)));
        assert!(inside(&sq, DVec2::new(2.0, 1.0)));
        assert!(!inside(&sq, DVec2::new(2.5, 1.0)));
        assert!(is_convex(&sq));
        let l = [
            DVec2::ZERO,
            DVec2::new(4.0, 0.0),
            DVec2::new(4.0, 1.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(1.0, 4.0),
            DVec2::new(0.0, 4.0),
        ];
        assert!(!is_convex(&l));
        assert!(!inside(&l, DVec2::new(3.0, 3.0)));
    }
}
