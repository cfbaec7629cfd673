//! Time histories of one run, as a study sees them: what to sample
//! ([`HistoryRequest`]), the columns and what the run says about itself
//! ([`HistoryMeta`]), and the [`HistorySink`] the rows stream into. The file
//! formats (CSV, HDF5) are kick-store's `history` module.

pub use crate::error::SinkError;
use crate::error::StudyError;
use kick_core::parameters::Value;
use kick_core::Spacing;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

/// `--samples`' default: 201 rows (200 intervals over the contact or flight).
pub const DEFAULT_SAMPLES: usize = 201;
/// Most rows a history file takes (10⁷, about 2 GB of 3D CSV).
pub const MAX_FILE_SAMPLES: u64 = 10_000_000;

/// Where a history's rows go: begins the sink for a request, its columns
/// (name, unit) and its description.
pub type OpenSink = fn(&HistoryRequest, &[(&str, &str)], &HistoryMeta) -> Result<Box<dyn HistorySink>, SinkError>;

/// Rows of one history streamed somewhere (a file, kick-store's
/// `HistoryWriter`): written whole by [`HistorySink::finish`] or not at all.
pub trait HistorySink {
    /// Append one row (one value per column).
    fn push(&mut self, values: &[f64]) -> Result<(), SinkError>;
    /// Rows pushed so far.
    fn rows(&self) -> u64;
    /// The last rows written; the sink's name (a file's path).
    fn finish(self: Box<Self>) -> Result<PathBuf, SinkError>;
}

/// The failure of a sink that has only a message (an in-memory sink, a test's).
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
struct Message(String);

impl From<String> for SinkError {
    fn from(message: String) -> SinkError {
        SinkError::new(Message(message))
    }
}

impl From<&str> for SinkError {
    fn from(message: &str) -> SinkError {
        SinkError::new(Message(message.to_string()))
    }
}

/// A history to write: where, on which grid, and through which sink.
#[derive(Debug, Clone)]
pub struct HistoryRequest {
    pub path: PathBuf,
    pub spacing: Spacing,
    pub open: OpenSink,
}

impl HistoryRequest {
    /// From the front ends' `--history FILE [--samples N | --interval DT]`
    /// (neither: [`DEFAULT_SAMPLES`]; both: refused).
    pub fn new(path: &Path, samples: Option<usize>, interval: Option<f64>, open: OpenSink) -> Result<HistoryRequest, StudyError> {
        let spacing = match (samples, interval) {
            (Some(_), Some(_)) => {
                return Err(StudyError::Flag { flag: "samples", message: "give --samples or --interval, not both".into() })
            }
            (Some(n), None) => Spacing::Count(n),
            (None, Some(dt)) => Spacing::Interval(dt),
            (None, None) => Spacing::Count(DEFAULT_SAMPLES),
        };
        let flag = if samples.is_some() { "samples" } else { "interval" };
        let spacing = spacing.validate().map_err(|source| StudyError::Spacing { flag, source })?;
        if let Spacing::Count(n) = spacing {
            if n as u64 > MAX_FILE_SAMPLES {
                return Err(StudyError::HistoryRows { samples: n, max: MAX_FILE_SAMPLES });
            }
        }
        HistoryFormat::of(path)?;
        Ok(HistoryRequest { path: path.to_path_buf(), spacing, open })
    }
}

/// The file format, from the extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HistoryFormat {
    Csv,
    Hdf5,
}

impl HistoryFormat {
    /// `.csv` → CSV, `.h5`/`.hdf5` → HDF5 (any case); anything else is an error naming `--history`.
    pub fn of(path: &Path) -> Result<HistoryFormat, StudyError> {
        let ext = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("csv") => Ok(HistoryFormat::Csv),
            Some("h5" | "hdf5") => Ok(HistoryFormat::Hdf5),
            _ => Err(StudyError::Flag {
                flag: "history",
                message: format!("--history {}: the format comes from the extension: .csv, .h5 or .hdf5", path.display()),
            }),
        }
    }
}

/// Names and units of a flight history's columns, in [`flight_values`] order.
pub const FLIGHT_HISTORY_COLUMNS: [(&str, &str); 10] = [
    ("time", "s"),
    ("position_x", "m"),
    ("position_y", "m"),
    ("position_z", "m"),
    ("velocity_x", "m/s"),
    ("velocity_y", "m/s"),
    ("velocity_z", "m/s"),
    ("spin_x", "rad/s"),
    ("spin_y", "rad/s"),
    ("spin_z", "rad/s"),
];

/// A flight sample in [`FLIGHT_HISTORY_COLUMNS`] order.
pub fn flight_values(s: &kick_flight::FlightSample) -> [f64; 10] {
    let mut v = [s.time; 10];
    v[1..4].copy_from_slice(&s.position);
    v[4..7].copy_from_slice(&s.velocity);
    v[7..10].copy_from_slice(&s.spin);
    v
}

/// What the file says about the run besides its rows.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HistoryMeta {
    /// `1d`, `3d` or `flight`.
    pub level: String,
    /// Text attributes (solver, law...).
    pub texts: Vec<(String, String)>,
    /// `/fixed/<name>`: (name, unit, values).
    pub fixed: Vec<(String, String, Vec<f64>)>,
}

impl HistoryMeta {
    /// A fixed parameter from a declared value.
    pub fn push_value(&mut self, name: &str, unit: &str, value: Value) {
        self.fixed.push((name.into(), unit.into(), value.numbers()));
    }
}

/// Write a history streamed by `solve` (which hands rows to its sink and
/// returns its outcome and the full history's row count): the outcome and
/// the file, or nothing written.
pub fn write<S, O, E>(
    request: &HistoryRequest,
    columns: &[(&str, &str)],
    meta: &HistoryMeta,
    values: impl Fn(&S) -> Vec<f64>,
    solve: impl FnOnce(&mut dyn FnMut(&S) -> ControlFlow<()>) -> Result<(O, u64), E>,
) -> Result<(O, PathBuf), StudyError>
where
    StudyError: From<E>,
{
    let mut writer = (request.open)(request, columns, meta).map_err(StudyError::Sink)?;
    let mut error = None;
    let (outcome, total) = {
        let mut sink = |s: &S| match writer.push(&values(s)) {
            Ok(()) => ControlFlow::Continue(()),
            Err(e) => {
                error = Some(e);
                ControlFlow::Break(())
            }
        };
        solve(&mut sink)?
    };
    if let Some(e) = error {
        return Err(StudyError::Sink(e));
    }
    if total != writer.rows() {
        return Err(StudyError::ShortHistory { path: request.path.clone(), written: writer.rows(), total });
    }
    Ok((outcome, writer.finish().map_err(StudyError::Sink)?))
}
