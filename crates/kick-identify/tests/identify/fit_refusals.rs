//! What a fit refuses, and how it says why it stopped.

use kick_compliant::Accurate;
use kick_core::{Parameter, Scenario, Solver};
use kick_identify::data::{Observable, ScalarObservation};
use kick_identify::fit::{fit, FitOptions, FitProblem, FitStop};
use kick_identify::{IdentifyError, Observations};

fn exit_speed(value: f64, sigma: f64) -> ScalarObservation {
    ScalarObservation { observable: Observable::VBallOut, value, sigma }
}

fn problem(free: &[Parameter], observations: Vec<ScalarObservation>) -> FitProblem {
    FitProblem {
        start: Scenario::baseline().into(),
        free: free.iter().map(|&p| p.into()).collect(),
        observations: Observations::scalars(observations).unwrap(),
    }
}

/// Three free parameters from one number: "−2 degrees of freedom" is not a fit.
#[test]
fn fewer_observations_than_free_parameters_is_refused() {
    let p = problem(&[Parameter::Stiffness, Parameter::Damping, Parameter::Exponent], vec![exit_speed(26.0, 0.1)]);
    let error = fit(&p, &FitOptions::default()).unwrap_err();
    assert_eq!(error, IdentifyError::UnderDetermined { observations: 1, parameters: 3, repeats: 0 });
    let text = error.to_string();
    assert!(text.contains("under-determined") && text.contains("free parameters (3)") && text.contains("observations (1)"), "{text}");
    // As many observations as parameters is determined: no variance, no
    // uncertainties, but an answer.
    let truth = Accurate::default().solve(&Scenario::baseline().with(Parameter::Stiffness, 5e5).unwrap()).unwrap();
    let exact = problem(&[Parameter::Stiffness], vec![exit_speed(truth.v_ball_out, 0.1)]);
    let report = fit(&exact, &FitOptions::default()).unwrap();
    assert_eq!(report.degrees_of_freedom, 0);
    assert!(report.residual_variance.is_none() && report.estimates[0].standard_uncertainty.is_none());
    assert!((report.estimates[0].value - 5e5).abs() < 1e-6 * 5e5, "{}", report.estimates[0].value);
}

/// Weighted residuals beyond ~1e154 overflow χ²: refused, never "converged"
/// with an infinite χ² and NaN correlations.
#[test]
fn an_overflowing_chi_square_is_refused() {
    for (value, sigma) in [(1e160, 1.0), (26.0, 1e-300)] {
        let p = problem(&[Parameter::Stiffness], vec![exit_speed(value, sigma)]);
        match fit(&p, &FitOptions::default()) {
            Err(IdentifyError::NonFinite { quantity, reason }) => {
                assert_eq!(quantity, "chi-square");
                assert!(reason.contains("sigma"), "{reason}");
            }
            other => panic!("{value} ± {sigma}: {other:?}"),
        }
    }
    // An extreme sigma alone is fine when the model meets the data exactly.
    let p = problem(&[Parameter::Stiffness], vec![exit_speed(26.0, 1e-160)]);
    let report = fit(&p, &FitOptions::default()).unwrap();
    assert!(report.chi_square.is_finite() && report.converged, "{report:?}");
}

#[test]
fn stop_reasons_print_as_words() {
    let cases = [
        (FitStop::Converged { ftol: true, xtol: true }, "converged: reduction of chi-square and parameter step both below tolerance"),
        (FitStop::Converged { ftol: true, xtol: false }, "converged: reduction of chi-square below tolerance"),
        (FitStop::Converged { ftol: false, xtol: true }, "converged: parameter step below tolerance"),
        (FitStop::ResidualsZero, "converged: residuals exactly zero"),
        (FitStop::Orthogonal, "converged: residuals orthogonal to the Jacobian (gradient zero)"),
        (FitStop::LostPatience, "stopped: evaluation budget exhausted before convergence"),
        (FitStop::NonFinite { quantity: "residuals norm" }, "stopped: non-finite residuals norm"),
    ];
    for (stop, words) in cases {
        assert_eq!(stop.to_string(), words);
        assert_eq!(stop.converged(), words.starts_with("converged"));
    }
    let truth = Accurate::default().solve(&Scenario::baseline().with(Parameter::Damping, 150.0).unwrap()).unwrap();
    let p = problem(
        &[Parameter::Damping],
        vec![
            exit_speed(truth.v_ball_out, 0.01),
            ScalarObservation { observable: Observable::ContactTime, value: truth.contact_time, sigma: 1e-5 },
        ],
    );
    let report = fit(&p, &FitOptions::default()).unwrap();
    assert_eq!(report.termination, report.stop.to_string());
    assert!(report.termination.starts_with("converged: "), "{}", report.termination);
}

