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

impl<P> At<P> {
    /// The sample at 0: `start`'s payload with `f0` where `f0` is `f`'s own value there (the
    /// caller already evaluated it), else `f` evaluated at 0.
    pub fn at_zero(
        f0: f64,
        start: Option<P>,
        f: impl FnOnce(f64) -> Option<(f64, P)>,
    ) -> Option<Self> {
        let (f, payload) = match start {
            Some(payload) => (f0, payload),
            None => f(0.0)?,
        };
        Some(At { t: 0.0, f, payload })
    }
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

/// Newton's 1-D step from 0 on a function, and the scale its argument is measured in: the
/// callers' arguments differ in unit (a length in space, or a count of steps), and each keeps
/// its own arithmetic, so its iterates do not move at rounding level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonStep {
    /// The function's value at 0, where the step starts.
    pub f0: f64,
    /// Where the step lands: −f0 over the slope at 0.
    pub t: f64,
    /// The length one unit of the argument spans (in the units of `reach` and `width`).
    pub unit: f64,
    /// How far from 0 the root may lie (farther, it is another root's).
    pub reach: f64,
    /// The bracket's width wanted, as `reach` measures it.
    pub width: f64,
    /// The value's rounding: a step landing within it is taken as the root, with no bracket.
    pub rounding: f64,
}

