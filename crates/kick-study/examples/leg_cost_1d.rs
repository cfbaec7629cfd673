//! Same-run cost of the 1D shell kick with and without the leg and its boot
//! (what `kick bench` reports), with step counts: `cargo run --release -p
//! kick-study --example leg_cost_1d [SAMPLES]`.
use kick_core::Solver;
use kick_study::sample::SampledSweep;
use std::time::Instant;

fn run(sweep: &SampledSweep) -> (f64, u64, u64, u64) {
    let solver = kick_compliant::SolverChoice::from_name("auto", 5e-6).unwrap();
    let started = Instant::now();
    let (mut evals, mut ok, mut other) = (0u64, 0u64, 0u64);
    for i in 0..sweep.samples {
        if let Ok(o) = sweep.scenario(i).and_then(|s| solver.solve(&s)) {
            ok += 1;
            if o.method != kick_core::SolverPath::Series {
                other += 1;
            } else {
                evals += o.evaluations;
            }
        }
    }
    (started.elapsed().as_secs_f64(), evals, ok, other)
}

fn main() {
    let samples: u64 = std::env::args().nth(1).map_or(20_000, |s| s.parse().unwrap());
    let mut shell = SampledSweep::new(samples, 1);
    shell.fixed.law = Some(kick_core::LawKind::Shell);
    let mut leg = shell.clone();
    leg.fixed.leg = Some(true);
    // One side alone (for `perf stat`): `shell` or `leg`.
    if let Some(side) = std::env::args().nth(2) {
        let r = run(if side == "leg" { &leg } else { &shell });
        println!("{side}: {:.3} s", r.0);
        return;
    }
    let mut ratios = Vec::new();
    for _ in 0..5 {
        let a = run(&shell);
        let b = run(&leg);
        println!(
            "shell {:.3} s ({} ok, {:.1} steps, {} not series), leg+boot {:.3} s ({} ok, {:.1} steps, {} not series): {:.2}x",
            a.0,
            a.2,
            a.1 as f64 / (a.2 - a.3) as f64,
            a.3,
            b.0,
            b.2,
            b.1 as f64 / (b.2 - b.3) as f64,
            b.3,
            b.0 / a.0
        );
        ratios.push(b.0 / a.0);
    }
    ratios.sort_by(f64::total_cmp);
    for s in [&shell, &leg] {
        let started = Instant::now();
        let n = (0..s.samples).filter(|&i| s.scenario(i).is_ok()).count();
        println!("building {n} scenarios: {:.3} s", started.elapsed().as_secs_f64());
    }
    println!("median ratio {:.2}x (range {:.2}-{:.2})", ratios[2], ratios[0], ratios[4]);
}
