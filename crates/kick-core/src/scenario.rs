//! Scenario parameters of the 1D model (Table 1) and their validation.

use crate::boot::{self, Boot};
use crate::error::KickError;
use crate::law::PowerLawContact;
use crate::laws::{AnyLaw, LawError, LawKind, LawParameters};
use crate::leg::{LegFoot, LegPose};
use crate::parameters::{self, Level, ParameterDef, ParameterError, SetParameter, Value};
use crate::shell::{self, ShellBall};
use serde::{Deserialize, Serialize};

/// See [`Scenario::contact_horizon`].
pub const CONTACT_HORIZON_FACTOR: f64 = 1000.0;

/// Range every scale of a contact (energies, compression, forces, contact
/// time, acceleration) must lie in: products and quotients of three such
/// stay inside double precision's normal range (2.2e-308 .. 1.8e308).
/// Table 1's scenarios sit within 1e-6 .. 1e6 of it.
pub const SCALE_RANGE: (f64, f64) = (1e-100, 1e100);

/// The eight model parameters of a 1D scenario, in the order files and
/// tables list them: the first eight of [`parameters::PARAMETERS`], where
/// each is declared (name, symbol, unit, default, valid range, sampling).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Parameter {
    FootMass,
    BallMass,
    FootSpeed,
    BallSpeed,
    Stiffness,
    Damping,
    Exponent,
    DriveForce,
}

impl Parameter {
    pub const ALL: [Parameter; 8] = [
        Parameter::FootMass,
        Parameter::BallMass,
        Parameter::FootSpeed,
        Parameter::BallSpeed,
        Parameter::Stiffness,
        Parameter::Damping,
        Parameter::Exponent,
        Parameter::DriveForce,
    ];

    /// The declaration of this parameter.
    pub fn def(self) -> &'static ParameterDef {
        &parameters::PARAMETERS[self as usize]
    }

    /// Snake-case name used by the CLI, TOML and HDF5 files.
    pub fn name(self) -> &'static str {
        self.def().name
    }

    /// SI unit; the stiffness unit depends on the exponent (Table 1).
    pub fn unit(self) -> &'static str {
        self.def().unit
    }

    pub fn from_name(name: &str) -> Option<Parameter> {
        Parameter::ALL.into_iter().find(|p| p.name() == name)
    }
}

/// Unvalidated scenario as read from a file or the command line: every field
/// left out takes Table 1's baseline value.
///
/// Read from files by the declared names ([`parameters`]): an unknown key is
/// refused with the nearby valid ones.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct ScenarioSpec {
    pub foot_mass: Option<f64>,
    pub ball_mass: Option<f64>,
    pub foot_speed: Option<f64>,
    pub ball_speed: Option<f64>,
    pub stiffness: Option<f64>,
    pub damping: Option<f64>,
    pub exponent: Option<f64>,
    pub drive_force: Option<f64>,
    /// Contact law (default: the paper's, Eq. 20).
    pub law: Option<LawKind>,
    /// Target restitution of the other laws (they take their damping from it).
    pub restitution: Option<f64>,
    /// The ball of law `shell` ([`ShellBall`]); each left out takes its
    /// declared default, the radius is [`crate::DEFAULT_BALL_RADIUS`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inflation_pressure: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gas_exponent: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shell_stiffness: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shell_damping: Option<f64>,
    /// The foot (Level::Foot): the articulated leg and its pose, the boot.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leg: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub knee: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ankle: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hip: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub boot_stiffness: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub boot_damping: Option<f64>,
}

impl ScenarioSpec {
    pub fn get(&self, parameter: Parameter) -> Option<f64> {
        match parameter {
            Parameter::FootMass => self.foot_mass,
            Parameter::BallMass => self.ball_mass,
            Parameter::FootSpeed => self.foot_speed,
            Parameter::BallSpeed => self.ball_speed,
            Parameter::Stiffness => self.stiffness,
            Parameter::Damping => self.damping,
            Parameter::Exponent => self.exponent,
            Parameter::DriveForce => self.drive_force,
        }
    }

    pub fn set(&mut self, parameter: Parameter, value: f64) {
        let slot = match parameter {
            Parameter::FootMass => &mut self.foot_mass,
            Parameter::BallMass => &mut self.ball_mass,
            Parameter::FootSpeed => &mut self.foot_speed,
            Parameter::BallSpeed => &mut self.ball_speed,
            Parameter::Stiffness => &mut self.stiffness,
            Parameter::Damping => &mut self.damping,
            Parameter::Exponent => &mut self.exponent,
            Parameter::DriveForce => &mut self.drive_force,
        };
        *slot = Some(value);
    }

    /// The value given for the declared parameter `p` (of [`ScenarioSpec::LEVELS`]), if any.
    pub fn value(&self, p: &ParameterDef) -> Option<f64> {
        match Parameter::from_name(p.name) {
            Some(q) => self.get(q),
            None if p.name == parameters::RESTITUTION.name => self.restitution,
            None if p.name == parameters::KNEE.name => self.knee,
            None if p.name == parameters::ANKLE.name => self.ankle,
            None if p.name == parameters::HIP.name => self.hip,
            None if p.name == parameters::BOOT_STIFFNESS.name => self.boot_stiffness,
            None if p.name == parameters::BOOT_DAMPING.name => self.boot_damping,
            None => self.given_ball().find(|(b, _)| b.name == p.name).map(|(_, v)| v),
        }
    }

