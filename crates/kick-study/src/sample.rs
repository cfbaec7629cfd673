//! Random sweeps around the baseline (`kick sweep`, and `kick sweep3d`'s draws).
//!
//! Scenario `i` of a sweep with seed `s` is drawn from its own generator,
//! seeded from (s, i), so any scenario can be made on its own, in any order,
//! on any thread, and a sweep of 10^6 needs no list in memory.
//!
//! Every declared parameter is a sampled dimension: it is drawn from the
//! range `--range NAME=LOW,HIGH` gives ([`Ranges`]), else from its declared
//! sampling range (`kick_core::parameters`: [`kick_core::ParameterDef::sample`]),
//! else held at its value (given, or the default); one the law does not use
//! is neither drawn nor stored ([`kick_core::LawKind::uses`]). The eight of
//! Table 1 are drawn from the one stream the sweeps always drew them from
//! (so files written before are the same); every other drawn parameter, and
//! one of the eight given a range of its own, from a stream of its own,
//! seeded from (s, its name, i): drawing, holding or ranging one parameter
//! leaves every other's values as they were.

use crate::error::StudyError;
use kick_core::parameters::{self, ParameterDef, SampleRange, SetParameter, Shape, Spacing};

/// A sampling range given for one parameter (`--range NAME=LOW,HIGH`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    pub parameter: &'static ParameterDef,
    pub range: SampleRange,
}

/// The ranges a sweep draws from instead of the declared ones.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Ranges(pub Vec<Range>);

impl Ranges {
    /// Parse `NAME=LOW,HIGH` texts: `find` names the parameter (or says why
    /// it is none the sweep takes); the range is uniform, or log-uniform
    /// where the parameter's declared range is, inside its valid values.
    /// Errors name the flag `--range`.
    pub fn parse<E: std::fmt::Display>(
        given: &[String],
        find: impl Fn(&str) -> Result<&'static ParameterDef, E>,
    ) -> Result<Ranges, StudyError> {
        let refuse = |text: &str, why: String| StudyError::Flag { flag: "range", message: format!("--range {text}: {why}") };
        let mut ranges = Vec::new();
        for text in given {
            let (name, bounds) = text.split_once('=').ok_or_else(|| refuse(text, "expected NAME=LOW,HIGH".into()))?;
            let p = find(name.trim()).map_err(|why| refuse(text, why.to_string()))?;
            if p.shape != Shape::Scalar {
                return Err(refuse(text, format!("`{}` takes {}, not a range", p.name, p.shape.describe())));
            }
            let numbers: Vec<f64> = bounds
                .split(',')
                .map(|x| x.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|_| refuse(text, "LOW and HIGH must be numbers".into()))?;
            let [low, high] = numbers[..] else { return Err(refuse(text, "expected two numbers LOW,HIGH".into())) };
            if !(low.is_finite() && high.is_finite() && low < high) {
                return Err(refuse(text, "LOW and HIGH must be finite with LOW < HIGH".into()));
            }
            if !(p.valid.contains(low) && p.valid.contains(high)) {
                return Err(refuse(text, format!("`{}` must be {}", p.name, p.valid.requirement)));
            }
            let spacing = p.sample.map_or(Spacing::Linear, |s| s.spacing);
            if spacing == Spacing::Log && !(low > 0.0) {
                return Err(refuse(text, format!("`{}` is drawn log-uniformly: LOW must be > 0", p.name)));
            }
            if ranges.iter().any(|r: &Range| r.parameter.name == p.name) {
                return Err(refuse(text, format!("`{}` given twice", p.name)));
            }
            ranges.push(Range { parameter: p, range: SampleRange { spacing, from: low, to: high, zero_probability: 0.0 } });
        }
        Ok(Ranges(ranges))
    }

    /// The range given for `p`.
    pub fn given(&self, p: &ParameterDef) -> Option<SampleRange> {
        self.0.iter().find(|r| r.parameter.name == p.name && r.parameter.level == p.level).map(|r| r.range)
    }

    /// The range `p` is drawn from: given, else declared.
    pub fn of(&self, p: &ParameterDef) -> Option<SampleRange> {
        self.given(p).or(p.sample)
    }

    /// `# NAME = [LOW, HIGH]` lines of the given ranges (a file's provenance).
    pub fn describe(&self) -> String {
        self.0.iter().map(|r| format!("{} = [{:?}, {:?}]", r.parameter.name, r.range.from, r.range.to)).collect::<Vec<_>>().join("\n")
    }
}

/// The seed of the stream of parameter `name` (FNV-1a of the name, mixed
/// into the sweep's seed), for the draws outside the eight's stream.
pub fn stream_seed(seed: u64, name: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in name.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
    }
    seed ^ h
}

