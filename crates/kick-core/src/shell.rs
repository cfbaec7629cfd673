//! A pressurised ball as a contact law, from quantities one can measure on a
//! ball: inflation pressure, radius, the gas's adiabatic exponent, and the
//! shell's own stiffness and loss ([`ShellBall`], its parameters declared
//! once in [`BALL_PARAMETERS`]). Sources and every default's trace: the
//! SOURCES.md of kick-bounce, where the ball is calibrated.
//!
//! Normal force on a flat rigid surface at compression δ (the ball flattened
//! over a disc of area A, the gas compressed adiabatically by the cap it loses):
//!
//! - A(δ) = π(2Rδ − δ²), the flat patch, and V(δ) = V0 − πδ²(3R − δ)/3,
//!   V0 = 4πR³/3, so dV/dδ = −A exactly;
//! - P(δ) = (p0 + p_atm)(V0/V)^γ, absolute; the gauge pressure P − p_atm acts
//!   over A: F_gas = (P − p_atm) A (Wesson's "pressure times contact area",
//!   with the gas compression that makes it stiffen). The gas is elastic:
//!   adiabatic and reversible;
//! - the shell's own resistance to flattening, linear: F_shell = k_s δ;
//! - the losses, in the shell: the shell material over the patch is
//!   flattened at the rate δ̇ and resists with a viscous stress β δ̇, so
//!   F = A(δ) (P(δ) − p_atm + β δ̇) + k_s δ, clamped at F ≥ 0.
//!
//! Why the losses sit there: a soccer ball's kinetic-energy loss on impact
//! is the viscoelastic loss of its shell (carcass, bladder, outer panels:
//! Price et al. 2008, kick-bounce SOURCES.md), while the air, compressed for
//! ~9 ms, exchanges heat only within ~0.5 mm of the wall (√(α t_c), α of
//! air 2.2e-5 m²/s): a loss of the order of 0.3 % of the gas's stored
//! energy, left out. The shell's loss depends on how far and how fast it
//! is flattened (δ, δ̇), not on the pressure behind it, so a harder ball,
//! which stores more of the impact in its gas, returns more of it:
//! restitution rises with pressure. The loss vanishes at first touch (A = 0:
//! no force jump, as Cross 1999 finds for every ball he measured). Its speed
//! dependence is a consequence, stated: at small δ the law is
//! 2πR (p0 + k_s/(2πR) + β δ̇) δ, Hunt–Crossley with χ = β/(p0 + k_s/(2πR)),
//! so restitution is the exact hysteresis relation of x0 = β V/(p0 + k_s/(2πR))
//! ([`crate::laws`]): it falls with impact speed and rises with pressure,
//! through their ratio. β is identified from one rebound test (kick-bounce).
//!
//! Vella et al. (2012)'s point-indentation stiffness of pressurised shells
//! and Hubbard & Stronge's membrane models describe a ball pressed by a
//! point or a curved body; on a flat plate the membrane's tension over the
//! flat patch is the pressure term above, and the shell's bending is the
//! small correction k_s.
//!
//! Valid while the patch is small against the ball, δ ≤ R/2 (`LawKind::validity`,
//! [`crate::validity`]); the formulas stay finite and repulsive up to δ → 2R,
//! where V → 0 and P → ∞, but a result past R/2 is flagged outside the
//! law's validity (status 4) by every front end and file, never reported as
//! a ball's.

use crate::error::KickError;
use crate::law::ContactLaw;
use crate::parameters::ParameterDef;
use serde::Serialize;
use std::f64::consts::PI;

// The ball's declared parameters live with the others (crate::parameters).
pub use crate::parameters::{GAS_EXPONENT, INFLATION_PRESSURE, SEA_LEVEL_PRESSURE, SHELL_DAMPING, SHELL_DAMPING_FIFA, SHELL_STIFFNESS};

/// Terms of [`AIR_SERIES`].
const AIR_TERMS: usize = 24;
/// Largest gas share c the series takes: there the terms after the 24th
/// sum to below 1e-19 of the increment (a_k < 10, c²⁴ < 1.7e-20).
const AIR_SERIES_LIMIT: f64 = 0.15;
/// Where sixteen terms do: the 17th and all after it are below 4e-18 of
/// the increment (a_k < 8, c¹⁶ < 2.9e-18).
const SHORT_SERIES_LIMIT: f64 = 0.08;
/// a_1..a_24 of (1 − c)^(−7/5) − 1 = Σ a_k c^k, a_k = a_{k−1}(γ + k − 1)/k.
const AIR_SERIES: [f64; AIR_TERMS] = {
    let mut terms = [0.0; AIR_TERMS];
    let mut a = 1.0;
    let mut k = 0;
    while k < AIR_TERMS {
        a = a * (1.4 + k as f64) / (k + 1) as f64;
        terms[k] = a;
        k += 1;
    }
    terms
};

