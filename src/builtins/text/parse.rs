//! `distof` and `angtof`: reading distances and angles written in AutoCAD's unit formats,
//! the inverses of `rtos` and `angtos`.
//!
//! Distances (AutoLISP reference, "distof"): modes 1, 2 and 5 read numbers — decimal
//! (`17.5`, `.5`), scientific (`1.75E+01`) and fractions (`17 1/2`, `17-1/2`, `1/2`); modes 3
//! and 4 also read feet and inches (`1'-5 1/2"`, `1'5-1/2"`, `1'-5.5"`, `1.5'`, `5 1/2"`, and
//! a bare number as inches). With no mode every form is read, as `getdist` does.
//!
//! Angles (AutoLISP reference, "angtof"): a bare number is in the mode's unit (degrees for 0,
//! 1, 4 and no mode; grads for 2; radians for 3); a suffix always says the unit whatever the
//! mode, as at AutoCAD's angle prompts: `45d30'15"`, `50g`, `0.7854r`, and surveyor's
//! bearings `N 45d0'0" E`, `N45dE`, `N`, `E`, `S`, `W` (absolute, like `angtos` mode 4).
//! Results are radians in [0, 2π), converted from ANGBASE/ANGDIR to the absolute angle.
//!
//! Leading and trailing blanks are ignored; anything else unreadable gives `None` (nil).

use std::f64::consts::{FRAC_PI_2, PI};

use super::angtos::{normalize, AngleSettings};
use super::vlstring::decimal_prefix_len;

/// `(distof string [mode])`: the distance `s` denotes in linear unit mode `mode` (1–5; `None`
/// reads every form), or `None` if `s` is not a distance in that mode or `mode` is invalid.
pub fn distof(s: &str, mode: Option<i32>) -> Option<f64> {
    let t = s.trim();
    let value = match mode {
        Some(1 | 2 | 5) => signed_number(t)?,
        Some(3 | 4) | None => feet_and_inches(t)?,
        Some(_) => return None,
    };
    value.is_finite().then_some(value)
}

/// `(angtof string [mode])`: the angle `s` denotes, in radians in [0, 2π), with a bare number
/// read in the unit of angular mode `mode` (0–4; `None` = degrees). `None` if `s` is not an
/// angle or `mode` is invalid.
pub fn angtof(s: &str, mode: Option<i32>, settings: &AngleSettings) -> Option<f64> {
    if let Some(m) = mode {
        if !(0..=4).contains(&m) {
            return None;
        }
    }
    let t = s.trim();
    if let Some(absolute) = bearing(t) {
        return Some(normalize(absolute));
    }
    let (negative, body) = split_sign(t);
    let last = body.chars().last()?;
    let magnitude = match last {
        'r' | 'R' => unsigned_decimal(&body[..body.len() - 1])?,
        'g' | 'G' => unsigned_decimal(&body[..body.len() - 1])? * PI / 200.0,
        _ if body.contains(['d', 'D', '\'', '"']) => dms_degrees(body)?.to_radians(),
        _ => {
            let v = unsigned_decimal(body)?;
            match mode {
                Some(2) => v * PI / 200.0,
                Some(3) => v,
                _ => v.to_radians(),
            }
        }
    };
    let relative = if negative { -magnitude } else { magnitude };
    let absolute = if settings.angdir & 1 != 0 {
        settings.angbase - relative
    } else {
        settings.angbase + relative
    };
    absolute.is_finite().then(|| normalize(absolute))
}

/// Splits off one leading `+` or `-`.
fn split_sign(t: &str) -> (bool, &str) {
    match t.as_bytes().first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    }
}

/// A decimal or scientific number without a sign: `17.5`, `.5`, `5.`, `1.75E+01`.
fn unsigned_decimal(t: &str) -> Option<f64> {
    let starts_unsigned = t.starts_with(|c: char| c.is_ascii_digit() || c == '.');
    (starts_unsigned && decimal_prefix_len(t) == t.len())
        .then(|| t.parse().ok())
        .flatten()
}

fn digits(t: &str) -> Option<u64> {
    if t.is_empty() || !t.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    t.parse().ok()
}

/// An unsigned decimal or fraction: `17.5`, `1/2`, `17 1/2`, `17-1/2`.
fn unsigned_number(t: &str) -> Option<f64> {
    let Some((left, denominator)) = t.split_once('/') else {
        return unsigned_decimal(t);
    };
    let denominator = digits(denominator)?;
    if denominator == 0 {
        return None;
    }
    let (whole, numerator) = match left.rfind([' ', '-']) {
        Some(i) => (digits(left[..i].trim_end())?, &left[i + 1..]),
        None => (0, left),
    };
    Some(whole as f64 + digits(numerator)? as f64 / denominator as f64)
}

