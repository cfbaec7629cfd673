//! The shell ball on the `series` path (`kick_compliant::shell_series`)
//! against `reduced` and `accurate` at 1e-14 (independent integrators of the
//! same law), the exact restitution of a Hunt–Crossley contact solved here
//! by bisection (the law's small-compression limit), and energy
//! conservation with the loss off. Its documented accuracy at the default
//! tolerance: 1e-10 relative on every observable.

use kick_compliant::precision::max_relative_error;
use kick_compliant::reduced::Reduced;
use kick_compliant::{Accurate, Auto, Series};
use kick_core::{KickError, Outcome, Parameter, Scenario, ShellBall, Solver, SolverPath};

fn tight() -> Reduced {
    Reduced::with_tolerances(1e-14, 1e-14).unwrap()
}

/// `count` scenarios from the declared sampling ranges of the eight 1D
/// parameters (drive ≥ 0 as drawn) with shell balls over Law 2's pressures,
/// losses up to 4x the calibrated one and a shell stiffness on every other row.
/// The sweep's foot speeds reach 40 m/s: the fastest rebounds reach the
/// clamp F = 0, which the series leaves to `reduced` (`NotApplicable`).
fn shell_scenarios(count: u64) -> Vec<Scenario> {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|i| {
            let values = Parameter::ALL.map(|p| p.def().sample.expect("every 1D parameter is sampled").draw(&mut uniform));
            let pressure = 6.0e4 + 5.0e4 * uniform();
            let loss = 4.0 * kick_core::shell::SHELL_DAMPING_FIFA * uniform();
            let stiffness = if i % 2 == 0 { 0.0 } else { 1.0e4 * uniform() };
            let ball = ShellBall::new(pressure, kick_core::DEFAULT_BALL_RADIUS, 1.4, stiffness, loss).unwrap();
            Scenario::from_values(values).unwrap().with_shell(ball)
        })
        .collect()
}

/// Every observable within 1e-10 of `reduced` at 1e-14 over the sweep's box;
/// a trapped scenario is trapped on both paths.
#[test]
fn matches_the_tight_reference_over_the_sweep_box() {
    let (mut worst, mut solved, mut trapped, mut clamped) = (0.0_f64, 0, 0, 0);
    for (i, scenario) in shell_scenarios(400).iter().enumerate() {
        let reference = tight().solve(scenario);
        let series = Series::default().solve(scenario);
        if let Err(KickError::NotApplicable { .. }) = series {
            // Handed to `reduced` by `auto`, which agrees with the reference.
            let auto = Auto::default().solve(scenario).unwrap();
            assert_eq!(auto.method, SolverPath::Reduced);
            assert!(max_relative_error(&auto, reference.as_ref().unwrap()) < 1e-9, "row {i}");
            clamped += 1;
            continue;
        }
        match (&series, &reference) {
            (Ok(s), Ok(r)) => {
                assert_eq!(s.method, SolverPath::Series);
                let error = max_relative_error(s, r);
                assert!(error < 1e-10, "row {i}: {error:e}\n{scenario:?}\n{s:?}\n{r:?}");
                worst = worst.max(error);
                solved += 1;
            }
            // `reduced` has no proof of trapping for this law: it runs to its horizon.
            (Err(KickError::Trapped { .. }), Err(KickError::Trapped { .. } | KickError::NoSeparation { .. })) => trapped += 1,
            _ => panic!("row {i}: {series:?} vs {reference:?}\n{scenario:?}"),
        }
    }
    println!(
        "shell series vs reduced at 1e-14: worst {worst:.2e} over {solved} scenarios ({trapped} trapped on both, {clamped} left to reduced)"
    );
    assert!(solved > 300, "{solved}");
}

/// Table 1's kick with the default ball, against `accurate` at 1e-14 too.
#[test]
fn table1_kick_matches_both_references() {
    let scenario = Scenario::baseline().with_shell(ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap());
    let series = Series::default().solve(&scenario).unwrap();
    for reference in [tight().solve(&scenario).unwrap(), Accurate::new(1e-14, 1e-14).unwrap().solve(&scenario).unwrap()] {
        let error = max_relative_error(&series, &reference);
        assert!(error < 1e-10, "{error:e}");
    }
}

