//! `kick bounce`: the flags of kick-bounce's declared parameters, one call
//! to [`kick_bounce::run`], the outcome printed.

use crate::flags::FlagSpec;
use kick_bounce::{BounceOutcome, BounceSpec, BOUNCE_PARAMETERS};
use kick_core::parameters::{ParameterDef, Value};
use kick_core::KickError;

impl FlagSpec for BounceSpec {
    const LAW: bool = false;
    fn parameters() -> Vec<&'static ParameterDef> {
        BOUNCE_PARAMETERS.iter().collect()
    }
    fn set(&mut self, parameter: &'static ParameterDef, value: Value) {
        // Flags exist only for declared parameters, with their shapes.
        let _ = BounceSpec::set(self, parameter.name, value);
    }
}

/// `--law NAME`: shell or a law of the kick's family.
pub fn parse_law(name: &str) -> Result<kick_bounce::LawChoice, String> {
    kick_bounce::LawChoice::from_name(name).map_err(|e| e.to_string())
}

/// The outcome, printable.
#[derive(serde::Serialize)]
#[serde(transparent)]
pub struct Report(pub BounceOutcome);

impl kick_study::Printable for Report {
    fn text(&self) -> String {
        self.0.text()
    }
    fn outside_validity(&self) -> Option<String> {
        self.0.outside_validity.as_ref().map(|o| o.to_string())
    }
}

/// Bounce, with a refusal naming the flags the user gave (the library's
/// errors use the bounce's own parameter names, never the kick's 1D ones).
pub fn bounce(spec: &BounceSpec) -> Result<Report, String> {
    kick_bounce::run(spec).map(Report).map_err(|e| {
        let names: Vec<&str> = match &e {
            KickError::InvalidParameter { name, .. } => vec![*name],
            KickError::DoesNotApply { given, .. } => vec![*given],
            KickError::OutOfRange { parameters, .. } => parameters.split(", ").collect(),
            // Resting on the plate: the impact speed given was too low to
            // rebound against the weight, so a weight the user set is named too.
            KickError::Trapped { .. } => {
                let mut names = match spec.build() {
                    Ok(b) if b.drop_height.is_some() => vec!["drop_height"],
                    _ => vec!["speed"],
                };
                names.extend(["ball_mass", "gravity"].into_iter().filter(|n| spec.given(n).is_some()));
                names
            }
            _ => Vec::new(),
        };
        let flags: Vec<String> = names.iter().filter_map(|n| kick_bounce::parameter(n).ok()).map(|p| p.flag()).collect();
        match flags.len() {
            0 => e.to_string(),
            1 => format!("{e} (flag {})", flags[0]),
            _ => format!("{e} (flags {})", flags.join(", ")),
        }
    })
}
