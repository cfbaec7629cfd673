//! The 1D contact beside published instep-kick measurements, and the
//! stiffness and foot mass those measurements imply (the validation chapter
//! of issue 14). Measurements: `experiments/validation/measurements.toml`
//! ([`kick_core::measurements`]).
//!
//! - [`contact_model`]: the model's counterparts of what was measured, for
//!   one scenario (contact time, ball travel on the foot, peak and mean
//!   force, exit speed, speed ratio, peak/mean force);
//! - [`contact_comparisons`]: those beside the measurements, one typed row each;
//! - [`contact_targets`]: the measurements as scalar observations of one
//!   "typical maximal instep kick" (midpoint ± half-width of each published
//!   range: a range is taken as ±1σ);
//! - [`implied_parameters`] / [`implied_parameter_study`]: least squares
//!   (`crate::fit`) of k, and m_f where the data reach it, to those targets,
//!   with uncertainties from the stated σ and the correlation.

use crate::data::{Observable, Observations, ScalarObservation};
use crate::fit::{fit, FitOptions, FitProblem, FitReport, Residual};
use crate::model::Trajectory;
use crate::parameter::{FitParameter, ModelPoint};
use crate::IdentifyError;
use kick_compliant::Accurate;
use kick_core::measurements::{Comparison, Measured, MeasurementError, Measurements};
use kick_core::{LawKind, Parameter, RecordingSolver, Scenario, Solver};
use nalgebra::DMatrix;
use serde::Serialize;
use thiserror::Error;

/// Named in errors about a missing measurement.
const NEEDED_BY: &str = "the 1D contact (kick_identify::validation)";

/// The measurement keys this module reads.
pub mod keys {
    pub const CONTACT_TIME: &str = "contact_time_instep";
    pub const BALL_TRAVEL: &str = "ball_travel_instep";
    pub const EFFECTIVE_FRACTION: &str = "effective_contact_fraction";
    /// Peak forces of soccer kicks, instep.
    pub const PEAK_FORCES: [&str; 3] = ["peak_force_instep_asai2002", "peak_force_tol2002", "peak_force_shinkai2009"];
    pub const MEAN_FORCE: &str = "mean_force_tol2002";
    pub const BALL_SPEED_TOL: &str = "ball_speed_tol2002";
    pub const PEAK_FORCE_PUNT: &str = "peak_force_punt";
    pub const MEAN_FORCE_PUNT: &str = "mean_force_punt";
    pub const BALL_SPEED: &str = "ball_speed_max_instep";
    pub const BALL_SPEED_NUNOME: &str = "ball_speed_instep_nunome2002";
}

/// Every way a contact validation can fail.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ValidationError {
    #[error(transparent)]
    Measurements(#[from] MeasurementError),
    #[error(transparent)]
    Identify(#[from] IdentifyError),
}

impl From<kick_core::KickError> for ValidationError {
    fn from(e: kick_core::KickError) -> Self {
        ValidationError::Identify(e.into())
    }
}

/// The model's counterparts of the measured quantities, for one contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactModel {
    /// t_c, s.
    pub contact_time: f64,
    /// x_b(t_c) − x_b(0), m: how far the ball moves while it touches the foot.
    pub ball_travel: f64,
    /// sup F, N (Eq. 20's includes F(0⁺) = c V0).
    pub peak_force: f64,
    /// J / t_c, N.
    pub mean_force: f64,
    /// v_b⁺, m/s.
    pub ball_speed: f64,
    /// v_b⁺ / v_f⁻.
    pub speed_ratio: f64,
    /// sup F · t_c / J: 1 for a rectangle, π/2 for a half sine.
    pub peak_to_mean: f64,
}

