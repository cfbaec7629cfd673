//! Published measurements the models are set beside (the validation chapter),
//! and the typed rows every validation function returns.
//!
//! The data live in `experiments/validation/measurements.toml`, read by
//! `kick_store::measurements` (this crate touches no file): `[[source]]` tables (one citation each) and
//! `[[measurement]]` tables, each a value or range *as published*, in the
//! published unit ([`Unit`]), with its conditions, the source key, where in
//! the source it stands, and how far it was checked ([`Checked`]). Code reads
//! values in SI through [`Measurement::interval_si`]; nothing is converted by
//! hand in the data file, so every number can be held against its source.
//!
//! A spread (`spread`) is the SD of a population (players, kicks, balls) and
//! says nothing of how well the mean was measured; a measurement uncertainty
//! ([`Uncertainty`]) is either stated by the source or, when it states none,
//! only the rounding of the published digits (`resolution`), a lower bound.
//! A [`Comparison`] normalises its residual by the uncertainty:
//! z = (model − measured)/u.

use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use thiserror::Error;

/// Every way measurements can be refused once read; messages name the file
/// and the key. (A file that cannot be opened or parsed is kick-store's
/// `MeasurementFileError`.)
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MeasurementError {
    #[error("{file}: `{key}`: {message}")]
    Invalid { file: String, key: String, message: String },
    #[error("{file}: no measurement `{key}`, which the validation of {needed_by} reads")]
    Missing { file: String, key: String, needed_by: &'static str },
    #[error("{file}: measurement `{key}` has no number ({what}), which {needed_by} needs")]
    NoValue { file: String, key: String, what: &'static str, needed_by: &'static str },
}

/// How far a number was checked against its source.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(into = "String")]
pub enum Checked {
    /// Read in a copy of the source's text (sentence, table or figure named in `location`).
    Text,
    /// Read in the source's abstract only.
    Abstract,
    /// Read only as quoted by another work, named here.
    Secondary(String),
    /// Read only in a code base's transcription (a digitised figure, copied
    /// constants), named here: shown beside the model, never counted.
    Transcription(String),
    /// Not found in any copy read.
    Unchecked,
}

impl Checked {
    /// text > abstract > secondary > transcription > unchecked.
    fn rank(&self) -> u8 {
        match self {
            Checked::Text => 4,
            Checked::Abstract => 3,
            Checked::Secondary(_) => 2,
            Checked::Transcription(_) => 1,
            Checked::Unchecked => 0,
        }
    }

    /// Read in the source itself (its text or its abstract).
    pub fn in_the_source(&self) -> bool {
        matches!(self, Checked::Text | Checked::Abstract)
    }

    /// The less checked of two (the first on a tie).
    pub fn weaker(a: &Checked, b: &Checked) -> Checked {
        if b.rank() < a.rank() {
            b.clone()
        } else {
            a.clone()
        }
    }

    fn parse(s: &str) -> Option<Checked> {
        match s.trim() {
            "text" => Some(Checked::Text),
            "abstract" => Some(Checked::Abstract),
            "unchecked" => Some(Checked::Unchecked),
            other => {
                let named = |prefix: &str| other.strip_prefix(prefix).map(str::trim).filter(|which| !which.is_empty()).map(str::to_string);
                named("secondary:").map(Checked::Secondary).or_else(|| named("transcription:").map(Checked::Transcription))
            }
        }
    }
}

impl std::fmt::Display for Checked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Checked::Text => write!(f, "text"),
            Checked::Abstract => write!(f, "abstract"),
            Checked::Secondary(which) => write!(f, "secondary: {which}"),
            Checked::Transcription(which) => write!(f, "transcription: {which}"),
            Checked::Unchecked => write!(f, "unchecked"),
        }
    }
}

impl From<Checked> for String {
    fn from(c: Checked) -> String {
        c.to_string()
    }
}

