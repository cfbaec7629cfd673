//! Core of the kick workspace: scenario parameters with validated construction,
//! the contact-law abstraction, outcome types and errors shared by every model level.
//!
//! Equation numbers refer to *The Millisecond Physics of a Soccer Kick*;
//! each is stated, with the function that implements it, in `paper/model.md`.

pub mod boot;
pub mod bound;
pub mod check;
pub mod dop853;
pub mod error;
pub mod input;
pub mod law;
pub mod laws;
pub mod leg;
pub mod measurements;
pub mod models;
pub mod number;
pub mod outcome;
pub mod paper;
pub mod parameters;
pub mod roots;
pub mod scenario;
pub mod shell;
pub mod special;
pub mod threads;
pub mod validity;

/// Laws and rules the unit tests of several modules share.
#[cfg(test)]
pub(crate) mod test_support;

pub use boot::Boot;
pub use error::{KickError, Status};
pub use law::{ContactLaw, PowerLawContact};
pub use laws::{AnyLaw, LawKind};
pub use number::{short, sig};
pub use outcome::{
    ContactPhase, EnergyBudget, ExitVelocities, Grid, History, Outcome, Sample, SolverPath, Spacing, StopReason, HISTORY_COLUMNS,
    MAX_HISTORY_SAMPLES, OBSERVABLES,
};
pub use parameters::{Level, ParameterDef, SetLaw, SetParameter, Value, PARAMETERS};
pub use scenario::{Foot, Parameter, Scenario, ScenarioSpec};
pub use shell::ShellBall;
use std::ops::ControlFlow;
pub use validity::{OutsideValidity, Validity};

/// Standard gravity of every model level that has gravity (kick-3d's scene,
/// kick-flight), m/s².
pub const GRAVITY: f64 = 9.81;
/// m_b of Table 1's baseline, kg (inside Law 2's 410–450 g).
pub const DEFAULT_BALL_MASS: f64 = 0.43;
/// R of the default ball, m (circumference 0.691 m, inside Law 2's 0.68–0.70 m).
pub const DEFAULT_BALL_RADIUS: f64 = 0.11;

/// A solver turns a scenario into an outcome (argmin-style: one required method).
pub trait Solver {
    /// Short stable name, as used by `--solver` and written to result files.
    fn name(&self) -> &'static str;
    /// Summary of one contact; keeps no time history.
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError>;
}

/// The answer of [`RecordingSolver::solve_streamed`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Streamed {
    pub outcome: Outcome,
    /// Samples in the full history (more than the sink took if it stopped).
    pub samples: u64,
}

/// A solver that can also record the time history of the contact, as
/// uniformly spaced samples ([`Spacing`]).
///
/// Sampling never changes the steps, the physics or the step budget: the
/// outcome is bit-identical to [`Solver::solve`]'s (the samples' own
/// evaluations are not counted in [`Outcome::evaluations`]).
pub trait RecordingSolver: Solver {
    /// Solve and hand each sample to `sink` in time order as it is made;
    /// nothing is kept, so a writer can stream a history of any length.
    /// `sink` returns `Break` to stop sampling; the solve still runs to its
    /// outcome.
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError>;

    /// Solve and collect the history, at most `limit` samples; a longer one
    /// is a [`KickError::HistoryTooLong`] that states the size it needs.
    fn solve_sampled(&self, scenario: &Scenario, spacing: Spacing, limit: usize) -> Result<(Outcome, History), KickError> {
        if let Spacing::Count(n) = spacing.validate()? {
            if n > limit {
                return Err(KickError::HistoryTooLong { needed: n as f64, limit: limit as u64 });
            }
        }
        let mut samples = Vec::new();
        let streamed = self.solve_streamed(scenario, spacing, &mut |sample| {
            if samples.len() < limit {
                samples.push(*sample);
                ControlFlow::Continue(())
            } else {
                ControlFlow::Break(())
            }
        })?;
        if streamed.samples > limit as u64 {
            return Err(KickError::HistoryTooLong { needed: streamed.samples as f64, limit: limit as u64 });
        }
        Ok((streamed.outcome, History { samples }))
    }

    /// Samples `interval` seconds apart, at most [`MAX_HISTORY_SAMPLES`].
    fn solve_recorded(&self, scenario: &Scenario, interval: f64) -> Result<(Outcome, History), KickError> {
        self.solve_sampled(scenario, Spacing::Interval(interval), MAX_HISTORY_SAMPLES)
    }
}

/// A model level that predicts exit velocities from a scenario and its own
/// extra input (an impulse, a restitution coefficient, a contact law).
pub trait ExitModel {
    fn exit_velocities(&self, scenario: &Scenario) -> Result<ExitVelocities, KickError>;
}
