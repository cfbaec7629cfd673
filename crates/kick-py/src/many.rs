//! The `*_many` functions (`simulate_many`, `simulate3d_many`, and through
//! the same [`run_many`] `bounce_many` and `flight_many`): every parameter a
//! scalar or an array, each through the one argument guard
//! ([`crate::params::real_array`]), broadcast by numpy's rules; the rows
//! solved in parallel (rayon) with the GIL released, straight into
//! preallocated numpy arrays, Ctrl-C heard by the one interruptible runner
//! ([`crate::interruptible`]). A row that fails gets a status code
//! (`kick_core::Status::code`), NaN outcomes and its message, not an
//! exception; a row outside its contact law's validity keeps its numbers
//! with status 4 and the message saying why.

use crate::params::{described, real_array, MAX_AXES};
use crate::{guard, library_error, value_error};
use kick_3d::{KickSpec, Outcome3d, Solver3d};
use kick_compliant::SolverChoice;
use kick_core::parameters::{self, ParameterDef, SetParameter, Shape, Value};
use kick_core::{ScenarioSpec, Solver, Status, OBSERVABLES};
use numpy::ndarray::{ArrayViewD, IxDyn};
use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Rows one parallel task solves in turn (as `kick run` chunks its rows).
const CHUNK: usize = 1024;
/// Rows a task solves between additions to the rows-done count (`progress`).
const COUNT_BATCH: usize = 64;

/// A model the rows are solved with: its keywords, its output columns and one solve.
pub(crate) trait Model: Sync {
    type Spec: Clone + Send + Sync;
    /// The declaration a keyword names, or the library's error naming the nearby ones.
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef>;
    /// Set a declared parameter; shapes were checked when the inputs were made.
    fn set(&self, spec: &mut Self::Spec, parameter: &'static ParameterDef, value: Value);
    /// Output columns: name and trailing axes ([]: one number a row; [3]: a
    /// vector; [P] or [P, 3]: one per crossing plane).
    fn columns(&self) -> &[(String, Vec<usize>)];
    /// Solve one row into `row` (the columns' values, vectors expanded);
    /// the evaluations spent (and a flag on the kept numbers), or the
    /// status and message of a failure.
    fn solve(&self, spec: &Self::Spec, row: &mut [f64]) -> Result<Solved, (Status, String)>;
}

/// A row solved: its evaluations, and why its numbers lie outside their
/// contact law's validity, if they do (status 4, the numbers kept).
pub(crate) struct Solved {
    pub evaluations: u64,
    pub outside_validity: Option<String>,
}

impl Solved {
    pub fn new(evaluations: u64, outside_validity: Option<kick_core::OutsideValidity>) -> Solved {
        Solved { evaluations, outside_validity: outside_validity.map(|o| o.to_string()) }
    }
}

/// The numbers a row of columns with these trailing axes takes.
fn width(axes: &[usize]) -> usize {
    axes.iter().product()
}

struct Model1d {
    solver: SolverChoice,
    columns: Vec<(String, Vec<usize>)>,
}

impl Model1d {
    fn new(solver: SolverChoice) -> Model1d {
        let mut columns: Vec<(String, Vec<usize>)> = OBSERVABLES.iter().map(|(n, _)| (n.to_string(), vec![])).collect();
        columns.push(("energy_residual".into(), vec![]));
        Model1d { solver, columns }
    }
}

/// A model whose spec holds declared levels of kick-core's list.
macro_rules! declared_levels {
    ($spec:ty) => {
        fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
            parameters::find_at(<$spec as SetParameter>::LEVELS, name).map_err(value_error)
        }
        fn set(&self, spec: &mut $spec, parameter: &'static ParameterDef, value: Value) {
            let _ = spec.set_parameter(parameter, value);
        }
    };
}

