//! Solvers on the relative coordinate only (Eq. 18).
//!
//! `reduced` integrates (δ, δ̇, D) and recovers foot and ball from the
//! centre of mass, which moves uniformly (or uniformly accelerated by the
//! drive, Eq. 26):
//! V_cm(t) = V_cm⁻ + F_drive t / M, v_f = V_cm + (m_b/M) δ̇, v_b = V_cm − (m_f/M) δ̇,
//! and the drive work is F_drive x_f(t) with x_f = X_cm + (m_b/M) δ.
//! Three states instead of seven, and no cancellation in δ = x_f − x_b.
//!
//! `reduced-return` integrates only the compression of a run of the paper's
//! law and takes the undamped return from δ_max in closed form
//! ([`crate::closed::undamped_return`]).

use crate::closed::{undamped_return, CompressionEnd};
use crate::events::{ContactSystem, Engine, Method, Recorder, StopAt};
use crate::history::{self, Sampler};
use kick_core::{
    AnyLaw, ContactLaw, ContactPhase, KickError, LawKind, Outcome, RecordingSolver, Sample, Scenario, Solver, SolverPath, Spacing,
    StopReason, Streamed,
};
use std::ops::ControlFlow;

use crate::relative::{reconstruct, separated};
pub use crate::relative::{RelativeOde, RelativeState};

fn sample<L: ContactLaw>(scenario: &Scenario, law: &L, t: f64, y: &RelativeState, phase: ContactPhase) -> Sample {
    let r = reconstruct(scenario, t, y);
    Sample {
        time: t,
        foot_position: r.foot_position,
        foot_velocity: r.foot_velocity,
        ball_position: r.ball_position,
        ball_velocity: r.ball_velocity,
        compression: y[0].max(0.0),
        force: law.contact_force(y[0], y[1]),
        kinetic: 0.5 * scenario.effective_foot_mass() * r.foot_velocity.powi(2) + 0.5 * scenario.ball_mass() * r.ball_velocity.powi(2),
        elastic: law.potential(y[0]),
        dissipated: y[2],
        drive_work: r.drive_work,
        phase,
    }
}

/// Event-located integration of Eq. 18 (Dop853 by default).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reduced {
    pub method: Method,
}

impl Default for Reduced {
    fn default() -> Self {
        Reduced { method: Method::Dop853 { relative_tolerance: 1e-12, absolute_tolerance: 1e-12 } }
    }
}

impl Reduced {
    pub fn with_tolerances(relative_tolerance: f64, absolute_tolerance: f64) -> Result<Self, KickError> {
        let method = Method::Dop853 { relative_tolerance, absolute_tolerance };
        method.validate()?;
        Ok(Reduced { method })
    }

    pub fn solve_law<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        sampler: Option<&mut Sampler>,
    ) -> Result<Outcome, KickError> {
        let system = RelativeOde::new(scenario, law);
        let mut engine = Engine::new(self.method, system, scenario)?;
        let y0 = RelativeState::new(0.0, scenario.approach_speed(), 0.0);
        let end = match sampler {
            Some(sampler) => {
                let sample = |t: f64, y: &RelativeState, phase: ContactPhase| sample(scenario, &law, t, y, phase);
                let mut recorder = Recorder { sampler, sample: &sample };
                engine.run(scenario, &law, y0, StopAt::Separation, Some(&mut recorder))?
            }
            None => engine.run(scenario, &law, y0, StopAt::Separation, None)?,
        };
        let energy = ContactSystem::budget(&system, scenario, end.time, &end.state);
        let outcome = separated(scenario, end.time, &end.state, end.extremes(), energy, engine.evaluations, SolverPath::Reduced)?;
        if let Some(step) = self.method.fixed_step() {
            crate::stability::check_energy(scenario, &law, &outcome.energy, step, outcome.contact_time)?;
        }
        Ok(outcome)
    }
}

impl Solver for Reduced {
    fn name(&self) -> &'static str {
        "reduced"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        if let Some(boot) = scenario.boot() {
            return crate::boot::solve(self.method, SolverPath::Reduced, scenario, boot, None);
        }
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.solve_law(scenario, law, None),
            law => self.solve_law(scenario, law, None),
        }
    }
}

impl RecordingSolver for Reduced {
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        if let Some(boot) = scenario.boot() {
            return crate::boot::solve_streamed(self.method, SolverPath::Reduced, scenario, boot, spacing, sink);
        }
        let end = |o: &Outcome| o.contact_time;
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => history::stream(spacing, sink, end, |s| self.solve_law(scenario, law, s)),
            law => history::stream(spacing, sink, end, |s| self.solve_law(scenario, law, s)),
        }
    }
}

/// Compression by [`Reduced`], return in closed form: the paper's law only
/// (damping acts only while compressing), with or without a drive.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReducedReturn {
    pub reduced: Reduced,
}

impl ReducedReturn {
    pub fn applies(scenario: &Scenario) -> bool {
        scenario.law_kind() == LawKind::PowerLaw && scenario.boot().is_none()
    }
}

impl Solver for ReducedReturn {
    fn name(&self) -> &'static str {
        "reduced-return"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        if scenario.boot().is_some() {
            return Err(crate::boot::not_applicable("reduced-return"));
        }
        if !Self::applies(scenario) {
            return Err(KickError::NotApplicable {
                solver: "reduced-return",
                reason: "its return phase is in closed form only for the paper's law, which does not damp while restituting",
            });
        }
        let law = scenario.paper_law();
        let system = RelativeOde::new(scenario, law);
        let mut engine = Engine::new(self.reduced.method, system, scenario)?;
        let y0 = RelativeState::new(0.0, scenario.approach_speed(), 0.0);
        let end = engine.run(scenario, &law, y0, StopAt::MaxCompression, None)?;
        let mut outcome = undamped_return(
            scenario,
            CompressionEnd {
                max_compression: end.max_compression,
                max_compression_time: end.max_compression_time,
                dissipated: end.state[2],
                peak_force: end.peak_force,
                peak_force_time: end.peak_force_time,
            },
        )?;
        outcome.evaluations = engine.evaluations;
        outcome.method = SolverPath::ReducedReturn;
        outcome.stop = StopReason::Separated { t: outcome.contact_time };
        Ok(outcome)
    }
}
