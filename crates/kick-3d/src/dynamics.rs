//! The two rigid bodies, the contact law and the ODE right-hand side.
//!
//! This module is the one boundary between parry's glam types (`Vec3`,
//! `Rot3`, `Pose3`) and the nalgebra state vector that ode_solvers integrates.
//!
//! Contact law (one law for every path):
//! - normal: F_n = F(δ, δ̇) of the kick's contact law ([`Kick3d::law`]: the
//!   paper's k δⁿ + c max(δ̇, 0), Eq. 20, or any law of `kick_core::laws`), δ
//!   the overlap from parry's ball–box query, δ̇ = n·(v_foot − v_ball) at the
//!   witness points (the exact rate of a convex distance);
//! - tangential: the spring k_t in series with a Coulomb slider capped by
//!   μ F_n of [`crate::tangential`] (no viscous term). The spring's stretch ξ
//!   is state; grip or slip is the phase's ([`Dynamics::slipping`]), switched
//!   by the runs where the phase's switch function changes sign. The slip's
//!   cap rate d(μ F_n)/dt is ∂F/∂δ δ̇ + ∂F/∂δ̇ δ̈, δ̈ from the accelerations
//!   the force gives, written in the foot's frame: r = qᵀ(c_b − c_f),
//!   r̈ = qᵀΔa − Ω × qᵀΔv − Ω̇ × r − Ω × ṙ, δ̈ = −n · r̈ − ṅ · ṙ with ṅ from
//!   the nearest point of the core box (its clamped coordinates stay put).
//!
//! Both bodies take the force at one point p = c_b − R n, the undeformed
//! ball's point nearest the foot: the lever of the friction about the ball
//! centre is R (Eq. 61) and action equals reaction at the same point, so the
//! pair's angular momentum is conserved exactly.

use crate::model::Kick3d;
use kick_core::{AnyLaw, ContactLaw};
use nalgebra::SVector;
use parry3d_f64::math::{Pose3, Rot3, Vec3};
use parry3d_f64::query::details::contact_convex_polyhedron_ball;
use parry3d_f64::shape::{Ball, Cuboid};

pub const DIM: usize = 41;
/// Foot (x, q, v, ω), ball (x, q, v, ω), tangential spring ξ, running
/// integrals, the boot's compression δ_b (zero without a boot).
pub type State = SVector<f64, DIM>;

pub const FOOT_POSITION: usize = 0;
pub const FOOT_ROTATION: usize = 3; // quaternion w, x, y, z
pub const FOOT_VELOCITY: usize = 7;
pub const FOOT_ANGULAR_VELOCITY: usize = 10;
pub const BALL_POSITION: usize = 13;
pub const BALL_ROTATION: usize = 16;
pub const BALL_VELOCITY: usize = 20;
pub const BALL_ANGULAR_VELOCITY: usize = 23;
pub const SPRING: usize = 26;
/// ∫ F dt on the ball.
pub const IMPULSE: usize = 29;
/// ∫ r × F dt about the ball centre.
pub const ANGULAR_IMPULSE: usize = 32;
pub const NORMAL_IMPULSE: usize = 35;
pub const DAMPING_LOSS: usize = 36;
pub const FRICTION_LOSS: usize = 37;
pub const DRIVE_WORK: usize = 38;
pub const GRAVITY_WORK: usize = 39;
/// δ_b, the boot's compression.
pub const BOOT: usize = 40;

#[inline]
pub fn vec3(y: &State, i: usize) -> Vec3 {
    Vec3::new(y[i], y[i + 1], y[i + 2])
}
#[inline]
fn put3(y: &mut State, i: usize, v: Vec3) {
    y[i] = v.x;
    y[i + 1] = v.y;
    y[i + 2] = v.z;
}
#[inline]
pub fn rot(y: &State, i: usize) -> Rot3 {
    Rot3::from_xyzw(y[i + 1], y[i + 2], y[i + 3], y[i]).normalize()
}
#[inline]
fn put_rot(y: &mut State, i: usize, q: Rot3) {
    y[i] = q.w;
    y[i + 1] = q.x;
    y[i + 2] = q.y;
    y[i + 3] = q.z;
}

