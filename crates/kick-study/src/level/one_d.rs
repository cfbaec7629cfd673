//! The 1D model as a [`Level`]: an experiment's scenarios (a grid, named
//! rows or random samples), each solved by every solver of the experiment,
//! and with `[flight]` each kick flown after it.

use super::{Failure, Level, Row};
use crate::columns::{Column, OutcomeSet, Setting};
use crate::experiment::Kicks1d;
use kick_compliant::SolverChoice;
use kick_core::{AnyLaw, KickError, Outcome, Parameter, Scenario, Solver, OBSERVABLES};
use kick_flight::FlightSpec;

/// Parameter columns of the 1D model: the eight [`Parameter`]s, and the
/// target restitution when the law takes one (names and units as declared).
pub fn parameter_columns(with_restitution: bool) -> Vec<Column> {
    let mut columns: Vec<Column> = Parameter::ALL.iter().map(|p| Column::new(p.name(), p.unit())).collect();
    if with_restitution {
        let e = &kick_core::parameters::RESTITUTION;
        columns.push(Column::new(e.name, e.unit));
    }
    columns
}

/// Outcome columns of the 1D model: [`OBSERVABLES`].
pub fn outcome_columns() -> Vec<Column> {
    OBSERVABLES.iter().map(|(n, u)| Column::new(n, u)).collect()
}

/// The outcome-set description of a solver: its name, its settings, the
/// scenarios' contact law (`law`; the target restitution is a parameter
/// column) and their foot.
pub fn outcome_set(solver: &SolverChoice, law: AnyLaw, foot: kick_core::Foot) -> OutcomeSet {
    let mut settings = Setting::numbers(solver.settings());
    settings.push(("law".into(), Setting::Text(law.kind().name().into())));
    settings.extend(crate::columns::ball_settings(law));
    settings.extend(crate::columns::foot_settings(foot));
    OutcomeSet { solver: solver.name().to_string(), settings, columns: outcome_columns() }
}

/// The 1D part of an experiment with its `[flight]`, as a [`Level`].
#[derive(Debug, Clone, Copy)]
pub struct OneD<'a> {
    pub kicks: &'a Kicks1d,
    pub flight: Option<&'a FlightSpec>,
}

impl OneD<'_> {
    /// Fill `row` from scenario `scenario` and each solver's outcome (in the
    /// experiment's solver order), flying each kick with `[flight]`: the one
    /// place a 1D row is made, whether its kicks were solved here
    /// ([`Level::solve_row`]) or streamed with their histories (kick-store).
    pub fn fill_row(&self, scenario: &Result<Scenario, KickError>, outcomes: &[Result<Outcome, KickError>], row: &mut Row) {
        self.put_parameters(scenario, row);
        for (k, outcome) in outcomes.iter().enumerate() {
            self.put_outcome(k, scenario, outcome, row);
        }
    }

    fn put_parameters(&self, scenario: &Result<Scenario, KickError>, row: &mut Row) {
        put_parameters(scenario, &mut row.parameters);
    }

    /// Solver `k`'s outcome and, with `[flight]`, the flight after it.
    /// A kick outside its law's validity keeps its numbers, flagged, and so
    /// does the flight after it.
    fn put_outcome(&self, k: usize, scenario: &Result<Scenario, KickError>, outcome: &Result<Outcome, KickError>, row: &mut Row) {
        let outside = match (scenario, outcome) {
            (Ok(s), Ok(o)) => s.check_validity(o).err().map(Failure::from),
            _ => None,
        };
        match outcome {
            Ok(o) => row.set(k, &o.observable_values()),
            Err(e) => row.fail(k, e.clone().into()),
        }
        if let Some(flag) = &outside {
            row.flag(k, flag.clone());
        }
        if let Some(rest) = self.flight {
            let flown = match (scenario, outcome) {
                (Ok(s), Ok(o)) => crate::flight::after_1d(s, o, rest).map(|run| run.outcome.values()),
                (Err(e), _) | (_, Err(e)) => Err(Failure::refused(format!("no flight: the kick failed: {e}"))),
            };
            let set = self.kicks.solvers.len() + k;
            row.put(set, flown);
            if let Some(flag) = &outside {
                row.flag_after(set, flag);
            }
        }
    }
}

