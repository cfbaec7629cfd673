//! Named 3D kicks and a seeded sample of off-center kicks, shared by tests,
//! benches and `kick bench` (diffsol-style test models, as `kick_core::models`).
//!
//! The box ([`OffCenterBox`]) is where the accurate path promises its speed
//! and accuracy: offset 0–9 cm, approach −20…30°, μ 0.2–∞, foot 1–10 kg,
//! everything else at Table 1's baseline and the 3D defaults.

use crate::model::{Kick3d, Kick3dSpec};
use crate::Kick3dError;
use kick_core::{LawKind, Parameter, Scenario};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// A seeded sample of off-center kicks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffCenterBox {
    pub seed: u64,
    /// Normal contact law of every kick (restitution 0.6 for laws other than the paper's).
    pub law: LawKind,
}

/// The documented ranges of [`OffCenterBox`].
pub const BOX_RANGES: &str = "\
offset          uniform 0 .. 0.09 m
approach_angle  uniform -20 .. 30 deg
friction        infinite with probability 1/8, else log-uniform 0.2 .. 5
foot_mass       uniform 1 .. 10 kg";

/// Target restitution of the box's kicks under a law other than the paper's.
pub const BOX_RESTITUTION: f64 = 0.6;

impl OffCenterBox {
    pub fn new(seed: u64) -> OffCenterBox {
        OffCenterBox { seed, law: LawKind::PowerLaw }
    }

    /// The box's draws of kick `index`: offset (m), approach angle (deg),
    /// friction and foot mass (kg), the same for every run, order and thread.
    pub fn values(&self, index: u64) -> [f64; 4] {
        // SplitMix64 finaliser of (seed, index), as kick-study's sweeps.
        let mut z = self.seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(z ^ (z >> 31));
        let mut uniform = |low: f64, high: f64| low + (high - low) * rng.random::<f64>();
        let offset = uniform(0.0, 0.09);
        let approach = uniform(-20.0, 30.0);
        let friction = if uniform(0.0, 1.0) < 0.125 { f64::INFINITY } else { 10f64.powf(uniform(0.2f64.log10(), 5f64.log10())) };
        let foot_mass = uniform(1.0, 10.0);
        [offset, approach, friction, foot_mass]
    }

    /// Kick `index`: the same for every run, order and thread.
    pub fn kick(&self, index: u64) -> Result<Kick3d, Kick3dError> {
        let [offset, approach, friction, foot_mass] = self.values(index);
        let restitution = (self.law != LawKind::PowerLaw).then_some(BOX_RESTITUTION);
        let base = Scenario::baseline().with(Parameter::FootMass, foot_mass)?.with_law(self.law, restitution)?;
        Kick3d::new(
            base,
            &Kick3dSpec { offset: Some(offset), approach_angle_deg: Some(approach), friction: Some(friction), ..Kick3dSpec::default() },
        )
    }

    /// Kicks 0..count.
    pub fn kicks(&self, count: u64) -> Result<Vec<Kick3d>, Kick3dError> {
        (0..count).map(|i| self.kick(i)).collect()
    }
}

/// The seed of the box sample used by the benches and `kick bench`.
pub const BENCH_SEED: u64 = 2024;

/// The cap patch kick of `kick bench` (issue 31's ≤ 120 µs row) and the
/// examples that take it apart: 5 cm off centre, μ = 0.5, the patch on the
/// assumed convex instep, its face square to the path.
pub fn cap_patch_kick() -> Kick3dSpec {
    Kick3dSpec {
        offset: Some(0.05),
        friction: Some(0.5),
        patch_contact: Some(true),
        instep_radius: Some(crate::validation::ASSUMED_INSTEP_RADIUS),
        face_yaw_deg: Some(0.0),
        ..Kick3dSpec::default()
    }
}

