//! Named scenarios shared by tests and benchmarks (diffsol-style test models).

use crate::{Parameter, Scenario};

fn baseline_with(changes: &[(Parameter, f64)]) -> Scenario {
    changes.iter().try_fold(Scenario::baseline(), |s, &(p, v)| s.with(p, v)).expect("test models are valid scenarios")
}

/// c = 0, no drive: the whole contact has a closed form (energy integral).
pub fn elastic() -> Vec<(&'static str, Scenario)> {
    vec![
        ("elastic n=1.35", baseline_with(&[(Parameter::Damping, 0.0)])),
        ("elastic n=1", baseline_with(&[(Parameter::Damping, 0.0), (Parameter::Exponent, 1.0), (Parameter::Stiffness, 1.0e5)])),
        (
            "elastic n=1.5 moving ball",
            baseline_with(&[
                (Parameter::Damping, 0.0),
                (Parameter::Exponent, 1.5),
                (Parameter::Stiffness, 2.0e6),
                (Parameter::BallSpeed, -6.0),
            ]),
        ),
        (
            "elastic n=2 heavy foot",
            baseline_with(&[
                (Parameter::Damping, 0.0),
                (Parameter::Exponent, 2.0),
                (Parameter::Stiffness, 1.0e7),
                (Parameter::FootMass, 20.0),
            ]),
        ),
        (
            "elastic n=3 light foot",
            baseline_with(&[
                (Parameter::Damping, 0.0),
                (Parameter::Exponent, 3.0),
                (Parameter::Stiffness, 1.0e9),
                (Parameter::FootMass, 0.5),
            ]),
        ),
    ]
}

/// n = 1 with compression-only damping, no drive: damped oscillator then an
/// undamped quarter swing. ζ below, at and above critical.
pub fn linear() -> Vec<(&'static str, Scenario)> {
    let base = [(Parameter::Exponent, 1.0), (Parameter::Stiffness, 1.0e5)];
    let critical = 2.0 * (1.0e5 * Scenario::baseline().reduced_mass()).sqrt();
    vec![
        ("linear zeta=0.05", baseline_with(&[base[0], base[1], (Parameter::Damping, 0.05 * critical)])),
        ("linear zeta=0.3", baseline_with(&[base[0], base[1], (Parameter::Damping, 0.3 * critical)])),
        (
            "linear zeta=0.9 moving ball",
            baseline_with(&[base[0], base[1], (Parameter::Damping, 0.9 * critical), (Parameter::BallSpeed, 5.0)]),
        ),
        ("linear zeta=1", baseline_with(&[base[0], base[1], (Parameter::Damping, critical)])),
        ("linear zeta=3", baseline_with(&[base[0], base[1], (Parameter::Damping, 3.0 * critical)])),
        (
            "linear zeta=0.2 stiff heavy",
            baseline_with(&[
                base[0],
                (Parameter::Stiffness, 1.0e8),
                (Parameter::FootMass, 50.0),
                (Parameter::Damping, 0.2 * 2.0 * (1.0e8_f64 * (50.0 * 0.43 / 50.43)).sqrt()),
            ]),
        ),
    ]
}

/// Table 2's scenarios at their fitted parameters (see `experiments/table2.toml`).
pub fn table2() -> Vec<(&'static str, Scenario)> {
    vec![
        ("Baseline", Scenario::baseline()),
        ("Light effective foot", baseline_with(&[(Parameter::FootMass, 0.6)])),
        ("Heavy effective foot", baseline_with(&[(Parameter::FootMass, 8.0)])),
        ("Very soft ball", baseline_with(&[(Parameter::Stiffness, 1.2e5)])),
        ("Very stiff ball", baseline_with(&[(Parameter::Stiffness, 1.8e6)])),
        ("Highly damped", baseline_with(&[(Parameter::Damping, 450.0)])),
        ("Ball approaching foot", baseline_with(&[(Parameter::BallSpeed, -8.0)])),
        ("Ball already moving", baseline_with(&[(Parameter::BallSpeed, 10.0)])),
    ]
}

/// Driven contacts that still separate.
pub fn driven() -> Vec<(&'static str, Scenario)> {
    vec![
        ("drive 500 N", baseline_with(&[(Parameter::DriveForce, 500.0)])),
        ("drive 2000 N", baseline_with(&[(Parameter::DriveForce, 2000.0)])),
        ("drive -1000 N (braking)", baseline_with(&[(Parameter::DriveForce, -1000.0)])),
    ]
}
