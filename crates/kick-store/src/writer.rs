//! The writers of result files: [`SweepWriter`] streams a sweep's table
//! (the layout of [`crate::h5`]), [`ResultWriter`] a file of its own group
//! layout ([`crate::layouts`]). Both go through [`crate::output::Staged`]:
//! one writer per file, a temporary name of this process's own, the final
//! name only when whole, and an unchanged file left as it was
//! ([`crate::compare::same_content`]).

use crate::h5::{
    disable_file_locking, extendable, extendable_with, group_at, h5err, layout, new_group, status_meaning, varlen, write_column,
    write_f64_attr, write_str_attr, write_strings, write_u64_attr, Column, Compression, H5Error, OutcomeSet, Setting, CHUNK_ROWS,
};
use crate::layouts::Layout;
use crate::output::Staged;
use crate::provenance::Provenance;
use hdf5::types::VarLenUnicode;
use hdf5::{Dataset, File, Group};
use kick_core::Status;
use std::path::{Path, PathBuf};

struct SetWriter {
    group: Group,
    columns: Vec<Dataset>,
    status: Dataset,
    failure_index: Dataset,
    failure_message: Dataset,
    /// Column-major buffer: `columns.len()` runs of up to CHUNK_ROWS values.
    buffer: Vec<Vec<f64>>,
    status_buffer: Vec<u8>,
    failures: Vec<(u64, VarLenUnicode)>,
    failures_written: usize,
    failure_count: u64,
    /// Rows per status code.
    counts: [u64; Status::ALL.len()],
}

impl kick_study::level::RowSink for SweepWriter {
    type Error = H5Error;
    /// The row's parameters, then each set's values or failure.
    fn push_row(&mut self, row: &kick_study::level::Row) -> Result<(), H5Error> {
        self.push_parameters(&row.parameters)?;
        for (set, values) in row.outcomes.iter().enumerate() {
            match &row.failures[set] {
                None => self.push_outcome(set, Ok(values))?,
                Some(f) if f.status.has_outcome() => self.push_flagged_outcome(set, values, f.status, &f.message)?,
                Some(f) => self.push_outcome(set, Err((f.status, &f.message)))?,
            }
        }
        Ok(())
    }
}

/// Streams a sweep into a new result file.
///
/// Usage: [`SweepWriter::create`], then per row [`SweepWriter::push_parameters`]
/// followed by one [`SweepWriter::push_outcome`] per outcome set, and finally
/// [`SweepWriter::finish`]. The file is written under a temporary name
/// ([`Staged`]) and renamed when finished, so a crashed run never leaves a
/// truncated `NAME.h5`; a second writer of the same file is refused.
pub struct SweepWriter {
    path: PathBuf,
    file: File,
    parameters: Vec<Dataset>,
    parameter_buffer: Vec<Vec<f64>>,
    /// Rows pushed since the last flush (a table may have no parameter
    /// columns: a 3D experiment without `[[sweep]]`).
    pending: usize,
    sets: Vec<SetWriter>,
    rows_written: usize,
    // After `file`: the file is closed before an abandoned temporary is removed.
    staged: Staged,
}

impl SweepWriter {
    /// Create the file with its provenance, a `parameters` group for
    /// `parameters` and one outcome group per entry of `sets` (the first at
    /// the root, the others under `solvers/<solver>`). `expected_rows` sizes
    /// the HDF5 chunks (at most [`CHUNK_ROWS`]), so small sweeps stay small
    /// files; more rows may still be pushed.
    pub fn create(
        path: &Path,
        provenance: &Provenance,
        parameters: &[Column],
        sets: &[OutcomeSet],
        expected_rows: u64,
    ) -> Result<SweepWriter, H5Error> {
        Self::create_with(path, provenance, parameters, sets, expected_rows, Compression::None)
    }

