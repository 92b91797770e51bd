//! Where a crossing runs into a tangent contact (a branch point: the gap across the contact
//! flattens there to a triple root, its Hessian vanishes and gives no direction along), the
//! contact is traced from a step off the point, and the crossing, whose march stops beside the
//! contact, is carried on along its tangent to where it meets it.

use super::alongside::between;
use super::line::{clamp_bounded, contact_curve, delta, settle, GapAt};
use crate::geom::mesh::Polyline3;
use crate::geom::surface::refine::assemble;
use crate::geom::surface::refine::Patch;
use glam::{DVec2, DVec3};

/// [`contact_curve`] through `uv0`, or, where none is traced from there, through a point a
/// step `len` off it in one of eight directions (the first that gives one): `uv0` may be a
/// branch point, where a crossing runs into the contact and the gap across flattens to a triple
/// root, so its Hessian vanishes and gives no direction along. Not from within a step of a
/// common region.
pub(crate) fn contact_curve_near(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv0: DVec2,
    len: f64,
    tol: f64,
    chord_tol: f64,
) -> Option<Polyline3> {
    contact_curve(a, gap, uv0, len, tol, chord_tol).or_else(|| {
        let mut w = uv0;
        a.normalise(&mut w);
        let (su, sv) = a.derivs(w);
        let (lu, lv) = (su.length(), sv.length());
        if !(lu > 0.0 && lv > 0.0) {
            return None;
        }
        let steps: Vec<DVec2> = (0..8)
            .map(|k| {
                let (s, c) = (f64::from(k) * std::f64::consts::FRAC_PI_4).sin_cos();
                uv0 + DVec2::new(c * len / lu, s * len / lv)
            })
            .collect();
        // From a branch point only the two steps along the contact stay on both surfaces;
        // more lie in or at the edge of a common region (flat all across it), whose edge a
        // surface folding away tangentially would give as a contact.
        let on_both = steps.iter().filter(|q| gap(**q).dist <= tol).count();
        if on_both > 2 {
            return None;
        }
        steps.into_iter().find_map(|q| {
            if clamp_bounded(a, q) != q {
                return None;
            }
            contact_curve(a, gap, q, len, tol, chord_tol)
        })
    })
}

/// A parameter pair of `a` and the point there.
type Node = (DVec2, DVec3);

/// The open `pieces` whose ends stop within 2·`near` of one of the `contacts` carried on to it
/// where they run into it (see [`meeting`]); the end's chord to the meeting point is densified
/// on the crossing within `chord_tol`. Two ends meeting a contact within 2·`near` of each other
/// are one crossing passing through a branch point, cut there: those pieces are joined by the
/// chord between the two ends, densified likewise (their meeting points spread about the branch
/// point by about ∛tol; through them the crossing would be that long on the contact), and
/// [`through_branch_points`] then puts the solved branch point in.
pub(crate) fn run_into(
    (a, other): (&Patch, Option<&Patch>),
    gap: &dyn Fn(DVec2) -> GapAt,
    mut pieces: Vec<Polyline3>,
    contacts: &[Polyline3],
    near: f64,
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    let mid_of = |x: &Node, y: &Node| between(a, gap, x, y, tol);
    let mut meets: Vec<(usize, usize, Node, Node)> = Vec::new();
    for (i, c) in pieces.iter().enumerate() {
        if c.closed || c.points.len() < 2 {
            continue;
        }
        for end in 0..2 {
            if let Some((from, to)) = meeting((a, other), gap, c, end, contacts, near, tol) {
                meets.push((i, end, from, to));
            }
        }
    }
    let mut through: Option<(usize, usize)> = None;
    for (x, m) in meets.iter().enumerate() {
        let other = meets[x + 1..]
            .iter()
            .position(|o| o.0 != m.0 && o.3 .1.distance(m.3 .1) <= 2.0 * near);
        if let Some(y) = other {
            through = Some((x, x + 1 + y));
            break;
        }
    }
    if let Some((x, y)) = through {
        let ((i, ei, pi, bx), (j, ej, pj, by)) = (meets[x], meets[y]);
        // Through the branch point where both meetings found it (solved there, see
        // `branch_point`, they agree to its accuracy); end to end where not.
        let nodes = if bx.1.distance(by.1) <= tol {
            vec![pi, bx, pj]
        } else {
            vec![pi, pj]
        };
        let chord = assemble(&nodes, false, |n| n.1, &mid_of, tol, chord_tol);
        let (mut head, mut tail) = (pieces[i].points.clone(), pieces[j].points.clone());
        if ei == 0 {
            head.reverse();
        }
        if ej == 1 {
            tail.reverse();
        }
        let inner = chord.points.len().saturating_sub(1);
        head.extend_from_slice(&chord.points[1.min(inner)..inner]);
        head.extend(tail);
        pieces[i.min(j)] = Polyline3 {
            points: head,
            closed: false,
        };
        pieces.remove(i.max(j));
        // The joined piece's other ends, and the rest, as before.
        return run_into((a, other), gap, pieces, contacts, near, (tol, chord_tol));
    }
    for (i, end, from, to) in meets {
        let chord = assemble(&[from, to], false, |n| n.1, &mid_of, tol, chord_tol);
        let more = chord.points.into_iter().skip(1);
        let c = &mut pieces[i].points;
        if end == 0 {
            c.splice(0..0, more.rev());
        } else {
            c.extend(more);
        }
    }
    pieces
}

