//! The ball alone: a ball fired at a rigid, massive, horizontal plate,
//! square or oblique, with or without spin (`kick bounce`). This is where
//! the shell law ([`kick_core::ShellBall`]) is calibrated, with no foot in
//! the way; SOURCES.md says which measurement calibrates which parameter
//! and which are predictions.
//!
//! Axes: the plate is z = 0, its normal +z; the ball comes down in the x–z
//! plane at `angle` θ from the normal, v⁻ = V (sin θ, 0, −cos θ); spin ω⁻
//! in the same axes. The contact point is (0, 0, −R) from the centre.
//!
//! - **Normal phase**: the 1D contact of the ball against an infinite mass,
//!   solved by kick-compliant's event-located solvers with the shell law in
//!   place of Eq. 20: the ball is the "foot" (it moves, and gravity on it
//!   during contact is the drive F_drive = m g, Eq. 26), the plate the
//!   "ball" of mass [`PLATE_MASS`] at rest. The drive's share on the
//!   relative coordinate (Eq. 18) is (μ/m) m g = μ g: gravity pressing the
//!   ball on the plate.
//!   Restitution e is −δ̇/V_n at separation, relative to the plate.
//! - **Tangential phase**: an impulse model (Cross 2002; tangential
//!   restitution of Cross & Nathan 2006), chosen over kick-3d's
//!   Cundall–Strack spring because a bounce needs only the exit state and
//!   the spring's stiffness and damping are not measurable on a ball. The
//!   slip velocity of the contact point u = v_t + ω × r is brought to
//!   −e_t u (grip: J_t = −m_t (1 + e_t) u, m_t = (1/m + R²/I)⁻¹) unless
//!   that needs more than Coulomb's μ J_n, when the ball slides throughout
//!   (J_t = −μ J_n û). The lever is R, the undeformed radius (Cross's
//!   model; a ball flattened by δ has its patch nearer R − δ, issue 22
//!   item 4); spin about the normal is unchanged (no torsional friction).
//!
//! The ball's law is the shell ([`BallLaw::Shell`], the default) or any law
//! of the kick's family by its `--law` name (the paper's Eq. 20 with its k,
//! c, n; the others with a target restitution at this impact speed), so the
//! kick's ball can be put through the same tests.

use kick_compliant::{Accurate, Reduced};
use kick_core::parameters::{Bound, DefaultValue, Level, ParameterDef, Shape, Valid, Value};
use kick_core::parameters::{DAMPING, EXPONENT, RESTITUTION, STIFFNESS};
use kick_core::shell::{ShellBall, GAS_EXPONENT, INFLATION_PRESSURE, SHELL_DAMPING, SHELL_STIFFNESS};
use kick_core::{AnyLaw, ContactLaw, KickError, LawKind, Outcome, Scenario, DEFAULT_BALL_MASS, DEFAULT_BALL_RADIUS, GRAVITY};
use serde::Serialize;

/// The plate's mass, kg: μ = m_b m_f/(m_b + m_f) equals m_b to 1e-15
/// relative, below the solvers' tolerance; restitution, taken from δ̇
/// relative to the plate, does not depend on it.
pub const PLATE_MASS: f64 = 1e15;

#[allow(clippy::too_many_arguments)] // one row of the declaration table
const fn bounce(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    shape: Shape,
    default: DefaultValue,
    low: Bound,
    high: Bound,
    requirement: &'static str,
    doc: &'static str,
) -> ParameterDef {
    ParameterDef { name, symbol, unit, level: Level::Bounce, shape, default, valid: Valid { low, high, requirement }, sample: None, doc }
}

use Bound::{Closed, Open, Unbounded};
use DefaultValue::{Derived, Number, Unset};
use Shape::{Scalar, Vector3};

/// How many parameters a bounce declares.
pub const BOUNCE_PARAMETER_COUNT: usize = 18;

/// The largest impact speed, m/s: `speed`'s bound, and the one a drop height may give.
pub const MAX_IMPACT_SPEED: f64 = 1000.0;

