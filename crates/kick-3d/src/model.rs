//! The validated 3D scenario: the 1D parameters (Table 1) plus the geometry of
//! an off-center, oblique impact and the tangential contact law.
//!
//! Frame: x is the horizontal direction of the foot's line of motion, z is up,
//! y completes a right-handed frame. The ball centre starts at the origin.
//!
//! - `offset` e: lateral (y) distance of the foot's line of motion from the
//!   ball centre. The instep face is tangent to the ball where that line first
//!   meets the sphere, p = (−√(R²−e²), e, 0), so the contact normal is tilted
//!   by φ = asin(e/R) from the line of motion. (A flat face struck square on
//!   would push through the centre whatever the offset; the tilt is what makes
//!   the offset matter.)
//! - `approach_angle` α: elevation of the foot's velocity above the
//!   horizontal, v_f = V (cos α, 0, sin α), with the face held as above; the
//!   foot then also slides up or down the ball.
//!
//! Normal approach speed V_n = (V cos α − v_b) cos φ; the tangential sliding
//! speed at first touch is V sin φ horizontally and V sin α vertically.
//!
//! Normal law: the scenario's contact law (`Scenario::contact_law`; Eq. 20
//! unless another is chosen). A law other than the paper's takes its damping
//! from its target restitution at the normal approach speed V_n, so the
//! normal impact has the restitution asked for, and a central square kick is
//! exactly the 1D scenario.

use crate::error::Kick3dError;
use kick_core::{AnyLaw, Scenario};
use parry3d_f64::math::{Rot3, Vec3};
use serde::{Deserialize, Serialize};

/// Shape of the instep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum FootShape {
    /// A box; the face at local +x touches the ball.
    Box { half_extents: [f64; 3] },
    /// A box of inner half-extents with every edge rounded by `border_radius`
    /// (the Minkowski sum of the box and a sphere).
    RoundedBox { half_extents: [f64; 3], border_radius: f64 },
}

impl FootShape {
    /// Default instep: 6 cm thick (along the contact normal), 24 cm long
    /// (across the line of motion), 10 cm high. An assumption, not a measurement.
    pub const DEFAULT_HALF_EXTENTS: [f64; 3] = [0.03, 0.12, 0.05];

    pub fn half_extents(&self) -> [f64; 3] {
        match *self {
            FootShape::Box { half_extents } | FootShape::RoundedBox { half_extents, .. } => half_extents,
        }
    }
    pub fn border_radius(&self) -> f64 {
        match *self {
            FootShape::Box { .. } => 0.0,
            FootShape::RoundedBox { border_radius, .. } => border_radius,
        }
    }
    /// Outer half-extents (inner box plus border).
    pub fn outer_half_extents(&self) -> [f64; 3] {
        let b = self.border_radius();
        self.half_extents().map(|h| h + b)
    }
    /// Principal moments of a uniform solid box of the outer size and `mass`.
    pub fn solid_inertia(&self, mass: f64) -> [f64; 3] {
        let [a, b, c] = self.outer_half_extents();
        [mass * (b * b + c * c) / 3.0, mass * (a * a + c * c) / 3.0, mass * (a * a + b * b) / 3.0]
    }
}

impl Default for FootShape {
    fn default() -> Self {
        FootShape::Box { half_extents: FootShape::DEFAULT_HALF_EXTENTS }
    }
}

/// Everything beyond the 1D parameters, as given by the user; `None` takes the default.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Kick3dSpec {
    /// R, m [0.11]
    pub ball_radius: Option<f64>,
    /// I_b, kg m² [2/3 m_b R², thin shell]
    pub ball_inertia: Option<f64>,
    /// Principal moments of the foot about its centre of mass, body axes, kg m²
    /// [uniform solid box of the instep's size and mass m_f]
    pub foot_inertia: Option<[f64; 3]>,
    pub foot_shape: Option<FootShape>,
    /// e, m [0]
    pub offset: Option<f64>,
    /// α, degrees [0]
    #[serde(rename = "approach_angle")]
    pub approach_angle_deg: Option<f64>,
    /// μ, Coulomb coefficient; `f64::INFINITY` means the contact never slips [0.5]
    pub friction: Option<f64>,
    /// k_t, N/m [1e5]
    pub tangential_stiffness: Option<f64>,
    /// c_t, N s/m [100]
    pub tangential_damping: Option<f64>,
    /// Uniform gravity (0, 0, −9.81 m/s²) on both bodies [off]
    pub gravity: Option<bool>,
    /// A ground plane under the ball (scene path only) [off]
    pub ground: Option<bool>,
}

/// Standard gravity, m/s² (one value for every model level: kick-core's).
pub use kick_core::GRAVITY;

