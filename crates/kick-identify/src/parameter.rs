//! What a fit can vary: any declared scalar parameter of the model's level
//! — the scenario's, the target restitution of the laws other than the
//! paper's, the shell ball's, and any parameter declared later in the one
//! list (`kick_core::parameters::PARAMETERS` for a kick,
//! `kick_bounce::BOUNCE_PARAMETERS` for a bounce) — and the data's time
//! offset. A parameter becomes fittable by being declared and taken by the
//! level's spec (`SetParameter` and `Scenario::spec` for a kick): the fit
//! reads and sets it by name, its coordinate comes from its valid range.

use crate::IdentifyError;
use kick_bounce::BounceSpec;
use kick_core::parameters::{self, Bound, DefaultValue, Level, ParameterDef, SetParameter, Shape, Valid, Value};
use kick_core::{LawKind, Parameter, Scenario, ScenarioSpec};
use serde::{Serialize, Serializer};

/// One fitted quantity.
#[derive(Debug, Clone, Copy)]
pub enum FitParameter {
    /// One of the eight scenario parameters (Table 1).
    Scenario(Parameter),
    /// e, the target restitution from which every law but the paper's takes
    /// its damping (`Scenario::with_law`).
    Restitution,
    /// t0, s: the data's time of first touch; the model is read at t − t0.
    TimeOffset,
    /// Any other declared scalar parameter of the level, by its declaration
    /// (the shell ball's at a kick; every bounce parameter at a bounce).
    Declared(&'static ParameterDef),
}

/// Equal when they name the same quantity.
impl PartialEq for FitParameter {
    fn eq(&self, other: &FitParameter) -> bool {
        match (self, other) {
            (FitParameter::Scenario(a), FitParameter::Scenario(b)) => a == b,
            (FitParameter::Restitution, FitParameter::Restitution) | (FitParameter::TimeOffset, FitParameter::TimeOffset) => true,
            (FitParameter::Declared(a), FitParameter::Declared(b)) => a.name == b.name,
            _ => false,
        }
    }
}

impl Eq for FitParameter {}

impl std::hash::Hash for FitParameter {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.name().hash(state);
    }
}

/// The model a fit compares the data with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FitLevel {
    /// The 1D kick (`kick simulate`): foot, ball and their contact law.
    #[default]
    Kick,
    /// The ball alone on a rigid plate (`kick bounce`): its normal phase.
    Bounce,
}

impl FitLevel {
    pub const NAMES: &'static str = "kick, bounce";

    pub fn name(self) -> &'static str {
        match self {
            FitLevel::Kick => "kick",
            FitLevel::Bounce => "bounce",
        }
    }

    pub fn from_name(name: &str) -> Result<FitLevel, IdentifyError> {
        match name {
            "kick" => Ok(FitLevel::Kick),
            "bounce" => Ok(FitLevel::Bounce),
            other => Err(IdentifyError::data("level", format!("`{other}`: expected one of {}", FitLevel::NAMES))),
        }
    }
}

/// t0, the one fitted quantity that is not a scenario parameter: declared
/// here as the scenario's are in `kick_core::parameters`.
pub const TIME_OFFSET: ParameterDef = ParameterDef {
    name: "time_offset",
    symbol: "t0",
    unit: "s",
    level: Level::Scenario,
    shape: Shape::Scalar,
    default: DefaultValue::Number(0.0),
    valid: Valid { low: Bound::Unbounded, high: Bound::Unbounded, requirement: "finite" },
    sample: None,
    doc: "Time of first touch in the data; the model is read at t - t0",
};

impl FitParameter {
    /// Every fittable quantity, in the order specifications list them.
    pub const ALL: [FitParameter; 10] = [
        FitParameter::Scenario(Parameter::FootMass),
        FitParameter::Scenario(Parameter::BallMass),
        FitParameter::Scenario(Parameter::FootSpeed),
        FitParameter::Scenario(Parameter::BallSpeed),
        FitParameter::Scenario(Parameter::Stiffness),
        FitParameter::Scenario(Parameter::Damping),
        FitParameter::Scenario(Parameter::Exponent),
        FitParameter::Scenario(Parameter::DriveForce),
        FitParameter::Restitution,
        FitParameter::TimeOffset,
    ];

