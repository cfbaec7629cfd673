//! A check of the elastic-ankle interpolation against the leg itself: the
//! ball's contact law (Eq. 20) coupled to the leg with a torsional ankle
//! spring, integrated in time.
//!
//! Over a few milliseconds the pose barely changes, so the leg is taken as
//! linear with its geometry frozen at the pose of contact (velocity-product
//! terms dropped). Then M u̇ = −Jᵀn F − e_a κ θ, and only three combinations of
//! M⁻¹ matter: the free-ankle mobility 1/m_free = gᵀM⁻¹g (g = Jᵀn), the
//! ankle's 1/I_a = (M⁻¹)_aa and the coupling c = (M⁻¹g)_a. The state reduces to
//! the contact-point velocity v_c, the ankle rate ω_a and deflection θ, the
//! ball velocity v_b and the compression δ:
//!   v̇_c = −F/m_free − c κ θ,   ω̇_a = −c F − κ θ / I_a,   θ̇ = ω_a,
//!   v̇_b = F/m_b,               δ̇ = v_c − v_b.
//! With κ = 0 this is exactly the 1D model with m_f = m_free; as κ → ∞ the
//! ankle locks and 1/m_locked = 1/m_free − c² I_a (the Schur complement).
//!
//! A stiff ankle is a fast mode, ω_a² = κ/I_a: the fixed RK4 step is kept
//! below [`ANKLE_MODE_STEP`]/|λ|max of the linearised system, so no κ makes
//! it unstable. The gap to the locked leg falls as 1/κ (measured ≈ 0.64
//! κ_c/κ in exit speed for the default pose, κ_c = I_a (π/t_c)² the
//! inertial stiffness of [`Leg::effective_mass`]); beyond
//! [`locked_limit_stiffness`], where it is far below the coupled run's own
//! error, the locked leg is returned in closed form (the 1D model with
//! m_locked, the ankle deflected quasi-statically by the contact torque).

use crate::{exit_outcome, AnkleJoint, Impact, Leg, LegEffectiveMass, LegError, Pose};
use kick_core::{roots, ContactLaw, Outcome, Parameter, Scenario};
use std::f64::consts::PI;

/// The ball's exit from a leg with an elastic ankle, frozen geometry.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CoupledContact {
    pub v_ball_out: f64,
    /// Contact-point velocity along n at separation.
    pub v_contact_out: f64,
    pub contact_time: f64,
    /// Largest |θ|, rad: the frozen-geometry assumption needs it small.
    pub max_ankle_deflection: f64,
    /// True when κ is beyond [`locked_limit_stiffness`] and the locked leg
    /// was taken in closed form instead of integrating.
    pub locked_limit: bool,
}

/// The three numbers of M⁻¹ the elastic ankle needs (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct AnkleMobilities {
    /// 1/m_free = gᵀ M⁻¹ g, 1/kg.
    pub free: f64,
    /// 1/I_a = (M⁻¹)_aa, 1/(kg m²).
    pub ankle: f64,
    /// c = (M⁻¹ g)_a, 1/(kg m).
    pub coupling: f64,
}

impl AnkleMobilities {
    pub fn of(leg: &Leg, pose: &Pose, impact: &Impact) -> Result<AnkleMobilities, LegError> {
        let (chain, x) = leg.chain(pose, impact, leg.knee_locked, true)?;
        let n = impact.direction.normalize();
        let g = chain.point_jacobian(chain.bodies.len() - 1, &x).transpose() * n;
        let inverse =
            chain.mass_matrix().cholesky().ok_or_else(|| LegError::Degenerate("mass matrix not positive definite".into()))?.inverse();
        let a = inverse.nrows() - 1; // the ankle is the last joint
        let w = &inverse * &g;
        Ok(AnkleMobilities { free: g.dot(&w), ankle: inverse[(a, a)], coupling: w[a] })
    }
    /// 1/m_locked = 1/m_free − c²/(1/I_a): the ankle held at θ = 0.
    pub fn locked(&self) -> f64 {
        self.free - self.coupling * self.coupling / self.ankle
    }
}

/// Reduced leg–ball system (see the module documentation).
#[derive(Debug, Clone, Copy)]
struct Reduced {
    free_mobility: f64,
    ankle_mobility: f64,
    coupling: f64,
    stiffness: f64,
    ball_mass: f64,
}

type State = [f64; 5]; // v_c, ω_a, θ, v_b, δ

impl Reduced {
    fn derivative<L: ContactLaw>(&self, law: &L, y: &State) -> State {
        let [v_c, omega, theta, v_b, delta] = *y;
        let force = law.contact_force(delta.max(0.0), v_c - v_b);
        let torque = self.stiffness * theta;
        [
            -self.free_mobility * force - self.coupling * torque,
            -self.coupling * force - self.ankle_mobility * torque,
            omega,
            force / self.ball_mass,
            v_c - v_b,
        ]
    }
}

