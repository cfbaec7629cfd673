//! `rapier`: the scene path. A rapier3d world holds the foot, the ball and
//! whatever else the scene needs (a ground plane and gravity now, an
//! articulated leg later). Rapier's own contact response is switched off for
//! the foot–ball pair with solver groups; the project's law
//! ([`Dynamics::contact`], the same function the accurate path integrates) is
//! applied as external forces and torques at every rapier step; the
//! tangential element advances by its return map ([`crate::tangential::return_map`],
//! the fixed-step form of the same law) and the loss integrals by explicit
//! Euler, next to rapier's own (semi-implicit Euler) update.
//!
//! Error: first order in the step (observed order 1.00 ± 0.01 against the
//! accurate path, `kick simulate3d --scene-convergence`). Across the swept
//! range (offset to ±9 cm, approach angle to 40°, μ from 0 to 2) launch
//! velocity and spin are off by at most 3e-4 relative per microsecond of step
//! with the paper's law (measured: velocity 0.9–1.2e-4, spin up to 2.8e-4 at
//! μ = 2, where the gripping spring rings undamped through most of the
//! contact and the step's error accumulates in its phase); with the other
//! laws the constant differs (Hunt–Crossley and Kelvin–Voigt at e = 0.6 on a
//! 5 cm, 10° kick: up to 0.9e-4 per microsecond); tests/model/scene.rs holds
//! the order and the bound.
//! The default step of 1e-6 s (~5300 steps per contact) gives ~1e-4. The
//! contact time is the linear interpolation of δ between the last two steps.
//! The path exists for
//! scenes the accurate path cannot hold (ground, later a leg), not for precision.

use crate::dynamics::{self, Dynamics, State};
use crate::error::Kick3dError;
use crate::model::{FootShape, Kick3d};
use crate::outcome::{self, Outcome3d, Peak, Peaks};
use parry3d_f64::math::Vec3;
use rapier3d_f64::prelude::*;

/// Collision groups: the foot–ball pair never reaches rapier's solver.
const FOOT: Group = Group::GROUP_1;
const BALL: Group = Group::GROUP_2;
const GROUND: Group = Group::GROUP_3;

/// Most rapier steps one scene run takes. One step costs 2.6 µs (`cargo
/// bench -p kick-3d --features bench --bench solve3d --profile test --
/// rapier`: 13.9 ms for the baseline kick's 5,293 steps at dt = 1e-6 s, on 2
/// shared cores) and up to 7.2 µs in the unoptimised `kick` binary on a
/// loaded machine (1e7 steps of a contact that never separates took 72 s),
/// so a run ends within about 5 s (15 s unoptimised), where the 2e8 steps
/// kick-compliant allows RK4 would be 9 minutes of rapier. The horizon over
/// dt is still refused beyond 2e8 up front; a contact still open after this
/// many steps is a numerical limit (naming `--dt`), not a finding. Real
/// contacts take far fewer: 5,293 for the baseline kick at the default dt,
/// 2e6 would be a 2 s contact there or a 20 ms one at dt = 1e-8 s.
pub const MAX_SCENE_STEPS: u64 = 2_000_000;

/// The rapier scene path with a fixed step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene {
    /// Rapier step Δt, s; the law is applied once per step.
    pub step: f64,
    /// Most steps one run takes ([`MAX_SCENE_STEPS`]).
    pub budget: u64,
}

impl Default for Scene {
    fn default() -> Self {
        Scene { step: crate::DEFAULT_SCENE_STEP, budget: MAX_SCENE_STEPS }
    }
}

/// Largest accepted step: a tenth of a millisecond, ~1/90 of the baseline contact.
pub const MAX_STEP: f64 = 1e-4;

impl Scene {
    pub fn new(step: f64) -> Result<Scene, Kick3dError> {
        if !(step.is_finite() && step > 0.0 && step <= MAX_STEP) {
            return Err(Kick3dError::InvalidParameter { name: "dt", value: step, requirement: "in (0, 1e-4] s" });
        }
        Ok(Scene { step, budget: MAX_SCENE_STEPS })
    }

