//! Identification and contact laws as a research tool: `kick fit` and `kick
//! laws` as library functions, their result files ([`files`]), figures
//! ([`figures`], drawn from those files) and report pages ([`report`]).

pub mod figures;
pub use kick_store::identify::files;
pub mod report;

use crate::error::PaperError;
pub use kick_store::identify::fit::{
    data, other_law_name, synthesize, table2, DataFit, ProfileReport, ProfileSettings, Synthesized, Table2Fits,
};
pub use kick_store::identify::laws::{LawsReport, LawsSettings};
use std::path::PathBuf;

/// `kick fit profile`: the study and its file (kick-store), then its
/// figure drawn from the file.
pub fn profile(settings: &ProfileSettings) -> Result<ProfileReport, PaperError> {
    let figures = figure_paths(settings.out.as_ref(), "identifiability");
    check_figures(&figures)?;
    let mut report = kick_store::identify::fit::profile(settings)?;
    if let Some(dir) = &settings.out {
        let h5 = dir.join(kick_store::identify::fit::IDENTIFIABILITY_FILE);
        report.written.extend(figures::identifiability(&h5, dir)?);
    }
    Ok(report)
}

/// `kick laws`: the comparisons and their file (kick-store), then the
/// figure drawn from the file.
pub fn laws(settings: &LawsSettings) -> Result<LawsReport, PaperError> {
    let figures = figure_paths(settings.out.as_ref(), "laws");
    check_figures(&figures)?;
    let mut report = kick_store::identify::laws::laws(settings)?;
    if let Some(dir) = &settings.out {
        report.written.extend(figures::laws(&dir.join(kick_store::identify::laws::LAWS_FILE), dir)?);
    }
    Ok(report)
}

fn figure_paths(dir: Option<&PathBuf>, name: &str) -> Vec<PathBuf> {
    dir.map_or(Vec::new(), |d| ["png", "svg"].iter().map(|e| d.join(format!("{name}.{e}"))).collect())
}

/// Refuse figure paths that would write over an input or a directory, as `--out` names them.
fn check_figures(paths: &[PathBuf]) -> Result<(), PaperError> {
    let targets: Vec<_> = paths.iter().map(|path| crate::output::Target::File { flag: "--out", path }).collect();
    Ok(crate::output::check_paths(&targets, &[])?)
}
