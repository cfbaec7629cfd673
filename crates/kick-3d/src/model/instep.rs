//! The kick's instep as the model builds it: its surface from the spec
//! (each value checked against its declaration), the patch's quadrature,
//! and where the instep first meets the ball. The contact over the patch
//! is [`crate::patch`]'s.

use super::{Instep, Kick3d, Kick3dSpec};
use crate::error::Kick3dError;
use kick_core::parameters as p;
use kick_core::{AnyLaw, KickError};
use parry3d_f64::math::Vec3;
use serde::Serialize;

/// The rule over a cap's patch: exact in the angle, Gauss–Legendre across
/// the rings. (The flat face needs none: closed form, see [`Patch::resultant`].)
///
/// In the angle θ every element's depth h depends on the ring alone and
/// its rate is affine in ρ⃗ · ṙ, so the sums over θ are closed forms
/// (Σ ρ⃗ = 0, Σ ρ⃗ (ρ⃗ · ṙ) = N ρ² ṙ_⊥ / 2 over equally spaced angles): no
/// angular nodes. Across the rings the nodes are equally weighted in
/// S = √((ν·q)² + R² − |q|²), the ball's half chord along the cap's normal
/// (ν passes through the cap's centre, so S² = κ² z² − B², κ = d/r_f,
/// B² = d² − R², z the ring's height on the cap's axis). In S the
/// integrands' only singularities are S = ±iB, many patch widths away, so
/// the rule converges about as fast as (width/4B)^(2n); in ρ² (16 rings
/// until this change) a branch point sat at κz = B, about one patch height
/// from the rim. Error of spin and launch velocity (5 and 10 cm offset
/// kicks on a 15 cm cap, μ = 0, 0.5 and ∞, approach 0 and 10°, rtol 1e-14,
/// against 40 rings; in rigid grip μ = 0.5 and ∞): 4 rings ≤ 1.7e-8,
/// 5 ≤ 2.5e-11, the default 6 ≤ 4.3e-13 (5.1e-14 in rigid grip), 8 ≤ 4.9e-15:
/// six keep the rule's error below the solver's own at its default
/// tolerance (~1e-11) at three quarters of eight's cost; `tests/model/patch.rs`
/// holds 6 against 12 within 1e-9.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Quadrature {
    pub rings: usize,
}

impl Default for Quadrature {
    fn default() -> Self {
        Quadrature { rings: 6 }
    }
}

/// The ball centre in the foot's body frame at first touch, and the normal there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Touch {
    /// r0, from the foot's centre of mass, body frame.
    pub centre: Vec3,
    /// Foot → ball, world frame.
    pub normal: Vec3,
}

/// [`Touch`] of a validated kick ([`instep`] refused any other).
pub fn first_touch(kick: &Kick3d, instep: &Instep) -> Touch {
    solve_touch(kick, instep).unwrap_or(Touch { centre: Vec3::new(kick.ball_radius + kick.face_distance(), 0.0, 0.0), normal: Vec3::X })
}

/// Where the instep first meets the ball: the pole moves on (0, e, 0) + s û.
fn solve_touch(kick: &Kick3d, instep: &Instep) -> Result<Touch, Kick3dError> {
    let big_r = kick.ball_radius;
    let h_x = kick.face_distance();
    let n_f = instep.face_normal();
    let u = kick.foot_direction();
    let line = kick.line_point();
    let q = instep.orientation();
    let facing = n_f.dot(u);
    if !(facing > 0.0) {
        return Err(Kick3dError::InvalidParameter {
            name: "face_yaw",
            value: instep.yaw.to_degrees(),
            requirement: "a face turned towards the foot's motion (n_f · û > 0)",
        });
    }
    if instep.is_curved() {
        let rf = instep.radius;
        // The cap's centre C = line + s û − r_f n_f at |C| = R + r_f.
        let w = line - n_f * rf;
        let wu = w.dot(u);
        let disc = wu * wu - w.length_squared() + (big_r + rf) * (big_r + rf);
        if !(disc >= 0.0) {
            return Err(Kick3dError::OffsetOutsideBall { offset: kick.offset, depth: kick.contact_depth, radius: big_r });
        }
        let s = -wu - disc.sqrt();
        let c = w + u * s;
        let centre = Vec3::new(h_x - rf, 0.0, 0.0) + q.inverse() * (-c);
        Ok(Touch { centre, normal: -c / c.length() })
    } else {
        // The face's plane touches the ball at −R n_f; the pole is on it.
        let s = n_f.dot(-n_f * big_r - line) / facing;
        let pole = line + u * s;
        let mut centre = q.inverse() * (-pole);
        centre.x = big_r + h_x;
        Ok(Touch { centre, normal: n_f })
    }
}

