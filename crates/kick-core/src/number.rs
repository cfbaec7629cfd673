//! Numbers in messages: one short form for every error and note.
//!
//! `{}` on an f64 prints every digit of its shortest round trip, and without
//! an exponent: 1e308 becomes 309 characters, 1.047530233023196e-7 stays at
//! 16 digits. A message wants the magnitude and a few digits, the same way
//! everywhere.

use std::fmt;

/// Significant digits of [`short`].
pub const SHORT_DIGITS: usize = 5;

/// `x` in short form, for messages: [`SHORT_DIGITS`] significant digits,
/// trailing zeros dropped, plain notation for 1e-3 ≤ |x| < 1e5 and
/// scientific otherwise (`717.43`, `0.97`, `1.0475e-7`, `1e308`, `inf`).
pub fn short(x: f64) -> Short {
    Short(x)
}

/// See [`short`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Short(pub f64);

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x.is_nan() {
            return f.write_str("NaN");
        }
        if x.is_infinite() {
            return f.write_str(if x > 0.0 { "inf" } else { "-inf" });
        }
        if x == 0.0 {
            return f.write_str("0");
        }
        // The decimal exponent after rounding to SHORT_DIGITS (99999.7 is 1e5).
        let scientific = format!("{x:.*e}", SHORT_DIGITS - 1);
        let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
        let exponent: i32 = exponent.parse().unwrap_or(0);
        if (-3..5).contains(&exponent) {
            let decimals = (SHORT_DIGITS as i32 - 1 - exponent).max(0) as usize;
            f.write_str(trim_zeros(&format!("{x:.decimals$}")))
        } else {
            write!(f, "{}e{exponent}", trim_zeros(mantissa))
        }
    }
}

/// `2.5000` → `2.5`, `3.000` → `3`; integers untouched.
fn trim_zeros(digits: &str) -> &str {
    if digits.contains('.') {
        digits.trim_end_matches('0').trim_end_matches('.')
    } else {
        digits
    }
}

#[cfg(test)]
mod tests {
    use super::short;

    #[test]
    fn short_forms() {
        let cases = [
            (1e308, "1e308"),
            (f64::MAX, "1.7977e308"),
            (1.047530233023196e-7, "1.0475e-7"),
            (717.433796006767, "717.43"),
            (-0.97, "-0.97"),
            (5e-6, "5e-6"),
            (22.0, "22"),
            (0.0056108384853953, "0.0056108"),
            (0.001, "0.001"),
            (0.00099999999, "0.001"),
            (99999.7, "1e5"),
            (12345.6, "12346"),
            (4.2e5, "4.2e5"),
            (1e-13, "1e-13"),
            (5e-324, "4.9407e-324"),
            (0.0, "0"),
            (-0.0, "0"),
            (f64::INFINITY, "inf"),
            (f64::NEG_INFINITY, "-inf"),
            (f64::NAN, "NaN"),
        ];
        for (x, expected) in cases {
            assert_eq!(short(x).to_string(), expected, "{x:e}");
        }
    }
}
