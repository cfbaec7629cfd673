//! The 3D kick as a [`Level`]: a grid of kicks from an experiment file
//! (`kick run` with `level = "3d"`), and with `[flight]` each kick flown.

use super::{Failure, Level, Row};
use crate::columns::{law_settings, Column, OutcomeSet};
use crate::experiment::Kicks3d;
use crate::flight::FlightPlan;
use kick_3d::OBSERVABLES_3D;

/// The 3D outcome set of a solver: its name (`NAME-3d`), the law and
/// [`OBSERVABLES_3D`], kick-3d's columns.
pub fn outcome_set_3d(solver: &str, scenario: &kick_core::Scenario) -> OutcomeSet {
    OutcomeSet {
        solver: format!("{solver}-3d"),
        settings: law_settings(scenario, []),
        columns: OBSERVABLES_3D.iter().map(|(n, u)| Column::new(n, u)).collect(),
    }
}

/// The 3D part of an experiment with its `[flight]`, as a [`Level`].
#[derive(Debug, Clone, Copy)]
pub struct ThreeD<'a> {
    pub kicks: &'a Kicks3d,
    pub flight: Option<&'a FlightPlan>,
}

impl Level for ThreeD<'_> {
    fn rows(&self) -> u64 {
        self.kicks.grid.len()
    }

    /// The swept axes, in axis order.
    fn parameter_columns(&self) -> Vec<Column> {
        self.kicks.grid.columns()
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let kick = outcome_set_3d(&self.kicks.solver_name, &self.kicks.scenario);
        let mut sets = vec![kick];
        if let Some(plan) = self.flight {
            let spec = kick_flight::FlightSpec { gravity: Some(kick_core::GRAVITY), ..plan.rest };
            let flown = kick_flight::Flight::from_launch([1.0, 0.0, 1.0], [0.0; 3], &spec).ok();
            sets.push(crate::flight::flight_set(&sets[0].solver, plan, flown.as_ref()));
        }
        sets
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        self.kicks.grid.coordinates_into(index, &mut row.parameters);
        let kick = self.kicks.kick(index);
        let outcome = kick.as_ref().map_err(Clone::clone).and_then(|k| self.kicks.solver.solve(k));
        match &outcome {
            Ok(o) => row.set(0, &o.observable_values()),
            Err(e) => row.fail(0, e.clone().into()),
        }
        // Outside the law's validity: the numbers kept, flagged, and the flight's too.
        let outside = match (&kick, &outcome) {
            (Ok(k), Ok(o)) => k.check_validity(o).err().map(Failure::from),
            _ => None,
        };
        if let Some(flag) = &outside {
            row.flag(0, flag.clone());
        }
        if let Some(plan) = self.flight {
            let mut values = [0.0; crate::flight::MAX_FLIGHT_VALUES];
            let flown = match (&kick, &outcome) {
                (Ok(k), Ok(o)) => {
                    let rest = self.kicks.grid.flight_spec(index, &plan.rest);
                    crate::flight::flight_after_3d(k, o, &rest).and_then(|f| plan.fly_into(&f, &mut values))
                }
                (Err(e), _) | (_, Err(e)) => Err(Failure::refused(format!("no flight: the kick failed: {e}"))),
            };
            row.put(1, flown.map(|n| &values[..n]));
            if let Some(flag) = &outside {
                row.flag_after(1, flag);
            }
        }
    }

    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        self.kicks.grid.coordinates_into(index, parameters);
        true
    }
}
