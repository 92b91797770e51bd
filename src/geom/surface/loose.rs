//! The last check on refined curves: no chord may stand for the curve where its midpoint is off
//! either surface by more than the tolerance promised (GEOMTOL + CHORDTOL).
//!
//! Chords are made in many places: densifying (`refine::assemble` and its callers), and then
//! every step that joins curves, cuts them, or puts a point in (regrouping beside contacts, the
//! branch points, the lens tips, a common region's edge). Rather than trust each of those to
//! report what it left unchecked, densifying vouches for the chords it has checked (a ledger
//! kept while a [`Ledger`] is open), and the pass checks every chord of every curve returned
//! that nobody vouched for: its midpoint is carried onto the surfaces, and where it is off, the
//! chord is refined from its own midpoint projected onto the surfaces, and where that does not
//! hold, the curve is cut there (a closed curve opened, an open one cut in two): a gap says what
//! a straight segment would hide. A piece of one point left by cuts is dropped: a lone point
//! reads as an isolated tangent contact, and it is a point of a curve the cuts lost.
//!
//! Vouching costs a hash insert per chord densified and a look-up per chord returned; only the
//! chords nobody vouched for pay for projections (none, where every chord was densified).

use super::refine::{newton_pair, newton_plane, off_pair, off_section, Patch};
use crate::geom::mesh::Polyline3;
use glam::DVec3;
use rustc_hash::FxHashSet;
use std::cell::RefCell;

/// Most halvings of one loose chord before it is cut.
const MAX_DEPTH: u32 = 8;

/// A chord by its ends' bits, the lower end first (curves are reversed and joined both ways).
type Key = [u64; 6];

fn key(p: DVec3, q: DVec3) -> Key {
    let (x, y) = (
        p.to_array().map(f64::to_bits),
        q.to_array().map(f64::to_bits),
    );
    let (x, y) = if x <= y { (x, y) } else { (y, x) };
    [x[0], x[1], x[2], y[0], y[1], y[2]]
}

thread_local! {
    /// The chords vouched for while a [`Ledger`] is open on this thread.
    static VOUCHED: RefCell<Option<FxHashSet<Key>>> = const { RefCell::new(None) };
}

/// Open while one surface intersection or section is refined: the chords checked meanwhile
/// (see [`vouch`]) need no check in [`settle`]. Closing it (dropping) restores the ledger of an
/// enclosing one, so an intersection run inside another keeps its own.
pub(crate) struct Ledger {
    outer: Option<FxHashSet<Key>>,
}

impl Ledger {
    pub(crate) fn open() -> Ledger {
        // About the chords of the curves of one intersection (a few hundred to a few thousand),
        // so that growing it costs little.
        let set = FxHashSet::with_capacity_and_hasher(1 << 10, Default::default());
        let outer = VOUCHED.with(|v| v.replace(Some(set)));
        Ledger { outer }
    }
}

impl Drop for Ledger {
    fn drop(&mut self) {
        let outer = self.outer.take();
        VOUCHED.with(|v| *v.borrow_mut() = outer);
    }
}

/// Records that the chord `pq`'s midpoint is within GEOMTOL + CHORDTOL of both surfaces (a
/// point of the curve within GEOMTOL of both lies within CHORDTOL of it): nothing where no
/// ledger is open.
pub(crate) fn vouch(p: DVec3, q: DVec3) {
    VOUCHED.with(|v| {
        if let Some(set) = v.borrow_mut().as_mut() {
            set.insert(key(p, q));
        }
    });
}

/// Whether the chord `pq` is short enough to need no check: its ends are points of the curve
/// (within GEOMTOL of both surfaces), and its midpoint is within `chord_tol` of them.
pub(crate) fn short(p: DVec3, q: DVec3, chord_tol: f64) -> bool {
    p.distance(q) <= 2.0 * chord_tol
}

fn vouched(p: DVec3, q: DVec3) -> bool {
    VOUCHED.with(|v| {
        v.borrow()
            .as_ref()
            .is_some_and(|set| set.contains(&key(p, q)))
    })
}

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
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    let off = |p: DVec3| off_pair(a, b, p);
    let onto = |p: DVec3| {
        let n = newton_pair(a, b, [a.project(p, None), b.project(p, None)], tol);
        (n.residual <= tol).then_some(n.point)
    };
    let on = On {
        off: &off,
        onto: &onto,
    };
    settle(curves, &on, (tol, chord_tol))
}

/// [`settle`] for `curves` on the section of `s` by the plane through `p0` with unit normal
/// `n`, to `tol`.
pub(crate) fn settle_section(
    s: &Patch,
    (p0, n): (DVec3, DVec3),
    curves: Vec<Polyline3>,
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    let off = |p: DVec3| off_section(s, (p0, n), p);
    let onto = |p: DVec3| {
        let (uv, r) = newton_plane(s, s.project(p, None), p0, n, tol);
        (r <= tol).then(|| s.eval(uv))
    };
    let on = On {
        off: &off,
        onto: &onto,
    };
    settle(curves, &on, (tol, chord_tol))
}

/// `curves` with every chord nobody vouched for checked: one whose midpoint is off the surfaces
/// by more than `tol + chord_tol` refined, or the curve cut there. Chords found good are
/// vouched for.
pub(crate) fn settle(curves: Vec<Polyline3>, on: &On, tols: (f64, f64)) -> Vec<Polyline3> {
    let mut out = Vec::with_capacity(curves.len());
    for c in curves {
        out.extend(settle_curve(c, on, tols));
    }
    out
}

