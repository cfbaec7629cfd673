//! Uniform time histories of the accurate 3D path ([`Accurate3d::solve_streamed`]).
//!
//! Samples fall as in 1D ([`kick_core::Spacing`]): t_k = k Δ from first
//! touch, every grid time strictly before separation, then one separation
//! row at the contact time (the outcome's end state, to the bit). A grid
//! sample is read from the 7th-order dense output of the accepted step that
//! holds it, on the branch of the phase that step belongs to (in the phases
//! whose independent variable is u = δ^(1/p), the u at which the integrated
//! time equals t_k is found by Brent's method on the same dense output). The
//! steps never see the grid, so the outcome is bit-identical with and
//! without a history, and a step whose dense output the run did not need is
//! interpolated for the history alone (three evaluations, not counted in
//! [`crate::Outcome3d::evaluations`]).
//!
//! Everything is in the world frame of [`crate::Outcome3d`] (x: the foot's
//! line of motion, z up), SI units; the columns are [`HISTORY_COLUMNS_3D`].

use crate::contact::{self, Clock, Friction, Relative, State, TIME};
use crate::model::Kick3d;
use crate::Accurate3d;
use crate::Kick3dError;
use kick_core::dop853::Dense;
use kick_core::{roots, Spacing};
use parry3d_f64::math::Vec3;
use std::ops::ControlFlow;

/// The contact's state in a sample ([`Sample3d::contact_state`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ContactState {
    /// The separation row (code 0).
    Separation,
    /// The contact points move together (the ball's surface in contact and
    /// the foot; the spring, the shell's compliance, takes the rest):
    /// |F_t| ≤ μ F_n (code 1; always for μ = ∞). See [`crate::tangential`].
    Grip,
    /// The contact points slide: |F_t| = μ F_n (code 2; also μ = 0, with no force).
    Slip,
}

impl ContactState {
    /// The number stored in the `contact_state` column.
    pub fn code(self) -> f64 {
        match self {
            ContactState::Separation => 0.0,
            ContactState::Grip => 1.0,
            ContactState::Slip => 2.0,
        }
    }
}

/// One sample of a 3D history, world frame, SI units.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Sample3d {
    pub time: f64,
    pub ball_position: [f64; 3],
    pub ball_velocity: [f64; 3],
    pub ball_angular_velocity: [f64; 3],
    pub foot_position: [f64; 3],
    pub foot_velocity: [f64; 3],
    pub foot_angular_velocity: [f64; 3],
    /// δ, m.
    pub compression: f64,
    /// The normal force on the ball, N: F_n n at a point contact; over a
    /// patch ([`crate::patch`]) the resultant of the element forces (on a
    /// cap not quite along n: each element pushes along its own normal).
    pub normal_force: [f64; 3],
    /// F_t on the ball, N.
    pub tangential_force: [f64; 3],
    pub contact_state: ContactState,
    /// The normal force's moment about the ball's centre, N m: zero at a
    /// point contact (its line passes through the centre), not over a patch.
    pub normal_moment: [f64; 3],
    /// Where the tangential force acts, from the ball's centre, m: −R n at a
    /// point contact, the patch's centroid over a patch (friction's arm).
    pub contact_arm: [f64; 3],
    /// The contact points' relative tangential velocity (ball's surface less
    /// the foot's), m/s: zero while gripping, the slider's while slipping
    /// ([`crate::tangential`]); with rigid grip and at μ = 0 the sliding of
    /// the material points at the contact.
    pub slip_velocity: [f64; 3],
}

