//! The shell ball (law `shell`, [`kick_core::ShellBall`]) by Taylor series,
//! compression and return alike: the `series` path for that law.
//!
//! Eq. 18 with the shell law reads μ δ̈ = f_s − F_el(δ) − β A(δ) δ̇, with
//! f_s = (μ/m_f) F_drive, F_el = (P(δ) − p_atm) A(δ) + k_s δ,
//! P = (p0 + p_atm)(1 − c)^(−γ) and c = δ²(3R − δ)/(4R³) the share of the
//! volume the cap takes. Unlike the paper's δⁿ, every factor is analytic at
//! δ = 0 (F_el ≈ 2πR p0 δ), so plain Taylor steps run from first touch to
//! separation, with no onset expansion and no energy-integral return (the
//! loss acts on both branches).
//!
//! - Coefficients: the recurrences of power-series arithmetic, order by
//!   order: Cauchy products for δ², δ³, P·A and A δ̇; the power
//!   (1 − c)^(−γ) by J. C. P. Miller's recurrence (as for δⁿ in
//!   [`crate::series`]), seeded with one `exp`/`ln_1p` per step; δ̈ from the
//!   force. O(K²) per step, no allocation.
//! - Step: the largest whose last two terms stay below the tolerance in the
//!   scenario's units (length V0·√(μ/k0), k0 = 2πR p0 + k_s).
//! - Events are roots of the step's polynomials, found by Brent's method on
//!   them: δ̇ = 0 (maximum compression), dF/dt = 0 (the force peak, which the
//!   rate-dependent loss moves before δ_max), δ = 0 (separation).
//! - The clamp F ≥ 0 engages only on a rebound faster than
//!   (F_el/A)/β ≥ p0/β (22 m/s for the default ball at 0.8 bar): the series
//!   checks F > 0 at its sample points while δ > 0, and a contact that
//!   reaches the clamp is `NotApplicable` here (`auto` then takes
//!   `reduced`, which treats the clamp as a switch). A negative drive is
//!   left to `reduced` too ([`applies`]).
//! - Trapping: E = ½ μ δ̇² + U(δ) − f_s δ falls whenever the force acts
//!   (dE/dt = −β A δ̇² ≤ 0) and is ½ μ δ̇² ≥ 0 at δ = 0, so E < 0 proves
//!   the ball cannot leave (`Trapped`); it also bounds a creep towards the
//!   drive's equilibrium, where E < 0.
//! - The dissipated energy ∫ β A δ̇² dt is integrated along the series
//!   (its own Cauchy product), so the energy balance is a check, not an input.
//!
//! Accuracy: at [`crate::series::DEFAULT_TOLERANCE`] every observable is
//! within 1e-10 relative of `reduced` and `accurate` at 1e-14 over the
//! sweep's box with Law 2's pressures and up to 4x the calibrated loss
//! (measured worst 1.2e-12 over 340 contacts; 59 of 400 reach the clamp and
//! go to `reduced`), restitution is the Hunt–Crossley relation of the law's
//! small-compression limit, and energy is conserved with the loss off
//! (`tests/solvers/shell_series.rs`).

use crate::events::proves_trapped;
use crate::events::ContactSystem;
use crate::ode::Extremes;
use crate::relative::{separated, RelativeOde, RelativeState};
use kick_core::{roots, ContactLaw, KickError, Outcome, Scenario, ShellBall, SolverPath};

/// Order K of the Taylor steps (δ to t^K).
pub const ORDER: usize = 20;
/// Bound on steps in one contact (typical: 10 to 30).
pub const MAX_STEPS: u32 = 20_000;
/// The step's last terms of δ are held to STEP_SCALE × tolerance × L: the
/// shared `series` tolerance was set for the paper law's δ̇, and here the
/// peak force and δ̇, derivatives of the step's polynomial, come out larger
/// than δ's own error. Measured worst error over the sweep's box against
/// `reduced` at 1e-14 at the default tolerance, with the loss F_el (1 + χ δ̇)
/// the law had until the loss moved into the shell: 1.7e-10 with 1, 6.6e-11
/// with 1e-3, 3.5e-12 with 1e-4 (chosen: 1.6x the steps of 1); with the
/// shell's loss β A δ̇, 3.1e-11 with 1e-4 and 1.2e-12 with 1e-5 (chosen: the
/// documented 1e-10 with a margin of 80, at (10)^(1/20) ≈ 1.12x the steps of 1e-4).
pub(crate) const STEP_SCALE: f64 = 1e-5;
/// Points per step at which δ, δ̇ and dF/dt are sampled for sign changes.
pub(crate) const SAMPLES: usize = 4;
pub(crate) const K: usize = ORDER;

