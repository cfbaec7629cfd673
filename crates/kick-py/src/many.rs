//! The `*_many` functions (`simulate_many`, `simulate3d_many`, and through
//! the same [`run_many`] `bounce_many` and `flight_many`): every parameter a
//! scalar or an array, each through the one argument guard
//! ([`crate::params::real_array`]), broadcast by numpy's rules; the rows
//! solved by kick-study's run loop ([`kick_study::many`]) with the GIL
//! released, into preallocated numpy arrays, Ctrl-C heard by the one interruptible runner
//! ([`crate::interruptible`]). A row that fails gets a status code
//! (`kick_core::Status::code`), NaN outcomes and its message, not an
//! exception; a row outside its contact law's validity keeps its numbers
//! with status 4 and the message saying why.

use crate::params::{described, real_array, MAX_AXES};
use crate::{guard, library_error, value_error};
use kick_3d::{KickSpec, Solver3d};
use kick_core::parameters::{self, ParameterDef, SetParameter, Shape};
use kick_core::ScenarioSpec;
use kick_study::many::{width, Broadcast, Flown, Input, Many1d, Many3d, RowModel, Slots};
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Rows solved without a thread watching for Ctrl-C: so few are over in
/// moments, even slow 3D kicks (a watching thread doubled a one-row call's 24 us).
const UNWATCHED_ROWS: usize = 1024;

/// A model's keywords: the declaration a keyword names, or the library's
/// error naming the nearby ones. The rows themselves are kick-study's
/// ([`kick_study::many`]).
pub(crate) trait Keywords: RowModel {
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef>;
}

impl Keywords for Many1d {
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
        parameters::find_at(<ScenarioSpec as SetParameter>::LEVELS, name).map_err(value_error)
    }
}

impl Keywords for Many3d {
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
        match parameters::find_at(KickSpec::LEVELS, name) {
            Ok(p) => Ok(p),
            Err(e) => match crate::params::flight_rest(name) {
                Some(q) if self.flies() => Ok(q.def()),
                Some(_) => Err(value_error(format!("`{name}` is a parameter of the flight: give flight=True"))),
                None => Err(value_error(e)),
            },
        }
    }
}

/// numpy's broadcasting: shapes aligned at the right, each axis equal or 1.
fn broadcast_shapes(shapes: &[(&str, Vec<usize>)]) -> PyResult<Vec<usize>> {
    let ndim = shapes.iter().map(|(_, s)| s.len()).max().unwrap_or(0);
    let mut out = vec![1usize; ndim];
    for (axis, size) in out.iter_mut().enumerate() {
        for (_, shape) in shapes {
            let offset = ndim - shape.len();
            if axis < offset {
                continue;
            }
            let n = shape[axis - offset];
            if n != 1 {
                if *size != 1 && *size != n {
                    let shown: Vec<String> = shapes.iter().map(|(name, s)| format!("`{name}` {s:?}")).collect();
                    return Err(PyValueError::new_err(format!(
                        "shape mismatch: the parameters cannot be broadcast to one shape ({})",
                        shown.join(", ")
                    )));
                }
                *size = n;
            }
        }
    }
    Ok(out)
}

/// A keyword's value as a float64 array (a switch's bools as 0 and 1), by
/// the rules of `params::real_array`; a switch takes bools only, a number
/// or vector no bools.
fn input_array<'py>(parameter: &'static ParameterDef, value: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let takes = match parameter.shape {
        Shape::Switch => "true or false",
        Shape::Scalar => "real numbers",
        Shape::Vector3 => "real numbers (x, y, z on the last axis)",
    };
    let (array, switches) = real_array(parameter.name, takes, value)?;
    if switches != (parameter.shape == Shape::Switch) {
        return Err(PyTypeError::new_err(format!("`{}` takes {takes}, got {}", parameter.name, described(value))));
    }
    Ok(array)
}

