//! Time-history files: `--history FILE` of `kick simulate`, `kick simulate3d`
//! and `kick flight`, one writer for every level ([`HistoryWriter`]).
//!
//! The format is the file's extension: `.csv`, or `.h5`/`.hdf5` (anything
//! else is refused naming `--history`). Rows are streamed as the solver makes
//! them (bounded memory), and the file is written whole or not at all
//! ([`crate::output::Staged`]): a failed solve leaves no file.
//!
//! - CSV: one header line of `name [unit]` per column, comma-separated, then
//!   one line per sample, numbers only (shortest round-trip form, e.g.
//!   `2.2e1`); nothing else (no comments, no prose).
//! - HDF5 (layout `history`):
//!
//! ```text
//! /                 attributes: provenance (tool, tool_version, git_commit, git_dirty),
//!                   layout = "history", level ("1d", "3d", "flight"), solver,
//!                   law (1D and 3D), samples (u64), and the spacing: `interval`
//!                   (s) or `samples_requested`
//! /history/<name>   f64[samples], attribute units: one dataset per column
//! /fixed/<name>     every parameter the run was solved with (defaults filled
//!                   in; vectors as three numbers, switches as 0 or 1), units
//! ```
//!
//! Columns: [`kick_core::HISTORY_COLUMNS`] (1D), [`kick_3d::HISTORY_COLUMNS_3D`]
//! (3D) and [`FLIGHT_HISTORY_COLUMNS`] (flight); vectors as `_x`, `_y`, `_z`.
//! No wall-clock time is written: the same run writes the same bytes.

use crate::h5::{self, Column, H5Error, ResultFile, ResultWriter, CHUNK_ROWS};
use crate::output::{OutputError, Staged};
use crate::provenance::Provenance;
use hdf5::Dataset;
use kick_core::parameters::Value;
use kick_core::Spacing;
use plotters::style::RGBColor;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

/// `--samples`' default: 201 rows (200 intervals over the contact or flight).
pub const DEFAULT_SAMPLES: usize = 201;
/// Most rows a history file takes (10⁷, about 2 GB of 3D CSV).
pub const MAX_FILE_SAMPLES: u64 = 10_000_000;

/// A history to write: where, and on which grid.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryRequest {
    pub path: PathBuf,
    pub spacing: Spacing,
}

impl HistoryRequest {
    /// From the front ends' `--history FILE [--samples N | --interval DT]`
    /// (neither: [`DEFAULT_SAMPLES`]; both: refused).
    pub fn new(path: &Path, samples: Option<usize>, interval: Option<f64>) -> Result<HistoryRequest, String> {
        let spacing = match (samples, interval) {
            (Some(_), Some(_)) => return Err("give --samples or --interval, not both".into()),
            (Some(n), None) => Spacing::Count(n),
            (None, Some(dt)) => Spacing::Interval(dt),
            (None, None) => Spacing::Count(DEFAULT_SAMPLES),
        };
        let spacing = spacing.validate().map_err(|e| format!("{e} (flag --{})", if samples.is_some() { "samples" } else { "interval" }))?;
        if let Spacing::Count(n) = spacing {
            if n as u64 > MAX_FILE_SAMPLES {
                return Err(format!("--samples {n}: at most {MAX_FILE_SAMPLES} rows in a history file"));
            }
        }
        HistoryFormat::of(path)?;
        Ok(HistoryRequest { path: path.to_path_buf(), spacing })
    }
}

/// The file format, from the extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HistoryFormat {
    Csv,
    Hdf5,
}

impl HistoryFormat {
    /// `.csv` → CSV, `.h5`/`.hdf5` → HDF5 (any case); anything else is an error naming `--history`.
    pub fn of(path: &Path) -> Result<HistoryFormat, String> {
        let ext = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("csv") => Ok(HistoryFormat::Csv),
            Some("h5" | "hdf5") => Ok(HistoryFormat::Hdf5),
            _ => Err(format!(
                "--history {}: the format comes from the extension: .csv, .h5 or .hdf5",
                path.display()
            )),
        }
    }
}

