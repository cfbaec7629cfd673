//! The validation chapter's flight side: the drag crisis read off the default
//! C_D(Re) independently, free-kick deflections against the circle estimate.

use kick_core::measurements::Measurements;
use kick_flight::coefficients::{BallConstruction, DragCrisis};
use kick_flight::validation::{
    ball_comparisons, drag_crisis_comparisons, drag_crisis_model, free_kick, free_kicks, keys, lift_plateau_bends, measured_flights,
    spin_decay_bends, FREE_KICK_DISTANCE, FREE_KICK_ELEVATION,
};
use kick_flight::{solve, Air, FlightSpec};
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn measurements() -> Measurements {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    read(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// Re at which C_D(Re) falls to `level`, by bisection on the model itself.
fn reynolds_at(level: f64) -> f64 {
    let (mut lo, mut hi) = (1e4, 1e6);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if DragCrisis::at(mid) > level {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// One definition of the critical Re everywhere: 95 % of the drop done, read
/// off the curve by bisection, for the default ball and for each construction
/// (whose own drag law is flown, not scaled here).
#[test]
fn crisis_points_are_where_the_curve_says() {
    let model = drag_crisis_model();
    let (base, drop) = (DragCrisis::SUPERCRITICAL, DragCrisis::DROP);
    assert!((reynolds_at(base + 0.5 * drop) / model.centre - 1.0).abs() < 1e-9);
    assert!((reynolds_at(base + 0.05 * drop) / model.critical - 1.0).abs() < 1e-9);
    assert!((DragCrisis::at(model.critical) - 0.1723).abs() < 1e-3);
    // C_D within 5 % of its supercritical value only from about 2.58e5 on: not the critical Re.
    let five_percent = reynolds_at(1.05 * base);
    assert!((five_percent / 2.58e5 - 1.0).abs() < 0.01, "{five_percent}");
    // As a speed of the default ball in default air: above Goff & Carré's v_c = 12.19 m/s.
    let per_speed = 0.22 / Air::standard().kinematic_viscosity();
    assert!((model.critical_speed * per_speed / model.critical - 1.0).abs() < 1e-12 && model.critical_speed > DragCrisis::CRISIS_SPEED);
    // Each construction: the speed where its own flown C_D (no spin, default
    // ball and air) has 95 % of the drop done, found by bisection on flights' launch report.
    for &(panels, re) in &model.constructions {
        let c_d = |v: f64| {
            let spec = FlightSpec { ball_panels: Some(panels as f64), ..FlightSpec::from_exit_speed(v, 45.0) };
            solve(&spec.build().unwrap()).unwrap().launch.drag_coefficient
        };
        let (mut lo, mut hi) = (3.0, 40.0);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if c_d(mid) > base + 0.05 * drop {
                lo = mid
            } else {
                hi = mid
            }
        }
        let found = 0.5 * (lo + hi) * per_speed;
        assert!((found / re - 1.0).abs() < 1e-9, "{panels} panels: {found} vs {re}");
        let published = BallConstruction::with_panels(panels as f64).unwrap().published_critical_reynolds();
        assert!((re / model.critical - published / 3.1e5).abs() < 1e-12, "{panels}");
    }
}

#[test]
fn drag_rows_and_ball_rows_read_the_file() {
    let m = measurements();
    let rows = drag_crisis_comparisons(&m).unwrap();
    let model = drag_crisis_model();
    let asai: Vec<_> = rows.iter().filter(|r| r.measured.key == keys::CRITICAL_RE).collect();
    assert_eq!(asai.len(), 1, "one definition, one row");
    assert_eq!(asai[0].model, model.critical);
    assert_eq!(asai[0].agrees(), Some(true));
    assert_eq!(rows.iter().filter(|r| r.measured.key.contains("panels")).count(), 4);
    // Every critical Re the rows quote is the one definition's.
    for r in rows.iter().filter(|r| r.quantity.contains("critical") || r.quantity.contains("transition")) {
        assert!(r.model == model.critical_speed || model.constructions.iter().any(|c| c.1 == r.model), "{r}");
    }
    for r in ball_comparisons(&m).unwrap() {
        assert_eq!(r.agrees(), Some(true), "{r}");
    }
    let mut short = m.clone();
    short.measurements.retain(|x| x.key != keys::TRANSITION_SPEED);
    let e = drag_crisis_comparisons(&short).unwrap_err().to_string();
    assert!(e.contains(keys::TRANSITION_SPEED) && e.contains(MEASUREMENTS_FILE), "{e}");
}

/// Lift is horizontal for a vertical spin axis and drag only slows the ball,
/// so the horizontal path is nearly a circle of the launch curvature; the
/// path's changing elevation (cos² θ) and C_L's rise as the ball slows keep
/// the two within 10 %.
#[test]
fn free_kick_deflections_meet_the_circle_estimate() {
    let m = measurements();
    let kicks = free_kicks(&m, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE).unwrap();
    assert_eq!(kicks.kicks.len(), 9);
    for k in &kicks.kicks {
        let ratio = k.lateral_offset / k.circle_estimate;
        assert!((ratio - 1.0).abs() < 0.10, "{k:?}: ratio {ratio}");
        assert!(k.height > 0.0 && k.time > 0.0);
    }
    // Opposite spin, mirror-image deflection.
    let a = free_kick(27.5, 9.0 * std::f64::consts::TAU, 16.0, 25.0).unwrap();
    let b = free_kick(27.5, -9.0 * std::f64::consts::TAU, 16.0, 25.0).unwrap();
    assert!((a.lateral_offset + b.lateral_offset).abs() < 1e-9 * a.lateral_offset.abs());
}

/// Mencke et al.'s flights, flown from the transcribed launch: the rows are
/// these flights (solved again here), the spin curves the ball toward −y,
/// and without spin the horizontal path keeps its launch direction exactly.
#[test]
fn measured_flights_are_the_flights_they_name() {
    let m = measurements();
    let rows = measured_flights(&m).unwrap();
    assert_eq!(rows.len(), 3);
    let straight = FlightSpec { launch_velocity: Some([20.0, 2.5, 4.9]), distance: Some(16.35182), ..FlightSpec::default() };
    let y = solve(&straight.build().unwrap()).unwrap().crossing.unwrap().lateral_offset;
    assert!((y - 16.35182 * 2.5 / 20.0).abs() < 1e-9 * y, "{y}");
    assert!(rows[0].model < y - 1.0, "the spin bends it toward -y: {}", rows[0].model);
    let plain = solve(&FlightSpec { launch_velocity: Some([11.0, 0.0, 10.2]), ..FlightSpec::default() }.build().unwrap()).unwrap();
    assert_eq!(rows[1].model, plain.apex_height - 0.11);
    assert_eq!(rows[2].model, plain.landing_point[0]);
    for r in &rows {
        assert!(matches!(r.measured.checked, kick_core::measurements::Checked::Transcription(_)), "{r}");
    }
}

/// The plateau's role: no lift, no bend (to rounding); the bend grows with a
/// constant C_L and stays within 10 % of the circle of launch curvature.
#[test]
fn the_bend_follows_the_lift_plateau() {
    let (v, w, theta, d) = (27.5, 9.0 * std::f64::consts::TAU, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE);
    let rows = lift_plateau_bends(v, w, theta, d, &[0.0, 0.20, 0.24, 0.29]).unwrap();
    assert_eq!(rows.len(), 5);
    assert!(rows[0].constant_lift.is_none() && rows[0].launch_lift > 0.25);
    assert!(rows[1].lateral_offset.abs() < 1e-12, "{}", rows[1].lateral_offset);
    for pair in rows[1..].windows(2) {
        assert!(pair[1].lateral_offset > pair[0].lateral_offset);
    }
    let k = 1.225 * std::f64::consts::PI * 0.11 * 0.11 / (2.0 * 0.43);
    for r in &rows[2..] {
        let c = r.constant_lift.unwrap();
        let rho = theta.to_radians().cos().powi(2) / (k * c);
        let circle = rho - (rho * rho - d * d).sqrt();
        assert!((r.lateral_offset / circle - 1.0).abs() < 0.10, "C_L {c}: {} vs {circle}", r.lateral_offset);
        assert_eq!(r.launch_lift, c);
    }
}

/// Spin decay: the k_M found leaves the asked share of the spin at landing,
/// and less spin left means less bend.
#[test]
fn spin_decay_leaves_the_asked_share() {
    let rows = spin_decay_bends(27.5, 9.0 * std::f64::consts::TAU, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE, &[0.9, 0.5]).unwrap();
    assert_eq!(rows[0].spin_decay, 0.0);
    assert!((rows[1].kept_at_landing - 0.9).abs() < 1e-9 && (rows[2].kept_at_landing - 0.5).abs() < 1e-9, "{rows:?}");
    assert!(rows[0].lateral_offset > rows[1].lateral_offset && rows[1].lateral_offset > rows[2].lateral_offset, "{rows:?}");
}

/// Physics World's own estimate beside the middle kick: the kick is the
/// free kick flown over the article's path; its lift at launch is ½ ρ A C_L v²
/// with the C_L of the flight's own launch report; the article's side force
/// is C_L = F/(½ ρ A v²), here 3.5/(½ · 1.2041… · π · 0.11² · 27.5²) ≈ 0.20;
/// and its estimate is a t²/2 with a = F/m: 3.5/0.43 · 1²/2 ≈ 4 m.
#[test]
fn the_article_s_estimate_stands_beside_the_middle_kick() {
    let m = measurements();
    let kicks = free_kicks(&m, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE).unwrap();
    let e = &kicks.estimate;
    let (v, w, d) = (27.5, 0.5 * (8.0 + 10.0) * std::f64::consts::TAU, 30.0);
    assert_eq!((e.kick.speed, e.distance.midpoint()), (v, Some(d)));
    assert!((e.kick.spin - w).abs() < 1e-12 * w);
    assert_eq!(e.kick, free_kick(v, w, FREE_KICK_ELEVATION, d).unwrap());
    let flight = FlightSpec { spin: Some([0.0, 0.0, w]), ..FlightSpec::from_exit_speed(v, FREE_KICK_ELEVATION) }.build().unwrap();
    let launch = solve(&flight).unwrap().launch;
    let q = 0.5 * Air::standard().density * std::f64::consts::PI * 0.11f64.powi(2) * v * v;
    assert!((e.lift_force - q * launch.lift_coefficient).abs() < 1e-12 * e.lift_force, "{} {}", e.lift_force, q * launch.lift_coefficient);
    assert!((e.implied_lift_coefficient - 3.5 / q).abs() < 1e-12, "{}", e.implied_lift_coefficient);
    assert!((0.19..0.21).contains(&e.implied_lift_coefficient));
    // "below the default's plateau": the C_L the middle kick launches with.
    assert!(e.implied_lift_coefficient < launch.lift_coefficient, "{} {}", e.implied_lift_coefficient, launch.lift_coefficient);
    let (force, time, bend) = (e.side_force.midpoint().unwrap(), e.flight_time.midpoint().unwrap(), e.bend.midpoint().unwrap());
    assert!((force / 0.43 * time * time / 2.0 - bend).abs() < 0.5 * bend.min(1.0), "the article's bend is a t²/2");
}
