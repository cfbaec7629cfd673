//! Fixed work for instruction counting (repeatable on a noisy machine):
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/count SOLVER SETTING N`
//! runs SOLVER on the eight Table 2 scenarios N times.
use kick_compliant::precision;
use kick_core::{models, Solver};
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let solver = precision::solver(&args[1], args[2].parse().unwrap()).unwrap();
    let n: usize = args[3].parse().unwrap();
    let scenarios: Vec<_> = models::table2().into_iter().map(|(_, s)| s).collect();
    for _ in 0..n {
        for s in &scenarios {
            std::hint::black_box(solver.solve(s).unwrap());
        }
    }
}