    /// Run the kick in a rapier world.
    pub fn solve(&self, kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
        if kick.rigid_grip() {
            return Err(Kick3dError::UnsupportedScene { path: "rapier", reason: crate::model::RIGID_GRIP_PATHS });
        }
        kick.require_point_contact_box("rapier")?;
        if kick.leg.is_some() || kick.base.boot().is_some() {
            return Err(Kick3dError::UnsupportedScene {
                path: "rapier",
                reason: "the scene's foot is the free box against the ball itself: the leg and the boot run on the accurate and full-state paths",
            });
        }
        let dynamics = Dynamics::new(kick);
        let start = dynamics::initial_state(kick);
        let init = kick.initial_state();
        let mut world = PhysicsWorld::new();
        world.gravity = kick.gravity_vector();
        world.integration_parameters.dt = self.step;
        world.integration_parameters.num_solver_iterations = 1;
        world.integration_parameters.normalized_max_linear_velocity = f64::MAX;

        let [ix, iy, iz] = kick.foot_inertia;
        let foot_body = RigidBodyBuilder::dynamic()
            .pose(Pose::from_parts(init.foot_position, init.foot_orientation))
            .linvel(init.foot_velocity)
            .additional_mass_properties(MassProperties::new(Vec3::ZERO, kick.base.effective_foot_mass(), Vec3::new(ix, iy, iz)))
            .can_sleep(false);
        let foot = world.bodies.insert(foot_body);
        let [hx, hy, hz] = kick.foot_shape.core_half_extents();
        let foot_collider = match kick.foot_shape {
            FootShape::Box { .. } => ColliderBuilder::cuboid(hx, hy, hz),
            FootShape::RoundedBox { border_radius, .. } => ColliderBuilder::round_cuboid(hx, hy, hz, border_radius),
        }
        .density(0.0)
        .solver_groups(InteractionGroups::new(FOOT, Group::ALL.difference(BALL), InteractionTestMode::And));
        world.colliders.insert_with_parent(foot_collider, foot, &mut world.bodies);

        let i_b = kick.ball_inertia;
        let ball_body = RigidBodyBuilder::dynamic()
            .translation(init.ball_position)
            .linvel(init.ball_velocity)
            .additional_mass_properties(MassProperties::new(Vec3::ZERO, kick.base.ball_mass(), Vec3::splat(i_b)))
            .can_sleep(false);
        let ball = world.bodies.insert(ball_body);
        let ball_collider = ColliderBuilder::ball(kick.ball_radius).density(0.0).solver_groups(InteractionGroups::new(
            BALL,
            Group::ALL.difference(FOOT),
            InteractionTestMode::And,
        ));
        world.colliders.insert_with_parent(ball_collider, ball, &mut world.bodies);

        if kick.ground {
            // Ground top at z = −R: the ball rests on it at first touch.
            let ground = world.bodies.insert(RigidBodyBuilder::fixed().translation(Vec3::new(0.0, 0.0, -kick.ball_radius - 1.0)));
            let slab = ColliderBuilder::cuboid(50.0, 50.0, 1.0).solver_groups(InteractionGroups::new(
                GROUND,
                Group::ALL,
                InteractionTestMode::And,
            ));
            world.colliders.insert_with_parent(slab, ground, &mut world.bodies);
        }

        let horizon = kick.contact_horizon()?;
        // A step budget refused up front (run time is ∝ 1/dt), and the
        // scene's own bound on the steps taken.
        let horizon_steps = kick_compliant::events::fixed_steps(horizon, self.step)?;
        let max_steps = horizon_steps.min(self.budget);
        let mut y = start;
        let first = dynamics.contact(&y);
        let mut peak_normal = Peak { value: first.normal_force, time: 0.0 };
        let mut peak_tangential = Peak { value: 0.0, time: 0.0 };
        let mut max_compression = (0.0f64, 0.0);
        let mut slip_time = 0.0;
        let mut t = 0.0;
        let mut previous_delta = 0.0;
        let dt = self.step;
        for step in 0..max_steps {
            pack(&world.bodies[foot], &world.bodies[ball], &mut y);
            let c = dynamics.contact(&y);
            if step > 0 && c.compression <= 0.0 {
                // Separated during the last step: interpolate δ linearly.
                let t_sep = t - dt * c.compression / (c.compression - previous_delta);
                let peaks = Peaks { normal: peak_normal, tangential: peak_tangential, compression: max_compression, slip_time };
                let end = dynamics.end_state(kick, &y, t_sep);
                let mut out = outcome::assemble(kick, &end, peaks, step, "rapier")?;
                out.evaluations = step;
                return Ok(out);
            }
            if c.compression > max_compression.0 {
                outcome::within_geometry(kick, c.compression, t)?;
                max_compression = (c.compression, t);
            }
            // The tangential element over this step: the return map of
            // `tangential` (the spring, kept in the tangent plane, takes v_t Δt).
            let xi = dynamics::vec3(&y, dynamics::SPRING);
            let xi_t = xi - c.normal * c.normal.dot(xi);
            let cap = if kick.friction.is_infinite() { f64::INFINITY } else { kick.friction * c.normal_force };
            let (spring, slipped, travel) = if kick.friction == 0.0 {
                (Vec3::ZERO, false, 0.0)
            } else {
                crate::tangential::return_map(kick.tangential_stiffness, xi_t, c.sliding_velocity, cap, dt)
            };
            let tangential = spring * -kick.tangential_stiffness;
            peak_normal.observe(c.normal_force, t);
            peak_tangential.observe(tangential.length(), t);
            if slipped {
                slip_time += dt;
            }
            previous_delta = c.compression;
            let force = c.normal * c.normal_force + tangential;
            {
                let b = &mut world.bodies[ball];
                b.reset_forces(true);
                b.reset_torques(true);
                b.add_force(force, true);
                b.add_torque(c.lever_ball.cross(force), true);
            }
            {
                let f = &mut world.bodies[foot];
                f.reset_forces(true);
                f.reset_torques(true);
                f.add_force(dynamics.drive - force, true);
                f.add_torque(c.lever_foot.cross(-force), true);
            }
            // The law's own integrals, explicit Euler, from the force applied;
            // the spring turns with the foot.
            let (v_f, v_b) = (dynamics::vec3(&y, dynamics::FOOT_VELOCITY), dynamics::vec3(&y, dynamics::BALL_VELOCITY));
            let w_f = dynamics::vec3(&y, dynamics::FOOT_ANGULAR_VELOCITY);
            let add = |y: &mut State, i: usize, v: Vec3| {
                y[i] += v.x;
                y[i + 1] += v.y;
                y[i + 2] += v.z;
            };
            let turned = spring + w_f.cross(spring) * dt;
            y[dynamics::SPRING] = turned.x;
            y[dynamics::SPRING + 1] = turned.y;
            y[dynamics::SPRING + 2] = turned.z;
            add(&mut y, dynamics::IMPULSE, force * dt);
            add(&mut y, dynamics::ANGULAR_IMPULSE, c.lever_ball.cross(force) * dt);
            y[dynamics::NORMAL_IMPULSE] += c.normal_force * dt;
            y[dynamics::DAMPING_LOSS] += c.damping_power * dt;
            y[dynamics::FRICTION_LOSS] += if slipped { cap * travel } else { 0.0 };
            y[dynamics::DRIVE_WORK] += dynamics.drive.dot(v_f) * dt;
            y[dynamics::GRAVITY_WORK] += dynamics.gravity.dot(v_f * dynamics.foot_mass + v_b * dynamics.ball_mass) * dt;
            world.step();
            t += dt;
        }
        let reason = if max_steps < horizon_steps {
            format!(
                "rapier scene: contact outlasted the budget of {max_steps} steps of dt = {} s (`--dt`), \
                 short of the horizon of {horizon:.6e} s; a larger dt covers more",
                kick_core::short(dt)
            )
        } else {
            format!("rapier scene: contact outlasted the horizon of {horizon:.6e} s")
        };
        Err(kick_core::KickError::NoSeparation { time: t, reason }.into())
    }
}