/// The uncertainty of a published value, one standard uncertainty in its unit.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "basis", rename_all = "snake_case")]
pub enum Uncertainty {
    /// Stated by the source (a standard error, an instrument's uncertainty):
    /// `what` says which.
    Stated { u: f64, what: String },
    /// The source states none: half a unit of the last published digit
    /// (`resolution`), taken as uniform, u = resolution/√12. A lower bound
    /// on the real uncertainty, never a measurement's own.
    Rounding { u: f64, resolution: f64 },
}

impl Uncertainty {
    pub fn u(&self) -> f64 {
        match self {
            Uncertainty::Stated { u, .. } | Uncertainty::Rounding { u, .. } => *u,
        }
    }
    /// Stated by the source (not rounding alone).
    pub fn is_stated(&self) -> bool {
        matches!(self, Uncertainty::Stated { .. })
    }
    /// The same basis at another size (a conversion or a propagation).
    fn with_u(&self, u: f64) -> Uncertainty {
        match self {
            Uncertainty::Stated { what, .. } => Uncertainty::Stated { u, what: what.clone() },
            Uncertainty::Rounding { resolution, .. } => Uncertainty::Rounding { u, resolution: *resolution },
        }
    }
    /// The combination of two relative uncertainties in quadrature (a ratio
    /// or a product): stated only if both are.
    fn combine(a: &Uncertainty, b: &Uncertainty, u: f64) -> Uncertainty {
        match (a, b) {
            (Uncertainty::Stated { what: x, .. }, Uncertainty::Stated { what: y, .. }) => {
                Uncertainty::Stated { u, what: format!("{x}; {y}, in quadrature") }
            }
            _ => Uncertainty::Rounding { u, resolution: f64::NAN },
        }
    }
    /// How the page describes it.
    pub fn describe(&self) -> String {
        match self {
            Uncertainty::Stated { what, .. } => format!("stated: {what}"),
            Uncertainty::Rounding { resolution, .. } if resolution.is_finite() => {
                format!("rounding of the published {} only (a lower bound)", crate::short(*resolution))
            }
            Uncertainty::Rounding { .. } => "rounding of the published digits only (a lower bound)".into(),
        }
    }
}

/// Units a value may be published in; [`Unit::to_si`] converts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Unit {
    #[serde(rename = "s")]
    Second,
    #[serde(rename = "ms")]
    Millisecond,
    #[serde(rename = "m")]
    Metre,
    #[serde(rename = "cm")]
    Centimetre,
    #[serde(rename = "mm")]
    Millimetre,
    #[serde(rename = "N")]
    Newton,
    #[serde(rename = "kN")]
    Kilonewton,
    #[serde(rename = "m/s")]
    MetrePerSecond,
    #[serde(rename = "rad/s")]
    RadianPerSecond,
    #[serde(rename = "rev/s")]
    RevolutionPerSecond,
    #[serde(rename = "g")]
    Gram,
    #[serde(rename = "kg")]
    Kilogram,
    #[serde(rename = "atm")]
    Atmosphere,
    /// Dimensionless (Reynolds numbers, coefficients, ratios, counts).
    #[serde(rename = "1")]
    One,
}

impl Unit {
    /// The SI unit a value converts to.
    pub fn si(self) -> &'static str {
        match self {
            Unit::Second | Unit::Millisecond => "s",
            Unit::Metre | Unit::Centimetre | Unit::Millimetre => "m",
            Unit::Newton | Unit::Kilonewton => "N",
            Unit::MetrePerSecond => "m/s",
            Unit::RadianPerSecond | Unit::RevolutionPerSecond => "rad/s",
            Unit::Gram | Unit::Kilogram => "kg",
            Unit::Atmosphere => "Pa",
            Unit::One => "1",
        }
    }

    /// The value in [`Unit::si`].
    pub fn to_si(self, value: f64) -> f64 {
        // Divide for the sub-units: 9 ms is then exactly the double 9e-3.
        match self {
            Unit::Millisecond | Unit::Millimetre | Unit::Gram => value / 1e3,
            Unit::Centimetre => value / 1e2,
            Unit::Kilonewton => value * 1e3,
            Unit::RevolutionPerSecond => value * std::f64::consts::TAU,
            Unit::Atmosphere => value * 101_325.0,
            _ => value,
        }
    }
}