/// (V0/V)^γ − 1 at c = (V0 − V)/V0, the share of the gas the cap takes
/// (below 0.1 in a kick, 0.18 in a 30 m/s bounce):
/// - γ = 7/5 (air, adiabatic; the default) and c ≤ 0.15: the binomial
///   series in Estrin's scheme, a third of one `powf`'s latency (`powf`
///   was a sixth of a 3D patch kick's time), with the increment's own
///   digits (~1e-16 of itself) where c is tiny;
/// - γ = 1 (isothermal): c/(1 − c);
/// - otherwise one `powf`, whose rounding, ~1e-16 of (V0/V)^γ, is ~1e-16
///   of the gauge pressure too (≥ p0 > 0).
#[inline(always)]
fn gas_increment(gamma: f64, c: f64) -> f64 {
    if gamma == 1.4 && c <= AIR_SERIES_LIMIT {
        let a = &AIR_SERIES;
        let (c2, c4) = (c * c, c * c * c * c);
        let c8 = c4 * c4;
        let pair = |i: usize| a[i] + a[i + 1] * c;
        let quad = |i: usize| pair(i) + pair(i + 2) * c2;
        let oct = |i: usize| quad(i) + quad(i + 4) * c4;
        // Below c = 0.08 (a kick's compressions) sixteen terms leave < 1e-18 of the increment.
        if c <= SHORT_SERIES_LIMIT {
            c * (oct(0) + oct(8) * c8)
        } else {
            c * (oct(0) + (oct(8) + oct(16) * c8) * c8)
        }
    } else if gamma == 1.0 {
        c / (1.0 - c)
    } else {
        (1.0 / (1.0 - c)).powf(gamma) - 1.0
    }
}

/// A pressurised ball's normal contact law (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShellBall {
    /// p0, gauge inflation pressure, Pa.
    pub pressure: f64,
    /// R, m.
    pub radius: f64,
    /// p_atm, Pa.
    pub atmospheric_pressure: f64,
    /// γ: 1.4 adiabatic (air), 1 isothermal.
    pub gas_exponent: f64,
    /// k_s, N/m.
    pub shell_stiffness: f64,
    /// β, Pa s/m: the shell's viscous stress per unit compression rate.
    pub shell_damping: f64,
}

/// The shell law's own parameters (beside the ball's mass and radius).
pub static BALL_PARAMETERS: [ParameterDef; 4] = [INFLATION_PRESSURE, GAS_EXPONENT, SHELL_STIFFNESS, SHELL_DAMPING];

