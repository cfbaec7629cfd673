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

use crate::error::StoreError;
use crate::h5::{self, Column, H5Error, CHUNK_ROWS};
use crate::output::{OutputError, Staged};
use crate::provenance::Provenance;
use crate::writer::ResultWriter;
use hdf5::Dataset;
use kick_core::Spacing;
pub use kick_study::history::*;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};

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

fn io(path: &Path) -> impl Fn(std::io::Error) -> StoreError + '_ {
    move |e| OutputError::Io { path: path.to_path_buf(), message: e.to_string() }.into()
}

fn h5(e: H5Error) -> StoreError {
    e.into()
}

impl HistoryWriter {
    /// Begin `request.path` (a temporary file until [`Self::finish`]).
    pub fn create(request: &HistoryRequest, columns: &[(&str, &str)], meta: &HistoryMeta) -> Result<HistoryWriter, StoreError> {
        let path = request.path.clone();
        let sink = match HistoryFormat::of(&path)? {
            HistoryFormat::Csv => {
                let staged = Staged::begin(&path)?;
                let file = File::create(staged.temporary()).map_err(io(&path))?;
                let mut out = BufWriter::new(file);
                let header: Vec<String> = columns.iter().map(|(n, u)| format!("{n} [{u}]")).collect();
                writeln!(out, "{}", header.join(",")).map_err(io(&path))?;
                Sink::Csv { staged, out }
            }
            HistoryFormat::Hdf5 => {
                let provenance = Provenance::now("history", "", "");
                let writer = ResultWriter::create(&path, &provenance, &crate::layouts::HISTORY).map_err(h5)?;
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
                let group = h5::new_group(&file, "history").map_err(|e| h5(H5Error::hdf5(&path, &e)))?;
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
    pub fn push(&mut self, values: &[f64]) -> Result<(), StoreError> {
        if values.len() != self.width {
            return Err(StoreError::RowWidth { path: self.path.clone(), values: values.len(), columns: self.width });
        }
        if self.rows >= MAX_FILE_SAMPLES {
            return Err(StoreError::HistoryRows { path: self.path.clone(), max: MAX_FILE_SAMPLES });
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

    fn flush(&mut self) -> Result<(), StoreError> {
        if let Sink::Hdf5 { datasets, buffer, .. } = &mut self.sink {
            for (dataset, column) in datasets.iter().zip(buffer.iter_mut()) {
                let start = dataset.size();
                let end = start + column.len();
                dataset
                    .resize(end)
                    .and_then(|()| dataset.write_slice(column.as_slice(), start..end))
                    .map_err(|e| h5(H5Error::hdf5(&self.path, &e)))?;
                column.clear();
            }
        }
        Ok(())
    }

    /// Write the last rows and give the file its name.
    pub fn finish(mut self) -> Result<PathBuf, StoreError> {
        self.flush()?;
        let path = self.path.clone();
        match self.sink {
            Sink::Csv { staged, out } => {
                out.into_inner().map_err(|e| io(&path)(e.into_error()))?.sync_all().map_err(io(&path))?;
                Ok(staged.commit()?)
            }
            Sink::Hdf5 { writer, datasets, .. } => {
                h5::write_u64_attr(writer.file(), &path, "samples", self.rows).map_err(h5)?;
                drop(datasets);
                Ok(writer.finish()?)
            }
        }
    }

    /// A sink for a solver's stream: each row pushed, the first error kept
    /// in `error` (the stream then stops).
    pub fn sink<'a, S>(
        &'a mut self,
        values: impl Fn(&S) -> Vec<f64> + 'a,
        error: &'a mut Option<StoreError>,
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

/// A [`HistorySink`] whose errors are the [`StoreError`]s, typed inside a [`SinkError`].
impl HistorySink for HistoryWriter {
    fn push(&mut self, values: &[f64]) -> Result<(), SinkError> {
        HistoryWriter::push(self, values).map_err(SinkError::new)
    }

    fn rows(&self) -> u64 {
        HistoryWriter::rows(self)
    }

    fn finish(self: Box<Self>) -> Result<PathBuf, SinkError> {
        HistoryWriter::finish(*self).map_err(SinkError::new)
    }
}

/// The [`OpenSink`] of history files: a [`HistoryWriter`].
pub fn open(request: &HistoryRequest, columns: &[(&str, &str)], meta: &HistoryMeta) -> Result<Box<dyn HistorySink>, SinkError> {
    Ok(Box::new(HistoryWriter::create(request, columns, meta).map_err(SinkError::new)?))
}

/// A request for a history file (`--history FILE [--samples N | --interval DT]`),
/// written by [`HistoryWriter`].
pub fn request(path: &Path, samples: Option<usize>, interval: Option<f64>) -> Result<HistoryRequest, StoreError> {
    // The commands that take `--history` read no file: only the path itself is checked.
    crate::output::check_paths(&[crate::output::Target::File { flag: "--history", path }], &[])?;
    Ok(HistoryRequest::new(path, samples, interval, open)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::h5::ResultFile;
    use kick_core::parameters::Value;
    use kick_core::KickError;
    use kick_study::StudyError;

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

    fn stream(rows: u64) -> impl FnOnce(Sink) -> Result<(&'static str, u64), StudyError> {
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
    fn a_row_of_another_width_is_refused_by_name() {
        let dir = scratch("width");
        let path = dir.join("h.csv");
        let request = HistoryRequest { path: path.clone(), spacing: Spacing::Count(5), open };
        let mut writer = HistoryWriter::create(&request, &COLUMNS, &HistoryMeta::default()).unwrap();
        let e = writer.push(&[1.0, 2.0]).unwrap_err();
        assert!(matches!(&e, StoreError::RowWidth { values: 2, columns: 3, path: p } if *p == path), "{e:?}");
        assert_eq!(e.to_string(), format!("{}: a row of 2 values for 3 columns", path.display()));
        drop(writer);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_sweep_target_names_the_flag_it_refuses() {
        let e = crate::sweep::SweepTarget::check(0, Path::new("a.h5"), None, None).unwrap_err();
        assert!(matches!(e, StoreError::Flag { flag: "samples", .. }), "{e:?}");
        let e = crate::sweep::SweepTarget::check(5, Path::new("a.csv"), None, None).unwrap_err();
        assert!(matches!(e, StoreError::Flag { flag: "out", .. }), "{e:?}");
        assert_eq!(e.to_string(), "--out a.csv must name a file NAME.h5");
        let e = crate::sweep::SweepTarget::check(5, Path::new("a.h5"), Some("3/2"), None).unwrap_err();
        assert!(matches!(e, StoreError::ShardFlag(_)), "{e:?}");
    }

    #[test]
    fn formats_come_from_the_extension_only() {
        assert_eq!(HistoryFormat::of(Path::new("a/b.CSV")), Ok(HistoryFormat::Csv));
        assert_eq!(HistoryFormat::of(Path::new("b.h5")), Ok(HistoryFormat::Hdf5));
        assert_eq!(HistoryFormat::of(Path::new("b.hdf5")), Ok(HistoryFormat::Hdf5));
        for bad in ["b.txt", "b", "b.h5.tmp", "csv"] {
            let e = HistoryFormat::of(Path::new(bad)).unwrap_err();
            assert!(matches!(e, StudyError::Flag { flag: "history", .. }), "{e:?}");
            let e = e.to_string();
            assert!(e.starts_with(&format!("--history {bad}:")) && e.contains(".csv, .h5 or .hdf5"), "{e}");
        }
        let e = request(Path::new("a.csv"), Some(2), Some(1e-3)).unwrap_err();
        assert!(matches!(e, StoreError::Study(StudyError::Flag { flag: "samples", .. })), "{e:?}");
        assert!(e.to_string().contains("--samples or --interval"), "{e}");
        assert_eq!(request(Path::new("a.csv"), None, None).unwrap().spacing, Spacing::Count(DEFAULT_SAMPLES));
        let e = request(Path::new("a.csv"), Some(MAX_FILE_SAMPLES as usize + 1), None).unwrap_err();
        assert!(matches!(e, StoreError::Study(StudyError::HistoryRows { max: MAX_FILE_SAMPLES, .. })), "{e:?}");
        assert_eq!(e.to_string(), format!("--samples {}: at most {MAX_FILE_SAMPLES} rows in a history file", MAX_FILE_SAMPLES + 1));
    }

    /// CSV: the header line, then the rows' numbers, every bit kept.
    #[test]
    fn csv_is_a_header_then_numbers_to_the_bit() {
        let dir = scratch("csv");
        let request = HistoryRequest { path: dir.join("h.csv"), spacing: Spacing::Count(5), open };
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
        let request = HistoryRequest { path: dir.join("h.h5"), spacing: Spacing::Interval(1e-6), open };
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

    /// A sink's failure reaches the study as `StudyError::Sink` holding the
    /// store's own error, matched by its variant, its message the store's;
    /// the old file stays as it was.
    #[test]
    fn a_sink_error_is_the_stores_error_by_variant() {
        let dir = scratch("sink-error");
        for name in ["h.csv", "h.h5"] {
            let path = dir.join(name);
            std::fs::write(&path, b"old").unwrap();
            let request = HistoryRequest { path: path.clone(), spacing: Spacing::Count(5), open };
            // Rows of two values for three columns.
            let e = write(&request, &COLUMNS, &HistoryMeta::default(), |&k: &u64| vec![k as f64; 2], stream(3)).unwrap_err();
            let StudyError::Sink(sink) = &e else { panic!("not a sink error: {e:?}") };
            let store = sink.downcast_ref::<StoreError>().expect("the store's error inside");
            assert!(matches!(store, StoreError::RowWidth { values: 2, columns: 3, path: p } if *p == path), "{store:?}");
            assert_eq!(e.to_string(), format!("{}: a row of 2 values for 3 columns", path.display()));
            assert_eq!(e.status(), kick_core::Status::NumericalFailure);
            assert_eq!(std::fs::read(&path).unwrap(), b"old");
        }
        // A directory where the file goes: the sink cannot open, by variant too.
        let request = HistoryRequest { path: dir.clone(), spacing: Spacing::Count(5), open };
        let e = write(&request, &COLUMNS, &HistoryMeta::default(), |&k| row(k), stream(3)).unwrap_err();
        let StudyError::Sink(sink) = &e else { panic!("not a sink error: {e:?}") };
        assert!(sink.downcast_ref::<StoreError>().is_some(), "{e:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A solve that fails, or a history that comes short, leaves the old
    /// file as it was and no temporary file.
    #[test]
    fn a_failed_run_writes_nothing() {
        let dir = scratch("fail");
        for name in ["h.csv", "h.h5"] {
            let path = dir.join(name);
            std::fs::write(&path, b"old").unwrap();
            let request = HistoryRequest { path: path.clone(), spacing: Spacing::Count(5), open };
            let no_separation = KickError::NoSeparation { time: 1e-3, reason: "horizon".into() };
            let failing = |sink: &mut dyn FnMut(&u64) -> ControlFlow<()>| -> Result<((), u64), KickError> {
                let _ = sink(&0);
                Err(no_separation.clone())
            };
            let e = write(&request, &COLUMNS, &HistoryMeta::default(), |&k| row(k), failing).unwrap_err();
            assert_eq!(e, StudyError::Kick(no_separation.clone()));
            assert_eq!(e.status(), kick_core::Status::NumericalFailure);
            let short = |sink: &mut dyn FnMut(&u64) -> ControlFlow<()>| -> Result<((), u64), StudyError> {
                let _ = sink(&0);
                Ok(((), 2))
            };
            let e = write(&request, &COLUMNS, &HistoryMeta::default(), |&k| row(k), short).unwrap_err();
            assert!(matches!(e, StudyError::ShortHistory { written: 1, total: 2, .. }), "{e:?}");
            assert!(e.to_string().contains("1 of 2 rows"), "{e}");
            assert_eq!(std::fs::read(&path).unwrap(), b"old");
        }
        let mut names: Vec<String> =
            std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        assert_eq!(names, ["h.csv", "h.h5"]);
    }
}
