//! One flight: equations of motion, the event loop, the outcome and the history.

use crate::coefficients::{DragLaw, LiftModel, SaturatingLift};
use crate::dop853::{Dense, StepFailure, Stepper, System};
use crate::{Flight, FlightError, MAX_SAMPLES, MAX_STEPS};
use kick_core::roots::brent;
use nalgebra::{SVector, Vector3};
use serde::Serialize;

/// r, v, ω; the third coordinate is the height above the landing height,
/// h = z − R (integrated as such: near z = R a tiny flight's height is
/// below the rounding of z, and its flight time came out halved).
type State = SVector<f64, 9>;
const X: usize = 0;
const Y: usize = 1;
const Z: usize = 2;
const VZ: usize = 5;

/// Where the ball crosses the vertical plane x = d.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Crossing {
    /// d, m.
    pub distance: f64,
    /// s after launch.
    pub time: f64,
    /// Height of the ball's centre above the ground, m.
    pub height: f64,
    /// y of the centre, m.
    pub lateral_offset: f64,
    /// m/s.
    pub velocity: [f64; 3],
}

/// Summary of one flight, SI units, world frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlightOutcome {
    /// From launch to landing (centre back at z = R), s.
    pub flight_time: f64,
    /// (x, y) of the centre at landing, m.
    pub landing_point: [f64; 2],
    /// Greatest height of the centre above the ground, m.
    pub apex_height: f64,
    /// When the apex is reached, s.
    pub apex_time: f64,
    /// m/s.
    pub landing_velocity: [f64; 3],
    /// rad/s.
    pub landing_spin: [f64; 3],
    /// At x = d when a distance is given and the ball gets there before landing.
    pub crossing: Option<Crossing>,
    /// Reynolds number, spin parameter and coefficients at launch.
    pub launch: Aerodynamics,
    /// Accepted integrator steps.
    pub steps: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
}

/// Outcome columns of a flight in a result table (name, unit), the flight's
/// own: the landing and apex, then, when a crossing plane is given, `crossed`
/// (1 when the ball reaches x = d before landing, 0 when it lands first; the
/// crossing columns are then NaN) and the crossing's time, height, lateral
/// position and velocity. Vectors as `_x`, `_y`, `_z`, as every result table.
pub const OUTCOME_COLUMNS: [(&str, &str); 18] = [
    ("flight_time", "s"),
    ("landing_point_x", "m"),
    ("landing_point_y", "m"),
    ("apex_height", "m"),
    ("apex_time", "s"),
    ("landing_velocity_x", "m/s"),
    ("landing_velocity_y", "m/s"),
    ("landing_velocity_z", "m/s"),
    ("landing_spin_x", "rad/s"),
    ("landing_spin_y", "rad/s"),
    ("landing_spin_z", "rad/s"),
    ("crossed", "1"),
    ("crossing_time", "s"),
    ("crossing_height", "m"),
    ("crossing_lateral_offset", "m"),
    ("crossing_velocity_x", "m/s"),
    ("crossing_velocity_y", "m/s"),
    ("crossing_velocity_z", "m/s"),
];

/// The columns of [`OUTCOME_COLUMNS`] a flight has: all with a crossing plane,
/// the landing and apex only without.
pub fn outcome_columns(crossing: bool) -> &'static [(&'static str, &'static str)] {
    if crossing {
        &OUTCOME_COLUMNS
    } else {
        &OUTCOME_COLUMNS[..11]
    }
}

/// The landing and apex columns of [`OUTCOME_COLUMNS`] (the first 11).
pub const LANDING_COLUMNS: usize = 11;

