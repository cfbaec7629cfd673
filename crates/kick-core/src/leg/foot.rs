//! The foot of a kick as the articulated leg (`leg = true`): its apparent
//! inertia at the contact point, Eq. 11 and its 6×6 generalisation.
//!
//! The leg is `kick leg`'s: de Leva's (1996) reference male (73 kg, 1.741 m),
//! posed by hip, knee and ankle ([`LegPose`], the declared `hip`, `knee`,
//! `ankle`), hit at 0.65 of the foot's length along the horizontal forward
//! direction. Choices, each `kick leg`'s option of the same name:
//! - the hip pinned (pelvis and trunk do not move in a few ms);
//! - the knee a free hinge (no muscle is modelled);
//! - the ankle locked: a player braces it at impact ("a firm ankle"), and
//!   `kick leg --ankle-stiffness` shows the coupled ankle nearly locked from
//!   10⁴ N m/rad on; the free ankle's 0.64 kg gives ball/foot speed ratios
//!   below every measured kick;
//! - the spatial leg (a ball-joint hip): in 3D the foot can move out of the
//!   sagittal plane. At zero abduction and rotation the sagittal plane is a
//!   mirror plane of the leg, so along the forward direction the spatial
//!   leg's mass is the planar leg's (the test `the_spatial_leg_is_the_planar_one_along_its_plane`).
//!
//! The mobility is frozen at the contact pose (the Eq. 11 assumption: the
//! leg does not change configuration within the contact, and the velocity
//! products of its motion, centripetal and Coriolis, are left out), and
//! expressed in the kick's frame: x forward along the foot's line of motion,
//! y lateral (the leg's mediolateral axis reversed, so the frame stays
//! right-handed), z up.

use super::{HipSupport, Impact, Leg, LegError, Pose, Variant};
use crate::KickError;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

/// The leg's pose at contact, degrees (`kick leg`'s `--hip`, `--knee`, `--ankle`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LegPose {
    /// Thigh angle from the downward vertical, positive forward.
    pub hip: f64,
    /// Knee flexion, 0 straight.
    pub knee: f64,
    /// Ankle plantarflexion from neutral.
    pub ankle: f64,
}

impl LegPose {
    /// `kick leg`'s default pose: thigh 10° forward, knee 30°, ankle 60°.
    pub const DEFAULT: LegPose = LegPose { hip: 10.0, knee: 30.0, ankle: 60.0 };
}

impl Default for LegPose {
    fn default() -> Self {
        LegPose::DEFAULT
    }
}

/// Contact point along the foot, fraction of its length (`kick leg --contact`).
pub const CONTACT_FRACTION: f64 = 0.65;

/// The leg as a kick's foot: its mass along the line of motion and its 6×6
/// mobility at the contact point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegFoot {
    pub pose: LegPose,
    /// m_eff = (nᵀ Ω_vv n)⁻¹ along the forward direction n (Eq. 11), kg.
    pub effective_mass: f64,
    /// Ω: the foot's twist [ω; v(p)] per unit impulsive wrench [τ about p;
    /// F] at the contact point p, kick frame (module docs), 1/(kg m²), 1/(kg m), 1/kg.
    pub mobility: Matrix6<f64>,
}

/// Leg frame (x forward, y up, z lateral) to the kick's (x forward, y lateral, z up): (x, −z, y).
fn to_kick(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.x, -v.z, v.y)
}

impl LegFoot {
    /// The reference subject's leg at `pose` (module docs); a pose outside
    /// `kick leg`'s ranges is refused naming `hip`, `knee` or `ankle`. The
    /// last pose's leg is kept per thread: a sweep's kicks share a pose, and
    /// the chain's allocations would cost as much as a 1D kick.
    pub fn new(pose: LegPose) -> Result<LegFoot, KickError> {
        thread_local! {
            static LAST: std::cell::Cell<Option<LegFoot>> = const { std::cell::Cell::new(None) };
        }
        if let Some(foot) = LAST.with(|last| last.get()).filter(|f| f.pose == pose) {
            return Ok(foot);
        }
        let foot = LegFoot::compute(pose)?;
        LAST.with(|last| last.set(Some(foot)));
        Ok(foot)
    }

    fn compute(pose: LegPose) -> Result<LegFoot, KickError> {
        let leg = Leg { variant: Variant::Spatial, hip: HipSupport::Pinned, knee_locked: false, ..Leg::reference() };
        let pose_ =
            Pose { hip_flexion: pose.hip, knee_flexion: pose.knee, plantarflexion: pose.ankle, hip_abduction: 0.0, hip_rotation: 0.0 };
        let impact = Impact { contact_fraction: CONTACT_FRACTION, ..Impact::default() };
        let failed = |e: LegError| match e {
            LegError::InvalidInput { name, value, .. } => KickError::InvalidParameter {
                name: match name {
                    "hip" | "knee" | "ankle" => name,
                    _ => "leg",
                },
                value,
                requirement: "a pose `kick leg` accepts (hip -90..150, knee -15..170, ankle -45..100 degrees)",
            },
            other => KickError::Integration { time: 0.0, reason: other.to_string() },
        };
        let (chain, contact) = leg.chain(&pose_, &impact, false, false).map_err(failed)?;
        let leg_frame = chain.spatial_mobility(&contact).map_err(failed)?;
        // Both halves of a twist and of a wrench turn alike.
        let mut turn = Matrix3::zeros();
        for i in 0..3 {
            turn.set_column(i, &to_kick(&Matrix3::<f64>::identity().column(i).into_owned()));
        }
        let mut rotate = Matrix6::zeros();
        rotate.fixed_view_mut::<3, 3>(0, 0).copy_from(&turn);
        rotate.fixed_view_mut::<3, 3>(3, 3).copy_from(&turn);
        let mobility = rotate * leg_frame * rotate.transpose();
        let forward = mobility[(3, 3)];
        if !(forward.is_finite() && forward > 0.0) {
            return Err(KickError::Integration { time: 0.0, reason: "the leg's foot cannot move along the line of motion".into() });
        }
        Ok(LegFoot { pose, effective_mass: 1.0 / forward, mobility })
    }

