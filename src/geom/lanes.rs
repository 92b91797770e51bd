//! Two f64 lanes and their lane masks: one SSE2 register on x86-64, a plain pair elsewhere.
//!
//! For the closed forms' hot paths, which handle the two hits of a pair side by side (the
//! fast `atan2`, the parameters of points on an arc) with selects instead of branches:
//! whether a hit's angle is negative, or on the arc, is a coin toss, and a mispredicted
//! branch costs more than both sides of a select. Both implementations do the same IEEE
//! operations, so results are bit for bit the same on every target.

use std::ops::{Add, Div, Mul, Neg, Sub};

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod imp {
    use std::arch::x86_64::*;

    pub type F = __m128d;
    pub type M = __m128d;

    // SAFETY (every block below): SSE2 is enabled for this build (the x86-64 baseline).
    #[inline(always)]
    pub fn new(a: f64, b: f64) -> F {
        unsafe { _mm_set_pd(b, a) }
    }
    #[inline(always)]
    pub fn splat(a: f64) -> F {
        unsafe { _mm_set1_pd(a) }
    }
    #[inline(always)]
    pub fn get(v: F) -> [f64; 2] {
        unsafe { [_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))] }
    }
    #[inline(always)]
    pub fn add(a: F, b: F) -> F {
        unsafe { _mm_add_pd(a, b) }
    }
    #[inline(always)]
    pub fn sub(a: F, b: F) -> F {
        unsafe { _mm_sub_pd(a, b) }
    }
    #[inline(always)]
    pub fn mul(a: F, b: F) -> F {
        unsafe { _mm_mul_pd(a, b) }
    }
    #[inline(always)]
    pub fn div(a: F, b: F) -> F {
        unsafe { _mm_div_pd(a, b) }
    }
    #[inline(always)]
    pub fn max(a: F, b: F) -> F {
        unsafe { _mm_max_pd(a, b) }
    }
    #[inline(always)]
    pub fn min(a: F, b: F) -> F {
        unsafe { _mm_min_pd(a, b) }
    }
    /// The sign bit of every lane.
    #[inline(always)]
    fn sign() -> F {
        splat(-0.0)
    }
    #[inline(always)]
    pub fn abs(a: F) -> F {
        unsafe { _mm_andnot_pd(sign(), a) }
    }
    #[inline(always)]
    pub fn neg(a: F) -> F {
        unsafe { _mm_xor_pd(sign(), a) }
    }
    /// |a| with the sign of `s`.
    #[inline(always)]
    pub fn copysign(a: F, s: F) -> F {
        unsafe { _mm_or_pd(_mm_andnot_pd(sign(), a), _mm_and_pd(sign(), s)) }
    }
    #[inline(always)]
    pub fn lt(a: F, b: F) -> M {
        unsafe { _mm_cmplt_pd(a, b) }
    }
    #[inline(always)]
    pub fn le(a: F, b: F) -> M {
        unsafe { _mm_cmple_pd(a, b) }
    }
    #[inline(always)]
    pub fn gt(a: F, b: F) -> M {
        unsafe { _mm_cmpgt_pd(a, b) }
    }
    #[inline(always)]
    pub fn ge(a: F, b: F) -> M {
        unsafe { _mm_cmpge_pd(a, b) }
    }
    #[inline(always)]
    pub fn and(m: M, n: M) -> M {
        unsafe { _mm_and_pd(m, n) }
    }
    #[inline(always)]
    pub fn or(m: M, n: M) -> M {
        unsafe { _mm_or_pd(m, n) }
    }
    /// `a` where the mask is set, else +0.
    #[inline(always)]
    pub fn keep(m: M, a: F) -> F {
        unsafe { _mm_and_pd(m, a) }
    }
    /// `a` where the mask is clear, else +0.
    #[inline(always)]
    pub fn drop(m: M, a: F) -> F {
        unsafe { _mm_andnot_pd(m, a) }
    }
    #[inline(always)]
    pub fn select(m: M, a: F, b: F) -> F {
        unsafe { _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)) }
    }
    /// −a where the mask is set.
    #[inline(always)]
    pub fn negate(m: M, a: F) -> F {
        unsafe { _mm_xor_pd(a, _mm_and_pd(m, sign())) }
    }
    #[inline(always)]
    pub fn bits(m: M) -> u32 {
        unsafe { _mm_movemask_pd(m) as u32 }
    }
}

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
mod imp {
    pub type F = [f64; 2];
    pub type M = [bool; 2];