    /// This spec with a file's top-level `law` and `restitution` keys, the
    /// place experiment files give them. `Err(key)` names a key that the
    /// scenario table sets too: the law is chosen in one place.
    pub fn with_law_keys(mut self, law: Option<LawKind>, restitution: Option<f64>) -> Result<ScenarioSpec, &'static str> {
        if law.is_some() && self.law.is_some() {
            return Err("law");
        }
        if restitution.is_some() && self.restitution.is_some() {
            return Err("restitution");
        }
        self.law = law.or(self.law);
        self.restitution = restitution.or(self.restitution);
        Ok(self)
    }

    /// Fill the gaps from Table 1 and validate; a damping setting the law
    /// would ignore is refused ([`ScenarioSpec::check_given`]).
    pub fn build(&self) -> Result<Scenario, KickError> {
        self.check_given()?;
        self.build_drawn()
    }

    /// Refuse `damping` under a law that takes a restitution, and
    /// `restitution` under the paper's law ([`LawKind::check_given`]).
    pub fn check_given(&self) -> Result<(), KickError> {
        let law = self.law.unwrap_or(LawKind::PowerLaw);
        law.check_given(self.damping.is_some(), self.restitution.is_some())?;
        if law != LawKind::Shell {
            if let Some((p, _)) = self.given_ball().next() {
                return Err(KickError::DoesNotApply {
                    given: p.name,
                    to: format!("law `{}`", law.name()),
                    reason: "it is a parameter of law shell (the pressurised ball)",
                });
            }
        }
        if self.leg == Some(true) && self.foot_mass.is_some() {
            return Err(KickError::DoesNotApply {
                given: "foot_mass",
                to: "the leg (`leg`)".into(),
                reason: "the leg's apparent mass at the contact point is the foot's (Eq. 11); pose it with knee, ankle and hip",
            });
        }
        self.foot().map(|_| ())
    }

    /// The foot this spec gives: the leg when `leg` is on (its pose from
    /// `knee`, `ankle`, `hip`, declared defaults for the rest) and the boot,
    /// given by `boot_stiffness`, else the identified one with the leg
    /// ([`boot::IDENTIFIED`]), else none (the rigid foot of Table 1). A pose
    /// without the leg, or a boot damping without a boot, is refused by name.
    pub fn foot(&self) -> Result<Foot, KickError> {
        let leg = self.leg == Some(true);
        if !leg {
            let pose = [(&parameters::KNEE, self.knee), (&parameters::ANKLE, self.ankle), (&parameters::HIP, self.hip)];
            if let Some((p, _)) = pose.iter().find(|(_, v)| v.is_some()) {
                return Err(KickError::DoesNotApply {
                    given: p.name,
                    to: "a foot without the leg".into(),
                    reason: "the pose sets the leg's apparent inertia; give `leg` too",
                });
            }
        }
        let pose = leg
            .then(|| -> Result<LegPose, KickError> {
                let or = |v: Option<f64>, p: &ParameterDef| p.check(v.unwrap_or(p.default_number()));
                Ok(LegPose {
                    hip: or(self.hip, &parameters::HIP)?,
                    knee: or(self.knee, &parameters::KNEE)?,
                    ankle: or(self.ankle, &parameters::ANKLE)?,
                })
            })
            .transpose()?;
        let boot = match (self.boot_stiffness, leg) {
            (Some(k), _) => Boot::new(k, self.boot_damping.unwrap_or(boot::IDENTIFIED.damping))?,
            (None, true) => Boot::new(boot::IDENTIFIED.stiffness, self.boot_damping.unwrap_or(boot::IDENTIFIED.damping))?,
            (None, false) if self.boot_damping.is_some() => {
                return Err(KickError::DoesNotApply {
                    given: "boot_damping",
                    to: "the rigid foot".into(),
                    reason: "it damps the boot in series; give `boot_stiffness` (or `leg`, which brings the identified boot)",
                })
            }
            (None, false) => None,
        };
        Ok(Foot { leg: pose, boot })
    }

    /// The shell ball's parameters given, with their declarations (for the
    /// law's check and for command lines a file records).
    pub fn given_ball(&self) -> impl Iterator<Item = (&'static ParameterDef, f64)> {
        [
            (&shell::INFLATION_PRESSURE, self.inflation_pressure),
            (&shell::GAS_EXPONENT, self.gas_exponent),
            (&shell::SHELL_STIFFNESS, self.shell_stiffness),
            (&shell::SHELL_DAMPING, self.shell_damping),
        ]
        .into_iter()
        .filter_map(|(p, v)| v.map(|v| (p, v)))
    }

    /// The ball of law `shell`: given values, declared defaults for the rest.
    pub fn shell_ball(&self) -> Result<ShellBall, KickError> {
        let or = |v: Option<f64>, p: &ParameterDef| v.unwrap_or(p.default_number());
        ShellBall::new(
            or(self.inflation_pressure, &shell::INFLATION_PRESSURE),
            crate::DEFAULT_BALL_RADIUS,
            or(self.gas_exponent, &shell::GAS_EXPONENT),
            or(self.shell_stiffness, &shell::SHELL_STIFFNESS),
            or(self.shell_damping, &shell::SHELL_DAMPING),
        )
    }

    /// As [`ScenarioSpec::build`] without [`ScenarioSpec::check_given`]: for
    /// samplers that draw every parameter whatever the law (`kick sweep3d`),
    /// whose `damping` is not the user's. Front ends call `build`.
    pub fn build_drawn(&self) -> Result<Scenario, KickError> {
        self.build_on_line(true)
    }

    /// [`ScenarioSpec::build`] for a 3D kick's base: the foot's and the
    /// ball's speeds along their own directions, the approach checked along
    /// the contact normal by kick-3d ([`Scenario::each_parameter`]).
    pub fn build_3d_base(&self) -> Result<Scenario, KickError> {
        self.check_given()?;
        self.build_drawn_3d_base()
    }

    /// [`ScenarioSpec::build_drawn`] for a 3D kick's base ([`ScenarioSpec::build_3d_base`]).
    pub fn build_drawn_3d_base(&self) -> Result<Scenario, KickError> {
        self.build_on_line(false)
    }

    /// The scenario, its approach along one line checked or (a 3D kick's base) not.
    fn build_on_line(&self, one_line: bool) -> Result<Scenario, KickError> {
        let scenario = self.build_on_line_unchecked(one_line)?;
        check_boot_resolution(&scenario).map_err(|e| match (e, self.boot_stiffness, self.boot_damping) {
            // The layer's time constant is c_b/k_b: the one of the two the user gave is named.
            (KickError::InvalidParameter { name: "boot_stiffness", requirement, .. }, None, Some(damping)) => {
                KickError::InvalidParameter { name: "boot_damping", value: damping, requirement }
            }
            (e, ..) => e,
        })?;
        Ok(scenario)
    }

    fn build_on_line_unchecked(&self, one_line: bool) -> Result<Scenario, KickError> {
        let base = Scenario::BASELINE;
        let mut values = [0.0; 8];
        for (slot, p) in values.iter_mut().zip(Parameter::ALL) {
            *slot = self.get(p).unwrap_or_else(|| base.get(p));
        }
        let foot = self.foot()?;
        // The leg's mass along the line of motion is the 1D foot's (Eq. 11).
        if let Some(pose) = foot.leg {
            values[0] = LegFoot::new(pose)?.effective_mass;
        }
        if one_line {
            return Ok(self.law_on(Scenario::from_values(values)?)?.with_foot(foot));
        }
        let scenario = Scenario::each_parameter(values)?;
        let lawful = match self.law.unwrap_or(LawKind::PowerLaw) {
            LawKind::Shell => scenario.with_shell(self.shell_ball()?),
            law => scenario.with_law_3d_base(law, self.restitution)?,
        };
        Ok(lawful.with_foot(foot))
    }

    /// `scenario` under this spec's law: its target restitution, or for the
    /// shell law its ball (given values, declared defaults for the rest).
    pub fn law_on(&self, scenario: Scenario) -> Result<Scenario, KickError> {
        match self.law.unwrap_or(LawKind::PowerLaw) {
            LawKind::Shell => Ok(scenario.with_shell(self.shell_ball()?)),
            law => scenario.with_law(law, self.restitution),
        }
    }
}

