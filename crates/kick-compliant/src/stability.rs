//! Step-size checks of the fixed-step methods (`seed-rk4`, `rk4-events`):
//! a step too large for the contact is an error that says so, never an
//! outcome and never "no separation".
//!
//! **A priori (stability).** Classical RK4 multiplies a mode e^{λt} by
//! R(hλ) = 1 + z + z²/2 + z³/6 + z⁴/24 per step and is stable iff
//! |R(hλ)| ≤ 1. The contact's fast modes are those of the relative motion
//! linearised about a state, μ s² + c_eff s + k_eff = 0 with k_eff = ∂F/∂δ
//! and c_eff = ∂F/∂δ̇ (centre-of-mass modes have λ = 0). They are taken at
//! the deepest compression the contact can reach, U(δ_ref) = ½ μ V0² +
//! max(f_s, 0) δ_ref (f_s = (μ/m_f) F_drive; damping only lowers δ_max), on
//! both branches (δ̇ = +V0 compressing, −V0 restoring). The largest stable
//! step is then min over λ of r(arg λ)/|λ|, r the radius of RK4's stability
//! region along the ray of λ ([`rk4_stability_radius`]: 2.785 on the negative
//! real axis, 2√2 on the imaginary axis, 2.62 at its narrowest near 124°).
//! Where it holds: for a stiffening law (n ≥ 1) k_eff is largest at δ_ref,
//! and c_eff of the laws here is largest at δ̇ = ±V0 and δ_ref, so the bound
//! covers every state of the contact. For n < 1, k_eff = n k δⁿ⁻¹ is
//! unbounded as δ → 0 and no fixed step is stable right at first touch (the
//! motion there is dominated by V0, so that costs little); the check at
//! δ_ref then does not cover the whole contact, and the a-posteriori check
//! below catches what it misses.
//!
//! **A posteriori (accuracy).** The energy budget K⁻ + W = K⁺ + U⁺ + D
//! (Eqs. 30–33), whose D and W are integrated alongside the state, closes to
//! the integrator's error. A run whose residual exceeds
//! [`ENERGY_RESIDUAL_BOUND`] of the energy through the contact,
//! ½ μ V0² + |f_s| δ_ref (the relative motion's kinetic energy and the most
//! work the drive's share can do on it), is refused as inaccurate. (The
//! drive's work on the centre of mass is integrated exactly by RK4 and left
//! out of the scale: at a horizon it would grow without bound and hide the
//! contact's error.) For `rk4-events`, a run that passes has exit velocities
//! within 0.5 × the bound of V0 on the shared test models (measured, held
//! by `tests/solvers/step_size.rs`). For `seed-rk4` the stop is quantised to the step
//! on top of that (see [`crate::seed`]).

use kick_core::{roots, ContactLaw, EnergyBudget, KickError, Scenario};

/// Largest accepted |(K⁻ + W) − (K⁺ + U⁺ + D)| / (½ μ V0² + |f_s| δ_ref) of a
/// fixed-step run. The paper's step (5 µs) leaves ~1e-6 on Table 2's rows.
pub const ENERGY_RESIDUAL_BOUND: f64 = 1e-3;

/// R(z) of classical RK4, |R|² for z = r e^{iθ}.
fn rk4_amplification_squared(r: f64, angle: f64) -> f64 {
    let (x, y) = (r * angle.cos(), r * angle.sin());
    // Horner in complex arithmetic: 1 + z(1 + z/2(1 + z/3(1 + z/4))).
    let (mut re, mut im) = (1.0, 0.0);
    for k in [4.0, 3.0, 2.0, 1.0] {
        let (a, b) = ((re * x - im * y) / k, (re * y + im * x) / k);
        re = 1.0 + a;
        im = b;
    }
    re * re + im * im
}

/// Radius of RK4's stability region along the ray at `angle` (radians, in
/// [π/2, π]): the first r > 0 where |R(r e^{iθ})| exceeds 1. Found by a scan
/// in steps of 0.05 (the region's boundary is at r > 2.6 on every such ray)
/// and bisection to rounding.
pub fn rk4_stability_radius(angle: f64) -> f64 {
    let angle = angle.clamp(std::f64::consts::FRAC_PI_2, std::f64::consts::PI);
    let mut high = 0.05;
    while rk4_amplification_squared(high, angle) <= 1.0 && high < 4.0 {
        high += 0.05;
    }
    let mut low = high - 0.05;
    for _ in 0..60 {
        let mid = 0.5 * (low + high);
        if rk4_amplification_squared(mid, angle) <= 1.0 {
            low = mid;
        } else {
            high = mid;
        }
    }
    low
}

/// Largest RK4 step stable on μ s² + c s + k = 0 (∞ when nothing moves).
fn largest_step_for(reduced_mass: f64, damping: f64, stiffness: f64) -> f64 {
    let (c, k) = (damping.abs(), stiffness.max(0.0));
    let discriminant = c * c - 4.0 * reduced_mass * k;
    let (modulus, angle) = if discriminant >= 0.0 {
        // Real roots; the faster one limits.
        ((c + discriminant.sqrt()) / (2.0 * reduced_mass), std::f64::consts::PI)
    } else {
        ((k / reduced_mass).sqrt(), (-discriminant).sqrt().atan2(-c))
    };
    if modulus > 0.0 {
        rk4_stability_radius(angle) / modulus
    } else {
        f64::INFINITY
    }
}