/// Outcome columns of a flight crossing several planes ([`solve_planes`]):
/// the landing and apex columns of [`OUTCOME_COLUMNS`], then for plane k
/// its crossing columns with the suffix `_k` (`crossed_0`,
/// `crossing_height_0`, ..., `crossed_1`, ...), in [`plane_values`]' order.
pub fn plane_columns(planes: usize) -> Vec<(String, &'static str)> {
    let mut columns: Vec<(String, &'static str)> = OUTCOME_COLUMNS[..LANDING_COLUMNS].iter().map(|(n, u)| (n.to_string(), *u)).collect();
    for k in 0..planes {
        columns.extend(OUTCOME_COLUMNS[LANDING_COLUMNS..].iter().map(|(n, u)| (format!("{n}_{k}"), *u)));
    }
    columns
}

/// The values of [`plane_columns`] into `out` (at least as long): the
/// outcome's landing and apex, then each plane's crossing (`crossed` 0 and
/// NaN where the ball lands first); how many were written. No allocation.
pub fn plane_values(outcome: &FlightOutcome, crossings: &[Option<Crossing>], out: &mut [f64]) -> usize {
    let values = outcome.values();
    out[..LANDING_COLUMNS].copy_from_slice(&values[..LANDING_COLUMNS]);
    let width = OUTCOME_COLUMNS.len() - LANDING_COLUMNS;
    for (k, c) in crossings.iter().enumerate() {
        let at = LANDING_COLUMNS + k * width;
        out[at..at + width].copy_from_slice(&crossing_values(c.as_ref()));
    }
    LANDING_COLUMNS + crossings.len() * width
}

/// The crossing columns of [`OUTCOME_COLUMNS`] for one plane.
fn crossing_values(c: Option<&Crossing>) -> [f64; 7] {
    match c {
        Some(c) => [1.0, c.time, c.height, c.lateral_offset, c.velocity[0], c.velocity[1], c.velocity[2]],
        None => [0.0, f64::NAN, f64::NAN, f64::NAN, f64::NAN, f64::NAN, f64::NAN],
    }
}

impl FlightOutcome {
    /// The values of [`OUTCOME_COLUMNS`], in order; a flight without a
    /// crossing has `crossed` 0 and NaN crossing columns.
    pub fn values(&self) -> [f64; OUTCOME_COLUMNS.len()] {
        let [crossed, time, height, lateral, vx, vy, vz] = crossing_values(self.crossing.as_ref());
        [
            self.flight_time,
            self.landing_point[0],
            self.landing_point[1],
            self.apex_height,
            self.apex_time,
            self.landing_velocity[0],
            self.landing_velocity[1],
            self.landing_velocity[2],
            self.landing_spin[0],
            self.landing_spin[1],
            self.landing_spin[2],
            crossed,
            time,
            height,
            lateral,
            vx,
            vy,
            vz,
        ]
    }
}

/// The air's numbers at one state of the ball.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Aerodynamics {
    /// Re = ρ |v| 2R/μ.
    pub reynolds: f64,
    /// S = R |ω × v|/|v|².
    pub spin_parameter: f64,
    /// C_D at Re and S.
    pub drag_coefficient: f64,
    /// C_L at S.
    pub lift_coefficient: f64,
}

/// One point of a flight's history.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlightSample {
    pub time: f64,
    pub position: [f64; 3],
    pub velocity: [f64; 3],
    pub spin: [f64; 3],
}

/// How a history is sampled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sampling {
    /// n ≥ 2 samples at t = T i/(n − 1), i = 0..n−1 (T the flight time: both ends included).
    Samples(usize),
    /// t = k Δt for k Δt < T, then the landing at T.
    Interval(f64),
}

/// A flight's outcome and its uniformly spaced samples.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlightHistory {
    pub outcome: FlightOutcome,
    pub samples: Vec<FlightSample>,
}

/// The equations of motion of one flight.
#[derive(Debug, Clone, Copy)]
struct Dynamics {
    gravity: f64,
    /// ρ A/(2 m), 1/m.
    aero: f64,
    drag: DragLaw,
    lift: LiftModel,
    radius_squared: f64,
    /// 3 ρ A k_M/(4 m), 1/m: dω/dt = −decay |v| ω.
    decay: f64,
    /// ρ 2R/μ, s/m.
    reynolds_per_speed: f64,
}

impl Dynamics {
    fn new(flight: &Flight) -> Dynamics {
        let air = flight.air();
        let m = flight.ball_mass();
        let area = flight.area();
        let reynolds_per_speed = air.density * 2.0 * flight.ball_radius() / air.viscosity;
        Dynamics {
            gravity: flight.gravity(),
            aero: air.density * area / (2.0 * m),
            drag: DragLaw::new(flight.drag(), reynolds_per_speed),
            lift: flight.lift(),
            radius_squared: flight.ball_radius().powi(2),
            decay: 3.0 * air.density * area * flight.spin_decay() / (4.0 * m),
            reynolds_per_speed,
        }
    }

