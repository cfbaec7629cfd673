//! The 1D compliant system (Eqs. 13–14, 20) on the state of Eq. 47, extended
//! by three running integrals so the energy budget is measured, not inferred.

use kick_core::{ContactLaw, ContactPhase, EnergyBudget, Outcome, Sample, Scenario, SolverPath, StopReason};
use nalgebra::SVector;

/// (x_f, v_f, x_b, v_b, J, D, W): Eq. 47 plus impulse ∫F dt, dissipation
/// ∫(F − F(δ,0)) δ̇ dt and drive work ∫F_drive v_f dt.
pub type State = SVector<f64, 7>;
pub const FOOT_POSITION: usize = 0;
pub const FOOT_VELOCITY: usize = 1;
pub const BALL_POSITION: usize = 2;
pub const BALL_VELOCITY: usize = 3;
pub const IMPULSE: usize = 4;
pub const DISSIPATED: usize = 5;
pub const DRIVE_WORK: usize = 6;

/// Which branch of the force the right-hand side uses at δ ≤ 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Branch {
    /// Eq. 20 literally: no force at δ ≤ 0 (the paper's fixed-step method).
    Literal,
    /// Contact is known to hold: the right limit at δ = 0, so F(0⁺) = c V0.
    InContact,
}

/// Right-hand side of Eqs. 13–14 for one scenario.
#[derive(Debug, Clone, Copy)]
pub struct ContactOde<L> {
    pub law: L,
    pub foot_mass: f64,
    pub ball_mass: f64,
    pub drive_force: f64,
    pub branch: Branch,
    /// Set per phase by the event engine: which side of δ̇ = 0 the force follows.
    pub compressing: Option<bool>,
}

impl<L: ContactLaw + Copy> ContactOde<L> {
    pub fn new(scenario: &Scenario, law: L, branch: Branch) -> Self {
        ContactOde {
            law,
            foot_mass: scenario.effective_foot_mass(),
            ball_mass: scenario.ball_mass(),
            drive_force: scenario.drive_force(),
            branch,
            compressing: None,
        }
    }

    /// (elastic, total) force.
    #[inline]
    fn forces(&self, y: &State) -> (f64, f64) {
        let (compression, rate) = (compression(y), compression_rate(y));
        match (self.branch, self.compressing) {
            (Branch::Literal, _) if compression <= 0.0 => (0.0, 0.0),
            (_, Some(compressing)) => self.law.branch_force(compression, rate, compressing),
            _ => self.law.elastic_and_contact_force(compression, rate),
        }
    }

    #[inline]
    pub fn force(&self, y: &State) -> f64 {
        self.forces(y).1
    }

    #[inline]
    pub fn derivative(&self, y: &State) -> State {
        let rate = compression_rate(y);
        let (elastic, force) = self.forces(y);
        State::from([
            y[FOOT_VELOCITY],
            (self.drive_force - force) / self.foot_mass, // Eq. 13
            y[BALL_VELOCITY],
            force / self.ball_mass, // Eq. 14
            force,
            (force - elastic) * rate, // Eq. 25
            self.drive_force * y[FOOT_VELOCITY],
        ])
    }

    /// One classical RK4 step of size h.
    #[inline]
    pub fn rk4_step(&self, y: &State, h: f64) -> State {
        crate::events::rk4_step(|y| self.derivative(y), y, h)
    }

    /// δ̈ (Eq. 16).
    #[inline]
    pub fn compression_acceleration(&self, y: &State) -> f64 {
        let force = self.force(y);
        (self.drive_force - force) / self.foot_mass - force / self.ball_mass
    }

    /// dF/dt along the solution.
    #[inline]
    pub fn force_rate(&self, y: &State) -> f64 {
        let rate = compression_rate(y);
        let (force, d_delta, d_rate) = match (self.branch, self.compressing) {
            (Branch::Literal, _) if compression(y) <= 0.0 => (0.0, 0.0, 0.0),
            (_, Some(compressing)) => self.law.branch_force_and_gradient(compression(y), rate, compressing),
            _ => self.law.force_and_gradient(compression(y), rate),
        };
        let acceleration = (self.drive_force - force) / self.foot_mass - force / self.ball_mass;
        d_delta * rate + d_rate * acceleration
    }

    pub fn kinetic_energy(&self, y: &State) -> f64 {
        // Eq. 30
        0.5 * self.foot_mass * y[FOOT_VELOCITY].powi(2) + 0.5 * self.ball_mass * y[BALL_VELOCITY].powi(2)
    }

    /// The energy budget (Eqs. 30–33) at state `y`.
    pub fn budget(&self, scenario: &Scenario, y: &State) -> EnergyBudget {
        EnergyBudget {
            kinetic_initial: scenario.initial_kinetic_energy(),
            kinetic_final: self.kinetic_energy(y),
            elastic_final: self.law.potential(compression(y)),
            dissipated: y[DISSIPATED],
            drive_work: y[DRIVE_WORK],
        }
    }

