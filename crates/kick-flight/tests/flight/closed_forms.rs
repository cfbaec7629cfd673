//! Landing, apex, crossing and spin decay against closed forms, and the
//! default solve against a solve at a 100× tighter tolerance: all within
//! ACCURACY = 1e-9 relative (the crate's documented accuracy).

use kick_flight::{models, solve, Flight, FlightError, FlightOutcome, FlightSpec};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

const ACCURACY: f64 = 1e-9;
const R: f64 = 0.11;
const G: f64 = 9.81;

fn rel(actual: f64, expected: f64) -> f64 {
    (actual - expected).abs() / expected.abs()
}

fn vacuum(speed: f64, angle: f64, azimuth: f64, distance: Option<f64>) -> FlightSpec {
    FlightSpec {
        azimuth: Some(azimuth),
        drag_coefficient: Some(0.0),
        lift_coefficient: Some(0.0),
        spin: Some([3.0, -40.0, 20.0]),
        distance,
        ..FlightSpec::from_exit_speed(speed, angle)
    }
}

#[test]
fn vacuum_parabola() {
    for (speed, angle, azimuth) in [(25.0, 20.0, 0.0), (7.0, 65.0, 30.0), (40.0, 3.0, -120.0), (0.5, 45.0, 180.0)] {
        let o = solve(&vacuum(speed, angle, azimuth, None).build().unwrap()).unwrap();
        let (th, ps) = (f64::to_radians(angle), f64::to_radians(azimuth));
        let (u, w) = (speed * th.cos(), speed * th.sin());
        let t = 2.0 * w / G;
        let range = u * t;
        assert!(rel(o.flight_time, t) <= ACCURACY, "{speed} {angle}: time {:.2e}", rel(o.flight_time, t));
        let landing = [range * ps.cos(), range * ps.sin()];
        let miss = (o.landing_point[0] - landing[0]).hypot(o.landing_point[1] - landing[1]);
        assert!(miss <= ACCURACY * range, "{speed} {angle}: landing {:.2e}", miss / range);
        let apex = R + w * w / (2.0 * G);
        assert!(rel(o.apex_height, apex) <= ACCURACY, "apex {:.2e}", rel(o.apex_height, apex));
        assert!(rel(o.apex_time, w / G) <= ACCURACY);
        assert!(rel(o.landing_velocity[2], -w) <= ACCURACY);
        // Without drag or lift nothing changes the spin.
        assert_eq!(o.landing_spin, [3.0, -40.0, 20.0]);
    }
}

#[test]
fn vacuum_vertical_launch_lands_where_it_started() {
    let o = solve(&vacuum(12.0, 90.0, 0.0, None).build().unwrap()).unwrap();
    assert!(rel(o.flight_time, 2.0 * 12.0 / G) <= ACCURACY);
    assert!(o.landing_point[0].abs() + o.landing_point[1].abs() <= ACCURACY * 12.0 * 12.0 / G);
    assert!(rel(o.apex_height, R + 144.0 / (2.0 * G)) <= ACCURACY);
}

#[test]
fn vacuum_crossing() {
    let (speed, angle) = (25.0, 20.0_f64);
    for d in [9.15, 25.0, 40.0] {
        let o = solve(&vacuum(speed, angle, 0.0, Some(d)).build().unwrap()).unwrap();
        let th = angle.to_radians();
        let t = d / (speed * th.cos());
        let c = o.crossing.expect("crosses before landing");
        assert!(rel(c.time, t) <= ACCURACY, "d {d}: time {:.2e}", rel(c.time, t));
        let height = R + speed * th.sin() * t - 0.5 * G * t * t;
        assert!(rel(c.height, height) <= ACCURACY, "d {d}: height {:.2e}", rel(c.height, height));
        assert!(c.lateral_offset.abs() <= ACCURACY * d);
        assert!(rel(c.velocity[2], speed * th.sin() - G * t) <= ACCURACY);
    }
    // Range 40.9 m: a plane at 45 m is never reached; a backward kick never crosses.
    let short = solve(&vacuum(speed, angle, 0.0, Some(45.0)).build().unwrap()).unwrap();
    assert_eq!(short.crossing, None);
    let backward = solve(&vacuum(speed, angle, 180.0, Some(5.0)).build().unwrap()).unwrap();
    assert_eq!(backward.crossing, None);
}

