//! Uniform 1D time histories: where samples fall, that sampling changes
//! nothing, how accurate the samples are, streaming and the collecting cap.

use kick_compliant::{Accurate, SolverChoice};
use kick_core::{models, ContactPhase, KickError, LawKind, Outcome, Parameter, RecordingSolver, Sample, Scenario, Solver, Spacing};
use std::ops::ControlFlow;

/// Every solver by name, fixed-step ones at 1 µs.
fn solvers() -> Vec<SolverChoice> {
    solvers_at(1e-6)
}

fn solvers_at(step: f64) -> Vec<SolverChoice> {
    SolverChoice::NAMES.iter().map(|name| SolverChoice::from_name(name, step).unwrap()).collect()
}

fn scenarios() -> Vec<(String, Scenario)> {
    let mut all: Vec<(String, Scenario)> = models::table2()
        .into_iter()
        .chain(models::elastic())
        .chain(models::linear())
        .chain(models::driven())
        .map(|(n, s)| (n.to_string(), s))
        .collect();
    for kind in [LawKind::HuntCrossley, LawKind::KelvinVoigt] {
        all.push((format!("{kind:?}"), Scenario::baseline().with_law(kind, Some(0.7)).unwrap()));
    }
    all
}

/// The end of the history: the contact time, or for the seed method the
/// step at which Eq. 48 held.
fn history_end(solver: &SolverChoice, outcome: &Outcome) -> f64 {
    match solver {
        SolverChoice::SeedRk4(seed) => outcome.contact_time + seed.step,
        _ => outcome.contact_time,
    }
}

/// The path that records: solvers without a history of their own record
/// through `accurate` (outcome and history of one run).
fn recording_path(solver: &SolverChoice) -> SolverChoice {
    match solver {
        SolverChoice::Auto(_) | SolverChoice::ClosedForm(_) | SolverChoice::Series(_) | SolverChoice::ReducedReturn(_) => {
            SolverChoice::Accurate(Accurate::default())
        }
        other => *other,
    }
}

/// The solvers that apply to `s`, fixed-step ones at `step`.
fn applicable_at(s: &Scenario, step: f64) -> Vec<SolverChoice> {
    solvers_at(step).into_iter().filter(|solver| !matches!(solver.solve(s), Err(KickError::NotApplicable { .. }))).collect()
}

fn applicable(s: &Scenario) -> Vec<SolverChoice> {
    applicable_at(s, 1e-6)
}

fn bits(o: &Outcome) -> Vec<u64> {
    o.observable_values().iter().map(|v| v.to_bits()).collect()
}

/// Sampling never changes the steps: the outcome with any history is the
/// recording path's outcome without one, bit for bit (evaluations
/// included). A fine interval once capped the steps of a phase and ended in
/// a false "no separation".
#[test]
fn the_outcome_with_a_history_is_bit_identical() {
    for solver in solvers() {
        for (case, s) in scenarios() {
            let plain = recording_path(&solver).solve(&s);
            for spacing in [Spacing::Interval(1e-4), Spacing::Interval(3.3e-7), Spacing::Count(2), Spacing::Count(777)] {
                let recorded = solver.solve_sampled(&s, spacing, usize::MAX);
                match (&plain, &recorded) {
                    (Ok(a), Ok((b, _))) => {
                        assert_eq!(bits(a), bits(b), "{} {case} {spacing:?}", solver.name());
                        assert_eq!(a, b, "{} {case} {spacing:?}", solver.name());
                    }
                    (Err(a), Err(b)) => assert_eq!(a, b, "{} {case}", solver.name()),
                    _ => panic!("{} {case} {spacing:?}: {plain:?} vs {:?}", solver.name(), recorded.map(|r| r.0)),
                }
            }
        }
    }
}

/// The case: a 20 ns interval on the baseline (≈ 265 000 samples).
#[test]
fn a_fine_interval_is_no_false_no_separation() {
    let s = Scenario::baseline();
    for name in ["accurate", "auto", "reduced", "dopri5"] {
        let solver = SolverChoice::from_name(name, 5e-6).unwrap();
        let (outcome, history) = solver.solve_recorded(&s, 2e-8).unwrap();
        assert_eq!(outcome, recording_path(&solver).solve(&s).unwrap(), "{name}");
        let expected = (outcome.contact_time / 2e-8).ceil() as usize + 1;
        assert!(history.samples.len().abs_diff(expected) <= 1, "{name}: {} samples", history.samples.len());
    }
}