/// Everything the law gives at one state.
#[derive(Debug, Clone, Copy)]
pub struct ContactEval {
    /// δ (negative: a gap).
    pub compression: f64,
    /// δ̇.
    pub compression_rate: f64,
    /// Unit normal, foot → ball.
    pub normal: Vec3,
    /// Application point p = c_b − R n.
    pub point: Vec3,
    /// p − c_b and p − c_f.
    pub lever_ball: Vec3,
    pub lever_foot: Vec3,
    /// Tangential part of v_ball(p) − v_foot(p).
    pub sliding_velocity: Vec3,
    pub normal_force: f64,
    /// Tangential force on the ball.
    pub tangential_force: Vec3,
    /// ξ̇ of the element (without the co-rotation with the foot).
    pub spring_rate: Vec3,
    /// The phase's switch function ([`crate::tangential::Response::margin`]):
    /// in grip μ F_n − k_t |ξ| (+1 when μ = ∞), in slip −k_t λ; 0 when μ = 0
    /// or no normal force caps the slider.
    pub grip_margin: f64,
    pub damping_power: f64,
    pub friction_power: f64,
    /// δ̇_b, the boot's compression rate (0 without a boot).
    pub boot_rate: f64,
    /// dF_n/dt (computed in slip only; 0 otherwise).
    pub normal_force_rate: f64,
    /// The contact points' relative tangential velocity (zero in grip).
    pub slip_velocity: Vec3,
    /// The phase: slip (true) or grip.
    pub slipping: bool,
}

impl ContactEval {
    pub fn force_on_ball(&self) -> Vec3 {
        self.normal * self.normal_force + self.tangential_force
    }
    /// The phase is slip.
    pub fn is_slipping(&self) -> bool {
        self.slipping
    }
}

/// The relative motion in the foot's body frame, for the normal's rates
/// (the tangential law's cap rate and the spring's transport).
struct FootFrame {
    rotation: Rot3,
    /// Ball centre from the foot's centre of mass, its rate, the relative
    /// velocity, the foot's angular velocity and the normal, body frame.
    r: Vec3,
    r_dot: Vec3,
    relative_velocity: Vec3,
    omega: Vec3,
    normal: Vec3,
    /// ṅ (body frame, relative to the foot).
    normal_rate: Vec3,
}

impl FootFrame {
    fn of(d: &Dynamics, y: &State, c_b: Vec3, c_f: Vec3, n: Vec3) -> FootFrame {
        let rotation = rot(y, FOOT_ROTATION);
        let back = rotation.inverse();
        let r = back * (c_b - c_f);
        let relative_velocity = back * (vec3(y, BALL_VELOCITY) - vec3(y, FOOT_VELOCITY));
        let omega = back * vec3(y, FOOT_ANGULAR_VELOCITY);
        let r_dot = relative_velocity - omega.cross(r);
        let normal = back * n;
        // n = (r − P)/|r − P|, P the core box's nearest point: its clamped
        // coordinates (where |r_i| > h_i) stay put, the others follow r.
        let h = d.cuboid.half_extents;
        let mut clamped = Vec3::ZERO;
        let mut nearest = r;
        for i in 0..3 {
            if r[i].abs() > h[i] {
                clamped[i] = r_dot[i];
                nearest[i] = h[i].copysign(r[i]);
            }
        }
        // (A ball centre inside the box is beyond the geometry, refused after the step.)
        let distance = (r - nearest).length();
        let normal_rate = if distance > 0.0 { (clamped - normal * normal.dot(r_dot)) / distance } else { Vec3::ZERO };
        FootFrame { rotation, r, r_dot, relative_velocity, omega, normal, normal_rate }
    }

    /// ṅ relative to the foot, in world components.
    fn normal_rate_world(&self) -> Vec3 {
        self.rotation * self.normal_rate
    }

