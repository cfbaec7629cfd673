//! One level of the model hierarchy as a study runs it, and the one run
//! loop over its rows.
//!
//! A [`Level`] declares a table: its parameter columns, its outcome sets
//! (one per solver, and one per chained flight) and its number of rows; and
//! it solves a row into a reused [`Row`]. [`run_rows`] is the executor: rows
//! in chunks, a chunk solved in parallel while the one before it goes to a
//! [`RowSink`], rows in order, so what a sink receives does not depend on the
//! number of threads. The loop knows no file format (kick-store's
//! `SweepWriter` is a sink; [`Table`] keeps rows in memory), and a level knows
//! no loop: `kick run` (1D and 3D experiments), `kick sweep`, `kick sweep3d`,
//! their shards (a row range) and the flight chained after a kick are levels
//! run by this one loop. Adding a level, such as the ball's bounce, is
//! implementing the trait.
//!
//! Statuses are [`Status`] codes in every table: 0 separated (an outcome),
//! 1 numerical failure, 2 trapped, 3 refused, 4 outside the contact law's
//! validity (an outcome whose numbers are kept, flagged: [`Row::flag`]).

pub mod bounce;
pub mod laws;
pub mod leg;
pub mod one_d;
pub mod sampled_3d;
pub mod three_d;

use crate::columns::{Column, OutcomeSet};
use crate::experiment::{Experiment, Kicks, Kicks1d, Output, Scenarios, MAX_SCENARIOS};
use crate::limits::{LimitError, OutputSize};
use kick_core::Status;
use kick_core::{Spacing, HISTORY_COLUMNS, OBSERVABLES};
use rayon::prelude::*;
use std::ops::Range;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

/// Rows solved together: a chunk is solved while the one before it is written.
pub const CHUNK_ROWS: usize = 4096;

pub use crate::error::Failure;

impl From<Failure> for String {
    fn from(f: Failure) -> String {
        f.message
    }
}

/// One row of a level's table, reused from row to row (no allocation on a
/// summary path once a chunk's rows exist).
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The parameter values, in [`Level::parameter_columns`] order.
    pub parameters: Vec<f64>,
    /// Per outcome set, its values in its column order (NaN where it failed).
    pub outcomes: Vec<Vec<f64>>,
    /// Per outcome set, why it has no values, or (a status that keeps
    /// them, [`Status::has_outcome`]) why its values are flagged.
    pub failures: Vec<Option<Failure>>,
}

impl Row {
    /// An empty row shaped as `level`'s table.
    pub fn shaped(parameters: usize, sets: &[OutcomeSet]) -> Row {
        Row {
            parameters: vec![f64::NAN; parameters],
            outcomes: sets.iter().map(|s| vec![f64::NAN; s.columns.len()]).collect(),
            failures: vec![None; sets.len()],
        }
    }

    /// Set `set`'s values (as many as its columns; the rest stay NaN).
    pub fn set(&mut self, set: usize, values: &[f64]) {
        let out = &mut self.outcomes[set];
        let n = out.len().min(values.len());
        out[..n].copy_from_slice(&values[..n]);
        out[n..].fill(f64::NAN);
        self.failures[set] = None;
    }

    /// Set `set` failed: NaN values and why.
    pub fn fail(&mut self, set: usize, failure: Failure) {
        self.outcomes[set].fill(f64::NAN);
        self.failures[set] = Some(failure);
    }

    /// Flag set `set`'s values, kept as they are, with a status that keeps
    /// them (outside the law's validity); another status fails the set.
    pub fn flag(&mut self, set: usize, flag: Failure) {
        if flag.status.has_outcome() {
            self.failures[set] = Some(flag);
        } else {
            self.fail(set, flag);
        }
    }

    /// Flag set `set` (a flight chained after a kick) as the kick before
    /// it was flagged, when it has values.
    pub fn flag_after(&mut self, set: usize, kick: &Failure) {
        if self.failures[set].is_none() {
            self.flag(set, Failure::new(kick.status, format!("the kick before this flight: {}", kick.message)));
        }
    }

    /// Set `set`'s result: its values or its failure.
    pub fn put(&mut self, set: usize, result: Result<impl AsRef<[f64]>, Failure>) {
        match result {
            Ok(values) => self.set(set, values.as_ref()),
            Err(failure) => self.fail(set, failure),
        }
    }

    /// The status of set `set`.
    pub fn status(&self, set: usize) -> Status {
        self.failures[set].as_ref().map_or(Status::Separated, |f| f.status)
    }
}