/// Every parameter of a bounce, declared once: the kick family's law
/// parameters (kick-core's, for `law` other than `shell`), the shot, the
/// ball, and the shell law's own (kick-core's `shell::BALL_PARAMETERS`).
/// Flags, keys and refusals use these names.
pub static BOUNCE_PARAMETERS: [ParameterDef; BOUNCE_PARAMETER_COUNT] = [
    STIFFNESS,
    DAMPING,
    EXPONENT,
    RESTITUTION,
    bounce(
        "speed",
        "V",
        "m/s",
        Scalar,
        Unset("required, unless drop_height gives it"),
        Open(0.0),
        Closed(MAX_IMPACT_SPEED),
        "in (0, 1000] m/s; not with drop_height",
        "Impact speed of the ball's centre",
    ),
    bounce(
        "angle",
        "θ",
        "deg",
        Scalar,
        Number(0.0),
        Closed(0.0),
        Open(90.0),
        "in [0, 90) degrees from the plate's normal",
        "Angle of the incoming velocity from the plate's normal (0: square)",
    ),
    bounce(
        "spin",
        "ω",
        "rad/s",
        Vector3,
        DefaultValue::Vector([0.0; 3]),
        Unbounded,
        Unbounded,
        "three finite numbers, rad/s",
        "Spin before impact (x along the tangential velocity, z the plate's normal)",
    ),
    bounce(
        "drop_height",
        "H",
        "m",
        Scalar,
        Unset("none"),
        Open(0.0),
        Unbounded,
        "finite and > 0, m, at most V²/(2 g) for V = 1000 m/s; not with speed or angle, and gravity > 0",
        "Drop the ball from rest at height H (no drag): V = √(2 g H), square; reports rebound_height",
    ),
    bounce(
        "ball_mass",
        "m",
        "kg",
        Scalar,
        Number(DEFAULT_BALL_MASS),
        Open(0.0),
        Unbounded,
        "finite and > 0, kg",
        "Ball mass (Law 2: 0.41-0.45 kg)",
    ),
    bounce(
        "ball_radius",
        "R",
        "m",
        Scalar,
        Number(DEFAULT_BALL_RADIUS),
        Open(0.0),
        Unbounded,
        "finite and > 0, m",
        "Ball radius (Law 2: circumference 0.68-0.70 m)",
    ),
    bounce(
        "ball_inertia",
        "I",
        "kg m^2",
        Scalar,
        Derived("2/3 m R^2, a thin shell"),
        Open(0.0),
        Unbounded,
        "finite and > 0, at most 2/3 m R^2",
        "Ball moment of inertia about its centre",
    ),
    bounce(
        "friction",
        "μ",
        "1",
        Scalar,
        Number(0.5),
        Closed(0.0),
        Closed(f64::INFINITY),
        ">= 0 (inf: never slips)",
        "Coulomb friction between ball and plate (not calibrated: the 3D kick's default)",
    ),
    bounce(
        "tangential_restitution",
        "e_t",
        "1",
        Scalar,
        Number(0.0),
        Closed(0.0),
        Closed(1.0),
        "in [0, 1]",
        "Tangential restitution of a gripping ball, u⁺ = −e_t u⁻ (0: it leaves rolling)",
    ),
    bounce(
        "gravity",
        "g",
        "m/s^2",
        Scalar,
        Number(GRAVITY),
        Closed(0.0),
        Unbounded,
        "finite and >= 0, m/s^2",
        "Gravity along −z, during contact too (0: off)",
    ),
    INFLATION_PRESSURE,
    GAS_EXPONENT,
    SHELL_STIFFNESS,
    SHELL_DAMPING,
];

/// The position of a declared name in [`BOUNCE_PARAMETERS`].
fn slot(name: &str) -> usize {
    BOUNCE_PARAMETERS.iter().position(|p| p.name == name).expect("a declared name")
}

/// The declaration called `name`, or an error with the valid names.
pub fn parameter(name: &str) -> Result<&'static ParameterDef, kick_core::parameters::ParameterError> {
    BOUNCE_PARAMETERS.iter().find(|p| p.name == name).ok_or_else(|| {
        let valid: Vec<&'static str> = BOUNCE_PARAMETERS.iter().map(|p| p.name).collect();
        kick_core::parameters::ParameterError::Unknown {
            name: name.to_string(),
            levels: Level::Bounce.name().to_string(),
            nearby: kick_core::parameters::nearby(name, &valid),
            valid,
        }
    })
}

