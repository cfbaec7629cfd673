//! Cost of one flight.
//!
//! `cargo bench -p kick-flight --features bench --bench flight`
//! Ratios are meaningful only between benches of one run (the machine is shared).

use criterion::{criterion_group, criterion_main, Criterion};
use kick_flight::{history, models, solve, Sampling};
use std::hint::black_box;

fn flights(c: &mut Criterion) {
    let free_kick = models::free_kick();
    let plain = models::plain_kick();
    let constant = kick_flight::FlightSpec {
        drag_coefficient: Some(0.25),
        lift_coefficient: Some(0.25),
        spin: Some([0.0, 0.0, 56.5]),
        ..kick_flight::FlightSpec::from_exit_speed(27.0, 16.0)
    }
    .build()
    .expect("valid");
    let mut group = c.benchmark_group("flight");
    group.bench_function("free_kick", |b| b.iter(|| black_box(solve(black_box(&free_kick)).expect("lands"))));
    group.bench_function("plain_25ms_20deg", |b| b.iter(|| black_box(solve(black_box(&plain)).expect("lands"))));
    group.bench_function("free_kick_constant_coefficients", |b| {
        b.iter(|| black_box(solve(black_box(&constant)).expect("lands")))
    });
    group.bench_function("free_kick_history_100", |b| {
        b.iter(|| black_box(history(black_box(&free_kick), Sampling::Samples(100)).expect("lands")))
    });
    group.finish();
}

criterion_group!(benches, flights);
criterion_main!(benches);
