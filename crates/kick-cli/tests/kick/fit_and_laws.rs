//! Contract of `kick fit` and `kick laws`: JSON keys, round trips, refusals.

use crate::kick;

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("kick-fit-test-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn fit_table2_json_reports_value_uncertainty_and_residuals() {
    let out = kick(&["fit", "table2", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 8);
    assert!(rows[0]["parameter"].is_null() && rows[0]["baseline_residuals"].is_array());
    for row in &rows[1..] {
        let report = &row["report"];
        let estimate = &report["estimates"][0];
        assert_eq!(estimate["parameter"], row["parameter"]);
        assert!(estimate["value"].is_f64() && estimate["standard_uncertainty"].as_f64().unwrap() > 0.0);
        assert_eq!(report["residuals"].as_array().unwrap().len(), 4);
        assert_eq!(report["degrees_of_freedom"], 3);
    }
}

#[test]
fn synthesized_history_is_fitted_back_within_three_sigma() {
    let dir = scratch("synth");
    let out = kick(&["fit", "synthesize", "--out", dir.to_str().unwrap(), "--seed", "3", "--times", "60"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let spec = dir.join("synthetic.toml");
    let out = kick(&["fit", "data", spec.to_str().unwrap(), "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // Table 1's values, the truth `synthesize` uses.
    let truth = [("foot_mass", 3.0), ("stiffness", 4.2e5), ("damping", 120.0), ("exponent", 1.35)];
    for (e, (name, t)) in report["estimates"].as_array().unwrap().iter().zip(truth) {
        assert_eq!(e["parameter"], name);
        let (v, s) = (e["value"].as_f64().unwrap(), e["standard_uncertainty"].as_f64().unwrap());
        assert!((v - t).abs() < 3.0 * s, "{name}: {v} ± {s} vs {t}");
    }
    assert_eq!(report["correlation"].as_array().unwrap().len(), 4);
    std::fs::remove_dir_all(&dir).ok();
}

/// The spec file written for a Hunt–Crossley kick with a late first touch
/// names the law and frees e and t0; `kick fit data` runs that law and
/// returns the truth within 3σ.
#[test]
fn synthesized_hunt_crossley_history_with_offset_is_fitted_back() {
    let dir = scratch("synth-hc");
    let out = kick(&[
        "fit",
        "synthesize",
        "--out",
        dir.to_str().unwrap(),
        "--name",
        "hc",
        "--seed",
        "4",
        "--law",
        "hunt-crossley-exact",
        "--restitution",
        "0.66",
        "--time-offset",
        "2e-4",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let spec = dir.join("hc.toml");
    let text = std::fs::read_to_string(&spec).unwrap();
    assert!(text.contains("law = \"hunt-crossley-exact\"") && text.contains("\"time_offset\""), "{text}");
    let out = kick(&["fit", "data", spec.to_str().unwrap(), "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(report["law"], "hunt-crossley-exact");
    let truth = [("foot_mass", 3.0), ("stiffness", 4.2e5), ("exponent", 1.35), ("restitution", 0.66), ("time_offset", 2e-4)];
    let estimates = report["estimates"].as_array().unwrap();
    assert_eq!(estimates.len(), truth.len());
    for (e, (name, t)) in estimates.iter().zip(truth) {
        assert_eq!(e["parameter"], name);
        let (v, s) = (e["value"].as_f64().unwrap(), e["standard_uncertainty"].as_f64().unwrap());
        assert!((v - t).abs() < 3.0 * s, "{name}: {v} ± {s} vs {t}");
    }
    // Damping does not act under this law: refused by name, exit 1.
    std::fs::write(&spec, text.replace("\"time_offset\"]", "\"time_offset\", \"damping\"]")).unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("`damping` does not apply to contact law `hunt-crossley-exact`"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn fit_data_refuses_bad_input_by_name() {
    let dir = scratch("bad");
    let spec = dir.join("bad.toml");
    std::fs::write(&spec, "free = [\"stifness\"]\n[[scalar]]\nobservable = \"v_ball_out\"\nvalue = 30.0\nsigma = 0.01\n").unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown parameter `stifness`"));

    std::fs::write(&spec, "free = [\"stiffness\"]\n[history]\nfile = \"h.csv\"\nsigma = { force = 10.0 }\n").unwrap();
    std::fs::write(dir.join("h.csv"), "time,force\n0,1\n1e-3,oops\n").unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("h.csv:3") && err.contains("`oops` is not a number"), "{err}");

    // A misspelt truth: the file, its line and the key's path.
    std::fs::write(
        &spec,
        "free = [\"stiffness\"]\n[[scalar]]\nobservable = \"v_ball_out\"\nvalue = 30.0\nsigma = 0.01\n[truth]\nstifness = 4e5\n",
    )
    .unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(&format!("{}:7: `truth.stifness`: unknown parameter `stifness`", spec.display())), "{err}");

    let out = kick(&["fit", "data", dir.join("missing.toml").to_str().unwrap()]);
    assert!(!out.status.success());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn laws_json_has_every_law_on_every_row() {
    let out = kick(&["laws", "--format", "json", "--samples", "50"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let all: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let all = all.as_array().unwrap();
    assert_eq!(all.len(), 8);
    for c in all {
        let runs = c["runs"].as_array().unwrap();
        let names: Vec<&str> = runs.iter().map(|r| r["law"].as_str().unwrap()).collect();
        assert_eq!(names, ["power-law", "hunt-crossley", "lankarani-nikravesh", "flores", "hunt-crossley-exact", "kelvin-voigt"]);
        // χ from the exact relation reproduces the paper's law's restitution.
        let e = |i: usize| runs[i]["outcome"]["restitution"].as_f64().unwrap();
        assert!((e(4) - e(0)).abs() < 1e-8, "{}: {} vs {}", c["name"], e(4), e(0));
    }
    let out = kick(&["laws", "--samples", "1"]);
    assert!(!out.status.success());
}

/// `--out` naming the specification or its data file is refused before the
/// fit, and both are left as they were (issue 21).
#[test]
fn fit_data_refuses_an_output_that_is_an_input() {
    let dir = scratch("overwrite");
    let out = kick(&["fit", "synthesize", "--out", dir.to_str().unwrap(), "--seed", "3", "--times", "20"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let (spec, data) = (dir.join("synthetic.toml"), dir.join("synthetic.csv"));
    let (spec_text, data_text) = (std::fs::read(&spec).unwrap(), std::fs::read(&data).unwrap());
    // Same file by another name: a link to the data, ending in .h5.
    let alias = dir.join("alias.h5");
    let _ = std::fs::remove_file(&alias);
    std::fs::hard_link(&data, &alias).unwrap();
    for (given, says) in [(&spec, "must end in `.h5`"), (&data, "must end in `.h5`"), (&alias, "is the input")] {
        let out = kick(&["fit", "data", spec.to_str().unwrap(), "--out", given.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(1), "{}", given.display());
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(&format!("`--out` = `{}`", given.display())) && stderr.contains(says), "{stderr}");
    }
    assert_eq!(std::fs::read(&spec).unwrap(), spec_text);
    assert_eq!(std::fs::read(&data).unwrap(), data_text);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--time-offset 0.02` used to sample 6.5 ms of free flight and exit 0;
/// `kick fit data` on such a history (t0 free) then ran for hours. Now the
/// first is refused naming the flag, and the second ends, refused.
#[test]
fn a_history_without_the_contact_is_refused_by_both_commands() {
    let dir = scratch("no-contact");
    for t0 in ["0.02", "1e9"] {
        let out = kick(&["fit", "synthesize", "--out", dir.to_str().unwrap(), "--time-offset", t0]);
        assert_eq!(out.status.code(), Some(1), "{t0}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(&format!("--time-offset {t0}: the data are sampled over [0, 0.0064")) && err.contains("holds 0%"), "{err}");
        assert!(!dir.join("synthetic.csv").exists());
    }
    // Free flight before a first touch at 20 ms: the baseline's velocities plus a ±σ pattern.
    let rows: String = (0..80)
        .map(|i| {
            let s = if i % 3 == 0 { 1.0 } else { -0.5 };
            format!("{:e},{},{},{},{}\n", i as f64 * 8.2e-5, 20.0 * s, 1e-4 * s, 22.0 + 0.05 * s, 0.05 * s)
        })
        .collect();
    std::fs::write(dir.join("flight.csv"), format!("time,force,compression,foot_velocity,ball_velocity\n{rows}")).unwrap();
    let spec = dir.join("flight.toml");
    std::fs::write(
        &spec,
        "free = [\"foot_mass\", \"stiffness\", \"damping\", \"exponent\", \"time_offset\"]\ntime_offset = 0.0\n\
         [history]\nfile = \"flight.csv\"\nsigma = { force = 20.0, compression = 1e-4, foot_velocity = 0.05, ball_velocity = 0.05 }\n",
    )
    .unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("the history shows no contact") && err.contains("over the 320 history samples"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A plate test at 300 m/s: `kick bounce` prints its result and exits 1,
/// outside the shell's validity (δ_max > R/2); `kick fit data` with that
/// test among its measurements used to exit 0 silently. It now says so in
/// the report (text and JSON), with the δ_max `kick bounce` prints at the
/// estimate, and exits 1 the same way.
#[test]
fn a_fit_outside_the_laws_validity_says_so_and_exits_one() {
    let dir = scratch("validity");
    let spec = dir.join("cannon.toml");
    let test = |name: &str, speed: f64, e: f64| {
        format!("[[measurement]]\nname = \"{name}\"\nspeed = {speed}\n[[measurement.scalar]]\nobservable = \"restitution\"\nvalue = {e}\nsigma = 0.01\n")
    };
    let head = "level = \"bounce\"\nfree = [\"shell_damping\"]\n[bounce]\nshell_damping = 5000.0\n";
    std::fs::write(&spec, format!("{head}{}{}", test("slow", 6.264, 0.84), test("cannon", 300.0, 0.77))).unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let (stdout, stderr) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    let says = "measurement `cannon`: outside the validity of law `shell`: δ_max = 0.20809 m exceeds R/2 = 0.055 m";
    assert!(stdout.contains(&format!("status outside validity: {says}")), "{stdout}");
    assert!(
        stderr.contains("the result above is a fit with a contact outside its law's validity at the estimate") && stderr.contains(says),
        "{stderr}"
    );
    let out = kick(&["fit", "data", spec.to_str().unwrap(), "--format", "json"]);
    assert_eq!(out.status.code(), Some(1));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(report["outside_validity"][0]["measurement"], "cannon");
    let beta = report["estimates"][0]["value"].as_f64().unwrap();
    let out = kick(&["bounce", "--speed", "300", "--shell-damping", &beta.to_string()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("δ_max = 0.20809 m exceeds R/2 = 0.055 m"));
    // Without the cannon: no status line, exit 0.
    std::fs::write(&spec, format!("{head}{}", test("slow", 6.264, 0.84))).unwrap();
    let out = kick(&["fit", "data", spec.to_str().unwrap()]);
    assert!(out.status.success() && !String::from_utf8_lossy(&out.stdout).contains("outside validity"));
    std::fs::remove_dir_all(&dir).ok();
}

/// `--spread` is held to (1, 10], named: 1e300 made a foot of 1e-300 kg,
/// refused naming foot_mass and foot_speed, never given; at 10 the profile
/// runs (its far points' contacts outlast the history limit at the data's
/// interval, and are recorded coarser instead of refused).
#[test]
fn the_profile_spread_is_bounded_and_its_far_points_run() {
    for spread in ["1e300", "1", "NaN", "10.5"] {
        let out = kick(&["fit", "profile", "--spread", spread, "--points", "3", "--map-points", "3"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{spread}: {stderr}");
        assert!(stderr.contains(&format!("--spread {spread}: must be in (1, 10]")), "{stderr}");
    }
    let out = kick(&["fit", "profile", "--spread", "10", "--points", "3", "--map-points", "3"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}