/// 1/k for k = 0..=K (INVERSE[0] unused): the recurrences multiply by it,
/// a division being the slowest link of their order-by-order chain.
pub(crate) const INVERSE: [f64; K + 1] = {
    let mut table = [0.0; K + 1];
    let mut k = 1;
    while k <= K {
        table[k] = 1.0 / k as f64;
        k += 1;
    }
    table
};

/// True when this path solves the scenario: the shell law with a drive that
/// pushes the foot on (or none).
pub fn applies(scenario: &Scenario) -> bool {
    matches!(scenario.contact_law(), kick_core::AnyLaw::Shell(_)) && scenario.drive_force() >= 0.0
}

/// One step's Taylor coefficients in time from (δ, δ̇): δ to t^K, the force
/// and the dissipation rate β A δ̇² to t^(K−2).
struct Step {
    delta: [f64; K + 1],
    force: [f64; K - 1],
    dissipation: [f64; K - 1],
}

/// The elastic force's Taylor coefficients E_k of F_el(δ(t)), order by
/// order from δ's (δ_k known up to k when E_k is asked for): the
/// recurrences of the module docs, shared by the shell's own steps and the
/// booted ones ([`crate::boot::series`]).
pub(crate) struct ElasticJet {
    radius: f64,
    absolute: f64,
    gamma: f64,
    shell_stiffness: f64,
    /// 1/(4R³) and 1/f_0: multiplied by, not divided by, on the chain.
    inverse_volume: f64,
    inverse_f0: f64,
    q: [f64; K + 1],
    cube: [f64; K + 1],
    f: [f64; K + 1],
    w: [f64; K + 1],
    g: [f64; K + 1],
    area: [f64; K + 1],
    elastic: [f64; K + 1],
}

impl ElasticJet {
    /// At compression δ0 (the step's start).
    pub(crate) fn new(ball: &ShellBall, delta0: f64) -> Result<ElasticJet, KickError> {
        let mut jet = ElasticJet {
            radius: 0.0,
            absolute: 0.0,
            gamma: 0.0,
            shell_stiffness: 0.0,
            inverse_volume: 0.0,
            inverse_f0: 0.0,
            q: [0.0; K + 1],
            cube: [0.0; K + 1],
            f: [0.0; K + 1],
            w: [0.0; K + 1],
            g: [0.0; K + 1],
            area: [0.0; K + 1],
            elastic: [0.0; K + 1],
        };
        jet.restart(ball, delta0)?;
        Ok(jet)
    }

    /// [`ElasticJet::new`] in place, for a loop of steps that keeps one jet
    /// (orders above 0 are overwritten by [`ElasticJet::next`] before they are read).
    pub(crate) fn restart(&mut self, ball: &ShellBall, delta0: f64) -> Result<(), KickError> {
        let r = ball.radius;
        let absolute = ball.pressure + ball.atmospheric_pressure;
        let gamma = ball.gas_exponent;
        (self.radius, self.absolute, self.gamma, self.shell_stiffness) = (r, absolute, gamma, ball.shell_stiffness);
        self.inverse_volume = 1.0 / (4.0 * r * r * r);
        let cap0 = delta0 * delta0 * (3.0 * r - delta0) / (4.0 * r * r * r);
        self.f[0] = 1.0 - cap0;
        if !(self.f[0] > 0.0) {
            return Err(KickError::Integration { time: 0.0, reason: format!("compression {delta0} m leaves no gas in the ball") });
        }
        self.inverse_f0 = 1.0 / self.f[0];
        // (1 − c)^(−γ) and the gauge pressure with the digits of a small cap.
        let log_ratio = -(-cap0).ln_1p();
        self.w[0] = (gamma * log_ratio).exp();
        self.g[0] = ball.pressure + absolute * (gamma * log_ratio).exp_m1();
        Ok(())
    }

    /// E_k from δ_0..δ_k (`d`).
    #[inline]
    pub(crate) fn next(&mut self, k: usize, d: &[f64]) -> f64 {
        let r = self.radius;
        let a = -self.gamma;
        self.q[k] = (0..=k).map(|i| d[i] * d[k - i]).sum();
        self.cube[k] = (0..=k).map(|i| self.q[i] * d[k - i]).sum();
        if k > 0 {
            self.f[k] = -(3.0 * r * self.q[k] - self.cube[k]) * self.inverse_volume;
            let s: f64 = (1..=k).map(|j| ((a + 1.0) * j as f64 - k as f64) * self.f[j] * self.w[k - j]).sum();
            self.w[k] = s * self.inverse_f0 * INVERSE[k];
            self.g[k] = self.absolute * self.w[k];
        }
        self.area[k] = std::f64::consts::PI * (2.0 * r * d[k] - self.q[k]);
        self.elastic[k] = (0..=k).map(|i| self.g[i] * self.area[k - i]).sum::<f64>() + self.shell_stiffness * d[k];
        self.elastic[k]
    }

