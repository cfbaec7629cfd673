//! `flight`: the ball's flight after the kick (crate kick-flight), keywords
//! from its declared list (`kick_flight::spec::FLIGHT_PARAMETERS`).

use crate::{guard, library_error, value_error};
use kick_core::parameters;
use kick_flight::spec::{FlightParameter, FlightSpec, FLIGHT_PARAMETERS};
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
/// by numpy's rules (a vector with a trailing axis of 3); the rows solved by
/// `kick_flight::flight_many` with the GIL released. Per row a status code
/// (`FlightError::status`), NaN outcomes and a message when it failed.
#[pyfunction]
#[pyo3(signature = (*, threads = None, **arrays))]
pub fn flight_many<'py>(
    py: Python<'py>,
    threads: Option<&Bound<'py, PyAny>>,
    arrays: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let threads = crate::params::threads(threads)?;
        let numpy = py.import("numpy")?;
        let float64 = numpy.getattr("float64")?;
        let mut given: Vec<(FlightParameter, Bound<'py, PyAny>)> = Vec::new();
        if let Some(arrays) = arrays {
            for (key, value) in arrays.iter() {
                let name: String = key.extract()?;
                let parameter = flight_parameter(&name)?;
                if !value.is_none() {
                    given.push((parameter, numpy.getattr("asarray")?.call1((value, &float64))?));
                }
            }
        }
        // Row shapes: a vector's array has a trailing axis of 3.
        let mut shapes = Vec::new();
        for (p, array) in &given {
            let mut shape: Vec<usize> = array.getattr("shape")?.extract()?;
            if p.components() == 3 {
                if shape.last() != Some(&3) {
                    return Err(value_error(format!("`{}` takes three numbers (x, y, z) on its last axis, got shape {shape:?}", p.name())));
                }
                shape.pop();
            }
            shapes.push(pyo3::types::PyTuple::new(py, shape)?);
        }
        let shape: Vec<usize> = numpy
            .getattr("broadcast_shapes")?
            .call1(pyo3::types::PyTuple::new(py, &shapes)?)
            .map_err(|e| value_error(format!("shape mismatch: the parameters cannot be broadcast to one shape ({e})")))?
            .extract()?;
        let rows: usize = shape.iter().product();
        let mut flat: Vec<(FlightParameter, Vec<f64>)> = Vec::with_capacity(given.len());
        for (p, array) in &given {
            let mut target = shape.clone();
            if p.components() == 3 {
                target.push(3);
            }
            let full = numpy.getattr("broadcast_to")?.call1((array, pyo3::types::PyTuple::new(py, target)?))?;
            let values: Vec<f64> = numpy.getattr("ravel")?.call1((full,))?.extract()?;
            flat.push((*p, values));
        }
        let columns: Vec<kick_flight::Column> = flat.iter().map(|(p, v)| kick_flight::Column { parameter: *p, values: v }).collect();
        let results = py.detach(|| kick_flight::flight_many(&FlightSpec::default(), &columns, rows, threads)).map_err(library_error)?;
        many_outputs(py, &shape, &results)
    })
}

