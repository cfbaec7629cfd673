//! The numbers kick-paper's 3D page states, computed here so the page only
//! writes them: the accurate path's error over the off-center box, its gap
//! to the 1D solver on a central kick, the scene path's error and order, the
//! force-history kick and the 1D baseline it is compared with.

use kick_3d::{Accurate3d, Kick3d, KickSpec, Outcome3d, Solver3d};
use kick_core::parameters::{SetParameter, Value};
use kick_core::{Outcome, Solver};

use crate::error::StudyError;

/// The kick the force-history figure shows: offset 5 cm, μ 0.5, baseline otherwise.
pub fn history_kick() -> Result<Kick3d, StudyError> {
    let mut spec = KickSpec::default();
    spec.set_named("offset", Value::Number(0.05))?;
    spec.set_named("friction", Value::Number(0.5))?;
    Ok(spec.build()?)
}

/// Largest relative error of the accurate path against the tightened
/// full-state reference over the first `kicks` kicks of the box, per
/// observable (kick_3d::precision::Errors3d order).
pub fn box_errors(kicks: u64) -> Result<[f64; 8], StudyError> {
    let sample = kick_3d::models::OffCenterBox::new(kick_3d::models::BENCH_SEED);
    let mut worst = [0.0f64; 8];
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
