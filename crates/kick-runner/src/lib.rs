//! The kick workspace as a research tool, one library for every front end
//! (the `kick` command line; Python next): each command is a function here
//! that returns a value with a text and a JSON form ([`Printable`]).
//!
//! - [`experiment`]: `experiments/*.toml` parsed and validated (errors name file, line and key).
//! - [`h5`]: the model-independent HDF5 writer/reader (parameter and outcome columns with units, provenance).
//! - [`run`]: the 1D model's runner over [`h5`] (rayon, chunked streaming); [`sample`], [`sweep`]: random sweeps.
//! - [`flight`]: the ball's flight, alone or after a 1D or 3D kick.
//! - [`simulate`]: one contact, 1D or 3D; [`table2`]: Table 2 side by side; [`checks`]: every cross-model check.
//! - [`three_d`]: 3D sweeps into files and figures; [`leg`]: the articulated leg and its figure data.
//! - [`identify`]: `kick fit` and `kick laws`, their result files, figures and pages.
//! - [`bench`]: work-precision of the 1D solvers, cost ratios, sweep throughput.
//! - [`figures`]: Figures 1-7 and the plotting helpers (plotters, bundled DejaVu Sans).
//! - [`report`]: `paper/README.md` from the result files and the cross-model checks.
//! - [`reproduce`]: all of it, step by step, as library calls.

pub mod bench;
pub mod checks;
pub mod experiment;
pub mod figures;
pub mod flight;
pub mod h5;
pub mod identify;
pub mod leg;
pub mod printable;
pub mod provenance;
pub mod report;
pub mod reproduce;
pub mod run;
pub mod sample;
pub mod simulate;
pub mod sweep;
pub mod table2;
pub mod three_d;

pub use experiment::{Experiment, ExperimentError, Output, Scenarios};
pub use h5::{Column, OutcomeSet, ResultFile, ResultWriter, Setting, SweepData, SweepWriter};
pub use printable::{json, set_threads, Printable};
pub use provenance::Provenance;
pub use run::{run, run_file, RunReport, RunSummary};
