//! The 1D model as a [`Level`]: an experiment's scenarios (a grid, named
//! rows or random samples), each solved by every solver of the experiment,
//! and with `[flight]` each kick flown after it.

use super::{Failure, Level, Row};
use crate::columns::{Column, OutcomeSet, Setting};
use crate::experiment::{Kicks1d, Scenarios};
use crate::flight::FlightPlan;
use kick_compliant::SolverChoice;
use kick_core::parameters::SetParameter;
use kick_core::{AnyLaw, KickError, Outcome, ParameterDef, Scenario, ScenarioSpec, Solver, OBSERVABLES};

/// The parameters of a 1D row under `law`: every parameter of the 1D
/// scenario and its ball the law uses ([`kick_core::LawKind::uses`]; the
/// eight [`Parameter`]s under the paper's law), in declaration order. The
/// foot (leg, pose, boot) is not a column: the outcomes' settings record it.
pub fn row_parameters(law: kick_core::LawKind) -> Vec<&'static ParameterDef> {
    kick_core::parameters::at_levels(ScenarioSpec::LEVELS)
        .filter(|p| law.uses(p) && p.level != kick_core::parameters::Level::Foot)
        .collect()
}

/// Parameter columns of the 1D model under `law` ([`row_parameters`]), names and units as declared.
pub fn parameter_columns(law: kick_core::LawKind) -> Vec<Column> {
    row_parameters(law).iter().map(|p| Column::new(p.name, p.unit)).collect()
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
    pub flight: Option<&'a FlightPlan>,
}

impl OneD<'_> {
    /// Fill `row` from scenario `index`, `scenario`, and each solver's outcome (in the
    /// experiment's solver order), flying each kick with `[flight]`: the one
    /// place a 1D row is made, whether its kicks were solved here
    /// ([`Level::solve_row`]) or streamed with their histories (kick-store).
    pub fn fill_row(&self, index: u64, scenario: &Result<Scenario, KickError>, outcomes: &[Result<Outcome, KickError>], row: &mut Row) {
        self.put_parameters(index, scenario, &mut row.parameters);
        for (k, outcome) in outcomes.iter().enumerate() {
            self.put_outcome(index, k, scenario, outcome, row);
        }
    }

    /// The law of every scenario (the file's `law`).
    fn law(&self) -> kick_core::LawKind {
        match &self.kicks.scenarios {
            Scenarios::Grid { base, .. } => base.law_kind(),
            Scenarios::Named { scenarios, .. } => scenarios.first().map_or(kick_core::LawKind::PowerLaw, Scenario::law_kind),
            Scenarios::Sampled(sweep) => sweep.fixed.law.unwrap_or(kick_core::LawKind::PowerLaw),
        }
    }

    /// The grid's flight axes, when it has any (each a parameter column).
    fn flight_axes(&self) -> impl Iterator<Item = &crate::grid::Axis> {
        let axes = match &self.kicks.scenarios {
            Scenarios::Grid { grid, .. } => grid.axes.as_slice(),
            _ => &[],
        };
        axes.iter().filter(|a| a.parameter.level == kick_core::Level::Flight)
    }

    /// A scenario's parameter values (NaN where it is invalid): the law's
    /// ([`row_parameters`]), then the flight's axes. Under the paper's law
    /// the eight at once (no lookup by name: a sweep's summary path).
    fn put_parameters(&self, index: u64, scenario: &Result<Scenario, KickError>, parameters: &mut [f64]) {
        parameters.fill(f64::NAN);
        let law = self.law();
        let own = if let Ok(s) = scenario {
            if law == kick_core::LawKind::PowerLaw {
                parameters[..8].copy_from_slice(&s.values());
                8
            } else {
                let spec = s.spec();
                let list = row_parameters(law);
                let mut n = 0;
                for (slot, p) in parameters.iter_mut().zip(list) {
                    *slot = spec.value(p).unwrap_or(f64::NAN);
                    n += 1;
                }
                n
            }
        } else {
            row_parameters(law).len()
        };
        if let Scenarios::Grid { grid, .. } = &self.kicks.scenarios {
            if grid.has_flight_axes() {
                let mut slot = own;
                grid.decode_forward(index, |axis, value| {
                    if axis.parameter.level == kick_core::Level::Flight {
                        parameters[slot] = value;
                        slot += 1;
                    }
                });
            }
        }
    }

    /// The flight of row `index`: `[flight]` and the grid's flight axes.
    fn flight_rest(&self, index: u64, plan: &FlightPlan) -> kick_flight::FlightSpec {
        match &self.kicks.scenarios {
            Scenarios::Grid { grid, .. } if grid.has_flight_axes() => grid.flight_spec(index, &plan.rest),
            _ => plan.rest,
        }
    }

    /// Solver `k`'s outcome and, with `[flight]`, the flight after it.
    /// A kick outside its law's validity keeps its numbers, flagged, and so
    /// does the flight after it.
    fn put_outcome(
        &self,
        index: u64,
        k: usize,
        scenario: &Result<Scenario, KickError>,
        outcome: &Result<Outcome, KickError>,
        row: &mut Row,
    ) {
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
        if let Some(plan) = self.flight {
            let mut values = [0.0; crate::flight::MAX_FLIGHT_VALUES];
            let rest = self.flight_rest(index, plan);
            let flown = match (scenario, outcome) {
                (Ok(s), Ok(o)) => crate::flight::flight_after_1d(s, o, &rest).and_then(|f| plan.fly_into(&f, &mut values)),
                (Err(e), _) | (_, Err(e)) => Err(Failure::refused(format!("no flight: the kick failed: {e}"))),
            };
            let set = self.kicks.solvers.len() + k;
            row.put(set, flown.map(|n| &values[..n]));
            if let Some(flag) = &outside {
                row.flag_after(set, flag);
            }
        }
    }
}

impl Level for OneD<'_> {
    fn rows(&self) -> u64 {
        self.kicks.scenarios.len()
    }

    fn parameter_columns(&self) -> Vec<Column> {
        let mut columns = parameter_columns(self.law());
        columns.extend(self.flight_axes().map(|a| Column::new(a.parameter.name, a.parameter.unit)));
        columns
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        // One law for every scenario of an experiment (the file's `law`).
        let first = self.kicks.scenarios.scenario(0).unwrap_or(Scenario::BASELINE);
        let (law, foot) = (first.contact_law(), first.foot());
        let mut sets: Vec<OutcomeSet> = self.kicks.solvers.iter().map(|s| outcome_set(s, law, foot)).collect();
        if let Some(plan) = self.flight {
            let flown = kick_flight::FlightSpec { speed: Some(1.0), ..plan.rest }.build().ok();
            sets.extend(self.kicks.solvers.iter().map(|s| crate::flight::flight_set(s.name(), plan, flown.as_ref())));
        }
        sets
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let scenario = self.kicks.scenarios.scenario(index);
        self.put_parameters(index, &scenario, &mut row.parameters);
        for (k, solver) in self.kicks.solvers.iter().enumerate() {
            let outcome = scenario.clone().and_then(|s| solver.solve(&s));
            self.put_outcome(index, k, &scenario, &outcome, row);
        }
    }

    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        self.put_parameters(index, &self.kicks.scenarios.scenario(index), parameters);
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
        let flown = crate::flight::after_1d(&Scenario::baseline(), &solved, &experiment.flight.as_ref().unwrap().rest).unwrap();
        assert_eq!(table.outcomes[1][0][0], flown.outcome.flight_time);
    }
}
