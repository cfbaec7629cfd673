//! Run an experiment into a result file: the thin layer over
//! [`crate::h5::SweepWriter`] for either level (a 3D experiment's own
//! groups are [`crate::three_d`]'s).

use crate::experiment::{Experiment, Kicks, Output, Scenarios};
use crate::h5::{Column, Compression, H5Error, CHUNK_ROWS};
use crate::provenance::Provenance;
use crate::table::progress;
use crate::writer::SweepWriter;
use indicatif::ProgressBar;
use kick_core::{KickError, Outcome, RecordingSolver, Spacing, HISTORY_COLUMNS};
use kick_study::level::one_d::OneD;
use kick_study::level::{Level, RowSink};
use std::ops::ControlFlow;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::sync::Mutex;

pub use crate::table::{create_table, fill_table, finish_table, Part, RunError, RunSummary};
pub use kick_study::level::one_d::{outcome_columns, outcome_set, parameter_columns};

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
fn stream_row(level: OneD, row: u64, interval: f64, to_writer: &SyncSender<Message>) {
    let scenario = level.kicks.scenarios.scenario(row);
    for (set, solver) in level.kicks.solvers.iter().enumerate() {
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
fn write_histories(level: OneD, part: &Range<u64>, writer: &mut SweepWriter, interval: f64, bar: &ProgressBar) -> Result<(), RunError> {
    let rows = (part.end - part.start) as usize;
    let solvers = level.kicks.solvers.len();
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
                        stream_row(level, part.start + row as u64, interval, &sender);
                    }
                }
            });
        }
        let written = receive_histories(level, part.start, writer, receivers, solvers, bar);
        // On an error the receivers are gone: workers stop at their next send.
        stop.store(true, Ordering::Relaxed);
        written
    })
}

fn receive_histories(
    level: OneD,
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
    let mut table_row = level.empty_row();
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
        let scenario = level.kicks.scenarios.scenario(first + row as u64);
        level.fill_row(first + row as u64, &scenario, &outcomes, &mut table_row);
        writer.push_row(&table_row)?;
        bar.inc(1);
    }
    Ok(())
}

/// Run `experiment` (1D or 3D) and write `out_dir/NAME.h5`.
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
    let part = Part { rows: 0..experiment.rows(), path: out_dir.join(format!("{}.h5", experiment.name)) };
    run_part(experiment, &part, show_progress, &|_| Ok(()))
}

/// [`run`] of the rows `part.rows` into `part.path`; `attributes` adds root
/// attributes of the caller's to the open file.
pub fn run_part(
    experiment: &Experiment,
    part: &Part,
    show_progress: bool,
    attributes: &dyn Fn(&hdf5::File) -> Result<(), H5Error>,
) -> Result<RunSummary, RunError> {
    let kicks = match &experiment.kicks {
        Kicks::OneD(kicks) => kicks,
        Kicks::ThreeD(kicks) => return crate::three_d::run_part(experiment, kicks, part, attributes),
        Kicks::Bounce(kicks) => return crate::three_d::run_bounce_part(experiment, kicks, part, attributes),
    };
    let level = OneD { kicks, flight: experiment.flight.as_ref() };
    let out_dir = part.path.parent().unwrap_or(Path::new("."));
    let size = kick_study::limits::OutputSize::check(experiment, &part.rows, out_dir)?;
    let path = part.path.clone();
    if show_progress && size.is_large() {
        eprintln!("{}: {} -> {}", experiment.name, size.describe(), path.display());
    }
    let provenance = Provenance::now(&experiment.name, &experiment.path.display().to_string(), &experiment.text);
    let mut writer = create_table(experiment, &path, &provenance, part.rows.end - part.rows.start, experiment.compress)?;
    crate::h5::write_str_attr(writer.file(), &path, "description", &experiment.description)?;
    if let Some(names) = kicks.scenarios.names() {
        let names = &names[part.rows.start as usize..part.rows.end as usize];
        crate::h5::write_strings(writer.file(), &path, "scenario_names", names)?;
        crate::h5::write_printed_table2(writer.file(), &path, names)?;
    }
    if let Scenarios::Grid { grid, .. } = &kicks.scenarios {
        // The grid's shape (the whole experiment's, in a shard too).
        let coordinates: Vec<(Column, &[f64])> = grid.columns().into_iter().zip(grid.axes.iter().map(|a| a.values.as_slice())).collect();
        if !coordinates.is_empty() {
            crate::h5::write_grid(writer.file(), &path, &coordinates)?;
        }
    }
    attributes(writer.file())?;
    if let Output::History { interval } = experiment.output {
        crate::h5::write_f64_attr(writer.file(), &path, "history_interval", interval)?;
    }

    let bar = progress(part.rows.end - part.rows.start, show_progress);
    bar.set_message(experiment.name.clone());
    match experiment.output {
        Output::History { interval } => write_histories(level, &part.rows, &mut writer, interval, &bar)?,
        Output::Summary => fill_table(experiment, part.rows.clone(), &mut writer, &bar)?,
    }
    finish_table(experiment, writer, &bar)
}

/// Whole levels as tables `dir/NAME.h5` (a command's own figure data, e.g.
/// `kick leg --sweep-out`), one after the other, each recording `source`
/// and `command` as its provenance.
pub fn write_levels(dir: &Path, tables: &[(&str, &dyn Level)], source: &str, command: &str) -> Result<Vec<PathBuf>, RunError> {
    let mut written = Vec::new();
    for &(name, level) in tables {
        let path = dir.join(format!("{name}.h5"));
        let provenance = Provenance::now(name, source, command);
        let bar = ProgressBar::hidden();
        let mut writer = create_table(level, &path, &provenance, level.rows(), Compression::default())?;
        fill_table(level, 0..level.rows(), &mut writer, &bar)?;
        written.push(finish_table(level, writer, &bar)?.path);
    }
    Ok(written)
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
        let failures: Vec<String> = self
            .summary
            .failures
            .iter()
            .zip(&self.summary.outside_validity)
            .map(|((solver, n), (_, outside))| match outside {
                0 => format!("{solver}: {n} failed"),
                _ => format!("{solver}: {n} failed, {outside} outside the law's validity"),
            })
            .collect();
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
