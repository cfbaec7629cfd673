//! `kick._kick`: the Rust half of the Python module `kick` (the pure-Python
//! half, `python/kick`, gives the functions their signatures and docstrings).
//!
//! A thin front end like the `kick` command line: it turns keywords into the
//! library's specs (names, defaults and validation from the declared
//! parameter lists, `kick_core::parameters` and
//! `kick_flight::spec::FLIGHT_PARAMETERS`), calls one library function and
//! turns the answer into Python objects. A library error raises by its
//! status ([`library_error`]) with its message (the text the command line
//! prints): bad input a `ValueError`; a panic never crosses into Python ([`guard`]).

mod bounce;
mod bridge;
mod convert;
mod fit;
mod flight;
mod many;
mod params;
mod progress;

use kick_compliant::SolverChoice;
use kick_core::{LawKind, RecordingSolver, Spacing, Status, HISTORY_COLUMNS, MAX_HISTORY_SAMPLES};
use numpy::PyArray1;
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyRuntimeWarning, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::fmt::Display;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

/// A `ValueError` carrying the library's message (input refused).
pub(crate) fn value_error(e: impl Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

create_exception!(
    kick,
    NumericalError,
    PyRuntimeError,
    "A numerical limit ended the computation (step budget, step too large, integration failure, \
     non-finite state): no statement about the physics (status 1, `kick.STATUS`)."
);

create_exception!(
    kick,
    OutsideValidityWarning,
    PyRuntimeWarning,
    "A result outside the region where its contact law holds (status 4, `kick.STATUS`; \
     `kick_core::validity`: the shell ball compressed past R/2, any other law past R). The \
     numbers are returned, but they are the law's, not a ball's. Make it an error with \
     `warnings.simplefilter(\"error\", kick.OutsideValidityWarning)`."
);

/// Warn (`OutsideValidityWarning`, at the caller's line) when a single
/// result lies outside its contact law's validity.
pub(crate) fn warn_outside(py: Python<'_>, outside: Option<String>) -> PyResult<()> {
    match outside {
        None => Ok(()),
        Some(why) => {
            let message = std::ffi::CString::new(why.replace('\0', " ")).unwrap_or_default();
            // 2: the user's call, not the wrapper in kick/__init__.py.
            PyErr::warn(py, &py.get_type::<OutsideValidityWarning>(), &message, 2)
        }
    }
}

/// A library error that says what became of the request (`kick_core::Status`).
pub(crate) trait WithStatus: Display {
    fn status(&self) -> Status;
}

macro_rules! with_status {
    ($($error:ty),*) => {$(
        impl WithStatus for $error {
            fn status(&self) -> Status {
                <$error>::status(self)
            }
        }
    )*};
}
with_status!(kick_core::KickError, kick_3d::Kick3dError, kick_flight::FlightError, kick_study::StudyError, kick_identify::IdentifyError);

/// The Python exception of a library error, by its status, with the
/// library's message: refused input a `ValueError`, a numerical failure a
/// [`NumericalError`], anything else (a ball proven trapped) a `RuntimeError`.
pub(crate) fn library_error(e: impl WithStatus) -> PyErr {
    match e.status() {
        Status::Refused => PyValueError::new_err(e.to_string()),
        Status::NumericalFailure => NumericalError::new_err(e.to_string()),
        Status::Separated | Status::Trapped | Status::OutsideValidity => PyRuntimeError::new_err(e.to_string()),
    }
}

/// Run a front-end function; a panic (a bug) becomes a `RuntimeError` with
/// its message instead of unwinding into the interpreter.
pub(crate) fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        Err(PyRuntimeError::new_err(format!("internal error in kick (please report): {message}")))
    })
}

/// How often a long call checks for Ctrl-C.
const SIGNAL_CHECK: Duration = Duration::from_millis(50);

/// Run `work` without the GIL on a thread of its own while this thread
/// checks for signals every [`SIGNAL_CHECK`] (Python runs its handlers on
/// the main thread only, holding the GIL). When a handler raises
/// (`KeyboardInterrupt` on Ctrl-C), `cancel` is set, `work` returns at its
/// next look at it, and the exception is the answer.
pub(crate) fn interruptible<T: Send>(py: Python<'_>, work: impl FnOnce(&AtomicBool) -> T + Send) -> PyResult<T> {
    watched(py, work, || {})
}

