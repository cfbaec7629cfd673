//! Print the flight's validation rows and the free-kick deflections
//! (numbers for experiments/validation/NOTES.md):
//! `cargo run --release -p kick-flight --example validation_flight`

use kick_flight::validation::{
    ball_comparisons, drag_crisis_comparisons, drag_crisis_model, free_kicks, lift_plateau_bends, measured_flights, spin_decay_bends,
    FREE_KICK_DISTANCE, FREE_KICK_ELEVATION,
};
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    let m = read(&path)?;
    println!("{:?}", drag_crisis_model());
    for row in drag_crisis_comparisons(&m)?.iter().chain(&ball_comparisons(&m)?).chain(&measured_flights(&m)?) {
        println!("{row}\n    {}", row.note);
    }
    let kicks = free_kicks(&m, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE)?;
    println!(
        "\nfree kicks at {} deg, crossing x = {} m (launch: {} [{}], {} [{}])",
        kicks.launch_angle,
        kicks.distance,
        kicks.launch_speed.key,
        kicks.launch_speed.checked,
        kicks.launch_spin.key,
        kicks.launch_spin.checked
    );
    println!("speed_m/s spin_rev/s lateral_m circle_estimate_m height_m time_s");
    for k in &kicks.kicks {
        println!(
            "{:6.2} {:6.2} {:8.3} {:8.3} {:7.3} {:6.3}",
            k.speed,
            k.spin / std::f64::consts::TAU,
            k.lateral_offset,
            k.circle_estimate,
            k.height,
            k.time
        );
    }
    let tau = std::f64::consts::TAU;
    for (v, w) in [(25.0, 10.0 * tau), (27.5, 9.0 * tau), (24.0, 106.0)] {
        println!("\nfree kick {v} m/s, {w:.3} rad/s, {FREE_KICK_ELEVATION} deg: bend at {FREE_KICK_DISTANCE} m");
        for b in lift_plateau_bends(v, w, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE, &[0.29, 0.24, 0.20])? {
            println!("  C_L {:?} (launch {:.4}): {:.4} m, height {:.3} m", b.constant_lift, b.launch_lift, b.lateral_offset, b.height);
        }
        for b in spin_decay_bends(v, w, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE, &[0.9, 0.75, 0.5])? {
            println!("  spin kept {:.3} (k_M {:.5}): {:.4} m", b.kept_at_landing, b.spin_decay, b.lateral_offset);
        }
    }
    Ok(())
}
