//! The contact in the foot's frame: the accurate path's state and
//! right-hand side.
//!
//! The pair's centre of mass moves under the drive and gravity alone, so it
//! is known in closed form; what the contact changes is the relative
//! motion. Everything is written in the foot's body frame, where the
//! instep's face is fixed: its normal is e_x and the compression on the face
//! is δ = −s_x, s the ball centre's displacement from where it touched
//! (no cancellation of two positions), and the tangential spring, glued to
//! the face, needs no co-rotation term.
//!
//! State (23, then 7 slots used by a leg or a boot, zero otherwise): s, the
//! relative velocity w = v_b − v_f, the foot's angular
//! velocity Ω and orientation q (world from body), the ball's angular
//! velocity, the spring ξ (all but q in body components), the normal
//! impulse, the two losses, the time (see [`Clock`]), the boot's
//! compression δ_b, and with the leg the foot's velocity and displacement
//! in the world frame. With r = r0 + s the ball centre from the
//! foot's centre of mass (r0 = (R + h_x, 0, 0)), p = r − R n the contact
//! point and F = F_n n + F_t the force on the ball:
//!
//! - ṡ = w − Ω × r,
//! - ẇ = F (1/m_b + 1/m_f) − qᵀ F_drive/m_f − Ω × w (gravity acts on both alike),
//! - I Ω̇ = p × (−F) − Ω × I Ω (Euler's equations),
//! - q̇ = ½ q ⊗ Ω,
//! - ω̇_b = (−R n) × F / I_b − Ω × ω_b,
//! - ξ̇ = the tangential element's rate (the law: [`crate::tangential`]).
//!
//! With the leg ([`crate::model::LegDynamics`]) the foot's two rates are the
//! leg's response to the wrench on it, [Ω̇; a_o] = qᵀ Ω_w [q (p × (−F));
//! q (−F) + F_drive], with no Euler term, and ẇ = F/m_b − a_o − Ω × w. A boot
//! in series ([`kick_core::Boot`]) takes the overlap δ as δ_b + δ_B: the
//! ball's law sees δ_B and its rate, δ̇_b follows from the force balance
//! (kick-core's `boot`), and the events, the clocks and the reported
//! compression are the ball's; under a patch the foot's surface moves
//! back by δ_b along the contact normal.
//!
//! The right-hand side is the same law as [`crate::dynamics::Dynamics`]
//! (which writes both bodies in the world frame), with each switch made
//! explicit in a [`Phase`]: the damping branch of the normal law, grip or
//! slip, and the geometry (analytic on the face; parry where edges and
//! rounded borders come in). Within a phase the right-hand side is smooth,
//! continued past its own switches, so a step that crosses one stays
//! accurate and its dense output locates the switch.
//!
//! First touch and separation: δⁿ is not smooth at δ = 0 (n not an integer),
//! so the solution has a t^(n+2) term at both ends that would hold a
//! high-order method to tiny steps there. Near both ends the independent
//! variable is u = δ^(1/p) instead of t ([`Clock`]): the force's δⁿ becomes
//! u^(pn), smooth enough for the 8th-order steps, and t is integrated as a
//! state (dt/du = p u^(p−1)/δ̇, δ̇ kept away from zero). Separation is then
//! the known end u = 0, not an event. The shell law, smooth at touch
//! (F ∝ δ), takes u only towards separation, where its force stops with a
//! kink at δ = 0 that a step across it would straddle.

use crate::dynamics::geometry;
use crate::model::Kick3d;
use crate::outcome::EndState;
use crate::patch::{Patch, PatchForce, Surface};
use crate::tangential as friction_law;
use kick_core::{AnyLaw, ContactLaw};
use nalgebra::SVector;
use parry3d_f64::math::{Pose3, Rot3, Vec3};
use parry3d_f64::shape::Cuboid;

pub const DIM: usize = 30;
pub type State = SVector<f64, DIM>;
/// The components of a kick without a leg or a boot: the rest stay zero,
/// and the error norm averages over these alone, so such a kick is the same
/// bit for bit as before the slots were added ([`Relative::counted_components`]).
pub const PLAIN_DIM: usize = 23;

/// s: the ball centre's displacement from first touch (body frame).
pub const DISPLACEMENT: usize = 0;
/// w = v_b − v_f (body components).
pub const RELATIVE_VELOCITY: usize = 3;
/// Ω (body components).
pub const FOOT_ANGULAR_VELOCITY: usize = 6;
/// q, world from body: w, x, y, z.
pub const FOOT_ROTATION: usize = 9;
/// ω_b (body components).
pub const BALL_ANGULAR_VELOCITY: usize = 13;
/// ξ (body components) while gripping; while slipping (where the spring's
/// length is μ F_n / k_t, a function of the state) only its direction, at
/// the length δ ([`Relative::spring`] gives the stretch in every phase).
/// Integrated, the length μ F_n / k_t would carry F_n's δⁿ roughness at
/// separation into the state and cost the power law's kicks half again
/// their evaluations (821 against 546 at 5 cm, μ = 0.5); at a fixed length
/// the direction would be held to the tolerance where friction vanishes
/// (1498 against 1010 at α = 10°); δ is smooth in the clock and vanishes with the force.
pub const SPRING: usize = 16;
/// ∫ F_n dt.
pub const NORMAL_IMPULSE: usize = 19;
/// ∫ (F_n − F_n(δ, 0)) δ̇ dt.
pub const DAMPING_LOSS: usize = 20;
/// ∫ tangential element power dt.
pub const FRICTION_LOSS: usize = 21;
/// t (integrated while the independent variable is not the time).
pub const TIME: usize = 22;
/// δ_b, the boot's compression (a boot in series, `kick_core::Boot`).
pub const BOOT: usize = 23;
/// The foot's reference point's velocity, world frame (the leg only: the
/// pair's centre of mass no longer moves freely, the hip holds the leg).
pub const FOOT_VELOCITY_WORLD: usize = 24;
/// The foot's reference point's displacement since first touch, world frame (the leg only).
pub const FOOT_DISPLACEMENT_WORLD: usize = 27;

/// The power p of u = δ^(1/p). δⁿ = u^(pn) is still not smooth at u = 0,
/// but far less steep: p = 2 took the fewest evaluations over the box
/// (p = 2, 3, 4, 6 tried; 496, 549, 592, 720 evaluations per kick).
pub const CLOCK_POWER: i32 = 2;

#[inline]
fn vec3(y: &State, i: usize) -> Vec3 {
    Vec3::new(y[i], y[i + 1], y[i + 2])
}
#[inline]
fn put3(y: &mut State, i: usize, v: Vec3) {
    y[i] = v.x;
    y[i + 1] = v.y;
    y[i + 2] = v.z;
}
#[inline]
pub(crate) fn rotation(y: &State) -> Rot3 {
    Rot3::from_xyzw(y[FOOT_ROTATION + 1], y[FOOT_ROTATION + 2], y[FOOT_ROTATION + 3], y[FOOT_ROTATION]).normalize()
}

/// The tangential element's state of a phase, named by what the contact
/// points do: the ball's surface where it touches the foot, and the foot.
/// The element ([`crate::tangential`]) is a spring k_t (the shell's
/// tangential compliance) in series with a Coulomb slider capped at μ F_n.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Friction {
    /// μ = 0: no slider; nothing acts tangentially and the spring stays relaxed.
    None,
    /// The contact points move together: the slider holds and the spring
    /// carries −k_t ξ, ξ̇ = v_t (always, for μ = ∞). With rigid grip
    /// (k_t = ∞): the force that keeps the contact point (the patch's
    /// centroid, with the patch) from sliding.
    Grip,
    /// The contact points slide: the slider carries μ F_n against the
    /// spring's stretch, which stays at μ F_n / k_t. With rigid grip:
    /// μ F_n against [`Phase::slip_direction`].
    Slip,
}

/// Where the ball touches the instep.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// The flat face: n = e_x, δ = −s_x.
    Face,
    /// An edge, corner or rounded border (parry's ball–box query).
    Border,
    /// The cap of a curved instep ([`crate::patch`]): a sphere, smooth everywhere.
    Curved,
}

