//! Every scenario parameter of the kick model, declared once.
//!
//! Each [`ParameterDef`] in [`PARAMETERS`] gives a parameter's name, symbol,
//! unit, default, valid range (and what the refusal says), sampling range,
//! doc line, model [`Level`] and [`Shape`]. Everything else is derived from
//! that list, never written again by hand:
//!
//! - the name is the TOML key, the HDF5 dataset name under `/parameters` and
//!   the Python keyword; the command-line flag is `--` plus its kebab case
//!   ([`ParameterDef::flag`]), with [`ParameterDef::help`] as its help text;
//! - validation: [`ParameterDef::check`] refuses a value outside
//!   [`ParameterDef::valid`] with a [`KickError::InvalidParameter`] naming it;
//! - random sweeps draw from [`ParameterDef::sample`] ([`SampleRange::draw`]);
//! - unknown names are refused with the nearby valid ones ([`find`]).
//!
//! A spec that takes values by name implements [`SetParameter`]
//! (`ScenarioSpec` for the 1D level, kick-3d's `KickSpec` for 1D and 3D).
//! The flight crate declares its parameters with the same [`ParameterDef`]
//! at [`Level::Flight`] in its own list (`kick_flight::spec::FLIGHT_PARAMETERS`):
//! its `gravity` is g in m/s², where the 3D kick's is a switch, so the two
//! levels keep separate name spaces.

use crate::error::KickError;
use serde::Serialize;

/// The model level a parameter belongs to. A level takes the parameters of
/// the levels below it too (a 3D kick has every 1D parameter).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Level {
    /// The 1D contact (Table 1), `kick simulate`.
    Scenario,
    /// The off-center 3D kick (spin, friction), `kick simulate3d`.
    Kick3d,
    /// The 3D kick's instep surface and contact model (kick-3d's `patch`):
    /// settings of the 3D contact, like the shell ball's of its law; not
    /// columns of result rows (their defaults are the rows' kicks).
    Instep,
    /// The ball's flight after the kick (kick-flight's own list).
    Flight,
    /// The ball alone: the shell law's parameters (kick-core's `shell`) and
    /// a bounce on a rigid plate (kick-bounce's own list).
    Bounce,
    /// The foot behind the contact, 1D and 3D kicks alike: the articulated
    /// leg (kick-core's `leg::foot`) and the boot in series (`boot`).
    /// Settings of the foot, like the shell ball's of its law: not columns
    /// of result rows (recorded with the outcome sets and in `/fixed`).
    Foot,
}

impl Level {
    pub fn name(self) -> &'static str {
        match self {
            Level::Scenario => "1D scenario",
            Level::Kick3d => "3D kick",
            Level::Instep => "3D instep",
            Level::Flight => "flight",
            Level::Bounce => "bounce",
            Level::Foot => "foot",
        }
    }
}

/// How many numbers a parameter takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Shape {
    Scalar,
    /// Three numbers (a flag takes them comma-separated, TOML an array).
    Vector3,
    /// On or off (a flag without a value, a TOML boolean).
    Switch,
}

impl Shape {
    pub fn describe(self) -> &'static str {
        match self {
            Shape::Scalar => "a number",
            Shape::Vector3 => "three numbers",
            Shape::Switch => "true or false",
        }
    }

    /// A value of this shape given where another was wanted (a bool is named as one).
    pub fn found(self) -> &'static str {
        match self {
            Shape::Switch => "a bool (true or false)",
            other => other.describe(),
        }
    }
}

/// One end of a valid range.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Bound {
    /// Any finite value on this side.
    Unbounded,
    /// The value itself is excluded.
    Open(f64),
    /// The value itself is included (`Closed(f64::INFINITY)` admits infinity).
    Closed(f64),
}

/// The values a parameter accepts on its own, and how a refusal says it.
/// Conditions involving other parameters (an offset inside the ball, a foot
/// faster than the ball) are the model's, with their own errors.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Valid {
    pub low: Bound,
    pub high: Bound,
    /// What a refusal says the value "must be".
    pub requirement: &'static str,
}

impl Valid {
    const fn new(low: Bound, high: Bound, requirement: &'static str) -> Valid {
        Valid { low, high, requirement }
    }
    /// Any finite number.
    const FINITE: Valid = Valid::new(Bound::Unbounded, Bound::Unbounded, "finite");
    /// Finite and > 0.
    const POSITIVE: Valid = Valid::new(Bound::Open(0.0), Bound::Unbounded, "finite and > 0");
    /// Finite and >= 0.
    const NON_NEGATIVE: Valid = Valid::new(Bound::Closed(0.0), Bound::Unbounded, "finite and >= 0");
    /// No condition (switches).
    const ANY: Valid = Valid::new(Bound::Unbounded, Bound::Unbounded, "true or false");

    pub fn contains(&self, x: f64) -> bool {
        let low = match self.low {
            Bound::Unbounded => x > f64::NEG_INFINITY,
            Bound::Open(a) => x > a,
            Bound::Closed(a) => x >= a,
        };
        let high = match self.high {
            Bound::Unbounded => x < f64::INFINITY,
            Bound::Open(b) => x < b,
            Bound::Closed(b) => x <= b,
        };
        low && high
    }
}

