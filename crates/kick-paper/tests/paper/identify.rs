//! `kick laws` and `kick fit` as library calls: the files they write read
//! back equal independent computations.

use crate::scratch;
use kick_paper::identify::{LawsSettings, ProfileSettings};
use std::path::PathBuf;

fn experiments() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../experiments")
}

/// `identify::laws` (`kick laws --out`) writes laws.h5; read back, every number equals an
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
    let settings = LawsSettings { scenarios: experiments().join("table2.toml"), out: Some(dir.clone()), samples: 50 };
    kick_paper::identify::laws(&settings).unwrap();
    assert!(dir.join("laws.png").exists() && dir.join("laws.svg").exists() && !dir.join("laws.json").exists());
    let path = dir.join("laws.h5");
    let data = kick_store::SweepData::read(&path).unwrap();
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
                // Not in LawKind::ALL, the family `kick laws` compares.
                AnyLaw::Shell(_) => unreachable!("kick laws compares LawKind::ALL, which leaves out the shell"),
            }
            let pulse = kick_store::h5::read_history(&path, &set.group, row).unwrap();
            let force = &pulse.iter().find(|(c, _)| c.name == "force").unwrap().1;
            let time = &pulse.iter().find(|(c, _)| c.name == "time").unwrap().1;
            assert_eq!(force, &history.samples.iter().map(|x| x.force).collect::<Vec<_>>());
            assert_eq!(time, &history.samples.iter().map(|x| x.time).collect::<Vec<_>>());
        }
    }
    let file = kick_store::ResultFile::open(&path).unwrap();
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

/// `identify::data` and `identify::profile` (`kick fit data --out`, `kick fit profile --out`): the files read back
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
    // `kick fit synthesize --law flores --restitution 0.7 --seed 9 --times 40 --time-offset 1e-4`,
    // `kick fit data s.toml --out s_fit.h5`, `kick fit profile --points 3 --map-points 3 --spread 1.2` (seed 5).
    let flores = kick_core::ScenarioSpec::default().with_law_keys(Some(kick_core::LawKind::Flores), Some(0.7)).unwrap();
    kick_paper::identify::synthesize(&dir, "s", 9, 40, &flores, 1e-4, None).unwrap();
    kick_paper::identify::data(&dir.join("s.toml"), Some(&dir.join("s_fit.h5"))).unwrap();
    let settings = ProfileSettings { out: Some(dir.clone()), spread: 1.2, points: 3, map_points: 3, seed: 5 };
    kick_paper::identify::profile(&settings).unwrap();
    // The fit report: predictions at the stored estimates.
    let file = kick_store::ResultFile::open(&dir.join("s_fit.h5")).unwrap();
    assert_eq!(file.text("", "layout").unwrap(), "kick-fit");
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
    let file = kick_store::ResultFile::open(&dir.join("identifiability.h5")).unwrap();
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

/// `kick fit synthesize --also-fit-law power-law` on Hunt–Crossley data
/// (as `kick reproduce` runs it for paper/identification.md): the data's own
/// law fits them with s² inside 1 ± 4√(2/ν), the paper's law leaves s² > 10
/// (model error), and the second specification lists no true value for the
/// paper law's parameters (they have none), only t0; its own law is refused.
#[test]
fn a_wrong_law_leaves_model_error_in_s2() {
    use kick_core::LawKind;
    let dir = scratch("wrong-law");
    let hunt_crossley = kick_core::ScenarioSpec::default().with_law_keys(Some(LawKind::HuntCrossleyExact), Some(0.66)).unwrap();
    let written = kick_paper::identify::synthesize(&dir, "hc", 2, 80, &hunt_crossley, 2.5e-4, Some(LawKind::PowerLaw)).unwrap();
    let other = written.other_law_spec.clone().unwrap();
    assert_eq!(other, dir.join("hc_as_power_law.toml"));
    let text = std::fs::read_to_string(&other).unwrap();
    let truth = text.split("[truth]").nth(1).unwrap();
    assert!(truth.contains("time_offset = 2.5e-4") && !truth.contains("stiffness") && !truth.contains("restitution"), "{text}");
    assert!(!text.contains("law = ") && text.contains("\"damping\"") && text.contains("file = \"hc.csv\""), "{text}");
    let right = kick_paper::identify::data(&written.spec, None).unwrap().report;
    let wrong = kick_paper::identify::data(&other, None).unwrap().report;
    assert!(right.converged && wrong.converged);
    let band = |nu: f64| 4.0 * (2.0 / nu).sqrt();
    let s2 = right.residual_variance.unwrap();
    assert!((s2 - 1.0).abs() < band(right.degrees_of_freedom as f64), "right law: s² = {s2}");
    let s2 = wrong.residual_variance.unwrap();
    assert!(s2 > 10.0, "the paper's law on Hunt–Crossley data: s² = {s2}");
    let refused = kick_paper::identify::synthesize(&dir, "hc2", 2, 80, &hunt_crossley, 0.0, Some(LawKind::HuntCrossleyExact));
    let refused = refused.unwrap_err();
    assert!(matches!(refused, kick_store::StoreError::Flag { flag: "--also-fit-law", .. }), "{refused:?}");
    assert!(refused.to_string().contains("--also-fit-law hunt-crossley-exact"), "{refused}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `kick fit table2 --out` goes through the outputs' one check before any
/// fit: an output that is the scenario file (or a second name of it), that
/// does not end in `.h5`, or that is a directory is refused naming `--out`,
/// and the scenario file is left as it was.
#[test]
fn fit_table2_out_refuses_an_input_a_wrong_extension_and_a_directory() {
    let dir = scratch("fit-table2-out");
    let scenarios = dir.join("table2.toml");
    std::fs::copy(experiments().join("table2.toml"), &scenarios).unwrap();
    let before = std::fs::read(&scenarios).unwrap();
    let link = dir.join("same.h5");
    std::fs::hard_link(&scenarios, &link).unwrap();
    let subdirectory = dir.join("out.h5");
    std::fs::create_dir(&subdirectory).unwrap();
    for (out, says) in [
        (scenarios.clone(), "must end in `.h5`"),
        (dir.join("fit.csv"), "must end in `.h5`"),
        (link.clone(), "is the input"),
        (subdirectory.clone(), "is a directory"),
    ] {
        let error = kick_paper::identify::table2(None, Some(&out), &scenarios).map(|_| ()).unwrap_err().to_string();
        assert!(error.contains("--out") && error.contains(says), "{}: {error}", out.display());
        assert_eq!(std::fs::read(&scenarios).unwrap(), before, "{}", out.display());
    }
    assert!(!dir.join("fit.csv").exists());
}