/// The independent variable x of a phase.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clock {
    /// x = t.
    Time,
    /// From first touch: x = u = δ^(1/p), δ = x^p.
    Onset,
    /// Towards separation: x = u_start − u, δ = (u_start − x)^p; separation at x = u_start.
    Release { start: f64 },
}

/// The branch of every switch the right-hand side holds through a phase,
/// and its independent variable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phase {
    /// The normal law's side of δ̇ = 0.
    pub compressing: bool,
    pub friction: Friction,
    pub geometry: Geometry,
    /// The normal force held at zero where the law would pull (see `ContactLaw::unclamped_force`).
    pub clamped: bool,
    pub clock: Clock,
    /// Rigid grip only: the sliding direction (body frame, tangential) of a
    /// slip phase, fixed through it (exact while the kick stays in one plane).
    pub slip_direction: Vec3,
    /// Rigid grip only: where a slip that began from grip ends, the sliding
    /// along `slip_direction` (≤ 0). Such a slip starts from the grip's
    /// residual sliding (at the tolerance) and grows quadratically from a
    /// tangency, so measured from zero its end would be found in the residual's
    /// rounding, and grip and slip would alternate there: the slip ends where
    /// the sliding falls back below the residual less ten times the speed
    /// tolerance (a shift of the reversal's time far below the tolerance's).
    pub slip_start: f64,
}

/// The law at one state, body frame.
#[derive(Debug, Clone, Copy)]
pub struct Local {
    pub compression: f64,
    pub compression_rate: f64,
    pub normal: Vec3,
    /// Contact point from the foot's centre of mass.
    pub point: Vec3,
    pub sliding_velocity: Vec3,
    pub normal_force: f64,
    /// The law's force before its clamp at zero (the normal force for a law that never pulls).
    pub unclamped_force: f64,
    pub tangential_force: Vec3,
    pub spring_rate: Vec3,
    /// The phase's grip/slip switch function ([`crate::tangential`]): in
    /// grip μ F_n − k_t |ξ| (+1 when μ = ∞), in slip −k_t λ (λ the slider's
    /// speed along the spring), 0 when μ = 0 or while the normal force is clamped.
    pub grip_margin: f64,
    pub damping_power: f64,
    pub friction_power: f64,
    /// The contact points' relative velocity (ball's surface less foot's),
    /// tangential: zero while gripping, the slider's velocity while
    /// slipping; with rigid grip and with μ = 0 the sliding velocity itself.
    pub slip_velocity: Vec3,
    /// The normal force over the patch, when it is spread ([`crate::patch`]).
    pub patch: Option<PatchForce>,
    /// δ̇_b, the boot's compression rate (0 without a boot).
    pub boot_rate: f64,
    /// The bodies' rates a slip phase computed for δ̈ (the slider's cap
    /// rate), and the loads they were computed under: the right-hand side
    /// takes them when its own loads are these, bit for bit, instead of
    /// computing them again (with the leg, a 6×6 product and four turns).
    pub(crate) body_rates: Option<BodyRates>,
}

/// ẇ, Ω̇ and the foot's world acceleration under `force` and `torque`
/// ([`Relative::body_rates`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct BodyRates {
    force: Vec3,
    torque: Vec3,
    rates: (Vec3, Vec3, Vec3),
}

impl BodyRates {
    /// The rates, if they were computed under exactly these loads.
    #[inline(always)]
    fn under(&self, force: Vec3, torque: Vec3) -> Option<(Vec3, Vec3, Vec3)> {
        let same = |a: Vec3, b: Vec3| a.x.to_bits() == b.x.to_bits() && a.y.to_bits() == b.y.to_bits() && a.z.to_bits() == b.z.to_bits();
        (same(self.force, force) && same(self.torque, torque)).then_some(self.rates)
    }
}

impl Local {
    /// |F_t| on the branch: exactly μ F_n while slipping.
    pub fn tangential_force_size(&self) -> f64 {
        self.tangential_force.length()
    }
}

/// The normal force's rate, dF_n/dt = `rate` + `per_acceleration` δ̈ (what
/// the slider's cap needs; zero outside a slip phase).
#[derive(Debug, Clone, Copy, Default)]
struct NormalRate {
    rate: f64,
    per_acceleration: f64,
}

/// The relative motion of one kick in one phase.
#[derive(Debug, Clone, Copy)]
pub struct Relative {
    pub law: AnyLaw,
    pub foot_mass: f64,
    pub ball_mass: f64,
    /// 1/m_b + 1/m_f.
    inverse_reduced_mass: f64,
    pub foot_inertia: Vec3,
    /// 1/I_f (products instead of quotients in the grip's off-face paths).
    inverse_foot_inertia: Vec3,
    pub ball_inertia: f64,
    /// 1/I_b.
    inverse_ball_inertia: f64,
    pub ball_radius: f64,
    /// r0 = (R + h_x outer, 0, 0): the ball centre at first touch.
    pub touch: Vec3,
    /// The face's extent in y and z (inner box): beyond it, the border.
    pub face: (f64, f64),
    pub cuboid: Cuboid,
    pub border: f64,
    pub friction: f64,
    pub tangential_stiffness: f64,
    /// True for a law that can pull (damps while restituting): its clamp is a switch.
    pub clamps: bool,
    /// k_t = ∞: grip is a constraint on the contact point's sliding velocity,
    /// not a stiff spring ([`Relative::grip_force`]).
    pub rigid: bool,
    /// F_drive in the world frame.
    pub drive: Vec3,
    /// F_drive/m_f.
    foot_drive: Vec3,
    pub phase: Phase,
    /// The curved instep's sphere (centre, radius), body frame.
    pub cap: Option<(Vec3, f64)>,
    /// The patch's quadrature, when the normal force is spread.
    pub patch: Option<Patch>,
    /// The leg behind the foot, in place of the box's mass and inertia.
    pub leg: Option<crate::model::LegDynamics>,
    /// The boot in series.
    pub boot: Option<kick_core::Boot>,
    /// Evaluate with the right-hand side's AVX2 copy ([`avx2`]; set by [`Relative::on_avx2`]).
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    avx2: bool,
}

impl Relative {
    pub fn new(kick: &Kick3d, phase: Phase) -> Relative {
        let [hx, hy, hz] = kick.foot_shape.core_half_extents();
        let [ix, iy, iz] = kick.foot_inertia;
        let (m_f, m_b) = (kick.base.effective_foot_mass(), kick.base.ball_mass());
        Relative {
            law: kick.law(),
            foot_mass: m_f,
            ball_mass: m_b,
            inverse_reduced_mass: 1.0 / m_b + 1.0 / m_f,
            foot_inertia: Vec3::new(ix, iy, iz),
            inverse_foot_inertia: Vec3::new(1.0 / ix, 1.0 / iy, 1.0 / iz),
            ball_inertia: kick.ball_inertia,
            inverse_ball_inertia: 1.0 / kick.ball_inertia,
            ball_radius: kick.ball_radius,
            touch: kick.touch(),
            face: (hy, hz),
            cuboid: Cuboid::new(Vec3::new(hx, hy, hz)),
            border: kick.foot_shape.border_radius(),
            friction: kick.friction,
            tangential_stiffness: kick.tangential_stiffness,
            clamps: !kick.law().damps_compression_only(),
            rigid: kick.rigid_grip(),
            drive: kick.drive(),
            foot_drive: kick.drive() / m_f,
            phase,
            cap: kick.instep.filter(|i| i.is_curved()).map(|i| (Vec3::new(kick.face_distance() - i.radius, 0.0, 0.0), i.radius)),
            patch: kick.instep.and_then(|i| i.patch).map(Patch::new),
            leg: kick.leg,
            boot: kick.base.boot(),
            avx2: false,
        }
    }

