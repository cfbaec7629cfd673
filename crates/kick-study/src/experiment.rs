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
//! One schema for both levels: [`parse`] reads the keys every level shares
//! (`name`, `description`, `law`, `restitution`, `[base]`, `[flight]`,
//! `compress`) once into one [`Experiment`], and the level's own keys into its
//! [`Kicks`]: 1D solvers and [`Scenarios`], or a 3D kick and its [`Grid`]
//! ([`three_d`] says which files are 3D). Both grids are one [`Grid`] type.
//! A file with `level = "bounce"` is the ball alone on the plate
//! ([`bounce`]: `kick bounce`'s parameters in `[base]` and `[[sweep]]`, the
//! same `Grid`).
//!
//! Every problem is reported with the file, line, column and key.

use kick_compliant::SolverChoice;
use kick_core::parameters::{self, Level, ParameterDef};
use kick_core::{short, KickError, Parameter, Scenario};
use serde::de::IgnoredAny;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

pub mod bounce;
mod flight;
mod one_d;
pub mod three_d;
pub use crate::grid::{Axis, Grid};
pub use bounce::{KicksBounce, MAX_CELLS_BOUNCE};
pub use three_d::{Kicks3d, MAX_CELLS_3D};

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

pub use crate::limits::MAX_SCENARIOS;
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

/// Every key of an experiment file, of either level; which keys a level
/// takes is [`Keys1d`]'s and [`Keys3d`]'s.
#[derive(Debug, Deserialize)]
struct RawExperiment {
    /// "1d", "3d" or "bounce": decided by [`file_level`], here for its type's error.
    #[allow(dead_code)]
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
    /// The 3D kick's own parameters (3D only).
    kick3d: Option<kick_3d::Kick3dSpec>,
    /// Flight outcomes on every row ([`flight`]).
    flight: Option<Spanned<toml::Table>>,
    /// Store the per-row datasets compressed ([`compression`]).
    compress: Option<Spanned<toml::Value>>,
}

/// The keys of a 1D experiment, in the order an unknown key's message lists them.
#[allow(dead_code)]
#[derive(Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct Keys1d {
    level: IgnoredAny,
    name: IgnoredAny,
    description: IgnoredAny,
    solver: IgnoredAny,
    solvers: IgnoredAny,
    dt: IgnoredAny,
    base: IgnoredAny,
    sweep: IgnoredAny,
    scenario: IgnoredAny,
    table2: IgnoredAny,
    output: IgnoredAny,
    law: IgnoredAny,
    restitution: IgnoredAny,
    flight: IgnoredAny,
    compress: IgnoredAny,
}

/// The keys of a 3D experiment, as [`Keys1d`].
#[allow(dead_code)]
#[derive(Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct Keys3d {
    level: IgnoredAny,
    name: IgnoredAny,
    description: IgnoredAny,
    solver: IgnoredAny,
    law: IgnoredAny,
    restitution: IgnoredAny,
    base: IgnoredAny,
    kick3d: IgnoredAny,
    sweep: IgnoredAny,
    flight: IgnoredAny,
    compress: IgnoredAny,
}

