//! `kick leg`: the articulated leg's effective mass at the instep (Eq. 11,
//! kick-leg) and the 1D exit speed that follows with m_f = m_eff (Section
//! 14.1); the figure data as two levels of the run loop
//! ([`crate::level::leg`]), which kick-store writes and kick-paper draws.

use crate::error::StudyError;
use crate::level::leg::{LegMassAxis, LegPoseGrid};
use crate::printable::Printable;
use kick_core::leg::LegPose;
use kick_core::{sig, Outcome, Scenario};
use kick_leg::{
    anthropometry::{DE_LEVA_BODY_MASS, DE_LEVA_STATURE},
    exit_outcome, AnkleJoint, HipSupport, Impact, Leg, LegEffectiveMass, Pose, Variant,
};
use nalgebra::Vector3;
use serde::ser::{Serialize, Serializer};
use serde_json::{json as value, Value};
use std::fmt::Write as _;
use std::path::PathBuf;

/// The figure data's tables, by file name: effective mass over the knee and
/// ankle grid, exit speed over the effective mass.
pub const EFFECTIVE_MASS_TABLE: &str = "leg_effective_mass";
pub const EXIT_SPEED_TABLE: &str = "leg_exit_speed";

/// The leg, its pose and the impact, as given (angles in degrees).
#[derive(Debug, Clone, PartialEq)]
pub struct LegSettings {
    /// Knee flexion (0 = straight).
    pub knee: f64,
    /// Ankle plantarflexion from neutral (0 = foot at right angles to the shank).
    pub ankle: f64,
    /// Thigh angle from the downward vertical, positive forward.
    pub hip: f64,
    pub locked_ankle: bool,
    /// Ankle torsional stiffness, N m/rad: leg and ball integrated together.
    pub ankle_stiffness: Option<f64>,
    pub locked_knee: bool,
    pub free_hip: bool,
    /// Spatial leg (ball-joint hip): abduction, rotation and lateral offset apply.
    pub spatial: bool,
    pub abduction: f64,
    pub rotation: f64,
    /// Contact offset along the foot's mediolateral axis, m.
    pub lateral_offset: f64,
    /// Contact point from the ankle along the foot, fraction of foot length.
    pub contact: f64,
    /// Impact direction in the sagittal plane, degrees above horizontal-forward.
    pub direction: f64,
    pub body_mass: f64,
    pub height: f64,
}

impl Default for LegSettings {
    /// The documented default pose (the declared `knee`, `ankle` and `hip`:
    /// knee 30°, ankle 60°, thigh 10° forward), free knee and ankle, pinned
    /// hip, planar, instep at 0.65 of the foot, horizontal impact, de Leva's
    /// reference subject.
    fn default() -> Self {
        let pose = LegPose::DEFAULT;
        LegSettings {
            knee: pose.knee,
            ankle: pose.ankle,
            hip: pose.hip,
            locked_ankle: false,
            ankle_stiffness: None,
            locked_knee: false,
            free_hip: false,
            spatial: false,
            abduction: 0.0,
            rotation: 0.0,
            lateral_offset: 0.0,
            contact: 0.65,
            direction: 0.0,
            body_mass: DE_LEVA_BODY_MASS,
            height: DE_LEVA_STATURE,
        }
    }
}

/// The leg's effective mass and the 1D contact it gives.
#[derive(Debug, Clone)]
pub struct LegReport {
    pub settings: LegSettings,
    pub mass: LegEffectiveMass,
    pub leg_mass: f64,
    pub outcome: Outcome,
    /// "free", "locked" or "elastic, κ N m/rad".
    pub ankle: String,
    pub elastic: Option<kick_leg::ankle::ElasticAnkle>,
    /// Files written from it (the front end's, kick-store's and kick-paper's).
    pub written: Vec<PathBuf>,
    leg: Leg,
    pose: Pose,
    impact: Impact,
    base: Scenario,
}

