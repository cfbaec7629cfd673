//! The validation chapter's 1D side: model counterparts against closed forms,
//! the comparisons' bookkeeping, and the identification on synthetic truth.

use kick_core::measurements::Measurements;
use kick_core::{LawKind, Parameter, Scenario};
use kick_identify::data::{Observable, Observations, ScalarObservation};
use kick_identify::validation::{
    contact_comparisons, contact_model, contact_targets, implied_parameter_study, implied_parameters, keys, ValidationError,
};
use kick_identify::FitParameter;
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn measurements() -> Measurements {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    read(&path).unwrap_or_else(|e| panic!("{e}"))
}

const K: FitParameter = FitParameter::Scenario(Parameter::Stiffness);
const MF: FitParameter = FitParameter::Scenario(Parameter::FootMass);

/// Undamped: contact time is the Beta-function closed form, the peak force
/// k δ_max^n at the closed-form δ_max, and the exit speed Newton's 2 m_f v/(m_f + m_b).
#[test]
fn undamped_contact_meets_its_closed_forms() {
    let s = Scenario::baseline().with(Parameter::Damping, 0.0).unwrap();
    let model = contact_model(&s).unwrap();
    let tc = s.elastic_contact_time();
    assert!((model.contact_time - tc).abs() < 1e-9 * tc, "{} vs {tc}", model.contact_time);
    let peak = s.get(Parameter::Stiffness) * s.elastic_max_compression().powf(s.get(Parameter::Exponent));
    assert!((model.peak_force - peak).abs() < 1e-8 * peak, "{} vs {peak}", model.peak_force);
    let v = 2.0 * 3.0 * 22.0 / 3.43;
    assert!((model.ball_speed - v).abs() < 1e-9 * v);
}

/// With no drive the centre of mass drifts uniformly and δ = 0 at both ends
/// of the contact, so the ball moves V_cm t_c while on the foot, damped or not.
#[test]
fn ball_travel_is_the_centre_of_mass_drift() {
    for s in [Scenario::baseline(), Scenario::baseline().with(Parameter::Stiffness, 7e4).unwrap()] {
        let model = contact_model(&s).unwrap();
        let drift = s.centre_of_mass_speed() * model.contact_time;
        assert!((model.ball_travel - drift).abs() < 1e-8 * drift, "{} vs {drift}", model.ball_travel);
    }
}

#[test]
fn comparisons_carry_the_model_and_the_miss() {
    let m = measurements();
    let rows = contact_comparisons(&m, &Scenario::baseline()).unwrap();
    let model = contact_model(&Scenario::baseline()).unwrap();
    let contact = rows.iter().find(|r| r.measured.key == keys::CONTACT_TIME).unwrap();
    assert_eq!(contact.model, model.contact_time);
    // 9–14 ms: the model's 5.29 ms lies 3.71 ms below the lower bound.
    assert!((contact.outside.unwrap() - (model.contact_time - 9e-3)).abs() < 1e-15);
    assert!((contact.ratio.unwrap() - model.contact_time / 11.5e-3).abs() < 1e-12);
    // Pulse shape: the punt kicks' 2062/1045.
    let pulse = rows.iter().find(|r| r.measured.key == "peak_force_punt/mean_force_punt").unwrap();
    assert!((pulse.measured.low.unwrap() - 2062.0 / 1045.0).abs() < 1e-12);
    // Every row names a source that the file cites.
    for r in &rows {
        for key in r.measured.source.split(['/', '*']) {
            assert!(m.source(key).is_some(), "{key}");
        }
    }
}

#[test]
fn targets_are_midpoints_with_half_widths() {
    let t = contact_targets(&measurements()).unwrap();
    let get = |o: Observable| t.scalars.iter().find(|s| s.observable == o).copied().unwrap();
    let tc = get(Observable::ContactTime);
    assert!((tc.value - 11.5e-3).abs() < 1e-15 && (tc.sigma - 2.5e-3).abs() < 1e-15);
    let v = get(Observable::VBallOut);
    assert!((v.value - 31.54).abs() < 1e-12 && (v.sigma - 2.94).abs() < 1e-12);
    // Peak forces 1610, 2439, 2926 N.
    let f = get(Observable::PeakForce);
    assert!((f.value - 2268.0).abs() < 1e-9 && (f.sigma - 658.0).abs() < 1e-9);
}

#[test]
fn a_missing_measurement_is_named() {
    let mut m = measurements();
    m.measurements.retain(|x| x.key != keys::BALL_TRAVEL);
    let e = contact_comparisons(&m, &Scenario::baseline()).unwrap_err();
    assert!(matches!(e, ValidationError::Measurements(_)));
    let text = e.to_string();
    assert!(text.contains(keys::BALL_TRAVEL) && text.contains(MEASUREMENTS_FILE), "{text}");
}

