//! Isolated tangent contacts of two parametric surfaces: where they touch without crossing, the
//! meshes (both inscribed in their surfaces) miss each other by about the chord tolerance and
//! their intersection says nothing. Such a contact is a local minimum, zero, of the distance
//! between the surfaces: the mesh vertices of one surface nearest the other (local minima of
//! that distance over their neighbours, away from every curve already found) seed a minimisation
//! of the distance from `S_a(u, v)` to surface b on the true surfaces (Nelder–Mead in (u, v);
//! the distance is smooth and quadratic about a contact), and a minimum within the tolerance is
//! a contact point.
//!
//! A plane section is searched the same way, on `|n·(S(u, v) − p)|`; the minimiser's point is
//! then levelled by Newton to where the surface is parallel to the plane, which tells a contact
//! (level within the tolerance) from a loop smaller than the seeding mesh (level beyond the plane),
//! traced from the extremum.
//!
//! Where the contact is a curve rather than a point (the gap flat along one direction), it is
//! followed on the true surfaces and comes back as one polyline ([`line`]).

mod alongside;
mod branch;
mod branch_out;
mod copies;
mod fold;
mod line;
mod ridge;
mod seeds;
mod small_loop;
mod tip;

use super::refine::Patch;
use crate::geom::mesh::{closest_on_triangle, Aabb, Mesh, Polyline3};
use branch::contact_curve_near;
use fold::{fold_probes, runs_through_any, step_in, Probed};
use glam::{DVec2, DVec3};
use line::{contact_curve, GapAt};
use seeds::Lows;
use small_loop::small_loop;
use std::cell::Cell;

/// The contacts of `a` and `b` (meshed as `ma`, `mb` within `seed_tol`) not on `curves`: a
/// one-point polyline for an isolated contact, the contact curve (closed when it closes) where
/// the surfaces touch along one; every point within `tol` of both surfaces, curves densified
/// within `chord_tol`. Seeds and contact points for which `shared` holds (a common region of
/// the two, where the surfaces touch everywhere and whose loops are already found) are passed
/// over.
#[allow(clippy::too_many_arguments)]
pub(crate) fn tangent_contacts(
    a: &Patch,
    b: &Patch,
    ma: &Mesh,
    mb: &Mesh,
    curves: &[Polyline3],
    shared: &dyn Fn(DVec3) -> bool,
    seed_tol: f64,
    tol: f64,
    chord_tol: f64,
) -> Vec<Polyline3> {
    let va = ma.vertices();
    if va.is_empty() || mb.is_empty() {
        return Vec::new();
    }
    let gap = seed_gap(seed_tol);
    let bvh = mb.bvh();
    // Distance to mb, only within the gap (a box query rejects the far vertices quickly),
    // and the side of mb it lies on (of its nearest triangle; 0 beyond the gap).
    let to_b_side = |p: DVec3| {
        let (mut best, mut side) = (f64::INFINITY, 0.0);
        let b = Aabb {
            min: p - DVec3::splat(gap),
            max: p + DVec3::splat(gap),
        };
        bvh.query_box(&b, |t| {
            let [x, y, z] = mb.corners_of(t as usize);
            let c = closest_on_triangle(p, x, y, z);
            let d = c.distance(p);
            if d < best {
                best = d;
                side = (p - c).dot((y - x).cross(z - x)).signum();
            }
        });
        (best, side)
    };
    let to_b = |p: DVec3| to_b_side(p).0;
    let (dist, side): (Vec<f64>, Vec<f64>) = va.iter().map(|&p| to_b_side(p)).unzip();
    let warm: Cell<Option<DVec2>> = Cell::new(None);
    let signed_gap = |uv: DVec2| pair_gap(a, b, &warm, uv);
    let mut out: Vec<Polyline3> = Vec::new();
    let sine = |c: DVec3, start: Option<(DVec2, DVec2)>| {
        let (ua, ub) = (
            a.project(c, start.map(|s| s.0)),
            b.project(c, start.map(|s| s.1)),
        );
        (
            unit_normal(a, ua).cross(unit_normal(b, ub)).length(),
            (ua, ub),
        )
    };
    let lows = Lows::new(ma, (&dist, &side), seed_tol, curves, &sine);
    let mut seeds: Vec<(DVec3, f64)> = lows
        .vertices(ma)
        .into_iter()
        .map(|(i, reach)| (va[i], reach))
        .collect();
    seeds.extend(lows.edges(ma, &to_b));
    let dup = beside(a, tol, chord_tol);
    let warm_ridge: Cell<Option<DVec2>> = Cell::new(None);
    let found = ridge::Found {
        a,
        gap: &|uv| pair_gap(a, b, &warm_ridge, uv).dist,
        rise: seed_tol,
    };
    for (q, reach) in seeds {
        if found.claims(q, &out, 4.0 * reach) || shared(q) {
            continue;
        }
        if let Some((uv, p)) = touch(a, b, q, tol) {
            // A seed beside a curve found (let through by `Lows`) can lead onto that curve.
            if found.claims(p, &out, 4.0 * reach) || near_any(p, curves, dup) || shared(p) {
                continue;
            }
            out.push(
                contact_curve(a, &signed_gap, uv, reach, tol, chord_tol).unwrap_or(Polyline3 {
                    points: vec![p],
                    closed: false,
                }),
            );
        }
    }
    out
}

