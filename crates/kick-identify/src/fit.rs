//! Levenberg–Marquardt over a subset of the model's parameters
//! ([`FitParameter`]: the scenario's, the target restitution, the time offset).
//!
//! Residuals are r_i = (model_i − data_i)/σ_i. Parameters that must be
//! positive (masses, k, c, n) are fitted as θ = ln p and the restitution as
//! θ = ln(e/(1 − e)), so every trial point is a valid scenario and steps are
//! relative; speeds, the drive and the time offset are fitted as they are
//! ([`Coordinate`]). The Jacobian is taken by central differences (Accurate's
//! outputs are smooth in the parameters to its 1e-12 tolerance).
//!
//! Uncertainties: with J the Jacobian of r in θ at the estimate, m residuals
//! and n parameters, s² = Σ r²/(m − n) and cov θ = s² (JᵀJ)⁻¹; a parameter's
//! standard uncertainty is |dp/dθ| σ_θ (first order). The correlation matrix
//! is invariant under these one-to-one rescalings to first order, so it is
//! the same in θ and in p.
//!
//! Refused: fewer observations than free parameters
//! ([`IdentifyError::UnderDetermined`]), a history whose fitted contact
//! explains it no better than none ([`IdentifyError::NoContact`]), and any non-finite χ², estimate,
//! uncertainty, correlation or singular value ([`IdentifyError::NonFinite`]):
//! weighted residuals beyond ~1e154 overflow χ² even where the optimiser's
//! own norm does not. How the optimiser stopped is a [`FitStop`], printed
//! in words.
//!
//! A caller may cancel ([`fit_with_cancel`]: Python's `kick.fit` on Ctrl-C):
//! the closure is asked before every model evaluation, and a fit it cancels
//! stops with [`FitStop::Cancelled`] at the best point evaluated so far.

use crate::data::Observations;
use crate::model::{outside_validity, predict, without_contact};
use crate::parameter::{Coordinate, FitParameter, ModelPoint};
use crate::IdentifyError;
use kick_compliant::Accurate;
use kick_core::{LawKind, Parameter};
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};
use serde::Serialize;
use std::cell::{Cell, RefCell};

/// Relative singular value below which JᵀJ is treated as singular: the
/// finite-difference Jacobian is accurate to about 1e-6 relative, so
/// directions weaker than that are not resolved by the data.
pub const RANK_TOLERANCE: f64 = 1e-6;

/// Central-difference step in θ (relative step for log and logit
/// coordinates; for the time offset, this fraction of the contact time).
pub const JACOBIAN_STEP: f64 = 1e-6;

/// What to fit.
#[derive(Debug, Clone, PartialEq)]
pub struct FitProblem {
    /// Known values and starting guesses of the free parameters; the
    /// scenario's contact law is the forward model's.
    pub start: ModelPoint,
    pub free: Vec<FitParameter>,
    pub observations: Observations,
}

/// Solver and optimiser settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitOptions {
    pub solver: Accurate,
    /// Bound on residual evaluations: patience × (n + 1) (crate semantics).
    pub patience: usize,
    /// ftol = xtol of the optimiser.
    pub tolerance: f64,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions { solver: Accurate::default(), patience: 100, tolerance: 1e-10 }
    }
}