    /// The error norm's count: [`PLAIN_DIM`] without a leg or a boot, all otherwise.
    #[inline]
    pub fn counted_components(&self) -> usize {
        if self.leg.is_none() && self.boot.is_none() {
            PLAIN_DIM
        } else {
            DIM
        }
    }

    /// This system evaluated by the right-hand side's AVX2 copy where `avx2`
    /// is asked for and the CPU has it ([`avx2`]), else by the baseline copy.
    pub(crate) fn on_avx2(self, avx2: bool) -> Relative {
        Relative { avx2: avx2 && self::avx2(), ..self }
    }

    pub fn in_phase(&self, phase: Phase) -> Relative {
        Relative { phase, ..*self }
    }

    /// The ball centre from the foot's centre of mass, body frame.
    #[inline]
    pub fn centre(&self, y: &State) -> Vec3 {
        self.touch + vec3(y, DISPLACEMENT)
    }

    /// > 0 while the ball centre is over the flat face (the face's region).
    #[inline]
    pub fn face_margin(&self, y: &State) -> f64 {
        let r = self.centre(y);
        (self.face.0 - r.y.abs()).min(self.face.1 - r.z.abs())
    }

    /// δ at (x, y): from x near the ends (see [`Clock`]), else from the geometry.
    #[inline]
    fn clock_compression(&self, x: f64) -> Option<f64> {
        match self.phase.clock {
            Clock::Time => None,
            Clock::Onset => Some(x.max(0.0).powi(CLOCK_POWER)),
            Clock::Release { start } => Some((start - x).max(0.0).powi(CLOCK_POWER)),
        }
    }

    /// t at (x, y).
    #[inline]
    pub fn time(&self, x: f64, y: &State) -> f64 {
        match self.phase.clock {
            Clock::Time => x,
            _ => y[TIME],
        }
    }

    /// dt/dx for a compression rate δ̇.
    #[inline]
    fn time_rate(&self, x: f64, compression_rate: f64) -> f64 {
        let p = f64::from(CLOCK_POWER);
        match self.phase.clock {
            Clock::Time => 1.0,
            Clock::Onset => p * x.max(0.0).powi(CLOCK_POWER - 1) / compression_rate,
            Clock::Release { start } => -p * (start - x).max(0.0).powi(CLOCK_POWER - 1) / compression_rate,
        }
    }

