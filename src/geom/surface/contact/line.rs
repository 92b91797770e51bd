//! Tangent contact along a curve (a cylinder lying on a plane, a torus under its top plane): the
//! surfaces touch at every point of a line or loop without crossing, so neither the meshes'
//! intersection nor the local minimum search sees more than scattered points of it.
//!
//! Seen from the parameters of surface `a`, the signed gap `h(u, v)` to the other surface has a
//! zero extremum at a contact; along a contact curve its Hessian is singular, the null direction
//! being the curve's tangent. From a contact point the curve is followed both ways: a step along
//! the tangent, then the extremum of `h` across it (Newton on the transverse derivative, exact
//! for the quadratic `h` of a tangency). A step is kept when the surfaces meet there within the
//! tolerance; it is halved where they part (bisecting for the contact's end to a hundredth of the
//! tolerance), held at the edge of a bounded parameter, and the loop closes when the walk returns
//! to its start. The nodes are then densified within the chord tolerance like every refined
//! curve.

use super::super::refine::{assemble, mid, Patch};
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

/// The gap between the surfaces at a parameter pair of `a`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GapAt {
    /// Signed: smooth through a contact, where it has an extremum of value zero.
    pub signed: f64,
    /// The distance between the surfaces (it differs from |signed| off the other's extent).
    pub dist: f64,
    /// The point of contact (midway between the surfaces).
    pub point: DVec3,
}

/// Difference step in (u, v) for the derivatives of the gap.
const D: f64 = 1e-5;

/// The smaller principal curvature of `h` over the larger below which the contact is a curve:
/// along one the Hessian is zero but for difference noise (about 1e-7 of the other).
const FLAT: f64 = 1e-4;

/// Most nodes one walk makes before giving up (a curve thousands of steps long).
pub(super) const MAX_NODES: usize = 1 << 15;

/// The Hessian of `h` at `uv` by central differences: `[h_uu, h_uv, h_vv]`.
fn hessian(h: &dyn Fn(DVec2) -> f64, uv: DVec2) -> [f64; 3] {
    let f = |du: f64, dv: f64| h(uv + DVec2::new(du, dv));
    let h0 = f(0.0, 0.0);
    let d2 = D * D;
    [
        (f(D, 0.0) - 2.0 * h0 + f(-D, 0.0)) / d2,
        (f(D, D) - f(D, -D) - f(-D, D) + f(-D, -D)) / (4.0 * d2),
        (f(0.0, D) - 2.0 * h0 + f(0.0, -D)) / d2,
    ]
}

/// The eigenpairs of the symmetric `[[a, b], [b, c]]`, the larger |λ| first.
fn eigen([a, b, c]: [f64; 3]) -> [(f64, DVec2); 2] {
    let (m, r) = (0.5 * (a + c), (0.25 * (a - c) * (a - c) + b * b).sqrt());
    let th = 0.5 * (2.0 * b).atan2(a - c);
    let (e1, e2) = (
        DVec2::new(th.cos(), th.sin()),
        DVec2::new(-th.sin(), th.cos()),
    );
    let (p1, p2) = ((m + r, e1), (m - r, e2));
    if p1.0.abs() >= p2.0.abs() {
        [p1, p2]
    } else {
        [p2, p1]
    }
}

/// The three-point derivative's bias over the second derivative (the shift it gives the
/// extremum, in parameters) up to which Newton runs on three-point differences less the bias
/// found at the start; a step of it this short has converged (the next is at the noise).
const QUICK: f64 = 1e-9;

/// The extremum of `h` on the line `uv + s·w` nearest `uv` (Newton on the derivative along `w`),
/// with bounded parameters held in their domain. The three-point derivative is off by D²·h‴/6,
/// which moves the extremum by that over h″ (1e-9 in parameters on a contact 1e-9 long, enough
/// for a scan across from its end on a bounded edge to leave the domain), unbounded where the
/// contact flattens to an inflection across (a crossing running into it): there Newton leapt
/// off, or onto the gap's other extremum, a maximum beside the contact. The five-point
/// derivative at the start measures the bias: below [`QUICK`], plain Newton on three-point
/// differences less that bias (h‴ barely changes over the search; two or three steps);
/// elsewhere [`settle_flat`].
pub(super) fn settle(a: &Patch, h: &dyn Fn(DVec2) -> f64, uv: DVec2, w: DVec2) -> DVec2 {
    settle_bent(a, h, uv, w).0
}