    /// E_0..E_k computed so far.
    pub(crate) fn elastic(&self) -> &[f64; K + 1] {
        &self.elastic
    }

    /// The contact patch's area A(δ(t)), coefficients 0..k computed so far.
    pub(crate) fn area(&self) -> &[f64; K + 1] {
        &self.area
    }
}

fn step(ball: &ShellBall, mu: f64, drive_share: f64, delta0: f64, rate0: f64) -> Result<Step, KickError> {
    let beta = ball.shell_damping;
    let mut d = [0.0; K + 1];
    let mut force = [0.0; K - 1];
    d[0] = delta0;
    d[1] = rate0;
    let mut jet = ElasticJet::new(ball, delta0)?;
    for k in 0..=K - 2 {
        jet.next(k, &d);
        let (elastic, area) = (jet.elastic(), jet.area());
        // F = F_el + β A δ̇: δ̇'s k-th coefficient is (k+1) d_(k+1).
        force[k] = elastic[k] + beta * (0..=k).map(|i| area[i] * (k - i + 1) as f64 * d[k - i + 1]).sum::<f64>();
        let drive = if k == 0 { drive_share } else { 0.0 };
        d[k + 2] = (drive - force[k]) / (mu * ((k + 1) * (k + 2)) as f64);
    }
    let elastic = jet.elastic();
    // β A δ̇² = (F − F_el) δ̇.
    let mut dissipation = [0.0; K - 1];
    for (k, slot) in dissipation.iter_mut().enumerate() {
        *slot = (0..=k).map(|i| (force[i] - elastic[i]) * (k - i + 1) as f64 * d[k - i + 1]).sum();
    }
    Ok(Step { delta: d, force, dissipation })
}

/// Σ c_k t^k (Horner).
pub(crate) fn poly(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * t + x)
}

/// d/dt Σ c_k t^k.
pub(crate) fn derivative(c: &[f64], t: f64) -> f64 {
    c.iter().enumerate().skip(1).rev().fold(0.0, |acc, (k, &x)| acc * t + k as f64 * x)
}

/// ∫_0^t Σ c_k s^k ds.
pub(crate) fn integral(c: &[f64], t: f64) -> f64 {
    t * c.iter().enumerate().rev().fold(0.0, |acc, (k, &x)| acc * t + x / (k + 1) as f64)
}

/// True when the force reaches its clamp at zero within a step of length
/// `h` while the compression is on (sampled at SAMPLES points).
pub(crate) fn reaches_clamp(compression: &[f64], force: &[f64], h: f64, length: f64) -> bool {
    (1..=SAMPLES).any(|j| {
        let x = h * j as f64 / SAMPLES as f64;
        poly(compression, x) > 1e-9 * length && poly(force, x) <= 0.0
    })
}

/// True when the shell's force is ≤ 0 just before it separates at the
/// compression rate `rate` (< 0): as δ → 0⁺, F/A → p0 + k_s/(2πR) + β δ̇
/// (A ≈ 2πR δ), so a rebound faster than (p0 + k_s/(2πR))/β has reached the
/// clamp however close to separation, where sampling may step over it.
pub(crate) fn separates_past_clamp(ball: &ShellBall, rate: f64) -> bool {
    ball.pressure + ball.shell_stiffness / (2.0 * std::f64::consts::PI * ball.radius) + ball.shell_damping * rate <= 0.0
}

/// The step's largest compression (at its turn inside the step) and force
/// (at its turn or the step's end) into the running `extremes`; `t` is the
/// step's start.
pub(crate) fn step_extremes(compression: &[f64], force: &[f64], t: f64, h: f64, extremes: &mut Extremes) {
    extremes_along(
        h,
        |x| t + x,
        (|x| poly(compression, x), |x| derivative(compression, x)),
        (|x| poly(force, x), |x| derivative(force, x)),
        extremes,
    );
}

