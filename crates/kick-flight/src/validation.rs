//! The flight model beside published measurements (the validation chapter of
//! issue 14; measurements in `experiments/validation/measurements.toml`, read
//! by [`kick_core::measurements`]; the coefficients' own sources are in
//! `SOURCES.md`).
//!
//! - [`drag_crisis_comparisons`]: where the default C_D(Re) drops, against
//!   the critical Reynolds numbers of soccer balls (one definition of the
//!   critical Re: [`DragCrisis::critical_reynolds`]), per ball construction;
//! - [`measured_flights`]: measured trajectories (Mencke et al. 2020, read
//!   only in a code base's transcription) flown from their launch;
//! - [`free_kicks`]: the lateral deflection at a distance of free kicks over
//!   the launch speeds and spins of Physics World's free kick (no measured
//!   deflection was found to set it beside; an independent estimate comes
//!   with each), and the article's own estimate of side force, time and bend
//!   beside the middle kick ([`ArticleEstimate`]);
//! - [`lift_plateau_bends`], [`spin_decay_bends`]: what the bend owes to the
//!   lift plateau (read only in transcriptions) and to spin decay (off: no
//!   measured rate);
//! - [`ball_comparisons`]: the default ball against Law 2.

use crate::coefficients::{BallConstruction, DragCrisis, DragLaw, SaturatingLift, BALL_CONSTRUCTIONS};
use crate::{solve, Air, DragModel, FlightError, FlightSpec};
use kick_core::measurements::{Comparison, Measured, MeasurementError, Measurements};
use kick_core::{DEFAULT_BALL_MASS, DEFAULT_BALL_RADIUS};
use serde::Serialize;
use thiserror::Error;

const NEEDED_BY: &str = "the flight (kick_flight::validation)";

/// The measurement keys this module reads.
pub mod keys {
    pub const CRITICAL_RE: &str = "critical_re_asai2007";
    /// Critical Reynolds numbers by panel count.
    pub const PANELS: [(&str, u8); 4] =
        [("critical_re_32_panels", 32), ("critical_re_14_panels", 14), ("critical_re_8_panels", 8), ("critical_re_6_panels", 6)];
    pub const TRANSITION_RE: &str = "transition_re_goff_carre2009";
    pub const TRANSITION_SPEED: &str = "transition_speed_goff_carre2009";
    pub const DRAG_COEFFICIENT: &str = "drag_coefficient_goff_carre2009";
    pub const FREE_KICK_SPEED: &str = "free_kick_speed";
    pub const FREE_KICK_SPIN: &str = "free_kick_spin";
    /// The article's own estimate for its free kick: side force, path length, time in the air, bend.
    pub const FREE_KICK_ESTIMATE: [&str; 4] = ["free_kick_side_force", "free_kick_distance", "free_kick_flight_time", "free_kick_bend"];
    /// Barber & Carré's (2010) measured launch of curling free kicks.
    pub const CURLING_SPEED: &str = "barber_carre2010_launch_speed";
    pub const CURLING_SPIN: &str = "barber_carre2010_launch_spin";
    /// Mencke et al.'s (2020) curveball: launch, spin, and its drift at a distance.
    pub const CURVEBALL_LAUNCH: [&str; 3] =
        ["mencke2020_curveball_launch_vx", "mencke2020_curveball_launch_vy", "mencke2020_curveball_launch_vz"];
    pub const CURVEBALL_SPIN: &str = "mencke2020_curveball_spin";
    pub const CURVEBALL_DISTANCE: &str = "mencke2020_curveball_distance";
    pub const CURVEBALL_DRIFT: &str = "mencke2020_curveball_drift";
    /// Mencke et al.'s kick without spin: launch, apex above the launch point, range.
    pub const PLAIN_LAUNCH: [&str; 2] = ["mencke2020_plain_launch_vx", "mencke2020_plain_launch_vz"];
    pub const PLAIN_APEX: &str = "mencke2020_plain_apex";
    pub const PLAIN_RANGE: &str = "mencke2020_plain_range";
    pub const LAW2_MASS: &str = "law2_mass";
    pub const LAW2_CIRCUMFERENCE: &str = "law2_circumference";
}

