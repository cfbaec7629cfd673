//! `full-state-3d`: both rigid bodies in the world frame, the tangential
//! spring and the running integrals (40 states) on adaptive Dop853
//! (ode_solvers) with located events, parry3d giving the geometry at every
//! evaluation. The accurate path before [`crate::accurate`]; kept as its
//! independent reference (another state, frame, geometry code, integrator
//! and event machinery for the same model), at a tightened tolerance in the
//! tests.
//!
//! Same scheme as the 1D `kick_compliant::Accurate`: integrate phase by phase;
//! a phase stops at the first accepted step across which an event function
//! changes sign, Brent's method then finds the event time on g(y(τ)), y(τ)
//! coming from re-integrating that step. Every kink of the right-hand side is
//! an event, so no step straddles one:
//! - separation: δ from + to − (contact onset is t = 0 by construction:
//!   free flight before touch is exact in a force-free world);
//! - δ̇ changes sign (the damping switch of Eq. 20; + → − is max compression);
//! - grip ↔ slip of the tangential element ([`crate::tangential`]: in grip
//!   μ F_n − k_t |ξ|, in slip the slider's speed changes sign); also where
//!   the margin crosses zero and back within one step (a short grip or
//!   slip): a step across which the margin turns back from zero has its
//!   turn located by Brent's method on the margin's rate, and a margin
//!   past zero there ends the phase at the first crossing;
//! - the clamp at F = 0 of a law that would pull (Kelvin–Voigt).
//!
//! Peaks (normal force, |tangential force|): every event point is a sample
//! of both the phase it ends and the phase it starts (both forces are
//! continuous there, only their rates jump), and inside a phase, where both
//! are smooth, every maximum is a root of dQ/dt: a step across which dQ/dt
//! falls through zero is kept, and the root is located by Brent's method on
//! re-integrated states after the phase. dQ/dt is a second-order difference
//! of Q along the flow, one-sided at the ends of a phase so it never reaches
//! across a switch. Locating the root of dQ/dt, not the maximum of Q, gives
//! the peak's time to the solver's tolerance, not to √ε.
//! Measured (`tests/peaks.rs`, against fixed-step RK4 sampled at every
//! step): peak forces within 1e-13 and their times within 3e-10 relative on
//! kicks whose largest force comes just after a grip/slip switch.
//!
//! Allocation: the right-hand side allocates nothing; Dop853's sparse output
//! keeps each accepted step in a `Vec` (amortized growth, as in
//! kick-compliant), about 100–300 steps per contact.
//!
//! Accuracy: with the default tolerances (rtol 1e-12, atol 1e-15) a central
//! frictionless kick matches the 1D accurate solver to below 1e-9 relative in
//! exit speeds, contact time, peak force and maximum compression, and the
//! energy partition closes to below 1e-9 of the input energy (tests hold it
//! to both). Trustworthy while the contact stays on the instep's face or
//! rounded border (parry's projection is exact there) and the foot turns by
//! a small angle during contact.

use crate::dynamics::{self, Dynamics, State};
use crate::error::Kick3dError;
use crate::model::Kick3d;
use crate::outcome::{self, EndState, EnergySample, Outcome3d, Peak, Peaks};
use kick_core::{roots, ContactLaw, KickError};
use ode_solvers::dop853::Dop853;
use ode_solvers::{OutputType, System};

/// Adaptive Dop853 with event location for the 3D contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FullState3d {
    pub relative_tolerance: f64,
    pub absolute_tolerance: f64,
    /// Bound on accepted steps in one phase.
    pub max_steps_per_phase: u32,
}

impl Default for FullState3d {
    fn default() -> Self {
        FullState3d { relative_tolerance: 1e-12, absolute_tolerance: 1e-15, max_steps_per_phase: 100_000 }
    }
}

/// Most phases (δ̇ and grip/slip switches) per run.
pub const MAX_PHASES: usize = 10_000;
/// Step of the differences that give dQ/dt, in units of the normal
/// scenario's time δ*/V_n: truncation (∝ step²) and rounding (∝ 1/step) of
/// the rate both stay near 1e-11 of its scale.
const DIFFERENCE_STEP: f64 = 2e-5;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Event {
    Separation,
    CompressionRate,
    GripSlip,
    /// The force of a law that would pull reaches zero (its clamp).
    Clamp,
}

