//! Cost of one flight, and of one aim solve.
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
    group.bench_function("free_kick_constant_coefficients", |b| b.iter(|| black_box(solve(black_box(&constant)).expect("lands"))));
    group.bench_function("free_kick_history_100", |b| {
        b.iter(|| black_box(history(black_box(&free_kick), Sampling::Samples(100)).expect("lands")))
    });
    // 1000 model free kicks at spread speeds through `flight_many` on 2 threads:
    // time per call / 1000 is the cost of a flight at that parallelism.
    let (base, speeds) = models::free_kick_speeds(1000);
    let columns = [kick_flight::Column { parameter: kick_flight::FlightParameter::Speed, values: &speeds }];
    group.bench_function("flight_many_1000_free_kicks_2_threads", |b| {
        b.iter(|| black_box(kick_flight::flight_many(&base, &columns, 1000, Some(2)).expect("valid")))
    });
    group.finish();
}

/// One aim solve (the "well under a second"): the default free
/// parameters (speed, elevation, azimuth) to a target by the far post, with
/// sidespin held; and azimuth and sidespin alone (two in two).
fn aims(c: &mut Criterion) {
    use kick_flight::aim::{aim_launch, LaunchFree, Wall};
    let mut group = c.benchmark_group("aim");
    group.sample_size(20);
    let curl = kick_flight::FlightSpec { spin: Some([0.0, 0.0, 50.0]), ..kick_flight::FlightSpec::default() };
    group.bench_function("launch_default_free", |b| {
        b.iter(|| black_box(aim_launch([25.0, 2.8, 2.0], Wall::default(), &LaunchFree::DEFAULT, &curl).expect("aims")))
    });
    let held = kick_flight::FlightSpec { speed: Some(27.0), launch_angle: Some(18.0), ..kick_flight::FlightSpec::default() };
    group.bench_function("launch_azimuth_and_sidespin", |b| {
        b.iter(|| black_box(aim_launch([25.0, 3.0, 1.9], Wall::default(), &[LaunchFree::Azimuth, LaunchFree::SpinZ], &held).expect("aims")))
    });
    group.finish();
}

criterion_group!(benches, flights, aims);
criterion_main!(benches);