/// A parameter's value when it is not given.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum DefaultValue {
    Number(f64),
    Vector([f64; 3]),
    /// Switched off.
    Off,
    /// Computed from other parameters, as described.
    Derived(&'static str),
    /// Absent unless given; the text says when it is needed.
    Unset(&'static str),
}

impl DefaultValue {
    /// The default as help text shows it.
    pub fn text(&self) -> String {
        match self {
            DefaultValue::Number(x) => crate::short(*x).to_string(),
            DefaultValue::Vector([a, b, c]) => format!("{},{},{}", crate::short(*a), crate::short(*b), crate::short(*c)),
            DefaultValue::Off => "off".to_string(),
            DefaultValue::Derived(text) | DefaultValue::Unset(text) => (*text).to_string(),
        }
    }
}

/// Spacing of a sampling range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Spacing {
    Linear,
    /// Uniform in log10 of the value.
    Log,
}

/// Where random sweeps draw a parameter from (`kick sweep`), and where grid
/// sweeps span by default.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SampleRange {
    pub spacing: Spacing,
    pub from: f64,
    pub to: f64,
    /// Probability of the value 0 (e.g. no drive) before the range is drawn.
    pub zero_probability: f64,
}

impl SampleRange {
    const fn linear(from: f64, to: f64) -> Option<SampleRange> {
        Some(SampleRange { spacing: Spacing::Linear, from, to, zero_probability: 0.0 })
    }
    const fn log(from: f64, to: f64) -> Option<SampleRange> {
        Some(SampleRange { spacing: Spacing::Log, from, to, zero_probability: 0.0 })
    }

    /// One draw, from uniform numbers in [0, 1) given by `uniform` (one for
    /// the range, one more first when `zero_probability` > 0).
    pub fn draw(&self, uniform: &mut impl FnMut() -> f64) -> f64 {
        if self.zero_probability > 0.0 && uniform() < self.zero_probability {
            return 0.0;
        }
        let between = |a: f64, b: f64, r: f64| a + (b - a) * r;
        match self.spacing {
            Spacing::Linear => between(self.from, self.to, uniform()),
            Spacing::Log => 10f64.powf(between(self.from.log10(), self.to.log10(), uniform())),
        }
    }

    /// One line of text, e.g. `log-uniform 0.5 .. 15`.
    pub fn describe(&self) -> String {
        let spacing = match self.spacing {
            Spacing::Linear => "uniform",
            Spacing::Log => "log-uniform",
        };
        let range = format!("{spacing} {} .. {}", self.from, self.to);
        if self.zero_probability > 0.0 {
            format!("0 with probability {}, else {range}", self.zero_probability)
        } else {
            range
        }
    }
}

/// One declared parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ParameterDef {
    /// snake_case: TOML key, HDF5 column, Python keyword; the flag is its kebab case.
    pub name: &'static str,
    pub symbol: &'static str,
    /// SI unit (`1` for dimensionless, empty for switches).
    pub unit: &'static str,
    pub level: Level,
    pub shape: Shape,
    pub default: DefaultValue,
    /// Accepted values (each component of a vector).
    pub valid: Valid,
    /// Sampling range, where the parameter has one.
    pub sample: Option<SampleRange>,
    /// One line for help texts.
    pub doc: &'static str,
}

impl ParameterDef {
    /// The long flag without its dashes: the name in kebab case.
    pub fn long(&self) -> String {
        self.name.replace('_', "-")
    }

    /// `--` plus the kebab case of the name.
    pub fn flag(&self) -> String {
        format!("--{}", self.long())
    }

    /// Help text: doc, symbol, unit and default, e.g.
    /// `Effective foot mass (Eq. 11): m_f, kg [default: 3]`.
    pub fn help(&self) -> String {
        let unit = match self.unit {
            "" | "1" => String::new(),
            unit => format!(", {unit}"),
        };
        format!("{}: {}{unit} [default: {}]", self.doc, self.symbol, self.default.text())
    }

    /// The value, or a [`KickError::InvalidParameter`] naming this parameter.
    pub fn check(&self, value: f64) -> Result<f64, KickError> {
        if self.valid.contains(value) {
            Ok(value)
        } else {
            Err(KickError::InvalidParameter { name: self.name, value, requirement: self.valid.requirement })
        }
    }

    /// The default of a scalar with a numeric default (for constants).
    pub const fn default_number(&self) -> f64 {
        match self.default {
            DefaultValue::Number(x) => x,
            _ => panic!("parameter without a numeric default"),
        }
    }

    /// The default of a vector with a numeric default (for constants).
    pub const fn default_vector(&self) -> [f64; 3] {
        match self.default {
            DefaultValue::Vector(v) => v,
            _ => panic!("parameter without a vector default"),
        }
    }

    /// Column names of this parameter in result files: the name, or
    /// `name_x`, `name_y`, `name_z` for a vector.
    pub fn columns(&self) -> Vec<String> {
        match self.shape {
            Shape::Scalar | Shape::Switch => vec![self.name.to_string()],
            Shape::Vector3 => ["x", "y", "z"].iter().map(|axis| format!("{}_{axis}", self.name)).collect(),
        }
    }
}

/// A value given for a parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Value {
    Number(f64),
    Vector([f64; 3]),
    Switch(bool),
}

impl Value {
    /// The value as stored in result files and flight specs: one number, a
    /// vector's three, a switch as 0 or 1.
    pub fn numbers(&self) -> Vec<f64> {
        match *self {
            Value::Number(x) => vec![x],
            Value::Vector(v) => v.to_vec(),
            Value::Switch(on) => vec![f64::from(u8::from(on))],
        }
    }

    pub fn shape(&self) -> Shape {
        match self {
            Value::Number(_) => Shape::Scalar,
            Value::Vector(_) => Shape::Vector3,
            Value::Switch(_) => Shape::Switch,
        }
    }
}

