//! `--history FILE [--samples N | --interval DT]` of `kick simulate`,
//! `kick simulate3d` and `kick flight`: CSV or HDF5 by extension, the
//! documented header and units, exact row counts, the summary alone on
//! stdout, and nothing written when the run fails.

use crate::kick;
use kick_store::ResultFile;
use std::path::{Path, PathBuf};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kick-history-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Run `kick args` expecting success; stdout parsed as the JSON summary.
fn json(args: &[&str]) -> serde_json::Value {
    let out = kick(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("stdout is the JSON summary alone")
}

/// (header, rows) of a history CSV: every cell of every row a number.
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(str::to_string).collect::<Vec<_>>();
    let rows = lines
        .map(|l| l.split(',').map(|c| c.parse::<f64>().unwrap_or_else(|_| panic!("not a number: {c:?} in {l}"))).collect::<Vec<_>>())
        .collect::<Vec<_>>();
    assert!(rows.iter().all(|r| r.len() == header.len()));
    (header, rows)
}

/// Equal but for the last bit: serde_json's default parser (no
/// `float_roundtrip`) may round the JSON summary's numbers one ulp off.
fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 2.0 * f64::EPSILON * a.abs().max(b.abs())
}

fn header_of(columns: &[(&str, &str)]) -> Vec<String> {
    columns.iter().map(|(n, u)| format!("{n} [{u}]")).collect()
}

#[test]
fn simulate_writes_a_csv_history_with_the_documented_header() {
    let dir = scratch("1d");
    let path = dir.join("h.csv");
    let summary = json(&["simulate", "--format", "json", "--solver", "accurate", "--history", path.to_str().unwrap(), "--samples", "101"]);
    assert!(summary.get("history").is_none());
    let (header, rows) = read_csv(&path);
    assert_eq!(header, header_of(&kick_core::HISTORY_COLUMNS));
    assert_eq!(header[0], "time [s]");
    assert_eq!(rows.len(), 101);
    let t_c = summary["contact_time"].as_f64().unwrap();
    let last = rows.last().unwrap();
    assert!(same(last[0], t_c));
    assert!(same(last[4], summary["v_ball_out"].as_f64().unwrap()));
    assert_eq!(last[11], 0.0, "separation row");
    for (k, row) in rows[..100].iter().enumerate() {
        assert!(same(row[0], k as f64 * (t_c / 100.0)), "row {k}");
    }
    // The default: 201 rows.
    let summary = json(&["simulate", "--format", "json", "--history", path.to_str().unwrap()]);
    assert_eq!(read_csv(&path).1.len(), 201, "{summary}");
}