/// One citation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Source {
    pub key: String,
    /// "Surname, I., Surname, I. & Surname, I."
    pub authors: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub year: Option<u16>,
    /// Why the year is missing, when it is.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub year_note: Option<String>,
    pub title: String,
    /// Journal, book or proceedings.
    pub container: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub volume: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pages: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doi: Option<String>,
    /// Where the copy that was read is (a web address), when one was read.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub read_at: Option<String>,
    /// How far the citation itself (volume, pages, authors) was confirmed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub citation_note: Option<String>,
}

impl Source {
    /// "Authors (year). Title. Container volume, pages. doi:…"
    pub fn citation(&self) -> String {
        let year = self.year.map_or_else(|| "n.d.".to_string(), |y| y.to_string());
        let mut s = format!("{} ({year}). {}. {}", self.authors, self.title, self.container);
        if let Some(v) = &self.volume {
            s.push_str(&format!(" {v}"));
        }
        if let Some(p) = &self.pages {
            s.push_str(&format!(", {p}"));
        }
        s.push('.');
        if let Some(d) = &self.doi {
            s.push_str(&format!(" doi:{d}"));
        }
        s
    }
}

/// One `[[measurement]]` table as written, before [`Measurements::check`].
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeasurementEntry {
    pub key: String,
    pub quantity: String,
    #[serde(default)]
    pub value: Option<f64>,
    #[serde(default)]
    pub range: Option<[f64; 2]>,
    #[serde(default)]
    pub spread: Option<f64>,
    #[serde(default)]
    pub uncertainty: Option<f64>,
    #[serde(default)]
    pub uncertainty_basis: Option<String>,
    #[serde(default)]
    pub resolution: Option<f64>,
    #[serde(default)]
    pub claim: Option<String>,
    pub unit: Unit,
    pub conditions: String,
    pub source: String,
    #[serde(default)]
    pub cites: Vec<String>,
    pub location: String,
    pub checked: String,
    #[serde(default)]
    pub note: Option<String>,
}

/// One published number (or range, or claim in words), as published.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measurement {
    pub key: String,
    pub quantity: String,
    /// A single published value (a mean when `spread` is given).
    pub value: Option<f64>,
    /// A published range [low, high].
    pub range: Option<[f64; 2]>,
    /// One standard deviation of a population (players, kicks, balls), same
    /// unit, when published with the value: not a measurement uncertainty.
    pub spread: Option<f64>,
    /// The value's uncertainty, same unit (stated, or the published rounding).
    pub uncertainty: Option<Uncertainty>,
    /// A published statement without a number (a trend, a sign).
    pub claim: Option<String>,
    pub unit: Unit,
    /// Kick type, speeds, subjects, ball.
    pub conditions: String,
    /// Key of the [`Source`] the number was read in.
    pub source: String,
    /// Keys of the works that source attributes the number to.
    pub cites: Vec<String>,
    /// Table, figure, page, section or abstract.
    pub location: String,
    pub checked: Checked,
    pub note: Option<String>,
}

impl Measurement {
    /// [low, high] in SI: the range, value ± spread, or the value itself.
    pub fn interval_si(&self) -> Option<[f64; 2]> {
        let [lo, hi] = match (self.value, self.range, self.spread) {
            (_, Some(r), _) => r,
            (Some(v), None, Some(s)) => [v - s, v + s],
            (Some(v), None, None) => [v, v],
            (None, None, _) => return None,
        };
        Some([self.unit.to_si(lo), self.unit.to_si(hi)])
    }

    /// The midpoint of [`Measurement::interval_si`].
    pub fn midpoint_si(&self) -> Option<f64> {
        self.interval_si().map(|[lo, hi]| 0.5 * (lo + hi))
    }

