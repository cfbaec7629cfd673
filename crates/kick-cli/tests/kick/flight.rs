//! `kick flight` and `--flight` of `kick simulate` / `kick simulate3d`: JSON
//! contract, closed forms, agreement with kick-flight, errors naming flags.

use crate::kick;
use kick_flight::{solve, Flight, FlightSpec};

fn json(args: &[&str]) -> serde_json::Value {
    let out = kick(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn vec_of(v: &serde_json::Value) -> Vec<f64> {
    v.as_array().expect("array").iter().map(num).collect()
}

/// Relative agreement; serde_json's default float parsing may be an ulp off.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-300) || a == b
}

#[test]
fn flight_json_has_the_contract_keys_and_matches_kick_flight() {
    let v = json(&["flight", "--speed", "27", "--launch-angle", "16", "--spin", "0,0,56.5", "--distance", "9.15", "--format", "json"]);
    for key in ["flight_time", "apex_height"] {
        assert!(v[key].is_f64(), "{key}");
    }
    assert_eq!(vec_of(&v["landing_point"]).len(), 2);
    assert_eq!(vec_of(&v["landing_velocity"]).len(), 3);
    let crossing = &v["crossing"];
    for key in ["time", "height", "lateral_offset"] {
        assert!(crossing[key].is_f64(), "crossing.{key}");
    }
    let spec = FlightSpec { spin: Some([0.0, 0.0, 56.5]), distance: Some(9.15), ..FlightSpec::from_exit_speed(27.0, 16.0) };
    let o = solve(&spec.build().unwrap()).unwrap();
    let c = o.crossing.unwrap();
    let pairs = [
        (num(&v["flight_time"]), o.flight_time),
        (num(&v["apex_height"]), o.apex_height),
        (vec_of(&v["landing_point"])[0], o.landing_point[0]),
        (vec_of(&v["landing_point"])[1], o.landing_point[1]),
        (vec_of(&v["landing_velocity"])[2], o.landing_velocity[2]),
        (num(&crossing["height"]), c.height),
        (num(&crossing["lateral_offset"]), c.lateral_offset),
    ];
    for (cli, library) in pairs {
        assert!(close(cli, library, 4.0 * f64::EPSILON), "{cli} vs {library}");
    }
    // ω_z > 0 curves a kick along +x toward +y.
    assert!(c.lateral_offset > 0.0 && o.landing_point[1] > 0.0);
    // No plane asked for: crossing is null, not missing.
    let v = json(&["flight", "--speed", "27", "--launch-angle", "16", "--format", "json"]);
    assert!(v.get("crossing").is_some_and(|c| c.is_null()));
}

/// `--format json` reports the air's numbers at launch: Re = ρ v 2R/μ,
/// S = R|ω × v|/|v|², C_D and C_L there, computed here independently (Eq. 3
/// without spin; the spinning ball's join above the crisis; the 32-panel
/// ball's crisis at 2.5/3.1 of the Teamgeist's Re).
#[test]
fn flight_json_reports_the_launch_aerodynamics() {
    let v = json(&["flight", "--speed", "12", "--launch-angle", "10", "--format", "json"]);
    let launch = &v["launch"];
    let (rho, mu, d) = (1.225, 1.7894e-5, 0.22);
    assert!(close(num(&launch["reynolds"]), rho * 12.0 * d / mu, 1e-4), "{launch}");
    assert_eq!(num(&launch["spin_parameter"]), 0.0);
    assert_eq!(num(&launch["lift_coefficient"]), 0.0);
    let eq3 = |v: f64| 0.155 + 0.346 / (1.0 + ((v - 12.19) / 1.309_f64).exp());
    assert!(close(num(&launch["drag_coefficient"]), eq3(12.0), 1e-12), "{launch}");
    // Sidespin 50 rad/s about the vertical at 25 m/s, 10° up: |ω × v| = ω v cos θ, so S = R ω cos θ/v.
    let v = json(&["flight", "--speed", "25", "--launch-angle", "10", "--spin", "0,0,50", "--format", "json"]);
    let launch = &v["launch"];
    let s = 0.11 * 50.0 * 10f64.to_radians().cos() / 25.0;
    assert!(close(num(&launch["spin_parameter"]), s, 1e-12), "{launch}");
    let s_star = (0.155_f64 / 0.4127).powf(1.0 / 0.3056);
    let sup = 0.155 * (1.0 + (s / s_star).powi(4)).powf(0.3056 / 4.0);
    let sigma = 1.0 / (1.0 + ((25.0 - 12.19) / 1.309_f64).exp());
    assert!(close(num(&launch["drag_coefficient"]), sup + sigma * (0.501 - sup), 1e-9), "{launch}");
    assert!(num(&launch["drag_coefficient"]) > 0.2, "a spinning ball has more drag than 0.155");
    let lift = 0.2923 * (1.0 - (-(s / 0.1027).powi(2)).exp());
    assert!(close(num(&launch["lift_coefficient"]), lift, 1e-12), "{launch}");
    // A 32-panel ball at 12 m/s is past more of its crisis: its Re_c is 2.5/3.1 of the default's.
    let v = json(&["flight", "--speed", "12", "--launch-angle", "10", "--ball-panels", "32", "--format", "json"]);
    let k = 2.5 / 3.1;
    let expected = 0.155 + 0.346 / (1.0 + ((12.0 - k * 12.19) / (k * 1.309_f64)).exp());
    assert!(close(num(&v["launch"]["drag_coefficient"]), expected, 1e-9), "{}", v["launch"]);
}

/// No drag, no lift: the vacuum parabola, T = 2 v sinθ/g, range v² sin2θ/g,
/// apex R + v² sin²θ/(2g) (the centre's height above the ground, starting at
/// R), crossing height R + v sinθ t − g t²/2 at x = d.
#[test]
fn flight_without_air_forces_is_the_parabola() {
    let (speed, angle, g, d, r) = (25.0_f64, 35.0_f64, 9.81, 30.0, 0.11);
    let v = json(&[
        "flight",
        "--speed",
        "25",
        "--launch-angle",
        "35",
        "--azimuth",
        "0",
        "--ball-radius",
        "0.11",
        "--drag-coefficient",
        "0",
        "--lift-coefficient",
        "0",
        "--spin",
        "0,0,40",
        "--distance",
        "30",
        "--format",
        "json",
    ]);
    let (s, c) = (angle.to_radians().sin(), angle.to_radians().cos());
    let time = 2.0 * speed * s / g;
    assert!(close(num(&v["flight_time"]), time, 1e-9), "{}", v["flight_time"]);
    assert!(close(vec_of(&v["landing_point"])[0], speed * speed * (2.0 * angle.to_radians()).sin() / g, 1e-9));
    assert!(vec_of(&v["landing_point"])[1].abs() < 1e-12);
    assert!(close(num(&v["apex_height"]), r + (speed * s).powi(2) / (2.0 * g), 1e-9));
    let t = d / (speed * c);
    assert!(close(num(&v["crossing"]["time"]), t, 1e-9));
    assert!(close(num(&v["crossing"]["height"]), r + speed * s * t - g * t * t / 2.0, 1e-9));
    // The vector form of the same launch gives the same flight.
    let launch = format!("{},0,{}", speed * c, speed * s);
    let w = json(&["flight", "--launch-velocity", &launch, "--drag-coefficient", "0", "--lift-coefficient", "0", "--format", "json"]);
    assert!(close(num(&w["flight_time"]), time, 1e-9));
}

#[test]
fn flight_bad_input_names_the_flag() {
    let cases: [(&[&str], &str); 8] = [
        (&["flight", "--speed", "-1", "--launch-angle", "20"], "--speed"),
        (&["flight", "--speed", "nan", "--launch-angle", "20"], "--speed"),
        (&["flight", "--speed", "20"], "--launch-angle"),
        (&["flight", "--speed", "20", "--launch-angle", "20", "--spin", "1,2"], "--spin"),
        (&["flight", "--speed", "20", "--launch-angle", "20", "--drag-coefficient", "-0.1"], "--drag-coefficient"),
        (&["flight", "--speed", "20", "--launch-angle", "20", "--ball-panels", "12"], "--ball-panels"),
        (&["flight", "--speed", "20", "--launch-angle", "20", "--launch-velocity", "20,0,5"], "--speed"),
        (&["simulate", "--distance", "20"], "--flight"),
    ];
    for (args, flag) in cases {
        let out = kick(args);
        assert!(!out.status.success(), "{args:?} should fail");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(flag), "{args:?}: {stderr}");
    }
}