    /// δ̈ when `force` (world) acts on the ball and `torque` (world, about its
    /// centre of mass) on the foot.
    fn compression_acceleration(&self, d: &Dynamics, force: Vec3, torque: Vec3) -> f64 {
        let back = self.rotation.inverse();
        // Δa = a_b − a_f (gravity acts on both alike).
        let omega = self.omega;
        let (relative_acceleration, omega_dot) = match &d.leg {
            // The leg's response to the wrench on the foot, as in `Dynamics::derivative`.
            Some(leg) => {
                let (turn, accel) = leg.response(torque, d.drive - force);
                (back * (force * (1.0 / d.ball_mass) - accel), back * turn)
            }
            None => (
                back * (force * (1.0 / d.ball_mass + 1.0 / d.foot_mass) - d.drive / d.foot_mass),
                ((back * torque) - omega.cross(omega * d.foot_inertia)) / d.foot_inertia,
            ),
        };
        let r_ddot = relative_acceleration - omega.cross(self.relative_velocity) - omega_dot.cross(self.r) - omega.cross(self.r_dot);
        -self.normal.dot(r_ddot) - self.normal_rate.dot(self.r_dot)
    }
}

/// Right-hand side of one kick.
#[derive(Debug, Clone, Copy)]
pub struct Dynamics {
    pub law: AnyLaw,
    pub foot_mass: f64,
    pub foot_inertia: Vec3,
    pub ball_mass: f64,
    pub ball_inertia: f64,
    pub ball_radius: f64,
    /// Inner box of the instep; the border radius is added to the ball's
    /// radius in the query (ball ⊕ border against box = ball against rounded box).
    pub cuboid: Cuboid,
    pub border: f64,
    pub friction: f64,
    pub tangential_stiffness: f64,
    pub drive: Vec3,
    pub gravity: Vec3,
    /// The leg behind the foot (its mobility about the foot's centre, world
    /// frame) in place of the box's mass and inertia.
    pub leg: Option<crate::model::LegDynamics>,
    /// The boot in series.
    pub boot: Option<kick_core::Boot>,
    /// The tangential element's phase: slip (true) or grip (μ = 0 and μ = ∞
    /// keep it false: no slider, or one that never moves).
    pub slipping: bool,
}

/// Where a slip ends in grip near separation the cap μ F_n is resolved only
/// to parry's rounding of the overlap, ε L/δ of it (L the bodies' distance
/// from the origin, δ the compression): Hunt and Crossley's box kick 1294
/// (seed 2024) entered grip 41 ns before separation at δ = 0.41 µm, where
/// that share (6.7e-11) exceeds `GRIP_ENTRY` (1e-12), and its margin read
/// negative at the grip's first instant: the grip ended where it began, 33 ns
/// of it counted as slip (5.5e-6 of the contact). The reference puts its
/// spring this many times that share inside the cap when that is larger than
/// `GRIP_ENTRY`, at most 1e-3 of it: the stretch shorter by that share where
/// the force it carries is itself that small (1.8e-4 N there).
pub const ENTRY_RESOLUTION: f64 = 100.0;

/// L, the bodies' distance from the origin at y: parry's overlap is resolved
/// to ~ε L ([`ENTRY_RESOLUTION`], the full state's `ONSET_RESOLUTION`).
pub fn position_scale(y: &State) -> f64 {
    vec3(y, BALL_POSITION).length().max(vec3(y, FOOT_POSITION).length())
}

impl Dynamics {
    pub fn new(kick: &Kick3d) -> Dynamics {
        let [hx, hy, hz] = kick.foot_shape.core_half_extents();
        let [ix, iy, iz] = kick.foot_inertia;
        Dynamics {
            law: kick.law(),
            foot_mass: kick.base.effective_foot_mass(),
            foot_inertia: Vec3::new(ix, iy, iz),
            ball_mass: kick.base.ball_mass(),
            ball_inertia: kick.ball_inertia,
            ball_radius: kick.ball_radius,
            cuboid: Cuboid::new(Vec3::new(hx, hy, hz)),
            border: kick.foot_shape.border_radius(),
            friction: kick.friction,
            tangential_stiffness: kick.tangential_stiffness,
            drive: kick.drive(),
            gravity: kick.gravity_vector(),
            leg: kick.leg,
            boot: kick.base.boot(),
            slipping: false,
        }
    }

