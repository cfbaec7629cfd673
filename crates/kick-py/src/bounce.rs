//! `bounce`: the ball alone on a rigid plate (crate kick-bounce, `kick
//! bounce`), keywords from its declared list
//! (`kick_bounce::BOUNCE_PARAMETERS`, named as the CLI's flags), one call to
//! `kick_bounce::run`; `bounce_many` the same per row of arrays.

use crate::many::{run_many, Keywords, Run};
use crate::{guard, library_error, value_error};
use kick_bounce::{BounceSpec, LawChoice};
use kick_core::parameters::ParameterDef;
use kick_study::many::ManyBounces;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The declaration a keyword names, or kick-bounce's refusal naming the nearby ones.
fn parameter(name: &str) -> PyResult<&'static ParameterDef> {
    kick_bounce::parameter(name).map_err(value_error)
}

/// The ball's law as `kick bounce --law` names it.
fn law(name: &str) -> PyResult<LawChoice> {
    LawChoice::from_name(name).map_err(value_error)
}

/// One bounce: the object `kick bounce --format json` prints.
#[pyfunction]
#[pyo3(signature = (*, law = "shell", **params))]
pub fn bounce<'py>(py: Python<'py>, law: &str, params: Option<&Bound<'py, PyDict>>) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let mut spec = BounceSpec::default();
        spec.law = Some(self::law(law)?);
        if let Some(params) = params {
            for (key, value) in params.iter() {
                let name: String = key.extract()?;
                let p = parameter(&name)?;
                if !value.is_none() {
                    spec.set(p.name, crate::params::value(p, &value)?).map_err(value_error)?;
                }
            }
        }
        let outcome = py.detach(|| kick_bounce::run(&spec)).map_err(library_error)?;
        crate::warn_outside(py, outcome.outside_validity.as_ref().map(|o| o.to_string()))?;
        crate::convert::json_to_py(py, &serde_json::to_value(outcome).map_err(value_error)?)
    })
}

impl Keywords for ManyBounces {
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
        parameter(name)
    }
}

/// Many bounces: `bounce`'s keywords, each a scalar or an array (`spin`
/// with a trailing axis of 3), broadcast by numpy's rules.
#[pyfunction]
#[pyo3(signature = (*, law = "shell", threads = None, progress = None, **arrays))]
pub fn bounce_many<'py>(
    py: Python<'py>,
    law: &str,
    threads: Option<&Bound<'py, PyAny>>,
    progress: Option<&Bound<'py, PyAny>>,
    arrays: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let mut base = BounceSpec::default();
        base.law = Some(self::law(law)?);
        run_many(py, &ManyBounces::default(), base, Run::new("bounce_many", threads, progress)?, arrays)
    })
}
