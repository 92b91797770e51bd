//! A bracketed root of a scalar function by the Illinois method (modified regula falsi).
//!
//! The secant through the bracket's ends keeps the root bracketed, unlike Newton, which may
//! leave for another root; plain regula falsi stalls when one end stays put (the function
//! convex on the bracket), so an end's value is halved each time it stays put twice running
//! (Dowell and Jarratt's rule, none on the first step), which pulls the next secant point
//! across the root and closes the bracket from both sides.
//!
//! The function returns a payload with each value (a surface point, a node of two surfaces),
//! so the point a caller gets back is the one its value was computed at, with no second
//! evaluation. Callers differ in what "close enough" means, given as a [`Stop`].

/// Steps at most. Each few Illinois steps at least halve the bracket where the ends' values are
/// of a size, so 60 reach its rounding from the brackets callers give (gaps of surfaces). Not
/// from any: ends whose values differ by hundreds of orders take a halving of the far one's
/// per step ((t − 1.3)·e^(700 (t − 1)) on [1, 2] stops 3e-4 off after 60).
const STEPS: usize = 60;

/// When to stop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stop {
    /// A value within this of zero (a gap small enough to be a point of both surfaces).
    Value(f64),
    /// The bracket no wider than this (the argument is what the caller needs exact).
    Width(f64),
}

/// A sample of the function: argument, value and the payload computed with the value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct At<P> {
    pub t: f64,
    pub f: f64,
    pub payload: P,
}

