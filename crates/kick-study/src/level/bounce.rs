//! The ball alone (kick-bounce) as a [`Level`]: a grid of bounces on the
//! rigid plate from an experiment file (`kick run` with `level = "bounce"`),
//! each row a pure function of its index. This is where the shell ball is
//! calibrated (the FIFA rebound) and where its restitution, contact time and
//! compression against speed and pressure are predicted.

use super::{Level, Row};
use crate::columns::{ball_settings, Column, OutcomeSet, Setting};
use crate::experiment::KicksBounce;
use kick_bounce::BallLaw;

/// The outcome columns of a bounce row, in [`BounceGrid::solve_row`]'s order.
pub const BOUNCE_COLUMNS: [(&str, &str); 13] = [
    ("restitution", "1"),
    ("contact_time", "s"),
    ("peak_force", "N"),
    ("max_compression", "m"),
    ("normal_impulse", "N s"),
    ("peak_force_time", "s"),
    ("max_compression_time", "s"),
    ("exit_velocity_x", "m/s"),
    ("exit_velocity_y", "m/s"),
    ("exit_velocity_z", "m/s"),
    ("exit_spin_x", "rad/s"),
    ("exit_spin_y", "rad/s"),
    ("exit_spin_z", "rad/s"),
];

/// The bounce part of an experiment as a [`Level`].
#[derive(Debug, Clone, Copy)]
pub struct BounceGrid<'a> {
    pub kicks: &'a KicksBounce,
}

impl Level for BounceGrid<'_> {
    fn rows(&self) -> u64 {
        self.kicks.grid.len()
    }

    /// The swept axes, in axis order.
    fn parameter_columns(&self) -> Vec<Column> {
        self.kicks.grid.columns()
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let mut settings = vec![("normal_solver".into(), Setting::Text("reduced (kick_bounce::run)".into()))];
        if let Ok(b) = self.kicks.spec_at(0).build() {
            settings.push(("ball_mass".into(), Setting::Number(b.mass)));
            settings.push(("ball_radius".into(), Setting::Number(b.radius)));
            settings.push(("gravity".into(), Setting::Number(b.gravity)));
            match b.law {
                BallLaw::Shell(ball) => {
                    settings.push(("law".into(), Setting::Text("shell".into())));
                    settings.extend(ball_settings(kick_core::AnyLaw::Shell(ball)));
                }
                BallLaw::Kick { kind, .. } => settings.push(("law".into(), Setting::Text(kind.name().into()))),
            }
        }
        vec![OutcomeSet { solver: "bounce".into(), settings, columns: BOUNCE_COLUMNS.iter().map(|(n, u)| Column::new(n, u)).collect() }]
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        self.kicks.grid.coordinates_into(index, &mut row.parameters);
        match kick_bounce::run(&self.kicks.spec_at(index)) {
            Ok(o) => {
                let [vx, vy, vz] = o.exit_velocity;
                let [wx, wy, wz] = o.exit_spin;
                row.set(
                    0,
                    &[
                        o.restitution,
                        o.contact_time,
                        o.peak_force,
                        o.max_compression,
                        o.normal_impulse,
                        o.peak_force_time,
                        o.max_compression_time,
                        vx,
                        vy,
                        vz,
                        wx,
                        wy,
                        wz,
                    ],
                );
                if let Some(outside) = o.outside_validity {
                    row.flag(0, outside.into());
                }
            }
            Err(e) => row.fail(0, e.into()),
        }
    }

    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        self.kicks.grid.coordinates_into(index, parameters);
        true
    }
}

#[cfg(test)]
mod tests {
    use crate::experiment::{parse, Kicks};
    use crate::level::{run_table, Level};
    use kick_bounce::BounceSpec;
    use kick_core::parameters::Value;
    use std::path::Path;

    /// Every row is `kick_bounce::run` at its values, bit for bit; a refused
    /// speed keeps its refusal's status.
    #[test]
    fn rows_are_bounces_at_their_values() {
        let text = "level = \"bounce\"\n[[sweep]]\nparameter = \"inflation_pressure\"\nvalues = [6.0e4, 1.1e5]\n\
                    [[sweep]]\nparameter = \"speed\"\nvalues = [2.0, 6.264, 19.2, 30.0, 900.0]\n";
        let e = parse(Path::new("b.toml"), text).unwrap();
        let Kicks::Bounce(kicks) = &e.kicks else { panic!() };
        let level = super::BounceGrid { kicks };
        let table = run_table(&level, 0..level.rows());
        for (i, (p, v)) in [6.0e4, 1.1e5].iter().flat_map(|&p| [2.0, 6.264, 19.2, 30.0, 900.0].map(|v| (p, v))).enumerate() {
            assert_eq!((table.parameters[0][i], table.parameters[1][i]), (p, v));
            let mut spec = BounceSpec::default();
            spec.set("speed", Value::Number(v)).unwrap();
            spec.set("inflation_pressure", Value::Number(p)).unwrap();
            match kick_bounce::run(&spec) {
                Ok(o) => {
                    let expected = [o.restitution, o.contact_time, o.peak_force, o.max_compression, o.normal_impulse];
                    for (column, x) in table.outcomes[0].iter().zip(expected) {
                        assert_eq!(column[i].to_bits(), x.to_bits(), "row {i}");
                    }
                    assert_eq!(table.status[0][i], o.status.code());
                }
                Err(err) => {
                    assert_eq!(table.status[0][i], err.status().code(), "row {i}");
                    assert!(table.failures[0].iter().any(|(row, _)| *row == i as u64));
                }
            }
        }
    }
}
