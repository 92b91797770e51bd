//! Intersection curves refined on the true surfaces: the mesh result only seeds them.
//!
//! Every seed point is carried onto both parametric surfaces by Newton iteration on
//! `S1(u1, v1) − S2(u2, v2) = 0` (three equations, four unknowns: the minimum-norm step
//! `−Jᵀ(JJᵀ + λI)⁻¹r`, damped near tangency), or on `n·(S(u, v) − p) = 0` for a plane section,
//! until the residual is below the tolerance. A parameter reaching the edge of its domain is held
//! there (the point then lies on the boundary curve) and a periodic one wraps, so seams and
//! boundary edges keep their hits; an open seed's end on a mesh's boundary is held on that edge
//! from the start, so the curve ends on it. Consecutive points are then densified — midpoints
//! refined the same way — until the polyline is within the chord tolerance of the curve.

use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};

mod across;
mod bracket;
mod newton;
mod patch;
mod plane_across;
use across::Across;
use newton::newton_pair_mid;
use newton::{min_norm, newton_pair_held, newton_plane_held};
pub(crate) use newton::{newton_pair, newton_plane, Node};
pub(crate) use patch::Patch;

/// The parameter midway between two, the short way round in a periodic direction.
pub(crate) fn mid(p: &Patch, a: DVec2, b: DVec2) -> DVec2 {
    let mut m = 0.5 * (a + b);
    for k in 0..2 {
        if p.periodic()[k] && (a[k] - b[k]).abs() > 0.5 {
            m[k] = (m[k] + 0.5).rem_euclid(1.0);
        }
    }
    m
}

/// Refined nodes joined into a polyline, each segment densified: a midpoint (from `mid`, None
/// when it does not converge) is inserted while it lies farther than `chord_tol` from the chord.
pub(crate) fn assemble<N: Copy>(
    nodes: &[N],
    closed: bool,
    pos: impl Fn(&N) -> DVec3 + Copy,
    mid: &impl Fn(&N, &N) -> Option<N>,
    tol: f64,
    chord_tol: f64,
) -> Polyline3 {
    assemble_loose(nodes, closed, pos, mid, tol, chord_tol).0
}

/// [`assemble`], with the chords left loose: those whose midpoint did not refine between their
/// ends (None, or it fell beyond them), so nothing says they are within `chord_tol` of the
/// curve. A seed curve that cuts across a part of the curve thinner than its cells (the tip of
/// a lens) leaves such a chord; see `contact::mend_section`.
pub(crate) fn assemble_loose<N: Copy>(
    nodes: &[N],
    closed: bool,
    pos: impl Fn(&N) -> DVec3 + Copy,
    mid: &impl Fn(&N, &N) -> Option<N>,
    tol: f64,
    chord_tol: f64,
) -> (Polyline3, Vec<[DVec3; 2]>) {
    let m = nodes.len();
    let segs = if closed { m } else { m.saturating_sub(1) };
    let mut out = Dense {
        points: Vec::with_capacity(m * 2),
        nodes: Vec::with_capacity(m * 2),
        loose: Vec::new(),
    };
    for i in 0..m {
        out.points.push(pos(&nodes[i]));
        out.nodes.push(nodes[i]);
        if i < segs {
            let ends = (nodes[i], nodes[(i + 1) % m]);
            densify(ends, pos, mid, (tol, chord_tol), 0, &mut out);
        }
    }
    let closed = closed && m >= 3;
    let points = dedup(&out, closed, (pos, mid), (tol, chord_tol));
    (Polyline3 { points, closed }, out.loose)
}

