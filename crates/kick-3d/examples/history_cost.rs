//! Cost of a uniform history on the accurate path over the box sample:
//! `cargo run --release -p kick-3d --example history_cost -- [N] [SAMPLES]`
//! prints the median wall time per kick without a history, with
//! `Interval(t_c/(SAMPLES − 1))` (one solve) and with `Count(SAMPLES)` (two
//! solves: the grid needs t_c), and checks every outcome, evaluation count
//! included, is the plain solve's to the bit.
use kick_3d::models::{OffCenterBox, BENCH_SEED};
use kick_3d::Accurate3d;
use kick_core::Spacing;
use std::hint::black_box;
use std::ops::ControlFlow;
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: u64 = args.get(1).map_or(200, |s| s.parse().expect("N"));
    let samples: usize = args.get(2).map_or(201, |s| s.parse().expect("SAMPLES"));
    let box_sample = OffCenterBox::new(BENCH_SEED);
    let solver = Accurate3d::default();
    let repeats = 20;
    let (mut plain, mut interval, mut count) = (Vec::new(), Vec::new(), Vec::new());
    let mut evaluations = Vec::new();
    for i in 0..n {
        let kick = box_sample.kick(i).expect("box kick");
        let reference = solver.solve(&kick).expect("solves");
        evaluations.push(reference.evaluations as f64);
        let spacing = Spacing::Interval(reference.contact_time / (samples - 1) as f64);
        let time = |f: &dyn Fn()| {
            let start = Instant::now();
            for _ in 0..repeats {
                f();
            }
            start.elapsed().as_secs_f64() / f64::from(repeats)
        };
        let mut sum = 0.0;
        let mut sink = |s: &kick_3d::Sample3d| {
            sum += s.time;
            ControlFlow::Continue(())
        };
        let (o, rows) = solver.solve_streamed(&kick, spacing, &mut sink).expect("solves");
        assert_eq!(o, reference, "kick {i}: a history changed the outcome");
        assert!(rows as usize >= samples - 1, "kick {i}: {rows} rows");
        let (o, rows) = solver.solve_streamed(&kick, Spacing::Count(samples), &mut sink).expect("solves");
        assert_eq!((o, rows), (reference, samples as u64), "kick {i}");
        plain.push(time(&|| {
            black_box(solver.solve(black_box(&kick)).unwrap());
        }));
        interval.push(time(&|| {
            black_box(
                solver
                    .solve_streamed(black_box(&kick), spacing, &mut |s| {
                        black_box(s);
                        ControlFlow::Continue(())
                    })
                    .unwrap(),
            );
        }));
        count.push(time(&|| {
            black_box(
                solver
                    .solve_streamed(black_box(&kick), Spacing::Count(samples), &mut |s| {
                        black_box(s);
                        ControlFlow::Continue(())
                    })
                    .unwrap(),
            );
        }));
        black_box(sum);
    }
    let (p, i, c) = (median(plain), median(interval), median(count));
    println!("{n} box kicks, {samples} rows, median over kicks:");
    println!("evaluations per kick (outcome, with and without history): {:.0}", median(evaluations));
    println!("no history:            {:8.2} µs", p * 1e6);
    println!("Interval (one solve):  {:8.2} µs  ({:+.2} µs, {:.2} µs a row)", i * 1e6, (i - p) * 1e6, (i - p) * 1e6 / samples as f64);
    println!("Count (two solves):    {:8.2} µs", c * 1e6);
    println!("outcomes and evaluation counts identical with and without a history: yes");
}