/// The refined section `curve` of `a` by the plane through `p0` with unit normal `n`, with the
/// chords left `loose` by its refinement that are off the surface carried across the tip of the
/// lens each cuts (see [`tip`]); with the contacts traced from those tips.
pub(crate) fn mend_section(
    a: &Patch,
    (p0, n): (DVec3, DVec3),
    curve: Polyline3,
    loose: &[[DVec3; 2]],
    (tol, chord_tol): (f64, f64),
) -> (Polyline3, Vec<Polyline3>) {
    if loose.is_empty() {
        return (curve, Vec::new());
    }
    let gap = |uv: DVec2| plane_gap(a, (p0, n), uv);
    let off = |p: DVec3| super::refine::off_section(a, (p0, n), p);
    tip::mend(a, &gap, &off, curve, loose, (tol, chord_tol))
}

/// [`mend_section`] for the refined intersection `curve` of `a` and `b`.
pub(crate) fn mend_pair(
    a: &Patch,
    b: &Patch,
    curve: Polyline3,
    loose: &[[DVec3; 2]],
    (tol, chord_tol): (f64, f64),
) -> (Polyline3, Vec<Polyline3>) {
    if loose.is_empty() {
        return (curve, Vec::new());
    }
    let warm: Cell<Option<DVec2>> = Cell::new(None);
    let gap = |uv: DVec2| pair_gap(a, b, &warm, uv);
    let off = |p: DVec3| super::refine::off_pair(a, b, p);
    tip::mend(a, &gap, &off, curve, loose, (tol, chord_tol))
}

/// The gap from `a(uv)` to `b`: signed along b's normal at the nearest point (found from
/// `warm`, the last one, which it updates).
fn pair_gap(a: &Patch, b: &Patch, warm: &Cell<Option<DVec2>>, uv: DVec2) -> GapAt {
    let (pa, ub, pb) = nearest_pair(a, b, warm, uv);
    GapAt {
        signed: (pa - pb).dot(unit_normal(b, ub)),
        dist: pa.distance(pb),
        point: 0.5 * (pa + pb),
    }
}

/// `a(uv)` (wrapped into a's domain), the parameters of b's point nearest it (searched from
/// `warm`, the last one, which it updates) and that point.
fn nearest_pair(
    a: &Patch,
    b: &Patch,
    warm: &Cell<Option<DVec2>>,
    uv: DVec2,
) -> (DVec3, DVec2, DVec3) {
    let mut uv = uv;
    a.normalise(&mut uv);
    let pa = a.eval(uv);
    let ub = b.project(pa, warm.get());
    warm.set(Some(ub));
    (pa, ub, b.eval(ub))
}

/// The gap from `a(uv)` to the plane through `p0` with unit normal `n`.
fn plane_gap(a: &Patch, (p0, n): (DVec3, DVec3), uv: DVec2) -> GapAt {
    let mut uv = uv;
    a.normalise(&mut uv);
    let p = a.eval(uv);
    let d = n.dot(p - p0);
    GapAt {
        signed: d,
        dist: d.abs(),
        point: p,
    }
}

fn unit_normal(a: &Patch, uv: DVec2) -> DVec3 {
    let (su, sv) = a.derivs(uv);
    su.cross(sv).normalize_or_zero()
}

