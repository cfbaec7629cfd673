//! Sharded runs: `kick run FILE --shard I/N` solves one contiguous slice of an
//! experiment's rows into a file of its own, `kick merge OUT PART...` joins
//! the slices into the file an unsharded run writes.
//!
//! Shards are numbered from 0, as Slurm numbers array tasks
//! (`--array=0-(N-1)`, `--shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT`).
//! Shard I of N holds rows `floor(I*rows/N) .. floor((I+1)*rows/N)`; the
//! slices are disjoint and cover every row, each of size rows/N rounded down
//! or up. Scenario i is a pure function of i, so a shard's rows are the same
//! bits as those rows of an unsharded run.
//!
//! A shard file `OUT/NAME.shard-I-of-N.h5` is an ordinary result file of its
//! rows (failures and histories numbered by its own rows from 0) with the
//! root attributes `shard_index`, `shard_count`, `shard_row_start`,
//! `shard_row_end`, `experiment_rows` and `experiment_fingerprint`
//! ([`fingerprint`] of the experiment text). [`merge`] refuses parts of
//! different experiments, tool versions or commits, of different N, and any
//! set that misses or repeats a row, naming the files; the merged file equals
//! the unsharded run's in every group, dataset and attribute.
//!
//! The same holds for 3D experiments and for the random sweeps (`kick sweep
//! --shard`, `kick sweep3d --shard`: shard I of the samples into
//! `NAME.shard-I-of-N.h5` beside `--out NAME.h5`; sample i is a pure
//! function of the seed and i, whatever the shard). What is per row is
//! joined in row order (datasets below `parameters`, `outcomes` and
//! `failures`, vectors `[rows, 3]` too, failure indices renumbered, and
//! histories); what describes the whole experiment (`/grid`, a 3D file's
//! `/fixed`) must be the same in every part and is copied once.

use crate::experiment::{AnyExperiment, Experiment, Experiment3d};
use crate::h5::{close_file, create_staged, disable_file_locking, new_group, read_str_attr, read_u64_attr, write_str_attr, write_u64_attr, H5Error, CHUNK_ROWS};
use crate::output::OutputError;
use crate::run::{run_part, Part, RunError, RunReport};
use hdf5::types::{FloatSize, IntSize, TypeDescriptor, VarLenUnicode};
use hdf5::{File, Group, Location};
use std::ops::Range;
use std::path::{Path, PathBuf};

/// Root attributes a shard adds; all but these (and `rows`) must agree
/// between the parts of a merge.
pub const SHARD_ATTRIBUTES: [&str; 6] =
    ["shard_index", "shard_count", "shard_row_start", "shard_row_end", "experiment_rows", "experiment_fingerprint"];

#[derive(Debug, thiserror::Error)]
pub enum ShardError {
    #[error("`{flag}` = `{given}`: {message}")]
    Flag { flag: String, given: String, message: String },
    #[error("{}: {message}", path.display())]
    Part { path: PathBuf, message: String },
    #[error("cannot merge: {0}")]
    Merge(String),
    #[error(transparent)]
    Run(#[from] RunError),
    #[error(transparent)]
    H5(#[from] H5Error),
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// Shard `index` of `count`, both from 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u64,
    pub count: u64,
}

impl Shard {
    /// Parse `I/N` (0 <= I < N) given as `flag`.
    pub fn parse(given: &str, flag: &str) -> Result<Shard, ShardError> {
        let error = |message: String| ShardError::Flag { flag: flag.into(), given: given.into(), message };
        let (i, n) = given.split_once('/').ok_or_else(|| error("expected I/N, e.g. 0/4 (shards numbered from 0)".into()))?;
        let number = |s: &str, what: &str| {
            s.trim().parse::<u64>().map_err(|_| error(format!("{what} `{s}` is not a whole number >= 0")))
        };
        let (index, count) = (number(i, "shard index")?, number(n, "shard count")?);
        if count == 0 {
            return Err(error("the shard count must be at least 1".into()));
        }
        if count > crate::experiment::MAX_SCENARIOS {
            return Err(error(format!("more than {} shards", crate::experiment::MAX_SCENARIOS)));
        }
        if index >= count {
            return Err(error(format!("shard index {index} out of 0..{count}: shards are numbered from 0 to {}", count - 1)));
        }
        Ok(Shard { index, count })
    }

    /// Rows `floor(I*rows/N) .. floor((I+1)*rows/N)` of an experiment of `rows` rows.
    pub fn rows(&self, rows: u64) -> Range<u64> {
        let at = |i: u64| (u128::from(i) * u128::from(rows) / u128::from(self.count)) as u64;
        at(self.index)..at(self.index + 1)
    }

    /// `NAME.shard-I-of-N.h5`.
    pub fn file_name(&self, experiment: &str) -> String {
        format!("{experiment}.shard-{}-of-{}.h5", self.index, self.count)
    }
}

/// FNV-1a (64 bit) of the experiment text, as `fnv1a64:` and 16 hex digits:
/// tells parts of different experiment files apart (the text itself is in
/// every part's provenance and compared too).
pub fn fingerprint(text: &str) -> String {
    let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3));
    format!("fnv1a64:{hash:016x}")
}