    /// [`Measurement::uncertainty`] in SI.
    pub fn uncertainty_si(&self) -> Option<Uncertainty> {
        self.uncertainty.as_ref().map(|x| x.with_u(self.unit.to_si(x.u())))
    }
}

/// The smallest file of the measurements' form: one source, one
/// measurement. The tests of this module and of kick-store's reader start
/// from it.
#[doc(hidden)]
pub const MINIMAL_FILE: &str = r#"
[[source]]
key = "a"
authors = "A, B."
year = 2000
title = "T"
container = "J"
[[measurement]]
key = "t"
quantity = "contact time"
range = [9.0, 14.0]
unit = "ms"
conditions = "instep"
source = "a"
location = "abstract"
checked = "secondary: B (2001), p. 2"
"#;

/// The parsed, checked data file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measurements {
    /// The name errors give (the path it was read from).
    pub file: String,
    pub sources: Vec<Source>,
    pub measurements: Vec<Measurement>,
}

impl Measurements {
    /// Check the tables read from `file` (the name errors give): keys unique, every measurement with a known source,
    /// its cited works known, exactly one of value/range (or a claim alone),
    /// finite numbers, low ≤ high, a recognised check status, and every
    /// source a citation (authors, title, container, and a year or why not).
    pub fn check(file: &str, sources: Vec<Source>, entries: Vec<MeasurementEntry>) -> Result<Measurements, MeasurementError> {
        let invalid = |key: &str, message: String| MeasurementError::Invalid { file: file.to_string(), key: key.to_string(), message };
        let mut source_keys = BTreeSet::new();
        for s in &sources {
            if !source_keys.insert(s.key.as_str()) {
                return Err(invalid(&s.key, "source key appears twice".into()));
            }
            for (field, v) in [("authors", &s.authors), ("title", &s.title), ("container", &s.container)] {
                if v.trim().is_empty() {
                    return Err(invalid(&s.key, format!("source has an empty `{field}`")));
                }
            }
            if s.year.is_none() && s.year_note.as_deref().is_none_or(|n| n.trim().is_empty()) {
                return Err(invalid(&s.key, "source has no `year` and no `year_note` saying why".into()));
            }
        }
        let mut keys = BTreeSet::new();
        let mut measurements = Vec::with_capacity(entries.len());
        for m in entries {
            let key = m.key.as_str();
            if !keys.insert(m.key.clone()) {
                return Err(invalid(key, "measurement key appears twice".into()));
            }
            if !source_keys.contains(m.source.as_str()) {
                return Err(invalid(key, format!("source `{}` is not a [[source]] key", m.source)));
            }
            if let Some(c) = m.cites.iter().find(|c| !source_keys.contains(c.as_str())) {
                return Err(invalid(key, format!("cited work `{c}` is not a [[source]] key")));
            }
            match (m.value, m.range, &m.claim) {
                (Some(_), Some(_), _) => return Err(invalid(key, "give `value` or `range`, not both".into())),
                (None, None, None) => return Err(invalid(key, "give a `value`, a `range` or a `claim`".into())),
                _ => {}
            }
            for v in m.value.iter().chain(m.range.iter().flatten()) {
                if !v.is_finite() {
                    return Err(invalid(key, format!("{v} is not finite")));
                }
            }
            if let Some([lo, hi]) = m.range {
                if lo > hi {
                    return Err(invalid(key, format!("range [{lo}, {hi}]: low above high")));
                }
            }
            if let Some(s) = m.spread {
                if !(s.is_finite() && s > 0.0) || m.value.is_none() {
                    return Err(invalid(key, format!("spread {s}: must be finite, > 0 and go with a `value`")));
                }
            }
            let uncertainty = match (m.uncertainty, m.uncertainty_basis.as_deref(), m.resolution) {
                (None, None, None) => None,
                (_, _, _) if m.value.is_none() => {
                    return Err(invalid(key, "`uncertainty` and `resolution` go with a single `value`, not a range or a claim".into()))
                }
                (Some(u), Some(what), None) if u.is_finite() && u > 0.0 && !what.trim().is_empty() => {
                    Some(Uncertainty::Stated { u, what: what.trim().to_string() })
                }
                (Some(u), _, None) if !(u.is_finite() && u > 0.0) => {
                    return Err(invalid(key, format!("uncertainty {u}: must be finite and > 0")))
                }
                (Some(_), _, None) => {
                    return Err(invalid(key, "`uncertainty` needs an `uncertainty_basis` saying what the source states".into()))
                }
                (None, None, Some(r)) if r.is_finite() && r > 0.0 => Some(Uncertainty::Rounding { u: r / 12f64.sqrt(), resolution: r }),
                (None, None, Some(r)) => return Err(invalid(key, format!("resolution {r}: must be finite and > 0"))),
                (None, Some(_), None) => return Err(invalid(key, "`uncertainty_basis` without an `uncertainty`".into())),
                (_, _, Some(_)) => return Err(invalid(key, "give a stated `uncertainty` or the published `resolution`, not both".into())),
            };
            for (field, v) in [("quantity", &m.quantity), ("conditions", &m.conditions), ("location", &m.location)] {
                if v.trim().is_empty() {
                    return Err(invalid(key, format!("empty `{field}`")));
                }
            }
            let checked = Checked::parse(&m.checked).ok_or_else(|| {
                invalid(
                    key,
                    format!(
                        "checked = \"{}\": expected \"text\", \"abstract\", \"secondary: <which>\", \"transcription: <which>\" \
                         or \"unchecked\"",
                        m.checked
                    ),
                )
            })?;
            measurements.push(Measurement {
                key: m.key,
                quantity: m.quantity,
                value: m.value,
                range: m.range,
                spread: m.spread,
                uncertainty,
                claim: m.claim,
                unit: m.unit,
                conditions: m.conditions,
                source: m.source,
                cites: m.cites,
                location: m.location,
                checked,
                note: m.note,
            });
        }
        Ok(Measurements { file: file.to_string(), sources, measurements })
    }

