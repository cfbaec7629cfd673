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
        TypeDescriptor::Integer(_) | TypeDescriptor::Unsigned(_) | TypeDescriptor::Float(_) | TypeDescriptor::Boolean => {
            container.read_raw::<f64>().map(Value::Numbers)
        }
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

/// Every dataset and attribute of an HDF5 file, by path.
fn entries(path: &Path) -> Result<BTreeMap<String, Value>, String> {
    crate::h5::disable_file_locking();
    let file = hdf5::File::open(path).map_err(|e| format!("cannot open: {e}"))?;
    let mut out = BTreeMap::new();
    walk(&file, "", &mut out).map_err(|e| format!("cannot read: {e}"))?;
    Ok(out)
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