/// Distance at which free kicks are compared, m (the task's 25 m).
pub const FREE_KICK_DISTANCE: f64 = 25.0;
/// Launch elevation of the free kicks, degrees: an assumption (no measured
/// elevation was found), 18° so that every kick of the grid reaches x = 25 m
/// in the air with the spinning ball's drag (at `models::free_kick`'s 16°
/// the 25 m/s kicks, at C_D ≈ 0.26, land short).
pub const FREE_KICK_ELEVATION: f64 = 18.0;
/// Speed at which the supercritical C_D is read, m/s: well above the crisis.
pub const SUPERCRITICAL_SPEED: f64 = 25.0;

#[derive(Debug, Error, Clone, PartialEq)]
pub enum FlightValidationError {
    #[error(transparent)]
    Measurements(#[from] MeasurementError),
    #[error(transparent)]
    Flight(#[from] FlightError),
    #[error("a free kick at {speed} m/s with {spin} rad/s lands before x = {distance} m")]
    NoCrossing { speed: f64, spin: f64, distance: f64 },
    #[error("no spin decay k_M in [1e-8, 10] leaves {share} of the spin at landing")]
    NoDecay { share: f64 },
}

/// Where the default drag model's crisis lies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DragCrisisModel {
    /// Re at which C_D is halfway down (the logistic's centre, Eq. 3's v_c): not the critical Re.
    pub centre: f64,
    /// The critical Re ([`DragCrisis::critical_reynolds`]: 95 % of the drop done), default ball (14 panels).
    pub critical: f64,
    /// The critical Re as a speed of the default ball (R = 0.11 m) in default air, m/s.
    pub critical_speed: f64,
    /// The critical Re of each declared construction (panels, Re): the default's times its factor.
    pub constructions: Vec<(u8, f64)>,
    /// C_D of the default ball in default air at [`SUPERCRITICAL_SPEED`].
    pub supercritical: f64,
}

/// The default C_D(Re)'s crisis, from its constants.
pub fn drag_crisis_model() -> DragCrisisModel {
    let air = Air::standard();
    let reynolds_per_speed = 2.0 * DEFAULT_BALL_RADIUS / air.kinematic_viscosity();
    let law = DragLaw::new(DragModel::DragCrisis { construction: Default::default() }, reynolds_per_speed);
    let critical = DragCrisis::critical_reynolds();
    DragCrisisModel {
        centre: DragCrisis::centre_reynolds(),
        critical,
        critical_speed: critical / reynolds_per_speed,
        constructions: BALL_CONSTRUCTIONS.iter().map(|c| (c.0, critical * BallConstruction { panels: c.0 }.reynolds_scale())).collect(),
        supercritical: law.at_speed(SUPERCRITICAL_SPEED),
    }
}

/// The default C_D's crisis beside the published critical Reynolds numbers
/// (each construction's own crisis beside its published number), the
/// transition and the supercritical C_D. Every critical Re of the model is
/// [`DragCrisis::critical_reynolds`]'s definition.
pub fn drag_crisis_comparisons(m: &Measurements) -> Result<Vec<Comparison>, FlightValidationError> {
    let model = drag_crisis_model();
    let get = |key: &str| m.measured(key, NEEDED_BY);
    let fit = "Goff & Carré's (2010) logistic fit to Asai et al.'s (2007) Teamgeist (14-panel) C_D, taken in Re";
    let mut rows = vec![Comparison::new("critical Reynolds number", get(keys::CRITICAL_RE)?, model.critical, fit)];
    for (key, panels) in keys::PANELS {
        let re = model.constructions.iter().find(|c| c.0 == panels).map_or(f64::NAN, |c| c.1);
        rows.push(Comparison::new(
            format!("critical Reynolds number, {panels} panels"),
            get(key)?,
            re,
            "the construction's factor on the crisis is its published critical Re over the 14-panel ball's",
        ));
    }
    rows.push(Comparison::new("Reynolds number of the drag transition", get(keys::TRANSITION_RE)?, model.critical, "the critical Re"));
    rows.push(Comparison::new(
        "speed of the drag transition (R = 0.11 m, standard sea-level air)",
        get(keys::TRANSITION_SPEED)?,
        model.critical_speed,
        "the critical Re as a speed of the default ball in default air",
    ));
    rows.push(Comparison::new(
        format!("drag coefficient above the crisis ({SUPERCRITICAL_SPEED} m/s, no spin)"),
        get(keys::DRAG_COEFFICIENT)?,
        model.supercritical,
        "Goff & Carré's 0.2 is one constant fitted to a whole no-spin trajectory, which spends time nearer the crisis",
    ));
    Ok(rows)
}

/// The default ball against Law 2.
pub fn ball_comparisons(m: &Measurements) -> Result<Vec<Comparison>, FlightValidationError> {
    Ok(vec![
        Comparison::new("ball mass", m.measured(keys::LAW2_MASS, NEEDED_BY)?, DEFAULT_BALL_MASS, "Table 1's m_b"),
        Comparison::new(
            "ball circumference",
            m.measured(keys::LAW2_CIRCUMFERENCE, NEEDED_BY)?,
            std::f64::consts::TAU * DEFAULT_BALL_RADIUS,
            "2 pi R with R = 0.11 m",
        ),
    ])
}

/// One free kick of the grid.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FreeKickDeflection {
    /// Launch speed, m/s.
    pub speed: f64,
    /// Sidespin ω_z, rad/s (> 0 curves toward +y).
    pub spin: f64,
    /// y of the ball's centre where it crosses x = distance, m.
    pub lateral_offset: f64,
    /// Height of the centre there, m.
    pub height: f64,
    /// s after launch.
    pub time: f64,
    /// Independent estimate of `lateral_offset`: the horizontal path as a
    /// circle of the launch's curvature k C_L(S0)/cos²θ0 (lift is horizontal
    /// for a vertical spin axis; drag changes the speed, not the curvature),
    /// y = ρ − √(ρ² − d²), k = ρ_air A/(2m), S0 = R ω cos θ0 / v0.
    pub circle_estimate: f64,
}

