//! `kick run --shard`, `kick merge` and the Slurm example scripts, run here without Slurm.

use crate::kick;
use std::path::{Path, PathBuf};
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kick-cli-shard-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const GRID: &str = "solver = \"accurate\"\n[[sweep]]\nparameter = \"stiffness\"\nvalues = [2e5, 4.2e5, 8e5, 1.6e6]\n\
                    [[sweep]]\nparameter = \"damping\"\nvalues = [0.0, 60.0, 120.0]\n";

#[test]
fn bad_shard_flags_are_refused_naming_the_flag() {
    let dir = scratch("flags");
    let file = dir.join("grid.toml");
    std::fs::write(&file, GRID).unwrap();
    for (given, says) in [("4/4", "numbered from 0 to 3"), ("1-4", "expected I/N"), ("0/0", "at least 1"), ("x/4", "not a whole number")] {
        let out = kick(&["run", file.to_str().unwrap(), "--out", dir.to_str().unwrap(), "--shard", given]);
        assert_eq!(out.status.code(), Some(1), "{given}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(&format!("`--shard` = `{given}`")) && stderr.contains(says), "{given}: {stderr}");
    }
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1, "only the experiment file");
    let _ = std::fs::remove_dir_all(&dir);
}

/// PATH without any directory that has `sbatch`: the scripts take their local branch.
fn path_without_sbatch() -> String {
    let path = std::env::var_os("PATH").unwrap_or_default();
    let kept: Vec<PathBuf> = std::env::split_paths(&path).filter(|d| !d.join("sbatch").exists()).collect();
    std::env::join_paths(kept).unwrap().into_string().unwrap()
}

