//! Closed forms of the 1D model, exact where they apply.
//!
//! - [`elastic`]: c = 0, no drive, any n. δ_max from Eq. 33, contact time
//!   twice the Beta-function return time, e = 1.
//! - [`linear`]: n = 1 with compression-only damping and no drive: a damped
//!   oscillator (under-, critically or over-damped) up to δ_max, then an
//!   undamped quarter swing back (Eq. 41).
//! - [`undamped_return`]: the undamped restitution phase of any run of the
//!   paper's law, from δ_max, with or without a constant drive.

use kick_core::{roots, special, ContactLaw, EnergyBudget, KickError, Outcome, Scenario, SolverPath, StopReason};

/// The end of compression, from which a passive run returns without loss.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompressionEnd {
    pub max_compression: f64,
    pub max_compression_time: f64,
    /// Dissipated during compression, J.
    pub dissipated: f64,
    pub peak_force: f64,
    pub peak_force_time: f64,
}

/// The restitution phase of the paper's law in closed form, from rest at
/// δ_max: the law does not damp while δ̇ < 0, so with a constant drive share
/// f_s = (μ/m_f) F_drive the return conserves ½ μ δ̇² + U(δ) − f_s δ.
/// The ball leaves with ½ μ w² = U(δ_max) − f_s δ_max = ½ μ V0² − D (a
/// `Trapped` error when that is negative; `end.dissipated` must be the
/// integrated D under a drive), after the Beta-function time without a drive
/// and [`special::driven_return_integral`] with one. The centre of
/// mass gains F_drive t / M (Eq. 26) and the drive does work F_drive x_f(t_c).
pub fn undamped_return(scenario: &Scenario, end: CompressionEnd) -> Result<Outcome, KickError> {
    let law = scenario.paper_law();
    let mu = scenario.reduced_mass();
    let drive = scenario.drive_force();
    let drive_share = mu / scenario.effective_foot_mass() * drive;
    let stored = law.potential(end.max_compression);
    let exponent = scenario.get(kick_core::Parameter::Exponent);
    let (exit_relative_speed, return_time) = if drive_share == 0.0 {
        let w = (2.0 * stored / mu).sqrt();
        (w, special::return_time(end.max_compression, w, exponent))
    } else {
        let (released, condition) = released_energy(scenario, &end);
        let terms = released.abs() * condition;
        if !(released >= 0.0) && !crate::events::proves_trapped(-released, terms) {
            // Within the rounding of its terms: neither outcome is proven.
            return Err(KickError::NoSeparation {
                time: end.max_compression_time,
                reason: format!(
                    "grazing: the energy released at maximum compression, {} J, is within the rounding of \
                     the energies compared ({} J), so neither separation nor trapping is proven",
                    kick_core::short(released),
                    kick_core::short(terms)
                ),
            });
        }
        if !(released >= 0.0) {
            return Err(KickError::Trapped {
                time: end.max_compression_time,
                reason: format!(
                    "the ball never leaves the foot, no separation: at maximum compression U(δ_max) − (μ/m_f) F_drive δ_max = ½μV0² − D = {} J < 0, \
                     so the ball turns back before release",
                    kick_core::short(released)
                ),
            });
        }
        let free_speed = (2.0 * stored / mu).sqrt();
        let margin = released / stored;
        let w = (2.0 * released / mu).sqrt();
        (w, end.max_compression / free_speed * special::driven_return_integral(exponent, margin))
    };
    let total = scenario.total_mass();
    let contact_time = end.max_compression_time + return_time;
    // Eq. 26: the centre of mass, uniformly accelerated by the drive.
    let v_cm = scenario.centre_of_mass_speed() + drive * contact_time / total;
    // Relative coordinates (numerics note): δ̇ = −w at exit.
    let v_ball_out = v_cm + scenario.effective_foot_mass() / total * exit_relative_speed;
    let v_foot_out = v_cm - scenario.ball_mass() / total * exit_relative_speed;
    // At δ = 0 the foot is where the centre of mass is.
    let foot_position = scenario.centre_of_mass_speed() * contact_time + 0.5 * drive * contact_time * contact_time / total;
    let kinetic_final = 0.5 * scenario.effective_foot_mass() * v_foot_out.powi(2) + 0.5 * scenario.ball_mass() * v_ball_out.powi(2);
    let (peak_force, peak_force_time) = if stored > 0.0 && law.elastic_force(end.max_compression) > end.peak_force {
        (law.elastic_force(end.max_compression), end.max_compression_time)
    } else {
        (end.peak_force, end.peak_force_time)
    };
    let outcome = Outcome {
        v_ball_out,
        v_foot_out,
        speed_ratio: Outcome::ratio(v_ball_out, scenario.foot_speed()),
        peak_force,
        peak_force_time,
        contact_time,
        max_compression: end.max_compression,
        max_compression_time: end.max_compression_time,
        impulse: scenario.ball_mass() * (v_ball_out - scenario.ball_speed()), // Eq. 2
        restitution: exit_relative_speed / scenario.approach_speed(),
        energy: EnergyBudget {
            kinetic_initial: scenario.initial_kinetic_energy(),
            kinetic_final,
            elastic_final: 0.0,
            dissipated: end.dissipated,
            drive_work: drive * foot_position,
        },
        stop: StopReason::ClosedForm { t: contact_time },
        evaluations: 0,
        method: SolverPath::ClosedForm,
    };
    crate::ode::check_finite(&outcome)
}

