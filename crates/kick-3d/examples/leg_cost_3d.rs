//! The realistic foot's cost on the cap patch kick (issue 31 item 8): evaluations
//! and µs per kick of the shell ball's cap patch kick at 5 cm, μ = 0.5, with no
//! foot model, the leg without a boot, the boot alone, and the leg with its boot,
//! timed in alternation (ratios within one run):
//! `cargo run --release -p kick-3d --example leg_cost_3d [SECONDS]`.
use kick_3d::{Accurate3d, KickSpec};
use kick_core::ScenarioSpec;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let seconds: f64 = std::env::args().nth(1).map_or(0.3, |s| s.parse().expect("SECONDS"));
    let cap = kick_3d::models::cap_patch_kick();
    let shell = ScenarioSpec { law: Some(kick_core::LawKind::Shell), ..Default::default() };
    let forms: Vec<(&str, ScenarioSpec)> = vec![
        ("rigid Table 1 foot", shell.clone()),
        ("leg, no boot", ScenarioSpec { leg: Some(true), boot_stiffness: Some(f64::INFINITY), ..shell.clone() }),
        (
            "boot alone",
            ScenarioSpec {
                boot_stiffness: Some(kick_core::boot::IDENTIFIED_STIFFNESS),
                boot_damping: Some(kick_core::boot::IDENTIFIED_DAMPING),
                ..shell.clone()
            },
        ),
        ("leg and boot", ScenarioSpec { leg: Some(true), ..shell.clone() }),
    ];
    let kicks: Vec<_> = forms.iter().map(|(_, s)| KickSpec { scenario: s.clone(), kick3d: cap }.build().expect("valid")).collect();
    let solver = Accurate3d::default();

    let mut times = vec![Vec::new(); kicks.len()];
    let mut evaluations = vec![0; kicks.len()];
    for _ in 0..5 {
        for (i, k) in kicks.iter().enumerate() {
            let (mut runs, started) = (0u32, Instant::now());
            while runs == 0 || started.elapsed().as_secs_f64() < seconds {
                evaluations[i] = black_box(solver.solve(black_box(k)).expect("solves")).evaluations;
                runs += 1;
            }
            times[i].push(started.elapsed().as_secs_f64() / f64::from(runs) * 1e6);
        }
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let base = median(&mut times[0].clone());
    for (i, (name, _)) in forms.iter().enumerate() {
        let t = median(&mut times[i]);
        println!(
            "{name:>20}: {:5} evaluations, {t:7.1} µs, {:.2}x the rigid foot, {:.3} µs/evaluation",
            evaluations[i],
            t / base,
            t / evaluations[i] as f64
        );
    }
}