/// A scenario's parameter values (NaN where it is invalid): the eight, then
/// the restitution target where the table has that column.
fn put_parameters(scenario: &Result<Scenario, KickError>, parameters: &mut [f64]) {
    parameters.fill(f64::NAN);
    if let Ok(s) = scenario {
        parameters[..8].copy_from_slice(&s.values());
        if let Some(slot) = parameters.get_mut(8) {
            *slot = s.restitution_target().unwrap_or(f64::NAN);
        }
    }
}

impl Level for OneD<'_> {
    fn rows(&self) -> u64 {
        self.kicks.scenarios.len()
    }

    fn parameter_columns(&self) -> Vec<Column> {
        parameter_columns(self.kicks.scenarios.has_restitution())
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        // One law for every scenario of an experiment (the file's `law`).
        let first = self.kicks.scenarios.scenario(0).unwrap_or(Scenario::BASELINE);
        let (law, foot) = (first.contact_law(), first.foot());
        let mut sets: Vec<OutcomeSet> = self.kicks.solvers.iter().map(|s| outcome_set(s, law, foot)).collect();
        if let Some(rest) = self.flight {
            let flown = kick_flight::FlightSpec { speed: Some(1.0), ..*rest }.build().ok();
            sets.extend(self.kicks.solvers.iter().map(|s| crate::flight::flight_set(s.name(), rest, flown.as_ref())));
        }
        sets
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let scenario = self.kicks.scenarios.scenario(index);
        self.put_parameters(&scenario, row);
        for (k, solver) in self.kicks.solvers.iter().enumerate() {
            let outcome = scenario.clone().and_then(|s| solver.solve(&s));
            self.put_outcome(k, &scenario, &outcome, row);
        }
    }

    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        put_parameters(&self.kicks.scenarios.scenario(index), parameters);
        true
    }
}

#[cfg(test)]
mod tests {
    use crate::level::run_table;
    use kick_core::{Parameter, Scenario, Solver, Status, OBSERVABLES};
    use std::path::Path;

    /// A 1D grid with a flight after each kick, run into memory: a kick that
    /// does not separate keeps its own status (a numerical failure, not a
    /// bare "failed"), its flight is refused with the kick's reason, and a
    /// row that separates equals the solve and the flight done by hand.
    #[test]
    fn a_failed_kick_keeps_its_status_and_its_flight_is_refused() {
        let text = "solver = \"accurate\"\n[[sweep]]\nparameter = \"drive_force\"\nvalues = [0.0, 1e6]\n[flight]\nlaunch_angle = 20.0\n";
        let experiment = crate::experiment::parse(Path::new("chain.toml"), text).unwrap();
        assert!(experiment.one_d().is_some());
        let table = run_table(&experiment, 0..2);
        let failed =
            kick_compliant::Accurate::default().solve(&Scenario::baseline().with(Parameter::DriveForce, 1e6).unwrap()).unwrap_err();
        assert_ne!(failed.status(), Status::Refused);
        assert_eq!(table.status[0], vec![0, failed.status().code()]);
        assert_eq!(table.status[1], vec![0, Status::Refused.code()]);
        assert!(table.failures[1][0].1.starts_with("no flight: the kick failed"), "{:?}", table.failures[1]);
        let solved = kick_compliant::Accurate::default().solve(&Scenario::baseline()).unwrap();
        let k = OBSERVABLES.iter().position(|(n, _)| *n == "v_ball_out").unwrap();
        assert_eq!(table.outcomes[0][k][0], solved.v_ball_out);
        let flown = crate::flight::after_1d(&Scenario::baseline(), &solved, &experiment.flight.unwrap()).unwrap();
        assert_eq!(table.outcomes[1][0][0], flown.outcome.flight_time);
    }
}
