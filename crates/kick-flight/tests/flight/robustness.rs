//! Far outside a kick's range (speeds 1e-6 m/s to the largest launch speed,
//! 1000 m/s, spins to 1e4 rad/s,
//! feather-light to 100 kg balls, weak to strong gravity) every valid flight
//! lands with finite numbers: no panic, no NaN, no endless loop.

use kick_flight::{solve, FlightSpec};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, rng_seed: RngSeed::Fixed(2024), ..ProptestConfig::default() })]
    #[test]
    fn every_valid_flight_lands_with_finite_numbers(
        speed in log_uniform(1e-6, kick_flight::MAX_LAUNCH_SPEED),
        angle in log_uniform(1e-4, 90.0),
        spin in prop::array::uniform3(-1e4..1e4_f64),
        mass in log_uniform(1e-4, 100.0),
        radius in log_uniform(0.01, 1.0),
        gravity in log_uniform(1e-3, 1e3),
        decay in 0.0..5.0_f64,
        distance in log_uniform(1e-3, 1e3),
    ) {
        let spec = FlightSpec {
            spin: Some(spin),
            ball_mass: Some(mass),
            ball_radius: Some(radius),
            gravity: Some(gravity),
            spin_decay: Some(decay),
            distance: Some(distance),
            ..FlightSpec::from_exit_speed(speed, angle)
        };
        let o = solve(&spec.build().unwrap()).unwrap();
        prop_assert!(o.flight_time > 0.0 && o.flight_time.is_finite());
        prop_assert!(o.apex_height >= radius);
        let json = serde_json::to_value(o).unwrap();
        // serde_json writes a non-finite number as null: only an absent crossing may be null.
        for (key, value) in json.as_object().unwrap() {
            prop_assert!(!value.is_null() || key == "crossing", "{} is null", key);
        }
        if let Some(c) = o.crossing {
            prop_assert!(c.time > 0.0 && c.time <= o.flight_time && c.height >= radius * (1.0 - 1e-9));
        }
    }
}

/// Valid numbers whose flight leaves double precision (each input at 1e300,
/// or 1e-300 where that underflows) are refused by the parameters they come
/// from, before a solve: they failed at t = 0 as "numerical failure", or (a
/// spin of 1e300 rad/s, through C_D(S)) landed within nanoseconds.
#[test]
fn flights_beyond_double_precision_are_refused_by_name() {
    let base = FlightSpec::from_exit_speed(25.0, 20.0);
    let cases = [
        (FlightSpec { spin: Some([0.0, 0.0, 1e300]), ..base }, "spin"),
        (FlightSpec::from_exit_speed(1e300, 20.0), "speed"),
        (FlightSpec::from_exit_speed(1e-300, 20.0), "speed"),
        (FlightSpec { ball_radius: Some(1e300), ..base }, "ball_radius"),
        (FlightSpec { gravity: Some(1e300), ..base }, "gravity"),
        (FlightSpec { temperature: Some(1e300), ..base }, "temperature"),
        (FlightSpec { air_density: Some(1e300), ..base }, "air_density"),
        (FlightSpec { drag_coefficient: Some(1e300), ..base }, "drag_coefficient"),
        (FlightSpec { spin: Some([0.0, 0.0, 10.0]), lift_coefficient: Some(1e300), ..base }, "lift_coefficient"),
    ];
    for (spec, named) in cases {
        match spec.build() {
            Err(e @ kick_flight::FlightError::OutOfRange { parameters, .. }) => {
                assert!(parameters.split(", ").any(|p| p == named), "{named}: {e}");
                assert_eq!(e.status(), kick_core::Status::Refused);
            }
            // A speed past the largest launch speed and air past the hottest
            // are refused by their declared bounds before any scale is read.
            Err(e @ kick_flight::FlightError::InvalidParameter { name, .. }) if ["speed", "temperature"].contains(&named) => {
                assert_eq!(name, named, "{e}");
                assert!(!e.to_string().contains("NaN") && !e.to_string().contains("inf"), "{e}");
            }
            other => panic!("{named}: {other:?}"),
        }
    }
    // No length overflows to inf in a refusal: 1e300 on every axis is 1.7e300.
    let spun = FlightSpec { spin: Some([1e300, 1e300, 1e300]), ..base }.build().unwrap_err().to_string();
    assert!(spun.contains("1.9053e299") && !spun.contains("inf"), "{spun}");
    let launched = FlightSpec { launch_velocity: Some([1e300, 1e300, 1e300]), ..FlightSpec::default() }.build().unwrap_err().to_string();
    assert!(launched.contains("= 1.7320508075688774e300:") && launched.contains("at most 1000 m/s"), "{launched}");
    assert!(FlightSpec::from_exit_speed(1000.0, 20.0).build().is_ok());
    assert!(matches!(
        FlightSpec::from_exit_speed(1000.1, 20.0).build(),
        Err(kick_flight::FlightError::InvalidParameter { name: "speed", .. })
    ));
    // The kicks' own flights stay inside.
    assert!(solve(&FlightSpec { spin: Some([0.0, 0.0, 56.5]), ..base }.build().unwrap()).is_ok());
}