/// [`settle`], with the second derivative of `h` along `w` where the search last took it (at
/// the extremum or one converged step from it; zero or NaN where it had none): its sign tells a
/// contact from the gap's extremum beside it at a branch point (see [`largest`]).
fn settle_bent(a: &Patch, h: &dyn Fn(DVec2) -> f64, uv: DVec2, w: DVec2) -> (DVec2, f64) {
    let f = |x: f64| h(uv + w * x);
    let g5 = slope5(&f, 0.0);
    let (p, z, m) = (f(D), f(0.0), f(-D));
    let (g, mut c) = ((p - m) / (2.0 * D), (p - 2.0 * z + m) / (D * D));
    if !(c.abs() > 0.0 && c.is_finite() && g.is_finite() && g5.is_finite()) {
        return (clamp_bounded(a, uv), c);
    }
    let bias = g - g5;
    if bias.abs() > QUICK * c.abs() {
        let (s, c) = settle_flat(&f, g5, c);
        return (clamp_bounded(a, uv + w * s), c);
    }
    let (mut s, mut step) = (0.0, (g5 / c).clamp(-0.05, 0.05));
    for _ in 0..10 {
        s -= step;
        if step.abs() <= QUICK {
            break;
        }
        let (m, z, p) = (f(s - D), f(s), f(s + D));
        let g = (p - m) / (2.0 * D) - bias;
        let cn = (p - 2.0 * z + m) / (D * D);
        if !(cn.abs() > 0.0 && cn.is_finite() && g.is_finite()) {
            break;
        }
        c = cn;
        step = (g / c).clamp(-0.05, 0.05);
    }
    (clamp_bounded(a, uv + w * s), c)
}

/// Whether the extremum of the gap settled at, with value `h` and second derivative `c` across,
/// is one where |h| is largest, not least (h·c < 0, h above its rounding, `point`'s
/// coordinates' ulps times 64, whose sign says nothing): between two zeros of the gap. Beside a
/// branch point the gap across the contact is about (a/2)·x² − (b/6)·x³: a double zero at
/// x = 0 (the contact), a simple one at 3a/b (the crossing), and between them such an extremum
/// at 2a/b, its gap 2a³/(3b²) within the tolerance for |a| up to about ∛tol: a search across
/// from the wrong side (a long step's tangent running off the contact's convex side) settles
/// there, up to 1e-3 off the contact. (Surfaces crossing by less than the tolerance have one
/// too, alone: the contact the tracer follows there.)
fn largest(h: f64, c: f64, point: DVec3) -> bool {
    h * c < 0.0 && h.abs() > touching(point)
}

/// The rounding of a gap at `point`: its coordinates' ulps times 64.
fn touching(point: DVec3) -> f64 {
    64.0 * f64::EPSILON * point.abs().max_element()
}

/// [`settle`] onto the contact, not onto the gap's extremum beside it at a branch point (see
/// [`largest`]), where the surfaces meet (within `within`): from there the contact lies
/// 2a/b = √(6·|h/c|) along `w` one way (the crossing half as far again the other, past which
/// the search comes back to the extremum), so the search is made again from that far either
/// way and taken where it finds the surfaces touching (the gap zero but for rounding). Where it
/// does not (surfaces crossing by less than the tolerance, their gap's one extremum), the point
/// stays. The point and the gap there.
fn settle_on_contact(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    (uv, w): (DVec2, DVec2),
    within: f64,
) -> (DVec2, GapAt) {
    let h = |uv: DVec2| gap(uv).signed;
    let (c, bent) = settle_bent(a, &h, uv, w);
    let g = gap(c);
    if g.dist > within || !largest(g.signed, bent, g.point) {
        return (c, g);
    }
    let reach = (6.0 * (g.signed / bent).abs()).sqrt();
    for side in [-1.0, 1.0] {
        let (q, _) = settle_bent(a, &h, c + w * (side * reach), w);
        let gq = gap(q);
        if gq.signed.abs() <= touching(gq.point) {
            return (q, gq);
        }
    }
    (c, g)
}