/// t_k = k Δ exactly, every grid time before the end, then the separation
/// row at the end; the count matches what the solver says the history holds.
#[test]
fn samples_lie_on_the_uniform_grid_then_the_separation_row() {
    for solver in solvers() {
        for (case, s) in scenarios() {
            let Ok(outcome) = recording_path(&solver).solve(&s) else { continue };
            let end = history_end(&solver, &outcome);
            for interval in [end / 10.0, end / 9.5, 1.234e-5] {
                let (_, history) = solver.solve_recorded(&s, interval).unwrap();
                let samples = &history.samples;
                let (last, grid) = samples.split_last().unwrap();
                assert_eq!(last.phase, ContactPhase::Separation, "{} {case}", solver.name());
                assert_eq!(last.time, end, "{} {case}", solver.name());
                for (k, sample) in grid.iter().enumerate() {
                    assert_eq!(sample.time, k as f64 * interval, "{} {case} k = {k}", solver.name());
                    assert_ne!(sample.phase, ContactPhase::Separation);
                }
                let before = grid.last().unwrap().time;
                assert!(before < end && end - before <= interval * (1.0 + 1e-12), "{} {case}: {before} {end} {interval}", solver.name());
                let mut counted = 0;
                let streamed = solver
                    .solve_streamed(&s, Spacing::Interval(interval), &mut |_| {
                        counted += 1;
                        ControlFlow::Continue(())
                    })
                    .unwrap();
                assert_eq!(streamed.samples, samples.len() as u64);
                assert_eq!(counted, samples.len());
            }
            // A sample count is honoured exactly, first at 0, last at the end.
            for n in [2, 3, 50] {
                let (_, history) = solver.solve_sampled(&s, Spacing::Count(n), n).unwrap();
                assert_eq!(history.samples.len(), n, "{} {case}", solver.name());
                let interval = end / (n - 1) as f64;
                for (k, sample) in history.samples[..n - 1].iter().enumerate() {
                    assert_eq!(sample.time, k as f64 * interval);
                }
                assert_eq!(history.samples[n - 1].time, end);
            }
        }
    }
}

/// Phases: compressing before the maximum compression, restoring after it.
#[test]
fn phases_follow_the_maximum_compression() {
    let s = Scenario::baseline();
    for solver in applicable(&s) {
        let outcome = solver.solve(&s).unwrap();
        let (_, history) = solver.solve_recorded(&s, 1e-5).unwrap();
        for sample in &history.samples[..history.samples.len() - 1] {
            // The seed method reads the phase off δ̇ at the sample, the others
            // off the integration phase: away from the turning point they agree.
            let margin = 2e-6;
            if sample.time < outcome.max_compression_time - margin {
                assert_eq!(sample.phase, ContactPhase::Compressing, "{} t = {}", solver.name(), sample.time);
            } else if sample.time > outcome.max_compression_time + margin {
                assert_eq!(sample.phase, ContactPhase::Restoring, "{} t = {}", solver.name(), sample.time);
            }
        }
    }
}

/// n = 1 with compression-only damping has a closed-form path: a damped
/// oscillator to δ̇ = 0, then an undamped quarter swing. Samples between
/// steps are as accurate as the steps: within 1e-9 of δ_max and V0, the
/// fixed-step methods at 0.2 µs (RK4's own error is then ~1e-11). (The
/// seed method is checked undamped only: Eq. 20 taken literally loses the
/// jump F(0⁺) = c V0 in its first step, a documented first-order error.)
#[test]
fn samples_follow_the_linear_closed_form() {
    for (case, s) in
        models::linear().into_iter().filter(|(_, s)| s.damping_ratio() < 1.0).chain(models::elastic().into_iter().take(2).skip(1))
    {
        let mu = s.reduced_mass();
        let v0 = s.approach_speed();
        let omega = (s.get(Parameter::Stiffness) / mu).sqrt();
        let zeta = s.damping_ratio();
        let omega_d = omega * (1.0 - zeta * zeta).sqrt();
        let t_max = (omega_d / (zeta * omega)).atan() / omega_d;
        let compression = |t: f64| (v0 / omega_d) * (-zeta * omega * t).exp() * (omega_d * t).sin();
        let rate = |t: f64| v0 * (-zeta * omega * t).exp() * ((omega_d * t).cos() - zeta * omega / omega_d * (omega_d * t).sin());
        let delta_max = compression(t_max);
        let t_c = t_max + std::f64::consts::FRAC_PI_2 / omega;
        let exact = |t: f64| {
            if t <= t_max {
                (compression(t), rate(t))
            } else {
                let phase = omega * (t - t_max);
                (delta_max * phase.cos(), -delta_max * omega * phase.sin())
            }
        };
        for solver in applicable_at(&s, 2e-7) {
            if matches!(solver, SolverChoice::SeedRk4(_)) && zeta > 0.0 {
                continue;
            }
            let (_, history) = solver.solve_sampled(&s, Spacing::Count(301), 301).unwrap();
            for sample in history.samples.iter().filter(|x| x.time < t_c) {
                let (delta, delta_rate) = exact(sample.time);
                let name = solver.name();
                assert!(
                    (sample.compression - delta).abs() <= 1e-9 * delta_max,
                    "{name} {case} t = {}: δ {} vs {delta}",
                    sample.time,
                    sample.compression
                );
                let measured_rate = sample.foot_velocity - sample.ball_velocity;
                assert!(
                    (measured_rate - delta_rate).abs() <= 1e-9 * v0,
                    "{name} {case} t = {}: δ̇ {measured_rate} vs {delta_rate}",
                    sample.time
                );
            }
        }
    }
}

