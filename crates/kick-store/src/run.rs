//! Run an experiment of the 1D model into a result file: the thin 1D layer
//! over [`crate::h5::SweepWriter`].

use crate::experiment::{Experiment, Output, Scenarios};
use crate::h5::{Column, H5Error, OutcomeSet, Setting, SweepWriter, CHUNK_ROWS};
use crate::provenance::Provenance;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use kick_compliant::SolverChoice;
use kick_core::{KickError, Outcome, Parameter, RecordingSolver, Scenario, Solver, Spacing, HISTORY_COLUMNS, OBSERVABLES};
use rayon::prelude::*;
use std::io::IsTerminal;
use std::ops::ControlFlow;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::sync::Mutex;

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

/// Solve one scenario with one solver; summary only, no allocation unless it fails.
fn solve(solver: &SolverChoice, scenario: &Result<Scenario, KickError>) -> Result<Outcome, KickError> {
    scenario.clone().and_then(|s| solver.solve(&s))
}

/// One chunk of rows of a summary run: its scenarios and every solver's results.
struct Chunk {
    start: u64,
    end: u64,
    scenarios: Vec<Result<Scenario, KickError>>,
    outcomes: Vec<Vec<Result<Outcome, KickError>>>,
    /// Per solver, the flights after its kicks (experiments with `[flight]`).
    flights: Vec<Vec<Result<Vec<f64>, String>>>,
}

impl Chunk {
    fn new(solvers: usize) -> Chunk {
        Chunk {
            start: 0,
            end: 0,
            scenarios: Vec::with_capacity(CHUNK_ROWS),
            outcomes: vec![Vec::with_capacity(CHUNK_ROWS); solvers],
            flights: vec![Vec::new(); solvers],
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
            self.scenarios.par_iter().map(|s| solve(solver, s)).collect_into_vec(&mut self.outcomes[k]);
            if let Some(rest) = &experiment.flight {
                self.scenarios
                    .par_iter()
                    .zip(&self.outcomes[k])
                    .map(|(s, o)| fly_1d(rest, s, o))
                    .collect_into_vec(&mut self.flights[k]);
            }
        }
    }

    /// Append the chunk's rows to the file, in order; nothing when empty.
    fn write(&self, experiment: &Experiment, writer: &mut SweepWriter) -> Result<(), RunError> {
        if self.start == self.end {
            return Ok(());
        }
        for (j, scenario) in self.scenarios.iter().enumerate() {
            push_row(writer, experiment, scenario, self.outcomes.iter().map(|o| &o[j]))?;
            if experiment.flight.is_some() {
                push_flights(writer, experiment, self.flights.iter().map(|f| &f[j]))?;
            }
        }
        Ok(())
    }
}

/// One row of the table: the scenario's parameters and each set's outcome.
fn push_row<'a>(
    writer: &mut SweepWriter,
    experiment: &Experiment,
    scenario: &Result<Scenario, KickError>,
    outcomes: impl Iterator<Item = &'a Result<Outcome, KickError>>,
) -> Result<(), RunError> {
    let mut values = [f64::NAN; 9];
    if let Ok(s) = scenario {
        values[..8].copy_from_slice(&s.values());
        values[8] = s.restitution_target().unwrap_or(f64::NAN);
    }
    writer.push_parameters(&values[..if experiment.scenarios.has_restitution() { 9 } else { 8 }])?;
    for (k, result) in outcomes.enumerate() {
        match result {
            Ok(o) => writer.push_outcome(k, Ok(&o.observable_values()))?,
            Err(e) => writer.push_outcome(k, Err(&e.to_string()))?,
        }
    }
    Ok(())
}

/// The flight after one 1D kick, in [`crate::flight::flight_columns`] order.
fn fly_1d(rest: &kick_flight::FlightSpec, scenario: &Result<Scenario, KickError>, outcome: &Result<Outcome, KickError>) -> Result<Vec<f64>, String> {
    match (scenario, outcome) {
        (Ok(s), Ok(o)) => crate::flight::after_1d(s, o, rest)
            .map(|run| crate::flight::flight_values(&run.outcome, rest.distance.is_some())),
        (Err(e), _) | (_, Err(e)) => Err(format!("no flight: the kick failed: {e}")),
    }
}

