//! `kick leg`'s files: the figure data (kick-study's leg levels, written by
//! kick-store's sweep writer) and the figures drawn back from them.

use crate::error::PaperError;
use kick_study::leg::{LegReport, LegSettings, EFFECTIVE_MASS_TABLE, EXIT_SPEED_TABLE};
use std::path::PathBuf;

/// `kick leg` as asked: the study, and with `sweep_out` its figure data and figures.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LegRun {
    pub settings: LegSettings,
    /// Also write the figure data (HDF5) and figures here.
    pub sweep_out: Option<PathBuf>,
    /// The command that asked, for the files' provenance.
    pub command: String,
}

/// [`kick_study::leg::leg`]; with `sweep_out` the figure data and figures too.
pub fn leg(run: &LegRun) -> Result<LegReport, PaperError> {
    let mut report = kick_study::leg::leg(&run.settings)?;
    if let Some(dir) = &run.sweep_out {
        let (grid, axis) = report.figure_levels();
        let tables: [(&str, &dyn kick_study::level::Level); 2] = [(EFFECTIVE_MASS_TABLE, &grid), (EXIT_SPEED_TABLE, &axis)];
        let command = if run.command.is_empty() { "kick leg" } else { run.command.as_str() };
        report.written.extend(crate::run::write_levels(dir, &tables, "kick leg (command line)", command)?);
        report.written.extend(draw_figures(dir, &dir.join("figures"))?);
    }
    Ok(report)
}

