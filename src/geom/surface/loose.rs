//! The last check on refined curves: no chord may stand for the curve where its midpoint is off
//! either surface by more than the tolerance promised (GEOMTOL + CHORDTOL). Densifying leaves
//! such a chord only where a midpoint did not refine between its ends (see
//! `refine::assemble_loose`), and the lens tips (`contact::tip`) mend those they can; a chord
//! left after that and after regrouping is refined once more, from the chord's own midpoint
//! projected onto the surfaces, and where that does not hold, the curve is cut there (a closed
//! curve opened, an open one cut in two): a gap says what a straight segment would hide.
//!
//! Only chords with an end among the loose chords' ends are checked: the others had their
//! midpoints refined within `chord_tol` when densified, so the pass costs nothing where none was
//! left loose. Regrouping may move an end (a branch point put in), and such a chord is missed.

use super::refine::{newton_pair, newton_plane, off_pair, off_section, Patch};
use crate::geom::mesh::Polyline3;
use glam::DVec3;

/// Most halvings of one loose chord before it is cut.
const MAX_DEPTH: u32 = 8;

/// The surfaces a curve lies on: how far a point is off the farther, and a point of the curve
/// near a given one (None where Newton does not converge within the tolerance).
pub(crate) struct On<'a> {
    pub off: &'a dyn Fn(DVec3) -> f64,
    pub onto: &'a dyn Fn(DVec3) -> Option<DVec3>,
}

/// [`settle`] for `curves` on the intersection of `a` and `b`, to `tol`.
pub(crate) fn settle_pair(
    a: &Patch,
    b: &Patch,
    curves: Vec<Polyline3>,
    loose: &[[DVec3; 2]],
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    if loose.is_empty() {
        return curves;
    }
    let off = |p: DVec3| off_pair(a, b, p);
    let onto = |p: DVec3| {
        let n = newton_pair(a, b, [a.project(p, None), b.project(p, None)], tol);
        (n.residual <= tol).then_some(n.point)
    };
    let on = On {
        off: &off,
        onto: &onto,
    };
    settle(curves, loose, &on, (tol, chord_tol))
}

/// [`settle`] for `curves` on the section of `s` by the plane through `p0` with unit normal
/// `n`, to `tol`.
pub(crate) fn settle_section(
    s: &Patch,
    (p0, n): (DVec3, DVec3),
    curves: Vec<Polyline3>,
    loose: &[[DVec3; 2]],
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    if loose.is_empty() {
        return curves;
    }
    let off = |p: DVec3| off_section(s, (p0, n), p);
    let onto = |p: DVec3| {
        let (uv, r) = newton_plane(s, s.project(p, None), p0, n, tol);
        (r <= tol).then(|| s.eval(uv))
    };
    let on = On {
        off: &off,
        onto: &onto,
    };
    settle(curves, loose, &on, (tol, chord_tol))
}

/// `curves` with every chord that has an end among `loose`'s and a midpoint off the surfaces by
/// more than `tol + chord_tol` refined, or the curve cut there.
pub(crate) fn settle(
    curves: Vec<Polyline3>,
    loose: &[[DVec3; 2]],
    on: &On,
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    let ends: Vec<DVec3> = loose.iter().flatten().copied().collect();
    let mut out = Vec::with_capacity(curves.len());
    for c in curves {
        if c.points.iter().any(|p| ends.contains(p)) {
            out.extend(settle_curve(c, &ends, on, tol + chord_tol));
        } else {
            out.push(c);
        }
    }
    out
}

