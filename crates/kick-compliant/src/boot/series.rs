//! The shell ball behind a boot by Taylor series: the `series` and `auto`
//! path of a booted shell kick (drive ≥ 0), as [`crate::shell_series`] is
//! of the bare one.
//!
//! With δ the approach, v = δ̇, b = δ_b the layer's compression and
//! β = δ − b the ball's, the motion is μ v̇ = f_s − F with F = E(β) + s A(β) β̇
//! on the ball's side (s the shell's damping, A the patch area) and
//! F = k_b b + c_b ḃ on the layer's. Their balance gives
//! ḃ = (E + s A v − k_b b)/D with D = c_b + s A(β), which vanishes at a
//! β < 0 just before touch: in time t the solution's radius of convergence
//! is the distance to that singular time, so Taylor steps in t start tiny
//! at touch and grow geometrically. The steps are taken in σ instead,
//! dt = D dσ (a Sundman transform), where the motion has no divisor:
//!
//!     dβ/dσ = c_b v + k_b b − E,     db/dσ = E + s A v − k_b b,
//!     μ dv/dσ = f_s D − N,           dt/dσ = D,
//!
//! N = D F = c_b E + s A (k_b b + c_b v), and the loss power P = s A β̇² + c_b ḃ²
//! has D P = (E − k_b b)² + c_b s A v² (the 1/D of each term cancels in the
//! sum). Every right-hand side is a polynomial in β, b, v and the shell's
//! E and A, so the coefficients come order by order from
//! [`crate::shell_series::ElasticJet`] on β and Cauchy products, and σ's
//! steps are as long as the shell's own: no singular time near touch.
//! D ≥ c_b > 0 wherever β ≥ 0, so σ grows with t: events are roots of the
//! step's polynomials in σ, β = 0 receding (separation), dβ/dσ = 0 (the
//! ball's maximum compression), d(N/D)/dσ = 0 ⇔ N' D − N D' = 0 (the force
//! peak), with F = N/D and t from t(σ) where they fall.
//! The energy ½ μ v² + U(β) + ½ k_b b² − f_s δ only falls (both dashpots
//! take power), and at separation (β = 0) it is at least −f_s²/(2 k_b):
//! below that the ball is proven trapped. The step is the largest whose
//! last terms of β, b, v and t stay below the tolerance in the scenario's
//! units.
//!
//! The clamp F ≥ 0 (E + s A β̇ ≤ 0 while the ball is compressed) is not
//! continued by series: a step that would start there, or reach it at its
//! sample points, or separate with the ball receding faster than
//! (p0 + k_s/(2πR))/s (the force then crossed zero just before β = 0,
//! [`crate::shell_series::separates_past_clamp`]), returns
//! [`KickError::NotApplicable`], and `auto` takes the engine
//! ([`super::solve`]).

use super::{BootedOde, BootedState};
use crate::events::proves_trapped;
use crate::events::ContactSystem;
use crate::ode::Extremes;
use crate::relative::{separated, RelativeState};
use crate::shell_series::{
    derivative, extremes_along, first_fall, integral, poly, reaches_clamp, separates_past_clamp, ElasticJet, INVERSE, K,
};
use kick_core::{Boot, ContactLaw, KickError, Outcome, Scenario, ShellBall, SolverPath};

/// The step's last terms of β, b, v T and t V0 are held to
/// BOOTED_STEP_SCALE × tolerance × L (T, L the scenario's time and length).
/// Measured worst error against the engine at 1e-14 over the test's box
/// (`tests/solvers/boot.rs`, 268 kicks, shell losses up to 2x the FIFA
/// one): 1.4e-12 with 1e-3 (chosen: 11.9 steps per kick of the 1D sweep
/// with `--leg`, the documented 1e-10 with a margin of 70); with the force
/// peak found on N and D themselves, 4.4e-14 with the bare series' 1e-5
/// (14.9 steps), 1.9e-13 with 1e-4 (13.4), 2.5e-12 with 1e-3, 1.6e-11 with
/// 3e-3 (11.4). In t, before σ, 1e-3 took 18.5 steps.
const BOOTED_STEP_SCALE: f64 = 1e-3;

/// Bound on steps in one contact (typical: 10 to 20).
pub const MAX_STEPS: u32 = 20_000;