    /// Ω about another point of the foot, `offset` = that point − the contact
    /// point (kick frame): v(o) = v(p) + ω × offset and τ_p = τ_o + offset × F,
    /// so Ω_o = T Ω_p Tᵀ with T = [[1, 0], [−[offset]×, 1]].
    pub fn mobility_about(&self, offset: Vector3<f64>) -> Matrix6<f64> {
        let mut t = Matrix6::identity();
        t.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-offset.cross_matrix()));
        t * self.mobility * t.transpose()
    }

    /// The twist change [Δω; Δv(p)] for an impulsive wrench (convenience for tests).
    pub fn response(&self, wrench: &Vector6<f64>) -> Vector6<f64> {
        self.mobility * wrench
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::leg::AnkleJoint;

    /// Along the forward direction the spatial leg's mass is the planar
    /// leg's of `kick leg --locked-ankle` (1.327 kg at the default pose),
    /// across poses: the sagittal plane is a mirror plane of the leg.
    #[test]
    fn the_spatial_leg_is_the_planar_one_along_its_plane() {
        for (hip, knee, ankle) in [(10.0, 30.0, 60.0), (0.0, 0.0, 30.0), (20.0, 40.0, 90.0), (-10.0, 80.0, 45.0)] {
            let foot = LegFoot::new(LegPose { hip, knee, ankle }).unwrap();
            let planar = Leg::reference()
                .effective_mass(
                    &Pose { hip_flexion: hip, knee_flexion: knee, plantarflexion: ankle, hip_abduction: 0.0, hip_rotation: 0.0 },
                    &Impact { contact_fraction: CONTACT_FRACTION, ..Impact::default() },
                    AnkleJoint::Locked,
                )
                .unwrap()
                .effective_mass;
            assert!((foot.effective_mass - planar).abs() <= 1e-12 * planar, "{hip} {knee} {ankle}: {} vs {planar}", foot.effective_mass);
        }
        let default = LegFoot::new(LegPose::DEFAULT).unwrap();
        assert!((default.effective_mass - 1.32686).abs() < 1e-5, "{}", default.effective_mass);
    }

    /// The mobility is symmetric, positive semi-definite of rank 4 (ball-joint
    /// hip and knee: the foot cannot translate and turn freely in all six
    /// directions); the mirror plane leaves no coupling between the sagittal
    /// (x, z, rotation about y) and the lateral motions; shifting the point
    /// and back is the identity, and the point's own twist is the same
    /// whichever point the wrench is taken about.
    #[test]
    fn the_mobility_is_a_symmetric_rank_four_operator() {
        let foot = LegFoot::new(LegPose::DEFAULT).unwrap();
        let m = foot.mobility;
        assert!((m - m.transpose()).abs().max() <= 1e-15 * m.abs().max());
        let eigen = m.symmetric_eigen().eigenvalues;
        let largest = eigen.max();
        let positive = eigen.iter().filter(|&&e| e > 1e-10 * largest).count();
        assert!(eigen.iter().all(|&e| e > -1e-12 * largest), "{eigen}");
        assert_eq!(positive, 4, "{eigen}");
        for sagittal in [1usize, 3, 5] {
            for lateral in [0usize, 2, 4] {
                assert!(m[(sagittal, lateral)].abs() <= 1e-12 * largest, "{sagittal} {lateral}: {}", m[(sagittal, lateral)]);
            }
        }
        let d = Vector3::new(-0.04, 0.01, 0.02);
        let there = LegFoot { mobility: foot.mobility_about(d), ..foot };
        let back = there.mobility_about(-d);
        assert!((back - m).abs().max() <= 1e-12 * largest);
        // A force F at p: the twist at o from Ω_o with the wrench moved to o
        // equals Ω_p's twist moved to o.
        let f = Vector3::new(100.0, -20.0, 5.0);
        let at_p = m * Vector6::new(0.0, 0.0, 0.0, f.x, f.y, f.z);
        let moved = at_p.fixed_rows::<3>(3) + at_p.fixed_rows::<3>(0).cross(&d);
        let torque_o = (-d).cross(&f);
        let at_o = foot.mobility_about(d) * Vector6::new(torque_o.x, torque_o.y, torque_o.z, f.x, f.y, f.z);
        assert!((at_o.fixed_rows::<3>(3) - moved).norm() <= 1e-12 * moved.norm());
        assert!((at_o.fixed_rows::<3>(0) - at_p.fixed_rows::<3>(0)).norm() <= 1e-12 * at_p.norm());
    }

    #[test]
    fn a_pose_outside_the_ranges_names_the_angle() {
        let e = LegFoot::new(LegPose { knee: 200.0, ..LegPose::DEFAULT }).unwrap_err();
        assert!(matches!(e, KickError::InvalidParameter { name: "knee", .. }), "{e:?}");
    }
}