/// Write the root attributes of shard `shard` of an experiment (or sweep)
/// of `total` rows whose text is `text` to the open shard file `file`.
pub fn write_shard_attributes(file: &hdf5::Location, path: &Path, shard: Shard, total: u64, text: &str) -> Result<(), H5Error> {
    let rows = shard.rows(total);
    write_u64_attr(file, path, "shard_index", shard.index)?;
    write_u64_attr(file, path, "shard_count", shard.count)?;
    write_u64_attr(file, path, "shard_row_start", rows.start)?;
    write_u64_attr(file, path, "shard_row_end", rows.end)?;
    write_u64_attr(file, path, "experiment_rows", total)?;
    write_str_attr(file, path, "experiment_fingerprint", &fingerprint(text))
}

/// Run shard `shard` of `experiment` into `out_dir/NAME.shard-I-of-N.h5`.
pub fn run_shard(experiment: &Experiment, shard: Shard, out_dir: &Path, show_progress: bool) -> Result<crate::RunSummary, ShardError> {
    let total = experiment.scenarios.len();
    let part = Part { rows: shard.rows(total), path: out_dir.join(shard.file_name(&experiment.name)) };
    let attributes = |file: &File| write_shard_attributes(file, &part.path, shard, total, &experiment.text);
    Ok(run_part(experiment, &part, show_progress, &attributes)?)
}

/// [`run_shard`] of a 3D experiment: its cells `shard.rows(cells)`.
pub fn run_shard3d(experiment: &Experiment3d, shard: Shard, out_dir: &Path) -> Result<crate::RunSummary, ShardError> {
    let total = experiment.grid.len();
    let part = Part { rows: shard.rows(total), path: out_dir.join(shard.file_name(&experiment.name)) };
    let attributes = |file: &File| write_shard_attributes(file, &part.path, shard, total, &experiment.text);
    Ok(crate::three_d::run_part(experiment, &part, &attributes)?)
}

/// `kick run FILE [--shard I/N]`: the whole experiment (1D or 3D) into
/// `out/NAME.h5`, or shard I/N (`shard` as given) into `out/NAME.shard-I-of-N.h5`.
pub fn run_file(file: &Path, out: &Path, shard: Option<&str>) -> Result<RunReport, String> {
    let Some(given) = shard else { return crate::run::run_file(file, out) };
    let shard = Shard::parse(given, "--shard").map_err(|e| e.to_string())?;
    let experiment = crate::experiment::load_any(file).map_err(|e| e.to_string())?;
    let started = std::time::Instant::now();
    let summary = match &experiment {
        AnyExperiment::OneD(e) => run_shard(e, shard, out, true),
        AnyExperiment::ThreeD(e) => run_shard3d(e, shard, out),
    }
    .map_err(|e| e.to_string())?;
    Ok(RunReport { file: file.to_path_buf(), summary, seconds: started.elapsed().as_secs_f64() })
}

/// What [`merge`] wrote.
#[derive(Debug, Clone, serde::Serialize)]
pub struct MergeReport {
    pub path: PathBuf,
    pub parts: usize,
    pub rows: u64,
}

