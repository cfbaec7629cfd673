//! The HDF5 result layout, independent of the model that produced the numbers.
//!
//! A result file holds one sweep: a table of named parameter columns and one
//! or more sets of named outcome columns (one set per solver), every column a
//! 1D dataset with a `units` attribute. Rows are streamed in chunks of
//! [`CHUNK_ROWS`] into extendable, chunked datasets, so a writer's memory does
//! not grow with the number of rows. The layouts are specified once, in
//! [`crate::layouts`] (printed as paper/reference/files.md).
//!
//! ```text
//! /                      attributes: provenance (tool, tool_version, git_commit,
//!                        git_dirty, experiment, experiment_file, experiment_text,
//!                        solver, solver_settings, ...), layout, layout_version, rows
//! /parameters/<name>     f64[rows], attribute units
//! /outcomes/<name>       f64[rows] of the first solver (NaN where the status has no
//!                        outcome: 1, 2, 3)
//! /outcomes/status       u8[rows]: kick_core::Status codes (0 separated, 1 numerical
//!                        failure, 2 trapped, 3 refused, 4 outside validity)
//! /failures/index        u64[f]: rows whose status is not 0
//! /failures/message      string[f]: why (the error, or the validity the row left)
//! /histories/<row>/<name>  time histories of that row (when recorded)
//! /solvers/<solver>/...  outcomes, failures and histories of every further solver
//! /scenario_names        string[rows] (named scenarios only)
//! /paper/<column>        f64[rows], Table 2 as printed, when every row is one of its rows
//! /grid/<axis>           f64[n] the values of each axis of a grid experiment, attribute
//!                        units; /grid/axes string[axes] their names in axis order; root
//!                        attribute grid_shape u64[axes] (grids only, see [`write_grid`])
//! ```
//!
//! Every dataset outside `/grid` (and a 3D file's `/fixed`) has one entry
//! per row; a shard file ([`crate::shard`]) holds the whole experiment's
//! `/grid` and its own rows.
//!
//! Results that are not one table (a fit report, misfit profiles) use
//! [`ResultWriter`] and [`ResultFile`]: the same provenance, temporary name
//! and `units` on every dataset, in a group layout of their own, named by the
//! root attribute `layout`.
//!
//! Both writers go through [`crate::output::Staged`]: one writer per file,
//! a temporary name of this process's own, the final name only when whole.
//!
//! Files are deterministic: no wall-clock time in the provenance, and HDF5's
//! object time stamps (on by default for every group and dataset) are off,
//! so the same run writes the same bytes.

use crate::layouts::Layout;
use crate::output::{OutputError, Staged};
use crate::provenance::Provenance;
use hdf5::types::VarLenUnicode;
use hdf5::{Dataset, File, Group};
use kick_core::Status;
use std::path::{Path, PathBuf};

/// Rows per HDF5 chunk and per flush.
pub const CHUNK_ROWS: usize = 4096;

pub use kick_study::columns::{law_settings, Column, Compression, OutcomeSet, Setting};

#[derive(Debug, thiserror::Error)]
pub enum H5Error {
    #[error("HDF5 file {path}: {message}")]
    Hdf5 { path: PathBuf, message: String },
    #[error("result file {path}: {message}")]
    Layout { path: PathBuf, message: String },
    #[error(transparent)]
    Output(#[from] OutputError),
}

impl H5Error {
    /// An HDF5 error on the file `path`, its message in plain words ([`plain`]).
    pub fn hdf5(path: &Path, error: &hdf5::Error) -> H5Error {
        H5Error::Hdf5 { path: path.to_path_buf(), message: plain(&error.to_string()) }
    }
}

fn h5err(path: &Path) -> impl Fn(hdf5::Error) -> H5Error + '_ {
    move |e| H5Error::hdf5(path, &e)
}

