//! Figures of `kick laws` and `kick fit profile`, drawn with the runner's
//! plotting helpers from the HDF5 files those commands write (never from
//! the data in memory).

use crate::error::PaperError;
use crate::figures::{save_grid, Panel, Series, COLORS};
use crate::identify::files::{read_identifiability, LawsData, SOURCES};
use kick_study::parameters::LawKind;
use plotters::prelude::SeriesLabelPosition;
use std::path::{Path, PathBuf};

/// `laws.png/svg` from `laws.h5`: each Table 2 scenario's force pulse under
/// every law, and the peak forces side by side.
pub fn laws(file: &Path, dir: &Path) -> Result<Vec<PathBuf>, PaperError> {
    let data = LawsData::read(file)?;
    let mut panels = Vec::new();
    for (row, name) in data.names.iter().enumerate() {
        let mut series = Vec::new();
        for (k, law) in LawKind::ALL.into_iter().enumerate() {
            let (t, f) = data.pulse(law, row)?;
            let t: Vec<f64> = t.iter().map(|x| x * 1e3).collect();
            let f: Vec<f64> = f.iter().map(|x| x * 1e-3).collect();
            // The legend goes once, on the peak-force panel, which has room for it.
            let s = Series::line("", COLORS[k % COLORS.len()], &t, &f);
            series.push(if law == LawKind::PowerLaw { s } else { s.dashed() });
        }
        panels.push(Panel::new(name, "time (ms)", "force (kN)", series));
    }
    let x: Vec<f64> = (1..=data.rows()).map(|i| i as f64).collect();
    let mut series = Vec::new();
    for (k, law) in LawKind::ALL.into_iter().enumerate() {
        let y: Vec<f64> = data.column(law, "peak_force")?.iter().map(|f| f * 1e-3).collect();
        let s = Series::line(law.name(), COLORS[k % COLORS.len()], &x, &y).with_markers();
        series.push(if law == LawKind::PowerLaw { s } else { s.dashed() });
    }
    panels.push(Panel::new("Peak force per Table 2 row (1 = baseline … 8)", "Table 2 row", "peak force (kN)", series));
    Ok(save_grid(dir, "laws", "Contact laws on Table 2's scenarios (same restitution target as the paper's law)", (3, 3), &panels)?)
}

/// `identifiability.png/svg` from `identifiability.h5`: profiles Δχ² of
/// m_f, k, c, n from the exit speed alone (top row) and from the four noisy
/// histories (bottom row).
pub fn identifiability(file: &Path, dir: &Path) -> Result<Vec<PathBuf>, PaperError> {
    let data = read_identifiability(file)?;
    let mut panels = Vec::new();
    for (source, profiles) in SOURCES.iter().zip(&data.profiles) {
        let source = source.replace('_', " ");
        let least = kick_store::identify::files::least_chi_square(profiles);
        for p in profiles {
            let y = p.delta_chi_square(least);
            let one: Vec<f64> = p.factor.iter().map(|_| 1.0).collect();
            let mut panel = Panel::new(
                &format!("{}: {source}", p.parameter),
                &format!("{} / truth", p.parameter),
                "Δχ² (others re-fitted)",
                vec![
                    Series::line("profile", COLORS[1], &p.factor, &y).with_markers(),
                    Series::line("Δχ² = 1", COLORS[2], &p.factor, &one).dashed(),
                ],
            );
            panel.legend = SeriesLabelPosition::UpperMiddle;
            panels.push(panel);
        }
    }
    Ok(save_grid(
        dir,
        "identifiability",
        "Misfit profiles: exit speed alone (top) vs force, compression and velocity histories (bottom)",
        (2, 4),
        &panels,
    )?)
}