/// [`interruptible`], calling `watch` after each check for signals (the
/// `*_many` functions' progress bar draws from there: on the calling
/// thread, never from the workers).
pub(crate) fn watched<T: Send>(py: Python<'_>, work: impl FnOnce(&AtomicBool) -> T + Send, mut watch: impl FnMut() + Send) -> PyResult<T> {
    let cancel = AtomicBool::new(false);
    let (answer, raised) = py.detach(|| {
        std::thread::scope(|scope| {
            let (done, finished) = mpsc::channel::<()>();
            let cancel = &cancel;
            let worker = scope.spawn(move || {
                let answer = work(cancel);
                let _ = done.send(());
                answer
            });
            let mut raised = None;
            // A panic drops `done` unsent: Disconnected, and `join` carries the panic on to `guard`.
            while let Err(RecvTimeoutError::Timeout) = finished.recv_timeout(SIGNAL_CHECK) {
                if raised.is_none() {
                    if let Err(e) = Python::attach(|py| py.check_signals()) {
                        cancel.store(true, Ordering::Relaxed);
                        raised = Some(e);
                    }
                }
                watch();
            }
            (worker.join(), raised)
        })
    });
    match (answer, raised) {
        (_, Some(e)) => Err(e),
        (Ok(answer), None) => Ok(answer),
        (Err(panic), None) => std::panic::resume_unwind(panic),
    }
}

/// The contact law named as `kick simulate --law` names it.
pub(crate) fn law(name: &str) -> PyResult<LawKind> {
    LawKind::from_name(name).map_err(value_error)
}

/// The 1D solver named as `--solver` names it; `dt` (seed-rk4's step) defaults as the CLI's.
pub(crate) fn solver_1d(name: &str, dt: Option<f64>) -> PyResult<SolverChoice> {
    SolverChoice::with_step(name, dt).map_err(value_error)
}

/// One 1D contact: the object `kick simulate --format json` prints.
#[pyfunction]
#[pyo3(signature = (*, solver = "auto", law = "power-law", dt = None, **params))]
fn simulate<'py>(
    py: Python<'py>,
    solver: &str,
    law: &str,
    dt: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let dt = params::optional_number("dt", dt)?;
        let spec = params::scenario_spec(params, crate::law(law)?)?;
        let (object, outside) = bridge::simulate(&spec, solver, dt).map_err(library_error)?;
        warn_outside(py, outside)?;
        convert::json_to_py(py, &object)
    })
}

/// One off-center 3D kick: the object `kick simulate3d --format json` prints;
/// with `flight`, the ball flown from the ground after it (`--flight`),
/// `distance` one crossing plane or a list of them, the flight's other
/// keywords among `params`.
#[pyfunction]
#[pyo3(signature = (*, solver = "auto", law = "power-law", dt = None, flight = false, distance = None, **params))]
#[allow(clippy::too_many_arguments)]
fn simulate3d<'py>(
    py: Python<'py>,
    solver: &str,
    law: &str,
    dt: Option<&Bound<'py, PyAny>>,
    flight: bool,
    distance: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let dt = params::optional_number("dt", dt)?;
        let (kick, rest) = params::split_flight(params, flight)?;
        let spec = params::kick_spec(kick.as_ref(), crate::law(law)?)?;
        let plan = params::flight_plan(flight, rest.as_ref(), distance)?;
        let (object, outside) = bridge::simulate3d(&spec, solver, dt, plan.as_ref()).map_err(library_error)?;
        warn_outside(py, outside)?;
        convert::json_to_py(py, &object)
    })
}

/// The time history of one 1D contact, uniform samples (`kick_core::Spacing`):
/// a dict of 1-D arrays named as `kick_core::HISTORY_COLUMNS`.
#[pyfunction]
#[pyo3(signature = (*, solver = "auto", law = "power-law", dt = None, samples = None, interval = None, **params))]
#[allow(clippy::too_many_arguments)]
fn history<'py>(
    py: Python<'py>,
    solver: &str,
    law: &str,
    dt: Option<&Bound<'py, PyAny>>,
    samples: Option<&Bound<'py, PyAny>>,
    interval: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let spacing = spacing(params::samples(samples)?, params::optional_number("interval", interval)?)?;
        let spec = params::scenario_spec(params, crate::law(law)?)?;
        let scenario = spec.build().map_err(value_error)?;
        let solver = solver_1d(solver, params::optional_number("dt", dt)?)?;
        let (outcome, history) = py.detach(|| solver.solve_sampled(&scenario, spacing, MAX_HISTORY_SAMPLES)).map_err(library_error)?;
        warn_outside(py, scenario.check_validity(&outcome).err().map(|o| o.to_string()))?;
        let out = PyDict::new(py);
        for (k, (name, _)) in HISTORY_COLUMNS.iter().enumerate() {
            let column: Vec<f64> = history.samples.iter().map(|s| s.values()[k]).collect();
            out.set_item(*name, PyArray1::from_vec(py, column))?;
        }
        Ok(out)
    })
}

/// The spacing of a history: exactly one of `samples` or `interval`.
fn spacing(samples: Option<usize>, interval: Option<f64>) -> PyResult<Spacing> {
    match (samples, interval) {
        (Some(n), None) => Ok(Spacing::Count(n)),
        (None, Some(dt)) => Ok(Spacing::Interval(dt)),
        _ => Err(PyValueError::new_err("give exactly one of `samples` (how many) or `interval` (s apart)")),
    }
}

