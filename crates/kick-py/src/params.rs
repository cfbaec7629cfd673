//! Keywords to specs, by the declared parameter lists: a keyword is a
//! parameter's name, and nothing else is accepted.

use crate::value_error;
use kick_3d::KickSpec;
use kick_core::parameters::{self, ParameterDef, ParameterError, SetLaw, SetParameter, Shape, Value};
use kick_core::{LawKind, ScenarioSpec, Status};
use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString};

/// A spec keywords fill: its levels' parameters and the contact law.
pub trait LawSpec: SetParameter + SetLaw + Default {}

impl<S: SetParameter + SetLaw + Default> LawSpec for S {}

/// Most axes an array may have: numpy 1's limit, which rust-numpy's views assume.
pub const MAX_AXES: usize = 32;

/// What the user gave, in words for a refusal: its type (and dtype), then its repr.
pub fn described(value: &Bound<'_, PyAny>) -> String {
    let kind = value.get_type().name().map(|n| n.to_string()).unwrap_or_default();
    let dtype = value.getattr("dtype").ok().and_then(|d| d.str().ok()).map(|d| format!(" of dtype {d}")).unwrap_or_default();
    let mut repr = value.repr().map(|r| r.to_string()).unwrap_or_default();
    if repr.chars().count() > 60 {
        repr = repr.chars().take(57).collect::<String>() + "...";
    }
    format!("{kind}{dtype} {repr}")
}

/// A keyword's value as numpy reads it: real numbers (ints, floats, or bools
/// when `switches`) as a float64 array of at most [`MAX_AXES`] axes.
/// Anything else (complex, datetime, strings, objects) is a `TypeError` and
/// a masked value a `ValueError`, each naming the keyword; `takes` says what
/// the keyword takes. Nothing is converted silently.
pub fn real_array<'py>(name: &str, takes: &str, value: &Bound<'py, PyAny>) -> PyResult<(Bound<'py, PyArrayDyn<f64>>, bool)> {
    let numpy = value.py().import("numpy")?;
    let ma = numpy.getattr("ma")?;
    let mut given = value.clone();
    if value.is_instance(&ma.getattr("MaskedArray")?)? {
        let masked: usize = ma.call_method1("count_masked", (value,))?.extract()?;
        if masked > 0 {
            return Err(PyValueError::new_err(format!(
                "`{name}` has {masked} masked value(s): fill them (numpy.ma.filled) or leave those rows out"
            )));
        }
        given = ma.call_method1("getdata", (value,))?;
    }
    let array = numpy.call_method1("asarray", (&given,)).map_err(|e| {
        let py = value.py();
        PyErr::from_type(e.get_type(py), format!("`{name}`: {}", e.value(py)))
    })?;
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    let switches = kind == "b";
    if !matches!(kind.as_str(), "b" | "i" | "u" | "f") {
        return Err(PyTypeError::new_err(format!("`{name}` takes {takes}, got {}", described(value))));
    }
    // numpy reads a bool among numbers as 0 or 1 (`(True, 0, 1)` is an int
    // array): in a list or tuple it is refused, as a lone bool is.
    if !switches && !given.is_instance(&numpy.getattr("ndarray")?)? && !given.is_instance(&numpy.getattr("generic")?)? {
        let objects = numpy.call_method1("asarray", (&given, numpy.getattr("object_")?))?.call_method0("ravel")?;
        let numpy_bool = numpy.getattr("bool_")?;
        for item in objects.try_iter()? {
            let item = item?;
            if item.is_instance_of::<PyBool>() || item.is_instance(&numpy_bool)? {
                return Err(PyTypeError::new_err(format!("`{name}` takes {takes}, got {} (a bool among the numbers)", described(value))));
            }
        }
    }
    let ndim: usize = array.getattr("ndim")?.extract()?;
    if ndim > MAX_AXES {
        return Err(PyValueError::new_err(format!("`{name}` has {ndim} axes: at most {MAX_AXES}")));
    }
    // Copied only when not float64 or not aligned (rust-numpy's views need
    // alignment; arrays unpickled from a buffer, as dask's, may lack it).
    let array = numpy.call_method1("require", (array, numpy.getattr("float64")?, "A"))?;
    Ok((array.cast_into::<PyArrayDyn<f64>>().map_err(|e| PyTypeError::new_err(e.to_string()))?, switches))
}

