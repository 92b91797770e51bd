//! Where a line from a point on the target to one off it leaves the target: the threshold
//! every boundary point of a region is found from ([`super::edge`] carries it on to the edge).
//!
//! Plain bisection of "lies on the target" took some 45 projections a crossing (a grid cell
//! halved down to 1e-15), the greater part of a region's cost: the last dozen of them among
//! points that the gap's rounding sorts on or off at random (where the surfaces part
//! tangentially the gap rises past the tolerance at a slope of √(2·tol/R), 3e-5 for the
//! oblique band, so its rounding of some 5e-16 blurs the threshold over 2e-11). The gap
//! beyond the tolerance (the [`super::Target::apart`]) rises smoothly past the region's edge,
//! so secants through the points off the target converge on the threshold from that side
//! ([`last_on`]), bisecting where they cannot (inside the region the gap is flat; outside the
//! target's extent it is unknown); and the search stops once the bracket is [`SHARP`] of the
//! tolerance wide in space, far below anything the edge's uses resolve. The end returned lies
//! on the target, as bisection's did.

use super::Tracer;
use glam::DVec2;

/// How wide in space the bracket around the threshold ends, as a fraction of the tolerance:
/// small enough that the threshold point stands for the threshold to a thousandth of the
/// tolerance; large enough to stop above the band the gap's rounding blurs.
const SHARP: f64 = 1e-3;

/// The last two points of a kind, the later last.
type Last = [Option<(f64, f64)>; 2];

/// Most evaluations of the gap (a third of the steps bisect, so at most three times
/// bisection's 50 or so).
const MOST: usize = 160;

impl Tracer<'_, '_> {
    /// How far the point at `uv` lies from the target ([`Self::on`] where within the
    /// tolerance): infinite outside the domain or the target's extent.
    pub(super) fn apart(&self, uv: DVec2) -> f64 {
        for k in 0..2 {
            if !self.periodic[k] && !(0.0..=1.0).contains(&uv[k]) {
                return f64::INFINITY;
            }
        }
        self.target.apart(self.eval(uv), self.tol)
    }

    /// The last point on the target from `lo` (on it) towards `hi` (off it), to [`SHARP`] of
    /// the tolerance in space (or 1e-15 in parameters, as bisection went).
    pub(super) fn bisect(&self, lo: DVec2, hi: DVec2) -> DVec2 {
        let d = hi - lo;
        let len = d.length();
        if len <= 1e-15 {
            return lo;
        }
        let chord = self.eval(lo).distance(self.eval(hi));
        let xtol = if chord > 0.0 {
            (SHARP * self.tol * len / chord).max(1e-15)
        } else {
            1e-15
        };
        let at = |x: f64| lo + d * (x / len);
        let gap = |x: f64| self.apart(at(x));
        let ends = ((0.0, gap(0.0)), (len, gap(len)));
        at(last_on(gap, ends.0, ends.1, (self.tol, self.flat), xtol))
    }
}

/// The last point where `gap` is at most `tol` on the way from `lo` (where it is) to `hi`
/// (where it is not, maybe infinite), bracketed to `xtol`; each end `(x, gap)`.
///
/// A gap no higher than `flat` is the region's own and tells nothing of where the threshold
/// lies. Past the region's edge the gap rises as `c·(s − e)^k` ([`super::edge`]): k = 2 where
/// the surfaces part tangentially, the common case, where √gap is linear in s, so the secant
/// of √gap through the last two points that rose from the flat finds the threshold at once;
/// for k above 2 it lands short of it, still off the target, and converges from there. For
/// k = 1 (a crease) it overshoots onto the target; then the secant of the gap itself through
/// the last two points off the target, exact for k = 1 and short of the threshold for any
/// k above 1, is taken next. A secant's point within `xtol`/2 of an end (or beyond it) is
/// taken `xtol`/2 inside that end, which closes the bracket when the secant was right.
/// Bisection wherever there are no two points to take a secant through (the gap flat, or
/// infinite outside the target's extent), or where two steps running have not halved the
/// bracket (the gap's rounding near the threshold, an end deep inside the region).
pub(super) fn last_on(
    mut gap: impl FnMut(f64) -> f64,
    lo: (f64, f64),
    hi: (f64, f64),
    (tol, flat): (f64, f64),
    xtol: f64,
) -> f64 {
    let on = |g: f64| g <= tol;
    // Not a bracket (a warm start's projection may classify a point otherwise than before):
    // where bisection would have ended, all points between taken as the ends are.
    if on(hi.1) {
        return hi.0;
    }
    if !on(lo.1) {
        return lo.0;
    }
    // The last two points that rose from the flat, and the last two off the target (on the
    // stack: no allocation per boundary point).
    let (mut risen, mut off) = ([None; 2], [None; 2]);
    let note = |(x, g): (f64, f64), risen: &mut Last, off: &mut Last| {
        if g.is_finite() && g > flat {
            *risen = [risen[1], Some((x, g))];
            if !on(g) {
                *off = [off[1], Some((x, g))];
            }
        }
    };
    note(lo, &mut risen, &mut off);
    note(hi, &mut risen, &mut off);
    let (mut a, mut b) = (lo.0, hi.0);
    let (mut slow, mut overshot) = (0, false);
    for _ in 0..MOST {
        let width = b - a;
        if width <= xtol {
            break;
        }
        let mut x = a + 0.5 * width;
        let mut by_root = false;
        if slow < 2 {
            let pts = if overshot { off } else { risen };
            let shape = |g: f64| if overshot { g } else { g.sqrt() };
            if let [Some((p, gp)), Some((q, gq))] = pts {
                let (hp, hq, h0) = (shape(gp), shape(gq), shape(tol));
                let s = q - (hq - h0) * (q - p) / (hq - hp);
                if s.is_finite() {
                    x = s.clamp(a + 0.5 * xtol, b - 0.5 * xtol);
                    by_root = !overshot;
                }
            }
        }
        if !(x > a && x < b) {
            // Ends a double apart: as closely bracketed as they can be.
            break;
        }
        let g = gap(x);
        overshot = by_root && on(g);
        if on(g) {
            a = x;
        } else {
            b = x;
        }
        note((x, g), &mut risen, &mut off);
        slow = if b - a > 0.5 * width { slow + 1 } else { 0 };
    }
    a
}

