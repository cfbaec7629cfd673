//! `--compress` / `compress = LEVEL`: HDF5's shuffle + deflate on the
//! per-row datasets. The values read back are the plain file's bits, every
//! numeric per-row dataset carries both filters, the file is smaller and the
//! same bytes on a rerun; a merge of compressed shards stays compressed.

use crate::scratch;
use crate::shard::assert_same_file;
use hdf5::filters::Filter;
use kick_store::h5::Compression;
use kick_store::shard::merge;
use kick_store::sweep::{sweep, SweepSettings};
use kick_store::sweep3d::{sweep3d, Sweep3dSettings};
use std::path::{Path, PathBuf};

fn sweep_settings(samples: u64, out: PathBuf, compress: Compression) -> SweepSettings {
    SweepSettings {
        ranges: Default::default(),
        samples,
        seed: 7,
        solver: "auto".into(),
        dt: None,
        out,
        fixed: Default::default(),
        shard: None,
        threads: None,
        compress,
    }
}

/// Paths of every dataset below `group` of the file, with its filters.
fn filters(file: &Path, group: &str) -> Vec<(String, Vec<Filter>)> {
    fn walk(g: &hdf5::Group, prefix: &str, out: &mut Vec<(String, Vec<Filter>)>) {
        for name in g.member_names().unwrap() {
            let path = format!("{prefix}/{name}");
            match g.group(&name) {
                Ok(inner) => walk(&inner, &path, out),
                Err(_) => out.push((path, g.dataset(&name).unwrap().filters())),
            }
        }
    }
    let f = hdf5::File::open(file).unwrap();
    let mut out = Vec::new();
    walk(&f.group(group).unwrap(), group, &mut out);
    out
}

/// Every dataset below `groups` has exactly shuffle then deflate at `level`.
fn assert_filtered(file: &Path, groups: &[&str], level: u8) -> usize {
    let mut count = 0;
    for group in groups {
        for (path, found) in filters(file, group) {
            assert_eq!(found, [Filter::Shuffle, Filter::Deflate(level)], "{path} of {}", file.display());
            count += 1;
        }
    }
    count
}

fn size(path: &Path) -> u64 {
    std::fs::metadata(path).unwrap().len()
}

