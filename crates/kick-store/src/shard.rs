//! Sharded runs: `kick run FILE --shard I/N` solves one contiguous slice of an
//! experiment's rows into a file of its own, `kick merge OUT PART...` joins
//! the slices into the file an unsharded run writes.
//!
//! A part's parameter columns are checked row by row against the level it
//! was cut from, rebuilt where the merge runs (`Level::parameters_into`):
//! an experiment file's rows (1D scenarios, a 3D grid's coordinates) or a
//! `kick sweep3d`'s kicks (its seed and the held spec of its provenance text).
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
//! different experiments, tool versions or commits, of different N or
//! different `--compress` filters, and any set that misses or repeats a row,
//! naming the files; the merged file equals
//! the unsharded run's in every group, dataset and attribute.
//!
//! The same holds for 3D experiments and for the random sweeps (`kick sweep
//! --shard`, `kick sweep3d --shard`: shard I of the samples into
//! `NAME.shard-I-of-N.h5` beside `--out NAME.h5`; sample i is a pure
//! function of the seed and i, whatever the shard). What is per row is
//! joined in row order (datasets below `parameters`, `outcomes` and
//! `failures`, failure indices renumbered, and
//! histories); what describes the whole experiment (`/grid`, a 3D file's
//! `/fixed`) must be the same in every part and is copied once.

use crate::error::StoreError;
use crate::experiment::Experiment;
use crate::h5::{disable_file_locking, new_group, read_str_attr, read_u64_attr, write_str_attr, write_u64_attr, H5Error, CHUNK_ROWS};
use crate::run::{run_part, Part, RunReport};
use crate::writer::{close_file, create_staged};
use hdf5::types::{FloatSize, IntSize, TypeDescriptor, VarLenUnicode};
use hdf5::{File, Group, Location};
use kick_study::level::Level;
pub use kick_study::shard::{fingerprint, Shard};
use std::ops::Range;
use std::path::{Path, PathBuf};

/// Root attributes a shard adds; all but these (and `rows`) must agree
/// between the parts of a merge.
pub const SHARD_ATTRIBUTES: [&str; 6] =
    ["shard_index", "shard_count", "shard_row_start", "shard_row_end", "experiment_rows", "experiment_fingerprint"];

pub use crate::error::ShardError;

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

/// Run shard `shard` of `experiment` (1D or 3D: its rows `shard.rows(rows)`)
/// into `out_dir/NAME.shard-I-of-N.h5`.
pub fn run_shard(experiment: &Experiment, shard: Shard, out_dir: &Path, show_progress: bool) -> Result<crate::RunSummary, ShardError> {
    let total = experiment.rows();
    let part = Part { rows: shard.rows(total), path: out_dir.join(shard.file_name(&experiment.name)) };
    let attributes = |file: &File| write_shard_attributes(file, &part.path, shard, total, &experiment.text);
    Ok(run_part(experiment, &part, show_progress, &attributes)?)
}

/// `kick run FILE [--shard I/N]`: the whole experiment (1D or 3D) into
/// `out/NAME.h5`, or shard I/N (`shard` as given) into `out/NAME.shard-I-of-N.h5`.
pub fn run_file(file: &Path, out: &Path, shard: Option<&str>) -> Result<RunReport, StoreError> {
    let shard = shard.map(|given| Shard::parse(given, "--shard")).transpose()?;
    let experiment = crate::experiment::load(file)?;
    let target = out.join(shard.map_or_else(|| format!("{}.h5", experiment.name), |s| s.file_name(&experiment.name)));
    let read: Vec<&Path> = experiment.read.iter().map(PathBuf::as_path).collect();
    // `--out` is a folder: said of the folder given (a file there was
    // quoted as `--out` = `file.toml/NAME.h5`), then the file in it.
    crate::output::check_paths(&[crate::output::Target::Folder { flag: "--out", path: out }], &[])?;
    crate::output::check_output(&target, "--out", "h5", &read)?;
    let started = std::time::Instant::now();
    let summary = match shard {
        None => crate::run::run(&experiment, out, true)?,
        Some(shard) => run_shard(&experiment, shard, out, true)?,
    };
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

/// One part of a merge: its root attributes and the shape, type and units of
/// every dataset, read and checked with the file open, then closed (a merge
/// of thousands of parts holds one part open at a time).
struct Piece {
    path: PathBuf,
    shard: Shard,
    rows: Range<u64>,
    total: u64,
    fingerprint: String,
    experiment: String,
    /// Root attributes but the shard's own and `rows`, printed to compare.
    attributes: Vec<(String, String)>,
    /// Every dataset outside `histories`.
    datasets: Vec<Meta>,
    /// The paths of its `histories` groups.
    histories: Vec<String>,
}

/// A dataset of a part as its header describes it (nothing read yet).
#[derive(Debug, Clone, PartialEq)]
struct Meta {
    path: String,
    descriptor: TypeDescriptor,
    units: String,
    /// Its filters as `--compress` sets them ("none", "shuffle + deflate 4").
    filters: String,
    len: usize,
}

/// A dataset's filters in `--compress`'s words.
fn filter_names(d: &hdf5::Dataset) -> String {
    let names: Vec<String> = d
        .filters()
        .iter()
        .map(|f| match f {
            hdf5::filters::Filter::Deflate(level) => format!("deflate {level}"),
            hdf5::filters::Filter::Shuffle => "shuffle".to_string(),
            other => format!("{other:?}"),
        })
        .collect();
    if names.is_empty() {
        "none".into()
    } else {
        names.join(" + ")
    }
}

fn part_error(path: &Path, message: impl Into<String>) -> ShardError {
    ShardError::Part { path: path.to_path_buf(), message: message.into() }
}

fn h5(path: &Path) -> impl Fn(hdf5::Error) -> ShardError + '_ {
    move |e| part_error(path, crate::h5::plain(&e.to_string()))
}

