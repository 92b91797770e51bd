//! Crossings beside a common region, for pairs with no closed form: two surfaces that coincide
//! over a region ([`super::common`]) may also cross elsewhere. Their meshes cross all over the
//! region too (two inscribed meshes of one surface), so the refined mesh curves hold the true
//! crossings and fragments of the region's interior and boundary alike, every point lying on
//! both surfaces. A point belongs to the region when the surfaces also coincide around it:
//! probes a short step away on one surface, in nine directions, lie on the other. On a crossing
//! at most one probe can (the curve runs along one direction, and no two directions are
//! opposite); inside the region all do, and on its boundary about half. The curves are cut
//! where they enter the region, and a crossing that runs into it is carried on the true
//! surfaces to the boundary loop, where it ends at a point shared with the loop.

use super::kinds::Surface;
use super::refine::{assemble, mid, newton_pair, Node, Patch};
use crate::geom::mesh::Polyline3;
use glam::{DVec2, DVec3};
use std::cell::Cell;
use std::f64::consts::TAU;

/// Probe directions, 40° apart: an odd count, so a curve through the point runs along at most
/// one of them.
const PROBES: usize = 9;
/// Probes on the other surface that make a point part of the region: two or more lie in it at a
/// right-angled corner of the region, at most one along a crossing.
const NEED: usize = 2;
/// The probes' step, as a fraction of the surface's size: far above GEOMTOL over the sine of
/// any crossing angle worth telling from a contact, small beside any region.
const STEP: f64 = 1e-4;

/// The common region of two surfaces, tested on the one that is not an analytic kind.
pub(super) struct Region<'a> {
    s: Patch<'a>,
    on_other: Box<dyn Fn(DVec3) -> bool + 'a>,
    hint: Cell<Option<DVec2>>,
    step: f64,
}

impl<'a> Region<'a> {
    pub(super) fn new(a: &'a Surface, b: &'a Surface, tol: f64) -> Region<'a> {
        let analytic = |s: &Surface| {
            matches!(
                s,
                Surface::Plane(_) | Surface::Sphere(_) | Surface::Cylinder(_)
            )
        };
        let (s, other) = if analytic(a) && !analytic(b) {
            (b, a)
        } else {
            (a, b)
        };
        let s = Patch::new(s);
        let step = STEP * s.scale();
        Region {
            s,
            on_other: Box::new(super::common::on_surface(other, tol)),
            hint: Cell::new(None),
            step,
        }
    }

    /// Whether `p`, a point on both surfaces, lies in (or on the boundary of) the region.
    fn contains(&self, p: DVec3) -> bool {
        self.holds(p, f64::INFINITY)
    }

    /// Whether `p`, a point within `near` of both surfaces (a mesh vertex or a seed point),
    /// lies in (or on the boundary of) the region: its nearest point on the surface does, and
    /// is no farther than `near` (a point beyond the surface's edge is not in the region).
    pub(super) fn holds(&self, p: DVec3, near: f64) -> bool {
        let (uv, foot) = self.s.project_warm(p, self.hint.get());
        self.hint.set(Some(uv));
        if foot.distance(p) > near {
            return false;
        }
        let (su, sv) = self.s.derivs(uv);
        // A parameter step of about `step` on the surface (bounded where it degenerates).
        let du = DVec2::new(
            (self.step / su.length().max(1e-300)).min(1e-2),
            (self.step / sv.length().max(1e-300)).min(1e-2),
        );
        let periodic = self.s.periodic();
        let mut on = 0;
        for k in 0..PROBES {
            // Turned off the grid lines and diagonals, along which crossings often run.
            let t = 0.3 + TAU * k as f64 / PROBES as f64;
            let mut q = uv + DVec2::new(t.cos(), t.sin()) * du;
            let inside = (0..2).all(|i| periodic[i] || (0.0..=1.0).contains(&q[i]));
            if inside {
                self.s.normalise(&mut q);
                if (self.on_other)(self.s.eval(q)) {
                    on += 1;
                    if on >= NEED {
                        return true;
                    }
                }
            }
            if on + (PROBES - 1 - k) < NEED {
                return false;
            }
        }
        false
    }
}

/// Tolerances and reach of a cut: GEOMTOL, CHORDTOL, and how far a crossing's end may be from
/// the loop it runs into (the meshes lose a crossing's last stretch where the surfaces are
/// nearly tangent).
#[derive(Clone, Copy)]
pub(super) struct Reach {
    pub tol: f64,
    pub chord_tol: f64,
    pub seed_tol: f64,
}

