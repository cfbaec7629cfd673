//! Flight parameters, declared once ([`FLIGHT_PARAMETERS`], kick-core's
//! [`ParameterDef`] at [`Level::Flight`]), the unvalidated [`FlightSpec`] and
//! the validated [`Flight`].
//!
//! Front ends derive flags (`--launch-angle` from `launch_angle`), TOML keys,
//! result columns and keywords from the declarations; every refusal names
//! the parameter by the same name.

use crate::air::{Air, SEA_LEVEL_DENSITY};
use crate::coefficients::{BallConstruction, DragModel, LiftModel};
use crate::{FlightError, DEFAULT_RELATIVE_TOLERANCE};
use kick_core::{DEFAULT_BALL_MASS, DEFAULT_BALL_RADIUS, GRAVITY};
use serde::{Deserialize, Serialize};

/// One flight parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FlightParameter {
    Speed,
    LaunchAngle,
    Azimuth,
    LaunchVelocity,
    Spin,
    BallMass,
    BallRadius,
    Gravity,
    AirDensity,
    Temperature,
    Pressure,
    Altitude,
    DragCoefficient,
    BallPanels,
    LiftCoefficient,
    SpinDecay,
    Distance,
}

use kick_core::parameters::{Bound, DefaultValue, Level, ParameterDef, Shape, Valid};

/// The largest launch speed, m/s, as the bounce's largest impact speed:
/// far past any kicked ball and the drag model's air (incompressible:
/// Mach 0.3 is ~100 m/s), and short of the speeds whose flight leaves
/// double precision's range (1e90 m/s failed in the drag's scale, and an
/// aim's --range up to it was searched there).
pub const MAX_LAUNCH_SPEED: f64 = 1000.0;
const SPEED_REQUIREMENT: &str = "in (0, 1000] m/s";

/// What `ball_panels` must be: a construction of [`crate::coefficients::BALL_CONSTRUCTIONS`].
const PANELS_REQUIREMENT: &str = "one of 32, 14, 8, 6 (the constructions with a published critical Reynolds number)";

#[allow(clippy::too_many_arguments)] // one row of the declaration table
const fn flight(
    name: &'static str,
    symbol: &'static str,
    unit: &'static str,
    default: DefaultValue,
    low: Bound,
    high: Bound,
    requirement: &'static str,
    doc: &'static str,
) -> ParameterDef {
    ParameterDef {
        name,
        symbol,
        unit,
        level: Level::Flight,
        shape: Shape::Scalar,
        default,
        valid: Valid { low, high, requirement },
        sample: None,
        doc,
    }
}

use Bound::{Closed, Open, Unbounded};
use DefaultValue::{Derived, Number, Unset};

