//! The tangential contact law, one place for every path (issue 31, item 4).
//!
//! **The element.** A spring k_t, the shell's own tangential compliance, in
//! series with a Coulomb slider capped at μ F_n; no viscous term. ξ is the
//! spring's stretch: how far the ball's rigid material point at the contact
//! has moved over the foot while the ball's surface in contact (the *contact
//! point*) stayed put. The contact points' relative velocity is the slider's,
//! v_s = v_t − ξ̇, with v_t the tangential velocity of the ball's material
//! point at the contact less the foot's. The states are named by what the
//! contact points do:
//! - **grip**: v_s = 0. The spring takes the sliding, ξ̇ = v_t, and carries
//!   F_t = −k_t ξ, while k_t |ξ| ≤ μ F_n;
//! - **slip**: the slider moves, F_t = −μ F_n ŝ with ŝ = ξ/|ξ|, and the spring
//!   stays on the cap, |ξ| = μ F_n / k_t. Its speed along ŝ is
//!   λ = ŝ · v_t − (d(μ F_n)/dt)/k_t ≥ 0, and ξ̇ = v_t − λ ŝ.
//!
//! Grip ends when the spring reaches the cap (μ F_n − k_t |ξ| falls through
//! zero); slip ends when slipping has brought the contact points' relative
//! velocity to zero (λ falls through zero: the grip–slip picture of Cross,
//! Am. J. Phys. 70, 1093 (2002): the ball grips when the bottom of the ball
//! comes to rest on the surface, and its contact region's deformation then
//! lets it vibrate tangentially, so the friction force can reverse). With a
//! finite k_t the force is continuous through every switch and at first
//! touch (rigid grip at μ = ∞ is the exception: **The limits** below): ξ
//! starts at zero, so the tangential force rises from zero, and an element
//! that starts in slip starts from the cap's own value. Nothing in the law
//! depends on a velocity alone.
//!
//! At first touch (ξ = 0) the element grips when the cap exceeds zero (a law
//! whose force jumps at touch, as the paper's Eq. 20 does by c V_n) or, with
//! the cap starting from zero, when it grows faster than the spring would
//! load, d(μ F_n)/dt ≥ k_t |v_t| (the criterion of Maw, Barber & Fawcett
//! (1976) for an elastic sphere that sticks from first touch); otherwise it
//! slips, along v_t.
//!
//! **Loss.** Only the slider's, μ F_n λ ≥ 0 (the power taken out of the
//! motion; the spring's energy ½ k_t |ξ|² is elastic and part of the
//! energy partition). The gripping spring is elastic: its tangential
//! vibration (Cross's reversal of the friction force) is damped only by
//! slipping. A dashpot beside the spring would put back a force c_t v_t the
//! instant the slider holds, whatever the sliding speed, which is the
//! artefact this law replaces; no measurement of a ball's tangential damping
//! was found to give it another form.
//!
//! **The slider's direction.** In three dimensions the spring turns towards
//! the sliding: ŝ turns at k_t |v_t⊥| / (μ F_n), which grows without bound
//! as μ F_n → 0 at separation (and at first touch), where the spring is
//! shorter than any step could resolve. Below a stretch of
//! [`RELAXATION_LENGTH`] the spring turns as if it were that long:
//! ξ̇ = v_t⊥ w + (d(μ F_n)/dt/k_t) ŝ with w = min(1, |ξ|/ℓ). It changes the
//! law only where |F_t| < k_t ℓ (0.1 N at the default k_t, against ~1.5 kN
//! at the peak) and only in a kick that leaves one plane (in a plane ŝ never
//! turns); it keeps the loss a square (the perpendicular part does no work).
//!
//! **The limits.** k_t = ∞ (rigid grip, [`crate::contact`]): grip is the
//! constraint v_t = 0; slip carries μ F_n against the sliding until the
//! sliding reverses (λ = ŝ · v_t when k_t = ∞); μ = ∞ on top of it stops the
//! sliding at first touch by an impulse, the instant slip that the limit
//! μ → ∞ of that slip is, its energy lost. μ = ∞ with a finite spring grips
//! from first touch and stays elastic. μ = 0: no slider, no force.