    /// The declaration: name, unit and valid range.
    pub fn def(self) -> &'static ParameterDef {
        match self {
            FitParameter::Scenario(p) => p.def(),
            FitParameter::Restitution => &parameters::RESTITUTION,
            FitParameter::TimeOffset => &TIME_OFFSET,
            FitParameter::Declared(def) => def,
        }
    }

    /// Name in fit specifications and reports.
    pub fn name(self) -> &'static str {
        self.def().name
    }

    pub fn unit(self) -> &'static str {
        self.def().unit
    }

    /// The kick's quantity called `name` ([`FitParameter::from_name_at`]).
    pub fn from_name(name: &str) -> Result<FitParameter, IdentifyError> {
        FitParameter::from_name_at(FitLevel::Kick, name)
    }

    /// The quantity called `name` at `level`: at a kick one of
    /// [`FitParameter::ALL`] or any other scalar parameter the 1D scenario
    /// takes (`ScenarioSpec::LEVELS`: the shell ball's, and what is declared
    /// there later); at a bounce any scalar of `kick_bounce::BOUNCE_PARAMETERS`.
    pub fn from_name_at(level: FitLevel, name: &str) -> Result<FitParameter, IdentifyError> {
        // A derived default (the boot's, set by the leg) is a number once given.
        let scalar = |p: &&'static ParameterDef| {
            p.shape == Shape::Scalar && matches!(p.default, DefaultValue::Number(_) | DefaultValue::Unset(_) | DefaultValue::Derived(_))
        };
        let found = match level {
            FitLevel::Kick => FitParameter::ALL.into_iter().find(|p| p.name() == name).or_else(|| {
                parameters::at_levels(ScenarioSpec::LEVELS).filter(scalar).find(|p| p.name == name).map(FitParameter::Declared)
            }),
            FitLevel::Bounce => kick_bounce::BOUNCE_PARAMETERS.iter().filter(scalar).find(|p| p.name == name).map(FitParameter::Declared),
        };
        found.ok_or_else(|| {
            let valid = FitParameter::names_at(level);
            IdentifyError::UnknownParameter {
                name: name.to_string(),
                hint: parameters::did_you_mean(&parameters::nearby(name, &valid), &valid),
            }
        })
    }

    /// Every name [`FitParameter::from_name_at`] takes at `level`.
    pub fn names_at(level: FitLevel) -> Vec<&'static str> {
        match level {
            FitLevel::Kick => {
                let mut names: Vec<&'static str> = FitParameter::ALL.map(|p| p.name()).to_vec();
                names.extend(parameters::at_levels(ScenarioSpec::LEVELS).filter(|p| p.shape == Shape::Scalar).map(|p| p.name));
                names.dedup();
                let mut seen = Vec::new();
                names.retain(|n| {
                    if seen.contains(n) {
                        false
                    } else {
                        seen.push(*n);
                        true
                    }
                });
                names
            }
            FitLevel::Bounce => kick_bounce::BOUNCE_PARAMETERS.iter().filter(|p| p.shape == Shape::Scalar).map(|p| p.name).collect(),
        }
    }

    /// The coordinate the optimiser moves in, from the valid range: every
    /// trial point is then valid (log for a quantity bounded below by 0,
    /// logit for one bounded on both sides by 0 and 1).
    pub fn coordinate(self) -> Coordinate {
        let valid = self.def().valid;
        match (valid.low, valid.high) {
            (Bound::Open(0.0) | Bound::Closed(0.0), Bound::Open(1.0) | Bound::Closed(1.0)) => Coordinate::Logit,
            (Bound::Open(0.0) | Bound::Closed(0.0), _) => Coordinate::Log,
            _ => Coordinate::Linear,
        }
    }
}

impl From<Parameter> for FitParameter {
    fn from(p: Parameter) -> Self {
        FitParameter::Scenario(p)
    }
}

impl Serialize for FitParameter {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

/// θ, the optimiser's coordinate of a parameter p.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Coordinate {
    /// θ = p (speeds, drive force, time offset).
    Linear,
    /// θ = ln p (masses, k, c, n: positive).
    Log,
    /// θ = ln(p/(1 − p)) (restitution, in (0, 1)).
    Logit,
}