/// Without a drive the relative motion of F = k δ (1 + χ δ̇) ends with
/// e = x_e/x0, x0 − ln(1 + x0) = −x_e − ln(1 − x_e), x0 = χ V0, whatever
/// k and the masses: solved here by bisection. The shell law is that at
/// small compression, k = 2πR p0 + k_s, χ = β/(p0 + k_s/(2πR)); at
/// V0 = 0.05 m/s (δ ≈ 0.1 mm) its own corrections, O(δ/R) ≈ 1e-3 in the
/// force, move e by less than 1e-3 × (1 − e) (measured below 1.5e-4 of it).
#[test]
fn restitution_is_the_hunt_crossley_relation() {
    let relation = |x0: f64| {
        let target = x0 - x0.ln_1p();
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if -mid - (-mid).ln_1p() < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi) / x0
    };
    let mut worst = 0.0_f64;
    for scenario in shell_scenarios(60) {
        let scenario = scenario.with(Parameter::DriveForce, 0.0).unwrap().with(Parameter::BallSpeed, 0.0).unwrap();
        let scenario = scenario.with(Parameter::FootSpeed, 0.05).unwrap();
        let kick_core::AnyLaw::Shell(ball) = scenario.contact_law() else { unreachable!() };
        let outcome = Series::default().solve(&scenario).unwrap();
        let chi = ball.small_compression_hysteresis();
        let expected = if chi == 0.0 { 1.0 } else { relation(chi * scenario.approach_speed()) };
        let error = (outcome.restitution - expected).abs() / (1.0 - expected).max(1e-3);
        worst = worst.max(error);
        assert!(error < 1e-3, "{} vs {expected}", outcome.restitution);
    }
    println!("shell series against Hunt–Crossley's restitution at 0.05 m/s: worst {worst:.1e} of 1 − e");
}

/// With the loss off the contact conserves energy (restitution 1, nothing
/// dissipated); with it on, the budget closes.
#[test]
fn energy_balance() {
    let residual = |o: &Outcome| o.energy.relative_residual().abs();
    let lossless = ShellBall::new(8.0e4, kick_core::DEFAULT_BALL_RADIUS, 1.4, 2.0e3, 0.0).unwrap();
    let outcome = Series::default().solve(&Scenario::baseline().with_shell(lossless)).unwrap();
    assert!((outcome.restitution - 1.0).abs() < 1e-11, "{}", outcome.restitution);
    assert!(outcome.energy.dissipated.abs() < 1e-11 * outcome.energy.kinetic_initial);
    for scenario in shell_scenarios(100) {
        if let Ok(o) = Series::default().solve(&scenario) {
            assert!(residual(&o) < 1e-11, "{:e}", residual(&o));
        }
    }
}

/// `auto` takes the series for the shell ball, `reduced` under a negative
/// drive (where the clamp F ≥ 0 can engage), and both agree there.
#[test]
fn auto_takes_the_series_for_the_shell_ball() {
    let ball = ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap();
    let scenario = Scenario::baseline().with_shell(ball);
    assert_eq!(Auto::default().solve(&scenario).unwrap().method, SolverPath::Series);
    let pulled = scenario.with(Parameter::DriveForce, -300.0).unwrap();
    assert_eq!(Auto::default().solve(&pulled).unwrap().method, SolverPath::Reduced);
    assert!(matches!(Series::default().solve(&pulled), Err(KickError::NotApplicable { .. })));
}

/// No kick the series solves separates past the clamp: at separation δ̇ is
/// the relative velocity v_f − v_b, and the force just before it,
/// A (p0 + k_s/(2πR) + β δ̇), must still push; a rebound faster than that
/// has met F = 0 however close to δ = 0, between the step's samples, and
/// belongs to `reduced` (found on 8 of 20,000 sampled kicks, 4.5e-6 off).
#[test]
fn no_series_kick_separates_past_the_clamp() {
    let (mut checked, mut handed) = (0, 0);
    for (i, scenario) in shell_scenarios(20_000).iter().enumerate() {
        let kick_core::AnyLaw::Shell(ball) = scenario.contact_law() else { panic!("row {i}: not a shell ball") };
        match Series::default().solve(scenario) {
            Ok(o) => {
                let rate = o.v_foot_out - o.v_ball_out;
                let push = ball.pressure + ball.shell_stiffness / (2.0 * std::f64::consts::PI * ball.radius) + ball.shell_damping * rate;
                assert!(push > 0.0, "row {i}: separates at δ̇ = {rate} m/s, F/A → {push} Pa\n{scenario:?}");
                checked += 1;
            }
            Err(KickError::NotApplicable { .. }) => handed += 1,
            Err(_) => {}
        }
    }
    println!("{checked} series kicks separate with the ball pushed; {handed} handed to reduced");
    assert!(checked > 15_000, "{checked}");
}