    /// The measurement `key`; `needed_by` names the validation asking, for the error.
    pub fn get(&self, key: &str, needed_by: &'static str) -> Result<&Measurement, MeasurementError> {
        self.measurements.iter().find(|m| m.key == key).ok_or_else(|| MeasurementError::Missing {
            file: self.file.clone(),
            key: key.to_string(),
            needed_by,
        })
    }

    pub fn source(&self, key: &str) -> Option<&Source> {
        self.sources.iter().find(|s| s.key == key)
    }

    /// The measurement `key` with a number, summarised in SI for a comparison.
    pub fn measured(&self, key: &str, needed_by: &'static str) -> Result<Measured, MeasurementError> {
        let m = self.get(key, needed_by)?;
        let [low, high] = m.interval_si().ok_or_else(|| MeasurementError::NoValue {
            file: self.file.clone(),
            key: key.to_string(),
            what: "a claim in words only",
            needed_by,
        })?;
        Ok(Measured {
            key: m.key.clone(),
            low: Some(low),
            high: Some(high),
            uncertainty: m.uncertainty_si(),
            unit: m.unit.si(),
            source: m.source.clone(),
            checked: m.checked.clone(),
        })
    }

    /// A measurement that is a claim in words (any number it has is ignored).
    pub fn claimed(&self, key: &str, needed_by: &'static str) -> Result<Measured, MeasurementError> {
        let m = self.get(key, needed_by)?;
        Ok(Measured {
            key: m.key.clone(),
            low: None,
            high: None,
            uncertainty: None,
            unit: m.unit.si(),
            source: m.source.clone(),
            checked: m.checked.clone(),
        })
    }
}