/// HDF5's message in words for the user: a failed system call says what
/// the system said (a full disk as such), never HDF5's internals (the
/// function stack, buffer addresses, "bytes actually written =
/// 18446744073709551615"); anything else loses the `H5X...(): ` prefixes.
pub fn plain(message: &str) -> String {
    let field = |name: &str| {
        let start = message.find(name)? + name.len();
        let rest = &message[start..];
        Some(rest[..rest.find([',', '\n']).unwrap_or(rest.len())].trim().trim_matches('\'').to_string())
    };
    if let Some(errno) = field("errno = ").and_then(|e| e.parse::<i32>().ok()) {
        let said = field("error message = ").unwrap_or_else(|| std::io::Error::from_raw_os_error(errno).to_string());
        return match errno {
            libc::ENOSPC | libc::EDQUOT => {
                format!("the file system is full ({said}); the file was not written (free space or write elsewhere)")
            }
            libc::EFBIG => format!("the file would be larger than allowed ({said}); the file was not written"),
            _ => said,
        };
    }
    // "H5Fopen(): unable to open file: ..." -> "unable to open file: ...".
    let mut text = message.trim();
    while let Some((head, tail)) = text.split_once("(): ") {
        if head.starts_with("H5") && !head.contains(' ') {
            text = tail;
        } else {
            break;
        }
    }
    text.to_string()
}

fn layout(path: &Path, message: impl Into<String>) -> H5Error {
    H5Error::Layout { path: path.to_path_buf(), message: message.into() }
}

fn varlen(path: &Path, text: &str) -> Result<VarLenUnicode, H5Error> {
    // HDF5 strings end at the first NUL.
    text.replace('\0', " ").parse::<VarLenUnicode>().map_err(|e| layout(path, format!("cannot store text: {e}")))
}

/// Write a scalar string attribute.
pub fn write_str_attr(location: &hdf5::Location, path: &Path, name: &str, value: &str) -> Result<(), H5Error> {
    let value = varlen(path, value)?;
    location.new_attr::<VarLenUnicode>().shape(()).create(name).and_then(|a| a.write_scalar(&value)).map_err(h5err(path))
}

/// Write a scalar f64 attribute.
pub fn write_f64_attr(location: &hdf5::Location, path: &Path, name: &str, value: f64) -> Result<(), H5Error> {
    location.new_attr::<f64>().shape(()).create(name).and_then(|a| a.write_scalar(&value)).map_err(h5err(path))
}

/// Write a scalar u64 attribute.
pub fn write_u64_attr(location: &hdf5::Location, path: &Path, name: &str, value: u64) -> Result<(), H5Error> {
    location.new_attr::<u64>().shape(()).create(name).and_then(|a| a.write_scalar(&value)).map_err(h5err(path))
}

/// Read a scalar string attribute.
pub fn read_str_attr(location: &hdf5::Location, name: &str) -> Option<String> {
    let attr = location.attr(name).ok()?;
    // Lossy: a file may hold any bytes, and a `str` must be UTF-8.
    attr.read_scalar::<VarLenUnicode>().ok().map(|s| String::from_utf8_lossy(s.as_bytes()).into_owned())
}

/// Read a scalar u64 attribute.
pub fn read_u64_attr(location: &hdf5::Location, name: &str) -> Option<u64> {
    location.attr(name).ok()?.read_scalar::<u64>().ok()
}

/// Read a scalar f64 attribute.
pub fn read_f64_attr(location: &hdf5::Location, name: &str) -> Option<f64> {
    location.attr(name).ok()?.read_scalar::<f64>().ok()
}

/// An attribute of the file at `path`, of its root (`group` "") or of a
/// group, read on its own: None when the file, the group or the attribute
/// is missing (for readers that hold no HDF5 handle, e.g. kick-paper).
pub fn file_str_attr(path: &Path, group: &str, name: &str) -> Option<String> {
    file_attr(path, group, |at| read_str_attr(at, name))
}

/// [`file_str_attr`] for a scalar f64 attribute.
pub fn file_f64_attr(path: &Path, group: &str, name: &str) -> Option<f64> {
    file_attr(path, group, |at| read_f64_attr(at, name))
}

fn file_attr<T>(path: &Path, group: &str, read: impl Fn(&hdf5::Location) -> Option<T>) -> Option<T> {
    let file = hdf5::File::open(path).ok()?;
    if group.is_empty() {
        read(&file)
    } else {
        let group = file.group(group).ok()?;
        read(&group)
    }
}

/// A new group `name` in `parent`, without HDF5's time stamps.
pub fn new_group(parent: &Group, name: &str) -> hdf5::Result<Group> {
    parent.create_group_builder().obj_track_times(false).create(name)
}

