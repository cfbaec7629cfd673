//! `flight`: the ball's flight after the kick (crate kick-flight), keywords
//! from its declared list (`kick_flight::spec::FLIGHT_PARAMETERS`).

use crate::{guard, value_error};
use kick_core::parameters;
use kick_flight::spec::{FlightParameter, FlightSpec, FLIGHT_PARAMETERS};
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pyfunction]
#[pyo3(signature = (**params))]
pub fn flight<'py>(py: Python<'py>, params: Option<&Bound<'py, PyDict>>) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let mut spec = FlightSpec::default();
        if let Some(params) = params {
            for (key, value) in params.iter() {
                let name: String = key.extract()?;
                let parameter = FlightParameter::from_name(&name).map_err(|_| {
                    let valid: Vec<&str> = FLIGHT_PARAMETERS.iter().map(|p| p.name).collect();
                    value_error(format!(
                        "unknown flight parameter `{name}`{}",
                        parameters::did_you_mean(&parameters::nearby(&name, &valid), &valid)
                    ))
                })?;
                if value.is_none() {
                    continue;
                }
                let values = crate::params::value(parameter.def(), &value)?.numbers();
                spec.set(parameter, &values).map_err(value_error)?;
            }
        }
        let flight = spec.build().map_err(value_error)?;
        let outcome = py.detach(|| kick_flight::solve::solve(&flight)).map_err(value_error)?;
        crate::convert::json_to_py(py, &serde_json::to_value(outcome).map_err(value_error)?)
    })
}
