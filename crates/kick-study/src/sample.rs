//! Random sweeps around the baseline (`kick sweep`).
//!
//! Scenario `i` of a sweep with seed `s` is drawn from its own generator,
//! seeded from (s, i), so any scenario can be made on its own, in any order,
//! on any thread, and a sweep of 10^6 needs no list in memory.

use kick_core::{KickError, LawKind, Parameter, Scenario, ScenarioSpec};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// The sampling ranges, one line per parameter, from the declarations
/// (`kick_core::parameters`: [`kick_core::ParameterDef::sample`]).
pub fn ranges() -> String {
    Parameter::ALL
        .iter()
        .map(|p| {
            let def = p.def();
            let range = def.sample.map_or_else(|| "not sampled".to_string(), |s| s.describe());
            format!("{:<11} {range} {}", def.name, def.unit)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The generator of row `index` of a sweep seeded `seed`: any row can be
/// drawn on its own, in any order, on any thread.
pub fn row_rng(seed: u64, index: u64) -> Xoshiro256PlusPlus {
    // Mix the index into the seed (SplitMix64 finaliser) so neighbouring
    // indices start far apart.
    let mut z = seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    Xoshiro256PlusPlus::seed_from_u64(z ^ (z >> 31))
}

/// A sweep of `samples` random scenarios.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampledSweep {
    pub samples: u64,
    pub seed: u64,
    /// Parameters held fixed instead of drawn, and the contact law of every
    /// scenario with its target restitution (default: the paper's law).
    pub fixed: ScenarioSpec,
}

impl SampledSweep {
    /// A sweep with the paper's law, every parameter drawn.
    pub fn new(samples: u64, seed: u64) -> SampledSweep {
        SampledSweep { samples, seed, fixed: ScenarioSpec::default() }
    }

    /// Scenario `index`, the same for every run, thread count and order.
    /// Each parameter is drawn from its declared range in [`Parameter::ALL`]
    /// order; a fixed one still takes its draws, so fixing one parameter
    /// leaves the others' values as they were.
    pub fn scenario(&self, index: u64) -> Result<Scenario, KickError> {
        let law = self.fixed.law.unwrap_or(LawKind::PowerLaw);
        // A held `damping` or `restitution` the law would ignore is refused.
        law.check_given(self.fixed.damping.is_some(), self.fixed.restitution.is_some())?;
        let mut rng = row_rng(self.seed, index);
        let mut uniform = || rng.random::<f64>();
        let mut values = [0.0; 8];
        for (slot, p) in values.iter_mut().zip(Parameter::ALL) {
            let drawn = p.def().sample.map_or(f64::NAN, |range| range.draw(&mut uniform));
            *slot = self.fixed.get(p).unwrap_or(drawn);
        }
        // The foot held (a leg sets the foot's mass over the drawn one, Eq. 11).
        let foot = self.fixed.foot()?;
        if let Some(pose) = foot.leg {
            values[0] = kick_core::leg::LegFoot::new(pose)?.effective_mass;
        }
        Ok(self.fixed.law_on(Scenario::from_values(values)?)?.with_foot(foot))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_core::Parameter;

    #[test]
    fn scenarios_are_reproducible_distinct_and_in_range() {
        let sweep = SampledSweep::new(1000, 7);
        let mut driven = 0;
        for i in 0..sweep.samples {
            let a = sweep.scenario(i).unwrap();
            assert_eq!(a, sweep.scenario(i).unwrap());
            assert_ne!(a, sweep.scenario(i + 1).unwrap());
            assert!((0.5..=15.0).contains(&a.effective_foot_mass()));
            assert!((1e4..=1e7).contains(&a.get(Parameter::Stiffness)));
            assert!((1.0..=2.0).contains(&a.get(Parameter::Exponent)));
            driven += usize::from(a.drive_force() > 0.0);
        }
        // Half driven, within 4 binomial standard deviations (σ ≈ 16).
        assert!((436..=564).contains(&driven), "{driven}");
        assert_ne!(sweep.scenario(0).unwrap(), SampledSweep::new(1, 8).scenario(0).unwrap());
    }

    /// The draws as they were written by hand before the ranges were
    /// declared: the sampled scenarios (and every sweep file) stay the same, bit for bit.
    #[test]
    fn declared_ranges_draw_the_scenarios_of_the_hand_written_sampler() {
        fn by_hand(seed: u64, index: u64) -> [f64; 8] {
            let mut z = seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15);
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(z ^ (z >> 31));
            let mut uniform = |low: f64, high: f64| low + (high - low) * rng.random::<f64>();
            let foot_mass = 10f64.powf(uniform(0.5f64.log10(), 15f64.log10()));
            let ball_mass = uniform(0.41, 0.45);
            let foot_speed = uniform(12.0, 35.0);
            let ball_speed = uniform(-10.0, 10.0);
            let stiffness = 10f64.powf(uniform(4.0, 7.0));
            let damping = uniform(0.0, 600.0);
            let exponent = uniform(1.0, 2.0);
            let drive_force = if uniform(0.0, 1.0) < 0.5 { 0.0 } else { uniform(0.0, 1000.0) };
            [foot_mass, ball_mass, foot_speed, ball_speed, stiffness, damping, exponent, drive_force]
        }
        for seed in [1, 7] {
            let sweep = SampledSweep::new(2000, seed);
            for i in 0..sweep.samples {
                let expected = by_hand(seed, i);
                let drawn = sweep.scenario(i).map(|s| s.values()).unwrap_or([f64::NAN; 8]);
                let same = drawn.iter().zip(&expected).all(|(a, b)| a.to_bits() == b.to_bits());
                // A hand-drawn scenario the model refuses (foot not faster than the ball) is refused now too.
                assert!(same || Scenario::from_values(expected).is_err(), "seed {seed}, row {i}: {drawn:?} vs {expected:?}");
            }
        }
    }

    #[test]
    fn a_fixed_parameter_leaves_the_others_drawn_as_before() {
        let free = SampledSweep::new(100, 3);
        let mut fixed = free;
        fixed.fixed.stiffness = Some(1e6);
        for i in 0..free.samples {
            let (a, b) = (free.scenario(i).unwrap(), fixed.scenario(i).unwrap());
            assert_eq!(b.get(Parameter::Stiffness), 1e6);
            assert_eq!(a.with(Parameter::Stiffness, 1e6).unwrap(), b);
        }
    }

    /// `kick sweep --law shell --inflation-pressure 6e4 --shell-damping 3000`:
    /// every scenario is solved with that ball (it once fell back to the
    /// declared 0.8 bar), the other values drawn as without it.
    #[test]
    fn a_given_shell_ball_is_the_ball_of_every_scenario() {
        let mut sweep = SampledSweep::new(50, 5);
        sweep.fixed.law = Some(kick_core::LawKind::Shell);
        let default_ball = sweep;
        sweep.fixed.inflation_pressure = Some(6.0e4);
        sweep.fixed.shell_damping = Some(3000.0);
        let ball = kick_core::ShellBall::new(6.0e4, kick_core::DEFAULT_BALL_RADIUS, 1.4, 0.0, 3000.0).unwrap();
        for i in 0..sweep.samples {
            let (a, b) = (default_ball.scenario(i).unwrap(), sweep.scenario(i).unwrap());
            assert_eq!(b.contact_law(), kick_core::AnyLaw::Shell(ball), "row {i}");
            assert_eq!(a.values(), b.values(), "row {i}");
        }
    }
}
