//! The ball's flight after the kick (`kick flight`, and `--flight` of
//! `kick simulate` and `kick simulate3d`): a kick-flight solve with its JSON
//! and text forms, and the chaining of a kick's launch into it.

use crate::error::Failure;
use crate::error::StudyError;
use crate::history::{flight_values as sample_values, HistoryMeta, HistoryRequest, FLIGHT_HISTORY_COLUMNS};
use crate::printable::Printable;
use kick_3d::{Kick3d, Outcome3d};
use kick_core::number::{sig, vector};
use kick_core::{Outcome, Scenario, Spacing};
use kick_flight::{solve, Flight, FlightError, FlightOutcome, FlightParameter, FlightSpec, Sampling};
use serde::ser::{Serialize, Serializer};
use serde_json::{Map, Value};
use std::fmt::Write as _;
use std::path::PathBuf;

/// The kick a flight follows (`kick simulate --flight`, `kick simulate3d --flight`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum After {
    Kick1d,
    Kick3d,
}

impl After {
    /// Whether the kick sets flight parameter `p`, which then cannot be
    /// given: a 1D kick its exit speed (no spin) and its ball's mass; a 3D
    /// kick the whole launch ([`FlightParameter::LAUNCH`]), its ball, and g
    /// (kick-3d's, `kick_core::GRAVITY`; its `gravity` flag is a switch).
    pub fn sets(self, p: FlightParameter) -> bool {
        use FlightParameter::*;
        match self {
            After::Kick1d => matches!(p, Speed | LaunchVelocity | Spin | BallMass),
            After::Kick3d => FlightParameter::LAUNCH.contains(&p) || matches!(p, BallMass | BallRadius | Gravity),
        }
    }

    fn name(self) -> &'static str {
        match self {
            After::Kick1d => "1D kick",
            After::Kick3d => "3D kick",
        }
    }

    /// Refuse a parameter of `rest` that the kick sets.
    fn refuse_set(self, rest: &FlightSpec) -> Result<(), Failure> {
        match FlightParameter::ALL.into_iter().find(|&p| self.sets(p) && rest.is_set(p)) {
            Some(p) => Err(Failure::refused(format!("flight parameter `{}` is set by the {} and cannot be given", p.name(), self.name()))),
            None => Ok(()),
        }
    }
}

/// What a study flies after each kick: the flight parameters the kick
/// leaves (`rest`; its `distance` is one crossing plane) and, instead of
/// that one, several crossing planes (`planes`: `distances` in `[flight]`,
/// `--distance` given more than once, Python's `distance=[...]`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FlightPlan {
    pub rest: FlightSpec,
    /// Crossing planes x = d, m, each located in the one solve; their
    /// columns carry the plane's index (`kick_flight::plane_columns`).
    pub planes: Option<Vec<f64>>,
}

impl FlightPlan {
    /// `rest` alone (its `distance`, if any, the one plane).
    pub fn new(rest: FlightSpec) -> FlightPlan {
        FlightPlan { rest, planes: None }
    }

    /// `rest` with the planes `distances` as a front end gives them: one
    /// is `rest`'s `distance` (the columns as ever), several the planes;
    /// `rest` may not give a distance too.
    pub fn with_distances(rest: FlightSpec, distances: &[f64]) -> Result<FlightPlan, FlightError> {
        match distances {
            [] => Ok(FlightPlan::new(rest)),
            [d] if rest.distance.is_none() => {
                // One plane is checked as several are (a negative one used to reach every row).
                kick_flight::check_planes(&[*d])?;
                Ok(FlightPlan::new(FlightSpec { distance: Some(*d), ..rest }))
            }
            more => FlightPlan::planes(rest, more.to_vec()),
        }
    }

    /// `rest` with the planes `planes` (checked: `kick_flight::check_planes`;
    /// `rest` without a distance).
    pub fn planes(rest: FlightSpec, planes: Vec<f64>) -> Result<FlightPlan, FlightError> {
        if rest.distance.is_some() {
            return Err(FlightError::Conflict { first: "distance", second: "distances" });
        }
        kick_flight::check_planes(&planes)?;
        Ok(FlightPlan { rest, planes: Some(planes) })
    }

    /// The planes located, in order: `planes`, or `rest`'s one distance.
    pub fn distances(&self) -> Vec<f64> {
        match &self.planes {
            Some(planes) => planes.clone(),
            None => self.rest.distance.into_iter().collect(),
        }
    }