impl Model for Model1d {
    type Spec = ScenarioSpec;
    declared_levels!(ScenarioSpec);
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &ScenarioSpec, row: &mut [f64]) -> Result<Solved, (Status, String)> {
        let failed = |e: kick_core::KickError| (e.status(), e.to_string());
        let scenario = spec.build().map_err(failed)?;
        let outcome = self.solver.solve(&scenario).map_err(failed)?;
        row[..OBSERVABLES.len()].copy_from_slice(&outcome.observable_values());
        row[OBSERVABLES.len()] = outcome.energy.residual();
        Ok(Solved::new(outcome.evaluations, scenario.check_validity(&outcome).err()))
    }
}

/// The 3D outcome's numbers as `simulate3d` names them: its serde fields,
/// vectors as width-3 columns, `energy.x` as `energy_x`, plus `energy_residual`.
fn flatten3d(outcome: &Outcome3d, out: &mut Vec<(String, Vec<f64>)>) {
    fn walk(prefix: &str, value: &serde_json::Value, out: &mut Vec<(String, Vec<f64>)>) {
        use serde_json::Value as J;
        match value {
            J::Number(n) => out.push((prefix.to_string(), vec![n.as_f64().unwrap_or(f64::NAN)])),
            J::Array(items) if items.iter().all(J::is_number) => {
                out.push((prefix.to_string(), items.iter().map(|x| x.as_f64().unwrap_or(f64::NAN)).collect()))
            }
            J::Object(map) => {
                for (k, v) in map {
                    let name = if prefix.is_empty() { k.clone() } else { format!("{prefix}_{k}") };
                    walk(&name, v, out);
                }
            }
            _ => {} // names (solver, law) are per call, not per row
        }
    }
    out.clear();
    walk("", &serde_json::to_value(outcome).unwrap_or_default(), out);
    out.push(("energy_residual".into(), vec![outcome.energy.residual()]));
}

/// The flight after each 3D kick of `simulate3d_many(flight=True)`: its
/// plan and whether `distance` was a list (a trailing plane axis).
struct Flown {
    plan: kick_study::flight::FlightPlan,
    planes: Option<usize>,
}

/// The flight's outputs after a kick, in [`kick_flight::plane_values`]'
/// order: the landing and apex, then the crossing columns (per plane with a
/// plane axis), and `flight_status` (the flight's status code: 0 flown,
/// 3 refused: a ball that does not leave the ground; 1 a numerical failure).
fn flight_columns(planes: Option<usize>, single: bool) -> Vec<(String, Vec<usize>)> {
    let mut columns: Vec<(String, Vec<usize>)> = vec![
        ("flight_time".into(), vec![]),
        ("landing_point".into(), vec![2]),
        ("apex_height".into(), vec![]),
        ("apex_time".into(), vec![]),
        ("landing_velocity".into(), vec![3]),
        ("landing_spin".into(), vec![3]),
    ];
    let crossing = |axes: Vec<usize>, vector: Vec<usize>| -> Vec<(String, Vec<usize>)> {
        vec![
            ("crossed".into(), axes.clone()),
            ("crossing_time".into(), axes.clone()),
            ("crossing_height".into(), axes.clone()),
            ("crossing_lateral_offset".into(), axes),
            ("crossing_velocity".into(), vector),
        ]
    };
    match planes {
        Some(p) => columns.extend(crossing(vec![p], vec![p, 3])),
        None if single => columns.extend(crossing(vec![], vec![3])),
        None => {}
    }
    columns.push(("flight_status".into(), vec![]));
    columns
}

struct Model3d {
    solver: Solver3d,
    columns: Vec<(String, Vec<usize>)>,
    /// Numbers of the kick's own columns (before the flight's).
    kick_width: usize,
    flight: Option<Flown>,
}

