//! Observations and the fit specification file.
//!
//! A fit specification (TOML, or JSON with the same fields) names the free
//! parameters, the known values and starting guesses, and the data:
//!
//! ```toml
//! free = ["foot_mass", "stiffness", "damping", "exponent"]  # FitParameter names
//! law = "power-law"     # optional contact law, as in experiment files (default: Eq. 20)
//! restitution = 0.66    # target restitution of the other laws (a start when free)
//! time_offset = 0.0     # t0, s: data time of first touch (a start when free)
//! [scenario]            # the eight parameters; the rest is Table 1's baseline
//! foot_mass = 2.5       # starting guess for a free parameter, known value otherwise
//! [[scalar]]            # zero or more scalar observations, SI units
//! observable = "v_ball_out"
//! value = 31.98
//! sigma = 0.005         # standard uncertainty, same unit
//! [history]             # optional time history
//! file = "kick.csv"     # relative to the specification file
//! sigma = { force = 40.0, compression = 2e-4, ball_velocity = 0.05 }
//! [truth]               # optional: true values (synthetic data), for the pulls
//! stiffness = 4.2e5
//! ```
//!
//! The history CSV has a header `time,<channel>,...` with channels among
//! `force` (N), `compression` (m), `foot_velocity`, `ball_velocity` (m/s);
//! times in s, strictly increasing, first touch at t0 (`time_offset`); lines
//! starting with `#` are comments. Every channel in the file needs a sigma.
//!
//! Many measurements, each at its own conditions: `[[measurement]]` tables,
//! each with the values of declared parameters it was taken at (its keys,
//! the level's names), its `[[measurement.scalar]]` observations with σ, an
//! optional `name` and (at the kick level) a `history`. The model point is
//! moved to a measurement's conditions before it predicts that measurement.
//! `level = "bounce"` fits the ball alone on a rigid plate (`kick bounce`):
//! its known values and starting guesses go in `[bounce]` by `kick bounce`'s
//! names, its observables are `restitution`, `contact_time`, `peak_force`
//! and `max_compression` of the normal phase:
//!
//! ```toml
//! level = "bounce"
//! free = ["shell_damping", "shell_stiffness"]
//! [bounce]
//! shell_stiffness = 1000.0   # a starting guess
//! [[measurement]]
//! name = "6 m/s at 0.8 bar"
//! speed = 6.0
//! inflation_pressure = 8.0e4
//! [[measurement.scalar]]
//! observable = "restitution"
//! value = 0.84
//! sigma = 0.01
//! ```
//!
//! A problem in a TOML file is reported as `file:line` with the key
//! (`measurement[2].speed`); in a JSON file as `file` with the key.

use crate::parameter::{FitLevel, FitParameter, ModelPoint};
use crate::IdentifyError;
use kick_core::{LawKind, Outcome, ScenarioSpec};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A scalar observable of one contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Observable {
    /// v_b⁺, m/s.
    VBallOut,
    /// v_f⁺, m/s.
    VFootOut,
    /// t_c, s.
    ContactTime,
    /// sup F, N.
    PeakForce,
    /// δ_max, m.
    MaxCompression,
    /// e = −δ̇⁺/δ̇⁻, the contact's restitution (a bounce's, relative to the plate).
    Restitution,
}

impl Observable {
    pub const ALL: [Observable; 6] = [
        Observable::VBallOut,
        Observable::VFootOut,
        Observable::ContactTime,
        Observable::PeakForce,
        Observable::MaxCompression,
        Observable::Restitution,
    ];
    pub const NAMES: &'static str = "v_ball_out, v_foot_out, contact_time, peak_force, max_compression, restitution";

    pub fn name(self) -> &'static str {
        match self {
            Observable::VBallOut => "v_ball_out",
            Observable::VFootOut => "v_foot_out",
            Observable::ContactTime => "contact_time",
            Observable::PeakForce => "peak_force",
            Observable::MaxCompression => "max_compression",
            Observable::Restitution => "restitution",
        }
    }

    /// SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            Observable::VBallOut | Observable::VFootOut => "m/s",
            Observable::ContactTime => "s",
            Observable::PeakForce => "N",
            Observable::MaxCompression => "m",
            Observable::Restitution => "1",
        }
    }

    pub fn from_name(name: &str) -> Result<Observable, IdentifyError> {
        Observable::ALL
            .into_iter()
            .find(|o| o.name() == name)
            .ok_or_else(|| IdentifyError::UnknownObservable { name: name.to_string(), expected: Observable::NAMES })
    }

    pub fn value(self, outcome: &Outcome) -> f64 {
        match self {
            Observable::VBallOut => outcome.v_ball_out,
            Observable::VFootOut => outcome.v_foot_out,
            Observable::ContactTime => outcome.contact_time,
            Observable::PeakForce => outcome.peak_force,
            Observable::MaxCompression => outcome.max_compression,
            Observable::Restitution => outcome.restitution,
        }
    }

    /// Whether a fit at `level` predicts it: a bounce's plate takes no
    /// exit speeds (its normal phase gives the ball's rebound as `restitution`).
    pub fn at(self, level: FitLevel) -> bool {
        level == FitLevel::Kick || !matches!(self, Observable::VBallOut | Observable::VFootOut)
    }
}

/// One measured scalar with its standard uncertainty.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScalarObservation {
    pub observable: Observable,
    pub value: f64,
    pub sigma: f64,
}

/// A recorded channel of a time history.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Channel {
    /// F(t), N.
    Force,
    /// δ(t) = max(x_f − x_b, 0), m.
    Compression,
    /// v_f(t), m/s.
    FootVelocity,
    /// v_b(t), m/s.
    BallVelocity,
}

impl Channel {
    pub const ALL: [Channel; 4] = [Channel::Force, Channel::Compression, Channel::FootVelocity, Channel::BallVelocity];
    pub const NAMES: &'static str = "force, compression, foot_velocity, ball_velocity";