/// The points of `d` less those within `tol` of the last one kept (refined twice over, as
/// from seed points either side of a seam); a chord that now spans a dropped point is checked
/// again, so that densifying vouches for it too (see [`densify`]).
fn dedup<N: Copy>(
    d: &Dense<N>,
    closed: bool,
    (pos, mid): (impl Fn(&N) -> DVec3 + Copy, &impl Fn(&N, &N) -> Option<N>),
    (tol, chord_tol): (f64, f64),
) -> Vec<DVec3> {
    // The indices kept, each with whether points after it were dropped.
    let mut keep: Vec<(usize, bool)> = Vec::with_capacity(d.points.len());
    for (i, p) in d.points.iter().enumerate() {
        match keep.last_mut() {
            Some((j, dropped)) if d.points[*j].distance(*p) <= tol => *dropped = true,
            _ => keep.push((i, false)),
        }
    }
    let k = keep.len();
    for (x, &(i, dropped)) in keep.iter().enumerate() {
        let next = if x + 1 < k {
            Some(keep[x + 1].0)
        } else {
            closed.then_some(keep[0].0)
        };
        if let (true, Some(j)) = (dropped, next) {
            let (n0, n1) = (d.nodes[i], d.nodes[j]);
            let (p0, p1) = (pos(&n0), pos(&n1));
            if mid(&n0, &n1).is_some_and(|m| sure((p0, p1), pos(&m), chord_tol)) {
                super::loose::vouch(p0, p1);
            }
        }
    }
    keep.into_iter().map(|(i, _)| d.points[i]).collect()
}

/// Whether the chord `p0p1`, whose midpoint refined onto the curve is `pm`, stands for the
/// curve within `chord_tol`: short enough that its ends (points of the curve) hold it there, or
/// the curve passes within `chord_tol` of it about its middle. A midpoint that lands near an
/// end (a parameterisation far from even there) says little of the chord's own.
fn sure((p0, p1): (DVec3, DVec3), pm: DVec3, chord_tol: f64) -> bool {
    if super::loose::short(p0, p1, chord_tol) {
        return true;
    }
    let chord = p1 - p0;
    let off = (pm - p0).cross(chord).length() / chord.length();
    let along = (pm - p0).dot(chord) / chord.length_squared();
    off <= chord_tol && (0.25..=0.75).contains(&along)
}

/// The points of a curve being densified, the nodes they are at, and its loose chords (see
/// [`assemble_loose`]).
struct Dense<N> {
    points: Vec<DVec3>,
    nodes: Vec<N>,
    loose: Vec<[DVec3; 2]>,
}

/// Puts the points between the nodes `n0` and `n1` (not themselves) that bring every chord
/// within `chord_tol` of the curve, where their midpoints refine between their ends: the
/// chords it can say so of are vouched for (see `loose::vouch`), the others are left to
/// `loose::settle` (those whose midpoint did not refine between their ends are also `loose`).
fn densify<N: Copy>(
    (n0, n1): (N, N),
    pos: impl Fn(&N) -> DVec3 + Copy,
    mid: &impl Fn(&N, &N) -> Option<N>,
    (tol, chord_tol): (f64, f64),
    depth: u32,
    out: &mut Dense<N>,
) {
    let (p0, p1) = (pos(&n0), pos(&n1));
    if super::loose::short(p0, p1, chord_tol) {
        super::loose::vouch(p0, p1);
    }
    if depth >= 16 || p0.distance(p1) <= 2.0 * tol {
        return;
    }
    let Some(m) = mid(&n0, &n1) else {
        out.loose.push([p0, p1]);
        return;
    };
    let pm = pos(&m);
    let chord = p1 - p0;
    let off = (pm - p0).cross(chord).length() / chord.length();
    // A midpoint that wandered off between its ends (onto another branch) is not inserted.
    let along = (pm - p0).dot(chord) / chord.length_squared();
    if off > chord_tol && (0.0..=1.0).contains(&along) {
        densify((n0, m), pos, mid, (tol, chord_tol), depth + 1, out);
        out.points.push(pm);
        out.nodes.push(m);
        densify((m, n1), pos, mid, (tol, chord_tol), depth + 1, out);
    } else if off > chord_tol {
        out.loose.push([p0, p1]);
    } else if !super::loose::short(p0, p1, chord_tol) && sure((p0, p1), pm, chord_tol) {
        super::loose::vouch(p0, p1);
    }
}