/// Normals this close to parallel (sine of their angle) mark a refined curve as possibly lying
/// on a tangent contact: points within GEOMTOL of both surfaces near a contact can be √GEOMTOL
/// off it, where the normals differ by about that much. A crossing at so small an angle is not
/// taken for a contact: the trace finds no zero extremum of the gap across it.
const PARALLEL: f64 = 1e-3;

/// The refined section `curves` with those on which the plane is tangent to `a` — the mesh's
/// vertices lying exactly on the plane give such a contact in overlapping pieces — replaced by
/// the contact curve traced through them on the true surface.
pub(crate) fn regroup_section(
    a: &Patch,
    (p0, n): (DVec3, DVec3),
    curves: Vec<Polyline3>,
    (seed_tol, tol, chord_tol): (f64, f64, f64),
) -> Vec<Polyline3> {
    let gap = |uv: DVec2| plane_gap(a, (p0, n), uv);
    let tangent = |uv: DVec2| unit_normal(a, uv).cross(n).length() <= PARALLEL;
    regroup(a, None, &gap, &tangent, curves, (seed_tol, tol, chord_tol))
}

/// [`regroup_section`] for the refined intersection `curves` of `a` and `b`.
pub(crate) fn regroup_pair(
    a: &Patch,
    b: &Patch,
    curves: Vec<Polyline3>,
    (seed_tol, tol, chord_tol): (f64, f64, f64),
) -> Vec<Polyline3> {
    let warm: Cell<Option<DVec2>> = Cell::new(None);
    let gap = |uv: DVec2| pair_gap(a, b, &warm, uv);
    let tangent = |uv: DVec2| {
        let ub = b.project(a.eval(uv), None);
        unit_normal(a, uv).cross(unit_normal(b, ub)).length() <= PARALLEL
    };
    regroup(
        a,
        Some(b),
        &gap,
        &tangent,
        curves,
        (seed_tol, tol, chord_tol),
    )
}

/// The touching `curves` replaced by the contacts traced through them, with the crossings
/// found alongside those contacts (the meshes, made within `seed_tol`, see a contact and a
/// crossing closer than their cells as one curve). `other` is the surface the gap is measured
/// to, where that is one (not a plane): a crossing can end on its edge.
fn regroup(
    a: &Patch,
    other: Option<&Patch>,
    gap: &dyn Fn(DVec2) -> GapAt,
    tangent: &dyn Fn(DVec2) -> bool,
    curves: Vec<Polyline3>,
    (seed_tol, tol, chord_tol): (f64, f64, f64),
) -> Vec<Polyline3> {
    let mut kept = Vec::with_capacity(curves.len());
    let mut touching: Vec<(Polyline3, DVec2)> = Vec::new();
    // Touching at one or two of the probes only (which, of the first, middle and last point):
    // a crossing running into a touch, or one seed curve that ran along a contact and then off
    // along a crossing leaving it. Or at none, but where it folds back (see `fold_probes`).
    let mut partly: Vec<Probed> = Vec::new();
    let near = beside(a, tol, chord_tol);
    for c in curves {
        let n = c.points.len();
        if n == 0 {
            continue;
        }
        let probes = [c.points[0], c.points[n / 2], c.points[n - 1]].map(|p| a.project(p, None));
        let on = probes.map(tangent);
        match on.iter().position(|t| *t) {
            None => match fold_probes(a, tangent, &c, near) {
                Some((probes, on, folds)) => partly.push(Probed {
                    c,
                    probes,
                    on,
                    folds,
                }),
                None => kept.push(c),
            },
            Some(_) if on.iter().all(|t| *t) => touching.push((c, probes[1])),
            Some(_) => partly.push(Probed {
                c,
                probes: probes.to_vec(),
                on: on.to_vec(),
                folds: Vec::new(),
            }),
        }
    }
    let tols = (tol, chord_tol, near);
    let (mut traced, steps) = trace_contacts(a, gap, tangent, &touching, &partly, tols);
    // The pieces a traced contact covers go; any other stays. Of one it covers in part, the
    // stretches off it are a crossing's: a seed curve along the contact and on along a
    // crossing leaving it nearly tangent (the stub beside a branch point, parting at a sine
    // under `PARALLEL`) touches at all three probes.
    let mut cut: Vec<(Polyline3, [bool; 2])> = Vec::new();
    for (c, _) in touching {
        let on: Vec<bool> = c
            .points
            .iter()
            .map(|p| near_any(*p, &traced, near))
            .collect();
        if !on.contains(&true) {
            kept.push(c);
        } else if on.contains(&false) {
            cut.extend(off_curves(&c, &traced, near));
        }
    }
    // Of a partly touching curve, the stretches off the contacts: pieces of a crossing.
    for Probed { c, folds, .. } in partly {
        // A curve probed at its folds only is cut only where a contact runs through a fold: a
        // true lens's tip, turning into a contact, is kept whole, as before.
        if !folds.is_empty() && !traced.iter().any(|t| runs_through_any(t, &folds, near)) {
            kept.push(c);
        } else if c.points.iter().any(|p| near_any(*p, &traced, near)) {
            cut.extend(off_curves(&c, &traced, near));
        } else {
            kept.push(c);
        }
    }
    let crossings = Crossings {
        a,
        other,
        gap,
        contacts: &traced,
        near,
        len: steps.iter().copied().fold(0.0, f64::max),
        tols: (seed_tol, tol, chord_tol),
    };
    let found = crossings.beside(cut, &steps, &kept);
    kept.extend(found);
    let (kept, found) =
        branch::through_branch_points((a, other), gap, kept, &mut traced, near, (tol, chord_tol));
    let len = steps.iter().copied().fold(0.0, f64::max);
    let tols = (tol, chord_tol);
    let mut kept = branch_out::march_out(a, gap, kept, (&traced, &found), (len, near), tols);
    kept.extend(traced);
    kept
}