/// The flight parameters, declared with kick-core's [`ParameterDef`] at
/// [`Level::Flight`] (their own name space: `gravity` here is g, the 3D
/// kick's is a switch), in [`FlightParameter::ALL`] order. Refusals keep
/// their own wording (with the unit) in [`FlightSpec::build`]; conditions
/// between parameters are in the requirement text.
pub static FLIGHT_PARAMETERS: [ParameterDef; 17] = [
    flight("speed", "|v0|", "m/s", Unset("required"), Open(0.0), Closed(MAX_LAUNCH_SPEED), SPEED_REQUIREMENT, "Launch speed of the ball"),
    flight(
        "launch_angle",
        "θ",
        "deg",
        Unset("required"),
        Open(0.0),
        Closed(90.0),
        "in (0, 90] degrees (the ball starts on the ground)",
        "Elevation of the launch velocity above the ground",
    ),
    flight(
        "azimuth",
        "ψ",
        "deg",
        Number(0.0),
        Closed(-180.0),
        Closed(180.0),
        "in [-180, 180] degrees",
        "Horizontal direction of launch from the x axis, positive toward +y",
    ),
    ParameterDef {
        shape: Shape::Vector3,
        ..flight(
            "launch_velocity",
            "v0",
            "m/s",
            Unset("none: speed, launch_angle and azimuth give it"),
            Unbounded,
            Unbounded,
            "three finite numbers with a vertical component > 0, m/s; not with speed, launch_angle or azimuth",
            "Launch velocity as a vector, world frame, instead of speed and angles",
        )
    },
    ParameterDef {
        shape: Shape::Vector3,
        default: DefaultValue::Vector([0.0; 3]),
        ..flight(
            "spin",
            "ω",
            "rad/s",
            Number(0.0),
            Unbounded,
            Unbounded,
            "three finite numbers, rad/s",
            "Spin vector at launch, world frame (x along the kick, z up): for a kick along +x, \
             ω_z > 0 curves the ball toward +y and ω_y < 0 (backspin) lifts it",
        )
    },
    flight(
        "ball_mass",
        "m",
        "kg",
        Number(DEFAULT_BALL_MASS),
        Open(0.0),
        Unbounded,
        "finite and > 0, kg",
        "Ball mass (Law 2: 0.41-0.45 kg)",
    ),
    flight(
        "ball_radius",
        "R",
        "m",
        Number(DEFAULT_BALL_RADIUS),
        Open(0.0),
        Unbounded,
        "finite and > 0, m",
        "Ball radius (Law 2: circumference 0.68-0.70 m)",
    ),
    flight(
        "gravity",
        "g",
        "m/s^2",
        Number(GRAVITY),
        Open(0.0),
        Unbounded,
        "finite and > 0, m/s^2 (the ball must come down)",
        "Gravitational acceleration",
    ),
    flight(
        "air_density",
        "ρ",
        "kg/m^3",
        Number(SEA_LEVEL_DENSITY),
        Open(0.0),
        Unbounded,
        "> 0; not with temperature, pressure or altitude",
        "Air density (viscosity then at 15 °C)",
    ),
    flight(
        "temperature",
        "T",
        "°C",
        Derived("standard atmosphere at the altitude (15 at sea level)"),
        Open(-273.15),
        Closed(crate::air::MAX_TEMPERATURE),
        crate::air::TEMPERATURE_REQUIREMENT,
        "Air temperature, for density (ideal gas) and viscosity (Sutherland)",
    ),
    flight(
        "pressure",
        "p",
        "Pa",
        Derived("standard atmosphere at the altitude (101325 at sea level)"),
        Open(0.0),
        Unbounded,
        "> 0",
        "Air pressure",
    ),
    flight(
        "altitude",
        "h",
        "m",
        Number(0.0),
        Closed(-500.0),
        Closed(11000.0),
        "[-500, 11000]; not with both temperature and pressure",
        "Geopotential altitude: standard-atmosphere temperature and pressure where not given",
    ),
    flight(
        "drag_coefficient",
        "C_D",
        "1",
        Derived("Goff & Carré (2010) drag crisis in Re (Eq. 3), with spin above it (Eq. 4); their constants as code bases transcribe them"),
        Closed(0.0),
        Unbounded,
        "finite and >= 0",
        "A constant drag coefficient instead of the drag-crisis model",
    ),
    flight(
        "ball_panels",
        "N_p",
        "1",
        Number(BallConstruction::DEFAULT_PANELS as f64),
        Closed(6.0),
        Closed(32.0),
        PANELS_REQUIREMENT,
        "Panel count of the ball: moves the drag crisis to its published critical Re (Asai & Hong 2021: 32, 14, 8, 6); \
         not with drag_coefficient",
    ),
    flight(
        "lift_coefficient",
        "C_L",
        "1",
        Derived("saturating fit in S to published soccer-ball data"),
        Closed(0.0),
        Unbounded,
        "finite and >= 0",
        "A constant lift coefficient instead of the C_L(S) model",
    ),
    flight(
        "spin_decay",
        "k_M",
        "1",
        Number(0.0),
        Closed(0.0),
        Unbounded,
        "finite and >= 0",
        "Slope of the aerodynamic moment coefficient C_M = k_M S; torque -(1/2) ρ A R² k_M |v| ω",
    ),
    flight(
        "distance",
        "d",
        "m",
        Unset("none"),
        Open(0.0),
        Unbounded,
        "finite and > 0, m",
        "Report where the ball crosses the vertical plane x = d (wall at 9.15 m, goal line)",
    ),
];

