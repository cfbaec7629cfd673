//! MERGE (issue 15 with the application-layer move on branch `arch`): the ONE
//! place where kick-py builds the objects `kick simulate --format json` and
//! `kick simulate3d --format json` print.
//!
//! When this branch was started those objects were built in the command line
//! (`crates/kick-cli/src/simulate.rs::outcome_json`,
//! `crates/kick-cli/src/simulate3d.rs::outcome_json`), which a library cannot
//! call. Branch `arch` moves them to `kick_runner::simulate::{simulate,
//! simulate3d}` (types `Simulation`, `Simulation3d`, serialized to exactly
//! those objects). At merge, replace each body below by
//! `serde_json::to_value(kick_runner::simulate::simulate(spec, solver, dt, None)?)`
//! (and `simulate3d(spec, solver, dt)`), add kick-runner to kick-py's
//! dependencies and delete the rest of this file; the pytest suite
//! (`tests/test_simulate.rs`) compares every key with the CLI's output.

use kick_3d::{KickSpec, Solver3d};
use kick_compliant::SolverChoice;
use kick_core::{Parameter, ScenarioSpec, Solver, OBSERVABLES};
use serde_json::{Map, Value};

/// seed-rk4's step when `dt` is not given (`kick simulate --dt`'s default).
pub fn default_dt() -> f64 {
    kick_compliant::SeedRk4::default().step
}

/// The rapier scene path's step when `dt` is not given (`kick simulate3d --dt`'s default).
pub fn default_scene_dt() -> f64 {
    kick_3d::scene::Scene::default().step
}

/// `kick simulate --format json` (without `--history`).
pub fn simulate(spec: &ScenarioSpec, solver: &str, dt: f64) -> Result<Value, String> {
    let scenario = spec.build().map_err(|e| e.to_string())?;
    let solver = SolverChoice::from_name(solver, dt).map_err(|e| e.to_string())?;
    let outcome = solver.solve(&scenario).map_err(|e| e.to_string())?;
    let mut object = Map::new();
    for ((name, _), value) in OBSERVABLES.iter().zip(outcome.observable_values()) {
        object.insert((*name).into(), value.into());
    }
    object.insert("energy_residual".into(), outcome.energy.residual().into());
    object.insert("solver".into(), solver.name().into());
    object.insert("method".into(), outcome.method.into());
    object.insert("stop".into(), serde_json::to_value(outcome.stop).unwrap_or(Value::Null));
    object.insert("evaluations".into(), outcome.evaluations.into());
    let mut parameters = Map::new();
    for p in Parameter::ALL {
        parameters.insert(p.name().into(), scenario.get(p).into());
    }
    object.insert("scenario".into(), Value::Object(parameters));
    object.insert("law".into(), serde_json::to_value(scenario.contact_law()).unwrap_or(Value::Null));
    Ok(Value::Object(object))
}

/// `kick simulate3d --format json`.
pub fn simulate3d(spec: &KickSpec, solver: &str, dt: f64) -> Result<Value, String> {
    let kick = spec.build().map_err(|e| e.to_string())?;
    let solver = Solver3d::from_name(solver, dt).map_err(|e| e.to_string())?;
    let o = solver.solve(&kick).map_err(|e| e.to_string())?;
    match serde_json::to_value(o).map_err(|e| e.to_string())? {
        Value::Object(mut m) => {
            m.insert("energy_residual".into(), o.energy.residual().into());
            m.insert("law_parameters".into(), serde_json::to_value(kick.law()).map_err(|e| e.to_string())?);
            Ok(Value::Object(m))
        }
        _ => Err("outcome is not an object".into()),
    }
}
