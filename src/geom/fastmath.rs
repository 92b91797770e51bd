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
    let (ay, ax) = (y.abs(), x.abs());
    // Both zero, non-finite or near overflow (ay + ax below): std handles it.
    let big = ay.max(ax);
    if big.is_nan() || big >= 1e300 || big == 0.0 {
        return y.atan2(x);
    }
    let (base, more, t) = if ay > T3P8 * ax {
        (FRAC_PI_2, MOREBITS, -ax / ay)
    } else if ay <= 0.66 * ax {
        (0.0, 0.0, ay / ax)
    } else {
        (FRAC_PI_4, 0.5 * MOREBITS, (ay - ax) / (ay + ax))
    };
    let z = t * t;
    // P and Q by Estrin's scheme (shorter dependency chains than Horner).
    let (z2, tz) = (z * z, t * z);
    let z4 = z2 * z2;
    let p = (P[0] * z2 + (P[1] * z + P[2])) * z2 + (P[3] * z + P[4]);
    let q = (z + Q[0]) * z4 + ((Q[1] * z + Q[2]) * z2 + (Q[3] * z + Q[4]));
    let r = base + ((tz * p / q + t) + more);
    // r = atan(|y| / |x|) in [0, π/2]; the left half-plane is π − r (π's low part added back).
    let r = if x < 0.0 {
        (PI - r) + 2.0 * MOREBITS
    } else {
        r
    };
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