/// A level of the model hierarchy as a table of rows.
pub trait Level: Sync {
    /// Rows of the whole study (a shard runs a range of them).
    fn rows(&self) -> u64;
    /// Names and units of the parameter columns, one value per row each.
    fn parameter_columns(&self) -> Vec<Column>;
    /// The outcome sets: a solver's columns, a chained flight's columns.
    fn outcome_sets(&self) -> Vec<OutcomeSet>;
    /// Build and solve row `index` into `row` (shaped by [`Row::shaped`]):
    /// every parameter value, every set's values or its failure. A pure
    /// function of `index`.
    fn solve_row(&self, index: u64, row: &mut Row);

    /// The parameter values of row `index` as [`Level::solve_row`] writes
    /// them, without solving it, where the level can give them cheaply
    /// (`false`: it cannot). `kick merge` checks a part's parameter columns
    /// against them.
    fn parameters_into(&self, _index: u64, _parameters: &mut [f64]) -> bool {
        false
    }

    /// An empty row of this level's shape.
    fn empty_row(&self) -> Row {
        Row::shaped(self.parameter_columns().len(), &self.outcome_sets())
    }

    /// Data bytes of a row in a table: eight per value, one status byte per set.
    fn bytes_per_row(&self) -> u64 {
        let sets = self.outcome_sets();
        let values = self.parameter_columns().len() + sets.iter().map(|s| s.columns.len()).sum::<usize>();
        8 * values as u64 + sets.len() as u64
    }
}

/// An experiment file of either level is the level of its kicks.
impl crate::experiment::Experiment {
    /// `f` of this experiment's level: [`one_d::OneD`] or [`three_d::ThreeD`]
    /// with the experiment's `[flight]`, or [`bounce::BounceGrid`].
    pub fn with_level<R>(&self, f: impl FnOnce(&dyn Level) -> R) -> R {
        use crate::experiment::Kicks;
        let flight = self.flight.as_ref();
        match &self.kicks {
            Kicks::OneD(kicks) => f(&one_d::OneD { kicks, flight }),
            Kicks::ThreeD(kicks) => f(&three_d::ThreeD { kicks, flight }),
            Kicks::Bounce(kicks) => f(&bounce::BounceGrid { kicks }),
        }
    }
}

impl Level for crate::experiment::Experiment {
    fn rows(&self) -> u64 {
        self.with_level(|l| l.rows())
    }
    fn parameter_columns(&self) -> Vec<Column> {
        self.with_level(|l| l.parameter_columns())
    }
    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        self.with_level(|l| l.outcome_sets())
    }
    fn solve_row(&self, index: u64, row: &mut Row) {
        self.with_level(|l| l.solve_row(index, row))
    }
    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        self.with_level(|l| l.parameters_into(index, parameters))
    }
}

impl OutputSize {
    /// The file of the experiment's rows `part` (all its rows, or a shard's):
    /// a shard is sized by its own rows and histories.
    pub fn of(experiment: &Experiment, part: &Range<u64>) -> OutputSize {
        let rows = part.end.saturating_sub(part.start);
        let Some(kicks) = experiment.one_d() else {
            // A 3D or bounce row: its values and status bytes.
            return OutputSize { rows, bytes: rows.saturating_mul(experiment.bytes_per_row()) };
        };
        let solvers = kicks.solvers.len() as u64;
        let mut per_row = 8 * kick_core::Parameter::ALL.len() as u64 + solvers * (8 * OBSERVABLES.len() as u64 + 1);
        if let Some(flight) = &experiment.flight {
            // A flight set per solver (`[flight]`).
            per_row += solvers * (8 * flight.columns().len() as u64 + 1);
        }
        let mut bytes = rows.saturating_mul(per_row);
        if let Output::History { interval } = experiment.output {
            let per_sample = 8 * HISTORY_COLUMNS.len() as u64;
            for row in part.clone() {
                if let Ok(s) = kicks.scenarios.scenario(row) {
                    let end = s.elastic_contact_time();
                    let samples = Spacing::Interval(interval).grid(end).samples_until(end);
                    bytes = bytes.saturating_add(solvers.saturating_mul(samples).saturating_mul(per_sample));
                }
            }
        }
        OutputSize { rows, bytes }
    }

    /// Refuse a run beyond the row bound, or whose file of rows `part` (the
    /// whole experiment's, or a shard's) would not fit the free space of
    /// `directory`; otherwise that file's estimated size.
    pub fn check(experiment: &Experiment, part: &Range<u64>, directory: &Path) -> Result<OutputSize, LimitError> {
        let rows = experiment.rows();
        if rows > MAX_SCENARIOS {
            let what = match &experiment.kicks {
                Kicks::OneD(Kicks1d { scenarios: Scenarios::Sampled(_), .. }) => "samples",
                Kicks::OneD(_) => "scenarios",
                Kicks::ThreeD(_) | Kicks::Bounce(_) => "cells",
            };
            return Err(LimitError::TooManyRows { what, rows });
        }
        crate::limits::check_space(OutputSize::of(experiment, part), directory, crate::limits::free_space(directory))
    }
}