/// Create (or open) the group at a slash-separated path below `root`.
fn group_at(root: &Group, relative: &str, path: &Path) -> Result<Group, H5Error> {
    let mut group = root.clone();
    for part in relative.split('/').filter(|p| !p.is_empty()) {
        group = if group.link_exists(part) { group.group(part) } else { new_group(&group, part) }.map_err(h5err(path))?;
    }
    Ok(group)
}

/// [`Compression`] as HDF5 filters.
pub trait Filters {
    fn filters(self) -> Vec<hdf5::filters::Filter>;
    fn filters_for<T: hdf5::H5Type>(self) -> Vec<hdf5::filters::Filter>;
}

impl Filters for Compression {
    /// The HDF5 filter pipeline: shuffle before deflate (the bytes of a
    /// column's numbers grouped by significance compress better).
    fn filters(self) -> Vec<hdf5::filters::Filter> {
        use hdf5::filters::Filter;
        match self {
            Compression::None => Vec::new(),
            Compression::Deflate(level) => vec![Filter::shuffle(), Filter::deflate(level)],
        }
    }

    /// The filters for a dataset of element type `T`: none for text.
    fn filters_for<T: hdf5::H5Type>(self) -> Vec<hdf5::filters::Filter> {
        if matches!(T::type_descriptor(), hdf5::types::TypeDescriptor::VarLenUnicode) {
            Vec::new()
        } else {
            self.filters()
        }
    }
}

pub(crate) fn extendable<T: hdf5::H5Type>(group: &Group, name: &str, unit: &str, chunk: usize, path: &Path) -> Result<Dataset, H5Error> {
    extendable_with::<T>(group, name, unit, chunk, Compression::None, path)
}

/// [`extendable`] with the filters of `compression`.
fn extendable_with<T: hdf5::H5Type>(
    group: &Group,
    name: &str,
    unit: &str,
    chunk: usize,
    compression: Compression,
    path: &Path,
) -> Result<Dataset, H5Error> {
    // Rows are only appended, so a cache of a few chunks suffices; HDF5's
    // default (1 MiB per dataset) would grow the memory with the row count
    // up to that size per column.
    let dataset = group
        .new_dataset::<T>()
        .obj_track_times(false)
        .chunk(chunk)
        .set_filters(&compression.filters_for::<T>())
        .chunk_cache(11, 2 * chunk * std::mem::size_of::<T>().max(16), 1.0)
        .shape(0..)
        .create(name)
        .map_err(h5err(path))?;
    write_str_attr(&dataset, path, "units", unit)?;
    Ok(dataset)
}

/// Write a complete 1D f64 dataset with its unit.
pub fn write_column(group: &Group, path: &Path, column: &Column, values: &[f64]) -> Result<(), H5Error> {
    let dataset = group.new_dataset_builder().obj_track_times(false).with_data(values).create(column.name.as_str()).map_err(h5err(path))?;
    write_str_attr(&dataset, path, "units", &column.unit)
}

/// Write a complete 1D u64 dataset (row indices) with its unit.
pub fn write_indices(group: &Group, path: &Path, name: &str, unit: &str, values: &[u64]) -> Result<(), H5Error> {
    let dataset = group.new_dataset_builder().obj_track_times(false).with_data(values).create(name).map_err(h5err(path))?;
    write_str_attr(&dataset, path, "units", unit)
}

/// Write the shape of a grid sweep: `/grid/<axis>` coordinate datasets (with
/// units) in axis order, the root attribute `grid_shape` (u64[axes]) and the
/// string dataset `/grid/axes`. Rows are the grid's cells in C order (the last
/// axis varies fastest), so `values.reshape(grid_shape)` restores the grid.
pub fn write_grid(file: &File, path: &Path, axes: &[(Column, &[f64])]) -> Result<(), H5Error> {
    let group = group_at(file, "grid", path)?;
    for (column, values) in axes {
        write_column(&group, path, column, values)?;
    }
    let names: Vec<String> = axes.iter().map(|(c, _)| c.name.clone()).collect();
    write_strings(&group, path, "axes", &names)?;
    let shape: Vec<u64> = axes.iter().map(|(_, v)| v.len() as u64).collect();
    file.new_attr::<u64>().shape(shape.len()).create("grid_shape").and_then(|a| a.write(&shape)).map_err(h5err(path))
}

