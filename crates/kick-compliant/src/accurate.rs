//! Event-located solvers on the full state of Eq. 47 (plus running integrals):
//! `accurate` / `dop853`, `dopri5` and `rk4-events`. See [`crate::events`] for
//! how events are located.
//!
//! Accuracy (measured by `kick bench` and held by the tests): `accurate`
//! (Dop853, rtol = atol = 1e-12 in scaled units) is within 1e-9 relative of
//! the closed forms on every observable across the stress ranges of the
//! README; `dopri5` at its default 1e-11 reaches ~1e-9; `rk4-events` has the
//! fourth-order error of its step but no step quantisation of the stop, and
//! refuses a step too large for the contact ([`crate::stability`]).

use crate::events::{Engine, Method, Recorder, StopAt};
use crate::history::{self, Sampler};
use crate::ode::{self, Branch, ContactOde, Extremes, State};
use crate::stability;
use kick_core::{
    AnyLaw, ContactLaw, ContactPhase, KickError, Outcome, RecordingSolver, Sample, Scenario, Solver, SolverPath, Spacing, StopReason,
    Streamed,
};
use std::ops::ControlFlow;

/// Adaptive Dop853 with located events: the default accurate solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accurate {
    pub relative_tolerance: f64,
    pub absolute_tolerance: f64,
}

impl Default for Accurate {
    fn default() -> Self {
        Accurate { relative_tolerance: 1e-12, absolute_tolerance: 1e-12 }
    }
}

impl Accurate {
    pub fn new(relative_tolerance: f64, absolute_tolerance: f64) -> Result<Self, KickError> {
        let accurate = Accurate { relative_tolerance, absolute_tolerance };
        accurate.method().validate()?;
        Ok(accurate)
    }
    pub fn method(&self) -> Method {
        Method::Dop853 { relative_tolerance: self.relative_tolerance, absolute_tolerance: self.absolute_tolerance }
    }
    /// Solve the scenario's masses and speeds with any contact law in place
    /// of the scenario's own (Eq. 20).
    pub fn solve_law<L: ContactLaw + Copy>(&self, scenario: &Scenario, law: L) -> Result<Outcome, KickError> {
        FullState { method: self.method(), path: SolverPath::Accurate }.run(scenario, law, None)
    }
    /// As [`Accurate::solve_law`], streaming a history (see [`RecordingSolver`]).
    pub fn solve_law_streamed<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        FullState { method: self.method(), path: SolverPath::Accurate }.streamed(scenario, law, spacing, sink)
    }
}

impl Solver for Accurate {
    fn name(&self) -> &'static str {
        "accurate"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        if let Some(boot) = scenario.boot() {
            return crate::boot::solve(self.method(), SolverPath::Accurate, scenario, boot, None);
        }
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.solve_law(scenario, law),
            law => self.solve_law(scenario, law),
        }
    }
}

impl RecordingSolver for Accurate {
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        if let Some(boot) = scenario.boot() {
            return crate::boot::solve_streamed(self.method(), SolverPath::Accurate, scenario, boot, spacing, sink);
        }
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.solve_law_streamed(scenario, law, spacing, sink),
            law => self.solve_law_streamed(scenario, law, spacing, sink),
        }
    }
}

/// Any ode_solvers method with event location on the full state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FullState {
    pub method: Method,
    /// Its path, whose name is the solver's name.
    pub path: SolverPath,
}

impl FullState {
    pub fn dop853(relative_tolerance: f64, absolute_tolerance: f64) -> Self {
        FullState { method: Method::Dop853 { relative_tolerance, absolute_tolerance }, path: SolverPath::Dop853 }
    }
    pub fn dopri5(relative_tolerance: f64, absolute_tolerance: f64) -> Self {
        FullState { method: Method::Dopri5 { relative_tolerance, absolute_tolerance }, path: SolverPath::Dopri5 }
    }
    pub fn rk4_events(step: f64) -> Self {
        FullState { method: Method::Rk4 { step }, path: SolverPath::Rk4Events }
    }

    fn run<L: ContactLaw + Copy>(&self, scenario: &Scenario, law: L, sampler: Option<&mut Sampler>) -> Result<Outcome, KickError> {
        let system = ContactOde::new(scenario, law, Branch::InContact);
        let mut engine = Engine::new(self.method, system, scenario)?;
        let y0 = ode::initial_state(scenario);
        let end = match sampler {
            Some(sampler) => {
                let sample = |t: f64, y: &State, phase: ContactPhase| system.sample(t, y, phase);
                let mut recorder = Recorder { sampler, sample: &sample };
                engine.run(scenario, &law, y0, StopAt::Separation, Some(&mut recorder))?
            }
            None => engine.run(scenario, &law, y0, StopAt::Separation, None)?,
        };
        let extremes = Extremes {
            peak_force: end.peak_force,
            peak_force_time: end.peak_force_time,
            max_compression: end.max_compression,
            max_compression_time: end.max_compression_time,
        };
        let outcome =
            ode::outcome(scenario, &system, &end.state, extremes, StopReason::Separated { t: end.time }, engine.evaluations, self.path)?;
        if let Some(step) = self.method.fixed_step() {
            stability::check_energy(scenario, &law, &outcome.energy, step, outcome.contact_time)?;
        }
        Ok(outcome)
    }

    fn streamed<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        history::stream(spacing, sink, |o| o.contact_time, |sampler| self.run(scenario, law, sampler))
    }
}

impl Solver for FullState {
    fn name(&self) -> &'static str {
        self.path.name()
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        if let Some(boot) = scenario.boot() {
            return crate::boot::solve(self.method, self.path, scenario, boot, None);
        }
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.run(scenario, law, None),
            law => self.run(scenario, law, None),
        }
    }
}

impl RecordingSolver for FullState {
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        if let Some(boot) = scenario.boot() {
            return crate::boot::solve_streamed(self.method, self.path, scenario, boot, spacing, sink);
        }
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.streamed(scenario, law, spacing, sink),
            law => self.streamed(scenario, law, spacing, sink),
        }
    }
}