/// How far past touch the first phase's grip/slip switch is looked for, in
/// units of ε L/V_n (L the bodies' distance from the origin, V_n the
/// approach speed): parry's overlap, and with it the normal force and the
/// grip margin, is resolved only to the positions' rounding, ~ε L, and the
/// margin starts at zero where the law's force does (the shell ball). Its
/// sign before this time is the rounding's: row 1127 of the
/// `--leg` sweep ended its grip at 6.5e-17 s, where the accurate path
/// (whose overlap is exactly zero at touch) grips for 0.58 µs as the
/// law's slope at touch says (`Dynamics::at_touch`). A switch found in that
/// stretch is put at its end: at most ~1e-12 s. The same share of L bounds
/// the overlap taken as zero where a separation crossed at a step's end and
/// its re-integration stops short of it (`FullState3d::locate`).
const ONSET_RESOLUTION: f64 = 1e5;

const EVENTS: [Event; 4] = [Event::Separation, Event::CompressionRate, Event::GripSlip, Event::Clamp];

impl Event {
    fn value(self, dynamics: &Dynamics, y: &State) -> f64 {
        let c = dynamics.contact(y);
        match self {
            Event::Separation => c.compression,
            Event::CompressionRate => c.compression_rate,
            Event::GripSlip => c.grip_margin,
            Event::Clamp => dynamics.law.unclamped_force(c.compression, c.compression_rate).1,
        }
    }
    /// A sign change away from a non-zero value: a phase that starts exactly
    /// on a switch (value 0) must not find it again at its first step.
    fn crossed(self, before: f64, after: f64) -> bool {
        match self {
            Event::Separation => before > 0.0 && after <= 0.0,
            Event::CompressionRate | Event::GripSlip => (before > 0.0 && after <= 0.0) || (before < 0.0 && after >= 0.0),
            // Strict: every law's force is zero beyond separation.
            Event::Clamp => (before > 0.0 && after < 0.0) || (before < 0.0 && after > 0.0),
        }
    }
}

fn event_values(dynamics: &Dynamics, y: &State) -> [f64; 4] {
    let c = dynamics.contact(y);
    [c.compression, c.compression_rate, c.grip_margin, dynamics.law.unclamped_force(c.compression, c.compression_rate).1]
}

/// The quantities whose supremum over the contact is reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Watched {
    NormalForce,
    TangentialForce,
}

const WATCHED: [Watched; 2] = [Watched::NormalForce, Watched::TangentialForce];

impl Watched {
    fn value(self, dynamics: &Dynamics, y: &State) -> f64 {
        let c = dynamics.contact(y);
        match self {
            Watched::NormalForce => c.normal_force,
            Watched::TangentialForce => c.tangential_force.length(),
        }
    }
}

/// Where a rate is taken within a phase: at its start and end only the
/// phase's own side may be sampled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    Start,
    Inside,
    End,
}

/// dQ/dt at y along ẏ = `dy`: second-order differences of s ↦ Q(y + s ẏ)
/// over steps of `dt` (forward at a phase's start, backward at its end).
fn rate(dynamics: &Dynamics, watched: Watched, y: &State, dy: &State, dt: f64, side: Side) -> f64 {
    let q = |s: f64| watched.value(dynamics, &(y + dy * s));
    match side {
        Side::Inside => (q(dt) - q(-dt)) / (2.0 * dt),
        Side::Start => (-3.0 * q(0.0) + 4.0 * q(dt) - q(2.0 * dt)) / (2.0 * dt),
        Side::End => (3.0 * q(0.0) - 4.0 * q(-dt) + q(-2.0 * dt)) / (2.0 * dt),
    }
}

fn rates(dynamics: &Dynamics, y: &State, dy: &State, dt: f64, side: Side) -> [f64; 2] {
    WATCHED.map(|w| rate(dynamics, w, y, dy, dt, side))
}