#[cfg(test)]
mod tests {
    use super::last_on;
    use std::cell::Cell;

    const TOL: f64 = 1e-9;
    /// The region's own gap, as the tracer's `flat`.
    const FLAT: f64 = 1e-13;

    /// A region's gap about its edge at `e`: 0 before, `(s − e)^k/4` past it, with a rounding
    /// of `noise` that changes with every bit of `s`.
    fn gap(e: f64, k: i32, noise: f64) -> impl Fn(f64) -> f64 {
        move |s: f64| {
            let jitter = noise * ((s.to_bits() % 7) as f64 / 3.0 - 1.0);
            (s - e).max(0.0).powi(k) / 4.0 + jitter
        }
    }

    /// The threshold of `g` between 0 and a grid cell (1/32), to `xtol`, and the number of
    /// evaluations it took.
    fn threshold(g: &dyn Fn(f64) -> f64, xtol: f64) -> (f64, usize) {
        let count = Cell::new(0);
        let f = |s: f64| {
            count.set(count.get() + 1);
            g(s)
        };
        let ends = ((0.0, g(0.0)), (1.0 / 32.0, g(1.0 / 32.0)));
        let x = last_on(f, ends.0, ends.1, (TOL, FLAT), xtol);
        (x, count.get())
    }

    /// The threshold bracketed on its near side, in half or less of bisection's
    /// evaluations (35 to 1e-12 of a grid cell), for a crease, a tangent parting and partings
    /// of higher order: where the gap c·(s − e)^k reaches the tolerance.
    #[test]
    fn the_threshold_is_bracketed_on_its_near_side() {
        for k in 1..=4 {
            let want = 0.01 + (4.0 * TOL).powf(1.0 / k as f64);
            let g = gap(0.01, k, 0.0);
            let (x, count) = threshold(&g, 1e-12);
            assert!(g(x) <= TOL, "k {k}: {x} off");
            assert!((x - want).abs() <= 1e-12, "k {k}: {x} vs {want}");
            assert!(count <= 17, "k {k}: {count} evaluations");
        }
    }

    /// Rounding that sorts points near the threshold at random, an unknown gap beyond the
    /// target's extent, and ends that are not a bracket: always a point on the target.
    #[test]
    fn a_point_on_the_target_whatever_the_gap() {
        for k in 1..=4 {
            let want = 0.01 + (4.0 * TOL).powf(1.0 / k as f64);
            let noisy = gap(0.01, k, 5e-16);
            let (x, count) = threshold(&noisy, 1e-12);
            // The rounding blurs the threshold over 5e-16 over the gap's slope there.
            let slope = k as f64 * (x - 0.01).powi(k - 1) / 4.0;
            assert!(noisy(x) <= TOL, "k {k}: {x} off");
            assert!(
                (x - want).abs() <= 1e-12 + 2e-15 / slope,
                "k {k}: {x} vs {want}"
            );
            assert!(count <= 24, "k {k}: {count} evaluations");
        }
        // The extent ends at 0.02, before the gap reaches the tolerance: found by bisection.
        let cut = |s: f64| if s > 0.02 { f64::INFINITY } else { 0.0 };
        let (x, _) = threshold(&cut, 1e-15);
        assert!(x <= 0.02 && 0.02 - x <= 1e-15, "{x}");
        // Not a bracket: the end that bisection would have come to.
        let ends = |a: f64, b: f64| ((0.0, a), (0.03, b));
        let ((lo, hi), t) = (ends(1.0, 2.0), (TOL, FLAT));
        assert_eq!(last_on(cut, lo, hi, t, 1e-15), 0.0);
        let (lo, hi) = ends(0.0, 0.0);
        assert_eq!(last_on(cut, lo, hi, t, 1e-15), 0.03);
    }
}