/// The ball's contact law by name: `shell`, or a law of the kick's family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LawChoice {
    Shell,
    Kick(LawKind),
}

impl LawChoice {
    /// Every law by name: kick-core's one list (`LawKind::SELECTABLE`, the shell included).
    pub const NAMES: &'static str = LawKind::NAMES;

    pub fn from_name(name: &str) -> Result<LawChoice, kick_core::laws::LawError> {
        match name {
            "shell" => Ok(LawChoice::Shell),
            _ => LawKind::from_name(name)
                .map(LawChoice::Kick)
                .map_err(|_| kick_core::laws::LawError::UnknownLaw { name: name.to_string(), expected: LawChoice::NAMES }),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            LawChoice::Shell => "shell",
            LawChoice::Kick(kind) => kind.name(),
        }
    }
}

/// The values given for a bounce, one slot per declared parameter
/// ([`BOUNCE_PARAMETERS`] order), and the law; validated by
/// [`BounceSpec::build`]. `Copy`: a fit moves it from trial to trial.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct BounceSpec {
    values: [Option<Value>; BOUNCE_PARAMETER_COUNT],
    /// `None`: the shell.
    pub law: Option<LawChoice>,
}

impl BounceSpec {
    /// Set the parameter `name` (a later value replaces an earlier one).
    pub fn set(&mut self, name: &str, value: Value) -> Result<&mut Self, kick_core::parameters::ParameterError> {
        let p = parameter(name)?;
        if value.shape() != p.shape {
            return Err(kick_core::parameters::ParameterError::WrongShape { name: p.name, expected: p.shape, found: value.shape() });
        }
        self.values[slot(p.name)] = Some(value);
        Ok(self)
    }

    /// The value given for `name`, if any (not its default).
    pub fn given(&self, name: &str) -> Option<Value> {
        BOUNCE_PARAMETERS.iter().position(|p| p.name == name).and_then(|i| self.values[i])
    }

    /// The scalar `name` as a bounce would use it: given, else its declared
    /// numeric default (`None` for a vector, or a scalar with no default).
    pub fn number(&self, name: &str) -> Option<f64> {
        let p = parameter(name).ok()?;
        match (self.given(name), p.default) {
            (Some(Value::Number(x)), _) => Some(x),
            (None, DefaultValue::Number(x)) => Some(x),
            _ => None,
        }
    }

    /// Forget the value given for `name` (its default applies again).
    pub fn unset(&mut self, name: &str) {
        if let Some(i) = BOUNCE_PARAMETERS.iter().position(|p| p.name == name) {
            self.values[i] = None;
        }
    }

    /// A scalar, checked against its declaration; the default if not given.
    fn scalar(&self, name: &str) -> Result<Option<f64>, KickError> {
        let p = parameter(name).expect("declared");
        match (self.given(name), p.default) {
            (Some(Value::Number(x)), _) => p.check(x).map(Some),
            (_, DefaultValue::Number(x)) => Ok(Some(x)),
            _ => Ok(None),
        }
    }

