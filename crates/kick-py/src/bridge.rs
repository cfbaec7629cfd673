//! The objects `kick simulate --format json` and `kick simulate3d --format
//! json` print, from the same library functions the CLI calls
//! (`kick_study::simulate`), so Python and the command line cannot drift;
//! `tests/test_simulate.py` compares every key with the CLI's output.

use kick_3d::KickSpec;
use kick_core::ScenarioSpec;
use kick_study::StudyError;
use serde_json::Value;

/// `kick simulate --format json` (without `--history`); `dt` as given (None: the default step).
pub fn simulate(spec: &ScenarioSpec, solver: &str, dt: Option<f64>) -> Result<Value, StudyError> {
    serde_json::to_value(kick_study::simulate::simulate(spec, solver, dt, None, None)?).map_err(|e| StudyError::Json(e.to_string()))
}

/// `kick simulate3d --format json` (with `--flight` when `flight` is given).
pub fn simulate3d(
    spec: &KickSpec,
    solver: &str,
    dt: Option<f64>,
    flight: Option<&kick_study::flight::FlightPlan>,
) -> Result<Value, StudyError> {
    serde_json::to_value(kick_study::simulate::simulate3d(spec, solver, dt, None, flight)?).map_err(|e| StudyError::Json(e.to_string()))
}