impl crate::Printable for MergeReport {
    fn text(&self) -> String {
        format!("{} shards, {} rows -> {}\n", self.parts, self.rows, self.path.display())
    }
}

/// One part of a merge, opened.
struct Piece {
    path: PathBuf,
    file: File,
    shard: Shard,
    rows: Range<u64>,
    total: u64,
    fingerprint: String,
}

fn part_error(path: &Path, message: impl Into<String>) -> ShardError {
    ShardError::Part { path: path.to_path_buf(), message: message.into() }
}

fn h5(path: &Path) -> impl Fn(hdf5::Error) -> ShardError + '_ {
    move |e| part_error(path, e.to_string())
}

impl Piece {
    fn open(path: &Path) -> Result<Piece, ShardError> {
        let file = File::open(path).map_err(h5(path))?;
        let number = |name: &str| {
            read_u64_attr(&file, name).ok_or_else(|| part_error(path, format!("not a shard file (no root attribute `{name}`)")))
        };
        let shard = Shard { index: number("shard_index")?, count: number("shard_count")? };
        let rows = number("shard_row_start")?..number("shard_row_end")?;
        let total = number("experiment_rows")?;
        let fingerprint = read_str_attr(&file, "experiment_fingerprint")
            .ok_or_else(|| part_error(path, "not a shard file (no root attribute `experiment_fingerprint`)"))?;
        if shard.count == 0 || shard.index >= shard.count || shard.rows(total) != rows {
            return Err(part_error(path, format!(
                "shard {}/{} of {total} rows cannot hold rows {}..{}",
                shard.index, shard.count, rows.start, rows.end
            )));
        }
        if read_u64_attr(&file, "rows") != Some(rows.end - rows.start) {
            return Err(part_error(path, "its `rows` attribute disagrees with its row range (an incomplete file?)"));
        }
        Ok(Piece { path: path.to_path_buf(), file, shard, rows, total, fingerprint })
    }
}

fn names(pieces: &[&Piece]) -> String {
    pieces.iter().map(|p| p.path.display().to_string()).collect::<Vec<_>>().join(", ")
}

/// Refuse parts of different experiments, N, tool or commit, and any set
/// that misses or repeats a row; the parts in row order.
fn check(mut pieces: Vec<Piece>) -> Result<Vec<Piece>, ShardError> {
    let first = pieces.first().ok_or_else(|| ShardError::Merge("no shard files given".into()))?;
    let groups = |key: &dyn Fn(&Piece) -> String| {
        let mut seen: Vec<(String, Vec<&Piece>)> = Vec::new();
        for p in &pieces {
            match seen.iter_mut().find(|(k, _)| *k == key(p)) {
                Some((_, list)) => list.push(p),
                None => seen.push((key(p), vec![p])),
            }
        }
        seen
    };
    let by_experiment = groups(&|p| format!("{} ({} rows)", p.fingerprint, p.total));
    if by_experiment.len() > 1 {
        let list: Vec<String> = by_experiment.iter().map(|(k, ps)| format!("experiment {k}: {}", names(ps))).collect();
        return Err(ShardError::Merge(format!("the shards come from different experiments: {}", list.join("; "))));
    }
    let by_count = groups(&|p| p.shard.count.to_string());
    if by_count.len() > 1 {
        let list: Vec<String> = by_count.iter().map(|(k, ps)| format!("N = {k}: {}", names(ps))).collect();
        return Err(ShardError::Merge(format!("the shards split the experiment differently: {}", list.join("; "))));
    }
    // Everything else at the root (experiment text, tool version, commit,
    // solver settings...) must agree too.
    let skip = |name: &str| SHARD_ATTRIBUTES.contains(&name) || name == "rows";
    for name in first.file.attr_names().map_err(h5(&first.path))?.into_iter().filter(|n| !skip(n)) {
        let value = |p: &Piece| read_attr(&p.file, &name).map(|v| format!("{v:?}")).unwrap_or_else(|_| "(absent)".into());
        let by_value = groups(&|p| value(p));
        if by_value.len() > 1 {
            let list: Vec<String> = by_value.iter().map(|(_, ps)| names(ps)).collect();
            return Err(ShardError::Merge(format!("root attribute `{name}` differs between {}", list.join(" and "))));
        }
    }
    pieces.sort_by_key(|p| (p.rows.start, p.rows.end, p.shard.index));
    let (count, total) = (pieces[0].shard.count, pieces[0].total);
    let mut problems = Vec::new();
    for pair in pieces.windows(2) {
        if pair[0].shard.index == pair[1].shard.index {
            problems.push(format!("shard {}/{count} given twice: {}", pair[0].shard.index, names(&[&pair[0], &pair[1]])));
        }
    }
    let present: Vec<u64> = pieces.iter().map(|p| p.shard.index).collect();
    let name = read_str_attr(&pieces[0].file, "experiment").unwrap_or_default();
    let missing: Vec<String> = (0..count)
        .filter(|i| !present.contains(i))
        .map(|index| {
            let shard = Shard { index, count };
            let rows = shard.rows(total);
            format!("{} (rows {}..{})", shard.file_name(&name), rows.start, rows.end)
        })
        .collect();
    if !missing.is_empty() {
        problems.push(format!("missing shard(s) of {count}: {}", missing.join(", ")));
    }
    if !problems.is_empty() {
        return Err(ShardError::Merge(problems.join("; ")));
    }
    Ok(pieces)
}

