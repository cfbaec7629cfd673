//! What `kick reproduce --check` compares: HDF5 files by value (every
//! dataset and attribute, so a difference is named by its path), other files
//! by bytes. The root attributes that describe the checkout
//! ([`PROVENANCE_ATTRIBUTES`]) are left out: they say where the numbers came
//! from, not what they are.

use crate::provenance::PROVENANCE_ATTRIBUTES;
use hdf5::types::{TypeDescriptor, VarLenAscii, VarLenUnicode};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One file that differs, and how.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Difference {
    /// The committed file's path.
    pub file: PathBuf,
    /// What differs (a dataset or attribute path and the first values that differ, or why).
    pub what: String,
}

/// A file's content as compared: one entry per dataset and attribute.
#[derive(Debug, Clone, PartialEq)]
enum Value {
    Numbers(Vec<f64>),
    /// Integers, read exactly (an f64 holds only 53 bits).
    Integers(Vec<i128>),
    Strings(Vec<String>),
    /// A type the comparison does not read (compared by its description only).
    Other(String),
}

fn same_numbers(a: &[f64], b: &[f64]) -> Option<String> {
    if a.len() != b.len() {
        return Some(format!("{} values committed, {} regenerated", a.len(), b.len()));
    }
    let differing: Vec<usize> = (0..a.len()).filter(|&i| a[i].to_bits() != b[i].to_bits() && !(a[i].is_nan() && b[i].is_nan())).collect();
    differing.first().map(|&i| {
        format!("{} of {} values differ; first at index {i}: committed {:e}, regenerated {:e}", differing.len(), a.len(), a[i], b[i])
    })
}

fn describe(a: &Value, b: &Value) -> Option<String> {
    match (a, b) {
        (Value::Numbers(a), Value::Numbers(b)) => same_numbers(a, b),
        (Value::Integers(a), Value::Integers(b)) if a.len() != b.len() => {
            Some(format!("{} values committed, {} regenerated", a.len(), b.len()))
        }
        (Value::Integers(a), Value::Integers(b)) => {
            let differing: Vec<usize> = (0..a.len()).filter(|&i| a[i] != b[i]).collect();
            differing.first().map(|&i| {
                format!("{} of {} values differ; first at index {i}: committed {}, regenerated {}", differing.len(), a.len(), a[i], b[i])
            })
        }
        (Value::Strings(a), Value::Strings(b)) if a.len() != b.len() => {
            Some(format!("{} strings committed, {} regenerated", a.len(), b.len()))
        }
        (Value::Strings(a), Value::Strings(b)) => {
            let differing: Vec<usize> = (0..a.len()).filter(|&i| a[i] != b[i]).collect();
            differing.first().map(|&i| {
                let short =
                    |s: &str| if s.chars().count() > 60 { format!("{}…", s.chars().take(60).collect::<String>()) } else { s.to_string() };
                format!(
                    "{} of {} strings differ; first at index {i}: committed {:?}, regenerated {:?}",
                    differing.len(),
                    a.len(),
                    short(&a[i]),
                    short(&b[i])
                )
            })
        }
        (a, b) if a == b => None,
        _ => Some("type differs".into()),
    }
}

fn read(container: &hdf5::Container) -> Value {
    let descriptor = match container.dtype().and_then(|t| t.to_descriptor()) {
        Ok(d) => d,
        Err(e) => return Value::Other(format!("unreadable type: {e}")),
    };
    let result = match &descriptor {
        TypeDescriptor::Integer(_) => container.read_raw::<i64>().map(|v| Value::Integers(v.into_iter().map(i128::from).collect())),
        TypeDescriptor::Unsigned(_) => container.read_raw::<u64>().map(|v| Value::Integers(v.into_iter().map(i128::from).collect())),
        TypeDescriptor::Float(_) | TypeDescriptor::Boolean => container.read_raw::<f64>().map(Value::Numbers),
        TypeDescriptor::VarLenUnicode => {
            container.read_raw::<VarLenUnicode>().map(|v| Value::Strings(v.iter().map(|s| s.as_str().to_string()).collect()))
        }
        TypeDescriptor::VarLenAscii => {
            container.read_raw::<VarLenAscii>().map(|v| Value::Strings(v.iter().map(|s| s.as_str().to_string()).collect()))
        }
        other => Ok(Value::Other(format!("{other:?}, shape {:?}", container.shape()))),
    };
    result.unwrap_or_else(|e| Value::Other(format!("unreadable: {e}")))
}

