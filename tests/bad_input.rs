//! Every bad input gets a typed error that names the problem; no NaN, no hang.

use kick_compliant::{Accurate, SeedRk4, SolverChoice};
use kick_core::{KickError, Parameter, Scenario, ScenarioSpec, Solver, Status};

fn spec_with(parameter: Parameter, value: f64) -> ScenarioSpec {
    let mut spec = ScenarioSpec::default();
    spec.set(parameter, value);
    spec
}

#[test]
fn invalid_parameters_are_named() {
    let cases = [
        (Parameter::FootMass, 0.0),
        (Parameter::FootMass, -3.0),
        (Parameter::FootMass, f64::NAN),
        (Parameter::BallMass, f64::INFINITY),
        (Parameter::BallMass, 0.0),
        (Parameter::Stiffness, 0.0),
        (Parameter::Stiffness, -1.0),
        (Parameter::Exponent, 0.0),
        (Parameter::Exponent, f64::NAN),
        (Parameter::Damping, -0.1),
        (Parameter::Damping, f64::INFINITY),
        (Parameter::FootSpeed, f64::NAN),
        (Parameter::BallSpeed, f64::NEG_INFINITY),
        (Parameter::DriveForce, f64::NAN),
    ];
    for (parameter, value) in cases {
        let error = spec_with(parameter, value).build().unwrap_err();
        match &error {
            KickError::InvalidParameter { name, .. } => assert_eq!(*name, parameter.name()),
            other => panic!("{parameter:?} = {value}: unexpected {other:?}"),
        }
        assert!(error.to_string().contains(parameter.name()), "{error}");
    }
}

#[test]
fn a_foot_not_faster_than_the_ball_is_no_contact() {
    for (foot, ball) in [(10.0, 10.0), (5.0, 12.0), (-3.0, 0.0)] {
        let mut spec = spec_with(Parameter::FootSpeed, foot);
        spec.set(Parameter::BallSpeed, ball);
        let error = spec.build().unwrap_err();
        assert!(matches!(error, KickError::NoContact { .. }), "{error:?}");
        assert!(error.to_string().contains("no contact"), "{error}");
    }
}

/// A drive that keeps the ball pressed: the accurate solver proves it at the
/// first maximum compression (trapped, a physical outcome); the seed method
/// stops at the documented horizon (a numerical limit, not a proof).
#[test]
fn a_drive_that_never_lets_go_is_an_error_not_a_hang() {
    let scenario = Scenario::baseline().with(Parameter::DriveForce, 5.0e4).unwrap();
    let error = Accurate::default().solve(&scenario).unwrap_err();
    assert!(matches!(error, KickError::Trapped { .. }), "{error:?}");
    assert_eq!(error.status(), Status::Trapped);
    assert!(error.to_string().starts_with("trapped"), "{error}");
    let error = SeedRk4::new(5e-5).unwrap().solve(&scenario).unwrap_err();
    assert!(matches!(error, KickError::NoSeparation { .. }), "{error:?}");
    assert_eq!(error.status(), Status::NumericalFailure);
    assert!(error.to_string().contains("not proven trapped"), "{error}");
}

/// Without damping, ½μδ̇² + U(δ) − (μ/m_f)F_drive δ is conserved through the
/// whole contact, so any constant drive lets go and the relative speed comes
/// back exactly: e = 1 (Eq. 60 holds even with a drive).
#[test]
fn an_undamped_contact_always_releases_with_e_one() {
    let base = Scenario::baseline().with(Parameter::Damping, 0.0).unwrap();
    for drive in [1.0e3, 1.0e4, 1.0e5] {
        let outcome = Accurate::default().solve(&base.with(Parameter::DriveForce, drive).unwrap()).unwrap();
        assert!((outcome.restitution - 1.0).abs() < 1e-9, "drive {drive}: e = {}", outcome.restitution);
    }
}