/// Where the `end` (0: first point, 1: last) of the crossing piece `c` runs into one of the
/// `contacts`, when it stops within 2·`near` of one: the end (with its parameters) and the
/// meeting point. The march stops beside a contact (whose double zero it could fall on), so a
/// crossing meeting a contact at a branch point ended near/sin(angle) short of it. The end's
/// tangent is carried on to where it passes within `near` of a contact's segment, no farther
/// than 4·near/sin(angle) (twice the most the end can be short of it): the crossing's last
/// points are within the tolerance of both surfaces but, the gap flattening there to a triple
/// root, up to about `near` across, so the tangent is off by that over the chord it is taken on
/// (a crossing running alongside a contact never comes within `near` of it). The meeting point
/// is solved on the true surfaces (the extremum of the gap across the contact there) or, within
/// near/sin(angle) of an open contact's end (a bounded edge the crossing runs into it at), is
/// that end. An end on a bounded edge of either surface is where the crossing ends: it runs into
/// nothing (where the two stand closer than `near`, at a coarse CHORDTOL, a crossing running
/// alongside a contact to the edge was carried along the edge to the contact's end).
fn meeting(
    (a, other): (&Patch, Option<&Patch>),
    gap: &dyn Fn(DVec2) -> GapAt,
    c: &Polyline3,
    end: usize,
    contacts: &[Polyline3],
    near: f64,
    tol: f64,
) -> Option<(Node, Node)> {
    let n = c.points.len();
    // The points from this end inwards.
    let inwards = |k: usize| c.points[if end == 0 { k } else { n - 1 - k }];
    let p = inwards(0);
    // The march stopped at the last node beyond `near`.
    if !super::near_any(p, contacts, 2.0 * near) {
        return None;
    }
    if on_bounded_edge(a, p) || other.is_some_and(|o| on_bounded_edge(o, p)) {
        return None;
    }
    // The tangent over a chord of about `near`: the last nodes can be a bisection's length
    // apart, their direction off by the tolerance over that.
    let far = (0..n).map(inwards).find(|x| x.distance(p) >= near);
    let q = far.unwrap_or(inwards(n - 1));
    let t = (p - q).normalize_or_zero();
    let hit = contacts
        .iter()
        .flat_map(|k| {
            let m = k.points.len();
            let segs = if k.closed { m } else { m.saturating_sub(1) };
            (0..segs).map(move |i| (k.points[i], k.points[(i + 1) % m]))
        })
        .filter_map(|seg| ray_meets(p, t, seg, near).map(|h| (h, seg)))
        .min_by(|x, y| x.0 .0.total_cmp(&y.0 .0));
    let from = (a.project(p, None), p);
    // The tangent is off by up to the spread of the last points over the chord (∛tol over
    // `near`: a tenth of a radian), more than the angle at which a crossing runs into a contact
    // where it ends at the other surface's edge, so the ray can pass the contact's end by:
    // an open contact's end within END_REACH·near is then the meeting point.
    let Some(((_, at, sine), seg)) = hit else {
        return contact_end(a, contacts, p, END_REACH * near, from.0).map(|to| (from, to));
    };
    let to = contact_end(a, contacts, at, near / sine, from.0)
        .or_else(|| branch_point(a, gap, a.project(at, Some(from.0)), near / sine, tol))
        .or_else(|| onto_contact(a, gap, at, seg, from.0, tol))?;
    Some((from, to))
}

