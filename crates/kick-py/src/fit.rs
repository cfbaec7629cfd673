//! `fit`: the identification of `kick fit data` (crate kick-identify) from
//! arrays instead of a specification file and a CSV file.

use crate::{guard, value_error};
use kick_core::parameters::{self, SetParameter};
use kick_core::ScenarioSpec;
use kick_identify::data::{Channel, HistoryData, WeightedHistory};
use kick_identify::fit::{fit as identify, FitOptions, FitProblem};
use kick_identify::{FitSpec, Observations};
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::BTreeMap;

/// Where a refusal says the data came from.
const SOURCE: &str = "fit data";

/// Fit `free` to the channels given (force, compression, foot_velocity,
/// ball_velocity: arrays over `time`), the other parameters known.
#[pyfunction]
#[pyo3(signature = (time, force = None, *, sigma, free, law = "power-law", time_offset = None, **data))]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    time: Vec<f64>,
    force: Option<Vec<f64>>,
    sigma: &Bound<'py, PyAny>,
    free: Vec<String>,
    law: &str,
    time_offset: Option<f64>,
    data: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        // Keywords: channels (arrays over time) or known 1D parameters.
        let mut channels: Vec<(Channel, Vec<f64>)> = force.map(|f| (Channel::Force, f)).into_iter().collect();
        let known = PyDict::new(py);
        if let Some(data) = data {
            for (key, value) in data.iter() {
                let name: String = key.extract()?;
                match Channel::from_name(&name) {
                    Ok(channel) if !value.is_none() => channels.push((channel, value.extract()?)),
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
        let sigma: BTreeMap<Channel, f64> = match sigma.extract::<f64>() {
            Ok(s) => data.channels.iter().map(|(c, _)| (*c, s)).collect(),
            Err(_) => {
                let given: BTreeMap<String, f64> = sigma.extract()?;
                given.iter().map(|(k, v)| Ok((Channel::from_name(k).map_err(value_error)?, *v))).collect::<PyResult<_>>()?
            }
        };
        let observations = Observations::history(WeightedHistory::new(data, sigma).map_err(value_error)?);
        let scenario = crate::params::scenario_spec(Some(&known), crate::law(law)?)?;
        let spec = FitSpec {
            free,
            law: None,
            restitution: None,
            time_offset,
            scenario,
            scalar: Vec::new(),
            history: None,
            truth: None,
        };
        let start = spec.start(SOURCE).map_err(value_error)?;
        let free = spec.free_parameters().map_err(value_error)?;
        let problem = FitProblem { start, free, observations };
        let report = py.detach(|| identify(&problem, &FitOptions::default())).map_err(value_error)?;

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