/// Names and units of a 3D history's columns, in [`Sample3d::values`] order:
/// vectors as `_x`, `_y`, `_z`; `contact_state` holds [`ContactState::code`]
/// (0 separation, 1 grip, 2 slip); `slip_velocity` is what the state is
/// named by (zero in grip).
pub const HISTORY_COLUMNS_3D: [(&str, &str); 30] = [
    ("time", "s"),
    ("ball_position_x", "m"),
    ("ball_position_y", "m"),
    ("ball_position_z", "m"),
    ("ball_velocity_x", "m/s"),
    ("ball_velocity_y", "m/s"),
    ("ball_velocity_z", "m/s"),
    ("ball_angular_velocity_x", "rad/s"),
    ("ball_angular_velocity_y", "rad/s"),
    ("ball_angular_velocity_z", "rad/s"),
    ("foot_position_x", "m"),
    ("foot_position_y", "m"),
    ("foot_position_z", "m"),
    ("foot_velocity_x", "m/s"),
    ("foot_velocity_y", "m/s"),
    ("foot_velocity_z", "m/s"),
    ("foot_angular_velocity_x", "rad/s"),
    ("foot_angular_velocity_y", "rad/s"),
    ("foot_angular_velocity_z", "rad/s"),
    ("compression", "m"),
    ("normal_force_x", "N"),
    ("normal_force_y", "N"),
    ("normal_force_z", "N"),
    ("tangential_force_x", "N"),
    ("tangential_force_y", "N"),
    ("tangential_force_z", "N"),
    ("contact_state", "1"),
    ("slip_velocity_x", "m/s"),
    ("slip_velocity_y", "m/s"),
    ("slip_velocity_z", "m/s"),
];

impl Sample3d {
    /// Values in [`HISTORY_COLUMNS_3D`] order.
    pub fn values(&self) -> [f64; 30] {
        let mut v = [0.0; 30];
        v[0] = self.time;
        for (i, a) in [
            self.ball_position,
            self.ball_velocity,
            self.ball_angular_velocity,
            self.foot_position,
            self.foot_velocity,
            self.foot_angular_velocity,
        ]
        .iter()
        .enumerate()
        {
            v[1 + 3 * i..4 + 3 * i].copy_from_slice(a);
        }
        v[19] = self.compression;
        v[20..23].copy_from_slice(&self.normal_force);
        v[23..26].copy_from_slice(&self.tangential_force);
        v[26] = self.contact_state.code();
        v[27..30].copy_from_slice(&self.slip_velocity);
        v
    }
}

/// The patch's columns ([`Sample3d::patch_values`] order), written after
/// [`HISTORY_COLUMNS_3D`] for a kick whose normal force is spread over a
/// patch: the ball's spin obeys I_b ω̇ = M + a × F_t with M the
/// `normal_moment` and a the `contact_arm` (world frame).
pub const PATCH_COLUMNS_3D: [(&str, &str); 6] = [
    ("normal_moment_x", "N m"),
    ("normal_moment_y", "N m"),
    ("normal_moment_z", "N m"),
    ("contact_arm_x", "m"),
    ("contact_arm_y", "m"),
    ("contact_arm_z", "m"),
];

impl Sample3d {
    /// Values in [`PATCH_COLUMNS_3D`] order.
    pub fn patch_values(&self) -> [f64; 6] {
        let [mx, my, mz] = self.normal_moment;
        let [ax, ay, az] = self.contact_arm;
        [mx, my, mz, ax, ay, az]
    }
}

/// The grid's samples are handed over by kick-compliant's sampler.
pub type Sampler3d<'a> = kick_compliant::history::Sampler<'a, Sample3d>;