/// `kick sweep --compress 4` of 3000 scenarios: the plain file's objects,
/// attributes and bits; shuffle + deflate on every parameter, outcome,
/// status and failure index; a smaller file (the mantissas of random
/// parameters and their outcomes hardly compress: the gain is in the
/// exponent bytes and the NaN rows of failures); the same bytes when run
/// again a second later.
#[test]
fn a_compressed_sweep_reads_back_the_plain_sweeps_bits_in_a_smaller_file() {
    let dir = scratch("compress-sweep");
    let plain = sweep(&sweep_settings(3000, dir.join("plain/s.h5"), Compression::None)).unwrap();
    let packed = sweep(&sweep_settings(3000, dir.join("packed/s.h5"), Compression::Deflate(4))).unwrap();
    assert!(packed.failed > 0, "the sweep has failures, so failures/index has rows");
    let datasets = assert_same_file(&packed.path, &plain.path);
    assert!(datasets > 8 + 15, "{datasets} datasets compared");
    let filtered = assert_filtered(&packed.path, &["parameters", "outcomes"], 4);
    // Every dataset of the file but the two of failures/.
    assert_eq!(filtered + 2, datasets);
    let index = hdf5::File::open(&packed.path).unwrap().dataset("failures/index").unwrap().filters();
    assert_eq!(index, [Filter::Shuffle, Filter::Deflate(4)]);
    // Text stays plain (deflate would see only heap references).
    assert!(hdf5::File::open(&packed.path).unwrap().dataset("failures/message").unwrap().filters().is_empty());
    // The plain file has no filter anywhere.
    assert!(filters(&plain.path, "/").iter().all(|(_, f)| f.is_empty()));
    let (a, b) = (size(&packed.path), size(&plain.path));
    assert!(a < b, "compressed {a} bytes, plain {b} bytes");
    std::thread::sleep(std::time::Duration::from_millis(1100));
    let again = sweep(&sweep_settings(3000, dir.join("again/s.h5"), Compression::Deflate(4))).unwrap();
    assert!(std::fs::read(&again.path).unwrap() == std::fs::read(&packed.path).unwrap(), "two compressed runs differ in bytes");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `kick sweep3d --compress 9` of 3000 kicks: every parameter column (vectors
/// as `_x`, `_y`, `_z`), the 3D outcome columns and the status are filtered, read back as the plain file's
/// bits, in a smaller file (the plain one is contiguous, without the chunk
/// indices a filtered dataset needs, so a few hundred rows would not be).
#[test]
fn a_compressed_sweep3d_reads_back_the_plain_sweeps_bits_in_a_smaller_file() {
    let dir = scratch("compress-sweep3d");
    let settings = |out: PathBuf, compress| {
        let mut fixed = kick_3d::KickSpec::default();
        fixed.scenario.law = Some(kick_core::LawKind::PowerLaw);
        Sweep3dSettings {
            ranges: Default::default(),
            flight: None,
            samples: 3000,
            seed: 2,
            out,
            fixed,
            shard: None,
            threads: None,
            compress,
        }
    };
    let plain = sweep3d(&settings(dir.join("plain/k.h5"), Compression::None)).unwrap();
    let packed = sweep3d(&settings(dir.join("packed/k.h5"), Compression::Deflate(9))).unwrap();
    assert_same_file(&packed.path, &plain.path);
    let filtered = assert_filtered(&packed.path, &["parameters", "outcomes"], 9);
    // Every declared parameter, kick-3d's outcome columns and the status.
    assert!(filtered >= kick_3d::OBSERVABLES_3D.len() + 1 + 8, "{filtered}");
    let launch = hdf5::File::open(&packed.path).unwrap().dataset("outcomes/launch_velocity_x").unwrap();
    assert_eq!((launch.shape(), launch.filters()), (vec![3000], vec![Filter::Shuffle, Filter::Deflate(9)]));
    assert!(filters(&plain.path, "/").iter().all(|(_, f)| f.is_empty()));
    let (a, b) = (size(&packed.path), size(&plain.path));
    assert!(a < b, "compressed {a} bytes, plain {b} bytes");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Compressed shards of a sweep merge into the compressed whole sweep: the
/// merge reads the filtered parts and writes the filters on.
#[test]
fn compressed_shards_merge_to_the_compressed_sweep() {
    let dir = scratch("compress-shards");
    let whole = sweep(&sweep_settings(900, dir.join("whole/s.h5"), Compression::Deflate(2))).unwrap();
    let parts: Vec<PathBuf> = ["2/3", "0/3", "1/3"]
        .iter()
        .map(|given| {
            let mut s = sweep_settings(900, dir.join("parts/s.h5"), Compression::Deflate(2));
            s.shard = Some((*given).into());
            sweep(&s).unwrap().path
        })
        .collect();
    assert_filtered(&parts[0], &["parameters", "outcomes"], 2);
    let merged = merge(&dir.join("merged/s.h5"), &parts).unwrap();
    assert_eq!(merged.rows, 900);
    assert_same_file(&merged.path, &whole.path);
    assert!(assert_filtered(&merged.path, &["parameters", "outcomes"], 2) > 8);
    let _ = std::fs::remove_dir_all(&dir);
}

const GRID: &str = "[[sweep]]\nparameter = \"stiffness\"\nlog = { from = 1e5, to = 1e7, count = 50 }\n";
const GRID3D: &str = "[kick3d]\nfriction = 0.6\n[[sweep]]\nparameter = \"offset\"\nvalues = [0.0, 0.04]\n";

/// The `compress` key of experiment files, 1D and 3D: a level or `true`
/// (level 4) filters the result file; `false` leaves it plain.
#[test]
fn the_compress_key_of_experiment_files_filters_their_result_files() {
    let dir = scratch("compress-key");
    for (name, key, text, level) in [
        ("one", "compress = 6", GRID, Some(6)),
        ("two", "compress = true", GRID, Some(Compression::DEFAULT_LEVEL)),
        ("three", "compress = false", GRID, None),
        ("four", "compress = 1", GRID3D, Some(1)),
    ] {
        let file = dir.join(format!("{name}.toml"));
        std::fs::write(&file, format!("{key}\n{text}")).unwrap();
        let out = kick_store::shard::run_file(&file, &dir.join("out"), None).unwrap().summary.path;
        match level {
            Some(level) => assert!(assert_filtered(&out, &["parameters", "outcomes"], level) > 1, "{key}"),
            None => assert!(filters(&out, "/").iter().all(|(_, f)| f.is_empty()), "{key}"),
        }
    }
    assert_eq!(kick_study::experiment::load(&dir.join("two.toml")).unwrap().compress, Compression::Deflate(4));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A level outside 1..=9 or a value that is no level is refused, naming
/// the key with its line (1D and 3D), or the flag.
#[test]
fn a_bad_compression_level_is_refused_by_name() {
    let dir = scratch("compress-bad");
    for (text, says) in [
        (format!("description = \"x\"\ncompress = 0\n{GRID}"), "compress 0: the deflate level must be 1 (fastest) to 9 (smallest)"),
        (format!("description = \"x\"\ncompress = 10\n{GRID}"), "compress 10: the deflate level must be 1"),
        (format!("description = \"x\"\ncompress = \"fast\"\n{GRID}"), "expected a deflate level 1 (fastest) to 9 (smallest), or true"),
        (format!("description = \"x\"\ncompress = 2.5\n{GRID}"), "expected a deflate level"),
        (format!("description = \"x\"\ncompress = -3\n{GRID3D}"), "compress -3: the deflate level must be 1"),
    ] {
        let file = dir.join("bad.toml");
        std::fs::write(&file, &text).unwrap();
        let e = kick_study::experiment::load(&file).unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "compress"), "{text}: {e}");
        assert!(e.message.contains(says), "{text}: {e}");
    }
    for level in [0, 10, -1] {
        let e = Compression::deflate(Some(level), "--compress").unwrap_err();
        assert_eq!(e, kick_study::StudyError::Deflate { what: "--compress".into(), level });
        assert_eq!(e.to_string(), format!("--compress {level}: the deflate level must be 1 (fastest) to 9 (smallest)"));
    }
    assert_eq!(Compression::deflate(None, "--compress"), Ok(Compression::Deflate(4)));
    let _ = std::fs::remove_dir_all(&dir);
}
