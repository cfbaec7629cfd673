use kick_core::{short, KickError, Status};
use thiserror::Error;

/// Every way a 3D kick computation can refuse or fail; messages name the problem.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Kick3dError {
    #[error(transparent)]
    Core(#[from] KickError),
    #[error("invalid parameter `{name}` = {}: must be {requirement}", short(*.value))]
    InvalidParameter { name: &'static str, value: f64, requirement: &'static str },
    #[error("offset {} m misses the ball: |offset| must be below the ball radius {} m", short(*.offset), short(*.radius))]
    OffsetOutsideBall { offset: f64, radius: f64 },
    #[error("contact geometry failed at t = {} s: {reason}", short(*.time))]
    Geometry { time: f64, reason: String },
    #[error("the {path} path cannot run this scene: {reason}")]
    UnsupportedScene { path: &'static str, reason: &'static str },
    #[error("unknown 3D solver `{name}`: expected one of {expected}")]
    UnknownSolver { name: String, expected: &'static str },
    #[error("3D experiment: {reason}")]
    Experiment { reason: String },
}

impl Kick3dError {
    /// What became of the kick (the status column of result files): a
    /// geometry failure is numerical, every other non-core error a refusal.
    pub fn status(&self) -> Status {
        match self {
            Kick3dError::Core(e) => e.status(),
            Kick3dError::Geometry { .. } => Status::NumericalFailure,
            _ => Status::Refused,
        }
    }
}