/// A name that is not a parameter, or a value of the wrong shape.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParameterError {
    #[error("unknown parameter `{name}` of the {levels}{}", did_you_mean(.nearby, .valid))]
    Unknown { name: String, levels: String, nearby: Vec<&'static str>, valid: Vec<&'static str> },
    #[error("`{name}` takes {}, got {}", .expected.describe(), .found.found())]
    WrongShape { name: &'static str, expected: Shape, found: Shape },
}

/// `: did you mean `x`?` with the nearby names, or `: expected one of ...`
/// with every valid one when none is near.
pub fn did_you_mean(nearby: &[&str], valid: &[&str]) -> String {
    let quoted = |names: &[&str]| names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ");
    match nearby {
        [] => format!(": expected one of {}", quoted(valid)),
        [one] => format!(": did you mean {}?", quoted(&[one])),
        more => format!(": did you mean one of {}?", quoted(more)),
    }
}

/// A spec that takes parameter values by name (front ends, grids, Python).
pub trait SetParameter {
    /// The levels whose parameters this spec holds.
    const LEVELS: &'static [Level];
    /// Set `parameter` (one of [`Self::LEVELS`]'); the value is validated
    /// when the spec is built, not here.
    fn set_parameter(&mut self, parameter: &'static ParameterDef, value: Value) -> Result<(), ParameterError>;

    /// Look `name` up among this spec's parameters and set it.
    fn set_named(&mut self, name: &str, value: Value) -> Result<(), ParameterError> {
        let parameter = find_at(Self::LEVELS, name)?;
        self.set_parameter(parameter, value)
    }
}

/// A spec that also takes the contact law (`--law`, the Python keyword `law`),
/// beside its declared parameters.
pub trait SetLaw {
    fn set_law(&mut self, law: crate::LawKind);
}

/// The message for an unknown key of a table whose keys are `valid`.
pub fn unknown_key(key: &str, valid: &[&'static str]) -> String {
    format!("unknown key `{key}`{}", did_you_mean(&nearby(key, valid), valid))
}

/// Fails with its message when asked for a value (see [`unknown_key`]): a table deserializer
/// refuses an unknown key while reading its value, so the error points at
/// the key's line.
pub struct Refuse(pub String);

impl<'de> serde::de::DeserializeSeed<'de> for Refuse {
    type Value = ();
    fn deserialize<D: serde::Deserializer<'de>>(self, _: D) -> Result<(), D::Error> {
        Err(serde::de::Error::custom(self.0))
    }
}

/// A spec read from a table (TOML, JSON) by the declared names of its
/// levels, each value by its shape (`null` leaves it unset), plus the keys
/// in [`DeclaredTable::EXTRA`]; any other key is refused at its line with
/// the nearby names. Its `Deserialize` is [`deserialize_table`].
pub trait DeclaredTable: SetParameter + Default {
    /// Keys beside the declared parameters, read by [`DeclaredTable::read_extra`].
    const EXTRA: &'static [&'static str] = &[];
    /// Read the value of the extra key `key`.
    fn read_extra<'de, A: serde::de::MapAccess<'de>>(&mut self, key: &str, map: &mut A) -> Result<(), A::Error> {
        let _ = key;
        map.next_value::<serde::de::IgnoredAny>().map(|_| ())
    }
}

/// Deserialize a [`DeclaredTable`].
pub fn deserialize_table<'de, S: DeclaredTable, D: serde::Deserializer<'de>>(deserializer: D) -> Result<S, D::Error> {
    struct Keys<S>(std::marker::PhantomData<S>);
    impl<'de, S: DeclaredTable> serde::de::Visitor<'de> for Keys<S> {
        type Value = S;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("a table of declared parameters")
        }
        fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<S, A::Error> {
            use serde::de::Error as _;
            let mut spec = S::default();
            let mut seen: Vec<String> = Vec::new();
            while let Some(key) = map.next_key::<String>()? {
                if seen.contains(&key) {
                    return Err(A::Error::custom(format!("duplicate key `{key}`")));
                }
                if S::EXTRA.contains(&key.as_str()) {
                    spec.read_extra(&key, &mut map)?;
                } else if let Ok(parameter) = find_at(S::LEVELS, &key) {
                    let value = match parameter.shape {
                        Shape::Scalar => map.next_value::<Option<f64>>()?.map(Value::Number),
                        Shape::Vector3 => map.next_value::<Option<[f64; 3]>>()?.map(Value::Vector),
                        Shape::Switch => map.next_value::<Option<bool>>()?.map(Value::Switch),
                    };
                    if let Some(value) = value {
                        spec.set_parameter(parameter, value).map_err(A::Error::custom)?;
                    }
                } else {
                    let mut valid: Vec<&'static str> = at_levels(S::LEVELS).map(|p| p.name).collect();
                    valid.extend(S::EXTRA);
                    return map.next_value_seed(Refuse(unknown_key(&key, &valid))).map(|()| spec);
                }
                seen.push(key);
            }
            Ok(spec)
        }
    }
    deserializer.deserialize_map(Keys(std::marker::PhantomData))
}

/// The value as a number, or a shape error naming `parameter`.
pub fn number(parameter: &ParameterDef, value: Value) -> Result<f64, ParameterError> {
    match value {
        Value::Number(x) => Ok(x),
        other => Err(ParameterError::WrongShape { name: parameter.name, expected: Shape::Scalar, found: other.shape() }),
    }
}

/// The value as three numbers, or a shape error naming `parameter`.
pub fn vector(parameter: &ParameterDef, value: Value) -> Result<[f64; 3], ParameterError> {
    match value {
        Value::Vector(v) => Ok(v),
        other => Err(ParameterError::WrongShape { name: parameter.name, expected: Shape::Vector3, found: other.shape() }),
    }
}

