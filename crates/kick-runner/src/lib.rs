//! The kick workspace as a research tool: experiment files, parallel sweeps
//! written to HDF5, figures drawn from those files, and the reproduction report.
//!
//! - [`experiment`]: `experiments/*.toml` parsed and validated (errors name file, line and key).
//! - [`output`]: whole-or-nothing files: temporary name, one writer per file, cleanup on signals.
//! - [`limits`]: bounds on threads, rows and bytes of a run, checked before it starts.
//! - [`h5`]: the model-independent HDF5 writer/reader (parameter and outcome columns with units, provenance).
//! - [`run`]: the 1D model's runner over [`h5`] (rayon, chunked streaming).
//! - [`figures`]: Figures 1–7 from the result files (plotters, bundled DejaVu Sans).
//! - [`report`]: `paper/README.md` from the result files and the cross-model checks.

pub mod experiment;
pub mod figures;
pub mod h5;
pub mod limits;
pub mod output;
pub mod provenance;
pub mod report;
pub mod run;
pub mod sample;

pub use experiment::{Experiment, ExperimentError, Output, Scenarios};
pub use h5::{Column, OutcomeSet, ResultFile, ResultWriter, SweepData, SweepWriter};
pub use provenance::Provenance;
pub use run::{run, RunSummary};