impl Coordinate {
    /// θ of p; `None` where p is outside the coordinate's domain.
    pub fn theta(self, p: f64) -> Option<f64> {
        let theta = match self {
            Coordinate::Linear => p,
            Coordinate::Log if p > 0.0 => p.ln(),
            Coordinate::Logit if p > 0.0 && p < 1.0 => (p / (1.0 - p)).ln(),
            _ => return None,
        };
        theta.is_finite().then_some(theta)
    }

    /// p of θ.
    pub fn value(self, theta: f64) -> f64 {
        match self {
            Coordinate::Linear => theta,
            Coordinate::Log => theta.exp(),
            Coordinate::Logit => 1.0 / (1.0 + (-theta).exp()),
        }
    }

    /// dp/dθ at p: turns a standard uncertainty in θ into one in p (first order).
    pub fn slope(self, p: f64) -> f64 {
        match self {
            Coordinate::Linear => 1.0,
            Coordinate::Log => p,
            Coordinate::Logit => p * (1.0 - p),
        }
    }

    /// What the domain requires, for error messages.
    pub fn requirement(self) -> &'static str {
        match self {
            Coordinate::Linear => "finite",
            Coordinate::Log => "> 0 (it is fitted as ln p)",
            Coordinate::Logit => "in (0, 1) (it is fitted as ln(e/(1 − e)))",
        }
    }
}

/// A point of the model the data are compared with: the scenario (with its
/// contact law) and the time offset t0 of the data; at the bounce level
/// also the bounce whose normal phase the scenario is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModelPoint {
    /// The 1D contact solved: the kick, or a bounce's normal phase (the ball
    /// as the moving body, the plate as a body of 1e15 kg, its weight the drive).
    pub scenario: Scenario,
    /// t0, s: data time t is model time t − t0.
    pub time_offset: f64,
    /// The bounce's values, at the bounce level.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bounce: Option<BounceSpec>,
}

impl From<Scenario> for ModelPoint {
    fn from(scenario: Scenario) -> Self {
        ModelPoint { scenario, time_offset: 0.0, bounce: None }
    }
}

impl ModelPoint {
    pub fn new(scenario: Scenario, time_offset: f64) -> Result<ModelPoint, IdentifyError> {
        ModelPoint::from(scenario).with(FitParameter::TimeOffset, time_offset)
    }

    /// The bounce `spec` describes, as a model point: its normal phase.
    pub fn bounce(spec: BounceSpec) -> Result<ModelPoint, IdentifyError> {
        let b = spec.build()?;
        let (_, cos) = b.angle.to_radians().sin_cos();
        let scenario = kick_bounce::normal_scenario(&b, b.speed * cos)?;
        // The shell law rides on the scenario (`normal_scenario` gives its scales only).
        let scenario = match b.law {
            kick_bounce::BallLaw::Shell(ball) => scenario.with_shell(ball),
            kick_bounce::BallLaw::Kick { .. } => scenario,
        };
        Ok(ModelPoint { scenario, time_offset: 0.0, bounce: Some(spec) })
    }

    /// The level this point is of.
    pub fn level(&self) -> FitLevel {
        if self.bounce.is_some() {
            FitLevel::Bounce
        } else {
            FitLevel::Kick
        }
    }

    /// The value of `parameter` at this point.
    pub fn get(&self, parameter: FitParameter) -> Result<f64, IdentifyError> {
        match (parameter, &self.bounce) {
            (FitParameter::Declared(def), Some(spec)) => {
                spec.number(def.name).ok_or_else(|| IdentifyError::data(def.name, "no value: give it (it has no default)"))
            }
            (FitParameter::Declared(def), None) => {
                // Read by its declared name from the scenario's spec, else its default.
                let spec = serde_json::to_value(self.scenario.spec()).map_err(|e| IdentifyError::data(def.name, e.to_string()))?;
                match (spec.get(def.name).and_then(|v| v.as_f64()), def.default) {
                    (Some(x), _) => Ok(x),
                    (None, DefaultValue::Number(x)) => Ok(x),
                    // A derived default (the boot's: none on the rigid foot) has no number to start from.
                    (None, DefaultValue::Derived(text)) => {
                        Err(IdentifyError::data(def.name, format!("no finite value to start the fit from: give one (its default: {text})")))
                    }
                    _ => Err(IdentifyError::data(def.name, "no value: give it (it has no default)")),
                }
            }
            (FitParameter::Scenario(p), _) => Ok(self.scenario.get(p)),
            // None exactly for the paper's law.
            (FitParameter::Restitution, _) => self.scenario.restitution_target().ok_or_else(|| {
                self.refusal(parameter, true)
                    .unwrap_or_else(|| IdentifyError::data("restitution", "the scenario has no target restitution"))
            }),
            (FitParameter::TimeOffset, _) => Ok(self.time_offset),
        }
    }

