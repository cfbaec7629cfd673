//! `accurate`: adaptive Dop853 (ode_solvers) with located events.
//!
//! The contact is integrated phase by phase. Each phase stops at the first
//! accepted step across which an event function changes sign; the event time
//! is then found by Brent's method on g(y(τ)), where y(τ) comes from
//! re-integrating that step from its start to τ with the same method. The
//! located state starts the next phase, so no step straddles a kink of the
//! force law (the damping switch at δ̇ = 0) or the separation.
//!
//! Events: maximum compression (δ̇: + → −), force peak (dF/dt: + → −),
//! separation (δ: + → −), re-compression (δ̇: − → +, only with a drive).
//! Peak force is the supremum over contact, including F(0⁺) = c V0.
//!
//! Accuracy: with the default tolerances every observable is within 1e-9
//! relative of the closed forms (tests hold it to that) for the paper's
//! parameter range; see the README for the measured region.

use crate::ode::{self, Branch, ContactOde, Extremes, State};
use kick_core::{
    roots, ContactLaw, History, KickError, Outcome, RecordingSolver, Scenario, Solver, StopReason,
};
use ode_solvers::dop853::Dop853;
use ode_solvers::{OutputType, System};

/// Adaptive Dop853 with event location.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accurate {
    pub relative_tolerance: f64,
    pub absolute_tolerance: f64,
    /// Bound on accepted steps in one phase.
    pub max_steps_per_phase: u32,
}

impl Default for Accurate {
    fn default() -> Self {
        Accurate {
            relative_tolerance: 1e-12,
            absolute_tolerance: 1e-15,
            max_steps_per_phase: 100_000,
        }
    }
}

/// Most phases (compression/restitution alternations under a drive) per run.
pub const MAX_PHASES: usize = 10_000;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Event {
    MaxCompression,
    ForcePeak,
    Separation,
    Recompression,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    Compression,
    Restitution,
}

impl Phase {
    fn events(self) -> &'static [Event] {
        match self {
            Phase::Compression => &[Event::MaxCompression, Event::ForcePeak],
            Phase::Restitution => &[Event::Separation, Event::Recompression, Event::ForcePeak],
        }
    }
}

impl Event {
    fn value<L: ContactLaw + Copy>(self, ode: &ContactOde<L>, y: &State) -> f64 {
        match self {
            Event::MaxCompression | Event::Recompression => ode::compression_rate(y),
            Event::ForcePeak => ode.force_rate(y),
            Event::Separation => ode::compression(y),
        }
    }
    /// True when the sign change from `before` to `after` is this event's direction.
    fn crossed(self, before: f64, after: f64) -> bool {
        match self {
            Event::Recompression => before < 0.0 && after >= 0.0,
            _ => before > 0.0 && after <= 0.0,
        }
    }
}

/// An event seen between two accepted steps.
#[derive(Debug, Clone, Copy)]
struct Bracket {
    event: Event,
    start_time: f64,
    start_state: State,
    end_time: f64,
}

/// The ODE as ode_solvers sees it, watching for events after each accepted step.
struct PhaseSystem<'a, L> {
    ode: ContactOde<L>,
    events: &'static [Event],
    previous: State,
    recorder: Option<&'a mut History>,
}

impl<L: ContactLaw + Copy> System<f64, State> for PhaseSystem<'_, L> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        *dy = self.ode.derivative(y);
    }
    fn solout(&mut self, t: f64, y: &State, _dy: &State) -> bool {
        let y0 = self.previous;
        for &event in self.events {
            if event.crossed(event.value(&self.ode, &y0), event.value(&self.ode, y)) {
                return true;
            }
        }
        if let Some(history) = self.recorder.as_deref_mut() {
            history.samples.push(self.ode.sample(t, y));
        }
        self.previous = *y;
        false
    }
}

/// Plain system for re-integrating one step.
struct Plain<L>(ContactOde<L>);

impl<L: ContactLaw + Copy> System<f64, State> for Plain<L> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        *dy = self.0.derivative(y);
    }
}

impl Accurate {
    pub fn new(relative_tolerance: f64, absolute_tolerance: f64) -> Result<Self, KickError> {
        for (name, value) in [("rtol", relative_tolerance), ("atol", absolute_tolerance)] {
            if !(value.is_finite() && value > 0.0 && value < 1.0) {
                return Err(KickError::InvalidParameter {
                    name,
                    value,
                    requirement: "in (0, 1)",
                });
            }
        }
        Ok(Accurate {
            relative_tolerance,
            absolute_tolerance,
            ..Accurate::default()
        })
    }