/// The value as a switch, or a shape error naming `parameter`.
pub fn switch(parameter: &ParameterDef, value: Value) -> Result<bool, ParameterError> {
    match value {
        Value::Switch(on) => Ok(on),
        other => Err(ParameterError::WrongShape { name: parameter.name, expected: Shape::Switch, found: other.shape() }),
    }
}

#[allow(clippy::too_many_arguments)] // one row of the declaration table
const fn scalar(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    level: Level,
    default: DefaultValue,
    valid: Valid,
    sample: Option<SampleRange>,
    doc: &'static str,
) -> ParameterDef {
    ParameterDef { name, symbol, unit, level, shape: Shape::Scalar, default, valid, sample, doc }
}

use DefaultValue::{Derived, Number, Unset};
use Level::{Instep, Kick3d, Scenario};

// The 1D scenario (Table 1's baseline as defaults). `Parameter::ALL` lists
// the first eight in this order.
pub const FOOT_MASS: ParameterDef = scalar(
    "foot_mass",
    "m_f",
    "kg",
    Scenario,
    Number(3.0),
    Valid::POSITIVE,
    SampleRange::log(0.5, 15.0),
    "Effective foot mass (Eqs. 11-12)",
);
pub const BALL_MASS: ParameterDef = scalar(
    "ball_mass",
    "m_b",
    "kg",
    Scenario,
    Number(crate::DEFAULT_BALL_MASS),
    Valid::POSITIVE,
    SampleRange::linear(0.41, 0.45),
    "Ball mass (size-5 ball: 0.41-0.45 kg)",
);
pub const FOOT_SPEED: ParameterDef = scalar(
    "foot_speed",
    "v_f⁻",
    "m/s",
    Scenario,
    Number(22.0),
    Valid::FINITE,
    SampleRange::linear(12.0, 35.0),
    "Foot speed before contact",
);
pub const BALL_SPEED: ParameterDef = scalar(
    "ball_speed",
    "v_b⁻",
    "m/s",
    Scenario,
    Number(0.0),
    Valid::FINITE,
    SampleRange::linear(-10.0, 10.0),
    "Ball speed before contact (3D: the ball moves along x, the foot's horizontal line of motion, whatever the approach angle)",
);
pub const STIFFNESS: ParameterDef =
    scalar("stiffness", "k", "N/m^n", Scenario, Number(4.2e5), Valid::POSITIVE, SampleRange::log(1e4, 1e7), "Contact stiffness (Eq. 20)");
pub const DAMPING: ParameterDef = scalar(
    "damping",
    "c",
    "N s/m",
    Scenario,
    Number(120.0),
    Valid::NON_NEGATIVE,
    SampleRange::linear(0.0, 600.0),
    "Contact damping, while compressing (Eq. 20)",
);
pub const EXPONENT: ParameterDef =
    scalar("exponent", "n", "1", Scenario, Number(1.35), Valid::POSITIVE, SampleRange::linear(1.0, 2.0), "Contact exponent (Eq. 20)");
pub const DRIVE_FORCE: ParameterDef = scalar(
    "drive_force",
    "F_drive",
    "N",
    Scenario,
    Number(0.0),
    Valid::FINITE,
    Some(SampleRange { spacing: Spacing::Linear, from: 0.0, to: 1000.0, zero_probability: 0.5 }),
    "Drive force on the foot along its velocity during contact",
);
pub const RESTITUTION: ParameterDef = scalar(
    "restitution",
    "e",
    "1",
    Scenario,
    Unset("none; needed by every law but the paper's"),
    Valid::new(Bound::Open(0.0), Bound::Closed(1.0), "in (0, 1]"),
    None,
    "Target restitution of the contact laws other than the paper's (their damping follows from it)",
);

// The off-center 3D kick (kick-3d; defaults are assumptions stated there).
pub const OFFSET: ParameterDef = scalar(
    "offset",
    "e",
    "m",
    Kick3d,
    Number(0.0),
    Valid::FINITE,
    SampleRange::linear(0.0, 0.09),
    "Lateral distance of the ball's centre from the foot's line of motion, the line on the ball's +y side for e > 0 \
     (the ball leaves toward -y spinning with ω_z < 0 and curves further toward -y); e² + h² < R²",
);
/// h: with the offset e, where the foot's line of motion passes the ball's
/// centre (kick-3d's `model`); the knife edge and the convex instep are
/// geometries placed on that line, not definitions of it.
pub const CONTACT_DEPTH: ParameterDef = scalar(
    "contact_depth",
    "h",
    "m",
    Kick3d,
    Number(0.0),
    Valid::FINITE,
    None,
    "Vertical distance of the ball's centre above the foot's line of motion, perpendicular to the line (h > 0: the foot \
     passes below the centre, the ball rises with backspin ω_y < 0); e² + h² < R²",
);
pub const APPROACH_ANGLE: ParameterDef = scalar(
    "approach_angle",
    "α",
    "deg",
    Kick3d,
    Number(0.0),
    Valid::new(Bound::Open(-90.0), Bound::Open(90.0), "finite, in (-90, 90) degrees"),
    SampleRange::linear(0.0, 40.0),
    "Elevation of the foot's velocity above the horizontal",
);
pub const FRICTION: ParameterDef = scalar(
    "friction",
    "μ",
    "1",
    Kick3d,
    Number(0.5),
    Valid::new(Bound::Closed(0.0), Bound::Closed(f64::INFINITY), ">= 0 (inf: never slips)"),
    SampleRange::linear(0.0, 2.0),
    "Coulomb friction coefficient (inf: never slips)",
);
pub const BALL_RADIUS: ParameterDef =
    scalar("ball_radius", "R", "m", Kick3d, Number(crate::DEFAULT_BALL_RADIUS), Valid::POSITIVE, None, "Ball radius");
