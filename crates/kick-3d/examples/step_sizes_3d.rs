//! Where the realistic foot's steps go (issue 31 item 8): the accepted
//! steps' times and sizes of the shell ball's cap patch kick at 5 cm
//! (`kick bench`'s row), μ = 0.5, with the rigid Table 1 foot, the leg
//! alone, the boot alone, the boot with ten times its damping, the leg with
//! its boot, and that at μ = ∞ (no slip):
//! `cargo run --release -p kick-3d --example step_sizes_3d`.
//!
//! What it showed (rtol 1e-13, evaluations 484 / 753 / 837 / 435 / 1138 / 725;
//! 488 / 757 / 841 / 439 / 1108 / 723 since the release clock's predictive
//! step control):
//! - behind the boot the first millisecond takes ~17 steps growing from
//!   25 µs by ~9 % a step, against ~5 of ~200 µs for the rigid foot: the
//!   layer's relaxation mode, time constant c_b/(k_b + k) ≈ 0.43 ms at touch,
//!   starts from δ̇_b = 0 and its transient holds the 8th-order steps to a
//!   share of it (accuracy, not stability: h/τ ≈ 0.06–0.25). With ten times
//!   the damping (τ ≈ 4 ms) the kick is cheaper than the rigid foot's;
//! - while slipping towards separation the steps shrink geometrically
//!   (120 µs to 0.1 µs over the last ~1.5 ms with the leg): the slider's
//!   direction turns at |v_t⊥|/max(μ F_n/k_t, ℓ), which grows without bound
//!   as F_n → 0, a stiff state (stability-limited; the tolerance's widening,
//!   `slip_direction_widening`, answers only its accuracy). At μ = ∞ the
//!   leg-and-boot kick takes 725 evaluations against 1138.
use kick_3d::{Accurate3d, Kick3dSpec, KickSpec};
use kick_core::ScenarioSpec;

fn main() {
    let cap = kick_3d::models::cap_patch_kick();
    let shell = ScenarioSpec { law: Some(kick_core::LawKind::Shell), ..Default::default() };
    let (k_b, c_b) = (kick_core::boot::IDENTIFIED_STIFFNESS, kick_core::boot::IDENTIFIED_DAMPING);
    let forms: Vec<(&str, ScenarioSpec, f64)> = vec![
        ("rigid Table 1 foot", shell, 0.5),
        ("leg, no boot", ScenarioSpec { leg: Some(true), boot_stiffness: Some(f64::INFINITY), ..shell }, 0.5),
        ("boot alone", ScenarioSpec { boot_stiffness: Some(k_b), boot_damping: Some(c_b), ..shell }, 0.5),
        ("boot, 10 c_b", ScenarioSpec { boot_stiffness: Some(k_b), boot_damping: Some(10.0 * c_b), ..shell }, 0.5),
        ("leg and boot", ScenarioSpec { leg: Some(true), ..shell }, 0.5),
        ("leg and boot, μ = ∞", ScenarioSpec { leg: Some(true), ..shell }, f64::INFINITY),
    ];
    for (name, scenario, friction) in forms {
        let kick = KickSpec { scenario, kick3d: Kick3dSpec { friction: Some(friction), ..cap } }.build().expect("valid");
        let (o, samples) = Accurate3d::default().solve_recorded(&kick).expect("solves");
        println!(
            "{name}: {} evaluations, contact {:.4e} s, slip {:.3e} s, {} accepted points",
            o.evaluations,
            o.contact_time,
            o.slip_time,
            samples.len()
        );
        let mut last = 0.0;
        let mut line = String::new();
        for s in &samples {
            line += &format!("{:.2}:{:.1} ", s.0 * 1e3, (s.0 - last) * 1e6);
            last = s.0;
        }
        println!("  t [ms]:step [µs] {line}");
    }
}