/// Where the run loop's rows go, in row order.
pub trait RowSink {
    type Error;
    fn push_row(&mut self, row: &Row) -> Result<(), Self::Error>;
}

/// Why the run loop stopped (a sink's error aside).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// Every row was solved and pushed.
    Finished,
    /// `cancel` was set: the rows pushed before it are whole, the rest were
    /// not solved or not pushed.
    Cancelled,
}

/// The run loop: rows `rows` of `level`, solved in chunks of [`CHUNK_ROWS`]
/// on rayon's current pool and pushed to `sink` in order. While a chunk goes
/// to the sink (one writer: HDF5 is serial), the next is solved on the rest
/// of the pool; two chunks of rows are in memory, their buffers reused.
/// `progress` hears the number of rows pushed after each chunk. Stops at the
/// sink's first error.
pub fn run_rows<L, S>(level: &L, rows: Range<u64>, sink: &mut S, progress: &(dyn Fn(u64) + Sync)) -> Result<(), S::Error>
where
    L: Level + ?Sized,
    S: RowSink + Send,
    S::Error: Send,
{
    run_rows_until(level, rows, sink, progress, &AtomicBool::new(false)).map(|_| ())
}

/// [`run_rows`], stopping once `cancel` is set (Ctrl-C in Python's
/// `*_many`): a row not yet begun is skipped, and no row of the chunk being
/// solved reaches the sink.
pub fn run_rows_until<L, S>(
    level: &L,
    rows: Range<u64>,
    sink: &mut S,
    progress: &(dyn Fn(u64) + Sync),
    cancel: &AtomicBool,
) -> Result<Stop, S::Error>
where
    L: Level + ?Sized,
    S: RowSink + Send,
    S::Error: Send,
{
    let width = rows.end.saturating_sub(rows.start).min(CHUNK_ROWS as u64) as usize;
    let template = level.empty_row();
    let mut solving: Vec<Row> = vec![template.clone(); width];
    let mut writing: Vec<Row> = vec![template; width];
    let mut pending = 0..0usize;
    let mut start = rows.start;
    while start < rows.end || !pending.is_empty() {
        let end = (start + CHUNK_ROWS as u64).min(rows.end);
        let n = (end - start) as usize;
        let to_write = &writing[pending.clone()];
        let (written, ()) = rayon::join(
            || -> Result<(), S::Error> {
                for row in to_write {
                    sink.push_row(row)?;
                }
                Ok(())
            },
            || {
                solving[..n].par_iter_mut().enumerate().for_each(|(j, row)| {
                    if !cancel.load(Ordering::Relaxed) {
                        level.solve_row(start + j as u64, row)
                    }
                });
            },
        );
        written?;
        progress(pending.len() as u64);
        if cancel.load(Ordering::Relaxed) {
            return Ok(Stop::Cancelled);
        }
        std::mem::swap(&mut solving, &mut writing);
        pending = 0..n;
        start = end;
    }
    Ok(Stop::Finished)
}

/// A table kept in memory: what a [`RowSink`] receives, column by column.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    /// Per parameter column, its values.
    pub parameters: Vec<Vec<f64>>,
    /// Per set, per column, its values.
    pub outcomes: Vec<Vec<Vec<f64>>>,
    /// Per set, the status code of every row.
    pub status: Vec<Vec<u8>>,
    /// Per set, (row, message) of every row without values.
    pub failures: Vec<Vec<(u64, String)>>,
}

impl Table {
    /// An empty table of `level`'s shape.
    pub fn of(level: &(impl Level + ?Sized)) -> Table {
        let sets = level.outcome_sets();
        Table {
            parameters: vec![Vec::new(); level.parameter_columns().len()],
            outcomes: sets.iter().map(|s| vec![Vec::new(); s.columns.len()]).collect(),
            status: vec![Vec::new(); sets.len()],
            failures: vec![Vec::new(); sets.len()],
        }
    }

    pub fn rows(&self) -> usize {
        self.status.first().map_or(0, Vec::len)
    }
}

impl RowSink for Table {
    type Error = std::convert::Infallible;
    fn push_row(&mut self, row: &Row) -> Result<(), Self::Error> {
        let index = self.rows() as u64;
        for (column, &v) in self.parameters.iter_mut().zip(&row.parameters) {
            column.push(v);
        }
        for (k, values) in row.outcomes.iter().enumerate() {
            for (column, &v) in self.outcomes[k].iter_mut().zip(values) {
                column.push(v);
            }
            self.status[k].push(row.status(k).code());
            if let Some(f) = &row.failures[k] {
                self.failures[k].push((index, f.message.clone()));
            }
        }
        Ok(())
    }
}

