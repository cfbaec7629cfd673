//! The rigid-body restitution model (Eqs. 36–40) and its limits (Eqs. 57–60).

use kick_core::{error::finite, ExitModel, ExitVelocities, KickError, Scenario};

/// Two rigid bodies and a coefficient of restitution e (Eq. 36).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestitutionModel {
    restitution: f64,
}

impl RestitutionModel {
    /// e must lie in [0, 1] for a passive collision.
    pub fn new(restitution: f64) -> Result<Self, KickError> {
        if (0.0..=1.0).contains(&restitution) {
            Ok(RestitutionModel { restitution })
        } else {
            Err(KickError::InvalidParameter { name: "restitution", value: restitution, requirement: "in [0, 1]" })
        }
    }
    pub fn restitution(&self) -> f64 {
        self.restitution
    }
}

impl ExitModel for RestitutionModel {
    fn exit_velocities(&self, scenario: &Scenario) -> Result<ExitVelocities, KickError> {
        let e = self.restitution;
        let (m_f, m_b) = (scenario.effective_foot_mass(), scenario.ball_mass());
        let (v_f, v_b) = (scenario.foot_speed(), scenario.ball_speed());
        let m = m_f + m_b;
        // Eq. 37
        let ball = (1.0 + e) * m_f / m * v_f + (m_b - e * m_f) / m * v_b;
        // Eq. 36 rearranged: v_f⁺ = v_b⁺ − e (v_f⁻ − v_b⁻)
        let foot = ball - e * (v_f - v_b);
        Ok(ExitVelocities { foot: finite("foot exit velocity", foot, 0.0)?, ball: finite("ball exit velocity", ball, 0.0)? })
    }
}

/// Eq. 38: v_b⁺/v_f⁻ for a ball at rest.
pub fn speed_ratio_ball_at_rest(restitution: f64, foot_mass: f64, ball_mass: f64) -> f64 {
    (1.0 + restitution) * foot_mass / (foot_mass + ball_mass)
}

/// Eq. 39: the restitution above which the ball leaves faster than the foot came in.
pub fn faster_than_foot_threshold(foot_mass: f64, ball_mass: f64) -> f64 {
    ball_mass / foot_mass
}

/// Eq. 57: the moving-wall limit m_f/m_b → ∞.
pub fn moving_wall_ball_speed(restitution: f64, foot_speed: f64, ball_speed: f64) -> f64 {
    (1.0 + restitution) * foot_speed - restitution * ball_speed
}

/// Eq. 58: as m_f → 0 the ball keeps its incoming speed (zero for a ball at rest).
pub fn vanishing_foot_ball_speed(ball_speed: f64) -> f64 {
    ball_speed
}

/// Eq. 59: perfectly inelastic, both leave at V_cm.
pub fn inelastic_exit(scenario: &Scenario) -> ExitVelocities {
    let v = scenario.centre_of_mass_speed();
    ExitVelocities { foot: v, ball: v }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scenario(foot_mass: f64, ball_speed: f64) -> Scenario {
        Scenario::baseline()
            .with(kick_core::Parameter::FootMass, foot_mass)
            .unwrap()
            .with(kick_core::Parameter::BallSpeed, ball_speed)
            .unwrap()
    }

    #[test]
    fn eq36_and_momentum_hold_for_any_e() {
        for e in [0.0, 0.3, 0.7, 1.0] {
            for v_b in [-8.0, 0.0, 5.0] {
                let s = scenario(3.0, v_b);
                let exit = RestitutionModel::new(e).unwrap().exit_velocities(&s).unwrap();
                let p0 = 3.0 * 22.0 + 0.43 * v_b;
                assert!((3.0 * exit.foot + 0.43 * exit.ball - p0).abs() < 1e-12 * p0.abs());
                assert!(((exit.ball - exit.foot) - e * (22.0 - v_b)).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn eq38_threshold_eq39() {
        // m_f = 3, m_b = 0.43: threshold 0.1433...
        let e_star = faster_than_foot_threshold(3.0, 0.43);
        assert!((e_star - 0.43 / 3.0).abs() < 1e-15);
        assert!((speed_ratio_ball_at_rest(e_star, 3.0, 0.43) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn limits_57_to_60() {
        let e = 0.6;
        let model = RestitutionModel::new(e).unwrap();
        // Eq. 57: heavy foot
        let heavy = model.exit_velocities(&scenario(1e9, -3.0)).unwrap();
        assert!((heavy.ball - moving_wall_ball_speed(e, 22.0, -3.0)).abs() < 1e-6);
        // Eq. 58: vanishing foot
        let light = model.exit_velocities(&scenario(1e-9, 0.0)).unwrap();
        assert!(light.ball.abs() < 1e-7);
        // Eq. 59
        let s = scenario(3.0, 2.0);
        let inelastic = RestitutionModel::new(0.0).unwrap().exit_velocities(&s).unwrap();
        assert!((inelastic.ball - inelastic_exit(&s).ball).abs() < 1e-12);
        assert!((inelastic.foot - s.centre_of_mass_speed()).abs() < 1e-12);
        // Eq. 60 and Eq. 40
        let elastic = RestitutionModel::new(1.0).unwrap().exit_velocities(&scenario(1e12, 0.0)).unwrap();
        assert!((elastic.ball - 44.0).abs() < 1e-9);
    }

    #[test]
    fn out_of_range_restitution_is_refused() {
        assert!(RestitutionModel::new(1.2).is_err());
        assert!(RestitutionModel::new(f64::NAN).is_err());
    }
}