fn attributes(location: &hdf5::Location, at: &str, root: bool, out: &mut BTreeMap<String, Value>) -> hdf5::Result<()> {
    for name in location.attr_names()? {
        if root && PROVENANCE_ATTRIBUTES.contains(&name.as_str()) {
            continue;
        }
        let attribute = location.attr(&name)?;
        out.insert(format!("{at} attribute {name}"), read(&attribute));
    }
    Ok(())
}

fn walk(group: &hdf5::Group, at: &str, out: &mut BTreeMap<String, Value>) -> hdf5::Result<()> {
    attributes(group, if at.is_empty() { "/" } else { at }, at.is_empty(), out)?;
    for name in group.member_names()? {
        let path = format!("{at}/{name}");
        if let Ok(child) = group.group(&name) {
            walk(&child, &path, out)?;
        } else {
            let dataset = group.dataset(&name)?;
            out.insert(format!("dataset {path}"), read(&dataset));
            attributes(&dataset, &path, false, out)?;
        }
    }
    Ok(())
}

/// Why a file's entries could not be listed (the difference reported).
#[derive(Debug, thiserror::Error)]
enum Unreadable {
    #[error("cannot open: {0}")]
    Open(hdf5::Error),
    #[error("cannot read: {0}")]
    Read(hdf5::Error),
}

/// Every dataset and attribute of an HDF5 file, by path.
fn entries(path: &Path) -> Result<BTreeMap<String, Value>, Unreadable> {
    crate::h5::disable_file_locking();
    let file = hdf5::File::open(path).map_err(Unreadable::Open)?;
    let mut out = BTreeMap::new();
    walk(&file, "", &mut out).map_err(Unreadable::Read)?;
    Ok(out)
}

/// Whether two HDF5 files hold the same content: the same groups, datasets
/// and attributes, each of the same type and shape with the same values (bit
/// for bit, NaN equal to NaN), the root's provenance of the checkout
/// ([`PROVENANCE_ATTRIBUTES`]) left out. What cannot be read, or holds a type
/// this module does not read, counts as different. Read one object at a time
/// and stops at the first difference. [`crate::output::Staged::commit_unless`]
/// keeps a result file that passes this, so a rerun at a later commit leaves
/// a file whose numbers did not change as it was, provenance included.
pub fn same_content(a: &Path, b: &Path) -> bool {
    crate::h5::disable_file_locking();
    match (hdf5::File::open(a), hdf5::File::open(b)) {
        (Ok(a), Ok(b)) => same_group(&a, &b, true).unwrap_or(false),
        _ => false,
    }
}

fn same_group(a: &hdf5::Group, b: &hdf5::Group, root: bool) -> hdf5::Result<bool> {
    if !same_attributes(a, b, root)? {
        return Ok(false);
    }
    let (mut names, mut others) = (a.member_names()?, b.member_names()?);
    names.sort();
    others.sort();
    if names != others {
        return Ok(false);
    }
    for name in &names {
        let same = match (a.group(name), b.group(name)) {
            (Ok(x), Ok(y)) => same_group(&x, &y, false)?,
            (Err(_), Err(_)) => {
                let (x, y) = (a.dataset(name)?, b.dataset(name)?);
                same_container(&x, &y) && same_attributes(&x, &y, false)?
            }
            _ => false,
        };
        if !same {
            return Ok(false);
        }
    }
    Ok(true)
}

fn same_attributes(a: &hdf5::Location, b: &hdf5::Location, root: bool) -> hdf5::Result<bool> {
    let kept = |names: Vec<String>| -> Vec<String> {
        let mut names: Vec<String> = names.into_iter().filter(|n| !(root && PROVENANCE_ATTRIBUTES.contains(&n.as_str()))).collect();
        names.sort();
        names
    };
    let names = kept(a.attr_names()?);
    if names != kept(b.attr_names()?) {
        return Ok(false);
    }
    for name in &names {
        let (x, y) = (a.attr(name)?, b.attr(name)?);
        if !same_container(&x, &y) {
            return Ok(false);
        }
    }
    Ok(true)
}