/// How the optimiser stopped (Levenberg–Marquardt's termination, in words
/// by `Display`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum FitStop {
    /// MINPACK's tests: `ftol`, the relative reduction of χ² (actual and
    /// predicted) below tolerance; `xtol`, the relative step below tolerance.
    Converged { ftol: bool, xtol: bool },
    /// The weighted residuals are exactly zero.
    ResidualsZero,
    /// The residuals are orthogonal to the Jacobian's columns (gradient zero).
    Orthogonal,
    /// A tolerance was set below what rounding allows.
    NoImprovementPossible { tolerance: &'static str },
    /// The evaluation budget (patience) ran out.
    LostPatience,
    /// The model could not be evaluated.
    ModelFailed,
    /// A non-finite value stopped the optimiser.
    NonFinite { quantity: &'static str },
    /// The problem had no parameters, no residuals or inconsistent sizes.
    Malformed { problem: &'static str },
    /// The caller's cancel check returned true ([`fit_with_cancel`]); the
    /// report is of the best point evaluated before, without uncertainties.
    Cancelled,
}

impl FitStop {
    fn of(reason: &TerminationReason) -> FitStop {
        match *reason {
            TerminationReason::Converged { ftol, xtol } => FitStop::Converged { ftol, xtol },
            TerminationReason::ResidualsZero => FitStop::ResidualsZero,
            TerminationReason::Orthogonal => FitStop::Orthogonal,
            TerminationReason::NoImprovementPossible(tolerance) => FitStop::NoImprovementPossible { tolerance },
            TerminationReason::LostPatience => FitStop::LostPatience,
            TerminationReason::User(_) => FitStop::ModelFailed,
            TerminationReason::Numerical(quantity) => FitStop::NonFinite { quantity },
            TerminationReason::NoParameters => FitStop::Malformed { problem: "no parameters" },
            TerminationReason::NoResiduals => FitStop::Malformed { problem: "no residuals" },
            TerminationReason::WrongDimensions(what) => FitStop::Malformed { problem: what },
        }
    }

    /// A stop at a (local) minimum.
    pub fn converged(&self) -> bool {
        matches!(self, FitStop::Converged { .. } | FitStop::ResidualsZero | FitStop::Orthogonal)
    }
}

impl std::fmt::Display for FitStop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            FitStop::Converged { ftol: true, xtol: true } => {
                write!(f, "converged: reduction of chi-square and parameter step both below tolerance")
            }
            FitStop::Converged { ftol: true, xtol: false } => write!(f, "converged: reduction of chi-square below tolerance"),
            FitStop::Converged { .. } => write!(f, "converged: parameter step below tolerance"),
            FitStop::ResidualsZero => write!(f, "converged: residuals exactly zero"),
            FitStop::Orthogonal => write!(f, "converged: residuals orthogonal to the Jacobian (gradient zero)"),
            FitStop::NoImprovementPossible { tolerance } => {
                write!(f, "stopped: no improvement possible at the set {tolerance} (below rounding)")
            }
            FitStop::LostPatience => write!(f, "stopped: evaluation budget exhausted before convergence"),
            FitStop::ModelFailed => write!(f, "stopped: the model could not be evaluated"),
            FitStop::NonFinite { quantity } => write!(f, "stopped: non-finite {quantity}"),
            FitStop::Malformed { problem } => write!(f, "stopped: malformed problem ({problem})"),
            FitStop::Cancelled => write!(f, "stopped: cancelled by the caller (best point so far, no uncertainties)"),
        }
    }
}

/// One fitted parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Estimate {
    pub parameter: FitParameter,
    pub value: f64,
    /// Standard uncertainty; `None` when the data do not determine it
    /// (JᵀJ singular, or no more residuals than parameters).
    pub standard_uncertainty: Option<f64>,
    pub start: f64,
    /// The optimiser's coordinate θ of this parameter.
    pub coordinate: Coordinate,
}

/// One residual.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Residual {
    pub label: String,
    pub observed: f64,
    pub predicted: f64,
    pub sigma: f64,
    /// (predicted − observed)/sigma.
    pub weighted: f64,
}

/// The answer of a fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FitReport {
    /// The forward model's contact law.
    pub law: LawKind,
    pub estimates: Vec<Estimate>,
    pub residuals: Vec<Residual>,
    /// Σ r².
    pub chi_square: f64,
    /// m − n.
    pub degrees_of_freedom: i64,
    /// s² = χ²/(m − n); `None` when m ≤ n.
    pub residual_variance: Option<f64>,
    /// Correlation matrix of the estimates, in `estimates` order.
    pub correlation: Option<Vec<Vec<f64>>>,
    /// Singular values of J (θ space), largest first: a near-zero one marks an
    /// unidentifiable combination.
    pub singular_values: Vec<f64>,
    pub stop: FitStop,
    /// `stop` in words.
    pub termination: String,
    pub converged: bool,
    pub evaluations: usize,
    /// The contacts that, at the estimate, leave their law's validity
    /// (`kick_core::validity`): the numbers fitted there are the law's,
    /// not a ball's. Empty when every one holds.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub outside_validity: Vec<OutsideAt>,
    /// ∂r_i/∂θ_j at the estimate (weighted residuals, θ = ln p for log-space
    /// parameters), row-major; left out of serialized reports.
    #[serde(skip)]
    pub jacobian: Vec<Vec<f64>>,
}

