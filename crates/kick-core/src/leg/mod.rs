//! Effective mass of an articulated leg at the contact point (Eq. 11), and
//! its 6×6 generalisation, the foot's mobility ([`chain::Chain::spatial_mobility`]).
//! Here in kick-core because a scenario with `leg = true` takes its foot from
//! it ([`foot`]); kick-leg adds the elastic ankle, grids and exit curves.
//!
//! A three-segment leg (thigh, shank, foot) with segment parameters from
//! de Leva (1996) ([`anthropometry`]), posed by hip, knee and ankle angles,
//! hit at a point on the foot along a direction n. The contact-point effective
//! mass m_eff = (nᵀ J M⁻¹ Jᵀ n)⁻¹ (Eq. 11) is the m_f of the 1D model.
//!
//! Two variants share one multibody computation ([`chain`]):
//! - planar: every joint is a hinge about the mediolateral axis, the leg moves
//!   in the sagittal plane;
//! - spatial: the hip is a ball joint (three rotations), knee and ankle are
//!   hinges whose axes follow the thigh's abduction and rotation, and the
//!   contact point may sit off the foot's long axis.
//!
//! The hip is either pinned ([`HipSupport::Pinned`], the default) or free
//! ([`HipSupport::Free`]). Pinned treats the pelvis as immovable over the few
//! milliseconds of contact — it carries the trunk, about half the body mass —
//! and so gives the leg's largest effective mass; free lets the hip translate
//! with no trunk behind it, the smallest. Reality lies between; the pinned hip
//! is the closer of the two for a planted, braced kicker.
//!
//! Model choices beyond the table: the foot's heel–toe axis passes through
//! the ankle joint centre (the real ankle sits some 5 cm above the heel, which
//! moves the 1 kg foot's centre of mass by a few cm); the ankle is a single
//! plantarflexion hinge parallel to the knee axis (no subtalar joint); no
//! wobbling masses, no muscle co-contraction other than through the ankle
//! stiffness below.

pub mod anthropometry;
pub mod chain;
pub mod foot;

pub use anthropometry::{Anthropometry, Segment, DE_LEVA_MALE};
pub use chain::{Body, Chain, Joint, Motion};
pub use foot::{LegFoot, LegPose};

use crate::{KickError, Status};
use nalgebra::{Matrix3, Rotation3, Vector3};
use std::f64::consts::PI;
use thiserror::Error;

/// Every way a leg computation can refuse or fail.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum LegError {
    #[error("invalid leg input `{name}` = {}: must be {requirement}", crate::number::given(*.value))]
    InvalidInput { name: &'static str, value: f64, requirement: String },
    #[error("degenerate leg configuration: {0}")]
    Degenerate(String),
    #[error(transparent)]
    Contact(#[from] KickError),
}

impl LegError {
    /// What became of the computation (see [`crate::Status`]): a
    /// trapped ball or a numerical failure of the contact, else refused.
    pub fn status(&self) -> Status {
        match self {
            LegError::Contact(e) => e.status(),
            LegError::InvalidInput { .. } | LegError::Degenerate(_) => Status::Refused,
        }
    }
}

pub fn check_range(name: &'static str, value: f64, low: f64, high: f64, unit: &str) -> Result<f64, LegError> {
    if value.is_finite() && (low..=high).contains(&value) {
        Ok(value)
    } else {
        Err(LegError::InvalidInput {
            name,
            value,
            requirement: format!("finite and in [{}, {}] {unit}", crate::short(low), crate::short(high)),
        })
    }
}

/// How the hip is held during the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HipSupport {
    /// The hip joint centre cannot move (pelvis and trunk far heavier than
    /// the leg over a few milliseconds).
    #[default]
    Pinned,
    /// The hip can translate freely: the leg floats with nothing behind it.
    Free,
}

/// Planar (sagittal) or spatial leg.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Variant {
    #[default]
    Planar,
    Spatial,
}

/// How the ankle responds during the contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AnkleJoint {
    /// Rigid: foot and shank move as one body.
    Locked,
    /// A frictionless hinge.
    Free,
    /// A torsional spring of `stiffness` (N m/rad) over a contact lasting
    /// `contact_time` (s); see [`Leg::effective_mass`] for how it enters.
    Elastic { stiffness: f64, contact_time: f64 },
}

