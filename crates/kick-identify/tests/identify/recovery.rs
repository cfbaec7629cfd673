//! Synthetic recovery: data from known parameters plus seeded Gaussian noise
//! are fitted back, and the identifiability claim of Section 17.8.

use kick_compliant::Accurate;
use kick_core::{Parameter, Scenario};
use kick_identify::data::{Channel, Observable};
use kick_identify::fit::{fit, minimise, FitOptions, FitProblem};
use kick_identify::profile::{log_factors, profiles};
use kick_identify::synthetic::{history, lab_sigma, scalars, time_grid};
use kick_identify::{IdentifyError, ModelPoint};

use crate::common;
use common::assert_recovered;
use std::collections::BTreeMap;

use kick_identify::profile::MODEL_PARAMETERS as FOUR;

fn sigma(channels: &[Channel]) -> BTreeMap<Channel, f64> {
    lab_sigma(channels)
}

fn start_from(truth: &Scenario, factors: &[(Parameter, f64)]) -> ModelPoint {
    factors.iter().fold(*truth, |s, &(p, f)| s.with(p, truth.get(p) * f).unwrap()).into()
}

#[test]
fn recovers_stiffness_and_damping_from_force_and_compression() {
    let truth = Scenario::baseline();
    let options = FitOptions::default();
    let times = time_grid(&truth, 80, 1.2);
    let data = history(&options.solver, &truth.into(), times, &sigma(&[Channel::Force, Channel::Compression]), 11).unwrap();
    let start = start_from(&truth, &[(Parameter::Stiffness, 1.5), (Parameter::Damping, 0.6)]);
    let problem = FitProblem { start, free: vec![Parameter::Stiffness.into(), Parameter::Damping.into()], observations: data };
    let report = fit(&problem, &options).unwrap();
    assert_recovered(&truth.into(), &report);
    let r = report.correlation.as_ref().unwrap();
    assert!((r[0][1] - r[1][0]).abs() < 1e-12 && r[0][0] == 1.0);
}

#[test]
fn recovers_all_four_from_full_histories() {
    let truth = Scenario::baseline();
    let options = FitOptions::default();
    let times = time_grid(&truth, 80, 1.2);
    let channels = [Channel::Force, Channel::Compression, Channel::FootVelocity, Channel::BallVelocity];
    let data = history(&options.solver, &truth.into(), times, &sigma(&channels), 2026).unwrap();
    let start = start_from(
        &truth,
        &[(Parameter::FootMass, 1.2), (Parameter::Stiffness, 0.7), (Parameter::Damping, 1.4), (Parameter::Exponent, 0.9)],
    );
    let problem = FitProblem { start, free: FOUR.to_vec(), observations: data };
    let report = fit(&problem, &options).unwrap();
    assert_recovered(&truth.into(), &report);
    // k and n trade off (k δⁿ at δ ≈ δ_max): their estimates are strongly
    // correlated, and the matrix is a valid correlation matrix.
    let r = report.correlation.as_ref().unwrap();
    for i in 0..4 {
        assert!((r[i][i] - 1.0).abs() < 1e-12);
        for j in 0..4 {
            assert!(r[i][j].abs() <= 1.0 + 1e-12 && (r[i][j] - r[j][i]).abs() < 1e-12);
        }
    }
}

/// The reported uncertainty matches the actual scatter: over 30 noise seeds
/// the pulls z = (estimate − truth)/σ have mean z² distributed as χ²₃₀/30;
/// its 0.1% and 99.9% quantiles are 0.39 and 1.99.
#[test]
fn uncertainties_match_the_scatter_over_noise_seeds() {
    let truth = Scenario::baseline();
    let options = FitOptions::default();
    let times = time_grid(&truth, 40, 1.2);
    let sig = sigma(&[Channel::Force, Channel::Compression]);
    let mut sum_z2 = [0.0; 2];
    let runs = 30;
    for seed in 0..runs {
        let data = history(&options.solver, &truth.into(), times.clone(), &sig, 1000 + seed).unwrap();
        let problem = FitProblem {
            start: start_from(&truth, &[(Parameter::Stiffness, 1.2), (Parameter::Damping, 0.8)]),
            free: vec![Parameter::Stiffness.into(), Parameter::Damping.into()],
            observations: data,
        };
        let report = fit(&problem, &options).unwrap();
        for (k, e) in report.estimates.iter().enumerate() {
            let z = (e.value - ModelPoint::from(truth).get(e.parameter).unwrap()) / e.standard_uncertainty.unwrap();
            sum_z2[k] += z * z;
        }
    }
    for (k, s) in sum_z2.iter().enumerate() {
        let mean = s / runs as f64;
        assert!((0.39..1.99).contains(&mean), "parameter {k}: mean pull² {mean}");
    }
}

