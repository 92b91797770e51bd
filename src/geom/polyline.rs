//! A polyline with bulges, as DXF's LWPOLYLINE: vertices, one bulge per vertex for the segment
//! that starts there (bulge = tan(θ/4), θ the included angle, positive = CCW about the normal),
//! open or closed. Vertices are 3D; bulged segments must lie in a plane perpendicular to the
//! normal (default +Z).
//!
//! Public parameter: segment i covers [i/n, (i+1)/n] (n segments), linear inside a segment
//! (by length on a line, by angle on an arc).

use glam::DVec3;

use super::arc::{check_normal, Arc};
use super::error::{finite, finite3, invalid, Result};
use super::line::Line;

/// A polyline of line and arc segments.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyline {
    pub(crate) vertices: Vec<DVec3>,
    pub(crate) bulges: Vec<f64>,
    pub(crate) closed: bool,
    pub(crate) normal: DVec3,
}

/// One segment of a polyline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Segment {
    Line(Line),
    Arc(Arc),
}

impl Polyline {
    /// A checked polyline. `bulges`: one per vertex (the segment starting there; the last one
    /// is used only when closed), or `None` for all zero. `normal` (default +Z) orients bulges.
    /// Errors: fewer than 2 vertices, NaN/inf, coincident consecutive vertices, wrong bulge
    /// count, a bulged segment not perpendicular to the normal. A closed polyline given with
    /// its first point repeated at the end has the repeat dropped (with its bulge).
    pub fn new(
        mut vertices: Vec<DVec3>,
        mut bulges: Option<Vec<f64>>,
        closed: bool,
        normal: Option<DVec3>,
    ) -> Result<Polyline> {
        let normal = check_normal(normal.unwrap_or(DVec3::Z))?;
        if closed && vertices.len() > 2 && vertices.first() == vertices.last() {
            vertices.pop();
            if let Some(b) = &mut bulges {
                if b.len() == vertices.len() + 1 {
                    b.pop();
                }
            }
        }
        if vertices.len() < 2 {
            return Err(invalid(
                "points",
                format!("a polyline needs at least 2 points, got {}", vertices.len()),
            ));
        }
        for p in &vertices {
            finite3("polyline point", *p)?;
        }
        let n = vertices.len();
        let mut bulges = match bulges {
            None => vec![0.0; n],
            Some(b) => {
                let open_short = b.len() + 1 == n && !closed;
                if b.len() != n && !open_short {
                    return Err(invalid(
                        "bulges",
                        format!("need one bulge per point ({n}), got {}", b.len()),
                    ));
                }
                b
            }
        };
        bulges.resize(n, 0.0);
        for b in &bulges {
            finite("bulge", *b)?;
        }
        let segs = if closed { n } else { n - 1 };
        for i in 0..segs {
            let (a, b) = (vertices[i], vertices[(i + 1) % n]);
            let chord = b - a;
            let scale = a.abs().max(b.abs()).max_element().max(1.0);
            if chord.length() <= 1e-12 * scale {
                return Err(invalid(
                    "points",
                    format!(
                        "points {} and {} coincide (zero-length segment)",
                        i,
                        (i + 1) % n
                    ),
                ));
            }
            if bulges[i] != 0.0 && chord.dot(normal).abs() > 1e-9 * chord.length() {
                return Err(invalid(
                    "bulges",
                    format!("segment {i} has a bulge but is not perpendicular to the normal"),
                ));
            }
        }
        if closed && n < 3 && bulges.iter().all(|b| *b == 0.0) {
            return Err(invalid(
                "points",
                "a closed polyline of straight segments needs at least 3 points",
            ));
        }
        Ok(Polyline {
            vertices,
            bulges,
            closed,
            normal,
        })
    }

    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }
    pub fn bulges(&self) -> &[f64] {
        &self.bulges
    }
    pub fn is_closed(&self) -> bool {
        self.closed
    }
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// The number of segments.
    pub fn segment_count(&self) -> usize {
        if self.closed {
            self.vertices.len()
        } else {
            self.vertices.len() - 1
        }
    }

    /// Segment `i` as a line or an arc (the arc's normal is ±normal so that it runs CCW from
    /// the segment's start to its end).
    pub fn segment(&self, i: usize) -> Segment {
        let n = self.vertices.len();
        let (a, b) = (self.vertices[i], self.vertices[(i + 1) % n]);
        bulge_segment(a, b, self.bulges[i], self.normal)
    }

    pub fn segments(&self) -> impl Iterator<Item = Segment> + '_ {
        (0..self.segment_count()).map(|i| self.segment(i))
    }
}

/// The segment from `a` to `b` with `bulge` about `normal`: centre at
/// m + (n × chord/c)·c(1 − b²)/(4b), radius c(1 + b²)/(4|b|), included angle 4·atan(b).
pub(crate) fn bulge_segment(a: DVec3, b: DVec3, bulge: f64, normal: DVec3) -> Segment {
    if bulge == 0.0 {
        return Segment::Line(Line { p0: a, p1: b });
    }
    let chord = b - a;
    let c = chord.length();
    let perp = normal.cross(chord) / c;
    let center = (a + b) * 0.5 + perp * (c * (1.0 - bulge * bulge) / (4.0 * bulge));
    let radius = c * (1.0 + bulge * bulge) / (4.0 * bulge.abs());
    let arc_normal = if bulge > 0.0 { normal } else { -normal };
    let sweep = 4.0 * bulge.atan().abs();
    let arc = Arc::from_parts(center, radius, arc_normal, 0.0, sweep);
    Segment::Arc(arc.with_range(arc.angle_of(a), sweep))
}

/// The bulge of an arc segment running CCW about `normal` (negative when the arc runs CW).
pub(crate) fn arc_bulge(arc: &Arc, normal: DVec3) -> f64 {
    let q = (arc.sweep / 4.0).tan();
    if arc.normal.dot(normal) >= 0.0 {
        q
    } else {
        -q
    }
}
