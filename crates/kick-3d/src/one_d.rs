//! The 1D reduction: a central, square kick is the 1D contact along the
//! normal, because the normal force of a sphere passes through its centre
//! and, with the foot's centre of mass behind the face centre, through the
//! foot's too. [`solve_along_normal`] also covers a frictionless oblique kick
//! when the foot cannot turn (the contact point then slides along the face
//! with no effect); tangential velocities ride along unchanged (plus the
//! drive's tangential part on the foot).

use crate::error::Kick3dError;
use crate::model::Kick3d;
use crate::outcome::{EnergyPartition, Outcome3d};
use kick_compliant::Accurate;
use kick_core::Solver;

/// Solve with `kick_compliant::Accurate` and rotate back to 3D.
/// Refuses kicks that are not one-dimensional (see [`Kick3d::is_one_dimensional`]).
pub fn solve(kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
    if !kick.is_one_dimensional() {
        return Err(Kick3dError::UnsupportedScene {
            path: "1d",
            reason: "the kick is off-center or oblique (the surfaces slide), gravity is on, or the foot is the leg (its contact point swings on an arc)",
        });
    }
    solve_along_normal(kick)
}

/// The 1D solution along the initial normal without the routing check: exact
/// for [`Kick3d::is_one_dimensional`] kicks, and for frictionless kicks with
/// a foot that does not turn (a model of the accurate path, used by tests).
pub fn solve_along_normal(kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
    if kick.gravity {
        return Err(Kick3dError::UnsupportedScene { path: "1d", reason: "gravity is on" });
    }
    if kick.ground {
        return Err(Kick3dError::UnsupportedScene { path: "1d", reason: "a ground plane is a third body" });
    }
    let scenario = kick.normal_scenario()?;
    let o = Accurate::default().solve(&scenario)?;
    crate::outcome::within_geometry(kick, o.max_compression, o.max_compression_time)?;
    let n = kick.initial_normal();
    let start = kick.initial_state();
    let tangential = |v: parry3d_f64::math::Vec3| v - n * v.dot(n);
    let m_f = kick.base.effective_foot_mass();
    let m_b = kick.base.ball_mass();
    let drive_t = tangential(kick.drive());
    let foot_t0 = tangential(start.foot_velocity);
    let foot_t = foot_t0 + drive_t * (o.contact_time / m_f);
    let ball = n * o.v_ball_out + tangential(start.ball_velocity);
    let foot = n * o.v_foot_out + foot_t;
    let impulse = n * o.impulse;
    let mut out = Outcome3d {
        launch_velocity: ball.to_array(),
        spin: [0.0; 3],
        speed: 0.0,
        spin_rpm: 0.0,
        launch_angle: 0.0,
        launch_azimuth: 0.0,
        foot_velocity: foot.to_array(),
        foot_angular_velocity: [0.0; 3],
        contact_time: o.contact_time,
        peak_normal_force: o.peak_force,
        peak_normal_force_time: o.peak_force_time,
        peak_tangential_force: 0.0,
        peak_tangential_force_time: 0.0,
        max_compression: o.max_compression,
        max_compression_time: o.max_compression_time,
        // Frictionless: no Coulomb element, so no slip phase; a central square
        // kick with friction never slides.
        slip_time: 0.0,
        impulse: impulse.to_array(),
        normal_impulse: o.impulse,
        angular_impulse: [0.0; 3],
        angular_impulse_fixed_point: [0.0; 3],
        energy: EnergyPartition {
            kinetic_initial: kick.initial_kinetic_energy(),
            ball_translation: 0.5 * m_b * ball.length_squared(),
            ball_spin: 0.0,
            foot: 0.5 * m_f * foot.length_squared(),
            elastic_final: o.energy.elastic_final,
            normal_damping_loss: o.energy.dissipated,
            friction_loss: 0.0,
            // normal part from the 1D run, tangential part in closed form
            drive_work: o.energy.drive_work + 0.5 * m_f * (foot_t.length_squared() - foot_t0.length_squared()),
            gravity_work: 0.0,
        },
        evaluations: o.evaluations,
        solver: "1d",
        law: scenario.law_kind(),
    };
    out.derive_summary();
    Ok(out.check_finite()?)
}
