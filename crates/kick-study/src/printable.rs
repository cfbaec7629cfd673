//! What every front end prints: a result as text or as JSON, with the same
//! keys for the command line and (later) Python.

// How numbers and statuses print, the same on every page and front end.
pub use kick_core::{short, sig, Status};
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
    /// Why the result, printed whole, lies outside its contact law's
    /// validity (`kick_core::validity`); front ends make it visible (the
    /// command line prints it and exits 1, Python warns).
    fn outside_validity(&self) -> Option<String> {
        None
    }
    /// Why the result holds no answer at all, every row of a sweep refused
    /// or failed (a file of failures, written whole): the command line
    /// prints the result, then this, and exits 1.
    fn no_answer(&self) -> Option<String> {
        None
    }
}

/// The `status` of a single result in its JSON, and why when it is
/// outside its law's validity (the numbers are the law's, not a ball's).
pub fn insert_status(object: &mut serde_json::Map<String, serde_json::Value>, outside: Option<&kick_core::OutsideValidity>) {
    let status = if outside.is_some() { kick_core::Status::OutsideValidity } else { kick_core::Status::Separated };
    object.insert("status".into(), serde_json::to_value(status).unwrap_or_default());
    if let Some(o) = outside {
        object.insert("outside_validity".into(), serde_json::to_value(o).unwrap_or_default());
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
