//! A boot in series (`kick_compliant::boot`): the series path against the
//! event engine at 1e-14 (independent methods on the same law), the engine
//! at its default against another integrator tightened (Dopri5 at 1e-14),
//! the layer's limits (k_b → ∞ is the rigid foot), energy, and the
//! refusals of solvers that cannot carry the layer.

use kick_compliant::events::Method;
use kick_compliant::precision::max_relative_error;
use kick_compliant::reduced::Reduced;
use kick_compliant::{Accurate, Auto, FullState, Series, SolverChoice};
use kick_core::{
    AnyLaw, Boot, Foot, KickError, LawKind, Outcome, Parameter, RecordingSolver, Scenario, ShellBall, Solver, SolverPath, Spacing,
};

fn tight() -> Reduced {
    Reduced::with_tolerances(1e-14, 1e-14).unwrap()
}

fn booted(scenario: Scenario, boot: Boot) -> Scenario {
    scenario.with_foot(Foot { leg: None, boot: Some(boot) })
}

fn uniform_source(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` booted shell kicks: the eight 1D parameters from their sampling
/// ranges (drive ≥ 0 as drawn), Law 2's pressures, shell losses up to 2x
/// the FIFA-calibrated one, and layers of 1e4–1e6 N/m (log) with 5–200 N s/m.
fn booted_shell_scenarios(count: u64) -> Vec<Scenario> {
    let mut uniform = uniform_source(0x9e37_79b9_7f4a_7c15);
    (0..count)
        .map(|_| {
            let values = Parameter::ALL.map(|p| p.def().sample.expect("every 1D parameter is sampled").draw(&mut uniform));
            let ball = ShellBall::new(
                6.0e4 + 5.0e4 * uniform(),
                kick_core::DEFAULT_BALL_RADIUS,
                1.4,
                0.0,
                2.0 * kick_core::shell::SHELL_DAMPING_FIFA * uniform(),
            )
            .unwrap();
            let boot = Boot { stiffness: 10f64.powf(4.0 + 2.0 * uniform()), damping: 5.0 + 195.0 * uniform() };
            booted(Scenario::from_values(values).unwrap().with_shell(ball), boot)
        })
        .collect()
}

/// The series path within 1e-10 of the engine at 1e-14 on every observable
/// over the box; a trapped kick is trapped (or unfinished) on both.
#[test]
fn the_booted_series_matches_the_tight_engine_over_the_box() {
    let (mut worst, mut solved, mut trapped, mut clamped) = (0.0_f64, 0, 0, 0);
    for (i, scenario) in booted_shell_scenarios(300).iter().enumerate() {
        let reference = tight().solve(scenario);
        let series = Series::default().solve(scenario);
        match (&series, &reference) {
            (Ok(s), Ok(r)) => {
                assert_eq!((s.method, r.method), (SolverPath::Series, SolverPath::Reduced));
                let error = max_relative_error(s, r);
                assert!(error < 1e-10, "row {i}: {error:e}\n{scenario:?}\n{s:?}\n{r:?}");
                worst = worst.max(error);
                solved += 1;
            }
            (Err(KickError::Trapped { .. }), Err(KickError::Trapped { .. } | KickError::NoSeparation { .. })) => trapped += 1,
            // The clamp (fast rebounds of a lossy ball): the series hands over, auto takes the engine.
            (Err(KickError::NotApplicable { .. }), Ok(r)) => {
                let auto = Auto::default().solve(scenario).unwrap();
                assert_eq!(auto.method, SolverPath::Reduced);
                let error = max_relative_error(&auto, r);
                assert!(error < 1e-9, "row {i}: {error:e}");
                clamped += 1;
            }
            _ => panic!("row {i}: {series:?} vs {reference:?}\n{scenario:?}"),
        }
    }
    println!("booted series vs engine at 1e-14: worst {worst:.2e} over {solved} kicks ({trapped} trapped on both, {clamped} clamped)");
    assert!(solved > 200, "{solved}");
}

/// The engine at its default tolerance (`accurate`, `reduced`) within 1e-9
/// of Dopri5 at 1e-14 (another integrator) on every observable, for each
/// law of the family and the shell ball, with and without a drive.
#[test]
fn the_engine_matches_another_integrator_tightened() {
    let reference = FullState { method: Method::Dopri5 { relative_tolerance: 1e-14, absolute_tolerance: 1e-14 }, path: SolverPath::Dopri5 };
    let shell = ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap();
    let boot = kick_core::boot::IDENTIFIED;
    let mut worst = 0.0_f64;
    for law in LawKind::SELECTABLE {
        for drive in [0.0, 400.0] {
            for &(k_b, c_b) in &[(boot.stiffness, boot.damping), (3.0e5, 10.0)] {
                let base = Scenario::baseline().with(Parameter::DriveForce, drive).unwrap();
                let scenario = match law {
                    LawKind::Shell => base.with_shell(shell),
                    LawKind::PowerLaw => base,
                    other => base.with_law(other, Some(0.6)).unwrap(),
                };
                let scenario = booted(scenario, Boot { stiffness: k_b, damping: c_b });
                let truth = reference.solve(&scenario).unwrap();
                for solver in [Accurate::default().solve(&scenario).unwrap(), Reduced::default().solve(&scenario).unwrap()] {
                    let error = max_relative_error(&solver, &truth);
                    assert!(error < 1e-9, "{law:?} drive {drive} k_b {k_b}: {error:e}\n{solver:?}\n{truth:?}");
                    worst = worst.max(error);
                }
                assert!(truth.energy.relative_residual().abs() < 1e-10, "{law:?}: {:e}", truth.energy.relative_residual());
            }
        }
    }
    println!("booted engine vs Dopri5 at 1e-14: worst {worst:.2e}");
}

/// A stiffer and stiffer layer tends to the rigid foot, its difference
/// falling as 1/k_b (the layer's share of the approach, F/k_b).
#[test]
fn a_stiff_layer_is_the_rigid_foot() {
    let shell = Scenario::baseline().with_shell(ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap());
    for scenario in [shell, Scenario::baseline()] {
        let rigid = Accurate::default().solve(&scenario).unwrap();
        let gap = |k_b: f64| {
            let o = Accurate::default().solve(&booted(scenario, Boot { stiffness: k_b, damping: 1e-3 * k_b })).unwrap();
            ((o.v_ball_out - rigid.v_ball_out) / rigid.v_ball_out)
                .abs()
                .max(((o.contact_time - rigid.contact_time) / rigid.contact_time).abs())
        };
        let (g6, g7) = (gap(1e7), gap(1e8));
        assert!(g7 < 0.02 && g7 < 0.2 * g6, "{:?}: {g6:e} {g7:e}", scenario.law_kind());
    }
}

/// The energy budget closes on both paths, the layer's energy left at
/// separation is its own (½ k_b δ_b², > 0), and the ball leaves before the
/// layer has relaxed.
#[test]
fn the_energy_budget_closes_with_the_layer() {
    for scenario in booted_shell_scenarios(40) {
        let Ok(series) = Series::default().solve(&scenario) else { continue };
        let engine = Reduced::default().solve(&scenario).unwrap();
        for o in [&series, &engine] {
            assert!(o.energy.relative_residual().abs() < 1e-10, "{:e}", o.energy.relative_residual());
            assert!(o.energy.elastic_final > 0.0);
        }
    }
}

/// `auto` takes the series for a booted shell kick and the engine for the
/// other laws; solvers that cannot carry the layer refuse it by name; a
/// history's outcome is the summary's.
#[test]
fn the_paths_that_carry_a_boot_and_those_that_refuse_it() {
    let boot = kick_core::boot::IDENTIFIED;
    let shell = booted(Scenario::baseline().with_shell(ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap()), boot);
    let paper = booted(Scenario::baseline(), boot);
    assert_eq!(Auto::default().solve(&shell).unwrap().method, SolverPath::Series);
    assert_eq!(Auto::default().solve(&paper).unwrap().method, SolverPath::Reduced);
    for name in ["seed-rk4", "closed-form", "reduced-return"] {
        let e = SolverChoice::from_name(name, 5e-6).unwrap().solve(&paper).unwrap_err();
        assert!(matches!(e, KickError::NotApplicable { .. }), "{name}: {e}");
        assert!(e.to_string().contains("boot"), "{name}: {e}");
    }
    assert!(matches!(Series::default().solve(&paper), Err(KickError::NotApplicable { .. })));
    let summary = Accurate::default().solve(&shell).unwrap();
    let (streamed, history) = Accurate::default().solve_sampled(&shell, Spacing::Count(50), 100).unwrap();
    assert_eq!(summary, streamed);
    let last = history.samples.last().unwrap();
    assert_eq!(last.time, summary.contact_time);
    assert!(last.compression.abs() < 1e-12);
    let AnyLaw::Shell(_) = shell.contact_law() else { unreachable!() };
}

/// With a layer the kick lasts longer and the peak force falls, as a
/// softer series spring must: the identified boot on Table 1's shell kick.
#[test]
fn the_layer_lengthens_the_kick_and_lowers_the_peak() {
    let shell = Scenario::baseline().with_shell(ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap());
    let rigid: Outcome = Auto::default().solve(&shell).unwrap();
    let soft = Auto::default().solve(&booted(shell, kick_core::boot::IDENTIFIED)).unwrap();
    assert!(soft.contact_time > 1.3 * rigid.contact_time, "{} vs {}", soft.contact_time, rigid.contact_time);
    assert!(soft.peak_force < 0.8 * rigid.peak_force);
}

/// The stiffest layer a spec accepts (c_b/k_b at `BOOT_TIME_SHARE` of the
/// contact time) solves on `auto`'s path for both laws, within 1e-3 of the
/// rigid foot; a stiffer one is refused naming `boot_stiffness`, where
/// k_b = 1e10 N/m used to run every solver out of its steps and be
/// reported as "no separation found".
#[test]
fn the_stiffest_layer_accepted_solves_and_a_stiffer_one_is_refused() {
    for law in [LawKind::PowerLaw, LawKind::Shell] {
        let spec = |k_b: Option<f64>| kick_core::ScenarioSpec { law: Some(law), boot_stiffness: k_b, ..Default::default() };
        let rigid = spec(None).build().unwrap();
        let limit = kick_core::boot::IDENTIFIED.damping / (kick_core::scenario::BOOT_TIME_SHARE * rigid.elastic_contact_time());
        let stiffest = spec(Some(0.99 * limit)).build().unwrap();
        let (o, o_rigid) = (Auto::default().solve(&stiffest).unwrap(), Auto::default().solve(&rigid).unwrap());
        assert!((o.v_ball_out / o_rigid.v_ball_out - 1.0).abs() < 1e-3, "{law:?}: {} vs {}", o.v_ball_out, o_rigid.v_ball_out);
        for k_b in [1.01 * limit, 1e10] {
            match spec(Some(k_b)).build() {
                Err(KickError::InvalidParameter { name: "boot_stiffness", value, .. }) => assert_eq!(value, k_b),
                other => panic!("{law:?} at {k_b:e}: {other:?}"),
            }
        }
        // With the leg's identified k_b and only c_b given, c_b is what was
        // too small, and is named (boot_stiffness, never given, was).
        let light = kick_core::ScenarioSpec { law: Some(law), leg: Some(true), boot_damping: Some(1e-9), ..Default::default() };
        match light.build() {
            Err(KickError::InvalidParameter { name: "boot_damping", value, .. }) => assert_eq!(value, 1e-9),
            other => panic!("{law:?}: {other:?}"),
        }
    }
}