/// One draw of `p` for row `index` of a sweep seeded `seed`, from `range`,
/// on the parameter's own stream.
pub fn draw_own(seed: u64, index: u64, p: &ParameterDef, range: &SampleRange) -> f64 {
    let mut rng = row_rng(stream_seed(seed, p.name), index);
    range.draw(&mut || rng.random::<f64>())
}

/// The sampling ranges, one line per parameter of `list` a sweep under
/// `law` draws (`ranges` given, else declared; the others: held).
pub fn describe_ranges<'a>(list: impl Iterator<Item = &'a ParameterDef>, ranges: &Ranges, law: kick_core::LawKind) -> String {
    list.filter(|p| law.uses(p) && p.shape == Shape::Scalar)
        .map(|p| {
            let range = ranges.of(p).map_or_else(|| "held".to_string(), |s| s.describe());
            format!("{:<20} {range} {}", p.name, p.unit)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

use kick_core::{KickError, LawKind, Parameter, Scenario, ScenarioSpec};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// The sampling ranges of `kick sweep` under the paper's law, one line per parameter.
pub fn ranges() -> String {
    describe_ranges(parameters::at_levels(ScenarioSpec::LEVELS), &Ranges::default(), LawKind::PowerLaw)
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
#[derive(Debug, Clone, PartialEq)]
pub struct SampledSweep {
    pub samples: u64,
    pub seed: u64,
    /// Parameters held fixed instead of drawn, and the contact law of every
    /// scenario with its target restitution (default: the paper's law).
    pub fixed: ScenarioSpec,
    /// Ranges given instead of the declared ones (`--range`).
    pub ranges: Ranges,
}

impl SampledSweep {
    /// A sweep with the paper's law, every parameter drawn.
    pub fn new(samples: u64, seed: u64) -> SampledSweep {
        SampledSweep { samples, seed, fixed: ScenarioSpec::default(), ranges: Ranges::default() }
    }

    fn law(&self) -> LawKind {
        self.fixed.law.unwrap_or(LawKind::PowerLaw)
    }

    /// The parameters the sweep's law uses (its file's columns), in
    /// declaration order; the foot (leg, pose, boot) is held, and recorded
    /// with the outcomes' settings.
    pub fn parameters(&self) -> impl Iterator<Item = &'static ParameterDef> + '_ {
        let law = self.law();
        parameters::at_levels(ScenarioSpec::LEVELS).filter(move |p| law.uses(p) && p.level != parameters::Level::Foot)
    }

    /// Refuse a range for a parameter held too, or one the law does not use.
    pub fn check(&self) -> Result<(), StudyError> {
        for r in &self.ranges.0 {
            let refuse = |why: String| Err(StudyError::Flag { flag: "range", message: format!("--range {}: {why}", r.parameter.name) });
            if !self.law().uses(r.parameter) {
                return refuse(format!("law `{}` does not use `{}`", self.law().name(), r.parameter.name));
            }
            if r.parameter.level == parameters::Level::Foot {
                return refuse(format!("the foot (`{}`) is held in a sampled sweep; give it by its flag", r.parameter.name));
            }
            if self.fixed.value(r.parameter).is_some() {
                return refuse(format!("`{}` is also held (flag {}); give one", r.parameter.name, r.parameter.flag()));
            }
        }
        Ok(())
    }

    /// The spec of scenario `index`: the held values, the rest drawn (module docs).
    pub fn spec(&self, index: u64) -> ScenarioSpec {
        let mut spec = self.fixed;
        // The eight from the stream they always came from: every one takes its draws.
        let mut rng = row_rng(self.seed, index);
        let mut uniform = || rng.random::<f64>();
        for p in Parameter::ALL {
            let drawn = p.def().sample.map_or(f64::NAN, |range| range.draw(&mut uniform));
            // One the law ignores (the shell's k, c, n) stays unset: it must not
            // reach the solve (its step sizes) unrecorded.
            if spec.get(p).is_none() && self.law().uses(p.def()) {
                let value = self.ranges.given(p.def()).map_or(drawn, |range| draw_own(self.seed, index, p.def(), &range));
                spec.set(p, value);
            }
        }
        // The others the law uses, each from its own stream.
        for p in self.parameters().filter(|p| Parameter::from_name(p.name).is_none()) {
            if let (None, Some(range)) = (spec.value(p), self.ranges.of(p)) {
                let _ = kick_core::parameters::SetParameter::set_parameter(
                    &mut spec,
                    p,
                    parameters::Value::Number(draw_own(self.seed, index, p, &range)),
                );
            }
        }
        spec
    }

    /// Scenario `index`, the same for every run, thread count and order.
    pub fn scenario(&self, index: u64) -> Result<Scenario, KickError> {
        // A held `damping` or `restitution` the law would ignore is refused.
        self.law().check_given(self.fixed.damping.is_some(), self.fixed.restitution.is_some())?;
        self.spec(index).build_drawn()
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
        let mut fixed = free.clone();
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
        let default_ball = sweep.clone();
        sweep.fixed.inflation_pressure = Some(6.0e4);
        sweep.fixed.shell_damping = Some(3000.0);
        let ball = kick_core::ShellBall::new(6.0e4, kick_core::DEFAULT_BALL_RADIUS, 1.4, 0.0, 3000.0).unwrap();
        for i in 0..sweep.samples {
            let (a, b) = (default_ball.scenario(i).unwrap(), sweep.scenario(i).unwrap());
            assert_eq!(b.contact_law(), kick_core::AnyLaw::Shell(ball), "row {i}");
            assert_eq!(a.values(), b.values(), "row {i}");
        }
    }

    /// Under law `shell` the inflation pressure is a sampled dimension (its
    /// declared range, Law 2's 0.6–1.1 atm) drawn from its own stream: the
    /// five the shell uses are the paper's law's draws, bit for bit, and
    /// k, c, n (no columns of its file) stay at the baseline.
    #[test]
    fn the_shell_balls_pressure_is_drawn_under_law_shell() {
        let paper = SampledSweep::new(200, 9);
        let mut shell = paper.clone();
        shell.fixed.law = Some(LawKind::Shell);
        let range = kick_core::shell::INFLATION_PRESSURE.sample.unwrap();
        let mut pressures = Vec::new();
        for i in 0..shell.samples {
            let (a, b) = (paper.scenario(i).unwrap(), shell.scenario(i).unwrap());
            for p in Parameter::ALL {
                let unused = matches!(p, Parameter::Stiffness | Parameter::Damping | Parameter::Exponent);
                let expected = if unused { Scenario::BASELINE.get(p) } else { a.get(p) };
                assert_eq!(b.get(p), expected, "row {i} {}", p.name());
            }
            let kick_core::AnyLaw::Shell(ball) = b.contact_law() else { panic!("row {i}") };
            assert!((range.from..=range.to).contains(&ball.pressure), "row {i}: {}", ball.pressure);
            pressures.push(ball.pressure);
        }
        pressures.sort_by(f64::total_cmp);
        pressures.dedup();
        assert_eq!(pressures.len(), 200);
        // Columns: no k, c, n under the shell; the ball's four instead.
        let names: Vec<&str> = shell.parameters().map(|p| p.name).collect();
        assert_eq!(
            names,
            [
                "foot_mass",
                "ball_mass",
                "foot_speed",
                "ball_speed",
                "drive_force",
                "inflation_pressure",
                "gas_exponent",
                "shell_stiffness",
                "shell_damping"
            ]
        );
    }

    /// A range given draws that parameter from it (on its own stream) and
    /// leaves every other value as it was; bad ranges name `--range`.
    #[test]
    fn a_range_given_moves_only_its_parameter() {
        let find = |name: &str| parameters::find_at(ScenarioSpec::LEVELS, name);
        let declared = SampledSweep::new(300, 4);
        let ranged = SampledSweep { ranges: Ranges::parse(&["stiffness=2e5,3e5".into()], find).unwrap(), ..declared.clone() };
        ranged.check().unwrap();
        for i in 0..declared.samples {
            let (a, b) = (declared.scenario(i).unwrap(), ranged.scenario(i).unwrap());
            let k = b.get(Parameter::Stiffness);
            assert!((2e5..=3e5).contains(&k), "row {i}: {k}");
            assert_eq!(a.with(Parameter::Stiffness, k).unwrap(), b, "row {i}");
        }
        for (text, says) in [
            ("stifness=1,2", "did you mean `stiffness`"),
            ("stiffness=2,1", "LOW < HIGH"),
            ("stiffness=0,1e5", "must be finite and > 0"),
            ("foot_speed", "NAME=LOW,HIGH"),
            ("foot_speed=1,x", "numbers"),
        ] {
            let error = Ranges::parse(&[text.into()], find).unwrap_err().to_string();
            assert!(error.starts_with(&format!("--range {text}")) && error.contains(says), "{text}: {error}");
        }
        let held = SampledSweep { fixed: ScenarioSpec { stiffness: Some(1e5), ..ScenarioSpec::default() }, ..ranged.clone() };
        assert!(held.check().unwrap_err().to_string().contains("also held"));
        let unused = SampledSweep { fixed: ScenarioSpec { law: Some(LawKind::Shell), ..ScenarioSpec::default() }, ..ranged };
        assert!(unused.check().unwrap_err().to_string().contains("does not use `stiffness`"));
    }
}