/// A contact of a fit outside its law's validity at the estimate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OutsideAt {
    /// The measurement's name; empty for the top-level observations.
    pub measurement: String,
    #[serde(flatten)]
    pub outside: kick_core::OutsideValidity,
}

impl std::fmt::Display for OutsideAt {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.measurement.as_str() {
            "" => write!(f, "{}", self.outside),
            name => write!(f, "measurement `{name}`: {}", self.outside),
        }
    }
}

impl FitReport {
    pub fn estimate(&self, parameter: impl Into<FitParameter>) -> Option<&Estimate> {
        let parameter = parameter.into();
        self.estimates.iter().find(|e| e.parameter == parameter)
    }

    /// Covariance of the estimates (in `estimates` order, units of the
    /// parameters), to first order in the coordinate change θ → p:
    /// ρ_ij σ_i σ_j. `None` when the uncertainties are.
    pub fn covariance(&self) -> Option<Vec<Vec<f64>>> {
        let correlation = self.correlation.as_ref()?;
        let sigma: Option<Vec<f64>> = self.estimates.iter().map(|e| e.standard_uncertainty).collect();
        let sigma = sigma?;
        Some(
            correlation.iter().enumerate().map(|(i, row)| row.iter().enumerate().map(|(j, r)| r * sigma[i] * sigma[j]).collect()).collect(),
        )
    }
}

/// Scenario parameters fitted as ln p because they must be positive.
pub fn log_space(parameter: Parameter) -> bool {
    FitParameter::Scenario(parameter).coordinate() == Coordinate::Log
}

/// The LM problem in θ.
struct Problem<'a> {
    problem: &'a FitProblem,
    options: &'a FitOptions,
    observed: DVector<f64>,
    sigma: DVector<f64>,
    theta: DVector<f64>,
    /// Largest residual norm seen at a valid point; a failing trial point
    /// is given 10x that, so the trust region shrinks away from it.
    worst: RefCell<f64>,
    failure: RefCell<Option<IdentifyError>>,
    /// Asked before every evaluation; true stops the optimiser.
    cancel: &'a dyn Fn() -> bool,
    cancelled: Cell<bool>,
    /// The valid point of smallest residual norm so far: (θ, weighted residuals).
    best: RefCell<(DVector<f64>, DVector<f64>)>,
}