/// The contacts traced from the seed curves that touch at all three probes (from the middle one)
/// and from those that touch at some (`partly`, with their probes and which touch), each
/// contact once, with each one's step along it (see [`trace_from`]).
fn trace_contacts(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    tangent: &dyn Fn(DVec2) -> bool,
    touching: &[(Polyline3, DVec2)],
    partly: &[Probed],
    tols: (f64, f64, f64),
) -> (Vec<Polyline3>, Vec<f64>) {
    let near = tols.2;
    let mut traced: Vec<Polyline3> = Vec::new();
    let mut steps: Vec<f64> = Vec::new();
    fn touches(on: &[bool]) -> impl Iterator<Item = usize> + '_ {
        (0..on.len()).filter(move |&k| on[k])
    }
    // A contact traced from a fold counts only where it runs on through one.
    let through =
        |t: &Polyline3, folds: &[DVec3]| folds.is_empty() || runs_through_any(t, folds, near);
    let first = partly
        .iter()
        .filter_map(|x| Some((&x.c, x.probes[touches(&x.on).next()?], &x.folds[..])));
    let all = touching.iter().map(|(c, uv)| (c, *uv, &[][..]));
    for (c, uv, folds) in all.chain(first) {
        let found = trace_from(a, gap, c, uv, &traced, tols);
        if let Some((t, len)) = found.filter(|(t, _)| through(t, folds)) {
            traced.push(t);
            steps.push(len);
        }
    }
    // A partly touching curve's first touching probe can lie on a crossing close beside a
    // branch point (at CHORDTOL 0.005, 0.017 off the contact), looking touching but tracing no
    // contact; the curve, kept whole, then runs on along the contact past the branch point. Its
    // other touching probes are tried too, but only where no traced contact reaches the curve
    // (most seed curves are cut by one, and this costs nothing there).
    for Probed {
        c,
        probes,
        on,
        folds,
    } in partly
    {
        if c.points.iter().any(|p| near_any(*p, &traced, near)) {
            continue;
        }
        // Nor does a touching probe on a branch point itself, where the gap across flattens to
        // a triple root (`contact_curve_near`'s steps off it, a seed step long and straight,
        // end up to its square over twice the radius off a curved contact: from the plate at
        // d = 0..1, none traced one): the curve's points a step along it from its touching
        // probes are tried last.
        let others = touches(on).skip(1).map(|k| probes[k]);
        let len = longest_step(c);
        let inward = folds
            .is_empty()
            .then(|| step_in(c, on, len))
            .into_iter()
            .flatten()
            .map(|q| a.project(q, None))
            .filter(|uv| tangent(*uv));
        for uv in others.chain(inward) {
            let found = trace_from(a, gap, c, uv, &traced, tols);
            if let Some((t, len)) = found.filter(|(t, _)| through(t, folds)) {
                traced.push(t);
                steps.push(len);
                break;
            }
        }
    }
    trace_lone_points(a, gap, touching, partly, (&mut traced, &mut steps), tols);
    (traced, steps)
}

