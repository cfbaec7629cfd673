//! The time-resolved 1D compliant contact model (Eqs. 13–20) and its solvers.
//!
//! - [`SeedRk4`]: the paper's fixed-step RK4 (Section 12), for reproducing its numbers.
//! - [`Accurate`]: adaptive Dop853 with located events, 1e-9 relative.
//! - [`closed`]: closed forms where they are exact (tests use them as the truth).
//! - [`FullState`]: `dop853`, `dopri5`, `rk4-events` on the full state.
//! - [`Reduced`], [`ReducedReturn`]: the relative coordinate only (Eq. 18).
//! - [`Series`]: the paper's law by power series through compression and the
//!   energy integral back (the fast accurate path).
//! - [`Auto`]: the cheapest exact path for the scene.
//!
//! Every solver records uniform time histories ([`kick_core::RecordingSolver`],
//! [`history`]) without changing its steps or its outcome; the fixed-step
//! methods refuse a step too large for the contact ([`stability`]); a ball
//! proven trapped is [`kick_core::KickError::Trapped`], a limit reached
//! without a proof [`kick_core::KickError::NoSeparation`].

pub mod accurate;
pub mod auto;
pub mod boot;
pub mod closed;
pub mod events;
pub mod history;
pub mod ode;
pub mod precision;
pub mod reduced;
pub mod relative;
pub mod seed;
pub mod series;
pub mod shell_series;
pub mod stability;
pub mod table2;

pub use accurate::{Accurate, FullState};
pub use auto::Auto;
pub use closed::ClosedForm;
pub use reduced::{Reduced, ReducedReturn};
pub use seed::SeedRk4;
pub use series::Series;

use kick_core::{KickError, Outcome, RecordingSolver, Sample, Scenario, Solver, Spacing, Streamed};
use std::ops::ControlFlow;

/// The solvers selectable by name (`--solver`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SolverChoice {
    Auto(Auto),
    SeedRk4(SeedRk4),
    Accurate(Accurate),
    FullState(FullState),
    Reduced(Reduced),
    ReducedReturn(ReducedReturn),
    ClosedForm(ClosedForm),
    Series(Series),
}