    /// The outcome columns of a flight flown by this plan (name, unit).
    pub fn columns(&self) -> Vec<(String, &'static str)> {
        match &self.planes {
            Some(planes) => kick_flight::plane_columns(planes.len()),
            None => kick_flight::outcome_columns(self.rest.distance.is_some()).iter().map(|(n, u)| (n.to_string(), *u)).collect(),
        }
    }

    /// Solve `flight` (its distance `rest`'s) and write the values of
    /// [`FlightPlan::columns`] into `out` (no allocation); how many.
    pub fn fly_into(&self, flight: &Flight, out: &mut [f64]) -> Result<usize, Failure> {
        match &self.planes {
            None => {
                let values = solve(flight).map_err(flight_failure)?.values();
                let n = kick_flight::outcome_columns(self.rest.distance.is_some()).len();
                out[..n].copy_from_slice(&values[..n]);
                Ok(n)
            }
            Some(planes) => {
                let mut crossings = [None; kick_flight::MAX_PLANES];
                let crossings = &mut crossings[..planes.len()];
                let outcome = kick_flight::solve_planes(flight, planes, crossings).map_err(flight_failure)?;
                Ok(kick_flight::plane_values(&outcome, crossings, out))
            }
        }
    }
}

/// Most values of a flight's row ([`FlightPlan::columns`]).
pub const MAX_FLIGHT_VALUES: usize =
    kick_flight::OUTCOME_COLUMNS.len() + (kick_flight::OUTCOME_COLUMNS.len() - kick_flight::LANDING_COLUMNS) * kick_flight::MAX_PLANES;

/// One solved flight: what was flown and what it gave, and the crossing
/// of each plane of its plan (None where the ball lands first).
#[derive(Debug, Clone, PartialEq)]
pub struct FlightRun {
    pub flight: Flight,
    pub outcome: FlightOutcome,
    /// The planes asked for (empty: the flight's own distance only) and their crossings.
    pub planes: Vec<f64>,
    pub crossings: Vec<Option<kick_flight::Crossing>>,
}

pub use crate::error::flight_flag;

/// A flight error as front ends show it: the parameter's name and its flag.
pub fn flight_error(error: FlightError) -> String {
    StudyError::from(error).to_string()
}

/// A flight error with its status (refused or a numerical failure) and
/// the message of [`flight_error`].
pub fn flight_failure(error: FlightError) -> Failure {
    Failure::new(error.status(), flight_error(error))
}

/// Solve one flight.
pub fn fly(flight: Flight) -> Result<FlightRun, Failure> {
    let outcome = solve(&flight).map_err(flight_failure)?;
    Ok(FlightRun { flight, outcome, planes: Vec::new(), crossings: Vec::new() })
}

/// Solve one flight and locate its crossing of each of `planes` too.
pub fn fly_planes(flight: Flight, planes: &[f64]) -> Result<FlightRun, Failure> {
    if planes.is_empty() {
        return fly(flight);
    }
    let mut crossings = vec![None; planes.len()];
    let outcome = kick_flight::solve_planes(&flight, planes, &mut crossings).map_err(flight_failure)?;
    Ok(FlightRun { flight, outcome, planes: planes.to_vec(), crossings })
}

/// `kick flight`: validate `spec` and fly it.
pub fn flight(spec: &FlightSpec) -> Result<FlightRun, Failure> {
    fly(spec.build().map_err(flight_failure)?)
}

/// `kick flight` with `--history`: the flight and the files it wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct FlightReport {
    pub run: FlightRun,
    pub written: Vec<PathBuf>,
}

/// The parameters a flight history file records (`/fixed`), and its models.
fn meta_flight(flight: &Flight) -> HistoryMeta {
    let mut meta = HistoryMeta { level: "flight".into(), ..HistoryMeta::default() };
    meta.texts.push(("drag".into(), format!("{:?}", flight.drag())));
    meta.texts.push(("lift".into(), format!("{:?}", flight.lift())));
    let mut push = |p: FlightParameter, values: Vec<f64>| meta.fixed.push((p.name().into(), p.def().unit.into(), values));
    push(FlightParameter::LaunchVelocity, flight.launch_velocity().to_vec());
    push(FlightParameter::Spin, flight.spin().to_vec());
    push(FlightParameter::BallMass, vec![flight.ball_mass()]);
    push(FlightParameter::BallRadius, vec![flight.ball_radius()]);
    push(FlightParameter::Gravity, vec![flight.gravity()]);
    push(FlightParameter::AirDensity, vec![flight.air().density]);
    push(FlightParameter::SpinDecay, vec![flight.spin_decay()]);
    if let Some(d) = flight.distance() {
        push(FlightParameter::Distance, vec![d]);
    }
    meta
}

