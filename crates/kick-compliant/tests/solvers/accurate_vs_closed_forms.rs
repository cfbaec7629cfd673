//! The accurate solver against the closed forms, at the 1e-9 relative target.

use crate::support::assert_close;
use kick_compliant::{closed, Accurate};
use kick_core::{models, special, ContactLaw, Outcome, Parameter, Scenario, Solver};

const TARGET: f64 = 1e-9;

fn compare(case: &str, accurate: &Outcome, exact: &Outcome) {
    let pairs = [
        ("v_ball_out", accurate.v_ball_out, exact.v_ball_out),
        ("v_foot_out", accurate.v_foot_out, exact.v_foot_out),
        ("contact_time", accurate.contact_time, exact.contact_time),
        ("max_compression", accurate.max_compression, exact.max_compression),
        ("max_compression_time", accurate.max_compression_time, exact.max_compression_time),
        ("peak_force", accurate.peak_force, exact.peak_force),
        ("impulse", accurate.impulse, exact.impulse),
        ("restitution", accurate.restitution, exact.restitution),
        ("dissipated", accurate.energy.dissipated + 1.0, exact.energy.dissipated + 1.0),
    ];
    for (quantity, a, e) in pairs {
        assert_close(case, quantity, a, e, TARGET);
    }
}

#[test]
fn elastic_contacts_match_the_energy_integral() {
    for (case, scenario) in models::elastic() {
        let exact = closed::elastic(&scenario).unwrap().unwrap();
        let accurate = Accurate::default().solve(&scenario).unwrap();
        compare(case, &accurate, &exact);
        assert_close(case, "peak_force_time", accurate.peak_force_time, exact.peak_force_time, TARGET);
    }
}

#[test]
fn linear_damped_contacts_match_the_oscillator() {
    for (case, scenario) in models::linear() {
        let exact = closed::linear(&scenario).unwrap().unwrap();
        let accurate = Accurate::default().solve(&scenario).unwrap();
        compare(case, &accurate, &exact);
    }
}

/// Eq. 43 is exact for n = 1, c = 0: t_c = π √(μ/k).
#[test]
fn eq43_contact_time_of_the_linear_spring() {
    for (k, m_f, v_b) in [(1.0e5, 3.0, 0.0), (3.0e6, 0.7, -4.0), (2.0e4, 40.0, 12.0)] {
        let scenario = Scenario::baseline()
            .with(Parameter::Exponent, 1.0)
            .unwrap()
            .with(Parameter::Damping, 0.0)
            .unwrap()
            .with(Parameter::Stiffness, k)
            .unwrap()
            .with(Parameter::FootMass, m_f)
            .unwrap()
            .with(Parameter::BallSpeed, v_b)
            .unwrap();
        let expected = std::f64::consts::PI * (scenario.reduced_mass() / k).sqrt();
        let accurate = Accurate::default().solve(&scenario).unwrap();
        assert_close("Eq. 43", "contact_time", accurate.contact_time, expected, TARGET);
        let exact = closed::linear(&scenario).unwrap().unwrap();
        assert_close("Eq. 43 closed form", "contact_time", exact.contact_time, expected, 1e-14);
    }
}

/// Eqs. 34–35 hold with equality when c = 0 and there is no drive.
#[test]
fn eq34_eq35_scaling_is_exact_without_damping() {
    for (case, scenario) in models::elastic() {
        let law = scenario.paper_law();
        let n = law.exponent;
        let mu = scenario.reduced_mass();
        let v0 = scenario.approach_speed();
        let delta_max = ((n + 1.0) * mu * v0 * v0 / (2.0 * law.stiffness)).powf(1.0 / (n + 1.0)); // Eq. 34
        let force_max = law.stiffness.powf(1.0 / (n + 1.0)) * (mu * v0 * v0).powf(n / (n + 1.0)) // Eq. 35
            * ((n + 1.0) / 2.0).powf(n / (n + 1.0)); // the constant Eq. 35 drops with "~"
        let accurate = Accurate::default().solve(&scenario).unwrap();
        assert_close(case, "Eq. 34 max_compression", accurate.max_compression, delta_max, TARGET);
        assert_close(case, "Eq. 35 peak_force", accurate.peak_force, force_max, TARGET);
    }
}

/// The Beta-function return time against an independent quadrature.
#[test]
fn beta_return_time_matches_simpson_quadrature() {
    for n in [1.0_f64, 1.35, 2.0, 3.0, 0.7] {
        // ∫₀¹ du/√(1−u^(n+1)) with u = 1 − v²: ∫₀¹ 2v dv/√(1−(1−v²)^(n+1)), smooth in v.
        let m = n + 1.0;
        let f = |v: f64| {
            if v == 0.0 {
                2.0 / m.sqrt()
            } else {
                2.0 * v / (1.0 - (1.0 - v * v).powf(m)).sqrt()
            }
        };
        let intervals = 20_000;
        let h = 1.0 / intervals as f64;
        let mut sum = f(0.0) + f(1.0);
        for i in 1..intervals {
            sum += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        let quadrature = sum * h / 3.0;
        let closed = special::return_time(1.0, 1.0, n);
        assert!((closed - quadrature).abs() < 1e-12, "n = {n}: {closed} vs {quadrature}");
    }
    // n = 1: B(1/2, 1/2)/2 = π/2.
    assert!((special::return_time(1.0, 1.0, 1.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
}

/// The closed-form linear peak force: an independent dense scan of F = kδ + cδ̇.
#[test]
fn linear_peak_force_against_a_dense_scan_of_the_accurate_history() {
    for (case, scenario) in models::linear() {
        let exact = closed::linear(&scenario).unwrap().unwrap();
        let (_, history) =
            kick_core::RecordingSolver::solve_recorded(&Accurate::default(), &scenario, exact.contact_time / 4000.0).unwrap();
        let scanned = history.samples.iter().map(|s| s.force).fold(0.0, f64::max);
        let onset = scenario.paper_law().onset_force(scenario.approach_speed());
        // A scan can only undershoot the supremum, by at most the curvature term.
        assert!(scanned.max(onset) <= exact.peak_force * (1.0 + 1e-12), "{case}");
        assert!(scanned.max(onset) >= exact.peak_force * (1.0 - 1e-6), "{case}");
    }
}