    /// This kick's right-hand side in the phase the element takes at first
    /// touch (`y` the state there): grip unless the cap starts at zero and
    /// grows slower than the spring would load ([`crate::tangential`]).
    pub fn at_touch(self, y: &State) -> Dynamics {
        if self.friction == 0.0 || self.friction.is_infinite() {
            return self;
        }
        let c = Dynamics { slipping: true, ..self }.contact(y);
        // Onset is t = 0, δ = 0 by construction: the cap there is the law's
        // F(0, δ̇), not the force of the geometry's rounding (1.2e-17 N on
        // box kick 31 of Hunt and Crossley's law, which started the element
        // in grip where F grows as t^1.35 and it slips for 0.39 ns).
        let approach = c.compression_rate + c.boot_rate;
        let onset_force = match &self.boot {
            None => self.law.contact_force(0.0, c.compression_rate),
            Some(boot) => boot.split(&self.law, 0.0, approach, 0.0, true, false).force.max(0.0),
        };
        // Its rate likewise: the law's slope at δ = 0 along the approach. Where
        // F(0) = 0, the only case the rate decides, the law's D(0) = 0 (F = E + D δ̇),
        // so δ̈ does not enter and a boot's layer has not started to move:
        // Ḟ = F_δ δ̇. The geometry's rounding put δ a hair below zero on row
        // 2894 of the flown sweep (the shell ball), where the clamped law gave
        // Ḟ = 0 and the element slipped from touch instead of gripping for 45 µs.
        let cap_rate = self.friction * self.law.force_gradient(0.0, approach).0 * approach;
        let slips = crate::tangential::slips_at_touch(self.tangential_stiffness, c.sliding_velocity, self.friction * onset_force, cap_rate);
        Dynamics { slipping: slips, ..self }
    }

    /// `y` with the spring put on the cap where a slip ends in grip: along its
    /// own direction in the tangent plane, k_t |ξ| = μ F_n (1 − s), s the
    /// larger of `GRIP_ENTRY` and what parry's overlap resolves
    /// ([`ENTRY_RESOLUTION`]).
    pub fn spring_on_cap(&self, y: &State) -> State {
        let c = self.contact(y);
        let xi = vec3(y, SPRING);
        let xi_t = xi - c.normal * c.normal.dot(xi);
        let share = crate::tangential::GRIP_ENTRY.max(ENTRY_RESOLUTION * f64::EPSILON * position_scale(y) / c.compression.abs()).min(1e-3);
        let size = self.friction * c.normal_force / self.tangential_stiffness * (1.0 - share);
        let mut out = *y;
        put3(&mut out, SPRING, xi_t.normalize_or_zero() * size);
        out
    }

    /// The same right-hand side in the other phase (a grip/slip switch).
    pub fn switched(self) -> Dynamics {
        Dynamics { slipping: !self.slipping, ..self }
    }

    pub fn foot_pose(y: &State) -> Pose3 {
        Pose3::from_parts(vec3(y, FOOT_POSITION), rot(y, FOOT_ROTATION))
    }

    /// Overlap, normal and witness point from parry (ball of radius R + border
    /// against the inner box, which is exact for the rounded box).
    /// Returns (δ, n foot → ball, point on the foot's surface).
    pub fn geometry(&self, foot: &Pose3, ball_centre: Vec3) -> (f64, Vec3, Vec3) {
        geometry(&self.cuboid, self.ball_radius, self.border, foot, ball_centre)
    }