/// The rows' results as a dict of arrays of the rows' shape (vectors with a
/// trailing axis of 2 or 3).
fn many_outputs<'py>(
    py: Python<'py>,
    shape: &[usize],
    results: &[Result<kick_flight::FlightOutcome, kick_flight::FlightError>],
) -> PyResult<Bound<'py, PyDict>> {
    type Get = fn(&kick_flight::FlightOutcome) -> Vec<f64>;
    let columns: [(&str, usize, Get); 16] = [
        ("flight_time", 1, |o| vec![o.flight_time]),
        ("landing_point", 2, |o| o.landing_point.to_vec()),
        ("apex_height", 1, |o| vec![o.apex_height]),
        ("apex_time", 1, |o| vec![o.apex_time]),
        ("landing_velocity", 3, |o| o.landing_velocity.to_vec()),
        ("landing_spin", 3, |o| o.landing_spin.to_vec()),
        ("crossed", 1, |o| vec![if o.crossing.is_some() { 1.0 } else { 0.0 }]),
        ("crossing_time", 1, |o| o.crossing.map_or(vec![f64::NAN], |c| vec![c.time])),
        ("crossing_height", 1, |o| o.crossing.map_or(vec![f64::NAN], |c| vec![c.height])),
        ("crossing_lateral_offset", 1, |o| o.crossing.map_or(vec![f64::NAN], |c| vec![c.lateral_offset])),
        ("crossing_velocity", 3, |o| o.crossing.map_or(vec![f64::NAN; 3], |c| c.velocity.to_vec())),
        ("launch_reynolds", 1, |o| vec![o.launch.reynolds]),
        ("launch_spin_parameter", 1, |o| vec![o.launch.spin_parameter]),
        ("launch_drag_coefficient", 1, |o| vec![o.launch.drag_coefficient]),
        ("launch_lift_coefficient", 1, |o| vec![o.launch.lift_coefficient]),
        ("steps", 1, |o| vec![o.steps as f64]),
    ];
    let out = PyDict::new(py);
    let reshape = |values: Bound<'py, PyAny>, width: usize| -> PyResult<Bound<'py, PyAny>> {
        let mut s = shape.to_vec();
        if width > 1 {
            s.push(width);
        }
        values.call_method1("reshape", (pyo3::types::PyTuple::new(py, s)?,))
    };
    for (name, width, get) in columns {
        let mut values = Vec::with_capacity(results.len() * width);
        for r in results {
            match r {
                Ok(o) => values.extend(get(o)),
                Err(_) => values.extend(std::iter::repeat_n(f64::NAN, width)),
            }
        }
        out.set_item(name, reshape(numpy::PyArray1::from_vec(py, values).into_any(), width)?)?;
    }
    let evaluations: Vec<u64> = results.iter().map(|r| r.as_ref().map_or(0, |o| o.evaluations)).collect();
    out.set_item("evaluations", reshape(numpy::PyArray1::from_vec(py, evaluations).into_any(), 1)?)?;
    let status: Vec<u8> = results.iter().map(|r| r.as_ref().map_or_else(|e| e.status().code(), |_| 0)).collect();
    out.set_item("status", reshape(numpy::PyArray1::from_vec(py, status).into_any(), 1)?)?;
    let failures: Vec<(i64, String)> =
        results.iter().enumerate().filter_map(|(i, r)| r.as_ref().err().map(|e| (i as i64, e.to_string()))).collect();
    out.set_item("failure_index", numpy::PyArray1::from_vec(py, failures.iter().map(|f| f.0).collect()))?;
    out.set_item("failure_message", pyo3::types::PyList::new(py, failures.iter().map(|f| f.1.as_str()))?)?;
    Ok(out)
}

/// Three numbers for `name`, or a ValueError naming it.
fn three(name: &str, values: &[f64]) -> PyResult<[f64; 3]> {
    match values {
        &[x, y, z] => Ok([x, y, z]),
        other => Err(value_error(format!("`{name}` takes three numbers, got {}", other.len()))),
    }
}

/// `kick aim`: the launch (or 3D kick, `from_="kick"`) that clears the wall
/// and crosses the goal plane at `target`; the other keywords are the
/// declared flight parameters, fixed (or the starts of free launch
/// parameters), and with `from_="kick"` the kick's (`simulate3d`'s keywords
/// but those the flight declares too).
#[pyfunction]
#[pyo3(signature = (target, *, wall = None, from_ = None, free = None, law = None, objective = None, bounds = None, **params))]
#[allow(clippy::too_many_arguments)]
pub fn aim<'py>(
    py: Python<'py>,
    target: Vec<f64>,
    wall: Option<Vec<f64>>,
    from_: Option<String>,
    free: Option<Vec<String>>,
    law: Option<String>,
    objective: Option<String>,
    bounds: Option<std::collections::BTreeMap<String, (f64, f64)>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    use kick_core::parameters::SetParameter;
    use kick_study::aim::{AimFrom, AimRequest};
    guard(|| {
        let mut flight = FlightSpec::default();
        let mut kick = kick_3d::KickSpec::default();
        // The paper's law is the default kick's (so from_="launch" takes it).
        if let Some(law) = law.as_deref().map(crate::law).transpose()?.filter(|&l| l != kick_core::LawKind::PowerLaw) {
            kick.scenario.law = Some(law);
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
        let request = AimRequest {
            target: Some(three("target", &target)?),
            wall: wall.as_deref().map(|w| three("wall", w)).transpose()?,
            from: from_.as_deref().map(AimFrom::from_name).transpose().map_err(value_error)?,
            free,
            flight,
            kick,
            ranges: bounds.unwrap_or_default().into_iter().map(|(name, (low, high))| format!("{name}={low:?},{high:?}")).collect(),
            objective: objective.as_deref().map(kick_flight::Objective::from_name).transpose().map_err(value_error)?,
        };
        let report = py.detach(|| kick_study::aim::aim(&request)).map_err(library_error)?;
        crate::convert::json_to_py(py, &serde_json::to_value(report).map_err(value_error)?)
    })
}