    #[inline(always)]
    fn map(a: F, f: impl Fn(f64) -> f64) -> F {
        [f(a[0]), f(a[1])]
    }
    #[inline(always)]
    fn zip(a: F, b: F, f: impl Fn(f64, f64) -> f64) -> F {
        [f(a[0], b[0]), f(a[1], b[1])]
    }
    #[inline(always)]
    fn test(a: F, b: F, f: impl Fn(f64, f64) -> bool) -> M {
        [f(a[0], b[0]), f(a[1], b[1])]
    }
    pub fn new(a: f64, b: f64) -> F {
        [a, b]
    }
    pub fn splat(a: f64) -> F {
        [a, a]
    }
    pub fn get(v: F) -> [f64; 2] {
        v
    }
    pub fn add(a: F, b: F) -> F {
        zip(a, b, |x, y| x + y)
    }
    pub fn sub(a: F, b: F) -> F {
        zip(a, b, |x, y| x - y)
    }
    pub fn mul(a: F, b: F) -> F {
        zip(a, b, |x, y| x * y)
    }
    pub fn div(a: F, b: F) -> F {
        zip(a, b, |x, y| x / y)
    }
    /// As `maxpd`: the second operand unless the first is greater (so NaN gives `b`).
    pub fn max(a: F, b: F) -> F {
        zip(a, b, |x, y| if x > y { x } else { y })
    }
    /// As `minpd`: the second operand unless the first is less.
    pub fn min(a: F, b: F) -> F {
        zip(a, b, |x, y| if x < y { x } else { y })
    }
    pub fn abs(a: F) -> F {
        map(a, f64::abs)
    }
    pub fn neg(a: F) -> F {
        map(a, |x| -x)
    }
    pub fn copysign(a: F, s: F) -> F {
        zip(a, s, f64::copysign)
    }
    pub fn lt(a: F, b: F) -> M {
        test(a, b, |x, y| x < y)
    }
    pub fn le(a: F, b: F) -> M {
        test(a, b, |x, y| x <= y)
    }
    pub fn gt(a: F, b: F) -> M {
        test(a, b, |x, y| x > y)
    }
    pub fn ge(a: F, b: F) -> M {
        test(a, b, |x, y| x >= y)
    }
    pub fn and(m: M, n: M) -> M {
        [m[0] && n[0], m[1] && n[1]]
    }
    pub fn or(m: M, n: M) -> M {
        [m[0] || n[0], m[1] || n[1]]
    }
    pub fn keep(m: M, a: F) -> F {
        select(m, a, [0.0; 2])
    }
    pub fn drop(m: M, a: F) -> F {
        select(m, [0.0; 2], a)
    }
    pub fn select(m: M, a: F, b: F) -> F {
        [
            if m[0] { a[0] } else { b[0] },
            if m[1] { a[1] } else { b[1] },
        ]
    }
    pub fn bits(m: M) -> u32 {
        m[0] as u32 | (m[1] as u32) << 1
    }
    pub fn negate(m: M, a: F) -> F {
        select(m, neg(a), a)
    }
}

/// Two f64 lanes.
#[derive(Clone, Copy)]
pub(crate) struct F2(imp::F);

/// A mask per lane (from a comparison of two `F2`).
#[derive(Clone, Copy)]
pub(crate) struct M2(imp::M);

impl F2 {
    #[inline(always)]
    pub fn new(a: f64, b: f64) -> F2 {
        F2(imp::new(a, b))
    }
    #[inline(always)]
    pub fn splat(a: f64) -> F2 {
        F2(imp::splat(a))
    }
    #[inline(always)]
    pub fn get(self) -> [f64; 2] {
        imp::get(self.0)
    }
    #[inline(always)]
    pub fn max(self, o: F2) -> F2 {
        F2(imp::max(self.0, o.0))
    }
    #[inline(always)]
    pub fn min(self, o: F2) -> F2 {
        F2(imp::min(self.0, o.0))
    }
    #[inline(always)]
    pub fn abs(self) -> F2 {
        F2(imp::abs(self.0))
    }
    /// `self`'s magnitude with the sign of `s`.
    #[inline(always)]
    pub fn copysign(self, s: F2) -> F2 {
        F2(imp::copysign(self.0, s.0))
    }
    #[inline(always)]
    pub fn lt(self, o: F2) -> M2 {
        M2(imp::lt(self.0, o.0))
    }
    #[inline(always)]
    pub fn le(self, o: F2) -> M2 {
        M2(imp::le(self.0, o.0))
    }
    #[inline(always)]
    pub fn gt(self, o: F2) -> M2 {
        M2(imp::gt(self.0, o.0))
    }
    #[inline(always)]
    pub fn ge(self, o: F2) -> M2 {
        M2(imp::ge(self.0, o.0))
    }
}

impl M2 {
    #[inline(always)]
    pub fn and(self, o: M2) -> M2 {
        M2(imp::and(self.0, o.0))
    }
    #[inline(always)]
    pub fn or(self, o: M2) -> M2 {
        M2(imp::or(self.0, o.0))
    }
    /// `a` in the set lanes, `b` in the others.
    #[inline(always)]
    pub fn select(self, a: F2, b: F2) -> F2 {
        F2(imp::select(self.0, a.0, b.0))
    }
    /// `a` in the set lanes, +0 in the others.
    #[inline(always)]
    pub fn keep(self, a: F2) -> F2 {
        F2(imp::keep(self.0, a.0))
    }
    /// `a` in the clear lanes, +0 in the set ones.
    #[inline(always)]
    pub fn drop(self, a: F2) -> F2 {
        F2(imp::drop(self.0, a.0))
    }
    /// −a in the set lanes, a in the others.
    #[inline(always)]
    pub fn negate(self, a: F2) -> F2 {
        F2(imp::negate(self.0, a.0))
    }
    /// Bit i set when lane i is.
    #[inline(always)]
    pub fn bits(self) -> u32 {
        imp::bits(self.0)
    }
}

macro_rules! binop {
    ($tr:ident, $f:ident) => {
        impl $tr for F2 {
            type Output = F2;
            #[inline(always)]
            fn $f(self, o: F2) -> F2 {
                F2(imp::$f(self.0, o.0))
            }
        }
    };
}
binop!(Add, add);
binop!(Sub, sub);
binop!(Mul, mul);
binop!(Div, div);

impl Neg for F2 {
    type Output = F2;
    #[inline(always)]
    fn neg(self) -> F2 {
        F2(imp::neg(self.0))
    }
}