    /// S² = R²|ω × v|²/|v|⁴ (0 without lift: ω × v = 0) and ω × v, |ω × v|².
    #[inline]
    fn spin_parameter_squared(&self, v: &Vector3<f64>, w: &Vector3<f64>, v2: f64) -> (f64, Vector3<f64>, f64) {
        let c = w.cross(v);
        let c2 = c.norm_squared();
        let s2 = if c2 > 0.0 { self.radius_squared * c2 / (v2 * v2) } else { 0.0 };
        (s2, c, c2)
    }

    #[inline]
    fn lift_coefficient(&self, s2: f64) -> f64 {
        match self.lift {
            LiftModel::Constant { value } => value,
            LiftModel::Saturating => SaturatingLift::of_square(s2),
        }
    }

    /// Re, S, C_D and C_L of a ball moving at `v` and spinning at `w`.
    fn aerodynamics(&self, v: [f64; 3], w: [f64; 3]) -> Aerodynamics {
        let (v, w) = (Vector3::from(v), Vector3::from(w));
        let v2 = v.norm_squared();
        let (s2, _, c2) = self.spin_parameter_squared(&v, &w, v2);
        let speed = v2.sqrt();
        Aerodynamics {
            reynolds: self.reynolds_per_speed * speed,
            spin_parameter: s2.sqrt(),
            drag_coefficient: self.drag.at(speed, s2),
            lift_coefficient: if c2 > 0.0 { self.lift_coefficient(s2) } else { 0.0 },
        }
    }
}

/// Refuse a flight whose scales leave double precision's working range
/// (kick-core's `SCALE_RANGE`), naming the parameters each comes from: a
/// launch at 1e300 m/s or a spin of 1e300 rad/s failed at t = 0 as a
/// numerical failure, or (the spin's drag through C_D(S)) landed within
/// nanoseconds. Each scale at launch: the speed, the spin's surface speed,
/// the ball, gravity and the time it sets, the air's drag and lift.
pub(crate) fn check_scales(flight: &Flight) -> Result<(), FlightError> {
    const AIR: &str = "air_density, temperature, pressure, altitude, drag_coefficient, ball_panels, speed, ball_radius, ball_mass";
    let (v, w) = (flight.launch_velocity(), flight.spin());
    // Lengths by hypot: a spin of 1e300 per axis is said as the length it has, not inf.
    let length = |a: [f64; 3]| a[0].hypot(a[1]).hypot(a[2]);
    let speed = length(v);
    let dynamics = Dynamics::new(flight);
    let a = dynamics.aerodynamics(v, w);
    let per_speed_squared = dynamics.aero * speed * speed;
    // (quantity, value, unit, from which parameters, whether it may be 0)
    let scales = [
        ("launch speed", speed, "m/s", "speed, launch_velocity", false),
        ("spin's surface speed R|ω|", flight.ball_radius() * length(w), "m/s", "spin, ball_radius", true),
        ("ball mass", flight.ball_mass(), "kg", "ball_mass", false),
        ("ball radius", flight.ball_radius(), "m", "ball_radius", false),
        ("gravity", flight.gravity(), "m/s²", "gravity", false),
        ("rise time |v0|/g", speed / flight.gravity(), "s", "speed, launch_velocity, gravity", false),
        ("drag's acceleration at launch", per_speed_squared * a.drag_coefficient, "m/s²", AIR, true),
        ("lift's acceleration at launch", per_speed_squared * a.lift_coefficient, "m/s²", "lift_coefficient, spin, air_density", true),
    ];
    let (low, high) = kick_core::scenario::SCALE_RANGE;
    for (quantity, value, unit, parameters, may_be_zero) in scales {
        if !((low..=high).contains(&value) || (may_be_zero && value == 0.0)) {
            return Err(FlightError::OutOfRange { quantity, value, unit, parameters });
        }
    }
    Ok(())
}