/// `simulate3d --flight` flies the launch velocity and spin it prints, as
/// `kick flight` does when given them.
#[test]
fn simulate3d_flight_is_kick_flight_of_its_launch() {
    let v = json(&[
        "simulate3d",
        "--offset",
        "0.05",
        "--approach-angle",
        "40",
        "--friction",
        "0.6",
        "--flight",
        "--distance",
        "9.15",
        "--format",
        "json",
    ]);
    let (launch, spin) = (vec_of(&v["launch_velocity"]), vec_of(&v["spin"]));
    let joined = |a: &[f64]| a.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",");
    let f = json(&["flight", "--launch-velocity", &joined(&launch), "--spin", &joined(&spin), "--distance", "9.15", "--format", "json"]);
    let flight = &v["flight"];
    assert!(spin[2].abs() > 10.0, "an off-center kick spins: {spin:?}");
    for key in ["flight_time", "apex_height"] {
        assert!(close(num(&flight[key]), num(&f[key]), 1e-12), "{key}: {} vs {}", flight[key], f[key]);
    }
    for key in ["landing_point", "landing_velocity"] {
        for (a, b) in vec_of(&flight[key]).iter().zip(vec_of(&f[key])) {
            assert!(close(*a, b, 1e-12), "{key}: {a} vs {b}");
        }
    }
    assert!(close(num(&flight["crossing"]["lateral_offset"]), num(&f["crossing"]["lateral_offset"]), 1e-12));
    // The 3D kick's ball is the flight's; a horizontal launch is refused, not flown.
    let out = kick(&["simulate3d", "--offset", "0.05", "--flight"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("not upward"));
}