/// Whether `p` (a point of `s`) lies on an edge of `s` that bounds it, to 1e-9 in parameters.
fn on_bounded_edge(s: &Patch, p: DVec3) -> bool {
    let mut uv = s.project(p, None);
    for k in 0..2 {
        if uv[k] <= 1e-9 {
            uv[k] = 0.0;
        } else if uv[k] >= 1.0 - 1e-9 {
            uv[k] = 1.0;
        }
    }
    s.bounds_at(uv)
}

/// The half-width in space of the stencils [`branch_point`] takes the gap's derivatives on: wide
/// enough that the gap's noise over its square is far under the third derivative (the Hessian's
/// noise about 1e-15/STEP², so the point is good to about 1e-10), narrow enough that the
/// differences' error (fourth order, extrapolated to sixth: STEP⁶ times the eighth derivative)
/// is smaller still. Seen: within 9e-10 of the closed form in every run of the branch tests.
const STEP: f64 = 4e-3;

/// The branch point near `uv0` (within `r` of it in space): where a crossing runs into a contact
/// the gap is zero with its gradient and, the section across flattening to a triple root, its
/// whole Hessian (all three components vanish there, and only there, along the contact: the
/// gap is w²·g(w, s) across and along the contact, g(0, s) passing through zero). Gauss–Newton
/// on the Hessian's three components by fourth-order differences, the Jacobian (the third
/// derivatives, regular where the crossing is transverse) by differences of those. Found so,
/// the point does not depend on where the crossing's last points are, which are known only to
/// about ∛tol across near it. Within 2.4e-2 of a bounded edge the stencils are narrowed across
/// it to fit (their noise grows as the square of that); None within 1.5e-3 of one, or when it
/// does not converge, leaves `r`, or the surfaces do not meet there within `tol`. Near the
/// other surface's edge they are narrowed both ways (which way its edge runs in `a`'s
/// parameters is not known), down to the same sixteenth.
fn branch_point(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv0: DVec2,
    r: f64,
    tol: f64,
) -> Option<(DVec2, DVec3)> {
    let mut w = uv0;
    a.normalise(&mut w);
    let (su, sv) = a.derivs(w);
    let (lu, lv) = (su.length(), sv.length());
    if !(lu > 0.0 && lv > 0.0 && lu.is_finite() && lv.is_finite()) {
        return None;
    }
    // Coordinates in which a unit is about STEP in space each way, or, across a bounded edge
    // nearer than the stencils reach (six units: four for the wider one, one for the
    // Jacobian's, one to move), shorter, to fit: down to a sixteenth (1.5e-3 in space from the
    // edge), nearer than which the branch point is the edge's (see `edge_meeting`).
    let mut unit = DVec2::new(STEP / lu, STEP / lv);
    for k in 0..2 {
        let room = w[k].min(1.0 - w[k]) / 6.0;
        if !a.periodic()[k] && room < unit[k] {
            if room < unit[k] / 16.0 {
                return None;
            }
            unit[k] = room;
        }
    }
    // Nor may they reach past the other surface's edge, where the gap is taken to its edge
    // (its distance then exceeds the signed gap by about how far past): narrowed to fit, in
    // quarters, down to the same sixteenth.
    let past = |x: DVec2, unit: DVec2| {
        let g = gap(uv0 + x * unit);
        g.dist - g.signed.abs() > tol
    };
    let ring = [
        (6.0, 0.0),
        (-6.0, 0.0),
        (0.0, 6.0),
        (0.0, -6.0),
        (4.5, 4.5),
        (4.5, -4.5),
        (-4.5, 4.5),
        (-4.5, -4.5),
    ];
    let mut shrunk = 1.0;
    while ring.iter().any(|&(i, j)| past(DVec2::new(i, j), unit)) {
        shrunk *= 0.75;
        if shrunk < 1.0 / 16.0 {
            return None;
        }
        unit *= 0.75;
    }
    let f = |x: DVec2| gap(uv0 + x * unit).signed;
    // On a stencil of `s` units: fourth order.
    let hess_on = |x: DVec2, s: f64| {
        let at = |i: f64, j: f64| f(x + DVec2::new(i, j) * s);
        let f0 = at(0.0, 0.0);
        let second = |p: &dyn Fn(f64) -> f64| {
            (-p(2.0) + 16.0 * p(1.0) - 30.0 * f0 + 16.0 * p(-1.0) - p(-2.0)) / (12.0 * s * s)
        };
        let cross =
            |k: f64| (at(k, k) - at(k, -k) - at(-k, k) + at(-k, -k)) / (4.0 * k * k * s * s);
        DVec3::new(
            second(&|i| at(i, 0.0)),
            (4.0 * cross(1.0) - cross(2.0)) / 3.0,
            second(&|j| at(0.0, j)),
        )
    };
    let hess = |x: DVec2| hess_on(x, 1.0);
    // The residual to zero, extrapolated to sixth order from stencils of one and two units: the
    // fourth-order one's error (STEP⁴ times the gap's sixth derivatives: 4e-9 in space where the
    // gap is taken from a plate's parameters to a patch over polar coordinates) is then under
    // its noise. The Jacobian, which only steers, stays fourth order.
    let residual = |x: DVec2| (16.0 * hess_on(x, 1.0) - hess_on(x, 2.0)) / 15.0;
    let inside = |x: DVec2| {
        let uv = uv0 + x * unit;
        (0..2).all(|k| a.periodic()[k] || (4.0 * unit[k]..=1.0 - 4.0 * unit[k]).contains(&uv[k]))
    };
    let mut x = DVec2::ZERO;
    for _ in 0..8 {
        if !inside(x + DVec2::ONE) || !inside(x - DVec2::ONE) {
            return None;
        }
        let h0 = residual(x);
        let ju = 0.5 * (hess(x + DVec2::X) - hess(x - DVec2::X));
        let jv = 0.5 * (hess(x + DVec2::Y) - hess(x - DVec2::Y));
        let step = gauss_newton((ju, jv), h0)?;
        x += step;
        if (x * (STEP * shrunk)).length() > r {
            return None;
        }
        // The components are linear in x near the point but for their noise (about 1e-15 of
        // STEP³ here): a step this short has reached it, within 1e-10 or so in space.
        // Only where the whole Hessian vanishes: where it does not (a crossing meeting the
        // contact tangentially), Gauss–Newton settles at its least, not at zero.
        if step.length() <= 1e-6 && h0.length() <= 1e-4 * (ju.length() + jv.length()) {
            x += gauss_newton((ju, jv), averaged(&residual, x))?;
            let mut uv = uv0 + x * unit;
            a.normalise(&mut uv);
            let g = gap(uv);
            return (g.dist <= tol).then_some((uv, g.point));
        }
    }
    None
}

