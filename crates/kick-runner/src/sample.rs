//! Random sweeps around the baseline (`kick sweep`).
//!
//! Scenario `i` of a sweep with seed `s` is drawn from its own generator,
//! seeded from (s, i), so any scenario can be made on its own, in any order,
//! on any thread, and a sweep of 10^6 needs no list in memory.

use kick_core::{KickError, Scenario};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// The documented sampling ranges (README, "Random sweeps").
pub const RANGES: &str = "\
foot_mass   log-uniform 0.5 .. 15 kg
ball_mass   uniform 0.41 .. 0.45 kg (size-5 ball)
foot_speed  uniform 12 .. 35 m/s
ball_speed  uniform -10 .. 10 m/s
stiffness   log-uniform 1e4 .. 1e7 N/m^n (three decades)
damping     uniform 0 .. 600 N s/m
exponent    uniform 1 .. 2
drive_force 0 N with probability 1/2, else uniform 0 .. 1000 N";

/// A sweep of `samples` random scenarios.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampledSweep {
    pub samples: u64,
    pub seed: u64,
    /// Contact law of every scenario, and the target restitution of a law
    /// other than the paper's.
    pub law: kick_core::LawKind,
    pub restitution: Option<f64>,
}

impl SampledSweep {
    /// A sweep with the paper's law.
    pub fn new(samples: u64, seed: u64) -> SampledSweep {
        SampledSweep { samples, seed, law: kick_core::LawKind::PowerLaw, restitution: None }
    }
}

impl SampledSweep {
    /// Scenario `index`, the same for every run, thread count and order.
    pub fn scenario(&self, index: u64) -> Result<Scenario, KickError> {
        // Mix the index into the seed (SplitMix64 finaliser) so neighbouring
        // indices start far apart.
        let mut z = self.seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15);
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
        Scenario::from_values([foot_mass, ball_mass, foot_speed, ball_speed, stiffness, damping, exponent, drive_force])?
            .with_law(self.law, self.restitution)
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
}
