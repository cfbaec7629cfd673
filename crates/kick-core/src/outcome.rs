//! What a model level returns.

use crate::KickError;
use serde::Serialize;

/// Exit velocities of foot and ball, the common answer of every model level.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ExitVelocities {
    /// v_f⁺ in m/s.
    pub foot: f64,
    /// v_b⁺ in m/s.
    pub ball: f64,
}

/// Energy bookkeeping at the end of contact (Eqs. 30–33), in J.
///
/// `kinetic_initial + drive_work = kinetic_final + elastic_final + dissipated`,
/// where `dissipated` and `drive_work` are integrated independently of the
/// kinetic energies, so the residual measures the solver's accuracy.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergyBudget {
    pub kinetic_initial: f64,
    pub kinetic_final: f64,
    /// U(δ) at the end of contact (zero at exact separation).
    pub elastic_final: f64,
    /// ∫ c max(δ̇,0) δ̇ dt (Eq. 25).
    pub dissipated: f64,
    /// ∫ F_drive v_f dt.
    pub drive_work: f64,
}

impl EnergyBudget {
    /// (K⁻ + W) − (K⁺ + U⁺ + D): zero up to the solver's error.
    pub fn residual(&self) -> f64 {
        (self.kinetic_initial + self.drive_work) - (self.kinetic_final + self.elastic_final + self.dissipated)
    }
    /// Residual relative to the energy that went through the contact.
    pub fn relative_residual(&self) -> f64 {
        self.residual() / (self.kinetic_initial + self.drive_work.abs())
    }
}

/// Why a contact integration ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum StopReason {
    /// Event located: δ = 0 with δ̇ < 0 at time `t` (exact separation).
    Separated { t: f64 },
    /// Fixed-step test of Eq. 48 held at the step after `t`, the last step
    /// point still in contact (the paper's convention).
    StepCondition { t: f64 },
    /// Closed form: no integration was needed.
    ClosedForm { t: f64 },
}

impl StopReason {
    pub fn time(&self) -> f64 {
        match *self {
            StopReason::Separated { t } | StopReason::StepCondition { t } | StopReason::ClosedForm { t } => t,
        }
    }
}

/// Summary of one contact: the observables the paper reports and more.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Outcome {
    /// v_b⁺ in m/s.
    pub v_ball_out: f64,
    /// v_f⁺ in m/s.
    pub v_foot_out: f64,
    /// v_b⁺ / v_f⁻ (Eq. 38's left side; Table 2's "Ratio"); `None` when
    /// v_f⁻ = 0 (a ball hitting a resting foot), where it is undefined.
    pub speed_ratio: Option<f64>,
    /// sup F over contact, including F(0⁺) = c V0, in N.
    pub peak_force: f64,
    pub peak_force_time: f64,
    /// t_c in s.
    pub contact_time: f64,
    /// δ_max in m.
    pub max_compression: f64,
    pub max_compression_time: f64,
    /// J = ∫ F dt in N s (Eq. 1).
    pub impulse: f64,
    /// e = (v_b⁺ − v_f⁺)/(v_f⁻ − v_b⁻) (Eq. 36).
    pub restitution: f64,
    pub energy: EnergyBudget,
    pub stop: StopReason,
    /// Right-hand-side evaluations spent (0 for closed forms).
    pub evaluations: u64,
    /// Which solver path produced it (`--solver auto` picks one per scenario).
    pub method: SolverPath,
}

/// The solver path that produced an outcome: each solver's own, and the one
/// `auto` took for the scenario. Written by its kebab-case name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SolverPath {
    SeedRk4,
    Accurate,
    Dop853,
    Dopri5,
    Rk4Events,
    Reduced,
    ReducedReturn,
    ClosedForm,
    Series,
}

impl SolverPath {
    /// The `--solver` name of the path.
    pub fn name(self) -> &'static str {
        match self {
            SolverPath::SeedRk4 => "seed-rk4",
            SolverPath::Accurate => "accurate",
            SolverPath::Dop853 => "dop853",
            SolverPath::Dopri5 => "dopri5",
            SolverPath::Rk4Events => "rk4-events",
            SolverPath::Reduced => "reduced",
            SolverPath::ReducedReturn => "reduced-return",
            SolverPath::ClosedForm => "closed-form",
            SolverPath::Series => "series",
        }
    }
}