impl FlightParameter {
    pub const ALL: [FlightParameter; 17] = [
        FlightParameter::Speed,
        FlightParameter::LaunchAngle,
        FlightParameter::Azimuth,
        FlightParameter::LaunchVelocity,
        FlightParameter::Spin,
        FlightParameter::BallMass,
        FlightParameter::BallRadius,
        FlightParameter::Gravity,
        FlightParameter::AirDensity,
        FlightParameter::Temperature,
        FlightParameter::Pressure,
        FlightParameter::Altitude,
        FlightParameter::DragCoefficient,
        FlightParameter::BallPanels,
        FlightParameter::LiftCoefficient,
        FlightParameter::SpinDecay,
        FlightParameter::Distance,
    ];

    /// The launch state a kick gives the ball: its velocity (as speed and
    /// angles, or as a vector) and its spin.
    pub const LAUNCH: [FlightParameter; 5] = [
        FlightParameter::Speed,
        FlightParameter::LaunchAngle,
        FlightParameter::Azimuth,
        FlightParameter::LaunchVelocity,
        FlightParameter::Spin,
    ];

    /// The declaration: name, symbol, unit, default, valid range, doc.
    pub fn def(self) -> &'static ParameterDef {
        &FLIGHT_PARAMETERS[self as usize]
    }

    pub fn name(self) -> &'static str {
        self.def().name
    }

    /// 1, or 3 for a vector given as three numbers.
    pub fn components(self) -> usize {
        if self.def().shape == Shape::Vector3 {
            3
        } else {
            1
        }
    }

    pub fn from_name(name: &str) -> Result<FlightParameter, FlightError> {
        FlightParameter::ALL.into_iter().find(|p| p.name() == name).ok_or_else(|| FlightError::UnknownParameter {
            name: name.to_string(),
            expected: FlightParameter::ALL.map(|p| p.name()).join(", "),
        })
    }
}

/// A flight as given: every field optional; `build` fills defaults and validates.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FlightSpec {
    pub speed: Option<f64>,
    pub launch_angle: Option<f64>,
    pub azimuth: Option<f64>,
    pub launch_velocity: Option<[f64; 3]>,
    pub spin: Option<[f64; 3]>,
    pub ball_mass: Option<f64>,
    pub ball_radius: Option<f64>,
    pub gravity: Option<f64>,
    pub air_density: Option<f64>,
    pub temperature: Option<f64>,
    pub pressure: Option<f64>,
    pub altitude: Option<f64>,
    pub drag_coefficient: Option<f64>,
    pub ball_panels: Option<f64>,
    pub lift_coefficient: Option<f64>,
    pub spin_decay: Option<f64>,
    pub distance: Option<f64>,
}

fn invalid(name: &'static str, value: f64, requirement: &'static str) -> FlightError {
    FlightError::InvalidParameter { name, value, requirement }
}

fn check(name: &'static str, value: f64, ok: bool, requirement: &'static str) -> Result<f64, FlightError> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(invalid(name, value, requirement))
    }
}

fn check_spin(spin: [f64; 3]) -> Result<[f64; 3], FlightError> {
    for w in spin {
        check("spin", w, true, "three finite numbers, rad/s")?;
    }
    Ok(spin)
}

fn check_launch_velocity(velocity: [f64; 3]) -> Result<[f64; 3], FlightError> {
    for v in velocity {
        check("launch_velocity", v, true, "three finite numbers, m/s")?;
    }
    check("launch_velocity", velocity[2], velocity[2] > 0.0, "with a vertical component > 0 (the ball starts on the ground)")?;
    // By hypot: no overflow to inf in the check.
    let length = velocity[0].hypot(velocity[1]).hypot(velocity[2]);
    check("launch_velocity", length, length <= MAX_LAUNCH_SPEED, "of length at most 1000 m/s (the largest launch speed)")?;
    Ok(velocity)
}

impl FlightSpec {
    /// A flight from a 1D kick: its exit speed and a launch angle in degrees.
    pub fn from_exit_speed(speed: f64, launch_angle: f64) -> FlightSpec {
        FlightSpec { speed: Some(speed), launch_angle: Some(launch_angle), ..FlightSpec::default() }
    }