/// The shortest boot time constant c_b/k_b, as a share of the undamped
/// contact time ([`Scenario::elastic_contact_time`]), that the solvers
/// resolve: the layer relaxes on that scale and the steps follow it. At
/// Table 1's c_b, the paper's law solved up to k_b = 5e9 N/m (1.4e-6) and
/// the shell ball's Taylor series to 1.5e9 (4.6e-6, failing at 2e9 after
/// its 20,000 steps); k_b = 1e10 ran every solver out of its budget and was
/// reported as "no separation found". Twice the series' limit: the largest
/// k_b accepted at c_b = 38.3 N s/m, 7e8 N/m, compresses 4 µm under 3 kN.
pub const BOOT_TIME_SHARE: f64 = 1e-5;

/// Refuse a boot whose layer relaxes faster than the solvers resolve
/// ([`BOOT_TIME_SHARE`]), naming `boot_stiffness`: it is rigid at that
/// resolution, and `inf` says so.
fn check_boot_resolution(scenario: &Scenario) -> Result<(), KickError> {
    let (Some(boot), contact) = (scenario.foot.boot, scenario.elastic_contact_time()) else { return Ok(()) };
    // (A 3D base whose ball is faster along the line has no contact time here: kick-3d's normal scenario is checked.)
    if contact.is_finite() && contact > 0.0 && boot.damping / boot.stiffness < BOOT_TIME_SHARE * contact {
        return Err(KickError::InvalidParameter {
            name: "boot_stiffness",
            value: boot.stiffness,
            requirement:
                "such that the layer's time constant c_b/k_b is at least 1e-5 of the contact time (a stiffer layer: give boot_stiffness = inf, the rigid foot)",
        });
    }
    Ok(())
}

impl SetParameter for ScenarioSpec {
    const LEVELS: &'static [Level] = &[Level::Scenario, Level::Bounce, Level::Foot];

    fn set_parameter(&mut self, parameter: &'static ParameterDef, value: Value) -> Result<(), ParameterError> {
        if parameter.name == parameters::LEG.name {
            self.leg = Some(parameters::switch(parameter, value)?);
            return Ok(());
        }
        let x = parameters::number(parameter, value)?;
        let name = parameter.name;
        match Parameter::from_name(name) {
            Some(p) => self.set(p, x),
            None if name == parameters::RESTITUTION.name => self.restitution = Some(x),
            None if name == shell::INFLATION_PRESSURE.name => self.inflation_pressure = Some(x),
            None if name == shell::GAS_EXPONENT.name => self.gas_exponent = Some(x),
            None if name == shell::SHELL_STIFFNESS.name => self.shell_stiffness = Some(x),
            None if name == shell::SHELL_DAMPING.name => self.shell_damping = Some(x),
            None if name == parameters::KNEE.name => self.knee = Some(x),
            None if name == parameters::ANKLE.name => self.ankle = Some(x),
            None if name == parameters::HIP.name => self.hip = Some(x),
            None if name == parameters::BOOT_STIFFNESS.name => self.boot_stiffness = Some(x),
            None if name == parameters::BOOT_DAMPING.name => self.boot_damping = Some(x),
            None => return Err(parameters::unknown(Self::LEVELS, parameter.name)),
        }
        Ok(())
    }
}

#[cfg(test)]
mod value_tests {
    use super::*;