    /// The law at (x, y) on this phase's branches.
    #[inline]
    pub fn local(&self, x: f64, y: &State) -> Local {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only where the CPU has AVX2 (`Relative::on_avx2`).
            return unsafe { self.local_avx2(x, y) };
        }
        self.local_here(x, y)
    }

    #[inline(always)]
    fn local_here(&self, x: f64, y: &State) -> Local {
        match self.phase.geometry {
            Geometry::Face => self.local_on::<true>(x, y),
            Geometry::Border | Geometry::Curved => self.local_on::<false>(x, y),
        }
    }

    /// [`Relative::local`] compiled apart for the face (n = e_x known), the common case.
    #[inline(always)]
    fn local_on<const FACE: bool>(&self, x: f64, y: &State) -> Local {
        let r = self.centre(y);
        let (delta, n) = if FACE {
            (-y[DISPLACEMENT], Vec3::X)
        } else if let Some((centre, radius)) = self.cap {
            let d = r - centre;
            let length = d.length();
            (self.ball_radius + radius - length, d * (1.0 / length))
        } else {
            let (delta, n, _) = geometry(&self.cuboid, self.ball_radius, self.border, &Pose3::IDENTITY, r);
            (delta, n)
        };
        // With a boot the law and the clocks see the ball's compression δ − δ_b.
        let delta = match self.boot {
            Some(_) => self.clock_compression(x).unwrap_or(delta - y[BOOT]),
            None => self.clock_compression(x).unwrap_or(delta),
        };
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let spin = vec3(y, BALL_ANGULAR_VELOCITY);
        // The slider's cap moves with the normal force: its rate is wanted while slipping.
        let slipping = !self.rigid && self.phase.friction == Friction::Slip && !self.phase.clamped;
        let mut boot_rate = 0.0;
        let mut body_rates = None;
        let (point, rate, sliding, normal_force, unclamped_force, damping_power, patch, zeta_rate, force_rate) = match &self.patch {
            Some(patch) => {
                let normal = self.patch_normal::<FACE>(patch, y, delta, n, slipping);
                boot_rate = normal.9;
                (normal.0, normal.1, normal.2, normal.3, normal.4, normal.5, normal.6, normal.7, normal.8)
            }
            None => {
                let lever_ball = along::<FACE>(n, -self.ball_radius);
                let point = r + lever_ball;
                // Ball's material point minus the foot's, at p (ω_b × (−R n) = −R (ω_b × n)).
                let v_rel = w - cross_normal::<FACE>(spin, n) * self.ball_radius - omega.cross(point);
                let rate = -dot_normal::<FACE>(n, v_rel);
                let sliding = tangential::<FACE>(n, v_rel);
                if let Some(boot) = &self.boot {
                    // The shell ball: (E, D) and, slipping, the gradient from one gas pressure.
                    let shell = match &self.law {
                        AnyLaw::Shell(ball) => Some(ball.at(delta)),
                        _ => None,
                    };
                    // The approach rate splits between the boot and the ball (kick-core's `boot`).
                    let (elastic, slope) = shell.map_or_else(|| self.law.rate_affine(delta, self.phase.compressing), |s| s.rate_affine());
                    let split = boot.split_affine(elastic, slope, rate, y[BOOT], self.phase.clamped);
                    boot_rate = split.boot_rate;
                    // Ḟ through the layer (kick-core's `Boot::force_rate`), δ̈ the approach's.
                    let force_rate = if slipping {
                        let (_, d_delta, d_rate) = shell.map_or_else(
                            || self.law.branch_force_and_gradient(delta, split.ball_rate, self.phase.compressing),
                            |s| s.force_and_gradient(split.ball_rate),
                        );
                        let (rate, per_acceleration) = boot.force_rate_parts(d_delta, d_rate, split.ball_rate, split.boot_rate);
                        NormalRate { rate, per_acceleration }
                    } else {
                        NormalRate::default()
                    };
                    (point, split.ball_rate, sliding, split.force, split.unclamped_force, split.loss_power(boot), None, 0.0, force_rate)
                } else {
                    // The shell ball slipping: force and gradient from one gas pressure.
                    let shell = match &self.law {
                        AnyLaw::Shell(ball) if self.clamps && slipping => Some(ball.unclamped_and_gradient(delta, rate)),
                        _ => None,
                    };
                    let (elastic, normal_force, unclamped_force) = if self.clamps {
                        let (elastic, raw) = shell.map_or_else(|| self.law.unclamped_force(delta, rate), |s| (s.0, s.1));
                        (elastic, if self.phase.clamped { 0.0 } else { raw }, raw)
                    } else {
                        let (elastic, force) = self.law.branch_force(delta, rate, self.phase.compressing);
                        (elastic, force, force)
                    };
                    let damping_power = (normal_force - elastic) * rate;
                    // dF_n/dt = ∂F/∂δ δ̇ + ∂F/∂δ̇ δ̈, on the phase's branch.
                    let force_rate = if !slipping {
                        NormalRate::default()
                    } else if self.clamps {
                        let (d_delta, d_rate) = shell.map_or_else(|| self.law.force_gradient(delta, rate), |s| (s.2, s.3));
                        NormalRate { rate: d_delta * rate, per_acceleration: d_rate }
                    } else {
                        let (_, d_delta, d_rate) = self.law.branch_force_and_gradient(delta, rate, self.phase.compressing);
                        NormalRate { rate: d_delta * rate, per_acceleration: d_rate }
                    };
                    (point, rate, sliding, normal_force, unclamped_force, damping_power, None, 0.0, force_rate)
                }
            }
        };

        let cap = if self.friction.is_infinite() { f64::INFINITY } else { self.friction * normal_force };
        // Rigid grip: the constraint's force, or μ F_n against the slip.
        let rigid_force = match self.phase.friction {
            _ if !self.rigid => Vec3::ZERO,
            Friction::None => Vec3::ZERO,
            Friction::Grip => match &patch {
                // The point contact on a cap: p = C + (r_f − δ) n, the patch's formula with dζ/dδ = −1.
                None if !FACE && self.cap.is_some() => {
                    let p = PatchForce { force: n * normal_force, moment: Vec3::ZERO, centroid: point, rate_weight: 1.0 };
                    self.patch_grip_force::<FACE>(y, &p, n, delta, rate, -1.0)
                }
                None => self.grip_force::<FACE>(y, n, point, normal_force),
                Some(p) => self.patch_grip_force::<FACE>(y, p, n, delta, rate, zeta_rate),
            },
            Friction::Slip => -self.slip_direction::<FACE>(n) * cap,
        };
        let element = if self.rigid {
            let grip_margin = if self.friction == 0.0 {
                0.0
            } else if self.friction.is_infinite() {
                1.0
            } else {
                match self.phase.friction {
                    // The slip ends where the sliding reverses.
                    Friction::Slip => self.phase.slip_start - sliding.dot(self.slip_direction::<FACE>(n)),
                    _ => cap - rigid_force.length(),
                }
            };
            // The power the contact takes out of the motion: ~0 while gripping.
            friction_law::Response {
                force: rigid_force,
                spring_rate: Vec3::ZERO,
                margin: grip_margin,
                power: -rigid_force.dot(sliding),
                slip_velocity: sliding,
            }
        } else {
            let xi = vec3(y, SPRING);
            let xi_t = tangential::<FACE>(n, xi);
            let k_t = self.tangential_stiffness;
            let mut element = match self.phase.friction {
                // No normal force to cap a slider: nothing acts tangentially.
                _ if self.phase.clamped => friction_law::free(sliding),
                Friction::None => friction_law::free(sliding),
                Friction::Grip => friction_law::grip(k_t, xi_t, sliding, cap),
                Friction::Slip => {
                    // The state holds the slider's direction only (see [`SPRING`]).
                    let s = friction_law::slip_direction(xi_t, sliding);
                    let (acceleration, rates) = self.compression_acceleration::<FACE>(y, n, normal_force, &patch, point, s * -cap);
                    body_rates = Some(rates);
                    let cap_rate = self.friction * (force_rate.rate + force_rate.per_acceleration * acceleration);
                    let mut element = friction_law::slip(k_t, s, sliding, cap, cap_rate);
                    element.spring_rate = friction_law::direction_rate(k_t, xi_t, sliding, cap, rate);
                    element
                }
            };
            // Off the face the spring is carried along the turning tangent
            // plane (n · ξ stays zero): ξ̇ gains −n (ṅ · ξ).
            if !FACE && element.spring_rate != Vec3::ZERO {
                let r_dot = w - omega.cross(r);
                element.spring_rate -= n * self.normal_rate(r, r_dot, n).dot(xi);
            }
            element
        };
        Local {
            compression: delta,
            compression_rate: rate,
            normal: n,
            point,
            sliding_velocity: sliding,
            normal_force,
            unclamped_force,
            tangential_force: element.force,
            spring_rate: element.spring_rate,
            grip_margin: element.margin,
            damping_power,
            friction_power: element.power,
            slip_velocity: element.slip_velocity,
            patch,
            boot_rate,
            body_rates,
        }
    }

    /// The normal side of [`Relative::local_on`] with the force spread over
    /// the patch ([`crate::patch`]): (point, δ̇, v_t, F_n, F_n unclamped, loss
    /// power, the patch's force, and on a cap while rigidly gripping the
    /// centroid height's rate dζ/dδ). Friction acts at the patch's centroid;
    /// the loss is the exact balance of the element forces' power.
    #[inline(always)]
    #[allow(clippy::type_complexity)]
    fn patch_normal<const FACE: bool>(
        &self,
        patch: &Patch,
        y: &State,
        delta: f64,
        n: Vec3,
        slipping: bool,
    ) -> (Vec3, f64, Vec3, f64, f64, f64, Option<PatchForce>, f64, NormalRate, f64) {
        let r = self.centre(y);
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let spin = vec3(y, BALL_ANGULAR_VELOCITY);
        let r_dot = w - omega.cross(r);
        let rate = -n.dot(r_dot);
        // The shell law (the patch's only law; others are refused when the kick
        // is built): F(δ, v) = F_el(δ) + β A(δ) v, slope β A exactly.
        // While slipping, the gradients too (`ShellBall::slip_terms`: one gas pressure for all four).
        let (elastic, slope, slip_gradient) = match &self.law {
            AnyLaw::Shell(ball) if slipping && !self.phase.clamped => {
                let (elastic, slope, d_elastic, d_slope) = ball.slip_terms(delta);
                (elastic, slope, Some((d_elastic, d_slope)))
            }
            AnyLaw::Shell(ball) => (ball.elastic_force(delta), ball.loss_slope(delta), None),
            law => {
                let (elastic, f1) = law.unclamped_force(delta, 1.0);
                (elastic, f1 - elastic, None)
            }
        };
        // A boot moves the foot's surface back by δ_b along n: the ball's
        // centre seen from it is r + δ_b n, which turns with n on a cap
        // (ṅ = ṙ_t/|r − C|); its rate along n, δ̇_b, is solved below.
        let (r_in, r_dot_in) = match self.boot {
            None => (r, r_dot),
            Some(_) => {
                let layer = y[BOOT];
                let turning = match self.cap {
                    Some((centre, _)) if !FACE => tangential::<false>(n, r_dot) * (layer / (r - centre).length()),
                    _ => Vec3::ZERO,
                };
                (r + n * layer, r_dot + turning)
            }
        };
        let mut zeta_rate = 0.0;
        // The normal force F_el + slope δ̇ ρ(δ), ρ = 1 on the flat face; (ρ, dρ/dδ) while slipping.
        let mut ratio = (1.0, 0.0);
        let mut p = match self.cap {
            Some((centre, radius)) if slipping => {
                let p;
                (p, ratio) = patch.resultant_and_normal_ratio(
                    Surface::Sphere { centre, radius },
                    self.ball_radius,
                    r_in,
                    r_dot_in,
                    spin - omega,
                    delta,
                    n,
                    elastic,
                    slope,
                );
                p
            }
            Some((centre, radius)) if self.rigid && self.phase.friction == Friction::Grip => {
                let p;
                (p, zeta_rate) = patch.resultant_and_centroid_rate(
                    Surface::Sphere { centre, radius },
                    self.ball_radius,
                    r_in,
                    r_dot_in,
                    spin - omega,
                    delta,
                    n,
                    elastic,
                    slope,
                );
                p
            }
            Some((centre, radius)) => patch.resultant(
                Surface::Sphere { centre, radius },
                self.ball_radius,
                r_in,
                r_dot_in,
                spin - omega,
                delta,
                n,
                elastic,
                slope,
            ),
            // The closed form, inlined here (no rule).
            None if delta > 0.0 => crate::patch::flat(self.ball_radius, r_in, n.dot(r_dot_in), spin - omega, delta, n, elastic, slope),
            None => patch.resultant(Surface::Flat, self.ball_radius, r_in, r_dot_in, spin - omega, delta, n, elastic, slope),
        };
        // The boot's balance: n · force = N0 − slope w δ̇_b = k_b δ_b + c_b δ̇_b
        // (the moment and the tangential part do not move with δ̇_b).
        let (boot_rate, boot_power) = match &self.boot {
            None => (0.0, 0.0),
            Some(boot) => {
                let (layer, give) = (y[BOOT], slope * p.rate_weight);
                let boot_rate = if self.phase.clamped {
                    -boot.stiffness * layer / boot.damping
                } else {
                    (n.dot(p.force) - boot.stiffness * layer) / (boot.damping + give)
                };
                p.force -= n * (give * boot_rate);
                (boot_rate, boot.stiffness * layer * boot_rate)
            }
        };
        let unclamped_force = n.dot(p.force);
        if self.phase.clamped {
            p.force = Vec3::ZERO;
            p.moment = Vec3::ZERO;
        }
        let point = p.centroid;
        let v_rel = w + spin.cross(point - r) - omega.cross(point);
        // Power of the element forces on the relative motion, less the elastic's (and the boot's spring's).
        let power = p.force.dot(w) + spin.dot(p.moment) - omega.dot(r.cross(p.force) + p.moment);
        let ball_rate = rate - boot_rate;
        let loss = -power - elastic * ball_rate - boot_power;
        // dF_n/dt of F_el(δ) + S(δ) δ̇ ρ(δ) (S = slope, affine in the rate as
        // above; δ the ball's), through the boot's balance when there is one.
        let force_rate = if slipping && !self.phase.clamped {
            let (d_elastic, d_slope) = slip_gradient.unwrap_or_else(|| {
                let (d_elastic, _) = self.law.force_gradient(delta, 0.0);
                (d_elastic, self.law.force_gradient(delta, 1.0).0 - d_elastic)
            });
            let (rho, d_rho) = ratio;
            let (d_delta, d_rate) = (d_elastic + (d_slope * rho + slope * d_rho) * ball_rate, slope * rho);
            match &self.boot {
                None => NormalRate { rate: d_delta * ball_rate, per_acceleration: d_rate },
                Some(boot) => {
                    let (rate, per_acceleration) = boot.force_rate_parts(d_delta, d_rate, ball_rate, boot_rate);
                    NormalRate { rate, per_acceleration }
                }
            }
        } else {
            NormalRate::default()
        };
        (point, ball_rate, tangential::<FACE>(n, v_rel), n.dot(p.force), unclamped_force, loss, Some(p), zeta_rate, force_rate, boot_rate)
    }

    /// δ̈ under the loads the phase applies (the normal force as `normal_force`
    /// or `patch`, the tangential `friction` at `point`): from the body-frame
    /// rates ẇ and Ω̇ of [`Relative::derivative`], r̈ = ẇ − Ω̇ × r − Ω × ṙ and
    /// δ̈ = −n · r̈ − ṅ · ṙ (δ̇ = −n · ṙ; ṅ from [`Relative::normal_rate`]).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn compression_acceleration<const FACE: bool>(
        &self,
        y: &State,
        n: Vec3,
        normal_force: f64,
        patch: &Option<PatchForce>,
        point: Vec3,
        friction: Vec3,
    ) -> (f64, BodyRates) {
        let r = self.centre(y);
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let (force, torque) = match patch {
            None => {
                let force = n * normal_force + friction;
                (force, point.cross(-force))
            }
            Some(p) => (p.force + friction, -(r.cross(p.force) + p.moment) - point.cross(friction)),
        };
        let rates = self.body_rates::<FACE>(y, force, torque);
        let (w_dot, omega_dot, _) = rates;
        let r_dot = w - omega.cross(r);
        let r_ddot = w_dot - omega_dot.cross(r) - omega.cross(r_dot);
        let acceleration = if FACE { -r_ddot.x } else { -n.dot(r_ddot) - self.normal_rate(r, r_dot, n).dot(r_dot) };
        (acceleration, BodyRates { force, torque, rates })
    }

    /// ẇ and Ω̇ (body frame) under `force` on the ball and `torque` on the
    /// foot (about its centre of mass, body frame), and with the leg the
    /// foot's world acceleration (zero without).
    #[inline(always)]
    fn body_rates<const FACE: bool>(&self, y: &State, force: Vec3, torque: Vec3) -> (Vec3, Vec3, Vec3) {
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        if let Some(leg) = &self.leg {
            // The leg's response to the wrench on the foot, in the world frame (model.rs).
            let q = rotation(y);
            let (turn, accel) = leg.response(q * torque, q * (-force) + self.drive);
            let inverse = q.inverse();
            (force * (1.0 / self.ball_mass) - inverse * accel - omega.cross(w), inverse * turn, accel)
        } else {
            let mut dw = force * self.inverse_reduced_mass - omega.cross(w);
            if self.drive != Vec3::ZERO {
                dw -= if FACE { rotation(y).inverse() * self.drive / self.foot_mass } else { rotation(y).inverse() * self.foot_drive };
            }
            // Off the face: products, not quotients (the divider is the right-hand side's bottleneck).
            let foot_turn = torque - omega.cross(omega * self.foot_inertia);
            (dw, if FACE { foot_turn / self.foot_inertia } else { foot_turn * self.inverse_foot_inertia }, Vec3::ZERO)
        }
    }

    /// ṅ (body frame) off the face, for the ball centre at r moving at ṙ: on
    /// a cap n = (r − C)/|r − C|, ṅ = (ṙ − n (n · ṙ))/|r − C|; on an edge,
    /// corner or rounded border n = (r − P)/|r − P| with P the nearest point
    /// of the core box, whose clamped coordinates stay put, so
    /// ṅ = (ṙ_c − n (n · ṙ))/|r − P| with ṙ_c the clamped coordinates' part of ṙ.
    #[inline(always)]
    fn normal_rate(&self, r: Vec3, r_dot: Vec3, n: Vec3) -> Vec3 {
        match self.cap {
            Some((centre, _)) => (r_dot - n * n.dot(r_dot)) * (1.0 / (r - centre).length()),
            None => {
                let h = self.cuboid.half_extents;
                let nearest = r.clamp(-h, h);
                let clamped = |ri: f64, hi: f64, vi: f64| if ri.abs() > hi { vi } else { 0.0 };
                let r_dot_c = Vec3::new(clamped(r.x, h.x, r_dot.x), clamped(r.y, h.y, r_dot.y), clamped(r.z, h.z, r_dot.z));
                // (A ball centre inside the box is beyond the geometry, refused after the step.)
                let distance = (r - nearest).length();
                if distance > 0.0 {
                    (r_dot_c - n * n.dot(r_dot)) * (1.0 / distance)
                } else {
                    Vec3::ZERO
                }
            }
        }
    }

    /// dy/dx at (x, y).
    #[inline]
    pub fn derivative(&self, x: f64, y: &State) -> State {
        self.derivative_and_local(x, y).0
    }

    /// dy/dx at (x, y) and the law there, from one evaluation.
    #[inline]
    pub fn derivative_and_local(&self, x: f64, y: &State) -> (State, Local) {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only where the CPU has AVX2 (`Relative::on_avx2`).
            return unsafe { self.derivative_and_local_avx2(x, y) };
        }
        self.derivative_and_local_here(x, y)
    }

    #[inline(always)]
    fn derivative_and_local_here(&self, x: f64, y: &State) -> (State, Local) {
        match self.phase.geometry {
            Geometry::Face => self.derivative_on::<true>(x, y),
            Geometry::Border | Geometry::Curved => self.derivative_on::<false>(x, y),
        }
    }

    /// [`Relative::derivative_and_local`] compiled for AVX2 ([`avx2`]).
    ///
    /// # Safety
    /// The CPU must have AVX2 ([`avx2`]).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn derivative_and_local_avx2(&self, x: f64, y: &State) -> (State, Local) {
        self.derivative_and_local_here(x, y)
    }

    /// [`Relative::local`] compiled for AVX2 ([`avx2`]).
    ///
    /// # Safety
    /// The CPU must have AVX2 ([`avx2`]).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn local_avx2(&self, x: f64, y: &State) -> Local {
        self.local_here(x, y)
    }

    #[inline(always)]
    fn derivative_on<const FACE: bool>(&self, x: f64, y: &State) -> (State, Local) {
        let c = self.local_on::<FACE>(x, y);
        let r = self.centre(y);
        // The patch: the normal force's own resultant and moment, friction at the centroid.
        let (force, torque, torque_ball) = match &c.patch {
            None => {
                let force = along::<FACE>(c.normal, c.normal_force) + c.tangential_force;
                // (−R n) × F = R (F × n)
                (force, c.point.cross(-force), cross_normal::<FACE>(force, c.normal) * self.ball_radius)
            }
            Some(p) => {
                let t = c.tangential_force;
                (p.force + t, -(r.cross(p.force) + p.moment) - c.point.cross(t), p.moment + (c.point - r).cross(t))
            }
        };
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let spin = vec3(y, BALL_ANGULAR_VELOCITY);
        let mut dy = State::zeros();
        put3(&mut dy, DISPLACEMENT, w - omega.cross(r));
        let (w_dot, omega_dot, foot_acceleration) = match c.body_rates.and_then(|b| b.under(force, torque)) {
            Some(rates) => rates,
            None => self.body_rates::<FACE>(y, force, torque),
        };
        put3(&mut dy, RELATIVE_VELOCITY, w_dot);
        put3(&mut dy, FOOT_ANGULAR_VELOCITY, omega_dot);
        if self.leg.is_some() {
            put3(&mut dy, FOOT_VELOCITY_WORLD, foot_acceleration);
            put3(&mut dy, FOOT_DISPLACEMENT_WORLD, vec3(y, FOOT_VELOCITY_WORLD));
        }
        dy[BOOT] = c.boot_rate;
        // q̇ = ½ q ⊗ (0, Ω)
        let (qw, qv) = (y[FOOT_ROTATION], Vec3::new(y[FOOT_ROTATION + 1], y[FOOT_ROTATION + 2], y[FOOT_ROTATION + 3]));
        dy[FOOT_ROTATION] = -0.5 * qv.dot(omega);
        put3(&mut dy, FOOT_ROTATION + 1, (omega * qw + qv.cross(omega)) * 0.5);
        let ball_turn = if FACE { torque_ball / self.ball_inertia } else { torque_ball * self.inverse_ball_inertia };
        put3(&mut dy, BALL_ANGULAR_VELOCITY, ball_turn - omega.cross(spin));
        put3(&mut dy, SPRING, c.spring_rate);
        dy[NORMAL_IMPULSE] = c.normal_force;
        dy[DAMPING_LOSS] = c.damping_power;
        dy[FRICTION_LOSS] = c.friction_power;
        dy[TIME] = 1.0;
        let dy = match self.phase.clock {
            Clock::Time => dy,
            _ => dy * self.time_rate(x, c.compression_rate),
        };
        (dy, c)
    }

    /// dt/dx at (x, y).
    pub fn clock_rate(&self, x: f64, y: &State) -> f64 {
        match self.phase.clock {
            Clock::Time => 1.0,
            _ => self.time_rate(x, self.local(x, y).compression_rate),
        }
    }

    /// Kinetic energy of the relative motion and of both rotations, plus the
    /// elastic energy (the centre of mass's kinetic energy is apart).
    pub fn internal_energy(&self, x: f64, y: &State) -> f64 {
        let reduced = 1.0 / self.inverse_reduced_mass;
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let c = self.local(x, y);
        0.5 * reduced * vec3(y, RELATIVE_VELOCITY).length_squared()
            + 0.5 * omega.dot(omega * self.foot_inertia)
            + 0.5 * self.ball_inertia * vec3(y, BALL_ANGULAR_VELOCITY).length_squared()
            + self.law.potential(c.compression)
            + self.boot.map_or(0.0, |b| b.potential(y[BOOT]))
            + if self.rigid { 0.0 } else { 0.5 * self.tangential_stiffness * self.spring(&c, y).length_squared() }
    }

    /// The spring's stretch ξ (body frame) in this phase: the state while
    /// gripping, μ F_n / k_t along the state's direction while slipping
    /// ([`SPRING`]), none without a slider or with rigid grip.
    pub fn spring(&self, c: &Local, y: &State) -> Vec3 {
        let xi = vec3(y, SPRING);
        let xi_t = xi - c.normal * c.normal.dot(xi);
        match self.phase.friction {
            _ if self.rigid => Vec3::ZERO,
            Friction::None => Vec3::ZERO,
            // (While the normal force is clamped at zero the element is left as it was.)
            Friction::Grip => xi_t,
            Friction::Slip => {
                friction_law::slip_direction(xi_t, c.sliding_velocity) * (self.friction * c.normal_force / self.tangential_stiffness)
            }
        }
    }

    /// Kinetic and elastic energy of the kick with the leg at (x, y), time
    /// t: the ball's (from the foot's world velocity and w), the foot's
    /// (`LegDynamics::foot_energy`) and the stored energy.
    pub fn leg_mechanical_energy(&self, leg: &crate::model::LegDynamics, x: f64, y: &State, t: f64, ball_velocity0: Vec3) -> f64 {
        let q = rotation(y);
        let foot_velocity = vec3(y, FOOT_VELOCITY_WORLD);
        let ball_velocity = foot_velocity + q * vec3(y, RELATIVE_VELOCITY);
        let impulse = (ball_velocity - ball_velocity0) * self.ball_mass;
        let c = self.local(x, y);
        0.5 * self.ball_mass * ball_velocity.length_squared()
            + 0.5 * self.ball_inertia * vec3(y, BALL_ANGULAR_VELOCITY).length_squared()
            + leg.foot_energy(self.foot_mass, self.drive * t - impulse, q * vec3(y, FOOT_ANGULAR_VELOCITY), foot_velocity)
            + self.law.potential(c.compression)
            + self.boot.map_or(0.0, |b| b.potential(y[BOOT]))
            + 0.5 * self.tangential_stiffness * self.spring(&c, y).length_squared()
    }

    /// K f: the rate of the contact point's relative velocity (ball's
    /// material point minus foot's) per unit force f on the ball at p, on the
    /// face: f (1/m_b + 1/m_f) + (L²/I_b) f_t − p × I_f⁻¹ (p × f), the
    /// inverse effective mass of the contact (symmetric, positive definite),
    /// L = |p − r| the ball's lever (R for the point contact, R − δ at the
    /// patch's centroid).
    #[inline]
    fn contact_compliance<const FACE: bool>(&self, n: Vec3, point: Vec3, lever: f64, f: Vec3) -> Vec3 {
        let r2 = lever * lever;
        // The face keeps its quotients (the point contact's kicks bit for bit).
        let turn = if FACE { point.cross(f) / self.foot_inertia } else { point.cross(f) * self.inverse_foot_inertia };
        f * self.inverse_reduced_mass + tangential::<FACE>(n, f) * (r2 / self.ball_inertia) - point.cross(turn)
    }

    /// Rigid grip: the tangential force on the ball that keeps the sliding
    /// velocity v_t = w − R ω_b × n − Ω × p at its value (zero while
    /// gripping). d/dt v = K F + b with F = F_n n + F_t (the body-frame
    /// rates of [`Relative::derivative`], n fixed on the face); the
    /// tangential rows K_tt F_t = −(b + K F_n n)_t are a 2×2 system.
    #[inline]
    fn grip_force<const FACE: bool>(&self, y: &State, n: Vec3, point: Vec3, normal_force: f64) -> Vec3 {
        let r = self.centre(y);
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let spin = vec3(y, BALL_ANGULAR_VELOCITY);
        let mut b = -omega.cross(w)
            + omega.cross(spin).cross(n) * self.ball_radius
            + (omega.cross(omega * self.foot_inertia) / self.foot_inertia).cross(point)
            - omega.cross(w - omega.cross(r));
        if self.drive != Vec3::ZERO {
            b -= rotation(y).inverse() * self.drive / self.foot_mass;
        }
        let rhs = -(b + self.contact_compliance::<FACE>(n, point, self.ball_radius, along::<FACE>(n, normal_force)));
        self.tangential_solve::<FACE>(n, point, self.ball_radius, rhs)
    }

    /// Rigid grip under the patch: friction acts at the centroid c, so the
    /// held velocity is the material points' at c, v = w + ω_b × ℓ − Ω × c
    /// with ℓ = c − r, and c moves with the ball and with δ. On the flat face
    /// ℓ = −(R − δ) n, ℓ̇ = δ̇ n; on a cap c = C + ζ(δ) n, ℓ = −(d − ζ) n,
    /// ℓ̇ = δ̇ (1 + ζ') n − (d − ζ) ṅ with ṅ = ṙ_t / d, and keeping v_t = 0
    /// on the turning normal needs (v̇)_t = (v · n) ṅ. Differentiating along
    /// the body-frame rates, v̇ = K F_t + b with K at c with lever |ℓ|, and b
    /// holding the patch's force F and moment M (functions of the state, not
    /// of F_t), the frame's rotation and the centroid's motion:
    /// b = F/m_r − Ω × w − F_drive/m_f + (M/I_b − Ω × ω_b) × ℓ + ω_b × ℓ̇
    ///   + I_f⁻¹(r × F + M + Ω × I_f Ω) × c − Ω × (ṙ + ℓ̇).
    ///
    /// The point contact on a cap is the case c = C + (r_f − δ) n, M = 0
    /// (dζ/dδ = −1, lever R).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn patch_grip_force<const FACE: bool>(&self, y: &State, p: &PatchForce, n: Vec3, delta: f64, rate: f64, zeta_rate: f64) -> Vec3 {
        let r = self.centre(y);
        let w = vec3(y, RELATIVE_VELOCITY);
        let omega = vec3(y, FOOT_ANGULAR_VELOCITY);
        let spin = vec3(y, BALL_ANGULAR_VELOCITY);
        let c = p.centroid;
        let r_dot = w - omega.cross(r);
        let (lever, lever_rate, normal_rate) = match self.cap {
            Some((centre, radius)) if !FACE => {
                let d = self.ball_radius + radius - delta; // |r − C|
                let normal_rate = tangential::<false>(n, r_dot) * (1.0 / d);
                // The patch at touch (δ = 0, the first evaluation only): the limit, from a patch of 1e-12 R.
                let zeta_rate = match &self.patch {
                    Some(patch) if !(delta > 0.0) => {
                        let tiny = 1e-12 * self.ball_radius;
                        let surface = Surface::Sphere { centre, radius };
                        patch
                            .resultant_and_centroid_rate(
                                surface,
                                self.ball_radius,
                                centre + n * (d - tiny),
                                Vec3::ZERO,
                                Vec3::ZERO,
                                tiny,
                                n,
                                0.0,
                                0.0,
                            )
                            .1
                    }
                    _ => zeta_rate,
                };
                let lever = n.dot(r - c);
                (lever, n * (rate * (1.0 + zeta_rate)) - normal_rate * lever, normal_rate)
            }
            _ => (self.ball_radius - delta.max(0.0), n * rate, Vec3::ZERO),
        };
        let arm = c - r;
        let foot_turn = (r.cross(p.force) + p.moment + omega.cross(omega * self.foot_inertia)) * self.inverse_foot_inertia;
        let mut b = p.force * self.inverse_reduced_mass - omega.cross(w)
            + (p.moment * self.inverse_ball_inertia - omega.cross(spin)).cross(arm)
            + spin.cross(lever_rate)
            + foot_turn.cross(c)
            - omega.cross(r_dot + lever_rate);
        if self.drive != Vec3::ZERO {
            b -= if FACE { rotation(y).inverse() * self.drive / self.foot_mass } else { rotation(y).inverse() * self.foot_drive };
        }
        if !FACE {
            let v = w + spin.cross(arm) - omega.cross(c);
            b -= normal_rate * n.dot(v);
        }
        self.tangential_solve::<FACE>(n, c, lever, -b)
    }

    /// The tangential f with (K f)_t = rhs_t: on the face the y and z rows,
    /// elsewhere the rows of a tangent basis.
    #[inline(always)]
    fn tangential_solve<const FACE: bool>(&self, n: Vec3, point: Vec3, lever: f64, rhs: Vec3) -> Vec3 {
        if FACE {
            let ky = self.contact_compliance::<FACE>(n, point, lever, Vec3::Y);
            let kz = self.contact_compliance::<FACE>(n, point, lever, Vec3::Z);
            let det = ky.y * kz.z - kz.y * ky.z;
            return Vec3::new(0.0, (rhs.y * kz.z - kz.y * rhs.z) / det, (ky.y * rhs.z - rhs.y * ky.z) / det);
        }
        // A tangent basis of equal lengths L, not normalised: the rows e_i · (K f) = e_i · rhs
        // are the unit basis's times L, and f = α e1 + β e2 the same force.
        // Z × n (or Y × n near the z axis), and n × e1, written out.
        let (e1, e2) = if n.z.abs() < 0.9 {
            (Vec3::new(-n.y, n.x, 0.0), Vec3::new(-n.z * n.x, -n.z * n.y, n.x * n.x + n.y * n.y))
        } else {
            (Vec3::new(n.z, 0.0, -n.x), Vec3::new(n.y * -n.x, n.z * n.z + n.x * n.x, -n.y * n.z))
        };
        // e_i · K e_j = (e_i · e_j)(1/m_r + L²/I_b) + (p × e_i) · I_f⁻¹ (p × e_j): symmetric.
        let (u1, u2) = (point.cross(e1), point.cross(e2));
        let (v1, v2) = (u1 * self.inverse_foot_inertia, u2 * self.inverse_foot_inertia);
        let diagonal = (self.inverse_reduced_mass + lever * lever * self.inverse_ball_inertia) * e1.length_squared();
        let (a11, a12, a22) = (diagonal + u1.dot(v1), u1.dot(v2), diagonal + u2.dot(v2));
        let (b1, b2) = (e1.dot(rhs), e2.dot(rhs));
        let inverse_det = 1.0 / (a11 * a22 - a12 * a12);
        e1 * ((b1 * a22 - a12 * b2) * inverse_det) + e2 * ((a11 * b2 - a12 * b1) * inverse_det)
    }

    /// A rigid slip's direction: fixed on the face; on a cap, the stored
    /// direction brought into the turning tangent plane (exact for a kick in
    /// one plane, where it is the plane's tangent).
    #[inline(always)]
    fn slip_direction<const FACE: bool>(&self, n: Vec3) -> Vec3 {
        if FACE {
            self.phase.slip_direction
        } else {
            tangential::<false>(n, self.phase.slip_direction).normalize_or_zero()
        }
    }

    /// Rigid grip with μ = ∞: the tangential impulse J at first touch that
    /// stops the sliding at once (the k_t → ∞ limit of the spring at any
    /// damping ratio > 0: the spring's transient shrinks to an instant and
    /// its energy is lost), applied to `y`: J = −K_tt⁻¹ v_t, the ball takes
    /// J and the foot −J at p. The energy it takes goes to the friction loss.
    pub fn grip_impulse(&self, y: &State) -> State {
        let before = self.internal_energy(0.0, y);
        let c = self.local(0.0, y);
        let n = c.normal;
        // At touch δ = 0: the patch's centroid is the point contact's p, lever R.
        let j = match self.phase.geometry {
            Geometry::Face => self.tangential_solve::<true>(Vec3::X, c.point, self.ball_radius, -c.sliding_velocity),
            _ => self.tangential_solve::<false>(n, c.point, self.ball_radius, -c.sliding_velocity),
        };
        let mut out = *y;
        put3(&mut out, RELATIVE_VELOCITY, vec3(y, RELATIVE_VELOCITY) + j * self.inverse_reduced_mass);
        put3(&mut out, FOOT_ANGULAR_VELOCITY, vec3(y, FOOT_ANGULAR_VELOCITY) + c.point.cross(-j) / self.foot_inertia);
        let spin_kick = match self.phase.geometry {
            Geometry::Face => cross_normal::<true>(j, Vec3::X),
            _ => j.cross(n),
        };
        put3(&mut out, BALL_ANGULAR_VELOCITY, vec3(y, BALL_ANGULAR_VELOCITY) + spin_kick * (self.ball_radius / self.ball_inertia));
        out[FRICTION_LOSS] += before - self.internal_energy(0.0, &out);
        out
    }
}

