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
