//! 3D experiments in the one experiment format (see the parent module).
//!
//! A file is a 3D experiment when it says `level = "3d"`, has a `[kick3d]`
//! table, or gives or sweeps a parameter of the 3D level; `level = "1d"`
//! keeps it 1D. The keys are the 1D ones (`name`, `description`, `solver`,
//! `law`, `restitution`, `compress`, `[base]`, `[[sweep]]`, `[flight]`) plus
//! `[kick3d]` (the declared 3D parameters, defaults as in `kick
//! simulate3d`). `[base]` takes every declared parameter of the kick (the
//! 1D scenario's, the ball's, the 3D kick's and the instep's, as
//! `[kick3d]` does) and of the flight (as `[flight]` does); a `[[sweep]]`
//! axis may be any scalar of them. `solver` is a `kick simulate3d --solver`
//! name (default `accurate`). Histories, `[[scenario]]` lists and `table2`
//! are 1D only.

use super::flight::key_span;
use super::{axis_values, build, Axis, ExperimentError, Grid, Locator, RawBase, RawExperiment};
use crate::flight::FlightPlan;
use kick_3d::{Kick3d, Kick3dError, Kick3dSpec, Solver3d};
use kick_core::parameters::{self, Level, SetParameter, Shape, Value};
use kick_core::{short, Parameter, Scenario};

/// Most cells one 3D grid may hold (~80 µs each on the accurate path).
pub const MAX_CELLS_3D: u64 = 10_000_000;

/// The kick's parameters a 3D file gives and sweeps: the 1D scenario's and
/// its ball's, the 3D kick's, the instep's and the foot's (the leg's pose,
/// the boot) (and the flight's, with `[flight]`).
const LEVELS_3D: &[Level] = &[Level::Scenario, Level::Bounce, Level::Kick3d, Level::Instep, Level::Foot];

/// The 3D part of an experiment: its solver and a grid of kicks, the base
/// kick and every combination of the axes' values (cell order: the last
/// axis varies fastest).
#[derive(Debug, Clone, PartialEq)]
pub struct Kicks3d {
    /// Its `kick simulate3d --solver` name.
    pub solver_name: String,
    pub solver: Solver3d,
    /// The 1D scenario with its law.
    pub scenario: Scenario,
    /// The 3D extras as given.
    pub kick3d: Kick3dSpec,
    /// Axes of parameters of either level.
    pub grid: Grid,
}

impl Kicks3d {
    /// The validated kick of cell `index`.
    pub fn kick(&self, index: u64) -> Result<Kick3d, Kick3dError> {
        kick_at(self.scenario, self.kick3d, &self.grid, index)
    }
}

/// The kick of cell `index` of `grid` over the base kick: a 1D parameter's
/// value applied to the scenario, a 3D one's to the 3D extras.
fn kick_at(mut scenario: Scenario, mut spec: Kick3dSpec, grid: &Grid, index: u64) -> Result<Kick3d, Kick3dError> {
    // In axis order: each step is validated, so the order names the error.
    for (axis, value) in grid.axes.iter().zip(grid.coordinates(index)) {
        match axis.parameter.level {
            // The flight's are the flight's (`Grid::flight_spec`).
            Level::Flight => {}
            // Through the spec, as a 3D kick's base: the approach is kick-3d's to check, along the normal.
            Level::Scenario | Level::Bounce => {
                let mut cell = scenario.spec();
                cell.set_parameter(axis.parameter, Value::Number(value)).map_err(|e| Kick3dError::Experiment { reason: e.to_string() })?;
                scenario = cell.build_drawn_3d_base()?;
            }
            // The foot: its spec with the value, built again (a pose moves the leg's mass).
            Level::Foot => {
                let mut foot_spec = scenario.spec();
                foot_spec
                    .set_parameter(axis.parameter, Value::Number(value))
                    .map_err(|e| Kick3dError::Experiment { reason: e.to_string() })?;
                scenario = scenario.on_foot(foot_spec.foot()?)?;
            }
            _ => spec.set_parameter(axis.parameter, Value::Number(value)).map_err(|e| Kick3dError::Experiment { reason: e.to_string() })?,
        }
    }
    Kick3d::new(scenario, &spec)
}

