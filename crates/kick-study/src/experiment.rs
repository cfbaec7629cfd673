//! Experiment files (`experiments/*.toml`): what to run and what to keep.
//!
//! ```toml
//! name = "figure3"                 # optional, default: the file's stem
//! description = "Stiffness sweep"
//! solvers = ["accurate"]           # or solver = "accurate"; names as `kick simulate --solver`
//! dt = 5e-6                        # step of seed-rk4, s (default 5e-6)
//!
//! [base]                           # any of the 8 parameters; missing ones: Table 1
//! damping = 120.0
//!
//! [[sweep]]                        # grid: every combination of all [[sweep]] axes,
//! parameter = "stiffness"          # the last axis varying fastest
//! log = { from = 1e5, to = 1e7, count = 41 }   # or linear = {...}, or values = [...]
//!
//! compress = 4                    # optional: shuffle + deflate the result file's
//!                                  # per-row datasets at level 1..9 (or true: 4)
//!
//! [output]
//! mode = "history"                 # "summary" (default) or "history"
//! interval = 1e-5                  # history sampling interval, s
//! ```
//!
//! Instead of `[[sweep]]`, a file may list `[[scenario]]` tables (a `name`
//! plus any parameters, relative to `[base]`) or name a Table 2 file with
//! `table2 = "table2.toml"`. A Table 2 file itself (`kick fit table2`) is run
//! as its eight named rows with its own solver and `accurate`.
//!
//! Every problem is reported with the file, line, column and key.

use kick_compliant::table2::Table2File;
use kick_compliant::SolverChoice;
use kick_core::parameters::{self, Level, ParameterDef};
use kick_core::{short, KickError, Parameter, Scenario};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

mod flight;
mod three_d;
pub use three_d::{Axis3d, Experiment3d, Grid3d, MAX_CELLS_3D};

type Span = std::ops::Range<usize>;

impl ExperimentError {
    /// `file:line:column: `key`: message`, or `file: message` when no line applies.
    fn located(&self) -> String {
        if self.line == 0 {
            format!("{}: {}", self.file, self.message)
        } else {
            format!("{}:{}:{}: `{}`: {}", self.file, self.line, self.column, self.key, self.message)
        }
    }
}

/// Most scenarios one experiment may hold.
pub const MAX_SCENARIOS: u64 = 100_000_000;
/// Most scenarios whose time histories one file may hold.
pub const MAX_HISTORY_SCENARIOS: u64 = 1000;
/// Most samples per recorded history (interval versus contact horizon).
pub const MAX_HISTORY_SAMPLES: f64 = kick_core::MAX_HISTORY_SAMPLES as f64;