/// Names and units of a flight history's columns, in [`flight_values`] order.
pub const FLIGHT_HISTORY_COLUMNS: [(&str, &str); 10] = [
    ("time", "s"),
    ("position_x", "m"),
    ("position_y", "m"),
    ("position_z", "m"),
    ("velocity_x", "m/s"),
    ("velocity_y", "m/s"),
    ("velocity_z", "m/s"),
    ("spin_x", "rad/s"),
    ("spin_y", "rad/s"),
    ("spin_z", "rad/s"),
];

/// A flight sample in [`FLIGHT_HISTORY_COLUMNS`] order.
pub fn flight_values(s: &kick_flight::FlightSample) -> [f64; 10] {
    let mut v = [s.time; 10];
    v[1..4].copy_from_slice(&s.position);
    v[4..7].copy_from_slice(&s.velocity);
    v[7..10].copy_from_slice(&s.spin);
    v
}

/// What the file says about the run besides its rows.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HistoryMeta {
    /// `1d`, `3d` or `flight`.
    pub level: String,
    /// Text attributes (solver, law...).
    pub texts: Vec<(String, String)>,
    /// `/fixed/<name>`: (name, unit, values).
    pub fixed: Vec<(String, String, Vec<f64>)>,
}

impl HistoryMeta {
    /// A fixed parameter from a declared value.
    pub fn push_value(&mut self, name: &str, unit: &str, value: Value) {
        self.fixed.push((name.into(), unit.into(), value.numbers()));
    }
}

enum Sink {
    Csv { staged: Staged, out: BufWriter<File> },
    Hdf5 { writer: ResultWriter, datasets: Vec<Dataset>, buffer: Vec<Vec<f64>> },
}

/// Streams rows of named columns into a CSV or HDF5 file (see the module docs).
pub struct HistoryWriter {
    path: PathBuf,
    sink: Sink,
    width: usize,
    rows: u64,
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> String + '_ {
    move |e| OutputError::Io { path: path.to_path_buf(), message: e.to_string() }.to_string()
}

fn h5(e: H5Error) -> String {
    e.to_string()
}

impl HistoryWriter {
    /// Begin `request.path` (a temporary file until [`Self::finish`]).
    pub fn create(request: &HistoryRequest, columns: &[(&str, &str)], meta: &HistoryMeta) -> Result<HistoryWriter, String> {
        let path = request.path.clone();
        let sink = match HistoryFormat::of(&path)? {
            HistoryFormat::Csv => {
                let staged = Staged::begin(&path).map_err(|e| e.to_string())?;
                let file = File::create(staged.temporary()).map_err(io(&path))?;
                let mut out = BufWriter::new(file);
                let header: Vec<String> = columns.iter().map(|(n, u)| format!("{n} [{u}]")).collect();
                writeln!(out, "{}", header.join(",")).map_err(io(&path))?;
                Sink::Csv { staged, out }
            }
            HistoryFormat::Hdf5 => {
                let provenance = Provenance::now("history", "", "");
                let writer = ResultWriter::create(&path, &provenance, "history").map_err(h5)?;
                let file = writer.file().clone();
                h5::write_str_attr(&file, &path, "level", &meta.level).map_err(h5)?;
                for (name, text) in &meta.texts {
                    h5::write_str_attr(&file, &path, name, text).map_err(h5)?;
                }
                match request.spacing {
                    Spacing::Interval(dt) => h5::write_f64_attr(&file, &path, "interval", dt).map_err(h5)?,
                    Spacing::Count(n) => h5::write_u64_attr(&file, &path, "samples_requested", n as u64).map_err(h5)?,
                }
                for (name, unit, values) in &meta.fixed {
                    writer.column("fixed", &Column::new(name, unit), values).map_err(h5)?;
                }
                let group = h5::new_group(&file, "history").map_err(|e| h5(H5Error::Hdf5 { path: path.clone(), message: e.to_string() }))?;
                let datasets = columns
                    .iter()
                    .map(|(n, u)| h5::extendable::<f64>(&group, n, u, CHUNK_ROWS, &path))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(h5)?;
                Sink::Hdf5 { writer, datasets, buffer: vec![Vec::with_capacity(CHUNK_ROWS); columns.len()] }
            }
        };
        Ok(HistoryWriter { path, sink, width: columns.len(), rows: 0 })
    }

