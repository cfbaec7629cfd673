//! `auto`: the cheapest path that is exact for the scene.
//!
//! | scene | path |
//! | --- | --- |
//! | no drive, c = 0 | `closed-form` (energy integral, Beta function) |
//! | no drive, n = 1 | `closed-form` (damped oscillator, undamped return) |
//! | the paper's law | `series` (power series to δ_max, energy integral back) |
//! | another contact law | `reduced` (δ through the whole contact) |
//!
//! A time history comes from `accurate` (the full state, every sample a
//! state of the integration); the outcome stays the path's own, so it is
//! the same with and without a history. The chosen path is reported in
//! [`kick_core::Outcome::method`].

use crate::closed::ClosedForm;
use crate::reduced::Reduced;
use crate::series::Series;
use crate::Accurate;
use kick_core::{KickError, Outcome, RecordingSolver, Sample, Scenario, Solver, Spacing, Streamed};
use std::ops::ControlFlow;

#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Auto {
    pub reduced: Reduced,
    pub accurate: Accurate,
    pub series: Series,
}

impl Auto {
    /// The name of the path `solve` takes for this scenario.
    pub fn path(scenario: &Scenario) -> &'static str {
        if ClosedForm::applies(scenario) {
            "closed-form"
        } else if Series::applies(scenario) {
            "series"
        } else {
            "reduced"
        }
    }
}

impl Solver for Auto {
    fn name(&self) -> &'static str {
        "auto"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        match Auto::path(scenario) {
            "closed-form" => ClosedForm.solve(scenario),
            "series" => self.series.solve(scenario),
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
        crate::history_through(self, &self.accurate, scenario, spacing, sink)
    }
}