    pub fn name(self) -> &'static str {
        match self {
            Channel::Force => "force",
            Channel::Compression => "compression",
            Channel::FootVelocity => "foot_velocity",
            Channel::BallVelocity => "ball_velocity",
        }
    }

    /// SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            Channel::Force => "N",
            Channel::Compression => "m",
            Channel::FootVelocity | Channel::BallVelocity => "m/s",
        }
    }

    pub fn from_name(name: &str) -> Result<Channel, IdentifyError> {
        Channel::ALL
            .into_iter()
            .find(|c| c.name() == name)
            .ok_or_else(|| IdentifyError::UnknownChannel { name: name.to_string(), expected: Channel::NAMES })
    }
}

/// Data rows of a history. A 1 MHz record of a 100 ms contact is 100,000
/// rows; 200,000 keeps a fit under a minute (a fit's time grows with the
/// rows: 10 million took 153 s and 10 GB) while no measurement reaches it.
pub const MAX_HISTORY_ROWS: usize = 200_000;

/// Sampled channels on a common time grid.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct HistoryData {
    pub times: Vec<f64>,
    pub channels: Vec<(Channel, Vec<f64>)>,
}

impl HistoryData {
    /// Parse the CSV format described in the module documentation (at most
    /// [`MAX_HISTORY_ROWS`] data rows).
    pub fn parse_csv(text: &str, source_name: &str) -> Result<HistoryData, IdentifyError> {
        let err = |line: usize, message: String| IdentifyError::data(format!("{source_name}:{line}"), message);
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let (header_line, header) = lines.next().ok_or_else(|| IdentifyError::data(source_name, "empty file: expected a header line"))?;
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        if names.first() != Some(&"time") {
            // The found text is not quoted: the file may be any file.
            return Err(err(header_line, "the first column must be `time` (is this a history file?)".into()));
        }
        let mut channels = Vec::new();
        for name in &names[1..] {
            let channel = Channel::from_name(name)?;
            if channels.iter().any(|(c, _)| *c == channel) {
                return Err(err(header_line, format!("column `{name}` appears twice")));
            }
            channels.push((channel, Vec::new()));
        }
        if channels.is_empty() {
            return Err(err(header_line, format!("no data column: expected any of {}", Channel::NAMES)));
        }
        let mut times: Vec<f64> = Vec::new();
        for (number, line) in lines {
            if times.len() == MAX_HISTORY_ROWS {
                return Err(err(number, format!("more than {MAX_HISTORY_ROWS} data rows, the most a history may have")));
            }
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            if fields.len() != names.len() {
                return Err(err(number, format!("{} fields, the header has {}", fields.len(), names.len())));
            }
            let mut values = Vec::with_capacity(fields.len());
            for (field, name) in fields.iter().zip(&names) {
                let v: f64 = field.parse().map_err(|_| err(number, format!("column `{name}`: `{field}` is not a number")))?;
                if !v.is_finite() {
                    return Err(err(number, format!("column `{name}`: {v} is not finite")));
                }
                values.push(v);
            }
            if let Some(&last) = times.last() {
                if values[0] <= last {
                    return Err(err(number, format!("time {} does not increase (previous {last})", values[0])));
                }
            }
            times.push(values[0]);
            for ((_, column), v) in channels.iter_mut().zip(&values[1..]) {
                column.push(*v);
            }
        }
        if times.is_empty() {
            return Err(IdentifyError::data(source_name, "no data rows"));
        }
        Ok(HistoryData { times, channels })
    }

    /// The same format, full precision.
    pub fn to_csv(&self) -> String {
        let mut out = String::from("time");
        for (c, _) in &self.channels {
            out.push(',');
            out.push_str(c.name());
        }
        out.push('\n');
        for (i, t) in self.times.iter().enumerate() {
            out.push_str(&format!("{t:e}"));
            for (_, column) in &self.channels {
                out.push_str(&format!(",{:e}", column[i]));
            }
            out.push('\n');
        }
        out
    }

    /// Channels given as arrays (not read from a CSV file): refused, naming
    /// `source_name`, unless there is a channel, every channel has one value
    /// per time, every value is finite and the times increase.
    pub fn checked(self, source_name: &str) -> Result<HistoryData, IdentifyError> {
        let err = |message: String| Err(IdentifyError::data(source_name, message));
        if self.times.is_empty() {
            return err("no samples".into());
        }
        if self.channels.is_empty() {
            return err(format!("no data channel: expected any of {}", Channel::NAMES));
        }
        if self.times.len() > MAX_HISTORY_ROWS {
            return err(format!("{} samples, more than the {MAX_HISTORY_ROWS} a history may have", self.times.len()));
        }
        for (k, pair) in self.times.windows(2).enumerate() {
            if !(pair[1] > pair[0]) {
                return err(format!("time[{}] = {} does not increase (time[{k}] = {})", k + 1, pair[1], pair[0]));
            }
        }
        if let Some(k) = self.times.iter().position(|t| !t.is_finite()) {
            return err(format!("time[{k}] = {} is not finite", self.times[k]));
        }
        for (channel, values) in &self.channels {
            if values.len() != self.times.len() {
                return err(format!("`{}` has {} values for {} times", channel.name(), values.len(), self.times.len()));
            }
            if let Some(k) = values.iter().position(|v| !v.is_finite()) {
                return err(format!("{}[{k}] = {} is not finite", channel.name(), values[k]));
            }
        }
        Ok(self)
    }