/// True when this path solves the scenario: a boot, the shell ball and a
/// drive that pushes the foot on (or none).
pub fn applies(scenario: &Scenario) -> bool {
    scenario.boot().is_some() && crate::shell_series::applies(scenario)
}

/// One step's coefficients in σ from its start (module docs): β, b, v and
/// t − t_start to σ^K; N = D F and D to σ^(K−1); D P and N' D − N D' (the
/// sign of dF/dσ) to σ^(K−2). Filled in place, step after step.
struct Step {
    ball: [f64; K + 1],
    boot: [f64; K + 1],
    rate: [f64; K + 1],
    time: [f64; K + 1],
    force: [f64; K],
    divisor: [f64; K],
    dissipation: [f64; K - 1],
    force_turn: [f64; K - 1],
    jet: ElasticJet,
}

impl Step {
    fn new(ball: &ShellBall) -> Result<Step, KickError> {
        Ok(Step {
            ball: [0.0; K + 1],
            boot: [0.0; K + 1],
            rate: [0.0; K + 1],
            time: [0.0; K + 1],
            force: [0.0; K],
            divisor: [0.0; K],
            dissipation: [0.0; K - 1],
            force_turn: [0.0; K - 1],
            jet: ElasticJet::new(ball, 0.0)?,
        })
    }

    /// The coefficients from (β, v, b) at the step's start.
    fn expand(&mut self, ball: &ShellBall, boot: &Boot, mu: f64, drive_share: f64, state: (f64, f64, f64)) -> Result<(), KickError> {
        let Step { ball: beta, boot: b, rate: v, time, force, divisor, dissipation, force_turn, jet } = self;
        let s = ball.shell_damping;
        let (kb, cb) = (boot.stiffness, boot.damping);
        // A v and E − k_b b, for the products of the loss power; N' and D'.
        let (mut area_rate, mut relaxing) = ([0.0; K], [0.0; K]);
        let (mut force_rate, mut divisor_rate) = ([0.0; K - 1], [0.0; K - 1]);
        (beta[0], v[0], b[0]) = state;
        jet.restart(ball, beta[0])?;
        let inverse_mu = 1.0 / mu;
        for k in 0..K {
            jet.next(k, &beta[..]);
            let (e, a) = (jet.elastic()[k], jet.area());
            let (mut av, mut ab) = (0.0, 0.0);
            for i in 0..k + 1 {
                av += a[i] * v[k - i];
                ab += a[i] * b[k - i];
            }
            let d = s * a[k] + if k == 0 { cb } else { 0.0 };
            let n = cb * e + s * (kb * ab + cb * av);
            let inverse = INVERSE[k + 1];
            beta[k + 1] = (cb * v[k] + kb * b[k] - e) * inverse;
            b[k + 1] = (e + s * av - kb * b[k]) * inverse;
            v[k + 1] = (drive_share * d - n) * inverse_mu * inverse;
            time[k + 1] = d * inverse;
            (force[k], divisor[k], area_rate[k], relaxing[k]) = (n, d, av, e - kb * b[k]);
            if k > 0 {
                (force_rate[k - 1], divisor_rate[k - 1]) = (k as f64 * n, k as f64 * d);
            }
        }
        for k in 0..K - 1 {
            let (mut layer, mut shell, mut turn) = (0.0, 0.0, 0.0);
            for i in 0..k + 1 {
                layer += relaxing[i] * relaxing[k - i];
                shell += area_rate[i] * v[k - i];
                turn += force_rate[i] * divisor[k - i] - force[i] * divisor_rate[k - i];
            }
            dissipation[k] = layer + cb * s * shell;
            force_turn[k] = turn;
        }
        Ok(())
    }
}

