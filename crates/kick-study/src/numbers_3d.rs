//! The numbers kick-paper's 3D page states, computed here so the page only
//! writes them: the accurate path's error over the off-center box, its gap
//! to the 1D solver on a central kick, the scene path's error and order, the
//! force-history kick and the 1D baseline it is compared with, and the spin
//! against friction beside Asai et al. (2002) with what sets its trend.

use kick_3d::{Accurate3d, Kick3d, KickSpec, Outcome3d, Solver3d};
use kick_core::parameters::{SetParameter, Value};
use kick_core::{Outcome, Solver};

use crate::error::StudyError;

/// The force-history kick's offset (m) and friction: 5 cm off the swing
/// line, μ 0.5, which grips, slips and grips again.
pub const HISTORY_OFFSET: f64 = 0.05;
pub const HISTORY_FRICTION: f64 = 0.5;

/// The kick the force-history figure shows, as a spec: [`HISTORY_OFFSET`],
/// [`HISTORY_FRICTION`], the 3D defaults otherwise.
pub fn history_spec() -> KickSpec {
    let mut spec = KickSpec::default();
    spec.kick3d.offset = Some(HISTORY_OFFSET);
    spec.kick3d.friction = Some(HISTORY_FRICTION);
    spec
}

/// The kick the force-history figure shows ([`history_spec`]).
pub fn history_kick() -> Result<Kick3d, StudyError> {
    Ok(history_spec().build()?)
}

/// Table 1's kick in 3D: kick-3d's defaults (its ball, foot and scene).
pub fn baseline_kick() -> Kick3d {
    Kick3d::baseline()
}

/// Largest relative error of the accurate path against the tightened
/// full-state reference over the first `kicks` kicks of the box, per
/// observable (kick_3d::precision::Errors3d order).
pub fn box_errors(kicks: u64) -> Result<[f64; 9], StudyError> {
    let sample = kick_3d::models::OffCenterBox::new(kick_3d::models::BENCH_SEED);
    let mut worst = [0.0f64; 9];
    for i in 0..kicks {
        let kick = sample.kick(i)?;
        let solved = Accurate3d::default().solve(&kick)?;
        let reference = kick_3d::precision::reference().solve(&kick)?;
        let e = kick_3d::precision::Errors3d::of(&kick, &solved, &reference);
        for (w, v) in worst.iter_mut().zip(e.values()) {
            *w = w.max(v);
        }
    }
    Ok(worst)
}

/// The reference's own error over the first `kicks` kicks of the box,
/// estimated by tightening it tenfold: the full-state path at rtol 1e-13
/// (`kick_3d::precision::reference`) against itself at 1e-14, the largest
/// relative difference over the observables (Errors3d).
pub fn reference_error(kicks: u64) -> Result<f64, StudyError> {
    let sample = kick_3d::models::OffCenterBox::new(kick_3d::models::BENCH_SEED);
    let reference = kick_3d::precision::reference();
    let tighter = kick_3d::FullState3d::new(reference.relative_tolerance / 10.0, reference.absolute_tolerance / 10.0)?;
    let mut worst = 0.0f64;
    for i in 0..kicks {
        let kick = sample.kick(i)?;
        let e = kick_3d::precision::Errors3d::of(&kick, &reference.solve(&kick)?, &tighter.solve(&kick)?);
        worst = worst.max(e.max());
    }
    Ok(worst)
}

/// Relative gap between the accurate 3D path on a central frictionless
/// kick and the 1D accurate solver on its scenario (exit speed).
pub fn central_gap() -> Result<f64, StudyError> {
    let mut spec = KickSpec::default();
    spec.set_named("friction", Value::Number(0.0))?;
    let kick = spec.build()?;
    let three = Accurate3d::default().solve(&kick)?;
    let one = kick_compliant::SolverChoice::from_name("accurate", 5e-6)?.solve(&kick.base)?;
    Ok(((three.speed - one.v_ball_out) / one.v_ball_out).abs())
}