/// One-point touching seeds (no step of their own) trace with the longest step of the other
/// seeds, where nothing traced runs by them: a seed curve coming into a branch point along the
/// crossing (densify leaving the chord there loose) steps in onto the crossing, not the contact,
/// and the contact's lone seed points are then all that is left on it.
fn trace_lone_points(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    touching: &[(Polyline3, DVec2)],
    partly: &[Probed],
    (traced, steps): (&mut Vec<Polyline3>, &mut Vec<f64>),
    (tol, chord_tol, near): (f64, f64, f64),
) {
    let step = touching
        .iter()
        .map(|(c, _)| c)
        .chain(partly.iter().map(|x| &x.c))
        .map(longest_step)
        .fold(0.0, f64::max);
    if step <= 0.0 {
        return;
    }
    for (c, uv) in touching.iter().filter(|(c, _)| c.points.len() == 1) {
        if near_any(c.points[0], traced, near) {
            continue;
        }
        let fresh = |t: &Polyline3| !t.points.iter().all(|p| near_any(*p, traced, near));
        if let Some(t) = contact_curve_near(a, gap, *uv, step, tol, chord_tol).filter(fresh) {
            traced.push(t);
            steps.push(step);
        }
    }
}

/// The contact traced on the true surfaces from `uv`, a touching probe of the seed curve `c`,
/// with `c`'s longest segment (the step along it); none where no contact traces from there, or
/// where `c` or `uv` lies on one of the `traced` contacts or the contact found is one of them.
/// `tols`: the refinement and chord tolerances and the contacts' nearness.
fn trace_from(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    c: &Polyline3,
    uv: DVec2,
    traced: &[Polyline3],
    (tol, chord_tol, near): (f64, f64, f64),
) -> Option<(Polyline3, f64)> {
    // A seed touching where a traced contact runs would trace that contact again (and beside a
    // branch point, where the gap's extremum off the contact is within tol too, wander about
    // it: seen from the plate, a second walk 18 long).
    if c.points.len() < 2
        || c.points.iter().all(|p| near_any(*p, traced, near))
        || near_any(a.eval(uv), traced, near)
    {
        return None;
    }
    let len = longest_step(c);
    // A seed curve partly off the traced contacts (where a crossing runs into one, points within
    // the tolerance of both surfaces stray farther from it) can trace one again.
    let fresh = |t: &Polyline3| !t.points.iter().all(|p| near_any(*p, traced, near));
    let t = contact_curve_near(a, gap, uv, len, tol, chord_tol).filter(fresh)?;
    Some((t, len))
}

/// The longest segment of `c`: the step along the contacts traced from it.
fn longest_step(c: &Polyline3) -> f64 {
    c.points
        .windows(2)
        .map(|w| w[0].distance(w[1]))
        .fold(0.0, f64::max)
}

/// The crossings beside traced contacts, found in pieces and carried on along them.
struct Crossings<'c> {
    a: &'c Patch<'c>,
    /// The surface the gap is measured to, where that is one: a crossing can end on its edge.
    other: Option<&'c Patch<'c>>,
    gap: &'c dyn Fn(DVec2) -> GapAt,
    /// The traced contacts: a crossing is followed until it comes beside one of them...
    contacts: &'c [Polyline3],
    /// ... within this.
    near: f64,
    /// The step along a crossing (the longest of the seed curves' segments).
    len: f64,
    /// The seed, refinement and chord tolerances.
    tols: (f64, f64, f64),
}