impl std::fmt::Display for SolverPath {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl Outcome {
    /// v_b⁺ / v_f⁻, `None` when v_f⁻ = 0 (undefined, not infinite).
    pub fn ratio(v_ball_out: f64, v_foot_in: f64) -> Option<f64> {
        (v_foot_in != 0.0).then(|| v_ball_out / v_foot_in)
    }
    pub fn exit(&self) -> ExitVelocities {
        ExitVelocities { foot: self.v_foot_out, ball: self.v_ball_out }
    }
}

/// Which part of the contact a history sample belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactPhase {
    /// δ̇ > 0: the foot gains on the ball (damping on, for the paper's law).
    Compressing,
    /// δ̇ < 0: the ball pulls away.
    Restoring,
    /// The separation state, a history's last row (off the uniform grid).
    Separation,
}

impl ContactPhase {
    /// Numeric code for columns of numbers: +1 compressing, −1 restoring,
    /// 0 the separation row.
    pub fn code(self) -> f64 {
        match self {
            ContactPhase::Compressing => 1.0,
            ContactPhase::Restoring => -1.0,
            ContactPhase::Separation => 0.0,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            ContactPhase::Compressing => "compressing",
            ContactPhase::Restoring => "restoring",
            ContactPhase::Separation => "separation",
        }
    }
}

/// One sample of a time history, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    pub time: f64,
    pub foot_position: f64,
    pub foot_velocity: f64,
    pub ball_position: f64,
    pub ball_velocity: f64,
    pub compression: f64,
    pub force: f64,
    pub kinetic: f64,
    pub elastic: f64,
    pub dissipated: f64,
    pub drive_work: f64,
    pub phase: ContactPhase,
}

/// Names and units of a history's columns, in [`Sample::values`] order; the
/// phase column holds [`ContactPhase::code`].
pub const HISTORY_COLUMNS: [(&str, &str); 12] = [
    ("time", "s"),
    ("foot_position", "m"),
    ("foot_velocity", "m/s"),
    ("ball_position", "m"),
    ("ball_velocity", "m/s"),
    ("compression", "m"),
    ("force", "N"),
    ("kinetic", "J"),
    ("elastic", "J"),
    ("dissipated", "J"),
    ("drive_work", "J"),
    ("phase", "1"),
];

impl Sample {
    /// Values in [`HISTORY_COLUMNS`] order.
    pub fn values(&self) -> [f64; 12] {
        [
            self.time,
            self.foot_position,
            self.foot_velocity,
            self.ball_position,
            self.ball_velocity,
            self.compression,
            self.force,
            self.kinetic,
            self.elastic,
            self.dissipated,
            self.drive_work,
            self.phase.code(),
        ]
    }
}

/// A recorded time history (see [`Spacing`] for where its samples fall).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct History {
    pub samples: Vec<Sample>,
}

/// Most samples the collecting form of a history keeps by default
/// ([`crate::RecordingSolver::solve_recorded`]): 10⁶ samples, about 100 MB.
/// Longer histories are streamed ([`crate::RecordingSolver::solve_streamed`]).
pub const MAX_HISTORY_SAMPLES: usize = 1_000_000;

/// Where the samples of a 1D time history fall.
///
/// Samples lie on a uniform grid t_k = k Δ from first touch (k = 0, t = 0),
/// every grid time strictly before the end of the contact, followed by one
/// more row, the separation state (phase [`ContactPhase::Separation`]) at the
/// contact's end t_end. So the last grid point is < t_end and the separation
/// row at most Δ after it (up to rounding of k Δ). t_end is the contact time for the solvers
/// that locate separation; for `seed-rk4` it is the step at which Eq. 48
/// held, one step after its contact time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spacing {
    /// Δ in s; ⌈t_end/Δ⌉ grid samples plus the separation row.
    Interval(f64),
    /// This many samples in all (≥ 2): Δ = t_end/(N − 1), N − 1 grid samples
    /// plus the separation row. t_end is not known in advance, so the
    /// contact is solved once for it first.
    Count(usize),
}

impl Spacing {
    /// Refuses a spacing that does not make a grid, naming `interval` or `samples`.
    pub fn validate(self) -> Result<Spacing, KickError> {
        match self {
            Spacing::Interval(dt) if !(dt.is_finite() && dt > 0.0) => {
                Err(KickError::InvalidParameter { name: "interval", value: dt, requirement: "finite and > 0 (s)" })
            }
            Spacing::Count(n) if n < 2 => Err(KickError::InvalidParameter {
                name: "samples",
                value: n as f64,
                requirement: "at least 2 (first touch and separation)",
            }),
            _ => Ok(self),
        }
    }