/// A problem in an experiment file, located.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.located())]
pub struct ExperimentError {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub key: String,
    pub message: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawExperiment {
    /// "1d" or "3d" (see [`parse_any`]).
    level: Option<Spanned<String>>,
    name: Option<Spanned<String>>,
    description: Option<String>,
    solver: Option<Spanned<String>>,
    solvers: Option<Spanned<Vec<Spanned<String>>>>,
    dt: Option<Spanned<f64>>,
    base: Option<RawBase>,
    sweep: Option<Vec<RawAxis>>,
    scenario: Option<Vec<RawNamed>>,
    table2: Option<Spanned<String>>,
    output: Option<RawOutput>,
    /// Contact law of every scenario (default: the paper's).
    law: Option<Spanned<String>>,
    /// Target restitution of a law other than the paper's.
    restitution: Option<Spanned<f64>>,
    /// Flight outcomes on every row ([`flight`]).
    flight: Option<Spanned<kick_flight::FlightSpec>>,
    /// Store the per-row datasets compressed ([`compression`]).
    compress: Option<Spanned<toml::Value>>,
}

/// A `[base]` or `[[scenario]]` table: values of the declared 1D parameters
/// (`kick_core::parameters`), with their spans; a `[[scenario]]` table also
/// has its `name`. Any other key is refused at its line with the nearby names.
#[derive(Debug, Default)]
struct RawSpec<const NAMED: bool> {
    name: Option<Spanned<String>>,
    values: Vec<(&'static ParameterDef, Spanned<f64>)>,
}

type RawBase = RawSpec<false>;
type RawNamed = RawSpec<true>;

impl<const NAMED: bool> RawSpec<NAMED> {
    fn value(&self, parameter: &ParameterDef) -> Option<&Spanned<f64>> {
        self.values.iter().find(|(p, _)| p.name == parameter.name).map(|(_, v)| v)
    }
    fn get(&self, p: Parameter) -> Option<&Spanned<f64>> {
        self.value(p.def())
    }
    fn restitution(&self) -> Option<&Spanned<f64>> {
        self.value(&parameters::RESTITUTION)
    }
    /// The table's name (`[[scenario]]` tables always have one).
    fn name(&self) -> &Spanned<String> {
        self.name.as_ref().unwrap_or_else(|| unreachable!("a named table without a name is refused when read"))
    }
}

impl<'de, const NAMED: bool> Deserialize<'de> for RawSpec<NAMED> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Keys<const NAMED: bool>;
        impl<'de, const NAMED: bool> serde::de::Visitor<'de> for Keys<NAMED> {
            type Value = RawSpec<NAMED>;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a table of 1D scenario parameters")
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<RawSpec<NAMED>, A::Error> {
                let mut table = RawSpec::<NAMED>::default();
                while let Some(key) = map.next_key::<String>()? {
                    if NAMED && key == "name" {
                        table.name = Some(map.next_value()?);
                        continue;
                    }
                    match parameters::find_at(&[Level::Scenario], &key) {
                        Ok(parameter) => {
                            if table.value(parameter).is_some() {
                                return Err(serde::de::Error::custom(format!("duplicate key `{key}`")));
                            }
                            table.values.push((parameter, map.next_value()?));
                        }
                        Err(_) => {
                            let mut valid: Vec<&str> = parameters::at_level(Level::Scenario).map(|p| p.name).collect();
                            if NAMED {
                                valid.insert(0, "name");
                            }
                            return map.next_value_seed(parameters::Refuse(parameters::unknown_key(&key, &valid))).map(|()| table);
                        }
                    }
                }
                if NAMED && table.name.is_none() {
                    return Err(serde::de::Error::missing_field("name"));
                }
                Ok(table)
            }
        }
        deserializer.deserialize_map(Keys::<NAMED>)
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAxis<P = Parameter> {
    parameter: Spanned<P>,
    values: Option<Spanned<Vec<Spanned<f64>>>>,
    linear: Option<Spanned<RawRange>>,
    log: Option<Spanned<RawRange>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRange {
    from: f64,
    to: f64,
    count: Spanned<i64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    mode: Option<Spanned<String>>,
    interval: Option<Spanned<f64>>,
}

/// What to record per scenario.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Output {
    /// Outcomes only; sweeps stream in chunks.
    Summary,
    /// Outcomes and time histories sampled at most `interval` seconds apart.
    History { interval: f64 },
}

/// One swept parameter and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub parameter: Parameter,
    pub values: Vec<f64>,
}

/// Where the scenarios come from.
#[derive(Debug, Clone, PartialEq)]
pub enum Scenarios {
    /// The base scenario, or every combination of the axes over it.
    Grid { base: Scenario, axes: Vec<Axis> },
    /// Named scenarios (Table 2 rows, `[[scenario]]` lists).
    Named { names: Vec<String>, scenarios: Vec<Scenario> },
    /// Random scenarios drawn on demand (`kick sweep`).
    Sampled(crate::sample::SampledSweep),
}

/// A validated experiment, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Experiment {
    pub name: String,
    pub description: String,
    /// The file as given on the command line.
    pub path: PathBuf,
    /// The file's full text (stored in every result file).
    pub text: String,
    pub solvers: Vec<SolverChoice>,
    pub scenarios: Scenarios,
    pub output: Output,
    /// The `[flight]` table: every row's kick is flown (after each solver's
    /// kick) and the flight outcomes stored beside it.
    pub flight: Option<kick_flight::FlightSpec>,
    /// The `compress` key: how the result file stores its per-row datasets.
    pub compress: crate::columns::Compression,
}

