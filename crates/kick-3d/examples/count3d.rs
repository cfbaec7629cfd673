//! Fixed work for instruction counting (repeatable on a shared machine):
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/count3d SOLVER N [RTOL]`
//! solves the first N kicks of the benchmark box sample (`kick_3d::models`)
//! with SOLVER (`accurate`, `full-state`, `auto`, or `1d-accurate` / `1d-auto`
//! on each kick's normal scenario) and prints the evaluations and wall time.
use kick_3d::models::{OffCenterBox, BENCH_SEED};
use kick_3d::{Accurate3d, Solver3d};
use kick_core::Solver;
use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let solver = args.get(1).map_or("accurate", |s| s.as_str());
    let n: u64 = args.get(2).map_or(100, |s| s.parse().expect("N"));
    let kicks = OffCenterBox::new(BENCH_SEED).kicks(n).expect("box kicks are valid");
    let started = std::time::Instant::now();
    let mut evaluations = 0;
    for k in &kicks {
        evaluations += match solver {
            "accurate" => match args.get(3) {
                Some(r) => Accurate3d::new(r.parse().expect("RTOL")).expect("rtol").solve(black_box(k)).expect("solves").evaluations,
                None => Accurate3d::default().solve(black_box(k)).expect("solves").evaluations,
            },
            "1d-accurate" => kick_compliant::Accurate::default().solve(&k.normal_scenario().expect("valid")).expect("solves").evaluations,
            "1d-auto" => kick_compliant::Auto::default().solve(&k.normal_scenario().expect("valid")).expect("solves").evaluations,
            name => Solver3d::from_name(name, 1e-6).expect("solver").solve(black_box(k)).expect("solves").evaluations,
        };
    }
    let seconds = started.elapsed().as_secs_f64();
    println!("{solver}: {n} kicks, {:.0} evaluations/kick, {:.1} µs/kick", evaluations as f64 / n as f64, seconds / n as f64 * 1e6);
}