    /// Fill the defaults and validate; errors name the parameter.
    pub fn build(&self) -> Result<Bounce, KickError> {
        let get = |name| self.scalar(name);
        let number = |name| self.scalar(name).map(|x| x.expect("a numeric default"));
        let gravity = number("gravity")?;
        let angle = number("angle")?;
        let (speed, drop_height) = match (get("speed")?, get("drop_height")?) {
            (Some(v), None) => (v, None),
            (None, Some(h)) => {
                if self.given("angle").is_some() {
                    return Err(does_not_apply("angle", "drop_height", "a dropped ball falls square onto the plate"));
                }
                if gravity <= 0.0 {
                    return Err(KickError::InvalidParameter { name: "gravity", value: gravity, requirement: "> 0 with drop_height" });
                }
                // The speed it sets is held to `speed`'s own bound (1000 m/s).
                let v = (2.0 * gravity * h).sqrt();
                if v > MAX_IMPACT_SPEED {
                    return Err(KickError::InvalidParameter {
                        name: "drop_height",
                        value: h,
                        // The bound at the g given (a user's 1e6 m/s² is not 9.81).
                        requirement: interned(format!(
                            "at most V²/(2 g) = {} m, V = {} m/s the largest impact speed, at g = {} m/s²",
                            kick_core::short(MAX_IMPACT_SPEED.powi(2) / (2.0 * gravity)),
                            kick_core::short(MAX_IMPACT_SPEED),
                            kick_core::short(gravity)
                        )),
                    });
                }
                (v, Some(h))
            }
            (Some(_), Some(_)) => return Err(does_not_apply("speed", "drop_height", "the drop height sets the impact speed")),
            (None, None) => {
                // NaN: no value was given (the message says what is needed).
                return Err(KickError::InvalidParameter { name: "speed", value: f64::NAN, requirement: "given, or drop_height instead" });
            }
        };
        let spin = match self.given("spin") {
            Some(Value::Vector(w)) if w.iter().all(|x| x.is_finite()) => w,
            Some(Value::Vector(w)) => {
                let bad = w.into_iter().find(|x| !x.is_finite()).unwrap_or(f64::NAN);
                return Err(KickError::InvalidParameter { name: "spin", value: bad, requirement: "three finite numbers, rad/s" });
            }
            _ => [0.0; 3],
        };
        let mass = number("ball_mass")?;
        let radius = number("ball_radius")?;
        let shell = kick_core::bound::thin_shell_inertia(mass, radius);
        let inertia = match get("ball_inertia")? {
            // The shell as printed and rounded up is the shell (kick_core::bound).
            Some(i) => kick_core::bound::at_most(i, shell).ok_or(KickError::InvalidParameter {
                name: "ball_inertia",
                value: i,
                requirement: "at most 2/3 m R^2 (a thin shell; up to 5e-4 above reads as it)",
            })?,
            None => shell,
        };
        let choice = self.law.unwrap_or(LawChoice::Shell);
        // A parameter of the other kind of law would be ignored: refuse it.
        let (others, reason): (&[&ParameterDef], _) = match choice {
            LawChoice::Shell => (
                &[&STIFFNESS, &DAMPING, &EXPONENT, &RESTITUTION],
                "it is a parameter of the kick family's laws (--law power-law, ...), not of the shell",
            ),
            LawChoice::Kick(_) => {
                (&[&INFLATION_PRESSURE, &GAS_EXPONENT, &SHELL_STIFFNESS, &SHELL_DAMPING], "it is a parameter of law shell")
            }
        };
        if let Some(p) = others.iter().find(|p| self.given(p.name).is_some()) {
            return Err(KickError::DoesNotApply { given: p.name, to: format!("law `{}`", choice.name()), reason });
        }
        let law = match choice {
            LawChoice::Shell => BallLaw::Shell(ShellBall::new(
                number("inflation_pressure")?,
                radius,
                number("gas_exponent")?,
                number("shell_stiffness")?,
                number("shell_damping")?,
            )?),
            LawChoice::Kick(kind) => {
                kind.check_given(self.given("damping").is_some(), self.given("restitution").is_some())?;
                BallLaw::Kick {
                    kind,
                    stiffness: number("stiffness")?,
                    damping: number("damping")?,
                    exponent: number("exponent")?,
                    restitution: get("restitution")?,
                }
            }
        };
        Ok(Bounce {
            speed,
            angle,
            spin,
            drop_height,
            mass,
            radius,
            inertia,
            friction: number("friction")?,
            tangential_restitution: number("tangential_restitution")?,
            gravity,
            law,
        })
    }
}

fn does_not_apply(given: &'static str, to: &'static str, reason: &'static str) -> KickError {
    KickError::DoesNotApply { given, to: format!("`{to}`"), reason }
}

/// A validated bounce.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Bounce {
    /// V, m/s.
    pub speed: f64,
    /// θ from the normal, degrees.
    pub angle: f64,
    pub spin: [f64; 3],
    pub drop_height: Option<f64>,
    pub mass: f64,
    pub radius: f64,
    pub inertia: f64,
    pub friction: f64,
    pub tangential_restitution: f64,
    pub gravity: f64,
    pub law: BallLaw,
}