/// The five-point derivative of `f` at `x`.
fn slope5(f: &dyn Fn(f64) -> f64, x: f64) -> f64 {
    (8.0 * (f(x + D) - f(x - D)) - (f(x + 2.0 * D) - f(x - 2.0 * D))) / (12.0 * D)
}

/// The extremum of `f` nearest 0 (where its five-point derivative is `g` and its second
/// derivative `c`) by Newton on the five-point derivative, where the three-point one is off: a
/// step that does not lessen the derivative is halved, and the search stops where none does
/// (the derivative at its noise).
fn settle_flat(f: &dyn Fn(f64) -> f64, mut g: f64, mut c: f64) -> (f64, f64) {
    let mut s = 0.0;
    for it in 0..20 {
        if it > 0 {
            c = (f(s + D) - 2.0 * f(s) + f(s - D)) / (D * D);
        }
        if !(c.abs() > 0.0 && c.is_finite() && g.is_finite()) {
            break;
        }
        let mut step = (g / c).clamp(-0.05, 0.05);
        let mut next = None;
        for _ in 0..8 {
            let gn = slope5(f, s - step);
            if gn.abs() < g.abs() {
                next = Some(gn);
                break;
            }
            step *= 0.5;
        }
        let Some(gn) = next else { break };
        s -= step;
        g = gn;
        if step.abs() <= 1e-13 {
            break;
        }
    }
    (s, c)
}

pub(super) fn clamp_bounded(a: &Patch, mut uv: DVec2) -> DVec2 {
    for k in 0..2 {
        if !a.periodic()[k] {
            uv[k] = uv[k].clamp(0.0, 1.0);
        }
    }
    uv
}

/// `y − x` the short way round in periodic directions.
pub(super) fn delta(a: &Patch, x: DVec2, y: DVec2) -> DVec2 {
    let mut d = y - x;
    for k in 0..2 {
        if a.periodic()[k] {
            d[k] -= d[k].round();
        }
    }
    d
}