    /// The contact law at state y (on the contact branch: F(0⁺) = c δ̇ for
    /// the paper's law, 0 for the hysteresis laws).
    #[inline]
    pub fn contact(&self, y: &State) -> ContactEval {
        let foot = Self::foot_pose(y);
        let c_f = foot.translation;
        let c_b = vec3(y, BALL_POSITION);
        let (delta, n, _surface) = self.geometry(&foot, c_b);
        let v_f = vec3(y, FOOT_VELOCITY);
        let w_f = vec3(y, FOOT_ANGULAR_VELOCITY);
        let v_b = vec3(y, BALL_VELOCITY);
        let w_b = vec3(y, BALL_ANGULAR_VELOCITY);
        let lever_ball = -n * self.ball_radius;
        let point = c_b + lever_ball;
        let lever_foot = point - c_f;
        let v_rel = (v_b + w_b.cross(lever_ball)) - (v_f + w_f.cross(lever_foot));
        // The foot's witness point lies δ n beyond p along the normal, so the
        // normal component of v_rel is the exact −δ̇ of the parry distance.
        let rate = -n.dot(v_rel);
        let sliding = v_rel + n * rate;
        let (delta, rate, normal_force, damping_power, boot_rate) = match &self.boot {
            None => {
                let normal_force = self.law.contact_force(delta, rate); // Eq. 20 for the paper's law
                let elastic = self.law.contact_force(delta, 0.0);
                // d/dt of kinetic + U(δ) is −(F − F(δ, 0)) δ̇: Eq. 25 for the paper's law.
                (delta, rate, normal_force, (normal_force - elastic) * rate, 0.0)
            }
            // The overlap splits between the boot and the ball (kick-core's
            // `boot`); the ball's rate has one sign on both damping branches,
            // so the branch is the one it gives, and a law that would pull is
            // held at zero.
            Some(boot) => {
                let (ball, layer) = (delta - y[BOOT], y[BOOT]);
                let mut split = boot.split(&self.law, ball, rate, layer, true, false);
                if split.ball_rate < 0.0 {
                    split = boot.split(&self.law, ball, rate, layer, false, false);
                }
                if split.force < 0.0 {
                    split = boot.split(&self.law, ball, rate, layer, split.ball_rate > 0.0, true);
                }
                (ball, split.ball_rate, split.force, split.loss_power(boot), split.boot_rate)
            }
        };

        let xi = vec3(y, SPRING);
        let xi_t = xi - n * xi.dot(n);
        let k_t = self.tangential_stiffness;
        let cap = if self.friction.is_infinite() { f64::INFINITY } else { self.friction * normal_force };
        let foot_frame = FootFrame::of(self, y, c_b, c_f, n);
        let mut normal_force_rate = 0.0;
        let element = if self.friction == 0.0 {
            crate::tangential::free(sliding)
        } else if normal_force == 0.0 && delta != 0.0 {
            // A law clamped at zero force (or no contact): no slider to cap,
            // nothing acts tangentially, and the phase holds (its margin keeps its sign).
            crate::tangential::Response { margin: if self.slipping { -1.0 } else { 1.0 }, ..crate::tangential::free(sliding) }
        } else if !self.slipping {
            crate::tangential::grip(k_t, xi_t, sliding, cap)
        } else {
            let s = crate::tangential::slip_direction(xi_t, sliding);
            let friction = s * -cap;
            // dF/dt = ∂F/∂δ δ̇ + ∂F/∂δ̇ δ̈ (the law's gradient: zero where it is
            // clamped), through the boot's balance when there is one (δ̈ the approach's).
            let (d_delta, d_rate) = self.law.force_gradient(delta, rate);
            let (force_rate, per_acceleration) = match &self.boot {
                None => (d_delta * rate, d_rate),
                Some(boot) => boot.force_rate_parts(d_delta, d_rate, rate, boot_rate),
            };
            let force = n * normal_force + friction;
            normal_force_rate = force_rate + per_acceleration * foot_frame.compression_acceleration(self, force, lever_foot.cross(-force));
            crate::tangential::slip(k_t, s, sliding, cap, self.friction * normal_force_rate)
        };
        // The spring is carried along the turning tangent plane: ξ̇ gains −n (ṅ · ξ)
        // (ṅ relative to the foot; the co-rotation with the foot is in `derivative`).
        let spring_rate =
            if element.spring_rate == Vec3::ZERO { Vec3::ZERO } else { element.spring_rate - n * foot_frame.normal_rate_world().dot(xi) };
        let (tangential_force, grip_margin, friction_power) = (element.force, element.margin, element.power);
        ContactEval {
            compression: delta,
            compression_rate: rate,
            normal: n,
            point,
            lever_ball,
            lever_foot,
            sliding_velocity: sliding,
            normal_force,
            tangential_force,
            spring_rate,
            grip_margin,
            damping_power,
            friction_power,
            boot_rate,
            slip_velocity: element.slip_velocity,
            slipping: self.slipping,
            normal_force_rate,
        }
    }