/// A `[base]` or `[[scenario]]` table: values of declared parameters
/// (`kick_core::parameters`, and kick-flight's), with their spans; a
/// `[[scenario]]` table also has its `name`. Any other key is refused at its
/// line with the nearby names; which keys a table of a level takes is the
/// level's to check ([`RawSpec::outside`]).
#[derive(Debug, Default)]
struct RawSpec<const NAMED: bool> {
    name: Option<Spanned<String>>,
    /// Numbers.
    values: Vec<(&'static ParameterDef, Spanned<f64>)>,
    /// Three numbers or a switch (parameters of the 3D kick).
    others: Vec<(&'static ParameterDef, Spanned<toml::Value>)>,
}

/// The keys of `[[scenario]]`, and of a 1D `[base]` beside the flight's:
/// the 1D scenario's, the shell ball's (which apply under `law = "shell"`)
/// and the foot's (the leg and the boot, `kick_core::Foot`).
const TABLE_LEVELS: &[Level] = &[Level::Scenario, Level::Bounce, Level::Foot];

/// The declared parameter a table key names: one of kick-core's list (the
/// kick's), else the flight's.
fn table_parameter(name: &str) -> Option<&'static ParameterDef> {
    parameters::find(name).or_else(|| kick_flight::FlightParameter::from_name(name).ok().map(|p| p.def()))
}

type RawBase = RawSpec<false>;
type RawNamed = RawSpec<true>;

impl<const NAMED: bool> RawSpec<NAMED> {
    fn value(&self, parameter: &ParameterDef) -> Option<&Spanned<f64>> {
        self.values.iter().find(|(p, _)| p.name == parameter.name && p.level == parameter.level).map(|(_, v)| v)
    }
    /// Every key given, with its declaration, value and span.
    fn given(&self) -> impl Iterator<Item = (&'static ParameterDef, kick_core::parameters::Value, Span)> + '_ {
        use kick_core::parameters::Value;
        let numbers = self.values.iter().map(|(p, v)| (*p, Value::Number(*v.get_ref()), v.span()));
        let others = self.others.iter().filter_map(|(p, v)| {
            let value = match v.get_ref() {
                toml::Value::Boolean(on) => Value::Switch(*on),
                toml::Value::Array(xs) => {
                    let xs: Vec<f64> = xs.iter().map(|x| x.as_float().or(x.as_integer().map(|i| i as f64))).collect::<Option<_>>()?;
                    Value::Vector(xs.try_into().ok()?)
                }
                _ => return None,
            };
            Some((*p, value, v.span()))
        });
        numbers.chain(others)
    }
    /// The first key not of `levels` (nor, with `flight`, a flight parameter).
    fn outside(&self, levels: &[Level], flight: bool) -> Option<(&'static ParameterDef, Span)> {
        self.given().find(|(p, _, _)| !(levels.contains(&p.level) || (flight && p.level == Level::Flight))).map(|(p, _, span)| (p, span))
    }
    fn get(&self, p: Parameter) -> Option<&Spanned<f64>> {
        self.value(p.def())
    }
    fn restitution(&self) -> Option<&Spanned<f64>> {
        self.value(&parameters::RESTITUTION)
    }
    fn switch(&self, parameter: &ParameterDef) -> Option<Spanned<bool>> {
        self.others.iter().find(|(p, _)| p.name == parameter.name).and_then(|(_, v)| match v.get_ref() {
            toml::Value::Boolean(on) => Some(Spanned::new(v.span(), *on)),
            _ => None,
        })
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
                    let found = if NAMED { parameters::find_at(TABLE_LEVELS, &key).ok() } else { table_parameter(&key) };
                    match found {
                        Some(parameter) => {
                            if table.given().any(|(p, _, _)| p.name == parameter.name) {
                                return Err(serde::de::Error::custom(format!("duplicate key `{key}`")));
                            }
                            match parameter.shape {
                                kick_core::parameters::Shape::Scalar => table.values.push((parameter, map.next_value()?)),
                                shape => {
                                    let value: Spanned<toml::Value> = map.next_value()?;
                                    let fits = match (shape, value.get_ref()) {
                                        (kick_core::parameters::Shape::Switch, toml::Value::Boolean(_)) => true,
                                        (kick_core::parameters::Shape::Vector3, toml::Value::Array(xs)) => {
                                            xs.len() == 3 && xs.iter().all(|x| x.is_float() || x.is_integer())
                                        }
                                        _ => false,
                                    };
                                    if !fits {
                                        return Err(serde::de::Error::custom(format!("`{key}` takes {}", shape.describe())));
                                    }
                                    table.others.push((parameter, value));
                                }
                            }
                        }
                        None => {
                            let mut valid: Vec<&str> = parameters::at_levels(TABLE_LEVELS).map(|p| p.name).collect();
                            if NAMED {
                                valid.insert(0, "name");
                            } else {
                                let kick_3d = parameters::at_levels(&[Level::Kick3d, Level::Instep]).map(|p| p.name);
                                valid.extend(kick_3d.chain(kick_flight::FLIGHT_PARAMETERS.iter().map(|p| p.name)));
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
struct RawAxis {
    parameter: Spanned<String>,
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

/// Where the scenarios come from.
#[derive(Debug, Clone, PartialEq)]
pub enum Scenarios {
    /// The base scenario, or every cell of the grid (of 1D parameters) over it.
    Grid { base: Scenario, grid: Grid },
    /// Named scenarios (Table 2 rows, `[[scenario]]` lists).
    Named { names: Vec<String>, scenarios: Vec<Scenario> },
    /// Random scenarios drawn on demand (`kick sweep`).
    Sampled(crate::sample::SampledSweep),
}

/// A validated experiment of either level, ready to run: what every level
/// shares, and the level's own part ([`Kicks`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Experiment {
    pub name: String,
    pub description: String,
    /// The file as given on the command line.
    pub path: PathBuf,
    /// Every file read to make it: the file itself and a Table 2 file it
    /// names (`table2 = ...`); none for a `kick sweep`. A command writing
    /// its results checks them against these (kick-store's `check_paths`).
    pub read: Vec<PathBuf>,
    /// The file's full text (stored in every result file).
    pub text: String,
    /// What to record per row (1D histories; a 3D experiment's is [`Output::Summary`]).
    pub output: Output,
    /// The `[flight]` table: every row's kick is flown (after each solver's
    /// kick) and the flight outcomes stored beside it.
    pub flight: Option<crate::flight::FlightPlan>,
    /// The `compress` key: how the result file stores its per-row datasets.
    pub compress: crate::columns::Compression,
    /// The level's kicks.
    pub kicks: Kicks,
}

/// The kicks of an experiment, by level.
#[derive(Debug, Clone, PartialEq)]
pub enum Kicks {
    /// 1D scenarios, each solved by every solver.
    OneD(Kicks1d),
    /// A grid of 3D kicks ([`three_d`]).
    ThreeD(Kicks3d),
    /// A grid of bounces of the ball alone on the plate ([`bounce`]).
    Bounce(KicksBounce),
}

/// The 1D part of an experiment.
#[derive(Debug, Clone, PartialEq)]
pub struct Kicks1d {
    pub solvers: Vec<SolverChoice>,
    pub scenarios: Scenarios,
}

impl Experiment {
    /// The 1D part, when the experiment is 1D.
    pub fn one_d(&self) -> Option<&Kicks1d> {
        match &self.kicks {
            Kicks::OneD(k) => Some(k),
            _ => None,
        }
    }

    /// The 3D part, when the experiment is 3D.
    pub fn three_d(&self) -> Option<&Kicks3d> {
        match &self.kicks {
            Kicks::ThreeD(k) => Some(k),
            _ => None,
        }
    }

    /// The bounce part, when the experiment is the ball alone.
    pub fn bounce(&self) -> Option<&KicksBounce> {
        match &self.kicks {
            Kicks::Bounce(k) => Some(k),
            _ => None,
        }
    }
}

impl Scenarios {
    /// Number of scenarios.
    pub fn len(&self) -> u64 {
        match self {
            Scenarios::Grid { grid, .. } => grid.len(),
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
            Scenarios::Grid { base, grid } => {
                let mut values = base.values();
                // The eight `Parameter`s at once; the others (the target
                // restitution, the ball's) after them; the flight's are the flight's.
                let mut others = false;
                grid.decode(index, |_, axis, value| match Parameter::ALL.iter().position(|p| p.name() == axis.parameter.name) {
                    Some(slot) if axis.parameter.level == Level::Scenario => values[slot] = value,
                    _ => others |= axis.parameter.level != Level::Flight,
                });
                let scenario = base.with_values(values)?;
                if !others {
                    return Ok(scenario);
                }
                let mut result = Ok(scenario);
                grid.decode(index, |_, axis, value| {
                    let theirs = axis.parameter.level == Level::Flight || Parameter::from_name(axis.parameter.name).is_some();
                    if let (Ok(s), false) = (&result, theirs) {
                        result = s.with_parameter(axis.parameter, value);
                    }
                });
                result
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
        .map(|(i, x)| {
            if i == 0 {
                from
            } else if i + 1 == count {
                to
            } else {
                x.exp()
            }
        })
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
        ExperimentError { file: self.file.to_string(), line, column, key: key.to_string(), message: message.into() }
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

/// Read and validate an experiment file of either level (see [`parse`]).
pub fn load(path: &Path) -> Result<Experiment, ExperimentError> {
    let text = kick_core::input::read_text(path, kick_core::input::MAX_TEXT_BYTES).map_err(|e| ExperimentError {
        file: path.display().to_string(),
        line: 0,
        column: 0,
        key: String::new(),
        message: e.to_string(),
    })?;
    parse(path, &text)
}

/// The keys that decide an experiment's level.
#[derive(Deserialize)]
struct LevelProbe {
    level: Option<Spanned<String>>,
    kick3d: Option<toml::Value>,
    base: Option<toml::Table>,
    sweep: Option<Vec<AxisProbe>>,
}

#[derive(Deserialize)]
struct AxisProbe {
    parameter: Option<toml::Value>,
}

/// The level a file is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum FileLevel {
    OneD,
    ThreeD,
    Bounce,
}

/// The file's level: what it says in `level` ("1d", "3d", "bounce"), or
/// without a `level` key 3D when it has a `[kick3d]` table or sweeps a
/// parameter of the 3D level, else 1D.
fn file_level(at: &Locator, text: &str) -> Result<FileLevel, ExperimentError> {
    match toml::from_str::<LevelProbe>(text) {
        Ok(LevelProbe { level: Some(level), .. }) => match level.get_ref().as_str() {
            "1d" => Ok(FileLevel::OneD),
            "3d" => Ok(FileLevel::ThreeD),
            "bounce" => Ok(FileLevel::Bounce),
            other => Err(at.error(level.span(), "level", format!("`{other}`: expected \"1d\", \"3d\" or \"bounce\""))),
        },
        Ok(probe) => {
            let three_d = |name: &str| parameters::find(name).is_some_and(|p| matches!(p.level, Level::Kick3d | Level::Instep));
            Ok(
                if probe.kick3d.is_some()
                    || probe.base.iter().flat_map(|b| b.keys()).any(|k| three_d(k))
                    || probe.sweep.iter().flatten().any(|a| a.parameter.as_ref().and_then(|p| p.as_str()).is_some_and(three_d))
                {
                    FileLevel::ThreeD
                } else {
                    FileLevel::OneD
                },
            )
        }
        // The 1D reader names the problem.
        Err(_) => Ok(FileLevel::OneD),
    }
}

/// Validate an experiment of either level given its text (`path` names it
/// in errors and resolves `table2 = ...`): the shared keys here, the level's
/// own in `one_d` or [`three_d`].
pub fn parse(path: &Path, text: &str) -> Result<Experiment, ExperimentError> {
    let file = path.display().to_string();
    let at = Locator { file: &file, text };
    let level = file_level(&at, text)?;
    let three_d = level == FileLevel::ThreeD;
    let stem = file_stem(path)?;
    if level == FileLevel::Bounce {
        let (name, description, compress, kicks) = bounce::parse(&at, text, stem)?;
        return Ok(Experiment {
            name,
            description,
            path: path.to_path_buf(),
            read: vec![path.to_path_buf()],
            text: text.to_string(),
            output: Output::Summary,
            flight: None,
            compress: compression(&at, compress.as_ref())?,
            kicks: Kicks::Bounce(kicks),
        });
    }
    let table: toml::Table = toml::from_str(text).map_err(|e| at.toml_error(&e))?;
    if !three_d && table.contains_key("row") {
        return one_d::table2_experiment(path, text, stem, &at);
    }
    // The level's keys, then their values.
    let keys = if three_d { toml::from_str::<Keys3d>(text).map(drop) } else { toml::from_str::<Keys1d>(text).map(drop) };
    keys.map_err(|e| at.toml_error(&e))?;
    let raw: RawExperiment = toml::from_str(text).map_err(|e| at.toml_error(&e))?;
    let after = if three_d { flight::After::ThreeD } else { flight::After::OneD };
    let flight = flight::parse(&at, text, raw.flight.as_ref(), after)?;
    let flight = flight::with_base(&at, text, flight, raw.base.as_ref(), after)?;
    let swept_1d = if three_d { Vec::new() } else { one_d::axes(&at, &raw, flight.as_ref())? };
    let name = experiment_name(&at, raw.name.as_ref(), stem)?;
    let (kicks, output) = if three_d {
        (Kicks::ThreeD(three_d::kicks(&at, text, &raw, flight.as_ref())?), Output::Summary)
    } else {
        let (kicks, output) = one_d::kicks(&at, path, &raw, &swept_1d, flight.as_ref())?;
        (Kicks::OneD(kicks), output)
    };
    let compress = compression(&at, raw.compress.as_ref())?;
    let read = std::iter::once(path.to_path_buf()).chain(raw.table2.as_ref().map(|t2| one_d::table2_path(path, t2.get_ref()))).collect();
    Ok(Experiment {
        name,
        description: raw.description.unwrap_or_default(),
        path: path.to_path_buf(),
        read,
        text: text.to_string(),
        output,
        flight,
        compress,
        kicks,
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
        // A float in short form (toml prints 1e-300 with every zero).
        toml::Value::Float(x) => Err(format!("compress = {}: expected a deflate level 1 (fastest) to 9 (smallest), or true", short(*x))),
        other => Err(format!("compress = {}: expected a deflate level 1 (fastest) to 9 (smallest), or true", other.type_str())),
    }
    .map_err(|message| at.error(given.span(), "compress", message))
}

/// The `law` key (default: the paper's power law).
fn contact_law(at: &Locator, raw: &RawExperiment) -> Result<kick_core::LawKind, ExperimentError> {
    match &raw.law {
        Some(name) => kick_core::LawKind::from_name(name.get_ref()).map_err(|e| at.error(name.span(), "law", e.to_string())),
        None => Ok(kick_core::LawKind::PowerLaw),
    }
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

/// Where each value of an axis stands in its file: its own span in a
/// `values` list, the range's for every value of `linear` or `log` (one
/// span, not one per value: a 1e8-value range held 1.6 GB of copies).
enum ValueSpans {
    Each(Vec<Span>),
    All(Span),
}

impl ValueSpans {
    /// The span of value `i`.
    fn at(&self, i: usize) -> Span {
        match self {
            ValueSpans::Each(spans) => spans[i].clone(),
            ValueSpans::All(span) => span.clone(),
        }
    }
}

/// The axis values, the span of the whole axis and the span of each value.
fn axis_values(at: &Locator, axis: &RawAxis, key: &str) -> Result<(Vec<f64>, Span, ValueSpans), ExperimentError> {
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
            ValueSpans::Each(values.get_ref().iter().map(|v| v.span()).collect()),
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
        return Err(at.error(
            range.span(),
            key,
            format!("a log range needs from > 0 and to > 0, got {} and {}", short(r.from), short(r.to)),
        ));
    }
    let values = if is_log { log_range(r.from, r.to, count as usize) } else { linear_range(r.from, r.to, count as usize) };
    Ok((values, range.span(), ValueSpans::All(range.span())))
}

/// A key and where it is: the span of its value and its dotted name.
type Located = Option<(std::ops::Range<usize>, String)>;

/// Refuse a `damping` or `restitution` the law would ignore
/// ([`kick_core::LawKind::check_given`]), at the key that gave it.
/// The shell ball of a table (each key from the table, else `[base]`;
/// `get` gives the value and its key): under law `shell` the ball it gives
/// (declared defaults for the rest), under another law `None`, and a key
/// given there is refused at its line.
fn shell_ball<'a>(
    at: &Locator,
    law: kick_core::LawKind,
    get: impl Fn(&'static ParameterDef) -> Option<(&'a Spanned<f64>, String)>,
) -> Result<Option<kick_core::ShellBall>, ExperimentError> {
    use kick_core::parameters::{SetParameter, Value};
    let mut spec = kick_core::ScenarioSpec { law: Some(law), ..Default::default() };
    let mut first: Located = None;
    for p in &kick_core::shell::BALL_PARAMETERS {
        if let Some((v, key)) = get(p) {
            spec.set_parameter(p, Value::Number(*v.get_ref())).map_err(|e| at.error(v.span(), &key, e.to_string()))?;
            first.get_or_insert((v.span(), key));
        }
    }
    if law != kick_core::LawKind::Shell {
        return match (first, spec.check_given()) {
            (Some((span, key)), Err(e)) => Err(at.error(span, &key, e.to_string())),
            _ => Ok(None),
        };
    }
    spec.shell_ball().map(Some).map_err(|e| {
        let (span, key) = first.unwrap_or((0..0, "law".into()));
        at.error(span, &key, e.to_string())
    })
}

/// The foot of a table ([`kick_core::Foot`]: `leg`, its pose, the boot;
/// each key from the table, else `[base]`, as `get` and `switch` give them
/// with their keys) applied to `scenario` (a leg's mass set, Eq. 11); a
/// setting that would be ignored (`foot_mass` with `leg`, a pose without
/// it, `boot_damping` without a boot) is refused at its line.
fn on_foot<'a>(
    at: &Locator,
    scenario: Scenario,
    get: impl Fn(&'static ParameterDef) -> Option<(&'a Spanned<f64>, String)>,
    switch: impl Fn(&'static ParameterDef) -> Option<(Spanned<bool>, String)>,
) -> Result<Scenario, ExperimentError> {
    use kick_core::parameters::{SetParameter, Value};
    let mut spec = kick_core::ScenarioSpec::default();
    let mut keys: Vec<(&'static str, std::ops::Range<usize>, String)> = Vec::new();
    if let Some((v, key)) = switch(&parameters::LEG) {
        spec.leg = Some(*v.get_ref());
        keys.push((parameters::LEG.name, v.span(), key));
    }
    for p in parameters::at_level(Level::Foot).filter(|p| p.shape == parameters::Shape::Scalar) {
        if let Some((v, key)) = get(p) {
            spec.set_parameter(p, Value::Number(*v.get_ref())).map_err(|e| at.error(v.span(), &key, e.to_string()))?;
            keys.push((p.name, v.span(), key));
        }
    }
    if let (Some(true), Some((v, key))) = (spec.leg, get(Parameter::FootMass.def())) {
        spec.foot_mass = Some(*v.get_ref());
        let e = spec.check_given().err().map(|e| e.to_string()).unwrap_or_default();
        return Err(at.error(v.span(), &key, e));
    }
    let blame = |e: KickError| {
        let named = match &e {
            KickError::DoesNotApply { given, .. } => Some(*given),
            KickError::InvalidParameter { name, .. } => Some(*name),
            _ => None,
        };
        let (span, key) = keys
            .iter()
            .find(|(name, _, _)| Some(*name) == named)
            .or(keys.first())
            .map(|(_, span, key)| (span.clone(), key.clone()))
            .unwrap_or((0..0, "leg".into()));
        at.error(span, &key, e.to_string())
    };
    let foot = spec.foot().map_err(blame)?;
    scenario.on_foot(foot).map_err(blame)
}

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
/// invalid one; `one_line`: the 1D contact's approach along one line checked
/// too, not for a 3D kick's base (`Scenario::each_parameter`: kick-3d checks
/// it along the contact normal).
fn build<'a>(
    at: &Locator,
    get: impl Fn(Parameter) -> Option<&'a Spanned<f64>>,
    table: &str,
    one_line: bool,
) -> Result<Scenario, ExperimentError> {
    let mut values = Scenario::BASELINE.values();
    for (slot, p) in values.iter_mut().zip(Parameter::ALL) {
        if let Some(v) = get(p) {
            *slot = *v.get_ref();
        }
    }
    let built = if one_line { Scenario::from_values(values) } else { Scenario::each_parameter(values) };
    built.map_err(|e| {
        let blamed = match &e {
            KickError::InvalidParameter { name, .. } => Parameter::from_name(name),
            KickError::NoContact { .. } => {
                Some(if get(Parameter::BallSpeed).is_some() { Parameter::BallSpeed } else { Parameter::FootSpeed })
            }
            _ => None,
        };
        let span = blamed.and_then(&get).map(|v| v.span()).unwrap_or(0..0);
        let key = blamed.map(|p| format!("{table}.{}", p.name())).unwrap_or_else(|| table.to_string());
        at.error(span, &key, e.to_string())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_text(text: &str) -> Result<Experiment, ExperimentError> {
        parse(Path::new("x.toml"), text)
    }

    /// Fault 13 of issue 33 and its kind: a number a file gives, however
    /// extreme, is quoted in every message in short form (kick-core's
    /// `short`), never as the 300-digit decimal `{}` prints for 1e-300.
    /// Every numeric key of either level, the flight's and the grid's.
    #[test]
    fn extreme_numbers_are_quoted_short_in_every_message() {
        let longest_digits = |m: &str| m.split(|c: char| !c.is_ascii_digit()).map(str::len).max().unwrap_or(0);
        let scalars = |level| parameters::PARAMETERS.iter().filter(move |p| p.level == level && p.shape == parameters::Shape::Scalar);
        let mut files: Vec<String> = vec![
            "dt = {v}\nsolver = \"seed-rk4\"\n".into(),
            "law = \"hunt-crossley\"\nrestitution = {v}\n".into(),
            "compress = {v}\n".into(),
            "[output]\nmode = \"history\"\ninterval = {v}\n".into(),
            "[[sweep]]\nparameter = \"stiffness\"\nlog = { from = {v}, to = 1e6, count = 3 }\n".into(),
            "[[sweep]]\nparameter = \"foot_mass\"\nvalues = [{v}]\n".into(),
            "[[sweep]]\nparameter = \"offset\"\nlinear = { from = 0.0, to = {v}, count = 2 }\n".into(),
        ];
        files.extend(scalars(Level::Scenario).map(|p| format!("[base]\n{} = {{v}}\n", p.name)));
        files.extend(
            scalars(Level::Kick3d).chain(scalars(Level::Instep)).map(|p| format!("level = \"3d\"\n[kick3d]\n{} = {{v}}\n", p.name)),
        );
        files.extend(
            kick_flight::FLIGHT_PARAMETERS
                .iter()
                .filter(|p| p.shape == parameters::Shape::Scalar)
                .map(|p| format!("[flight]\n{} = {{v}}\n", p.name)),
        );
        let mut refused = 0;
        for template in &files {
            for v in ["1e-300", "-1e-300", "1e300", "-1e300", "4.9e-324"] {
                let text = template.replace("{v}", v);
                if let Err(e) = parse_text(&text) {
                    refused += 1;
                    let message = e.to_string();
                    assert!(longest_digits(&message) <= 17, "{text}: {message}");
                }
            }
        }
        assert!(refused > files.len(), "the extremes must be refused somewhere: {refused}");
        let e = parse_text("[output]\nmode = \"history\"\ninterval = 1e-300\n").unwrap_err();
        assert!(e.message.contains("1e-300 s is too fine"), "{e}");
    }

    /// A file name that is not UTF-8 is refused naming it (lossy), 1D and
    /// 3D: it used to write `experiment.h5`.
    #[cfg(unix)]
    #[test]
    fn a_non_utf8_file_name_is_refused_naming_it() {
        use std::os::unix::ffi::OsStrExt;
        let path = Path::new(std::ffi::OsStr::from_bytes(b"dir/bad\xff.toml"));
        for text in ["[base]\nfoot_speed = 20.0\n", "[kick3d]\noffset = 0.01\n"] {
            let error = parse(path, text).expect_err("refused");
            assert!(error.to_string().contains("bad\u{FFFD}.toml") && error.to_string().contains("UTF-8"), "{error}");
        }
    }

    /// One `parse` for both levels: the keys every level shares land in the
    /// same fields, the level's own in its `kicks`, and a sweep of the same
    /// 1D axes is the same `Grid` in a 1D and a 3D experiment.
    /// A 3D file whose ball is faster along the foot's line than the foot
    /// still makes its kicks: they close along the contact normal (a 23 m/s
    /// ball and a 22 m/s foot rising at 80°, at 18 m/s), in the base and in
    /// every cell of a grid over the ball's speed, under a restitution law
    /// too; the 1D file of the same base is refused as no contact.
    #[test]
    fn a_3d_file_meets_a_faster_ball_along_the_normal() {
        let text = "law = \"flores\"\nrestitution = 0.6\n[base]\nball_speed = 23.0\n[kick3d]\napproach_angle = 80.0\n\
                    [[sweep]]\nparameter = \"ball_speed\"\nvalues = [21.0, 23.0]\n";
        let three = parse_text(&format!("level = \"3d\"\n{}", text.replace("[base]\nball_speed = 23.0\n", ""))).unwrap();
        let kicks = three.three_d().unwrap();
        for (i, v_b) in [21.0, 23.0f64].into_iter().enumerate() {
            let kick = kicks.kick(i as u64).unwrap();
            let closing = 22.0 - v_b * 80f64.to_radians().cos();
            assert!((kick.normal_approach_speed() / closing - 1.0).abs() < 1e-12, "{v_b}: {}", kick.normal_approach_speed());
        }
        let base = parse_text(&format!("level = \"3d\"\n{}", text.split("[[sweep]]").next().unwrap())).unwrap();
        assert!(base.three_d().unwrap().kick(0).is_ok());
        let e = parse_text(text.split("[kick3d]").next().unwrap()).unwrap_err();
        assert!(e.message.contains("no contact"), "{e}");
    }

    #[test]
    fn both_levels_share_one_schema_and_one_grid() {
        let shared = "name = \"both\"\ndescription = \"one schema\"\ncompress = 6\nlaw = \"flores\"\nrestitution = 0.5\n\
                      [base]\nfoot_mass = 1.5\n\
                      [[sweep]]\nparameter = \"stiffness\"\nvalues = [1e5, 1e6]\n\
                      [[sweep]]\nparameter = \"foot_speed\"\nlinear = { from = 10.0, to = 20.0, count = 3 }\n";
        let one = parse(Path::new("a.toml"), &format!("{shared}[flight]\nlaunch_angle = 20.0\ndistance = 11.0\n")).unwrap();
        let three = parse(Path::new("b.toml"), &format!("level = \"3d\"\n{shared}[flight]\ndistance = 11.0\n")).unwrap();
        for e in [&one, &three] {
            assert_eq!((e.name.as_str(), e.description.as_str()), ("both", "one schema"));
            assert_eq!(e.compress, crate::columns::Compression::Deflate(6));
            assert_eq!(e.output, Output::Summary);
            assert_eq!(e.flight.as_ref().and_then(|f| f.rest.distance), Some(11.0));
        }
        let Kicks::OneD(Kicks1d { scenarios: Scenarios::Grid { base, grid }, .. }) = &one.kicks else { panic!("{:?}", one.kicks) };
        let Kicks::ThreeD(kicks) = &three.kicks else { panic!("{:?}", three.kicks) };
        assert_eq!(grid, &kicks.grid);
        assert_eq!((grid.len(), grid.shape()), (6, vec![2, 3]));
        assert_eq!(grid.coordinates(5), vec![1e6, 20.0]);
        // The base kick and its law, read once for both.
        assert_eq!(base, &kicks.scenario);
        assert_eq!((base.get(Parameter::FootMass), base.restitution_target()), (1.5, Some(0.5)));
        // Cell 4 of each level is the same scenario: (1e6, 15).
        let four = one.one_d().unwrap().scenarios.scenario(4).unwrap();
        assert_eq!((four.get(Parameter::Stiffness), four.get(Parameter::FootSpeed)), (1e6, 15.0));
        assert_eq!(kicks.kick(4).unwrap().base, four);
    }

    /// A fixed `[kick3d]` key the model refuses is said at that key, with a
    /// sweep beside it (`friction = nan` was said at the sweep's first value).
    #[test]
    fn a_refused_fixed_key_is_said_at_its_line_beside_a_sweep() {
        for value in ["nan", "-1.0"] {
            let text = format!("level = \"3d\"\n[kick3d]\nfriction = {value}\n[[sweep]]\nparameter = \"offset\"\nvalues = [0.0, 0.05]\n");
            let e = parse_text(&text).unwrap_err();
            assert_eq!((e.line, e.key.as_str()), (3, "kick3d.friction"), "{e}");
            assert!(e.message.contains("invalid parameter `friction`"), "{e}");
        }
        // The swept parameter's own bad value is still said at its value.
        let e = parse_text("level = \"3d\"\n[[sweep]]\nparameter = \"friction\"\nvalues = [0.5, -1.0]\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (4, "sweep.friction"), "{e}");
    }

    /// A key of the other level is refused at its line with the keys this
    /// level takes (1D histories, 3D `[kick3d]`).
    #[test]
    fn a_key_of_the_other_level_is_refused_with_this_levels_keys() {
        let e = parse_text("level = \"3d\"\n[output]\nmode = \"summary\"\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "output"), "{e}");
        assert_eq!(
            e.message,
            "unknown field `output`, expected one of `level`, `name`, `description`, `solver`, `law`, \
                               `restitution`, `base`, `kick3d`, `sweep`, `flight`, `compress`"
        );
        let e = parse_text("level = \"1d\"\n[kick3d]\noffset = 0.01\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "kick3d"), "{e}");
        assert!(
            e.message.starts_with("unknown field `kick3d`, expected one of `level`, `name`, `description`, `solver`, `solvers`, `dt`"),
            "{e}"
        );
        // A 1D axis is a parameter of the 1D scenario, its ball or its flight; one the law ignores is refused at its line.
        let e = parse_text("[[sweep]]\nparameter = \"restitution\"\nvalues = [0.5]\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "sweep.restitution"), "{e}");
        assert!(e.message.starts_with("`restitution` does not apply to law `power-law`"), "{e}");
        let e = parse_text("[[sweep]]\nparameter = \"ofset\"\nvalues = [0.5]\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "parameter"), "{e}");
        assert!(e.message.starts_with("unknown parameter `ofset` of the 1D scenario or its flight"), "{e}");
        let e = parse_text("[[sweep]]\nparameter = \"air_density\"\nvalues = [1.1]\n").unwrap_err();
        assert!(e.message.contains("add a [flight] table"), "{e}");
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
                let scenario = experiment.one_d().unwrap().scenarios.scenario(0).unwrap();
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

    /// A `table2` file gives every row whole: a `[base]` key, a `law` or a
    /// `restitution` beside it is refused at its line (they were ignored,
    /// the runs identical to a plain Table 2 run).
    #[test]
    fn what_a_table2_file_would_ignore_is_refused() {
        for (text, line, key) in [
            ("table2 = \"t.toml\"\n[base]\nstiffness = 1e5\n", 3, "base.stiffness"),
            ("table2 = \"t.toml\"\nlaw = \"flores\"\nrestitution = 0.6\n", 2, "law"),
            ("table2 = \"t.toml\"\nrestitution = 0.6\n", 2, "restitution"),
        ] {
            let e = parse_text(text).unwrap_err();
            assert_eq!((e.line, e.key.as_str()), (line, key), "{e}");
            assert!(e.message.contains("would be ignored"), "{e}");
        }
    }

    /// Inputs that are not experiment or scenario files: refused at once
    /// (no read until memory runs out, no wait on a FIFO), naming the key,
    /// and no line of the file quoted (issue 21).
    #[cfg(unix)]
    #[test]
    fn inputs_are_bounded_and_their_contents_not_quoted() {
        let e = parse_text("table2 = \"/dev/zero\"\n").unwrap_err();
        assert!(e.key == "table2" && e.message.contains("not a regular file"), "{e}");
        let e = load(Path::new("/dev/zero")).unwrap_err();
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

    /// `law = "shell"` with the ball's keys in `[base]` and `[[scenario]]`:
    /// every scenario solves with that ball (a swept grid keeps it, a named
    /// scenario's own key wins), in 1D and 3D files; under another law a
    /// ball key is refused at its line.
    #[test]
    fn the_shell_balls_keys_reach_every_scenario() {
        let ball =
            |p, loss| kick_core::AnyLaw::Shell(kick_core::ShellBall::new(p, kick_core::DEFAULT_BALL_RADIUS, 1.4, 0.0, loss).unwrap());
        let loss = kick_core::shell::SHELL_DAMPING.default_number();
        let grid = "law = \"shell\"\n[base]\ninflation_pressure = 6.0e4\n[[sweep]]\nparameter = \"foot_speed\"\nvalues = [18.0, 22.0]\n";
        let e = parse(Path::new("g.toml"), grid).unwrap();
        let kicks = e.one_d().unwrap();
        for i in 0..2 {
            assert_eq!(kicks.scenarios.scenario(i).unwrap().contact_law(), ball(6.0e4, loss), "row {i}");
        }
        let named = "law = \"shell\"\n[base]\nshell_damping = 3000.0\n[[scenario]]\nname = \"soft\"\ninflation_pressure = 6.0e4\n[[scenario]]\nname = \"hard\"\n";
        let kicks = parse(Path::new("n.toml"), named).unwrap();
        let kicks = kicks.one_d().unwrap();
        assert_eq!(kicks.scenarios.scenario(0).unwrap().contact_law(), ball(6.0e4, 3000.0));
        assert_eq!(kicks.scenarios.scenario(1).unwrap().contact_law(), ball(8.0e4, 3000.0));
        let three = "level = \"3d\"\nlaw = \"shell\"\n[base]\ninflation_pressure = 6.0e4\n[[sweep]]\nparameter = \"offset\"\nvalues = [0.0, 0.05]\n";
        let e = parse(Path::new("t.toml"), three).unwrap();
        assert_eq!(e.three_d().unwrap().scenario.contact_law(), ball(6.0e4, loss));
        let refused = parse(Path::new("r.toml"), "[base]\nfoot_mass = 2.0\ninflation_pressure = 6.0e4\n").unwrap_err();
        assert_eq!(refused.line, 3, "{refused}");
        assert!(
            refused.to_string().contains("`base.inflation_pressure`: `inflation_pressure` does not apply to law `power-law`"),
            "{refused}"
        );
    }

    /// `leg = true` and the boot's keys in `[base]` and `[[scenario]]`: every
    /// scenario stands on that foot (the leg's mass, its identified boot, a
    /// named scenario's own pose), a 3D file sweeps them (level 3d), and a
    /// setting the foot would ignore is refused at its line.
    #[test]
    fn the_foots_keys_reach_every_scenario() {
        use kick_core::leg::{LegFoot, LegPose};
        use kick_core::{boot::IDENTIFIED, Foot};
        let grid = "law = \"shell\"\n[base]\nleg = true\n[[sweep]]\nparameter = \"foot_speed\"\nvalues = [9.1, 21.2]\n";
        let e = parse(Path::new("g.toml"), grid).unwrap();
        let kicks = e.one_d().unwrap();
        let mass = LegFoot::new(LegPose::DEFAULT).unwrap().effective_mass;
        for i in 0..2 {
            let s = kicks.scenarios.scenario(i).unwrap();
            assert_eq!(s.foot(), Foot { leg: Some(LegPose::DEFAULT), boot: Some(IDENTIFIED) }, "row {i}");
            assert_eq!(s.effective_foot_mass(), mass);
        }
        let named =
            "[base]\nboot_stiffness = 5.0e4\n[[scenario]]\nname = \"boot\"\n[[scenario]]\nname = \"leg\"\nleg = true\nknee = 50.0\n";
        let e = parse(Path::new("n.toml"), named).unwrap();
        let kicks = e.one_d().unwrap();
        let (boot, leg) = (kicks.scenarios.scenario(0).unwrap(), kicks.scenarios.scenario(1).unwrap());
        assert_eq!((boot.effective_foot_mass(), boot.boot().map(|b| b.stiffness)), (3.0, Some(5.0e4)));
        assert_eq!(leg.foot().leg.map(|p| p.knee), Some(50.0));
        assert_eq!(leg.boot().map(|b| b.stiffness), Some(5.0e4));
        let three = "level = \"3d\"\nlaw = \"shell\"\n[base]\nleg = true\n[kick3d]\noffset = 0.03\n[[sweep]]\nparameter = \"boot_stiffness\"\nvalues = [3.0e4, 6.0e4]\n";
        let e = parse(Path::new("t.toml"), three).unwrap();
        let kicks = e.three_d().unwrap();
        for (i, k_b) in [3.0e4, 6.0e4].into_iter().enumerate() {
            let spec: kick_core::ScenarioSpec =
                toml::from_str(&format!("law = \"shell\"\nleg = true\nboot_stiffness = {k_b:e}\n")).unwrap();
            let by_hand = kick_3d::KickSpec { scenario: spec, kick3d: kick_3d::Kick3dSpec { offset: Some(0.03), ..Default::default() } };
            assert_eq!(kicks.kick(i as u64).unwrap(), by_hand.build().unwrap(), "cell {i}");
        }
        let refused = parse(Path::new("r.toml"), "[base]\nleg = true\nfoot_mass = 2.0\n").unwrap_err();
        assert_eq!(refused.line, 3, "{refused}");
        assert!(refused.to_string().contains("`base.foot_mass`: `foot_mass` does not apply to the leg"), "{refused}");
        let refused = parse(Path::new("k.toml"), "[base]\nfoot_speed = 20.0\nknee = 20.0\n").unwrap_err();
        assert_eq!(refused.line, 3, "{refused}");
        assert!(refused.to_string().contains("`knee` does not apply to a foot without the leg"), "{refused}");
    }

    /// The instep's parameters are 3D sweep axes (a file sweeping one is a
    /// 3D file): every cell's kick is the one built by hand with that value.
    #[test]
    fn an_instep_parameter_is_a_3d_sweep_axis() {
        use kick_core::parameters::{find, SetParameter, Value};
        let text = "law = \"shell\"\n[kick3d]\noffset = 0.04\n[[sweep]]\nparameter = \"face_yaw\"\nvalues = [0.0, 10.0, 21.3]\n";
        let e = parse(Path::new("yaw.toml"), text).unwrap();
        let kicks = e.three_d().expect("a file sweeping face_yaw is 3D");
        for (i, yaw) in [0.0, 10.0, 21.3].into_iter().enumerate() {
            let mut spec = kick_3d::KickSpec::default();
            spec.scenario.law = Some(kick_core::LawKind::Shell);
            spec.set_parameter(find("offset").unwrap(), Value::Number(0.04)).unwrap();
            spec.set_parameter(find("face_yaw").unwrap(), Value::Number(yaw)).unwrap();
            assert_eq!(kicks.kick(i as u64).unwrap(), spec.build().unwrap(), "cell {i}");
        }
    }
}
