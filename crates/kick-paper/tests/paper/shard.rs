//! Sharded runs and their merge against the unsharded run, object by object.

use crate::scratch;
use hdf5::types::{FloatSize, IntSize, TypeDescriptor, VarLenUnicode};
use kick_compliant::Accurate;
use kick_core::Solver;
use kick_store::h5::{read_str_attr, read_u64_attr};
use kick_store::shard::{merge, run_shard, Shard};
use kick_study::experiment;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A dataset's or attribute's content, compared bit for bit.
#[derive(Debug, PartialEq)]
enum Content {
    F64(Vec<u64>),
    U64(Vec<u64>),
    U8(Vec<u8>),
    Text(Vec<String>),
}

fn content(dtype: hdf5::Datatype, f: impl Fn(&TypeDescriptor) -> Content) -> Content {
    f(&dtype.to_descriptor().expect("descriptor"))
}

fn attributes(location: &hdf5::Location) -> BTreeMap<String, Content> {
    let mut out = BTreeMap::new();
    for name in location.attr_names().unwrap() {
        let a = location.attr(&name).unwrap();
        let value = content(a.dtype().unwrap(), |t| match t {
            // Scalars, and lists (`grid_shape`).
            TypeDescriptor::Float(FloatSize::U8) => Content::F64(a.read_raw::<f64>().unwrap().iter().map(|v| v.to_bits()).collect()),
            TypeDescriptor::Unsigned(IntSize::U8) => Content::U64(a.read_raw::<u64>().unwrap()),
            TypeDescriptor::Unsigned(IntSize::U1) => Content::U8(a.read_raw::<u8>().unwrap()),
            TypeDescriptor::VarLenUnicode => Content::Text(vec![a.read_scalar::<VarLenUnicode>().unwrap().to_string()]),
            other => panic!("attribute {name}: {other:?}"),
        });
        out.insert(name, value);
    }
    out
}

/// Every group and dataset of a file by path: its attributes and (datasets) values.
fn tree(group: &hdf5::Group, prefix: &str, out: &mut BTreeMap<String, (BTreeMap<String, Content>, Option<Content>)>) {
    out.insert(prefix.to_string(), (attributes(group), None));
    for name in group.member_names().unwrap() {
        let path = format!("{prefix}/{name}");
        if let Ok(g) = group.group(&name) {
            tree(&g, &path, out);
        } else {
            let d = group.dataset(&name).unwrap();
            let values = content(d.dtype().unwrap(), |t| match t {
                TypeDescriptor::Float(FloatSize::U8) => Content::F64(d.read_raw::<f64>().unwrap().iter().map(|v| v.to_bits()).collect()),
                TypeDescriptor::Unsigned(IntSize::U8) => Content::U64(d.read_raw::<u64>().unwrap()),
                TypeDescriptor::Unsigned(IntSize::U1) => Content::U8(d.read_raw::<u8>().unwrap()),
                TypeDescriptor::VarLenUnicode => {
                    Content::Text(d.read_raw::<VarLenUnicode>().unwrap().iter().map(|s| s.to_string()).collect())
                }
                other => panic!("{path}: {other:?}"),
            });
            out.insert(path, (attributes(&d), Some(values)));
        }
    }
}

/// The two files hold the same objects with the same attributes and values,
/// every one of them (no wall-clock time in either); returns how many datasets were compared.
pub(crate) fn assert_same_file(merged: &Path, whole: &Path) -> usize {
    let (mut a, mut b) = (BTreeMap::new(), BTreeMap::new());
    tree(&hdf5::File::open(merged).unwrap(), "", &mut a);
    tree(&hdf5::File::open(whole).unwrap(), "", &mut b);
    assert_eq!(a.keys().collect::<Vec<_>>(), b.keys().collect::<Vec<_>>(), "objects");
    for (path, (attrs, values)) in &a {
        assert_eq!(attrs, &b[path].0, "attributes of {path:?}");
        assert_eq!(values, &b[path].1, "values of {path:?}");
    }
    a.values().filter(|(_, v)| v.is_some()).count()
}

/// Run `text` whole and in `count` shards (in reverse order) in `dir`; the
/// whole file and the shard files.
fn whole_and_shards(dir: &Path, name: &str, text: &str, count: u64) -> (PathBuf, Vec<PathBuf>) {
    let file = dir.join(format!("{name}.toml"));
    std::fs::write(&file, text).unwrap();
    let experiment = experiment::load(&file).unwrap();
    let whole = kick_store::run(&experiment, &dir.join("whole"), false).unwrap().path;
    let parts: Vec<PathBuf> =
        (0..count).rev().map(|index| run_shard(&experiment, Shard { index, count }, &dir.join("parts"), false).unwrap().path).collect();
    (whole, parts)
}

