//! The ball alone (kick-bounce) as a [`Level`]: square impacts on the rigid
//! plate over an axis of impact speeds, each row a pure function of its index.
//! This is where the shell ball is calibrated (the FIFA rebound) and where
//! its restitution, contact time and compression against speed are predicted.

use super::{Failure, Level, Row};
use crate::columns::{ball_settings, Column, OutcomeSet, Setting};
use kick_bounce::{BallLaw, BounceSpec};
use kick_core::parameters::Value;

/// The outcome columns of a bounce row, in [`BounceSpeeds::solve_row`]'s order.
pub const BOUNCE_COLUMNS: [(&str, &str); 5] =
    [("restitution", "1"), ("contact_time", "s"), ("peak_force", "N"), ("max_compression", "m"), ("normal_impulse", "N s")];

/// Square impacts at `speeds` (m/s) of the ball `spec` describes (its other
/// parameters held; `speed`, `angle` and `drop_height` are the axis's).
#[derive(Debug, Clone, PartialEq)]
pub struct BounceSpeeds {
    pub spec: BounceSpec,
    pub speeds: Vec<f64>,
}

impl BounceSpeeds {
    fn at(&self, speed: f64) -> BounceSpec {
        let mut spec = self.spec.clone();
        // Declared scalars of the bounce: setting them cannot fail.
        let _ = spec.set("speed", Value::Number(speed));
        let _ = spec.set("angle", Value::Number(0.0));
        spec
    }
}

impl Level for BounceSpeeds {
    fn rows(&self) -> u64 {
        self.speeds.len() as u64
    }

    fn parameter_columns(&self) -> Vec<Column> {
        vec![Column::new("speed", "m/s")]
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let mut settings = vec![("normal_solver".into(), Setting::Text("reduced (kick_bounce::run)".into()))];
        if let Ok(b) = self.at(self.speeds.first().copied().unwrap_or(1.0)).build() {
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
        let speed = self.speeds[index as usize];
        row.parameters[0] = speed;
        match kick_bounce::run(&self.at(speed)) {
            Ok(o) => {
                row.set(0, &[o.restitution, o.contact_time, o.peak_force, o.max_compression, o.normal_impulse]);
                if let Some(outside) = o.outside_validity {
                    row.flag(0, outside.into());
                }
            }
            Err(e) => row.fail(0, Failure::from(e)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level::{run_table, Level};

    /// Every row is `kick_bounce::run` at its speed, bit for bit; a refused
    /// speed keeps its refusal's status.
    #[test]
    fn rows_are_bounces_at_their_speeds() {
        let speeds = vec![2.0, 6.264, 19.2, 30.0, -1.0];
        let level = BounceSpeeds { spec: BounceSpec::default(), speeds: speeds.clone() };
        let table = run_table(&level, 0..level.rows());
        for (i, &v) in speeds.iter().enumerate() {
            let mut spec = BounceSpec::default();
            spec.set("speed", Value::Number(v)).unwrap();
            match kick_bounce::run(&spec) {
                Ok(o) => {
                    let expected = [o.restitution, o.contact_time, o.peak_force, o.max_compression, o.normal_impulse];
                    for (column, x) in table.outcomes[0].iter().zip(expected) {
                        assert_eq!(column[i].to_bits(), x.to_bits(), "row {i}");
                    }
                    assert_eq!(table.status[0][i], o.status.code());
                }
                Err(e) => {
                    assert_eq!(table.status[0][i], e.status().code(), "row {i}");
                    assert!(table.failures[0].iter().any(|(row, _)| *row == i as u64));
                }
            }
        }
        assert_ne!(table.status[0][4], 0, "a negative speed is refused");
    }
}