/// Named kicks: (name, kick). Each stands for a kind of contact the solvers
/// must get right: both laws' families, μ from 0 to ∞, rounded and sharp
/// edges (two leave the flat face over an edge or a rounded border), a
/// drive, an incoming ball, gravity.
pub fn named_kicks() -> Result<Vec<(&'static str, Kick3d)>, Kick3dError> {
    let d = Kick3dSpec::default();
    // Outer size: the default instep, its edges rounded with 1 cm inside it.
    const ROUNDED_OUTER: [f64; 3] = [0.03, 0.12, 0.05];
    let baseline = Scenario::baseline();
    let soft = baseline.with(Parameter::Stiffness, 1.0e5)?;
    let cases = [
        ("central frictionless", baseline, Kick3dSpec { friction: Some(0.0), ..d }, LawKind::PowerLaw),
        ("curve 5 cm", baseline, Kick3dSpec { offset: Some(0.05), ..d }, LawKind::PowerLaw),
        ("curve 5 cm rising 10 deg", baseline, Kick3dSpec { offset: Some(0.05), approach_angle_deg: Some(10.0), ..d }, LawKind::PowerLaw),
        ("grip 7 cm mu inf", baseline, Kick3dSpec { offset: Some(0.07), friction: Some(f64::INFINITY), ..d }, LawKind::PowerLaw),
        ("slide 9 cm mu 0.2", baseline, Kick3dSpec { offset: Some(0.09), friction: Some(0.2), ..d }, LawKind::PowerLaw),
        ("frictionless 6 cm", baseline, Kick3dSpec { offset: Some(0.06), friction: Some(0.0), ..d }, LawKind::PowerLaw),
        (
            "rounded 4 cm rising 20 deg",
            baseline,
            Kick3dSpec {
                offset: Some(0.04),
                approach_angle_deg: Some(20.0),
                foot_half_extents: Some(ROUNDED_OUTER),
                border_radius: Some(0.01),
                ..d
            },
            LawKind::PowerLaw,
        ),
        ("over the sharp edge: soft ball 9 cm", soft, Kick3dSpec { offset: Some(0.09), friction: Some(0.2), ..d }, LawKind::PowerLaw),
        (
            "onto the rounded border: soft ball rising 30 deg",
            soft,
            // The line above the centre by R sin α (contact_depth −R sin α):
            // the kick this was before the depth was declared, sliding up
            // the ball onto the border (a central rising kick now pushes
            // through the centre, with no tangential force to check).
            Kick3dSpec {
                approach_angle_deg: Some(30.0),
                contact_depth: Some(-kick_core::DEFAULT_BALL_RADIUS * 0.5),
                friction: Some(0.05),
                foot_half_extents: Some(ROUNDED_OUTER),
                border_radius: Some(0.01),
                ..d
            },
            LawKind::PowerLaw,
        ),
        ("driven 800 N 5 cm", baseline.with(Parameter::DriveForce, 800.0)?, Kick3dSpec { offset: Some(0.05), ..d }, LawKind::PowerLaw),
        (
            "incoming ball 8 m/s 4 cm",
            baseline.with(Parameter::BallSpeed, -8.0)?,
            Kick3dSpec { offset: Some(0.04), approach_angle_deg: Some(-10.0), ..d },
            LawKind::PowerLaw,
        ),
        ("gravity 5 cm", baseline, Kick3dSpec { offset: Some(0.05), gravity: Some(true), ..d }, LawKind::PowerLaw),
        (
            "lankarani-nikravesh 6 cm",
            baseline,
            Kick3dSpec { offset: Some(0.06), approach_angle_deg: Some(5.0), ..d },
            LawKind::LankaraniNikravesh,
        ),
        (
            "hunt-crossley-exact 3 cm mu 1",
            baseline,
            Kick3dSpec { offset: Some(0.03), friction: Some(1.0), ..d },
            LawKind::HuntCrossleyExact,
        ),
        ("kelvin-voigt 3 cm", baseline, Kick3dSpec { offset: Some(0.03), ..d }, LawKind::KelvinVoigt),
    ];
    cases
        .into_iter()
        .map(|(name, base, spec, law)| {
            let restitution = (law != LawKind::PowerLaw).then_some(BOX_RESTITUTION);
            Ok((name, Kick3d::new(base.with_law(law, restitution)?, &spec)?))
        })
        .collect()
}

/// Kicks whose largest normal or tangential force comes just after a
/// grip/slip switch (found by search over the box; the running maximum
/// once missed them): (name, kick).
pub fn peak_after_switch() -> Result<Vec<(&'static str, Kick3d)>, Kick3dError> {
    let case = |law: LawKind, offset: f64, approach: f64, friction: f64, foot_mass: f64| -> Result<Kick3d, Kick3dError> {
        let restitution = (law != LawKind::PowerLaw).then_some(BOX_RESTITUTION);
        let base = Scenario::baseline().with(Parameter::FootMass, foot_mass)?.with_law(law, restitution)?;
        let spec =
            Kick3dSpec { offset: Some(offset), approach_angle_deg: Some(approach), friction: Some(friction), ..Kick3dSpec::default() };
        Kick3d::new(base, &spec)
    };
    Ok(vec![
        ("power-law, normal peak after a switch", case(LawKind::PowerLaw, 0.0417, -17.97, 0.271, 6.67)?),
        ("lankarani-nikravesh, tangential peak after a switch", case(LawKind::LankaraniNikravesh, 0.0697, -9.15, 0.608, 9.02)?),
        ("kelvin-voigt, tangential peak after a switch", case(LawKind::KelvinVoigt, 0.0741, 12.18, 0.84, 4.44)?),
    ])
}