    /// ẏ at y.
    #[inline]
    pub fn derivative(&self, y: &State) -> State {
        let c = self.contact(y);
        let force = c.force_on_ball();
        let mut dy = State::zeros();
        let q_f = rot(y, FOOT_ROTATION);
        let q_b = rot(y, BALL_ROTATION);
        let v_f = vec3(y, FOOT_VELOCITY);
        let w_f = vec3(y, FOOT_ANGULAR_VELOCITY);
        let v_b = vec3(y, BALL_VELOCITY);
        let w_b = vec3(y, BALL_ANGULAR_VELOCITY);

        put3(&mut dy, FOOT_POSITION, v_f);
        put_rot(&mut dy, FOOT_ROTATION, Rot3::from_xyzw(w_f.x, w_f.y, w_f.z, 0.0) * q_f * 0.5);
        let torque_foot = c.lever_foot.cross(-force);
        if let Some(leg) = &self.leg {
            // The leg's mobility about the foot's centre, frozen in the world frame.
            let (turn, accel) = leg.response(torque_foot, self.drive - force);
            put3(&mut dy, FOOT_VELOCITY, accel + self.gravity);
            put3(&mut dy, FOOT_ANGULAR_VELOCITY, turn);
        } else {
            put3(&mut dy, FOOT_VELOCITY, (self.drive - force) / self.foot_mass + self.gravity);
            // Euler's equations in the foot's principal axes.
            let w_body = q_f.inverse() * w_f;
            let l_body = w_body * self.foot_inertia;
            let dw_body = ((q_f.inverse() * torque_foot) - w_body.cross(l_body)) / self.foot_inertia;
            put3(&mut dy, FOOT_ANGULAR_VELOCITY, q_f * dw_body);
        }

        put3(&mut dy, BALL_POSITION, v_b);
        put_rot(&mut dy, BALL_ROTATION, Rot3::from_xyzw(w_b.x, w_b.y, w_b.z, 0.0) * q_b * 0.5);
        put3(&mut dy, BALL_VELOCITY, force / self.ball_mass + self.gravity);
        let torque_ball = c.lever_ball.cross(force);
        put3(&mut dy, BALL_ANGULAR_VELOCITY, torque_ball / self.ball_inertia); // sphere: I isotropic

        // The spring is glued to the foot's face: it turns with the foot.
        let xi = vec3(y, SPRING);
        put3(&mut dy, SPRING, w_f.cross(xi) + c.spring_rate);
        put3(&mut dy, IMPULSE, force);
        put3(&mut dy, ANGULAR_IMPULSE, torque_ball);
        dy[NORMAL_IMPULSE] = c.normal_force;
        dy[DAMPING_LOSS] = c.damping_power;
        dy[FRICTION_LOSS] = c.friction_power;
        dy[DRIVE_WORK] = self.drive.dot(v_f);
        dy[GRAVITY_WORK] = self.gravity.dot(v_f * self.foot_mass + v_b * self.ball_mass);
        dy[BOOT] = c.boot_rate;
        dy
    }

    /// One classical RK4 step (used only below Dop853's step-size floor).
    pub fn rk4_step(&self, y: &State, h: f64) -> State {
        kick_compliant::events::rk4_step(|y| self.derivative(y), y, h)
    }