use parry3d_f64::math::Vec3;

/// The shortest stretch whose turning the slider follows at the exact rate,
/// m (module docs): a micrometre, below which the direction of sliding of
/// real surfaces is not defined either (their roughness).
pub const RELAXATION_LENGTH: f64 = 1e-6;

/// Where a slip ends in grip, the spring is put on the cap a hair inside it,
/// k_t |ξ| = μ F_n (1 − this): the grip's margin μ F_n − k_t |ξ| starts
/// there from zero with zero slope (a tangency), and a start in its own
/// rounding would be found again as a switch back to slip. The stretch
/// moves by this share (its energy by twice it), far below any tolerance.
pub const GRIP_ENTRY: f64 = 1e-12;

/// What the element gives at one state: the force on the ball (tangential),
/// ξ̇ (without the frame's or the normal's turning), the phase's switch
/// function, the power the slider takes out of the motion, and the contact
/// points' relative velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Response {
    pub force: Vec3,
    pub spring_rate: Vec3,
    /// Grip: μ F_n − k_t |ξ| (held while ≥ 0; +1 when μ = ∞). Slip: −k_t λ
    /// (held while < 0).
    pub margin: f64,
    pub power: f64,
    pub slip_velocity: Vec3,
}

/// Grip: the spring carries −k_t ξ and takes the sliding.
#[inline(always)]
pub fn grip(stiffness: f64, spring: Vec3, sliding: Vec3, cap: f64) -> Response {
    let force = spring * -stiffness;
    let margin = if cap.is_infinite() { 1.0 } else { cap - stiffness * spring.length() };
    Response { force, spring_rate: sliding, margin, power: 0.0, slip_velocity: Vec3::ZERO }
}

/// The slider's direction: along the spring, or along the sliding while the
/// spring is relaxed (first touch).
#[inline(always)]
pub fn slip_direction(spring: Vec3, sliding: Vec3) -> Vec3 {
    let size = spring.length();
    if size > 0.0 {
        spring * (1.0 / size)
    } else {
        sliding.normalize_or_zero()
    }
}

/// Slip along `direction` ([`slip_direction`]) under the cap μ F_n and its
/// rate d(μ F_n)/dt.
#[inline(always)]
pub fn slip(stiffness: f64, direction: Vec3, sliding: Vec3, cap: f64, cap_rate: f64) -> Response {
    let along = direction.dot(sliding);
    let speed = along - cap_rate / stiffness; // λ
    let across = sliding - direction * along;
    // |ξ| = cap/k_t: the turning rate's floor (RELAXATION_LENGTH).
    let weight = (cap / (stiffness * RELAXATION_LENGTH)).min(1.0);
    Response {
        force: direction * -cap,
        spring_rate: direction * (cap_rate / stiffness) + across * weight,
        margin: -stiffness * speed,
        power: cap * speed,
        slip_velocity: direction * speed + across * (1.0 - weight),
    }
}

/// The rate of a state that holds the slider's direction at a length of
/// its own, `length` (a slip's spring length μ F_n / k_t being a function of
/// the normal force), growing at `length_rate`: it turns as the spring of
/// [`slip`] does, at |v_t⊥| / max(μ F_n / k_t, ℓ). From zero it grows along
/// the sliding ([`slip_direction`]).
#[inline(always)]
pub fn direction_rate(stiffness: f64, state: Vec3, sliding: Vec3, cap: f64, length_rate: f64) -> Vec3 {
    let size = state.length();
    let direction = slip_direction(state, sliding);
    let across = sliding - direction * direction.dot(sliding);
    across * (size / (cap / stiffness).max(RELAXATION_LENGTH)) + direction * length_rate
}

/// No slider (μ = 0), or no normal force to cap it (a clamped law): no
/// force, the spring left as it is, the contact points sliding freely.
#[inline(always)]
pub fn free(sliding: Vec3) -> Response {
    Response { force: Vec3::ZERO, spring_rate: Vec3::ZERO, margin: 0.0, power: 0.0, slip_velocity: sliding }
}

