//! Cost per scenario of every 1D solver on the shared test models.
//!
//! Full run: `cargo bench -p kick-compliant --features bench --bench solvers`
//! Short CI variant: `cargo bench -p kick-compliant --features bench --bench solvers -- --quick`
//! Ratios are only meaningful between benches of one run (the machine is shared).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use kick_compliant::SolverChoice;
use kick_core::{models, Solver};
use std::hint::black_box;

fn table2(c: &mut Criterion) {
    let scenarios: Vec<_> = models::table2().into_iter().map(|(_, s)| s).collect();
    let mut group = c.benchmark_group("table2_per_8_scenarios");
    for name in ["seed-rk4", "rk4-events", "accurate", "dopri5", "reduced", "reduced-return", "series", "auto"] {
        let solver = SolverChoice::from_name(name, 5e-6).expect("known solver");
        group.bench_with_input(BenchmarkId::from_parameter(name), &scenarios, |b, scenarios| {
            b.iter(|| {
                for s in scenarios {
                    black_box(solver.solve(black_box(s)).expect("table 2 solves"));
                }
            })
        });
    }
    group.finish();
}

fn closed_forms(c: &mut Criterion) {
    let scenarios: Vec<_> = models::elastic().into_iter().chain(models::linear()).map(|(_, s)| s).collect();
    let mut group = c.benchmark_group("closed_form_models_per_11_scenarios");
    for name in ["closed-form", "series", "reduced", "accurate"] {
        let solver = SolverChoice::from_name(name, 5e-6).expect("known solver");
        group.bench_with_input(BenchmarkId::from_parameter(name), &scenarios, |b, scenarios| {
            b.iter(|| {
                for s in scenarios {
                    black_box(solver.solve(black_box(s)).expect("model solves"));
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, table2, closed_forms);
criterion_main!(benches);
