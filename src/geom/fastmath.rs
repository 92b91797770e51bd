//! A fast full-precision `atan2` for the hot paths (circle and arc parameters of hits).
//!
//! glibc's `atan2` is correctly rounded and pays for it with a slow multi-stage path; the
//! intersections only need ~1 ulp. This is Cephes' `atan` (S. L. Moshier, Cephes Math Library,
//! atan.c: range reduction to |t| ≤ tan(π/8) about 0, π/4 or π/2, then the rational
//! approximation t + t³·P(t²)/Q(t²), peak relative error ≈ 1e-16), with the reduction done
//! directly on |y| and |x| so no ratio is rounded twice. The left half-plane is folded into
//! the reduction (negated argument, base π − base), so the result is one final sum. The sign
//! is restored exactly: the result always has the sign of `y`, as std's, so an angle just
//! below the seam never flips to just above it. Written on two lanes (`lanes::F2`) with the
//! reduction chosen by masks: the two hits of a pair at once, and no branch on the angle.

use std::f64::consts::FRAC_PI_2;

use super::lanes::{F2, M2};

/// tan(3π/8).
const T3P8: f64 = 2.414_213_562_373_095;
/// The low part of π/2 (π/2 − FRAC_PI_2 in exact arithmetic).
const MOREBITS: f64 = 6.123_233_995_736_766e-17;

const P: [f64; 5] = [
    -8.750_608_600_031_904e-1,
    -1.615_753_718_733_365e1,
    -7.500_855_792_314_705e1,
    -1.228_866_684_490_136_2e2,
    -6.485_021_904_942_025e1,
];
const Q: [f64; 5] = [
    2.485_846_490_142_306_3e1,
    1.650_270_098_316_988_5e2,
    4.328_810_604_912_903e2,
    4.853_903_996_359_137e2,
    1.945_506_571_482_614e2,
];

/// atan2(y, x) within ~1 ulp of std's, with the same sign and the same special values
/// (zeros, infinities and NaN fall back to std).
#[inline(always)]
pub fn atan2(y: f64, x: f64) -> f64 {
    atan2_2([y, y], [x, x])[0]
}

/// `atan2` of two pairs at once (the two hits of a circle pair), bit for bit the same as
/// two calls of `atan2`.
#[inline(always)]
pub fn atan2_2(y: [f64; 2], x: [f64; 2]) -> [f64; 2] {
    atan2_lanes(F2::new(y[0], y[1]), F2::new(x[0], x[1])).get()
}

/// `atan2` lane by lane.
#[inline(always)]
pub(crate) fn atan2_lanes(y: F2, x: F2) -> F2 {
    let (ay, ax) = (y.abs(), x.abs());
    // Both zero, non-finite or near overflow (|y| + |x| below): std handles those. One test
    // per lane: false for NaN, for zero and from 1e300 up.
    let big = ay.max(ax);
    let fine = big.gt(F2::splat(0.0)).and(big.lt(F2::splat(1e300)));
    if fine.bits() != 0b11 {
        return special(y, x, fine);
    }
    kernel(y, x, ay, ax)
}

/// `atan2_lanes` for lanes known finite, below 1e300 in magnitude and not both zero (the
/// direction between two distinct centres of a fitting pair): no special-value test.
#[inline(always)]
pub(crate) fn atan2_lanes_regular(y: F2, x: F2) -> F2 {
    let (ay, ax) = (y.abs(), x.abs());
    debug_assert!({
        let big = ay.max(ax);
        big.gt(F2::splat(0.0)).and(big.lt(F2::splat(1e300))).bits() == 0b11
    });
    kernel(y, x, ay, ax)
}

#[cold]
fn special(y: F2, x: F2, fine: M2) -> F2 {
    let r = kernel(y, x, y.abs(), x.abs()).get();
    let (y, x) = (y.get(), x.get());
    let f = |i: usize| {
        if fine.bits() >> i & 1 == 1 {
            r[i]
        } else {
            y[i].atan2(x[i])
        }
    };
    F2::new(f(0), f(1))
}