#[test]
fn the_slurm_example_run_locally_equals_an_unsharded_run() {
    let dir = scratch("slurm");
    let file = dir.join("grid.toml");
    std::fs::write(&file, GRID).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out = Command::new("bash")
        .arg(root.join("experiments/slurm/submit.sh"))
        .env("PATH", path_without_sbatch())
        .env("EXPERIMENT", &file)
        .env("OUT", dir.join("shards"))
        .env("KICK", env!("CARGO_BIN_EXE_kick"))
        .env("SHARDS", "3")
        .env_remove("SLURM_CPUS_PER_TASK")
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("3 shards, 12 rows"), "{stdout}");
    for i in 0..3 {
        assert!(dir.join(format!("shards/grid.shard-{i}-of-3.h5")).exists());
    }

    let whole = kick(&["run", file.to_str().unwrap(), "--out", dir.join("whole").to_str().unwrap()]);
    assert!(whole.status.success(), "{}", String::from_utf8_lossy(&whole.stderr));
    let mut merged = kick_store::SweepData::read(&dir.join("shards/grid.h5")).unwrap();
    let whole = kick_store::SweepData::read(&dir.join("whole/grid.h5")).unwrap();
    assert_eq!(merged.rows(), 12);
    merged.path = whole.path.clone();
    assert_eq!(merged, whole);

    // One shard gone: the merge job fails naming it, and writes nothing.
    std::fs::remove_file(dir.join("shards/grid.shard-1-of-3.h5")).unwrap();
    let again = kick(&[
        "merge",
        dir.join("again.h5").to_str().unwrap(),
        dir.join("shards/grid.shard-0-of-3.h5").to_str().unwrap(),
        dir.join("shards/grid.shard-2-of-3.h5").to_str().unwrap(),
    ]);
    assert_eq!(again.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&again.stderr);
    assert!(stderr.contains("missing") && stderr.contains("grid.shard-1-of-3.h5 (rows 4..8)"), "{stderr}");
    assert!(!dir.join("again.h5").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// submit.sh with a stand-in `sbatch` on PATH (it records its arguments and
/// the `KICK` it was given): the array of SHARDS tasks, the merge queued
/// after it, and KICK exported as the absolute path of the binary checked at
/// submit time. A `KICK` that is missing or not kick, and a bad `SHARDS`,
/// are refused before anything is submitted.
#[test]
fn submit_checks_kick_and_queues_the_array_then_the_merge() {
    let dir = scratch("submit");
    let bin = dir.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let log = dir.join("sbatch.log");
    let sbatch = bin.join("sbatch");
    std::fs::write(&sbatch, format!("#!/bin/bash\necho \"$* KICK=$KICK\" >> {}\necho 4242\n", log.display())).unwrap();
    std::process::Command::new("chmod").arg("+x").arg(&sbatch).status().unwrap();
    // The binary by name, found on PATH (as after `cargo install --root $PREFIX` and PATH=$PREFIX/bin:...).
    let kick_bin = Path::new(env!("CARGO_BIN_EXE_kick"));
    let path = format!("{}:{}:{}", bin.display(), kick_bin.parent().unwrap().display(), path_without_sbatch());
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let submit = |kick_var: &str, shards: &str| {
        Command::new("bash")
            .arg(root.join("experiments/slurm/submit.sh"))
            .env("PATH", &path)
            .env("OUT", dir.join("shards"))
            .env("KICK", kick_var)
            .env("SHARDS", shards)
            .output()
            .unwrap()
    };
    let out = submit("kick", "5");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let calls = std::fs::read_to_string(&log).unwrap();
    let calls: Vec<&str> = calls.lines().collect();
    let absolute = std::fs::canonicalize(kick_bin).unwrap();
    let exported = |line: &str| std::fs::canonicalize(line.rsplit("KICK=").next().unwrap()).unwrap();
    assert_eq!(calls.len(), 2, "{calls:?}");
    assert!(calls[0].starts_with("--parsable --array=0-4 --export=ALL") && calls[0].contains("shard.sbatch"), "{calls:?}");
    assert!(calls[1].starts_with("--dependency=afterok:4242 --export=ALL") && calls[1].contains("merge.sbatch"), "{calls:?}");
    for line in &calls {
        assert!(line.rsplit("KICK=").next().unwrap().starts_with('/'), "KICK exported as an absolute path: {line}");
        assert_eq!(exported(line), absolute, "{line}");
    }

    // Refusals: nothing submitted, the message names KICK (or SHARDS) and how to build the binary.
    std::fs::remove_file(&log).unwrap();
    let not_kick = dir.join("not-kick");
    std::fs::write(&not_kick, "#!/bin/bash\necho hello\n").unwrap();
    std::process::Command::new("chmod").arg("+x").arg(&not_kick).status().unwrap();
    for (kick_var, shards, says) in [
        ("/nonexistent/bin/kick", "2", "KICK=/nonexistent/bin/kick is not an executable kick binary"),
        ("kick-not-installed", "2", "cargo install --locked --path crates/kick-cli --root"),
        (not_kick.to_str().unwrap(), "2", "does not run as kick"),
        ("kick", "0", "SHARDS=0: a whole number of array tasks, at least 1"),
        ("kick", "two", "SHARDS=two"),
    ] {
        let out = submit(kick_var, shards);
        assert_eq!(out.status.code(), Some(2), "{kick_var} {shards}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(says), "{kick_var} {shards}: {stderr}");
        assert!(!log.exists(), "nothing submitted for {kick_var} {shards}");
    }
    assert!(!dir.join("shards").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The Slurm example with `SWEEP`: `kick sweep3d --shard I/N` per array task
/// and the merge, run here, equal to one unsharded `kick sweep3d`.
#[test]
fn the_slurm_example_shards_a_sweep3d_locally() {
    let dir = scratch("slurm-sweep");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out = Command::new("bash")
        .arg(root.join("experiments/slurm/submit.sh"))
        .env("PATH", path_without_sbatch())
        .env("SWEEP", "sweep3d --samples 30 --seed 2")
        .env("NAME", "spin")
        .env("OUT", dir.join("shards"))
        .env("KICK", env!("CARGO_BIN_EXE_kick"))
        .env("SHARDS", "3")
        .env_remove("SLURM_CPUS_PER_TASK")
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("shard 1/3: samples 10..20") && stdout.contains("3 shards, 30 rows"), "{stdout}");

    let whole = dir.join("whole/spin.h5");
    let done = kick(&["sweep3d", "--samples", "30", "--seed", "2", "--out", whole.to_str().unwrap()]);
    assert!(done.status.success(), "{}", String::from_utf8_lossy(&done.stderr));
    let (merged, whole) =
        (kick_store::ResultFile::open(&dir.join("shards/spin.h5")).unwrap(), kick_store::ResultFile::open(&whole).unwrap());
    for dataset in ["parameters/offset", "parameters/foot_inertia_y", "outcomes/spin_z", "outcomes/speed", "outcomes/energy_friction_loss"]
    {
        let bits = |f: &kick_store::ResultFile| f.values(dataset).unwrap().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&merged), bits(&whole), "{dataset}");
    }
    assert_eq!(merged.values("outcomes/spin_z").unwrap().len(), 30);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `kick run --shard I/N` of a 3D experiment and `kick merge`: the same
/// table, grid and every cell as `kick run` of the whole grid.
#[test]
fn a_3d_experiment_runs_in_shards_and_merges() {
    let dir = scratch("grid3d");
    let file = dir.join("spin.toml");
    std::fs::write(
        &file,
        "[kick3d]\nfriction = 0.5\n[[sweep]]\nparameter = \"offset\"\nvalues = [0.0, 0.02, 0.04, 0.06, 0.08]\n\
                          [[sweep]]\nparameter = \"approach_angle\"\nvalues = [-10.0, 10.0]\n",
    )
    .unwrap();
    let parts = dir.join("parts");
    let mut names = Vec::new();
    for given in ["0/2", "1/2"] {
        let done = kick(&["run", file.to_str().unwrap(), "--out", parts.to_str().unwrap(), "--shard", given]);
        assert!(done.status.success(), "{}", String::from_utf8_lossy(&done.stderr));
        names.push(parts.join(format!("spin.shard-{}-of-2.h5", &given[..1])).to_str().unwrap().to_string());
    }
    let merged = dir.join("merged.h5");
    let done = kick(&["merge", merged.to_str().unwrap(), &names[1], &names[0]]);
    assert!(done.status.success(), "{}", String::from_utf8_lossy(&done.stderr));
    assert!(String::from_utf8_lossy(&done.stdout).contains("2 shards, 10 rows"));
    let whole = kick(&["run", file.to_str().unwrap(), "--out", dir.join("whole").to_str().unwrap()]);
    assert!(whole.status.success(), "{}", String::from_utf8_lossy(&whole.stderr));
    let mut merged = kick_store::SweepData::read(&merged).unwrap();
    let whole = kick_store::SweepData::read(&dir.join("whole/spin.h5")).unwrap();
    assert_eq!(merged.grid_shape(), Some(vec![5, 2]));
    merged.path = whole.path.clone();
    assert_eq!(merged, whole);
    let _ = std::fs::remove_dir_all(&dir);
}

/// An output that is one of the inputs, or not `.h5`, is refused naming the
/// argument, and the input is left as it was (issue 21); also when it names
/// the input through a directory that does not exist yet (issue 33, fault 1:
/// `nodir/../PART` was created and the part replaced), and nothing is created.
#[test]
fn merge_refuses_an_output_that_would_replace_an_input() {
    let dir = scratch("overwrite");
    let file = dir.join("grid.toml");
    std::fs::write(&file, GRID).unwrap();
    let parts = dir.join("parts");
    let mut names = Vec::new();
    for given in ["0/2", "1/2"] {
        let done = kick(&["run", file.to_str().unwrap(), "--out", parts.to_str().unwrap(), "--shard", given]);
        assert!(done.status.success(), "{}", String::from_utf8_lossy(&done.stderr));
        names.push(parts.join(format!("grid.shard-{}-of-2.h5", &given[..1])).to_str().unwrap().to_string());
    }
    let before = std::fs::read(&names[0]).unwrap();
    let toml = std::fs::read(&file).unwrap();
    let through = format!("{}/nodir/../grid.shard-0-of-2.h5", parts.display());
    for (out, says) in
        [(names[0].as_str(), "is the input"), (file.to_str().unwrap(), "must end in `.h5`"), (through.as_str(), "is the input")]
    {
        let done = kick(&["merge", out, &names[0], &names[1]]);
        assert_eq!(done.status.code(), Some(1), "{out}");
        let stderr = String::from_utf8_lossy(&done.stderr);
        assert!(stderr.contains(&format!("`OUT` = `{out}`")) && stderr.contains(says), "{stderr}");
    }
    assert_eq!(std::fs::read(&names[0]).unwrap(), before);
    assert_eq!(std::fs::read(&file).unwrap(), toml);
    assert!(!parts.join("nodir").exists(), "the refusal created the missing directory");
    // A directory where the file goes is refused before any row is solved.
    std::fs::create_dir_all(dir.join("whole/grid.h5")).unwrap();
    let done = kick(&["run", file.to_str().unwrap(), "--out", dir.join("whole").to_str().unwrap()]);
    assert_eq!(done.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(stderr.contains("grid.h5") && stderr.contains("it is a directory; give a file name"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// 1,200 parts merge with at most 256 open files (one part open at a time),
/// into the file an unsharded run writes (issue 21).
#[test]
fn many_parts_merge_under_a_low_open_file_limit() {
    let dir = scratch("many");
    let values = |n: usize, from: f64, step: f64| (0..n).map(|i| format!("{}", from + step * i as f64)).collect::<Vec<_>>().join(", ");
    let text = format!(
        "solver = \"accurate\"\n[[sweep]]\nparameter = \"stiffness\"\nvalues = [{}]\n[[sweep]]\nparameter = \"damping\"\nvalues = [{}]\n",
        values(40, 2e5, 2e4),
        values(30, 0.0, 4.0)
    );
    let file = dir.join("many.toml");
    std::fs::write(&file, &text).unwrap();
    let experiment = kick_study::experiment::parse(&file, &text).unwrap();
    let count = 1200;
    let parts: Vec<String> = (0..count)
        .map(|i| {
            let shard = kick_study::shard::Shard::parse(&format!("{i}/{count}"), "--shard").unwrap();
            kick_store::shard::run_shard(&experiment, shard, &dir.join("parts"), false).unwrap();
            dir.join("parts").join(shard.file_name("many")).to_str().unwrap().to_string()
        })
        .collect();
    let merged = dir.join("merged.h5");
    let out = Command::new("bash")
        .arg("-c")
        .arg("ulimit -n 256 && exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_kick"))
        .arg("merge")
        .arg(&merged)
        .args(&parts)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains("1200 shards, 1200 rows"));
    let whole = kick_store::run(&experiment, &dir.join("whole"), false).unwrap().path;
    let mut merged = kick_store::SweepData::read(&merged).unwrap();
    let whole = kick_store::SweepData::read(&whole).unwrap();
    merged.path = whole.path.clone();
    assert_eq!(merged, whole);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Shards written with and without `--compress` are two commands' parts: the
/// merge refuses them naming the flag (it stored every column as its first
/// part did), and writes nothing.
#[test]
fn merge_refuses_parts_of_different_compression() {
    let dir = scratch("compress");
    let out = dir.join("s.h5");
    for (shard, compress) in [("0/2", true), ("1/2", false)] {
        let mut args = vec!["sweep", "--samples", "40", "--seed", "1", "--threads", "1", "--out", out.to_str().unwrap(), "--shard", shard];
        if compress {
            args.push("--compress");
        }
        let done = kick(&args);
        assert!(done.status.success(), "{}", String::from_utf8_lossy(&done.stderr));
    }
    let parts = [dir.join("s.shard-0-of-2.h5"), dir.join("s.shard-1-of-2.h5")];
    let merged = dir.join("merged.h5");
    let done = kick(&["merge", merged.to_str().unwrap(), parts[0].to_str().unwrap(), parts[1].to_str().unwrap()]);
    assert_eq!(done.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert!(stderr.contains("stored with filters none here, shuffle + deflate 4") && stderr.contains("--compress"), "{stderr}");
    assert!(!merged.exists());
    let _ = std::fs::remove_dir_all(&dir);
}
