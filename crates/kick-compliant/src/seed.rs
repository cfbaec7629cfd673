//! `seed-rk4`: the paper's own method (Section 12), reproduced as printed.
//!
//! Classical RK4 on Eq. 47's state at a fixed step, Eq. 20 taken literally
//! (no force at δ ≤ 0), stop at the first step after compression where
//! δ ≤ 0 and v_b ≥ v_f (Eq. 48); peak force and maximum compression are the
//! largest values seen at step points. Time is accumulated as `t += Δt` and
//! the contact time is the last step point still in contact (the step before
//! the one where Eq. 48 holds): Table 2's printed contact times are all one
//! step below the stopping step, and its two half-way cases (5.105 ms and
//! 5.055 ms) round down only with the accumulated time.
//!
//! Accuracy: RK4 is fourth order in smooth stretches, but the stop and the
//! extremes are quantised to the step: contact time is late by up to one
//! step, and the exit velocities carry the error of the last partial step
//! (relative error ~1e-4 at 5 µs on the baseline). The peak force of a
//! damped run misses the jump F(0⁺) = c V0 at the first instant.
//!
//! A step too large for the contact is refused ([`crate::stability`]):
//! before integrating if RK4 is unstable on the linearised law, after it if
//! the energy budget does not close to [`crate::stability::ENERGY_RESIDUAL_BOUND`]
//! (also when the run ends at its horizon or in a non-finite state).
//!
//! Histories: grid samples between step points are one RK4 step from the
//! step point before them, phased by the sign of δ̇ there; the separation
//! row is the state where Eq. 48 held (t_end one step after the contact
//! time), so the last grid samples may lie just past the true separation
//! (δ < 0, no force), as the method's own step points do.

use crate::history::{self, Sampler};
use crate::ode::{self, Branch, ContactOde, Extremes, State};
use crate::stability;
use kick_core::{
    AnyLaw, ContactPhase, KickError, Outcome, RecordingSolver, Sample, Scenario, Solver, SolverPath, Spacing, StopReason, Streamed,
};
use std::ops::ControlFlow;

/// The paper's fixed-step RK4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeedRk4 {
    /// Δt in s (Table 1: 5 µs).
    pub step: f64,
}

impl Default for SeedRk4 {
    fn default() -> Self {
        SeedRk4 { step: 5e-6 }
    }
}

impl SeedRk4 {
    pub fn new(step: f64) -> Result<Self, KickError> {
        if step.is_finite() && step > 0.0 {
            Ok(SeedRk4 { step })
        } else {
            Err(KickError::InvalidParameter { name: "dt", value: step, requirement: "finite and > 0" })
        }
    }

    fn run<L: kick_core::ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        mut sampler: Option<&mut Sampler>,
    ) -> Result<Outcome, KickError> {
        let ode = ContactOde::new(scenario, law, Branch::Literal);
        stability::check_rk4_step(scenario, &law, self.step)?;
        let horizon = scenario.contact_horizon();
        let max_steps = crate::events::fixed_steps(horizon, self.step)?;
        let h = self.step;
        let mut y = ode::initial_state(scenario);
        let mut extremes = Extremes::new(ode.force(&y));
        let mut compressed = false;
        // Samples between step points: one RK4 step from the point before.
        let sample = |t: f64, y: &State| {
            let phase = if ode::compression_rate(y) > 0.0 { ContactPhase::Compressing } else { ContactPhase::Restoring };
            ode.sample(t, y, phase)
        };
        let mut t = 0.0;
        for step in 1..=max_steps {
            let before = y;
            y = ode.rk4_step(&y, h);
            let last_in_contact = t;
            t += h;
            let delta = ode::compression(&y);
            let force = ode.force(&y);
            if !(force.is_finite() && delta.is_finite()) {
                // A blow-up: the step, if the budget before it shows it.
                stability::check_energy(scenario, &law, &ode.budget(scenario, &before), h, last_in_contact)?;
                return Err(KickError::NonFinite { quantity: "state", time: t });
            }
            extremes.observe(t, force, delta);
            compressed |= delta > 0.0;
            // Eq. 48
            let stop = compressed && delta <= 0.0 && y[ode::BALL_VELOCITY] >= y[ode::FOOT_VELOCITY];
            if let Some(sampler) = sampler.as_deref_mut() {
                sampler.fill(t, !stop, |tk, evaluations| {
                    *evaluations += 4;
                    Ok(sample(tk, &ode.rk4_step(&before, tk - last_in_contact)))
                })?;
                if stop {
                    sampler.finish(ode.sample(t, &y, ContactPhase::Separation));
                }
            }
            if stop {
                let outcome = ode::outcome(
                    scenario,
                    &ode,
                    &y,
                    extremes,
                    StopReason::StepCondition { t: last_in_contact },
                    4 * step,
                    SolverPath::SeedRk4,
                )?;
                stability::check_energy(scenario, &law, &outcome.energy, h, t)?;
                return Ok(outcome);
            }
        }
        // Not a proof of trapping; but first, whether the step is to blame.
        stability::check_energy(scenario, &law, &ode.budget(scenario, &y), h, t)?;
        Err(KickError::NoSeparation {
            time: t,
            reason: format!(
                "contact outlasted the horizon of {} s = {} x the undriven elastic contact time",
                kick_core::short(horizon),
                kick_core::scenario::CONTACT_HORIZON_FACTOR
            ),
        })
    }
}

impl Solver for SeedRk4 {
    fn name(&self) -> &'static str {
        "seed-rk4"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        if scenario.boot().is_some() {
            return Err(crate::boot::not_applicable("seed-rk4"));
        }
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => self.run(scenario, law, None),
            law => self.run(scenario, law, None),
        }
    }
}

impl RecordingSolver for SeedRk4 {
    fn solve_streamed(
        &self,
        scenario: &Scenario,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    ) -> Result<Streamed, KickError> {
        // The history ends where Eq. 48 held, one step after the contact time.
        if scenario.boot().is_some() {
            return Err(crate::boot::not_applicable("seed-rk4"));
        }
        let end = |o: &Outcome| o.contact_time + self.step;
        match scenario.contact_law() {
            AnyLaw::PowerLaw(law) => history::stream(spacing, sink, end, |s| self.run(scenario, law, s)),
            law => history::stream(spacing, sink, end, |s| self.run(scenario, law, s)),
        }
    }
}
