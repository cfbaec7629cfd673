//! One contact, 1D (`kick simulate`) or 3D (`kick simulate3d`): the solve and
//! its JSON and text forms.

use crate::error::StudyError;
use crate::flight::{self, FlightPlan, FlightRun};
use crate::history::{self, HistoryMeta, HistoryRequest};
use crate::printable::Printable;
use kick_3d::{Kick3d, KickSpec, Outcome3d, Solver3d};
use kick_compliant::SolverChoice;
use kick_core::number::{sig, vector};
use kick_core::{KickError, Outcome, Parameter, RecordingSolver, Scenario, ScenarioSpec, Solver, HISTORY_COLUMNS, OBSERVABLES};
use serde::ser::{Serialize, Serializer};
use serde_json::{Map, Value};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

/// A 1D run: the scenario, the solver and what it gave.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    pub scenario: Scenario,
    pub solver: &'static str,
    pub outcome: Outcome,
    /// The ball's flight after the kick, when asked for.
    pub flight: Option<FlightRun>,
    /// The history file, when asked for.
    pub written: Vec<PathBuf>,
}

/// The parameters a 1D history file records (`/fixed`): the eight
/// [`Parameter`]s and the law's target restitution, with the solver and law.
fn meta_1d(scenario: &Scenario, solver: &str) -> HistoryMeta {
    let mut meta = HistoryMeta { level: "1d".into(), ..HistoryMeta::default() };
    meta.texts.push(("solver".into(), solver.into()));
    meta.texts.push(("law".into(), scenario.law_kind().name().into()));
    for p in Parameter::ALL {
        meta.fixed.push((p.name().into(), p.unit().into(), vec![scenario.get(p)]));
    }
    if let Some(e) = scenario.restitution_target() {
        let def = &kick_core::parameters::RESTITUTION;
        meta.fixed.push((def.name.into(), def.unit.into(), vec![e]));
    }
    for (name, value) in scenario.foot().settings() {
        let unit = kick_core::parameters::find(name).map_or("", |p| p.unit);
        meta.fixed.push((name.into(), unit.into(), vec![value]));
    }
    meta
}

/// Solve `spec` with the solver named `solver` (`dt`: step of the fixed-step
/// solvers, refused with the others); with `history`, its time history streamed into that file
/// ([`crate::history`], columns [`HISTORY_COLUMNS`]); with `flight`, the
/// ball's flight after it ([`flight::after_1d`]).
pub fn simulate(
    spec: &ScenarioSpec,
    solver: &str,
    dt: Option<f64>,
    history: Option<&HistoryRequest>,
    flight: Option<&FlightPlan>,
) -> Result<Simulation, StudyError> {
    let scenario = spec.build()?;
    let choice = SolverChoice::with_step(solver, dt)?;
    let (outcome, written) = match history {
        Some(request) => {
            let meta = meta_1d(&scenario, choice.name());
            let (outcome, path) = history::write(
                request,
                &HISTORY_COLUMNS,
                &meta,
                |s: &kick_core::Sample| s.values().to_vec(),
                |sink| {
                    let streamed = choice.solve_streamed(&scenario, request.spacing, sink)?;
                    Ok::<_, KickError>((streamed.outcome, streamed.samples))
                },
            )?;
            (outcome, vec![path])
        }
        None => (choice.solve(&scenario)?, Vec::new()),
    };
    let flight = flight.map(|plan| flight::after_1d_plan(&scenario, &outcome, plan)).transpose()?;
    Ok(Simulation { scenario, solver: choice.name(), outcome, flight, written })
}

/// The JSON object of one run: every observable, the energy residual, the
/// solver, the path it took, the scenario and its contact law.
pub fn outcome_json(scenario: &Scenario, solver: &str, outcome: &Outcome) -> Map<String, Value> {
    let mut object = Map::new();
    for ((name, _), value) in OBSERVABLES.iter().zip(outcome.observable_values()) {
        object.insert((*name).into(), value.into());
    }
    // Undefined (v_f⁻ = 0): null, not a number.
    object.insert("speed_ratio".into(), outcome.speed_ratio.into());
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
    if let Some(foot) = foot_json(scenario) {
        object.insert("foot".into(), foot);
    }
    object
}

impl Simulation {
    /// Why the contact lies outside its law's validity, if it does.
    pub fn outside_validity(&self) -> Option<kick_core::OutsideValidity> {
        self.scenario.check_validity(&self.outcome).err()
    }
}

/// One line naming the foot when it is not Table 1's rigid one.
fn foot_line(scenario: &Scenario) -> Option<String> {
    let foot = scenario.foot();
    let leg = foot.leg.map(|p| {
        format!(
            "the leg (knee {}, ankle {}, hip {} deg; {} kg along the line of motion)",
            sig(p.knee),
            sig(p.ankle),
            sig(p.hip),
            sig(scenario.effective_foot_mass())
        )
    });
    let boot = foot.boot.map(|b| format!("a boot in series (k_b {} N/m, c_b {} N s/m)", sig(b.stiffness), sig(b.damping)));
    match (leg, boot) {
        (None, None) => None,
        (Some(l), None) => Some(format!("foot: {l}, no boot")),
        (None, Some(b)) => Some(format!("foot: rigid, {b}")),
        (Some(l), Some(b)) => Some(format!("foot: {l}, {b}")),
    }
}

