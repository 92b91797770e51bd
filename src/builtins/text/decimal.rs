//! Decimal rounding and DIMZIN zero suppression shared by `rtos` and `angtos`.
//!
//! AutoCAD rounds half away from zero. Rounding the exact binary value would turn the 1.005
//! a user typed into 1.00 (its binary value is 1.00499999999999989…), so rounding works on
//! the shortest decimal text that reads back as the same double (Rust's `{:e}`, the
//! Steele–White/Grisu/Ryu "shortest round-trip" digits): what the user wrote is what is
//! rounded. For values that came out of arithmetic this differs from exact-binary rounding
//! only at the 17th significant digit.

/// The digits of a non-negative number: value = 0.d₁d₂d₃… × 10^`point`.
#[derive(Debug, Clone, PartialEq)]
struct Digits {
    digits: Vec<u8>,
    point: i32,
}

impl Digits {
    /// Shortest round-trip digits of |x|; `x` must be finite. Zero has no digits.
    fn of(x: f64) -> Digits {
        let x = x.abs();
        if x == 0.0 {
            return Digits {
                digits: Vec::new(),
                point: 1,
            };
        }
        let sci = format!("{:e}", x);
        let (mantissa, exp) = sci.split_once('e').expect("{:e} has an exponent");
        let exp: i32 = exp.parse().expect("{:e} exponent is an integer");
        let digits = mantissa
            .bytes()
            .filter(u8::is_ascii_digit)
            .map(|b| b - b'0')
            .collect();
        Digits {
            digits,
            point: exp + 1,
        }
    }

    /// Keeps the first `keep` digits (a negative `keep` keeps none), rounding half away from
    /// zero; a carry out of the first digit raises `point`.
    fn round_to(&mut self, keep: i64) {
        let keep_len = keep.max(0) as usize;
        if keep_len >= self.digits.len() {
            return;
        }
        let round_up = keep >= 0 && self.digits[keep_len] >= 5;
        self.digits.truncate(keep_len);
        if !round_up {
            return;
        }
        let mut i = keep_len;
        loop {
            if i == 0 {
                self.digits.insert(0, 1);
                self.point += 1;
                break;
            }
            i -= 1;
            if self.digits[i] == 9 {
                self.digits[i] = 0;
            } else {
                self.digits[i] += 1;
                break;
            }
        }
    }

    fn digit(&self, i: i64) -> u8 {
        usize::try_from(i)
            .ok()
            .and_then(|i| self.digits.get(i).copied())
            .unwrap_or(0)
    }

    fn is_zero(&self) -> bool {
        self.digits.iter().all(|&d| d == 0)
    }
}

/// |x| rounded half away from zero to `decimals` places, in fixed notation with exactly that
/// many decimals (no point when `decimals` is 0), without a sign. Returns the text and whether
/// the rounded value is zero. `x` must be finite.
pub(crate) fn fixed_abs(x: f64, decimals: usize) -> (String, bool) {
    let mut d = Digits::of(x);
    d.round_to(i64::from(d.point) + decimals as i64);
    let mut out = String::new();
    if d.point <= 0 {
        out.push('0');
    } else {
        for i in 0..i64::from(d.point) {
            out.push(char::from(b'0' + d.digit(i)));
        }
    }
    if decimals > 0 {
        out.push('.');
        for k in 0..decimals as i64 {
            out.push(char::from(b'0' + d.digit(i64::from(d.point) + k)));
        }
    }
    (out, d.is_zero())
}

/// |x| in scientific notation with `decimals` mantissa decimals, rounded half away from zero,
/// as AutoCAD's `rtos` mode 1 writes it: `1.7500E+01` (exponent sign and at least two digits).
/// Returns the text and whether the value is zero. `x` must be finite.
pub(crate) fn scientific_abs(x: f64, decimals: usize) -> (String, bool) {
    let mut d = Digits::of(x);
    let zero = d.is_zero();
    d.round_to(1 + decimals as i64);
    let exp = if zero { 0 } else { d.point - 1 };
    let mut out = String::new();
    out.push(char::from(b'0' + d.digit(0)));
    if decimals > 0 {
        out.push('.');
        for k in 1..=decimals as i64 {
            out.push(char::from(b'0' + d.digit(k)));
        }
    }
    let sign = if exp < 0 { '-' } else { '+' };
    out.push_str(&format!("E{sign}{:02}", exp.unsigned_abs()));
    (out, zero)
}