impl SolverChoice {
    pub const NAMES: [&'static str; 10] =
        ["auto", "seed-rk4", "accurate", "dop853", "dopri5", "rk4-events", "reduced", "reduced-return", "closed-form", "series"];

    /// Look a solver up by its `--solver` name at default settings; `step` is
    /// the fixed step of `seed-rk4` and `rk4-events`.
    pub fn from_name(name: &str, step: f64) -> Result<SolverChoice, KickError> {
        match name {
            "auto" => Ok(SolverChoice::Auto(Auto::default())),
            "series" => Ok(SolverChoice::Series(Series::default())),
            "dopri5" => SolverChoice::with_settings(name, step, DOPRI5_DEFAULT_TOLERANCE),
            _ => SolverChoice::with_settings(name, step, Accurate::default().relative_tolerance),
        }
    }

    /// The solvers that take a fixed step `dt`; the others choose their own steps.
    pub const FIXED_STEP: [&'static str; 2] = ["seed-rk4", "rk4-events"];

    /// As `from_name`, with `dt` as the user gave it: `None` is seed-rk4's
    /// default step, and a step given to a solver that chooses its own is
    /// refused (it would be ignored). One rule for flags, file keys and keywords.
    pub fn with_step(name: &str, dt: Option<f64>) -> Result<SolverChoice, KickError> {
        if dt.is_some() {
            SolverChoice::check_step_given(&[name])?;
        }
        SolverChoice::from_name(name, dt.unwrap_or(SeedRk4::default().step))
    }

    /// Refuse a `dt` given beside `names` when none of them takes a fixed
    /// step (unknown names are left to `from_name` to refuse).
    pub fn check_step_given(names: &[&str]) -> Result<(), KickError> {
        let known = names.iter().all(|n| SolverChoice::NAMES.contains(n));
        let takes_step = names.iter().any(|n| SolverChoice::FIXED_STEP.contains(n));
        match names.first() {
            Some(first) if known && !takes_step => Err(KickError::DoesNotApply {
                given: "dt",
                to: format!("solver `{first}`"),
                reason: "it chooses its own steps; `dt` is the step of the fixed-step solvers seed-rk4 and rk4-events",
            }),
            _ => Ok(()),
        }
    }

    /// As `from_name` with the adaptive methods' tolerance (relative and
    /// absolute, in scaled units) set to `tolerance`.
    pub fn with_settings(name: &str, step: f64, tolerance: f64) -> Result<SolverChoice, KickError> {
        let reduced = Reduced::with_tolerances(tolerance, tolerance)?;
        Ok(match name {
            "auto" => SolverChoice::Auto(Auto {
                reduced,
                accurate: Accurate::new(tolerance, tolerance)?,
                series: Series::with_tolerance(tolerance)?,
            }),
            "seed-rk4" => SolverChoice::SeedRk4(SeedRk4::new(step)?),
            "accurate" => SolverChoice::Accurate(Accurate::new(tolerance, tolerance)?),
            "dop853" => SolverChoice::FullState(FullState::dop853(tolerance, tolerance)),
            "dopri5" => SolverChoice::FullState(FullState::dopri5(tolerance, tolerance)),
            "rk4-events" => SolverChoice::FullState(FullState::rk4_events(SeedRk4::new(step)?.step)),
            "reduced" => SolverChoice::Reduced(reduced),
            "reduced-return" => SolverChoice::ReducedReturn(ReducedReturn { reduced }),
            "closed-form" => SolverChoice::ClosedForm(ClosedForm),
            "series" => SolverChoice::Series(Series::with_tolerance(tolerance)?),
            _ => {
                return Err(KickError::UnknownSolver {
                    name: name.to_string(),
                    expected: "auto, seed-rk4, accurate, dop853, dopri5, rk4-events, reduced, reduced-return, closed-form, series",
                })
            }
        })
    }

    /// The numeric settings, by name (result files store each as a typed
    /// attribute): steps in s, tolerances relative/absolute in scaled units.
    /// `auto`'s name each path: `series_tolerance`, `reduced_*`, and the
    /// `history_*` of the full-state run it records histories with.
    pub fn settings(&self) -> Vec<(&'static str, f64)> {
        fn method(prefix: Option<&'static str>, m: events::Method) -> Vec<(&'static str, f64)> {
            let (rtol, atol) = match prefix {
                None => ("relative_tolerance", "absolute_tolerance"),
                Some("reduced") => ("reduced_relative_tolerance", "reduced_absolute_tolerance"),
                Some(_) => ("history_relative_tolerance", "history_absolute_tolerance"),
            };
            match m {
                events::Method::Dop853 { relative_tolerance, absolute_tolerance }
                | events::Method::Dopri5 { relative_tolerance, absolute_tolerance } => {
                    vec![(rtol, relative_tolerance), (atol, absolute_tolerance)]
                }
                events::Method::Rk4 { step } => vec![("dt", step)],
            }
        }
        match self {
            SolverChoice::Auto(a) => {
                let mut settings = vec![("series_tolerance", a.series.tolerance)];
                settings.extend(method(Some("reduced"), a.reduced.method));
                settings.extend(method(Some("history"), a.accurate.method()));
                settings
            }
            SolverChoice::SeedRk4(s) => vec![("dt", s.step)],
            SolverChoice::Accurate(a) => method(None, a.method()),
            SolverChoice::FullState(f) => method(None, f.method),
            SolverChoice::Reduced(r) | SolverChoice::ReducedReturn(ReducedReturn { reduced: r }) => method(None, r.method),
            SolverChoice::ClosedForm(_) => Vec::new(),
            SolverChoice::Series(s) => vec![("tolerance", s.tolerance)],
        }
    }

    fn solver(&self) -> &dyn Solver {
        match self {
            SolverChoice::Auto(s) => s,
            SolverChoice::SeedRk4(s) => s,
            SolverChoice::Accurate(s) => s,
            SolverChoice::FullState(s) => s,
            SolverChoice::Reduced(s) => s,
            SolverChoice::ReducedReturn(s) => s,
            SolverChoice::ClosedForm(s) => s,
            SolverChoice::Series(s) => s,
        }
    }
}

/// Dopri5 is fifth order: a tighter tolerance than Dop853's reaches 1e-9.
pub const DOPRI5_DEFAULT_TOLERANCE: f64 = 1e-12;

impl Solver for SolverChoice {
    fn name(&self) -> &'static str {
        self.solver().name()
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        self.solver().solve(scenario)
    }
}

impl RecordingSolver for SolverChoice {
    /// Solvers without a time history of their own (closed forms and the
    /// split path) record through `accurate`: outcome and history of one run.
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        match self {
            SolverChoice::SeedRk4(s) => s.solve_streamed(scenario, spacing, sink),
            SolverChoice::FullState(s) => s.solve_streamed(scenario, spacing, sink),
            SolverChoice::Reduced(s) => s.solve_streamed(scenario, spacing, sink),
            SolverChoice::Auto(s) => s.solve_streamed(scenario, spacing, sink),
            SolverChoice::Accurate(s) => s.solve_streamed(scenario, spacing, sink),
            SolverChoice::ReducedReturn(_) | SolverChoice::ClosedForm(_) | SolverChoice::Series(_) => {
                Accurate::default().solve_streamed(scenario, spacing, sink)
            }
        }
    }
}