pub const BALL_INERTIA: ParameterDef = scalar(
    "ball_inertia",
    "I_b",
    "kg m^2",
    Kick3d,
    Derived("2/3 m_b R^2, a thin shell"),
    Valid::POSITIVE,
    None,
    "Ball moment of inertia (at most 2/3 m_b R^2, a thin shell)",
);
pub const TANGENTIAL_STIFFNESS: ParameterDef = scalar(
    "tangential_stiffness",
    "k_t",
    "N/m",
    Kick3d,
    Number(1.0e5),
    Valid::new(Bound::Open(0.0), Bound::Closed(f64::INFINITY), "> 0 (inf: rigid grip, solved as a constraint)"),
    SampleRange::log(1e4, 1e6),
    "Tangential stiffness of the contact: the shell's tangential compliance, a spring in series with the Coulomb slider (inf: rigid grip, a constraint with no spring)",
);
pub const FOOT_INERTIA: ParameterDef = ParameterDef {
    name: "foot_inertia",
    symbol: "I_f",
    unit: "kg m^2",
    level: Kick3d,
    shape: Shape::Vector3,
    default: Derived("a uniform solid box of the instep's size and mass m_f"),
    valid: Valid::POSITIVE,
    sample: None,
    doc: "Principal moments of inertia of the foot about its centre of mass, Ix,Iy,Iz (x: face normal)",
};
pub const FOOT_HALF_EXTENTS: ParameterDef = ParameterDef {
    name: "foot_half_extents",
    symbol: "h",
    unit: "m",
    level: Kick3d,
    shape: Shape::Vector3,
    default: DefaultValue::Vector([0.03, 0.12, 0.05]),
    valid: Valid::POSITIVE,
    sample: None,
    doc: "Outer half-extents of the instep box, hx,hy,hz (hx along the face normal)",
};
pub const BORDER_RADIUS: ParameterDef = scalar(
    "border_radius",
    "r_b",
    "m",
    Kick3d,
    Number(0.0),
    Valid::new(Bound::Closed(0.0), Bound::Unbounded, "finite, >= 0 and below the smallest foot half-extent"),
    None,
    "Round the instep box's edges with this radius, inside its outer size (0: plain box)",
);
pub const GRAVITY_SWITCH: ParameterDef = ParameterDef {
    name: "gravity",
    symbol: "g",
    unit: "",
    level: Kick3d,
    shape: Shape::Switch,
    default: DefaultValue::Off,
    valid: Valid::ANY,
    sample: None,
    doc: "Uniform gravity (9.81 m/s^2, downward) on both bodies",
};
pub const GROUND_PLANE: ParameterDef = ParameterDef {
    name: "ground",
    symbol: "ground",
    unit: "",
    level: Kick3d,
    shape: Shape::Switch,
    default: DefaultValue::Off,
    valid: Valid::ANY,
    sample: None,
    doc: "A ground plane under the ball (rapier scene path)",
};

// The instep as a surface of its own (kick-3d's `patch` module): given,
// they replace the knife-edge face (tangent where the foot's line of motion
// meets the ball); absent, the 3D kick is exactly the one above.
pub const FACE_YAW: ParameterDef = scalar(
    "face_yaw",
    "ψ",
    "deg",
    Instep,
    Derived("the knife edge's: the face tangent to the ball where the foot's line of motion meets it (asin(e/R) on a horizontal path with h = 0)"),
    Valid::new(Bound::Open(-90.0), Bound::Open(90.0), "finite, in (-90, 90) degrees"),
    None,
    "Yaw of the instep's face normal from the x axis, about z (positive turns it as a positive offset's knife edge does)",
);
pub const FACE_PITCH: ParameterDef = scalar(
    "face_pitch",
    "θ",
    "deg",
    Instep,
    Derived("the knife edge's (0 on a horizontal path with h = 0)"),
    Valid::new(Bound::Open(-90.0), Bound::Open(90.0), "finite, in (-90, 90) degrees"),
    None,
    "Pitch of the instep's face normal above the horizontal (positive: the face meets the ball below its centre)",
);
pub const INSTEP_RADIUS: ParameterDef = scalar(
    "instep_radius", "r_i", "m", Instep, Number(0.0),
    // Flatter caps lose their digits (d = R + r_i − δ against a² / 2d) and are
    // the flat face to 1e-4 anyway (`a_flatter_cap_tends_to_the_flat_face`).
    Valid::new(Bound::Closed(0.0), Bound::Closed(1000.0), "0 (a flat face) to 1000 m"), None,
    "Radius of curvature of the instep's contact surface, a sphere cap (0: flat) whose pole moves on the foot's line of motion (offset, contact_depth)",
);
pub const PATCH_CONTACT: ParameterDef = ParameterDef {
    name: "patch_contact",
    symbol: "patch",
    unit: "",
    level: Instep,
    shape: Shape::Switch,
    default: DefaultValue::Off,
    valid: Valid::ANY,
    sample: None,
    doc: "Spread the shell ball's normal force over the contact patch, each element damped at its own rate (law shell)",
};