/// Solve one contact (accurate solver) and read off the counterparts.
pub fn contact_model(scenario: &Scenario) -> Result<ContactModel, IdentifyError> {
    let solver = Accurate::default();
    let interval = scenario.elastic_contact_time() * crate::model::RECORD_FRACTION;
    let (outcome, history) = solver.solve_recorded(scenario, interval)?;
    let trajectory = Trajectory::new(scenario, &outcome, history)?;
    let ball_travel = trajectory.state(outcome.contact_time)[2] - trajectory.state(0.0)[2];
    let mean_force = outcome.impulse / outcome.contact_time;
    Ok(ContactModel {
        contact_time: outcome.contact_time,
        ball_travel,
        peak_force: outcome.peak_force,
        mean_force,
        ball_speed: outcome.v_ball_out,
        // Table 1's foot speed is non-zero: the ratio is defined.
        speed_ratio: outcome.speed_ratio.unwrap_or(f64::NAN),
        peak_to_mean: outcome.peak_force / mean_force,
    })
}

/// The contact of `scenario` beside every 1D measurement, one row each.
pub fn contact_comparisons(m: &Measurements, scenario: &Scenario) -> Result<Vec<Comparison>, ValidationError> {
    let model = contact_model(scenario)?;
    let get = |key: &str| m.measured(key, NEEDED_BY);
    let contact = get(keys::CONTACT_TIME)?;
    let effective = get(keys::CONTACT_TIME)?
        .scaled_by(&get(keys::EFFECTIVE_FRACTION)?)
        .ok_or_else(|| invalid(m, keys::EFFECTIVE_FRACTION, "must be a dimensionless fraction >= 0"))?;
    let pulse = Measured::ratio(&get(keys::PEAK_FORCE_PUNT)?, &get(keys::MEAN_FORCE_PUNT)?)
        .ok_or_else(|| invalid(m, keys::MEAN_FORCE_PUNT, "must be > 0"))?;
    let stiff = "the model's ball is a sphere touching a rigid instep at one point with Table 1's k; a real ball \
                 wraps around the instep and its shell bends, which is softer and lasts longer";
    let mut rows = vec![
        Comparison::new("contact time", contact, model.contact_time, stiff),
        Comparison::new(
            "contact time vs the part of the measured contact that accelerates the ball",
            effective,
            model.contact_time,
            "measured contact scaled by Nunome et al.'s 3/4: the visually determined contact includes a tail in \
             which foot and ball no longer push on each other; every instant of the model's contact carries force",
        ),
        Comparison::new(
            "ball travel while on the foot",
            get(keys::BALL_TRAVEL)?,
            model.ball_travel,
            "equals the centre-of-mass drift m_f v_f t_c/(m_f + m_b) (no drive): short because the contact is short",
        ),
    ];
    for key in keys::PEAK_FORCES {
        rows.push(Comparison::new(
            "peak force",
            get(key)?,
            model.peak_force,
            "the stiffer model pushes the same impulse through in half the time, so its force is higher",
        ));
    }
    rows.push(Comparison::new(
        "mean force over contact",
        get(keys::MEAN_FORCE)?,
        model.mean_force,
        "at the model's own ball speed (below); the next row matches Tol et al.'s",
    ));
    let tol_speed = get(keys::BALL_SPEED_TOL)?;
    let target = tol_speed.midpoint().unwrap_or(f64::NAN);
    let matched = with_ball_speed(scenario, target)?;
    let matched_model = contact_model(&matched)?;
    rows.push(Comparison::new(
        "mean force over contact, at Tol et al.'s ball speed",
        get(keys::MEAN_FORCE)?,
        matched_model.mean_force,
        format!(
            "foot speed lowered to {:.2} m/s so the ball leaves at {target} m/s; the impulse then matches theirs \
             (0.43 kg x {target} m/s), so the force ratio is the inverse contact-time ratio (model {:.2} ms)",
            matched.foot_speed(),
            1e3 * matched_model.contact_time
        ),
    ));
    for key in [keys::BALL_SPEED, keys::BALL_SPEED_NUNOME] {
        rows.push(Comparison::new(
            "ball speed after contact",
            get(key)?,
            model.ball_speed,
            "set by m_f, v_f and the restitution; the model's foot speed is Table 1's, not a measured one",
        ));
    }
    rows.push(Comparison::new(
        "peak / mean force (pulse shape)",
        pulse,
        model.peak_to_mean,
        "measured in rugby-league punt kicks (the only soccer-like pulse whose peak and mean were read); a \
         half sine gives pi/2",
    ));
    Ok(rows)
}

