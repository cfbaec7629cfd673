//! Table 2 of the paper: its scenarios, found from the printed numbers.
//!
//! The paper prints Table 2's observables but not the parameters. Each row
//! differs from the baseline in one parameter its name points to. We find it
//! in two steps:
//! 1. Brent's method on that parameter so that `seed-rk4` gives the printed
//!    exit speed v_b⁺ (the `root`);
//! 2. the root rounded to the fewest significant digits (1 to 6) at which
//!    `seed-rk4` reproduces all five printed columns (the `adopted` value).
//!
//! `experiments/table2.toml` keeps both with the residuals, written by
//! `kick fit table2 --write experiments/table2.toml`.

use crate::SeedRk4;
use kick_core::paper::{PrintedRow, TABLE2, TABLE2_DECIMALS};
use kick_core::{roots, KickError, Outcome, Parameter, Scenario, Solver};
use serde::{Deserialize, Serialize};

/// Which parameter each row changes, and where to look for it.
pub const ROW_PARAMETERS: [(Option<Parameter>, f64, f64); 8] = [
    (None, 0.0, 0.0),
    (Some(Parameter::FootMass), 0.3, 3.0),
    (Some(Parameter::FootMass), 3.0, 50.0),
    (Some(Parameter::Stiffness), 1e4, 4.2e5),
    (Some(Parameter::Stiffness), 4.2e5, 1e8),
    (Some(Parameter::Damping), 120.0, 5000.0),
    (Some(Parameter::BallSpeed), -20.0, 0.0),
    (Some(Parameter::BallSpeed), 0.0, 20.0),
];

/// One row of `experiments/table2.toml`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Table2Row {
    pub name: String,
    /// The changed parameter (absent for the baseline).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub parameter: Option<Parameter>,
    /// Value used by every command.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
    /// Brent root on the printed exit speed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub root: Option<f64>,
    /// seed-rk4 at `value` minus the printed number, per column:
    /// v_b⁺ (m/s), ratio, peak force (N), contact time (ms), compression (mm).
    pub residuals: [f64; 5],
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Table2File {
    pub name: String,
    pub description: String,
    pub solver: String,
    pub dt: f64,
    pub row: Vec<Table2Row>,
}

/// Why a Table 2 scenario file's text was refused: the parser's message and
/// where (1-based line and column), never the offending line itself, since
/// the file given as a scenario file may be any file (`table2 = "/etc/passwd"`).
/// The caller names the file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}{message}", .at.map(|(line, column)| format!("line {line}, column {column}: ")).unwrap_or_default())]
pub struct Table2ParseError {
    pub at: Option<(usize, usize)>,
    pub message: String,
}

impl Table2File {
    /// The file's text, each row's scenario built too: a row the model
    /// refuses is named by its number and name (the error used to name the
    /// parameter alone, whichever row gave it).
    pub fn parse(text: &str) -> Result<Self, Table2ParseError> {
        let file = Table2File::parse_text(text)?;
        for (i, row) in file.row.iter().enumerate() {
            if let Some((p, v)) = row.parameter.zip(row.value) {
                Scenario::baseline().with(p, v).map_err(|e| Table2ParseError {
                    at: None,
                    message: format!("[[row]] {} (`{}`), {} = {}: {e}", i + 1, row.name, p.name(), kick_core::short(v)),
                })?;
            }
        }
        Ok(file)
    }

    fn parse_text(text: &str) -> Result<Self, Table2ParseError> {
        toml::from_str(text).map_err(|e: toml::de::Error| {
            let at = e.span().map(|span| {
                let before = text.get(..span.start).unwrap_or(text);
                let line = before.matches('\n').count() + 1;
                let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
                (line, column)
            });
            Table2ParseError { at, message: e.message().trim().to_string() }
        })
    }

    /// The scenarios, in the paper's order.
    pub fn scenarios(&self) -> Result<Vec<(String, Scenario)>, KickError> {
        self.row
            .iter()
            .map(|row| {
                let scenario = match (row.parameter, row.value) {
                    (Some(p), Some(v)) => Scenario::baseline().with(p, v)?,
                    _ => Scenario::baseline(),
                };
                Ok((row.name.clone(), scenario))
            })
            .collect()
    }
}

/// The five printed columns of an outcome, in the table's units.
pub fn columns(outcome: &Outcome) -> [f64; 5] {
    [
        outcome.v_ball_out,
        // Table 2's rows all have v_f⁻ > 0: the ratio is defined.
        outcome.speed_ratio.unwrap_or(f64::NAN),
        outcome.peak_force,
        outcome.contact_time * 1e3,
        outcome.max_compression * 1e3,
    ]
}