/// Read the root attribute `grid_shape` (see [`write_grid`]); `None` for a file without one.
pub fn read_grid_shape(file: &File) -> Option<Vec<u64>> {
    file.attr("grid_shape").ok()?.read_raw::<u64>().ok()
}

/// Write a complete 1D string dataset.
pub fn write_strings(group: &Group, path: &Path, name: &str, values: &[String]) -> Result<(), H5Error> {
    let values = values.iter().map(|v| varlen(path, v)).collect::<Result<Vec<_>, _>>()?;
    let dataset = group.new_dataset_builder().obj_track_times(false).with_data(values.as_slice()).create(name).map_err(h5err(path))?;
    write_str_attr(&dataset, path, "units", "")
}

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

/// Turn HDF5's file locking off for this process, before the library reads
/// its settings. Writers hold a lock of their own ([`crate::output`]) and
/// write under a temporary name renamed when complete, so readers never meet
/// a half-written file; and HDF5's lock would otherwise outlive the writer
/// whenever another thread forks a child (e.g. `git` for the provenance)
/// while the file is open, since HDF5's descriptors are inherited.
pub fn disable_file_locking() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| std::env::set_var("HDF5_USE_FILE_LOCKING", "FALSE"));
}

/// Columns of `/paper` (Table 2 as printed): name, unit, value of a row.
type PrintedColumn = (&'static str, &'static str, fn(&kick_core::paper::PrintedRow) -> f64);
const PRINTED_COLUMNS: [PrintedColumn; 5] = [
    ("v_ball_out", "m/s", |r| r.v_ball_out),
    ("speed_ratio", "1", |r| r.speed_ratio),
    ("peak_force", "N", |r| r.peak_force),
    ("contact_time_ms", "ms", |r| r.contact_time_ms),
    ("max_compression_mm", "mm", |r| r.max_compression_mm),
];

/// When every one of `names` is a row of the paper's Table 2, the printed
/// values of those rows beside the computed ones: `/paper/<column>`, one
/// entry per row as the paper prints it (digits and units of Table 2).
/// Other named experiments get nothing.
pub fn write_printed_table2(file: &File, path: &Path, names: &[String]) -> Result<(), H5Error> {
    let rows: Option<Vec<&kick_core::paper::PrintedRow>> =
        names.iter().map(|n| kick_core::paper::TABLE2.iter().find(|r| r.name == n.as_str())).collect();
    let Some(rows) = rows.filter(|r| !r.is_empty()) else {
        return Ok(());
    };
    let group = new_group(file, "paper").map_err(h5err(path))?;
    write_str_attr(&group, path, "source", "Table 2 of the paper, as printed")?;
    for (name, unit, value) in PRINTED_COLUMNS {
        let values: Vec<f64> = rows.iter().map(|r| value(r)).collect();
        write_column(&group, path, &Column::new(name, unit), &values)?;
    }
    Ok(())
}