/// The root of `f` near Newton's step from 0 on it (`step.t`), bracketed and solved by
/// [`illinois`] to `step.width`:
/// - the step's own sample where its value is within `step.rounding` (nothing left to
///   bracket, and maybe no sign change to find past it);
/// - else, where the step crosses the root, the bracket [0, step];
/// - else, where it falls short but cuts the value at least eightfold, the bracket from the
///   step to past it by twice the secant's estimate of what is left.
///
/// None where the step cuts the value less than eightfold (an even root, as a tangent
/// contact's: Newton cuts that fourfold, and the value keeps its sign), where the point past
/// the step lies beyond `step.reach` (not evaluated there) or brackets no root, where `f0` or
/// the step is not finite, or where `f` returns None or a value that is not finite.
///
/// `start` is the payload at 0 where `f0` is `f`'s own value there. None where `f0` was
/// computed otherwise (`across`'s gap to b's unprojected foot): `f` is then evaluated at 0 for
/// the bracket [0, step] (after the step, and only there), and that value's sign must differ
/// from the step's (an exact zero counts with its sign).
pub fn from_newton_step<P>(
    mut f: impl FnMut(f64) -> Option<(f64, P)>,
    step: NewtonStep,
    start: Option<P>,
) -> Option<At<P>> {
    let NewtonStep { f0, t, unit, .. } = step;
    if !(f0.is_finite() && t.is_finite()) {
        return None;
    }
    let (f1, payload) = f(t)?;
    let one = At { t, f: f1, payload };
    if f1.abs() <= step.rounding {
        return Some(one);
    }
    let (lo, hi) = if f1.signum() != f0.signum() {
        let zero = At::at_zero(f0, start, &mut f)?;
        (zero, one)
    } else if 8.0 * f1.abs() > f0.abs() {
        return None;
    } else {
        let beyond = t + 2.0 * t * f1 / (f0 - f1);
        if beyond.is_nan() || beyond.abs() * unit > step.reach {
            return None;
        }
        let (f, payload) = f(beyond)?;
        (
            one,
            At {
                t: beyond,
                f,
                payload,
            },
        )
    };
    if lo.f.signum() == hi.f.signum() {
        return None;
    }
    illinois(f, [lo, hi], Stop::Width(step.width / unit))
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

    /// [`from_newton_step`] on `f` with its argument as the payload, and the arguments `f` was
    /// evaluated at, in order.
    fn from_step(
        f: impl Fn(f64) -> f64,
        step: NewtonStep,
        start: Option<f64>,
    ) -> (Option<At<f64>>, Vec<f64>) {
        let mut seen = Vec::new();
        let r = from_newton_step(
            |t| {
                seen.push(t);
                Some((f(t), t))
            },
            step,
            start,
        );
        (r, seen)
    }

    /// Newton's step from 0 on `f` with slope `slope` there, its argument's unit 1 long.
    fn newton(f: impl Fn(f64) -> f64, slope: f64, reach: f64, width: f64) -> NewtonStep {
        NewtonStep {
            f0: f(0.0),
            t: -f(0.0) / slope,
            unit: 1.0,
            reach,
            width,
            rounding: 1e-16,
        }
    }

    #[test]
    fn a_step_onto_the_root_to_rounding_is_kept_though_no_sign_change_lies_past_it() {
        // t − 1 − 1e-17 has its root at 1 + 1e-17, between 1 and the next float: no argument
        // has a value of the other sign within reach of the step (which lands on 1, −1e-17,
        // the start's sign), and twice the secant's estimate past it rounds back onto 1. The
        // step is as near the root as floats get, and comes back without another evaluation.
        let f = |t: f64| t - 1.0 - 1e-17;
        let step = newton(f, 1.0, 4.0, 1e-12);
        assert_eq!((step.f0, step.t), (-1.0, 1.0));
        let (r, seen) = from_step(f, step, Some(0.0));
        let r = r.expect("the step's point");
        assert_eq!((r.t, r.f, r.payload), (1.0, -1e-17, 1.0));
        assert_eq!(seen, [1.0]);
        // Over the rounding it is not kept: t − 1 − 1e-15 is −1e-15 at the step, its root
        // 4.5 floats past 1, bracketed past the step and solved to its last float.
        let g = |t: f64| t - 1.0 - 1e-15;
        let step = NewtonStep {
            f0: -1.0,
            width: 1e-17,
            ..step
        };
        let (r, seen) = from_step(g, step, Some(0.0));
        let r = r.expect("a root past the step");
        assert!(r.t > 1.0 && (r.t - 1.0 - 1e-15).abs() <= 2.3e-16, "{r:?}");
        assert!(seen.len() > 1, "{seen:?}");
    }

    #[test]
    fn a_step_across_the_root_is_bracketed_with_the_start() {
        // e^t − 2 from 0 (value −1, slope 1): the step lands on 1, past the root ln 2.
        let f = |t: f64| t.exp() - 2.0;
        let step = newton(f, 1.0, 4.0, 1e-12);
        let (r, seen) = from_step(f, step, Some(0.0));
        let r = r.expect("ln 2");
        assert!((r.t - 2f64.ln()).abs() <= 1e-12, "{r:?}");
        assert_eq!((r.f, r.payload), (f(r.t), r.t));
        // The start's sample is the caller's: not evaluated again.
        assert_eq!(seen[0], 1.0);
        assert!(!seen.contains(&0.0), "{seen:?}");
        // Without it, `f` is evaluated at 0, once, after the step.
        let (r, seen) = from_step(f, step, None);
        assert!((r.expect("ln 2").t - 2f64.ln()).abs() <= 1e-12);
        assert_eq!(seen[..2], [1.0, 0.0]);
        assert_eq!(seen.iter().filter(|t| **t == 0.0).count(), 1, "{seen:?}");
    }

    #[test]
    fn a_start_whose_own_value_has_the_steps_sign_brackets_nothing() {
        // f0 computed otherwise (−1) where `f`'s own value at 0 is of the step's sign: e^t −
        // 0.5 is positive on [0, 1], with no root there, and so is 1 − e^(−t) but for its
        // exact zero at 0, which counts with its sign (+0): neither is bracketed.
        let fs: [fn(f64) -> f64; 2] = [|t| t.exp() - 0.5, |t| 1.0 - (-t).exp()];
        for f in fs {
            let step = NewtonStep {
                f0: -1.0,
                t: 1.0,
                unit: 1.0,
                reach: 4.0,
                width: 1e-12,
                rounding: 1e-16,
            };
            assert!(f(0.0) >= 0.0 && f(0.0).is_sign_positive() && f(1.0) > 0.0);
            let (r, seen) = from_step(f, step, None);
            assert!(r.is_none(), "{r:?}");
            assert_eq!(seen, [1.0, 0.0]);
        }
    }

    #[test]
    fn a_step_short_of_the_root_is_followed_past_it_by_twice_the_secants_estimate() {
        // ln(1 + 0.3 t) − ln 1.3, root 1, concave: Newton from 0 (slope 0.3) lands short, at
        // ln(1.3)/0.3 = 0.8745, its value cut 8.9-fold; once the secant's estimate of what is
        // left reaches 0.985 (still short), twice it 1.095 (past the root).
        let f = |t: f64| (0.3 * t).ln_1p() - 1.3f64.ln();
        let step = newton(f, 0.3, 4.0, 1e-12);
        let f1 = f(step.t);
        assert!(f1 < 0.0 && 8.0 * f1.abs() < step.f0.abs(), "{f1}");
        let (r, seen) = from_step(f, step, Some(0.0));
        let r = r.expect("the root 1");
        assert!((r.t - 1.0).abs() <= 1e-12 && r.f == f(r.t), "{r:?}");
        let beyond = seen[1];
        assert!((beyond - 1.0951).abs() <= 1e-4, "{seen:?}");
        // The reach and the width are measured in the argument's unit's length: here 100
        // long, the point past the step lies 109.5 away, and the width of 0.5 is 0.005 in t
        // (the first bracket, [0.87, 1.10], is under 0.5 wide).
        let long = NewtonStep {
            unit: 100.0,
            reach: 110.0,
            width: 0.5,
            ..step
        };
        let (r, _) = from_step(f, long, Some(0.0));
        let r = r.expect("the root 1");
        assert!((r.t - 1.0).abs() <= 0.005, "{r:?}");
        // Out of reach: None, and `f` not evaluated there (it may not be able to).
        let short = NewtonStep {
            reach: 109.0,
            ..long
        };
        let (r, seen) = from_step(f, short, Some(0.0));
        assert!(r.is_none(), "{r:?}");
        assert_eq!(seen, [step.t]);
    }

    #[test]
    fn a_step_that_cuts_the_value_less_than_eightfold_finds_no_root() {
        // Newton on a double root cuts the value fourfold: (t − 1)² from 0 lands on 0.5, 0.25.
        // No root to find (none is bracketed either way).
        let double = |t: f64| (t - 1.0) * (t - 1.0);
        let (r, _) = from_step(double, newton(double, -2.0, 4.0, 1e-12), Some(0.0));
        assert!(r.is_none(), "{r:?}");
        // Two roots 0.6 apart about a minimum (a tangent contact's near-double zero, seen
        // from afar): the step to 0.455 cuts the value 4.4-fold, and twice the secant's
        // estimate past it would reach 0.72, past the root 0.7. That is not taken for a
        // simple root's.
        let pair = |t: f64| (t - 1.0) * (t - 1.0) - 0.09;
        let step = newton(pair, -2.0, 4.0, 1e-12);
        let f1 = pair(step.t);
        assert!(f1 > 0.0 && 8.0 * f1 > step.f0 && 4.0 * f1 < step.f0, "{f1}");
        let (r, seen) = from_step(pair, step, Some(0.0));
        assert!(r.is_none(), "{r:?}");
        assert_eq!(seen, [step.t]);
    }

    #[test]
    fn a_step_or_value_that_is_not_a_number_finds_no_root() {
        let f = |t: f64| t - 0.5;
        let unused = |_: f64| -> Option<(f64, ())> { panic!("no evaluation needed") };
        let step = NewtonStep {
            f0: -0.5,
            t: 0.5,
            unit: 1.0,
            reach: 4.0,
            width: 1e-12,
            rounding: 0.0,
        };
        for bad in [
            NewtonStep {
                t: f64::NAN,
                ..step
            },
            NewtonStep {
                f0: f64::NEG_INFINITY,
                ..step
            },
        ] {
            assert!(from_newton_step(unused, bad, Some(())).is_none());
        }
        // `f` None or not a number at the step, or None past it.
        assert!(from_newton_step(|_| None::<(f64, ())>, step, Some(())).is_none());
        assert!(from_step(|_| f64::NAN, step, Some(0.0)).0.is_none());
        let short = NewtonStep { t: 0.45, ..step };
        assert!(from_step(f, short, Some(0.0)).0.is_some());
        let none_past = |t: f64| (t < 0.46).then_some((f(t), ()));
        assert!(from_newton_step(none_past, short, Some(())).is_none());
    }
}
