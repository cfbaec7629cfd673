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
    max_compression / exit_speed * beta_function_return(a)
}

/// The return integral under a constant drive:
/// I(n, β) = ∫₀¹ dy / √(1 − yⁿ⁺¹ − β (1 − y)), for β ≤ 1, given the margin
/// 1 − β ≥ 0 (near β = 1 the caller knows the margin better than β).
///
/// From rest at δ_max, the undamped return of the paper's law under a drive
/// share f_s = (μ/m_f) F_drive conserves ½ μ δ̇² + U(δ) − f_s δ (Eqs. 18, 23).
/// With y = δ/δ_max, U_max = U(δ_max) and β = f_s δ_max / U_max, the time
/// back to δ = 0 is (δ_max / √(2 U_max/μ)) · I(n, β), and the margin is
/// ½ μ w²/U_max with w the exit speed. β = 0 gives the Beta function of
/// [`return_time`]; β > 1 (a negative margin) means the ball never gets back
/// to δ = 0 and gives NaN. The integrand is positive on (0, 1) for β ≤ 1
/// because 1 − yⁿ⁺¹ − β(1 − y) is concave in y and non-negative at both ends.
///
/// y = 1 − z² removes the 1/√(1 − y) turning point; the rest, a weak
/// y^(n+1) branch point at y = 0 and, as β → 1, a 1/√y end, is left to
/// tanh–sinh quadrature on z ∈ (0, 1), refined by halving the step until two
/// levels agree to 1e-9 (the error squares per halving, so the result is then
/// good to rounding). With a margin of at least 1/2 a fixed 24-point
/// Gauss–Legendre rule after z = 1 − u² does as well for less. The tests
/// compare both with the Beta function, with each other and with an
/// independent adaptive Simpson rule.
pub fn driven_return_integral(exponent: f64, margin: f64) -> f64 {
    if !(margin >= 0.0) || !(exponent > 0.0) {
        return f64::NAN;
    }
    if margin == 1.0 {
        let a = 1.0 / (exponent + 1.0);
        return beta_function_return(a);
    }
    let integrand = return_integrand(exponent, margin);
    if margin >= GAUSS_MARGIN {
        // z = 1 − u²: the y^(n+1) end becomes u^(2n+2), smooth enough for
        // Gauss–Legendre; with the margin this wide the nearest complex
        // singularity (u ≈ ±i √(margin/2β)) is far from [0, 1].
        return gauss_legendre(|u| {
            let complement = u * u;
            2.0 * u * integrand(1.0 - complement, complement)
        });
    }
    tanh_sinh(integrand, 1e-9)
}

/// The integrand of I(n, β) after y = 1 − z², as a function of z and 1 − z:
/// 2/√r(z), r = q(1 − z²)/z², computed without cancellation at both ends.
fn return_integrand(exponent: f64, margin: f64) -> impl Fn(f64, f64) -> f64 {
    let (power, beta) = (exponent + 1.0, 1.0 - margin);
    move |z: f64, complement: f64| {
        let z2 = z * z;
        let q = if z < 0.5 {
            // y near 1: 1 − y^(n+1) = −expm1((n+1) ln(1 − z²)).
            -(power * (-z2).ln_1p()).exp_m1() - beta * z2
        } else {
            // y = (1 − z)(1 + z) small: q = (1 − β) + y (β − yⁿ).
            let y = complement * (2.0 - complement);
            margin + y * (beta - y.powf(exponent))
        };
        2.0 / (q / z2).sqrt()
    }
}

/// Margins from which the fixed Gauss–Legendre rule is used (tested against
/// tanh–sinh and an independent Simpson rule down to this value).
const GAUSS_MARGIN: f64 = 0.5;
const GAUSS_NODES: usize = 24;

/// Node i and weight of the n-point Gauss–Legendre rule mapped to (0, 1):
/// root i of P_n by Newton's method from the Chebyshev-like first guess,
/// node (1 − x)/2, weight 1/((1 − x²) P_n'(x)²).
pub fn gauss_legendre_node(n: usize, i: usize) -> (f64, f64) {
    let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
    let mut derivative = 0.0;
    for _ in 0..100 {
        let (mut p0, mut p1) = (1.0, x);
        for k in 2..=n {
            let k = k as f64;
            (p0, p1) = (p1, ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k);
        }
        derivative = n as f64 * (x * p1 - p0) / (x * x - 1.0);
        let step = p1 / derivative;
        x -= step;
        if step.abs() < 1e-16 {
            break;
        }
    }
    ((1.0 - x) / 2.0, 1.0 / ((1.0 - x * x) * derivative * derivative))
}