/// Copy the rigid-body states into the law's state vector (ξ and the
/// integrals, stored from `SPRING` on, are left as they are).
fn pack(foot: &RigidBody, ball: &RigidBody, y: &mut State) {
    let put = |y: &mut State, i: usize, v: Vec3| {
        y[i] = v.x;
        y[i + 1] = v.y;
        y[i + 2] = v.z;
    };
    let put_q = |y: &mut State, i: usize, q: &parry3d_f64::math::Rot3| {
        y[i] = q.w;
        y[i + 1] = q.x;
        y[i + 2] = q.y;
        y[i + 3] = q.z;
    };
    put(y, dynamics::FOOT_POSITION, foot.translation());
    put_q(y, dynamics::FOOT_ROTATION, foot.rotation());
    put(y, dynamics::FOOT_VELOCITY, foot.linvel());
    put(y, dynamics::FOOT_ANGULAR_VELOCITY, foot.angvel());
    put(y, dynamics::BALL_POSITION, ball.translation());
    put_q(y, dynamics::BALL_ROTATION, ball.rotation());
    put(y, dynamics::BALL_VELOCITY, ball.linvel());
    put(y, dynamics::BALL_ANGULAR_VELOCITY, ball.angvel());
}

/// One row of a convergence study of the scene path against the accurate path.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ConvergenceRow {
    pub step: f64,
    /// |Δ launch velocity| / speed.
    pub velocity_error: f64,
    /// |Δ spin| / |spin| (absolute in rad/s when the accurate spin is zero).
    pub spin_error: f64,
    /// |Δ contact time| / contact time.
    pub contact_time_error: f64,
    /// Observed order log2(e(2h)/e(h)) of the velocity error against the previous row (steps halving).
    pub velocity_order: Option<f64>,
    /// Wall time of this scene run, s (one run; machine-dependent).
    pub seconds: f64,
}

