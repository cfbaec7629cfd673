//! The rows of the validation chapter and the rules they follow (issue 23):
//! every row has a [`Role`]; only predictions with a measured interval of
//! nonzero width, like for like with the model run, are counted; every row
//! states the conditions the model ran at beside the measurement's own.

use kick_core::measurements::{Comparison, Measurements};
use serde::Serialize;

/// What a row does for the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Role {
    /// The measurement set a parameter ([`Row::sets`] says which).
    Calibration,
    /// The measurement set nothing: the model predicts it.
    Prediction,
    /// A consistency or definition check (the ball against Law 2, the integrator, a pulse shape of another kick).
    Check,
}

impl Role {
    pub fn name(self) -> &'static str {
        match self {
            Role::Calibration => "calibration",
            Role::Prediction => "prediction",
            Role::Check => "check",
        }
    }
}

/// One comparison with its role and conditions.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    pub role: Role,
    /// Calibration rows: the parameter the measurement set, and its value.
    pub sets: Option<String>,
    /// The model: law and ball (e.g. "paper's law (Table 1)", "shell ball, 0.8 bar").
    pub model: String,
    /// The conditions the model ran at (foot, speed, offset, friction).
    pub model_conditions: String,
    /// The measurement's own conditions (from the measurement file).
    pub measured_conditions: String,
    /// Why a prediction is left out of the count although it has an
    /// interval (not like for like); None when counted or not countable.
    pub not_counted: Option<String>,
    /// Quantity, measured interval, model value, ratio, miss, and why it agrees or misses.
    pub comparison: Comparison,
}

impl Row {
    /// A row with the measurement's conditions read from `m` (the first key of a composite `a/b` or `a*b`).
    pub fn new(m: &Measurements, role: Role, model: &str, model_conditions: impl Into<String>, comparison: Comparison) -> Row {
        let first = comparison.measured.key.split(['/', '*']).next().unwrap_or("");
        let measured_conditions = m.get(first, "the validation chapter").map(|x| x.conditions.clone()).unwrap_or_default();
        Row {
            role,
            sets: None,
            model: model.to_string(),
            model_conditions: model_conditions.into(),
            measured_conditions,
            not_counted: None,
            comparison,
        }
    }

    pub fn sets(mut self, what: impl Into<String>) -> Row {
        self.sets = Some(what.into());
        self
    }

    pub fn not_counted(mut self, why: impl Into<String>) -> Row {
        self.not_counted = Some(why.into());
        self
    }

    /// [low, high] when the measurement is an interval of nonzero width.
    pub fn interval(&self) -> Option<(f64, f64)> {
        match (self.comparison.measured.low, self.comparison.measured.high) {
            (Some(lo), Some(hi)) if hi > lo => Some((lo, hi)),
            _ => None,
        }
    }

    /// A measured point (a value without a spread from its source): shown, never counted.
    pub fn is_point(&self) -> bool {
        matches!((self.comparison.measured.low, self.comparison.measured.high), (Some(lo), Some(hi)) if hi == lo)
    }

    /// Counted in the headline: a prediction, like for like, with an interval.
    pub fn counted(&self) -> bool {
        self.role == Role::Prediction && self.not_counted.is_none() && self.interval().is_some()
    }

    /// Inside the measured interval (bounds included), for a counted row.
    pub fn inside(&self) -> Option<bool> {
        self.counted().then(|| self.comparison.agrees() == Some(true))
    }

    /// What the page prints in the "counted?" column.
    pub fn count_note(&self) -> String {
        if self.counted() {
            return "yes".into();
        }
        match (self.role, &self.not_counted) {
            (Role::Prediction, Some(why)) => format!("no: {why}"),
            (Role::Prediction, None) if self.is_point() => "no: a point (the source gives no spread)".into(),
            (Role::Prediction, None) => "no: a claim in words".into(),
            (role, _) => format!("no: a {}", role.name()),
        }
    }
}

/// (predictions inside their interval, predictions counted) over `rows`.
pub fn headline<'a>(rows: impl IntoIterator<Item = &'a Row>) -> (usize, usize) {
    rows.into_iter().filter(|r| r.counted()).fold((0, 0), |(i, n), r| (i + usize::from(r.inside() == Some(true)), n + 1))
}

/// An estimate as the page prints it: "not identified" when its σ exceeds it.
pub fn estimate_cell(value: Option<f64>, sigma: Option<f64>) -> String {
    match (value, sigma) {
        (None, _) => "not identified".into(),
        (Some(v), Some(s)) if s > v.abs() => format!("not identified (σ = {} > {})", kick_core::short(s), kick_core::short(v)),
        (Some(v), Some(s)) => format!("{} ± {}", kick_core::short(v), kick_core::short(s)),
        (Some(v), None) => format!("{} (no σ: the source gives means only)", kick_core::short(v)),
    }
}
