//! [`StoreError`]: every way a command that writes or reads result files
//! refuses or fails. It wraps the file layer's errors and kick-study's
//! [`StudyError`]; its `Display` is the message the front ends print.

use crate::h5::H5Error;
use crate::output::OutputError;
use crate::table::RunError;
use kick_study::experiment::ExperimentError;
use kick_study::limits::LimitError;
use kick_study::shard::ShardFlagError;
use kick_study::StudyError;
use std::path::PathBuf;

/// Why a shard could not be run or the parts not merged.
#[derive(Debug, thiserror::Error)]
pub enum ShardError {
    #[error(transparent)]
    Flag(#[from] kick_study::shard::ShardFlagError),
    #[error("{}: {message}", path.display())]
    Part { path: PathBuf, message: String },
    #[error("cannot merge: {0}")]
    Merge(String),
    #[error(transparent)]
    Run(#[from] RunError),
    #[error(transparent)]
    H5(#[from] H5Error),
    #[error(transparent)]
    Output(#[from] OutputError),
}

#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    #[error(transparent)]
    H5(#[from] H5Error),
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error(transparent)]
    Run(#[from] RunError),
    #[error(transparent)]
    Shard(#[from] ShardError),
    #[error(transparent)]
    Study(#[from] StudyError),
    #[error(transparent)]
    Experiment(#[from] ExperimentError),
    #[error(transparent)]
    Limit(#[from] LimitError),
    #[error(transparent)]
    ShardFlag(#[from] ShardFlagError),
    /// The measurement file, unreadable or refused.
    #[error(transparent)]
    Measurements(#[from] crate::measurements::MeasurementFileError),
    /// A flag the user gave, refused: the message names it.
    #[error("{message}")]
    Flag { flag: &'static str, message: String },
    /// A history row of another width than its columns.
    #[error("{}: a row of {values} values for {columns} columns", .path.display())]
    RowWidth { path: PathBuf, values: usize, columns: usize },
    /// A history streaming more rows than a file takes.
    #[error("--history {}: more than {max} rows; give a larger --interval or fewer --samples", .path.display())]
    HistoryRows { path: PathBuf, max: u64 },
}

impl From<kick_core::KickError> for StoreError {
    fn from(e: kick_core::KickError) -> StoreError {
        StoreError::Study(e.into())
    }
}

impl From<kick_3d::Kick3dError> for StoreError {
    fn from(e: kick_3d::Kick3dError) -> StoreError {
        StoreError::Study(e.into())
    }
}

/// The front ends and the callers still returning text print the message.
impl From<StoreError> for String {
    fn from(e: StoreError) -> String {
        e.to_string()
    }
}