    /// Rows written so far.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// Append one row (one value per column).
    pub fn push(&mut self, values: &[f64]) -> Result<(), String> {
        if values.len() != self.width {
            return Err(format!("{}: a row of {} values for {} columns", self.path.display(), values.len(), self.width));
        }
        if self.rows >= MAX_FILE_SAMPLES {
            return Err(format!(
                "--history {}: more than {MAX_FILE_SAMPLES} rows; give a larger --interval or fewer --samples",
                self.path.display()
            ));
        }
        self.rows += 1;
        match &mut self.sink {
            Sink::Csv { out, .. } => {
                let mut line = String::with_capacity(24 * values.len());
                for (i, v) in values.iter().enumerate() {
                    if i > 0 {
                        line.push(',');
                    }
                    use std::fmt::Write as _;
                    let _ = write!(line, "{v:e}");
                }
                line.push('\n');
                out.write_all(line.as_bytes()).map_err(io(&self.path))
            }
            Sink::Hdf5 { buffer, .. } => {
                for (column, v) in buffer.iter_mut().zip(values) {
                    column.push(*v);
                }
                if buffer[0].len() == CHUNK_ROWS {
                    self.flush()?;
                }
                Ok(())
            }
        }
    }

    fn flush(&mut self) -> Result<(), String> {
        if let Sink::Hdf5 { datasets, buffer, .. } = &mut self.sink {
            for (dataset, column) in datasets.iter().zip(buffer.iter_mut()) {
                let start = dataset.size();
                let end = start + column.len();
                dataset.resize(end).and_then(|()| dataset.write_slice(column.as_slice(), start..end)).map_err(|e| {
                    h5(H5Error::Hdf5 { path: self.path.clone(), message: e.to_string() })
                })?;
                column.clear();
            }
        }
        Ok(())
    }

    /// Write the last rows and give the file its name.
    pub fn finish(mut self) -> Result<PathBuf, String> {
        self.flush()?;
        let path = self.path.clone();
        match self.sink {
            Sink::Csv { staged, out } => {
                out.into_inner().map_err(|e| io(&path)(e.into_error()))?.sync_all().map_err(io(&path))?;
                staged.commit().map_err(|e| e.to_string())
            }
            Sink::Hdf5 { writer, datasets, .. } => {
                h5::write_u64_attr(writer.file(), &path, "samples", self.rows).map_err(h5)?;
                drop(datasets);
                writer.finish().map_err(h5)
            }
        }
    }

    /// A sink for a solver's stream: each row pushed, the first error kept
    /// in `error` (the stream then stops).
    pub fn sink<'a, S>(
        &'a mut self,
        values: impl Fn(&S) -> Vec<f64> + 'a,
        error: &'a mut Option<String>,
    ) -> impl FnMut(&S) -> ControlFlow<()> + 'a {
        move |s| match self.push(&values(s)) {
            Ok(()) => ControlFlow::Continue(()),
            Err(e) => {
                *error = Some(e);
                ControlFlow::Break(())
            }
        }
    }
}

/// Write a history streamed by `solve` (which hands rows to its sink and
/// returns its outcome and the full history's row count): the outcome and
/// the file, or nothing written.
pub fn write<S, O>(
    request: &HistoryRequest,
    columns: &[(&str, &str)],
    meta: &HistoryMeta,
    values: impl Fn(&S) -> Vec<f64>,
    solve: impl FnOnce(&mut dyn FnMut(&S) -> ControlFlow<()>) -> Result<(O, u64), String>,
) -> Result<(O, PathBuf), String> {
    let mut writer = HistoryWriter::create(request, columns, meta)?;
    let mut error = None;
    let (outcome, total) = {
        let mut sink = writer.sink(values, &mut error);
        solve(&mut sink)?
    };
    if let Some(e) = error {
        return Err(e);
    }
    if total != writer.rows() {
        return Err(format!("{}: {} of {total} rows written", request.path.display(), writer.rows()));
    }
    Ok((outcome, writer.finish()?))
}

