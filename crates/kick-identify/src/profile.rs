//! Identifiability (Section 17.8): misfit profiles and maps.
//!
//! The profile of parameter p_j is χ²_j(v) = min over the other free
//! parameters of χ² with p_j fixed at v. A flat profile means the data cannot
//! tell v from the truth; Δχ² = χ²_j(v) − min χ² ≥ 1 marks a one-sigma
//! departure (one parameter of interest).

use crate::data::{Channel, Observable, Observations};
use crate::fit::{minimise, misfit, FitOptions, FitProblem};
use crate::parameter::{FitParameter, ModelPoint};
use crate::synthetic;
use crate::IdentifyError;
use kick_core::{Parameter, Scenario};
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ProfilePoint {
    /// p_j / truth.
    pub factor: f64,
    pub value: f64,
    /// Minimum χ² over the other free parameters.
    pub chi_square: f64,
    /// The other parameters at that minimum, as factors of their truth.
    pub others: Vec<(FitParameter, f64)>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Profile {
    pub parameter: FitParameter,
    pub truth: f64,
    pub points: Vec<ProfilePoint>,
}

/// Profile each of `free` over `factors` × its value in `truth`, re-fitting
/// the others from the truth (a start that favours the flat direction least).
pub fn profiles(
    truth: &ModelPoint,
    free: &[FitParameter],
    factors: &[f64],
    observations: &Observations,
    options: &FitOptions,
) -> Result<Vec<Profile>, IdentifyError> {
    let mut out = Vec::new();
    for &p in free {
        let others: Vec<FitParameter> = free.iter().copied().filter(|&q| q != p).collect();
        let mut points = Vec::new();
        for &factor in factors {
            let value = truth.get(p)? * factor;
            let start = truth.with(p, value)?;
            let (chi_square, refit) = if others.is_empty() {
                (misfit(&options.solver, &start, observations)?, Vec::new())
            } else {
                let problem = FitProblem { start, free: others.clone(), observations: observations.clone() };
                // The exit speed alone leaves the others under-determined:
                // that flat minimum is what a profile shows.
                let report = minimise(&problem, options)?;
                let refit = report
                    .estimates
                    .iter()
                    .map(|e| Ok((e.parameter, e.value / truth.get(e.parameter)?)))
                    .collect::<Result<Vec<_>, IdentifyError>>()?;
                (report.chi_square, refit)
            };
            points.push(ProfilePoint { factor, value, chi_square, others: refit });
        }
        out.push(Profile { parameter: p, truth: truth.get(p)?, points });
    }
    Ok(out)
}

/// χ² on a grid of factors of two parameters, the rest at `truth`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MisfitMap {
    pub x: FitParameter,
    pub y: FitParameter,
    pub x_factors: Vec<f64>,
    pub y_factors: Vec<f64>,
    /// chi_square[iy][ix].
    pub chi_square: Vec<Vec<f64>>,
}

pub fn misfit_map(
    truth: &ModelPoint,
    (x, y): (FitParameter, FitParameter),
    x_factors: &[f64],
    y_factors: &[f64],
    observations: &Observations,
    options: &FitOptions,
) -> Result<MisfitMap, IdentifyError> {
    let mut chi_square = Vec::with_capacity(y_factors.len());
    let (x0, y0) = (truth.get(x)?, truth.get(y)?);
    for &fy in y_factors {
        let mut row = Vec::with_capacity(x_factors.len());
        for &fx in x_factors {
            let point = truth.with(x, x0 * fx)?.with(y, y0 * fy)?;
            row.push(misfit(&options.solver, &point, observations)?);
        }
        chi_square.push(row);
    }
    Ok(MisfitMap { x, y, x_factors: x_factors.to_vec(), y_factors: y_factors.to_vec(), chi_square })
}

/// Factors spaced evenly in log between 1/`spread` and `spread`.
pub fn log_factors(spread: f64, count: usize) -> Vec<f64> {
    let count = count.max(2);
    let l = spread.ln();
    (0..count).map(|i| (-l + 2.0 * l * i as f64 / (count - 1) as f64).exp()).collect()
}

/// Section 17.8's claim, as data: profiles of (m_f, k, c, n) and (k, c)
/// misfit maps from the exit speed alone and from full noisy histories of
/// the same truth.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IdentifiabilityStudy {
    pub truth: Scenario,
    /// σ of the exit speed, m/s.
    pub exit_speed_sigma: f64,
    /// Channel noise of the histories.
    pub history_sigma: Vec<(Channel, f64)>,
    pub history_times: usize,
    pub seed: u64,
    pub exit_speed_profiles: Vec<Profile>,
    pub history_profiles: Vec<Profile>,
    pub exit_speed_map: MisfitMap,
    pub history_map: MisfitMap,
}

/// The four parameters of the paper's inverse problem (Section 19).
pub const MODEL_PARAMETERS: [FitParameter; 4] = [
    FitParameter::Scenario(Parameter::FootMass),
    FitParameter::Scenario(Parameter::Stiffness),
    FitParameter::Scenario(Parameter::Damping),
    FitParameter::Scenario(Parameter::Exponent),
];

/// Profiles over `profile_points` factors in [1/spread, spread] and maps on a
/// `map_points`² grid, for `truth` with exit-speed σ 0.01 m/s and the four
/// channels at [`synthetic::lab_sigma`] on `times` samples over 1.2 contact times.
pub fn identifiability_study(
    truth: &Scenario,
    spread: f64,
    profile_points: usize,
    map_points: usize,
    times: usize,
    seed: u64,
    options: &FitOptions,
) -> Result<IdentifiabilityStudy, IdentifyError> {
    if !(spread.is_finite() && spread > 1.0) {
        return Err(IdentifyError::data("spread", format!("{spread}: must be finite and > 1")));
    }
    let exit_speed_sigma = 0.01;
    let exit = synthetic::scalars(&options.solver, truth, &[(Observable::VBallOut, exit_speed_sigma)], None)?;
    let channels = Channel::ALL;
    let sigma = synthetic::lab_sigma(&channels);
    let point = ModelPoint::from(*truth);
    let histories = synthetic::history(&options.solver, &point, synthetic::time_grid(truth, times, 1.2), &sigma, seed)?;
    let factors = log_factors(spread, profile_points);
    let map_factors = log_factors(spread, map_points);
    let pair = (Parameter::Stiffness.into(), Parameter::Damping.into());
    Ok(IdentifiabilityStudy {
        truth: *truth,
        exit_speed_sigma,
        history_sigma: sigma.into_iter().collect(),
        history_times: times,
        seed,
        exit_speed_profiles: profiles(&point, &MODEL_PARAMETERS, &factors, &exit, options)?,
        history_profiles: profiles(&point, &MODEL_PARAMETERS, &factors, &histories, options)?,
        exit_speed_map: misfit_map(&point, pair, &map_factors, &map_factors, &exit, options)?,
        history_map: misfit_map(&point, pair, &map_factors, &map_factors, &histories, options)?,
    })
}
