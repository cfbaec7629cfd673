//! Curve kicks beside Asai et al. (2002) and the measured swerve kicks (the
//! validation chapter of issue 14; measurements in
//! `experiments/validation/measurements.toml`, read by [`kick_core::measurements`]).
//!
//! Asai et al. simulated a deformable ball on a foot (finite elements tuned
//! to 4500 Hz video) and report, in their abstract, that spin grows with the
//! offset of the foot from the ball's axis and with friction, peaks near
//! 100 mm, that friction from 0 to 1 adds at most 13 rad/s, and that the ball
//! spins even without friction because it wraps around the foot. Here the
//! same sweep runs on the rigid sphere of [`crate::Kick3d`]: its normal force
//! acts at the point p = c_b − R n and passes through the centre, so every
//! bit of its spin comes from friction, and none at μ = 0.

use crate::{Accurate3d, Kick3d, Kick3dError, Kick3dSpec};
use kick_core::measurements::{Comparison, MeasurementError, Measurements};
use kick_core::Scenario;
use serde::Serialize;
use thiserror::Error;

const NEEDED_BY: &str = "the curve kicks (kick_3d::validation)";

/// The measurement keys this module reads.
pub mod keys {
    pub const FRICTION_GAIN: &str = "spin_friction_gain_asai2002";
    pub const PEAK_OFFSET: &str = "spin_peak_offset_asai2002";
    pub const ZERO_FRICTION: &str = "spin_zero_friction_asai2002";
    pub const TREND: &str = "spin_trend_asai2002";
    pub const SWERVE_SPEED: &str = "ball_speed_swerve_instep";
    pub const SPIN_MAX: &str = "spin_max_professional";
    pub const FREE_KICK_SPIN: &str = "free_kick_spin";
}

/// Offsets swept, as fractions of R: 0 to 0.98 R in 44 steps (2.45 mm for R = 0.11 m).
pub const OFFSET_STEPS: usize = 44;
pub const LARGEST_OFFSET_FRACTION: f64 = 0.98;
/// Friction coefficient of the model's reference curve kick (kick-3d's default).
pub const REFERENCE_FRICTION: f64 = Kick3d::DEFAULT_FRICTION;
/// Golden-section search for the offset of largest spin stops at this width, m.
pub const OFFSET_TOLERANCE: f64 = 1e-4;