/// Join shard files `parts` (any order) into `out`, whole or not at all
/// (through [`create_staged`], like every result file): the file an
/// unsharded run of the experiment writes.
pub fn merge(out: &Path, parts: &[PathBuf]) -> Result<MergeReport, ShardError> {
    disable_file_locking();
    let inputs: Vec<&Path> = parts.iter().map(|p| p.as_path()).collect();
    crate::output::check_output(out, "OUT", "h5", &inputs)?;
    let pieces = check(parts.iter().map(|p| Piece::open(p)).collect::<Result<Vec<_>, _>>()?)?;
    let total = pieces[0].total;
    let (file, staged) = create_staged(out)?;
    let writer = Merger { out, pieces: &pieces };
    writer.group(&pieces[0].file, &file, "")?;
    write_u64_attr(&file, out, "rows", total)?;
    drop(pieces);
    let path = close_file(file, staged, out)?;
    Ok(MergeReport { path, parts: parts.len(), rows: total })
}

fn varlen(text: &str) -> hdf5::Result<VarLenUnicode> {
    text.parse::<VarLenUnicode>().map_err(|e| hdf5::Error::from(e.to_string().as_str()))
}

/// An attribute of a type the result layout uses: a scalar, or a list of
/// u64 (`grid_shape`).
#[derive(Debug, Clone, PartialEq)]
enum Value {
    F64(f64),
    U64(u64),
    U64s(Vec<u64>),
    U8(u8),
    Text(String),
}

fn read_attr(location: &Location, name: &str) -> hdf5::Result<Value> {
    let attr = location.attr(name)?;
    let descriptor = attr.dtype()?.to_descriptor()?;
    if !attr.is_scalar() {
        return match descriptor {
            TypeDescriptor::Unsigned(IntSize::U8) => Ok(Value::U64s(attr.read_raw()?)),
            other => Err(format!("attribute `{name}`: a list of {other:?}, not one of the result layout").as_str().into()),
        };
    }
    Ok(match descriptor {
        TypeDescriptor::Float(FloatSize::U8) => Value::F64(attr.read_scalar()?),
        TypeDescriptor::Unsigned(IntSize::U8) => Value::U64(attr.read_scalar()?),
        TypeDescriptor::Unsigned(IntSize::U1) => Value::U8(attr.read_scalar()?),
        TypeDescriptor::VarLenUnicode => Value::Text(attr.read_scalar::<VarLenUnicode>()?.as_str().to_string()),
        other => return Err(format!("attribute `{name}` of type {other:?}, not one of the result layout").as_str().into()),
    })
}