/// Joint angles in degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Thigh angle from the downward vertical, positive forward (flexion).
    pub hip_flexion: f64,
    /// Knee flexion: 0 straight, positive bends the shank backward.
    pub knee_flexion: f64,
    /// Ankle plantarflexion from neutral (foot at right angles to the shank),
    /// positive pointing the toe along the shank.
    pub plantarflexion: f64,
    /// Spatial only: thigh abduction, positive moving the knee laterally (+z).
    pub hip_abduction: f64,
    /// Spatial only: thigh rotation about its long axis, positive turning the
    /// knee and ankle hinge axes toward the front (+x).
    pub hip_rotation: f64,
}

impl Default for Pose {
    /// Near ball contact in an instep kick: thigh a little forward of
    /// vertical, knee extending, ankle strongly plantarflexed.
    fn default() -> Self {
        Pose { hip_flexion: 10.0, knee_flexion: 30.0, plantarflexion: 60.0, hip_abduction: 0.0, hip_rotation: 0.0 }
    }
}

/// Where and in which direction the ball pushes on the foot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// Contact point along the foot's long axis from the ankle, as a fraction
    /// of foot length.
    pub contact_fraction: f64,
    /// Spatial only: offset of the contact point along the foot's
    /// mediolateral axis, m (off-axis impacts also spin the foot, Eq. 61).
    pub lateral_offset: f64,
    /// Impact normal n (x forward, y up, z lateral); normalised internally.
    pub direction: Vector3<f64>,
}

impl Default for Impact {
    /// The instep, about two thirds down the foot, driven horizontally forward.
    fn default() -> Self {
        Impact { contact_fraction: 0.65, lateral_offset: 0.0, direction: Vector3::x() }
    }
}

/// Effective mass of one configuration, with both ankle limits.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LegEffectiveMass {
    /// m_eff used as m_f, kg.
    pub effective_mass: f64,
    /// With the ankle locked, kg.
    pub locked_ankle: f64,
    /// With the ankle a free hinge, kg.
    pub free_ankle: f64,
    /// Weight of the locked limit in the mobility interpolation (1 locked, 0 free).
    pub locked_share: f64,
    /// Rotational inertia the ankle hinge sees with the other joints free, kg m².
    pub ankle_inertia: f64,
}

/// A leg: segments, hip support, variant, and whether the knee is braced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leg {
    pub segments: Anthropometry,
    pub hip: HipSupport,
    pub variant: Variant,
    /// Knee rigid during contact (full co-contraction); by default it is a
    /// free hinge, as no muscle is modelled.
    pub knee_locked: bool,
}

/// Positions and frames of the posed leg.
struct Geometry {
    hip: Vector3<f64>,
    knee: Vector3<f64>,
    ankle: Vector3<f64>,
    frames: [Rotation3<f64>; 3],
}

fn rotation(axis: Vector3<f64>, degrees: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), degrees.to_radians())
}

/// Long axis of a segment frame (proximal → distal): the frame's −y.
fn long_axis(frame: &Rotation3<f64>) -> Vector3<f64> {
    frame * -Vector3::y()
}

impl Leg {
    /// de Leva's reference male (73 kg, 1.741 m), planar, pinned hip, free knee.
    pub fn reference() -> Leg {
        Leg { segments: Anthropometry::reference(), hip: HipSupport::Pinned, variant: Variant::Planar, knee_locked: false }
    }

    /// de Leva's male leg for `body_mass` (kg) and `height` (m), planar, pinned hip.
    pub fn de_leva(body_mass: f64, height: f64) -> Result<Leg, LegError> {
        Ok(Leg {
            segments: Anthropometry::de_leva_male(body_mass, height)?,
            hip: HipSupport::Pinned,
            variant: Variant::Planar,
            knee_locked: false,
        })
    }