/// The Gauss–Newton step taking the Hessian components `h0` to zero, their derivatives along
/// the two parameters `ju` and `jv`; None where those are (nearly) parallel.
fn gauss_newton((ju, jv): (DVec3, DVec3), h0: DVec3) -> Option<DVec2> {
    let (m11, m12, m22) = (ju.dot(ju), ju.dot(jv), jv.dot(jv));
    let det = m11 * m22 - m12 * m12;
    if !(det > 1e-12 * m11 * m22 && det.is_finite()) {
        return None;
    }
    let (b1, b2) = (-ju.dot(h0), -jv.dot(h0));
    Some(DVec2::new(m22 * b1 - m12 * b2, m11 * b2 - m12 * b1) / det)
}

/// How many pairs of stencils [`averaged`] takes.
const POLISH_PAIRS: usize = 8;

/// `residual` at the converged branch point `x` (in stencil units), averaged over
/// [`POLISH_PAIRS`] pairs of stencils shifted a ten-thousandth of a unit either way. Converged,
/// the point is only as good as the residual's noise over its slope: the gap's rounding (about
/// 4e-16, each value a different one) over STEP³ times the gap's third derivatives, and the
/// point moved by up to 2e-9 in space between starts 1e-5 apart (the patch against the cone,
/// where the crossing runs into the contact at a slope of 0.25 in d). The rounding at shifted
/// stencils is another; the residual's change is linear in the shift to about 1e-8 of the
/// slope (the shift squared), and cancels within a pair: the mean's noise is a fourth of one
/// stencil's, and the point within about 2e-10. Only where a branch point has been solved,
/// which sixteen residuals (416 gap values) cost once more.
fn averaged(residual: &dyn Fn(DVec2) -> DVec3, x: DVec2) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for k in 0..POLISH_PAIRS {
        let t = std::f64::consts::PI * (k as f64 + 0.5) / POLISH_PAIRS as f64;
        let o = DVec2::new(t.cos(), t.sin()) * 1e-4;
        sum += residual(x + o) + residual(x - o);
    }
    sum / (2 * POLISH_PAIRS) as f64
}