fn write_attr(location: &Location, name: &str, value: &Value) -> hdf5::Result<()> {
    match value {
        Value::F64(v) => location.new_attr::<f64>().shape(()).create(name)?.write_scalar(v),
        Value::U64(v) => location.new_attr::<u64>().shape(()).create(name)?.write_scalar(v),
        Value::U64s(v) => location.new_attr::<u64>().shape(v.len()).create(name)?.write(v),
        Value::U8(v) => location.new_attr::<u8>().shape(()).create(name)?.write_scalar(v),
        Value::Text(v) => location.new_attr::<VarLenUnicode>().shape(()).create(name)?.write_scalar(&varlen(v)?),
    }
}

fn copy_attrs(from: &Location, to: &Location, skip: &dyn Fn(&str) -> bool) -> hdf5::Result<()> {
    for name in from.attr_names()?.into_iter().filter(|n| !skip(n)) {
        write_attr(to, &name, &read_attr(from, &name)?)?;
    }
    Ok(())
}

/// Copies the first part's tree into the merged file, joining what is per row.
struct Merger<'a> {
    out: &'a Path,
    pieces: &'a [Piece],
}

impl Merger<'_> {
    fn err(&self) -> impl Fn(hdf5::Error) -> ShardError + '_ {
        move |e| ShardError::H5(H5Error::Hdf5 { path: self.out.to_path_buf(), message: e.to_string() })
    }

    /// Group `path` ("" the root) of the first part, into `to`.
    fn group(&self, from: &Group, to: &Group, path: &str) -> Result<(), ShardError> {
        let root = path.is_empty();
        // At the root, `rows` is written by `merge`.
        let skip = |n: &str| root && (SHARD_ATTRIBUTES.contains(&n) || n == "rows");
        copy_attrs(from, to, &skip).map_err(self.err())?;
        for name in from.member_names().map_err(self.err())? {
            let member = format!("{path}/{name}");
            if let Ok(group) = from.group(&name) {
                let target = new_group(to, &name).map_err(self.err())?;
                if name == "histories" {
                    self.histories(&member, &target)?;
                } else {
                    self.group(&group, &target, &member)?;
                }
            } else {
                match kind(&member) {
                    Some(Kind::PerRow) => self.join(&member, to, &name, member.ends_with("failures/index"))?,
                    Some(Kind::Whole) => self.same_in_every_part(&member, to, &name)?,
                    None => return Err(part_error(&self.pieces[0].path, format!("{member}: a dataset the result layout does not have"))),
                }
            }
        }
        Ok(())
    }

    /// Dataset `path`, the same in every part (it describes the whole
    /// experiment), copied once.
    fn same_in_every_part(&self, path: &str, to: &Group, name: &str) -> Result<(), ShardError> {
        let first = &self.pieces[0];
        let content = |piece: &Piece| -> Result<(Vec<usize>, Vec<String>), ShardError> {
            let d = piece.file.dataset(path).map_err(|e| part_error(&piece.path, format!("{path}: {e}")))?;
            let values = match d.dtype().and_then(|t| t.to_descriptor()).map_err(h5(&piece.path))? {
                TypeDescriptor::VarLenUnicode => d.read_raw::<VarLenUnicode>().map(|v| v.iter().map(|s| s.to_string()).collect()),
                _ => d.read_raw::<f64>().map(|v| v.iter().map(|x| format!("{:016x}", x.to_bits())).collect()),
            }
            .map_err(h5(&piece.path))?;
            Ok((d.shape(), values))
        };
        let expected = content(first)?;
        for piece in &self.pieces[1..] {
            if content(piece)? != expected {
                return Err(ShardError::Merge(format!("{path} differs between {} and {}", first.path.display(), piece.path.display())));
            }
        }
        self.copy(first, path, to, name, 0)
    }

    /// Every part's histories of `path`, renamed to experiment rows.
    fn histories(&self, path: &str, to: &Group) -> Result<(), ShardError> {
        for piece in self.pieces {
            let Ok(from) = piece.file.group(path) else { continue };
            for name in from.member_names().map_err(h5(&piece.path))? {
                let local: u64 = name.parse().map_err(|_| part_error(&piece.path, format!("{path}/{name}: not a row number")))?;
                let row = piece.rows.start + local;
                let history = from.group(&name).map_err(h5(&piece.path))?;
                let target = new_group(to, &format!("{row:06}")).map_err(self.err())?;
                copy_attrs(&history, &target, &|n| n == "row").map_err(self.err())?;
                write_u64_attr(&target, self.out, "row", row)?;
                for column in history.member_names().map_err(h5(&piece.path))? {
                    self.copy(piece, &format!("{path}/{name}/{column}"), &target, &column, 0)?;
                }
            }
        }
        Ok(())
    }

    /// Dataset `path` of every part, in row order, as `to/name` (`offset`:
    /// add each part's first row, for row indices).
    fn join(&self, path: &str, to: &Group, name: &str, offset: bool) -> Result<(), ShardError> {
        let first = &self.pieces[0];
        let dataset = first.file.dataset(path).map_err(h5(&first.path))?;
        let created = self.create(&dataset, to, name)?;
        for piece in self.pieces {
            let from = piece.file.dataset(path).map_err(|e| part_error(&piece.path, format!("{path}: {e}")))?;
            self.append(piece, &from, &created, if offset { piece.rows.start } else { 0 })?;
        }
        Ok(())
    }

    /// One part's dataset `path` alone (a history column).
    fn copy(&self, piece: &Piece, path: &str, to: &Group, name: &str, offset: u64) -> Result<(), ShardError> {
        let from = piece.file.dataset(path).map_err(h5(&piece.path))?;
        let created = self.create(&from, to, name)?;
        self.append(piece, &from, &created, offset)
    }

    /// An empty dataset of `like`'s type, attributes, filters and trailing
    /// shape (`[rows]` or `[rows, k]`), extendable along the rows.
    fn create(&self, like: &hdf5::Dataset, to: &Group, name: &str) -> Result<hdf5::Dataset, ShardError> {
        let layout_error = |what: String| part_error(&self.pieces[0].path, format!("{name}: {what}, not one of the result layout"));
        let shape = like.shape();
        let (extents, chunk): (hdf5::Extents, Vec<usize>) = match shape.as_slice() {
            [_] => ((0..).into(), vec![CHUNK_ROWS]),
            [_, k] => ((0.., *k).into(), vec![CHUNK_ROWS, (*k).max(1)]),
            other => return Err(layout_error(format!("dataset of shape {other:?}"))),
        };
        // The part's filters (`--compress`): a merge of compressed parts is compressed.
        let filters = like.filters();
        macro_rules! of {
            ($t:ty) => {
                to.new_dataset::<$t>().obj_track_times(false).chunk(chunk.as_slice()).set_filters(&filters).shape(extents).create(name)
            };
        }
        let created = match like.dtype().and_then(|t| t.to_descriptor()).map_err(self.err())? {
            TypeDescriptor::Float(FloatSize::U8) => of!(f64),
            TypeDescriptor::Unsigned(IntSize::U8) => of!(u64),
            TypeDescriptor::Unsigned(IntSize::U1) => of!(u8),
            TypeDescriptor::VarLenUnicode => of!(VarLenUnicode),
            other => return Err(layout_error(format!("dataset of type {other:?}"))),
        }
        .map_err(self.err())?;
        copy_attrs(like, &created, &|_| false).map_err(self.err())?;
        Ok(created)
    }

    /// Append `from` to `to` in blocks of rows.
    fn append(&self, piece: &Piece, from: &hdf5::Dataset, to: &hdf5::Dataset, offset: u64) -> Result<(), ShardError> {
        let shape = from.shape();
        let n = shape.first().copied().unwrap_or(0);
        let block = 16 * CHUNK_ROWS;
        let mut start = 0;
        while start < n {
            let end = (start + block).min(n);
            let at = to.shape().first().copied().unwrap_or(0);
            let rows = at..at + end - start;
            let read = h5(&piece.path);
            if let [_, k] = shape.as_slice() {
                // Vectors: f64 [rows, k].
                to.resize((rows.end, *k)).map_err(self.err())?;
                let values = from.read_slice_2d::<f64, _>((start..end, ..)).map_err(read)?;
                to.write_slice(&values, (rows, ..)).map_err(self.err())?;
                start = end;
                continue;
            }
            to.resize(rows.end).map_err(self.err())?;
            match to.dtype().and_then(|t| t.to_descriptor()).map_err(self.err())? {
                TypeDescriptor::Float(_) => {
                    let values = from.read_slice_1d::<f64, _>(start..end).map_err(read)?;
                    to.write_slice(&values, rows)
                }
                TypeDescriptor::Unsigned(IntSize::U8) => {
                    let values = from.read_slice_1d::<u64, _>(start..end).map_err(read)?.mapv(|v| v + offset);
                    to.write_slice(&values, rows)
                }
                TypeDescriptor::Unsigned(_) => {
                    let values = from.read_slice_1d::<u8, _>(start..end).map_err(read)?;
                    to.write_slice(&values, rows)
                }
                _ => {
                    let values = from.read_slice_1d::<VarLenUnicode, _>(start..end).map_err(read)?;
                    to.write_slice(&values, rows)
                }
            }
            .map_err(self.err())?;
            start = end;
        }
        Ok(())
    }
}