    fn integrator<S: System<f64, State>>(
        &self,
        system: S,
        t0: f64,
        t1: f64,
        y0: State,
        max_step: f64,
        first_step: f64,
    ) -> Dop853<f64, State, S> {
        Dop853::from_param(
            system,
            t0,
            t1,
            0.0,
            y0,
            self.relative_tolerance,
            self.absolute_tolerance,
            0.9,
            0.0,
            0.333,
            6.0,
            max_step,
            first_step,
            self.max_steps_per_phase,
            u32::MAX, // no stiffness test: the contact is not stiff
            OutputType::Sparse,
        )
    }

    /// y(t1) from y(t0) = y0, taking one step if the error estimate allows.
    fn advance<L: ContactLaw + Copy>(
        &self,
        ode: ContactOde<L>,
        t0: f64,
        y0: State,
        t1: f64,
        evaluations: &mut u64,
    ) -> Result<State, KickError> {
        if t1 <= t0 {
            return Ok(y0);
        }
        // Below Dop853's step-size floor; one RK4 step is exact to rounding here.
        if t1 - t0 <= 1e3 * f64::EPSILON * t0.abs() {
            *evaluations += 4;
            return Ok(ode.rk4_step(&y0, t1 - t0));
        }
        let mut stepper = self.integrator(Plain(ode), t0, t1, y0, t1 - t0, t1 - t0);
        let stats = stepper.integrate().map_err(|e| KickError::Integration {
            time: t0,
            reason: e.to_string(),
        })?;
        *evaluations += u64::from(stats.num_eval);
        stepper
            .y_out()
            .last()
            .copied()
            .ok_or(KickError::Integration { time: t0, reason: "empty step".into() })
    }

    /// Integrate from (t, y) until the first event of `phase` or `t_end`.
    #[allow(clippy::too_many_arguments)]
    fn phase<L: ContactLaw + Copy>(
        &self,
        ode: ContactOde<L>,
        phase: Phase,
        t: f64,
        y: State,
        t_end: f64,
        max_step: f64,
        recorder: Option<&mut History>,
        evaluations: &mut u64,
    ) -> Result<Option<(Event, f64, State)>, KickError> {
        let system = PhaseSystem {
            ode,
            events: phase.events(),
            previous: y,
            recorder,
        };
        let mut stepper = self.integrator(system, t, t_end, y, max_step, 0.0);
        let stats = stepper.integrate().map_err(|e| KickError::Integration {
            time: t,
            reason: e.to_string(),
        })?;
        *evaluations += u64::from(stats.num_eval);
        // The system stopped at the first step across an event: it lies
        // between the last two accepted points.
        let bracket = last_bracket(&ode, phase.events(), stepper.x_out(), stepper.y_out());
        let Some(bracket) = bracket else {
            return Ok(None);
        };
        let event = bracket.event;
        let g = |tau: f64, evaluations: &mut u64| -> Result<f64, KickError> {
            let state = self.advance(ode, bracket.start_time, bracket.start_state, tau, evaluations)?;
            Ok(event.value(&ode, &state))
        };
        let mut failure = None;
        let mut count = 0u64;
        let root = roots::brent(
            |tau| match g(tau, &mut count) {
                Ok(v) => v,
                Err(e) => {
                    failure = Some(e);
                    f64::NAN
                }
            },
            bracket.start_time,
            bracket.end_time,
            4.0 * f64::EPSILON * bracket.end_time.abs(),
            200,
        );
        *evaluations += count;
        if let Some(e) = failure {
            return Err(e);
        }
        let root = root.ok_or(KickError::Integration {
            time: bracket.start_time,
            reason: format!("could not locate {event:?}"),
        })?;
// Continue from the end of the final bracket that lies past the event,
        // so the next phase does not find the same crossing again.
        let before = event.value(&ode, &bracket.start_state);
        let mut time = root.x;
        let mut state = self.advance(ode, bracket.start_time, bracket.start_state, time, evaluations)?;
        if !event.crossed(before, event.value(&ode, &state)) && root.other != root.x {
            time = root.other;
            state = self.advance(ode, bracket.start_time, bracket.start_state, time, evaluations)?;
        }
        Ok(Some((event, time, state)))
    }

