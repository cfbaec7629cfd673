//! The accurate path against the tightened full-state reference
//! (`kick_3d::precision::reference`: another state, frame, geometry code,
//! integrator and event machinery for the same model): every observable it
//! promises (launch velocity, spin, contact time, peak normal and
//! tangential force and their times, maximum compression) within 1e-9
//! relative, over a seeded sample of the box with every contact law, and
//! on the named kicks (μ = 0 and ∞, sharp and rounded edges, contact over
//! an edge, drive, incoming ball, gravity).
//!
//! `cargo run --release -p kick-3d --example accuracy3d` prints the same
//! errors' maxima and medians over 200 kicks.

use kick_3d::models::{self, OffCenterBox, BENCH_SEED};
use kick_3d::precision::{self, Errors3d};
use kick_3d::{Accurate3d, Kick3d};
use kick_core::LawKind;

/// The accurate path's promise.
const TOLERANCE: f64 = 1e-9;

fn check(name: &str, kick: &Kick3d) -> Errors3d {
    let solved = Accurate3d::default().solve(kick).unwrap_or_else(|e| panic!("{name}: {e}"));
    let reference = precision::reference().solve(kick).unwrap_or_else(|e| panic!("{name}: reference: {e}"));
    let errors = Errors3d::of(kick, &solved, &reference);
    for (quantity, error) in Errors3d::NAMES.iter().zip(errors.values()) {
        assert!(error <= TOLERANCE, "{name}: {quantity} off by {error:.3e} relative");
    }
    // The energy partition closes to the solver's tolerance.
    let residual = solved.energy.relative_residual().abs();
    assert!(residual <= 1e-10, "{name}: energy residual {residual:.3e}");
    errors
}

fn worst(label: &str, errors: &[Errors3d]) {
    let mut line = format!("{label}:");
    for (j, name) in Errors3d::NAMES.iter().enumerate() {
        let max = errors.iter().map(|e| e.values()[j]).fold(0.0, f64::max);
        line += &format!(" {name} {max:.1e}");
    }
    println!("{line}");
}

#[test]
fn box_sample_matches_the_reference() {
    // 60 kicks with the paper's law, 100 with the shell ball (every study's
    // default; 12 missed kick 82), 12 with each other law.
    let count_of = |law| match law {
        LawKind::PowerLaw => 60,
        LawKind::Shell => 100,
        _ => 12,
    };
    for (law, count) in LawKind::SELECTABLE.iter().map(|&law| (law, count_of(law))) {
        let sample = OffCenterBox { seed: BENCH_SEED, law };
        let errors: Vec<Errors3d> = (0..count).map(|i| check(&format!("{} kick {i}", law.name()), &sample.kick(i).unwrap())).collect();
        worst(law.name(), &errors);
    }
}

#[test]
fn named_kicks_match_the_reference() {
    let errors: Vec<Errors3d> = models::named_kicks().unwrap().iter().map(|(name, kick)| check(name, kick)).collect();
    worst("named kicks", &errors);
}

/// Box kick 82 of the shell ball (offset 7.1 cm, μ = 0.22) grips from
/// 7.759 ms and must slip again 7 µs before separation, where μ F_n falls
/// below the spring's k_t |ξ|. The step that landed on separation skipped
/// the grip's margin, so the kick gripped to the end with 0.95 N of
/// tangential force at zero normal force: slip time off by 1.1e-3 of the
/// contact, spin by 4.7e-4.
#[test]
fn a_grip_lost_in_the_last_step_slips_before_separation() {
    let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::Shell }.kick(82).unwrap();
    let errors = check("shell kick 82", &kick);
    assert!(errors.slip_time <= 1e-9, "slip time off by {:.3e}", errors.slip_time);
}

/// Box kicks 31 and 114 of Hunt and Crossley's law (μ ≈ 4.7): F_n grows as
/// t^1.35 from touch, slower than the spring would load, so the element
/// slips for the first 0.39 ns. The reference started in grip, reading the
/// cap from the geometry's rounding (F_n = 1.2e-17 N at touch) instead of
/// the law at δ = 0, and the spring's 4e-4 N of extra stretch held to
/// separation: spin off by 5.8e-8, slip time by 6.6e-8 of the contact.
#[test]
fn a_cap_growing_from_zero_slips_at_touch_in_both_paths() {
    for i in [31, 114] {
        let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::HuntCrossley }.kick(i).unwrap();
        check(&format!("hunt-crossley kick {i}"), &kick);
    }
}

/// Box kick 97 of Lankarani and Nikravesh's law (μ = ∞, offset 8.7 cm):
/// |F_t| peaks 0.24 µs before separation, inside the last step, which lands
/// on separation on the release clock u. There every rate is zero
/// (dt/du = 0), so the peak was not bracketed and the value at separation,
/// 3.9e-5 N lower, was reported (its time off by 3.9e-5 of the contact).
#[test]
fn a_peak_in_the_step_that_lands_on_separation_is_found() {
    let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::LankaraniNikravesh }.kick(97).unwrap();
    let errors = check("lankarani-nikravesh kick 97", &kick);
    assert!(errors.peak_tangential_force_time <= 1e-9, "{errors:?}");
}

/// Box kick 82 of Hunt and Crossley's exact law slips from touch and grips
/// for the last 34 ns: the slip's end lies inside the step that lands on
/// separation, where such a switch was taken for separation itself and
/// skipped (slip time off by 5.7e-6 of the contact).
#[test]
fn a_slip_that_ends_in_the_last_step_grips_before_separation() {
    let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::HuntCrossleyExact }.kick(82).unwrap();
    let errors = check("hunt-crossley-exact kick 82", &kick);
    assert!(errors.slip_time <= 1e-9, "{errors:?}");
}

/// Box kick 82 of the paper's law slips from 0.34 ms, grips 13.6 ns before
/// separation and slips again for the last 2.5 ns. At the default tolerance
/// the step that lands on separation holds all of it, with the slip's margin
/// falling at both ends (at separation its rate is −2.3e11: the direction
/// state has no length there), so no dip was looked for and the grip was
/// counted as slip: slip time off by 2.1e-6 of the contact.
#[test]
fn a_grip_hidden_in_the_landing_step_is_found() {
    let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::PowerLaw }.kick(82).unwrap();
    let errors = check("power-law kick 82", &kick);
    assert!(errors.slip_time <= 1e-9, "{errors:?}");
}

/// Box kick 1294 of Hunt and Crossley's law grips for 33 ns from 41 ns before
/// separation, at δ = 0.41 µm: the reference's grip margin, μ F_n less the
/// spring put a hair (`GRIP_ENTRY`) inside the cap, was below parry's
/// rounding of the overlap there and read negative at once, so its grip
/// ended where it began (slip time off by 5.5e-6 of the contact).
#[test]
fn a_grip_entered_at_a_tiny_compression_holds_in_the_reference() {
    let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::HuntCrossley }.kick(1294).unwrap();
    let errors = check("hunt-crossley kick 1294", &kick);
    assert!(errors.slip_time <= 1e-9, "{errors:?}");
}

/// Box kick 925 of Flores's law: the reference's step crossed separation at
/// its end, and the step's re-integration stopped 1.4e-17 m short of it, the
/// overlap's rounding: "could not locate Separation", no reference at all.
#[test]
fn a_separation_at_a_steps_end_is_located_by_the_reference() {
    let kick = OffCenterBox { seed: BENCH_SEED, law: LawKind::Flores }.kick(925).unwrap();
    check("flores kick 925", &kick);
}