impl Crossings<'_> {
    /// The crossings from the `cut` pieces (stretches of seed curves off the contacts, with the
    /// ends where they were cut) and from the scan across each contact (every `steps` along it)
    /// for crossings beside it not among `known`: each carried on, then joined end to end.
    fn beside(
        &self,
        cut: Vec<(Polyline3, [bool; 2])>,
        steps: &[f64],
        known: &[Polyline3],
    ) -> Vec<Polyline3> {
        let (seed_tol, tol, chord_tol) = self.tols;
        let unfold = |c: &Polyline3| {
            let c = alongside::unfold_overshoots(self.a, self.gap, c.clone(), tol, chord_tol);
            copies::without_retraces(self.a, self.gap, c, tol, chord_tol)
        };
        let mut pieces: Vec<Polyline3> = cut.iter().map(|x| unfold(&x.0)).collect();
        self.extend(&mut pieces, &cut);
        // The scan looks across only every step along a contact: what it finds is carried on
        // likewise.
        for (c, &step) in self.contacts.iter().zip(steps) {
            // At least three looks across an open contact (its ends and its middle): a contact
            // seeded by a single segment (a ruled sheet meshed with one cell along it, at a
            // coarse CHORDTOL) was looked across at its ends only, where one was a branch point,
            // and the one root found made no piece of the crossing.
            let whole = c.length();
            let step = if whole > 0.0 {
                step.min(0.5 * whole)
            } else {
                step
            };
            let scan = alongside::Scan {
                step,
                apart: seed_gap(seed_tol),
                dup: self.near,
            };
            let known: Vec<Polyline3> = known.iter().chain(&pieces).cloned().collect();
            let found =
                alongside::crossings_alongside(self.a, self.gap, c, &scan, &known, tol, chord_tol);
            let found: Vec<(Polyline3, [bool; 2])> =
                found.into_iter().map(|f| (f, [false; 2])).collect();
            pieces.extend(found.iter().map(|x| x.0.clone()));
            self.extend(&mut pieces, &found);
        }
        let reach = 2.0 * self.len;
        // Several seed curves can refine onto one stretch of a crossing (at a CHORDTOL as coarse
        // as the contact's band): its copies go before joining, which would double back over them
        // or leave them beside it; what lay between pieces only until they were joined (a stub
        // on the crossing between two ends) goes after. No surface is evaluated where nothing
        // is cut.
        let (pieces, cut) = copies::without_copies(pieces, self.near);
        let mut joined = alongside::join_ends(self.a, self.gap, pieces, reach, tol, chord_tol);
        if cut {
            let (pieces, again) = copies::without_copies(joined, self.near);
            joined = pieces;
            if again {
                joined = alongside::join_ends(self.a, self.gap, joined, reach, tol, chord_tol);
            }
        }
        branch::run_into(
            (self.a, self.other),
            self.gap,
            joined,
            self.contacts,
            self.near,
            (tol, chord_tol),
        )
    }

    /// Carries on the last `new.len()` of `pieces` (each with the ends where it was cut off a
    /// seed curve), each until it comes beside a contact or another piece: the joints between
    /// pieces are made afterwards by [`alongside::join_ends`].
    fn extend(&self, pieces: &mut [Polyline3], new: &[(Polyline3, [bool; 2])]) {
        let (_, tol, chord_tol) = self.tols;
        let first = pieces.len() - new.len();
        for (i, (_, cut)) in (first..pieces.len()).zip(new) {
            // Beside a contact the search can fall on its double zero; a node there is kept
            // only where the gap changes sign across it (on the true surfaces, so a crossing
            // closer to a contact than `near`, which scales with CHORDTOL, is still followed).
            let stop = |uv: DVec2, t: DVec2, p: DVec3| {
                near_any(p, self.contacts, self.near)
                    && !alongside::changes_sign(self.a, self.gap, uv, t, self.near, tol)
                    || (0..pieces.len())
                        .any(|j| j != i && near_any(p, std::slice::from_ref(&pieces[j]), self.near))
            };
            let longer = alongside::extend_crossing(
                self.a,
                self.gap,
                (&pieces[i], *cut),
                &stop,
                self.len,
                (tol, chord_tol),
            );
            pieces[i] = longer;
        }
    }
}

/// How far apart two meshes made within `seed_tol` of touching surfaces can be: inscribed, they
/// are apart by a few chord tolerances at most. Seeds of a contact lie within it.
fn seed_gap(seed_tol: f64) -> f64 {
    8.0 * seed_tol
}

/// The runs of `c`'s points (two or more) farther than `r` from every one of `curves`, each
/// with whether it was cut there at its start and at its end (ran on near a curve).
fn off_curves(c: &Polyline3, curves: &[Polyline3], r: f64) -> Vec<(Polyline3, [bool; 2])> {
    let off: Vec<bool> = c.points.iter().map(|p| !near_any(*p, curves, r)).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < off.len() {
        let j = (i..off.len()).find(|&k| !off[k]).unwrap_or(off.len());
        if j - i >= 2 {
            let piece = Polyline3 {
                points: c.points[i..j].to_vec(),
                closed: false,
            };
            out.push((piece, [i > 0, j < off.len()]));
        }
        i = j + 1;
    }
    out
}