    fn run<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        mut history: Option<(&mut History, f64)>,
    ) -> Result<Outcome, KickError> {
        let ode = ContactOde::new(scenario, law, Branch::InContact);
        let horizon = scenario.contact_horizon();
        let mut t = 0.0;
        let mut y = ode::initial_state(scenario);
        let mut extremes = Extremes::new(law.onset_force(scenario.approach_speed()));
        let mut evaluations = 0u64;
        let mut phase = Phase::Compression;
        if let Some((h, _)) = history.as_mut() {
            h.samples.push(ode.sample(0.0, &y));
        }
        for _ in 0..MAX_PHASES {
            let (recorder, max_step) = match history.as_mut() {
                Some((h, interval)) => (Some(&mut **h), *interval),
                None => (None, horizon),
            };
            let hit = self.phase(ode, phase, t, y, horizon, max_step, recorder, &mut evaluations)?;
            let Some((event, t_event, y_event)) = hit else {
                return Err(KickError::NoSeparation {
                    time: horizon,
                    reason: format!(
                        "contact outlasted the horizon of {horizon:.6e} s = {} x the undriven elastic contact time",
                        kick_core::scenario::CONTACT_HORIZON_FACTOR
                    ),
                });
            };
            t = t_event;
            y = y_event;
            extremes.observe(t, ode.force(&y), ode::compression(&y));
            if let Some((h, _)) = history.as_mut() {
                h.samples.push(ode.sample(t, &y));
            }
            match event {
                Event::ForcePeak => {}
                Event::Recompression => phase = Phase::Compression,
                Event::MaxCompression => {
                    phase = Phase::Restitution;
                    check_release(scenario, &law, &y, t)?;
                }
                Event::Separation => {
                    return ode::outcome(
                        scenario,
                        &ode,
                        &y,
                        extremes,
                        StopReason::Separated { t },
                        evaluations,
                    );
                }
            }
        }
        Err(KickError::NoSeparation {
            time: t,
            reason: format!("more than {MAX_PHASES} compression/restitution phases"),
        })
    }
}

/// The event, if any, across the last accepted step.
fn last_bracket<L: ContactLaw + Copy>(
    ode: &ContactOde<L>,
    events: &[Event],
    times: &[f64],
    states: &[State],
) -> Option<Bracket> {
    let n = states.len();
    if n < 2 || times.len() != n {
        return None;
    }
    let (before, after) = (&states[n - 2], &states[n - 1]);
    events
        .iter()
        .find(|event| event.crossed(event.value(ode, before), event.value(ode, after)))
        .map(|&event| Bracket {
            event,
            start_time: times[n - 2],
            start_state: *before,
            end_time: times[n - 1],
        })
}

/// Under a constant drive and a law that is conservative while restituting,
/// the return from δ_max conserves ½ μ δ̇² + U(δ) − (μ/m_f) F_drive δ. The
/// ball reaches δ = 0 only if U(δ_max) ≥ (μ/m_f) F_drive δ_max; otherwise it
/// turns back before releasing, and later compressions only lose energy.
fn check_release<L: ContactLaw>(
    scenario: &Scenario,
    law: &L,
    y: &State,
    t: f64,
) -> Result<(), KickError> {
    let drive = scenario.drive_force();
    if drive <= 0.0 || !law.damps_compression_only() {
        return Ok(());
    }
    let max_compression = ode::compression(y);
    let drive_share = scenario.reduced_mass() / scenario.effective_foot_mass() * drive;
    let stored = law.potential(max_compression);
    if stored < drive_share * max_compression {
        return Err(KickError::NoSeparation {
            time: t,
            reason: format!(
                "at maximum compression the stored energy U(δ_max) = {stored:.6e} J is below the \
                 drive's share (μ/m_f) F_drive δ_max = {:.6e} J, so the ball turns back before release",
                drive_share * max_compression
            ),
        });
    }
    Ok(())
}

impl Accurate {
    /// Solve the scenario's masses and speeds with any contact law in place of
    /// the scenario's own (Eq. 20).
    pub fn solve_law<L: ContactLaw + Copy>(&self, scenario: &Scenario, law: L) -> Result<Outcome, KickError> {
        self.run(scenario, law, None)
    }

    /// As [`Accurate::solve_law`], recording samples at most `interval` apart.
    pub fn solve_law_recorded<L: ContactLaw + Copy>(
        &self,
        scenario: &Scenario,
        law: L,
        interval: f64,
    ) -> Result<(Outcome, History), KickError> {
        if !(interval.is_finite() && interval > 0.0) {
            return Err(KickError::InvalidParameter {
                name: "interval",
                value: interval,
                requirement: "finite and > 0",
            });
        }
        let mut history = History::default();
        let outcome = self.run(scenario, law, Some((&mut history, interval)))?;
        Ok((outcome, history))
    }
}

impl Solver for Accurate {
    fn name(&self) -> &'static str {
        "accurate"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        self.run(scenario, scenario.law(), None)
    }
}

impl RecordingSolver for Accurate {
    fn solve_recorded(
        &self,
        scenario: &Scenario,
        interval: f64,
    ) -> Result<(Outcome, History), KickError> {
        self.solve_law_recorded(scenario, scenario.law(), interval)
    }
}
