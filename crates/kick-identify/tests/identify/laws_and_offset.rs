//! Fitting with the other contact laws (their target restitution as a
//! parameter) and with a time offset between data and model: synthetic
//! recovery, the scatter of the estimates against their reported
//! uncertainties, and the refusals of parameters that do not act.

use kick_core::{LawKind, Parameter, Scenario};
use kick_identify::data::{Channel, FitSpec, Observable};
use kick_identify::fit::{fit, FitOptions, FitProblem};
use kick_identify::synthetic::{history, lab_sigma, scalars, time_grid};
use kick_identify::{FitParameter, IdentifyError, ModelPoint};

use crate::common;
use common::assert_recovered;

const ALL_CHANNELS: [Channel; 4] = [Channel::Force, Channel::Compression, Channel::FootVelocity, Channel::BallVelocity];

fn law(kind: LawKind, e: f64) -> Scenario {
    Scenario::baseline().with_law(kind, Some(e)).unwrap()
}

/// `truth` with each parameter multiplied (or, for t0, replaced) as given.
fn start_from(truth: &ModelPoint, moves: &[(FitParameter, f64)]) -> ModelPoint {
    moves.iter().fold(*truth, |point, &(p, v)| match p {
        FitParameter::TimeOffset => point.with(p, v).unwrap(),
        _ => point.with(p, truth.get(p).unwrap() * v).unwrap(),
    })
}

/// Data from `hunt-crossley-exact` (e = 0.66): m_f, k, n and the target
/// restitution e come back within 3σ from four noisy channels, and the fitted
/// model runs that law. The paper's law, fitted to the same data with its
/// four parameters, cannot follow them: the hysteresis pulse starts at zero
/// force, Eq. 20's jumps to c V0.
#[test]
fn recovers_a_hunt_crossley_kick_and_its_restitution() {
    let options = FitOptions::default();
    let truth = ModelPoint::from(law(LawKind::HuntCrossleyExact, 0.66));
    let times = time_grid(&truth.scenario, 80, 1.2);
    let data = history(&options.solver, &truth, times, &lab_sigma(&ALL_CHANNELS), 17).unwrap();
    let free: Vec<FitParameter> =
        vec![Parameter::FootMass.into(), Parameter::Stiffness.into(), Parameter::Exponent.into(), FitParameter::Restitution];
    let start = start_from(&truth, &[(free[0], 1.2), (free[1], 0.7), (free[2], 0.93), (free[3], 0.75)]);
    let report = fit(&FitProblem { start, free, observations: data.clone() }, &options).unwrap();
    assert_eq!(report.law, LawKind::HuntCrossleyExact);
    assert_recovered(&truth, &report);

    let paper = ModelPoint::from(Scenario::baseline());
    let four = kick_identify::profile::MODEL_PARAMETERS.to_vec();
    let wrong = fit(&FitProblem { start: paper, free: four, observations: data }, &options).unwrap();
    let s2 = wrong.residual_variance.unwrap();
    println!("paper's law on hunt-crossley-exact data: s² = {s2:.1}");
    // s² of a right model is 1 ± 0.3 (four standard deviations at ν = 316).
    assert!(s2 > 10.0, "the paper's law fits hunt-crossley data: s² = {s2}");
}

/// A history whose first touch is at t0 ≠ 0, fitted from t0 = 0: the
/// paper's law (whose force jumps at t0, so χ² jumps as samples cross it)
/// and a hysteresis law (continuous force), with the other parameters.
#[test]
fn recovers_the_time_offset_of_a_history() {
    let options = FitOptions::default();
    for (scenario, t0, free) in [
        (
            Scenario::baseline(),
            2.5e-4,
            vec![Parameter::FootMass.into(), Parameter::Stiffness.into(), Parameter::Damping.into(), Parameter::Exponent.into()],
        ),
        (law(LawKind::HuntCrossley, 0.7), -1.3e-4, vec![Parameter::Stiffness.into(), FitParameter::Restitution]),
    ] {
        let truth = ModelPoint::new(scenario, t0).unwrap();
        let times = time_grid(&scenario, 80, 1.2);
        let data = history(&options.solver, &truth, times, &lab_sigma(&ALL_CHANNELS), 23).unwrap();
        let mut free: Vec<FitParameter> = free;
        let moves: Vec<(FitParameter, f64)> = free.iter().map(|&p| (p, 0.85)).chain([(FitParameter::TimeOffset, 0.0)]).collect();
        free.push(FitParameter::TimeOffset);
        let start = start_from(&truth, &moves);
        let report = fit(&FitProblem { start, free, observations: data }, &options).unwrap();
        assert_recovered(&truth, &report);
        assert_eq!(report.estimate(FitParameter::TimeOffset).unwrap().start, 0.0);
    }
}