/// `input_array` for `kick.dask`, which splits the rows on the client: the
/// keyword `name` of `function` (`simulate_many`, `simulate3d_many`,
/// `flight_many` or `bounce_many`).
#[pyfunction]
pub fn many_input<'py>(function: &str, name: &str, value: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let parameter = match function {
        "simulate_many" => parameters::find_at(ScenarioSpec::LEVELS, name).map_err(value_error)?,
        "simulate3d_many" => parameters::find_at(KickSpec::LEVELS, name).map_err(value_error)?,
        "flight_many" => kick_flight::FLIGHT_PARAMETERS
            .iter()
            .find(|p| p.name == name)
            .ok_or_else(|| value_error(format!("unknown flight parameter `{name}`")))?,
        "bounce_many" => kick_bounce::parameter(name).map_err(value_error)?,
        other => return Err(value_error(format!("no function `{other}` takes arrays"))),
    };
    input_array(parameter, value)
}

/// How a `*_many` call runs: its worker threads, and the label of its
/// progress bar (`progress=True`: the function's name; None, no bar).
pub(crate) struct Run {
    pub threads: Option<usize>,
    pub progress: Option<&'static str>,
}

impl Run {
    /// The `threads` and `progress` keywords of `function`, each checked.
    pub fn new(function: &'static str, threads: Option<&Bound<'_, PyAny>>, progress: Option<&Bound<'_, PyAny>>) -> PyResult<Run> {
        let threads = crate::params::threads(threads)?;
        let progress = crate::params::switch("progress", progress)?.then_some(function);
        Ok(Run { threads, progress })
    }
}

