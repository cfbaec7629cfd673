//! Print the 1D validation rows and the implied parameters (numbers for
//! experiments/validation/NOTES.md):
//! `cargo run --release -p kick-identify --example validation`

use kick_core::measurements::{Comparison, Measurements, MEASUREMENTS_FILE};
use kick_core::Scenario;
use kick_identify::validation::{contact_comparisons, implied_parameter_study};
use std::path::Path;

fn print(rows: &[Comparison]) {
    for r in rows {
        let (lo, hi) = (r.measured.low.unwrap_or(f64::NAN), r.measured.high.unwrap_or(f64::NAN));
        println!(
            "{:<58} [{:.4e}, {:.4e}] {:<5} model {:.4e}  ratio {:>7.3}  outside {:+.3e}  ({}; {})",
            r.quantity,
            lo,
            hi,
            r.measured.unit,
            r.model,
            r.ratio.unwrap_or(f64::NAN),
            r.outside.unwrap_or(f64::NAN),
            r.measured.key,
            r.measured.checked
        );
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    let m = Measurements::load(&path)?;
    println!("== Table 1 baseline");
    print(&contact_comparisons(&m, &Scenario::baseline())?);
    println!("\n== implied parameters (targets: contact time, ball speed, peak force)");
    for i in implied_parameter_study(&m)? {
        println!(
            "law {:?} e {:?} v_f {} m/s: chi2 {:.4} dof {}",
            i.law, i.restitution, i.foot_speed, i.chi_square, i.degrees_of_freedom
        );
        for e in &i.estimates {
            println!(
                "    {:<10} {:.4e} {:<8} ± {:.3e} (stated σ)  ± {:.3e} (scaled)",
                e.parameter.name(),
                e.value,
                e.unit,
                e.sigma,
                e.sigma_scaled.unwrap_or(f64::NAN)
            );
        }
        println!("    correlation {:?}", i.correlation);
        for r in &i.residuals {
            println!("    {:<14} observed {:.4e} ± {:.3e}  model {:.4e}", r.label, r.observed, r.sigma, r.predicted);
        }
    }
    Ok(())
}