impl Model3d {
    fn new(solver: Solver3d, flight: Option<Flown>) -> PyResult<Model3d> {
        // The columns of a solved kick (the baseline on the cheap 1D path).
        let baseline = kick_3d::one_d::solve(&kick_3d::Kick3d::baseline()).map_err(library_error)?;
        let mut flat = Vec::new();
        flatten3d(&baseline, &mut flat);
        let mut columns: Vec<(String, Vec<usize>)> = flat
            .into_iter()
            .filter(|(n, _)| n != "evaluations")
            .map(|(n, v)| {
                let axes = if v.len() == 1 { vec![] } else { vec![v.len()] };
                (n, axes)
            })
            .collect();
        let kick_width = columns.iter().map(|(_, a)| width(a)).sum();
        if let Some(f) = &flight {
            columns.extend(flight_columns(f.planes, f.plan.rest.distance.is_some()));
        }
        Ok(Model3d { solver, columns, kick_width, flight })
    }
}

impl Model for Model3d {
    type Spec = (KickSpec, kick_flight::FlightSpec);
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
        match parameters::find_at(KickSpec::LEVELS, name) {
            Ok(p) => Ok(p),
            Err(e) => match crate::params::flight_rest(name) {
                Some(q) if self.flight.is_some() => Ok(q.def()),
                Some(_) => Err(value_error(format!("`{name}` is a parameter of the flight: give flight=True"))),
                None => Err(value_error(e)),
            },
        }
    }
    fn set(&self, spec: &mut Self::Spec, parameter: &'static ParameterDef, value: Value) {
        match kick_flight::FlightParameter::from_name(parameter.name) {
            Ok(q) if parameter.level == kick_core::Level::Flight => {
                let _ = match value {
                    Value::Number(x) => spec.1.set(q, &[x]),
                    Value::Vector(v) => spec.1.set(q, &v),
                    Value::Switch(_) => Ok(()),
                };
            }
            _ => {
                let _ = spec.0.set_parameter(parameter, value);
            }
        }
    }
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &Self::Spec, row: &mut [f64]) -> Result<Solved, (Status, String)> {
        let failed = |e: kick_3d::Kick3dError| (e.status(), e.to_string());
        let kick = spec.0.build().map_err(failed)?;
        let outcome = self.solver.solve(&kick).map_err(failed)?;
        let mut flat = Vec::with_capacity(self.columns.len() + 1);
        flatten3d(&outcome, &mut flat);
        let mut at = 0;
        for (name, values) in flat.iter().filter(|(n, _)| n != "evaluations") {
            debug_assert!(self.columns.iter().any(|(c, _)| c == name));
            row[at..at + values.len()].copy_from_slice(values);
            at += values.len();
        }
        if let Some(f) = &self.flight {
            let out = &mut row[self.kick_width..];
            let plan = kick_study::flight::FlightPlan { rest: spec.1, planes: f.plan.planes.clone() };
            let flown = kick_study::flight::flight_after_3d(&kick, &outcome, &spec.1).and_then(|flight| plan.fly_into(&flight, out));
            let last = out.len() - 1;
            match flown {
                Ok(_) => out[last] = 0.0,
                Err(failure) => {
                    out.fill(f64::NAN);
                    out[last] = f64::from(failure.status.code());
                }
            }
            // `crossed` and the crossing's columns come plane by plane in
            // `plane_values`; the outputs want each quantity over the planes.
            if let Some(p) = f.planes {
                regroup_planes(&mut out[kick_flight::LANDING_COLUMNS..last], p);
            }
        }
        Ok(Solved::new(outcome.evaluations, kick.check_validity(&outcome).err()))
    }
}

/// `plane_values`' crossings (plane by plane, 7 numbers each) as the
/// outputs hold them: `crossed`, `crossing_time`, `crossing_height`,
/// `crossing_lateral_offset` each over the planes, then `crossing_velocity`
/// plane by plane (3 each).
fn regroup_planes(values: &mut [f64], planes: usize) {
    let per = kick_flight::OUTCOME_COLUMNS.len() - kick_flight::LANDING_COLUMNS;
    let by_plane: Vec<f64> = values[..per * planes].to_vec();
    let mut at = 0;
    for q in 0..4 {
        for k in 0..planes {
            values[at] = by_plane[k * per + q];
            at += 1;
        }
    }
    for k in 0..planes {
        values[at..at + 3].copy_from_slice(&by_plane[k * per + 4..k * per + 7]);
        at += 3;
    }
}

