//! A compliant layer in series between the foot and the ball: the boot's
//! upper and the tissue of the dorsum, one element ([`Boot`]).
//!
//! The layer is massless (a boot's upper weighs a few grams against the
//! ball's 430) and linear Kelvin–Voigt: F = k_b δ_b + c_b δ̇_b, δ_b its
//! compression. In series with the ball's law F = F_B(δ_B, δ̇_B) the two
//! carry one force, and the foot–ball approach is the sum δ = δ_b + δ_B.
//! Every law of [`crate::laws`] is affine in the rate on each side of its
//! switch before its clamp, F_B = E(δ_B) + D(δ_B) δ̇_B
//! ([`ContactLaw::rate_affine`]), so the force balance
//! E + D (δ̇ − δ̇_b) = k_b δ_b + c_b δ̇_b gives the layer's rate in closed form,
//!
//!     δ̇_b = (E + D δ̇ − k_b δ_b) / (c_b + D),
//!
//! an ordinary differential equation for δ_b beside the bodies' motion:
//! no inner iteration, no algebraic loop, and the solvers' events keep their
//! meaning on the ball's side (separation where δ_B reaches 0, the damping
//! switch of Eq. 20 where δ̇_B does). With c_b > 0 the denominator never
//! vanishes; at first touch δ_b = 0 and δ̇_b = E(0)/c_b + … = 0 for the laws
//! that start from F(0⁺) = 0, and c V0/(c_b + c) for the paper's law, whose
//! dashpot jumps. After the ball leaves the layer relaxes on its own
//! (δ̇_b = −k_b δ_b/c_b): its elastic energy at separation is reported as
//! `elastic_final` and lost later, not to the ball.
//!
//! Why this law: an algebraic split (δ_b from k_b δ_b = F_B with no state)
//! exists only when both elements are elastic; with the ball's rate-dependent
//! loss the layer's compression must be a state, and Kelvin–Voigt is the
//! one loss that keeps its rate regular where the ball's force starts from
//! zero (a hysteretic layer, k_b δ_b (1 + χ_b δ̇_b), gives 0/0 at touch).
//! Its error is the model's own: the layer is taken as linear (tissue
//! stiffens), massless, and uniform under the contact (3D: it moves the
//! foot's surface along the contact normal). The solvers integrate it to
//! their stated tolerance (`kick-compliant`, `kick-3d`).
//!
//! Identified from one published measurement: kick-compliant's
//! `boot::identify` and its SOURCES entry ([`IDENTIFIED`]).

use crate::error::KickError;
use crate::law::ContactLaw;
use crate::parameters::ParameterDef;

/// The layer: k_b and c_b.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Boot {
    /// k_b, N/m (finite: an infinite one is no layer, the rigid foot).
    pub stiffness: f64,
    /// c_b, N s/m (> 0, see the module docs).
    pub damping: f64,
}

/// The boot `leg = true` brings with it (identified in kick-compliant's
/// `boot` module from Peacock & Ball 2016; the test there recomputes it).
pub const IDENTIFIED: Boot = Boot { stiffness: IDENTIFIED_STIFFNESS, damping: IDENTIFIED_DAMPING };
/// k_b of [`IDENTIFIED`], N/m.
pub const IDENTIFIED_STIFFNESS: f64 = 35_066.065;
/// c_b of [`IDENTIFIED`], N s/m.
pub const IDENTIFIED_DAMPING: f64 = 38.3008;

/// The two elements at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Split {
    /// F, carried by both (the ball law's force at its own rate).
    pub force: f64,
    /// The ball law's force before its clamp at zero (the switch of laws that would pull).
    pub unclamped_force: f64,
    /// δ̇_b.
    pub boot_rate: f64,
    /// δ̇_B = δ̇ − δ̇_b.
    pub ball_rate: f64,
    /// E = F_B(δ_B, 0), the ball's elastic part.
    pub elastic: f64,
    /// D = ∂F_B/∂δ̇_B on the branch.
    pub slope: f64,
}

