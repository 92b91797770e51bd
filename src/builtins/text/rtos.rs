//! `rtos`: a real as text in AutoCAD's linear unit formats (LUNITS modes 1–5).
//!
//! AutoLISP reference, "rtos" — with DIMZIN 0 and UNITMODE 0:
//! `(rtos 17.5 1 4)` → `"1.7500E+01"`, `(rtos 17.5 2 4)` → `"17.5000"`,
//! `(rtos 17.5 3 4)` → `"1'-5.5000\""`, `(rtos 17.5 4 4)` → `"1'-5 1/2\""`,
//! `(rtos 17.5 5 4)` → `"17 1/2"`.
//!
//! DIMZIN (AutoCAD system variable reference) is read as two fields:
//! - the low two bits are a choice for feet-and-inches (modes 3 and 4):
//!   0 suppresses zero feet and precisely zero inches, 1 includes both, 2 includes zero feet
//!   and suppresses zero inches, 3 includes zero inches and suppresses zero feet;
//! - bit 4 suppresses leading zeros and bit 8 trailing zeros of decimals (modes 1, 2, 3).
//!
//! UNITMODE 1 writes feet-inches and fractions the way they are typed at the command line:
//! `1'5-1/2"` and `17-1/2` instead of `1'-5 1/2"` and `17 1/2`.

use super::decimal::{fixed_abs, scientific_abs, suppress_zeros};
use super::FmtError;

/// Largest precision accepted for the decimal modes 1–3. `(rtos pi 2 16)` is a common idiom
/// for "all the digits", so decimals go beyond LUPREC's 8.
pub const MAX_DECIMAL_PRECISION: i32 = 16;
/// Largest precision for the fraction modes 4–5: denominators up to 2⁸ = 256, as LUPREC allows.
pub const MAX_FRACTION_PRECISION: i32 = 8;

/// Formats `x` in linear unit mode `mode` (1 scientific, 2 decimal, 3 engineering, 4
/// architectural, 5 fractional) with precision `prec`, the DIMZIN value `dimzin` and the
/// UNITMODE value `unitmode` (only bit 1 is used).
///
/// Modes 3 and 4 take `x` in inches. Decimals round half away from zero on the value as
/// written (see `decimal`); fractions round to the nearest 1/2^prec, half away from zero, and
/// are reduced (`1/2`, not `4/8`). A value that rounds to zero is printed without a minus sign.
///
/// Errors: `mode` outside 1..=5, `prec` outside 0..=16 (modes 1–3) or 0..=8 (modes 4–5),
/// a non-finite `x`, or a value too large for whole feet/fraction counts in 64 bits.
pub fn rtos(x: f64, mode: i32, prec: i32, dimzin: i32, unitmode: i32) -> Result<String, FmtError> {
    if !(1..=5).contains(&mode) {
        return Err(FmtError::Mode {
            function: "rtos",
            mode: i64::from(mode),
            min: 1,
            max: 5,
        });
    }
    let max_prec = if mode >= 4 {
        MAX_FRACTION_PRECISION
    } else {
        MAX_DECIMAL_PRECISION
    };
    if !(0..=max_prec).contains(&prec) {
        return Err(FmtError::Precision {
            function: "rtos",
            precision: i64::from(prec),
            max: i64::from(max_prec),
        });
    }
    if !x.is_finite() {
        return Err(FmtError::NonFinite { function: "rtos" });
    }
    let decimals = prec as usize;
    let typed_form = unitmode & 1 != 0;
    let (body, zero) = match mode {
        1 => {
            let (text, zero) = scientific_abs(x, decimals);
            (suppress_zeros(&text, dimzin), zero)
        }
        2 => {
            let (text, zero) = fixed_abs(x, decimals);
            (suppress_zeros(&text, dimzin), zero)
        }
        3 => engineering(x.abs(), decimals, dimzin, typed_form)?,
        4 => architectural(x.abs(), prec, dimzin, typed_form)?,
        _ => fractional(x.abs(), prec, typed_form)?,
    };
    Ok(if x < 0.0 && !zero {
        format!("-{body}")
    } else {
        body
    })
}

/// Joins feet and an inch text as DIMZIN's low two bits ask. `inches_zero` is true when the
/// inches are precisely zero after rounding.
fn feet_and_inches(
    feet: u64,
    inches: &str,
    inches_zero: bool,
    dimzin: i32,
    typed_form: bool,
) -> String {
    let choice = dimzin & 3;
    let show_feet = feet != 0 || choice == 1 || choice == 2;
    let show_inches = !inches_zero || choice == 1 || choice == 3 || !show_feet;
    match (show_feet, show_inches) {
        (true, true) if typed_form => format!("{feet}'{inches}\""),
        (true, true) => format!("{feet}'-{inches}\""),
        (true, false) => format!("{feet}'"),
        _ => format!("{inches}\""),
    }
}

