//! The validation chapter's curve kicks: the rigid sphere's spin against the
//! Coulomb bound and its exact sliding value, and the sweep's bookkeeping.

use kick_3d::validation::{curve_kick_comparisons, keys, largest_spin, offsets, spin_curve, spin_point};
use kick_3d::Kick3d;
use kick_core::measurements::Measurements;
use kick_core::Scenario;
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn measurements() -> Measurements {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    read(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// I_b of the default thin-shell ball, kg m².
fn shell_inertia() -> f64 {
    2.0 / 3.0 * 0.43 * 0.11 * 0.11
}

/// Without friction the normal force passes through the centre: no spin at
/// any offset, to rounding of the spin scale J_n R / I_b (≈ 400 rad/s).
#[test]
fn frictionless_kicks_do_not_spin() {
    for e in [0.0, 0.03, 0.08, 0.105] {
        let p = spin_point(&Scenario::baseline(), e, 0.0).unwrap();
        let scale = p.normal_impulse * 0.11 / shell_inertia();
        assert!(p.spin < 1e-12 * scale, "e = {e}: {} rad/s", p.spin);
    }
}

/// The friction force never exceeds μ F_n and acts at lever R, so
/// |ω| ≤ μ R J_n / I_b; a contact that slides throughout meets it exactly.
/// Both balls: the paper's law (whose force jumps at touch, so its relaxed
/// spring grips a few microseconds first) and the shell ball (which slips
/// from first touch where the friction is small).
#[test]
fn spin_meets_the_coulomb_bound_and_equals_it_when_sliding() {
    let shell = Scenario::baseline().with_law(kick_core::LawKind::Shell, None).unwrap();
    for base in [Scenario::baseline(), shell] {
        for (e, mu) in [(0.02, 0.5), (0.05, 1.0), (0.08, 0.5), (0.1, 1.0), (0.08, 0.05), (0.1, 0.1)] {
            let p = spin_point(&base, e, mu).unwrap();
            let bound = mu * 0.11 * p.normal_impulse / shell_inertia();
            assert!(p.spin <= bound * (1.0 + 1e-9), "e {e} mu {mu}: {} > {bound}", p.spin);
            if p.slip_time == p.contact_time {
                assert!((p.spin - bound).abs() < 1e-9 * bound, "e {e} mu {mu}: sliding {} vs {bound}", p.spin);
            }
        }
    }
    // Small friction at a large offset slides throughout: the equality above was reached.
    let p = spin_point(&shell, 0.08, 0.05).unwrap();
    assert_eq!(p.slip_time, p.contact_time);
}

#[test]
fn the_refined_peak_is_a_local_maximum() {
    let base = Scenario::baseline();
    let curve = spin_curve(&base, 0.5).unwrap();
    assert_eq!(curve.len(), offsets(Kick3d::DEFAULT_BALL_RADIUS).len());
    let peak = largest_spin(&base, &curve).unwrap();
    assert!(curve.iter().all(|p| p.spin <= peak.spin), "refinement lost the sweep's best");
    for de in [-1e-3, 1e-3] {
        let near = spin_point(&base, peak.offset + de, 0.5).unwrap();
        assert!(near.spin <= peak.spin, "{} at {} beats {}", near.spin, near.offset, peak.spin);
    }
}

#[test]
fn comparisons_read_the_file_and_report_the_sweep() {
    let m = measurements();
    let kicks = curve_kick_comparisons(&m, &Scenario::baseline()).unwrap();
    assert_eq!(kicks.curves.len(), 3);
    let row = |key: &str| kicks.comparisons.iter().find(|r| r.measured.key == key).unwrap();
    // No friction, no spin: the model cannot produce Asai et al.'s wrapping spin.
    let zero = kicks.comparisons.iter().find(|r| r.measured.key == keys::ZERO_FRICTION).unwrap();
    assert!(zero.model < 1e-12, "{}", zero.model);
    assert!(zero.ratio.is_none());
    // The friction gain is the μ = 1 spin (μ = 0 gives none), largest over the sweep.
    let gain = row(keys::FRICTION_GAIN);
    let best_full = kicks.curves[2].iter().map(|p| p.spin).fold(0.0, f64::max);
    assert!((gain.model - best_full).abs() < 1e-12 * best_full);
    // Measured spins are converted from rev/s.
    let spin = row(keys::SPIN_MAX);
    assert!((spin.measured.low.unwrap() - 13.89 * std::f64::consts::TAU).abs() < 1e-9);
}