/// ∫₀¹ f by Gauss–Legendre with GAUSS_NODES nodes (computed once by Newton
/// steps on the Legendre polynomial).
fn gauss_legendre(f: impl Fn(f64) -> f64) -> f64 {
    static RULE: std::sync::OnceLock<[(f64, f64); GAUSS_NODES]> = std::sync::OnceLock::new();
    let rule = RULE.get_or_init(|| {
        let n = GAUSS_NODES;
        std::array::from_fn(|i| gauss_legendre_node(n, i))
    });
    rule.iter().map(|&(node, weight)| weight * f(node)).sum()
}

fn beta_function_return(a: f64) -> f64 {
    beta(a, 0.5) * a
}

/// Nodes of tanh–sinh quadrature on (0, 1): z = 1/(1 + e^(−π sinh t)), with
/// 1 − z kept separately (the integrands need it near z = 1) and the weight
/// dz/dt = π cosh t · z (1 − z), for t = k h, h = 2^−FINEST_LEVEL, 0 ≤ t ≤ T_MAX.
struct TanhSinhNode {
    z: f64,
    complement: f64,
    weight: f64,
}

const FINEST_LEVEL: u32 = 7;
/// Beyond |t| = 4 the weights are below 1e-36: even a 1/√(1 − z) end adds nothing.
const T_MAX: f64 = 4.0;

fn tanh_sinh_nodes() -> &'static [(TanhSinhNode, TanhSinhNode)] {
    static NODES: std::sync::OnceLock<Vec<(TanhSinhNode, TanhSinhNode)>> = std::sync::OnceLock::new();
    NODES.get_or_init(|| {
        let h = 0.5f64.powi(FINEST_LEVEL as i32);
        let count = (T_MAX / h) as usize;
        (0..=count)
            .map(|k| {
                let t = k as f64 * h;
                let (u, cosh) = (std::f64::consts::PI * t.sinh(), t.cosh());
                // The node at +t and its mirror at −t: z(−t) = 1 − z(t).
                let (small, large) = (1.0 / (1.0 + u.exp()), 1.0 / (1.0 + (-u).exp()));
                let weight = std::f64::consts::PI * cosh * small * large;
                (TanhSinhNode { z: large, complement: small, weight }, TanhSinhNode { z: small, complement: large, weight })
            })
            .collect()
    })
}