/// The off-center kick of the force-history figure: 5 cm off centre, μ 0.5
/// (the 3D defaults otherwise), which grips, slips and grips again.
pub const FIGURE_OFFSET: f64 = 0.05;
pub const FIGURE_FRICTION: f64 = 0.5;
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
pub fn reproduce_force_history(out: &Path, figures: &Path) -> Result<(String, String, Vec<PathBuf>), String> {
    let path = out.join("3d_force_history.h5");
    let command = force_history_command(out);
    let mut spec = kick_3d::KickSpec::default();
    spec.kick3d.offset = Some(FIGURE_OFFSET);
    spec.kick3d.friction = Some(FIGURE_FRICTION);
    let request = HistoryRequest { path: path.clone(), spacing: Spacing::Count(FIGURE_SAMPLES) };
    let run = crate::simulate::simulate3d(&spec, "accurate", None, Some(&request), None)?;
    let mut written = run.written.clone();
    written.extend(force_history_figure(&path, figures).map_err(|e| e.to_string())?);
    Ok((command, crate::Printable::text(&run), written))
}

/// Runs of equal `state` as (first time, last time) intervals, their ends
/// halfway between the rows where the state changes.
fn phases(time: &[f64], state: &[f64], code: f64) -> Vec<(f64, f64)> {
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
    let (grip, slip) = (kick_3d::ContactState::Grip.code(), kick_3d::ContactState::Slip.code());
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

    const COLUMNS: [(&str, &str); 3] = [("time", "s"), ("force_x", "N"), ("state", "1")];

    /// Rows that need every digit: (k/7, 1/3 + k, (-1)^k 1e-300 k).
    fn row(k: u64) -> Vec<f64> {
        let k = k as f64;
        vec![k / 7.0, 1.0 / 3.0 + k, if (k as u64).is_multiple_of(2) { 1e-300 * k } else { -1e-300 * k }]
    }

    type Sink<'a> = &'a mut dyn FnMut(&u64) -> ControlFlow<()>;

    fn stream(rows: u64) -> impl FnOnce(Sink) -> Result<(&'static str, u64), String> {
        move |sink| {
            for k in 0..rows {
                if sink(&k).is_break() {
                    break;
                }
            }
            Ok(("done", rows))
        }
    }

    #[test]
    fn formats_come_from_the_extension_only() {
        assert_eq!(HistoryFormat::of(Path::new("a/b.CSV")), Ok(HistoryFormat::Csv));
        assert_eq!(HistoryFormat::of(Path::new("b.h5")), Ok(HistoryFormat::Hdf5));
        assert_eq!(HistoryFormat::of(Path::new("b.hdf5")), Ok(HistoryFormat::Hdf5));
        for bad in ["b.txt", "b", "b.h5.tmp", "csv"] {
            let e = HistoryFormat::of(Path::new(bad)).unwrap_err();
            assert!(e.starts_with(&format!("--history {bad}:")) && e.contains(".csv, .h5 or .hdf5"), "{e}");
        }
        let e = HistoryRequest::new(Path::new("a.csv"), Some(2), Some(1e-3)).unwrap_err();
        assert!(e.contains("--samples or --interval"), "{e}");
        assert_eq!(HistoryRequest::new(Path::new("a.csv"), None, None).unwrap().spacing, Spacing::Count(DEFAULT_SAMPLES));
        let e = HistoryRequest::new(Path::new("a.csv"), Some(MAX_FILE_SAMPLES as usize + 1), None).unwrap_err();
        assert!(e.contains("--samples"), "{e}");
    }

    /// CSV: the header line, then the rows' numbers, every bit kept.
    #[test]
    fn csv_is_a_header_then_numbers_to_the_bit() {
        let dir = scratch("csv");
        let request = HistoryRequest { path: dir.join("h.csv"), spacing: Spacing::Count(5) };
        let (outcome, path) = write(&request, &COLUMNS, &HistoryMeta::default(), |&k| row(k), stream(5)).unwrap();
        assert_eq!(outcome, "done");
        let text = std::fs::read_to_string(path).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("time [s],force_x [N],state [1]"));
        let rows: Vec<Vec<f64>> = lines.map(|l| l.split(',').map(|c| c.parse().unwrap()).collect()).collect();
        assert_eq!(rows, (0..5).map(row).collect::<Vec<_>>());
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1, "only the file: no temporary, no lock");
    }

    /// HDF5: one dataset per column with its units across several chunks,
    /// the fixed parameters, the level and the row count.
    #[test]
    fn hdf5_has_a_dataset_per_column_with_units_and_the_parameters() {
        let dir = scratch("h5");
        let rows = 2 * CHUNK_ROWS as u64 + 17;
        let request = HistoryRequest { path: dir.join("h.h5"), spacing: Spacing::Interval(1e-6) };
        let mut meta = HistoryMeta { level: "3d".into(), texts: vec![("solver".into(), "accurate-3d".into())], fixed: vec![] };
        meta.push_value("offset", "m", Value::Number(0.05));
        meta.push_value("foot_inertia", "kg m^2", Value::Vector([1.0, 2.0, 3.0]));
        meta.push_value("gravity", "", Value::Switch(true));
        let (_, path) = write(&request, &COLUMNS, &meta, |&k| row(k), stream(rows)).unwrap();
        let file = ResultFile::open(&path).unwrap();
        assert_eq!(file.text("", "layout").unwrap(), "history");
        assert_eq!(file.text("", "level").unwrap(), "3d");
        assert_eq!(file.text("", "solver").unwrap(), "accurate-3d");
        for (i, (name, unit)) in COLUMNS.iter().enumerate() {
            let (column, values) = file.column(&format!("history/{name}")).unwrap();
            assert_eq!(column.unit, *unit);
            assert_eq!(values, (0..rows).map(|k| row(k)[i]).collect::<Vec<_>>(), "{name}");
        }
        assert_eq!(file.values("fixed/offset").unwrap(), [0.05]);
        assert_eq!(file.values("fixed/foot_inertia").unwrap(), [1.0, 2.0, 3.0]);
        assert_eq!(file.values("fixed/gravity").unwrap(), [1.0]);
        let h = hdf5::File::open(&path).unwrap();
        assert_eq!(h5::read_u64_attr(&h, "samples"), Some(rows));
        assert_eq!(h5::read_f64_attr(&h, "interval"), Some(1e-6));
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
        let slipping = phases(&time, &state, kick_3d::ContactState::Slip.code());
        let gripping = phases(&time, &state, kick_3d::ContactState::Grip.code());
        assert!(!slipping.is_empty() && !gripping.is_empty());
        let mut spec = kick_3d::KickSpec::default();
        spec.kick3d.offset = Some(FIGURE_OFFSET);
        spec.kick3d.friction = Some(FIGURE_FRICTION);
        let outcome = kick_3d::Accurate3d::default().solve(&spec.build().unwrap()).unwrap();
        let shaded: f64 = slipping.iter().map(|(a, b)| b - a).sum();
        let step = outcome.contact_time / (FIGURE_SAMPLES - 1) as f64;
        // Each end of a slip phase is placed within half a step of the switch.
        assert!((shaded - outcome.slip_time).abs() <= slipping.len() as f64 * step, "{shaded} vs {}", outcome.slip_time);
    }

    /// A solve that fails, or a history that comes short, leaves the old
    /// file as it was and no temporary file.
    #[test]
    fn a_failed_run_writes_nothing() {
        let dir = scratch("fail");
        for name in ["h.csv", "h.h5"] {
            let path = dir.join(name);
            std::fs::write(&path, b"old").unwrap();
            let request = HistoryRequest { path: path.clone(), spacing: Spacing::Count(5) };
            let failing = |sink: &mut dyn FnMut(&u64) -> ControlFlow<()>| -> Result<((), u64), String> {
                let _ = sink(&0);
                Err("no separation".into())
            };
            assert_eq!(write(&request, &COLUMNS, &HistoryMeta::default(), |&k| row(k), failing).unwrap_err(), "no separation");
            let short = |sink: &mut dyn FnMut(&u64) -> ControlFlow<()>| -> Result<((), u64), String> {
                let _ = sink(&0);
                Ok(((), 2))
            };
            let e = write(&request, &COLUMNS, &HistoryMeta::default(), |&k| row(k), short).unwrap_err();
            assert!(e.contains("1 of 2 rows"), "{e}");
            assert_eq!(std::fs::read(&path).unwrap(), b"old");
        }
        let mut names: Vec<String> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        assert_eq!(names, ["h.csv", "h.h5"]);
    }
}