/// Exact observations of a known Hunt–Crossley kick are fitted back to its
/// k and m_f from a distant start.
#[test]
fn identification_recovers_synthetic_truth() {
    let truth = Scenario::baseline()
        .with_law(LawKind::HuntCrossleyExact, Some(0.66))
        .unwrap()
        .with(Parameter::Stiffness, 8.0e4)
        .unwrap()
        .with(Parameter::FootMass, 2.5)
        .unwrap();
    let model = contact_model(&truth).unwrap();
    let targets = Observations::scalars(vec![
        ScalarObservation { observable: Observable::ContactTime, value: model.contact_time, sigma: 2.5e-3 },
        ScalarObservation { observable: Observable::VBallOut, value: model.ball_speed, sigma: 2.94 },
        ScalarObservation { observable: Observable::PeakForce, value: model.peak_force, sigma: 658.0 },
    ])
    .unwrap();
    let start = truth.with(Parameter::Stiffness, 4.2e5).unwrap().with(Parameter::FootMass, 3.0).unwrap();
    let implied = implied_parameters(&targets, start.into(), &[K, MF]).unwrap();
    assert!(implied.converged && implied.chi_square < 1e-12, "{implied:?}");
    let k = implied.estimate(K).unwrap();
    let mf = implied.estimate(MF).unwrap();
    assert!((k.value / 8.0e4 - 1.0).abs() < 1e-6, "{}", k.value);
    assert!((mf.value / 2.5 - 1.0).abs() < 1e-6, "{}", mf.value);
    assert!(implied.correlation[0][1].abs() <= 1.0 && (implied.correlation[0][0] - 1.0).abs() < 1e-12);
}

/// The stated-σ uncertainty of k against a χ² profile: holding ln k one σ
/// from its estimate and refitting m_f raises χ² by about 1 (exactly 1 for a
/// linear model; 0.8–1.2 allows the curvature of this one).
#[test]
fn stated_sigma_matches_the_chi_square_profile() {
    let m = measurements();
    let targets = contact_targets(&m).unwrap();
    let start = Scenario::baseline().with_law(LawKind::HuntCrossleyExact, Some(0.66)).unwrap();
    let best = implied_parameters(&targets, start.into(), &[K, MF]).unwrap();
    let k = best.estimate(K).unwrap();
    let mf = best.estimate(MF).unwrap();
    let held = start.with(Parameter::Stiffness, k.value * (k.sigma / k.value).exp()).unwrap().with(Parameter::FootMass, mf.value).unwrap();
    let profile = implied_parameters(&targets, held.into(), &[MF]).unwrap();
    let rise = profile.chi_square - best.chi_square;
    assert!((0.8..1.2).contains(&rise), "Δχ² = {rise}");
}

/// The study's Hunt–Crossley k reproduces the targets' contact time, and the
/// undamped closed form at that k and m_f lands within 10 % of it (damping at
/// e ≈ 0.66 lengthens the contact by about 5 %).
#[test]
fn implied_stiffness_meets_the_closed_form_contact_time() {
    let m = measurements();
    let study = implied_parameter_study(&m).unwrap();
    assert_eq!(study.len(), 5);
    let hc = study.iter().find(|i| i.law == LawKind::HuntCrossleyExact && i.foot_speed == 22.0 && i.estimates.len() == 2);
    let hc = hc.unwrap();
    let contact = hc.residuals.iter().find(|r| r.label == "contact_time").unwrap();
    assert!((contact.predicted - contact.observed).abs() < contact.sigma);
    let s = Scenario::baseline()
        .with(Parameter::Stiffness, hc.estimate(K).unwrap().value)
        .unwrap()
        .with(Parameter::FootMass, hc.estimate(MF).unwrap().value)
        .unwrap();
    let closed = s.elastic_contact_time();
    assert!((closed / contact.observed - 1.0).abs() < 0.10, "{closed} vs {}", contact.observed);
    for i in &study {
        assert!(i.converged);
        for e in &i.estimates {
            assert!(e.value.is_finite() && e.sigma.is_finite() && e.sigma > 0.0, "{e:?}");
        }
    }
}

/// Matching Tol et al.'s ball speed fixes the impulse at m_b v_b (ball at
/// rest before), so mean force × contact time is 0.43 kg × 24.6 m/s.
#[test]
fn matched_ball_speed_fixes_the_impulse() {
    let s = kick_identify::validation::with_ball_speed(&Scenario::baseline(), 24.6).unwrap();
    let model = contact_model(&s).unwrap();
    assert!((model.ball_speed - 24.6).abs() < 1e-9, "{}", model.ball_speed);
    let impulse = model.mean_force * model.contact_time;
    assert!((impulse - 0.43 * 24.6).abs() < 1e-9, "{impulse}");
}
