//! A polyline with bulges, as DXF's LWPOLYLINE: vertices, one bulge per vertex for the segment
//! that starts there (bulge = tan(θ/4), θ the included angle, positive = CCW about the normal),
//! open or closed. Vertices are 3D; bulged segments must lie in a plane perpendicular to the
//! normal (default +Z).
//!
//! Public parameter: segment i covers [i/n, (i+1)/n] (n segments), linear inside a segment
//! (by length on a line, by angle on an arc).

use std::fmt;
use std::sync::OnceLock;

use glam::DVec3;

use super::arc::{check_normal, Arc};
use super::error::{finite, finite3, invalid, Result};
use super::line::Line;

/// A polyline of line and arc segments.
#[derive(Clone)]
pub struct Polyline {
    pub(crate) vertices: Vec<DVec3>,
    pub(crate) bulges: Vec<f64>,
    pub(crate) closed: bool,
    pub(crate) normal: DVec3,
    /// Every segment as [`Polyline::segment`] builds it, made on first use: a surface whose
    /// profile this is evaluates it millions of times, and building an arc costs an atan, an
    /// atan2 and a square root. Derived from the fields above, which are never changed after
    /// [`Polyline::new`].
    built: OnceLock<Box<[Segment]>>,
}

/// Equality and the debug form are those of the defining fields (the cache is derived).
impl PartialEq for Polyline {
    fn eq(&self, other: &Self) -> bool {
        self.vertices == other.vertices
            && self.bulges == other.bulges
            && self.closed == other.closed
            && self.normal == other.normal
    }
}