/// How far (in `near`s) from a crossing's end, one whose tangent passes by every contact, an
/// open contact's end is taken for where it runs in: 2·near/sine for crossings at 1/8 or steeper.
const END_REACH: f64 = 16.0;

/// The end of an open one of `contacts` within `r` of `at`, with its parameters (from `near`).
fn contact_end(
    a: &Patch,
    contacts: &[Polyline3],
    at: DVec3,
    r: f64,
    near: DVec2,
) -> Option<(DVec2, DVec3)> {
    let ends = contacts
        .iter()
        .filter(|k| !k.closed && !k.points.is_empty());
    let end = ends
        .flat_map(|k| [k.points[0], k.points[k.points.len() - 1]])
        .filter(|e| e.distance(at) <= r)
        .min_by(|x, y| x.distance(at).total_cmp(&y.distance(at)))?;
    Some((a.project(end, Some(near)), end))
}

/// The point of the contact beside `at` on the true surfaces: the extremum of the gap across the
/// contact's segment `seg` (through `at`), when the surfaces meet there within `tol`.
fn onto_contact(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    at: DVec3,
    (x, y): (DVec3, DVec3),
    near: DVec2,
    tol: f64,
) -> Option<(DVec2, DVec3)> {
    let (ux, uy) = (a.project(x, Some(near)), a.project(y, Some(near)));
    let across = delta(a, ux, uy).perp().try_normalize()?;
    let h = |uv: DVec2| gap(uv).signed;
    let mut uv = settle(a, &h, a.project(at, Some(near)), across);
    a.normalise(&mut uv);
    let g = gap(uv);
    (g.dist <= tol).then_some((uv, g.point))
}

/// Where the ray `p + s·t` (s > 0, no farther than 4·`within`/sine) passes within `within` of
/// the segment `xy`: s, the segment's point there, and the sine of their angle.
fn ray_meets(p: DVec3, t: DVec3, (x, y): (DVec3, DVec3), within: f64) -> Option<(f64, DVec3, f64)> {
    let e = y - x;
    let (a, b, c) = (t.dot(t), t.dot(e), e.dot(e));
    let w = p - x;
    let (d, f) = (t.dot(w), e.dot(w));
    let den = a * c - b * b;
    if den.is_nan() || den <= 0.0 {
        return None;
    }
    let s = (b * f - c * d) / den;
    let r = ((a * f - b * d) / den).clamp(0.0, 1.0);
    let at = x + e * r;
    let on = p + t * s;
    let sine = (den / (a * c)).sqrt();
    (s > 0.0 && s * sine <= 4.0 * within && on.distance(at) <= within).then_some((s, at, sine))
}

