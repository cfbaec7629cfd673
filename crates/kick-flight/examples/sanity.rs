//! Sanity numbers (reported, not asserted): a plain kick and free kicks with sidespin.
//!
//! `cargo run --release -p kick-flight --example sanity`

use kick_flight::{solve, FlightSpec};
use std::f64::consts::TAU;

fn main() {
    let plain = FlightSpec::from_exit_speed(25.0, 20.0);
    let vacuum = FlightSpec { drag_coefficient: Some(0.0), lift_coefficient: Some(0.0), ..plain };
    for (name, spec) in [("25 m/s, 20°, no spin", plain), ("same in vacuum", vacuum)] {
        let o = solve(&spec.build().expect("valid")).expect("lands");
        let [vx, vy, vz] = o.landing_velocity;
        println!(
            "{name}: flight time {:.3} s, range {:.2} m, apex {:.2} m (centre), landing speed {:.2} m/s at {:.1}°",
            o.flight_time,
            o.landing_point[0],
            o.apex_height,
            (vx * vx + vy * vy + vz * vz).sqrt(),
            (-vz).atan2(vx.hypot(vy)).to_degrees()
        );
    }
    println!("\nFree kicks at 15° elevation, sidespin ω_z; lateral deflection where the ball crosses x = 25 m:");
    println!("speed m/s  spin rev/s  S0     deflection m  height m  time s   [with C_D of Goff & Carré Eq. 4 at launch S]");
    for speed in [25.0, 27.5, 30.0] {
        for revs in [8.0, 9.0, 10.0] {
            let spec = FlightSpec { spin: Some([0.0, 0.0, revs * TAU]), distance: Some(25.0), ..FlightSpec::from_exit_speed(speed, 15.0) };
            let s0 = 0.11 * revs * TAU / speed;
            let spin_drag = FlightSpec { drag_coefficient: Some(0.4127 * s0.powf(0.3056)), ..spec };
            let fly = |s: FlightSpec| solve(&s.build().expect("valid")).expect("lands");
            let (a, b) = (fly(spec), fly(spin_drag));
            let other = match b.crossing {
                Some(d) => format!("{:.2} m, {:.2} m high", d.lateral_offset, d.height),
                None => format!("lands short at x = {:.2} m, y = {:.2} m", b.landing_point[0], b.landing_point[1]),
            };
            match a.crossing {
                Some(c) => {
                    println!("{speed:9.1}  {revs:10.0}  {s0:.3}  {:12.2}  {:8.2}  {:.3}    [{other}]", c.lateral_offset, c.height, c.time)
                }
                None => println!("{speed:9.1}  {revs:10.0}  {s0:.3}  lands short at x = {:.2} m    [{other}]", a.landing_point[0]),
            }
        }
    }
}
