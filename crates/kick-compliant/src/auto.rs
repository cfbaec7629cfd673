//! `auto`: the cheapest path that is exact for the scene.
//!
//! | scene | path |
//! | --- | --- |
//! | no drive, c = 0 | `closed-form` (energy integral, Beta function) |
//! | no drive, n = 1 | `closed-form` (damped oscillator, undamped return) |
//! | the paper's law | `series` (power series to δ_max, energy integral back) |
//! | the shell ball, drive ≥ 0 | `series` ([`crate::shell_series`]: Taylor steps from touch to separation; `reduced` for a rebound that reaches the clamp F = 0) |
//! | a boot in series: the shell ball, drive ≥ 0 | `series` ([`crate::boot::series`]; `reduced` likewise at the clamp) |
//! | a boot in series, another law | `reduced` ([`crate::boot`]: (δ, δ̇, δ_b) on the engine) |
//! | another contact law | `reduced` (δ through the whole contact) |
//! | time history wanted | `accurate` (full state; outcome and history from one run) |
//!
//! With a history the outcome is `accurate`'s (method "accurate"), bit for
//! bit what `accurate` gives without one. The chosen path is reported in
//! [`kick_core::Outcome::method`].

use crate::closed::ClosedForm;
use crate::reduced::Reduced;
use crate::series::Series;
use crate::Accurate;
use kick_core::{KickError, Outcome, RecordingSolver, Sample, Scenario, Solver, SolverPath, Spacing, Streamed};
use std::ops::ControlFlow;

#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Auto {
    pub reduced: Reduced,
    pub accurate: Accurate,
    pub series: Series,
}

impl Auto {
    /// The path `solve` takes for this scenario (closed form, series or reduced).
    pub fn path(scenario: &Scenario) -> SolverPath {
        if ClosedForm::applies(scenario) {
            SolverPath::ClosedForm
        } else if Series::applies(scenario) {
            SolverPath::Series
        } else {
            SolverPath::Reduced
        }
    }
}

impl Solver for Auto {
    fn name(&self) -> &'static str {
        "auto"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        match Auto::path(scenario) {
            SolverPath::ClosedForm => ClosedForm.solve(scenario),
            // A shell series (bare or booted) hands a rebound that reaches the clamp F = 0 to `reduced`.
            SolverPath::Series => match self.series.solve(scenario) {
                Err(KickError::NotApplicable { .. }) => self.reduced.solve(scenario),
                other => other,
            },
            _ => self.reduced.solve(scenario),
        }
    }
}

impl RecordingSolver for Auto {
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        self.accurate.solve_streamed(scenario, spacing, sink)
    }
}