pub fn printed_columns(row: &PrintedRow) -> [f64; 5] {
    [row.v_ball_out, row.speed_ratio, row.peak_force, row.contact_time_ms, row.max_compression_mm]
}

/// True when every column prints as the paper printed it.
pub fn matches_printed(outcome: &Outcome, row: &PrintedRow) -> bool {
    columns(outcome)
        .iter()
        .zip(printed_columns(row))
        .zip(TABLE2_DECIMALS)
        .all(|((&value, printed), decimals)| format!("{value:.*}", decimals as usize) == format!("{printed:.*}", decimals as usize))
}

/// Fit all rows with the seed method at the paper's step.
pub fn fit() -> Result<Table2File, KickError> {
    let seed = SeedRk4::default();
    let mut rows = Vec::new();
    for (printed, (parameter, low, high)) in TABLE2.iter().zip(ROW_PARAMETERS) {
        let (root, value) = match parameter {
            None => (None, None),
            Some(p) => {
                let solve = |x: f64| -> f64 {
                    Scenario::baseline()
                        .with(p, x)
                        .and_then(|s| seed.solve(&s))
                        .map(|o| o.v_ball_out - printed.v_ball_out)
                        .unwrap_or(f64::NAN)
                };
                let root = roots::brent(solve, low, high, 1e-12 * high.abs().max(low.abs()), 200)
                    .ok_or(KickError::Integration { time: 0.0, reason: format!("no root for `{}` in [{low}, {high}]", printed.name) })?
                    .x;
                let adopted = (1..=6)
                    .map(|digits| round_significant(root, digits))
                    .find(|&x| {
                        Scenario::baseline().with(p, x).and_then(|s| seed.solve(&s)).map(|o| matches_printed(&o, printed)).unwrap_or(false)
                    })
                    .unwrap_or(root);
                (Some(root), Some(adopted))
            }
        };
        let scenario = match (parameter, value) {
            (Some(p), Some(v)) => Scenario::baseline().with(p, v)?,
            _ => Scenario::baseline(),
        };
        let outcome = seed.solve(&scenario)?;
        let mut residuals = [0.0; 5];
        for ((r, c), p) in residuals.iter_mut().zip(columns(&outcome)).zip(printed_columns(printed)) {
            *r = c - p;
        }
        rows.push(Table2Row { name: printed.name.to_string(), parameter, value, root, residuals });
    }
    Ok(Table2File {
        name: "table2".into(),
        description: "Table 2 of the paper: baseline plus one changed parameter per row, \
                      found from the printed numbers (kick fit table2)"
            .into(),
        solver: "seed-rk4".into(),
        dt: SeedRk4::default().step,
        row: rows,
    })
}

/// x rounded to `digits` significant decimal digits.
pub fn round_significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    // Through decimal text, so 1.8e6 stays 1.8e6 and not 1799999.9999999998.
    format!("{x:.*e}", (digits.max(1) - 1) as usize).parse().unwrap_or(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A refused file says where and which key, not the line's text.
    #[test]
    fn a_refused_file_names_the_line_and_the_key() {
        let e = Table2File::parse("name = \"t\"\nsecret_key = 1\n").unwrap_err();
        let Table2ParseError { at: Some((2, 1)), message } = &e else { panic!("{e:?}") };
        assert!(message.contains("secret_key"), "{message}");
        assert!(e.to_string().starts_with("line 2, column 1: "), "{e}");
        assert!(!e.to_string().contains("= 1"), "{e}");
    }

    /// A row the model refuses is named by its number and name, with the
    /// parameter and value it gives.
    #[test]
    fn a_refused_row_is_named() {
        let head = "name = \"t\"\ndescription = \"d\"\nsolver = \"seed-rk4\"\ndt = 5e-6\n";
        let row = |name: &str, parameter: &str, value: &str| {
            format!("[[row]]\nname = \"{name}\"\nparameter = \"{parameter}\"\nvalue = {value}\nresiduals = [0.0, 0.0, 0.0, 0.0, 0.0]\n")
        };
        let fine = format!("{head}{}", row("Light", "foot_mass", "0.6"));
        assert_eq!(Table2File::parse(&fine).unwrap().scenarios().unwrap().len(), 1);
        for (bad, named) in [("ball_speed", "30"), ("foot_mass", "nan")] {
            let text = format!("{head}{}{}", row("Light", "foot_mass", "0.6"), row("Odd", bad, named));
            let e = Table2File::parse(&text).unwrap_err().to_string();
            assert!(e.starts_with(&format!("[[row]] 2 (`Odd`), {bad} = ")), "{e}");
        }
    }
}
