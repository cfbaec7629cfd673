//! Flights shared by tests, benches and the sanity report.

use crate::{Flight, FlightSpec};
use std::f64::consts::TAU;

/// Distance of the defensive wall from the ball in a free kick, m (Law 13: 9.15 m).
pub const WALL_DISTANCE: f64 = 9.15;

/// 25 m/s at 20° elevation, no spin, default ball and air.
pub fn plain_kick() -> Flight {
    build(FlightSpec::from_exit_speed(25.0, 20.0))
}

/// A typical direct free kick: 27 m/s at 16° elevation with 9 rev/s of
/// sidespin (ω_z > 0 curves it toward +y), crossing the wall plane.
pub fn free_kick() -> Flight {
    build(FlightSpec {
        spin: Some([0.0, 0.0, 9.0 * TAU]),
        distance: Some(WALL_DISTANCE),
        ..FlightSpec::from_exit_speed(27.0, 16.0)
    })
}

fn build(spec: FlightSpec) -> Flight {
    match spec.build() {
        Ok(f) => f,
        Err(e) => unreachable!("model flights are valid: {e}"),
    }
}
