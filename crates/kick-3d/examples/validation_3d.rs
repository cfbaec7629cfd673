//! Print the curve-kick validation rows and the offset–friction sweep
//! (numbers for experiments/validation/NOTES.md):
//! `cargo run --release -p kick-3d --example validation_3d`

use kick_3d::validation::curve_kick_comparisons;
use kick_core::Scenario;
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    let m = read(&path)?;
    let kicks = curve_kick_comparisons(&m, &Scenario::baseline())?;
    for row in &kicks.comparisons {
        println!("{row}\n    {}", row.note);
    }
    println!("\noffset_mm spin_mu0 spin_mu0.5 spin_mu1 (rad/s) speed_mu0 speed_mu0.5 speed_mu1 (m/s)");
    for i in 0..kicks.curves[0].len() {
        let p: Vec<_> = kicks.curves.iter().map(|c| c[i]).collect();
        println!(
            "{:6.1} {:9.3} {:9.3} {:9.3} {:8.3} {:8.3} {:8.3}",
            1e3 * p[0].offset,
            p[0].spin,
            p[1].spin,
            p[2].spin,
            p[0].speed,
            p[1].speed,
            p[2].speed
        );
    }
    for p in &kicks.largest {
        println!(
            "largest spin at mu {}: e = {:.2} mm, {:.2} rad/s ({:.2} rev/s), speed {:.2} m/s",
            p.friction,
            1e3 * p.offset,
            p.spin,
            p.spin / std::f64::consts::TAU,
            p.speed
        );
    }
    Ok(())
}