/// ½ μ w², the energy the return gives back, from the end of compression of
/// the paper's law, and how much its computation amplifies relative errors
/// of δ_max or D (the size of the terms over their difference).
///
/// ½ μ w² = U(δ_max) − f_s δ_max = ½ μ V0² − D. Both differences can cancel,
/// so the one whose terms are smaller is taken: a strong drive makes U and
/// f_s δ large, heavy damping makes D close to ½ μ V0². Near a trapping drive
/// both cancel, and w is only as good as δ_max or D times the amplification.
pub fn released_energy(scenario: &Scenario, end: &CompressionEnd) -> (f64, f64) {
    let mu = scenario.reduced_mass();
    let drive_share = mu / scenario.effective_foot_mass() * scenario.drive_force();
    let stored = scenario.paper_law().potential(end.max_compression);
    let kinetic = scenario.relative_kinetic_energy();
    if drive_share == 0.0 {
        return (stored, 1.0);
    }
    let (released, terms) = if kinetic < stored {
        (kinetic - end.dissipated, kinetic)
    } else {
        (stored - drive_share * end.max_compression, stored + (drive_share * end.max_compression).abs())
    };
    (released, terms / released.abs())
}

/// c = 0 and no drive: the whole contact in closed form (Eqs. 33–34).
pub fn elastic(scenario: &Scenario) -> Option<Result<Outcome, KickError>> {
    if scenario.law_kind() != kick_core::LawKind::PowerLaw
        || scenario.boot().is_some()
        || scenario.get(kick_core::Parameter::Damping) != 0.0
        || scenario.drive_force() != 0.0
    {
        return None;
    }
    let max_compression = scenario.elastic_max_compression();
    let half = special::return_time(max_compression, scenario.approach_speed(), scenario.get(kick_core::Parameter::Exponent));
    let force = scenario.paper_law().elastic_force(max_compression);
    Some(undamped_return(
        scenario,
        CompressionEnd { max_compression, max_compression_time: half, dissipated: 0.0, peak_force: force, peak_force_time: half },
    ))
}

/// Linear damped compression δ(t), δ̇(t) from δ(0) = 0, δ̇(0) = V0.
#[derive(Debug, Clone, Copy)]
enum LinearCompression {
    Under { v0: f64, decay: f64, omega_d: f64 },
    Critical { v0: f64, omega0: f64 },
    Over { v0: f64, r1: f64, r2: f64 },
}