/// The crossing `pieces` made to pass through (or end at) the branch points where they meet the
/// `contacts` away from a bounded edge, and the contacts through them. Where a piece comes
/// within `near` of a contact (or, between points farther apart, within half their spacing),
/// the branch point there is solved on the Hessian ([`branch_point`]); where one is found, the
/// points of the piece and of the contact within `near` of it are replaced by it, the chords to
/// it densified within `chord_tol`. The points there (refined onto both surfaces, joined across
/// the contact end to end, or settled across the contact where it flattens to an inflection)
/// are known only to about ∛tol across, the gap flattening to a triple root; the solved point
/// is good to about 1e-9 however the crossing was found: in one piece from the seeding meshes,
/// or joined by [`run_into`] or `alongside::join_ends`.
pub(crate) fn through_branch_points(
    (a, other): (&Patch, Option<&Patch>),
    gap: &dyn Fn(DVec2) -> GapAt,
    mut pieces: Vec<Polyline3>,
    contacts: &mut [Polyline3],
    near: f64,
    (tol, chord_tol): (f64, f64),
) -> (Vec<Polyline3>, Vec<Node>) {
    let mut found: Vec<Node> = Vec::new();
    {
        let lines: Vec<&Polyline3> = contacts.iter().filter(|k| k.points.len() >= 2).collect();
        if lines.is_empty() {
            return (pieces, found);
        }
        let mid_of = |x: &Node, y: &Node| between(a, gap, x, y, tol);
        for c in &mut pieces {
            // From the last, so the earlier indices stay where they were.
            for i in beside_contacts(&c.points, &lines, near).into_iter().rev() {
                let Some(b) = branch_near(a, gap, &c.points, i, &lines, near, tol) else {
                    continue;
                };
                let segs = i.saturating_sub(1)..(i + 1).min(c.points.len() - 1);
                let spliced = splice_at(a, c, segs, b, near, &mid_of, (tol, chord_tol));
                if let Some(q) = spliced {
                    c.points = q;
                    found.push(b);
                }
            }
        }
    }
    for c in &mut pieces {
        let Some(b) = edge_meeting((a, other), gap, c, &contacts_of(contacts), near, tol) else {
            continue;
        };
        let n = c.points.len();
        let segs = if b.1.distance(c.points[0]) < b.1.distance(c.points[n - 1]) {
            0..1
        } else {
            n - 2..n - 1
        };
        let mid_of = |x: &Node, y: &Node| between(a, gap, x, y, tol);
        if let Some(q) = splice_at(a, c, segs, b, near, &mid_of, (tol, chord_tol)) {
            c.points = q;
            found.push(b);
        }
    }
    // Along the contact the plain midpoint in parameters: chords this short are on it to their
    // curvature times their square, and settled across near a branch point they would zigzag.
    let on_contact = |x: &Node, y: &Node| {
        let m = crate::geom::surface::refine::mid(a, x.0, y.0);
        let g = gap(m);
        (g.dist <= tol).then_some((m, g.point))
    };
    for &b in &found {
        let at = contacts
            .iter()
            .enumerate()
            .filter(|(_, k)| k.points.len() >= 2)
            .map(|(j, k)| (j, to_contacts(b.1, &[k])))
            .min_by(|x, y| x.1.total_cmp(&y.1));
        let Some((j, _)) = at else { continue };
        let segs = 0..contacts[j].points.len() - 1;
        let spliced = splice_at(
            a,
            &contacts[j],
            segs,
            b,
            near,
            &on_contact,
            (tol, chord_tol),
        );
        if let Some(q) = spliced {
            contacts[j].points = q;
        }
    }
    (pieces, found)
}

/// The `contacts` that are lines (two points or more).
fn contacts_of(contacts: &[Polyline3]) -> Vec<&Polyline3> {
    contacts.iter().filter(|k| k.points.len() >= 2).collect()
}

/// The branch point on a bounded edge of `a` (or of `other`, the surface the gap is measured
/// to, where that is one) where an end of the open crossing `c`, on that edge, meets one of the
/// `contacts` (within `near`): the gap along the edge has a triple root there, so its second
/// derivative along the edge a simple one, solved by Newton (differences of fourth order
/// extrapolated to sixth, on stencils along the edge). The ends, found where the gap across the
/// contact is within the tolerance, are known only to about ∛tol there. On `other`'s edge (no
/// parameter edge of `a`) the gap is taken from `other`'s parameters to `a`.
fn edge_meeting(
    (a, other): (&Patch, Option<&Patch>),
    gap: &dyn Fn(DVec2) -> GapAt,
    c: &Polyline3,
    contacts: &[&Polyline3],
    near: f64,
    tol: f64,
) -> Option<Node> {
    let n = c.points.len();
    if c.closed || n < 2 || contacts.is_empty() {
        return None;
    }
    let on_edge = |s: &Patch, uv: DVec2| {
        (0..2).find(|&k| !s.periodic()[k] && (uv[k] <= 1e-9 || uv[k] >= 1.0 - 1e-9))
    };
    [c.points[0], c.points[n - 1]].into_iter().find_map(|p| {
        if to_contacts(p, contacts) > near {
            return None;
        }
        let uv = a.project(p, None);
        let b = if let Some(k) = on_edge(a, uv) {
            edge_branch_point(a, gap, uv, k, tol)?
        } else {
            let o = other?;
            let uo = o.project(p, None);
            let k = on_edge(o, uo)?;
            let warm = std::cell::Cell::new(None);
            let back = |w: DVec2| super::pair_gap(o, a, &warm, w);
            let (_, q) = edge_branch_point(o, &back, uo, k, tol)?;
            let mut ua = a.project(q, Some(uv));
            a.normalise(&mut ua);
            let g = gap(ua);
            (g.dist <= tol).then_some((ua, g.point))?
        };
        (b.1.distance(p) <= 16.0 * near && to_contacts(b.1, contacts) <= near).then_some(b)
    })
}