/// The time history of one off-center 3D kick on the accurate path, uniform
/// samples (`kick simulate3d --history`): a dict of 1-D arrays named as
/// `kick_3d::HISTORY_COLUMNS_3D` (vectors as `_x`, `_y`, `_z`).
#[pyfunction]
#[pyo3(signature = (*, solver = "auto", law = "power-law", samples = None, interval = None, **params))]
fn history3d<'py>(
    py: Python<'py>,
    solver: &str,
    law: &str,
    samples: Option<&Bound<'py, PyAny>>,
    interval: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let spacing = spacing(params::samples(samples)?, params::optional_number("interval", interval)?)?;
        let spec = params::kick_spec(params, crate::law(law)?)?;
        let (outcome, history) = py.detach(|| kick_study::simulate::sampled3d(&spec, solver, spacing)).map_err(library_error)?;
        // Built again (cheap, and it built above) for the law and radius of the verdict.
        let kick = spec.build().map_err(library_error)?;
        warn_outside(py, kick.check_validity(&outcome).err().map(|o| o.to_string()))?;
        let out = PyDict::new(py);
        for (k, (name, _)) in kick_3d::HISTORY_COLUMNS_3D.iter().enumerate() {
            let column: Vec<f64> = history.iter().map(|s| s.values()[k]).collect();
            out.set_item(*name, PyArray1::from_vec(py, column))?;
        }
        Ok(out)
    })
}

#[pymodule]
fn _kick(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // Load numpy's C API now: loaded lazily, inside a call, a Ctrl-C during
    // the import panics in rust-numpy.
    PyArray1::<f64>::zeros(m.py(), 0, false);
    m.add("NumericalError", m.py().get_type::<NumericalError>())?;
    m.add("OutsideValidityWarning", m.py().get_type::<OutsideValidityWarning>())?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(simulate3d, m)?)?;
    m.add_function(wrap_pyfunction!(history, m)?)?;
    m.add_function(wrap_pyfunction!(history3d, m)?)?;
    m.add_function(wrap_pyfunction!(many::simulate_many, m)?)?;
    m.add_function(wrap_pyfunction!(many::simulate3d_many, m)?)?;
    m.add_function(wrap_pyfunction!(many::many_input, m)?)?;
    m.add_function(wrap_pyfunction!(params::whole_number_py, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(flight::flight, m)?)?;
    m.add_function(wrap_pyfunction!(flight::flight_many, m)?)?;
    m.add_function(wrap_pyfunction!(bounce::bounce, m)?)?;
    m.add_function(wrap_pyfunction!(bounce::bounce_many, m)?)?;
    m.add_function(wrap_pyfunction!(params::bounce_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(flight::aim, m)?)?;
    m.add_function(wrap_pyfunction!(params::declared, m)?)?;
    m.add_function(wrap_pyfunction!(params::keywords, m)?)?;
    m.add("STATUS", params::status_codes(m.py())?)?;
    m.add("HISTORY_COLUMNS", HISTORY_COLUMNS.iter().map(|(n, u)| (*n, *u)).collect::<Vec<_>>())?;
    m.add("HISTORY_COLUMNS_3D", kick_3d::HISTORY_COLUMNS_3D.iter().map(|(n, u)| (*n, *u)).collect::<Vec<_>>())?;
    m.add("OBSERVABLES", kick_core::OBSERVABLES.iter().map(|(n, u)| (*n, *u)).collect::<Vec<_>>())?;
    // The outputs' units, for `kick.to_xarray`.
    m.add("OBSERVABLES_3D", kick_3d::OBSERVABLES_3D.iter().map(|(n, u)| (*n, *u)).collect::<Vec<_>>())?;
    m.add("FLIGHT_COLUMNS", kick_flight::OUTCOME_COLUMNS.to_vec())?;
    m.add("CHANNELS", kick_identify::Channel::ALL.map(|c| (c.name(), c.unit())).to_vec())?;
    m.add("SOLVERS", SolverChoice::NAMES.to_vec())?;
    m.add("SOLVERS_3D", kick_3d::Solver3d::NAMES.to_vec())?;
    // Every law a `law` keyword takes, the shell included: the one list.
    m.add("LAWS", LawKind::SELECTABLE.map(LawKind::name).to_vec())?;
    m.add("BOUNCE_COLUMNS", kick_study::many::BOUNCE_COLUMNS.iter().map(|(n, _, u)| (*n, *u)).collect::<Vec<_>>())?;
    // Every study, declared once in kick-study: what `kick.dask` runs, what each function belongs to.
    let studies = serde_json::to_value(kick_study::studies::STUDIES).map_err(value_error)?;
    m.add("STUDIES", convert::json_to_py(m.py(), &studies)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