/// The 3D part of an experiment (the parent's `parse` decided it is one).
pub(super) fn kicks(at: &Locator, text: &str, raw: &RawExperiment, flight: Option<&FlightPlan>) -> Result<Kicks3d, ExperimentError> {
    let (solver_name, solver) = match &raw.solver {
        Some(s) => {
            let solver = Solver3d::from_name(s.get_ref(), 1e-5).map_err(|e| at.error(s.span(), "solver", e.to_string()))?;
            (s.get_ref().clone(), solver)
        }
        None => ("accurate".to_string(), Solver3d::Accurate(kick_3d::Accurate3d::default())),
    };

    let no_base = RawBase::default();
    let base_raw = raw.base.as_ref().unwrap_or(&no_base);
    let law = super::contact_law(at, raw)?;
    if let (Some(_), Some(r)) = (&raw.restitution, base_raw.restitution()) {
        return Err(at.error(r.span(), "base.restitution", "`restitution` is also set at the top level; set it in one place"));
    }
    let restitution = raw.restitution.as_ref().or(base_raw.restitution());
    // `damping` or `restitution` the law would ignore, given or swept: refused at its key.
    let swept = |name: &str| {
        raw.sweep.iter().flatten().find(|a| a.parameter.get_ref() == name).map(|a| (a.parameter.span(), format!("sweep.{name}")))
    };
    let damping = base_raw.get(Parameter::Damping).map(|d| (d.span(), "base.damping".to_string())).or_else(|| swept("damping"));
    let restitution_key = if raw.restitution.is_some() { "restitution" } else { "base.restitution" };
    let given_restitution = restitution.map(|r| (r.span(), restitution_key.to_string())).or_else(|| swept("restitution"));
    super::law_settings_apply(at, law, damping, given_restitution)?;
    // A 3D kick's base: the approach is checked along the contact normal (kick-3d).
    let scenario = build(at, |p| base_raw.get(p), "base", false)?;
    let law_span = restitution.map(|r| r.span()).or(raw.law.as_ref().map(|l| l.span())).unwrap_or(0..0);
    let scenario =
        scenario.with_law_3d_base(law, restitution.map(|r| *r.get_ref())).map_err(|e| at.error(law_span.clone(), "law", e.to_string()))?;
    let ball = super::shell_ball(at, law, |p| base_raw.value(p).map(|v| (v, format!("base.{}", p.name))))?;
    let scenario = ball.map_or(scenario, |ball| scenario.with_shell(ball));
    let scenario = super::on_foot(
        at,
        scenario,
        |p| base_raw.value(p).map(|v| (v, format!("base.{}", p.name))),
        |p| base_raw.switch(p).map(|v| (v, format!("base.{}", p.name))),
    )?;
    let mut kick3d = raw.kick3d.unwrap_or_default();
    // [base]'s keys of the 3D kick and the instep: as [kick3d]'s.
    for (p, value, span) in base_raw.given().filter(|(p, _, _)| matches!(p.level, Level::Kick3d | Level::Instep)) {
        if kick3d.value(p).is_some() {
            return Err(at.error(span, &format!("base.{}", p.name), "also set in [kick3d]; set it in one place"));
        }
        kick3d.set_parameter(p, value).map_err(|e| at.error(span, &format!("base.{}", p.name), e.to_string()))?;
    }
    // A problem of the fixed kick names its key in [kick3d] (or [base]).
    let in_table = |n: &str| {
        key_span(text, "kick3d", n)
            .map(|s| (s, format!("kick3d.{n}")))
            .or_else(|| base_raw.given().find(|(p, _, _)| p.name == n).map(|(_, _, s)| (s, format!("base.{n}"))))
    };
    let locate = |e: &Kick3dError, fallback: &str| {
        let named = match e {
            Kick3dError::InvalidParameter { name, .. } => Some(*name),
            Kick3dError::OffsetOutsideBall { .. } => Some("offset"),
            _ => None,
        };
        match named.and_then(in_table) {
            Some((span, key)) => at.error(span, &key, e.to_string()),
            None => at.error(0..0, fallback, e.to_string()),
        }
    };

    let mut axes: Vec<Axis> = Vec::new();
    let mut last_span = 0..0;
    let mut total: u64 = 1;
    for axis in raw.sweep.iter().flatten() {
        let name = axis.parameter.get_ref();
        let key = format!("sweep.{name}");
        let parameter = match parameters::find_at(LEVELS_3D, name) {
            Ok(p) => p,
            Err(e) => match super::flight::axis_parameter(name, flight, super::flight::After::ThreeD) {
                Some(found) => found.map_err(|e| at.error(axis.parameter.span(), &key, e.to_string()))?,
                None => return Err(at.error(axis.parameter.span(), &key, e.to_string())),
            },
        };
        if parameter.shape != Shape::Scalar {
            return Err(at.error(
                axis.parameter.span(),
                &key,
                format!("a sweep axis takes a number; `{name}` is {}", parameter.shape.describe()),
            ));
        }
        if axes.iter().any(|a| a.parameter.name == parameter.name) {
            return Err(at.error(axis.parameter.span(), &key, "parameter swept twice"));
        }
        let fixed_at = match parameter.level {
            Level::Flight => None,
            Level::Scenario | Level::Bounce | Level::Foot => base_raw.value(parameter).map(|v| (v.span(), format!("base.{name}"))),
            _ => key_span(text, "kick3d", name)
                .map(|s| (s, format!("kick3d.{name}")))
                .or_else(|| base_raw.given().find(|(p, _, _)| p.name == parameter.name).map(|(_, _, s)| (s, format!("base.{name}")))),
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
        for (i, &v) in values.iter().enumerate() {
            let value_span = value_spans.at(i);
            let checked = match (parameter.level, flight) {
                (Level::Flight, Some(plan)) => {
                    super::flight::check_axis_value(&plan.rest, parameter, v, super::flight::After::ThreeD).map_err(|e| e.to_string())
                }
                _ => {
                    let one = Grid { axes: vec![Axis { parameter, values: vec![v] }] };
                    match kick_at(scenario, kick3d, &one, 0) {
                        // A fixed key's own refusal is said at that key, not at
                        // this axis's value ([kick3d] friction = nan pointed here).
                        Err(e @ Kick3dError::InvalidParameter { name, .. }) if name != parameter.name && in_table(name).is_some() => {
                            return Err(locate(&e, &key));
                        }
                        other => other.map(drop).map_err(|e| e.to_string()),
                    }
                }
            };
            checked.map_err(|e| at.error(value_span.clone(), &key, format!("value {}: {e}", short(v))))?;
        }
        axes.push(Axis { parameter, values });
        last_span = span;
    }
    let kicks = Kicks3d { solver_name, solver, scenario, kick3d, grid: Grid { axes } };
    if kicks.grid.axes.is_empty() {
        kicks.kick(0).map_err(|e| locate(&e, "kick3d"))?;
    }
    // Combinations (an offset with a smaller ball) can still fail.
    for i in 0..kicks.grid.len() {
        if let Err(e) = kicks.kick(i) {
            let at_cell: Vec<String> = kicks
                .grid
                .axes
                .iter()
                .zip(kicks.grid.coordinates(i))
                .map(|(a, v)| format!("{} = {}", a.parameter.name, short(v)))
                .collect();
            return Err(at.error(last_span, "sweep", format!("grid point {i} ({}): {e}", at_cell.join(", "))));
        }
    }
    Ok(kicks)
}
