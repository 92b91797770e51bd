//! `angtos`: an angle in radians as text in AutoCAD's angular unit formats (AUNITS modes 0–4).
//!
//! AutoLISP reference, "angtos": `(angtos 0.785398 0 4)` → `"45.0000"`,
//! `(angtos -0.785398 0 4)` → `"315.0000"`, `(angtos -0.785398 4)` → `"S 45d E"` (AUPREC 0).
//!
//! Modes: 0 decimal degrees, 1 degrees/minutes/seconds (`45d30'15"`), 2 grads (`50.0000g`),
//! 3 radians (`0.7854r`), 4 surveyor's bearings (`N 45d0'0" E`).
//!
//! For degrees/minutes/seconds the precision counts places as AUPREC does in the Drawing Units
//! dialog, minutes and seconds each taking two: 0 → `45d`, 1–2 → `45d30'`, 3–4 → `45d30'15"`,
//! 5–8 → seconds with 1–4 decimals (`45d30'15.25"`). Minutes and seconds are not zero-padded.
//!
//! Choices where the reference is silent: degrees, grads and DMS that round up to a full
//! circle print as 0 (radians are left as rounded); surveyor's bearings are absolute (north is
//! up whatever ANGBASE says); DIMZIN's decimal bits (4 leading, 8 trailing zeros) apply to
//! modes 0, 2 and 3; UNITMODE 1 drops the spaces of surveyor's bearings (`N45dE`).

use std::f64::consts::{PI, TAU};

use super::decimal::{fixed_abs, suppress_zeros};
use super::FmtError;

/// The drawing settings that change how angles are written and read.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleSettings {
    /// ANGBASE: the direction of angle 0, in radians from the X axis.
    pub angbase: f64,
    /// ANGDIR: 0 counter-clockwise, 1 clockwise.
    pub angdir: i32,
    /// DIMZIN: bits 4 and 8 suppress leading/trailing zeros of decimals.
    pub dimzin: i32,
    /// UNITMODE: bit 1 writes surveyor's bearings without spaces.
    pub unitmode: i32,
}

impl Default for AngleSettings {
    /// A new drawing: ANGBASE 0, ANGDIR 0, DIMZIN 0, UNITMODE 0.
    fn default() -> Self {
        AngleSettings {
            angbase: 0.0,
            angdir: 0,
            dimzin: 0,
            unitmode: 0,
        }
    }
}

/// Largest precision for the decimal modes 0, 2, 3 (as `rtos`).
pub const MAX_DECIMAL_PRECISION: i32 = 16;
/// Largest precision for the DMS and surveyor's modes (AUPREC's limit).
pub const MAX_DMS_PRECISION: i32 = 8;

/// Formats the angle `a` (radians) in angular mode `mode` with precision `prec`.
///
/// The angle is first measured from ANGBASE in the ANGDIR sense and brought into [0, 2π)
/// (surveyor's bearings use `a` itself). Errors: `mode` outside 0..=4, `prec` outside
/// 0..=16 (modes 0, 2, 3) or 0..=8 (modes 1, 4), a non-finite angle.
pub fn angtos(a: f64, mode: i32, prec: i32, settings: &AngleSettings) -> Result<String, FmtError> {
    if !(0..=4).contains(&mode) {
        return Err(FmtError::Mode {
            function: "angtos",
            mode: i64::from(mode),
            min: 0,
            max: 4,
        });
    }
    let max_prec = if mode == 1 || mode == 4 {
        MAX_DMS_PRECISION
    } else {
        MAX_DECIMAL_PRECISION
    };
    if !(0..=max_prec).contains(&prec) {
        return Err(FmtError::Precision {
            function: "angtos",
            precision: i64::from(prec),
            max: i64::from(max_prec),
        });
    }
    if !a.is_finite() || !settings.angbase.is_finite() {
        return Err(FmtError::NonFinite { function: "angtos" });
    }
    let relative = if settings.angdir & 1 != 0 {
        settings.angbase - a
    } else {
        a - settings.angbase
    };
    let relative = normalize(relative);
    let decimals = prec as usize;
    Ok(match mode {
        0 => decimal_in_circle(relative.to_degrees(), 360.0, decimals, settings.dimzin),
        1 => {
            let (units, per_degree) = dms_units(relative.to_degrees(), prec);
            dms_text(units % (360 * per_degree), prec)
        }
        2 => decimal_in_circle(relative * 200.0 / PI, 400.0, decimals, settings.dimzin) + "g",
        3 => suppress_zeros(&fixed_abs(relative, decimals).0, settings.dimzin) + "r",
        _ => surveyor(normalize(a), prec, settings.unitmode & 1 != 0),
    })
}

