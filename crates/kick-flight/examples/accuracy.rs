//! Worst relative difference between the default solve and one at a 100×
//! tighter tolerance over many random kicks (what `tests/flight/closed_forms.rs`
//! samples 64 of), and the mean cost.
//!
//! `cargo run --release -p kick-flight --example accuracy -- 20000`

use kick_flight::{solve, FlightSpec};

/// Deterministic uniform numbers in [0, 1) (64-bit LCG, top 53 bits).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

fn main() {
    let count: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(10_000);
    let mut rng = Lcg(2024);
    let (mut worst, mut worst_case) = (0.0_f64, String::new());
    let (mut steps, mut evaluations) = (0u64, 0u64);
    for _ in 0..count {
        let spec = FlightSpec {
            azimuth: Some(rng.range(-40.0, 40.0)),
            spin: Some([rng.range(-80.0, 80.0), rng.range(-80.0, 80.0), rng.range(-80.0, 80.0)]),
            spin_decay: if rng.next() < 0.5 { None } else { Some(rng.range(0.0, 2.0)) },
            distance: Some(rng.range(1.0, 40.0)),
            ..FlightSpec::from_exit_speed(rng.range(3.0, 40.0), rng.range(3.0, 85.0))
        };
        let flight = spec.build().expect("valid");
        let a = solve(&flight).expect("lands");
        let b = solve(&flight.with_relative_tolerance(flight.relative_tolerance() / 100.0).unwrap()).expect("lands");
        steps += a.steps;
        evaluations += a.evaluations;
        let rel = |x: f64, y: f64| ((x - y) / y).abs();
        // The flight's size: its range, or its apex height for a steep kick that lands near its start.
        let size = b.landing_point[0].hypot(b.landing_point[1]).max(b.apex_height);
        let mut d = ((a.landing_point[0] - b.landing_point[0]).hypot(a.landing_point[1] - b.landing_point[1]) / size)
            .max(rel(a.flight_time, b.flight_time))
            .max(rel(a.apex_height, b.apex_height));
        match (a.crossing, b.crossing) {
            (Some(x), Some(y)) => {
                // The crossing point (d, y, z): its error relative to its distance from the origin.
                let size = (y.distance.powi(2) + y.lateral_offset.powi(2) + y.height.powi(2)).sqrt();
                d = d.max(rel(x.time, y.time)).max((x.lateral_offset - y.lateral_offset).hypot(x.height - y.height) / size)
            }
            (None, None) => {}
            _ => d = f64::INFINITY,
        }
        if d > worst {
            worst = d;
            worst_case = format!("{spec:?}");
        }
    }
    println!(
        "{count} kicks: worst relative difference {worst:.2e}; mean {:.1} steps, {:.1} evaluations",
        steps as f64 / count as f64,
        evaluations as f64 / count as f64
    );
    println!("worst: {worst_case}");
}
