//! The contact-law comparison (`kick laws`) as a [`Level`]: one row per
//! Table 2 scenario, parameters the eight scenario parameters and the
//! target restitution, one outcome set per law of [`LawKind::ALL`] (the
//! paper's first). A row's laws are solved together by
//! [`kick_identify::laws::compare`], since each law's target is the paper's
//! law's e on that row; the level lays the comparisons out as a table. The
//! force pulses are per-row arrays a table row cannot hold: the writer puts
//! them beside the table ([`LawTable::pulse`]).

use super::{Failure, Level, Row};
use crate::columns::{Column, OutcomeSet, Setting};
use kick_core::laws::{AnyLaw, LawKind};
use kick_core::{ContactLaw, Parameter, OBSERVABLES};
use kick_identify::laws::LawComparison;

/// The comparisons of `kick laws` as a table; pulses sampled at most
/// t_c/`samples` apart, t_c the undamped contact time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawTable<'a> {
    comparisons: &'a [LawComparison],
    samples: u32,
}

impl<'a> LawTable<'a> {
    /// The table of `comparisons`, each with its runs in [`LawKind::ALL`]
    /// order (as `compare` makes them), or the first row out of order.
    pub fn new(comparisons: &'a [LawComparison], samples: u32) -> Result<LawTable<'a>, Failure> {
        for c in comparisons {
            let laws: Vec<LawKind> = c.runs.iter().map(|r| r.law).collect();
            if laws != LawKind::ALL {
                let names: Vec<&str> = laws.iter().map(|l| l.name()).collect();
                return Err(Failure::refused(format!("{}: laws out of order ({})", c.name, names.join(", "))));
            }
        }
        Ok(LawTable { comparisons, samples })
    }

    /// The force pulse of row `row` in set `set` (the law `LawKind::ALL[set]`):
    /// its times (s) and forces (N).
    pub fn pulse(&self, row: usize, set: usize) -> (Vec<f64>, Vec<f64>) {
        self.comparisons[row].runs[set].pulse.iter().copied().unzip()
    }
}

/// Columns of a law's outcome set: the observables, `onset_force` (F(0⁺))
/// and the law's own dissipation parameter.
pub fn law_columns(law: LawKind) -> Vec<Column> {
    let mut columns: Vec<Column> = OBSERVABLES.iter().map(|(n, u)| Column::new(n, u)).collect();
    columns.push(Column::new("onset_force", "N"));
    match law {
        LawKind::PowerLaw => {}
        LawKind::KelvinVoigt => {
            columns.push(Column::new("linear_stiffness", "N/m"));
            columns.push(Column::new("linear_damping", "N s/m"));
        }
        _ => columns.push(Column::new("hysteresis", "s/m")),
    }
    columns
}

/// The values of [`law_columns`] for one run.
fn law_values(parameters: &AnyLaw, outcome: &kick_core::Outcome, approach_speed: f64) -> Vec<f64> {
    let mut values = outcome.observable_values().to_vec();
    values.push(parameters.onset_force(approach_speed));
    match parameters {
        AnyLaw::PowerLaw(_) => {}
        AnyLaw::KelvinVoigt(k) => values.extend([k.stiffness, k.damping]),
        AnyLaw::Hysteresis(h) => values.push(h.hysteresis),
        // Not in LawKind::ALL, so never among the compared laws' rows.
        AnyLaw::Shell(_) => {}
    }
    values
}

impl Level for LawTable<'_> {
    fn rows(&self) -> u64 {
        self.comparisons.len() as u64
    }

    fn parameter_columns(&self) -> Vec<Column> {
        let mut parameters: Vec<Column> = Parameter::ALL.iter().map(|p| Column::new(p.name(), p.unit())).collect();
        parameters.push(Column::new("target_restitution", "1"));
        parameters
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        LawKind::ALL
            .iter()
            .map(|&law| OutcomeSet {
                solver: law.name().into(),
                settings: Setting::numbers([
                    ("relative_tolerance", 1e-12),
                    ("absolute_tolerance", 1e-12),
                    ("samples_per_contact_time", f64::from(self.samples)),
                ]),
                columns: law_columns(law),
            })
            .collect()
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let c = &self.comparisons[index as usize];
        let n = Parameter::ALL.len();
        row.parameters[..n].copy_from_slice(&c.scenario.values());
        row.parameters[n] = c.restitution;
        for (set, run) in c.runs.iter().enumerate() {
            row.set(set, &law_values(&run.parameters, &run.outcome, c.scenario.approach_speed()));
        }
    }
}
