//! Run an experiment of the 1D model into a result file: the thin 1D layer
//! over [`crate::h5::SweepWriter`].

use crate::experiment::{Experiment, Output};
use crate::h5::{Column, H5Error, OutcomeSet, Setting, SweepWriter, CHUNK_ROWS};
use crate::provenance::Provenance;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use kick_compliant::SolverChoice;
use kick_core::{History, KickError, Outcome, Parameter, RecordingSolver, Scenario, Solver, OBSERVABLES};
use rayon::prelude::*;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

/// Names and units of the columns of a recorded history (the fields of [`kick_core::Sample`]).
pub const HISTORY_COLUMNS: [(&str, &str); 11] = [
    ("time", "s"),
    ("foot_position", "m"),
    ("foot_velocity", "m/s"),
    ("ball_position", "m"),
    ("ball_velocity", "m/s"),
    ("compression", "m"),
    ("force", "N"),
    ("kinetic", "J"),
    ("elastic", "J"),
    ("dissipated", "J"),
    ("drive_work", "J"),
];

#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    H5(#[from] H5Error),
    #[error("cannot create {path}: {message}")]
    Io { path: PathBuf, message: String },
}

/// What a run produced.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RunSummary {
    pub path: PathBuf,
    pub scenarios: u64,
    /// Failed scenarios per solver, in the experiment's solver order.
    pub failures: Vec<(String, u64)>,
}

/// Parameter columns of the 1D model: the eight [`Parameter`]s, and the
/// target restitution when the law takes one (names and units as declared).
pub fn parameter_columns(with_restitution: bool) -> Vec<Column> {
    let mut columns: Vec<Column> = Parameter::ALL.iter().map(|p| Column::new(p.name(), p.unit())).collect();
    if with_restitution {
        let e = &kick_core::parameters::RESTITUTION;
        columns.push(Column::new(e.name, e.unit));
    }
    columns
}

/// Outcome columns of the 1D model: [`OBSERVABLES`].
pub fn outcome_columns() -> Vec<Column> {
    OBSERVABLES.iter().map(|(n, u)| Column::new(n, u)).collect()
}

/// The outcome-set description of a solver: its name, its settings and the
/// scenarios' contact law (`law`; the target restitution is a parameter column).
pub fn outcome_set(solver: &SolverChoice, law: kick_core::LawKind) -> OutcomeSet {
    let mut settings = Setting::numbers(solver.settings());
    settings.push(("law".into(), Setting::Text(law.name().into())));
    OutcomeSet { solver: solver.name().to_string(), settings, columns: outcome_columns() }
}

fn history_columns(history: &History) -> Vec<(Column, Vec<f64>)> {
    let s = &history.samples;
    let pick = |f: fn(&kick_core::Sample) -> f64| s.iter().map(f).collect::<Vec<f64>>();
    let data = [
        pick(|x| x.time),
        pick(|x| x.foot_position),
        pick(|x| x.foot_velocity),
        pick(|x| x.ball_position),
        pick(|x| x.ball_velocity),
        pick(|x| x.compression),
        pick(|x| x.force),
        pick(|x| x.kinetic),
        pick(|x| x.elastic),
        pick(|x| x.dissipated),
        pick(|x| x.drive_work),
    ];
    HISTORY_COLUMNS.iter().zip(data).map(|((n, u), v)| (Column::new(n, u), v)).collect()
}

