//! The 1D contact with a boot in series ([`kick_core::Boot`]): the
//! compliant layer between the foot and the ball, its compression δ_b a
//! state beside Eq. 18's.
//!
//! Eq. 18 becomes μ δ̈ = (μ/m_f) F_drive − F with F the force both elements
//! carry ([`kick_core::boot`]: δ̇_b = (E + D δ̇ − k_b δ_b)/(c_b + D) in closed
//! form), and the ball's compression is δ_B = δ − δ_b. Two paths:
//!
//! - [`BootedOde`] on the event engine ([`crate::events`]), any law, any
//!   method of the engine: (δ, δ̇, δ_b, D) on Dop853 (`accurate`, `dop853`,
//!   `reduced`), Dopri5 or RK4. The engine's events are the ball's: the
//!   damping switch and maximum compression where δ̇_B = 0, separation where
//!   δ_B = 0, the force peak where dF/dt = 0 (dF/dt in closed form,
//!   [`kick_core::Boot::force_rate`]). A law that would pull is held at
//!   F ≥ 0 and the layer then relaxes on its own.
//! - [`series`]: the shell ball (drive ≥ 0) by Taylor steps, as
//!   [`crate::shell_series`], taken in σ with dt = (c_b + s A) dσ so that
//!   the force balance needs no division: the `series` and `auto` path.
//!
//! Outcome: `max_compression` is the ball's δ_B (its deformation, as
//! without a boot), the restitution and speeds those of the bodies; the
//! layer's elastic energy at separation is `elastic_final` and its dashpot's
//! loss is in `dissipated`.
//!
//! Accuracy: the series path against the engine at 1e-14 within 1e-10 on
//! every observable, the engine's own within 1e-9 of the same at 1e-14
//! (`tests/solvers/boot.rs`); the layer's limits: k_b → ∞ is the rigid foot,
//! energy closes to the solvers' tolerance.

use crate::events::{ContactSystem, Engine, Method, Recorder, Scales, StopAt};
use crate::history::{self, Sampler};
use crate::relative::{reconstruct, separated, RelativeState};
use kick_core::boot::Split;
use kick_core::{
    AnyLaw, Boot, ContactLaw, ContactPhase, EnergyBudget, KickError, Outcome, Sample, Scenario, SolverPath, Spacing, Streamed,
};
use nalgebra::SVector;
use std::ops::ControlFlow;

/// (δ, δ̇, δ_b, D): the approach, its rate, the layer's compression and the
/// energy both dashpots took.
pub type BootedState = SVector<f64, 4>;
pub const BOOT: usize = 2;
pub const DISSIPATED: usize = 3;

/// The ball's law as the engine's bookkeeping sees it under a boot: the
/// law's force and potential, the onset force of the split at touch, and no
/// conservative return (the layer's dashpot acts on the way back), so no
/// trapping proof or return horizon of the paper's law is drawn from it.
#[derive(Debug, Clone, Copy)]
pub struct Booted<L> {
    pub law: L,
    pub boot: Boot,
}

impl<L: ContactLaw> ContactLaw for Booted<L> {
    fn force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.law.force(compression, compression_rate)
    }
    fn potential(&self, compression: f64) -> f64 {
        self.law.potential(compression)
    }
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.law.contact_force(compression, compression_rate)
    }
    fn onset_force(&self, approach_speed: f64) -> f64 {
        self.boot.split(&self.law, 0.0, approach_speed, 0.0, true, false).force.max(0.0)
    }
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        self.law.force_gradient(compression, compression_rate)
    }
    fn damps_compression_only(&self) -> bool {
        false
    }
}

/// Eq. 18 with the layer in series, on one branch of the ball's law.
#[derive(Debug, Clone, Copy)]
pub struct BootedOde<L> {
    pub law: L,
    pub boot: Boot,
    pub reduced_mass: f64,
    /// (μ/m_f) F_drive.
    pub drive_share: f64,
    /// Set per phase by the engine: the ball law's side of δ̇_B = 0.
    pub compressing: Option<bool>,
}

impl<L: ContactLaw + Copy> BootedOde<L> {
    pub fn new(scenario: &Scenario, law: L, boot: Boot) -> Self {
        BootedOde {
            law,
            boot,
            reduced_mass: scenario.reduced_mass(),
            drive_share: scenario.reduced_mass() / scenario.effective_foot_mass() * scenario.drive_force(),
            compressing: None,
        }
    }

    /// δ_B = δ − δ_b.
    #[inline]
    pub fn ball_compression(y: &BootedState) -> f64 {
        y[0] - y[BOOT]
    }

    /// The split at y; a law that would pull is held at zero.
    #[inline]
    pub fn split(&self, y: &BootedState) -> Split {
        let compressing = self.compressing.unwrap_or(true);
        let split = self.boot.split(&self.law, Self::ball_compression(y), y[1], y[BOOT], compressing, false);
        if split.force < 0.0 {
            self.boot.split(&self.law, Self::ball_compression(y), y[1], y[BOOT], compressing, true)
        } else {
            split
        }
    }

    #[inline]
    fn acceleration(&self, force: f64) -> f64 {
        (self.drive_share - force) / self.reduced_mass
    }

    fn clamped(split: &Split) -> bool {
        split.force == 0.0 && split.unclamped_force < 0.0
    }