fn same_container(a: &hdf5::Container, b: &hdf5::Container) -> bool {
    let kind = |c: &hdf5::Container| c.dtype().and_then(|t| t.to_descriptor()).ok().map(|d| (d, c.shape()));
    match (kind(a), kind(b)) {
        (Some(x), Some(y)) if x == y => {}
        _ => return false,
    }
    match (read(a), read(b)) {
        (Value::Other(_), _) | (_, Value::Other(_)) => false,
        (x, y) => describe(&x, &y).is_none(),
    }
}

/// `regenerated` against `committed` (both HDF5 files); `rename` maps strings
/// of the regenerated file (its folder's path) to the committed ones'.
pub fn compare_h5(committed: &Path, regenerated: &Path, rename: &dyn Fn(&str) -> String) -> Vec<Difference> {
    let difference = |what: String| Difference { file: committed.to_path_buf(), what };
    let (a, b) = match (entries(committed), entries(regenerated)) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) => return vec![difference(format!("committed file: {e}"))],
        (_, Err(e)) => return vec![difference(format!("regenerated file: {e}"))],
    };
    let mut found = Vec::new();
    for (key, value) in &a {
        match b.get(key) {
            None => found.push(difference(format!("{key}: no longer written"))),
            Some(new) => {
                let new = match new {
                    Value::Strings(s) => Value::Strings(s.iter().map(|s| rename(s)).collect()),
                    other => other.clone(),
                };
                if let Some(what) = describe(value, &new) {
                    found.push(difference(format!("{key}: {what}")));
                }
            }
        }
    }
    for key in b.keys().filter(|k| !a.contains_key(*k)) {
        found.push(difference(format!("{key}: new, not in the committed file")));
    }
    found
}

/// Whether a file is compared by value (HDF5) or by bytes.
fn is_h5(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "h5")
}

/// Whether a file's text may hold the folder's path (compared after renaming).
fn is_text(path: &Path) -> bool {
    path.extension().is_some_and(|e| ["md", "toml", "txt", "csv", "json"].iter().any(|t| e == *t))
}

/// One regenerated file against its committed counterpart.
pub fn compare_file(committed: &Path, regenerated: &Path, rename: &dyn Fn(&str) -> String) -> Vec<Difference> {
    let difference = |what: &str| vec![Difference { file: committed.to_path_buf(), what: what.into() }];
    if !committed.exists() {
        return difference("not committed (written by the regeneration)");
    }
    let (Ok(old), Ok(new)) = (std::fs::read(committed), std::fs::read(regenerated)) else {
        return difference("cannot read");
    };
    if old == new {
        return Vec::new();
    }
    if is_h5(committed) {
        return compare_h5(committed, regenerated, rename);
    }
    if is_text(committed) {
        if let Ok(new) = String::from_utf8(new) {
            if rename(&new).as_bytes() == old {
                return Vec::new();
            }
            let old = String::from_utf8_lossy(&old);
            let new = rename(&new);
            let line = old.lines().zip(new.lines()).position(|(a, b)| a != b).unwrap_or(old.lines().count().min(new.lines().count()));
            return difference(&format!("text differs from line {}", line + 1));
        }
    }
    difference("bytes differ")
}