/// The midpoint of two intersection nodes, refined onto both patches. Where Newton's point may
/// lie off the curve (see `newton::newton_pair_mid`: towards a branch point the surfaces part
/// so slowly across the curve that a point within 0.01·`tol` of both lies far off it), it is
/// taken across the chord onto the simple root of the gap, if there is one (a crossing's); a
/// contact's even root has none, and its point is kept as Newton left it. A point that is
/// neither (see `across::flat`: beside a branch point, off both curves) is None, as one that
/// does not converge: `densify` stops there and leaves the chord loose rather than put in a
/// point off both curves, where it would bisect on towards the branch point through more.
fn pair_mid<'p>(
    a: &'p Patch<'p>,
    b: &'p Patch<'p>,
    tol: f64,
) -> impl Fn(&Node, &Node) -> Option<Node> + 'p {
    move |n0: &Node, n1: &Node| {
        let uv = [mid(a, n0.uv[0], n1.uv[0]), mid(b, n0.uv[1], n1.uv[1])];
        let (m, unsure) = newton_pair_mid(a, b, uv, tol);
        if m.residual > tol {
            return None;
        }
        match taken_across(a, b, &m, unsure, (n0.point, n1.point), tol) {
            Across::Onto(x) => Some(x),
            Across::Stands => Some(m),
            Across::Neither => None,
        }
    }
}

/// Newton's point `m` taken across `chord` onto the crossing (`across::onto_crossing`) where it
/// may lie off its curve (`unsure`: the surfaces' derivatives there); where it is sure it
/// stands. Searched only there (the surfaces nearly tangent): crossings at an angle, and points
/// Newton brought to the rounding, cost nothing more.
fn taken_across(
    a: &Patch,
    b: &Patch,
    m: &Node,
    unsure: Option<[DVec3; 4]>,
    chord: (DVec3, DVec3),
    tol: f64,
) -> Across<Node> {
    match unsure {
        Some(cols) => across::onto_crossing(a, b, m, (chord, cols), tol),
        None => Across::Stands,
    }
}

/// A free seed point refined onto both patches from `uv`: Newton's point, or, where it may lie
/// off the curve, the crossing's root across it, as [`pair_mid`]'s midpoints (`chord`, the
/// seed's neighbouring points, bounds how far it is looked for). Where the surfaces part slowly
/// across a crossing (beside a branch point: by W² at W from the contact) Newton's damped steps
/// across crawl, and it stopped on its residual up to 3.6e-6 off the crossing.
fn seed_node(a: &Patch, b: &Patch, uv: [DVec2; 2], chord: (DVec3, DVec3), tol: f64) -> Node {
    let (m, unsure) = newton_pair_mid(a, b, uv, tol);
    match taken_across(a, b, &m, unsure, chord, tol) {
        Across::Onto(x) => x,
        // A midpoint off both curves leaves its chord loose; a seed node has no chord to leave,
        // and stands as Newton left it (for regrouping to sort out, as before).
        Across::Stands | Across::Neither => m,
    }
}

/// A seed point's mesh edge: whether it is `b`'s, and its vertices (see `bracket`).
pub(crate) type SeedEdge = Option<(bool, [DVec3; 2])>;

/// One seeded polyline refined onto both surfaces and densified within `chord_tol`, with its
/// loose chords (see [`assemble_loose`]). Points that do not converge (a seed far from any true
/// intersection) are dropped. `seed_tol` bounds how far the seeding meshes' boundary chords lie
/// from the surfaces' edges.
pub(crate) fn refine_pair_curve(
    a: &Patch,
    b: &Patch,
    (seed, edges): (&Polyline3, &[SeedEdge]),
    (tol, chord_tol, seed_tol): (f64, f64, f64),
) -> (Polyline3, Vec<[DVec3; 2]>) {
    let mut nodes: Vec<Node> = Vec::with_capacity(seed.points.len());
    let mut prev: Option<[DVec2; 2]> = None;
    let last = seed.points.len().saturating_sub(1);
    for (i, &p) in seed.points.iter().enumerate() {
        let mut start = [
            a.project(p, prev.map(|u| u[0])),
            b.project(p, prev.map(|u| u[1])),
        ];
        // An open seed ends where the meshes' curve leaves one of them: on its boundary, where
        // the true curve ends too. Refined freely, the end slides along the curve off the edge
        // (by the seed's error over the angle the curve makes with the edge: 9e-6 for a seed
        // 1.5e-4 off at a 1/59 slope); held there, it ends on it.
        let mut hold = [[false; 2]; 2];
        if !seed.closed && (i == 0 || i == last) {
            hold = [
                on_edge(a, p, &mut start[0], seed_tol),
                on_edge(b, p, &mut start[1], seed_tol),
            ];
        }
        let held = (hold != [[false; 2]; 2])
            .then(|| newton_pair_held(a, b, start, hold, tol))
            .filter(|h| h.residual <= tol);
        let chord = (
            seed.points[i.saturating_sub(1)],
            seed.points[(i + 1).min(last)],
        );
        let n = held.unwrap_or_else(|| seed_node(a, b, start, chord, tol));
        let n = match edges.get(i).copied().flatten() {
            Some(e) => bracket::pair_within_edge((a, b), e, (start, chord.1 - chord.0), n, tol),
            _ => n,
        };
        if n.residual <= tol {
            prev = Some(n.uv);
            nodes.push(n);
        }
    }
    assemble_loose(
        &nodes,
        seed.closed,
        |n| n.point,
        &pair_mid(a, b, tol),
        tol,
        chord_tol,
    )
}

