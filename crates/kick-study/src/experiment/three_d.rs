//! 3D experiments in the one experiment format (see the parent module).
//!
//! A file is a 3D experiment when it says `level = "3d"`, has a `[kick3d]`
//! table, or sweeps a parameter of the 3D level; `level = "1d"` keeps it 1D.
//! The keys are the 1D ones (`name`, `description`, `solver`, `law`,
//! `restitution`, `compress`, `[base]`, `[[sweep]]`) plus `[kick3d]` (the declared 3D
//! parameters, defaults as in `kick simulate3d`). A `[[sweep]]` axis may be
//! any scalar parameter of either level; `solver` is a `kick simulate3d
//! --solver` name (default `accurate`). Histories, `[[scenario]]` lists and
//! `table2` are 1D only.

use super::flight::key_span;
use super::{axis_values, build, ExperimentError, Locator, RawAxis, RawBase};
use kick_3d::{Kick3d, Kick3dError, Kick3dSpec, Solver3d};
use kick_core::parameters::{self, Level, ParameterDef, SetParameter, Shape, Value};
use kick_core::{short, Parameter, Scenario};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// Most cells one 3D grid may hold (~80 µs each on the accurate path).
pub const MAX_CELLS_3D: u64 = 10_000_000;

/// Parameter levels a 3D experiment takes.
const LEVELS_3D: &[Level] = &[Level::Scenario, Level::Kick3d];

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawExperiment3d {
    #[allow(dead_code)]
    level: Option<Spanned<String>>,
    name: Option<Spanned<String>>,
    description: Option<String>,
    solver: Option<Spanned<String>>,
    law: Option<Spanned<String>>,
    restitution: Option<Spanned<f64>>,
    base: Option<RawBase>,
    kick3d: Option<Kick3dSpec>,
    sweep: Option<Vec<RawAxis<String>>>,
    flight: Option<Spanned<kick_flight::FlightSpec>>,
    compress: Option<Spanned<toml::Value>>,
}

/// One swept parameter of a 3D grid and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis3d {
    pub parameter: &'static ParameterDef,
    pub values: Vec<f64>,
}

/// A grid of 3D kicks: the base kick and every combination of the axes'
/// values (cell order: the last axis varies fastest).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid3d {
    /// The 1D scenario with its law.
    pub scenario: Scenario,
    /// The 3D extras as given.
    pub kick3d: Kick3dSpec,
    pub axes: Vec<Axis3d>,
}

impl Grid3d {
    /// Number of cells (1 without axes).
    pub fn len(&self) -> u64 {
        self.axes.iter().map(|a| a.values.len() as u64).product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The grid's shape, one length per axis.
    pub fn shape(&self) -> Vec<usize> {
        self.axes.iter().map(|a| a.values.len()).collect()
    }

    /// The axes' values at cell `index`, in axis order.
    pub fn coordinates(&self, index: u64) -> Vec<f64> {
        let mut out = vec![0.0; self.axes.len()];
        self.coordinates_into(index, &mut out);
        out
    }

    /// [`Self::coordinates`] into `out` (one slot per axis), allocating nothing.
    pub fn coordinates_into(&self, index: u64, out: &mut [f64]) {
        crate::grid::decode(self.axes.iter().map(|a| a.values.len()), index, |k, position| out[k] = self.axes[k].values[position]);
    }

    /// The validated kick of cell `index`.
    pub fn kick(&self, index: u64) -> Result<Kick3d, Kick3dError> {
        let mut scenario = self.scenario;
        let mut spec = self.kick3d;
        for (axis, value) in self.axes.iter().zip(self.coordinates(index)) {
            match Parameter::from_name(axis.parameter.name) {
                Some(p) => scenario = scenario.with(p, value)?,
                None if axis.parameter.level == Level::Scenario => {
                    // The target restitution, the one 1D parameter outside `Parameter`.
                    scenario = scenario.with_law(scenario.law_kind(), Some(value))?;
                }
                None => spec.set_parameter(axis.parameter, Value::Number(value)).map_err(|e| Kick3dError::Experiment { reason: e.to_string() })?,
            }
        }
        Kick3d::new(scenario, &spec)
    }
}

/// A validated 3D experiment, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Experiment3d {
    pub name: String,
    pub description: String,
    pub path: PathBuf,
    pub text: String,
    /// Its `kick simulate3d --solver` name.
    pub solver_name: String,
    pub solver: Solver3d,
    pub grid: Grid3d,
    /// The `[flight]` table: every cell's kick is flown and the flight
    /// outcomes stored beside it.
    pub flight: Option<kick_flight::FlightSpec>,
    /// The `compress` key, as in 1D.
    pub compress: crate::columns::Compression,
}

