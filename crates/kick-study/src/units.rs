//! Spin as every page quotes it (issue 34: one unit across pages): rad/s,
//! with rpm beside it wherever prose quotes a spin; tables carry rad/s only.

use kick_core::number::Digits;

/// rpm per rad/s: 60/2π.
pub const RPM_PER_RAD_PER_S: f64 = 60.0 / std::f64::consts::TAU;

/// |ω| below this is zero to rounding, rad/s.
pub const ZERO_SPIN: f64 = 1e-12;

/// `x` to three significant digits.
pub fn three(x: f64) -> String {
    Digits { x, digits: 3 }.to_string()
}

/// A spin in prose: "58.3 rad/s (557 rpm)"; zero to rounding below [`ZERO_SPIN`].
pub fn spin(rad_per_s: f64) -> String {
    if rad_per_s.abs() < ZERO_SPIN {
        format!("0 rad/s (|ω| < {ZERO_SPIN:e} rad/s)")
    } else {
        format!("{} rad/s ({} rpm)", three(rad_per_s), three(rad_per_s * RPM_PER_RAD_PER_S))
    }
}

/// `x` to `digits` significant digits, as text.
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return "—".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor() as i32;
    let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
    format!("{x:.decimals$}")
}

/// [`sig`], but "0" where |x| is below `zero`: a value that is zero to
/// rounding (a symmetric kick's sideways numbers), not a digit string of noise.
pub fn sig_or_zero(x: f64, digits: usize, zero: f64) -> String {
    if x.abs() < zero {
        "0".into()
    } else {
        sig(x, digits)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spin_gives_both_units() {
        // 2π rad/s is one revolution a second, 60 rpm.
        assert_eq!(spin(std::f64::consts::TAU), "6.28 rad/s (60 rpm)");
        assert_eq!(spin(58.3), "58.3 rad/s (557 rpm)");
        assert!(spin(1e-14).starts_with("0 rad/s"));
    }

    #[test]
    fn noise_below_the_zero_is_printed_as_zero() {
        assert_eq!(sig(-2.19e-15, 3), "-0.00000000000000219");
        assert_eq!(sig_or_zero(-2.19e-15, 3, 1e-9), "0");
        assert_eq!(sig_or_zero(-2.89, 3, 1e-9), "-2.89");
    }
}
