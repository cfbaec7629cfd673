//! The shell ball behind a boot by Taylor series: the `series` and `auto`
//! path of a booted shell kick (drive ≥ 0), as [`crate::shell_series`] is
//! of the bare one.
//!
//! With δ the approach, b = δ_b the layer's compression and β = δ − b the
//! ball's, the motion is μ δ̈ = f_s − F with F = E(β) + s A(β) β̇ on the
//! ball's side (s the shell's damping, A the patch area) and
//! F = k_b b + c_b ḃ on the layer's. In Taylor coefficients (d_k, b_k,
//! β_k = d_k − b_k, E_k and A_k from [`crate::shell_series::ElasticJet`]
//! on β) the balance at order k holds b_(k+1) once, in the s A_0 β̇ term, so
//!
//!     (k+1) b_(k+1) (c_b + s A_0) = E_k + s Σ_(i=1..k) A_i (k−i+1) β_(k−i+1)
//!                                    + s A_0 (k+1) d_(k+1) − k_b b_k,
//!
//! then F_k = k_b b_k + c_b (k+1) b_(k+1) and d_(k+2) = (f_s δ_k0 − F_k)/(μ (k+1)(k+2)).
//! c_b > 0 keeps the divisor away from zero at first touch (A_0 = 0).
//! Events are roots of the step's polynomials: β̇ = 0 (the ball's maximum
//! compression), dF/dt = 0, β = 0 (separation). The energy
//! ½ μ δ̇² + U(β) + ½ k_b b² − f_s δ only falls (both dashpots take power),
//! and at separation (β = 0) it is at least −f_s²/(2 k_b): below that the
//! ball is proven trapped. The step is the largest whose last terms of δ and
//! of b stay below the tolerance in the scenario's units.
//!
//! The clamp F ≥ 0 (E + s A β̇ ≤ 0 while the ball is compressed) is not continued by series: a step that
//! would start there returns [`KickError::NotApplicable`], and `auto` takes
//! the engine ([`super::solve`]).

use super::{BootedOde, BootedState};
use crate::events::proves_trapped;
use crate::events::ContactSystem;
use crate::ode::Extremes;
use crate::reduced::{separated, RelativeState};
use crate::shell_series::{derivative, first_fall, integral, poly, reaches_clamp, step_extremes, ElasticJet, INVERSE, K};
use kick_core::{Boot, ContactLaw, KickError, Outcome, Scenario, ShellBall, SolverPath};

/// The step's last terms of δ and b are held to BOOTED_STEP_SCALE ×
/// tolerance × L. The layer's equation divides by c_b + s A(β), which
/// vanishes at a β < 0 just before touch: each step reaches only a share of
/// the distance to that singular time, so from touch the steps grow
/// geometrically and most of a contact's steps are spent near its start.
/// Measured worst error against the engine at 1e-14 over the test's box
/// (`tests/solvers/boot.rs`, 297 kicks): 2.37e-12 with the bare series'
/// scale (1e-5, 23.2 steps per kick of the 1D sweep with `--leg`), 3.44e-12
/// with 1e-4 (20.7 steps), 1.20e-11 with 1e-3 (chosen: 18.5 steps, the
/// documented 1e-10 with a margin of 8).
const BOOTED_STEP_SCALE: f64 = 1e-3;

/// Bound on steps in one contact (typical: 20 to 40).
pub const MAX_STEPS: u32 = 20_000;

/// True when this path solves the scenario: a boot, the shell ball and a
/// drive that pushes the foot on (or none).
pub fn applies(scenario: &Scenario) -> bool {
    scenario.boot().is_some() && crate::shell_series::applies(scenario)
}

/// One step's coefficients: δ, b and β to t^K, the force and the loss
/// power to t^(K−2).
struct Step {
    delta: [f64; K + 1],
    boot: [f64; K + 1],
    ball: [f64; K + 1],
    force: [f64; K - 1],
    dissipation: [f64; K - 1],
}

