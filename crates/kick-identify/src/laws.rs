//! The contact-law comparison: every law of `kick_core::laws` on a scenario,
//! chosen the way every command chooses a law (`Scenario::with_law`) and
//! solved by `kick_compliant::Accurate` (Dop853 with located events).

use kick_compliant::Accurate;
use kick_core::laws::{AnyLaw, LawKind};
use kick_core::{KickError, Outcome, RecordingSolver, Scenario, Solver};
use serde::Serialize;

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

/// Compare the laws on `scenario`: the paper's law first, then the others
/// with its restitution as their target (`Scenario::with_law`: the
/// hysteresis laws keep k and n and take χ from e at V0; Kelvin–Voigt takes
/// the secant stiffness k δ*ⁿ⁻¹ at the undamped maximum compression δ* and
/// c from e). Pulses are recorded at most `interval` apart.
pub fn compare(name: &str, scenario: &Scenario, solver: &Accurate, interval: f64) -> Result<LawComparison, KickError> {
    let paper = solver.solve(&scenario.with_law(LawKind::PowerLaw, None)?)?;
    // A fully plastic paper's law (e = 0) has no target the others can take.
    let target = paper.restitution.clamp(f64::MIN_POSITIVE, 1.0);
    let mut runs = Vec::new();
    for kind in LawKind::ALL {
        let s = scenario.with_law(kind, Some(target))?;
        let (outcome, history) = solver.solve_recorded(&s, interval)?;
        let pulse = history.samples.iter().map(|x| (x.time, x.force)).collect();
        runs.push(LawRun { law: kind, parameters: s.contact_law(), outcome, pulse });
    }
    Ok(LawComparison { name: name.into(), scenario: *scenario, restitution: paper.restitution, runs })
}

/// The laws that take their damping from a target restitution.
pub const RESTITUTION_LAWS: [LawKind; 5] =
    [LawKind::HuntCrossley, LawKind::LankaraniNikravesh, LawKind::Flores, LawKind::HuntCrossleyExact, LawKind::KelvinVoigt];

/// Restitution each law gives when asked for e, on `scenario`: one row per
/// target, one value per [`RESTITUTION_LAWS`] entry (simulated, not a formula).
pub fn restitution_table(scenario: &Scenario, targets: &[f64], solver: &Accurate) -> Result<Vec<Vec<f64>>, KickError> {
    targets
        .iter()
        .map(|&e| RESTITUTION_LAWS.iter().map(|&kind| Ok(solver.solve(&scenario.with_law(kind, Some(e))?)?.restitution)).collect())
        .collect()
}