/// The parts of the refined `curves` (on both surfaces `a` and `b`) that lie outside the
/// region, each end that runs into it carried onto one of its boundary `loops` (and put into
/// that loop, so the two share the point).
pub(super) fn outside(
    region: &Region,
    (a, b): (&Patch, &Patch),
    curves: Vec<Polyline3>,
    loops: &mut [Polyline3],
    r: Reach,
) -> Vec<Polyline3> {
    let mut out = Vec::new();
    for c in curves {
        let flags: Vec<bool> = c.points.iter().map(|p| region.contains(*p)).collect();
        if flags.iter().all(|&f| f) {
            continue;
        }
        if !flags.iter().any(|&f| f) {
            let mut c = c;
            if !c.closed && c.points.len() >= 2 {
                for at_start in [true, false] {
                    extend(region, (a, b), &mut c.points, at_start, loops, r);
                }
            }
            if !along_loops(&c.points, loops, region) {
                out.push(c);
            }
            continue;
        }
        // Start a closed curve at a point in the region: its runs outside then do not wrap.
        let n = c.points.len();
        let first = if c.closed {
            flags.iter().position(|&f| f).unwrap_or(0)
        } else {
            0
        };
        let pts: Vec<DVec3> = (0..n).map(|i| c.points[(first + i) % n]).collect();
        let fl: Vec<bool> = (0..n).map(|i| flags[(first + i) % n]).collect();
        let mut i = 0;
        while i < n {
            if fl[i] {
                i += 1;
                continue;
            }
            let j = (i..n).find(|&k| fl[k]).unwrap_or(n);
            let mut run = pts[i..j].to_vec();
            if c.closed && j == n {
                run.push(pts[0]);
            }
            if run.len() >= 2 {
                for at_start in [true, false] {
                    extend(region, (a, b), &mut run, at_start, loops, r);
                }
                if !along_loops(&run, loops, region) {
                    out.push(Polyline3 {
                        points: run,
                        closed: false,
                    });
                }
            }
            i = j;
        }
    }
    without_doubles(out, 2.0 * region.step)
}

/// The `curves` without the open ones lying along a longer one within `d` (the meshes can
/// seed a crossing twice, as a hairpin out along it and back where the surfaces part slowly).
fn without_doubles(mut curves: Vec<Polyline3>, d: f64) -> Vec<Polyline3> {
    curves.sort_by(|x, y| y.length().total_cmp(&x.length()));
    let mut kept: Vec<Polyline3> = Vec::with_capacity(curves.len());
    for c in curves {
        if c.closed
            || !c
                .points
                .iter()
                .all(|p| super::contact::near_any(*p, &kept, d))
        {
            kept.push(c);
        }
    }
    kept
}

/// The mesh `seeds` with what lies inside the region dropped before they are refined: two
/// inscribed meshes of one surface cross all over the region, and refining those fragments
/// costs many times what the region's loops do. A seed point (within `near` of both surfaces)
/// is tested as a refined one is.
/// Each run kept takes one point inside at either end, so that its refined curve still reaches
/// the region, where [`outside`] cuts it exactly.
pub(super) fn seeds_outside(region: &Region, seeds: Vec<Polyline3>, near: f64) -> Vec<Polyline3> {
    let mut out = Vec::new();
    for c in seeds {
        let flags: Vec<bool> = c.points.iter().map(|p| region.holds(*p, near)).collect();
        if !flags.iter().any(|&f| f) {
            out.push(c);
            continue;
        }
        let n = c.points.len();
        // Indices walked from a point inside, so a closed seed's runs do not wrap.
        let first = flags.iter().position(|&f| f).unwrap_or(0);
        let order: Vec<usize> = if c.closed {
            (0..=n).map(|i| (first + i) % n).collect()
        } else {
            (0..n).collect()
        };
        let mut i = 0;
        while i < order.len() {
            if flags[order[i]] {
                i += 1;
                continue;
            }
            let j = (i..order.len())
                .find(|&k| flags[order[k]])
                .unwrap_or(order.len());
            let (lo, hi) = (i.saturating_sub(1), (j + 1).min(order.len()));
            out.push(Polyline3 {
                points: order[lo..hi].iter().map(|&k| c.points[k]).collect(),
                closed: false,
            });
            i = j;
        }
    }
    out
}

