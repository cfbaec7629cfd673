//! `kick bounce`: the JSON contract, the FIFA drop, refusals naming the flag.

use super::kick;

fn json(args: &[&str]) -> serde_json::Value {
    let out = kick(args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn bounce_json_has_the_contract_keys() {
    let j = json(&["bounce", "--speed", "12", "--angle", "25", "--spin", "0,-10,3", "--format", "json"]);
    for key in ["restitution", "contact_time", "peak_force", "max_compression"] {
        assert!(j[key].as_f64().unwrap() > 0.0, "{key}");
    }
    for key in ["exit_velocity", "exit_spin"] {
        assert_eq!(j[key].as_array().unwrap().len(), 3, "{key}");
    }
    assert!(j.get("rebound_height").is_none());
    // Normal exit speed is e times the normal impact speed; z-spin untouched.
    let e = j["restitution"].as_f64().unwrap();
    let vz = j["exit_velocity"][2].as_f64().unwrap();
    assert!((vz - e * 12.0 * 25f64.to_radians().cos()).abs() < 1e-12 * vz, "{vz}");
    assert_eq!(j["exit_spin"][2].as_f64().unwrap(), 3.0);
}

/// The library's answer, through the flags: the same numbers as `kick_bounce::run`.
#[test]
fn bounce_drop_matches_the_library() {
    let j = json(&["bounce", "--drop-height", "2", "--inflation-pressure", "70000", "--format", "json"]);
    let mut spec = kick_bounce::BounceSpec::default();
    spec.set("drop_height", kick_core::Value::Number(2.0)).unwrap();
    spec.set("inflation_pressure", kick_core::Value::Number(7.0e4)).unwrap();
    let o = kick_bounce::run(&spec).unwrap();
    // To a few ulp: JSON text parsed back need not be the bit pattern printed.
    let same = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
    assert!(same(j["rebound_height"].as_f64().unwrap(), o.rebound_height.unwrap()));
    assert!(same(j["peak_force"].as_f64().unwrap(), o.peak_force));
}

#[test]
fn bounce_refusals_name_the_flag() {
    for (args, flag) in [
        (&["bounce", "--speed", "0"][..], "--speed"),
        (&["bounce", "--speed", "nan"][..], "--speed"),
        (&["bounce"][..], "--speed"),
        (&["bounce", "--speed", "5", "--angle", "90"][..], "--angle"),
        (&["bounce", "--speed", "5", "--inflation-pressure", "-1"][..], "--inflation-pressure"),
        (&["bounce", "--speed", "5", "--drop-height", "2"][..], "--speed"),
        (&["bounce", "--drop-height", "2", "--angle", "5"][..], "--angle"),
        (&["bounce", "--speed", "5", "--spin", "1,2"][..], "--spin"),
        (&["bounce", "--speed", "5", "--stiffness", "1e5"][..], "--stiffness"),
        (&["bounce", "--law", "power-law", "--speed", "5", "--shell-damping", "3000"][..], "--shell-damping"),
        (&["bounce", "--law", "hertz", "--speed", "5"][..], "--law"),
    ] {
        let out = kick(args);
        // Parse errors (clap: a shape, a name, a non-finite number) exit 2, refusals by the library 1.
        let parse = flag == "--spin" || flag == "--law" || args.contains(&"nan");
        assert_eq!(out.status.code(), Some(if parse { 2 } else { 1 }), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(flag), "{args:?}: {err}");
    }
}

/// `--law power-law` is the kick's default ball (Eq. 20, Table 1): the
/// drop the issue reports, e ≈ 0.64.
#[test]
fn bounce_takes_the_kick_family_laws() {
    let j = json(&["bounce", "--law", "power-law", "--drop-height", "2", "--format", "json"]);
    let e = j["restitution"].as_f64().unwrap();
    assert!((e - 0.64).abs() < 0.01, "{e}");
}

/// Values far outside a ball are refused by name before any solve: before
/// their bounds, 1e300 ended in "integration failed … step size underflow"
/// or in an error naming the foot (the bounce's ball plays the 1D foot).
#[test]
fn values_beyond_a_ball_are_refused_by_name() {
    for (args, name) in [
        (&["bounce", "--speed", "1e300"][..], "`speed`"),
        (&["bounce", "--speed", "5", "--shell-damping", "1e300"][..], "`shell_damping`"),
        (&["bounce", "--speed", "5", "--inflation-pressure", "1e-300"][..], "`inflation_pressure`"),
        (&["simulate", "--law", "shell", "--shell-stiffness", "1e300"][..], "`shell_stiffness`"),
        (&["simulate", "--law", "shell", "--shell-damping", "1e300"][..], "`shell_damping`"),
        (&["simulate", "--law", "shell", "--inflation-pressure", "1e300"][..], "`inflation_pressure`"),
    ] {
        let out = kick(args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(name) && !err.contains("integration failed"), "{args:?}: {err}");
    }
}

/// Valid values whose normal contact leaves double precision are refused
/// naming `kick bounce`'s own flags, never the 1D kick's (`foot_mass`,
/// `foot_speed`, `drive_force`), which `kick bounce` does not have.
#[test]
fn bounce_out_of_range_names_its_own_flags() {
    for (args, flag) in [
        (&["bounce", "--speed", "5", "--ball-mass", "1e-300"][..], "--ball-mass"),
        (&["bounce", "--drop-height", "1e300"][..], "--drop-height"),
        (&["bounce", "--speed", "5", "--gravity", "1e300"][..], "--gravity"),
    ] {
        let out = kick(args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(flag) && !err.contains("foot") && !err.contains("drive_force"), "{args:?}: {err}");
    }
}

/// Issue 33, fault 5: a result past its contact law's validity is printed
/// whole with its status and ends in exit 1 with the reason, never as an
/// ordinary result. `kick bounce --speed 100` compresses the shell ball
/// 0.114 m, past R/2 (and past R); `kick simulate --law shell --foot-speed
/// 1e4` 0.218 m. A bounce within it keeps status `separated` and exit 0.
#[test]
fn a_result_outside_its_law_is_flagged_and_exits_1() {
    for args in [
        &["bounce", "--speed", "100", "--format", "json"][..],
        &["simulate", "--law", "shell", "--foot-speed", "1000", "--format", "json"][..],
        &["simulate", "--stiffness", "1e4", "--foot-speed", "100", "--format", "json"][..],
        &["simulate3d", "--law", "shell", "--foot-speed", "60", "--format", "json"][..],
    ] {
        let out = kick(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(j["status"], "outside_validity", "{args:?}");
        let limit = j["outside_validity"]["largest"].as_f64().unwrap();
        assert!(j["max_compression"].as_f64().unwrap() > limit, "{args:?}");
        assert!(stderr.contains("outside the validity of law") && stderr.contains("exceeds"), "{args:?}: {stderr}");
    }
    let out = kick(&["bounce", "--speed", "100"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("status            outside validity"));
    let j = json(&["bounce", "--speed", "20", "--format", "json"]);
    assert_eq!(j["status"], "separated");
    assert!(j.get("outside_validity").is_none());
}

/// Issue 33, fault 12: a ball too slow to rebound rests on the plate; the
/// refusal speaks of the plate and the ball's weight, names the flag given,
/// and never of a foot or a drive, which a bounce has not.
#[test]
fn a_ball_that_stays_on_the_plate_is_said_in_the_bounce_s_terms() {
    for args in [&["bounce", "--speed", "0.01", "--law", "power-law"][..], &["bounce", "--drop-height", "1e-6", "--law", "power-law"][..]] {
        let out = kick(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{stderr}");
        assert!(stderr.contains("never leaves the plate") && stderr.contains("weight"), "{stderr}");
        let flag = if args.contains(&"--speed") { "(flag --speed)" } else { "(flag --drop-height)" };
        assert!(stderr.contains(flag), "{stderr}");
        for word in ["foot", "drive", "F_drive"] {
            assert!(!stderr.contains(word), "`{word}` in {stderr}");
        }
    }
    // A weight the user set is named beside the speed: it is what holds the
    // ball (1e6 m/s² traps a ball at 5 m/s).
    let out = kick(&["bounce", "--speed", "5", "--gravity", "1e6"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("(flags --speed, --gravity)"), "{stderr}");
}
