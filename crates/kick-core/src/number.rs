//! Numbers in messages: one short form for every error and note.
//!
//! `{}` on an f64 prints every digit of its shortest round trip, and without
//! an exponent: 1e308 becomes 309 characters, 1.047530233023196e-7 stays at
//! 16 digits. A message wants the magnitude and a few digits, the same way
//! everywhere.

use std::fmt;

/// Significant digits of [`short`].
pub const SHORT_DIGITS: usize = 5;

/// Significant digits of [`sig`], the form of values in text outputs.
pub const VALUE_DIGITS: usize = 6;

/// `x` in short form, for messages: [`SHORT_DIGITS`] significant digits,
/// trailing zeros dropped, plain notation for 1e-3 ≤ |x| < 1e5 and
/// scientific otherwise (`717.43`, `0.97`, `1.0475e-7`, `1e308`, `inf`).
pub fn short(x: f64) -> Short {
    Short(x)
}

/// `x` as every text output prints a value (`kick simulate`, `kick fit`,
/// tables): the form of [`short`] with [`VALUE_DIGITS`] significant digits
/// (`31.9793`, `0.00529317`, `4.2e5`). Width and alignment (`{:>12}`) apply.
/// JSON and result files keep every digit.
pub fn sig(x: f64) -> Digits {
    Digits { x, digits: VALUE_DIGITS }
}

/// `x` as it was given, for a refusal quoting it: the form of [`short`]
/// with as many significant digits as its shortest round trip needs (at
/// least [`SHORT_DIGITS`]), so a value just inside or outside a bound never
/// reads as the bound itself (89.9999 printed as 90).
pub fn given(x: f64) -> Digits {
    let shortest = format!("{x:e}");
    let mantissa = shortest.trim_start_matches('-').split('e').next().unwrap_or("");
    let digits = mantissa.chars().filter(char::is_ascii_digit).count();
    Digits { x, digits: digits.max(SHORT_DIGITS) }
}

/// A vector as text outputs print it: `[a, b, c]`, each as [`sig`].
pub fn vector(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|&x| sig(x).to_string()).collect();
    format!("[{}]", parts.join(", "))
}

/// See [`short`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Short(pub f64);

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        Digits { x: self.0, digits: SHORT_DIGITS }.fmt(f)
    }
}

/// `x` to `digits` significant digits in the form of [`short`]; see [`sig`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Digits {
    pub x: f64,
    pub digits: usize,
}

impl fmt::Display for Digits {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (x, digits) = (self.x, self.digits.max(1));
        if x.is_nan() {
            return f.pad("NaN");
        }
        if x.is_infinite() {
            return f.pad(if x > 0.0 { "inf" } else { "-inf" });
        }
        if x == 0.0 {
            return f.pad("0");
        }
        // The decimal exponent after rounding to `digits` (99999.7 is 1e5).
        let scientific = format!("{x:.*e}", digits - 1);
        let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
        let exponent: i32 = exponent.parse().unwrap_or(0);
        if (-3..5).contains(&exponent) {
            let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
            f.pad(trim_zeros(&format!("{x:.decimals$}")))
        } else {
            f.pad(&format!("{}e{exponent}", trim_zeros(mantissa)))
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
    use super::{given, short};

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

    #[test]
    fn given_values_keep_their_digits() {
        // Just inside a bound stays inside (short rounds 89.9999 to 90).
        assert_eq!(given(89.9999).to_string(), "89.9999");
        assert_eq!(short(89.9999).to_string(), "90");
        // Round trips: what the user typed comes back.
        for x in [89.9999, 0.1, -1.0, 1e300, 1.047530233023196e-7, 123456.789, 0.30000000000000004] {
            assert_eq!(given(x).to_string().parse::<f64>().unwrap(), x, "{x}");
        }
        // Short values keep short's form.
        assert_eq!(given(-1.0).to_string(), "-1");
        assert_eq!(given(1e300).to_string(), "1e300");
        assert_eq!(given(f64::NAN).to_string(), "NaN");
    }

    /// Text outputs' form: six significant digits, the same notation, and
    /// width and alignment honoured.
    #[test]
    fn values_in_text_outputs() {
        use super::{sig, vector};
        let cases = [
            (31.979279398204, "31.9793"),
            (0.0052931654, "0.00529317"),
            (420000.0, "4.2e5"),
            (3802.86221097, "3802.86"),
            (123456.7, "1.23457e5"),
            (-8.0060897, "-8.00609"),
            (1.5e-12, "1.5e-12"),
            (0.0, "0"),
        ];
        for (x, expected) in cases {
            assert_eq!(sig(x).to_string(), expected, "{x:e}");
        }
        assert_eq!(format!("[{:>8}]", sig(2.5)), "[     2.5]");
        assert_eq!(format!("[{:<6}]", super::short(f64::INFINITY)), "[inf   ]");
        assert_eq!(vector(&[1.0, -0.25, 3e-9]), "[1, -0.25, 3e-9]");
    }
}