#[derive(Debug, Error, Clone, PartialEq)]
pub enum CurveKickError {
    #[error(transparent)]
    Measurements(#[from] MeasurementError),
    #[error(transparent)]
    Kick(#[from] Kick3dError),
}

/// One off-centre kick of the sweep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpinPoint {
    /// e, m.
    pub offset: f64,
    /// μ.
    pub friction: f64,
    /// |ω| of the ball after contact, rad/s.
    pub spin: f64,
    /// |v| of the ball after contact, m/s.
    pub speed: f64,
    /// ∫ F_n dt, N s.
    pub normal_impulse: f64,
    /// Time the contact slides, s.
    pub slip_time: f64,
    pub contact_time: f64,
}

/// One kick of `base` (Table 1's parameters) at offset `e` and friction `μ`,
/// everything else kick-3d's defaults, on the accurate solver.
pub fn spin_point(base: &Scenario, offset: f64, friction: f64) -> Result<SpinPoint, Kick3dError> {
    let spec = Kick3dSpec { offset: Some(offset), friction: Some(friction), ..Kick3dSpec::default() };
    let kick = Kick3d::new(*base, &spec)?;
    Ok(SpinPoint::of(offset, friction, &Accurate3d::default().solve(&kick)?))
}

impl SpinPoint {
    fn of(offset: f64, friction: f64, o: &crate::Outcome3d) -> SpinPoint {
        let [x, y, z] = o.spin;
        SpinPoint {
            offset,
            friction,
            spin: (x * x + y * y + z * z).sqrt(),
            speed: o.speed,
            normal_impulse: o.normal_impulse,
            slip_time: o.slip_time,
            contact_time: o.contact_time,
        }
    }
}

/// The instep radius of the patch kicks set beside Asai et al.: an
/// assumption, of the order of the ball's radius (no published instep or
/// boot-vamp curvature was found; see [`crate::patch`]).
pub const ASSUMED_INSTEP_RADIUS: f64 = 0.15;

/// One kick of the shell ball (`shell`, a scenario with law `shell`) on a
/// convex instep of radius `instep_radius`, face square to the swing
/// (yaw 0), the contact spread over its patch ([`crate::patch`]); the offset
/// is the ball centre's distance from the swing line through the instep's
/// apex, as Asai et al.'s foot-axis-to-ball-axis offset. Returns the spin
/// vector (world frame, rad/s) with the point.
pub fn patch_spin_point(shell: &Scenario, offset: f64, friction: f64, instep_radius: f64) -> Result<(SpinPoint, [f64; 3]), Kick3dError> {
    let spec = Kick3dSpec {
        offset: Some(offset),
        friction: Some(friction),
        face_yaw_deg: Some(0.0),
        instep_radius: Some(instep_radius),
        patch_contact: Some(true),
        ..Kick3dSpec::default()
    };
    let o = Accurate3d::default().solve(&Kick3d::new(*shell, &spec)?)?;
    Ok((SpinPoint::of(offset, friction, &o), o.spin))
}

/// The offsets of the sweep for a ball of radius `radius`.
pub fn offsets(radius: f64) -> Vec<f64> {
    (0..=OFFSET_STEPS).map(|i| LARGEST_OFFSET_FRACTION * radius * i as f64 / OFFSET_STEPS as f64).collect()
}

/// Spin against offset at one friction coefficient.
pub fn spin_curve(base: &Scenario, friction: f64) -> Result<Vec<SpinPoint>, Kick3dError> {
    offsets(Kick3d::DEFAULT_BALL_RADIUS).into_iter().map(|e| spin_point(base, e, friction)).collect()
}

/// The offset of largest spin: the sweep's best point, refined by
/// golden-section search between its neighbours to [`OFFSET_TOLERANCE`].
pub fn largest_spin(base: &Scenario, curve: &[SpinPoint]) -> Result<SpinPoint, Kick3dError> {
    let Some(best) = (0..curve.len()).max_by(|&a, &b| curve[a].spin.total_cmp(&curve[b].spin)) else {
        return Err(Kick3dError::InvalidParameter { name: "offset", value: f64::NAN, requirement: "a non-empty sweep" });
    };
    let friction = curve[best].friction;
    let (mut lo, mut hi) = (curve[best.saturating_sub(1)].offset, curve[(best + 1).min(curve.len() - 1)].offset);
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let mut a = spin_point(base, hi - ratio * (hi - lo), friction)?;
    let mut b = spin_point(base, lo + ratio * (hi - lo), friction)?;
    // Each step shrinks the bracket by 0.618; 2 steps per mm of 5 mm is plenty.
    for _ in 0..64 {
        if hi - lo <= OFFSET_TOLERANCE {
            break;
        }
        if a.spin < b.spin {
            lo = a.offset;
            a = b;
            b = spin_point(base, lo + ratio * (hi - lo), friction)?;
        } else {
            hi = b.offset;
            b = a;
            a = spin_point(base, hi - ratio * (hi - lo), friction)?;
        }
    }
    let refined = if a.spin >= b.spin { a } else { b };
    Ok(if refined.spin >= curve[best].spin { refined } else { curve[best] })
}

/// The model's curve kicks and what they are set beside.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveKicks {
    /// Spin against offset at μ = 0, 0.5 and 1.
    pub curves: Vec<Vec<SpinPoint>>,
    /// The largest spin at μ = 0.5 and at μ = 1.
    pub largest: Vec<SpinPoint>,
    pub comparisons: Vec<Comparison>,
}

/// Whether spin rises at every step of the sweep up to its largest value.
fn rises_to_peak(curve: &[SpinPoint]) -> bool {
    let peak = (0..curve.len()).max_by(|&a, &b| curve[a].spin.total_cmp(&curve[b].spin)).unwrap_or(0);
    curve[..=peak].windows(2).all(|w| w[1].spin > w[0].spin)
}

