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
//! Both writers ([`crate::writer`]) go through [`crate::output::Staged`]:
//! one writer per file, a temporary name of this process's own, the final
//! name only when whole.
//!
//! Files are deterministic: no wall-clock time in the provenance, and HDF5's
//! object time stamps (on by default for every group and dataset) are off,
//! so the same run writes the same bytes.

use crate::output::OutputError;
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

pub(crate) fn h5err(path: &Path) -> impl Fn(hdf5::Error) -> H5Error + '_ {
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

pub(crate) fn layout(path: &Path, message: impl Into<String>) -> H5Error {
    H5Error::Layout { path: path.to_path_buf(), message: message.into() }
}

pub(crate) fn varlen(path: &Path, text: &str) -> Result<VarLenUnicode, H5Error> {
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
pub(crate) fn group_at(root: &Group, relative: &str, path: &Path) -> Result<Group, H5Error> {
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
pub(crate) fn extendable_with<T: hdf5::H5Type>(
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