    /// [`Self::create`], the per-row datasets stored as `compression` says.
    pub fn create_with(
        path: &Path,
        provenance: &Provenance,
        parameters: &[Column],
        sets: &[OutcomeSet],
        expected_rows: u64,
        compression: Compression,
    ) -> Result<SweepWriter, H5Error> {
        disable_file_locking();
        let chunk = expected_rows.clamp(1, CHUNK_ROWS as u64) as usize;
        // Failures are usually few.
        let failure_chunk = chunk.min(64);
        let column = |group: &Group, c: &Column| extendable_with::<f64>(group, &c.name, &c.unit, chunk, compression, path);
        if sets.is_empty() {
            return Err(layout(path, "a sweep needs at least one outcome set"));
        }
        for (i, set) in sets.iter().enumerate() {
            if sets[..i].iter().any(|s| s.solver == set.solver) {
                return Err(layout(path, format!("solver `{}` listed twice", set.solver)));
            }
            if set.columns.iter().any(|c| c.name == "status") {
                return Err(layout(path, "`status` is reserved for the status dataset"));
            }
        }
        let (file, staged) = create_file(path, provenance)?;
        crate::layouts::SWEEP.stamp(&file, path)?;
        write_set_attrs(&file, path, &sets[0])?;

        let group = new_group(&file, "parameters").map_err(h5err(path))?;
        let parameter_datasets = parameters.iter().map(|c| column(&group, c)).collect::<Result<Vec<_>, _>>()?;
        let mut set_writers = Vec::new();
        for (i, set) in sets.iter().enumerate() {
            let base = if i == 0 {
                (*file).clone()
            } else {
                let g = group_at(&file, &format!("solvers/{}", set.solver), path)?;
                write_set_attrs(&g, path, set)?;
                g
            };
            let outcomes = new_group(&base, "outcomes").map_err(h5err(path))?;
            let columns = set.columns.iter().map(|c| column(&outcomes, c)).collect::<Result<Vec<_>, _>>()?;
            let status = extendable_with::<u8>(&outcomes, "status", "1", chunk, compression, path)?;
            write_str_attr(&status, path, "meaning", &status_meaning())?;
            let failures = new_group(&base, "failures").map_err(h5err(path))?;
            let failure_index = extendable_with::<u64>(&failures, "index", "1", failure_chunk, compression, path)?;
            let failure_message = extendable_with::<VarLenUnicode>(&failures, "message", "", failure_chunk, compression, path)?;
            set_writers.push(SetWriter {
                group: base,
                buffer: vec![Vec::with_capacity(CHUNK_ROWS); columns.len()],
                columns,
                status,
                failure_index,
                failure_message,
                status_buffer: Vec::with_capacity(CHUNK_ROWS),
                failures: Vec::new(),
                failures_written: 0,
                failure_count: 0,
                counts: [0; Status::ALL.len()],
            });
        }
        Ok(SweepWriter {
            path: path.to_path_buf(),
            staged,
            file,
            parameter_buffer: vec![Vec::with_capacity(CHUNK_ROWS); parameter_datasets.len()],
            pending: 0,
            parameters: parameter_datasets,
            sets: set_writers,
            rows_written: 0,
        })
    }

    /// The open file, e.g. to add datasets of one's own.
    pub fn file(&self) -> &File {
        &self.file
    }

    /// Rows pushed so far.
    pub fn rows(&self) -> usize {
        self.rows_written + self.pending
    }

    /// Start a row with its parameter values (in the order given to `create`).
    pub fn push_parameters(&mut self, values: &[f64]) -> Result<(), H5Error> {
        if values.len() != self.parameters.len() {
            return Err(layout(
                &self.path,
                format!("row has {} parameter values, the file {} columns", values.len(), self.parameters.len()),
            ));
        }
        if self.pending >= CHUNK_ROWS {
            self.flush()?;
        }
        for (buffer, &v) in self.parameter_buffer.iter_mut().zip(values) {
            buffer.push(v);
        }
        self.pending += 1;
        Ok(())
    }

    /// The current row's outcome in set `set`: its values, or the error message
    /// of a failed solve with its status (stored as NaN values, the status
    /// code and the message).
    pub fn push_outcome(&mut self, set: usize, outcome: Result<&[f64], (Status, &str)>) -> Result<(), H5Error> {
        match outcome {
            Ok(values) => self.push(set, Some(values), Status::Separated, None),
            Err((status, message)) => self.push(set, None, status, Some(message)),
        }
    }