    /// Set one parameter from numbers (one, or three for `spin`).
    pub fn set(&mut self, parameter: FlightParameter, values: &[f64]) -> Result<(), FlightError> {
        if values.len() != parameter.components() {
            return Err(FlightError::WrongLength { name: parameter.name(), expected: parameter.components(), found: values.len() });
        }
        let x = Some(values[0]);
        match parameter {
            FlightParameter::Speed => self.speed = x,
            FlightParameter::LaunchAngle => self.launch_angle = x,
            FlightParameter::Azimuth => self.azimuth = x,
            FlightParameter::LaunchVelocity => self.launch_velocity = Some([values[0], values[1], values[2]]),
            FlightParameter::Spin => self.spin = Some([values[0], values[1], values[2]]),
            FlightParameter::BallMass => self.ball_mass = x,
            FlightParameter::BallRadius => self.ball_radius = x,
            FlightParameter::Gravity => self.gravity = x,
            FlightParameter::AirDensity => self.air_density = x,
            FlightParameter::Temperature => self.temperature = x,
            FlightParameter::Pressure => self.pressure = x,
            FlightParameter::Altitude => self.altitude = x,
            FlightParameter::DragCoefficient => self.drag_coefficient = x,
            FlightParameter::BallPanels => self.ball_panels = x,
            FlightParameter::LiftCoefficient => self.lift_coefficient = x,
            FlightParameter::SpinDecay => self.spin_decay = x,
            FlightParameter::Distance => self.distance = x,
        }
        Ok(())
    }

    /// The value given for the scalar `parameter` (None: not given, or a vector).
    pub fn number(&self, parameter: FlightParameter) -> Option<f64> {
        match parameter {
            FlightParameter::Speed => self.speed,
            FlightParameter::LaunchAngle => self.launch_angle,
            FlightParameter::Azimuth => self.azimuth,
            FlightParameter::LaunchVelocity | FlightParameter::Spin => None,
            FlightParameter::BallMass => self.ball_mass,
            FlightParameter::BallRadius => self.ball_radius,
            FlightParameter::Gravity => self.gravity,
            FlightParameter::AirDensity => self.air_density,
            FlightParameter::Temperature => self.temperature,
            FlightParameter::Pressure => self.pressure,
            FlightParameter::Altitude => self.altitude,
            FlightParameter::DragCoefficient => self.drag_coefficient,
            FlightParameter::BallPanels => self.ball_panels,
            FlightParameter::LiftCoefficient => self.lift_coefficient,
            FlightParameter::SpinDecay => self.spin_decay,
            FlightParameter::Distance => self.distance,
        }
    }

    /// Whether `parameter` was given.
    pub fn is_set(&self, parameter: FlightParameter) -> bool {
        match parameter {
            FlightParameter::Speed => self.speed.is_some(),
            FlightParameter::LaunchAngle => self.launch_angle.is_some(),
            FlightParameter::Azimuth => self.azimuth.is_some(),
            FlightParameter::LaunchVelocity => self.launch_velocity.is_some(),
            FlightParameter::Spin => self.spin.is_some(),
            FlightParameter::BallMass => self.ball_mass.is_some(),
            FlightParameter::BallRadius => self.ball_radius.is_some(),
            FlightParameter::Gravity => self.gravity.is_some(),
            FlightParameter::AirDensity => self.air_density.is_some(),
            FlightParameter::Temperature => self.temperature.is_some(),
            FlightParameter::Pressure => self.pressure.is_some(),
            FlightParameter::Altitude => self.altitude.is_some(),
            FlightParameter::DragCoefficient => self.drag_coefficient.is_some(),
            FlightParameter::BallPanels => self.ball_panels.is_some(),
            FlightParameter::LiftCoefficient => self.lift_coefficient.is_some(),
            FlightParameter::SpinDecay => self.spin_decay.is_some(),
            FlightParameter::Distance => self.distance.is_some(),
        }
    }

