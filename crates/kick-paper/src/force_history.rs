//! The force history of one off-center kick (Figure `3d_force_history`):
//! written by kick-store's history writer, then drawn from that file.

use crate::error::PaperError;
use kick_store::h5::H5Error;
use kick_store::ResultFile;
use kick_study::history::ContactState;
use plotters::style::RGBColor;
use std::path::{Path, PathBuf};

/// The off-center kick of the force-history figure (kick-study's).
pub use kick_study::numbers_3d::{HISTORY_FRICTION as FIGURE_FRICTION, HISTORY_OFFSET as FIGURE_OFFSET};
/// Rows of its history: phase boundaries shaded to 1/2000 of the contact.
pub const FIGURE_SAMPLES: usize = 2001;

/// The command that writes [`reproduce_force_history`]'s file alone.
pub fn force_history_command(out: &Path) -> String {
    format!(
        "kick simulate3d --offset {FIGURE_OFFSET} --friction {FIGURE_FRICTION} --history {} --samples {FIGURE_SAMPLES}",
        out.join("3d_force_history.h5").display()
    )
}

/// `kick reproduce`'s step: the force history of one off-center kick written
/// to `out/3d_force_history.h5` by this module's writer, then drawn from that
/// file into `figures/3d_force_history.{png,svg}`. Returns the command that
/// writes the same file alone, the summary and the files.
pub fn reproduce_force_history(out: &Path, figures: &Path) -> Result<(String, String, Vec<PathBuf>), PaperError> {
    let path = out.join(kick_store::force_history::FILE);
    let command = force_history_command(out);
    let run = kick_store::force_history::run(out, FIGURE_SAMPLES)?;
    let mut written = run.written.clone();
    written.extend(force_history_figure(&path, figures)?);
    Ok((command, kick_study::Printable::text(&run), written))
}

/// Runs of equal `state` as (first time, last time) intervals, their ends
/// halfway between the rows where the state changes.
pub(crate) fn phases(time: &[f64], state: &[f64], code: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let mut start = None;
    for i in 0..time.len() {
        let inside = state[i] == code;
        match (inside, start) {
            (true, None) => start = Some(if i == 0 { time[0] } else { 0.5 * (time[i - 1] + time[i]) }),
            (false, Some(a)) => {
                out.push((a, 0.5 * (time[i - 1] + time[i])));
                start = None;
            }
            _ => {}
        }
    }
    if let (Some(a), Some(&b)) = (start, time.last()) {
        out.push((a, b));
    }
    out
}

/// `figures/3d_force_history.{png,svg}` from a 3D history file: |F_n| and
/// |F_t| against time (ms), μ F_n dashed (the Coulomb cap), grip and slip
/// phases shaded.
pub fn force_history_figure(h5: &Path, figures: &Path) -> Result<Vec<PathBuf>, crate::figures::FigureError> {
    use crate::figures::{color, save_grid, Panel, Series};
    let file = ResultFile::open(h5)?;
    let v = |name: &str| file.values(&format!("history/{name}"));
    let size = |name: &str| -> Result<Vec<f64>, H5Error> {
        let (x, y, z) = (v(&format!("{name}_x"))?, v(&format!("{name}_y"))?, v(&format!("{name}_z"))?);
        Ok((0..x.len()).map(|i| (x[i] * x[i] + y[i] * y[i] + z[i] * z[i]).sqrt() * 1e-3).collect())
    };
    let time: Vec<f64> = v("time")?.iter().map(|t| t * 1e3).collect();
    let state = v("contact_state")?;
    let (normal, tangential) = (size("normal_force")?, size("tangential_force")?);
    let mu = file.values("fixed/friction")?.first().copied().unwrap_or(f64::NAN);
    let offset = file.values("fixed/offset")?.first().copied().unwrap_or(f64::NAN);
    let cap: Vec<f64> = normal.iter().map(|f| mu * f).collect();
    let (grip, slip) = (ContactState::Grip.code(), ContactState::Slip.code());
    let panel = Panel::new(
        &format!("Off-center kick: offset {:.0} cm, μ = {mu}", offset * 100.0),
        "time t (ms)",
        "force (kN)",
        vec![
            Series::shade("grip", RGBColor(44, 160, 44), &phases(&time, &state, grip)),
            Series::shade("slip", RGBColor(255, 127, 14), &phases(&time, &state, slip)),
            Series::line("normal |F_n|", color(0), &time, &normal),
            Series::line("tangential |F_t|", color(1), &time, &tangential),
            Series::line("Coulomb cap μ F_n", RGBColor(0, 0, 0), &time, &cap).dashed(),
        ],
    );
    save_grid(figures, "3d_force_history", "Force history of one off-center kick (accurate 3D path)", (1, 1), &[panel])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-history-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Runs of a state between midpoints of the rows where it changes.
    #[test]
    fn phases_end_halfway_between_rows() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let state = [1.0, 1.0, 2.0, 2.0, 1.0, 0.0];
        assert_eq!(phases(&t, &state, 1.0), [(0.0, 1.5), (3.5, 4.5)]);
        assert_eq!(phases(&t, &state, 2.0), [(1.5, 3.5)]);
        assert_eq!(phases(&t, &[2.0; 6], 2.0), [(0.0, 5.0)]);
    }

    /// The figure's kick grips and slips; its history file holds the
    /// kick's own slip time in its slip rows (to the grid's resolution), and
    /// the figure is drawn from that file.
    #[test]
    fn the_force_history_figure_is_drawn_from_its_file() {
        let dir = scratch("figure");
        let (command, summary, written) = reproduce_force_history(&dir, &dir.join("figures")).unwrap();
        assert!(command.contains("--history") && summary.contains("slip_time"), "{command}\n{summary}");
        let names: Vec<String> = written.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["3d_force_history.h5", "3d_force_history.png", "3d_force_history.svg"]);
        let file = ResultFile::open(&written[0]).unwrap();
        let time = file.values("history/time").unwrap();
        let state = file.values("history/contact_state").unwrap();
        assert_eq!(time.len(), FIGURE_SAMPLES);
        let slipping = phases(&time, &state, ContactState::Slip.code());
        let gripping = phases(&time, &state, ContactState::Grip.code());
        assert!(!slipping.is_empty() && !gripping.is_empty());
        let outcome = kick_3d::Accurate3d::default().solve(&kick_study::numbers_3d::history_kick().unwrap()).unwrap();
        let shaded: f64 = slipping.iter().map(|(a, b)| b - a).sum();
        let step = outcome.contact_time / (FIGURE_SAMPLES - 1) as f64;
        // Each end of a slip phase is placed within half a step of the switch.
        assert!((shaded - outcome.slip_time).abs() <= slipping.len() as f64 * step, "{shaded} vs {}", outcome.slip_time);
    }
}
