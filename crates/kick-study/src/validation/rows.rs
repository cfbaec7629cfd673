//! The rows of the validation chapter and the rules they follow (issues 23
//! and 31): every row has a [`Role`]; a row whose verdict hinges on an
//! assumed foot mass or speed is a sensitivity statement; a finite-element
//! result is a model comparison; only predictions read in the source itself,
//! like for like with the model run and with a measurement uncertainty the
//! source states, are counted, once per distinct measurement and model, each
//! by its normalised residual z = (model − measured)/u.

use kick_core::measurements::{Comparison, Measurements};
use serde::Serialize;
use std::collections::BTreeSet;

/// What a row does for the model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// The measurement set a parameter ([`Row::sets`] says which).
    Calibration,
    /// A consistency or definition check (the ball against Law 2, a pulse shape of another kick).
    Check,
    /// The measurement set nothing: the model predicts it.
    Prediction,
    /// A prediction whose verdict hinges on an assumed foot mass or speed
    /// ([`Row::hinges_on`]): it says how far the assumption carries it.
    Sensitivity,
    /// Set beside another model's result (a finite-element simulation), not a measurement.
    ModelComparison,
}

impl Role {
    pub fn name(self) -> &'static str {
        match self {
            Role::Calibration => "calibration",
            Role::Check => "check",
            Role::Prediction => "prediction",
            Role::Sensitivity => "sensitivity",
            Role::ModelComparison => "model comparison",
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
    /// The foot the kick ran with ([`super::Foot::name`]); None for rows without a kick.
    pub foot: Option<String>,
    /// The conditions the model ran at (foot, speed, offset, friction).
    pub model_conditions: String,
    /// The measurement's own conditions (from the measurement file).
    pub measured_conditions: String,
    /// What an assumed input the verdict hinges on (foot mass, foot or ball speed).
    pub hinges_on: Option<String>,
    /// For a sensitivity statement: the value of that input which meets the measurement, when one does.
    pub would_meet: Option<String>,
    /// The model's cell when a number would mislead (a sweep's edge is no maximum).
    pub model_text: Option<String>,
    /// Why a prediction is left out of the count although it has a number
    /// (not like for like); None when counted or when another rule leaves it out.
    pub not_counted: Option<String>,
    /// Quantity, measured value, model value, ratio, miss, z, and why it agrees or misses.
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
            foot: None,
            model_conditions: model_conditions.into(),
            measured_conditions,
            hinges_on: None,
            would_meet: None,
            model_text: None,
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

    /// The kick ran with `foot`.
    pub fn with_foot(mut self, foot: super::Foot) -> Row {
        self.foot = Some(foot.name().to_string());
        self
    }

    /// The verdict hinges on `what`: a sensitivity statement while `foot` is
    /// an assumption, a prediction once the foot is measured or derived.
    pub fn hinges_on(mut self, foot: super::Foot, what: impl Into<String>, would_meet: Option<String>) -> Row {
        self.foot = Some(foot.name().to_string());
        if foot.assumed() && self.role == Role::Prediction {
            self.role = Role::Sensitivity;
        }
        self.hinges_on = Some(what.into());
        self.would_meet = would_meet;
        self
    }

    pub fn model_text(mut self, text: impl Into<String>) -> Row {
        self.model_text = Some(text.into());
        self
    }

    /// Counted: a prediction read in the source itself, like for like, with
    /// an uncertainty the source states (rounding alone does not count).
    pub fn counted(&self) -> bool {
        self.role == Role::Prediction
            && self.not_counted.is_none()
            && self.comparison.measured.checked.in_the_source()
            && self.stated_z().is_some()
    }

    /// z when the measurement's uncertainty is stated by its source.
    fn stated_z(&self) -> Option<f64> {
        let m = &self.comparison.measured;
        m.uncertainty.as_ref().filter(|u| u.is_stated()).and(self.comparison.z)
    }

    /// What the page prints in the "counted?" column.
    pub fn count_note(&self) -> String {
        if self.counted() {
            return "yes".into();
        }
        if self.role != Role::Prediction {
            return format!("no: a {}", self.role.name());
        }
        if let Some(why) = &self.not_counted {
            return format!("no: {why}");
        }
        let m = &self.comparison.measured;
        match &m.checked {
            kick_core::measurements::Checked::Transcription(_) => return "no: read only in a code base's transcription".into(),
            kick_core::measurements::Checked::Secondary(_) => return "no: read only as another work quotes it".into(),
            kick_core::measurements::Checked::Unchecked => return "no: not found in any copy read".into(),
            _ => {}
        }
        match (m.low, m.high, &m.uncertainty) {
            (None, _, _) | (_, None, _) => "no: a claim in words".into(),
            (Some(lo), Some(hi), _) if hi > lo => "no: a range over subjects or conditions, not a value with an uncertainty".into(),
            (_, _, Some(_)) => "no: the source states no uncertainty (u is its rounding)".into(),
            _ => "no: the source states no uncertainty".into(),
        }
    }
}

/// The count of a set of rows.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Headline {
    /// Distinct (measurement, model) pairs among counted rows.
    pub counted: usize,
    /// Of those, how many lie within 2u (|z| ≤ 2).
    pub within_two_u: usize,
    /// Rows by role: (role, rows).
    pub by_role: Vec<(Role, usize)>,
    /// Predictions not counted, by reason: (reason, rows).
    pub not_counted: Vec<(String, usize)>,
}

/// The count over `rows`: each distinct (measurement key, model) once.
pub fn headline<'a>(rows: impl IntoIterator<Item = &'a Row>) -> Headline {
    let mut seen = BTreeSet::new();
    let mut h = Headline::default();
    let mut roles = std::collections::BTreeMap::new();
    let mut reasons = std::collections::BTreeMap::new();
    for r in rows {
        *roles.entry(r.role).or_insert(0) += 1;
        if r.counted() {
            if seen.insert((r.comparison.measured.key.clone(), r.model.clone())) {
                h.counted += 1;
                h.within_two_u += usize::from(r.comparison.z.is_some_and(|z| z.abs() <= 2.0));
            }
        } else if r.role == Role::Prediction {
            *reasons.entry(r.count_note().trim_start_matches("no: ").to_string()).or_insert(0) += 1;
        }
    }
    h.by_role = roles.into_iter().collect();
    h.not_counted = reasons.into_iter().collect();
    h
}