impl Scenarios {
    /// Number of scenarios.
    pub fn len(&self) -> u64 {
        match self {
            Scenarios::Grid { axes, .. } => axes.iter().map(|a| a.values.len() as u64).product(),
            Scenarios::Named { scenarios, .. } => scenarios.len() as u64,
            Scenarios::Sampled(sweep) => sweep.samples,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Scenario `index` (grid order: the last axis varies fastest).
    pub fn scenario(&self, index: u64) -> Result<Scenario, KickError> {
        match self {
            Scenarios::Grid { base, axes } => {
                let mut values = base.values();
                crate::grid::decode(axes.iter().map(|a| a.values.len()), index, |k, position| {
                    let axis = &axes[k];
                    let slot = Parameter::ALL.iter().position(|&p| p == axis.parameter).unwrap_or(0);
                    values[slot] = axis.values[position];
                });
                Scenario::from_values(values)?.with_law(base.law_kind(), base.restitution_target())
            }
            Scenarios::Named { scenarios, .. } => Ok(scenarios[index as usize]),
            Scenarios::Sampled(sweep) => sweep.scenario(index),
        }
    }

    /// True when the scenarios' law takes a target restitution (a law other
    /// than the paper's): result files then have a `restitution` column.
    pub fn has_restitution(&self) -> bool {
        match self {
            Scenarios::Grid { base, .. } => base.restitution_target().is_some(),
            Scenarios::Named { scenarios, .. } => scenarios.iter().any(|s| s.restitution_target().is_some()),
            Scenarios::Sampled(sweep) => sweep.fixed.law.is_some_and(|law| law != kick_core::LawKind::PowerLaw),
        }
    }

    /// Row names, for named scenarios.
    pub fn names(&self) -> Option<&[String]> {
        match self {
            Scenarios::Grid { .. } | Scenarios::Sampled(_) => None,
            Scenarios::Named { names, .. } => Some(names),
        }
    }
}

/// Values of a linear range: `from`, `to` and `count − 2` evenly spaced between.
pub fn linear_range(from: f64, to: f64, count: usize) -> Vec<f64> {
    match count {
        0 => Vec::new(),
        1 => vec![from],
        _ => (0..count)
            .map(|i| {
                if i + 1 == count {
                    to
                } else {
                    let t = i as f64 / (count - 1) as f64;
                    // A span beyond f64 (-1e308 .. 1e308) weighs the ends
                    // instead of overflowing to NaN; the usual form otherwise
                    // (its values are the results' to the bit).
                    if (to - from).is_finite() {
                        from + (to - from) * t
                    } else {
                        from * (1.0 - t) + to * t
                    }
                }
            })
            .collect(),
    }
}

/// Values of a log range: geometric spacing from `from` to `to` (both > 0).
pub fn log_range(from: f64, to: f64, count: usize) -> Vec<f64> {
    let (a, b) = (from.ln(), to.ln());
    linear_range(a, b, count)
        .into_iter()
        .enumerate()
        .map(|(i, x)| if i == 0 { from } else if i + 1 == count { to } else { x.exp() })
        .collect()
}

struct Locator<'a> {
    file: &'a str,
    text: &'a str,
}

impl Locator<'_> {
    fn error(&self, span: std::ops::Range<usize>, key: &str, message: impl Into<String>) -> ExperimentError {
        let start = span.start.min(self.text.len());
        let before = &self.text[..start];
        let line = before.matches('\n').count() + 1;
        let column = before.chars().rev().take_while(|&c| c != '\n').count() + 1;
        ExperimentError {
            file: self.file.to_string(),
            line,
            column,
            key: key.to_string(),
            message: message.into(),
        }
    }

    /// A toml error, with the key under its span when the span covers a bare key.
    fn toml_error(&self, error: &toml::de::Error) -> ExperimentError {
        let span = error.span().unwrap_or(0..0);
        let under = self.text.get(span.clone()).unwrap_or("").trim();
        // A bare key under the span (serde's unknown fields); a value (a
        // refused key's) names the key of its line.
        let key = if !under.is_empty()
            && under.len() < 64
            && under.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && under.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        {
            under.to_string()
        } else {
            key_before(self.text, span.start)
        };
        let message = error.message().trim();
        // A key refused while reading its value (`parameters::Refuse`): point at the key.
        let span = if message.starts_with("unknown key") {
            let at = span.start.min(self.text.len());
            let line_start = self.text[..at].rfind('\n').map_or(0, |i| i + 1);
            let indent = self.text[line_start..].len() - self.text[line_start..].trim_start().len();
            line_start + indent..span.end
        } else {
            span
        };
        self.error(span, &key, message.to_string())
    }
}

/// The key of the `key = value` line holding byte `at`, or the table header.
fn key_before(text: &str, at: usize) -> String {
    let at = at.min(text.len());
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].lines().next().unwrap_or("");
    match line.split_once('=') {
        Some((key, _)) => key.trim().to_string(),
        None => line.trim().trim_matches(|c| c == '[' || c == ']').to_string(),
    }
}

/// The experiment's name, its file's stem: refused unless UTF-8, as it
/// names the result file (a lossy or default name would write another).
fn file_stem(path: &Path) -> Result<String, ExperimentError> {
    match path.file_stem().map(|stem| stem.to_str()) {
        Some(Some(stem)) => Ok(stem.to_string()),
        Some(None) => Err(ExperimentError {
            file: path.to_string_lossy().into_owned(),
            line: 0,
            column: 0,
            key: String::new(),
            message: format!("the file name {:?} is not valid UTF-8 (it names the result file); rename it", path.to_string_lossy()),
        }),
        None => Ok("experiment".to_string()),
    }
}

