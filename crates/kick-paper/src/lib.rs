//! kick-paper writes kick's paper: the plotting kit and Figures 1-7
//! ([`figures`], bundled DejaVu Sans), the pages (`paper/README.md`:
//! [`report`]; [`pages_3d`]; [`validation`]; the identification pages and
//! figures: [`identify`]; the model with the paper's equation numbers,
//! `paper/model.md`: [`model`]), the articulated leg's figure data ([`leg`]), the
//! work-precision benchmark ([`bench`]) and the reproduction pipeline
//! ([`reproduce`], `--check` through kick-store's `compare`).
//!
//! Depends on kick-study (what to compute) and kick-store (the files it
//! reads and writes), and on plotters; neither depends on it.

pub mod ball;
pub mod bench;
pub mod error;
pub mod figures;
pub mod force_history;
pub mod free_kick;
pub mod identify;
pub mod leg;
pub mod links;
pub mod model;
pub mod pages_3d;
pub mod patch;
pub mod report;
pub mod reproduce;
pub mod three_d;
pub mod validation;

// The modules of kick-study and kick-store under the names this crate's files use.
pub use error::PaperError;
pub(crate) use kick_store::{compare, h5, output, provenance, run, shard};
pub(crate) use kick_store::{ResultFile, SweepData};
pub(crate) use kick_study::{checks, printable, units};