/// A type of the result layout, by name (so a float32 column says so).
fn type_name(descriptor: &TypeDescriptor) -> String {
    match descriptor {
        TypeDescriptor::Float(FloatSize::U8) => "f64".into(),
        TypeDescriptor::Float(FloatSize::U4) => "f32".into(),
        TypeDescriptor::Unsigned(IntSize::U8) => "u64".into(),
        TypeDescriptor::Unsigned(IntSize::U1) => "u8".into(),
        TypeDescriptor::VarLenUnicode => "text".into(),
        other => format!("{other:?}"),
    }
}

fn is_failure(path: &str) -> bool {
    path.contains("/failures/")
}

/// The status dataset that says which rows of outcome `path` are solved.
fn status_of(path: &str) -> Option<String> {
    let at = path.find("/outcomes/")?;
    Some(format!("{}/outcomes/status", &path[..at]))
}

/// The `crossed` column that says which rows of the flight's crossing
/// column `path` hold numbers (the ball lands before the plane: NaN with
/// status 0): `crossed`, or `crossed_k` for plane k of several.
fn crossed_of(path: &str) -> Option<String> {
    let (group, name) = path.rsplit_once('/')?;
    let crossing = &kick_flight::OUTCOME_COLUMNS[kick_flight::LANDING_COLUMNS + 1..];
    crossing.iter().find_map(|(base, _)| {
        if name == *base {
            return Some(format!("{group}/crossed"));
        }
        let plane = name.strip_prefix(base)?.strip_prefix('_')?;
        plane.chars().all(|c| c.is_ascii_digit()).then(|| format!("{group}/crossed_{plane}"))
    })
}

/// Every dataset below `group` (at `prefix`), histories aside.
fn collect(group: &Group, prefix: &str, path: &Path, out: &mut Vec<Meta>, histories: &mut Vec<String>) -> Result<(), ShardError> {
    for name in group.member_names().map_err(h5(path))? {
        let member = format!("{prefix}/{name}");
        if let Ok(inner) = group.group(&name) {
            if name == "histories" {
                histories.push(member);
            } else {
                collect(&inner, &member, path, out, histories)?;
            }
            continue;
        }
        let d = group.dataset(&name).map_err(|e| part_error(path, format!("{member}: {e}")))?;
        let descriptor = d.dtype().and_then(|t| t.to_descriptor()).map_err(|e| part_error(path, format!("{member}: {e}")))?;
        let shape = d.shape();
        // One value per row (vectors are `_x/_y/_z` columns): 1-D only.
        let [len] = shape.as_slice() else {
            return Err(part_error(path, format!("{member}: a dataset of shape {shape:?}, not one of the result layout (1-D)")));
        };
        let units = crate::h5::read_str_attr(&d, "units").unwrap_or_default();
        out.push(Meta { path: member, descriptor, units, filters: filter_names(&d), len: *len });
    }
    Ok(())
}

/// Why a part's dataset is refused before anything is read (the part's
/// error names the file and the dataset).
#[derive(Debug, thiserror::Error)]
enum Refusal {
    #[error("a dataset the result layout does not have")]
    NotInLayout,
    #[error("a column of type {name}, not one of the result layout (f64, u64, u8, text)")]
    Type { name: String },
    #[error("{len} failures in a part of {rows} rows (a corrupt file)")]
    Failures { len: usize, rows: usize },
    #[error("{len} entries in a part of {rows} rows (a truncated or corrupt file)")]
    Entries { len: usize, rows: usize },
    #[error("{len} entries for an experiment of {total} rows (a corrupt file)")]
    Axis { len: usize, total: u64 },
}

