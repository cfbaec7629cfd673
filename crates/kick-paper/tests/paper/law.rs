//! Experiment files choose the contact law for all their scenarios.

use kick_core::LawKind;
use std::path::Path;

#[test]
fn an_experiment_file_sets_the_law_of_every_scenario() {
    let text = "name = \"hc\"\nsolver = \"auto\"\nlaw = \"hunt-crossley\"\nrestitution = 0.7\n\n[[sweep]]\nparameter = \"foot_mass\"\nvalues = [1.0, 3.0, 8.0]\n";
    let experiment = kick_study::experiment::parse(Path::new("hc.toml"), text).unwrap();
    for i in 0..experiment.one_d().unwrap().scenarios.len() {
        let scenario = experiment.one_d().unwrap().scenarios.scenario(i).unwrap();
        assert_eq!(scenario.law_kind(), LawKind::HuntCrossley);
        assert_eq!(scenario.restitution_target(), Some(0.7));
    }
}

#[test]
fn a_bad_law_names_the_file_line_and_key() {
    let text = "name = \"hc\"\nlaw = \"rubber\"\n";
    let error = kick_study::experiment::parse(Path::new("bad.toml"), text).unwrap_err().to_string();
    assert!(error.contains("bad.toml:2") && error.contains("law") && error.contains("rubber"), "{error}");
    let text = "name = \"hc\"\nlaw = \"flores\"\n";
    let error = kick_study::experiment::parse(Path::new("bad.toml"), text).unwrap_err().to_string();
    assert!(error.contains("restitution"), "{error}");
}

/// The target restitution is a declared parameter: a file whose law takes
/// one has it as a column in place of `damping` (the paper's law has none).
#[test]
fn the_target_restitution_is_a_parameter_column() {
    let dir = crate::scratch("law");
    for (law, expected) in [("law = \"flores\"\nrestitution = 0.7\n", Some(0.7)), ("", None)] {
        let text = format!("name = \"e\"\n{law}[[sweep]]\nparameter = \"foot_mass\"\nvalues = [1.0, 3.0]\n");
        let experiment = kick_study::experiment::parse(Path::new("e.toml"), &text).unwrap();
        let path = kick_store::run(&experiment, &dir, false).unwrap().path;
        let data = kick_store::SweepData::read(&path).unwrap();
        // A file stores the parameters its law uses: flores takes no `damping` (its restitution sets it).
        for p in kick_core::Parameter::ALL.into_iter().filter(|&p| expected.is_none() || p != kick_core::Parameter::Damping) {
            assert_eq!(data.parameter(p.name()).unwrap().len(), 2);
        }
        if expected.is_some() {
            assert!(data.parameter("damping").is_err());
        }
        match expected {
            Some(e) => assert_eq!(data.parameter("restitution").unwrap(), &[e, e]),
            None => assert!(data.parameter("restitution").is_err()),
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