    /// A copy with `parameter` set to `value`, validated (the law kept; a
    /// law other than the paper's recomputes its damping from its target
    /// restitution at the new masses and speeds).
    pub fn with(&self, parameter: FitParameter, value: f64) -> Result<ModelPoint, IdentifyError> {
        match (parameter, &self.bounce) {
            (FitParameter::TimeOffset, _) => {
                if !value.is_finite() {
                    return Err(IdentifyError::data("time_offset", format!("{value}: must be finite")));
                }
                Ok(ModelPoint { time_offset: value, ..*self })
            }
            (_, Some(spec)) => {
                let mut spec = *spec;
                // The impact speed is given one way or the other: a measurement's replaces the start's.
                match parameter.name() {
                    "speed" => spec.unset("drop_height"),
                    "drop_height" => spec.unset("speed"),
                    _ => {}
                }
                spec.set(parameter.name(), Value::Number(value)).map_err(|e| IdentifyError::data(parameter.name(), e.to_string()))?;
                Ok(ModelPoint { time_offset: self.time_offset, ..ModelPoint::bounce(spec)? })
            }
            (FitParameter::Scenario(p), None) => Ok(ModelPoint { scenario: self.scenario.with(p, value)?, ..*self }),
            (FitParameter::Restitution, None) => {
                if let Some(refused) = self.refusal(parameter, true) {
                    return Err(refused);
                }
                let scenario = self.scenario.with_law(self.scenario.law_kind(), Some(value))?;
                Ok(ModelPoint { scenario, ..*self })
            }
            (FitParameter::Declared(def), None) => {
                // Through the scenario's spec: every declared parameter it takes, by name.
                let mut spec = self.scenario.spec();
                spec.set_parameter(def, Value::Number(value)).map_err(|e| IdentifyError::data(def.name, e.to_string()))?;
                Ok(ModelPoint { scenario: spec.build()?, ..*self })
            }
        }
    }

    /// Whether `outcome`, this point's contact, stayed where its law holds
    /// (`kick_core::validity`), as `kick bounce` (the bounce's own ball
    /// radius) and `kick simulate` judge it.
    pub fn check_validity(&self, outcome: &kick_core::Outcome) -> Result<Result<(), kick_core::OutsideValidity>, IdentifyError> {
        match &self.bounce {
            Some(spec) => {
                let radius = spec.build()?.radius;
                Ok(kick_core::validity::check(self.scenario.law_kind(), radius, outcome.max_compression))
            }
            None => Ok(self.scenario.check_validity(outcome)),
        }
    }

    /// Refuse to fit a parameter that does not act on the model's
    /// predictions here (the law, and whether the data include a history):
    /// it would be a flat direction of χ², not an estimate.
    pub fn check_fittable(&self, parameter: FitParameter, has_history: bool) -> Result<(), IdentifyError> {
        match self.refusal(parameter, has_history) {
            Some(refused) => Err(refused),
            None => Ok(()),
        }
    }