/// Whether the element starts in slip at first touch (ξ = 0): the cap starts
/// at zero and grows slower than the spring would load (module docs).
#[inline]
pub fn slips_at_touch(stiffness: f64, sliding: Vec3, cap: f64, cap_rate: f64) -> bool {
    cap == 0.0 && sliding != Vec3::ZERO && stiffness * sliding.length() > cap_rate
}

/// One step Δt of the element as a fixed-step scene advances it (the
/// return map of Cundall and Strack, first order, stable at any step):
/// the spring (already turned with the foot and the normal) takes v_t Δt
/// and is brought back onto the cap when it overshoots. Returns the new
/// stretch, whether it slipped, and the slider's travel |Δ| (its loss is
/// μ F_n |Δ|).
pub fn return_map(stiffness: f64, spring: Vec3, sliding: Vec3, cap: f64, dt: f64) -> (Vec3, bool, f64) {
    let trial = spring + sliding * dt;
    let size = trial.length();
    if cap.is_infinite() || stiffness * size <= cap {
        return (trial, false, 0.0);
    }
    let kept = trial * (cap / (stiffness * size));
    (kept, true, (trial - kept).length())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Slip: the spring's stretch grows at the cap's rate along ŝ and turns
    /// with the sliding across it; the slider's velocity v_t − ξ̇ is λ ŝ, and
    /// the power it takes is μ F_n λ = the work on the motion less the
    /// spring's gain.
    #[test]
    fn slip_splits_the_sliding_between_spring_and_slider() {
        let (k_t, cap, cap_rate) = (1e5, 800.0, 3e5);
        let s = Vec3::new(0.0, 0.6, 0.8);
        let v = Vec3::new(0.0, 7.0, -2.0);
        let r = slip(k_t, s, v, cap, cap_rate);
        let lambda = s.dot(v) - cap_rate / k_t;
        assert!((r.slip_velocity - s * lambda).length() <= 1e-15 * v.length());
        assert!((v - r.spring_rate - r.slip_velocity).length() <= 1e-15 * v.length());
        assert_eq!(r.force, s * -cap);
        // Work of F_t on the motion, −F_t·v, is the slider's loss plus the spring's gain cap·ċap/k_t.
        let work = -r.force.dot(v);
        assert!((work - (r.power + cap * cap_rate / k_t)).abs() <= 1e-12 * work.abs());
        assert!((r.margin + k_t * lambda).abs() <= 1e-12 * k_t * lambda.abs());
    }

    /// Below the relaxation length the spring turns at the rate of a spring of
    /// that length; the slider then also moves across ŝ, where its force does
    /// no work.
    #[test]
    fn a_spring_shorter_than_the_relaxation_length_turns_at_its_rate() {
        let k_t = 1e5;
        let cap = 0.25 * k_t * RELAXATION_LENGTH;
        let s = Vec3::Y;
        let v = Vec3::new(0.0, 3.0, 4.0);
        let r = slip(k_t, s, v, cap, 0.0);
        assert_eq!(r.spring_rate, Vec3::new(0.0, 0.0, 1.0));
        assert_eq!(r.slip_velocity, Vec3::new(0.0, 3.0, 3.0));
        assert_eq!(r.power, cap * 3.0);
    }

    /// The return map keeps the spring within the cap and slips only beyond it.
    #[test]
    fn the_return_map_caps_the_spring() {
        let (k_t, dt) = (1e5, 1e-6);
        let (held, slipped, travel) = return_map(k_t, Vec3::new(0.0, 1e-3, 0.0), Vec3::new(0.0, 10.0, 0.0), 200.0, dt);
        assert!(!slipped && travel == 0.0 && (held.y - 1.01e-3).abs() < 1e-15);
        let (kept, slipped, travel) = return_map(k_t, Vec3::new(0.0, 1e-3, 0.0), Vec3::new(0.0, 10.0, 0.0), 50.0, dt);
        assert!(slipped && (kept.length() * k_t - 50.0).abs() < 1e-9 && (travel - (1.01e-3 - 5e-4)).abs() < 1e-15);
    }
}