/// Which parameters of `uv` (the projection of the seed's end `p`) put it on a bounded edge of
/// `patch` (not a seam or a pole), set exactly onto it. A mesh's boundary vertices lie on the
/// true boundary, so an end on its boundary is as near the boundary curve as the mesh is to its
/// surface, or as its boundary chord sags from a curved edge (within `seed_tol`, the mesh's
/// tolerance; where the edge bends in the surface's own plane the chord lies on the surface,
/// 2.5e-3 inside the edge at seed 1e-2, and only this tells). Its distance to the edge point is
/// taken against twice its distance to the surface plus `seed_tol` (an end a cell inside is a
/// cell from the edge, at least ~2.8 `seed_tol`, and that far from the surface only by the
/// mesh's sag). The projection itself does not land on the edge where the surface slopes there
/// (5e-8 inside it for an end 2.6e-5 off a 1/200 slope).
fn on_edge(patch: &Patch, p: DVec3, uv: &mut DVec2, seed_tol: f64) -> [bool; 2] {
    let mut held = [false; 2];
    let off = patch.eval(*uv).distance(p);
    for k in 0..2 {
        if patch.periodic()[k] {
            continue;
        }
        let mut q = *uv;
        q[k] = q[k].round();
        let near = patch.eval(q).distance(p) <= 2.0 * off + seed_tol + 1e-12 * patch.scale();
        if near && patch.bounds_at(q) {
            *uv = q;
            held[k] = true;
        }
    }
    held
}

/// How far `p` lies from the farther of `a` and `b`.
pub(crate) fn off_pair(a: &Patch, b: &Patch, p: DVec3) -> f64 {
    let (ua, ub) = (a.project(p, None), b.project(p, None));
    a.eval(ua).distance(p).max(b.eval(ub).distance(p))
}

/// How far `p` lies from the farther of `s` and the plane through `p0` with unit normal `n`.
pub(crate) fn off_section(s: &Patch, (p0, n): (DVec3, DVec3), p: DVec3) -> f64 {
    let on = s.eval(s.project(p, None));
    on.distance(p).max(n.dot(p - p0).abs())
}

/// Closes an open refined curve whose ends are within a few of its own segment lengths and
/// head for each other — the meshes lose the last pieces before a branch point, where the
/// surfaces touch (two equal cylinders crossing) — when the gap refines onto both surfaces: the
/// gap is densified like any other segment, and not closed where a chord left loose there is off
/// the surfaces (the ends are the two sides of something thinner than the seed's cells).
pub(crate) fn close_gap(a: &Patch, b: &Patch, c: &mut Polyline3, tol: f64, chord_tol: f64) {
    let n = c.points.len();
    if c.closed || n < 4 {
        return;
    }
    let h = c
        .points
        .windows(2)
        .map(|w| w[0].distance(w[1]))
        .fold(0.0, f64::max);
    let (s, e) = (c.points[0], c.points[n - 1]);
    if s.distance(e) > 3.0 * h || !ends_meet(&c.points) {
        return;
    }
    let node = |p: DVec3| newton_pair(a, b, [a.project(p, None), b.project(p, None)], tol);
    let (ne, ns) = (node(e), node(s));
    if ne.residual > tol || ns.residual > tol {
        return;
    }
    let mut extra = Dense {
        points: Vec::new(),
        nodes: Vec::new(),
        loose: Vec::new(),
    };
    let pos = |n: &Node| n.point;
    densify(
        (ne, ns),
        pos,
        &pair_mid(a, b, tol),
        (tol, chord_tol),
        0,
        &mut extra,
    );
    let off = |[p, q]: &[DVec3; 2]| off_pair(a, b, 0.5 * (p + q)) > chord_tol + tol;
    if extra.loose.iter().any(off) {
        return;
    }
    c.points.extend(extra.points);
    c.closed = true;
}

