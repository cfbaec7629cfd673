//! `kick run` and `kick reproduce`: exit codes, located errors, files written.

use std::path::PathBuf;
use crate::kick;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kick-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn run_rejects_a_bad_file_naming_line_and_key() {
    let dir = scratch("bad");
    let file = dir.join("bad.toml");
    std::fs::write(&file, "solver = \"accurate\"\n\n[base]\nfoot_mas = 3.0\n").unwrap();
    let out = kick(&["run", file.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("bad.toml:4:1: `foot_mas`"), "{stderr}");
    assert!(!dir.join("bad.h5").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn run_writes_the_named_file() {
    let dir = scratch("good");
    let file = dir.join("small.toml");
    std::fs::write(&file, "[[sweep]]\nparameter = \"damping\"\nvalues = [0.0, 120.0]\n").unwrap();
    let out = kick(&["run", file.to_str().unwrap(), "--out", dir.to_str().unwrap(), "--threads", "1"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let data = kick_store::SweepData::read(&dir.join("small.h5")).unwrap();
    assert_eq!(data.parameter("damping").unwrap(), [0.0, 120.0]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn reproduce_writes_results_figures_and_report() {
    let dir = scratch("reproduce");
    let results = dir.join("results");
    let report = dir.join("paper/README.md");
    let out = kick(&["reproduce", "--quick-bench", "--out", results.to_str().unwrap(), "--report", report.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for name in ["table2", "figure1", "figure2", "figure3", "figure4", "figure5", "figure6", "figure7"] {
        assert!(results.join(format!("{name}.h5")).exists(), "{name}.h5");
    }
    let text = std::fs::read_to_string(&report).unwrap();
    for n in 1..=7 {
        assert!(results.join(format!("figures/figure{n}.png")).exists());
        assert!(text.contains(&format!("figures/figure{n}.png)")), "figure {n} not embedded");
    }
    assert!(text.contains("## Cross-model checks") && text.contains("| Check | Equation |"));
    // What depends on the clock is in results/timing and paper/timing.md only.
    assert!(results.join("timing/work_precision.h5").exists() && !results.join("work_precision.h5").exists());
    let timing = std::fs::read_to_string(dir.join("paper/timing.md")).unwrap();
    assert!(timing.contains("µs per scenario") && timing.contains("cores available"), "{timing}");
    // The sweeps into files, plain and compressed, measured on the same page.
    for command in ["`kick sweep --samples 2000 --seed 1 --threads 2 --out sweep.h5`", "`kick sweep3d --samples 200 --seed 1 --threads 2 --out sweep3d.h5 --compress 4`"] {
        assert!(timing.contains("## Sweeps into result files") && timing.contains(command), "{command}: {timing}");
    }
    let solvers = std::fs::read_to_string(dir.join("paper/solvers.md")).unwrap();
    assert!(!solvers.contains("µs per scenario") && !solvers.contains("scenarios/s"), "{solvers}");
    assert!(solvers.contains("evaluations per scenario") && solvers.contains("(timing.md)"), "{solvers}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn table2_works_outside_the_repository_from_the_built_in_file() {
    let dir = scratch("outside");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kick")).arg("table2").current_dir(&dir).output().expect("kick runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // The baseline row as printed in the paper (Table 2) and reproduced by seed-rk4.
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("31.98") && text.contains("3804"), "{text}");
    // `kick laws` reads the same scenarios, from anywhere.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kick")).args(["laws", "--samples", "20"]).current_dir(&dir).output().expect("kick runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains("Very soft ball"), "{}", String::from_utf8_lossy(&out.stdout));
    // A file on disk overrides the built-in one.
    std::fs::create_dir_all(dir.join("experiments")).unwrap();
    std::fs::write(dir.join("experiments/table2.toml"), "not = [valid").unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kick")).arg("table2").current_dir(&dir).output().expect("kick runs");
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("experiments/table2.toml"), "{}", String::from_utf8_lossy(&out.stderr));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kick")).arg("laws").current_dir(&dir).output().expect("kick runs");
    assert!(!out.status.success() && String::from_utf8_lossy(&out.stderr).contains("experiments/table2.toml"));
    let _ = std::fs::remove_dir_all(&dir);
}
