//! Fixed-step methods refuse a step too large for the contact, with an
//! error that says so, never an outcome and never "no separation".

use kick_compliant::stability::{largest_stable_rk4_step, relative_energy_residual, ENERGY_RESIDUAL_BOUND};
use kick_compliant::{precision, Accurate, FullState, SeedRk4, SolverChoice};
use kick_core::{models, KickError, Outcome, Parameter, Scenario, Solver, Status};

fn baseline_with(parameter: Parameter, value: f64) -> Scenario {
    Scenario::baseline().with(parameter, value).unwrap()
}

fn is_step_too_large(error: &KickError) -> bool {
    matches!(error, KickError::StepTooLarge { .. } | KickError::StepTooInaccurate { .. })
}

/// The three cases.
#[test]
fn the_reported_cases_say_the_step_is_too_large() {
    // Heavy damping: the fast root of μ s² + c s + k_eff is ≈ −c/μ, and RK4
    // is stable on the negative real axis up to h|λ| = 2.785.
    let damped = baseline_with(Parameter::Damping, 1e7);
    match SeedRk4::new(5e-6).unwrap().solve(&damped) {
        Err(KickError::StepTooLarge { step, largest_stable_step, .. }) => {
            assert_eq!(step, 5e-6);
            let expected = 2.785_293_563_405_282 * damped.reduced_mass() / 1e7;
            assert!((largest_stable_step - expected).abs() < 1e-3 * expected, "{largest_stable_step:e} vs {expected:e}");
        }
        other => panic!("{other:?}"),
    }
    // A step of a second against a 5 ms contact.
    let error = SeedRk4::new(1.0).unwrap().solve(&Scenario::baseline()).unwrap_err();
    assert!(matches!(error, KickError::StepTooLarge { .. }), "{error:?}");
    // Stable, but two steps per contact: the energy budget does not close.
    let stiff = baseline_with(Parameter::Stiffness, 1e12);
    match FullState::rk4_events(5e-6).solve(&stiff) {
        Err(KickError::StepTooInaccurate { relative_residual, bound, .. }) => {
            assert_eq!(bound, ENERGY_RESIDUAL_BOUND);
            assert!(relative_residual > 0.1, "{relative_residual}");
        }
        other => panic!("{other:?}"),
    }
    for error in [
        SeedRk4::new(5e-6).unwrap().solve(&damped).unwrap_err(),
        FullState::rk4_events(5e-6).solve(&stiff).unwrap_err(),
        SeedRk4::new(5e-6).unwrap().solve(&stiff).unwrap_err(),
    ] {
        assert_eq!(error.status(), Status::NumericalFailure);
        let text = error.to_string();
        assert!(text.starts_with("step too large") && text.contains("dt"), "{text}");
    }
}

/// The a-priori limit is sharp where the linearisation is exact (n = 1, no
/// damping: λ = ±iω, h_max = 2√2/ω): 1% above it is refused before
/// integrating; 1% below it the integration runs (and is then judged by the
/// energy budget: one step per contact cannot close it).
#[test]
fn the_stability_limit_is_sharp_on_a_linear_law() {
    let s = Scenario::baseline()
        .with(Parameter::Exponent, 1.0)
        .unwrap()
        .with(Parameter::Stiffness, 1e5)
        .unwrap()
        .with(Parameter::Damping, 0.0)
        .unwrap();
    let omega = (1e5 / s.reduced_mass()).sqrt();
    let limit = largest_stable_rk4_step(&s, &s.contact_law());
    assert!((limit * omega - 8f64.sqrt()).abs() < 1e-12, "{}", limit * omega);
    for solver in [SolverChoice::SeedRk4(SeedRk4::new(1.01 * limit).unwrap()), SolverChoice::FullState(FullState::rk4_events(1.01 * limit))]
    {
        assert!(matches!(solver.solve(&s), Err(KickError::StepTooLarge { .. })), "{}", solver.name());
    }
    for solver in [SolverChoice::SeedRk4(SeedRk4::new(0.99 * limit).unwrap()), SolverChoice::FullState(FullState::rk4_events(0.99 * limit))]
    {
        assert!(matches!(solver.solve(&s), Err(KickError::StepTooInaccurate { .. })), "{}", solver.name());
    }
}

fn exit_error(o: &Outcome, exact: &Outcome, s: &Scenario) -> f64 {
    ((o.v_ball_out - exact.v_ball_out).abs()).max((o.v_foot_out - exact.v_foot_out).abs()) / s.approach_speed()
}