    pub fn len(&self) -> usize {
        self.times.len() * self.channels.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// A history with one standard uncertainty per channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WeightedHistory {
    pub data: HistoryData,
    pub sigma: BTreeMap<Channel, f64>,
}

impl WeightedHistory {
    pub fn new(data: HistoryData, sigma: BTreeMap<Channel, f64>) -> Result<Self, IdentifyError> {
        for (channel, _) in &data.channels {
            match sigma.get(channel) {
                Some(&s) if s.is_finite() && s > 0.0 => {}
                Some(&s) => {
                    return Err(IdentifyError::data(
                        "history sigma",
                        format!("`{}` = {}: must be finite and > 0", channel.name(), kick_core::short(s)),
                    ))
                }
                None => return Err(IdentifyError::data("history sigma", format!("no sigma for channel `{}`", channel.name()))),
            }
        }
        for channel in sigma.keys() {
            if !data.channels.iter().any(|(c, _)| c == channel) {
                return Err(IdentifyError::data(
                    "history sigma",
                    format!("sigma given for `{}`, which the data do not have", channel.name()),
                ));
            }
        }
        Ok(WeightedHistory { data, sigma })
    }
}

/// Everything a fit compares the model with: observations at the model
/// point's own conditions, and measurements each at its own.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Observations {
    pub scalars: Vec<ScalarObservation>,
    pub history: Option<WeightedHistory>,
    /// Further measurements (`[[measurement]]`), each at its own conditions.
    pub measurements: Vec<Measurement>,
}

/// One measurement at its own conditions: values of declared parameters
/// (an impact speed, a pressure) set on the model point before it predicts
/// this measurement's observations.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measurement {
    /// Its label in reports (`measurement[i]` when the file names none).
    pub name: String,
    pub conditions: Vec<(FitParameter, f64)>,
    /// Its scalars and history (no nested measurements).
    pub observations: Observations,
}

impl Measurement {
    /// `point` at this measurement's conditions.
    pub fn at(&self, point: &ModelPoint) -> Result<ModelPoint, IdentifyError> {
        let mut point = *point;
        for &(p, value) in &self.conditions {
            point = point.with(p, value).map_err(|e| IdentifyError::data(format!("measurement `{}`", self.name), e.to_string()))?;
        }
        Ok(point)
    }
}

impl Observations {
    pub fn scalars(scalars: Vec<ScalarObservation>) -> Result<Self, IdentifyError> {
        let o = Observations { scalars, history: None, measurements: Vec::new() };
        o.validate()?;
        Ok(o)
    }

    pub fn history(history: WeightedHistory) -> Self {
        Observations { scalars: Vec::new(), history: Some(history), measurements: Vec::new() }
    }

    /// Number of residuals, the measurements' included.
    pub fn len(&self) -> usize {
        self.scalars.len()
            + self.history.as_ref().map_or(0, |h| h.data.len())
            + self.measurements.iter().map(|m| m.observations.len()).sum::<usize>()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether any history is among them (the measurements' included).
    pub fn has_history(&self) -> bool {
        self.history.is_some() || self.measurements.iter().any(|m| m.observations.has_history())
    }

    pub fn validate(&self) -> Result<(), IdentifyError> {
        if self.is_empty() {
            return Err(IdentifyError::NoData);
        }
        self.validate_own()?;
        for (i, m) in self.measurements.iter().enumerate() {
            let named = |e: IdentifyError| IdentifyError::data(format!("measurement `{}`", m.name), e.to_string());
            // Names label the residuals and the report's groups: one each.
            if let Some(j) = self.measurements[..i].iter().position(|other| other.name == m.name) {
                return Err(named(IdentifyError::data(
                    "name",
                    format!("measurements {j} and {i} are both called so; give each its own name"),
                )));
            }
            if m.observations.is_empty() {
                return Err(named(IdentifyError::NoData));
            }
            if !m.observations.measurements.is_empty() {
                return Err(named(IdentifyError::data("measurement", "a measurement holds no measurements of its own")));
            }
            m.observations.validate_own().map_err(named)?;
        }
        Ok(())
    }

    /// The checks of this level's own scalars and history.
    fn validate_own(&self) -> Result<(), IdentifyError> {
        if let Some(history) = &self.history {
            // A channel that never changes (all zero, or one value) says
            // nothing about the contact: refused now, not after a long fit.
            for (channel, values) in &history.data.channels {
                let first = values[0];
                if values.iter().all(|&v| v == first) {
                    let what = if first == 0.0 { "zero".to_string() } else { format!("the one value {}", kick_core::short(first)) };
                    return Err(IdentifyError::data(
                        format!("history column `{}`", channel.name()),
                        format!("all {} rows are {what}: a constant record carries no information on the contact", values.len()),
                    ));
                }
            }
        }
        for s in &self.scalars {
            if !s.value.is_finite() {
                return Err(IdentifyError::data(s.observable.name(), format!("value {} is not finite", s.value)));
            }
            if !(s.sigma.is_finite() && s.sigma > 0.0) {
                return Err(IdentifyError::data(
                    s.observable.name(),
                    format!("sigma {}: must be finite and > 0", kick_core::short(s.sigma)),
                ));
            }
        }
        Ok(())
    }
}

/// The `[history]` table of a fit specification.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HistorySpec {
    pub file: PathBuf,
    pub sigma: BTreeMap<String, f64>,
}

/// A value of a declared parameter in a specification: a number, three
/// numbers or a switch (a bounce's `spin` is three).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum GivenValue {
    Number(f64),
    Vector([f64; 3]),
    Switch(bool),
}

/// What a [`GivenValue`] may be, for error messages.
const GIVEN_VALUE: &str = "a number, three numbers [x, y, z] or true/false";

