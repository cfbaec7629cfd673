//! The ball's flight after the kick: gravity, drag with the drag crisis,
//! Magnus lift and (optionally) spin decay, from the launch state a kick
//! gives to the landing on flat ground.
//!
//! Frame as in kick-3d: x horizontal along the kick, y lateral, z up. The
//! ball's centre starts at (0, 0, R) on the ground and lands when it comes
//! back down to z = R. State: position r, velocity v, spin ω.
//!
//! - gravity (0, 0, −g);
//! - drag −½ ρ A C_D(Re, S) |v| v, Re = ρ |v| 2R/μ, A = π R²: the drag
//!   crisis of Goff & Carré (2010) Eq. 3 (moved to the ball construction's
//!   critical Re, `ball_panels`), joined smoothly above the crisis to their
//!   Eq. 4 for a spinning ball ([`coefficients::SpinDrag`]);
//! - Magnus lift ½ ρ A C_L(S) |v|² (ω × v)/|ω × v|, zero when ω × v = 0,
//!   with S = R |ω × v|/|v|², the spin parameter R|ω|/|v| of the spin
//!   component across the flight direction (the only one that lifts);
//! - spin decay by an aerodynamic torque −½ ρ A R² k_M |v| ω (moment
//!   coefficient C_M = k_M S, the form of Smits & Smith's (1994) golf-ball
//!   spin-decay law), on a thin-shell ball I = ⅔ m R²: dω/dt = −(3 ρ A k_M/(4 m)) |v| ω.
//!   Off (k_M = 0) by default: the default coefficients come from trajectory
//!   and wind-tunnel analyses that hold the spin constant.
//!
//! Coefficient models: [`coefficients`]; every number's source and how far
//! it was checked: `SOURCES.md` beside `Cargo.toml`.
//!
//! Numerics: Dormand–Prince 8(5,3) ([`dop853`]) at a relative tolerance of
//! [`DEFAULT_RELATIVE_TOLERANCE`] (absolute tolerances: that times R, |v0|
//! and |ω0|); landing, apex and the crossing of a plane x = d are located by
//! Brent's method on the step's 7th-order dense output, which is formed only
//! for the steps that hold an event, so `solve` allocates nothing.
//!
//! Accuracy (held by `tests/flight/closed_forms.rs`): flight time, apex height,
//! landing point and crossing are within 1e-9 relative of closed forms
//! (vacuum parabola; vertical flight with quadratic drag; spin decay along a
//! vacuum parabola) and of a solve at a 100× tighter tolerance, over kicks of
//! 3–40 m/s at 3–85° with spins up to 80 rad/s per axis (64 random kicks in
//! the test; `examples/accuracy.rs` found 3.3e-10 at worst over 20000 with
//! the spinning ball's drag, 1.5e-10 before it). The
//! landing point is measured against the flight's size (range, or apex
//! height for a steep kick landing near its start), the crossing point
//! against its distance from the launch point: a ball dropping steeply
//! through the plane has an ill-conditioned crossing height.
//!
//! The inverse problem, the launch that clears a wall and crosses the goal
//! plane at a target (`kick aim`): [`aim`].
//!
//! A flight that has not landed after [`HORIZON_FACTOR`] × 2|v0|/g (or the
//! horizon set by [`Flight::with_horizon`]) is refused.

pub mod aim;
pub mod air;
pub mod coefficients;
/// The integrator lives in kick-core (kick-3d steps with it too).
pub use kick_core::dop853;
pub mod many;
pub mod models;
pub mod solve;
pub mod spec;
pub mod validation;

pub use aim::{
    aim_best, aim_launch, aim_launch_cancellable, aim_launch_with, aim_with, AimError, AimSolution, Family, LaunchFree, Objective, Scene,
    Wall, WallPass,
};
pub use air::Air;
pub use coefficients::{DragModel, LiftModel};
pub use many::{flight_many, Column};
pub use solve::{
    check_planes, history, outcome_columns, plane_columns, plane_values, solve, solve_planes, Aerodynamics, Crossing, FlightHistory,
    FlightOutcome, FlightSample, Sampling, LANDING_COLUMNS, MAX_PLANES, OUTCOME_COLUMNS,
};
pub use spec::{Flight, FlightParameter, FlightSpec, FLIGHT_PARAMETERS, MAX_LAUNCH_SPEED};

use kick_core::short;
use thiserror::Error;

/// Default relative tolerance of the integrator (see the crate docs).
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-12;
/// A flight still in the air after this many vacuum flight times of a
/// vertical launch at the same speed (2|v0|/g) is refused as not landing.
pub const HORIZON_FACTOR: f64 = 100.0;
/// Bound on accepted steps of one flight.
pub const MAX_STEPS: u64 = 1_000_000;
/// Bound on the samples of one history: the one bound of every history
/// (1D, 3D, flight, Python), [`kick_core::MAX_HISTORY_SAMPLES`].
pub const MAX_SAMPLES: usize = kick_core::MAX_HISTORY_SAMPLES;

/// Every way a flight computation can refuse or fail; messages name the parameter.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum FlightError {
    #[error("invalid parameter `{name}` = {}: must be {requirement}", kick_core::number::given(*.value))]
    InvalidParameter { name: &'static str, value: f64, requirement: &'static str },
    #[error("parameter `{name}` is required")]
    Missing { name: &'static str },
    /// Valid parameters whose flight leaves double precision's working range
    /// (kick-core's `SCALE_RANGE`, as a 1D contact's scales are checked).
    #[error(
        "parameters out of range: the {quantity} is {} {unit}, outside 1e-100 .. 1e100; change {parameters}",
        short(*.value)
    )]
    OutOfRange { quantity: &'static str, value: f64, unit: &'static str, parameters: &'static str },
    #[error("parameter `{name}` takes {expected} numbers, got {found}")]
    WrongLength { name: &'static str, expected: usize, found: usize },
    #[error("parameter `{name}` takes at most {most} numbers, got {found}")]
    TooMany { name: &'static str, most: usize, found: usize },
    #[error("unknown flight parameter `{name}`: expected one of {expected}")]
    UnknownParameter { name: String, expected: String },
    #[error("`{first}` and `{second}` cannot both be given")]
    Conflict { first: &'static str, second: &'static str },
    #[error("the ball has not landed within the horizon of {} s (last height of its centre {} m)", short(*.horizon), short(*.height))]
    NoLanding { horizon: f64, height: f64 },
    #[error("integration failed at t = {} s: {reason} (a numerical failure, not physics)", short(*.time))]
    Integration { time: f64, reason: &'static str },
    #[error("non-finite {quantity} at t = {} s", short(*.time))]
    NonFinite { quantity: &'static str, time: f64 },
    #[error("`{name}` asks for {} samples, more than the limit {limit}", short(*.requested))]
    TooManySamples { name: &'static str, requested: f64, limit: usize },
    #[error(
        "`threads` = {requested}: must be between 1 and {max}, the most this machine can use \
         ({} per core x its {cores} cores, never above {})",
        kick_core::threads::THREADS_PER_CORE,
        kick_core::threads::MAX_THREADS
    )]
    TooManyThreads { requested: usize, max: usize, cores: usize },
}