    pub fn ball_translation_energy(&self, y: &State) -> f64 {
        0.5 * self.ball_mass * vec3(y, BALL_VELOCITY).length_squared()
    }
    pub fn ball_spin_energy(&self, y: &State) -> f64 {
        0.5 * self.ball_inertia * vec3(y, BALL_ANGULAR_VELOCITY).length_squared()
    }
    /// The foot's kinetic energy at y, time t (with the leg, `LegDynamics::foot_energy`).
    pub fn foot_energy(&self, y: &State, t: f64) -> f64 {
        if let Some(leg) = &self.leg {
            let impulse = self.drive * t - vec3(y, IMPULSE);
            return leg.foot_energy(self.foot_mass, impulse, vec3(y, FOOT_ANGULAR_VELOCITY), vec3(y, FOOT_VELOCITY));
        }
        let q = rot(y, FOOT_ROTATION);
        let w_body = q.inverse() * vec3(y, FOOT_ANGULAR_VELOCITY);
        0.5 * self.foot_mass * vec3(y, FOOT_VELOCITY).length_squared() + 0.5 * w_body.dot(w_body * self.foot_inertia)
    }
    /// U(δ) + ½ k_t |ξ|² (+ ½ k_b δ_b² with a boot).
    pub fn elastic_energy(&self, y: &State, compression: f64) -> f64 {
        self.law.potential(compression)
            + 0.5 * self.tangential_stiffness * vec3(y, SPRING).length_squared()
            + self.boot.map_or(0.0, |b| b.potential(y[BOOT]))
    }
    /// The world-frame end state of a run that stopped at state y, time t.
    pub fn end_state(&self, kick: &Kick3d, y: &State, t: f64) -> crate::outcome::EndState {
        let _ = kick;
        crate::outcome::EndState {
            time: t,
            foot_position: vec3(y, FOOT_POSITION),
            foot_orientation: rot(y, FOOT_ROTATION),
            foot_velocity: vec3(y, FOOT_VELOCITY),
            foot_angular_velocity: vec3(y, FOOT_ANGULAR_VELOCITY),
            ball_position: vec3(y, BALL_POSITION),
            ball_velocity: vec3(y, BALL_VELOCITY),
            ball_angular_velocity: vec3(y, BALL_ANGULAR_VELOCITY),
            spring: vec3(y, SPRING),
            compression: self.contact(y).compression,
            boot_compression: y[BOOT],
            impulse: vec3(y, IMPULSE),
            angular_impulse: vec3(y, ANGULAR_IMPULSE),
            normal_impulse: y[NORMAL_IMPULSE],
            normal_damping_loss: y[DAMPING_LOSS],
            friction_loss: y[FRICTION_LOSS],
            drive_work: y[DRIVE_WORK],
            gravity_work: y[GRAVITY_WORK],
        }
    }

    /// Kinetic plus elastic energy (what a passive contact can only lose).
    pub fn mechanical_energy(&self, y: &State, t: f64) -> f64 {
        let c = self.contact(y);
        self.ball_translation_energy(y) + self.ball_spin_energy(y) + self.foot_energy(y, t) + self.elastic_energy(y, c.compression)
    }
}

/// Ball of radius `radius` against `cuboid` ⊕ a sphere of radius `border`
/// at pose `foot`, by parry: (δ, unit normal foot → ball, point on the
/// foot's surface); NaN only on non-finite input (caught before output).
pub fn geometry(cuboid: &Cuboid, radius: f64, border: f64, foot: &Pose3, ball_centre: Vec3) -> (f64, Vec3, Vec3) {
    let pos12 = foot.inv_mul(&Pose3::from_translation(ball_centre));
    let ball = Ball::new(radius + border);
    match contact_convex_polyhedron_ball(&pos12, cuboid, &ball, f64::INFINITY) {
        Some(c) => {
            let n = foot.rotation * c.normal1;
            let surface = foot.transform_point(c.point1) + n * border;
            (-c.dist, n, surface)
        }
        None => (f64::NAN, Vec3::NAN, Vec3::NAN),
    }
}

/// The state at first touch.
pub fn initial_state(kick: &Kick3d) -> State {
    let s = kick.initial_state();
    let mut y = State::zeros();
    put3(&mut y, FOOT_POSITION, s.foot_position);
    put_rot(&mut y, FOOT_ROTATION, s.foot_orientation);
    put3(&mut y, FOOT_VELOCITY, s.foot_velocity);
    put3(&mut y, BALL_POSITION, s.ball_position);
    put_rot(&mut y, BALL_ROTATION, Rot3::IDENTITY);
    put3(&mut y, BALL_VELOCITY, s.ball_velocity);
    y
}