/// `scenario` with the foot speed that sends the ball off at `ball_speed`
/// (Brent on v_f; the exit speed rises monotonically with it).
pub fn with_ball_speed(scenario: &Scenario, ball_speed: f64) -> Result<Scenario, ValidationError> {
    let solver = Accurate::default();
    let base = solver.solve(scenario)?.v_ball_out;
    let exit = |v_f: f64| match scenario.with(Parameter::FootSpeed, v_f).and_then(|s| solver.solve(&s)) {
        Ok(o) => o.v_ball_out - ball_speed,
        Err(_) => f64::NAN,
    };
    let guess = scenario.foot_speed() * ball_speed / base;
    let root = kick_core::roots::brent(exit, 0.5 * guess, 2.0 * guess, 1e-12 * guess, 200).ok_or(IdentifyError::NonFinite {
        quantity: "foot speed",
        reason: format!("no foot speed in [{:.3}, {:.3}] m/s sends the ball off at {ball_speed} m/s", 0.5 * guess, 2.0 * guess),
    })?;
    Ok(scenario.with(Parameter::FootSpeed, root.x)?)
}

fn invalid(m: &Measurements, key: &str, message: &str) -> ValidationError {
    ValidationError::Measurements(MeasurementError::Invalid { file: m.file.clone(), key: key.to_string(), message: message.to_string() })
}

/// The midpoint ± half-width of [low, high] as one observation.
fn observation(observable: Observable, low: f64, high: f64) -> ScalarObservation {
    ScalarObservation { observable, value: 0.5 * (low + high), sigma: 0.5 * (high - low) }
}

/// The measurements as scalar observations of one typical maximal instep
/// kick: contact time and ball speed from their published ranges, peak force
/// from the range of the three soccer instep peaks ([`keys::PEAK_FORCES`]);
/// each midpoint ± half-width, i.e. a published range taken as ±1σ.
pub fn contact_targets(m: &Measurements) -> Result<Observations, ValidationError> {
    let range = |key: &str| -> Result<(f64, f64), ValidationError> {
        let x = m.measured(key, NEEDED_BY)?;
        match (x.low, x.high) {
            (Some(lo), Some(hi)) if hi > lo => Ok((lo, hi)),
            _ => Err(invalid(m, key, "needs a range of nonzero width to give a sigma")),
        }
    };
    let (t_lo, t_hi) = range(keys::CONTACT_TIME)?;
    let (v_lo, v_hi) = range(keys::BALL_SPEED)?;
    let mut forces = Vec::with_capacity(keys::PEAK_FORCES.len());
    for key in keys::PEAK_FORCES {
        let x = m.measured(key, NEEDED_BY)?;
        forces.extend(x.low);
        forces.extend(x.high);
    }
    let f_lo = forces.iter().copied().fold(f64::INFINITY, f64::min);
    let f_hi = forces.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Ok(Observations::scalars(vec![
        observation(Observable::ContactTime, t_lo, t_hi),
        observation(Observable::VBallOut, v_lo, v_hi),
        observation(Observable::PeakForce, f_lo, f_hi),
    ])?)
}

/// One implied parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpliedEstimate {
    pub parameter: FitParameter,
    pub unit: &'static str,
    pub value: f64,
    /// Standard uncertainty with the observations' σ as stated: |dp/dθ|
    /// √((JᵀJ)⁻¹)ᵢᵢ, whatever χ² came out (the σ are published spreads, not
    /// noise estimates to be rescaled).
    pub sigma: f64,
    /// The same scaled by √(χ²/dof), as `kick fit` reports it (None when dof = 0).
    pub sigma_scaled: Option<f64>,
}

/// The parameters one model setup needs to meet the targets.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Implied {
    pub law: LawKind,
    /// Target restitution of a law other than the paper's.
    pub restitution: Option<f64>,
    /// v_f⁻ the model is driven at (held fixed: no foot speed was measured with the targets), m/s.
    pub foot_speed: f64,
    pub estimates: Vec<ImpliedEstimate>,
    /// Correlation of the estimates (stated σ), in `estimates` order.
    pub correlation: Vec<Vec<f64>>,
    pub chi_square: f64,
    pub degrees_of_freedom: i64,
    /// Observed, predicted and σ of each target at the estimate.
    pub residuals: Vec<Residual>,
    pub converged: bool,
}