/// Whether the open curve `p` (at least two points) could close across the gap between its
/// ends: each end runs on towards the other (within 60°). A straight or gently bent curve is
/// densified to a few long segments, so its ends can lie within a few segment lengths of each
/// other while it runs away from the gap at both.
fn ends_meet(p: &[DVec3]) -> bool {
    let n = p.len();
    let (s, e) = (p[0], p[n - 1]);
    let Some(gap) = (s - e).try_normalize() else {
        return true;
    };
    let (Some(out_e), Some(out_s)) = (
        leaving(e, p.iter().rev().skip(1), 0.0),
        leaving(s, p.iter().skip(1), 0.0),
    ) else {
        return false;
    };
    out_e.dot(gap) >= 0.5 && out_s.dot(-gap) >= 0.5
}

/// The direction a curve leaves at `end`, from the first of the `inner` points (walking in from
/// that end) farther than `apart` from it.
pub(crate) fn leaving<'p>(
    end: DVec3,
    mut inner: impl Iterator<Item = &'p DVec3>,
    apart: f64,
) -> Option<DVec3> {
    inner
        .find(|q| q.distance(end) > apart)
        .and_then(|q| (end - *q).try_normalize())
}

/// One seeded plane-section polyline refined onto the surface and densified, its seed not from
/// a mesh (no boundary chord to hold on an edge beyond the surface's own distance).
pub(crate) fn refine_section_curve(
    s: &Patch,
    seed: &Polyline3,
    p0: DVec3,
    n: DVec3,
    tol: f64,
    chord_tol: f64,
) -> Polyline3 {
    refine_section_loose(s, (seed, &[]), (p0, n), (tol, chord_tol, 0.0)).0
}

/// [`refine_section_curve`] with its loose chords (see [`assemble_loose`]), the seed from a mesh
/// made within `seed_tol` (see [`on_edge`]), each of its points kept between the vertices of the
/// mesh edge it lies on where `edges` has them (see [`bracket`]).
pub(crate) fn refine_section_loose(
    s: &Patch,
    (seed, edges): (&Polyline3, &[Option<[DVec3; 2]>]),
    (p0, n): (DVec3, DVec3),
    (tol, chord_tol, seed_tol): (f64, f64, f64),
) -> (Polyline3, Vec<[DVec3; 2]>) {
    let mut nodes: Vec<(DVec2, DVec3)> = Vec::with_capacity(seed.points.len());
    let mut prev = None;
    let last = seed.points.len().saturating_sub(1);
    for (i, &p) in seed.points.iter().enumerate() {
        let mut start = s.project(p, prev);
        // An open seed's end on the boundary: held there (see `refine_pair_curve`).
        let mut hold = [false; 2];
        if !seed.closed && (i == 0 || i == last) {
            hold = on_edge(s, p, &mut start, seed_tol);
        }
        let held = (hold != [false; 2])
            .then(|| newton_plane_held(s, start, (p0, n), hold, tol))
            .filter(|h| h.1 <= tol);
        let (uv, r) = held.unwrap_or_else(|| newton_plane(s, start, p0, n, tol));
        let (uv, r) = match edges.get(i).copied().flatten() {
            Some(e) => {
                let along = seed.points[(i + 1).min(last)] - seed.points[i.saturating_sub(1)];
                bracket::within_edge(s, (p0, n), (start, along), (uv, r), e, tol)
            }
            None => (uv, r),
        };
        if r <= tol {
            prev = Some(uv);
            nodes.push((uv, s.eval(uv)));
        }
    }
    // Where Newton crawled beside a branch point, the point is taken across the curve onto
    // the crossing's root (see `plane_across`), within four chords of the midpoint.
    let mid_of = |a: &(DVec2, DVec3), b: &(DVec2, DVec3)| {
        let (uv, r) = newton_plane(s, mid(s, a.0, b.0), p0, n, tol);
        if r > tol {
            return None;
        }
        let at = s.eval(uv);
        let reach = 4.0 * a.1.distance(b.1);
        match plane_across::onto_plane_crossing(s, (uv, at), (p0, n), tol, reach) {
            Across::Onto(x) => Some((x, s.eval(x))),
            Across::Stands => Some((uv, at)),
            // Off both curves beside a branch point: not put in (see `pair_mid`).
            Across::Neither => None,
        }
    };
    assemble_loose(&nodes, seed.closed, |x| x.1, &mid_of, tol, chord_tol)
}