    /// Fill defaults and validate.
    pub fn build(&self) -> Result<Flight, FlightError> {
        if let Some(velocity) = self.launch_velocity {
            let angles =
                [("speed", self.speed.is_some()), ("launch_angle", self.launch_angle.is_some()), ("azimuth", self.azimuth.is_some())];
            if let Some((name, _)) = angles.iter().find(|(_, set)| *set) {
                return Err(FlightError::Conflict { first: "launch_velocity", second: name });
            }
            return self.finish(check_launch_velocity(velocity)?, check_spin(self.spin.unwrap_or([0.0; 3]))?);
        }
        let speed = self.speed.ok_or(FlightError::Missing { name: "speed" })?;
        let speed = check("speed", speed, speed > 0.0 && speed <= MAX_LAUNCH_SPEED, SPEED_REQUIREMENT)?;
        let angle = self.launch_angle.ok_or(FlightError::Missing { name: "launch_angle" })?;
        let angle = check("launch_angle", angle, angle > 0.0 && angle <= 90.0, "in (0, 90] degrees (the ball starts on the ground)")?;
        let azimuth = self.azimuth.unwrap_or(0.0);
        let azimuth = check("azimuth", azimuth, azimuth.abs() <= 180.0, "in [-180, 180] degrees")?;
        let (theta, psi) = (angle.to_radians(), azimuth.to_radians());
        let velocity = if angle == 90.0 {
            [0.0, 0.0, speed]
        } else {
            [speed * theta.cos() * psi.cos(), speed * theta.cos() * psi.sin(), speed * theta.sin()]
        };
        self.finish(velocity, check_spin(self.spin.unwrap_or([0.0; 3]))?)
    }

    /// Everything but the launch state.
    fn finish(&self, launch_velocity: [f64; 3], spin: [f64; 3]) -> Result<Flight, FlightError> {
        let mass = self.ball_mass.unwrap_or(DEFAULT_BALL_MASS);
        let mass = check("ball_mass", mass, mass > 0.0, "finite and > 0, kg")?;
        let radius = self.ball_radius.unwrap_or(DEFAULT_BALL_RADIUS);
        let radius = check("ball_radius", radius, radius > 0.0, "finite and > 0, m")?;
        let gravity = self.gravity.unwrap_or(GRAVITY);
        let gravity = check("gravity", gravity, gravity > 0.0, "finite and > 0, m/s^2 (the ball must come down)")?;
        let air = Air::new(self.air_density, self.temperature, self.pressure, self.altitude)?;
        let drag = match (self.drag_coefficient, self.ball_panels) {
            (Some(_), Some(_)) => return Err(FlightError::Conflict { first: "drag_coefficient", second: "ball_panels" }),
            (Some(c), None) => DragModel::Constant { value: check("drag_coefficient", c, c >= 0.0, "finite and >= 0")? },
            (None, panels) => {
                let panels = panels.unwrap_or(BallConstruction::DEFAULT_PANELS as f64);
                match BallConstruction::with_panels(panels) {
                    Some(construction) => DragModel::DragCrisis { construction },
                    None => return Err(invalid("ball_panels", panels, PANELS_REQUIREMENT)),
                }
            }
        };
        let lift = match self.lift_coefficient {
            None => LiftModel::Saturating,
            Some(c) => LiftModel::Constant { value: check("lift_coefficient", c, c >= 0.0, "finite and >= 0")? },
        };
        let spin_decay = self.spin_decay.unwrap_or(0.0);
        let spin_decay = check("spin_decay", spin_decay, spin_decay >= 0.0, "finite and >= 0")?;
        let distance = match self.distance {
            None => None,
            Some(d) => Some(check("distance", d, d > 0.0, "finite and > 0, m")?),
        };
        let flight = Flight {
            ball_mass: mass,
            ball_radius: radius,
            gravity,
            air,
            drag,
            lift,
            spin_decay,
            launch_velocity,
            spin,
            distance,
            relative_tolerance: DEFAULT_RELATIVE_TOLERANCE,
            horizon: None,
        };
        crate::solve::check_scales(&flight)?;
        Ok(flight)
    }
}

/// A validated flight: SI units, radians, world frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Flight {
    ball_mass: f64,
    ball_radius: f64,
    gravity: f64,
    air: Air,
    drag: DragModel,
    lift: LiftModel,
    spin_decay: f64,
    launch_velocity: [f64; 3],
    spin: [f64; 3],
    distance: Option<f64>,
    relative_tolerance: f64,
    /// Set by `with_horizon`; otherwise HORIZON_FACTOR × 2|v0|/g.
    horizon: Option<f64>,
}