    /// The current row's outcome in set `set`, its values kept but flagged
    /// with a status that keeps them (outside the law's validity) and why.
    pub fn push_flagged_outcome(&mut self, set: usize, values: &[f64], status: Status, message: &str) -> Result<(), H5Error> {
        self.push(set, Some(values), status, Some(message))
    }

    /// Values (or NaN), the status, and the message of a row whose status is not 0.
    fn push(&mut self, set: usize, values: Option<&[f64]>, status: Status, message: Option<&str>) -> Result<(), H5Error> {
        let row = self.rows();
        // Split borrows: the path only for messages, no copy per row.
        let (path, sets) = (&self.path, &mut self.sets);
        let writer = sets.get_mut(set).ok_or_else(|| layout(path, format!("no outcome set {set}")))?;
        if writer.status_buffer.len() + self.rows_written + 1 != row {
            return Err(layout(path, format!("outcome set {set} pushed out of step with the parameters at row {row}")));
        }
        match values {
            Some(values) => {
                if values.len() != writer.columns.len() {
                    return Err(layout(
                        path,
                        format!("row has {} outcome values, set {set} has {} columns", values.len(), writer.columns.len()),
                    ));
                }
                for (buffer, &v) in writer.buffer.iter_mut().zip(values) {
                    buffer.push(v);
                }
            }
            None => {
                for buffer in writer.buffer.iter_mut() {
                    buffer.push(f64::NAN);
                }
                writer.failure_count += 1;
            }
        }
        writer.status_buffer.push(status.code());
        writer.counts[usize::from(status.code())] += 1;
        if let Some(message) = message {
            writer.failures.push(((row - 1) as u64, varlen(path, message)?));
        }
        Ok(())
    }

    /// Rows so far of set `set` per status code (`kick_core::Status`).
    pub fn status_counts(&self, set: usize) -> [u64; Status::ALL.len()] {
        self.sets.get(set).map_or([0; Status::ALL.len()], |s| s.counts)
    }

    /// Failed rows so far in each set: rows without values.
    pub fn failure_counts(&self) -> Vec<u64> {
        self.sets.iter().map(|s| s.failure_count).collect()
    }

    /// Rows so far in each set whose values are flagged outside their law's validity.
    pub fn outside_validity_counts(&self) -> Vec<u64> {
        self.sets.iter().map(|s| s.counts[usize::from(Status::OutsideValidity.code())]).collect()
    }

    fn flush(&mut self) -> Result<(), H5Error> {
        let pending = self.pending;
        let path = self.path.clone();
        for (i, set) in self.sets.iter().enumerate() {
            if set.status_buffer.len() != pending {
                return Err(layout(&path, format!("outcome set {i} has {} of {pending} pending rows", set.status_buffer.len())));
            }
        }
        let (start, end) = (self.rows_written, self.rows_written + pending);
        let append = |dataset: &Dataset, values: &[f64]| -> Result<(), H5Error> {
            dataset.resize(end).map_err(h5err(&path))?;
            dataset.write_slice(values, start..end).map_err(h5err(&path))
        };
        for (dataset, buffer) in self.parameters.iter().zip(self.parameter_buffer.iter_mut()) {
            append(dataset, buffer)?;
            buffer.clear();
        }
        for set in &mut self.sets {
            for (dataset, buffer) in set.columns.iter().zip(set.buffer.iter_mut()) {
                append(dataset, buffer)?;
                buffer.clear();
            }
            set.status.resize(end).map_err(h5err(&path))?;
            set.status.write_slice(&set.status_buffer, start..end).map_err(h5err(&path))?;
            set.status_buffer.clear();
            if !set.failures.is_empty() {
                let (s, e) = (set.failures_written, set.failures_written + set.failures.len());
                let index: Vec<u64> = set.failures.iter().map(|f| f.0).collect();
                let message: Vec<VarLenUnicode> = set.failures.drain(..).map(|f| f.1).collect();
                set.failure_index.resize(e).map_err(h5err(&path))?;
                set.failure_index.write_slice(&index, s..e).map_err(h5err(&path))?;
                set.failure_message.resize(e).map_err(h5err(&path))?;
                set.failure_message.write_slice(&message, s..e).map_err(h5err(&path))?;
                set.failures_written = e;
            }
        }
        self.rows_written = end;
        self.pending = 0;
        Ok(())
    }

