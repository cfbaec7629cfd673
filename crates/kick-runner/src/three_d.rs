//! `kick run3d FILE.toml... [--out DIR]`: 3D sweeps (kick-3d) into
//! `DIR/3d_NAME.h5` through kick-runner's writer, and their figures into
//! `DIR/figures/` (spin and speed against the swept axis; for the offset
//! sweep also the speed–spin trade-off).

use crate::figures::{save_grid, Panel, Series};
use crate::h5::{law_settings, Column, OutcomeSet, SweepWriter};
use crate::printable::Printable;
use crate::Provenance;
use kick_3d::sweep::{Axis, Experiment3d, SweepPoint, COLUMNS};
use plotters::prelude::RGBColor;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const BLUE: RGBColor = RGBColor(31, 119, 180);
const RED: RGBColor = RGBColor(214, 39, 40);

fn write_h5(path: &Path, file: &Path, text: &str, e: &Experiment3d, points: &[SweepPoint]) -> Result<PathBuf, String> {
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("3d");
    let provenance = Provenance::now(name, &file.display().to_string(), text);
    let law = e.base()?;
    let set = OutcomeSet {
        solver: "accurate-3d".into(),
        settings: law_settings(&law, [("relative_tolerance", 1e-12), ("absolute_tolerance", 1e-15)]),
        columns: COLUMNS.iter().map(|(n, u)| Column::new(n, u)).collect(),
    };
    let mut writer = SweepWriter::create(path, &provenance, &[Column::new(e.axis.name(), e.axis.unit())], &[set], points.len() as u64)
        .map_err(|err| err.to_string())?;
    for p in points {
        writer.push_parameters(&[p.value]).map_err(|err| err.to_string())?;
        writer.push_outcome(0, Ok(&p.columns())).map_err(|err| err.to_string())?;
    }
    writer.finish().map_err(|err| err.to_string())
}

fn figures(dir: &Path, name: &str, e: &Experiment3d, points: &[SweepPoint]) -> Result<Vec<PathBuf>, String> {
    let x: Vec<f64> = points.iter().map(|p| p.value).collect();
    let speed: Vec<f64> = points.iter().map(|p| p.speed).collect();
    let rpm: Vec<f64> = points.iter().map(|p| p.spin_rpm).collect();
    let x_label = format!("{} ({})", e.axis.name().replace('_', " "), e.axis.unit());
    let mut panels = vec![
        Panel::new("ball speed", &x_label, "speed (m/s)", vec![Series::line("accurate-3d", BLUE, &x, &speed).with_markers()]),
        Panel::new("ball spin", &x_label, "spin (rpm)", vec![Series::line("accurate-3d", RED, &x, &rpm).with_markers()]),
    ];
    let mut layout = (1, 2);
    if e.axis == kick_3d::sweep::Axis::Offset {
        panels.push(Panel::new("speed-spin trade-off (offset sweep)", "spin (rpm)", "speed (m/s)", vec![Series::line("accurate-3d", BLUE, &rpm, &speed).with_markers()]));
        layout = (1, 3);
    }
    save_grid(dir, name, &e.description, layout, &panels).map_err(|err| err.to_string())
}

/// One 3D experiment file run: its points, result file and figures.
#[derive(Debug, Clone, Serialize)]
pub struct Run3d {
    pub file: PathBuf,
    pub axis: Axis,
    pub points: Vec<SweepPoint>,
    pub h5: PathBuf,
    pub figures: Vec<PathBuf>,
    pub seconds: f64,
}

/// Every 3D experiment file run, in order.
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct Run3dReport {
    pub runs: Vec<Run3d>,
}

/// Run each 3D experiment file into `out/3d_NAME.h5` and draw its figures
/// into `out/figures/`.
pub fn run3d(files: &[PathBuf], out: &Path) -> Result<Run3dReport, String> {
    let mut runs = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
        let e = Experiment3d::parse(&text).map_err(|err| format!("{}: {err}", file.display()))?;
        let stem = file.file_stem().and_then(|s| s.to_str()).ok_or_else(|| format!("{}: no file name", file.display()))?;
        let name = format!("3d_{stem}");
        let started = std::time::Instant::now();
        let points = e.run().map_err(|err| format!("{}: {err}", file.display()))?;
        std::fs::create_dir_all(out).map_err(|err| format!("{}: {err}", out.display()))?;
        let h5 = write_h5(&out.join(format!("{name}.h5")), file, &text, &e, &points)?;
        let figures = figures(&out.join("figures"), &name, &e, &points)?;
        runs.push(Run3d { file: file.clone(), axis: e.axis, points, h5, figures, seconds: started.elapsed().as_secs_f64() });
    }
    Ok(Run3dReport { runs })
}

impl Printable for Run3dReport {
    fn text(&self) -> String {
        let mut w = String::new();
        for r in &self.runs {
            let _ = writeln!(w, "{}: {} points -> {} and {} figures ({:.2} s)", r.file.display(), r.points.len(), r.h5.display(), r.figures.len(), r.seconds);
            for p in &r.points {
                let _ = writeln!(
                    w,
                    "  {} = {:<8.4} speed {:>8.4} m/s  spin {:>8.2} rpm  launch angle {:>6.2} deg  azimuth {:>7.2} deg  slip {:.3e} s",
                    r.axis.name(), p.value, p.speed, p.spin_rpm, p.launch_angle, p.launch_azimuth, p.slip_time
                );
            }
        }
        w
    }
}