/// Read and validate an experiment file.
pub fn load(path: &Path) -> Result<Experiment, ExperimentError> {
    let file = path.display().to_string();
    let text = kick_core::input::read_text(path, kick_core::input::MAX_TEXT_BYTES).map_err(|message| ExperimentError {
        file: file.clone(),
        line: 0,
        column: 0,
        key: String::new(),
        message,
    })?;
    parse(path, &text)
}

/// Validate an experiment given its text (`path` names it in errors and
/// resolves `table2 = ...`).
pub fn parse(path: &Path, text: &str) -> Result<Experiment, ExperimentError> {
    let file = path.display().to_string();
    let at = Locator { file: &file, text };
    let stem = file_stem(path)?;
    let table: toml::Table = toml::from_str(text).map_err(|e| at.toml_error(&e))?;
    if table.contains_key("row") {
        return table2_experiment(path, text, stem, &at);
    }
    let raw: RawExperiment = toml::from_str(text).map_err(|e| at.toml_error(&e))?;
    if let Some(level) = &raw.level {
        if level.get_ref() != "1d" {
            return Err(at.error(level.span(), "level", format!("`{}`: this reader takes 1D experiments (`kick run` reads both)", level.get_ref())));
        }
    }
    let name = experiment_name(&at, raw.name.as_ref(), stem)?;

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
        solvers.push(
            SolverChoice::from_name(name.get_ref(), dt)
                .map_err(|e| at.error(name.span(), "solver", e.to_string()))?,
        );
    }

    let base_raw = raw.base.unwrap_or_default();
    let law = match &raw.law {
        Some(name) => kick_core::LawKind::from_name(name.get_ref()).map_err(|e| at.error(name.span(), "law", e.to_string()))?,
        None => kick_core::LawKind::PowerLaw,
    };
    // The target restitution is a declared parameter: at the top level beside
    // `law`, or in a table ([[scenario]] over [base]), but not both.
    let top_restitution = raw.restitution.as_ref();
    let law_span = top_restitution.map(|r| r.span()).or(raw.law.as_ref().map(|l| l.span())).unwrap_or(0..0);
    let check_law = |damping, restitution| law_settings_apply(&at, law, damping, restitution);
    let with_law = |s: Scenario, table: &str, given: Option<&Spanned<f64>>, damping: Located| -> Result<Scenario, ExperimentError> {
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
        s.with_law(law, restitution).map_err(|e| at.error(span, &key, e.to_string()))
    };
    // The base scenario of a grid; named scenarios build their own over [base].
    let base_damping = || base_raw.get(Parameter::Damping).map(|d| (d.span(), "base.damping".to_string()));
    let base = || with_law(build(&at, |p| base_raw.get(p), "base")?, "base", base_raw.restitution(), base_damping());

    let sources = [raw.sweep.is_some(), raw.scenario.is_some(), raw.table2.is_some()];
    if sources.iter().filter(|&&s| s).count() > 1 {
        let span = raw.table2.as_ref().map(|t| t.span()).unwrap_or(0..0);
        return Err(at.error(span, "sweep", "give one of [[sweep]], [[scenario]] or table2"));
    }

    let scenarios = if let Some(axes_raw) = &raw.sweep {
        let base = base()?;
        let mut axes: Vec<Axis> = Vec::new();
        let mut spans = Vec::new();
        let mut total: u64 = 1;
        for axis in axes_raw {
            let parameter = *axis.parameter.get_ref();
            let key = format!("sweep.{}", parameter.name());
            if axes.iter().any(|a| a.parameter == parameter) {
                return Err(at.error(axis.parameter.span(), &key, "parameter swept twice"));
            }
            if let Some(v) = base_raw.get(parameter) {
                return Err(at.error(v.span(), &format!("base.{}", parameter.name()), "this parameter is also swept; set it in one place"));
            }
            if parameter == Parameter::Damping {
                check_law(Some((axis.parameter.span(), key.clone())), None)?;
            }
            let (values, span, value_spans) = axis_values(&at, axis, &key)?;
            total = total.saturating_mul(values.len() as u64);
            if total > MAX_SCENARIOS {
                return Err(at.error(span, &key, format!("the grid exceeds {MAX_SCENARIOS} scenarios")));
            }
            // Each value alone against the base, so the error names its line.
            for (&v, value_span) in values.iter().zip(&value_spans) {
                base.with(parameter, v).map_err(|e| at.error(value_span.clone(), &key, format!("value {}: {e}", short(v))))?;
            }
            axes.push(Axis { parameter, values });
            spans.push(span);
        }
        let grid = Scenarios::Grid { base, axes };
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
            if names.contains(entry.name().get_ref()) {
                return Err(at.error(entry.name().span(), &key, "scenario name used twice"));
            }
            let restitution = entry.restitution().or(base_raw.restitution());
            let damping = entry.get(Parameter::Damping).map(|d| (d.span(), format!("{key}.damping"))).or_else(base_damping);
            let scenario = with_law(build(&at, |p| entry.get(p).or_else(|| base_raw.get(p)), "scenario")?, "scenario", restitution, damping)?;
            names.push(entry.name().get_ref().clone());
            scenarios.push(scenario);
        }
        if scenarios.is_empty() {
            return Err(at.error(0..0, "scenario", "list at least one scenario"));
        }
        Scenarios::Named { names, scenarios }
    } else if let Some(t2) = &raw.table2 {
        let t2_path = path.parent().unwrap_or(Path::new(".")).join(t2.get_ref());
        let t2_text = kick_core::input::read_text(&t2_path, kick_core::input::MAX_TEXT_BYTES)
            .map_err(|e| at.error(t2.span(), "table2", format!("{}: {e}", t2_path.display())))?;
        let file = Table2File::parse(&t2_text)
            .map_err(|e| at.error(t2.span(), "table2", format!("{}: {e}", t2_path.display())))?;
        let rows = file
            .scenarios()
            .map_err(|e| at.error(t2.span(), "table2", format!("{}: {e}", t2_path.display())))?;
        let (names, scenarios) = rows.into_iter().unzip();
        Scenarios::Named { names, scenarios }
    } else {
        Scenarios::Grid { base: base()?, axes: Vec::new() }
    };

    let output = match &raw.output {
        None => Output::Summary,
        Some(out) => {
            let mode = out.mode.as_ref().map(|m| m.get_ref().as_str()).unwrap_or("summary");
            let mode_span = out.mode.as_ref().map(|m| m.span()).unwrap_or(0..0);
            match (mode, &out.interval) {
                ("summary", None) => Output::Summary,
                ("summary", Some(i)) => {
                    return Err(at.error(i.span(), "output.interval", "only with mode = \"history\""))
                }
                ("history", None) => {
                    return Err(at.error(mode_span, "output.interval", "mode = \"history\" needs a sampling interval (s)"))
                }
                ("history", Some(i)) => {
                    let v = *i.get_ref();
                    if !(v.is_finite() && v > 0.0) {
                        return Err(at.error(i.span(), "output.interval", format!("{} must be finite and > 0 (s)", short(v))));
                    }
                    if scenarios.len() > MAX_HISTORY_SCENARIOS {
                        return Err(at.error(mode_span, "output.mode", format!(
                            "histories of {} scenarios; at most {MAX_HISTORY_SCENARIOS} (use mode = \"summary\" for large sweeps)",
                            scenarios.len()
                        )));
                    }
                    for k in 0..scenarios.len() {
                        let horizon = scenarios.scenario(k).map(|s| s.contact_horizon()).unwrap_or(0.0);
                        // The horizon is 1000 elastic contact times; a history
                        // of a normal contact is ~1/1000 of this bound.
                        if horizon / v > MAX_HISTORY_SAMPLES * kick_core::scenario::CONTACT_HORIZON_FACTOR {
                            return Err(at.error(i.span(), "output.interval", format!(
                                "{v} s is too fine: more than {MAX_HISTORY_SAMPLES:e} samples per contact"
                            )));
                        }
                    }
                    Output::History { interval: v }
                }
                (other, _) => {
                    return Err(at.error(mode_span, "output.mode", format!("`{other}`: expected \"summary\" or \"history\"")))
                }
            }
        }
    };

    let flight = flight::parse(&at, text, raw.flight.as_ref(), flight::After::OneD)?;
    let compress = compression(&at, raw.compress.as_ref())?;
    Ok(Experiment {
        name,
        description: raw.description.unwrap_or_default(),
        path: path.to_path_buf(),
        text: text.to_string(),
        solvers,
        scenarios,
        output,
        flight,
        compress,
    })
}