impl Problem<'_> {
    fn point(&self, theta: &DVector<f64>) -> Result<ModelPoint, IdentifyError> {
        let mut point = self.problem.start;
        for (p, &t) in self.problem.free.iter().zip(theta.iter()) {
            point = point.with(*p, p.coordinate().value(t))?;
        }
        Ok(point)
    }

    fn weighted(&self, theta: &DVector<f64>) -> Result<DVector<f64>, IdentifyError> {
        let point = self.point(theta)?;
        let predicted = predict(&self.options.solver, &point, &self.problem.observations)?;
        Ok(DVector::from_iterator(
            predicted.len(),
            predicted.iter().zip(self.observed.iter()).zip(self.sigma.iter()).map(|((p, o), s)| (p - o) / s),
        ))
    }

    /// Whether the caller cancelled (asked once more unless it already did).
    fn cancelled(&self) -> bool {
        if !self.cancelled.get() && (self.cancel)() {
            self.cancelled.set(true);
        }
        self.cancelled.get()
    }

    /// Residuals at θ, or a large penalty if the model fails there.
    fn residuals_or_penalty(&self, theta: &DVector<f64>) -> DVector<f64> {
        match self.weighted(theta) {
            Ok(r) => {
                let norm = r.norm();
                let mut worst = self.worst.borrow_mut();
                *worst = worst.max(norm);
                let mut best = self.best.borrow_mut();
                if norm < best.1.norm() {
                    *best = (theta.clone(), r.clone());
                }
                r
            }
            Err(e) => {
                let m = self.observed.len();
                let level = 10.0 * self.worst.borrow().max(1.0) / (m as f64).sqrt();
                *self.failure.borrow_mut() = Some(e);
                DVector::from_element(m, level)
            }
        }
    }

    fn steps(&self) -> Vec<f64> {
        let time_scale = self.problem.start.scenario.elastic_contact_time();
        self.problem
            .free
            .iter()
            .zip(self.theta.iter())
            .map(|(p, &t)| match (p, p.coordinate()) {
                (FitParameter::TimeOffset, _) => JACOBIAN_STEP * time_scale,
                (_, Coordinate::Linear) => JACOBIAN_STEP * t.abs().max(1.0),
                (_, Coordinate::Log | Coordinate::Logit) => JACOBIAN_STEP,
            })
            .collect()
    }

    fn jacobian_at(&self, theta: &DVector<f64>) -> Result<DMatrix<f64>, IdentifyError> {
        let m = self.observed.len();
        let n = theta.len();
        let mut j = DMatrix::zeros(m, n);
        for (col, h) in self.steps().into_iter().enumerate() {
            let mut plus = theta.clone();
            plus[col] += h;
            let mut minus = theta.clone();
            minus[col] -= h;
            let column = (self.weighted(&plus)? - self.weighted(&minus)?) / (2.0 * h);
            j.set_column(col, &column);
        }
        Ok(j)
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.theta.copy_from(x);
    }
    fn params(&self) -> DVector<f64> {
        self.theta.clone()
    }
    fn residuals(&self) -> Option<DVector<f64>> {
        if self.cancelled() {
            return None;
        }
        Some(self.residuals_or_penalty(&self.theta))
    }
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        if self.cancelled() {
            return None;
        }
        match self.jacobian_at(&self.theta) {
            Ok(j) => Some(j),
            Err(e) => {
                *self.failure.borrow_mut() = Some(e);
                None
            }
        }
    }
}

/// Restarts of the onset search (see [`fit`]).
pub const MAX_ONSET_RESTARTS: usize = 20;

/// Fit `problem` and report estimates, uncertainties, residuals and correlations.
///
/// With the time offset free, χ² jumps whenever a history sample crosses
/// the onset t0: Eq. 20's force jumps to c V0 at first touch, and every
/// law's velocities and compression have a kink there. Levenberg–Marquardt
/// cannot step across such a jump, so it can stop with a sample on the
/// wrong side. After it converges, the fit restarts from its estimate with
/// t0 moved past the neighbouring sample on either side, keeps the lower
/// χ², and repeats until neither side improves.
///
/// Fewer observations than free parameters is refused
/// ([`IdentifyError::UnderDetermined`]); [`minimise`] allows it.
pub fn fit(problem: &FitProblem, options: &FitOptions) -> Result<FitReport, IdentifyError> {
    fit_checked(problem, options, true, &|| false)
}

/// As [`fit`], asking `cancel` before every model evaluation (and before
/// each onset restart): once it returns true the fit stops with
/// [`FitStop::Cancelled`], reporting the best point evaluated so far.
pub fn fit_with_cancel(problem: &FitProblem, options: &FitOptions, cancel: &dyn Fn() -> bool) -> Result<FitReport, IdentifyError> {
    fit_checked(problem, options, true, cancel)
}

/// As [`fit`], but an under-determined problem is minimised too: for
/// misfit profiles ([`crate::profile`]), where a χ² minimum that other
/// parameters reach exactly is the finding. Uncertainties are then `None`.
pub fn minimise(problem: &FitProblem, options: &FitOptions) -> Result<FitReport, IdentifyError> {
    fit_checked(problem, options, false, &|| false)
}

/// A fit's time is bounded: each residual records the model only over the
/// data's span (`model::record_until`; at most `MAX_HISTORY_SAMPLES`), each
/// Levenberg–Marquardt run makes at most patience × (n + 1) residual
/// evaluations and as many Jacobians of 2n each, and there are at most
/// 1 + 2 × [`MAX_ONSET_RESTARTS`] runs.
fn fit_checked(
    problem: &FitProblem,
    options: &FitOptions,
    determined: bool,
    cancel: &dyn Fn() -> bool,
) -> Result<FitReport, IdentifyError> {
    let report = fit_onsets(problem, options, determined, cancel)?;
    if determined && problem.observations.has_history() && report.stop != FitStop::Cancelled {
        check_contact(problem, options, &report)?;
    }
    Ok(report)
}