    /// Write a time history of `row` in outcome set `set` as group
    /// `[solvers/<solver>/]histories/<row>` with one dataset per column.
    pub fn write_history(&mut self, set: usize, row: usize, columns: &[(Column, &[f64])]) -> Result<(), H5Error> {
        let path = self.path.clone();
        let writer = self.sets.get(set).ok_or_else(|| layout(&path, format!("no outcome set {set}")))?;
        let group = group_at(&writer.group, &format!("histories/{row:06}"), &path)?;
        write_u64_attr(&group, &path, "row", row as u64)?;
        for (column, values) in columns {
            write_column(&group, &path, column, values)?;
        }
        Ok(())
    }

    /// Append samples to the history of `row` in set `set`, one slice per
    /// column (equal lengths), creating `[solvers/<solver>/]histories/<row>`
    /// with extendable datasets on the first call: a history of any length
    /// is streamed in blocks. (A history known whole is [`Self::write_history`].)
    pub fn append_history(&mut self, set: usize, row: usize, columns: &[(Column, &[f64])]) -> Result<(), H5Error> {
        let path = self.path.clone();
        let writer = self.sets.get(set).ok_or_else(|| layout(&path, format!("no outcome set {set}")))?;
        let name = format!("histories/{row:06}");
        let new =
            !writer.group.link_exists("histories") || !writer.group.group("histories").is_ok_and(|g| g.link_exists(&format!("{row:06}")));
        let group = group_at(&writer.group, &name, &path)?;
        if new {
            write_u64_attr(&group, &path, "row", row as u64)?;
        }
        for (column, values) in columns {
            let dataset = if new {
                extendable::<f64>(&group, &column.name, &column.unit, CHUNK_ROWS, &path)?
            } else {
                group.dataset(&column.name).map_err(h5err(&path))?
            };
            let start = dataset.size();
            let end = start + values.len();
            dataset.resize(end).map_err(h5err(&path))?;
            dataset.write_slice(values, start..end).map_err(h5err(&path))?;
        }
        Ok(())
    }

    /// Remove the history of `row` in set `set`, if any (a solve that failed
    /// after part of its history was streamed).
    pub fn remove_history(&mut self, set: usize, row: usize) -> Result<(), H5Error> {
        let path = self.path.clone();
        let writer = self.sets.get(set).ok_or_else(|| layout(&path, format!("no outcome set {set}")))?;
        if let Ok(histories) = writer.group.group("histories") {
            let name = format!("{row:06}");
            if histories.link_exists(&name) {
                histories.unlink(&name).map_err(h5err(&path))?;
            }
        }
        Ok(())
    }

    /// Flush the last rows, record the row count, close and rename the file.
    pub fn finish(mut self) -> Result<PathBuf, H5Error> {
        self.flush()?;
        let rows = self.rows_written as u64;
        write_u64_attr(&self.file, &self.path, "rows", rows)?;
        let SweepWriter { path, staged, file, parameters, sets, .. } = self;
        drop(parameters);
        drop(sets);
        close_file(file, staged, &path)
    }
}

/// A new empty HDF5 file for `path`, whole or not at all: open under its
/// [`Staged`] temporary name (one writer per file), HDF5's object time stamps
/// off so the same content is the same bytes. Finish with [`close_file`].
pub fn create_staged(path: &Path) -> Result<(File, Staged), H5Error> {
    disable_file_locking();
    let staged = Staged::begin(path)?;
    let mut builder = File::with_options();
    builder.with_fcpl(|p| p.obj_track_times(false));
    let file = builder.create(staged.temporary()).map_err(h5err(path))?;
    Ok((file, staged))
}