    /// Why `parameter` cannot be fitted at this point, if it cannot.
    fn refusal(&self, parameter: FitParameter, has_history: bool) -> Option<IdentifyError> {
        let law = self.scenario.law_kind();
        if let Some(spec) = &self.bounce {
            let name = parameter.name();
            // What the normal phase does not see.
            let reason = match name {
                "angle" | "friction" | "tangential_restitution" | "ball_inertia" => {
                    Some("the fit compares the normal phase (restitution, contact time, peak force, compression), which it does not enter")
                }
                "time_offset" => Some("a bounce fit has no recorded history"),
                _ => None,
            };
            if let Some(reason) = reason {
                return Some(IdentifyError::NotApplicable { parameter: parameter.name(), context: "to a bounce fit".into(), reason });
            }
            // One the law does not take is refused where it is set.
            let value = self.get(parameter).ok()?;
            return self.with(parameter, value).err().map(|e| match e {
                IdentifyError::Model(kick_core::KickError::DoesNotApply { given, reason, .. }) => IdentifyError::NotApplicable {
                    parameter: given,
                    context: format!("to bounce law `{}`", spec.law.unwrap_or(kick_bounce::LawChoice::Shell).name()),
                    reason,
                },
                other => other,
            });
        }
        let (context, reason) = match parameter {
            FitParameter::Scenario(Parameter::Damping) if law != LawKind::PowerLaw => {
                (law, "its damping follows from the target restitution; fit `restitution` instead")
            }
            FitParameter::Scenario(Parameter::Exponent) if law == LawKind::KelvinVoigt => {
                (law, "the law is linear; n only sets its secant stiffness k δ*^(n−1), which `stiffness` already moves")
            }
            FitParameter::Scenario(Parameter::Damping | Parameter::Stiffness | Parameter::Exponent) if law == LawKind::Shell => (
                law,
                "the shell ball takes its stiffness and loss from its own parameters (inflation_pressure, shell_stiffness, shell_damping)",
            ),
            FitParameter::Restitution if law == LawKind::PowerLaw => {
                (law, "the paper's law (Eq. 20) has no target restitution; fit `damping`, or choose another law")
            }
            FitParameter::TimeOffset if !has_history => {
                return Some(IdentifyError::NotApplicable {
                    parameter: parameter.name(),
                    context: "to scalar observations".into(),
                    reason: "a time offset only shifts a recorded history; add a [history]",
                })
            }
            FitParameter::Declared(def) => {
                // A declared parameter acts when setting it builds (the law takes it).
                let fallback = match def.default {
                    DefaultValue::Number(x) => x,
                    _ => 1.0,
                };
                let value = self.get(parameter).unwrap_or(fallback);
                return match self.with(parameter, value) {
                    Err(IdentifyError::Model(kick_core::KickError::DoesNotApply { given, reason, .. })) => {
                        Some(IdentifyError::NotApplicable { parameter: given, context: format!("to contact law `{}`", law.name()), reason })
                    }
                    _ => None,
                };
            }
            _ => return None,
        };
        Some(IdentifyError::NotApplicable { parameter: parameter.name(), context: format!("to contact law `{}`", context.name()), reason })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_invert_and_refuse_their_outside() {
        for (c, p) in [(Coordinate::Linear, -3.5), (Coordinate::Log, 4.2e5), (Coordinate::Logit, 0.662)] {
            let theta = c.theta(p).unwrap();
            assert!((c.value(theta) - p).abs() <= 4.0 * f64::EPSILON * p.abs());
            // dp/dθ against a central difference of value(θ).
            let h = 1e-6;
            let fd = (c.value(theta + h) - c.value(theta - h)) / (2.0 * h);
            assert!((fd - c.slope(p)).abs() <= 1e-8 * c.slope(p).abs(), "{c:?}: {fd} vs {}", c.slope(p));
        }
        assert_eq!(Coordinate::Log.theta(0.0), None);
        assert_eq!(Coordinate::Logit.theta(1.0), None);
        assert_eq!(Coordinate::Logit.theta(0.0), None);
        assert_eq!(Coordinate::Linear.theta(f64::NAN), None);
    }

    /// The coordinates the fits have always used, now derived from the valid ranges.
    #[test]
    fn coordinates_follow_the_valid_ranges() {
        use Parameter::*;
        for p in [FootMass, BallMass, Stiffness, Damping, Exponent] {
            assert_eq!(FitParameter::from(p).coordinate(), Coordinate::Log, "{p:?}");
        }
        for p in [FootSpeed, BallSpeed, DriveForce] {
            assert_eq!(FitParameter::from(p).coordinate(), Coordinate::Linear, "{p:?}");
        }
        assert_eq!(FitParameter::Restitution.coordinate(), Coordinate::Logit);
        assert_eq!(FitParameter::TimeOffset.coordinate(), Coordinate::Linear);
        assert_eq!(FitParameter::Restitution.unit(), "1");
        assert_eq!(FitParameter::TimeOffset.unit(), "s");
    }

    #[test]
    fn names_round_trip() {
        for p in Parameter::ALL.map(FitParameter::from).into_iter().chain([FitParameter::Restitution, FitParameter::TimeOffset]) {
            assert_eq!(FitParameter::from_name(p.name()).unwrap(), p);
        }
        assert!(matches!(FitParameter::from_name("t0"), Err(IdentifyError::UnknownParameter { .. })));
    }
}