/// By hand, not untagged: serde's untagged error ("data did not match any
/// variant") says neither what was found nor what would do.
impl<'de> Deserialize<'de> for GivenValue {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Any;
        impl<'de> serde::de::Visitor<'de> for Any {
            type Value = GivenValue;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(GIVEN_VALUE)
            }
            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<GivenValue, E> {
                Ok(GivenValue::Number(v))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<GivenValue, E> {
                Ok(GivenValue::Number(v as f64))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<GivenValue, E> {
                Ok(GivenValue::Number(v as f64))
            }
            fn visit_bool<E: serde::de::Error>(self, v: bool) -> Result<GivenValue, E> {
                Ok(GivenValue::Switch(v))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<GivenValue, A::Error> {
                use serde::de::Error as _;
                let mut x = [0.0; 3];
                for (k, slot) in x.iter_mut().enumerate() {
                    *slot = seq.next_element()?.ok_or_else(|| A::Error::invalid_length(k, &self))?;
                }
                if seq.next_element::<f64>()?.is_some() {
                    return Err(A::Error::invalid_length(4, &self));
                }
                Ok(GivenValue::Vector(x))
            }
        }
        deserializer.deserialize_any(Any)
    }
}

/// The `[bounce]` table, each value's error naming its key (`bounce.law`).
fn bounce_table<'de, D: serde::Deserializer<'de>>(deserializer: D) -> Result<Option<BTreeMap<String, GivenValue>>, D::Error> {
    struct Table;
    impl<'de> serde::de::Visitor<'de> for Table {
        type Value = BTreeMap<String, GivenValue>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("a table of `kick bounce`'s parameters and their values")
        }
        fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            use serde::de::Error as _;
            let mut table = BTreeMap::new();
            while let Some(key) = map.next_key::<String>()? {
                let value: GivenValue = map.next_value().map_err(|_| {
                    // The law is chosen once for the fit, not as a value of the ball.
                    A::Error::custom(match key.as_str() {
                        "law" => "`bounce.law`: the contact law goes at the top level: law = \"...\"".to_string(),
                        _ => format!("`bounce.{key}`: expected {GIVEN_VALUE}"),
                    })
                })?;
                if table.insert(key.clone(), value).is_some() {
                    return Err(A::Error::custom(format!("`bounce.{key}`: given twice")));
                }
            }
            Ok(table)
        }
    }
    deserializer.deserialize_map(Table).map(Some)
}

/// The `[[measurement]]` tables, each parsed knowing its index, so that its
/// errors name `measurement[i]`.
fn measurement_tables<'de, D: serde::Deserializer<'de>>(deserializer: D) -> Result<Vec<MeasurementSpec>, D::Error> {
    struct Tables;
    impl<'de> serde::de::Visitor<'de> for Tables {
        type Value = Vec<MeasurementSpec>;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("an array of measurements")
        }
        fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
            let mut out = Vec::new();
            while let Some(m) = seq.next_element_seed(MeasurementKeys(Some(out.len())))? {
                out.push(m);
            }
            Ok(out)
        }
    }
    deserializer.deserialize_seq(Tables)
}

impl From<GivenValue> for kick_core::parameters::Value {
    fn from(v: GivenValue) -> Self {
        match v {
            GivenValue::Number(x) => kick_core::parameters::Value::Number(x),
            GivenValue::Vector(x) => kick_core::parameters::Value::Vector(x),
            GivenValue::Switch(x) => kick_core::parameters::Value::Switch(x),
        }
    }
}

/// A `[[measurement]]` of a fit specification: its conditions (any
/// declared parameter of the level, by name, as keys of the table), its
/// scalars (`[[measurement.scalar]]`) and optionally a history.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct MeasurementSpec {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(flatten)]
    pub conditions: BTreeMap<String, f64>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub scalar: Vec<ScalarObservation>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub history: Option<HistorySpec>,
}

impl<'de> Deserialize<'de> for MeasurementSpec {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        serde::de::DeserializeSeed::deserialize(MeasurementKeys(None), deserializer)
    }
}

/// Reads a `[[measurement]]`, its errors naming `measurement[i].KEY` when
/// its index is known, `KEY` otherwise.
struct MeasurementKeys(Option<usize>);

impl<'de> serde::de::DeserializeSeed<'de> for MeasurementKeys {
    type Value = MeasurementSpec;
    fn deserialize<D: serde::Deserializer<'de>>(self, deserializer: D) -> Result<MeasurementSpec, D::Error> {
        deserializer.deserialize_map(self)
    }
}

impl<'de> serde::de::Visitor<'de> for MeasurementKeys {
    type Value = MeasurementSpec;
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a measurement: `name`, `scalar`, `history` and the values of the parameters it was taken at")
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<MeasurementSpec, A::Error> {
        use serde::de::Error as _;
        let at = |key: &str| match self.0 {
            Some(i) => format!("measurement[{i}].{key}"),
            None => key.to_string(),
        };
        let mut m = MeasurementSpec::default();
        while let Some(key) = map.next_key::<String>()? {
            // The nested tables' errors keep the parser's place (its line; `FitSpec::parse` adds the path).
            match key.as_str() {
                "name" => m.name = Some(map.next_value()?),
                "scalar" => m.scalar = map.next_value()?,
                "history" => m.history = Some(map.next_value()?),
                _ => {
                    let value = match map.next_value::<GivenValue>() {
                        Ok(GivenValue::Number(x)) => x,
                        _ => {
                            return Err(A::Error::custom(format!(
                                "`{}`: a measurement's conditions are numbers (the scalar parameters it was taken at)",
                                at(&key)
                            )))
                        }
                    };
                    if m.conditions.insert(key.clone(), value).is_some() {
                        return Err(A::Error::custom(format!("`{}`: given twice", at(&key))));
                    }
                }
            }
        }
        Ok(m)
    }
}

/// The bounce keys that give the impact speed, one or the other.
const IMPACT_SPEED: [&str; 2] = ["speed", "drop_height"];