fn rk4<L: ContactLaw>(system: &Reduced, law: &L, y: &State, h: f64) -> State {
    let add = |a: &State, b: &State, s: f64| -> State { std::array::from_fn(|i| a[i] + s * b[i]) };
    let k1 = system.derivative(law, y);
    let k2 = system.derivative(law, &add(y, &k1, 0.5 * h));
    let k3 = system.derivative(law, &add(y, &k2, 0.5 * h));
    let k4 = system.derivative(law, &add(y, &k3, h));
    std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// Largest h |λ|max of the coupled run's fixed RK4 step: well inside RK4's
/// stability region (|hλ| ≤ 2.6 in every direction), and fine enough that
/// the ankle mode, whose amplitude is O(1/κ), adds nothing measurable.
pub const ANKLE_MODE_STEP: f64 = 0.5;

/// Estimated relative gap in exit speed to the locked leg at which the
/// locked limit is taken instead of integrating: far below the coupled
/// run's own error (~1e-8 at [`ELASTIC_STEPS`]).
pub const LOCKED_LIMIT_GAP: f64 = 1e-9;

/// κ_c = I_a (π/t_c)², the ankle's inertial stiffness over the locked leg's
/// contact (see [`Leg::effective_mass`]); the gap to the locked leg is
/// ≈ 0.64 κ_c/κ in exit speed for the default pose.
fn inertial_stiffness(mobilities: &AnkleMobilities, locked_contact_time: f64) -> f64 {
    (PI / locked_contact_time).powi(2) / mobilities.ankle
}

/// The ankle stiffness beyond which [`coupled_ankle_contact`] returns the
/// locked leg: κ_c / [`LOCKED_LIMIT_GAP`], with κ_c the ankle's inertial
/// stiffness over the locked leg's contact (≈ 3.7e12 N m/rad for the default
/// pose). The coupled run and the locked limit agree there to 1e-8
/// (tests/leg/elastic_ankle.rs).
pub fn locked_limit_stiffness(leg: &Leg, pose: &Pose, impact: &Impact, base: &Scenario) -> Result<f64, LegError> {
    let mobilities = AnkleMobilities::of(leg, pose, impact)?;
    let locked = leg.effective_mass(pose, impact, AnkleJoint::Locked)?.locked_ankle;
    let contact_time = exit_outcome(locked, base)?.contact_time;
    Ok(inertial_stiffness(&mobilities, contact_time) / LOCKED_LIMIT_GAP)
}

/// The locked leg as a [`CoupledContact`]: the 1D contact with m_locked,
/// the ankle deflected quasi-statically, θ = −c F/(κ/I_a).
fn locked_limit(mobilities: &AnkleMobilities, stiffness: f64, locked: &Outcome) -> CoupledContact {
    CoupledContact {
        v_ball_out: locked.v_ball_out,
        v_contact_out: locked.v_foot_out,
        contact_time: locked.contact_time,
        max_ankle_deflection: (mobilities.coupling * locked.peak_force / (stiffness * mobilities.ankle)).abs(),
        locked_limit: true,
    }
}

/// Integrate the coupled contact with at least `steps` RK4 steps per 1D
/// contact time of the locked leg, and more when the ankle mode is fast
/// (h |λ|max ≤ [`ANKLE_MODE_STEP`]); separation is interpolated linearly
/// within the last step, where the force is already near zero. Beyond
/// [`locked_limit_stiffness`] the locked leg is returned in closed form.
pub fn coupled_ankle_contact(
    leg: &Leg,
    pose: &Pose,
    impact: &Impact,
    stiffness: f64,
    base: &Scenario,
    steps: u32,
) -> Result<CoupledContact, LegError> {
    crate::check_range("ankle_stiffness", stiffness, 0.0, f64::MAX, "N m/rad")?;
    if steps < 100 {
        return Err(LegError::InvalidInput { name: "steps", value: f64::from(steps), requirement: "at least 100 per contact".into() });
    }
    let mobilities = AnkleMobilities::of(leg, pose, impact)?;
    let system = Reduced {
        free_mobility: mobilities.free,
        ankle_mobility: mobilities.ankle,
        coupling: mobilities.coupling,
        stiffness,
        ball_mass: base.ball_mass(),
    };
    let law = base.paper_law();
    let locked = leg.effective_mass(pose, impact, AnkleJoint::Locked)?.locked_ankle;
    let locked_outcome = exit_outcome(locked, base)?;
    let estimate = locked_outcome.contact_time;
    if stiffness >= inertial_stiffness(&mobilities, estimate) / LOCKED_LIMIT_GAP {
        return Ok(locked_limit(&mobilities, stiffness, &locked_outcome));
    }
    // |λ|max of the linearised system: the ankle mode κ/I_a and the contact
    // (stiffest at the free leg's deepest compression) share the trace of
    // M⁻¹K, and the damping adds at most c (1/m_free + 1/m_b).
    let contact_mobility = mobilities.free + 1.0 / base.ball_mass();
    let free = base.with(Parameter::FootMass, 1.0 / mobilities.free)?;
    let deepest = kick_compliant::stability::reference_compression(&free, &law);
    let (_, contact_stiffness, contact_damping) = law.force_and_gradient(deepest, base.approach_speed());
    let fastest = (contact_stiffness * contact_mobility + stiffness * mobilities.ankle).sqrt() + contact_damping * contact_mobility;
    let h = (estimate / f64::from(steps)).min(ANKLE_MODE_STEP / fastest);
    // Before contact the leg swings with a still ankle (ω_a = 0, θ = 0); the
    // equations are linear in the leg, so only the response to F matters.
    let mut y: State = [base.foot_speed(), 0.0, 0.0, base.ball_speed(), 0.0];
    let mut t = 0.0;
    let mut max_deflection: f64 = 0.0;
    let mut compressing = true;
    // Generous bound: an elastic ankle lengthens the contact, not by 100×.
    let limit = (100.0 * (estimate / h).ceil()) as u64;
    for _ in 0..limit {
        let next = rk4(&system, &law, &y, h);
        max_deflection = max_deflection.max(next[2].abs());
        if compressing && next[0] - next[3] < 0.0 {
            compressing = false;
        }
        if !compressing && next[4] <= 0.0 {
            // δ crosses zero within this step: interpolate.
            let s = y[4] / (y[4] - next[4]);
            let lerp = |i: usize| y[i] + s * (next[i] - y[i]);
            let out = CoupledContact {
                v_ball_out: lerp(3),
                v_contact_out: lerp(0),
                contact_time: t + s * h,
                max_ankle_deflection: max_deflection,
                locked_limit: false,
            };
            for v in [out.v_ball_out, out.v_contact_out, out.contact_time] {
                kick_core::error::finite("coupled leg-ball state", v, out.contact_time)?;
            }
            return Ok(out);
        }
        y = next;
        t += h;
    }
    Err(LegError::Contact(kick_core::KickError::NoSeparation {
        time: t,
        reason: "the coupled leg-ball contact did not end within 100 locked-leg contact times".into(),
    }))
}

/// RK4 steps per contact used by [`elastic_ankle`]: at 1e4 steps the
/// coupled run with κ = 0 matches the 1D model (`accurate`) to 3e-9 relative,
/// at 1e5 to 2e-11 (tests hold the convergence); 2e4 keeps it below 1e-8.
pub const ELASTIC_STEPS: u32 = 20_000;

/// An elastic ankle summarised for the 1D model.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ElasticAnkle {
    /// The constant m_f with which the 1D model reproduces the coupled
    /// run's ball exit speed, kg.
    pub equivalent_mass: f64,
    pub coupled: CoupledContact,
    /// The 1D contact with m_f = `equivalent_mass`.
    pub outcome: Outcome,
    /// The cheap series-spring interpolation ([`Leg::effective_mass`]) at the
    /// coupled run's contact time, for comparison.
    pub interpolated: LegEffectiveMass,
}

