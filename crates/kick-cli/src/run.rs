//! `kick run FILE.toml [--out DIR]`: one experiment into `DIR/NAME.h5`.

use crate::output::CliResult;
use std::path::{Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Experiment file (experiments/*.toml)
    file: PathBuf,
    /// Directory for the result file NAME.h5
    #[arg(long, default_value = "results")]
    out: PathBuf,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
}

/// Use `threads` rayon workers for the rest of the process (if given), within the machine's bound.
pub fn set_threads(threads: Option<usize>) -> CliResult {
    kick_runner::limits::use_threads(threads, "--threads").map_err(|e| e.to_string())
}

/// Load, run and report one experiment file; returns the result file's path.
pub fn run_file(file: &Path, out: &Path) -> Result<PathBuf, String> {
    let experiment = kick_runner::experiment::load(file).map_err(|e| e.to_string())?;
    let started = std::time::Instant::now();
    let summary = kick_runner::run(&experiment, out, true).map_err(|e| e.to_string())?;
    let failures: Vec<String> = summary
        .failures
        .iter()
        .map(|(solver, n)| format!("{solver}: {n} failed"))
        .collect();
    println!(
        "{}: {} scenarios -> {} ({}; {:.1} s)",
        file.display(),
        summary.scenarios,
        summary.path.display(),
        failures.join(", "),
        started.elapsed().as_secs_f64()
    );
    Ok(summary.path)
}

pub fn run(args: Args) -> CliResult {
    set_threads(args.threads)?;
    run_file(&args.file, &args.out).map(|_| ())
}