/// Vertical launch with constant C_D: with k = ρ A C_D/(2m) and v_t = √(g/k),
/// up: t_up = (v_t/g) atan(v0/v_t), h = (v_t²/2g) ln(1 + v0²/v_t²);
/// down from rest: t_down = (v_t/g) acosh(exp(g h/v_t²)), |v| = v_t √(1 − exp(−2gh/v_t²)).
#[test]
fn vertical_flight_with_quadratic_drag() {
    for (speed, cd) in [(20.0, 0.25), (30.0, 0.5), (5.0, 0.155)] {
        let spec = FlightSpec { drag_coefficient: Some(cd), ..FlightSpec::from_exit_speed(speed, 90.0) };
        let flight = spec.build().unwrap();
        let o = solve(&flight).unwrap();
        let k = 1.225 * std::f64::consts::PI * R * R * cd / (2.0 * 0.43);
        let vt = (G / k).sqrt();
        let t_up = vt / G * (speed / vt).atan();
        let h = vt * vt / (2.0 * G) * (speed * speed / (vt * vt)).ln_1p();
        let t_down = vt / G * (G * h / (vt * vt)).exp().acosh();
        let v_land = vt * (-(-2.0 * G * h / (vt * vt)).exp_m1()).sqrt();
        assert!(rel(o.apex_time, t_up) <= ACCURACY, "{speed} {cd}: apex time {:.2e}", rel(o.apex_time, t_up));
        assert!(rel(o.apex_height, R + h) <= ACCURACY, "apex {:.2e}", rel(o.apex_height, R + h));
        assert!(rel(o.flight_time, t_up + t_down) <= ACCURACY, "time {:.2e}", rel(o.flight_time, t_up + t_down));
        assert!(rel(o.landing_velocity[2], -v_land) <= ACCURACY, "v {:.2e}", rel(o.landing_velocity[2], -v_land));
        assert!(o.landing_point[0].abs() + o.landing_point[1].abs() <= ACCURACY * h);
    }
}

/// Spin decay on a vacuum parabola: dω/dt = −κ|v|ω, κ = 3ρA k_M/(4m), so
/// ω(T) = ω0 exp(−κ L) with L the arc length, 2F(w)/g, F(w) = ½(w√(u²+w²) + u² asinh(w/u)).
#[test]
fn spin_decay_over_a_vacuum_parabola() {
    let (speed, angle, k_m) = (25.0, 30.0_f64, 0.8);
    let spec = FlightSpec { spin_decay: Some(k_m), ..vacuum(speed, angle, 0.0, None) };
    let o = solve(&spec.build().unwrap()).unwrap();
    let (u, w) = (speed * angle.to_radians().cos(), speed * angle.to_radians().sin());
    let arc = (w * (u * u + w * w).sqrt() + u * u * (w / u).asinh()) / G;
    let kappa = 3.0 * 1.225 * std::f64::consts::PI * R * R * k_m / (4.0 * 0.43);
    let decay = (-kappa * arc).exp();
    for (got, w0) in o.landing_spin.iter().zip([3.0, -40.0, 20.0]) {
        assert!(rel(*got, w0 * decay) <= ACCURACY, "{got} vs {}: {:.2e}", w0 * decay, rel(*got, w0 * decay));
    }
}

/// Worst relative difference of the reported quantities between two solves:
/// times and apex height relative to themselves, the landing point relative
/// to the flight's size (range, or apex height for a steep kick landing near
/// its start), the crossing point relative to its distance from the origin.
fn difference(a: &FlightOutcome, b: &FlightOutcome) -> f64 {
    // The flight's size: its range, or its apex height for a steep kick that lands near its start.
    let size = b.landing_point[0].hypot(b.landing_point[1]).max(b.apex_height);
    let landing = (a.landing_point[0] - b.landing_point[0]).hypot(a.landing_point[1] - b.landing_point[1]) / size;
    let mut worst = landing.max(rel(a.flight_time, b.flight_time)).max(rel(a.apex_height, b.apex_height));
    match (a.crossing, b.crossing) {
        (Some(x), Some(y)) => {
            // The crossing point (d, y, z), relative to its distance from the origin.
            let point = (y.distance.powi(2) + y.lateral_offset.powi(2) + y.height.powi(2)).sqrt();
            let miss = (x.lateral_offset - y.lateral_offset).hypot(x.height - y.height);
            worst = worst.max(rel(x.time, y.time)).max(miss / point);
        }
        (None, None) => {}
        _ => return f64::INFINITY,
    }
    worst
}

