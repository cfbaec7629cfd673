//! The articulated leg: effective mass at the contact point (Eq. 11), the
//! elastic ankle ([`ankle`]), the figures' grids and exit-speed curves.
//!
//! The leg itself (de Leva's segments, the chain, poses, Eq. 11 and its 6×6
//! generalisation) lives in kick-core's [`kick_core::leg`], since a scenario
//! with `leg = true` takes its foot from it; it is re-exported here under its
//! old paths (`kick_leg::Leg`, `kick_leg::anthropometry`, `kick_leg::chain`).

pub mod ankle;
pub use kick_core::leg::{anthropometry, chain, foot};
pub use kick_core::leg::{
    check_range, AnkleJoint, Anthropometry, Body, Chain, HipSupport, Impact, Joint, Leg, LegEffectiveMass, LegError, Motion, Pose, Segment,
    Variant, DE_LEVA_MALE,
};

use kick_compliant::Accurate;
use kick_core::{Outcome, Parameter, Scenario, Solver};

/// The 1D contact (Eqs. 13–20, `accurate` solver) with m_f = `effective_mass`
/// and every other parameter from `base`.
pub fn exit_outcome(effective_mass: f64, base: &Scenario) -> Result<Outcome, LegError> {
    let scenario = base.with(Parameter::FootMass, effective_mass)?;
    Ok(Accurate::default().solve(&scenario)?)
}

/// m_eff on a grid of knee × ankle angles (degrees), other angles from
/// `pose`: rows (knee, ankle, m_eff), knee-major. For the figure "effective
/// mass vs knee and ankle angle".
pub fn effective_mass_grid(
    leg: &Leg,
    pose: &Pose,
    impact: &Impact,
    ankle: AnkleJoint,
    knees: &[f64],
    ankles: &[f64],
) -> Result<Vec<(f64, f64, f64)>, LegError> {
    let mut rows = Vec::with_capacity(knees.len() * ankles.len());
    for &knee in knees {
        for &plantarflexion in ankles {
            let p = Pose { knee_flexion: knee, plantarflexion, ..*pose };
            rows.push((knee, plantarflexion, leg.effective_mass(&p, impact, ankle)?.effective_mass));
        }
    }
    Ok(rows)
}

/// Ball exit speed v_b⁺ of the 1D model for each effective foot mass: rows
/// (m_f, v_b⁺). For the figure "exit speed vs effective mass" (Section 14.1).
pub fn exit_speed_curve(masses: &[f64], base: &Scenario) -> Result<Vec<(f64, f64)>, LegError> {
    masses.iter().map(|&m| Ok((m, exit_outcome(m, base)?.v_ball_out))).collect()
}