/// Run the scene path at each step (give them halving) and compare with the
/// accurate path. Also returns the accurate path's wall time, s.
pub fn convergence(kick: &Kick3d, steps: &[f64]) -> Result<(Vec<ConvergenceRow>, f64), Kick3dError> {
    let started = std::time::Instant::now();
    let exact = crate::accurate::Accurate3d::default().solve(kick)?;
    let accurate_seconds = started.elapsed().as_secs_f64();
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let diff = |a: [f64; 3], b: [f64; 3]| norm([a[0] - b[0], a[1] - b[1], a[2] - b[2]]);
    let spin_scale = if norm(exact.spin) > 0.0 { norm(exact.spin) } else { 1.0 };
    let mut rows: Vec<ConvergenceRow> = Vec::with_capacity(steps.len());
    for &step in steps {
        let started = std::time::Instant::now();
        let o = Scene::new(step)?.solve(kick)?;
        let seconds = started.elapsed().as_secs_f64();
        let velocity_error = diff(o.launch_velocity, exact.launch_velocity) / exact.speed;
        let velocity_order = rows.last().map(|r| (r.velocity_error / velocity_error).log2() / (r.step / step).log2());
        rows.push(ConvergenceRow {
            step,
            velocity_error,
            spin_error: diff(o.spin, exact.spin) / spin_scale,
            contact_time_error: (o.contact_time - exact.contact_time).abs() / exact.contact_time,
            velocity_order,
            seconds,
        });
    }
    Ok((rows, accurate_seconds))
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_compliant::events::MAX_FIXED_STEPS;
    use kick_core::KickError;

    /// A step whose run would exceed the fixed-step budget (time ∝ 1/dt) is
    /// refused before the first step, naming dt (`--dt`) and the count:
    /// 1e-10 s over the baseline's horizon, and 1e-300 s, which used to end in
    /// "non-finite contact time at t = inf s". The count is the horizon over the step.
    #[test]
    fn a_step_beyond_the_budget_is_refused_up_front() {
        let kick = Kick3d::baseline();
        let horizon = kick.contact_horizon().unwrap();
        for dt in [1e-300, 1e-10, horizon / (2.0 * MAX_FIXED_STEPS)] {
            match Scene::new(dt).unwrap().solve(&kick) {
                Err(Kick3dError::Core(e @ KickError::TooManySteps { .. })) => {
                    let KickError::TooManySteps { step, steps, limit, .. } = e else { unreachable!() };
                    assert_eq!((step, steps, limit), (dt, (horizon / dt).ceil(), MAX_FIXED_STEPS));
                    assert!(e.to_string().contains("dt = ") && e.to_string().contains("`--dt`"), "{e}");
                }
                other => panic!("dt = {dt}: {other:?}"),
            }
        }
    }

    /// A contact that never separates (a 3e4 N drive holds the foot on the
    /// ball) stops after the scene's budget of steps, at t = budget x dt,
    /// as a numerical limit naming `--dt`, not after the whole horizon
    /// (5.4e5 steps here, 2e8 at the smallest dt the horizon's budget allows:
    /// 9 minutes at the measured 2.6 µs a step).
    /// A small budget stands in for [`MAX_SCENE_STEPS`]; the default runs the
    /// baseline and stays within about 5 s of measured steps.
    #[test]
    fn a_contact_outlasting_the_scene_budget_stops_there() {
        let mut driven = Kick3d::baseline();
        driven.base = driven.base.with(kick_core::Parameter::DriveForce, 3e4).unwrap();
        let scene = Scene { budget: 2_000, ..Scene::new(1e-5).unwrap() };
        match scene.solve(&driven) {
            Err(Kick3dError::Core(KickError::NoSeparation { time, reason })) => {
                assert!((time - 2_000.0 * 1e-5).abs() < 1e-12, "{time}");
                assert!(reason.contains("budget of 2000 steps") && reason.contains("`--dt`"), "{reason}");
            }
            other => panic!("{other:?}"),
        }
        assert!(MAX_SCENE_STEPS as f64 * 2.6e-6 < 10.0);
        let baseline = Scene::default().solve(&Kick3d::baseline()).unwrap();
        assert!(baseline.evaluations < MAX_SCENE_STEPS / 100, "{}", baseline.evaluations);
    }
}