/// The reported uncertainties of k, e and t0 match the scatter: over 30
/// noise seeds the mean squared pull follows χ²₃₀/30, whose 0.1% and 99.9%
/// quantiles are 0.39 and 1.99.
#[test]
fn uncertainties_of_restitution_and_time_offset_match_the_scatter() {
    let options = FitOptions::default();
    let truth = ModelPoint::new(law(LawKind::HuntCrossleyExact, 0.6), 1.0e-4).unwrap();
    let times = time_grid(&truth.scenario, 40, 1.2);
    let sigma = lab_sigma(&[Channel::Force, Channel::Compression]);
    let free = vec![Parameter::Stiffness.into(), FitParameter::Restitution, FitParameter::TimeOffset];
    let start = start_from(&truth, &[(free[0], 1.1), (free[1], 0.9), (free[2], 0.0)]);
    let runs = 30;
    let mut sum_z2 = [0.0; 3];
    for seed in 0..runs {
        let data = history(&options.solver, &truth, times.clone(), &sigma, 500 + seed).unwrap();
        let report = fit(&FitProblem { start, free: free.clone(), observations: data }, &options).unwrap();
        for (k, e) in report.estimates.iter().enumerate() {
            let z = (e.value - truth.get(e.parameter).unwrap()) / e.standard_uncertainty.unwrap();
            sum_z2[k] += z * z;
        }
    }
    for (p, s) in free.iter().zip(sum_z2) {
        let mean = s / runs as f64;
        println!("{}: mean pull² {mean:.3}", p.name());
        assert!((0.39..1.99).contains(&mean), "{}: mean pull² {mean}", p.name());
    }
}

/// Parameters that do not act are refused by name, before any solve.
#[test]
fn parameters_that_do_not_act_are_refused() {
    let options = FitOptions::default();
    let refuse = |scenario: Scenario, parameter: FitParameter, with_history: bool| {
        let point = ModelPoint::from(scenario);
        let observations = if with_history {
            history(&options.solver, &point, time_grid(&scenario, 10, 1.2), &lab_sigma(&[Channel::Force]), 1).unwrap()
        } else {
            scalars(&options.solver, &scenario, &[(Observable::VBallOut, 0.01)], None).unwrap()
        };
        let problem = FitProblem { start: point, free: vec![Parameter::Stiffness.into(), parameter], observations };
        fit(&problem, &options).unwrap_err()
    };
    let cases = [
        (law(LawKind::HuntCrossley, 0.7), Parameter::Damping.into(), true, ["`damping`", "`hunt-crossley`", "restitution"]),
        (law(LawKind::KelvinVoigt, 0.7), Parameter::Exponent.into(), true, ["`exponent`", "`kelvin-voigt`", "linear"]),
        (Scenario::baseline(), FitParameter::Restitution, true, ["`restitution`", "`power-law`", "Eq. 20"]),
        (Scenario::baseline(), FitParameter::TimeOffset, false, ["`time_offset`", "scalar observations", "history"]),
    ];
    for (scenario, parameter, with_history, words) in cases {
        let e = refuse(scenario, parameter, with_history);
        assert!(matches!(e, IdentifyError::NotApplicable { .. }), "{e}");
        for w in words {
            assert!(e.to_string().contains(w), "`{w}` missing from: {e}");
        }
    }
    // e = 1 is a valid law (no damping) but the edge of the logit coordinate.
    let elastic = law(LawKind::HuntCrossleyExact, 1.0);
    let data = scalars(&options.solver, &elastic, &[(Observable::VBallOut, 0.01)], None).unwrap();
    let e = fit(&FitProblem { start: elastic.into(), free: vec![FitParameter::Restitution], observations: data }, &options).unwrap_err();
    assert!(matches!(e, IdentifyError::StartOutOfRange { name: "restitution", value, .. } if value == 1.0), "{e}");
}