/// An accepted step (t0, y0) → t1 of one phase across which dQ/dt fell through zero.
#[derive(Debug, Clone, Copy)]
struct Bracket {
    watched: usize,
    t0: f64,
    y0: State,
    t1: f64,
}

/// d(grip margin)/dt at y along ẏ = `dy`, a central difference over ±`dt`
/// on the phase's own branch (the margin is smooth through the phase's ends).
fn margin_rate(dynamics: &Dynamics, y: &State, dy: &State, dt: f64) -> f64 {
    (dynamics.contact(&(y + dy * dt)).grip_margin - dynamics.contact(&(y - dy * dt)).grip_margin) / (2.0 * dt)
}

/// The last accepted point, the samples and the brackets of one phase.
struct Watch {
    /// (t, y, event values, dQ/dt, d(grip margin)/dt)
    previous: (f64, State, [f64; 4], [f64; 2], f64),
    /// The events whose functions changed sign in the step (t0, y0) → t1.
    crossing: Option<([bool; 4], f64, State, f64)>,
    peaks: [Peak; 2],
    brackets: Vec<Bracket>,
    difference_step: f64,
    /// (overlap, t) where the ball and the boot's layer together overlap
    /// the foot by more than R plus the border: the ball's centre inside the
    /// box's core, where parry's contact is a penetration along the nearest
    /// face, no longer the distance from outside this path's normal needs.
    beyond: Option<(f64, f64)>,
    /// A failure while re-integrating a step to look for a dip of the margin.
    failure: Option<KickError>,
    /// The phase's start when it starts on the grip/slip switch itself, its
    /// margin at zero with zero slope (`tangential::GRIP_ENTRY`): its first
    /// step's turn is that start, not a dip.
    on_switch: Option<f64>,
    evaluations: u64,
}

struct PhaseSystem<'a> {
    solver: FullState3d,
    dynamics: Dynamics,
    watch: &'a mut Watch,
    recorder: Option<&'a mut Vec<EnergySample>>,
}

impl PhaseSystem<'_> {
    /// Where the grip margin, `margin0` at (t0, y0) and of the same sign at
    /// t1, turned back from zero inside the step (its rate moved from towards
    /// zero, `rate0`, to away, `rate1`) and crossed it at the turn: the turn's
    /// time, which brackets the crossing with t0.
    fn dip(&mut self, (t0, y0, margin0, rate0): (f64, &State, f64, f64), t1: f64, rate1: f64) -> Option<f64> {
        let sign = margin0.signum();
        if margin0 == 0.0 || !(sign * rate0 < 0.0 && sign * rate1 >= 0.0) || self.watch.on_switch == Some(t0) {
            return None;
        }
        let (solver, dynamics, dt) = (self.solver, self.dynamics, self.watch.difference_step);
        let mut count = 0u64;
        let mut failure = None;
        let mut state_at = |tau: f64, count: &mut u64| match solver.advance(dynamics, t0, *y0, tau, count) {
            Ok(state) => Some(state),
            Err(e) => {
                failure.get_or_insert(e);
                None
            }
        };
        let turn = roots::brent(
            |tau| {
                let Some(state) = state_at(tau, &mut count) else { return f64::NAN };
                // ẏ and the margin on both sides of the difference.
                count += 3;
                margin_rate(&dynamics, &state, &dynamics.derivative(&state), dt)
            },
            t0,
            t1,
            4.0 * f64::EPSILON * t1.abs(),
            200,
        );
        let crossed = turn.and_then(|root| {
            let state = state_at(root.x, &mut count)?;
            (sign * dynamics.contact(&state).grip_margin <= 0.0).then_some(root.x)
        });
        self.watch.evaluations += count;
        if let Some(e) = failure {
            self.watch.failure = Some(e);
            return Some(t1);
        }
        crossed
    }
}