/// Carries a curve/surface hit onto the true surface and the true curve: Newton on
/// `S(u, v) − C(t) = 0` (three equations, three unknowns), with a parameter on a domain edge
/// held there. Returns `(t, point, residual)`.
pub(crate) fn newton_curve_hit(
    s: &Patch,
    c: &dyn crate::geom::ParamCurve,
    t0: f64,
    p: DVec3,
) -> (f64, DVec3, f64) {
    let mut uv = s.project(p, None);
    let mut t = t0.clamp(0.0, 1.0);
    let mut best = (t, p, f64::INFINITY);
    let mut fixed = [false; 3];
    for _ in 0..40 {
        let (ps, pc) = (s.eval(uv), c.eval(t));
        let r = ps - pc;
        if r.length() < best.2 {
            best = (t, 0.5 * (ps + pc), r.length());
        }
        if r.length() <= 1e-15 * (1.0 + ps.length()) {
            break;
        }
        let (su, sv) = s.derivs(uv);
        const H: f64 = 1e-7;
        let (ta, tb) = ((t - H).max(0.0), (t + H).min(1.0));
        let dc = (c.eval(tb) - c.eval(ta)) / (tb - ta);
        let mut cols = [su, sv, -dc];
        for (k, col) in cols.iter_mut().enumerate() {
            if fixed[k] {
                *col = DVec3::ZERO;
            }
        }
        let Some(y) = min_norm(&cols, r) else {
            break;
        };
        uv.x -= cols[0].dot(y);
        uv.y -= cols[1].dot(y);
        t -= cols[2].dot(y);
        let e = s.normalise(&mut uv);
        let te = !(0.0..=1.0).contains(&t);
        t = t.clamp(0.0, 1.0);
        fixed = [e[0], e[1], te];
    }
    best
}