/// One curve settled (see [`settle`]): its pieces, in order.
fn settle_curve(c: Polyline3, ends: &[DVec3], on: &On, within: f64) -> Vec<Polyline3> {
    let pts = &c.points;
    let n = pts.len();
    let segs = if c.closed { n } else { n.saturating_sub(1) };
    // Each piece's points; a chord that cannot be refined starts a new piece.
    let mut pieces: Vec<Vec<DVec3>> = vec![Vec::with_capacity(n)];
    // Whether the closing chord (of a closed curve) was cut, and whether any other was.
    let (mut closing_cut, mut inner_cut) = (false, false);
    for k in 0..n {
        pieces.last_mut().expect("a piece").push(pts[k]);
        if k >= segs {
            continue;
        }
        let (p, q) = (pts[k], pts[(k + 1) % n]);
        if !(ends.contains(&p) || ends.contains(&q)) || (on.off)(0.5 * (p + q)) <= within {
            continue;
        }
        match fill(p, q, on, within, 0) {
            Some(f) => pieces.last_mut().expect("a piece").extend(f),
            None if k + 1 == n => closing_cut = true,
            None => {
                inner_cut = true;
                pieces.push(Vec::new());
            }
        }
    }
    if c.closed && inner_cut && !closing_cut {
        // Opened at a cut: the piece after the last cut runs on into the first.
        let last = pieces.pop().expect("a piece");
        let first = std::mem::take(&mut pieces[0]);
        pieces[0] = last.into_iter().chain(first).collect();
    }
    let closed = c.closed && !closing_cut && !inner_cut;
    pieces
        .into_iter()
        .filter(|p| !p.is_empty())
        .map(|points| Polyline3 { points, closed })
        .collect()
}

/// The points to put between `p` and `q` (both on the curve) so that every chord's midpoint is
/// within `within` of the surfaces: each the chord's midpoint carried onto the curve, kept only
/// where it falls between the ends. None where that fails.
fn fill(p: DVec3, q: DVec3, on: &On, within: f64, depth: u32) -> Option<Vec<DVec3>> {
    let c = 0.5 * (p + q);
    if (on.off)(c) <= within {
        return Some(Vec::new());
    }
    if depth >= MAX_DEPTH {
        return None;
    }
    let m = (on.onto)(c)?;
    let chord = q - p;
    let along = (m - p).dot(chord) / chord.length_squared();
    if !(along > 0.0 && along < 1.0) {
        return None;
    }
    let mut f = fill(p, m, on, within, depth + 1)?;
    f.push(m);
    f.extend(fill(m, q, on, within, depth + 1)?);
    Some(f)
}

#[cfg(test)]
mod tests {
    use super::{settle_pair, settle_section};
    use crate::geom::mesh::Polyline3;
    use crate::geom::surface::refine::Patch;
    use crate::geom::surface::Surface;
    use glam::DVec3;

    const TOL: f64 = 1e-9;
    const CHORD: f64 = 1e-3;

    /// The circle x² + y² = 0.25 at height `z`, at the angles (degrees) given.
    fn circle(z: f64, deg: impl Iterator<Item = i32>) -> Vec<DVec3> {
        deg.map(|d| {
            let t = f64::from(d).to_radians();
            DVec3::new(0.5 * t.cos(), 0.5 * t.sin(), z)
        })
        .collect()
    }

    /// Every chord's midpoint of `c` within TOL + CHORD of the sphere of radius 1 at the origin
    /// and of the cylinder of radius 0.5 about z (closed forms), and every point within TOL.
    fn assert_on(c: &Polyline3) {
        let off = |p: DVec3| {
            (p.length() - 1.0)
                .abs()
                .max((p.truncate().length() - 0.5).abs())
        };
        let n = c.points.len();
        let segs = if c.closed { n } else { n - 1 };
        for k in 0..segs {
            let (p, q) = (c.points[k], c.points[(k + 1) % n]);
            assert!(off(p) <= TOL, "point {p} off by {}", off(p));
            let m = 0.5 * (p + q);
            assert!(
                off(m) <= TOL + CHORD,
                "chord {p}..{q}: midpoint off by {}",
                off(m)
            );
        }
    }

    fn surfaces() -> (Surface, Surface) {
        let sphere = Surface::sphere(DVec3::ZERO, 1.0).unwrap();
        let cyl = Surface::cylinder(DVec3::new(0.0, 0.0, -1.5), DVec3::Z, 0.5, 3.0).unwrap();
        (sphere, cyl)
    }