/// The `compress` key: a deflate level 1..=9, `true` (the default level) or
/// `false` (plain, as without the key).
fn compression(at: &Locator, given: Option<&Spanned<toml::Value>>) -> Result<crate::columns::Compression, ExperimentError> {
    use crate::columns::Compression;
    let Some(given) = given else { return Ok(Compression::None) };
    match given.get_ref() {
        toml::Value::Boolean(false) => Ok(Compression::None),
        toml::Value::Boolean(true) => Compression::deflate(None, "compress").map_err(|e| e.to_string()),
        toml::Value::Integer(level) => Compression::deflate(Some(*level), "compress").map_err(|e| e.to_string()),
        other => Err(format!("compress = {other}: expected a deflate level 1 (fastest) to 9 (smallest), or true")),
    }
    .map_err(|message| at.error(given.span(), "compress", message))
}

/// The `name` key checked, or the file's stem.
fn experiment_name(at: &Locator, name: Option<&Spanned<String>>, stem: String) -> Result<String, ExperimentError> {
    match name {
        Some(n) => {
            let value = n.get_ref();
            if value.is_empty() || !value.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
                return Err(at.error(n.span(), "name", "must be non-empty letters, digits, `_` or `-` (it names the result file)"));
            }
            Ok(value.clone())
        }
        None => Ok(stem),
    }
}