/// The hits of a curve on a parametric surface: the mesh hits plus every place the curve passes
/// within `chord_tol` of the mesh boundary (a hit on a boundary edge of the true surface can miss
/// the mesh by roundoff), each carried onto both true objects; kept when they meet within
/// `tol`, one per point.
pub(crate) fn curve_hits_refined(
    s: &Patch,
    mesh: &crate::geom::mesh::Mesh,
    c: &dyn crate::geom::ParamCurve,
    samples: (&[f64], &[DVec3]),
    tol: f64,
    chord_tol: f64,
) -> Vec<(f64, DVec3)> {
    let (ts, pts) = samples;
    let mut cands: Vec<(f64, DVec3)> = super::hits::polyline_mesh_hits(pts, mesh)
        .into_iter()
        .map(|h| {
            let i = (h.t.floor() as usize).min(ts.len() - 2);
            (ts[i] + (ts[i + 1] - ts[i]) * (h.t - i as f64), h.point)
        })
        .collect();
    for l in mesh.boundary() {
        let n = l.points.len();
        for k in 0..n {
            let (q0, q1) = (l.points[k], l.points[(k + 1) % n]);
            for i in 0..pts.len().saturating_sub(1) {
                let (f, p, d) = segment_gap(pts[i], pts[i + 1], q0, q1);
                if d <= 2.0 * chord_tol {
                    cands.push((ts[i] + (ts[i + 1] - ts[i]) * f, p));
                }
            }
        }
    }
    let mut out: Vec<(f64, DVec3)> = Vec::new();
    for (t, p) in cands {
        let (t, q, r) = newton_curve_hit(s, c, t, p);
        if r <= tol && !out.iter().any(|o| o.1.distance(q) <= tol) {
            out.push((t, q));
        }
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

/// Closest approach of segments `p0p1` and `q0q1`: (fraction along p, point on p, distance).
fn segment_gap(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> (f64, DVec3, f64) {
    let (d1, d2, r) = (p1 - p0, q1 - q0, p0 - q0);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let (mut s, mut t);
    if a <= 1e-300 && e <= 1e-300 {
        return (0.0, p0, p0.distance(q0));
    }
    if a <= 1e-300 {
        s = 0.0;
        t = (f / e).clamp(0.0, 1.0);
    } else {
        let c = d1.dot(r);
        if e <= 1e-300 {
            t = 0.0;
            s = (-c / a).clamp(0.0, 1.0);
        } else {
            let b = d1.dot(d2);
            let den = a * e - b * b;
            s = if den > 0.0 {
                ((b * f - c * e) / den).clamp(0.0, 1.0)
            } else {
                0.0
            };
            t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
        }
    }
    let (cp, cq) = (p0 + d1 * s, q0 + d2 * t);
    (s, cp, cp.distance(cq))
}

#[cfg(test)]
mod tests {
    use super::Patch;
    use crate::geom::curve::Curve;
    use crate::geom::surface::{CurveRef, Surface};
    use crate::geom::ParamCurve;
    use glam::{DVec2, DVec3};
    use std::sync::Arc;

    fn v(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z)
    }

    fn pline(pts: Vec<DVec3>) -> CurveRef {
        Arc::new(Curve::pline(pts, false, None).unwrap())
    }

    /// Two plates crossing at a small angle `s` along x = 0.3, seeded 1e-3 beside the line:
    /// Newton's damped steps across cut the gap only by about λ/(λ + σ²) (σ ∝ `s`), and it
    /// stopped with the residual within 0.01·tol but up to that over `s` off the line (9.2e-6
    /// at s = 1e-6 before seed nodes were taken across; the sloped patch and the cone beside
    /// their branch point: 3.3e-7 where they part at 2.5e-5). Seed nodes are now taken onto
    /// the crossing's root across, as midpoints are.
    #[test]
    fn a_seed_point_where_plates_cross_at_a_small_angle_is_put_on_the_crossing() {
        use super::refine_pair_curve;
        use crate::geom::mesh::Polyline3;
        let plate = |s: f64| {
            let z = |x: f64| s * (x - 0.3);
            let c = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)];
            Surface::plane(c.iter().map(|&(x, y)| v(x, y, z(x))).collect()).unwrap()
        };
        let flat = plate(0.0);
        let tol = 1e-9;
        for s in [1e-6, 3e-6, 1e-5] {
            let tilted = plate(s);
            let (a, b) = (Patch::new(&flat), Patch::new(&tilted));
            let seed = Polyline3 {
                points: (0..5).map(|i| v(0.301, 0.2 * f64::from(i), 0.0)).collect(),
                closed: false,
            };
            let (c, _) = refine_pair_curve(&a, &b, (&seed, &[]), (tol, 1e-3, 1e-3));
            assert_eq!(c.points.len(), 5, "{s}: {:?}", c.points);
            for q in &c.points {
                assert!((q.x - 0.3).abs() <= 1e-10 && q.z.abs() <= 1e-12, "{s}: {q}");
            }
        }
    }

    #[test]
    fn creases_are_the_joins_where_the_derivative_jumps() {
        // Three segments of a polyline, each a third of the parameter: a turn at t = 1/3, a
        // straight join between segments of unequal length at 2/3 (the speed jumps), none
        // between equal collinear ones.
        let c = pline(vec![
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(1.0, 3.0, 0.0),
        ]);
        assert_eq!(c.creases(), vec![1.0 / 3.0, 2.0 / 3.0]);
        let straight = pline(vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(2.0, 0.0, 0.0)]);
        assert!(straight.creases().is_empty());
        // A quadratic B-spline with a double knot at 0.5 (C0 there) and a simple one at 0.25.
        let knots = vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 1.0, 1.0, 1.0];
        let ctrl = vec![
            v(0.0, 0.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(2.0, 0.0, 0.0),
            v(3.0, 2.0, 0.0),
            v(4.0, 0.0, 0.0),
            v(5.0, 1.0, 0.0),
        ];
        let b = Curve::bspline(ctrl, 2, Some(knots), None).unwrap();
        assert_eq!(b.creases(), vec![0.5]);
        let arc = Curve::arc(DVec3::ZERO, 1.0, 0.0, 1.0, None).unwrap();
        assert!(arc.creases().is_empty());
    }

    #[test]
    fn a_coons_side_taken_backwards_has_its_creases_mirrored() {
        let (a, b, c, d) = (
            v(0.0, 0.0, 0.0),
            v(3.0, 0.0, 0.0),
            v(3.0, 2.0, 0.0),
            v(0.0, 2.0, 0.0),
        );
        // Each side kinks at 2/3 of its own parameter only (a turn, or a straight join of
        // unequal segments on the left). The bottom is given from b to a, so the patch takes
        // it backwards: its kink lies at u = 1/3. The top given from d to c and the left from
        // a to d run with u and v as given (the patch takes them backwards from its own
        // order around): 2/3.
        let s = Surface::boundary([
            pline(vec![b, v(2.0, -0.5, 0.0), v(1.0, -1.0, 0.0), a]),
            pline(vec![b, c]),
            pline(vec![d, v(1.0, 2.5, 0.0), v(2.0, 3.0, 0.0), c]),
            pline(vec![a, v(0.0, 0.5, 0.0), v(0.0, 1.0, 0.0), d]),
        ])
        .unwrap();
        let [u, w] = s.creases();
        let close = |x: &[f64], y: &[f64]| {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| (p - q).abs() <= 1e-15)
        };
        assert!(close(&u, &[1.0 / 3.0, 2.0 / 3.0]), "{u:?}");
        assert!(close(&w, &[2.0 / 3.0]), "{w:?}");
    }

    #[test]
    fn derivatives_beside_a_crease_are_those_of_its_side() {
        // A fold ruled between two polylines that turn at u = 1/2: z = 0 before, z falling
        // 3 per unit of y after. Exactly, S_u = 10·(0, 4, 0) before and 10·(0, 6, −3) after
        // (on the v = 0 side, the ruling from x = 0), S_v = (10, 0, 0) + the two sides' gap.
        let fold = Surface::ruled(
            pline(vec![v(0.0, 0.0, 0.0), v(0.0, 4.0, 0.0), v(0.0, 10.0, -3.0)]),
            pline(vec![
                v(10.0, 0.0, 0.0),
                v(10.0, 4.0, 0.0),
                v(10.0, 10.0, -3.0),
            ]),
        );
        let patch = Patch::new(&fold);
        for (u, want) in [
            (0.5 - 3e-7, v(0.0, 8.0, 0.0)),
            (0.5 - 1e-12, v(0.0, 8.0, 0.0)),
            (0.5, v(0.0, 12.0, -6.0)),
            (0.5 + 7e-7, v(0.0, 12.0, -6.0)),
        ] {
            let (su, sv) = patch.derivs(DVec2::new(u, 0.3));
            assert!(su.distance(want) <= 1e-8, "{u}: {su} vs {want}");
            assert!(sv.distance(v(10.0, 0.0, 0.0)) <= 1e-8, "{u}: {sv}");
        }
    }

    #[test]
    fn a_warm_start_that_stops_at_a_pole_is_checked_from_the_search_grid() {
        // A cone's tip on the z axis, then flat on z = 0 out to r = 3, revolved: the profile's
        // start is a pole of the patch. A point of the flat, warm-started at the pole: Newton
        // stops there (the turn's derivative vanishes), 0.22 away.
        let prof = pline(vec![v(0.0, 0.0, 0.01), v(0.01, 0.0, 0.0), v(3.0, 0.0, 0.0)]);
        let s = Surface::revolve(prof, DVec3::ZERO, DVec3::Z, std::f64::consts::TAU).unwrap();
        let patch = Patch::new(&s);
        let pole = DVec2::new(0.0, 0.5);
        let p = v(0.2, 0.1, 0.0);
        assert!(patch.eval(pole).distance(v(0.0, 0.0, 0.01)) <= 1e-12);
        let slid = patch.project(p, Some(pole));
        assert!(patch.eval(slid).distance(p) > 0.2, "{slid}");
        let (uv, foot) = patch.project_warm(p, Some(pole));
        assert_eq!(foot, patch.eval(uv));
        assert!(foot.distance(p) <= 1e-12, "{foot}");
        // Past the outer edge (a bounding edge, not a pole) the warm foot stands: the edge.
        let q = v(3.3, 0.0, 0.0);
        let (uv, foot) = patch.project_warm(q, Some(DVec2::new(0.999, 0.0)));
        assert_eq!(uv.x, 1.0);
        assert!(foot.distance(v(3.0, 0.0, 0.0)) <= 1e-12, "{foot}");
        assert!(patch.bounds_at(uv) && !patch.bounds_at(pole));
    }
}