/// The staged file of `path` with the provenance at its root.
fn create_file(path: &Path, provenance: &Provenance) -> Result<(File, Staged), H5Error> {
    let (file, staged) = create_staged(path)?;
    write_provenance(&file, path, provenance)?;
    Ok((file, staged))
}

/// Close the temporary file of [`create_staged`] and give it its final name,
/// unless the file there already holds the same content but for the
/// checkout's provenance ([`crate::compare::same_content`]): that file is
/// left as it was.
pub fn close_file(file: File, staged: Staged, path: &Path) -> Result<PathBuf, H5Error> {
    file.close().map_err(h5err(path))?;
    Ok(staged.commit_unless(crate::compare::same_content)?)
}

/// Writes a result file of one's own group layout: provenance and `layout`
/// at the root, every dataset 1D with a `units` attribute (scalars are
/// one-element datasets), written under a temporary name and renamed on
/// [`ResultWriter::finish`]. Groups are slash-separated paths below the root.
pub struct ResultWriter {
    path: PathBuf,
    file: File,
    staged: Staged,
}

impl ResultWriter {
    /// Create the file of layout `layout` (one of [`crate::layouts::LAYOUTS`]:
    /// its `layout` and `layout_version` attributes).
    pub fn create(path: &Path, provenance: &Provenance, layout: &Layout) -> Result<ResultWriter, H5Error> {
        let (file, staged) = create_file(path, provenance)?;
        layout.stamp(&file, path)?;
        Ok(ResultWriter { path: path.to_path_buf(), file, staged })
    }

    fn group(&self, group: &str) -> Result<Group, H5Error> {
        group_at(&self.file, group, &self.path)
    }

    /// The open file, for datasets the writer has no method for.
    pub fn file(&self) -> &File {
        &self.file
    }

    /// A 1D f64 dataset `group/column.name` with its unit.
    pub fn column(&self, group: &str, column: &Column, values: &[f64]) -> Result<(), H5Error> {
        write_column(&self.group(group)?, &self.path, column, values)
    }

    /// A one-element f64 dataset `group/name` with its unit.
    pub fn scalar(&self, group: &str, name: &str, unit: &str, value: f64) -> Result<(), H5Error> {
        self.column(group, &Column::new(name, unit), &[value])
    }

    /// A 1D string dataset `group/name` (units empty).
    pub fn strings(&self, group: &str, name: &str, values: &[String]) -> Result<(), H5Error> {
        write_strings(&self.group(group)?, &self.path, name, values)
    }

    /// A string attribute of `group` ("" for the root).
    pub fn text(&self, group: &str, name: &str, value: &str) -> Result<(), H5Error> {
        let location = self.group(group)?;
        write_str_attr(&location, &self.path, name, value)
    }

    /// Close and rename the file.
    pub fn finish(self) -> Result<PathBuf, H5Error> {
        close_file(self.file, self.staged, &self.path)
    }
}

fn write_provenance(file: &File, path: &Path, p: &Provenance) -> Result<(), H5Error> {
    write_str_attr(file, path, "tool", &p.tool)?;
    write_str_attr(file, path, "tool_version", &p.tool_version)?;
    if let Some(commit) = &p.git_commit {
        write_str_attr(file, path, "git_commit", commit)?;
    }
    if let Some(dirty) = p.git_dirty {
        // 1: the run used tracked files that differ from git_commit.
        write_u64_attr(file, path, "git_dirty", u64::from(dirty))?;
    }
    write_str_attr(file, path, "experiment", &p.experiment)?;
    write_str_attr(file, path, "experiment_file", &p.experiment_file)?;
    write_str_attr(file, path, "experiment_text", &p.experiment_text)
}

fn write_set_attrs(location: &hdf5::Location, path: &Path, set: &OutcomeSet) -> Result<(), H5Error> {
    write_str_attr(location, path, "solver", &set.solver)?;
    for (name, value) in &set.settings {
        match value {
            Setting::Number(x) => write_f64_attr(location, path, name, *x)?,
            Setting::Text(text) => write_str_attr(location, path, name, text)?,
        }
    }
    Ok(())
}
