use crate::number::short;
use serde::Serialize;
use thiserror::Error;

/// [`KickError::InvalidParameter`]'s message: a parameter that was not
/// given (NaN, "must be given ...") is said to be missing, not to be NaN.
fn invalid_text(name: &str, value: f64, requirement: &str) -> String {
    if value.is_nan() && requirement.starts_with("given") {
        format!("`{name}` is not given: it must be {requirement}")
    } else {
        format!("invalid parameter `{name}` = {}: must be {requirement}", crate::number::given(value))
    }
}

/// Every way a kick computation can refuse or fail. Messages name the problem.
///
/// [`KickError::status`] sorts them: a ball proven trapped is a physical
/// outcome ([`KickError::Trapped`]); a run a numerical limit ended is a
/// failure ([`KickError::NoSeparation`] among others), never physics.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum KickError {
    #[error("{}", invalid_text(name, *.value, requirement))]
    InvalidParameter { name: &'static str, value: f64, requirement: &'static str },
    #[error(
        "no contact: the foot ({} m/s) is not faster than the ball ({} m/s), \
         so they never touch",
        short(*.foot_speed),
        short(*.ball_speed)
    )]
    NoContact { foot_speed: f64, ball_speed: f64 },
    /// Proven: the ball never leaves the foot (a drive keeps it pressed) or,
    /// in a bounce, the plate (its weight holds it). `reason` says which
    /// and why; `time` is where the proof was made.
    #[error("trapped: {reason} (proven at t = {} s)", short(*.time))]
    Trapped { time: f64, reason: String },
    /// Still in contact when a solver's limit ran out (its time horizon, its
    /// step budget): a numerical limit, not a proof that the ball is trapped.
    #[error(
        "no separation found within the solver's limits ({reason}; last checked at t = {} s); \
         not proven trapped",
        short(*.time)
    )]
    NoSeparation { time: f64, reason: String },
    /// A fixed step beyond the stability limit of its method on this contact
    /// (linearised law, checked before integrating).
    #[error(
        "step too large: dt = {} s exceeds {} s, the largest step \
         {method} keeps stable on this contact ({reason}); use a smaller dt or an adaptive solver",
        short(*.step),
        short(*.largest_stable_step)
    )]
    StepTooLarge { method: &'static str, step: f64, largest_stable_step: f64, reason: String },
    /// A fixed step whose energy budget does not close: the residual
    /// (K⁻ + W) − (K⁺ + U⁺ + D) relative to the energy through the contact
    /// exceeds the bound (checked after integrating).
    #[error(
        "step too large: dt = {} s leaves an energy residual of {} of the \
         energy through the contact (bound {}) at t = {} s; use a smaller dt or an \
         adaptive solver",
        short(*.step),
        short(*.relative_residual),
        short(*.bound),
        short(*.time)
    )]
    StepTooInaccurate { step: f64, relative_residual: f64, bound: f64, time: f64 },
    /// A history would hold more samples than allowed
    /// ([`crate::MAX_HISTORY_SAMPLES`]), counted before any is made.
    #[error(
        "history too long: it needs {} samples, more than the limit of {limit}; use a \
         longer interval or fewer samples",
        short(*.needed)
    )]
    HistoryTooLong { needed: f64, limit: u64 },
    /// Valid parameters whose contact leaves double precision's working
    /// range ([`crate::scenario::SCALE_RANGE`]).
    #[error(
        "parameters out of range: the {quantity} is {} {unit}, outside 1e-100 .. 1e100; \
         change {parameters}",
        short(*.value)
    )]
    OutOfRange { quantity: &'static str, value: f64, unit: &'static str, parameters: &'static str },
    #[error("unknown solver `{name}`: expected one of {expected}")]
    UnknownSolver { name: String, expected: &'static str },
    #[error("solver `{solver}` does not apply to this scenario: {reason}")]
    NotApplicable { solver: &'static str, reason: &'static str },
    /// A setting given that the chosen law or solver would ignore
    /// (`restitution` under the paper's law, `dt` with an adaptive solver).
    #[error("`{given}` does not apply to {to}: {reason}; leave it out")]
    DoesNotApply { given: &'static str, to: String, reason: &'static str },
    #[error("integration failed at t = {} s: {reason}", short(*.time))]
    Integration { time: f64, reason: String },
    /// A driven foot caught the ball up again at a least compression within
    /// the integration's own error of separation (`resolved`: that error
    /// bound), so whether the ball left cannot be told: a numerical failure.
    #[error(
        "integration failed at t = {} s: the foot caught the ball up again at a least compression of {} m, within the \
         integration's error ({} m) of separation: whether the ball left the foot cannot be told (a drive whose work \
         dwarfs the approach's kinetic energy); the `series` solver takes the separation from the energy balance instead",
        short(*.time),
        short(*.least),
        short(*.resolved)
    )]
    CaughtUp { time: f64, least: f64, resolved: f64 },
    #[error("non-finite {quantity} at t = {} s", short(*.time))]
    NonFinite { quantity: &'static str, time: f64 },
    /// A fixed step that would need more steps than the budget to cover the
    /// contact horizon: refused before integrating, as its run time is ∝ 1/dt.
    #[error(
        "step too small: dt = {} s (`--dt`, the `dt` key or keyword) needs {} steps to cover the contact \
         horizon of {} s, more than the budget of {} steps; use a larger dt or an adaptive solver",
        short(*.step),
        short(*.steps),
        short(*.horizon),
        short(*.limit)
    )]
    TooManySteps { step: f64, steps: f64, horizon: f64, limit: f64 },
    /// A compression beyond what the contact geometry allows: the bodies
    /// would pass through each other, so the law (and the scene) no longer
    /// describe a contact. An error, never an outcome.
    #[error(
        "compression beyond the geometry: δ = {} m at t = {} s exceeds {limit_name} = {} m, where {why}; \
         the scene is outside the contact model (lower the speeds or the drive, or stiffen the ball)",
        short(*.compression),
        short(*.time),
        short(*.limit)
    )]
    BeyondGeometry { compression: f64, time: f64, limit: f64, limit_name: &'static str, why: &'static str },
}