/// The root of `f` bracketed by `ends` (already evaluated; values of opposite signs, or one of
/// them zero), solved until `stop` holds, the secant point stops moving off the bracket's ends,
/// or after [`STEPS`]: of the last bracket's two ends, the one with the lesser |value| (the
/// first on a tie). Not the least |value| seen: away from the root a value can be smaller (the
/// end of a bracket where a contact's double zero flattens the gap), and a width stop promises
/// the bracket. None where the ends bracket no root, a value is NaN or infinite, or `f`
/// returns None (a point the caller cannot evaluate).
pub fn illinois<P>(
    mut f: impl FnMut(f64) -> Option<(f64, P)>,
    [mut a, mut b]: [At<P>; 2],
    stop: Stop,
) -> Option<At<P>> {
    if !(a.f.is_finite() && b.f.is_finite()) {
        return None;
    }
    // Signs compared, not the values' product, which underflows for tiny values.
    if a.f != 0.0 && b.f != 0.0 && (a.f < 0.0) == (b.f < 0.0) {
        return None;
    }
    // The values the secant sees: an end's is halved each time the other end is replaced
    // twice running (`moved`, which end the last step replaced: `true` for `b`).
    let (mut fa, mut fb) = (a.f, b.f);
    let mut moved = None;
    for _ in 0..STEPS {
        let least = a.f.abs().min(b.f.abs());
        let done = match stop {
            Stop::Value(eps) => least <= eps,
            Stop::Width(eps) => (b.t - a.t).abs() <= eps,
        };
        if done || least == 0.0 {
            break;
        }
        let (lo, hi) = (a.t.min(b.t), a.t.max(b.t));
        let t = (a.t * fb - b.t * fa) / (fb - fa);
        // Rounding may put the secant point on an end (or off the bracket): bisect instead,
        // and where even that lands on an end the bracket is at its rounding.
        let t = if t > lo && t < hi { t } else { 0.5 * (lo + hi) };
        if t <= lo || t >= hi {
            break;
        }
        let (ft, payload) = f(t)?;
        if !ft.is_finite() {
            return None;
        }
        let next = At { t, f: ft, payload };
        if (ft < 0.0) == (a.f < 0.0) {
            if moved == Some(false) {
                fb *= 0.5;
            }
            (a, fa, moved) = (next, ft, Some(false));
        } else {
            if moved == Some(true) {
                fa *= 0.5;
            }
            (b, fb, moved) = (next, ft, Some(true));
        }
    }
    Some(if a.f.abs() <= b.f.abs() { a } else { b })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `f` sampled with its argument as the payload, so a test can tell the payload returned
    /// is the one computed at the returned argument.
    fn solve(f: impl Fn(f64) -> f64, (a, b): (f64, f64), stop: Stop) -> Option<At<f64>> {
        let at = |t: f64| At {
            t,
            f: f(t),
            payload: t,
        };
        illinois(|t| Some((f(t), t)), [at(a), at(b)], stop)
    }

    #[test]
    fn a_simple_root_to_either_stop_rule() {
        // sqrt 2 as the root of t² − 2 on [0, 2]: convex, where plain regula falsi keeps the
        // end 2 and crawls; Illinois gets there in a handful of steps either way.
        let f = |t: f64| t * t - 2.0;
        let r = solve(f, (0.0, 2.0), Stop::Value(1e-14)).unwrap();
        assert!(r.f.abs() <= 1e-14, "{r:?}");
        assert!((r.t - 2f64.sqrt()).abs() <= 1e-14, "{r:?}");
        let r = solve(f, (2.0, 0.0), Stop::Width(1e-13)).unwrap();
        assert!((r.t - 2f64.sqrt()).abs() <= 1e-13, "{r:?}");
        assert_eq!(r.f, f(r.t));
        // A width stop is the bracket's: a loose one stops well before the value is small.
        let loose = solve(f, (0.0, 2.0), Stop::Width(0.1)).unwrap();
        assert!((loose.t - 2f64.sqrt()).abs() <= 0.1, "{loose:?}");
        assert!(loose.f.abs() > 1e-6, "{loose:?}");
        // And a value stop lets the bracket stay wide (t⁸ − 0.5 is flat near the root's left).
        let g = |t: f64| t.powi(8) - 0.5;
        let r = solve(g, (0.0, 1.0), Stop::Value(1e-15)).unwrap();
        assert!((r.t - 0.5f64.powf(0.125)).abs() <= 1e-13, "{r:?}");
        assert!(r.f.abs() <= 1e-15, "{r:?}");
    }

    #[test]
    fn the_sample_returned_lies_in_the_last_bracket_even_where_one_away_is_smaller() {
        // A gap flattened to −1e-9 on [0, 0.1) (as beside a contact's double zero), its simple
        // root at 0.5: the samples on the flat are the smallest seen (the last bracket's ends
        // have values about 1e-7), but the width stop promises the root within 0.01.
        let f = |t: f64| {
            if t < 0.1 {
                -1e-9
            } else {
                (t - 0.5) * (1.0 + 4.0 * (t - 0.5).powi(2))
            }
        };
        let r = solve(f, (0.0, 1.0), Stop::Width(0.01)).unwrap();
        assert!((r.t - 0.5).abs() <= 0.01, "{r:?}");
        assert_eq!(r.f, f(r.t));
    }

    #[test]
    fn the_root_found_is_the_one_between_the_ends() {
        // Roots at 0.2 (between the ends) and 1.5 (beyond): Newton from 0.9, where the slope
        // points to 1.5's side, would leave the bracket; Illinois stays in it.
        let f = |t: f64| (t - 0.2) * (t - 1.5);
        let r = solve(f, (0.0, 1.0), Stop::Value(1e-14)).unwrap();
        assert!((r.t - 0.2).abs() <= 1e-12 && r.f.abs() <= 1e-14, "{r:?}");
    }

    #[test]
    fn a_root_at_an_end_or_beside_it() {
        // Exactly at an end: that end, with no evaluation.
        let f = |t: f64| t - 1.0;
        let r = illinois(
            |_| -> Option<(f64, f64)> { panic!("no step needed") },
            [
                At {
                    t: 0.0,
                    f: f(0.0),
                    payload: 0.0,
                },
                At {
                    t: 1.0,
                    f: 0.0,
                    payload: 1.0,
                },
            ],
            Stop::Value(0.0),
        )
        .unwrap();
        assert_eq!((r.t, r.f, r.payload), (1.0, 0.0, 1.0));
        // Within rounding of an end (e^t − 1 − 1e-300 has its root at 1e-300): found to it.
        let g = |t: f64| t.exp_m1() - 1e-300;
        let r = solve(g, (0.0, 1.0), Stop::Width(1e-12)).unwrap();
        assert!(r.t.abs() <= 1e-12, "{r:?}");
        let r = solve(g, (1.0, 0.0), Stop::Value(0.0)).unwrap();
        assert!(r.t.abs() <= 1e-12 && r.f.abs() <= 1e-300, "{r:?}");
    }

    #[test]
    fn no_sign_change_or_a_nan_is_no_root() {
        assert!(solve(|t| (t - 0.5).powi(2) + 1e-3, (0.0, 1.0), Stop::Value(0.0)).is_none());
        // A double root touches zero without crossing: no bracket either.
        assert!(solve(|t| (t - 0.5).powi(2), (0.0, 1.0), Stop::Width(1e-9)).is_none());
        // Tiny values of one sign, whose product underflows to zero, are not a bracket.
        assert!(solve(|t| 1e-200 * (1.0 + t), (0.0, 1.0), Stop::Value(0.0)).is_none());
        // A NaN at an end, or inside (the first secant point of t − 0.5 on [0, 1] is 0.5's
        // neighbourhood, here made NaN).
        let nan_end = |t: f64| if t == 0.0 { f64::NAN } else { t };
        assert!(solve(nan_end, (0.0, 1.0), Stop::Value(1e-12)).is_none());
        // Where the other end is negative, the signs' test lets a NaN end through (a NaN is
        // not below zero); and an infinite end, whose sign is all right, is no value either.
        let nan_end = |t: f64| if t == 0.0 { f64::NAN } else { t - 2.0 };
        assert!(solve(nan_end, (0.0, 1.0), Stop::Value(1e-12)).is_none());
        let infinite_end = |t: f64| if t == 0.0 { f64::NEG_INFINITY } else { t };
        assert!(solve(infinite_end, (0.0, 1.0), Stop::Width(1e-12)).is_none());
        let nan_inside = |t: f64| {
            if t > 0.25 && t < 0.75 {
                f64::NAN
            } else {
                t - 0.5
            }
        };
        assert!(solve(nan_inside, (0.0, 1.0), Stop::Value(1e-12)).is_none());
        // The caller's None (a point it cannot evaluate) ends it too.
        let ends = [0.0, 1.0].map(|t| At {
            t,
            f: t - 0.5,
            payload: (),
        });
        assert!(illinois(|_| None, ends, Stop::Value(1e-12)).is_none());
    }

    #[test]
    fn a_secant_point_rounded_onto_an_end_is_replaced_by_the_bracket_midpoint() {
        // (t − 1.3)·(1 + 1e20 (t − 1)^40) on [1, 2]: −0.3 at 1, 7e19 at 2, so the first
        // secant point lies within 5e-21 of 1 and rounds onto it. Stopping there would give
        // back the end 1, 0.3 from the root; bisecting until the values are of a size,
        // Illinois takes over and finds 1.3.
        let f = |t: f64| (t - 1.3) * (1.0 + 1e20 * (t - 1.0).powi(40));
        let r = solve(f, (1.0, 2.0), Stop::Width(1e-12)).unwrap();
        assert!((r.t - 1.3).abs() <= 1e-12, "{r:?}");
        assert_eq!(r.f, f(r.t));
    }

    #[test]
    fn the_payload_is_the_one_computed_at_the_returned_argument() {
        // The payload counts the evaluations: the returned one must be the evaluation whose
        // argument and value came back, checked against f recomputed there.
        let f = |t: f64| t.cos() - t;
        let mut seen = Vec::new();
        let ends = [(0.0, 0usize), (1.0, 1)].map(|(t, k)| At {
            t,
            f: f(t),
            payload: k,
        });
        let r = illinois(
            |t| {
                seen.push(t);
                Some((f(t), seen.len() + 1))
            },
            ends,
            Stop::Value(1e-15),
        )
        .unwrap();
        // The Dottie number, cos t = t, to 1e-15 in value (slope about −1.67).
        assert!((r.t - 0.739_085_133_215_160_6).abs() <= 1e-15, "{r:?}");
        assert!(r.payload >= 2, "{r:?}");
        assert_eq!(seen[r.payload - 2], r.t);
        assert_eq!(r.f, f(r.t));
    }
}
