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
    /// kick-identify's refusal or failure (a fit specification, a fit, a study).
    #[error(transparent)]
    Identify(#[from] kick_identify::IdentifyError),
    /// A result file that lacks what its reader needs: the file and what.
    #[error("{}: {what}", .path.display())]
    Lacks { path: PathBuf, what: String },
    /// A dataset of a result file holding more or fewer values than its layout says.
    #[error("{dataset}: expected one value")]
    NotScalar { dataset: String },
    /// A fit report with fewer residuals than its observations (the fit's, not the user's).
    #[error("fit report: no residual for {label}")]
    NoResidual { label: String },
    /// An input file the user named (`name`, as given), unreadable.
    #[error("{name}: {source}")]
    Input { name: String, source: kick_core::input::InputError },
    /// A named row of a study (Table 2's) whose solve failed.
    #[error("{name}: {source}")]
    Row { name: String, source: kick_core::KickError },
    /// An output folder that cannot be made.
    #[error("cannot create {}: {source}", .path.display())]
    CreateDir { path: PathBuf, source: std::io::Error },
    /// A file that cannot be read or listed (its metadata, a folder).
    #[error("{}: {source}", .path.display())]
    Io { path: PathBuf, source: std::io::Error },
    /// A thread pool that cannot be built.
    #[error(transparent)]
    ThreadPool(#[from] rayon::ThreadPoolBuildError),
    /// A file's text that cannot be written as TOML.
    #[error(transparent)]
    Toml(#[from] toml::ser::Error),
    /// `kick fit data` that did not converge (the report is written).
    #[error("the fit stopped without converging: {termination}")]
    NotConverged { termination: String },
    /// A synthetic history that came back without its samples.
    #[error("no history produced")]
    NoHistory,
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
