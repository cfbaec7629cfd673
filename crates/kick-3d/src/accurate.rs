//! `accurate-3d`: the relative motion in the foot's frame ([`crate::contact`],
//! 23 states, 30 with a leg or a boot) on Dormand–Prince 8(5,3) ([`kick_core::dop853`]), switches
//! located on the step's dense output.
//!
//! A run is a sequence of phases, each holding one branch of every switch
//! (the normal law's damping branch, grip or slip, face or border), so the
//! right-hand side is smooth within a phase and continued past its own
//! switches. After each accepted step the switch functions are read at its
//! end; one that has left its phase's side is located by Brent's method on
//! the step's 7th-order dense output (three more evaluations, only for such
//! steps), and the run restarts there on the new branch, keeping its step
//! size. Switches that change nothing in the right-hand side do not restart:
//! δ̇ = 0 under a law that damps on both sides only marks a maximum compression.
//! - separation: δ from + to −; contact onset is t = 0 by construction;
//! - δ̇ changes sign (the damping switch of Eq. 20; + → − is max compression);
//! - grip ↔ slip ([`crate::tangential`]): in grip μ F_n − k_t |ξ|, in slip
//!   the slider's speed λ changes sign (another switch that makes the
//!   slider's speed jump, such as δ̇ = 0 under the paper's law, is met at the
//!   next phase's start, which is past it); not once the tangential impulse
//!   left is below 1e-16 of the normal impulse ([`friction_settled`]);
//! - the ball centre leaves (or comes back over) the flat face: analytic
//!   geometry on the face, parry's query on edges and rounded borders.
//!
//! Peaks (normal force, |tangential force|): every switch is a sample of both
//! the phase it ends and the one it starts (both forces are continuous; only
//! their rates jump); inside a phase every maximum is a root of dQ/dt, a
//! central difference of Q along the flow on the phase's own branch (no
//! one-sided differences needed: the branch is smooth through its ends).
//! A step across which dQ/dt falls through zero, or the stretch from the
//! last accepted point to a switch, has its root located by Brent's method
//! on the dense output, to 1e-10 of the step (`RATE_ROOT_SHARE`) or to
//! where the difference's two sides agree to their rounding (`ROUNDING`),
//! whichever comes first. At an
//! accepted point the rates are read only by sign, so a one-sided
//! difference serves there unless a sign is in doubt (`rates_after_step`).
//!
//! Tolerance: relative [`DEFAULT_TOLERANCE`] (1e-13) on every component,
//! absolute the same share of the component's unit (δ* for displacements
//! and the spring, V_n for speeds, V_n/R and V_n/(R + h_x) for spins, μ V_n
//! and μ V_n² for the running integrals: the 1D units of the normal
//! scenario, `kick_compliant::events::Scales`).
//! In slip the spring's slots hold the slider's direction, which turns
//! towards the sliding at |v_t|/|ξ| ([`crate::tangential`]): a contracting
//! state, whose error is forgotten within τ = |ξ|/(ŝ · v_t) and acts on the
//! motion only through the tangential force meanwhile, where a state that
//! does not contract carries its error for the rest of the contact (the
//! time unit T = δ*/V_n). Its absolute tolerance is therefore widened by
//! T/τ when that exceeds 1 ([`slip_direction_widening`]), read at each
//! accepted point: an error of one unit then moves the motion as much as
//! one unit's error of a slow state. Near separation, where |ξ| = μ F_n/k_t
//! vanishes, τ falls to microseconds and this state alone set the steps:
//! the cap patch kick at 5 cm, μ = 0.5, with the leg took 1039 evaluations,
//! 753 with the widening; with the leg and its boot 1438 and 1163 (the
//! error against the tightened references stays as it was: tests/model/foot.rs).
//!
//! Measured error against the full-state path tightened to rtol 1e-13
//! ([`crate::full_state`], another state, frame, geometry code, integrator
//! and event machinery), over 200 kicks of the box (offset 0–9 cm, approach
//! −20…30°, μ 0.2–∞, foot 1–10 kg, [`crate::models::OffCenterBox`], seed
//! 2024), relative: see the table in `tests/box_accuracy.rs`.
//!
//! Cost (one core; `cargo bench -p kick-3d --bench solve3d`): see the bench.
//!
//! Allocation: none.
//!
//! Time histories: [`crate::history`] samples a uniform grid from each
//! accepted step's dense output ([`Accurate3d::solve_streamed`]); the hook is
//! compiled out of [`Accurate3d::solve`] (`run::<false>`), and the outcome is
//! bit-identical with and without it.

use crate::contact::{self, Clock, Friction, Geometry, Local, Phase, Relative, State, DIM};
use crate::error::Kick3dError;
use crate::history::{self, ContactState, Sampler3d};
use crate::model::Kick3d;
use crate::outcome::{self, EndState, EnergySample, Outcome3d, Peak, Peaks};
use kick_core::dop853::{Dense, StepFailure, Stepper};
use kick_core::{roots, AnyLaw, ContactLaw, KickError};
use nalgebra::SVector;

/// The accurate 3D path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accurate3d {
    /// Relative tolerance, and absolute tolerance in each component's unit (module docs).
    pub relative_tolerance: f64,
}

/// Default tolerance: the largest that keeps every observable within 1e-9
/// of the tightened reference over the box (module docs). Over the wider
/// boxes `kick sweep3d` draws (5000 rows each of its defaults, `--law shell`,
/// flown, `--leg`, booted and patch kicks: kick-study's example
/// `sweep3d_accuracy`) 11 rows of about 29,000 exceed it, by 1.0e-9 to
/// 2.1e-9 in a spin or a peak's time, as much as the path itself moves
/// between this tolerance and 1e-15; and a spin far below V_n/R is held to
/// ~3e-13 V_n/R, not to 1e-9 of itself (`precision::Errors3d`).
pub const DEFAULT_TOLERANCE: f64 = 1e-13;

impl Default for Accurate3d {
    fn default() -> Self {
        Accurate3d { relative_tolerance: DEFAULT_TOLERANCE }
    }
}

/// Most steps (accepted and rejected) per run.
pub const MAX_STEPS: u64 = 1_000_000;
/// Most phases per run.
pub const MAX_PHASES: usize = 10_000;
/// A run whose accepted steps stay below [`STALL_SHARE`] of the clock's
/// unit (δ*/V_n, or u's) this many times in a row has stalled and is
/// stopped as a numerical failure. A kick of the sweeps' boxes takes at most
/// ~800 steps in all, its shortest ~1e-4 of the unit (towards separation);
/// the one stall seen (`kick sweep3d --law shell --leg`, seed 1, row 7162:
/// the point contact on the rounded border, slipping behind the boot) sat at
/// 3e-14 s ≈ 3e-11 of the unit with every other step rejected, and ran into
/// [`MAX_STEPS`] after 7.7 s: the 20,000-row leg sweep spent about half
/// its wall time on it.
pub const STALL_STEPS: u32 = 10_000;
/// See [`STALL_STEPS`].
pub const STALL_SHARE: f64 = 1e-9;
/// Step of the differences that give dQ/dt, in units of the normal
/// scenario's time δ*/V_n: truncation (∝ step²) and rounding (∝ 1/step) of
/// the rate both stay near 1e-11 of its scale.
const DIFFERENCE_STEP: f64 = 2e-5;

/// The first step, in the clock's unit at touch (δ*/V_n on the time
/// clock, δ*^(1/p) on the onset clock's u), at [`DEFAULT_TOLERANCE`], and
/// scaled as rtol^(1/8) (the step's error is of 8th order). Hairer's `hinit`
/// guessed four times too large at touch, where the force starts from zero,
/// and a kick paid two rejected steps (22 evaluations) for it; so did 0.1 on
/// the onset clock. Measured (evaluations per kick, against `hinit` or 0.1):
/// the box of `count3d` 577 → 558 at rtol 1e-13, 962 → 940 at 1e-15, 341 →
/// 342 at 1e-11; 24 shell kicks (point, patch, cap, rigid grip; offsets
/// 0–8 cm) −4.1 %, −2.4 % and −5.0 % at the same tolerances.
const FIRST_STEP_TIME: f64 = 0.1;
const FIRST_STEP_ONSET: f64 = 0.05;
/// With a boot in series, the first step on the time clock is at most this
/// share of the layer's time constant at touch, c_b/(k_b + k(0))
/// (`kick_core::Boot::time_constant`): the layer's rate starts from zero
/// and relaxes on that scale, which holds the first steps to about 0.07 of
/// it at the default tolerance; from δ*/V_n the cap patch kick with the
/// leg and its boot paid two rejected steps (22 evaluations) to get there.
const FIRST_STEP_BOOT: f64 = 0.06;