/// An experiment of either level.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyExperiment {
    OneD(Experiment),
    ThreeD(Experiment3d),
}

/// Read and validate an experiment file of either level (see [`parse_any`]).
pub fn load_any(path: &Path) -> Result<AnyExperiment, ExperimentError> {
    let text = kick_core::input::read_text(path, kick_core::input::MAX_TEXT_BYTES).map_err(|message| ExperimentError {
        file: path.display().to_string(),
        line: 0,
        column: 0,
        key: String::new(),
        message,
    })?;
    parse_any(path, &text)
}

/// The keys that decide an experiment's level.
#[derive(Deserialize)]
struct LevelProbe {
    level: Option<Spanned<String>>,
    kick3d: Option<toml::Value>,
    sweep: Option<Vec<AxisProbe>>,
}

#[derive(Deserialize)]
struct AxisProbe {
    parameter: Option<toml::Value>,
}

/// Validate an experiment of either level. It is 3D ([`three_d`]) when it
/// says `level = "3d"`, or without a `level` key when it has a `[kick3d]`
/// table or sweeps a parameter of the 3D level; 1D ([`parse`]) otherwise.
pub fn parse_any(path: &Path, text: &str) -> Result<AnyExperiment, ExperimentError> {
    let file = path.display().to_string();
    let at = Locator { file: &file, text };
    let probe: Result<LevelProbe, _> = toml::from_str(text);
    let three_d = match probe {
        Ok(LevelProbe { level: Some(level), .. }) => match level.get_ref().as_str() {
            "1d" => false,
            "3d" => true,
            other => return Err(at.error(level.span(), "level", format!("`{other}`: expected \"1d\" or \"3d\""))),
        },
        Ok(probe) => {
            probe.kick3d.is_some()
                || probe.sweep.iter().flatten().any(|a| {
                    a.parameter.as_ref().and_then(|p| p.as_str()).and_then(parameters::find).is_some_and(|p| p.level == Level::Kick3d)
                })
        }
        // The 1D reader names the problem.
        Err(_) => false,
    };
    if three_d {
        let stem = file_stem(path)?;
        three_d::parse(path, text, &at, stem).map(AnyExperiment::ThreeD)
    } else {
        parse(path, text).map(AnyExperiment::OneD)
    }
}

