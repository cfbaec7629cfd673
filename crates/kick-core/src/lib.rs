//! Core of the kick workspace: scenario parameters with validated construction,
//! the contact-law abstraction, outcome types and errors shared by every model level.
//!
//! Equation numbers refer to "The Millisecond Physics of a Soccer Kick"
//! (`shared/paper/millisecond-physics-of-a-soccer-kick.md`).

pub mod error;
pub mod check;
pub mod law;
pub mod laws;
pub mod models;
pub mod outcome;
pub mod paper;
pub mod roots;
pub mod scenario;
pub mod special;

pub use error::KickError;
pub use law::{ContactLaw, PowerLawContact};
pub use laws::{AnyLaw, LawKind};
pub use outcome::{EnergyBudget, ExitVelocities, History, Outcome, Sample, StopReason, OBSERVABLES};
pub use scenario::{Parameter, Scenario, ScenarioSpec};

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

/// A solver that can also record the time history of the contact.
pub trait RecordingSolver: Solver {
    /// Solve and record samples spaced by at most `interval` seconds (plus every event).
    fn solve_recorded(&self, scenario: &Scenario, interval: f64)
        -> Result<(Outcome, History), KickError>;
}

/// A model level that predicts exit velocities from a scenario and its own
/// extra input (an impulse, a restitution coefficient, a contact law).
pub trait ExitModel {
    fn exit_velocities(&self, scenario: &Scenario) -> Result<ExitVelocities, KickError>;
}
