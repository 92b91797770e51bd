//! Newton's method on the true surfaces: a point of two patches' intersection (minimum-norm
//! steps on `S1(u1, v1) − S2(u2, v2) = 0`) or of a patch's plane section, with parameters
//! optionally held on a domain edge, and how far past the tolerance each goes on.

use super::Patch;
use glam::{DMat3, DVec2, DVec3};

/// A point of the intersection of two patches, with its parameters on both.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Node {
    pub uv: [DVec2; 2],
    pub point: DVec3,
    pub residual: f64,
}

/// Carries `(uv_a, uv_b)` onto the intersection of `a` and `b` by minimum-norm Newton steps.
/// A residual within 0.01·`tol` leaves the point up to that over the sine of the surfaces'
/// angle off the curve (3e-9 where they cross at 3e-3 rad, more towards a branch point), so
/// Newton goes on while its next step would be longer than 0.01·`tol` (see [`goes_on`]).
pub(crate) fn newton_pair(a: &Patch, b: &Patch, uv: [DVec2; 2], tol: f64) -> Node {
    newton_pair_held(a, b, uv, [[false; 2]; 2], tol)
}

/// [`newton_pair`] with the parameters marked in `hold` kept where they start (on a domain
/// edge: the curve's end there).
pub(super) fn newton_pair_held(
    a: &Patch,
    b: &Patch,
    uv: [DVec2; 2],
    hold: [[bool; 2]; 2],
    tol: f64,
) -> Node {
    newton_pair_run(a, b, uv, hold, tol).0
}

/// [`newton_pair`] for a midpoint between two points of a curve (`refine::pair_mid`) or a free
/// seed point (`refine::seed_node`), with the surfaces' derivatives there where the point is
/// not known to be on the curve: its residual over the sine of the surfaces' angle (how far off
/// the curve it may be) exceeds `tol`, and the residual is above the rounding (see
/// `across::rounding`; within it no computation tells where the curve is, and the point
/// stands). Towards a branch point the surfaces part so
/// slowly across the curve that a point within 1e-11 of both can lie 1.7e-5 off it:
/// `min_norm`'s damping caps the steps across to about the residual over √λ (6.7e-7 a step,
/// the residual falling 4 % a step), and Newton stops crawling. The derivatives are those Newton
/// last took (from its last start), or taken at the point where those say it lies far off.
pub(super) fn newton_pair_mid(
    a: &Patch,
    b: &Patch,
    uv: [DVec2; 2],
    tol: f64,
) -> (Node, Option<[DVec3; 4]>) {
    let (node, cols) = newton_pair_run(a, b, uv, [[false; 2]; 2], tol);
    // No shortcut for a residual falling about fourfold a step (a contact's double zero): beside
    // a branch point, where the gap is near a triple root, a crossing's point falls so too
    // (3.85-fold, left 1.6e-6 off at 1.5e-2 from an edge); `across`'s probe tells contacts.
    if node.residual <= super::across::rounding(a, b) || node.residual > tol {
        return (node, None);
    }
    // A start taken with no step (within 0.01·`tol`: mostly a midpoint between two points of a
    // contact) is left as it was.
    let Some(cols) = cols else {
        return (node, None);
    };
    let old = sine(cols);
    // Not sure by the derivatives at Newton's last start. Its last step can be long beside a
    // contact (from a chord's parameter midpoint on one surface onto the other), and where the
    // surfaces' angle grows with the distance from the contact, as beside a branch point, those
    // had it 1.5e4 times too small: `across` then stepped 1.7e-2 across from a contact's point,
    // onto another crossing (i13c-s18). A step across they give longer than a chord whose
    // sagitta is `tol` (crawled points lie 1e-4 off at most; stale angles made it 4e-3 and more)
    // has them taken again where Newton stopped; otherwise they stand (8 evaluations saved).
    let chord = (8.0 * tol * a.scale().min(b.scale())).sqrt();
    if node.residual <= chord * old {
        return (node, (node.residual > tol * old).then_some(cols));
    }
    let ([au, av], [bu, bv]) = (a.derivs(node.uv[0]).into(), b.derivs(node.uv[1]).into());
    let cols = [au, av, bu, bv];
    (node, (node.residual > tol * sine(cols)).then_some(cols))
}

/// The sine of the surfaces' angle from their derivatives `cols`: a residual over it is how far
/// off the curve a point can be.
fn sine(cols: [DVec3; 4]) -> f64 {
    let (na, nb) = (cols[0].cross(cols[1]), cols[2].cross(cols[3]));
    na.cross(nb).length() / (na.length() * nb.length())
}

