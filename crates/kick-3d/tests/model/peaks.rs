//! Peak normal and tangential force and their times against an independent
//! method (fixed-step RK4, every step sampled, see `support/fine_rk4.rs`),
//! on kicks whose largest force comes just after a grip/slip switch.

use crate::support::fine_rk4;
use kick_3d::{Accurate3d, FullState3d, Kick3d};

/// The accurate path's promise on peaks and their times.
const PEAK_TOLERANCE: f64 = 1e-9;
/// RK4 steps per contact of the reference: its peaks converge to ~1e-14
/// and their times to ~1e-11 (measured against 4x the steps).
const REFERENCE_STEPS: f64 = 1e5;

fn check(name: &str, kick: &Kick3d, solve: impl Fn(&Kick3d) -> kick_3d::Outcome3d) {
    let o = solve(kick);
    let [(normal, normal_time), (tangential, tangential_time)] = fine_rk4::peaks(kick, o.contact_time, REFERENCE_STEPS);
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    let errors = [
        ("peak normal force", rel(o.peak_normal_force, normal)),
        ("its time", rel(o.peak_normal_force_time, normal_time)),
        ("peak tangential force", rel(o.peak_tangential_force, tangential)),
        ("its time", rel(o.peak_tangential_force_time, tangential_time)),
    ];
    for (quantity, error) in errors {
        println!("{name}: {quantity} {error:.2e}");
        assert!(error <= PEAK_TOLERANCE, "{name}: {quantity} off by {error:.3e} relative");
    }
}

#[test]
fn peaks_after_a_switch_match_fine_rk4() {
    for (name, kick) in kick_3d::models::peak_after_switch().unwrap() {
        check(&format!("accurate, {name}"), &kick, |k| Accurate3d::default().solve(k).unwrap());
        check(&format!("full-state, {name}"), &kick, |k| FullState3d::default().solve(k).unwrap());
    }
}