/// ∫₀¹ f(z) dz by tanh–sinh, f given z and 1 − z. Halves the step from 1/2
/// until two levels differ by at most `agreement` relative (or the finest
/// level is reached); non-finite terms give NaN.
fn tanh_sinh(f: impl Fn(f64, f64) -> f64, agreement: f64) -> f64 {
    let nodes = tanh_sinh_nodes();
    let term = |k: usize| {
        let (upper, lower) = &nodes[k];
        let value = upper.weight * f(upper.z, upper.complement);
        if k == 0 {
            value
        } else {
            value + lower.weight * f(lower.z, lower.complement)
        }
    };
    // Level 1 (h = 1/2): every 2^(FINEST−1)-th node.
    let mut stride = 1usize << (FINEST_LEVEL - 1);
    let mut sum: f64 = (0..nodes.len()).step_by(stride).map(term).sum();
    let mut estimate = sum * 0.5;
    while stride > 1 {
        stride /= 2;
        // The new level adds the odd multiples of the halved step.
        sum += (stride..nodes.len()).step_by(2 * stride).map(term).sum::<f64>();
        let h = stride as f64 * 0.5f64.powi(FINEST_LEVEL as i32);
        let refined = sum * h;
        if !refined.is_finite() {
            return f64::NAN;
        }
        let converged = (refined - estimate).abs() <= agreement * refined.abs();
        estimate = refined;
        if converged {
            break;
        }
    }
    estimate
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Adaptive Simpson on [a, b], an independent check of the quadrature.
    fn simpson(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tolerance: f64, depth: u32) -> f64 {
        let m = 0.5 * (a + b);
        let whole = (b - a) / 6.0 * (f(a) + 4.0 * f(m) + f(b));
        let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
        let left = (m - a) / 6.0 * (f(a) + 4.0 * f(lm) + f(m));
        let right = (b - m) / 6.0 * (f(m) + 4.0 * f(rm) + f(b));
        // The tolerance stops halving near rounding, so the recursion ends.
        if depth == 0 || (left + right - whole).abs() <= 15.0 * tolerance.max(1e-15 * whole.abs()) {
            left + right + (left + right - whole) / 15.0
        } else {
            simpson(f, a, m, 0.5 * tolerance, depth - 1) + simpson(f, m, b, 0.5 * tolerance, depth - 1)
        }
    }

    /// I(n, β) by Simpson in another variable: y = 1 − u⁴ at the turning
    /// point (u ∈ [0, 2^(−1/4)]) and y = w⁴ at y = 0, so both ends are smooth
    /// enough for a low-order rule.
    fn independent(exponent: f64, beta: f64) -> f64 {
        let upper = |u: f64| {
            // q(1 − u⁴)/u⁴ without cancellation; the integrand is 4/√(q/u⁴) · u.
            let u4 = u.powi(4);
            let ratio = if u == 0.0 { exponent + 1.0 - beta } else { -((exponent + 1.0) * (-u4).ln_1p()).exp_m1() / u4 - beta };
            4.0 * u / ratio.sqrt()
        };
        let lower = |w: f64| {
            // 4w³/√q with q/w⁴ = (1 − β)/w⁴ + β − yⁿ; the integrand vanishes at w = 0.
            let y = w.powi(4);
            if w == 0.0 {
                0.0
            } else {
                4.0 * w / ((1.0 - beta) / y + beta - y.powf(exponent)).sqrt()
            }
        };
        let split = 0.5f64;
        simpson(&upper, 0.0, (1.0 - split).powf(0.25), 1e-14, 30) + simpson(&lower, 0.0, split.powf(0.25), 1e-14, 30)
    }

    #[test]
    fn no_drive_is_the_beta_function() {
        // The tanh–sinh path itself against B(1/(n+1), 1/2)/(n+1).
        for exponent in [1.0, 1.35, 2.0, 3.0] {
            let quadrature = driven_return_integral(exponent, 1.0 - 1e-16);
            let a = 1.0 / (exponent + 1.0);
            let exact = beta(a, 0.5) * a;
            assert!((quadrature / exact - 1.0).abs() < 1e-14, "n = {exponent}: {quadrature} vs {exact}");
        }
        // n = 1: π/2, the quarter period of Eq. 43.
        assert!((driven_return_integral(1.0, 1.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }

    #[test]
    fn linear_law_under_a_drive_has_a_closed_form() {
        // n = 1: q = (1 − y)(1 + y − β), so I = 2 asin(1/√(2 − β)); at β = 1
        // the ball just gets back to δ = 0 and I = π.
        for beta in [-5.0f64, -1.0, -0.1, 0.1, 0.5, 0.9, 0.99, 0.9999, 1.0] {
            let exact = 2.0 * (1.0 / (2.0 - beta).sqrt()).asin();
            let quadrature = driven_return_integral(1.0, 1.0 - beta);
            assert!((quadrature / exact - 1.0).abs() < 1e-13, "β = {beta}: {quadrature} vs {exact}");
        }
    }

    #[test]
    fn nonlinear_laws_match_an_independent_quadrature() {
        for exponent in [1.35, 2.0, 3.0, 0.5] {
            for beta in [-3.0, -0.5, 0.3, 0.9, 0.999, 1.0] {
                let quadrature = driven_return_integral(exponent, 1.0 - beta);
                let reference = independent(exponent, beta);
                assert!((quadrature / reference - 1.0).abs() < 1e-10, "n = {exponent}, β = {beta}: {quadrature} vs {reference}");
            }
        }
    }

    #[test]
    fn gauss_legendre_and_tanh_sinh_agree_where_they_meet() {
        for exponent in [1.0, 1.35, 1.9, 3.0] {
            for margin in [GAUSS_MARGIN, 0.7, 1.5, 6.0] {
                let gauss = driven_return_integral(exponent, margin);
                let tanh = tanh_sinh(return_integrand(exponent, margin), 1e-12);
                assert!((gauss / tanh - 1.0).abs() < 1e-13, "n = {exponent}, margin {margin}: {gauss} vs {tanh}");
            }
        }
    }

    #[test]
    fn a_ball_that_cannot_get_back_gives_nan() {
        assert!(driven_return_integral(1.35, -1e-9).is_nan());
        assert!(driven_return_integral(-1.0, 0.5).is_nan());
    }
}