/// Mode 3: whole feet and decimal inches (`1'-5.5000"`); `inches` is non-negative.
///
/// The total is rounded once, to whole units of 10^-decimals inch held in an integer, and
/// split into feet and inches there, so a carry (11.99999" → 1') and the split are exact.
fn engineering(
    inches: f64,
    decimals: usize,
    dimzin: i32,
    typed_form: bool,
) -> Result<(String, bool), FmtError> {
    // 1e17 inches with 16 decimals is 1e33 units, inside u128.
    if inches >= 1e17 {
        return Err(FmtError::TooLarge {
            function: "rtos",
            value: inches,
            mode: 3,
        });
    }
    let (text, _) = fixed_abs(inches, decimals);
    let units: u128 = text
        .replace('.', "")
        .parse()
        .expect("fixed_abs writes digits and one point");
    let scale = 10u128.pow(decimals as u32);
    let per_foot = 12 * scale;
    let feet = (units / per_foot) as u64;
    let rest = units % per_foot;
    let mut rest_text = (rest / scale).to_string();
    if decimals > 0 {
        rest_text.push_str(&format!(".{:0width$}", rest % scale, width = decimals));
    }
    let rest_text = suppress_zeros(&rest_text, dimzin);
    let body = feet_and_inches(feet, &rest_text, rest == 0, dimzin, typed_form);
    Ok((body, units == 0))
}

/// Rounds `value` to a whole number of 1/2^prec, half away from zero.
fn to_fraction_units(value: f64, prec: i32, mode: i64) -> Result<u64, FmtError> {
    let scaled = (value * f64::from(1u32 << prec)).round();
    if scaled >= 9.0e18 {
        return Err(FmtError::TooLarge {
            function: "rtos",
            value,
            mode,
        });
    }
    Ok(scaled as u64)
}

/// Writes `units`/2^prec as a whole part and a reduced fraction: `(17, Some("1/2"))`.
fn split_fraction(units: u64, prec: i32) -> (u64, Option<String>) {
    let denominator = 1u64 << prec;
    let whole = units / denominator;
    let mut numerator = units % denominator;
    if numerator == 0 {
        return (whole, None);
    }
    let mut denominator = denominator;
    while numerator.is_multiple_of(2) {
        numerator /= 2;
        denominator /= 2;
    }
    (whole, Some(format!("{numerator}/{denominator}")))
}

/// A mixed number: `17 1/2` (`17-1/2` typed form), `1/2` when the whole part is zero and
/// `keep_zero_whole` is false, `17` without a fraction.
fn mixed_number(
    whole: u64,
    fraction: Option<&str>,
    keep_zero_whole: bool,
    typed_form: bool,
) -> String {
    match fraction {
        None => whole.to_string(),
        Some(f) if whole == 0 && !keep_zero_whole => f.to_string(),
        Some(f) if typed_form => format!("{whole}-{f}"),
        Some(f) => format!("{whole} {f}"),
    }
}

/// Mode 4: whole feet and inches with a fraction (`1'-5 1/2"`); `inches` is non-negative.
fn architectural(
    inches: f64,
    prec: i32,
    dimzin: i32,
    typed_form: bool,
) -> Result<(String, bool), FmtError> {
    let units = to_fraction_units(inches, prec, 4)?;
    let per_foot = 12u64 << prec;
    let feet = units / per_foot;
    let (whole_inches, fraction) = split_fraction(units % per_foot, prec);
    let inches_zero = whole_inches == 0 && fraction.is_none();
    let choice = dimzin & 3;
    let feet_shown = feet != 0 || choice == 1 || choice == 2;
    let text = mixed_number(whole_inches, fraction.as_deref(), feet_shown, typed_form);
    let body = feet_and_inches(feet, &text, inches_zero, dimzin, typed_form);
    Ok((body, units == 0))
}