/// Whether this CPU runs AVX2 (false off x86-64). The 3D kick's hot code is
/// compiled twice from the same source, for the baseline x86-64 and for
/// AVX2 (`Accurate3d`'s run with the stepper, and the right-hand side), and
/// the copy is chosen here at run time. On AVX2 a kick takes about a fifth
/// less time (the cap's patch rings go four to a register, large copies
/// stay in registers), and its results are bit for bit the baseline's:
/// the same IEEE operations in the same order (Rust fuses no multiply and
/// add it was not asked to), held by the test
/// `the_avx2_copy_is_the_baseline_bit_for_bit`.
pub(crate) fn avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

impl kick_core::dop853::System<DIM> for Relative {
    #[inline]
    fn derivative(&self, x: f64, y: &State) -> State {
        Relative::derivative(self, x, y)
    }
    fn counted_components(&self) -> usize {
        Relative::counted_components(self)
    }
}

// Products with the normal n, written out for the face (n = e_x) where the
// zeros would otherwise be multiplied (IEEE rules keep the compiler from
// dropping them).

/// n · v
#[inline(always)]
fn dot_normal<const FACE: bool>(n: Vec3, v: Vec3) -> f64 {
    if FACE {
        v.x
    } else {
        n.dot(v)
    }
}

/// s n
#[inline(always)]
fn along<const FACE: bool>(n: Vec3, s: f64) -> Vec3 {
    if FACE {
        Vec3::new(s, 0.0, 0.0)
    } else {
        n * s
    }
}

