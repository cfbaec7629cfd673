//! `kick run3d FILE.toml... [--out DIR]`: 3D sweeps (kick-3d) into
//! `DIR/3d_NAME.h5` through kick-runner's writer, and their figures into
//! `DIR/figures/` (spin and speed against the swept axis; for the offset
//! sweep also the speed–spin trade-off).

use crate::output::CliResult;
use kick_3d::sweep::{Experiment3d, SweepPoint, COLUMNS};
use kick_runner::figures::{save_grid, Panel, Series};
use kick_runner::h5::{Column, OutcomeSet, SweepWriter};
use kick_runner::Provenance;
use plotters::prelude::RGBColor;
use std::path::{Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Experiment files (experiments/3d/*.toml)
    #[arg(required = true)]
    files: Vec<PathBuf>,
    /// Directory for the result files (figures go to DIR/figures)
    #[arg(long, default_value = "results")]
    out: PathBuf,
}

const BLUE: RGBColor = RGBColor(31, 119, 180);
const RED: RGBColor = RGBColor(214, 39, 40);

fn write_h5(path: &Path, file: &Path, text: &str, e: &Experiment3d, points: &[SweepPoint]) -> Result<PathBuf, String> {
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("3d");
    let provenance = Provenance::now(name, &file.display().to_string(), text);
    let law = e.base()?;
    let set = OutcomeSet {
        solver: "accurate-3d".into(),
        settings: format!(
            "Dop853 rtol 1e-12 atol 1e-15, located events; normal law {}{}",
            law.law_kind().name(),
            law.restitution_target().map(|r| format!(" (target restitution {r})")).unwrap_or_default()
        ),
        numeric_settings: vec![("relative_tolerance".into(), 1e-12), ("absolute_tolerance".into(), 1e-15)],
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

pub fn run(args: Args) -> CliResult {
    for file in &args.files {
        let text = std::fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
        let e = Experiment3d::parse(&text).map_err(|err| format!("{}: {err}", file.display()))?;
        let stem = file.file_stem().and_then(|s| s.to_str()).ok_or_else(|| format!("{}: no file name", file.display()))?;
        let name = format!("3d_{stem}");
        let started = std::time::Instant::now();
        let points = e.run().map_err(|err| format!("{}: {err}", file.display()))?;
        std::fs::create_dir_all(&args.out).map_err(|err| format!("{}: {err}", args.out.display()))?;
        let h5 = write_h5(&args.out.join(format!("{name}.h5")), file, &text, &e, &points)?;
        let figs = figures(&args.out.join("figures"), &name, &e, &points)?;
        println!("{}: {} points -> {} and {} figures ({:.2} s)", file.display(), points.len(), h5.display(), figs.len(), started.elapsed().as_secs_f64());
        for p in &points {
            println!("  {} = {:<8.4} speed {:>8.4} m/s  spin {:>8.2} rpm  launch angle {:>6.2} deg  azimuth {:>7.2} deg  slip {:.3e} s", e.axis.name(), p.value, p.speed, p.spin_rpm, p.launch_angle, p.launch_azimuth, p.slip_time);
        }
    }
    Ok(())
}
