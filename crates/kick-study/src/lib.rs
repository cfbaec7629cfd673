//! kick-study runs kick's studies: one contact ([`simulate`]), the flight
//! after a kick ([`flight`]), experiment files and their grids
//! ([`experiment`]), random sweeps ([`sample`]), shards as row ranges
//! ([`shard`]), the bounds on a run ([`limits`]), Table 2 side by side
//! ([`table2`]) and the cross-model checks ([`checks`]). Each command returns
//! a value with a text and a JSON form ([`Printable`]).
//!
//! Depends on the model crates (kick-core, kick-compliant, kick-restitution,
//! kick-3d, kick-flight, kick-checks) and on no file format and no plotting
//! library: no hdf5, no plotters. Rows leave through sinks ([`history::HistorySink`])
//! that kick-store implements for files and kick-py keeps in memory.
//!
//! - [`experiment`]: `experiments/*.toml` parsed and validated (errors name file, line and key).
//! - [`error`]: [`StudyError`], every way a study command refuses or fails, wrapping the model crates' errors.
//! - [`columns`]: named columns with units, outcome sets, the compression a file asks for.
//! - [`history`]: what a time history samples and the sink its rows stream into.
//! - [`level`]: the `Level` trait every model level implements, and the one run loop over row ranges.
//! - [`many`]: Python's `*_many` calls as a level: rows broadcast over arrays, run by the one loop into the caller's columns.
//! - [`studies`]: every study declared once (name, commands, Python and Dask functions, layouts, `kick reproduce`'s steps).
//! - [`limits`]: bounds on threads, rows and bytes of a run, checked before it starts.

pub mod aim;
pub mod aimed;
pub mod ball;
pub mod bench;
pub mod checks;
pub mod columns;
pub mod error;
pub mod experiment;
pub mod flight;
pub mod free_kick;
pub mod grid;
pub mod history;
pub mod leg;
pub mod level;
pub mod limits;
pub mod many;
pub mod numbers_3d;
pub mod parameters;
pub mod patch;
pub mod printable;
pub mod sample;
pub mod shard;
pub mod simulate;
pub mod studies;
pub mod table2;
pub mod units;
pub mod validation;

pub use error::StudyError;
pub use experiment::{Experiment, ExperimentError, Kicks, Kicks1d, Kicks3d, Output, Scenarios};
pub use grid::{Axis, Grid};
pub use limits::set_threads;
pub use printable::{json, Printable};