    /// Every declared number of the spec's levels comes back as given.
    #[test]
    fn every_parameter_set_comes_back() {
        for p in parameters::at_levels(ScenarioSpec::LEVELS).filter(|p| p.shape == parameters::Shape::Scalar) {
            let mut spec = ScenarioSpec::default();
            assert_eq!(spec.value(p), None, "{}", p.name);
            spec.set_parameter(p, Value::Number(0.25)).unwrap();
            assert_eq!(spec.value(p), Some(0.25), "{}", p.name);
        }
    }
}

impl parameters::SetLaw for ScenarioSpec {
    fn set_law(&mut self, law: LawKind) {
        self.law = Some(law);
    }
}

/// A [`ScenarioSpec`] table: the declared parameters of the 1D level and
/// `law`, the key that chooses the contact law.
impl parameters::DeclaredTable for ScenarioSpec {
    const EXTRA: &'static [&'static str] = &["law"];
    fn read_extra<'de, A: serde::de::MapAccess<'de>>(&mut self, _key: &str, map: &mut A) -> Result<(), A::Error> {
        self.law = map.next_value()?;
        Ok(())
    }
}

impl<'de> Deserialize<'de> for ScenarioSpec {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        parameters::deserialize_table(deserializer)
    }
}

/// A validated 1D scenario: masses, initial speeds and the paper's contact law.
///
/// Construction checks every field, so solvers may assume positive masses,
/// stiffness and exponent, non-negative damping, finite speeds and an
/// approaching foot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Scenario {
    foot_mass: f64,
    ball_mass: f64,
    foot_speed: f64,
    ball_speed: f64,
    stiffness: f64,
    damping: f64,
    exponent: f64,
    drive_force: f64,
    /// The contact law in use: Eq. 20 from the fields above unless another is chosen.
    contact: AnyLaw,
    /// Target restitution when a law other than the paper's is chosen.
    restitution_target: Option<f64>,
    /// The foot behind the contact: the leg's pose (then `foot_mass` is its
    /// apparent mass) and the boot in series.
    foot: Foot,
}

/// The foot behind the contact (Level::Foot): `leg` the pose of the
/// articulated leg when the foot is the leg ([`LegFoot`]), `boot` the layer
/// in series ([`Boot`]); neither is Table 1's rigid foot of mass `foot_mass`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Foot {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub leg: Option<LegPose>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub boot: Option<Boot>,
}

impl Foot {
    /// Table 1's: rigid, no leg.
    pub const RIGID: Foot = Foot { leg: None, boot: None };

    /// The foot's settings by name, for result files and JSON (the leg's
    /// pose and switch, the boot's two numbers), in declaration order.
    pub fn settings(&self) -> Vec<(&'static str, f64)> {
        let mut out = Vec::new();
        if let Some(pose) = self.leg {
            out.extend([
                (parameters::LEG.name, 1.0),
                (parameters::KNEE.name, pose.knee),
                (parameters::ANKLE.name, pose.ankle),
                (parameters::HIP.name, pose.hip),
            ]);
        }
        match self.boot {
            Some(boot) => out.extend(boot.parameters()),
            // The leg brings a boot unless told there is none.
            None if self.leg.is_some() => out.push((parameters::BOOT_STIFFNESS.name, f64::INFINITY)),
            None => {}
        }
        out
    }
}

impl Scenario {
    /// Table 1's baseline.
    pub const BASELINE: Scenario = Scenario {
        foot_mass: parameters::FOOT_MASS.default_number(),
        ball_mass: parameters::BALL_MASS.default_number(),
        foot_speed: parameters::FOOT_SPEED.default_number(),
        ball_speed: parameters::BALL_SPEED.default_number(),
        stiffness: parameters::STIFFNESS.default_number(),
        damping: parameters::DAMPING.default_number(),
        exponent: parameters::EXPONENT.default_number(),
        drive_force: parameters::DRIVE_FORCE.default_number(),
        contact: AnyLaw::PowerLaw(PowerLawContact {
            stiffness: parameters::STIFFNESS.default_number(),
            damping: parameters::DAMPING.default_number(),
            exponent: parameters::EXPONENT.default_number(),
        }),
        restitution_target: None,
        foot: Foot::RIGID,
    };

    pub fn baseline() -> Scenario {
        Scenario::BASELINE
    }

    /// Validate values given in [`Parameter::ALL`] order.
    pub fn from_values(values: [f64; 8]) -> Result<Scenario, KickError> {
        let scenario = Scenario::each_parameter(values)?;
        // The foot must close the gap (Eq. 48's start: v_f > v_b), and the
        // relative speed must be representable next to the absolute speeds.
        let (foot_speed, ball_speed) = (scenario.foot_speed, scenario.ball_speed);
        let approach = foot_speed - ball_speed;
        if !(approach > 0.0) || !approach.is_finite() {
            return Err(KickError::NoContact { foot_speed, ball_speed });
        }
        scenario.check_scales()?;
        Ok(scenario)
    }

    /// Each value checked against its declaration, but not the contact
    /// they make along one line: the base of a 3D kick, whose foot and ball
    /// move along different directions and close along the contact normal,
    /// where kick-3d's `Kick3d::new` checks them (its normal scenario is
    /// [`Scenario::from_values`]'s).
    pub fn each_parameter(values: [f64; 8]) -> Result<Scenario, KickError> {
        let [foot_mass, ball_mass, foot_speed, ball_speed, stiffness, damping, exponent, drive_force] = values;
        let check = |p: Parameter, v: f64| p.def().check(v);
        let scenario = Scenario {
            foot_mass: check(Parameter::FootMass, foot_mass)?,
            ball_mass: check(Parameter::BallMass, ball_mass)?,
            foot_speed: check(Parameter::FootSpeed, foot_speed)?,
            ball_speed: check(Parameter::BallSpeed, ball_speed)?,
            stiffness: check(Parameter::Stiffness, stiffness)?,
            damping: check(Parameter::Damping, damping)?,
            exponent: check(Parameter::Exponent, exponent)?,
            drive_force: check(Parameter::DriveForce, drive_force)?,
            contact: AnyLaw::PowerLaw(PowerLawContact { stiffness, damping, exponent }),
            restitution_target: None,
            foot: Foot::RIGID,
        };
        Ok(scenario)
    }

