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
    let data = kick_runner::SweepData::read(&dir.join("small.h5")).unwrap();
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
    let _ = std::fs::remove_dir_all(&dir);
}