/// One run, then (t0 free, with a history) the onset restarts of [`fit`].
fn fit_onsets(problem: &FitProblem, options: &FitOptions, determined: bool, cancel: &dyn Fn() -> bool) -> Result<FitReport, IdentifyError> {
    let mut best = fit_from(problem, options, determined, cancel)?;
    let (Some(index), Some(history)) =
        (problem.free.iter().position(|&p| p == FitParameter::TimeOffset), problem.observations.history.as_ref())
    else {
        return Ok(best);
    };
    let times = &history.data.times;
    for _ in 0..MAX_ONSET_RESTARTS {
        if best.stop == FitStop::Cancelled {
            break;
        }
        let t0 = best.estimates[index].value;
        // Samples i−1 < t0 ≤ i: move the onset past sample i (later) or i−1 (earlier).
        let i = times.partition_point(|&t| t < t0);
        let later = (i < times.len()).then(|| times[i] + 0.5 * (times.get(i + 1).unwrap_or(&times[i]) - times[i]).max(0.0));
        let earlier = (i >= 1).then(|| times[i - 1] - 0.5 * (times[i - 1] - times[i.saturating_sub(2)]));
        let mut improved = false;
        for candidate in [later, earlier].into_iter().flatten() {
            if cancel() {
                best.stop = FitStop::Cancelled;
                best.termination = best.stop.to_string();
                best.converged = false;
                break;
            }
            let mut start = problem.start;
            for e in &best.estimates {
                start = start.with(e.parameter, e.value)?;
            }
            let restart = FitProblem { start: start.with(FitParameter::TimeOffset, candidate)?, ..problem.clone() };
            // A restart the model cannot compute is no better.
            let Ok(mut report) = fit_from(&restart, options, determined, cancel) else { continue };
            if report.stop == FitStop::Cancelled {
                // Stopped inside the restart: the better point, reported as cancelled.
                if report.chi_square >= best.chi_square {
                    best.stop = FitStop::Cancelled;
                    best.termination = best.stop.to_string();
                    best.converged = false;
                    best.evaluations += report.evaluations;
                    break;
                }
            }
            if report.chi_square < best.chi_square {
                report.evaluations += best.evaluations;
                for (e, first) in report.estimates.iter_mut().zip(&best.estimates) {
                    e.start = first.start;
                }
                best = report;
                improved = true;
            }
        }
        if !improved {
            break;
        }
    }
    Ok(best)
}

/// How far, in standard deviations of χ²_n (n ± √(2n), what n free
/// parameters gain on pure noise), a history fit's contact must lower χ²
/// below no contact at all for the data to show one.
pub const CONTACT_SIGNIFICANCE: f64 = 10.0;

/// Refuse a history fit whose contact explains its samples no better than
/// no contact at all (force and compression zero, the velocities before
/// first touch): data sampled away from the contact, or a t0 the fit moved
/// off it, leave estimates that are noise, not a kick.
fn check_contact(problem: &FitProblem, options: &FitOptions, report: &FitReport) -> Result<(), IdentifyError> {
    let mut point = problem.start;
    for e in &report.estimates {
        point = point.with(e.parameter, e.value)?;
    }
    let none = without_contact(&options.solver, &point, &problem.observations)?;
    let (mut fitted, mut without, mut samples) = (0.0, 0.0, 0usize);
    for (r, v) in report.residuals.iter().zip(&none) {
        if let Some(v) = v {
            fitted += r.weighted * r.weighted;
            without += ((v - r.observed) / r.sigma).powi(2);
            samples += 1;
        }
    }
    let n = report.estimates.len() as f64;
    // NaN or a gain within the noise: refused.
    if samples == 0 || without - fitted > n + CONTACT_SIGNIFICANCE * (2.0 * n).sqrt() {
        return Ok(());
    }
    let histories = std::iter::once(&problem.observations).chain(problem.observations.measurements.iter().map(|m| &m.observations));
    let times: Vec<f64> =
        histories.filter_map(|o| o.history.as_ref()).flat_map(|h| [h.data.times[0], h.data.times[h.data.times.len() - 1]]).collect();
    Err(IdentifyError::NoContact {
        time_offset: point.time_offset,
        fitted,
        without,
        samples,
        first: times.iter().copied().fold(f64::INFINITY, f64::min),
        last: times.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    })
}

