//! The crossing through a solved branch point, marched out of it. Beside a branch point the two
//! surfaces are within the tolerance of each other over a band about the contact, and the seed
//! curves refined into that band leave points there that lie on neither curve (stubs, copies,
//! points placed by the gap's rounding rather than on the crossing). The branch point itself is
//! known to about 1e-10 (see `branch::branch_point`), and the crossing's two directions there
//! follow from the gap's cubic form; marched out of it both ways on the true surfaces, each node
//! the root of the gap across the march (bracketed by its change of sign, which the contact's
//! double zero beside it does not have), the crossing no longer depends on the seed.

use super::alongside::{between, changes_sign, join_ends, march};
use super::branch::to_segment;
use super::line::{delta, GapAt};
use super::{near_any, off_curves};
use crate::geom::mesh::Polyline3;
use crate::geom::surface::refine::{assemble, Patch};
use glam::{DVec2, DVec3};

/// A parameter pair of `a` and the point there.
type Node = (DVec2, DVec3);

/// The half-width in space of the stencils the gap's third derivatives are taken on at a branch
/// point (as `branch::STEP`: there the gap is a cubic, about STEP³ on them, far over its noise).
const STEP: f64 = 4e-3;

/// The crossing `pieces` with the crossing through each solved branch point in `found` marched
/// out of it both ways (to a bounded edge or to where it falls onto a contact), in steps of
/// `len`, densified within `chord_tol`; the pieces' stretches along it go, and so do pieces
/// lying wholly within `near` of it and of the `contacts` (what the seed left in the band).
/// Runs only where a branch point was solved: elsewhere nothing is evaluated.
pub(crate) fn march_out(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    mut pieces: Vec<Polyline3>,
    (contacts, found): (&[Polyline3], &[Node]),
    (len, near): (f64, f64),
    (tol, chord_tol): (f64, f64),
) -> Vec<Polyline3> {
    let mut done: Vec<DVec3> = Vec::new();
    for &b in found {
        if done.iter().any(|d| d.distance(b.1) <= near) {
            continue;
        }
        let Some(dirs) = directions(a, gap, b, contacts, &pieces, (near, tol)) else {
            continue;
        };
        // Beside a contact the search across can fall onto its double zero: a node there is
        // kept only where the gap changes sign across it (as `Crossings::extend` does).
        let stop = |uv: DVec2, t: DVec2, p: DVec3| {
            near_any(p, contacts, near) && !changes_sign(a, gap, uv, t, near, tol)
        };
        let mut back = march(a, gap, (b.0, dirs[0]), len, tol, &stop);
        back.reverse();
        back.push(b);
        if let Some(&d) = dirs.get(1) {
            back.extend(march(a, gap, (b.0, d), len, tol, &stop));
        }
        if back.len() < 2 {
            continue;
        }
        // Within `near` of the branch point the gap across the crossing flattens (its slope the
        // square of the distance to it) and a midpoint there is placed by its rounding: the
        // chords to the point no longer than `near` are left as they are (see `splice_at`).
        let mid_of = |x: &Node, y: &Node| {
            let to_b = x.1 == b.1 || y.1 == b.1;
            if to_b && x.1.distance(y.1) <= near {
                return None;
            }
            between(a, gap, x, y, tol)
        };
        let crossing = assemble(&back, false, |n| n.1, &mid_of, tol, chord_tol);
        let line = std::slice::from_ref(&crossing);
        let mut rest = Vec::with_capacity(pieces.len() + 1);
        for c in pieces {
            let along: Vec<bool> = c.points.iter().map(|p| near_any(*p, line, near)).collect();
            let banded = |k: usize| along[k] || in_band(a, gap, c.points[k], contacts, near, tol);
            if (0..along.len()).all(banded) {
                continue;
            }
            if along.contains(&true) {
                rest.extend(off_curves(&c, line, near).into_iter().map(|x| x.0));
            } else {
                rest.push(c);
            }
        }
        rest.push(crossing);
        // Where a march stopped short of an edge (falling onto a contact), the stretches of the
        // pieces left beyond it carry the crossing on.
        pieces = join_ends(a, gap, rest, 2.0 * len, tol, chord_tol);
        done.push(b.1);
    }
    pieces
}