/// Exit speed alone: four parameters, one number. A fit refuses it as
/// under-determined; minimised anyway, the Jacobian has rank one, so no
/// uncertainty can be reported; each profile is flat (another parameter
/// compensates exactly), while the histories' profiles rise by more than 25
/// (five sigma) within a factor 1.4 either side.
#[test]
fn exit_speed_alone_does_not_identify_while_histories_do() {
    let truth = Scenario::baseline();
    let options = FitOptions::default();
    let exit = scalars(&options.solver, &truth, &[(Observable::VBallOut, 0.01)], None).unwrap();

    let start = start_from(&truth, &[(Parameter::Stiffness, 1.3), (Parameter::Damping, 0.8)]);
    let problem = FitProblem { start, free: FOUR.to_vec(), observations: exit.clone() };
    assert_eq!(fit(&problem, &options).unwrap_err(), IdentifyError::UnderDetermined { observations: 1, parameters: 4, repeats: 0 });
    let report = minimise(&problem, &options).unwrap();
    assert!(report.estimates.iter().all(|e| e.standard_uncertainty.is_none()));
    assert!(report.correlation.is_none());
    assert!(report.chi_square < 1e-6, "one equation, four unknowns: matched exactly ({})", report.chi_square);

    let factors = log_factors(1.4, 5);
    let flat = profiles(&truth.into(), &FOUR, &factors, &exit, &options).unwrap();
    for p in &flat {
        for point in &p.points {
            assert!(point.chi_square < 1e-6, "{} × {}: χ² {}", p.parameter.name(), point.factor, point.chi_square);
        }
    }

    let channels = [Channel::Force, Channel::Compression, Channel::FootVelocity, Channel::BallVelocity];
    let data = history(&options.solver, &truth.into(), time_grid(&truth, 40, 1.2), &sigma(&channels), 5).unwrap();
    let sharp = profiles(&truth.into(), &FOUR, &factors, &data, &options).unwrap();
    for p in &sharp {
        let centre = p.points[2].chi_square;
        for end in [&p.points[0], &p.points[4]] {
            assert!(end.chi_square - centre > 25.0, "{} × {}: Δχ² {}", p.parameter.name(), end.factor, end.chi_square - centre);
        }
    }
}

#[test]
fn bad_fit_requests_are_refused_by_name() {
    let truth = Scenario::baseline();
    let options = FitOptions::default();
    let exit = scalars(&Accurate::default(), &truth, &[(Observable::VBallOut, 0.01)], None).unwrap();
    let problem = |free: Vec<Parameter>, start: Scenario| FitProblem {
        start: start.into(),
        free: free.into_iter().map(Into::into).collect(),
        observations: exit.clone(),
    };
    assert_eq!(fit(&problem(vec![], truth), &options).unwrap_err(), IdentifyError::NoFreeParameters);
    assert_eq!(
        fit(&problem(vec![Parameter::Damping, Parameter::Damping], truth), &options).unwrap_err(),
        IdentifyError::DuplicateParameter("damping")
    );
    let undamped = truth.with(Parameter::Damping, 0.0).unwrap();
    let e = fit(&problem(vec![Parameter::Damping], undamped), &options).unwrap_err();
    assert!(matches!(e, IdentifyError::StartOutOfRange { name: "damping", .. }), "{e}");
    assert!(e.to_string().contains("> 0"), "{e}");
    let mut empty = problem(vec![Parameter::Damping], truth);
    empty.observations.scalars.clear();
    assert_eq!(fit(&empty, &options).unwrap_err(), IdentifyError::NoData);
    let mut bad_sigma = problem(vec![Parameter::Damping], truth);
    bad_sigma.observations.scalars[0].sigma = 0.0;
    assert!(fit(&bad_sigma, &options).unwrap_err().to_string().contains("sigma"));
}