/// Arrays (from Python) get the CSV reader's checks, naming the index.
#[test]
fn history_arrays_are_checked() {
    use kick_identify::data::{Channel, HistoryData};
    let data = |times: Vec<f64>, force: Vec<f64>| HistoryData { times, channels: vec![(Channel::Force, force)] };
    assert!(data(vec![0.0, 1e-4], vec![1.0, 2.0]).checked("x").is_ok());
    let message = |d: HistoryData| d.checked("fit data").unwrap_err().to_string();
    assert_eq!(message(data(vec![0.0, 0.0], vec![1.0, 2.0])), "fit data: time[1] = 0 does not increase (time[0] = 0)");
    assert_eq!(message(data(vec![0.0, 1.0], vec![1.0])), "fit data: `force` has 1 values for 2 times");
    assert_eq!(message(data(vec![0.0, 1.0], vec![1.0, f64::NAN])), "fit data: force[1] = NaN is not finite");
    assert_eq!(message(data(vec![], vec![])), "fit data: no samples");
    let none = HistoryData { times: vec![0.0], channels: vec![] };
    assert!(message(none).starts_with("fit data: no data channel"));
}

/// Covariance in parameter units: σ² on the diagonal, ρ σ_i σ_j off it.
#[test]
fn covariance_from_correlation_and_uncertainties() {
    let mut observations = vec![exit_speed(30.0, 0.1)];
    observations.push(ScalarObservation { observable: Observable::ContactTime, value: 9e-3, sigma: 1e-4 });
    observations.push(ScalarObservation { observable: Observable::PeakForce, value: 4000.0, sigma: 50.0 });
    let report = fit(&problem(&[Parameter::FootMass, Parameter::Stiffness], observations), &FitOptions::default()).unwrap();
    let c = report.covariance().expect("determined");
    let rho = report.correlation.as_ref().unwrap();
    let s: Vec<f64> = report.estimates.iter().map(|e| e.standard_uncertainty.unwrap()).collect();
    assert_eq!(c[0][0], s[0] * s[0]);
    assert_eq!(c[1][1], s[1] * s[1]);
    assert_eq!(c[0][1], rho[0][1] * s[0] * s[1]);
    assert_eq!(c[0][1], c[1][0]);
}

/// A cancel check that says yes after N evaluations stops the fit there
/// (Python's `kick.fit` on Ctrl-C): stop `Cancelled`, not converged, the
/// check not asked again, and the report is of the best point evaluated,
/// its χ² the misfit an independent evaluation gives there, no larger than
/// the start's; no uncertainties (no Jacobian at a point the optimiser left).
#[test]
fn a_cancel_after_n_evaluations_stops_with_cancelled() {
    use kick_identify::fit::{fit_with_cancel, misfit};
    use std::cell::Cell;
    let solver = Accurate::default();
    let truth =
        solver.solve(&Scenario::baseline().with(Parameter::FootMass, 1.5).unwrap().with(Parameter::Stiffness, 2e6).unwrap()).unwrap();
    let observations = vec![
        exit_speed(truth.v_ball_out, 0.01),
        ScalarObservation { observable: Observable::ContactTime, value: truth.contact_time, sigma: 1e-6 },
        ScalarObservation { observable: Observable::PeakForce, value: truth.peak_force, sigma: 1.0 },
    ];
    let p = problem(&[Parameter::FootMass, Parameter::Stiffness], observations);
    let whole = fit(&p, &FitOptions::default()).unwrap();
    let n = 3;
    assert!(whole.converged && whole.evaluations > n + 1, "{whole:?}");
    let asked = Cell::new(0usize);
    let cancel = || {
        asked.set(asked.get() + 1);
        asked.get() > n
    };
    let report = fit_with_cancel(&p, &FitOptions::default(), &cancel).unwrap();
    assert_eq!(report.stop, FitStop::Cancelled);
    assert!(!report.converged && report.termination.starts_with("stopped: cancelled"), "{}", report.termination);
    assert_eq!(asked.get(), n + 1);
    assert!(report.evaluations <= n + 1, "{}", report.evaluations);
    let mut at = p.start;
    for e in &report.estimates {
        assert!(e.standard_uncertainty.is_none());
        at = at.with(e.parameter, e.value).unwrap();
    }
    let independent = misfit(&solver, &at, &p.observations).unwrap();
    assert!((report.chi_square - independent).abs() <= 1e-12 * independent, "{} vs {independent}", report.chi_square);
    assert!(report.chi_square <= misfit(&solver, &p.start, &p.observations).unwrap());
    assert!(report.chi_square > whole.chi_square);
    // A check that never says yes changes nothing.
    assert_eq!(fit_with_cancel(&p, &FitOptions::default(), &|| false).unwrap(), whole);
}
