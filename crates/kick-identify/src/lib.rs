//! Parameter identification for the 1D kick model (Sections 17.8 and 19).
//!
//! - [`data`]: observations — scalar observables (exit speed, contact time,
//!   peak force, maximum compression) or time histories (force, compression,
//!   velocities) — and the fit specification file.
//! - [`model`]: the forward model, `kick_compliant::Accurate` with the
//!   scenario's contact law, evaluated at the observations (histories by
//!   Hermite interpolation between its steps, shifted by the time offset).
//! - [`parameter`]: what a fit can vary: the scenario's parameters, the
//!   target restitution of the laws other than the paper's, the time offset.
//! - [`fit`]: Levenberg–Marquardt (crate `levenberg-marquardt`) over any subset
//!   of those, positive ones in log space, the restitution in logit space, with
//!   standard uncertainties from the Jacobian, residuals and the correlation matrix.
//! - [`profile`]: misfit profiles and maps for the identifiability question.
//! - [`table2`]: Table 2's changed parameter per row from the four printed observables.
//! - [`synthetic`]: data from known parameters plus seeded Gaussian noise.
//! - [`laws`]: the contact-law comparison on Table 2's scenarios.
//! - [`validation`]: the 1D contact beside published measurements, and the
//!   stiffness and foot mass they imply.

pub mod data;
pub mod fit;
pub mod laws;
pub mod model;
pub mod parameter;
pub mod profile;
pub mod synthetic;
pub mod table2;
pub mod validation;

pub use data::{Channel, FitSpec, HistoryData, Measurement, Observable, Observations, ScalarObservation};
pub use fit::{fit, fit_with_cancel, Estimate, FitOptions, FitProblem, FitReport, FitStop};
pub use parameter::{Coordinate, FitLevel, FitParameter, ModelPoint};

use kick_core::KickError;
use thiserror::Error;

/// Every way an identification can refuse or fail; messages name the problem.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum IdentifyError {
    #[error(transparent)]
    Model(#[from] KickError),
    #[error("no free parameters: name at least one parameter to fit")]
    NoFreeParameters,
    #[error("parameter `{0}` is listed more than once")]
    DuplicateParameter(&'static str),
    /// `hint`: ": did you mean ...?" or ": expected one of ...".
    #[error("unknown parameter `{name}`{hint}")]
    UnknownParameter { name: String, hint: String },
    #[error("parameter `{name}` starts at {}: it must be {requirement}", kick_core::short(*.value))]
    StartOutOfRange { name: &'static str, value: f64, requirement: &'static str },
    #[error("parameter `{parameter}` does not apply {context}: {reason}")]
    NotApplicable { parameter: &'static str, context: String, reason: &'static str },
    #[error("no observations to fit")]
    NoData,
    #[error("unknown observable `{name}`: expected one of {expected}")]
    UnknownObservable { name: String, expected: &'static str },
    #[error("unknown history column `{name}`: expected time and any of {expected}")]
    UnknownChannel { name: String, expected: &'static str },
    #[error("{source_name}: {message}")]
    Data { source_name: String, message: String },
    #[error("the fit stopped without converging: {0}")]
    NotConverged(String),
    /// `observations`: the distinct ones; `repeats`: those that repeat an
    /// observable at conditions already observed ([`fit::distinct_observations`]).
    #[error(
        "under-determined fit: more free parameters ({parameters}) than observations ({observations}){}; \
         fix some parameters or add observations",
        if *.repeats == 0 { String::new() } else {
            format!(" at distinct conditions ({} more repeat one at the same conditions: they sharpen it, they determine no \
                     other parameter)", .repeats)
        }
    )]
    UnderDetermined { observations: usize, parameters: usize, repeats: usize },
    #[error("non-finite {quantity} in the fit: {reason}")]
    NonFinite { quantity: &'static str, reason: String },
    /// A history fit whose contact explains the data no better than none
    /// ([`fit::CONTACT_SIGNIFICANCE`]): its estimates would be noise.
    #[error(
        "the history shows no contact: the fitted one (first touch at t0 = {} s) leaves chi-square {} over the \
         {samples} history samples, no contact at all {}; the data run from {} s to {} s: check their times and time_offset",
        kick_core::short(*.time_offset), kick_core::short(*.fitted), kick_core::short(*.without),
        kick_core::short(*.first), kick_core::short(*.last)
    )]
    NoContact { time_offset: f64, fitted: f64, without: f64, samples: usize, first: f64, last: f64 },
    /// Every observation's derivative with respect to every free parameter
    /// is zero at the end of the fit: the optimiser stops where it started
    /// ("gradient zero"), which is no estimate.
    #[error(
        "the observations do not depend on the free parameters ({free}) at the fit's end, {point}: their derivatives are all \
         zero, so nothing was fitted (data taken away from the contact, or a start where the observables no longer move?)"
    )]
    Insensitive { free: String, point: String },
}

impl IdentifyError {
    /// What became of the fit: the model's own status, a fit that stopped
    /// or went non-finite a numerical failure, anything else refused.
    pub fn status(&self) -> kick_core::Status {
        use kick_core::Status;
        match self {
            IdentifyError::Model(e) => e.status(),
            IdentifyError::NotConverged(_) | IdentifyError::NonFinite { .. } => Status::NumericalFailure,
            IdentifyError::NoFreeParameters
            | IdentifyError::DuplicateParameter(_)
            | IdentifyError::UnknownParameter { .. }
            | IdentifyError::StartOutOfRange { .. }
            | IdentifyError::NotApplicable { .. }
            | IdentifyError::NoData
            | IdentifyError::UnknownObservable { .. }
            | IdentifyError::UnknownChannel { .. }
            | IdentifyError::Data { .. }
            | IdentifyError::UnderDetermined { .. }
            | IdentifyError::NoContact { .. }
            | IdentifyError::Insensitive { .. } => Status::Refused,
        }
    }

    pub(crate) fn data(source_name: impl Into<String>, message: impl Into<String>) -> Self {
        IdentifyError::Data { source_name: source_name.into(), message: message.into() }
    }
}
