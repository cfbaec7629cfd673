use thiserror::Error;

/// Every way a kick computation can refuse or fail. Messages name the problem.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum KickError {
    #[error("invalid parameter `{name}` = {value}: must be {requirement}")]
    InvalidParameter {
        name: &'static str,
        value: f64,
        requirement: &'static str,
    },
    #[error(
        "no contact: the foot ({foot_speed} m/s) is not faster than the ball ({ball_speed} m/s), \
         so they never touch"
    )]
    NoContact { foot_speed: f64, ball_speed: f64 },
    #[error("no separation: the foot never releases the ball ({reason}; last checked at t = {time} s)")]
    NoSeparation { time: f64, reason: String },
    #[error("unknown solver `{name}`: expected one of {expected}")]
    UnknownSolver { name: String, expected: &'static str },
    #[error("solver `{solver}` does not apply to this scenario: {reason}")]
    NotApplicable { solver: &'static str, reason: &'static str },
    #[error("integration failed at t = {time} s: {reason}")]
    Integration { time: f64, reason: String },
    #[error("non-finite {quantity} at t = {time} s")]
    NonFinite { quantity: &'static str, time: f64 },
}

impl KickError {
    pub(crate) fn invalid(name: &'static str, value: f64, requirement: &'static str) -> Self {
        KickError::InvalidParameter {
            name,
            value,
            requirement,
        }
    }
}

/// Check that a computed quantity is finite before it leaves the library.
pub fn finite(quantity: &'static str, value: f64, time: f64) -> Result<f64, KickError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(KickError::NonFinite { quantity, time })
    }
}
