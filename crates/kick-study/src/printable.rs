//! What every front end prints: a result as text or as JSON, with the same
//! keys for the command line and (later) Python.

use serde::Serialize;
use std::path::PathBuf;

/// A result a command prints: JSON from its `Serialize`, text from [`Printable::text`].
pub trait Printable: Serialize {
    /// The text form, ending with a newline.
    fn text(&self) -> String;
    /// Files the command wrote (front ends say where).
    fn written(&self) -> &[PathBuf] {
        &[]
    }
}

/// Pretty JSON of a result.
pub fn json<T: Serialize + ?Sized>(value: &T) -> Result<String, crate::error::StudyError> {
    serde_json::to_string_pretty(value)
        .map(|mut s| {
            s.push('\n');
            s
        })
        .map_err(|e| crate::error::StudyError::Json(format!("cannot write JSON: {e}")))
}