/// Carries the end of `run` (its first or last point) onto a loop it runs into: along the
/// end's direction, the nearest loop segment within reach; the meeting point is refined onto
/// both surfaces, put into the loop, and the gap to it densified on the true surfaces.
fn extend(
    region: &Region,
    (a, b): (&Patch, &Patch),
    run: &mut Vec<DVec3>,
    at_start: bool,
    loops: &mut [Polyline3],
    r: Reach,
) {
    let n = run.len();
    let (e, f) = if at_start {
        (run[0], run[1])
    } else {
        (run[n - 1], run[n - 2])
    };
    let Some(dir) = (e - f).try_normalize() else {
        return;
    };
    let reach = 4.0 * region.step + 2.0 * e.distance(f) + 4.0 * (r.seed_tol * a.scale()).sqrt();
    let ray = (e, e + dir * reach);
    // The nearest segment off the ray; of those the ray meets (within the tolerance), the
    // first along it: a crossing whose end lies on the loop where it runs along a side of it
    // (the crossing leaving a fold's flat along a rectangle's edge) ends there, not at
    // whichever of that side's segments comes first in the loop.
    let mut best: Option<((f64, f64), usize, usize, DVec3)> = None;
    for (li, l) in loops.iter().enumerate() {
        let m = l.points.len();
        let segs = if l.closed { m } else { m.saturating_sub(1) };
        for k in 0..segs {
            let (q0, q1) = (l.points[k], l.points[(k + 1) % m]);
            let (s, t, d) = segment_gap(ray.0, ray.1, q0, q1);
            // Off the ray's line by no more than the curve's own bending over the step.
            let lateral = 4.0 * r.chord_tol + 0.05 * s * reach;
            let key = if d <= r.tol { (0.0, s) } else { (d, s) };
            if d <= lateral && best.is_none_or(|x| key < x.0) {
                best = Some((key, li, k, q0.lerp(q1, t)));
            }
        }
    }
    let Some((_, li, k, x0)) = best else {
        return;
    };
    let node = |p: DVec3| newton_pair(a, b, [a.project(p, None), b.project(p, None)], r.tol);
    let nx = node(x0);
    if nx.residual > r.tol {
        return;
    }
    // The loop's own vertex when the point is one; otherwise it becomes one.
    let l = &mut loops[li];
    let m = l.points.len();
    let (q0, q1) = (l.points[k], l.points[(k + 1) % m]);
    let x = if nx.point.distance(q0) <= r.tol {
        q0
    } else if nx.point.distance(q1) <= r.tol {
        q1
    } else {
        l.points.insert(k + 1, nx.point);
        nx.point
    };
    let ne = node(e);
    let pair_mid = |n0: &Node, n1: &Node| {
        let uv = [mid(a, n0.uv[0], n1.uv[0]), mid(b, n0.uv[1], n1.uv[1])];
        let m = newton_pair(a, b, uv, r.tol);
        (m.residual <= r.tol).then_some(m)
    };
    let gap = if ne.residual <= r.tol {
        assemble(&[ne, nx], false, |n| n.point, &pair_mid, r.tol, r.chord_tol).points
    } else {
        vec![e, x]
    };
    // Between the end (kept as it is) and the loop's point (exactly).
    let mut inner: Vec<DVec3> = gap[1..].to_vec();
    inner.pop();
    inner.push(x);
    if e.distance(x) <= r.tol {
        inner = vec![x];
        if at_start {
            run.remove(0);
        } else {
            run.pop();
        }
    }
    if at_start {
        inner.reverse();
        run.splice(0..0, inner);
    } else {
        run.extend(inner);
    }
}

/// Whether the curve through `points` is a sliver along the region's boundary (every point
/// just outside it, as where a crossing meets the boundary): not a crossing.
fn along_loops(points: &[DVec3], loops: &[Polyline3], region: &Region) -> bool {
    points
        .iter()
        .all(|p| super::contact::near_any(*p, loops, 2.0 * region.step))
}

/// The closest points of the segments `p0 p1` and `q0 q1`: their parameters and distance.
fn segment_gap(p0: DVec3, p1: DVec3, q0: DVec3, q1: DVec3) -> (f64, f64, f64) {
    let (d1, d2, r) = (p1 - p0, q1 - q0, p0 - q0);
    let (a, e, f) = (d1.dot(d1), d2.dot(d2), d2.dot(r));
    let clamp = |x: f64| x.clamp(0.0, 1.0);
    let (s, t) = if a <= f64::MIN_POSITIVE && e <= f64::MIN_POSITIVE {
        (0.0, 0.0)
    } else if a <= f64::MIN_POSITIVE {
        (0.0, clamp(f / e))
    } else {
        let c = d1.dot(r);
        if e <= f64::MIN_POSITIVE {
            (clamp(-c / a), 0.0)
        } else {
            let b = d1.dot(d2);
            let den = a * e - b * b;
            let s = if den > 0.0 {
                clamp((b * f - c * e) / den)
            } else {
                0.0
            };
            let t = (b * s + f) / e;
            if t < 0.0 {
                (clamp(-c / a), 0.0)
            } else if t > 1.0 {
                (clamp((b - c) / a), 1.0)
            } else {
                (s, t)
            }
        }
    };
    let d = (p0 + d1 * s).distance(q0 + d2 * t);
    (s, t, d)
}
