//! The elastic ankle: the coupled leg–ball integration against the 1D model
//! in its two exact limits, and the 1D-equivalent mass.

use kick_core::Scenario;
use kick_leg::ankle::{coupled_ankle_contact, elastic_ankle, locked_limit_stiffness, AnkleMobilities, ELASTIC_STEPS};
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

/// A very stiff ankle is the locked leg: no wrong number (once −409 m/s at
/// κ = 1e13) and no false "no separation" (at 1e16), up to f64::MAX.
#[test]
fn a_very_stiff_ankle_is_the_locked_leg() {
    let (leg, pose, impact, base) = setup();
    let locked_mass = leg.effective_mass(&pose, &impact, AnkleJoint::Locked).unwrap().locked_ankle;
    let locked = exit_outcome(locked_mass, &base).unwrap();
    for k in [1e13, 1e16, 1e300, f64::MAX] {
        let c = coupled_ankle_contact(&leg, &pose, &impact, k, &base, ELASTIC_STEPS).unwrap();
        assert!(c.locked_limit, "{k:e}");
        assert_eq!((c.v_ball_out, c.v_contact_out, c.contact_time), (locked.v_ball_out, locked.v_foot_out, locked.contact_time), "{k:e}");
        assert!(c.max_ankle_deflection.is_finite() && c.max_ankle_deflection < 1e-10, "{k:e}: {}", c.max_ankle_deflection);
        let e = elastic_ankle(&leg, &pose, &impact, k, &base).unwrap();
        assert_eq!(e.equivalent_mass, locked_mass);
        assert_eq!(e.outcome.v_ball_out, locked.v_ball_out);
    }
}

/// At the switch stiffness the coupled run (integrated just below it) and
/// the locked limit (taken just above it) agree to the coupled run's own
/// accuracy, 1e-8, over knee and ankle angles.
#[test]
fn the_coupled_run_meets_the_locked_limit_at_the_switch() {
    let (leg, _, impact, base) = setup();
    for knee in [0.0, 30.0, 70.0] {
        for ankle in [20.0, 60.0] {
            let pose = Pose { knee_flexion: knee, plantarflexion: ankle, ..Pose::default() };
            let switch = locked_limit_stiffness(&leg, &pose, &impact, &base).unwrap();
            let below = coupled_ankle_contact(&leg, &pose, &impact, switch * (1.0 - 1e-9), &base, ELASTIC_STEPS).unwrap();
            let above = coupled_ankle_contact(&leg, &pose, &impact, switch, &base, ELASTIC_STEPS).unwrap();
            assert!(!below.locked_limit && above.locked_limit);
            let case = format!("knee {knee}, ankle {ankle}, κ = {switch:.3e}");
            assert!(
                (below.v_ball_out - above.v_ball_out).abs() < 1e-8 * above.v_ball_out,
                "{case}: {} vs {}",
                below.v_ball_out,
                above.v_ball_out
            );
            assert!((below.v_contact_out - above.v_contact_out).abs() < 1e-8 * above.v_ball_out, "{case}");
            assert!((below.contact_time - above.contact_time).abs() < 1e-8 * above.contact_time, "{case}");
            // The quasi-static deflection is the coupled run's up to its
            // dynamic overshoot (at most 3x for a single-humped force).
            assert!(
                below.max_ankle_deflection <= 3.0 * above.max_ankle_deflection && below.max_ankle_deflection >= above.max_ankle_deflection,
                "{case}"
            );
        }
    }
}

/// Up to the switch, the ankle mode (ω² = κ/I_a, up to ~2e7 rad/s) is
/// integrated stably: the gap to the locked leg keeps falling as 1/κ.
#[test]
fn a_stiff_ankle_below_the_switch_keeps_the_one_over_stiffness_gap() {
    let (leg, pose, impact, base) = setup();
    let locked = leg.effective_mass(&pose, &impact, AnkleJoint::Locked).unwrap().locked_ankle;
    let truth = exit_outcome(locked, &base).unwrap().v_ball_out;
    let gap = |k: f64| {
        let c = coupled_ankle_contact(&leg, &pose, &impact, k, &base, ELASTIC_STEPS).unwrap();
        assert!(!c.locked_limit);
        (c.v_ball_out - truth) / truth
    };
    let (g9, g11) = (gap(1e9), gap(1e11));
    assert!(g9 > 0.0 && g11 > 0.0, "{g9} {g11}");
    assert!((50.0..200.0).contains(&(g9 / g11)), "{g9} {g11}");
}

/// A drive that keeps the ball pressed is a trapped ball through the leg
/// too, not a numerical failure.
#[test]
fn a_trapping_drive_is_trapped_through_the_leg() {
    let (leg, pose, impact, _) = setup();
    let pressed = Scenario::baseline().with(kick_core::Parameter::DriveForce, 5e4).unwrap();
    let mass = leg.effective_mass(&pose, &impact, AnkleJoint::Locked).unwrap().effective_mass;
    let error = exit_outcome(mass, &pressed).unwrap_err();
    assert!(matches!(error, kick_leg::LegError::Contact(kick_core::KickError::Trapped { .. })), "{error:?}");
    assert_eq!(error.status(), kick_core::Status::Trapped);
}