/// One Levenberg–Marquardt run from `problem.start`; `determined` refuses
/// fewer observations than free parameters.
fn fit_from(problem: &FitProblem, options: &FitOptions, determined: bool, cancel: &dyn Fn() -> bool) -> Result<FitReport, IdentifyError> {
    if problem.free.is_empty() {
        return Err(IdentifyError::NoFreeParameters);
    }
    for (i, p) in problem.free.iter().enumerate() {
        if problem.free[..i].contains(p) {
            return Err(IdentifyError::DuplicateParameter(p.name()));
        }
    }
    problem.observations.validate()?;
    let mut theta0 = Vec::with_capacity(problem.free.len());
    for &p in &problem.free {
        problem.start.check_fittable(p, problem.observations.has_history())?;
        let v = problem.start.get(p)?;
        let coordinate = p.coordinate();
        let theta = coordinate.theta(v).ok_or(IdentifyError::StartOutOfRange {
            name: p.name(),
            value: v,
            requirement: coordinate.requirement(),
        })?;
        theta0.push(theta);
    }
    // After the per-parameter checks, which name the more specific problem.
    let (observations, parameters) = (distinct_observations(problem)?, problem.free.len());
    if determined && observations < parameters {
        let repeats = problem.observations.len() - observations;
        return Err(IdentifyError::UnderDetermined { observations, parameters, repeats });
    }
    let (observed, sigma, labels) = flatten(&problem.observations);
    let lm_problem = Problem {
        problem,
        options,
        observed: DVector::from_vec(observed),
        sigma: DVector::from_vec(sigma),
        theta: DVector::from_vec(theta0.clone()),
        worst: RefCell::new(0.0),
        failure: RefCell::new(None),
        cancel,
        cancelled: Cell::new(false),
        best: RefCell::new((DVector::zeros(0), DVector::zeros(0))),
    };
    // The starting point itself must be computable.
    let start_residuals = lm_problem.weighted(&lm_problem.theta)?;
    *lm_problem.worst.borrow_mut() = start_residuals.norm();
    *lm_problem.best.borrow_mut() = (lm_problem.theta.clone(), start_residuals);

    let lm = LevenbergMarquardt::new()
        .with_ftol(options.tolerance)
        .with_xtol(options.tolerance)
        .with_gtol(0.0)
        .with_patience(options.patience.max(1));
    let (solved, report) = lm.minimize(lm_problem);
    let cancelled = solved.cancelled.get();
    let stop = if cancelled { FitStop::Cancelled } else { FitStop::of(&report.termination) };
    let converged = stop.converged();
    match stop {
        FitStop::ModelFailed => {
            let failure = solved.failure.borrow().clone();
            return Err(failure.unwrap_or(IdentifyError::NotConverged(stop.to_string())));
        }
        FitStop::NonFinite { quantity } => {
            return Err(IdentifyError::NonFinite {
                quantity,
                reason: "the optimiser met it (data or sigmas beyond what double precision resolves?)".into(),
            })
        }
        _ => {}
    }
    // Cancelled: the best point so far, as evaluated, and no Jacobian (2n more solves).
    let (theta, residual_vector, jacobian) = if cancelled {
        let (theta, residuals) = solved.best.borrow().clone();
        (theta, residuals, None)
    } else {
        let theta = solved.theta.clone();
        let residuals = solved.weighted(&theta)?;
        let jacobian = solved.jacobian_at(&theta)?;
        (theta, residuals, Some(jacobian))
    };
    let point = solved.point(&theta)?;
    // Judged as `kick bounce` and `kick simulate` judge a contact; not for a cancelled fit (more solves).
    let outside_validity = if cancelled {
        Vec::new()
    } else {
        outside_validity(&options.solver, &point, &problem.observations)?
            .into_iter()
            .map(|(measurement, outside)| OutsideAt { measurement, outside })
            .collect()
    };

    let m = residual_vector.len();
    let n = theta.len();
    let chi_square = chi_square_of(&residual_vector)?;
    let dof = m as i64 - n as i64;
    let residual_variance = (dof > 0).then(|| chi_square / dof as f64);

    // (JᵀJ)⁻¹ = V Σ⁻² Vᵀ from the SVD of J; refuse when a direction is unresolved.
    let svd = jacobian.clone().map(|j| j.svd(false, true));
    let mut singular: Vec<f64> = svd.iter().flat_map(|svd| svd.singular_values.iter().copied()).collect();
    singular.sort_by(|a, b| b.total_cmp(a));
    let largest = singular.first().copied().unwrap_or(0.0);
    if determined && jacobian.is_some() && largest == 0.0 {
        let values: Result<Vec<String>, IdentifyError> =
            problem.free.iter().map(|&p| Ok(format!("{} = {}", p.name(), kick_core::short(point.get(p)?)))).collect();
        return Err(IdentifyError::Insensitive {
            free: problem.free.iter().map(|p| p.name()).collect::<Vec<_>>().join(", "),
            point: values?.join(", "),
        });
    }
    let resolved = m >= n && largest > 0.0 && singular.iter().all(|&s| s > RANK_TOLERANCE * largest);
    let covariance = match (resolved, residual_variance, svd.as_ref().and_then(|svd| svd.v_t.as_ref().map(|v_t| (svd, v_t)))) {
        (true, Some(s2), Some((svd, v_t))) => {
            let mut inv = DMatrix::zeros(n, n);
            for (k, &sv) in svd.singular_values.iter().enumerate() {
                let row = v_t.row(k);
                inv += row.transpose() * row / (sv * sv);
            }
            Some(inv * s2)
        }
        _ => None,
    };

    let estimates = problem
        .free
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let value = point.get(p)?;
            let sigma_theta = covariance.as_ref().map(|c| c[(i, i)].sqrt());
            Ok(Estimate {
                parameter: p,
                value,
                standard_uncertainty: sigma_theta.map(|s| p.coordinate().slope(value).abs() * s),
                start: problem.start.get(p)?,
                coordinate: p.coordinate(),
            })
        })
        .collect::<Result<Vec<_>, IdentifyError>>()?;
    let correlation =
        covariance.as_ref().map(|c| (0..n).map(|i| (0..n).map(|j| c[(i, j)] / (c[(i, i)] * c[(j, j)]).sqrt()).collect()).collect());
    let residuals = labels
        .into_iter()
        .enumerate()
        .map(|(i, label)| {
            let observed = solved.observed[i];
            let sigma = solved.sigma[i];
            Residual { label, observed, predicted: observed + residual_vector[i] * sigma, sigma, weighted: residual_vector[i] }
        })
        .collect();
    let report = FitReport {
        law: point.scenario.law_kind(),
        estimates,
        residuals,
        chi_square,
        degrees_of_freedom: dof,
        residual_variance,
        correlation,
        singular_values: singular,
        stop,
        termination: stop.to_string(),
        converged,
        evaluations: report.number_of_evaluations,
        outside_validity,
        jacobian: jacobian.map_or_else(Vec::new, |j| (0..m).map(|i| j.row(i).iter().copied().collect()).collect()),
    };
    check_finite(&report)?;
    Ok(report)
}