impl ShellBall {
    /// Each value checked against its declaration (`radius` finite and > 0).
    pub fn new(pressure: f64, radius: f64, gas_exponent: f64, shell_stiffness: f64, shell_damping: f64) -> Result<ShellBall, KickError> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(KickError::invalid("ball_radius", radius, "finite and > 0"));
        }
        Ok(ShellBall {
            pressure: INFLATION_PRESSURE.check(pressure)?,
            radius,
            atmospheric_pressure: SEA_LEVEL_PRESSURE,
            gas_exponent: GAS_EXPONENT.check(gas_exponent)?,
            shell_stiffness: SHELL_STIFFNESS.check(shell_stiffness)?,
            shell_damping: SHELL_DAMPING.check(shell_damping)?,
        })
    }

    /// The defaults of [`BALL_PARAMETERS`] at radius `radius`.
    pub fn default_with_radius(radius: f64) -> Result<ShellBall, KickError> {
        let d = |p: &ParameterDef| p.default_number();
        ShellBall::new(d(&INFLATION_PRESSURE), radius, d(&GAS_EXPONENT), d(&SHELL_STIFFNESS), d(&SHELL_DAMPING))
    }

    /// V0 = 4πR³/3.
    pub fn volume(&self) -> f64 {
        4.0 / 3.0 * PI * self.radius.powi(3)
    }

    /// A(δ) = π(2Rδ − δ²) for 0 ≤ δ ≤ 2R.
    pub fn patch_area(&self, compression: f64) -> f64 {
        let d = compression.clamp(0.0, 2.0 * self.radius);
        PI * d * (2.0 * self.radius - d)
    }

    /// V(δ) = V0 − πδ²(3R − δ)/3.
    pub fn gas_volume(&self, compression: f64) -> f64 {
        self.volume() - self.cap_volume(compression)
    }

    /// Cap volume V0 − V(δ) = πδ²(3R − δ)/3, computed directly (not as a difference).
    fn cap_volume(&self, compression: f64) -> f64 {
        let d = compression.clamp(0.0, 2.0 * self.radius);
        PI * d * d * (3.0 * self.radius - d) / 3.0
    }

    /// ln(V0/V) = −ln(1 − cap/V0), accurate for a small cap.
    fn log_compression_ratio(&self, compression: f64) -> f64 {
        -(-self.cap_volume(compression) / self.volume()).ln_1p()
    }

    /// Gauge pressure P(δ) − p_atm = p0 + (p0 + p_atm)((V0/V)^γ − 1), the
    /// increment from [`gas_increment`].
    #[inline(always)]
    pub fn gauge_pressure(&self, compression: f64) -> f64 {
        let absolute = self.pressure + self.atmospheric_pressure;
        // c = (V0 − V)/V0 = δ²(3R − δ)/(4R³), one division.
        let (d, r) = (compression.clamp(0.0, 2.0 * self.radius), self.radius);
        // 1/(4R³) first: a division on R alone is off the path from δ.
        let inverse = 1.0 / (4.0 * r * r * r);
        self.pressure + absolute * gas_increment(self.gas_exponent, d * d * (3.0 * r - d) * inverse)
    }

    /// dF/dδ at δ = 0: 2πR p0 + k_s (the gas is not yet compressed).
    pub fn small_compression_stiffness(&self) -> f64 {
        2.0 * PI * self.radius * self.pressure + self.shell_stiffness
    }

    /// F_elastic at δ ≥ 0 (what a right-hand side needs: no gradient).
    #[inline(always)]
    fn elastic_value(&self, compression: f64) -> f64 {
        if !(compression > 0.0) {
            return 0.0;
        }
        let d = compression.min(2.0 * self.radius);
        PI * d * (2.0 * self.radius - d) * self.gauge_pressure(d) + self.shell_stiffness * d
    }

    /// (F_elastic, F_elastic + β A δ̇) at δ, the patch computed once (zero at δ ≤ 0).
    #[inline(always)]
    fn elastic_and_unclamped(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        if !(compression > 0.0) {
            return (0.0, 0.0);
        }
        let d = compression.min(2.0 * self.radius);
        let area = PI * d * (2.0 * self.radius - d);
        let gauge = self.gauge_pressure(d);
        let shell = self.shell_stiffness * d;
        (area * gauge + shell, area * (gauge + self.shell_damping * compression_rate) + shell)
    }

    /// (A, P − p_atm, k_s δ) at δ > 0 (`elastic`'s and
    /// `elastic_and_unclamped`'s terms, the same operations), None at δ ≤ 0.
    #[inline(always)]
    fn pressure(&self, compression: f64) -> Option<(f64, f64, f64)> {
        if !(compression > 0.0) {
            return None;
        }
        let r = self.radius;
        let d = compression.min(2.0 * r);
        let area = PI * d * (2.0 * r - d);
        let gauge = self.gauge_pressure(d);
        Some((area, gauge, self.shell_stiffness * d))
    }

    /// dF_el/dδ at δ > 0 from its A and P − p_atm ([`ShellBall::pressure`]).
    #[inline(always)]
    fn elastic_gradient(&self, compression: f64, area: f64, gauge: f64) -> f64 {
        let r = self.radius;
        let d = compression.min(2.0 * r);
        let d_pressure = self.gas_exponent * (gauge + self.atmospheric_pressure) * area / self.gas_volume(d);
        d_pressure * area + gauge * 2.0 * PI * (r - d) + self.shell_stiffness
    }

    /// The gas pressure at δ, computed once for the values a layer in series
    /// needs of the law at one state ([`PressureAt`]).
    #[inline(always)]
    pub fn at(&self, compression: f64) -> PressureAt<'_> {
        PressureAt { ball: self, compression, terms: self.pressure(compression) }
    }

    /// (F_elastic, dF_elastic/dδ) at δ ≥ 0 (the gradient's former path,
    /// which the test of `slip_terms` holds `PressureAt` to).
    #[cfg(test)]
    fn elastic(&self, compression: f64) -> (f64, f64) {
        if !(compression > 0.0) {
            return (0.0, self.small_compression_stiffness());
        }
        let r = self.radius;
        let d = compression.min(2.0 * r);
        let area = PI * d * (2.0 * r - d);
        let gauge = self.gauge_pressure(d);
        // dP/dδ = γ P A / V (dV/dδ = −A).
        let d_pressure = self.gas_exponent * (gauge + self.atmospheric_pressure) * area / self.gas_volume(d);
        let gradient = d_pressure * area + gauge * 2.0 * PI * (r - d) + self.shell_stiffness;
        (self.elastic_value(d), gradient)
    }

    /// The elastic force F_gas + F_shell at compression δ (zero at δ ≤ 0).
    #[inline(always)]
    pub fn elastic_force(&self, compression: f64) -> f64 {
        self.elastic_value(compression)
    }

    /// β A(δ), the loss's slope in δ̇: the force is F_el(δ) + β A(δ) δ̇
    /// before the clamp, affine in the rate (the 3D patch spreads both parts).
    #[inline(always)]
    pub fn loss_slope(&self, compression: f64) -> f64 {
        self.shell_damping * self.patch_area(compression)
    }

    /// (F_el, β A, ∂F/∂δ at δ̇ = 0, ∂(β A)/∂δ) at δ: what a slipping patch
    /// needs (kick-3d), the gas pressure computed once where
    /// `elastic_force`, `loss_slope` and two `force_gradient` calls (at
    /// δ̇ = 0 and 1, the second less the first) computed it seven times.
    /// The same operations in the same order: equal to theirs to the bit
    /// (test `slip_terms_are_the_separate_calls_to_the_bit`).
    #[inline(always)]
    pub fn slip_terms(&self, compression: f64) -> (f64, f64, f64, f64) {
        let at = self.at(compression);
        let gradient = at.elastic_gradient();
        let d_compression = |rate: f64| match at.at_rate(gradient, rate) {
            (_, _, true) => 0.0,
            (_, d_compression, false) => d_compression,
        };
        let d_elastic = d_compression(0.0);
        (at.elastic(), at.slope(), d_elastic, d_compression(1.0) - d_elastic)
    }

    /// (F_el, F_el + β A δ̇, ∂F/∂δ, ∂F/∂δ̇) at (δ, δ̇): `unclamped_force`
    /// and `force_gradient` (zero gradients where the clamp holds F at 0)
    /// from one gas pressure, where the two calls computed it twice: what a
    /// slipping point contact needs per evaluation (kick-3d). The same
    /// operations in the same order, equal to theirs to the bit (test
    /// `slip_terms_are_the_separate_calls_to_the_bit`).
    #[inline(always)]
    pub fn unclamped_and_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64, f64, f64) {
        let at = self.at(compression);
        match at.at_rate(at.elastic_gradient(), compression_rate) {
            (force, _, true) => (at.elastic(), force, 0.0, 0.0),
            (force, d_compression, false) => (at.elastic(), force, d_compression, at.slope()),
        }
    }

    /// Hunt–Crossley's χ of the small-compression limit, β/(p0 + k_s/(2πR)),
    /// s/m: restitution there is `laws::exact_restitution(χ V)`.
    pub fn small_compression_hysteresis(&self) -> f64 {
        self.shell_damping * 2.0 * PI * self.radius / self.small_compression_stiffness()
    }
}