impl System<9> for Dynamics {
    #[inline]
    fn derivative(&self, _t: f64, y: &State) -> State {
        let v = Vector3::new(y[3], y[4], y[5]);
        let w = Vector3::new(y[6], y[7], y[8]);
        let v2 = v.norm_squared();
        let speed = v2.sqrt();
        // S = R|ω×v|/|v|², for drag and lift.
        let (s2, c, c2) = self.spin_parameter_squared(&v, &w, v2);
        // Drag (−½ρA C_D |v| v)/m and gravity.
        let mut a = v * (-self.aero * self.drag.at(speed, s2) * speed);
        a.z -= self.gravity;
        // Magnus lift ½ρA C_L |v|² (ω×v)/|ω×v| / m.
        if c2 > 0.0 {
            a += c * (self.aero * self.lift_coefficient(s2) * v2 / c2.sqrt());
        }
        let dw = w * (-self.decay * speed);
        State::from_column_slice(&[v.x, v.y, v.z, a.x, a.y, a.z, dw.x, dw.y, dw.z])
    }
}

/// Root of `f` in [lo, hi] where f(lo) and f(hi) should differ in sign; on
/// the dense output the end values may differ from the step's by rounding, so
/// without a sign change the end nearer zero is the root.
fn locate(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let tol = 4.0 * f64::EPSILON * hi.abs().max(lo.abs());
    match brent(&f, lo, hi, tol, 200) {
        Some(root) => root.x,
        None => {
            if f(lo).abs() < f(hi).abs() {
                lo
            } else {
                hi
            }
        }
    }
}

fn vector(y: &State, first: usize) -> [f64; 3] {
    [y[first], y[first + 1], y[first + 2]]
}

fn finite(quantity: &'static str, values: &[f64], time: f64) -> Result<(), FlightError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(FlightError::NonFinite { quantity, time })
    }
}

/// Sees every step's dense output and the end of its part of the flight
/// (the landing in the last step).
type StepObserver<'a> = Option<&'a mut dyn FnMut(&Dense<9>, f64)>;

/// Most crossing planes one flight locates besides its `distance` ([`solve_planes`]).
pub const MAX_PLANES: usize = 16;