/// The row's flight outcomes, one set per solver after the kick sets.
fn push_flights<'a>(
    writer: &mut SweepWriter,
    experiment: &Experiment,
    flights: impl Iterator<Item = &'a Result<Vec<f64>, String>>,
) -> Result<(), RunError> {
    let first = experiment.solvers.len();
    for (k, flight) in flights.enumerate() {
        match flight {
            Ok(values) => writer.push_outcome(first + k, Ok(values))?,
            Err(e) => writer.push_outcome(first + k, Err(e))?,
        }
    }
    Ok(())
}

/// Samples per streamed block of a history, and per HDF5 chunk of a long one.
const HISTORY_BLOCK: usize = CHUNK_ROWS;
/// Blocks a row may have in flight to the writer.
const HISTORY_BLOCKS_IN_FLIGHT: usize = 2;

/// From a worker solving one row to the writer.
enum Message {
    /// The next samples of set `set`'s history, one vector per column.
    Block { set: usize, columns: Vec<Vec<f64>> },
    /// Set `set` solved: its outcome and the last samples.
    Done { set: usize, result: Result<Outcome, KickError>, columns: Vec<Vec<f64>> },
}

fn empty_block() -> Vec<Vec<f64>> {
    (0..HISTORY_COLUMNS.len()).map(|_| Vec::with_capacity(HISTORY_BLOCK)).collect()
}

/// Solve scenario `row` with every solver, streaming each history to `to_writer`
/// in blocks: a worker holds one block, the channel a few.
fn stream_row(experiment: &Experiment, row: u64, interval: f64, to_writer: &SyncSender<Message>) {
    let scenario = experiment.scenarios.scenario(row);
    for (set, solver) in experiment.solvers.iter().enumerate() {
        let mut block = empty_block();
        let result = scenario.clone().and_then(|s| {
            let mut sink = |sample: &kick_core::Sample| {
                for (column, value) in block.iter_mut().zip(sample.values()) {
                    column.push(value);
                }
                if block[0].len() == HISTORY_BLOCK {
                    let full = std::mem::replace(&mut block, empty_block());
                    if to_writer.send(Message::Block { set, columns: full }).is_err() {
                        // The writer stopped; the solve ends without sampling.
                        return ControlFlow::Break(());
                    }
                }
                ControlFlow::Continue(())
            };
            solver.solve_streamed(&s, Spacing::Interval(interval), &mut sink).map(|streamed| streamed.outcome)
        });
        if to_writer.send(Message::Done { set, result, columns: block }).is_err() {
            return;
        }
    }
}

/// Histories of the experiment's rows `part` (file rows from 0), written in
/// row order as they are solved.
///
/// Rows are claimed in order by `threads` workers, each streaming its row's
/// histories through a bounded channel of that row; the writer empties the
/// rows' channels in order. The row the writer waits for is always being
/// solved (claimed before any later row), so nothing waits in a circle, and
/// memory is a few blocks per worker whatever the histories' lengths. The
/// file's content does not depend on the number of threads.
fn write_histories(
    experiment: &Experiment,
    part: &Range<u64>,
    writer: &mut SweepWriter,
    interval: f64,
    bar: &ProgressBar,
) -> Result<(), RunError> {
    let rows = (part.end - part.start) as usize;
    let solvers = experiment.solvers.len();
    let threads = rayon::current_num_threads().clamp(1, rows.max(1));
    let (senders, receivers): (Vec<_>, Vec<_>) =
        (0..rows).map(|_| sync_channel::<Message>(HISTORY_BLOCKS_IN_FLIGHT)).map(|(s, r)| (Mutex::new(Some(s)), r)).unzip();
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                while !stop.load(Ordering::Relaxed) {
                    let row = next.fetch_add(1, Ordering::Relaxed);
                    if row >= rows {
                        break;
                    }
                    let sender = senders[row].lock().unwrap_or_else(|e| e.into_inner()).take();
                    if let Some(sender) = sender {
                        stream_row(experiment, part.start + row as u64, interval, &sender);
                    }
                }
            });
        }
        let written = receive_histories(experiment, part.start, writer, receivers, solvers, bar);
        // On an error the receivers are gone: workers stop at their next send.
        stop.store(true, Ordering::Relaxed);
        written
    })
}