impl LinearCompression {
    fn new(v0: f64, omega0: f64, zeta: f64) -> Self {
        if zeta < 1.0 {
            LinearCompression::Under { v0, decay: zeta * omega0, omega_d: omega0 * (1.0 - zeta * zeta).sqrt() }
        } else if zeta == 1.0 {
            LinearCompression::Critical { v0, omega0 }
        } else {
            let s = omega0 * (zeta * zeta - 1.0).sqrt();
            // r1 r2 = ω0², so form the small root from the large one without cancellation.
            let r2 = -zeta * omega0 - s;
            LinearCompression::Over { v0, r1: omega0 * omega0 / r2, r2 }
        }
    }
    /// (δ, δ̇) at t.
    fn state(&self, t: f64) -> (f64, f64) {
        match *self {
            LinearCompression::Under { v0, decay, omega_d } => {
                let (s, c) = (omega_d * t).sin_cos();
                let e = (-decay * t).exp();
                (v0 / omega_d * e * s, v0 * e * (c - decay / omega_d * s))
            }
            LinearCompression::Critical { v0, omega0 } => {
                let e = (-omega0 * t).exp();
                (v0 * t * e, v0 * e * (1.0 - omega0 * t))
            }
            LinearCompression::Over { v0, r1, r2 } => {
                let (e1, e2) = ((r1 * t).exp(), (r2 * t).exp());
                (v0 / (r1 - r2) * (e1 - e2), v0 / (r1 - r2) * (r1 * e1 - r2 * e2))
            }
        }
    }
    /// Time of δ̇ = 0.
    fn max_compression_time(&self) -> f64 {
        match *self {
            LinearCompression::Under { decay, omega_d, .. } => omega_d.atan2(decay) / omega_d,
            LinearCompression::Critical { omega0, .. } => 1.0 / omega0,
            LinearCompression::Over { r1, r2, .. } => (r2 / r1).ln() / (r1 - r2),
        }
    }
}

/// n = 1, compression-only damping, no drive: closed form for any ζ.
pub fn linear(scenario: &Scenario) -> Option<Result<Outcome, KickError>> {
    if scenario.law_kind() != kick_core::LawKind::PowerLaw
        || scenario.boot().is_some()
        || scenario.get(kick_core::Parameter::Exponent) != 1.0
        || scenario.drive_force() != 0.0
    {
        return None;
    }
    let law = scenario.paper_law();
    let (k, c) = (law.stiffness, law.damping);
    let mu = scenario.reduced_mass();
    let v0 = scenario.approach_speed();
    let omega0 = (k / mu).sqrt(); // Eq. 42
    let motion = LinearCompression::new(v0, omega0, scenario.damping_ratio());
    let t1 = motion.max_compression_time();
    let (max_compression, _) = motion.state(t1);
    // Peak of F = kδ + cδ̇ on [0, t1]: dF/dt = kδ̇ − (c/μ)(kδ + cδ̇).
    let force_rate = |t: f64| {
        let (d, r) = motion.state(t);
        k * r - c / mu * (k * d + c * r)
    };
    let onset = law.onset_force(v0);
    let (peak_force, peak_force_time) = if force_rate(0.0) > 0.0 {
        match roots::brent(force_rate, 0.0, t1, 4.0 * f64::EPSILON * t1, 200) {
            Some(root) => {
                let (d, r) = motion.state(root.x);
                (law.contact_force(d, r).max(onset), root.x)
            }
            None => (k * max_compression, t1),
        }
    } else {
        (onset, 0.0)
    };
    let dissipated = scenario.relative_kinetic_energy() - law.potential(max_compression);
    Some(undamped_return(scenario, CompressionEnd { max_compression, max_compression_time: t1, dissipated, peak_force, peak_force_time }))
}

/// The closed forms as a solver: exact, or an error naming why none applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ClosedForm;

impl ClosedForm {
    pub fn applies(scenario: &Scenario) -> bool {
        scenario.law_kind() == kick_core::LawKind::PowerLaw
            && scenario.boot().is_none()
            && scenario.drive_force() == 0.0
            && (scenario.get(kick_core::Parameter::Damping) == 0.0 || scenario.get(kick_core::Parameter::Exponent) == 1.0)
    }
}

impl kick_core::Solver for ClosedForm {
    fn name(&self) -> &'static str {
        "closed-form"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        elastic(scenario).or_else(|| linear(scenario)).unwrap_or_else(|| {
            Err(KickError::NotApplicable {
                solver: "closed-form",
                reason: "it needs the paper's law, no drive, no boot, and either damping = 0 or exponent = 1",
            })
        })
    }
}