/// Integrate to the landing; `planes` are further crossing planes, located
/// into `crossings` (as many), in the same steps.
fn run(
    flight: &Flight,
    planes: &[f64],
    crossings: &mut [Option<Crossing>],
    mut on_step: StepObserver,
) -> Result<FlightOutcome, FlightError> {
    let dynamics = Dynamics::new(flight);
    let radius = flight.ball_radius();
    let v0 = flight.launch_velocity();
    let w0 = flight.spin();
    let y0 = State::from_column_slice(&[0.0, 0.0, 0.0, v0[0], v0[1], v0[2], w0[0], w0[1], w0[2]]);
    // Units of the absolute tolerance: lengths in R, speeds in |v0|, spins
    // in |ω0| (|v0|/R without spin, which then stays zero).
    let speed = flight.speed();
    let length = radius;
    let spin = (w0[0] * w0[0] + w0[1] * w0[1] + w0[2] * w0[2]).sqrt();
    let spin = if spin > 0.0 { spin } else { speed / radius };
    let rtol = flight.relative_tolerance();
    let atol = State::from_column_slice(&[length, length, length, speed, speed, speed, spin, spin, spin]) * rtol;
    let horizon = flight.horizon();
    let mut stepper = Stepper::new(&dynamics, 0.0, y0, rtol, atol, horizon);

    let mut apex: Option<(f64, f64)> = None;
    let mut crossing: Option<Crossing> = None;
    loop {
        stepper.step(&dynamics).map_err(|failure| match failure {
            StepFailure::StepSizeUnderflow { time } => FlightError::Integration { time, reason: "step size underflow" },
            StepFailure::Rejections { time } => {
                FlightError::Integration { time, reason: "every step size tried was rejected (non-finite trial states)" }
            }
        })?;
        let (t0, _, start) = stepper.last_step();
        let (start, end, t1) = (*start, *stepper.state(), stepper.time());
        let apex_here = start[VZ] > 0.0 && end[VZ] <= 0.0;
        // At launch h = 0 exactly: the first step lands only past an apex.
        let lands_here = end[Z] <= 0.0 && (start[Z] > 0.0 || apex_here);
        let crosses_here = match (flight.distance(), crossing) {
            (Some(d), None) => start[X] < d && end[X] >= d,
            _ => false,
        };
        let crosses_plane = |k: usize| crossings[k].is_none() && start[X] < planes[k] && end[X] >= planes[k];
        let planes_here = (0..planes.len()).any(crosses_plane);
        if apex_here || lands_here || crosses_here || planes_here || on_step.is_some() {
            let dense = stepper.dense(&dynamics);
            let mut t_apex = t0;
            if apex_here {
                t_apex = locate(|t| dense.component(VZ, t), t0, t1);
                let z = radius + dense.component(Z, t_apex);
                if apex.is_none_or(|(_, best)| z > best) {
                    apex = Some((t_apex, z));
                }
            }
            let t_land = if lands_here {
                let lo = if start[Z] > 0.0 { t0 } else { t_apex };
                Some(locate(|t| dense.component(Z, t), lo, t1))
            } else {
                None
            };
            if crosses_here {
                let d = flight.distance().unwrap_or(f64::INFINITY);
                let t_cross = locate(|t| dense.component(X, t) - d, t0, t1);
                if t_land.is_none_or(|t| t_cross <= t) {
                    let s = dense.at(t_cross);
                    crossing =
                        Some(Crossing { distance: d, time: t_cross, height: radius + s[Z], lateral_offset: s[Y], velocity: vector(&s, 3) });
                }
            }
            if planes_here {
                for k in 0..planes.len() {
                    if crossings[k].is_none() && start[X] < planes[k] && end[X] >= planes[k] {
                        let d = planes[k];
                        let t_cross = locate(|t| dense.component(X, t) - d, t0, t1);
                        if t_land.is_none_or(|t| t_cross <= t) {
                            let s = dense.at(t_cross);
                            let c = Crossing {
                                distance: d,
                                time: t_cross,
                                height: radius + s[Z],
                                lateral_offset: s[Y],
                                velocity: vector(&s, 3),
                            };
                            finite("crossing", &[c.time, c.height, c.lateral_offset], c.time)?;
                            finite("crossing velocity", &c.velocity, c.time)?;
                            crossings[k] = Some(c);
                        }
                    }
                }
            }
            if let Some(callback) = on_step.as_deref_mut() {
                callback(&dense, t_land.unwrap_or(t1));
            }
            if let Some(t) = t_land {
                if t > horizon {
                    return Err(FlightError::NoLanding { horizon, height: radius + dense.component(Z, horizon) });
                }
                let s = dense.at(t);
                let (apex_time, apex_height) = apex.unwrap_or((t0, radius + start[Z]));
                let outcome = FlightOutcome {
                    flight_time: t,
                    landing_point: [s[X], s[Y]],
                    apex_height,
                    apex_time,
                    landing_velocity: vector(&s, 3),
                    landing_spin: vector(&s, 6),
                    crossing,
                    launch: dynamics.aerodynamics(v0, w0),
                    steps: stepper.accepted,
                    evaluations: stepper.evaluations,
                };
                finite("landing state", s.as_slice(), t)?;
                finite("apex", &[apex_time, apex_height], t)?;
                if let Some(c) = crossing {
                    finite("crossing", &[c.time, c.height, c.lateral_offset], c.time)?;
                    finite("crossing velocity", &c.velocity, c.time)?;
                }
                return Ok(outcome);
            }
        }
        stepper.advance();
        if t1 >= horizon {
            return Err(FlightError::NoLanding { horizon, height: radius + end[Z] });
        }
        if stepper.accepted >= MAX_STEPS {
            return Err(FlightError::Integration { time: t1, reason: "more steps than kick_flight::MAX_STEPS" });
        }
    }
}

/// Solve one flight to its landing (no allocation).
pub fn solve(flight: &Flight) -> Result<FlightOutcome, FlightError> {
    run(flight, &[], &mut [], None)
}