/// The measured side of a comparison, in SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measured {
    /// The measurement's key (or `a/b` for a ratio of two).
    pub key: String,
    pub low: Option<f64>,
    pub high: Option<f64>,
    /// The uncertainty of a single value (low = high), in `unit`.
    pub uncertainty: Option<Uncertainty>,
    pub unit: &'static str,
    /// Key of the source (or `a/b`).
    pub source: String,
    /// The weaker of the two checks for a ratio.
    pub checked: Checked,
}

impl Measured {
    /// a/b of two single values (bounds divided crosswise for ranges), dimensionless.
    pub fn ratio(a: &Measured, b: &Measured) -> Option<Measured> {
        let (al, ah, bl, bh) = (a.low?, a.high?, b.low?, b.high?);
        if bl <= 0.0 || bh <= 0.0 {
            return None;
        }
        let weaker = Checked::weaker(&a.checked, &b.checked);
        let uncertainty = match (&a.uncertainty, &b.uncertainty) {
            (Some(ua), Some(ub)) if al == ah && bl == bh => {
                let r = al / bl;
                Some(Uncertainty::combine(ua, ub, r * ((ua.u() / al).powi(2) + (ub.u() / bl).powi(2)).sqrt()))
            }
            _ => None,
        };
        Some(Measured {
            key: format!("{}/{}", a.key, b.key),
            low: Some(al / bh),
            high: Some(ah / bl),
            uncertainty,
            unit: "1",
            source: if a.source == b.source { a.source.clone() } else { format!("{}/{}", a.source, b.source) },
            checked: weaker,
        })
    }

    /// This interval times a dimensionless measured factor (bounds multiplied
    /// low by low, high by high), in this unit.
    pub fn scaled_by(&self, factor: &Measured) -> Option<Measured> {
        let (l, h, fl, fh) = (self.low?, self.high?, factor.low?, factor.high?);
        if factor.unit != "1" || fl < 0.0 {
            return None;
        }
        let weaker = Checked::weaker(&self.checked, &factor.checked);
        Some(Measured {
            key: format!("{}*{}", self.key, factor.key),
            low: Some(l * fl),
            high: Some(h * fh),
            uncertainty: None,
            unit: self.unit,
            source: if self.source == factor.source { self.source.clone() } else { format!("{}*{}", self.source, factor.source) },
            checked: weaker,
        })
    }

    pub fn midpoint(&self) -> Option<f64> {
        Some(0.5 * (self.low? + self.high?))
    }

    /// A single value (not a range, not a claim).
    pub fn is_point(&self) -> bool {
        matches!((self.low, self.high), (Some(lo), Some(hi)) if lo == hi)
    }
}

/// One row of a validation: a model number set beside a measured one.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    pub quantity: String,
    pub measured: Measured,
    /// The model's number, in `measured.unit`.
    pub model: f64,
    /// model / measured midpoint (None for a claim in words).
    pub ratio: Option<f64>,
    /// How far the model lies outside [low, high]: model − high above,
    /// model − low below, 0 inside (None for a claim in words).
    pub outside: Option<f64>,
    /// (model − measured)/u for a single value with an uncertainty.
    pub z: Option<f64>,
    /// Conditions of the model run and why it agrees or misses.
    pub note: String,
}

impl Comparison {
    pub fn new(quantity: impl Into<String>, measured: Measured, model: f64, note: impl Into<String>) -> Comparison {
        let ratio = measured.midpoint().map(|mid| model / mid);
        let outside = match (measured.low, measured.high) {
            (Some(lo), Some(hi)) => Some(if model > hi {
                model - hi
            } else if model < lo {
                model - lo
            } else {
                0.0
            }),
            _ => None,
        };
        let z = match (&measured.uncertainty, measured.is_point()) {
            (Some(u), true) => measured.midpoint().map(|m| (model - m) / u.u()),
            _ => None,
        };
        Comparison { quantity: quantity.into(), measured, model, ratio, outside, z, note: note.into() }
    }

    /// Inside the measured interval (bounds included).
    pub fn agrees(&self) -> Option<bool> {
        self.outside.map(|o| o == 0.0)
    }
}