/// The crossing's two directions (in `a`'s parameters) out of the branch point `b`. Across the
/// contact (q) and along it (p) the gap there is q²·(α·q + β·p) to third order, so the crossing
/// runs along α·q + β·p = 0: α and β from the third differences g_qqq = 6α and g_pqq = 2β, the
/// contact's direction from [`contact_tangent`]. Where the stencils do not fit (a branch point on
/// or by an edge of either surface), the way the piece through `b` leaves it, 4·`near` out.
fn directions(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    b: Node,
    contacts: &[Polyline3],
    pieces: &[Polyline3],
    (near, tol): (f64, f64),
) -> Option<Vec<DVec2>> {
    let cubic = cubic_direction(a, gap, b, contacts, tol);
    let piece = piece_directions(a, b, pieces, near);
    // Where the piece through the branch point gives the way too, the form must agree with it
    // (seen: plate ∩ patch d = −0.3..0.1 at CHORDTOL 1e-2, the form about 4.5° off with the
    // contact's direction from its nearest chord); where not,
    // the piece's way, 4·near out and so off the band, is taken.
    match (cubic, piece) {
        (Some(d), Some(p)) if p.iter().any(|x| x.dot(d).abs() >= 0.9) => Some(vec![-d, d]),
        (Some(d), None) => Some(vec![-d, d]),
        (_, p) => p,
    }
}

/// See [`directions`].
fn cubic_direction(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    b: Node,
    contacts: &[Polyline3],
    tol: f64,
) -> Option<DVec2> {
    let (su, sv) = a.derivs(b.0);
    let (lu, lv) = (su.length(), sv.length());
    if !(lu > 0.0 && lv > 0.0 && lu.is_finite() && lv.is_finite()) {
        return None;
    }
    let unit = DVec2::new(STEP / lu, STEP / lv);
    let e1 = (contact_tangent(a, b, contacts)? / unit).try_normalize()?;
    let e2 = e1.perp();
    let at = |p: f64, q: f64| {
        let uv = b.0 + (e1 * p + e2 * q) * unit;
        let inside = (0..2).all(|k| a.periodic()[k] || (0.0..=1.0).contains(&uv[k]));
        let g = inside.then(|| gap(uv))?;
        (g.signed.is_finite() && g.dist - g.signed.abs() <= tol).then_some(g.signed)
    };
    let across = |p: f64| Some(at(p, 1.0)? - 2.0 * at(p, 0.0)? + at(p, -1.0)?);
    let g_qqq = 0.5 * (at(0.0, 2.0)? - 2.0 * at(0.0, 1.0)? + 2.0 * at(0.0, -1.0)? - at(0.0, -2.0)?);
    let g_pqq = 0.5 * (across(1.0)? - across(-1.0)?);
    ((e1 * g_qqq - e2 * (3.0 * g_pqq)) * unit).try_normalize()
}

/// The contact's tangent (in `a`'s parameters) at the branch point `b`. The crossing leaves the
/// contact at a small angle (seen 0.127 rad: plate ∩ patch d = −0.3..0.1), and an error ε in the
/// contact's direction moves the form's β by 3·α·ε: the direction of a chord from `b` (half
/// its turn off the tangent, 0.025 rad on a contact densified within 1e-2) took the march out
/// onto the contact. Where `b` is a point of a contact (spliced in by `through_branch_points`),
/// the derivative through it and its two neighbours (exact to second order for unequal chords);
/// else the nearest segment's direction.
fn contact_tangent(a: &Patch, b: Node, contacts: &[Polyline3]) -> Option<DVec2> {
    let at = |p: DVec3| delta(a, b.0, a.project(p, Some(b.0)));
    for k in contacts {
        let m = k.points.len();
        let Some(i) = k.points.iter().position(|p| *p == b.1) else {
            continue;
        };
        let (prev, next) = match (i, k.closed) {
            (0, true) => (m - 1, 1 % m),
            (_, true) => (i - 1, (i + 1) % m),
            (0, false) => continue,
            (_, false) if i + 1 >= m => continue,
            _ => (i - 1, i + 1),
        };
        let (x, y) = (k.points[prev], k.points[next]);
        let (h1, h2) = (x.distance(b.1), y.distance(b.1));
        if !(h1 > 0.0 && h2 > 0.0) {
            continue;
        }
        let t = at(y) * (h1 / (h2 * (h1 + h2))) - at(x) * (h2 / (h1 * (h1 + h2)));
        return t.try_normalize();
    }
    let (x, y) = nearest_segment(b.1, contacts)?;
    Some(delta(a, a.project(x, Some(b.0)), a.project(y, Some(b.0))))
}