/// Every file below `dir`, relative to it, sorted; files below `skip` (relative) left out.
pub fn files_below(dir: &Path, skip: &[&Path]) -> Vec<PathBuf> {
    fn visit(root: &Path, dir: &Path, skip: &[&Path], out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for entry in entries.flatten() {
            let path = entry.path();
            let relative = path.strip_prefix(root).unwrap_or(&path).to_path_buf();
            if skip.iter().any(|s| relative.starts_with(s)) {
                continue;
            }
            if path.is_dir() {
                visit(root, &path, skip, out);
            } else {
                out.push(relative);
            }
        }
    }
    let mut out = Vec::new();
    visit(dir, dir, skip, &mut out);
    out.sort();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::h5::{read_str_attr, write_u64_attr, Column};
    use crate::provenance::Provenance;
    use crate::writer::ResultWriter;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-compare-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn provenance(commit: &str) -> Provenance {
        Provenance {
            tool: "kick".into(),
            tool_version: "0".into(),
            git_commit: Some(commit.into()),
            git_dirty: Some(false),
            experiment: "e".into(),
            experiment_file: "e.toml".into(),
            experiment_text: "x = 1".into(),
        }
    }

    /// A result file written at commit `commit` with `values`, and an
    /// integer attribute `seed`.
    fn write(path: &Path, commit: &str, values: &[f64], seed: u64) -> PathBuf {
        let writer = ResultWriter::create(path, &provenance(commit), &crate::layouts::HISTORY).unwrap();
        writer.column("fixed", &Column::new("v", "m"), values).unwrap();
        write_u64_attr(writer.file(), path, "seed", seed).unwrap();
        writer.finish().unwrap()
    }

    fn commit_of(path: &Path) -> Option<String> {
        read_str_attr(&hdf5::File::open(path).unwrap(), "git_commit")
    }

    /// Rerun at another commit with the same numbers: the file stays as it
    /// was, bytes and provenance; a changed number, NaN pattern or integer
    /// beyond 2^53 rewrites it with the new provenance.
    #[test]
    fn a_rerun_that_changes_no_number_leaves_the_file_as_it_was() {
        crate::h5::disable_file_locking();
        let dir = scratch("rerun");
        let path = dir.join("r.h5");
        let values = [1.0, f64::NAN, -0.0];
        write(&path, "aaaa111", &values, 1 << 53);
        let bytes = std::fs::read(&path).unwrap();
        write(&path, "bbbb222", &values, 1 << 53);
        assert_eq!(std::fs::read(&path).unwrap(), bytes, "same numbers at another commit must not rewrite the file");
        assert_eq!(commit_of(&path).as_deref(), Some("aaaa111"));
        // One bit of the seed past what an f64 holds.
        write(&path, "cccc333", &values, (1 << 53) + 1);
        assert_eq!(commit_of(&path).as_deref(), Some("cccc333"));
        // +0 against -0: a different bit pattern is a different number.
        write(&path, "dddd444", &[1.0, f64::NAN, 0.0], (1 << 53) + 1);
        assert_eq!(commit_of(&path).as_deref(), Some("dddd444"));
        // One more value (another shape).
        write(&path, "eeee555", &[1.0, f64::NAN, 0.0, 0.0], (1 << 53) + 1);
        assert_eq!(commit_of(&path).as_deref(), Some("eeee555"));
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, ["r.h5"], "no temporary file left");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn same_content_leaves_out_only_the_provenance_of_the_checkout() {
        crate::h5::disable_file_locking();
        let dir = scratch("content");
        let (a, b) = (dir.join("a.h5"), dir.join("b.h5"));
        write(&a, "aaaa111", &[1.0, 2.0], 3);
        write(&b, "bbbb222", &[1.0, 2.0], 3);
        assert!(same_content(&a, &b) && same_content(&b, &a));
        // Any other provenance attribute counts: the experiment's text.
        let mut other = provenance("aaaa111");
        other.experiment_text = "x = 2".into();
        let writer = ResultWriter::create(&b, &other, &crate::layouts::HISTORY).unwrap();
        writer.column("fixed", &Column::new("v", "m"), &[1.0, 2.0]).unwrap();
        write_u64_attr(writer.file(), &b, "seed", 3).unwrap();
        writer.finish().unwrap();
        assert!(!same_content(&a, &b));
        // A unit is an attribute of a dataset.
        let writer = ResultWriter::create(&b, &provenance("aaaa111"), &crate::layouts::HISTORY).unwrap();
        writer.column("fixed", &Column::new("v", "mm"), &[1.0, 2.0]).unwrap();
        write_u64_attr(writer.file(), &b, "seed", 3).unwrap();
        writer.finish().unwrap();
        assert!(!same_content(&a, &b));
        assert!(!same_content(&a, &dir.join("missing.h5")));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