/// v − (v · n) n
#[inline(always)]
fn tangential<const FACE: bool>(n: Vec3, v: Vec3) -> Vec3 {
    if FACE {
        Vec3::new(0.0, v.y, v.z)
    } else {
        v - n * v.dot(n)
    }
}

/// v × n
#[inline(always)]
fn cross_normal<const FACE: bool>(v: Vec3, n: Vec3) -> Vec3 {
    if FACE {
        Vec3::new(0.0, v.z, -v.y)
    } else {
        v.cross(n)
    }
}

/// The spring's stretch where a slip ends in grip: along the slider's
/// direction, k_t |ξ| = μ F_n (1 − [`friction_law::GRIP_ENTRY`]).
pub(crate) fn spring_on_cap(system: &Relative, c: &Local, y: &State) -> Vec3 {
    system.spring(c, y) * (1.0 - friction_law::GRIP_ENTRY)
}

/// The state's spring where a slip starts (at first touch or from grip):
/// the slider's direction at the length δ ([`SPRING`]).
pub(crate) fn slip_direction_state(c: &Local, y: &State) -> Vec3 {
    let xi = vec3(y, SPRING);
    friction_law::slip_direction(xi - c.normal * c.normal.dot(xi), c.sliding_velocity) * c.compression
}

/// Set the spring's stretch (body frame).
pub(crate) fn put_spring(y: &mut State, spring: Vec3) {
    put3(y, SPRING, spring);
}