/// The reduction and the rational approximation, for finite (y, x) not both zero. The
/// reduction is chosen by masks (num and den built from |y| and |x| with a lane zeroed,
/// which is exact), so no branch depends on the angle.
#[inline(always)]
fn kernel(y: F2, x: F2, ay: F2, ax: F2) -> F2 {
    let k = F2::splat;
    // |y|/|x| above tan(3π/8): about π/2; at most 0.66: about 0; else about π/4.
    let hi = ay.gt(k(T3P8) * ax);
    let lo = ay.le(k(0.66) * ax);
    let not_mid = hi.or(lo);
    // The left half-plane is π − atan(|y| / |x|): there the reduced argument is negated and
    // the base is π − base (exact for 0, π/4 and π/2), low parts included, so the result
    // comes out of one sum.
    let left = x.lt(k(0.0));
    // hi: −|x| / |y|; lo: |y| / |x|; mid: (|y| − |x|) / (|y| + |x|).
    let num = left.negate(hi.drop(ay) - lo.drop(ax));
    let den = lo.drop(ay) + hi.drop(ax);
    // The base angle is c·π/2 for c = 1, 0 or 1/2 (2 − c on the left), with low part
    // c·MOREBITS: both products exact (c·FRAC_PI_2 needs at most one more bit).
    let c = hi.keep(k(1.0)).max(not_mid.drop(k(0.5)));
    let c = left.keep(k(2.0)) + left.negate(c);
    let (base, more) = (c * k(FRAC_PI_2), c * k(MOREBITS));
    let t = num / den;
    let z = t * t;
    // P and Q by Estrin's scheme (shorter dependency chains than Horner).
    let (z2, tz) = (z * z, t * z);
    let z4 = z2 * z2;
    let p = (k(P[0]) * z2 + (k(P[1]) * z + k(P[2]))) * z2 + (k(P[3]) * z + k(P[4]));
    let q = (z + k(Q[0])) * z4 + ((k(Q[1]) * z + k(Q[2])) * z2 + (k(Q[3]) * z + k(Q[4])));
    (base + ((tz * p / q + t) + more)).copysign(y)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance in ulps between two finite doubles of the same sign.
    fn ulps(a: f64, b: f64) -> u64 {
        if a == b {
            return 0;
        }
        assert_eq!(a.is_sign_negative(), b.is_sign_negative(), "{a} vs {b}");
        (a.abs().to_bits() as i64 - b.abs().to_bits() as i64).unsigned_abs()
    }

    use crate::geom::test_rng::Rng;

    fn check(y: f64, x: f64, worst: &mut u64) {
        let (f, s) = (atan2(y, x), y.atan2(x));
        if s.is_nan() {
            assert!(f.is_nan(), "atan2({y}, {x}) = {f}, std NaN");
            return;
        }
        assert_eq!(
            f.is_sign_negative(),
            s.is_sign_negative(),
            "sign of atan2({y}, {x})"
        );
        let u = ulps(f, s);
        assert!(u <= 2, "atan2({y:e}, {x:e}) = {f:e}, std {s:e}: {u} ulps");
        *worst = (*worst).max(u);
    }

    #[test]
    fn matches_std_on_random_inputs() {
        let mut r = Rng(0x2545F4914F6CDD1D);
        let mut worst = 0;
        for i in 0..2_000_000 {
            let (y, x) = match i % 4 {
                // Uniform in a box around the origin (all quadrants).
                0 | 1 => (r.f() * 2.0 - 1.0, r.f() * 2.0 - 1.0),
                // Wide dynamic range in both, random signs.
                2 => {
                    let e1 = (r.f() * 80.0 - 40.0).exp2();
                    let e2 = (r.f() * 80.0 - 40.0).exp2();
                    let sy = if r.next() & 1 == 0 { 1.0 } else { -1.0 };
                    let sx = if r.next() & 1 == 0 { 1.0 } else { -1.0 };
                    (sy * r.f() * e1, sx * r.f() * e2)
                }
                // Near the reduction boundaries and the axes.
                _ => {
                    let x = r.f() * 2.0 - 1.0;
                    let k = [0.66, T3P8, 1.0, 1e-12, 1e12][(r.next() % 5) as usize];
                    let y = x * k * (1.0 + (r.f() - 0.5) * 1e-9);
                    if r.next() & 1 == 0 {
                        (y, x)
                    } else {
                        (-y, x)
                    }
                }
            };
            check(y, x, &mut worst);
        }
        eprintln!("worst {worst} ulps");
        assert!(worst <= 2);
    }

    #[test]
    fn two_lanes_are_bitwise_two_calls() {
        let mut r = Rng(0x9E3779B97F4A7C15);
        let specials = [0.0, -0.0, f64::INFINITY, f64::NAN, 1e300, -1e-310];
        for i in 0..200_000 {
            let mut v = [0.0; 4];
            for x in &mut v {
                *x = if r.next().is_multiple_of(16) {
                    specials[(r.next() % 6) as usize]
                } else {
                    (r.f() * 2.0 - 1.0) * (r.f() * 40.0 - 20.0).exp2()
                };
            }
            let (y, x) = ([v[0], v[1]], [v[2], v[3]]);
            let two = atan2_2(y, x);
            for k in 0..2 {
                let one = atan2(y[k], x[k]);
                assert!(
                    two[k].to_bits() == one.to_bits() || (two[k].is_nan() && one.is_nan()),
                    "case {i}: atan2({:e}, {:e}) = {:e} in lanes, {:e} alone",
                    y[k],
                    x[k],
                    two[k],
                    one
                );
            }
        }
    }

    #[test]
    fn special_values_match_std() {
        let vals = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1e-310,
            -1e-310,
            f64::MIN_POSITIVE,
            1e300,
            -1e300,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            0.66,
            T3P8,
        ];
        let mut worst = 0;
        for &y in &vals {
            for &x in &vals {
                check(y, x, &mut worst);
            }
        }
        // The axes and diagonals exactly.
        for &(y, x) in &[
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (-0.0, -1.0),
            (1.0, 1.0),
        ] {
            assert_eq!(atan2(y, x), y.atan2(x), "atan2({y}, {x})");
        }
    }
}