/// `law`, `restitution` and `time_offset` of a fit specification: parsed,
/// written back and parsed again unchanged (TOML and JSON), turned into the
/// start point, and refused when given twice or misspelt.
#[test]
fn specification_keys_round_trip() {
    let text = "free = [\"stiffness\", \"restitution\", \"time_offset\"]\nlaw = \"lankarani-nikravesh\"\n\
                restitution = 0.7\ntime_offset = 1.5e-4\n[scenario]\nstiffness = 3e5\n\
                [[scalar]]\nobservable = \"v_ball_out\"\nvalue = 31.0\nsigma = 0.01\n";
    let spec = FitSpec::parse(text, "a.toml").unwrap();
    let again = FitSpec::parse(&toml::to_string(&spec).unwrap(), "b.toml").unwrap();
    assert_eq!(again, spec);
    let json = FitSpec::parse(&serde_json::to_string(&spec).unwrap(), "c.json").unwrap();
    assert_eq!(json, spec);
    let start = spec.start("a.toml").unwrap();
    assert_eq!(start.scenario.law_kind(), LawKind::LankaraniNikravesh);
    assert_eq!(start.scenario.restitution_target(), Some(0.7));
    assert_eq!(start.scenario.get(Parameter::Stiffness), 3e5);
    assert_eq!(start.time_offset, 1.5e-4);
    // The law's χ is Lankarani–Nikravesh's formula at the baseline's V0 = 22 m/s.
    let expected = law(LawKind::LankaraniNikravesh, 0.7).with(Parameter::Stiffness, 3e5).unwrap();
    assert_eq!(start.scenario.contact_law(), expected.contact_law());
    assert_eq!(spec.free_parameters().unwrap(), vec![Parameter::Stiffness.into(), FitParameter::Restitution, FitParameter::TimeOffset]);

    let twice = text.replace("[scenario]\n", "[scenario]\nlaw = \"flores\"\n");
    let e = FitSpec::parse(&twice, "d.toml").unwrap().start("d.toml").unwrap_err();
    assert!(e.to_string().contains("d.toml") && e.to_string().contains("`law` is set both"), "{e}");
    let unknown = text.replace("lankarani-nikravesh", "hertz");
    let e = FitSpec::parse(&unknown, "e.toml").unwrap().start("e.toml").unwrap_err();
    assert!(e.to_string().contains("unknown contact law `hertz`"), "{e}");
    let no_e = text.replace("restitution = 0.7\n", "");
    let e = FitSpec::parse(&no_e, "f.toml").unwrap().start("f.toml").unwrap_err();
    assert!(e.to_string().contains("restitution"), "{e}");
}

/// A history sampled wholly before first touch (`kick fit synthesize
/// --time-offset 0.02` over its 6.5 ms window), fitted from t0 = 0 with
/// m_f, k, c, n and t0 free: it used to run for hours (trial contacts of
/// two minutes each recorded whole); now it ends, refused as showing no
/// contact, its fitted χ² no better than the 320 noise samples' own.
#[test]
fn a_history_with_no_contact_is_refused_in_bounded_time() {
    let options = FitOptions::default();
    let truth = ModelPoint::new(Scenario::baseline(), 0.02).unwrap();
    let times = time_grid(&truth.scenario, 80, 1.2);
    let data = history(&options.solver, &truth, times, &lab_sigma(&ALL_CHANNELS), 1).unwrap();
    let mut free = kick_identify::profile::MODEL_PARAMETERS.to_vec();
    free.push(FitParameter::TimeOffset);
    let start = start_from(&truth, &[(free[0], 1.2), (free[1], 0.714), (free[2], 1.333), (free[3], 0.926), (free[4], 0.0)]);
    let started = std::time::Instant::now();
    match fit(&FitProblem { start, free, observations: data }, &options) {
        Err(IdentifyError::NoContact { fitted, without, samples, first, last, .. }) => {
            assert_eq!((samples, first), (320, 0.0));
            assert!((last - 1.2 * truth.scenario.elastic_contact_time()).abs() < 1e-15, "{last}");
            // Pure noise against no contact: χ²_320 = 320 ± 25.
            assert!((without - 320.0).abs() < 100.0 && fitted > without, "{fitted} vs {without}");
        }
        other => panic!("{other:?}"),
    }
    println!("refused after {:?}", started.elapsed());
}

/// A force history fitted from a start whose contact is over before the
/// second sample (k 1e12 times the truth's): no sample's prediction moves
/// with k there, and the optimiser stopped at once with "converged:
/// gradient zero", the start reported as the estimate. Now refused.
#[test]
fn a_fit_whose_observations_do_not_move_with_its_parameters_is_refused() {
    let options = FitOptions::default();
    let truth = ModelPoint::new(Scenario::baseline(), 0.0).unwrap();
    let times = time_grid(&truth.scenario, 30, 1.2);
    let data = history(&options.solver, &truth, times, &lab_sigma(&[Channel::Force]), 1).unwrap();
    let stiffness = FitParameter::Scenario(Parameter::Stiffness);
    let start = start_from(&truth, &[(stiffness, 1e12)]);
    match fit(&FitProblem { start, free: vec![stiffness], observations: data }, &options) {
        Err(e @ IdentifyError::Insensitive { .. }) => {
            let text = e.to_string();
            assert!(text.contains("do not depend on the free parameters (stiffness)"), "{text}");
            assert_eq!(e.status(), kick_core::Status::Refused);
        }
        other => panic!("{other:?}"),
    }
}
