//! The runner end to end: experiment files in, HDF5 files out, read back with
//! the hdf5 crate and compared with solves that do not go through the runner.

use crate::scratch;
use kick_compliant::{closed, Accurate, SeedRk4};
use kick_core::{Parameter, Scenario, Solver, OBSERVABLES};
use kick_store::h5::{read_f64_attr, read_str_attr, CHUNK_ROWS};
use kick_study::experiment::{self, linear_range, log_range};
use std::path::{Path, PathBuf};

fn write_experiment(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).expect("write experiment");
    path
}

fn run(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = write_experiment(dir, name, text);
    let experiment = experiment::load(&path).expect("valid experiment");
    kick_store::run(&experiment, &dir.join("out"), false).expect("run").path
}

fn read(file: &hdf5::File, name: &str) -> Vec<f64> {
    file.dataset(name).and_then(|d| d.read_raw::<f64>()).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Every dataset below `group`, recursively, with its path.
fn datasets(group: &hdf5::Group, prefix: &str, out: &mut Vec<(String, hdf5::Dataset)>) {
    for name in group.member_names().expect("members") {
        let path = format!("{prefix}/{name}");
        if let Ok(d) = group.dataset(&name) {
            out.push((path, d));
        } else if let Ok(g) = group.group(&name) {
            datasets(&g, &path, out);
        }
    }
}

const GRID: &str = r#"
description = "grid for the read-back test"
solvers = ["accurate", "seed-rk4"]
dt = 5e-6

[base]
foot_mass = 2.5

[[sweep]]
parameter = "stiffness"
log = { from = 2e5, to = 8e5, count = 3 }

[[sweep]]
parameter = "damping"
values = [0.0, 120.0]
"#;

#[test]
fn result_file_reads_back_against_independent_solves() {
    let dir = scratch("readback");
    let path = run(&dir, "grid", GRID);
    assert_eq!(path, dir.join("out/grid.h5"));
    let file = hdf5::File::open(&path).expect("open");

    // Provenance.
    assert_eq!(read_str_attr(&file, "tool").as_deref(), Some("kick"));
    assert_eq!(read_str_attr(&file, "tool_version").as_deref(), Some(env!("CARGO_PKG_VERSION")));
    assert_eq!(read_str_attr(&file, "experiment_text").as_deref(), Some(GRID));
    assert_eq!(read_str_attr(&file, "experiment").as_deref(), Some("grid"));
    assert_eq!(read_str_attr(&file, "solver").as_deref(), Some("accurate"));
    let accurate = Accurate::default();
    assert_eq!(read_f64_attr(&file, "relative_tolerance"), Some(accurate.relative_tolerance));
    assert_eq!(read_f64_attr(&file, "absolute_tolerance"), Some(accurate.absolute_tolerance));
    // Deterministic: no wall-clock time.
    assert!(read_str_attr(&file, "created_utc").is_none());
    if let Some(commit) = read_str_attr(&file, "git_commit") {
        assert!(commit.len() == 40 && commit.chars().all(|c| c.is_ascii_hexdigit()), "{commit}");
    }
    if let Ok(dirty) = file.attr("git_dirty") {
        assert!(dirty.read_scalar::<u64>().unwrap() <= 1);
    }
    let seed_group = file.group("solvers/seed-rk4").expect("second solver");
    assert_eq!(read_f64_attr(&seed_group, "dt"), Some(5e-6));
    // Settings are typed attributes, one per field, not Debug text.
    for group in [&*file, &*seed_group] {
        assert_eq!(read_str_attr(group, "law").as_deref(), Some("power-law"));
        assert!(group.attr("solver_settings").is_err());
    }

    // Every dataset carries units.
    let mut all = Vec::new();
    datasets(&file, "", &mut all);
    assert!(all.len() >= 8 + 2 * (OBSERVABLES.len() + 1 + 2));
    for (name, dataset) in &all {
        assert!(read_str_attr(dataset, "units").is_some(), "{name} has no units");
    }

    // Parameters: the grid, last axis fastest.
    let stiffness = log_range(2e5, 8e5, 3);
    let mut expected_rows = Vec::new();
    for &k in &stiffness {
        for c in [0.0, 120.0] {
            expected_rows.push(
                Scenario::baseline()
                    .with(Parameter::FootMass, 2.5)
                    .unwrap()
                    .with(Parameter::Stiffness, k)
                    .unwrap()
                    .with(Parameter::Damping, c)
                    .unwrap(),
            );
        }
    }
    for p in Parameter::ALL {
        let column = read(&file, &format!("parameters/{}", p.name()));
        let unit = read_str_attr(&file.dataset(&format!("parameters/{}", p.name())).unwrap(), "units");
        assert_eq!(unit.as_deref(), Some(p.unit()));
        let expected: Vec<f64> = expected_rows.iter().map(|s| s.get(p)).collect();
        assert_eq!(column, expected, "parameter {}", p.name());
    }

    // Outcomes: the same solvers called directly give the same bits.
    let seed = SeedRk4::new(5e-6).unwrap();
    for (group, solver) in [("outcomes", &accurate as &dyn Solver), ("solvers/seed-rk4/outcomes", &seed)] {
        let status: Vec<u8> = file.dataset(&format!("{group}/status")).unwrap().read_raw().unwrap();
        assert_eq!(status, vec![0; 6]);
        for (j, (name, unit)) in OBSERVABLES.iter().enumerate() {
            let dataset = file.dataset(&format!("{group}/{name}")).unwrap();
            assert_eq!(read_str_attr(&dataset, "units").as_deref(), Some(*unit));
            let stored: Vec<f64> = dataset.read_raw().unwrap();
            for (row, scenario) in expected_rows.iter().enumerate() {
                let direct = solver.solve(scenario).unwrap().observable_values()[j];
                assert_eq!(stored[row].to_bits(), direct.to_bits(), "{group}/{name} row {row}");
            }
        }
    }

    // And against the closed form (Eq. 33, c = 0): the accurate solver's
    // stated 1e-9 relative accuracy.
    let v_ball = read(&file, "outcomes/v_ball_out");
    for (row, scenario) in expected_rows.iter().enumerate().filter(|(_, s)| s.paper_law().damping == 0.0) {
        let exact = closed::elastic(scenario).expect("c = 0 has a closed form").unwrap();
        let error = (v_ball[row] - exact.v_ball_out).abs() / exact.v_ball_out;
        assert!(error < 1e-9, "row {row}: relative error {error:e}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn same_numbers_for_one_and_two_threads() {
    // More rows than one chunk, so the chunk boundary is crossed.
    let rows = CHUNK_ROWS + 904;
    let text = format!(
        r#"
solver = "accurate"
[[sweep]]
parameter = "foot_mass"
log = {{ from = 0.5, to = 20.0, count = {rows} }}
"#
    );
    let dir = scratch("threads");
    let mut files = Vec::new();
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let sub = dir.join(format!("t{threads}"));
        std::fs::create_dir_all(&sub).unwrap();
        files.push(pool.install(|| run(&sub, "sweep", &text)));
    }
    let (a, b) = (hdf5::File::open(&files[0]).unwrap(), hdf5::File::open(&files[1]).unwrap());
    let (mut da, mut db) = (Vec::new(), Vec::new());
    datasets(&a, "", &mut da);
    datasets(&b, "", &mut db);
    assert_eq!(da.iter().map(|d| &d.0).collect::<Vec<_>>(), db.iter().map(|d| &d.0).collect::<Vec<_>>());
    for ((name, x), (_, y)) in da.iter().zip(&db) {
        if name.ends_with("/message") {
            continue;
        }
        if name.starts_with("/grid/") {
            // The axes' names and values (not one per row).
            let text =
                |d: &hdf5::Dataset| d.read_raw::<hdf5::types::VarLenUnicode>().map(|v| v.iter().map(|s| s.to_string()).collect::<Vec<_>>());
            let bits = |d: &hdf5::Dataset| d.read_raw::<f64>().map(|v| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>());
            match name.as_str() {
                "/grid/axes" => assert_eq!(text(x).unwrap(), text(y).unwrap()),
                _ => assert_eq!(bits(x).unwrap(), bits(y).unwrap(), "{name}"),
            }
            continue;
        }
        if name.ends_with("/status") || name.ends_with("/index") {
            let (x, y): (Vec<u64>, Vec<u64>) = (x.read_raw().unwrap(), y.read_raw().unwrap());
            assert_eq!(x, y, "{name}");
            continue;
        }
        let (x, y): (Vec<f64>, Vec<f64>) = (x.read_raw().unwrap(), y.read_raw().unwrap());
        assert_eq!(x.len(), rows, "{name}");
        let bits = |v: &[f64]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&x), bits(&y), "{name}");
    }
    // Input order: the foot-mass column is the log range itself.
    assert_eq!(read(&a, "parameters/foot_mass"), log_range(0.5, 20.0, rows));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_failed_scenario_is_recorded_and_the_sweep_goes_on() {
    // 1 MN of drive: the ball turns back before release (no separation).
    let text = r#"
solver = "accurate"
[[sweep]]
parameter = "drive_force"
values = [0.0, 1e6, 500.0]
"#;
    let dir = scratch("failure");
    let path = run(&dir, "fail", text);
    let file = hdf5::File::open(&path).unwrap();
    let status: Vec<u8> = file.dataset("outcomes/status").unwrap().read_raw().unwrap();
    let v = read(&file, "outcomes/v_ball_out");
    assert!(v[0].is_finite() && v[1].is_nan() && v[2].is_finite());
    let index: Vec<u64> = file.dataset("failures/index").unwrap().read_raw().unwrap();
    assert_eq!(index, vec![1]);
    let messages: Vec<hdf5::types::VarLenUnicode> = file.dataset("failures/message").unwrap().read_raw().unwrap();
    let direct = Accurate::default().solve(&Scenario::baseline().with(Parameter::DriveForce, 1e6).unwrap()).unwrap_err();
    // The status is the solver's own (kick_core::Status), not a bare "failed".
    assert_eq!(status, vec![0, direct.status().code(), 0]);
    assert_ne!(direct.status(), kick_core::Status::Separated);
    let direct = direct.to_string();
    assert_eq!(messages[0].as_str(), direct);
    assert!(direct.contains("no separation"), "{direct}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The located error of an experiment text.
fn error_of(text: &str) -> experiment::ExperimentError {
    experiment::parse(Path::new("experiments/bad.toml"), text).expect_err("should be rejected")
}

#[test]
fn bad_files_name_file_line_and_key() {
    let e = error_of("solver = \"accurate\"\n\n[base]\nfoot_mas = 3.0\n");
    assert_eq!((e.file.as_str(), e.line, e.key.as_str()), ("experiments/bad.toml", 4, "foot_mas"), "{e}");
    assert!(e.to_string().starts_with("experiments/bad.toml:4:"), "{e}");

    let e = error_of("colour = 3\n");
    assert_eq!((e.line, e.key.as_str()), (1, "colour"), "{e}");

    let e = error_of("[base]\nfoot_mass = 3.0\nstiffness = -4.2e5\n");
    assert_eq!((e.line, e.key.as_str()), (3, "base.stiffness"), "{e}");
    assert!(e.message.contains("stiffness"), "{e}");

    let e = error_of("[base]\nball_speed = 30.0\n");
    assert_eq!((e.line, e.key.as_str()), (2, "base.ball_speed"), "{e}");

    let e = error_of("[[sweep]]\nparameter = \"foot_mass\"\nvalues = [1.0,\n  -2.0]\n");
    assert_eq!((e.line, e.column, e.key.as_str()), (4, 3, "sweep.foot_mass"), "{e}");
    assert!(e.message.contains("-2"), "{e}");

    let e = error_of("[[sweep]]\nparameter = \"damping\"\nlog = { from = 0.0, to = 100.0, count = 5 }\n");
    assert_eq!((e.line, e.key.as_str()), (3, "sweep.damping"), "{e}");

    let e = error_of("[[sweep]]\nparameter = \"damping\"\nlinear = { from = 0.0, to = 100.0, count = 0 }\n");
    assert_eq!((e.line, e.key.as_str()), (3, "sweep.damping.count"), "{e}");

    let e = error_of("[[sweep]]\nparameter = \"stifness\"\nvalues = [1.0]\n");
    assert_eq!(e.line, 2, "{e}");
    assert!(e.message.contains("stifness"), "{e}");

    let e = error_of("solver = \"rk45\"\n");
    assert_eq!((e.line, e.key.as_str()), (1, "solver"), "{e}");

    let e = error_of("[output]\nmode = \"history\"\n");
    assert_eq!((e.line, e.key.as_str()), (2, "output.interval"), "{e}");

    let e = error_of("dt = -1.0\n");
    assert_eq!((e.line, e.key.as_str()), (1, "dt"), "{e}");

    // Grid points that are invalid only in combination.
    let e = error_of(
        "[[sweep]]\nparameter = \"foot_speed\"\nvalues = [10.0, 20.0]\n\n[[sweep]]\nparameter = \"ball_speed\"\nvalues = [0.0, 15.0]\n",
    );
    assert_eq!(e.key, "sweep", "{e}");
    assert!(e.message.contains("no contact"), "{e}");
}

#[test]
fn ranges_hit_their_ends_and_spacing() {
    let l = linear_range(-20.0, 20.0, 81);
    assert_eq!((l[0], l[40], l[80]), (-20.0, 0.0, 20.0));
    for w in l.windows(2) {
        assert!((w[1] - w[0] - 0.5).abs() < 1e-13);
    }
    let g = log_range(1e5, 1e7, 21);
    assert_eq!((g[0], g[20]), (1e5, 1e7));
    for w in g.windows(2) {
        // Constant ratio 10^(2/20).
        assert!((w[1] / w[0] - 10f64.powf(0.1)).abs() < 1e-12);
    }
    assert_eq!(linear_range(3.0, 7.0, 1), vec![3.0]);
}

#[test]
fn table2_file_runs_both_solvers_and_the_report_explains_the_onset_peak() {
    let dir = scratch("report");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../experiments");
    let out = dir.join("results");
    for name in
        ["table2", "figure1", "figure2", "figure3", "figure3_histories", "figure4", "figure4_histories", "figure5", "figure6", "figure7"]
    {
        let experiment = experiment::load(&root.join(format!("{name}.toml"))).expect(name);
        kick_store::run(&experiment, &out, false).expect(name);
    }
    let data = kick_store::SweepData::read(&out.join("table2.h5")).unwrap();
    assert_eq!(data.sets.iter().map(|s| s.solver.as_str()).collect::<Vec<_>>(), ["seed-rk4", "accurate"]);
    assert_eq!(data.names.as_ref().map(Vec::len), Some(8));
    // The paper's printed values beside the computed ones (Table 2: baseline
    // 31.98 m/s and 3804 N, highly damped 9853 N and 5.10 ms), matched by row.
    let file = kick_store::ResultFile::open(&out.join("table2.h5")).unwrap();
    let names = data.names.as_ref().unwrap();
    let printed = |column: &str, row: &str| file.values(&format!("paper/{column}")).unwrap()[names.iter().position(|n| n == row).unwrap()];
    assert_eq!(printed("v_ball_out", "Baseline"), 31.98);
    assert_eq!(printed("peak_force", "Baseline"), 3804.0);
    assert_eq!(printed("peak_force", "Highly damped"), 9853.0);
    assert_eq!(printed("contact_time_ms", "Highly damped"), 5.10);
    // seed-rk4 reproduces every printed exit speed to its two decimals.
    let computed = data.sets[0].column("v_ball_out").unwrap();
    for (row, v) in computed.iter().enumerate() {
        assert_eq!(format!("{v:.2}"), format!("{:.2}", printed("v_ball_out", &names[row])), "{}", names[row]);
    }

    let figures = kick_paper::figures::draw_all(&out, &out.join("figures")).expect("figures");
    assert_eq!(figures.len(), 14);
    for f in &figures {
        let bytes = std::fs::read(f).unwrap();
        if f.extension().is_some_and(|e| e == "png") {
            assert_eq!(&bytes[1..4], b"PNG", "{}", f.display());
        } else {
            assert!(String::from_utf8_lossy(&bytes).contains("<svg"), "{}", f.display());
        }
    }

    let report_path = dir.join("paper/README.md");
    kick_paper::report::write(&out, "../results/figures", None, &report_path).expect("report");
    let report = std::fs::read_to_string(&report_path).unwrap();
    for n in 1..=7 {
        assert!(report.contains(&format!("](../results/figures/figure{n}.png)")), "figure {n} not embedded");
    }
    // The very soft and highly damped rows peak at onset: F(0+) = c V0 (Eq. 20),
    // 120 x 22 and 450 x 22 N.
    assert!(report.contains(&format!("c·V0 = 120 × 22 = {:.1} N", 120.0 * 22.0)), "{report}");
    assert!(report.contains(&format!("c·V0 = 450 × 22 = {:.1} N", 450.0 * 22.0)), "{report}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A 1D grid keeps its shape as a 3D one does: the root attribute
/// `grid_shape`, `/grid/<axis>` coordinates with units and `/grid/axes`;
/// every row is the cell `values.reshape(grid_shape)` puts there, and the
/// table readers see the same eight parameter columns as before.
#[test]
fn a_1d_grid_keeps_its_shape() {
    let dir = scratch("shape");
    let path = run(&dir, "grid", GRID);
    let file = hdf5::File::open(&path).expect("open");
    assert_eq!(kick_store::h5::read_grid_shape(&file), Some(vec![3, 2]));
    let axes: Vec<String> =
        file.dataset("grid/axes").unwrap().read_raw::<hdf5::types::VarLenUnicode>().unwrap().iter().map(|s| s.to_string()).collect();
    assert_eq!(axes, ["stiffness", "damping"]);
    let stiffness = log_range(2e5, 8e5, 3);
    assert_eq!(read(&file, "grid/stiffness"), stiffness);
    assert_eq!(read(&file, "grid/damping"), [0.0, 120.0]);
    for p in [Parameter::Stiffness, Parameter::Damping] {
        let d = file.dataset(&format!("grid/{}", p.name())).unwrap();
        assert_eq!(read_str_attr(&d, "units").as_deref(), Some(p.unit()));
    }
    // C order: row (i, j) = i * 2 + j.
    let (k, c) = (read(&file, "parameters/stiffness"), read(&file, "parameters/damping"));
    for (i, &ki) in stiffness.iter().enumerate() {
        for (j, cj) in [0.0, 120.0].into_iter().enumerate() {
            assert_eq!((k[i * 2 + j], c[i * 2 + j]), (ki, cj), "cell ({i}, {j})");
        }
    }
    let data = kick_store::SweepData::read(&path).unwrap();
    let names: Vec<&str> = data.parameters.iter().map(|(c, _)| c.name.as_str()).collect();
    assert_eq!(names.len(), 8, "{names:?}");
    assert_eq!(data.rows(), 6);
    assert_eq!(data.grid_shape(), Some(vec![3, 2]));
    assert_eq!((data.grid[0].0.name.as_str(), data.grid[1].1.as_slice()), ("stiffness", [0.0, 120.0].as_slice()));
    // Named scenarios and single runs have no grid.
    let single = run(&dir, "single", "solver = \"accurate\"\n[base]\nfoot_mass = 2.0\n");
    assert_eq!(kick_store::h5::read_grid_shape(&hdf5::File::open(&single).unwrap()), None);
    let _ = std::fs::remove_dir_all(&dir);
}
