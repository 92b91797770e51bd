//! Printing reals: C's `%g` and the AutoLISP variant used by `princ`, `prin1` and `print`.
//!
//! AutoLISP prints a real through the C runtime's `%g` with 6 significant digits and then makes
//! sure the text still reads back as a real, so a decimal point is always present:
//! `(princ 1.0)` prints `1.0`, `(princ 1e6)` prints `1.0e+06`. Infinities and NaN come out in
//! the Microsoft C runtime's spelling (`1.#INF`, `-1.#IND`), which is what AutoCAD shows.

/// Formats `x` like C's `printf("%.*g", digits, x)`.
///
/// `digits` is the number of significant digits; 0 is taken as 1, as C does, and more than 800
/// as 800. The exponent has
/// at least two digits (`1e+06`), trailing zeros and a trailing point are removed. Non-finite
/// values give C's `inf`, `-inf` and `nan`.
///
/// Method: the C standard's definition of `%g` — with P significant digits and X the decimal
/// exponent of the value *after rounding to P digits*, use fixed notation with P−1−X decimals
/// if P > X ≥ −4, else scientific with P−1 decimals; then strip trailing zeros. Rounding uses
/// Rust's exact decimal conversion (correctly rounded, ties to even on the exact binary value,
/// like glibc and the UCRT).
pub fn format_g(x: f64, digits: usize) -> String {
    if x.is_nan() {
        return "nan".to_string();
    }
    if x.is_infinite() {
        return if x < 0.0 { "-inf" } else { "inf" }.to_string();
    }
    // Beyond 800 digits every f64 is exact (the longest needs 767), so larger requests add
    // only zeros that C would print and that nobody needs; clamping keeps allocation bounded.
    let p = digits.clamp(1, 800);
    // Scientific rendering with P digits gives the post-rounding exponent X.
    // One correctly rounded scientific rendering gives both the digits and the exponent X
    // after rounding; fixed notation with P−1−X decimals rounds at the same digit, so it is
    // these digits with the point moved.
    let sci = format!("{:.*e}", p - 1, x);
    let (mantissa, exp) = sci
        .split_once('e')
        .expect("Rust's {:e} always has an exponent");
    let exp: i32 = exp.parse().expect("Rust's exponent is a plain integer");
    let (negative, mantissa) = match mantissa.strip_prefix('-') {
        Some(m) => (true, m),
        None => (false, mantissa),
    };
    let mut out = String::with_capacity(p + 8);
    if negative {
        out.push('-');
    }
    if exp < -4 || exp >= p as i32 {
        out.push_str(strip_fraction_zeros(mantissa));
        out.push('e');
        out.push(if exp < 0 { '-' } else { '+' });
        let e = exp.unsigned_abs();
        if e < 10 {
            out.push('0');
        }
        out.push_str(&e.to_string());
        return out;
    }
    let digits: Vec<u8> = mantissa.bytes().filter(|b| *b != b'.').collect();
    if exp < 0 {
        out.push_str("0.");
        for _ in 0..(-exp - 1) {
            out.push('0');
        }
        out.push_str(std::str::from_utf8(&digits).expect("ASCII digits"));
    } else {
        let int_len = exp as usize + 1;
        out.push_str(std::str::from_utf8(&digits[..int_len]).expect("ASCII digits"));
        if int_len < digits.len() {
            out.push('.');
            out.push_str(std::str::from_utf8(&digits[int_len..]).expect("ASCII digits"));
        }
    }
    let kept = strip_fraction_zeros(&out).len();
    out.truncate(kept);
    out
}

/// Formats a real the way AutoLISP's `princ`/`prin1`/`print` do: `%g` with 6 significant
/// digits, with a decimal point always present (`.0` is added to the mantissa if `%g` dropped
/// it).
///
/// Decisions, documented because AutoCAD's own output depends on the C runtime:
/// - the exponent has two digits (`1.0e+06`), as the modern UCRT prints; AutoCAD releases built
///   on the old MSVCRT printed three (`1.0e+006`);
/// - negative zero prints `-0.0`, as C's `%g` keeps the sign of zero;
/// - `+∞` → `1.#INF`, `−∞` → `-1.#INF`, and every NaN → `-1.#IND` (the "indefinite" NaN the
///   x87/SSE units produce, which is the only NaN AutoLISP arithmetic can make).
pub fn format_real(x: f64) -> String {
    if x.is_nan() {
        return "-1.#IND".to_string();
    }
    if x.is_infinite() {
        return if x < 0.0 { "-1.#INF" } else { "1.#INF" }.to_string();
    }
    let g = format_g(x, 6);
    match g.split_once('e') {
        Some((mantissa, exp)) if !mantissa.contains('.') => format!("{mantissa}.0e{exp}"),
        Some(_) => g,
        None if g.contains('.') => g,
        None => g + ".0",
    }
}