/// The `meaning` attribute of every status dataset: each [`Status`] code and its name.
pub fn status_meaning() -> String {
    Status::ALL.map(|s| format!("{}: {}", s.code(), s.name())).join("; ")
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

/// A result file opened for reading by dataset path.
pub struct ResultFile {
    path: PathBuf,
    file: File,
}

impl ResultFile {
    pub fn open(path: &Path) -> Result<ResultFile, H5Error> {
        disable_file_locking();
        let file = File::open(path).map_err(h5err(path))?;
        Ok(ResultFile { path: path.to_path_buf(), file })
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The dataset at `path` with its unit; a dataset without one is a layout error.
    pub fn column(&self, path: &str) -> Result<(Column, Vec<f64>), H5Error> {
        let dataset = self.file.dataset(path).map_err(|e| layout(&self.path, format!("{path}: {e}")))?;
        let unit = read_str_attr(&dataset, "units").ok_or_else(|| layout(&self.path, format!("dataset {path} has no units attribute")))?;
        let values = dataset.read_raw::<f64>().map_err(h5err(&self.path))?;
        let name = path.rsplit('/').next().unwrap_or(path).to_string();
        Ok((Column { name, unit }, values))
    }

    /// The values of the dataset at `path`.
    pub fn values(&self, path: &str) -> Result<Vec<f64>, H5Error> {
        Ok(self.column(path)?.1)
    }

    /// The one value of a one-element dataset.
    pub fn scalar(&self, path: &str) -> Result<f64, H5Error> {
        match self.values(path)?.as_slice() {
            [v] => Ok(*v),
            other => Err(layout(&self.path, format!("{path}: {} values, expected one", other.len()))),
        }
    }

    /// Whether a dataset or group exists at `path`.
    pub fn exists(&self, path: &str) -> bool {
        let mut group: Group = (*self.file).clone();
        let parts: Vec<&str> = path.split('/').filter(|p| !p.is_empty()).collect();
        for (i, part) in parts.iter().enumerate() {
            if !group.link_exists(part) {
                return false;
            }
            if i + 1 < parts.len() {
                match group.group(part) {
                    Ok(g) => group = g,
                    Err(_) => return false,
                }
            }
        }
        true
    }

    pub fn strings(&self, path: &str) -> Result<Vec<String>, H5Error> {
        let raw =
            self.file.dataset(path).and_then(|d| d.read_raw::<VarLenUnicode>()).map_err(|e| layout(&self.path, format!("{path}: {e}")))?;
        Ok(raw.iter().map(|s| s.as_str().to_string()).collect())
    }

    /// A string attribute of the group at `group` ("" for the root).
    pub fn text(&self, group: &str, name: &str) -> Result<String, H5Error> {
        let location: Group = if group.is_empty() {
            (*self.file).clone()
        } else {
            self.file.group(group).map_err(|e| layout(&self.path, format!("{group}: {e}")))?
        };
        read_str_attr(&location, name).ok_or_else(|| layout(&self.path, format!("{group}: no attribute `{name}`")))
    }

    /// Names of the members of the group at `group`, in HDF5's (alphabetical) order.
    pub fn members(&self, group: &str) -> Result<Vec<String>, H5Error> {
        let g = self.file.group(group).map_err(|e| layout(&self.path, format!("{group}: {e}")))?;
        g.member_names().map_err(h5err(&self.path))
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

/// A result file read back whole (for figures and reports; sweeps that fit in memory).
#[derive(Debug, Clone, PartialEq)]
pub struct SweepData {
    pub path: PathBuf,
    /// Parameter columns in file order.
    pub parameters: Vec<(Column, Vec<f64>)>,
    /// Row names, when the file has `scenario_names`.
    pub names: Option<Vec<String>>,
    /// Outcome sets: first the root set, then `solvers/*`.
    pub sets: Vec<SetData>,
    /// A grid experiment's axes (`/grid`, in axis order) with their values:
    /// rows are the cells in C order; empty for other files.
    pub grid: Vec<(Column, Vec<f64>)>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct SetData {
    pub solver: String,
    pub group: String,
    pub columns: Vec<(Column, Vec<f64>)>,
    pub status: Vec<u8>,
}

/// Every numeric dataset of `group` but those named in `skip`.
fn read_columns(group: &Group, path: &Path, skip: &[&str]) -> Result<Vec<(Column, Vec<f64>)>, H5Error> {
    let mut out = Vec::new();
    for name in group.member_names().map_err(h5err(path))? {
        if skip.contains(&name.as_str()) {
            continue;
        }
        let dataset = group.dataset(&name).map_err(h5err(path))?;
        let unit = read_str_attr(&dataset, "units").ok_or_else(|| layout(path, format!("dataset {name} has no units attribute")))?;
        let values = dataset.read_raw::<f64>().map_err(h5err(path))?;
        out.push((Column { name, unit }, values));
    }
    Ok(out)
}

impl SweepData {
    pub fn read(path: &Path) -> Result<SweepData, H5Error> {
        disable_file_locking();
        let file = File::open(path).map_err(h5err(path))?;
        let parameters = read_columns(&file.group("parameters").map_err(h5err(path))?, path, &[])?;
        let names = if file.link_exists("scenario_names") {
            let raw = file.dataset("scenario_names").and_then(|d| d.read_raw::<VarLenUnicode>()).map_err(h5err(path))?;
            Some(raw.iter().map(|s| s.as_str().to_string()).collect())
        } else {
            None
        };
        let mut groups = vec![(String::new(), (*file).clone())];
        if file.link_exists("solvers") {
            let solvers = file.group("solvers").map_err(h5err(path))?;
            // Further solvers in alphabetical order; look sets up by solver name.
            for name in solvers.member_names().map_err(h5err(path))? {
                let g = solvers.group(&name).map_err(h5err(path))?;
                groups.push((format!("solvers/{name}"), g));
            }
        }
        let mut sets = Vec::new();
        for (name, group) in groups {
            let outcomes = group.group("outcomes").map_err(h5err(path))?;
            let status = outcomes.dataset("status").and_then(|d| d.read_raw::<u8>()).map_err(h5err(path))?;
            sets.push(SetData {
                solver: read_str_attr(&group, "solver").unwrap_or_default(),
                group: name,
                columns: read_columns(&outcomes, path, &["status"])?,
                status,
            });
        }
        let mut grid = Vec::new();
        if file.link_exists("grid") {
            let group = file.group("grid").map_err(h5err(path))?;
            let axes = group.dataset("axes").and_then(|d| d.read_raw::<VarLenUnicode>()).map_err(h5err(path))?;
            let columns = read_columns(&group, path, &["axes"])?;
            for axis in &axes {
                let found = columns.iter().find(|(c, _)| c.name == axis.as_str());
                grid.push(found.cloned().ok_or_else(|| layout(path, format!("grid axis `{axis}` has no /grid/{axis}")))?);
            }
        }
        Ok(SweepData { path: path.to_path_buf(), parameters, names, sets, grid })
    }

    /// A parameter column by name.
    pub fn parameter(&self, name: &str) -> Result<&[f64], H5Error> {
        self.parameters
            .iter()
            .find(|(c, _)| c.name == name)
            .map(|(_, v)| v.as_slice())
            .ok_or_else(|| layout(&self.path, format!("no parameter `{name}`")))
    }

    /// The outcome set of a solver.
    pub fn set(&self, solver: &str) -> Result<&SetData, H5Error> {
        self.sets.iter().find(|s| s.solver == solver).ok_or_else(|| layout(&self.path, format!("no outcomes of solver `{solver}`")))
    }

    pub fn rows(&self) -> usize {
        self.parameters.first().map_or(0, |(_, v)| v.len())
    }

    /// The grid's shape (one length per axis), for a grid experiment.
    pub fn grid_shape(&self) -> Option<Vec<usize>> {
        (!self.grid.is_empty()).then(|| self.grid.iter().map(|(_, v)| v.len()).collect())
    }
}

impl SetData {
    /// An outcome column by name.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.columns.iter().find(|(c, _)| c.name == name).map(|(_, v)| v.as_slice())
    }
}

/// Read the history of `row` in the outcome group `group` ("" for the root set).
pub fn read_history(path: &Path, group: &str, row: usize) -> Result<Vec<(Column, Vec<f64>)>, H5Error> {
    disable_file_locking();
    let file = File::open(path).map_err(h5err(path))?;
    let name = if group.is_empty() { format!("histories/{row:06}") } else { format!("{group}/histories/{row:06}") };
    let g = file.group(&name).map_err(h5err(path))?;
    read_columns(&g, path, &[])
}

#[cfg(test)]
mod tests {
    use super::plain;

    /// HDF5's own messages of a full disk (captured from `kick sweep` on a
    /// 256 kB tmpfs) and of a missing file, in plain words.
    #[test]
    fn hdf5_messages_are_said_plainly() {
        let full = "H5C_dest(): disable slist on flush dest failure failed: file write failed: time = Fri Nov 27 07:33:49 2026\n, \
                    filename = '/tmp/tiny/s1300.8957-0.tmp.h5', file descriptor = 6, errno = 28, error message = 'No space left \
                    on device', buf = 0x557dcfe12668, total write size = 2160, bytes this sub-write = 2160, bytes actually written = \
                    18446744073709551615, offset = 0";
        assert_eq!(
            plain(full),
            "the file system is full (No space left on device); the file was not written (free space or write elsewhere)"
        );
        let missing = "H5Fopen(): unable to open file: unable to open file: name = 'e.h5', errno = 2, error message = 'No such file \
                       or directory', flags = 0, o_flags = 0";
        assert_eq!(plain(missing), "No such file or directory");
        assert_eq!(plain("H5Fopen(): unable to open file: file signature not found"), "unable to open file: file signature not found");
        assert_eq!(plain("H5Dwrite(): H5D__write(): can't write data"), "can't write data");
    }
}