    /// Each parameter may be valid and the contact they make still leave
    /// double precision: 1e308 kg at 1e308 m/s has no finite energy. Every
    /// scale of the contact must lie within [`SCALE_RANGE`], so that the
    /// solvers' products of up to three of them (work = force x speed x
    /// time) stay finite and normal; the error names the quantity and the
    /// parameters it comes from.
    fn check_scales(&self) -> Result<(), KickError> {
        const MASSES_AND_SPEEDS: &str = "foot_mass, ball_mass, foot_speed, ball_speed";
        const CONTACT: &str = "foot_mass, ball_mass, foot_speed, ball_speed, stiffness, exponent";
        let law = self.paper_law();
        let approach = self.approach_speed();
        let compression = self.elastic_max_compression();
        let force = law.stiffness * compression.powf(law.exponent);
        let time = self.elastic_contact_time();
        let acceleration = (force + law.damping * approach + self.drive_force.abs()) / self.foot_mass.min(self.ball_mass);
        // (quantity, value, unit, from which parameters, whether it may be 0)
        let scales = [
            ("foot kinetic energy ½ m_f v_f²", 0.5 * self.foot_mass * self.foot_speed.powi(2), "J", "foot_mass, foot_speed", true),
            ("ball kinetic energy ½ m_b v_b²", 0.5 * self.ball_mass * self.ball_speed.powi(2), "J", "ball_mass, ball_speed", true),
            ("impact energy ½ μ V0²", self.relative_kinetic_energy(), "J", MASSES_AND_SPEEDS, false),
            ("elastic maximum compression", compression, "m", CONTACT, false),
            ("elastic peak force k δ_max^n", force, "N", CONTACT, false),
            ("elastic contact time", time, "s", CONTACT, false),
            ("damping force c V0", law.damping * approach, "N", "damping, foot_speed, ball_speed", true),
            ("drive force", self.drive_force.abs(), "N", "drive_force", true),
            ("largest acceleration (forces over the lighter mass)", acceleration, "m/s²", "every parameter", false),
        ];
        for (quantity, value, unit, parameters, may_be_zero) in scales {
            let inside = (SCALE_RANGE.0..=SCALE_RANGE.1).contains(&value) || (may_be_zero && value == 0.0);
            if !inside {
                return Err(KickError::OutOfRange { quantity, value, unit, parameters });
            }
        }
        Ok(())
    }

    pub fn get(&self, parameter: Parameter) -> f64 {
        match parameter {
            Parameter::FootMass => self.foot_mass,
            Parameter::BallMass => self.ball_mass,
            Parameter::FootSpeed => self.foot_speed,
            Parameter::BallSpeed => self.ball_speed,
            Parameter::Stiffness => self.stiffness,
            Parameter::Damping => self.damping,
            Parameter::Exponent => self.exponent,
            Parameter::DriveForce => self.drive_force,
        }
    }

    pub fn values(&self) -> [f64; 8] {
        Parameter::ALL.map(|p| self.get(p))
    }

    /// A copy with one parameter changed, validated again (the law choice kept).
    pub fn with(&self, parameter: Parameter, value: f64) -> Result<Scenario, KickError> {
        let mut values = self.values();
        values[Parameter::ALL.iter().position(|&p| p == parameter).unwrap_or(0)] = value;
        self.with_values(values)
    }

    /// A copy with the declared parameter `p` (of [`ScenarioSpec::LEVELS`])
    /// at `value`, validated again: one of the eight, the target
    /// restitution, or the shell ball's (refused under another law).
    pub fn with_parameter(&self, p: &'static ParameterDef, value: f64) -> Result<Scenario, KickError> {
        if let Some(q) = Parameter::from_name(p.name) {
            return self.with(q, value);
        }
        if p.name == parameters::RESTITUTION.name {
            return self.with_law(self.law_kind(), Some(value));
        }
        let mut spec = self.spec();
        spec.set_parameter(p, Value::Number(value))
            .map_err(|_| KickError::invalid(p.name, value, "a number of the 1D scenario or its ball"))?;
        spec.check_given()?;
        match self.contact {
            AnyLaw::Shell(b) => {
                let ball = spec.shell_ball()?;
                Ok(self.with_shell(ShellBall::new(ball.pressure, b.radius, ball.gas_exponent, ball.shell_stiffness, ball.shell_damping)?))
            }
            _ => Ok(*self),
        }
    }

    /// A copy with all eight values replaced (in [`Parameter::ALL`] order),
    /// validated again, the law choice kept: its kind, its target
    /// restitution (the damping recomputed at the new impact speed) and the
    /// shell law's ball.
    pub fn with_values(&self, values: [f64; 8]) -> Result<Scenario, KickError> {
        if self.foot.leg.is_some() && values[0] != self.foot_mass {
            return Err(KickError::DoesNotApply {
                given: "foot_mass",
                to: "the leg (`leg`)".into(),
                reason: "the leg's apparent mass at the contact point is the foot's (Eq. 11); pose it with knee, ankle and hip",
            });
        }
        let scenario = Scenario::from_values(values)?.with_foot(self.foot);
        match self.contact {
            AnyLaw::Shell(ball) => Ok(scenario.with_shell(ball)),
            _ => scenario.with_law(self.law_kind(), self.restitution_target),
        }
    }