/// How near a curve a point within `tol` of both surfaces is taken for a point of that curve: a
/// point within `tol` of both surfaces beside a contact can be √(tol·R) off it.
fn beside(a: &Patch, tol: f64, chord_tol: f64) -> f64 {
    2.0 * chord_tol.max(tol) + 4.0 * (tol * a.scale()).sqrt()
}

/// Whether `p` lies within `r` of one of `curves` (points, or segments of polylines).
pub(super) fn near_any(p: DVec3, curves: &[Polyline3], r: f64) -> bool {
    closest_points(p, curves).any(|q| p.distance(q) <= r)
}

/// The point of each of `curves` nearest `p`, segment by segment (a one-point curve: its point).
pub(super) fn closest_points(p: DVec3, curves: &[Polyline3]) -> impl Iterator<Item = DVec3> + '_ {
    curves.iter().flat_map(move |c| {
        let n = c.points.len();
        let segs = match n {
            1 => 1,
            _ if c.closed => n,
            _ => n.saturating_sub(1),
        };
        (0..segs).map(move |k| {
            if n == 1 {
                return c.points[0];
            }
            let (s, e) = (c.points[k], c.points[(k + 1) % n]);
            let d = e - s;
            let f = ((p - s).dot(d) / d.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            s + d * f
        })
    })
}

/// The points where the plane through `p0` with unit normal `n` touches `a` (meshed as `ma`
/// within `seed_tol`) without crossing it, away from the section `curves`: zero minima of
/// `|n·(S(u, v) − p0)|`, each on the true surface and within `tol` of the plane.
pub(crate) fn plane_contacts(
    a: &Patch,
    ma: &Mesh,
    (p0, n): (DVec3, DVec3),
    curves: &[Polyline3],
    (seed_tol, chord_tol): (f64, f64),
    tol: f64,
) -> Vec<Polyline3> {
    let side: Vec<f64> = ma.vertices().iter().map(|v| n.dot(*v - p0)).collect();
    let dist: Vec<f64> = side.iter().map(|h| h.abs()).collect();
    let sine = |c: DVec3, start: Option<(DVec2, DVec2)>| {
        let ua = a.project(c, start.map(|s| s.0));
        (unit_normal(a, ua).cross(n).length(), (ua, DVec2::ZERO))
    };
    let lows = Lows::new(ma, (&dist, &side), seed_tol, curves, &sine);
    let dup = beside(a, tol, chord_tol);
    let h = |uv: DVec2| {
        let mut uv = uv;
        a.normalise(&mut uv);
        n.dot(a.eval(uv) - p0)
    };
    let gap_at = |uv: DVec2| plane_gap(a, (p0, n), uv);
    let mut out: Vec<Polyline3> = Vec::new();
    let found = ridge::Found {
        a,
        gap: &|uv| h(uv).abs(),
        rise: seed_tol,
    };
    for (i, reach) in lows.vertices(ma) {
        if found.claims(ma.vertices()[i], &out, 4.0 * reach) {
            continue;
        }
        let mut uv = nelder_mead(&|uv| h(uv).abs(), a.project(ma.vertices()[i], None), 1e-3);
        a.normalise(&mut uv);
        if h(uv).abs() <= tol {
            // A seed beside a section curve (let through by `Lows`) can lead onto that curve,
            // or onto a contact found (a seed that a ridge parts from its nearest one).
            if near_any(a.eval(uv), curves, dup) || near_any(a.eval(uv), &out, dup) {
                continue;
            }
            if let Some(c) = contact_curve(a, &gap_at, uv, reach, tol, chord_tol) {
                out.push(c);
                continue;
            }
        }
        let top = level(a, uv, n);
        let p = a.eval(top);
        if found.claims(p, &out, 4.0 * reach) {
            continue;
        }
        if h(top).abs() <= tol {
            out.push(Polyline3 {
                points: vec![p],
                closed: false,
            });
        } else if h(uv).abs() <= tol {
            // The surface reaches through the plane in a loop smaller than the seeding mesh:
            // rays in (u, v) from the extremum to the sign change seed it.
            if let Some(c) = small_loop(a, top, uv.distance(top), &h) {
                let c = super::refine::refine_section_curve(a, &c, p0, n, tol, chord_tol);
                if c.points.len() > 2 {
                    out.push(c);
                }
            }
        }
    }
    out
}