/// The axis values, the span of the whole axis and the span of each value.
fn axis_values<P>(at: &Locator, axis: &RawAxis<P>, key: &str) -> Result<(Vec<f64>, Span, Vec<Span>), ExperimentError> {
    let given = [axis.values.is_some(), axis.linear.is_some(), axis.log.is_some()];
    if given.iter().filter(|&&g| g).count() != 1 {
        return Err(at.error(axis.parameter.span(), key, "give exactly one of `values`, `linear` or `log`"));
    }
    if let Some(values) = &axis.values {
        if values.get_ref().is_empty() {
            return Err(at.error(values.span(), key, "`values` is empty"));
        }
        // `inf` (TOML's infinity) passes here and is checked with the
        // parameter, which admits it only where declared (friction: never slips).
        for v in values.get_ref() {
            if v.get_ref().is_nan() {
                return Err(at.error(v.span(), key, "nan is not a value"));
            }
        }
        return Ok((
            values.get_ref().iter().map(|v| *v.get_ref()).collect(),
            values.span(),
            values.get_ref().iter().map(|v| v.span()).collect(),
        ));
    }
    let (range, is_log) = match (&axis.linear, &axis.log) {
        (Some(r), None) => (r, false),
        (None, Some(r)) => (r, true),
        _ => unreachable!("exactly one range checked above"),
    };
    let r = range.get_ref();
    let count = *r.count.get_ref();
    if !(1..=MAX_SCENARIOS as i64).contains(&count) {
        return Err(at.error(r.count.span(), &format!("{key}.count"), format!("{count} must be between 1 and {MAX_SCENARIOS}")));
    }
    if !(r.from.is_finite() && r.to.is_finite()) {
        return Err(at.error(range.span(), key, "`from` and `to` must be finite"));
    }
    if is_log && !(r.from > 0.0 && r.to > 0.0) {
        return Err(at.error(range.span(), key, format!("a log range needs from > 0 and to > 0, got {} and {}", short(r.from), short(r.to))));
    }
    let values = if is_log {
        log_range(r.from, r.to, count as usize)
    } else {
        linear_range(r.from, r.to, count as usize)
    };
    let spans = vec![range.span(); values.len()];
    Ok((values, range.span(), spans))
}

/// A key and where it is: the span of its value and its dotted name.
type Located = Option<(std::ops::Range<usize>, String)>;

/// Refuse a `damping` or `restitution` the law would ignore
/// ([`kick_core::LawKind::check_given`]), at the key that gave it.
fn law_settings_apply(at: &Locator, law: kick_core::LawKind, damping: Located, restitution: Located) -> Result<(), ExperimentError> {
    law.check_given(damping.is_some(), restitution.is_some()).map_err(|e| {
        let (span, key) = match &e {
            KickError::DoesNotApply { given: "damping", .. } => damping,
            _ => restitution,
        }
        .unwrap_or_default();
        at.error(span, &key, e.to_string())
    })
}

/// Build a scenario from optional spanned values, naming the key of the first
/// invalid one.
fn build<'a>(
    at: &Locator,
    get: impl Fn(Parameter) -> Option<&'a Spanned<f64>>,
    table: &str,
) -> Result<Scenario, ExperimentError> {
    let mut values = Scenario::BASELINE.values();
    for (slot, p) in values.iter_mut().zip(Parameter::ALL) {
        if let Some(v) = get(p) {
            *slot = *v.get_ref();
        }
    }
    Scenario::from_values(values).map_err(|e| {
        let blamed = match &e {
            KickError::InvalidParameter { name, .. } => Parameter::from_name(name),
            KickError::NoContact { .. } => Some(if get(Parameter::BallSpeed).is_some() {
                Parameter::BallSpeed
            } else {
                Parameter::FootSpeed
            }),
            _ => None,
        };
        let span = blamed.and_then(&get).map(|v| v.span()).unwrap_or(0..0);
        let key = blamed.map(|p| format!("{table}.{}", p.name())).unwrap_or_else(|| table.to_string());
        at.error(span, &key, e.to_string())
    })
}