/// `simulate --flight --launch-angle` flies v_b⁺ at that elevation, no spin.
#[test]
fn simulate_flight_flies_the_exit_speed() {
    let v = json(&["simulate", "--flight", "--launch-angle", "15", "--distance", "20", "--format", "json"]);
    let speed = num(&v["v_ball_out"]);
    let flight = &v["flight"];
    let spec = FlightSpec { distance: Some(20.0), ..FlightSpec::from_exit_speed(speed, 15.0) };
    let o = solve(&spec.build().unwrap()).unwrap();
    assert!(close(num(&flight["flight_time"]), o.flight_time, 1e-12));
    assert!(close(vec_of(&flight["landing_point"])[0], o.landing_point[0], 1e-12));
    assert!(close(num(&flight["crossing"]["height"]), o.crossing.unwrap().height, 1e-12));
    assert_eq!(vec_of(&flight["spin"]), [0.0; 3]);
    // The kick's ball mass reaches the flight: a heavier ball flies farther at the same launch.
    let heavy = json(&["simulate", "--ball-mass", "0.45", "--flight", "--launch-angle", "15", "--format", "json"]);
    let same_launch = Flight::from_launch(
        {
            let s = num(&heavy["v_ball_out"]);
            let a = 15f64.to_radians();
            [s * a.cos(), 0.0, s * a.sin()]
        },
        [0.0; 3],
        &FlightSpec { ball_mass: Some(0.45), ..FlightSpec::default() },
    )
    .unwrap();
    let o = solve(&same_launch).unwrap();
    assert!(close(num(&heavy["flight"]["flight_time"]), o.flight_time, 1e-9));
    let out = kick(&["simulate", "--flight"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--launch-angle"));
}
