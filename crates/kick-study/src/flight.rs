//! The ball's flight after the kick (`kick flight`, and `--flight` of
//! `kick simulate` and `kick simulate3d`): a kick-flight solve with its JSON
//! and text forms, and the chaining of a kick's launch into it.

use crate::error::StudyError;
use crate::history::{flight_values as sample_values, HistoryMeta, HistoryRequest, FLIGHT_HISTORY_COLUMNS};
use crate::level::Failure;
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

/// One solved flight: what was flown and what it gave.
#[derive(Debug, Clone, PartialEq)]
pub struct FlightRun {
    pub flight: Flight,
    pub outcome: FlightOutcome,
}

/// The flag of the flight parameter `error` names, if it names one.
pub fn flight_flag(error: &FlightError) -> Option<String> {
    let name = match error {
        FlightError::InvalidParameter { name, .. } | FlightError::Missing { name } | FlightError::WrongLength { name, .. } => Some(*name),
        FlightError::Conflict { second, .. } => Some(*second),
        _ => None,
    };
    name.and_then(|n| FlightParameter::from_name(n).ok()).map(|p| p.def().flag())
}

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
    Ok(FlightRun { flight, outcome })
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
    Ok(FlightReport { run: FlightRun { flight: f, outcome }, written: vec![path] })
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
    After::Kick1d.refuse_set(rest)?;
    if !(outcome.v_ball_out > 0.0) {
        return Err(Failure::refused(format!("the ball leaves the 1D kick at {} m/s: nothing flies forward", outcome.v_ball_out)));
    }
    let spec = FlightSpec { speed: Some(outcome.v_ball_out), ball_mass: Some(scenario.ball_mass()), ..*rest };
    flight(&spec)
}

/// The flight after a 3D kick: the ball leaves with the kick's launch velocity
/// and spin; `rest` gives the air, coefficients and crossing plane.
pub fn after_3d(kick: &Kick3d, outcome: &Outcome3d, rest: &FlightSpec) -> Result<FlightRun, Failure> {
    After::Kick3d.refuse_set(rest)?;
    let spec = FlightSpec {
        ball_mass: Some(kick.base.ball_mass()),
        ball_radius: Some(kick.ball_radius),
        gravity: Some(kick_core::GRAVITY),
        ..*rest
    };
    if !(outcome.launch_velocity[2] > 0.0) {
        return Err(Failure::refused(format!(
            "the 3D kick launches the ball at {} m/s, not upward: nothing to fly (an --approach-angle > 0 lifts it)",
            vector(&outcome.launch_velocity)
        )));
    }
    fly(Flight::from_launch(outcome.launch_velocity, outcome.spin, &spec).map_err(flight_failure)?)
}

/// The name of the flight outcome set that follows the kick set `solver`
/// in a result file (`solvers/<solver>+flight`).
pub fn flight_set_name(solver: &str) -> String {
    format!("{solver}+flight")
}

/// The flight outcome set after the kick set `solver`: [`kick_flight::outcome_columns`]
/// and, as settings, every flight parameter the experiment gave (`rest`)
/// and the coefficient models and air the flight used.
pub fn flight_set(solver: &str, rest: &FlightSpec, flown: Option<&Flight>) -> crate::columns::OutcomeSet {
    use crate::columns::{Column, Setting};
    let mut settings = Vec::new();
    let given = serde_json::to_value(rest).unwrap_or_default();
    for p in FlightParameter::ALL {
        if let Some(v) = given.get(p.name()).and_then(serde_json::Value::as_f64) {
            settings.push((p.name().to_string(), Setting::Number(v)));
        }
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
        columns: kick_flight::outcome_columns(rest.distance.is_some()).iter().map(|(n, u)| Column::new(n, u)).collect(),
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
        match &o.crossing {
            Some(c) => {
                let _ = writeln!(
                    w,
                    "{:<24} x = {} m at {} s: height {} m, lateral offset {} m",
                    "crossing",
                    sig(c.distance),
                    sig(c.time),
                    sig(c.height),
                    sig(c.lateral_offset)
                );
            }
            None => {
                if let Some(d) = f.distance() {
                    let _ = writeln!(w, "{:<24} none: the ball lands before x = {} m", "crossing", sig(d));
                }
            }
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
}