    /// The grid for a contact ending at `end` (needed only by `Count`).
    pub fn grid(self, end: f64) -> Grid {
        match self {
            Spacing::Interval(interval) => Grid { interval, last: None },
            Spacing::Count(n) => Grid { interval: end / (n - 1) as f64, last: Some(n as u64 - 2) },
        }
    }
}

/// A history's time grid: t_k = k Δ for k = 0, 1, … (at most `last`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Δ in s.
    pub interval: f64,
    /// Largest index k on the grid, if bounded.
    pub last: Option<u64>,
}

impl Grid {
    /// t_k, computed from k (never accumulated).
    #[inline]
    pub fn time(&self, k: u64) -> f64 {
        k as f64 * self.interval
    }
    /// Whether t_k is on the grid and not past `end` (`inclusive`) or before it.
    #[inline]
    pub fn admits(&self, k: u64, end: f64, inclusive: bool) -> bool {
        let t = self.time(k);
        self.last.is_none_or(|last| k <= last) && if inclusive { t <= end } else { t < end }
    }
    /// [`Grid::samples_until`], or [`KickError::HistoryTooLong`] when that
    /// is more than `limit`, decided from the ratio end/Δ before counting
    /// (an interval of 1e-300 s asks for 1e297 rows: never walked).
    pub fn samples_within(&self, end: f64, limit: usize) -> Result<u64, KickError> {
        let mut ratio = (end / self.interval).ceil();
        if let Some(last) = self.last {
            ratio = ratio.min(last as f64 + 1.0);
        }
        let too_long = |needed: f64| KickError::HistoryTooLong { needed, limit: limit as u64 };
        if !(ratio <= limit as f64 + 1.0) {
            return Err(too_long(ratio + 1.0));
        }
        let samples = self.samples_until(end);
        if samples > limit as u64 {
            return Err(too_long(samples as f64));
        }
        Ok(samples)
    }

    /// How many samples a history ending at `end` holds: the grid points
    /// before `end` plus the separation row.
    pub fn samples_until(&self, end: f64) -> u64 {
        // The grid points are those k below the first one `admits` refuses
        // (it is monotone in k): start from the ratio, settle the rounding
        // with the predicate itself.
        let ratio = (end / self.interval).ceil();
        let mut k = if ratio.is_finite() && ratio > 0.0 { ratio as u64 } else { 0 };
        if let Some(last) = self.last {
            k = k.min(last + 1);
        }
        while self.admits(k, end, false) {
            k += 1;
        }
        while k > 0 && !self.admits(k - 1, end, false) {
            k -= 1;
        }
        k + 1
    }
}

/// Names and units of the scalar observables of an [`Outcome`], as used by
/// `kick simulate --format json` and the HDF5 `outcomes` group.
pub const OBSERVABLES: [(&str, &str); 15] = [
    ("v_ball_out", "m/s"),
    ("v_foot_out", "m/s"),
    ("speed_ratio", "1"),
    ("peak_force", "N"),
    ("peak_force_time", "s"),
    ("contact_time", "s"),
    ("max_compression", "m"),
    ("max_compression_time", "s"),
    ("impulse", "N s"),
    ("restitution", "1"),
    ("energy_kinetic_initial", "J"),
    ("energy_kinetic_final", "J"),
    ("energy_elastic_final", "J"),
    ("energy_dissipated", "J"),
    ("energy_drive_work", "J"),
];

impl Outcome {
    /// Values in [`OBSERVABLES`] order, for columns of numbers: an undefined
    /// speed ratio (v_f⁻ = 0) is NaN, the one documented NaN of a row.
    pub fn observable_values(&self) -> [f64; 15] {
        [
            self.v_ball_out,
            self.v_foot_out,
            self.speed_ratio.unwrap_or(f64::NAN),
            self.peak_force,
            self.peak_force_time,
            self.contact_time,
            self.max_compression,
            self.max_compression_time,
            self.impulse,
            self.restitution,
            self.energy.kinetic_initial,
            self.energy.kinetic_final,
            self.energy.elastic_final,
            self.energy.dissipated,
            self.energy.drive_work,
        ]
    }
}