/// The booted contact of `scenario` with `ball` (module docs); `tolerance`
/// is the local error per step in the scenario's units.
pub fn solve(scenario: &Scenario, ball: ShellBall, boot: Boot, tolerance: f64) -> Result<Outcome, KickError> {
    let mu = scenario.reduced_mass();
    let v0 = scenario.approach_speed();
    let drive_share = mu / scenario.effective_foot_mass() * scenario.drive_force();
    // The series stiffness at touch sets the time and length units.
    let k0 = ball.small_compression_stiffness();
    let time_unit = (mu * (1.0 / k0 + 1.0 / boot.stiffness)).sqrt();
    let length = v0 * time_unit;
    let (mut t, mut compression, mut rate, mut layer, mut dissipated) = (0.0, 0.0, v0, 0.0, 0.0);
    let mut extremes = Extremes::new(0.0);
    let mut steps = 0u32;
    let trap_floor = drive_share * drive_share / (2.0 * boot.stiffness);
    let mut s = Step::new(&ball)?;
    loop {
        steps += 1;
        if steps > MAX_STEPS {
            return Err(KickError::Integration {
                time: t,
                reason: format!("the booted series took more than {MAX_STEPS} steps without separation"),
            });
        }
        s.expand(&ball, &boot, mu, drive_share, (compression, rate, layer))?;
        // The clamp: the force at the step's start, with the ball compressed.
        if s.ball[0] > 0.0 && s.force[0] <= 0.0 {
            return Err(KickError::NotApplicable {
                solver: "series",
                reason: "the ball's force reached its clamp at zero (E + s A dδ_B/dt <= 0)",
            });
        }
        // Each order's bound from the largest of its last terms in lengths (one root per order).
        let last = |k: usize| s.ball[k].abs().max(s.boot[k].abs()).max(time_unit * s.rate[k].abs()).max(v0 * s.time[k].abs());
        let size = |k: usize| (BOOTED_STEP_SCALE * tolerance * length / last(k)).powf(1.0 / k as f64);
        // σ's unit is time per N s/m, and D ≥ c_b: the cap is 100 T in time at most.
        let mut h = size(K).min(size(K - 1)).min(100.0 * time_unit / boot.damping);
        if !(h.is_finite() && h > 0.0) {
            return Err(KickError::Integration { time: t, reason: format!("the booted series found no step at δ_B = {compression} m") });
        }
        let ball_poly = &s.ball[..];
        // Separation: β falls through 0 while receding.
        let separates = if s.ball[1] < 0.0 || derivative(ball_poly, h) < 0.0 { first_fall(|x| poly(ball_poly, x), h) } else { None };
        if let Some(end) = separates {
            h = end;
        }
        // The clamp within the step (module docs): N = D F > 0 wherever β > 0, sampled as the bare series does,
        // and exactly at separation (β̇ = dβ/dσ / D).
        if reaches_clamp(ball_poly, &s.force, h, length)
            || separates.is_some_and(|_| separates_past_clamp(&ball, derivative(ball_poly, h) / poly(&s.divisor, h)))
        {
            return Err(KickError::NotApplicable {
                solver: "series",
                reason: "the ball's force reaches its clamp at zero (E + s A dδ_B/dt <= 0)",
            });
        }
        // F = N/D; dF/dσ has the sign of N' D − N D'.
        extremes_along(
            h,
            |x| t + poly(&s.time, x),
            (|x| poly(ball_poly, x), |x| derivative(ball_poly, x)),
            (|x| poly(&s.force, x) / poly(&s.divisor, x), |x| poly(&s.force_turn, x)),
            &mut extremes,
        );
        dissipated += integral(&s.dissipation, h);
        t += poly(&s.time, h);
        rate = poly(&s.rate, h);
        compression = if separates.is_some() { 0.0 } else { poly(ball_poly, h) };
        layer = poly(&s.boot, h);
        if separates.is_some() {
            break;
        }
        // Without a drive the energy stays ≥ 0: only a drive can trap.
        if drive_share == 0.0 {
            continue;
        }
        let delta = compression + layer;
        let stored = ball.potential(compression) + boot.potential(layer);
        let energy = 0.5 * mu * rate * rate + stored - drive_share * delta;
        if proves_trapped(-(energy + trap_floor), stored.max(drive_share * delta)) {
            return Err(KickError::Trapped {
                time: t,
                reason: "½μδ̇² + U(δ_B) + ½k_b δ_b² − (μ/m_f)F_drive δ fell below −f²/(2 k_b), its least value at separation \
                         (the drive keeps the ball pressed)"
                    .into(),
            });
        }
    }
    let delta = compression + layer;
    let energy = BootedOde::new(scenario, ball, boot).budget(scenario, t, &BootedState::new(delta, rate, layer, dissipated));
    separated(scenario, t, &RelativeState::new(delta, rate, dissipated), extremes, energy, u64::from(steps), SolverPath::Series)
}