/// [`newton_pair_held`], with the surfaces' derivatives (unheld) at the last point Newton
/// stepped from (None where it took no step).
fn newton_pair_run(
    a: &Patch,
    b: &Patch,
    mut uv: [DVec2; 2],
    hold: [[bool; 2]; 2],
    tol: f64,
) -> (Node, Option<[DVec3; 4]>) {
    let mut fixed = hold;
    let mut derivs = None;
    let mut best: Option<Node> = None;
    // The last step's length in space and the residual before it.
    let mut last: Option<(f64, f64)> = None;
    for it in 0..40 {
        let (pa, pb) = (a.eval(uv[0]), b.eval(uv[1]));
        let r = pa - pb;
        let node = Node {
            uv,
            point: 0.5 * (pa + pb),
            residual: r.length(),
        };
        if best.is_none_or(|n| node.residual < n.residual) {
            best = Some(node);
        }
        let small = node.residual <= 0.01 * tol;
        if (small && !goes_on(last, node.residual, tol)) || (it > 30 && node.residual <= tol) {
            break;
        }
        let (au, av) = a.derivs(uv[0]);
        let (bu, bv) = b.derivs(uv[1]);
        derivs = Some([au, av, bu, bv]);
        // Columns of J; a parameter held on a domain edge contributes nothing.
        let mut cols = [au, av, -bu, -bv];
        for (k, c) in cols.iter_mut().enumerate() {
            if fixed[k / 2][k % 2] {
                *c = DVec3::ZERO;
            }
        }
        let Some(y) = min_norm(&cols, r) else {
            break;
        };
        let d = cols.map(|c| c.dot(y));
        let len = (cols[0] * d[0] + cols[1] * d[1])
            .length()
            .max((cols[2] * d[2] + cols[3] * d[3]).length());
        if small && !shrinks(last, len, tol) {
            break;
        }
        for (k, dk) in d.iter().enumerate() {
            uv[k / 2][k % 2] -= dk;
        }
        let ea = a.normalise(&mut uv[0]);
        let eb = b.normalise(&mut uv[1]);
        let or = |e: [bool; 2], h: [bool; 2]| [e[0] || h[0], e[1] || h[1]];
        fixed = [or(ea, hold[0]), or(eb, hold[1])];
        last = Some((len, node.residual));
    }
    let node = best.unwrap_or(Node {
        uv,
        point: a.eval(uv[0]),
        residual: f64::INFINITY,
    });
    (node, derivs)
}

/// Whether Newton, its residual now `r` (within 0.01·`tol`), is to go on: where its `last` step
/// (length in space, residual before it) says the next would be longer than 0.01·`tol` (the
/// step scales with the residual, the slope about the same) and the residual fell sixteenfold
/// (onto a simple root; onto a tangent contact's double zero it falls fourfold, and the point
/// is already within the tolerance of both). Not where there was no step to say: a start that
/// close (a midpoint between two points of a contact, mostly) is taken as it is, as before.
fn goes_on(last: Option<(f64, f64)>, r: f64, tol: f64) -> bool {
    last.is_some_and(|(len, r0)| 16.0 * r <= r0 && len * r > 0.01 * tol * r0)
}

/// Whether a step of length `len` past a residual within 0.01·`tol` is taken: while it is longer
/// than that and shorter than a quarter of the `last` (steps onto a simple root shrink at least
/// fourfold; halving, they are falling onto a tangent contact's double zero, and the point is
/// already within the tolerance of both surfaces).
fn shrinks(last: Option<(f64, f64)>, len: f64, tol: f64) -> bool {
    len > 0.01 * tol && last.is_none_or(|(l, _)| len <= 0.25 * l)
}

/// `y = (JJᵀ + λI)⁻¹ r` for the Jacobian with columns `cols`: the minimum-norm Newton step is
/// `−Jᵀy`. The small Levenberg damping λ keeps the step bounded where the surfaces (or the
/// curve and the surface) are tangent.
pub(super) fn min_norm(cols: &[DVec3], r: DVec3) -> Option<DVec3> {
    let mut jjt = DMat3::ZERO;
    for c in cols {
        jjt += DMat3::from_cols(*c * c.x, *c * c.y, *c * c.z);
    }
    let lambda = 1e-12
        * jjt
            .to_cols_array()
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs()));
    jjt += DMat3::from_diagonal(DVec3::splat(lambda.max(1e-300)));
    (jjt.determinant().abs() > 1e-300).then(|| jjt.inverse() * r)
}

/// A point of a plane section: Newton on `n·(S(u, v) − p0) = 0` (minimum-norm step), on past a
/// residual within 0.01·`tol` while its steps would be longer than that (as [`newton_pair`]).
pub(crate) fn newton_plane(s: &Patch, uv: DVec2, p0: DVec3, n: DVec3, tol: f64) -> (DVec2, f64) {
    newton_plane_held(s, uv, (p0, n), [false; 2], tol)
}

/// [`newton_plane`] with the parameters marked in `hold` kept where they start.
pub(super) fn newton_plane_held(
    s: &Patch,
    mut uv: DVec2,
    (p0, n): (DVec3, DVec3),
    hold: [bool; 2],
    tol: f64,
) -> (DVec2, f64) {
    let mut r = n.dot(s.eval(uv) - p0);
    let mut last: Option<(f64, f64)> = None;
    for _ in 0..40 {
        let small = r.abs() <= 0.01 * tol;
        if small && !goes_on(last, r.abs(), tol) {
            break;
        }
        let (su, sv) = s.derivs(uv);
        let mut g = DVec2::new(n.dot(su), n.dot(sv));
        for k in 0..2 {
            if hold[k] {
                g[k] = 0.0;
            }
        }
        let g2 = g.length_squared();
        if g2 <= 1e-300 {
            break;
        }
        let d = g * (r / g2);
        let len = (su * d.x + sv * d.y).length();
        if small && !shrinks(last, len, tol) {
            break;
        }
        let prev = uv;
        uv -= d;
        s.normalise(&mut uv);
        let nr = n.dot(s.eval(uv) - p0);
        if nr.abs() >= r.abs() && uv == prev {
            break;
        }
        // Past the tolerance only to come nearer (the residual's rounding can outgrow it).
        if small && nr.abs() > r.abs() {
            uv = prev;
            break;
        }
        last = Some((len, r.abs()));
        r = nr;
    }
    (uv, r.abs())
}