/// The factor on the absolute tolerance of the slip's direction state
/// (contact::SPRING) at the law `c`: T/τ with τ = max(|ξ|, ℓ)/(ŝ · v_t) the
/// time in which the direction forgets an error (module docs), at least 1;
/// 1 outside slip, where the slots hold the spring's stretch itself.
fn slip_direction_widening(system: &Relative, c: &Local, time_unit: f64) -> f64 {
    if system.phase.friction != Friction::Slip || system.rigid {
        return 1.0;
    }
    // In slip F_t = −μ F_n ŝ.
    let cap = c.tangential_force.length();
    if cap == 0.0 {
        return 1.0;
    }
    let along = -c.tangential_force.dot(c.sliding_velocity) / cap;
    let stretch = (cap / system.tangential_stiffness).max(crate::tangential::RELAXATION_LENGTH);
    (time_unit * along / stretch).max(1.0)
}

/// The share of the normal impulse below which the tangential impulse
/// still to come no longer switches grip and slip ([`friction_settled`]).
const SETTLED_SHARE: f64 = 1e-16;

/// Whether, on the release clock, the tangential impulse left before
/// separation is below [`SETTLED_SHARE`] of the normal impulse so far, in
/// either branch: at most (μ F_n + k_t |v_t| τ) τ, τ = δ/|δ̇| bounding the
/// time left (δ falls at least as fast as it does now, F ∝ δⁿ). Then grip
/// and slip stop switching, and the phase runs on to separation on its
/// branch. Picoseconds from separation they switched for ever: the spring
/// there is shorter than rounding resolves (μ F_n/k_t ~ 1e-12 m) and the
/// cap falls as fast as the sliding stretches it: of `kick sweep3d`'s
/// default box (seed 1) 118 of 4000 kicks ran into MAX_PHASES, 60 with this
/// rule (those switch for ever at millinewtons, not at rounding: a sliding
/// mode of the slider's law below its relaxation length, left open).
fn friction_settled(system: &Relative, c: &Local, y: &State) -> bool {
    if !matches!(system.phase.clock, Clock::Release { .. }) || !system.friction.is_finite() || !(c.compression_rate < 0.0) {
        return false;
    }
    let left = c.compression / -c.compression_rate;
    let bound = (system.friction * c.normal_force + system.tangential_stiffness * c.sliding_velocity.length() * left) * left;
    bound < SETTLED_SHARE * y[contact::NORMAL_IMPULSE]
}

/// What ends a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Switch {
    Separation,
    CompressionRate,
    GripSlip,
    Geometry,
    /// The normal force reaches zero before δ does (a law that would pull).
    Clamp,
}

const SWITCHES: [Switch; 5] = [Switch::Separation, Switch::CompressionRate, Switch::GripSlip, Switch::Geometry, Switch::Clamp];

impl Switch {
    /// The switch function's value from the law at a point.
    fn value(self, system: &Relative, c: &Local, y: &State) -> f64 {
        match self {
            Switch::Separation => c.compression,
            Switch::CompressionRate => c.compression_rate,
            Switch::GripSlip => c.grip_margin,
            Switch::Geometry => system.face_margin(y),
            Switch::Clamp => c.unclamped_force,
        }
    }
    /// The sign the switch function keeps through the phase (None: not watched).
    fn sign(self, system: &Relative) -> Option<f64> {
        let phase = system.phase;
        match self {
            // Near separation the clock ends the contact at a known x.
            Switch::Separation => (phase.clock == Clock::Time).then_some(1.0),
            Switch::CompressionRate => Some(if phase.compressing { 1.0 } else { -1.0 }),
            Switch::GripSlip => match phase.friction {
                // No normal force, no slider: nothing to switch until it comes back.
                _ if phase.clamped && !system.rigid => None,
                Friction::Grip if system.friction.is_finite() => Some(1.0),
                Friction::Slip => Some(-1.0),
                _ => None,
            },
            Switch::Geometry => match phase.geometry {
                Geometry::Face => Some(1.0),
                Geometry::Border => Some(-1.0),
                // A cap: one smooth surface.
                Geometry::Curved => None,
            },
            Switch::Clamp => system.clamps.then_some(if phase.clamped { -1.0 } else { 1.0 }),
        }
    }
    /// Whether the value at a step's end keeps the phase: strictly on its
    /// side, or (for the clamp) at zero, where every law sits beyond separation.
    fn holds(self, signed: f64) -> bool {
        signed > 0.0 || (self == Switch::Clamp && signed == 0.0)
    }
}

/// Normal force and |tangential force| on the phase's branch.
#[inline]
fn watched(c: &Local) -> [f64; 2] {
    [c.normal_force, c.tangential_force_size()]
}

/// Rates along the flow: dQ/dx of the normal and tangential force, and of
/// the grip margin, the face margin and δ̇ (to find a switch function that
/// dips through zero and back within one step).
type Rates = [f64; 5];
const GRIP_RATE: usize = 2;
const FACE_RATE: usize = 3;
const COMPRESSION_RATE_RATE: usize = 4;

/// [`Rates`] at (x, y) along the flow dy (central differences over ±dx).
#[inline]
fn rates(system: &Relative, x: f64, y: &State, dy: &State, dx: f64) -> Rates {
    let (qa, qb) = sides(system, x, y, dy, dx);
    std::array::from_fn(|i| (qa[i] - qb[i]) / (2.0 * dx))
}

/// The [`quantities`] at the two sides of a central difference, x ± dx along dy.
#[inline(always)]
fn sides(system: &Relative, x: f64, y: &State, dy: &State, dx: f64) -> (Rates, Rates) {
    let (ya, yb) = (y + dy * dx, y - dy * dx);
    (quantities(system, &system.local(x + dx, &ya), &ya), quantities(system, &system.local(x - dx, &yb), &yb))
}

/// The watched quantities, the two margins and δ̇, in [`Rates`]' order.
#[inline(always)]
fn quantities(system: &Relative, c: &Local, y: &State) -> Rates {
    let q = watched(c);
    [q[0], q[1], c.grip_margin, system.face_margin(y), c.compression_rate]
}

/// The watched quantities' difference from b to a over `span` of x.
#[inline(always)]
fn difference(system: &Relative, (a, ya): (&Local, &State), (b, yb): (&Local, &State), span: f64) -> Rates {
    let (qa, qb) = (quantities(system, a, ya), quantities(system, b, yb));
    std::array::from_fn(|i| (qa[i] - qb[i]) / span)
}

/// Units in the last place (of the larger value, in ε) within which the two
/// sides of a central difference are taken as equal: the differences'
/// rounding, seen in the traces as ±1–5 ulp once a root is reached.
const ROUNDING: f64 = 4.0;

/// The `i`th of [`rates`], for Brent: zero where the two sides agree to
/// their rounding ([`ROUNDING`]), so the root is taken there. Past that
/// point Brent's iterations (two evaluations each) follow the rounding
/// alone; the root is then off by at most the rounding over the rate's
/// slope, as it was at the end of those iterations. (A margin's rounding
/// is of μ F_n or the face's size, not of the margin: larger than this
/// test takes, so it stops no earlier than Brent would.)
#[inline]
fn rate_for_root(system: &Relative, x: f64, y: &State, dy: &State, dx: f64, i: usize) -> f64 {
    let (a, b) = sides(system, x, y, dy, dx);
    let (qa, qb) = (a[i], b[i]);
    if (qa - qb).abs() <= ROUNDING * f64::EPSILON * qa.abs().max(qb.abs()) {
        0.0
    } else {
        (qa - qb) / (2.0 * dx)
    }
}

