//! Print the 1D validation rows and the implied parameters (numbers for
//! experiments/validation/NOTES.md):
//! `cargo run --release -p kick-identify --example validation_identify`

use kick_core::Scenario;
use kick_identify::validation::{contact_comparisons, implied_parameter_study};
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    let m = read(&path)?;
    println!("== Table 1 baseline");
    for row in contact_comparisons(&m, &Scenario::baseline())? {
        println!("{row}\n    {}", row.note);
    }
    println!("\n== implied parameters (targets: contact time, ball speed, peak force)");
    let study = implied_parameter_study(&m)?;
    for i in &study {
        println!(
            "law {} e {:?} v_f {} m/s: chi2 {:.4}, dof {}",
            i.law.name(),
            i.restitution,
            i.foot_speed,
            i.chi_square,
            i.degrees_of_freedom
        );
        for e in &i.estimates {
            println!(
                "    {:<10} {:.4e} {:<8} ± {:.3e} (stated σ), ± {:.3e} (scaled by √(χ²/dof))",
                e.parameter.name(),
                e.value,
                e.unit,
                e.sigma,
                e.sigma_scaled.unwrap_or(f64::NAN)
            );
        }
        println!("    correlation {:?}", i.correlation);
        for r in &i.residuals {
            println!("    {:<14} observed {:.4e} ± {:.3e}, model {:.4e}", r.label, r.observed, r.sigma, r.predicted);
        }
    }
    // The Hunt–Crossley setup at 22 m/s with k and m_f free, set beside everything again.
    let hc = &study[2];
    let mut s = Scenario::baseline().with_law(hc.law, hc.restitution)?;
    for e in &hc.estimates {
        if let kick_identify::FitParameter::Scenario(p) = e.parameter {
            s = s.with(p, e.value)?;
        }
    }
    println!("\n== at the implied Hunt-Crossley point (k, m_f above, v_f {} m/s)", hc.foot_speed);
    for row in contact_comparisons(&m, &s)? {
        println!("{row}");
    }
    Ok(())
}