/// Solve one flight and locate where it crosses each plane x = `planes[k]`
/// (at most [`MAX_PLANES`], each finite and > 0) into `crossings[k]`: None
/// where the ball lands first. The flight's own `distance` gives the
/// outcome's `crossing` as in [`solve`], and the steps are [`solve`]'s, so
/// the outcome and each crossing are the ones a flight with that one
/// distance gives, to the bit. No allocation.
pub fn solve_planes(flight: &Flight, planes: &[f64], crossings: &mut [Option<Crossing>]) -> Result<FlightOutcome, FlightError> {
    check_planes(planes)?;
    if crossings.len() != planes.len() {
        return Err(FlightError::WrongLength { name: "distance", expected: planes.len(), found: crossings.len() });
    }
    crossings.fill(None);
    run(flight, planes, crossings, None)
}

/// The planes of [`solve_planes`]: at most [`MAX_PLANES`], each finite and > 0.
pub fn check_planes(planes: &[f64]) -> Result<(), FlightError> {
    if planes.len() > MAX_PLANES {
        return Err(FlightError::TooMany { name: "distance", most: MAX_PLANES, found: planes.len() });
    }
    if planes.is_empty() {
        return Err(FlightError::InvalidParameter {
            name: "distances",
            value: 0.0,
            requirement: "at least one plane (leave it out for none)",
        });
    }
    if let Some(&d) = planes.iter().find(|&&d| !(d.is_finite() && d > 0.0)) {
        return Err(FlightError::InvalidParameter { name: "distance", value: d, requirement: "finite and > 0, m" });
    }
    // A plane given twice would be two columns of one crossing.
    match planes.iter().enumerate().find(|(i, d)| planes[..*i].contains(d)) {
        Some((_, &d)) => {
            Err(FlightError::InvalidParameter { name: "distance", value: d, requirement: "each plane once (this one is given twice)" })
        }
        None => Ok(()),
    }
}

