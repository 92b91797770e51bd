//! FILLET of a 2D polyline (LWPOLYLINE, or a flat POLYLINE): its Polyline option fillets
//! every vertex where two straight segments meet, and two picked adjacent segments of one
//! polyline fillet the vertex they share. A fillet replaces the vertex by the two tangent
//! points, the first carrying the bulge of the fillet arc (tan of a quarter of its turn,
//! positive for a left turn). As AutoCAD does, a vertex next to an arc segment, a vertex
//! where the segments are in line, and a vertex whose fillet needs more of a segment than
//! is left of it (after the fillet of the vertex before) are left as they are; the
//! Polyline option reports how many were filleted and how many were too short.

use glam::{DVec2, DVec3};

use super::cmd_err;
use crate::lang::error::Exn;
use crate::lang::Interp;
use crate::output::drawing::is_flat;
use crate::output::{Drawing, EntityKind};

/// A polyline's vertices in its plane, bulges (one per vertex), closed flag.
struct Plane2d {
    points: Vec<DVec2>,
    bulges: Vec<f64>,
    closed: bool,
}

fn plane_of(kind: &EntityKind) -> Option<Plane2d> {
    match kind {
        EntityKind::LwPolyline {
            points,
            bulges,
            closed,
            ..
        } => Some(Plane2d {
            points: points.clone(),
            bulges: full_bulges(bulges, points.len()),
            closed: *closed,
        }),
        EntityKind::Polyline {
            points,
            bulges,
            closed,
        } if is_flat(points) => Some(Plane2d {
            points: points.iter().map(|p| p.truncate()).collect(),
            bulges: full_bulges(bulges, points.len()),
            closed: *closed,
        }),
        _ => None,
    }
}

fn full_bulges(b: &[f64], n: usize) -> Vec<f64> {
    if b.is_empty() {
        vec![0.0; n]
    } else {
        b.to_vec()
    }
}

fn with_plane(kind: &EntityKind, p: Plane2d) -> EntityKind {
    let bulges = if p.bulges.iter().all(|b| *b == 0.0) {
        Vec::new()
    } else {
        p.bulges
    };
    match kind {
        EntityKind::LwPolyline {
            elevation, normal, ..
        } => EntityKind::LwPolyline {
            points: p.points,
            bulges,
            closed: p.closed,
            elevation: *elevation,
            normal: *normal,
        },
        EntityKind::Polyline { points, .. } => {
            let z = points[0].z;
            EntityKind::Polyline {
                points: p.points.iter().map(|q| q.extend(z)).collect(),
                bulges,
                closed: p.closed,
            }
        }
        other => other.clone(),
    }
}

/// What filleting the vertices did: (filleted, too short).
#[derive(Debug, Default, PartialEq)]
pub(super) struct Counts {
    pub filleted: usize,
    pub too_short: usize,
}

/// Fillets vertices `which` (all when `None`) of the polyline with radius `r`.
fn fillet_vertices(p: &Plane2d, r: f64, which: Option<usize>) -> (Plane2d, Counts) {
    let n = p.points.len();
    let seg = |i: usize| i < n - 1 || p.closed;
    // Tangent length taken from each vertex's segments by its fillet.
    let mut used = vec![0.0; n];
    let mut fillet: Vec<Option<(DVec2, DVec2, f64)>> = vec![None; n];
    let mut counts = Counts::default();
    for i in 0..n {
        if which.is_some_and(|w| w != i) || r <= 0.0 {
            continue;
        }
        let prev = (i + n - 1) % n;
        let has_prev = if i == 0 { p.closed } else { true };
        if !has_prev || !seg(i) || p.bulges[prev] != 0.0 || p.bulges[i] != 0.0 {
            continue;
        }
        let (a, v, b) = (p.points[prev], p.points[i], p.points[(i + 1) % n]);
        let (len_in, len_out) = ((v - a).length(), (b - v).length());
        if len_in < 1e-12 || len_out < 1e-12 {
            continue;
        }
        let (d_in, d_out) = ((v - a) / len_in, (b - v) / len_out);
        let turn = d_in.angle_to(d_out);
        if turn.abs() < 1e-12 || std::f64::consts::PI - turn.abs() < 1e-12 {
            continue;
        }
        let t = r * (turn.abs() / 2.0).tan();
        let room_in = len_in - used[prev];
        let room_out = len_out - used[(i + 1) % n];
        if t > room_in + 1e-9 || t > room_out + 1e-9 {
            counts.too_short += 1;
            continue;
        }
        used[i] = t;
        fillet[i] = Some((v - d_in * t, v + d_out * t, (turn / 4.0).tan()));
        counts.filleted += 1;
    }
    let mut out = Plane2d {
        points: Vec::with_capacity(n + counts.filleted),
        bulges: Vec::with_capacity(n + counts.filleted),
        closed: p.closed,
    };
    for (i, f) in fillet.iter().enumerate() {
        match *f {
            Some((t1, t2, bulge)) => {
                out.points.extend([t1, t2]);
                out.bulges.extend([bulge, p.bulges[i]]);
            }
            None => {
                out.points.push(p.points[i]);
                out.bulges.push(p.bulges[i]);
            }
        }
    }
    (out, counts)
}