/// The root of the gap's second derivative along the edge of `a` where parameter `k` is fixed
/// (at `uv0`'s), from `uv0`, where the gap there is within `tol`.
fn edge_branch_point(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    uv0: DVec2,
    k: usize,
    tol: f64,
) -> Option<Node> {
    let j = 1 - k;
    let (su, sv) = a.derivs(uv0);
    let speed = if j == 0 { su } else { sv }.length();
    if !(speed > 0.0 && speed.is_finite()) {
        return None;
    }
    let h = STEP / speed;
    let at = |t: f64| {
        let mut uv = uv0;
        uv[j] = t;
        uv
    };
    let f = |t: f64| gap(at(t)).signed;
    let second = |t: f64, s: f64| {
        let (x, e) = (s * h, |m: f64| f(t + m * s * h));
        (-e(2.0) + 16.0 * e(1.0) - 30.0 * f(t) + 16.0 * e(-1.0) - e(-2.0)) / (12.0 * x * x)
    };
    let periodic = a.periodic()[j];
    let mut t = uv0[j];
    for _ in 0..8 {
        if !periodic && !(5.0 * h..=1.0 - 5.0 * h).contains(&t) {
            return None;
        }
        let g2 = (16.0 * second(t, 1.0) - second(t, 2.0)) / 15.0;
        let g3 = (second(t + h, 1.0) - second(t - h, 1.0)) / (2.0 * h);
        if !(g3.abs() > 0.0 && g3.is_finite() && g2.is_finite()) {
            return None;
        }
        let step = g2 / g3;
        t -= step;
        if (t - uv0[j]).abs() > 4.0 * h {
            return None;
        }
        if step.abs() <= 1e-6 * h {
            let mut uv = at(t);
            a.normalise(&mut uv);
            let g = gap(uv);
            return (g.dist <= tol).then_some((uv, g.point));
        }
    }
    None
}

/// The distance from `p` to the nearest segment of `contacts`.
fn to_contacts(p: DVec3, contacts: &[&Polyline3]) -> f64 {
    contacts
        .iter()
        .flat_map(|k| k.segments())
        .map(|(x, y)| to_segment(p, x, y))
        .fold(f64::INFINITY, f64::min)
}