/// A sink that stops early stops the sampling, not the solve; the answer
/// still says how many samples the whole history holds.
#[test]
fn a_stopped_sink_stops_sampling_only() {
    let s = Scenario::baseline();
    for solver in applicable(&s) {
        let mut taken: Vec<Sample> = Vec::new();
        let streamed = solver
            .solve_streamed(&s, Spacing::Interval(1e-6), &mut |sample| {
                taken.push(*sample);
                if taken.len() < 10 {
                    ControlFlow::Continue(())
                } else {
                    ControlFlow::Break(())
                }
            })
            .unwrap();
        assert_eq!(taken.len(), 10, "{}", solver.name());
        assert_eq!(streamed.outcome, recording_path(&solver).solve(&s).unwrap());
        let (_, full) = solver.solve_recorded(&s, 1e-6).unwrap();
        assert_eq!(streamed.samples, full.samples.len() as u64);
        assert_eq!(&full.samples[..10], &taken[..]);
    }
}

/// The collecting form holds at most its limit and names the size it needs.
#[test]
fn the_collecting_form_refuses_past_its_limit_with_the_size_needed() {
    let s = Scenario::baseline();
    let solver = Accurate::default();
    let (_, full) = solver.solve_recorded(&s, 1e-6).unwrap();
    let needed = full.samples.len();
    match solver.solve_sampled(&s, Spacing::Interval(1e-6), needed - 1) {
        Err(KickError::HistoryTooLong { needed: n, limit }) => assert_eq!((n, limit), (needed as f64, needed as u64 - 1)),
        other => panic!("{other:?}"),
    }
    assert_eq!(solver.solve_sampled(&s, Spacing::Interval(1e-6), needed).unwrap().1, full);
    let error = solver.solve_sampled(&s, Spacing::Count(1001), 1000).unwrap_err();
    assert_eq!(error, KickError::HistoryTooLong { needed: 1001.0, limit: 1000 });
    assert!(error.to_string().contains("1001"), "{error}");
}

#[test]
fn a_spacing_that_makes_no_grid_is_named() {
    let s = Scenario::baseline();
    for solver in solvers() {
        for (spacing, name) in [
            (Spacing::Interval(0.0), "interval"),
            (Spacing::Interval(-1e-6), "interval"),
            (Spacing::Interval(f64::NAN), "interval"),
            (Spacing::Interval(f64::INFINITY), "interval"),
            (Spacing::Count(0), "samples"),
            (Spacing::Count(1), "samples"),
        ] {
            match solver.solve_sampled(&s, spacing, 1000) {
                Err(KickError::InvalidParameter { name: n, .. }) => assert_eq!(n, name, "{}", solver.name()),
                other => panic!("{} {spacing:?}: {:?}", solver.name(), other.map(|r| r.0)),
            }
        }
    }
}

/// A history up to the one limit of every history
/// ([`kick_core::MAX_HISTORY_SAMPLES`]) streams through in time order, one
/// sink call per sample; a longer one (2e-9 s: 2.6e6 rows) is refused with
/// its count before the first row.
#[test]
fn a_long_history_streams_up_to_the_limit() {
    let s = Scenario::baseline();
    let solver = Accurate::default();
    let contact_time = solver.solve(&s).unwrap().contact_time;
    let mut count = 0u64;
    let mut previous = f64::NEG_INFINITY;
    let interval = contact_time / (kick_core::MAX_HISTORY_SAMPLES - 2) as f64;
    let streamed = solver
        .solve_streamed(&s, Spacing::Interval(interval), &mut |sample| {
            assert!(sample.time > previous);
            previous = sample.time;
            count += 1;
            ControlFlow::Continue(())
        })
        .unwrap();
    assert_eq!(count, streamed.samples);
    assert!(count as usize <= kick_core::MAX_HISTORY_SAMPLES && count as usize >= kick_core::MAX_HISTORY_SAMPLES - 2, "{count}");
    let refused = solver.solve_streamed(&s, Spacing::Interval(2e-9), &mut |_| ControlFlow::Continue(()));
    match refused {
        Err(KickError::HistoryTooLong { needed, .. }) => assert_eq!(needed, (contact_time / 2e-9).ceil() + 1.0),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
}