/// A fit specification file (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FitSpec {
    /// The model: `kick` (default: the 1D kick) or `bounce` (the ball alone on a plate).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub level: Option<String>,
    pub free: Vec<String>,
    /// Contact law of the forward model, by `LawKind` name (default: the
    /// paper's); at the bounce level a `kick bounce --law` name (default shell).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub law: Option<String>,
    /// Target restitution of a law other than the paper's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    /// t0, s: the data's time of first touch (default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_offset: Option<f64>,
    #[serde(default)]
    pub scenario: ScenarioSpec,
    /// The bounce's known values and starting guesses (level `bounce`), by
    /// `kick bounce`'s parameter names.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "bounce_table")]
    pub bounce: Option<BTreeMap<String, GivenValue>>,
    #[serde(default)]
    pub scalar: Vec<ScalarObservation>,
    #[serde(default)]
    pub history: Option<HistorySpec>,
    /// Measurements, each at its own conditions.
    #[serde(default, skip_serializing_if = "Vec::is_empty", deserialize_with = "measurement_tables")]
    pub measurement: Vec<MeasurementSpec>,
    /// The true values, when known (synthetic data): `kick fit data`
    /// reports (estimate − truth)/σ for the free parameters named here.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub truth: Option<BTreeMap<String, f64>>,
}

/// The table of a TOML text that holds byte `offset`, as a fit error names
/// it: `measurement[1]`, `measurement[1].scalar[0]`, `measurement[1].history`,
/// `scalar[0]`, `bounce`; empty at the top level.
fn table_path(text: &str, offset: usize) -> String {
    let (mut path, mut measurements, mut scalars, mut own_scalars) = (String::new(), 0, 0, 0);
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        if start > offset {
            break;
        }
        start += line.len();
        let line = line.trim();
        if let Some(header) = line.strip_prefix("[[").and_then(|l| l.split("]]").next()) {
            path = match header.trim() {
                "measurement" => {
                    (measurements, scalars) = (measurements + 1, 0);
                    format!("measurement[{}]", measurements - 1)
                }
                "measurement.scalar" => {
                    scalars += 1;
                    format!("measurement[{}].scalar[{}]", measurements.max(1) - 1, scalars - 1)
                }
                "scalar" => {
                    own_scalars += 1;
                    format!("scalar[{}]", own_scalars - 1)
                }
                other => other.to_string(),
            };
        } else if let Some(header) = line.strip_prefix('[').and_then(|l| l.split(']').next()) {
            path = match header.trim().strip_prefix("measurement.") {
                Some(key) => format!("measurement[{}].{key}", measurements.max(1) - 1),
                None => header.trim().to_string(),
            };
        }
    }
    path
}

/// Where a key of a specification is: `file:line` in a TOML text (the first
/// line of the table that holds it setting it), `file` otherwise.
struct Locator<'a> {
    source: &'a str,
    /// The text, when it is TOML.
    toml: Option<&'a str>,
}

/// A table of a specification.
#[derive(Clone, Copy)]
enum Section<'a> {
    Top,
    Table(&'a str),
    /// The i-th `[[measurement]]`.
    Measurement(usize),
    /// The j-th `[[measurement.scalar]]` (or `scalar` key) of the i-th measurement.
    MeasurementScalar(usize, usize),
}

impl Locator<'_> {
    /// The 1-based line of `key = ...` in `section`.
    fn line(&self, section: Section, key: &str) -> Option<usize> {
        let text = self.toml?;
        let (mut table, mut measurement, mut scalar): (String, Option<usize>, Option<usize>) = (String::new(), None, None);
        let mut measurements = 0;
        let mut scalars = 0;
        let mut first_scalar_line = None;
        // A key a measurement does not set: its `[[measurement]]` header's line.
        let mut header_line = None;
        for (i, raw) in text.lines().enumerate() {
            let line = raw.trim();
            if let Some(header) = line.strip_prefix("[[").and_then(|l| l.split("]]").next()) {
                let header = header.trim();
                // A top-level array of tables (`[[scalar]]`): its first header's line.
                if matches!(section, Section::Top) && header == key {
                    return Some(i + 1);
                }
                if header == "measurement" {
                    if matches!(section, Section::Measurement(m) if m == measurements) {
                        header_line = Some(i + 1);
                    }
                    measurement = Some(measurements);
                    measurements += 1;
                    scalars = 0;
                    scalar = None;
                    table = header.into();
                } else if header == "measurement.scalar" {
                    scalar = Some(scalars);
                    scalars += 1;
                    table = header.into();
                } else {
                    (table, measurement, scalar) = (header.into(), None, None);
                }
                continue;
            }
            if let Some(header) = line.strip_prefix('[').and_then(|l| l.split(']').next()) {
                // A top-level key that is a table: its header's line.
                if matches!(section, Section::Top) && header.trim() == key {
                    return Some(i + 1);
                }
                // A measurement's key that is a table (`[measurement.history]`): its header's line.
                if matches!(section, Section::Measurement(m) if measurement == Some(m))
                    && header.trim().strip_prefix("measurement.") == Some(key)
                {
                    return Some(i + 1);
                }
                (table, measurement, scalar) = (header.trim().into(), None, None);
                continue;
            }
            let Some((k, _)) = line.split_once('=') else { continue };
            let k = k.trim().trim_matches('"');
            let here = match section {
                Section::Top => table.is_empty(),
                Section::Table(name) => table == name,
                Section::Measurement(m) => measurement == Some(m) && table == "measurement",
                Section::MeasurementScalar(m, j) => {
                    if measurement == Some(m) && table == "measurement" && k == "scalar" {
                        first_scalar_line.get_or_insert(i + 1);
                    }
                    measurement == Some(m) && scalar == Some(j) && table == "measurement.scalar"
                }
            };
            if here && k == key {
                return Some(i + 1);
            }
        }
        first_scalar_line.or(header_line)
    }

    /// A data error at `key` of `section`, named `what`.
    fn error(&self, section: Section, key: &str, what: &str, message: impl Into<String>) -> IdentifyError {
        let place = match self.line(section, key) {
            Some(line) => format!("{}:{line}", self.source),
            None => self.source.to_string(),
        };
        IdentifyError::data(place, format!("`{what}`: {}", message.into()))
    }
}

