//! The impulse-only model (Eqs. 1–2): exit velocities from a known impulse.
//!
//! It answers how much the velocities change, not how long the contact lasts
//! or how large the force gets.

use kick_core::{error::finite, ExitModel, ExitVelocities, KickError, Scenario};

/// Exit velocities from the contact impulse J and any external (drive) impulse on the foot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpulseModel {
    /// J = ∫ F_c dt in N s (Eq. 1), positive when the foot pushes the ball.
    pub impulse: f64,
    /// ∫ F_drive dt on the foot, in N s (zero for a passive kick).
    pub drive_impulse: f64,
}

impl ImpulseModel {
    pub fn passive(impulse: f64) -> Self {
        ImpulseModel { impulse, drive_impulse: 0.0 }
    }
}

impl ExitModel for ImpulseModel {
    fn exit_velocities(&self, scenario: &Scenario) -> Result<ExitVelocities, KickError> {
        finite("impulse", self.impulse, 0.0)?;
        finite("drive impulse", self.drive_impulse, 0.0)?;
        // Eq. 2 for the ball; Newton's third law (Eq. 13 integrated) for the foot.
        let ball = scenario.ball_speed() + self.impulse / scenario.ball_mass();
        let foot = scenario.foot_speed() + (self.drive_impulse - self.impulse) / scenario.effective_foot_mass();
        Ok(ExitVelocities { foot: finite("foot exit velocity", foot, 0.0)?, ball: finite("ball exit velocity", ball, 0.0)? })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn momentum_is_conserved_for_a_passive_impulse() {
        let s = Scenario::baseline();
        let exit = ImpulseModel::passive(13.75).exit_velocities(&s).unwrap();
        let before = s.effective_foot_mass() * s.foot_speed() + s.ball_mass() * s.ball_speed();
        let after = s.effective_foot_mass() * exit.foot + s.ball_mass() * exit.ball;
        assert!((before - after).abs() <= 1e-14 * before.abs());
        assert!((exit.ball - 13.75 / 0.43).abs() < 1e-13);
    }

    #[test]
    fn non_finite_impulse_is_an_error() {
        let s = Scenario::baseline();
        assert!(ImpulseModel::passive(f64::NAN).exit_velocities(&s).is_err());
    }
}