/// How a dataset of a result file is merged.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// One entry per row: joined in row order.
    PerRow,
    /// Describes the whole experiment: the same in every part.
    Whole,
}

/// The kind of the dataset at `path` ("/a/b/name"), or None for one the
/// result layouts do not have.
fn kind(path: &str) -> Option<Kind> {
    let groups: Vec<&str> = path.split('/').filter(|p| !p.is_empty()).collect();
    let groups = &groups[..groups.len().saturating_sub(1)];
    match groups.first() {
        Some(&"grid") | Some(&"fixed") => Some(Kind::Whole),
        Some(&"paper") => Some(Kind::PerRow),
        _ if path == "/scenario_names" => Some(Kind::PerRow),
        _ if groups.iter().any(|g| matches!(*g, "parameters" | "outcomes" | "failures")) => Some(Kind::PerRow),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_every_row_once_in_near_equal_slices() {
        for rows in [0u64, 1, 2, 7, 10, 4096, 100_003] {
            for count in [1u64, 2, 3, 7, 16] {
                let mut next = 0;
                for index in 0..count {
                    let r = Shard { index, count }.rows(rows);
                    assert_eq!(r.start, next, "{rows} rows, {index}/{count}");
                    let len = r.end - r.start;
                    assert!(len == rows / count || len == rows / count + 1, "{rows} rows, {index}/{count}: {len}");
                    next = r.end;
                }
                assert_eq!(next, rows);
            }
        }
        // floor(I*rows/N): 10 rows in 3 shards are 0..3, 3..6, 6..10.
        let slices: Vec<_> = (0..3).map(|index| Shard { index, count: 3 }.rows(10)).collect();
        assert_eq!(slices, [0..3, 3..6, 6..10]);
        // No overflow at the largest experiment.
        let big = crate::experiment::MAX_SCENARIOS;
        assert_eq!(Shard { index: big - 1, count: big }.rows(big), big - 1..big);
    }

    #[test]
    fn bad_shard_flags_are_refused_by_name() {
        assert_eq!(Shard::parse("2/5", "--shard").unwrap(), Shard { index: 2, count: 5 });
        for (given, says) in [
            ("3", "expected I/N"),
            ("5/5", "out of 0..5"),
            ("1/0", "at least 1"),
            ("-1/4", "not a whole number"),
            ("a/4", "not a whole number"),
            ("1/4.5", "not a whole number"),
        ] {
            let message = Shard::parse(given, "--shard").unwrap_err().to_string();
            assert!(message.starts_with(&format!("`--shard` = `{given}`")) && message.contains(says), "{given}: {message}");
        }
    }

    #[test]
    fn fingerprint_is_fnv1a_64() {
        // Published FNV-1a 64 test vectors.
        assert_eq!(fingerprint(""), "fnv1a64:cbf29ce484222325");
        assert_eq!(fingerprint("a"), "fnv1a64:af63dc4c8601ec8c");
        assert_eq!(fingerprint("foobar"), "fnv1a64:85944171f73967e8");
    }
}
