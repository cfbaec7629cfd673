use crate::output::{json, CliResult, Format};
use kick_compliant::table2::{columns, printed_columns, Table2File};
use kick_compliant::{Accurate, SeedRk4};
use kick_core::paper::{TABLE2, TABLE2_DECIMALS};
use kick_core::Solver;
use serde::Serialize;
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Scenario file with the rows' parameters
    #[arg(long, default_value = "experiments/table2.toml")]
    scenarios: PathBuf,
}

const COLUMNS: [&str; 5] = ["v_ball_out_m_s", "speed_ratio", "peak_force_N", "contact_time_ms", "max_compression_mm"];

#[derive(Serialize)]
struct Cell {
    paper: f64,
    seed_rk4: f64,
    accurate: f64,
    /// (seed − paper)/paper
    seed_vs_paper: f64,
    /// (accurate − seed)/seed
    accurate_vs_seed: f64,
}

#[derive(Serialize)]
struct Row {
    name: String,
    parameter: Option<String>,
    value: Option<f64>,
    columns: std::collections::BTreeMap<&'static str, Cell>,
    seed_matches_printed: bool,
}

pub fn load(path: &PathBuf) -> Result<Table2File, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    Table2File::parse(&text).map_err(|e| format!("{}: {e}", path.display()))
}

pub fn run(args: Args) -> CliResult {
    let file = load(&args.scenarios)?;
    let scenarios = file.scenarios().map_err(|e| e.to_string())?;
    let seed = SeedRk4::new(file.dt).map_err(|e| e.to_string())?;
    let accurate = Accurate::default();
    let mut rows = Vec::new();
    for ((name, scenario), (printed, spec)) in scenarios.iter().zip(TABLE2.iter().zip(&file.row)) {
        let s = seed.solve(scenario).map_err(|e| format!("{name}: {e}"))?;
        let a = accurate.solve(scenario).map_err(|e| format!("{name}: {e}"))?;
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
    match args.format {
        Format::Json => println!("{}", json(&rows)?),
        Format::Text => {
            for row in &rows {
                let changed = match (&row.parameter, row.value) {
                    (Some(p), Some(v)) => format!("{p} = {v}"),
                    _ => "baseline".into(),
                };
                println!(
                    "{} ({changed}); seed-rk4 prints as the paper: {}",
                    row.name,
                    if row.seed_matches_printed { "yes" } else { "NO" }
                );
                println!("  {:<20} {:>10} {:>12} {:>16} {:>11} {:>11}", "column", "paper", "seed-rk4", "accurate", "seed/paper-1", "acc/seed-1");
                for (column, decimals) in COLUMNS.iter().zip(TABLE2_DECIMALS) {
                    let c = &row.columns[column];
                    println!(
                        "  {:<20} {:>10.*} {:>12.*} {:>16.10} {:>+11.2e} {:>+11.2e}",
                        column, decimals as usize, c.paper, decimals as usize + 2, c.seed_rk4, c.accurate, c.seed_vs_paper, c.accurate_vs_seed
                    );
                }
            }
        }
    }
    if rows.iter().all(|r| r.seed_matches_printed) {
        Ok(())
    } else {
        Err("seed-rk4 does not reproduce every printed digit of Table 2".into())
    }
}