/// A validated 3D kick.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Kick3d {
    /// Masses, speeds (magnitudes), the normal law and the drive of the 1D model.
    pub base: Scenario,
    /// The normal contact law: `base`'s law at the normal approach speed
    /// (see the module docs), set by [`Kick3d::new`].
    pub law: AnyLaw,
    pub ball_radius: f64,
    pub ball_inertia: f64,
    pub foot_inertia: [f64; 3],
    pub foot_shape: FootShape,
    pub offset: f64,
    /// α in radians.
    pub approach_angle: f64,
    pub friction: f64,
    pub tangential_stiffness: f64,
    pub tangential_damping: f64,
    pub gravity: bool,
    pub ground: bool,
}

/// Initial rigid-body states of one kick, in the world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InitialState {
    pub foot_position: Vec3,
    pub foot_orientation: Rot3,
    pub foot_velocity: Vec3,
    pub ball_position: Vec3,
    pub ball_velocity: Vec3,
    /// Outward face normal of the foot (foot → ball) at first touch.
    pub normal: Vec3,
}

fn invalid(name: &'static str, value: f64, requirement: &'static str) -> Kick3dError {
    Kick3dError::InvalidParameter { name, value, requirement }
}

impl Kick3d {
    pub const DEFAULT_BALL_RADIUS: f64 = kick_core::DEFAULT_BALL_RADIUS;
    pub const DEFAULT_FRICTION: f64 = 0.5;
    /// About 0.8 of the normal law's tangent stiffness n k δ^(n−1) at the
    /// baseline's δ_max (1.2e5 N/m), a Mindlin-like ratio. Assumed.
    pub const DEFAULT_TANGENTIAL_STIFFNESS: f64 = 1.0e5;
    /// Damping ratio ≈ 0.4 of the tangential mode at the defaults. Assumed.
    pub const DEFAULT_TANGENTIAL_DAMPING: f64 = 100.0;

