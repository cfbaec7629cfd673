//! Fixed work for instruction counting (repeatable on a noisy machine):
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/flight_count N`
//! solves the model free kick N times; the difference of two N over the
//! difference of N is the cost of one flight.
use kick_flight::{models, solve};
fn main() {
    let n: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(1);
    let flight = models::free_kick();
    for _ in 0..n {
        std::hint::black_box(solve(std::hint::black_box(&flight)).expect("lands"));
    }
}