impl fmt::Debug for Polyline {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Polyline")
            .field("vertices", &self.vertices)
            .field("bulges", &self.bulges)
            .field("closed", &self.closed)
            .field("normal", &self.normal)
            .finish()
    }
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
            built: OnceLock::new(),
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

    /// Every segment, built once on first use (the same values as [`Self::segment`] gives).
    pub(crate) fn built_segments(&self) -> &[Segment] {
        self.built.get_or_init(|| self.segments().collect())
    }

    /// The segment holding public parameter t (clamped to [0, 1]; the caller maps NaN), the
    /// segment parameter there and the segment's public range [t0, t1]: what `Curve::locate`
    /// finds in the curve's spans, by the same arithmetic, so the same bits.
    pub(crate) fn segment_at(&self, t: f64) -> (&Segment, f64, f64, f64) {
        let t = t.clamp(0.0, 1.0);
        let n = self.segment_count();
        let t1 = |i: usize| (i + 1) as f64 / n as f64;
        // The partition point of `t1(i) <= t` over 0..n (t1 rises strictly with i): from a
        // guess a step or two off, moved until the segment before ends at or before t and
        // this one after it.
        let mut i = ((t * n as f64) as usize).min(n);
        while i < n && t1(i) <= t {
            i += 1;
        }
        while i > 0 && t1(i - 1) > t {
            i -= 1;
        }
        let i = i.min(n - 1);
        let (t0, t1) = (i as f64 / n as f64, t1(i));
        let s = ((t - t0) / (t1 - t0)).clamp(0.0, 1.0);
        (&self.built_segments()[i], s, t0, t1)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::curve::Curve;
    use crate::geom::piece::Piece;

    /// The segment holding t, the piece parameter there and the segment's range, as `Curve`
    /// found them before the segments were kept: a partition point over the spans' ends, the
    /// segment built afresh from its vertices and bulge.
    fn fresh(p: &Polyline, t: f64) -> (Piece, f64, f64, f64) {
        let t = if t.is_nan() { 0.0 } else { t }.clamp(0.0, 1.0);
        let n = p.segment_count();
        let i = (0..n)
            .collect::<Vec<_>>()
            .partition_point(|&i| (i + 1) as f64 / n as f64 <= t)
            .min(n - 1);
        let piece = match p.segment(i) {
            Segment::Line(l) => Piece::Line(l),
            Segment::Arc(a) => Piece::Arc(a),
        };
        let (t0, t1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
        (piece, ((t - t0) / (t1 - t0)).clamp(0.0, 1.0), t0, t1)
    }

    fn bits(v: DVec3) -> [u64; 3] {
        v.to_array().map(f64::to_bits)
    }

    /// Parameters at and beside every segment end, outside [0, 1], NaN, and a dense sweep.
    fn params(n: usize) -> Vec<f64> {
        let mut ts = vec![-1.0, -0.0, 0.0, 1.0, 2.0, f64::NAN, f64::MIN_POSITIVE];
        for i in 0..=n {
            let t = i as f64 / n as f64;
            ts.extend([t, t.next_up(), t.next_down()]);
        }
        ts.extend((0..=5003).map(|k| k as f64 / 5003.0));
        ts
    }

    fn polylines() -> Vec<Polyline> {
        let v = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        let square = vec![v(0.0, 0.0), v(3.0, 0.0), v(3.0, 2.0), v(0.0, 2.0)];
        let mut zig: Vec<DVec3> = (0..41).map(|k| v(k as f64, (k % 3) as f64)).collect();
        zig[7].y += 1e-11; // a segment barely longer than the 1e-12 zero-length limit
        zig.insert(8, zig[7] + DVec3::new(3e-11, 0.0, 0.0));
        let zig_bulges: Vec<f64> = (0..zig.len())
            .map(|k| match k % 7 {
                0 => 0.0,
                1 => 1e-300,
                2 => -1e-17,
                3 => 5e-324,
                4 => 0.4,
                5 => -1e6,
                _ => 1.0,
            })
            .collect();
        let tilted = DVec3::new(1.0, -2.0, 0.5).normalize();
        let (a, b) = (
            tilted.any_orthonormal_vector(),
            tilted.cross(tilted.any_orthonormal_vector()),
        );
        let ring: Vec<DVec3> = (0..9)
            .map(|k| {
                let f = k as f64 * 0.7;
                DVec3::new(1.0, 2.0, 3.0) + a * f.cos() * 5.0 + b * f.sin() * 4.0
            })
            .collect();
        vec![
            Polyline::new(square.clone(), None, false, None).unwrap(),
            Polyline::new(square.clone(), Some(vec![0.3, 0.0, -0.7, 2.0]), true, None).unwrap(),
            Polyline::new(
                vec![v(0.0, 0.0), v(1.0, 0.0)],
                Some(vec![1.0, 1.0]),
                true,
                None,
            )
            .unwrap(),
            Polyline::new(zig.clone(), Some(zig_bulges.clone()), false, None).unwrap(),
            Polyline::new(zig, Some(zig_bulges), true, None).unwrap(),
            Polyline::new(
                ring,
                Some(vec![0.2, -0.1, 1e-9, 0.0, 3.0, -0.5, 0.05, 1e-15, 0.9]),
                true,
                Some(tilted),
            )
            .unwrap(),
        ]
    }

    #[test]
    fn the_kept_segments_evaluate_to_the_bits_of_fresh_ones() {
        for p in polylines() {
            let before = Curve::Polyline(p.clone());
            let c = Curve::Polyline(p.clone());
            for round in 0..2 {
                for t in params(p.segment_count()) {
                    let (piece, s, t0, t1) = fresh(&p, t);
                    assert_eq!(bits(c.eval(t)), bits(piece.eval(s)), "round {round} t {t}");
                    let d = piece.deriv(s) / (t1 - t0);
                    assert_eq!(bits(c.deriv(t)), bits(d), "t {t}");
                }
            }
            // A copy made before the segments were kept agrees too, and keeps them alike.
            let t = 0.37;
            assert_eq!(bits(before.eval(t)), bits(c.eval(t)));
            assert_eq!(before, c);
            assert_eq!(format!("{before:?}"), format!("{c:?}"));
            let spans = c.spans();
            assert_eq!(spans.len(), p.segment_count());
            for (sp, seg) in spans.iter().zip(p.segments()) {
                let fresh = match seg {
                    Segment::Line(l) => Piece::Line(l),
                    Segment::Arc(a) => Piece::Arc(a),
                };
                assert_eq!(format!("{:?}", sp.piece), format!("{fresh:?}"));
            }
        }
    }

    #[test]
    fn a_zero_length_segment_is_refused() {
        let v = |x: f64| DVec3::new(x, 0.0, 0.0);
        let e = Polyline::new(
            vec![v(0.0), v(1.0), v(1.0), v(2.0)],
            Some(vec![0.5; 4]),
            false,
            None,
        );
        assert!(e.unwrap_err().to_string().contains("zero-length"));
    }
}