/// The whole call: inputs from the keywords, outputs allocated, rows solved
/// without the GIL, the dict of arrays.
pub(crate) fn run_many<'py, M: Keywords>(
    py: Python<'py>,
    model: &M,
    base: M::Spec,
    run: Run,
    arrays: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let Run { threads, progress } = run;
    let numpy = py.import("numpy")?;
    let mut given: Vec<(&'static ParameterDef, Bound<'py, PyArrayDyn<f64>>)> = Vec::new();
    if let Some(arrays) = arrays {
        for (key, value) in arrays.iter() {
            let name: String = key.extract()?;
            let parameter = model.parameter(&name)?;
            if !value.is_none() {
                given.push((parameter, input_array(parameter, &value)?));
            }
        }
    }
    // Row shapes: a vector's array has a trailing axis of 3.
    let mut shapes = Vec::new();
    for (p, array) in &given {
        let mut shape = array.shape().to_vec();
        if p.shape == Shape::Vector3 {
            if shape.last() != Some(&3) {
                return Err(PyValueError::new_err(format!(
                    "`{}` takes three numbers (x, y, z) on its last axis, got shape {shape:?}",
                    p.name
                )));
            }
            shape.pop();
        }
        shapes.push((p.name, shape));
    }
    let shape = broadcast_shapes(&shapes)?;
    // Outputs with trailing axes (a vector's, the planes') have more axes than the rows.
    let widest = model.columns().iter().max_by_key(|(_, a)| a.len()).filter(|(_, a)| !a.is_empty());
    let axes = shape.len() + widest.map_or(0, |(_, a)| a.len());
    if axes > MAX_AXES {
        let from = shapes.iter().max_by_key(|(_, s)| s.len()).map_or("", |(n, _)| *n);
        let column = widest.map_or("", |(c, _)| c.as_str());
        return Err(PyValueError::new_err(format!(
            "the rows' shape (from `{from}`) has {} axes, so `{column}` would have {axes}: at most {MAX_AXES}",
            shape.len()
        )));
    }
    // Every output's size before any is allocated: bytes per row, times rows.
    let row_bytes = model.columns().iter().map(|(_, a)| width(a) * size_of::<f64>()).sum::<usize>() + size_of::<u8>() + size_of::<u64>();
    let rows = shape.iter().try_fold(1usize, |n, &k| n.checked_mul(k));
    let bytes = rows.and_then(|n| n.checked_mul(row_bytes)).filter(|&b| b <= isize::MAX as usize);
    let (Some(rows), Some(_)) = (rows, bytes) else {
        let exact: Vec<String> = shape.iter().map(|k| k.to_string()).collect();
        return Err(PyMemoryError::new_err(format!(
            "outputs of {} rows ({row_bytes} bytes each) are larger than this machine can address",
            exact.join(" x ")
        )));
    };

    // Each input as C-ordered values, which kick-study reads by its own shape
    // (`require`, not `ascontiguousarray`, which makes a scalar's 0-d array 1-d).
    let mut contiguous_inputs = Vec::with_capacity(given.len());
    for (p, array) in &given {
        let array: Bound<'py, PyArrayDyn<f64>> =
            numpy.call_method1("require", (array, py.None(), "C"))?.cast_into().map_err(value_error)?;
        contiguous_inputs.push((*p, array));
    }
    let guards: Vec<PyReadonlyArrayDyn<'py, f64>> = contiguous_inputs.iter().map(|(_, a)| a.readonly()).collect();
    let mut inputs = Vec::with_capacity(guards.len());
    for ((p, _), g) in contiguous_inputs.iter().zip(&guards) {
        inputs.push(Input { parameter: p, data: g.as_slice().map_err(value_error)?, shape: g.shape().to_vec() });
    }
    let done = AtomicU64::new(0);
    let mut level = Broadcast::new(model, base, inputs, &shape).map_err(value_error)?;
    if progress.is_some() {
        level = level.counting(&done);
    }

    // Outputs, filled in place.
    let with_axis = |trailing: &[usize]| {
        let mut s = shape.clone();
        s.extend_from_slice(trailing);
        s
    };
    // Allocated by numpy, whose failure is a MemoryError (rust-numpy's `zeros` panics).
    let zeros = |shape: Vec<usize>, dtype: &str| -> PyResult<Bound<'py, PyAny>> {
        numpy.call_method1("zeros", (PyTuple::new(py, shape)?, numpy.getattr(dtype)?))
    };
    let mut outputs: Vec<Bound<'py, PyArrayDyn<f64>>> = Vec::with_capacity(model.columns().len());
    for (_, axes) in model.columns() {
        outputs.push(zeros(with_axis(axes), "float64")?.cast_into().map_err(value_error)?);
    }
    let status: Bound<'py, PyArrayDyn<u8>> = zeros(shape.clone(), "uint8")?.cast_into().map_err(value_error)?;
    let evaluations: Bound<'py, PyArrayDyn<u64>> = zeros(shape.clone(), "uint64")?.cast_into().map_err(value_error)?;
    let mut output_guards: Vec<_> = outputs.iter().map(|a| a.readwrite()).collect();
    let mut status_guard = status.readwrite();
    let mut evaluations_guard = evaluations.readwrite();
    let contiguous = |e: numpy::AsSliceError| value_error(e);
    let mut columns = Vec::with_capacity(output_guards.len());
    for guard in output_guards.iter_mut() {
        columns.push(guard.as_slice_mut().map_err(contiguous)?);
    }
    let mut slots =
        Slots::new(model, columns, status_guard.as_slice_mut().map_err(contiguous)?, evaluations_guard.as_slice_mut().map_err(contiguous)?);

    let level_ref = &level;
    let slots_ref = &mut slots;
    let mut solve = move |cancel: &AtomicBool| kick_study::many::run(level_ref, slots_ref, threads, cancel);
    // No rows, no bar (kick.dask checks its options on a call of none).
    let progress = progress.filter(|_| rows > 0);
    // A cancelled run raised KeyboardInterrupt in `interruptible`: its rows are never returned.
    match progress {
        None if rows <= UNWATCHED_ROWS => py.detach(move || solve(&AtomicBool::new(false))).map_err(library_error)?,
        None => crate::interruptible(py, solve)?.map_err(library_error)?,
        Some(label) => {
            let bar = crate::progress::bar(py, rows as u64, label);
            let answer = crate::watched(py, solve, || bar.set_position(done.load(Ordering::Relaxed)));
            crate::progress::end(py, &bar, done.load(Ordering::Relaxed));
            answer?.map_err(library_error)?
        }
    };
    let failures = std::mem::take(&mut slots.failures);
    drop(slots);
    drop(output_guards);
    drop(status_guard);
    drop(evaluations_guard);

    let out = PyDict::new(py);
    for ((name, _), array) in model.columns().iter().zip(outputs) {
        out.set_item(name, array)?;
    }
    out.set_item("evaluations", evaluations)?;
    out.set_item("status", status)?;
    let index: Vec<i64> = failures.iter().map(|(i, _)| *i as i64).collect();
    out.set_item("failure_index", PyArray1::from_vec(py, index))?;
    let messages = PyList::empty(py);
    for (_, message) in &failures {
        messages.append(message)?;
    }
    out.set_item("failure_message", messages)?;
    Ok(out)
}