/// The free kicks over the task's launch speeds and spins.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FreeKicks {
    pub launch_speed: Measured,
    pub launch_spin: Measured,
    /// Degrees (assumed, see [`FREE_KICK_ELEVATION`]).
    pub launch_angle: f64,
    /// m.
    pub distance: f64,
    pub kicks: Vec<FreeKickDeflection>,
    /// The article's estimate beside the model's middle kick.
    pub estimate: ArticleEstimate,
}

/// Physics World's own estimate for its free kick (side force, time in the
/// air and bend over a path of given length: a constant sideways
/// acceleration from rest, not a measurement), beside the middle kick of
/// the grid flown over the same path.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ArticleEstimate {
    /// Side force, path length, time in the air and bend, as [`keys::FREE_KICK_ESTIMATE`].
    pub side_force: Measured,
    pub distance: Measured,
    pub flight_time: Measured,
    pub bend: Measured,
    /// The middle kick crossing x = the path length.
    pub kick: FreeKickDeflection,
    /// Its lift at launch, ½ ρ A C_L(S0) v0², N.
    pub lift_force: f64,
    /// C_L the article's side force gives at the middle speed: F/(½ ρ A v0²).
    pub implied_lift_coefficient: f64,
}

/// Free kicks at the low, middle and high launch speed and spin of the
/// measurement file (default ball, air and coefficients), each crossing x = `distance`.
pub fn free_kicks(m: &Measurements, launch_angle: f64, distance: f64) -> Result<FreeKicks, FlightValidationError> {
    let speed = m.measured(keys::FREE_KICK_SPEED, NEEDED_BY)?;
    let spin = m.measured(keys::FREE_KICK_SPIN, NEEDED_BY)?;
    let three = |x: &Measured| {
        let (lo, hi) = (x.low.unwrap_or(f64::NAN), x.high.unwrap_or(f64::NAN));
        [lo, 0.5 * (lo + hi), hi]
    };
    let mut kicks = Vec::with_capacity(9);
    for v in three(&speed) {
        for w in three(&spin) {
            kicks.push(free_kick(v, w, launch_angle, distance)?);
        }
    }
    let [side_force, path, flight_time, bend] = keys::FREE_KICK_ESTIMATE.map(|key| m.measured(key, NEEDED_BY));
    let (side_force, path, flight_time, bend) = (side_force?, path?, flight_time?, bend?);
    let (v, w) = (three(&speed)[1], three(&spin)[1]);
    let kick = free_kick(v, w, launch_angle, path.midpoint().unwrap_or(f64::NAN))?;
    // ½ ρ A v0²: the lift per unit C_L at launch, of the flight the kicks fly with.
    let flight = FlightSpec::from_exit_speed(v, launch_angle).build()?;
    let dynamic = 0.5 * flight.air().density * std::f64::consts::PI * flight.ball_radius().powi(2) * v * v;
    let s0 = flight.ball_radius() * w * launch_angle.to_radians().cos() / v;
    let estimate = ArticleEstimate {
        implied_lift_coefficient: side_force.midpoint().unwrap_or(f64::NAN) / dynamic,
        lift_force: dynamic * SaturatingLift::at(s0),
        side_force,
        distance: path,
        flight_time,
        bend,
        kick,
    };
    Ok(FreeKicks { launch_speed: speed, launch_spin: spin, launch_angle, distance, kicks, estimate })
}