/// One real number for keyword `name` (an option such as `dt`), or a `TypeError` naming it.
pub fn real_number(name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let (array, switches) = real_array(name, "a number", value)?;
    if switches || array.ndim() != 0 {
        return Err(PyTypeError::new_err(format!("`{name}` takes a number, got {}", described(value))));
    }
    Ok(array.readonly().as_array().iter().copied().next().unwrap_or(f64::NAN))
}

/// `real_number` for an optional keyword (None: not given).
pub fn optional_number(name: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    value.filter(|v| !v.is_none()).map(|v| real_number(name, v)).transpose()
}

/// A count for keyword `name` (`samples`, `threads`): a Python int or a
/// numpy integer (anything with `__index__` but a bool), in `range`, or a
/// `TypeError` naming the keyword and the type it got (a `ValueError`
/// naming the limit when out of `range`). A float is refused even when
/// whole, as `range(3.0)` refuses it: a count computed as a float (`1e6`,
/// `n / 2`) may not be the integer the user meant, and accepting `3.0` but
/// not `3.5` would make the kind of error depend on the value.
pub fn whole_number(name: &str, value: &Bound<'_, PyAny>, range: std::ops::RangeInclusive<usize>, limit: &str) -> PyResult<usize> {
    let py = value.py();
    let refused = |hint: String| PyTypeError::new_err(format!("`{name}` takes a whole number (int), got {}{hint}", described(value)));
    let numpy_bool = py.import("numpy")?.getattr("bool_")?;
    if value.is_instance_of::<PyBool>() || value.is_instance(&numpy_bool)? {
        return Err(refused(String::new()));
    }
    let index = py.import("operator")?.call_method1("index", (value,)).map_err(|_| {
        let whole = value.extract::<f64>().ok().filter(|x| x.fract() == 0.0 && x.abs() <= 2f64.powi(53));
        refused(whole.map(|x| format!(": write {name}={x:.0}")).unwrap_or_default())
    })?;
    // Compared as Python ints, so no size overflows before the check.
    let (low, high) = (*range.start(), *range.end());
    if index.lt(low)? || index.gt(high)? {
        return Err(PyValueError::new_err(format!(
            "`{name}` = {}: must be between {low} and {high}{limit}",
            described(&index).trim_start_matches("int ")
        )));
    }
    index.extract()
}

/// `whole_number` for Python code of the package (`kick.dask`'s `chunks`):
/// one rule for counts, bools refused.
#[pyfunction]
#[pyo3(name = "whole_number", signature = (name, value, low = 0))]
pub fn whole_number_py(name: &str, value: &Bound<'_, PyAny>, low: usize) -> PyResult<usize> {
    whole_number(name, value, low..=usize::MAX, "")
}

/// `whole_number` for an optional keyword (None: not given).
pub fn optional_whole_number(
    name: &str,
    value: Option<&Bound<'_, PyAny>>,
    range: std::ops::RangeInclusive<usize>,
    limit: &str,
) -> PyResult<Option<usize>> {
    value.filter(|v| !v.is_none()).map(|v| whole_number(name, v, range, limit)).transpose()
}

