//! β across the FIFA rebound band (115–165 cm from 2 m at 0.8 bar), for
//! SOURCES.md: each rebound height solved for the shell's loss β by Brent's
//! method on `kick bounce --drop-height 2` (gravity on during contact, as in
//! the test). `cargo run -p kick-bounce --example fifa_band`.

use kick_bounce::{run, BounceSpec};
use kick_core::parameters::Value;

fn rebound(beta: f64) -> f64 {
    let mut spec = BounceSpec::default();
    spec.set("drop_height", Value::Number(2.0)).expect("declared");
    spec.set("shell_damping", Value::Number(beta)).expect("declared");
    run(&spec).expect("the drop bounces").rebound_height.expect("a drop gives a rebound")
}

fn main() {
    for h in [1.15, 1.20, 1.40, 1.65] {
        let root = kick_core::roots::brent(|beta| rebound(beta) - h, 10.0, 2.0e4, 1e-13, 200).expect("bracketed");
        println!("rebound {h} m: e = {:.4}, β = {:.10e} Pa s/m", (h / 2.0_f64).sqrt(), root.x);
    }
}