    /// Validate; every problem is a typed error naming the parameter.
    pub fn new(base: Scenario, spec: &Kick3dSpec) -> Result<Kick3d, Kick3dError> {
        let positive = |name, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(invalid(name, v, "finite and > 0"))
            }
        };
        let radius = positive("ball_radius", spec.ball_radius.unwrap_or(Self::DEFAULT_BALL_RADIUS))?;
        let m_b = base.ball_mass();
        let shell = 2.0 / 3.0 * m_b * radius * radius;
        let ball_inertia = positive("ball_inertia", spec.ball_inertia.unwrap_or(shell))?;
        // A thin shell puts all the mass at R: no sphere of radius R can exceed it.
        if ball_inertia > shell * (1.0 + 1e-12) {
            return Err(invalid("ball_inertia", ball_inertia, "<= 2/3 m_b R^2 (thin shell, the most a sphere can have)"));
        }
        let foot_shape = spec.foot_shape.unwrap_or_default();
        for h in foot_shape.half_extents() {
            positive("foot_half_extent", h)?;
        }
        let border = foot_shape.border_radius();
        if !(border.is_finite() && border >= 0.0) {
            return Err(invalid("border_radius", border, "finite and >= 0"));
        }
        let foot_inertia = spec.foot_inertia.unwrap_or_else(|| foot_shape.solid_inertia(base.effective_foot_mass()));
        for i in foot_inertia {
            positive("foot_inertia", i)?;
        }
        let offset = spec.offset.unwrap_or(0.0);
        if !(offset.is_finite() && offset.abs() < radius) {
            return Err(Kick3dError::OffsetOutsideBall { offset, radius });
        }
        let alpha_deg = spec.approach_angle_deg.unwrap_or(0.0);
        if !(alpha_deg.is_finite() && alpha_deg.abs() < 90.0) {
            return Err(invalid("approach_angle", alpha_deg, "finite, in (-90, 90) degrees"));
        }
        let friction = spec.friction.unwrap_or(Self::DEFAULT_FRICTION);
        if friction.is_nan() || friction < 0.0 {
            return Err(invalid("friction", friction, ">= 0 (inf: never slips)"));
        }
        let tangential_stiffness =
            positive("tangential_stiffness", spec.tangential_stiffness.unwrap_or(Self::DEFAULT_TANGENTIAL_STIFFNESS))?;
        let tangential_damping =
            positive("tangential_damping", spec.tangential_damping.unwrap_or(Self::DEFAULT_TANGENTIAL_DAMPING))?;
        let mut kick = Kick3d {
            base,
            law: base.contact_law(),
            ball_radius: radius,
            ball_inertia,
            foot_inertia,
            foot_shape,
            offset,
            approach_angle: alpha_deg.to_radians(),
            friction,
            tangential_stiffness,
            tangential_damping,
            gravity: spec.gravity.unwrap_or(false),
            ground: spec.ground.unwrap_or(false),
        };
        let v_n = kick.normal_approach_speed();
        // NaN-safe: anything not strictly positive refuses.
        if v_n.is_nan() || v_n <= 0.0 {
            return Err(Kick3dError::Core(kick_core::KickError::NoContact {
                foot_speed: base.foot_speed() * kick.approach_angle.cos() * kick.obliquity().cos(),
                ball_speed: base.ball_speed() * kick.obliquity().cos(),
            }));
        }
        kick.law = kick.normal_scenario()?.contact_law();
        Ok(kick)
    }

    /// The default 3D kick on Table 1's baseline: central, μ = 0.5.
    pub fn baseline() -> Kick3d {
        match Kick3d::new(Scenario::baseline(), &Kick3dSpec::default()) {
            Ok(k) => k,
            Err(_) => unreachable!("the defaults are valid"),
        }
    }

    /// φ = asin(e/R), the tilt of the contact normal from the line of motion.
    pub fn obliquity(&self) -> f64 {
        (self.offset / self.ball_radius).asin()
    }

    /// Unit direction of the foot's velocity, û = (cos α, 0, sin α).
    pub fn foot_direction(&self) -> Vec3 {
        Vec3::new(self.approach_angle.cos(), 0.0, self.approach_angle.sin())
    }

    /// Face normal (foot → ball) at first touch, n0 = (cos φ, −sin φ, 0).
    pub fn initial_normal(&self) -> Vec3 {
        let phi = self.obliquity();
        Vec3::new(phi.cos(), -phi.sin(), 0.0)
    }

    /// V_n = (v_f − v_b)·n0 at first touch.
    pub fn normal_approach_speed(&self) -> f64 {
        let rel = self.foot_direction() * self.base.foot_speed() - Vec3::X * self.base.ball_speed();
        rel.dot(self.initial_normal())
    }

    /// Relative sliding velocity of the foot over the ball at first touch (tangential part).
    pub fn initial_sliding_velocity(&self) -> Vec3 {
        let n = self.initial_normal();
        let rel = self.foot_direction() * self.base.foot_speed() - Vec3::X * self.base.ball_speed();
        rel - n * rel.dot(n)
    }

    /// Distance from the foot's centre of mass to its contact face.
    pub fn face_distance(&self) -> f64 {
        self.foot_shape.outer_half_extents()[0]
    }

    /// Foot and ball at first touch (δ = 0), the foot's face tangent to the
    /// ball where the line of motion meets it.
    pub fn initial_state(&self) -> InitialState {
        let n = self.initial_normal();
        let contact = -n * self.ball_radius;
        InitialState {
            foot_position: contact - n * self.face_distance(),
            foot_orientation: Rot3::from_rotation_z(-self.obliquity()),
            foot_velocity: self.foot_direction() * self.base.foot_speed(),
            ball_position: Vec3::ZERO,
            ball_velocity: Vec3::X * self.base.ball_speed(),
            normal: n,
        }
    }

    /// The normal contact law (see the module docs).
    pub fn law(&self) -> AnyLaw {
        self.law
    }

    /// Drive force on the foot, along its initial direction of motion.
    pub fn drive(&self) -> Vec3 {
        self.foot_direction() * self.base.drive_force()
    }

    pub fn gravity_vector(&self) -> Vec3 {
        if self.gravity {
            Vec3::new(0.0, 0.0, -GRAVITY)
        } else {
            Vec3::ZERO
        }
    }

    /// The 1D scenario along the initial normal: the same masses and law, the
    /// normal components of the speeds and of the drive (a law other than the
    /// paper's recomputes its damping at this approach speed). Exact for a
    /// frictionless contact (the normal force passes through both centres of mass).
    pub fn normal_scenario(&self) -> Result<Scenario, Kick3dError> {
        let n = self.initial_normal();
        let foot_n = (self.foot_direction() * self.base.foot_speed()).dot(n);
        let ball_n = self.base.ball_speed() * n.x;
        let drive_n = self.drive().dot(n);
        let s = self
            .base
            .with(kick_core::Parameter::FootSpeed, foot_n)?
            .with(kick_core::Parameter::BallSpeed, ball_n)?
            .with(kick_core::Parameter::DriveForce, drive_n)?;
        Ok(s)
    }

    /// True when the kick is the 1D kick along the normal: central and square
    /// (no sliding at first touch), so no friction acts and the contact point
    /// stays on the line through both centres of mass; and no gravity.
    /// (Frictionless but oblique is not enough: the contact point slides along
    /// the face, the normal force then turns the foot and tilts the normal.)
    pub fn is_one_dimensional(&self) -> bool {
        !self.gravity && self.initial_sliding_velocity().length() == 0.0
    }

    /// Time after which a contact still going is reported as no separation:
    /// the 1D horizon of the normal scenario.
    pub fn contact_horizon(&self) -> Result<f64, Kick3dError> {
        let s = self.normal_scenario()?;
        Ok(s.contact_horizon())
    }

    /// Total initial kinetic energy (both bodies translate only).
    pub fn initial_kinetic_energy(&self) -> f64 {
        let s = self.initial_state();
        0.5 * self.base.effective_foot_mass() * s.foot_velocity.length_squared()
            + 0.5 * self.base.ball_mass() * s.ball_velocity.length_squared()
    }
}