fn step(ball: &ShellBall, boot: &Boot, mu: f64, drive_share: f64, state: (f64, f64, f64)) -> Result<Step, KickError> {
    let (delta0, rate0, boot0) = state;
    let damping = ball.shell_damping;
    let (kb, cb) = (boot.stiffness, boot.damping);
    let (mut d, mut b, mut beta) = ([0.0; K + 1], [0.0; K + 1], [0.0; K + 1]);
    // β's rate coefficients (k+1) β_(k+1) and the layer's (k+1) b_(k+1).
    let (mut ball_rate, mut boot_rate) = ([0.0; K], [0.0; K]);
    let mut force = [0.0; K - 1];
    d[0] = delta0;
    d[1] = rate0;
    b[0] = boot0;
    beta[0] = delta0 - boot0;
    let mut jet = ElasticJet::new(ball, beta[0])?;
    // 1/(c_b + s A_0), set at order 0 (A_0 is known there); reciprocals
    // in place of divisions on the order-by-order chain, which is latency-bound.
    let (mut a0, mut divisor) = (0.0, 0.0);
    let inverse_mu = 1.0 / mu;
    let mut a_rate = [0.0; K];
    // To order K − 1 for b (its step criterion takes b_K), to K − 2 for the force.
    for k in 0..K {
        jet.next(k, &beta);
        let (e, a) = (jet.elastic(), jet.area());
        if k == 0 {
            a0 = a[0];
            divisor = 1.0 / (cb + damping * a0);
        }
        // The Cauchy product A β̇ at order k without its i = 0 term (β̇_k is still unknown).
        let cross: f64 = (1..=k).map(|i| a[i] * ball_rate[k - i]).sum();
        let kk = (k + 1) as f64;
        let numerator = e[k] + damping * cross + damping * a0 * kk * d[k + 1] - kb * b[k];
        boot_rate[k] = numerator * divisor;
        b[k + 1] = boot_rate[k] * INVERSE[k + 1];
        beta[k + 1] = d[k + 1] - b[k + 1];
        ball_rate[k] = kk * beta[k + 1];
        a_rate[k] = cross + a0 * ball_rate[k];
        if k + 2 <= K {
            force[k] = kb * b[k] + cb * boot_rate[k];
            let drive = if k == 0 { drive_share } else { 0.0 };
            d[k + 2] = (drive - force[k]) * inverse_mu * INVERSE[k + 1] * INVERSE[k + 2];
        }
    }
    // s A β̇² + c_b ḃ², by Cauchy products of A β̇ with β̇ and of ḃ with itself.
    let mut dissipation = [0.0; K - 1];
    for (k, slot) in dissipation.iter_mut().enumerate() {
        let ball_loss: f64 = (0..=k).map(|i| a_rate[i] * ball_rate[k - i]).sum();
        let boot_loss: f64 = (0..=k).map(|i| boot_rate[i] * boot_rate[k - i]).sum();
        *slot = damping * ball_loss + cb * boot_loss;
    }
    Ok(Step { delta: d, boot: b, ball: beta, force, dissipation })
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
    let (mut t, mut delta, mut rate, mut layer, mut dissipated) = (0.0, 0.0, v0, 0.0, 0.0);
    let mut extremes = Extremes::new(0.0);
    let mut steps = 0u32;
    let trap_floor = drive_share * drive_share / (2.0 * boot.stiffness);
    loop {
        steps += 1;
        if steps > MAX_STEPS {
            return Err(KickError::Integration {
                time: t,
                reason: format!("the booted series took more than {MAX_STEPS} steps without separation"),
            });
        }
        let s = step(&ball, &boot, mu, drive_share, (delta, rate, layer))?;
        // The clamp: the force at the step's start, with the ball compressed.
        if s.ball[0] > 0.0 && s.force[0] <= 0.0 {
            return Err(KickError::NotApplicable {
                solver: "series",
                reason: "the ball's force reached its clamp at zero (E + s A dδ_B/dt <= 0)",
            });
        }
        // The larger of δ's and b's last terms sets each order's bound (one root per order).
        let size = |c: f64, k: usize| (BOOTED_STEP_SCALE * tolerance * length / c).powf(1.0 / k as f64);
        let mut h = size(s.delta[K].abs().max(s.boot[K].abs()), K)
            .min(size(s.delta[K - 1].abs().max(s.boot[K - 1].abs()), K - 1))
            .min(100.0 * time_unit);
        if !(h.is_finite() && h > 0.0) {
            return Err(KickError::Integration { time: t, reason: format!("the booted series found no step at δ = {delta} m") });
        }
        let ball_poly = &s.ball[..];
        // Separation: β falls through 0 while receding.
        let separates = if s.ball[1] < 0.0 || derivative(ball_poly, h) < 0.0 { first_fall(|x| poly(ball_poly, x), h) } else { None };
        if let Some(end) = separates {
            h = end;
        }
        // The clamp within the step (module docs): F > 0 wherever β > 0, sampled as the bare series does.
        if reaches_clamp(ball_poly, &s.force, h, length) {
            return Err(KickError::NotApplicable {
                solver: "series",
                reason: "the ball's force reaches its clamp at zero (E + s A dδ_B/dt <= 0)",
            });
        }
        step_extremes(ball_poly, &s.force, t, h, &mut extremes);
        dissipated += integral(&s.dissipation, h);
        t += h;
        rate = derivative(&s.delta, h);
        delta = poly(&s.delta, h);
        layer = poly(&s.boot, h);
        if separates.is_some() {
            break;
        }
        // Without a drive the energy stays ≥ 0: only a drive can trap.
        if drive_share == 0.0 {
            continue;
        }
        let ball_compression = delta - layer;
        let stored = ball.potential(ball_compression) + boot.potential(layer);
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
    let energy = BootedOde::new(scenario, ball, boot).budget(scenario, t, &BootedState::new(delta, rate, layer, dissipated));
    separated(scenario, t, &RelativeState::new(delta, rate, dissipated), extremes, energy, u64::from(steps), SolverPath::Series)
}