    /// Ball, layer and bodies at time t: a history row.
    pub fn sample(&self, scenario: &Scenario, t: f64, y: &BootedState, phase: ContactPhase) -> Sample {
        let r = reconstruct(scenario, t, &RelativeState::new(y[0], y[1], y[DISSIPATED]));
        let ball = Self::ball_compression(y);
        Sample {
            time: t,
            foot_position: r.foot_position,
            foot_velocity: r.foot_velocity,
            ball_position: r.ball_position,
            ball_velocity: r.ball_velocity,
            compression: ball.max(0.0),
            force: self.split(y).force,
            kinetic: 0.5 * scenario.effective_foot_mass() * r.foot_velocity.powi(2) + 0.5 * scenario.ball_mass() * r.ball_velocity.powi(2),
            elastic: self.law.potential(ball) + self.boot.potential(y[BOOT]),
            dissipated: y[DISSIPATED],
            drive_work: r.drive_work,
            phase,
        }
    }
}

impl<L: ContactLaw + Copy> ContactSystem<4> for BootedOde<L> {
    #[inline]
    fn derivative(&self, _t: f64, y: &BootedState) -> BootedState {
        let s = self.split(y);
        BootedState::new(y[1], self.acceleration(s.force), s.boot_rate, s.loss_power(&self.boot))
    }
    #[inline]
    fn compression(&self, y: &BootedState) -> f64 {
        Self::ball_compression(y)
    }
    #[inline]
    fn compression_rate(&self, y: &BootedState) -> f64 {
        self.split(y).ball_rate
    }
    #[inline]
    fn force(&self, y: &BootedState) -> f64 {
        self.split(y).force
    }
    #[inline]
    fn force_rate(&self, y: &BootedState) -> f64 {
        let s = self.split(y);
        let compressing = self.compressing.unwrap_or(true);
        self.boot.force_rate(&self.law, Self::ball_compression(y), &s, self.acceleration(s.force), compressing, Self::clamped(&s))
    }
    #[inline]
    fn compression_acceleration(&self, y: &BootedState) -> f64 {
        // δ̈_B = δ̈ − δ̈_b.
        let s = self.split(y);
        let acceleration = self.acceleration(s.force);
        let compressing = self.compressing.unwrap_or(true);
        let rate = self.boot.force_rate(&self.law, Self::ball_compression(y), &s, acceleration, compressing, Self::clamped(&s));
        acceleration - self.boot.boot_acceleration(&s, rate)
    }
    fn for_phase(&self, compressing: bool) -> Self {
        BootedOde { compressing: Some(compressing), ..*self }
    }
    fn units(&self, s: &Scales) -> BootedState {
        BootedState::new(s.length, s.speed, s.length, s.energy)
    }
    fn budget(&self, scenario: &Scenario, t: f64, y: &BootedState) -> EnergyBudget {
        let r = reconstruct(scenario, t, &RelativeState::new(y[0], y[1], y[DISSIPATED]));
        EnergyBudget {
            kinetic_initial: scenario.initial_kinetic_energy(),
            kinetic_final: 0.5 * scenario.effective_foot_mass() * r.foot_velocity.powi(2)
                + 0.5 * scenario.ball_mass() * r.ball_velocity.powi(2),
            elastic_final: self.law.potential(Self::ball_compression(y)) + self.boot.potential(y[BOOT]),
            dissipated: y[DISSIPATED],
            drive_work: r.drive_work,
        }
    }
}

/// The booted contact on the event engine with `method` (module docs),
/// recording into `sampler` when given; `path` names it in the outcome.
pub fn solve_engine<L: ContactLaw + Copy>(
    method: Method,
    path: SolverPath,
    scenario: &Scenario,
    law: L,
    boot: Boot,
    sampler: Option<&mut Sampler>,
) -> Result<Outcome, KickError> {
    let system = BootedOde::new(scenario, law, boot);
    let booted = Booted { law, boot };
    let mut engine = Engine::new(method, system, scenario)?;
    let y0 = BootedState::new(0.0, scenario.approach_speed(), 0.0, 0.0);
    let end = match sampler {
        Some(sampler) => {
            let sample = |t: f64, y: &BootedState, phase: ContactPhase| system.sample(scenario, t, y, phase);
            let mut recorder = Recorder { sampler, sample: &sample };
            engine.run(scenario, &booted, y0, StopAt::Separation, Some(&mut recorder))?
        }
        None => engine.run(scenario, &booted, y0, StopAt::Separation, None)?,
    };
    let relative = RelativeState::new(end.state[0], end.state[1], end.state[DISSIPATED]);
    let energy = ContactSystem::budget(&system, scenario, end.time, &end.state);
    let outcome = separated(scenario, end.time, &relative, end.extremes(), energy, engine.evaluations, path)?;
    if let Some(step) = method.fixed_step() {
        crate::stability::check_energy(scenario, &booted, &outcome.energy, step, outcome.contact_time)?;
    }
    Ok(outcome)
}

/// [`solve_engine`] with the scenario's own law.
pub fn solve(
    method: Method,
    path: SolverPath,
    scenario: &Scenario,
    boot: Boot,
    sampler: Option<&mut Sampler>,
) -> Result<Outcome, KickError> {
    match scenario.contact_law() {
        AnyLaw::PowerLaw(law) => solve_engine(method, path, scenario, law, boot, sampler),
        law => solve_engine(method, path, scenario, law, boot, sampler),
    }
}

/// [`solve`] streaming a history (see [`kick_core::RecordingSolver`]).
pub fn solve_streamed(
    method: Method,
    path: SolverPath,
    scenario: &Scenario,
    boot: Boot,
    spacing: Spacing,
    sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
) -> Result<Streamed, KickError> {
    history::stream(spacing, sink, |o| o.contact_time, |s| solve(method, path, scenario, boot, s))
}

/// Why a solver refuses a scenario with a boot.
pub fn not_applicable(solver: &'static str) -> KickError {
    KickError::NotApplicable {
        solver,
        reason: "a boot in series (`boot_stiffness`, or `leg`) needs its compression as a state: use accurate, reduced, dop853, \
                 dopri5, rk4-events, series (the shell ball) or auto",
    }
}

pub mod identify;
pub mod series;
