//! The kick workspace as a research tool, one library for every front end
//! (the `kick` command line; Python next): each command is a function here
//! that returns a value with a text and a JSON form ([`Printable`]).
//!
//! - [`experiment`]: `experiments/*.toml` parsed and validated (errors name file, line and key).
//! - [`output`]: whole-or-nothing files: temporary name, one writer per file, cleanup on signals.
//! - [`limits`]: bounds on threads, rows and bytes of a run, checked before it starts.
//! - [`h5`]: the model-independent HDF5 writer/reader (parameter and outcome columns with units, provenance).
//! - [`run`]: the 1D model's runner over [`h5`] (rayon, chunked streaming); [`sample`], [`sweep`]: random sweeps;
//!   [`sweep3d`]: random off-center 3D kicks into one file.
//! - [`shard`]: one slice of an experiment's rows per file (`--shard I/N`), and their merge.
//! - [`flight`]: the ball's flight, alone or after a 1D or 3D kick.
//! - [`simulate`]: one contact, 1D or 3D; [`table2`]: Table 2 side by side; [`checks`]: every cross-model check.
//! - [`three_d`]: 3D sweeps into files and figures; [`leg`]: the articulated leg and its figure data.
//! - [`identify`]: `kick fit` and `kick laws`, their result files, figures and pages.
//! - [`bench`]: work-precision of the 1D solvers, cost ratios, sweep throughput.
//! - [`figures`]: Figures 1-7 and the plotting helpers (plotters, bundled DejaVu Sans).
//! - [`report`]: `paper/README.md` from the result files and the cross-model checks.
//! - [`validation`]: the model beside published measurements (`paper/validation.md`).
//! - [`reproduce`]: all of it, step by step, as library calls; `--check` against the committed files ([`compare`]).

pub mod bench;
pub mod checks;
pub mod compare;
pub mod experiment;
pub mod figures;
pub mod flight;
pub mod free_kick;
pub mod h5;
pub mod history;
pub mod identify;
pub mod leg;
pub mod limits;
pub mod output;
pub mod pages_3d;
pub mod printable;
pub mod provenance;
pub mod report;
pub mod reproduce;
pub mod run;
pub mod sample;
pub mod shard;
pub mod simulate;
pub mod sweep;
pub mod sweep3d;
pub mod table2;
pub mod three_d;
pub mod validation;

pub use experiment::{Experiment, ExperimentError, Output, Scenarios};
pub use h5::{Column, OutcomeSet, ResultFile, ResultWriter, Setting, SweepData, SweepWriter};
pub use printable::{json, set_threads, Printable};
pub use provenance::Provenance;
pub use run::{run, run_file, RunReport, RunSummary};