    #[test]
    fn a_loose_chord_left_on_a_closed_intersection_is_refined() {
        // The sphere meets the cylinder in the circles r = 0.5, z = ±√0.75. A closed curve on the
        // upper one, every 5°, but straight from 30° to 90°: that chord's midpoint is 0.067 off.
        let (s, c) = surfaces();
        let (a, b) = (Patch::new(&s), Patch::new(&c));
        let z = 0.75f64.sqrt();
        let mut pts = circle(z, (0..=30).step_by(5));
        pts.extend(circle(z, (90..360).step_by(5)));
        let loose = [[pts[6], pts[7]]];
        let curve = Polyline3 {
            points: pts,
            closed: true,
        };
        let out = settle_pair(&a, &b, vec![curve], &loose, (TOL, CHORD));
        assert_eq!(out.len(), 1);
        assert!(out[0].closed);
        assert_on(&out[0]);
    }

    #[test]
    fn a_loose_chord_that_cannot_be_refined_cuts_the_curve() {
        // An open curve along the upper circle from 0° to 180°, then straight down to the lower
        // circle at 180° and along it back to 0°: the straight chord's midpoint (−0.5, 0, 0) is
        // 0.5 off the sphere and carried onto the intersection lands on one circle, beyond the
        // chord's ends. It is cut there: the two arcs, each on both surfaces.
        let (s, c) = surfaces();
        let (a, b) = (Patch::new(&s), Patch::new(&c));
        let z = 0.75f64.sqrt();
        let mut pts = circle(z, (0..=180).step_by(5));
        let k = pts.len();
        pts.extend(circle(-z, (0..=180).rev().step_by(5)));
        let loose = [[pts[k - 1], pts[k]]];
        let curve = Polyline3 {
            points: pts,
            closed: false,
        };
        let out = settle_pair(&a, &b, vec![curve], &loose, (TOL, CHORD));
        assert_eq!(out.len(), 2);
        for (piece, zz) in out.iter().zip([z, -z]) {
            assert!(!piece.closed);
            assert_eq!(piece.points.len(), k);
            assert!(piece.points.iter().all(|p| (p.z - zz).abs() <= TOL));
        }
        // Closed, the same curve is opened there: one open curve, no chord across.
        let mut pts = out[0].points.clone();
        pts.extend(out[1].points.iter().copied());
        let closed = Polyline3 {
            points: pts,
            closed: true,
        };
        let loose = [
            [closed.points[k - 1], closed.points[k]],
            [closed.points[2 * k - 1], closed.points[0]],
        ];
        let out = settle_pair(&a, &b, vec![closed], &loose, (TOL, CHORD));
        assert_eq!(out.len(), 2, "cut at both vertical chords: {out:?}");
        out.iter().for_each(assert_on);
    }

    #[test]
    fn a_loose_chord_left_on_a_section_is_refined() {
        // The plane z = 0.6 cuts the sphere in the circle of radius 0.8. A closed curve on it
        // with a chord from 0° to 60° (midpoint 0.107 off) is refined.
        let (s, _) = surfaces();
        let a = Patch::new(&s);
        let plane = (DVec3::new(0.0, 0.0, 0.6), DVec3::Z);
        let on_circle = |d: i32| {
            let t = f64::from(d).to_radians();
            DVec3::new(0.8 * t.cos(), 0.8 * t.sin(), 0.6)
        };
        let pts: Vec<DVec3> = (60..=360).step_by(5).map(on_circle).collect();
        let n = pts.len();
        let loose = [[pts[n - 1], pts[0]]];
        let curve = Polyline3 {
            points: pts,
            closed: true,
        };
        let out = settle_section(&a, plane, vec![curve], &loose, (TOL, CHORD));
        assert_eq!(out.len(), 1);
        assert!(out[0].closed);
        let off = |p: DVec3| (p.length() - 1.0).abs().max((p.z - 0.6).abs());
        let m = out[0].points.len();
        for k in 0..m {
            let (p, q) = (out[0].points[k], out[0].points[(k + 1) % m]);
            assert!(
                off(p) <= TOL && off(0.5 * (p + q)) <= TOL + CHORD,
                "{p}..{q}"
            );
        }
    }
}