/// The foot behind the contact when it is not Table 1's rigid one: the
/// leg's pose and its apparent mass along the line of motion (Eq. 11, the
/// scenario's foot mass), the boot; JSON has no infinity, so no boot is null.
fn foot_json(scenario: &Scenario) -> Option<Value> {
    let foot = scenario.foot();
    if foot == kick_core::Foot::RIGID {
        return None;
    }
    let mut settings = Map::new();
    for (name, value) in foot.settings() {
        settings.insert(name.into(), if value.is_finite() { value.into() } else { Value::Null });
    }
    if foot.leg.is_some() {
        settings.insert("effective_mass".into(), scenario.effective_foot_mass().into());
    }
    Some(Value::Object(settings))
}

impl Serialize for Simulation {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut object = outcome_json(&self.scenario, self.solver, &self.outcome);
        crate::printable::insert_status(&mut object, self.outside_validity().as_ref());
        if let Some(f) = &self.flight {
            object.insert("flight".into(), serde_json::to_value(f).map_err(serde::ser::Error::custom)?);
        }
        object.serialize(serializer)
    }
}

impl Printable for Simulation {
    fn text(&self) -> String {
        let mut w = String::new();
        let o = &self.outcome;
        let _ = writeln!(w, "solver: {} (path: {})", self.solver, o.method);
        if let Some(line) = foot_line(&self.scenario) {
            let _ = writeln!(w, "{line}");
        }
        for ((name, unit), value) in OBSERVABLES.iter().zip(o.observable_values()) {
            let value = if *name == "speed_ratio" && o.speed_ratio.is_none() { "undefined".to_string() } else { sig(value).to_string() };
            let _ = writeln!(w, "{name:<24} {value:>12} {unit}");
        }
        let _ = writeln!(w, "{:<24} {:>12} J", "energy_residual", sig(o.energy.residual()));
        if let Some(outside) = self.outside_validity() {
            let _ = writeln!(w, "{:<24} {outside}", "status: outside validity");
        }
        if let Some(f) = &self.flight {
            let _ = write!(w, "\nflight:\n{}", f.text());
        }
        w
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
    fn outside_validity(&self) -> Option<String> {
        Simulation::outside_validity(self).map(|o| o.to_string())
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
    /// The history file, when asked for.
    pub written: Vec<PathBuf>,
}

/// The parameters a 3D history file records (`/fixed`): every declared 1D
/// and 3D parameter as the kick was built ([`Kick3d::parameter_values`]).
pub fn meta_3d(kick: &Kick3d) -> HistoryMeta {
    let mut meta = HistoryMeta { level: "3d".into(), ..HistoryMeta::default() };
    meta.texts.push(("solver".into(), "accurate-3d".into()));
    meta.texts.push(("law".into(), kick.base.law_kind().name().into()));
    for (def, value) in kick.parameter_values() {
        meta.push_value(def.name, def.unit, value);
    }
    meta
}

/// The accurate path a 3D history needs: `auto` or `accurate` (the other
/// paths sample no history).
fn history_solver(solver: &Solver3d) -> Result<kick_3d::Accurate3d, StudyError> {
    match solver {
        Solver3d::Auto => Ok(kick_3d::Accurate3d::default()),
        Solver3d::Accurate(a) => Ok(*a),
        _ => Err(StudyError::Flag {
            flag: "history",
            message: "--history samples the accurate 3D path: use --solver accurate (or auto)".into(),
        }),
    }
}

/// Solve the 3D kick `spec` with the path named `solver` (`dt`: the rapier
/// scene path's step, refused with the others); with `history`, on the accurate path, its time history
/// streamed into that file ([`crate::history`], columns
/// [`kick_3d::HISTORY_COLUMNS_3D`]); with `flight` given, the ball's flight
/// after it from the ground, crossing the plan's planes ([`flight::after_3d_plan`]; not in `seconds`).
pub fn simulate3d(
    spec: &KickSpec,
    solver: &str,
    dt: Option<f64>,
    history: Option<&HistoryRequest>,
    flight: Option<&FlightPlan>,
) -> Result<Simulation3d, StudyError> {
    let kick = spec.build()?;
    let solver = Solver3d::with_step(solver, dt)?;
    let start = Instant::now();
    let (outcome, written) = match history {
        Some(request) => {
            let (outcome, path) = history3d(&kick, &solver, request)?;
            (outcome, vec![path])
        }
        None => (solver.solve(&kick)?, Vec::new()),
    };
    let seconds = start.elapsed().as_secs_f64();
    let flight = flight.map(|plan| flight::after_3d_plan(&kick, &outcome, plan)).transpose()?;
    Ok(Simulation3d { kick, outcome, seconds, flight, written })
}

/// The accurate path's history of `spec` collected, at most
/// [`kick_core::MAX_HISTORY_SAMPLES`] rows (Python's `kick.history3d`);
/// `solver` as for [`simulate3d`] with a history.
pub fn sampled3d(spec: &KickSpec, solver: &str, spacing: kick_core::Spacing) -> Result<(Outcome3d, Vec<kick_3d::Sample3d>), StudyError> {
    let kick = spec.build()?;
    // The name first, with a valid step: a scene path's own `dt` check would
    // blame a step this call never takes.
    let accurate = match Solver3d::from_name(solver, 1e-5)? {
        Solver3d::Auto => kick_3d::Accurate3d::default(),
        Solver3d::Accurate(a) => a,
        _ => {
            return Err(StudyError::Flag {
                flag: "solver",
                message: format!("a time history samples the accurate 3D path: `solver` = {solver} gives none (use accurate or auto)"),
            })
        }
    };
    Ok(accurate.solve_sampled(&kick, spacing, kick_core::MAX_HISTORY_SAMPLES)?)
}

/// Write the accurate path's history of `kick` into `request`'s file; a
/// kick whose normal force is spread over a patch also gets
/// [`kick_3d::PATCH_COLUMNS_3D`] (its moment and friction's arm).
pub fn history3d(kick: &Kick3d, solver: &Solver3d, request: &HistoryRequest) -> Result<(Outcome3d, PathBuf), StudyError> {
    let accurate = history_solver(solver)?;
    let solve =
        |sink: &mut dyn FnMut(&kick_3d::Sample3d) -> std::ops::ControlFlow<()>| accurate.solve_streamed(kick, request.spacing, sink);
    if kick.instep.is_some_and(|i| i.patch.is_some()) {
        let columns: Vec<(&str, &str)> = kick_3d::HISTORY_COLUMNS_3D.iter().chain(&kick_3d::PATCH_COLUMNS_3D).copied().collect();
        history::write(request, &columns, &meta_3d(kick), |s: &kick_3d::Sample3d| [&s.values()[..], &s.patch_values()].concat(), solve)
    } else {
        history::write(request, &kick_3d::HISTORY_COLUMNS_3D, &meta_3d(kick), |s: &kick_3d::Sample3d| s.values().to_vec(), solve)
    }
}

impl Simulation3d {
    /// Why the kick lies outside its normal law's validity, if it does.
    pub fn outside_validity(&self) -> Option<kick_core::OutsideValidity> {
        self.kick.check_validity(&self.outcome).err()
    }
}

/// The JSON object of one 3D run: the outcome (with `law`, the normal law's
/// name), the energy residual, `law_parameters` (the law as solved) and
/// the `status` ([`crate::printable::insert_status`]).
impl Serialize for Simulation3d {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let o = &self.outcome;
        let mut m = match serde_json::to_value(o).map_err(serde::ser::Error::custom)? {
            Value::Object(m) => m,
            _ => return Err(serde::ser::Error::custom("outcome is not an object")),
        };
        m.insert("energy_residual".into(), o.energy.residual().into());
        m.insert("law_parameters".into(), serde_json::to_value(self.kick.law()).map_err(serde::ser::Error::custom)?);
        crate::printable::insert_status(&mut m, self.outside_validity().as_ref());
        if let Some(foot) = foot_json(&self.kick.base) {
            m.insert("foot".into(), foot);
        }
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
        if let Some(line) = foot_line(&self.kick.base) {
            let _ = writeln!(w, "{line}");
        }
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
        if let Some(outside) = self.outside_validity() {
            let _ = writeln!(w, "{:<24} {outside}", "status: outside validity");
        }
        if let Some(f) = &self.flight {
            let _ = write!(w, "\nflight:\n{}", f.text());
        }
        w
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
    fn outside_validity(&self) -> Option<String> {
        Simulation3d::outside_validity(self).map(|o| o.to_string())
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

pub fn scene_convergence(spec: &KickSpec) -> Result<SceneConvergence, StudyError> {
    let kick = spec.build()?;
    let steps: Vec<f64> = (0..7).map(|i| 4e-5 / f64::from(1u32 << i)).collect();
    let (rows, accurate_seconds) = kick_3d::scene::convergence(&kick, &steps)?;
    Ok(SceneConvergence { rows, accurate_seconds })
}

impl Printable for SceneConvergence {
    fn text(&self) -> String {
        let mut w = String::new();
        let _ = writeln!(w, "accurate-3d: {} ms", sig(self.accurate_seconds * 1e3));
        let _ = writeln!(w, "{:>10} {:>12} {:>12} {:>12} {:>7} {:>10}", "dt_s", "velocity", "spin", "contact_t", "order", "ms");
        for r in &self.rows {
            let order = r.velocity_order.map_or("-".to_string(), |p| sig(p).to_string());
            let _ = writeln!(
                w,
                "{:>10} {:>12} {:>12} {:>12} {:>7} {:>10}",
                sig(r.step),
                sig(r.velocity_error),
                sig(r.spin_error),
                sig(r.contact_time_error),
                order,
                sig(r.seconds * 1e3)
            );
        }
        w
    }
}
