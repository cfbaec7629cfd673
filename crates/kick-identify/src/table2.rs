//! Table 2 by least squares: each row's one changed parameter from the four
//! printed observables together (v_b⁺, peak force, contact time, compression),
//! each weighted by its printed precision, σ = half a unit of the last
//! printed digit (a rounded number is uniform within ±σ of the truth; we use
//! σ as the scale, not as a Gaussian claim). The ratio column is left out: it
//! is v_b⁺/v_f⁻, no new information.
//!
//! The forward model is `Accurate`. The paper's numbers came from the 5 µs
//! fixed-step method, whose contact time is a multiple of the step and whose
//! peak force is a sampled value, so the accurate fit differs slightly from
//! `experiments/table2.toml` (seed-rk4 root on v_b⁺ alone).

use crate::data::{Observable, Observations, ScalarObservation};
use crate::fit::{fit, log_space, misfit, FitOptions, FitProblem, FitReport};
use crate::IdentifyError;
use kick_compliant::table2::ROW_PARAMETERS;
use kick_core::paper::{PrintedRow, TABLE2};
use kick_core::{Parameter, Scenario};
use serde::Serialize;

/// Printed precision: half a unit of the last digit, in SI units:
/// v_b⁺ 2 decimals (m/s), peak force 0 decimals (N), contact time 2 decimals
/// (ms), compression 2 decimals (mm).
pub const PRINTED_SIGMA: [(Observable, f64); 4] = [
    (Observable::VBallOut, 0.005),
    (Observable::PeakForce, 0.5),
    (Observable::ContactTime, 0.005e-3),
    (Observable::MaxCompression, 0.005e-3),
];

/// The four printed observables of a row, in SI units.
pub fn printed_observations(row: &PrintedRow) -> Observations {
    let value = |o: Observable| match o {
        Observable::VBallOut => row.v_ball_out,
        Observable::PeakForce => row.peak_force,
        Observable::ContactTime => row.contact_time_ms * 1e-3,
        Observable::MaxCompression => row.max_compression_mm * 1e-3,
        Observable::VFootOut | Observable::Restitution => f64::NAN, // not printed; not in PRINTED_SIGMA
    };
    Observations {
        scalars: PRINTED_SIGMA
            .iter()
            .map(|&(observable, sigma)| ScalarObservation { observable, value: value(observable), sigma })
            .collect(),
        history: None,
        measurements: Vec::new(),
    }
}

/// A solver's unrounded values of the four printed observables, with the
/// printed precision as σ (to fit the same model to them as to the print).
pub fn unrounded_observations(outcome: &kick_core::Outcome) -> Observations {
    Observations {
        scalars: PRINTED_SIGMA
            .iter()
            .map(|&(observable, sigma)| ScalarObservation { observable, value: observable.value(outcome), sigma })
            .collect(),
        history: None,
        measurements: Vec::new(),
    }
}

/// One row's answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table2Fit {
    pub name: String,
    /// The changed parameter; `None` for the baseline, which has nothing to fit.
    pub parameter: Option<Parameter>,
    /// The fit (for the baseline: residuals at Table 1's values, no estimate).
    pub report: Option<FitReport>,
    /// Baseline row only: weighted residuals of the four observables at Table 1.
    pub baseline_residuals: Option<Vec<(Observable, f64)>>,
}

impl Table2Fit {
    pub fn value(&self) -> Option<f64> {
        self.report.as_ref().map(|r| r.estimates[0].value)
    }
    pub fn standard_uncertainty(&self) -> Option<f64> {
        self.report.as_ref().and_then(|r| r.estimates[0].standard_uncertainty)
    }
}

/// Points of the coarse scan that picks each row's starting value.
pub const SCAN_POINTS: usize = 25;

/// Fit one row to the printed numbers. The start is the best of a coarse
/// scan over the row's search interval (`ROW_PARAMETERS`, log-spaced for
/// positive parameters): the peak force switches from the elastic maximum to
/// the onset value c V0 as c grows, and a start on the wrong side of that kink
/// can lead the optimiser away.
pub fn fit_row(index: usize, options: &FitOptions) -> Result<Table2Fit, IdentifyError> {
    let row = TABLE2.get(index).ok_or_else(|| IdentifyError::data("table2", format!("no row {index}")))?;
    fit_row_to(index, printed_observations(row), options)
}

/// As [`fit_row`] with other observations of the same four observables
/// (e.g. a solver's unrounded outputs).
pub fn fit_row_to(index: usize, observations: Observations, options: &FitOptions) -> Result<Table2Fit, IdentifyError> {
    let row = TABLE2.get(index).ok_or_else(|| IdentifyError::data("table2", format!("no row {index}")))?;
    let (parameter, low, high) = ROW_PARAMETERS[index];
    match parameter {
        None => {
            let outcome = kick_core::Solver::solve(&options.solver, &Scenario::baseline())?;
            let residuals =
                observations.scalars.iter().map(|s| (s.observable, (s.observable.value(&outcome) - s.value) / s.sigma)).collect();
            Ok(Table2Fit { name: row.name.into(), parameter: None, report: None, baseline_residuals: Some(residuals) })
        }
        Some(p) => {
            let start = scan(p, low, high, &observations, options)?;
            let problem = FitProblem { start: start.into(), free: vec![p.into()], observations };
            let report = fit(&problem, options)?;
            Ok(Table2Fit { name: row.name.into(), parameter: Some(p), report: Some(report), baseline_residuals: None })
        }
    }
}

/// The scan point with the least χ²; points where the model fails are skipped.
fn scan(p: Parameter, low: f64, high: f64, observations: &Observations, options: &FitOptions) -> Result<Scenario, IdentifyError> {
    let mut best: Option<(f64, Scenario)> = None;
    for i in 0..SCAN_POINTS {
        let u = i as f64 / (SCAN_POINTS - 1) as f64;
        let v = if log_space(p) { low * (high / low).powf(u) } else { low + (high - low) * u };
        let Ok(s) = Scenario::baseline().with(p, v) else { continue };
        let Ok(chi_square) = misfit(&options.solver, &s.into(), observations) else { continue };
        if best.is_none_or(|(b, _)| chi_square < b) {
            best = Some((chi_square, s));
        }
    }
    best.map(|(_, s)| s).ok_or_else(|| IdentifyError::data("table2", format!("no valid {} in [{low}, {high}]", p.name())))
}

/// All eight rows.
pub fn fit_all(options: &FitOptions) -> Result<Vec<Table2Fit>, IdentifyError> {
    (0..TABLE2.len()).map(|i| fit_row(i, options)).collect()
}
