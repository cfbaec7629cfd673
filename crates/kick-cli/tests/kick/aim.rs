//! `kick aim`: the JSON's launch flown by kick-flight reaches the target;
//! no solution exits 1 saying so; bad input names its flag.

use crate::kick;
use kick_flight::{solve, Flight, FlightSpec};

fn json(args: &[&str]) -> serde_json::Value {
    let out = kick(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn three(v: &serde_json::Value) -> [f64; 3] {
    let a: Vec<f64> = v.as_array().expect("array").iter().map(|x| x.as_f64().unwrap()).collect();
    [a[0], a[1], a[2]]
}

#[test]
fn the_printed_launch_flown_again_reaches_the_target() {
    for from in ["launch", "kick"] {
        let mut args = vec!["aim", "--target", "25,-2.5,1.9", "--wall", "9.15,2.0,1.2", "--from", from, "--format", "json"];
        if from == "launch" {
            args.extend(["--spin", "0,0,-40"]);
        }
        let v = json(&args);
        let (launch, spin) = (three(&v["launch_velocity"]), three(&v["spin"]));
        let rest = FlightSpec { distance: Some(25.0), ..FlightSpec::default() };
        let c = solve(&Flight::from_launch(launch, spin, &rest).unwrap()).unwrap().crossing.unwrap();
        let miss = (c.lateral_offset + 2.5).hypot(c.height - 1.9);
        assert!(miss <= kick_flight::aim::MISS_TOLERANCE, "{from}: miss {miss} m");
        assert!(v["wall_clearance"].as_f64().unwrap() >= 0.0);
        assert_eq!(v["from"], from);
        let names: Vec<&str> = v["parameters"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
        let expected: &[&str] =
            if from == "kick" { &["foot_speed", "offset", "contact_depth", "heading"] } else { &["speed", "launch_angle", "azimuth"] };
        assert_eq!(names, expected);
    }
}

#[test]
fn no_solution_exits_1_and_says_so() {
    let out = kick(&["aim", "--target", "25,0,1.5", "--speed", "12", "--free", "launch_angle,azimuth"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr.contains("no solution found within the parameters' ranges"), "{stderr}");
    assert!(out.stdout.is_empty());
}

#[test]
fn bad_input_names_the_flag() {
    for (args, flag) in [
        (&["aim", "--target", "25,0,10"][..], "--target"),
        (&["aim", "--target", "25,0,nan"], "--target"),
        (&["aim", "--target", "25,0"], "--target"),
        (&["aim", "--target", "25,0,1", "--wall", "30,1.8,1"], "--wall"),
        (&["aim", "--target", "25,0,1", "--wall", "9.15,-1,1"], "--wall"),
        (&["aim", "--target", "25,0,1", "--free", "speed,spinz"], "--free"),
        (&["aim", "--target", "25,0,1", "--free", "speed,speed"], "--free"),
        // A flag holds its parameter; a free one's start must lie in its range.
        (&["aim", "--target", "25,0,1", "--free", "speed", "--speed", "50"], "--speed"),
        (&["aim", "--target", "25,0,1", "--distance", "20"], "--distance"),
        (&["aim", "--target", "25,0,1", "--launch-velocity", "20,0,5"], "--launch-velocity"),
        (&["aim", "--target", "25,0,1", "--from", "kick", "--speed", "20"], "--speed"),
        (&["aim", "--target", "25,0,1", "--from", "foot"], "--from"),
        (&["aim", "--target", "25,0,1", "--foot-mass", "5"], "--from kick"),
        (&["aim", "--target", "25,0,1", "--from", "kick", "--free", "foot_speed", "--foot-speed", "50"], "--foot-speed"),
    ] {
        let out = kick(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?}");
        assert!(stderr.contains(flag), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
}

/// Kick flags reach the kick: a heavier foot needs a slower swing for the
/// same target (the ball leaves faster per unit foot speed, Eq. 57's mass ratio).
#[test]
fn kick_flags_set_the_kick() {
    let foot_speed = |args: &[&str]| {
        let mut all = vec!["aim", "--target", "25,-2,1.8", "--from", "kick", "--format", "json"];
        all.extend(args);
        let v = json(&all);
        v["parameters"][0]["value"].as_f64().unwrap()
    };
    let (light, heavy) = (foot_speed(&[]), foot_speed(&["--foot-mass", "6"]));
    assert!(heavy < light - 1.0, "{heavy} vs {light}");
}