/// `kick flight`: validate `spec`, fly it and, with `history`, write its
/// uniform samples ([`kick_flight::history`], columns
/// [`crate::history::FLIGHT_HISTORY_COLUMNS`]) into that file.
pub fn flight_report(spec: &FlightSpec, history: Option<&HistoryRequest>) -> Result<FlightReport, StudyError> {
    let f = spec.build()?;
    let Some(request) = history else {
        return Ok(FlightReport { run: fly(f)?, written: Vec::new() });
    };
    flight_history_report(f, request)
}

/// [`flight_report`] of a flight crossing several planes (`kick flight
/// --distance A --distance B`): `plan`'s planes located in the one solve.
pub fn flight_report_planes(plan: &FlightPlan, history: Option<&HistoryRequest>) -> Result<FlightReport, StudyError> {
    let f = plan.rest.build()?;
    match history {
        None => Ok(FlightReport { run: fly_planes(f, plan.planes.as_deref().unwrap_or_default())?, written: Vec::new() }),
        Some(request) => {
            let mut report = flight_history_report(f, request)?;
            if let Some(planes) = &plan.planes {
                report.run = fly_planes(f, planes)?;
            }
            Ok(report)
        }
    }
}

fn flight_history_report(f: Flight, request: &HistoryRequest) -> Result<FlightReport, StudyError> {
    let sampling = match request.spacing {
        Spacing::Count(n) => Sampling::Samples(n),
        Spacing::Interval(dt) => Sampling::Interval(dt),
    };
    let (outcome, path) = crate::history::write(
        request,
        &FLIGHT_HISTORY_COLUMNS,
        &meta_flight(&f),
        |s| sample_values(s).to_vec(),
        |sink| {
            let h = kick_flight::history(&f, sampling).map_err(|e| match e {
                // The spacing's own flags, not flight parameters.
                FlightError::TooManySamples { name, .. } | FlightError::InvalidParameter { name: name @ ("samples" | "interval"), .. } => {
                    StudyError::Flight { source: e, flag: Some(format!("--{name}")) }
                }
                e => StudyError::from(e),
            })?;
            for s in &h.samples {
                if sink(s).is_break() {
                    break;
                }
            }
            Ok::<_, StudyError>((h.outcome, h.samples.len() as u64))
        },
    )?;
    Ok(FlightReport { run: FlightRun { flight: f, outcome, planes: Vec::new(), crossings: Vec::new() }, written: vec![path] })
}

impl Serialize for FlightReport {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.run.serialize(serializer)
    }
}