// Two solvers, a failed row in the middle shard (1 MN of drive: no separation).
const GRID: &str = r#"
description = "shard test grid"
solvers = ["accurate", "seed-rk4"]
dt = 5e-6
[[sweep]]
parameter = "drive_force"
values = [0.0, 1e6, 500.0]
[[sweep]]
parameter = "stiffness"
values = [2e5, 4.2e5, 8e5]
[[sweep]]
parameter = "damping"
values = [0.0, 120.0]
"#;

#[test]
fn three_shards_merged_equal_the_unsharded_run() {
    let dir = scratch("shard-grid");
    let (whole, parts) = whole_and_shards(&dir, "grid", GRID, 3);
    // Shard 1 of 3 of 18 rows: rows 6..12, with its own attributes and rows.
    let middle = hdf5::File::open(dir.join("parts/grid.shard-1-of-3.h5")).unwrap();
    for (name, value) in
        [("shard_index", 1), ("shard_count", 3), ("shard_row_start", 6), ("shard_row_end", 12), ("experiment_rows", 18), ("rows", 6)]
    {
        assert_eq!(read_u64_attr(&middle, name), Some(value), "{name}");
    }
    let print = read_str_attr(&middle, "experiment_fingerprint").unwrap();
    assert!(print.starts_with("fnv1a64:") && print.len() == 24, "{print}");
    // Its failures are numbered by its own rows: the rows of 6..12 (1 MN of
    // drive) that a direct solve does not separate, or separates past the
    // law's validity (status 4, the numbers kept), less 6.
    let experiment = experiment::load(&dir.join("grid.toml")).unwrap();
    let failing: Vec<u64> = (6..12)
        .filter(|&row| {
            let scenario = experiment.one_d().unwrap().scenarios.scenario(row).unwrap();
            Accurate::default().solve(&scenario).map_or(true, |o| scenario.check_validity(&o).is_err())
        })
        .collect();
    assert!(!failing.is_empty());
    let failed: Vec<u64> = middle.dataset("failures/index").unwrap().read_raw().unwrap();
    assert_eq!(failed, failing.iter().map(|r| r - 6).collect::<Vec<_>>());
    drop(middle);

    let merged = merge(&dir.join("merged/grid.h5"), &parts).unwrap();
    assert_eq!(merged.rows, 18);
    let datasets = assert_same_file(&merged.path, &whole);
    // 8 parameters; per solver 1 status, 2 failure datasets and the observables.
    assert!(datasets > 8 + 2 * 3, "{datasets} datasets compared");
    let file = hdf5::File::open(&merged.path).unwrap();
    let failed: Vec<u64> = file.dataset("failures/index").unwrap().read_raw().unwrap();
    assert_eq!(failed, failing);
    // The grid's shape and coordinates, once, as in the unsharded file.
    assert_eq!(kick_store::h5::read_grid_shape(&file), Some(vec![3, 3, 2]));
    assert_eq!(file.dataset("grid/drive_force").unwrap().read_raw::<f64>().unwrap(), [0.0, 1e6, 500.0]);
    drop(file);
    // Nothing but the merged file in its directory: no temporary or lock file.
    assert_eq!(std::fs::read_dir(dir.join("merged")).unwrap().count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn histories_and_named_rows_merge_to_the_unsharded_run() {
    let dir = scratch("shard-history");
    let histories = r#"
solver = "accurate"
[[sweep]]
parameter = "stiffness"
values = [1.2e5, 4.2e5, 1.8e6, 6e6, 9e5]
[output]
mode = "history"
interval = 2e-5
"#;
    let (whole, parts) = whole_and_shards(&dir, "h", histories, 2);
    let merged = merge(&dir.join("merged/h.h5"), &parts).unwrap();
    assert_same_file(&merged.path, &whole);
    // Shard 1 of 2 of 5 rows holds rows 2..5, its histories numbered 0..3.
    let part = hdf5::File::open(dir.join("parts/h.shard-1-of-2.h5")).unwrap();
    assert_eq!(part.group("histories").unwrap().member_names().unwrap(), ["000000", "000001", "000002"]);

    // Table 2: named scenarios, eight rows in three shards.
    let table2 = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../experiments/table2.toml")).unwrap();
    let (whole, parts) = whole_and_shards(&dir, "table2", &table2, 3);
    let merged = merge(&dir.join("merged/table2.h5"), &parts).unwrap();
    assert_same_file(&merged.path, &whole);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn incomplete_or_mixed_shards_are_refused_by_file_name() {
    let dir = scratch("shard-refuse");
    let (_, parts) = whole_and_shards(&dir, "grid", GRID, 3);
    // parts are 2, 1, 0 of 3.
    let out = dir.join("merged/grid.h5");
    let message = merge(&out, &parts[..2]).unwrap_err().to_string();
    assert!(message.contains("missing") && message.contains("grid.shard-0-of-3.h5 (rows 0..6)"), "{message}");
    let twice = [parts[0].clone(), parts[1].clone(), parts[1].clone(), parts[2].clone()];
    let message = merge(&out, &twice).unwrap_err().to_string();
    assert!(message.contains("shard 1/3 given twice") && message.contains("grid.shard-1-of-3.h5"), "{message}");

    // Another experiment's shard 0 of 3 (one stiffness changed).
    let other = dir.join("other");
    std::fs::create_dir_all(&other).unwrap();
    let (_, other_parts) = whole_and_shards(&other, "grid", &GRID.replace("8e5", "9e5"), 3);
    let mixed = [parts[0].clone(), parts[1].clone(), other_parts[2].clone()];
    let message = merge(&out, &mixed).unwrap_err().to_string();
    assert!(message.contains("different experiments") && message.contains(&other_parts[2].display().to_string()), "{message}");
    // Same experiment split in 2: N differs.
    let experiment = experiment::load(&dir.join("grid.toml")).unwrap();
    let half = run_shard(&experiment, Shard { index: 1, count: 2 }, &dir.join("halves"), false).unwrap().path;
    let message = merge(&out, &[parts[1].clone(), parts[2].clone(), half.clone()]).unwrap_err().to_string();
    assert!(message.contains("split the experiment differently") && message.contains(&half.display().to_string()), "{message}");
    // An unsharded file is not a shard.
    let whole = dir.join("whole/grid.h5");
    let message = merge(&out, &[whole.clone()]).unwrap_err().to_string();
    assert!(message.contains(&whole.display().to_string()) && message.contains("not a shard file"), "{message}");
    // Nothing written on refusal.
    assert!(!out.exists() && std::fs::read_dir(dir.join("merged")).map_or(0, |d| d.count()) == 0);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every part ran into `dir/parts`, merged (twice, a second apart) into
/// `dir/merged`: the merged file equals `whole` object by object, and the
/// two merges are the same bytes (no time stamps).
fn merge_and_compare(dir: &Path, name: &str, parts: &[PathBuf], whole: &Path) -> usize {
    let merged = merge(&dir.join(format!("merged/{name}.h5")), parts).unwrap();
    let datasets = assert_same_file(&merged.path, whole);
    std::thread::sleep(std::time::Duration::from_millis(1100));
    let again = merge(&dir.join(format!("again/{name}.h5")), parts).unwrap();
    assert!(std::fs::read(&merged.path).unwrap() == std::fs::read(&again.path).unwrap(), "two merges of {name} differ in bytes");
    datasets
}

const GRID3D: &str = r#"
description = "3D shard test grid"
[kick3d]
friction = 0.6
[[sweep]]
parameter = "foot_speed"
values = [16.0, 22.0, 28.0]
[[sweep]]
parameter = "offset"
linear = { from = 0.0, to = 0.08, count = 3 }
"#;

/// `kick run --shard` of a 3D experiment: three shards merged equal the
/// unsharded run, `/grid`, `/fixed` and every cell; a shard holds its own cells.
#[test]
fn a_3d_experiment_in_three_shards_merges_to_the_unsharded_run() {
    let dir = scratch("grid3d");
    let file = dir.join("g3.toml");
    std::fs::write(&file, GRID3D).unwrap();
    let whole = kick_store::shard::run_file(&file, &dir.join("whole"), None).unwrap().summary.path;
    let parts: Vec<PathBuf> = ["2/3", "0/3", "1/3"]
        .iter()
        .map(|given| kick_store::shard::run_file(&file, &dir.join("parts"), Some(given)).unwrap().summary.path)
        .collect();
    // Shard 1 of 3 of 9 cells: cells 3..6 (foot speed 22 m/s), the whole grid's shape.
    let middle = hdf5::File::open(dir.join("parts/g3.shard-1-of-3.h5")).unwrap();
    assert_eq!(read_u64_attr(&middle, "rows"), Some(3));
    assert_eq!(kick_store::h5::read_grid_shape(&middle), Some(vec![3, 3]));
    assert_eq!(middle.dataset("parameters/foot_speed").unwrap().read_raw::<f64>().unwrap(), [22.0; 3]);
    assert_eq!(middle.dataset("parameters/offset").unwrap().read_raw::<f64>().unwrap(), [0.0, 0.04, 0.08]);
    drop(middle);
    let datasets = merge_and_compare(&dir, "g3", &parts, &whole);
    // 2 axes, the 3D outcomes, status, failures (2), grid (2 axes + names), fixed.
    assert!(datasets > 2 + kick_3d::OBSERVABLES_3D.len() + 3 + 3, "{datasets}");
    let merged = hdf5::File::open(dir.join("merged/g3.h5")).unwrap();
    assert_eq!(merged.dataset("fixed/friction").unwrap().read_raw::<f64>().unwrap(), [0.6]);
    assert_eq!(kick_store::h5::read_grid_shape(&merged), Some(vec![3, 3]));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `kick sweep --shard I/N`: three parts merged equal the unsharded sweep;
/// sample i is the same scenario in its shard as in the whole sweep.
#[test]
fn a_sweep_in_three_shards_merges_to_the_unsharded_sweep() {
    use kick_store::sweep::{sweep, SweepSettings};
    let dir = scratch("sweep");
    let settings = |out: PathBuf, shard: Option<&str>| SweepSettings {
        ranges: Default::default(),
        samples: 200,
        seed: 5,
        solver: "auto".into(),
        dt: None,
        out,
        fixed: Default::default(),
        shard: shard.map(String::from),
        threads: None,
        compress: Default::default(),
    };
    let whole = sweep(&settings(dir.join("whole/s.h5"), None)).unwrap();
    assert_eq!(whole.path, dir.join("whole/s.h5"));
    let parts: Vec<PathBuf> =
        ["1/3", "2/3", "0/3"].iter().map(|given| sweep(&settings(dir.join("parts/s.h5"), Some(given))).unwrap().path).collect();
    assert_eq!(parts[0], dir.join("parts/s.shard-1-of-3.h5"));
    // Shard 1 of 3 of 200 samples: samples 66..133, drawn from (seed, i).
    let middle = hdf5::File::open(&parts[0]).unwrap();
    let mass: Vec<f64> = middle.dataset("parameters/foot_mass").unwrap().read_raw().unwrap();
    let sampled = kick_study::sample::SampledSweep::new(200, 5);
    let expected: Vec<f64> = (66..133).map(|i| sampled.scenario(i).map_or(f64::NAN, |s| s.get(kick_core::Parameter::FootMass))).collect();
    assert_eq!(mass.len(), 67);
    assert!(mass.iter().zip(&expected).all(|(a, b)| a.to_bits() == b.to_bits()));
    drop(middle);
    merge_and_compare(&dir, "s", &parts, &whole.path);
    // A part of another seed is another sweep.
    let mut other = settings(dir.join("other/s.h5"), Some("0/3"));
    other.seed = 6;
    let foreign = sweep(&other).unwrap().path;
    let message = merge(&dir.join("bad/s.h5"), &[parts[0].clone(), parts[1].clone(), foreign.clone()]).unwrap_err().to_string();
    assert!(message.contains("different experiments") && message.contains(&foreign.display().to_string()), "{message}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `kick sweep3d --shard I/N`: three parts merged equal the unsharded sweep
/// (vectors as `_x`, `_y`, `_z` columns, energy, failures renumbered), and each part's rows
/// are the whole sweep's rows of its slice.
#[test]
fn a_sweep3d_in_three_shards_merges_to_the_unsharded_sweep() {
    use kick_store::sweep3d::{sweep3d, Sweep3dSettings};
    let dir = scratch("sweep3d");
    let settings = |out: PathBuf, shard: Option<&str>| {
        let mut fixed = kick_3d::KickSpec::default();
        fixed.scenario.law = Some(kick_core::LawKind::PowerLaw);
        Sweep3dSettings {
            ranges: Default::default(),
            flight: None,
            samples: 40,
            seed: 3,
            out,
            fixed,
            shard: shard.map(String::from),
            threads: None,
            compress: Default::default(),
        }
    };
    let whole = sweep3d(&settings(dir.join("whole/k.h5"), None)).unwrap();
    assert_eq!(whole.kicks, 40);
    let parts: Vec<PathBuf> =
        ["0/3", "2/3", "1/3"].iter().map(|given| sweep3d(&settings(dir.join("parts/k.h5"), Some(given))).unwrap().path).collect();
    let part = hdf5::File::open(&parts[1]).unwrap();
    let whole_file = hdf5::File::open(&whole.path).unwrap();
    // Shard 2 of 3 of 40: samples 26..40.
    assert_eq!(
        (read_u64_attr(&part, "shard_row_start"), read_u64_attr(&part, "rows"), read_u64_attr(&part, "samples")),
        (Some(26), Some(14), Some(40))
    );
    let spin: Vec<f64> = part.dataset("outcomes/spin_z").unwrap().read_raw().unwrap();
    let all: Vec<f64> = whole_file.dataset("outcomes/spin_z").unwrap().read_raw().unwrap();
    assert!(spin.iter().zip(&all[26..]).all(|(a, b)| a.to_bits() == b.to_bits()) && spin.len() == 14);
    drop((part, whole_file));
    merge_and_compare(&dir, "k", &parts, &whole.path);
    let _ = std::fs::remove_dir_all(&dir);
}