/// One curve settled (see [`settle`]): its pieces, in order.
fn settle_curve(c: Polyline3, on: &On, (tol, chord_tol): (f64, f64)) -> Vec<Polyline3> {
    let within = tol + chord_tol;
    let pts = &c.points;
    let n = pts.len();
    let segs = if c.closed { n } else { n.saturating_sub(1) };
    let unsure = |k: usize| {
        let (p, q) = (pts[k], pts[(k + 1) % n]);
        !(short(p, q, chord_tol) || vouched(p, q))
    };
    if !(0..segs).any(unsure) {
        return vec![c];
    }
    // Each piece's points; a chord that cannot be refined starts a new piece.
    let mut pieces: Vec<Vec<DVec3>> = vec![Vec::with_capacity(n)];
    // Whether the closing chord (of a closed curve) was cut, and whether any other was.
    let (mut closing_cut, mut inner_cut) = (false, false);
    for k in 0..n {
        pieces.last_mut().expect("a piece").push(pts[k]);
        if k >= segs || !unsure(k) {
            continue;
        }
        let (p, q) = (pts[k], pts[(k + 1) % n]);
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
    let cut = closing_cut || inner_cut;
    let closed = c.closed && !cut;
    // A lone point left between cuts is no touch: drop it (a curve of one point that was never
    // cut, an isolated contact, has no chord and is returned above).
    pieces
        .into_iter()
        .filter(|p| p.len() > usize::from(cut))
        .map(|points| Polyline3 { points, closed })
        .collect()
}

/// The points to put between `p` and `q` (both on the curve) so that every chord's midpoint is
/// within `within` of the surfaces: each the chord's midpoint carried onto the curve, kept only
/// where it falls between the ends. None where that fails.
fn fill(p: DVec3, q: DVec3, on: &On, within: f64, depth: u32) -> Option<Vec<DVec3>> {
    let c = 0.5 * (p + q);
    if (on.off)(c) <= within {
        vouch(p, q);
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
    use super::{settle, settle_pair, settle_section, vouch, Ledger, On};
    use crate::geom::mesh::Polyline3;
    use crate::geom::surface::refine::Patch;
    use crate::geom::surface::Surface;
    use glam::DVec3;
    use std::cell::RefCell;

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
        let curve = Polyline3 {
            points: pts,
            closed: true,
        };
        let out = settle_pair(&a, &b, vec![curve], (TOL, CHORD));
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
        let curve = Polyline3 {
            points: pts,
            closed: false,
        };
        let out = settle_pair(&a, &b, vec![curve], (TOL, CHORD));
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
        let out = settle_pair(&a, &b, vec![closed], (TOL, CHORD));
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
        let curve = Polyline3 {
            points: pts,
            closed: true,
        };
        let out = settle_section(&a, plane, vec![curve], (TOL, CHORD));
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

    #[test]
    fn a_lone_point_left_by_a_cut_is_no_touch_point() {
        // The upper circle from 0° to 180°, then straight down to the lower circle's point at
        // 180° (on both surfaces), where the curve ends: that chord cannot be refined (its
        // midpoint carried onto the intersection lands on a circle, beyond its ends), and the
        // cut leaves the lower point alone. It is no tangent contact (the surfaces cross
        // there): only the arc comes back.
        let (s, c) = surfaces();
        let (a, b) = (Patch::new(&s), Patch::new(&c));
        let z = 0.75f64.sqrt();
        let mut pts = circle(z, (0..=180).step_by(5));
        let k = pts.len();
        pts.extend(circle(-z, std::iter::once(180)));
        let curve = Polyline3 {
            points: pts,
            closed: false,
        };
        let out = settle_pair(&a, &b, vec![curve], (TOL, CHORD));
        assert_eq!(out.len(), 1, "{out:?}");
        assert_eq!(out[0].points.len(), k);
        assert_on(&out[0]);
    }

    #[test]
    fn only_the_chords_nobody_vouched_for_are_checked() {
        // The upper circle every 5° from 0° to 30° and from 90° to 180°, joined straight from
        // 30° to 90° (as a join or a cut leaves a chord no densifying saw): with every other
        // chord vouched for, only that one's midpoint is asked about, and it is refined.
        let z = 0.75f64.sqrt();
        let mut pts = circle(z, (0..=30).step_by(5));
        let j = pts.len() - 1;
        pts.extend(circle(z, (90..=180).step_by(5)));
        let _ledger = Ledger::open();
        for (i, w) in pts.windows(2).enumerate() {
            if i != j {
                vouch(w[0], w[1]);
            }
        }
        let asked = RefCell::new(Vec::new());
        let off = |p: DVec3| {
            asked.borrow_mut().push(p);
            (p.length() - 1.0)
                .abs()
                .max((p.truncate().length() - 0.5).abs())
        };
        // Onto the circle along the radius: the intersection's nearest point.
        let onto = |p: DVec3| Some((p.truncate().normalize() * 0.5).extend(z));
        let on = On {
            off: &off,
            onto: &onto,
        };
        let curve = Polyline3 {
            points: pts.clone(),
            closed: false,
        };
        let out = settle(vec![curve], &on, (TOL, CHORD));
        assert_eq!(out.len(), 1);
        assert_on(&out[0]);
        assert!(out[0].points.len() > pts.len());
        // Asked first at the join's midpoint, then only between the join's ends.
        let asked = asked.into_inner();
        assert_eq!(asked[0], 0.5 * (pts[j] + pts[j + 1]));
        let between = |p: &DVec3| {
            let t = p.y.atan2(p.x).to_degrees();
            (30.0..=90.0).contains(&t)
        };
        assert!(asked.iter().all(between), "{asked:?}");
    }
}