#[test]
fn simulate3d_writes_an_hdf5_history_with_units_and_parameters() {
    let dir = scratch("3d");
    let path = dir.join("h.h5");
    let dt = 1e-4;
    let summary = json(&[
        "simulate3d",
        "--offset",
        "0.05",
        "--friction",
        "0.5",
        "--format",
        "json",
        "--history",
        path.to_str().unwrap(),
        "--interval",
        "1e-4",
    ]);
    let t_c = summary["contact_time"].as_f64().unwrap();
    let grid = (0u64..).take_while(|&k| k as f64 * dt < t_c).count();
    let file = ResultFile::open(&path).unwrap();
    assert_eq!(file.text("", "layout").unwrap(), "history");
    assert_eq!(file.text("", "level").unwrap(), "3d");
    assert_eq!(file.text("", "solver").unwrap(), "accurate-3d");
    for (name, unit) in kick_3d::HISTORY_COLUMNS_3D {
        let (column, values) = file.column(&format!("history/{name}")).unwrap();
        assert_eq!(column.unit, unit, "{name}");
        assert_eq!(values.len(), grid + 1, "{name}");
    }
    let time = file.values("history/time").unwrap();
    assert!(same(*time.last().unwrap(), t_c));
    assert_eq!(time[grid - 1], (grid - 1) as f64 * dt);
    let launch: Vec<f64> =
        ["x", "y", "z"].iter().map(|c| *file.values(&format!("history/ball_velocity_{c}")).unwrap().last().unwrap()).collect();
    let expected: Vec<f64> = summary["launch_velocity"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    assert!(launch.iter().zip(&expected).all(|(a, b)| same(*a, *b)), "{launch:?} vs {expected:?}");
    let state = file.values("history/contact_state").unwrap();
    assert!(state.contains(&1.0) && state.contains(&2.0), "grip and slip: {state:?}");
    assert_eq!(*state.last().unwrap(), 0.0);
    assert_eq!(file.values("fixed/offset").unwrap(), [0.05]);
    assert_eq!(file.column("fixed/friction").unwrap().0.unit, "1");
    assert_eq!(file.values("fixed/foot_half_extents").unwrap().len(), 3);
}

/// A patch contact's history also has the patch's columns, with units: the
/// normal force's moment about the ball's centre (not zero 5 cm off) and
/// friction's arm, inside the ball. A point contact's history has neither.
#[test]
fn simulate3d_with_a_patch_writes_the_patch_columns() {
    let dir = scratch("3d-patch");
    let path = dir.join("p.h5");
    let patch = ["--law", "shell", "--patch-contact", "--instep-radius", "0.15", "--face-yaw", "0"];
    let mut args = vec![
        "simulate3d",
        "--offset",
        "0.05",
        "--friction",
        "0.5",
        "--format",
        "json",
        "--history",
        path.to_str().unwrap(),
        "--samples",
        "101",
    ];
    args.extend(patch);
    json(&args);
    let file = ResultFile::open(&path).unwrap();
    for (name, unit) in kick_3d::HISTORY_COLUMNS_3D.iter().chain(&kick_3d::PATCH_COLUMNS_3D) {
        let (column, values) = file.column(&format!("history/{name}")).unwrap();
        assert_eq!((column.unit.as_str(), values.len()), (*unit, 101), "{name}");
    }
    let moment = file.values("history/normal_moment_z").unwrap();
    assert!(moment.iter().any(|m| *m != 0.0), "{moment:?}");
    let radius = file.values("fixed/ball_radius").unwrap()[0];
    let arm: Vec<f64> = ["x", "y", "z"].iter().map(|c| file.values(&format!("history/contact_arm_{c}")).unwrap()[50]).collect();
    let size = arm.iter().map(|a| a * a).sum::<f64>().sqrt();
    assert!(size > 0.5 * radius && size < radius, "{size} against R = {radius}");
    let point = dir.join("q.h5");
    json(&["simulate3d", "--offset", "0.05", "--history", point.to_str().unwrap(), "--format", "json"]);
    assert!(!ResultFile::open(&point).unwrap().exists("history/normal_moment_z"));
}

#[test]
fn flight_writes_its_history() {
    let dir = scratch("flight");
    let path = dir.join("f.hdf5");
    let summary = json(&[
        "flight",
        "--speed",
        "25",
        "--launch-angle",
        "20",
        "--format",
        "json",
        "--history",
        path.to_str().unwrap(),
        "--samples",
        "50",
    ]);
    let file = ResultFile::open(&path).unwrap();
    let time = file.values("history/time").unwrap();
    assert_eq!(time.len(), 50);
    assert!(same(*time.last().unwrap(), summary["flight_time"].as_f64().unwrap()));
    // Landing: the centre back at z = R, located to the solver's tolerance.
    assert!((file.values("history/position_z").unwrap().last().unwrap() - 0.11).abs() < 1e-12);
    assert_eq!(file.column("history/velocity_x").unwrap().0.unit, "m/s");
    let csv = dir.join("f.csv");
    json(&["flight", "--speed", "25", "--launch-angle", "20", "--format", "json", "--history", csv.to_str().unwrap(), "--interval", "0.1"]);
    let (header, rows) = read_csv(&csv);
    assert_eq!(header[..2], ["time [s]", "position_x [m]"]);
    let t_f = summary["flight_time"].as_f64().unwrap();
    assert_eq!(rows.len(), (0u64..).take_while(|&k| k as f64 * 0.1 < t_f).count() + 1);
}

/// Refusals name the flag; a run that fails writes nothing.
#[test]
fn bad_history_requests_are_refused_and_leave_no_file() {
    let dir = scratch("bad");
    let file = |name: &str| dir.join(name).to_str().unwrap().to_string();
    for (args, needle) in [
        (vec!["simulate", "--history", &file("h.txt")], "--history"),
        (vec!["simulate3d", "--history", &file("h")], ".csv, .h5 or .hdf5"),
        (vec!["simulate", "--history", &file("h.csv"), "--samples", "1"], "--samples"),
        (vec!["flight", "--speed", "20", "--launch-angle", "10", "--history", &file("h.csv"), "--interval", "0"], "--interval"),
        (vec!["simulate", "--history", &file("h.csv"), "--samples", "3", "--interval", "1e-4"], "cannot be used with"),
        (vec!["simulate", "--samples", "3"], "--history"),
        (vec!["simulate3d", "--history", &file("h.h5"), "--solver", "full-state"], "--solver accurate"),
        (vec!["simulate3d", "--history", &file("h.h5"), "--foot-speed", "-3"], "foot"),
        // Rows counted before the first is written (1e297 of them).
        (vec!["simulate", "--history", &file("h.csv"), "--interval", "1e-300"], "history too long"),
        (vec!["simulate3d", "--history", &file("h.csv"), "--interval", "1e-300"], "history too long"),
    ] {
        let out = kick(&args);
        let message = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} must fail");
        assert!(message.contains(needle), "{args:?}: {message}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    assert!(std::fs::read_dir(&dir).unwrap().next().is_none(), "a refused run left a file");
}