/// The distance from `p` to the segment `ab`, and where along it (0 at a, 1 at b) it is nearest.
fn to_segment(p: DVec3, a: DVec3, b: DVec3) -> (f64, f64) {
    let d = b - a;
    let f = ((p - a).dot(d) / d.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
    (p.distance(a + d * f), f)
}

/// A step along a contact this short (in space) is within about the tolerance of it when taken
/// straight along its tangent: the contact's curvature (about 1/size at most) times its square.
fn short_step(a: &Patch, tol: f64) -> f64 {
    (tol * a.scale()).sqrt()
}

/// Follows the contact from `start` along `dir` (in (u, v)) in steps of about `len` in space.
/// Returns the nodes after `start` and whether the walk came back round to it.
fn walk(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    start: DVec2,
    dir: DVec2,
    len: f64,
    tol: f64,
) -> (Vec<DVec2>, bool) {
    let g_start = gap(start);
    let p_start = g_start.point;
    // Where the surfaces part: half way from the contact's own gap to the tolerance (half the
    // tolerance for surfaces that touch), so the end is found within it, and a contact held a
    // fraction of the tolerance apart (0.6 of it: they still meet) is followed all the same.
    let level = if g_start.dist >= 0.0 {
        g_start.dist.min(tol)
    } else {
        0.0
    };
    let parted = 0.5 * (tol + level);
    let (mut uv, mut t) = (start, dir.normalize());
    let mut p_prev = p_start;
    let mut nodes: Vec<DVec2> = Vec::new();
    let mut frac = 1.0;
    let short = short_step(a, tol);
    // How fast the walk turns (radians per unit of parameter), measured between two
    // consecutive settled chords longer than `short`: the straight steps near an end follow
    // that arc, not the last chord's line, which leans off the contact by half the chord's turn
    // and more with each straight step (a contact on a circle of radius 2, traced from a
    // plate's parameters to the patch's edge, ended 2.1e-8 off it after straight steps over
    // 1.6e-4 along a chord 3.5e-4 long; now 1e-12).
    let (mut turn, mut settled_chord): (f64, Option<DVec2>) = (0.0, None);
    let mut last_chord = 0.0;
    while nodes.len() < MAX_NODES {
        let Some(speed) = speed_along(a, uv, t) else {
            break;
        };
        let mut step = frac * len / speed;
        // A bounded parameter reaching its edge: the step ends there, and so does the walk.
        let mut at_edge = false;
        for k in 0..2 {
            if a.periodic()[k] || t[k] == 0.0 {
                continue;
            }
            let room = ((if t[k] > 0.0 { 1.0 } else { 0.0 }) - uv[k]) / t[k];
            if room <= 1e-12 {
                return (nodes, false);
            }
            if room <= step {
                step = room;
                at_edge = true;
            }
        }
        let ahead = uv + t * step;
        let on = |g: &GapAt, moved: DVec2| {
            g.dist <= parted && moved.dot(t) > 0.0 && moved.length() <= 2.0 * step
        };
        // Once a bisection for the end has made the step shorter than `short`, the step straight
        // along the tangent is on the contact to its curvature times the step squared (about
        // the tolerance), and is taken where the surfaces meet there: near a branch point (a
        // crossing running into the contact, here where it ends at the other surface's edge)
        // the section across flattens to an inflection, and the extremum `settle` finds is off
        // the contact by the derivative's noise over a vanishing curvature (1e-6 within 1e-5
        // of it), or missing. Where the surfaces part (the contact's true end) it fails.
        let bend = DVec2::from_angle(0.5 * turn * (last_chord + step));
        let straight = clamp_bounded(a, uv + bend.rotate(t) * step);
        let gs = (frac * len <= short).then(|| gap(straight));
        let (cand, g, settled) = match gs {
            Some(gs) if on(&gs, straight - uv) => (straight, gs, false),
            _ => {
                let (c, g) = settle_on_contact(a, gap, (ahead, t.perp()), parted);
                (c, g, true)
            }
        };
        let moved = cand - uv;
        if on(&g, moved) {
            // Back round to the start (this step reaches or passes it): the loop closes there.
            let (d, f) = to_segment(p_start, p_prev, g.point);
            if nodes.len() >= 2 && d <= 0.1 * len && f > 0.0 {
                return (nodes, true);
            }
            nodes.push(cand);
            let long = settled && p_prev.distance(g.point) > short;
            if let (true, Some(c)) = (long, settled_chord) {
                turn =
                    c.perp_dot(moved).atan2(c.dot(moved)) / (0.5 * (c.length() + moved.length()));
            }
            settled_chord = long.then_some(moved);
            last_chord = moved.length();
            t = moved.normalize();
            uv = cand;
            p_prev = g.point;
            if at_edge {
                return (nodes, false);
            }
            // Back up to full steps gradually: near an end the next full step fails again,
            // and growing fourfold keeps the search for the end a bisection.
            frac = (4.0 * frac).min(1.0);
        } else {
            // The surfaces part (or the step left the curve): shorter steps find the end, to
            // well within the tolerance.
            frac *= 0.5;
            if frac * len < 0.01 * tol {
                break;
            }
        }
    }
    (nodes, false)
}

/// The contact curve through the contact at `uv0` (parameters of `a`, `gap` within `tol` there)
/// when the contact is a curve, densified within `chord_tol`; None when it is isolated (the gap
/// curves up both ways). `len` is the step length in space (the seeding mesh's edge length).
pub(crate) fn contact_curve(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv0: DVec2,
    len: f64,
    tol: f64,
    chord_tol: f64,
) -> Option<Polyline3> {
    let h = |uv: DVec2| gap(uv).signed;
    let [(big, across), (small, along)] = eigen(hessian(&h, uv0));
    // Curved both ways (or NaN): an isolated contact.
    let flat = small.abs() <= FLAT * big.abs();
    if !flat {
        return None;
    }
    // The seed lies on the contact to about √tol across it: settle it there first.
    let uv0 = settle(a, &h, uv0, across);
    if gap(uv0).dist > tol {
        return None;
    }
    let (fwd, mut closed) = walk(a, gap, uv0, along, len, tol);
    let mut nodes: Vec<DVec2> = Vec::new();
    if !closed {
        let (back, _) = walk(a, gap, uv0, -along, len, tol);
        nodes.extend(back.into_iter().rev());
    }
    nodes.push(uv0);
    nodes.extend(fwd);
    if nodes.len() < 2 {
        return None;
    }
    // Both ways ending on parameter edges that the surface joins (a sweep round a closed guide
    // whose frames do not close to roundoff): one loop.
    if !closed && nodes.len() >= 3 {
        let (p, q) = (gap(nodes[0]).point, gap(nodes[nodes.len() - 1]).point);
        if p.distance(q) <= 4.0 * tol {
            nodes.pop();
            closed = true;
        }
    }
    let nodes: Vec<(DVec2, GapAt)> = nodes
        .into_iter()
        .map(|mut uv| {
            a.normalise(&mut uv);
            (uv, gap(uv))
        })
        .collect();
    if crosses(nodes.iter().map(|n| n.1.signed), tol) {
        return None;
    }
    let nodes: Vec<(DVec2, DVec3)> = nodes.into_iter().map(|(uv, g)| (uv, g.point)).collect();
    let short = short_step(a, tol);
    let mid_of = |x: &(DVec2, DVec3), y: &(DVec2, DVec3)| {
        let across = delta(a, x.0, y.0).perp().normalize_or_zero();
        // Between nodes a short step apart (the walk's last, near an end) the midpoint is on
        // the contact to about the tolerance: settled, near a branch point, it would be off by
        // the noise over a vanishing curvature across (see `walk`) and be inserted as a zigzag.
        let m = mid(a, x.0, y.0);
        let (m, g) = if x.1.distance(y.1) <= short {
            (m, gap(m))
        } else {
            // Beside a branch point a long chord's midpoint can settle on the gap's extremum
            // beside the contact, up to 1e-3 off it, and the chords to it would follow that
            // out and back (a spur on the contact).
            settle_on_contact(a, gap, (m, across), tol)
        };
        (g.dist <= tol).then_some((m, g.point))
    };
    Some(assemble(&nodes, closed, |x| x.1, &mid_of, tol, chord_tol))
}

/// The fraction of the tolerance by which a walk's gap must reach either side of zero for the
/// surfaces to cross along it (see [`crosses`]): a contact's nodes lie on the gap's zero
/// extremum (at its rounding, far under this) or, where the surfaces part, on one side of it.
const ACROSS: f64 = 0.1;

/// Whether the signed gaps at a walk's nodes lie beyond `ACROSS·tol` on both sides of zero:
/// the surfaces cross along the walk, so it is no contact. From a branch point on a bounded
/// edge (the gap across a triple root, its Hessian vanishing, so no direction along it) the
/// walk can run across the contact and through the crossing instead of along the contact
/// (cone ∩ patch d = 0..0.3 at CHORDTOL 1e-3: 21 nodes 1.84e-3 long across r = 2, the gap
/// from +5e-10 to −5e-10), and cut the crossing there as a contact.
fn crosses(gaps: impl Iterator<Item = f64>, tol: f64) -> bool {
    let (mut above, mut below) = (false, false);
    for h in gaps {
        above |= h > ACROSS * tol;
        below |= h < -ACROSS * tol;
    }
    above && below
}

/// How fast the surface moves in space along the parameter direction `t` at `uv`; None at a
/// degenerate point of the parameterisation (zero, infinite or NaN), where there is no way on.
pub(super) fn speed_along(a: &Patch, uv: DVec2, t: DVec2) -> Option<f64> {
    let mut w = uv;
    a.normalise(&mut w);
    let (su, sv) = a.derivs(w);
    let speed = (su * t.x + sv * t.y).length();
    (speed > 0.0 && speed.is_finite()).then_some(speed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::surface::Surface;

    /// A unit square plate.
    fn plate() -> Surface {
        let c = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        Surface::plane(c.map(|(x, y)| DVec3::new(x, y, 0.0)).to_vec()).unwrap()
    }

    /// The gap over `p` h = level + (a/2)·x² − (b/6)·x³ with x = u − 1/2 (for level 0 the
    /// section across a contact beside a branch point): the contact at x = 0, the crossing at
    /// 3a/b, the gap's extremum between them at 2a/b, where h = 2a³/(3b²).
    fn cubic<'a>(p: &'a Patch<'a>, (a, b, level): (f64, f64, f64)) -> impl Fn(DVec2) -> GapAt + 'a {
        move |uv: DVec2| {
            let x = uv.x - 0.5;
            let signed = level + 0.5 * a * x * x - b / 6.0 * x * x * x;
            GapAt {
                signed,
                dist: signed.abs(),
                point: p.eval(uv),
            }
        }
    }

    /// Beside a branch point (a = 2d with d = 4.7e-4, b = 6: the extremum 3.1e-4 off the
    /// contact, its gap 1.5e-11, within tol), a search from past the gap's extremum beside the
    /// contact lands on it with `settle`, and on the contact with `settle_on_contact`.
    #[test]
    fn a_search_settled_beside_the_contact_goes_on_to_it() {
        let s = plate();
        let p = Patch::new(&s);
        for a in [9.4e-4, -9.4e-4] {
            let b = 6.0;
            let gap = cubic(&p, (a, b, 0.0));
            let h = |uv: DVec2| gap(uv).signed;
            let (beside, start) = (2.0 * a / b, DVec2::new(0.5 + 3.0 * a / b, 0.5));
            let plain = settle(&p, &h, start, DVec2::X).x - 0.5;
            assert!((plain - beside).abs() <= 1e-9, "{a}: {plain:e}");
            let (uv, g) = settle_on_contact(&p, &gap, (start, DVec2::X), 1e-9);
            assert!((uv.x - 0.5).abs() <= 1e-9, "{a}: {uv} {}", g.signed);
            assert!((uv.y - 0.5).abs() <= 1e-15);
        }
    }

    /// A contact, touching or held apart, is never taken for an extremum where |h| is largest:
    /// not where its gap is zero but for rounding (whatever the signs), nor where it is held
    /// 1e-10 apart (|h| least there); the extremum beside a branch point is, on either side.
    /// Surfaces crossing by 3e-10 (the gap's one extremum, |h| largest between two zeros)
    /// keep it: no search past it finds them touching.
    #[test]
    fn the_extremum_beside_a_contact_is_told_from_it() {
        let at = DVec3::new(2.0, 0.5, 0.0);
        for c in [1e-3, -1e-3, 1e-9, -1e-9] {
            for h in [4e-16, -4e-16, 0.0] {
                assert!(!largest(h, c, at), "{h:e} {c:e}");
            }
            assert!(!largest(1e-10 * c.signum(), c, at));
        }
        for (a, b) in [(9.4e-4, 6.0), (-9.4e-4, 6.0), (2e-4, 6.0)] {
            let x = 2.0 * a / b;
            let (h, c) = (0.5 * a * x * x - b / 6.0 * x * x * x, a - b * x);
            assert!(largest(h, c, at), "{a} {b}: {h:e} {c:e}");
        }
        let s = plate();
        let p = Patch::new(&s);
        for level in [1e-10, -3e-10] {
            let gap = cubic(&p, (1e-3, 0.0, level));
            let start = (DVec2::new(0.5003, 0.5), DVec2::X);
            let (uv, g) = settle_on_contact(&p, &gap, start, 1e-9);
            assert!((uv.x - 0.5).abs() <= 1e-9, "{level:e}: {uv}");
            assert!((g.signed - level).abs() <= 1e-15, "{level:e}: {}", g.signed);
        }
    }
}