/// With damping, the release criterion decides at the first maximum
/// compression. The seed method, which knows nothing of it and simply runs
/// to its horizon, agrees on both sides of the critical drive.
#[test]
fn release_criterion_agrees_with_the_seed_method() {
    let base = Scenario::baseline();
    let accurate = Accurate::default();
    let releases = |drive: f64| match accurate.solve(&base.with(Parameter::DriveForce, drive).unwrap()) {
        Ok(_) => true,
        Err(KickError::Trapped { .. }) => false,
        Err(e) => panic!("{e}"),
    };
    let (mut low, mut high) = (0.0, 1.0e5);
    assert!(releases(low) && !releases(high));
    for _ in 0..40 {
        let mid = 0.5 * (low + high);
        if releases(mid) { low = mid } else { high = mid }
    }
    let seed = SeedRk4::new(2e-6).unwrap();
    let below = base.with(Parameter::DriveForce, 0.97 * low).unwrap();
    let above = base.with(Parameter::DriveForce, 1.03 * high).unwrap();
    assert!(seed.solve(&below).is_ok(), "seed should separate at {} N", 0.97 * low);
    assert!(matches!(seed.solve(&above), Err(KickError::NoSeparation { .. })), "seed should not separate at {} N", 1.03 * high);
}

#[test]
fn bad_solver_settings_are_named() {
    let error = SolverChoice::from_name("euler", 5e-6).unwrap_err();
    assert!(error.to_string().contains("euler"));
    for dt in [0.0, -1e-6, f64::NAN] {
        let error = SeedRk4::new(dt).unwrap_err();
        assert!(error.to_string().contains("dt"), "{error}");
    }
    let error = SeedRk4::new(1e-15).unwrap().solve(&Scenario::baseline()).unwrap_err();
    assert!(error.to_string().contains("dt"), "{error}");
    assert!(Accurate::new(0.0, 1e-12).is_err());
    assert!(Accurate::new(1e-10, f64::NAN).is_err());
}

/// Significant digits of the longest number in `text` (mantissas only: the
/// digits before an exponent, leading zeros not counted).
fn longest_number(text: &str) -> usize {
    let mut longest = 0;
    let mut digits = 0;
    let mut leading = true;
    let mut in_exponent = false;
    let mut previous = ' ';
    for c in text.chars() {
        if c.is_ascii_digit() && !in_exponent {
            if c != '0' || !leading {
                leading = false;
                digits += 1;
            }
        } else if c == '.' && previous.is_ascii_digit() {
        } else if c == 'e' && previous.is_ascii_digit() {
            in_exponent = true;
        } else if in_exponent && (c.is_ascii_digit() || c == '-') {
        } else {
            longest = longest.max(digits);
            (digits, leading, in_exponent) = (0, true, false);
        }
        previous = c;
    }
    longest.max(digits)
}

/// Numbers in messages are in one short form (kick_core::short): 1e308 is
/// not 309 digits, a computed step not 16 (issue 13).
#[test]
fn numbers_in_messages_are_short() {
    assert_eq!(longest_number("dt = 1.047530233023196e-7 s, 0.00056, 717.433796 s, 1e308"), 16);
    assert_eq!(longest_number("dt = 1.0475e-7 s at 0.0056108 s"), 5);
    let error = spec_with(Parameter::FootMass, -1e308).build().unwrap_err();
    assert!(error.to_string().contains("`foot_mass` = -1e308:"), "{error}");
    let too_large = SeedRk4::default().solve(&Scenario::baseline().with(Parameter::Damping, 1e7).unwrap()).unwrap_err();
    let too_inaccurate = SolverChoice::from_name("rk4-events", 5e-6)
        .unwrap()
        .solve(&Scenario::baseline().with(Parameter::Stiffness, 1e12).unwrap())
        .unwrap_err();
    let horizon = SeedRk4::new(5e-5).unwrap().solve(&Scenario::baseline().with(Parameter::DriveForce, 5e4).unwrap()).unwrap_err();
    for error in [error, too_large, too_inaccurate, horizon, SeedRk4::new(1e-13).unwrap().solve(&Scenario::baseline()).unwrap_err()] {
        let text = error.to_string();
        assert!(longest_number(&text) <= kick_core::number::SHORT_DIGITS, "{text}");
    }
}