fn receive_histories(
    experiment: &Experiment,
    first: u64,
    writer: &mut SweepWriter,
    receivers: Vec<Receiver<Message>>,
    solvers: usize,
    bar: &ProgressBar,
) -> Result<(), RunError> {
    let names: Vec<Column> = HISTORY_COLUMNS.iter().map(|(n, u)| Column::new(n, u)).collect();
    fn pair<'a>(columns: &[Column], values: &'a [Vec<f64>]) -> Vec<(Column, &'a [f64])> {
        columns.iter().cloned().zip(values.iter().map(Vec::as_slice)).collect()
    }
    let mut outcomes: Vec<Result<Outcome, KickError>> = Vec::with_capacity(solvers);
    for (row, receiver) in receivers.into_iter().enumerate() {
        outcomes.clear();
        let mut streamed = vec![false; solvers];
        while outcomes.len() < solvers {
            let message = receiver.recv().map_err(|_| RunError::Worker { row })?;
            match message {
                Message::Block { set, columns } => {
                    writer.append_history(set, row, &pair(&names, &columns))?;
                    streamed[set] = true;
                }
                Message::Done { set, result, columns } => {
                    match (&result, streamed[set]) {
                        (Ok(_), true) => writer.append_history(set, row, &pair(&names, &columns))?,
                        (Ok(_), false) => writer.write_history(set, row, &pair(&names, &columns))?,
                        (Err(_), true) => writer.remove_history(set, row)?,
                        (Err(_), false) => {}
                    }
                    outcomes.push(result);
                }
            }
        }
        let scenario = experiment.scenarios.scenario(first + row as u64);
        push_row(writer, experiment, &scenario, outcomes.iter())?;
        if let Some(rest) = &experiment.flight {
            let flights: Vec<_> = outcomes.iter().map(|o| fly_1d(rest, &scenario, o)).collect();
            push_flights(writer, experiment, flights.iter())?;
        }
        bar.inc(1);
    }
    Ok(())
}

/// Run `experiment` and write `out_dir/NAME.h5`.
///
/// Refused before it starts beyond the bounds of [`crate::limits::check`]
/// (rows, free space); with `show_progress`, a large run states its size on
/// stderr first and draws a progress bar on a terminal.
///
/// Scenarios are solved in parallel (rayon's current pool, or as many
/// threads for histories) and written in input order, so the file does not
/// depend on the number of threads. Summary runs go chunk by chunk, a chunk
/// written while the next one is solved, two chunks of outcomes in memory;
/// histories are streamed to the file in blocks (see `write_histories`), so
/// memory does not grow with their length.
pub fn run(experiment: &Experiment, out_dir: &Path, show_progress: bool) -> Result<RunSummary, RunError> {
    let part = Part { rows: 0..experiment.scenarios.len(), path: out_dir.join(format!("{}.h5", experiment.name)) };
    run_part(experiment, &part, show_progress, &|_| Ok(()))
}

/// Rows of an experiment and the file they go to (a shard: [`crate::shard`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Experiment rows, written as the file's rows 0.. (histories and
    /// failures numbered by file row).
    pub rows: Range<u64>,
    pub path: PathBuf,
}

