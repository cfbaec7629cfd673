//! `kick leg`: effective mass of the articulated leg (Eq. 11, kick-leg) and
//! the 1D exit speed that follows with m_f = m_eff (Section 14.1).

use crate::printable::Printable;
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
    /// Also write the figure data (HDF5) and figures here.
    pub sweep_out: Option<PathBuf>,
    /// The command that asked, for the files' provenance.
    pub command: String,
}

impl Default for LegSettings {
    /// The documented default pose: knee 30°, ankle 60°, thigh 10° forward,
    /// free knee and ankle, pinned hip, planar, instep at 0.65 of the foot,
    /// horizontal impact, de Leva's reference subject.
    fn default() -> Self {
        LegSettings {
            knee: 30.0,
            ankle: 60.0,
            hip: 10.0,
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
            sweep_out: None,
            command: "kick leg".into(),
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
    pub written: Vec<PathBuf>,
}

/// Effective mass of the leg (Eq. 11) and the 1D exit speed with m_f = m_eff;
/// with `sweep_out`, the figure data and figures too.
pub fn leg(settings: &LegSettings) -> Result<LegReport, String> {
    let args = settings;
    let mut leg = Leg::de_leva(args.body_mass, args.height).map_err(|e| e.to_string())?;
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
    if !args.direction.is_finite() {
        return Err(format!("invalid `direction` = {}: must be finite", args.direction));
    }
    if args.locked_ankle && args.ankle_stiffness.is_some() {
        return Err("--locked-ankle and --ankle-stiffness exclude each other".into());
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
            let e = kick_leg::ankle::elastic_ankle(&leg, &pose, &impact, k, &base).map_err(|e| e.to_string())?;
            let mass = LegEffectiveMass { effective_mass: e.equivalent_mass, ..e.interpolated };
            (mass, e.outcome, format!("elastic, {k} N m/rad"), Some(e))
        }
        (locked, None) => {
            let joint = if locked { AnkleJoint::Locked } else { AnkleJoint::Free };
            let mass = leg.effective_mass(&pose, &impact, joint).map_err(|e| e.to_string())?;
            let outcome = exit_outcome(mass.effective_mass, &base).map_err(|e| e.to_string())?;
            (mass, outcome, if locked { "locked".into() } else { "free".into() }, None)
        }
    };
    let mut written = Vec::new();
    if let Some(dir) = &args.sweep_out {
        written.extend(write_sweeps(dir, &leg, &pose, &impact, &base, &args.command)?);
        written.extend(draw_figures(dir, &dir.join("figures"))?);
    }
    Ok(LegReport { settings: settings.clone(), mass, leg_mass: leg.segments.total_mass(), outcome, ankle, elastic, written })
}

impl LegReport {
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

/// The leg's figures, drawn from the two result files (not re-computed):
/// effective mass against knee flexion for several ankle angles (locked and
/// free ankle), and the 1D exit speed against effective mass (Section 14.1).
fn draw_figures(results: &std::path::Path, out: &std::path::Path) -> Result<Vec<std::path::PathBuf>, String> {
    use crate::figures::{color, save_grid, Panel, Series};
    use crate::SweepData;
    use plotters::prelude::{RGBColor, SeriesLabelPosition};
    let grid = SweepData::read(&results.join("leg_effective_mass.h5")).map_err(|e| e.to_string())?;
    let knee = grid.parameter("knee").map_err(|e| e.to_string())?;
    let ankle = grid.parameter("ankle").map_err(|e| e.to_string())?;
    let mut panels = Vec::new();
    for (set, title) in [("locked-ankle", "Locked ankle"), ("free-ankle", "Free ankle")] {
        let mass = grid.set(set).map_err(|e| e.to_string())?.column("effective_mass").ok_or("no effective_mass column")?;
        let series = [0.0, 30.0, 60.0, 90.0]
            .iter()
            .enumerate()
            .map(|(i, &a)| {
                let (x, y): (Vec<f64>, Vec<f64>) =
                    knee.iter().zip(ankle).zip(mass).filter(|((_, &an), _)| an == a).map(|((&k, _), &m)| (k, m)).unzip();
                Series::line(&format!("ankle {a:.0}°"), color(i), &x, &y)
            })
            .collect();
        panels.push(Panel {
            title: format!("{title}: effective mass at the instep (Eq. 11)"),
            x_label: "knee flexion (deg)".into(),
            y_label: "effective foot mass m_eff (kg)".into(),
            log_x: false,
            series,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
        });
    }
    let mut written =
        save_grid(out, "leg_effective_mass", "Articulated leg (de Leva 1996 segments)", (1, 2), &panels).map_err(|e| e.to_string())?;
    let speeds = SweepData::read(&results.join("leg_exit_speed.h5")).map_err(|e| e.to_string())?;
    let foot_mass = speeds.parameter("foot_mass").map_err(|e| e.to_string())?;
    let set = speeds.set("accurate").map_err(|e| e.to_string())?;
    let v = set.column("v_ball_out").ok_or("no v_ball_out column")?;
    let bound = set.column("elastic_bound_v_ball_out").ok_or("no elastic bound column")?;
    let panel = Panel {
        title: "Exit speed against effective foot mass (baseline contact)".into(),
        x_label: "effective foot mass m_f (kg, log scale)".into(),
        y_label: "ball exit speed v_b+ (m/s)".into(),
        log_x: true,
        series: vec![
            Series::line("1D model (accurate)", color(0), foot_mass, v),
            Series::line("perfectly elastic bound (Eq. 38, e = 1)", RGBColor(0, 0, 0), foot_mass, bound).dashed(),
        ],
        y_from_zero: true,
        legend: SeriesLabelPosition::LowerRight,
    };
    written.extend(save_grid(out, "leg_exit_speed", "Diminishing returns of effective mass", (1, 1), &[panel]).map_err(|e| e.to_string())?);
    Ok(written)
}

/// Figure data as two tables of the one run loop (kick-study's leg levels)
/// through kick-store's sweep writer: parameters and outcome columns with
/// units, provenance at the root.
fn write_sweeps(
    dir: &std::path::Path,
    leg: &Leg,
    pose: &Pose,
    impact: &Impact,
    base: &Scenario,
    command: &str,
) -> Result<Vec<std::path::PathBuf>, String> {
    use crate::run::{create_table, fill_table, finish_table};
    use crate::Provenance;
    use kick_study::level::leg::{LegMassAxis, LegPoseGrid};
    use kick_study::level::Level;
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let (knees, ankles) = grid_axes();
    let grid = LegPoseGrid { leg: *leg, pose: *pose, impact: *impact, base: *base, knees, ankles };
    let axis = LegMassAxis { base: *base, masses: mass_axis() };
    let tables: [(&str, &dyn Level); 2] = [("leg_effective_mass", &grid), ("leg_exit_speed", &axis)];
    let mut written = Vec::new();
    for (name, level) in tables {
        let path = dir.join(format!("{name}.h5"));
        let provenance = Provenance::now(name, "kick leg (command line)", command);
        let bar = indicatif::ProgressBar::hidden();
        let mut writer = create_table(level, &path, &provenance, level.rows(), Default::default()).map_err(|e| e.to_string())?;
        fill_table(level, 0..level.rows(), &mut writer, &bar).map_err(|e| e.to_string())?;
        written.push(finish_table(level, writer, &bar).map_err(|e| e.to_string())?.path);
    }
    Ok(written)
}
