//! Print the flight's validation rows and the free-kick deflections
//! (numbers for experiments/validation/NOTES.md):
//! `cargo run --release -p kick-flight --example validation_flight`

use kick_core::measurements::{Measurements, MEASUREMENTS_FILE};
use kick_flight::validation::{
    ball_comparisons, drag_crisis_comparisons, drag_crisis_model, free_kicks, FREE_KICK_DISTANCE, FREE_KICK_ELEVATION,
};
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    let m = Measurements::load(&path)?;
    println!("{:?}", drag_crisis_model());
    for row in drag_crisis_comparisons(&m)?.iter().chain(&ball_comparisons(&m)?) {
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
    Ok(())
}