/// Brings an angle into [0, 2π); `rem_euclid` can return 2π itself for tiny negative inputs.
pub(crate) fn normalize(a: f64) -> f64 {
    let r = a.rem_euclid(TAU);
    if r >= TAU {
        0.0
    } else {
        r
    }
}

/// A decimal in [0, full) rounded to `decimals`, with a full circle written as 0.
fn decimal_in_circle(value: f64, full: f64, decimals: usize, dimzin: i32) -> String {
    let (mut text, _) = fixed_abs(value, decimals);
    if text.parse::<f64>().is_ok_and(|v| v >= full) {
        text = fixed_abs(0.0, decimals).0;
    }
    suppress_zeros(&text, dimzin)
}

/// Rounds `degrees` (non-negative) to the DMS precision's smallest unit. Returns the count of
/// those units and how many make one degree.
fn dms_units(degrees: f64, prec: i32) -> (u64, u64) {
    let per_degree: u64 = match prec {
        0 => 1,
        1 | 2 => 60,
        3 | 4 => 3600,
        p => 3600 * 10u64.pow((p - 4) as u32),
    };
    ((degrees * per_degree as f64).round() as u64, per_degree)
}

/// Writes a count of DMS units (see `dms_units`) as `45d`, `45d30'`, `45d30'15"` or
/// `45d30'15.25"`.
fn dms_text(units: u64, prec: i32) -> String {
    match prec {
        0 => format!("{units}d"),
        1 | 2 => format!("{}d{}'", units / 60, units % 60),
        _ => {
            let second_decimals = (prec - 4).max(0) as u32;
            let per_second = 10u64.pow(second_decimals);
            let total_seconds = units / per_second;
            let fraction = units % per_second;
            let (d, m, s) = (
                total_seconds / 3600,
                total_seconds / 60 % 60,
                total_seconds % 60,
            );
            if second_decimals == 0 {
                format!("{d}d{m}'{s}\"")
            } else {
                let width = second_decimals as usize;
                format!("{d}d{m}'{s}.{fraction:0width$}\"")
            }
        }
    }
}

/// Mode 4: a bearing from north or south toward east or west, `N 45d0'0" E`; exactly
/// cardinal directions (after rounding) are the bare letter.
fn surveyor(a: f64, prec: i32, compact: bool) -> String {
    let (units, per_degree) = dms_units(a.to_degrees(), prec);
    let quarter = 90 * per_degree;
    let units = units % (4 * quarter);
    let (from, bearing, toward) = match units {
        0 => return "E".to_string(),
        u if u == quarter => return "N".to_string(),
        u if u == 2 * quarter => return "W".to_string(),
        u if u == 3 * quarter => return "S".to_string(),
        u if u < quarter => ('N', quarter - u, 'E'),
        u if u < 2 * quarter => ('N', u - quarter, 'W'),
        u if u < 3 * quarter => ('S', 3 * quarter - u, 'W'),
        u => ('S', u - 3 * quarter, 'E'),
    };
    let text = dms_text(bearing, prec);
    if compact {
        format!("{from}{text}{toward}")
    } else {
        format!("{from} {text} {toward}")
    }
}

#[cfg(test)]
// The reference's examples use 0.785398, not π/4, and so do these tests.
#[allow(clippy::approx_constant)]
mod tests {
    use super::*;

    fn at(a: f64, mode: i32, prec: i32) -> String {
        angtos(a, mode, prec, &AngleSettings::default()).unwrap()
    }

    // AutoLISP reference, "angtos".
    #[test]
    fn reference_examples() {
        assert_eq!(at(0.785398, 0, 4), "45.0000");
        assert_eq!(at(-0.785398, 0, 4), "315.0000");
        assert_eq!(at(-0.785398, 4, 0), "S 45d E");
    }

    #[test]
    fn decimal_degrees() {
        assert_eq!(at(PI, 0, 0), "180");
        assert_eq!(at(PI / 6.0, 0, 2), "30.00");
        assert_eq!(at(0.0, 0, 4), "0.0000");
        assert_eq!(at(TAU, 0, 4), "0.0000");
        assert_eq!(at(5.0 * TAU + PI / 2.0, 0, 1), "90.0");
        // Rounds up to a full circle: written as 0.
        assert_eq!(at(TAU - 1e-9, 0, 4), "0.0000");
        assert_eq!(at(1.0, 0, 6), "57.295780");
    }

