//! `kick check` and `kick leg`: exit codes, JSON keys, agreement with the libraries.

use crate::kick;
use kick_leg::{AnkleJoint, Impact, Leg, Pose};

#[test]
fn check_json_lists_every_row_and_exits_zero_when_all_pass() {
    let out = kick(&["check", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let rows: Vec<serde_json::Value> = serde_json::from_slice(&out.stdout).unwrap();
    // kick check also appends other crates' checks (kick-3d): ours must all be there.
    for ours in kick_checks::run_all() {
        assert!(rows.iter().any(|r| r["name"] == ours.name.as_str()), "missing {}", ours.name);
    }
    for row in &rows {
        for key in ["expected", "actual", "error", "tolerance"] {
            assert!(row[key].is_f64(), "{key} in {row}");
        }
        assert_eq!(row["passed"], serde_json::Value::Bool(true), "{row}");
        assert!(row["name"].is_string() && row["equation"].is_string());
    }
    let text = kick(&["check"]);
    assert!(text.status.success());
    let stdout = String::from_utf8_lossy(&text.stdout);
    assert!(stdout.contains("PASS") && !stdout.contains("FAIL"), "{stdout}");
}

#[test]
fn leg_json_matches_the_library_and_bad_angles_fail() {
    let out = kick(&["leg", "--knee", "40", "--ankle", "50", "--locked-ankle", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let leg = Leg::de_leva(73.0, 1.741).unwrap();
    let pose = Pose { knee_flexion: 40.0, plantarflexion: 50.0, ..Pose::default() };
    let expected = leg.effective_mass(&pose, &Impact::default(), AnkleJoint::Locked).unwrap().effective_mass;
    assert_eq!(value["effective_mass"].as_f64().unwrap(), expected);
    // The exit speed comes from the 1D model with m_f = m_eff: below the
    // elastic bound 2 m_f/(m_f + m_b) v_f (Eq. 38 with e = 1).
    let v = value["v_ball_out"].as_f64().unwrap();
    assert!(v > 0.0 && v < 2.0 * expected / (expected + 0.43) * 22.0, "{v}");

    let bad = kick(&["leg", "--knee", "200", "--ankle", "50"]);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("knee"));
    let planar_rotation = kick(&["leg", "--knee", "30", "--ankle", "50", "--rotation", "20"]);
    assert!(!planar_rotation.status.success());
    assert!(String::from_utf8_lossy(&planar_rotation.stderr).contains("`rotation` = 20"));
    // The spatial leg's inputs are named as their flags are (not `hip_abduction`).
    let abduction = kick(&["leg", "--spatial", "--abduction", "200"]);
    assert!(String::from_utf8_lossy(&abduction.stderr).contains("`abduction` = 200"), "{abduction:?}");
    // -inf reaches the check that names the flag (clap took "-i" for a flag),
    // and the impact direction is an angle like the others: one turn.
    for (args, named) in [
        (["leg", "--knee", "-inf"], "`knee` = -inf"),
        (["leg", "--body-mass", "-inf"], "`body_mass` = -inf"),
        (["leg", "--direction", "1e300"], "`direction` = 1e300"),
        (["leg", "--direction", "-181"], "`direction` = -181"),
    ] {
        let out = kick(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains(named), "{args:?}: {stderr}");
    }
    assert!(kick(&["leg", "--direction", "-30"]).status.success());
}

#[test]
fn leg_sweep_files_read_back_with_units_and_library_values() {
    let dir = std::env::temp_dir().join(format!("kick-leg-sweep-{}", std::process::id()));
    let out = kick(&["leg", "--knee", "30", "--ankle", "60", "--sweep-out", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let grid = kick_store::SweepData::read(&dir.join("leg_effective_mass.h5")).unwrap();
    let (knees, ankles) = (grid.parameter("knee").unwrap(), grid.parameter("ankle").unwrap());
    assert_eq!(knees.len(), 25 * 19);
    let leg = Leg::de_leva(73.0, 1.741).unwrap();
    for (solver, joint) in [("locked-ankle", AnkleJoint::Locked), ("free-ankle", AnkleJoint::Free)] {
        let set = grid.set(solver).unwrap();
        assert!(set.status.iter().all(|&s| s == 0));
        let (column, masses) = set.columns.iter().find(|(c, _)| c.name == "effective_mass").unwrap();
        assert_eq!(column.unit, "kg");
        // Row 100: knee-major order, the library's value for that pose.
        let pose = Pose { knee_flexion: knees[100], plantarflexion: ankles[100], ..Pose::default() };
        let expected = leg.effective_mass(&pose, &Impact::default(), joint).unwrap().effective_mass;
        assert_eq!(masses[100], expected);
    }
    let curve = kick_store::SweepData::read(&dir.join("leg_exit_speed.h5")).unwrap();
    let set = curve.set("accurate").unwrap();
    let speed = &set.columns.iter().find(|(c, _)| c.name == "v_ball_out").unwrap().1;
    let bound = &set.columns.iter().find(|(c, _)| c.name == "elastic_bound_v_ball_out").unwrap().1;
    // Rising, below the elastic bound of Eq. 38 (e = 1).
    assert!(speed.windows(2).all(|w| w[1] > w[0]));
    assert!(speed.iter().zip(bound.iter()).all(|(v, b)| v < b));
    std::fs::remove_dir_all(&dir).ok();
}

/// `kick leg` with no arguments is the library's documented default pose,
/// and its help names that pose.
#[test]
fn leg_without_arguments_is_the_documented_default_pose() {
    let out = kick(&["leg", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let cli: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let library = kick_study::json(&kick_study::leg::leg(&kick_study::leg::LegSettings::default()).unwrap()).unwrap();
    let library: serde_json::Value = serde_json::from_str(&library).unwrap();
    for key in ["effective_mass", "locked_ankle", "free_ankle", "leg_mass", "v_ball_out", "contact_time", "knee", "hip", "ankle"] {
        assert_eq!(cli[key], library[key], "{key}");
    }
    let help = String::from_utf8(kick(&["leg", "--help"]).stdout).unwrap();
    assert!(help.contains("With no arguments, the default pose") && help.contains("[default: 30]"), "{help}");
}

/// A huge ankle stiffness is printed as a number is, not as 301 digits.
#[test]
fn a_huge_ankle_stiffness_is_printed_short() {
    let out = kick(&["leg", "--ankle-stiffness", "1e300"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("elastic, 1e300 N m/rad") && !text.contains("0000000000"), "{text}");
}