/// One parameter given as an array, broadcast to the rows' shape (plus the
/// trailing axis of 3 for a vector).
struct Input<'a> {
    parameter: &'static ParameterDef,
    view: ArrayViewD<'a, f64>,
}

impl Input<'_> {
    /// The value at row index `index` (`scratch`: room for index plus one axis).
    fn value(&self, index: &[usize], scratch: &mut Vec<usize>) -> Value {
        match self.parameter.shape {
            Shape::Scalar => Value::Number(self.view[index]),
            Shape::Switch => Value::Switch(self.view[index] != 0.0),
            Shape::Vector3 => {
                scratch.clear();
                scratch.extend_from_slice(index);
                scratch.push(0);
                let mut v = [0.0; 3];
                for (k, slot) in v.iter_mut().enumerate() {
                    *scratch.last_mut().unwrap_or(&mut 0) = k;
                    *slot = self.view[scratch.as_slice()];
                }
                Value::Vector(v)
            }
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

/// Row `i` (C order) of `shape` as an index.
fn unravel(mut i: usize, shape: &[usize], index: &mut [usize]) {
    for (slot, &n) in index.iter_mut().zip(shape).rev() {
        *slot = i % n;
        i /= n;
    }
}

/// One chunk of rows and its part of every output.
struct Chunk<'a> {
    start: usize,
    rows: usize,
    columns: Vec<&'a mut [f64]>,
    status: &'a mut [u8],
    evaluations: &'a mut [u64],
}

/// Solve rows `chunk.start..` into the chunk's outputs; the failures (row,
/// message). Returns early, rows unsolved, once `cancel` is set (Ctrl-C).
/// Each row solved adds one to `done`, the progress bar's count.
fn solve_chunk<M: Model>(
    model: &M,
    base: &M::Spec,
    inputs: &[Input],
    shape: &[usize],
    chunk: Chunk,
    cancel: &AtomicBool,
    done: &AtomicU64,
) -> Vec<(usize, String)> {
    let Chunk { start, rows, mut columns, status, evaluations } = chunk;
    let widths: Vec<usize> = model.columns().iter().map(|(_, axes)| width(axes)).collect();
    let mut row = vec![0.0; widths.iter().sum()];
    let mut index = vec![0usize; shape.len()];
    let mut scratch = Vec::with_capacity(shape.len() + 1);
    let mut failures = Vec::new();
    let mut solved = 0usize;
    for j in 0..rows {
        if cancel.load(Ordering::Relaxed) {
            break;
        }
        unravel(start + j, shape, &mut index);
        let mut spec = base.clone();
        for input in inputs {
            model.set(&mut spec, input.parameter, input.value(&index, &mut scratch));
        }
        let result = model.solve(&spec, &mut row);
        let mut at = 0;
        for (column, &w) in columns.iter_mut().zip(&widths) {
            let target = &mut column[j * w..(j + 1) * w];
            match result {
                Ok(_) => target.copy_from_slice(&row[at..at + w]),
                Err(_) => target.fill(f64::NAN),
            }
            at += w;
        }
        match result {
            Ok(Solved { evaluations: n, outside_validity }) => {
                evaluations[j] = n;
                status[j] = match outside_validity {
                    None => Status::Separated.code(),
                    Some(message) => {
                        failures.push((start + j, message));
                        Status::OutsideValidity.code()
                    }
                };
            }
            Err((s, message)) => {
                status[j] = s.code();
                evaluations[j] = 0;
                failures.push((start + j, message));
            }
        }
        // Counted in batches: one shared counter bumped per row would cost the cheap 1D rows.
        solved += 1;
        if solved % COUNT_BATCH == 0 {
            done.fetch_add(COUNT_BATCH as u64, Ordering::Relaxed);
        }
    }
    done.fetch_add((solved % COUNT_BATCH) as u64, Ordering::Relaxed);
    failures
}

/// Run `f` on `threads` workers of its own pool (a count `params::threads`
/// checked), or on rayon's global pool.
fn in_pool<T: Send>(threads: Option<usize>, f: impl FnOnce() -> T + Send) -> PyResult<T> {
    match threads {
        None => Ok(f()),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| PyValueError::new_err(format!("cannot start {n} threads: {e}")))?;
            Ok(pool.install(f))
        }
    }
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
pub(crate) fn run_many<'py, M: Model>(
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

    let guards: Vec<PyReadonlyArrayDyn<'py, f64>> = given.iter().map(|(_, a)| a.readonly()).collect();
    let bases: Vec<ArrayViewD<f64>> = guards.iter().map(|g| g.as_array()).collect();
    let mut inputs = Vec::with_capacity(guards.len());
    for ((p, _), g) in given.iter().zip(&bases) {
        let mut target = shape.clone();
        if p.shape == Shape::Vector3 {
            target.push(3);
        }
        let view = g.broadcast(IxDyn(&target)).ok_or_else(|| value_error("broadcast failed"))?;
        inputs.push(Input { parameter: p, view });
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
    let mut column_chunks: Vec<std::slice::ChunksMut<f64>> = Vec::new();
    for (guard, (_, axes)) in output_guards.iter_mut().zip(model.columns()) {
        column_chunks.push(guard.as_slice_mut().map_err(contiguous)?.chunks_mut(CHUNK * width(axes)));
    }
    let mut status_chunks = status_guard.as_slice_mut().map_err(contiguous)?.chunks_mut(CHUNK);
    let mut evaluation_chunks = evaluations_guard.as_slice_mut().map_err(contiguous)?.chunks_mut(CHUNK);
    let mut chunks = Vec::with_capacity(rows.div_ceil(CHUNK));
    for start in (0..rows).step_by(CHUNK) {
        chunks.push(Chunk {
            start,
            rows: CHUNK.min(rows - start),
            columns: column_chunks.iter_mut().map(|c| c.next().unwrap_or_default()).collect(),
            status: status_chunks.next().unwrap_or_default(),
            evaluations: evaluation_chunks.next().unwrap_or_default(),
        });
    }

    let shape_ref = &shape;
    let inputs_ref = &inputs;
    let base_ref = &base;
    let done = AtomicU64::new(0);
    let done_ref = &done;
    let solve = |cancel: &AtomicBool| {
        in_pool(threads, || {
            chunks
                .into_par_iter()
                .flat_map_iter(|chunk| solve_chunk(model, base_ref, inputs_ref, shape_ref, chunk, cancel, done_ref))
                .collect()
        })
    };
    // One chunk is over in moments: no watching thread (it doubled a one-row call's 24 us).
    // No rows, no bar (kick.dask checks its options on a call of none).
    let progress = progress.filter(|_| rows > 0);
    let failures: Vec<(usize, String)> = match progress {
        None if rows <= CHUNK => py.detach(|| solve(&AtomicBool::new(false)))?,
        None => crate::interruptible(py, solve)??,
        Some(label) => {
            let bar = crate::progress::bar(py, rows as u64, label);
            let answer = crate::watched(py, solve, || bar.set_position(done.load(Ordering::Relaxed)));
            crate::progress::end(py, &bar, done.load(Ordering::Relaxed));
            answer??
        }
    };
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
        let model = Model1d::new(crate::solver_1d(solver, dt)?);
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
        let model = Model3d::new(solver, flown)?;
        let law = crate::law(law)?;
        check_law_keywords(law, arrays)?;
        let base: KickSpec = crate::params::spec(None, law)?;
        run_many(py, &model, (base, base_flight), Run::new("simulate3d_many", threads, progress)?, arrays)
    })
}