/// An observation as the model predicts it: a scalar, or a history's channel at a time.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Observed {
    Scalar(crate::data::Observable),
    Sample(crate::data::Channel, u64),
}

/// How many of the observations the model could predict differently: those
/// that observe the same quantity (an observable, a channel at a time) at
/// the same conditions count once. A careful user repeats a test to sharpen
/// its value, not to determine a second parameter from it, and the model
/// gives every repeat the same prediction: identical or conflicting, they
/// fix one number. Conditions are the same when the model point they give
/// at the start is (what the normal phase does not see, as a bounce's
/// friction, does not tell them apart). Repeats still count in χ², s² and
/// the degrees of freedom, as replicates should.
pub fn distinct_observations(problem: &FitProblem) -> Result<usize, IdentifyError> {
    let mut points: Vec<ModelPoint> = Vec::new();
    let mut seen = Vec::with_capacity(problem.observations.len());
    let own = std::iter::once(Ok((problem.start, &problem.observations)));
    let measured = problem.observations.measurements.iter().map(|m| m.at(&problem.start).map(|point| (point, &m.observations)));
    for context in own.chain(measured) {
        let (point, observations) = context?;
        let same = |p: &ModelPoint| p.scenario == point.scenario && p.time_offset == point.time_offset;
        let group = points.iter().position(same).unwrap_or_else(|| {
            points.push(point);
            points.len() - 1
        });
        seen.extend(observations.scalars.iter().map(|s| (group, Observed::Scalar(s.observable))));
        if let Some(h) = &observations.history {
            for (channel, _) in &h.data.channels {
                seen.extend(h.data.times.iter().map(|t| (group, Observed::Sample(*channel, t.to_bits()))));
            }
        }
    }
    seen.sort_unstable();
    seen.dedup();
    Ok(seen.len())
}