/// The ball's normal contact law.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "law", rename_all = "kebab-case")]
pub enum BallLaw {
    Shell(ShellBall),
    /// A law of the kick's family, built at the bounce's impact speed
    /// (`Scenario::with_law`: a target restitution is met at this speed).
    Kick {
        kind: LawKind,
        stiffness: f64,
        damping: f64,
        exponent: f64,
        restitution: Option<f64>,
    },
}

/// Whether the contact point stopped slipping (or reversed, e_t > 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Tangential {
    /// No slip to start with: no tangential impulse.
    NoSlip,
    /// Friction was enough: u⁺ = −e_t u⁻.
    Grips,
    /// Coulomb's limit reached: slides throughout, |J_t| = μ J_n.
    Slides,
}

/// What a bounce gives (SI units, the axes of the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BounceOutcome {
    /// The shell ball's gauge inflation pressure, Pa (law `shell`): what a
    /// pressure study sets each bounce's outcome against.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inflation_pressure: Option<f64>,
    /// e = v_n⁺/v_n⁻, normal, relative to the plate.
    pub restitution: f64,
    /// s.
    pub contact_time: f64,
    /// N.
    pub peak_force: f64,
    pub peak_force_time: f64,
    /// δ_max, m.
    pub max_compression: f64,
    pub max_compression_time: f64,
    /// ∫F dt, N s (gravity's share during contact included).
    pub normal_impulse: f64,
    pub impact_velocity: [f64; 3],
    pub exit_velocity: [f64; 3],
    pub exit_spin: [f64; 3],
    pub tangential: Tangential,
    /// v_z⁺²/(2g), m (with drop_height).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rebound_height: Option<f64>,
    /// Right-hand-side evaluations of the normal phase.
    pub evaluations: u64,
    /// `separated`, or `outside_validity` when δ_max passed the region where
    /// the ball's law holds (`kick_core::validity`: the shell to R/2): the
    /// numbers are kept, and flagged.
    pub status: kick_core::Status,
    /// Why, when outside.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outside_validity: Option<kick_core::OutsideValidity>,
}

/// The 1D normal contact: ball at V_n onto the plate, gravity as the drive
/// (module docs); with the shell, Eq. 20's k, c, n only set the solvers'
/// scales (the small-δ stiffness, linear).
/// The scenario's refusals are in the bounce's own names ([`in_bounce_terms`]).
pub fn normal_scenario(b: &Bounce, normal_speed: f64) -> Result<Scenario, KickError> {
    let scenario = |k, c, n| Scenario::from_values([b.mass, PLATE_MASS, normal_speed, 0.0, k, c, n, b.mass * b.gravity]);
    match b.law {
        BallLaw::Shell(shell) => scenario(shell.small_compression_stiffness(), 0.0, 1.0),
        BallLaw::Kick { kind, stiffness, damping, exponent, restitution } => {
            scenario(stiffness, damping, exponent).and_then(|s| s.with_law(kind, restitution))
        }
    }
    .map_err(|e| in_bounce_terms(b, e))
}

/// The bounce parameters a parameter of the 1D scenario comes from: the
/// ball is the 1D "foot" (its mass, the normal speed V cos θ or √(2gH), the
/// drive its weight m g); the plate, the 1D "ball", is fixed; with the
/// shell, k (n = 1) is 2πR p0 + k_s and there is no c.
fn bounce_names(b: &Bounce, one_d: &str) -> &'static [&'static str] {
    let shell = matches!(b.law, BallLaw::Shell(_));
    match one_d {
        "foot_mass" => &["ball_mass"],
        "foot_speed" if b.drop_height.is_some() => &["drop_height", "gravity"],
        "foot_speed" => &["speed", "angle"],
        "ball_mass" | "ball_speed" => &[],
        "drive_force" => &["ball_mass", "gravity"],
        "stiffness" | "exponent" if shell => &["inflation_pressure", "ball_radius", "shell_stiffness"],
        "damping" if shell => &[],
        "stiffness" => &["stiffness"],
        "exponent" => &["exponent"],
        "damping" => &["damping"],
        _ => &[],
    }
}