impl Flight {
    /// From a 3D kick's outcome: launch velocity and spin vectors (m/s,
    /// rad/s, world frame); `rest` gives ball, air, coefficients and distance
    /// and must leave speed, launch_angle, azimuth and spin unset.
    pub fn from_launch(launch_velocity: [f64; 3], spin: [f64; 3], rest: &FlightSpec) -> Result<Flight, FlightError> {
        let given = [
            ("speed", rest.speed.is_some()),
            ("launch_angle", rest.launch_angle.is_some()),
            ("azimuth", rest.azimuth.is_some()),
            ("launch_velocity", rest.launch_velocity.is_some()),
            ("spin", rest.spin.is_some()),
        ];
        if let Some((name, _)) = given.iter().find(|(_, set)| *set) {
            return Err(FlightError::Conflict { first: "launch_velocity", second: name });
        }
        rest.finish(check_launch_velocity(launch_velocity)?, check_spin(spin)?)
    }

    /// The same flight solved at another relative tolerance, in (0, 1e-3].
    pub fn with_relative_tolerance(mut self, relative_tolerance: f64) -> Result<Flight, FlightError> {
        self.relative_tolerance =
            check("relative_tolerance", relative_tolerance, relative_tolerance > 0.0 && relative_tolerance <= 1e-3, "in (0, 1e-3]")?;
        Ok(self)
    }

    /// The same flight with another horizon (s, > 0): still in the air then, it is refused.
    pub fn with_horizon(mut self, horizon: f64) -> Result<Flight, FlightError> {
        self.horizon = Some(check("horizon", horizon, horizon > 0.0, "finite and > 0, s")?);
        Ok(self)
    }

    /// The same flight with another crossing plane (None: no crossing).
    pub fn with_distance(mut self, distance: Option<f64>) -> Result<Flight, FlightError> {
        if let Some(d) = distance {
            check("distance", d, d > 0.0, "finite and > 0, m")?;
        }
        self.distance = distance;
        Ok(self)
    }

    pub fn ball_mass(&self) -> f64 {
        self.ball_mass
    }
    pub fn ball_radius(&self) -> f64 {
        self.ball_radius
    }
    pub fn gravity(&self) -> f64 {
        self.gravity
    }
    pub fn air(&self) -> Air {
        self.air
    }
    pub fn drag(&self) -> DragModel {
        self.drag
    }
    pub fn lift(&self) -> LiftModel {
        self.lift
    }
    pub fn spin_decay(&self) -> f64 {
        self.spin_decay
    }
    pub fn launch_velocity(&self) -> [f64; 3] {
        self.launch_velocity
    }
    pub fn spin(&self) -> [f64; 3] {
        self.spin
    }
    pub fn distance(&self) -> Option<f64> {
        self.distance
    }
    pub fn relative_tolerance(&self) -> f64 {
        self.relative_tolerance
    }
    /// |v0|, m/s.
    pub fn speed(&self) -> f64 {
        let [x, y, z] = self.launch_velocity;
        (x * x + y * y + z * z).sqrt()
    }
    /// A = π R², m².
    pub fn area(&self) -> f64 {
        std::f64::consts::PI * self.ball_radius * self.ball_radius
    }
    /// Re at speed `v`.
    pub fn reynolds(&self, v: f64) -> f64 {
        self.air.density * v * 2.0 * self.ball_radius / self.air.viscosity
    }
    /// Time after which a flight that has not landed is refused, s:
    /// [`crate::HORIZON_FACTOR`] × 2|v0|/g unless set by [`Flight::with_horizon`].
    pub fn horizon(&self) -> f64 {
        self.horizon.unwrap_or(crate::HORIZON_FACTOR * 2.0 * self.speed() / self.gravity)
    }
}

impl Default for Flight {
    /// A 25 m/s kick at 20°, no spin, everything else at its default.
    fn default() -> Self {
        match FlightSpec::from_exit_speed(25.0, 20.0).build() {
            Ok(f) => f,
            Err(_) => unreachable!("the defaults are valid"),
        }
    }
}

