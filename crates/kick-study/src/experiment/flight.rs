//! The `[flight]` table of an experiment (1D or 3D): flight outcomes on
//! every row.
//!
//! ```toml
//! [flight]                 # kick-flight's declared names (`kick flight --help`)
//! launch_angle = 15.0      # 1D only, required there: the 1D kick has no direction
//! distance = 25.0          # crossing plane x = d, m (optional)
//! drag_coefficient = 0.2   # optional: constants instead of the models
//! air_density = 1.2
//! ```
//!
//! The kick sets the launch ([`crate::flight::After::sets`]): a 1D kick its
//! exit speed and ball mass, a 3D kick its launch velocity, spin, ball and g;
//! those keys are refused at their line, as are unknown keys and invalid values.

use super::{ExperimentError, Locator};
use kick_flight::{Flight, FlightError, FlightParameter, FlightSpec};
use toml::Spanned;

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
    raw: Option<&Spanned<FlightSpec>>,
    after: After,
) -> Result<Option<FlightSpec>, ExperimentError> {
    let Some(raw) = raw else { return Ok(None) };
    let spec = *raw.get_ref();
    let located = |name: &str, message: String| {
        let span = key_span(text, "flight", name).unwrap_or(raw.span());
        at.error(span, &format!("flight.{name}"), message)
    };
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
            FlightError::InvalidParameter { name, .. } | FlightError::Missing { name } | FlightError::WrongLength { name, .. } => *name,
            FlightError::Conflict { second, .. } => *second,
            _ => "",
        };
        located(name, e.to_string())
    })?;
    Ok(Some(spec))
}
