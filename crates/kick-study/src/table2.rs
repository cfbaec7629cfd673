//! `kick table2`: Table 2 side by side, the paper's printed values, seed-rk4
//! and accurate, from a Table 2 scenario file.

use crate::error::StudyError;
use crate::printable::Printable;
use kick_compliant::table2::{columns, printed_columns, Table2File};
use kick_compliant::{Accurate, SeedRk4};
pub use kick_core::paper::{TABLE2, TABLE2_DECIMALS};
use kick_core::{sig, Solver};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::Path;

const COLUMNS: [&str; 5] = ["v_ball_out_m_s", "speed_ratio", "peak_force_N", "contact_time_ms", "max_compression_mm"];

#[derive(Debug, Clone, Serialize)]
pub struct Cell {
    pub paper: f64,
    pub seed_rk4: f64,
    pub accurate: f64,
    /// (seed − paper)/paper
    pub seed_vs_paper: f64,
    /// (accurate − seed)/seed
    pub accurate_vs_seed: f64,
}

#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub name: String,
    pub parameter: Option<String>,
    pub value: Option<f64>,
    pub columns: std::collections::BTreeMap<&'static str, Cell>,
    pub seed_matches_printed: bool,
}

/// Every row of Table 2 (JSON: the list of rows).
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct Table2Comparison {
    pub rows: Vec<Row>,
}

impl Table2Comparison {
    /// True when seed-rk4 reproduces every printed digit.
    pub fn all_match(&self) -> bool {
        self.rows.iter().all(|r| r.seed_matches_printed)
    }
}

/// Where the commands look for Table 2's scenarios by default.
pub const DEFAULT_PATH: &str = "experiments/table2.toml";

/// `experiments/table2.toml` as compiled into the binary, so that `kick
/// table2`, `kick laws` and `kick fit table2` work outside the repository.
pub const BUILT_IN: &str = include_str!("../../../experiments/table2.toml");

/// The text of a Table 2 scenario file: the file on disk when it exists,
/// else, for the default path only, the built-in copy.
pub fn read_text(path: &Path) -> Result<String, StudyError> {
    if path == Path::new(DEFAULT_PATH) && std::fs::symlink_metadata(path).is_err() {
        return Ok(BUILT_IN.to_string());
    }
    kick_core::input::read_text(path, kick_core::input::MAX_TEXT_BYTES)
        .map_err(|e| StudyError::File { path: path.to_path_buf(), message: e.to_string() })
}

/// Read a Table 2 scenario file (`kick fit table2 --write`); see [`read_text`].
pub fn load(path: &Path) -> Result<Table2File, StudyError> {
    let text = read_text(path)?;
    Table2File::parse(&text).map_err(|e| StudyError::File { path: path.to_path_buf(), message: e.to_string() })
}

/// Table 2 from the scenario file `scenarios`: printed, seed-rk4 and accurate.
pub fn compare(scenarios: &Path) -> Result<Table2Comparison, StudyError> {
    let path = scenarios;
    let file = load(scenarios)?;
    let scenarios = file.scenarios()?;
    let seed = SeedRk4::new(file.dt)?;
    let accurate = Accurate::default();
    let mut rows: Vec<Row> = Vec::new();
    for ((name, scenario), spec) in scenarios.iter().zip(&file.row) {
        // Set against the paper's row of the same name (by position a second
        // "Baseline" was read against "Light effective foot" and said not to
        // print as the paper).
        let refuse = |message: String| StudyError::File { path: path.to_path_buf(), message };
        let printed = TABLE2.iter().find(|r| r.name == name.as_str()).ok_or_else(|| {
            let names: Vec<&str> = TABLE2.iter().map(|r| r.name).collect();
            refuse(format!("row `{name}` is not a row of the paper's Table 2 (one of: {})", names.join(", ")))
        })?;
        if rows.iter().any(|r| &r.name == name) {
            return Err(refuse(format!("row `{name}` is given twice")));
        }
        let s = seed.solve(scenario).map_err(|source| StudyError::Row { name: name.clone(), source })?;
        let a = accurate.solve(scenario).map_err(|source| StudyError::Row { name: name.clone(), source })?;
        let mut cells = std::collections::BTreeMap::new();
        for (i, column) in COLUMNS.iter().enumerate() {
            let (p, sv, av) = (printed_columns(printed)[i], columns(&s)[i], columns(&a)[i]);
            cells.insert(
                *column,
                Cell { paper: p, seed_rk4: sv, accurate: av, seed_vs_paper: (sv - p) / p, accurate_vs_seed: (av - sv) / sv },
            );
        }
        rows.push(Row {
            name: name.clone(),
            parameter: spec.parameter.map(|p| p.name().to_string()),
            value: spec.value,
            seed_matches_printed: kick_compliant::table2::matches_printed(&s, printed),
            columns: cells,
        });
    }
    Ok(Table2Comparison { rows })
}

impl Printable for Table2Comparison {
    fn text(&self) -> String {
        let mut w = String::new();
        for row in &self.rows {
            let changed = match (&row.parameter, row.value) {
                (Some(p), Some(v)) => format!("{p} = {}", sig(v)),
                _ => "baseline".into(),
            };
            let _ = writeln!(
                w,
                "{} ({changed}); seed-rk4 prints as the paper: {}",
                row.name,
                if row.seed_matches_printed { "yes" } else { "NO" }
            );
            let _ = writeln!(
                w,
                "  {:<20} {:>10} {:>12} {:>12} {:>12} {:>12}",
                "column", "paper", "seed-rk4", "accurate", "seed/paper-1", "acc/seed-1"
            );
            for (column, decimals) in COLUMNS.iter().zip(TABLE2_DECIMALS) {
                let c = &row.columns[column];
                let _ = writeln!(
                    w,
                    // The paper's column as printed (its digits are the data); ours in the one text form.
                    "  {:<20} {:>10.*} {:>12} {:>12} {:>12} {:>12}",
                    column,
                    decimals as usize,
                    c.paper,
                    sig(c.seed_rk4),
                    sig(c.accurate),
                    sig(c.seed_vs_paper),
                    sig(c.accurate_vs_seed)
                );
            }
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows are set against the paper's row of their name, not their place:
    /// the file's rows reversed still print as the paper; a second
    /// "Baseline" (it was read against "Light effective foot" and said NO)
    /// and a name the paper has not are refused, naming the file.
    #[test]
    fn rows_are_compared_by_name() {
        let dir = std::env::temp_dir().join(format!("kick-table2-by-name-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (head, rows) = BUILT_IN.split_once("[[row]]").unwrap();
        let rows: Vec<String> = rows.split("[[row]]").map(|r| format!("[[row]]{r}")).collect();
        let write = |name: &str, text: String| {
            let path = dir.join(name);
            std::fs::write(&path, text).unwrap();
            path
        };
        let reversed = write("reversed.toml", format!("{head}{}", rows.iter().rev().cloned().collect::<String>()));
        let table = compare(&reversed).unwrap();
        assert!(table.all_match());
        assert_eq!(table.rows[0].name, TABLE2[7].name);
        let twice = write("twice.toml", format!("{head}{}{}", rows[0], rows[0]));
        let e = compare(&twice).unwrap_err().to_string();
        assert!(e.contains("twice.toml") && e.contains("row `Baseline` is given twice"), "{e}");
        let odd = write("odd.toml", format!("{head}{}", rows[1].replace("Light effective foot", "Featherweight")));
        let e = compare(&odd).unwrap_err().to_string();
        assert!(e.contains("row `Featherweight` is not a row of the paper's Table 2"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
