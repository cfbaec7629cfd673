//! The objects `kick simulate --format json` and `kick simulate3d --format
//! json` print, from the same library functions the CLI calls
//! (`kick_runner::simulate`), so Python and the command line cannot drift;
//! `tests/test_simulate.py` compares every key with the CLI's output.

use kick_3d::KickSpec;
use kick_core::ScenarioSpec;
use serde_json::Value;

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
    serde_json::to_value(kick_runner::simulate::simulate(spec, solver, dt, None, None)?).map_err(|e| e.to_string())
}

/// `kick simulate3d --format json`.
pub fn simulate3d(spec: &KickSpec, solver: &str, dt: f64) -> Result<Value, String> {
    serde_json::to_value(kick_runner::simulate::simulate3d(spec, solver, dt, None, None)?).map_err(|e| e.to_string())
}