/// Run the rows `rows` of `level` into memory.
pub fn run_table(level: &(impl Level + ?Sized), rows: Range<u64>) -> Table {
    let mut table = Table::of(level);
    match run_rows(level, rows, &mut table, &|_| {}) {
        Ok(()) => table,
        Err(never) => match never {},
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A level with a closed form: row i has parameter i and outcome i²,
    /// and every seventh row is refused.
    struct Squares(u64);

    impl Level for Squares {
        fn rows(&self) -> u64 {
            self.0
        }
        fn parameter_columns(&self) -> Vec<Column> {
            vec![Column::new("i", "1")]
        }
        fn outcome_sets(&self) -> Vec<OutcomeSet> {
            vec![OutcomeSet { solver: "square".into(), settings: vec![], columns: vec![Column::new("i2", "1")] }]
        }
        fn solve_row(&self, index: u64, row: &mut Row) {
            row.parameters[0] = index as f64;
            if index % 7 == 3 {
                row.fail(0, Failure::refused(format!("row {index}")));
            } else {
                row.set(0, &[(index * index) as f64]);
            }
        }
    }

    /// Rows arrive whole and in order across chunk boundaries, whatever the
    /// pool; failures carry their status and their row.
    #[test]
    fn rows_arrive_in_order_across_chunks_on_any_pool() {
        let n = 2 * CHUNK_ROWS as u64 + 5;
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let table = pool.install(|| run_table(&Squares(n), 3..n));
            assert_eq!(table.rows() as u64, n - 3);
            for (j, i) in (3..n).enumerate() {
                assert_eq!(table.parameters[0][j], i as f64);
                if i % 7 == 3 {
                    assert!(table.outcomes[0][0][j].is_nan());
                    assert_eq!(table.status[0][j], Status::Refused.code());
                } else {
                    assert_eq!(table.outcomes[0][0][j], (i * i) as f64);
                    assert_eq!(table.status[0][j], 0);
                }
            }
            let failed: Vec<u64> = table.failures[0].iter().map(|f| f.0).collect();
            let expected: Vec<u64> = (3..n).enumerate().filter(|(_, i)| i % 7 == 3).map(|(j, _)| j as u64).collect();
            assert_eq!(failed, expected);
        }
    }

    /// Cancelled in the second chunk: the first chunk's rows arrive whole
    /// and in order, none of the second, and the loop says why it stopped.
    #[test]
    fn a_cancel_stops_the_run_between_chunks() {
        struct Cancels<'a>(&'a AtomicBool);
        impl Level for Cancels<'_> {
            fn rows(&self) -> u64 {
                3 * CHUNK_ROWS as u64
            }
            fn parameter_columns(&self) -> Vec<Column> {
                vec![Column::new("i", "1")]
            }
            fn outcome_sets(&self) -> Vec<OutcomeSet> {
                Squares(0).outcome_sets()
            }
            fn solve_row(&self, index: u64, row: &mut Row) {
                if index == CHUNK_ROWS as u64 + 10 {
                    self.0.store(true, Ordering::Relaxed);
                }
                Squares(0).solve_row(index, row)
            }
        }
        let cancel = AtomicBool::new(false);
        let level = Cancels(&cancel);
        let mut table = Table::of(&level);
        let pushed = std::sync::atomic::AtomicU64::new(0);
        let stop = run_rows_until(&level, 0..level.rows(), &mut table, &|n| _ = pushed.fetch_add(n, Ordering::Relaxed), &cancel);
        assert_eq!(stop, Ok(Stop::Cancelled));
        assert_eq!(table.rows(), CHUNK_ROWS);
        assert_eq!(pushed.load(Ordering::Relaxed), CHUNK_ROWS as u64);
        assert!((0..CHUNK_ROWS).filter(|i| i % 7 != 3).all(|i| table.outcomes[0][0][i] == (i * i) as f64));
        // Not cancelled: every row.
        let mut table = Table::of(&Squares(10));
        assert_eq!(run_rows_until(&Squares(10), 0..10, &mut table, &|_| {}, &AtomicBool::new(false)), Ok(Stop::Finished));
        assert_eq!(table.rows(), 10);
    }

    /// The loop stops at the sink's first error and reports it.
    #[test]
    fn a_sink_error_stops_the_run() {
        struct Full(usize);
        impl RowSink for Full {
            type Error = String;
            fn push_row(&mut self, _: &Row) -> Result<(), String> {
                self.0 += 1;
                if self.0 > 10 {
                    Err("disk full".into())
                } else {
                    Ok(())
                }
            }
        }
        let mut sink = Full(0);
        assert_eq!(run_rows(&Squares(10_000), 0..10_000, &mut sink, &|_| {}), Err("disk full".to_string()));
        assert_eq!(sink.0, 11);
    }
}
