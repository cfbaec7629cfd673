//! `kick check`: the cross-model checks (kick-checks), one row per check.

use crate::output::{json, CliResult, Format};
use kick_checks::{run_all, CheckRow};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

/// Every check row: kick-checks' and the 3D model's (also used by `kick reproduce`).
pub fn rows() -> Vec<CheckRow> {
    let mut rows = run_all();
    // The 3D model's checks (kick-3d) in the same row shape.
    rows.extend(kick_3d::checks::checks());
    rows
}

pub fn run(args: Args) -> CliResult {
    let rows = rows();
    match args.format {
        Format::Json => println!("{}", json(&rows)?),
        Format::Text => print_text(&rows),
    }
    let failed = rows.iter().filter(|r| !r.passed).count();
    if failed == 0 {
        Ok(())
    } else {
        Err(format!("{failed} of {} cross-model checks failed", rows.len()))
    }
}

fn print_text(rows: &[CheckRow]) {
    println!(
        "{:<6} {:<10} {:>20} {:>20} {:>10} {:>10}  check",
        "result", "equation", "expected", "actual", "error", "tolerance"
    );
    for r in rows {
        println!(
            "{:<6} {:<10} {:>20.12e} {:>20.12e} {:>10.3e} {:>10.3e}  {}",
            if r.passed { "PASS" } else { "FAIL" },
            r.equation,
            r.expected,
            r.actual,
            r.error,
            r.tolerance,
            r.name
        );
    }
    let passed = rows.iter().filter(|r| r.passed).count();
    println!("{passed} of {} checks passed", rows.len());
}