fn signed_number(t: &str) -> Option<f64> {
    let (negative, body) = split_sign(t);
    let v = unsigned_number(body)?;
    Some(if negative { -v } else { v })
}

/// Feet and inches, or a bare number of inches, with an optional sign in front of it all.
fn feet_and_inches(t: &str) -> Option<f64> {
    let (negative, body) = split_sign(t);
    let inches = match body.split_once('\'') {
        Some((feet, rest)) => {
            let feet = unsigned_number(feet.trim_end())?;
            let rest = rest.trim_start();
            let rest = match rest.strip_prefix('-') {
                Some(after_dash) if after_dash.trim().is_empty() => return None,
                Some(after_dash) => after_dash.trim_start(),
                None => rest,
            };
            let inches = if rest.is_empty() {
                0.0
            } else {
                unsigned_number(rest.strip_suffix('"').unwrap_or(rest).trim_end())?
            };
            feet * 12.0 + inches
        }
        None => unsigned_number(body.strip_suffix('"').unwrap_or(body).trim_end())?,
    };
    Some(if negative { -inches } else { inches })
}

/// Degrees, minutes and seconds, each part optional but at least one present, in that order:
/// `45d30'15.5"`, `45d`, `45d30'`, `30'`, `45.5d`. Returns degrees.
fn dms_degrees(t: &str) -> Option<f64> {
    let mut rest = t;
    let mut total = 0.0;
    let mut any = false;
    for (marks, per_degree) in [
        (&['d', 'D'][..], 1.0),
        (&['\''][..], 60.0),
        (&['"'][..], 3600.0),
    ] {
        if let Some(i) = rest.find(marks) {
            total += unsigned_decimal(rest[..i].trim())? / per_degree;
            rest = &rest[i + 1..];
            any = true;
        }
    }
    (any && rest.trim().is_empty()).then_some(total)
}

/// A surveyor's bearing, as an absolute angle in radians: `N 45d E`, `S30d0'W`, or a bare
/// cardinal letter.
fn bearing(t: &str) -> Option<f64> {
    match t {
        "N" | "n" => return Some(FRAC_PI_2),
        "S" | "s" => return Some(3.0 * FRAC_PI_2),
        "E" | "e" => return Some(0.0),
        "W" | "w" => return Some(PI),
        _ => {}
    }
    let first = t.chars().next()?.to_ascii_uppercase();
    let last = t.chars().last()?.to_ascii_uppercase();
    if !matches!(first, 'N' | 'S') || !matches!(last, 'E' | 'W') || t.len() < 3 {
        return None;
    }
    let inner = t[1..t.len() - 1].trim();
    let degrees = if inner.contains(['d', 'D', '\'', '"']) {
        dms_degrees(inner)?
    } else {
        unsigned_decimal(inner)?
    };
    if degrees > 90.0 {
        return None;
    }
    let b = degrees.to_radians();
    Some(match (first, last) {
        ('N', 'E') => FRAC_PI_2 - b,
        ('N', _) => FRAC_PI_2 + b,
        ('S', 'W') => 3.0 * FRAC_PI_2 - b,
        _ => 3.0 * FRAC_PI_2 + b,
    })
}

#[cfg(test)]
// The reference's examples use 0.785398, not π/4, and so do these tests.
#[allow(clippy::approx_constant)]
mod tests {
    use super::super::angtos::angtos;
    use super::super::rtos::rtos;
    use super::*;
    use std::f64::consts::TAU;

    fn close(a: Option<f64>, b: f64) -> bool {
        a.is_some_and(|a| (a - b).abs() < 1e-9)
    }

    // AutoLISP reference, "distof": the inverse of the rtos examples for 17.5.
    #[test]
    fn distof_reference_examples() {
        assert_eq!(distof("1.7500E+01", Some(1)), Some(17.5));
        assert_eq!(distof("17.5000", Some(2)), Some(17.5));
        assert_eq!(distof("1'-5.5000\"", Some(3)), Some(17.5));
        assert_eq!(distof("1'-5 1/2\"", Some(4)), Some(17.5));
        assert_eq!(distof("17 1/2", Some(5)), Some(17.5));
    }

    #[test]
    fn distof_numbers() {
        assert_eq!(distof("1.5E+01", Some(1)), Some(15.0));
        assert_eq!(distof("1.5e1", Some(2)), Some(15.0));
        assert_eq!(distof(".5", Some(2)), Some(0.5));
        assert_eq!(distof("5.", Some(2)), Some(5.0));
        assert_eq!(distof("-2.25", Some(2)), Some(-2.25));
        assert_eq!(distof("  12  ", Some(2)), Some(12.0));
        assert_eq!(distof("17-1/2", Some(5)), Some(17.5));
        assert_eq!(distof("-17 1/2", Some(5)), Some(-17.5));
        assert_eq!(distof("3/4", Some(5)), Some(0.75));
        assert_eq!(distof("17", Some(5)), Some(17.0));
    }

