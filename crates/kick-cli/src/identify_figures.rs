//! Figures of `kick laws` and `kick fit profile`, drawn with the runner's
//! plotting helpers from the data those commands also write as JSON.

use kick_identify::laws::LawComparison;
use kick_identify::profile::{IdentifiabilityStudy, Profile};
use kick_runner::figures::{save_grid, Panel, Series};
use plotters::prelude::SeriesLabelPosition;
use std::path::{Path, PathBuf};

use kick_runner::figures::COLORS;

/// `laws.png/svg`: each Table 2 scenario's force pulse under every law, and
/// the peak forces side by side.
pub fn laws(all: &[LawComparison], dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut panels = Vec::new();
    for (i, c) in all.iter().enumerate() {
        let series = c
            .runs
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let t: Vec<f64> = r.pulse.iter().map(|p| p.0 * 1e3).collect();
                let f: Vec<f64> = r.pulse.iter().map(|p| p.1 * 1e-3).collect();
                // Legend once, on the first panel.
                let label = if i == 0 { r.law.name() } else { "" };
                let s = Series::line(label, COLORS[k % COLORS.len()], &t, &f);
                if r.law == kick_core::laws::LawKind::PowerLaw { s } else { s.dashed() }
            })
            .collect();
        panels.push(Panel::new(&c.name, "time (ms)", "force (kN)", series));
    }
    if let Some(first) = all.first() {
        let x: Vec<f64> = (1..=all.len()).map(|i| i as f64).collect();
        let series = first
            .runs
            .iter()
            .enumerate()
            .map(|(k, _)| {
                let y: Vec<f64> = all.iter().map(|c| c.runs[k].outcome.peak_force * 1e-3).collect();
                Series::line("", COLORS[k % COLORS.len()], &x, &y).with_markers()
            })
            .collect::<Vec<_>>();
        panels.push(Panel::new("Peak force per Table 2 row (1 = baseline … 8)", "Table 2 row", "peak force (kN)", series));
    }
    save_grid(dir, "laws", "Contact laws on Table 2's scenarios (same restitution target as the paper's law)", (3, 3), &panels)
        .map_err(|e| e.to_string())
}

fn delta_chi_square(p: &Profile) -> (Vec<f64>, Vec<f64>) {
    let min = p.points.iter().map(|q| q.chi_square).fold(f64::INFINITY, f64::min);
    (p.points.iter().map(|q| q.factor).collect(), p.points.iter().map(|q| q.chi_square - min).collect())
}

/// `identifiability.png/svg`: profiles Δχ² of m_f, k, c, n from the exit
/// speed alone (top row) and from the four noisy histories (bottom row).
pub fn identifiability(study: &IdentifiabilityStudy, dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut panels = Vec::new();
    for (source, profiles) in [("exit speed only", &study.exit_speed_profiles), ("histories", &study.history_profiles)] {
        for p in profiles.iter() {
            let (x, y) = delta_chi_square(p);
            let one: Vec<f64> = x.iter().map(|_| 1.0).collect();
            let mut pnl = Panel::new(
                &format!("{}: {}", p.parameter.name(), source),
                &format!("{} / truth", p.parameter.name()),
                "Δχ² (others re-fitted)",
                vec![
                    Series::line("profile", COLORS[1], &x, &y).with_markers(),
                    Series::line("Δχ² = 1", COLORS[2], &x, &one).dashed(),
                ],
            );
            pnl.legend = SeriesLabelPosition::UpperMiddle;
            panels.push(pnl);
        }
    }
    save_grid(
        dir,
        "identifiability",
        "Misfit profiles: exit speed alone (top) vs force, compression and velocity histories (bottom)",
        (2, 4),
        &panels,
    )
    .map_err(|e| e.to_string())
}