/// A refusal of the 1D scenario under the bounce restated in the bounce's
/// parameters (`kick bounce` has no foot_mass or foot_speed).
pub fn in_bounce_terms(b: &Bounce, e: KickError) -> KickError {
    match e {
        KickError::OutOfRange { quantity, value, unit, parameters } => {
            let mut names: Vec<&str> = Vec::new();
            for one_d in parameters.split(", ") {
                match bounce_names(b, one_d) {
                    [] if one_d == "every parameter" => names.push(one_d),
                    mapped => names.extend(mapped.iter().filter(|n| !names.contains(n)).copied().collect::<Vec<_>>()),
                }
            }
            let quantity = match quantity {
                "foot kinetic energy ½ m_f v_f²" => "ball's normal kinetic energy ½ m V_n²",
                "ball kinetic energy ½ m_b v_b²" => "plate's kinetic energy",
                "drive force" => "ball's weight m g",
                other => other,
            };
            KickError::OutOfRange { quantity, value, unit, parameters: interned(names.join(", ")) }
        }
        KickError::InvalidParameter { name, value, requirement } => match bounce_names(b, name).first() {
            Some(&own) => KickError::InvalidParameter { name: own, value, requirement },
            None => KickError::InvalidParameter { name, value, requirement },
        },
        // The 1D proof speaks of the foot and its drive; here the ball's own
        // weight holds it on the plate (physics: no rebound at this speed).
        KickError::Trapped { time, .. } => KickError::Trapped {
            time,
            reason: format!(
                "the ball never leaves the plate, no separation: its weight m g ({}) holds it there, and at the impact \
                 speed of {} m/s ({}) the law stores too little energy to lift it off; {}",
                ["ball_mass", "gravity"].join(", "),
                kick_core::short(b.speed * b.angle.to_radians().cos()),
                bounce_names(b, "foot_speed").join(", "),
                // Only the normal motion is trapped: an oblique ball keeps its motion along the plate.
                if b.angle == 0.0 {
                    "the ball comes to rest on the plate".to_string()
                } else {
                    format!(
                        "its motion along the plate ({} m/s) goes on, no bounce",
                        kick_core::short(b.speed * b.angle.to_radians().sin())
                    )
                }
            ),
        },
        other => other,
    }
}

/// `text` as a `&'static str`, each distinct text allocated once (the
/// lists [`in_bounce_terms`] makes are a few fixed combinations).
fn interned(text: String) -> &'static str {
    static SEEN: std::sync::Mutex<std::collections::BTreeSet<&'static str>> = std::sync::Mutex::new(std::collections::BTreeSet::new());
    let mut seen = SEEN.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some(&known) = seen.get(text.as_str()) {
        return known;
    }
    let leaked: &'static str = Box::leak(text.into_boxed_str());
    seen.insert(leaked);
    leaked
}

/// Which solver runs the normal phase: `Reduced` (Dop853 on the relative
/// coordinate, 1e-12) for results; an independent full-state solve for tests.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalSolver {
    Reduced(Reduced),
    /// Dop853 on the full state (both bodies' positions and velocities).
    Accurate(Accurate),
}

impl Default for NormalSolver {
    fn default() -> Self {
        NormalSolver::Reduced(Reduced::default())
    }
}

impl NormalSolver {
    pub fn solve<L: ContactLaw + Copy>(&self, scenario: &Scenario, law: L) -> Result<Outcome, KickError> {
        match self {
            NormalSolver::Reduced(r) => r.solve_law(scenario, law, None),
            NormalSolver::Accurate(a) => a.solve_law(scenario, law),
        }
    }
}

/// `kick bounce`: build the spec and bounce it with the default solver.
pub fn run(spec: &BounceSpec) -> Result<BounceOutcome, KickError> {
    solve(&spec.build()?, NormalSolver::default())
}