/// The leg's figures, drawn from the two result files (not re-computed):
/// effective mass against knee flexion for several ankle angles (locked and
/// free ankle), and the 1D exit speed against effective mass (Section 14.1).
fn draw_figures(results: &std::path::Path, out: &std::path::Path) -> Result<Vec<std::path::PathBuf>, PaperError> {
    use crate::figures::{color, save_grid, Panel, Series};
    use crate::SweepData;
    use plotters::prelude::{RGBColor, SeriesLabelPosition};
    let grid = SweepData::read(&results.join(format!("{EFFECTIVE_MASS_TABLE}.h5")))?;
    let knee = grid.parameter("knee")?;
    let ankle = grid.parameter("ankle")?;
    let mut panels = Vec::new();
    for (set, title) in [("locked-ankle", "Locked ankle"), ("free-ankle", "Free ankle")] {
        let mass = grid.set(set)?.column("effective_mass").ok_or_else(|| PaperError::missing("no effective_mass column"))?;
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
    let mut written = save_grid(out, "leg_effective_mass", "Articulated leg (de Leva 1996 segments)", (1, 2), &panels)?;
    let speeds = SweepData::read(&results.join(format!("{EXIT_SPEED_TABLE}.h5")))?;
    let foot_mass = speeds.parameter("foot_mass")?;
    let set = speeds.set("accurate")?;
    let v = set.column("v_ball_out").ok_or_else(|| PaperError::missing("no v_ball_out column"))?;
    let bound = set.column("elastic_bound_v_ball_out").ok_or_else(|| PaperError::missing("no elastic bound column"))?;
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
    written.extend(save_grid(out, "leg_exit_speed", "Diminishing returns of effective mass", (1, 1), &[panel])?);
    Ok(written)
}

/// leg.md: the default pose's effective mass with the ankle free, locked,
/// and knee and ankle locked (kick-study's `leg`), the 1D kick each gives,
/// and the exit speed against m_f read back from `results` (the figure's
/// data). `command` is the reproduction's; `out` and `figures` are as the
/// page links them.
pub fn page(results: &std::path::Path, out: &str, figures: &str, command: &str) -> Result<String, PaperError> {
    use kick_study::printable::short;
    let default = LegSettings::default();
    let free = kick_study::leg::leg(&default)?;
    let ankle = kick_study::leg::leg(&LegSettings { locked_ankle: true, ..default.clone() })?;
    let braced = kick_study::leg::leg(&LegSettings { locked_ankle: true, locked_knee: true, ..default.clone() })?;
    let base = kick_study::parameters::Scenario::baseline();
    let row = |name: &str, r: &LegReport| {
        format!(
            "| {name} | {} | {} | {} | {} |\n",
            short(r.mass.effective_mass),
            short(r.outcome.v_ball_out),
            short(r.outcome.v_ball_out / base.foot_speed()),
            short(r.outcome.contact_time * 1e3)
        )
    };
    let speeds = crate::SweepData::read(&results.join(format!("{EXIT_SPEED_TABLE}.h5")))?;
    let masses = speeds.parameter("foot_mass")?;
    let v = speeds.set("accurate")?.column("v_ball_out").ok_or_else(|| PaperError::missing("no v_ball_out column"))?;
    // The axis's first, middle and last masses (0.2, 2 and 20 kg: a decade each way).
    let at = |i: usize| (masses[i], v[i]);
    let ((m0, v0), (m1, v1), (m2, v2)) = (at(0), at(masses.len() / 2), at(masses.len() - 1));
    Ok(format!(
        "# Effective mass of the articulated leg (Eq. 11)\n\n\
         Generated by `kick reproduce` (`{command}`). A three-segment leg (thigh, shank, foot; de Leva 1996 segment \
         parameters for a 73 kg, 1.741 m male), pinned at the hip, struck at the instep ({} of the foot's length from \
         the ankle) by an impact along the horizontal, forward (`--direction 0`; the pose does not turn it): \
         m_eff = (nᵀ J M⁻¹ Jᵀ n)⁻¹ (Eq. 11). The pose is assumed, not measured: knee flexion {}°, ankle {}° of \
         plantarflexion (0° = foot at right angles to the shank), thigh {}° forward of the downward vertical, the knee \
         and ankle free hinges unless locked. Data: `{out}/leg_effective_mass.h5`, `{out}/leg_exit_speed.h5`; the \
         model's choices: `crates/kick-leg/README.md`; its tests: `crates/kick-leg/tests/leg/`.\n\n\
         At that pose, the 1D kick with m_f = m_eff (Table 1's contact otherwise, the foot at {} m/s, `accurate`):\n\n\
         | joints | m_eff (kg) | v_b⁺ (m/s) | v_b⁺/v_f⁻ | contact time (ms) |\n| --- | --- | --- | --- | --- |\n{}{}{}\n\
         Only the braced leg (`--locked-knee --locked-ankle`) comes near Table 1's assumed m_f = {} kg; with the ankle \
         free the ball leaves slower than the foot arrived. Locking the ankle is the `leg = true` foot of the kicks \
         (its apparent inertia at the contact point, `kick simulate --leg`).\n\n\
         ![effective mass]({figures}/leg_effective_mass.png)\n\n\
         The exit speed that follows through the 1D model (baseline contact, foot at {} m/s, `accurate`), with the \
         perfectly elastic bound of Eq. 38: v_b⁺ = {} m/s at m_f = {} kg, {} at {} kg, {} at {} kg. The second decade \
         of foot mass adds {} m/s, the first {}: the gains shrink but have not flattened by {} ball masses \
         (Section 14.1: m_f ≫ m_b).\n\n\
         ![exit speed]({figures}/leg_exit_speed.png)\n",
        short(default.contact),
        short(default.knee),
        short(default.ankle),
        short(default.hip),
        short(base.foot_speed()),
        row("knee and ankle free", &free),
        row("ankle locked", &ankle),
        row("knee and ankle locked", &braced),
        short(base.effective_foot_mass()),
        short(base.foot_speed()),
        short(v0),
        short(m0),
        short(v1),
        short(m1),
        short(v2),
        short(m2),
        crate::units::three(v2 - v1),
        crate::units::three(v1 - v0),
        crate::units::three(m2 / base.ball_mass()),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The page's rows are the leg's, and its claim that the locked ankle is
    /// the kicks' `leg = true` foot holds: that foot's mass, built through
    /// the scenario (kick-core's apparent inertia along the line of motion),
    /// is the row's to 1e-12.
    #[test]
    fn the_leg_page_quotes_the_leg_and_the_kicks_foot() {
        let dir = std::env::temp_dir().join(format!("kick-paper-leg-page-{}", std::process::id()));
        leg(&LegRun { sweep_out: Some(dir.clone()), ..Default::default() }).unwrap();
        let page = page(&dir, "results", "figures", "kick leg").unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        let locked = kick_study::leg::leg(&LegSettings { locked_ankle: true, ..Default::default() }).unwrap().mass.effective_mass;
        let spec = kick_study::parameters::ScenarioSpec { leg: Some(true), boot_stiffness: Some(f64::INFINITY), ..Default::default() };
        let foot = spec.build().unwrap().effective_foot_mass();
        assert!((foot - locked).abs() < 1e-12 * locked, "{foot} {locked}");
        let row = format!("| ankle locked | {} |", kick_study::printable::short(locked));
        assert!(page.contains(&row), "{row}\n{page}");
        // Free < locked < braced < Table 1's 3 kg, as the page says.
        let mass = |locked_ankle, locked_knee| {
            kick_study::leg::leg(&LegSettings { locked_ankle, locked_knee, ..Default::default() }).unwrap().mass.effective_mass
        };
        assert!(mass(false, false) < locked && locked < mass(true, true) && mass(true, true) < 3.0);
        // "with the ankle free the ball leaves slower than the foot arrived"
        let free = kick_study::leg::leg(&LegSettings::default()).unwrap().outcome;
        assert!(free.v_ball_out < kick_study::parameters::Scenario::baseline().foot_speed(), "{free:?}");
    }
}
