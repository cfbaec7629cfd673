//! The `[flight]` table of an experiment (1D or 3D): flight outcomes on
//! every row.
//!
//! ```toml
//! [flight]                 # kick-flight's declared names (`kick flight --help`)
//! launch_angle = 15.0      # 1D only, required there: the 1D kick has no direction
//! distance = 25.0          # crossing plane x = d, m (optional)
//! distances = [9.15, 25.0] # or several planes, each located in the one solve
//! drag_coefficient = 0.2   # optional: constants instead of the models
//! air_density = 1.2
//! ```
//!
//! The kick sets the launch ([`crate::flight::After::sets`]): a 1D kick its
//! exit speed and ball mass, a 3D kick its launch velocity, spin, ball and g;
//! those keys are refused at their line, as are unknown keys and invalid values.
//! With `distances` the crossing columns carry the plane's index
//! (`crossing_height_0`, ...; `kick_flight::plane_columns`) and the set
//! records `distance_0`, `distance_1`, ...

use super::{ExperimentError, Locator};
use crate::flight::FlightPlan;
use kick_flight::{Flight, FlightError, FlightParameter, FlightSpec};
use toml::Spanned;

/// The key of several crossing planes.
pub(super) const DISTANCES: &str = "distances";

/// Which kick the flight follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum After {
    OneD,
    ThreeD,
}

/// The byte span of `key = ...` inside `[table]`.
pub(super) fn key_span(text: &str, table: &str, key: &str) -> Option<std::ops::Range<usize>> {
    let mut offset = 0;
    let mut inside = false;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim();
        if trimmed.starts_with('[') {
            inside = trimmed == format!("[{table}]");
        } else if inside && trimmed.split_once('=').is_some_and(|(k, _)| k.trim() == key) {
            let indent = line.len() - line.trim_start().len();
            return Some(offset + indent..offset + indent + key.len());
        }
        offset += line.len();
    }
    None
}

/// Check the `[flight]` table (`None`: no flight outcomes).
pub(super) fn parse(
    at: &Locator,
    text: &str,
    raw: Option<&Spanned<toml::Table>>,
    after: After,
) -> Result<Option<FlightPlan>, ExperimentError> {
    let Some(raw) = raw else { return Ok(None) };
    let located = |name: &str, message: String| {
        let span = key_span(text, "flight", name).unwrap_or(raw.span());
        at.error(span, &format!("flight.{name}"), message)
    };
    let mut table = raw.get_ref().clone();
    let distances = match table.remove(DISTANCES) {
        None => None,
        Some(value) => {
            let list = value.as_array().and_then(|a| a.iter().map(|v| v.as_float().or(v.as_integer().map(|i| i as f64))).collect());
            Some(list.ok_or_else(|| located(DISTANCES, "expected a list of numbers, m (the crossing planes x = d)".into()))?)
        }
    };
    let spec: FlightSpec = toml::Value::Table(table).try_into().map_err(|e: toml::de::Error| {
        let message = e.message().trim().to_string();
        // An unknown key's name, to point at its line.
        let key = message.split('`').nth(1).unwrap_or("").to_string();
        let valid: Vec<&'static str> = FlightParameter::ALL.iter().map(|p| p.name()).chain([DISTANCES]).collect();
        let message = if message.starts_with("unknown field") { kick_core::parameters::unknown_key(&key, &valid) } else { message };
        located(&key, message)
    })?;
    let (kick, by) = match after {
        After::OneD => (crate::flight::After::Kick1d, "the 1D kick (its exit speed along launch_angle, no spin, its ball mass)"),
        After::ThreeD => (crate::flight::After::Kick3d, "the 3D kick (its launch velocity and spin, its ball, g)"),
    };
    if let Some(p) = FlightParameter::ALL.into_iter().find(|&p| kick.sets(p) && spec.is_set(p)) {
        return Err(located(p.name(), format!("set by {by}; remove it from [flight]")));
    }
    // Validate once against a stand-in launch, so a bad value names its key
    // before any kick is solved.
    let checked = match after {
        After::OneD => {
            if spec.launch_angle.is_none() {
                return Err(at.error(raw.span(), "flight.launch_angle", "a 1D kick has no direction: give launch_angle (deg) in [flight]"));
            }
            FlightSpec { speed: Some(1.0), ..spec }.build()
        }
        After::ThreeD => Flight::from_launch([1.0, 0.0, 1.0], [0.0; 3], &spec),
    };
    checked.map_err(|e| {
        let name = match &e {
            FlightError::InvalidParameter { name, .. }
            | FlightError::Missing { name }
            | FlightError::WrongLength { name, .. }
            | FlightError::TooMany { name, .. } => *name,
            FlightError::Conflict { second, .. } => *second,
            _ => "",
        };
        located(name, e.to_string())
    })?;
    match distances {
        None => Ok(Some(FlightPlan::new(spec))),
        Some(list) => FlightPlan::planes(spec, list).map(Some).map_err(|e| {
            let name = if matches!(e, FlightError::Conflict { .. }) { "distance" } else { DISTANCES };
            located(name, e.to_string().replace("`distance`", if name == DISTANCES { "`distances`" } else { "`distance`" }))
        }),
    }
}