impl Implied {
    pub fn estimate(&self, parameter: impl Into<FitParameter>) -> Option<&ImpliedEstimate> {
        let parameter = parameter.into();
        self.estimates.iter().find(|e| e.parameter == parameter)
    }
}

/// Least squares of `free` to `targets` from `start` (its law and fixed
/// values kept), with uncertainties from the stated σ.
pub fn implied_parameters(targets: &Observations, start: ModelPoint, free: &[FitParameter]) -> Result<Implied, ValidationError> {
    let problem = FitProblem { start, free: free.to_vec(), observations: targets.clone() };
    let report = fit(&problem, &FitOptions::default())?;
    let (sigma, correlation) = stated_covariance(&report)?;
    let scale = report.residual_variance.map(f64::sqrt);
    let estimates = report
        .estimates
        .iter()
        .zip(&sigma)
        .map(|(e, &s)| ImpliedEstimate {
            parameter: e.parameter,
            unit: e.parameter.unit(),
            value: e.value,
            sigma: s,
            sigma_scaled: scale.map(|k| k * s),
        })
        .collect();
    let scenario = start.scenario;
    Ok(Implied {
        law: report.law,
        restitution: scenario.restitution_target(),
        foot_speed: scenario.foot_speed(),
        estimates,
        correlation,
        chi_square: report.chi_square,
        degrees_of_freedom: report.degrees_of_freedom,
        residuals: report.residuals.clone(),
        converged: report.converged,
    })
}

/// Standard uncertainties (in p) and correlations from (JᵀJ)⁻¹ of the
/// weighted residuals' Jacobian in θ; refused when JᵀJ is singular.
fn stated_covariance(report: &FitReport) -> Result<(Vec<f64>, Vec<Vec<f64>>), ValidationError> {
    let n = report.estimates.len();
    let rows = report.jacobian.len();
    let j = DMatrix::from_fn(rows, n, |i, k| report.jacobian[i][k]);
    let cov = (j.transpose() * &j).try_inverse().ok_or(IdentifyError::NonFinite {
        quantity: "covariance",
        reason: "JᵀJ is singular: the targets do not determine these parameters together".into(),
    })?;
    let sigma_theta: Vec<f64> = (0..n).map(|i| cov[(i, i)].sqrt()).collect();
    let sigma = report.estimates.iter().zip(&sigma_theta).map(|(e, s)| e.coordinate.slope(e.value).abs() * s).collect();
    let correlation = (0..n).map(|i| (0..n).map(|k| cov[(i, k)] / (sigma_theta[i] * sigma_theta[k])).collect()).collect();
    Ok((sigma, correlation))
}

/// The setups the validation chapter reports, all from Table 1's baseline:
///
/// 1. the paper's law (Eq. 20), k and m_f free, v_f = 22 m/s;
/// 2. Hunt–Crossley (exact restitution) at the baseline's own restitution,
///    k and m_f free, v_f = 20, 22 and 24 m/s (m_f hangs on v_f);
/// 3. the same at v_f = 22 m/s with m_f held at 3 kg, k alone free.
pub fn implied_parameter_study(m: &Measurements) -> Result<Vec<Implied>, ValidationError> {
    let targets = contact_targets(m)?;
    let baseline = Scenario::baseline();
    let restitution = Accurate::default().solve(&baseline)?.restitution;
    let hunt_crossley = baseline.with_law(LawKind::HuntCrossleyExact, Some(restitution))?;
    let both = [FitParameter::Scenario(Parameter::Stiffness), FitParameter::Scenario(Parameter::FootMass)];
    let mut out = vec![implied_parameters(&targets, baseline.into(), &both)?];
    for foot_speed in [20.0, 22.0, 24.0] {
        let start = hunt_crossley.with(Parameter::FootSpeed, foot_speed)?;
        out.push(implied_parameters(&targets, start.into(), &both)?);
    }
    out.push(implied_parameters(&targets, hunt_crossley.into(), &both[..1])?);
    Ok(out)
}