impl Split {
    /// Power the two dashpots take: (F − E) δ̇_B + c_b δ̇_b².
    #[inline]
    pub fn loss_power(&self, boot: &Boot) -> f64 {
        (self.force - self.elastic) * self.ball_rate + boot.damping * self.boot_rate * self.boot_rate
    }
}

impl Boot {
    /// Each value checked against its declaration (`boot_stiffness`,
    /// `boot_damping`); an infinite stiffness is no layer (`None`).
    pub fn new(stiffness: f64, damping: f64) -> Result<Option<Boot>, KickError> {
        let check = |p: &ParameterDef, x: f64| p.check(x);
        let stiffness = check(&crate::parameters::BOOT_STIFFNESS, stiffness)?;
        let damping = check(&crate::parameters::BOOT_DAMPING, damping)?;
        Ok(stiffness.is_finite().then_some(Boot { stiffness, damping }))
    }

    /// The split at ball compression δ_B, approach rate δ̇ and layer
    /// compression δ_b, on the ball law's branch `compressing` (the side of
    /// δ̇_B = 0), the force held at zero when `clamped` (module docs).
    #[inline]
    pub fn split<L: ContactLaw>(
        &self,
        law: &L,
        ball_compression: f64,
        rate: f64,
        boot_compression: f64,
        compressing: bool,
        clamped: bool,
    ) -> Split {
        let (elastic, slope) = law.rate_affine(ball_compression, compressing);
        self.split_affine(elastic, slope, rate, boot_compression, clamped)
    }

    /// [`Boot::split`] from the ball law's (E, D) at its compression
    /// ([`ContactLaw::rate_affine`]), for a caller that has them.
    #[inline(always)]
    pub fn split_affine(&self, elastic: f64, slope: f64, rate: f64, boot_compression: f64, clamped: bool) -> Split {
        let spring = self.stiffness * boot_compression;
        if clamped {
            let boot_rate = -spring / self.damping;
            return Split {
                force: 0.0,
                unclamped_force: elastic + slope * (rate - boot_rate),
                boot_rate,
                ball_rate: rate - boot_rate,
                elastic,
                slope,
            };
        }
        let boot_rate = (elastic + slope * rate - spring) / (self.damping + slope);
        let ball_rate = rate - boot_rate;
        let force = elastic + slope * ball_rate;
        Split { force, unclamped_force: force, boot_rate, ball_rate, elastic, slope }
    }

    /// dF/dt along the motion, given the split and δ̈ (the approach's
    /// acceleration, from the bodies): with F = E + D δ̇_B and
    /// F = k_b δ_b + c_b δ̇_b, Ḟ = (c_b F_δ δ̇_B + c_b D δ̈ + D k_b δ̇_b)/(c_b + D),
    /// F_δ = ∂F_B/∂δ_B at the ball's rate. Zero while clamped.
    #[inline]
    pub fn force_rate<L: ContactLaw>(
        &self,
        law: &L,
        ball_compression: f64,
        split: &Split,
        acceleration: f64,
        compressing: bool,
        clamped: bool,
    ) -> f64 {
        if clamped {
            return 0.0;
        }
        let (_, d_delta, d_rate) = law.branch_force_and_gradient(ball_compression, split.ball_rate, compressing);
        let (rate, per_acceleration) = self.force_rate_parts(d_delta, d_rate, split.ball_rate, split.boot_rate);
        rate + per_acceleration * acceleration
    }

    /// [`Boot::force_rate`] from the ball law's gradient (F_δ, F_v) at the
    /// split, as Ḟ = `rate` + `per_acceleration` δ̈ (for a caller whose δ̈
    /// depends on the force it is computing, or whose law is a patch's).
    #[inline]
    pub fn force_rate_parts(&self, d_delta: f64, d_rate: f64, ball_rate: f64, boot_rate: f64) -> (f64, f64) {
        let c = self.damping;
        ((c * d_delta * ball_rate + d_rate * self.stiffness * boot_rate) / (c + d_rate), c * d_rate / (c + d_rate))
    }

    /// δ̈_b from Ḟ = k_b δ̇_b + c_b δ̈_b.
    #[inline]
    pub fn boot_acceleration(&self, split: &Split, force_rate: f64) -> f64 {
        (force_rate - self.stiffness * split.boot_rate) / self.damping
    }

