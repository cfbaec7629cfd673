//! `flight`: the ball's flight after the kick (crate kick-flight), keywords
//! from its declared list (`kick_flight::spec::FLIGHT_PARAMETERS`).

use crate::many::{run_many, Keywords, Run};
use crate::{guard, library_error, value_error};
use kick_core::parameters::{self, ParameterDef};
use kick_flight::spec::{FlightParameter, FlightSpec, FLIGHT_PARAMETERS};
use kick_study::many::ManyFlights;
use numpy::{PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The flight parameter a keyword names, or a ValueError naming the nearby ones.
fn flight_parameter(name: &str) -> PyResult<FlightParameter> {
    FlightParameter::from_name(name).map_err(|_| {
        let valid: Vec<&str> = FLIGHT_PARAMETERS.iter().map(|p| p.name).collect();
        value_error(format!("unknown flight parameter `{name}`{}", parameters::did_you_mean(&parameters::nearby(name, &valid), &valid)))
    })
}

/// One flight (`kick flight`): its outcome; `distance` one crossing plane or
/// a list (each located in the one solve: `crossings`, one entry per plane);
/// with `samples`, its trajectory at that many uniform times (`trajectory`:
/// `time` [N], `position`, `velocity`, `spin` [N, 3]).
#[pyfunction]
#[pyo3(signature = (*, samples = None, distance = None, **params))]
pub fn flight<'py>(
    py: Python<'py>,
    samples: Option<&Bound<'py, PyAny>>,
    distance: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let samples = crate::params::samples(samples)?;
        let mut spec = FlightSpec::default();
        if let Some(params) = params {
            for (key, value) in params.iter() {
                let name: String = key.extract()?;
                let parameter = flight_parameter(&name)?;
                if value.is_none() {
                    continue;
                }
                let values = crate::params::value(parameter.def(), &value)?.numbers();
                spec.set(parameter, &values).map_err(value_error)?;
            }
        }
        let planes = crate::params::distances(distance)?;
        let scalar = distance.is_some_and(|d| !d.is_none() && d.extract::<f64>().is_ok());
        let planes = match planes {
            Some(list) if scalar => {
                spec.distance = list.first().copied();
                Vec::new()
            }
            Some(list) => list,
            None => Vec::new(),
        };
        let flight = spec.build().map_err(value_error)?;
        let run = py
            .detach(|| kick_study::flight::fly_planes(flight, &planes))
            .map_err(|f| crate::library_error(kick_study::StudyError::Failure(f)))?;
        let mut object = serde_json::to_value(run.outcome).map_err(value_error)?;
        if !planes.is_empty() {
            let crossings: Vec<serde_json::Value> = run.crossings.iter().map(|c| serde_json::to_value(c).unwrap_or_default()).collect();
            object["crossings"] = crossings.into();
        }
        let out = crate::convert::json_to_py(py, &object)?;
        if let Some(n) = samples {
            let h = py.detach(|| kick_flight::history(&flight, kick_flight::Sampling::Samples(n))).map_err(library_error)?;
            let trajectory = PyDict::new(py);
            let time: Vec<f64> = h.samples.iter().map(|s| s.time).collect();
            trajectory.set_item("time", numpy::PyArray1::from_vec(py, time))?;
            type Get = fn(&kick_flight::FlightSample) -> [f64; 3];
            let vectors: [(&str, Get); 3] = [("position", |s| s.position), ("velocity", |s| s.velocity), ("spin", |s| s.spin)];
            for (name, get) in vectors {
                let rows: Vec<Vec<f64>> = h.samples.iter().map(|s| get(s).to_vec()).collect();
                trajectory.set_item(name, numpy::PyArray2::from_vec2(py, &rows).map_err(value_error)?)?;
            }
            out.set_item("trajectory", trajectory)?;
        }
        Ok(out)
    })
}

/// Many flights: `flight`'s keywords, each a scalar or an array, broadcast
/// by numpy's rules (a vector with a trailing axis of 3), through the
/// `*_many` functions' one argument guard and runner ([`run_many`]): the
/// rows solved in parallel with the GIL released, Ctrl-C heard. Per row a
/// status code (`FlightError::status`), NaN outcomes and a message when it
/// failed.
#[pyfunction]
#[pyo3(signature = (*, threads = None, progress = None, **arrays))]
pub fn flight_many<'py>(
    py: Python<'py>,
    threads: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    arrays: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| run_many(py, &ManyFlights::default(), FlightSpec::default(), Run::new("flight_many", threads, progress)?, arrays))
}

impl Keywords for ManyFlights {
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
        flight_parameter(name).map(FlightParameter::def)
    }
}

/// Three real numbers for keyword `name`, through the one argument guard
/// ([`crate::params::real_array`]: no bools, strings, complex or masked
/// values), or an error naming it.
fn three(name: &str, value: &Bound<'_, PyAny>) -> PyResult<[f64; 3]> {
    numbers(name, "three numbers (x, y, z)", value)
}

/// N real numbers through the one argument guard (no bools, no objects;
/// a list, tuple or array), or an error naming `name`.
fn numbers<const N: usize>(name: &str, takes: &str, value: &Bound<'_, PyAny>) -> PyResult<[f64; N]> {
    let (array, switches) = crate::params::real_array(name, takes, value)?;
    let numbers: Vec<f64> = array.readonly().as_array().iter().copied().collect();
    match (switches, array.ndim(), <[f64; N]>::try_from(numbers.as_slice())) {
        (false, 1, Ok(n)) => Ok(n),
        (true, ..) => Err(PyTypeError::new_err(format!("`{name}` takes {takes}, got {}", crate::params::described(value)))),
        _ => Err(value_error(format!("`{name}` takes {takes}, got {}", crate::params::described(value)))),
    }
}

