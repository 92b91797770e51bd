//! Whether a seed of the contact search (or the point its minimisation reached) belongs to a
//! contact already found. Nearness alone is not enough: the search's nearness is four mesh
//! cells of the seed's longest edge, and where the cells are long one way (a ruled strip's
//! rulings, 1.5 or 3 long at a coarse CHORDTOL) a second contact four units across them, behind
//! a ridge, was taken for the first and lost. Two lows are one only where the surfaces do not
//! part between them: the gap is sampled on the true surfaces along the parameter line from the
//! point to the nearest point of the contact.

use super::super::refine::Patch;
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

/// Samples along the parameter line from a point to the contact nearest it: a ridge narrower
/// than an eighth of the way (at most half a cell of the seed's longest edge) is not seen.
const SAMPLES: usize = 8;

/// The contacts found so far, as the search on `a` measures the gap to the other surface.
pub(super) struct Found<'c> {
    pub a: &'c Patch<'c>,
    /// The distance from `a(uv)` to the other surface (or the plane), on the true surfaces.
    pub gap: &'c dyn Fn(DVec2) -> f64,
    /// How far the gap may rise between two points of one low above the higher of them: the
    /// seeding meshes' tolerance, below which the seeds cannot tell a rise from their error.
    pub rise: f64,
}

impl Found<'_> {
    /// Whether `p`, a point of `a`, belongs to one of `out`: one passes within `r` of it, and
    /// the gap does not rise between `p` and its nearest point by more than [`Found::rise`].
    pub(super) fn claims(&self, p: DVec3, out: &[Polyline3], r: f64) -> bool {
        nearest_within(p, out, r).is_some_and(|c| !self.ridge_between(p, c))
    }

    fn ridge_between(&self, p: DVec3, c: DVec3) -> bool {
        let a = self.a;
        let up = a.project(p, None);
        let uc = a.project(c, Some(up));
        // Across a seam the short way round.
        let mut d = uc - up;
        for (k, periodic) in a.periodic().into_iter().enumerate() {
            if periodic {
                d[k] -= d[k].round();
            }
        }
        let top = (self.gap)(up).max((self.gap)(uc)) + self.rise;
        (1..SAMPLES).any(|i| {
            let mut uv = up + d * (i as f64 / SAMPLES as f64);
            a.normalise(&mut uv);
            // A NaN gap (a degenerate point) is no evidence of a ridge.
            (self.gap)(uv) > top
        })
    }
}

/// The point of `curves` (points, or segments of polylines) nearest `p`, if within `r`.
fn nearest_within(p: DVec3, curves: &[Polyline3], r: f64) -> Option<DVec3> {
    let mut best: Option<(f64, DVec3)> = None;
    for q in super::closest_points(p, curves) {
        let d = q.distance(p);
        if d <= r && best.is_none_or(|b| d < b.0) {
            best = Some((d, q));
        }
    }
    best.map(|b| b.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: DVec3, b: DVec3) -> Polyline3 {
        Polyline3 {
            points: vec![a, b],
            closed: false,
        }
    }

    #[test]
    fn the_nearest_point_is_on_the_nearest_segment_within_reach() {
        let curves = [
            line(DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.0, 3.0, 0.0)),
            line(DVec3::new(2.0, 0.0, 0.0), DVec3::new(2.0, 3.0, 0.0)),
        ];
        let p = DVec3::new(1.5, 1.0, 0.0);
        assert_eq!(
            nearest_within(p, &curves, 1.0),
            Some(DVec3::new(2.0, 1.0, 0.0))
        );
        assert_eq!(nearest_within(p, &curves, 0.4), None);
    }
}
