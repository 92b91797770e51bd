//! A fast full-precision `atan2` for the hot paths (circle and arc parameters of hits).
//!
//! glibc's `atan2` is correctly rounded and pays for it with a slow multi-stage path; the
//! intersections only need ~1 ulp. This is Cephes' `atan` (S. L. Moshier, Cephes Math Library,
//! atan.c: range reduction to |t| ≤ tan(π/8) about 0, π/4 or π/2, then the rational
//! approximation t + t³·P(t²)/Q(t²), peak relative error ≈ 1e-16), with the reduction done
//! directly on |y| and |x| so no ratio is rounded twice. Quadrant and sign are restored
//! exactly: the result always has the sign of `y`, as std's, so an angle just below the seam
//! never flips to just above it.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

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
    if special(y, x) {
        return y.atan2(x);
    }
    kernel(y, x)
}

/// `atan2` of two pairs at once (the two hits of a circle pair), bit for bit the same as
/// two calls of `atan2`. On x86-64 both lanes run in one SSE2 register.
#[inline(always)]
pub fn atan2_2(y: [f64; 2], x: [f64; 2]) -> [f64; 2] {
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    // SAFETY: SSE2 is enabled for this build (it is part of the x86-64 baseline).
    let mut r = unsafe { kernel2(y, x) };
    #[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
    let mut r = kernel2(y, x);
    for i in 0..2 {
        if special(y[i], x[i]) {
            r[i] = y[i].atan2(x[i]);
        }
    }
    r
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
#[inline(always)]
fn kernel2(y: [f64; 2], x: [f64; 2]) -> [f64; 2] {
    [kernel(y[0], x[0]), kernel(y[1], x[1])]
}

/// `kernel` on two lanes, operation for operation (so the results are identical).
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[inline(always)]
unsafe fn kernel2(y: [f64; 2], x: [f64; 2]) -> [f64; 2] {
    use std::arch::x86_64::*;
    let k = _mm_set1_pd;
    let sel = |m: __m128d, a: __m128d, b: __m128d| _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b));
    let sign = k(-0.0);
    let (y, x) = (_mm_set_pd(y[1], y[0]), _mm_set_pd(x[1], x[0]));
    let (ay, ax) = (_mm_andnot_pd(sign, y), _mm_andnot_pd(sign, x));
    let hi = _mm_cmpgt_pd(ay, _mm_mul_pd(k(T3P8), ax));
    let lo = _mm_cmple_pd(ay, _mm_mul_pd(k(0.66), ax));
    let pick = |h: __m128d, l: __m128d, m: __m128d| sel(hi, h, sel(lo, l, m));
    let num = pick(_mm_xor_pd(ax, sign), ay, _mm_sub_pd(ay, ax));
    let den = pick(ay, ax, _mm_add_pd(ay, ax));
    let base = pick(k(FRAC_PI_2), k(0.0), k(FRAC_PI_4));
    let more = pick(k(MOREBITS), k(0.0), k(0.5 * MOREBITS));
    let (add, mul) = (_mm_add_pd, _mm_mul_pd);
    let t = _mm_div_pd(num, den);
    let z = mul(t, t);
    let (z2, tz) = (mul(z, z), mul(t, z));
    let z4 = mul(z2, z2);
    let p = add(
        mul(add(mul(k(P[0]), z2), add(mul(k(P[1]), z), k(P[2]))), z2),
        add(mul(k(P[3]), z), k(P[4])),
    );
    let q = add(
        mul(add(z, k(Q[0])), z4),
        add(
            mul(add(mul(k(Q[1]), z), k(Q[2])), z2),
            add(mul(k(Q[3]), z), k(Q[4])),
        ),
    );
    let r = add(base, add(add(_mm_div_pd(mul(tz, p), q), t), more));
    let left = add(_mm_sub_pd(k(PI), r), k(2.0 * MOREBITS));
    let r = sel(_mm_cmplt_pd(x, k(0.0)), left, r);
    let r = _mm_or_pd(_mm_andnot_pd(sign, r), _mm_and_pd(sign, y));
    [_mm_cvtsd_f64(r), _mm_cvtsd_f64(_mm_unpackhi_pd(r, r))]
}

/// Both zero, non-finite or near overflow (|y| + |x| in the kernel): std handles those.
#[inline(always)]
fn special(y: f64, x: f64) -> bool {
    let big = y.abs().max(x.abs());
    // One test: false for NaN, for zero and from 1e300 up.
    !(big > 0.0 && big < 1e300)
}

/// The reduction and the rational approximation, for finite (y, x) not both zero.
#[inline(always)]
fn kernel(y: f64, x: f64) -> f64 {
    let (ay, ax) = (y.abs(), x.abs());
    // The reduction is chosen by selects, as `kernel2` must do it lane by lane: the two
    // stay operation for operation the same, so their results are bit for bit equal.
    let (hi, lo) = (ay > T3P8 * ax, ay <= 0.66 * ax);
    let pick = |h: f64, l: f64, m: f64| {
        if hi {
            h
        } else if lo {
            l
        } else {
            m
        }
    };
    let num = pick(-ax, ay, ay - ax);
    let den = pick(ay, ax, ay + ax);
    let base = pick(FRAC_PI_2, 0.0, FRAC_PI_4);
    let more = pick(MOREBITS, 0.0, 0.5 * MOREBITS);
    let t = num / den;
    let z = t * t;
    // P and Q by Estrin's scheme (shorter dependency chains than Horner).
    let (z2, tz) = (z * z, t * z);
    let z4 = z2 * z2;
    let p = (P[0] * z2 + (P[1] * z + P[2])) * z2 + (P[3] * z + P[4]);
    let q = (z + Q[0]) * z4 + ((Q[1] * z + Q[2]) * z2 + (Q[3] * z + Q[4]));
    let r = base + ((tz * p / q + t) + more);
    // r = atan(|y| / |x|) in [0, π/2]; the left half-plane is π − r (π's low part added back).
    let left = (PI - r) + 2.0 * MOREBITS;
    let r = if x < 0.0 { left } else { r };
    r.copysign(y)
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

    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn f(&mut self) -> f64 {
            (self.next() >> 11) as f64 / (1u64 << 53) as f64
        }
    }

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
