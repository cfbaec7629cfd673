//! 1D experiments in the one experiment format (see the parent module):
//! solvers, and scenarios from a grid of declared parameters (the 1D
//! scenario's, the target restitution, the shell ball's, and with
//! `[flight]` the flight's), named `[[scenario]]` tables or a Table 2 file;
//! summaries or histories.

use super::{
    axis_values, build, contact_law, law_settings_apply, Axis, Experiment, ExperimentError, Grid, Kicks, Kicks1d, Located, Locator, Output,
    RawBase, RawExperiment, Scenarios, MAX_HISTORY_SAMPLES, MAX_HISTORY_SCENARIOS, MAX_SCENARIOS,
};
use crate::flight::FlightPlan;
use kick_compliant::table2::Table2File;
use kick_compliant::SolverChoice;
use kick_core::parameters::{self, Level, ParameterDef, SetParameter};
use kick_core::{short, Parameter, Scenario, ScenarioSpec};
use std::path::{Path, PathBuf};
use toml::Spanned;

/// The parameters of a 1D grid's axes: any scalar of the 1D scenario and
/// its ball (`ScenarioSpec::LEVELS`), or of the flight after it.
pub(super) fn axes(at: &Locator, raw: &RawExperiment, flight: Option<&FlightPlan>) -> Result<Vec<&'static ParameterDef>, ExperimentError> {
    let mut swept = Vec::new();
    for axis in raw.sweep.iter().flatten() {
        let name = axis.parameter.get_ref();
        let key = format!("sweep.{name}");
        let parameter = match super::flight::axis_parameter(name, flight, super::flight::After::OneD) {
            Some(found) => found.map_err(|e| at.error(axis.parameter.span(), &key, e.to_string()))?,
            None => parameters::find_at(ScenarioSpec::LEVELS, name).map_err(|e| {
                let mut valid: Vec<&'static str> = parameters::at_levels(ScenarioSpec::LEVELS).map(|p| p.name).collect();
                valid.extend(kick_flight::FLIGHT_PARAMETERS.iter().map(|p| p.name));
                let message = match e {
                    parameters::ParameterError::Unknown { nearby, .. } => {
                        format!("unknown parameter `{name}` of the 1D scenario or its flight{}", parameters::did_you_mean(&nearby, &valid))
                    }
                    other => other.to_string(),
                };
                at.error(axis.parameter.span(), "parameter", message)
            })?,
        };
        swept.push(parameter);
    }
    Ok(swept)
}