/// Validate a 3D experiment (the parent's `parse_any` decided it is one).
pub(super) fn parse(path: &Path, text: &str, at: &Locator, stem: String) -> Result<Experiment3d, ExperimentError> {
    let raw: RawExperiment3d = toml::from_str(text).map_err(|e| at.toml_error(&e))?;
    let name = super::experiment_name(at, raw.name.as_ref(), stem)?;
    let (solver_name, solver) = match &raw.solver {
        Some(s) => {
            let solver = Solver3d::from_name(s.get_ref(), 1e-5).map_err(|e| at.error(s.span(), "solver", e.to_string()))?;
            (s.get_ref().clone(), solver)
        }
        None => ("accurate".to_string(), Solver3d::Accurate(kick_3d::Accurate3d::default())),
    };

    let base_raw = raw.base.unwrap_or_default();
    let law = match &raw.law {
        Some(n) => kick_core::LawKind::from_name(n.get_ref()).map_err(|e| at.error(n.span(), "law", e.to_string()))?,
        None => kick_core::LawKind::PowerLaw,
    };
    if let (Some(_), Some(r)) = (&raw.restitution, base_raw.restitution()) {
        return Err(at.error(r.span(), "base.restitution", "`restitution` is also set at the top level; set it in one place"));
    }
    let restitution = raw.restitution.as_ref().or(base_raw.restitution());
    // `damping` or `restitution` the law would ignore, given or swept: refused at its key.
    let swept = |name: &str| raw.sweep.iter().flatten().find(|a| a.parameter.get_ref() == name).map(|a| (a.parameter.span(), format!("sweep.{name}")));
    let damping = base_raw.get(Parameter::Damping).map(|d| (d.span(), "base.damping".to_string())).or_else(|| swept("damping"));
    let restitution_key = if raw.restitution.is_some() { "restitution" } else { "base.restitution" };
    let given_restitution = restitution.map(|r| (r.span(), restitution_key.to_string())).or_else(|| swept("restitution"));
    super::law_settings_apply(at, law, damping, given_restitution)?;
    let scenario = build(at, |p| base_raw.get(p), "base")?;
    let law_span = restitution.map(|r| r.span()).or(raw.law.as_ref().map(|l| l.span())).unwrap_or(0..0);
    let scenario = scenario
        .with_law(law, restitution.map(|r| *r.get_ref()))
        .map_err(|e| at.error(law_span.clone(), "law", e.to_string()))?;
    let kick3d = raw.kick3d.unwrap_or_default();
    // A problem of the fixed kick names its key in [kick3d] (or [base]).
    let locate = |e: &Kick3dError, fallback: &str| {
        let named = match e {
            Kick3dError::InvalidParameter { name, .. } => Some(*name),
            Kick3dError::OffsetOutsideBall { .. } => Some("offset"),
            _ => None,
        };
        match named.and_then(|n| key_span(text, "kick3d", n).map(|s| (s, format!("kick3d.{n}")))) {
            Some((span, key)) => at.error(span, &key, e.to_string()),
            None => at.error(0..0, fallback, e.to_string()),
        }
    };

    let mut axes: Vec<Axis3d> = Vec::new();
    let mut last_span = 0..0;
    let mut total: u64 = 1;
    for axis in raw.sweep.iter().flatten() {
        let name = axis.parameter.get_ref();
        let key = format!("sweep.{name}");
        let parameter = parameters::find_at(LEVELS_3D, name).map_err(|e| at.error(axis.parameter.span(), &key, e.to_string()))?;
        if parameter.shape != Shape::Scalar {
            return Err(at.error(axis.parameter.span(), &key, format!("a sweep axis takes a number; `{name}` is {}", parameter.shape.describe())));
        }
        if axes.iter().any(|a| a.parameter.name == parameter.name) {
            return Err(at.error(axis.parameter.span(), &key, "parameter swept twice"));
        }
        let fixed_at = match parameter.level {
            Level::Scenario => base_raw.value(parameter).map(|v| (v.span(), format!("base.{name}"))),
            _ => key_span(text, "kick3d", name).map(|s| (s, format!("kick3d.{name}"))),
        };
        if let Some((span, key)) = fixed_at {
            return Err(at.error(span, &key, "this parameter is also swept; set it in one place"));
        }
        if parameter.name == "restitution" && raw.restitution.is_some() {
            return Err(at.error(axis.parameter.span(), &key, "`restitution` is also set at the top level; set it in one place"));
        }
        let (values, span, value_spans) = axis_values(at, axis, &key)?;
        total = total.saturating_mul(values.len() as u64);
        if total > MAX_CELLS_3D {
            return Err(at.error(span, &key, format!("the grid exceeds {MAX_CELLS_3D} kicks")));
        }
        // Each value alone against the base, so the error names its line.
        for (&v, value_span) in values.iter().zip(&value_spans) {
            let one = Grid3d { scenario, kick3d, axes: vec![Axis3d { parameter, values: vec![v] }] };
            one.kick(0).map_err(|e| at.error(value_span.clone(), &key, format!("value {}: {e}", short(v))))?;
        }
        axes.push(Axis3d { parameter, values });
        last_span = span;
    }
    let grid = Grid3d { scenario, kick3d, axes };
    if grid.axes.is_empty() {
        grid.kick(0).map_err(|e| locate(&e, "kick3d"))?;
    }
    // Combinations (an offset with a smaller ball) can still fail.
    for i in 0..grid.len() {
        if let Err(e) = grid.kick(i) {
            let at_cell: Vec<String> =
                grid.axes.iter().zip(grid.coordinates(i)).map(|(a, v)| format!("{} = {}", a.parameter.name, short(v))).collect();
            return Err(at.error(last_span, "sweep", format!("grid point {i} ({}): {e}", at_cell.join(", "))));
        }
    }
    let flight = super::flight::parse(at, text, raw.flight.as_ref(), super::flight::After::ThreeD)?;
    let compress = super::compression(at, raw.compress.as_ref())?;
    Ok(Experiment3d {
        flight,
        compress,
        name,
        description: raw.description.unwrap_or_default(),
        path: path.to_path_buf(),
        text: text.to_string(),
        solver_name,
        solver,
        grid,
    })
}