impl Meta {
    /// Refuse what no writer of the layout makes, before anything is read:
    /// lengths other than the part's rows, types other than the layout's.
    fn check(&self, rows: usize, total: u64) -> Result<(), Refusal> {
        let kind = kind(&self.path).ok_or(Refusal::NotInLayout)?;
        let allowed = matches!(
            self.descriptor,
            TypeDescriptor::Float(FloatSize::U8) | TypeDescriptor::Unsigned(IntSize::U8 | IntSize::U1) | TypeDescriptor::VarLenUnicode
        );
        if !allowed {
            return Err(Refusal::Type { name: type_name(&self.descriptor) });
        }
        let len = self.len;
        match kind {
            Kind::PerRow if is_failure(&self.path) && len > rows => Err(Refusal::Failures { len, rows }),
            Kind::PerRow if !is_failure(&self.path) && len != rows => Err(Refusal::Entries { len, rows }),
            // The grid's axes: no longer than the experiment.
            Kind::Whole if len as u64 > total.max(1024) => Err(Refusal::Axis { len, total }),
            _ => Ok(()),
        }
    }
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
        if total > crate::experiment::MAX_SCENARIOS || shard.count == 0 || shard.index >= shard.count || shard.rows(total) != rows {
            return Err(part_error(
                path,
                format!("shard {}/{} of {total} rows cannot hold rows {}..{}", shard.index, shard.count, rows.start, rows.end),
            ));
        }
        // Only the table layout this merge knows, at its version.
        let table = &crate::layouts::SWEEP;
        let (layout, version) = (read_str_attr(&file, "layout"), read_u64_attr(&file, "layout_version"));
        if layout.as_deref() != Some(table.name) || version != Some(table.version) {
            return Err(part_error(
                path,
                format!(
                    "layout {} version {}, not `{}` version {} (written by another version of kick: rerun the shard)",
                    layout.as_deref().unwrap_or("(none)"),
                    version.map_or("(none)".into(), |v| v.to_string()),
                    table.name,
                    table.version
                ),
            ));
        }
        if read_u64_attr(&file, "rows") != Some(rows.end - rows.start) {
            return Err(part_error(path, "its `rows` attribute disagrees with its row range (an incomplete file?)"));
        }
        let experiment = read_str_attr(&file, "experiment").unwrap_or_default();
        let skip = |name: &str| SHARD_ATTRIBUTES.contains(&name) || name == "rows";
        let mut attributes = Vec::new();
        for name in file.attr_names().map_err(h5(path))?.into_iter().filter(|n| !skip(n)) {
            let value = read_attr(&file, &name).map(|v| format!("{v:?}")).unwrap_or_else(|_| "(unreadable)".into());
            attributes.push((name, value));
        }
        let (mut datasets, mut histories) = (Vec::new(), Vec::new());
        collect(&file, "", path, &mut datasets, &mut histories)?;
        let n = (rows.end - rows.start) as usize;
        for d in &datasets {
            d.check(n, total).map_err(|m| part_error(path, format!("{}: {m}", d.path)))?;
        }
        Ok(Piece { path: path.to_path_buf(), shard, rows, total, fingerprint, experiment, attributes, datasets, histories })
    }
}

fn names(pieces: &[&Piece]) -> String {
    pieces.iter().map(|p| p.path.display().to_string()).collect::<Vec<_>>().join(", ")
}

