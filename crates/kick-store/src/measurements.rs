//! The validation chapter's data file, `experiments/validation/measurements.toml`
//! ([`MEASUREMENTS_FILE`]): opened and parsed here, then checked into
//! kick-core's [`Measurements`] (the in-memory types the model crates
//! compare against; kick-core touches no file).

use kick_core::measurements::{MeasurementEntry, MeasurementError, Measurements, Source};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The data file, relative to the workspace root.
pub const MEASUREMENTS_FILE: &str = "experiments/validation/measurements.toml";

/// Why a measurement file could not be read: every message names the file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeasurementFileError {
    /// The file cannot be opened, or is not TOML of the file's form (the
    /// parser's message names the line and the key).
    #[error("{}: {message}", .path.display())]
    Read { path: PathBuf, message: String },
    /// Parsed, but refused by the checks (a key, a unit, a range).
    #[error(transparent)]
    Invalid(#[from] MeasurementError),
}

/// The file's tables as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Tables {
    #[serde(default)]
    source: Vec<Source>,
    #[serde(default)]
    measurement: Vec<MeasurementEntry>,
}

/// Read and check [`MEASUREMENTS_FILE`] or another file of that form.
pub fn read(path: &Path) -> Result<Measurements, MeasurementFileError> {
    let text =
        std::fs::read_to_string(path).map_err(|e| MeasurementFileError::Read { path: path.to_path_buf(), message: e.to_string() })?;
    parse(&text, path)
}

/// Parse and check `text`, read from `path` (the name errors give).
pub fn parse(text: &str, path: &Path) -> Result<Measurements, MeasurementFileError> {
    let tables: Tables =
        toml::from_str(text).map_err(|e| MeasurementFileError::Read { path: path.to_path_buf(), message: e.to_string() })?;
    Ok(Measurements::check(&path.display().to_string(), tables.source, tables.measurement)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = kick_core::measurements::MINIMAL_FILE;

    #[test]
    fn errors_name_the_file_and_the_key() {
        let file = Path::new("x.toml");
        assert_eq!(parse(MINIMAL, file).unwrap().file, "x.toml");
        // An unknown unit is the parser's refusal, naming the file and the value.
        let e = parse(&MINIMAL.replace("\"ms\"", "\"furlong\""), file).unwrap_err();
        let MeasurementFileError::Read { path, message } = &e else { panic!("{e:?}") };
        assert_eq!(path, file);
        assert!(message.contains("furlong"), "{message}");
        assert!(e.to_string().starts_with("x.toml: "), "{e}");
        // A check's refusal is kick-core's, naming the file and the key.
        let e = parse(&MINIMAL.replace("source = \"a\"", "source = \"zz\""), file).unwrap_err();
        let MeasurementFileError::Invalid(MeasurementError::Invalid { file, key, .. }) = &e else { panic!("{e:?}") };
        assert_eq!((file.as_str(), key.as_str()), ("x.toml", "t"));
        assert!(e.to_string().contains("zz"), "{e}");
        // A file that is not there names itself.
        let e = read(Path::new("no/such/measurements.toml")).unwrap_err();
        assert!(matches!(&e, MeasurementFileError::Read { path, .. } if path == Path::new("no/such/measurements.toml")), "{e:?}");
        assert!(e.to_string().starts_with("no/such/measurements.toml: "), "{e}");
    }
}