fn against_tightened(flight: &Flight) -> f64 {
    let default = solve(flight).unwrap();
    let tight = solve(&flight.with_relative_tolerance(flight.relative_tolerance() / 100.0).unwrap()).unwrap();
    difference(&default, &tight)
}

#[test]
fn model_flights_against_a_tightened_solve() {
    for flight in [models::plain_kick(), models::free_kick()] {
        let d = against_tightened(&flight);
        assert!(d <= ACCURACY, "{d:.2e}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, rng_seed: RngSeed::Fixed(2024), ..ProptestConfig::default() })]
    /// Kicks through the drag crisis (3–40 m/s), with any spin (so through
    /// the join of the spinning ball's drag, S* ≈ 0.04), spin decay on or
    /// off, any ball construction, default coefficient models.
    #[test]
    fn random_kicks_against_a_tightened_solve(
        speed in 3.0..40.0_f64,
        angle in 3.0..85.0_f64,
        azimuth in -40.0..40.0_f64,
        spin in prop::array::uniform3(-80.0..80.0_f64),
        decay in prop::option::of(0.0..2.0_f64),
        distance in 1.0..40.0_f64,
        panels in prop::option::of(prop::sample::select(vec![32.0, 14.0, 8.0, 6.0])),
    ) {
        let spec = FlightSpec {
            azimuth: Some(azimuth),
            spin: Some(spin),
            spin_decay: decay,
            ball_panels: panels,
            distance: Some(distance),
            ..FlightSpec::from_exit_speed(speed, angle)
        };
        let d = against_tightened(&spec.build().unwrap());
        prop_assert!(d <= ACCURACY, "{:.2e}", d);
    }
}

#[test]
fn a_flight_past_its_horizon_is_refused() {
    let flight = models::free_kick().with_horizon(0.5).unwrap();
    assert!(matches!(solve(&flight), Err(FlightError::NoLanding { horizon, .. }) if horizon == 0.5));
    // The default horizon is far beyond any kick's flight.
    assert!(models::free_kick().horizon() > 100.0);
}

/// Lift alone (no drag, gravity 1e-12 m/s²) with backspin across the
/// velocity: |v| and S stay constant, so the ball runs round a circle of
/// radius r = 1/(k C_L(S)), k = ρA/(2m). Launched at θ it comes back to
/// z = R behind the start at x = −2 r sin θ after an arc of 2π − 2θ, with its
/// apex at R + r(1 + cos θ). Holds the Magnus force's size and direction,
/// for a constant C_L and for the saturating C_L(S).
#[test]
fn magnus_loop_without_gravity_or_drag() {
    let (speed, angle, w) = (20.0, 30.0_f64, 60.0);
    let k = 1.225 * std::f64::consts::PI * R * R / (2.0 * 0.43);
    let s = R * w / speed;
    for (lift, cl) in [(Some(0.3), 0.3), (None, kick_flight::coefficients::SaturatingLift::at(s))] {
        let spec = FlightSpec {
            gravity: Some(1e-12),
            drag_coefficient: Some(0.0),
            lift_coefficient: lift,
            spin: Some([0.0, -w, 0.0]),
            ..FlightSpec::from_exit_speed(speed, angle)
        };
        let o = solve(&spec.build().unwrap()).unwrap();
        let r = 1.0 / (k * cl);
        let th = angle.to_radians();
        let t = r * (2.0 * std::f64::consts::PI - 2.0 * th) / speed;
        assert!(rel(o.flight_time, t) <= ACCURACY, "{lift:?}: time {:.2e}", rel(o.flight_time, t));
        assert!(rel(o.landing_point[0], -2.0 * r * th.sin()) <= ACCURACY, "landing {:.2e}", rel(o.landing_point[0], -2.0 * r * th.sin()));
        assert!(rel(o.apex_height, R + r * (1.0 + th.cos())) <= ACCURACY, "apex");
        assert!(rel(o.landing_velocity[0], speed * th.cos()) <= ACCURACY);
        assert!(rel(o.landing_velocity[2], -speed * th.sin()) <= ACCURACY);
    }
}