/// Effective mass of the leg (Eq. 11) and the 1D exit speed with m_f = m_eff.
pub fn leg(settings: &LegSettings) -> Result<LegReport, StudyError> {
    let args = settings;
    let mut leg = Leg::de_leva(args.body_mass, args.height)?;
    leg.hip = if args.free_hip { HipSupport::Free } else { HipSupport::Pinned };
    leg.variant = if args.spatial { Variant::Spatial } else { Variant::Planar };
    leg.knee_locked = args.locked_knee;
    let pose = Pose {
        hip_flexion: args.hip,
        knee_flexion: args.knee,
        plantarflexion: args.ankle,
        hip_abduction: args.abduction,
        hip_rotation: args.rotation,
    };
    // An angle in the sagittal plane: one turn, as the joint angles are bounded.
    if !(-180.0..=180.0).contains(&args.direction) {
        return Err(StudyError::Flag {
            flag: "--direction",
            message: format!("invalid `direction` = {}: must be within -180..180 degrees", kick_core::number::given(args.direction)),
        });
    }
    if args.locked_ankle && args.ankle_stiffness.is_some() {
        return Err(StudyError::Flag { flag: "--locked-ankle", message: "--locked-ankle and --ankle-stiffness exclude each other".into() });
    }
    let angle = args.direction.to_radians();
    let impact = Impact {
        contact_fraction: args.contact,
        lateral_offset: args.lateral_offset,
        direction: Vector3::new(angle.cos(), angle.sin(), 0.0),
    };
    let base = Scenario::baseline();
    // An elastic ankle is integrated with the ball (kick_leg::ankle); its
    // m_eff is the 1D-equivalent mass, with the interpolation shown beside it.
    let (mass, outcome, ankle, elastic) = match (args.locked_ankle, args.ankle_stiffness) {
        (_, Some(k)) => {
            let e = kick_leg::ankle::elastic_ankle(&leg, &pose, &impact, k, &base)?;
            let mass = LegEffectiveMass { effective_mass: e.equivalent_mass, ..e.interpolated };
            (mass, e.outcome, format!("elastic, {} N m/rad", kick_core::number::short(k)), Some(e))
        }
        (locked, None) => {
            let joint = if locked { AnkleJoint::Locked } else { AnkleJoint::Free };
            let mass = leg.effective_mass(&pose, &impact, joint)?;
            let outcome = exit_outcome(mass.effective_mass, &base)?;
            (mass, outcome, if locked { "locked".into() } else { "free".into() }, None)
        }
    };
    Ok(LegReport {
        settings: settings.clone(),
        mass,
        leg_mass: leg.segments.total_mass(),
        outcome,
        ankle,
        elastic,
        written: Vec::new(),
        leg,
        pose,
        impact,
        base,
    })
}

impl LegReport {
    /// The figure data as two levels of the run loop: effective mass over
    /// the knee and ankle grid at this leg and impact, and the exit speed
    /// over the effective mass ([`EFFECTIVE_MASS_TABLE`], [`EXIT_SPEED_TABLE`]).
    pub fn figure_levels(&self) -> (LegPoseGrid, LegMassAxis) {
        let (knees, ankles) = grid_axes();
        let grid = LegPoseGrid { leg: self.leg, pose: self.pose, impact: self.impact, base: self.base, knees, ankles };
        (grid, LegMassAxis { base: self.base, masses: mass_axis() })
    }

    fn labels(&self) -> (&'static str, &'static str, &'static str) {
        let s = &self.settings;
        (
            if s.free_hip { "free" } else { "pinned" },
            if s.locked_knee { "locked" } else { "free" },
            if s.spatial { "spatial" } else { "planar" },
        )
    }
}