// The foot behind the contact (Level::Foot): the articulated leg and the boot.
pub const LEG: ParameterDef = ParameterDef {
    name: "leg",
    symbol: "leg",
    unit: "",
    level: Level::Foot,
    shape: Shape::Switch,
    default: DefaultValue::Off,
    valid: Valid::ANY,
    sample: None,
    doc: "The foot is the articulated leg posed by knee, ankle and hip: its apparent inertia at the contact point (Eq. 11; 6x6 in 3D) \
          in place of foot_mass, with the identified boot",
};
pub const KNEE: ParameterDef = scalar(
    "knee",
    "θ_k",
    "deg",
    Level::Foot,
    Number(crate::leg::LegPose::DEFAULT.knee),
    Valid::new(Bound::Closed(-15.0), Bound::Closed(170.0), "in [-15, 170] degrees"),
    None,
    "With leg: knee flexion, 0 straight (kick leg --knee)",
);
pub const ANKLE: ParameterDef = scalar(
    "ankle",
    "θ_a",
    "deg",
    Level::Foot,
    Number(crate::leg::LegPose::DEFAULT.ankle),
    Valid::new(Bound::Closed(-45.0), Bound::Closed(100.0), "in [-45, 100] degrees"),
    None,
    "With leg: ankle plantarflexion from neutral, the ankle braced (kick leg --ankle --locked-ankle)",
);
pub const HIP: ParameterDef = scalar(
    "hip",
    "θ_h",
    "deg",
    Level::Foot,
    Number(crate::leg::LegPose::DEFAULT.hip),
    Valid::new(Bound::Closed(-90.0), Bound::Closed(150.0), "in [-90, 150] degrees"),
    None,
    "With leg: thigh angle from the downward vertical, positive forward (kick leg --hip)",
);
pub const BOOT_STIFFNESS: ParameterDef = scalar(
    "boot_stiffness",
    "k_b",
    "N/m",
    Level::Foot,
    Derived("inf (the rigid foot); with leg the identified boot's 3.51e4"),
    Valid::new(Bound::Open(0.0), Bound::Closed(f64::INFINITY), "> 0 (inf: no layer, the rigid foot)"),
    None,
    "Stiffness of the compliant layer (boot upper and tissue) in series between foot and ball, Kelvin-Voigt (inf: rigid foot)",
);
pub const BOOT_DAMPING: ParameterDef = scalar(
    "boot_damping",
    "c_b",
    "N s/m",
    Level::Foot,
    Derived("the identified boot's 38.3"),
    Valid::new(Bound::Open(0.0), Bound::Unbounded, "finite and > 0"),
    None,
    "Damping of the compliant layer in series, F = k_b δ_b + c_b dδ_b/dt",
);

// The shell ball's (law `shell`, crate::shell).

/// Standard atmosphere at sea level, Pa (Law 2 states the pressure "at sea level").
pub const SEA_LEVEL_PRESSURE: f64 = 101_325.0;

const fn ball(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    default: f64,
    valid: Valid,
    sample: Option<SampleRange>,
    doc: &'static str,
) -> ParameterDef {
    ParameterDef {
        name,
        symbol,
        unit,
        level: Level::Bounce,
        shape: Shape::Scalar,
        default: DefaultValue::Number(default),
        valid,
        sample,
        doc,
    }
}

/// p0 = 0.8 bar, the FIFA Quality Programme's test pressure; sampled over
/// Law 2's 0.6–1.1 atm.
pub const INFLATION_PRESSURE: ParameterDef = ball(
    "inflation_pressure",
    "p0",
    "Pa",
    8.0e4,
    Valid {
        low: Bound::Closed(1.0e3),
        high: Bound::Closed(1.0e7),
        requirement: "in [1e3, 1e7] Pa gauge (0.01-100 bar: a ball neither flat nor burst)",
    },
    Some(SampleRange { spacing: Spacing::Linear, from: 0.6 * SEA_LEVEL_PRESSURE, to: 1.1 * SEA_LEVEL_PRESSURE, zero_probability: 0.0 }),
    "Gauge inflation pressure of the shell ball (Law 2: 0.6-1.1 atm; FIFA tests at 0.8 bar)",
);
/// γ of air (c_p/c_v = 1.40); a ~10 ms impact leaves no time for heat to flow.
pub const GAS_EXPONENT: ParameterDef = ball(
    "gas_exponent",
    "γ",
    "1",
    1.4,
    Valid { low: Bound::Closed(1.0), high: Bound::Closed(5.0 / 3.0), requirement: "in [1, 5/3] (1: isothermal, 1.4: adiabatic air)" },
    None,
    "Polytropic exponent of the gas, P V^γ constant (1.4: air compressed adiabatically)",
);
/// k_s: not identified from a checked measurement (kick-bounce SOURCES.md);
/// 0 leaves the pressure alone to carry the ball.
pub const SHELL_STIFFNESS: ParameterDef = ball(
    "shell_stiffness",
    "k_s",
    "N/m",
    0.0,
    Valid { low: Bound::Closed(0.0), high: Bound::Closed(1.0e8), requirement: "in [0, 1e8] N/m (a shell, not a rigid sphere)" },
    None,
    "Linear stiffness of the shell itself (bending), beside the gas",
);
/// β identified from the FIFA rebound test: the default ball dropped 2 m
/// (gravity on during contact, as in the test) rebounds to 1.40 m, the
/// middle of 115–165 cm; `shell_damping_is_the_fifa_rebound` in kick-bounce
/// recomputes it.
pub const SHELL_DAMPING: ParameterDef = ball(
    "shell_damping",
    "β",
    "Pa s/m",
    SHELL_DAMPING_FIFA,
    Valid { low: Bound::Closed(0.0), high: Bound::Closed(1.0e6), requirement: "in [0, 1e6] Pa s/m (about 270x the FIFA-calibrated loss)" },
    None,
    "Loss of the shell: a viscous stress β δ̇ over the contact patch, F = A(δ)(P − p_atm + β δ̇) + k_s δ (calibrated on the FIFA rebound test)",
);