/// The pair's centre of mass: it moves under the drive and gravity alone.
#[derive(Debug, Clone, Copy)]
pub struct CentreOfMass {
    pub position: Vec3,
    pub velocity: Vec3,
    pub acceleration: Vec3,
    pub mass: f64,
}

impl CentreOfMass {
    pub fn of(kick: &Kick3d) -> CentreOfMass {
        let s = kick.initial_state();
        let (m_f, m_b) = (kick.base.effective_foot_mass(), kick.base.ball_mass());
        let mass = m_f + m_b;
        CentreOfMass {
            position: (s.foot_position * m_f + s.ball_position * m_b) / mass,
            velocity: (s.foot_velocity * m_f + s.ball_velocity * m_b) / mass,
            acceleration: kick.drive() / mass + kick.gravity_vector(),
            mass,
        }
    }
    /// Displacement since first touch at time t.
    pub fn displacement(&self, t: f64) -> Vec3 {
        self.velocity * t + self.acceleration * (0.5 * t * t)
    }
    pub fn velocity_at(&self, t: f64) -> Vec3 {
        self.velocity + self.acceleration * t
    }
}

/// The state at first touch.
pub fn initial_state(kick: &Kick3d) -> State {
    let s = kick.initial_state();
    let q = s.foot_orientation;
    let mut y = State::zeros();
    put3(&mut y, RELATIVE_VELOCITY, q.inverse() * (s.ball_velocity - s.foot_velocity));
    y[FOOT_ROTATION] = q.w;
    put3(&mut y, FOOT_ROTATION + 1, Vec3::new(q.x, q.y, q.z));
    if kick.leg.is_some() {
        put3(&mut y, FOOT_VELOCITY_WORLD, s.foot_velocity);
    }
    y
}