    /// A copy with the foot `foot` behind the contact, the mass unchanged
    /// (see [`Scenario::on_foot`] for a leg's).
    pub fn with_foot(&self, foot: Foot) -> Scenario {
        Scenario { foot, ..*self }
    }

    /// A copy on the foot `foot`: with a leg its apparent mass along the
    /// line of motion is the foot's mass (Eq. 11), validated again.
    pub fn on_foot(&self, foot: Foot) -> Result<Scenario, KickError> {
        let rigid = Scenario { foot: Foot::RIGID, ..*self };
        let moved = match foot.leg {
            Some(pose) => rigid.with(Parameter::FootMass, LegFoot::new(pose)?.effective_mass)?,
            None => rigid,
        };
        Ok(moved.with_foot(foot))
    }

    /// The foot behind the contact: the leg's pose and the boot.
    pub fn foot(&self) -> Foot {
        self.foot
    }

    /// The boot in series, if any.
    pub fn boot(&self) -> Option<Boot> {
        self.foot.boot
    }

    /// A copy whose contact is the pressurised ball `ball` (law `shell`):
    /// set by the ball's own quantities, with no target restitution.
    pub fn with_shell(&self, ball: ShellBall) -> Scenario {
        Scenario { contact: AnyLaw::Shell(ball), restitution_target: None, ..*self }
    }

    /// A copy with another contact law. The paper's law takes its damping
    /// from `damping`; the others take k and n from the scenario and their
    /// damping from the target `restitution` e in (0, 1] at this impact speed.
    pub fn with_law(&self, kind: LawKind, restitution: Option<f64>) -> Result<Scenario, KickError> {
        if kind == LawKind::PowerLaw {
            return Ok(Scenario { contact: AnyLaw::PowerLaw(self.paper_law()), restitution_target: None, ..*self });
        }
        if kind == LawKind::Shell {
            // The ball in use, else the declared defaults ([`ScenarioSpec::shell_ball`]).
            let ball = match self.contact {
                AnyLaw::Shell(ball) => ball,
                _ => ScenarioSpec::default().shell_ball()?,
            };
            return Ok(self.with_shell(ball));
        }
        let restitution = restitution.ok_or(KickError::InvalidParameter {
            name: "restitution",
            value: f64::NAN,
            requirement: "given (a target restitution in (0, 1]) for every law but the paper's",
        })?;
        parameters::RESTITUTION.check(restitution)?;
        let parameters = LawParameters {
            stiffness: self.stiffness,
            exponent: self.exponent,
            damping: self.damping,
            restitution,
            impact_speed: self.approach_speed(),
            reduced_mass: self.reduced_mass(),
            // Kelvin–Voigt's linear spring: the secant stiffness k δ*ⁿ⁻¹ at
            // the undamped maximum compression of this law.
            linear_stiffness: self.stiffness * self.elastic_max_compression().powf(self.exponent - 1.0),
            shell: None,
        };
        let contact = AnyLaw::new(kind, &parameters).map_err(|e| match e {
            LawError::Invalid(error) => error,
            // AnyLaw::new is given a known kind, so only invalid values remain.
            LawError::UnknownLaw { .. } => KickError::InvalidParameter { name: "law", value: f64::NAN, requirement: "a known contact law" },
        })?;
        Ok(Scenario { contact, restitution_target: Some(restitution), ..*self })
    }

    /// [`Scenario::with_law`] for a 3D kick's base ([`Scenario::each_parameter`]),
    /// whose ball may be faster along the foot's line than the foot: only the
    /// law's kind and target matter then, kick-3d builds the law again along
    /// the contact normal (`Kick3d::normal_scenario`), where the bodies close;
    /// a law set by a restitution is built on the foot's speed alone meanwhile.
    pub fn with_law_3d_base(&self, kind: LawKind, restitution: Option<f64>) -> Result<Scenario, KickError> {
        if self.approach_speed() > 0.0 {
            return self.with_law(kind, restitution);
        }
        let lawful = Scenario { ball_speed: 0.0, ..*self }.with_law(kind, restitution)?;
        Ok(Scenario { ball_speed: self.ball_speed, ..lawful })
    }

    /// The contact law in use: the one chosen (`with_law`), Eq. 20 by default.
    /// Solvers integrate this one; [`Scenario::paper_law`] is Eq. 20 whatever
    /// the choice.
    pub fn contact_law(&self) -> AnyLaw {
        self.contact
    }

    pub fn law_kind(&self) -> LawKind {
        self.contact.kind()
    }

    /// Whether `outcome`, a contact of this scenario, stayed where its law
    /// holds ([`crate::validity`]); R is the shell ball's radius, else the
    /// default ball's (the 1D model's own laws carry none).
    pub fn check_validity(&self, outcome: &crate::Outcome) -> Result<(), crate::OutsideValidity> {
        let radius = match self.contact {
            AnyLaw::Shell(ball) => ball.radius,
            _ => crate::DEFAULT_BALL_RADIUS,
        };
        crate::validity::check(self.law_kind(), radius, outcome.max_compression)
    }

    /// Target restitution of a law other than the paper's.
    pub fn restitution_target(&self) -> Option<f64> {
        self.restitution_target
    }