/// β of the FIFA calibration, Pa s/m ([`SHELL_DAMPING`]'s default).
pub const SHELL_DAMPING_FIFA: f64 = 3_759.624_857_9;

/// Every parameter of the 1D and 3D levels, each once, lower levels first.
pub static PARAMETERS: [ParameterDef; 35] = [
    FOOT_MASS,
    BALL_MASS,
    FOOT_SPEED,
    BALL_SPEED,
    STIFFNESS,
    DAMPING,
    EXPONENT,
    DRIVE_FORCE,
    RESTITUTION,
    OFFSET,
    CONTACT_DEPTH,
    APPROACH_ANGLE,
    FRICTION,
    BALL_RADIUS,
    BALL_INERTIA,
    TANGENTIAL_STIFFNESS,
    FOOT_INERTIA,
    FOOT_HALF_EXTENTS,
    BORDER_RADIUS,
    GRAVITY_SWITCH,
    GROUND_PLANE,
    FACE_YAW,
    FACE_PITCH,
    INSTEP_RADIUS,
    PATCH_CONTACT,
    // Law `shell`'s ball (crate::shell), taken by 1D kicks under it.
    INFLATION_PRESSURE,
    GAS_EXPONENT,
    SHELL_STIFFNESS,
    SHELL_DAMPING,
    // The foot (leg and boot), taken by 1D and 3D kicks alike.
    LEG,
    KNEE,
    ANKLE,
    HIP,
    BOOT_STIFFNESS,
    BOOT_DAMPING,
];

/// The parameters of one level (not those it takes from lower levels).
pub fn at_level(level: Level) -> impl Iterator<Item = &'static ParameterDef> {
    PARAMETERS.iter().filter(move |p| p.level == level)
}

/// The parameters of any of `levels`, in declaration order.
pub fn at_levels(levels: &'static [Level]) -> impl Iterator<Item = &'static ParameterDef> {
    PARAMETERS.iter().filter(move |p| levels.contains(&p.level))
}

/// The parameter called `name`, at any level.
pub fn find(name: &str) -> Option<&'static ParameterDef> {
    PARAMETERS.iter().find(|p| p.name == name)
}

