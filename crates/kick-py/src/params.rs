//! Keywords to specs, by the declared parameter lists: a keyword is a
//! parameter's name, and nothing else is accepted.

use crate::value_error;
use kick_3d::KickSpec;
use kick_core::parameters::{self, ParameterDef, ParameterError, SetLaw, SetParameter, Shape, Value};
use kick_core::{LawKind, ScenarioSpec, Status};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList};

/// A spec keywords fill: its levels' parameters and the contact law.
pub trait LawSpec: SetParameter + SetLaw + Default {}

impl<S: SetParameter + SetLaw + Default> LawSpec for S {}

/// The shape a Python value has: a bool is a switch, a sequence a vector,
/// anything `float()` takes a number.
fn shape_of(value: &Bound<'_, PyAny>) -> Option<Shape> {
    if value.is_instance_of::<PyBool>() {
        Some(Shape::Switch)
    } else if value.extract::<f64>().is_ok() {
        Some(Shape::Scalar)
    } else if value.len().is_ok() {
        Some(Shape::Vector3)
    } else {
        None
    }
}

/// One value for `parameter`, or an error naming it.
pub fn value(parameter: &'static ParameterDef, value: &Bound<'_, PyAny>) -> PyResult<Value> {
    let wrong = |found: Shape| value_error(ParameterError::WrongShape { name: parameter.name, expected: parameter.shape, found });
    let found = shape_of(value).ok_or_else(|| {
        PyTypeError::new_err(format!(
            "`{}` takes {}, got a {}",
            parameter.name,
            parameter.shape.describe(),
            value.get_type().name().map(|n| n.to_string()).unwrap_or_default()
        ))
    })?;
    if found != parameter.shape {
        return Err(wrong(found));
    }
    Ok(match parameter.shape {
        Shape::Scalar => Value::Number(value.extract()?),
        Shape::Switch => Value::Switch(value.extract()?),
        Shape::Vector3 => match value.extract::<Vec<f64>>() {
            Ok(v) if v.len() == 3 => Value::Vector([v[0], v[1], v[2]]),
            _ => {
                return Err(PyTypeError::new_err(format!(
                    "`{}` takes three numbers (x, y, z), got {}",
                    parameter.name,
                    value.repr()?
                )))
            }
        },
    })
}

/// The spec the keywords give (the rest left to the declared defaults) with
/// contact law `law`. `None` leaves a parameter at its default.
pub fn spec<S: LawSpec>(params: Option<&Bound<'_, PyDict>>, law: LawKind) -> PyResult<S> {
    let mut spec = S::default();
    spec.set_law(law);
    if let Some(params) = params {
        for (key, v) in params.iter() {
            let name: String = key.extract()?;
            let parameter = parameters::find_at(S::LEVELS, &name).map_err(value_error)?;
            if !v.is_none() {
                spec.set_parameter(parameter, value(parameter, &v)?).map_err(value_error)?;
            }
        }
    }
    Ok(spec)
}

pub fn scenario_spec(params: Option<&Bound<'_, PyDict>>, law: LawKind) -> PyResult<ScenarioSpec> {
    spec(params, law)
}

pub fn kick_spec(params: Option<&Bound<'_, PyDict>>, law: LawKind) -> PyResult<KickSpec> {
    spec(params, law)
}

/// A declaration as a dict (name, symbol, unit, level, shape, default, doc, requirement).
fn declaration<'py>(py: Python<'py>, p: &ParameterDef) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", p.name)?;
    d.set_item("symbol", p.symbol)?;
    d.set_item("unit", p.unit)?;
    d.set_item("level", serde_json::to_value(p.level).ok().and_then(|v| v.as_str().map(String::from)))?;
    d.set_item("shape", serde_json::to_value(p.shape).ok().and_then(|v| v.as_str().map(String::from)))?;
    // Numbers and vectors as values; derived and unset defaults are None with their text.
    let default = match p.default {
        kick_core::parameters::DefaultValue::Number(x) => x.into_pyobject(py)?.into_any(),
        kick_core::parameters::DefaultValue::Vector(v) => v.to_vec().into_pyobject(py)?.into_any(),
        kick_core::parameters::DefaultValue::Off => false.into_pyobject(py)?.to_owned().into_any(),
        _ => py.None().into_bound(py),
    };
    d.set_item("default", default)?;
    d.set_item("default_text", p.default.text())?;
    d.set_item("doc", p.doc)?;
    d.set_item("requirement", p.valid.requirement)?;
    d.set_item("help", p.help())?;
    Ok(d)
}

/// Every declared parameter (1D, 3D and flight levels), in declaration order.
#[pyfunction]
#[pyo3(name = "parameters")]
pub fn declared(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for p in parameters::PARAMETERS.iter().chain(kick_flight::spec::FLIGHT_PARAMETERS.iter()) {
        list.append(declaration(py, p)?)?;
    }
    Ok(list)
}

/// The parameter keywords of a function: `simulate`, `simulate3d`, `flight`,
/// their `_many` forms, `history` or `history3d`.
#[pyfunction]
pub fn keywords(function: &str) -> PyResult<Vec<&'static str>> {
    Ok(match function {
        "simulate" | "simulate_many" | "history" => parameters::at_levels(ScenarioSpec::LEVELS).map(|p| p.name).collect(),
        "simulate3d" | "simulate3d_many" | "history3d" => parameters::at_levels(KickSpec::LEVELS).map(|p| p.name).collect(),
        "flight" | "flight_many" => kick_flight::spec::FLIGHT_PARAMETERS.iter().map(|p| p.name).collect(),
        other => return Err(value_error(format!("no function `{other}` takes declared parameters"))),
    })
}

/// Status codes of `simulate_many`'s `status` array (`kick_core::Status::code`).
pub fn status_codes(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    for s in Status::ALL {
        d.set_item(s.code(), s.name())?;
    }
    Ok(d)
}