    /// The spec that builds this scenario: every parameter its law takes
    /// (`damping` only under the paper's law, see [`LawKind::check_given`]).
    pub fn spec(&self) -> ScenarioSpec {
        let mut spec = ScenarioSpec::default();
        for p in Parameter::ALL {
            if p != Parameter::Damping || self.law_kind() == LawKind::PowerLaw {
                spec.set(p, self.get(p));
            }
        }
        spec.law = Some(self.law_kind());
        spec.restitution = self.restitution_target;
        if let AnyLaw::Shell(b) = self.contact {
            // Under the shell the damping and the law's own k, n are not used.
            spec.inflation_pressure = Some(b.pressure);
            spec.gas_exponent = Some(b.gas_exponent);
            spec.shell_stiffness = Some(b.shell_stiffness);
            spec.shell_damping = Some(b.shell_damping);
        }
        if let Some(pose) = self.foot.leg {
            // The leg sets the foot's mass.
            spec.foot_mass = None;
            (spec.leg, spec.knee, spec.ankle, spec.hip) = (Some(true), Some(pose.knee), Some(pose.ankle), Some(pose.hip));
        }
        match self.foot.boot {
            Some(b) => (spec.boot_stiffness, spec.boot_damping) = (Some(b.stiffness), Some(b.damping)),
            // The leg brings a boot unless told there is none.
            None if self.foot.leg.is_some() => spec.boot_stiffness = Some(f64::INFINITY),
            None => {}
        }
        spec
    }

    /// m_f, the effective foot mass (Eq. 11–12).
    pub fn effective_foot_mass(&self) -> f64 {
        self.foot_mass
    }
    /// m_b.
    pub fn ball_mass(&self) -> f64 {
        self.ball_mass
    }
    /// v_f⁻.
    pub fn foot_speed(&self) -> f64 {
        self.foot_speed
    }
    /// v_b⁻.
    pub fn ball_speed(&self) -> f64 {
        self.ball_speed
    }
    pub fn drive_force(&self) -> f64 {
        self.drive_force
    }
    /// The paper's law (Eq. 20) with this scenario's k, c and n, whatever
    /// law is in use: for the paper's own closed forms and series. The law
    /// the solvers integrate is [`Scenario::contact_law`].
    pub fn paper_law(&self) -> PowerLawContact {
        PowerLawContact { stiffness: self.stiffness, damping: self.damping, exponent: self.exponent }
    }
    pub fn total_mass(&self) -> f64 {
        self.foot_mass + self.ball_mass
    }
    /// μ (Eq. 17).
    pub fn reduced_mass(&self) -> f64 {
        self.foot_mass * self.ball_mass / (self.foot_mass + self.ball_mass)
    }
    /// V0 = v_f⁻ − v_b⁻ (Eq. 45), positive by construction.
    pub fn approach_speed(&self) -> f64 {
        self.foot_speed - self.ball_speed
    }
    /// V_cm before contact (Eq. 28).
    pub fn centre_of_mass_speed(&self) -> f64 {
        (self.foot_mass * self.foot_speed + self.ball_mass * self.ball_speed) / self.total_mass()
    }
    /// K⁻ (Eq. 30).
    pub fn initial_kinetic_energy(&self) -> f64 {
        0.5 * self.foot_mass * self.foot_speed.powi(2) + 0.5 * self.ball_mass * self.ball_speed.powi(2)
    }
    /// K_rel⁻ = ½ μ V0² (Eq. 56).
    pub fn relative_kinetic_energy(&self) -> f64 {
        0.5 * self.reduced_mass() * self.approach_speed().powi(2)
    }
    /// δ_max of the undamped, undriven contact (Eqs. 33–34 with equality).
    pub fn elastic_max_compression(&self) -> f64 {
        self.paper_law().compression_for_energy(self.relative_kinetic_energy())
    }
    /// Contact time of the undamped, undriven contact: twice the Beta-function
    /// return time (see `special::return_time`).
    pub fn elastic_contact_time(&self) -> f64 {
        2.0 * crate::special::return_time(self.elastic_max_compression(), self.approach_speed(), self.exponent)
    }
    /// Time after which a contact that has not ended is reported as
    /// [`KickError::NoSeparation`]: `CONTACT_HORIZON_FACTOR` times the undamped,
    /// undriven contact time of the same masses, stiffness and speeds.
    pub fn contact_horizon(&self) -> f64 {
        CONTACT_HORIZON_FACTOR * self.elastic_contact_time()
    }
    /// ζ (Eq. 46), a local guide only for n ≠ 1.
    pub fn damping_ratio(&self) -> f64 {
        self.damping / (2.0 * (self.stiffness * self.reduced_mass()).sqrt())
    }
}