/// Newton on `S_u·n = S_v·n = 0` from the minimiser's `uv`: the minimum of `|n·S|` is flat,
/// so the minimiser leaves the point about √tol off along the surface; the contact is where the
/// surface is parallel to the plane (the minimiser's point when Newton wanders off or does not
/// settle).
fn level(a: &Patch, uv0: DVec2, n: DVec3) -> DVec2 {
    const H: f64 = 1e-5;
    // Iterates unwrapped (a step across a periodic seam is a small step), evaluates wrapped.
    let g = |uv: DVec2| {
        let mut uv = uv;
        a.normalise(&mut uv);
        let (su, sv) = a.derivs(uv);
        DVec2::new(su.dot(n), sv.dot(n))
    };
    let mut uv = uv0;
    for _ in 0..20 {
        let g0 = g(uv);
        let (gu, gv) = (
            (g(uv + DVec2::X * H) - g(uv - DVec2::X * H)) / (2.0 * H),
            (g(uv + DVec2::Y * H) - g(uv - DVec2::Y * H)) / (2.0 * H),
        );
        let det = gu.x * gv.y - gv.x * gu.y;
        if det.abs() <= 1e-300 || !det.is_finite() {
            return uv0;
        }
        let step = DVec2::new(
            (g0.x * gv.y - gv.x * g0.y) / det,
            (gu.x * g0.y - g0.x * gu.y) / det,
        );
        uv -= step;
        if uv.distance(uv0) > 0.05 {
            return uv0;
        }
        // The derivatives are differences: steps settle at their noise, about 1e-10.
        if step.length() <= 1e-10 {
            a.normalise(&mut uv);
            return uv;
        }
    }
    uv0
}

/// Minimises the distance from `a(u, v)` to `b` from the point of `a` nearest `p`; the
/// parameters on `a` and the contact point (midway between the surfaces) when the minimum is
/// within `tol`.
fn touch(a: &Patch, b: &Patch, p: DVec3, tol: f64) -> Option<(DVec2, DVec3)> {
    let warm: Cell<Option<DVec2>> = Cell::new(None);
    let eval = |uv: DVec2| {
        let (pa, _, pb) = nearest_pair(a, b, &warm, uv);
        (pa.distance(pb), pa, pb)
    };
    let start = a.project(p, None);
    let uv = nelder_mead(&|uv| eval(uv).0, start, 1e-3);
    let (d, pa, pb) = eval(uv);
    let mut uv = uv;
    a.normalise(&mut uv);
    (d <= tol).then(|| (uv, 0.5 * (pa + pb)))
}

/// Nelder–Mead minimisation in the plane from `x0` with an initial simplex of size `h`.
fn nelder_mead(f: &dyn Fn(DVec2) -> f64, x0: DVec2, h: f64) -> DVec2 {
    let mut s = [
        (x0, f(x0)),
        (x0 + DVec2::X * h, f(x0 + DVec2::X * h)),
        (x0 + DVec2::Y * h, f(x0 + DVec2::Y * h)),
    ];
    for _ in 0..600 {
        s.sort_by(|p, q| p.1.total_cmp(&q.1));
        let size = s[1].0.distance(s[0].0).max(s[2].0.distance(s[0].0));
        if size <= 1e-15 || s[0].1 == 0.0 {
            break;
        }
        let c = 0.5 * (s[0].0 + s[1].0);
        let xr = c + (c - s[2].0);
        let fr = f(xr);
        if fr < s[0].1 {
            let xe = c + 2.0 * (c - s[2].0);
            let fe = f(xe);
            s[2] = if fe < fr { (xe, fe) } else { (xr, fr) };
        } else if fr < s[1].1 {
            s[2] = (xr, fr);
        } else {
            let xc = c + 0.5 * (s[2].0 - c);
            let fc = f(xc);
            if fc < s[2].1 {
                s[2] = (xc, fc);
            } else {
                for k in 1..3 {
                    let x = s[0].0 + 0.5 * (s[k].0 - s[0].0);
                    s[k] = (x, f(x));
                }
            }
        }
    }
    s.sort_by(|p, q| p.1.total_cmp(&q.1));
    s[0].0
}