/// Elastic ankle of stiffness κ: run the coupled leg–ball contact, then find
/// by Brent's method the m_f that gives the 1D model the same exit speed.
/// v_b⁺ rises monotonically with m_f (Section 14.1), so the root is unique.
pub fn elastic_ankle(leg: &Leg, pose: &Pose, impact: &Impact, stiffness: f64, base: &Scenario) -> Result<ElasticAnkle, LegError> {
    let coupled = coupled_ankle_contact(leg, pose, impact, stiffness, base, ELASTIC_STEPS)?;
    let limits = leg.effective_mass(pose, impact, AnkleJoint::Free)?;
    let interpolated = |contact_time| leg.effective_mass(pose, impact, AnkleJoint::Elastic { stiffness, contact_time });
    if coupled.locked_limit {
        let equivalent_mass = limits.locked_ankle;
        let outcome = exit_outcome(equivalent_mass, base)?;
        return Ok(ElasticAnkle { equivalent_mass, coupled, outcome, interpolated: interpolated(coupled.contact_time)? });
    }
    let mut failure = None;
    let mut miss = |m: f64| match exit_outcome(m, base) {
        Ok(o) => o.v_ball_out - coupled.v_ball_out,
        Err(e) => {
            failure = Some(e);
            f64::NAN
        }
    };
    // The spring can return energy and beat the locked ankle a little, so
    // bracket well beyond both limits.
    let (low, high) = (0.5 * limits.free_ankle, 4.0 * limits.locked_ankle);
    let root = roots::brent(&mut miss, low, high, 1e-12 * limits.locked_ankle, 200);
    if let Some(e) = failure {
        return Err(e);
    }
    let equivalent_mass = root
        .ok_or_else(|| {
            LegError::Degenerate(format!(
                "no foot mass in [{}, {}] kg gives the 1D model the coupled exit speed {} m/s",
                kick_core::short(low),
                kick_core::short(high),
                kick_core::short(coupled.v_ball_out)
            ))
        })?
        .x;
    Ok(ElasticAnkle {
        equivalent_mass,
        coupled,
        outcome: exit_outcome(equivalent_mass, base)?,
        interpolated: interpolated(coupled.contact_time)?,
    })
}
