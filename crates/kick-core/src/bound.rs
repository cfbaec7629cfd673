//! Bounds that other parameters' values put on a parameter: the ball's
//! moment of inertia at most the thin shell's 2/3 m_b R², a convex instep's
//! radius at least the face's half-extents.
//!
//! Such a bound is a computed number, and a user gives it back as printed:
//! `--ball-inertia 0.0034687` is the thin shell of the default ball, 2/3 ×
//! 0.43 × 0.11² = 0.00346866…, rounded up in its fifth digit. A closed bound
//! therefore admits a value past it by rounding at the printed precision,
//! [`PRINTED_ROUNDING`], and reads it as the bound itself (what was meant,
//! and what the geometry admits). Beyond that the value is refused. Open
//! bounds whose boundary is degenerate (an offset of a whole radius grazes
//! the ball; a border as wide as the face leaves no face) stay strict:
//! rounding cannot make a degenerate value valid.

/// Relative slack of a closed bound set by other parameters: a number
/// printed to 4 significant digits is within half a unit of its last digit
/// of the value, at most 5e-4 of it (5e-4 when the first digit is 1).
pub const PRINTED_ROUNDING: f64 = 5e-4;

/// The most inertia a sphere of `mass` and `radius` can have: a thin shell,
/// all the mass at R, 2/3 m R².
pub fn thin_shell_inertia(mass: f64, radius: f64) -> f64 {
    2.0 / 3.0 * mass * radius * radius
}

/// `value` under the closed upper `bound`: itself when at most the bound,
/// the bound when above it by no more than [`PRINTED_ROUNDING`] of it, and
/// `None` beyond (or for NaN).
pub fn at_most(value: f64, bound: f64) -> Option<f64> {
    if value <= bound {
        Some(value)
    } else if value <= bound * (1.0 + PRINTED_ROUNDING) {
        Some(bound)
    } else {
        None
    }
}

/// `value` over the closed lower `bound` (positive): itself when at least
/// the bound, the bound when below it by no more than [`PRINTED_ROUNDING`]
/// of it, and `None` beyond (or for NaN).
pub fn at_least(value: f64, bound: f64) -> Option<f64> {
    if value >= bound {
        Some(value)
    } else if value >= bound * (1.0 - PRINTED_ROUNDING) {
        Some(bound)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The default ball's thin shell printed to 4, 5 and 6 significant
    /// digits and rounded up is read as the shell; 0.1% above is refused.
    #[test]
    fn the_thin_shell_printed_and_rounded_up_is_the_thin_shell() {
        let shell = thin_shell_inertia(0.43, 0.11);
        assert!((shell - 0.003_468_666_666_666_667).abs() < 1e-18);
        for printed in [0.003469, 0.0034687, 0.00346867] {
            assert!(printed > shell);
            assert_eq!(at_most(printed, shell), Some(shell), "{printed}");
        }
        assert_eq!(at_most(0.0034686, shell), Some(0.0034686));
        assert_eq!(at_most(shell * 1.001, shell), None);
        assert_eq!(at_most(f64::NAN, shell), None);
        assert_eq!(at_most(f64::INFINITY, shell), None);
    }

    #[test]
    fn a_lower_bound_admits_rounding_down() {
        assert_eq!(at_least(0.11995, 0.12), Some(0.12));
        assert_eq!(at_least(0.1199, 0.12), None, "0.12 to 4 digits is 0.1200");
        assert_eq!(at_least(0.13, 0.12), Some(0.13));
        assert_eq!(at_least(0.119, 0.12), None);
        assert_eq!(at_least(f64::NAN, 0.12), None);
    }
}