/// One line: quantity, measured [low, high] unit, model, ratio, miss, key and check.
impl std::fmt::Display for Comparison {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let m = &self.measured;
        match (m.low, m.high) {
            (Some(lo), Some(hi)) if lo == hi => write!(f, "{}: measured {lo:.4e} {}", self.quantity, m.unit)?,
            (Some(lo), Some(hi)) => write!(f, "{}: measured [{lo:.4e}, {hi:.4e}] {}", self.quantity, m.unit)?,
            _ => write!(f, "{}: measured (a claim in words)", self.quantity)?,
        }
        write!(f, ", model {:.4e}", self.model)?;
        if let (Some(r), Some(o)) = (self.ratio, self.outside) {
            write!(f, ", ratio {r:.3}, outside {o:+.3e}")?;
        }
        write!(f, " [{}; {}]", m.key, m.checked)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tables as kick-store's reader parses them (TOML is only a test
    /// dependency here), then [`Measurements::check`].
    fn parse(text: &str, file: &str) -> Result<Measurements, MeasurementError> {
        #[derive(Deserialize)]
        struct Tables {
            #[serde(default)]
            source: Vec<Source>,
            #[serde(default)]
            measurement: Vec<MeasurementEntry>,
        }
        let t: Tables = toml::from_str(text).unwrap_or_else(|e| panic!("{e}"));
        Measurements::check(file, t.source, t.measurement)
    }

    const MINIMAL: &str = MINIMAL_FILE;

    #[test]
    fn units_convert_to_si() {
        let m = parse(MINIMAL, "x.toml").unwrap();
        let t = m.get("t", "test").unwrap();
        assert_eq!(t.interval_si(), Some([9.0e-3, 14.0e-3]));
        assert_eq!(t.checked, Checked::Secondary("B (2001), p. 2".into()));
        assert_eq!(Unit::RevolutionPerSecond.to_si(1.0), std::f64::consts::TAU);
        assert_eq!(Unit::Atmosphere.to_si(1.0), 101_325.0);
    }

    #[test]
    fn errors_name_the_file_and_the_key() {
        let bad_source = MINIMAL.replace("source = \"a\"", "source = \"zz\"");
        let e = parse(&bad_source, "x.toml").unwrap_err().to_string();
        assert!(e.contains("x.toml") && e.contains("`t`") && e.contains("zz"), "{e}");
        let both = MINIMAL.replace("range = [9.0, 14.0]", "range = [9.0, 14.0]\nvalue = 10.0");
        let e = parse(&both, "x.toml").unwrap_err().to_string();
        assert!(e.contains("`t`") && e.contains("not both"), "{e}");
        let status = MINIMAL.replace("secondary: B (2001), p. 2", "maybe");
        let e = parse(&status, "x.toml").unwrap_err().to_string();
        assert!(e.contains("`t`") && e.contains("maybe"), "{e}");
        let reversed = MINIMAL.replace("[9.0, 14.0]", "[14.0, 9.0]");
        assert!(parse(&reversed, "x.toml").unwrap_err().to_string().contains("low above high"));
        let no_year = MINIMAL.replace("year = 2000\n", "");
        assert!(parse(&no_year, "x.toml").unwrap_err().to_string().contains("`a`"));
        let m = parse(MINIMAL, "x.toml").unwrap();
        let e = m.get("missing", "the 1D contact").unwrap_err().to_string();
        assert!(e.contains("missing") && e.contains("the 1D contact"), "{e}");
    }

    #[test]
    fn comparison_measures_the_miss_from_the_nearest_bound() {
        let m = parse(MINIMAL, "x.toml").unwrap();
        let measured = m.measured("t", "test").unwrap();
        let below = Comparison::new("t", measured.clone(), 5.0e-3, "");
        assert!((below.outside.unwrap() - (5.0e-3 - 9.0e-3)).abs() < 1e-18);
        assert!((below.ratio.unwrap() - 5.0 / 11.5).abs() < 1e-15);
        assert_eq!(Comparison::new("t", measured.clone(), 0.010, "").agrees(), Some(true));
        assert!((Comparison::new("t", measured, 0.020, "").outside.unwrap() - 0.006).abs() < 1e-15);
    }