/// Bounce `b`: the normal phase by `solver`, then the tangential impulse.
pub fn solve(b: &Bounce, solver: NormalSolver) -> Result<BounceOutcome, KickError> {
    let (sin, cos) = b.angle.to_radians().sin_cos();
    let v_in = [b.speed * sin, 0.0, -b.speed * cos];
    let normal_speed = b.speed * cos;
    let scenario = normal_scenario(b, normal_speed)?;
    let o = match b.law {
        BallLaw::Shell(shell) => solver.solve(&scenario, shell),
        BallLaw::Kick { .. } => solver.solve::<AnyLaw>(&scenario, scenario.contact_law()),
    }
    .map_err(|e| in_bounce_terms(b, e))?;
    let j_n = o.impulse;
    let r = b.radius;
    let [wx, wy, wz] = b.spin;
    // Slip of the contact point r = (0, 0, −R): v_t + ω × r.
    let u = [v_in[0] - r * wy, v_in[1] + r * wx];
    let slip = u[0].hypot(u[1]);
    let m_t = 1.0 / (1.0 / b.mass + r * r / b.inertia);
    let grip = [-m_t * (1.0 + b.tangential_restitution) * u[0], -m_t * (1.0 + b.tangential_restitution) * u[1]];
    let (j_t, tangential) = if slip == 0.0 {
        ([0.0, 0.0], Tangential::NoSlip)
    } else if b.friction.is_infinite() || grip[0].hypot(grip[1]) <= b.friction * j_n {
        (grip, Tangential::Grips)
    } else {
        let scale = -b.friction * j_n / slip;
        ([scale * u[0], scale * u[1]], Tangential::Slides)
    };
    let v_z = o.restitution * normal_speed;
    let exit_velocity = [v_in[0] + j_t[0] / b.mass, v_in[1] + j_t[1] / b.mass, v_z];
    // Δω = r × J_t / I with r = (0, 0, −R): (R J_y, −R J_x, 0)/I.
    let exit_spin = [wx + r * j_t[1] / b.inertia, wy - r * j_t[0] / b.inertia, wz];
    let rebound_height = b.drop_height.map(|_| v_z * v_z / (2.0 * b.gravity));
    let kind = match b.law {
        BallLaw::Shell(_) => LawKind::Shell,
        BallLaw::Kick { kind, .. } => kind,
    };
    let outside_validity = kick_core::validity::check(kind, b.radius, o.max_compression).err();
    Ok(BounceOutcome {
        inflation_pressure: match b.law {
            BallLaw::Shell(shell) => Some(shell.pressure),
            BallLaw::Kick { .. } => None,
        },
        restitution: o.restitution,
        contact_time: o.contact_time,
        peak_force: o.peak_force,
        peak_force_time: o.peak_force_time,
        max_compression: o.max_compression,
        max_compression_time: o.max_compression_time,
        normal_impulse: j_n,
        impact_velocity: v_in,
        exit_velocity,
        exit_spin,
        tangential,
        rebound_height,
        evaluations: o.evaluations,
        status: if outside_validity.is_some() { kick_core::Status::OutsideValidity } else { kick_core::Status::Separated },
        outside_validity,
    })
}

impl BounceOutcome {
    /// The text form, one quantity a line.
    pub fn text(&self) -> String {
        let v = |x: [f64; 3]| format!("{}, {}, {}", kick_core::sig(x[0]), kick_core::sig(x[1]), kick_core::sig(x[2]));
        let mut s = String::new();
        if let Some(p) = self.inflation_pressure {
            s += &format!("inflation_pressure {} Pa (gauge)\n", kick_core::sig(p));
        }
        s += &format!("restitution       {}\n", kick_core::sig(self.restitution));
        s += &format!("contact_time      {} ms\n", kick_core::sig(self.contact_time * 1e3));
        s += &format!("peak_force        {} N\n", kick_core::sig(self.peak_force));
        s += &format!("max_compression   {} mm\n", kick_core::sig(self.max_compression * 1e3));
        s += &format!("exit_velocity     {} m/s\n", v(self.exit_velocity));
        s += &format!("exit_spin         {} rad/s\n", v(self.exit_spin));
        s += &format!(
            "tangential        {}\n",
            match self.tangential {
                Tangential::NoSlip => "no slip",
                Tangential::Grips => "grips",
                Tangential::Slides => "slides",
            }
        );
        if let Some(h) = self.rebound_height {
            s += &format!("rebound_height    {} m\n", kick_core::sig(h));
        }
        if let Some(outside) = &self.outside_validity {
            s += &format!("status            {}: {outside}\n", self.status.name());
        }
        s
    }
}
