//! `kick reproduce --check` on a small experiment: a second run writes the
//! same bytes, and a changed value, page or stale file is named.

use kick_paper::reproduce::{check, list, reproduce, ReproduceSettings, Steps};
use std::path::{Path, PathBuf};

const SMALL: &str = r#"
description = "two stiffnesses, two solvers"
solvers = ["accurate", "seed-rk4"]
dt = 5e-6

[base]
foot_mass = 2.5

[[sweep]]
parameter = "stiffness"
values = [3e5, 6e5]
"#;

fn setup(name: &str) -> (PathBuf, ReproduceSettings) {
    let dir = crate::scratch(&format!("check-{name}"));
    std::fs::create_dir_all(dir.join("experiments")).unwrap();
    std::fs::write(dir.join("experiments/small.toml"), SMALL).unwrap();
    let settings = ReproduceSettings {
        experiments: dir.join("experiments"),
        out: dir.join("results"),
        report: dir.join("paper/README.md"),
        quick_bench: true,
        steps: Steps::only(&["experiments"]),
    };
    reproduce(&settings, &mut std::io::sink()).expect("first run");
    (dir, settings)
}

fn differences(settings: &ReproduceSettings) -> Vec<(PathBuf, String)> {
    check(settings, &mut std::io::sink()).expect("check runs").differences.into_iter().map(|d| (d.file, d.what)).collect()
}

#[test]
fn a_second_run_writes_the_same_bytes() {
    let (dir, settings) = setup("bytes");
    let file = dir.join("results/small.h5");
    let first = std::fs::read(&file).unwrap();
    // Past a second: a wall-clock stamp (provenance or HDF5's object times) would change.
    std::thread::sleep(std::time::Duration::from_millis(1100));
    reproduce(&settings, &mut std::io::sink()).expect("second run");
    assert!(std::fs::read(&file).unwrap() == first, "a second run changed the bytes of small.h5");
    assert_eq!(differences(&settings), []);
    let _ = std::fs::remove_dir_all(&dir);
}

fn set_value(path: &Path, dataset: &str, index: usize, value: f64) {
    let file = hdf5::File::open_rw(path).unwrap();
    let d = file.dataset(dataset).unwrap();
    let mut values = d.read_raw::<f64>().unwrap();
    values[index] = value;
    d.write_raw(&values).unwrap();
}

#[test]
fn check_names_every_file_and_dataset_that_differs() {
    let (dir, settings) = setup("differ");
    let file = dir.join("results/small.h5");
    set_value(&file, "parameters/stiffness", 1, 6.5e5);
    set_value(&file, "solvers/seed-rk4/outcomes/contact_time", 0, 1.0);
    std::fs::write(dir.join("results/stale.h5"), b"old").unwrap();
    let found = differences(&settings);
    let about = |needle: &str| found.iter().any(|(f, what)| f == &file && what.contains(needle));
    assert!(about("dataset /parameters/stiffness: 1 of 2 values differ; first at index 1: committed 6.5e5, regenerated 6e5"), "{found:?}");
    assert!(about("dataset /solvers/seed-rk4/outcomes/contact_time: 1 of 2 values differ; first at index 0"), "{found:?}");
    assert!(found.iter().any(|(f, what)| f == &dir.join("results/stale.h5") && what.contains("no longer written")), "{found:?}");
    assert_eq!(found.len(), 3, "{found:?}");
    // The committed files are left as they were.
    assert_eq!(std::fs::read(dir.join("results/stale.h5")).unwrap(), b"old");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The steps run in their one order whatever order `--only` names them in,
/// each under the command line made from its call's arguments; a name that
/// is not a step is refused naming `--only` and every step; `--only checks`
/// writes no file and still counts the checks.
#[test]
fn only_runs_the_named_steps_in_order() {
    let (dir, mut settings) = setup("only");
    settings.steps = Steps::only(&["checks", "experiments"]);
    let listed = list(&settings).expect("list").steps;
    let small = dir.join("experiments/small.toml");
    let expected = [
        ("experiments".to_string(), vec![format!("kick run {} --out {}", small.display(), dir.join("results").display())]),
        ("checks".to_string(), vec!["kick check".to_string()]),
    ];
    assert_eq!(listed, expected);

    settings.steps = Steps::only(&["checks", "chekcs"]);
    let error = reproduce(&settings, &mut std::io::sink()).expect_err("an unknown step");
    assert!(matches!(error, kick_paper::PaperError::Study(kick_study::StudyError::Flag { flag: "--only", .. })), "{error:?}");
    let error = error.to_string();
    assert!(error.starts_with("--only: no step `chekcs`"), "{error}");
    assert!(kick_paper::reproduce::step_names().iter().all(|name| error.contains(name)), "{error}");

    let _ = std::fs::remove_dir_all(dir.join("results"));
    settings.steps = Steps::only(&["checks"]);
    let mut log = Vec::new();
    let done = reproduce(&settings, &mut log).expect("checks");
    assert_eq!(done.checks, kick_study::checks::run_all().rows.len());
    assert!(String::from_utf8_lossy(&log).starts_with("\n# kick check\nchecks: "), "{}", String::from_utf8_lossy(&log));
    assert!(!dir.join("results").exists() && !settings.report.exists());
    let _ = std::fs::remove_dir_all(&dir);
}