/// The flight's samples at uniform times: the same steps as [`solve`], read
/// from each step's dense output, so outcome and last sample are [`solve`]'s
/// to the bit.
pub fn history(flight: &Flight, sampling: Sampling) -> Result<FlightHistory, FlightError> {
    let outcome = solve(flight)?;
    let flight_time = outcome.flight_time;
    let times: Vec<f64> = match sampling {
        Sampling::Samples(n) => {
            if n < 2 {
                return Err(FlightError::InvalidParameter { name: "samples", value: n as f64, requirement: ">= 2 (both ends)" });
            }
            if n > MAX_SAMPLES {
                return Err(FlightError::TooManySamples { name: "samples", requested: n as f64, limit: MAX_SAMPLES });
            }
            (0..n).map(|i| if i + 1 == n { flight_time } else { flight_time * i as f64 / (n - 1) as f64 }).collect()
        }
        Sampling::Interval(dt) => {
            if !(dt.is_finite() && dt > 0.0) {
                return Err(FlightError::InvalidParameter { name: "interval", value: dt, requirement: "finite and > 0, s" });
            }
            let count = (flight_time / dt).ceil() + 1.0;
            if count > MAX_SAMPLES as f64 {
                return Err(FlightError::TooManySamples { name: "interval", requested: count, limit: MAX_SAMPLES });
            }
            let mut times: Vec<f64> = (0..count as usize).map(|k| k as f64 * dt).take_while(|&t| t < flight_time).collect();
            times.push(flight_time);
            times
        }
    };
    let v0 = flight.launch_velocity();
    let radius = flight.ball_radius();
    let start = FlightSample { time: 0.0, position: [0.0, 0.0, radius], velocity: v0, spin: flight.spin() };
    let mut samples = Vec::with_capacity(times.len());
    let mut next = 0;
    while next < times.len() && times[next] == 0.0 {
        samples.push(start);
        next += 1;
    }
    let mut record = |dense: &Dense<9>, until: f64| {
        while next < times.len() && times[next] <= until {
            let t = times[next];
            let s = dense.at(t);
            let [x, y, h] = vector(&s, 0);
            samples.push(FlightSample { time: t, position: [x, y, radius + h], velocity: vector(&s, 3), spin: vector(&s, 6) });
            next += 1;
        }
    };
    let again = run(flight, &[], &mut [], Some(&mut record))?;
    // Same steps; only the dense outputs of the steps without events add evaluations.
    debug_assert_eq!(FlightOutcome { evaluations: outcome.evaluations, ..again }, outcome);
    Ok(FlightHistory { outcome, samples })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{models, FlightSpec};

    #[test]
    fn history_samples_are_uniform_and_end_at_the_landing() {
        let flight = models::free_kick();
        let outcome = solve(&flight).unwrap();
        let h = history(&flight, Sampling::Samples(50)).unwrap();
        assert_eq!(h.outcome, outcome);
        assert_eq!(h.samples.len(), 50);
        let first = h.samples[0];
        assert_eq!(first.position, [0.0, 0.0, flight.ball_radius()]);
        assert_eq!(first.velocity, flight.launch_velocity());
        let last = h.samples[49];
        assert_eq!(last.time, outcome.flight_time);
        assert_eq!([last.position[0], last.position[1]], outcome.landing_point);
        assert_eq!(last.velocity, outcome.landing_velocity);
        let dt = outcome.flight_time / 49.0;
        for (i, s) in h.samples.iter().enumerate() {
            assert!((s.time - i as f64 * dt).abs() <= 1e-15 * outcome.flight_time);
        }
        // In flight the centre stays above the ground.
        assert!(h.samples[1..49].iter().all(|s| s.position[2] > flight.ball_radius()));
    }

    #[test]
    fn interval_history_and_vacuum_positions() {
        let spec = FlightSpec { drag_coefficient: Some(0.0), lift_coefficient: Some(0.0), ..FlightSpec::from_exit_speed(20.0, 40.0) };
        let flight = spec.build().unwrap();
        let h = history(&flight, Sampling::Interval(0.1)).unwrap();
        let t_end = h.outcome.flight_time;
        assert_eq!(h.samples.len(), (t_end / 0.1).ceil() as usize + 1);
        let [u, _, w] = flight.launch_velocity();
        for (k, s) in h.samples.iter().enumerate() {
            let t = if k + 1 == h.samples.len() { t_end } else { k as f64 * 0.1 };
            assert_eq!(s.time, t);
            let (x, z) = (u * t, flight.ball_radius() + w * t - 0.5 * flight.gravity() * t * t);
            assert!((s.position[0] - x).abs() <= 1e-9 * 40.0, "x at {t}");
            assert!((s.position[2] - z).abs() <= 1e-9 * 40.0, "z at {t}");
        }
    }

    /// Fault 6 of issue 33: in vacuum the flight time is 2 v sin θ / g and
    /// the ball lands at −v sin θ, down to speeds whose height (2.5e-20 m at
    /// 1e-9 m/s) is far below the rounding of z = R (1.4e-17 m): the height
    /// is integrated as h = z − R. Before, every speed below 1e-8 m/s gave
    /// half the flight time and a landing at v_z = 0.
    #[test]
    fn a_vacuum_flight_takes_its_closed_form_time_at_any_speed() {
        for speed in [1e-9, 3e-9, 1e-8, 1e-6, 1e-3, 0.1, 5.0, 30.0] {
            for angle in [45.0, 10.0, 80.0] {
                let spec =
                    FlightSpec { drag_coefficient: Some(0.0), lift_coefficient: Some(0.0), ..FlightSpec::from_exit_speed(speed, angle) };
                let flight = spec.build().unwrap();
                let vz = flight.launch_velocity()[2];
                let g = flight.gravity();
                let o = solve(&flight).unwrap();
                let time = 2.0 * vz / g;
                assert!((o.flight_time / time - 1.0).abs() < 1e-9, "{speed} m/s at {angle}°: {} s vs {time} s", o.flight_time);
                assert!((o.landing_velocity[2] / -vz - 1.0).abs() < 1e-9, "{speed} m/s at {angle}°: v_z {}", o.landing_velocity[2]);
                assert!((o.apex_time / (0.5 * time) - 1.0).abs() < 1e-9, "{speed} m/s at {angle}°: apex at {} s", o.apex_time);
                let apex = vz * vz / (2.0 * g);
                let radius = flight.ball_radius();
                assert!((o.apex_height - radius - apex).abs() <= 1e-9 * apex + 2.0 * f64::EPSILON * radius, "{speed}: {}", o.apex_height);
            }
        }
    }

    #[test]
    fn bad_sampling_is_refused_by_name() {
        let flight = models::plain_kick();
        assert!(matches!(history(&flight, Sampling::Samples(1)), Err(FlightError::InvalidParameter { name: "samples", .. })));
        assert!(matches!(history(&flight, Sampling::Interval(0.0)), Err(FlightError::InvalidParameter { name: "interval", .. })));
        assert!(matches!(history(&flight, Sampling::Interval(f64::NAN)), Err(FlightError::InvalidParameter { name: "interval", .. })));
        assert!(matches!(history(&flight, Sampling::Interval(1e-9)), Err(FlightError::TooManySamples { name: "interval", .. })));
        assert!(matches!(history(&flight, Sampling::Samples(MAX_SAMPLES + 1)), Err(FlightError::TooManySamples { name: "samples", .. })));
    }

    /// Lift from the spin across the flight direction only: with ω = (a, b, 0)
    /// and v = (v, 0, 0), S = R|b|/v whatever a is, and the force points along ω × v.
    #[test]
    fn lift_uses_the_spin_across_the_velocity() {
        let flight = models::free_kick();
        let dynamics = Dynamics::new(&flight);
        let (v, a, b) = (20.0, 150.0, -40.0);
        let y = State::from_column_slice(&[0.0, 0.0, 1.0, v, 0.0, 0.0, a, b, 0.0]);
        let dy = dynamics.derivative(0.0, &y);
        let k = dynamics.aero;
        let s = flight.ball_radius() * b.abs() / v;
        // ω × v = (0, 0, −b v): straight up for backspin b < 0.
        assert_eq!(dy[4], 0.0);
        // Drag along −v with the spinning ball's C_D at this S.
        let drag = k * dynamics.drag.at(v, s * s) * v * v;
        assert!((dy[3] + drag).abs() <= 1e-14 * drag, "{} vs {drag}", -dy[3]);
        let lift = dy[5] + dynamics.gravity;
        assert!((lift / (k * SaturatingLift::at(s) * v * v) - 1.0).abs() < 1e-14, "{lift}");
    }

    /// Several planes in one solve: each crossing is the one a flight with
    /// that plane as its `distance` gives, to the bit, and a plane past the
    /// landing has none; the outcome is [`solve`]'s.
    #[test]
    fn several_planes_cross_as_one_plane_each() {
        let flight = models::free_kick();
        let planes = [25.0, 9.15, 0.5, 500.0];
        let mut crossings = [None; 4];
        let outcome = solve_planes(&flight, &planes, &mut crossings).unwrap();
        assert_eq!(FlightOutcome { evaluations: 0, ..outcome }, FlightOutcome { evaluations: 0, ..solve(&flight).unwrap() });
        for (d, c) in planes.iter().zip(crossings) {
            let alone = solve(&flight.with_distance(Some(*d)).unwrap()).unwrap().crossing;
            assert_eq!(c, alone, "plane {d}");
        }
        assert!(crossings[3].is_none() && crossings[0].is_some());
        assert!(matches!(solve_planes(&flight, &[f64::NAN], &mut [None]), Err(FlightError::InvalidParameter { name: "distance", .. })));
        assert!(matches!(solve_planes(&flight, &[1.0], &mut []), Err(FlightError::WrongLength { .. })));
        // One plane too many is said as the bound it is (it read "takes 16 numbers, got 17").
        let many: Vec<f64> = (1..=MAX_PLANES + 1).map(|d| d as f64).collect();
        let refused = check_planes(&many).unwrap_err().to_string();
        assert_eq!(refused, format!("parameter `distance` takes at most {MAX_PLANES} numbers, got {}", MAX_PLANES + 1));
    }

    #[test]
    fn same_flight_same_bits() {
        let a = solve(&models::free_kick()).unwrap();
        let b = solve(&models::free_kick()).unwrap();
        assert_eq!(serde_json::to_string(&a).unwrap(), serde_json::to_string(&b).unwrap());
    }
}