/// One free kick: `speed` m/s at `launch_angle` degrees with sidespin `spin`
/// rad/s about the vertical, its crossing of x = `distance`.
pub fn free_kick(speed: f64, spin: f64, launch_angle: f64, distance: f64) -> Result<FreeKickDeflection, FlightValidationError> {
    let flight = FlightSpec { spin: Some([0.0, 0.0, spin]), distance: Some(distance), ..FlightSpec::from_exit_speed(speed, launch_angle) }
        .build()?;
    let crossing = solve(&flight)?.crossing.ok_or(FlightValidationError::NoCrossing { speed, spin, distance })?;
    let theta = launch_angle.to_radians();
    let k = flight.air().density * std::f64::consts::PI * flight.ball_radius().powi(2) / (2.0 * flight.ball_mass());
    let s0 = flight.ball_radius() * spin.abs() * theta.cos() / speed;
    let radius = theta.cos().powi(2) / (k * SaturatingLift::at(s0));
    let circle_estimate = if radius > distance { radius - (radius * radius - distance * distance).sqrt() } else { f64::NAN };
    Ok(FreeKickDeflection {
        speed,
        spin,
        lateral_offset: crossing.lateral_offset,
        height: crossing.height,
        time: crossing.time,
        circle_estimate: circle_estimate.copysign(spin),
    })
}

/// Mencke et al.'s (2020) measured flights, flown from their launch with the
/// default ball, air and coefficients: the curveball's drift where its last
/// point was digitised, and the plain kick's apex above its launch point and
/// its range. Their numbers were read only in a code base's transcription
/// of the paper's figures (the rows say so; the measurement file marks them).
pub fn measured_flights(m: &Measurements) -> Result<Vec<Comparison>, FlightValidationError> {
    let value = |key: &str| -> Result<f64, FlightValidationError> { Ok(m.measured(key, NEEDED_BY)?.midpoint().unwrap_or(f64::NAN)) };
    let [vx, vy, vz] = [value(keys::CURVEBALL_LAUNCH[0])?, value(keys::CURVEBALL_LAUNCH[1])?, value(keys::CURVEBALL_LAUNCH[2])?];
    let distance = value(keys::CURVEBALL_DISTANCE)?;
    // The published sense: the ball curves toward −y (ω_z < 0 for a kick along +x).
    let spin = -value(keys::CURVEBALL_SPIN)?.abs();
    let curve =
        FlightSpec { launch_velocity: Some([vx, vy, vz]), spin: Some([0.0, 0.0, spin]), distance: Some(distance), ..FlightSpec::default() }
            .build()?;
    let crossing =
        solve(&curve)?.crossing.ok_or(FlightValidationError::NoCrossing { speed: (vx * vx + vy * vy + vz * vz).sqrt(), spin, distance })?;
    // Drag and lift act in the vertical plane through v and across it; with no
    // spin the horizontal path keeps the launch direction, y = x vy/vx.
    let straight = distance * vy / vx;
    let drift = value(keys::CURVEBALL_DRIFT)?;
    let [px, pz] = [value(keys::PLAIN_LAUNCH[0])?, value(keys::PLAIN_LAUNCH[1])?];
    let plain = solve(&FlightSpec { launch_velocity: Some([px, 0.0, pz]), ..FlightSpec::default() }.build()?)?;
    let launch = format!("launched at ({}, {}, {}) m/s with {} rad/s about the vertical", vx, vy, vz, spin.abs());
    Ok(vec![
        Comparison::new(
            format!("lateral drift at x = {} m, curveball", kick_core::short(distance)),
            m.measured(keys::CURVEBALL_DRIFT, NEEDED_BY)?,
            crossing.lateral_offset,
            format!(
                "{launch}; default ball, air, C_D and C_L; measured from the straight launch line (y = {} m there) the \
                 model bends {} m, the digitised path {} m",
                kick_core::short(straight),
                kick_core::short(straight - crossing.lateral_offset),
                kick_core::short(straight - drift)
            ),
        ),
        Comparison::new(
            "apex above the launch point, kick without spin",
            m.measured(keys::PLAIN_APEX, NEEDED_BY)?,
            plain.apex_height - DEFAULT_BALL_RADIUS,
            format!("launched at ({px}, 0, {pz}) m/s, no spin; default ball, air and C_D"),
        ),
        Comparison::new(
            "range back to the launch height, kick without spin",
            m.measured(keys::PLAIN_RANGE, NEEDED_BY)?,
            plain.landing_point[0],
            format!("launched at ({px}, 0, {pz}) m/s, no spin; default ball, air and C_D"),
        ),
    ])
}