    #[test]
    fn degrees_minutes_seconds() {
        assert_eq!(at(0.785398, 1, 4), "45d0'0\"");
        assert_eq!(at(PI / 2.0, 1, 4), "90d0'0\"");
        let a = (45.0 + 30.0 / 60.0 + 15.0 / 3600.0f64).to_radians();
        assert_eq!(at(a, 1, 0), "46d");
        assert_eq!(at(a, 1, 1), "45d30'");
        assert_eq!(at(a, 1, 2), "45d30'");
        assert_eq!(at(a, 1, 3), "45d30'15\"");
        assert_eq!(at(a, 1, 4), "45d30'15\"");
        assert_eq!(at(a, 1, 5), "45d30'15.0\"");
        assert_eq!(at(a, 1, 8), "45d30'15.0000\"");
        let b = (10.0 + 5.0 / 60.0 + 7.25 / 3600.0f64).to_radians();
        assert_eq!(at(b, 1, 6), "10d5'7.25\"");
        assert_eq!(at(b, 1, 4), "10d5'7\"");
        // 59.9999" carries into minutes and degrees.
        let c = (29.0 + 59.0 / 60.0 + 59.9999 / 3600.0f64).to_radians();
        assert_eq!(at(c, 1, 4), "30d0'0\"");
        assert_eq!(at(TAU - 1e-9, 1, 4), "0d0'0\"");
    }

    #[test]
    fn grads_and_radians() {
        assert_eq!(at(0.785398, 2, 4), "50.0000g");
        assert_eq!(at(PI, 2, 0), "200g");
        assert_eq!(at(0.785398, 3, 4), "0.7854r");
        assert_eq!(at(-PI / 2.0, 3, 3), "4.712r");
        assert_eq!(at(PI, 3, 0), "3r");
    }

    #[test]
    fn surveyor_bearings() {
        assert_eq!(at(0.785398, 4, 4), "N 45d0'0\" E");
        assert_eq!(at(PI / 2.0, 4, 4), "N");
        assert_eq!(at(0.0, 4, 4), "E");
        assert_eq!(at(PI, 4, 4), "W");
        assert_eq!(at(1.5 * PI, 4, 4), "S");
        assert_eq!(at(100f64.to_radians(), 4, 0), "N 10d W");
        assert_eq!(at(200f64.to_radians(), 4, 0), "S 70d W");
        assert_eq!(at(300f64.to_radians(), 4, 2), "S 30d0' E");
        assert_eq!(at(30f64.to_radians(), 4, 2), "N 60d0' E");
        // Within rounding of north prints N, never "N 0d E".
        assert_eq!(at(PI / 2.0 + 1e-9, 4, 4), "N");
        let compact = AngleSettings {
            unitmode: 1,
            ..AngleSettings::default()
        };
        assert_eq!(angtos(0.785398, 4, 0, &compact).unwrap(), "N45dE");
    }

    #[test]
    fn angbase_and_angdir() {
        let north_based = AngleSettings {
            angbase: PI / 2.0,
            ..AngleSettings::default()
        };
        assert_eq!(angtos(PI / 2.0, 0, 0, &north_based).unwrap(), "0");
        assert_eq!(angtos(0.0, 0, 0, &north_based).unwrap(), "270");
        let clockwise = AngleSettings {
            angdir: 1,
            ..AngleSettings::default()
        };
        assert_eq!(angtos(PI / 2.0, 0, 0, &clockwise).unwrap(), "270");
        let compass = AngleSettings {
            angbase: PI / 2.0,
            angdir: 1,
            ..AngleSettings::default()
        };
        assert_eq!(angtos(0.0, 0, 0, &compass).unwrap(), "90");
        assert_eq!(angtos(PI, 0, 0, &compass).unwrap(), "270");
        // Bearings stay absolute.
        assert_eq!(angtos(0.0, 4, 0, &compass).unwrap(), "E");
    }

    #[test]
    fn dimzin_decimal_bits() {
        let trailing = AngleSettings {
            dimzin: 8,
            ..AngleSettings::default()
        };
        assert_eq!(angtos(0.785398, 0, 4, &trailing).unwrap(), "45");
        assert_eq!(angtos(0.785398, 3, 4, &trailing).unwrap(), "0.7854r");
        let leading = AngleSettings {
            dimzin: 4,
            ..AngleSettings::default()
        };
        assert_eq!(angtos(0.5, 3, 2, &leading).unwrap(), ".50r");
    }

    #[test]
    fn bad_arguments_are_errors() {
        let s = AngleSettings::default();
        assert!(angtos(1.0, 5, 4, &s).is_err());
        assert!(angtos(1.0, -1, 4, &s).is_err());
        assert!(angtos(1.0, 1, 9, &s).is_err());
        assert!(angtos(1.0, 0, 16, &s).is_ok());
        assert!(angtos(1.0, 0, -1, &s).is_err());
        assert!(angtos(f64::NAN, 0, 4, &s).is_err());
        assert!(angtos(f64::INFINITY, 0, 4, &s).is_err());
    }

    #[test]
    fn huge_angles_normalize() {
        assert_eq!(at(1e15, 0, 2), at(1e15 % TAU, 0, 2));
        assert_eq!(normalize(-1e-300), 0.0);
    }
}