impl ContactLaw for ShellBall {
    #[inline]
    fn force(&self, compression: f64, compression_rate: f64) -> f64 {
        if compression > 0.0 {
            self.contact_force(compression, compression_rate)
        } else {
            0.0
        }
    }
    /// U = P0 V0/(γ − 1) [(V0/V)^(γ−1) − 1] − p_atm (V0 − V) + k_s δ²/2
    /// (P0 V0 ln(V0/V) − p_atm (V0 − V) at γ = 1): −∫ (P − p_atm) dV.
    fn potential(&self, compression: f64) -> f64 {
        let d = compression.max(0.0);
        let v0 = self.volume();
        let p0 = self.pressure + self.atmospheric_pressure;
        let g = self.gas_exponent;
        // ln(V0/V) and expm1 keep the digits of a small cap (no 1 + tiny − 1).
        let log_ratio = self.log_compression_ratio(d);
        let gas = if g == 1.0 { p0 * v0 * log_ratio } else { p0 * v0 * ((g - 1.0) * log_ratio).exp_m1() / (g - 1.0) };
        gas - self.atmospheric_pressure * self.cap_volume(d) + 0.5 * self.shell_stiffness * d * d
    }
    #[inline]
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.elastic_and_unclamped(compression, compression_rate).1.max(0.0)
    }
    #[inline]
    fn elastic_and_contact_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let (elastic, force) = self.elastic_and_unclamped(compression, compression_rate);
        (elastic, force.max(0.0))
    }
    #[inline]
    fn unclamped_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        self.elastic_and_unclamped(compression, compression_rate)
    }
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let (_, d_compression, d_rate) = self.force_and_gradient(compression, compression_rate);
        (d_compression, d_rate)
    }
    /// (F, ∂F/∂δ, ∂F/∂δ̇) = (F_el + β A δ̇, F_el' + 2πβ(R − δ) δ̇, β A); zero
    /// where the clamp holds F at 0 (at δ ≤ 0, the one-sided slope while approaching).
    #[inline]
    fn force_and_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64, f64) {
        self.at(compression).force_and_gradient(compression_rate)
    }
    /// (F_el, β A) from one gas pressure: F_el + β A δ̇ on both sides of δ̇ = 0.
    #[inline]
    fn rate_affine(&self, compression: f64, _compressing: bool) -> (f64, f64) {
        self.at(compression).rate_affine()
    }
    fn damps_compression_only(&self) -> bool {
        false
    }
}

