//! The relative coordinate of Eq. 18, (δ, δ̇, D), shared by every solver
//! that integrates it (`reduced`, the booted engine, the shell and the
//! booted series): its equations, and foot and ball recovered from it.

use crate::events::{ContactSystem, Scales};
use crate::ode::Extremes;
use kick_core::{ContactLaw, EnergyBudget, KickError, Outcome, Scenario, SolverPath, StopReason};
use nalgebra::SVector;

/// (δ, δ̇, D).
pub type RelativeState = SVector<f64, 3>;

/// Eq. 18 with the dissipation integral.
#[derive(Debug, Clone, Copy)]
pub struct RelativeOde<L> {
    pub law: L,
    pub reduced_mass: f64,
    /// (μ/m_f) F_drive, the drive's share on the relative coordinate.
    pub drive_share: f64,
    /// Set per phase by the engine: which side of δ̇ = 0 the force follows.
    pub compressing: Option<bool>,
}

impl<L: ContactLaw + Copy> RelativeOde<L> {
    pub fn new(scenario: &Scenario, law: L) -> Self {
        RelativeOde {
            law,
            reduced_mass: scenario.reduced_mass(),
            drive_share: scenario.reduced_mass() / scenario.effective_foot_mass() * scenario.drive_force(),
            compressing: None,
        }
    }
    /// (elastic, total) force on this phase's branch.
    #[inline]
    fn forces(&self, y: &RelativeState) -> (f64, f64) {
        match self.compressing {
            Some(compressing) => self.law.branch_force(y[0], y[1], compressing),
            None => self.law.elastic_and_contact_force(y[0], y[1]),
        }
    }
    #[inline]
    fn acceleration(&self, y: &RelativeState) -> f64 {
        (self.drive_share - self.forces(y).1) / self.reduced_mass
    }
}

impl<L: ContactLaw + Copy> ContactSystem<3> for RelativeOde<L> {
    #[inline]
    fn derivative(&self, _t: f64, y: &RelativeState) -> RelativeState {
        let (elastic, force) = self.forces(y);
        RelativeState::new(y[1], (self.drive_share - force) / self.reduced_mass, (force - elastic) * y[1])
    }
    #[inline]
    fn compression(&self, y: &RelativeState) -> f64 {
        y[0]
    }
    #[inline]
    fn compression_rate(&self, y: &RelativeState) -> f64 {
        y[1]
    }
    #[inline]
    fn force(&self, y: &RelativeState) -> f64 {
        self.forces(y).1
    }
    #[inline]
    fn force_rate(&self, y: &RelativeState) -> f64 {
        let (force, d_delta, d_rate) = match self.compressing {
            Some(compressing) => self.law.branch_force_and_gradient(y[0], y[1], compressing),
            None => self.law.force_and_gradient(y[0], y[1]),
        };
        d_delta * y[1] + d_rate * (self.drive_share - force) / self.reduced_mass
    }
    #[inline]
    fn compression_acceleration(&self, y: &RelativeState) -> f64 {
        self.acceleration(y)
    }
    fn for_phase(&self, compressing: bool) -> Self {
        RelativeOde { compressing: Some(compressing), ..*self }
    }
    fn units(&self, s: &Scales) -> RelativeState {
        RelativeState::new(s.length, s.speed, s.energy)
    }
    fn budget(&self, scenario: &Scenario, t: f64, y: &RelativeState) -> EnergyBudget {
        let r = reconstruct(scenario, t, y);
        EnergyBudget {
            kinetic_initial: scenario.initial_kinetic_energy(),
            kinetic_final: 0.5 * scenario.effective_foot_mass() * r.foot_velocity.powi(2)
                + 0.5 * scenario.ball_mass() * r.ball_velocity.powi(2),
            elastic_final: self.law.potential(y[0]),
            dissipated: y[2],
            drive_work: r.drive_work,
        }
    }
}

/// Foot and ball from the relative state at time t.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Reconstruction {
    pub foot_velocity: f64,
    pub ball_velocity: f64,
    pub foot_position: f64,
    pub ball_position: f64,
    pub drive_work: f64,
}

pub(crate) fn reconstruct(scenario: &Scenario, t: f64, y: &RelativeState) -> Reconstruction {
    let total = scenario.total_mass();
    let drive = scenario.drive_force();
    let v_cm = scenario.centre_of_mass_speed() + drive * t / total; // Eq. 26
    let x_cm = scenario.centre_of_mass_speed() * t + 0.5 * drive * t * t / total;
    let foot_share = scenario.ball_mass() / total;
    let ball_share = scenario.effective_foot_mass() / total;
    let foot_position = x_cm + foot_share * y[0];
    Reconstruction {
        foot_velocity: v_cm + foot_share * y[1],
        ball_velocity: v_cm - ball_share * y[1],
        foot_position,
        ball_position: x_cm - ball_share * y[0],
        drive_work: drive * foot_position,
    }
}

/// The summary of a contact solved in relative coordinates (`reduced`, the
/// booted engine, the shell and the booted series): the state `end` (δ, δ̇
/// and the energy dissipated) at separation time `t`, the extremes located
/// along the way and the path's own energy budget. Exit velocities by
/// [`reconstruct`], Eq. 2's impulse, and Eq. 36 from δ̇ itself (v_b − v_f =
/// −δ̇, without the cancellation of two lab-frame speeds). Checked finite.
pub(crate) fn separated(
    scenario: &Scenario,
    t: f64,
    end: &RelativeState,
    extremes: Extremes,
    energy: EnergyBudget,
    evaluations: u64,
    method: SolverPath,
) -> Result<Outcome, KickError> {
    let r = reconstruct(scenario, t, end);
    crate::ode::check_finite(&Outcome {
        v_ball_out: r.ball_velocity,
        v_foot_out: r.foot_velocity,
        speed_ratio: Outcome::ratio(r.ball_velocity, scenario.foot_speed()),
        peak_force: extremes.peak_force,
        peak_force_time: extremes.peak_force_time,
        contact_time: t,
        max_compression: extremes.max_compression,
        max_compression_time: extremes.max_compression_time,
        impulse: scenario.ball_mass() * (r.ball_velocity - scenario.ball_speed()), // Eq. 2
        restitution: -end[1] / scenario.approach_speed(),                          // Eq. 36
        energy,
        stop: StopReason::Separated { t },
        evaluations,
        method,
    })
}
