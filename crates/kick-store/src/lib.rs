//! kick-store stores kick's studies: whole-or-nothing files, one writer per
//! file and cleanup on signals ([`output`]), provenance ([`provenance`]), the
//! HDF5 result tables, grids and layouts ([`h5`]), history files
//! ([`history`], the file sinks of kick-study's history rows), experiments
//! run into files ([`run`], [`three_d`], [`sweep`], [`sweep3d`]), shards and
//! their merge ([`shard`]), the comparison of result trees ([`compare`]),
//! the identification files ([`identify::files`]) and the measurement file
//! the validation reads ([`measurements`]).
//!
//! Depends on kick-study and the model crates (and hdf5); never the reverse.
//! No plotting: figures and pages are kick-paper's.

pub mod bench;
pub mod compare;
pub mod error;
pub mod force_history;
pub mod free_kick;
pub mod h5;
pub mod held;
pub mod history;
pub mod layouts;
pub mod measurements;
pub mod output;
pub mod patch;
pub mod provenance;
pub mod run;
pub mod shard;
pub mod sweep;
pub mod sweep3d;
pub mod table;
pub mod three_d;
pub mod writer;

/// Files of `kick fit` and `kick laws`.
pub mod identify {
    pub mod files;
    pub mod fit;
    pub mod laws;
}

// kick-study's modules under the names this crate's files use.
pub(crate) use kick_study::{experiment, limits, printable, sample, table2};
pub(crate) use kick_study::{Experiment, Output, Printable, Scenarios};

pub use error::StoreError;
pub use h5::{Column, OutcomeSet, ResultFile, Setting, SweepData};
pub use provenance::Provenance;
pub use run::{run, RunReport, RunSummary};
pub use shard::run_file;
pub use writer::{ResultWriter, SweepWriter};
