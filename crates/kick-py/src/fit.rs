//! `fit`: the identification of `kick fit data` (crate kick-identify) from
//! arrays instead of a specification file and a CSV file.

use crate::params::{names, optional_number, real_number, real_vector};
use crate::{guard, library_error, value_error};
use kick_core::parameters::{self, SetParameter};
use kick_core::ScenarioSpec;
use kick_identify::data::{Channel, HistoryData, WeightedHistory};
use kick_identify::fit::{fit_with_cancel, FitOptions, FitProblem};
use kick_identify::{FitSpec, Observations};
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::BTreeMap;
use std::sync::atomic::Ordering;

/// Where a refusal says the data came from.
const SOURCE: &str = "fit data";

/// Fit `free` to the channels given (force, compression, foot_velocity,
/// ball_velocity: arrays over `time`), the other parameters known.
#[pyfunction]
#[pyo3(signature = (time, force = None, *, sigma, free, law = "power-law", time_offset = None, **data))]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    time: &Bound<'py, PyAny>,
    force: Option<&Bound<'py, PyAny>>,
    sigma: &Bound<'py, PyAny>,
    free: &Bound<'py, PyAny>,
    law: &str,
    time_offset: Option<&Bound<'py, PyAny>>,
    data: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        // Keywords: channels (arrays over time) or known 1D parameters.
        let time = real_vector("time", time)?;
        let time_offset = optional_number("time_offset", time_offset)?;
        let free = names("free", free)?;
        let mut channels: Vec<(Channel, Vec<f64>)> = Vec::new();
        if let Some(force) = force.filter(|f| !f.is_none()) {
            channels.push((Channel::Force, real_vector("force", force)?));
        }
        let known = PyDict::new(py);
        if let Some(data) = data {
            for (key, value) in data.iter() {
                let name: String = key.extract()?;
                match Channel::from_name(&name) {
                    Ok(channel) if !value.is_none() => channels.push((channel, real_vector(&name, &value)?)),
                    Ok(_) => {}
                    Err(_) if parameters::find_at(ScenarioSpec::LEVELS, &name).is_ok() => known.set_item(key, value)?,
                    Err(_) => {
                        let mut valid: Vec<&str> = Channel::ALL.iter().map(|c| c.name()).collect();
                        valid.extend(parameters::at_levels(ScenarioSpec::LEVELS).map(|p| p.name));
                        return Err(value_error(format!(
                            "unknown keyword `{name}`{}",
                            parameters::did_you_mean(&parameters::nearby(&name, &valid), &valid)
                        )));
                    }
                }
            }
        }
        let data = HistoryData { times: time, channels }.checked(SOURCE).map_err(value_error)?;
        // One sigma for every channel, or one per channel by name.
        let sigma: BTreeMap<Channel, f64> = match sigma.cast::<PyDict>() {
            Ok(given) => given
                .iter()
                .map(|(k, v)| {
                    let name: String =
                        k.extract().map_err(|_| PyTypeError::new_err(format!("`sigma`'s keys are channel names, got {k}")))?;
                    Ok((Channel::from_name(&name).map_err(value_error)?, real_number(&format!("sigma[{name:?}]"), &v)?))
                })
                .collect::<PyResult<_>>()?,
            Err(_) => {
                let s = real_number("sigma", sigma).map_err(|e| {
                    let got = sigma.get_type().name().map(|n| n.to_string()).unwrap_or_default();
                    if e.is_instance_of::<PyTypeError>(py) {
                        PyTypeError::new_err(format!(
                            "`sigma` takes a number or a dict {{channel: number}}, got {got} {}",
                            sigma.repr().map(|r| r.to_string()).unwrap_or_default()
                        ))
                    } else {
                        e
                    }
                })?;
                data.channels.iter().map(|(c, _)| (*c, s)).collect()
            }
        };
        let observations = Observations::history(WeightedHistory::new(data, sigma).map_err(value_error)?);
        let scenario = crate::params::scenario_spec(Some(&known), crate::law(law)?)?;
        let spec = FitSpec {
            level: None,
            free,
            law: None,
            restitution: None,
            time_offset,
            scenario,
            bounce: None,
            scalar: Vec::new(),
            history: None,
            measurement: Vec::new(),
            truth: None,
        };
        let start = spec.start(SOURCE).map_err(value_error)?;
        let free = spec.free_parameters().map_err(value_error)?;
        let problem = FitProblem { start, free, observations };
        // Ctrl-C stops the optimiser at its next model evaluation (KeyboardInterrupt).
        let report =
            crate::interruptible(py, |cancel| fit_with_cancel(&problem, &FitOptions::default(), &|| cancel.load(Ordering::Relaxed)))?
                .map_err(library_error)?;
        // As `kick fit data` (which exits 1): the numbers are kept, flagged.
        let outside: Vec<String> = report.outside_validity.iter().map(|o| o.to_string()).collect();
        crate::warn_outside(py, (!outside.is_empty()).then(|| outside.join("; ")))?;

        let out = PyDict::new(py);
        let names: Vec<&str> = report.estimates.iter().map(|e| e.parameter.name()).collect();
        let column = |f: &dyn Fn(&kick_identify::Estimate) -> f64| -> Vec<f64> { report.estimates.iter().map(f).collect() };
        let n = names.len();
        let matrix = |m: Option<Vec<Vec<f64>>>| m.unwrap_or_else(|| vec![vec![f64::NAN; n]; n]);
        out.set_item("names", names.clone())?;
        out.set_item("units", report.estimates.iter().map(|e| e.parameter.unit()).collect::<Vec<_>>())?;
        out.set_item("estimate", PyArray1::from_vec(py, column(&|e| e.value)))?;
        out.set_item("standard_error", PyArray1::from_vec(py, column(&|e| e.standard_uncertainty.unwrap_or(f64::NAN))))?;
        out.set_item("start", PyArray1::from_vec(py, column(&|e| e.start)))?;
        out.set_item("covariance", PyArray2::from_vec2(py, &matrix(report.covariance())).map_err(value_error)?)?;
        out.set_item("correlation", PyArray2::from_vec2(py, &matrix(report.correlation.clone())).map_err(value_error)?)?;
        out.set_item("singular_values", PyArray1::from_vec(py, report.singular_values.clone()))?;
        out.set_item("residuals", PyArray1::from_vec(py, report.residuals.iter().map(|r| r.weighted).collect()))?;
        out.set_item("predicted", PyArray1::from_vec(py, report.residuals.iter().map(|r| r.predicted).collect()))?;
        out.set_item("chi_square", report.chi_square)?;
        out.set_item("degrees_of_freedom", report.degrees_of_freedom)?;
        out.set_item("residual_variance", report.residual_variance)?;
        let stop = serde_json::to_value(report.stop).ok();
        out.set_item("stop", stop.as_ref().and_then(|s| s["kind"].as_str()))?;
        out.set_item("termination", &report.termination)?;
        out.set_item("converged", report.converged)?;
        out.set_item("evaluations", report.evaluations)?;
        out.set_item("law", report.law.name())?;
        Ok(out)
    })
}
