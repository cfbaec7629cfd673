//! Where a `kick sweep3d` row's time goes, on one core: drawing and
//! building the kick, the 3D solve (and its evaluations), the flight. `cargo
//! run --release -p kick-study --example sweep3d_cost [SAMPLES] [flown|leg]`:
//! `flown` is `--law shell --range contact_depth=0,0.05 --range
//! approach_angle=0,20 --flight --distance 9.15 --distance 25`, `leg` is
//! `--law shell --leg`.
use kick_3d::Solver3d;
use kick_study::flight::FlightPlan;
use kick_study::level::sampled_3d::{find_range, SampledKicks};
use kick_study::sample::Ranges;
use std::time::Instant;

fn main() {
    let samples: u64 = std::env::args().nth(1).map_or(2000, |s| s.parse().unwrap());
    let mode = std::env::args().nth(2).unwrap_or_else(|| "flown".into());
    let mut fixed = kick_3d::KickSpec::default();
    fixed.scenario.law = Some(kick_core::LawKind::Shell);
    let (ranges, plan) = if mode == "leg" {
        fixed.scenario.leg = Some(true);
        (Ranges::default(), None)
    } else {
        let given = ["contact_depth=0,0.05".to_string(), "approach_angle=0,20".to_string()];
        let ranges = Ranges::parse(&given, |n| find_range(n, true)).unwrap();
        (ranges, Some(FlightPlan::with_distances(Default::default(), &[9.15, 25.0]).unwrap()))
    };
    let kicks = SampledKicks { seed: 1, fixed, ranges };
    let (mut build, mut solve, mut fly) = (0.0, 0.0, 0.0);
    let (mut evaluations, mut failed) = (0u64, 0u64);
    let mut per_row: Vec<(f64, u64, u64)> = Vec::new();
    for i in 0..samples {
        let t0 = Instant::now();
        let spec = kicks.spec(i);
        let kick = spec.build_drawn();
        let t1 = Instant::now();
        build += (t1 - t0).as_secs_f64();
        let Ok(kick) = kick else {
            failed += 1;
            continue;
        };
        let outcome = Solver3d::Auto.solve(&kick);
        let t2 = Instant::now();
        solve += (t2 - t1).as_secs_f64();
        let Ok(o) = outcome else {
            failed += 1;
            continue;
        };
        evaluations += o.evaluations;
        per_row.push(((t2 - t1).as_secs_f64() * 1e6, o.evaluations, i));
        if let Some(plan) = &plan {
            let rest = kicks.flight_spec(&plan.rest, i);
            let mut values = [0.0; kick_study::flight::MAX_FLIGHT_VALUES];
            let _ = kick_study::flight::flight_after_3d(&kick, &o, &rest).and_then(|f| plan.fly_into(&f, &mut values));
            fly += t2.elapsed().as_secs_f64();
        }
    }
    let n = samples as f64;
    println!(
        "{mode}: {samples} rows, {failed} failed; per row: build {:.1} us, solve {:.1} us, fly {:.1} us; {:.0} evaluations per solved row",
        build / n * 1e6,
        solve / n * 1e6,
        fly / n * 1e6,
        evaluations as f64 / per_row.len() as f64
    );
    per_row.sort_by(|a, b| b.0.total_cmp(&a.0));
    let total: f64 = per_row.iter().map(|r| r.0).sum();
    let top: f64 = per_row.iter().take(per_row.len() / 10).map(|r| r.0).sum();
    println!("the slowest tenth of rows takes {:.0} % of the solve time; slowest rows (us, evaluations, index):", 100.0 * top / total);
    for r in per_row.iter().take(8) {
        println!("  {:.0} us {} evals row {}", r.0, r.1, r.2);
    }
    let mut by_evals: Vec<u64> = per_row.iter().map(|r| r.1).collect();
    by_evals.sort_unstable();
    let q = |p: f64| by_evals[((by_evals.len() - 1) as f64 * p) as usize];
    println!("evaluations: median {}, 90 % {}, 99 % {}, max {}", q(0.5), q(0.9), q(0.99), q(1.0));
    println!("us per evaluation: {:.3}", solve * 1e6 / evaluations as f64);
    per_row.sort_by_key(|r| std::cmp::Reverse(r.1));
    let all: u64 = per_row.iter().map(|r| r.1).sum();
    let tenth: u64 = per_row.iter().take(per_row.len() / 10).map(|r| r.1).sum();
    println!("the tenth of rows with most evaluations has {:.0} % of them; those rows:", 100.0 * tenth as f64 / all as f64);
    for r in per_row.iter().take(12) {
        let kick = kicks.spec(r.2).build_drawn().unwrap();
        let o = Solver3d::Auto.solve(&kick).unwrap();
        println!(
            "  {} evals row {}: offset {:.4} depth {:.4} approach {:.2} mu {:.3} foot {:.2} m/s mass {:.2} kg; contact {:.3e} s slip {:.3e} s spin {:.0} rpm",
            r.1, r.2, kick.offset, kick.contact_depth, kick.approach_angle.to_degrees(), kick.friction,
            kick.base.foot_speed(), kick.base.effective_foot_mass(), o.contact_time, o.slip_time, o.spin_rpm
        );
    }
}