impl System<f64, State> for PhaseSystem<'_> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        *dy = self.dynamics.derivative(y);
    }
    fn solout(&mut self, t: f64, y: &State, dy: &State) -> bool {
        let (t0, y0, g0, r0, m0) = self.watch.previous;
        if t <= t0 {
            return false;
        }
        let g = event_values(&self.dynamics, y);
        if self.dynamics.boot.is_some() {
            // g[0] is the ball's compression: the overlap less the layer's.
            let overlap = g[0] + y[dynamics::BOOT];
            if overlap > self.dynamics.ball_radius + self.dynamics.border {
                self.watch.beyond = Some((overlap, t));
                return true;
            }
        }
        let crossed: [bool; 4] = std::array::from_fn(|i| EVENTS[i].crossed(g0[i], g[i]));
        if crossed.contains(&true) {
            // The phase ends inside this step, at the earliest of the events
            // that crossed (located after the phase; the grip/slip phase is
            // state, so a switch passed over would not be seen again): its
            // last stretch is examined once the event is located.
            self.watch.crossing = Some((crossed, t0, y0, t));
            return true;
        }
        let m = margin_rate(&self.dynamics, y, dy, self.watch.difference_step);
        if let Some(turn) = self.dip((t0, &y0, g0[2], m0), t, m) {
            // A short grip or slip inside the step: the phase ends at its start.
            let grip_slip = std::array::from_fn(|i| EVENTS[i] == Event::GripSlip);
            self.watch.crossing = Some((grip_slip, t0, y0, turn));
            return true;
        }
        let r = rates(&self.dynamics, y, dy, self.watch.difference_step, Side::Inside);
        for k in 0..2 {
            if r0[k] > 0.0 && r[k] <= 0.0 {
                self.watch.brackets.push(Bracket { watched: k, t0, y0, t1: t });
            }
            self.watch.peaks[k].observe(WATCHED[k].value(&self.dynamics, y), t);
        }
        if let Some(r) = self.recorder.as_deref_mut() {
            r.push(sample(&self.dynamics, t, y));
        }
        self.watch.previous = (t, *y, g, r, m);
        false
    }
}

fn sample(dynamics: &Dynamics, t: f64, y: &State) -> EnergySample {
    (t, dynamics.mechanical_energy(y, t), y[dynamics::DAMPING_LOSS], y[dynamics::FRICTION_LOSS])
}

struct Plain(Dynamics);

impl System<f64, State> for Plain {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        *dy = self.0.derivative(y);
    }
}

impl FullState3d {
    pub fn new(relative_tolerance: f64, absolute_tolerance: f64) -> Result<Self, Kick3dError> {
        for (name, value) in [("rtol", relative_tolerance), ("atol", absolute_tolerance)] {
            if !(value.is_finite() && value > 0.0 && value < 1.0) {
                return Err(Kick3dError::InvalidParameter { name, value, requirement: "in (0, 1)" });
            }
        }
        Ok(FullState3d { relative_tolerance, absolute_tolerance, ..FullState3d::default() })
    }