/// [`step_extremes`] along a step parametrised by x in [0, h] (the time
/// from the step's start, or another variable that grows with it): `time`
/// maps x to the time, each pair is a value and a function of x with the
/// sign of its rate.
pub(crate) fn extremes_along(
    h: f64,
    time: impl Fn(f64) -> f64,
    compression: (impl Fn(f64) -> f64, impl Fn(f64) -> f64),
    force: (impl Fn(f64) -> f64, impl Fn(f64) -> f64),
    extremes: &mut Extremes,
) {
    if let Some(turn) = first_fall(&compression.1, h) {
        let reached = compression.0(turn);
        if reached > extremes.max_compression {
            (extremes.max_compression, extremes.max_compression_time) = (reached, time(turn));
        }
    }
    for candidate in [first_fall(&force.1, h), Some(h)].into_iter().flatten() {
        let value = force.0(candidate);
        if value > extremes.peak_force {
            (extremes.peak_force, extremes.peak_force_time) = (value, time(candidate));
        }
    }
}

/// The first time in (0, h] where `f` changes sign from positive to
/// non-positive, sampled at SAMPLES points and refined by Brent's method.
pub(crate) fn first_fall(f: impl Fn(f64) -> f64, h: f64) -> Option<f64> {
    let mut previous = (0.0, f(0.0));
    for j in 1..=SAMPLES {
        let t = h * j as f64 / SAMPLES as f64;
        let value = f(t);
        if previous.1 > 0.0 && value <= 0.0 {
            return roots::brent(&f, previous.0, t, h * 1e-16, 200).map(|root| root.x);
        }
        previous = (t, value);
    }
    None
}

/// The contact of `scenario` with `ball` (module docs); `tolerance` is the
/// local error per step in the scenario's units.
pub fn solve(scenario: &Scenario, ball: ShellBall, tolerance: f64) -> Result<Outcome, KickError> {
    let mu = scenario.reduced_mass();
    let v0 = scenario.approach_speed();
    let drive_share = mu / scenario.effective_foot_mass() * scenario.drive_force();
    let time_unit = (mu / ball.small_compression_stiffness()).sqrt();
    let length = v0 * time_unit;
    let (mut t, mut delta, mut rate, mut dissipated) = (0.0, 0.0, v0, 0.0);
    let mut extremes = Extremes::new(0.0);
    let mut steps = 0u32;
    loop {
        steps += 1;
        if steps > MAX_STEPS {
            return Err(KickError::Integration {
                time: t,
                reason: format!("the shell series took more than {MAX_STEPS} steps without separation"),
            });
        }
        let s = step(&ball, mu, drive_share, delta, rate)?;
        let size = |k: usize| (STEP_SCALE * tolerance * length / s.delta[k].abs()).powf(1.0 / k as f64);
        let mut h = size(K).min(size(K - 1)).min(100.0 * time_unit);
        if !(h.is_finite() && h > 0.0) {
            return Err(KickError::Integration { time: t, reason: format!("the shell series found no step at δ = {delta} m") });
        }
        // Separation (δ falls through 0 while receding) ends the contact.
        let separates = if rate < 0.0 || derivative(&s.delta, h) < 0.0 { first_fall(|x| poly(&s.delta, x), h) } else { None };
        if let Some(end) = separates {
            h = end;
        }
        // The clamp (module docs): F > 0 wherever δ > 0 within the step, and
        // just before separation, where sampling may step over it.
        if reaches_clamp(&s.delta, &s.force, h, length)
            || separates.is_some_and(|end| separates_past_clamp(&ball, derivative(&s.delta, end)))
        {
            return Err(KickError::NotApplicable {
                solver: "series",
                reason: "the shell's loss reaches the clamp F = 0 on this rebound (faster than p0/β); `reduced` solves it",
            });
        }
        step_extremes(&s.delta, &s.force, t, h, &mut extremes);
        dissipated += integral(&s.dissipation, h);
        t += h;
        rate = derivative(&s.delta, h);
        if separates.is_some() {
            break;
        }
        delta = poly(&s.delta, h);
        let stored = ball.potential(delta);
        let energy = 0.5 * mu * rate * rate + stored - drive_share * delta;
        if proves_trapped(-energy, stored.max(drive_share * delta)) {
            return Err(KickError::Trapped {
                time: t,
                reason: "the ball never leaves the foot, no separation: ½μδ̇² + U(δ) − (μ/m_f)F_drive δ fell below zero, so the ball cannot get back to δ = 0 \
                         (the drive keeps it pressed)"
                    .into(),
            });
        }
    }
    let end = RelativeState::new(0.0, rate, dissipated);
    let energy = RelativeOde::new(scenario, ball).budget(scenario, t, &end);
    separated(scenario, t, &end, extremes, energy, u64::from(steps), SolverPath::Series)
}