/// The kick's [`Instep`] from the spec (None when none of its parameters is
/// given), each value checked against its declaration.
pub fn instep(kick: &Kick3d, spec: &Kick3dSpec) -> Result<Option<Instep>, Kick3dError> {
    let patch = spec.patch_contact == Some(true);
    if spec.face_yaw_deg.is_none() && spec.face_pitch_deg.is_none() && spec.instep_radius.is_none() && !patch {
        return Ok(None);
    }
    let check = |def: &p::ParameterDef, value: f64| -> Result<f64, Kick3dError> {
        if def.valid.contains(value) {
            Ok(value)
        } else {
            Err(Kick3dError::InvalidParameter { name: def.name, value, requirement: def.valid.requirement })
        }
    };
    let (edge_yaw, edge_pitch) = kick.knife_edge_angles();
    let yaw = match spec.face_yaw_deg {
        Some(deg) => check(&p::FACE_YAW, deg)?.to_radians(),
        None => edge_yaw,
    };
    let pitch = match spec.face_pitch_deg {
        Some(deg) => check(&p::FACE_PITCH, deg)?.to_radians(),
        None => edge_pitch,
    };
    let given = check(&p::INSTEP_RADIUS, spec.instep_radius.unwrap_or(p::INSTEP_RADIUS.default_number()))?;
    let [_, hy, hz] = kick.foot_shape.core_half_extents();
    // The half-extent as printed and rounded down is the half-extent (kick_core::bound).
    let radius = if given == 0.0 {
        0.0
    } else {
        kick_core::bound::at_least(given, hy.max(hz)).ok_or(Kick3dError::InvalidParameter {
            name: "instep_radius",
            value: given,
            requirement: "0 (flat) or at least the face's half-extents (a cap over the whole face; up to 5e-4 below reads as it)",
        })?
    };
    if patch && !matches!(kick.base.contact_law(), AnyLaw::Shell(_)) {
        return Err(KickError::DoesNotApply {
            given: "patch_contact",
            to: format!("law `{}`", kick.base.law_kind().name()),
            reason: "the patch spreads the shell ball's force (`--law shell`), whose loss acts per element at its own rate",
        }
        .into());
    }
    let instep = Instep { radius, yaw, pitch, patch: patch.then(Quadrature::default) };
    let touch = solve_touch(kick, &instep)?;
    // The ball must meet the instep on its face (the cap over it).
    let n_body = instep.orientation().inverse() * touch.normal;
    let contact = touch.centre - n_body * kick.ball_radius;
    if contact.y.abs() > hy || contact.z.abs() > hz {
        // Name what the user gave that puts the contact off the face: on the
        // axis it misses by most, the face's own angle when given, else the
        // kick's (the approach angle up or down, the offset sideways; a
        // derived yaw or pitch was never given).
        let vertical = contact.z.abs() / hz >= contact.y.abs() / hy;
        let (name, value, requirement) = match (vertical, spec.face_pitch_deg, spec.face_yaw_deg) {
            (true, Some(pitch), _) => {
                ("face_pitch", pitch, "a face that meets the ball within its half-height (check face_pitch and approach_angle)")
            }
            (true, None, _) => (
                "approach_angle",
                spec.approach_angle_deg.unwrap_or(kick.approach_angle.to_degrees()),
                "an approach whose contact lies within the instep face's half-height (a rising foot meets the ball \
                 below the face's centre: lower approach_angle, or pitch the face with face_pitch)",
            ),
            (false, _, Some(yaw)) => ("face_yaw", yaw, "a face that meets the ball within its half-width (check face_yaw and offset)"),
            (false, _, None) => (
                "offset",
                spec.offset.unwrap_or(kick.offset),
                "an offset whose contact lies within the instep face's half-width (lower the offset, or turn the face with face_yaw)",
            ),
        };
        return Err(Kick3dError::InvalidParameter { name, value, requirement });
    }
    Ok(Some(instep))
}