fn polyline(d: &Drawing, h: u64) -> Result<(crate::output::Entity, Plane2d), Exn> {
    let e = d
        .get(h)
        .cloned()
        .ok_or_else(|| cmd_err("FILLET", "the object is deleted"))?;
    let p = plane_of(&e.kind).ok_or_else(|| {
        cmd_err(
            "FILLET",
            format!(
                "the Polyline option fillets 2D polylines, not a {}",
                e.kind.type_name()
            ),
        )
    })?;
    Ok((e, p))
}

/// FILLET's Polyline option: every vertex of the polyline with radius `r`.
pub(super) fn fillet_polyline(it: &mut Interp, h: u64, r: f64) -> Result<Counts, Exn> {
    let d = it.ext::<Drawing>();
    let (e, p) = polyline(d, h)?;
    let (q, counts) = fillet_vertices(&p, r, None);
    let kind = with_plane(&e.kind, q);
    d.replace(h, crate::output::Entity { kind, ..e })
        .map_err(|x| cmd_err("FILLET", x))?;
    Ok(counts)
}

/// The index of the segment of `p` nearest `q`.
fn nearest_segment(p: &Plane2d, q: DVec2) -> usize {
    let n = p.points.len();
    let segs = if p.closed { n } else { n - 1 };
    let dist = |i: usize| {
        let (a, b) = (p.points[i], p.points[(i + 1) % n]);
        let ab = b - a;
        let t = if ab.length_squared() > 0.0 {
            ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (a + ab * t - q).length()
    };
    (0..segs)
        .min_by(|&i, &j| dist(i).total_cmp(&dist(j)))
        .unwrap_or(0)
}

/// FILLET of two picked segments of one polyline: the vertex they share.
pub(super) fn fillet_segments(
    it: &mut Interp,
    h: u64,
    (q1, q2): (Option<DVec3>, Option<DVec3>),
    r: f64,
) -> Result<(), Exn> {
    let d = it.ext::<Drawing>();
    let (e, p) = polyline(d, h)?;
    let (Some(q1), Some(q2)) = (q1, q2) else {
        return Err(cmd_err(
            "FILLET",
            "pick the two segments of the polyline with points ((ename point) lists)",
        ));
    };
    let n = p.points.len();
    let (i, j) = (
        nearest_segment(&p, q1.truncate()),
        nearest_segment(&p, q2.truncate()),
    );
    let vertex = if (i + 1) % n == j && (j != 0 || p.closed) {
        j
    } else if (j + 1) % n == i && (i != 0 || p.closed) {
        i
    } else {
        return Err(cmd_err(
            "FILLET",
            "lispcad fillets two adjacent segments of one polyline",
        ));
    };
    let (q, counts) = fillet_vertices(&p, r, Some(vertex));
    if counts.too_short > 0 {
        return Err(cmd_err(
            "FILLET",
            format!("radius {r} is too large for these segments"),
        ));
    }
    let kind = with_plane(&e.kind, q);
    d.replace(h, crate::output::Entity { kind, ..e })
        .map_err(|x| cmd_err("FILLET", x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_gets_four_quarter_arcs() {
        let sq = Plane2d {
            points: vec![
                DVec2::ZERO,
                DVec2::new(10.0, 0.0),
                DVec2::new(10.0, 10.0),
                DVec2::new(0.0, 10.0),
            ],
            bulges: vec![0.0; 4],
            closed: true,
        };
        let (q, c) = fillet_vertices(&sq, 2.0, None);
        assert_eq!(
            c,
            Counts {
                filleted: 4,
                too_short: 0
            }
        );
        assert_eq!(q.points.len(), 8);
        assert!((q.points[0] - DVec2::new(0.0, 2.0)).length() < 1e-12);
        assert!((q.points[1] - DVec2::new(2.0, 0.0)).length() < 1e-12);
        // A left turn of 90°: bulge tan(22.5°).
        assert!((q.bulges[0] - (std::f64::consts::PI / 8.0).tan()).abs() < 1e-15);
        assert_eq!(q.bulges[1], 0.0);
        // Radius 6 needs 6 + 6 of each side of 10: the first two fit, the rest do not.
        let (_, c) = fillet_vertices(&sq, 6.0, None);
        assert_eq!(
            c,
            Counts {
                filleted: 2,
                too_short: 2
            }
        );
    }
}