/// [`rates`] at an accepted step's end x, where the law `c` is already
/// evaluated: one more evaluation, behind it, and the one-sided difference.
/// The run reads these rates only by sign (a maximum, or a margin's dip,
/// between two accepted points; the roots themselves are located on
/// [`rate_for_root`]). The one-sided error is about |Q''| dx/2; where a rate lies
/// within a hundred times that of zero (Q'' from the rates at the step's
/// two ends, `before` at x0), its sign is not trusted and the central
/// difference is taken instead. Half the evaluations of [`rates`], which
/// took a fifth of a kick's.
#[inline]
#[allow(clippy::too_many_arguments)]
fn rates_after_step(system: &Relative, x: f64, y: &State, dy: &State, dx: f64, c: &Local, x0: f64, before: &Rates) -> Rates {
    let behind = rates_behind(system, x, y, dy, dx, c);
    let step = x - x0;
    // (δ̇'s rate only asks for a dip's search, which finds none where there is none.)
    let trusted = behind[..COMPRESSION_RATE_RATE].iter().zip(before).all(|(&r, &r0)| {
        let window = 100.0 * ((r - r0) / step).abs() * dx;
        r.abs() > window || (r == 0.0 && r0 == 0.0)
    });
    if trusted {
        behind
    } else {
        rates(system, x, y, dy, dx)
    }
}

/// The one-sided difference of [`rates_after_step`], from behind x.
#[inline]
fn rates_behind(system: &Relative, x: f64, y: &State, dy: &State, dx: f64, c: &Local) -> Rates {
    let yb = y - dy * dx;
    difference(system, (c, y), (&system.local(x - dx, &yb), &yb), dx)
}

/// Share of a step to which a root of [`rates`] (a force's maximum, a
/// margin's least value) is located. The rates are central differences
/// whose rounding is 1e-11–1e-10 of their scale (module docs); once the
/// root is known to this share of the step, Brent's further iterations (to
/// 4 ε x: about ten more, two evaluations each) only chased that noise. A
/// maximum's time moves by less than this share of its step (measured: at
/// most 1.9e-11 of the time over the results' kicks), its value by the
/// square of that.
const RATE_ROOT_SHARE: f64 = 1e-10;

/// Brent's tolerance for a root of [`rates`] in (x0, x1].
fn rate_root_tolerance(x0: f64, x1: f64, dx: f64) -> f64 {
    (4.0 * f64::EPSILON * x1.abs().max(dx)).max(RATE_ROOT_SHARE * (x1 - x0))
}

/// Share of the step at which a switch's bracket starts when the phase
/// starts on that switch (`locate_switch`).
const START_SHARE: f64 = 1e-6;

/// The root of `g` (sign `sign` at x0) in (x0, x1] on the dense output,
/// taken on the far side of the crossing so the next phase starts past it;
/// x0 itself when g is already past there (two switches at one instant).
/// g is evaluated once per point: at x0 once, and Brent's last point is
/// read from its value.
fn locate_switch(g: impl Fn(f64) -> f64, sign: f64, x0: f64, x1: f64) -> f64 {
    let start = sign * g(x0);
    if start < 0.0 {
        return x0;
    }
    let on_side = |x: f64| sign * g(x);
    // A phase starts on its switch (g = 0 there): on its own side. Its
    // bracket then starts where g has left zero, START_SHARE into the step,
    // so that Brent's first secant is not drawn from a made-up value at x0:
    // from (x0, MIN_POSITIVE) it fell within 1e-300 of x0 and stopped there
    // (the cap patch kick with the leg, sweep row 153, ended a 17 µs grip from
    // touch at touch: slip time off by 1.4e-3 of the contact).
    let (xa, fa) = match start {
        0.0 => {
            let xs = x0 + START_SHARE * (x1 - x0);
            let fs = on_side(xs);
            if fs > 0.0 {
                (xs, fs)
            } else {
                (x0, f64::MIN_POSITIVE)
            }
        }
        _ => (x0, start),
    };
    match roots::brent_from(on_side, (xa, fa), (x1, on_side(x1)), 4.0 * f64::EPSILON * x1.abs(), 200) {
        Some(root) if root.value <= 0.0 || (root.x == x0 && start == 0.0) => root.x,
        Some(root) => root.other,
        None => x1,
    }
}

/// The exponent of δⁿ when it is not smooth at δ = 0 (the ends need the clock).
fn singular_exponent(law: &AnyLaw) -> Option<f64> {
    let n = match law {
        AnyLaw::PowerLaw(l) => l.exponent,
        AnyLaw::Hysteresis(h) => h.exponent,
        AnyLaw::KelvinVoigt(_) => 1.0,
        // F = (2πR p0 + k_s) δ + O(δ²), smooth in δ.
        AnyLaw::Shell(_) => 1.0,
    };
    (n.fract() != 0.0).then_some(n)
}

/// Where the ends are integrated in u = δ^(1/p): below these shares of δ*
/// (first touch) and of δ_max (towards separation), while |δ̇| stays above
/// [`CLOCK_RATE`] of V_n.
/// (Tried: onset 0.003–0.3 and release 0.1–0.5; these took the fewest evaluations.)
const ONSET_SHARE: f64 = 0.03;
const RELEASE_SHARE: f64 = 0.3;
const CLOCK_RATE: f64 = 0.2;
/// Share of the step that lands on separation within which a grip/slip
/// switch located there is separation itself (see `locate_switches`).
/// What is left of the contact there has δ = u^p below (1e-3 Δu/u_start)^p
/// of its start, a normal force and a time to match: a grip or a slip in it
/// moves no observable by a measurable amount. With 1e-9 instead, grips
/// begun in that stretch failed with a step-size underflow on the boxes
/// (200 kicks) of 6 of 7 laws.
const LANDING_SHARE: f64 = 1e-3;
/// Points of the landing step at which a grip/slip margin that holds at
/// both ends is read for a dip (see `locate_switches`).
const LANDING_SAMPLES: u32 = 16;

/// The system as the stepper sees it, keeping the law at the accepted
/// step's end: an accepted step ends on the right-hand side there (DOP853's
/// k13), so the law at its end is read back, not evaluated again. Only that
/// evaluation is kept (`derivative_at_step_end`): keeping every one copied a
/// `Local` (about 400 bytes) per evaluation, 4.6 % of a flown sweep's time.
struct Remembering<'a> {
    system: &'a Relative,
    last: std::cell::Cell<Option<(f64, Local)>>,
}

impl<'a> Remembering<'a> {
    fn new(system: &'a Relative) -> Self {
        Remembering { system, last: std::cell::Cell::new(None) }
    }
    /// The law at (x, y): the accepted step's end's when it was at x, else evaluated.
    fn local_at(&self, x: f64, y: &State) -> Local {
        match self.last.get() {
            Some((at, c)) if at == x => c,
            _ => self.system.local(x, y),
        }
    }
}

impl kick_core::dop853::System<DIM> for Remembering<'_> {
    #[inline]
    fn derivative(&self, x: f64, y: &State) -> State {
        self.system.derivative(x, y)
    }
    #[inline]
    fn derivative_at_step_end(&self, x: f64, y: &State) -> State {
        let (dy, c) = self.system.derivative_and_local(x, y);
        self.last.set(Some((x, c)));
        dy
    }
    fn counted_components(&self) -> usize {
        self.system.counted_components()
    }
}

/// The last accepted point or switch of the run and the watched rates there.
#[derive(Debug, Clone, Copy)]
struct Point {
    x: f64,
    rates: Rates,
}

impl Accurate3d {
    pub fn new(relative_tolerance: f64) -> Result<Self, Kick3dError> {
        if !(relative_tolerance.is_finite() && relative_tolerance > 0.0 && relative_tolerance < 1e-3) {
            return Err(Kick3dError::InvalidParameter { name: "rtol", value: relative_tolerance, requirement: "in (0, 1e-3)" });
        }
        Ok(Accurate3d { relative_tolerance })
    }

    /// Solve one kick; keeps no time history.
    pub fn solve(&self, kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
        Ok(self.run::<false>(kick, None, None)?.0)
    }

    /// [`Accurate3d::solve`] on the baseline x86-64 copy even where the CPU
    /// has AVX2 (`contact::avx2`): the same outcome bit for bit, for timing
    /// the two copies against each other.
    pub fn solve_baseline(&self, kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
        Ok(self.run_on::<false, false>(kick, None, None)?.0)
    }

