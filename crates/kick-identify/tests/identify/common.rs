//! Shared by the recovery tests.

use kick_identify::{FitReport, ModelPoint};

/// |estimate − truth| < 3σ for each parameter, and s² within four standard
/// deviations of its expectation 1 (s² ~ χ²_ν/ν has sd √(2/ν)).
/// From exact data every estimate is the truth to 1e-6 (relative).
pub fn assert_exact(truth: &ModelPoint, report: &FitReport) {
    assert!(report.converged, "{}", report.termination);
    for e in &report.estimates {
        let t = truth.get(e.parameter).unwrap();
        assert!((e.value / t - 1.0).abs() < 1e-6, "{}: {} vs {t}", e.parameter.name(), e.value);
    }
}

pub fn assert_recovered(truth: &ModelPoint, report: &FitReport) {
    assert!(report.converged, "{}", report.termination);
    for e in &report.estimates {
        let sigma = e.standard_uncertainty.expect("identified");
        let t = truth.get(e.parameter).unwrap();
        println!("{:<12} {:.6e} ± {:.3e} (truth {t:.6e}, pull {:+.2})", e.parameter.name(), e.value, sigma, (e.value - t) / sigma);
        assert!((e.value - t).abs() < 3.0 * sigma, "{}: {} vs truth {t} (σ = {sigma})", e.parameter.name(), e.value);
    }
    let nu = report.degrees_of_freedom as f64;
    let s2 = report.residual_variance.unwrap();
    assert!((s2 - 1.0).abs() < 4.0 * (2.0 / nu).sqrt(), "s² = {s2} with ν = {nu}");
}
