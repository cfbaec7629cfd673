//! [`PaperError`]: every way writing a page, a figure or the reproduction
//! fails. It wraps the layers' errors as they are (kick-store's files,
//! kick-study's computing, the figures and the report); its own variants
//! name the file, the flag or the folder. Its `Display` is the message the
//! front ends print.

use std::path::PathBuf;

#[derive(Debug, thiserror::Error)]
pub enum PaperError {
    #[error(transparent)]
    Store(#[from] kick_store::StoreError),
    #[error(transparent)]
    Study(#[from] kick_study::StudyError),
    #[error(transparent)]
    Bench(#[from] kick_study::bench::BenchError),
    #[error(transparent)]
    Validation(#[from] kick_study::validation::ValidationError),
    #[error(transparent)]
    H5(#[from] kick_store::h5::H5Error),
    #[error(transparent)]
    Run(#[from] kick_store::table::RunError),
    #[error(transparent)]
    Output(#[from] kick_store::output::OutputError),
    #[error(transparent)]
    Measurements(#[from] kick_store::measurements::MeasurementFileError),
    #[error(transparent)]
    Figure(#[from] crate::figures::FigureError),
    #[error(transparent)]
    Report(#[from] crate::report::ReportError),
    #[error(transparent)]
    ModelPage(#[from] crate::model::ModelPageError),
    /// A result file without what a page or figure reads from it: the file
    /// (when the reader knows it) and what.
    #[error("{}{what}", .file.as_ref().map(|f| format!("{}: ", f.display())).unwrap_or_default())]
    Lacks { file: Option<PathBuf>, what: String },
    /// A number a page states in words that the results no longer bear out.
    #[error("{0}")]
    Claim(String),
    /// A flag of `kick reproduce` refused; the message names it.
    #[error("{message}")]
    Flag { flag: &'static str, message: String },
    /// A folder or file that cannot be read, made or copied (`what`: "read", "create", "copy").
    #[error("cannot {what} {}: {source}", .path.display())]
    Io { what: &'static str, path: PathBuf, source: std::io::Error },
    /// Two steps that would write the same file.
    #[error("{} and {} both write {}", .first.display(), .second.display(), .file.display())]
    SameFile { first: PathBuf, second: PathBuf, file: PathBuf },
    /// `reproduce --check` given one folder for both sides.
    #[error("{} and {} must be different folders", .out.display(), .report.display())]
    SameFolder { out: PathBuf, report: PathBuf },
    /// The study registry (`kick_study::studies`) and the steps kick-paper runs disagree.
    #[error("{0}")]
    Registry(String),
    /// No experiment file in the folder given.
    #[error("--experiments {}: no experiment files (*.toml) in the folder", .0.display())]
    NoExperiments(PathBuf),
}

impl PaperError {
    /// A result file `file` without `what`.
    pub fn lacks(file: impl Into<PathBuf>, what: impl Into<String>) -> PaperError {
        PaperError::Lacks { file: Some(file.into()), what: what.into() }
    }

    /// A result without `what` (the file named by the caller's context).
    pub fn missing(what: impl Into<String>) -> PaperError {
        PaperError::Lacks { file: None, what: what.into() }
    }
}

/// The front ends print the message.
impl From<PaperError> for String {
    fn from(e: PaperError) -> String {
        e.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A page's reader names the file and what it lacks; a refused flag is its flag.
    #[test]
    fn messages_name_the_file_and_the_flag() {
        let e = PaperError::lacks("results/ball/ball.h5", "no column rebound_height");
        assert!(matches!(&e, PaperError::Lacks { file: Some(f), .. } if f.ends_with("ball.h5")), "{e:?}");
        assert_eq!(e.to_string(), "results/ball/ball.h5: no column rebound_height");
        assert_eq!(PaperError::missing("empty curve").to_string(), "empty curve");
        let e = PaperError::SameFolder { out: "a".into(), report: "a".into() };
        assert_eq!(e.to_string(), "a and a must be different folders");
        // A layer's error is kept whole, its message unchanged.
        let store = kick_store::StoreError::Flag { flag: "--times", message: "--times must be in 2..=100000 (got 1)".into() };
        let e = PaperError::from(store);
        assert!(matches!(&e, PaperError::Store(kick_store::StoreError::Flag { flag: "--times", .. })), "{e:?}");
        assert_eq!(String::from(e), "--times must be in 2..=100000 (got 1)");
    }
}