/// A progress bar on a terminal, nothing otherwise.
fn progress(total: u64, show: bool) -> ProgressBar {
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

/// Solve one scenario with one solver; summary only, no allocation unless it fails.
fn solve(solver: &SolverChoice, scenario: &Result<Scenario, KickError>) -> Result<Outcome, KickError> {
    scenario.clone().and_then(|s| solver.solve(&s))
}

/// One chunk of rows: its scenarios and every solver's results.
struct Chunk {
    start: u64,
    end: u64,
    scenarios: Vec<Result<Scenario, KickError>>,
    outcomes: Vec<Vec<Result<Outcome, KickError>>>,
    histories: Vec<Vec<Result<(Outcome, History), KickError>>>,
}

impl Chunk {
    fn new(solvers: usize) -> Chunk {
        Chunk {
            start: 0,
            end: 0,
            scenarios: Vec::with_capacity(CHUNK_ROWS),
            outcomes: vec![Vec::with_capacity(CHUNK_ROWS); solvers],
            histories: vec![Vec::new(); solvers],
        }
    }

    /// Make and solve rows start..end in parallel.
    fn solve(&mut self, experiment: &Experiment, start: u64, end: u64) {
        (self.start, self.end) = (start, end);
        // Scenario i is a pure function of i (sampled sweeps included).
        (0..(end - start) as usize)
            .into_par_iter()
            .map(|j| experiment.scenarios.scenario(start + j as u64))
            .collect_into_vec(&mut self.scenarios);
        for (k, solver) in experiment.solvers.iter().enumerate() {
            match experiment.output {
                Output::Summary => self.scenarios.par_iter().map(|s| solve(solver, s)).collect_into_vec(&mut self.outcomes[k]),
                Output::History { interval } => {
                    self.scenarios
                        .par_iter()
                        .map(|s| s.clone().and_then(|s| solver.solve_recorded(&s, interval)))
                        .collect_into_vec(&mut self.histories[k]);
                }
            }
        }
    }

    /// Append the chunk's rows to the file, in order; nothing when empty.
    fn write(&self, writer: &mut SweepWriter, experiment: &Experiment) -> Result<(), RunError> {
        if self.start == self.end {
            return Ok(());
        }
        for (j, scenario) in self.scenarios.iter().enumerate() {
            let row = self.start as usize + j;
            let mut values = [f64::NAN; 9];
            if let Ok(s) = scenario {
                values[..8].copy_from_slice(&s.values());
                values[8] = s.restitution_target().unwrap_or(f64::NAN);
            }
            writer.push_parameters(&values[..if experiment.scenarios.has_restitution() { 9 } else { 8 }])?;
            for k in 0..experiment.solvers.len() {
                let result = match experiment.output {
                    Output::Summary => self.outcomes[k][j].as_ref().map(|o| o.observable_values()),
                    Output::History { .. } => self.histories[k][j].as_ref().map(|(o, _)| o.observable_values()),
                };
                match result {
                    Ok(values) => writer.push_outcome(k, Ok(&values))?,
                    Err(e) => writer.push_outcome(k, Err(&e.to_string()))?,
                }
                if let Output::History { .. } = experiment.output {
                    if let Ok((_, history)) = &self.histories[k][j] {
                        let columns = history_columns(history);
                        let refs: Vec<(Column, &[f64])> = columns.iter().map(|(c, v)| (c.clone(), v.as_slice())).collect();
                        writer.write_history(k, row, &refs)?;
                    }
                }
            }
        }
        Ok(())
    }
}

/// Run `experiment` and write `out_dir/NAME.h5`.
///
/// Scenarios are solved in parallel (rayon's current pool) chunk by chunk and
/// written in input order, so the file's numbers do not depend on the number
/// of threads; a chunk is written while the next one is solved. Summary-only
/// runs hold two chunks of outcomes at a time.
pub fn run(experiment: &Experiment, out_dir: &Path, show_progress: bool) -> Result<RunSummary, RunError> {
    std::fs::create_dir_all(out_dir).map_err(|e| RunError::Io { path: out_dir.to_path_buf(), message: e.to_string() })?;
    let path = out_dir.join(format!("{}.h5", experiment.name));
    let provenance = Provenance::now(&experiment.name, &experiment.path.display().to_string(), &experiment.text);
    // One law for every scenario of an experiment (the file's `law`).
    let law = experiment.scenarios.scenario(0).map_or(kick_core::LawKind::PowerLaw, |s| s.law_kind());
    let sets: Vec<OutcomeSet> = experiment.solvers.iter().map(|s| outcome_set(s, law)).collect();
    let mut writer = SweepWriter::create(
        &path,
        &provenance,
        &parameter_columns(experiment.scenarios.has_restitution()),
        &sets,
        experiment.scenarios.len(),
    )?;
    crate::h5::write_str_attr(writer.file(), &path, "description", &experiment.description)?;
    if let Some(names) = experiment.scenarios.names() {
        crate::h5::write_strings(writer.file(), &path, "scenario_names", names)?;
    }
    if let Output::History { interval } = experiment.output {
        crate::h5::write_f64_attr(writer.file(), &path, "history_interval", interval)?;
    }

    let total = experiment.scenarios.len();
    let bar = progress(total, show_progress);
    bar.set_message(experiment.name.clone());
    // Two chunks in flight: while one is written (HDF5 is serial), the next is
    // solved on the rest of the pool. Their buffers are swapped, not reallocated.
    let mut solving = Chunk::new(experiment.solvers.len());
    let mut writing = Chunk::new(experiment.solvers.len());
    let mut start = 0u64;
    while start < total || writing.start < writing.end {
        let end = (start + CHUNK_ROWS as u64).min(total);
        let (written, ()) = rayon::join(
            || writing.write(&mut writer, experiment),
            || solving.solve(experiment, start, end),
        );
        written?;
        bar.inc(writing.end - writing.start);
        std::mem::swap(&mut solving, &mut writing);
        solving.start = end;
        solving.end = end;
        start = end;
    }
    bar.finish_and_clear();
    let failures = experiment
        .solvers
        .iter()
        .map(|s| s.name().to_string())
        .zip(writer.failure_counts())
        .collect();
    let path = writer.finish()?;
    Ok(RunSummary { path, scenarios: total, failures })
}

/// What [`run_file`] did: the file given, the result file and the counts.
#[derive(Debug, Clone, serde::Serialize)]
pub struct RunReport {
    pub file: PathBuf,
    pub summary: RunSummary,
    pub seconds: f64,
}

/// Load and run one experiment file into `out/NAME.h5`.
pub fn run_file(file: &Path, out: &Path) -> Result<RunReport, String> {
    let experiment = crate::experiment::load(file).map_err(|e| e.to_string())?;
    let started = std::time::Instant::now();
    let summary = run(&experiment, out, true).map_err(|e| e.to_string())?;
    Ok(RunReport { file: file.to_path_buf(), summary, seconds: started.elapsed().as_secs_f64() })
}

impl crate::Printable for RunReport {
    fn text(&self) -> String {
        let failures: Vec<String> = self.summary.failures.iter().map(|(solver, n)| format!("{solver}: {n} failed")).collect();
        format!(
            "{}: {} scenarios -> {} ({}; {:.1} s)\n",
            self.file.display(),
            self.summary.scenarios,
            self.summary.path.display(),
            failures.join(", "),
            self.seconds
        )
    }
}
