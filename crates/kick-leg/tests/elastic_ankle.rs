//! The elastic ankle: the coupled leg–ball integration against the 1D model
//! in its two exact limits, and the 1D-equivalent mass.

use kick_core::Scenario;
use kick_leg::ankle::{coupled_ankle_contact, elastic_ankle, AnkleMobilities};
use kick_leg::{exit_outcome, AnkleJoint, Impact, Leg, Pose};

fn setup() -> (Leg, Pose, Impact, Scenario) {
    (Leg::de_leva(73.0, 1.741).unwrap(), Pose::default(), Impact::default(), Scenario::baseline())
}

#[test]
fn schur_complement_of_the_ankle_gives_the_locked_mass() {
    // Holding θ = 0 removes the ankle from M⁻¹ by a Schur complement; the
    // chain with the ankle joint removed must agree to rounding.
    let (leg, _, impact, _) = setup();
    for knee in [0.0, 30.0, 70.0] {
        for ankle in [20.0, 60.0] {
            let pose = Pose { knee_flexion: knee, plantarflexion: ankle, ..Pose::default() };
            let m = AnkleMobilities::of(&leg, &pose, &impact).unwrap();
            let locked = leg.effective_mass(&pose, &impact, AnkleJoint::Locked).unwrap().effective_mass;
            assert!((1.0 / m.locked() - locked).abs() < 1e-12 * locked);
            let free = leg.effective_mass(&pose, &impact, AnkleJoint::Free).unwrap().effective_mass;
            assert!((1.0 / m.free - free).abs() < 1e-12 * free);
        }
    }
}

#[test]
fn without_a_spring_the_coupled_leg_is_the_1d_model_with_the_free_mass() {
    // κ = 0 leaves v̇_c = −F/m_free: exactly Eqs. 13–14. Fixed-step RK4 with a
    // force kinked at δ = 0 converges; the error must fall at least 5× per
    // tenfold refinement and end below 1e-9 relative.
    let (leg, pose, impact, base) = setup();
    let free = leg.effective_mass(&pose, &impact, AnkleJoint::Free).unwrap().free_ankle;
    let truth = exit_outcome(free, &base).unwrap();
    let errors: Vec<f64> = [1_000u32, 10_000, 100_000]
        .iter()
        .map(|&steps| {
            let c = coupled_ankle_contact(&leg, &pose, &impact, 0.0, &base, steps).unwrap();
            assert!((c.contact_time - truth.contact_time).abs() < 1e-3 * truth.contact_time);
            ((c.v_ball_out - truth.v_ball_out) / truth.v_ball_out).abs()
        })
        .collect();
    assert!(errors[1] < errors[0] / 5.0 && errors[2] < errors[1] / 5.0, "{errors:?}");
    assert!(errors[2] < 1e-9, "{errors:?}");
}

#[test]
fn a_stiff_ankle_approaches_the_locked_leg_as_one_over_stiffness() {
    // The ankle's deflection under the contact torque scales as 1/κ, and so
    // does the gap to the locked leg: tenfold κ, tenfold smaller gap (the
    // observed ratio must lie in [5, 20]).
    let (leg, pose, impact, base) = setup();
    let locked = leg.effective_mass(&pose, &impact, AnkleJoint::Locked).unwrap().locked_ankle;
    let truth = exit_outcome(locked, &base).unwrap().v_ball_out;
    let gap = |k: f64| {
        let c = coupled_ankle_contact(&leg, &pose, &impact, k, &base, 20_000).unwrap();
        ((c.v_ball_out - truth) / truth).abs()
    };
    let (g7, g8) = (gap(1e7), gap(1e8));
    assert!(g8 < 1e-4, "{g8}");
    let ratio = g7 / g8;
    assert!((5.0..20.0).contains(&ratio), "{g7} {g8}");
}

#[test]
fn equivalent_mass_spans_free_to_locked_and_reproduces_the_coupled_speed() {
    let (leg, pose, impact, base) = setup();
    let limits = leg.effective_mass(&pose, &impact, AnkleJoint::Free).unwrap();
    let soft = elastic_ankle(&leg, &pose, &impact, 0.0, &base).unwrap();
    // κ = 0: the equivalent mass is m_free up to the coupled run's 1e-8 error
    // in v_b⁺, amplified by (m/v) dm/dv ≈ 3 at this mass.
    assert!((soft.equivalent_mass - limits.free_ankle).abs() < 1e-7 * limits.free_ankle);
    let stiff = elastic_ankle(&leg, &pose, &impact, 1e8, &base).unwrap();
    assert!((stiff.equivalent_mass - limits.locked_ankle).abs() < 1e-3 * limits.locked_ankle);
    // Brent's root reproduces the coupled exit speed.
    for e in [soft, stiff, elastic_ankle(&leg, &pose, &impact, 300.0, &base).unwrap()] {
        assert!((e.outcome.v_ball_out - e.coupled.v_ball_out).abs() < 1e-10 * e.coupled.v_ball_out);
    }
}