/// The deepest compression the contact can reach (see the module docs).
pub fn reference_compression<L: ContactLaw>(scenario: &Scenario, law: &L) -> f64 {
    let energy = scenario.relative_kinetic_energy();
    let drive_share = (scenario.reduced_mass() / scenario.effective_foot_mass() * scenario.drive_force()).max(0.0);
    let excess = |delta: f64| law.potential(delta) - drive_share * delta - energy;
    let mut high = scenario.elastic_max_compression();
    for _ in 0..200 {
        if excess(high) > 0.0 {
            break;
        }
        high *= 2.0;
    }
    roots::brent(excess, 0.0, high, 1e-12 * high, 200).map_or(high, |r| r.x.max(r.other))
}

/// The largest RK4 step stable on this contact (module docs).
pub fn largest_stable_rk4_step<L: ContactLaw>(scenario: &Scenario, law: &L) -> f64 {
    let delta = reference_compression(scenario, law);
    let speed = scenario.approach_speed();
    let mu = scenario.reduced_mass();
    [(speed, true), (-speed, false)]
        .into_iter()
        .map(|(rate, compressing)| {
            let (_, stiffness, damping) = law.branch_force_and_gradient(delta, rate, compressing);
            largest_step_for(mu, damping, stiffness)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Refuse an RK4 step beyond the stability limit (module docs).
pub fn check_rk4_step<L: ContactLaw>(scenario: &Scenario, law: &L, step: f64) -> Result<(), KickError> {
    let largest = largest_stable_rk4_step(scenario, law);
    if step <= largest {
        return Ok(());
    }
    Err(KickError::StepTooLarge {
        method: "classical RK4",
        step,
        largest_stable_step: largest,
        reason: format!(
            "|R(hλ)| ≤ 1 for both roots λ of the law linearised at the deepest compression {} m",
            kick_core::short(reference_compression(scenario, law))
        ),
    })
}

/// |residual| / (½ μ V0² + |f_s| δ_ref) of a budget (module docs).
pub fn relative_energy_residual<L: ContactLaw>(scenario: &Scenario, law: &L, budget: &EnergyBudget) -> f64 {
    let drive_share = scenario.reduced_mass() / scenario.effective_foot_mass() * scenario.drive_force().abs();
    let drive_work = if drive_share > 0.0 { drive_share * reference_compression(scenario, law) } else { 0.0 };
    budget.residual().abs() / (scenario.relative_kinetic_energy() + drive_work)
}

/// Refuse a fixed-step run whose energy budget does not close (module docs);
/// `time` is where the budget was taken.
pub fn check_energy<L: ContactLaw>(scenario: &Scenario, law: &L, budget: &EnergyBudget, step: f64, time: f64) -> Result<(), KickError> {
    let relative = relative_energy_residual(scenario, law, budget);
    if relative <= ENERGY_RESIDUAL_BOUND {
        return Ok(());
    }
    Err(KickError::StepTooInaccurate {
        step,
        relative_residual: if relative.is_nan() { f64::INFINITY } else { relative },
        bound: ENERGY_RESIDUAL_BOUND,
        time,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn stability_radius_matches_the_known_values() {
        // Real axis: the root of R(−r) = −1 is 2.785293563...; imaginary: 2√2.
        assert!((rk4_stability_radius(PI) - 2.785_293_563_405_282).abs() < 1e-12);
        assert!((rk4_stability_radius(PI / 2.0) - 8f64.sqrt()).abs() < 1e-12);
        // Along every ray the region is an interval from 0: a fine scan finds
        // no unstable point below the radius.
        for i in 0..=90 {
            let angle = PI / 2.0 + PI / 2.0 * i as f64 / 90.0;
            let r = rk4_stability_radius(angle);
            assert!(r > 2.6 && r < 2.97, "{angle}: {r}");
            for j in 1..1000 {
                assert!(rk4_amplification_squared(r * j as f64 / 1000.0, angle) <= 1.0 + 1e-12);
            }
        }
    }

    #[test]
    fn the_linear_oscillator_limit_is_two_root_two_over_omega() {
        // No damping: λ = ±iω, h_max = 2√2/ω; critical damping: λ = −ω twice.
        let (mu, k): (f64, f64) = (0.5, 2.0e5);
        let omega = (k / mu).sqrt();
        assert!((largest_step_for(mu, 0.0, k) * omega - 8f64.sqrt()).abs() < 1e-12);
        // (A double root: rounding in c² − 4μk moves it by ~√ε.)
        let critical = 2.0 * (k * mu).sqrt();
        assert!((largest_step_for(mu, critical, k) * omega - 2.785_293_563_405_282).abs() < 1e-7);
        // Heavy damping: the fast real root c/μ limits.
        let c = 1.0e4;
        let fast = (c + (c * c - 4.0 * mu * k).sqrt()) / (2.0 * mu);
        assert!((largest_step_for(mu, c, k) * fast - 2.785_293_563_405_282).abs() < 1e-9);
    }
}