    /// Refusals name the inputs as `kick leg` declares them (`abduction`,
    /// not the field's `hip_abduction`).
    fn validate(&self, pose: &Pose, impact: &Impact) -> Result<(), LegError> {
        check_range("hip", pose.hip_flexion, -90.0, 150.0, "deg")?;
        check_range("knee", pose.knee_flexion, -15.0, 170.0, "deg")?;
        check_range("ankle", pose.plantarflexion, -45.0, 100.0, "deg")?;
        check_range("abduction", pose.hip_abduction, -60.0, 90.0, "deg")?;
        check_range("rotation", pose.hip_rotation, -90.0, 90.0, "deg")?;
        check_range("contact", impact.contact_fraction, 0.0, 1.0, "of foot length")?;
        check_range("lateral_offset", impact.lateral_offset, -0.1, 0.1, "m")?;
        let norm = impact.direction.norm();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(LegError::InvalidInput { name: "direction", value: norm, requirement: "a finite, non-zero vector".into() });
        }
        if self.variant == Variant::Planar {
            // The planar leg lives in the sagittal plane; out-of-plane input
            // would be silently ignored, so refuse it.
            for (name, value) in [
                ("abduction", pose.hip_abduction),
                ("rotation", pose.hip_rotation),
                ("lateral_offset", impact.lateral_offset),
                ("direction_z", impact.direction.z),
            ] {
                if value != 0.0 {
                    return Err(LegError::InvalidInput {
                        name,
                        value,
                        requirement: "0 for the planar leg (use the spatial variant)".into(),
                    });
                }
            }
        }
        Ok(())
    }

    fn geometry(&self, pose: &Pose) -> Geometry {
        let s = &self.segments;
        // Thigh: flexion about z, then abduction about the anteroposterior
        // axis, then rotation about the long axis (intrinsic order).
        let thigh = rotation(Vector3::z(), pose.hip_flexion)
            * rotation(Vector3::x(), -pose.hip_abduction)
            * rotation(Vector3::y(), pose.hip_rotation);
        let shank = thigh * rotation(Vector3::z(), -pose.knee_flexion);
        // Neutral ankle: foot long axis at right angles to the shank, forward.
        let foot = shank * rotation(Vector3::z(), 90.0 - pose.plantarflexion);
        let hip = Vector3::zeros();
        let knee = hip + s.thigh.length * long_axis(&thigh);
        let ankle = knee + s.shank.length * long_axis(&shank);
        Geometry { hip, knee, ankle, frames: [thigh, shank, foot] }
    }

    /// The chain at `pose`: bodies thigh, shank, foot (or thigh and a rigid
    /// shank+foot when the ankle is locked), joints per variant and hip
    /// support, and the contact point. `knee_locked` merges thigh and shank
    /// too (used to compare with a single rigid body).
    pub fn chain(&self, pose: &Pose, impact: &Impact, knee_locked: bool, ankle_free: bool) -> Result<(Chain, Vector3<f64>), LegError> {
        self.validate(pose, impact)?;
        let g = self.geometry(pose);
        let s = &self.segments;
        let segments = [s.thigh, s.shank, s.foot];
        let origins = [g.hip, g.knee, g.ankle];
        let bodies: Vec<Body> = (0..3)
            .map(|i| {
                let frame = &g.frames[i];
                let seg = &segments[i];
                // Body frame: x anteroposterior, y along the segment, z mediolateral.
                let local = Matrix3::from_diagonal(&Vector3::new(seg.inertia_abduction, seg.inertia_long, seg.inertia_flexion));
                let r = frame.matrix();
                Body { mass: seg.mass, centre: origins[i] + seg.centre * long_axis(frame), inertia: r * local * r.transpose() }
            })
            .collect();
        let foot_frame = &g.frames[2];
        let contact =
            g.ankle + impact.contact_fraction * s.foot.length * long_axis(foot_frame) + impact.lateral_offset * (foot_frame * Vector3::z());

        let mut joints = Vec::new();
        if self.hip == HipSupport::Free {
            let axes: &[Vector3<f64>] = match self.variant {
                Variant::Planar => &[Vector3::x(), Vector3::y()],
                Variant::Spatial => &[Vector3::x(), Vector3::y(), Vector3::z()],
            };
            joints.extend(axes.iter().map(|&direction| Joint { motion: Motion::Prismatic { direction }, first_body: 0 }));
        }
        // A ball joint's angular velocities span R³ whatever its angles, so
        // the world axes serve (Eq. 11 is invariant to the parametrisation).
        let hip_axes: &[Vector3<f64>] = match self.variant {
            Variant::Planar => &[Vector3::z()],
            Variant::Spatial => &[Vector3::x(), Vector3::y(), Vector3::z()],
        };
        joints.extend(hip_axes.iter().map(|&axis| Joint { motion: Motion::Revolute { axis, point: g.hip }, first_body: 0 }));
        if !knee_locked {
            joints.push(Joint { motion: Motion::Revolute { axis: g.frames[0] * Vector3::z(), point: g.knee }, first_body: 1 });
        }
        if ankle_free {
            joints.push(Joint { motion: Motion::Revolute { axis: g.frames[1] * Vector3::z(), point: g.ankle }, first_body: 2 });
        }
        Ok((Chain { bodies, joints }, contact))
    }

    /// m_eff at the contact point (Eq. 11) for the given ankle behaviour.
    ///
    /// A joint stiffness has no place in Eq. 11 itself: M is a mass matrix and
    /// an impulse changes velocities before any spring has deflected. Over a
    /// contact of finite length t_c it matters through timing. A torsional
    /// spring κ on a hinge whose own rotational inertia is I_a (the inertia
    /// the ankle sees with the other joints free: I_a = 1/(M⁻¹)_aa) has
    /// natural frequency √(κ/I_a). If that is high against π/t_c, the spring
    /// follows the load and the ankle acts locked; if low, the spring barely
    /// loads within the contact and the ankle acts free.
    ///
    /// The interpolation between the limits is our model choice, not a
    /// derived result: the ankle's contribution to the contact-point mobility
    /// is scaled as a spring in series with the inertial stiffness
    /// κ_c = I_a (π/t_c)² (the stiffness of the foot's inertia at the contact
    /// frequency): 1/m_eff = w/m_locked + (1 − w)/m_free, w = κ/(κ + κ_c).
    /// It gives both limits exactly and is monotone in κ; the crossover
    /// (w = ½) is the joint whose half period equals the contact time.
    /// kick-leg's `ankle::elastic_ankle` replaces it by a time integration of the leg
    /// coupled to the ball; against that, this interpolation is off by up to
    /// ~6% in exit speed for the default pose (it locks too late: at κ = 1e4
    /// N m/rad the coupled leg is already nearly locked).
    pub fn effective_mass(&self, pose: &Pose, impact: &Impact, ankle: AnkleJoint) -> Result<LegEffectiveMass, LegError> {
        let n = impact.direction;
        let (locked_chain, x) = self.chain(pose, impact, self.knee_locked, false)?;
        let locked = locked_chain.effective_mass(&x, &n)?;
        let (free_chain, x) = self.chain(pose, impact, self.knee_locked, true)?;
        let free = free_chain.effective_mass(&x, &n)?;
        let m = free_chain.mass_matrix();
        let a = m.nrows() - 1; // the ankle is the last joint
        let inverse = m.cholesky().ok_or_else(|| LegError::Degenerate("mass matrix not positive definite".into()))?.inverse();
        let ankle_inertia = 1.0 / inverse[(a, a)];
        let locked_share = match ankle {
            AnkleJoint::Locked => 1.0,
            AnkleJoint::Free => 0.0,
            AnkleJoint::Elastic { stiffness, contact_time } => {
                check_range("ankle_stiffness", stiffness, 0.0, f64::MAX, "N m/rad")?;
                check_range("contact_time", contact_time, f64::MIN_POSITIVE, 1.0, "s")?;
                let inertial = ankle_inertia * (PI / contact_time).powi(2);
                stiffness / (stiffness + inertial)
            }
        };
        let mobility = locked_share / locked + (1.0 - locked_share) / free;
        Ok(LegEffectiveMass { effective_mass: 1.0 / mobility, locked_ankle: locked, free_ankle: free, locked_share, ankle_inertia })
    }
}