/// Removes trailing zeros after a decimal point, and the point itself if nothing follows it.
fn strip_fraction_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_g_matches_c_printf() {
        // Expected strings are glibc's printf("%g") / printf("%.Ng") output.
        let cases: &[(f64, usize, &str)] = &[
            (0.0, 6, "0"),
            (1.0, 6, "1"),
            (-1.0, 6, "-1"),
            (0.5, 6, "0.5"),
            (std::f64::consts::PI, 6, "3.14159"),
            (100000.0, 6, "100000"),
            (999999.0, 6, "999999"),
            (999999.5, 6, "1e+06"),
            (1e6, 6, "1e+06"),
            (123456789.0, 6, "1.23457e+08"),
            (0.0001, 6, "0.0001"),
            (0.00001, 6, "1e-05"),
            (0.000123456789, 6, "0.000123457"),
            (1.5e-7, 6, "1.5e-07"),
            (1e100, 6, "1e+100"),
            (1e-300, 6, "1e-300"),
            (2.5, 1, "2"),
            (3.5, 1, "4"),
            (0.1, 17, "0.10000000000000001"),
            (1234.5678, 2, "1.2e+03"),
            (1234.5678, 0, "1e+03"),
            (12.0, 2, "12"),
            (99.5, 2, "1e+02"),
            (-0.0, 6, "-0"),
            (f64::MAX, 6, "1.79769e+308"),
            (f64::MIN_POSITIVE, 6, "2.22507e-308"),
            (5e-324, 6, "4.94066e-324"),
        ];
        for &(x, p, want) in cases {
            assert_eq!(format_g(x, p), want, "format_g({x:e}, {p})");
        }
    }

    #[test]
    fn format_g_huge_precision_is_bounded() {
        let text = format_g(0.1, usize::MAX);
        assert!(text.starts_with("0.1000000000000000055511151231257827"));
        assert!(text.len() < 900);
        assert_eq!(format_g(0.5, 10_000), "0.5");
    }

    #[test]
    fn format_g_non_finite_is_c_spelling() {
        assert_eq!(format_g(f64::INFINITY, 6), "inf");
        assert_eq!(format_g(f64::NEG_INFINITY, 6), "-inf");
        assert_eq!(format_g(f64::NAN, 6), "nan");
    }

    // AutoLISP reference, "princ": reals print with 6 significant digits; the examples below
    // are what AutoCAD's command line echoes for `(princ x)` / `!x`.
    #[test]
    fn format_real_always_shows_a_decimal_point() {
        let cases: &[(f64, &str)] = &[
            (1.0, "1.0"),
            (0.0, "0.0"),
            (-2.0, "-2.0"),
            (std::f64::consts::PI, "3.14159"),
            (100000.0, "100000.0"),
            (1e6, "1.0e+06"),
            (1.5e-7, "1.5e-07"),
            (0.1, "0.1"),
            (123456789.0, "1.23457e+08"),
            (0.75, "0.75"),
            (-12.5, "-12.5"),
            (1e-5, "1.0e-05"),
            (2.0 / 3.0, "0.666667"),
            (1e20, "1.0e+20"),
        ];
        for &(x, want) in cases {
            assert_eq!(format_real(x), want, "format_real({x:e})");
        }
    }

    #[test]
    fn format_real_negative_zero_keeps_its_sign() {
        assert_eq!(format_real(-0.0), "-0.0");
    }

    #[test]
    fn format_real_non_finite_uses_msvc_spelling() {
        assert_eq!(format_real(f64::INFINITY), "1.#INF");
        assert_eq!(format_real(f64::NEG_INFINITY), "-1.#INF");
        assert_eq!(format_real(f64::NAN), "-1.#IND");
        assert_eq!(format_real(-f64::NAN), "-1.#IND");
    }

    #[test]
    fn format_real_reads_back_as_a_number_within_print_precision() {
        for &x in &[1.0, 12345.6, 1e-9, 7.25e33, -0.000321] {
            let text = format_real(x);
            let back: f64 = text.parse().unwrap();
            assert!(((back - x) / x).abs() < 5e-6, "{x} -> {text}");
        }
    }

    /// The C library's own `%.*g`, as the oracle for `format_g`.
    #[cfg(unix)]
    fn c_printf_g(x: f64, digits: usize) -> String {
        use std::ffi::{c_char, c_int, CStr};
        extern "C" {
            fn snprintf(buf: *mut c_char, size: usize, fmt: *const c_char, ...) -> c_int;
        }
        let mut buf = [0 as c_char; 64];
        // SAFETY: the buffer is 64 bytes and snprintf is told so; the format takes an int
        // precision and a double, which are what is passed.
        unsafe {
            snprintf(
                buf.as_mut_ptr(),
                buf.len(),
                c"%.*g".as_ptr(),
                digits as c_int,
                x,
            );
            CStr::from_ptr(buf.as_ptr()).to_string_lossy().into_owned()
        }
    }

    #[cfg(unix)]
    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        #[test]
        fn format_g_agrees_with_libc(bits in proptest::num::u64::ANY, digits in 0usize..18) {
            let x = f64::from_bits(bits);
            proptest::prop_assume!(x.is_finite());
            proptest::prop_assert_eq!(format_g(x, digits), c_printf_g(x, digits));
        }

        #[test]
        fn format_g_agrees_with_libc_on_ordinary_values(
            m in -1_000_000i64..1_000_000, e in -12i32..12, digits in 1usize..9,
        ) {
            let x = m as f64 * 10f64.powi(e) / 7.0;
            proptest::prop_assert_eq!(format_g(x, digits), c_printf_g(x, digits));
        }
    }
}