/// What became of a scenario: the status column of result files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// The ball left the foot; there is an outcome.
    Separated,
    /// Proven that the ball never leaves the foot (or, bouncing, the plate): a physical outcome.
    Trapped,
    /// A numerical limit ended the run (step too large, integration
    /// failure, non-finite state, horizon or step budget reached without a
    /// proof): no statement about the physics.
    NumericalFailure,
    /// The input or request was refused (invalid parameter, no contact,
    /// unknown or inapplicable solver, history beyond its limit).
    Refused,
    /// Solved, but outside the region where the contact law holds
    /// ([`crate::validity`]: the shell ball compressed past R/2, any other
    /// law past R): the outcome's numbers are kept and flagged, never
    /// reported as an ordinary result.
    OutsideValidity,
}

impl Status {
    /// Every status, in code order.
    pub const ALL: [Status; 5] = [Status::Separated, Status::NumericalFailure, Status::Trapped, Status::Refused, Status::OutsideValidity];

    pub fn of<T>(result: &Result<T, KickError>) -> Status {
        match result {
            Ok(_) => Status::Separated,
            Err(e) => e.status(),
        }
    }
    /// Code for integer status columns.
    pub fn code(self) -> u8 {
        match self {
            Status::Separated => 0,
            Status::NumericalFailure => 1,
            Status::Trapped => 2,
            Status::Refused => 3,
            Status::OutsideValidity => 4,
        }
    }
    /// Whether a row of this status keeps its outcome's numbers (separated,
    /// or outside the law's validity); the others have none.
    pub fn has_outcome(self) -> bool {
        matches!(self, Status::Separated | Status::OutsideValidity)
    }
    pub fn name(self) -> &'static str {
        match self {
            Status::Separated => "separated",
            Status::Trapped => "trapped",
            Status::NumericalFailure => "numerical failure",
            Status::Refused => "refused",
            Status::OutsideValidity => "outside validity",
        }
    }
}

impl KickError {
    pub(crate) fn invalid(name: &'static str, value: f64, requirement: &'static str) -> Self {
        KickError::InvalidParameter { name, value, requirement }
    }

    pub fn status(&self) -> Status {
        match self {
            KickError::Trapped { .. } => Status::Trapped,
            KickError::NoSeparation { .. }
            | KickError::StepTooLarge { .. }
            | KickError::StepTooInaccurate { .. }
            | KickError::Integration { .. }
            | KickError::CaughtUp { .. }
            | KickError::NonFinite { .. } => Status::NumericalFailure,
            KickError::InvalidParameter { .. }
            | KickError::NoContact { .. }
            | KickError::OutOfRange { .. }
            | KickError::HistoryTooLong { .. }
            | KickError::UnknownSolver { .. }
            | KickError::NotApplicable { .. }
            | KickError::DoesNotApply { .. }
            | KickError::TooManySteps { .. }
            | KickError::BeyondGeometry { .. } => Status::Refused,
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

#[cfg(test)]
mod tests {
    use super::{KickError, Status};

    /// `Status::ALL` lists every status once, at the index of its code.
    #[test]
    fn all_statuses_in_code_order() {
        for (i, status) in Status::ALL.iter().enumerate() {
            assert_eq!(usize::from(status.code()), i, "{status:?}");
        }
    }

    /// A parameter that was not given is reported missing, not "= NaN"
    /// (`kick bounce` without a speed); a given value is quoted as before.
    #[test]
    fn a_missing_parameter_is_not_reported_as_nan() {
        let missing = KickError::InvalidParameter { name: "speed", value: f64::NAN, requirement: "given, or drop_height instead" };
        assert_eq!(missing.to_string(), "`speed` is not given: it must be given, or drop_height instead");
        let given = KickError::InvalidParameter { name: "foot_mass", value: -1.0, requirement: "finite and > 0" };
        assert_eq!(given.to_string(), "invalid parameter `foot_mass` = -1: must be finite and > 0");
    }
}
