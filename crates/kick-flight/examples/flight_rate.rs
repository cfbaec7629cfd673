//! Flights per second through `flight_many`: N free kicks (22–32 m/s,
//! 10–25° elevation, ±10° azimuth, sidespin and backspin up to 10 rev/s,
//! crossing the wall plane), on 1 and on 2 threads, best of 5 runs each.
//! Wall-clock rates count what the machine gave this process; on a shared
//! machine the CPU time (Linux: /proc/self/stat, 10 ms ticks) tells what
//! each thread did when it ran: flights per CPU second × threads is the rate
//! of that many unshared cores.
//!
//! `cargo run --release -p kick-flight --example flight_rate -- 200000`

use kick_flight::{flight_many, Column, FlightParameter, FlightSpec};
use std::time::Instant;

/// Deterministic uniform numbers in [0, 1) (64-bit LCG, top 53 bits).
struct Lcg(u64);
impl Lcg {
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// CPU seconds of this process (user + system, every thread), if readable.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command's closing parenthesis: utime and stime are the 12th and 13th.
    let rest = &stat[stat.rfind(')')? + 2..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = fields.get(11)?.parse::<f64>().ok()? + fields.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

fn main() {
    let n: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(200_000);
    let mut rng = Lcg(7);
    let (mut speed, mut angle, mut azimuth, mut spin) = (vec![], vec![], vec![], vec![]);
    for _ in 0..n {
        speed.push(rng.range(22.0, 32.0));
        angle.push(rng.range(10.0, 25.0));
        azimuth.push(rng.range(-10.0, 10.0));
        spin.extend([0.0, rng.range(-30.0, 0.0), rng.range(-63.0, 63.0)]);
    }
    let columns = [
        Column { parameter: FlightParameter::Speed, values: &speed },
        Column { parameter: FlightParameter::LaunchAngle, values: &angle },
        Column { parameter: FlightParameter::Azimuth, values: &azimuth },
        Column { parameter: FlightParameter::Spin, values: &spin },
    ];
    let base = FlightSpec { distance: Some(9.15), ..FlightSpec::default() };
    for threads in [1, 2] {
        let (mut best, mut best_cpu) = (f64::INFINITY, f64::INFINITY);
        let mut landed = 0;
        for _ in 0..5 {
            let (start, cpu) = (Instant::now(), cpu_seconds());
            let out = flight_many(&base, &columns, n, Some(threads)).expect("valid call");
            best = best.min(start.elapsed().as_secs_f64());
            if let (Some(a), Some(b)) = (cpu, cpu_seconds()) {
                best_cpu = best_cpu.min(b - a);
            }
            landed = out.iter().filter(|r| r.is_ok()).count();
        }
        println!(
            "{threads} thread(s): {n} flights in {best:.3} s wall (best of 5): {:.0} flights/s; \
             {best_cpu:.2} CPU s: {:.2} µs CPU per flight, {:.0} flights/s on {threads} unshared core(s); {landed} landed",
            n as f64 / best,
            best_cpu / n as f64 * 1e6,
            n as f64 / best_cpu * threads as f64
        );
    }
}
