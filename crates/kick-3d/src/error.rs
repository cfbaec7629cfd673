use kick_core::{short, KickError};
use thiserror::Error;

/// Every way a 3D kick computation can refuse or fail; messages name the problem.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Kick3dError {
    #[error(transparent)]
    Core(#[from] KickError),
    #[error("invalid parameter `{name}` = {}: must be {requirement}", kick_core::number::given(*.value))]
    InvalidParameter { name: &'static str, value: f64, requirement: &'static str },
    /// The foot's line of motion passes outside the ball: √(e² + h²) ≥ R.
    #[error("{}", outside_ball(*.offset, *.depth, *.radius))]
    OffsetOutsideBall { offset: f64, depth: f64, radius: f64 },
    #[error("contact geometry failed at t = {} s: {reason}", short(*.time))]
    Geometry { time: f64, reason: String },
    #[error("the {path} path cannot run this scene: {reason}")]
    UnsupportedScene { path: &'static str, reason: &'static str },
    #[error("unknown 3D solver `{name}`: expected one of {expected}")]
    UnknownSolver { name: String, expected: &'static str },
    #[error("3D experiment: {reason}")]
    Experiment { reason: String },
}

/// The message of [`Kick3dError::OffsetOutsideBall`]: the offset alone when the contact depth is 0.
fn outside_ball(offset: f64, depth: f64, radius: f64) -> String {
    if depth == 0.0 {
        format!("offset {} m misses the ball: |offset| must be below the ball radius {} m", short(offset), short(radius))
    } else {
        format!(
            "offset {} m and contact_depth {} m miss the ball: the foot's line of motion must pass within the ball radius {} m \
             of its centre (offset² + contact_depth² < R²)",
            short(offset),
            short(depth),
            short(radius)
        )
    }
}

impl Kick3dError {
    /// What became of the kick, for status columns: the core error's own
    /// status, a geometry query that failed mid-run a numerical failure,
    /// anything refused before solving `Refused`.
    pub fn status(&self) -> kick_core::Status {
        match self {
            Kick3dError::Core(e) => e.status(),
            Kick3dError::Geometry { .. } => kick_core::Status::NumericalFailure,
            Kick3dError::InvalidParameter { .. }
            | Kick3dError::OffsetOutsideBall { .. }
            | Kick3dError::UnsupportedScene { .. }
            | Kick3dError::UnknownSolver { .. }
            | Kick3dError::Experiment { .. } => kick_core::Status::Refused,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_core::Status;

    #[test]
    fn status_sorts_refusals_failures_and_physics() {
        let mut spec = crate::KickSpec::default();
        spec.kick3d.offset = Some(0.2);
        assert_eq!(spec.build().unwrap_err().status(), Status::Refused);
        let trapped = Kick3dError::Core(KickError::Trapped { time: 1e-3, reason: "drive".into() });
        assert_eq!(trapped.status(), Status::Trapped);
        assert_eq!(Kick3dError::Geometry { time: 0.0, reason: "none".into() }.status(), Status::NumericalFailure);
        let limit = Kick3dError::Core(KickError::NoSeparation { time: 1.0, reason: "horizon".into() });
        assert_eq!(limit.status(), Status::NumericalFailure);
    }
}
