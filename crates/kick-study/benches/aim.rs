//! Cost of one aim solve through the 3D kick (`kick aim --from kick`): foot
//! speed, contact offset and depth, and heading to a target by the post.
//!
//! `cargo bench -p kick-study --features bench --bench aim`

use criterion::{criterion_group, criterion_main, Criterion};
use kick_study::aim::{aim, AimFrom, AimRequest};
use std::hint::black_box;

fn aims(c: &mut Criterion) {
    let mut group = c.benchmark_group("aim");
    group.sample_size(10);
    let request = AimRequest { target: Some([25.0, -3.0, 1.5]), from: Some(AimFrom::Kick), ..AimRequest::default() };
    group.bench_function("from_kick_all_free", |b| b.iter(|| black_box(aim(black_box(&request)).expect("aims"))));
    group.finish();
}

criterion_group!(benches, aims);
criterion_main!(benches);