impl FitSpec {
    /// Parse TOML, or JSON when the text starts with `{`. A TOML error
    /// names the table it is in (`measurement[1].history`) before the
    /// parser's line, unless its message names the key already.
    pub fn parse(text: &str, source_name: &str) -> Result<FitSpec, IdentifyError> {
        if text.trim_start().starts_with('{') {
            serde_json::from_str(text).map_err(|e| IdentifyError::data(source_name, e.to_string()))
        } else {
            toml::from_str(text).map_err(|e| {
                let path = e.span().map(|span| table_path(text, span.start)).unwrap_or_default();
                match path.is_empty() || e.message().starts_with('`') {
                    true => IdentifyError::data(source_name, e.to_string()),
                    false => IdentifyError::data(source_name, format!("`{path}`: {e}")),
                }
            })
        }
    }

    /// The model the data are fitted with (`level`, default the kick).
    pub fn fit_level(&self) -> Result<FitLevel, IdentifyError> {
        self.level.as_deref().map_or(Ok(FitLevel::Kick), FitLevel::from_name)
    }

    /// Known values and starting guesses: the scenario with its law, and t0;
    /// at the bounce level the bounce of `[bounce]`.
    pub fn start(&self, source_name: &str) -> Result<ModelPoint, IdentifyError> {
        self.start_located(&Locator { source: source_name, toml: None })
    }

    fn start_located(&self, at: &Locator) -> Result<ModelPoint, IdentifyError> {
        let source_name = at.source;
        match self.fit_level().map_err(|e| at.error(Section::Top, "level", "level", e.to_string()))? {
            FitLevel::Kick => {
                if self.bounce.is_some() {
                    return Err(at.error(Section::Top, "level", "bounce", "a [bounce] table needs level = \"bounce\""));
                }
                let law = match &self.law {
                    Some(name) => Some(LawKind::from_name(name).map_err(|e| at.error(Section::Top, "law", "law", e.to_string()))?),
                    None => None,
                };
                let spec = self.scenario.with_law_keys(law, self.restitution).map_err(|key| {
                    IdentifyError::data(
                        source_name,
                        format!("`{key}` is set both at the top level and in [scenario]; set it once, at the top level"),
                    )
                })?;
                let scenario = spec.build().map_err(|e| IdentifyError::data(source_name, e.to_string()))?;
                ModelPoint::new(scenario, self.time_offset.unwrap_or(0.0))
            }
            FitLevel::Bounce => {
                for (given, key) in [
                    (self.scenario != ScenarioSpec::default(), "scenario"),
                    (self.restitution.is_some(), "restitution"),
                    (self.time_offset.is_some(), "time_offset"),
                    (self.history.is_some(), "history"),
                ] {
                    if given {
                        return Err(at.error(
                            Section::Top,
                            key,
                            key,
                            "not a key of a bounce fit (its values go in [bounce], by `kick bounce`'s names; it has no history)",
                        ));
                    }
                }
                let mut spec = kick_bounce::BounceSpec::default();
                if let Some(name) = &self.law {
                    spec.law =
                        Some(kick_bounce::LawChoice::from_name(name).map_err(|e| at.error(Section::Top, "law", "law", e.to_string()))?);
                }
                for (key, &value) in self.bounce.iter().flatten() {
                    spec.set(key, value.into())
                        .map_err(|e| at.error(Section::Table("bounce"), key, &format!("bounce.{key}"), e.to_string()))?;
                }
                // Without an impact speed in [bounce], every observation needs
                // one of its own: the top-level [[scalar]]s have none to take
                // (a measurement's would make the fit depend on their order),
                // each measurement must give its own, and one of theirs only
                // completes the start (each replaces it, `ModelPoint::with`).
                if IMPACT_SPEED.iter().all(|k| spec.given(k).is_none()) {
                    let own = |m: &MeasurementSpec| IMPACT_SPEED.iter().find_map(|&k| m.conditions.get(k).map(|&v| (k, v)));
                    if !self.scalar.is_empty() {
                        return Err(at.error(
                            Section::Top,
                            "scalar",
                            "scalar",
                            "a top-level [[scalar]] is taken at [bounce]'s conditions, which give no impact speed: give \
                             `speed` (or `drop_height`) in [bounce], or move it into a [[measurement]] with its own",
                        ));
                    }
                    // A measurement without one is refused where it is read (`load`).
                    let (name, value) = self.measurement.iter().find_map(own).ok_or_else(|| {
                        at.error(
                            Section::Table("bounce"),
                            "speed",
                            "bounce.speed",
                            "give the impact speed (or drop_height) in [bounce] or in each [[measurement]]",
                        )
                    })?;
                    spec.set(name, kick_core::parameters::Value::Number(value))
                        .map_err(|e| IdentifyError::data(source_name, e.to_string()))?;
                }
                ModelPoint::bounce(spec).map_err(|e| at.error(Section::Table("bounce"), "speed", "bounce", e.to_string()))
            }
        }
    }

    /// The free parameters, by name.
    pub fn free_parameters(&self) -> Result<Vec<FitParameter>, IdentifyError> {
        let level = self.fit_level()?;
        self.free.iter().map(|name| FitParameter::from_name_at(level, name)).collect()
    }

    /// The `[truth]` table by parameter; names are checked (free
    /// parameters only), values must be finite.
    pub fn truth(&self) -> Result<Vec<(FitParameter, f64)>, IdentifyError> {
        let Some(truth) = &self.truth else { return Ok(Vec::new()) };
        let level = self.fit_level()?;
        truth
            .iter()
            .map(|(name, &value)| {
                self.truth_entry(level, name, value).map_err(|message| IdentifyError::data(format!("truth.{name}"), message))
            })
            .collect()
    }

    /// One `[truth]` entry, or why it is refused.
    fn truth_entry(&self, level: FitLevel, name: &str, value: f64) -> Result<(FitParameter, f64), String> {
        let p = FitParameter::from_name_at(level, name).map_err(|e| e.to_string())?;
        // Only an estimate has a pull; a truth for a fixed parameter would go unused, unseen.
        if !self.free.iter().any(|f| f == name) {
            return Err(format!(
                "`{name}` is not free: [truth] gives the true values of the free parameters, for their pulls (estimate − truth)/σ"
            ));
        }
        if !value.is_finite() {
            return Err(format!("{value} is not finite"));
        }
        Ok((p, value))
    }