fn array(v: Vec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// The sample at (x, y), time t, on `system`'s phase (`state` overrides the
/// phase's grip or slip: the separation row).
pub(crate) fn sample(kick: &Kick3d, system: &Relative, x: f64, y: &State, t: f64, state: Option<ContactState>) -> Sample3d {
    let e = contact::end_state(kick, system, x, y, t);
    let c = system.local(x, y);
    let q = e.foot_orientation;
    let contact_state = state.unwrap_or(match system.phase.friction {
        Friction::Grip => ContactState::Grip,
        Friction::Slip | Friction::None => ContactState::Slip,
    });
    // The force on the ball as the right-hand side applies it (contact::Relative::derivative).
    let (normal_force, normal_moment, arm) = match c.patch {
        Some(p) => (p.force, p.moment, c.point - system.centre(y)),
        None => (c.normal * c.normal_force, Vec3::ZERO, c.normal * -system.ball_radius),
    };
    Sample3d {
        time: t,
        ball_position: array(e.ball_position),
        ball_velocity: array(e.ball_velocity),
        ball_angular_velocity: array(e.ball_angular_velocity),
        foot_position: array(e.foot_position),
        foot_velocity: array(e.foot_velocity),
        foot_angular_velocity: array(e.foot_angular_velocity),
        compression: c.compression,
        normal_force: array(q * normal_force),
        tangential_force: array(q * c.tangential_force),
        contact_state,
        normal_moment: array(q * normal_moment),
        contact_arm: array(q * arm),
        slip_velocity: array(q * c.slip_velocity),
    }
}

/// The sample at time t within the stretch [x0, x1] of one step's dense output.
pub(crate) fn sample_in(kick: &Kick3d, system: &Relative, dense: &Dense<{ contact::DIM }>, x0: f64, x1: f64, t: f64) -> Sample3d {
    let x = match system.phase.clock {
        Clock::Time => t.clamp(x0, x1),
        // t(x) increases through the stretch: its root is unique.
        Clock::Onset | Clock::Release { .. } => {
            let g = |x: f64| dense.component(TIME, x) - t;
            if g(x0) >= 0.0 {
                x0
            } else if g(x1) <= 0.0 {
                x1
            } else {
                roots::brent(g, x0, x1, 4.0 * f64::EPSILON * x1.abs(), 200).map_or(x1, |r| r.x)
            }
        }
    };
    sample(kick, system, x, &dense.at(x), t, None)
}

impl Accurate3d {
    /// Solve and hand each sample of the history on `spacing`'s grid to
    /// `sink` in time order (nothing kept: any length streams in bounded
    /// memory); returns the outcome, bit-identical to [`Accurate3d::solve`]'s,
    /// and the number of samples of the full history. `sink` returns `Break`
    /// to stop sampling; the solve still runs to its outcome.
    /// [`Spacing::Count`] solves twice (the grid needs the contact time).
    pub fn solve_streamed(
        &self,
        kick: &Kick3d,
        spacing: Spacing,
        sink: &mut dyn FnMut(&Sample3d) -> ControlFlow<()>,
    ) -> Result<(crate::Outcome3d, u64), Kick3dError> {
        kick_compliant::history::stream_any(
            spacing,
            sink,
            |o: &crate::Outcome3d| o.contact_time,
            |sampler| Ok(self.run::<true>(kick, None, sampler)?.0),
        )
    }

    /// [`Self::solve_streamed`] collected, at most `limit` samples (a longer
    /// history is refused before it is kept).
    pub fn solve_sampled(&self, kick: &Kick3d, spacing: Spacing, limit: usize) -> Result<(crate::Outcome3d, Vec<Sample3d>), Kick3dError> {
        if let Spacing::Count(n) = spacing.validate()? {
            if n > limit {
                return Err(kick_core::KickError::HistoryTooLong { needed: n as f64, limit: limit as u64 }.into());
            }
        }
        let mut samples = Vec::new();
        let (outcome, total) = self.solve_streamed(kick, spacing, &mut |s| {
            if samples.len() < limit {
                samples.push(*s);
                ControlFlow::Continue(())
            } else {
                ControlFlow::Break(())
            }
        })?;
        if total > limit as u64 {
            return Err(kick_core::KickError::HistoryTooLong { needed: total as f64, limit: limit as u64 }.into());
        }
        Ok((outcome, samples))
    }
}

#[cfg(test)]
mod tests {
    use crate::{Accurate3d, Kick3d, Kick3dError};
    use kick_core::{KickError, Spacing, MAX_HISTORY_SAMPLES};
    use std::ops::ControlFlow;

    /// A 3D history's rows are counted before the first is made (t_c / Δ + 1
    /// from the kick solved alone) and refused beyond MAX_HISTORY_SAMPLES,
    /// the sink never called: `simulate3d --interval 1e-300` used to spin.
    #[test]
    fn a_3d_history_longer_than_the_limit_is_refused_before_its_first_row() {
        let kick = Kick3d::baseline();
        let solver = Accurate3d::default();
        let contact_time = solver.solve(&kick).unwrap().contact_time;
        for interval in [contact_time / (2.0 * MAX_HISTORY_SAMPLES as f64), 1e-300] {
            let mut rows = 0u64;
            let result = solver.solve_streamed(&kick, Spacing::Interval(interval), &mut |_| {
                rows += 1;
                ControlFlow::Continue(())
            });
            match result {
                Err(Kick3dError::Core(KickError::HistoryTooLong { needed, .. })) => {
                    let expected = (contact_time / interval).ceil() + 1.0;
                    assert!((needed - expected).abs() <= 1.0 + 1e-12 * expected, "{interval}: {needed} {expected}");
                }
                other => panic!("{interval}: {other:?}"),
            }
            assert_eq!(rows, 0, "{interval}");
        }
    }
}