/// DIMZIN bit 4: suppress the leading zero of a decimal (`0.5000` → `.5000`).
pub(crate) const DIMZIN_LEADING: i32 = 4;
/// DIMZIN bit 8: suppress trailing zeros of a decimal (`12.5000` → `12.5`, `12.0000` → `12`).
pub(crate) const DIMZIN_TRAILING: i32 = 8;

/// Applies DIMZIN's decimal bits (4 leading, 8 trailing) to an unsigned fixed or scientific
/// number. A number suppressed to nothing (`0.0000` with both bits) stays `0`.
pub(crate) fn suppress_zeros(text: &str, dimzin: i32) -> String {
    let (number, exponent) = match text.find('E') {
        Some(i) => text.split_at(i),
        None => (text, ""),
    };
    let mut number = number;
    if dimzin & DIMZIN_TRAILING != 0 && number.contains('.') {
        number = number.trim_end_matches('0').trim_end_matches('.');
    }
    if dimzin & DIMZIN_LEADING != 0 && number.starts_with("0.") {
        number = &number[1..];
    }
    if number.is_empty() {
        number = "0";
    }
    format!("{number}{exponent}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_rounds_half_away_from_zero_on_the_written_value() {
        assert_eq!(fixed_abs(2.5, 0), ("3".to_string(), false));
        assert_eq!(fixed_abs(-2.5, 0), ("3".to_string(), false));
        assert_eq!(fixed_abs(0.125, 2).0, "0.13");
        assert_eq!(fixed_abs(1.005, 2).0, "1.01");
        assert_eq!(fixed_abs(2.675, 2).0, "2.68");
        assert_eq!(fixed_abs(17.5, 4).0, "17.5000");
        assert_eq!(fixed_abs(9.99995, 4).0, "10.0000");
        assert_eq!(fixed_abs(999.6, 0).0, "1000");
        assert_eq!(fixed_abs(0.0, 3), ("0.000".to_string(), true));
        assert_eq!(fixed_abs(0.00004, 4), ("0.0000".to_string(), true));
        assert_eq!(fixed_abs(0.00005, 4), ("0.0001".to_string(), false));
        assert_eq!(fixed_abs(0.4, 0), ("0".to_string(), true));
        assert_eq!(fixed_abs(0.5, 0), ("1".to_string(), false));
        assert_eq!(fixed_abs(1e20, 1).0, "100000000000000000000.0");
        assert_eq!(fixed_abs(1.5e-7, 8).0, "0.00000015");
        assert_eq!(fixed_abs(std::f64::consts::PI, 16).0, "3.1415926535897930");
    }

    #[test]
    fn scientific_mantissa_and_exponent() {
        assert_eq!(scientific_abs(17.5, 4).0, "1.7500E+01");
        assert_eq!(scientific_abs(0.0, 4), ("0.0000E+00".to_string(), true));
        assert_eq!(scientific_abs(9.99995, 4).0, "1.0000E+01");
        assert_eq!(scientific_abs(1.5e-7, 1).0, "1.5E-07");
        assert_eq!(scientific_abs(1e100, 2).0, "1.00E+100");
        assert_eq!(scientific_abs(123.0, 0).0, "1E+02");
        assert_eq!(scientific_abs(150.0, 0).0, "2E+02");
    }

    #[test]
    fn dimzin_decimal_bits() {
        assert_eq!(suppress_zeros("17.5000", 0), "17.5000");
        assert_eq!(suppress_zeros("17.5000", 8), "17.5");
        assert_eq!(suppress_zeros("17.0000", 8), "17");
        assert_eq!(suppress_zeros("0.5000", 4), ".5000");
        assert_eq!(suppress_zeros("0.5000", 12), ".5");
        assert_eq!(suppress_zeros("0.0000", 12), "0");
        assert_eq!(suppress_zeros("0.0000", 4), ".0000");
        assert_eq!(suppress_zeros("100", 8), "100");
        assert_eq!(suppress_zeros("1.7500E+01", 8), "1.75E+01");
        assert_eq!(suppress_zeros("1.0000E+01", 8), "1E+01");
        // The feet/inch values 0–3 leave decimals alone.
        assert_eq!(suppress_zeros("0.5000", 3), "0.5000");
    }
}