impl Default for Scenario {
    fn default() -> Self {
        Scenario::BASELINE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A spec reads the declared names (and `law`), leaves `null` unset and
    /// refuses any other key with the nearby names.
    #[test]
    fn specs_read_the_declared_names_only() {
        let spec: ScenarioSpec =
            serde_json::from_str(r#"{"foot_mass": 2.5, "damping": null, "law": "flores", "restitution": 0.6}"#).unwrap();
        let expected = ScenarioSpec { foot_mass: Some(2.5), law: Some(LawKind::Flores), restitution: Some(0.6), ..Default::default() };
        assert_eq!(spec, expected);
        assert_eq!(serde_json::from_str::<ScenarioSpec>(&serde_json::to_string(&spec).unwrap()).unwrap(), spec);
        let error = serde_json::from_str::<ScenarioSpec>(r#"{"foot_mass": 2.5, "lw": "flores"}"#).unwrap_err();
        assert!(error.to_string().contains("unknown key `lw`: did you mean `law`?"), "{error}");
        let mut by_name = ScenarioSpec::default();
        by_name.set_named("restitution", Value::Number(0.6)).unwrap();
        assert_eq!(by_name.restitution, Some(0.6));
        assert!(by_name.set_named("offset", Value::Number(0.1)).is_err());
    }

    /// A damping setting the chosen law would ignore is refused, naming the
    /// setting and the law; the setting the law takes is accepted.
    #[test]
    fn settings_a_law_ignores_are_refused() {
        let spec = |law, damping, restitution| ScenarioSpec { law, damping, restitution, ..Default::default() };
        let message = |s: ScenarioSpec| s.build().unwrap_err().to_string();
        let e = message(spec(None, None, Some(0.5)));
        assert!(e.starts_with("`restitution` does not apply to law `power-law`"), "{e}");
        let e = message(spec(Some(LawKind::PowerLaw), Some(100.0), Some(0.5)));
        assert!(e.starts_with("`restitution` does not apply to law `power-law`"), "{e}");
        let e = message(spec(Some(LawKind::Flores), Some(100.0), Some(0.5)));
        assert!(e.starts_with("`damping` does not apply to law `flores`"), "{e}");
        assert!(e.contains("`restitution`"), "{e}");
        assert_eq!(spec(Some(LawKind::Flores), Some(100.0), Some(0.5)).build().unwrap_err().status(), crate::Status::Refused);
        // What each law takes still builds, and a scenario's spec builds it again.
        assert_eq!(spec(None, Some(100.0), None).build().unwrap().paper_law().damping, 100.0);
        let flores = spec(Some(LawKind::Flores), None, Some(0.5)).build().unwrap();
        assert_eq!(flores.restitution_target(), Some(0.5));
        assert_eq!(flores.spec().build().unwrap(), flores);
    }

    /// `leg = true` (a TOML key, a flag, a keyword: one declaration) makes
    /// the foot the leg: its apparent mass along the line of motion (Eq. 11,
    /// `kick leg --locked-ankle`'s 1.327 kg at the default pose) and the
    /// identified boot; the pose moves the mass; a boot is given alone by its
    /// stiffness (inf: none); settings that would be ignored are refused by name.
    #[test]
    fn the_leg_and_the_boot_are_built_from_their_keys() {
        let leg: ScenarioSpec = toml::from_str("leg = true\n").unwrap();
        let s = leg.build().unwrap();
        assert!((s.effective_foot_mass() - 1.32686).abs() < 1e-5, "{}", s.effective_foot_mass());
        assert_eq!(s.foot(), Foot { leg: Some(LegPose::DEFAULT), boot: Some(boot::IDENTIFIED) });
        assert_eq!(s.spec().build().unwrap(), s);
        let bent: ScenarioSpec = toml::from_str("leg = true\nknee = 60.0\nankle = 45.0\nboot_stiffness = inf\n").unwrap();
        let b = bent.build().unwrap();
        assert!(b.effective_foot_mass() != s.effective_foot_mass());
        assert_eq!(b.boot(), None);
        assert_eq!(b.spec().build().unwrap(), b);
        // A changed speed keeps the foot; a changed mass is refused under the leg.
        assert_eq!(s.with(Parameter::FootSpeed, 15.0).unwrap().foot(), s.foot());
        assert!(s.with(Parameter::FootMass, 3.0).unwrap_err().to_string().starts_with("`foot_mass` does not apply to the leg"));
        let boot: ScenarioSpec = toml::from_str("boot_stiffness = 5.0e4\n").unwrap();
        let k = boot.build().unwrap();
        assert_eq!(k.effective_foot_mass(), 3.0);
        assert_eq!(k.boot(), Some(Boot { stiffness: 5.0e4, damping: boot::IDENTIFIED.damping }));
        let refused = |text: &str| toml::from_str::<ScenarioSpec>(text).unwrap().build().unwrap_err().to_string();
        assert!(refused("leg = true\nfoot_mass = 2.0\n").starts_with("`foot_mass` does not apply to the leg"));
        assert!(refused("knee = 20.0\n").starts_with("`knee` does not apply to a foot without the leg"));
        assert!(refused("boot_damping = 20.0\n").starts_with("`boot_damping` does not apply to the rigid foot"));
        assert!(refused("leg = true\nknee = 200.0\n").contains("`knee`"));
        assert!(refused("boot_stiffness = -1.0\n").contains("`boot_stiffness`"));
        // Table 1's foot is untouched.
        assert_eq!(ScenarioSpec::default().build().unwrap(), Scenario::BASELINE);
    }

    /// TOML `law = "shell"` with the ball's keys builds the pressurised ball
    /// they name (the rest at their declared defaults); its spec builds it
    /// again, a changed parameter keeps the ball, and the ball's keys are
    /// refused under another law, naming the key.
    #[test]
    fn law_shell_is_built_from_the_balls_keys() {
        let spec: ScenarioSpec = toml::from_str("law = \"shell\"\ninflation_pressure = 7.0e4\nshell_damping = 3000.0\n").unwrap();
        let scenario = spec.build().unwrap();
        let ball = ShellBall::new(7.0e4, crate::DEFAULT_BALL_RADIUS, 1.4, 0.0, 3000.0).unwrap();
        assert_eq!(scenario.contact_law(), AnyLaw::Shell(ball));
        assert_eq!((scenario.law_kind(), scenario.restitution_target()), (LawKind::Shell, None));
        assert_eq!(scenario.spec().build().unwrap(), scenario);
        assert_eq!(scenario.with(Parameter::FootSpeed, 20.0).unwrap().contact_law(), AnyLaw::Shell(ball));
        // The paper's law stays the default.
        let paper: ScenarioSpec = toml::from_str("foot_mass = 3.0\n").unwrap();
        assert_eq!(paper.build().unwrap().law_kind(), LawKind::PowerLaw);
        let e = toml::from_str::<ScenarioSpec>("inflation_pressure = 7.0e4\n").unwrap().build().unwrap_err().to_string();
        assert!(e.starts_with("`inflation_pressure` does not apply to law `power-law`"), "{e}");
        let e = toml::from_str::<ScenarioSpec>("law = \"shell\"\ndamping = 10.0\n").unwrap().build().unwrap_err().to_string();
        assert!(e.starts_with("`damping` does not apply to law `shell`"), "{e}");
    }
}