    /// Solve and also return both bodies at separation (world frame).
    pub fn solve_to_state(&self, kick: &Kick3d) -> Result<(Outcome3d, EndState), Kick3dError> {
        self.run::<false>(kick, None, None)
    }

    /// Solve and record (t, kinetic + elastic energy, losses) at every accepted step and switch.
    pub fn solve_recorded(&self, kick: &Kick3d) -> Result<(Outcome3d, Vec<EnergySample>), Kick3dError> {
        let mut samples = Vec::new();
        let (outcome, _) = self.run::<false>(kick, Some(&mut samples), None)?;
        Ok((outcome, samples))
    }

    /// One run; `recorder` takes energy samples at every accepted point and
    /// switch, `sampler` a uniform history ([`crate::history`]; only read
    /// when `SAMPLE`, so the summary path compiles without it). Neither
    /// changes a step: both only read the run.
    pub(crate) fn run<const SAMPLE: bool>(
        &self,
        kick: &Kick3d,
        recorder: Option<&mut Vec<EnergySample>>,
        sampler: Option<&mut Sampler3d>,
    ) -> Result<(Outcome3d, EndState), Kick3dError> {
        #[cfg(target_arch = "x86_64")]
        if contact::avx2() {
            // SAFETY: the CPU has AVX2 (`contact::avx2`).
            return unsafe { self.run_avx2::<SAMPLE>(kick, recorder, sampler) };
        }
        self.run_on::<SAMPLE, false>(kick, recorder, sampler)
    }

    /// [`Accurate3d::run`] compiled for AVX2, the stepper inlined
    /// ([`contact::avx2`]: the same results, bit for bit).
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn run_avx2<const SAMPLE: bool>(
        &self,
        kick: &Kick3d,
        recorder: Option<&mut Vec<EnergySample>>,
        sampler: Option<&mut Sampler3d>,
    ) -> Result<(Outcome3d, EndState), Kick3dError> {
        self.run_on::<SAMPLE, true>(kick, recorder, sampler)
    }

    /// The run as a sequence of named phases ([`Run`]): the scene checked
    /// and the first touch set up ([`refuse_scene`], [`first_touch`],
    /// [`Run::start`]), then per step the contact integrated
    /// ([`Run::integrate_step`]), its switches located
    /// ([`Run::locate_switches`]), the stretch closed with its peaks and
    /// records ([`Run::close_stretch`]), and what comes next
    /// ([`Run::next`]: advance, a change of clock, a switch of regime, or
    /// separation and the summary, [`Run::separate`]).
    #[inline(always)]
    fn run_on<const SAMPLE: bool, const AVX2: bool>(
        &self,
        kick: &Kick3d,
        recorder: Option<&mut Vec<EnergySample>>,
        sampler: Option<&mut Sampler3d>,
    ) -> Result<(Outcome3d, EndState), Kick3dError> {
        refuse_scene(kick)?;
        let horizon = kick.contact_horizon()?;
        let scales = kick_compliant::events::Scales::of(&kick.normal_scenario()?);
        let (system, y0) = first_touch::<AVX2>(kick);
        let mut run = Run::<SAMPLE>::start(self.relative_tolerance, kick, system, y0, horizon, scales, recorder, sampler)?;
        loop {
            let (x1, y1, c1) = run.integrate_step()?;
            let dx = run.step_of(run.system.phase.clock);
            // Landed on u = 0 (to rounding of the last step's end): separation.
            let landed = matches!(run.system.phase.clock, Clock::Release { start } if x1 >= start * (1.0 - 1e-14));
            let rates_1 = if landed {
                // On u every rate is zero at separation (dt/du = 0 there), so
                // its sign just before is read on the time clock, from behind:
                // the contact's own side. Taken on u, a maximum in the last
                // step went unseen (box kick 97 of Lankarani and Nikravesh's
                // law, μ = ∞: |F_t| 3.9e-5 N low at separation, where the
                // reference has it 0.24 µs before).
                let on_time = run.system.in_phase(Phase { clock: Clock::Time, ..run.system.phase });
                let t1 = run.system.time(x1, &y1);
                let (dy, c) = on_time.derivative_and_local(t1, &y1);
                run.extra_evaluations += 1;
                rates_behind(&on_time, t1, &y1, &dy, run.step_of(Clock::Time), &c)
            } else {
                rates_after_step(&run.system, x1, &y1, run.stepper.end_derivative(), dx, &c1, run.point.x, &run.point.rates)
            };
            let mut dense: Option<Dense<DIM>> = None;
            let end = run.locate_switches(x1, &y1, &c1, &rates_1, dx, landed, &mut dense);
            let stretch = run.close_stretch(end, (x1, y1, c1, rates_1), dx, &mut dense)?;
            match run.next(end, landed, &c1) {
                Next::Advance => run.advance(&c1, x1, stretch.rates),
                Next::Clock(clock) => run.change_clock(clock, x1, &y1, stretch.t),
                Next::Switch(switch) => {
                    run.end_phase(stretch.t);
                    if switch == Switch::Separation {
                        return run.separate(&stretch);
                    }
                    run.switch_phase(switch, stretch, dx)?;
                }
            }
        }
    }
}

/// Scenes this path refuses: a ground plane, and rigid grip at a finite
/// friction out of one plane.
#[inline(always)]
fn refuse_scene(kick: &Kick3d) -> Result<(), Kick3dError> {
    if kick.ground {
        return Err(Kick3dError::UnsupportedScene {
            path: "accurate",
            reason: "a ground plane is a third body; use the rapier scene path",
        });
    }
    // One plane: the foot's path (x–z at an approach angle), the ball's
    // (x), the face's normal and the foot's mirror plane. The knife edge
    // is the lateral kick rolled about the path: one plane with a
    // horizontal path, a ball at rest, or no offset. An instep keeps its
    // box level: a yaw needs a horizontal path and the pole at the
    // centre's height, a pitch no offset and no yaw.
    let planar = match kick.instep {
        None => kick.approach_angle == 0.0 || kick.base.ball_speed() == 0.0 || kick.offset == 0.0,
        Some(i) => (kick.approach_angle == 0.0 && i.pitch == 0.0 && kick.contact_depth == 0.0) || (kick.offset == 0.0 && i.yaw == 0.0),
    };
    if kick.rigid_grip() && kick.friction.is_finite() && kick.friction > 0.0 && !planar {
        return Err(Kick3dError::UnsupportedScene {
            path: "accurate",
            reason: "rigid grip (tangential_stiffness = inf) with a finite friction keeps each slip in one direction, \
                     exact for a kick in one plane: on the knife edge give approach_angle = 0, ball_speed = 0 or \
                     offset = 0; on an instep approach_angle = 0, face_pitch = 0 and contact_depth = 0, or offset = 0 \
                     and face_yaw = 0 (or friction = inf)",
        });
    }
    Ok(())
}

/// The system at first touch, on the branches the contact starts on
/// (compressing; grip or slip; face, border or cap; the clock), and the
/// state at touch (a rigid grip's impulse, or a slip's direction state, applied).
#[inline(always)]
fn first_touch<const AVX2: bool>(kick: &Kick3d) -> (Relative, State) {
    let y0 = contact::initial_state(kick);
    let singular = singular_exponent(&kick.law).is_some();
    let clock = if singular { Clock::Onset } else { Clock::Time };
    let mut system = Relative::new(
        kick,
        Phase {
            compressing: true,
            friction: Friction::Grip,
            geometry: if kick.instep.is_some_and(|i| i.is_curved()) { Geometry::Curved } else { Geometry::Face },
            clamped: false,
            clock: Clock::Time,
            slip_direction: parry3d_f64::math::Vec3::ZERO,
            slip_start: 0.0,
        },
    )
    .on_avx2(AVX2);
    let mut y0 = y0;
    let sliding = system.local(0.0, &y0).sliding_velocity;
    let friction = if kick.friction == 0.0 {
        Friction::None
    } else if system.rigid && sliding != parry3d_f64::math::Vec3::ZERO {
        // Rigid grip: μ = ∞ stops the sliding at once; a finite μ starts
        // in slip, against the sliding.
        if kick.friction.is_infinite() {
            y0 = system.grip_impulse(&y0);
            Friction::Grip
        } else {
            system = system.in_phase(Phase { slip_direction: sliding.normalize(), ..system.phase });
            Friction::Slip
        }
    } else if !system.rigid {
        // ξ = 0: grip unless the cap starts at zero and grows slower than
        // the spring would load (`crate::tangential`).
        let slip = system.in_phase(Phase { friction: Friction::Slip, ..system.phase }).local(0.0, &y0);
        if kick.friction.is_finite() && slip.normal_force == 0.0 && slip.grip_margin < 0.0 {
            // The state holds the slider's direction (contact::SPRING), along the sliding.
            let direction = contact::slip_direction_state(&slip, &y0);
            contact::put_spring(&mut y0, direction);
            Friction::Slip
        } else {
            Friction::Grip
        }
    } else if system.local(0.0, &y0).grip_margin >= 0.0 {
        Friction::Grip
    } else {
        if system.rigid {
            let needed = system.local(0.0, &y0).tangential_force;
            system = system.in_phase(Phase { slip_direction: -needed.normalize_or_zero(), ..system.phase });
        }
        Friction::Slip
    };
    (system.in_phase(Phase { friction, clock, ..system.phase }), y0)
}

