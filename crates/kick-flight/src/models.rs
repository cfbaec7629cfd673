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
    build(FlightSpec { spin: Some([0.0, 0.0, 9.0 * TAU]), distance: Some(WALL_DISTANCE), ..FlightSpec::from_exit_speed(27.0, 16.0) })
}

/// `rows` free kicks for [`crate::flight_many`]: the base (18° elevation,
/// 9 rev/s of sidespin, crossing the wall plane) and launch speeds spread
/// evenly over 22–32 m/s, one per row. Shared by `kick bench` and the
/// criterion bench, so both time the same flights.
pub fn free_kick_speeds(rows: usize) -> (FlightSpec, Vec<f64>) {
    let base = FlightSpec {
        speed: None,
        launch_angle: Some(18.0),
        spin: Some([0.0, 0.0, 9.0 * TAU]),
        distance: Some(WALL_DISTANCE),
        ..FlightSpec::default()
    };
    let speeds = (0..rows).map(|i| 22.0 + 10.0 * i as f64 / rows.max(1) as f64).collect();
    (base, speeds)
}

fn build(spec: FlightSpec) -> Flight {
    match spec.build() {
        Ok(f) => f,
        Err(e) => unreachable!("model flights are valid: {e}"),
    }
}