impl Printable for FlightReport {
    fn text(&self) -> String {
        self.run.text()
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

/// The flight after a 1D kick: the ball leaves at its exit speed v_b⁺ with no
/// spin, in the direction `rest`'s launch_angle (required) and azimuth give;
/// `rest` gives the air, coefficients, ball radius, g and crossing plane.
pub fn after_1d(scenario: &Scenario, outcome: &Outcome, rest: &FlightSpec) -> Result<FlightRun, Failure> {
    fly(flight_after_1d(scenario, outcome, rest)?)
}

/// The validated flight [`after_1d`] flies.
pub fn flight_after_1d(scenario: &Scenario, outcome: &Outcome, rest: &FlightSpec) -> Result<Flight, Failure> {
    After::Kick1d.refuse_set(rest)?;
    if !(outcome.v_ball_out > 0.0) {
        return Err(Failure::refused(format!("the ball leaves the 1D kick at {} m/s: nothing flies forward", sig(outcome.v_ball_out))));
    }
    let spec = FlightSpec { speed: Some(outcome.v_ball_out), ball_mass: Some(scenario.ball_mass()), ..*rest };
    spec.build().map_err(flight_failure)
}

/// The flight after a 3D kick: the ball leaves from the ground (its centre
/// at height R) with the kick's launch velocity and spin; `rest` gives the
/// air, coefficients and crossing plane.
pub fn after_3d(kick: &Kick3d, outcome: &Outcome3d, rest: &FlightSpec) -> Result<FlightRun, Failure> {
    fly(flight_after_3d(kick, outcome, rest)?)
}

/// The validated flight [`after_3d`] flies: refused when the ball does not
/// leave the ground upward.
pub fn flight_after_3d(kick: &Kick3d, outcome: &Outcome3d, rest: &FlightSpec) -> Result<Flight, Failure> {
    After::Kick3d.refuse_set(rest)?;
    let spec = FlightSpec {
        ball_mass: Some(kick.base.ball_mass()),
        ball_radius: Some(kick.ball_radius),
        gravity: Some(kick_core::GRAVITY),
        ..*rest
    };
    if !(outcome.launch_velocity[2] > 0.0) {
        return Err(Failure::refused(format!(
            "the 3D kick launches the ball at {} m/s, not upward: it does not leave the ground (a contact_depth > 0, the \
             foot's line of motion below the ball's centre, lifts it; so does a rising path, approach_angle > 0)",
            vector(&outcome.launch_velocity)
        )));
    }
    Flight::from_launch(outcome.launch_velocity, outcome.spin, &spec).map_err(flight_failure)
}

/// The flight after a 3D kick by `plan`: its planes located too.
pub fn after_3d_plan(kick: &Kick3d, outcome: &Outcome3d, plan: &FlightPlan) -> Result<FlightRun, Failure> {
    fly_planes(flight_after_3d(kick, outcome, &plan.rest)?, plan.planes.as_deref().unwrap_or_default())
}

/// The flight after a 1D kick by `plan`.
pub fn after_1d_plan(scenario: &Scenario, outcome: &Outcome, plan: &FlightPlan) -> Result<FlightRun, Failure> {
    fly_planes(flight_after_1d(scenario, outcome, &plan.rest)?, plan.planes.as_deref().unwrap_or_default())
}

/// The name of the flight outcome set that follows the kick set `solver`
/// in a result file (`solvers/<solver>+flight`).
pub fn flight_set_name(solver: &str) -> String {
    format!("{solver}+flight")
}

/// The flight outcome set after the kick set `solver`: the plan's columns
/// ([`FlightPlan::columns`]) and, as settings, every flight parameter the
/// experiment gave (`rest`; several planes as `distance_0`, `distance_1`, ...)
/// and the coefficient models and air the flight used.
pub fn flight_set(solver: &str, plan: &FlightPlan, flown: Option<&Flight>) -> crate::columns::OutcomeSet {
    use crate::columns::{Column, Setting};
    let rest = &plan.rest;
    let mut settings = Vec::new();
    let given = serde_json::to_value(rest).unwrap_or_default();
    for p in FlightParameter::ALL {
        if let Some(v) = given.get(p.name()).and_then(serde_json::Value::as_f64) {
            settings.push((p.name().to_string(), Setting::Number(v)));
        }
    }
    for (k, d) in plan.planes.iter().flatten().enumerate() {
        settings.push((format!("distance_{k}"), Setting::Number(*d)));
    }
    if let Some(f) = flown {
        settings.push(("drag_model".into(), Setting::Text(f.drag().name().into())));
        settings.push(("lift_model".into(), Setting::Text(f.lift().name().into())));
        settings.push(("air_density_flown".into(), Setting::Number(f.air().density)));
        settings.push(("air_viscosity_flown".into(), Setting::Number(f.air().viscosity)));
        settings.push(("gravity_flown".into(), Setting::Number(f.gravity())));
    }
    crate::columns::OutcomeSet {
        solver: flight_set_name(solver),
        settings,
        columns: plan.columns().iter().map(|(n, u)| Column::new(n, u)).collect(),
    }
}

impl Serialize for FlightRun {
    /// The outcome's keys (`flight_time`, `landing_point`, `apex_height`,
    /// `landing_velocity`, `crossing` or null, ...) and the launch state flown.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut m: Map<String, Value> = match serde_json::to_value(self.outcome).map_err(serde::ser::Error::custom)? {
            Value::Object(m) => m,
            _ => return Err(serde::ser::Error::custom("flight outcome is not an object")),
        };
        m.insert("launch_velocity".into(), self.flight.launch_velocity().to_vec().into());
        m.insert("spin".into(), self.flight.spin().to_vec().into());
        m.insert("air_density".into(), self.flight.air().density.into());
        if !self.planes.is_empty() {
            // One entry per plane, in the order given: the crossing, or null where the ball lands first.
            let crossings: Vec<Value> = self.crossings.iter().map(|c| serde_json::to_value(c).unwrap_or(Value::Null)).collect();
            m.insert("crossings".into(), crossings.into());
        }
        m.serialize(serializer)
    }
}