/// Both bodies in the world frame at (x, y), time t.
pub fn end_state(kick: &Kick3d, system: &Relative, x: f64, y: &State, t: f64) -> EndState {
    if kick.leg.is_some() {
        return leg_end_state(kick, system, x, y, t);
    }
    let start = kick.initial_state();
    let com = CentreOfMass::of(kick);
    let (m_f, m_b, mass) = (system.foot_mass, system.ball_mass, com.mass);
    let q = rotation(y);
    let r = q * system.centre(y);
    let r0 = start.ball_position - start.foot_position;
    let w = q * vec3(y, RELATIVE_VELOCITY);
    let shift = com.displacement(t);
    let v_com = com.velocity_at(t);
    let foot_shift = shift - (r - r0) * (m_b / mass);
    let ball_velocity = v_com + w * (m_f / mass);
    let spin = q * vec3(y, BALL_ANGULAR_VELOCITY);
    let gravity = kick.gravity_vector();
    let local = system.local(x, y);
    EndState {
        time: t,
        foot_position: start.foot_position + foot_shift,
        foot_orientation: q,
        foot_velocity: v_com - w * (m_b / mass),
        foot_angular_velocity: q * vec3(y, FOOT_ANGULAR_VELOCITY),
        ball_position: start.ball_position + shift + (r - r0) * (m_f / mass),
        ball_velocity,
        ball_angular_velocity: spin,
        spring: q * system.spring(&local, y),
        compression: local.compression,
        boot_compression: y[BOOT],
        impulse: (ball_velocity - start.ball_velocity - gravity * t) * m_b,
        angular_impulse: spin * system.ball_inertia,
        normal_impulse: y[NORMAL_IMPULSE],
        normal_damping_loss: y[DAMPING_LOSS],
        friction_loss: y[FRICTION_LOSS],
        drive_work: kick.drive().dot(foot_shift),
        gravity_work: gravity.dot(shift) * mass,
    }
}

/// [`end_state`] with the leg: the foot's world velocity and displacement
/// are states (the hip holds the leg, the pair's centre of mass is not free).
fn leg_end_state(kick: &Kick3d, system: &Relative, x: f64, y: &State, t: f64) -> EndState {
    let start = kick.initial_state();
    let q = rotation(y);
    let foot_position = start.foot_position + vec3(y, FOOT_DISPLACEMENT_WORLD);
    let foot_velocity = vec3(y, FOOT_VELOCITY_WORLD);
    let ball_velocity = foot_velocity + q * vec3(y, RELATIVE_VELOCITY);
    let spin = q * vec3(y, BALL_ANGULAR_VELOCITY);
    let local = system.local(x, y);
    EndState {
        time: t,
        foot_position,
        foot_orientation: q,
        foot_velocity,
        foot_angular_velocity: q * vec3(y, FOOT_ANGULAR_VELOCITY),
        ball_position: foot_position + q * system.centre(y),
        ball_velocity,
        ball_angular_velocity: spin,
        spring: q * system.spring(&local, y),
        compression: local.compression,
        boot_compression: y[BOOT],
        impulse: (ball_velocity - start.ball_velocity) * system.ball_mass,
        angular_impulse: spin * system.ball_inertia,
        normal_impulse: y[NORMAL_IMPULSE],
        normal_damping_loss: y[DAMPING_LOSS],
        friction_loss: y[FRICTION_LOSS],
        drive_work: kick.drive().dot(vec3(y, FOOT_DISPLACEMENT_WORLD)),
        gravity_work: 0.0,
    }
}
