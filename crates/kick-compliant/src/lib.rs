//! The time-resolved 1D compliant contact model (Eqs. 13–20) and its solvers.
//!
//! - [`SeedRk4`]: the paper's fixed-step RK4 (Section 12), for reproducing its numbers.
//! - [`Accurate`]: adaptive Dop853 with located events, 1e-9 relative.
//! - [`closed`]: closed forms where they are exact (tests use them as the truth).

pub mod accurate;
pub mod closed;
pub mod ode;
pub mod seed;

pub use accurate::Accurate;
pub use seed::SeedRk4;

use kick_core::{History, KickError, Outcome, RecordingSolver, Scenario, Solver};

/// The solvers selectable by name (`--solver`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SolverChoice {
    SeedRk4(SeedRk4),
    Accurate(Accurate),
}

impl SolverChoice {
    pub const NAMES: [&'static str; 2] = ["seed-rk4", "accurate"];

    /// Look a solver up by its `--solver` name; `step` is the seed method's Δt.
    pub fn from_name(name: &str, step: f64) -> Result<SolverChoice, KickError> {
        match name {
            "seed-rk4" => Ok(SolverChoice::SeedRk4(SeedRk4::new(step)?)),
            "accurate" => Ok(SolverChoice::Accurate(Accurate::default())),
            _ => Err(KickError::UnknownSolver {
                name: name.to_string(),
                expected: "seed-rk4, accurate",
            }),
        }
    }
}

impl Solver for SolverChoice {
    fn name(&self) -> &'static str {
        match self {
            SolverChoice::SeedRk4(s) => s.name(),
            SolverChoice::Accurate(s) => s.name(),
        }
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        match self {
            SolverChoice::SeedRk4(s) => s.solve(scenario),
            SolverChoice::Accurate(s) => s.solve(scenario),
        }
    }
}

impl RecordingSolver for SolverChoice {
    fn solve_recorded(
        &self,
        scenario: &Scenario,
        interval: f64,
    ) -> Result<(Outcome, History), KickError> {
        match self {
            SolverChoice::SeedRk4(s) => s.solve_recorded(scenario, interval),
            SolverChoice::Accurate(s) => s.solve_recorded(scenario, interval),
        }
    }
}
pub mod table2;
