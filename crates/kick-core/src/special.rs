//! Special functions and closed forms shared by the solvers and tests.

/// Euler's Beta function B(a, b) for a, b > 0, through ln Γ (libm).
pub fn beta(a: f64, b: f64) -> f64 {
    (libm::lgamma(a) + libm::lgamma(b) - libm::lgamma(a + b)).exp()
}

/// Time for a conservative power-law contact (F = k δⁿ) to go from rest at
/// `max_compression` to δ = 0, where it leaves with relative speed `exit_speed`.
///
/// From ½ μ δ̇² + k δⁿ⁺¹/(n+1) = k δ_maxⁿ⁺¹/(n+1):
/// t = (δ_max / w) ∫₀¹ du / √(1 − uⁿ⁺¹) = (δ_max / w) B(1/(n+1), 1/2) / (n+1).
pub fn return_time(max_compression: f64, exit_speed: f64, exponent: f64) -> f64 {
    let a = 1.0 / (exponent + 1.0);
    max_compression / exit_speed * beta(a, 0.5) * a
}