    /// ½ k_b δ_b².
    #[inline]
    pub fn potential(&self, boot_compression: f64) -> f64 {
        0.5 * self.stiffness * boot_compression * boot_compression
    }

    /// Time constant of the layer against a ball of tangent stiffness `k`:
    /// c_b/(k_b + k), the scale on which δ_b follows the force.
    pub fn time_constant(&self, ball_stiffness: f64) -> f64 {
        self.damping / (self.stiffness + ball_stiffness)
    }

    /// The settings a result file records, by name.
    pub fn parameters(&self) -> [(&'static str, f64); 2] {
        [(crate::parameters::BOOT_STIFFNESS.name, self.stiffness), (crate::parameters::BOOT_DAMPING.name, self.damping)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laws::AnyLaw;
    use crate::ShellBall;

    fn laws() -> Vec<AnyLaw> {
        let mut laws = crate::test_support::laws();
        laws.push(AnyLaw::Shell(ShellBall::default_with_radius(crate::DEFAULT_BALL_RADIUS).unwrap()));
        laws
    }

    /// The split carries one force: the ball law's at the ball's own rate
    /// equals the layer's k_b δ_b + c_b δ̇_b, and the rates add up to δ̇.
    #[test]
    fn both_elements_carry_one_force() {
        let boot = Boot { stiffness: 4.0e4, damping: 30.0 };
        for law in laws() {
            for &(d, rate, db) in &[(0.01, 5.0, 0.004), (0.02, -3.0, 0.01), (0.005, 12.0, 0.0), (0.03, 0.5, 0.02)] {
                for compressing in [true, false] {
                    let s = boot.split(&law, d, rate, db, compressing, false);
                    let ball = law.branch_force(d, s.ball_rate, compressing).1;
                    let layer = boot.stiffness * db + boot.damping * s.boot_rate;
                    let scale = ball.abs().max(boot.stiffness * db).max(1.0);
                    assert!((s.force - layer).abs() <= 1e-12 * scale, "{:?}: {} vs {layer}", law.kind(), s.force);
                    if ball > 0.0 {
                        assert!((s.force - ball).abs() <= 1e-12 * scale, "{:?}: {} vs {ball}", law.kind(), s.force);
                    }
                    assert!((s.ball_rate + s.boot_rate - rate).abs() <= 1e-15 * rate.abs().max(1.0));
                }
            }
        }
    }

    /// Ḟ from `force_rate` against a central difference of the split along
    /// a short motion: δ_B, δ̇ and δ_b advanced by their rates.
    #[test]
    fn the_force_rate_is_the_derivative_along_the_motion() {
        let boot = Boot { stiffness: 4.0e4, damping: 30.0 };
        for law in laws() {
            let (d, rate, db, acceleration) = (0.012, 6.0, 0.003, -2000.0);
            let s = boot.split(&law, d, rate, db, true, false);
            let at = |h: f64| {
                let d_h = d + s.ball_rate * h;
                let rate_h = rate + acceleration * h;
                let db_h = db + s.boot_rate * h;
                boot.split(&law, d_h, rate_h, db_h, true, false).force
            };
            let h = 1e-8;
            let numeric = (at(h) - at(-h)) / (2.0 * h);
            let exact = boot.force_rate(&law, d, &s, acceleration, true, false);
            assert!((numeric - exact).abs() <= 1e-5 * exact.abs().max(1e3), "{:?}: {numeric} vs {exact}", law.kind());
        }
    }

    #[test]
    fn an_infinite_stiffness_is_no_layer_and_bad_values_are_named() {
        assert_eq!(Boot::new(f64::INFINITY, 30.0).unwrap(), None);
        assert_eq!(Boot::new(4e4, 30.0).unwrap(), Some(Boot { stiffness: 4e4, damping: 30.0 }));
        let e = Boot::new(-1.0, 30.0).unwrap_err().to_string();
        assert!(e.contains("`boot_stiffness`"), "{e}");
        let e = Boot::new(4e4, 0.0).unwrap_err().to_string();
        assert!(e.contains("`boot_damping`"), "{e}");
    }
}
