//! Cost per off-center kick of the 3D paths and of the 1D contact along the
//! same kick's normal, over one seeded sample of the box
//! (`kick_3d::models::OffCenterBox`, seed `BENCH_SEED`), in one run, so the
//! 3D/1D ratio comes from one binary on one machine load.
//!
//! Full run: `cargo bench -p kick-3d --features bench --bench solve3d`
//! Short variant: `cargo bench -p kick-3d --features bench --bench solve3d -- --quick`
//! Criterion reports time per iteration (all kicks) and kicks per second.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use kick_3d::models::{OffCenterBox, BENCH_SEED};
use kick_3d::{Accurate3d, FullState3d, Solver3d};
use kick_core::Solver;
use std::hint::black_box;

/// Kicks in the sample.
const KICKS: u64 = 50;

fn off_center_box(c: &mut Criterion) {
    let kicks = OffCenterBox::new(BENCH_SEED).kicks(KICKS).expect("box kicks are valid");
    let normals: Vec<_> = kicks.iter().map(|k| k.normal_scenario().expect("valid")).collect();
    let mut group = c.benchmark_group("off_center_box_50_kicks");
    group.throughput(Throughput::Elements(KICKS));
    group.bench_function(BenchmarkId::from_parameter("3d accurate"), |b| {
        let solver = Accurate3d::default();
        b.iter(|| {
            for k in &kicks {
                black_box(solver.solve(black_box(k)).expect("solves"));
            }
        })
    });
    group.bench_function(BenchmarkId::from_parameter("3d auto"), |b| {
        b.iter(|| {
            for k in &kicks {
                black_box(Solver3d::Auto.solve(black_box(k)).expect("solves"));
            }
        })
    });
    group.bench_function(BenchmarkId::from_parameter("1d accurate"), |b| {
        let solver = kick_compliant::Accurate::default();
        b.iter(|| {
            for s in &normals {
                black_box(solver.solve(black_box(s)).expect("solves"));
            }
        })
    });
    group.bench_function(BenchmarkId::from_parameter("1d auto"), |b| {
        let solver = kick_compliant::Auto::default();
        b.iter(|| {
            for s in &normals {
                black_box(solver.solve(black_box(s)).expect("solves"));
            }
        })
    });
    group.sample_size(10);
    group.bench_function(BenchmarkId::from_parameter("3d full-state (reference)"), |b| {
        let solver = FullState3d::default();
        b.iter(|| {
            for k in &kicks {
                black_box(solver.solve(black_box(k)).expect("solves"));
            }
        })
    });
    group.finish();
}

/// The shell ball at 5 cm offset, μ = 0.5 (Table 1's foot, 22 m/s): the
/// point contact against the patch on the knife-edge face and on a 15 cm
/// cap (`kick_3d::patch`), and the patch with rigid grip, one kick per
/// iteration, one binary.
fn patch_contact(c: &mut Criterion) {
    let base = kick_core::Scenario::baseline().with_law(kick_core::LawKind::Shell, None).expect("shell");
    let spec = kick_3d::Kick3dSpec { offset: Some(0.05), ..kick_3d::Kick3dSpec::default() };
    let cases = [
        ("shell point contact", spec),
        ("shell patch, knife edge", kick_3d::Kick3dSpec { patch_contact: Some(true), ..spec }),
        (
            "shell patch, 15 cm cap",
            kick_3d::Kick3dSpec { patch_contact: Some(true), instep_radius: Some(0.15), face_yaw_deg: Some(0.0), ..spec },
        ),
        // Rigid grip (k_t = ∞, a constraint) under the patch: μ = 0.5 slips, grips and slips; μ = ∞ grips throughout.
        (
            "shell patch, knife edge, rigid grip",
            kick_3d::Kick3dSpec { patch_contact: Some(true), tangential_stiffness: Some(f64::INFINITY), ..spec },
        ),
        (
            "shell patch, knife edge, rigid grip, mu inf",
            kick_3d::Kick3dSpec {
                patch_contact: Some(true),
                tangential_stiffness: Some(f64::INFINITY),
                friction: Some(f64::INFINITY),
                ..spec
            },
        ),
        (
            "shell patch, 15 cm cap, rigid grip",
            kick_3d::Kick3dSpec {
                patch_contact: Some(true),
                instep_radius: Some(0.15),
                face_yaw_deg: Some(0.0),
                tangential_stiffness: Some(f64::INFINITY),
                ..spec
            },
        ),
    ];
    let mut group = c.benchmark_group("patch_contact_5cm");
    group.throughput(Throughput::Elements(1));
    let solver = Accurate3d::default();
    for (name, spec) in cases {
        let kick = kick_3d::Kick3d::new(base, &spec).expect("valid");
        group.bench_function(BenchmarkId::from_parameter(name), |b| b.iter(|| black_box(solver.solve(black_box(&kick)).expect("solves"))));
    }
    group.finish();
}

/// One rapier scene step (`--solver rapier`): the baseline kick at the
/// default dt (1e-6 s, about 5,300 steps), throughput in steps, so the
/// scene's step budget (`kick_3d::scene::MAX_SCENE_STEPS`) can be stated in
/// seconds.
fn rapier_step(c: &mut Criterion) {
    let kick = kick_3d::Kick3d::baseline();
    let scene = kick_3d::scene::Scene::new(kick_3d::DEFAULT_SCENE_STEP).expect("valid step");
    let steps = scene.solve(&kick).expect("solves").evaluations;
    let mut group = c.benchmark_group("rapier_scene");
    group.throughput(Throughput::Elements(steps));
    group.sample_size(10);
    group.bench_function(BenchmarkId::from_parameter("baseline kick, steps"), |b| {
        b.iter(|| black_box(scene.solve(black_box(&kick)).expect("solves")))
    });
    group.finish();
}

criterion_group!(benches, off_center_box, patch_contact, rapier_step);
criterion_main!(benches);