/// [`run`] of the rows `part.rows` into `part.path`; `attributes` adds root
/// attributes of the caller's to the open file.
pub fn run_part(
    experiment: &Experiment,
    part: &Part,
    show_progress: bool,
    attributes: &dyn Fn(&hdf5::File) -> Result<(), H5Error>,
) -> Result<RunSummary, RunError> {
    let out_dir = part.path.parent().unwrap_or(Path::new("."));
    let size = crate::limits::check(experiment, &part.rows, out_dir)?;
    let path = part.path.clone();
    if show_progress && size.is_large() {
        eprintln!("{}: {} -> {}", experiment.name, size.describe(), path.display());
    }
    let provenance = Provenance::now(&experiment.name, &experiment.path.display().to_string(), &experiment.text);
    // One law for every scenario of an experiment (the file's `law`).
    let law = experiment.scenarios.scenario(0).map_or(kick_core::LawKind::PowerLaw, |s| s.law_kind());
    let mut sets: Vec<OutcomeSet> = experiment.solvers.iter().map(|s| outcome_set(s, law)).collect();
    if let Some(rest) = &experiment.flight {
        let flown = kick_flight::FlightSpec { speed: Some(1.0), ..*rest }.build().ok();
        let flight_sets: Vec<OutcomeSet> =
            experiment.solvers.iter().map(|s| crate::flight::flight_set(s.name(), rest, flown.as_ref())).collect();
        sets.extend(flight_sets);
    }
    let mut writer = SweepWriter::create_with(
        &path,
        &provenance,
        &parameter_columns(experiment.scenarios.has_restitution()),
        &sets,
        part.rows.end - part.rows.start,
        experiment.compress,
    )?;
    crate::h5::write_str_attr(writer.file(), &path, "description", &experiment.description)?;
    if let Some(names) = experiment.scenarios.names() {
        let names = &names[part.rows.start as usize..part.rows.end as usize];
        crate::h5::write_strings(writer.file(), &path, "scenario_names", names)?;
        crate::h5::write_printed_table2(writer.file(), &path, names)?;
    }
    if let Scenarios::Grid { axes, .. } = &experiment.scenarios {
        // The grid's shape (the whole experiment's, in a shard too).
        let coordinates: Vec<(Column, &[f64])> =
            axes.iter().map(|a| (Column::new(a.parameter.name(), a.parameter.unit()), a.values.as_slice())).collect();
        if !coordinates.is_empty() {
            crate::h5::write_grid(writer.file(), &path, &coordinates)?;
        }
    }
    attributes(writer.file())?;
    if let Output::History { interval } = experiment.output {
        crate::h5::write_f64_attr(writer.file(), &path, "history_interval", interval)?;
    }

    let total = part.rows.end;
    let bar = progress(part.rows.end - part.rows.start, show_progress);
    bar.set_message(experiment.name.clone());
    if let Output::History { interval } = experiment.output {
        write_histories(experiment, &part.rows, &mut writer, interval, &bar)?;
        return finish(experiment, writer, &bar);
    }
    // Two chunks in flight: while one is written (HDF5 is serial), the next is
    // solved on the rest of the pool. Their buffers are swapped, not reallocated.
    let mut solving = Chunk::new(experiment.solvers.len());
    let mut writing = Chunk::new(experiment.solvers.len());
    let mut start = part.rows.start;
    while start < total || writing.start < writing.end {
        let end = (start + CHUNK_ROWS as u64).min(total);
        let (written, ()) = rayon::join(
            || writing.write(experiment, &mut writer),
            || solving.solve(experiment, start, end),
        );
        written?;
        bar.inc(writing.end - writing.start);
        std::mem::swap(&mut solving, &mut writing);
        solving.start = end;
        solving.end = end;
        start = end;
    }
    finish(experiment, writer, &bar)
}

fn finish(experiment: &Experiment, writer: SweepWriter, bar: &ProgressBar) -> Result<RunSummary, RunError> {
    bar.finish_and_clear();
    let mut names: Vec<String> = experiment.solvers.iter().map(|s| s.name().to_string()).collect();
    if experiment.flight.is_some() {
        names.extend(experiment.solvers.iter().map(|s| crate::flight::flight_set_name(s.name())));
    }
    let failures = names.into_iter().zip(writer.failure_counts()).collect();
    let scenarios = writer.rows() as u64;
    let path = writer.finish()?;
    Ok(RunSummary { path, scenarios, failures })
}

/// What `kick_store::shard::run_file` did: the file given, the result file and the counts.
#[derive(Debug, Clone, serde::Serialize)]
pub struct RunReport {
    pub file: PathBuf,
    pub summary: RunSummary,
    pub seconds: f64,
}

impl crate::Printable for RunReport {
    fn text(&self) -> String {
        let failures: Vec<String> = self.summary.failures.iter().map(|(solver, n)| format!("{solver}: {n} failed")).collect();
        format!(
            "{}: {} scenarios -> {} ({}; {} s)\n",
            self.file.display(),
            self.summary.scenarios,
            self.summary.path.display(),
            failures.join(", "),
            kick_core::sig(self.seconds)
        )
    }
}