/// The scene path's launch-velocity error against `accurate` on the kick of
/// [`history_kick`] at steps 1e-5 s and 5e-6 s (relative to the speed);
/// `None` when the scene path is not built (cargo feature `rapier` off).
pub fn scene_errors() -> Result<Option<[f64; 2]>, StudyError> {
    let kick = history_kick()?;
    let exact = Accurate3d::default().solve(&kick)?;
    let mut errors = [0.0; 2];
    for (e, dt) in errors.iter_mut().zip([1e-5, 5e-6]) {
        let Ok(solver) = Solver3d::from_name("rapier", dt) else {
            return Ok(None);
        };
        let o = solver.solve(&kick)?;
        let d: f64 = (0..3).map(|i| (o.launch_velocity[i] - exact.launch_velocity[i]).powi(2)).sum::<f64>().sqrt();
        *e = d / exact.speed;
    }
    Ok(Some(errors))
}

/// The 1D accurate solve of the 3D baseline's scenario.
pub fn baseline_1d(kick: &Kick3d) -> Result<Outcome, StudyError> {
    Ok(kick_compliant::SolverChoice::from_name("accurate", 5e-6)?.solve(&kick.base)?)
}

/// The force-history kick solved on the default (auto) path.
pub fn history_outcome() -> Result<Outcome3d, StudyError> {
    Ok(Solver3d::Auto.solve(&history_kick()?)?)
}

/// The frictions of [`friction_spin`] (∞: the contact never slips).
pub const SPIN_FRICTIONS: [f64; 7] = [0.1, 0.2, 0.3, 0.5, 1.0, 2.0, f64::INFINITY];
/// The tangential stiffnesses of [`friction_spin`], N/m: a quarter of the
/// default, the default, four times it.
pub const SPIN_STIFFNESSES: [f64; 3] = [2.5e4, 1.0e5, 4.0e5];
/// The offset of [`friction_spin`]'s kicks, m.
pub const SPIN_OFFSET: f64 = 0.05;

/// Spin against friction at one tangential stiffness, for one ball.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionSpin {
    /// The normal law's name.
    pub law: &'static str,
    /// k_t, N/m.
    pub tangential_stiffness: f64,
    /// The gripping contact's tangential vibration period 2π √(m_t / k_t), s
    /// (m_t the contact point's tangential mass, the foot's turn included).
    pub period: f64,
    /// Contact time at the largest μ, s.
    pub contact_time: f64,
    /// (μ, sidespin rpm in friction's sense, slip time / contact time) at
    /// each of [`SPIN_FRICTIONS`]: −ω_z for the offset e > 0, so a negative
    /// value is a ball that leaves spinning against friction's sense.
    pub points: Vec<(f64, f64, f64)>,
}

/// Table 1's kick at [`SPIN_OFFSET`] against μ ([`SPIN_FRICTIONS`]) for the
/// paper's ball and the shell ball, at each of [`SPIN_STIFFNESSES`]; and rigid
/// grip's spin (μ = ∞, k_t = ∞) per ball, rpm; spins in friction's sense
/// ([`FrictionSpin::points`]).
pub fn friction_spin() -> Result<(Vec<FrictionSpin>, Vec<RigidGrip>), StudyError> {
    let shell = kick_core::Scenario::baseline().with_law(kick_core::LawKind::Shell, None)?;
    let mut rows = Vec::new();
    let mut rigid = Vec::new();
    for (law, base) in [("paper's law (Eq. 20)", kick_core::Scenario::baseline()), ("shell ball", shell)] {
        let at = |friction: f64, k_t: f64| -> Result<(Kick3d, Outcome3d), StudyError> {
            let spec = kick_3d::Kick3dSpec {
                offset: Some(SPIN_OFFSET),
                friction: Some(friction),
                tangential_stiffness: Some(k_t),
                ..kick_3d::Kick3dSpec::default()
            };
            let kick = Kick3d::new(base, &spec)?;
            let o = Accurate3d::default().solve(&kick)?;
            Ok((kick, o))
        };
        for k_t in SPIN_STIFFNESSES {
            let mut points = Vec::new();
            let mut last = None;
            for mu in SPIN_FRICTIONS {
                let (kick, o) = at(mu, k_t)?;
                points.push((mu, sidespin_rpm(&o), o.slip_time / o.contact_time));
                last = Some((kick, o));
            }
            let Some((kick, o)) = last else { continue };
            let m_t = kick_3d::checks::tangential_mass(&kick, kick.foot_inertia[2]);
            rows.push(FrictionSpin {
                law,
                tangential_stiffness: k_t,
                period: std::f64::consts::TAU * (m_t / k_t).sqrt(),
                contact_time: o.contact_time,
                points,
            });
        }
        let (kick, o) = at(f64::INFINITY, f64::INFINITY)?;
        let limit = |inertia: f64| kick_3d::checks::gripping_limit_spin(&kick, inertia).length() * 60.0 / std::f64::consts::TAU;
        rigid.push(RigidGrip {
            law,
            rpm: sidespin_rpm(&o),
            limit_rpm: limit(kick.foot_inertia[2]),
            fixed_foot_limit_rpm: limit(f64::INFINITY),
        });
    }
    Ok((rows, rigid))
}