fn table2_experiment(path: &Path, text: &str, name: String, at: &Locator) -> Result<Experiment, ExperimentError> {
    let file = Table2File::parse(text).map_err(|e| at.error(0..0, "row", e))?;
    let rows = file.scenarios().map_err(|e| at.error(0..0, "row", e.to_string()))?;
    // The file's own solver (the paper's method) first, then the accurate reference.
    let mut solvers = vec![SolverChoice::from_name(&file.solver, file.dt)
        .map_err(|e| at.error(0..0, "solver", e.to_string()))?];
    if file.solver != "accurate" {
        solvers.push(SolverChoice::from_name("accurate", file.dt).map_err(|e| at.error(0..0, "solver", e.to_string()))?);
    }
    let (names, scenarios) = rows.into_iter().unzip();
    Ok(Experiment {
        name: if file.name.is_empty() { name } else { file.name.clone() },
        description: file.description.clone(),
        path: path.to_path_buf(),
        text: text.to_string(),
        solvers,
        scenarios: Scenarios::Named { names, scenarios },
        output: Output::Summary,
        flight: None,
        compress: crate::columns::Compression::None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_text(text: &str) -> Result<Experiment, ExperimentError> {
        parse(Path::new("x.toml"), text)
    }

    /// A file name that is not UTF-8 is refused naming it (lossy), 1D and
    /// 3D: it used to write `experiment.h5`.
    #[cfg(unix)]
    #[test]
    fn a_non_utf8_file_name_is_refused_naming_it() {
        use std::os::unix::ffi::OsStrExt;
        let path = Path::new(std::ffi::OsStr::from_bytes(b"dir/bad\xff.toml"));
        for text in ["[base]\nfoot_speed = 20.0\n", "[kick3d]\noffset = 0.01\n"] {
            let error = parse_any(path, text).err().expect("refused");
            assert!(error.to_string().contains("bad\u{FFFD}.toml") && error.to_string().contains("UTF-8"), "{error}");
        }
    }

    /// A linear range spanning more than f64 holds (-1e308 .. 1e308) gives
    /// its ends and evenly spaced finite values, not NaN.
    #[test]
    fn a_linear_range_beyond_the_largest_span_stays_finite() {
        assert_eq!(linear_range(-1e308, 1e308, 3), [-1e308, 0.0, 1e308]);
        let values = linear_range(-1e308, 1e308, 5);
        for (x, expected) in values.iter().zip([-1e308, -5e307, 0.0, 5e307, 1e308]) {
            assert!((x - expected).abs() <= 1e-15 * 1e308, "{values:?}");
        }
        assert_eq!(linear_range(1.0, 2.0, 5), [1.0, 1.25, 1.5, 1.75, 2.0]);
    }

    /// Every declared 1D parameter is a key of `[base]` and of
    /// `[[scenario]]`, and the value reaches the scenario.
    #[test]
    fn every_declared_1d_parameter_is_a_toml_key() {
        for p in parameters::at_level(Level::Scenario) {
            // A value inside the valid range other than the default.
            let value = p.sample.map_or(0.5, |s| 0.5 * (s.from + s.to)).max(0.25);
            let law = if p.name == "restitution" { "law = \"flores\"\n" } else { "" };
            for table in ["[base]", "[[scenario]]\nname = \"a\""] {
                let text = format!("{law}{table}\n{} = {value:?}\n", p.name);
                let experiment = parse_text(&text).unwrap_or_else(|e| panic!("{}: {e}", p.name));
                let scenario = experiment.scenarios.scenario(0).unwrap();
                let got = match Parameter::from_name(p.name) {
                    Some(q) => scenario.get(q),
                    None => scenario.restitution_target().unwrap(),
                };
                assert_eq!(got, value, "{} in {table}", p.name);
            }
        }
    }

    #[test]
    fn unknown_keys_name_their_line_and_the_nearby_keys() {
        let e = parse_text("[base]\nfoot_mass = 3\nstifness = 4\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (3, "stifness"), "{e}");
        assert!(e.message.ends_with("unknown key `stifness`: did you mean `stiffness`?"), "{e}");
        let e = parse_text("[[scenario]]\nname = \"a\"\nspeed = 3\n").unwrap_err();
        assert!(e.message.contains("did you mean one of `foot_speed`, `ball_speed`?"), "{e}");
        let e = parse_text("[[scenario]]\nfoot_mass = 3\n").unwrap_err();
        assert!(e.message.contains("name"), "{e}");
        let e = parse_text("restitution = 0.5\nlaw = \"flores\"\n[base]\nrestitution = 0.6\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (4, "base.restitution"), "{e}");
    }

    /// Inputs that are not experiment or scenario files: refused at once
    /// (no read until memory runs out, no wait on a FIFO), naming the key,
    /// and no line of the file quoted (issue 21).
    #[cfg(unix)]
    #[test]
    fn inputs_are_bounded_and_their_contents_not_quoted() {
        let e = parse_text("table2 = \"/dev/zero\"\n").unwrap_err();
        assert!(e.key == "table2" && e.message.contains("not a regular file"), "{e}");
        let e = load_any(Path::new("/dev/zero")).unwrap_err();
        assert!(e.message.contains("not a regular file"), "{e}");
        let secret = std::env::temp_dir().join(format!("kick-secret-{}.txt", std::process::id()));
        std::fs::write(&secret, "root:x:0:0:root:/root:/bin/bash\n").unwrap();
        let e = parse_text(&format!("table2 = {:?}\n", secret.to_str().unwrap())).unwrap_err();
        assert!(e.key == "table2" && e.message.contains("line 1") && !e.to_string().contains("root:x"), "{e}");
        let _ = std::fs::remove_file(&secret);
        let big = std::env::temp_dir().join(format!("kick-big-{}.toml", std::process::id()));
        std::fs::File::create(&big).unwrap().set_len(kick_core::input::MAX_TEXT_BYTES + 1).unwrap();
        let e = load(&big).unwrap_err();
        assert!(e.message.contains("more than the 16777216 bytes"), "{e}");
        let _ = std::fs::remove_file(&big);
    }
}
