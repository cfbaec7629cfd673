//! Event-located solvers on the full state of Eq. 47 (plus running integrals):
//! `accurate` / `dop853`, `dopri5` and `rk4-events`. See [`crate::events`] for
//! how events are located.
//!
//! Accuracy (measured by `kick bench` and held by the tests): `accurate`
//! (Dop853, rtol = atol = 1e-12 in scaled units) is within 1e-9 relative of
//! the closed forms on every observable across the stress ranges of the
//! README; `dopri5` at its default 1e-11 reaches ~1e-9; `rk4-events` has the
//! fourth-order error of its step but no step quantisation of the stop.

use crate::events::{Engine, Method, StopAt};
use crate::ode::{self, Branch, ContactOde, Extremes, State};
use kick_core::{AnyLaw, ContactLaw, History, KickError, Outcome, RecordingSolver, Scenario, Solver, StopReason};

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
        Method::Dop853 {
            relative_tolerance: self.relative_tolerance,
            absolute_tolerance: self.absolute_tolerance,
        }
    }
    /// Solve the scenario's masses and speeds with any contact law in place
    /// of the scenario's own (Eq. 20).
    pub fn solve_law<L: ContactLaw + Copy>(&self, scenario: &Scenario, law: L) -> Result<Outcome, KickError> {
        FullState { method: self.method(), name: "accurate" }.run(scenario, law, None)
    }
    /// As [`Accurate::solve_law`], recording samples at most `interval` apart.
    pub fn solve_law_recorded<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        interval: f64,
    ) -> Result<(Outcome, History), KickError> {
        FullState { method: self.method(), name: "accurate" }.run_recorded(scenario, law, interval)
    }
}

impl Solver for Accurate {
    fn name(&self) -> &'static str {
        "accurate"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.solve_law(scenario, law),
            law => self.solve_law(scenario, law),
        }
    }
}

impl RecordingSolver for Accurate {
    fn solve_recorded(&self, scenario: &Scenario, interval: f64) -> Result<(Outcome, History), KickError> {
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.solve_law_recorded(scenario, law, interval),
            law => self.solve_law_recorded(scenario, law, interval),
        }
    }
}

/// Any ode_solvers method with event location on the full state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FullState {
    pub method: Method,
    pub name: &'static str,
}

impl FullState {
    pub fn dop853(relative_tolerance: f64, absolute_tolerance: f64) -> Self {
        FullState { method: Method::Dop853 { relative_tolerance, absolute_tolerance }, name: "dop853" }
    }
    pub fn dopri5(relative_tolerance: f64, absolute_tolerance: f64) -> Self {
        FullState { method: Method::Dopri5 { relative_tolerance, absolute_tolerance }, name: "dopri5" }
    }
    pub fn rk4_events(step: f64) -> Self {
        FullState { method: Method::Rk4 { step }, name: "rk4-events" }
    }

    fn run<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        recorder: Option<(&mut History, f64)>,
    ) -> Result<Outcome, KickError> {
        let system = ContactOde::new(scenario, law, Branch::InContact);
        let mut engine = Engine::new(self.method, system, scenario)?;
        let y0 = ode::initial_state(scenario);
        let end = match recorder {
            Some((history, interval)) => {
                let mut record = |t: f64, y: &State| history.samples.push(system.sample(t, y));
                engine.run(scenario, &law, y0, StopAt::Separation, Some((&mut record, interval)))?
            }
            None => engine.run(scenario, &law, y0, StopAt::Separation, None)?,
        };
        let extremes = Extremes {
            peak_force: end.peak_force,
            peak_force_time: end.peak_force_time,
            max_compression: end.max_compression,
            max_compression_time: end.max_compression_time,
        };
        ode::outcome(
            scenario,
            &system,
            &end.state,
            extremes,
            StopReason::Separated { t: end.time },
            engine.evaluations,
            self.name,
        )
    }

    fn run_recorded<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        interval: f64,
    ) -> Result<(Outcome, History), KickError> {
        if !(interval.is_finite() && interval > 0.0) {
            return Err(KickError::InvalidParameter { name: "interval", value: interval, requirement: "finite and > 0" });
        }
        let mut history = History::default();
        let outcome = self.run(scenario, law, Some((&mut history, interval)))?;
        Ok((outcome, history))
    }
}

impl Solver for FullState {
    fn name(&self) -> &'static str {
        self.name
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.run(scenario, law, None),
            law => self.run(scenario, law, None),
        }
    }
}

impl RecordingSolver for FullState {
    fn solve_recorded(&self, scenario: &Scenario, interval: f64) -> Result<(Outcome, History), KickError> {
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.run_recorded(scenario, law, interval),
            law => self.run_recorded(scenario, law, interval),
        }
    }
}