/// One free kick flown with one lift model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LiftBend {
    /// None: the default saturating C_L(S); Some(c): a constant C_L = c.
    pub constant_lift: Option<f64>,
    /// C_L at launch.
    pub launch_lift: f64,
    /// y of the centre where it crosses x = distance, m.
    pub lateral_offset: f64,
    /// Height of the centre there, m.
    pub height: f64,
}

/// The free kick `speed` m/s at `launch_angle`° with sidespin `spin` rad/s
/// about the vertical, crossing x = `distance`, flown with the default C_L(S)
/// and then with each constant C_L of `constants` (the plateau's role in the
/// bend: the default's seven points were read only in transcriptions).
pub fn lift_plateau_bends(
    speed: f64,
    spin: f64,
    launch_angle: f64,
    distance: f64,
    constants: &[f64],
) -> Result<Vec<LiftBend>, FlightValidationError> {
    std::iter::once(None)
        .chain(constants.iter().map(|&c| Some(c)))
        .map(|constant_lift| {
            let spec = FlightSpec {
                spin: Some([0.0, 0.0, spin]),
                distance: Some(distance),
                lift_coefficient: constant_lift,
                ..FlightSpec::from_exit_speed(speed, launch_angle)
            };
            let out = solve(&spec.build()?)?;
            let crossing = out.crossing.ok_or(FlightValidationError::NoCrossing { speed, spin, distance })?;
            Ok(LiftBend {
                constant_lift,
                launch_lift: out.launch.lift_coefficient,
                lateral_offset: crossing.lateral_offset,
                height: crossing.height,
            })
        })
        .collect()
}

/// One free kick flown with spin decay.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpinDecayBend {
    /// Share of the launch spin left at landing (1: no decay).
    pub kept_at_landing: f64,
    /// k_M that leaves that share (0: no decay).
    pub spin_decay: f64,
    /// y of the centre where it crosses x = distance, m.
    pub lateral_offset: f64,
}

/// The free kick of [`lift_plateau_bends`] (default coefficients) with no spin
/// decay and with the k_M that leaves each share of `kept` of its spin at
/// landing (Brent on ln k_M, the landing spin falling monotonically with it).
/// No measured decay rate of a soccer ball was reached: the shares are
/// what-ifs, not a sourced range.
pub fn spin_decay_bends(
    speed: f64,
    spin: f64,
    launch_angle: f64,
    distance: f64,
    kept: &[f64],
) -> Result<Vec<SpinDecayBend>, FlightValidationError> {
    let fly = |k_m: f64| -> Result<(f64, f64), FlightValidationError> {
        let spec = FlightSpec {
            spin: Some([0.0, 0.0, spin]),
            distance: Some(distance),
            spin_decay: Some(k_m),
            ..FlightSpec::from_exit_speed(speed, launch_angle)
        };
        let out = solve(&spec.build()?)?;
        let crossing = out.crossing.ok_or(FlightValidationError::NoCrossing { speed, spin, distance })?;
        Ok((out.landing_spin[2] / spin, crossing.lateral_offset))
    };
    let mut rows = vec![SpinDecayBend { kept_at_landing: 1.0, spin_decay: 0.0, lateral_offset: fly(0.0)?.1 }];
    for &share in kept {
        let f = |ln_k: f64| fly(ln_k.exp()).map_or(f64::NAN, |(k, _)| k - share);
        let root = kick_core::roots::brent(f, 1e-8f64.ln(), 10f64.ln(), 1e-12, 200).ok_or(FlightValidationError::NoDecay { share })?;
        let k_m = root.x.exp();
        let (kept_at_landing, lateral_offset) = fly(k_m)?;
        rows.push(SpinDecayBend { kept_at_landing, spin_decay: k_m, lateral_offset });
    }
    Ok(rows)
}
