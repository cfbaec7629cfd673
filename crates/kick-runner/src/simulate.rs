//! One contact, 1D (`kick simulate`) or 3D (`kick simulate3d`): the solve and
//! its JSON and text forms.

use crate::flight::{self, FlightRun};
use crate::printable::Printable;
use kick_flight::FlightSpec;
use kick_3d::{Kick3d, KickSpec, Outcome3d, Solver3d};
use kick_compliant::SolverChoice;
use kick_core::number::{sig, vector};
use kick_core::{History, Outcome, Parameter, RecordingSolver, Scenario, ScenarioSpec, Solver, OBSERVABLES};
use serde::ser::{Serialize, Serializer};
use serde_json::{Map, Value};
use std::fmt::Write as _;
use std::time::Instant;

/// A 1D run: the scenario, the solver and what it gave.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    pub scenario: Scenario,
    pub solver: &'static str,
    pub outcome: Outcome,
    pub history: Option<History>,
    /// The ball's flight after the kick, when asked for.
    pub flight: Option<FlightRun>,
}

/// Solve `spec` with the solver named `solver` (`dt`: step of the fixed-step
/// solvers, refused with the others), with a history sampled at most `history` seconds apart if given,
/// and with `flight` given, the ball's flight after it ([`flight::after_1d`]).
pub fn simulate(
    spec: &ScenarioSpec,
    solver: &str,
    dt: Option<f64>,
    history: Option<f64>,
    flight: Option<&FlightSpec>,
) -> Result<Simulation, String> {
    let scenario = spec.build().map_err(|e| e.to_string())?;
    let choice = SolverChoice::with_step(solver, dt).map_err(|e| e.to_string())?;
    let (outcome, history) = match history {
        Some(interval) => {
            let (o, h) = choice.solve_recorded(&scenario, interval).map_err(|e| e.to_string())?;
            (o, Some(h))
        }
        None => (choice.solve(&scenario).map_err(|e| e.to_string())?, None),
    };
    let flight = flight.map(|rest| flight::after_1d(&scenario, &outcome, rest)).transpose()?;
    Ok(Simulation { scenario, solver: choice.name(), outcome, history, flight })
}

/// The JSON object of one run: every observable, the energy residual, the
/// solver, the path it took, the scenario and its contact law.
pub fn outcome_json(scenario: &Scenario, solver: &str, outcome: &Outcome) -> Map<String, Value> {
    let mut object = Map::new();
    for ((name, _), value) in OBSERVABLES.iter().zip(outcome.observable_values()) {
        object.insert((*name).into(), value.into());
    }
    object.insert("energy_residual".into(), outcome.energy.residual().into());
    object.insert("solver".into(), solver.into());
    object.insert("method".into(), serde_json::to_value(outcome.method).unwrap_or(Value::Null));
    object.insert("stop".into(), serde_json::to_value(outcome.stop).unwrap_or(Value::Null));
    object.insert("evaluations".into(), outcome.evaluations.into());
    let mut parameters = Map::new();
    for p in Parameter::ALL {
        parameters.insert(p.name().into(), scenario.get(p).into());
    }
    object.insert("scenario".into(), Value::Object(parameters));
    object.insert("law".into(), serde_json::to_value(scenario.contact_law()).unwrap_or(Value::Null));
    object
}

impl Serialize for Simulation {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        // Samples serialised as they are, not through a JSON tree (~2.5 kB a sample).
        #[derive(serde::Serialize)]
        struct WithHistory<'a> {
            #[serde(flatten)]
            outcome: &'a Map<String, Value>,
            #[serde(skip_serializing_if = "Option::is_none")]
            history: Option<&'a [kick_core::Sample]>,
        }
        let mut object = outcome_json(&self.scenario, self.solver, &self.outcome);
        if let Some(f) = &self.flight {
            object.insert("flight".into(), serde_json::to_value(f).map_err(serde::ser::Error::custom)?);
        }
        WithHistory { outcome: &object, history: self.history.as_ref().map(|h| h.samples.as_slice()) }.serialize(serializer)
    }
}

impl Printable for Simulation {
    fn text(&self) -> String {
        let mut w = String::new();
        let o = &self.outcome;
        let _ = writeln!(w, "solver: {} (path: {})", self.solver, o.method);
        for ((name, unit), value) in OBSERVABLES.iter().zip(o.observable_values()) {
            let _ = writeln!(w, "{name:<24} {:>12} {unit}", sig(value));
        }
        let _ = writeln!(w, "{:<24} {:>12} J", "energy_residual", sig(o.energy.residual()));
        if let Some(f) = &self.flight {
            let _ = write!(w, "\nflight:\n{}", f.text());
        }
        if let Some(h) = &self.history {
            let _ = writeln!(
                w,
                "\ntime_s,foot_position_m,foot_velocity_m_s,ball_position_m,ball_velocity_m_s,compression_m,force_N,kinetic_J,elastic_J,dissipated_J,drive_work_J"
            );
            for s in &h.samples {
                let _ = writeln!(
                    w,
                    "{},{},{},{},{},{},{},{},{},{},{}",
                    s.time, s.foot_position, s.foot_velocity, s.ball_position, s.ball_velocity, s.compression, s.force,
                    s.kinetic, s.elastic, s.dissipated, s.drive_work
                );
            }
        }
        w
    }
}