/// Mode 5: a mixed number (`17 1/2`); `x` is non-negative.
fn fractional(x: f64, prec: i32, typed_form: bool) -> Result<(String, bool), FmtError> {
    let units = to_fraction_units(x, prec, 5)?;
    let (whole, fraction) = split_fraction(units, prec);
    Ok((
        mixed_number(whole, fraction.as_deref(), false, typed_form),
        units == 0,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(x: f64, mode: i32, prec: i32) -> String {
        rtos(x, mode, prec, 0, 0).unwrap()
    }

    // AutoLISP reference, "rtos", examples for 17.5 in each mode.
    #[test]
    fn reference_examples() {
        assert_eq!(r(17.5, 1, 4), "1.7500E+01");
        assert_eq!(r(17.5, 2, 4), "17.5000");
        assert_eq!(r(17.5, 3, 4), "1'-5.5000\"");
        assert_eq!(r(17.5, 4, 4), "1'-5 1/2\"");
        assert_eq!(r(17.5, 5, 4), "17 1/2");
    }

    #[test]
    fn scientific() {
        assert_eq!(r(15.0, 1, 4), "1.5000E+01");
        assert_eq!(r(0.0, 1, 4), "0.0000E+00");
        assert_eq!(r(-0.00123, 1, 2), "-1.23E-03");
        assert_eq!(r(1e100, 1, 1), "1.0E+100");
        assert_eq!(r(-1e-100, 1, 1), "-1.0E-100");
        assert_eq!(r(99999.0, 1, 2), "1.00E+05");
        assert_eq!(rtos(17.5, 1, 4, 8, 0).unwrap(), "1.75E+01");
    }

    #[test]
    fn decimal() {
        assert_eq!(r(1.5, 2, 4), "1.5000");
        assert_eq!(r(2.5, 2, 0), "3");
        assert_eq!(r(-2.5, 2, 0), "-3");
        assert_eq!(r(0.125, 2, 2), "0.13");
        assert_eq!(r(-0.125, 2, 2), "-0.13");
        assert_eq!(r(1.005, 2, 2), "1.01");
        assert_eq!(r(-0.00001, 2, 4), "0.0000");
        assert_eq!(r(-0.0, 2, 2), "0.00");
        assert_eq!(r(123456789.0, 2, 2), "123456789.00");
        assert_eq!(r(std::f64::consts::PI, 2, 8), "3.14159265");
        assert_eq!(r(std::f64::consts::PI, 2, 15), "3.141592653589793");
    }

    #[test]
    fn decimal_dimzin() {
        assert_eq!(rtos(17.5, 2, 4, 8, 0).unwrap(), "17.5");
        assert_eq!(rtos(17.0, 2, 4, 8, 0).unwrap(), "17");
        assert_eq!(rtos(0.5, 2, 4, 4, 0).unwrap(), ".5000");
        assert_eq!(rtos(-0.5, 2, 4, 4, 0).unwrap(), "-.5000");
        assert_eq!(rtos(0.5, 2, 4, 12, 0).unwrap(), ".5");
        assert_eq!(rtos(0.0, 2, 4, 12, 0).unwrap(), "0");
        assert_eq!(rtos(100.0, 2, 0, 8, 0).unwrap(), "100");
        // The feet/inch choices do not touch decimal mode.
        assert_eq!(rtos(0.5, 2, 4, 3, 0).unwrap(), "0.5000");
    }

    #[test]
    fn engineering() {
        assert_eq!(r(15.5, 3, 4), "1'-3.5000\"");
        assert_eq!(r(-15.5, 3, 4), "-1'-3.5000\"");
        assert_eq!(r(6.25, 3, 2), "6.25\"");
        assert_eq!(r(24.0, 3, 2), "2'");
        assert_eq!(r(0.0, 3, 2), "0.00\"");
        assert_eq!(r(23.99999, 3, 2), "2'");
        assert_eq!(r(11.999, 3, 2), "1'");
        assert_eq!(rtos(11.999, 3, 2, 1, 0).unwrap(), "1'-0.00\"");
        assert_eq!(rtos(17.5, 3, 4, 8, 0).unwrap(), "1'-5.5\"");
        assert_eq!(rtos(12.5, 3, 4, 1 | 4, 0).unwrap(), "1'-.5000\"");
        assert_eq!(rtos(17.5, 3, 4, 0, 1).unwrap(), "1'5.5000\"");
        // 1.1' = 13.2", whose binary value is 13.200000000000001.
        assert_eq!(r(1.1 * 12.0, 3, 4), "1'-1.2000\"");
        assert_eq!(r(12.0 * 1000.0 + 0.05, 3, 1), "1000'-0.1\"");
        assert_eq!(r(-0.00001, 3, 2), "0.00\"");
    }

    #[test]
    fn engineering_dimzin_feet_inch_choices() {
        // 0: suppress zero feet and precisely zero inches.
        assert_eq!(rtos(6.0, 3, 1, 0, 0).unwrap(), "6.0\"");
        assert_eq!(rtos(12.0, 3, 1, 0, 0).unwrap(), "1'");
        // 1: include both.
        assert_eq!(rtos(6.0, 3, 1, 1, 0).unwrap(), "0'-6.0\"");
        assert_eq!(rtos(12.0, 3, 1, 1, 0).unwrap(), "1'-0.0\"");
        // 2: include zero feet, suppress zero inches.
        assert_eq!(rtos(6.0, 3, 1, 2, 0).unwrap(), "0'-6.0\"");
        assert_eq!(rtos(12.0, 3, 1, 2, 0).unwrap(), "1'");
        // 3: include zero inches, suppress zero feet.
        assert_eq!(rtos(6.0, 3, 1, 3, 0).unwrap(), "6.0\"");
        assert_eq!(rtos(12.0, 3, 1, 3, 0).unwrap(), "1'-0.0\"");
    }

    #[test]
    fn architectural() {
        assert_eq!(r(17.5, 4, 2), "1'-5 1/2\"");
        assert_eq!(r(-17.5, 4, 2), "-1'-5 1/2\"");
        assert_eq!(r(15.5, 4, 4), "1'-3 1/2\"");
        assert_eq!(r(15.25, 4, 4), "1'-3 1/4\"");
        assert_eq!(r(15.0625, 4, 4), "1'-3 1/16\"");
        assert_eq!(r(15.0625, 4, 3), "1'-3 1/8\"");
        assert_eq!(r(15.0625, 4, 0), "1'-3\"");
        assert_eq!(r(15.5, 4, 0), "1'-4\"");
        assert_eq!(r(11.99, 4, 4), "1'");
        assert_eq!(r(0.5, 4, 4), "1/2\"");
        assert_eq!(r(6.0, 4, 4), "6\"");
        assert_eq!(r(0.0, 4, 4), "0\"");
        assert_eq!(r(12.5, 4, 4), "1'-0 1/2\"");
        assert_eq!(r(1.0 / 256.0, 4, 8), "1/256\"");
        assert_eq!(r(1200.0, 4, 8), "100'");
    }

    #[test]
    fn architectural_dimzin_and_unitmode() {
        assert_eq!(rtos(0.5, 4, 4, 1, 0).unwrap(), "0'-0 1/2\"");
        assert_eq!(rtos(12.0, 4, 4, 1, 0).unwrap(), "1'-0\"");
        assert_eq!(rtos(6.0, 4, 4, 2, 0).unwrap(), "0'-6\"");
        assert_eq!(rtos(12.0, 4, 4, 3, 0).unwrap(), "1'-0\"");
        assert_eq!(rtos(15.5, 4, 4, 0, 1).unwrap(), "1'3-1/2\"");
        assert_eq!(rtos(0.5, 4, 4, 0, 1).unwrap(), "1/2\"");
        // Decimal-only bits do not change fractions.
        assert_eq!(rtos(17.5, 4, 4, 12, 0).unwrap(), "1'-5 1/2\"");
    }

    #[test]
    fn fractional() {
        assert_eq!(r(17.5, 5, 4), "17 1/2");
        assert_eq!(r(-17.5, 5, 4), "-17 1/2");
        assert_eq!(r(0.75, 5, 4), "3/4");
        assert_eq!(r(0.0, 5, 4), "0");
        assert_eq!(r(-0.01, 5, 4), "0");
        assert_eq!(r(3.0, 5, 4), "3");
        assert_eq!(r(2.96875, 5, 4), "3");
        assert_eq!(r(2.96875, 5, 5), "2 31/32");
        assert_eq!(r(0.5, 5, 0), "1");
        assert_eq!(rtos(17.5, 5, 4, 0, 1).unwrap(), "17-1/2");
    }

    #[test]
    fn bad_arguments_are_errors() {
        assert_eq!(
            rtos(1.0, 0, 4, 0, 0),
            Err(FmtError::Mode {
                function: "rtos",
                mode: 0,
                min: 1,
                max: 5
            })
        );
        assert!(rtos(1.0, 6, 4, 0, 0).is_err());
        assert!(rtos(1.0, 2, -1, 0, 0).is_err());
        assert!(rtos(1.0, 2, 17, 0, 0).is_err());
        assert!(rtos(1.0, 2, 16, 0, 0).is_ok());
        assert!(rtos(1.0, 4, 9, 0, 0).is_err());
        assert!(rtos(f64::NAN, 2, 4, 0, 0).is_err());
        assert!(rtos(f64::INFINITY, 1, 4, 0, 0).is_err());
        assert!(rtos(1e300, 4, 8, 0, 0).is_err());
        assert!(rtos(1e300, 3, 4, 0, 0).is_err());
        assert!(rtos(1e300, 2, 2, 0, 0).is_ok());
        assert_eq!(
            rtos(1.0, 9, 4, 0, 0).unwrap_err().to_string(),
            "bad argument value: rtos mode 9 (must be 1..=5)"
        );
    }
}