/// Just inside the largest step the checks accept, `rk4-events` works and
/// its exit velocities are within the bound (of V0); just outside it is
/// refused as a step too large.
#[test]
fn just_inside_the_accepted_step_still_works() {
    let tight = Accurate::new(1e-14, 1e-14).unwrap();
    for (case, s) in [("baseline", Scenario::baseline()), ("linear zeta=0.3", models::linear()[1].1)] {
        let exact = tight.solve(&s).unwrap();
        let accepted = |dt: f64| FullState::rk4_events(dt).solve(&s);
        // Bisect between an accepted and a refused step.
        let (mut low, mut high) = (1e-6, largest_stable_rk4_step(&s, &s.contact_law()));
        assert!(accepted(low).is_ok() && accepted(high).is_err());
        for _ in 0..40 {
            let mid = (low * high).sqrt();
            if accepted(mid).is_ok() {
                low = mid
            } else {
                high = mid
            }
        }
        let inside = accepted(0.99 * low).unwrap();
        assert!(exit_error(&inside, &exact, &s) <= ENERGY_RESIDUAL_BOUND, "{case}: {:e}", exit_error(&inside, &exact, &s));
        assert!(matches!(accepted(high), Err(KickError::StepTooInaccurate { .. })), "{case}");
    }
}

/// Over the shared test models and steps from far below to far above the
/// limits, `rk4-events` either answers within the bound or says the step
/// is too large; never another error.
#[test]
fn every_answer_is_within_the_bound_or_a_step_too_large() {
    let tight = Accurate::new(1e-14, 1e-14).unwrap();
    let mut worst: f64 = 0.0;
    for (case, s) in models::table2().into_iter().chain(models::elastic()).chain(models::linear()).chain(models::driven()) {
        let exact = tight.solve(&s).unwrap();
        let limit = largest_stable_rk4_step(&s, &s.contact_law());
        for fraction in [0.003, 0.01, 0.03, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99, 1.01, 2.0, 100.0] {
            let dt = fraction * limit;
            for solver in [SolverChoice::FullState(FullState::rk4_events(dt)), SolverChoice::SeedRk4(SeedRk4::new(dt).unwrap())] {
                match solver.solve(&s) {
                    Ok(o) if solver.name() == "rk4-events" => {
                        worst = worst.max(exit_error(&o, &exact, &s));
                        assert!(
                            exit_error(&o, &exact, &s) <= ENERGY_RESIDUAL_BOUND,
                            "{case} dt = {dt:e}: {:e}",
                            exit_error(&o, &exact, &s)
                        );
                    }
                    // The seed's stop is quantised to its step (documented).
                    Ok(o) => assert!(relative_energy_residual(&s, &s.contact_law(), &o.energy) <= ENERGY_RESIDUAL_BOUND),
                    Err(e) => assert!(is_step_too_large(&e), "{} {case} dt = {dt:e}: {e}", solver.name()),
                }
            }
        }
    }
    assert!(worst > 1e-5, "the ladder should reach the bound's neighbourhood: {worst:e}");
}

/// A blow-up the a-priori check cannot see (n < 1 is unboundedly stiff at
/// first touch) is still a step too large, not "no separation".
#[test]
fn a_softening_law_at_a_coarse_step_is_a_step_too_large() {
    let s = Scenario::baseline().with(Parameter::Exponent, 0.5).unwrap().with(Parameter::Stiffness, 1e3).unwrap();
    let limit = largest_stable_rk4_step(&s, &s.contact_law());
    for fraction in [0.3, 0.5, 0.9] {
        let error = SeedRk4::new(fraction * limit).unwrap().solve(&s).unwrap_err();
        assert!(matches!(error, KickError::StepTooInaccurate { .. }), "{fraction}: {error:?}");
    }
}

/// The paper's step and the benchmark's ladder pass on every benchmark case.
#[test]
fn the_paper_step_and_the_bench_ladder_pass() {
    let cases = precision::cases().unwrap();
    for (name, setting) in precision::ladder().into_iter().filter(|(n, _)| *n == "seed-rk4" || *n == "rk4-events") {
        let solver = precision::solver(name, setting).unwrap();
        for case in &cases {
            assert!(solver.solve(&case.scenario).is_ok(), "{name} {setting:e} {}", case.name);
        }
    }
}
