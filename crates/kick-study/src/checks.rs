//! `kick check`: every cross-model check row, kick-checks' and the 3D model's.

use crate::printable::Printable;
pub use kick_core::check::CheckRow;
use kick_core::sig;
use serde::Serialize;
use std::fmt::Write as _;

/// The check rows (JSON: the list of rows).
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct CheckTable {
    pub rows: Vec<CheckRow>,
}

impl CheckTable {
    /// Rows that failed.
    pub fn failed(&self) -> usize {
        self.rows.iter().filter(|r| !r.passed).count()
    }
}

/// How every family of rows is scored: kick-checks' and the 3D model's.
pub fn scoring() -> Vec<kick_core::check::Scoring> {
    kick_checks::SCORING.iter().chain(&kick_3d::checks::SCORING).copied().collect()
}

/// Run every check: kick-checks' and the 3D model's, in the same row shape.
pub fn run_all() -> CheckTable {
    let mut rows = kick_checks::run_all();
    rows.extend(kick_3d::checks::checks());
    CheckTable { rows }
}

impl Printable for CheckTable {
    fn text(&self) -> String {
        let mut w = String::new();
        let _ = writeln!(
            w,
            "{:<6} {:<10} {:>12} {:>12} {:>12} {:>12}  check",
            "result", "equation", "expected", "actual", "error", "tolerance"
        );
        for r in &self.rows {
            let _ = writeln!(
                w,
                "{:<6} {:<10} {:>12} {:>12} {:>12} {:>12}  {}",
                if r.passed { "PASS" } else { "FAIL" },
                r.equation,
                sig(r.expected),
                sig(r.actual),
                sig(r.error),
                sig(r.tolerance),
                r.name
            );
        }
        let passed = self.rows.len() - self.failed();
        let _ = writeln!(w, "{passed} of {} checks passed", self.rows.len());
        w
    }
}