/// What the run does after a stretch (the stop reasons of a phase).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Next {
    /// The step was accepted inside the phase: on to the next.
    Advance,
    /// The same phase goes on on another clock (onset → time, time → release, release → time).
    Clock(Clock),
    /// A switch ends the phase; [`Switch::Separation`] ends the run.
    Switch(Switch),
}

/// A stretch's end: a switch, or the accepted point.
struct Stretch {
    x: f64,
    y: State,
    t: f64,
    c: Local,
    rates: Rates,
}

/// The state of one run: the system on its current phase, the stepper, the
/// settings fixed at touch and the running record (peaks, maximum
/// compression, slip time, evaluations).
struct Run<'a, 's, const SAMPLE: bool> {
    kick: &'a Kick3d,
    system: Relative,
    stepper: Stepper<DIM>,
    recorder: Option<&'a mut Vec<EnergySample>>,
    sampler: Option<&'a mut Sampler3d<'s>>,
    /// Absolute tolerance per component (module docs).
    absolute: SVector<f64, DIM>,
    scales: kick_compliant::events::Scales,
    horizon: f64,
    /// The unit of u = δ^(1/p).
    u_unit: f64,
    v_n: f64,
    /// Whether the ends of the contact are integrated on the release clock.
    release: bool,
    release_scale: f64,
    com: contact::CentreOfMass,
    ball_velocity0: parry3d_f64::math::Vec3,
    peaks: [Peak; 2],
    max_compression: (f64, f64),
    slip_time: f64,
    phase_start: f64,
    extra_evaluations: u64,
    /// Dense outputs made for the history alone (not in the outcome's count).
    history_evaluations: u64,
    phases: usize,
    /// [`friction_settled`] at the last accepted point: grip and slip no
    /// longer switch in the steps after it (read at a step's start, where
    /// the bound is the larger: at its end it is 0 on landing).
    settled: bool,
    /// The last accepted point or switch.
    point: Point,
    /// Accepted steps in a row below [`STALL_SHARE`] of the clock's unit.
    tiny_steps: u32,
}

