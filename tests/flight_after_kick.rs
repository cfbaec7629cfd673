//! A kick's launch state into kick-flight: the 1D kick's exit speed and the
//! 3D kick's launch velocity and spin, wired through the flight constructors.

use kick_3d::{checks::kick, Accurate3d, Kick3dSpec};
use kick_compliant::Accurate;
use kick_core::{Scenario, Solver};
use kick_flight::{solve, Flight, FlightSpec};

const ACCURACY: f64 = 1e-9;

#[test]
fn one_d_exit_speed_flies_the_vacuum_range() {
    let exit = Accurate::default().solve(&Scenario::baseline()).unwrap().v_ball_out;
    let angle = 25.0_f64;
    let spec = FlightSpec { drag_coefficient: Some(0.0), lift_coefficient: Some(0.0), ..FlightSpec::from_exit_speed(exit, angle) };
    let o = solve(&spec.build().unwrap()).unwrap();
    let range = exit * exit * (2.0 * angle.to_radians()).sin() / kick_core::GRAVITY;
    assert!((o.landing_point[0] / range - 1.0).abs() <= ACCURACY);
    // In air the same kick falls short of the vacuum range.
    let air = solve(&FlightSpec::from_exit_speed(exit, angle).build().unwrap()).unwrap();
    assert!(air.landing_point[0] < 0.9 * range);
}

#[test]
fn three_d_launch_state_flies_and_curves_with_its_spin() {
    let k = kick(Kick3dSpec { offset: Some(0.05), approach_angle_deg: Some(20.0), ..Kick3dSpec::default() });
    let launch = Accurate3d::default().solve(&k).unwrap();
    let ball = FlightSpec { ball_mass: Some(k.base.ball_mass()), ball_radius: Some(k.ball_radius), ..FlightSpec::default() };
    let [vx, vy, vz] = launch.launch_velocity;
    assert!(vz > 0.0, "the kick lifts the ball");

    // Vacuum: the launch velocity alone sets the landing point.
    let vacuum = FlightSpec { drag_coefficient: Some(0.0), lift_coefficient: Some(0.0), ..ball };
    let o = solve(&Flight::from_launch(launch.launch_velocity, launch.spin, &vacuum).unwrap()).unwrap();
    let t = 2.0 * vz / kick_core::GRAVITY;
    assert!((o.flight_time / t - 1.0).abs() <= ACCURACY);
    assert!((o.landing_point[0] - vx * t).hypot(o.landing_point[1] - vy * t) <= ACCURACY * vx.hypot(vy) * t);

    // In air the Magnus force bends the path to the side ω × v points to.
    let flight = Flight::from_launch(launch.launch_velocity, launch.spin, &ball).unwrap();
    let o = solve(&flight).unwrap();
    let [wx, wy, wz] = launch.spin;
    let magnus = [wy * vz - wz * vy, wz * vx - wx * vz];
    let across = [-vy, vx]; // horizontal, left of the launch direction
    let side = magnus[0] * across[0] + magnus[1] * across[1];
    let deflection = o.landing_point[0] * across[0] + o.landing_point[1] * across[1];
    assert!(side.abs() > 0.0 && deflection * side > 0.0, "deflection {deflection} against Magnus side {side}");
}