/// The shell law at one compression with its gas pressure computed once
/// ([`ShellBall::at`]): a boot in series asks for (E, D) and then for the
/// gradient at the ball's own rate, which the split gives.
#[derive(Debug, Clone, Copy)]
pub struct PressureAt<'a> {
    ball: &'a ShellBall,
    compression: f64,
    /// (A, P − p_atm, k_s δ), None at δ ≤ 0; dF_el/dδ only when asked for.
    terms: Option<(f64, f64, f64)>,
}

impl PressureAt<'_> {
    /// F_el (zero at δ ≤ 0).
    #[inline(always)]
    fn elastic(&self) -> f64 {
        self.terms.map_or(0.0, |(area, gauge, shell)| area * gauge + shell)
    }

    /// β A(δ).
    #[inline(always)]
    fn slope(&self) -> f64 {
        self.ball.loss_slope(self.compression.clamp(0.0, 2.0 * self.ball.radius))
    }

    /// dF_el/dδ; at δ ≤ 0 the small-compression slope, the one-sided limit while approaching.
    #[inline(always)]
    fn elastic_gradient(&self) -> f64 {
        match self.terms {
            Some((area, gauge, _)) => self.ball.elastic_gradient(self.compression, area, gauge),
            None => self.ball.small_compression_stiffness(),
        }
    }

    /// (F before the clamp, ∂F/∂δ, whether the clamp holds F at 0 nearby)
    /// at the rate δ̇, from dF_el/dδ.
    #[inline(always)]
    fn at_rate(&self, gradient: f64, compression_rate: f64) -> (f64, f64, bool) {
        let ball = self.ball;
        let force = self.terms.map_or(0.0, |(area, gauge, shell)| area * (gauge + ball.shell_damping * compression_rate) + shell);
        let d = self.compression.clamp(0.0, 2.0 * ball.radius);
        let d_compression = gradient + ball.shell_damping * 2.0 * PI * (ball.radius - d) * compression_rate;
        (force, d_compression, force < 0.0 || (force == 0.0 && d_compression <= 0.0))
    }

    /// `ContactLaw::rate_affine`: (F_el, β A) as the branch force at
    /// δ̇ = 1 less the elastic part (its former path, to the bit).
    #[inline(always)]
    pub fn rate_affine(&self) -> (f64, f64) {
        let (elastic, total) = match self.terms {
            Some((area, gauge, shell)) => (area * gauge + shell, (area * (gauge + self.ball.shell_damping * 1.0) + shell).max(0.0)),
            None => (0.0, 0.0),
        };
        (elastic, total - elastic)
    }

    /// `ContactLaw::force_and_gradient` at the rate δ̇: (F, ∂F/∂δ, ∂F/∂δ̇),
    /// zero where the clamp holds F at 0.
    #[inline(always)]
    pub fn force_and_gradient(&self, compression_rate: f64) -> (f64, f64, f64) {
        match self.at_rate(self.elastic_gradient(), compression_rate) {
            (_, _, true) => (0.0, 0.0, 0.0),
            (force, d_compression, false) => (force, d_compression, self.slope()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball() -> ShellBall {
        ShellBall::new(8.0e4, 0.11, 1.4, 2.0e3, 3.6e3).unwrap()
    }

    /// `slip_terms` is `elastic_force`, `loss_slope` and the two
    /// `force_gradient` calls it replaces, bit for bit, from before touch to
    /// past the ball's diameter (where every clamp and branch is met).
    #[test]
    fn slip_terms_are_the_separate_calls_to_the_bit() {
        for b in [ball(), ShellBall::new(6.0e4, 0.11, 1.0, 0.0, 3.6e3).unwrap()] {
            for i in -20..=500 {
                let delta = f64::from(i) * 5e-4 + if i % 3 == 0 { 1e-7 } else { 0.0 };
                let (d_elastic, _) = b.force_gradient(delta, 0.0);
                let separate = (b.elastic_force(delta), b.loss_slope(delta), d_elastic, b.force_gradient(delta, 1.0).0 - d_elastic);
                let joint = b.slip_terms(delta);
                assert_eq!(format!("{joint:?}"), format!("{separate:?}"), "δ = {delta}");
                // `force_and_gradient` from one gas pressure is its former two-call self.
                for rate in [-3.0, 0.0, 1.0, 7.5] {
                    let d = delta.clamp(0.0, 0.22);
                    let force = b.elastic_and_unclamped(delta, rate).1;
                    let gradient = b.elastic(delta).1 + b.shell_damping * 2.0 * PI * (b.radius - d) * rate;
                    let former =
                        if force < 0.0 || (force == 0.0 && gradient <= 0.0) { (0.0, 0.0, 0.0) } else { (force, gradient, b.loss_slope(d)) };
                    assert_eq!(format!("{:?}", b.force_and_gradient(delta, rate)), format!("{former:?}"), "δ = {delta}, δ̇ = {rate}");
                    // `unclamped_and_gradient` is `unclamped_force` and `force_gradient`.
                    let ((elastic, raw), (d_delta, d_rate)) = (b.unclamped_force(delta, rate), b.force_gradient(delta, rate));
                    let separate = (elastic, raw, d_delta, d_rate);
                    assert_eq!(format!("{:?}", b.unclamped_and_gradient(delta, rate)), format!("{separate:?}"), "δ = {delta}, δ̇ = {rate}");
                }
                // `rate_affine` is the trait's default (the branch force at δ̇ = 1 less the elastic part).
                let (elastic, total) = b.branch_force(delta, 1.0, true);
                assert_eq!(format!("{:?}", b.rate_affine(delta, true)), format!("{:?}", (elastic, total - elastic)), "δ = {delta}");
            }
        }
    }

    /// Small δ: F ≈ (2πR p0 + k_s) δ, the pressure over the patch (the
    /// closed form k ≈ 2πR p). The next order is O(δ²), so F/δ − k = O(δ).
    #[test]
    fn small_compression_stiffness_is_two_pi_r_p() {
        let b = ball();
        let k = 2.0 * PI * 0.11 * 8.0e4 + 2.0e3;
        assert_eq!(b.small_compression_stiffness(), k);
        for d in [1e-6, 1e-7] {
            let secant = b.elastic_force(d) / d;
            assert!((secant / k - 1.0).abs() < 20.0 * d / 0.11, "δ={d}: {secant} vs {k}");
        }
    }

    /// The gas volume and patch: V(2R) = 0 and V(R) = V0/2; dV/dδ = −A.
    #[test]
    fn geometry_closed_forms() {
        let b = ball();
        assert!(b.gas_volume(0.22).abs() < 1e-15 * b.volume());
        assert!((b.gas_volume(0.11) / b.volume() - 0.5).abs() < 1e-15);
        for d in [0.005, 0.02, 0.05] {
            let h = 1e-7;
            let dv = (b.gas_volume(d + h) - b.gas_volume(d - h)) / (2.0 * h);
            assert!((dv + b.patch_area(d)).abs() < 1e-9 * b.patch_area(d), "{d}");
        }
        // Isothermal, no shell: P V = P0 V0 (Boyle) at δ = R.
        let iso = ShellBall::new(8.0e4, 0.11, 1.0, 0.0, 0.0).unwrap();
        let absolute = iso.gauge_pressure(0.11) + SEA_LEVEL_PRESSURE;
        assert!((absolute - 2.0 * (8.0e4 + SEA_LEVEL_PRESSURE)).abs() < 1e-9 * absolute);
    }

    /// U(δ) = ∫₀^δ F(s, 0) ds by composite Simpson (smooth integrand: error
    /// O(h⁴), ~1e-14 relative with 2000 panels), for γ = 1.4 and γ = 1.
    #[test]
    fn potential_is_the_integral_of_the_elastic_force() {
        for b in [ball(), ShellBall::new(6.0e4, 0.1, 1.0, 0.0, 0.0).unwrap()] {
            for d in [0.01, 0.04, 0.08] {
                let integral = crate::test_support::simpson(|s| b.force(s, 0.0), d, 2000);
                let u = b.potential(d);
                assert!((integral - u).abs() <= 1e-11 * u, "{b:?} δ={d}: {integral} vs {u}");
            }
        }
    }

    /// Tiny δ: U = ∫ (P − p_atm) dV → p0 (V0 − V) + O(cap²), kept to
    /// rounding (a plain (V0/V)^(γ−1) − 1 loses ten digits at δ = 1e-6 m).
    #[test]
    fn potential_keeps_its_digits_at_small_compression() {
        let b = ShellBall::new(8.0e4, 0.11, 1.4, 0.0, 0.0).unwrap();
        for d in [1e-6, 1e-8] {
            let cap = PI * d * d * (3.0 * 0.11 - d) / 3.0;
            let u = b.potential(d);
            // Next order: γ P0 cap²/(2 V0), relative γ P0 cap/(2 p0 V0) < 1e-9 here.
            assert!((u / (8.0e4 * cap) - 1.0).abs() < 1e-9, "δ={d}: {u} vs {}", 8.0e4 * cap);
        }
    }

    /// (V0/V)^γ − 1 against expm1(−γ ln(1 − c)) (a few ulp of the
    /// increment itself): the series to 4e-16 of the increment over its
    /// whole range, both sides of its sixteen-term limit and at its end,
    /// where powf takes over; γ = 1 in closed form. (x^γ − 1, the form
    /// before the series, keeps only ~1e-16/c of the increment.) Then the
    /// gauge pressure with c = δ²(3R − δ)/(4R³) against p0 + P0 times the
    /// reference.
    #[test]
    fn gas_increment_keeps_its_digits() {
        let reference = |gamma: f64, c: f64| (-gamma * (-c).ln_1p()).exp_m1();
        for gamma in [1.4, 1.0, 1.2, 5.0 / 3.0] {
            let mut c = 1e-12;
            while c < 0.3 {
                for c in [c, SHORT_SERIES_LIMIT, SHORT_SERIES_LIMIT.next_up(), AIR_SERIES_LIMIT, AIR_SERIES_LIMIT.next_up()] {
                    let (got, want) = (gas_increment(gamma, c), reference(gamma, c));
                    // powf's own rounding is ~1e-16 of (V0/V)^γ, not of the increment.
                    let bound = if gamma == 1.4 && c <= AIR_SERIES_LIMIT || gamma == 1.0 { 4e-16 * want } else { 4e-16 * (1.0 + want) };
                    assert!((got - want).abs() <= bound, "γ {gamma}, c {c}: {got} vs {want}");
                }
                c *= 1.37;
            }
        }
        let b = ShellBall::new(8.0e4, 0.11, 1.4, 0.0, 0.0).unwrap();
        for d in [1e-6, 1e-4, 0.01, 0.03, 0.06, 0.1] {
            let cap = PI * d * d * (3.0 * 0.11 - d) / 3.0;
            let want = 8.0e4 + (8.0e4 + SEA_LEVEL_PRESSURE) * reference(1.4, cap / b.volume());
            assert!((b.gauge_pressure(d) / want - 1.0).abs() < 1e-15, "δ {d}: {} vs {want}", b.gauge_pressure(d));
        }
    }

    #[test]
    fn gradient_matches_finite_differences() {
        let b = ball();
        for &(d, r) in &[(0.005, 5.0), (0.02, -3.0), (0.05, 0.7)] {
            let (gd, gr) = b.force_gradient(d, r);
            let (hd, hr) = (1e-6 * d, 1e-5);
            let fd = (b.contact_force(d + hd, r) - b.contact_force(d - hd, r)) / (2.0 * hd);
            let fr = (b.contact_force(d, r + hr) - b.contact_force(d, r - hr)) / (2.0 * hr);
            assert!((gd - fd).abs() <= 1e-7 * gd.abs(), "d={d}: {gd} vs {fd}");
            assert!((gr - fr).abs() <= 1e-7 * gr.abs(), "d={d}: {gr} vs {fr}");
            assert_eq!(b.force_and_gradient(d, r), (b.contact_force(d, r), gd, gr));
        }
    }

    #[test]
    fn bad_values_name_their_parameter() {
        let named = |r: Result<ShellBall, KickError>| match r {
            Err(KickError::InvalidParameter { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(named(ShellBall::new(0.0, 0.11, 1.4, 0.0, 0.0)), "inflation_pressure");
        assert_eq!(named(ShellBall::new(-1.0, 0.11, 1.4, 0.0, 0.0)), "inflation_pressure");
        assert_eq!(named(ShellBall::new(f64::NAN, 0.11, 1.4, 0.0, 0.0)), "inflation_pressure");
        assert_eq!(named(ShellBall::new(8e4, 0.0, 1.4, 0.0, 0.0)), "ball_radius");
        assert_eq!(named(ShellBall::new(8e4, 0.11, 0.9, 0.0, 0.0)), "gas_exponent");
        assert_eq!(named(ShellBall::new(8e4, 0.11, 1.4, -1.0, 0.0)), "shell_stiffness");
        assert_eq!(named(ShellBall::new(8e4, 0.11, 1.4, 0.0, f64::INFINITY)), "shell_damping");
        crate::parameters::check_declarations(&BALL_PARAMETERS).unwrap();
    }

    /// The losses sit in the shell: F(δ, δ̇) − F(δ, 0) = β A(δ) δ̇ whatever
    /// the pressure, the gas and k_s (the gas is elastic), and it is zero at
    /// first touch (A(0) = 0: no jump).
    #[test]
    fn the_loss_is_the_shells_and_does_not_depend_on_pressure() {
        for (p, gamma, k_s) in [(6.0e4, 1.4, 0.0), (1.1e5, 1.4, 5.0e3), (8.0e4, 1.0, 0.0)] {
            let b = ShellBall::new(p, 0.11, gamma, k_s, 3.6e3).unwrap();
            for (d, v) in [(0.004, 6.0), (0.02, -3.0), (0.05, 12.0)] {
                let loss = b.contact_force(d, v) - b.elastic_force(d);
                let want = 3.6e3 * PI * d * (2.0 * 0.11 - d) * v;
                assert!((loss - want).abs() <= 1e-12 * b.elastic_force(d).max(want.abs()), "p {p}, δ {d}: {loss} vs {want}");
            }
            assert_eq!(b.contact_force(0.0, 30.0), 0.0);
            assert!(b.contact_force(1e-12, 30.0) < 1e-5, "{}", b.contact_force(1e-12, 30.0));
        }
        // The clamp: F ≥ 0, reached where the shell's loss outweighs the gas on a fast rebound.
        let b = ball();
        let rate = -2.0 * b.elastic_force(0.01) / b.loss_slope(0.01);
        assert_eq!(b.contact_force(0.01, rate), 0.0);
        assert!(b.unclamped_force(0.01, rate).1 < 0.0);
        assert_eq!(b.force_and_gradient(0.01, rate), (0.0, 0.0, 0.0));
    }

    /// At small δ the law is Hunt–Crossley's 2πR p0 δ (1 + χ δ̇) plus the
    /// shell's k_s δ (1 + χ δ̇), χ = β/(p0 + k_s/(2πR)): the secant
    /// F/δ against (2πR p0 + k_s)(1 + χ δ̇) to O(δ/R).
    #[test]
    fn small_compression_is_hunt_crossley() {
        let b = ball();
        let chi = b.small_compression_hysteresis();
        assert!((chi - 3.6e3 / (8.0e4 + 2.0e3 / (2.0 * PI * 0.11)) as f64).abs() < 1e-15 * chi);
        for d in [1e-6, 1e-7] {
            for v in [5.0, -2.0] {
                let want = b.small_compression_stiffness() * (1.0 + chi * v);
                let secant = b.contact_force(d, v) / d;
                assert!((secant / want - 1.0).abs() < 20.0 * d / 0.11, "δ={d}: {secant} vs {want}");
            }
        }
    }
}