impl Serialize for LegReport {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let (hip, knee, variant) = self.labels();
        let (mass, outcome) = (&self.mass, &self.outcome);
        let mut object: Value = value!({
            "effective_mass": mass.effective_mass,
            "locked_ankle": mass.locked_ankle,
            "free_ankle": mass.free_ankle,
            "locked_share": mass.locked_share,
            "ankle_inertia": mass.ankle_inertia,
            "leg_mass": self.leg_mass,
            "ankle": self.ankle,
            "hip": hip,
            "knee": knee,
            "variant": variant,
            "v_ball_out": outcome.v_ball_out,
            "v_foot_out": outcome.v_foot_out,
            "speed_ratio": outcome.speed_ratio,
            "contact_time": outcome.contact_time,
            "solver": "accurate",
        });
        if let Some(e) = &self.elastic {
            object["interpolated_mass"] = value!(e.interpolated.effective_mass);
            object["max_ankle_deflection"] = value!(e.coupled.max_ankle_deflection);
            object["coupled_v_ball_out"] = value!(e.coupled.v_ball_out);
            object["coupled_contact_time"] = value!(e.coupled.contact_time);
        }
        object.serialize(serializer)
    }
}

impl Printable for LegReport {
    fn text(&self) -> String {
        let (hip, knee, variant) = self.labels();
        let (s, mass, outcome) = (&self.settings, &self.mass, &self.outcome);
        let mut w = String::new();
        let _ = writeln!(
            w,
            "leg: de Leva (1996) male, {} kg, {} m, {hip} hip, {knee} knee, {} ankle ({variant})",
            sig(s.body_mass),
            sig(s.height),
            self.ankle
        );
        let _ = writeln!(w, "{:<20} {:>12} kg", "effective_mass", sig(mass.effective_mass));
        let _ = writeln!(w, "{:<20} {:>12} kg", "locked_ankle", sig(mass.locked_ankle));
        let _ = writeln!(w, "{:<20} {:>12} kg", "free_ankle", sig(mass.free_ankle));
        let _ = writeln!(w, "{:<20} {:>12}", "locked_share", sig(mass.locked_share));
        let _ = writeln!(w, "{:<20} {:>12} kg", "leg_mass", sig(self.leg_mass));
        if let Some(e) = &self.elastic {
            let _ = writeln!(
                w,
                "{:<20} {:>12} kg (series-spring interpolation, for comparison)",
                "interpolated_mass",
                sig(e.interpolated.effective_mass)
            );
            let _ = writeln!(
                w,
                "{:<20} {:>12} rad (coupled leg-ball run, frozen geometry)",
                "max_ankle_deflection",
                sig(e.coupled.max_ankle_deflection)
            );
            let _ = writeln!(w, "{:<20} {:>12} s (coupled leg-ball run)", "coupled_contact_time", sig(e.coupled.contact_time));
        }
        let _ = writeln!(w, "1D contact with m_f = effective_mass (Table 1 otherwise, accurate solver):");
        let _ = writeln!(w, "{:<20} {:>12} m/s", "v_ball_out", sig(outcome.v_ball_out));
        let _ = writeln!(w, "{:<20} {:>12} m/s", "v_foot_out", sig(outcome.v_foot_out));
        let _ = writeln!(w, "{:<20} {:>12}", "speed_ratio", outcome.speed_ratio.map_or("undefined".to_string(), |r| sig(r).to_string()));
        let _ = writeln!(w, "{:<20} {:>12} s", "contact_time", sig(outcome.contact_time));
        w
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

/// Knee and ankle angles of the effective-mass figure, degrees.
fn grid_axes() -> (Vec<f64>, Vec<f64>) {
    ((0..=24).map(|i| 5.0 * f64::from(i)).collect(), (0..=18).map(|i| 5.0 * f64::from(i)).collect())
}

/// Effective foot masses of the exit-speed figure: 0.2 to 20 kg, log-spaced.
fn mass_axis() -> Vec<f64> {
    (0..=60).map(|i| 0.2 * 100f64.powf(f64::from(i) / 60.0)).collect()
}
