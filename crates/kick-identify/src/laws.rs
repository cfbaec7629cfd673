//! The contact-law comparison: every law of `kick_core::laws` on a scenario,
//! solved by `kick_compliant::Accurate::solve_law_recorded` (Dop853 with
//! located events, generic over the law).

use kick_compliant::Accurate;
use kick_core::laws::{AnyLaw, LawError, LawKind, LawParameters};
use kick_core::{KickError, Outcome, Scenario};
use serde::Serialize;

/// Each law's parameters for one scenario: the hysteresis laws keep the
/// scenario's k and n and take χ from `restitution` at the scenario's V0;
/// Kelvin–Voigt takes the secant stiffness k δ_ref^(n−1) at the power law's
/// maximum compression `reference_compression`, and c from `restitution`.
pub fn law_parameters(scenario: &Scenario, restitution: f64, reference_compression: f64) -> LawParameters {
    let law = scenario.law();
    LawParameters {
        stiffness: law.stiffness,
        exponent: law.exponent,
        damping: law.damping,
        restitution,
        impact_speed: scenario.approach_speed(),
        reduced_mass: scenario.reduced_mass(),
        linear_stiffness: law.stiffness * reference_compression.powf(law.exponent - 1.0),
    }
}

/// One law on one scenario.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LawRun {
    pub law: LawKind,
    pub parameters: AnyLaw,
    pub outcome: Outcome,
    /// (t, F) samples of the pulse.
    pub pulse: Vec<(f64, f64)>,
}

/// All laws on one scenario, matched to the paper's law's restitution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LawComparison {
    pub name: String,
    pub scenario: Scenario,
    /// e of the paper's law on this scenario (Eq. 36), the target for the others.
    pub restitution: f64,
    pub runs: Vec<LawRun>,
}

/// Compare the five laws on `scenario`: the paper's law first, then the
/// others given its effective restitution and (Kelvin–Voigt) its δ_max.
pub fn compare(name: &str, scenario: &Scenario, solver: &Accurate, interval: f64) -> Result<LawComparison, KickError> {
    let paper = solver.solve_law(scenario, scenario.law())?;
    let parameters = law_parameters(scenario, paper.restitution.clamp(f64::MIN_POSITIVE, 1.0), paper.max_compression);
    let mut runs = Vec::new();
    for kind in LawKind::ALL {
        let law = AnyLaw::new(kind, &parameters).map_err(|e| match e {
            LawError::Invalid(k) => k,
            other => KickError::Integration { time: 0.0, reason: other.to_string() },
        })?;
        let (outcome, history) = solver.solve_law_recorded(scenario, law, interval)?;
        let pulse = history.samples.iter().map(|s| (s.time, s.force)).collect();
        runs.push(LawRun { law: kind, parameters: law, outcome, pulse });
    }
    Ok(LawComparison { name: name.into(), scenario: *scenario, restitution: paper.restitution, runs })
}