/// A `damping` or `restitution` keyword the law would ignore is refused for
/// the whole call (`LawKind::check_given`), not row by row.
fn check_law_keywords(law: kick_core::LawKind, arrays: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    let given = |name: &str| -> PyResult<bool> {
        Ok(match arrays {
            Some(a) => a.get_item(name)?.is_some_and(|v| !v.is_none()),
            None => false,
        })
    };
    law.check_given(given("damping")?, given("restitution")?).map_err(value_error)
}

/// Many 1D contacts: `simulate`'s keywords, each a scalar or an array.
#[pyfunction]
#[pyo3(signature = (*, solver = "auto", law = "power-law", dt = None, threads = None, progress = None, **arrays))]
pub fn simulate_many<'py>(
    py: Python<'py>,
    solver: &str,
    law: &str,
    dt: Option<&Bound<'py, PyAny>>,
    threads: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    arrays: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let dt = crate::params::optional_number("dt", dt)?;
        let model = Many1d::new(crate::solver_1d(solver, dt)?);
        let law = crate::law(law)?;
        check_law_keywords(law, arrays)?;
        let base: ScenarioSpec = crate::params::spec(None, law)?;
        run_many(py, &model, base, Run::new("simulate_many", threads, progress)?, arrays)
    })
}

/// Many 3D kicks: `simulate3d`'s keywords, each a scalar or an array
/// (vectors with a trailing axis of 3); with `flight`, each ball flown from
/// the ground after its kick, the flight's keywords broadcast too and
/// `distance` one plane or a list of them (a trailing axis of the planes).
#[pyfunction]
#[pyo3(signature = (*, solver = "auto", law = "power-law", dt = None, threads = None, progress = None, flight = false, distance = None, **arrays))]
#[allow(clippy::too_many_arguments)]
pub fn simulate3d_many<'py>(
    py: Python<'py>,
    solver: &str,
    law: &str,
    dt: Option<&Bound<'py, PyAny>>,
    threads: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    flight: bool,
    distance: Option<&Bound<'py, PyAny>>,
    arrays: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let dt = crate::params::optional_number("dt", dt)?;
        let solver = Solver3d::with_step(solver, dt).map_err(value_error)?;
        let plan = crate::params::flight_plan(flight, None, distance)?;
        let flown = plan.map(|plan| Flown { planes: plan.planes.as_ref().map(Vec::len), plan });
        let base_flight = flown.as_ref().map(|f| f.plan.rest).unwrap_or_default();
        let model = Many3d::new(solver, flown).map_err(library_error)?;
        let law = crate::law(law)?;
        check_law_keywords(law, arrays)?;
        let base: KickSpec = crate::params::spec(None, law)?;
        run_many(py, &model, (base, base_flight), Run::new("simulate3d_many", threads, progress)?, arrays)
    })
}
