//! The force history of one off-center kick (`3d_force_history.h5`, the
//! history layout): [`kick_study::numbers_3d::history_spec`] solved on the
//! accurate path into kick-store's history writer.

use crate::history::HistoryRequest;
use crate::StoreError;
use kick_core::Spacing;
use kick_study::simulate::Simulation3d;
use std::path::Path;

/// The file, below the results directory.
pub const FILE: &str = "3d_force_history.h5";

/// Solve the force-history kick and write `out/3d_force_history.h5` with
/// `samples` rows uniform in time; the run (its summary and the file).
pub fn run(out: &Path, samples: usize) -> Result<Simulation3d, StoreError> {
    let request = HistoryRequest { path: out.join(FILE), spacing: Spacing::Count(samples), open: crate::history::open };
    Ok(kick_study::simulate::simulate3d(&kick_study::numbers_3d::history_spec(), "accurate", None, Some(&request), None)?)
}