/// The distance from `p` to the segment `xy`.
pub(super) fn to_segment(p: DVec3, x: DVec3, y: DVec3) -> f64 {
    let d = y - x;
    let f = ((p - x).dot(d) / d.length_squared().max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
    p.distance(x + d * f)
}

/// The longest distance from `points[i]` to its neighbours.
fn spacing(points: &[DVec3], i: usize) -> f64 {
    [i.checked_sub(1), (i + 1 < points.len()).then_some(i + 1)]
        .into_iter()
        .flatten()
        .map(|j| points[j].distance(points[i]))
        .fold(0.0, f64::max)
}

/// In each run of `points` within `near` of `contacts` (or within half the spacing to the next
/// or last point, where that is longer: a chord can pass the contact far from its ends), the
/// index of the one nearest, in order.
fn beside_contacts(points: &[DVec3], contacts: &[&Polyline3], near: f64) -> Vec<usize> {
    let mut out: Vec<usize> = Vec::new();
    let mut run: Option<(usize, f64)> = None;
    for (k, p) in points.iter().enumerate() {
        let d = to_contacts(*p, contacts);
        if d <= near.max(0.5 * spacing(points, k)) {
            run = match run {
                Some((i, e)) if e <= d => Some((i, e)),
                _ => Some((k, d)),
            };
        } else if let Some((i, _)) = run.take() {
            out.push(i);
        }
    }
    out.extend(run.map(|r| r.0));
    out
}

/// The branch point solved from `points[i]` (beside one of the `contacts`), or where none is
/// found from there, from the point of the segments next to i nearest the contacts (sampled: a
/// chord of a coarse CHORDTOL can pass the branch point half its length from its ends), when it
/// lies on a contact (within `near`) and beside the points (within `near` of a segment next to
/// i).
fn branch_near(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    points: &[DVec3],
    i: usize,
    contacts: &[&Polyline3],
    near: f64,
    tol: f64,
) -> Option<Node> {
    let reach = 16.0 * near + spacing(points, i);
    let n = points.len();
    let from = |q: DVec3| branch_point(a, gap, a.project(q, None), reach, tol);
    let b = from(points[i]).or_else(|| {
        let segs = i.saturating_sub(1)..(i + 1).min(n - 1);
        let samples = segs.flat_map(|j| (1..32).map(move |k| (j, f64::from(k) / 32.0)));
        let at = samples.map(|(j, f)| points[j].lerp(points[j + 1], f));
        let q =
            at.min_by(|x, y| to_contacts(*x, contacts).total_cmp(&to_contacts(*y, contacts)))?;
        (q.distance(points[i]) > near).then(|| from(q)).flatten()
    })?;
    let beside = (i.saturating_sub(1)..(i + 1).min(n - 1))
        .any(|j| to_segment(b.1, points[j], points[j + 1]) <= near);
    (beside && to_contacts(b.1, contacts) <= near).then_some(b)
}

/// `c`'s points with `b` put in on the nearest of its segments `segs` (segment j from point j
/// to j + 1), and the points within `near` of it left out, the chords to it densified within
/// `chord_tol` by `mid_of`; None where the points left out would run round a loop's start.
fn splice_at(
    a: &Patch,
    c: &Polyline3,
    segs: std::ops::Range<usize>,
    b: Node,
    near: f64,
    mid_of: &dyn Fn(&Node, &Node) -> Option<Node>,
    (tol, chord_tol): (f64, f64),
) -> Option<Vec<DVec3>> {
    let p = &c.points;
    let n = p.len();
    let seg = |j: &usize| to_segment(b.1, p[*j], p[*j + 1]);
    let s = segs.min_by(|x, y| seg(x).total_cmp(&seg(y)))?;
    let (mut lo, mut hi) = (s + 1, s + 1);
    while lo > 0 && p[lo - 1].distance(b.1) < near {
        lo -= 1;
    }
    while hi < n && p[hi].distance(b.1) < near {
        hi += 1;
    }
    if c.closed && (lo == 0 || hi == n) {
        return None;
    }
    let node = |q: DVec3| (a.project(q, Some(b.0)), q);
    let mut nodes = Vec::with_capacity(3);
    nodes.extend((lo > 0).then(|| node(p[lo - 1])));
    nodes.push(b);
    nodes.extend((hi < n).then(|| node(p[hi])));
    // Within `near` of the branch point the gap across the crossing flattens (its slope the
    // square of the distance to the point), so a midpoint there is placed by the gap's rounding,
    // up to far off the crossing, and each chord to it would draw another nearer still (seen:
    // 3.2e-6 off at 8.6e-6 from it). The points within `near` are replaced for that reason; a
    // chord to the solved point no longer than `near` is left as it is (its sagitta is near²
    // times the crossing's curvature over 8).
    let settled = |x: &Node, y: &Node| {
        let to_b = x.1 == b.1 || y.1 == b.1;
        if to_b && x.1.distance(y.1) <= near {
            return None;
        }
        mid_of(x, y)
    };
    let chord = assemble(&nodes, false, |x| x.1, &settled, tol, chord_tol);
    let mut out = p[..lo.saturating_sub(1)].to_vec();
    out.extend(chord.points);
    out.extend_from_slice(p.get(hi + 1..).unwrap_or(&[]));
    Some(out)
}