    pub fn sample(&self, t: f64, y: &State, phase: ContactPhase) -> Sample {
        Sample {
            time: t,
            foot_position: y[FOOT_POSITION],
            foot_velocity: y[FOOT_VELOCITY],
            ball_position: y[BALL_POSITION],
            ball_velocity: y[BALL_VELOCITY],
            compression: compression(y).max(0.0),
            force: self.force(y),
            kinetic: self.kinetic_energy(y),
            elastic: self.law.potential(compression(y)),
            dissipated: y[DISSIPATED],
            drive_work: y[DRIVE_WORK],
            phase,
        }
    }
}

impl<L: ContactLaw + Copy> crate::events::ContactSystem<7> for ContactOde<L> {
    #[inline]
    fn derivative(&self, _t: f64, y: &State) -> State {
        ContactOde::derivative(self, y)
    }
    #[inline]
    fn compression(&self, y: &State) -> f64 {
        compression(y)
    }
    #[inline]
    fn compression_rate(&self, y: &State) -> f64 {
        compression_rate(y)
    }
    #[inline]
    fn force(&self, y: &State) -> f64 {
        ContactOde::force(self, y)
    }
    #[inline]
    fn force_rate(&self, y: &State) -> f64 {
        ContactOde::force_rate(self, y)
    }
    #[inline]
    fn compression_acceleration(&self, y: &State) -> f64 {
        ContactOde::compression_acceleration(self, y)
    }
    fn for_phase(&self, compressing: bool) -> Self {
        ContactOde { compressing: Some(compressing), ..*self }
    }
    fn units(&self, s: &crate::events::Scales) -> State {
        State::from([s.length, s.speed, s.length, s.speed, s.momentum, s.energy, s.energy])
    }
    fn budget(&self, scenario: &Scenario, _t: f64, y: &State) -> EnergyBudget {
        ContactOde::budget(self, scenario, y)
    }
}

/// State at first touch: δ = 0, nothing accumulated yet.
pub fn initial_state(scenario: &Scenario) -> State {
    State::from([0.0, scenario.foot_speed(), 0.0, scenario.ball_speed(), 0.0, 0.0, 0.0])
}

/// δ = x_f − x_b without the max of Eq. 5 (its sign marks separation).
#[inline]
pub fn compression(y: &State) -> f64 {
    y[FOOT_POSITION] - y[BALL_POSITION]
}

/// δ̇ = v_f − v_b (Eq. 6).
#[inline]
pub fn compression_rate(y: &State) -> f64 {
    y[FOOT_VELOCITY] - y[BALL_VELOCITY]
}

pub use crate::events::Extremes;

/// Assemble the summary from the final state; checks that nothing is NaN.
pub fn outcome<L: ContactLaw + Copy>(
    scenario: &Scenario,
    ode: &ContactOde<L>,
    y: &State,
    extremes: Extremes,
    stop: StopReason,
    evaluations: u64,
    method: SolverPath,
) -> Result<Outcome, kick_core::KickError> {
    let t = stop.time();
    let v_ball_out = y[BALL_VELOCITY];
    let v_foot_out = y[FOOT_VELOCITY];
    let outcome = Outcome {
        v_ball_out,
        v_foot_out,
        speed_ratio: Outcome::ratio(v_ball_out, scenario.foot_speed()),
        peak_force: extremes.peak_force,
        peak_force_time: extremes.peak_force_time,
        contact_time: t,
        max_compression: extremes.max_compression,
        max_compression_time: extremes.max_compression_time,
        impulse: y[IMPULSE],
        restitution: (v_ball_out - v_foot_out) / scenario.approach_speed(), // Eq. 36
        energy: ode.budget(scenario, y),
        stop,
        evaluations,
        method,
    };
    check_finite(&outcome)
}

/// No NaN or infinity leaves the library.
pub fn check_finite(outcome: &Outcome) -> Result<Outcome, kick_core::KickError> {
    let t = outcome.contact_time;
    let fields = [
        ("ball exit velocity", outcome.v_ball_out),
        ("foot exit velocity", outcome.v_foot_out),
        // An undefined ratio (v_f⁻ = 0) is absent, not a failure.
        ("speed ratio", outcome.speed_ratio.unwrap_or(0.0)),
        ("peak force", outcome.peak_force),
        ("contact time", outcome.contact_time),
        ("max compression", outcome.max_compression),
        ("impulse", outcome.impulse),
        ("restitution", outcome.restitution),
        ("kinetic energy", outcome.energy.kinetic_final),
        ("dissipated energy", outcome.energy.dissipated),
        ("drive work", outcome.energy.drive_work),
    ];
    for (quantity, value) in fields {
        kick_core::error::finite(quantity, value, t)?;
    }
    Ok(*outcome)
}