/// See [`directions`].
fn piece_directions(a: &Patch, b: Node, pieces: &[Polyline3], near: f64) -> Option<Vec<DVec2>> {
    let c = pieces.iter().find(|c| c.points.contains(&b.1))?;
    let i = c.points.iter().position(|p| *p == b.1)?;
    let out = |k: usize| {
        let q = c.points[k];
        let d = delta(a, b.0, a.project(q, Some(b.0)));
        (q.distance(b.1) >= 4.0 * near).then_some(d.try_normalize()?)
    };
    let before = (0..i).rev().find_map(out);
    let after = (i + 1..c.points.len()).find_map(out);
    match (before, after) {
        (Some(x), Some(y)) => Some(vec![x, y]),
        // A piece ending at the branch point (on an edge, or where the seed stopped): the one
        // way it is known to run (the other way lies past an edge, or in the band).
        (Some(x), None) => Some(vec![x]),
        (None, Some(y)) => Some(vec![y]),
        (None, None) => None,
    }
}

/// Whether `p` (within the tolerance of both surfaces) lies on a contact (within `near`) or in
/// the band beside one where the surfaces stay within the tolerance but neither curve runs:
/// the gap keeps its sign across `p` (looked at across the contact, no farther than halfway to
/// it, so the contact's double zero is not passed). Near a branch point that band is about
/// ∛tol wide, far wider than `near` (seen: a 7-point stub 2.4e-4..8.8e-4 off the contact,
/// `near` 2.2e-4); a crossing point there is one where the gap changes sign.
fn in_band(
    a: &Patch,
    gap: &dyn Fn(DVec2) -> GapAt,
    p: DVec3,
    contacts: &[Polyline3],
    near: f64,
    tol: f64,
) -> bool {
    if near_any(p, contacts, near) {
        return true;
    }
    let Some((x, y)) = nearest_segment(p, contacts) else {
        return false;
    };
    let uv = a.project(p, None);
    let along = delta(a, a.project(x, Some(uv)), a.project(y, Some(uv)));
    let off = to_segment(p, x, y);
    !changes_sign(a, gap, uv, along, 0.5 * off, tol)
}

/// The segment of `contacts` nearest `p`.
fn nearest_segment(p: DVec3, contacts: &[Polyline3]) -> Option<(DVec3, DVec3)> {
    let to = |s: &(DVec3, DVec3)| to_segment(p, s.0, s.1);
    contacts
        .iter()
        .flat_map(|k| k.segments())
        .min_by(|x, y| to(x).total_cmp(&to(y)))
}

#[cfg(test)]
mod tests {
    use super::contact_tangent;
    use crate::geom::mesh::Polyline3;
    use crate::geom::surface::refine::Patch;
    use crate::geom::surface::Surface;
    use glam::DVec3;

    #[test]
    fn the_contacts_tangent_at_a_branch_point_between_unequal_chords() {
        // The circle r = 2 on the plate z = 0 through θ = 1.129, 1.178 (the branch point) and
        // 1.203, as plate ∩ patch d = −0.3..0.1 at CHORDTOL 1e-2 left it: either chord's
        // direction is 0.012..0.025 rad off the tangent, the crossing 0.127 off it.
        let plate = Surface::plane(vec![
            DVec3::new(-4.0, -4.0, 0.0),
            DVec3::new(4.0, -4.0, 0.0),
            DVec3::new(4.0, 4.0, 0.0),
            DVec3::new(-4.0, 4.0, 0.0),
        ])
        .unwrap();
        let a = Patch::new(&plate);
        let on = |th: f64| DVec3::new(2.0 * th.cos(), 2.0 * th.sin(), 0.0);
        let contact = Polyline3 {
            points: [1.0, 1.129, 1.178, 1.203, 1.3].map(on).to_vec(),
            closed: false,
        };
        let b = (a.project(on(1.178), None), on(1.178));
        let t = contact_tangent(&a, b, std::slice::from_ref(&contact)).unwrap();
        let along = a.project(
            b.1 + DVec3::new(-1.178f64.sin(), 1.178f64.cos(), 0.0) * 1e-3,
            None,
        );
        let want = (along - b.0).normalize();
        let off = t.normalize().perp_dot(want).abs();
        assert!(off < 1e-3, "{off:e} rad off the tangent");
    }
}
