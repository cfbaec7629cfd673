//! Restitution, contact time, peak force and compression of the default
//! shell ball against impact speed (and the FIFA drop), for SOURCES.md:
//! `cargo run -p kick-bounce --example speeds`.

use kick_bounce::{run, BounceSpec};
use kick_core::parameters::Value;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut drop = BounceSpec::default();
    drop.set("drop_height", Value::Number(2.0))?;
    let o = run(&drop)?;
    println!(
        "FIFA drop 2 m: e {:.4} rebound {:.3} m, t_c {:.2} ms, F {:.0} N, δ {:.1} mm",
        o.restitution,
        o.rebound_height.unwrap_or(f64::NAN),
        o.contact_time * 1e3,
        o.peak_force,
        o.max_compression * 1e3
    );
    println!("{:>6} {:>7} {:>8} {:>8} {:>8}", "V m/s", "e", "t_c ms", "F N", "δ mm");
    for v in [2.0, 4.0, 6.0, 8.0, 10.0, 15.0, 19.2, 20.0, 25.0, 30.0, 35.0] {
        let mut s = BounceSpec::default();
        s.set("speed", Value::Number(v))?;
        let o = run(&s)?;
        println!("{v:>6} {:>7.4} {:>8.3} {:>8.0} {:>8.1}", o.restitution, o.contact_time * 1e3, o.peak_force, o.max_compression * 1e3);
    }
    Ok(())
}
