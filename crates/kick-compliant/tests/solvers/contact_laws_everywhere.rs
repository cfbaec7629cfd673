//! Every 1D solver and the scenario itself accept the family of contact laws.

use kick_compliant::{Auto, ClosedForm, SolverChoice};
use kick_core::{KickError, LawKind, Parameter, Scenario, ScenarioSpec, Solver};

fn hunt_crossley_exact(restitution: f64) -> Scenario {
    Scenario::baseline().with_law(LawKind::HuntCrossleyExact, Some(restitution)).unwrap()
}

/// The exact-χ law meets its target restitution (its χ solves the energy
/// relation exactly), whichever event-located solver runs it.
#[test]
fn every_solver_reaches_the_target_restitution_of_the_exact_law() {
    for target in [0.9, 0.6, 0.3] {
        let scenario = hunt_crossley_exact(target);
        for name in ["auto", "accurate", "dopri5", "reduced"] {
            let outcome = SolverChoice::from_name(name, 5e-6).unwrap().solve(&scenario).unwrap();
            assert!((outcome.restitution - target).abs() < 1e-8, "{name}: e = {} for {target}", outcome.restitution);
            // Hunt–Crossley starts at zero force: no jump at first touch.
            assert!(outcome.peak_force_time > 0.0, "{name}");
        }
        // The seed method converges to it at its step's accuracy.
        let seed = SolverChoice::from_name("seed-rk4", 1e-7).unwrap().solve(&scenario).unwrap();
        assert!((seed.restitution - target).abs() < 1e-4, "seed-rk4: e = {}", seed.restitution);
    }
}

#[test]
fn the_law_choice_survives_parameter_changes_and_routes_auto() {
    let scenario = Scenario::baseline().with_law(LawKind::Flores, Some(0.7)).unwrap();
    let changed = scenario.with(Parameter::FootMass, 8.0).unwrap();
    assert_eq!(changed.law_kind(), LawKind::Flores);
    assert_eq!(changed.restitution_target(), Some(0.7));
    // No closed form and no closed-form return for the other laws.
    assert!(!ClosedForm::applies(&changed.with(Parameter::Damping, 0.0).unwrap()));
    assert_eq!(Auto::path(&changed), kick_core::SolverPath::Reduced);
    assert!(matches!(ClosedForm.solve(&changed), Err(KickError::NotApplicable { .. })));
    // Back to the paper's law.
    let paper = changed.with_law(LawKind::PowerLaw, None).unwrap();
    assert_eq!(paper.contact_law(), kick_core::AnyLaw::PowerLaw(paper.paper_law()));
}

#[test]
fn a_law_needs_a_valid_restitution() {
    let error = Scenario::baseline().with_law(LawKind::HuntCrossley, None).unwrap_err();
    assert!(error.to_string().contains("restitution"), "{error}");
    for bad in [0.0, -0.2, 1.5, f64::NAN] {
        let error = Scenario::baseline().with_law(LawKind::KelvinVoigt, Some(bad)).unwrap_err();
        assert!(error.to_string().contains("restitution"), "{error}");
    }
    let spec = ScenarioSpec { law: Some(LawKind::LankaraniNikravesh), restitution: Some(0.5), ..ScenarioSpec::default() };
    assert_eq!(spec.build().unwrap().law_kind(), LawKind::LankaraniNikravesh);
}

/// Kelvin–Voigt (n = 1 spring at the secant stiffness) against the exact
/// damped-oscillator restitution with its force clamped at zero: the
/// accurate and reduced solvers agree with each other.
#[test]
fn kelvin_voigt_agrees_between_solvers() {
    let scenario = Scenario::baseline().with_law(LawKind::KelvinVoigt, Some(0.6)).unwrap();
    let a = SolverChoice::from_name("accurate", 5e-6).unwrap().solve(&scenario).unwrap();
    let r = SolverChoice::from_name("reduced", 5e-6).unwrap().solve(&scenario).unwrap();
    for (x, y) in
        [(a.v_ball_out, r.v_ball_out), (a.contact_time, r.contact_time), (a.peak_force, r.peak_force), (a.restitution, r.restitution)]
    {
        assert!(((x - y) / y).abs() < 1e-9, "{x} vs {y}");
    }
}
