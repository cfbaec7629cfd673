//! The objects `kick simulate --format json` and `kick simulate3d --format
//! json` print, from the same library functions the CLI calls
//! (`kick_study::simulate`), so Python and the command line cannot drift;
//! `tests/test_simulate.py` compares every key with the CLI's output.

use kick_3d::KickSpec;
use kick_core::ScenarioSpec;
use kick_study::{Printable, StudyError};
use serde_json::Value;

/// `kick simulate --format json` (without `--history`); `dt` as given (None:
/// the default step); and why it lies outside its law's validity, if it does.
pub fn simulate(spec: &ScenarioSpec, solver: &str, dt: Option<f64>) -> Result<(Value, Option<String>), StudyError> {
    printed(&kick_study::simulate::simulate(spec, solver, dt, None, None)?)
}

/// `kick simulate3d --format json` (with `--flight` when `flight` is given),
/// and why it lies outside its law's validity.
pub fn simulate3d(
    spec: &KickSpec,
    solver: &str,
    dt: Option<f64>,
    flight: Option<&kick_study::flight::FlightPlan>,
) -> Result<(Value, Option<String>), StudyError> {
    printed(&kick_study::simulate::simulate3d(spec, solver, dt, None, flight)?)
}

/// A result as the command line prints it in JSON, with its flag.
fn printed(result: &impl Printable) -> Result<(Value, Option<String>), StudyError> {
    Ok((serde_json::to_value(result).map_err(|e| StudyError::Json(e.to_string()))?, result.outside_validity()))
}
