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
        "fit", "synthesize", "--out", dir.to_str().unwrap(), "--name", "hc", "--seed", "4", "--law", "hunt-crossley-exact",
        "--restitution", "0.66", "--time-offset", "2e-4",
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
        assert_eq!(
            names,
            ["power-law", "hunt-crossley", "lankarani-nikravesh", "flores", "hunt-crossley-exact", "kelvin-voigt"]
        );
        // χ from the exact relation reproduces the paper's law's restitution.
        let e = |i: usize| runs[i]["outcome"]["restitution"].as_f64().unwrap();
        assert!((e(4) - e(0)).abs() < 1e-8, "{}: {} vs {}", c["name"], e(4), e(0));
    }
    let out = kick(&["laws", "--samples", "1"]);
    assert!(!out.status.success());
}

/// `kick laws --out` writes laws.h5; read back, every number equals an
/// independent solve: each law's outcomes on each row (the scenario rebuilt
/// from the file's parameters and target, `Scenario::with_law`, `Accurate`),
/// its pulse (the same solve's recorded forces), the target (the paper's
/// law's restitution), and the restitution table against the closed form of
/// the hysteresis laws (kick_core::laws::exact_restitution) to 1e-8.
#[test]
fn laws_h5_equals_independent_solves() {
    use kick_core::laws::{AnyLaw, LawKind};
    use kick_core::{Parameter, RecordingSolver, Scenario, Solver};
    let dir = scratch("laws-h5");
    let samples = 50.0;
    let out = kick(&["laws", "--samples", "50", "--out", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(dir.join("laws.png").exists() && dir.join("laws.svg").exists() && !dir.join("laws.json").exists());
    let path = dir.join("laws.h5");
    let data = kick_runner::SweepData::read(&path).unwrap();
    let solver = kick_compliant::Accurate::default();
    let names = data.names.clone().unwrap();
    assert_eq!(names.len(), 8);
    assert_eq!(data.sets.len(), LawKind::ALL.len());
    let target = data.parameter("target_restitution").unwrap();
    for row in 0..names.len() {
        let values = Parameter::ALL.map(|p| data.parameter(p.name()).unwrap()[row]);
        let scenario = Scenario::from_values(values).unwrap();
        assert_eq!(target[row], solver.solve(&scenario).unwrap().restitution, "{}", names[row]);
        for kind in LawKind::ALL {
            let s = scenario.with_law(kind, Some(target[row])).unwrap();
            let (o, history) = solver.solve_recorded(&s, s.elastic_contact_time() / samples).unwrap();
            let set = data.set(kind.name()).unwrap();
            assert_eq!(set.status[row], 0);
            for (name, value) in kick_core::OBSERVABLES.iter().zip(o.observable_values()) {
                assert_eq!(set.column(name.0).unwrap()[row], value, "{} {} {}", names[row], kind.name(), name.0);
            }
            let law = s.contact_law();
            assert_eq!(set.column("onset_force").unwrap()[row], kick_core::ContactLaw::onset_force(&law, s.approach_speed()));
            match law {
                AnyLaw::Hysteresis(h) => assert_eq!(set.column("hysteresis").unwrap()[row], h.hysteresis),
                AnyLaw::KelvinVoigt(k) => assert_eq!(set.column("linear_damping").unwrap()[row], k.damping),
                AnyLaw::PowerLaw(_) => assert!(set.column("hysteresis").is_none()),
            }
            let pulse = kick_runner::h5::read_history(&path, &set.group, row).unwrap();
            let force = &pulse.iter().find(|(c, _)| c.name == "force").unwrap().1;
            let time = &pulse.iter().find(|(c, _)| c.name == "time").unwrap().1;
            assert_eq!(force, &history.samples.iter().map(|x| x.force).collect::<Vec<_>>());
            assert_eq!(time, &history.samples.iter().map(|x| x.time).collect::<Vec<_>>());
        }
    }
    let file = kick_runner::ResultFile::open(&path).unwrap();
    let targets = file.values("restitution_formulas/target_restitution").unwrap();
    let baseline = Scenario::baseline();
    for kind in kick_identify::laws::RESTITUTION_LAWS {
        let (column, values) = file.column(&format!("restitution_formulas/{}", kind.name())).unwrap();
        assert_eq!(column.unit, "1");
        for (&e, &simulated) in targets.iter().zip(&values) {
            let law = baseline.with_law(kind, Some(e)).unwrap().contact_law();
            let expected = match law {
                AnyLaw::Hysteresis(h) => h.exact_restitution(baseline.approach_speed()).unwrap(),
                // Clamped Kelvin–Voigt: checked against its closed form in kick-identify/tests/identify/laws.rs.
                _ => solver.solve(&baseline.with_law(kind, Some(e)).unwrap()).unwrap().restitution,
            };
            assert!((simulated - expected).abs() < 1e-8, "{} e={e}: {simulated} vs {expected}", kind.name());
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `kick fit data --out` and `kick fit profile --out`: the files read back
/// equal independent computations — the report's predictions are the
/// forward model at the stored estimates, and each stored profile point's χ²
/// is the misfit at the stored parameters against data regenerated from the
/// stored seed and noise.
#[test]
fn fit_and_profile_h5_equal_independent_computations() {
    use kick_core::{Parameter, Scenario};
    use kick_identify::data::{Channel, FitSpec};
    use kick_identify::{FitParameter, ModelPoint};
    let dir = scratch("fit-h5");
    let d = dir.to_str().unwrap();
    for args in [
        vec!["fit", "synthesize", "--out", d, "--name", "s", "--seed", "9", "--times", "40", "--law", "flores", "--restitution", "0.7", "--time-offset", "1e-4"],
        vec!["fit", "data", &format!("{d}/s.toml"), "--out", &format!("{d}/s_fit.h5")],
        vec!["fit", "profile", "--out", d, "--points", "3", "--map-points", "3", "--spread", "1.2"],
    ] {
        let out = kick(&args);
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
    // The fit report: predictions at the stored estimates.
    let file = kick_runner::ResultFile::open(&dir.join("s_fit.h5")).unwrap();
    assert_eq!(file.text("", "layout").unwrap(), "kick-fit-1");
    assert_eq!(file.text("fit", "law").unwrap(), "flores");
    let (spec, observations) = FitSpec::load(&dir.join("s.toml")).unwrap();
    let mut point = spec.start("s.toml").unwrap();
    for name in file.strings("fit/parameters").unwrap() {
        let p = FitParameter::from_name(&name).unwrap();
        let (column, value) = file.column(&format!("fit/estimates/{name}/value")).unwrap();
        assert_eq!(column.unit, p.unit());
        let truth = file.scalar(&format!("fit/estimates/{name}/truth")).unwrap();
        let sigma = file.scalar(&format!("fit/estimates/{name}/standard_uncertainty")).unwrap();
        assert!((value[0] - truth).abs() < 3.0 * sigma, "{name}: {} ± {sigma} vs {truth}", value[0]);
        point = point.with(p, value[0]).unwrap();
    }
    let predicted = kick_identify::model::predict(&kick_compliant::Accurate::default(), &point, &observations).unwrap();
    let h = observations.history.as_ref().unwrap();
    for (k, (channel, _)) in h.data.channels.iter().enumerate() {
        let g = format!("fit/residuals/{}", channel.name());
        assert_eq!(file.values(&format!("{g}/time")).unwrap(), h.data.times);
        let (column, stored) = file.column(&format!("{g}/predicted")).unwrap();
        assert_eq!(column.unit, channel.unit());
        let sigma = h.sigma[channel];
        for (i, v) in stored.iter().enumerate() {
            let independent = predicted[k * h.data.times.len() + i];
            // Stored as observed + weighted·σ: rounding of that sum only.
            assert!((v - independent).abs() <= 1e-9 * sigma, "{} {i}: {v} vs {independent}", channel.name());
        }
    }

    // The profiles: regenerate the data from the stored settings, recompute χ².
    let file = kick_runner::ResultFile::open(&dir.join("identifiability.h5")).unwrap();
    let values = Parameter::ALL.map(|p| file.scalar(&format!("truth/{}", p.name())).unwrap());
    let truth = ModelPoint::from(Scenario::from_values(values).unwrap());
    let seed = file.scalar("settings/seed").unwrap() as u64;
    let times = file.scalar("settings/history_times").unwrap() as usize;
    let sigma = Channel::ALL.iter().map(|&c| (c, file.scalar(&format!("history_sigma/{}", c.name())).unwrap())).collect();
    let solver = kick_compliant::Accurate::default();
    let grid = kick_identify::synthetic::time_grid(&truth.scenario, times, 1.2);
    let data = kick_identify::synthetic::history(&solver, &truth, grid, &sigma, seed).unwrap();
    let names = file.strings("profiles/histories/parameters").unwrap();
    assert_eq!(names, ["foot_mass", "stiffness", "damping", "exponent"]);
    for name in &names {
        let g = format!("profiles/histories/{name}");
        let p = FitParameter::from_name(name).unwrap();
        let value = file.values(&format!("{g}/value")).unwrap();
        let chi_square = file.values(&format!("{g}/chi_square")).unwrap();
        for (i, (&v, &chi)) in value.iter().zip(&chi_square).enumerate() {
            let mut at = truth.with(p, v).unwrap();
            for other in file.members(&format!("{g}/others")).unwrap() {
                let q = FitParameter::from_name(&other).unwrap();
                let factor = file.values(&format!("{g}/others/{other}")).unwrap()[i];
                at = at.with(q, truth.get(q).unwrap() * factor).unwrap();
            }
            let independent = kick_identify::fit::misfit(&solver, &at, &data).unwrap();
            // The factors are stored as value/truth: rebuilding loses ~1e-16
            // relative per parameter, which moves χ² near its minimum by far less than 1e-6.
            assert!((chi - independent).abs() <= 1e-6 * chi.max(1.0), "{name} point {i}: {chi} vs {independent}");
        }
    }
    assert!(dir.join("identifiability.png").exists() && !dir.join("identifiability.json").exists());
    std::fs::remove_dir_all(&dir).ok();
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
