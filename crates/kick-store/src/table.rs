//! A run's table: one level's rows solved by the one run loop
//! ([`kick_study::level::run_rows`]) into a sweep table ([`SweepWriter`]),
//! with its progress bar and summary; what [`crate::run`] and
//! [`crate::three_d`] and `kick sweep3d` share.

use crate::h5::{Compression, H5Error};
use crate::provenance::Provenance;
use crate::writer::SweepWriter;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use kick_study::level::{run_rows, Level};
use std::io::IsTerminal;
use std::ops::Range;
use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    H5(#[from] H5Error),
    #[error("the worker solving row {row} stopped without its result")]
    Worker { row: usize },
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
}

/// What a run produced.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RunSummary {
    pub path: PathBuf,
    pub scenarios: u64,
    /// Failed scenarios per solver, in the experiment's solver order.
    pub failures: Vec<(String, u64)>,
    /// Scenarios per solver whose numbers are kept but lie outside their
    /// contact law's validity (status 4), in the same order.
    pub outside_validity: Vec<(String, u64)>,
}

/// A progress bar on a terminal, nothing otherwise.
pub(crate) fn progress(total: u64, show: bool) -> ProgressBar {
    if show && std::io::stderr().is_terminal() {
        let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
        if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} scenarios, {elapsed} (eta {eta})") {
            bar.set_style(style.progress_chars("=> "));
        }
        bar
    } else {
        ProgressBar::hidden()
    }
}

/// Rows of an experiment and the file they go to (a shard: [`crate::shard`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Experiment rows, written as the file's rows 0.. (histories and
    /// failures numbered by file row).
    pub rows: Range<u64>,
    pub path: PathBuf,
}

/// A new sweep table at `path` shaped as `level`'s rows: its parameter
/// columns and outcome sets ([`SweepWriter`], chunks sized for `rows`).
pub fn create_table<L: Level + ?Sized>(
    level: &L,
    path: &Path,
    provenance: &Provenance,
    rows: u64,
    compress: Compression,
) -> Result<SweepWriter, H5Error> {
    SweepWriter::create_with(path, provenance, &level.parameter_columns(), &level.outcome_sets(), rows, compress)
}

/// Solve rows `rows` of `level` and push them to `writer`: the one run loop
/// ([`kick_study::level::run_rows`]), the bar counting rows written.
pub fn fill_table<L: Level + ?Sized>(level: &L, rows: Range<u64>, writer: &mut SweepWriter, bar: &ProgressBar) -> Result<(), H5Error> {
    run_rows(level, rows, writer, &|n| bar.inc(n))
}

/// Close the table and count each set's rows without values.
pub fn finish_table<L: Level + ?Sized>(level: &L, writer: SweepWriter, bar: &ProgressBar) -> Result<RunSummary, RunError> {
    bar.finish_and_clear();
    let names: Vec<String> = level.outcome_sets().into_iter().map(|s| s.solver).collect();
    let failures = names.iter().cloned().zip(writer.failure_counts()).collect();
    let outside_validity = names.into_iter().zip(writer.outside_validity_counts()).collect();
    let scenarios = writer.rows() as u64;
    let path = writer.finish()?;
    Ok(RunSummary { path, scenarios, failures, outside_validity })
}