/// Refuse parts of different experiments, N, tool or commit, layouts or
/// filters, and any set that misses or repeats a row; the parts in row order.
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
    for (name, _) in &first.attributes {
        let value = |p: &Piece| p.attributes.iter().find(|(n, _)| n == name).map_or_else(|| "(absent)".into(), |(_, v)| v.clone());
        let by_value = groups(&|p| value(p));
        if by_value.len() > 1 {
            let list: Vec<String> = by_value.iter().map(|(_, ps)| names(ps)).collect();
            return Err(ShardError::Merge(format!("root attribute `{name}` differs between {}", list.join(" and "))));
        }
    }
    // The same datasets, types, units and filters in every part (a merge
    // stores every column as its first part does, so parts written with
    // different `--compress` come from different commands).
    let layout = |p: &Piece| {
        p.datasets.iter().map(|d| (d.path.clone(), d.descriptor.clone(), d.units.clone(), d.filters.clone())).collect::<Vec<_>>()
    };
    let expected = layout(first);
    for piece in &pieces[1..] {
        let got = layout(piece);
        if got != expected {
            let differs = expected.iter().zip(&got).find(|(a, b)| a != b).map(|(a, b)| (a.clone(), b.clone()));
            let message = match differs {
                Some((a, b)) if a.0 == b.0 && a.1 == b.1 && a.2 == b.2 => format!(
                    "{}: stored with filters {} here, {} in {} (write every shard with the same --compress)",
                    a.0,
                    b.3,
                    a.3,
                    first.path.display()
                ),
                Some((a, b)) if a.0 == b.0 => {
                    format!("{}: {} [{}] here, {} [{}] in {}", a.0, type_name(&b.1), b.2, type_name(&a.1), a.2, first.path.display())
                }
                _ => format!("its datasets are not those of {}", first.path.display()),
            };
            return Err(part_error(&piece.path, message));
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
    let name = pieces[0].experiment.clone();
    let missing: Vec<String> = (0..count)
        .filter(|i| present.binary_search(i).is_err())
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
/// unsharded run of the experiment writes, stored as it stores it. Every
/// part is checked against its rows and the layout, one open at a time.
pub fn merge(out: &Path, parts: &[PathBuf]) -> Result<MergeReport, ShardError> {
    disable_file_locking();
    let inputs: Vec<&Path> = parts.iter().map(|p| p.as_path()).collect();
    crate::output::check_output(out, "OUT", "h5", &inputs)?;
    let pieces = check(parts.iter().map(|p| Piece::open(p)).collect::<Result<Vec<_>, _>>()?)?;
    let total = pieces[0].total;
    let experiment = experiment_of(&pieces[0]);
    let (file, staged) = create_staged(out)?;
    let merger = Merger { out, pieces: &pieces, total, experiment: experiment.as_deref() };
    let first = File::open(&pieces[0].path).map_err(h5(&pieces[0].path))?;
    merger.group(&first, &file, "")?;
    drop(first);
    let mut cursor = std::collections::HashMap::new();
    for piece in &pieces {
        merger.part(piece, &file, &mut cursor)?;
    }
    write_u64_attr(&file, out, "rows", total)?;
    drop(pieces);
    let path = close_file(file, staged, out)?;
    Ok(MergeReport { path, parts: parts.len(), rows: total })
}

/// The level the parts were cut from, when it can be rebuilt where the
/// merge runs: an experiment file's (its text, stored in every part and the
/// same by fingerprint, parses), 1D or a 3D grid, or a `kick sweep3d`'s
/// (its seed, samples and held spec). Its parameter columns are then
/// checked row by row.
fn experiment_of(piece: &Piece) -> Option<Box<dyn Level>> {
    let file = File::open(&piece.path).ok()?;
    let text = read_str_attr(&file, "experiment_text")?;
    let path = read_str_attr(&file, "experiment_file")?;
    if fingerprint(&text) != piece.fingerprint {
        return None;
    }
    // An experiment file's (`kick sweep` and `kick sweep3d` name no file).
    if Path::new(&path).extension().and_then(|e| e.to_str()) != Some("toml") {
        let (seed, samples) = (read_u64_attr(&file, "seed")?, read_u64_attr(&file, "samples")?);
        let sweep =
            (read_str_attr(&file, "level").as_deref() == Some("3d")).then(|| crate::held::sampled_sweep(&text, seed, samples))??;
        return (sweep.rows() == piece.total).then(|| Box::new(sweep) as Box<dyn Level>);
    }
    let level: Box<dyn Level> = Box::new(crate::experiment::parse(Path::new(&path), &text).ok()?);
    (level.rows() == piece.total).then_some(level)
}

fn varlen(text: &str) -> hdf5::Result<VarLenUnicode> {
    text.parse::<VarLenUnicode>().map_err(|e| hdf5::Error::from(e.to_string().as_str()))
}

/// Text of a file, which may hold any bytes: never a `str` that is not UTF-8.
fn text_of(v: &VarLenUnicode) -> String {
    String::from_utf8_lossy(v.as_bytes()).into_owned()
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

/// Attributes longer than this are no result layout's (a `grid_shape` has one
/// entry per axis).
const MAX_ATTRIBUTE_LIST: usize = 64;

fn read_attr(location: &Location, name: &str) -> hdf5::Result<Value> {
    let attr = location.attr(name)?;
    let descriptor = attr.dtype()?.to_descriptor()?;
    if !attr.is_scalar() {
        return match descriptor {
            TypeDescriptor::Unsigned(IntSize::U8) if attr.size() <= MAX_ATTRIBUTE_LIST => Ok(Value::U64s(attr.read_raw()?)),
            other => Err(format!("attribute `{name}`: a list of {} {}, not one of the result layout", attr.size(), type_name(&other))
                .as_str()
                .into()),
        };
    }
    Ok(match descriptor {
        TypeDescriptor::Float(FloatSize::U8) => Value::F64(attr.read_scalar()?),
        TypeDescriptor::Unsigned(IntSize::U8) => Value::U64(attr.read_scalar()?),
        TypeDescriptor::Unsigned(IntSize::U1) => Value::U8(attr.read_scalar()?),
        TypeDescriptor::VarLenUnicode => Value::Text(text_of(&attr.read_scalar::<VarLenUnicode>()?)),
        other => return Err(format!("attribute `{name}` of type {}, not one of the result layout", type_name(&other)).as_str().into()),
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

/// Builds the merged file from the first part's tree, then joins every
/// part's rows into it.
struct Merger<'a> {
    out: &'a Path,
    pieces: &'a [Piece],
    total: u64,
    experiment: Option<&'a dyn Level>,
}

impl Merger<'_> {
    fn err(&self) -> impl Fn(hdf5::Error) -> ShardError + '_ {
        move |e| ShardError::H5(H5Error::hdf5(self.out, &e))
    }

    /// Group `path` ("" the root) of the first part, into `to`: groups,
    /// attributes, per-row datasets created empty, whole ones copied.
    fn group(&self, from: &Group, to: &Group, path: &str) -> Result<(), ShardError> {
        let root = path.is_empty();
        // At the root, `rows` is written by `merge`.
        let skip = |n: &str| root && (SHARD_ATTRIBUTES.contains(&n) || n == "rows");
        copy_attrs(from, to, &skip).map_err(self.err())?;
        for name in from.member_names().map_err(self.err())? {
            let member = format!("{path}/{name}");
            if let Ok(group) = from.group(&name) {
                let target = new_group(to, &name).map_err(self.err())?;
                if name != "histories" {
                    self.group(&group, &target, &member)?;
                }
            } else {
                let first = &self.pieces[0];
                let like = from.dataset(&name).map_err(h5(&first.path))?;
                match kind(&member) {
                    Some(Kind::PerRow) => {
                        let len = self.pieces.iter().flat_map(|p| p.datasets.iter().find(|d| d.path == member)).map(|d| d.len).sum();
                        let mut chunk = (self.total as usize).clamp(1, CHUNK_ROWS);
                        if is_failure(&member) {
                            // As the writer sizes them: failures are usually few.
                            chunk = chunk.min(64);
                        }
                        self.create(&like, to, &name, len, like.is_chunked().then_some(chunk))?;
                    }
                    Some(Kind::Whole) => {
                        let created = self.create(&like, to, &name, like.shape()[0], like.chunk().map(|c| c[0]))?;
                        self.append(first, &like, &created, &member, 0, 0, None)?;
                    }
                    None => return Err(part_error(&first.path, format!("{member}: a dataset the result layout does not have"))),
                }
            }
        }
        Ok(())
    }

    /// One part's rows, histories and whole datasets (these must equal the
    /// first part's), into the merged `file`; `cursor`: rows written per dataset.
    fn part(&self, piece: &Piece, file: &File, cursor: &mut std::collections::HashMap<String, usize>) -> Result<(), ShardError> {
        let from = File::open(&piece.path).map_err(h5(&piece.path))?;
        let rows = (piece.rows.end - piece.rows.start) as usize;
        // Status codes first: they say which outcomes must be numbers.
        let mut statuses: Vec<(String, Vec<u8>)> = Vec::new();
        for d in piece.datasets.iter().filter(|d| d.path.ends_with("/outcomes/status")) {
            let values =
                from.dataset(&d.path).and_then(|s| s.read_raw::<u8>()).map_err(|e| part_error(&piece.path, format!("{}: {e}", d.path)))?;
            if let Some(i) = values.iter().position(|&c| usize::from(c) >= kick_core::Status::ALL.len()) {
                return Err(part_error(
                    &piece.path,
                    format!(
                        "{}: status {} at row {}, not one of the codes 0..{}",
                        d.path,
                        values[i],
                        piece.rows.start + i as u64,
                        kick_core::Status::ALL.len() - 1
                    ),
                ));
            }
            statuses.push((d.path.clone(), values));
        }
        if let Some(level) = self.experiment {
            self.check_parameters(piece, level, &from)?;
        }
        for d in &piece.datasets {
            let source = from.dataset(&d.path).map_err(|e| part_error(&piece.path, format!("{}: {e}", d.path)))?;
            let target = file.dataset(&d.path).map_err(self.err())?;
            match kind(&d.path) {
                Some(Kind::PerRow) => {
                    let at = cursor.entry(d.path.clone()).or_insert(0);
                    let offset = if d.path.ends_with("failures/index") { piece.rows.start } else { 0 };
                    let status = status_of(&d.path).and_then(|s| statuses.iter().find(|(p, _)| *p == s)).map(|(_, v)| v.as_slice());
                    let limit = if d.path.ends_with("failures/index") { Some(rows as u64) } else { None };
                    // A crossing column is NaN where its plane was not crossed, the row solved.
                    let crossed: Option<Vec<u8>> = crossed_of(&d.path)
                        .and_then(|c| from.dataset(&c).ok())
                        .and_then(|c| c.read_raw::<f64>().ok())
                        .map(|c| c.iter().map(|&x| if x == 1.0 { 0 } else { u8::MAX }).collect());
                    let status: Vec<u8> = match (status, crossed) {
                        (Some(s), Some(c)) => s.iter().zip(c).map(|(&s, c)| s.max(c)).collect(),
                        (s, _) => s.unwrap_or(&[]).to_vec(),
                    };
                    *at += self.append(piece, &source, &target, &d.path, *at, offset, Some((&status, limit)))?;
                }
                _ => {
                    if !same_content(&source, &target).map_err(h5(&piece.path))? {
                        return Err(ShardError::Merge(format!(
                            "{} differs between {} and {}",
                            d.path,
                            self.pieces[0].path.display(),
                            piece.path.display()
                        )));
                    }
                }
            }
        }
        self.histories(piece, &from, file)
    }

    /// The part's parameter columns: row by row the values the level gives
    /// (as the run writes them: NaN where a 1D scenario is invalid), read
    /// a block of rows at a time, each row's values made once.
    fn check_parameters(&self, piece: &Piece, level: &dyn Level, from: &File) -> Result<(), ShardError> {
        let columns = level.parameter_columns();
        let mut checked = Vec::new();
        for d in &piece.datasets {
            let Some(name) = d.path.strip_prefix("/parameters/") else { continue };
            let Some(j) = columns.iter().position(|c| c.name == name) else {
                return Err(part_error(&piece.path, format!("/parameters/{name}: not a parameter of the experiment")));
            };
            checked.push((name, j, from.dataset(&d.path).map_err(|e| part_error(&piece.path, format!("{}: {e}", d.path)))?));
        }
        let rows = (piece.rows.end - piece.rows.start) as usize;
        let mut expected = vec![f64::NAN; columns.len()];
        for start in (0..rows).step_by(CHUNK_ROWS) {
            let end = (start + CHUNK_ROWS).min(rows);
            let block = checked
                .iter()
                .map(|(_, _, d)| d.read_slice_1d::<f64, _>(start..end).map(|a| a.to_vec()))
                .collect::<hdf5::Result<Vec<_>>>()
                .map_err(h5(&piece.path))?;
            for i in start..end {
                let row = piece.rows.start + i as u64;
                if !level.parameters_into(row, &mut expected) {
                    return Ok(());
                }
                for ((name, j, _), values) in checked.iter().zip(&block) {
                    let (value, expected) = (values[i - start], expected[*j]);
                    if value.to_bits() != expected.to_bits() && !(value.is_nan() && expected.is_nan()) {
                        return Err(part_error(
                            &piece.path,
                            format!(
                                "/parameters/{name}: {} at row {row}, where the experiment gives {}",
                                kick_core::short(value),
                                kick_core::short(expected)
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// The part's histories, renamed to experiment rows.
    fn histories(&self, piece: &Piece, file: &File, to: &File) -> Result<(), ShardError> {
        for base in &piece.histories {
            let from = file.group(base).map_err(h5(&piece.path))?;
            // A part may have histories where the first part has none.
            let target_group = match to.group(base) {
                Ok(g) => g,
                Err(_) => new_group(to, base).map_err(self.err())?,
            };
            for name in from.member_names().map_err(h5(&piece.path))? {
                let local: u64 = name.parse().map_err(|_| part_error(&piece.path, format!("{base}/{name}: not a row number")))?;
                if local >= piece.rows.end - piece.rows.start {
                    return Err(part_error(&piece.path, format!("{base}/{name}: no such row in the part")));
                }
                let row = piece.rows.start + local;
                let history = from.group(&name).map_err(h5(&piece.path))?;
                let target = new_group(&target_group, &format!("{row:06}")).map_err(self.err())?;
                copy_attrs(&history, &target, &|n| n == "row").map_err(self.err())?;
                write_u64_attr(&target, self.out, "row", row)?;
                for column in history.member_names().map_err(h5(&piece.path))? {
                    let like = history.dataset(&column).map_err(h5(&piece.path))?;
                    let created =
                        self.create(&like, &target, &column, like.shape().first().copied().unwrap_or(0), like.chunk().map(|c| c[0]))?;
                    self.append(piece, &like, &created, &format!("{base}/{name}/{column}"), 0, 0, None)?;
                }
            }
        }
        Ok(())
    }

    /// A dataset of `like`'s type, attributes, filters and trailing shape
    /// for `len` rows: chunked by `chunk` rows and extendable, or (None)
    /// contiguous, as the unsharded writer stores it.
    fn create(&self, like: &hdf5::Dataset, to: &Group, name: &str, len: usize, chunk: Option<usize>) -> Result<hdf5::Dataset, ShardError> {
        let layout_error = |what: String| part_error(&self.pieces[0].path, format!("{name}: {what}, not one of the result layout"));
        let shape = like.shape();
        if shape.len() != 1 {
            return Err(layout_error(format!("dataset of shape {shape:?}")));
        }
        // The part's filters (`--compress`): a merge of compressed parts is compressed.
        let filters = like.filters();
        macro_rules! of {
            ($t:ty) => {{
                let builder = to.new_dataset::<$t>().obj_track_times(false);
                match chunk {
                    Some(c) => builder.chunk(c).set_filters(&filters).shape(0..).create(name),
                    None => builder.shape(len).create(name),
                }
            }};
        }
        let created = match like.dtype().and_then(|t| t.to_descriptor()).map_err(self.err())? {
            TypeDescriptor::Float(FloatSize::U8) => of!(f64),
            TypeDescriptor::Unsigned(IntSize::U8) => of!(u64),
            TypeDescriptor::Unsigned(IntSize::U1) => of!(u8),
            TypeDescriptor::VarLenUnicode => of!(VarLenUnicode),
            other => return Err(layout_error(format!("dataset of type {}", type_name(&other)))),
        }
        .map_err(self.err())?;
        copy_attrs(like, &created, &|_| false).map_err(self.err())?;
        Ok(created)
    }

    /// Append `from` (dataset `path` of `piece`) to `to` at row `at`, in
    /// blocks of rows; the number of rows. `check`: the part's status codes
    /// (an outcome that is NaN where the status says solved is refused) and
    /// a bound on the values (row indices).
    #[allow(clippy::too_many_arguments)]
    fn append(
        &self,
        piece: &Piece,
        from: &hdf5::Dataset,
        to: &hdf5::Dataset,
        path: &str,
        at: usize,
        offset: u64,
        check: Option<(&[u8], Option<u64>)>,
    ) -> Result<usize, ShardError> {
        let shape = from.shape();
        let n = shape.first().copied().unwrap_or(0);
        let (status, limit) = check.unwrap_or((&[], None));
        let bad = |what: String| part_error(&piece.path, format!("{path}: {what}"));
        let nan_at = |i: usize| status.get(i) == Some(&kick_core::Status::Separated.code());
        let chunked = to.is_chunked();
        let block = 16 * CHUNK_ROWS;
        let mut start = 0;
        while start < n {
            let end = (start + block).min(n);
            let rows = at + start..at + end;
            let read = h5(&piece.path);
            if chunked {
                to.resize(rows.end).map_err(self.err())?;
            }
            match to.dtype().and_then(|t| t.to_descriptor()).map_err(self.err())? {
                TypeDescriptor::Float(_) => {
                    let values = from.read_slice_1d::<f64, _>(start..end).map_err(read)?;
                    if let Some(i) = values.iter().enumerate().position(|(i, v)| v.is_nan() && nan_at(start + i)) {
                        return Err(bad(format!("NaN at row {} where the status says solved", piece.rows.start + (start + i) as u64)));
                    }
                    to.write_slice(&values, rows)
                }
                TypeDescriptor::Unsigned(IntSize::U8) => {
                    let values = from.read_slice_1d::<u64, _>(start..end).map_err(read)?;
                    if let Some(v) = limit.and_then(|l| values.iter().find(|&&v| v >= l)) {
                        return Err(bad(format!("row {v} in a part of {} rows", limit.unwrap_or(0))));
                    }
                    to.write_slice(&values.mapv(|v| v + offset), rows)
                }
                TypeDescriptor::Unsigned(_) => {
                    let values = from.read_slice_1d::<u8, _>(start..end).map_err(read)?;
                    to.write_slice(&values, rows)
                }
                _ => {
                    let values = from.read_slice_1d::<VarLenUnicode, _>(start..end).map_err(read)?;
                    if values.iter().any(|v| std::str::from_utf8(v.as_bytes()).is_err()) {
                        return Err(bad("text that is not UTF-8".into()));
                    }
                    to.write_slice(&values, rows)
                }
            }
            .map_err(self.err())?;
            start = end;
        }
        Ok(n)
    }
}

/// Whether a whole-experiment dataset of a part equals the merged file's copy.
fn same_content(a: &hdf5::Dataset, b: &hdf5::Dataset) -> hdf5::Result<bool> {
    if a.shape() != b.shape() {
        return Ok(false);
    }
    Ok(match b.dtype()?.to_descriptor()? {
        TypeDescriptor::VarLenUnicode => {
            let text = |d: &hdf5::Dataset| d.read_raw::<VarLenUnicode>().map(|v| v.iter().map(text_of).collect::<Vec<_>>());
            text(a)? == text(b)?
        }
        _ => {
            let bits = |d: &hdf5::Dataset| d.read_raw::<f64>().map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
            bits(a)? == bits(b)?
        }
    })
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

    const GRID: &str = "solver = \"accurate\"\n[[sweep]]\nparameter = \"stiffness\"\nvalues = [2e5, 4.2e5, 8e5, 1.6e6]\n\
                        [[sweep]]\nparameter = \"damping\"\nvalues = [0.0, 60.0, 120.0]\n";

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-shard-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// `grid.toml` in `dir` and its shards 0/2, 1/2 in `dir/parts`.
    fn two_parts(dir: &Path) -> (Experiment, Vec<PathBuf>) {
        let file = dir.join("grid.toml");
        std::fs::write(&file, GRID).unwrap();
        let experiment = crate::experiment::parse(&file, GRID).unwrap();
        let parts: Vec<PathBuf> = (0..2)
            .map(|index| {
                let shard = Shard { index, count: 2 };
                run_shard(&experiment, shard, &dir.join("parts"), false).unwrap();
                dir.join("parts").join(shard.file_name("grid"))
            })
            .collect();
        (experiment, parts)
    }

    /// A part corrupted in each way a disk, a copy or a hand can: a clean
    /// error naming the part and what is wrong, and no merged file.
    #[test]
    fn corrupt_parts_are_refused_naming_them() {
        let dir = scratch("corrupt");
        let (_, parts) = two_parts(&dir);
        type Corruption = (&'static str, &'static str, fn(&hdf5::File));
        let corruptions: [Corruption; 9] = [
            ("a [rows, 3] column", "parameters/stiffness: a dataset of shape [6, 3], not one of the result layout (1-D)", |f| {
                f.unlink("parameters/stiffness").unwrap();
                let d = f.new_dataset::<f64>().shape((6, 3)).create("parameters/stiffness").unwrap();
                d.write_raw(&[1.0; 18]).unwrap();
            }),
            ("older layout", "layout sweep version 1, not `sweep` version 3", |f| {
                f.delete_attr("layout_version").unwrap();
                f.new_attr::<u64>().create("layout_version").unwrap().write_scalar(&1u64).unwrap();
            }),
            ("short dataset", "5 entries in a part of 6 rows", |f| {
                f.dataset("parameters/stiffness").unwrap().resize(5).unwrap();
            }),
            ("status out of range", "status 7 at row 7", |f| {
                f.dataset("outcomes/status").unwrap().write_slice(&[7u8], 1..2).unwrap();
            }),
            ("NaN with status 0", "NaN at row 6 where the status says solved", |f| {
                let name = &crate::run::outcome_columns()[0].name;
                assert_eq!(f.dataset("outcomes/status").unwrap().read_raw::<u8>().unwrap()[0], 0);
                f.dataset(&format!("outcomes/{name}")).unwrap().write_slice(&[f64::NAN], 0..1).unwrap();
            }),
            ("changed parameter", "/parameters/stiffness: 1 at row 6, where the experiment gives", |f| {
                f.dataset("parameters/stiffness").unwrap().write_slice(&[1.0], 0..1).unwrap();
            }),
            ("other units", "parameters/damping: f64 [N*s/mm] here, f64 [", |f| {
                let d = f.dataset("parameters/damping").unwrap();
                d.delete_attr("units").unwrap();
                crate::h5::write_str_attr(&d, Path::new("x"), "units", "N*s/mm").unwrap();
            }),
            ("float32 column", "a column of type f32", |f| {
                let outcomes = f.group("outcomes").unwrap();
                let name = &crate::run::outcome_columns()[0].name;
                let values: Vec<f32> = outcomes.dataset(name).unwrap().read_raw::<f64>().unwrap().iter().map(|&v| v as f32).collect();
                outcomes.unlink(name).unwrap();
                outcomes.new_dataset_builder().with_data(&values).create(name.as_str()).unwrap();
            }),
            ("failure index beyond the part", "row 6 in a part of 6 rows", |f| {
                let failures = f.group("failures").unwrap();
                failures.unlink("index").unwrap();
                failures.unlink("message").unwrap();
                let index = failures.new_dataset_builder().with_data(&[6u64]).create("index").unwrap();
                crate::h5::write_str_attr(&index, Path::new("x"), "units", "1").unwrap();
                let text: VarLenUnicode = "x".parse().unwrap();
                let message = failures.new_dataset_builder().with_data(&[text]).create("message").unwrap();
                crate::h5::write_str_attr(&message, Path::new("x"), "units", "").unwrap();
            }),
        ];
        for (what, says, corrupt) in corruptions {
            let bad = dir.join("bad.shard-1-of-2.h5");
            std::fs::copy(&parts[1], &bad).unwrap();
            corrupt(&hdf5::File::open_rw(&bad).unwrap());
            let out = dir.join("merged.h5");
            let message = merge(&out, &[parts[0].clone(), bad.clone()]).err().unwrap_or_else(|| panic!("{what}: merged")).to_string();
            assert!(message.contains("bad.shard-1-of-2.h5") && message.contains(says), "{what}: {message}");
            assert!(!out.exists(), "{what}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A 3D grid part and a `kick sweep3d` part with one parameter value
    /// changed are refused by name (the experiment's grid, the sweep's seed
    /// and held spec give every row's values); the untouched parts merge to
    /// the whole, held values (a vector, an infinite friction, the law) read
    /// back exactly.
    #[test]
    fn changed_3d_parameters_are_refused_and_untouched_parts_merge() {
        let dir = scratch("3d-parameters");
        let file = dir.join("g3.toml");
        std::fs::write(
            &file,
            "[kick3d]\nfriction = 0.6\n[[sweep]]\nparameter = \"foot_speed\"\nvalues = [16.0, 22.0, 28.0]\n\
                               [[sweep]]\nparameter = \"offset\"\nvalues = [0.0, 0.04]\n",
        )
        .unwrap();
        let grid: Vec<PathBuf> = ["0/2", "1/2"].iter().map(|s| run_file(&file, &dir.join("grid"), Some(s)).unwrap().summary.path).collect();
        let mut fixed = kick_3d::KickSpec::default();
        fixed.scenario.law = Some(kick_core::LawKind::HuntCrossley);
        fixed.scenario.restitution = Some(0.7);
        fixed.kick3d.friction = Some(f64::INFINITY);
        fixed.kick3d.foot_half_extents = Some([0.03, 0.11, 0.05]);
        fixed.kick3d.gravity = Some(true);
        let sweep: Vec<PathBuf> = ["0/2", "1/2"]
            .iter()
            .map(|s| {
                let settings = crate::sweep3d::Sweep3dSettings {
                    samples: 6,
                    seed: 5,
                    out: dir.join("sweep/k.h5"),
                    fixed,
                    // A range of the kick's and of the flight's, and two planes: the merge redraws them.
                    ranges: kick_study::sample::Ranges::parse(&["contact_depth=0,0.03".into(), "air_density=1.1,1.2".into()], |n| {
                        crate::sweep3d::find_range(n, true)
                    })
                    .unwrap(),
                    flight: Some(kick_study::flight::FlightPlan::planes(Default::default(), vec![9.15, 25.0]).unwrap()),
                    shard: Some(s.to_string()),
                    threads: None,
                    compress: Default::default(),
                };
                crate::sweep3d::sweep3d(&settings).unwrap().path
            })
            .collect();
        for (parts, column, says) in [
            (&grid, "offset", "/parameters/offset: 0.05 at row 3, where the experiment gives 0.04"),
            (&sweep, "friction", "/parameters/friction: 0.05 at row 3, where the experiment gives inf"),
            (&sweep, "foot_half_extents_y", "/parameters/foot_half_extents_y: 0.05 at row 3, where the experiment gives 0.11"),
        ] {
            let whole = dir.join("whole.h5");
            merge(&whole, parts).unwrap();
            std::fs::remove_file(&whole).unwrap();
            let bad = dir.join("bad.shard-1-of-2.h5");
            std::fs::copy(&parts[1], &bad).unwrap();
            let f = hdf5::File::open_rw(&bad).unwrap();
            f.dataset(&format!("parameters/{column}")).unwrap().write_slice(&[0.05], 0..1).unwrap();
            drop(f);
            let out = dir.join("merged.h5");
            let message = merge(&out, &[parts[0].clone(), bad.clone()]).err().unwrap_or_else(|| panic!("{column}: merged")).to_string();
            assert!(message.contains("bad.shard-1-of-2.h5") && message.contains(says), "{column}: {message}");
            assert!(!out.exists(), "{column}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// The merged file stores its datasets as the unsharded run does: chunks
    /// sized by the experiment's rows, not 4096 rows against 12.
    #[test]
    fn a_merge_is_stored_like_the_unsharded_run() {
        let dir = scratch("storage");
        let (experiment, parts) = two_parts(&dir);
        let merged = dir.join("merged.h5");
        merge(&merged, &parts).unwrap();
        let whole = crate::run::run(&experiment, &dir.join("whole"), false).unwrap().path;
        let (merged, whole) = (hdf5::File::open(&merged).unwrap(), hdf5::File::open(&whole).unwrap());
        let mut compared = 0;
        for path in ["parameters/stiffness", "outcomes/status", "failures/index", "failures/message"] {
            let (a, b) = (merged.dataset(path).unwrap(), whole.dataset(path).unwrap());
            assert_eq!((a.chunk(), a.shape()), (b.chunk(), b.shape()), "{path}");
            compared += 1;
        }
        assert_eq!(compared, 4);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