/// The `threads` keyword: None (rayon's pool) or 1 to
/// [`kick_core::threads::max_threads`], as `--threads` is bounded.
pub fn threads(value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<usize>> {
    use kick_core::threads::{cores, max_threads, THREADS_PER_CORE};
    let limit = format!(" ({THREADS_PER_CORE} per core, {} cores here)", cores());
    optional_whole_number("threads", value, 1..=max_threads(), &limit)
}

/// A true-or-false keyword (`progress`): a bool or numpy bool, None for
/// false; anything else (a 1, a string) a `TypeError` naming the keyword.
pub fn switch(name: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<bool> {
    let Some(value) = value.filter(|v| !v.is_none()) else { return Ok(false) };
    let refused = || PyTypeError::new_err(format!("`{name}` takes true or false, got {}", described(value)));
    let (array, switches) = real_array(name, "true or false", value).map_err(|_| refused())?;
    if !switches || array.ndim() != 0 {
        return Err(refused());
    }
    Ok(array.readonly().as_array().iter().any(|&x| x != 0.0))
}

/// The `samples` keyword of a history: None or 2 to [`kick_core::MAX_HISTORY_SAMPLES`].
pub fn samples(value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<usize>> {
    optional_whole_number("samples", value, 2..=kick_core::MAX_HISTORY_SAMPLES, "")
}

/// Real numbers along one axis for keyword `name` (a data channel), or an error naming it.
pub fn real_vector(name: &str, value: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    let (array, switches) = real_array(name, "an array of real numbers", value)?;
    if switches || array.ndim() != 1 {
        return Err(PyTypeError::new_err(format!("`{name}` takes an array of real numbers, got {}", described(value))));
    }
    Ok(array.readonly().as_array().iter().copied().collect())
}

/// A list of names for keyword `name` (`free`); a lone string is refused
/// (it would be read as a list of letters).
pub fn names(name: &str, value: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    let refused = || PyTypeError::new_err(format!("`{name}` takes a list of names, got {}", described(value)));
    if value.is_instance_of::<PyString>() {
        let one: String = value.extract()?;
        return Err(PyTypeError::new_err(
            format!("`{name}` takes a list of names, got str {one:?}: write {name}=[{one:?}]").replace('"', "'"),
        ));
    }
    value.extract::<Vec<String>>().map_err(|_| refused())
}

/// One value for `parameter`, or an error naming it: a bool is a switch, a
/// real number a number, three real numbers a vector; a value of the wrong
/// one of these shapes is the library's `WrongShape` (`ValueError`), any
/// other value a `TypeError` with its type.
pub fn value(parameter: &'static ParameterDef, value: &Bound<'_, PyAny>) -> PyResult<Value> {
    let takes = match parameter.shape {
        Shape::Vector3 => "three numbers (x, y, z)",
        shape => shape.describe(),
    };
    let (array, switches) = real_array(parameter.name, takes, value)?;
    let numbers: Vec<f64> = array.readonly().as_array().iter().copied().collect();
    let found = match (switches, array.ndim(), numbers.len()) {
        (true, 0, _) => Shape::Switch,
        (false, 0, _) => Shape::Scalar,
        (false, 1, 3) => Shape::Vector3,
        _ => return Err(PyTypeError::new_err(format!("`{}` takes {takes}, got {}", parameter.name, described(value)))),
    };
    if found != parameter.shape {
        return Err(value_error(ParameterError::WrongShape { name: parameter.name, expected: parameter.shape, found }));
    }
    Ok(match found {
        Shape::Scalar => Value::Number(numbers[0]),
        Shape::Switch => Value::Switch(numbers[0] != 0.0),
        Shape::Vector3 => Value::Vector([numbers[0], numbers[1], numbers[2]]),
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

/// kick-bounce's declared parameters (`kick bounce`'s flags), in declaration order.
#[pyfunction]
pub fn bounce_parameters(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for p in kick_bounce::BOUNCE_PARAMETERS.iter() {
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
        "bounce" | "bounce_many" => kick_bounce::BOUNCE_PARAMETERS.iter().map(|p| p.name).collect(),
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

/// The keywords of a kick and, with `flight`, of the flight after it: those
/// of the kick's levels (`KickSpec::LEVELS`; `ball_mass`, `ball_radius` and
/// `gravity` are the kick's), then the flight's it leaves (`air_density`,
/// `drag_coefficient`, ...); any other keyword is refused naming the nearby
/// ones of both.
pub fn split_flight<'py>(
    params: Option<&Bound<'py, PyDict>>,
    flight: bool,
) -> PyResult<(Option<Bound<'py, PyDict>>, Option<Bound<'py, PyDict>>)> {
    let Some(params) = params else { return Ok((None, None)) };
    let py = params.py();
    let (kick, rest) = (PyDict::new(py), PyDict::new(py));
    for (key, value) in params.iter() {
        let name: String = key.extract()?;
        if parameters::find_at(KickSpec::LEVELS, &name).is_ok() {
            kick.set_item(&key, value)?;
        } else if let Some(p) = flight_rest(&name).filter(|_| flight) {
            rest.set_item(p.name(), value)?;
        } else {
            let mut valid: Vec<&'static str> = parameters::at_levels(KickSpec::LEVELS).map(|p| p.name).collect();
            if flight {
                valid.extend(
                    kick_flight::FlightParameter::ALL.iter().filter(|&&q| !kick_study::flight::After::Kick3d.sets(q)).map(|q| q.name()),
                );
            } else if flight_rest(&name).is_some() {
                return Err(value_error(format!("`{name}` is a parameter of the flight: give flight=True")));
            }
            let levels = if flight { "3D kick or its flight" } else { "3D kick" };
            return Err(value_error(format!(
                "unknown parameter `{name}` of the {levels}{}",
                parameters::did_you_mean(&parameters::nearby(&name, &valid), &valid)
            )));
        }
    }
    Ok((Some(kick), Some(rest)))
}

/// The flight parameter `name` a kick leaves to its flight (not `distance`: a keyword of its own).
pub fn flight_rest(name: &str) -> Option<kick_flight::FlightParameter> {
    kick_flight::FlightParameter::from_name(name)
        .ok()
        .filter(|&q| !kick_study::flight::After::Kick3d.sets(q) && q != kick_flight::FlightParameter::Distance)
}

/// The crossing planes of keyword `distance`: None, a number, or a list of numbers.
pub fn distances(distance: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<f64>>> {
    let Some(value) = distance.filter(|d| !d.is_none()) else { return Ok(None) };
    let (array, switches) = real_array("distance", "a number or a list of numbers, m", value)?;
    if switches || array.ndim() > 1 {
        return Err(PyTypeError::new_err(format!("`distance` takes a number or a list of numbers, m, got {}", described(value))));
    }
    Ok(Some(array.readonly().as_array().iter().copied().collect()))
}

/// The flight plan of `flight=True`: the flight keywords `rest` and the
/// planes of `distance` (a number: the one plane, as `--distance` once; a
/// list: each a plane, the crossing columns per plane). None without `flight`
/// (a `distance` then refused).
pub fn flight_plan(
    flight: bool,
    rest: Option<&Bound<'_, PyDict>>,
    distance: Option<&Bound<'_, PyAny>>,
) -> PyResult<Option<kick_study::flight::FlightPlan>> {
    let planes = distances(distance)?;
    if !flight {
        return match planes {
            Some(_) => Err(value_error("`distance` is a plane of the flight: give flight=True")),
            None => Ok(None),
        };
    }
    let mut spec = kick_flight::FlightSpec::default();
    if let Some(rest) = rest {
        for (key, v) in rest.iter() {
            let name: String = key.extract()?;
            if let (Some(q), false) = (flight_rest(&name), v.is_none()) {
                spec.set(q, &value(q.def(), &v)?.numbers()).map_err(value_error)?;
            }
        }
    }
    let scalar = distance.is_some_and(|d| !d.is_none() && d.extract::<f64>().is_ok());
    let plan = match planes {
        None => kick_study::flight::FlightPlan::new(spec),
        Some(list) if scalar => kick_study::flight::FlightPlan::with_distances(spec, &list).map_err(value_error)?,
        Some(list) => kick_study::flight::FlightPlan::planes(spec, list).map_err(value_error)?,
    };
    Ok(Some(plan))
}