    #[test]
    fn distof_rejects_garbage() {
        assert_eq!(distof("", Some(2)), None);
        assert_eq!(distof("abc", Some(2)), None);
        assert_eq!(distof("12abc", Some(2)), None);
        assert_eq!(distof("1/0", Some(5)), None);
        assert_eq!(distof("1 /2", Some(5)), None);
        assert_eq!(distof("--1", Some(2)), None);
        assert_eq!(distof("1e999", Some(2)), None);
        assert_eq!(distof("1'-3\"", Some(2)), None);
        assert_eq!(distof("1'-", Some(4)), None);
        assert_eq!(distof("1'-3\"x", Some(4)), None);
        assert_eq!(distof("1", Some(0)), None);
        assert_eq!(distof("1", Some(6)), None);
        assert_eq!(distof("inf", None), None);
        assert_eq!(distof("nan", None), None);
    }

    #[test]
    fn distof_feet_and_inches() {
        assert_eq!(distof("1'-3 1/2\"", Some(4)), Some(15.5));
        assert_eq!(distof("1'3.5\"", Some(3)), Some(15.5));
        assert_eq!(distof("1'3-1/2\"", Some(4)), Some(15.5));
        assert_eq!(distof("1'", Some(4)), Some(12.0));
        assert_eq!(distof("1.5'", Some(3)), Some(18.0));
        assert_eq!(distof("3\"", Some(4)), Some(3.0));
        assert_eq!(distof("1/2\"", Some(4)), Some(0.5));
        assert_eq!(distof("15", Some(4)), Some(15.0));
        assert_eq!(distof("-1'-3\"", Some(3)), Some(-15.0));
        assert_eq!(distof("1'-.5\"", Some(3)), Some(12.5));
        assert_eq!(distof("0'-0 1/2\"", Some(4)), Some(0.5));
        assert_eq!(distof("1' 3\"", Some(4)), Some(15.0));
        assert_eq!(distof("1'-3", Some(4)), Some(15.0));
        assert_eq!(distof("1'-5 1/2\"", None), Some(17.5));
        assert_eq!(distof("17.5", None), Some(17.5));
    }

    #[test]
    fn distof_inverts_rtos() {
        let values = [
            0.0, 0.5, 1.0, 6.0, 11.9, 12.0, 15.5, 17.5, 100.25, 1234.5625, -3.75, -27.125,
        ];
        for &x in &values {
            for mode in 1..=5 {
                for prec in [0, 2, 4, 8] {
                    for dimzin in [0, 1, 2, 3, 4, 8, 12] {
                        for unitmode in [0, 1] {
                            let text = rtos(x, mode, prec, dimzin, unitmode).unwrap();
                            let back = distof(&text, Some(mode))
                                .unwrap_or_else(|| panic!("distof({text:?}, {mode})"));
                            // Fractions round to 1/2^prec, decimals to 10^-prec (scientific:
                            // relative to the exponent).
                            let step = match mode {
                                4 | 5 => 1.0 / f64::from(1u32 << prec),
                                1 => 10f64.powi(-prec) * x.abs().max(1.0) * 10.0,
                                _ => 10f64.powi(-prec),
                            };
                            assert!(
                                (back - x).abs() <= step / 2.0 + 1e-9,
                                "{x} mode {mode} prec {prec} dimzin {dimzin}: {text:?} -> {back}"
                            );
                        }
                    }
                }
            }
        }
    }

    // AutoLISP reference, "angtof": (angtof "45.0000" 0) → 0.785398, and the inverses of the
    // angtos examples.
    #[test]
    fn angtof_reference_examples() {
        let s = AngleSettings::default();
        assert!(close(angtof("45.0000", Some(0), &s), 0.785398163397));
        assert!(close(angtof("315.0000", Some(0), &s), 5.497787143782));
        assert!(close(angtof("S 45d E", Some(4), &s), 5.497787143782));
        assert!(close(angtof("45d0'0\"", Some(1), &s), 0.785398163397));
        assert!(close(angtof("50.0000g", Some(2), &s), 0.785398163397));
        assert!(close(angtof("0.7854r", Some(3), &s), 0.7854));
        assert!(close(angtof("N 45d0'0\" E", Some(4), &s), 0.785398163397));
    }