    #[allow(clippy::too_many_arguments)]
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
            u32::MAX, // the contact is not stiff: no stiffness test
            OutputType::Sparse,
        )
    }

    /// y(t1) from y(t0) = y0.
    fn advance(&self, dynamics: Dynamics, t0: f64, y0: State, t1: f64, evaluations: &mut u64) -> Result<State, KickError> {
        if t1 <= t0 {
            return Ok(y0);
        }
        // Below Dop853's step-size floor one RK4 step is exact to rounding.
        if t1 - t0 <= 1e3 * f64::EPSILON * t0.abs() {
            *evaluations += 4;
            return Ok(dynamics.rk4_step(&y0, t1 - t0));
        }
        let mut stepper = self.integrator(Plain(dynamics), t0, t1, y0, t1 - t0, t1 - t0);
        let stats = stepper.integrate().map_err(|e| KickError::Integration { time: t0, reason: e.to_string() })?;
        *evaluations += u64::from(stats.num_eval);
        stepper.y_out().last().copied().ok_or(KickError::Integration { time: t0, reason: "empty step".into() })
    }

    /// Integrate from (t, y) to the first event or `t_end`, folding the
    /// phase's samples and located maxima into `peaks`.
    #[allow(clippy::too_many_arguments)]
    fn phase(
        &self,
        dynamics: Dynamics,
        t: f64,
        y: State,
        t_end: f64,
        peaks: &mut [Peak; 2],
        difference_step: f64,
        recorder: Option<&mut Vec<EnergySample>>,
        evaluations: &mut u64,
        on_switch: bool,
    ) -> Result<Option<(Event, f64, State)>, KickError> {
        let dy = dynamics.derivative(&y);
        *evaluations += 1;
        let mut watch = Watch {
            previous: (
                t,
                y,
                event_values(&dynamics, &y),
                rates(&dynamics, &y, &dy, difference_step, Side::Start),
                margin_rate(&dynamics, &y, &dy, difference_step),
            ),
            crossing: None,
            peaks: *peaks,
            brackets: Vec::new(),
            difference_step,
            beyond: None,
            failure: None,
            evaluations: 0,
            on_switch: on_switch.then_some(t),
        };
        let system = PhaseSystem { solver: *self, dynamics, watch: &mut watch, recorder };
        let mut stepper = self.integrator(system, t, t_end, y, t_end - t, 0.0);
        let stats = stepper.integrate().map_err(|e| KickError::Integration { time: t, reason: e.to_string() })?;
        *evaluations += u64::from(stats.num_eval);
        drop(stepper);
        *evaluations += watch.evaluations;
        if let Some(e) = watch.failure.take() {
            return Err(e);
        }
        if let Some((compression, time)) = watch.beyond {
            // Rows 201, 269 and 342 of `sweep3d`'s box with the identified
            // boot (foot 30-34 m/s into a ball at -9 m/s): 9 cm of layer
            // behind 5 cm of ball, the centre near the box's far side, the
            // normal turned (3.9 m/s out where the accurate path and the 1D
            // booted kick give 57 and 58 m/s).
            let (limit_name, why) = (
                "the ball radius R plus the border",
                "the ball and the boot's layer together overlap the foot so far that the ball's centre is inside the foot's box, where this path's geometry reads the nearest face",
            );
            return Err(KickError::BeyondGeometry { compression, time, limit: dynamics.ball_radius + dynamics.border, limit_name, why });
        }
        let phase_start = t;
        let side = |tau: f64, end: f64| {
            if tau == phase_start {
                Side::Start
            } else if tau == end {
                Side::End
            } else {
                Side::Inside
            }
        };
        let mut hit = None;
        if let Some((crossed, t0, y0, t1)) = watch.crossing {
            let mut first: Option<(Event, f64, State)> = None;
            for (event, _) in EVENTS.iter().zip(crossed).filter(|(_, c)| *c) {
                let (time, state) = self.locate(dynamics, *event, t0, y0, t1, evaluations)?;
                if first.is_none_or(|(_, t, _)| time < t) {
                    first = Some((*event, time, state));
                }
            }
            let Some((event, time, state)) = first else { unreachable!("a crossing names an event") };
            // The last stretch of the phase, from the last accepted point to the event.
            let dy = dynamics.derivative(&state);
            *evaluations += 1;
            let r = rates(&dynamics, &state, &dy, difference_step, Side::End);
            let (tp, yp, _, rp, _) = watch.previous;
            for k in 0..2 {
                if rp[k] > 0.0 && r[k] <= 0.0 {
                    watch.brackets.push(Bracket { watched: k, t0: tp, y0: yp, t1: time });
                }
            }
            hit = Some((event, time, state));
        }
        let end = hit.map_or(f64::NAN, |(_, time, _)| time);
        for b in &watch.brackets {
            let watched = WATCHED[b.watched];
            let mut failure = None;
            let mut count = 0u64;
            let mut rate_at = |tau: f64| -> f64 {
                let state = match self.advance(dynamics, b.t0, b.y0, tau, &mut count) {
                    Ok(state) => state,
                    Err(e) => {
                        failure = Some(e);
                        return f64::NAN;
                    }
                };
                count += 1;
                rate(&dynamics, watched, &state, &dynamics.derivative(&state), difference_step, side(tau, end))
            };
            let root = roots::brent(&mut rate_at, b.t0, b.t1, 4.0 * f64::EPSILON * b.t1.abs(), 200);
            *evaluations += count;
            if let Some(e) = failure {
                return Err(e);
            }
            // No sign change once the ends are taken one-sided: the maximum is an end, already sampled.
            if let Some(root) = root {
                let state = self.advance(dynamics, b.t0, b.y0, root.x, evaluations)?;
                watch.peaks[b.watched].observe(watched.value(&dynamics, &state), root.x);
            }
        }
        *peaks = watch.peaks;
        Ok(hit)
    }

    /// The event's time in the step (t0, y0) → t1, and the state there on
    /// the far side of the crossing (so the next phase does not see it again).
    fn locate(
        &self,
        dynamics: Dynamics,
        event: Event,
        t0: f64,
        y0: State,
        t1: f64,
        evaluations: &mut u64,
    ) -> Result<(f64, State), KickError> {
        // The first phase's grip/slip switch is looked for from where the
        // geometry resolves its sign (ONSET_RESOLUTION).
        let (t0, y0) = if event == Event::GripSlip && t0 == 0.0 {
            let c = dynamics.contact(&y0);
            let speed = (c.compression_rate + c.boot_rate).abs();
            let resolved = (ONSET_RESOLUTION * f64::EPSILON * dynamics::position_scale(&y0) / speed).min(t1);
            let y = self.advance(dynamics, t0, y0, resolved, evaluations)?;
            let value = event.value(&dynamics, &y);
            let on_side = if dynamics.slipping { value < 0.0 } else { value > 0.0 };
            if resolved < t1 && on_side {
                (resolved, y)
            } else {
                return Ok((resolved, y));
            }
        } else {
            (t0, y0)
        };
        let before = event.value(&dynamics, &y0);
        let mut failure = None;
        let mut count = 0u64;
        let root = roots::brent(
            |tau| match self.advance(dynamics, t0, y0, tau, &mut count) {
                Ok(state) => event.value(&dynamics, &state),
                Err(e) => {
                    failure = Some(e);
                    f64::NAN
                }
            },
            t0,
            t1,
            4.0 * f64::EPSILON * t1.abs(),
            200,
        );
        *evaluations += count;
        if let Some(e) = failure {
            return Err(e);
        }
        let Some(root) = root else {
            // The stepper's state crossed at t1 but its re-integration stops
            // short by the overlap's rounding (Flores box kick 925: δ =
            // 1.4e-17 m at the end of a 2e-14 s step): separation is at t1.
            let state = self.advance(dynamics, t0, y0, t1, evaluations)?;
            let resolved = ONSET_RESOLUTION * f64::EPSILON * dynamics::position_scale(&state);
            if event == Event::Separation && event.value(&dynamics, &state).abs() <= resolved {
                return Ok((t1, state));
            }
            return Err(KickError::Integration { time: t0, reason: format!("could not locate {event:?}") });
        };
        let mut time = root.x;
        let mut state = self.advance(dynamics, t0, y0, time, evaluations)?;
        if !event.crossed(before, event.value(&dynamics, &state)) && root.other != root.x {
            time = root.other;
            state = self.advance(dynamics, t0, y0, time, evaluations)?;
        }
        Ok((time, state))
    }

    fn run(&self, kick: &Kick3d, mut recorder: Option<&mut Vec<EnergySample>>) -> Result<(Outcome3d, State), Kick3dError> {
        if kick.rigid_grip() {
            return Err(Kick3dError::UnsupportedScene { path: "full-state", reason: crate::model::RIGID_GRIP_PATHS });
        }
        kick.require_point_contact_box("full-state")?;
        if kick.ground {
            return Err(Kick3dError::UnsupportedScene {
                path: "accurate",
                reason: "a ground plane is a third body; use the rapier scene path",
            });
        }
        let horizon = kick.contact_horizon()?;
        let mut t = 0.0;
        let mut y = dynamics::initial_state(kick);
        let mut dynamics = Dynamics::new(kick).at_touch(&y);
        // sup F includes the onset value F(0⁺) = c V_n.
        let mut peaks = WATCHED.map(|w| Peak { value: w.value(&dynamics, &y), time: 0.0 });
        let difference_step = DIFFERENCE_STEP * kick_compliant::events::Scales::of(&kick.normal_scenario()?).time;
        let mut max_compression = (0.0, 0.0);
        let mut slip_time = 0.0;
        let mut evaluations = 0u64;
        if let Some(r) = recorder.as_deref_mut() {
            r.push(sample(&dynamics, 0.0, &y));
        }
        // Whether the phase starts on the grip/slip switch (`Watch::on_switch`).
        let mut on_switch = false;
        for _ in 0..MAX_PHASES {
            let hit =
                self.phase(dynamics, t, y, horizon, &mut peaks, difference_step, recorder.as_deref_mut(), &mut evaluations, on_switch)?;
            let Some((event, t_event, y_event)) = hit else {
                return Err(KickError::NoSeparation {
                    time: horizon,
                    reason: format!("3D contact outlasted the horizon of {horizon:.6e} s"),
                }
                .into());
            };
            // Grip or slip holds through a phase.
            if dynamics.slipping {
                slip_time += t_event - t;
            }
            t = t_event;
            y = y_event;
            let c = dynamics.contact(&y);
            outcome::within_geometry(kick, c.compression, t)?;
            // The event point ends one phase and starts the next: a sample of both.
            for (peak, w) in peaks.iter_mut().zip(WATCHED) {
                peak.observe(w.value(&dynamics, &y), t);
            }
            if let Some(r) = recorder.as_deref_mut() {
                r.push(sample(&dynamics, t, &y));
            }
            on_switch = false;
            if event == Event::GripSlip {
                on_switch = true;
                if dynamics.slipping {
                    // Grip starts with the spring on the cap, a hair inside it
                    // (`tangential::GRIP_ENTRY`): the grip's margin starts there
                    // from zero with zero slope.
                    y = dynamics.spring_on_cap(&y);
                }
                dynamics = dynamics.switched();
            } else if event != Event::Separation {
                // Another switch may bring grip or slip with it (at δ̇ = 0 the
                // paper's law's dashpot stops, the cap's rate jumps, and so does
                // the slider's speed): the next phase starts on its own side.
                let margin = dynamics.contact(&y).grip_margin;
                if (dynamics.slipping && margin > 0.0) || (!dynamics.slipping && margin < 0.0) {
                    if dynamics.slipping {
                        y = dynamics.spring_on_cap(&y);
                    }
                    dynamics = dynamics.switched();
                    on_switch = true;
                }
            }
            match event {
                Event::CompressionRate | Event::GripSlip | Event::Clamp => {
                    if c.compression > max_compression.0 {
                        max_compression = (c.compression, t);
                    }
                }
                Event::Separation => {
                    let [normal, tangential] = peaks;
                    let peaks = Peaks { normal, tangential, compression: max_compression, slip_time };
                    let end = dynamics.end_state(kick, &y, t);
                    let out = outcome::assemble(kick, &end, peaks, evaluations, "full-state-3d")?;
                    return Ok((out, y));
                }
            }
        }
        Err(KickError::NoSeparation { time: t, reason: format!("more than {MAX_PHASES} phases") }.into())
    }

    /// Solve one kick; keeps no time history.
    pub fn solve(&self, kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
        Ok(self.run(kick, None)?.0)
    }

    /// Solve and also return the state at separation (world frame).
    pub fn solve_to_state(&self, kick: &Kick3d) -> Result<(Outcome3d, EndState), Kick3dError> {
        let (outcome, y) = self.run(kick, None)?;
        Ok((outcome, Dynamics::new(kick).end_state(kick, &y, outcome.contact_time)))
    }

    /// Solve and record (t, kinetic + elastic energy, losses) at every accepted step and event.
    pub fn solve_recorded(&self, kick: &Kick3d) -> Result<(Outcome3d, Vec<EnergySample>), Kick3dError> {
        let mut samples = Vec::new();
        let (outcome, _) = self.run(kick, Some(&mut samples))?;
        Ok((outcome, samples))
    }
}