/// The offset–friction sweep of `base` beside Asai et al. (2002) and the
/// measured swerve and free kicks.
pub fn curve_kick_comparisons(m: &Measurements, base: &Scenario) -> Result<CurveKicks, CurveKickError> {
    let frictions = [0.0, REFERENCE_FRICTION, 1.0];
    let curves: Vec<Vec<SpinPoint>> = frictions.iter().map(|&mu| spin_curve(base, mu)).collect::<Result<_, _>>()?;
    let (frictionless, reference, full) = (&curves[0], &curves[1], &curves[2]);
    let largest = vec![largest_spin(base, reference)?, largest_spin(base, full)?];
    let gain = full.iter().zip(frictionless).map(|(a, b)| a.spin - b.spin).fold(f64::NEG_INFINITY, f64::max);
    let zero = frictionless.iter().map(|p| p.spin).fold(0.0, f64::max);
    let get = |key: &str| m.measured(key, NEEDED_BY);
    let v_f = base.foot_speed();
    let at = |p: &SpinPoint| format!("at e = {:.1} mm, mu = {}, v_f = {v_f} m/s", 1e3 * p.offset, p.friction);
    let rigid = "a rigid sphere: its normal force passes through the centre, so spin comes from friction alone";
    let mut rows = vec![
        Comparison::new(
            "spin added by friction 0 -> 1 (largest over offsets)",
            get(keys::FRICTION_GAIN)?,
            gain,
            format!(
                "{rigid}; in Asai et al.'s deformable ball most spin comes from wrapping, which friction only tops up \
                 (v_f = {v_f} m/s)"
            ),
        ),
        Comparison::new(
            "spin without friction (largest over offsets)",
            m.claimed(keys::ZERO_FRICTION, NEEDED_BY)?,
            zero,
            format!("{rigid}: zero to rounding; Asai et al.'s wrapping spin has no number in their abstract"),
        ),
    ];
    for p in &largest {
        rows.push(Comparison::new(
            format!("offset of largest spin, mu = {}", p.friction),
            get(keys::PEAK_OFFSET)?,
            p.offset,
            format!(
                "beyond it the normal tilts so far that the foot glances off: speed and normal impulse fall faster \
                 than the lever gains ({})",
                at(p)
            ),
        ));
    }
    let peak = &largest[0];
    rows.push(Comparison::new(
        "spin growth with offset",
        m.claimed(keys::TREND, NEEDED_BY)?,
        peak.spin,
        format!(
            "largest spin {}; rises at every step of the sweep up to it: mu = 0.5 {}, mu = 1 {}; larger at mu = 1 \
             than 0.5 beyond e = {:.0} mm only",
            at(peak),
            rises_to_peak(reference),
            rises_to_peak(full),
            1e3 * crossover(reference, full),
        ),
    ));
    for key in [keys::SPIN_MAX, keys::FREE_KICK_SPIN] {
        rows.push(Comparison::new(
            "largest spin of the reference curve kick",
            get(key)?,
            peak.spin,
            format!("{}; spin scales with the foot speed", at(peak)),
        ));
    }
    rows.push(Comparison::new(
        "ball speed at the offset of largest spin",
        get(keys::SWERVE_SPEED)?,
        peak.speed,
        format!("{} (Table 1's foot speed, not a measured one)", at(peak)),
    ));
    Ok(CurveKicks { curves, largest, comparisons: rows })
}

/// The smallest swept offset beyond which μ = 1 spins the ball more than μ = 0.5
/// (the first offset if it always does).
fn crossover(half: &[SpinPoint], full: &[SpinPoint]) -> f64 {
    let last_below = half.iter().zip(full).rposition(|(h, f)| f.spin <= h.spin && h.spin > 0.0);
    match last_below {
        Some(i) if i + 1 < full.len() => full[i + 1].offset,
        Some(i) => full[i].offset,
        None => full.first().map_or(0.0, |p| p.offset),
    }
}
