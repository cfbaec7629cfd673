//! What a model level returns.

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
        (self.kinetic_initial + self.drive_work)
            - (self.kinetic_final + self.elastic_final + self.dissipated)
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
            StopReason::Separated { t }
            | StopReason::StepCondition { t }
            | StopReason::ClosedForm { t } => t,
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
    /// v_b⁺ / v_f⁻ (Eq. 38's left side; Table 2's "Ratio").
    pub speed_ratio: f64,
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
    pub method: &'static str,
}

impl Outcome {
    pub fn exit(&self) -> ExitVelocities {
        ExitVelocities {
            foot: self.v_foot_out,
            ball: self.v_ball_out,
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
}

/// A recorded time history.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct History {
    pub samples: Vec<Sample>,
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
    /// Values in [`OBSERVABLES`] order.
    pub fn observable_values(&self) -> [f64; 15] {
        [
            self.v_ball_out,
            self.v_foot_out,
            self.speed_ratio,
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