    /// Read the specification and the history files it names (relative to it).
    pub fn load(path: &Path) -> Result<(FitSpec, Observations), IdentifyError> {
        let name = path.display().to_string();
        let text =
            kick_core::input::read_text(path, kick_core::input::MAX_TEXT_BYTES).map_err(|e| IdentifyError::data(&name, e.to_string()))?;
        let spec = FitSpec::parse(&text, &name)?;
        let at = Locator { source: &name, toml: (!text.trim_start().starts_with('{')).then_some(text.as_str()) };
        let dir = path.parent().unwrap_or(Path::new("."));
        let level = spec.fit_level().map_err(|e| at.error(Section::Top, "level", "level", e.to_string()))?;
        for (i, free) in spec.free.iter().enumerate() {
            FitParameter::from_name_at(level, free).map_err(|e| at.error(Section::Top, "free", &format!("free[{i}]"), e.to_string()))?;
        }
        for (key, &value) in spec.truth.iter().flatten() {
            spec.truth_entry(level, key, value)
                .map_err(|message| at.error(Section::Table("truth"), key, &format!("truth.{key}"), message))?;
        }
        let start = spec.start_located(&at)?;
        let history = spec.history.as_ref().map(|h| load_history(dir, h, &at, Section::Top, "history")).transpose()?;
        for s in &spec.scalar {
            if !s.observable.at(level) {
                return Err(at.error(Section::Top, "scalar", s.observable.name(), format!("not an observable of a {} fit", level.name())));
            }
        }
        let mut measurements = Vec::with_capacity(spec.measurement.len());
        for (i, m) in spec.measurement.iter().enumerate() {
            let label = m.name.clone().unwrap_or_else(|| format!("measurement[{i}]"));
            if let Some(j) = measurements.iter().position(|other: &Measurement| other.name == label) {
                return Err(at.error(
                    Section::Measurement(i),
                    "name",
                    &format!("measurement[{i}].name"),
                    format!("`{label}` names measurement[{j}] already: names label the residuals and the report, give each its own"),
                ));
            }
            let mut conditions = Vec::new();
            for (key, &value) in &m.conditions {
                let what = format!("measurement[{i}].{key}");
                let p = FitParameter::from_name_at(level, key).map_err(|e| at.error(Section::Measurement(i), key, &what, e.to_string()))?;
                if spec.free.iter().any(|f| f == key) {
                    return Err(at.error(Section::Measurement(i), key, &what, "it is free: a measurement cannot also fix it"));
                }
                p.def().check(value).map_err(|e| at.error(Section::Measurement(i), key, &what, e.to_string()))?;
                conditions.push((p, value));
            }
            let gives_speed = |k: &String| IMPACT_SPEED.contains(&k.as_str());
            if level == FitLevel::Bounce
                && !spec.bounce.iter().flat_map(|b| b.keys()).any(gives_speed)
                && !m.conditions.keys().any(gives_speed)
            {
                return Err(at.error(
                    Section::Measurement(i),
                    "speed",
                    &format!("measurement[{i}].speed"),
                    "no impact speed: give this measurement's `speed` (or `drop_height`), or one for all in [bounce]",
                ));
            }
            for (j, s) in m.scalar.iter().enumerate() {
                let what = format!("measurement[{i}].scalar[{j}]");
                if m.scalar[..j].iter().any(|t| t.observable == s.observable) {
                    return Err(at.error(
                        Section::MeasurementScalar(i, j),
                        "observable",
                        &what,
                        format!("`{}` is observed twice in this measurement; give one value with its sigma", s.observable.name()),
                    ));
                }
                if !s.observable.at(level) {
                    return Err(at.error(
                        Section::MeasurementScalar(i, j),
                        "observable",
                        &what,
                        format!("`{}` is not an observable of a {} fit", s.observable.name(), level.name()),
                    ));
                }
                if !s.value.is_finite() {
                    return Err(at.error(Section::MeasurementScalar(i, j), "value", &what, format!("value {} is not finite", s.value)));
                }
                if !(s.sigma.is_finite() && s.sigma > 0.0) {
                    return Err(at.error(
                        Section::MeasurementScalar(i, j),
                        "sigma",
                        &what,
                        format!("sigma {}: must be finite and > 0", s.sigma),
                    ));
                }
            }
            if level == FitLevel::Bounce && m.history.is_some() {
                return Err(at.error(
                    Section::Measurement(i),
                    "history",
                    &format!("measurement[{i}].history"),
                    "a bounce fit takes scalars only",
                ));
            }
            let history = m
                .history
                .as_ref()
                .map(|h| load_history(dir, h, &at, Section::Measurement(i), &format!("measurement[{i}].history")))
                .transpose()?;
            let observations = Observations { scalars: m.scalar.clone(), history, measurements: Vec::new() };
            if observations.is_empty() {
                return Err(at.error(
                    Section::Measurement(i),
                    "name",
                    &format!("measurement[{i}]"),
                    "no observations: add [[measurement.scalar]] tables",
                ));
            }
            let measurement = Measurement { name: label, conditions, observations };
            // Its conditions must build on the start (a speed the plate can take, say).
            measurement.at(&start).map_err(|e| {
                let key = m.conditions.keys().next().map(String::as_str).unwrap_or("name");
                at.error(Section::Measurement(i), key, &format!("measurement[{i}]"), e.to_string())
            })?;
            measurements.push(measurement);
        }
        let observations = Observations { scalars: spec.scalar.clone(), history, measurements };
        observations.validate()?;
        Ok((spec, observations))
    }
}