/// The flight parameters given in `[base]` (every declared parameter is a
/// `[base]` key): set on the `[flight]` table's plan, refused without one,
/// when `[flight]` gives the key too, or when the kick sets it.
pub(super) fn with_base(
    at: &Locator,
    text: &str,
    plan: Option<FlightPlan>,
    base: Option<&super::RawBase>,
    after: After,
) -> Result<Option<FlightPlan>, ExperimentError> {
    let Some(base) = base else { return Ok(plan) };
    let given: Vec<_> = base.given().filter(|(p, _, _)| p.level == kick_core::Level::Flight).collect();
    let Some((first, _, span)) = given.first().cloned() else { return Ok(plan) };
    let key = |name: &str| format!("base.{name}");
    let Some(mut plan) = plan else {
        return Err(at.error(
            span,
            &key(first.name),
            format!("`{}` is a flight parameter: add a [flight] table to fly the kicks", first.name),
        ));
    };
    let kick = match after {
        After::OneD => crate::flight::After::Kick1d,
        After::ThreeD => crate::flight::After::Kick3d,
    };
    for (p, value, span) in given {
        let Ok(q) = FlightParameter::from_name(p.name) else { continue };
        if kick.sets(q) {
            return Err(at.error(span, &key(p.name), format!("`{}` is set by the kick; leave it out", p.name)));
        }
        if plan.rest.is_set(q) || (q == FlightParameter::Distance && plan.planes.is_some()) {
            return Err(at.error(span, &key(p.name), "also set in [flight]; set it in one place"));
        }
        plan.rest.set(q, &value.numbers()).map_err(|e| at.error(span.clone(), &key(p.name), e.to_string()))?;
        let checked = match after {
            After::OneD => FlightSpec { speed: Some(1.0), ..plan.rest }.build(),
            After::ThreeD => Flight::from_launch([1.0, 0.0, 1.0], [0.0; 3], &plan.rest),
        };
        checked.map_err(|e| at.error(span, &key(p.name), e.to_string()))?;
    }
    let _ = text;
    Ok(Some(plan))
}

/// `rest` with `parameter` (a flight parameter) at `value`, checked against
/// a stand-in launch of `after`'s kind: a flight axis's value.
pub(super) fn check_axis_value(
    rest: &FlightSpec,
    parameter: &kick_core::ParameterDef,
    value: f64,
    after: After,
) -> Result<(), FlightError> {
    let q = FlightParameter::from_name(parameter.name)?;
    let mut spec = *rest;
    spec.set(q, &[value])?;
    match after {
        After::OneD => FlightSpec { speed: Some(1.0), ..spec }.build().map(drop),
        After::ThreeD => Flight::from_launch([1.0, 0.0, 1.0], [0.0; 3], &spec).map(drop),
    }
}

/// Why a flight parameter cannot be a sweep axis (the error names the key).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FlightAxisError {
    #[error("`{name}` is a flight parameter: add a [flight] table to fly the kicks")]
    NoFlight { name: String },
    #[error("`{name}` is set by the kick")]
    SetByKick { name: String },
    #[error("`{name}` is also set in [flight] or [base]; set it in one place")]
    SetTwice { name: String },
}

/// The flight parameter a sweep axis `name` names: one the kick leaves
/// (`after`), with a `[flight]` table; `None` when `name` is no flight parameter.
pub(super) fn axis_parameter(
    name: &str,
    plan: Option<&FlightPlan>,
    after: After,
) -> Option<Result<&'static kick_core::ParameterDef, FlightAxisError>> {
    let q = FlightParameter::from_name(name).ok()?;
    let kick = match after {
        After::OneD => crate::flight::After::Kick1d,
        After::ThreeD => crate::flight::After::Kick3d,
    };
    Some(match plan {
        None => Err(FlightAxisError::NoFlight { name: name.to_string() }),
        Some(_) if kick.sets(q) => Err(FlightAxisError::SetByKick { name: name.to_string() }),
        Some(plan) if plan.rest.is_set(q) || (q == FlightParameter::Distance && plan.planes.is_some()) => {
            Err(FlightAxisError::SetTwice { name: name.to_string() })
        }
        Some(_) => Ok(q.def()),
    })
}