/// A 3D run: the kick, what the solver gave and how long the solve took.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation3d {
    pub kick: Kick3d,
    pub outcome: Outcome3d,
    /// Wall time of the solve, s (one run).
    pub seconds: f64,
    /// The ball's flight after the kick, when asked for.
    pub flight: Option<FlightRun>,
}

/// Solve the 3D kick `spec` with the path named `solver` (`dt`: the rapier
/// scene path's step, refused with the others) and, with `flight` given, the ball's flight after it
/// ([`flight::after_3d`]; not in `seconds`).
pub fn simulate3d(spec: &KickSpec, solver: &str, dt: Option<f64>, flight: Option<&FlightSpec>) -> Result<Simulation3d, String> {
    spec.scenario.check_given().map_err(|e| e.to_string())?;
    let kick = spec.build().map_err(|e| e.to_string())?;
    let solver = Solver3d::with_step(solver, dt).map_err(|e| e.to_string())?;
    let start = Instant::now();
    let outcome = solver.solve(&kick).map_err(|e| e.to_string())?;
    let seconds = start.elapsed().as_secs_f64();
    let flight = flight.map(|rest| flight::after_3d(&kick, &outcome, rest)).transpose()?;
    Ok(Simulation3d { kick, outcome, seconds, flight })
}

/// The JSON object of one 3D run: the outcome (with `law`, the normal law's
/// name), the energy residual and `law_parameters` (the law as solved).
impl Serialize for Simulation3d {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let o = &self.outcome;
        let mut m = match serde_json::to_value(o).map_err(serde::ser::Error::custom)? {
            Value::Object(m) => m,
            _ => return Err(serde::ser::Error::custom("outcome is not an object")),
        };
        m.insert("energy_residual".into(), o.energy.residual().into());
        m.insert("law_parameters".into(), serde_json::to_value(self.kick.law()).map_err(serde::ser::Error::custom)?);
        if let Some(f) = &self.flight {
            m.insert("flight".into(), serde_json::to_value(f).map_err(serde::ser::Error::custom)?);
        }
        m.serialize(serializer)
    }
}

impl Printable for Simulation3d {
    fn text(&self) -> String {
        let o = &self.outcome;
        let mut w = String::new();
        let v = |a: [f64; 3], unit: &str| format!("{} {unit}", vector(&a));
        let _ = writeln!(w, "solver: {}, normal law: {}", o.solver, o.law.name());
        let _ = writeln!(w, "{:<24} {}", "launch_velocity", v(o.launch_velocity, "m/s"));
        let _ = writeln!(w, "{:<24} {}", "spin", v(o.spin, "rad/s"));
        for (name, value, unit) in [
            ("speed", o.speed, "m/s"),
            ("spin_rpm", o.spin_rpm, "rpm"),
            ("launch_angle", o.launch_angle, "deg"),
            ("launch_azimuth", o.launch_azimuth, "deg"),
            ("contact_time", o.contact_time, "s"),
            ("peak_normal_force", o.peak_normal_force, "N"),
            ("peak_tangential_force", o.peak_tangential_force, "N"),
            ("max_compression", o.max_compression, "m"),
            ("slip_time", o.slip_time, "s"),
            ("energy_ball_spin", o.energy.ball_spin, "J"),
            ("energy_friction_loss", o.energy.friction_loss, "J"),
            ("energy_residual", o.energy.residual(), "J"),
        ] {
            let _ = writeln!(w, "{name:<24} {:>12} {unit}", sig(value));
        }
        let _ = writeln!(w, "{:<24} {:>12}", "evaluations", o.evaluations);
        if let Some(f) = &self.flight {
            let _ = write!(w, "\nflight:\n{}", f.text());
        }
        w
    }
}

/// The rapier scene path at steps 4e-5 s halving to 6.25e-7 s against the
/// accurate path: error, observed order and wall time per step.
#[derive(Debug, Clone, serde::Serialize)]
pub struct SceneConvergence {
    pub rows: Vec<kick_3d::scene::ConvergenceRow>,
    /// Wall time of the accurate path, s.
    pub accurate_seconds: f64,
}

pub fn scene_convergence(spec: &KickSpec) -> Result<SceneConvergence, String> {
    spec.scenario.check_given().map_err(|e| e.to_string())?;
    let kick = spec.build().map_err(|e| e.to_string())?;
    let steps: Vec<f64> = (0..7).map(|i| 4e-5 / f64::from(1u32 << i)).collect();
    let (rows, accurate_seconds) = kick_3d::scene::convergence(&kick, &steps).map_err(|e| e.to_string())?;
    Ok(SceneConvergence { rows, accurate_seconds })
}

impl Printable for SceneConvergence {
    fn text(&self) -> String {
        let mut w = String::new();
        let _ = writeln!(w, "accurate-3d: {:.3} ms", self.accurate_seconds * 1e3);
        let _ = writeln!(w, "{:>10} {:>12} {:>12} {:>12} {:>7} {:>10}", "dt_s", "velocity", "spin", "contact_t", "order", "ms");
        for r in &self.rows {
            let order = r.velocity_order.map_or("-".to_string(), |p| format!("{p:.3}"));
            let _ = writeln!(
                w,
                "{:>10.3e} {:>12.3e} {:>12.3e} {:>12.3e} {:>7} {:>10.3}",
                r.step, r.velocity_error, r.spin_error, r.contact_time_error, order, r.seconds * 1e3
            );
        }
        w
    }
}