/// χ² = Σ r², refused when it overflows (residuals beyond ~1e154).
fn chi_square_of(residuals: &DVector<f64>) -> Result<f64, IdentifyError> {
    let chi_square = residuals.norm_squared();
    if chi_square.is_finite() {
        return Ok(chi_square);
    }
    let largest = residuals.iter().fold(0.0f64, |a, r| a.max(r.abs()));
    Err(IdentifyError::NonFinite {
        quantity: "chi-square",
        reason: format!(
            "at the estimate the weighted residuals (model − data)/sigma reach {}, so their sum of squares \
             overflows; check the data's values and sigmas",
            kick_core::short(largest)
        ),
    })
}

/// Every number of a report is finite, or the fit is refused naming it.
fn check_finite(report: &FitReport) -> Result<(), IdentifyError> {
    let bad = |quantity: &'static str, detail: String| {
        Err(IdentifyError::NonFinite { quantity, reason: format!("{detail}; the data do not determine it in double precision") })
    };
    for e in &report.estimates {
        if !e.value.is_finite() {
            return bad("estimate", format!("`{}` = {}", e.parameter.name(), e.value));
        }
        if let Some(u) = e.standard_uncertainty.filter(|u| !u.is_finite()) {
            return bad("uncertainty", format!("`{}` ± {u}", e.parameter.name()));
        }
    }
    if let Some(v) = report.residual_variance.filter(|v| !v.is_finite()) {
        return bad("residual variance", format!("s² = {v}"));
    }
    if let Some(r) = report.correlation.iter().flatten().flatten().find(|r| !r.is_finite()) {
        return bad("correlation", format!("a correlation coefficient is {r}"));
    }
    if let Some(s) = report.singular_values.iter().find(|s| !s.is_finite()) {
        return bad("singular value", format!("a singular value of the Jacobian is {s}"));
    }
    Ok(())
}

/// Observed values, sigmas and labels in [`predict`]'s order (a
/// measurement's labels start with its name).
pub fn flatten(observations: &Observations) -> (Vec<f64>, Vec<f64>, Vec<String>) {
    let mut observed = Vec::new();
    let mut sigma = Vec::new();
    let mut labels = Vec::new();
    let mut own = |o: &Observations, prefix: &str| {
        for s in &o.scalars {
            observed.push(s.value);
            sigma.push(s.sigma);
            labels.push(format!("{prefix}{}", s.observable.name()));
        }
        if let Some(h) = &o.history {
            for (channel, values) in &h.data.channels {
                let sig = h.sigma[channel];
                for (t, v) in h.data.times.iter().zip(values) {
                    observed.push(*v);
                    sigma.push(sig);
                    labels.push(format!("{prefix}{} at t = {} s", channel.name(), kick_core::number::sig(*t)));
                }
            }
        }
    };
    own(observations, "");
    for m in &observations.measurements {
        own(&m.observations, &format!("{}: ", m.name));
    }
    (observed, sigma, labels)
}

/// χ² = Σ ((model − data)/σ)² of a model point against observations.
pub fn misfit(solver: &Accurate, point: &ModelPoint, observations: &Observations) -> Result<f64, IdentifyError> {
    let predicted = predict(solver, point, observations)?;
    let (observed, sigma, _) = flatten(observations);
    Ok(predicted.iter().zip(&observed).zip(&sigma).map(|((p, o), s)| ((p - o) / s).powi(2)).sum())
}
