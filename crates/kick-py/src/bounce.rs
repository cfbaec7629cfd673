//! `bounce`: the ball alone on a rigid plate (crate kick-bounce, `kick
//! bounce`), keywords from its declared list
//! (`kick_bounce::BOUNCE_PARAMETERS`, named as the CLI's flags), one call to
//! `kick_bounce::run`; `bounce_many` the same per row of arrays.

use crate::many::{run_many, Model, Run, Solved};
use crate::{guard, library_error, value_error};
use kick_bounce::{BounceOutcome, BounceSpec, LawChoice, Tangential};
use kick_core::parameters::{ParameterDef, Value};
use kick_core::Status;
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

/// `bounce_many`'s rows: a spec per row through `kick_bounce::run`.
struct ModelBounce {
    columns: Vec<(String, Vec<usize>)>,
}

/// Output columns of `bounce_many`: (name, width, unit).
pub const BOUNCE_COLUMNS: [(&str, usize, &str); 12] = [
    ("restitution", 1, "1"),
    ("contact_time", 1, "s"),
    ("peak_force", 1, "N"),
    ("peak_force_time", 1, "s"),
    ("max_compression", 1, "m"),
    ("max_compression_time", 1, "s"),
    ("normal_impulse", 1, "N s"),
    ("impact_velocity", 3, "m/s"),
    ("exit_velocity", 3, "m/s"),
    ("exit_spin", 3, "rad/s"),
    ("tangential", 1, "0 no slip, 1 grips, 2 slides"),
    ("rebound_height", 1, "m (NaN without drop_height)"),
];

/// The numbers of one outcome in [`BOUNCE_COLUMNS`] order.
fn row_values(o: &BounceOutcome, row: &mut [f64]) {
    let mut at = 0;
    let mut put = |values: &[f64]| {
        row[at..at + values.len()].copy_from_slice(values);
        at += values.len();
    };
    put(&[o.restitution, o.contact_time, o.peak_force, o.peak_force_time, o.max_compression, o.max_compression_time, o.normal_impulse]);
    put(&o.impact_velocity);
    put(&o.exit_velocity);
    put(&o.exit_spin);
    put(&[match o.tangential {
        Tangential::NoSlip => 0.0,
        Tangential::Grips => 1.0,
        Tangential::Slides => 2.0,
    }]);
    put(&[o.rebound_height.unwrap_or(f64::NAN)]);
}

impl Model for ModelBounce {
    type Spec = BounceSpec;
    fn parameter(&self, name: &str) -> PyResult<&'static ParameterDef> {
        parameter(name)
    }
    fn set(&self, spec: &mut BounceSpec, parameter: &'static ParameterDef, value: Value) {
        let _ = spec.set(parameter.name, value);
    }
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &BounceSpec, row: &mut [f64]) -> Result<Solved, (Status, String)> {
        let failed = |e: kick_core::KickError| (e.status(), e.to_string());
        let o = kick_bounce::run(spec).map_err(failed)?;
        row_values(&o, row);
        Ok(Solved::new(o.evaluations, o.outside_validity))
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
        let model = ModelBounce {
            columns: BOUNCE_COLUMNS.iter().map(|(n, w, _)| (n.to_string(), if *w == 1 { vec![] } else { vec![*w] })).collect(),
        };
        run_many(py, &model, base, Run::new("bounce_many", threads, progress)?, arrays)
    })
}
