//! [`StudyError`]: every way a study command refuses or fails. It wraps the
//! model crates' errors and names the flag, key or file where one applies;
//! its `Display` is the message the front ends print.

use crate::limits::LimitError;
use kick_3d::Kick3dError;
use kick_core::parameters::ParameterError;
use kick_core::{KickError, Status};
use kick_flight::{FlightError, FlightParameter};
use std::path::PathBuf;
use std::sync::Arc;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudyError {
    #[error(transparent)]
    Kick(#[from] KickError),
    #[error(transparent)]
    Kick3d(#[from] Kick3dError),
    /// A flight's error; `flag` is the flag of the parameter it names, when
    /// it names one (`--spin`).
    #[error("{source}{}", .flag.as_ref().map(|f| format!(" (flag {f})")).unwrap_or_default())]
    Flight { source: FlightError, flag: Option<String> },
    /// An aim refused or not found; `flag` as for [`StudyError::Flight`].
    #[error("{source}{}", .flag.as_ref().map(|f| format!(" (flag {f})")).unwrap_or_default())]
    Aim { source: kick_flight::aim::AimError, flag: Option<String> },
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    #[error(transparent)]
    Leg(#[from] kick_core::leg::LegError),
    #[error(transparent)]
    Failure(#[from] Failure),
    #[error(transparent)]
    Limit(#[from] LimitError),
    /// A history's spacing refused by the model, on the flag the user gave
    /// (`samples` or `interval`).
    #[error("{source} (flag --{flag})")]
    Spacing { flag: &'static str, source: KickError },
    /// `--samples N` beyond the rows a history file takes.
    #[error("--samples {samples}: at most {max} rows in a history file")]
    HistoryRows { samples: usize, max: u64 },
    /// Two flags that exclude each other, or a flag that does not apply:
    /// the message names them.
    #[error("{message}")]
    Flag { flag: &'static str, message: String },
    /// An input or output file the user named, and what is wrong with it.
    #[error("{}: {message}", .path.display())]
    File { path: PathBuf, message: String },
    /// One named 3D kick of a study whose solve failed.
    #[error("{name}: {source}")]
    Kick3dRow { name: String, source: Kick3dError },
    /// A flight of kick-flight's validation scenes that could not be flown as asked.
    #[error(transparent)]
    FlightValidation(#[from] kick_flight::validation::FlightValidationError),
    /// A measurement file that cannot be read, or lacks what a study needs.
    #[error(transparent)]
    Measurements(#[from] kick_core::measurements::MeasurementError),
    /// One named row of a table (Table 2's) whose solve failed.
    #[error("{name}: {source}")]
    Row { name: String, source: KickError },
    /// A history's sink (kick-store's file, an in-memory sink) failed: its
    /// own error inside.
    #[error(transparent)]
    Sink(#[from] SinkError),
    /// A history whose solve reported more rows than reached its sink.
    #[error("{}: {written} of {total} rows written", .path.display())]
    ShortHistory { path: PathBuf, written: u64, total: u64 },
    /// A deflate level outside 1..=9, given as `what` (`--compress`, `compress`).
    #[error("{what} {level}: the deflate level must be 1 (fastest) to 9 (smallest)")]
    Deflate { what: String, level: i64 },
    /// kick-identify's refusal or failure (a fit specification, synthetic data).
    #[error(transparent)]
    Identify(#[from] kick_identify::IdentifyError),
    /// No shell damping in the search bracket makes the FIFA drop rebound to `height` (m).
    #[error("no β rebounds {height} m")]
    NoRebound { height: f64 },
    /// A 3D outcome's column (`simulate3d_many`'s) that the outcome's
    /// field list (`kick_3d::FIELDS_3D`) does not name: the two drifted apart.
    #[error("the 3D outcome's column `{column}` is not one of kick_3d::FIELDS_3D")]
    Column { column: String },
    /// A value that has no JSON form.
    #[error("{0}")]
    Json(String),
}

impl StudyError {
    /// What became of the request: the model error's own status, a sink or
    /// JSON failure a numerical (non-physical) failure, the rest refused.
    pub fn status(&self) -> Status {
        match self {
            StudyError::Kick(e) | StudyError::Row { source: e, .. } => e.status(),
            StudyError::Kick3d(e) | StudyError::Kick3dRow { source: e, .. } => e.status(),
            StudyError::Leg(e) => e.status(),
            StudyError::Flight { source, .. } => source.status(),
            StudyError::Aim { .. } => Status::Refused,
            StudyError::Identify(e) => e.status(),
            StudyError::NoRebound { .. } => Status::NumericalFailure,
            StudyError::Failure(f) => f.status,
            StudyError::Sink(_) | StudyError::ShortHistory { .. } | StudyError::Json(_) | StudyError::Column { .. } => {
                Status::NumericalFailure
            }
            StudyError::FlightValidation(e) => match e {
                kick_flight::validation::FlightValidationError::Flight(f) => f.status(),
                kick_flight::validation::FlightValidationError::Measurements(_) => Status::Refused,
                _ => Status::NumericalFailure,
            },
            StudyError::Parameter(_)
            | StudyError::Limit(_)
            | StudyError::Spacing { .. }
            | StudyError::HistoryRows { .. }
            | StudyError::Flag { .. }
            | StudyError::File { .. }
            | StudyError::Measurements(_)
            | StudyError::Deflate { .. } => Status::Refused,
        }
    }
}

impl From<FlightError> for StudyError {
    /// With the flag of the parameter the error names ([`crate::flight::flight_error`]'s message).
    fn from(source: FlightError) -> StudyError {
        let flag = flight_flag(&source);
        StudyError::Flight { source, flag }
    }
}

/// The flag of the flight parameter `error` names, if it names one.
pub fn flight_flag(error: &FlightError) -> Option<String> {
    let name = match error {
        FlightError::InvalidParameter { name, .. }
        | FlightError::Missing { name }
        | FlightError::WrongLength { name, .. }
        | FlightError::TooMany { name, .. } => Some(*name),
        FlightError::Conflict { second, .. } => Some(*second),
        _ => None,
    };
    name.and_then(|n| FlightParameter::from_name(n).ok()).map(|p| p.def().flag())
}

/// Why a row of an outcome set has no values: its status and the message.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct Failure {
    pub status: Status,
    pub message: String,
}

impl Failure {
    pub fn new(status: Status, message: impl Into<String>) -> Failure {
        Failure { status, message: message.into() }
    }

    /// Bad input or a request that does not apply.
    pub fn refused(message: impl Into<String>) -> Failure {
        Failure::new(Status::Refused, message)
    }
}

impl From<kick_core::OutsideValidity> for Failure {
    fn from(e: kick_core::OutsideValidity) -> Failure {
        Failure::new(Status::OutsideValidity, e.to_string())
    }
}

impl From<kick_core::KickError> for Failure {
    fn from(e: kick_core::KickError) -> Failure {
        Failure::new(e.status(), e.to_string())
    }
}

impl From<kick_3d::Kick3dError> for Failure {
    fn from(e: kick_3d::Kick3dError) -> Failure {
        Failure::new(e.status(), e.to_string())
    }
}

/// Why a [`HistorySink`] failed: the sink's own error (kick-store's
/// `StoreError` for a file), kept typed behind the trait, which knows no
/// file format: [`SinkError::downcast_ref`] gives it back. Its message is
/// the sink's.
#[derive(Debug, Clone, thiserror::Error)]
#[error(transparent)]
pub struct SinkError(Arc<dyn std::error::Error + Send + Sync>);

impl SinkError {
    pub fn new(source: impl std::error::Error + Send + Sync + 'static) -> SinkError {
        SinkError(Arc::new(source))
    }

    /// The sink's error, when it is an `E`.
    pub fn downcast_ref<E: std::error::Error + 'static>(&self) -> Option<&E> {
        self.0.downcast_ref()
    }
}

/// Equal when the same error or the same message (errors of a sink need not
/// compare).
impl PartialEq for SinkError {
    fn eq(&self, other: &SinkError) -> bool {
        Arc::ptr_eq(&self.0, &other.0) || self.0.to_string() == other.0.to_string()
    }
}

/// The front ends and the callers still returning text print the message.
impl From<StudyError> for String {
    fn from(e: StudyError) -> String {
        e.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::history::{HistoryMeta, HistoryRequest, HistorySink, SinkError, MAX_FILE_SAMPLES};
    use kick_core::{Parameter, ScenarioSpec};
    use kick_flight::FlightSpec;
    use std::path::Path;

    fn no_sink(_: &HistoryRequest, _: &[(&str, &str)], _: &HistoryMeta) -> Result<Box<dyn HistorySink>, SinkError> {
        Err("no sink in this test".into())
    }

    #[test]
    fn a_bad_simulate_input_is_the_model_error_it_was() {
        let mut spec = ScenarioSpec::default();
        spec.set(Parameter::FootMass, -1.0);
        let e = crate::simulate::simulate(&spec, "auto", None, None, None).unwrap_err();
        let StudyError::Kick(KickError::InvalidParameter { name, value, requirement }) = &e else {
            panic!("not the model's invalid parameter: {e:?}");
        };
        assert_eq!((*name, *value), ("foot_mass", -1.0));
        assert_eq!(e.status(), Status::Refused);
        // The message is the model's, byte for byte.
        let model = KickError::InvalidParameter { name, value: *value, requirement };
        assert_eq!(e.to_string(), model.to_string());
    }

    #[test]
    fn history_refusals_name_their_flag() {
        let too_many = MAX_FILE_SAMPLES as usize + 1;
        let e = HistoryRequest::new(Path::new("h.csv"), Some(too_many), None, no_sink).unwrap_err();
        assert_eq!(e, StudyError::HistoryRows { samples: too_many, max: MAX_FILE_SAMPLES });
        assert_eq!(e.to_string(), format!("--samples {too_many}: at most 10000000 rows in a history file"));
        assert_eq!(e.status(), Status::Refused);
        let e = HistoryRequest::new(Path::new("h.csv"), None, Some(-1.0), no_sink).unwrap_err();
        let StudyError::Spacing { flag: "interval", source } = &e else { panic!("{e:?}") };
        assert_eq!(e.to_string(), format!("{source} (flag --interval)"));
        let e = HistoryRequest::new(Path::new("h.txt"), None, None, no_sink).unwrap_err();
        assert!(matches!(e, StudyError::Flag { flag: "history", .. }), "{e:?}");
        // A sink that cannot open is the sink's error, not a model error.
        let request = HistoryRequest::new(Path::new("h.csv"), Some(3), None, no_sink).unwrap();
        let e = crate::simulate::simulate(&ScenarioSpec::default(), "auto", None, Some(&request), None).unwrap_err();
        assert_eq!(e, StudyError::Sink("no sink in this test".into()));
    }

    #[test]
    fn a_bad_flight_is_the_flight_error_with_its_flag() {
        let spec = FlightSpec { speed: Some(25.0), launch_angle: Some(20.0), ball_mass: Some(-1.0), ..FlightSpec::default() };
        let e = crate::flight::flight_report(&spec, None).unwrap_err();
        let StudyError::Flight { source: FlightError::InvalidParameter { name: "ball_mass", .. }, flag: Some(flag) } = &e else {
            panic!("not the flight's invalid parameter: {e:?}");
        };
        assert_eq!(flag, "--ball-mass");
        assert!(e.to_string().ends_with(" (flag --ball-mass)"), "{e}");
        assert_eq!(e.status(), Status::Refused);
    }

    #[test]
    fn a_missing_table2_file_names_the_file() {
        let e = crate::table2::compare(Path::new("no/such/table2.toml")).unwrap_err();
        let StudyError::File { path, .. } = &e else { panic!("{e:?}") };
        assert_eq!(path, Path::new("no/such/table2.toml"));
        assert!(e.to_string().starts_with("no/such/table2.toml: "), "{e}");
    }
}