    #[test]
    fn angtof_units_and_suffixes() {
        let s = AngleSettings::default();
        assert!(close(angtof("90", None, &s), FRAC_PI_2));
        assert!(close(angtof("100", Some(2), &s), FRAC_PI_2));
        assert!(close(angtof("1", Some(3), &s), 1.0));
        assert!(close(angtof("100g", Some(0), &s), FRAC_PI_2));
        assert!(close(angtof("1r", Some(0), &s), 1.0));
        assert!(close(angtof("-90", Some(0), &s), 1.5 * PI));
        assert!(close(angtof("450", Some(0), &s), FRAC_PI_2));
        assert!(close(angtof("360", Some(0), &s), 0.0));
        assert!(close(
            angtof("45d30'15\"", Some(1), &s),
            (45.0 + 30.0 / 60.0 + 15.0 / 3600.0f64).to_radians()
        ));
        assert!(close(angtof("45d30'", Some(1), &s), 45.5f64.to_radians()));
        assert!(close(angtof("45.5d", Some(1), &s), 45.5f64.to_radians()));
        assert!(close(angtof("45", Some(1), &s), 45f64.to_radians()));
        assert!(close(angtof(".5r", None, &s), 0.5));
    }

    #[test]
    fn angtof_bearings() {
        let s = AngleSettings::default();
        assert!(close(angtof("N45dE", Some(4), &s), PI / 4.0));
        assert!(close(angtof("N 10d W", Some(4), &s), 100f64.to_radians()));
        assert!(close(angtof("S 70d W", Some(4), &s), 200f64.to_radians()));
        assert!(close(angtof("S 30d0' E", Some(4), &s), 300f64.to_radians()));
        assert!(close(angtof("n 45 e", None, &s), PI / 4.0));
        assert!(close(angtof("N", Some(4), &s), FRAC_PI_2));
        assert!(close(angtof("E", Some(4), &s), 0.0));
        assert!(close(angtof("W", Some(4), &s), PI));
        assert!(close(angtof("S", Some(4), &s), 1.5 * PI));
        assert_eq!(angtof("N 91d E", Some(4), &s), None);
        assert_eq!(angtof("N 45d", Some(4), &s), None);
    }

    #[test]
    fn angtof_rejects_garbage() {
        let s = AngleSettings::default();
        assert_eq!(angtof("", Some(0), &s), None);
        assert_eq!(angtof("abc", Some(0), &s), None);
        assert_eq!(angtof("45x", Some(0), &s), None);
        assert_eq!(angtof("d30'", Some(1), &s), None);
        assert_eq!(angtof("45d30'x", Some(1), &s), None);
        assert_eq!(angtof("g", Some(2), &s), None);
        assert_eq!(angtof("45", Some(5), &s), None);
        assert_eq!(angtof("1e999", Some(0), &s), None);
    }

    #[test]
    fn angtof_angbase_angdir_invert_angtos() {
        let compass = AngleSettings {
            angbase: FRAC_PI_2,
            angdir: 1,
            ..AngleSettings::default()
        };
        assert!(close(angtof("90", Some(0), &compass), 0.0));
        assert!(close(angtof("0", Some(0), &compass), FRAC_PI_2));
        // Bearings stay absolute.
        assert!(close(angtof("E", Some(4), &compass), 0.0));
    }

    #[test]
    fn angtof_inverts_angtos() {
        let settings = [
            AngleSettings::default(),
            AngleSettings {
                angbase: 1.0,
                angdir: 1,
                dimzin: 12,
                unitmode: 1,
            },
        ];
        for s in &settings {
            for k in 0..97 {
                let a = k as f64 * TAU / 97.0;
                for mode in 0..=4 {
                    for prec in [0, 3, 4, 8] {
                        let text = angtos(a, mode, prec, s).unwrap();
                        let back = angtof(&text, Some(mode), s)
                            .unwrap_or_else(|| panic!("angtof({text:?}, {mode})"));
                        let step = match (mode, prec) {
                            (1 | 4, 0) => 1f64.to_radians(),
                            (1 | 4, 1 | 2) => (1.0 / 60.0f64).to_radians(),
                            (1 | 4, p) => (10f64.powi(4 - p.max(4)) / 3600.0).to_radians(),
                            (0, p) => 10f64.powi(-p).to_radians(),
                            (2, p) => 10f64.powi(-p) * PI / 200.0,
                            (_, p) => 10f64.powi(-p),
                        };
                        let diff = (back - a).rem_euclid(TAU);
                        let diff = diff.min(TAU - diff);
                        assert!(
                            diff <= step / 2.0 + 1e-9,
                            "{a} mode {mode} prec {prec}: {text:?} -> {back}"
                        );
                    }
                }
            }
        }
    }
}