impl Printable for FlightRun {
    fn text(&self) -> String {
        let o = &self.outcome;
        let f = &self.flight;
        let mut w = String::new();
        let v = |a: &[f64], unit: &str| format!("{} {unit}", vector(a));
        let _ = writeln!(w, "{:<24} {}", "launch_velocity", v(&f.launch_velocity(), "m/s"));
        let _ = writeln!(w, "{:<24} {}", "spin", v(&f.spin(), "rad/s"));
        let _ = writeln!(w, "{:<24} {} s", "flight_time", sig(o.flight_time));
        let _ = writeln!(w, "{:<24} {}", "landing_point", v(&o.landing_point, "m"));
        let _ = writeln!(w, "{:<24} {} m (at {} s)", "apex_height", sig(o.apex_height), sig(o.apex_time));
        let _ = writeln!(w, "{:<24} {}", "landing_velocity", v(&o.landing_velocity, "m/s"));
        // One line per plane: the single crossing's, then the other planes'.
        let single = f.distance().map(|d| (d, o.crossing.as_ref()));
        for (d, c) in single.into_iter().chain(self.planes.iter().copied().zip(self.crossings.iter().map(Option::as_ref))) {
            let _ = match c {
                Some(c) => writeln!(
                    w,
                    "{:<24} x = {} m at {} s: height {} m, lateral offset {} m",
                    "crossing",
                    sig(c.distance),
                    sig(c.time),
                    sig(c.height),
                    sig(c.lateral_offset)
                ),
                None => writeln!(w, "{:<24} none: the ball lands before x = {} m", "crossing", sig(d)),
            };
        }
        let _ = writeln!(w, "{:<24} {}", "steps", o.steps);
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_core::Solver;

    /// A kick's launch is the kick's: giving it again is refused by name,
    /// and refusals name the flag.
    #[test]
    fn a_kick_sets_its_launch_and_errors_name_flags() {
        let scenario = Scenario::baseline();
        let outcome = kick_compliant::SolverChoice::from_name("auto", 5e-6).unwrap().solve(&scenario).unwrap();
        let rest = FlightSpec { launch_angle: Some(15.0), ..FlightSpec::default() };
        assert!(after_1d(&scenario, &outcome, &rest).is_ok());
        let error = after_1d(&scenario, &outcome, &FlightSpec { spin: Some([0.0, 0.0, 10.0]), ..rest }).unwrap_err();
        assert!(error.message.contains("`spin` is set by the 1D kick"), "{error}");
        assert_eq!(error.status, kick_core::Status::Refused);
        let kick = Kick3d::baseline();
        let o3 = kick_3d::Accurate3d::default().solve(&kick).unwrap();
        let error = after_3d(&kick, &o3, &rest).unwrap_err();
        assert!(error.message.contains("`launch_angle` is set by the 3D kick"), "{error}");
        let error = flight(&FlightSpec { launch_angle: Some(95.0), ..FlightSpec::from_exit_speed(20.0, 10.0) }).unwrap_err();
        assert!(error.message.contains("(flag --launch-angle)"), "{error}");
        assert_eq!(error.status, kick_core::Status::Refused);
    }

    /// Crossing planes are checked however many are given: one negative
    /// plane (`--distance=-9`) is refused before a run, as several are; an
    /// empty list and a plane given twice are refused naming `distance(s)`.
    #[test]
    fn every_plane_list_is_checked() {
        let name = |r: Result<FlightPlan, FlightError>| match r {
            Err(FlightError::InvalidParameter { name, value, .. }) => (name, value),
            other => panic!("{other:?}"),
        };
        let rest = FlightSpec::default();
        assert_eq!(name(FlightPlan::with_distances(rest.clone(), &[-9.0])), ("distance", -9.0));
        assert_eq!(name(FlightPlan::with_distances(rest.clone(), &[9.15, -1.0])), ("distance", -1.0));
        assert_eq!(name(FlightPlan::with_distances(rest.clone(), &[9.15, 9.15])), ("distance", 9.15));
        assert_eq!(name(FlightPlan::planes(rest.clone(), vec![])), ("distances", 0.0));
        assert_eq!(FlightPlan::with_distances(rest.clone(), &[9.15]).unwrap().distances(), [9.15]);
        assert_eq!(FlightPlan::with_distances(rest, &[]).unwrap().distances(), Vec::<f64>::new());
    }
}