/// A `[history]` table's file (relative to `dir`) with its sigmas; errors
/// name the specification's line of the table and `what` (`history`,
/// `measurement[i].history`) with `.file` or `.sigma`, then the data file's
/// own place.
fn load_history(dir: &Path, h: &HistorySpec, at: &Locator, section: Section, what: &str) -> Result<WeightedHistory, IdentifyError> {
    let err = |key: &str, e: IdentifyError| {
        // The sigmas' own errors are called "history sigma": the key says it.
        let message = match e {
            IdentifyError::Data { source_name, message } if source_name == "history sigma" => message,
            other => other.to_string(),
        };
        at.error(section, "history", &format!("{what}.{key}"), message)
    };
    let file = dir.join(&h.file);
    let file_name = file.display().to_string();
    let csv = kick_core::input::read_text(&file, kick_core::input::MAX_DATA_BYTES)
        .map_err(|e| err("file", IdentifyError::data(&file_name, e.to_string())))?;
    let data = HistoryData::parse_csv(&csv, &file_name).map_err(|e| err("file", e))?;
    let mut sigma = BTreeMap::new();
    for (k, v) in &h.sigma {
        sigma.insert(Channel::from_name(k).map_err(|e| err("sigma", e))?, *v);
    }
    WeightedHistory::new(data, sigma).map_err(|e| err("sigma", e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trips_and_names_its_errors() {
        let text = "# a comment\ntime,force,ball_velocity\n0,0,0\n1e-3,100.5,2\n2e-3,50,4\n";
        let h = HistoryData::parse_csv(text, "k.csv").unwrap();
        assert_eq!(h.times, vec![0.0, 1e-3, 2e-3]);
        assert_eq!(h.channels[0].1, vec![0.0, 100.5, 50.0]);
        assert_eq!(HistoryData::parse_csv(&h.to_csv(), "again").unwrap(), h);

        let e = HistoryData::parse_csv("time,force\n0,1\n0,2\n", "k.csv").unwrap_err();
        assert!(e.to_string().contains("k.csv:3") && e.to_string().contains("does not increase"), "{e}");
        let e = HistoryData::parse_csv("time,force\n0,x\n", "k.csv").unwrap_err();
        assert!(e.to_string().contains("`x` is not a number"), "{e}");
        let e = HistoryData::parse_csv("time,forse\n0,1\n", "k.csv").unwrap_err();
        assert!(matches!(e, IdentifyError::UnknownChannel { .. }), "{e}");
        let e = HistoryData::parse_csv("time,force\n0,NaN\n", "k.csv").unwrap_err();
        assert!(e.to_string().contains("not finite"), "{e}");
        assert!(HistoryData::parse_csv("", "k.csv").is_err());
        assert!(HistoryData::parse_csv("force,time\n1,0\n", "k.csv").is_err());
    }

    #[test]
    fn sigma_must_cover_exactly_the_channels() {
        let h = HistoryData::parse_csv("time,force\n0,1\n", "k").unwrap();
        assert!(WeightedHistory::new(h.clone(), BTreeMap::new()).is_err());
        assert!(WeightedHistory::new(h.clone(), BTreeMap::from([(Channel::Force, -1.0)])).is_err());
        assert!(WeightedHistory::new(h.clone(), BTreeMap::from([(Channel::Force, 1.0), (Channel::Compression, 1.0)])).is_err());
        assert!(WeightedHistory::new(h, BTreeMap::from([(Channel::Force, 1.0)])).is_ok());
    }

    #[test]
    fn spec_parses_toml_and_json() {
        let toml =
            "free = [\"stiffness\"]\n[scenario]\nstiffness = 3e5\n[[scalar]]\nobservable = \"v_ball_out\"\nvalue = 31.98\nsigma = 0.005\n";
        let spec = FitSpec::parse(toml, "a.toml").unwrap();
        assert_eq!(spec.scenario.stiffness, Some(3e5));
        assert_eq!(spec.scalar[0].observable, Observable::VBallOut);
        let json = r#"{"free": ["damping"], "scalar": [{"observable": "peak_force", "value": 3804, "sigma": 0.5}]}"#;
        assert_eq!(FitSpec::parse(json, "a.json").unwrap().scalar[0].value, 3804.0);
        assert!(FitSpec::parse("free = [\"k\"]\nbogus = 1\n", "b.toml").is_err());
    }

    /// All-zero or constant data is refused before any fit, naming the column.
    #[test]
    fn a_constant_record_is_refused_naming_the_column() {
        for (force, says) in [("0", "are zero"), ("250", "are the one value 250")] {
            let text: String = std::iter::once("time,force,ball_velocity\n".to_string())
                .chain((0..50).map(|i| format!("{},{force},{}\n", i as f64 * 1e-4, i as f64 * 0.1)))
                .collect();
            let data = HistoryData::parse_csv(&text, "k.csv").unwrap();
            let sigma = BTreeMap::from([(Channel::Force, 1.0), (Channel::BallVelocity, 0.1)]);
            let e = Observations::history(WeightedHistory::new(data, sigma).unwrap()).validate().unwrap_err().to_string();
            assert!(e.contains("`force`") && e.contains(says) && e.contains("50 rows"), "{e}");
        }
    }

    /// More rows than a history may have: refused at the first row beyond,
    /// not after reading and fitting them all; the header's text is not quoted.
    #[test]
    fn histories_are_bounded_and_errors_quote_no_content() {
        let mut text = String::from("time,force\n");
        for i in 0..=MAX_HISTORY_ROWS {
            text.push_str(&format!("{i},1\n"));
        }
        let e = HistoryData::parse_csv(&text, "big.csv").unwrap_err().to_string();
        assert!(e.contains(&format!("big.csv:{}", MAX_HISTORY_ROWS + 2)) && e.contains("more than 200000 data rows"), "{e}");
        let e = HistoryData::parse_csv("root:x:0:0:root:/root:/bin/bash\n", "/etc/passwd").unwrap_err().to_string();
        assert!(e.contains("/etc/passwd:1") && !e.contains("root:x"), "{e}");
    }
}