impl<'a, 's, const SAMPLE: bool> Run<'a, 's, SAMPLE> {
    /// First touch: tolerances in each component's unit, the first step,
    /// the stepper, the first samples.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn start(
        rtol: f64,
        kick: &'a Kick3d,
        system: Relative,
        y0: State,
        horizon: f64,
        scales: kick_compliant::events::Scales,
        recorder: Option<&'a mut Vec<EnergySample>>,
        sampler: Option<&'a mut Sampler3d<'s>>,
    ) -> Result<Self, Kick3dError> {
        let singular = singular_exponent(&kick.law).is_some();
        // The shell law is smooth at touch (F ∝ δ), but its force stops at
        // δ = 0 with a kink (F_el = 0 below, F ∝ δ above), which a step across
        // separation straddles: its error estimate can miss it (6.5e-10 in
        // spin at rtol 1e-14 on a cap patch kick, where 3e-14 gave 5e-12),
        // and the step is rejected and retried there. The release clock ends
        // the contact at a known x instead (δ = u², F smooth in u): the
        // kink's error goes and the kick takes a quarter fewer evaluations
        // (774 → 559 at 5 cm offset, μ = 0.5, point contact; 763 → 583 with
        // the flat patch, 681 → 558 on the cap).
        let release = singular || matches!(kick.law, AnyLaw::Shell(_));
        // Behind a boot the ball leaves the boot's surface slower than the
        // foot approached (0.36 V_n in the cap patch kick with the leg, which
        // never reached 0.4 V_n: its separation, on the time clock, straddled
        // the kink and cost 1.1e-9 in spin); its clock's thresholds are halved.
        let release_scale = if kick.base.boot().is_some() { 0.5 } else { 1.0 };
        let (length, speed) = (scales.length, scales.speed);
        let mut units = [0.0; DIM];
        for (i, unit) in units.iter_mut().enumerate() {
            *unit = match i {
                0..=2 | 16..=18 => length,
                3..=5 => speed,
                6..=8 => speed / system.touch.x,
                9..=12 => 1.0,
                13..=15 => speed / kick.ball_radius,
                19 => scales.momentum,
                22 => scales.time,
                // The boot's compression, the leg's foot velocity and displacement.
                23 | 27..=29 => length,
                24..=26 => speed,
                _ => scales.energy,
            };
        }
        let absolute = SVector::<f64, DIM>::from(units) * rtol;
        // Units of u = δ^(1/p) and of the differences along x.
        let u_unit = length.powf(1.0 / f64::from(contact::CLOCK_POWER));
        let first_clock_step = match kick.base.boot() {
            Some(boot) if !singular => {
                let touch_stiffness = kick.law.force_gradient(0.0, 0.0).0;
                (FIRST_STEP_TIME * scales.time).min(FIRST_STEP_BOOT * boot.time_constant(touch_stiffness))
            }
            _ if singular => FIRST_STEP_ONSET * u_unit,
            _ => FIRST_STEP_TIME * scales.time,
        };
        let first_step = (rtol / DEFAULT_TOLERANCE).powf(1.0 / 8.0) * first_clock_step;
        let stepper = Stepper::starting_with(&system, 0.0, y0, rtol, absolute, if singular { u_unit } else { horizon }, first_step);
        let first = system.local(0.0, &y0);
        let mut run = Run {
            kick,
            system,
            stepper,
            recorder,
            sampler,
            absolute,
            scales,
            horizon,
            u_unit,
            v_n: kick.normal_approach_speed(),
            release,
            release_scale,
            com: contact::CentreOfMass::of(kick),
            ball_velocity0: kick.initial_state().ball_velocity,
            peaks: watched(&first).map(|value| Peak { value, time: 0.0 }),
            max_compression: (0.0f64, 0.0),
            slip_time: 0.0,
            phase_start: 0.0,
            extra_evaluations: 0,
            history_evaluations: 0,
            phases: 0,
            settled: false,
            point: Point { x: 0.0, rates: [0.0; 5] },
            tiny_steps: 0,
        };
        let dx = run.step_of(run.system.phase.clock);
        run.point = Point { x: 0.0, rates: rates(&run.system, 0.0, &y0, run.stepper.start_derivative(), dx) };
        let sample = run.energy(0.0, &y0);
        if let Some(r) = run.recorder.as_deref_mut() {
            r.push(sample);
        }
        if let Some(s) = run.sampler.as_deref_mut().filter(|_| SAMPLE) {
            let system = &run.system;
            s.fill(0.0, true, |t, _| Ok::<_, Kick3dError>(history::sample(kick, system, 0.0, &y0, t, None)))?;
        }
        Ok(run)
    }

    /// The step of the differences along x on `clock`.
    #[inline(always)]
    fn step_of(&self, clock: Clock) -> f64 {
        DIFFERENCE_STEP * if clock == Clock::Time { self.scales.time } else { self.u_unit }
    }

    /// (t, kinetic + elastic energy, losses) at (x, y).
    fn energy(&self, x: f64, y: &State) -> EnergySample {
        let system = &self.system;
        let t = system.time(x, y);
        let mechanical = match &system.leg {
            Some(leg) => system.leg_mechanical_energy(leg, x, y, t, self.ball_velocity0),
            None => 0.5 * self.com.mass * self.com.velocity_at(t).length_squared() + system.internal_energy(x, y),
        };
        (t, mechanical, y[contact::DAMPING_LOSS], y[contact::FRICTION_LOSS])
    }

    /// Contact integration: one accepted step on the phase's branch (the
    /// release clock's steps end at u = 0 at the latest); the point, state
    /// and law at its end.
    #[inline(always)]
    fn integrate_step(&mut self) -> Result<(f64, State, Local), Kick3dError> {
        let stepper = &mut self.stepper;
        if stepper.accepted + stepper.rejected >= MAX_STEPS {
            let t = self.system.time(self.point.x, stepper.state());
            return Err(KickError::NoSeparation { time: t, reason: format!("more than {MAX_STEPS} steps") }.into());
        }
        if let Clock::Release { start } = self.system.phase.clock {
            stepper.set_max_step(start - stepper.time());
        }
        let remembering = Remembering::new(&self.system);
        stepper.step(&remembering).map_err(|e| {
            let (time, reason) = match e {
                StepFailure::StepSizeUnderflow { time } => (time, "step size underflow"),
                StepFailure::Rejections { time } => (time, "too many rejected steps"),
            };
            Kick3dError::Core(KickError::Integration { time, reason: reason.to_string() })
        })?;
        let x1 = stepper.time();
        let y1 = *stepper.state();
        let unit = if self.system.phase.clock == Clock::Time { self.scales.time } else { self.u_unit };
        if stepper.last_step().1 < STALL_SHARE * unit {
            self.tiny_steps += 1;
            if self.tiny_steps >= STALL_STEPS {
                return Err(KickError::Integration {
                    time: self.system.time(x1, &y1),
                    reason: format!(
                        "the step size stalled below {STALL_SHARE:e} of the contact's time scale for {STALL_STEPS} steps \
                         in a row (a switch the run cannot settle)"
                    ),
                }
                .into());
            }
        } else {
            self.tiny_steps = 0;
        }
        let c1 = remembering.local_at(x1, &y1);
        Ok((x1, y1, c1))
    }

    /// Event location: the earliest switch that ends the phase in the step
    /// to x1, located on the dense output; δ̇ = 0 where it does not change
    /// the right-hand side is a marker only, applied here unless a switch
    /// ends the phase before it.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn locate_switches(
        &mut self,
        x1: f64,
        y1: &State,
        c1: &Local,
        rates_1: &Rates,
        dx: f64,
        landed: bool,
        dense: &mut Option<Dense<DIM>>,
    ) -> Option<(f64, Switch)> {
        let settled = std::mem::replace(&mut self.settled, friction_settled(&self.system, c1, y1));
        let (system, stepper, point) = (&self.system, &mut self.stepper, self.point);
        // The earliest switch that ends the phase in this step; switches
        // that do not change the right-hand side are marked on the way.
        let mut end: Option<(f64, Switch)> = None;
        let mut marker: Option<f64> = None;
        let kinked = self.kick.law.damps_compression_only();
        for switch in SWITCHES {
            let Some(sign) = switch.sign(system) else { continue };
            if switch == Switch::GripSlip && settled {
                continue;
            }
            let mut crossed_by = x1;
            let signed = sign * switch.value(system, c1, y1);
            // At separation a margin may reach zero with the force (μ F_n − 0 on a
            // central kick): a switch landing on separation changes nothing.
            if landed && signed == 0.0 {
                continue;
            }
            if switch.holds(signed) {
                // Both ends on the phase's side: a margin may still dip
                // through zero and back between them, at its minimum.
                // δ̇ = 0 where it changes the right-hand side too (a law that
                // damps compression only, the paper's Eq. 20): sweep row 726
                // of `kick sweep3d` (a driven foot riding a soft ball for
                // 0.14 s) passed over a 0.12 ms restitution in one step at
                // rtol 1e-13, keeping compression's damping through it.
                let i = match switch {
                    Switch::GripSlip => GRIP_RATE,
                    Switch::Geometry => FACE_RATE,
                    Switch::CompressionRate if kinked => COMPRESSION_RATE_RATE,
                    _ => continue,
                };
                let past = |d: &Dense<DIM>, x: f64| {
                    let y = d.at(x);
                    sign * switch.value(system, &system.local(x, &y), &y) <= 0.0
                };
                let mut found = None;
                if sign * point.rates[i] < 0.0 && sign * rates_1[i] > 0.0 {
                    let d = dense.get_or_insert_with(|| stepper.dense(system));
                    let least = roots::brent_from(
                        |x| {
                            let y = d.at(x);
                            rate_for_root(system, x, &y, &d.derivative_at(x), dx, i)
                        },
                        (point.x, point.rates[i]),
                        (x1, rates_1[i]),
                        rate_root_tolerance(point.x, x1, dx),
                        200,
                    );
                    found = least.map(|least| least.x).filter(|&x| past(d, x));
                }
                // The step that lands on separation: there a slip's direction
                // state has no length (contact::SPRING) and the margin's rate
                // at the end says nothing of the step (box kick 82 of the
                // paper's law: −2.3e11, falling, after a grip of the contact's
                // last 14 ns that neither end's rate showed). The margin itself
                // is read across the step, short of LANDING_SHARE.
                if found.is_none() && landed && switch == Switch::GripSlip {
                    let d = dense.get_or_insert_with(|| stepper.dense(system));
                    let last = x1 - LANDING_SHARE * (x1 - point.x);
                    found = (1..=LANDING_SAMPLES)
                        .map(|j| point.x + (last - point.x) * (j as f64 / LANDING_SAMPLES as f64))
                        .find(|&x| past(d, x));
                }
                let Some(x) = found else { continue };
                crossed_by = x;
            }
            let d = dense.get_or_insert_with(|| stepper.dense(system));
            let x = locate_switch(
                |x| {
                    let y = d.at(x);
                    switch.value(system, &system.local(x, &y), &y)
                },
                sign,
                point.x,
                crossed_by,
            );
            // A slip's direction state (contact::SPRING) shrinks to zero length
            // with δ at separation, where the slider's speed is read from a
            // direction of no length: a slip's end located there, within
            // LANDING_SHARE of the landing step's end, is separation itself. One inside
            // the step is a grip before it (box kick 82 of Hunt and Crossley's
            // exact law grips for the last 34 ns, as the reference finds; a
            // grip's margin, likewise, cannot hold a stretched spring at zero
            // normal force: the shell ball's kick 82 gripped to separation
            // with 0.95 N of tangential force when this step skipped both).
            if landed && switch == Switch::GripSlip && x1 - x <= LANDING_SHARE * (x1 - point.x) {
                continue;
            }
            if switch == Switch::CompressionRate && !kinked {
                // A marker only, applied below unless a switch ends the phase before it.
                marker = Some(x);
                continue;
            }
            if end.is_none_or(|(xe, _)| x < xe) {
                end = Some((x, switch));
            }
        }

        // δ̇ = 0 where the right-hand side does not change: the phase goes on
        // with the other sign expected. Past a switch that ends the phase
        // first, the phase's continuation is not the motion (there δ_max
        // was read off it: 6.5e-8 of δ_max where a slip began within the
        // step); the next phase finds it again.
        if let Some(x) = marker.filter(|&x| end.is_none_or(|(xe, _)| x <= xe)) {
            if self.system.phase.compressing {
                let y = dense.as_ref().map_or(*y1, |d| d.at(x));
                let delta = self.system.local(x, &y).compression;
                if delta > self.max_compression.0 {
                    self.max_compression = (delta, self.system.time(x, &y));
                }
            }
            self.system = self.system.in_phase(Phase { compressing: !self.system.phase.compressing, ..self.system.phase });
        }
        end
    }

    /// The stretch to the phase's end or the accepted point: its end, the
    /// peaks inside it located, the records (energy, history) taken.
    #[inline(always)]
    fn close_stretch(
        &mut self,
        end: Option<(f64, Switch)>,
        (x1, y1, c1, rates_1): (f64, State, Local, Rates),
        dx: f64,
        dense: &mut Option<Dense<DIM>>,
    ) -> Result<Stretch, Kick3dError> {
        let (kick, system, stepper, point) = (self.kick, &self.system, &mut self.stepper, self.point);
        let (x_end, y_end, dy_end, c_end) = match (end, dense.as_ref()) {
            (Some((x, _)), Some(d)) => {
                let y = d.at(x);
                self.extra_evaluations += 1;
                let (dy, c) = system.derivative_and_local(x, &y);
                (x, y, dy, c)
            }
            _ => (x1, y1, *stepper.end_derivative(), c1),
        };
        let t_end = system.time(x_end, &y_end);
        outcome::within_geometry(kick, c_end.compression, t_end)?;
        let rates_end = if x_end == x1 { rates_1 } else { rates(system, x_end, &y_end, &dy_end, dx) };
        for k in 0..2 {
            if point.rates[k] > 0.0 && rates_end[k] <= 0.0 {
                let d = dense.get_or_insert_with(|| stepper.dense(system));
                // The ends' rates are known, their signs trusted (`rates_after_step`).
                let root = roots::brent_from(
                    |x| {
                        let y = d.at(x);
                        rate_for_root(system, x, &y, &d.derivative_at(x), dx, k)
                    },
                    (point.x, point.rates[k]),
                    (x_end, rates_end[k]),
                    rate_root_tolerance(point.x, x_end, dx),
                    200,
                );
                // No sign change between the ends as evaluated on the
                // dense output: the maximum is an end, sampled there.
                if let Some(root) = root {
                    let y = d.at(root.x);
                    self.peaks[k].observe(watched(&system.local(root.x, &y))[k], system.time(root.x, &y));
                }
            }
        }
        let q_end = watched(&c_end);
        for k in 0..2 {
            self.peaks[k].observe(q_end[k], t_end);
        }
        if self.recorder.is_some() {
            let sample = self.energy(x_end, &y_end);
            if let Some(r) = self.recorder.as_deref_mut() {
                r.push(sample);
            }
        }
        // The history's grid times in this stretch, [t(point), t_end), on its phase.
        if let Some(s) = self.sampler.as_deref_mut().filter(|_| SAMPLE) {
            if s.due(t_end, false) {
                let d = match dense.as_ref() {
                    Some(d) => *d,
                    None => {
                        self.history_evaluations += 3;
                        self.stepper.dense(&self.system)
                    }
                };
                let system = &self.system;
                s.fill(t_end, false, |t, _| Ok::<_, Kick3dError>(history::sample_in(kick, system, &d, point.x, x_end, t)))?;
            }
        }
        if t_end > self.horizon {
            return Err(KickError::NoSeparation {
                time: self.horizon,
                reason: format!("3D contact outlasted the horizon of {:.6e} s", self.horizon),
            }
            .into());
        }
        Ok(Stretch { x: x_end, y: y_end, t: t_end, c: c_end, rates: rates_end })
    }

    /// What ends the stretch: the switch located, separation landed on by
    /// the release clock, a change of clock (needing no location: any
    /// accepted point serves), or nothing.
    #[inline(always)]
    fn next(&self, end: Option<(f64, Switch)>, landed: bool, c: &Local) -> Next {
        let phase = self.system.phase;
        let (length, v_n, release_scale) = (self.scales.length, self.v_n, self.release_scale);
        match end {
            Some((_, switch)) => Next::Switch(switch),
            None if landed => Next::Switch(Switch::Separation),
            None => match phase.clock {
                Clock::Onset if c.compression >= ONSET_SHARE * length || c.compression_rate <= CLOCK_RATE * v_n => Next::Clock(Clock::Time),
                Clock::Release { .. } if c.compression_rate >= -CLOCK_RATE * release_scale * v_n => Next::Clock(Clock::Time),
                Clock::Time
                    if self.release
                        && !phase.compressing
                        && c.compression_rate < -2.0 * CLOCK_RATE * release_scale * v_n
                        && c.compression <= RELEASE_SHARE * self.max_compression.0 =>
                {
                    Next::Clock(Clock::Release { start: c.compression.powf(1.0 / f64::from(contact::CLOCK_POWER)) })
                }
                _ => Next::Advance,
            },
        }
    }

    /// On within the phase from the accepted point x1, the slip direction's
    /// tolerance read there ([`slip_direction_widening`]).
    #[inline(always)]
    fn advance(&mut self, c: &Local, x1: f64, rates_end: Rates) {
        let mut widened = self.absolute;
        let factor = slip_direction_widening(&self.system, c, self.scales.time);
        for i in contact::SPRING..contact::SPRING + 3 {
            widened[i] *= factor;
        }
        self.stepper.set_absolute_tolerance(widened);
        self.stepper.advance();
        self.point = Point { x: x1, rates: rates_end };
    }

    /// The phase goes on on `clock` from the accepted point (x1, y1) at
    /// time `t_end`, its next step the same in time.
    #[inline(always)]
    fn change_clock(&mut self, clock: Clock, x1: f64, y1: &State, t_end: f64) {
        let rate_before = self.system.clock_rate(x1, y1);
        let h = self.stepper.next_step() * rate_before;
        self.system = self.system.in_phase(Phase { clock, ..self.system.phase });
        let x = if clock == Clock::Time { t_end } else { 0.0 };
        let rate_after = self.system.clock_rate(x, y1);
        self.stepper.restart(&self.system, x, *y1);
        // Towards separation a slip's direction turns ever faster (at
        // |v_t⊥|/|ξ|, |ξ| = μ F_n/k_t → 0), and the standard control had
        // nearly every step of that tail rejected once, proposing each too
        // large by the same share; the predictive one follows the growing
        // error coefficient. On the release clock only: elsewhere it saved
        // nothing (`examples/sweep3d_cost`, 2000 rows, evaluations per row:
        // flown 885 → 858, leg 1357 → 1335; the box of `count3d`, 200
        // kicks: 541 → 540, and 544 with it on every clock).
        self.stepper.set_predictive(matches!(clock, Clock::Release { .. }));
        self.stepper.set_next_step(0.7 * h / rate_after);
        self.stepper.set_max_step(if let Clock::Release { start } = clock { start } else { self.horizon });
        let dx = self.step_of(clock);
        self.point = Point { x, rates: rates(&self.system, x, y1, self.stepper.start_derivative(), dx) };
    }

    /// A phase ends at `t_end`: its slip time counted.
    #[inline(always)]
    fn end_phase(&mut self, t_end: f64) {
        if self.system.phase.friction == Friction::Slip {
            self.slip_time += t_end - self.phase_start;
        }
    }

    /// A switch of regime (damping, grip/slip, geometry, clamp) at the
    /// stretch's end: the next phase starts there, on the plain tolerance.
    #[inline(always)]
    fn switch_phase(&mut self, switch: Switch, stretch: Stretch, dx: f64) -> Result<(), Kick3dError> {
        let Stretch { x: x_end, y: mut y_end, t: t_end, c: c_end, .. } = stretch;
        let system = &self.system;
        let mut phase = system.phase;
        match switch {
            Switch::Separation => unreachable!("separation ends the run (Run::separate)"),
            Switch::CompressionRate => {
                if phase.compressing && c_end.compression > self.max_compression.0 {
                    self.max_compression = (c_end.compression, t_end);
                }
                phase.compressing = !phase.compressing;
            }
            Switch::GripSlip => {
                if system.rigid && phase.friction == Friction::Grip {
                    // Sliding starts against the force that could no longer hold it.
                    phase.slip_direction = -c_end.tangential_force.normalize_or_zero();
                    phase.slip_start =
                        c_end.sliding_velocity.dot(phase.slip_direction).min(0.0) - 10.0 * self.absolute[contact::RELATIVE_VELOCITY];
                }
                if !system.rigid && phase.friction == Friction::Slip {
                    // Grip starts with the spring on the cap, k_t |ξ| = μ F_n, where the
                    // grip's margin starts from zero with zero slope: put the spring
                    // there, a hair inside (`tangential::GRIP_ENTRY`), so the grip
                    // does not find its own start again.
                    let spring = contact::spring_on_cap(system, &c_end, &y_end);
                    contact::put_spring(&mut y_end, spring);
                } else if !system.rigid {
                    // A slip's state holds the slider's direction only (contact::SPRING).
                    let direction = contact::slip_direction_state(&c_end, &y_end);
                    contact::put_spring(&mut y_end, direction);
                }
                phase.friction = if phase.friction == Friction::Grip { Friction::Slip } else { Friction::Grip };
            }
            Switch::Geometry if system.rigid && phase.geometry == Geometry::Face => {
                return Err(Kick3dError::UnsupportedScene {
                    path: "accurate",
                    reason: "rigid grip (tangential_stiffness = inf) is a constraint on the flat face; the ball reached \
                             the instep's edge or rounded border, where the normal turns under the contact",
                });
            }
            Switch::Geometry => {
                if system.patch.is_some() {
                    return Err(Kick3dError::UnsupportedScene {
                        path: "accurate",
                        reason: "the patch contact left the instep's flat face, and an edge under a patch is not modelled: a smaller \
                                 offset, a convex instep (instep_radius: a cap over the whole face) or the point contact \
                                 (patch_contact = false) keeps the kick on one surface",
                    });
                }
                phase.geometry = if phase.geometry == Geometry::Face { Geometry::Border } else { Geometry::Face };
            }
            Switch::Clamp => phase.clamped = !phase.clamped,
        }
        self.phases += 1;
        if self.phases > MAX_PHASES {
            return Err(KickError::NoSeparation { time: t_end, reason: format!("more than {MAX_PHASES} phases") }.into());
        }
        self.system = self.system.in_phase(phase);
        // The switch is the new phase's first accepted point.
        self.settled = friction_settled(&self.system, &c_end, &y_end);
        self.phase_start = t_end;
        // A new phase starts at the plain tolerance: the spring's slots change meaning.
        self.stepper.set_absolute_tolerance(self.absolute);
        self.stepper.restart(&self.system, x_end, y_end);
        self.point = Point { x: x_end, rates: rates(&self.system, x_end, &y_end, self.stepper.start_derivative(), dx) };
        Ok(())
    }

    /// Separation: both bodies at the stretch's end, and the summary.
    #[inline(always)]
    fn separate(mut self, stretch: &Stretch) -> Result<(Outcome3d, EndState), Kick3dError> {
        let (kick, system) = (self.kick, &self.system);
        let end_state = contact::end_state(kick, system, stretch.x, &stretch.y, stretch.t);
        let peaks =
            Peaks { normal: self.peaks[0], tangential: self.peaks[1], compression: self.max_compression, slip_time: self.slip_time };
        let evaluations = self.stepper.evaluations + self.extra_evaluations - self.history_evaluations;
        let out = outcome::assemble(kick, &end_state, peaks, evaluations, "accurate-3d")?;
        if let Some(s) = self.sampler.as_deref_mut().filter(|_| SAMPLE) {
            s.finish(history::sample(kick, &self.system, stretch.x, &stretch.y, stretch.t, Some(ContactState::Separation)));
        }
        Ok((out, end_state))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::Geometry;

    /// The baseline kick 5 cm off centre, its ball pushed 1 cm into the
    /// face, on a sliding phase: a state with every watched rate nonzero.
    fn pressed() -> (Relative, State) {
        let kick =
            Kick3d::new(kick_core::Scenario::baseline(), &crate::Kick3dSpec { offset: Some(0.05), ..Default::default() }).expect("valid");
        let phase = Phase {
            compressing: true,
            friction: Friction::Slip,
            geometry: Geometry::Face,
            clamped: false,
            clock: Clock::Time,
            slip_direction: parry3d_f64::math::Vec3::ZERO,
            slip_start: 0.0,
        };
        let mut y = contact::initial_state(&kick);
        y[contact::DISPLACEMENT] -= 0.01;
        let system = Relative::new(&kick, phase);
        // A slip's spring state: the slider's direction at the length δ (contact::SPRING).
        let direction = contact::slip_direction_state(&system.local(0.0, &y), &y);
        contact::put_spring(&mut y, direction);
        (system, y)
    }

    /// The AVX2 copy of the run ([`contact::avx2`]) gives the baseline
    /// copy's outcome bit for bit: the rigid sphere under every law, and the
    /// shell ball's point contact and patch on the flat face and on a cap,
    /// gripping (spring and rigid) and slipping. (Skipped where the CPU has
    /// no AVX2: there only the baseline runs.)
    #[test]
    fn the_avx2_copy_is_the_baseline_bit_for_bit() {
        if !contact::avx2() {
            return;
        }
        let mut kicks = Vec::new();
        for law in kick_core::LawKind::ALL {
            let sample = crate::models::OffCenterBox { seed: crate::models::BENCH_SEED, law };
            kicks.extend((0..4).map(|i| sample.kick(i).expect("box kick")));
        }
        let shell = kick_core::Scenario::baseline().with_law(kick_core::LawKind::Shell, None).expect("shell");
        let spec = crate::Kick3dSpec { offset: Some(0.05), ..Default::default() };
        let cap = crate::Kick3dSpec { patch_contact: Some(true), instep_radius: Some(0.15), face_yaw_deg: Some(0.0), ..spec };
        for s in [
            spec,
            crate::Kick3dSpec { patch_contact: Some(true), ..spec },
            crate::Kick3dSpec { patch_contact: Some(true), tangential_stiffness: Some(f64::INFINITY), ..spec },
            cap,
            crate::Kick3dSpec { friction: Some(0.2), ..cap },
            crate::Kick3dSpec { tangential_stiffness: Some(f64::INFINITY), friction: Some(f64::INFINITY), ..cap },
        ] {
            kicks.push(Kick3d::new(shell, &s).expect("valid"));
        }
        let solver = Accurate3d::default();
        for kick in &kicks {
            let baseline = solver.solve_baseline(kick).expect("solves");
            // SAFETY: the CPU has AVX2 (checked above).
            let (wide, _) = unsafe { solver.run_avx2::<false>(kick, None, None) }.expect("solves");
            assert_eq!(format!("{wide:?}"), format!("{baseline:?}"));
        }
    }

    /// A root's rate is the central rate, bit for bit, while its two sides
    /// differ by more than their rounding, and zero once they agree to it:
    /// over steps from 1e-6 s down to 5e-26 s, where the sides differ in
    /// their last places, both happen, and the second where the central rate is not
    /// zero (the noise Brent would otherwise follow).
    #[test]
    fn a_roots_rate_stops_at_the_rounding() {
        let (system, y) = pressed();
        let dy = system.derivative(0.0, &y);
        let (mut above, mut noise) = (0, 0);
        for j in 0..64 {
            let dx = 1e-6 * 0.5f64.powi(j);
            let central = rates(&system, 0.0, &y, &dy, dx);
            for i in 0..2 {
                let (a, b) = sides(&system, 0.0, &y, &dy, dx);
                let (qa, qb) = (a[i], b[i]);
                let root_rate = rate_for_root(&system, 0.0, &y, &dy, dx, i);
                if (qa - qb).abs() > ROUNDING * f64::EPSILON * qa.abs().max(qb.abs()) {
                    assert_eq!(root_rate.to_bits(), central[i].to_bits());
                    above += 1;
                } else {
                    assert_eq!(root_rate, 0.0);
                    noise += usize::from(central[i] != 0.0);
                }
            }
        }
        assert!(above > 0 && noise > 0, "{above} {noise}");
    }

    /// The one-sided rates at a step's end carry the central rates' signs
    /// where they are trusted (off by the difference's truncation, |Q''| dx/2,
    /// which the rule keeps below 1/200 of the rate), and are the central
    /// rates, bit for bit, where a rate swung over the step by so much that
    /// its sign is in doubt.
    #[test]
    fn one_sided_rates_keep_the_signs_or_defer() {
        let (system, y) = pressed();
        let (dy, c) = system.derivative_and_local(0.0, &y);
        let (dx, step) = (2e-8, 1e-4);
        let central = rates(&system, 0.0, &y, &dy, dx);
        assert!(central.iter().take(3).all(|r| r.abs() > 0.0), "{central:?}");
        let calm = rates_after_step(&system, 0.0, &y, &dy, dx, &c, -step, &central);
        for (one, two) in calm.iter().zip(&central) {
            assert!(one.signum() == two.signum() && (one - two).abs() <= two.abs() / 200.0, "{calm:?} vs {central:?}");
        }
        assert_ne!(calm, central, "the one-sided difference is its own");
        let swung = central.map(|r| r - 1e12 * r.abs().max(1.0));
        assert_eq!(rates_after_step(&system, 0.0, &y, &dy, dx, &c, -step, &swung), central);
    }
}