/// `bounds={name: (low, high)}` as `kick aim --range`'s texts, each pair
/// through the argument guard (a bool, an int past double precision or a
/// list were taken as numbers or refused with pyo3's words).
fn aim_bounds(bounds: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<(String, [f64; 2])>> {
    let Some(bounds) = bounds.filter(|b| !b.is_none()) else { return Ok(Vec::new()) };
    let dict = bounds.cast::<PyDict>().map_err(|_| {
        PyTypeError::new_err(format!("`bounds` takes a dict {{name: (low, high)}}, got {}", crate::params::described(bounds)))
    })?;
    let mut out = Vec::with_capacity(dict.len());
    for (key, value) in dict.iter() {
        let name: String = key
            .extract()
            .map_err(|_| PyTypeError::new_err(format!("`bounds` takes parameter names as keys, got {}", crate::params::described(&key))))?;
        out.push((name.clone(), numbers(&format!("bounds[{name:?}]"), "two numbers (low, high)", &value)?));
    }
    Ok(out)
}

/// `kick aim`: the launch (or 3D kick, `from_="kick"`) that clears the wall
/// and crosses the goal plane at `target`; the other keywords are the
/// declared flight parameters, fixed (or the starts of free launch
/// parameters), and with `from_="kick"` the kick's (`simulate3d`'s keywords
/// but those the flight declares too) and its normal contact `law`
/// (`kick aim --law`). `target` and `wall` go through the one argument
/// guard (three real numbers, no bools); the solve hears Ctrl-C.
#[pyfunction]
#[pyo3(signature = (target, *, wall = None, from_ = None, free = None, law = None, objective = None, bounds = None, **params))]
#[allow(clippy::too_many_arguments)]
pub fn aim<'py>(
    py: Python<'py>,
    target: &Bound<'py, PyAny>,
    wall: Option<&Bound<'py, PyAny>>,
    from_: Option<String>,
    free: Option<&Bound<'py, PyAny>>,
    law: Option<&str>,
    objective: Option<String>,
    bounds: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    use kick_core::parameters::{SetLaw, SetParameter};
    use kick_study::aim::{AimFrom, AimRequest};
    guard(|| {
        let target = three("target", target)?;
        let wall = wall.filter(|w| !w.is_none()).map(|w| three("wall", w)).transpose()?;
        let free = free.filter(|f| !f.is_none()).map(|f| crate::params::names("free", f)).transpose()?;
        let mut flight = FlightSpec::default();
        let mut kick = kick_3d::KickSpec::default();
        // As `kick aim --law`: the paper's law is the kick's default, so naming it changes nothing.
        if let Some(name) = law {
            let kind = crate::law(name)?;
            if kind != kick_core::LawKind::PowerLaw {
                kick.set_law(kind);
            }
        }
        if let Some(params) = params {
            for (key, value) in params.iter() {
                let name: String = key.extract()?;
                // A flight keyword, else a kick one (the kick's names the flight does not declare).
                let parameter = match flight_parameter(&name) {
                    Ok(p) => Ok(p),
                    Err(e) => match parameters::find_at(kick_3d::KickSpec::LEVELS, &name) {
                        Ok(def) => {
                            if !value.is_none() {
                                kick.set_parameter(def, crate::params::value(def, &value)?).map_err(value_error)?;
                            }
                            continue;
                        }
                        Err(_) => Err(e),
                    },
                }?;
                if value.is_none() {
                    continue;
                }
                let values = crate::params::value(parameter.def(), &value)?.numbers();
                flight.set(parameter, &values).map_err(value_error)?;
            }
        }
        let bounds = aim_bounds(bounds)?;
        let request = AimRequest {
            target: Some(target),
            wall,
            from: from_.as_deref().map(AimFrom::from_name).transpose().map_err(value_error)?,
            free,
            flight,
            kick,
            ranges: bounds.iter().map(|(name, [low, high])| format!("{name}={low:?},{high:?}")).collect(),
            objective: objective.as_deref().map(kick_flight::Objective::from_name).transpose().map_err(value_error)?,
        };
        let report = crate::interruptible(py, |cancel| {
            kick_study::aim::aim_cancellable(&request, &|| cancel.load(std::sync::atomic::Ordering::Relaxed))
        })?
        .map_err(|e| match e {
            // `--range NAME=LOW,HIGH: why` in the call's own words.
            kick_study::StudyError::Flag { flag: "range", message } => {
                let why = message.split_once(": ").map_or(message.as_str(), |(_, why)| why);
                let name = bounds.iter().find(|(n, _)| message.starts_with(&format!("--range {n}"))).map(|(n, _)| n.as_str());
                value_error(match name {
                    Some(n) => format!("bounds[{n:?}]: {}", why.replace("(flag --free)", "(keyword free)")),
                    None => format!("bounds: {why}"),
                })
            }
            e => library_error(e),
        })?;
        crate::convert::json_to_py(py, &serde_json::to_value(report).map_err(value_error)?)
    })
}