    /// A stated uncertainty is kept with what the source states; a published
    /// value without one gets its rounding, resolution/√12, marked as such;
    /// a ratio of two values combines their relative uncertainties in
    /// quadrature; z is (model − value)/u.
    #[test]
    fn uncertainties_convert_propagate_and_normalise() {
        let two = MINIMAL.to_string()
            + r#"
[[measurement]]
key = "v"
quantity = "ball speed"
value = 13.0
resolution = 0.1
unit = "m/s"
conditions = "c"
source = "a"
location = "abstract"
checked = "abstract"
[[measurement]]
key = "f"
quantity = "foot speed"
value = 9.1
resolution = 0.1
unit = "m/s"
conditions = "c"
source = "a"
location = "abstract"
checked = "abstract"
[[measurement]]
key = "d"
quantity = "drift"
value = 2.0
uncertainty = 5.0
uncertainty_basis = "standard error of the mean of 10 trials"
unit = "cm"
conditions = "c"
source = "a"
location = "table 1"
checked = "text"
"#;
        let m = parse(&two, "x.toml").unwrap();
        let v = m.measured("v", "test").unwrap();
        let u = v.uncertainty.clone().unwrap();
        assert!(!u.is_stated() && (u.u() - 0.1 / 12f64.sqrt()).abs() < 1e-15, "{u:?}");
        assert!(u.describe().contains("lower bound"));
        let d = m.measured("d", "test").unwrap();
        let ud = d.uncertainty.clone().unwrap();
        assert!(ud.is_stated() && (ud.u() - 0.05).abs() < 1e-15, "{ud:?}");
        // 13.0/9.1 with both rounded to 0.1.
        let ratio = Measured::ratio(&v, &m.measured("f", "test").unwrap()).unwrap();
        let r = 13.0 / 9.1;
        let expected = r * ((0.1 / 12f64.sqrt() / 13.0).powi(2) + (0.1 / 12f64.sqrt() / 9.1).powi(2)).sqrt();
        assert!((ratio.uncertainty.as_ref().unwrap().u() - expected).abs() < 1e-15);
        let c = Comparison::new("ratio", ratio, 1.5, "");
        assert!((c.z.unwrap() - (1.5 - r) / expected).abs() < 1e-9);
        // A range has no z, whatever the model.
        assert_eq!(Comparison::new("t", m.measured("t", "test").unwrap(), 0.02, "").z, None);
        // Refusals name the key.
        for (from, to, says) in [
            ("resolution = 0.1\nunit = \"m/s\"\nconditions = \"c\"\nsource = \"a\"\nlocation = \"abstract\"\nchecked = \"abstract\"\n[[measurement]]\nkey = \"f\"", "resolution = -1.0\nunit = \"m/s\"\nconditions = \"c\"\nsource = \"a\"\nlocation = \"abstract\"\nchecked = \"abstract\"\n[[measurement]]\nkey = \"f\"", "resolution -1"),
            ("uncertainty_basis = \"standard error of the mean of 10 trials\"\n", "", "needs an `uncertainty_basis`"),
            ("uncertainty = 5.0\n", "", "without an `uncertainty`"),
        ] {
            let bad = two.replace(from, to);
            assert_ne!(bad, two, "{from}");
            let e = parse(&bad, "x.toml").unwrap_err().to_string();
            assert!(e.contains(says), "{e}");
        }
        let on_range = MINIMAL.replace("range = [9.0, 14.0]", "range = [9.0, 14.0]\nresolution = 1.0");
        assert!(parse(&on_range, "x.toml").unwrap_err().to_string().contains("single `value`"));
    }
}