/// The 1D part of an experiment: its solvers and scenarios, and what to record.
pub(super) fn kicks(
    at: &Locator,
    path: &Path,
    raw: &RawExperiment,
    swept: &[&'static ParameterDef],
    flight: Option<&FlightPlan>,
) -> Result<(Kicks1d, Output), ExperimentError> {
    let dt = match &raw.dt {
        Some(dt) => {
            let v = *dt.get_ref();
            if !(v.is_finite() && v > 0.0) {
                return Err(at.error(dt.span(), "dt", format!("{} must be finite and > 0 (s)", short(v))));
            }
            v
        }
        None => kick_compliant::SeedRk4::default().step,
    };
    let solver_names: Vec<Spanned<String>> = match (&raw.solver, &raw.solvers) {
        (Some(s), None) => vec![s.clone()],
        (None, Some(list)) => {
            if list.get_ref().is_empty() {
                return Err(at.error(list.span(), "solvers", "list at least one solver"));
            }
            list.get_ref().clone()
        }
        (None, None) => vec![Spanned::new(0..0, "accurate".to_string())],
        (Some(s), Some(_)) => return Err(at.error(s.span(), "solver", "give `solver` or `solvers`, not both")),
    };
    if let Some(given) = &raw.dt {
        let names: Vec<&str> = solver_names.iter().map(|n| n.get_ref().as_str()).collect();
        SolverChoice::check_step_given(&names).map_err(|e| at.error(given.span(), "dt", e.to_string()))?;
    }
    let mut solvers = Vec::new();
    for (i, name) in solver_names.iter().enumerate() {
        if solver_names[..i].iter().any(|n| n.get_ref() == name.get_ref()) {
            return Err(at.error(name.span(), "solvers", format!("`{}` listed twice", name.get_ref())));
        }
        solvers.push(SolverChoice::from_name(name.get_ref(), dt).map_err(|e| at.error(name.span(), "solver", e.to_string()))?);
    }

    let no_base = RawBase::default();
    let base_raw = raw.base.as_ref().unwrap_or(&no_base);
    // A 1D file's [base]: the scenario's and its ball's keys, and the flight's (set on [flight]).
    if let Some((p, span)) = base_raw.outside(super::TABLE_LEVELS, true) {
        return Err(at.error(
            span,
            &format!("base.{}", p.name),
            format!("`{}` is a parameter of the {}: give level = \"3d\"", p.name, p.level.name()),
        ));
    }
    let law = contact_law(at, raw)?;
    // The target restitution is a declared parameter: at the top level beside
    // `law`, or in a table ([[scenario]] over [base]), but not both.
    let top_restitution = raw.restitution.as_ref();
    let law_span = top_restitution.map(|r| r.span()).or(raw.law.as_ref().map(|l| l.span())).unwrap_or(0..0);
    let check_law = |damping, restitution| law_settings_apply(at, law, damping, restitution);
    let with_law = |s: Scenario,
                    table: &str,
                    given: Option<&Spanned<f64>>,
                    damping: Located,
                    ball: Option<kick_core::ShellBall>|
     -> Result<Scenario, ExperimentError> {
        let key = format!("{table}.restitution");
        if let (Some(_), Some(r)) = (top_restitution, given) {
            return Err(at.error(r.span(), &key, "`restitution` is also set at the top level; set it in one place"));
        }
        let restitution_key = if given.is_some() { key.clone() } else { "restitution".to_string() };
        check_law(damping, given.or(top_restitution).map(|r| (r.span(), restitution_key)))?;
        let (restitution, span, key) = match given.or(top_restitution) {
            Some(r) if given.is_some() => (Some(*r.get_ref()), r.span(), key),
            other => (other.map(|r| *r.get_ref()), law_span.clone(), "law".to_string()),
        };
        let s = s.with_law(law, restitution).map_err(|e| at.error(span, &key, e.to_string()))?;
        Ok(ball.map_or(s, |ball| s.with_shell(ball)))
    };
    let base_key = |p: &'static kick_core::parameters::ParameterDef| base_raw.value(p).map(|v| (v, format!("base.{}", p.name)));
    // The base scenario of a grid; named scenarios build their own over [base].
    let base_damping = || base_raw.get(Parameter::Damping).map(|d| (d.span(), "base.damping".to_string()));
    let base_switch = |p: &'static kick_core::parameters::ParameterDef| base_raw.switch(p).map(|v| (v, format!("base.{}", p.name)));
    // `swept`: a swept restitution's first value, the base's target (each cell sets its own).
    let base = |swept: Option<&Spanned<f64>>| {
        let ball = super::shell_ball(at, law, base_key)?;
        let scenario =
            with_law(build(at, |p| base_raw.get(p), "base", true)?, "base", base_raw.restitution().or(swept), base_damping(), ball)?;
        super::on_foot(at, scenario, base_key, base_switch)
    };

    let sources = [raw.sweep.is_some(), raw.scenario.is_some(), raw.table2.is_some()];
    if sources.iter().filter(|&&s| s).count() > 1 {
        let span = raw.table2.as_ref().map(|t| t.span()).unwrap_or(0..0);
        return Err(at.error(span, "sweep", "give one of [[sweep]], [[scenario]] or table2"));
    }

    let scenarios = if let Some(axes_raw) = &raw.sweep {
        let restitution_axis = axes_raw.iter().zip(swept).find(|(_, p)| p.name == parameters::RESTITUTION.name);
        if let Some((axis, _)) = restitution_axis {
            check_law(None, Some((axis.parameter.span(), "sweep.restitution".to_string())))?;
        }
        let swept_restitution = match restitution_axis {
            Some((axis, _)) if top_restitution.is_none() && base_raw.restitution().is_none() => {
                let (values, span, _) = axis_values(at, axis, "sweep.restitution")?;
                Some(Spanned::new(span, values[0]))
            }
            _ => None,
        };
        let base = base(swept_restitution.as_ref())?;
        let mut axes: Vec<Axis> = Vec::new();
        let mut spans = Vec::new();
        let mut total: u64 = 1;
        for (axis, &parameter) in axes_raw.iter().zip(swept) {
            let key = format!("sweep.{}", parameter.name);
            if axes.iter().any(|a| a.parameter.name == parameter.name) {
                return Err(at.error(axis.parameter.span(), &key, "parameter swept twice"));
            }
            if parameter.level != Level::Flight {
                if let Some(v) = base_raw.value(parameter) {
                    return Err(at.error(
                        v.span(),
                        &format!("base.{}", parameter.name),
                        "this parameter is also swept; set it in one place",
                    ));
                }
            }
            if parameter.name == Parameter::Damping.name() {
                check_law(Some((axis.parameter.span(), key.clone())), None)?;
            }
            if parameter.name == parameters::RESTITUTION.name {
                if top_restitution.is_some() || base_raw.restitution().is_some() {
                    return Err(at.error(axis.parameter.span(), &key, "`restitution` is also set; set it in one place"));
                }
                check_law(None, Some((axis.parameter.span(), key.clone())))?;
            }
            let (values, span, value_spans) = axis_values(at, axis, &key)?;
            total = total.saturating_mul(values.len() as u64);
            if total > MAX_SCENARIOS {
                return Err(at.error(span, &key, format!("the grid exceeds {MAX_SCENARIOS} scenarios")));
            }
            // Each value alone against the base, so the error names its line.
            for (i, &v) in values.iter().enumerate() {
                let value_span = value_spans.at(i);
                let checked = match (parameter.level, flight) {
                    (Level::Flight, Some(plan)) => {
                        super::flight::check_axis_value(&plan.rest, parameter, v, super::flight::After::OneD).map_err(|e| e.to_string())
                    }
                    _ => base.with_parameter(parameter, v).map(drop).map_err(|e| e.to_string()),
                };
                checked.map_err(|e| at.error(value_span.clone(), &key, format!("value {}: {e}", short(v))))?;
            }
            axes.push(Axis { parameter, values });
            spans.push(span);
        }
        let grid = Scenarios::Grid { base, grid: Grid { axes } };
        // Combinations (e.g. foot_speed with ball_speed) can still fail.
        for i in 0..grid.len() {
            if let Err(e) = grid.scenario(i) {
                return Err(at.error(spans.last().cloned().unwrap_or(0..0), "sweep", format!("grid point {i}: {e}")));
            }
        }
        grid
    } else if let Some(list) = &raw.scenario {
        let mut names = Vec::new();
        let mut scenarios = Vec::new();
        for entry in list {
            let key = format!("scenario.{}", entry.name().get_ref());
            if let Some((p, span)) = entry.outside(super::TABLE_LEVELS, false) {
                return Err(at.error(
                    span,
                    &format!("{key}.{}", p.name),
                    "a [[scenario]] table takes the 1D scenario's and its ball's parameters",
                ));
            }
            if names.contains(entry.name().get_ref()) {
                return Err(at.error(entry.name().span(), &key, "scenario name used twice"));
            }
            let restitution = entry.restitution().or(base_raw.restitution());
            let damping = entry.get(Parameter::Damping).map(|d| (d.span(), format!("{key}.damping"))).or_else(base_damping);
            let ball = super::shell_ball(at, law, |p| entry.value(p).map(|v| (v, format!("{key}.{}", p.name))).or_else(|| base_key(p)))?;
            let scenario = with_law(
                build(at, |p| entry.get(p).or_else(|| base_raw.get(p)), "scenario", true)?,
                "scenario",
                restitution,
                damping,
                ball,
            )?;
            let scenario = super::on_foot(
                at,
                scenario,
                |p| entry.value(p).map(|v| (v, format!("{key}.{}", p.name))).or_else(|| base_key(p)),
                |p| entry.switch(p).map(|v| (v, format!("{key}.{}", p.name))).or_else(|| base_switch(p)),
            )?;
            names.push(entry.name().get_ref().clone());
            scenarios.push(scenario);
        }
        if scenarios.is_empty() {
            return Err(at.error(0..0, "scenario", "list at least one scenario"));
        }
        Scenarios::Named { names, scenarios }
    } else if let Some(t2) = &raw.table2 {
        // A Table 2 file gives every row whole, law included: what the
        // experiment file adds would be ignored (it was, silently).
        let why = "a table2 file gives every scenario whole, its law included; this would be ignored: leave it out";
        if let Some((p, _, span)) = base_raw.given().next() {
            return Err(at.error(span, &format!("base.{}", p.name), why));
        }
        if let Some(given) = &raw.law {
            return Err(at.error(given.span(), "law", why));
        }
        if let Some(given) = top_restitution {
            return Err(at.error(given.span(), "restitution", why));
        }
        let t2_path = table2_path(path, t2.get_ref());
        let t2_text = kick_core::input::read_text(&t2_path, kick_core::input::MAX_TEXT_BYTES)
            .map_err(|e| at.error(t2.span(), "table2", format!("{}: {e}", t2_path.display())))?;
        let file = Table2File::parse(&t2_text).map_err(|e| at.error(t2.span(), "table2", format!("{}: {e}", t2_path.display())))?;
        let rows = file.scenarios().map_err(|e| at.error(t2.span(), "table2", format!("{}: {e}", t2_path.display())))?;
        let (names, scenarios) = rows.into_iter().unzip();
        Scenarios::Named { names, scenarios }
    } else {
        Scenarios::Grid { base: base(None)?, grid: Grid::default() }
    };

    let output = match &raw.output {
        None => Output::Summary,
        Some(out) => {
            let mode = out.mode.as_ref().map(|m| m.get_ref().as_str()).unwrap_or("summary");
            let mode_span = out.mode.as_ref().map(|m| m.span()).unwrap_or(0..0);
            match (mode, &out.interval) {
                ("summary", None) => Output::Summary,
                ("summary", Some(i)) => return Err(at.error(i.span(), "output.interval", "only with mode = \"history\"")),
                ("history", None) => {
                    return Err(at.error(mode_span, "output.interval", "mode = \"history\" needs a sampling interval (s)"))
                }
                ("history", Some(i)) => {
                    let v = *i.get_ref();
                    if !(v.is_finite() && v > 0.0) {
                        return Err(at.error(i.span(), "output.interval", format!("{} must be finite and > 0 (s)", short(v))));
                    }
                    if scenarios.len() > MAX_HISTORY_SCENARIOS {
                        return Err(at.error(
                            mode_span,
                            "output.mode",
                            format!(
                                "histories of {} scenarios; at most {MAX_HISTORY_SCENARIOS} (use mode = \"summary\" for large sweeps)",
                                scenarios.len()
                            ),
                        ));
                    }
                    for k in 0..scenarios.len() {
                        let horizon = scenarios.scenario(k).map(|s| s.contact_horizon()).unwrap_or(0.0);
                        // The horizon is 1000 elastic contact times; a history
                        // of a normal contact is ~1/1000 of this bound.
                        if horizon / v > MAX_HISTORY_SAMPLES * kick_core::scenario::CONTACT_HORIZON_FACTOR {
                            return Err(at.error(
                                i.span(),
                                "output.interval",
                                format!("{} s is too fine: more than {MAX_HISTORY_SAMPLES:e} samples per contact", short(v)),
                            ));
                        }
                    }
                    Output::History { interval: v }
                }
                (other, _) => return Err(at.error(mode_span, "output.mode", format!("`{other}`: expected \"summary\" or \"history\""))),
            }
        }
    };

    Ok((Kicks1d { solvers, scenarios }, output))
}

/// The Table 2 file `table2 = "NAME"` of the experiment file `path` names: beside it.
pub(super) fn table2_path(path: &Path, name: &str) -> PathBuf {
    path.parent().unwrap_or(Path::new(".")).join(name)
}

pub(super) fn table2_experiment(path: &Path, text: &str, name: String, at: &Locator) -> Result<Experiment, ExperimentError> {
    let file = Table2File::parse(text).map_err(|e| at.error(0..0, "row", e.to_string()))?;
    let rows = file.scenarios().map_err(|e| at.error(0..0, "row", e.to_string()))?;
    // The file's own solver (the paper's method) first, then the accurate reference.
    let mut solvers = vec![SolverChoice::from_name(&file.solver, file.dt).map_err(|e| at.error(0..0, "solver", e.to_string()))?];
    if file.solver != "accurate" {
        solvers.push(SolverChoice::from_name("accurate", file.dt).map_err(|e| at.error(0..0, "solver", e.to_string()))?);
    }
    let (names, scenarios) = rows.into_iter().unzip();
    Ok(Experiment {
        name: if file.name.is_empty() { name } else { file.name.clone() },
        description: file.description.clone(),
        path: path.to_path_buf(),
        read: vec![path.to_path_buf()],
        text: text.to_string(),
        output: Output::Summary,
        flight: None,
        compress: crate::columns::Compression::None,
        kicks: Kicks::OneD(Kicks1d { solvers, scenarios: Scenarios::Named { names, scenarios } }),
    })
}