/// The default air density, re-exported for front ends' help text.
pub const DEFAULT_AIR_DENSITY: f64 = SEA_LEVEL_DENSITY;

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(spec: FlightSpec) -> &'static str {
        match spec.build() {
            Err(FlightError::InvalidParameter { name, .. }) | Err(FlightError::Missing { name }) => name,
            Err(FlightError::Conflict { first, .. }) => first,
            other => panic!("expected a refusal, got {other:?}"),
        }
    }

    #[test]
    fn every_bad_input_names_its_parameter() {
        let ok = FlightSpec::from_exit_speed(25.0, 20.0);
        assert!(ok.build().is_ok());
        let with = |f: &dyn Fn(&mut FlightSpec)| {
            let mut s = ok;
            f(&mut s);
            s
        };
        assert_eq!(refused(FlightSpec::default()), "speed");
        assert_eq!(refused(with(&|s| s.speed = Some(-1.0))), "speed");
        assert_eq!(refused(with(&|s| s.speed = Some(f64::NAN))), "speed");
        assert_eq!(refused(with(&|s| s.speed = Some(f64::INFINITY))), "speed");
        assert_eq!(refused(with(&|s| s.launch_angle = None)), "launch_angle");
        assert_eq!(refused(with(&|s| s.launch_angle = Some(0.0))), "launch_angle");
        assert_eq!(refused(with(&|s| s.launch_angle = Some(91.0))), "launch_angle");
        assert_eq!(refused(with(&|s| s.azimuth = Some(200.0))), "azimuth");
        assert_eq!(refused(with(&|s| s.spin = Some([0.0, f64::NAN, 1.0]))), "spin");
        assert_eq!(refused(with(&|s| s.ball_mass = Some(0.0))), "ball_mass");
        assert_eq!(refused(with(&|s| s.ball_radius = Some(-0.1))), "ball_radius");
        assert_eq!(refused(with(&|s| s.gravity = Some(0.0))), "gravity");
        assert_eq!(refused(with(&|s| s.air_density = Some(-1.0))), "air_density");
        assert_eq!(refused(with(&|s| s.temperature = Some(-280.0))), "temperature");
        assert_eq!(refused(with(&|s| s.pressure = Some(0.0))), "pressure");
        assert_eq!(refused(with(&|s| s.altitude = Some(f64::NAN))), "altitude");
        assert_eq!(refused(with(&|s| s.drag_coefficient = Some(-0.2))), "drag_coefficient");
        assert_eq!(refused(with(&|s| s.lift_coefficient = Some(-0.2))), "lift_coefficient");
        assert_eq!(refused(with(&|s| s.ball_panels = Some(12.0))), "ball_panels");
        assert_eq!(refused(with(&|s| s.ball_panels = Some(f64::NAN))), "ball_panels");
        assert_eq!(
            with(&|s| {
                s.ball_panels = Some(32.0);
                s.drag_coefficient = Some(0.2)
            })
            .build(),
            Err(FlightError::Conflict { first: "drag_coefficient", second: "ball_panels" })
        );
        assert_eq!(refused(with(&|s| s.spin_decay = Some(-1.0))), "spin_decay");
        assert_eq!(refused(with(&|s| s.distance = Some(0.0))), "distance");
        assert_eq!(
            refused(with(&|s| {
                s.air_density = Some(1.2);
                s.altitude = Some(100.0)
            })),
            "air_density"
        );
    }

    /// The flight list keeps kick-core's invariants, in `ALL` order, and
    /// its defaults are the ones `build` fills in.
    #[test]
    fn the_declarations_keep_their_invariants() {
        kick_core::parameters::check_declarations(&FLIGHT_PARAMETERS).unwrap();
        for (i, p) in FlightParameter::ALL.iter().enumerate() {
            assert_eq!(serde_json::to_value(p).unwrap(), FLIGHT_PARAMETERS[i].name);
        }
        let f = FlightSpec::from_exit_speed(25.0, 20.0).build().unwrap();
        let number = |p: FlightParameter| p.def().default_number();
        assert_eq!(f.ball_mass(), number(FlightParameter::BallMass));
        assert_eq!(f.ball_radius(), number(FlightParameter::BallRadius));
        assert_eq!(f.gravity(), number(FlightParameter::Gravity));
        assert_eq!(f.spin_decay(), number(FlightParameter::SpinDecay));
        assert_eq!(f.air().density, number(FlightParameter::AirDensity));
    }

    #[test]
    fn spin_takes_three_numbers() {
        let mut s = FlightSpec::default();
        assert_eq!(s.set(FlightParameter::Spin, &[1.0, 2.0]), Err(FlightError::WrongLength { name: "spin", expected: 3, found: 2 }));
        assert!(s.set(FlightParameter::Spin, &[1.0, 2.0, 3.0]).is_ok());
        assert_eq!(s.spin, Some([1.0, 2.0, 3.0]));
        assert!(matches!(FlightParameter::from_name("spinn"), Err(FlightError::UnknownParameter { .. })));
        for p in FlightParameter::ALL {
            assert_eq!(FlightParameter::from_name(p.name()), Ok(p));
        }
    }

    #[test]
    fn toml_keys_are_the_declared_names() {
        let spec: FlightSpec = serde_json::from_str(r#"{"speed": 25, "launch_angle": 20, "spin": [0, 0, 50]}"#).unwrap();
        assert_eq!(spec.spin, Some([0.0, 0.0, 50.0]));
        assert!(serde_json::from_str::<FlightSpec>(r#"{"speeed": 25}"#).is_err());
        // Every declared name is a field of the spec (round trip through JSON).
        let mut full = FlightSpec::default();
        for p in FlightParameter::ALL {
            full.set(p, &vec![1.0; p.components()]).unwrap();
        }
        let value = serde_json::to_value(full).unwrap();
        for p in FlightParameter::ALL {
            assert!(full.is_set(p) && !FlightSpec::default().is_set(p), "{}", p.name());
            assert!(value.get(p.name()).is_some_and(|v| !v.is_null()), "{}", p.name());
        }
    }

    #[test]
    fn from_launch_refuses_a_second_launch_state() {
        let rest = FlightSpec { speed: Some(20.0), ..FlightSpec::default() };
        assert_eq!(
            Flight::from_launch([20.0, 0.0, 5.0], [0.0; 3], &rest),
            Err(FlightError::Conflict { first: "launch_velocity", second: "speed" })
        );
        assert!(matches!(
            Flight::from_launch([20.0, 0.0, 0.0], [0.0; 3], &FlightSpec::default()),
            Err(FlightError::InvalidParameter { name: "launch_velocity", .. })
        ));
        let f = Flight::from_launch([20.0, 1.0, 5.0], [0.0, 0.0, 60.0], &FlightSpec::default()).unwrap();
        assert_eq!(f.launch_velocity(), [20.0, 1.0, 5.0]);
    }

    /// `launch_velocity` is the vector form of speed and angles: the same
    /// flight as `from_launch`, refused beside speed or angles or when it
    /// does not leave the ground.
    #[test]
    fn launch_velocity_replaces_speed_and_angles() {
        let spec = FlightSpec { launch_velocity: Some([20.0, 1.0, 5.0]), spin: Some([0.0, 0.0, 60.0]), ..FlightSpec::default() };
        let direct = Flight::from_launch([20.0, 1.0, 5.0], [0.0, 0.0, 60.0], &FlightSpec::default()).unwrap();
        assert_eq!(spec.build().unwrap(), direct);
        for (name, with) in [
            ("speed", FlightSpec { speed: Some(20.0), ..spec }),
            ("launch_angle", FlightSpec { launch_angle: Some(20.0), ..spec }),
            ("azimuth", FlightSpec { azimuth: Some(0.0), ..spec }),
        ] {
            assert_eq!(with.build(), Err(FlightError::Conflict { first: "launch_velocity", second: name }));
        }
        assert_eq!(refused(FlightSpec { launch_velocity: Some([20.0, 0.0, -1.0]), ..spec }), "launch_velocity");
        assert_eq!(refused(FlightSpec { launch_velocity: Some([f64::NAN, 0.0, 1.0]), ..spec }), "launch_velocity");
        assert_eq!(
            Flight::from_launch([20.0, 1.0, 5.0], [0.0; 3], &spec),
            Err(FlightError::Conflict { first: "launch_velocity", second: "launch_velocity" })
        );
    }
}