/// The parameter called `name` among `levels`, or an error with the nearby names.
pub fn find_at(levels: &'static [Level], name: &str) -> Result<&'static ParameterDef, ParameterError> {
    at_levels(levels).find(|p| p.name == name).ok_or_else(|| unknown(levels, name))
}

/// The error for a name that is none of `levels`' parameters.
pub fn unknown(levels: &'static [Level], name: &str) -> ParameterError {
    let valid: Vec<&'static str> = at_levels(levels).map(|p| p.name).collect();
    ParameterError::Unknown {
        name: name.to_string(),
        levels: levels.iter().map(|l| l.name()).collect::<Vec<_>>().join(" or "),
        nearby: nearby(name, &valid),
        valid,
    }
}

/// The names in `valid` close to `name` (a typo, a missing part), nearest
/// first (ties in declaration order): edit distance at most a third of the longer name, or one
/// containing the other.
pub fn nearby(name: &str, valid: &[&'static str]) -> Vec<&'static str> {
    let mut close: Vec<(usize, &'static str)> = valid
        .iter()
        .filter_map(|&candidate| {
            let distance = edit_distance(name, candidate);
            let limit = name.chars().count().max(candidate.chars().count()) / 3;
            let contains = name.len() >= 3 && (candidate.contains(name) || name.contains(candidate));
            (distance <= limit.max(1) || contains).then_some((distance, candidate))
        })
        .collect();
    close.sort_by_key(|&(distance, _)| distance);
    close.into_iter().map(|(_, n)| n).collect()
}

/// Levenshtein distance over characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != cb)).min(row[j] + 1).min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// A declaration that breaks an invariant of [`check_declarations`]: the
/// parameter's name and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{name}: {what}")]
pub struct DeclarationError {
    pub name: &'static str,
    pub what: String,
}

/// The invariants every declared list keeps (this one and kick-flight's),
/// for their tests: unique snake_case names, doc and symbol, lower levels
/// first, defaults of the declared shape inside the valid range, sampling
/// ranges scalar, ordered, inside the valid range (positive for log spacing).
pub fn check_declarations(list: &[ParameterDef]) -> Result<(), DeclarationError> {
    let snake_case = |name: &str| {
        name.starts_with(|c: char| c.is_ascii_lowercase())
            && name.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
            && !name.contains("__")
            && !name.ends_with('_')
    };
    for (i, p) in list.iter().enumerate() {
        let fail = |what: &str| Err(DeclarationError { name: p.name, what: what.to_string() });
        if !snake_case(p.name) {
            return fail("not snake_case");
        }
        if list[..i].iter().any(|q| q.name == p.name) {
            return fail("declared twice");
        }
        if p.doc.is_empty() || p.symbol.is_empty() {
            return fail("no doc or symbol");
        }
        if i > 0 && list[i - 1].level > p.level {
            return fail("declared after a higher level");
        }
        let default_ok = match (p.default, p.shape) {
            (DefaultValue::Number(x), Shape::Scalar) => p.valid.contains(x),
            (DefaultValue::Vector(v), Shape::Vector3) => v.iter().all(|&x| p.valid.contains(x)),
            (DefaultValue::Off, Shape::Switch) | (DefaultValue::Derived(_) | DefaultValue::Unset(_), _) => true,
            _ => false,
        };
        if !default_ok {
            return fail(&format!("default {:?} outside the valid range or not a {:?}", p.default, p.shape));
        }
        if let Some(s) = p.sample {
            let inside = p.shape == Shape::Scalar
                && s.from < s.to
                && p.valid.contains(s.from)
                && p.valid.contains(s.to)
                && (s.spacing == Spacing::Linear || s.from > 0.0)
                && (0.0..1.0).contains(&s.zero_probability)
                && (s.zero_probability == 0.0 || p.valid.contains(0.0));
            if !inside {
                return fail(&format!("sampling range {s:?} not inside the valid range"));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_declarations_keep_their_invariants() {
        check_declarations(&PARAMETERS).unwrap();
        for (i, p) in PARAMETERS.iter().enumerate() {
            assert_eq!(p.flag(), format!("--{}", p.name.replace('_', "-")));
            assert_eq!(find(p.name), Some(&PARAMETERS[i]));
        }
        // The check can fail: a default outside its range, a duplicate, a sampling range too wide.
        let mut bad = PARAMETERS;
        bad[0].default = DefaultValue::Number(-1.0);
        assert!(check_declarations(&bad).is_err());
        let mut bad = PARAMETERS;
        bad[1].name = bad[0].name;
        assert!(check_declarations(&bad).is_err());
        let mut bad = PARAMETERS;
        bad[5].sample = SampleRange::linear(-1.0, 600.0);
        let e = check_declarations(&bad).unwrap_err();
        assert_eq!(e.name, "damping");
        assert!(e.to_string().starts_with("damping: sampling range"), "{e}");
    }

    /// Every draw lands in its range, at both ends of [0, 1).
    #[test]
    fn draws_stay_in_their_ranges() {
        for p in PARAMETERS.iter().filter(|p| p.sample.is_some()) {
            let s = p.sample.unwrap();
            for r in [0.0, 0.5, 1.0 - f64::EPSILON] {
                let x = s.draw(&mut || r);
                assert!(x == 0.0 && s.zero_probability > r || (s.from..=s.to).contains(&x), "{} at {r}: {x}", p.name);
            }
        }
    }

    /// Every parameter of the 1D model has a sampling range (random sweeps
    /// draw all eight) and the eight come first, in `Parameter::ALL` order.
    #[test]
    fn the_eight_come_first_and_are_sampled() {
        for (i, p) in crate::Parameter::ALL.iter().enumerate() {
            assert_eq!(p.def().name, serde_name(p), "{p:?}");
            assert_eq!(PARAMETERS[i].name, p.name());
            assert!(p.def().sample.is_some(), "{p:?}");
        }
    }

    fn serde_name(p: &crate::Parameter) -> String {
        // Parameter's serde name (snake case of the variant) is independent of the list.
        format!("{p:?}").chars().fold(String::new(), |mut name, c| {
            if c.is_ascii_uppercase() && !name.is_empty() {
                name.push('_');
            }
            name.push(c.to_ascii_lowercase());
            name
        })
    }

    #[test]
    fn valid_ranges_keep_their_ends() {
        assert!(FOOT_MASS.check(0.0).is_err() && FOOT_MASS.check(1e-300).is_ok());
        assert!(DAMPING.check(0.0).is_ok() && DAMPING.check(-1e-300).is_err());
        assert!(RESTITUTION.check(1.0).is_ok() && RESTITUTION.check(0.0).is_err());
        assert!(FRICTION.check(f64::INFINITY).is_ok() && FRICTION.check(f64::NAN).is_err());
        assert!(TANGENTIAL_STIFFNESS.check(f64::INFINITY).is_ok() && TANGENTIAL_STIFFNESS.check(0.0).is_err());
        assert!(APPROACH_ANGLE.check(90.0).is_err() && APPROACH_ANGLE.check(-89.9).is_ok());
        for p in &PARAMETERS {
            if p.shape != Shape::Switch {
                assert!(p.check(f64::NAN).is_err(), "{}", p.name);
            }
            // μ = ∞ never slips; k_t = ∞ is rigid grip, a constraint; k_b = ∞ is no boot.
            if !["friction", "tangential_stiffness", "boot_stiffness"].contains(&p.name) {
                assert!(p.check(f64::INFINITY).is_err(), "{}", p.name);
            }
        }
        let error = STIFFNESS.check(-1.0).unwrap_err();
        assert_eq!(error.to_string(), "invalid parameter `stiffness` = -1: must be finite and > 0");
    }

    #[test]
    fn unknown_names_are_refused_with_the_nearby_ones() {
        let error = find_at(&[Level::Scenario], "foot_mas").unwrap_err();
        assert_eq!(error.to_string(), "unknown parameter `foot_mas` of the 1D scenario: did you mean `foot_mass`?");
        let ParameterError::Unknown { nearby, .. } = find_at(&[Level::Scenario], "speed").unwrap_err() else { panic!() };
        assert_eq!(nearby, ["foot_speed", "ball_speed"]);
        let error = find_at(&[Level::Scenario], "xyz").unwrap_err();
        assert!(error.to_string().contains("expected one of `foot_mass`"), "{error}");
        // A 3D parameter is not one of the 1D level.
        assert!(find_at(&[Level::Scenario], "offset").is_err());
        assert_eq!(find_at(&[Level::Scenario, Level::Kick3d], "offset").unwrap().name, "offset");
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }

    #[test]
    fn help_shows_symbol_unit_and_default() {
        assert_eq!(FOOT_MASS.help(), "Effective foot mass (Eqs. 11-12): m_f, kg [default: 3]");
        assert_eq!(STIFFNESS.default.text(), "4.2e5");
        assert_eq!(FOOT_HALF_EXTENTS.columns(), ["foot_half_extents_x", "foot_half_extents_y", "foot_half_extents_z"]);
    }
}
