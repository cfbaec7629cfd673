//! Identification and contact laws as a research tool: `kick fit` and `kick
//! laws` as library functions, their result files ([`files`]), figures
//! ([`figures`], drawn from those files) and report pages ([`report`]).

pub mod figures;
pub use kick_store::identify::files;
pub mod fit;
pub mod laws;
pub mod report;

pub use fit::{data, other_law_name, profile, synthesize, table2, DataFit, ProfileReport, ProfileSettings, Synthesized, Table2Fits};
pub use laws::{laws, LawsReport, LawsSettings};