/// Rigid grip's kick (μ = ∞, k_t = ∞) of one ball, rpm: its sidespin in
/// friction's sense, and the gripping limit R m_t |v_t0| / I_b with the
/// foot's turn in m_t (the foot's default inertia) and without it (a foot
/// that cannot turn, `kick check`'s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidGrip {
    pub law: &'static str,
    pub rpm: f64,
    pub limit_rpm: f64,
    pub fixed_foot_limit_rpm: f64,
}

/// −ω_z in rpm: the sidespin of a kick at e > 0 in the sense friction turns the ball.
fn sidespin_rpm(o: &Outcome3d) -> f64 {
    -o.spin[2] * 60.0 / std::f64::consts::TAU
}

/// The seed of kick-3d's test box (the kicks the page's accuracy is stated over).
pub use kick_3d::models::BENCH_SEED;

/// kick-3d's default tangential stiffness k_t, N/m.
pub const DEFAULT_TANGENTIAL_STIFFNESS: f64 = Kick3d::DEFAULT_TANGENTIAL_STIFFNESS;

/// Spin against friction at 5 cm on Table 1's kick (the paper's law, the
/// validation chapter's sweep): |ω| at μ = 0 and μ = 1 (rad/s), and the
/// kick of the largest spin at the reference friction.
pub fn friction_at_five_cm() -> Result<(f64, f64, kick_3d::validation::SpinPoint), StudyError> {
    use kick_3d::validation::{largest_spin, spin_curve, spin_point, REFERENCE_FRICTION};
    let base = kick_core::Scenario::baseline();
    let spin_at = |mu: f64| spin_point(&base, 0.05, mu).map(|p| p.spin);
    let (spin0, spin1) = (spin_at(0.0)?, spin_at(1.0)?);
    let optimum = largest_spin(&base, &spin_curve(&base, REFERENCE_FRICTION)?)?;
    Ok((spin0, spin1, optimum))
}

/// The flight's own report at launch (Re, S, C_D, C_L) of the free kick at
/// (e, μ) flown to `distance`.
pub fn free_kick_launch(offset: f64, friction: f64, distance: f64) -> Result<kick_flight::Aerodynamics, StudyError> {
    let flight = crate::free_kick::FreeKick::new(offset, friction)?.flight(distance)?;
    Ok(kick_flight::solve(&flight)?.launch)
}

/// The free kick whose bend paper/flight.md takes apart, flown at each
/// constant lift coefficient of `lifts` and with each share of its spin
/// kept at landing of `kept` (kick-flight's validation scene).
pub fn plateau_and_decay(
    kick: (f64, f64),
    lifts: &[f64],
    kept: &[f64],
) -> Result<(Vec<kick_flight::validation::LiftBend>, Vec<kick_flight::validation::SpinDecayBend>), StudyError> {
    use kick_flight::validation::{lift_plateau_bends, spin_decay_bends, FREE_KICK_DISTANCE, FREE_KICK_ELEVATION};
    let (v, w) = kick;
    let bends = lift_plateau_bends(v, w, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE, lifts)?;
    let decays = spin_decay_bends(v, w, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE, kept)?;
    Ok((bends, decays))
}

/// The validation scene's free kicks: distance to the goal (m) and launch elevation (deg).
pub use kick_flight::validation::{FREE_KICK_DISTANCE, FREE_KICK_ELEVATION};
